// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reads and writes height fields: 16-bit (or 8-bit) grey PNG and PGM, read
// through stb_image (Debian's libstb-dev; link with -lstb), PNG written
// through libpng (libpng-dev), and ESRI ASCII grids.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_IO_HEIGHT_FIELD_IO_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_IO_HEIGHT_FIELD_IO_H

#include <CGAL/Penrose_Delaunay_triangulation_2/IO/internal/file_names.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/IO/internal/image_checks.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/IO/internal/output_file.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/IO/internal/read_radiance_hdr.h>

#include <png.h>
#include <stb/stb_image.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <memory>
#include <new>
#include <optional>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

namespace CGAL {
namespace IO {

/*!
\ingroup PkgPenroseDelaunayTriangulation2IO

The most pixels, or cells, that the readers of images and height fields
accept unless told otherwise: 2^26 (8192 x 8192). A file whose header claims
more is refused before anything is allocated; the `max_pixels` (`max_cells`)
argument of each reader raises the limit. At that size, `penrose_mesh` takes
up to 1.5 GiB for an RGB image, 2.5 GiB to mesh one for its reconstruction,
0.7 GiB for a 16-bit terrain (its `--max-pixels` option sets the limit there).
*/
constexpr std::size_t default_max_pixels = std::size_t(1) << 26;

/*!
\ingroup PkgPenroseDelaunayTriangulation2IO

A regular grid of heights stretched over a rectangle of the plane. Row 0 is
the northern row (largest y), as in an image and in an ESRI grid.
*/
struct Height_field
{
  std::size_t width = 0;                  ///< columns
  std::size_t height = 0;                 ///< rows
  std::vector<double> values;             ///< `width * height` heights, row after row from the top
  /// \name The rectangle covered by the cells
  /// From their outer corners: (x0, y0) the lower left, (x1, y1) the upper right.
  /// @{

  double x0 = 0.; ///< west
  double y0 = 0.; ///< south
  double x1 = 0.; ///< east
  double y1 = 0.; ///< north
  /// @}

  /// The height of cell (i, j), column i, row j from the top.
  double at(std::size_t i, std::size_t j) const { return values[j * width + i]; }
};

namespace internal {

// How far read_file() reads a file: `bytes` at most, beyond which the rest
// is ignored (a PNM file may hold several images) or refused, as more than
// the `dimensions` that its header claims can take.
struct Read_limit
{
  std::size_t bytes;
  bool rest_ignored;
  std::string dimensions;
};

// `bytes`, in a std::size_t, or the largest one: the limits grow with pixel
// counts up to 10^18 (--max-pixels).
inline std::size_t saturated(double bytes)
{
  return bytes < double((std::numeric_limits<std::size_t>::max)()) ? std::size_t(bytes)
                                                                   : (std::numeric_limits<std::size_t>::max)();
}

// The most bytes that the header of a file may take, metadata before the
// pixels included: past them, the file is refused.
constexpr std::size_t most_header_bytes = std::size_t(1) << 24;

/*
The bytes of `file`, read in bounded blocks: a device or a pipe
(/dev/zero, /dev/urandom) may never end, and a file may be larger than its
header's dimensions can take. `limit(head)` is given the first 64 KiB (a
file that ends before is read whole, and its decoder has the last word); it
returns a Read_limit from the dimensions that the header claims, checked
against the pixel limit, or nothing while the header is incomplete (the
head then doubles, up to most_header_bytes), and throws if the head is not
of its format. Then a regular file is read at once into a buffer of its
size (a 4096^2 grid's text, 100 MB, grown block by block was copied about
twice over), a pipe block by block; the exception tells why not (missing, a
directory, unreadable, empty, too large).
*/
template <class Limit>
std::string read_file(const std::string& file, const Limit& limit)
{
  std::error_code error;
  if(std::filesystem::is_directory(file, error)) throw file_error(file, "is a directory");
  std::ifstream in(file, std::ios::binary);
  if(!in) throw file_error(file, std::string("cannot open (") + std::strerror(errno) + ")");
  const std::uintmax_t size = std::filesystem::is_regular_file(file, error) ? std::filesystem::file_size(file, error) : 0;
  const bool sized = !error && size > 0;
  std::string s;
  // Reads until `s` holds `total` bytes, or the file ends first (false).
  auto read_to = [&](std::size_t total) {
    while(s.size() < total) {
      const std::size_t at = s.size();
      const std::size_t n = sized && size > at ? std::size_t((std::min<std::uintmax_t>)(total, size)) - at
                                               : (std::min)(total - at, std::size_t(1) << 20);
      if(in.peek() == std::ifstream::traits_type::eof()) return false;
      s.resize(at + n);
      in.read(&s[at], std::streamsize(n));
      s.resize(at + std::size_t(in.gcount()));
      if(s.size() < at + n) return false;
    }
    return true;
  };
  try {
    std::optional<Read_limit> most;
    for(std::size_t head = std::size_t(1) << 16; !most; head *= 2) {
      if(!read_to(head)) break;
      most = limit(static_cast<const std::string&>(s));
      if(!most && head >= most_header_bytes)
        throw file_error(file, "cannot read as an image (no complete header in its first "
                               + std::to_string(most_header_bytes >> 20) + " MiB)");
    }
    if(most) {
      auto too_large = [&] {
        return file_error(file, "more than the " + std::to_string(most->bytes) + " bytes that its "
                                + most->dimensions + " can take");
      };
      if(most->rest_ignored) {
        if(s.size() > most->bytes) s.resize(most->bytes);
      } else if(s.size() > most->bytes || (sized && size > most->bytes)) throw too_large();
      if(sized) s.reserve(std::size_t((std::min<std::uintmax_t>)(size, most->bytes)));
      if(read_to(most->bytes) && !most->rest_ignored && in.peek() != std::ifstream::traits_type::eof()) throw too_large();
    }
  } catch(const std::bad_alloc&) {
    throw file_error(file, "too large to hold in memory");
  }
  if(in.bad()) throw file_error(file, "read error");
  if(s.empty()) throw file_error(file, "empty file");
  return s;
}

/*
A binary PGM (P5) or PPM (P6), 8 or 16 bits a sample: read here rather than
by stb_image, whose version 2.27 (Debian 12) takes 16-bit samples as
little-endian where the format says big-endian.
*/
struct Pnm
{
  std::size_t width = 0, height = 0, channels = 0;
  double maxval = 0.;
  std::size_t pixels_at = 0;  // where the samples start
  std::vector<std::uint16_t> samples;

  std::size_t sample_bytes() const { return maxval > 255. ? 2 : 1; }
};

// The header of a PNM file from its `bytes`, or nothing if they end within
// it and are not `whole` (the head of a file being read).
inline std::optional<Pnm> pnm_header(const std::string& file, const std::string& bytes, std::size_t max_pixels,
                                     bool whole)
{
  std::size_t at = 2;
  bool incomplete = false;
  auto field = [&](const char* name) {
    while(at < bytes.size() && (std::isspace((unsigned char)bytes[at]) || bytes[at] == '#'))
      if(bytes[at] == '#') at = bytes.find('\n', at) == std::string::npos ? bytes.size() : bytes.find('\n', at);
      else ++at;
    double v = 0.;
    const std::size_t first = at;
    for(; at < bytes.size() && std::isdigit((unsigned char)bytes[at]); ++at) v = 10. * v + (bytes[at] - '0');
    incomplete = incomplete || at == bytes.size();
    if(at == first && !incomplete) throw file_error(file, std::string("truncated or corrupt PNM header (no ") + name + ")");
    return v;
  };
  Pnm p;
  p.channels = bytes[1] == '5' ? 1 : 3;
  const double w = field("width"), h = field("height");
  p.maxval = field("maxval");
  if(incomplete && !whole) return std::nullopt;
  if(incomplete) throw file_error(file, "truncated PNM header");
  check_dimensions(file, w, h, max_pixels);
  if(p.maxval < 1. || p.maxval > 65535.) throw file_error(file, "PNM maxval must be in [1, 65535]");
  if(!std::isspace((unsigned char)bytes[at])) throw file_error(file, "truncated PNM header");
  p.pixels_at = at + 1;
  p.width = std::size_t(w);
  p.height = std::size_t(h);
  return p;
}

inline Pnm read_pnm(const std::string& file, const std::string& bytes, std::size_t max_pixels)
{
  Pnm p = *pnm_header(file, bytes, max_pixels, true);
  const std::size_t n = p.width * p.height * p.channels, size = p.sample_bytes(), at = p.pixels_at;
  if(bytes.size() - at < n * size)
    throw file_error(file, "truncated: " + std::to_string(bytes.size() - at) + " bytes of pixels, "
                           + std::to_string(n * size) + " expected");
  p.samples.resize(n);
  const unsigned char* d = reinterpret_cast<const unsigned char*>(bytes.data() + at);
  for(std::size_t k = 0; k < n; ++k) {
    p.samples[k] = size == 2 ? std::uint16_t(d[2 * k] << 8 | d[2 * k + 1]) : d[k];
    if(p.samples[k] > p.maxval)  // it would be brighter than white
      throw file_error(file, "sample " + std::to_string(k) + " is " + std::to_string(p.samples[k])
                             + ", more than the maxval " + std::to_string(int(p.maxval)));
  }
  return p;
}

// How far to read an image file from its `head` (see read_file()): a PNM
// file to its last sample, a Radiance file to its last scanline at 8 bytes
// a pixel (runs of one, the worst case of its run-length encoding), a PNG
// or JPEG file to 16 bytes a pixel plus most_header_bytes of metadata (a
// PNG's 8 bytes a pixel at most, 16-bit RGBA, doubled for the worst case of
// its compression and chunks).
inline std::optional<Read_limit> image_read_limit(const std::string& file, const std::string& head,
                                                  std::size_t max_pixels)
{
  const Image_format format = image_format(head);
  auto pixels = [](std::size_t w, std::size_t h) { return std::to_string(w) + " x " + std::to_string(h) + " pixels"; };
  if(format == Image_format::pnm) {
    const std::optional<Pnm> p = pnm_header(file, head, max_pixels, false);
    if(!p) return std::nullopt;
    return Read_limit{saturated(double(p->pixels_at) + double(p->width) * double(p->height) * double(p->channels)
                                                       * double(p->sample_bytes())),
                      true, pixels(p->width, p->height)};
  }
  if(format == Image_format::radiance) {
    Radiance_image img;
    const std::size_t at = radiance_header(file, head, max_pixels, img);
    if(at == std::string::npos) return std::nullopt;
    return Read_limit{saturated(double(at) + double(img.height) * (4. + 8. * double(img.width))), true,
                      pixels(img.width, img.height)};
  }
  if(format != Image_format::png && format != Image_format::jpeg) throw unknown_format(file);
  int w = 0, h = 0, c = 0;
  if(!stbi_info_from_memory(reinterpret_cast<const stbi_uc*>(head.data()), int(head.size()), &w, &h, &c)) {
    if(format == Image_format::jpeg) return std::nullopt;  // its frame header may lie further
    const char* reason = stbi_failure_reason();
    throw file_error(file, std::string("cannot read as an image (") + (reason ? reason : "unknown format") + ")");
  }
  check_dimensions(file, w, h, max_pixels);
  return Read_limit{saturated(16. * double(w) * double(h) + double(most_header_bytes)), false,
                    pixels(std::size_t(w), std::size_t(h))};
}

} // namespace internal

namespace internal {

// A blank within a line: what std::isspace() accepts, the end of line aside.
inline bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// Reads the decimal number at `p`, before `end`, into `v`, as std::strtod()
// does (a plus sign, "inf", "nan" included), and returns where it ends, or
// `p` if there is none. std::from_chars() reads a grid's values several times
// faster; strtod() only gives the value that overflows or underflows a double.
// (Hexadecimal numbers, which strtod() reads too, have no place in a grid.)
inline const char* read_number(const char* p, const char* end, double& v)
{
  const char* digits = p + (p != end && *p == '+' && p + 1 != end && p[1] != '-');
  const std::from_chars_result r = std::from_chars(digits, end, v);
  if(r.ec == std::errc::result_out_of_range) v = std::strtod(p, nullptr);
  else if(r.ec != std::errc()) return p;
  return r.ptr;
}

// The heights of an ESRI grid, from `at` on: one row of `ncols` numbers a
// line, blank lines aside, `nrows` rows.
inline void read_grid_rows(const std::string& file, const std::string& text, std::size_t at, Height_field& hf)
{
  std::size_t line = 1 + std::size_t(std::count(text.begin(), text.begin() + std::ptrdiff_t(at), '\n'));
  auto fail = [&](const std::string& why) { return file_error(file, "line " + std::to_string(line) + ": " + why); };
  std::size_t row = 0;
  const char* p = text.data() + at;
  const char* const text_end = text.data() + text.size();
  for(; p != text_end; ++line) {
    const void* newline = std::memchr(p, '\n', std::size_t(text_end - p));
    const char* const end = newline ? static_cast<const char*>(newline) : text_end;
    std::size_t count = 0;
    for(;;) {
      while(p != end && is_blank(*p)) ++p;
      if(p == end) break;
      double v = 0.;
      const char* next = read_number(p, end, v);
      if(next == p) throw fail("value " + std::to_string(count + 1) + " is not a number");
      if(!std::isfinite(v)) throw fail("value " + std::to_string(count + 1) + " is not finite");
      if(row == hf.height) throw fail("more rows than nrows (" + std::to_string(hf.height) + ")");
      if(count == hf.width) throw fail("more values than ncols (" + std::to_string(hf.width) + ")");
      hf.values[row * hf.width + count++] = v;
      p = next;
    }
    if(count > 0 && count < hf.width)
      throw fail(std::to_string(count) + " values where ncols is " + std::to_string(hf.width));
    row += count > 0;
    p = end == text_end ? end : end + 1;
  }
  if(row < hf.height)
    throw file_error(file, "truncated: " + std::to_string(row) + " of " + std::to_string(hf.height) + " rows");
}

// The header of an ESRI grid: its extent, NODATA_value, and where the rows start.
struct Asc_header
{
  Height_field grid;  // without its values
  double nodata = NAN;
  std::size_t rows_at = 0;
};

// The header of an ESRI grid from `text`, or nothing if the text ends within
// it and is not `whole` (the head of a file being read).
inline std::optional<Asc_header> asc_header(const std::string& file, const std::string& text, std::size_t max_cells,
                                            bool whole)
{
  const char* p = text.c_str();
  const char* const text_end = p + text.size();
  auto fail = [&](const std::string& why) { return file_error(file, why); };
  double ncols = -1., nrows = -1., xll = NAN, yll = NAN, cell = -1.;
  bool x_centre = false, y_centre = false;
  Asc_header header;
  // "keyword value" lines, until the first line that starts with a number
  for(;;) {
    while(std::isspace((unsigned char)*p)) ++p;
    if(p == text_end && !whole) return std::nullopt;
    if(!std::isalpha((unsigned char)*p)) break;
    const char* k = p;
    while(std::isalpha((unsigned char)*p) || *p == '_') ++p;
    const std::string key = lowercase(std::string(k, p));
    char* end = nullptr;
    const double v = std::strtod(p, &end);
    if(end == text_end && !whole) return std::nullopt;  // the number may go on
    if(end == p) throw fail("header field '" + printable(key, 40) + "' has no numeric value");
    p = end;
    if(key == "ncols") ncols = v;
    else if(key == "nrows") nrows = v;
    else if(key == "xllcorner" || key == "xllcenter") { xll = v; x_centre = key == "xllcenter"; }
    else if(key == "yllcorner" || key == "yllcenter") { yll = v; y_centre = key == "yllcenter"; }
    else if(key == "cellsize") cell = v;
    else if(key == "nodata_value") header.nodata = v;
    else throw fail("not an ESRI ASCII grid (unknown header field '" + printable(key, 40) + "')");
  }
  if(ncols < 0. || nrows < 0.) throw fail("not an ESRI ASCII grid (no ncols / nrows header)");
  if(std::isnan(xll) || std::isnan(yll)) throw fail("header lacks xllcorner / yllcorner");
  if(!(cell > 0. && std::isfinite(cell))) throw fail("cellsize must be positive");
  if(ncols != std::floor(ncols) || nrows != std::floor(nrows)) throw fail("ncols and nrows must be integers");
  check_dimensions(file, ncols, nrows, max_cells);

  Height_field& hf = header.grid;
  hf.width = std::size_t(ncols);
  hf.height = std::size_t(nrows);
  hf.x0 = x_centre ? xll - 0.5 * cell : xll;
  hf.y0 = y_centre ? yll - 0.5 * cell : yll;
  hf.x1 = hf.x0 + cell * ncols;
  hf.y1 = hf.y0 + cell * nrows;
  if(!(std::isfinite(hf.x0) && std::isfinite(hf.y0) && std::isfinite(hf.x1) && std::isfinite(hf.y1)
       && hf.x1 > hf.x0 && hf.y1 > hf.y0))
    throw fail("the extent from xllcorner, yllcorner and cellsize is not finite or is empty");
  header.rows_at = std::size_t(p - text.c_str());
  return header;
}

// The most bytes that a value of a grid takes, its blanks included: past
// them a file is refused (17 significant digits and an exponent take 24).
constexpr double most_bytes_a_cell = 64.;

// The grid of read_ESRI_ASCII_grid() from the text of `file`.
inline Height_field parse_ESRI_ASCII_grid(const std::string& file, const std::string& text, std::size_t max_cells)
{
  Asc_header header = *asc_header(file, text, max_cells, true);
  Height_field hf = std::move(header.grid);
  const std::size_t n = hf.width * hf.height;
  if(text.size() < 2 * n) throw file_error(file, "truncated: " + std::to_string(text.size()) + " bytes cannot hold "
                                                 + std::to_string(n) + " values");
  hf.values.resize(n);
  read_grid_rows(file, text, header.rows_at, hf);
  double lowest = std::numeric_limits<double>::infinity();
  for(double v : hf.values)
    if(v != header.nodata) lowest = (std::min)(lowest, v);
  if(lowest == std::numeric_limits<double>::infinity()) throw file_error(file, "every cell is NODATA");
  for(double& v : hf.values)
    if(v == header.nodata) v = lowest;
  return hf;
}

// The heights of read_height_image() from the bytes of `file`.
inline Height_field decode_height_image(const std::string& file, const std::string& bytes, std::size_t max_cells)
{
  auto fail = [&](const std::string& why) { return file_error(file, why); };
  Height_field hf;
  if(image_format(bytes) == Image_format::pnm) {
    Pnm p = read_pnm(file, bytes, max_cells);
    if(p.channels != 1) throw fail("is a colour PPM; a height field is a grey image");
    hf.width = p.width;
    hf.height = p.height;
    hf.values.assign(p.samples.begin(), p.samples.end());
  } else {
    Stb_image_bytes b = stb_image_bytes(file, bytes, max_cells);
    const stbi_uc* data = b.data;
    const int size = b.size;
    int w = b.width, h = b.height, c = b.channels;
    if(c > 2) throw fail("has " + std::to_string(c) + " colour channels; a height field is a grey image");
    std::unique_ptr<stbi_us, void (*)(void*)> pixels(stbi_load_16_from_memory(data, size, &w, &h, &c, 1),
                                                     stbi_image_free);
    if(!pixels) throw fail(std::string("truncated or corrupt image (") + stbi_failure_reason() + ")");
    // stb widens 8-bit samples to 16 bits (v * 257): undo it to keep the file's values
    const double unit = stbi_is_16_bit_from_memory(data, size) ? 1. : 1. / 257.;
    hf.width = std::size_t(w);
    hf.height = std::size_t(h);
    hf.values.resize(hf.width * hf.height);
    for(std::size_t k = 0; k < hf.values.size(); ++k) hf.values[k] = pixels.get()[k] * unit;
  }
  hf.x1 = double(hf.width);
  hf.y1 = double(hf.height);
  return hf;
}

} // namespace internal

/*!
\ingroup PkgPenroseDelaunayTriangulation2IO
Reads an ESRI ASCII grid (`.asc`): the header `ncols`, `nrows`,
`xllcorner` or `xllcenter`, `yllcorner` or `yllcenter`, `cellsize` and the
optional `NODATA_value`, then `nrows` lines of `ncols` heights from the north
(blank lines aside). Cells without data take the lowest height of the grid,
so that a DEM clipped to a coastline or a border still makes a closed surface.

\throws std::runtime_error naming the file and the problem: missing or empty
file, a directory, a header field missing or invalid, an extent that is not
finite, absurd dimensions (more than `max_cells` cells), a value that is not
a finite number, a row of more or fewer than `ncols` values or more rows
than `nrows` (naming the line), too few rows, no data, or more than 64 bytes
a cell. The file is read no further than that: a device or a pipe that does
not end is refused once the header's dimensions are passed.
*/
inline Height_field read_ESRI_ASCII_grid(const std::string& file, std::size_t max_cells = default_max_pixels)
{
  const std::string text = internal::read_file(file, [&](const std::string& head) -> std::optional<internal::Read_limit> {
    const std::optional<internal::Asc_header> h = internal::asc_header(file, head, max_cells, false);
    if(!h) return std::nullopt;
    return internal::Read_limit{internal::saturated(double(h->rows_at) + internal::most_bytes_a_cell
                                                    * double(h->grid.width) * double(h->grid.height)),
                                false, std::to_string(h->grid.width) + " x " + std::to_string(h->grid.height)
                                       + " cells at " + std::to_string(int(internal::most_bytes_a_cell))
                                       + " bytes a cell"};
  });
  return internal::parse_ESRI_ASCII_grid(file, text, max_cells);
}

/*!
\ingroup PkgPenroseDelaunayTriangulation2IO
Reads a grey PNG or PGM image (16 or 8 bits per sample) as heights: the raw
sample values (0 to 65535, or 0 to 255), one pixel a unit square, the image
over the rectangle [0, width] x [0, height]. (A grey JPEG is read too.)

\throws std::runtime_error naming the file and the problem: missing, empty,
a directory, not a PNG, JPEG or PGM image, colour, absurd dimensions (more
than `max_cells` pixels, or more than the file's size can hold), a PGM
sample above its maxval, truncated or corrupt, or larger than its
dimensions can take (a PNG or JPEG file: 16 bytes a pixel and 16 MiB of
metadata; a PGM file is read to its last sample). The file is read no
further than that, so that a device or a pipe that does not end is refused.
*/
inline Height_field read_height_image(const std::string& file, std::size_t max_cells = default_max_pixels)
{
  const std::string bytes = internal::read_file(file, [&](const std::string& head) {
    return internal::image_read_limit(file, head, max_cells);
  });
  return internal::decode_height_image(file, bytes, max_cells);
}

/// \ingroup PkgPenroseDelaunayTriangulation2IO
/// Reads a height field, by the file's extension: `.asc` with
/// `read_ESRI_ASCII_grid()`, anything else with `read_height_image()`.
inline Height_field read_height_field(const std::string& file, std::size_t max_cells = default_max_pixels)
{
  return internal::lowercase_extension(file) == "asc" ? read_ESRI_ASCII_grid(file, max_cells)
                                                      : read_height_image(file, max_cells);
}

namespace internal {

// A height as a 16-bit sample, rounded and clamped to [0, 65535].
inline std::uint16_t sample_16(double height)
{
  return std::uint16_t(std::round((std::min)((std::max)(height, 0.), 65535.)));
}

// The heights as 16-bit samples, big-endian.
inline std::string big_endian_samples(const Height_field& hf)
{
  std::string s(2 * hf.values.size(), '\0');
  for(std::size_t k = 0; k < hf.values.size(); ++k) {
    const unsigned v = sample_16(hf.values[k]);
    s[2 * k] = char(v >> 8);
    s[2 * k + 1] = char(v & 0xff);
  }
  return s;
}

} // namespace internal

/// \ingroup PkgPenroseDelaunayTriangulation2IO
/// Writes `hf` as a 16-bit binary PGM (P5), heights rounded and clamped to [0, 65535].
/// \throws std::runtime_error if the file cannot be written.
inline void write_PGM_16(const std::string& file, const Height_field& hf)
{
  internal::write_bytes(file, "P5\n" + std::to_string(hf.width) + " " + std::to_string(hf.height)
                              + "\n65535\n" + internal::big_endian_samples(hf));
}

/// \ingroup PkgPenroseDelaunayTriangulation2IO
/// Writes `hf` as a 16-bit grey PNG with libpng, heights rounded and clamped to [0, 65535].
/// \throws std::runtime_error if the file cannot be written, or libpng refuses the image.
inline void write_PNG_16(const std::string& file, const Height_field& hf)
{
  std::vector<png_uint_16> samples(hf.values.size());
  for(std::size_t k = 0; k < samples.size(); ++k) samples[k] = internal::sample_16(hf.values[k]);
  png_image image;
  std::memset(&image, 0, sizeof image);
  image.version = PNG_IMAGE_VERSION;
  image.width = png_uint_32(hf.width);
  image.height = png_uint_32(hf.height);
  image.format = PNG_FORMAT_LINEAR_Y;  // 16 bits, grey, samples in the machine's byte order
  png_alloc_size_t size = 0;
  const bool sized = hf.width <= 0x7fffffffu && hf.height <= 0x7fffffffu
                     && png_image_write_to_memory(&image, nullptr, &size, 0, samples.data(), 0, nullptr);
  std::string png(sized ? size : 0, '\0');
  if(!sized || !png_image_write_to_memory(&image, &png[0], &size, 0, samples.data(), 0, nullptr))
    throw internal::file_error(file, std::string("cannot encode the PNG: ") + image.message);
  png.resize(size);
  internal::write_bytes(file, png);
}

/// \ingroup PkgPenroseDelaunayTriangulation2IO
/// Writes `hf` as an ESRI ASCII grid, heights in full precision.
/// \throws std::runtime_error if the file cannot be written.
inline void write_ESRI_ASCII_grid(const std::string& file, const Height_field& hf)
{
  std::string s = "ncols " + std::to_string(hf.width) + "\nnrows " + std::to_string(hf.height) + "\n";
  char buf[64];
  std::snprintf(buf, sizeof buf, "xllcorner %.17g\n", hf.x0); s += buf;
  std::snprintf(buf, sizeof buf, "yllcorner %.17g\n", hf.y0); s += buf;
  std::snprintf(buf, sizeof buf, "cellsize %.17g\n", (hf.x1 - hf.x0) / double(hf.width)); s += buf;
  for(std::size_t j = 0; j < hf.height; ++j)
    for(std::size_t i = 0; i < hf.width; ++i) {
      std::snprintf(buf, sizeof buf, i + 1 < hf.width ? "%.17g " : "%.17g\n", hf.at(i, j));
      s += buf;
    }
  internal::write_bytes(file, s);
}

/// \ingroup PkgPenroseDelaunayTriangulation2IO
/// Writes `hf` by the file's extension: `.asc`, `.png` or `.pgm`.
/// \throws std::runtime_error on another extension or if the file cannot be written.
inline void write_height_field(const std::string& file, const Height_field& hf)
{
  const std::string e = internal::lowercase_extension(file);
  if(e == "asc") write_ESRI_ASCII_grid(file, hf);
  else if(e == "png") write_PNG_16(file, hf);
  else if(e == "pgm") write_PGM_16(file, hf);
  else throw internal::file_error(file, "unknown height field format '." + e + "' (asc, png or pgm)");
}

} // namespace IO
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_IO_HEIGHT_FIELD_IO_H

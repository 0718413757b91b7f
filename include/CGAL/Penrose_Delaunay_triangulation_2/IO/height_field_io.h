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
argument of each reader raises the limit. A raster of that size takes about
2 GB in `penrose_mesh` (its `--max-pixels` option sets the limit there).
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

// The whole file, or an exception that tells why not (missing, a directory,
// unreadable, empty). A regular file is read at once into a buffer of its
// size (a 4096^2 grid's text, 100 MB, grown block by block was copied about
// twice over); what is left, or a pipe, in blocks.
inline std::string read_whole_file(const std::string& file)
{
  std::error_code error;
  if(std::filesystem::is_directory(file, error)) throw file_error(file, "is a directory");
  std::ifstream in(file, std::ios::binary);
  if(!in) throw file_error(file, std::string("cannot open (") + std::strerror(errno) + ")");
  std::string s;
  char block[1 << 16];
  try {
    const std::uintmax_t size = std::filesystem::is_regular_file(file, error) ? std::filesystem::file_size(file, error) : 0;
    if(!error && size > 0 && size < s.max_size()) {
      s.resize(std::size_t(size));
      in.read(&s[0], std::streamsize(size));
      s.resize(std::size_t(in.gcount()));
    }
    while(in.read(block, sizeof block) || in.gcount() > 0) s.append(block, std::size_t(in.gcount()));
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
  std::vector<std::uint16_t> samples;
};

inline Pnm read_pnm(const std::string& file, const std::string& bytes, std::size_t max_pixels)
{
  std::size_t at = 2;
  auto field = [&](const char* name) {
    while(at < bytes.size() && (std::isspace((unsigned char)bytes[at]) || bytes[at] == '#'))
      if(bytes[at] == '#') at = bytes.find('\n', at) == std::string::npos ? bytes.size() : bytes.find('\n', at);
      else ++at;
    double v = 0.;
    const std::size_t first = at;
    for(; at < bytes.size() && std::isdigit((unsigned char)bytes[at]); ++at) v = 10. * v + (bytes[at] - '0');
    if(at == first) throw file_error(file, std::string("truncated or corrupt PNM header (no ") + name + ")");
    return v;
  };
  Pnm p;
  p.channels = bytes[1] == '5' ? 1 : 3;
  const double w = field("width"), h = field("height");
  p.maxval = field("maxval");
  check_dimensions(file, w, h, max_pixels);
  if(p.maxval < 1. || p.maxval > 65535.) throw file_error(file, "PNM maxval must be in [1, 65535]");
  if(at >= bytes.size() || !std::isspace((unsigned char)bytes[at])) throw file_error(file, "truncated PNM header");
  ++at;
  p.width = std::size_t(w);
  p.height = std::size_t(h);
  const std::size_t n = p.width * p.height * p.channels, size = p.maxval > 255. ? 2 : 1;
  if(bytes.size() - at < n * size)
    throw file_error(file, "truncated: " + std::to_string(bytes.size() - at) + " bytes of pixels, "
                           + std::to_string(n * size) + " expected");
  p.samples.resize(n);
  const unsigned char* d = reinterpret_cast<const unsigned char*>(bytes.data() + at);
  for(std::size_t k = 0; k < n; ++k) p.samples[k] = size == 2 ? std::uint16_t(d[2 * k] << 8 | d[2 * k + 1]) : d[k];
  return p;
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

// The grid of read_ESRI_ASCII_grid() from the text of `file`.
inline Height_field parse_ESRI_ASCII_grid(const std::string& file, const std::string& text, std::size_t max_cells)
{
  const char* p = text.c_str();
  auto fail = [&](const std::string& why) { return file_error(file, why); };
  double ncols = -1., nrows = -1., xll = NAN, yll = NAN, cell = -1., nodata = NAN;
  bool x_centre = false, y_centre = false;
  // header: "keyword value" lines, until the first line that starts with a number
  for(;;) {
    while(std::isspace((unsigned char)*p)) ++p;
    if(!std::isalpha((unsigned char)*p)) break;
    const char* k = p;
    while(std::isalpha((unsigned char)*p) || *p == '_') ++p;
    const std::string key = lowercase(std::string(k, p));
    char* end = nullptr;
    const double v = std::strtod(p, &end);
    if(end == p) throw fail("header field '" + key + "' has no numeric value");
    p = end;
    if(key == "ncols") ncols = v;
    else if(key == "nrows") nrows = v;
    else if(key == "xllcorner" || key == "xllcenter") { xll = v; x_centre = key == "xllcenter"; }
    else if(key == "yllcorner" || key == "yllcenter") { yll = v; y_centre = key == "yllcenter"; }
    else if(key == "cellsize") cell = v;
    else if(key == "nodata_value") nodata = v;
    else throw fail("not an ESRI ASCII grid (unknown header field '" + key + "')");
  }
  if(ncols < 0. || nrows < 0.) throw fail("not an ESRI ASCII grid (no ncols / nrows header)");
  if(std::isnan(xll) || std::isnan(yll)) throw fail("header lacks xllcorner / yllcorner");
  if(!(cell > 0. && std::isfinite(cell))) throw fail("cellsize must be positive");
  if(ncols != std::floor(ncols) || nrows != std::floor(nrows)) throw fail("ncols and nrows must be integers");
  check_dimensions(file, ncols, nrows, max_cells);

  Height_field hf;
  hf.width = std::size_t(ncols);
  hf.height = std::size_t(nrows);
  hf.x0 = x_centre ? xll - 0.5 * cell : xll;
  hf.y0 = y_centre ? yll - 0.5 * cell : yll;
  hf.x1 = hf.x0 + cell * ncols;
  hf.y1 = hf.y0 + cell * nrows;
  if(!(std::isfinite(hf.x0) && std::isfinite(hf.y0) && std::isfinite(hf.x1) && std::isfinite(hf.y1)
       && hf.x1 > hf.x0 && hf.y1 > hf.y0))
    throw fail("the extent from xllcorner, yllcorner and cellsize is not finite or is empty");
  const std::size_t n = hf.width * hf.height;
  if(text.size() < 2 * n) throw fail("truncated: " + std::to_string(text.size()) + " bytes cannot hold "
                                     + std::to_string(n) + " values");
  hf.values.resize(n);
  read_grid_rows(file, text, std::size_t(p - text.c_str()), hf);
  double lowest = std::numeric_limits<double>::infinity();
  for(double v : hf.values)
    if(v != nodata) lowest = (std::min)(lowest, v);
  if(lowest == std::numeric_limits<double>::infinity()) throw fail("every cell is NODATA");
  for(double& v : hf.values)
    if(v == nodata) v = lowest;
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
than `nrows` (naming the line), too few rows, or no data.
*/
inline Height_field read_ESRI_ASCII_grid(const std::string& file, std::size_t max_cells = default_max_pixels)
{
  return internal::parse_ESRI_ASCII_grid(file, internal::read_whole_file(file), max_cells);
}

/*!
\ingroup PkgPenroseDelaunayTriangulation2IO
Reads a grey PNG or PGM image (16 or 8 bits per sample) as heights: the raw
sample values (0 to 65535, or 0 to 255), one pixel a unit square, the image
over the rectangle [0, width] x [0, height]. (A grey JPEG is read too.)

\throws std::runtime_error naming the file and the problem: missing, empty,
a directory, not a PNG, JPEG or PGM image, colour, absurd dimensions (more
than `max_cells` pixels, or more than the file's size can hold), truncated
or corrupt.
*/
inline Height_field read_height_image(const std::string& file, std::size_t max_cells = default_max_pixels)
{
  return internal::decode_height_image(file, internal::read_whole_file(file), max_cells);
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

// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reads a Radiance HDR (RGBE) image, flat or run-length encoded, with every
// read checked against the bytes left: stb_image 2.27 (Debian 12) loops
// forever on a run-length encoded file cut short, and leaves the pixels of a
// flat one cut short uninitialised. The values are those stb_image gives;
// old-style runs, which it does not read, are read as Radiance reads them.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_IO_INTERNAL_READ_RADIANCE_HDR_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_IO_INTERNAL_READ_RADIANCE_HDR_H

#include <CGAL/Penrose_Delaunay_triangulation_2/IO/internal/file_names.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace IO {
namespace internal {

struct Radiance_image
{
  std::size_t width = 0, height = 0;
  std::vector<float> rgb;  // linear radiance, row after row from the top
};

// Reads the scanline that starts at `at` into `rgbe` (four bytes a pixel)
// and returns where it ends, or std::string::npos if the bytes end first.
// Once a scanline is not run-length encoded, none that follows is.
inline std::size_t radiance_scanline(const std::string& file, const std::string& bytes, std::size_t at, bool& flat,
                                     std::vector<unsigned char>& rgbe)
{
  const unsigned char* d = reinterpret_cast<const unsigned char*>(bytes.data());
  const std::size_t n = bytes.size(), w = rgbe.size() / 4;
  if(n - at < 4) return std::string::npos;
  flat = flat || w < 8 || w >= 32768 || !(d[at] == 2 && d[at + 1] == 2 && !(d[at + 2] & 0x80));
  if(flat) {
    // A pixel (1, 1, 1, e) is an old-style run, as Radiance reads it (not
    // stb_image): the pixel before, e times; e << 8 times after a run, and so on.
    int shift = 0;
    for(std::size_t i = 0; i < w;) {
      if(n - at < 4) return std::string::npos;
      const unsigned char* p = d + at;
      at += 4;
      if(p[0] == 1 && p[1] == 1 && p[2] == 1) {
        const std::size_t count = shift < 32 ? std::size_t(p[3]) << shift : 0;
        if(i == 0 || count == 0 || count > w - i) throw file_error(file, "corrupt Radiance HDR old-style run");
        for(std::size_t k = 0; k < count; ++k, ++i) std::copy_n(&rgbe[4 * (i - 1)], 4, &rgbe[4 * i]);
        shift += 8;
      } else {
        std::copy_n(p, 4, &rgbe[4 * i++]);
        shift = 0;
      }
    }
    return at;
  }
  if((std::size_t(d[at + 2]) << 8 | d[at + 3]) != w) throw file_error(file, "corrupt Radiance HDR scanline length");
  at += 4;
  for(std::size_t c = 0; c < 4; ++c)
    for(std::size_t i = 0; i < w;) {
      if(at == n) return std::string::npos;
      std::size_t count = d[at++];
      const bool run = count > 128;
      if(run) count -= 128;
      if(count == 0 || count > w - i) throw file_error(file, "corrupt Radiance HDR run");
      if(n - at < (run ? 1 : count)) return std::string::npos;
      for(std::size_t k = 0; k < count; ++k, ++i) rgbe[4 * i + c] = d[run ? at : at + k];
      at += run ? 1 : count;
    }
  return at;
}

// The header: the signature line, lines up to an empty one, then the
// resolution "-Y height +X width" (the only orientation that stb_image
// reads). Returns where the pixels start, or std::string::npos if `bytes`
// end within the header.
inline std::size_t radiance_header(const std::string& file, const std::string& bytes, std::size_t max_pixels,
                                   Radiance_image& img)
{
  auto fail = [&](const std::string& why) {
    return file_error(file, "cannot read as an image (Radiance HDR: " + why + ")");
  };
  std::size_t at = 0;
  auto line = [&](std::string& l) {
    const std::size_t end = bytes.find('\n', at);
    if(end == std::string::npos) return false;
    l = bytes.substr(at, end - at);
    at = end + 1;
    return true;
  };
  std::string l, r;
  if(!line(l)) return std::string::npos;
  for(;;) {
    if(!line(l)) return std::string::npos;
    if(l.empty()) break;
    if(l.rfind("FORMAT=", 0) == 0 && l != "FORMAT=32-bit_rle_rgbe") throw fail("unsupported " + printable(l, 40));
  }
  if(!line(r)) return std::string::npos;
  std::size_t k = 0;
  auto number = [&](const char* before) {
    for(const char* c = before; *c; ++c, ++k)
      if(k == r.size() || r[k] != *c) throw fail("unsupported resolution line '" + printable(r, 40) + "'");
    double v = 0.;
    const std::size_t first = k;
    for(; k < r.size() && r[k] >= '0' && r[k] <= '9' && k - first < 12; ++k) v = 10. * v + (r[k] - '0');
    return k == first ? -1. : v;
  };
  const double h = number("-Y "), w = number(" +X ");
  if(k != r.size()) throw fail("unsupported resolution line '" + printable(r, 40) + "'");
  check_dimensions(file, w, h, max_pixels);
  img.width = std::size_t(w);
  img.height = std::size_t(h);
  return at;
}

// The pixels grow with the scanlines read, so that a file cut short costs
// no more memory than it holds.
inline Radiance_image read_radiance_hdr(const std::string& file, const std::string& bytes, std::size_t max_pixels)
{
  Radiance_image img;
  std::size_t at = radiance_header(file, bytes, max_pixels, img);
  if(at == std::string::npos) throw file_error(file, "cannot read as an image (Radiance HDR: truncated header)");
  std::vector<unsigned char> rgbe(4 * img.width);
  bool flat = false;
  for(std::size_t j = 0; j < img.height; ++j) {
    at = radiance_scanline(file, bytes, at, flat, rgbe);
    if(at == std::string::npos)
      throw file_error(file, "truncated: " + std::to_string(j) + " of " + std::to_string(img.height) + " scanlines");
    for(std::size_t i = 0; i < img.width; ++i) {
      const unsigned char* p = &rgbe[4 * i];
      const float f = p[3] ? float(std::ldexp(1.f, int(p[3]) - 136)) : 0.f;
      for(int c = 0; c < 3; ++c) img.rgb.push_back(float(p[c]) * f);
    }
  }
  return img;
}

} // namespace internal
} // namespace IO
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_IO_INTERNAL_READ_RADIANCE_HDR_H

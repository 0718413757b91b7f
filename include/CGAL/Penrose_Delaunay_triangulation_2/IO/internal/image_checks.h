// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What an image file may hold, checked before stb_image decodes it: stb
// allocates the pixels that a header claims before it reads them, and the
// JPEG decoder of version 2.27 (Debian 12) decodes a file cut short as if
// zeros followed: the structure of a file, its chunks or markers, is walked
// to its end first. Only PNG and JPEG go to stb_image; the package reads PNM
// and Radiance HDR itself.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_IO_INTERNAL_IMAGE_CHECKS_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_IO_INTERNAL_IMAGE_CHECKS_H

#include <CGAL/Penrose_Delaunay_triangulation_2/IO/internal/file_names.h>

#include <stb/stb_image.h>

#include <cstddef>
#include <limits>
#include <string>

namespace CGAL {
namespace IO {
namespace internal {

enum class Image_format { png, jpeg, pnm, radiance, unknown };

inline Image_format image_format(const std::string& bytes)
{
  auto starts = [&](const char* s, std::size_t n) { return bytes.compare(0, n, s, n) == 0; };
  if(starts("\x89PNG\r\n\x1a\n", 8)) return Image_format::png;
  if(starts("\xff\xd8\xff", 3)) return Image_format::jpeg;
  if(starts("P5", 2) || starts("P6", 2)) return Image_format::pnm;
  if(starts("#?RADIANCE\n", 11) || starts("#?RGBE\n", 7)) return Image_format::radiance;
  return Image_format::unknown;
}

inline std::runtime_error unknown_format(const std::string& file)
{
  return file_error(file, "cannot read as an image (not a PNG, JPEG, PGM/PPM or Radiance HDR file)");
}

// Whether each chunk of the PNG `bytes` lies within the file, up to IEND:
// stb_image allocates the length that an IDAT chunk claims before it reads it.
inline bool png_is_complete(const std::string& bytes)
{
  const unsigned char* d = reinterpret_cast<const unsigned char*>(bytes.data());
  const std::size_t n = bytes.size();
  for(std::size_t at = 8; n - at >= 12;) {
    const std::size_t length = std::size_t(d[at]) << 24 | std::size_t(d[at + 1]) << 16 | std::size_t(d[at + 2]) << 8 | d[at + 3];
    if(length > n - at - 12) return false;
    if(bytes.compare(at + 4, 4, "IEND") == 0) return true;
    at += 12 + length;
  }
  return false;
}

// Whether the JPEG `bytes` reaches its end-of-image marker: the marker
// segments are walked by their lengths, and each scan's entropy-coded data
// to the next marker that is neither a stuffed 0xff nor a restart.
inline bool jpeg_is_complete(const std::string& bytes)
{
  const unsigned char* d = reinterpret_cast<const unsigned char*>(bytes.data());
  const std::size_t n = bytes.size();
  std::size_t at = 2;  // after the start-of-image marker
  while(at + 1 < n) {
    if(d[at] != 0xff) return false;
    const unsigned char marker = d[at + 1];
    if(marker == 0xd9) return true;
    if(marker == 0xff) { ++at; continue; }  // fill byte
    if(marker == 0x01 || (marker >= 0xd0 && marker <= 0xd7)) { at += 2; continue; }  // no length
    if(at + 3 >= n) return false;
    at += 2 + (std::size_t(d[at + 2]) << 8 | d[at + 3]);
    if(marker == 0xda)
      while(at + 1 < n && !(d[at] == 0xff && d[at + 1] != 0 && !(d[at + 1] >= 0xd0 && d[at + 1] <= 0xd7))) ++at;
  }
  return false;
}

// The bytes of a PNG or JPEG file as stb_image sees them, its dimensions
// checked against `max_pixels` and against what the file's size can hold:
// deflate expands at most 1032 times and a PNG pixel takes at least a bit;
// each 8 x 8 block of a JPEG takes at least a bit.
struct Stb_image_bytes
{
  const stbi_uc* data;
  int size;
  int width = 0, height = 0, channels = 0;
};

inline Stb_image_bytes stb_image_bytes(const std::string& file, const std::string& bytes, std::size_t max_pixels)
{
  const Image_format format = image_format(bytes);
  if(format != Image_format::png && format != Image_format::jpeg) throw unknown_format(file);
  Stb_image_bytes b;
  b.data = reinterpret_cast<const stbi_uc*>(bytes.data());
  b.size = bytes.size() > std::size_t(std::numeric_limits<int>::max()) ? std::numeric_limits<int>::max()
                                                                       : int(bytes.size());
  if(!stbi_info_from_memory(b.data, b.size, &b.width, &b.height, &b.channels)) {
    const char* reason = stbi_failure_reason();
    throw file_error(file, std::string("cannot read as an image (") + (reason ? reason : "unknown format") + ")");
  }
  check_dimensions(file, b.width, b.height, max_pixels);
  const double most = (format == Image_format::png ? 8. * 1032. : 512.) * double(bytes.size());
  if(double(b.width) * double(b.height) > most)
    throw file_error(file, "truncated or corrupt image (" + std::to_string(bytes.size()) + " bytes cannot hold its "
                           + std::to_string(b.width) + " x " + std::to_string(b.height) + " pixels)");
  if(!(format == Image_format::png ? png_is_complete(bytes) : jpeg_is_complete(bytes)))
    throw file_error(file, "truncated or corrupt image (its chunks or markers run past the end of the file)");
  return b;
}

} // namespace internal
} // namespace IO
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_IO_INTERNAL_IMAGE_CHECKS_H

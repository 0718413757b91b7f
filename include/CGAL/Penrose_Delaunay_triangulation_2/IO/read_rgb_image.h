// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reads an image as RGB colours: PNG and JPG through stb_image (Debian's
// libstb-dev; link with -lstb), PGM/PPM (8 and 16 bit) and Radiance .hdr.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_IO_READ_RGB_IMAGE_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_IO_READ_RGB_IMAGE_H

#include <CGAL/Penrose_Delaunay_triangulation_2/IO/height_field_io.h>

#include <stb/stb_image.h>

#include <algorithm>
#include <cstddef>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace IO {

/*!
\ingroup PkgPenroseDelaunayTriangulation2IO

A colour image, row 0 at the top, three values (red, green, blue) a pixel.
*/
struct Rgb_image
{
  std::size_t width = 0;            ///< columns
  std::size_t height = 0;           ///< rows
  std::vector<float> values;        ///< `3 * width * height` values, row after row from the top
  bool high_dynamic_range = false;  ///< read from a Radiance .hdr file (linear radiance)

  /// The three values of pixel (i, j), column i, row j from the top.
  const float* pixel(std::size_t i, std::size_t j) const { return &values[3 * (j * width + i)]; }
};

namespace internal {

// The image of read_rgb_image() from the bytes of `file`.
inline Rgb_image decode_rgb_image(const std::string& file, const std::string& bytes, std::size_t max_pixels)
{
  Rgb_image img;
  const Image_format format = image_format(bytes);
  if(format == Image_format::pnm) {
    const Pnm p = read_pnm(file, bytes, max_pixels);
    img.width = p.width;
    img.height = p.height;
    img.values.resize(3 * p.width * p.height);
    for(std::size_t k = 0; k < img.values.size(); ++k)
      img.values[k] = float(p.samples[p.channels == 3 ? k : k / 3] / p.maxval);
    return img;
  }
  if(format == Image_format::radiance) {
    Radiance_image r = read_radiance_hdr(file, bytes, max_pixels);
    img.width = r.width;
    img.height = r.height;
    img.values = std::move(r.rgb);
    img.high_dynamic_range = true;
    return img;
  }
  Stb_image_bytes b = stb_image_bytes(file, bytes, max_pixels);
  int w = b.width, h = b.height, c = b.channels;
  img.width = std::size_t(w);
  img.height = std::size_t(h);
  auto convert = [&](auto* pixels, float unit) {
    if(!pixels)
      throw file_error(file, std::string("truncated or corrupt image (") + stbi_failure_reason() + ")");
    std::unique_ptr<void, void (*)(void*)> owner(pixels, stbi_image_free);
    img.values.resize(3 * img.width * img.height);
    for(std::size_t k = 0; k < img.values.size(); ++k) img.values[k] = float(pixels[k]) * unit;
  };
  if(stbi_is_16_bit_from_memory(b.data, b.size))
    convert(stbi_load_16_from_memory(b.data, b.size, &w, &h, &c, 3), 1.f / 65535.f);
  else
    convert(stbi_load_from_memory(b.data, b.size, &w, &h, &c, 3), 1.f / 255.f);
  return img;
}

} // namespace internal

/*!
\ingroup PkgPenroseDelaunayTriangulation2IO
Reads `file` as colours: in [0, 1] for 8- and 16-bit images (grey images give
three equal channels), in linear radiance for .hdr files. PNG and JPEG are
decoded by stb_image, once their dimensions are checked; PGM/PPM and
Radiance HDR by the package, every read checked against the bytes left.

\throws std::runtime_error naming the file and the problem: missing, empty,
a directory, not an image of these formats, absurd dimensions (more than
`max_pixels`, see `default_max_pixels`, or more than the file's size can
hold), a PNM sample above its maxval, truncated or corrupt, or larger than
its dimensions can take (a PNG or JPEG file: 16 bytes a pixel and 16 MiB of
metadata; PNM and Radiance files are read to their last pixel). The file is
read no further than that, so that a device or a pipe that does not end is
refused.
*/
inline Rgb_image read_rgb_image(const std::string& file, std::size_t max_pixels = default_max_pixels)
{
  const std::string bytes = internal::read_file(file, [&](const std::string& head) {
    return internal::image_read_limit(file, head, max_pixels);
  });
  return internal::decode_rgb_image(file, bytes, max_pixels);
}

/// \ingroup PkgPenroseDelaunayTriangulation2IO
/// The luminance of each pixel of `rgb` (Rec. 709 weights), at least 0, row
/// after row.
inline std::vector<double> luminance(const Rgb_image& rgb)
{
  std::vector<double> l(rgb.width * rgb.height);
  for(std::size_t k = 0; k < l.size(); ++k) {
    const float* c = &rgb.values[3 * k];
    l[k] = (std::max)(0., 0.2126 * c[0] + 0.7152 * c[1] + 0.0722 * c[2]);
  }
  return l;
}

} // namespace IO
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_IO_READ_RGB_IMAGE_H

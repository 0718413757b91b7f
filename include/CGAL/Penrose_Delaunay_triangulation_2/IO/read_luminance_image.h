// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reads an image as a raster of luminance: PNG, JPG, PGM/PPM (8 and 16 bit)
// and Radiance .hdr through stb_image (Debian's libstb-dev; link with -lstb).

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_IO_READ_LUMINANCE_IMAGE_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_IO_READ_LUMINANCE_IMAGE_H

#include <stb/stb_image.h>

#include <cstddef>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace IO {

/// A raster of non-negative values, row 0 at the top.
struct Luminance_image
{
  std::size_t width = 0, height = 0;
  std::vector<double> values;
  bool high_dynamic_range = false;  ///< read from a Radiance .hdr file (linear radiance)
};

/// Reads `file` and converts it to luminance (Rec. 709 weights): in [0, 1]
/// for 8- and 16-bit images, in linear radiance for .hdr files.
/// \throws std::runtime_error naming the file and the problem.
inline Luminance_image read_luminance_image(const std::string& file,
                                            std::size_t max_pixels = std::size_t(1) << 28)
{
  auto fail = [&](const std::string& why) -> std::runtime_error {
    return std::runtime_error(file + ": " + why);
  };
  int w = 0, h = 0, c = 0;
  if(!stbi_info(file.c_str(), &w, &h, &c)) {
    const char* reason = stbi_failure_reason();
    throw fail(std::string("cannot read as an image (") + (reason ? reason : "unknown error") + ")");
  }
  if(w <= 0 || h <= 0 || std::size_t(w) * std::size_t(h) > max_pixels)
    throw fail("absurd dimensions " + std::to_string(w) + " x " + std::to_string(h));
  Luminance_image img;
  img.width = std::size_t(w);
  img.height = std::size_t(h);
  img.values.resize(img.width * img.height);
  auto luminance = [](const double* v, int channels) {
    return channels >= 3 ? 0.2126 * v[0] + 0.7152 * v[1] + 0.0722 * v[2] : v[0];
  };
  double px[4];
  if(stbi_is_hdr(file.c_str())) {
    std::unique_ptr<float, void (*)(void*)> data(stbi_loadf(file.c_str(), &w, &h, &c, 0), stbi_image_free);
    if(!data) throw fail(std::string("truncated or corrupt HDR image (") + stbi_failure_reason() + ")");
    img.high_dynamic_range = true;
    for(std::size_t k = 0; k < img.values.size(); ++k) {
      for(int i = 0; i < c; ++i) px[i] = data.get()[k * c + i];
      img.values[k] = luminance(px, c) > 0. ? luminance(px, c) : 0.;
    }
  } else if(stbi_is_16_bit(file.c_str())) {
    std::unique_ptr<unsigned short, void (*)(void*)> data(stbi_load_16(file.c_str(), &w, &h, &c, 0), stbi_image_free);
    if(!data) throw fail(std::string("truncated or corrupt image (") + stbi_failure_reason() + ")");
    for(std::size_t k = 0; k < img.values.size(); ++k) {
      for(int i = 0; i < c; ++i) px[i] = data.get()[k * c + i] / 65535.;
      img.values[k] = luminance(px, c);
    }
  } else {
    std::unique_ptr<unsigned char, void (*)(void*)> data(stbi_load(file.c_str(), &w, &h, &c, 0), stbi_image_free);
    if(!data) throw fail(std::string("truncated or corrupt image (") + stbi_failure_reason() + ")");
    for(std::size_t k = 0; k < img.values.size(); ++k) {
      for(int i = 0; i < c; ++i) px[i] = data.get()[k * c + i] / 255.;
      img.values[k] = luminance(px, c);
    }
  }
  return img;
}

} // namespace IO
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_IO_READ_LUMINANCE_IMAGE_H

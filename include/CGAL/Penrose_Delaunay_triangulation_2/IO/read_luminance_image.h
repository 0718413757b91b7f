// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Reads an image as a raster of luminance, from the colours that
// read_rgb_image() reads (PNG, JPG, PGM/PPM 8 and 16 bit, Radiance .hdr).

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_IO_READ_LUMINANCE_IMAGE_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_IO_READ_LUMINANCE_IMAGE_H

#include <CGAL/Penrose_Delaunay_triangulation_2/IO/read_rgb_image.h>

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

namespace CGAL {
namespace IO {

/// \ingroup PkgPenroseDelaunayTriangulation2IO
/// A raster of non-negative values, row 0 at the top.
struct Luminance_image
{
  std::size_t width = 0;            ///< columns
  std::size_t height = 0;           ///< rows
  std::vector<double> values;       ///< `width * height` values, row after row from the top
  bool high_dynamic_range = false;  ///< read from a Radiance .hdr file (linear radiance)
};

/// \ingroup PkgPenroseDelaunayTriangulation2IO
/// Reads `file` and converts it to luminance (Rec. 709 weights): in [0, 1]
/// for 8- and 16-bit images, in linear radiance for .hdr files.
/// \throws std::runtime_error naming the file and the problem.
inline Luminance_image read_luminance_image(const std::string& file,
                                            std::size_t max_pixels = default_max_pixels)
{
  const Rgb_image rgb = read_rgb_image(file, max_pixels);
  Luminance_image img;
  img.width = rgb.width;
  img.height = rgb.height;
  img.high_dynamic_range = rgb.high_dynamic_range;
  img.values = luminance(rgb);
  return img;
}

} // namespace IO
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_IO_READ_LUMINANCE_IMAGE_H

// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The four inputs of the paper's Figure 8, as samplers on the unit square:
// the constant density and the ramp of benchmark_support.h, a luminance
// image, and a terrain-like density. Needs stb_image (the IO target).

#ifndef PENROSE_BENCHMARK_FIGURE8_INPUTS_H
#define PENROSE_BENCHMARK_FIGURE8_INPUTS_H

#include "benchmark_support.h"

#include <CGAL/Penrose_Delaunay_triangulation_2/IO/read_luminance_image.h>
#include <CGAL/Penrose_importance_sampler.h>
#include <CGAL/Raster_density_2.h>

#include <cmath>
#include <memory>
#include <string>
#include <utility>

namespace benchmark_support {

// Whether figure8_sampler() knows `input`.
inline bool is_figure8_input(const std::string& input)
{
  return is_unit_square_input(input) || input == "image" || input == "terrain";
}

// A terrain-like density: the absolute Laplacian of a few hills and ridges,
// high on slopes' bends and low on flats, plus a floor.
template <class Point>
double terrain_density(const Point& p)
{
  static const double hills[5][4] = {{0.3, 0.3, 0.12, 1.0}, {0.7, 0.35, 0.08, 0.6}, {0.55, 0.75, 0.15, 0.8},
                                     {0.2, 0.8, 0.05, 0.4}, {0.85, 0.85, 0.1, 0.5}};
  double lap = 0.;
  for(const auto& h : hills) {
    const double dx = p.x() - h[0], dy = p.y() - h[1], s2 = h[2] * h[2];
    const double r2 = dx * dx + dy * dy;
    lap += h[3] * std::exp(-r2 / (2 * s2)) * (r2 - 2 * s2) / (s2 * s2);
  }
  return 5. + std::abs(lap + 30. * std::sin(9 * p.x()) * std::sin(7 * p.y()));
}

// A sampler of about n points of `input` (see is_figure8_input()); `image`
// is the luminance image of the input "image".
template <class K>
CGAL::Penrose_importance_sampler<K> figure8_sampler(const std::string& input, double n, const std::string& image)
{
  typedef typename K::Point_2 Point;
  typedef CGAL::Penrose_importance_sampler<K> Sampler;
  const typename K::Iso_rectangle_2 unit(0, 0, 1, 1);
  const auto np = sampling_parameters(n);
  if(input == "terrain") return Sampler(unit, terrain_density<Point>, np);
  if(input == "image") {
    CGAL::IO::Luminance_image img = CGAL::IO::read_luminance_image(image);
    for(double& v : img.values) v += 0.02;  // dark regions get a few points too
    auto d = std::make_shared<CGAL::Raster_density_2<K>>(img.width, img.height, std::move(img.values), unit);
    return Sampler(unit, [d](const Point& p) { return (*d)(p); },
      CGAL::parameters::density_upper_bound([d](const typename K::Iso_rectangle_2& b) { return d->upper_bound(b); }, np));
  }
  return unit_square_sampler<K>(input, n);
}

} // namespace benchmark_support

#endif // PENROSE_BENCHMARK_FIGURE8_INPUTS_H

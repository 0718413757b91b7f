// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One measurement of the paper's Figure 8: one input density, one size, one
// method, repeated; prints a CSV row
//   input,N,method,median_seconds,ns_per_point,peak_bytes_per_point
// The script run_benchmarks.sh calls it once per (input, size, method), each
// in its own process so that the peak memory (of the first repetition) is that
// of the method alone, and adds the ratio to CGAL's range insertion.
//
//   figure8_benchmark INPUT N METHOD REPETITIONS [IMAGE]
//   INPUT: constant | ramp | image | terrain
//   METHOD: incremental          Delaunay_triangulation_2::insert(p), one point at a time, no hint
//           hierarchy            Triangulation_hierarchy_2::insert(p), one point at a time, sampler order
//           hierarchy_range      Triangulation_hierarchy_2::insert(range)
//           cgal_range           Delaunay_triangulation_2::insert(range): spatial sort + insert (the reference)
//           penrose              Penrose_Delaunay_triangulation_2 from the sampler: sampling and triangulation
//           sampling             Penrose_importance_sampler alone (streaming)

#include <CGAL/Penrose_Delaunay_triangulation_2.h>
#include <CGAL/Raster_density_2.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/IO/read_luminance_image.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "benchmark_support.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_2 Point;
typedef CGAL::Penrose_importance_sampler<K> Sampler;
typedef CGAL::Delaunay_triangulation_2<K> Dt;
typedef benchmark_support::Hierarchy<K> Hierarchy;
using benchmark_support::now;

// A terrain-like density: the absolute Laplacian of a few hills and ridges,
// high on slopes' bends and low on flats, plus a floor.
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

Sampler make_sampler(const std::string& input, double n, const std::string& image)
{
  const K::Iso_rectangle_2 unit(0, 0, 1, 1);
  const auto np = benchmark_support::sampling_parameters(n);
  if(input == "terrain") return Sampler(unit, terrain_density, np);
  if(input == "image") {
    CGAL::IO::Luminance_image img = CGAL::IO::read_luminance_image(image);
    for(double& v : img.values) v += 0.02;  // dark regions get a few points too
    auto d = std::make_shared<CGAL::Raster_density_2<K>>(img.width, img.height, std::move(img.values), unit);
    return Sampler(unit, [d](const Point& p) { return (*d)(p); },
      CGAL::parameters::density_upper_bound([d](const K::Iso_rectangle_2& b) { return d->upper_bound(b); }, np));
  }
  return benchmark_support::unit_square_sampler<K>(input, n);
}

// Runs `method` on the points; returns the number of vertices it made.
std::size_t run(const std::string& method, const Sampler& sampler, const std::vector<Point>& points)
{
  if(method == "incremental") {
    Dt dt;
    for(const Point& p : points) dt.insert(p);
    return dt.number_of_vertices();
  }
  if(method == "hierarchy") {
    Hierarchy h;
    for(const Point& p : points) h.insert(p);
    return h.number_of_vertices();
  }
  if(method == "hierarchy_range") {
    Hierarchy h;
    h.insert(points.begin(), points.end());
    return h.number_of_vertices();
  }
  if(method == "cgal_range") {
    Dt dt;
    dt.insert(points.begin(), points.end());
    return dt.number_of_vertices();
  }
  if(method == "penrose") {
    CGAL::Penrose_Delaunay_triangulation_2<K> pdt(sampler);
    return pdt.number_of_vertices();
  }
  if(method == "sampling") {
    std::vector<Point> p;
    p.reserve(points.size());
    sampler(std::back_inserter(p));
    return p.size();
  }
  throw std::invalid_argument("unknown method " + method);
}

} // namespace

int main(int argc, char** argv)
{
  if(argc < 5) {
    std::cerr << "usage: figure8_benchmark INPUT N METHOD REPETITIONS [IMAGE]\n";
    return 2;
  }
  const std::string input = argv[1], method = argv[3];
  const double n = std::atof(argv[2]);
  const int repetitions = std::max(1, std::atoi(argv[4]));
  const std::string image = argc > 5 ? argv[5] : "data/test_image.png";
  try {
    const Sampler sampler = make_sampler(input, n, image);
    std::vector<Point> points;
    sampler(std::back_inserter(points));
    const double before = benchmark_support::peak_resident_bytes();
    double extra = 0.;
    std::vector<double> t;
    for(int r = 0; r < repetitions; ++r) {
      const double t0 = now();
      const std::size_t made = run(method, sampler, points);
      t.push_back(now() - t0);
      // the peak of one construction: later repetitions can add the
      // allocator's fragmentation to it
      if(r == 0) extra = std::max(0., benchmark_support::peak_resident_bytes() - before);
      if(made != points.size()) {
        std::cerr << method << ": " << made << " vertices for " << points.size() << " points\n";
        return 1;
      }
    }
    const double median = benchmark_support::median(t);
    std::printf("%s,%zu,%s,%.6g,%.6g,%.6g\n", input.c_str(), points.size(), method.c_str(), median,
                median / double(points.size()) * 1e9, extra / double(points.size()));
  } catch(const std::exception& e) {
    std::cerr << "figure8_benchmark: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

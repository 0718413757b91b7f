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
//           penrose_parallel     the same with Parallel_tag, on the threads that TBB allows (built with TBB only)
//           sampling             Penrose_importance_sampler alone (streaming)

#include <CGAL/Penrose_Delaunay_triangulation_2.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "benchmark_support.h"
#include "figure8_inputs.h"

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
#if defined(CGAL_LINKED_WITH_TBB)
  if(method == "penrose_parallel") {
    CGAL::Penrose_Delaunay_triangulation_2<K, CGAL::Default, CGAL::Parallel_tag> pdt(sampler);
    return pdt.number_of_vertices();
  }
#endif
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
    const Sampler sampler = benchmark_support::figure8_sampler<K>(input, n, image);
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

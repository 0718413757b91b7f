// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the benchmark programs share: a clock, medians, the peak resident
// memory, the Devillers hierarchy they compare against, and the samplers of
// the two inputs of the speed bars.

#ifndef PENROSE_BENCHMARK_SUPPORT_H
#define PENROSE_BENCHMARK_SUPPORT_H

#include <CGAL/Penrose_importance_sampler.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_hierarchy_2.h>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <vector>

namespace benchmark_support {

template <class K>
using Hierarchy = CGAL::Triangulation_hierarchy_2<CGAL::Delaunay_triangulation_2<K,
  CGAL::Triangulation_data_structure_2<CGAL::Triangulation_hierarchy_vertex_base_2<
    CGAL::Triangulation_vertex_base_2<K>>>>>;

inline double now()
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

inline double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

// The peak resident memory of the process so far.
inline double peak_resident_bytes()
{
  rusage u;
  getrusage(RUSAGE_SELF, &u);
  return double(u.ru_maxrss) * 1024.;
}

// The sampler's parameters for about n points, up to sizes beyond its
// default maximum.
inline auto sampling_parameters(double n)
{
  return CGAL::parameters::number_of_output_points(std::size_t(n)).maximum_number(std::size_t(1e9));
}

// Whether unit_square_sampler() knows `input`.
inline bool is_unit_square_input(const std::string& input) { return input == "constant" || input == "ramp"; }

// A sampler of about n points on the unit square, for the constant density
// or the ramp of the paper's Figure 7 (`input`: "constant" or "ramp").
template <class K>
CGAL::Penrose_importance_sampler<K> unit_square_sampler(const std::string& input, double n)
{
  typedef typename K::Point_2 Point;
  const typename K::Iso_rectangle_2 unit(0, 0, 1, 1);
  const auto np = sampling_parameters(n);
  if(!is_unit_square_input(input)) throw std::invalid_argument("unknown input " + input);
  if(input == "constant") return CGAL::Penrose_importance_sampler<K>(unit, [](const Point&) { return 1.; }, np);
  return CGAL::Penrose_importance_sampler<K>(unit, [](const Point& p) { return p.x(); }, np);
}

} // namespace benchmark_support

#endif // PENROSE_BENCHMARK_SUPPORT_H

// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What the benchmark programs share: a clock, medians, the peak resident
// memory, and the Devillers hierarchy they compare against.

#ifndef PENROSE_BENCHMARK_SUPPORT_H
#define PENROSE_BENCHMARK_SUPPORT_H

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Triangulation_hierarchy_2.h>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
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

} // namespace benchmark_support

#endif // PENROSE_BENCHMARK_SUPPORT_H

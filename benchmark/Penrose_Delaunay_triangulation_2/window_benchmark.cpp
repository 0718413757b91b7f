// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The windowed construction (Penrose_Delaunay_window_2 and
// Penrose_Delaunay_border_2) measured:
//
//   window_benchmark speed N constant|ramp K [RUNS] [THREADS]
//     the windows of a K x K grid and the border, computed in TBB tasks on
//     THREADS threads (default: all), against CGAL's range insertion of the
//     same points in the same process (medians), with the margins' retries;
//   window_benchmark calls N constant|ramp K
//     the density calls that the middle window of a K x K grid makes, in the
//     window, in its margin and outside both, its sampler given the
//     region's integral (as a worker's is).

#include "benchmark_support.h"

#include <CGAL/Penrose_Delaunay_border_2.h>
#include <CGAL/Penrose_Delaunay_window_2.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#endif

#include <atomic>
#include <cstdlib>
#include <iostream>
#include <optional>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
using namespace benchmark_support;

K::Iso_rectangle_2 window(int k, int i, int j)
{
  auto cut = [k](int c) { return c == k ? 1. : double(c) / k; };
  return K::Iso_rectangle_2(cut(i), cut(j), cut(i + 1), cut(j + 1));
}

int speed(double n, const std::string& input, int k, int runs)
{
  const CGAL::Penrose_importance_sampler<K> sampler = unit_square_sampler<K>(input, n);
  std::vector<K::Point_2> points;
  sampler(std::back_inserter(points));
  std::vector<double> windowed, cgal;
  for(int r = 0; r < runs; ++r) {
    double t = now();
    std::atomic<std::size_t> triangles{0}, retries{0};
    auto one = [&](int w) {
      const CGAL::Penrose_Delaunay_window_2<K> part(sampler, window(k, w % k, w / k));
      triangles += part.triangles().size();
      retries += std::size_t(part.attempts() - 1);
    };
#ifdef CGAL_LINKED_WITH_TBB
    tbb::parallel_for(0, k * k + 1, [&](int w) {
      if(w < k * k) one(w);
      else triangles += CGAL::Penrose_Delaunay_border_2<K>(sampler).triangles().size();
    });
#else
    for(int w = 0; w < k * k; ++w) one(w);
    triangles += CGAL::Penrose_Delaunay_border_2<K>(sampler).triangles().size();
#endif
    windowed.push_back(now() - t);
    t = now();
    const CGAL::Delaunay_triangulation_2<K> dt(points.begin(), points.end());
    cgal.push_back(now() - t);
    std::cout << "run " << r << ": " << points.size() << " points, " << k << " x " << k << " windows: "
              << windowed.back() << " s (" << triangles << " triangles, CGAL's " << dt.number_of_faces() << ", "
              << retries << " retries), CGAL range insertion " << cgal.back() << " s\n";
  }
  std::cout << input << " " << n << " windows " << k << " x " << k << ": ratio to CGAL range insertion "
            << median(windowed) / median(cgal) << "\n";
  return 0;
}

int calls(double n, const std::string& input, int k)
{
  const CGAL::Penrose_importance_sampler<K> whole = unit_square_sampler<K>(input, n);
  const K::Iso_rectangle_2 w = window(k, k / 2, k / 2);
  struct Counts { std::size_t inside = 0, margin = 0, outside = 0; } c;
  double m = 0.;
  auto count = [&](const K::Point_2& p) {
    const bool in = p.x() >= w.xmin() && p.x() <= w.xmax() && p.y() >= w.ymin() && p.y() <= w.ymax();
    const bool near = p.x() >= w.xmin() - m && p.x() <= w.xmax() + m && p.y() >= w.ymin() - m && p.y() <= w.ymax() + m;
    ++(in ? c.inside : near ? c.margin : c.outside);
    return input == "constant" ? 1. : p.x();
  };
  const CGAL::Penrose_importance_sampler<K> worker(
    K::Iso_rectangle_2(0, 0, 1, 1), count,
    CGAL::parameters::density_integral(whole.density_integral(), sampling_parameters(n)));
  m = CGAL::Penrose_Delaunay_window_2<K>(worker, w).margin();  // first, to know the margin
  c = Counts();
  const CGAL::Penrose_Delaunay_window_2<K> part(worker, w);
  std::cout << input << " " << n << ", the middle window of " << k << " x " << k << " (" << part.points().size()
            << " points, margin " << part.margin() << ", " << part.attempts() << " attempts): density calls "
            << c.inside << " in it, " << c.margin << " in its margin, " << c.outside << " outside both\n";
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  const std::string mode = argc > 1 ? argv[1] : "";
  if(argc >= 5 && (mode == "speed" || mode == "calls") && is_unit_square_input(argv[3])) {
    const double n = std::atof(argv[2]);
    const int k = std::atoi(argv[4]);
    if(mode == "calls") return calls(n, argv[3], k);
#ifdef CGAL_LINKED_WITH_TBB
    std::optional<tbb::global_control> threads;
    if(argc > 6) threads.emplace(tbb::global_control::max_allowed_parallelism, std::size_t(std::atoi(argv[6])));
#endif
    return speed(n, argv[3], k, argc > 5 ? std::atoi(argv[5]) : 5);
  }
  std::cerr << "usage: window_benchmark speed N constant|ramp K [RUNS] [THREADS] | calls N constant|ramp K\n";
  return 2;
}

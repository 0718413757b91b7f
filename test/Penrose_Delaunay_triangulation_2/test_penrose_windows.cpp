// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Penrose_Delaunay_window_2 and Penrose_Delaunay_border_2 against CGAL's
// Delaunay_triangulation_2 of the whole sample: over partitions of the
// region into windows (regular grids of 1 x 1 to 16 x 16 and irregular
// cuts), the windows give every sample once, and with the border every
// triangle of CGAL's triangulation once, and its hull.

#include "streamed_ply.h"

#include <CGAL/Penrose_Delaunay_border_2.h>
#include <CGAL/Penrose_Delaunay_window_2.h>
#include <CGAL/Penrose_importance_sampler.h>
#include <CGAL/Raster_density_2.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <gtest/gtest.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/parallel_for.h>
#endif

#include <unistd.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef std::uint64_t Key;
typedef std::array<Key, 3> Triangle;

// The triangle turned so that its smallest key comes first: the same
// triangle, counter-clockwise, is the same array.
Triangle rotated(Triangle t)
{
  std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
  return t;
}

// CGAL's triangulation of the whole sample, as key triples, and its hull's keys.
template <class K>
struct Reference
{
  std::set<Triangle> triangles;
  std::set<Key> hull;
  std::set<Key> keys;
  std::size_t points = 0;

  explicit Reference(const CGAL::Penrose_importance_sampler<K>& sampler)
  {
    typedef CGAL::Triangulation_vertex_base_with_info_2<Key, Epick> Vb;
    typedef CGAL::Delaunay_triangulation_2<Epick, CGAL::Triangulation_data_structure_2<Vb>> Dt;
    std::vector<typename CGAL::Penrose_importance_sampler<K>::Sample> samples;
    sampler.samples(std::back_inserter(samples));
    std::vector<std::pair<Epick::Point_2, Key>> points_with_keys;
    for(const auto& s : samples) {
      points_with_keys.emplace_back(Epick::Point_2(CGAL::to_double(s.point.x()), CGAL::to_double(s.point.y())), s.key);
      keys.insert(s.key);
    }
    points = samples.size();
    Dt dt(points_with_keys.begin(), points_with_keys.end());
    for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
      triangles.insert(rotated({{f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()}}));
    auto v = dt.incident_vertices(dt.infinite_vertex()), done = v;
    do hull.insert(v->info()); while(++v != done);
  }
};

struct Partition_result
{
  std::vector<Key> keys;
  std::vector<Triangle> triangles;
  int retries = 0;
};

template <class K>
Partition_result triangulate_in_windows(const CGAL::Penrose_importance_sampler<K>& sampler, const std::vector<double>& xs,
                                        const std::vector<double>& ys, double margin = 0.)
{
  Partition_result r;
  for(std::size_t j = 0; j + 1 < ys.size(); ++j)
    for(std::size_t i = 0; i + 1 < xs.size(); ++i) {
      const typename K::Iso_rectangle_2 w(xs[i], ys[j], xs[i + 1], ys[j + 1]);
      const CGAL::Penrose_Delaunay_window_2<K> window =
        margin > 0. ? CGAL::Penrose_Delaunay_window_2<K>(sampler, w, CGAL::parameters::window_margin(margin))
                    : CGAL::Penrose_Delaunay_window_2<K>(sampler, w);
      EXPECT_TRUE(std::is_sorted(window.keys().begin(), window.keys().end()));
      EXPECT_EQ(window.keys().size(), window.points().size());
      for(std::size_t k = 0; k < window.points().size(); ++k) {
        // the window's own samples lie in it (half-open, closed on the region's border)
        const auto& p = window.points()[k];
        EXPECT_TRUE(CGAL::to_double(p.x()) >= xs[i] && CGAL::to_double(p.y()) >= ys[j]);
        EXPECT_TRUE(CGAL::to_double(p.x()) < xs[i + 1] || i + 2 == xs.size());
        EXPECT_TRUE(CGAL::to_double(p.y()) < ys[j + 1] || j + 2 == ys.size());
      }
      r.keys.insert(r.keys.end(), window.keys().begin(), window.keys().end());
      r.triangles.insert(r.triangles.end(), window.triangles().begin(), window.triangles().end());
      r.retries += window.attempts() - 1;
    }
  return r;
}

std::vector<double> grid(double lo, double hi, int k)
{
  std::vector<double> c;
  for(int i = 0; i <= k; ++i) c.push_back(i == k ? hi : lo + (hi - lo) * i / k);
  return c;
}

template <class K>
void expect_partition_is_the_triangulation(const CGAL::Penrose_importance_sampler<K>& sampler, const Reference<K>& reference,
                                           const CGAL::Penrose_Delaunay_border_2<K>& border,
                                           const std::vector<double>& xs, const std::vector<double>& ys,
                                           const std::string& what, double margin = 0.)
{
  Partition_result r = triangulate_in_windows(sampler, xs, ys, margin);
  std::vector<Key> keys = r.keys;
  std::sort(keys.begin(), keys.end());
  EXPECT_EQ(keys.size(), reference.points) << what;
  EXPECT_TRUE(std::adjacent_find(keys.begin(), keys.end()) == keys.end()) << what << ": a sample in two windows";
  EXPECT_TRUE(std::equal(keys.begin(), keys.end(), reference.keys.begin(), reference.keys.end())) << what;

  r.triangles.insert(r.triangles.end(), border.triangles().begin(), border.triangles().end());
  const std::size_t h = border.hull().size();
  EXPECT_EQ(r.triangles.size(), 2 * reference.points - h - 2) << what << ": 2N - h - 2";
  std::set<Triangle> found;
  for(const Triangle& t : r.triangles) {
    EXPECT_TRUE(found.insert(rotated(t)).second) << what << ": a triangle twice";
  }
  EXPECT_EQ(found.size(), reference.triangles.size()) << what;
  EXPECT_TRUE(found == reference.triangles) << what << ": not CGAL's triangles";
  if(margin > 0.) {
    EXPECT_GT(r.retries, 0) << what << ": a margin that small must be grown";
  }
}

template <class K>
void expect_border_is_the_hull(const CGAL::Penrose_Delaunay_border_2<K>& border, const Reference<K>& reference,
                               const std::string& what)
{
  EXPECT_EQ(std::set<Key>(border.hull().begin(), border.hull().end()), reference.hull) << what;
  EXPECT_EQ(border.hull().size(), reference.hull.size()) << what;
}

template <class K, class Density>
void check_density(const Density& density, std::size_t n, const std::string& what)
{
  typedef typename K::Iso_rectangle_2 Rectangle;
  const CGAL::Penrose_importance_sampler<K> sampler(Rectangle(0, 0, 2, 1), density,
                                                    CGAL::parameters::number_of_output_points(n));
  const Reference<K> reference(sampler);
  const CGAL::Penrose_Delaunay_border_2<K> border(sampler);
  expect_border_is_the_hull(border, reference, what);
  for(int k : {1, 2, 5, 16})
    expect_partition_is_the_triangulation(sampler, reference, border, grid(0, 2, k), grid(0, 1, k),
                                          what + ", " + std::to_string(k) + " x " + std::to_string(k));
  // irregular cuts, one of them through a sample, and windows that reach beyond the region
  std::vector<typename K::Point_2> some;
  sampler(std::back_inserter(some));
  const double through = CGAL::to_double(some[some.size() / 3].x());
  std::vector<double> xs = {-0.5, 0.013, through, 1.37, 2.5};
  std::sort(xs.begin(), xs.end());
  expect_partition_is_the_triangulation(sampler, reference, border, xs, {-1., 0.29, 0.3, 0.88, 3.},
                                        what + ", irregular");
  // a margin far too small is found out by the certificate and grown
  expect_partition_is_the_triangulation(sampler, reference, border, grid(0, 2, 3), grid(0, 1, 2),
                                        what + ", margin 1e-4", 1e-4);
}

template <class K>
void check_densities(std::size_t n)
{
  check_density<K>([](const typename K::Point_2&) { return 1.; }, n, "constant");
  check_density<K>([](const typename K::Point_2& p) { return 0.05 + CGAL::to_double(p.x()); }, n, "ramp");
  // steep: four orders of magnitude across a narrow front
  check_density<K>([](const typename K::Point_2& p) {
    return 1e-2 + std::exp(-std::pow((CGAL::to_double(p.x()) - 1.) * 30., 2)) * 100.;
  }, n, "steep");
  // holes of zero density, inside and on the border
  check_density<K>([](const typename K::Point_2& p) {
    const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y());
    const bool hole = std::hypot(x - 0.7, y - 0.5) < 0.2 || (x > 1.6 && y < 0.3);
    return hole ? 0. : 1.;
  }, n, "holes");
}

TEST(PenroseDelaunayWindows, EpickPartitionsAreCgalsTriangulation) { check_densities<Epick>(100000); }

// The sampler of the unit square against CGAL, on k x k windows for each k.
void check_square_grids(const CGAL::Penrose_importance_sampler<Epick>& sampler, const std::string& what,
                        std::initializer_list<int> ks)
{
  const Reference<Epick> reference(sampler);
  const CGAL::Penrose_Delaunay_border_2<Epick> border(sampler);
  expect_border_is_the_hull(border, reference, what);
  for(int k : ks)
    expect_partition_is_the_triangulation(sampler, reference, border, grid(0, 1, k), grid(0, 1, k),
                                          what + ", " + std::to_string(k) + " x " + std::to_string(k));
}

// Without correction vectors the samples are tile vertices, and four of them
// are often cocircular: every window must break the ties as CGAL does.
TEST(PenroseDelaunayWindows, CocircularSamplesArePartitionedAsCgalBreaksTies)
{
  typedef Epick::Point_2 Point;
  const CGAL::Penrose_importance_sampler<Epick> sampler(
    Epick::Iso_rectangle_2(0, 0, 1, 1), [](const Point&) { return 1.; },
    CGAL::parameters::use_correction_vectors(false, CGAL::parameters::number_of_output_points(40000)));
  check_square_grids(sampler, "lattice", {1, 3, 8});
}

// A window computed by a worker whose sampler was given the region's
// integral is the same, bit for bit, as one of the sampler that measured it.
TEST(PenroseDelaunayWindows, AWorkersWindowIsTheSame)
{
  typedef Epick::Point_2 Point;
  auto ramp = [](const Point& p) { return 0.05 + p.x(); };
  const Epick::Iso_rectangle_2 region(0, 0, 1, 1), window(0.3, 0.2, 0.55, 0.7);
  const CGAL::Penrose_importance_sampler<Epick> whole(region, ramp, CGAL::parameters::number_of_output_points(50000));
  const CGAL::Penrose_importance_sampler<Epick> worker(
    region, ramp, CGAL::parameters::density_integral(whole.density_integral(), CGAL::parameters::number_of_output_points(50000)));
  const CGAL::Penrose_Delaunay_window_2<Epick> a(whole, window), b(worker, window);
  EXPECT_EQ(a.keys(), b.keys());
  EXPECT_TRUE(a.points() == b.points());
  EXPECT_EQ(a.triangles(), b.triangles());
  EXPECT_GT(a.triangles().size(), 5000u);
}

// What the density throws in a worker reaches the caller, and a streamed
// file is then not left behind, half written.
TEST(PenroseDelaunayWindows, WhatTheDensityThrowsInAWorkerReachesTheCaller)
{
  typedef Epick::Point_2 Point;
  const Epick::Iso_rectangle_2 region(0, 0, 1, 1);
  auto throwing = [](const Point& p) -> double {
    if(CGAL::squared_distance(p, Point(0.8, 0.75)) < 0.0025) throw std::runtime_error("no data here");
    return 1.;
  };
  // the integral given, as a worker's: sampling the whole region would throw at once
  const CGAL::Penrose_importance_sampler<Epick> sampler(
    region, throwing, CGAL::parameters::density_integral(1., CGAL::parameters::number_of_output_points(100000)));
  // a window far from it reads the density near itself and at its tiles' ancestors' corners only
  EXPECT_NO_THROW(CGAL::Penrose_Delaunay_window_2<Epick>(sampler, Epick::Iso_rectangle_2(0, 0, 0.3, 0.3)));
#ifdef CGAL_LINKED_WITH_TBB
  EXPECT_THROW(tbb::parallel_for(0, 16, [&](int w) {
                 const double x = 0.25 * (w % 4), y = 0.25 * (w / 4);
                 CGAL::Penrose_Delaunay_window_2<Epick>(sampler, Epick::Iso_rectangle_2(x, y, x + 0.25, y + 0.25));
               }), std::runtime_error);
#endif
  const std::string file = testing::TempDir() + "penrose_windows_throwing.ply";
  std::remove(file.c_str());
  penrose_tools::Streamed_ply_writer<Epick> writer(sampler, 4000.);
  EXPECT_THROW(writer.write(file, {}), std::runtime_error);
  EXPECT_NE(access(file.c_str(), F_OK), 0) << "a failed stream left " << file;
}

std::string file_bytes(const std::string& name)
{
  std::ifstream in(name, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

// The streamed PLY, its windows computed in TBB's tasks and written in
// order, is the same file on every thread count.
TEST(PenroseDelaunayWindows, StreamedPlyIsTheSameOnEveryThreadCount)
{
  typedef Epick::Point_2 Point;
  const CGAL::Penrose_importance_sampler<Epick> sampler(
    Epick::Iso_rectangle_2(0, 0, 2, 1), [](const Point& p) { return 0.05 + p.x() * p.y(); },
    CGAL::parameters::number_of_output_points(60000));
  std::string first;
  for(int threads : {1, 2, 3, 8}) {
#ifdef CGAL_LINKED_WITH_TBB
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, std::size_t(threads));
#endif
    const std::string file = testing::TempDir() + "penrose_windows_streamed.ply";
    const penrose_tools::Streamed_mesh m = penrose_tools::Streamed_ply_writer<Epick>(sampler, 2000.).write(file, {});
    EXPECT_GT(m.windows, 20u);
    EXPECT_EQ(m.faces, 2 * m.vertices - CGAL::Penrose_Delaunay_border_2<Epick>(sampler).hull().size() - 2);
    const std::string bytes = file_bytes(file);
    if(first.empty()) first = bytes;
    EXPECT_TRUE(bytes == first) << threads << " threads";
    std::remove(file.c_str());
  }
}

// 10^6 points: about 6 s.
TEST(PenroseDelaunayWindows, MillionPointPartitionsAreCgalsTriangulation)
{
  typedef Epick::Point_2 Point;
  const CGAL::Penrose_importance_sampler<Epick> sampler(
    Epick::Iso_rectangle_2(0, 0, 1, 1), [](const Point& p) { return p.x(); }, CGAL::parameters::number_of_output_points(1000000));
  check_square_grids(sampler, "ramp 10^6", {1, 4, 16});
}

TEST(PenroseDelaunayWindows, EpeckPartitionsAreCgalsTriangulation)
{
  check_density<CGAL::Exact_predicates_exact_constructions_kernel>(
    [](const auto& p) { return 0.05 + CGAL::to_double(p.x()); }, 5000, "ramp, Epeck");
}

} // namespace

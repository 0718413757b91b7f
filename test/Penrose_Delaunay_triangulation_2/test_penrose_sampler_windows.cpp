// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Penrose_importance_sampler's windows against the whole sample:
// test_windows<K>() partitions the region into windows, some of them cut
// through samples, and checks that together they give every sample of the
// region once, bit for bit; run over Epick, Epeck and Simple_cartesian<Gmpq>.

#include <CGAL/Penrose_importance_sampler.h>
#include <CGAL/Raster_density_2.h>

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <iterator>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

typedef std::pair<double, double> XY;

template <class K>
std::vector<XY> coordinates(const std::vector<typename K::Point_2>& points)
{
  std::vector<XY> xy;
  for(const auto& p : points) xy.emplace_back(CGAL::to_double(p.x()), CGAL::to_double(p.y()));
  return xy;
}

// The cuts of an axis: the ends, irregular steps, and the coordinate of a
// sample, so that a window's open side runs through it.
std::vector<double> cuts(double lo, double hi, double through)
{
  std::vector<double> c = {lo, lo + 0.13 * (hi - lo), through, lo + 0.71 * (hi - lo), hi};
  std::sort(c.begin(), c.end());
  return c;
}

template <class K, class Sampler>
void expect_windows_partition_the_sample(const Sampler& sampler, const std::string& what)
{
  typedef typename K::Point_2 Point;
  typedef typename K::Iso_rectangle_2 Rectangle;
  std::vector<Point> all;
  sampler(std::back_inserter(all));
  ASSERT_GT(all.size(), 10u) << what;
  const std::vector<XY> whole = coordinates<K>(all);
  const Rectangle& r = sampler.region();
  const XY middle = whole[whole.size() / 2];
  const std::vector<double> xs = cuts(CGAL::to_double(r.xmin()), CGAL::to_double(r.xmax()), middle.first);
  const std::vector<double> ys = cuts(CGAL::to_double(r.ymin()), CGAL::to_double(r.ymax()), middle.second);

  std::vector<XY> together;
  std::size_t largest = 0;
  for(std::size_t i = 0; i + 1 < xs.size(); ++i)
    for(std::size_t j = 0; j + 1 < ys.size(); ++j) {
      std::vector<Point> part;
      sampler(Rectangle(Point(xs[i], ys[j]), Point(xs[i + 1], ys[j + 1])), std::back_inserter(part));
      for(const XY& p : coordinates<K>(part)) {
        EXPECT_TRUE(p.first >= xs[i] && p.first <= xs[i + 1] && p.second >= ys[j] && p.second <= ys[j + 1]) << what;
        together.push_back(p);
      }
      largest = (std::max)(largest, part.size());
    }
  EXPECT_LT(largest, whole.size()) << what;
  std::vector<XY> sorted = whole;
  std::sort(sorted.begin(), sorted.end());
  std::sort(together.begin(), together.end());
  EXPECT_EQ(together.size(), sorted.size()) << what;
  EXPECT_TRUE(together == sorted) << what;

  // the region as a window, or a larger one: the same points in the same order
  for(double grow : {0., 1.}) {
    std::vector<Point> same;
    sampler(Rectangle(Point(CGAL::to_double(r.xmin()) - grow, CGAL::to_double(r.ymin()) - grow),
                      Point(CGAL::to_double(r.xmax()) + grow, CGAL::to_double(r.ymax()) + grow)),
            std::back_inserter(same));
    EXPECT_TRUE(coordinates<K>(same) == whole) << what << ", window grown by " << grow;
  }
  // samples(window) agrees with the points
  std::vector<typename Sampler::Sample> s;
  sampler.samples(Rectangle(Point(xs[1], ys[1]), Point(xs[3], ys[3])), std::back_inserter(s));
  std::vector<Point> p;
  sampler(Rectangle(Point(xs[1], ys[1]), Point(xs[3], ys[3])), std::back_inserter(p));
  ASSERT_EQ(s.size(), p.size()) << what;
  for(std::size_t k = 0; k < s.size(); ++k) EXPECT_TRUE(s[k].point == p[k]) << what;
}

template <class K>
void test_windows(std::size_t n, const std::string& kernel)
{
  typedef typename K::Point_2 Point;
  typedef typename K::Iso_rectangle_2 Rectangle;
  typedef CGAL::Penrose_importance_sampler<K> Sampler;
  using CGAL::parameters::density_upper_bound;
  using CGAL::parameters::number_of_output_points;
  using CGAL::parameters::use_correction_vectors;
  const Rectangle region(Point(-3, 2), Point(5, 6));

  auto ramp = [](const Point& p) { return 1 + CGAL::to_double(p.x()) + 3; };
  auto bump = [](const Point& p) {
    const double dx = CGAL::to_double(p.x()) - 1, dy = CGAL::to_double(p.y()) - 4;
    return 0.05 + std::exp(-(dx * dx + dy * dy));
  };
  expect_windows_partition_the_sample<K>(Sampler(region, ramp, number_of_output_points(n)), kernel + ", ramp");
  expect_windows_partition_the_sample<K>(Sampler(region, bump, use_correction_vectors(false, number_of_output_points(n))),
                                         kernel + ", bump without correction");
  std::vector<double> pixels(64 * 32);
  for(std::size_t k = 0; k < pixels.size(); ++k) pixels[k] = double((k * 37) % 11) + 0.5 * double(k % 64);
  const CGAL::Raster_density_2<K> raster(64, 32, pixels, region);
  expect_windows_partition_the_sample<K>(
    Sampler(region, raster, density_upper_bound(raster.upper_bound_function(), number_of_output_points(n))),
    kernel + ", raster with its bound");
}

} // namespace

TEST(Windows, PartitionTheSampleOverEpick) { test_windows<CGAL::Exact_predicates_inexact_constructions_kernel>(20000, "Epick"); }

TEST(Windows, PartitionTheSampleOverEpeck) { test_windows<CGAL::Exact_predicates_exact_constructions_kernel>(2000, "Epeck"); }

TEST(Windows, PartitionTheSampleOverGmpq) { test_windows<CGAL::Simple_cartesian<CGAL::Gmpq>>(1000, "Simple_cartesian<Gmpq>"); }

// A small window asks for the density only around it: its cost follows its
// samples, not the region's.
TEST(Windows, SmallWindowVisitsFewTiles)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  std::size_t calls = 0;
  CGAL::Penrose_importance_sampler<K> sampler(K::Iso_rectangle_2(0, 0, 1, 1),
                                              [&calls](const K::Point_2& p) { ++calls; return 1 + 4 * p.x(); },
                                              CGAL::parameters::density_control_factor(200000.));
  std::vector<K::Point_2> all, part;
  calls = 0;
  sampler(std::back_inserter(all));
  const std::size_t whole_calls = calls;
  calls = 0;
  sampler(K::Iso_rectangle_2(0.3, 0.3, 0.4, 0.4), std::back_inserter(part));
  EXPECT_GT(part.size(), 0.005 * double(all.size()));
  EXPECT_LT(double(calls), 0.05 * double(whole_calls)) << calls << " calls of " << whole_calls;
  EXPECT_LT(double(calls), 30. * double(part.size()) + 2000.);
}

TEST(Windows, OutsideEmptyAndBadWindows)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  CGAL::Penrose_importance_sampler<K> sampler(K::Iso_rectangle_2(0, 0, 1, 1), [](const K::Point_2&) { return 1.; },
                                              CGAL::parameters::number_of_output_points(5000));
  std::vector<K::Point_2> p;
  sampler(K::Iso_rectangle_2(2, 2, 3, 3), std::back_inserter(p));
  sampler(K::Iso_rectangle_2(0.5, 0, 0.5, 1), std::back_inserter(p));  // no width, inside: open
  EXPECT_TRUE(p.empty());
  const double nan = std::nan("");
  EXPECT_THROW(sampler(K::Iso_rectangle_2(K::Point_2(nan, 0), K::Point_2(1, 1)), std::back_inserter(p)), std::invalid_argument);
  EXPECT_THROW(sampler(K::Iso_rectangle_2(K::Point_2(0, 0), K::Point_2(HUGE_VAL, 1)), std::back_inserter(p)), std::invalid_argument);
}

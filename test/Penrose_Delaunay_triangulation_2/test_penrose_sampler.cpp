// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Properties of Penrose_importance_sampler and Penrose_tile_tree, each
// checked against an independent expectation: geometry of the tiles, the
// Fibonacci codes, point counts against the integral of the density, spacing
// against the packing distance, coverage, determinism and input checks.

#include <CGAL/Penrose_importance_sampler.h>
#include <CGAL/Penrose_tile_tree.h>
#include <CGAL/Raster_density_2.h>
#include "point_set_quality.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Simple_cartesian.h>

#include <boost/iterator/function_output_iterator.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Penrose_importance_sampler<Epick> Sampler;
typedef Epick::Point_2 Point;
namespace Q = Penrose_quality;

const Epick::Iso_rectangle_2 unit_square(0, 0, 1, 1);
const double phi2 = 2.6180339887498949;

std::vector<Point> constant_sample(double n, bool correct = true)
{
  std::vector<Point> p;
  Sampler s(unit_square, [](const Point&) { return 1.; },
            CGAL::parameters::use_correction_vectors(correct).number_of_output_points(std::size_t(n)));
  s(std::back_inserter(p));
  return p;
}

double triangle_area(const CGAL::Penrose_tile_tree& tree, CGAL::Penrose_tile_tree::Index t)
{
  const auto& tile = tree.tile(t);
  const auto& a = tree.vertex(tile.vertices[0]);
  const auto& b = tree.vertex(tile.vertices[1]);
  const auto& c = tree.vertex(tile.vertices[2]);
  return 0.5 * ((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
}

// Separating axis test with a tolerance: true if the interiors overlap by more than eps.
bool interiors_overlap(const CGAL::Penrose_tile_tree& tree, CGAL::Penrose_tile_tree::Index s,
                       CGAL::Penrose_tile_tree::Index t, double eps)
{
  const CGAL::Penrose_tile_tree::Index tiles[2] = {s, t};
  for(int k = 0; k < 2; ++k)
    for(int e = 0; e < 3; ++e) {
      const auto& a = tree.vertex(tree.tile(tiles[k]).vertices[e]);
      const auto& b = tree.vertex(tree.tile(tiles[k]).vertices[(e + 1) % 3]);
      const double nx = b.y - a.y, ny = a.x - b.x; // outward normal of a ccw edge
      double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
      for(int m = 0; m < 2; ++m)
        for(int i = 0; i < 3; ++i) {
          const auto& v = tree.vertex(tree.tile(tiles[m]).vertices[i]);
          const double d = nx * (v.x - a.x) + ny * (v.y - a.y);
          lo[m] = std::min(lo[m], d); hi[m] = std::max(hi[m], d);
        }
      const double len = std::hypot(nx, ny);
      if(hi[0] <= lo[1] + eps * len || hi[1] <= lo[0] + eps * len) return false;
    }
  return true;
}

CGAL::Penrose_tile_tree constant_tree(double n)
{
  return Sampler(unit_square, [](const Point&) { return 1.; },
                 CGAL::parameters::number_of_output_points(std::size_t(n))).tile_tree();
}

} // namespace

TEST(Tiles, ChildrenCoverTheirParentExactly)
{
  const CGAL::Penrose_tile_tree tree = constant_tree(3000);
  std::size_t subdivided = 0;
  for(CGAL::Penrose_tile_tree::Index t = 0; t < tree.tiles().size(); ++t) {
    if(tree.is_leaf(t)) continue;
    ++subdivided;
    const double area = triangle_area(tree, t);
    ASSERT_GT(area, 0.);
    double sum = 0.;
    const int n = tree.tile(t).number_of_children;
    for(int c = 0; c < n; ++c) {
      const double a = triangle_area(tree, tree.child(t, c));
      ASSERT_GT(a, 0.) << "child " << c << " of tile " << t << " is not counter-clockwise";
      sum += a;
      for(int c2 = c + 1; c2 < n; ++c2)
        ASSERT_FALSE(interiors_overlap(tree, tree.child(t, c), tree.child(t, c2), 1e-9 * std::sqrt(area)))
          << "children " << c << " and " << c2 << " of tile " << t << " overlap";
    }
    ASSERT_NEAR(sum, area, 1e-12 * area + 1e-15);
  }
  EXPECT_GT(subdivided, 1000u);
}

TEST(Tiles, NeighboursShareTheirEdge)
{
  const CGAL::Penrose_tile_tree tree = constant_tree(3000);
  std::size_t same_level = 0, coarser = 0;
  for(CGAL::Penrose_tile_tree::Index t = 0; t < tree.tiles().size(); ++t)
    for(int e = 0; e < 3; ++e) {
      const auto n = tree.neighbor(t, e);
      if(n == CGAL::Penrose_tile_tree::null_index) continue;
      const auto& tt = tree.tile(t);
      const auto& tn = tree.tile(n);
      ASSERT_LE(tn.level, tt.level);
      const auto& a = tree.vertex(tt.vertices[e]);
      const auto& b = tree.vertex(tt.vertices[(e + 1) % 3]);
      if(tn.level == tt.level) {
        ++same_level;
        const int f = tree.facing_edge(n, t);
        EXPECT_EQ(tn.vertices[f], tt.vertices[(e + 1) % 3]);
        EXPECT_EQ(tn.vertices[(f + 1) % 3], tt.vertices[e]);
      } else {
        ++coarser;
        // the edge lies on an edge of the coarser tile
        bool on_some_edge = false;
        for(int f = 0; f < 3; ++f) {
          const auto& c = tree.vertex(tn.vertices[f]);
          const auto& d = tree.vertex(tn.vertices[(f + 1) % 3]);
          const double l = std::hypot(d.x - c.x, d.y - c.y);
          const double da = ((d.x - c.x) * (a.y - c.y) - (d.y - c.y) * (a.x - c.x)) / l;
          const double db = ((d.x - c.x) * (b.y - c.y) - (d.y - c.y) * (b.x - c.x)) / l;
          if(std::abs(da) < 1e-12 && std::abs(db) < 1e-12) on_some_edge = true;
        }
        EXPECT_TRUE(on_some_edge);
      }
    }
  EXPECT_GT(same_level, 1000u);
  EXPECT_GT(coarser, 0u); // the region's border makes the tree adaptive
}

TEST(Tiles, FCodesAreZeckendorfAndThresholdsDistinct)
{
  const CGAL::Penrose_tile_tree tree = constant_tree(5000);
  for(const auto& t : tree.tiles()) ASSERT_EQ(t.f_code & (t.f_code >> 1), 0u);
  // All sample vertices are A/B tiles of the deepest level: their thresholds
  // must differ, and equal the Fibonacci reading of their codes.
  std::set<std::uint64_t> thresholds;
  std::size_t samples = 0;
  for(const auto& v : tree.vertices()) {
    if(!v.is_sample) continue;
    ++samples;
    ASSERT_EQ(v.birth.code & (v.birth.code >> 1), 0u);
    std::uint64_t f = 0;
    const int bits = 2 * v.birth.level;
    for(int b = 0; b < bits; ++b)
      if(v.birth.code >> b & 1u) f += CGAL::internal::Penrose::fibonacci().fib[bits + 1 - b];
    ASSERT_EQ(f, v.birth.threshold);
    thresholds.insert(v.birth.threshold);
  }
  EXPECT_GT(samples, 5000u);
  EXPECT_EQ(thresholds.size(), samples);
}

// The importance index (the correction table's row) is the step of
// log_{phi^2}(1 + sqrt(5) i) within its level: checked against that
// logarithm in long double, away from the steps' bounds, where rounding
// decides.
TEST(Tiles, ImportanceBinsFollowTheLogarithm)
{
  const long double log_phi2 = std::log(static_cast<long double>(CGAL::internal::Penrose::golden_ratio) *
                                        static_cast<long double>(CGAL::internal::Penrose::golden_ratio));
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> exponent(-4., 12.5);  // up to the deepest level
  for(unsigned bins : {1u, 5u, 21u, 64u}) {
    const CGAL::internal::Penrose::Importance_bins index(bins);
    std::size_t checked = 0;
    for(int k = 0; k < 200000; ++k) {
      const double i = std::pow(10., exponent(random));
      const long double steps = std::log1p(std::sqrt(5.L) * i) / log_phi2 * bins;
      const long double within = steps - std::floor(steps);
      if(within < 1e-9L || within > 1. - 1e-9L) continue;
      ASSERT_EQ(index(i), static_cast<unsigned>(static_cast<unsigned long long>(std::floor(steps)) % bins)) << i;
      ++checked;
    }
    EXPECT_GT(checked, 199000u);
    EXPECT_EQ(index(0.), 0u);
  }
}

TEST(Tiles, TreeAndStreamingSamplerAgreeBitForBit)
{
  Sampler s(unit_square, [](const Point& p) { return 1. + 3. * p.x() * p.y(); },
            CGAL::parameters::number_of_output_points(20000));
  std::vector<std::pair<double, double>> a, b;
  s.samples(boost::make_function_output_iterator([&](const Sampler::Sample& q) {
    a.emplace_back(q.point.x(), q.point.y());
  }));
  s.tile_tree().for_each_sample([&](CGAL::Penrose_tile_tree::Index, const CGAL::internal::Penrose::Placed_sample& q) {
    b.emplace_back(q.x, q.y);
  });
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  ASSERT_EQ(a.size(), b.size());
  EXPECT_TRUE(a == b);
}

TEST(Density, ConstantCountMatchesTheIntegral)
{
  for(double n : {1e4, 3e4, 1e5, 3e5}) {
    const double count = double(constant_sample(n).size());
    EXPECT_NEAR(count / n, 1., 0.01) << "target " << n;
  }
  // a density given in points per unit area, on a region that is not a square
  const Epick::Iso_rectangle_2 r(-2, 1, 3, 3);
  std::vector<Point> p;
  Sampler(r, [](const Point&) { return 4000.; })(std::back_inserter(p));
  EXPECT_NEAR(double(p.size()) / 40000., 1., 0.01);
}

TEST(Density, CountIsLinearInTheDensity)
{
  // least squares over a decade of densities
  std::vector<double> x, y;
  for(int k = 0; k <= 10; ++k) {
    const double d = 2e4 * std::pow(10., k / 10.);
    std::vector<Point> p;
    Sampler(unit_square, [d](const Point&) { return d; })(std::back_inserter(p));
    x.push_back(d); y.push_back(double(p.size()));
  }
  const double n = double(x.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0, syy = 0;
  for(std::size_t i = 0; i < x.size(); ++i) {
    sx += x[i]; sy += y[i]; sxx += x[i] * x[i]; sxy += x[i] * y[i]; syy += y[i] * y[i];
  }
  const double r = (n * sxy - sx * sy) / std::sqrt((n * sxx - sx * sx) * (n * syy - sy * sy));
  EXPECT_GE(r * r, 0.9999);
}

TEST(Density, RampCellCountsFollowTheIntegral)
{
  std::vector<Point> p;
  Sampler s(unit_square, [](const Point& q) { return q.x(); },
            CGAL::parameters::number_of_output_points(65536));
  s(std::back_inserter(p));
  const int g = 16;
  std::vector<double> count(g * g, 0.);
  for(const Point& q : p) {
    const int i = std::min(g - 1, int(q.x() * g)), j = std::min(g - 1, int(q.y() * g));
    count[j * g + i] += 1.;
  }
  // integral of scale * x over cell column i: scale * (x1^2 - x0^2) / 2 / g
  double err = 0., norm = 0.;
  for(int j = 0; j < g; ++j)
    for(int i = 0; i < g; ++i) {
      const double x0 = double(i) / g, x1 = double(i + 1) / g;
      const double e = s.density_scale() * (x1 * x1 - x0 * x0) / 2. / g;
      err += (count[j * g + i] - e) * (count[j * g + i] - e);
      norm += e * e;
    }
  EXPECT_LE(std::sqrt(err / norm), 0.03);
}

TEST(BlueNoise, SpacingFloorsOverOneLevel)
{
  for(int k = 0; k < 7; ++k) {
    const std::vector<Point> p = constant_sample(16384 * std::pow(phi2, (k + 0.5) / 7.));
    const Q::Spacing s = Q::spacing(p, Q::Rectangle{0, 0, 1, 1});
    EXPECT_GE(s.delta_min, 0.60) << "density " << k;
    EXPECT_GE(s.delta_avg, 0.84) << "density " << k;
  }
}

TEST(BlueNoise, CoverageHasNoHoles)
{
  for(double n : {16384., 40000.}) {
    const std::vector<Point> p = constant_sample(n);
    EXPECT_LE(Q::coverage_radius(p, Q::Rectangle{0, 0, 1, 1}), 2.) << n << " points";
  }
  // the corners of a wide region too
  std::vector<Point> p;
  const Epick::Iso_rectangle_2 wide(0, 0, 4, 1);
  Sampler(wide, [](const Point&) { return 1.; }, CGAL::parameters::number_of_output_points(20000))(std::back_inserter(p));
  EXPECT_LE(Q::coverage_radius(p, Q::Rectangle{0, 0, 4, 1}), 2.);
}

TEST(Sampler, IsDeterministic)
{
  auto density = [](const Point& q) { return 1. + std::sin(7 * q.x()) * std::sin(5 * q.y()); };
  std::vector<Point> a, b;
  Sampler(unit_square, density, CGAL::parameters::number_of_output_points(30000))(std::back_inserter(a));
  Sampler(unit_square, density, CGAL::parameters::number_of_output_points(30000))(std::back_inserter(b));
  ASSERT_EQ(a.size(), b.size());
  for(std::size_t i = 0; i < a.size(); ++i) {
    ASSERT_EQ(a[i].x(), b[i].x());
    ASSERT_EQ(a[i].y(), b[i].y());
  }
}

namespace {
template <class F>
std::string message_of_invalid_argument(F f)
{
  try { f(); } catch(const std::invalid_argument& e) { return e.what(); }
  return "no std::invalid_argument thrown";
}
} // namespace

TEST(Sampler, RejectsBadDensities)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for(double bad : {-1., nan, inf}) {
    const std::string m = message_of_invalid_argument([&] {
      Sampler s(unit_square, [bad](const Point& q) { return q.x() > 0.5 && q.y() > 0.25 ? bad : 100.; });
      std::vector<Point> p;
      s(std::back_inserter(p));
    });
    EXPECT_NE(m.find("density at ("), std::string::npos) << m;
    EXPECT_NE(m.find(bad == -1. ? "-1" : (bad == inf ? "inf" : "nan")), std::string::npos) << m;
  }
}

TEST(Sampler, RejectsBadRegionsAndParameters)
{
  auto one = [](const Point&) { return 1.; };
  EXPECT_THROW(Sampler(Epick::Iso_rectangle_2(0, 0, 0, 1), one), std::invalid_argument);
  EXPECT_THROW(Sampler(Epick::Iso_rectangle_2(0, 0, 1, 0), one), std::invalid_argument);
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(Sampler(Epick::Iso_rectangle_2(Point(0, 0), Point(inf, 1)), one), std::invalid_argument);
  EXPECT_THROW(Sampler(unit_square, [](const Point&) { return 0.; }, CGAL::parameters::number_of_output_points(100)),
               std::invalid_argument);
  EXPECT_THROW(Sampler(unit_square, one, CGAL::parameters::density_control_factor(-1.)), std::invalid_argument);
  // scales out of the doubles' range (the first gave NaN points expected and
  // a meaningless error from std::vector, the second infinitely many points)
  EXPECT_THROW(Sampler(unit_square, [](const Point&) { return 1.7e308; }, CGAL::parameters::number_of_output_points(100)),
               std::invalid_argument);
  EXPECT_THROW(Sampler(unit_square, [](const Point&) { return 1e-310; }, CGAL::parameters::number_of_output_points(100)),
               std::invalid_argument);
  // so many points that they would exhaust memory: refused before anything is allocated
  EXPECT_THROW(Sampler(unit_square, [](const Point&) { return 1e300; }), std::length_error);
}

TEST(Sampler, RefusesDensitiesBeyondItsLevelsAsDocumented)
{
  // the documented limit, about 4 x 10^11 / L^2 points per unit area (L the
  // region's longer side), whatever the aspect ratio: a half disk on the
  // region's border of density just under it is sampled, one just over it
  // refused, naming a point of the region where the density was evaluated
  // (not the tile vertex outside it)
  for(const auto& [length, height] : {std::make_pair(1., 1.), std::make_pair(2., 0.02)}) {
    const double limit = 4e11 / (length * length);
    for(const double factor : {0.95, 1.05}) {
      const double peak = factor * limit, radius = 100 / std::sqrt(peak), cx = 0.3 * length, cy = 0.;
      auto in_disk = [=](double x, double y) { return (x - cx) * (x - cx) + (y - cy) * (y - cy) <= radius * radius; };
      auto density = [=](const Point& p) { return in_disk(p.x(), p.y()) ? peak : 1.; };
      auto bound = [=](const Epick::Iso_rectangle_2& b) {
        return in_disk((std::min)((std::max)(cx, b.xmin()), b.xmax()), (std::min)((std::max)(cy, b.ymin()), b.ymax()))
                 ? peak : 1.;
      };
      const Sampler s(Epick::Iso_rectangle_2(0, 0, length, height), density,
                      CGAL::parameters::density_upper_bound(bound, CGAL::parameters::maximum_number(std::size_t(1e13))));
      std::vector<Point> points;
      const std::string m = message_of_invalid_argument([&] { s(std::back_inserter(points)); });
      const std::string what = std::to_string(length) + " x " + std::to_string(height) + ", " + std::to_string(factor);
      if(factor < 1) {
        EXPECT_EQ(m, "no std::invalid_argument thrown") << what;
        const double in_disk_points = peak * 3.14159265358979 * radius * radius / 2;  // 15,708; the rest 1 per unit area
        EXPECT_NEAR(double(points.size()), in_disk_points, 0.03 * in_disk_points) << what;
        continue;
      }
      EXPECT_NE(m.find("levels of the tile tree"), std::string::npos) << what << ": " << m;
      double x = -1, y = -1;
      ASSERT_EQ(std::sscanf(m.c_str(), "Penrose_importance_sampler: the density at (%lf, %lf)", &x, &y), 2) << m;
      EXPECT_TRUE(x >= 0 && x <= length && y >= 0 && y <= height) << what << ": " << m;
    }
  }
}

TEST(Sampler, RefusesTilesFinerThanItsCoordinatesResolve)
{
  auto one = [](const Point&) { return 1.; };
  auto far_square = [](double corner) { return Epick::Iso_rectangle_2(corner, corner, corner + 1, corner + 1); };
  auto sample = [&](double corner, std::size_t n) {
    std::vector<Point> p;
    Sampler(far_square(corner), one, CGAL::parameters::number_of_output_points(n))(std::back_inserter(p));
    return p;
  };
  // doubles are 0.125 apart at 10^15: not even the first tiles can be placed
  EXPECT_THROW(Sampler(far_square(1e15), one), std::range_error);
  // 0.0001 apart at 10^12: 5000 points (0.014 apart) need tiles of 0.006, too fine
  try {
    sample(1e12, 5000);
    ADD_FAILURE() << "5000 points at 10^12 were not refused";
  } catch(const std::range_error& e) {
    EXPECT_NE(std::string(e.what()).find("move the region nearer to the origin"), std::string::npos) << e.what();
  }
  // at 10^11, where doubles are eight times closer, they are resolved, all distinct
  std::vector<Point> p = sample(1e11, 5000);
  EXPECT_GT(p.size(), 4900u);
  std::sort(p.begin(), p.end());
  EXPECT_TRUE(std::adjacent_find(p.begin(), p.end()) == p.end());
}

TEST(Sampler, MaximumNumberGuardsMemory)
{
  auto one = [](const Point&) { return 1.; };
  // 10^12 points would exhaust memory: refused before any allocation
  EXPECT_THROW(Sampler(unit_square, one, CGAL::parameters::number_of_output_points(std::size_t(1e12))), std::length_error);
  try {
    Sampler(unit_square, one, CGAL::parameters::number_of_output_points(std::size_t(1e12)));
  } catch(const std::length_error& e) {
    EXPECT_NE(std::string(e.what()).find("about 1e+12 points expected, more than maximum_number (100000000)"),
              std::string::npos) << e.what();
  }
  EXPECT_THROW(Sampler(unit_square, one, CGAL::parameters::number_of_output_points(5000).maximum_number(4000)), std::length_error);
  EXPECT_NO_THROW(Sampler(unit_square, one, CGAL::parameters::number_of_output_points(5000).maximum_number(6000)));
}

TEST(Sampler, ConservativeBoundFindsThinFeatures)
{
  // a thin bright line that the probes of most tiles miss
  const std::size_t w = 512, h = 512;
  std::vector<double> v(w * h, 1.);
  for(std::size_t j = 0; j < h; ++j) v[j * w + 301] = 400.;
  const CGAL::Raster_density_2<Epick> d(w, h, v, unit_square);
  const double line = 400. / 512.;  // integral of the line's excess, over the unscaled unit
  auto count_near_line = [&](bool bound) {
    std::vector<Point> p;
    const auto np = CGAL::parameters::density_upper_bound(d.upper_bound_function()).density_control_factor(20000.);
    if(bound) Sampler(unit_square, d, np)(std::back_inserter(p));
    else Sampler(unit_square, d, CGAL::parameters::density_control_factor(20000.))(std::back_inserter(p));
    std::size_t c = 0;
    for(const Point& q : p) if(std::abs(q.x() - 301.5 / 512.) < 1.5 / 512.) ++c;
    return double(c);
  };
  // expected in the band: the integral of the interpolated density over it
  double expected = 0.;
  for(int k = 0; k < 3000; ++k) {
    const double x = 301.5 / 512. + (k + 0.5) / 3000. * 3. / 512. - 1.5 / 512.;
    expected += d(Point(x, 0.5)) * 3. / 512. / 3000.;
  }
  expected *= 20000.;
  const double with_bound = count_near_line(true), with_probes = count_near_line(false);
  EXPECT_NEAR(with_bound / expected, 1., 0.15);
  EXPECT_LT(with_probes, with_bound);
  (void)line;
}

// Bilinear interpolation between pixel centres, written out from its
// definition, over a raster of random values on a region that is not the
// unit square, with sizes that are not powers of two.
TEST(Raster, InterpolatesBetweenPixelCentres)
{
  const std::size_t w = 37, h = 23;
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> unit(0., 1.);
  std::vector<double> v(w * h);
  for(double& x : v) x = 10. * unit(random);
  const Epick::Iso_rectangle_2 region(-2., 1., 3., 2.5);
  const CGAL::Raster_density_2<Epick> d(w, h, v, region);
  auto pixel = [&](long i, long j) {
    i = std::clamp(i, 0L, long(w) - 1); j = std::clamp(j, 0L, long(h) - 1);
    return v[std::size_t(j) * w + std::size_t(i)];
  };
  auto reference = [&](double x, double y) {
    const double u = (x + 2.) / 5. * double(w) - 0.5, t = (2.5 - y) / 1.5 * double(h) - 0.5;
    const double i = std::floor(u), j = std::floor(t), a = u - i, b = t - j;
    return (1 - a) * (1 - b) * pixel(long(i), long(j)) + a * (1 - b) * pixel(long(i) + 1, long(j))
         + (1 - a) * b * pixel(long(i), long(j) + 1) + a * b * pixel(long(i) + 1, long(j) + 1);
  };
  for(int k = 0; k < 20000; ++k) {
    // the border and the corners too, where the interpolation is clamped
    const double x = k < 4 ? (k % 2 ? 3. : -2.) : -2. + 5. * unit(random);
    const double y = k < 4 ? (k / 2 ? 2.5 : 1.) : 1. + 1.5 * unit(random);
    ASSERT_NEAR(d(Point(x, y)), reference(x, y), 1e-9) << x << " " << y;
  }
  // at a pixel centre, the pixel
  EXPECT_NEAR(d(Point(-2. + 5. * 10.5 / double(w), 2.5 - 1.5 * 4.5 / double(h))), pixel(10, 4), 1e-9);
  // far outside, the value at the nearest point of the border
  EXPECT_NEAR(d(Point(1e300, 1.7)), reference(3., 1.7), 1e-9);
  EXPECT_NEAR(d(Point(-1e300, -1e300)), pixel(0, long(h) - 1), 1e-9);
  EXPECT_NEAR(d.upper_bound(Epick::Iso_rectangle_2(-1e300, -1e300, 1e300, 1e300)), *std::max_element(v.begin(), v.end()), 1e-9);
}

TEST(Raster, RejectsBadRasters)
{
  typedef CGAL::Raster_density_2<Epick> Raster;
  const std::vector<double> six(6, 1.);
  EXPECT_NO_THROW(Raster(3, 2, six, unit_square));
  EXPECT_THROW(Raster(0, 2, {}, unit_square), std::invalid_argument);
  EXPECT_THROW(Raster(2, 2, six, unit_square), std::invalid_argument);
  // sizes whose product wraps around to the number of values
  const std::size_t half = std::size_t(1) << (std::numeric_limits<std::size_t>::digits / 2);
  EXPECT_THROW(Raster(half, half * 6, six, unit_square), std::invalid_argument);
  for(double bad : {-1., std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    std::vector<double> v = six;
    v[4] = bad;
    EXPECT_THROW(Raster(3, 2, v, unit_square), std::invalid_argument) << bad;
  }
  EXPECT_THROW(Raster(3, 2, six, Epick::Iso_rectangle_2(0, 0, 1, 0)), std::invalid_argument);
  EXPECT_THROW(Raster(3, 2, six, Epick::Iso_rectangle_2(0, 0, std::numeric_limits<double>::infinity(), 1)),
               std::invalid_argument);
}

// The max pyramid's bound, over boxes from a fraction of a pixel to more
// than the region, against the brute-force maximum of the pixels whose
// interpolation reaches into the box and against the density inside it.
TEST(Raster, UpperBoundCoversEveryBox)
{
  for(const auto& [w, h] : {std::pair<std::size_t, std::size_t>(37, 23), {1, 1}, {64, 64}, {300, 7}}) {
    std::mt19937_64 random(w * 1000 + h);
    std::uniform_real_distribution<double> unit(0., 1.);
    std::vector<double> v(w * h);
    for(double& x : v) x = unit(random) < 0.02 ? 100. * unit(random) : unit(random);
    const CGAL::Raster_density_2<Epick> d(w, h, v, unit_square);
    for(int k = 0; k < 3000; ++k) {
      const double size = std::pow(10., -4. + 4.5 * unit(random));
      const double x0 = -0.1 + 1.2 * unit(random), y0 = -0.1 + 1.2 * unit(random);
      const double x1 = x0 + size * unit(random), y1 = y0 + size * unit(random);
      const double bound = d.upper_bound(Epick::Iso_rectangle_2(x0, y0, x1, y1));
      // pixel (i, j) matters where its centre is less than a pixel from the box
      double pixels = 0.;
      for(std::size_t j = 0; j < h; ++j)
        for(std::size_t i = 0; i < w; ++i) {
          const double cx = (double(i) + 0.5) / double(w), cy = 1. - (double(j) + 0.5) / double(h);
          if(cx > std::max(x0, 0.) - 1. / double(w) && cx < std::min(x1, 1.) + 1. / double(w) &&
             cy > std::max(y0, 0.) - 1. / double(h) && cy < std::min(y1, 1.) + 1. / double(h))
            pixels = std::max(pixels, v[j * w + i]);
        }
      ASSERT_GE(bound, pixels) << w << " x " << h << ": box " << x0 << " " << y0 << " " << x1 << " " << y1;
      for(int s = 0; s < 4; ++s) {
        const double x = std::clamp(x0 + (x1 - x0) * unit(random), 0., 1.);
        const double y = std::clamp(y0 + (y1 - y0) * unit(random), 0., 1.);
        ASSERT_GE(bound, d(Point(x, y)));
      }
      ASSERT_LE(bound, *std::max_element(v.begin(), v.end()) * (1. + 1e-13));
    }
  }
}

TEST(Sampler, ThresholdPruningDropsNoActiveSample)
{
  // Any valid bound gives the exact set of active samples. The loosest one
  // (the global maximum) subdivides every tile whose subtree has a threshold
  // under it; a tight one prunes far more, and must lose nothing.
  auto density = [](const Point& p) {
    const double dx = p.x() - 0.3, dy = p.y() - 0.6;
    return 1.2 + std::sin(37. * p.x()) * std::cos(29. * p.y()) + 3. * std::exp(-(dx * dx + dy * dy) / 0.004);
  };
  const double global_max = 5.2, lipschitz = 37. + 29. + 3. * 2. / std::sqrt(2. * 0.004) * std::exp(-0.5);
  auto tight = [&](const Epick::Iso_rectangle_2& b) {
    const Point c((b.xmin() + b.xmax()) / 2., (b.ymin() + b.ymax()) / 2.);
    const double reach = std::hypot(b.xmax() - b.xmin(), b.ymax() - b.ymin()) / 2.;
    return std::min(global_max, density(c) + lipschitz * reach);
  };
  auto loose = [&](const Epick::Iso_rectangle_2&) { return global_max; };
  for(std::size_t n : {300, 3000, 20000}) {
    const Sampler with_tight(unit_square, density,
                             CGAL::parameters::density_upper_bound(tight).number_of_output_points(n));
    const Sampler with_loose(unit_square, density,
                             CGAL::parameters::density_upper_bound(loose).number_of_output_points(n));
    std::vector<Point> a, b;
    with_tight(std::back_inserter(a));
    with_loose(std::back_inserter(b));
    EXPECT_EQ(a, b) << n << " points";
    EXPECT_LT(with_tight.tile_tree().tiles().size(), with_loose.tile_tree().tiles().size());
  }
}

TEST(Sampler, RegionPruningDropsNoSample)
{
  // A tile beyond the region's margin is not subdivided. No sample that its
  // subtree could hold may land in the region: born anywhere in the tile at
  // the next level or deeper, with the F-code of a random path down the
  // rules, any direction, and an importance that keeps its leaf at its birth
  // level (the largest moves), moved by the real correction table. The tiles
  // tried lie beside the region at 0.95 to 1.25 of their size, and the
  // samples near their corner nearest to it, where a margin too thin would
  // show: a margin 5% thinner lets 4 of the 1.9 million samples in.
  using namespace CGAL::internal::Penrose;
  const Sampler sampler(unit_square, [](const Point&) { return 1.; }, CGAL::parameters::number_of_output_points(1000));
  const Sampling_context& c = Sampler_access::context(sampler);
  ASSERT_NE(c.correction_table(), nullptr);
  std::mt19937_64 rng(20261122);
  std::uniform_real_distribution<double> u(0., 1.);
  const auto& li = fibonacci().level_importance;
  auto sample_code = [&rng](int birth_level) {
    for(;;) {
      Tile_type type = FAT_F;  // the root's
      std::uint64_t code = 0;
      for(int l = 1; l < birth_level; ++l) {
        const Child_rule& child = rule(type).children[rng() % rule(type).number_of_children];
        code = code * 4 + child.code_pair;
        type = child.type;
      }
      const Subdivision_rule& r = rule(type);
      for(int n = 0; n < r.number_of_new_vertices; ++n)
        if(r.new_vertices[n].is_sample) return code * 4 + r.sample_code_pair;
    }
  };
  std::size_t pruned = 0, samples = 0, inside = 0;
  for(int trial = 0; trial < 20000; ++trial) {
    const int level = 1 + trial % 14;
    const double s = c.scale(level), gap = s * (0.95 + 0.3 * u(rng)), along = u(rng);
    // left of the region, then mirrored or turned onto the other three sides
    double x[3] = {-gap, -gap - 0.8 * s, -gap - 0.4 * s}, y[3] = {along, along + 0.3 * s, along - 0.6 * s};
    for(int i = 0; i < 3; ++i) {
      if(trial % 2 == 1) x[i] = 1. - x[i];
      if(trial % 4 >= 2) std::swap(x[i], y[i]);
    }
    const double reach = double(fibonacci().fib[2 * level + 2]);
    const double importance[3] = {reach, reach, reach};  // the importance alone would subdivide it
    if(c.should_refine(level, 0, x, y, importance)) continue;
    ++pruned;
    for(int k = 0; k < 100; ++k) {
      const double a = 0.05 * u(rng), b = 0.05 * u(rng);
      const double px = x[0] + a * (x[1] - x[0]) + b * (x[2] - x[0]), py = y[0] + a * (y[1] - y[0]) + b * (y[2] - y[0]);
      const int birth_level = (std::min)(max_level, level + 1 + int(rng() % 3));
      const double lo = li[birth_level], hi = li[birth_level + 1];
      const Sample_birth birth = {sample_code(birth_level), 0, std::uint8_t(birth_level), std::uint8_t(rng() % 20)};
      Placed_sample placed;
      ASSERT_TRUE(c.activate(px, py, lo + (hi - lo) * 0.999 * u(rng), birth, placed));
      ASSERT_EQ(placed.leaf_level, birth_level);
      ++samples;
      inside += c.contains(placed.x, placed.y);
    }
  }
  EXPECT_GT(pruned, 5000u);
  EXPECT_EQ(inside, 0u) << "of " << samples << " samples of pruned tiles";
}

namespace {
// The smallest model of PenroseImportanceSamplerTraits_2.
struct Minimal_traits
{
  typedef double FT;
  struct Point_2 { double px, py; };
  struct Iso_rectangle_2 { Point_2 lo, hi; };
  struct Construct_point_2 { Point_2 operator()(double x, double y) const { return {x, y}; } };
  struct Compute_x_2 { double operator()(const Point_2& p) const { return p.px; } };
  struct Compute_y_2 { double operator()(const Point_2& p) const { return p.py; } };
  struct Construct_vertex_2 {
    Point_2 operator()(const Iso_rectangle_2& r, int i) const {
      return i == 0 ? r.lo : i == 2 ? r.hi : i == 1 ? Point_2{r.hi.px, r.lo.py} : Point_2{r.lo.px, r.hi.py};
    }
  };
  struct Construct_iso_rectangle_2 { Iso_rectangle_2 operator()(const Point_2& a, const Point_2& b) const { return {a, b}; } };
  Construct_point_2 construct_point_2_object() const { return {}; }
  Compute_x_2 compute_x_2_object() const { return {}; }
  Compute_y_2 compute_y_2_object() const { return {}; }
  Construct_vertex_2 construct_vertex_2_object() const { return {}; }
  Construct_iso_rectangle_2 construct_iso_rectangle_2_object() const { return {}; }
};

template <class K>
std::vector<std::pair<double, double>> sample_with(const typename K::Iso_rectangle_2& r)
{
  typedef typename K::Point_2 P;
  CGAL::Penrose_importance_sampler<K> s(r, [](const P& p) {
    const double x = CGAL::to_double(K().compute_x_2_object()(p));
    return 1000. + 3000. * x;
  });
  std::vector<std::pair<double, double>> out;
  std::vector<P> pts;
  s(std::back_inserter(pts));
  for(const P& p : pts)
    out.emplace_back(CGAL::to_double(K().compute_x_2_object()(p)), CGAL::to_double(K().compute_y_2_object()(p)));
  return out;
}
} // namespace

TEST(Traits, EveryKernelGivesTheSamePoints)
{
  const auto epick = sample_with<Epick>(Epick::Iso_rectangle_2(0, 0, 2, 1));
  typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;
  typedef CGAL::Simple_cartesian<double> Sc;
  const auto epeck = sample_with<Epeck>(Epeck::Iso_rectangle_2(0, 0, 2, 1));
  const auto sc = sample_with<Sc>(Sc::Iso_rectangle_2(0, 0, 2, 1));
  const auto minimal = sample_with<Minimal_traits>(Minimal_traits::Iso_rectangle_2{{0, 0}, {2, 1}});
  EXPECT_GT(epick.size(), 3000u);
  EXPECT_TRUE(epick == epeck);
  EXPECT_TRUE(epick == sc);
  EXPECT_TRUE(epick == minimal);
}

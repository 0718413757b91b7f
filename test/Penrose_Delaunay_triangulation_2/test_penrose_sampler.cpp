// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Properties of Penrose_importance_sampler and Raster_density_2, each
// checked against an independent expectation: point counts against the
// integral of the density, spacing against the packing distance, coverage,
// determinism and input checks; and test_sampler<K>(), what the sampler
// promises for any kernel K, run over Epick, Epeck and Simple_cartesian<Gmpq>.

#include <CGAL/Penrose_importance_sampler.h>
#include <CGAL/Raster_density_2.h>
#include "point_set_quality.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Simple_cartesian.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <random>
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

} // namespace

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

// A bad density_upper_bound is named as the bound, over its box, not taken
// for the density at the box's centre.
TEST(Sampler, RejectsBadDensityUpperBounds)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for(double bad : {-1., nan}) {
    const std::string m = message_of_invalid_argument([&] {
      Sampler s(unit_square, [](const Point&) { return 1.; },
                CGAL::parameters::density_upper_bound([bad](const Epick::Iso_rectangle_2&) { return bad; })
                  .number_of_output_points(1000));
      std::vector<Point> p;
      s(std::back_inserter(p));
    });
    EXPECT_EQ(m.rfind("Penrose_importance_sampler: density_upper_bound over [", 0), 0u) << m;
    EXPECT_NE(m.find(std::string("] is ") + (bad == -1. ? "-1" : "nan")), std::string::npos) << m;
    EXPECT_EQ(m.find("density at"), std::string::npos) << m;
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

TEST(Sampler, RefinementCapRefusesALooseBound)
{
  // a bound 10^6 times the density refined tiles that hold no point for 95 s
  // before its 1,004 points: the cap on the tiles refined per expected point
  // refuses it as the tree grows. A bound 64 times too high is within the
  // cap, and gives the points of a tight one.
  auto one = [](const Point&) { return 1.; };
  auto bound = [](double k) { return [k](const Epick::Iso_rectangle_2&) { return k; }; };
  auto sampled = [&](double k) {
    std::vector<Point> points;
    Sampler(unit_square, one, CGAL::parameters::density_upper_bound(bound(k)).number_of_output_points(1004))
      (std::back_inserter(points));
    return points;
  };
  try {
    sampled(1e6);
    ADD_FAILURE() << "a bound 10^6 times the density was not refused";
  } catch(const std::length_error& e) {
    EXPECT_NE(std::string(e.what()).find("tiles refined for about 1e+03 points expected (at most 256 a point"),
              std::string::npos) << e.what();
  }
  const std::vector<Point> tight = sampled(1.);
  EXPECT_GT(tight.size(), 900u);
  EXPECT_EQ(sampled(64.), tight);
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

TEST(Raster, UpperBoundFunctionOutlivesTheDensity)
{
  // the function holds its own copy, which shares the pyramid: it gives the
  // same bounds once the density and its copies are destroyed
  std::vector<double> v(40 * 30);
  for(std::size_t k = 0; k < v.size(); ++k) v[k] = double((k * 7919) % 101);
  std::function<double(const Epick::Iso_rectangle_2&)> bound;
  std::vector<double> expected;
  const std::vector<Epick::Iso_rectangle_2> boxes = {Epick::Iso_rectangle_2(0, 0, 1, 1), Epick::Iso_rectangle_2(0.1, 0.2, 0.15, 0.3),
                                                     Epick::Iso_rectangle_2(0.7, 0.7, 0.71, 0.72)};
  {
    const CGAL::Raster_density_2<Epick> d(40, 30, v, unit_square);
    const CGAL::Raster_density_2<Epick> copy = d;
    bound = copy.upper_bound_function();
    for(const auto& b : boxes) expected.push_back(d.upper_bound(b));
  }
  for(std::size_t k = 0; k < boxes.size(); ++k) EXPECT_EQ(bound(boxes[k]), expected[k]);
  EXPECT_EQ(expected[0], 100. * (1. + 1e-14));
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

namespace {

// Everything the sampler promises, for the kernel K: `n` points of a ramp
// over a region that is not the unit square, the same as with Epick.
template <class K>
void test_sampler(std::size_t n, const std::string& name)
{
  typedef CGAL::Penrose_importance_sampler<K> S;
  typedef typename K::Point_2 P;
  typedef typename K::Iso_rectangle_2 R;
  const K traits;
  auto x_of = [&](const P& p) { return CGAL::to_double(traits.compute_x_2_object()(p)); };
  auto y_of = [&](const P& p) { return CGAL::to_double(traits.compute_y_2_object()(p)); };
  auto points_of = [](const S& s) {
    std::vector<P> p;
    s(std::back_inserter(p));
    return p;
  };
  auto xy_of = [&](const std::vector<P>& p) {
    std::vector<std::pair<double, double>> xy;
    for(const P& q : p) xy.emplace_back(x_of(q), y_of(q));
    return xy;
  };
  const R region(P(-1, 0.5), P(1, 1.5));
  auto ramp = [&](const P& p) { return 1. + 4. * (x_of(p) + 1.); };
  const S s(region, ramp, CGAL::parameters::number_of_output_points(n).geom_traits(traits));

  // the count and the accessors
  const std::vector<P> points = points_of(s);
  EXPECT_NEAR(double(points.size()) / double(n), 1., 0.05) << name;
  EXPECT_NEAR(s.expected_number_of_points(), double(n), 1e-6 * double(n)) << name;
  EXPECT_NEAR(s.density_scale() * s.density_integral(), s.expected_number_of_points(), 1e-9 * double(n)) << name;
  EXPECT_NEAR(s.density_integral(), 2. * (1. + 4.), 0.01) << name;  // the ramp's mean is 5 over an area of 2
  EXPECT_TRUE(s.region() == region) << name;
  EXPECT_TRUE(s.uses_correction_vectors()) << name;
  for(const P& p : points)
    ASSERT_TRUE(x_of(p) >= -1 && x_of(p) <= 1 && y_of(p) >= 0.5 && y_of(p) <= 1.5) << name;

  // determinism, and the same points as with Epick
  EXPECT_TRUE(xy_of(points_of(S(region, ramp, CGAL::parameters::number_of_output_points(n)))) == xy_of(points))
    << name;
  const CGAL::Penrose_importance_sampler<Epick> with_epick(
    Epick::Iso_rectangle_2(-1, 0.5, 1, 1.5), [](const Point& p) { return 1. + 4. * (p.x() + 1.); },
    CGAL::parameters::number_of_output_points(n));
  std::vector<Point> epick_points;
  with_epick(std::back_inserter(epick_points));
  std::vector<std::pair<double, double>> epick_xy;
  for(const Point& p : epick_points) epick_xy.emplace_back(p.x(), p.y());
  EXPECT_TRUE(epick_xy == xy_of(points)) << name;

  // samples(): the same points, in the same order, with their tiles' data
  std::vector<typename S::Sample> samples;
  s.samples(std::back_inserter(samples));
  ASSERT_EQ(samples.size(), points.size()) << name;
  for(std::size_t i = 0; i < samples.size(); ++i) {
    ASSERT_TRUE(samples[i].point == points[i]) << name << ", sample " << i;
    ASSERT_GT(samples[i].level, 0) << name;
    ASSERT_GT(samples[i].importance, 0.) << name;
    // the correction moves a point by less than its tile, itself under 1 / sqrt(density) in size
    ASSERT_LT(std::hypot(x_of(samples[i].point) - x_of(samples[i].reference_point),
                         y_of(samples[i].point) - y_of(samples[i].reference_point)),
              3. / std::sqrt(s.density_scale() * ramp(samples[i].point))) << name << ", sample " << i;
  }

  // without correction: the tile vertices, about as many
  const S raw(region, ramp, CGAL::parameters::use_correction_vectors(false).number_of_output_points(n));
  EXPECT_FALSE(raw.uses_correction_vectors()) << name;
  const std::vector<P> raw_points = points_of(raw);
  EXPECT_NEAR(double(raw_points.size()) / double(n), 1., 0.05) << name;
  EXPECT_FALSE(xy_of(raw_points) == xy_of(points)) << name;

  // a raster density of K with its bound; any valid bound gives the same points
  std::vector<double> pixels(16 * 8);
  for(std::size_t k = 0; k < pixels.size(); ++k) pixels[k] = 1. + double(k % 16) + 0.5 * double(k / 16);
  const CGAL::Raster_density_2<K> raster(16, 8, pixels, region);
  const auto bounded = points_of(S(region, raster, CGAL::parameters::density_upper_bound(
                                                     raster.upper_bound_function(), CGAL::parameters::number_of_output_points(n))));
  const auto loosely_bounded = points_of(S(region, raster, CGAL::parameters::density_upper_bound(
                                                             [](const R&) { return 20.; },
                                                             CGAL::parameters::number_of_output_points(n))));
  EXPECT_NEAR(double(bounded.size()) / double(n), 1., 0.05) << name;
  EXPECT_TRUE(xy_of(bounded) == xy_of(loosely_bounded)) << name;

  // what it throws
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(points_of(S(region, [&](const P& p) { return x_of(p) > 0.5 ? nan : 1000.; })), std::invalid_argument)
    << name;
  EXPECT_THROW(S(R(P(0, 0), P(0, 1)), ramp), std::invalid_argument) << name;
  EXPECT_THROW(S(region, ramp, CGAL::parameters::density_control_factor(-1.)), std::invalid_argument) << name;
  EXPECT_THROW(S(region, ramp, CGAL::parameters::number_of_output_points(n).maximum_number(n / 2)), std::length_error)
    << name;
}

} // namespace

TEST(Traits, SamplerDriverOverEpick) { test_sampler<Epick>(20000, "Epick"); }

TEST(Traits, SamplerDriverOverEpeck) { test_sampler<CGAL::Exact_predicates_exact_constructions_kernel>(2000, "Epeck"); }

TEST(Traits, SamplerDriverOverGmpq) { test_sampler<CGAL::Simple_cartesian<CGAL::Gmpq>>(1000, "Simple_cartesian<Gmpq>"); }

// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Penrose_Delaunay_triangulation_2 against CGAL's own triangulators on the
// same points: the edge sets must be equal, for many densities, sizes and
// traits classes, and the triangulation must stay valid under edits; and
// test_triangulation<Gt, Tds>(), what the triangulation promises for any
// traits and TDS, run over Epick, Epeck, Simple_cartesian<Gmpq>,
// Projection_traits_xy_3<Epick> and a vertex base with info; and the same
// triangulation, and errors, with Parallel_tag on any number of threads.

#include <CGAL/Penrose_Delaunay_triangulation_2.h>
#include <CGAL/Raster_density_2.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Gmpq.h>
#include <CGAL/Projection_traits_xy_3.h>
#include <CGAL/Random.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Triangulation_hierarchy_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <set>
#include <sstream>
#include <thread>
#include <type_traits>
#include <utility>
#include <vector>

#if defined(CGAL_LINKED_WITH_TBB)
#  include <tbb/global_control.h>
#endif

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef Epick::Point_2 Point;
typedef CGAL::Penrose_importance_sampler<Epick> Sampler;
typedef std::array<double, 4> Edge_key;  // the two endpoints' (x, y), sorted
typedef std::function<double(const Point&)> Density;

template <class Triangulation, class XY>
std::set<Edge_key> edge_set(const Triangulation& t, XY xy)
{
  std::set<Edge_key> edges;
  for(auto e = t.finite_edges_begin(); e != t.finite_edges_end(); ++e) {
    std::pair<double, double> a = xy(e->first->vertex(t.cw(e->second))->point());
    std::pair<double, double> b = xy(e->first->vertex(t.ccw(e->second))->point());
    if(b < a) std::swap(a, b);
    edges.insert({a.first, a.second, b.first, b.second});
  }
  return edges;
}

std::pair<double, double> xy_of(const Point& p) { return {p.x(), p.y()}; }

// The reference: CGAL's range insertion, and the Devillers hierarchy fed one
// point at a time, on the points of the sampler `s` made by `lift` in the
// traits of `pdt`; `sampled`, if given, receives the sampler's points.
template <class Pdt, class S, class Lift, class XY>
void expect_matches_cgal(const Pdt& pdt, const S& s, const Lift& lift, const XY& xy, const std::string& what,
                         std::vector<typename S::Point_2>* sampled = nullptr)
{
  typedef typename Pdt::Geom_traits Gt;
  typedef typename Gt::Point_2 P;
  ASSERT_TRUE(pdt.is_valid()) << what;
  std::vector<typename S::Point_2> planar;
  s(std::back_inserter(planar));
  std::vector<P> points;
  for(const auto& p : planar) points.push_back(lift(CGAL::to_double(p.x()), CGAL::to_double(p.y())));
  if(sampled != nullptr) sampled->swap(planar);
  const CGAL::Delaunay_triangulation_2<Gt> dt(points.begin(), points.end());
  CGAL::Triangulation_hierarchy_2<CGAL::Delaunay_triangulation_2<Gt,
    CGAL::Triangulation_data_structure_2<CGAL::Triangulation_hierarchy_vertex_base_2<
      CGAL::Triangulation_vertex_base_2<Gt>>>>> hierarchy;
  for(const P& p : points) hierarchy.insert(p);
  EXPECT_EQ(pdt.number_of_vertices(), dt.number_of_vertices()) << what;
  EXPECT_EQ(pdt.dimension(), dt.dimension()) << what;
  const std::set<Edge_key> mine = edge_set(pdt, xy);
  EXPECT_TRUE(mine == edge_set(dt, xy)) << what << ": edges differ from Delaunay_triangulation_2";
  EXPECT_TRUE(mine == edge_set(hierarchy, xy)) << what << ": edges differ from Triangulation_hierarchy_2";
}

// The reference for `pdt`, built from `sampler`, with few fallbacks;
// `sampled` receives the sampler's points.
void expect_built_as_cgal(const CGAL::Penrose_Delaunay_triangulation_2<Epick>& pdt, const Sampler& sampler,
                          const std::string& what, std::vector<Point>& sampled)
{
  expect_matches_cgal(pdt, sampler, [](double x, double y) { return Point(x, y); }, xy_of, what, &sampled);
  EXPECT_LE(double(pdt.number_of_fallbacks()), 0.001 * double(sampled.size()) + 0.5) << what;
}

// Returns the number of points and the dimension of the triangulation.
std::pair<std::size_t, int> expect_same_as_cgal(const Sampler& sampler, const std::string& what)
{
  const CGAL::Penrose_Delaunay_triangulation_2<Epick> pdt(sampler);
  std::vector<Point> sampled;
  expect_built_as_cgal(pdt, sampler, what, sampled);
  return {sampled.size(), pdt.dimension()};
}

// Inserts 300 random points of `box` into `pdt`, whose vertices are
// `points`, and removes about one vertex in 40 (300 at most); checks
// validity after each batch and that the edges are then those of CGAL's
// triangulation of what is left, which is returned.
CGAL::Delaunay_triangulation_2<Epick>
expect_delaunay_after_edits(CGAL::Penrose_Delaunay_triangulation_2<Epick>& pdt, std::vector<Point> points,
                            const Epick::Iso_rectangle_2& box, CGAL::Random& r, const std::string& what)
{
  for(int i = 0; i < 300; ++i) {
    const Point p(r.get_double(box.xmin(), box.xmax()), r.get_double(box.ymin(), box.ymax()));
    pdt.insert(p);
    points.push_back(p);
  }
  EXPECT_TRUE(pdt.is_valid()) << what << ": after insertions";
  std::vector<CGAL::Penrose_Delaunay_triangulation_2<Epick>::Vertex_handle> to_remove;
  for(auto v = pdt.finite_vertices_begin(); v != pdt.finite_vertices_end() && to_remove.size() < 300; ++v)
    if(r.get_int(0, 40) == 0) to_remove.push_back(v);
  std::set<std::pair<double, double>> removed;
  for(auto v : to_remove) { removed.insert(xy_of(v->point())); pdt.remove(v); }
  EXPECT_TRUE(pdt.is_valid()) << what << ": after removals";
  std::vector<Point> rest;
  for(const Point& p : points) if(!removed.count(xy_of(p))) rest.push_back(p);
  CGAL::Delaunay_triangulation_2<Epick> dt(rest.begin(), rest.end());
  EXPECT_TRUE(edge_set(pdt, xy_of) == edge_set(dt, xy_of)) << what << ": edges differ after edits";
  return dt;
}

// The built-in densities of penrose_mesh, on the unit square.
std::vector<std::pair<std::string, Density>> builtin_densities()
{
  return {
    {"constant", [](const Point&) { return 1.; }},
    {"ramp", [](const Point& p) { return p.x(); }},
    {"radial", [](const Point& p) {
       const double r2 = (p.x() - .5) * (p.x() - .5) + (p.y() - .5) * (p.y() - .5);
       return std::exp(-r2 / (2 * 0.04)) + 0.05; }}};
}

const Epick::Iso_rectangle_2 unit_square(0, 0, 1, 1);

// A random smooth density: a few Gaussian bumps over a floor.
Density random_density(int seed)
{
  CGAL::Random r(seed);
  std::vector<std::array<double, 4>> bumps;
  const int n = 1 + r.get_int(0, 6);
  for(int i = 0; i < n; ++i)
    bumps.push_back({r.get_double(0, 1), r.get_double(0, 1), r.get_double(0.02, 0.3), r.get_double(0.5, 20)});
  const double floor = r.get_double(0, 0.3);
  return [bumps, floor](const Point& p) {
    double d = floor;
    for(const auto& b : bumps) {
      const double dx = p.x() - b[0], dy = p.y() - b[1];
      d += b[3] * std::exp(-(dx * dx + dy * dy) / (2 * b[2] * b[2]));
    }
    return d;
  };
}

} // namespace

TEST(Triangulation, BuiltInDensitiesMatchCgal)
{
  for(const auto& d : builtin_densities())
    for(std::size_t n : {std::size_t(10), std::size_t(300), std::size_t(5000), std::size_t(100000)})
      expect_same_as_cgal(Sampler(unit_square, d.second, CGAL::parameters::number_of_output_points(n)),
                          d.first + " " + std::to_string(n));
}

TEST(Triangulation, LargeEnoughToSplitEveryWalkMatchesCgal)
{
  // at this size every walk of the construction is split in halves
  expect_same_as_cgal(Sampler(unit_square, [](const Point& p) { return 0.2 + p.x() * p.x() + p.y(); },
                              CGAL::parameters::number_of_output_points(400000)), "400000 points");
}

#if defined(CGAL_LINKED_WITH_TBB)
typedef CGAL::Penrose_Delaunay_triangulation_2<Epick, CGAL::Default, CGAL::Parallel_tag> Parallel_pdt;

// Parallel_tag on 1, 2, 3 and 8 threads gives the triangulation of
// `sequential`, built from `s` with Sequential_tag: the same vertices, edges
// and statistics (the base mesh is split the same way); the callback is only
// called from the calling thread.
void expect_every_thread_count_as_sequential(const Sampler& s, const CGAL::Penrose_Delaunay_triangulation_2<Epick>& sequential,
                                             const std::string& what)
{
  const std::set<Edge_key> edges = edge_set(sequential, xy_of);
  for(std::size_t threads : {1, 2, 3, 8}) {
    const std::string where = what + ", Parallel_tag on " + std::to_string(threads) + " threads";
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    const std::thread::id caller = std::this_thread::get_id();
    bool called_elsewhere = false;
    const std::function<bool(double)> callback = [&](double) {
      called_elsewhere |= std::this_thread::get_id() != caller;
      return true;
    };
    Parallel_pdt parallel;
    ASSERT_TRUE(parallel.build(s, [](double x, double y) { return Point(x, y); },
                               [](Parallel_pdt::Vertex_handle, const Sampler::Sample&) {},
                               CGAL::parameters::callback(callback))) << where;
    EXPECT_FALSE(called_elsewhere) << where;
    EXPECT_TRUE(parallel.is_valid()) << where;
    EXPECT_EQ(parallel.number_of_vertices(), sequential.number_of_vertices()) << where;
    EXPECT_TRUE(edge_set(parallel, xy_of) == edges) << where;
    const auto& a = parallel.construction_statistics();
    const auto& b = sequential.construction_statistics();
    EXPECT_EQ(a.flips, b.flips) << where;
    EXPECT_EQ(a.base_vertices, b.base_vertices) << where;
    EXPECT_EQ(a.removed_vertices, b.removed_vertices) << where;
    EXPECT_EQ(a.repaired_vertices, b.repaired_vertices) << where;
    EXPECT_EQ(a.fallbacks, b.fallbacks) << where;
  }
}

TEST(Triangulation, EveryTagAndThreadCountGivesCgalsTriangulation)
{
  for(const auto& d : builtin_densities()) {
    if(d.first == "radial") continue;
    const Sampler s(unit_square, d.second, CGAL::parameters::number_of_output_points(150000));
    const CGAL::Penrose_Delaunay_triangulation_2<Epick> sequential(s);
    std::vector<Point> points;
    expect_built_as_cgal(sequential, s, d.first + " Sequential_tag", points);
    expect_every_thread_count_as_sequential(s, sequential, d.first);
  }
}

TEST(Triangulation, EveryThreadCountOnARasterGivesCgalsTriangulation)
{
  // a raster with steps between its pixels and empty pixels, as an image
  // has, read from TBB's threads through its max pyramid
  const std::size_t w = 96, h = 64;
  std::vector<double> values(w * h);
  CGAL::Random r(7);
  for(double& v : values) v = r.get_int(0, 8) == 0 ? 0. : r.get_double(0.05, 1.);
  const Epick::Iso_rectangle_2 region(0, 0, 1.5, 1);
  const CGAL::Raster_density_2<Epick> raster(w, h, values, region);
  const Sampler s(region, raster, CGAL::parameters::density_upper_bound(raster.upper_bound_function(),
                                      CGAL::parameters::number_of_output_points(150000)));
  const CGAL::Penrose_Delaunay_triangulation_2<Epick> sequential(s);
  std::vector<Point> points;
  expect_built_as_cgal(sequential, s, "raster, Sequential_tag", points);
  expect_every_thread_count_as_sequential(s, sequential, "raster");
}
#endif

namespace {
// A density that fails partway through the tile tree (after a number of
// calls, as the sampler's own estimates would not see a bad spot) throws
// to the caller of `Pdt` with the sampler's message, and leaves the
// triangulation empty and usable; once the density is good again, the same
// sampler triangulates. Large enough for every walk to be split.
template <class Pdt>
void expect_bad_density_thrown_to_the_caller(const std::string& what)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::atomic<std::size_t> calls{0}, good_calls{std::numeric_limits<std::size_t>::max()};
  auto density = [&calls, &good_calls, nan](const Point& q) { return ++calls > good_calls ? nan : 1. + q.x(); };
  const Sampler s(unit_square, density, CGAL::parameters::number_of_output_points(200000));
  good_calls = calls + 100000;
  std::string message;
  Pdt pdt;
  pdt.insert(Point(0.5, 0.5));
  try {
    pdt.build(s, [](double x, double y) { return Point(x, y); });
  } catch(const std::invalid_argument& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("the density at ("), std::string::npos) << what << ": " << message;
  EXPECT_NE(message.find("nan"), std::string::npos) << what << ": " << message;
  EXPECT_EQ(pdt.number_of_vertices(), 0u) << what;
  EXPECT_TRUE(pdt.is_valid()) << what;
  pdt.insert(Point(0.5, 0.5));
  EXPECT_TRUE(pdt.is_valid()) << what;
  good_calls = std::numeric_limits<std::size_t>::max();
  ASSERT_TRUE(pdt.build(s, [](double x, double y) { return Point(x, y); })) << what;
  std::vector<Point> points;
  s(std::back_inserter(points));
  const CGAL::Delaunay_triangulation_2<Epick> dt(points.begin(), points.end());
  EXPECT_TRUE(edge_set(pdt, xy_of) == edge_set(dt, xy_of)) << what;
}
} // namespace

TEST(Triangulation, BadDensityThrowsToTheCallerWhateverTheTag)
{
  expect_bad_density_thrown_to_the_caller<CGAL::Penrose_Delaunay_triangulation_2<Epick>>("Sequential_tag");
#if defined(CGAL_LINKED_WITH_TBB)
  for(std::size_t threads : {2, 8}) {
    tbb::global_control limit(tbb::global_control::max_allowed_parallelism, threads);
    expect_bad_density_thrown_to_the_caller<Parallel_pdt>("Parallel_tag on " + std::to_string(threads) + " threads");
  }
#endif
}

TEST(Triangulation, RandomSmoothDensitiesMatchCgal)
{
  for(int seed = 1; seed <= 24; ++seed) {
    const std::size_t n = std::size_t(50) << (seed % 8);  // 50 to 6400 points
    const Epick::Iso_rectangle_2 region(-1, 2, -1 + 0.5 + 0.1 * seed, 3);
    expect_same_as_cgal(Sampler(region, random_density(seed), CGAL::parameters::number_of_output_points(n)),
                        "random density " + std::to_string(seed));
  }
}

TEST(Triangulation, UnusualRegionsAndDensitiesMatchCgal)
{
  auto one = [](const Point&) { return 1.; };
  expect_same_as_cgal(Sampler(Epick::Iso_rectangle_2(1e12, -1e12, 1e12 + 3, -1e12 + 1), one,
                              CGAL::parameters::number_of_output_points(3000)), "far from the origin");
  expect_same_as_cgal(Sampler(Epick::Iso_rectangle_2(0, 0, 1000, 1), one,
                              CGAL::parameters::number_of_output_points(8000)), "1000:1");
  expect_same_as_cgal(Sampler(Epick::Iso_rectangle_2(0, 0, 1e-9, 1e-9), one,
                              CGAL::parameters::number_of_output_points(2000)), "tiny");
  expect_same_as_cgal(Sampler(Epick::Iso_rectangle_2(-1e100, -1e100, 1e100, 1e100), one,
                              CGAL::parameters::number_of_output_points(2000)), "huge");
  expect_same_as_cgal(Sampler(unit_square, [](const Point& p) { return p.x() < 0.5 ? 0. : 1.; },
                              CGAL::parameters::number_of_output_points(5000)), "step");
  expect_same_as_cgal(Sampler(unit_square, [](const Point& p) {
                                const double r2 = (p.x() - .3) * (p.x() - .3) + (p.y() - .7) * (p.y() - .7);
                                return 1. + 1e4 * std::exp(-r2 / 1e-5); },
                              CGAL::parameters::number_of_output_points(8000)), "spike");
  EXPECT_THROW(Sampler(Epick::Iso_rectangle_2(-1e160, -1e160, 1e160, 1e160), one), std::invalid_argument);
  expect_same_as_cgal(Sampler(Epick::Iso_rectangle_2(1e11, 1e11, 1e11 + 1, 1e11 + 1), one,
                              CGAL::parameters::number_of_output_points(50000)), "finest resolved at 10^11");
  // tiles too fine for the coordinates (which crashed the construction):
  // refused, the triangulation left valid
  CGAL::Penrose_Delaunay_triangulation_2<Epick> pdt(Sampler(unit_square, one, CGAL::parameters::number_of_output_points(500)));
  EXPECT_THROW(pdt.build(Sampler(Epick::Iso_rectangle_2(1e12, 1e12, 1e12 + 1, 1e12 + 1), one,
                                 CGAL::parameters::number_of_output_points(5000)),
                         [](double x, double y) { return Point(x, y); }),
               std::range_error);
  EXPECT_TRUE(pdt.is_valid());
}

// One random case: a region of random size, aspect and distance from the
// origin, a density of one of several kinds drawn over it, a number of
// points, with or without correction vectors, and, for the densities whose
// maximum over a box is known, a density_upper_bound.
struct Random_case
{
  Epick::Iso_rectangle_2 region;
  Density density;
  std::function<double(const Epick::Iso_rectangle_2&)> bound;  // empty: none
  std::size_t n;
  bool correct;
  std::string what;
};

Random_case random_case(int seed)
{
  CGAL::Random r(seed);
  const double size = std::pow(10., r.get_double(-6, 6)), aspect = std::pow(10., r.get_double(-1.3, 1.3));
  const double w = size * std::sqrt(aspect), h = size / std::sqrt(aspect);
  auto centre = [&] { return r.get_int(0, 3) == 0 ? r.get_double(-1, 1) * size
                                                  : (r.get_bool() ? 1 : -1) * std::pow(10., r.get_double(0, 12)); };
  const double cx = centre(), cy = centre();
  const Epick::Iso_rectangle_2 region(cx - w / 2, cy - h / 2, cx + w / 2, cy + h / 2);
  const double x0 = region.xmin(), y0 = region.ymin(), dx = region.xmax() - x0, dy = region.ymax() - y0;
  auto u = [=](const Point& p) { return (p.x() - x0) / dx; };
  auto v = [=](const Point& p) { return (p.y() - y0) / dy; };

  Random_case c{region, Density(), {}, std::size_t(std::pow(10., r.get_double(0, 4.3))), r.get_int(0, 4) != 0, ""};
  switch(r.get_int(0, 6)) {
  case 0: {
    const Density smooth = random_density(seed);
    c.density = [=](const Point& p) { return smooth(Point(u(p), v(p))); };
    c.what = "bumps";
    break; }
  case 1: {  // zero on one side of a line
    const double angle = r.get_double(0, 2 * CGAL_PI), offset = r.get_double(-0.3, 0.3), high = r.get_double(0.1, 10);
    c.density = [=](const Point& p) {
      return std::cos(angle) * (u(p) - 0.5) + std::sin(angle) * (v(p) - 0.5) < offset ? 0. : high; };
    c.what = "step";
    break; }
  case 2: {  // zero outside a disc
    const double ux = r.get_double(0.2, 0.8), uy = r.get_double(0.2, 0.8), radius = r.get_double(0.05, 0.5);
    c.density = [=](const Point& p) {
      const double a = u(p) - ux, b = v(p) - uy, d = radius * radius - a * a - b * b;
      return d > 0. ? d : 0.; };
    c.what = "disc";
    break; }
  case 3: {  // up to nine orders of magnitude across the region
    const double k = r.get_double(1, 20);
    c.density = [=](const Point& p) { return std::exp(k * u(p)); };
    c.bound = [=](const Epick::Iso_rectangle_2& b) { return std::exp(k * (std::min)(1., (b.xmax() - x0) / dx)) * (1 + 1e-9); };
    c.what = "exponential";
    break; }
  case 4: {
    const double f = r.get_double(1, 40);
    c.density = [=](const Point& p) { return 1. + 0.9 * std::sin(f * u(p)) * std::sin(f * v(p)); };
    c.what = "waves";
    break; }
  default: {
    const double loose = r.get_double(1, 3);
    c.density = [](const Point&) { return 1.; };
    c.bound = [=](const Epick::Iso_rectangle_2&) { return loose; };
    c.what = "constant";
  } }
  std::ostringstream what;
  what.precision(17);
  what << "seed " << seed << ": " << c.what << ", " << c.n << " points, region " << region
       << (c.correct ? "" : ", no correction") << (c.bound ? ", with a bound" : "");
  c.what = what.str();
  return c;
}

// Whether doubles cannot tell apart the points that `c` asks for where its
// density peaks: a spacing under 1000 units in the last place of the
// region's largest coordinate, by a 64 x 64 grid's estimate (in 2000
// random cases, every refusal came below 80).
bool may_be_refused(const Random_case& c)
{
  double sum = 0., peak = 0.;
  const int k = 64;
  for(int i = 0; i < k; ++i)
    for(int j = 0; j < k; ++j) {
      const double d = c.density(Point(c.region.xmin() + (i + 0.5) / k * (c.region.xmax() - c.region.xmin()),
                                       c.region.ymin() + (j + 0.5) / k * (c.region.ymax() - c.region.ymin())));
      sum += d;
      peak = (std::max)(peak, d);
    }
  const double area = (c.region.xmax() - c.region.xmin()) * (c.region.ymax() - c.region.ymin());
  const double spacing = std::sqrt(area * (sum / (k * k)) / (double(c.n) * peak));
  const double largest = (std::max)({std::abs(c.region.xmin()), std::abs(c.region.xmax()),
                                     std::abs(c.region.ymin()), std::abs(c.region.ymax())});
  const double ulp = std::nextafter(largest, std::numeric_limits<double>::infinity()) - largest;
  return !(spacing >= 1e3 * ulp);
}

// PENROSE_RANDOM_CASES cases (200 by default) from seed PENROSE_RANDOM_FIRST_SEED
// (1 by default): the same edges as CGAL's triangulators, and the same
// again after edits in one case of four; or, where the points are too
// close for doubles, a clear refusal.
TEST(Triangulation, RandomRegionsAndDensitiesMatchCgal)
{
  // a malformed value fails the test rather than silently running no case
  auto from_environment = [](const char* name, int fallback) {
    const char* value = std::getenv(name);
    if(value == nullptr) return fallback;
    char* end = nullptr;
    const long parsed = std::strtol(value, &end, 10);
    if(end == value || *end != '\0' || parsed < 1 || parsed > 1000000) {
      ADD_FAILURE() << name << "=\"" << value << "\" is not a whole number from 1 to 10^6";
      return 0;
    }
    return int(parsed);
  };
  const int cases = from_environment("PENROSE_RANDOM_CASES", 200);
  const int first = from_environment("PENROSE_RANDOM_FIRST_SEED", 1);
  int matched = 0, refused = 0;
  auto expect_refusal = [&refused](const Random_case& c, const std::exception& e) {
    EXPECT_TRUE(may_be_refused(c)) << c.what << ": refused: " << e.what();
    ++refused;
  };
  for(int seed = first; seed < first + cases; ++seed) {
    const Random_case c = random_case(seed);
    try {
      const auto np = CGAL::parameters::use_correction_vectors(c.correct, CGAL::parameters::number_of_output_points(c.n));
      const Sampler s = c.bound ? Sampler(c.region, c.density, CGAL::parameters::density_upper_bound(c.bound, np))
                                : Sampler(c.region, c.density, np);
      CGAL::Penrose_Delaunay_triangulation_2<Epick> pdt(s);
      std::vector<Point> points;
      expect_built_as_cgal(pdt, s, c.what, points);
      if(seed % 4 == 0) {
        CGAL::Random r(seed);
        expect_delaunay_after_edits(pdt, std::move(points), c.region, r, c.what);
      }
      ++matched;
    } catch(const std::range_error& e) {
      expect_refusal(c, e);
    } catch(const std::invalid_argument& e) {  // a region that doubles cannot tell from a point
      expect_refusal(c, e);
    }
  }
  std::cout << matched << " cases matched CGAL, " << refused << " refused as too fine for doubles\n";
  EXPECT_GT(matched, 0) << "no case was compared with CGAL";
}

#if defined(CGAL_LINKED_WITH_TBB)
TEST(Triangulation, EveryThreadCountOnRandomCasesGivesCgalsTriangulation)
{
  // the first random cases, at a size where every walk is split in tasks;
  // those that doubles cannot hold are refused as above
  int matched = 0;
  for(int seed = 1; seed <= 6; ++seed) {
    Random_case c = random_case(seed);
    c.n = 100000;
    try {
      const auto np = CGAL::parameters::use_correction_vectors(c.correct, CGAL::parameters::number_of_output_points(c.n));
      const Sampler s = c.bound ? Sampler(c.region, c.density, CGAL::parameters::density_upper_bound(c.bound, np))
                                : Sampler(c.region, c.density, np);
      const CGAL::Penrose_Delaunay_triangulation_2<Epick> sequential(s);
      std::vector<Point> points;
      expect_built_as_cgal(sequential, s, c.what, points);
      expect_every_thread_count_as_sequential(s, sequential, c.what);
      ++matched;
    } catch(const std::range_error& e) {
      EXPECT_TRUE(may_be_refused(c)) << c.what << ": refused: " << e.what();
    } catch(const std::invalid_argument& e) {
      EXPECT_TRUE(may_be_refused(c)) << c.what << ": refused: " << e.what();
    }
  }
  std::cout << matched << " of 6 cases matched on every thread count\n";
  EXPECT_GE(matched, 3) << "too few random cases were compared";
}
#endif

TEST(Triangulation, WithoutCorrectionCocircularPointsMatchCgal)
{
  // raw tile vertices: many collinear and cocircular subsets
  for(std::size_t n : {std::size_t(2000), std::size_t(30000)})
    expect_same_as_cgal(Sampler(unit_square, [](const Point&) { return 1.; },
                                CGAL::parameters::use_correction_vectors(false).number_of_output_points(n)),
                        "no correction " + std::to_string(n));
}

TEST(Triangulation, RefusesWhatCannotFit)
{
  // 10^10 points: refused before any allocation, the triangulation untouched
  CGAL::Penrose_Delaunay_triangulation_2<Epick> pdt(
    Sampler(unit_square, [](const Point&) { return 1.; }, CGAL::parameters::number_of_output_points(500)));
  const std::set<Edge_key> before = edge_set(pdt, xy_of);
  const Sampler huge(unit_square, [](const Point&) { return 1.; },
                     CGAL::parameters::number_of_output_points(std::size_t(1e10)).maximum_number(std::size_t(1e11)));
  try {
    pdt.build(huge, [](double x, double y) { return Point(x, y); });
    ADD_FAILURE() << "10^10 points were not refused";
  } catch(const std::length_error& e) {
    EXPECT_NE(std::string(e.what()).find("about 1e+10 points: more than its 32-bit indices allow"), std::string::npos)
      << e.what();
  }
  EXPECT_TRUE(pdt.is_valid());
  EXPECT_TRUE(edge_set(pdt, xy_of) == before);
}

TEST(Triangulation, RefinementCapRefusesALooseBound)
{
  // a bound 10^6 times the density grew the base mesh to 8-9 GB for 81 s
  // before its length_error; the cap on the tiles refined per expected point
  // refuses it as the tree grows, and the triangulation can be built again
  auto one = [](const Point&) { return 1.; };
  auto loose = [](const Epick::Iso_rectangle_2&) { return 1e6; };
  CGAL::Penrose_Delaunay_triangulation_2<Epick> pdt(
    Sampler(unit_square, one, CGAL::parameters::number_of_output_points(500)));
  try {
    pdt.build(Sampler(unit_square, one, CGAL::parameters::density_upper_bound(loose).number_of_output_points(1004)),
              [](double x, double y) { return Point(x, y); });
    ADD_FAILURE() << "a bound 10^6 times the density was not refused";
  } catch(const std::length_error& e) {
    EXPECT_NE(std::string(e.what()).find("tiles refined for about 1e+03 points expected"), std::string::npos)
      << e.what();
  }
  EXPECT_TRUE(pdt.is_valid());
  pdt.build(Sampler(unit_square, one, CGAL::parameters::number_of_output_points(500)),
            [](double x, double y) { return Point(x, y); });
  EXPECT_GT(pdt.number_of_vertices(), 400u);
  EXPECT_TRUE(pdt.is_valid());
}

TEST(Triangulation, FewPointsHaveCgalsDimension)
{
  // tiny densities: 0, 1, 2, ... points
  std::set<std::size_t> seen;
  for(int k = 0; k < 60; ++k) {
    const double scale = 0.05 * std::pow(1.07, k);
    const Sampler s(unit_square, [](const Point& p) { return 1. + p.x(); },
                    CGAL::parameters::density_control_factor(scale));
    const std::pair<std::size_t, int> made = expect_same_as_cgal(s, "scale " + std::to_string(scale));
    seen.insert(made.first);
    if(made.first < 3) {
      EXPECT_EQ(made.second, int(made.first) - 1);
    }
  }
  EXPECT_TRUE(seen.count(0) && seen.count(1) && seen.count(2));
  // a density that is zero everywhere
  const CGAL::Penrose_Delaunay_triangulation_2<Epick> empty(
    Sampler(unit_square, [](const Point&) { return 0.; }));
  EXPECT_EQ(empty.number_of_vertices(), 0u);
  EXPECT_EQ(empty.dimension(), -1);
  EXPECT_TRUE(empty.is_valid());
}

TEST(Triangulation, StaysValidUnderEdits)
{
  const Sampler s(unit_square, [](const Point& p) { return 1. + 4. * p.x() * p.y(); },
                  CGAL::parameters::number_of_output_points(20000));
  CGAL::Penrose_Delaunay_triangulation_2<Epick> pdt(s);
  std::vector<Point> points;
  s(std::back_inserter(points));
  CGAL::Random r(7);
  const CGAL::Delaunay_triangulation_2<Epick> dt =
    expect_delaunay_after_edits(pdt, std::move(points), Epick::Iso_rectangle_2(-0.2, -0.2, 1.2, 1.2), r, "edits");
  // the rest of the Delaunay_triangulation_2 interface works on it
  const auto v = pdt.nearest_vertex(Point(0.5, 0.5));
  EXPECT_EQ(v->point(), dt.nearest_vertex(Point(0.5, 0.5))->point());
  std::size_t voronoi_edges = 0;
  for(auto e = pdt.finite_edges_begin(); e != pdt.finite_edges_end(); ++e)
  {
    const CGAL::Object o = pdt.dual(e);
    if(CGAL::object_cast<Epick::Segment_2>(&o)) ++voronoi_edges;
  }
  EXPECT_GT(voronoi_edges, 0u);
}

TEST(Triangulation, CopiesAndSwapsCarryTheirStatistics)
{
  typedef CGAL::Penrose_Delaunay_triangulation_2<Epick> Pdt;
  const Sampler s(unit_square, [](const Point& p) { return 1. + p.x(); },
                  CGAL::parameters::number_of_output_points(3000));
  const Pdt built(s);
  ASSERT_GT(built.number_of_flips(), 0u);
  Pdt copy(built), other;
  EXPECT_TRUE(copy.is_valid());
  EXPECT_TRUE(edge_set(copy, xy_of) == edge_set(built, xy_of));
  EXPECT_EQ(copy.number_of_flips(), built.number_of_flips());
  other.swap(copy);
  EXPECT_EQ(copy.number_of_vertices(), 0u);
  EXPECT_EQ(copy.number_of_flips(), 0u);
  EXPECT_TRUE(other.is_valid());
  EXPECT_TRUE(edge_set(other, xy_of) == edge_set(built, xy_of));
  EXPECT_EQ(other.number_of_flips(), built.number_of_flips());
  EXPECT_EQ(other.construction_statistics().base_vertices, built.construction_statistics().base_vertices);
}

TEST(Triangulation, CallbackReportsAdvancementAndStops)
{
  const Sampler s(unit_square, [](const Point& p) { return 1. + p.x(); },
                  CGAL::parameters::number_of_output_points(300000));
  auto lift = [](double x, double y) { return Point(x, y); };
  auto no_info = [](CGAL::Penrose_Delaunay_triangulation_2<Epick>::Vertex_handle, const Sampler::Sample&) {};
  std::vector<double> seen;
  CGAL::Penrose_Delaunay_triangulation_2<Epick> pdt;
  const std::function<bool(double)> record = [&seen](double a) { seen.push_back(a); return true; };
  ASSERT_TRUE(pdt.build(s, lift, no_info, CGAL::parameters::callback(record)));
  // the tile tree reports at each level and every 65536 tiles, then each step
  EXPECT_GE(std::count_if(seen.begin(), seen.end(), [](double a) { return a < 0.58; }), 10);
  EXPECT_TRUE(std::is_sorted(seen.begin(), seen.end()));
  EXPECT_GE(seen.front(), 0.);
  EXPECT_EQ(seen.back(), 1.);
  std::vector<Point> points;
  s(std::back_inserter(points));
  const CGAL::Delaunay_triangulation_2<Epick> dt(points.begin(), points.end());
  EXPECT_TRUE(edge_set(pdt, xy_of) == edge_set(dt, xy_of));

  // stopped within the tile tree, as the last level's triangles begin (in
  // two halves), after the flips (the TDS's storage reserved) and after the
  // TDS is written: empty, valid, and
  // usable again
  for(double limit : {0.3, 0.5, 0.7, 0.95}) {
    const std::function<bool(double)> stop = [limit](double a) { return a < limit; };
    EXPECT_FALSE(pdt.build(s, lift, no_info, CGAL::parameters::callback(stop))) << limit;
    EXPECT_EQ(pdt.number_of_vertices(), 0u) << limit;
    EXPECT_TRUE(pdt.is_valid()) << limit;
    pdt.insert(Point(0.5, 0.5));
    EXPECT_EQ(pdt.number_of_vertices(), 1u) << limit;
  }
  // through the constructor from a region and a density
  std::size_t calls = 0;
  const std::function<bool(double)> count = [&calls](double) { ++calls; return true; };
  const CGAL::Penrose_Delaunay_triangulation_2<Epick> from_density(
    unit_square, [](const Point&) { return 1.; },
    CGAL::parameters::number_of_output_points(1000).callback(count));
  EXPECT_GT(calls, 0u);
  EXPECT_GT(from_density.number_of_vertices(), 900u);
}

namespace {
template <class Gt, class Lift, class XY>
void expect_traits_match(const Sampler& s, const Lift& lift, const XY& xy, const std::string& what)
{
  expect_matches_cgal(CGAL::Penrose_Delaunay_triangulation_2<Gt>(s, lift), s, lift, xy, what);
}
} // namespace

// Every traits class of the issue, on the built-in and 20 random densities,
// from a few points to a few thousand (exact number types are slow: the
// sizes stop there; Epick goes to 10^5 above).
TEST(Traits, EveryTraitsClassOnEveryDensity)
{
  typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;
  typedef CGAL::Simple_cartesian<CGAL::Gmpq> Gmpq_kernel;
  typedef CGAL::Projection_traits_xy_3<Epick> Terrain;
  std::vector<std::pair<std::string, Density>> densities = builtin_densities();
  for(int seed = 0; seed < 20; ++seed) densities.emplace_back("random " + std::to_string(seed), random_density(seed));
  for(const auto& d : densities)
    for(std::size_t n : {std::size_t(12), std::size_t(300), std::size_t(2000)}) {
      const Sampler s(unit_square, d.second, CGAL::parameters::number_of_output_points(n));
      const std::string what = d.first + " " + std::to_string(n);
      auto to_double_xy = [](const auto& p) { return std::make_pair(CGAL::to_double(p.x()), CGAL::to_double(p.y())); };
      expect_traits_match<Epeck>(s, [](double x, double y) { return Epeck::Point_2(x, y); }, to_double_xy,
                                 "Epeck, " + what);
      expect_traits_match<Gmpq_kernel>(s, [](double x, double y) { return Gmpq_kernel::Point_2(x, y); },
                                       to_double_xy, "Simple_cartesian<Gmpq>, " + what);
      expect_traits_match<Terrain>(s, [](double x, double y) { return Epick::Point_3(x, y, x * x - y); },
                                   to_double_xy, "Projection_traits_xy_3, " + what);
    }
}

TEST(Traits, TerrainWithProjectionTraits)
{
  typedef CGAL::Projection_traits_xy_3<Epick> Gt;
  typedef Epick::Point_3 P3;
  auto height = [](double x, double y) { return std::sin(3 * x) * std::cos(2 * y); };
  const Sampler s(Epick::Iso_rectangle_2(0, 0, 2, 1),
                  [](const Point& p) { return 1. + 3. * p.x(); },
                  CGAL::parameters::number_of_output_points(5000));
  const CGAL::Penrose_Delaunay_triangulation_2<Gt> terrain(s, [&](double x, double y) { return P3(x, y, height(x, y)); });
  ASSERT_TRUE(terrain.is_valid());
  std::vector<P3> points;
  for(auto v = terrain.finite_vertices_begin(); v != terrain.finite_vertices_end(); ++v) {
    points.push_back(v->point());
    EXPECT_EQ(v->point().z(), height(v->point().x(), v->point().y()));
  }
  const CGAL::Delaunay_triangulation_2<Gt> dt(points.begin(), points.end());
  auto xy = [](const P3& p) { return std::make_pair(p.x(), p.y()); };
  EXPECT_TRUE(edge_set(terrain, xy) == edge_set(dt, xy));
  std::vector<Point> planar;
  s(std::back_inserter(planar));
  EXPECT_EQ(planar.size(), points.size());
}

TEST(Traits, VertexBaseWithTileInformation)
{
  typedef CGAL::Triangulation_vertex_base_with_info_2<std::pair<int, std::uint64_t>, Epick> Vb;
  typedef CGAL::Triangulation_data_structure_2<Vb> Tds;
  typedef CGAL::Penrose_Delaunay_triangulation_2<Epick, Tds> Pdt;
  const Sampler s(unit_square, [](const Point& p) { return 1. + p.y(); }, CGAL::parameters::number_of_output_points(4000));
  Pdt pdt;
  pdt.build(s, [](double x, double y) { return Point(x, y); },
            [](Pdt::Vertex_handle v, const Sampler::Sample& sample) { v->info() = {sample.level, sample.f_code}; });
  ASSERT_TRUE(pdt.is_valid());
  std::vector<Sampler::Sample> samples;
  s.samples(std::back_inserter(samples));
  std::map<std::pair<double, double>, std::pair<int, std::uint64_t>> expected;
  for(const auto& q : samples) expected[xy_of(q.point)] = {q.level, q.f_code};
  ASSERT_EQ(pdt.number_of_vertices(), expected.size());
  for(auto v = pdt.finite_vertices_begin(); v != pdt.finite_vertices_end(); ++v)
    EXPECT_EQ(v->info(), expected.at(xy_of(v->point())));
}

namespace {

// The sampler's traits for the triangulation's: the same where they are a
// kernel, Epick where they have no rectangle (the projection traits).
template <class Gt, class = void> struct Sampler_traits_of { typedef Epick type; };
template <class Gt> struct Sampler_traits_of<Gt, std::void_t<typename Gt::Iso_rectangle_2>> { typedef Gt type; };

// Everything the triangulation promises, for the traits Gt and the TDS Tds
// (CGAL::Default for the default one), its points made by `lift`: the
// triangulation of CGAL, on `n` points of a ramp and on degenerate inputs
// (raw tile vertices, with cocircular and collinear subsets; 0 to 3 points),
// the visitor, copies and swaps, a callback that stops, edits, a bad density.
template <class Gt, class Tds, class Lift>
void test_triangulation(const Lift& lift, std::size_t n, const std::string& name)
{
  typedef CGAL::Penrose_Delaunay_triangulation_2<Gt, Tds> Pdt;
  typedef typename Sampler_traits_of<Gt>::type K;
  typedef CGAL::Penrose_importance_sampler<K> S;
  typedef typename K::Point_2 P;
  auto x_of = [](const P& p) { return CGAL::to_double(K().compute_x_2_object()(p)); };
  auto xy = [](const typename Gt::Point_2& p) { return std::make_pair(CGAL::to_double(p.x()), CGAL::to_double(p.y())); };
  auto no_visitor = [](typename Pdt::Vertex_handle, const typename S::Sample&) {};
  const typename K::Iso_rectangle_2 region(P(0, 0), P(2, 1));
  auto ramp = [x_of](const P& p) { return 1. + x_of(p); };
  const S s(region, ramp, CGAL::parameters::number_of_output_points(n));

  const Pdt pdt(s, lift);
  std::vector<P> sampled;
  expect_matches_cgal(pdt, s, lift, xy, name, &sampled);
  EXPECT_GT(sampled.size(), n / 2) << name;
  EXPECT_GT(pdt.number_of_flips(), 0u) << name;
  EXPECT_LE(double(pdt.number_of_fallbacks()), 0.001 * double(sampled.size()) + 0.5) << name;

  // the visitor sees each vertex once, with the sample it comes from
  Pdt visited;
  std::size_t visits = 0, wrong = 0;
  ASSERT_TRUE(visited.build(s, lift, [&](typename Pdt::Vertex_handle v, const typename S::Sample& q) {
    ++visits;
    wrong += xy(v->point()) != std::make_pair(x_of(q.point), CGAL::to_double(K().compute_y_2_object()(q.point)));
  })) << name;
  EXPECT_EQ(visits, visited.number_of_vertices()) << name;
  EXPECT_EQ(wrong, 0u) << name;
  EXPECT_TRUE(edge_set(visited, xy) == edge_set(pdt, xy)) << name;

  // copies and swaps carry the statistics
  Pdt copy(pdt), other;
  other.swap(copy);
  EXPECT_EQ(copy.number_of_vertices(), 0u) << name;
  EXPECT_EQ(copy.number_of_flips(), 0u) << name;
  EXPECT_TRUE(other.is_valid()) << name;
  EXPECT_TRUE(edge_set(other, xy) == edge_set(pdt, xy)) << name;
  EXPECT_EQ(other.number_of_flips(), pdt.number_of_flips()) << name;
  EXPECT_EQ(other.construction_statistics().base_vertices, pdt.construction_statistics().base_vertices) << name;

  // a callback that stops the construction leaves it empty, valid and usable
  const std::function<bool(double)> stop = [](double a) { return a < 0.7; };
  EXPECT_FALSE(other.build(s, lift, no_visitor, CGAL::parameters::callback(stop))) << name;
  EXPECT_EQ(other.number_of_vertices(), 0u) << name;
  EXPECT_TRUE(other.is_valid()) << name;
  other.insert(lift(0.5, 0.5));
  EXPECT_EQ(other.number_of_vertices(), 1u) << name;

  // degenerate inputs
  const S raw(region, [](const P&) { return 1.; },
              CGAL::parameters::use_correction_vectors(false).number_of_output_points(n));
  expect_matches_cgal(Pdt(raw, lift), raw, lift, xy, name + ", no correction");
  std::set<std::size_t> seen;
  for(int k = 0; k < 30; ++k) {
    const S few(region, ramp, CGAL::parameters::density_control_factor(0.02 * std::pow(1.15, k)));
    std::vector<P> points;
    const Pdt t(few, lift);
    expect_matches_cgal(t, few, lift, xy, name + ", few points " + std::to_string(k), &points);
    seen.insert(points.size());
    EXPECT_EQ(t.dimension(), int((std::min)(points.size(), std::size_t(3))) - 1) << name << ", few points " << k;
  }
  EXPECT_TRUE(seen.count(0) && seen.count(1) && seen.count(2) && seen.count(3)) << name;

  // inserting and removing keep it the Delaunay triangulation of its vertices
  Pdt edited(s, lift);
  CGAL::Random r(7);
  for(int i = 0; i < 50; ++i) edited.insert(lift(r.get_double(-0.2, 2.2), r.get_double(-0.2, 1.2)));
  std::vector<typename Pdt::Vertex_handle> to_remove;
  for(auto v = edited.finite_vertices_begin(); v != edited.finite_vertices_end() && to_remove.size() < 30; ++v)
    if(r.get_int(0, 10) == 0) to_remove.push_back(v);
  for(auto v : to_remove) edited.remove(v);
  EXPECT_TRUE(edited.is_valid()) << name << ": after edits";
  std::vector<typename Gt::Point_2> rest;
  for(auto v = edited.finite_vertices_begin(); v != edited.finite_vertices_end(); ++v) rest.push_back(v->point());
  EXPECT_EQ(rest.size(), sampled.size() + 50 - to_remove.size()) << name;
  const CGAL::Delaunay_triangulation_2<Gt> dt(rest.begin(), rest.end());
  EXPECT_TRUE(edge_set(edited, xy) == edge_set(dt, xy)) << name << ": edges differ after edits";

  // a density that turns bad partway through throws the sampler's error and leaves it empty
  std::size_t calls = 0, good_calls = std::numeric_limits<std::size_t>::max();
  const S bad(region, [&](const P& p) { return ++calls > good_calls ? -1. : ramp(p); },
              CGAL::parameters::number_of_output_points(n));
  good_calls = calls + 10;
  Pdt refused(s, lift);
  EXPECT_THROW(refused.build(bad, lift), std::invalid_argument) << name;
  EXPECT_EQ(refused.number_of_vertices(), 0u) << name;
  EXPECT_TRUE(refused.is_valid()) << name;

  // from a region and a density, where the traits have a rectangle
  if constexpr(std::is_same<K, Gt>::value) {
    const Pdt from_region(region, ramp, CGAL::parameters::number_of_output_points(n));
    EXPECT_TRUE(edge_set(from_region, xy) == edge_set(pdt, xy)) << name;
  }
}

template <class K>
typename K::Point_2 planar(double x, double y) { return typename K::Point_2(x, y); }

} // namespace

TEST(Traits, TriangulationDriverOverEpick)
{
  test_triangulation<Epick, CGAL::Default>(planar<Epick>, 3000, "Epick");
}

// the sizes of Traits.EpeckAndGmpqMatchCgal, which this driver replaced
TEST(Traits, TriangulationDriverOverEpeck)
{
  typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;
  test_triangulation<Epeck, CGAL::Default>(planar<Epeck>, 3000, "Epeck");
}

TEST(Traits, TriangulationDriverOverGmpq)
{
  typedef CGAL::Simple_cartesian<CGAL::Gmpq> Gmpq_kernel;
  test_triangulation<Gmpq_kernel, CGAL::Default>(planar<Gmpq_kernel>, 3000, "Simple_cartesian<Gmpq>");
}

TEST(Traits, TriangulationDriverOverProjectionTraitsXy3)
{
  test_triangulation<CGAL::Projection_traits_xy_3<Epick>, CGAL::Default>(
    [](double x, double y) { return Epick::Point_3(x, y, x * x - y); }, 2000, "Projection_traits_xy_3<Epick>");
}

TEST(Traits, TriangulationDriverOverAVertexBaseWithInfo)
{
  typedef CGAL::Triangulation_data_structure_2<CGAL::Triangulation_vertex_base_with_info_2<int, Epick>,
                                               CGAL::Triangulation_face_base_2<Epick>> Tds;
  test_triangulation<Epick, Tds>(planar<Epick>, 1000, "Epick, a vertex base with info");
}

// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Penrose_Delaunay_triangulation_2 against CGAL's own triangulators on the
// same points: the edge sets must be equal, for many densities, sizes and
// traits classes, and the triangulation must stay valid under edits.

#include <CGAL/Penrose_Delaunay_triangulation_2.h>

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
#include <utility>
#include <vector>

#if defined(__linux__)
#  include <sched.h>
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
// point at a time, on the sampler's points made by `lift` in the traits Gt;
// `sampled`, if given, receives the sampler's points.
template <class Gt, class Lift, class XY>
void expect_matches_cgal(const CGAL::Penrose_Delaunay_triangulation_2<Gt>& pdt, const Sampler& s, const Lift& lift,
                         const XY& xy, const std::string& what, std::vector<Point>* sampled = nullptr)
{
  typedef typename Gt::Point_2 P;
  ASSERT_TRUE(pdt.is_valid()) << what;
  std::vector<Point> planar;
  s(std::back_inserter(planar));
  std::vector<P> points;
  for(const Point& p : planar) points.push_back(lift(p.x(), p.y()));
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

TEST(Triangulation, LargeEnoughForHugePagesMatchesCgal)
{
  // at this size the flat mesh's arrays pass Huge_page_allocator's threshold
  expect_same_as_cgal(Sampler(unit_square, [](const Point& p) { return 0.2 + p.x() * p.y(); },
                              CGAL::parameters::number_of_output_points(400000)), "400000 points");
}

// Grown one element at a time, a vector of `Vector` moves from
// std::allocator to mapped pages (aligned to `alignment` where mapped);
// shrunk, back again. Its contents survive both moves.
template <class Vector>
void expect_contents_kept_across_threshold(std::uint64_t n, std::uintptr_t alignment)
{
  Vector v;
  for(std::uint64_t i = 0; i < n; ++i) v.push_back(i * 0x9e3779b97f4a7c15u);
#if defined(CGAL_PENROSE_HUGE_PAGES)
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(v.data()) % alignment, 0u);
#else
  (void)alignment;
#endif
  std::size_t wrong = 0;
  for(std::uint64_t i = 0; i < n; ++i) wrong += v[i] != i * 0x9e3779b97f4a7c15u;
  EXPECT_EQ(wrong, 0u);
  v.resize(1000);
  v.shrink_to_fit();
  for(std::uint64_t i = 0; i < 1000; ++i) wrong += v[i] != i * 0x9e3779b97f4a7c15u;
  EXPECT_EQ(wrong, 0u);
}

TEST(Internals, HugePageAllocatorKeepsContentsAcrossItsThreshold)
{
  expect_contents_kept_across_threshold<CGAL::internal::Penrose::Large_vector<std::uint64_t>>(3000000, 1u << 21);
}

TEST(Internals, SmallPageAllocatorKeepsContentsAcrossItsThreshold)
{
  expect_contents_kept_across_threshold<CGAL::internal::Penrose::Scratch_vector<std::uint64_t>>(1000000, 4096u);
}

TEST(Internals, HugePageAllocatorReusesAReleasedBlockUntilReleasedForGood)
{
  typedef CGAL::internal::Penrose::Huge_page_allocator<double> Allocator;
  const std::size_t n = 3000000;  // 24 MB
  Allocator a;
  double* first = a.allocate(n);
  for(std::size_t i = 0; i < n; i += 512) first[i] = double(i);
  a.deallocate(first, n);
  double* second = a.allocate(n);
#if defined(CGAL_PENROSE_HUGE_PAGES)
  EXPECT_EQ(first, second);
#endif
  // whatever the kernel did with the released block, it is usable
  std::size_t wrong = 0;
  for(std::size_t i = 0; i < n; ++i) second[i] = double(i);
  for(std::size_t i = 0; i < n; ++i) wrong += second[i] != double(i);
  EXPECT_EQ(wrong, 0u);
  a.deallocate(second, n);
  // unmapped now: a fresh mapping reads as zeros (malloc's memory need not)
  CGAL::internal::Penrose::release_kept_blocks();
  double* third = a.allocate(n);
#if defined(CGAL_PENROSE_HUGE_PAGES)
  for(std::size_t i = 0; i < n; i += 512) wrong += third[i] != 0.;
  EXPECT_EQ(wrong, 0u);
#endif
  a.deallocate(third, n);
  CGAL::internal::Penrose::release_kept_blocks();
}

TEST(Internals, LookaheadWorkerHandsResultsInOrderAndRethrows)
{
  using CGAL::internal::Penrose::Lookahead_worker;
  for(bool wanted : {false, true}) {
    Lookahead_worker worker(wanted);
    if(!wanted) { EXPECT_FALSE(worker.running()); }
    const std::size_t n = 100000;
    std::vector<std::size_t> out(n, 0);
    for(int batch = 1; batch <= 3; ++batch) {
      worker.start(n, [&out, batch](std::size_t b, std::size_t e) {
        for(std::size_t k = b; k < e; ++k) out[k] = k * k + std::size_t(batch);
      });
      std::size_t wrong = 0;
      for(std::size_t k = 0; k < n; ++k) {
        worker.wait_for(k);
        wrong += out[k] != k * k + std::size_t(batch);
      }
      EXPECT_EQ(wrong, 0u) << wanted << " " << batch;
    }
    // a job that throws at item 70000: the throw reaches the caller (at
    // start() without a helper, which does the jobs at once; at the wait
    // for an item of its chunk with one), and the worker goes on
    std::string message;
    std::size_t handed = 0;
    try {
      worker.start(n, [](std::size_t b, std::size_t e) {
        for(std::size_t k = b; k < e; ++k)
          if(k == 70000) throw std::runtime_error("item 70000");
      });
      for(; handed < n; ++handed) worker.wait_for(handed);
    } catch(const std::runtime_error& e) {
      message = e.what();
    }
    EXPECT_EQ(message, "item 70000") << wanted;
    EXPECT_LE(handed, 70000u) << wanted;
    // with a helper, the items before the chunk that threw were handed over
    if(worker.running()) { EXPECT_GT(handed, 70000u - 1024u); }
    worker.start(0, [](std::size_t, std::size_t) {});
    worker.wait_for_all();
    std::vector<int> empty_batch_seen;
    worker.start(10, [&empty_batch_seen](std::size_t b, std::size_t e) {
      for(std::size_t k = b; k < e; ++k) empty_batch_seen.push_back(int(k));
    });
    worker.wait_for_all();
    EXPECT_EQ(empty_batch_seen.size(), 10u) << wanted;
  }
}

TEST(Internals, TwoHalvesRunBothHalvesTheSecondOnAHelper)
{
  for(bool worth_a_thread : {false, true}) {
    std::array<std::thread::id, 2> ran_on;
    std::array<int, 2> runs = {{0, 0}};
    CGAL::internal::Penrose::run_in_two_halves(worth_a_thread, [&](int half) noexcept {
      ran_on[half] = std::this_thread::get_id();
      ++runs[half];
    });
    EXPECT_EQ(runs[0], 1);
    EXPECT_EQ(runs[1], 1);
    EXPECT_EQ(ran_on[0], std::this_thread::get_id());
#if defined(CGAL_PENROSE_HELPER_THREADS)
    const bool helped = worth_a_thread && CGAL::internal::Penrose::more_than_one_core();
#else
    const bool helped = false;
#endif
    EXPECT_EQ(ran_on[1] != std::this_thread::get_id(), helped) << worth_a_thread;
  }
}

#if defined(CGAL_PENROSE_HELPER_THREADS) && defined(__linux__) && defined(CPU_COUNT)
TEST(Triangulation, HelperThreadsChangeNothingInTheConstruction)
{
  // the last level's triangles are made in two halves, on two threads where
  // there are two cores: confined to one core, the construction runs without
  // helpers, and its base mesh must be the same (as many flips, removals,
  // repairs), not only its result
  const Sampler s(unit_square, [](const Point& p) { return 0.3 + p.x() * p.x() + p.y(); },
                  CGAL::parameters::number_of_output_points(250000));
  const CGAL::Penrose_Delaunay_triangulation_2<Epick> helped(s);
  cpu_set_t all, one;
  ASSERT_EQ(sched_getaffinity(0, sizeof(all), &all), 0);
  CPU_ZERO(&one);
  for(int c = 0; c < CPU_SETSIZE; ++c)
    if(CPU_ISSET(c, &all)) {
      CPU_SET(c, &one);
      break;
    }
  ASSERT_EQ(sched_setaffinity(0, sizeof(one), &one), 0);
  EXPECT_FALSE(CGAL::internal::Penrose::more_than_one_core());
  const CGAL::Penrose_Delaunay_triangulation_2<Epick> alone(s);
  ASSERT_EQ(sched_setaffinity(0, sizeof(all), &all), 0);
  const auto& a = helped.construction_statistics();
  const auto& b = alone.construction_statistics();
  EXPECT_EQ(a.flips, b.flips);
  EXPECT_EQ(a.base_vertices, b.base_vertices);
  EXPECT_EQ(a.removed_vertices, b.removed_vertices);
  EXPECT_EQ(a.repaired_vertices, b.repaired_vertices);
  EXPECT_EQ(a.fallbacks, b.fallbacks);
  EXPECT_GT(a.flips, 0u);
  EXPECT_TRUE(edge_set(helped, xy_of) == edge_set(alone, xy_of));
  std::vector<Point> points;
  s(std::back_inserter(points));
  const CGAL::Delaunay_triangulation_2<Epick> dt(points.begin(), points.end());
  EXPECT_TRUE(edge_set(helped, xy_of) == edge_set(dt, xy_of));
}
#endif

TEST(Triangulation, BadDensityFoundByTheHelperThrowsAsWithout)
{
  // large enough for the builder's helper thread, which calls the density:
  // a density that fails partway through the tile tree (after a number of
  // calls, as the sampler's own estimates would not see a bad spot) throws
  // to the caller with the sampler's message, and leaves the triangulation
  // usable
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::size_t calls = 0, good_calls = std::numeric_limits<std::size_t>::max();
  auto density = [&calls, &good_calls, nan](const Point& q) { return ++calls > good_calls ? nan : 1. + q.x(); };
  const Sampler s(unit_square, density, CGAL::parameters::number_of_output_points(200000));
  good_calls = calls + 100000;
  std::string message;
  CGAL::Penrose_Delaunay_triangulation_2<Epick> pdt;
  try {
    pdt.build(s, [](double x, double y) { return Point(x, y); });
  } catch(const std::invalid_argument& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("the density at ("), std::string::npos) << message;
  EXPECT_NE(message.find("nan"), std::string::npos) << message;
  EXPECT_TRUE(pdt.is_valid());
  pdt.insert(Point(0.5, 0.5));
  EXPECT_TRUE(pdt.is_valid());
  // and once the density is good again, the same sampler triangulates
  good_calls = std::numeric_limits<std::size_t>::max();
  ASSERT_TRUE(pdt.build(s, [](double x, double y) { return Point(x, y); }));
  std::vector<Point> points;
  s(std::back_inserter(points));
  const CGAL::Delaunay_triangulation_2<Epick> dt(points.begin(), points.end());
  EXPECT_TRUE(edge_set(pdt, xy_of) == edge_set(dt, xy_of));
}

TEST(Internals, TdsReservationReleasesThenMakesTheFacesOnAHelper)
{
  typedef CGAL::Penrose_Delaunay_triangulation_2<Epick>::Triangulation_data_structure Tds;
  typedef CGAL::internal::Penrose::Tds_reservation<Tds> Reservation;
  const std::size_t large = Reservation::least_vertices, small = large - 1;
#if defined(CGAL_PENROSE_HELPER_THREADS)
  const bool helped = CGAL::internal::Penrose::more_than_one_core();
#else
  const bool helped = false;
#endif
  for(const std::size_t n : {small, large}) {
    const std::size_t faces = 2 * n - 3;  // odd: the first half is the shorter
    std::thread::id released_on;
    Reservation reservation(n, faces, [&released_on] { released_on = std::this_thread::get_id(); });
    const bool prepared = reservation.prepared();
    const Reservation::Faces& made = reservation.faces();
    const Tds& tds = reservation.tds();
    EXPECT_EQ(prepared, helped && n == large) << n;
    // the release always runs, on the helper where there is one
    EXPECT_EQ(released_on == std::this_thread::get_id(), !prepared);
    EXPECT_EQ(tds.number_of_vertices(), 0u);
    EXPECT_EQ(tds.vertices().capacity() >= n, prepared);
    EXPECT_EQ(tds.faces().size(), prepared ? faces : 0u);
    EXPECT_EQ(made.size(), prepared ? faces : 0u);
    if(prepared) {
      // the k-th face made is the k-th of the container, and empty
      std::size_t k = 0;
      for(auto f = tds.faces().begin(); f != tds.faces().end(); ++f, ++k) {
        EXPECT_EQ(made[k], Tds::Face_handle(f));
        EXPECT_EQ(f->vertex(0), Tds::Vertex_handle());
      }
    }
  }
}

TEST(Internals, CreationOrderHandlesFindEveryElementByRank)
{
  // Elements made in a container with holes (runs of one element, in the
  // free list's order) and then in fresh blocks (long runs).
  typedef CGAL::Penrose_Delaunay_triangulation_2<Epick>::Triangulation_data_structure Tds;
  typedef CGAL::internal::Penrose::Creation_order_handles<Tds::Face_range> Handles;
  Tds tds;
  std::vector<Tds::Face_handle> early;
  for(int i = 0; i < 3000; ++i) early.push_back(tds.create_face());
  for(std::size_t i = 0; i < early.size(); i += 3) tds.delete_face(early[i]);
  Handles made;
  std::vector<Tds::Face_handle> expected;
  for(int i = 0; i < 20000; ++i) {
    expected.push_back(tds.create_face());
    made.record(expected.back());
  }
  made.index();
  ASSERT_EQ(made.size(), expected.size());
  for(std::size_t k = 0; k < expected.size(); ++k) ASSERT_EQ(made[k], expected[k]) << k;
}

TEST(Internals, FastPredicatesNeverContradictEpick)
{
  // Near-degenerate configurations at every scale: four points rounded onto a
  // circle, three onto a line, then nudged by a few ulps. The filters may
  // leave a case undecided (ZERO), never decide it wrongly, and must decide
  // the generic ones.
  using namespace CGAL::internal::Penrose;
  CGAL::Random rng(20261122);
  const Epick::Orientation_2 orientation;
  const Epick::Side_of_oriented_circle_2 side_of_oriented_circle;
  auto nudge = [&rng](double v) {
    for(int k = rng.get_int(-3, 4); k != 0; k += (k < 0 ? 1 : -1))
      v = std::nextafter(v, k < 0 ? -HUGE_VAL : HUGE_VAL);
    return v;
  };
  std::size_t wrong = 0, generic = 0, generic_decided = 0, degenerate_decided = 0;
  for(int trial = 0; trial < 200000; ++trial) {
    const double scale = std::ldexp(1., rng.get_int(-700, 700));
    const double offset = (trial % 3 == 0) ? 0. : scale * std::ldexp(1., rng.get_int(0, 40));
    const double cx = offset + scale * rng.get_double(-1, 1), cy = offset + scale * rng.get_double(-1, 1);
    const double r = scale * rng.get_double(0.01, 1);
    const bool degenerate = trial % 2 == 0;
    std::array<Point, 4> q;
    for(int i = 0; i < 4; ++i) {
      const double a = rng.get_double(0, 6.283185307179586);
      const double x = cx + r * std::cos(a), y = cy + r * std::sin(a);
      q[i] = degenerate ? Point(nudge(x), nudge(y)) : Point(cx + scale * rng.get_double(-1, 1), cy + scale * rng.get_double(-1, 1));
    }
    if(degenerate && trial % 4 == 0)  // the third point on the line of the first two
      q[2] = Point(nudge(q[0].x() + 0.375 * (q[1].x() - q[0].x())), nudge(q[0].y() + 0.375 * (q[1].y() - q[0].y())));
    const CGAL::Sign o = filtered_orientation(q[0].x(), q[0].y(), q[1].x(), q[1].y(), q[2].x(), q[2].y());
    wrong += o != CGAL::ZERO && o != orientation(q[0], q[1], q[2]);
    if(orientation(q[0], q[1], q[2]) != CGAL::POSITIVE) std::swap(q[0], q[1]);
    const CGAL::Sign s = filtered_in_circle(q[0].x(), q[0].y(), q[1].x(), q[1].y(), q[2].x(), q[2].y(), q[3].x(), q[3].y());
    wrong += s != CGAL::ZERO && s != CGAL::Sign(side_of_oriented_circle(q[0], q[1], q[2], q[3]));
    const bool in_range = std::abs(scale) > 1e-40 && std::abs(offset) + scale < 1e60;
    if(!degenerate && in_range) {
      ++generic;
      generic_decided += (o != CGAL::ZERO) + (s != CGAL::ZERO);
    }
    if(degenerate) degenerate_decided += (s != CGAL::ZERO);
  }
  EXPECT_EQ(wrong, 0u);
  EXPECT_GT(double(generic_decided), 0.99 * 2. * double(generic));
  EXPECT_GT(generic, 10000u);
  std::cout << "fast predicates: " << generic_decided << " of " << 2 * generic << " generic tests decided, "
            << degenerate_decided << " of 100000 near-cocircular ones\n";
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
  using CGAL::internal::Penrose::check_construction_size;
  const double gib = double(1 << 30);
  EXPECT_THROW(check_construction_size(1e7, 200., 1. * gib), std::length_error);
  EXPECT_NO_THROW(check_construction_size(1e7, 200., 4. * gib));
  EXPECT_NO_THROW(check_construction_size(1e7, 200., 0.));  // memory unknown
  EXPECT_THROW(check_construction_size(2e9, 200., 0.), std::length_error);  // 32-bit indices
  EXPECT_NO_THROW(check_construction_size(1.5e9, 200., 0.));
  using CGAL::internal::Penrose::check_growth;
  EXPECT_THROW(check_growth(1e6, 2e6, 500., 0.25 * gib, "", "", ""), std::length_error);
  EXPECT_NO_THROW(check_growth(1e6, 2e6, 500., 1. * gib, "", "", ""));
  EXPECT_NO_THROW(check_growth(1e6, 2e6, 500., 0., "", "", ""));  // memory unknown
  EXPECT_THROW(check_growth(2e6, 2e6, 0., 0., "", "", ""), std::length_error);

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

TEST(Internals, BaseMeshThatWouldOutgrowMemoryIsRefusedBeforeItGrows)
{
  // a density bound 64 times the density refines tiles that hold no point,
  // and the mesh outgrows what was reserved for the points: a builder
  // allowed 64 MiB refuses to grow it past them, with its
  // helper thread and without (2^16 points and up), and a mesh that stays
  // within what was reserved is not refused
  using CGAL::internal::Penrose::Base_triangulation_builder;
  using CGAL::internal::Penrose::Flat_mesh;
  using CGAL::internal::Penrose::Sampler_access;
  const double budget = 64. * (1 << 20);
  auto one = [](const Point&) { return 1.; };
  auto loose = [](const Epick::Iso_rectangle_2&) { return 64.; };
  for(std::size_t n : {std::size_t(20000), std::size_t(100000)}) {
    const Sampler s(unit_square, one,
                    CGAL::parameters::density_upper_bound(loose, CGAL::parameters::number_of_output_points(n)));
    Flat_mesh mesh;
    Base_triangulation_builder builder(Sampler_access::context(s), mesh, false, budget);
    std::string message = "not refused";
    try {
      builder.build(s.expected_number_of_points(), std::function<bool(double)>());
    } catch(const std::length_error& e) {
      message = e.what();
    }
    EXPECT_NE(message.find("the base mesh would grow to about"), std::string::npos) << n << ": " << message;
    EXPECT_NE(message.find("GiB of this machine"), std::string::npos) << n << ": " << message;
    EXPECT_LT(520. * double(mesh.points.size()), budget) << n;

    const Sampler tight(unit_square, one, CGAL::parameters::number_of_output_points(n));
    Flat_mesh fitting;
    EXPECT_TRUE(Base_triangulation_builder(Sampler_access::context(tight), fitting, false, budget)
                  .build(tight.expected_number_of_points(), std::function<bool(double)>())) << n;
    EXPECT_GT(fitting.points.size(), n / 2) << n;
  }
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
  // two halves, the other on the helper), after the flips (while the TDS's
  // storage is reserved) and after the TDS is written: empty, valid, and
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
template <class K>
void expect_kernel_matches(const std::string& name)
{
  typedef typename K::Point_2 P;
  const CGAL::Penrose_importance_sampler<K> s(typename K::Iso_rectangle_2(P(0, 0), P(2, 1)),
    [](const P& p) { return 1. + CGAL::to_double(p.x()); }, CGAL::parameters::number_of_output_points(3000));
  const CGAL::Penrose_Delaunay_triangulation_2<K> pdt(s);
  ASSERT_TRUE(pdt.is_valid()) << name;
  std::vector<P> points;
  s(std::back_inserter(points));
  const CGAL::Delaunay_triangulation_2<K> dt(points.begin(), points.end());
  auto xy = [](const P& p) { return std::make_pair(CGAL::to_double(p.x()), CGAL::to_double(p.y())); };
  EXPECT_TRUE(edge_set(pdt, xy) == edge_set(dt, xy)) << name;
}
} // namespace

TEST(Traits, EpeckAndGmpqMatchCgal)
{
  expect_kernel_matches<CGAL::Exact_predicates_exact_constructions_kernel>("Epeck");
  expect_kernel_matches<CGAL::Simple_cartesian<CGAL::Gmpq>>("Simple_cartesian<Gmpq>");
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

// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The internals, each checked against an independent expectation: the tile
// tree (the geometry of its tiles, their neighbours, the Fibonacci codes,
// the importance bins, agreement with the depth-first sampler, pruning), the
// halves and blocks of either concurrency tag, the TDS reservation, the fast
// predicates and the size checks.

#include <CGAL/Penrose_Delaunay_triangulation_2.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tiling/Tile_tree.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Random.h>

#include <boost/iterator/function_output_iterator.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iostream>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>
#include <vector>

using namespace CGAL::internal::Penrose;

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Penrose_importance_sampler<Epick> Sampler;
typedef Epick::Point_2 Point;

const Epick::Iso_rectangle_2 unit_square(0, 0, 1, 1);

#if defined(CGAL_LINKED_WITH_TBB)
typedef CGAL::Parallel_tag Parallel_if_available;
#else
typedef CGAL::Sequential_tag Parallel_if_available;
#endif

Tile_tree tile_tree(const Sampler& s) { return Tile_tree(Sampler_access::context(s)); }

double triangle_area(const Tile_tree& tree, Tile_tree::Index t)
{
  const auto& tile = tree.tile(t);
  const auto& a = tree.vertex(tile.vertices[0]);
  const auto& b = tree.vertex(tile.vertices[1]);
  const auto& c = tree.vertex(tile.vertices[2]);
  return 0.5 * ((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
}

// Separating axis test with a tolerance: true if the interiors overlap by more than eps.
bool interiors_overlap(const Tile_tree& tree, Tile_tree::Index s,
                       Tile_tree::Index t, double eps)
{
  const Tile_tree::Index tiles[2] = {s, t};
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

Tile_tree constant_tree(double n)
{
  return tile_tree(Sampler(unit_square, [](const Point&) { return 1.; },
                           CGAL::parameters::number_of_output_points(std::size_t(n))));
}

} // namespace

TEST(Tiles, ChildrenCoverTheirParentExactly)
{
  const Tile_tree tree = constant_tree(3000);
  std::size_t subdivided = 0;
  for(Tile_tree::Index t = 0; t < tree.tiles().size(); ++t) {
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
  const Tile_tree tree = constant_tree(3000);
  std::size_t same_level = 0, coarser = 0;
  for(Tile_tree::Index t = 0; t < tree.tiles().size(); ++t)
    for(int e = 0; e < 3; ++e) {
      const auto n = tree.neighbor(t, e);
      if(n == Tile_tree::null_index) continue;
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
  const Tile_tree tree = constant_tree(5000);
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
      if(v.birth.code >> b & 1u) f += fibonacci().fib[bits + 1 - b];
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
  const long double log_phi2 = std::log(static_cast<long double>(golden_ratio) *
                                        static_cast<long double>(golden_ratio));
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> exponent(-4., 12.5);  // up to the deepest level
  for(unsigned bins : {1u, 5u, 21u, 64u}) {
    const Importance_bins index(bins);
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
  tile_tree(s).for_each_sample([&](Tile_tree::Index, const Placed_sample& q) {
    b.emplace_back(q.x, q.y);
  });
  std::sort(a.begin(), a.end());
  std::sort(b.begin(), b.end());
  ASSERT_EQ(a.size(), b.size());
  EXPECT_TRUE(a == b);
}

TEST(Tiles, ThresholdPruningDropsNoActiveSample)
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
    EXPECT_LT(tile_tree(with_tight).tiles().size(), tile_tree(with_loose).tiles().size());
  }
}

TEST(Tiles, TreeRefusesALooseBoundAsItGrows)
{
  // the cap on the tiles refined per expected point holds for the tree too
  const Sampler loose(unit_square, [](const Point&) { return 1.; },
                      CGAL::parameters::density_upper_bound([](const Epick::Iso_rectangle_2&) { return 1e6; })
                        .number_of_output_points(1004));
  try {
    tile_tree(loose);
    ADD_FAILURE() << "a bound 10^6 times the density was not refused";
  } catch(const std::length_error& e) {
    EXPECT_NE(std::string(e.what()).find("tiles refined for about 1e+03 points expected"), std::string::npos)
      << e.what();
  }
}

TEST(Tiles, RegionPruningDropsNoSample)
{
  // A tile beyond the region's margin is not subdivided. No sample that its
  // subtree could hold may land in the region: born anywhere in the tile at
  // the next level or deeper, with the F-code of a random path down the
  // rules, any direction, and an importance that keeps its leaf at its birth
  // level (the largest moves), moved by the real correction table. The tiles
  // tried lie beside the region at 0.95 to 1.25 of their size, and the
  // samples near their corner nearest to it, where a margin too thin would
  // show: a margin 5% thinner lets 4 of the 1.9 million samples in.
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

// Both halves run once, the first on the calling thread (which alone may
// call the user's callback), and what either throws reaches the caller;
// every block of a walk runs once, and what the blocks gather comes in the
// order of the items, whatever the tag; what a block throws reaches the
// caller.
template <class ConcurrencyTag>
void expect_pieces_run_once_and_rethrow()
{
  for(bool worth_splitting : {false, true}) {
    std::array<std::thread::id, 2> ran_on;
    std::array<int, 2> runs = {{0, 0}};
    run_in_two_halves<ConcurrencyTag>(worth_splitting, [&](int half) {
      ran_on[half] = std::this_thread::get_id();
      ++runs[half];
    });
    EXPECT_EQ(runs[0], 1);
    EXPECT_EQ(runs[1], 1);
    EXPECT_EQ(ran_on[0], std::this_thread::get_id());
    if(!is_parallel<ConcurrencyTag>) { EXPECT_EQ(ran_on[1], std::this_thread::get_id()); }
    for(int thrower : {0, 1}) {
      std::string message;
      try {
        run_in_two_halves<ConcurrencyTag>(worth_splitting, [thrower](int half) {
          if(half == thrower) throw std::runtime_error("half " + std::to_string(half));
        });
      } catch(const std::runtime_error& e) {
        message = e.what();
      }
      EXPECT_EQ(message, "half " + std::to_string(thrower)) << worth_splitting;
    }
  }

  constexpr std::size_t n = 5 * walk_block + 17;
  std::vector<int> seen(n, 0);
  for_each_block<ConcurrencyTag>(n, 1000, [&seen](std::size_t b, std::size_t e) {
    for(std::size_t k = b; k < e; ++k) ++seen[k];
  });
  EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), std::ptrdiff_t(n));
  // every third item, in order
  const std::vector<std::size_t> found =
    gather_in_blocks<std::size_t, ConcurrencyTag>(n, [](std::size_t b, std::size_t e, std::vector<std::size_t>& f) {
      for(std::size_t k = b; k < e; ++k)
        if(k % 3 == 0) f.push_back(k);
    });
  std::vector<std::size_t> expected;
  for(std::size_t k = 0; k < n; k += 3) expected.push_back(k);
  EXPECT_TRUE(found == expected);
  std::string message;
  try {
    gather_in_blocks<std::size_t, ConcurrencyTag>(n, [](std::size_t b, std::size_t e, std::vector<std::size_t>&) {
      if(b <= n - 1 && n - 1 < e) throw std::runtime_error("the last item");
    });
  } catch(const std::runtime_error& e) {
    message = e.what();
  }
  EXPECT_EQ(message, "the last item");
}

TEST(Internals, HalvesAndBlocksRunOnceInOrderAndRethrow)
{
  expect_pieces_run_once_and_rethrow<CGAL::Sequential_tag>();
#if defined(CGAL_LINKED_WITH_TBB)
  expect_pieces_run_once_and_rethrow<CGAL::Parallel_tag>();
#endif
}

TEST(Internals, TdsReservationMakesTheFacesInOrder)
{
  typedef CGAL::Penrose_Delaunay_triangulation_2<Epick>::Triangulation_data_structure Tds;
  typedef Tds_reservation<Tds> Reservation;
  const std::size_t n = 70000, faces = 2 * n - 3;
  const Reservation reservation(n, faces);
  const Tds& tds = reservation.tds;
  EXPECT_EQ(tds.number_of_vertices(), 0u);
  EXPECT_GE(tds.vertices().capacity(), n);
  EXPECT_EQ(tds.faces().size(), faces);
  EXPECT_EQ(reservation.made.size(), faces);
  // the k-th face made is the k-th of the container, and empty
  std::size_t k = 0;
  for(auto f = tds.faces().begin(); f != tds.faces().end(); ++f, ++k) {
    EXPECT_EQ(reservation.made[k], Tds::Face_handle(f));
    EXPECT_EQ(f->vertex(0), Tds::Vertex_handle());
  }
}

TEST(Internals, CreationOrderHandlesFindEveryElementByRank)
{
  // Elements made in a container with holes (runs of one element, in the
  // free list's order) and then in fresh blocks (long runs).
  typedef CGAL::Penrose_Delaunay_triangulation_2<Epick>::Triangulation_data_structure Tds;
  typedef Creation_order_handles<Tds::Face_range> Handles;
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

TEST(Internals, BaseMeshThatWouldOutgrowMemoryIsRefusedBeforeItGrows)
{
  // a density bound 64 times the density refines tiles that hold no point,
  // and the mesh outgrows what was reserved for the points: a builder
  // allowed 64 MiB refuses to grow it past them, with either tag (the
  // Parallel_tag surveys tiles in tasks), and a mesh that stays within what
  // was reserved is not refused
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
      if(n < 50000) builder.build<CGAL::Sequential_tag>(s.expected_number_of_points(), std::function<bool(double)>());
      else builder.build<Parallel_if_available>(s.expected_number_of_points(), std::function<bool(double)>());
    } catch(const std::length_error& e) {
      message = e.what();
    }
    EXPECT_NE(message.find("the base mesh would grow to about"), std::string::npos) << n << ": " << message;
    EXPECT_NE(message.find("GiB of this machine"), std::string::npos) << n << ": " << message;
    EXPECT_LT(520. * double(mesh.points.size()), budget) << n;

    const Sampler tight(unit_square, one, CGAL::parameters::number_of_output_points(n));
    Flat_mesh fitting;
    EXPECT_TRUE(Base_triangulation_builder(Sampler_access::context(tight), fitting, false, budget)
                  .build<Parallel_if_available>(tight.expected_number_of_points(), std::function<bool(double)>())) << n;
    EXPECT_GT(fitting.points.size(), n / 2) << n;
  }
}

TEST(Internals, SizeChecksRefuseWhatCannotFit)
{
  const double gib = double(1 << 30);
  EXPECT_THROW(check_construction_size(1e7, 200., 1. * gib), std::length_error);
  EXPECT_NO_THROW(check_construction_size(1e7, 200., 4. * gib));
  EXPECT_NO_THROW(check_construction_size(1e7, 200., 0.));  // memory unknown
  EXPECT_THROW(check_construction_size(2e9, 200., 0.), std::length_error);  // 32-bit indices
  EXPECT_NO_THROW(check_construction_size(1.5e9, 200., 0.));
  EXPECT_THROW(check_growth(1e6, 2e6, 500., 0.25 * gib, "", "", ""), std::length_error);
  EXPECT_NO_THROW(check_growth(1e6, 2e6, 500., 1. * gib, "", "", ""));
  EXPECT_NO_THROW(check_growth(1e6, 2e6, 500., 0., "", "", ""));  // memory unknown
  EXPECT_THROW(check_growth(2e6, 2e6, 0., 0., "", "", ""), std::length_error);
}

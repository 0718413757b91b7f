// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// refine_terrain_by_greedy_insertion(): the error bound, checked at every
// cell by locating its centre in the triangulation (CGAL's exact point
// location, not the refinement's own rasterisation); the vertex budget; the
// triangulation valid and Delaunay afterwards; what it throws.

#include <CGAL/refine_terrain_by_greedy_insertion.h>
#include <CGAL/Penrose_Delaunay_triangulation_2.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Projection_traits_xy_3.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Projection_traits_xy_3<K> Gt;
typedef CGAL::Penrose_Delaunay_triangulation_2<Gt> Penrose_dt;
typedef CGAL::Delaunay_triangulation_2<Gt> Cgal_dt;

// A 37 x 23 grid over [-2, 3] x [1, 4]: a bump, a ridge and a crease.
struct Grid
{
  std::size_t width = 37, height = 23;
  CGAL::Bbox_2 region{-2., 1., 3., 4.};
  std::vector<double> heights;

  // as the refinement places them
  double x(std::size_t i) const { return region.xmin() + (double(i) + 0.5) * ((region.xmax() - region.xmin()) / double(width)); }
  double y(std::size_t j) const { return region.ymax() - (double(j) + 0.5) * ((region.ymax() - region.ymin()) / double(height)); }
  static double f(double x, double y)
  {
    return 10. * std::exp(-((x - 0.5) * (x - 0.5) + (y - 2.5) * (y - 2.5))) + 3. * std::sin(3. * x + y)
           + 2. * std::abs(x + 0.3 * y - 1.);
  }

  Grid()
  {
    for(std::size_t j = 0; j < height; ++j)
      for(std::size_t i = 0; i < width; ++i) heights.push_back(f(x(i), y(j)));
  }
};

// The largest error over the cells whose centre lies in a finite face, each
// located with CGAL's predicates and interpolated with its barycentric
// coordinates; `uncovered` counts the others.
template <class DT>
double independent_max_error(const DT& dt, const Grid& g, std::size_t& uncovered)
{
  double largest = 0.;
  uncovered = 0;
  for(std::size_t j = 0; j < g.height; ++j)
    for(std::size_t i = 0; i < g.width; ++i) {
      const double x = g.x(i), y = g.y(j);
      const auto f = dt.locate(K::Point_3(x, y, 0.));
      if(dt.is_infinite(f)) { ++uncovered; continue; }
      double px[3], py[3], pz[3];
      for(int k = 0; k < 3; ++k) {
        px[k] = f->vertex(k)->point().x();
        py[k] = f->vertex(k)->point().y();
        pz[k] = f->vertex(k)->point().z();
      }
      const double area = (px[1] - px[0]) * (py[2] - py[0]) - (px[2] - px[0]) * (py[1] - py[0]);
      const double b1 = ((x - px[0]) * (py[2] - py[0]) - (px[2] - px[0]) * (y - py[0])) / area;
      const double b2 = ((px[1] - px[0]) * (y - py[0]) - (x - px[0]) * (py[1] - py[0])) / area;
      const double z = (1. - b1 - b2) * pz[0] + b1 * pz[1] + b2 * pz[2];
      largest = std::max(largest, std::abs(z - g.heights[j * g.width + i]));
    }
  return largest;
}

// A Penrose triangulation of the grid's region, lifted to f, not to the
// grid: its vertices are off the cells' centres.
Penrose_dt sampled(const Grid& g, std::size_t n)
{
  const K::Iso_rectangle_2 region(g.region.xmin(), g.region.ymin(), g.region.xmax(), g.region.ymax());
  CGAL::Penrose_importance_sampler<K> sampler(region, [](const K::Point_2&) { return 1.; },
                                              CGAL::parameters::number_of_output_points(n));
  return Penrose_dt(sampler, [](double x, double y) { return K::Point_3(x, y, Grid::f(x, y)); });
}

const double tolerance = 1e-9;  // of the heights' range (about 20): rounding only

TEST(RefineTerrain, EveryCoveredCellWithinMaxError)
{
  const Grid g;
  Penrose_dt dt = sampled(g, 60);
  const std::size_t sampled_vertices = dt.number_of_vertices();
  std::size_t uncovered_before = 0, uncovered = 0;
  ASSERT_GT(independent_max_error(dt, g, uncovered_before), 2.);
  std::size_t visited = 0;
  auto visit = [&](Penrose_dt::Vertex_handle v) {
    ++visited;
    // an inserted vertex is a cell's centre with the cell's height
    const double u = (v->point().x() - g.region.xmin()) / (5. / 37.) - 0.5;
    const double w = (g.region.ymax() - v->point().y()) / (3. / 23.) - 0.5;
    ASSERT_NEAR(u, std::round(u), 1e-9);
    ASSERT_NEAR(w, std::round(w), 1e-9);
    EXPECT_EQ(v->point().z(), g.heights[std::size_t(std::round(w)) * g.width + std::size_t(std::round(u))]);
  };
  for(double e : {1., 0.25, 0.01}) {
    const std::size_t before = dt.number_of_vertices();
    const CGAL::Terrain_refinement_result r = CGAL::refine_terrain_by_greedy_insertion(
      dt, g.width, g.height, g.heights, g.region, CGAL::parameters::max_error(e, CGAL::parameters::visitor(visit)));
    EXPECT_TRUE(r.max_error_reached);
    EXPECT_LE(r.max_error, e);
    EXPECT_GT(r.number_of_inserted_points, 0u);
    EXPECT_EQ(dt.number_of_vertices(), before + r.number_of_inserted_points);
    EXPECT_EQ(visited, dt.number_of_vertices() - sampled_vertices);
    const double measured = independent_max_error(dt, g, uncovered);
    EXPECT_LE(measured, e + tolerance * 20.) << "max_error " << e;
    EXPECT_NEAR(measured, r.max_error, tolerance * 20.);
    EXPECT_LE(uncovered, uncovered_before);  // inserting only grows the hull
    EXPECT_TRUE(dt.is_valid());              // Delaunay_triangulation_2's: the empty circles too
  }
}

TEST(RefineTerrain, StopsAtTheVertexBudget)
{
  const Grid g;
  Penrose_dt dt = sampled(g, 60);
  const std::size_t sampled_vertices = dt.number_of_vertices();
  const CGAL::Terrain_refinement_result r = CGAL::refine_terrain_by_greedy_insertion(
    dt, g.width, g.height, g.heights, g.region, CGAL::parameters::max_error(0.01, CGAL::parameters::number_of_points(200)));
  EXPECT_FALSE(r.max_error_reached);
  EXPECT_EQ(dt.number_of_vertices(), 200u);
  EXPECT_EQ(r.number_of_inserted_points, 200u - sampled_vertices);
  std::size_t uncovered = 0;
  EXPECT_NEAR(independent_max_error(dt, g, uncovered), r.max_error, tolerance * 20.);
  EXPECT_GT(r.max_error, 0.01);
  EXPECT_TRUE(dt.is_valid());
  // a budget already reached inserts nothing
  const CGAL::Terrain_refinement_result none = CGAL::refine_terrain_by_greedy_insertion(
    dt, g.width, g.height, g.heights, g.region, CGAL::parameters::number_of_points(100));
  EXPECT_EQ(none.number_of_inserted_points, 0u);
  EXPECT_FALSE(none.max_error_reached);
  EXPECT_EQ(dt.number_of_vertices(), 200u);
}

// Without max_error, the refinement goes on until the interpolation is
// exact: at every cell of a grid whose corners' centres are vertices.
TEST(RefineTerrain, ExactWithoutMaxErrorOnCgalTriangulation)
{
  const Grid g;
  Cgal_dt dt;
  for(std::size_t j : {std::size_t(0), g.height - 1})
    for(std::size_t i : {std::size_t(0), g.width - 1}) dt.insert(K::Point_3(g.x(i), g.y(j), g.heights[j * g.width + i]));
  const CGAL::Terrain_refinement_result r = CGAL::refine_terrain_by_greedy_insertion(dt, g.width, g.height, g.heights, g.region);
  std::size_t uncovered = 0;
  EXPECT_TRUE(r.max_error_reached);
  EXPECT_EQ(r.max_error, 0.);
  EXPECT_LE(independent_max_error(dt, g, uncovered), tolerance * 20.);
  EXPECT_EQ(uncovered, 0u);
  EXPECT_LE(dt.number_of_vertices(), g.width * g.height);
  EXPECT_TRUE(dt.is_valid());
}

// A vertex at a cell's centre with another height cannot be inserted
// again: it takes the cell's height.
TEST(RefineTerrain, VertexAtACellCentreTakesItsHeight)
{
  const Grid g;
  Cgal_dt dt;
  for(std::size_t j : {std::size_t(0), g.height - 1})
    for(std::size_t i : {std::size_t(0), g.width - 1}) dt.insert(K::Point_3(g.x(i), g.y(j), g.heights[j * g.width + i]));
  const auto v = dt.insert(K::Point_3(g.x(18), g.y(11), g.heights[11 * g.width + 18] + 100.));
  const CGAL::Terrain_refinement_result r = CGAL::refine_terrain_by_greedy_insertion(
    dt, g.width, g.height, g.heights, g.region, CGAL::parameters::max_error(0.5));
  std::size_t uncovered = 0;
  EXPECT_TRUE(r.max_error_reached);
  EXPECT_EQ(v->point().z(), g.heights[11 * g.width + 18]);
  EXPECT_LE(independent_max_error(dt, g, uncovered), 0.5 + tolerance * 20.);
  EXPECT_TRUE(dt.is_valid());
}

TEST(RefineTerrain, ThrowsOnBadInputAndLeavesTheTriangulation)
{
  const Grid g;
  Penrose_dt dt = sampled(g, 60);
  const std::size_t sampled_vertices = dt.number_of_vertices();
  using CGAL::parameters::max_error;
  auto refine = [&](std::size_t w, std::size_t h, const std::vector<double>& z, const CGAL::Bbox_2& r, double e) {
    CGAL::refine_terrain_by_greedy_insertion(dt, w, h, z, r, max_error(e));
  };
  std::vector<double> nan = g.heights, inf = g.heights;
  nan[100] = std::numeric_limits<double>::quiet_NaN();
  inf[7] = -std::numeric_limits<double>::infinity();
  EXPECT_THROW(refine(g.width + 1, g.height, g.heights, g.region, 1.), std::invalid_argument);
  EXPECT_THROW(refine(0, g.height, g.heights, g.region, 1.), std::invalid_argument);
  EXPECT_THROW(refine(g.width, g.height, nan, g.region, 1.), std::invalid_argument);
  EXPECT_THROW(refine(g.width, g.height, inf, g.region, 1.), std::invalid_argument);
  EXPECT_THROW(refine(g.width, g.height, g.heights, CGAL::Bbox_2(0., 0., 0., 1.), 1.), std::invalid_argument);
  EXPECT_THROW(refine(g.width, g.height, g.heights, CGAL::Bbox_2(-1e308, 0., 1e308, 1.), 1.), std::invalid_argument);
  EXPECT_THROW(refine(g.width, g.height, g.heights, g.region, -1.), std::invalid_argument);
  EXPECT_THROW(refine(g.width, g.height, g.heights, g.region, std::numeric_limits<double>::quiet_NaN()),
               std::invalid_argument);
  EXPECT_EQ(dt.number_of_vertices(), sampled_vertices);
}

} // namespace

// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// refine_terrain_by_greedy_insertion(), triangulate_height_grid() and
// fit_terrain_heights(): the error bound, checked at every cell by locating
// its centre in the triangulation (CGAL's exact point location, not the
// refinement's own rasterisation); the vertex budget; an image's luminance
// meshed better than a regular grid; the RMS error lowered by the fit; the
// triangulation valid and Delaunay afterwards; what they throw.

#include <CGAL/fit_terrain_heights.h>
#include <CGAL/refine_terrain_by_greedy_insertion.h>
#include <CGAL/triangulate_height_grid.h>
#include <CGAL/Penrose_Delaunay_triangulation_2.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Projection_traits_xy_3.h>

#include <gtest/gtest.h>

#include <algorithm>
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

// By default a 37 x 23 grid over [-2, 3] x [1, 4]: a bump, a ridge and a crease.
struct Grid
{
  std::size_t width = 37, height = 23;
  CGAL::Bbox_2 region{-2., 1., 3., 4.};
  std::vector<double> heights;

  // An image's luminance, from 0 to 1 in steps of 1/255, one unit a pixel:
  // a shaded background, a dark disc, a bright rectangle and thin stripes,
  // whose sharp edges a regular grid blurs.
  static Grid image()
  {
    Grid g;
    g.width = 96;
    g.height = 64;
    g.region = CGAL::Bbox_2(0., 0., 96., 64.);
    g.heights.clear();
    for(std::size_t j = 0; j < g.height; ++j)
      for(std::size_t i = 0; i < g.width; ++i) {
        const double x = g.x(i), y = g.y(j);
        double l = 0.2 + 0.5 * x / 96.;
        if((x - 30.) * (x - 30.) + (y - 40.) * (y - 40.) < 15. * 15.) l = 0.1;
        if(x > 55. && x < 85. && y > 10. && y < 30.) l = 0.9 - 0.01 * (y - 10.);
        if(y < 6. && int(x / 4.) % 2 == 0) l = 1.;
        g.heights.push_back(std::round(255. * l) / 255.);
      }
    return g;
  }

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

// The largest and the RMS error over the cells whose centre lies in a
// finite face, each located with CGAL's predicates and interpolated with its
// barycentric coordinates; `uncovered` counts the others.
struct Errors
{
  double max = 0., rms = 0.;
};

template <class DT>
Errors independent_errors(const DT& dt, const Grid& g, std::size_t& uncovered)
{
  double largest = 0., squares = 0.;
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
      const double e = z - g.heights[j * g.width + i];
      largest = std::max(largest, std::abs(e));
      squares += e * e;
    }
  const std::size_t covered = g.width * g.height - uncovered;
  return {largest, covered ? std::sqrt(squares / double(covered)) : 0.};
}

template <class DT>
double independent_max_error(const DT& dt, const Grid& g, std::size_t& uncovered)
{
  return independent_errors(dt, g, uncovered).max;
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

// The triangulation of about n cell centres on a regular lattice, the corners included.
Cgal_dt regular_grid(const Grid& g, std::size_t n)
{
  Cgal_dt grid;
  const std::size_t nx = std::size_t(std::sqrt(double(n) * double(g.width) / double(g.height))), ny = n / nx;
  for(std::size_t b = 0; b < ny; ++b)
    for(std::size_t a = 0; a < nx; ++a) {
      const std::size_t i = a * (g.width - 1) / (nx - 1), j = b * (g.height - 1) / (ny - 1);
      grid.insert(K::Point_3(g.x(i), g.y(j), g.heights[j * g.width + i]));
    }
  return grid;
}

// An image's luminance triangulated with 5% of its pixels as vertices: the
// whole grid covered, a lower RMS error than a regular grid of as many
// vertices; then every cell within max_error with a fraction of the pixels.
TEST(TriangulateHeightGrid, ImageLuminanceBeatsTheRegularGrid)
{
  const Grid g = Grid::image();
  const std::size_t n = g.width * g.height / 20;
  Penrose_dt dt;
  std::size_t visited = 0;
  const CGAL::Terrain_refinement_result r = CGAL::triangulate_height_grid(
    dt, g.width, g.height, g.heights, g.region,
    CGAL::parameters::number_of_points(n, CGAL::parameters::visitor([&](Penrose_dt::Vertex_handle) { ++visited; })));
  EXPECT_EQ(dt.number_of_vertices(), n);
  EXPECT_EQ(visited, n);
  EXPECT_FALSE(r.max_error_reached);
  EXPECT_GT(r.number_of_inserted_points, n / 2);
  std::size_t uncovered = 0;
  const Errors mesh = independent_errors(dt, g, uncovered);
  EXPECT_EQ(uncovered, 0u);
  EXPECT_NEAR(mesh.max, r.max_error, tolerance);

  const Cgal_dt grid = regular_grid(g, n);
  ASSERT_LE(grid.number_of_vertices(), n);
  std::size_t grid_uncovered = 0;
  const Errors regular = independent_errors(grid, g, grid_uncovered);
  EXPECT_EQ(grid_uncovered, 0u);
  EXPECT_LT(mesh.rms, 0.5 * regular.rms) << "grid of " << grid.number_of_vertices() << " vertices";

  const CGAL::Terrain_refinement_result bounded = CGAL::refine_terrain_by_greedy_insertion(
    dt, g.width, g.height, g.heights, g.region, CGAL::parameters::max_error(0.02));
  EXPECT_TRUE(bounded.max_error_reached);
  EXPECT_LE(independent_max_error(dt, g, uncovered), 0.02 + tolerance);
  EXPECT_LT(dt.number_of_vertices(), g.width * g.height / 4);
  EXPECT_TRUE(dt.is_valid());
}

// max_error alone: every cell within it, from a sparse sample.
TEST(TriangulateHeightGrid, MaxErrorAlone)
{
  for(const Grid& g : {Grid(), Grid::image()}) {
    Penrose_dt dt;
    const double e = g.width == 37 ? 0.5 : 0.02;  // a 40th of the terrain's range; 5 grey levels
    const CGAL::Terrain_refinement_result r = CGAL::triangulate_height_grid(
      dt, g.width, g.height, g.heights, g.region, CGAL::parameters::max_error(e));
    std::size_t uncovered = 0;
    EXPECT_TRUE(r.max_error_reached);
    EXPECT_LE(independent_max_error(dt, g, uncovered), e + tolerance * 20.);
    EXPECT_EQ(uncovered, 0u);
    EXPECT_LT(dt.number_of_vertices(), g.width * g.height / 2);
    EXPECT_TRUE(dt.is_valid());
  }
}

TEST(TriangulateHeightGrid, ThrowsOnBadInput)
{
  const Grid g;
  Penrose_dt dt;
  using namespace CGAL::parameters;
  auto triangulate = [&](const auto& np) { CGAL::triangulate_height_grid(dt, g.width, g.height, g.heights, g.region, np); };
  EXPECT_THROW(triangulate(base_fraction(0.05)), std::invalid_argument);  // no bound
  EXPECT_THROW(triangulate(number_of_points(3)), std::invalid_argument);
  EXPECT_THROW(triangulate(max_error(0.)), std::invalid_argument);
  EXPECT_THROW(triangulate(max_error(std::numeric_limits<double>::quiet_NaN())), std::invalid_argument);
  EXPECT_THROW(triangulate(base_fraction(0., number_of_points(100))), std::invalid_argument);
  EXPECT_THROW(triangulate(base_fraction(1.5, number_of_points(100))), std::invalid_argument);
  EXPECT_THROW(CGAL::triangulate_height_grid(dt, g.width, g.height - 1, g.heights, g.region, number_of_points(100)),
               std::invalid_argument);
  EXPECT_EQ(dt.number_of_vertices(), 0u);
  triangulate(number_of_points(4, base_fraction(1.)));  // the smallest: a sample, then the corners as needed
  EXPECT_GE(dt.number_of_vertices(), 4u);
  EXPECT_TRUE(dt.is_valid());
}

// The least-squares fit lowers the RMS error, as measured independently, and
// leaves the triangulation's x and y.
TEST(FitTerrainHeights, LowersTheRmsError)
{
  for(const Grid& g : {Grid(), Grid::image()}) {
    Penrose_dt dt = sampled(g, 40);
    CGAL::refine_terrain_by_greedy_insertion(dt, g.width, g.height, g.heights, g.region,
                                             CGAL::parameters::number_of_points(g.width * g.height / 8));
    std::vector<K::Point_2> before;
    for(auto v : dt.finite_vertex_handles()) before.emplace_back(v->point().x(), v->point().y());
    std::size_t uncovered = 0, uncovered_after = 0;
    const Errors interpolating = independent_errors(dt, g, uncovered);
    const CGAL::Terrain_fit_result r = CGAL::fit_terrain_heights(dt, g.width, g.height, g.heights, g.region);
    const Errors fitted = independent_errors(dt, g, uncovered_after);
    EXPECT_EQ(uncovered_after, uncovered);
    EXPECT_EQ(r.number_of_cells, g.width * g.height - uncovered);
    EXPECT_NEAR(r.rms_error_before, interpolating.rms, tolerance);
    EXPECT_NEAR(r.rms_error_after, fitted.rms, tolerance);
    EXPECT_LT(fitted.rms, 0.95 * interpolating.rms);
    EXPECT_GT(r.number_of_iterations, 0u);
    std::size_t k = 0;
    for(auto v : dt.finite_vertex_handles()) EXPECT_EQ(K::Point_2(v->point().x(), v->point().y()), before[k++]);
    EXPECT_TRUE(dt.is_valid());
  }
}

// Where every cell's centre is a vertex, off its height, the fit gives each
// its cell's height; vertices among them that no cell constrains (their
// faces cover only the cell centres at their other vertices, where their
// weight is rounding) keep their heights instead of running away.
TEST(FitTerrainHeights, UnconstrainedVerticesKeepTheirHeights)
{
  const Grid g;
  Cgal_dt dt;
  for(std::size_t j = 0; j < g.height; ++j)
    for(std::size_t i = 0; i < g.width; ++i)
      dt.insert(K::Point_3(g.x(i), g.y(j), g.heights[j * g.width + i] + std::sin(double(i * j))));
  const double dx = 5. / 37., dy = 3. / 23.;
  std::vector<Cgal_dt::Vertex_handle> loose;
  for(std::size_t k = 0; k < 20; ++k)
    loose.push_back(dt.insert(K::Point_3(g.x(k + 5) + 0.3 * dx, g.y(k % 19 + 2) - 0.4 * dy, 100.)));
  const CGAL::Terrain_fit_result r = CGAL::fit_terrain_heights(dt, g.width, g.height, g.heights, g.region);
  EXPECT_GT(r.rms_error_before, 0.1);
  // the pinning holds each vertex back by 10^-6 of its move (at most 1 here)
  EXPECT_LE(r.rms_error_after, 2e-6);
  for(auto v : loose) EXPECT_NEAR(v->point().z(), 100., 1e-3);
  std::size_t uncovered = 0;
  EXPECT_LE(independent_max_error(dt, g, uncovered), 2e-6);
}

TEST(FitTerrainHeights, ThrowsOnBadInputAndLeavesTheTriangulation)
{
  const Grid g;
  Penrose_dt dt = sampled(g, 60);
  std::vector<double> z;
  for(auto v : dt.finite_vertex_handles()) z.push_back(v->point().z());
  std::vector<double> nan = g.heights;
  nan[3] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(CGAL::fit_terrain_heights(dt, g.width, g.height + 1, g.heights, g.region), std::invalid_argument);
  EXPECT_THROW(CGAL::fit_terrain_heights(dt, g.width, g.height, nan, g.region), std::invalid_argument);
  EXPECT_THROW(CGAL::fit_terrain_heights(dt, g.width, g.height, g.heights, CGAL::Bbox_2(0., 0., 1., 0.)),
               std::invalid_argument);
  std::size_t k = 0;
  for(auto v : dt.finite_vertex_handles()) EXPECT_EQ(v->point().z(), z[k++]);
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

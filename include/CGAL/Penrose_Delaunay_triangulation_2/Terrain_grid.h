// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The height grid that refine_terrain_by_greedy_insertion() and
// fit_terrain_heights() read: its checks, its cell coordinates and the cells
// under a triangle, written once so that both see the same cells.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_TERRAIN_GRID_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_TERRAIN_GRID_H

#include <CGAL/Bbox_2.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace CGAL {
namespace internal {
namespace Penrose {

// `width x height` cells over `region`, row 0 at the top (largest y). In cell
// coordinates (u, v), cell (i, j) is centred at (i, j).
class Terrain_grid
{
public:
  // Throws std::invalid_argument, the message starting with `caller`, if the
  // grid is empty or its size does not match `heights`, a height is NaN or
  // infinite, or `region` is empty or not finite.
  template <class HeightRange>
  Terrain_grid(std::size_t width, std::size_t height, const HeightRange& heights, const Bbox_2& region,
               const std::string& caller)
    : w_(width), h_(height), x0_(region.xmin()), y1_(region.ymax()),
      cell_x_((region.xmax() - region.xmin()) / double(width)),
      cell_y_((region.ymax() - region.ymin()) / double(height))
  {
    const std::size_t size = std::size_t(std::distance(std::begin(heights), std::end(heights)));
    if(width == 0 || height == 0 || height > size / width || size != width * height)
      throw std::invalid_argument(caller + ": the grid is empty or its size does not match");
    for(std::size_t k = 0; k < size; ++k)
      if(!std::isfinite(double(heights[k])))
        throw std::invalid_argument(caller + ": the height of cell (" + std::to_string(k % width) + ", "
                                    + std::to_string(k / width) + ") is not finite");
    const double inf = std::numeric_limits<double>::infinity();
    if(!(region.xmax() > region.xmin() && region.ymax() > region.ymin() && region.xmax() - region.xmin() < inf
         && region.ymax() - region.ymin() < inf))
      throw std::invalid_argument(caller + ": the region is empty or not finite");
  }

  std::size_t width() const { return w_; }
  std::size_t height() const { return h_; }

  // The centre of cell (i, j) in the region's coordinates.
  double x(std::size_t i) const { return x0_ + (double(i) + 0.5) * cell_x_; }
  double y(std::size_t j) const { return y1_ - (double(j) + 0.5) * cell_y_; }

  // The cell coordinates of a point.
  template <class Point>
  double u(const Point& p) const { return (to_double(p.x()) - x0_) / cell_x_ - 0.5; }
  template <class Point>
  double v(const Point& p) const { return (y1_ - to_double(p.y())) / cell_y_ - 0.5; }

  // The bilinear interpolation of `heights` between the cell centres at
  // (u, v) in cell coordinates, clamped to the outer centres.
  template <class HeightRange>
  double interpolate(const HeightRange& heights, double u, double v) const
  {
    u = (std::min)((std::max)(u, 0.), double(w_ - 1));
    v = (std::min)((std::max)(v, 0.), double(h_ - 1));
    const std::size_t i = (std::min)(std::size_t(u), w_ - 1), j = (std::min)(std::size_t(v), h_ - 1);
    const std::size_t i1 = (std::min)(i + 1, w_ - 1), j1 = (std::min)(j + 1, h_ - 1);
    const double a = u - double(i), b = v - double(j);
    const double top = (1 - a) * double(heights[j * w_ + i]) + a * double(heights[j * w_ + i1]);
    const double bottom = (1 - a) * double(heights[j1 * w_ + i]) + a * double(heights[j1 * w_ + i1]);
    return (1 - b) * top + b * bottom;
  }

  // Calls `span(j, i_lo, i_hi)`, i_lo <= i_hi, for each row j of the cells
  // (i, j) whose centre the triangle with vertices (u[k], v[k]) in cell
  // coordinates covers, on an edge or a vertex included. Each row's span is
  // bounded by the crossings of its edges, each computed from the edge's
  // endpoints in a fixed order and kept inclusive: two triangles find the
  // same crossing on their common edge, so that every cell covered is visited.
  template <class Span>
  void for_each_row(const double u[3], const double v[3], Span span) const
  {
    const double v_lo = (std::max)(0., std::ceil((std::min)({v[0], v[1], v[2]})));
    const double v_hi = (std::min)(double(h_) - 1., std::floor((std::max)({v[0], v[1], v[2]})));
    int from[3], to[3];  // each edge from its lower endpoint (in v, then u) up
    double slope[3];
    for(int k = 0; k < 3; ++k) {
      from[k] = k;
      to[k] = (k + 1) % 3;
      if(v[to[k]] < v[from[k]] || (v[to[k]] == v[from[k]] && u[to[k]] < u[from[k]])) std::swap(from[k], to[k]);
      slope[k] = v[to[k]] == v[from[k]] ? 0. : (u[to[k]] - u[from[k]]) / (v[to[k]] - v[from[k]]);
    }
    for(double row = v_lo; row <= v_hi; ++row) {
      double lo = std::numeric_limits<double>::infinity(), hi = -lo;
      for(int k = 0; k < 3; ++k) {
        const int p = from[k], q = to[k];
        if(row < v[p] || row > v[q]) continue;
        if(v[p] == v[q]) {
          lo = (std::min)(lo, u[p]);
          hi = (std::max)(hi, u[q]);
        } else {
          const double c = u[p] + (row - v[p]) * slope[k];
          lo = (std::min)(lo, c);
          hi = (std::max)(hi, c);
        }
      }
      // clamped to the grid before the conversions
      const long i_lo = long((std::min)(double(w_), (std::max)(0., std::ceil(lo))));
      const long i_hi = long((std::max)(-1., (std::min)(double(w_) - 1., std::floor(hi))));
      if(i_lo <= i_hi) span(std::size_t(row), std::size_t(i_lo), std::size_t(i_hi));
    }
  }

private:
  std::size_t w_, h_;
  double x0_, y1_, cell_x_, cell_y_;
};

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_TERRAIN_GRID_H

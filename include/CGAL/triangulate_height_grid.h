// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_TRIANGULATE_HEIGHT_GRID_H
#define CGAL_TRIANGULATE_HEIGHT_GRID_H

#include <CGAL/Penrose_Delaunay_triangulation_2.h>
#include <CGAL/Penrose_importance_sampler.h>
#include <CGAL/refine_terrain_by_greedy_insertion.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/named_parameters.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/Terrain_grid.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/Kernel_traits.h>
#include <CGAL/Named_function_parameters.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>

namespace CGAL {

/*!
\ingroup PkgPenroseDelaunayTriangulation2Ref

Triangulates a height grid, the heights of a terrain or the luminance of an
image, with few vertices for its error: samples a fraction of the vertices
with the Penrose sampler, uniformly, inserts the centres of the four corner
cells, so that every cell centre is covered, then inserts the centres of the
cells of largest vertical error one at a time with
`refine_terrain_by_greedy_insertion()` until the triangulation has
`number_of_points` vertices or every cell is within `max_error`, whichever
comes first. The blue-noise sample spreads the first vertices better than
greedy insertion would, which then puts the rest where the error is: with a
base of 5%, the RMS error is close to that of greedy insertion alone
(delatin's), in a fraction of its time.

\code
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
CGAL::Penrose_Delaunay_triangulation_2<CGAL::Projection_traits_xy_3<K>> dt;
CGAL::triangulate_height_grid(dt, width, height, heights, CGAL::Bbox_2(0, 0, width, height),
                              CGAL::parameters::number_of_points(20000));
CGAL::fit_terrain_heights(dt, width, height, heights, CGAL::Bbox_2(0, 0, width, height));  // optional
\endcode

The grid is that of `refine_terrain_by_greedy_insertion()`: `width x height`
cells over `region`, row after row from the top, cell (i, j) centred at
(xmin + (i + 1/2) dx, ymax - (j + 1/2) dy) with height `heights[j * width + i]`.
A sample takes the bilinear interpolation of the heights of the cell centres
around it; an inserted vertex is a cell centre with its height.

\tparam PDT a `Penrose_Delaunay_triangulation_2<Projection_traits_xy_3<K>, Tds>`.
\tparam HeightRange a random access range of values convertible to `double`.

\param dt the triangulation, cleared and built.
\param width, height the number of columns and rows of the grid.
\param heights the `width * height` heights.
\param region the rectangle that the grid covers.
\param np a sequence of named parameters among the following, with
  `number_of_points`, `max_error` or both:
  - `number_of_points(n)`: the number of vertices, at least 4, a `std::size_t`;
  - `max_error(e)`: the largest vertical error allowed, a positive `double`;
    alone, the sample is of a point per 1024 cells (at least 16);
  - `base_fraction(f)`: the fraction of `number_of_points` sampled, in (0, 1]
    (default 0.05); the sampler's count is about that, so that with the
    corners a small `number_of_points` may be exceeded, and nothing inserted;
  - `visitor(f)`: called as `f(v)` with the handle of each vertex created.

\returns what the greedy insertion did (the sample and the corners apart),
the largest error at the end and which bound stopped it.

\throws std::invalid_argument if the grid is empty or its size does not
match `heights`, a height is NaN or infinite, `region` is empty or not
finite, neither `number_of_points` nor `max_error` is given, or one of the
named parameters is out of its range. What the sampler, `dt.build()`,
`dt.insert()` and the visitor throw passes through.

\sa `refine_terrain_by_greedy_insertion()`, `fit_terrain_heights()`
*/
template <class PDT, class HeightRange, class NamedParameters>
Terrain_refinement_result triangulate_height_grid(PDT& dt, std::size_t width, std::size_t height,
                                                  const HeightRange& heights, const Bbox_2& region,
                                                  const NamedParameters& np)
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  using parameters::is_default_parameter;
  typedef typename PDT::Point Point;
  typedef typename Kernel_traits<Point>::Kernel K;
  const char* const name = "triangulate_height_grid";
  const internal::Penrose::Terrain_grid grid(width, height, heights, region, name);
  const bool bounded = !is_default_parameter<NamedParameters, Penrose_np::number_of_points_t>::value;
  const bool bound_error = !is_default_parameter<NamedParameters, Penrose_np::max_error_t>::value;
  const std::size_t n = choose_parameter(get_parameter(np, Penrose_np::number_of_points),
                                         (std::numeric_limits<std::size_t>::max)());
  const double e = choose_parameter(get_parameter(np, Penrose_np::max_error), 0.);
  const double f = choose_parameter(get_parameter(np, Penrose_np::base_fraction), 0.05);
  auto visitor = choose_parameter(get_parameter(np, internal_np::visitor), [](typename PDT::Vertex_handle) {});
  if(!bounded && !bound_error) throw std::invalid_argument(std::string(name) + ": give number_of_points, max_error or both");
  if(bounded && n < 4) throw std::invalid_argument(std::string(name) + ": number_of_points must be at least 4");
  if(bound_error && !(e > 0.)) throw std::invalid_argument(std::string(name) + ": max_error must be positive");
  if(!(f > 0. && f <= 1.)) throw std::invalid_argument(std::string(name) + ": base_fraction must be in (0, 1]");

  // without a count, sparse: greedy insertion needs the fewest vertices for a given error
  const std::size_t sampled = bounded ? (std::max)(std::size_t(1), std::size_t(std::llround(f * double(n))))
                                      : (std::max)(std::size_t(16), width * height / 1024);
  const Penrose_importance_sampler<K> sampler(
    typename K::Iso_rectangle_2(region.xmin(), region.ymin(), region.xmax(), region.ymax()),
    [](const typename K::Point_2&) { return 1.; }, parameters::number_of_output_points(sampled));
  const auto lift = [&](double x, double y) {
    return Point(x, y, grid.interpolate(heights, grid.u(typename K::Point_2(x, y)), grid.v(typename K::Point_2(x, y))));
  };
  dt.build(sampler, lift, [&](typename PDT::Vertex_handle v, const auto&) { visitor(v); });
  for(std::size_t j : {std::size_t(0), height - 1})
    for(std::size_t i : {std::size_t(0), width - 1}) {
      const std::size_t before = dt.number_of_vertices();
      const auto v = dt.insert(Point(grid.x(i), grid.y(j), double(heights[j * width + i])));
      if(dt.number_of_vertices() > before) visitor(v);
    }
  return refine_terrain_by_greedy_insertion(dt, width, height, heights, region,
                                            parameters::max_error(e, parameters::number_of_points(n, parameters::visitor(visitor))));
}

} // namespace CGAL

#endif // CGAL_TRIANGULATE_HEIGHT_GRID_H

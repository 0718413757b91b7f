// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_REFINE_TERRAIN_BY_GREEDY_INSERTION_H
#define CGAL_REFINE_TERRAIN_BY_GREEDY_INSERTION_H

#include <CGAL/Penrose_Delaunay_triangulation_2/named_parameters.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/Terrain_grid.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_utils.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <queue>
#include <stdexcept>
#include <vector>

namespace CGAL {

/// \ingroup PkgPenroseDelaunayTriangulation2Ref
/// What `refine_terrain_by_greedy_insertion()` did.
struct Terrain_refinement_result
{
  /// The number of vertices inserted.
  std::size_t number_of_inserted_points = 0;
  /// The largest vertical error over the cells covered by the triangulation at the end.
  double max_error = 0.;
  /// `true` if every covered cell is within the parameter `max_error` (the
  /// refinement stopped there), `false` if it stopped at `number_of_points`
  /// vertices before.
  bool max_error_reached = true;
};

namespace internal {
namespace Penrose {

// The greedy refinement: for each face, its worst cell in a priority queue;
// an insertion rescans only the faces it creates. The entry of a destroyed
// face is recognised when it comes out: its face is free, or holds other
// vertices (a face that insertion creates always holds the new vertex).
template <class DT, class HeightRange>
class Greedy_terrain_refinement
{
  typedef typename DT::Face_handle Face_handle;
  typedef typename DT::Vertex_handle Vertex_handle;
  typedef typename DT::Point Point;

  // The worst cell of a face when it was scanned.
  struct Entry
  {
    std::size_t cell;
    Face_handle face;
    Vertex_handle vertex[3];
  };

  // The queue holds the errors and where their entries are: the heap's
  // sifts, most of the cost of a step, then touch a third of the memory.
  struct Key
  {
    double error;
    std::size_t entry;
    bool operator<(const Key& k) const { return error < k.error; }
  };

public:
  Greedy_terrain_refinement(DT& dt, const Terrain_grid& grid, const HeightRange& heights)
    : dt_(dt), grid_(grid), heights_(heights), at_vertex_(grid.width() * grid.height(), 0)
  {}

  template <class Visitor>
  Terrain_refinement_result run(double max_error, std::size_t number_of_points, Visitor& visitor)
  {
    Terrain_refinement_result result;
    const double inf = std::numeric_limits<double>::infinity();
    if(dt_.dimension() == 2)
      for(Face_handle f : dt_.finite_face_handles()) scan(f, max_error);
    while(!queue_.empty()) {
      const Key top = queue_.top();
      const Entry e = entries_[top.entry];
      if(!current(e)) {
        pop();
        continue;
      }
      if(top.error <= max_error) break;
      if(dt_.number_of_vertices() >= number_of_points) {
        result.max_error_reached = false;
        break;
      }
      pop();
      const std::size_t i = e.cell % grid_.width(), j = e.cell / grid_.width();
      const Point p(grid_.x(i), grid_.y(j), double(heights_[e.cell]));
      const std::size_t before = dt_.number_of_vertices();
      const Vertex_handle v = dt_.insert(p, e.face);
      at_vertex_[e.cell] = 1;
      if(dt_.number_of_vertices() == before)
        v->set_point(p);  // a vertex at the cell's centre with another height: it takes the cell's
      else {
        ++result.number_of_inserted_points;
        visitor(v);
      }
      auto f = dt_.incident_faces(v), done = f;
      do
        if(!dt_.is_infinite(f)) scan(f, max_error);
      while(++f != done);
    }
    if(queue_.empty() || queue_.top().error <= max_error) {
      // the faces within the bound were not queued: the largest error is among them
      result.max_error = 0.;
      for(Face_handle f : dt_.finite_face_handles()) result.max_error = (std::max)(result.max_error, scan(f, inf));
    } else
      result.max_error = queue_.top().error;
    return result;
  }

private:
  // Whether the face of `e` still exists. (After a vertex took a cell's
  // height, see run(), the older entries of its faces look current too: at
  // worst one of them wastes an insertion, as the faces were scanned again.)
  bool current(const Entry& e) const
  {
    if(!dt_.tds().faces().is_used(e.face)) return false;
    for(int k = 0; k < 3; ++k)
      if(e.face->vertex(k) != e.vertex[k]) return false;
    return true;
  }

  // Returns the largest error of the finite face `f`, and queues its cell if
  // the error is above `queued_above`.
  double scan(Face_handle f, double queued_above)
  {
    double u[3], v[3], z[3];
    for(int k = 0; k < 3; ++k) {
      const Point& p = f->vertex(k)->point();
      u[k] = grid_.u(p);
      v[k] = grid_.v(p);
      z[k] = to_double(p.z());
    }
    // the linear interpolation of the heights, z[0] + a (u - u[0]) + b (v - v[0])
    const double d = (u[1] - u[0]) * (v[2] - v[0]) - (u[2] - u[0]) * (v[1] - v[0]);
    if(d == 0.) return 0.;  // no area in doubles: its cells are on its neighbours' edges
    const double a = ((z[1] - z[0]) * (v[2] - v[0]) - (z[2] - z[0]) * (v[1] - v[0])) / d;
    const double b = ((u[1] - u[0]) * (z[2] - z[0]) - (u[2] - u[0]) * (z[1] - z[0])) / d;
    double worst = 0.;
    std::size_t worst_cell = 0;
    grid_.for_each_row(u, v, [&](std::size_t row, std::size_t i_lo, std::size_t i_hi) {
      const std::size_t row_start = row * grid_.width();
      const double row_height = z[0] + b * (double(row) - v[0]);
      for(std::size_t i = i_lo; i <= i_hi; ++i) {
        const std::size_t cell = row_start + i;
        if(at_vertex_[cell]) continue;
        const double e = std::abs(row_height + a * (double(i) - u[0]) - double(heights_[cell]));
        if(e > worst) {
          worst = e;
          worst_cell = cell;
        }
      }
    });
    if(worst > queued_above) {
      const Entry e{worst_cell, f, {f->vertex(0), f->vertex(1), f->vertex(2)}};
      if(free_.empty()) {
        queue_.push({worst, entries_.size()});
        entries_.push_back(e);
      } else {
        queue_.push({worst, free_.back()});
        entries_[free_.back()] = e;
        free_.pop_back();
      }
    }
    return worst;
  }

  void pop()
  {
    free_.push_back(queue_.top().entry);
    queue_.pop();
  }

  DT& dt_;
  const Terrain_grid& grid_;
  const HeightRange& heights_;
  // The cells at a vertex with their height, whose error is 0: the plane
  // through a face, rounded, may miss it by an ulp, which inserting the
  // cell again would not cure.
  std::vector<unsigned char> at_vertex_;
  std::priority_queue<Key> queue_;
  std::vector<Entry> entries_;
  std::vector<std::size_t> free_;  // the entries that left the queue
};

} // namespace Penrose
} // namespace internal

/*!
\ingroup PkgPenroseDelaunayTriangulation2Ref

Refines the triangulation of a terrain by greedy insertion (Garland and
Heckbert's, as in delatin): inserts, one at a time, the centre of the grid
cell whose vertical error, the distance between its height and the linear
interpolation of the heights of the vertices of the face over it, is the
largest, until every cell is within `max_error` or the triangulation has
`number_of_points` vertices, whichever comes first.

The height grid has `width x height` cells over `region`, row after row from
the top (largest y), as in an image: cell (i, j) is centred at
(xmin + (i + 1/2) dx, ymax - (j + 1/2) dy), with dx and dy the size of a cell,
and its height is `heights[j * width + i]`. A cell inserted becomes a vertex
at its centre with its height. The triangulation is typically a
`Penrose_Delaunay_triangulation_2` built from samples of the grid, for
example with the density that `penrose_mesh --terrain` takes from its
curvature, and lifted to the heights of the grid. It stays a Delaunay
triangulation of its points. An image is a terrain too, its luminance (or
any channel) the heights: the refinement then makes a mesh that renders the
image back, as `penrose_mesh --reconstruct` does. `fit_terrain_heights()`
can follow, for a lower RMS error without the interpolation.

Each face keeps its worst cell in a priority queue; an insertion rescans only
the faces it creates, so the cost is that of the insertions plus a scan of
the cells under the new faces. The error is measured at every cell whose
centre a finite face covers (on an edge or vertex included); the others, outside
the convex hull, are neither measured nor inserted. A vertex already at the
centre of a cell whose error is still too large (a vertex of the
triangulation given, lifted to another height) takes the height of the cell.

\tparam DT a `Delaunay_triangulation_2<Projection_traits_xy_3<K>, Tds>` (a
        `Penrose_Delaunay_triangulation_2` over the same traits is one).
\tparam HeightRange a random access range of values convertible to `double`.

\param dt the triangulation refined.
\param width, height the number of columns and rows of the grid.
\param heights the `width * height` heights.
\param region the rectangle that the grid covers.
\param np an optional sequence of named parameters among:
  - `max_error(e)`: the largest vertical error allowed, a non-negative
    `double` (default 0: insert until the interpolation is exact at every
    cell covered);
  - `number_of_points(n)`: the most vertices the triangulation may have, a
    `std::size_t`, existing ones included (default: no limit);
  - `visitor(f)`: called as `f(v)` with the handle of each vertex inserted.

\returns what was inserted, the largest error at the end and which bound
stopped the refinement.

\throws std::invalid_argument if the grid is empty or its size does not
match `heights`, a height is NaN or infinite, `region` is empty or not
finite, or `max_error` is negative or NaN. The triangulation is then left
unchanged. What `dt.insert()` and the visitor throw passes through.

\sa `triangulate_height_grid()`, `fit_terrain_heights()`
*/
template <class DT, class HeightRange, class NamedParameters = parameters::Default_named_parameters>
Terrain_refinement_result refine_terrain_by_greedy_insertion(DT& dt, std::size_t width, std::size_t height,
                                                             const HeightRange& heights, const Bbox_2& region,
                                                             const NamedParameters& np = parameters::default_values())
{
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const double e = choose_parameter(get_parameter(np, Penrose_np::max_error), 0.);
  const std::size_t n = choose_parameter(get_parameter(np, Penrose_np::number_of_points),
                                         (std::numeric_limits<std::size_t>::max)());
  auto visitor = choose_parameter(get_parameter(np, internal_np::visitor), [](typename DT::Vertex_handle) {});
  const internal::Penrose::Terrain_grid grid(width, height, heights, region, "refine_terrain_by_greedy_insertion");
  if(!(e >= 0.)) throw std::invalid_argument("refine_terrain_by_greedy_insertion: max_error must be non-negative");
  internal::Penrose::Greedy_terrain_refinement<DT, HeightRange> refinement(dt, grid, heights);
  return refinement.run(e, n, visitor);
}

} // namespace CGAL

#endif // CGAL_REFINE_TERRAIN_BY_GREEDY_INSERTION_H

// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_FIT_TERRAIN_HEIGHTS_H
#define CGAL_FIT_TERRAIN_HEIGHTS_H

#include <CGAL/Penrose_Delaunay_triangulation_2/Terrain_grid.h>

#include <CGAL/Bbox_2.h>
#include <CGAL/Handle_hash_function.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <unordered_map>
#include <vector>

namespace CGAL {

/// \ingroup PkgPenroseDelaunayTriangulation2Ref
/// What `fit_terrain_heights()` did.
struct Terrain_fit_result
{
  /// The number of cells covered by the triangulation, over which the error is measured.
  std::size_t number_of_cells = 0;
  /// The root mean square vertical error over those cells before the fit.
  double rms_error_before = 0.;
  /// The same after the fit: at most `rms_error_before`.
  double rms_error_after = 0.;
  /// The conjugate gradient iterations taken.
  std::size_t number_of_iterations = 0;
};

namespace internal {
namespace Penrose {

// The least-squares problem of fit_terrain_heights(): minimise, over the
// heights z of the vertices, the sum over the covered cells c of
// (sum_k w_k(c) z_k - h_c)^2, w(c) the barycentric coordinates of c's centre
// in its face, plus pinning x (z - z0)^2 for each vertex, z0 its height
// before. The pinning keeps the vertices that the cells barely constrain (a
// vertex whose faces cover only cell centres at their other vertices, where
// its weight is 10^-17 of rounding) at their heights, instead of sending
// them to 10^17, and makes the problem definite; a cell's weight is at most
// 1, so the vertices with cells of their own hardly feel it. The normal
// equations A z = b are kept face by face, A the sum of the faces' 3 x 3
// blocks and of the pinning, which is all that conjugate gradients need.
template <class DT, class HeightRange>
class Terrain_height_fit
{
  typedef typename DT::Vertex_handle Vertex_handle;
  typedef typename DT::Point Point;

  struct Face
  {
    std::array<std::size_t, 3> vertex;
    double block[3][3];
  };

public:
  Terrain_height_fit(DT& dt, const Terrain_grid& grid, const HeightRange& heights)
    : dt_(dt), grid_(grid), heights_(heights)
  {
    std::unordered_map<Vertex_handle, std::size_t, Handle_hash_function> index;
    for(Vertex_handle v : dt_.finite_vertex_handles()) {
      index.emplace(v, vertices_.size());
      vertices_.push_back(v);
      z_.push_back(to_double(v->point().z()));
    }
    for(auto f : dt_.finite_face_handles()) {
      Face face;
      for(int k = 0; k < 3; ++k) face.vertex[k] = index[f->vertex(k)];
      faces_.push_back(face);
    }
  }

  Terrain_fit_result run()
  {
    const std::size_t n = vertices_.size();
    Terrain_fit_result result;
    std::vector<double> b(n, 0.), diagonal(n, pinning);
    double squares = 0.;
    for(Face& face : faces_)
      for(auto& row : face.block) row[0] = row[1] = row[2] = 0.;
    for_each_cell([&](Face& face, std::size_t cell, const double w[3]) {
      const double h = double(heights_[cell]);
      double e = -h;
      for(int k = 0; k < 3; ++k) {
        b[face.vertex[k]] += w[k] * h;
        e += w[k] * z_[face.vertex[k]];
        for(int l = 0; l < 3; ++l) face.block[k][l] += w[k] * w[l];
      }
      squares += e * e;
      ++result.number_of_cells;
    });
    if(result.number_of_cells == 0) return result;
    result.rms_error_before = std::sqrt(squares / double(result.number_of_cells));
    for(const Face& face : faces_)
      for(int k = 0; k < 3; ++k) diagonal[face.vertex[k]] += face.block[k][k];

    // Conjugate gradients with Jacobi's preconditioner, from the heights
    // given: every iterate lowers the error plus the pinning, which is 0 at
    // the start, so the fit can only improve on them. The pinning's part of
    // b, pinning x z0, cancels in the first residual b - A z0.
    std::vector<double> r = b, p(n), q(n), s(n);
    product(z_, q);
    for(std::size_t i = 0; i < n; ++i) {
      r[i] -= q[i] - pinning * z_[i];
      s[i] = r[i] / diagonal[i];
    }
    p = s;
    double rs = dot(r, s);
    const double tolerance = 1e-20 * dot(b, b);
    for(std::size_t it = 0; it < 1000 && dot(r, r) > tolerance; ++it) {
      product(p, q);
      const double pq = dot(p, q);
      if(!(pq > 0.)) break;
      const double alpha = rs / pq;
      for(std::size_t i = 0; i < n; ++i) {
        z_[i] += alpha * p[i];
        r[i] -= alpha * q[i];
        s[i] = r[i] / diagonal[i];
      }
      const double rs_next = dot(r, s);
      for(std::size_t i = 0; i < n; ++i) p[i] = s[i] + rs_next / rs * p[i];
      rs = rs_next;
      ++result.number_of_iterations;
    }

    squares = 0.;
    for_each_cell([&](Face& face, std::size_t cell, const double w[3]) {
      double e = -double(heights_[cell]);
      for(int k = 0; k < 3; ++k) e += w[k] * z_[face.vertex[k]];
      squares += e * e;
    });
    result.rms_error_after = std::sqrt(squares / double(result.number_of_cells));
    for(std::size_t i = 0; i < n; ++i) {
      const Point& p = vertices_[i]->point();
      vertices_[i]->set_point(Point(p.x(), p.y(), z_[i]));
    }
    return result;
  }

private:
  // Calls f(face, cell, w) once for each cell whose centre a face covers,
  // with its barycentric coordinates w in that face; a cell on an edge or a
  // vertex goes to the first face that covers it, so that it counts once.
  template <class F>
  void for_each_cell(F f)
  {
    std::vector<bool> seen(grid_.width() * grid_.height(), false);
    auto face = faces_.begin();
    for(auto fh : dt_.finite_face_handles()) {
      double u[3], v[3];
      for(int k = 0; k < 3; ++k) {
        u[k] = grid_.u(fh->vertex(k)->point());
        v[k] = grid_.v(fh->vertex(k)->point());
      }
      const double d = (u[1] - u[0]) * (v[2] - v[0]) - (u[2] - u[0]) * (v[1] - v[0]);
      if(d != 0.)  // else no area in doubles: its cells are on its neighbours' edges
        grid_.for_each_row(u, v, [&](std::size_t row, std::size_t i_lo, std::size_t i_hi) {
          for(std::size_t i = i_lo; i <= i_hi; ++i) {
            const std::size_t cell = row * grid_.width() + i;
            if(seen[cell]) continue;
            seen[cell] = true;
            double w[3];
            w[1] = ((double(i) - u[0]) * (v[2] - v[0]) - (u[2] - u[0]) * (double(row) - v[0])) / d;
            w[2] = ((u[1] - u[0]) * (double(row) - v[0]) - (double(i) - u[0]) * (v[1] - v[0])) / d;
            w[0] = 1. - w[1] - w[2];
            f(*face, cell, w);
          }
        });
      ++face;
    }
  }

  // y = A x
  void product(const std::vector<double>& x, std::vector<double>& y) const
  {
    for(std::size_t i = 0; i < x.size(); ++i) y[i] = pinning * x[i];
    for(const Face& face : faces_)
      for(int k = 0; k < 3; ++k)
        for(int l = 0; l < 3; ++l) y[face.vertex[k]] += face.block[k][l] * x[face.vertex[l]];
  }

  static double dot(const std::vector<double>& x, const std::vector<double>& y)
  {
    double s = 0.;
    for(std::size_t i = 0; i < x.size(); ++i) s += x[i] * y[i];
    return s;
  }

  static constexpr double pinning = 1e-6;
  DT& dt_;
  const Terrain_grid& grid_;
  const HeightRange& heights_;
  std::vector<Vertex_handle> vertices_;
  std::vector<double> z_;    // the heights of vertices_
  std::vector<Face> faces_;  // in the order of dt_.finite_face_handles()
};

} // namespace Penrose
} // namespace internal

/*!
\ingroup PkgPenroseDelaunayTriangulation2Ref

Gives the vertices of the triangulation of a terrain the heights that
minimise the squared vertical error over the cells of a height grid: the sum,
over every cell whose centre a finite face covers, of the squared difference
between the cell's height and the linear interpolation of the heights of the
vertices of the face over it (a least-squares fit, one unknown per vertex).
The root mean square error drops, but the surface no longer interpolates the
grid at the vertices, and the largest error may grow: call it after
`refine_terrain_by_greedy_insertion()`, whose `max_error` bound it does not
keep. The triangulation, a triangulation of the points' x and y, is unchanged.

The grid is that of `refine_terrain_by_greedy_insertion()`: `width x height`
cells over `region`, row after row from the top, cell (i, j) centred at
(xmin + (i + 1/2) dx, ymax - (j + 1/2) dy) with height `heights[j * width + i]`.
A cell on an edge or a vertex counts once. The normal equations, sparse, are
solved by conjugate gradients with Jacobi's preconditioner from the heights
given, each iteration lowering the error, until the residual is 10^-10 of the
right-hand side or for 1000 iterations (a few tens suffice on meshes of
terrains). A vertex that no cell constrains (its faces cover no cell
centre, or only those at their other vertices) keeps its height: each vertex
is pinned to its height by a weight of 10^-6, where a cell weighs up to 1.

\tparam DT a `Delaunay_triangulation_2<Projection_traits_xy_3<K>, Tds>` (a
        `Penrose_Delaunay_triangulation_2` over the same traits is one), or
        any `Triangulation_2` over those traits.
\tparam HeightRange a random access range of values convertible to `double`.

\param dt the triangulation whose heights are fitted.
\param width, height the number of columns and rows of the grid.
\param heights the `width * height` heights.
\param region the rectangle that the grid covers.

\returns the number of cells covered, the RMS error before and after the
fit, and the iterations taken.

\throws std::invalid_argument if the grid is empty or its size does not
match `heights`, a height is NaN or infinite, or `region` is empty or not
finite. The triangulation is then left unchanged.

\sa `triangulate_height_grid()`, `refine_terrain_by_greedy_insertion()`
*/
template <class DT, class HeightRange>
Terrain_fit_result fit_terrain_heights(DT& dt, std::size_t width, std::size_t height, const HeightRange& heights,
                                       const Bbox_2& region)
{
  const internal::Penrose::Terrain_grid grid(width, height, heights, region, "fit_terrain_heights");
  internal::Penrose::Terrain_height_fit<DT, HeightRange> fit(dt, grid, heights);
  return fit.run();
}

} // namespace CGAL

#endif // CGAL_FIT_TERRAIN_HEIGHTS_H

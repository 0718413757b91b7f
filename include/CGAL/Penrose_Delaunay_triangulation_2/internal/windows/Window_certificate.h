// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Whether a window's mesh holds, over a domain, the triangles of the
// Delaunay triangulation of all the region's samples.
//
// The mesh is the framed triangulation of the samples Q in the grown window
// G. For a point x of the domain D, let rho(x) be its distance to the
// nearest vertex of the mesh. If the disk of radius rho(x) around every x
// of D stays inside G (its sides inside the region, that is: beyond the
// region's border there is no sample), no sample outside G is nearer to x
// than that vertex, so that the Voronoi diagram of all the samples
// coincides with the mesh's over D, and so do the triangles whose
// circumcentres (the Voronoi vertices) lie in D; the mesh's vertices that
// are not samples (the frame) must have no cell in D either.
//
// rho(x) minus the distance from x to a side of G is convex over each
// Voronoi cell cut by D, so that it is largest at a vertex of such a piece:
// a Voronoi vertex in D (a circumcentre), a point where a Voronoi edge (the
// segment between the circumcentres of the two triangles of an edge)
// crosses the boundary of D, or a corner of D. Those points are checked,
// with a relative slack for the rounding of the centres.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_WINDOW_CERTIFICATE_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_WINDOW_CERTIFICATE_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/flat_mesh/Flat_mesh.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/windows/Canonical_circumcircle.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/windows/Window_mesh.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace internal {
namespace Penrose {

struct Box
{
  double x0, y0, x1, y1;

  bool contains(double x, double y) const { return x >= x0 && x <= x1 && y >= y0 && y <= y1; }
};

// The grown window G, with the sides that lie inside the region: only
// those bound the disks.
struct Bounding_window
{
  Box box;
  bool inner_left, inner_bottom, inner_right, inner_top;
  double tolerance;  // absolute, for the rounding of the coordinates

  bool bounds_nothing() const { return !(inner_left || inner_bottom || inner_right || inner_top); }

  // Whether the disk of radius r around (x, y) stays inside, with slack.
  bool holds_disk(double x, double y, double r) const
  {
    const double s = 1e-9 * r + tolerance;
    return (!inner_left || x - r > box.x0 + s) && (!inner_right || x + r < box.x1 - s) &&
           (!inner_bottom || y - r > box.y0 + s) && (!inner_top || y + r < box.y1 - s);
  }
};

class Window_certificate
{
  typedef Flat_mesh::Index Index;

public:
  Window_certificate(const Window_mesh& w, const Box& domain, const Bounding_window& g)
    : w_(w), m_(w.mesh), d_(domain), g_(g)
  {}

  // The circumcircles of the mesh's faces, by face (unset for dead ones).
  const std::vector<Circumcircle>& circles()
  {
    if(circles_.empty()) {
      circles_.resize(m_.faces.size());
      for(Index f = 0; f < m_.faces.size(); ++f)
        if(m_.face_alive[f]) circles_[f] = circle_of(f);
    }
    return circles_;
  }

  bool holds()
  {
    circles();
    return voronoi_vertices_hold() && voronoi_edges_hold() && corners_hold();
  }

private:
  Circumcircle circle_of(Index f) const
  {
    const auto& v = m_.faces[f].v;
    auto p = [&](int i) { return Xy{m_.points[v[i]].x(), m_.points[v[i]].y()}; };
    return canonical_circumcircle(p(0), p(1), p(2));
  }

  bool samples_only(Index f) const
  {
    for(Index v : m_.faces[f].v)
      if(!w_.is_sample[v]) return false;
    return true;
  }

  bool near_window(Index f) const
  {
    for(Index v : m_.faces[f].v)
      if(w_.is_sample[v] && g_.box.contains(m_.points[v].x(), m_.points[v].y())) return true;
    return false;
  }

  bool voronoi_vertices_hold() const
  {
    for(Index f = 0; f < m_.faces.size(); ++f) {
      if(!m_.face_alive[f]) continue;
      const Circumcircle& c = circles_[f];
      if(!c.is_finite()) {
        if(near_window(f)) return false;
        continue;
      }
      if(!d_.contains(c.x, c.y)) continue;
      if(!samples_only(f) || !g_.holds_disk(c.x, c.y, c.radius)) return false;
    }
    return true;
  }

  // Each edge between two faces once, from the face of larger index.
  bool voronoi_edges_hold() const
  {
    for(Index f = 0; f < m_.faces.size(); ++f) {
      if(!m_.face_alive[f]) continue;
      for(int i = 0; i < 3; ++i) {
        const Index g = m_.faces[f].n[i];
        if(g == Flat_mesh::null || g > f) continue;
        const Circumcircle &a = circles_[f], &b = circles_[g];
        if(!a.is_finite() || !b.is_finite()) continue;  // judged with the vertices
        if((std::max)(a.x, b.x) < d_.x0 || (std::min)(a.x, b.x) > d_.x1 ||
           (std::max)(a.y, b.y) < d_.y0 || (std::min)(a.y, b.y) > d_.y1)
          continue;
        const Index u = m_.faces[f].v[Flat_mesh::ccw(i)], v = m_.faces[f].v[Flat_mesh::cw(i)];
        bool crossed = false, held = true;
        for_each_crossing(a, b, [&](double x, double y) {
          crossed = true;
          const double r = std::hypot(x - m_.points[u].x(), y - m_.points[u].y());
          held = held && g_.holds_disk(x, y, r);
        });
        if(crossed && (!held || !w_.is_sample[u] || !w_.is_sample[v])) return false;
      }
    }
    return true;
  }

  // Calls f(x, y) at the points where the segment from a to b meets the
  // boundary of the domain (both ends of a part that runs along it).
  template <class F>
  void for_each_crossing(const Circumcircle& a, const Circumcircle& b, const F& f) const
  {
    auto on_vertical = [&](double X) {
      if(a.x == X && b.x == X) {
        for(double y : {a.y, b.y}) f(X, (std::min)((std::max)(y, d_.y0), d_.y1));
      } else if((a.x - X) * (b.x - X) <= 0.) {
        const double y = a.y + (X - a.x) / (b.x - a.x) * (b.y - a.y);
        if(y >= d_.y0 && y <= d_.y1) f(X, y);
      }
    };
    auto on_horizontal = [&](double Y) {
      if(a.y == Y && b.y == Y) {
        for(double x : {a.x, b.x}) f((std::min)((std::max)(x, d_.x0), d_.x1), Y);
      } else if((a.y - Y) * (b.y - Y) <= 0.) {
        const double x = a.x + (Y - a.y) / (b.y - a.y) * (b.x - a.x);
        if(x >= d_.x0 && x <= d_.x1) f(x, Y);
      }
    };
    on_vertical(d_.x0); on_vertical(d_.x1);
    on_horizontal(d_.y0); on_horizontal(d_.y1);
  }

  bool corners_hold() const
  {
    for(double x : {d_.x0, d_.x1})
      for(double y : {d_.y0, d_.y1}) {
        double best = std::numeric_limits<double>::infinity();
        Index nearest = Flat_mesh::null;
        for(Index v = 0; v < m_.points.size(); ++v) {
          if(m_.vertex_face[v] == Flat_mesh::null) continue;
          const double dx = x - m_.points[v].x(), dy = y - m_.points[v].y();
          if(dx * dx + dy * dy < best) { best = dx * dx + dy * dy; nearest = v; }
        }
        if(nearest == Flat_mesh::null || !w_.is_sample[nearest] || !g_.holds_disk(x, y, std::sqrt(best))) return false;
      }
    return true;
  }

  const Window_mesh& w_;
  const Flat_mesh& m_;
  Box d_;
  Bounding_window g_;
  std::vector<Circumcircle> circles_;
};

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_WINDOW_CERTIFICATE_H

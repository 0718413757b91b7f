// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Refinement of the triangles that touch the border of a rectangle until
// none has an angle under 15 degrees: Ruppert's algorithm, restricted to
// them. Greedy insertion puts vertices wherever the error is, a cell's width
// from the border as well, and no rule on where the samples and the border
// points lie keeps such vertices from making slivers with the border.

#ifndef PENROSE_TOOLS_BORDER_REFINEMENT_H
#define PENROSE_TOOLS_BORDER_REFINEMENT_H

#include "border_points.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <set>
#include <vector>

namespace penrose_tools {

// The smallest angle that the triangles touching the border keep: below
// Ruppert's bound of 20.7 degrees, under which the refinement terminates.
constexpr double smallest_border_angle_degrees = 15.;

/*
Refines the Delaunay triangulation `t`, whose convex hull is the rectangle
region = {x0, y0, x1, y1} with a vertex at each corner, until every
triangle with a vertex on the border has angles of at least
smallest_border_angle_degrees. A bad triangle's circumcentre is inserted,
unless it lies outside the rectangle or encroaches upon a border edge (lies
in its diametral circle): that edge is then split at its midpoint instead,
if its side may be split (`splittable[s]`, sides s in the order bottom,
right, top, left); a triangle that could only be mended by splitting a side
that may not be is left as it is. Inserts `lift(x, y)` and calls
`added(v)` for each new vertex v; returns their number, at most the number
of vertices of `t` (a bound that Ruppert's termination leaves far).
*/
template <class DT, class Lift, class Added>
std::size_t refine_border_triangles(DT& t, const std::array<double, 4>& region, const std::array<bool, 4>& splittable,
                                    const Lift& lift, Added added)
{
  typedef typename DT::Face_handle Face_handle;
  typedef typename DT::Vertex_handle Vertex_handle;
  const double x0 = region[0], y0 = region[1], x1 = region[2], y1 = region[3];
  // the vertices on each side, by their abscissa (bottom, top) or ordinate (right, left)
  std::array<std::set<double>, 4> side;
  auto on_side = [&](double x, double y, int s) {
    return s == 0 ? y == y0 : s == 1 ? x == x1 : s == 2 ? y == y1 : x == x0;
  };
  auto position = [](double x, double y, int s) { return s % 2 == 0 ? x : y; };
  for(auto v : t.finite_vertex_handles()) {
    const double x = v->point().x(), y = v->point().y();
    for(int s = 0; s < 4; ++s)
      if(on_side(x, y, s)) side[std::size_t(s)].insert(position(x, y, s));
  }
  auto on_border = [&](Vertex_handle v) { return is_on_border(region, v->point().x(), v->point().y()); };
  // (2 area)^2 < sin^2 of the bound times the product of the two longer edges' squared lengths
  const double sine = std::sin(smallest_border_angle_degrees * 3.14159265358979323846 / 180.);
  auto bad = [&](Face_handle f) {
    if(t.is_infinite(f) || !(on_border(f->vertex(0)) || on_border(f->vertex(1)) || on_border(f->vertex(2))))
      return false;
    double l[3];
    for(int i = 0; i < 3; ++i) {
      const auto &p = f->vertex((i + 1) % 3)->point(), &q = f->vertex((i + 2) % 3)->point();
      l[i] = (q.x() - p.x()) * (q.x() - p.x()) + (q.y() - p.y()) * (q.y() - p.y());
    }
    std::sort(l, l + 3);
    const auto &a = f->vertex(0)->point(), &b = f->vertex(1)->point(), &c = f->vertex(2)->point();
    const double twice_area = (b.x() - a.x()) * (c.y() - a.y()) - (c.x() - a.x()) * (b.y() - a.y());
    return twice_area * twice_area < sine * sine * l[1] * l[2];
  };
  struct Item
  {
    Face_handle f;
    Vertex_handle v[3];
  };
  std::vector<Item> queue;
  auto push_if_bad = [&](Face_handle f) {
    if(bad(f)) queue.push_back({f, {f->vertex(0), f->vertex(1), f->vertex(2)}});
  };
  for(Face_handle f : t.finite_face_handles()) push_if_bad(f);
  auto current = [&](const Item& e) {
    if(!t.tds().faces().is_used(e.f)) return false;
    for(int k = 0; k < 3; ++k)
      if(e.f->vertex(k) != e.v[k]) return false;
    return true;
  };
  auto insert = [&](double x, double y, Face_handle hint) {
    const std::size_t before = t.number_of_vertices();
    const Vertex_handle v = t.insert(lift(x, y), hint);
    if(t.number_of_vertices() == before) return false;
    added(v);
    auto f = t.incident_faces(v), done = f;
    do push_if_bad(f);
    while(++f != done);
    return true;
  };
  const std::size_t limit = t.number_of_vertices();
  std::size_t inserted = 0;
  while(!queue.empty() && inserted < limit) {
    const Item e = queue.back();
    queue.pop_back();
    if(!current(e)) continue;
    const auto &a = e.f->vertex(0)->point(), &b = e.f->vertex(1)->point(), &c = e.f->vertex(2)->point();
    // the circumcentre, relative to a for accuracy
    const double bx = b.x() - a.x(), by = b.y() - a.y(), cx = c.x() - a.x(), cy = c.y() - a.y();
    const double d = 2. * (bx * cy - by * cx);
    if(d == 0.) continue;
    const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
    const double ux = a.x() + (cy * b2 - by * c2) / d, uy = a.y() + (bx * c2 - cx * b2) / d;
    // a side whose edge the circumcentre encroaches upon, or lies beyond
    int split = -1;
    double from = 0., to = 0.;
    for(int s = 0; s < 4 && split < 0; ++s) {
      const double inward = s == 0 ? uy - y0 : s == 1 ? x1 - ux : s == 2 ? y1 - uy : ux - x0;
      const std::set<double>& p = side[std::size_t(s)];
      const double lo = *p.begin(), hi = *p.rbegin();
      const double foot = (std::min)(hi, (std::max)(lo, s % 2 == 0 ? ux : uy));
      auto next = p.upper_bound(foot);
      if(next == p.end()) --next;
      const double q1 = *next, q0 = *std::prev(next);
      const double along = s % 2 == 0 ? ux : uy;
      // (u - q0) . (u - q1) < 0, u in the side's coordinates (along, inward)
      if(inward <= 0. || (along - q0) * (along - q1) + inward * inward < 0.) {
        split = s;
        from = q0;
        to = q1;
      }
    }
    if(split < 0) {
      inserted += insert(ux, uy, e.f);
      continue;
    }
    const double mid = from + 0.5 * (to - from);
    if(!splittable[std::size_t(split)] || !(mid > from && mid < to)) continue;
    const double mx = split == 1 ? x1 : split == 3 ? x0 : mid, my = split == 0 ? y0 : split == 2 ? y1 : mid;
    if(insert(mx, my, e.f)) {
      ++inserted;
      side[std::size_t(split)].insert(mid);
      if(current(e)) queue.push_back(e);
    }
  }
  return inserted;
}

} // namespace penrose_tools

#endif // PENROSE_TOOLS_BORDER_REFINEMENT_H

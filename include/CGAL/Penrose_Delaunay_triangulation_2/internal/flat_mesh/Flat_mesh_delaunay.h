// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Lawson flips on a Flat_mesh until every edge is locally Delaunay, with
// exact predicates on the double coordinates (Fast_predicates, then Epick's)
// and the symbolic perturbation of
// Triangulation_2::side_of_oriented_circle(..., true): the flips end in
// exactly the triangulation that Delaunay_triangulation_2 builds from the
// same points, cocircular points included.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_FLAT_MESH_DELAUNAY_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_FLAT_MESH_DELAUNAY_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/flat_mesh/Fast_predicates.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/flat_mesh/Flat_mesh.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <boost/config.hpp>

#include <algorithm>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace internal {
namespace Penrose {

// Triangulation_2::side_of_oriented_circle(p0, p1, p2, p, true), restated.
inline Oriented_side perturbed_side_of_oriented_circle(const Epick::Point_2& p0, const Epick::Point_2& p1,
                                                       const Epick::Point_2& p2, const Epick::Point_2& p)
{
  const Sign filtered = filtered_in_circle(p0.x(), p0.y(), p1.x(), p1.y(), p2.x(), p2.y(), p.x(), p.y());
  if(filtered != ZERO) return Oriented_side(filtered);
  const Oriented_side os = Epick::Side_of_oriented_circle_2()(p0, p1, p2, p);
  if(os != ON_ORIENTED_BOUNDARY) return os;
  const Epick::Point_2* points[4] = {&p0, &p1, &p2, &p};
  std::sort(points, points + 4, [](const Epick::Point_2* a, const Epick::Point_2* b) {
    return Epick::Compare_xy_2()(*a, *b) == SMALLER;
  });
  const Epick::Orientation_2 orientation;
  for(int i = 3; i > 0; --i) {
    if(points[i] == &p) return ON_NEGATIVE_SIDE;
    Orientation o;
    if(points[i] == &p2 && (o = orientation(p0, p1, p)) != COLLINEAR) return Oriented_side(o);
    if(points[i] == &p1 && (o = orientation(p0, p, p2)) != COLLINEAR) return Oriented_side(o);
    if(points[i] == &p0 && (o = orientation(p, p1, p2)) != COLLINEAR) return Oriented_side(o);
  }
  return ON_NEGATIVE_SIDE;
}

// Whether the vertex opposite edge i of face f is strictly inside the
// circle of the face across, which must exist, as Triangulation_2 decides
// it: the points in the order of the face across. Out of line: the flips'
// rare path, which, inlined, took registers and code space from the common
// one and made the flips slower.
BOOST_NOINLINE inline bool is_in_circle_across(const Flat_mesh& m, Flat_mesh::Index f, int i)
{
  const Flat_mesh::Face& G = m.faces[m.faces[f].n[i]];
  return perturbed_side_of_oriented_circle(m.points[G.v[0]], m.points[G.v[1]], m.points[G.v[2]],
                                           m.points[m.faces[f].v[i]]) == ON_POSITIVE_SIDE;
}

// Whether edge i of face f is not locally Delaunay, that is, the same
// test, filtered first on f's vertices, which the walks have at hand, and
// the one vertex across, instead of the three of the face across.
inline bool is_flippable(const Flat_mesh& m, Flat_mesh::Index f, int i)
{
  const Flat_mesh::Face& F = m.faces[f];
  const Flat_mesh::Point& a = m.points[F.v[i]];
  const Flat_mesh::Point& b = m.points[F.v[Flat_mesh::ccw(i)]];
  const Flat_mesh::Point& c = m.points[F.v[Flat_mesh::cw(i)]];
  const Flat_mesh::Point& d = m.points[m.faces[F.n[i]].v[m.index_of_neighbor(F.n[i], f)]];
  // the face across is (d, c, b), up to a rotation, which changes no sign
  const Sign filtered = filtered_in_circle(d.x(), d.y(), c.x(), c.y(), b.x(), b.y(), a.x(), a.y());
  return filtered != ZERO ? filtered == POSITIVE : is_in_circle_across(m, f, i);
}

// An edge to test, as face * 4 + index, in one word: an edge is most often
// popped right after it is pushed, and a load wider than the stores it reads
// (a pair's two halves) would wait for them to retire.
typedef std::uint64_t Suspect_edge;

// Flips edge i of face f, which is not locally Delaunay, and then every edge
// that this makes suspect, depth first. Returns the number of flips. An
// edge one of whose faces comes after face `sweep` is left to the sweep of
// make_delaunay(), which tests it when it reaches the last of them. Out of
// line: inlined into the sweep, it made the sweep's common path (an edge
// tested, not flipped) much slower, and the flips themselves no faster.
BOOST_NOINLINE inline std::size_t flip_from(Flat_mesh& m, Flat_mesh::Index f0, int i0,
                                            Flat_mesh::Index sweep,
                                            std::vector<Suspect_edge>& stack)
{
  typedef Flat_mesh::Index Index;
  std::size_t flips = 0;
  auto flip = [&](Index f, int i) {
    const Index g = m.faces[f].n[i];
    m.flip(f, i);  // f = (a, b, c), g = (d, c, b) become (a, b, d), (a, d, c)
    ++flips;
    for(const auto& [h, k] : {std::make_pair(f, 0), std::make_pair(f, 2), std::make_pair(g, 0), std::make_pair(g, 1)}) {
      const Index across = m.faces[h].n[k];
      if(across != Flat_mesh::null && h <= sweep && across <= sweep) stack.push_back(Suspect_edge(h) << 2 | Suspect_edge(k));
    }
  };
  flip(f0, i0);
  while(!stack.empty()) {
    const Index f = Index(stack.back() >> 2);
    const int i = int(stack.back() & 3);
    stack.pop_back();
    if(m.faces[f].n[i] != Flat_mesh::null && is_flippable(m, f, i)) flip(f, i);
  }
  return flips;
}

// Flips until Delaunay; returns the number of flips. The faces are swept in
// memory order, each edge tested from its last face, and each flip's
// consequences are settled at once: an edge can only stop being locally
// Delaunay when one of its faces changes, and then it is either on the
// stack or still ahead of the sweep. Tested from its last face rather than
// its first, an edge reads a face across that the sweep has passed, often
// still in the caches, and fewer edges go through the stack; the
// triangulation is the same.
inline std::size_t make_delaunay(Flat_mesh& m)
{
  typedef Flat_mesh::Index Index;
  constexpr Index ahead = Flat_mesh::fetch_distance;
  std::vector<Suspect_edge> stack;
  std::size_t flips = 0;
  const Index nf = Index(m.faces.size());
  for(Index f = 0; f < nf; ++f) {
    // The walk is bound by memory, not by the predicates: fetch what the
    // test of the edges of a face ahead reads, in two steps (the faces across
    // and the face's vertices, then, once those faces are in, the vertices
    // across and the two faces beyond each edge, which its flip updates).
    if(f + 2 * ahead < nf) {
      const Flat_mesh::Face& F = m.faces[f + 2 * ahead];
      for(int i = 0; i < 3; ++i) {
        CGAL_PENROSE_PREFETCH(&m.points[F.v[i]]);
        if(F.n[i] != Flat_mesh::null) CGAL_PENROSE_PREFETCH(&m.faces[F.n[i]]);
      }
    }
    if(f + ahead < nf) {
      const Index h = f + ahead;
      const Flat_mesh::Face& F = m.faces[h];
      for(int i = 0; i < 3; ++i)
        if(const Index g = F.n[i]; g != Flat_mesh::null && g < h) {
          const Flat_mesh::Face& G = m.faces[g];
          const int j = m.index_of_neighbor(g, h);
          CGAL_PENROSE_PREFETCH(&m.points[G.v[j]]);
          for(int k : {Flat_mesh::ccw(j), Flat_mesh::cw(j)})
            if(G.n[k] != Flat_mesh::null) CGAL_PENROSE_PREFETCH(&m.faces[G.n[k]]);
        }
    }
    if(!m.face_alive[f]) continue;
    // tested here, not through the stack: most edges do not flip
    for(int i = 0; i < 3; ++i) {
      const Index g = m.faces[f].n[i];
      if(g != Flat_mesh::null && g < f && is_flippable(m, f, i)) flips += flip_from(m, f, i, f, stack);
    }
  }
  return flips;
}

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_FLAT_MESH_DELAUNAY_H

// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A triangle mesh in flat arrays, with CGAL's conventions (vertices counter-
// clockwise; neighbour i opposite vertex i), on which the base triangulation
// is built and edited before it is written once into a TDS. Orientation tests
// are exact on the double coordinates (Fast_predicates, then Epick).

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_FLAT_MESH_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_FLAT_MESH_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/flat_mesh/Fast_predicates.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/assertions.h>
#include <CGAL/use.h>

#include <array>
#include <cstdint>
#include <utility>
#include <vector>

// Walks over a flat mesh are bound by memory: they fetch what they will
// read a few steps ahead. A macro, not a function: GCC deletes calls to a
// function whose only effect is a prefetch.
#if defined(__GNUC__)
#  define CGAL_PENROSE_PREFETCH(p) __builtin_prefetch(p)
#else
#  define CGAL_PENROSE_PREFETCH(p) ((void)(p))
#endif

namespace CGAL {
namespace internal {
namespace Penrose {

class Flat_mesh
{
public:
  typedef std::uint32_t Index;
  typedef Exact_predicates_inexact_constructions_kernel::Point_2 Point;
  static constexpr Index null = 0xffffffffu;
  // how many elements ahead a walk in memory order fetches what it will read
  // (16 is too short for the fetches to arrive in time, mostly in writing
  // the TDS; 24 to 48 do about as well as 32)
  static constexpr Index fetch_distance = 32;

  struct Face
  {
    typedef std::array<Index, 3> Indices;
    // left as it is: every face is written (reset_face()) before it is read,
    // and zeroing the last level's appended faces would be a walk for nothing
    Face() {}
    Indices v;
    Indices n;
  };

  static int ccw(int i) { return i == 2 ? 0 : i + 1; }
  static int cw(int i) { return i == 0 ? 2 : i - 1; }

  // vertices, their coordinates in one array for locality
  std::vector<Point> points;
  std::vector<Index> vertex_face;  // one incident face, or null for a removed vertex

  std::vector<Face> faces;
  std::vector<char> face_alive;

  // the faces alive
  std::size_t number_of_faces() const { return faces.size() - free_.size(); }

  Index add_vertex(double px, double py)
  {
    points.emplace_back(px, py); vertex_face.push_back(null);
    return Index(points.size() - 1);
  }

  // A face, alive, to be written with reset_face().
  Index new_face()
  {
    if(free_.empty()) {
      faces.emplace_back();
      face_alive.push_back(1);
      return Index(faces.size() - 1);
    }
    const Index f = free_.back();
    free_.pop_back();
    face_alive[f] = 1;
    return f;
  }

  Index create_face(Index a, Index b, Index c)
  {
    const Index f = new_face();
    reset_face(f, a, b, c);
    return f;
  }

  // Appends `count` faces, alive, to be written with reset_face(); returns
  // the first.
  Index append_faces(std::size_t count)
  {
    const Index first = Index(faces.size());
    faces.resize(faces.size() + count);
    face_alive.resize(face_alive.size() + count, 1);
    return first;
  }

  // Overwrites face f in place with new vertices (keeps it alive, clears its neighbours).
  void reset_face(Index f, Index a, Index b, Index c)
  {
    faces[f].v = {{a, b, c}};
    faces[f].n = {{null, null, null}};
    vertex_face[a] = vertex_face[b] = vertex_face[c] = f;
  }

  void delete_face(Index f)
  {
    face_alive[f] = 0;
    free_.push_back(f);
  }

  void link(Index f, int i, Index g, int j)
  {
    faces[f].n[i] = g;
    if(g != null) faces[g].n[j] = f;
  }

  // Face f takes over g (or null) as its neighbour i from face `old`.
  void inherit_neighbor(Index f, int i, Index g, Index old)
  {
    faces[f].n[i] = g;
    if(g != null) faces[g].n[index_of_neighbor(g, old)] = f;
  }

  int index_of_vertex(Index f, Index v) const
  {
    const Face& F = faces[f];
    return F.v[0] == v ? 0 : (F.v[1] == v ? 1 : 2);
  }

  // The next face around vertex v from its face f: counter-clockwise
  // across the edge of f that ends at v, clockwise across the one that
  // leaves it; null past the boundary.
  Index ccw_face_around(Index f, Index v) const { return faces[f].n[ccw(index_of_vertex(f, v))]; }
  Index cw_face_around(Index f, Index v) const { return faces[f].n[cw(index_of_vertex(f, v))]; }

  // The boundary edge that leaves vertex b, on the mesh's boundary, as
  // (face, edge index): the faces around b turned clockwise until there is
  // nothing across.
  std::pair<Index, int> boundary_edge_from(Index b) const
  {
    Index f = vertex_face[b];
    for(Index g = cw_face_around(f, b); g != null; g = cw_face_around(f, b)) f = g;
    return {f, cw(index_of_vertex(f, b))};
  }

  int index_of_neighbor(Index f, Index g) const
  {
    const Face& F = faces[f];
    return F.n[0] == g ? 0 : (F.n[1] == g ? 1 : 2);
  }

  // The edge of face f from vertex a to vertex b, which must be one of its
  // edges, as the index of the opposite vertex.
  int edge_index(Index f, Index a, Index b) const
  {
    const int i = cw(index_of_vertex(f, a));
    CGAL_assertion(faces[f].v[ccw(i)] == a && faces[f].v[cw(i)] == b);
    CGAL_USE(b);
    return i;
  }

  Orientation orientation(Index a, Index b, Index c) const { return orientation(a, b, points[c]); }

  Orientation orientation(Index a, Index b, const Point& p) const
  {
    const Point& q = points[a];
    const Point& r = points[b];
    const Sign filtered = filtered_orientation(q.x(), q.y(), r.x(), r.y(), p.x(), p.y());
    return filtered != ZERO ? filtered : Exact_predicates_inexact_constructions_kernel::Orientation_2()(q, r, p);
  }

  // Splits face f at vertex m, which lies on its edge i (opposite vertex i):
  // f keeps one half, a new face takes the other. Returns the new face, which
  // holds the part of the edge next to vertex cw(i).
  Index split_face_on_edge(Index f, int i, Index m) { return split_face_on_edge(f, i, m, new_face()); }

  // The same, with g, a live face whose content is dead, as the new face.
  Index split_face_on_edge(Index f, int i, Index m, Index g)
  {
    const Face F = faces[f];
    const Index apex = F.v[i], a = F.v[ccw(i)], b = F.v[cw(i)];
    // f becomes (apex, a, m); g becomes (apex, m, b)
    reset_face(g, apex, m, b);
    reset_face(f, apex, a, m);
    // the half-edges m-b (g's edge 0) and a-m (f's edge 0) are the caller's
    inherit_neighbor(g, 1, F.n[ccw(i)], f);
    link(g, 2, f, 1);                 // shared edge apex-m
    faces[f].n[2] = F.n[cw(i)];       // which still borders f
    vertex_face[m] = f; vertex_face[b] = g;  // apex and a stay in f
    return g;
  }

  // Flips the edge i of face f, whose quadrilateral must be strictly convex:
  // f = (a, b, c) and g = (d, c, b) across become f = (a, b, d), g = (a, d, c).
  void flip(Index f, int i)
  {
    const Index g = faces[f].n[i];
    const int j = index_of_neighbor(g, f);
    const Face F = faces[f], G = faces[g];
    const Index a = F.v[i], b = F.v[ccw(i)], c = F.v[cw(i)], d = G.v[j];
    const Index nf_b = F.n[ccw(i)], nf_c = F.n[cw(i)];
    const Index ng_c = G.n[ccw(j)], ng_b = G.n[cw(j)];
    faces[f].v = {{a, b, d}};
    faces[f].n = {{ng_c, g, nf_c}};
    faces[g].v = {{a, d, c}};
    faces[g].n = {{ng_b, nf_b, f}};
    if(ng_c != null) faces[ng_c].n[index_of_neighbor(ng_c, g)] = f;
    if(nf_b != null) faces[nf_b].n[index_of_neighbor(nf_b, f)] = g;
    // a and d keep whichever face they had; b leaves g, c leaves f
    vertex_face[b] = f; vertex_face[c] = g;
  }

private:
  std::vector<Index> free_;
};

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_FLAT_MESH_H

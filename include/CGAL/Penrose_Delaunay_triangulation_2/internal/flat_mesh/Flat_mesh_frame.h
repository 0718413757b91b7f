// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A frame around the base mesh: three far vertices and the triangles
// between them and the root tile, so that every vertex of the tile tree is
// interior and can be removed or moved by local edits only. The frame's
// vertices are removed from the triangulation at the end.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_FLAT_MESH_FRAME_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_FLAT_MESH_FRAME_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/flat_mesh/Flat_mesh.h>

#include <array>

namespace CGAL {
namespace internal {
namespace Penrose {

// The corner face (w[e - 1], w[e], e) between the frame faces `before` and
// `after` of root corner e.
inline void close_frame_corner(Flat_mesh& m, const std::array<Flat_mesh::Index, 3>& w, int e,
                               Flat_mesh::Index before, Flat_mesh::Index after)
{
  const Flat_mesh::Index h = m.create_face(w[(e + 2) % 3], w[e], Flat_mesh::Index(e));
  m.link(before, 1, h, 1);
  m.link(h, 0, after, 0);
}

// Adds the frame around `m`, a disk whose vertices 0, 1, 2 are the corners
// of the root tile, counter-clockwise; returns the frame's vertices. The
// root tile's boundary is walked counter-clockwise from its corner 0: its
// edge e runs from corner e to corner e + 1. Each far vertex lies beyond
// the middle of an edge, eight times as far from the centre.
inline std::array<Flat_mesh::Index, 3> add_frame(Flat_mesh& m)
{
  typedef Flat_mesh::Index Index;
  double cx = 0., cy = 0.;
  for(Index i = 0; i < 3; ++i) { cx += m.points[i].x() / 3.; cy += m.points[i].y() / 3.; }
  std::array<Index, 3> w;
  for(Index e = 0; e < 3; ++e) {
    const Index f = (e + 1) % 3;
    const double mx = 0.5 * (m.points[e].x() + m.points[f].x()) - cx;
    const double my = 0.5 * (m.points[e].y() + m.points[f].y()) - cy;
    w[e] = m.add_vertex(cx + 8. * mx, cy + 8. * my);
  }
  // Each boundary edge a -> b of root edge e gets the face (b, a, w[e])
  // outside it; consecutive ones share their edge from b to w[e], and at
  // corner e the face (w[e - 1], w[e], e) closes the gap.
  Index first = Flat_mesh::null, previous = Flat_mesh::null;
  Index a = 0;
  int e = 0;
  do {
    const auto [f, i] = m.boundary_edge_from(a);
    const Index b = m.faces[f].v[Flat_mesh::cw(i)];
    const Index g = m.create_face(b, a, w[e]);
    m.link(g, 2, f, i);
    if(previous == Flat_mesh::null) first = g;
    else if(a < 3) close_frame_corner(m, w, e, previous, g);
    else m.link(previous, 1, g, 0);
    previous = g;
    a = b;
    if(a < 3) e = int(a);
  } while(a != 0);
  close_frame_corner(m, w, 0, previous, first);
  return w;
}

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_FLAT_MESH_FRAME_H

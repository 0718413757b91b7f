// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The flat mesh, once Delaunay, written into a triangulation's TDS in one
// pass: its vertices, then each face's vertices and neighbours by index
// into the faces that Tds_reservation made in the flat mesh's order, then
// the infinite faces along the frame. The writes change no container, so
// with Parallel_tag they are split in blocks (parallel/Concurrency.h).

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TDS_WRITING_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TDS_WRITING_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/flat_mesh/Flat_mesh.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/parallel/Concurrency.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tds/Tds_reservation.h>

#include <CGAL/assertions.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace CGAL {
namespace internal {
namespace Penrose {

// Writes the flat mesh, a disk whose boundary passes through its vertex
// `on_boundary`, into the TDS of `reservation`, which then becomes that of
// `tr`; the mesh's coordinates are released as soon as the TDS
// vertices hold them.
template <class ConcurrencyTag, class Triangulation, class Lift>
std::vector<typename Triangulation::Vertex_handle>
write_tds(Triangulation& tr, Flat_mesh& m, const Lift& lift,
          Tds_reservation<typename Triangulation::Triangulation_data_structure>& reservation,
          Flat_mesh::Index on_boundary)
{
  typedef typename Triangulation::Triangulation_data_structure Tds;
  typedef typename Triangulation::Vertex_handle Vertex_handle;
  typedef typename Triangulation::Face_handle Face_handle;
  typedef Flat_mesh::Index Index;
  constexpr std::size_t ahead = Flat_mesh::fetch_distance;
  Tds& prepared_tds = reservation.tds;
  const Vertex_handle infinite = prepared_tds.create_vertex();
  std::vector<Vertex_handle> vh(m.vertex_face.size());
  for(std::size_t v = 0; v < vh.size(); ++v)
    if(m.vertex_face[v] != Flat_mesh::null) {
      vh[v] = prepared_tds.create_vertex();
      vh[v]->set_point(lift(m.points[v].x(), m.points[v].y()));
    }
  decltype(m.points)().swap(m.points);
  Tds& tds = tr.tds();
  tds.swap(prepared_tds);
  tr.set_infinite_vertex(infinite);
  tds.set_dimension(2);
  // the edges without a face across, counter-clockwise
  std::vector<std::pair<Index, int>> boundary;
  Index next = on_boundary;
  do {
    boundary.push_back(m.boundary_edge_from(next));
    next = m.faces[boundary.back().first].v[Flat_mesh::cw(boundary.back().second)];
  } while(next != on_boundary);
  // The TDS face of flat face f, dead or alive, is the f-th made.
  const auto& made = reservation.made;
  CGAL_assertion(made.size() == m.faces.size());
  // Each face's vertices and neighbours, and each vertex's face, change no
  // container: bound by memory, they are written in blocks.
  // The dead faces, found on the way, are never faces of the triangulation.
  auto write_faces = [&m, &made, &vh](std::size_t begin, std::size_t end, std::vector<Index>& dead) {
    for(std::size_t f = begin; f < end; ++f) {
      if(f + ahead < end)
        for(Index v : m.faces[f + ahead].v) CGAL_PENROSE_PREFETCH(&vh[v]);
      if(!m.face_alive[f]) {
        dead.push_back(Index(f));
        continue;
      }
      const Flat_mesh::Face& F = m.faces[f];
      const Face_handle h = made[f];
      h->set_vertices(vh[F.v[0]], vh[F.v[1]], vh[F.v[2]]);
      for(int i = 0; i < 3; ++i)
        if(F.n[i] != Flat_mesh::null) h->set_neighbor(i, made[F.n[i]]);
    }
  };
  auto give_vertices_a_face = [&m, &made, &vh](std::size_t begin, std::size_t end) {
    for(std::size_t v = begin; v < end; ++v)
      if(vh[v] != Vertex_handle()) vh[v]->set_face(made[m.vertex_face[v]]);
  };
  const std::vector<Index> dead = gather_in_blocks<Index, ConcurrencyTag>(m.faces.size(), write_faces);
  for_each_block<ConcurrencyTag>(vh.size(), walk_block, give_vertices_a_face);
  for(Index f : dead) tds.faces().erase(made[f]);
  std::vector<std::pair<Vertex_handle, Face_handle>> hull;  // infinite face (inf, b, a), keyed by b
  for(const auto& [f, i] : boundary) {
    const Face_handle F = made[f];
    const Vertex_handle a = F->vertex(Flat_mesh::ccw(i)), b = F->vertex(Flat_mesh::cw(i));
    const Face_handle h = tds.create_face(infinite, b, a);
    h->set_neighbor(0, F);
    F->set_neighbor(i, h);
    hull.emplace_back(b, h);
  }
  // (inf, b, a) borders (inf, a, c) across the edge inf-a, and (inf, d, b) across inf-b
  for(auto& bh : hull)
    for(auto& other : hull)
      if(other.second->vertex(1) == bh.second->vertex(2)) {
        bh.second->set_neighbor(1, other.second);
        other.second->set_neighbor(2, bh.second);
      }
  infinite->set_face(hull.front().second);
  return vh;
}

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TDS_WRITING_H

// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Writes the finite faces of a 2D triangulation as a triangle mesh (OFF, PLY
// or OBJ), with the vertices in an order the caller chooses.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_IO_WRITE_TRIANGULATION_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_IO_WRITE_TRIANGULATION_H

#include <CGAL/Penrose_Delaunay_triangulation_2/IO/internal/file_names.h>

#include <CGAL/Handle_hash_function.h>
#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/IO/PLY.h>
#include <CGAL/Kernel_traits.h>

#include <array>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace IO {
namespace internal {

// The points of a mesh file are 3D: a 2D point gets z = 0, and the 3D point
// of a `Projection_traits_xy_3` triangulation (a terrain) keeps its height.
template <class Point>
typename Kernel_traits<Point>::Kernel::Point_3 mesh_point(const Point& p)
{
  if constexpr(Point::Ambient_dimension::value == 2)
    return typename Kernel_traits<Point>::Kernel::Point_3(p.x(), p.y(), 0);
  else
    return p;
}

} // namespace internal

/*!
\ingroup PkgPenroseDelaunayTriangulation2IO

Writes the finite faces of the 2D triangulation `t` as a triangle mesh, in the
format given by the extension of `file`: `.off`, `.ply` (binary) or `.obj`.
The mesh's vertices are the points of `vertices`, in this order; its faces
are the finite faces of `t`, counter-clockwise seen from above (+z). A vertex
listed more than once is written each time, and faces refer to its first
occurrence.

\tparam Triangulation a `Triangulation_2` whose points are 2D, or 3D as with
        `Projection_traits_xy_3` (the heights are written)
\tparam VertexRange a range of `Triangulation::Vertex_handle` holding every
        finite vertex of `t`

\throws std::runtime_error naming the file if its extension is unknown, a
finite vertex of `t` is not in `vertices`, or the file cannot be written.
*/
template <class Triangulation, class VertexRange>
void write_triangulation(const std::string& file, const Triangulation& t, const VertexRange& vertices)
{
  typedef typename Triangulation::Vertex_handle Vertex_handle;
  typedef decltype(internal::mesh_point(t.finite_vertices_begin()->point())) Point_3;
  std::vector<Point_3> points;
  std::unordered_map<Vertex_handle, std::size_t, Handle_hash_function> index;
  index.reserve(t.number_of_vertices());
  for(Vertex_handle v : vertices) {
    index.emplace(v, points.size());
    points.push_back(internal::mesh_point(v->point()));
  }
  std::vector<std::array<std::size_t, 3>> faces;
  faces.reserve(t.number_of_faces());
  for(auto f = t.finite_faces_begin(); f != t.finite_faces_end(); ++f) {
    std::array<std::size_t, 3> face;
    for(int i = 0; i < 3; ++i) {
      const auto it = index.find(f->vertex(i));
      if(it == index.end()) throw internal::file_error(file, "a vertex of the triangulation is not listed");
      face[i] = it->second;
    }
    faces.push_back(face);
  }
  const std::string e = internal::lowercase_extension(file);
  const auto precision = parameters::stream_precision(17);
  bool ok = false;
  if(e == "off") ok = write_OFF(file, points, faces, precision);
  else if(e == "ply") ok = write_PLY(file, points, faces, precision);
  else if(e == "obj") ok = write_OBJ(file, points, faces, precision);
  else throw internal::file_error(file, "unknown mesh format '." + e + "' (off, ply or obj)");
  if(!ok) throw internal::file_error(file, "cannot write");
}

/// \ingroup PkgPenroseDelaunayTriangulation2IO
/// Writes `t` as `write_triangulation(file, t, vertices)` does, with the
/// vertices in the order of `t.finite_vertex_handles()`.
template <class Triangulation>
void write_triangulation(const std::string& file, const Triangulation& t)
{
  std::vector<typename Triangulation::Vertex_handle> vertices;
  for(auto v : t.finite_vertex_handles()) vertices.push_back(v);
  write_triangulation(file, t, vertices);
}

} // namespace IO
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_IO_WRITE_TRIANGULATION_H

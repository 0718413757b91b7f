// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Writes the finite faces of a 2D triangulation as a triangle mesh (OFF, PLY
// or OBJ), with the vertices in an order the caller chooses.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_IO_WRITE_TRIANGULATION_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_IO_WRITE_TRIANGULATION_H

#include <CGAL/Penrose_Delaunay_triangulation_2/IO/internal/file_names.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/IO/internal/output_file.h>

#include <CGAL/Unique_hash_map.h>
#include <CGAL/number_utils.h>

#include <array>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace IO {
namespace internal {

// The points of a mesh file are 3D: a 2D point gets z = 0, and the 3D point
// of a `Projection_traits_xy_3` triangulation (a terrain) keeps its height.
template <class Point>
std::array<double, 3> mesh_point(const Point& p)
{
  if constexpr(Point::Ambient_dimension::value == 2)
    return {to_double(p.x()), to_double(p.y()), 0.};
  else
    return {to_double(p.x()), to_double(p.y()), to_double(p.z())};
}

/*
A mesh file written through a buffer: numbers as the shortest decimal that
reads back as the same double (std::to_chars), binary values little-endian
whatever the machine. CGAL's writers, through streams with 17 digits, took as
long as a tenth of the greedy refinement of a 10^6-vertex terrain. The file
replaces the target only once complete (see Output_file).
*/
class Mesh_file_writer
{
public:
  explicit Mesh_file_writer(const std::string& file) : out_(file) { buffer_.reserve(capacity + 64); }

  void text(const char* s) { append(s, std::strlen(s)); }

  void number(double v)
  {
    char digits[32];
    append(digits, std::size_t(std::to_chars(digits, digits + sizeof digits, v).ptr - digits));
  }

  void number(std::size_t v)
  {
    char digits[24];
    append(digits, std::size_t(std::to_chars(digits, digits + sizeof digits, v).ptr - digits));
  }

  // The `bytes` low bytes of `v`, the least significant first.
  void little_endian(std::uint64_t v, int bytes)
  {
    char b[8];
    for(int k = 0; k < bytes; ++k) b[k] = char((v >> (8 * k)) & 0xff);
    append(b, std::size_t(bytes));
  }

  void little_endian(double v)
  {
    std::uint64_t bits;
    std::memcpy(&bits, &v, sizeof bits);
    little_endian(bits, 8);
  }

  void close()
  {
    flush();
    out_.commit();
  }

private:
  static constexpr std::size_t capacity = std::size_t(1) << 20;

  void append(const char* s, std::size_t n)
  {
    buffer_.append(s, n);
    if(buffer_.size() >= capacity) flush();
  }

  void flush()
  {
    out_.write(buffer_);
    buffer_.clear();
  }

  Output_file out_;
  std::string buffer_;
};

// Writes the mesh in the format `e`: "off", "ply" (binary) or "obj".
inline void write_mesh(const std::string& file, const std::string& e, const std::vector<std::array<double, 3>>& points,
                       const std::vector<std::array<std::size_t, 3>>& faces)
{
  if(e == "ply" && points.size() > std::size_t((std::numeric_limits<std::int32_t>::max)()))
    throw file_error(file, "too many vertices for the int indices of a PLY file");
  Mesh_file_writer out(file);
  if(e == "ply") {
    const std::string header = "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(points.size())
      + "\nproperty double x\nproperty double y\nproperty double z\nelement face " + std::to_string(faces.size())
      + "\nproperty list uchar int vertex_indices\nend_header\n";
    out.text(header.c_str());
    for(const auto& p : points)
      for(double c : p) out.little_endian(c);
    for(const auto& f : faces) {
      out.little_endian(3, 1);
      for(std::size_t v : f) out.little_endian(v, 4);
    }
  } else {
    const bool off = e == "off";
    if(off) {
      out.text("OFF\n");
      out.number(points.size());
      out.text(" ");
      out.number(faces.size());
      out.text(" 0\n");
    }
    for(const auto& p : points) {
      out.text(off ? "" : "v ");
      for(int k = 0; k < 3; ++k) {
        out.number(p[k]);
        out.text(k < 2 ? " " : "\n");
      }
    }
    for(const auto& f : faces) {
      out.text(off ? "3" : "f");
      for(std::size_t v : f) {
        out.text(" ");
        out.number(off ? v : v + 1);  // OBJ counts from 1
      }
      out.text("\n");
    }
  }
  out.close();
}

} // namespace internal

/*!
\ingroup PkgPenroseDelaunayTriangulation2IO

Writes the finite faces of the 2D triangulation `t` as a triangle mesh, in the
format given by the extension of `file`: `.off`, `.ply` (binary) or `.obj`.
The mesh's vertices are the points of `vertices`, in this order; its faces
are the finite faces of `t`, counter-clockwise seen from above (+z). A vertex
listed more than once is written each time, and faces refer to its first
occurrence. Coordinates are written as the shortest decimals that read back
as the same doubles (OFF, OBJ), or as doubles (PLY).

\tparam Triangulation a `Triangulation_2` whose points are 2D, or 3D as with
        `Projection_traits_xy_3` (the heights are written)
\tparam VertexRange a range of `Triangulation::Vertex_handle` holding every
        finite vertex of `t`

\throws std::runtime_error naming the file if its extension is unknown, a
finite vertex of `t` is not in `vertices`, a PLY file would have more
vertices than its int indices count, or the file cannot be written.
*/
template <class Triangulation, class VertexRange>
void write_triangulation(const std::string& file, const Triangulation& t, const VertexRange& vertices)
{
  typedef typename Triangulation::Vertex_handle Vertex_handle;
  const std::string e = internal::lowercase_extension(file);
  if(e != "off" && e != "ply" && e != "obj")
    throw internal::file_error(file, "unknown mesh format '." + e + "' (off, ply or obj)");
  std::vector<std::array<double, 3>> points;
  const std::size_t none = (std::numeric_limits<std::size_t>::max)();
  Unique_hash_map<Vertex_handle, std::size_t> index(none, t.number_of_vertices());
  for(Vertex_handle v : vertices) {
    if(!index.is_defined(v)) index[v] = points.size();
    points.push_back(internal::mesh_point(v->point()));
  }
  std::vector<std::array<std::size_t, 3>> faces;
  faces.reserve(t.number_of_faces());
  for(auto f = t.finite_faces_begin(); f != t.finite_faces_end(); ++f) {
    std::array<std::size_t, 3> face;
    for(int i = 0; i < 3; ++i) {
      face[i] = index[f->vertex(i)];
      if(face[i] == none) throw internal::file_error(file, "a vertex of the triangulation is not listed");
    }
    faces.push_back(face);
  }
  internal::write_mesh(file, e, points, faces);
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

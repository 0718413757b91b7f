// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Delaunay triangulation of the region's samples in a window, made
// alone: steps 1 to 4 of the construction on the tiles whose samples can
// land in the window, inside the frame, left as a flat mesh. A window's
// mesh is framed, so that the triangles near its hull are not those of the
// samples alone; the certificate (Window_certificate.h) tells which
// triangles hold for the whole region.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_WINDOW_MESH_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_WINDOW_MESH_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/base_mesh/Base_triangulation_builder.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/flat_mesh/Flat_mesh.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/flat_mesh/Flat_mesh_delaunay.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/flat_mesh/Flat_mesh_editing.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/flat_mesh/Flat_mesh_frame.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tiling/Sampling_context.h>

#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>
#include <CGAL/tags.h>

#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace CGAL {
namespace internal {
namespace Penrose {

struct Window_mesh
{
  Flat_mesh mesh;
  std::vector<std::uint64_t> key;  // of each vertex that is a sample
  std::vector<char> is_sample;     // a sample of the region in the window; not a frame vertex
  bool repaired_by_insertion = false;  // made again by Delaunay_triangulation_2 (see below)
};

struct Window_sample
{
  double x, y;
  std::uint64_t key;
};

// The framed mesh of `samples` and the frame's vertices `frame`, made by
// CGAL's Delaunay_triangulation_2: the same triangulation as the flips
// give, for the rare windows where local repair leaves vertices to
// insert() or remove().
inline void triangulate_by_insertion(const std::vector<Window_sample>& samples, const std::vector<Flat_mesh::Point>& frame,
                                     Window_mesh& w)
{
  typedef Exact_predicates_inexact_constructions_kernel K;
  typedef Triangulation_vertex_base_with_info_2<Flat_mesh::Index, K> Vb;
  typedef Triangulation_face_base_with_info_2<Flat_mesh::Index, K> Fb;
  typedef Delaunay_triangulation_2<K, Triangulation_data_structure_2<Vb, Fb>> Dt;
  Flat_mesh& m = w.mesh;
  m = Flat_mesh();
  w.key.clear();
  w.is_sample.clear();
  std::vector<std::pair<K::Point_2, Flat_mesh::Index>> points;
  for(const Window_sample& s : samples) {
    points.emplace_back(K::Point_2(s.x, s.y), Flat_mesh::Index(points.size()));
    w.key.push_back(s.key);
    w.is_sample.push_back(1);
  }
  for(const Flat_mesh::Point& p : frame) {
    points.emplace_back(p, Flat_mesh::Index(points.size()));
    w.key.push_back(0);
    w.is_sample.push_back(0);
  }
  for(const auto& p : points) m.add_vertex(p.first.x(), p.first.y());
  Dt dt(points.begin(), points.end());
  // two points that coincide would leave a vertex out: none do among samples
  for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
    f->info() = m.create_face(f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info());
  for(auto f = dt.finite_faces_begin(); f != dt.finite_faces_end(); ++f)
    for(int i = 0; i < 3; ++i)
      if(!dt.is_infinite(f->neighbor(i))) m.faces[f->info()].n[i] = f->neighbor(i)->info();
  w.repaired_by_insertion = true;
}

// The framed Delaunay triangulation of the region's samples in `window`
// (about `expected_points` of them), with the calling thread only.
inline Window_mesh make_window_mesh(const Sampling_context& c, const Sample_window& window, double expected_points)
{
  typedef Flat_mesh::Index Index;
  Window_mesh w;
  std::vector<std::pair<double, double>> target;
  std::vector<Window_sample> samples;
  {
    Base_triangulation_builder builder(c, window, w.mesh, true);
    builder.build<Sequential_tag>(expected_points, std::function<bool(double)>());
    target = builder.take_targets();
    w.key.assign(target.size(), 0);
    w.is_sample.assign(target.size(), 0);
    for(Index v = 0; v < target.size(); ++v)
      if(!std::isnan(target[v].first)) {
        w.key[v] = builder.sample(v).key;
        w.is_sample[v] = 1;
        samples.push_back({target[v].first, target[v].second, w.key[v]});
      }
  }
  const std::size_t n = target.size();
  const std::array<Index, 3> frame = add_frame(w.mesh);
  w.key.resize(w.mesh.points.size(), 0);
  w.is_sample.resize(w.mesh.points.size(), 0);
  std::vector<Index> inactive;
  for(Index v = 0; v < n; ++v)
    if(w.mesh.vertex_face[v] != Flat_mesh::null && !w.is_sample[v]) inactive.push_back(v);
  Flat_mesh_editor editor(w.mesh);
  std::size_t removed = 0, repaired = 0;
  const std::vector<Index> stuck = editor.remove_vertices(inactive, removed);
  const std::vector<Index> unplaced = editor.template move_vertices<Sequential_tag>(target, repaired);
  if(stuck.empty() && unplaced.empty()) {
    make_delaunay(w.mesh);
    return w;
  }
  std::vector<Flat_mesh::Point> frame_points;
  for(Index f : frame) frame_points.push_back(w.mesh.points[f]);
  triangulate_by_insertion(samples, frame_points, w);
  return w;
}

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_WINDOW_MESH_H

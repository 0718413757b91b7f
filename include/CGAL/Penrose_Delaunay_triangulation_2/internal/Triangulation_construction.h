// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The construction of Penrose_Delaunay_triangulation_2 (steps 1 to 4 of its
// documentation): the base mesh of the tile tree, framed; the vertices that
// are not samples removed; the samples moved; Lawson flips; the flat mesh
// written into the TDS; what local repair could not place left to insert()
// and remove(). With Parallel_tag, the walks that are bound by memory are
// split in TBB tasks, and the TDS's storage is made beside the flips (see
// Concurrency.h and Tds_reservation.h); the base mesh's builder runs the
// density in tasks of its own.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TRIANGULATION_CONSTRUCTION_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TRIANGULATION_CONSTRUCTION_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Base_triangulation_builder.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Construction_size.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Flat_mesh.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Flat_mesh_delaunay.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Flat_mesh_editing.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Sampler_access.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Tds_reservation.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Concurrency.h>

#include <CGAL/assertions.h>

#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <functional>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace internal {
namespace Penrose {

template <class Triangulation>
class Triangulation_construction
{
  typedef typename Triangulation::Triangulation_data_structure Tds;
  typedef typename Triangulation::Vertex_handle Vertex_handle;
  typedef typename Triangulation::Face_handle Face_handle;
  typedef typename Triangulation::Concurrency_tag Concurrency_tag;
  typedef Flat_mesh::Index Index;
  typedef Tds_reservation<Tds> Reservation;

public:
  // Clears `tr` and makes it the Delaunay triangulation of the points of
  // `sampler`, each made by `lift(x, y)`; where `visits`, calls
  // `on_vertex(v, sample)` for each vertex made from a sample. `stats` (with
  // the members of Construction_statistics) says what was done. Returns
  // false, with `tr` and `stats` cleared, if `callback` stopped it.
  template <class Sampler, class Lift, class OnVertex, class Statistics>
  static bool run(Triangulation& tr, const Sampler& sampler, const Lift& lift, OnVertex& on_vertex, bool visits,
                  const std::function<bool(double)>& callback, Statistics& stats)
  {
    auto abandon = [&]() {
      tr.clear();
      stats = Statistics();
      return false;
    };
    // the advancements are the shares of the time that the steps end at (10^6 points)
    auto proceed = [&](double advancement) { return !callback || callback(advancement); };
    check_construction_size(sampler.expected_number_of_points(), peak_bytes_per_point(),
                                               physical_memory_bytes());
    const Sampling_context& context = Sampler_access::context(sampler);
    tr.clear();
    stats = Statistics();
    Flat_mesh mesh;
    // where each sample of the region goes; NaN for the vertices to remove (freed with the builder)
    std::vector<std::pair<double, double>> target;
    std::vector<std::pair<Index, Placed_sample>> placed;  // for on_vertex only
    std::optional<Base_triangulation_builder> builder;  // freed before the TDS grows
    builder.emplace(context, mesh, visits);
    {
      std::function<bool(double)> progress;
      if(callback) progress = [&callback](double f) { return callback(0.58 * f); };
      if(!builder->build<Concurrency_tag>(sampler.expected_number_of_points(), progress)) return abandon();
      target = builder->take_targets();
      if(visits)
        for(Index v = 0; v < target.size(); ++v)
          if(!std::isnan(target[v].first)) placed.emplace_back(v, builder->sample(v));
    }
    const std::size_t n = target.size();
    auto kept = [&](std::size_t v) { return !std::isnan(target[v].first); };
    const std::array<Index, 3> frame = add_frame(mesh, context);

    Flat_mesh_editor editor(mesh);
    const std::vector<Index> inactive = inactive_vertices(mesh, n, kept, stats.base_vertices);
    const std::vector<Index> stuck = editor.remove_vertices(inactive, stats.removed_vertices);
    if(!proceed(0.61)) return abandon();
    const std::vector<Index> unplaced = editor.template move_vertices<Concurrency_tag>(target, stats.repaired_vertices);
    if(!proceed(0.66)) return abandon();

    // keep of the targets only what is still needed: the rest is freed before the TDS grows
    std::vector<std::pair<double, double>> unplaced_target;
    for(Index v : unplaced) unplaced_target.push_back(target[v]);
    builder.reset();
    decltype(target)().swap(target);
    // the TDS will have at most `live` finite vertices and the infinite one,
    // and a face for each flat one
    const std::size_t live = stats.base_vertices + frame.size() - stats.removed_vertices;
    std::optional<Reservation> reservation;
    run_beside<Concurrency_tag>([&] { reservation.emplace(live + 1, mesh.faces.size()); },
                                [&] { stats.flips = make_delaunay(mesh); });
    if(!proceed(0.84)) return abandon();

    auto handle = write_tds(tr, mesh, lift, *reservation, frame[0]);
    mesh = Flat_mesh();
    if(!proceed(0.99)) return abandon();
    for(Index v : stuck) tr.remove(handle[v]);
    for(Index w : frame) tr.remove(handle[w]);
    for(std::size_t i = 0; i < unplaced.size(); ++i)
      handle[unplaced[i]] = tr.insert(lift(unplaced_target[i].first, unplaced_target[i].second));
    stats.fallbacks = stuck.size() + unplaced.size();
    for(const auto& vp : placed)
      if(handle[vp.first] != Vertex_handle()) on_vertex(handle[vp.first], Sampler_access::sample(sampler, vp.second));
    return proceed(1.) || abandon();
  }


private:
  // The peak of a construction: the flat mesh (about 100 bytes per point at
  // the peak, which is while the mesh is made Delaunay and the TDS's vertices
  // are reserved and its faces made beside it) and the TDS itself, with two
  // faces per vertex.
  static double peak_bytes_per_point()
  {
    typedef typename Tds::Vertex Vertex;
    typedef typename Tds::Face Face;
    return 100. + double(sizeof(Vertex)) + 2. * double(sizeof(Face));
  }

  // The vertices among the first `n` of the mesh that are in it and not
  // `kept`, in order; `in_mesh` counts those in it. A walk over every vertex,
  // bound by memory, so it is split in blocks.
  template <class Kept>
  static std::vector<Index> inactive_vertices(const Flat_mesh& mesh, std::size_t n, const Kept& kept, std::size_t& in_mesh)
  {
    std::atomic<std::size_t> present{0};
    std::vector<Index> inactive = gather_in_blocks<Index, Concurrency_tag>(
      n, [&](std::size_t begin, std::size_t end, std::vector<Index>& found) {
        std::size_t here = 0;
        for(std::size_t v = begin; v < end; ++v)
          if(mesh.vertex_face[v] != Flat_mesh::null) {
            ++here;
            if(!kept(v)) found.push_back(Index(v));
          }
        present += here;
      });
    in_mesh = present;
    return inactive;
  }

  // Three far vertices and the triangles between them and the root tile, so
  // that every vertex of the tile tree is interior. The root tile's boundary
  // is walked counter-clockwise from its corner 0: its edge e runs from
  // corner e to corner e + 1, and the vertices 0, 1, 2 are those corners.
  static std::array<Index, 3> add_frame(Flat_mesh& m, const Sampling_context& c)
  {
    double cx = 0., cy = 0.;
    for(int i = 0; i < 3; ++i) { cx += c.root_x(i) / 3.; cy += c.root_y(i) / 3.; }
    std::array<Index, 3> w;
    for(int e = 0; e < 3; ++e) {
      const double mx = 0.5 * (c.root_x(e) + c.root_x((e + 1) % 3)) - cx;
      const double my = 0.5 * (c.root_y(e) + c.root_y((e + 1) % 3)) - cy;
      w[e] = m.add_vertex(cx + 8. * mx, cy + 8. * my);
    }
    // Each boundary edge a -> b of root edge e gets the face (b, a, w[e])
    // outside it; consecutive ones share their edge from b to w[e], and at
    // corner e the face (w[e - 1], w[e], e) closes the gap.
    Index first = Flat_mesh::null, previous = Flat_mesh::null;
    Index a = 0;
    int e = 0;
    do {
      const auto [f, i] = boundary_edge_from(m, a);
      const Index b = m.faces[f].v[Flat_mesh::cw(i)];
      const Index g = m.create_face(b, a, w[e]);
      m.link(g, 2, f, i);
      if(previous == Flat_mesh::null) first = g;
      else if(a < 3) close_corner(m, w, e, previous, g);
      else m.link(previous, 1, g, 0);
      previous = g;
      a = b;
      if(a < 3) e = int(a);
    } while(a != 0);
    close_corner(m, w, 0, previous, first);
    return w;
  }

  // The boundary edge of the flat mesh that leaves its vertex b, as (face,
  // edge index): the faces around b are turned clockwise until there is
  // nothing across.
  static std::pair<Index, int> boundary_edge_from(const Flat_mesh& m, Index b)
  {
    Index f = m.vertex_face[b];
    for(Index g = m.cw_face_around(f, b); g != Flat_mesh::null; g = m.cw_face_around(f, b)) f = g;
    return {f, Flat_mesh::cw(m.index_of_vertex(f, b))};
  }

  // The corner face (w[e - 1], w[e], e) between the frame faces `before` and
  // `after` of root corner e.
  static void close_corner(Flat_mesh& m, const std::array<Index, 3>& w, int e, Index before, Index after)
  {
    const Index h = m.create_face(w[(e + 2) % 3], w[e], Index(e));
    m.link(before, 1, h, 1);
    m.link(h, 0, after, 0);
  }

  // Writes the flat mesh, a disk whose boundary passes through its vertex
  // `on_boundary`, into the TDS of `reservation`, which then becomes that of
  // `tr`; the mesh's coordinates are released as soon as the TDS
  // vertices hold them.
  template <class Lift>
  static std::vector<Vertex_handle> write_tds(Triangulation& tr, Flat_mesh& m, const Lift& lift,
                                               Reservation& reservation, Index on_boundary)
  {
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
      boundary.push_back(boundary_edge_from(m, next));
      next = m.faces[boundary.back().first].v[Flat_mesh::cw(boundary.back().second)];
    } while(next != on_boundary);
    // The TDS face of flat face f, dead or alive, is the f-th made.
    const typename Reservation::Faces& made = reservation.made;
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
    const std::vector<Index> dead = gather_in_blocks<Index, Concurrency_tag>(m.faces.size(), write_faces);
    for_each_block<Concurrency_tag>(vh.size(), walk_block, give_vertices_a_face);
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

};

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TRIANGULATION_CONSTRUCTION_H

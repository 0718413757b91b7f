// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The construction of Penrose_Delaunay_triangulation_2 (steps 1 to 4 of its
// documentation), one stage a folder: the base mesh of the tile tree
// (tiling/, base_mesh/), framed; the vertices that are not samples removed,
// the samples moved and Lawson flips (flat_mesh/); the flat mesh written
// into the TDS (tds/); what local repair could not place left to insert()
// and remove(). With Parallel_tag, the walks that are bound by memory are
// split in TBB tasks, and the TDS's storage is made beside the flips
// (parallel/); the base mesh's builder runs the density in tasks of its own.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TRIANGULATION_CONSTRUCTION_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TRIANGULATION_CONSTRUCTION_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Construction_size.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Sampler_access.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/base_mesh/Base_triangulation_builder.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/flat_mesh/Flat_mesh.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/flat_mesh/Flat_mesh_delaunay.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/flat_mesh/Flat_mesh_editing.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/flat_mesh/Flat_mesh_frame.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/parallel/Concurrency.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tds/Tds_reservation.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tds/Tds_writing.h>

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
    const std::array<Index, 3> frame = add_frame(mesh);

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

    auto handle = write_tds<Concurrency_tag>(tr, mesh, lift, *reservation, frame[0]);
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
};

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TRIANGULATION_CONSTRUCTION_H

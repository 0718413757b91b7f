// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_H

#include <CGAL/Penrose_importance_sampler.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Base_triangulation_builder.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Construction_size.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Flat_mesh.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Flat_mesh_delaunay.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Flat_mesh_editing.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Tds_reservation.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Two_halves.h>

#include <CGAL/Default.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <functional>
#include <limits>
#include <optional>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {

/*!
\ingroup PkgPenroseDelaunayTriangulation2Ref

The Delaunay triangulation of the points of a `Penrose_importance_sampler`,
derived from the sampler's tile tree as in "Fast Delaunay-triangulated
importance-sampled point sets", without locating a single point:

1. the tile tree is built breadth first straight into a triangulation free of
   T-edges (a new vertex on an edge splits the two triangles of that edge);
   a vertex that is neither a sample of the region nor a corner of a tile
   subdivided further is never created, and the tiles around it stay merged;
2. the remaining vertices that are not samples (inactive, or moved out of the
   region) are removed, and each hole is filled greedily with exact
   orientation tests;
3. the samples are moved by their correction vectors; where a triangle would
   fold, its vertices are removed and reinserted locally;
4. Lawson flips make the triangulation Delaunay. They are decided with CGAL's
   exact predicates on the points' double coordinates and the symbolic
   perturbation of `Triangulation_2::side_of_oriented_circle(..., true)`,
   restated, so the result is exactly the triangulation that
   `Delaunay_triangulation_2::insert()` builds from the same points,
   cocircular points included.

Steps 1 to 4 run on a flat mesh, which is written once into the TDS. The
triangulation is framed by three far vertices during the construction so that
every vertex removed there is interior; the frame is removed last with
`remove()`. A point that local repair cannot place (for instance one that
coincides with another) is inserted with `insert()` at the end: such
fallbacks are counted.

The decisions of steps 1 to 4 are made on the coordinates (x, y) of the
sampler, so the traits must see the points made by the lift with these
coordinates (true of every kernel's `Point_2`, and of
`Projection_traits_xy_3` with a lift to (x, y, z)); their predicates must be
exact.

It is a `Delaunay_triangulation_2<Gt, Tds>`: every operation of that class
works on it after construction.

On a machine with more than one core, a construction of at least
2<sup>16</sup> points uses helper threads, one at a time:
- during step 1, one that surveys the tiles of a level ahead of the
  calling thread (the density at their new vertices, which samples are kept,
  which children are subdivided), while the calling thread builds the mesh,
  and, once it has surveyed a level, faults in the memory that the calling
  thread will write there. The density (and its bound, if given) is then
  called from that thread, in the same order as without it, and never from
  two threads at once;
- before step 2, one that looks for the vertices to remove among half of
  the vertices;
- during step 3, one that moves half of the samples, then looks for folded
  triangles among half of the faces;
- during step 4, one that frees the arrays that served steps 1 to 3 alone, then
  reserves the storage of the TDS's vertices and creates its faces, empty
  (default-constructed), one for each face of the flat mesh: most of the
  cost of writing a TDS is the first touch of its memory;
- while the TDS is written, one that gives half of its faces their vertices
  and neighbours, and half of its vertices their face.

The helpers create no vertex and call neither the traits nor the lift; the
faces' default constructor is the only code of the TDS that runs on a
helper. They have ended when the constructor or `build()` returns or
throws; what the density throws in the helper is rethrown to the caller.
The triangulation is the same either way. Define
`CGAL_PENROSE_NO_HELPER_THREAD` (or CGAL's `CGAL_HAS_NO_THREADS`) to do
without them, for instance for a density that must be called from the
calling thread.

A construction that would not fit in the machine's memory (its peak is
about 220 bytes per point with the default TDS), or that has more than
about 1.7 x 10<sup>9</sup> points, is refused before anything is allocated:
the constructors and `build()` throw `std::length_error`. The base mesh
follows the tile tree rather than the points, and a `density_upper_bound`
far above the density refines tiles that hold no point: a mesh that would
then outgrow the machine's memory (about 520 bytes per vertex, once it has
outgrown what was reserved for the points) or its 32-bit indices is refused
in the same way before it grows, and the triangulation is left empty.

On Linux, the blocks of the internal mesh (on transparent huge pages) are
kept after a construction for the next one of the same size, about 65 bytes
per point; a construction unmaps those it does not take back before its
peak. Define `CGAL_PENROSE_NO_HUGE_PAGES` to allocate with `std::allocator`
throughout.

\tparam Gt a model of `DelaunayTriangulationTraits_2` with exact predicates
        (for example `Exact_predicates_inexact_constructions_kernel`,
        `Exact_predicates_exact_constructions_kernel`,
        `Projection_traits_xy_3<K>` for terrains).
\tparam Tds a `Triangulation_data_structure_2<Vb, Fb>`, with any vertex and
        face bases (the construction finds its faces in their
        `Compact_container` from the order it made them in); `Default` means
        the one of `Delaunay_triangulation_2<Gt>`.
*/
template <class Gt = Exact_predicates_inexact_constructions_kernel, class Tds_ = Default>
class Penrose_Delaunay_triangulation_2
  : public Delaunay_triangulation_2<Gt, typename Default::Get<Tds_, Triangulation_data_structure_2<
                                          Triangulation_vertex_base_2<Gt>, Triangulation_face_base_2<Gt>>>::type>
{
  typedef typename Default::Get<Tds_, Triangulation_data_structure_2<
    Triangulation_vertex_base_2<Gt>, Triangulation_face_base_2<Gt>>>::type Tds;
  typedef Delaunay_triangulation_2<Gt, Tds> Base;
  typedef internal::Penrose::Flat_mesh Flat_mesh;
  typedef Flat_mesh::Index Index;

public:
  /// \name Types
  /// Besides those of `Delaunay_triangulation_2<Gt, Tds>`:
  /// @{

  /// The traits, `Gt`.
  typedef typename Base::Geom_traits Geom_traits;
  /// The triangulation data structure, `Tds` or its default.
  typedef typename Base::Triangulation_data_structure Triangulation_data_structure;
  /// The point type of the traits.
  typedef typename Base::Point Point;
  /// A handle to a vertex.
  typedef typename Base::Vertex_handle Vertex_handle;
  /// A handle to a face.
  typedef typename Base::Face_handle Face_handle;

  /// What the construction did.
  struct Construction_statistics
  {
    std::size_t base_vertices = 0;    ///< vertices of the tile tree's triangulation
    std::size_t removed_vertices = 0; ///< of those, removed (not samples of the region)
    std::size_t repaired_vertices = 0;///< moved by removal and local reinsertion
    std::size_t flips = 0;            ///< Lawson flips
    std::size_t fallbacks = 0;        ///< points or vertices left to `insert()` / `remove()`
  };
  /// @}

  /// \name Creation
  /// @{

  /// An empty triangulation.
  explicit Penrose_Delaunay_triangulation_2(const Gt& gt = Gt()) : Base(gt) {}

  /// The triangulation of the points of `sampler`. Each point is made with
  /// the traits' `Construct_point_2` from its two coordinates.
  template <class SamplerTraits>
  explicit Penrose_Delaunay_triangulation_2(const Penrose_importance_sampler<SamplerTraits>& sampler,
                                            const Gt& gt = Gt())
    : Base(gt)
  {
    auto construct = gt.construct_point_2_object();
    build(sampler, [construct](double x, double y) { return construct(x, y); });
  }

  /// The triangulation of the points of `sampler`, each made by `lift(x, y)`,
  /// for instance a 3D point with a height for `Projection_traits_xy_3`.
  template <class SamplerTraits, class Lift>
  Penrose_Delaunay_triangulation_2(const Penrose_importance_sampler<SamplerTraits>& sampler,
                                   const Lift& lift, const Gt& gt = Gt())
    : Base(gt)
  {
    build(sampler, lift);
  }

  /// Samples `density` over `region` (see `Penrose_importance_sampler` for
  /// the named parameters, and `build()` for `callback`) and triangulates
  /// the samples.
  template <class Density, class NamedParameters = parameters::Default_named_parameters,
            class G = Gt, class = typename G::Iso_rectangle_2>
  Penrose_Delaunay_triangulation_2(const typename G::Iso_rectangle_2& region, const Density& density,
                                   const NamedParameters& np = parameters::default_values())
    : Base(Gt())
  {
    auto construct = this->geom_traits().construct_point_2_object();
    build(Penrose_importance_sampler<G>(region, density, np),
          [construct](double x, double y) { return construct(x, y); }, No_vertex_visitor(), np);
  }
  /// @}

  /*!
  Clears the triangulation and builds that of the points of `sampler`.

  \tparam Lift a callable `Point(double x, double y)`.
  \tparam OnVertex a callable `void(Vertex_handle v, const Penrose_importance_sampler<SamplerTraits>::Sample& sample)`.

  \param sampler the sampler whose points are triangulated.
  \param lift makes the point of each sample from its coordinates, for
         instance a 3D point with a height for `Projection_traits_xy_3`.
  \param on_vertex called for every vertex created, with the sample it
         comes from, for instance to fill the info of a vertex base with info.
  \param np an optional sequence of named parameters among:
    - `callback`: a `std::function<bool(double)>`, called regularly with the
      advancement of the construction, in [0, 1]; if it returns `false`, the
      construction stops and the triangulation is left empty.

  \return `false` if `callback` stopped the construction, `true` otherwise.
  \throws std::length_error, leaving the triangulation as it was, if the
  construction would need more memory than the machine has, or more than
  about 1.7 x 10<sup>9</sup> points; leaving it empty, if its base mesh
  would outgrow them.
  \throws what sampling throws (a bad density, tiles too fine for the
  coordinates: see `Penrose_importance_sampler`), leaving the triangulation
  empty.
  */
  template <class SamplerTraits, class Lift, class OnVertex,
            class NamedParameters = parameters::Default_named_parameters>
  bool build(const Penrose_importance_sampler<SamplerTraits>& sampler, const Lift& lift, OnVertex on_vertex,
             const NamedParameters& np = parameters::default_values())
  {
    constexpr bool visits = !std::is_same<OnVertex, No_vertex_visitor>::value;
    const std::function<bool(double)> callback =
      parameters::choose_parameter(parameters::get_parameter(np, internal_np::callback), std::function<bool(double)>());
    auto abandon = [&]() {
      this->clear();
      stats_ = Construction_statistics();
      return false;
    };
    // the advancements are the shares of the time that the steps end at (10^6 points)
    auto proceed = [&](double advancement) { return !callback || callback(advancement); };
    internal::Penrose::check_construction_size(sampler.expected_number_of_points(), peak_bytes_per_point(),
                                               internal::Penrose::physical_memory_bytes());
    const internal::Penrose::Sampling_context& context = sampler.context();
    this->clear();
    stats_ = Construction_statistics();
    Flat_mesh mesh;
    // where each sample of the region goes; NaN for the vertices to remove (freed with the builder)
    internal::Penrose::Scratch_vector<std::pair<double, double>> target;
    std::vector<std::pair<Index, internal::Penrose::Placed_sample>> placed;  // for on_vertex only
    // freed by the TDS reservation's helper, where there is one
    std::optional<internal::Penrose::Base_triangulation_builder> builder;
    builder.emplace(context, mesh, visits);
    {
      std::function<bool(double)> progress;
      if(callback) progress = [&callback](double f) { return callback(0.58 * f); };
      if(!builder->build(sampler.expected_number_of_points(), progress)) return abandon();
      target = builder->take_targets();
      if(visits)
        for(Index v = 0; v < target.size(); ++v)
          if(!std::isnan(target[v].first)) placed.emplace_back(v, builder->sample(v));
    }
    const std::size_t n = target.size();
    auto kept = [&](std::size_t v) { return !std::isnan(target[v].first); };
    const std::array<Index, 3> frame = add_frame(mesh, context);

    internal::Penrose::Flat_mesh_editor editor(mesh);
    const std::vector<Index> inactive = inactive_vertices(mesh, n, kept, stats_.base_vertices);
    const std::vector<Index> stuck = editor.remove_vertices(inactive, stats_.removed_vertices);
    if(!proceed(0.61)) return abandon();
    const std::vector<Index> unplaced = editor.move_vertices(target, stats_.repaired_vertices);
    if(!proceed(0.66)) return abandon();

    // keep of the targets only what is still needed: the rest is freed before the TDS grows
    std::vector<std::pair<double, double>> unplaced_target;
    for(Index v : unplaced) unplaced_target.push_back(target[v]);
    // the TDS will have at most `live` finite vertices and the infinite one,
    // and a face for each flat one
    const std::size_t live = stats_.base_vertices + frame.size() - stats_.removed_vertices;
    // blocks kept from an earlier construction and not taken by this one would add to its peak
    internal::Penrose::release_kept_blocks();
    Reservation reservation(live + 1, mesh.faces.size(), [&builder, &target] {
      builder.reset();
      decltype(target)().swap(target);
    });
    stats_.flips = internal::Penrose::make_delaunay(mesh);
    if(!proceed(0.84)) return abandon();

    auto handle = write_tds(mesh, lift, reservation, frame[0]);
    mesh = Flat_mesh();
    if(!proceed(0.99)) return abandon();
    for(Index v : stuck) this->remove(handle[v]);
    for(Index w : frame) this->remove(handle[w]);
    for(std::size_t i = 0; i < unplaced.size(); ++i)
      handle[unplaced[i]] = this->insert(lift(unplaced_target[i].first, unplaced_target[i].second));
    stats_.fallbacks = stuck.size() + unplaced.size();
    for(const auto& vp : placed)
      if(handle[vp.first] != Vertex_handle()) on_vertex(handle[vp.first], sampler.to_sample(vp.second));
    return proceed(1.) || abandon();
  }

  /// Clears the triangulation and builds that of the points of `sampler`,
  /// each made by `lift(x, y)`, as `build(sampler, lift, on_vertex)` does
  /// with a visitor that does nothing.
  template <class SamplerTraits, class Lift>
  bool build(const Penrose_importance_sampler<SamplerTraits>& sampler, const Lift& lift)
  {
    return build(sampler, lift, No_vertex_visitor());
  }

  /// Exchanges the triangulations and their construction statistics.
  void swap(Penrose_Delaunay_triangulation_2& other)
  {
    Base::swap(other);
    std::swap(stats_, other.stats_);
  }

  /// \name Statistics of the construction
  /// Those of the last construction or call to `build()`, carried by copies
  /// and swaps; zero if there was none. The operations of
  /// `Delaunay_triangulation_2`, `insert()`, `remove()` and `clear()` among
  /// them, leave them as they are.
  /// @{

  /// What the last construction did.
  const Construction_statistics& construction_statistics() const { return stats_; }
  /// The Lawson flips that made the triangulation Delaunay.
  std::size_t number_of_flips() const { return stats_.flips; }
  /// The points inserted and the vertices removed with `insert()` and
  /// `remove()` because local repair could not place them.
  std::size_t number_of_fallbacks() const { return stats_.fallbacks; }
  /// @}

private:
  // The peak of a construction: the flat mesh (about 100 bytes per point at
  // the peak, which is while the mesh is made Delaunay and the TDS's vertices
  // are reserved and its faces made beside it) and the TDS itself, with two
  // faces per vertex.
  static double peak_bytes_per_point()
  {
    typedef typename Triangulation_data_structure::Vertex Vertex;
    typedef typename Triangulation_data_structure::Face Face;
    return 100. + double(sizeof(Vertex)) + 2. * double(sizeof(Face));
  }

  // The vertices among the first `n` of the mesh that are in it and not
  // `kept`, in order; `in_mesh` counts those in it. A walk over every vertex,
  // bound by memory, so it is done in halves on two threads.
  template <class Kept>
  static std::vector<Index> inactive_vertices(const Flat_mesh& mesh, std::size_t n, const Kept& kept, std::size_t& in_mesh)
  {
    std::array<std::size_t, 2> count = {{0, 0}};
    std::vector<Index> inactive = internal::Penrose::gather_in_two_halves<Index>(
      n >= internal::Penrose::least_size_for_two_halves, [&](int half, std::vector<Index>& found) {
        std::size_t present = 0;
        const internal::Penrose::Half_range vertices = internal::Penrose::half_of(n, half);
        for(std::size_t v = vertices.begin; v < vertices.end; ++v)
          if(mesh.vertex_face[v] != Flat_mesh::null) {
            ++present;
            if(!kept(v)) found.push_back(Index(v));
          }
        count[half] = present;
      });
    in_mesh = count[0] + count[1];
    return inactive;
  }

  struct No_vertex_visitor
  {
    template <class V, class S> void operator()(V, const S&) const {}
  };

  // Three far vertices and the triangles between them and the root tile, so
  // that every vertex of the tile tree is interior. The root tile's boundary
  // is walked counter-clockwise from its corner 0: its edge e runs from
  // corner e to corner e + 1, and the vertices 0, 1, 2 are those corners.
  static std::array<Index, 3> add_frame(Flat_mesh& m, const internal::Penrose::Sampling_context& c)
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

  typedef internal::Penrose::Tds_reservation<Triangulation_data_structure> Reservation;

  // Writes the flat mesh, a disk whose boundary passes through its vertex
  // `on_boundary`, into the TDS of `reservation`, which then becomes this
  // triangulation's; the mesh's coordinates are released as soon as the TDS
  // vertices hold them.
  template <class Lift>
  internal::Penrose::Large_vector<Vertex_handle> write_tds(Flat_mesh& m, const Lift& lift, Reservation& reservation,
                                                           Index on_boundary)
  {
    constexpr std::size_t ahead = Flat_mesh::fetch_distance;
    // the vertices first, while the helper may still make the faces
    Triangulation_data_structure& prepared_tds = reservation.tds_for_vertices();
    const Vertex_handle infinite = prepared_tds.create_vertex();
    internal::Penrose::Large_vector<Vertex_handle> vh(m.vertex_face.size());
    for(std::size_t v = 0; v < vh.size(); ++v)
      if(m.vertex_face[v] != Flat_mesh::null) {
        vh[v] = prepared_tds.create_vertex();
        vh[v]->set_point(lift(m.points[v].x(), m.points[v].y()));
      }
    decltype(m.points)().swap(m.points);
    const bool prepared = reservation.prepared();
    Triangulation_data_structure& tds = this->tds();
    tds.swap(reservation.tds());
    this->set_infinite_vertex(infinite);
    tds.set_dimension(2);
    // the edges without a face across, counter-clockwise
    std::vector<std::pair<Index, int>> boundary;
    Index next = on_boundary;
    do {
      boundary.push_back(boundary_edge_from(m, next));
      next = m.faces[boundary.back().first].v[Flat_mesh::cw(boundary.back().second)];
    } while(next != on_boundary);
    // The TDS face of flat face f, dead or alive, is the f-th made.
    typename Reservation::Faces made;
    if(prepared) {
      made = std::move(reservation.faces());
    } else {
      for(std::size_t f = 0; f < m.faces.size(); ++f) made.record(tds.create_face());
      made.index();
    }
    CGAL_assertion(made.size() == m.faces.size());
    // Each face's vertices and neighbours, and each vertex's face, change no
    // container: bound by memory, they take two threads, in halves.
    // The dead faces, found on the way, are never faces of the triangulation.
    auto write_faces = [&m, &made, &vh](internal::Penrose::Half_range faces, std::vector<Index>& dead) {
      const std::size_t end = faces.end;
      for(std::size_t f = faces.begin; f < end; ++f) {
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
    auto give_vertices_a_face = [&m, &made, &vh](internal::Penrose::Half_range vertices) {
      for(std::size_t v = vertices.begin; v < vertices.end; ++v)
        if(vh[v] != Vertex_handle()) vh[v]->set_face(made[m.vertex_face[v]]);
    };
    const std::vector<Index> dead = internal::Penrose::gather_in_two_halves<Index>(
      vh.size() >= internal::Penrose::least_size_for_two_halves, [&](int half, std::vector<Index>& dead_in_half) {
        write_faces(internal::Penrose::half_of(m.faces.size(), half), dead_in_half);
        give_vertices_a_face(internal::Penrose::half_of(vh.size(), half));
      });
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

  Construction_statistics stats_;
};

} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_H

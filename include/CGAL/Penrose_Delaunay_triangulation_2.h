// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_H

#include <CGAL/Penrose_importance_sampler.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Triangulation_construction.h>

#include <CGAL/Default.h>
#include <CGAL/assertions.h>
#include <CGAL/Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/tags.h>

#include <cstddef>
#include <functional>
#include <type_traits>
#include <utility>

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

With `ConcurrencyTag` = `Sequential_tag` (the default), the calling thread
does all the work: no thread is started, and the density (and its bound, if
given) is only called from it. With `Parallel_tag`, which needs TBB
(`CGAL_LINKED_WITH_TBB`, for instance through CGAL's `CGAL::TBB_support`
target), the construction is split into TBB tasks, run on the threads that
TBB allows (`tbb::global_control`, `tbb::task_arena`):
- during step 1, the tiles of each level are surveyed (the density at their
  new vertices, which samples are kept, which children are subdivided) in
  tasks, those of the next level while the calling thread links the
  triangles of this one; the last level's triangles are made in two halves;
- before step 2, the vertices to remove are looked for in tasks;
- during step 3, the samples are moved, then folded triangles looked for,
  in tasks;
- during step 4, the storage of the TDS is reserved and its faces created,
  empty, in a task beside the Lawson flips (most of the cost of writing a
  TDS is the first touch of its memory);
- while the TDS is written, its faces are given their vertices and
  neighbours, and its vertices their face, in tasks.

The density (and its bound) is then called from several threads at once, and
must be thread-safe; the callback of `build()` is only called from the
calling thread. The tasks create no vertex and call neither the traits nor
the lift; the faces' default constructor is the only code of the TDS that
runs in a task. The triangulation is the same whatever the tag and the
number of threads. What the density throws in a task reaches the caller,
once no task of the construction runs any more.

A construction that would not fit in the machine's memory (its peak is
about 220 bytes per point with the default TDS), or that has more than
about 1.7 x 10<sup>9</sup> points, is refused before anything is allocated:
the constructors and `build()` throw `std::length_error`. The base mesh
follows the tile tree rather than the points, and a `density_upper_bound`
far above the density refines tiles that hold no point: a mesh that would
then outgrow the machine's memory (about 520 bytes per vertex, once it has
outgrown what was reserved for the points) or its 32-bit indices is refused
in the same way before it grows, and the triangulation is left empty.

\tparam Gt a model of `DelaunayTriangulationTraits_2` with exact predicates
        (for example `Exact_predicates_inexact_constructions_kernel`,
        `Exact_predicates_exact_constructions_kernel`,
        `Projection_traits_xy_3<K>` for terrains).
\tparam Tds a `Triangulation_data_structure_2<Vb, Fb>`, with any vertex and
        face bases (the construction finds its faces in their
        `Compact_container` from the order it made them in); `Default` means
        the one of `Delaunay_triangulation_2<Gt>`.
\tparam ConcurrencyTag `Sequential_tag` (the default) or `Parallel_tag`, which
        needs `CGAL_LINKED_WITH_TBB`.
*/
template <class Gt = Exact_predicates_inexact_constructions_kernel, class Tds_ = Default,
          class ConcurrencyTag = Sequential_tag>
class Penrose_Delaunay_triangulation_2
  : public Delaunay_triangulation_2<Gt, typename Default::Get<Tds_, Triangulation_data_structure_2<
                                          Triangulation_vertex_base_2<Gt>, Triangulation_face_base_2<Gt>>>::type>
{
  typedef typename Default::Get<Tds_, Triangulation_data_structure_2<
    Triangulation_vertex_base_2<Gt>, Triangulation_face_base_2<Gt>>>::type Tds;
  typedef Delaunay_triangulation_2<Gt, Tds> Base;

#if !defined(CGAL_LINKED_WITH_TBB)
  static_assert(!(std::is_convertible<ConcurrencyTag, Parallel_tag>::value),
                "Parallel_tag is enabled but TBB is unavailable.");
#endif

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
  /// `ConcurrencyTag`: `Sequential_tag` or `Parallel_tag`.
  typedef ConcurrencyTag Concurrency_tag;

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
  /// \throws what `build()` throws.
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
  /// \throws what `build()` throws.
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
  /// \throws what the constructor of `Penrose_importance_sampler` and
  /// `build()` throw.
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
      advancement of the construction, in [0, 1], from the calling thread; if
      it returns `false`, the construction stops and the triangulation is
      left empty.

  \return `false` if `callback` stopped the construction, `true` otherwise.
  \throws std::length_error, leaving the triangulation as it was, if the
  construction would need more memory than the machine has, or more than
  about 1.7 x 10<sup>9</sup> points; leaving it empty, if its base mesh
  would outgrow them.
  \throws what sampling throws (a bad density, tiles too fine for the
  coordinates: see `Penrose_importance_sampler`), and what the density
  throws, in whichever thread, leaving the triangulation empty.
  */
  template <class SamplerTraits, class Lift, class OnVertex,
            class NamedParameters = parameters::Default_named_parameters>
  bool build(const Penrose_importance_sampler<SamplerTraits>& sampler, const Lift& lift, OnVertex on_vertex,
             const NamedParameters& np = parameters::default_values())
  {
    const std::function<bool(double)> callback =
      parameters::choose_parameter(parameters::get_parameter(np, internal_np::callback), std::function<bool(double)>());
    return internal::Penrose::Triangulation_construction<Penrose_Delaunay_triangulation_2>::run(
      *this, sampler, lift, on_vertex, !std::is_same<OnVertex, No_vertex_visitor>::value, callback, stats_);
  }

  /// Clears the triangulation and builds that of the points of `sampler`,
  /// each made by `lift(x, y)`, as `build(sampler, lift, on_vertex)` does
  /// with a visitor that does nothing, and throws what it throws.
  template <class SamplerTraits, class Lift>
  bool build(const Penrose_importance_sampler<SamplerTraits>& sampler, const Lift& lift)
  {
    return build(sampler, lift, No_vertex_visitor());
  }

  /// Exchanges the triangulations and their construction statistics; throws nothing.
  void swap(Penrose_Delaunay_triangulation_2& other)
  {
    Base::swap(other);
    std::swap(stats_, other.stats_);
  }

  /// \name Statistics of the construction
  /// Those of the last construction or call to `build()`, carried by copies
  /// and swaps; zero if there was none. The operations of
  /// `Delaunay_triangulation_2`, `insert()`, `remove()` and `clear()` among
  /// them, leave them as they are. None of these throws.
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
  struct No_vertex_visitor
  {
    template <class V, class S> void operator()(V, const S&) const {}
  };

  Construction_statistics stats_;
};

} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_H

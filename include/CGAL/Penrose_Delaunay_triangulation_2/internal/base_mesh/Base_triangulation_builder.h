// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The base triangulation of section 3.2 of the paper: the tile tree, made free
// of T-edges, built breadth first straight into a flat mesh.
//
// A new vertex enters the mesh only if it is kept (an active sample that
// lands in the region) or a corner of a tile that is subdivided further:
// the other ones, which section 3.3 would create and remove again, are never
// created, not even as records, and the children around them stay merged
// (Split_patterns). A present vertex on an edge whose other side is a leaf
// splits that leaf's face in two. Two tiles of one level that split a shared
// edge share its vertex: the first that finds it present creates it for
// both, and the first to triangulate leaves its triangles along the edge to
// the second. Only the tiles that are still to be subdivided are held, so
// memory follows the mesh, not the tree.
//
// The faces of a level's tiles are consecutive, in the order of the tiles:
// the face across an edge is a tile's, and which one, by a subtraction, and
// the walks over the tiles read their faces in memory order. A tile's
// triangles that are no such face take its own face first; where every one
// is, its face is taken over by the triangles of the next level, in order,
// before new faces are appended, so that no face stays empty.
//
// What each tile's subdivision decides from the importance field alone (its
// survey) is apart from the mesh. With Sequential_tag each tile is surveyed
// as its vertices are made. With Parallel_tag a level's tiles are surveyed
// in TBB tasks, those of the next level while the calling thread links this
// level's triangles, and the last level's triangles are made in two halves;
// a task faults in the pages of the mesh's arrays ahead of the calling
// thread (Page_population.h).

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_BASE_TRIANGULATION_BUILDER_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_BASE_TRIANGULATION_BUILDER_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/parallel/Concurrency.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/parallel/Page_population.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/flat_mesh/Flat_mesh.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tiling/Sampling_context.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tiling/Tile_subdivision.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Size_limits.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/base_mesh/Split_patterns.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <iomanip>
#include <limits>
#include <memory>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace internal {
namespace Penrose {

class Base_triangulation_builder
{
public:
  typedef Flat_mesh::Index Index;
  static constexpr Index null = Flat_mesh::null;

  // `record_births`: keep what sample() needs (for vertex visitors only);
  // `memory`: the bytes that the mesh may take (0: not checked).
  Base_triangulation_builder(const Sampling_context& context, Flat_mesh& mesh, bool record_births = false,
                             double memory = physical_memory_bytes())
    : Base_triangulation_builder(context, context.region_window(), mesh, record_births, memory)
  {}

  // The same for the samples of `window` only: a tile is subdivided only if
  // a sample of its subtree can land there, and a sample is kept only if it
  // does, so that the mesh is made Delaunay on the region's samples in the
  // window, and a few corners of tiles around it, not samples, to remove.
  Base_triangulation_builder(const Sampling_context& context, const Sample_window& window, Flat_mesh& mesh,
                             bool record_births = false, double memory = physical_memory_bytes())
    : c_(context), window_(window), m_(mesh), record_births_(record_births), memory_(memory)
  {}

  // Where each vertex of the mesh goes: its corrected position if it is an
  // active sample that lands in the region, NaN otherwise (to be removed).
  std::vector<std::pair<double, double>> take_targets() { return std::move(target_); }

  // The sample at kept vertex v, with the data of its leaf tile; needs
  // `record_births`.
  Placed_sample sample(Index v) const
  {
    CGAL_precondition(record_births_);
    Placed_sample s;
    c_.activate(m_.points[v].x(), m_.points[v].y(), importance_[v], birth_[v], s);
    return s;
  }

  // The vertices that build() makes room for: the count varies around the
  // expectation by about a percent. Twice as many faces.
  static std::size_t vertex_capacity(double expected_points)
  {
    return std::size_t(vertex_margin * expected_points) + extra_vertices;
  }

  // The most points whose reservation, twice vertex_capacity() in faces,
  // the mesh's indices can hold.
  static double most_expected_points() { return (0.5 * double(null) - double(extra_vertices)) / vertex_margin; }

  // `expected_points` sizes the arrays once: growing them level after level
  // would fault fresh pages in at every reallocation. `progress(f)`, if set,
  // is called now and then with an estimate f in [0, 1) of the work done;
  // the build stops, returning false, as soon as it returns false; it is
  // called from the calling thread only.
  template <class ConcurrencyTag>
  bool build(double expected_points, const std::function<bool(double)>& progress)
  {
    constexpr bool surveyed_apart = is_parallel<ConcurrencyTag>;
    expected_points_ = expected_points;
    const std::size_t n = vertex_capacity(expected_points);
    m_.points.reserve(n); m_.vertex_face.reserve(n);
    importance_.reserve(n); target_.reserve(n);
    if(record_births_) birth_.reserve(n);
    m_.faces.reserve(2 * n); m_.face_alive.reserve(2 * n);
    // Two consecutive levels' tiles take turns in two blocks, reserved once
    // (untouched pages cost nothing): a level's children are written over its
    // grandparents, in pages already faulted in.
    frontier_.reserve(n); next_.reserve(n); work_.reserve(n);
    if(surveyed_apart) surveys_.reserve(n);
    // about as many vertices as points, and twice as many faces, will be written
    const std::size_t vertices = std::size_t(expected_points);
    const Pages_populated_beside<ConcurrencyTag> populated({first_elements(m_.points, vertices),
                                                            first_elements(m_.vertex_face, vertices),
                                                            first_elements(importance_, vertices),
                                                            first_elements(target_, vertices),
                                                            first_elements(m_.faces, 2 * vertices),
                                                            first_elements(m_.face_alive, 2 * vertices)});
    for(int i = 0; i < 3; ++i) add_vertex(c_.root_x(i), c_.root_y(i), c_.importance(c_.root_x(i), c_.root_y(i)));
    frontier_base_ = m_.create_face(0, 1, 2);
    const Tile root(root_label(), {{0, 1, 2}});
    double rx[3], ry[3];
    for(int i = 0; i < 3; ++i) { rx[i] = m_.points[i].x(); ry[i] = m_.points[i].y(); }
    if(!window_.is_empty() && c_.should_refine(0, 0, rx, ry, importance_.data(), window_)) frontier_.push_back(root);
    // about 1.5 tiles are subdivided per point (1.26 to 1.59 for the constant
    // density and the ramp from 10^5 to 4 x 10^6)
    const double expected_tiles = 1.5 * expected_points + 1.;
    std::size_t tiles_done = 0;
    auto report = [&](double tiles) { return !progress || progress((std::min)(0.99, tiles / expected_tiles)); };
    for(int level = 0; !frontier_.empty(); ++level) {
      c_.check_refinement(tiles_done + frontier_.size());
      work_.assign(frontier_.size(), Work());
      next_.clear();
      const double done = double(tiles_done), half = 0.5 * double(frontier_.size());
      if(surveyed_apart && level == 0) survey_level<ConcurrencyTag>(frontier_, level);
      bool completed =
        for_each_tile(0, frontier_.size(), [&](std::size_t k) { return report(done + 0.5 * k); },
                      [this](const Tile& t) { if(!surveyed_apart) fetch_corners(t, corners()); },
                      [this, level](std::size_t k) {
                        if constexpr(surveyed_apart) create_vertices(k, level, surveys_[k]);
                        else create_vertices(k, level, survey(c_, window_, frontier_[k], level, corners()));
                      });
      if(completed) {
        next_base_ = m_.append_faces(next_.size());
        auto link_triangles = [&] {
          auto proceed = [&](std::size_t k) { return report(done + half + 0.5 * k); };
          completed = (next_.empty() && frontier_.size() >= least_size_for_two_halves)
                        ? create_last_triangles_in_halves<ConcurrencyTag>(proceed)
                        : create_level_triangles(proceed);
        };
        // the next level's tiles are all known: surveyed while this level's triangles are linked
        if(surveyed_apart) run_beside<ConcurrencyTag>([&] { survey_level<ConcurrencyTag>(next_, level + 1); }, link_triangles);
        else link_triangles();
      }
      if(!completed) return false;
      tiles_done += frontier_.size();
      frontier_.swap(next_);
      frontier_base_ = next_base_;
      // the faces given up at this level are taken over at the next one
      recycled_.insert(recycled_.end(), given_up_.begin(), given_up_.end());
      given_up_.clear();
    }
    for(Index f : recycled_) m_.delete_face(f);
    return true;
  }

private:
  // A tile that is to be subdivided; its face is implied (see face_of()).
  // Packed in 32 bytes: every level writes its children and walks its
  // frontier twice, which costs by the byte.
  struct Tile
  {
    Tile() = default;
    // built in place, field by field: a tile assembled on the stack and
    // copied would be reloaded in wider words than it was stored in, and
    // such loads wait for the stores to retire
    Tile(const Tile_label& label, const std::array<Index, 3>& corners)
      : code(label.code), threshold(label.threshold), type(label.type), direction(label.direction),
        refined_children(0), unused(0), corners(corners)
    {}

    std::uint64_t code;
    std::uint64_t threshold : 52;
    std::uint64_t type : 2;              // a Tile_type
    std::uint64_t direction : 5;
    std::uint64_t refined_children : 3;  // bit c: child c is in the next frontier
    std::uint64_t unused : 2;            // set, so that the word is stored whole, not merged into memory
    std::array<Index, 3> corners;

    Tile_type tile_type() const { return static_cast<Tile_type>(type); }
    Tile_label label() const { return {code, threshold, tile_type(), static_cast<std::uint8_t>(direction)}; }
  };
  // thresholds stay below the Fibonacci number of the level after the last
  static_assert(max_level <= 30, "Tile::threshold holds 52 bits");

  // What the subdivision of a tile of the current level needs besides: the
  // new vertex of each split edge. Every tile type splits at most its edge 0
  // and one other edge, so an edge's slot is known without its type (see
  // slot()). Held for one level only, apart from the tiles, to keep them
  // small.
  struct Work
  {
    std::array<Index, 2> new_vertices = {{null, null}};
  };

  static int slot(int edge) { return edge == 0 ? 0 : 1; }

  // What the subdivision of a tile decides from the importance field alone,
  // apart from the mesh: the importance at its new vertices, whether its
  // sample is kept and where it goes, and which children are subdivided
  // further. Not where the new vertices are: recomputed where they enter the
  // mesh, they spare the surveys 32 bytes of fresh memory per tile.
  struct Survey
  {
    Survey() {}  // left as it is: every survey is written before it is read

    std::array<double, 2> importance;        // at new vertex n
    double target_x, target_y;               // of the sample, if kept
    bool kept;
    std::uint8_t refined_children;           // bit c: child c
  };

  // Where a density bound far above the density refines tiles that hold no
  // sample, the mesh follows the tiles, not the points, and outgrows what
  // was reserved for them: its arrays then grow by doubling, and the peak
  // was 219 to 514 bytes per vertex (constant density under bounds 2 to 256
  // times too high, 3 x 10^4 to 10^7 vertices).
  static constexpr double bytes_per_vertex_beyond_reservation = 520.;

  // Throws std::length_error before the mesh's arrays double, if twice as
  // many vertices would overflow its indices (at most two faces per vertex)
  // or the machine's memory.
  void check_room_to_double() const
  {
    std::ostringstream units;
    units << " vertices, for about " << std::setprecision(3) << expected_points_ << " points";
    check_growth(2. * double(m_.points.size()), 0.5 * double(null), bytes_per_vertex_beyond_reservation, memory_,
                 "Penrose_Delaunay_triangulation_2: the base mesh would grow to about ", units.str(),
                 overrefinement_hint);
  }

  static constexpr double vertex_margin = 1.25;
  static constexpr std::size_t extra_vertices = 64;

  // Surveys the tiles of `level` into surveys_, in independent blocks: with
  // Parallel_tag the density is then called from TBB's threads. A block
  // reads nothing through this builder or the mesh: the calling thread may
  // write the ends of their vectors meanwhile, and a read of a word beside
  // them would move that cache line between the cores at each tile (false
  // sharing). The tiles, and the points and importances of their corners,
  // are written before and not meanwhile.
  template <class ConcurrencyTag>
  void survey_level(const std::vector<Tile>& tiles, int level)
  {
    if(surveys_.size() < tiles.size()) surveys_.resize(tiles.size());
    const Tile* t = tiles.data();
    Survey* s = surveys_.data();
    const Corners corners = this->corners();
    const Sampling_context* context = &c_;
    const Sample_window* window = &window_;
    for_each_block<ConcurrencyTag>(tiles.size(), survey_grain, [=](std::size_t b, std::size_t e) {
      for(std::size_t k = b; k < e; ++k) {
        if(k + ahead < e) fetch_corners(t[k + ahead], corners);
        s[k] = survey(*context, *window, t[k], level, corners);
      }
    });
  }

  // tiles per task: a few hundred microseconds of work
  static constexpr std::size_t survey_grain = 1024;

  // The points and importances of the vertices, which a survey reads at a
  // tile's corners; valid while the vertex arrays keep their capacity.
  struct Corners
  {
    const Flat_mesh::Point* points;
    const double* importance;
  };

  Corners corners() const { return {m_.points.data(), importance_.data()}; }

  static void fetch_corners(const Tile& t, const Corners& d)
  {
    for(Index c : t.corners) {
      CGAL_PENROSE_PREFETCH(&d.points[c]);
      CGAL_PENROSE_PREFETCH(&d.importance[c]);
    }
  }

  CGAL_PENROSE_HOT_INLINE static Survey survey(const Sampling_context& context, const Sample_window& window,
                                               const Tile& t, int level, const Corners& d)
  {
    const Subdivision_rule& r = rule(t.tile_type());
    const int child_level = level + 1;
    Survey s;
    s.kept = false;
    s.refined_children = 0;
    double vx[5], vy[5], vi[5];
    for(int i = 0; i < 3; ++i) {
      vx[i] = d.points[t.corners[i]].x(); vy[i] = d.points[t.corners[i]].y(); vi[i] = d.importance[t.corners[i]];
    }
    place_new_vertices(r, vx, vy);
    for(int n = 0; n < r.number_of_new_vertices; ++n) {
      s.importance[n] = vi[3 + n] = context.importance(vx[3 + n], vy[3 + n]);
      Placed_sample p;
      if(r.new_vertices[n].is_sample
         && context.activate(vx[3 + n], vy[3 + n], vi[3 + n], sample_birth(t.label(), r, child_level), p)
         && window.contains(p.x, p.y)) {
        s.kept = true;
        s.target_x = p.x; s.target_y = p.y;
      }
    }
    for(int c = 0; c < r.number_of_children; ++c) {
      const Child_rule& cr = r.children[c];
      double cx[3], cy[3], ci[3];
      for(int i = 0; i < 3; ++i) {
        const int j = cr.corners[i];
        cx[i] = vx[j]; cy[i] = vy[j]; ci[i] = vi[j];
      }
      if(context.should_refine(child_level, child_threshold(t.threshold, cr, child_level), cx, cy, ci, window))
        s.refined_children |= 1u << c;
    }
    return s;
  }

  // The faces that a walk over tiles gives to what is neither a tile's own
  // face nor a child's: a triangle takes one of those given up at the level
  // before while any is left, otherwise a new one, as the half of a leaf
  // face that a tile splits does. New faces are appended one by one
  // (`reserved` null) or taken in order from those reserved at `reserved`.
  struct Face_supply
  {
    const Index* recycled;
    std::size_t recycled_count;
    Index reserved;
    std::size_t recycled_taken, new_taken;
  };

  // What the triangles of a tile take from a Face_supply.
  struct Faces_needed
  {
    std::size_t triangles, splits;
  };

  Index take_face(Face_supply& s)
  {
    if(s.recycled_taken < s.recycled_count) return s.recycled[s.recycled_taken++];
    return take_new_face(s);
  }

  Index take_new_face(Face_supply& s)
  {
    const std::size_t i = s.new_taken++;
    return s.reserved == null ? m_.new_face() : s.reserved + Index(i);
  }

  // Takes nothing, but moves on as if `needed` were taken.
  static void skip(Face_supply& s, const Faces_needed& needed)
  {
    const std::size_t recycled = (std::min)(needed.triangles, s.recycled_count - s.recycled_taken);
    s.recycled_taken += recycled;
    s.new_taken += needed.triangles - recycled + needed.splits;
  }

  // Phase 2 of a level, tile after tile: the tile across an edge is done if
  // it comes before.
  template <class Proceed>
  bool create_level_triangles(const Proceed& proceed)
  {
    Face_supply s{recycled_.data(), recycled_.size(), null, 0, 0};
    Index next_child = 0;
    const bool completed = for_each_tile(0, frontier_.size(), proceed, [](const Tile&) {},
                                         [&](std::size_t k) {
                                           create_triangles(k, next_child, s, [k](Index a) { return a < k; });
                                         });
    recycled_.erase(recycled_.begin(), recycled_.begin() + std::ptrdiff_t(s.recycled_taken));
    return completed;
  }

  // Phase 2 of the last level, which has no children, so that nothing is
  // surveyed meanwhile: the tiles in two halves of the frontier, beside each
  // other with Parallel_tag. Two tiles of different halves may not write the same faces or
  // vertices, which they could only do through a vertex that both touch
  // (a corner of either, or a vertex of a leaf face across an edge of
  // either): each half first marks the vertices that its tiles touch, and
  // counts the faces they will take, so that the faces of each half can be
  // reserved; then each half triangulates its tiles but those that touch a
  // vertex marked by the other, which are postponed, keeping their faces,
  // and done last, in order. Deterministic: the mesh is the same whether the
  // halves run on two threads or one after the other.
  template <class ConcurrencyTag, class Proceed>
  bool create_last_triangles_in_halves(const Proceed& proceed)
  {
    const std::size_t n = frontier_.size(), vertices = m_.points.size();
    // left uninitialized here, to be cleared by the halves
    std::array<std::unique_ptr<unsigned char[]>, 2> marks = {{std::unique_ptr<unsigned char[]>(new unsigned char[vertices]),
                                                             std::unique_ptr<unsigned char[]>(new unsigned char[vertices])}};
    const std::unique_ptr<unsigned char[]> postponed_tile(new unsigned char[n]);
    std::array<Faces_needed, 2> needed;
    run_in_two_halves<ConcurrencyTag>(true, [&](int h) {
      std::fill_n(marks[h].get(), vertices, 0);
      const Half_range tiles = half_of(n, h);
      std::fill(postponed_tile.get() + tiles.begin, postponed_tile.get() + tiles.end, 0);
      needed[h] = mark_touched_vertices(tiles.begin, tiles.end, marks[h].get());
    });

    // each half's share of the given-up faces and of the new ones, as if the
    // second came after the first in one walk
    Face_supply first{recycled_.data(), recycled_.size(), null, 0, 0};
    skip(first, needed[0]);
    Face_supply second{recycled_.data() + first.recycled_taken, recycled_.size() - first.recycled_taken, null, 0, 0};
    skip(second, needed[1]);
    const Index reserved = m_.append_faces(first.new_taken + second.new_taken);
    std::array<Face_supply, 2> supply = {{Face_supply{first.recycled, first.recycled_taken, reserved, 0, 0},
                                          Face_supply{second.recycled, second.recycled_taken,
                                                      reserved + Index(first.new_taken), 0, 0}}};
    const std::size_t recycled_taken = first.recycled_taken + second.recycled_taken;

    std::array<std::vector<std::pair<std::size_t, Face_supply>>, 2> postponed;  // tile, supply before it
    bool completed = true;
    run_in_two_halves<ConcurrencyTag>(true, [&](int h) {
      const unsigned char* other = marks[1 - h].get();
      // the halves' own copies: sharing a cache line, the two would take turns at it
      Face_supply s = supply[h];
      std::vector<std::pair<std::size_t, Face_supply>> later;
      Index next_child = 0;
      auto step = [&](std::size_t k) {
        if(touches_marked_vertex(k, other)) {
          postponed_tile[k] = 1;
          later.emplace_back(k, s);
          skip(s, faces_needed(k));
          return;
        }
        create_triangles(k, next_child, s, [&postponed_tile, k](Index a) { return a < k && !postponed_tile[a]; });
      };
      // only the calling thread asks whether to go on
      auto go_on = [&](std::size_t k) { return h == 1 || proceed(k); };
      const Half_range tiles = half_of(n, h);
      const bool walked = for_each_tile(tiles.begin, tiles.end, go_on, [](const Tile&) {}, step);
      CGAL_assertion(!walked || (s.recycled_taken == s.recycled_count &&
                                 s.new_taken == needed[h].triangles + needed[h].splits - s.recycled_count));
      if(!walked) completed = false;  // by the calling thread only
      postponed[h].swap(later);
    });
    if(!completed) return false;
    Index next_child = 0;
    for(auto& half : postponed)
      for(auto& [k, s] : half) {
        CGAL_assertion_code(Face_supply after = s; skip(after, faces_needed(k));)
        create_triangles(k, next_child, s, [&postponed_tile, k = k](Index a) { return a < k || !postponed_tile[a]; });
        CGAL_assertion(s.recycled_taken == after.recycled_taken && s.new_taken == after.new_taken);
      }
    recycled_.erase(recycled_.begin(), recycled_.begin() + std::ptrdiff_t(recycled_taken));
    return true;
  }

  // Marks the vertices that the triangulation of the tiles from `begin` to
  // `end` touches: their corners and the vertices of the leaf faces across
  // their edges, which the tiles split or link to. Returns the faces they
  // will take.
  Faces_needed mark_touched_vertices(std::size_t begin, std::size_t end, unsigned char* mark) const
  {
    Faces_needed all{0, 0};
    for_each_tile(begin, end, [](std::size_t) { return true; }, [](const Tile&) {}, [&](std::size_t k) {
      any_touched_vertex(k, [mark](Index v) { mark[v] = 1; return false; });
      const Faces_needed f = faces_needed(k);
      all.triangles += f.triangles;
      all.splits += f.splits;
    });
    return all;
  }

  // Whether the triangulation of tile k touches a vertex that `mark` marks
  // (see mark_touched_vertices()). The faces across its edges may have
  // changed since they were marked, but only by tiles of the same half that
  // were not postponed, and then the vertices they hold now are marked as
  // the ones they held were.
  bool touches_marked_vertex(std::size_t k, const unsigned char* mark) const
  {
    return any_touched_vertex(k, [mark](Index v) { return mark[v] != 0; });
  }

  // Whether `pred(v)` holds for a vertex v that the triangulation of tile k
  // touches (its corners, and the vertices of the leaf faces across its
  // edges); stops at the first.
  template <class Pred>
  bool any_touched_vertex(std::size_t k, const Pred& pred) const
  {
    for(Index c : frontier_[k].corners)
      if(pred(c)) return true;
    for(Index g : m_.faces[face_of(k)].n)
      if(is_leaf(g))
        for(Index v : m_.faces[g].v)
          if(pred(v)) return true;
    return false;
  }

  // Whether face g, across an edge of a tile of the last level, is no tile's.
  bool is_leaf(Index g) const { return g != null && tile_of_face(g) == null; }

  // The faces that the triangles of tile k of the last level take: one for
  // each but the first, which is the tile's own, and one for each leaf face
  // that they split.
  Faces_needed faces_needed(std::size_t k) const
  {
    const Tile& t = frontier_[k];
    const Split_pattern& p = split_patterns(t.tile_type(), new_vertex_mask(t, work_[k]));
    const Flat_mesh::Face& own = m_.faces[face_of(k)];
    Faces_needed f{std::size_t(p.number_of_triangles) - 1, 0};
    for(int e = 0; e < 3; ++e)
      if(p.number_of_segments[e] == 2 && is_leaf(own.n[face_edge(e)])) ++f.splits;
    return f;
  }

  // Bit n: new vertex n of tile t is in the mesh.
  static unsigned new_vertex_mask(const Tile& t, const Work& w)
  {
    const Subdivision_rule& r = rule(t.tile_type());
    unsigned mask = 0;
    for(int n = 0; n < r.number_of_new_vertices; ++n)
      if(w.new_vertices[slot(r.new_vertices[n].edge)] != null) mask |= 1u << n;
    return mask;
  }

  // Runs `step(k)` on the tiles k of the frontier from `begin` to `end`,
  // while `proceed(k)`, asked now and then, agrees. The walk is bound by memory: it fetches what
  // a tile reads some steps ahead, its face and `fetch(tile)` first, then,
  // once that face is in, the faces across its edges and their tiles.
  template <class Proceed, class Fetch, class Step>
  bool for_each_tile(std::size_t begin, std::size_t end, const Proceed& proceed, const Fetch& fetch,
                     const Step& step) const
  {
    for(std::size_t k = begin; k < end; ++k) {
      if(k % progress_period == 0 && !proceed(k)) return false;
      if(k + 2 * ahead < end) {
        fetch(frontier_[k + 2 * ahead]);
        CGAL_PENROSE_PREFETCH(&m_.faces[face_of(k + 2 * ahead)]);
      }
      if(k + ahead < end)
        for(Index g : m_.faces[face_of(k + ahead)].n)
          if(g != null) CGAL_PENROSE_PREFETCH(&m_.faces[g]);
      step(k);
    }
    return true;
  }

  static constexpr std::size_t ahead = 8;
  static constexpr std::size_t progress_period = std::size_t(1) << 16;

  // tile edge e (corner e to corner e + 1) is the face edge opposite corner e + 2
  static int face_edge(int e) { return (e + 2) % 3; }

  Index add_vertex(double x, double y, double importance)
  {
    const Index v = m_.add_vertex(x, y);
    importance_.push_back(importance);
    target_.emplace_back(std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN());
    if(record_births_) birth_.push_back(Sample_birth{0, 0, 0, 0});
    return v;
  }

  // The face of tile k of the frontier.
  Index face_of(std::size_t k) const { return frontier_base_ + Index(k); }

  // The tile still to be subdivided whose face is g, or null.
  Index tile_of_face(Index g) const
  {
    return (g != null && g >= frontier_base_ && g - frontier_base_ < frontier_.size()) ? g - frontier_base_ : null;
  }

  // Phase 1: the samples born on the new vertices, and the children that
  // will be subdivided, as the tile's survey decided. A new vertex enters
  // the mesh only once it is known to be present, kept or a corner of a
  // subdivided child (of this tile or of the one across); the two tiles of
  // an edge survey its vertex alike (the same doubles from the same
  // operands).
  void create_vertices(std::size_t k, int level, const Survey& s)
  {
    const Tile& t = frontier_[k];
    Work& w = work_[k];
    const Subdivision_rule& r = rule(t.tile_type());
    const int child_level = level + 1;
    std::array<Index, 5> v = {{t.corners[0], t.corners[1], t.corners[2], null, null}};
    for(int n = 0; n < r.number_of_new_vertices; ++n) {
      const New_vertex_rule& nv = r.new_vertices[n];
      Index& x = w.new_vertices[slot(nv.edge)];
      if(nv.is_sample && s.kept) {
        if(x == null) add_new_vertex(k, n, s.importance[n]);
        target_[x] = {s.target_x, s.target_y};
        if(record_births_) birth_[x] = sample_birth(t.label(), r, child_level);
      }
      v[3 + n] = x;
    }
    for(int c = 0; c < r.number_of_children; ++c) {
      if(!(s.refined_children >> c & 1u)) continue;
      const Child_rule& cr = r.children[c];
      std::array<Index, 3> corners;
      for(int i = 0; i < 3; ++i) {
        const int j = cr.corners[i];
        if(v[j] == null) v[j] = add_new_vertex(k, j - 3, s.importance[j - 3]);
        corners[i] = v[j];
      }
      next_.emplace_back(child_label(t.label(), cr, child_level), corners);
    }
    // written once the tile is read no more: a byte stored into the word that
    // the next child's threshold loads would stall that load
    frontier_[k].refined_children = s.refined_children;
  }

  // Adds new vertex n of tile k, for it and for the tile across its edge,
  // if that one is subdivided at this level too.
  Index add_new_vertex(std::size_t k, int n, double importance)
  {
    if(m_.points.size() == m_.points.capacity() || importance_.size() == importance_.capacity()) check_room_to_double();
    const Tile& t = frontier_[k];
    const New_vertex_rule& nv = rule(t.tile_type()).new_vertices[n];
    const int e = nv.edge;
    const Flat_mesh::Point& a = m_.points[t.corners[nv.near_corner]];
    const Flat_mesh::Point& b = m_.points[t.corners[nv.far_corner]];
    const Index v = add_vertex(split_coordinate(a.x(), b.x()), split_coordinate(a.y(), b.y()), importance);
    work_[k].new_vertices[slot(e)] = v;
    const Index g = m_.faces[face_of(k)].n[face_edge(e)];
    const Index across = tile_of_face(g);
    if(across != null) work_[across].new_vertices[slot_across(g, t, e)] = v;
    return v;
  }

  // How many children of t before child c are in the next frontier.
  static Index refined_before(const Tile& t, int c)
  {
    Index count = 0;
    for(int d = 0; d < c; ++d) count += (t.refined_children >> d) & 1u;
    return count;
  }

  // The new vertex slot, in the tile across the edge e of tile t (face g),
  // of the vertex that splits that edge.
  int slot_across(Index g, const Tile& t, int e) const
  {
    const int ge = m_.edge_index(g, t.corners[(e + 1) % 3], t.corners[e]);
    return slot((ge + 1) % 3);
  }

  // Phase 2: the triangles of the tile, and their links across its edges.
  // `next_child`: where the tile's first child in the next frontier is, if
  // any; advanced past its children (the tiles are walked in the order of
  // phase 1, which placed them). The other new faces come from `supply`;
  // `done(a)` says whether tile a, across an edge, is triangulated.
  template <class Done>
  void create_triangles(std::size_t k, Index& next_child, Face_supply& supply, const Done& done)
  {
    const Tile& t = frontier_[k];
    const Work& w = work_[k];
    const Subdivision_rule& r = rule(t.tile_type());
    std::array<Index, 5> v = {{t.corners[0], t.corners[1], t.corners[2], null, null}};
    for(int n = 0; n < r.number_of_new_vertices; ++n) v[3 + n] = w.new_vertices[slot(r.new_vertices[n].edge)];
    const Split_pattern& p = split_patterns(t.tile_type(), new_vertex_mask(t, w));
    const Index own = face_of(k);
    const Flat_mesh::Face parent = m_.faces[own];

    // a face at each split vertex before this tile's triangles take it over:
    // where the tile across came first, one of the triangles it left
    std::array<Index, 2> left;
    for(int n = 0; n < 2; ++n) left[n] = w.new_vertices[n] == null ? null : m_.vertex_face[w.new_vertices[n]];
    std::array<Index, 3> tri;
    bool own_taken = false;
    for(int f = 0; f < p.number_of_triangles; ++f) {
      const auto& c = p.triangles[f].corners;
      const int child = p.triangles[f].child;
      if(child >= 0 && (t.refined_children >> child & 1u)) tri[f] = next_base_ + next_child + refined_before(t, child);
      else if(!own_taken) { tri[f] = own; own_taken = true; }
      else tri[f] = take_face(supply);
      m_.reset_face(tri[f], v[c[0]], v[c[1]], v[c[2]]);
    }
    for(int f = 0; f < p.number_of_triangles; ++f)
      for(int j = 0; j < 3; ++j)
        if(p.places[f][j].parent_edge < 0) m_.faces[tri[f]].n[j] = tri[p.places[f][j].triangle];
    for(int e = 0; e < 3; ++e) connect_parent_edge(w, left, parent, e, p, tri, supply, done);
    // still the frontier's until this level ends: tile_of_face() must keep finding it
    if(!own_taken) given_up_.push_back(own);
    next_child += refined_before(t, 3);
  }

  template <class Done>
  void connect_parent_edge(const Work& w, const std::array<Index, 2>& left, const Flat_mesh::Face& parent, int e,
                           const Split_pattern& p, const std::array<Index, 3>& tri, Face_supply& supply,
                           const Done& done)
  {
    const Index a = parent.v[e], b = parent.v[(e + 1) % 3];
    const Index g = parent.n[face_edge(e)];
    Index seg[2]; int seg_edge[2];
    for(int s = 0; s < p.number_of_segments[e]; ++s) {
      seg[s] = tri[p.segments[e][s][0]];
      seg_edge[s] = p.segments[e][s][1];
    }
    const Index across = tile_of_face(g);
    if(p.number_of_segments[e] == 1) {  // one segment: whatever lies across now borders it
      if(g != null) m_.link(seg[0], seg_edge[0], g, m_.edge_index(g, b, a));
      return;
    }
    const int n = slot(e);
    const Index x = w.new_vertices[n];
    if(g == null) return;  // the root's boundary
    if(across != null && done(across)) {  // take the triangles it left
      const std::array<Index, 2> f = triangles_left_at(left[n], x, a, b);
      m_.link(seg[0], seg_edge[0], f[0], m_.edge_index(f[0], x, a));
      m_.link(seg[1], seg_edge[1], f[1], m_.edge_index(f[1], b, x));
      return;
    }
    if(across != null) {  // still to come: leave it our triangles
      m_.faces[seg[0]].n[seg_edge[0]] = g;
      m_.faces[seg[1]].n[seg_edge[1]] = g;
      return;
    }
    // a leaf, or part of one: split it at x
    const int ge = m_.edge_index(g, b, a);
    const Index h = m_.split_face_on_edge(g, ge, x, take_new_face(supply));  // g keeps b-x, h takes x-a
    m_.link(seg[0], seg_edge[0], h, 0);
    m_.link(seg[1], seg_edge[1], g, 0);
  }

  // The triangles that the tile across, subdivided earlier in this level,
  // left along the edge a -> b that it split at x: the one with the edge
  // x -> a and the one with the edge b -> x, found by turning around x from
  // h, any of its triangles at x.
  std::array<Index, 2> triangles_left_at(Index h, Index x, Index a, Index b) const
  {
    std::array<Index, 2> f;
    while(m_.faces[h].v[Flat_mesh::ccw(m_.index_of_vertex(h, x))] != a) {
      h = m_.cw_face_around(h, x);
      CGAL_assertion(h != null);
    }
    f[0] = h;
    while(m_.faces[h].v[Flat_mesh::cw(m_.index_of_vertex(h, x))] != b) {
      h = m_.ccw_face_around(h, x);
      CGAL_assertion(h != null);
    }
    f[1] = h;
    return f;
  }

  const Sampling_context& c_;
  const Sample_window window_;
  Flat_mesh& m_;
  const bool record_births_;
  const double memory_;
  double expected_points_ = 0.;
  std::vector<Sample_birth> birth_;  // with record_births_ only
  std::vector<Tile> frontier_, next_;
  std::vector<Work> work_;          // for the tiles of frontier_
  std::vector<Survey> surveys_;     // for the tiles of frontier_, with Parallel_tag
  std::vector<double> importance_;   // per vertex, at the nearest point of the region
  std::vector<std::pair<double, double>> target_;  // see take_targets()
  Index frontier_base_ = 0, next_base_ = 0;  // the faces of the tiles of frontier_ and next_
  std::vector<Index> given_up_;       // at this level, to be taken over at the next
  std::vector<Index> recycled_;       // given up at the levels before, not yet taken
};

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_BASE_TRIANGULATION_BUILDER_H

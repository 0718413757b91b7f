// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Local edits of a Flat_mesh that keep it a valid triangulation: removing an
// interior vertex and filling its star greedily (section 3.3 of the paper),
// and moving a vertex, by removal and reinsertion where its new position
// would fold its star (section 3.4). Every decision is an exact orientation
// test, so points that the Penrose tiling makes collinear are never joined
// by a flat triangle.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_FLAT_MESH_EDITING_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_FLAT_MESH_EDITING_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/flat_mesh/Flat_mesh.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/parallel/Concurrency.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace CGAL {
namespace internal {
namespace Penrose {

class Flat_mesh_editor
{
public:
  typedef Flat_mesh::Index Index;
  static constexpr Index null = Flat_mesh::null;

  explicit Flat_mesh_editor(Flat_mesh& m) : m_(m) {}

  // Removes interior vertex v. Returns false, changing nothing, if v is on the
  // boundary or its star cannot be filled.
  bool remove_vertex(Index v)
  {
    if(!collect_star(v)) return false;
    if(!plan_ears(v)) return false;
    for(Index f : star_) m_.delete_face(f);
    apply_ears();
    m_.vertex_face[v] = null;
    return true;
  }

  // Removes the interior vertices `doomed`, in order, and returns those
  // that remove_vertex() refused; `removed` counts the others. They are
  // sparse in memory, so that each removal would begin with a chain of cache
  // misses: what the next ones read is fetched some removals ahead, in
  // steps (the vertex's face, then that face, then the faces around it ring
  // after ring, with their vertices), each step reading only what the one
  // before fetched. Three rings of faces around one face of a star hold
  // the whole star of a vertex of degree 7 or less, and, up to degree 5, the
  // faces across its ring too, which fetching only the first ring would
  // leave to cache misses.
  std::vector<Index> remove_vertices(const std::vector<Index>& doomed, std::size_t& removed)
  {
    std::vector<Index> refused;
    const std::size_t n = doomed.size();
    auto face_ahead = [&](std::size_t k) { return k < n ? m_.vertex_face[doomed[k]] : null; };
    for(std::size_t k = 0; k < n; ++k) {
      if(k + 12 < n) CGAL_PENROSE_PREFETCH(&m_.vertex_face[doomed[k + 12]]);
      if(k + 8 < n) CGAL_PENROSE_PREFETCH(&m_.points[doomed[k + 8]]);
      if(const Index f = face_ahead(k + 8); f != null) CGAL_PENROSE_PREFETCH(&m_.faces[f]);
      if(const Index f = face_ahead(k + 4); f != null) fetch_rings(f, 0);
      if(const Index f = face_ahead(k + 2); f != null) fetch_rings(f, 1);
      if(const Index f = face_ahead(k + 1); f != null) fetch_rings(f, 2);
      if(remove_vertex(doomed[k])) ++removed;
      else refused.push_back(doomed[k]);
    }
    return refused;
  }

  // Moves vertex v to (px, py). Returns false if the point cannot be placed
  // (it coincides with another vertex, or lies outside the mesh); v is then
  // removed from the mesh.
  bool move_vertex(Index v, double px, double py, bool& repaired)
  {
    repaired = false;
    if(!collect_star(v)) return false;
    bool fits = true;
    const Flat_mesh::Point p(px, py);
    for(std::size_t i = 0; i < ring_.size() && fits; ++i)
      fits = m_.orientation(ring_[i], ring_[(i + 1) % ring_.size()], p) == POSITIVE;
    if(fits) { m_.points[v] = p; return true; }
    repaired = true;
    const Index start = ring_[0];
    if(!remove_vertex(v)) return false;
    m_.points[v] = p;
    return insert_vertex(v, m_.vertex_face[start]);
  }

  // Moves every vertex v whose target (x, y) is not NaN there at once. Where a face
  // would fold, its moved vertices go back, until no face folds; those are
  // then moved one at a time with move_vertex(). Returns the vertices that
  // could not be placed (removed from the mesh) and counts the repairs.
  // The vertices moved at once trade places with their targets, so that no
  // copy of the positions is needed for the way back: on return `target`
  // holds their former positions, and still the targets of the vertices
  // that went back (moved one at a time, or returned).
  // With Parallel_tag, the moves at once and the search for folds are TBB
  // tasks.
  template <class ConcurrencyTag, class Targets>
  std::vector<Index> move_vertices(Targets& target, std::size_t& repaired)
  {
    const std::size_t n = m_.points.size();
    std::vector<char> state(n, 0);  // 1: moved, 2: sent back
    auto trade = [&](Index v) {
      const Flat_mesh::Point p = m_.points[v];
      m_.points[v] = Flat_mesh::Point(target[v].first, target[v].second);
      target[v] = {p.x(), p.y()};
    };
    // The moves at once, and the search for folds, read or write each
    // vertex's or face's own data: they can be split in blocks.
    for_each_block<ConcurrencyTag>(target.size(), walk_block, [&](std::size_t begin, std::size_t end) {
      for(std::size_t v = begin; v < end; ++v)
        if(!std::isnan(target[v].first) && m_.vertex_face[v] != null &&
           (target[v].first != m_.points[v].x() || target[v].second != m_.points[v].y())) {
          trade(Index(v));
          state[v] = 1;
        }
    });
    std::vector<Index> folded = gather_in_blocks<Index, ConcurrencyTag>(
      m_.faces.size(), [&](std::size_t begin, std::size_t end, std::vector<Index>& found) {
        for(std::size_t f = begin; f < end; ++f) {
          if(f + Flat_mesh::fetch_distance < end)
            for(Index u : m_.faces[f + Flat_mesh::fetch_distance].v) CGAL_PENROSE_PREFETCH(&m_.points[u]);
          if(m_.face_alive[f] && !positive(Index(f))) found.push_back(Index(f));
        }
      });
    std::vector<Index> next, sent_back;
    while(!folded.empty()) {
      next.clear();
      for(Index f : folded) {
        if(positive(f)) continue;
        for(int i = 0; i < 3; ++i) {
          const Index u = m_.faces[f].v[i];
          if(state[u] != 1) continue;
          state[u] = 2;
          sent_back.push_back(u);
          trade(u);
          faces_around(u, next);
        }
      }
      folded.clear();
      for(Index f : next) if(!positive(f)) folded.push_back(f);
    }
    std::vector<Index> unplaced;
    repaired = 0;
    std::sort(sent_back.begin(), sent_back.end());  // moved in the order of the vertices
    for(Index u : sent_back) {
      bool r = false;
      if(!move_vertex(u, target[u].first, target[u].second, r)) unplaced.push_back(u);
      if(r) ++repaired;
    }
    return unplaced;
  }

  // Inserts the (detached) vertex v, whose coordinates are set, walking from face f.
  bool insert_vertex(Index v, Index f)
  {
    int on_edge = -1;
    f = locate(m_.points[v], f, on_edge);
    if(f == null) return false;
    if(on_edge < 0) split_in_three(f, v);
    else if(!split_edge(f, on_edge, v)) return false;
    return true;
  }

private:
  // Fetches the vertices of f and the faces next to it, and so on for
  // `depth` more rings of faces.
  void fetch_rings(Index f, int depth) const
  {
    for(int i = 0; i < 3; ++i) {
      const Index g = m_.faces[f].n[i];
      if(depth == 0) {
        CGAL_PENROSE_PREFETCH(&m_.points[m_.faces[f].v[i]]);
        if(g != null) CGAL_PENROSE_PREFETCH(&m_.faces[g]);
      } else if(g != null) {
        fetch_rings(g, depth - 1);
      }
    }
  }

  bool positive(Index f) const
  {
    const Flat_mesh::Face& F = m_.faces[f];
    return m_.orientation(F.v[0], F.v[1], F.v[2]) == POSITIVE;
  }

  void faces_around(Index v, std::vector<Index>& out) const
  {
    const Index f0 = m_.vertex_face[v];
    Index f = f0;
    do {
      out.push_back(f);
      f = m_.ccw_face_around(f, v);
    } while(f != f0 && f != null);
  }

  // Ring of the star of v, counter-clockwise, with the faces across its edges.
  bool collect_star(Index v)
  {
    star_.clear(); ring_.clear(); across_.clear();
    const Index f0 = m_.vertex_face[v];
    if(f0 == null) return false;
    Index f = f0;
    do {
      const Flat_mesh::Face& F = m_.faces[f];
      const int i = m_.index_of_vertex(f, v);
      const Index a = F.v[Flat_mesh::ccw(i)], b = F.v[Flat_mesh::cw(i)];
      const Index g = F.n[i];  // null where the ring edge is on the boundary
      star_.push_back(f);
      ring_.push_back(a);
      across_.push_back({g, g == null ? 0 : m_.edge_index(g, b, a)});
      f = F.n[Flat_mesh::ccw(i)];
      if(f == null || star_.size() > 4096) return false;
    } while(f != f0);
    return ring_.size() >= 3;
  }

  // Chooses the ears that triangulate the ring, without touching the mesh.
  // The ring is star-shaped around the removed vertex v, so a convex corner
  // whose diagonal leaves v on its inner side is an ear; the general test,
  // against every other ring vertex, is the fallback.
  bool plan_ears(Index v)
  {
    if(plan_ears_with([&](const std::vector<int>&, int p, int q, int r) {
         return m_.orientation(ring_[p], ring_[q], ring_[r]) == POSITIVE &&
                m_.orientation(ring_[p], ring_[r], v) != NEGATIVE;
       }))
      return true;
    return plan_ears_with([&](const std::vector<int>& idx, int p, int q, int r) { return is_ear(idx, p, q, r); });
  }

  template <class Ear_test>
  bool plan_ears_with(Ear_test is_valid_ear)
  {
    ears_.clear();
    std::vector<int> idx(ring_.size());
    for(std::size_t i = 0; i < idx.size(); ++i) idx[i] = int(i);
    std::size_t start = 0;
    while(idx.size() > 3) {
      bool found = false;
      const std::size_t n = idx.size();
      for(std::size_t s = 0; s < n && !found; ++s) {
        const std::size_t t = (start + s) % n;
        const int p = idx[(t + n - 1) % n], q = idx[t], r = idx[(t + 1) % n];
        if(!is_valid_ear(idx, p, q, r)) continue;
        ears_.push_back({p, q, r});
        idx.erase(idx.begin() + std::ptrdiff_t(t));
        start = t % idx.size();
        found = true;
      }
      if(!found) return false;
    }
    if(m_.orientation(ring_[idx[0]], ring_[idx[1]], ring_[idx[2]]) != POSITIVE) return false;
    ears_.push_back({idx[0], idx[1], idx[2]});
    return true;
  }

  bool is_ear(const std::vector<int>& idx, int p, int q, int r) const
  {
    const Index a = ring_[p], b = ring_[q], c = ring_[r];
    if(m_.orientation(a, b, c) != POSITIVE) return false;
    for(int u : idx) {
      if(u == p || u == q || u == r) continue;
      const Index w = ring_[u];
      if(m_.orientation(a, b, w) != NEGATIVE && m_.orientation(b, c, w) != NEGATIVE &&
         m_.orientation(c, a, w) != NEGATIVE)
        return false;
    }
    return true;
  }

  // Creates the planned faces, gluing each to the ring's outside or to the
  // ear cut before it across the polygon edge it closes.
  void apply_ears()
  {
    const std::size_t k = ring_.size();
    // the face and edge across the polygon edge that starts at ring index i
    std::vector<std::pair<Index, int>> side(across_.begin(), across_.end());
    std::vector<int> next(k);
    for(std::size_t i = 0; i < k; ++i) next[i] = int((i + 1) % k);
    for(const auto& e : ears_) {
      const int p = e[0], q = e[1], r = e[2];
      const Index f = m_.create_face(ring_[p], ring_[q], ring_[r]);
      m_.link(f, 2, side[p].first, side[p].second);  // edge p -> q
      m_.link(f, 0, side[q].first, side[q].second);  // edge q -> r
      if(next[q] == r && next[r] == p) { m_.link(f, 1, side[r].first, side[r].second); break; }  // the last triangle
      side[p] = {f, 1};     // the new polygon edge p -> r
      next[p] = r;
    }
  }

  // Walks from face f to the face containing p. on_edge is set to the
  // index of the edge the point lies on, or -1 inside. Null if the point is
  // outside the mesh or on a vertex.
  Index locate(const Flat_mesh::Point& p, Index f, int& on_edge) const
  {
    for(int step = 0; f != null && step < 100000; ++step) {
      const Flat_mesh::Face& F = m_.faces[f];
      int zero = -1, zeros = 0;
      bool moved = false;
      for(int s = 0; s < 3 && !moved; ++s) {
        const int i = (s + step) % 3;
        const Orientation o = m_.orientation(F.v[Flat_mesh::ccw(i)], F.v[Flat_mesh::cw(i)], p);
        if(o == NEGATIVE) { f = F.n[i]; moved = true; }
        else if(o == COLLINEAR) { zero = i; ++zeros; }
      }
      if(moved) continue;
      if(zeros >= 2) return null;  // on a vertex
      on_edge = zero;
      return f;
    }
    return null;
  }

  void split_in_three(Index f, Index v)
  {
    const Flat_mesh::Face F = m_.faces[f];
    const Index g = m_.create_face(v, F.v[1], F.v[2]);
    const Index h = m_.create_face(F.v[0], v, F.v[2]);
    m_.reset_face(f, F.v[0], F.v[1], v);
    m_.inherit_neighbor(g, 0, F.n[0], f);
    m_.inherit_neighbor(h, 1, F.n[1], f);
    m_.faces[f].n[2] = F.n[2];  // which still borders f
    m_.link(g, 1, h, 0);
    m_.link(g, 2, f, 0);
    m_.link(h, 2, f, 1);
    m_.vertex_face[F.v[0]] = f; m_.vertex_face[F.v[1]] = f; m_.vertex_face[F.v[2]] = g;
    m_.vertex_face[v] = f;
  }

  // Splits the two faces of edge i of f at v, which lies on the edge.
  bool split_edge(Index f, int i, Index v)
  {
    const Index g = m_.faces[f].n[i];
    if(g == null) return false;
    const Index a = m_.faces[f].v[Flat_mesh::ccw(i)], b = m_.faces[f].v[Flat_mesh::cw(i)];
    const int j = m_.edge_index(g, b, a);
    const Index f2 = m_.split_face_on_edge(f, i, v);  // f: a-v, f2: v-b
    const Index g2 = m_.split_face_on_edge(g, j, v);  // g: b-v, g2: v-a
    m_.link(f, 0, g2, 0);
    m_.link(f2, 0, g, 0);
    return true;
  }

  Flat_mesh& m_;
  std::vector<Index> star_, ring_;
  std::vector<std::pair<Index, int>> across_;
  std::vector<std::array<int, 3>> ears_;
};

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_FLAT_MESH_EDITING_H

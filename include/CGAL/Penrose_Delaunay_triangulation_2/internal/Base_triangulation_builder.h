// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The base triangulation of section 3.2 of the paper: the tile tree, made free
// of T-edges, built breadth first straight into a flat mesh.
//
// A new vertex enters the mesh only if it is kept (an active sample that
// lands in the region) or a corner of a tile that is subdivided further:
// the other ones, which section 3.3 would create and remove again, are never
// created, and the children around them stay merged (Split_patterns). A
// present vertex on an edge whose other side is a leaf splits that leaf's
// face in two. Two tiles of one level that split a shared edge share its
// vertex: the first to reach it leaves it, and later its triangles along the
// edge, to the second. Only the tiles that are still to be subdivided are
// held, so memory follows the mesh, not the tree.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_BASE_TRIANGULATION_BUILDER_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_BASE_TRIANGULATION_BUILDER_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Flat_mesh.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Sampling_context.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Split_patterns.h>

#include <CGAL/assertions.h>

#include <array>
#include <cstdint>
#include <limits>
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

  // Per vertex, after build(): whether it is a sample of the region, and if
  // so where its correction takes it.
  struct Vertex_state
  {
    Sample_birth birth;
    bool is_sample;
    signed char kept;       // -1: not decided yet
  };

  Base_triangulation_builder(const Sampling_context& context, Flat_mesh& mesh)
    : c_(context), m_(mesh)
  {}

  const std::vector<Vertex_state>& vertices() const { return v_; }

  // Where each vertex of the mesh goes: its corrected position if it is an
  // active sample that lands in the region, NaN otherwise (to be removed).
  // Each sample is activated once, during the build or here.
  std::vector<std::pair<double, double>> take_targets()
  {
    for(Index v = 0; v < v_.size(); ++v)
      if(m_.vertex_face[v] != null && v_[v].kept < 0) decide(v);
    return std::move(target_);
  }

  // The sample at kept vertex v, with the data of its leaf tile.
  Placed_sample sample(Index v) const
  {
    Placed_sample s;
    c_.activate(m_.x[v], m_.y[v], importance_[v], v_[v].birth, s);
    return s;
  }

  // `expected_points` sizes the arrays once: growing them level after level
  // would fault fresh pages in at every reallocation.
  void build(double expected_points)
  {
    const std::size_t n = std::size_t(1.25 * expected_points) + 64;
    m_.x.reserve(n); m_.y.reserve(n); m_.vertex_face.reserve(n);
    v_.reserve(n); needed_.reserve(n); importance_.reserve(n); target_.reserve(n);
    m_.faces.reserve(2 * n); m_.face_alive.reserve(2 * n);
    face_tile_.assign(2 * n, null);
    frontier_.reserve(n); next_.reserve(n);
    for(int i = 0; i < 3; ++i) add_vertex(c_.root_x(i), c_.root_y(i));
    const Tile root = {0, 0, {{0, 1, 2}}, m_.create_face(0, 1, 2), FAT_F, 15};
    if(c_.should_refine(0, m_.x.data(), m_.y.data(), importance_.data())) frontier_.push_back(root);
    for(int level = 0; !frontier_.empty(); ++level) {
      if(face_tile_.size() < m_.faces.size()) face_tile_.resize(m_.faces.size() + m_.faces.size() / 2, null);
      for(std::size_t k = 0; k < frontier_.size(); ++k) face_tile_[frontier_[k].face] = Index(k);
      work_.assign(frontier_.size(), Work());
      next_.clear();
      for(std::size_t k = 0; k < frontier_.size(); ++k) create_vertices(k, level);
      for(std::size_t k = 0; k < frontier_.size(); ++k) create_triangles(k);
      for(const Tile& t : frontier_) if(t.face < face_tile_.size()) face_tile_[t.face] = null;
      frontier_.swap(next_);
    }
  }

private:
  // A tile that is to be subdivided.
  struct Tile
  {
    std::uint64_t code, threshold;
    std::array<Index, 3> corners;
    Index face;
    Tile_type type;
    std::uint8_t direction;
  };

  // What the subdivision of a tile of the current level needs besides: its
  // new vertices and children, and what its neighbours across each edge left
  // for it (the vertex they created there, then their triangles along it).
  // Held for one level only, apart from the tiles, to keep them small.
  struct Work
  {
    std::array<Index, 2> new_vertices = {{null, null}};
    std::array<Index, 3> child_slot = {{null, null, null}};  // in the next frontier
    std::array<Index, 3> pending_vertex = {{null, null, null}};
    std::array<std::array<Index, 2>, 3> pending_triangles = {{{{null, null}}, {{null, null}}, {{null, null}}}};
  };

  // tile edge e (corner e to corner e + 1) is the face edge opposite corner e + 2
  static int face_edge(int e) { return (e + 2) % 3; }

  Index add_vertex(double x, double y)
  {
    const Index v = m_.add_vertex(x, y);
    importance_.push_back(c_.importance(x, y));
    Vertex_state s;
    s.birth = Sample_birth{0, 0, 0, 0};
    s.is_sample = false;
    s.kept = -1;
    v_.push_back(s);
    needed_.push_back(0);
    target_.emplace_back(std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::quiet_NaN());
    return v;
  }

  // The tile still to be subdivided whose face is g, or null.
  Index tile_of_face(Index g) const
  {
    return (g == null || g >= face_tile_.size()) ? null : face_tile_[g];
  }

  // Phase 1: the new vertices, their samples, and the children that will be
  // subdivided (their corners are needed).
  void create_vertices(std::size_t k, int level)
  {
    const Tile& t = frontier_[k];
    Work& w = work_[k];
    const Subdivision_rule& r = rule(t.type);
    const Flat_mesh::Face& face = m_.faces[t.face];
    const int child_level = level + 1;
    std::array<Index, 5> v = {{t.corners[0], t.corners[1], t.corners[2], null, null}};
    double vx[5], vy[5], vi[5];
    for(int i = 0; i < 3; ++i) { vx[i] = m_.x[v[i]]; vy[i] = m_.y[v[i]]; vi[i] = importance_[v[i]]; }
    for(int n = 0; n < r.number_of_new_vertices; ++n) {
      const New_vertex_rule& nv = r.new_vertices[n];
      const int a = nv.near_corner, b = nv.far_corner;
      vx[3 + n] = vx[a] + split_fraction * (vx[b] - vx[a]);
      vy[3 + n] = vy[a] + split_fraction * (vy[b] - vy[a]);
      Index x = w.pending_vertex[nv.edge];
      if(x == null) {
        x = add_vertex(vx[3 + n], vy[3 + n]);
        // a tile across that is still to come will split the edge here too
        const Index across = tile_of_face(face.n[face_edge(nv.edge)]);
        if(across != null && across > k) {
          const Index g = face.n[face_edge(nv.edge)];
          const int ge = m_.edge_index(g, t.corners[(nv.edge + 1) % 3], t.corners[nv.edge]);
          work_[across].pending_vertex[(ge + 1) % 3] = x;
        }
      }
      v[3 + n] = x;
      vi[3 + n] = importance_[x];
      w.new_vertices[n] = x;
      if(nv.is_sample) {
        Vertex_state& s = v_[x];
        s.is_sample = true;
        s.birth = Sample_birth{ t.code * 4 + r.sample_code_pair,
                                t.threshold + pair_weight(r.sample_code_pair, child_level),
                                static_cast<std::uint8_t>(child_level),
                                add_direction(t.direction, r.sample_direction_step) };
      }
    }
    for(int c = 0; c < r.number_of_children; ++c) {
      const Child_rule& cr = r.children[c];
      double cx[3], cy[3], ci[3];
      Tile child;
      for(int i = 0; i < 3; ++i) {
        const int ci_ = cr.corners[i];
        child.corners[i] = v[ci_]; cx[i] = vx[ci_]; cy[i] = vy[ci_]; ci[i] = vi[ci_];
      }
      if(!c_.should_refine(child_level, cx, cy, ci)) continue;
      child.code = t.code * 4 + cr.code_pair;
      child.threshold = t.threshold + pair_weight(cr.code_pair, child_level);
      child.face = null;
      child.type = cr.type;
      child.direction = add_direction(t.direction, cr.direction_step);
      for(Index corner : child.corners) needed_[corner] = 1;
      w.child_slot[c] = Index(next_.size());
      next_.push_back(child);
    }
  }

  bool present(Index x)
  {
    if(needed_[x]) return true;
    if(v_[x].kept < 0) decide(x);
    return v_[x].kept > 0;
  }

  // Whether x is an active sample whose corrected position is in the region.
  void decide(Index x)
  {
    Vertex_state& s = v_[x];
    s.kept = s.is_sample && c_.activate(m_.x[x], m_.y[x], importance_[x], s.birth, scratch_)
             && c_.contains(scratch_.x, scratch_.y);
    if(s.kept) target_[x] = {scratch_.x, scratch_.y};
  }

  // Phase 2: the triangles of the tile, and their links across its edges.
  void create_triangles(std::size_t k)
  {
    const Tile& t = frontier_[k];
    const Work& w = work_[k];
    const Subdivision_rule& r = rule(t.type);
    unsigned mask = 0;
    for(int n = 0; n < r.number_of_new_vertices; ++n)
      if(present(w.new_vertices[n])) mask |= 1u << n;
    const Split_pattern& p = split_patterns(t.type, mask);
    const Flat_mesh::Face parent = m_.faces[t.face];
    const std::array<Index, 5> v = {{t.corners[0], t.corners[1], t.corners[2], w.new_vertices[0], w.new_vertices[1]}};

    std::array<Index, 3> tri;
    for(int f = 0; f < p.number_of_triangles; ++f) {
      const auto& c = p.triangles[f].corners;
      if(f == 0) { tri[f] = t.face; m_.reset_face(t.face, v[c[0]], v[c[1]], v[c[2]]); }
      else tri[f] = m_.create_face(v[c[0]], v[c[1]], v[c[2]]);
    }
    for(int f = 0; f < p.number_of_triangles; ++f)
      for(int j = 0; j < 3; ++j)
        if(p.places[f][j].parent_edge < 0) m_.faces[tri[f]].n[j] = tri[p.places[f][j].triangle];
    for(int e = 0; e < 3; ++e) connect_parent_edge(t, w, k, parent, e, p, tri);
    // the children to subdivide next take their triangles
    for(int f = 0; f < p.number_of_triangles; ++f) {
      const int c = p.triangles[f].child;
      if(c >= 0 && w.child_slot[c] != null) next_[w.child_slot[c]].face = tri[f];
    }
    for(int c = 0; c < 3; ++c) CGAL_assertion(w.child_slot[c] == null || next_[w.child_slot[c]].face != null);
  }

  void connect_parent_edge(const Tile& t, const Work& w, std::size_t k, const Flat_mesh::Face& parent, int e,
                           const Split_pattern& p, const std::array<Index, 3>& tri)
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
    const Index x = w.new_vertices[rule(t.type).new_vertices[0].edge == e ? 0 : 1];
    if(w.pending_triangles[e][0] != null) {  // the tile across is done: take its triangles
      const Index f0 = w.pending_triangles[e][0], f1 = w.pending_triangles[e][1];
      m_.link(seg[0], seg_edge[0], f0, m_.edge_index(f0, x, a));
      m_.link(seg[1], seg_edge[1], f1, m_.edge_index(f1, b, x));
      return;
    }
    if(g == null) return;  // the root's boundary
    if(across != null && across > k) {  // still to come: leave it our triangles
      const int ge = m_.edge_index(g, b, a);
      work_[across].pending_triangles[(ge + 1) % 3] = {{seg[1], seg[0]}};
      m_.faces[seg[0]].n[seg_edge[0]] = g;
      m_.faces[seg[1]].n[seg_edge[1]] = g;
      return;
    }
    // a leaf, or part of one: split it at x
    const int ge = m_.edge_index(g, b, a);
    CGAL_assertion(ge >= 0);
    const Index h = m_.split_face_on_edge(g, ge, x);  // g keeps b-x, h takes x-a
    m_.link(seg[0], seg_edge[0], h, 0);
    m_.link(seg[1], seg_edge[1], g, 0);
  }

  const Sampling_context& c_;
  Flat_mesh& m_;
  std::vector<Vertex_state> v_;
  std::vector<char> needed_;         // a corner of a tile that is subdivided
  std::vector<Tile> frontier_, next_;
  std::vector<Work> work_;           // for the tiles of frontier_
  std::vector<double> importance_;   // per vertex, at the nearest point of the region
  std::vector<std::pair<double, double>> target_;  // see take_targets()
  Placed_sample scratch_;
  std::vector<Index> face_tile_;     // frontier tile of an intact face, or null
};

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_BASE_TRIANGULATION_BUILDER_H

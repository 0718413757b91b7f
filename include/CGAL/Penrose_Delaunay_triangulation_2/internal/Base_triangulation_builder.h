// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The base triangulation of section 3.2 of the paper: the tile tree, made free
// of T-edges, built breadth first straight into a flat mesh. Each subdivided
// tile is replaced by its children; a new vertex on an edge whose other side
// is a leaf splits that leaf's face in two. Two tiles of one level that split
// a shared edge share its vertex: the first to subdivide leaves the vertex and
// its children along the edge to the second. Only the current level of tiles
// is held, so memory follows the mesh, not the tree.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_BASE_TRIANGULATION_BUILDER_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_BASE_TRIANGULATION_BUILDER_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Flat_mesh.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Sampling_context.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Tile_edge_tables.h>

#include <CGAL/assertions.h>

#include <array>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace internal {
namespace Penrose {

// What a vertex of the base triangulation knows of its sample.
struct Vertex_sample
{
  double importance;
  Sample_birth birth;
  bool is_sample;
};

class Base_triangulation_builder
{
public:
  typedef Flat_mesh::Index Index;
  static constexpr Index null = Flat_mesh::null;

  Base_triangulation_builder(const Sampling_context& context, Flat_mesh& mesh,
                             std::vector<Vertex_sample>& samples)
    : c_(context), m_(mesh), s_(samples)
  {}

  void build()
  {
    for(int i = 0; i < 3; ++i) add_vertex(c_.root_x(i), c_.root_y(i));
    const Index root = m_.create_face(0, 1, 2);
    frontier_.push_back(Tile{0, 0, root, FAT_F, 15, false, {}});
    for(int level = 0; !frontier_.empty(); ++level) {
      index_frontier(level);
      next_.clear();
      for(std::size_t k = 0; k < frontier_.size(); ++k)
        if(frontier_[k].refine) subdivide(k, level);
      for(const Tile& t : frontier_) face_tile_[t.face] = null;
      frontier_.swap(next_);
    }
  }

private:
  // The split of a shared edge that the tile on the other side made first:
  // the vertex, and that tile's children along the edge, in this tile's order.
  struct Pending
  {
    Index vertex = null;
    std::array<Index, 2> faces = {{null, null}};
  };

  struct Tile
  {
    std::uint64_t code, threshold;
    Index face;
    Tile_type type;
    std::uint8_t direction;
    bool refine;
    std::array<Pending, 3> pending;  // by tile edge
  };

  // tile edge e (corner e to corner e + 1) is the face edge opposite corner e + 2
  static int face_edge(int e) { return (e + 2) % 3; }

  Index add_vertex(double x, double y)
  {
    const Index v = m_.add_vertex(x, y);
    s_.push_back(Vertex_sample{c_.importance(x, y), Sample_birth{0, 0, 0, 0}, false});
    return v;
  }

  void index_frontier(int level)
  {
    if(face_tile_.size() < m_.faces.size()) face_tile_.resize(m_.faces.size() + m_.faces.size() / 2, null);
    for(std::size_t k = 0; k < frontier_.size(); ++k) {
      Tile& t = frontier_[k];
      face_tile_[t.face] = Index(k);
      double x[3], y[3], importance[3];
      for(int i = 0; i < 3; ++i) {
        const Index v = m_.faces[t.face].v[i];
        x[i] = m_.x[v]; y[i] = m_.y[v]; importance[i] = s_[v].importance;
      }
      t.refine = c_.should_refine(level, x, y, importance);
    }
  }

  // The frontier tile whose intact face is g and that will subdivide later in
  // this pass, or null.
  Index refining_tile_of(Index g) const
  {
    if(g == null || g >= face_tile_.size()) return null;
    const Index k = face_tile_[g];
    return (k != null && frontier_[k].refine) ? k : null;
  }

  void subdivide(std::size_t k, int level)
  {
    const Tile t = frontier_[k];
    face_tile_[t.face] = null;  // its face becomes a child's
    const Subdivision_rule& r = rule(t.type);
    const Tile_edge_tables& tables = tile_edge_tables();
    const Flat_mesh::Face parent = m_.faces[t.face];
    const int child_level = level + 1;

    std::array<Index, 5> v = {{parent.v[0], parent.v[1], parent.v[2], null, null}};
    for(int n = 0; n < r.number_of_new_vertices; ++n) {
      const New_vertex_rule& nv = r.new_vertices[n];
      Index& x = v[3 + n];
      x = t.pending[nv.edge].vertex;
      if(x == null) {
        const Index a = v[nv.near_corner], b = v[nv.far_corner];
        x = add_vertex(m_.x[a] + split_fraction * (m_.x[b] - m_.x[a]),
                       m_.y[a] + split_fraction * (m_.y[b] - m_.y[a]));
      }
      if(nv.is_sample) {
        s_[x].is_sample = true;
        s_[x].birth = Sample_birth{ t.code * 4 + r.sample_code_pair,
                                    t.threshold + pair_weight(r.sample_code_pair, child_level),
                                    static_cast<std::uint8_t>(child_level),
                                    add_direction(t.direction, r.sample_direction_step) };
      }
    }

    std::array<Index, 3> cf;
    for(int c = 0; c < r.number_of_children; ++c) {
      const Child_rule& cr = r.children[c];
      const Index a = v[cr.corners[0]], b = v[cr.corners[1]], d = v[cr.corners[2]];
      if(c == 0) { cf[c] = t.face; m_.reset_face(t.face, a, b, d); }
      else cf[c] = m_.create_face(a, b, d);
      next_.push_back(Tile{ t.code * 4 + cr.code_pair, t.threshold + pair_weight(cr.code_pair, child_level),
                            cf[c], cr.type, add_direction(t.direction, cr.direction_step), false, {} });
    }
    for(int c = 0; c < r.number_of_children; ++c)
      for(int j = 0; j < 3; ++j) {
        const Child_edge_place& p = tables.places[t.type][c][j];
        if(!p.on_parent_edge)
          m_.faces[cf[c]].n[face_edge(j)] = cf[p.sibling.child];
      }
    for(int e = 0; e < 3; ++e) connect_parent_edge(t, parent, e, v, cf);
  }

  // Links the children along parent edge e to what lies across it.
  void connect_parent_edge(const Tile& t, const Flat_mesh::Face& parent, int e,
                           const std::array<Index, 5>& v, const std::array<Index, 3>& cf)
  {
    const Tile_edge_tables& tables = tile_edge_tables();
    const int segments = tables.number_of_segments[t.type][e];
    const Index a = parent.v[e], b = parent.v[(e + 1) % 3];
    const Index g = parent.n[face_edge(e)];
    Index child[2]; int child_edge[2];
    for(int s = 0; s < segments; ++s) {
      child[s] = cf[tables.segments[t.type][e][s].child];
      child_edge[s] = face_edge(tables.segments[t.type][e][s].edge);
    }
    if(segments == 1) {            // unsplit: whatever is across now borders the child
      if(g == null) return;
      m_.link(child[0], child_edge[0], g, m_.edge_index(g, b, a));
      return;
    }
    const Index x = v[3 + tables.new_vertex_on_edge[t.type][e]];
    const Pending& pending = t.pending[e];
    if(pending.vertex != null) {   // the tile across split the edge first
      m_.link(child[0], child_edge[0], pending.faces[0], m_.edge_index(pending.faces[0], x, a));
      m_.link(child[1], child_edge[1], pending.faces[1], m_.edge_index(pending.faces[1], b, x));
      return;
    }
    if(g == null) return;          // the root's boundary
    const Index across = refining_tile_of(g);
    if(across != null) {           // it will subdivide later: leave it the split
      Tile& n = frontier_[across];
      const int ge = m_.edge_index(g, b, a);
      const int ne = (ge + 1) % 3;  // its tile edge
      n.pending[ne].vertex = x;
      n.pending[ne].faces = {{child[1], child[0]}};
      m_.faces[child[0]].n[child_edge[0]] = g;
      m_.faces[child[1]].n[child_edge[1]] = g;
      return;
    }
    // a leaf (or part of one): split its face at x
    const int ge = m_.edge_index(g, b, a);
    CGAL_assertion(ge >= 0);
    const Index h = m_.split_face_on_edge(g, ge, x);  // g: b-x, h: x-a
    m_.link(child[0], child_edge[0], h, 0);
    m_.link(child[1], child_edge[1], g, 0);
  }

  const Sampling_context& c_;
  Flat_mesh& m_;
  std::vector<Vertex_sample>& s_;
  std::vector<Tile> frontier_, next_;
  std::vector<Index> face_tile_;  // frontier tile of an intact face, or null
};

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_BASE_TRIANGULATION_BUILDER_H

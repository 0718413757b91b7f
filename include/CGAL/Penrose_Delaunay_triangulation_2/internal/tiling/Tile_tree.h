// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The sampler's tile tree, built breadth first and stored in two contiguous
// arrays: tiles, level after level, and vertices. Tiles sharing an edge share
// its vertices, with the very doubles of the depth-first sampler, and each
// tile knows the tile across each of its edges (at its own level, or a
// coarser one), so the tree can be walked with no search. The tests check the
// tiling on it (the geometry of the tiles, their neighbours, the F-codes, the
// pruning) and its samples against the sampler's; the triangulation builds
// its base mesh with Base_triangulation_builder instead, straight from the
// rules. The point-like A and B tiles of the 2004 system are not stored: a
// sample is a vertex flagged with the data of the A tile born there.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TILE_TREE_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TILE_TREE_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tiling/Sampling_context.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tiling/Tile_subdivision.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Size_limits.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tiling/Tile_edge_tables.h>

#include <CGAL/assertions.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace CGAL {
namespace internal {
namespace Penrose {

class Tile_tree
{
public:
  // The index of a tile in `tiles()` or of a vertex in `vertices()`.
  typedef std::uint32_t Index;
  // No tile: across the root's boundary.
  static constexpr Index null_index = 0xffffffffu;
  // A triangular tile.
  struct Tile
  {
    std::uint64_t f_code;            // the tile's F-code, its path from the root, two bits a level
    std::array<Index, 3> vertices;   // counter-clockwise; edge i runs from vertex i to vertex i+1
    std::array<Index, 3> neighbors;  // tile across edge i, or `null_index` on the root's boundary
    Index first_child;               // children are consecutive
    Tile_type type;                  // two skinny (C, D) and two fat (E, F)
    std::uint8_t direction;          // its orientation, in steps of 18 degrees counter-clockwise from North
    std::uint8_t level;              // its level, 0 for the root
    std::uint8_t number_of_children; // 0 for a leaf
  };

  // A vertex of the tiles.
  struct Vertex
  {
    double x;                               // abscissa, before any correction
    double y;                               // ordinate, before any correction
    double importance;                      // at the nearest point of the region
    Sample_birth birth;                     // valid when `is_sample`
    bool is_sample;                         // an A tile is born here
  };

  // Builds the tree that `context` describes.
  explicit Tile_tree(const Sampling_context& context)
    : context_(context)
  {
    build();
  }

  // The number of levels, the root's included.
  int number_of_levels() const { return int(level_begin_.size()) - 1; }
  // The first tile of level `l`: the tiles of a level are consecutive.
  Index level_begin(int l) const { return level_begin_[l]; }
  // Past the last tile of level `l`.
  Index level_end(int l) const { return level_begin_[l + 1]; }
  // All tiles, level after level.
  const std::vector<Tile>& tiles() const { return tiles_; }
  // All vertices.
  const std::vector<Vertex>& vertices() const { return vertices_; }
  // Tile `t`.
  const Tile& tile(Index t) const { return tiles_[t]; }
  // Vertex `v`.
  const Vertex& vertex(Index v) const { return vertices_[v]; }
  // Whether tile `t` has no children.
  bool is_leaf(Index t) const { return tiles_[t].number_of_children == 0; }
  // Child `k` of tile `t`, for `k` below its `number_of_children`.
  Index child(Index t, int k) const { return tiles_[t].first_child + Index(k); }
  // The tile across edge `edge` of tile `t` (see `Tile::neighbors`).
  Index neighbor(Index t, int edge) const { return tiles_[t].neighbors[edge]; }
  // The length scale of the tiles of `t`'s level: the root's, divided by the golden ratio at each level.
  double scale(Index t) const { return context_.scale(tiles_[t].level); }
  // The sampling context the tree was built from.
  const Sampling_context& context() const { return context_; }

  // The edge of `n` whose neighbour is `t`, for two tiles of one level that share an edge.
  int facing_edge(Index n, Index t) const
  {
    const Tile& tn = tiles_[n];
    for(int i = 0; i < 3; ++i)
      if(tn.neighbors[i] == t) return i;
    CGAL_assertion_msg(false, "the two tiles are not linked");
    return -1;
  }

  // Number of children of subdivided tile `t` along its edge `edge` (1 or
  // 2); writes each child and its edge index, from corner `edge` on.
  int children_along_edge(Index t, int edge, std::array<std::pair<Index, int>, 2>& out) const
  {
    const auto& tables = tile_edge_tables();
    const Tile& tt = tiles_[t];
    const int n = tables.number_of_segments[tt.type][edge];
    for(int s = 0; s < n; ++s) {
      const auto& ce = tables.segments[tt.type][edge][s];
      out[s] = {tt.first_child + ce.child, ce.edge};
    }
    return n;
  }

  // The vertex that splits edge `edge` of subdivided tile `t`, or `null_index`.
  Index split_vertex(Index t, int edge) const
  {
    const auto& tables = tile_edge_tables();
    const Tile& tt = tiles_[t];
    const int k = tables.new_vertex_on_edge[tt.type][edge];
    if(k < 0) return null_index;
    const auto& ce = tables.corner_of_new_vertex[tt.type][k];
    return tiles_[tt.first_child + ce.child].vertices[ce.edge];
  }

  // Calls `f(vertex_index, sample)` for every active sample whose corrected
  // position lies in the region, with its Placed_sample.
  template <class F>
  void for_each_sample(F&& f) const
  {
    Placed_sample s;
    for(Index v = 0; v < vertices_.size(); ++v) {
      const Vertex& vx = vertices_[v];
      if(vx.is_sample && context_.activate(vx.x, vx.y, vx.importance, vx.birth, s)
         && context_.contains(s.x, s.y))
        f(v, s);
    }
  }

private:
  void build()
  {
    for(int i = 0; i < 3; ++i)
      add_vertex(context_.root_x(i), context_.root_y(i));
    const Tile_label root = root_label();
    tiles_.push_back(Tile{root.code, {{0, 1, 2}}, {{null_index, null_index, null_index}}, null_index,
                          root.type, root.direction, 0, 0});
    level_begin_ = {0, 1};
    std::size_t refined = 0;
    for(int level = 0; level_begin_[level] < level_begin_[level + 1]; ++level) {
      for(Index t = level_begin_[level]; t < level_begin_[level + 1]; ++t)
        if(should_refine(t)) {
          context_.check_refinement(++refined);
          if(tiles_.size() + 3 > tiles_.capacity()) check_room_to_grow(level);
          subdivide(t);
        }
      level_begin_.push_back(Index(tiles_.size()));
    }
    level_begin_.pop_back();
  }

  // Before the tiles' array grows to twice its size: the peak, with the
  // vertices' array beside it, was 50 to 60 bytes per tile of the grown
  // array (10^5 to 3 x 10^7 tiles, a density bound 1 to 512 times too high).
  void check_room_to_grow(int level) const
  {
    check_growth(2. * double(tiles_.size()) + 3., double(null_index), 80.,
                                    physical_memory_bytes(),
                                    "the tile tree would grow to about ",
                                    " tiles at level " + std::to_string(level + 1),
                                    overrefinement_hint);
  }

  Index add_vertex(double x, double y)
  {
    Vertex v;
    v.x = x; v.y = y;
    v.importance = context_.importance(x, y);
    v.birth = Sample_birth{0, 0, 0, 0};
    v.is_sample = false;
    vertices_.push_back(v);
    return Index(vertices_.size() - 1);
  }

  bool should_refine(Index t) const
  {
    double x[3], y[3], importance[3];
    for(int i = 0; i < 3; ++i) {
      const Vertex& v = vertices_[tiles_[t].vertices[i]];
      x[i] = v.x; y[i] = v.y; importance[i] = v.importance;
    }
    return context_.should_refine(tiles_[t].level, tile_threshold(t), x, y, importance);
  }

  // A same-level neighbour that is already subdivided, or null_index.
  Index subdivided_twin(const Tile& tt, int edge) const
  {
    const Index n = tt.neighbors[edge];
    if(n == null_index) return null_index;
    const Tile& tn = tiles_[n];
    return (tn.level == tt.level && tn.number_of_children > 0) ? n : null_index;
  }

  void subdivide(Index t)
  {
    const Tile tt = tiles_[t];
    const Tile_label label = label_of(t);
    const Subdivision_rule& r = rule(tt.type);
    const int child_level = tt.level + 1;
    std::array<Index, 5> v = {{tt.vertices[0], tt.vertices[1], tt.vertices[2], null_index, null_index}};
    for(int k = 0; k < r.number_of_new_vertices; ++k) {
      const New_vertex_rule& nv = r.new_vertices[k];
      const Index twin = subdivided_twin(tt, nv.edge);
      if(twin != null_index) {
        v[3 + k] = split_vertex(twin, facing_edge(twin, t));
        CGAL_assertion(v[3 + k] != null_index);
      } else {
        const Vertex& a = vertices_[v[nv.near_corner]];
        const Vertex& b = vertices_[v[nv.far_corner]];
        v[3 + k] = add_vertex(split_coordinate(a.x, b.x), split_coordinate(a.y, b.y));
      }
      if(nv.is_sample) {
        Vertex& s = vertices_[v[3 + k]];
        s.is_sample = true;
        s.birth = sample_birth(label, r, child_level);
      }
    }
    const Index first = Index(tiles_.size());
    for(int c = 0; c < r.number_of_children; ++c) {
      const Child_rule& cr = r.children[c];
      const Tile_label child = child_label(label, cr, child_level);
      tiles_.push_back(Tile{ child.code, {{v[cr.corners[0]], v[cr.corners[1]], v[cr.corners[2]]}},
                             {{null_index, null_index, null_index}}, null_index, child.type, child.direction,
                             static_cast<std::uint8_t>(child_level), 0 });
    }
    tiles_[t].first_child = first;
    tiles_[t].number_of_children = r.number_of_children;
    link_children(t, first);
  }

  void link_children(Index t, Index first)
  {
    const auto& tables = tile_edge_tables();
    const Tile& tt = tiles_[t];
    for(int c = 0; c < tt.number_of_children; ++c)
      for(int j = 0; j < 3; ++j) {
        const auto& p = tables.places[tt.type][c][j];
        Index& slot = tiles_[first + c].neighbors[j];
        if(!p.on_parent_edge) { slot = first + p.sibling.child; continue; }
        const Index twin = subdivided_twin(tt, p.parent_edge);
        if(twin == null_index) { slot = tt.neighbors[p.parent_edge]; continue; }
        std::array<std::pair<Index, int>, 2> across;
        const int n = children_along_edge(twin, facing_edge(twin, t), across);
        CGAL_assertion(n == tables.number_of_segments[tt.type][p.parent_edge]);
        const auto& other = across[n - 1 - p.segment];  // the twin runs the edge backwards
        slot = other.first;
        tiles_[other.first].neighbors[other.second] = first + c;
      }
  }

  // Fibonacci value of a tile's F-code, all 2 level bits of it.
  std::uint64_t tile_threshold(Index t) const
  {
    return fibonacci_value(tiles_[t].f_code, 2 * tiles_[t].level);
  }

  Tile_label label_of(Index t) const
  {
    return {tiles_[t].f_code, tile_threshold(t), tiles_[t].type, tiles_[t].direction};
  }

  Sampling_context context_;
  std::vector<Tile> tiles_;
  std::vector<Vertex> vertices_;
  std::vector<Index> level_begin_;
};

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TILE_TREE_H

// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// One step of the subdivision of a tile, written once for the three walks
// of the tile tree (the depth-first sampler, Tile_tree and the base mesh's
// builder): where its new vertices are, and what its label (F-code,
// threshold, type, direction) passes on to its children and to the A tile
// born at its sample vertex. The walks differ only in what they keep.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TILE_SUBDIVISION_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TILE_SUBDIVISION_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tiling/Fibonacci_code.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tiling/Penrose_rules.h>

#include <cstdint>

namespace CGAL {
namespace internal {
namespace Penrose {

// The data of the A tile born at a vertex, fixed at birth.
struct Sample_birth
{
  std::uint64_t code;      // F-code of the A tile at its birth level
  std::uint64_t threshold; // Fibonacci value of that code
  std::uint8_t level;
  std::uint8_t direction;
};

// What a tile's place in the tree decides: its F-code (its path from the
// root, two bits a level), the Fibonacci value of that code, which its
// sample's threshold and its children's start from, its type and its
// direction (in steps of 18 degrees counter-clockwise from North).
struct Tile_label
{
  std::uint64_t code;
  std::uint64_t threshold;
  Tile_type type;
  std::uint8_t direction;
};

// The root tile's label.
constexpr Tile_label root_label() { return {0, 0, FAT_F, 15}; }

// The threshold of child `cr` of a tile of threshold `threshold`, the
// child at level `child_level`: all a walk needs to decide whether to
// subdivide the child.
inline std::uint64_t child_threshold(std::uint64_t threshold, const Child_rule& cr, int child_level)
{
  return threshold + pair_weight(cr.code_pair, child_level);
}

// A name of the sample born with `b`, the same in every traversal: tile
// codes are unique within a level (two bits a level, distinct among
// siblings) and a tile bears at most one sample, so that the birth level and
// code tell samples apart; the level is the leading bit above the code's
// 2 level bits (level <= 31: below 2^63).
inline std::uint64_t sample_key(const Sample_birth& b)
{
  return (std::uint64_t(1) << (2 * b.level)) + b.code;
}

// The label of child `cr` of a tile labelled `t`, at level `child_level`.
inline Tile_label child_label(const Tile_label& t, const Child_rule& cr, int child_level)
{
  return {t.code * 4 + cr.code_pair, child_threshold(t.threshold, cr, child_level), cr.type,
          add_direction(t.direction, cr.direction_step)};
}

// The A tile born at the sample vertex of a tile labelled `t`, subdivided
// by `r` into children of level `child_level`.
inline Sample_birth sample_birth(const Tile_label& t, const Subdivision_rule& r, int child_level)
{
  return {t.code * 4 + r.sample_code_pair, t.threshold + pair_weight(r.sample_code_pair, child_level),
          static_cast<std::uint8_t>(child_level), add_direction(t.direction, r.sample_direction_step)};
}

// The new vertices of a tile subdivided by `r`, after its corners: x[3 + k]
// and y[3 + k] from x[0..2] and y[0..2]. Two tiles that share an edge split
// it into the same doubles (see split_coordinate()).
inline void place_new_vertices(const Subdivision_rule& r, double* x, double* y)
{
  for(int k = 0; k < r.number_of_new_vertices; ++k) {
    const New_vertex_rule& nv = r.new_vertices[k];
    x[3 + k] = split_coordinate(x[nv.near_corner], x[nv.far_corner]);
    y[3 + k] = split_coordinate(y[nv.near_corner], y[nv.far_corner]);
  }
}

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TILE_SUBDIVISION_H

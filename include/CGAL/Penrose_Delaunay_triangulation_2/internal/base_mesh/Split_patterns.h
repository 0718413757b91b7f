// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How a subdivided tile is triangulated when only some of its new vertices
// enter the mesh. With all of them the triangles are the children; where a
// vertex is left out, the children around it merge, and the merged region is
// again a triangle (for E and F the split at the remaining vertex). Each
// pattern lists its triangles over corner indices (0..2 the tile's corners,
// 3..4 its new vertices) and where each triangle edge lies.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_SPLIT_PATTERNS_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_SPLIT_PATTERNS_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tiling/Penrose_rules.h>

#include <array>
#include <cstdint>

namespace CGAL {
namespace internal {
namespace Penrose {

struct Split_pattern
{
  struct Triangle
  {
    std::array<std::uint8_t, 3> corners;
    std::int8_t child;  // the child tile it is, or -1 for a merged region
  };
  // where edge j of a triangle (opposite corner j, CGAL's convention) lies
  struct Edge_place
  {
    std::int8_t parent_edge;   // tile edge e (corner e to e + 1), or -1 inside
    std::uint8_t segment;      // 0: the part holding corner e
    std::uint8_t triangle, edge;  // inside: the triangle across and its edge
  };
  std::uint8_t number_of_triangles;
  std::array<Triangle, 3> triangles;
  std::array<std::array<Edge_place, 3>, 3> places;
  // along tile edge e: the triangles and their edges, from corner e on
  std::array<std::uint8_t, 3> number_of_segments;
  std::array<std::array<std::array<std::uint8_t, 2>, 2>, 3> segments;
};

class Split_patterns
{
public:
  Split_patterns()
  {
    // masks: bit k set when new vertex k is in the mesh
    typedef Split_pattern::Triangle T;
    set(SKINNY_C, 0, {T{{{0, 1, 2}}, -1}});
    set(SKINNY_C, 1, {T{{{2, 0, 3}}, 0}, T{{{1, 3, 0}}, 1}});
    set(SKINNY_D, 0, {T{{{0, 1, 2}}, -1}});
    set(SKINNY_D, 1, {T{{{1, 2, 3}}, 0}, T{{{3, 0, 1}}, 1}});
    set(FAT_E, 0, {T{{{0, 1, 2}}, -1}});
    set(FAT_E, 1, {T{{{0, 3, 2}}, -1}, T{{{1, 2, 3}}, 1}});
    set(FAT_E, 2, {T{{{0, 1, 4}}, -1}, T{{{4, 1, 2}}, -1}});
    set(FAT_E, 3, {T{{{2, 4, 3}}, 0}, T{{{1, 2, 3}}, 1}, T{{{0, 3, 4}}, 2}});
    set(FAT_F, 0, {T{{{0, 1, 2}}, -1}});
    set(FAT_F, 1, {T{{{2, 0, 3}}, 0}, T{{{3, 1, 2}}, -1}});
    set(FAT_F, 2, {T{{{0, 1, 4}}, -1}, T{{{0, 4, 2}}, -1}});
    set(FAT_F, 3, {T{{{2, 0, 3}}, 0}, T{{{3, 1, 4}}, 1}, T{{{4, 2, 3}}, 2}});
  }

  const Split_pattern& operator()(Tile_type t, unsigned mask) const { return patterns_[t][mask]; }

private:
  void set(Tile_type t, unsigned mask, std::initializer_list<Split_pattern::Triangle> triangles)
  {
    const Subdivision_rule& r = rule(t);
    Split_pattern& p = patterns_[t][mask];
    p.number_of_triangles = std::uint8_t(triangles.size());
    p.number_of_segments = {{1, 1, 1}};
    for(int k = 0; k < r.number_of_new_vertices; ++k)
      if(mask >> k & 1u) p.number_of_segments[r.new_vertices[k].edge] = 2;
    std::copy(triangles.begin(), triangles.end(), p.triangles.begin());
    for(int f = 0; f < p.number_of_triangles; ++f)
      for(int j = 0; j < 3; ++j) {
        const int a = p.triangles[f].corners[(j + 1) % 3], b = p.triangles[f].corners[(j + 2) % 3];
        Split_pattern::Edge_place& place = p.places[f][j];
        place.parent_edge = -1;
        for(int e = 0; e < 3; ++e)
          if(lies_on_edge(r, a, e) && lies_on_edge(r, b, e)) {
            place.parent_edge = std::int8_t(e);
            place.segment = (a == e) ? 0 : 1;
          }
        if(place.parent_edge >= 0) {
          p.segments[place.parent_edge][place.segment] = {{std::uint8_t(f), std::uint8_t(j)}};
          continue;
        }
        for(int g = 0; g < p.number_of_triangles; ++g)
          for(int k = 0; k < 3; ++k)
            if(p.triangles[g].corners[(k + 1) % 3] == b && p.triangles[g].corners[(k + 2) % 3] == a) {
              place.triangle = std::uint8_t(g);
              place.edge = std::uint8_t(k);
            }
      }
  }

  std::array<std::array<Split_pattern, 4>, 4> patterns_;
};

inline const Split_patterns split_patterns;

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_SPLIT_PATTERNS_H

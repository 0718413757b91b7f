// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Where the edges of a tile's children lie: on a sibling, or on a segment of
// one of the parent's edges. Derived once from the subdivision rules.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TILE_EDGE_TABLES_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TILE_EDGE_TABLES_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tiling/Penrose_rules.h>

#include <CGAL/assertions.h>

#include <array>
#include <cstdint>

namespace CGAL {
namespace internal {
namespace Penrose {

// Edge i of a tile runs from its corner i to its corner i + 1 (mod 3).
struct Child_edge
{
  std::uint8_t child, edge;
};

struct Child_edge_place
{
  bool on_parent_edge;
  std::uint8_t parent_edge, segment;  // when on a parent edge: segment 0 holds corner parent_edge
  Child_edge sibling;                 // otherwise: the sibling's edge across
};

struct Tile_edge_tables
{
  // segments[type][parent edge]: the children's edges along it, from its first corner
  std::array<std::array<std::array<Child_edge, 2>, 3>, 4> segments;
  std::array<std::array<std::uint8_t, 3>, 4> number_of_segments;
  std::array<std::array<std::array<Child_edge_place, 3>, 3>, 4> places;
  // corner_of_new_vertex[type][k]: a child and its corner that is new vertex k
  std::array<std::array<Child_edge, 2>, 4> corner_of_new_vertex;
  // new_vertex_on_edge[type][edge]: index of the new vertex splitting it, or -1
  std::array<std::array<std::int8_t, 3>, 4> new_vertex_on_edge;

  Tile_edge_tables()
  {
    for(int t = 0; t < 4; ++t) {
      const Subdivision_rule& r = rule(Tile_type(t));
      new_vertex_on_edge[t] = {{-1, -1, -1}};
      for(int k = 0; k < r.number_of_new_vertices; ++k) {
        new_vertex_on_edge[t][r.new_vertices[k].edge] = std::int8_t(k);
        for(int c = 0; c < r.number_of_children; ++c)
          for(int j = 0; j < 3; ++j)
            if(r.children[c].corners[j] == 3 + k) corner_of_new_vertex[t][k] = {std::uint8_t(c), std::uint8_t(j)};
      }
      number_of_segments[t] = {{0, 0, 0}};
      for(int c = 0; c < r.number_of_children; ++c)
        for(int j = 0; j < 3; ++j) {
          const int a = r.children[c].corners[j], b = r.children[c].corners[(j + 1) % 3];
          Child_edge_place& p = places[t][c][j];
          p.on_parent_edge = false;
          for(int e = 0; e < 3; ++e)
            if(lies_on_edge(r, a, e) && lies_on_edge(r, b, e)) {
              p.on_parent_edge = true;
              p.parent_edge = std::uint8_t(e);
              p.segment = (a == e) ? 0 : 1;
            }
          if(!p.on_parent_edge)
            for(int c2 = 0; c2 < r.number_of_children; ++c2)
              for(int j2 = 0; j2 < 3; ++j2)
                if(r.children[c2].corners[j2] == b && r.children[c2].corners[(j2 + 1) % 3] == a)
                  p.sibling = {std::uint8_t(c2), std::uint8_t(j2)};
        }
      for(int e = 0; e < 3; ++e)
        for(int c = 0; c < r.number_of_children; ++c)
          for(int j = 0; j < 3; ++j) {
            const Child_edge_place& p = places[t][c][j];
            if(p.on_parent_edge && p.parent_edge == e) {
              segments[t][e][p.segment] = {std::uint8_t(c), std::uint8_t(j)};
              ++number_of_segments[t][e];
            }
          }
    }
  }
};

inline const Tile_edge_tables& tile_edge_tables()
{
  static const Tile_edge_tables tables;
  return tables;
}

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TILE_EDGE_TABLES_H

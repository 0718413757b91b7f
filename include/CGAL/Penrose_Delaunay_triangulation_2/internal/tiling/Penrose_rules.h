// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The subdivision rules of the Penrose tiles of Ostromoukhov, Donohue and
// Jodoin (2004), written as tables over corner indices.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_PENROSE_RULES_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_PENROSE_RULES_H

#include <array>
#include <cmath>
#include <cstdint>

namespace CGAL {
namespace internal {
namespace Penrose {

// The triangular tiles. The point-like tiles A and B of the 2004 system are
// not stored: a sample is a tile vertex plus the data of the A tile that is
// born there (see Sample_birth).
enum Tile_type : std::uint8_t { SKINNY_C = 0, SKINNY_D = 1, FAT_E = 2, FAT_F = 3 };

constexpr double golden_ratio = 1.6180339887498948482;
// Every new vertex splits an edge at this fraction from its "near" end, so the
// two tiles sharing the edge compute the same double from the same operands.
constexpr double split_fraction = 0.38196601125010515180; // 1 / phi^2

// The coordinate of a new vertex, from those of its near and far corners:
// every traversal computes it here, so that all get the same double.
inline double split_coordinate(double near, double far) { return near + split_fraction * (far - near); }

// Unit vector of direction d (steps of 18 degrees, 0 = North, counter-clockwise).
// Built so that u(d + 10) == -u(d) and the axis directions are exact.
struct Direction_table
{
  std::array<double, 20> x, y;
  Direction_table()
  {
    for(int d = 0; d < 5; ++d) {
      const long double a = 3.14159265358979323846264338327950288L * d / 10.0L;
      const double s = static_cast<double>(std::sin(a));
      const double c = static_cast<double>(std::cos(a));
      // u(d) = (-sin, cos); u(d+5) = (-cos, -sin); u(d+10) = -u(d); u(d+15) = -u(d+5)
      x[d] = (d == 0) ? 0. : -s;          y[d] = c;
      x[d + 5] = -c;                      y[d + 5] = (d == 0) ? 0. : -s;
      x[d + 10] = -x[d];                  y[d + 10] = -y[d];
      x[d + 15] = -x[d + 5];              y[d + 15] = -y[d + 5];
    }
  }
};

inline const Direction_table direction_table;
inline const Direction_table& directions() { return direction_table; }

// Corner indices 0..2 are the parent's p1..p3; 3 and 4 are its new vertices.
struct New_vertex_rule
{
  std::uint8_t edge;        // parent edge (i, i+1 mod 3) that the vertex splits
  std::uint8_t near_corner; // split point = near + split_fraction * (far - near)
  std::uint8_t far_corner;
  bool is_sample;           // an A tile is born here
};

struct Child_rule
{
  Tile_type type;
  std::uint8_t direction_step; // added to the parent's direction, mod 20
  std::uint8_t code_pair;      // two bits appended to the F-code
  std::array<std::uint8_t, 3> corners;
};

struct Subdivision_rule
{
  std::uint8_t number_of_new_vertices;
  std::array<New_vertex_rule, 2> new_vertices;
  std::uint8_t number_of_children;
  std::array<Child_rule, 3> children;
  // the A tile born at the sample vertex (if any)
  std::uint8_t sample_direction_step;
  std::uint8_t sample_code_pair;
};

// The geometry of the children follows from C.2 and C.3 of the sampler facts:
// C splits its long edge p2p3, D its long edge p3p1, E its base p1p2 and its
// leg p3p1, F its base p1p2 and its leg p2p3. Matching rules make the two
// tiles on either side of an edge split it at the same point.
inline const std::array<Subdivision_rule, 4>& subdivision_rules()
{
  static const std::array<Subdivision_rule, 4> rules = {{
    // C -> F(p3,p1,X) C(p2,X,p1), sample A at X
    { 1, {{ {1, 1, 2, true}, {0, 0, 0, false} }},
      2, {{ {FAT_F, 14, 0, {{2, 0, 3}}}, {SKINNY_C, 6, 1, {{1, 3, 0}}}, {SKINNY_C, 0, 0, {{0, 0, 0}}} }},
      1, 1 },
    // D -> E(p2,p3,Y) D(Y,p1,p2), no sample
    { 1, {{ {2, 0, 2, false}, {0, 0, 0, false} }},
      2, {{ {FAT_E, 6, 0, {{1, 2, 3}}}, {SKINNY_D, 14, 1, {{3, 0, 1}}}, {SKINNY_C, 0, 0, {{0, 0, 0}}} }},
      0, 0 },
    // E -> C(p3,N,M) E(p2,p3,M) F(p1,M,N), M on p1p2, sample A at N on p3p1
    { 2, {{ {0, 1, 0, false}, {2, 2, 0, true} }},
      3, {{ {SKINNY_C, 12, 1, {{2, 4, 3}}}, {FAT_E, 8, 2, {{1, 2, 3}}}, {FAT_F, 0, 0, {{0, 3, 4}}} }},
      7, 1 },
    // F -> F(p3,p1,P) E(P,p2,Q) D(Q,p3,P), sample A at P on p1p2, Q on p2p3
    { 2, {{ {0, 0, 1, true}, {1, 2, 1, false} }},
      3, {{ {FAT_F, 12, 2, {{2, 0, 3}}}, {FAT_E, 0, 0, {{3, 1, 4}}}, {SKINNY_D, 8, 1, {{4, 2, 3}}} }},
      15, 2 }
  }};
  return rules;
}

inline const Subdivision_rule& rule(Tile_type t) { return subdivision_rules()[t]; }

// Whether corner index a of rule r (0..2 the corners, 3.. the new vertices)
// lies on the tile's edge e, from corner e to corner e + 1.
inline bool lies_on_edge(const Subdivision_rule& r, int a, int e)
{
  if(a < 3) return a == e || a == (e + 1) % 3;
  return r.new_vertices[a - 3].edge == e;
}

inline std::uint8_t add_direction(std::uint8_t d, std::uint8_t step)
{
  return static_cast<std::uint8_t>((d + step) % 20);
}

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_PENROSE_RULES_H

// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The circumcircle of a triangle as every window computes it. Which window
// owns a triangle is decided on its circumcentre, and windows that build
// the same triangle apart must decide alike: the centre is computed from
// the three points in lexicographic order, whatever order a mesh gives
// them in, with the same operations, so that it is the same double
// everywhere.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_CANONICAL_CIRCUMCIRCLE_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_CANONICAL_CIRCUMCIRCLE_H

#include <cmath>
#include <utility>

namespace CGAL {
namespace internal {
namespace Penrose {

struct Circumcircle
{
  double x, y;        // centre, not finite for a triangle that doubles see flat
  double radius;

  bool is_finite() const { return std::isfinite(x) && std::isfinite(y) && std::isfinite(radius); }
};

struct Xy
{
  double x, y;
};

inline bool lexicographically_smaller(const Xy& a, const Xy& b)
{
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

inline Circumcircle canonical_circumcircle(Xy a, Xy b, Xy c)
{
  if(lexicographically_smaller(b, a)) std::swap(a, b);
  if(lexicographically_smaller(c, b)) std::swap(b, c);
  if(lexicographically_smaller(b, a)) std::swap(a, b);
  // relative to the smallest point, where the terms are small
  const double bx = b.x - a.x, by = b.y - a.y, cx = c.x - a.x, cy = c.y - a.y;
  const double b2 = bx * bx + by * by, c2 = cx * cx + cy * cy;
  const double d = 2. * (bx * cy - by * cx);
  const double ux = (cy * b2 - by * c2) / d, uy = (bx * c2 - cx * b2) / d;
  return {a.x + ux, a.y + uy, std::sqrt(ux * ux + uy * uy)};
}

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_CANONICAL_CIRCUMCIRCLE_H

// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Floating-point filters for the two predicates that the flat mesh's walks
// call millions of times: they return the sign of the determinant where
// doubles certainly get it right, and ZERO where they may not, for the
// caller to ask Epick's exact predicate.
//
// The error bounds are those of the first stage of Shewchuk's adaptive
// predicates ("Adaptive precision floating-point arithmetic and fast robust
// geometric predicates", 1997), with eps = 2^-53: (3 + 16 eps) eps for the
// orientation and (10 + 96 eps) eps for the in-circle test, times the
// permanent of the determinant. Both are rounded up (to 3.5e-16 and
// 1.25e-15), which also covers the terms that underflow while the permanent
// is at least 1e-200; below that, or where it may overflow, nothing is
// decided. The filters cost less than Epick's static filters, which the
// flips, moves and removals call millions of times, and in a construction
// they decide all the in-circle tests and all but a few hundred of the
// orientation tests (points on the edges that the tiles split, collinear up
// to rounding).

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_FAST_PREDICATES_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_FAST_PREDICATES_H

#include <CGAL/enum.h>

#include <cmath>

namespace CGAL {
namespace internal {
namespace Penrose {

// where the bounds above hold
inline bool permanent_in_range(double permanent) { return permanent >= 1e-200 && permanent <= 1e300; }

// The orientation of (a, b, c), or ZERO if undecided.
inline Sign filtered_orientation(double ax, double ay, double bx, double by, double cx, double cy)
{
  const double left = (bx - ax) * (cy - ay), right = (by - ay) * (cx - ax);
  const double det = left - right;
  const double permanent = std::abs(left) + std::abs(right);
  if(!permanent_in_range(permanent)) return ZERO;
  const double bound = 3.5e-16 * permanent;
  return det > bound ? POSITIVE : (det < -bound ? NEGATIVE : ZERO);
}

// The side of the circle through a, b, c (counter-clockwise) that d lies on:
// POSITIVE inside, NEGATIVE outside, or ZERO if undecided.
inline Sign filtered_in_circle(double ax, double ay, double bx, double by, double cx, double cy, double dx, double dy)
{
  const double adx = ax - dx, ady = ay - dy;
  const double bdx = bx - dx, bdy = by - dy;
  const double cdx = cx - dx, cdy = cy - dy;
  const double alift = adx * adx + ady * ady, blift = bdx * bdx + bdy * bdy, clift = cdx * cdx + cdy * cdy;
  const double det = alift * (bdx * cdy - cdx * bdy) + blift * (cdx * ady - adx * cdy) + clift * (adx * bdy - bdx * ady);
  // at least the permanent, as |bdx cdy| + |cdx bdy| <= (blift + clift) / 2, and cheaper
  const double permanent = alift * (blift + clift) + blift * clift;
  if(!permanent_in_range(permanent)) return ZERO;
  const double bound = 1.25e-15 * permanent;
  return det > bound ? POSITIVE : (det < -bound ? NEGATIVE : ZERO);
}

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_FAST_PREDICATES_H

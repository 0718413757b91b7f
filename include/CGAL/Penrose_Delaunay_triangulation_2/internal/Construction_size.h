// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Whether a construction of a given expected size can run here, checked up
// front: the flat mesh indexes its faces with 32 bits, and the machine's
// memory must hold the construction's peak.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_CONSTRUCTION_SIZE_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_CONSTRUCTION_SIZE_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/base_mesh/Base_triangulation_builder.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Size_limits.h>

namespace CGAL {
namespace internal {
namespace Penrose {

// Throws std::length_error if a construction of about `expected_points`
// points would overflow the flat mesh's indices (the builder makes room for
// twice its vertex capacity in faces), or if its peak, `bytes_per_point`
// each, would exceed `memory` bytes (0: unknown, not checked).
inline void check_construction_size(double expected_points, double bytes_per_point, double memory)
{
  check_growth(expected_points, Base_triangulation_builder::most_expected_points(), bytes_per_point, memory,
               "Penrose_Delaunay_triangulation_2: about ", " points", "");
}

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_CONSTRUCTION_SIZE_H

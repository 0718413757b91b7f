// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Whether a construction of a given expected size can run here: the flat
// mesh indexes its faces with 32 bits, and a construction larger than the
// machine's memory ends in the kernel's out-of-memory killer or in swap, not
// in an exception. Both are refused up front, with std::length_error.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_CONSTRUCTION_SIZE_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_CONSTRUCTION_SIZE_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Base_triangulation_builder.h>
#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Flat_mesh.h>

#include <iomanip>
#include <sstream>
#include <stdexcept>

#if defined(__unix__) || defined(__APPLE__)
#  include <unistd.h>
#endif

namespace CGAL {
namespace internal {
namespace Penrose {

// The machine's physical memory in bytes, or 0 where it cannot be told.
inline double physical_memory_bytes()
{
#if defined(_SC_PHYS_PAGES) && defined(_SC_PAGESIZE)
  const long pages = sysconf(_SC_PHYS_PAGES), page = sysconf(_SC_PAGESIZE);
  if(pages > 0 && page > 0) return double(pages) * double(page);
#endif
  return 0.;
}

// Throws std::length_error if a construction of about `expected_points`
// points would overflow the flat mesh's indices (the builder makes room for
// twice its vertex capacity in faces), or if its peak, `bytes_per_point`
// each, would exceed `memory` bytes (0: unknown, not checked).
inline void check_construction_size(double expected_points, double bytes_per_point, double memory)
{
  // the first test keeps vertex_capacity() from converting an out-of-range double
  const bool too_many = expected_points >= 0.5 * double(Flat_mesh::null) ||
                        2 * Base_triangulation_builder::vertex_capacity(expected_points) >= Flat_mesh::null;
  const double bytes = expected_points * bytes_per_point;
  if(!too_many && !(memory > 0. && bytes > memory)) return;
  std::ostringstream msg;
  msg << "Penrose_Delaunay_triangulation_2: about " << std::setprecision(3) << expected_points << " points ";
  if(too_many) msg << "are more than its 32-bit indices allow (about 1.7e+09)";
  else msg << "need about " << bytes / double(1 << 30) << " GiB, more than the " << memory / double(1 << 30)
           << " GiB of this machine";
  throw std::length_error(msg.str());
}

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_CONSTRUCTION_SIZE_H

// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Whether a structure that grows with the tile tree still fits: its 32-bit
// indices, and the machine's memory. Memory exhausted ends in the kernel's
// out-of-memory killer or in swap, not in std::bad_alloc, so the structures
// check before they grow and refuse with std::length_error.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_SIZE_LIMITS_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_SIZE_LIMITS_H

#include <cstddef>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

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

// Why a tile tree, or a base mesh, may outgrow the points it samples.
constexpr const char* overrefinement_hint =
  " (a density_upper_bound far above the density, for one, refines tiles that hold no point)";

// A tight density bound, or none (probes), subdivides 1.3 to 1.6 tiles per
// point; one far above the density refines tiles that hold no point, without
// limit (10^6 times the density: 95 s for 1,004 points). Sampling refuses to
// subdivide more than this many tiles per expected point, plus a budget that
// any count gets (the uniform levels alone subdivide a few hundred tiles).
constexpr double most_refined_tiles_per_point = 256.;
constexpr double least_refinement_budget = 1e5;

inline std::size_t refinement_budget(double expected_points)
{
  const double budget = most_refined_tiles_per_point * expected_points + least_refinement_budget;
  return budget < 1e18 ? std::size_t(budget) : (std::numeric_limits<std::size_t>::max)();
}

// Throws std::length_error if `count` elements reach `index_limit`, or if,
// at `bytes_each`, they exceed `memory` bytes (0: unknown, not checked). The
// message is `subject`, the count, `units`, the reason, then `hint`.
inline void check_growth(double count, double index_limit, double bytes_each, double memory,
                         const std::string& subject, const std::string& units, const std::string& hint)
{
  const bool too_many = !(count < index_limit);
  const double bytes = count * bytes_each;
  if(!too_many && !(memory > 0. && bytes > memory)) return;
  std::ostringstream msg;
  msg << subject << std::setprecision(3) << count << units << ": ";
  if(too_many) msg << "more than its 32-bit indices allow (" << index_limit << ")";
  else msg << "about " << bytes / double(1 << 30) << " GiB, more than the " << memory / double(1 << 30)
           << " GiB of this machine";
  msg << hint;
  throw std::length_error(msg.str());
}

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_SIZE_LIMITS_H

// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A walk split in two halves, the second on a helper thread: for the walks
// whose halves write disjoint data (the links of the TDS written from the
// flat mesh; the moves of the samples, and the search for folded faces
// after them). A thread is started for each walk, which the callers do only
// for walks of least_size_for_two_halves items or more, like the other
// helpers. Whether a helper is used follows the rules of Tds_reservation.h:
// none without threads (CGAL_HAS_THREADS), where the user asks for none
// (CGAL_PENROSE_NO_HELPER_THREAD), on a machine with one core, or where no
// thread can be started.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TWO_HALVES_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TWO_HALVES_H

#include <CGAL/config.h>

#include <cstddef>

#if defined(CGAL_HAS_THREADS) && !defined(CGAL_PENROSE_NO_HELPER_THREAD)
#  define CGAL_PENROSE_TWO_HALVES_THREAD 1
#  include <system_error>
#  include <thread>
#endif

namespace CGAL {
namespace internal {
namespace Penrose {

constexpr std::size_t least_size_for_two_halves = std::size_t(1) << 16;

// Runs `half(0)` on the calling thread and `half(1)` on a helper, if
// `worth_a_thread` and a helper can be had, and returns once both are done;
// otherwise runs both on the calling thread. `half` must not throw.
template <class Half>
void run_in_two_halves(bool worth_a_thread, const Half& half)
{
#if defined(CGAL_PENROSE_TWO_HALVES_THREAD)
  if(worth_a_thread && std::thread::hardware_concurrency() > 1) {
    std::thread helper;
    try {
      helper = std::thread([&half] { half(1); });
    } catch(const std::system_error&) {  // no thread to be had: both halves here
    }
    if(helper.joinable()) {
      half(0);
      helper.join();
      return;
    }
  }
#else
  (void)worth_a_thread;
#endif
  half(0);
  half(1);
}

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TWO_HALVES_H

// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A walk split in two halves, the second on a helper thread: for the walks
// whose halves write disjoint data (the links of the TDS written from the
// flat mesh; the moves of the samples, and the search for folded faces
// after them), or gather what they find apart (the vertices to remove, the
// folded faces, the dead faces). A thread is started for each walk, which the callers do only
// for walks of least_size_for_two_halves items or more, like the other
// helpers. Whether a helper is used follows the rules of Tds_reservation.h
// (Helper_threads.h, and none on a machine with one core). The base mesh's
// last level is split by the same halves and threshold, its second half
// run by the survey helper (Lookahead_worker::run_in_two_halves()).

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TWO_HALVES_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TWO_HALVES_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Helper_threads.h>

#include <array>
#include <cstddef>
#include <exception>
#include <vector>

namespace CGAL {
namespace internal {
namespace Penrose {

constexpr std::size_t least_size_for_two_halves = std::size_t(1) << 16;

// Half `half` (0 or 1) of the items 0 to n - 1: [begin, end).
struct Half_range
{
  std::size_t begin, end;
};

inline Half_range half_of(std::size_t n, int half) { return {std::size_t(half) * n / 2, std::size_t(half + 1) * n / 2}; }

// Runs `half(0)` on the calling thread and `half(1)` on a helper, if
// `worth_a_thread` and a helper can be had, and returns once both are done;
// otherwise runs both on the calling thread. What a half throws (the first
// half's exception where both throw) is rethrown once both have ended.
template <class Half>
void run_in_two_halves(bool worth_a_thread, const Half& half)
{
#if defined(CGAL_PENROSE_HELPER_THREADS)
  if(worth_a_thread && more_than_one_core()) {
    std::exception_ptr helper_failed;
    std::thread helper = try_to_start_thread([&half, &helper_failed] {
      try {
        half(1);
      } catch(...) {
        helper_failed = std::current_exception();
      }
    });
    if(helper.joinable()) {
      try {
        half(0);
      } catch(...) {
        helper.join();
        throw;
      }
      helper.join();
      if(helper_failed) std::rethrow_exception(helper_failed);
      return;
    }
  }
#else
  (void)worth_a_thread;
#endif
  half(0);
  half(1);
}

// Runs `half(h, found)` for the halves h = 0 and 1 as run_in_two_halves()
// does, each half with a vector `found` of its own, and returns the two
// vectors one after the other. Each half has its vector apart until it
// ends: side by side, the two vectors' ends would share a cache line, which
// the threads would take turns at.
template <class T, class Half>
std::vector<T> gather_in_two_halves(bool worth_a_thread, const Half& half)
{
  std::array<std::vector<T>, 2> found;
  run_in_two_halves(worth_a_thread, [&half, &found](int h) {
    std::vector<T> own;
    half(h, own);
    found[h].swap(own);
  });
  found[0].insert(found[0].end(), found[1].begin(), found[1].end());
  return std::move(found[0]);
}

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_TWO_HALVES_H

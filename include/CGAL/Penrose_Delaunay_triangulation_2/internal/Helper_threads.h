// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Whether a construction may start helper threads, and how it starts one.
// None without threads (CGAL's CGAL_HAS_THREADS), nor where the user asks
// for none (CGAL_PENROSE_NO_HELPER_THREAD), nor where the process may run on
// one core only; where no thread can be had, the caller does the work
// itself.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_HELPER_THREADS_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_HELPER_THREADS_H

#include <CGAL/config.h>

#if defined(CGAL_HAS_THREADS) && !defined(CGAL_PENROSE_NO_HELPER_THREAD)
#  define CGAL_PENROSE_HELPER_THREADS 1
#  include <system_error>
#  include <thread>
#  include <utility>
#  if defined(__linux__)
#    include <sched.h>
#  endif
#endif

namespace CGAL {
namespace internal {
namespace Penrose {

#if defined(CGAL_PENROSE_HELPER_THREADS)
// Whether the process may run on more than one core (its affinity, where the
// system tells it): on one, a helper would only take turns with the caller.
inline bool more_than_one_core()
{
#  if defined(__linux__) && defined(CPU_COUNT)
  cpu_set_t allowed;
  if(sched_getaffinity(0, sizeof(allowed), &allowed) == 0) return CPU_COUNT(&allowed) > 1;
#  endif
  return std::thread::hardware_concurrency() > 1;
}

// A thread running `f`, or, where none can be started, no thread (not
// joinable).
template <class F>
std::thread try_to_start_thread(F&& f)
{
  try {
    return std::thread(std::forward<F>(f));
  } catch(const std::system_error&) {
    return std::thread();
  }
}
#endif

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_HELPER_THREADS_H

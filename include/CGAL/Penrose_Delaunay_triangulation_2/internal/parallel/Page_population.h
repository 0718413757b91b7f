// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The first write to a page of fresh memory costs a page fault, about a
// microsecond: a tenth of a fresh construction is spent so. With
// Parallel_tag, a task asks the kernel to fault in the pages that the
// calling thread is about to fill (Linux's MADV_POPULATE_WRITE), beside it,
// and the calling thread finds them present. Nothing is written: the
// arrays' contents are the calling thread's alone. Where the kernel or the
// system cannot do it, the pages are faulted in when written, as with
// Sequential_tag.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_PAGE_POPULATION_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_PAGE_POPULATION_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/parallel/Concurrency.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

#if defined(__linux__)
#  include <sys/mman.h>
#  include <unistd.h>
#endif

namespace CGAL {
namespace internal {
namespace Penrose {

// Bytes of memory that are about to be written.
struct Byte_range
{
  const void* begin;
  std::size_t bytes;
};

// The storage of the first `n` elements of `v`, within its capacity.
template <class T>
Byte_range first_elements(const std::vector<T>& v, std::size_t n)
{
  return {v.data(), (std::min)(n, v.capacity()) * sizeof(T)};
}

// Faults in the whole pages of `r`, ready to be written; does nothing where
// that cannot be asked for.
inline void populate_for_writing(const Byte_range& r)
{
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
  static const std::uintptr_t page = std::uintptr_t(sysconf(_SC_PAGESIZE));
  const std::uintptr_t begin = (reinterpret_cast<std::uintptr_t>(r.begin) + page - 1) / page * page;
  const std::uintptr_t end = (reinterpret_cast<std::uintptr_t>(r.begin) + r.bytes) / page * page;
  // an older kernel refuses the advice: its pages are then faulted in when written
  if(begin < end) (void)madvise(reinterpret_cast<void*>(begin), end - begin, MADV_POPULATE_WRITE);
#else
  (void)r;
#endif
}

// With Parallel_tag, faults in the pages of `ranges` in a task, from their
// beginnings on, in step, as arrays filled side by side are; when destroyed,
// stops it and waits for it: on a busy machine, where the task may start
// late or never, the calling thread has faulted the pages in by then. With
// Sequential_tag, does nothing.
template <class ConcurrencyTag>
class Pages_populated_beside
{
public:
  explicit Pages_populated_beside(const std::vector<Byte_range>& ranges)
  {
#if defined(CGAL_LINKED_WITH_TBB)
    if constexpr(is_parallel<ConcurrencyTag>) {
      group_.run(task([ranges] {
        constexpr std::size_t steps = 64;
        for(std::size_t s = 0; s < steps && !tbb::is_current_task_group_canceling(); ++s)
          for(const Byte_range& r : ranges) {
            const std::size_t from = r.bytes / steps * s, to = s + 1 == steps ? r.bytes : r.bytes / steps * (s + 1);
            populate_for_writing({static_cast<const char*>(r.begin) + from, to - from});
          }
      }));
    }
#endif
    (void)ranges;
  }

  Pages_populated_beside(const Pages_populated_beside&) = delete;
  Pages_populated_beside& operator=(const Pages_populated_beside&) = delete;

  ~Pages_populated_beside()
  {
#if defined(CGAL_LINKED_WITH_TBB)
    if constexpr(is_parallel<ConcurrencyTag>) {
      [[maybe_unused]] const Tasks_ended ended;
      try {
        group_.cancel();
        group_.wait();
      } catch(...) {  // the task only gives advice: nothing of it can matter
      }
    }
#endif
  }

private:
#if defined(CGAL_LINKED_WITH_TBB)
  // none with Sequential_tag
  std::conditional_t<is_parallel<ConcurrencyTag>, tbb::task_group, char> group_;
#endif
};

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_PAGE_POPULATION_H

// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// How the construction shares its work, as its ConcurrencyTag says. With
// Sequential_tag the calling thread does everything, in order. With
// Parallel_tag the work is made of TBB tasks, which run on the threads that
// TBB allows (tbb::global_control, tbb::task_arena) and wait for each other
// through TBB: a thread that waits runs other tasks, or the task it waits
// for, so a busy machine, or a single thread, only makes it slower. What
// the pieces find is gathered in the same order whatever the tag, so the
// result does not depend on it. What a task throws reaches the caller once
// the others have ended.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_CONCURRENCY_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_CONCURRENCY_H

#include <CGAL/tags.h>

#include <algorithm>
#include <cstddef>
#include <type_traits>
#include <vector>

#if defined(CGAL_LINKED_WITH_TBB)
#  include <tbb/blocked_range.h>
#  include <tbb/parallel_for.h>
#  include <tbb/task_group.h>
#endif

#if defined(__SANITIZE_THREAD__)
#  define CGAL_PENROSE_THREAD_SANITIZER 1
#elif defined(__has_feature)
#  if __has_feature(thread_sanitizer)
#    define CGAL_PENROSE_THREAD_SANITIZER 1
#  endif
#endif
#if defined(CGAL_PENROSE_THREAD_SANITIZER)
#  include <sanitizer/tsan_interface.h>
#  include <utility>
#endif

namespace CGAL {
namespace internal {
namespace Penrose {

template <class ConcurrencyTag>
constexpr bool is_parallel = std::is_convertible<ConcurrencyTag, Parallel_tag>::value;

#if defined(CGAL_PENROSE_THREAD_SANITIZER)
// Under ThreadSanitizer, a task's function tells it of the hand-offs that
// TBB's library, which is not instrumented, makes: a task starts after its
// function was copied into it, and the thread that waits for the tasks goes
// on after them, whether they returned or threw (Tasks_ended, from its
// creation to its end). Elsewhere the function is used as it is.
inline char& tasks_started() { static char tag; return tag; }
inline char& tasks_finished() { static char tag; return tag; }

struct Tasks_ended
{
  ~Tasks_ended() { __tsan_acquire(&tasks_finished()); }
};

template <class F>
struct Task_function
{
  explicit Task_function(const F& f) : f(f) { __tsan_release(&tasks_started()); }
  Task_function(const Task_function& other) : f((__tsan_acquire(&tasks_started()), other.f))
  {
    __tsan_release(&tasks_started());
  }

  template <class... Args>
  void operator()(Args&&... args) const
  {
    struct Finished
    {
      ~Finished() { __tsan_release(&tasks_finished()); }
    } finished;
    __tsan_acquire(&tasks_started());
    f(std::forward<Args>(args)...);
  }

  F f;
};

template <class F>
Task_function<F> task(const F& f) { return Task_function<F>(f); }
#else
template <class F>
const F& task(const F& f) { return f; }

struct Tasks_ended {};
#endif

// Runs `background()` and `foreground()`, which must not depend on each
// other, and returns once both are done. `foreground()` runs on the calling
// thread (it may call the user's callback); with Parallel_tag,
// `background()` is a task beside it, otherwise it runs after it.
template <class ConcurrencyTag, class Background, class Foreground>
void run_beside(const Background& background, const Foreground& foreground)
{
#if defined(CGAL_LINKED_WITH_TBB)
  if constexpr(is_parallel<ConcurrencyTag>) {
    [[maybe_unused]] const Tasks_ended ended;
    tbb::task_group group;
    group.run(task([&background] { background(); }));
    try {
      foreground();
    } catch(...) {
      group.cancel();
      try {
        group.wait();
      } catch(...) {  // the foreground's exception goes first
      }
      throw;
    }
    group.wait();
    return;
  }
#endif
  foreground();
  background();
}

// Below this many items, a walk is not worth splitting in halves.
constexpr std::size_t least_size_for_two_halves = std::size_t(1) << 16;

// Half `half` (0 or 1) of the items 0 to n - 1: [begin, end).
struct Half_range
{
  std::size_t begin, end;
};

inline Half_range half_of(std::size_t n, int half) { return {std::size_t(half) * n / 2, std::size_t(half + 1) * n / 2}; }

// Runs `half(0)`, on the calling thread, and `half(1)`, beside it where
// `worth_splitting`, as run_beside() does: for walks whose halves write
// disjoint data.
template <class ConcurrencyTag, class Half>
void run_in_two_halves(bool worth_splitting, const Half& half)
{
  if(!worth_splitting) {
    half(0);
    half(1);
    return;
  }
  run_beside<ConcurrencyTag>([&half] { half(1); }, [&half] { half(0); });
}

// Runs `block(b, e)` over blocks [b, e) that cover the items 0 to n - 1:
// one block with Sequential_tag, TBB's blocks of at least `grain` items
// otherwise. For items that are independent of each other.
template <class ConcurrencyTag, class Block>
void for_each_block(std::size_t n, std::size_t grain, const Block& block)
{
#if defined(CGAL_LINKED_WITH_TBB)
  if constexpr(is_parallel<ConcurrencyTag>) {
    [[maybe_unused]] const Tasks_ended ended;
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, n, grain),
                      task([&block](const tbb::blocked_range<std::size_t>& r) { block(r.begin(), r.end()); }));
    return;
  }
#endif
  (void)grain;
  if(n > 0) block(std::size_t(0), n);
}

// Items per task of a walk bound by memory: small, so that a thread that
// the system stops holds little of the walk back.
constexpr std::size_t walk_block = std::size_t(1) << 14;

// Runs `walk(b, e, found)` over blocks [b, e) that cover the items 0 to
// n - 1, in order, each with a vector `found` of its own, and returns the
// vectors one after the other: the same whatever the tag. With
// Parallel_tag the blocks are TBB tasks of walk_block items.
template <class T, class ConcurrencyTag, class Walk>
std::vector<T> gather_in_blocks(std::size_t n, const Walk& walk)
{
  const std::size_t blocks = is_parallel<ConcurrencyTag> ? (n + walk_block - 1) / walk_block : 1;
  const std::size_t size = is_parallel<ConcurrencyTag> ? walk_block : n;
  // each block's vector apart until it ends: side by side, the ends of two
  // vectors would share a cache line, which their threads would take turns at
  std::vector<std::vector<T>> found(blocks);
  for_each_block<ConcurrencyTag>(blocks, 1, [&](std::size_t first, std::size_t last) {
    for(std::size_t i = first; i < last; ++i) {
      std::vector<T> own;
      walk(i * size, (std::min)(n, (i + 1) * size), own);
      found[i].swap(own);
    }
  });
  std::vector<T> all;
  for(std::vector<T>& f : found) all.insert(all.end(), f.begin(), f.end());
  return all;
}

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_CONCURRENCY_H

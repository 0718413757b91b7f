// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A helper thread that works through a batch of items ahead of the calling
// thread, which consumes their results in order: the helper runs the part of
// each item that reads only what the caller no longer writes, and the caller
// waits, item by item, only where the helper has not got there yet. One
// batch at a time: the caller starts the next one once it has consumed the
// last, so a job never runs on two threads at once, and whatever the job
// calls (a user's density, say) is never called concurrently with the
// caller as long as the caller does not call it itself meanwhile. Between
// batches, the helper can also run one half of a walk in two halves.
//
// Once a batch is done, the helper may run an idle job, step after step,
// until the caller starts the next batch or waits for the helper: work that
// may be left unfinished, such as faulting in memory that the caller will
// write.
//
// The caller's waits spin, or do what the caller gives them to do meanwhile:
// they are short, and a sleeping thread takes tens of microseconds to wake.
// The helper, once done with a batch, spins a little, then sleeps until the
// next one: spinning on, it would slow the caller down wherever the two
// threads share a core's execution units. What a job throws is rethrown to
// the caller when it waits for an item of the chunk that threw.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_LOOKAHEAD_WORKER_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_LOOKAHEAD_WORKER_H

#include <CGAL/config.h>

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Helper_threads.h>

#include <cstddef>
#include <exception>
#include <functional>

#if defined(CGAL_PENROSE_HELPER_THREADS)
#  include <atomic>
#  include <condition_variable>
#  include <mutex>
#  include <thread>
#  if defined(__x86_64__) || defined(__i386__)
#    include <immintrin.h>
#    define CGAL_PENROSE_SPIN_PAUSE() _mm_pause()
#  else
#    define CGAL_PENROSE_SPIN_PAUSE() ((void)0)
#  endif
#endif

namespace CGAL {
namespace internal {
namespace Penrose {

class Lookahead_worker
{
public:
  // `job(b, e)` does items b to e - 1 of the current batch.
  typedef std::function<void(std::size_t, std::size_t)> Job;
  // a step of the idle job; false once there is nothing left to do
  typedef std::function<bool()> Idle_step;

  // Starts the helper if `wanted`, threads are available, the process may
  // run on more than one core and a thread can be started; running() says.
  explicit Lookahead_worker(bool wanted)
  {
#if defined(CGAL_PENROSE_HELPER_THREADS)
    if(wanted && more_than_one_core()) helper_ = try_to_start_thread([this] { serve(); });
#else
    (void)wanted;
#endif
  }

  Lookahead_worker(const Lookahead_worker&) = delete;
  Lookahead_worker& operator=(const Lookahead_worker&) = delete;

  ~Lookahead_worker()
  {
#if defined(CGAL_PENROSE_HELPER_THREADS)
    if(helper_.joinable()) {
      stop_.store(true, std::memory_order_release);
      wake_helper();
      helper_.join();
    }
#endif
  }

  bool running() const
  {
#if defined(CGAL_PENROSE_HELPER_THREADS)
    return helper_.joinable();
#else
    return false;
#endif
  }

  // Hands the helper the items 0 to n - 1, and then `idle`, once it has
  // left the last batch; without a helper, does the items at once and
  // leaves `idle` undone.
  void start(std::size_t n, Job job, Idle_step idle = Idle_step())
  {
#if defined(CGAL_PENROSE_HELPER_THREADS)
    if(running()) {
      wait_until_idle();
      hand_over(n, std::move(job), std::move(idle));
      return;
    }
#endif
    (void)idle;
    if(n > 0) job(0, n);
  }

  // Runs `half(0)` here and `half(1)` on the helper, where it runs (once it
  // has left the last batch), otherwise here, first, and returns once both
  // are done; like run_in_two_halves() of Two_halves.h, without starting a
  // thread. What a half throws (the first half's exception where both
  // throw) is rethrown once both have ended.
  template <class Half>
  void run_in_two_halves(const Half& half)
  {
    start(1, [&half](std::size_t, std::size_t) { half(1); });
    try {
      half(0);
    } catch(...) {
      try {
        wait_for_all();
      } catch(...) {
      }
      throw;
    }
    wait_for_all();
  }

  // Waits until item k of the batch is done, calling `idle()`, while it
  // returns true, instead of spinning: what the caller can do meanwhile.
  template <class Idle>
  void wait_for(std::size_t k, Idle idle)
  {
#if defined(CGAL_PENROSE_HELPER_THREADS)
    if(!running()) return;
    unsigned spins = 0;
    bool busy = true;
    while(seen_ <= k) {
      seen_ = done_.load(std::memory_order_acquire);
      if(seen_ <= k) {
        if(failed_.load(std::memory_order_acquire)) rethrow();
        if(!busy || !(busy = idle())) pause(spins);
      }
    }
#else
    (void)k; (void)idle;
#endif
  }

  void wait_for(std::size_t k)
  {
    wait_for(k, [] { return false; });
  }

  // Waits until the whole batch is done.
  void wait_for_all()
  {
#if defined(CGAL_PENROSE_HELPER_THREADS)
    if(size_ > 0) wait_for(size_ - 1);
#endif
  }

  // Waits until the helper has left the last batch, done or failed, cutting
  // its idle job short: only then may the next one change what the helper
  // reads. What the batch threw is not rethrown here.
  void wait_until_idle()
  {
#if defined(CGAL_PENROSE_HELPER_THREADS)
    if(!running()) return;
    interrupt_.store(true, std::memory_order_release);
    unsigned spins = 0;
    while(finished_.load(std::memory_order_acquire) != handed_) pause(spins);
#endif
  }

private:
#if defined(CGAL_PENROSE_HELPER_THREADS)
  static constexpr std::size_t chunk = 64;

  // Spins, but lets another thread of the core run now and then.
  static void pause(unsigned& spins)
  {
    if(++spins % 1024 == 0) std::this_thread::yield();
    else CGAL_PENROSE_SPIN_PAUSE();
  }

  void hand_over(std::size_t n, Job job, Idle_step idle)
  {
    size_ = n;
    job_ = std::move(job);
    idle_ = std::move(idle);
    interrupt_.store(false, std::memory_order_relaxed);
    error_ = nullptr;
    seen_ = 0;
    done_.store(0, std::memory_order_relaxed);
    failed_.store(false, std::memory_order_relaxed);
    batch_.store(++handed_, std::memory_order_release);
    wake_helper();
  }

  void wake_helper()
  {
    { std::lock_guard<std::mutex> lock(mutex_); }  // the helper sleeps, or sees the change before it would
    wake_.notify_one();
  }

  void serve()
  {
    unsigned served = 0;
    for(;;) {
      if(!wait_for_batch(served)) return;
      ++served;
      for(std::size_t b = 0; b < size_; b += chunk) {
        if(stop_.load(std::memory_order_acquire)) return;
        const std::size_t e = (b + chunk < size_) ? b + chunk : size_;
        try {
          job_(b, e);
        } catch(...) {
          error_ = std::current_exception();
          failed_.store(true, std::memory_order_release);
          break;
        }
        done_.store(e, std::memory_order_release);
      }
      if(idle_ && !failed_.load(std::memory_order_relaxed))
        while(!interrupt_.load(std::memory_order_acquire) && !stop_.load(std::memory_order_acquire) && idle_()) {}
      finished_.store(served, std::memory_order_release);
    }
  }

  // Waits for the batch after `served`; false if asked to stop.
  bool wait_for_batch(unsigned served)
  {
    auto arrived = [&] { return batch_.load(std::memory_order_acquire) != served || stop_.load(std::memory_order_acquire); };
    for(int spins = 0; spins < spins_before_sleep && !arrived(); ++spins) CGAL_PENROSE_SPIN_PAUSE();
    if(!arrived()) {
      std::unique_lock<std::mutex> lock(mutex_);
      wake_.wait(lock, arrived);
    }
    return !stop_.load(std::memory_order_acquire);
  }

  // about 50 to 100 microseconds
  static constexpr int spins_before_sleep = 2000;

  [[noreturn]] void rethrow() { std::rethrow_exception(error_); }

  // Each group on a cache line of its own: the helper spins on the first
  // while the caller writes its own data, and the caller polls the second
  // while the helper works; sharing a line with either (the caller's stack
  // included) would make the two cores take turns at it.
  // read by the helper at every spin, written by the caller once a batch
  alignas(64) std::atomic<unsigned> batch_{0};  // batches handed over
  std::atomic<bool> stop_{false};
  std::atomic<bool> interrupt_{false};  // of the idle job
  // written by the helper once a chunk, read by the caller
  alignas(64) std::atomic<std::size_t> done_{0};
  std::atomic<unsigned> finished_{0};  // batches left
  std::atomic<bool> failed_{false};
  // written by the caller before a batch starts, read by the helper in it
  alignas(64) std::size_t size_ = 0;
  Job job_;
  Idle_step idle_;
  // written by the helper before failed_, read by the caller after it
  std::exception_ptr error_;
  // where the helper sleeps between batches
  std::mutex mutex_;
  std::condition_variable wake_;
  // the caller's own
  alignas(64) std::thread helper_;
  unsigned handed_ = 0;
  std::size_t seen_ = 0;
#endif
};

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_LOOKAHEAD_WORKER_H

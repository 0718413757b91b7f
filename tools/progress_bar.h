// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A progress bar on stderr for penrose_mesh: drawn by a thread ten times a
// second once the run has lasted a second, and only when stderr is a
// terminal, so that logs and pipes stay clean.

#ifndef PENROSE_TOOLS_PROGRESS_BAR_H
#define PENROSE_TOOLS_PROGRESS_BAR_H

#include <unistd.h>

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdio>
#include <mutex>
#include <string>
#include <thread>

namespace penrose_tools {

class Progress_bar
{
public:
  Progress_bar() : start_(std::chrono::steady_clock::now())
  {
    if(isatty(STDERR_FILENO)) thread_ = std::thread([this] { run(); });
  }

  ~Progress_bar() { finish(); }

  // Stops drawing and clears the bar, before the run prints its results.
  void finish()
  {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      stop_ = true;
    }
    wake_.notify_one();
    if(thread_.joinable()) thread_.join();
  }

  // Enters a stage that covers [from, to] of the whole run; set() moves
  // within it. A stage that calls no set() shows its start and the clock.
  void stage(const char* name, double from, double to)
  {
    std::lock_guard<std::mutex> lock(mutex_);
    name_ = name;
    from_ = from;
    to_ = to;
    fraction_ = 0.;
  }
  void set(double fraction_of_stage) { fraction_ = fraction_of_stage; }

private:
  void run()
  {
    std::unique_lock<std::mutex> lock(mutex_);
    bool drawn = false;
    while(!wake_.wait_for(lock, std::chrono::milliseconds(100), [this] { return stop_; })) {
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
      if(seconds < 1.) continue;
      const double f = from_ + (to_ - from_) * fraction_.load();
      const int width = 30, filled = int(f * width + 0.5);
      std::fprintf(stderr, "\r[%s%s] %3d%% %-14s %6.1f s", std::string(filled, '#').c_str(),
                   std::string(width - filled, ' ').c_str(), int(100 * f + 0.5), name_.c_str(), seconds);
      std::fflush(stderr);
      drawn = true;
    }
    if(drawn) std::fprintf(stderr, "\r%66s\r", "");
  }

  std::chrono::steady_clock::time_point start_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  std::string name_;
  double from_ = 0., to_ = 0.;
  std::atomic<double> fraction_{0.};
  std::thread thread_;
};

} // namespace penrose_tools

#endif // PENROSE_TOOLS_PROGRESS_BAR_H

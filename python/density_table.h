// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The values of a density that is evaluated in blocks, looked up by the
// exact coordinates at which the sampler asks for them.

#ifndef PENROSE_PYTHON_DENSITY_TABLE_H
#define PENROSE_PYTHON_DENSITY_TABLE_H

#include <cstdint>
#include <cstring>
#include <functional>
#include <utility>
#include <vector>

namespace penrose_python {

// A Python function of numpy arrays costs microseconds a call, however
// short the arrays: called once a point, it would take longer than the
// whole construction. The sampler asks for the density one point at a time
// and what it asks next depends on the answer, so the construction is run
// on this table instead, more than once: a point that the table does not
// know yet reads as a guess and is noted as pending; the pending points are
// then evaluated in one block, and the run is repeated until it asks for
// nothing new. A run in which every point was known is exact, so its result
// is the construction on the function itself. A good guess (an
// interpolation of the function on a grid) makes the first run ask for
// nearly every point that the last one needs, and two or three runs do.
//
// The sampler never calls the density from two threads at once, which is
// all that the table asks of it.
class Density_table
{
public:
  explicit Density_table(std::function<double(double, double)> guess)
    : guess_(std::move(guess)), slots_(std::size_t(1) << 16, Slot{empty_key, 0, 0.})
  {}

  // The density at (x, y), or the guess there if it is not known yet.
  double operator()(double x, double y)
  {
    Slot& s = find(bits(x), bits(y));
    if(s.key_x == empty_key) {
      s = Slot{bits(x), bits(y), pending_value()};
      pending_.emplace_back(x, y);
      if(++size_ * 2 > slots_.size()) grow();
      return guess_(x, y);
    }
    return is_pending(s.value) ? guess_(x, y) : s.value;
  }

  // The points asked for and not known yet, in the order they were asked for.
  const std::vector<std::pair<double, double>>& pending() const { return pending_; }

  // Gives the pending points their values, `values[k]` that of `pending()[k]`.
  void set_pending_values(const std::vector<double>& values)
  {
    for(std::size_t k = 0; k < pending_.size(); ++k)
      find(bits(pending_[k].first), bits(pending_[k].second)).value = values[k];
    pending_.clear();
  }

private:
  struct Slot
  {
    std::uint64_t key_x, key_y;
    double value;
  };

  // No coordinate of the region is NaN, so a NaN's bits mark an empty slot,
  // and another NaN's a value not known yet.
  static constexpr std::uint64_t empty_key = 0x7ff8dead00000000ull;
  static constexpr std::uint64_t pending_bits = 0x7ff8beef00000000ull;
  static double pending_value()
  {
    double v;
    std::memcpy(&v, &pending_bits, sizeof v);
    return v;
  }
  static bool is_pending(double v) { return bits(v) == pending_bits; }
  static std::uint64_t bits(double v)
  {
    std::uint64_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
  }

  // Coordinates on a grid share their low bits: all bits are mixed into those kept.
  static std::uint64_t mix(std::uint64_t h)
  {
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
    return h ^ (h >> 31);
  }

  Slot& find(std::uint64_t kx, std::uint64_t ky)
  {
    const std::size_t mask = slots_.size() - 1;
    std::size_t i = std::size_t(mix(mix(kx) ^ ky)) & mask;
    while(slots_[i].key_x != empty_key && (slots_[i].key_x != kx || slots_[i].key_y != ky)) i = (i + 1) & mask;
    return slots_[i];
  }

  void grow()
  {
    std::vector<Slot> old(slots_.size() * 2, Slot{empty_key, 0, 0.});
    old.swap(slots_);
    for(const Slot& s : old)
      if(s.key_x != empty_key) find(s.key_x, s.key_y) = s;
  }

  std::function<double(double, double)> guess_;
  std::vector<Slot> slots_;
  std::size_t size_ = 0;
  std::vector<std::pair<double, double>> pending_;
};

} // namespace penrose_python

#endif // PENROSE_PYTHON_DENSITY_TABLE_H

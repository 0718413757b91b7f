// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The values of a density that is evaluated in blocks, looked up by the
// exact coordinates at which the sampler asks for them.

#ifndef PENROSE_PYTHON_DENSITY_TABLE_H
#define PENROSE_PYTHON_DENSITY_TABLE_H

#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <stdexcept>
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
    : guess_(std::move(guess)), slots_(std::size_t(1) << 16, 0)
  {}

  // The density at (x, y), or the guess there if it is not known yet.
  double operator()(double x, double y)
  {
    const std::uint64_t kx = bits(x), ky = bits(y);
    // A run asks for the points in the order of the run before it, but
    // where their values differ: most points are the next one in the
    // table, read without a search, and the table is laid in that order.
    if(next_ < entries_.size() && entries_[next_].key_x == kx && entries_[next_].key_y == ky)
      return value(entries_[next_++], x, y);
    // Tiles that share a vertex are visited close together: the other
    // points were mostly asked for a moment ago.
    Entry& recent = recent_[std::size_t(mix(kx ^ ky) >> 50)];
    if(recent.key_x == kx && recent.key_y == ky) return value(recent, x, y);
    const std::uint64_t h = hash(kx, ky);
    std::uint64_t& slot = find(kx, ky, h);
    if(slot == 0) {
      if(entries_.size() >= max_entries) throw std::length_error("the density function is asked for too many points");
      entries_.push_back(Entry{kx, ky, pending_value()});
      slot = tagged(entries_.size(), h);
      pending_.push_back(entries_.size() - 1);
      if(entries_.size() * 2 > slots_.size()) grow_to(2 * slots_.size());
      return guess_(x, y);
    }
    const std::size_t k = std::size_t(slot & index_mask) - 1;
    if(k >= next_) next_ = k + 1;
    recent = entries_[k];
    return value(recent, x, y);
  }

  // Makes room for `n` points: growing a table of millions of points costs
  // a cache miss for each point it holds.
  void reserve(std::size_t n)
  {
    entries_.reserve(n);
    std::size_t size = slots_.size();
    while(size < 2 * n) size *= 2;
    if(size > slots_.size()) grow_to(size);
  }

  // Starts a run: the points are expected again in the order they were first asked for.
  void rewind() { next_ = 0; }

  // The number of points asked for and not known yet.
  std::size_t number_of_pending() const { return pending_.size(); }
  // The k-th of them, in the order they were asked for.
  std::pair<double, double> pending(std::size_t k) const
  {
    const Entry& e = entries_[pending_[k]];
    return {coordinate(e.key_x), coordinate(e.key_y)};
  }

  // Gives the pending points their values, `values[k]` that of `pending(k)`.
  // A NaN becomes the default one, which the sampler refuses: its payload
  // might be that of a value not known yet.
  void set_pending_values(const std::vector<double>& values)
  {
    for(std::size_t k = 0; k < pending_.size(); ++k)
      entries_[pending_[k]].value = std::isnan(values[k]) ? std::numeric_limits<double>::quiet_NaN() : values[k];
    pending_.clear();
    for(Entry& e : recent_) e = Entry{empty_key, 0, 0.};
  }

private:
  struct Entry
  {
    std::uint64_t key_x, key_y;
    double value;
  };

  // A slot holds the index of an entry + 1 (0 for none) in its low 32 bits,
  // and the high bits of the entry's hash above, which spare reading the
  // entries that only share a slot's neighbourhood: each is a cache miss.
  static constexpr std::size_t max_entries = (std::size_t(1) << 32) - 2;
  static constexpr std::uint64_t index_mask = 0xffffffffull;
  static std::uint64_t tagged(std::size_t index_plus_one, std::uint64_t h)
  {
    return (h & ~index_mask) | std::uint64_t(index_plus_one);
  }
  // No coordinate of the region is NaN: a NaN's bits mark an empty cache
  // line, and another NaN's a value not known yet.
  static constexpr std::uint64_t empty_key = 0x7ff8dead00000000ull;
  static constexpr std::uint64_t pending_bits = 0x7ff8beef00000000ull;

  double value(const Entry& e, double x, double y) const
  {
    return bits(e.value) == pending_bits ? guess_(x, y) : e.value;
  }
  static double pending_value() { return coordinate(pending_bits); }
  static std::uint64_t bits(double v)
  {
    std::uint64_t b;
    std::memcpy(&b, &v, sizeof b);
    return b;
  }
  static double coordinate(std::uint64_t b)
  {
    double v;
    std::memcpy(&v, &b, sizeof v);
    return v;
  }

  // Coordinates on a grid share their low bits: all bits are mixed into those kept.
  static std::uint64_t mix(std::uint64_t h)
  {
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
    return h ^ (h >> 31);
  }

  static std::uint64_t hash(std::uint64_t kx, std::uint64_t ky) { return mix(mix(kx) ^ ky); }

  // The slot of (kx, ky), whose hash is h, or the empty slot where it would go.
  std::uint64_t& find(std::uint64_t kx, std::uint64_t ky, std::uint64_t h)
  {
    const std::size_t mask = slots_.size() - 1;
    for(std::size_t i = std::size_t(h) & mask;; i = (i + 1) & mask) {
      const std::uint64_t s = slots_[i];
      if(s == 0) return slots_[i];
      if((s & ~index_mask) == (h & ~index_mask)) {
        const Entry& e = entries_[std::size_t(s & index_mask) - 1];
        if(e.key_x == kx && e.key_y == ky) return slots_[i];
      }
    }
  }

  void grow_to(std::size_t size)
  {
    slots_.assign(size, 0);
    for(std::size_t k = 0; k < entries_.size(); ++k) {
      const std::uint64_t h = hash(entries_[k].key_x, entries_[k].key_y);
      find(entries_[k].key_x, entries_[k].key_y, h) = tagged(k + 1, h);
    }
  }

  std::function<double(double, double)> guess_;
  std::vector<Entry> entries_;       // in the order first asked for
  std::vector<std::uint64_t> slots_; // hash of the entries' keys
  std::size_t next_ = 0;             // the entry expected next
  std::vector<Entry> recent_ = std::vector<Entry>(std::size_t(1) << 14, Entry{empty_key, 0, 0.});
  std::vector<std::size_t> pending_;  // entries not known yet
};

} // namespace penrose_python

#endif // PENROSE_PYTHON_DENSITY_TABLE_H

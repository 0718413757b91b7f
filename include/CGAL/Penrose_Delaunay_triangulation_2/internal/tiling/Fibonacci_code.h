// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// F-codes read in the Fibonacci number system: sample thresholds, required
// subdivision levels, and the two indices of the correction table.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_FIBONACCI_CODE_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_FIBONACCI_CODE_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tiling/Penrose_rules.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <vector>

namespace CGAL {
namespace internal {
namespace Penrose {

// Two bits per level in a 64-bit code, and thresholds that stay exact in a
// double (F(2 * 30 + 1) < 2^53): 30 levels hold about 4 x 10^11 points in a
// square region, 4 x 10^11 / L^2 per unit area (L the region's longer side).
constexpr int max_level = 30;

struct Fibonacci_tables
{
  std::array<std::uint64_t, 2 * max_level + 4> fib;      // fib[n] = F(n), F(1) = F(2) = 1
  // level_importance[m]: the least importance whose required level (C.5 of
  // the sampler facts) is m or more; level 1 needs any positive importance
  std::array<double, max_level + 2> level_importance;
  Fibonacci_tables()
  {
    fib[0] = 0; fib[1] = 1;
    for(std::size_t n = 2; n < fib.size(); ++n) fib[n] = fib[n - 1] + fib[n - 2];
    // the required level is m or more  <=>  sqrt(5) I + 1 >= phi^(2m)   (m >= 2)
    level_importance[0] = 0.;
    level_importance[1] = 0.;
    for(int m = 2; m < max_level + 2; ++m)
      level_importance[m] = (std::pow(static_cast<long double>(golden_ratio), 2 * m) - 1.L)
                            / std::sqrt(5.L);
  }
};

// initialised before main, so that reading it costs no guard
inline const Fibonacci_tables fibonacci_tables;
inline const Fibonacci_tables& fibonacci() { return fibonacci_tables; }

// Threshold added by the pair appended at level `level`: the older bit of the
// pair weighs F(2 level), the newer F(2 level + 1).
inline std::uint64_t pair_weight(std::uint8_t pair, int level)
{
  const Fibonacci_tables& t = fibonacci();
  return (pair & 2 ? t.fib[2 * level] : 0) + (pair & 1 ? t.fib[2 * level + 1] : 0);
}

// Fibonacci value of the `bits` newest bits of a code; the oldest weighs 1.
// With all 2 l bits of a tile of level l, it is the tile's threshold.
inline std::uint64_t fibonacci_value(std::uint64_t code, int bits)
{
  const Fibonacci_tables& t = fibonacci();
  std::uint64_t v = 0;
  for(int b = 0; b < bits; ++b)            // bit b (0 = newest) weighs F(bits + 1 - b)
    if(code >> b & 1u) v += t.fib[bits + 1 - b];
  return v;
}

// Number of Zeckendorf strings of `bits` bits, i.e. of structural indices.
inline unsigned number_of_structural_indices(int bits)
{
  return static_cast<unsigned>(fibonacci().fib[bits + 2]);
}

// Position of an importance i within its level, in `bins` equal steps of
// log_{phi^2}(1 + sqrt(5) i): it returns to 0 where the required level rises.
// The steps' bounds are tabulated (rounded to doubles), so that an index
// costs a rough logarithm from the bits of the double and a comparison or
// two, not a log1p per sample.
class Importance_bins
{
public:
  explicit Importance_bins(unsigned bins)
    : steps_per_log2_(double(bins) / std::log2(golden_ratio * golden_ratio))
  {
    const long double phi2 = static_cast<long double>(golden_ratio) * static_cast<long double>(golden_ratio);
    const std::size_t steps = std::size_t(bins) * (max_level + 2);
    bound_.resize(steps + 1);
    bin_.resize(steps);
    for(std::size_t k = 0; k < steps; ++k) {
      bound_[k] = static_cast<double>((std::pow(phi2, static_cast<long double>(k) / bins) - 1.L) / std::sqrt(5.L));
      bin_[k] = unsigned(k % bins);
    }
    bound_[steps] = std::numeric_limits<double>::infinity();
  }

  // the bin of i, from 0 to the least importance that needs more than max_level levels
  unsigned operator()(double i) const
  {
    CGAL_precondition(i >= 0. && i <= fibonacci().level_importance[max_level + 1]);
    // log2(x) for x >= 1 exceeds its exponent plus its mantissa's fraction by
    // less than 0.09: the estimate is at most 0.09 steps_per_log2_ steps low
    // sqrt(5) written out: under -frounding-math, which CGAL asks for,
    // std::sqrt(5.) is computed at every call (only an estimate, corrected below)
    const double x = 1. + 2.2360679774997896964 * i;
    std::uint64_t bits;
    std::memcpy(&bits, &x, sizeof bits);
    const double log2x = double(int(bits >> 52) - 1023) + double(bits & ((std::uint64_t(1) << 52) - 1)) * 0x1p-52;
    std::size_t k = std::size_t((std::min)(log2x * steps_per_log2_, double(bin_.size() - 1)));
    while(k > 0 && i < bound_[k]) --k;
    while(i >= bound_[k + 1]) ++k;
    return bin_[k];
  }

private:
  double steps_per_log2_;
  std::vector<double> bound_;  // bound_[k]: least importance of step k, counted from importance 0
  std::vector<unsigned> bin_;  // bin of step k
};

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_FIBONACCI_CODE_H

// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// F-codes read in the Fibonacci number system: sample thresholds, required
// subdivision levels, and the two indices of the correction table.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_FIBONACCI_CODE_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_FIBONACCI_CODE_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/Penrose_rules.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>

namespace CGAL {
namespace internal {
namespace Penrose {

// Two bits per level in a 64-bit code, and thresholds that stay exact in a
// double (F(2 * 30 + 1) < 2^53): 30 levels hold about 10^12 points per region.
constexpr int max_level = 30;

struct Fibonacci_tables
{
  std::array<std::uint64_t, 2 * max_level + 4> fib;      // fib[n] = F(n), F(1) = F(2) = 1
  // level_importance[m]: the least importance whose required level is m or more
  std::array<double, max_level + 2> level_importance;
  Fibonacci_tables()
  {
    fib[0] = 0; fib[1] = 1;
    for(std::size_t n = 2; n < fib.size(); ++n) fib[n] = fib[n - 1] + fib[n - 2];
    // required_level(I) >= m  <=>  sqrt(5) I + 1 >= phi^(2m)   (m >= 2)
    level_importance[0] = 0.;
    level_importance[1] = 0.; // any positive importance (tested with >, see below)
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

// The level required by importance i (C.5 of the sampler facts).
inline int required_level(double i)
{
  if(!(i > 0.)) return 0;
  const auto& li = fibonacci().level_importance;
  int m = 1;
  while(m <= max_level && i >= li[m + 1]) ++m;
  return m;
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

// Position of importance i within its level, in `bins` equal steps of
// log_{phi^2}(1 + sqrt(5) i); it returns to 0 where the required level rises.
inline unsigned importance_index(double i, unsigned bins)
{
  static const double inv_log_phi2 = 1. / std::log(golden_ratio * golden_ratio);
  const double l = std::log1p(std::sqrt(5.) * i) * inv_log_phi2;
  const double f = l - std::floor(l);
  return std::min(bins - 1, static_cast<unsigned>(f * bins));
}

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_FIBONACCI_CODE_H

// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A view on a table of correction vectors, indexed by importance index and
// structural index, in the frame of the sample's leaf tile.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_CORRECTION_TABLE_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_CORRECTION_TABLE_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tiling/Fibonacci_code.h>

#include <cmath>

namespace CGAL {
namespace internal {
namespace Penrose {

struct Correction_table
{
  unsigned importance_bins;  // rows: steps of the importance within a level
  int structural_bits;       // columns: Fibonacci value of this many newest code bits
  const float* vectors;      // row-major (a, b) pairs; null means no correction

  unsigned structural_indices() const { return number_of_structural_indices(structural_bits); }

  // (a, b) such that the correction is s_leaf * (a u(d_leaf) + b u(d_leaf + 5))
  const float* at(unsigned importance_index, unsigned structural_index) const
  {
    return vectors + 2 * (importance_index * structural_indices() + structural_index);
  }

  // The largest |(a, b)|: it bounds how far a sample moves, in leaf scales.
  double max_length() const
  {
    double m = 0.;
    if(vectors == nullptr) return m;
    for(unsigned k = 0; k < importance_bins * structural_indices(); ++k)
      m = (std::max)(m, std::hypot(double(vectors[2 * k]), double(vectors[2 * k + 1])));
    return m;
  }
};

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_CORRECTION_TABLE_H

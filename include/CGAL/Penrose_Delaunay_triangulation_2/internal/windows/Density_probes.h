// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The density read on a grid over a box, to size a window's margin and its
// arrays. Probes are a guess, not a bound: a margin they make too small is
// found by the certificate and grown.

#ifndef CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_DENSITY_PROBES_H
#define CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_DENSITY_PROBES_H

#include <CGAL/Penrose_Delaunay_triangulation_2/internal/tiling/Sampling_context.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace CGAL {
namespace internal {
namespace Penrose {

struct Density_probes
{
  double least_positive = std::numeric_limits<double>::infinity();  // points per unit area
  double mean = 0.;

  // The spacing of the samples where they are sparsest, times `factor`, or
  // `otherwise` where every probe reads zero.
  double spacing(double factor, double otherwise) const
  {
    return least_positive < std::numeric_limits<double>::infinity() ? factor / std::sqrt(least_positive) : otherwise;
  }
};

// `k` x `k` probes, cell centres and corners of [x0, x1] x [y0, y1]; the
// density scaled by `scale` (points per unit area).
inline Density_probes probe_density(const Sampling_context& c, double scale, double x0, double y0, double x1, double y1,
                                    int k = 9)
{
  Density_probes p;
  double sum = 0.;
  for(int j = 0; j < k; ++j)
    for(int i = 0; i < k; ++i) {
      const double x = x0 + (x1 - x0) * i / (k - 1), y = y0 + (y1 - y0) * j / (k - 1);
      const double d = c.density(x, y) * scale;
      sum += d;
      if(d > 0.) p.least_positive = (std::min)(p.least_positive, d);
    }
  p.mean = sum / (k * k);
  return p;
}

} // namespace Penrose
} // namespace internal
} // namespace CGAL

#endif // CGAL_PENROSE_DELAUNAY_TRIANGULATION_2_INTERNAL_DENSITY_PROBES_H

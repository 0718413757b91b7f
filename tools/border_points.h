// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Points along the border of a rectangle at the local density, so that a
// triangulation of the samples and of these points covers the rectangle.

#ifndef PENROSE_TOOLS_BORDER_POINTS_H
#define PENROSE_TOOLS_BORDER_POINTS_H

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace penrose_tools {

// Calls `add(x, y)` for points along the border of [x0, x1] x [y0, y1],
// counter-clockwise from the lower left corner, spaced by the mean distance
// of blue-noise samples of the density `points_per_unit_area(x, y)`,
// 1.07 / sqrt(density) (that of a hexagonal packing).
template <class Density, class Add>
void for_each_border_point(const std::array<double, 4>& region, const Density& points_per_unit_area, Add add)
{
  const double c[5][2] = {{region[0], region[1]}, {region[2], region[1]}, {region[2], region[3]},
                          {region[0], region[3]}, {region[0], region[1]}};
  for(int side = 0; side < 4; ++side) {
    const double dx = c[side + 1][0] - c[side][0], dy = c[side + 1][1] - c[side][1], length = std::hypot(dx, dy);
    for(double t = 0.; t < length;) {
      const double x = c[side][0] + dx * t / length, y = c[side][1] + dy * t / length;
      const double rho = points_per_unit_area(x, y);
      t += rho > 0. ? (std::max)(1.07 / std::sqrt(rho), 1e-9 * length) : length;
      add(x, y);
    }
  }
}

} // namespace penrose_tools

#endif // PENROSE_TOOLS_BORDER_POINTS_H

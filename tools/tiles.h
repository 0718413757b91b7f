// Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The tiles of `penrose_mesh --tiles K`: the K x K rectangles of the region,
// their file names, the cells of a raster that each refines, and each one's
// share of the vertices. Every figure that two tiles share (a side, a
// corner) is computed by one expression from the region alone, so that both
// find it bit for bit.

#ifndef PENROSE_TOOLS_TILES_H
#define PENROSE_TOOLS_TILES_H

#include "raster_maps.h"

#include <array>
#include <cmath>
#include <cstddef>
#include <string>

namespace penrose_tools {

// Boundary k of the K + 1 that cut [a, b] into K parts: equal ones, or, if
// [a, b] spans `cells` cells of a raster, on the nearest boundary between
// cells, so that no cell centre lies on a side shared by two tiles (nor
// closer to it than half a cell, where greedy insertion would put a vertex
// making slivers with the side's points).
inline double tile_boundary(double a, double b, int k, int K, std::size_t cells)
{
  if(k == K) return b;
  const double t = cells ? double(std::llround(double(cells) * double(k) / double(K))) / double(cells)
                         : double(k) / double(K);
  return a + (b - a) * t;
}

// Tile (i, j) of the K x K tiles of region = {x0, y0, x1, y1}, i from west to
// east and j from south to north, as {x0, y0, x1, y1}; `cells` is the size
// of the raster over the region, if any ({0, 0} otherwise).
inline std::array<double, 4> tile_rectangle(const std::array<double, 4>& region, int i, int j, int K,
                                            const std::array<std::size_t, 2>& cells)
{
  return {tile_boundary(region[0], region[2], i, K, cells[0]), tile_boundary(region[1], region[3], j, K, cells[1]),
          tile_boundary(region[0], region[2], i + 1, K, cells[0]),
          tile_boundary(region[1], region[3], j + 1, K, cells[1])};
}

// Which sides of tile (i, j) lie on the region's border, in the order
// bottom, right, top, left: the others are shared with a neighbour.
inline std::array<bool, 4> sides_on_region_border(int i, int j, int K)
{
  return {j == 0, i == K - 1, j == K - 1, i == 0};
}

// NAME_I_J.EXT for NAME.EXT (NAME_I_J without an extension).
inline std::string tile_file_name(const std::string& file, int i, int j)
{
  const std::size_t slash = file.find_last_of("/\\"), dot = file.find_last_of('.');
  const std::size_t stem = dot != std::string::npos && (slash == std::string::npos || dot > slash) ? dot : file.size();
  return file.substr(0, stem) + "_" + std::to_string(i) + "_" + std::to_string(j) + file.substr(stem);
}

/*
The cells of `r` whose centres lie inside `rect`, a hundredth of a cell from
its sides at least, as a raster of their own over their cells' union.
Greedy insertion on it puts vertices only strictly inside the tile, so that
nothing new lands on a side shared with a neighbour; the margin keeps the
centres that it computes from its own corners (which round differently)
inside too. Tiles whose sides lie between cells (see tile_boundary()) share
out all the cells. Empty if no cell is inside.
*/
template <class T>
Raster<T> cells_inside(const Raster<T>& r, const std::array<double, 4>& rect)
{
  const double margin_x = 0.01 * (r.x1 - r.x0) / double(r.width), margin_y = 0.01 * (r.y1 - r.y0) / double(r.height);
  auto inside_x = [&](std::size_t i) {
    const double x = r.x(double(i) + 0.5);
    return x > rect[0] + margin_x && x < rect[2] - margin_x;
  };
  auto inside_y = [&](std::size_t j) {
    const double y = r.y(double(j) + 0.5);
    return y > rect[1] + margin_y && y < rect[3] - margin_y;
  };
  std::size_t i0 = 0, j0 = 0;
  while(i0 < r.width && !inside_x(i0)) ++i0;
  while(j0 < r.height && !inside_y(j0)) ++j0;
  std::size_t i1 = i0, j1 = j0;
  while(i1 < r.width && inside_x(i1)) ++i1;
  while(j1 < r.height && inside_y(j1)) ++j1;
  Raster<T> cells;
  if(i1 == i0 || j1 == j0) return cells;
  cells.width = i1 - i0;
  cells.height = j1 - j0;
  cells.channels = r.channels;
  cells.x0 = r.x(double(i0));
  cells.x1 = r.x(double(i1));
  cells.y1 = r.y(double(j0));  // row 0 at the top
  cells.y0 = r.y(double(j1));
  for(std::size_t j = j0; j < j1; ++j) {
    const auto row = r.values.begin() + std::ptrdiff_t(r.channels * (j * r.width + i0));
    cells.values.insert(cells.values.end(), row, row + std::ptrdiff_t(r.channels * cells.width));
  }
  return cells;
}

} // namespace penrose_tools

#endif // PENROSE_TOOLS_TILES_H

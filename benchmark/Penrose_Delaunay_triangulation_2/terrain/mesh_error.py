#!/usr/bin/env python3
# Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The vertical error of a terrain mesh at every node of its height grid.

    mesh_error.py HEIGHTS.f64 WIDTH HEIGHT MESH.off [--cells] [--sample]

HEIGHTS.f64 holds WIDTH x HEIGHT little-endian doubles, row 0 (the north) first.
The mesh's vertices are (column, row, height) on the grid's nodes, as delatin
and martini write them, or, with --cells, (x, y, height) over the rectangle
(0, 0, WIDTH, HEIGHT) with y to the north, as penrose_mesh writes a PNG or an
.asc with cellsize 1 and its corner at the origin: node (i, j) is then the
centre of cell (i, j), at (i + 1/2, HEIGHT - j - 1/2). With --sample, the
vertices' heights are not the mesh's but the grid's, interpolated bilinearly
at the vertices (penrose_mesh's mesh of an image sampled for a density
option has no heights; --reconstruct renders it so).

The mesh is interpolated linearly at every node by matplotlib's triangle
finder, independently of the tools measured. Prints one CSV line:
vertices,triangles,rms,max,uncovered (nodes outside the mesh, left out of
rms and max).
"""

import sys

import numpy as np
from matplotlib.tri import LinearTriInterpolator, Triangulation


def read_off(path):
    with open(path) as f:
        words = f.read().split()
    assert words[0] == "OFF"
    n, m = int(words[1]), int(words[2])
    v = np.array(words[4:4 + 3 * n], dtype=np.float64).reshape(n, 3)
    f = np.array(words[4 + 3 * n:4 + 3 * n + 4 * m], dtype=np.int64).reshape(m, 4)
    assert np.all(f[:, 0] == 3)
    return v, f[:, 1:]


def bilinear(heights, u, w):
    h, wd = heights.shape
    u, w = np.clip(u, 0, wd - 1), np.clip(w, 0, h - 1)
    i, j = np.minimum(u.astype(int), wd - 2), np.minimum(w.astype(int), h - 2)
    a, b = u - i, w - j
    return ((1 - a) * (1 - b) * heights[j, i] + a * (1 - b) * heights[j, i + 1]
            + (1 - a) * b * heights[j + 1, i] + a * b * heights[j + 1, i + 1])


def main(heights_file, width, height, mesh_file, cells=False, sample=False):
    width, height = int(width), int(height)
    heights = np.fromfile(heights_file, dtype="<f8").reshape(height, width)
    v, faces = read_off(mesh_file)
    u, w = (v[:, 0] - 0.5, height - v[:, 1] - 0.5) if cells else (v[:, 0], v[:, 1])
    z = bilinear(heights, u, w) if sample else v[:, 2]
    interpolated = LinearTriInterpolator(Triangulation(u, w, faces), z)
    rows, columns = np.mgrid[0:height, 0:width]
    z = interpolated(columns.ravel().astype(np.float64), rows.ravel().astype(np.float64))
    error = np.ma.abs(z - heights.ravel())
    uncovered = int(np.ma.count_masked(error))
    covered = error.compressed()
    print(f"{len(v)},{len(faces)},{np.sqrt(np.mean(covered ** 2)):.6g},{covered.max():.6g},{uncovered}")


if __name__ == "__main__":
    main(*sys.argv[1:5], cells="--cells" in sys.argv[5:], sample="--sample" in sys.argv[5:])

#!/usr/bin/env python3
# Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The regular grid mesh of about N vertices over a height grid, the baseline
that image_benchmark.sh compares the meshes with.

    grid_mesh.py HEIGHTS.f64 WIDTH HEIGHT N OUT.off

HEIGHTS.f64 holds WIDTH x HEIGHT little-endian doubles, row 0 first. The
vertices are nodes of the height grid, (column, row, height) as delatin
writes them, about as many per unit length across as down, the first and
last rows and columns included; each cell of the mesh is cut in two.
"""

import sys

import numpy as np


def main(heights_file, width, height, n, out):
    width, height, n = int(width), int(height), int(n)
    heights = np.fromfile(heights_file, dtype="<f8").reshape(height, width)
    nx = max(2, round((n * width / height) ** 0.5))
    ny = max(2, round(n / nx))
    columns = np.round(np.linspace(0, width - 1, nx)).astype(int)
    rows = np.round(np.linspace(0, height - 1, ny)).astype(int)
    lines = ["OFF", f"{nx * ny} {2 * (nx - 1) * (ny - 1)} 0"]
    lines += [f"{c} {r} {heights[r, c]!r}" for r in rows for c in columns]
    for j in range(ny - 1):
        for i in range(nx - 1):
            a = j * nx + i
            lines += [f"3 {a} {a + 1} {a + nx + 1}", f"3 {a} {a + nx + 1} {a + nx}"]
    with open(out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main(*sys.argv[1:6])

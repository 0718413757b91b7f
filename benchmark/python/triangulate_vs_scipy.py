#!/usr/bin/env python3
# Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Times penrose_delaunay.triangulate() against scipy.spatial.Delaunay on its output points.

    PYTHONPATH=build/python /usr/bin/python3 benchmark/python/triangulate_vs_scipy.py [N] [RUNS]

For each kind of density (a number, a 256 x 256 raster, a Python function),
the whole triangulate() call, sampling included, and scipy's Delaunay (Qhull)
of the points it returned are timed in this process, alternately; the
medians of RUNS runs and their ratio are printed, with the number of
triangles found by only one of the two. Qhull decides in floating point and
merges the flattest triangles along the convex hull, which exact predicates
keep: at 10^6 points a few dozen hull slivers are the package's only.
"""

import statistics
import sys
import time

import numpy as np
from scipy.spatial import Delaunay

import penrose_delaunay as pd


def raster(size=256):
    v, u = np.mgrid[0:size, 0:size] + 0.5
    return 0.05 + u / size + 4.0 * np.exp(-((u - 0.7 * size) ** 2 + (v - 0.3 * size) ** 2) / (0.02 * size * size))


def timed(f):
    start = time.perf_counter()
    result = f()
    return time.perf_counter() - start, result


def main(n=1000000, runs=5):
    densities = {"number": 1.0, "raster 256x256": raster(), "function 1+4x": lambda x, y: 1 + 4 * x}
    print(f"{n} points, medians of {runs} runs")
    print("density, triangulate() s, scipy Delaunay s, ratio, triangles only ours, only scipy's")
    for name, density in densities.items():
        ours, theirs = [], []
        for _ in range(runs):
            t, (points, simplices) = timed(lambda: pd.triangulate(density, n=n))
            ours.append(t)
            t, reference = timed(lambda: Delaunay(points))
            theirs.append(t)
        mine = set(map(tuple, np.sort(simplices, axis=1)))
        qhull = set(map(tuple, np.sort(reference.simplices, axis=1)))
        a, b = statistics.median(ours), statistics.median(theirs)
        print(f"{name}, {a:.3f}, {b:.3f}, {a / b:.3f}, {len(mine - qhull)}, {len(qhull - mine)}")


if __name__ == "__main__":
    main(int(float(sys.argv[1])) if len(sys.argv) > 1 else 1000000, int(sys.argv[2]) if len(sys.argv) > 2 else 5)

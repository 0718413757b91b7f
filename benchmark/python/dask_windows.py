# Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Times penrose_delaunay.dask.triangulate() on LocalClusters of 1 and 2 worker
processes (one thread each), medians of RUNS, and checks that both stores hold
the same triangles as penrose_delaunay.triangulate() (at most 10^6 points; the
check takes longer than the run).

usage: PYTHONPATH=build/python python3 benchmark/python/dask_windows.py [N] [KX KY] [RUNS]
"""

import os
import shutil
import statistics
import sys
import tempfile
import time

import numpy as np
from distributed import Client, LocalCluster

import penrose_delaunay as pd
import penrose_delaunay.dask as pdd


def point_triangles(points, triangles):
    return set(tuple(sorted(map(tuple, points[t]))) for t in triangles)


def main():
    n = int(float(sys.argv[1])) if len(sys.argv) > 1 else 10**7
    kx, ky = (int(sys.argv[2]), int(sys.argv[3])) if len(sys.argv) > 3 else (4, 4)
    runs = int(sys.argv[4]) if len(sys.argv) > 4 else 3
    density = np.linspace(0.0, 1.0, 1024)[None, :].repeat(4, axis=0)  # the ramp as a raster: no Python in the loop
    folder = tempfile.mkdtemp()
    seconds = {}
    try:
        for workers in (1, 2):
            with LocalCluster(n_workers=workers, processes=True, threads_per_worker=1,
                              dashboard_address=None) as cluster, Client(cluster) as client:
                times = []
                for r in range(runs):
                    store = os.path.join(folder, f"w{workers}_{r}.zarr")
                    t = time.perf_counter()
                    z = pdd.triangulate(density, region=(0, 0, 1, 1), n=n, windows=(kx, ky), store=store,
                                        client=client)
                    times.append(time.perf_counter() - t)
                    print(f"{workers} worker(s), run {r}: {times[-1]:.2f} s, {len(z['points'])} points, "
                          f"{len(z['triangles'])} triangles", flush=True)
                seconds[workers] = statistics.median(times)
                if n <= 10**6:
                    points, triangles = pd.triangulate(density, region=(0, 0, 1, 1), n=n)
                    same = point_triangles(z["points"][:], z["triangles"][:]) == point_triangles(points, triangles)
                    print(f"  the same triangles as triangulate(): {same}")
        print(f"{n} points, {kx} x {ky} windows: 1 worker {seconds[1]:.2f} s, 2 workers {seconds[2]:.2f} s, "
              f"speed-up {seconds[1] / seconds[2]:.2f}")
    finally:
        shutil.rmtree(folder)


if __name__ == "__main__":
    main()

#!/usr/bin/env python3
# Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Height grids for terrain_benchmark.sh, each as NAME.asc (for penrose_mesh)
and NAME.f64 (for the other tools and the evaluator).

    make_dems.py OUT_DIR [SIZE]        two synthetic DEMs: volcano, hills
    make_dems.py OUT_DIR --png FILE    a 16-bit grey PNG's heights (data/terrain.png)

The synthetic ones are deterministic: a volcano (a cone with a crater,
ravines down its flanks and fractal noise) and rolling hills (smooth bumps
and fractal noise), in metres on 1 m cells.
"""

import os
import sys

import numpy as np


def fractal_noise(size, rng, octaves=7):
    total = np.zeros((size, size))
    for o in range(octaves):
        cells = 2 ** (o + 2)
        coarse = rng.standard_normal((cells + 1, cells + 1))
        t = np.linspace(0, cells, size)
        i = np.minimum(t.astype(int), cells - 1)
        f = t - i
        f = f * f * (3 - 2 * f)  # smoothstep: no crease along the coarse grid's lines
        rows = coarse[i] * (1 - f)[:, None] + coarse[i + 1] * f[:, None]
        total += (rows[:, i] * (1 - f) + rows[:, i + 1] * f) / 2 ** o
    return total


def volcano(size, rng):
    y, x = (np.mgrid[0:size, 0:size] + 0.5) / size - 0.5
    r = np.hypot(x, y)
    angle = np.arctan2(y, x)
    cone = 900 * np.exp(-r / 0.18) - 500 * np.exp(-(r / 0.05) ** 2)
    ravines = 40 * np.abs(np.sin(9 * angle)) * np.clip(r / 0.1, 0, 1) * np.exp(-r / 0.3)
    return cone - ravines + 25 * fractal_noise(size, rng)


def hills(size, rng):
    y, x = (np.mgrid[0:size, 0:size] + 0.5) / size
    z = np.zeros((size, size))
    for _ in range(30):
        cx, cy, s, a = rng.uniform(0, 1), rng.uniform(0, 1), rng.uniform(0.05, 0.2), rng.uniform(20, 120)
        z += a * np.exp(-((x - cx) ** 2 + (y - cy) ** 2) / (2 * s * s))
    return z + 15 * fractal_noise(size, rng)


def write(out_dir, name, z):
    height, width = z.shape
    z.astype("<f8").tofile(os.path.join(out_dir, name + ".f64"))
    with open(os.path.join(out_dir, name + ".asc"), "w") as f:
        f.write(f"ncols {width}\nnrows {height}\nxllcorner 0\nyllcorner 0\ncellsize 1\n")
        np.savetxt(f, z, fmt="%.17g")
    print(name, width, height)


def main(out_dir, *args):
    os.makedirs(out_dir, exist_ok=True)
    if args and args[0] == "--png":
        import matplotlib.image
        z = np.round(matplotlib.image.imread(args[1]).astype(np.float64) * 65535)
        write(out_dir, os.path.splitext(os.path.basename(args[1]))[0], z)
        return
    size = int(args[0]) if args else 512
    rng = np.random.default_rng(2004)
    write(out_dir, "volcano", volcano(size, rng))
    write(out_dir, "hills", hills(size, rng))


if __name__ == "__main__":
    main(*sys.argv[1:])

# Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Draws the manual's figure of the windowed construction: a 3 x 3 partition
of the region, one window with its margin, the triangles it owns (their
circumcentres in it), those of the other windows, and the border's (their
circumcentres outside the region), from penrose_delaunay.window_triangles().

usage: PYTHONPATH=build/python python3 benchmark/python/plot_windows.py OUT.png
"""

import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.collections import PolyCollection  # noqa: E402
from matplotlib.patches import Rectangle  # noqa: E402

import penrose_delaunay as pd  # noqa: E402

N = 1500
MARGIN = 0.06
DENSITY = lambda x, y: 0.3 + x  # noqa: E731


def main(out):
    cuts = [0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0]
    integral = pd.density_integral(DENSITY)
    points, keys, triangles = {}, [], {}
    for j in range(3):
        for i in range(3):
            w = (cuts[i], cuts[j], cuts[i + 1], cuts[j + 1])
            p, k, t = pd.window_triangles(DENSITY, n=N, window=w, integral=integral, border=False,
                                          margin=MARGIN if (i, j) == (1, 1) else 0.0)
            points.update(zip(k.tolist(), map(tuple, p)))
            triangles[(i, j)] = t
    _, _, border = pd.window_triangles(DENSITY, n=N, integral=integral)
    xy = lambda t: np.array([[points[int(k)] for k in row] for row in t])  # noqa: E731

    fig, ax = plt.subplots(figsize=(7, 7))
    others = np.concatenate([xy(t) for w, t in triangles.items() if w != (1, 1)])
    ax.add_collection(PolyCollection(others, facecolors="none", edgecolors="0.75", linewidths=0.4))
    ax.add_collection(PolyCollection(xy(triangles[(1, 1)]), facecolors="#9ecae1", edgecolors="#08519c",
                                     linewidths=0.5, label="owned by the middle window"))
    ax.add_collection(PolyCollection(xy(border), facecolors="#fdae6b", edgecolors="#a63603", linewidths=0.5,
                                     label="the border's (circumcentre outside the region)"))
    for c in cuts[1:-1]:
        ax.axvline(c, color="k", lw=0.8, ls=":")
        ax.axhline(c, color="k", lw=0.8, ls=":")
    ax.add_patch(Rectangle((1 / 3, 1 / 3), 1 / 3, 1 / 3, fill=False, ec="#08519c", lw=1.8, label="a window"))
    ax.add_patch(Rectangle((1 / 3 - MARGIN, 1 / 3 - MARGIN), 1 / 3 + 2 * MARGIN, 1 / 3 + 2 * MARGIN, fill=False,
                           ec="#08519c", lw=1.2, ls="--", label="its margin"))
    pts = np.array(list(points.values()))
    ax.plot(pts[:, 0], pts[:, 1], ".", ms=1.5, color="k")
    ax.set_xlim(-0.02, 1.02)
    ax.set_ylim(-0.02, 1.02)
    ax.set_aspect("equal")
    ax.legend(loc="upper left", fontsize=8, framealpha=0.9)
    ax.set_title(f"{len(pts)} samples of 0.3 + x, 3 x 3 windows: each triangle once")
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main(sys.argv[1])

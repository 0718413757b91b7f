#!/usr/bin/env python3
# Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Plots terrain_benchmark.sh's CSV: RMS and maximum error against vertices, one figure a DEM.

    plot_terrain_benchmark.py terrain.csv OUT_DIR
"""

import csv
import sys
from collections import defaultdict

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402


def main(path, out_dir):
    rows = defaultdict(lambda: defaultdict(list))
    with open(path) as f:
        for r in csv.DictReader(f):
            rows[r["dem"]][r["tool"]].append((int(r["vertices"]), float(r["rms"]), float(r["max"])))
    for dem, tools in rows.items():
        fig, (a, b) = plt.subplots(1, 2, figsize=(10, 4))
        for tool, values in sorted(tools.items()):
            values.sort()
            a.loglog([v[0] for v in values], [v[1] for v in values], "o-", label=tool)
            b.loglog([v[0] for v in values], [v[2] for v in values], "o-", label=tool)
        a.set(title=f"{dem}: RMS error", xlabel="vertices")
        b.set(title=f"{dem}: maximum error", xlabel="vertices")
        a.legend()
        fig.tight_layout()
        fig.savefig(f"{out_dir}/terrain_{dem}.png", dpi=100)


if __name__ == "__main__":
    main(*sys.argv[1:3])

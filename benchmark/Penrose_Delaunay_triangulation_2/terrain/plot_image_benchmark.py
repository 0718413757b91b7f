#!/usr/bin/env python3
# Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Plots image_benchmark.sh's CSV: the PSNR of the luminance against vertices, one panel an image.

    plot_image_benchmark.py image.csv OUT_DIR      writes OUT_DIR/image_psnr.png
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
            rows[r["image"]][r["tool"]].append((int(r["vertices"]), float(r["psnr"])))
    fig, axes = plt.subplots(1, len(rows), figsize=(5 * len(rows), 4), squeeze=False)
    for a, (image, tools) in zip(axes[0], rows.items()):
        for tool, values in sorted(tools.items()):
            values.sort()
            a.semilogx([v[0] for v in values], [v[1] for v in values], "o-", label=tool)
        a.set(title=f"{image}: luminance", xlabel="vertices", ylabel="PSNR (dB)")
        a.legend()
    fig.tight_layout()
    fig.savefig(f"{out_dir}/image_psnr.png", dpi=100)


if __name__ == "__main__":
    main(*sys.argv[1:3])

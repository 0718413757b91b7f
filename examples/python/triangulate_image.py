#!/usr/bin/env python3
# Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Meshes an image with penrose_delaunay and draws the mesh and the image it renders.

    PYTHONPATH=build/python python3 examples/python/triangulate_image.py data/test_image.png 20000 mesh.png

The density follows the image's edges (the gradient of its luminance), with a
floor so that flat areas keep a few vertices: the triangles are small along
the edges and large elsewhere. The right panel colours the triangulation with
the luminance at its vertices, interpolated linearly: the image as the mesh
renders it.
"""

import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
from matplotlib.tri import Triangulation  # noqa: E402

import penrose_delaunay as pd  # noqa: E402


def luminance(path):
    image = plt.imread(path).astype(np.float64)
    if image.ndim == 3:
        image = image[..., :3] @ np.array([0.2126, 0.7152, 0.0722])
    return image


def main(path="data/test_image.png", n=20000, out="image_triangulation.png"):
    lum = luminance(path)
    height, width = lum.shape
    gy, gx = np.gradient(lum)
    edges = np.hypot(gx, gy)
    density = edges / edges.mean() + 0.1

    # One unit a pixel: the region is (0, 0, width, height), y upwards.
    points, simplices = pd.triangulate(density, n=n, boundary=True)
    columns = np.clip(points[:, 0].astype(int), 0, width - 1)
    rows = np.clip((height - points[:, 1]).astype(int), 0, height - 1)
    mesh = Triangulation(points[:, 0], points[:, 1], simplices)

    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 6 * height / width))
    left.triplot(mesh, color="black", linewidth=0.15)
    left.set_title(f"{len(points)} vertices, {len(simplices)} triangles")
    right.tripcolor(mesh, lum[rows, columns], shading="gouraud", cmap="gray")
    right.set_title("the image rendered by the mesh")
    for ax in (left, right):
        ax.set_aspect("equal")
        ax.set_xlim(0, width)
        ax.set_ylim(0, height)
        ax.axis("off")
    fig.tight_layout()
    fig.savefig(out, dpi=150, bbox_inches="tight")
    print(f"{out}: {len(points)} vertices, {len(simplices)} triangles")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "data/test_image.png",
         int(sys.argv[2]) if len(sys.argv) > 2 else 20000,
         sys.argv[3] if len(sys.argv) > 3 else "image_triangulation.png")

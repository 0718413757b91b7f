#!/usr/bin/env python3
# Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""A photograph for image_benchmark.sh, larger than data/test_image.png and
unlike its flat shapes: SciPy's raccoon face (1024 x 768, 8-bit RGB, fur,
leaves and shadows), bundled with Debian's python3-scipy.

    make_images.py OUT_DIR      writes OUT_DIR/face.png
"""

import os
import sys
import warnings

import matplotlib.image
from scipy import misc


def main(out_dir):
    os.makedirs(out_dir, exist_ok=True)
    with warnings.catch_warnings():  # misc.face moves to scipy.datasets, which downloads it
        warnings.simplefilter("ignore", DeprecationWarning)
        face = misc.face()
    matplotlib.image.imsave(os.path.join(out_dir, "face.png"), face)


if __name__ == "__main__":
    main(sys.argv[1])

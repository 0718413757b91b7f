# Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Blue-noise points that follow a density, and their Delaunay triangulation.

The functions are those of the C++ extension `penrose_delaunay._core` (see
its documentation, `help(penrose_delaunay._core)`). `penrose_delaunay.dask`
maps the windows of `window_triangles()` over a dask.distributed cluster; it
is imported only when asked for, so that this package does not need dask.
"""

from ._core import __doc__ as _core_doc
from ._core import density_integral, sample, triangulate, window_triangles

__all__ = ["density_integral", "sample", "triangulate", "window_triangles"]
__doc__ = _core_doc

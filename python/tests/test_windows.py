# Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""window_triangles() and penrose_delaunay.dask against triangulate()."""

import os
import subprocess
import sys

import numpy as np
import pytest

import penrose_delaunay as pd


def point_triangles(points, triangles):
    """The triangles as a set of point triples, each sorted: comparable across numberings."""
    return set(tuple(sorted(map(tuple, points[t]))) for t in triangles)


def cuts(lo, hi, k):
    return [lo + (hi - lo) * i / k for i in range(k)] + [hi]


def signed_areas(points, triangles):
    a, b, c = points[triangles[:, 0]], points[triangles[:, 1]], points[triangles[:, 2]]
    return (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])


def union_of_windows(density, region, n, xs, ys, **kwargs):
    integral = pd.density_integral(density, region)
    points, keys, triangles = [], [], []
    for j in range(len(ys) - 1):
        for i in range(len(xs) - 1):
            p, k, t = pd.window_triangles(density, region=region, n=n, window=(xs[i], ys[j], xs[i + 1], ys[j + 1]),
                                          integral=integral, **kwargs)
            assert p.shape == (len(k), 2) and k.dtype == np.uint64 and t.dtype == np.uint64
            assert np.all(np.diff(k.astype(np.float64)) > 0), "keys increase within a window"
            points.append(p)
            keys.append(k)
            triangles.append(t)
    points, keys, triangles = np.concatenate(points), np.concatenate(keys), np.concatenate(triangles)
    order = np.argsort(keys)
    assert np.all(keys[order][1:] != keys[order][:-1]), "a sample in two windows"
    return points, order[np.searchsorted(keys[order], triangles)]


RAMP = lambda x, y: 0.05 + x  # noqa: E731


def holed_raster():
    v, u = np.mgrid[0:64, 0:96] + 0.5
    r = 0.2 + u / 96.0
    r[np.hypot(u - 40, v - 30) < 12] = 0.0
    r[:10, 80:] = 0.0
    return r


@pytest.mark.parametrize("density, region", [(1.0, None), (RAMP, (0.0, 0.0, 2.0, 1.0)), (holed_raster(), None)])
@pytest.mark.parametrize("grid", [(1, 1), (3, 2), (7, 5)])
def test_union_of_windows_is_the_triangulation(density, region, grid):
    n = 30000
    points, triangles = pd.triangulate(density, region=region, n=n)
    r = region or ((0, 0, 96, 64) if isinstance(density, np.ndarray) else (0, 0, 1, 1))
    wp, wt = union_of_windows(density, region, n, cuts(r[0], r[2], grid[0]), cuts(r[1], r[3], grid[1]))
    assert len(wp) == len(points)
    assert len(wt) == len(triangles)
    assert np.all(signed_areas(wp, wt) > 0), "counter-clockwise triangles"
    assert point_triangles(wp, wt) == point_triangles(points, triangles)


def test_irregular_windows_and_a_margin_too_small():
    n = 20000
    points, triangles = pd.triangulate(RAMP, n=n)
    wp, wt = union_of_windows(RAMP, None, n, [-1.0, 0.1, 0.37, 0.38, 1.0], [0.0, 0.5, 0.93, 2.0], margin=1e-5)
    assert point_triangles(wp, wt) == point_triangles(points, triangles)


def test_a_window_alone_gives_the_same_bytes():
    """The same bytes whether the sampler integrates the density or is given the integral; another
    margin gives the same samples and triangles, the triangles in another order."""
    integral = pd.density_integral(RAMP)
    window = (0.25, 0.25, 0.5, 0.75)
    a = pd.window_triangles(RAMP, n=20000, window=window, integral=integral)
    b = pd.window_triangles(RAMP, n=20000, window=window)
    for x, y in zip(a, b):
        assert x.tobytes() == y.tobytes()
    c = pd.window_triangles(RAMP, n=20000, window=window, integral=integral, margin=0.3)
    assert a[0].tobytes() == c[0].tobytes() and a[1].tobytes() == c[1].tobytes()
    rows = lambda t: set(tuple(np.roll(r, -int(np.argmin(r)))) for r in t)  # noqa: E731
    assert rows(a[2]) == rows(c[2])


def test_bad_windows_are_refused():
    with pytest.raises(ValueError):
        pd.window_triangles(1.0, n=100, window=(0.5, 0.0, 0.4, 1.0))
    with pytest.raises(ValueError):
        pd.window_triangles(1.0, n=100, window=(0.0, 0.0, 1.0, 1.0), integral=float("nan"))
    with pytest.raises(ValueError):
        pd.window_triangles(1.0, n=100, window=(0.0, 0.0, 1.0, 1.0), margin=-1.0)


def test_importing_the_package_does_not_import_dask():
    code = "import sys, penrose_delaunay; assert 'dask' not in sys.modules and 'distributed' not in sys.modules"
    subprocess.run([sys.executable, "-c", code], check=True, env=dict(os.environ))


@pytest.fixture(scope="module")
def client():
    distributed = pytest.importorskip("distributed")
    cluster = distributed.LocalCluster(n_workers=2, processes=True, threads_per_worker=1, dashboard_address=None)
    c = distributed.Client(cluster)
    yield c
    c.close()
    cluster.close()


@pytest.mark.filterwarnings("ignore::DeprecationWarning")  # tornado, under distributed 2022.12
@pytest.mark.parametrize("density", [RAMP, holed_raster()])
def test_dask_gives_the_in_process_triangulation(client, tmp_path, density):
    import penrose_delaunay.dask as pdd
    n = 100000
    points, triangles = pd.triangulate(density, n=n)
    z = pdd.triangulate(density, n=n, windows=(3, 4), store=str(tmp_path / "t.zarr"), client=client)
    p, t, h = z["points"][:], z["triangles"][:], z["hull"][:]
    assert p.dtype == np.float64 and t.dtype == np.int64 and z["keys"].dtype == np.uint64
    assert len(t) == 2 * len(p) - len(h) - 2
    assert np.all(signed_areas(p, t) > 0)
    assert point_triangles(p, t) == point_triangles(points, triangles)


def test_a_window_of_a_region_larger_than_one_process():
    """triangulate() refuses 2 x 10^8 points; a window of them holds its part only."""
    with pytest.raises(MemoryError):
        pd.triangulate(1.0, n=200_000_000)
    integral = pd.density_integral(1.0)
    p, k, t = pd.window_triangles(1.0, n=200_000_000, window=(0.5, 0.5, 0.51, 0.51), integral=integral, border=False)
    assert 19000 < len(p) < 21000
    assert len(t) > 1.9 * len(p)

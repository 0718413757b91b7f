# Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Tests of the Python module penrose_delaunay against scipy and the C++ tool."""

import os
import subprocess
import threading

import numpy as np
import pytest
from scipy.spatial import Delaunay

import penrose_delaunay as pd


def sorted_rows(points):
    """The rows of an (N, 2) array in lexicographic order, to compare point sets."""
    return points[np.lexsort((points[:, 1], points[:, 0]))]


def triangle_set(simplices):
    """The triangles as a set of vertex triples, each in ascending order."""
    return set(map(tuple, np.sort(simplices, axis=1)))


def gaussian_image(size=256):
    """A bright disc on a dark ramp, as an image: row 0 at the top."""
    v, u = np.mgrid[0:size, 0:size] + 0.5
    disc = np.exp(-((u - 0.7 * size) ** 2 + (v - 0.3 * size) ** 2) / (0.02 * size * size))
    return 0.05 + u / size + 4.0 * disc


def orientation(points, simplices):
    a, b, c = (points[simplices[:, k]] for k in range(3))
    return (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])


# --- sample() ---------------------------------------------------------------

def test_sample_returns_float64_rows_inside_the_region():
    p = pd.sample(lambda x, y: 1 + (x + 2) * y, region=(-2.0, 1.0, 3.0, 2.5), n=5000)
    assert p.dtype == np.float64 and p.ndim == 2 and p.shape[1] == 2
    assert p.flags.c_contiguous
    assert np.all(p[:, 0] >= -2.0) and np.all(p[:, 0] <= 3.0)
    assert np.all(p[:, 1] >= 1.0) and np.all(p[:, 1] <= 2.5)
    assert len(np.unique(p, axis=0)) == len(p)


@pytest.mark.parametrize("n", [1000, 10000, 100000])
@pytest.mark.parametrize("density", [1.0, "ramp", "raster"])
def test_counts_follow_n(n, density):
    if density == "ramp":
        density = lambda x, y: 1 + 4 * x  # noqa: E731
    elif density == "raster":
        density = gaussian_image(64)
    p = pd.sample(density, n=n)
    assert abs(len(p) - n) <= 0.03 * n + 10


def test_without_n_the_count_is_the_integral_of_the_density():
    assert abs(len(pd.sample(2000.0)) - 2000) <= 60
    assert abs(len(pd.sample(10.0, region=(0, 0, 20, 10))) - 2000) <= 60
    assert abs(len(pd.sample(1000.0, scale=3.0)) - 3000) <= 90


def test_sampling_is_deterministic():
    a = pd.sample(lambda x, y: np.exp(-x * y), n=3000)
    b = pd.sample(lambda x, y: np.exp(-x * y), n=3000)
    assert np.array_equal(a, b)


def test_windows_partition_the_sample():
    density = gaussian_image(64)
    whole = pd.sample(density, n=20000)
    cuts_x, cuts_y = sorted([0, 10.5, whole[7, 0], 40, 64]), sorted([0, whole[99, 1], 33.3, 64])
    parts = [pd.sample(density, n=20000, window=(x0, y0, x1, y1))
             for x0, x1 in zip(cuts_x[:-1], cuts_x[1:]) for y0, y1 in zip(cuts_y[:-1], cuts_y[1:])]
    assert max(len(p) for p in parts) < len(whole)
    assert np.array_equal(sorted_rows(np.concatenate(parts)), sorted_rows(whole))
    assert np.array_equal(pd.sample(density, n=20000, window=(-5, -5, 100, 100)), whole)
    assert len(pd.sample(density, n=20000, window=(70, 70, 80, 80))) == 0
    with pytest.raises(ValueError):
        pd.sample(density, n=20000, window=(5, 5, 1, 1))
    with pytest.raises(ValueError):
        pd.sample(density, n=20000, window=(0, 0, float("nan"), 1))


def test_correction_vectors_move_the_samples():
    a = pd.sample(1.0, n=2000)
    b = pd.sample(1.0, n=2000, correction=False)
    assert abs(len(a) - len(b)) < 20
    assert len(set(map(tuple, a)) & set(map(tuple, b))) < 20


def test_a_function_gives_the_points_of_the_same_density_given_otherwise():
    # A constant: the function's points are those of the number, bit for bit.
    assert np.array_equal(pd.sample(lambda x, y: np.full_like(x, 3.0), n=20000), pd.sample(3.0, n=20000))
    # A function may return one number for all the points.
    assert np.array_equal(pd.sample(lambda x, y: 3.0, n=2000), pd.sample(3.0, n=2000))


@pytest.mark.skipif("PENROSE_MESH" not in os.environ, reason="needs the penrose_mesh tool (set by ctest)")
def test_a_function_gives_the_points_of_the_cpp_sampler(tmp_path):
    # penrose_mesh's ramp is the density x over the unit square, evaluated in C++.
    out = tmp_path / "ramp.xy"
    subprocess.run([os.environ["PENROSE_MESH"], "--density", "ramp", "--points", "50000",
                    "--out-points", str(out)], check=True, capture_output=True)
    reference = np.loadtxt(out)
    points = pd.sample(lambda x, y: x, n=50000)
    assert points.shape == reference.shape
    assert np.array_equal(sorted_rows(points), sorted_rows(reference))


def test_a_raster_density_follows_the_image():
    # Dark left half, bright right half, nine times brighter.
    image = np.ones((64, 64))
    image[:, 32:] = 9.0
    p = pd.sample(image, n=20000)
    assert p[:, 0].min() >= 0 and p[:, 0].max() <= 64
    left = np.count_nonzero(p[:, 0] < 32)
    right = np.count_nonzero(p[:, 0] >= 32)
    assert 8.0 < right / left < 10.0
    # Row 0 is the top: bright top rows give points of large y.
    top = np.ones((64, 64))
    top[:32, :] = 9.0
    q = pd.sample(top, n=20000)
    assert np.count_nonzero(q[:, 1] > 32) > 8 * np.count_nonzero(q[:, 1] < 32)


def test_a_raster_accepts_other_number_types_and_layouts():
    image = gaussian_image(64)
    reference = pd.sample(image, n=5000)
    assert np.array_equal(pd.sample(image.astype(np.float32).astype(np.float64), n=5000), reference)
    assert np.array_equal(pd.sample(np.asfortranarray(image), n=5000), reference)
    strided = np.zeros((64, 128))
    strided[:, ::2] = image
    assert np.array_equal(pd.sample(strided[:, ::2], n=5000), reference)
    assert np.array_equal(pd.sample(np.round(image * 1000).astype(np.int64) / 1000.0, n=5000),
                          pd.sample(np.round(image * 1000).astype(np.int64).astype(np.float64) / 1000.0, n=5000))


# --- triangulate() ----------------------------------------------------------

def test_triangulate_gives_the_points_of_sample_and_scipys_triangles():
    image = gaussian_image(256)
    points, simplices = pd.triangulate(image, n=100000)
    samples = pd.sample(image, n=100000)
    assert abs(len(points) - 100000) < 3000
    assert np.array_equal(sorted_rows(points), sorted_rows(samples))
    assert simplices.dtype == np.int32 and simplices.shape[1] == 3
    assert np.all(orientation(points, simplices) > 0)
    reference = Delaunay(points)
    assert len(simplices) == len(reference.simplices)
    assert triangle_set(simplices) == triangle_set(reference.simplices)


@pytest.mark.parametrize("density", [1.0, "ramp"])
def test_triangles_are_scipys_for_numbers_and_functions(density):
    if density == "ramp":
        density = lambda x, y: 0.1 + x * x  # noqa: E731
    points, simplices = pd.triangulate(density, region=(10.0, -5.0, 12.0, -4.0), n=20000)
    assert np.array_equal(sorted_rows(points), sorted_rows(pd.sample(density, region=(10.0, -5.0, 12.0, -4.0), n=20000)))
    assert triangle_set(simplices) == triangle_set(Delaunay(points).simplices)


@pytest.mark.parametrize("density", [1.0, "raster", "function"])
def test_every_thread_count_gives_the_same_mesh(density):
    # large enough for the construction's walks to be split in tasks
    density = {1.0: 1.0, "raster": gaussian_image(128), "function": lambda x, y: 0.1 + x * x}[density]
    n = 20000 if callable(density) else 200000
    points, simplices, neighbors = pd.triangulate(density, n=n, boundary=True, neighbors=True)
    for threads in [0, 2, 3]:
        p, s, nb = pd.triangulate(density, n=n, boundary=True, neighbors=True, threads=threads)
        assert np.array_equal(p, points) and np.array_equal(s, simplices) and np.array_equal(nb, neighbors)
    with pytest.raises(ValueError):
        pd.triangulate(density, n=1000, threads=-1)


def test_neighbors_are_scipys():
    points, simplices, neighbors = pd.triangulate(gaussian_image(64), n=3000, neighbors=True)
    assert neighbors.dtype == np.int32 and neighbors.shape == simplices.shape
    reference = Delaunay(points)
    # Map each of our triangles to scipy's, then compare the neighbour opposite each vertex.
    index = {tuple(sorted(t)): k for k, t in enumerate(reference.simplices)}
    for t, (s, n) in enumerate(zip(simplices, neighbors)):
        r = index[tuple(sorted(s))]
        for j in range(3):
            rj = list(reference.simplices[r]).index(s[j])
            expected = reference.neighbors[r][rj]
            if expected == -1:
                assert n[j] == -1
            else:
                assert tuple(sorted(simplices[n[j]])) == tuple(sorted(reference.simplices[expected]))
    assert np.count_nonzero(neighbors == -1) == len(reference.convex_hull)


def test_boundary_points_make_the_triangles_cover_the_region():
    region = (0.0, 0.0, 2.0, 1.0)
    points, simplices = pd.triangulate(lambda x, y: 1 + x, region=region, n=5000, boundary=True)
    samples = pd.sample(lambda x, y: 1 + x, region=region, n=5000)
    # the samples come first, but for those too close to the border
    kept = sorted_rows(samples)
    kept = kept[np.isin(kept.view([('', kept.dtype)] * 2), points.view([('', points.dtype)] * 2))[:, 0]]
    assert np.array_equal(sorted_rows(points[:len(kept)]), kept)
    assert 0 < len(samples) - len(kept) < 0.05 * len(samples)
    spacing = 1.07 / np.sqrt(5000 / 4.0 * (1 + samples[:, 0]))  # the density's integral is 4
    border_distance = np.minimum(np.minimum(samples[:, 0], 2.0 - samples[:, 0]),
                                 np.minimum(samples[:, 1], 1.0 - samples[:, 1]))
    dropped = ~np.isin(samples.view([('', samples.dtype)] * 2), points.view([('', points.dtype)] * 2))[:, 0]
    assert np.all(border_distance[dropped] < 0.5 * spacing[dropped])
    area = 0.5 * orientation(points, simplices).sum()
    assert area == pytest.approx(2.0, rel=1e-12)
    assert triangle_set(simplices) == triangle_set(Delaunay(points).simplices)
    # no triangle with a vertex on the border has an angle under 15 degrees
    on_border = (points[:, 0] == 0.0) | (points[:, 0] == 2.0) | (points[:, 1] == 0.0) | (points[:, 1] == 1.0)
    at_border = simplices[on_border[simplices].any(axis=1)]
    corners = points[at_border]
    angles = []
    for i in range(3):
        u = corners[:, (i + 1) % 3] - corners[:, i]
        v = corners[:, (i + 2) % 3] - corners[:, i]
        cross = np.abs(u[:, 0] * v[:, 1] - u[:, 1] * v[:, 0])
        angles.append(np.degrees(np.arctan2(cross, (u * v).sum(axis=1))))
    assert len(at_border) > 0 and np.min(angles) >= 15.0


def test_the_gil_is_released_while_the_construction_runs():
    ticks = [0]
    stop = threading.Event()

    def count():
        while not stop.is_set():
            ticks[0] += 1

    worker = threading.Thread(target=count)
    worker.start()
    try:
        before = ticks[0]
        pd.triangulate(1.0, n=300000)
        during = ticks[0] - before
    finally:
        stop.set()
        worker.join()
    # With the GIL held, the other thread could not run at all during the call.
    assert during > 1000


# --- bad input --------------------------------------------------------------

@pytest.mark.parametrize("call", [pd.sample, pd.triangulate])
@pytest.mark.parametrize("kwargs", [
    dict(density=-1.0),
    dict(density=float("nan")),
    dict(density=float("inf")),
    dict(density="dense"),
    dict(density=np.array([1.0, 2.0])),
    dict(density=np.array([[1.0, -2.0], [1.0, 1.0]])),
    dict(density=np.array([[1.0, np.nan], [1.0, 1.0]])),
    dict(density=np.zeros((0, 3))),
    dict(density=1.0, region=(0, 0, 0, 1)),
    dict(density=1.0, region=(0, 0, float("inf"), 1)),
    dict(density=1.0, region=(1, 1, 0, 0)),
    dict(density=1.0, n=-5),
    dict(density=1.0, n=2.5),
    dict(density=1.0, scale=float("nan")),
    dict(density=1.0, scale=-1.0),
    dict(density=0.0, n=100),
    dict(density=lambda x, y: -np.ones_like(x)),
    dict(density=lambda x, y: np.where(x > 0.5, np.nan, 1.0), n=1000),
    dict(density=lambda x, y: np.ones(3)),
])
def test_bad_input_raises_value_error(call, kwargs):
    with pytest.raises(ValueError):
        call(**kwargs)


@pytest.mark.parametrize("call", [pd.sample, pd.triangulate])
def test_requests_that_would_not_fit_raise_memory_error(call):
    with pytest.raises(MemoryError):
        call(1.0, n=10**10)
    with pytest.raises(MemoryError):
        call(1e12)


@pytest.mark.parametrize("call", [pd.sample, pd.triangulate])
def test_what_the_density_raises_is_raised_and_the_next_call_works(call):
    def failing(x, y):
        if np.any(x > 0.9):
            raise KeyError("no density there")
        return np.ones_like(x)

    with pytest.raises(KeyError, match="no density there"):
        call(failing, n=1000)
    with pytest.raises(TypeError):
        call(lambda x: x, n=1000)
    assert abs(len(call(1.0, n=1000)[0] if call is pd.triangulate else call(1.0, n=1000)) - 1000) < 50


def test_errors_carry_the_cpp_message():
    with pytest.raises(ValueError, match="density"):
        pd.sample(lambda x, y: np.where(x > 0.5, -2.0, 1.0), n=1000)
    with pytest.raises(ValueError, match="non-negative"):
        pd.triangulate(1.0, n=-1)

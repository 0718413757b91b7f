# Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Randomized inputs, from fixed seeds so that a failure repeats: rasters of
random shapes, number types and layouts, NaNs with random payloads, and
density functions that misbehave on some calls only. Each gives a valid
result or the documented exception, and the next call works."""

import numpy as np
import pytest

import penrose_delaunay as pd

SEEDS = range(12)


def check_mesh(points, simplices, region):
    assert points.dtype == np.float64 and points.ndim == 2 and points.shape[1] == 2
    x0, y0, x1, y1 = region
    assert np.all((points[:, 0] >= x0) & (points[:, 0] <= x1) & (points[:, 1] >= y0) & (points[:, 1] <= y1))
    assert simplices.dtype == np.int32 and simplices.ndim == 2 and simplices.shape[1] == 3
    assert simplices.min() >= 0 and simplices.max() < len(points)
    a, b, c = (points[simplices[:, k]] for k in range(3))
    cross = (b[:, 0] - a[:, 0]) * (c[:, 1] - a[:, 1]) - (b[:, 1] - a[:, 1]) * (c[:, 0] - a[:, 0])
    assert np.all(cross > 0)


def random_raster(rng):
    """A non-negative raster of a random shape, number type and memory layout."""
    shape = (int(rng.integers(1, 40)), int(rng.integers(1, 40)))
    values = rng.random(shape) * 10.0 ** rng.uniform(-3, 3)
    values[rng.random(shape) < 0.3] = 0.0
    values.flat[int(rng.integers(values.size))] = 1.0  # never zero everywhere
    kind = rng.integers(4)
    if kind == 0:
        return values.astype(np.float32)
    if kind == 1:
        return np.round(values * 100).astype(np.int32)
    if kind == 2:
        return np.asfortranarray(values)
    wide = np.zeros((shape[0], 2 * shape[1]))
    wide[:, ::2] = values
    return wide[:, ::2]


@pytest.mark.parametrize("seed", SEEDS)
def test_random_rasters_give_meshes(seed):
    rng = np.random.default_rng(seed)
    raster = random_raster(rng)
    n = int(rng.integers(1, 3000))
    boundary = bool(rng.integers(2))
    points, simplices = pd.triangulate(raster, n=n, boundary=boundary)
    check_mesh(points, simplices, (0, 0, raster.shape[1], raster.shape[0]))
    if not boundary:  # the points of sample(), in another order
        samples = pd.sample(raster, n=n)
        assert np.array_equal(points[np.lexsort(points.T)], samples[np.lexsort(samples.T)])


def random_nan(rng):
    """A NaN with random payload bits, quiet or signalling, of either sign."""
    bits = np.uint64(0x7FF0000000000000) | np.uint64(rng.integers(1, 1 << 52, dtype=np.uint64))
    if rng.integers(2):
        bits |= np.uint64(1 << 63)
    value = np.array([bits], dtype=np.uint64).view(np.float64)[0]
    assert np.isnan(value)
    return value


@pytest.mark.parametrize("seed", SEEDS)
def test_nans_of_any_payload_raise_value_error(seed):
    rng = np.random.default_rng(seed)
    nan = random_nan(rng)
    raster = np.ones((16, 16))
    raster[int(rng.integers(16)), int(rng.integers(16))] = nan
    with pytest.raises(ValueError):
        pd.sample(raster, n=500)
    threshold = rng.uniform(0.2, 0.8)
    for call in (pd.sample, pd.triangulate):
        with pytest.raises(ValueError):
            call(lambda x, y: np.where(x > threshold, nan, 1.0), n=500)


class Flaky:
    """A density 1 + x that misbehaves on its k-th call alone: raises, returns
    a NaN, a negative value or the wrong number of values."""

    def __init__(self, k, how):
        self.calls, self.k, self.how = 0, k, how

    def __call__(self, x, y):
        self.calls += 1
        if self.calls != self.k:
            return 1.0 + x
        if self.how == "raise":
            raise RuntimeError("flaky")
        if self.how == "nan":
            return np.full_like(x, np.nan)
        if self.how == "negative":
            return -np.ones_like(x)
        return np.ones(len(x) + 1)


@pytest.mark.parametrize("seed", SEEDS)
def test_functions_that_misbehave_on_one_call(seed):
    rng = np.random.default_rng(seed)
    how = ["raise", "nan", "negative", "shape"][seed % 4]
    boundary = bool(rng.integers(2))
    # how many calls a good run makes, to pick one of them
    counter = Flaky(0, how)
    pd.triangulate(counter, n=1000, boundary=boundary)
    flaky = Flaky(int(rng.integers(1, counter.calls + 1)), how)
    # A misbehaving call, if the construction needs its values, fails it;
    # one whose values are never needed leaves a valid mesh.
    try:
        points, simplices = pd.triangulate(flaky, n=1000, boundary=boundary)
        check_mesh(points, simplices, (0, 0, 1, 1))
    except RuntimeError as e:
        assert how == "raise" and "flaky" in str(e)
    except ValueError:
        assert how != "raise"
    points, simplices = pd.triangulate(lambda x, y: 1.0 + x, n=1000, boundary=boundary)
    check_mesh(points, simplices, (0, 0, 1, 1))

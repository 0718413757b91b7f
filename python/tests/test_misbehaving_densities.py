# Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Density functions that misbehave where the sampler does not look: on the
border walk alone, or with a NaN that the evaluation table could mistake."""

import time

import numpy as np
import pytest

import penrose_delaunay as pd


@pytest.mark.parametrize("bad", [np.nan, -1.0, 1e12, np.inf])
def test_a_density_bad_only_on_the_border_walk_raises_value_error_at_once(bad):
    # The border is walked one point a call; the sampler asks in blocks.
    border_calls = []

    def density(x, y):
        if len(x) == 1:
            border_calls.append((x[0], y[0]))
            return np.full_like(x, bad)
        return np.ones_like(x)

    start = time.monotonic()
    with pytest.raises(ValueError, match="density on the border"):
        pd.triangulate(density, n=1000, boundary=True)
    assert time.monotonic() - start < 5
    assert 0 < len(border_calls) < 100


def test_a_nan_is_a_nan_whatever_its_payload():
    # the bits that the table gives a value not evaluated yet
    marker = np.array([0x7FF8BEEF00000000], dtype=np.uint64).view(np.float64)[0]
    assert np.isnan(marker)
    for call in (pd.sample, pd.triangulate):
        with pytest.raises(ValueError, match="nan"):
            call(lambda x, y: np.where(x > 0.5, marker, 1.0), n=1000)

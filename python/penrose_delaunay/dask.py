# Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The triangulation of `penrose_delaunay.triangulate()`, window by window on
a dask.distributed cluster, into one zarr store.

Each window of a kx x ky grid over the region is triangulated alone by
`window_triangles()` on a worker (the border's triangles by one more task),
with no message between windows: a window's triangles are exactly those of
the whole triangulation whose circumcentres it holds. The vertices are
numbered window after window, by key within a window: each window ranks the
keys of its samples that the others' triangles use, and a last round of
tasks writes each window's rows into the store. Only those keys and ranks
travel between workers, not the windows' samples or triangles.
"""

import numcodecs
import numpy as np
import zarr
from distributed import Client, LocalCluster, wait

from . import _core

__all__ = ["triangulate"]

_CHUNK_ROWS = 1 << 16  # small enough that few chunks are shared by two windows, whose writes then wait on a lock


def _cuts(lo, hi, k):
    """k windows along [lo, hi]: the same doubles on the driver and the workers."""
    return np.array([lo + (hi - lo) * i / k for i in range(k)] + [hi], dtype=np.float64)


def _owner(cuts, values):
    """The window of each value along one axis: half-open, the last one closed."""
    return np.clip(np.searchsorted(cuts, values, side="right") - 1, 0, len(cuts) - 2)


def _piece(density, region, n, scale, correction, integral, window):
    """A window's part (window None: the border's), with what numbering its vertices needs."""
    points, keys, _, foreign_points, foreign_keys, hull, local = _core.window_triangles(
        density, region=region, n=n, window=window, scale=scale, correction=correction,
        integral=integral, border=window is None, foreign=True)
    return {"points": points, "keys": keys, "local": local,
            "foreign_points": foreign_points, "foreign_keys": foreign_keys, "hull": hull}


def _owners(piece, cx, cy):
    fp = piece["foreign_points"]
    return _owner(cx, fp[:, 0]) + (len(cx) - 1) * _owner(cy, fp[:, 1])


def _summary(piece, cx, cy):
    """Counts, and the keys of the piece's other vertices by the window that holds them."""
    owner, fk = _owners(piece, cx, cy), piece["foreign_keys"]
    wanted = {int(w): fk[owner == w] for w in np.unique(owner)}
    return len(piece["keys"]), len(piece["local"]), wanted, len(piece["hull"])


def _ranks(piece, wanted):
    """The ranks of the keys `wanted` among the window's own, sorted."""
    keys = piece["keys"]
    at = np.searchsorted(keys, wanted)
    if np.any(at >= len(keys)) or np.any(keys[np.minimum(at, len(keys) - 1)] != wanted):
        raise RuntimeError("penrose_delaunay.dask: a vertex is missing from the window that holds it")
    return at


def _write(piece, offset, triangle_offset, numbers_by_owner, cx, cy, store):
    """Writes the piece's rows; `numbers_by_owner` numbers its other vertices, for each window that
    holds some, in the order of _summary()."""
    # one thread a worker, as the cluster was told: Blosc would start more
    numcodecs.blosc.use_threads = False
    keys = piece["keys"]
    owner = _owners(piece, cx, cy)
    foreign_numbers = np.empty(len(owner), dtype=np.int64)
    for o, numbers in numbers_by_owner.items():
        foreign_numbers[owner == o] = numbers
    numbers = np.concatenate([offset + np.arange(len(keys), dtype=np.int64), foreign_numbers])
    tri = piece["local"]
    sync = zarr.ProcessSynchronizer(store + ".sync")
    root = zarr.open_group(store, mode="r+", synchronizer=sync)
    if len(keys):
        root["points"][offset:offset + len(keys)] = piece["points"]
        root["keys"][offset:offset + len(keys)] = keys
    if len(tri):
        root["triangles"][triangle_offset:triangle_offset + len(tri)] = numbers[tri]
    if len(piece["hull"]):
        # the hull's vertices are among the piece's others (the border's piece has no samples of its own)
        fk = piece["foreign_keys"]
        order = np.argsort(fk)
        root["hull"][:] = foreign_numbers[order][np.searchsorted(fk[order], piece["hull"])]
    return len(tri)


def _default_region(density):
    if isinstance(density, np.ndarray) and density.ndim == 2:
        return (0.0, 0.0, float(density.shape[1]), float(density.shape[0]))
    return (0.0, 0.0, 1.0, 1.0)


def triangulate(density, region=None, n=None, windows=(4, 4), store=None, client=None, scale=None,
                correction=True):
    """triangulate(density, region=None, n=None, windows=(4, 4), store=PATH, client=None, scale=None,
                correction=True) -> zarr.Group

    `penrose_delaunay.triangulate()`'s triangulation computed window by window
    on the workers of `client` (a dask.distributed Client; None: a
    LocalCluster on this machine, closed on return), written to the zarr
    store at the path `store`:
    - points: float64 (N, 2), window after window (row-major from the lower
      left), by key within a window;
    - keys: uint64 (N,), the samples' keys (see `window_triangles()`);
    - triangles: int64 (M, 3), indices into points, counter-clockwise;
    - hull: int64, the convex hull's vertices, counter-clockwise.
    The same points and triangles as `triangulate()`, bit for bit, in
    another order; M = 2N - h - 2 is checked. The density is a number, a
    raster or a function, as for `triangulate()` (a function is sent to the
    workers with cloudpickle). Returns the store, opened for reading.
    """
    if store is None:
        raise ValueError("penrose_delaunay.dask.triangulate needs store=PATH, the zarr store to write")
    kx, ky = (int(windows[0]), int(windows[1]))
    if kx < 1 or ky < 1:
        raise ValueError("windows must be (kx, ky), two positive numbers of windows")
    region = tuple(float(v) for v in (region if region is not None else _default_region(density)))
    integral = _core.density_integral(density, region)
    cx, cy = _cuts(region[0], region[2], kx), _cuts(region[1], region[3], ky)
    own_cluster = None
    if client is None:
        own_cluster = LocalCluster(processes=True, threads_per_worker=1, dashboard_address=None)
        client = Client(own_cluster)
    try:
        args = (density, region, n, scale, correction, integral)
        boxes = [(cx[i], cy[j], cx[i + 1], cy[j + 1]) for j in range(ky) for i in range(kx)]
        # the border first, so that it does not run alone at the end
        border = client.submit(_piece, *args, None, pure=False, priority=1)
        pieces = [client.submit(_piece, *args, box, pure=False) for box in boxes] + [border]
        summaries = client.gather([client.submit(_summary, p, cx, cy) for p in pieces])
        counts = np.array([s[0] for s in summaries], dtype=np.int64)
        triangle_counts = np.array([s[1] for s in summaries], dtype=np.int64)
        offsets = np.concatenate([[0], np.cumsum(counts)])
        triangle_offsets = np.concatenate([[0], np.cumsum(triangle_counts)])
        points, triangles, hull = int(offsets[-1]), int(triangle_offsets[-1]), summaries[-1][3]
        if points >= 3 and triangles != 2 * points - hull - 2:
            raise RuntimeError(f"penrose_delaunay.dask: {triangles} triangles for {points} points and a hull of "
                               f"{hull}, not 2N - h - 2")
        root = zarr.open_group(store, mode="w")
        fast = numcodecs.Blosc(cname="lz4", clevel=1, shuffle=numcodecs.Blosc.SHUFFLE)
        root.zeros("points", shape=(points, 2), chunks=(_CHUNK_ROWS, 2), dtype=np.float64, compressor=fast)
        root.zeros("keys", shape=(points,), chunks=(_CHUNK_ROWS,), dtype=np.uint64, compressor=fast)
        root.zeros("triangles", shape=(triangles, 3), chunks=(_CHUNK_ROWS, 3), dtype=np.int64, compressor=fast)
        root.zeros("hull", shape=(hull,), chunks=(max(hull, 1),), dtype=np.int64)
        root.attrs.update({"region": list(region), "windows": [kx, ky], "integral": integral})
        # the other vertices' numbers: each window ranks the keys that the others want of it
        wanted = {}
        for w, summary in enumerate(summaries):
            for o, k in summary[2].items():
                wanted.setdefault(o, []).append((w, k))
        ranks = {o: client.submit(_ranks, pieces[o], np.concatenate([k for _, k in asked]))
                 for o, asked in wanted.items()}
        ranks = dict(zip(ranks.keys(), client.gather(list(ranks.values()))))
        foreign = [dict() for _ in pieces]
        for o, asked in wanted.items():
            start = 0
            for w, k in asked:
                foreign[w][o] = offsets[o] + ranks[o][start:start + len(k)]
                start += len(k)
        writes = [client.submit(_write, piece, int(offsets[w]), int(triangle_offsets[w]), foreign[w], cx, cy, store,
                                pure=False) for w, piece in enumerate(pieces)]
        wait(writes)
        client.gather(writes)
    finally:
        if own_cluster is not None:
            client.close()
            own_cluster.close()
    return zarr.open_group(store, mode="r")

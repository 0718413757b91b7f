# Copyright (c) 2026 The Penrose_Delaunay_triangulation_2 authors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The triangulation of `penrose_delaunay.triangulate()`, window by window on
a dask.distributed cluster, into one zarr store.

Each window of a kx x ky grid over the region is triangulated alone by
`window_triangles()` on a worker (the border's triangles by one more task),
with no message between windows: a window's triangles are exactly those of
the whole triangulation whose circumcentres it holds. A second round of
tasks numbers the vertices (window after window, by key within a window)
and writes each window's rows into the store; only the windows' keys travel
between workers, not their triangles.
"""

import numpy as np
import zarr
from distributed import Client, LocalCluster, wait

from . import _core

__all__ = ["triangulate"]

_CHUNK_ROWS = 1 << 20


def _cuts(lo, hi, k):
    """k windows along [lo, hi]: the same doubles on the driver and the workers."""
    return np.array([lo + (hi - lo) * i / k for i in range(k)] + [hi], dtype=np.float64)


def _owner(cuts, values):
    """The window of each value along one axis: half-open, the last one closed."""
    return np.clip(np.searchsorted(cuts, values, side="right") - 1, 0, len(cuts) - 2)


def _piece(density, region, n, scale, correction, integral, window):
    """A window's part (window None: the border's), with what numbering its vertices needs."""
    points, keys, triangles, foreign_points, foreign_keys, hull = _core.window_triangles(
        density, region=region, n=n, window=window, scale=scale, correction=correction,
        integral=integral, border=window is None, foreign=True)
    return {"points": points, "keys": keys, "triangles": triangles,
            "foreign_points": foreign_points, "foreign_keys": foreign_keys, "hull": hull}


def _summary(piece, cx, cy):
    """Counts, and the windows that own the piece's other vertices."""
    fp = piece["foreign_points"]
    owners = _owner(cx, fp[:, 0]) + (len(cx) - 1) * _owner(cy, fp[:, 1])
    return len(piece["keys"]), len(piece["triangles"]), sorted(set(owners.tolist())), len(piece["hull"])


def _keys(piece):
    return piece["keys"]


def _numbers(keys, offset, wanted):
    """The numbers of the keys `wanted` among a window's sorted `keys`."""
    at = np.searchsorted(keys, wanted)
    if np.any(at >= len(keys)) or np.any(keys[np.minimum(at, len(keys) - 1)] != wanted):
        raise RuntimeError("penrose_delaunay.dask: a vertex is missing from the window that holds it")
    return offset + at


def _write(piece, offset, triangle_offset, owners, cx, cy, store):
    """Numbers the piece's vertices and writes its rows; `owners` maps a window to (keys, offset)."""
    keys = piece["keys"]
    fp, fk = piece["foreign_points"], piece["foreign_keys"]
    owner = _owner(cx, fp[:, 0]) + (len(cx) - 1) * _owner(cy, fp[:, 1])
    foreign_numbers = np.empty(len(fk), dtype=np.int64)
    for w in np.unique(owner):
        sel = owner == w
        owner_keys, owner_offset = owners[int(w)]
        foreign_numbers[sel] = _numbers(owner_keys, owner_offset, fk[sel])
    all_keys = np.concatenate([keys, fk])
    all_numbers = np.concatenate([offset + np.arange(len(keys), dtype=np.int64), foreign_numbers])
    order = np.argsort(all_keys, kind="stable")
    tri = piece["triangles"]
    triangles = all_numbers[order][np.searchsorted(all_keys[order], tri)].astype(np.int64)
    sync = zarr.ProcessSynchronizer(store + ".sync")
    root = zarr.open_group(store, mode="r+", synchronizer=sync)
    if len(keys):
        root["points"][offset:offset + len(keys)] = piece["points"]
        root["keys"][offset:offset + len(keys)] = keys
    if len(tri):
        root["triangles"][triangle_offset:triangle_offset + len(tri)] = triangles
    if len(piece["hull"]):
        root["hull"][:] = all_numbers[order][np.searchsorted(all_keys[order], piece["hull"])]
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
        pieces = [client.submit(_piece, *args, box, pure=False) for box in boxes]
        pieces.append(client.submit(_piece, *args, None, pure=False))
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
        root.zeros("points", shape=(points, 2), chunks=(_CHUNK_ROWS, 2), dtype=np.float64)
        root.zeros("keys", shape=(points,), chunks=(_CHUNK_ROWS,), dtype=np.uint64)
        root.zeros("triangles", shape=(triangles, 3), chunks=(_CHUNK_ROWS, 3), dtype=np.int64)
        root.zeros("hull", shape=(hull,), chunks=(max(hull, 1),), dtype=np.int64)
        root.attrs.update({"region": list(region), "windows": [kx, ky], "integral": integral})
        keys = [client.submit(_keys, p) for p in pieces[:-1]]
        writes = []
        for w, piece in enumerate(pieces):
            owners = {o: (keys[o], int(offsets[o])) for o in summaries[w][2]}
            writes.append(client.submit(_write, piece, int(offsets[w]), int(triangle_offsets[w]), owners,
                                        cx, cy, store, pure=False))
        wait(writes)
        client.gather(writes)
    finally:
        if own_cluster is not None:
            client.close()
            own_cluster.close()
    return zarr.open_group(store, mode="r")

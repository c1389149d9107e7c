"""COPC test inputs: a LAS/LAZ file rewritten as a Cloud Optimized Point Cloud.

The tests need ``.copc.laz`` inputs like the ones PDAL/untwine produce: a LAZ 1.4 file
(point format 6, 7 or 8) whose points are stored node by node in an octree, one LAZ
chunk per node, described by the ``copc`` info VLR and hierarchy EVLR. They are
written with copclib (the COPC library of Rock Robotic, on PyPI, a test-only
dependency), independently of the plugin's own LAS code, from the points of a plain
file in the order laspy reads them, node by node:

* level 0 (the root) holds about one point in 16, level 1 one in 5 of the rest,
  level 2 the others (drawn from a hash of the coordinates, so the order of the source
  does not matter); each point goes to the node of its level whose cube contains it,
  and a node whose parent would be empty gives its first point to the parent;
* the CRS (WKT) is kept; copclib cannot describe extra-bytes dimensions, so the
  source must have none.

:func:`write_copc` returns the point count; :func:`copc_point_order` gives the order
in which the points were stored, so a test can compare a result on the COPC file with
the same result on the plain file point for point.
"""
from __future__ import annotations

import os
import warnings
from typing import Tuple

import numpy as np

#: octree depth of the test files (root + 2 levels)
MAX_DEPTH = 2


def _levels(xyz: np.ndarray) -> np.ndarray:
    """Level of each point from a hash of its centimetre coordinates (order-free)."""
    q = np.round(xyz * 100.0).astype(np.int64)
    h = (q[:, 0] * 73856093) ^ (q[:, 1] * 19349663) ^ (q[:, 2] * 83492791)
    h = np.abs(h) % 16
    return np.where(h == 0, 0, np.where(h % 4 == 0, 1, MAX_DEPTH))


def _cube(xyz: np.ndarray) -> Tuple[np.ndarray, float]:
    mins, maxs = xyz.min(axis=0), xyz.max(axis=0)
    half = float((maxs - mins).max()) / 2.0 + 0.01
    return (mins + maxs) / 2.0, half


def _keys_at(xyz: np.ndarray, level: np.ndarray, center: np.ndarray,
            half: float) -> np.ndarray:
    cells = 2.0 * half / (2.0 ** level)
    ijk = np.floor((xyz - (center - half)) / cells[:, None]).astype(np.int64)
    ijk = np.clip(ijk, 0, (2 ** level)[:, None] - 1)
    return np.column_stack([level, ijk])


def _node_keys(xyz: np.ndarray, center: np.ndarray, half: float) -> np.ndarray:
    """(n, 4) int keys (depth, x, y, z) of each point's node.

    Every node's parent holds points too (a reader walks the hierarchy from the root):
    the first point of a node whose parent would be empty moves up into the parent.
    """
    level = _levels(xyz)
    for depth in range(MAX_DEPTH, 0, -1):
        keys = _keys_at(xyz, level, center, half)
        present = {tuple(k) for k in keys[level == depth - 1]}
        at = np.flatnonzero(level == depth)
        parents = np.column_stack([keys[at, 0] - 1, keys[at, 1:] // 2])
        _, first = np.unique(keys[at], axis=0, return_index=True)
        for i in first:
            if tuple(parents[i]) not in present:
                level[at[i]] = depth - 1
                present.add(tuple(parents[i]))
    return _keys_at(xyz, level, center, half)


def copc_point_order(x, y, z) -> np.ndarray:
    """Indices of the source points in the order :func:`write_copc` stores them."""
    xyz = np.column_stack([x, y, z]).astype(float)
    center, half = _cube(xyz)
    keys = _node_keys(xyz, center, half)
    return np.lexsort(keys[:, ::-1].T) if len(keys) else np.arange(0)


def write_copc(src, dst) -> int:
    """Write the points, scales, offsets, classes and CRS of ``src`` as COPC ``dst``.

    Parameters
    ----------
    src : path-like
        A LAS/LAZ 1.4 file, point format 6, 7 or 8, without extra bytes.
    dst : path-like
        The ``.copc.laz`` file to write.

    Returns
    -------
    int
        Number of points written.
    """
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        import copclib
        import laspy
    las = laspy.read(os.fspath(src))
    fmt = las.header.point_format
    if fmt.id not in (6, 7, 8):
        raise ValueError(f"COPC needs point format 6, 7 or 8; {src} has {fmt.id}")
    if list(fmt.extra_dimension_names):
        raise ValueError("copclib cannot describe extra-bytes dimensions")
    wkt = ""
    for vlr in las.header.vlrs:
        if isinstance(vlr, laspy.vlrs.known.WktCoordinateSystemVlr):
            wkt = vlr.string
    scale = copclib.Vector3(*map(float, las.header.scales))
    offset = copclib.Vector3(*map(float, las.header.offsets))
    cfg = copclib.CopcConfigWriter(fmt.id, scale, offset, wkt)
    xyz = np.column_stack([las.x, las.y, las.z]).astype(float)
    center, half = _cube(xyz)
    info = cfg.copc_info
    info.center_x, info.center_y, info.center_z = (float(v) for v in center)
    info.halfsize = half
    info.spacing = 2.0 * half / 64.0
    cfg.las_header.min = copclib.Vector3(*map(float, xyz.min(axis=0)))
    cfg.las_header.max = copclib.Vector3(*map(float, xyz.max(axis=0)))
    keys = _node_keys(xyz, center, half)
    order = copc_point_order(las.x, las.y, las.z)
    raw = las.points.array
    writer = copclib.FileWriter(os.fspath(dst), cfg)
    try:
        sorted_keys = keys[order]
        starts = np.flatnonzero(np.r_[True, (np.diff(sorted_keys, axis=0) != 0).any(axis=1)])
        stops = np.r_[starts[1:], len(order)]
        for a, b in zip(starts, stops):
            d, i, j, k = (int(v) for v in sorted_keys[a])
            data = np.frombuffer(raw[order[a:b]].tobytes(), dtype=np.int8)
            writer.AddNode(copclib.VoxelKey(d, i, j, k), copclib.VectorChar(data))
    finally:
        writer.Close()
    return int(len(order))

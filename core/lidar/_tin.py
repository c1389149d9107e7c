"""Vectorised TIN helpers of progressive TIN densification (scipy Qhull, private).

After Axelsson, P. (2000). DEM generation from laser scanner data using adaptive
TIN models. IAPRS XXXIII-B4, 110-117.
"""
from __future__ import annotations

import numpy as np
from scipy.spatial import Delaunay, cKDTree

__all__ = ["build", "facet_geometry", "find_simplex", "locate", "distances", "cell_index",
           "lowest_per_cell", "dedupe_xy", "z_order", "cKDTree"]

#: Points per block of the vectorised per-point steps (bounds temporary memory).
CHUNK = 1 << 17


def cell_index(x, y, x0, y0, cell, ncols):
    """Row-major flat cell index of every point on a grid with origin (x0, y0)."""
    col = ((x - x0) // cell).astype(np.int64)
    row = ((y - y0) // cell).astype(np.int64)
    return row * ncols + col


def lowest_per_cell(idx, z):
    """Return the indices of the lowest point of every occupied cell (``idx`` = flat cell ids)."""
    order = np.lexsort((z, idx))
    first = np.ones(order.size, dtype=bool)
    first[1:] = idx[order[1:]] != idx[order[:-1]]
    return order[first]


def dedupe_xy(x, y, z, resolution: float = 0.01):
    """Return the indices of the lowest point of each ``resolution``-sized xy position.

    Delaunay needs distinct xy positions; the other points of a position are
    classified afterwards against the final surface.

    Parameters
    ----------
    x, y, z : ndarray
        Coordinates (m).
    resolution : float
        Positions closer than this share a cell (m).

    Returns
    -------
    ndarray of int
        Indices of the kept points.
    """
    x0, y0 = x.min(), y.min()
    ncols = int((x.max() - x0) // resolution) + 2
    idx = cell_index(x, y, x0, y0, resolution, ncols)
    return lowest_per_cell(idx, z)


def build(xy):
    """Delaunay triangulation of the (m, 2) array ``xy`` (Qhull, built once)."""
    return Delaunay(xy, qhull_options="Qbb Qc Qz Q12")


def facet_geometry(tri, z):
    """Return unit upward normals (k, 3), vertices (k, 3, 3), longest xy edge (k,)."""
    s = tri.simplices
    p = np.column_stack((tri.points[s].reshape(-1, 2), z[s].reshape(-1)))
    p = p.reshape(-1, 3, 3)
    n = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    n /= np.linalg.norm(n, axis=1)[:, None] + 1e-300
    n *= np.where(n[:, 2] < 0, -1.0, 1.0)[:, None]
    e = np.stack([np.hypot(*(p[:, i, :2] - p[:, (i + 1) % 3, :2]).T) for i in range(3)])
    return n, p, e.max(axis=0)


def z_order(x, y):
    """Permutation that puts the points (x, y) on a Z-order (Morton) curve."""
    if x.size == 0:
        return np.zeros(0, dtype=np.intp)
    span = max(float(np.ptp(x)), float(np.ptp(y)), 1e-300)
    code = _spread(((x - x.min()) * (65535.0 / span)).astype(np.uint64))
    code |= _spread(((y - y.min()) * (65535.0 / span)).astype(np.uint64)) << np.uint64(1)
    return np.argsort(code, kind="stable")


def _spread(v):
    """Interleave zero bits into the low 32 bits of ``v`` (uint64), for :func:`z_order`."""
    for shift, mask in ((16, 0x0000FFFF0000FFFF), (8, 0x00FF00FF00FF00FF),
                        (4, 0x0F0F0F0F0F0F0F0F), (2, 0x3333333333333333),
                        (1, 0x5555555555555555)):
        v = (v | (v << np.uint64(shift))) & np.uint64(mask)
    return v


def _clear_inside(tri, q, s, tol):
    """Flag the points ``q`` inside facet ``s`` farther than ``tol`` from its edges.

    Such a point lies in exactly one facet, so any search returns that facet.
    """
    sure = s >= 0
    for a in range(0, s.size, CHUNK):
        b = min(a + CHUNK, s.size)
        v = tri.points[tri.simplices[np.where(sure[a:b], s[a:b], 0)]]      # (m, 3, 2)
        gap = np.full(b - a, np.inf)
        for i in range(3):
            e = v[:, (i + 1) % 3] - v[:, i]
            r = q[a:b] - v[:, i]
            length = np.hypot(e[:, 0], e[:, 1])
            cross = np.abs(e[:, 0] * r[:, 1] - e[:, 1] * r[:, 0])
            gap = np.minimum(gap, np.where(length > 0, cross / np.where(length > 0, length,
                                                                        1.0), 0.0))
        sure[a:b] &= gap > tol
    return sure


def find_simplex(tri, q):
    """``tri.find_simplex(q)``, same answer for every point, in near-linear time.

    scipy walks from the facet found for the previous point, so a point on an edge
    or outside the hull may get a different (equally valid) answer when the points
    come in another order. The points are located in Z-order (short walks); the
    points within ``tol`` of an edge of their facet, or outside, are then located
    again each after its predecessor in the original order (whose facet is unique),
    which reproduces scipy's walk for them exactly.
    """
    s = np.empty(q.shape[0], dtype=np.intc)
    if s.size == 0:
        return s
    order = z_order(q[:, 0], q[:, 1])
    s[order] = tri.find_simplex(q[order])
    tol = 1e-5 * max(float(np.ptp(tri.points, axis=0).max()), 1.0)
    amb = ~_clear_inside(tri, q, s, tol)
    if amb.any():
        start = np.flatnonzero(amb & ~np.r_[False, amb[:-1]])
        stop = np.flatnonzero(amb & ~np.r_[amb[1:], False]) + 1
        first = np.maximum(start - 1, 0)             # the run's sure predecessor
        key = z_order(q[first, 0], q[first, 1])
        key = np.r_[key[start[key] == 0], key[start[key] > 0]]   # no predecessor: first
        length = stop[key] - first[key]
        seq = np.repeat(first[key] - np.r_[0, np.cumsum(length)[:-1]], length) \
            + np.arange(length.sum())
        s[seq] = tri.find_simplex(q[seq])
    return s


def locate(tri, qx, qy):
    """Facet of every query point; points outside the hull get the nearest facet."""
    q = np.column_stack((qx, qy))
    s = find_simplex(tri, q)
    out = s < 0
    if np.any(out):
        centroids = tri.points[tri.simplices].mean(axis=1)
        s[out] = cKDTree(centroids).query(q[out])[1]
    return s


def distances(tri, z, qx, qy, qz, simplex=None, geom=None):
    """Signed perpendicular distance, vertical offset and largest vertex angle.

    Parameters
    ----------
    tri : scipy.spatial.Delaunay
        The TIN.
    z : ndarray
        Heights of its vertices.
    qx, qy, qz : ndarray
        Query points.
    simplex : ndarray of int, optional
        Facet of every query point (located when None).
    geom : tuple, optional
        :func:`facet_geometry` of ``tri`` (computed when None).

    Returns
    -------
    tuple
        ``(d, dz, angle_deg, simplex)``: ``d`` the signed distance to the facet plane
        (positive above), ``dz`` the vertical offset from the facet and ``angle_deg``
        the largest angle between the facet and the lines from the point to the
        facet's three vertices (Axelsson 2000).
    """
    if simplex is None:
        simplex = locate(tri, qx, qy)
    n, p, _ = geom if geom is not None else facet_geometry(tri, z)
    d, dz, angle = (np.empty(simplex.size) for _ in range(3))
    for a in range(0, simplex.size, CHUNK):
        b = min(a + CHUNK, simplex.size)
        nn, v = n[simplex[a:b]], p[simplex[a:b]]
        q = np.column_stack((qx[a:b], qy[a:b], qz[a:b]))
        d[a:b] = np.einsum("ij,ij->i", q - v[:, 0], nn)
        dz[a:b] = d[a:b] / np.maximum(nn[:, 2], 1e-6)
        length = np.linalg.norm(q[:, None, :] - v, axis=2).min(axis=1)
        angle[a:b] = np.degrees(np.arcsin(np.clip(np.abs(d[a:b]) / np.maximum(length, 1e-9),
                                                  0.0, 1.0)))
    return d, dz, angle, simplex

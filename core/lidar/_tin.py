"""Vectorised TIN helpers of progressive TIN densification (scipy Qhull, private).

After Axelsson, P. (2000). DEM generation from laser scanner data using adaptive
TIN models. IAPRS XXXIII-B4, 110-117.
"""
from __future__ import annotations

import numpy as np
from scipy.spatial import Delaunay, cKDTree

__all__ = ["build", "facet_geometry", "locate", "distances", "cell_index",
           "lowest_per_cell", "dedupe_xy", "cKDTree"]


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


def locate(tri, qx, qy):
    """Facet of every query point; points outside the hull get the nearest facet."""
    q = np.column_stack((qx, qy))
    s = tri.find_simplex(q)
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
    nn, v = n[simplex], p[simplex]
    rel = np.column_stack((qx, qy, qz)) - v[:, 0]
    d = np.einsum("ij,ij->i", rel, nn)
    dz = d / np.maximum(nn[:, 2], 1e-6)
    q = np.column_stack((qx, qy, qz))[:, None, :]
    length = np.linalg.norm(q - v, axis=2).min(axis=1)
    ratio = np.clip(np.abs(d) / np.maximum(length, 1e-9), 0.0, 1.0)
    return d, dz, np.degrees(np.arcsin(ratio)), simplex

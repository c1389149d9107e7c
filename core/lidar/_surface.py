"""Hole filling that continues the terrain's slope (numpy/scipy only, private).

A linear TIN or a harmonic (Laplace) fill over a hole never rises above the
hole's border: where an opening wrongly removed the crest of a ridge, an
embankment or a terrace edge, such a fill cuts the crest, and the ground points
there fall below the tolerance band (Type I errors).  Here every hole cell is
the inverse-distance weighted mean of the tangent planes of its nearest border
cells, a Shepard interpolation of first-order (gradient) data that continues the
slopes on both sides of a crest towards each other (Shepard 1968; Franke &
Nielson 1980).  The border gradients are least-squares planes over the valid
cells of a small window, and the slope term is damped beyond ``reach`` metres so
that a large hole (a building) is not extrapolated far.

References
----------
Shepard, D. (1968). A two-dimensional interpolation function for irregularly-spaced
data. Proc. 23rd ACM National Conference, 517-524.

Franke, R. & Nielson, G. (1980). Smooth interpolation of large sets of scattered
data. Int. J. Numer. Methods Eng. 15(11), 1691-1704.
"""
from __future__ import annotations

import numpy as np
from scipy import ndimage
from scipy.spatial import cKDTree

from . import _raster as R  # noqa: N812

__all__ = ["plane_fit", "plane_gradient", "tangent_fill"]

#: Hole cells processed per batch (bounds the k-neighbour arrays' memory).
BATCH = 65_536


def _window_planes(z, valid, radius: int, *, spread: bool = False):
    """Moments and least-squares plane of the valid cells of every (2r+1)² window.

    Returns a dict: ``n`` (valid cells), ``mx, my, mz`` (means of column, row and z
    offset; z relative to ``zc``, the mean of all valid cells), ``det`` (of the
    coordinate covariance), ``gx, gy`` (rise per cell) and, with ``spread``, ``czz``
    (variance of z) and the covariances ``cxz, cyz``.
    """
    r = int(radius)
    off = np.arange(-r, r + 1, dtype=np.float64)
    box = np.ones(2 * r + 1)
    w = valid.astype(np.float64)
    zc = float(np.mean(z[valid])) if valid.any() else 0.0
    zw = np.where(valid, z - zc, 0.0)

    def corr(a, kx, ky):
        a = ndimage.correlate1d(a, kx, axis=1, mode="constant")
        return ndimage.correlate1d(a, ky, axis=0, mode="constant")

    n = corr(w, box, box)
    with np.errstate(invalid="ignore", divide="ignore"):
        mx, my, mz = corr(w, off, box) / n, corr(w, box, off) / n, corr(zw, box, box) / n
        cxx = corr(w, off * off, box) / n - mx * mx
        cyy = corr(w, box, off * off) / n - my * my
        cxy = corr(w, off, off) / n - mx * my
        cxz = corr(zw, off, box) / n - mx * mz
        cyz = corr(zw, box, off) / n - my * mz
        out = dict(n=n, mx=mx, my=my, mz=mz, zc=zc)
        if spread:
            out.update(czz=corr(zw * zw, box, box) / n - mz * mz, cxz=cxz, cyz=cyz)
        det = cxx * cyy - cxy * cxy
        out.update(det=det, gx=(cyy * cxz - cxy * cyz) / det, gy=(cxx * cyz - cxy * cxz) / det)
    return out


def plane_gradient(z, valid, radius: int, cell: float):
    """Gradient of the least-squares plane through the valid cells of every window.

    Parameters
    ----------
    z : ndarray
        Raster (values of invalid cells are ignored).
    valid : ndarray of bool
        Cells that carry data.
    radius : int
        Window half-size in cells (window ``2 * radius + 1`` square).
    cell : float
        Cell size (m).

    Returns
    -------
    tuple of ndarray
        ``(gx, gy)``: rise over run along columns and rows; 0 where the valid
        cells of a window do not span a plane.
    """
    r = int(radius)
    m = _window_planes(z, valid, r)
    gx, gy, det = m["gx"], m["gy"], m["det"]
    full = (r * (r + 1) / 3.0) ** 2                 # det of a complete window
    bad = ~(det > 1e-3 * full) | ~np.isfinite(gx) | ~np.isfinite(gy)
    gx[bad] = 0.0
    gy[bad] = 0.0
    return gx / cell, gy / cell


def plane_fit(z, valid, radius: int):
    """Least-squares plane over the valid cells of every (2r+1)² window, with its fit.

    Parameters
    ----------
    z : ndarray
        Raster (values of invalid cells are ignored).
    valid : ndarray of bool
        Cells that carry data.
    radius : int
        Window half-size in cells.

    Returns
    -------
    tuple of ndarray
        ``(rms, centre, gx, gy)``: RMS residual of the plane, its height at the
        window centre and its rise per cell along columns and rows; rms and centre
        are NaN where fewer than 6 valid cells or a degenerate layout.
    """
    m = _window_planes(z, valid, radius, spread=True)
    gx, gy = m["gx"], m["gy"]
    with np.errstate(invalid="ignore"):
        rms = np.sqrt(np.maximum(m["czz"] - gx * m["cxz"] - gy * m["cyz"], 0.0))
        centre = m["mz"] - gx * m["mx"] - gy * m["my"] + m["zc"]
    bad = ~(m["det"] > 0.1) | (m["n"] < 6)
    rms[bad] = np.nan
    centre[bad] = np.nan
    return rms, centre, gx, gy


def _knn(tree, q, k: int):
    """``k`` nearest neighbours: first within a short radius, then unbounded.

    Most hole cells have their border close by; the bounded search prunes the tree.
    """
    bound = 2.0 * np.sqrt(k)
    d, j = tree.query(q, k=k, distance_upper_bound=bound)
    d, j = d.reshape(len(q), k), j.reshape(len(q), k)
    far = np.isinf(d[:, -1])
    if far.any():
        df, jf = tree.query(q[far], k=k)
        d[far], j[far] = df.reshape(-1, k), jf.reshape(-1, k)
    return d, j


def tangent_fill(z, valid, cell: float, *, radius: int = 3, neighbours: int = 12,
                 reach: float = 10.0, need=None):
    """Fill invalid cells with the weighted tangent planes of the hole borders.

    Parameters
    ----------
    z : ndarray
        Raster (NaN or anything where invalid).
    valid : ndarray of bool
        Cells to keep.
    cell : float
        Cell size (m).
    radius : int
        Half-size of the plane-fit window of the border gradients (cells).
    neighbours : int
        Border cells per hole cell (the nearest ones).
    reach : float
        Distance (m) beyond which a tangent plane's slope term stops growing.
    need : ndarray of bool, optional
        Cells that will be read; invalid cells outside it are left NaN (at low
        density most cells are empty and only those near a point are ever read).

    Returns
    -------
    ndarray
        The filled raster; with fewer than 3 border cells, the linear TIN fill
        (:func:`._raster.fill_tin`).
    """
    if valid.all():
        return z.copy()
    ring = valid & ndimage.binary_dilation(~valid, structure=np.ones((3, 3), bool))
    rr, cc = np.nonzero(ring)
    if rr.size < 3:
        return R.fill_tin(z, valid)
    gx, gy = plane_gradient(z, valid, radius, cell)
    bz, bgx, bgy = z[rr, cc], gx[rr, cc], gy[rr, cc]
    bs = bgx * cc + bgy * rr               # plane term at the border cell itself
    del gx, gy
    tree = cKDTree(np.column_stack((cc, rr)))
    k = min(int(neighbours), rr.size)
    out = np.where(valid, z, np.nan)
    hr, hc = np.nonzero(~valid if need is None else ~valid & need)
    for s in range(0, hr.size, BATCH):
        r, c = hr[s:s + BATCH], hc[s:s + BATCH]
        d, j = _knn(tree, np.column_stack((c, r)), k)
        d *= cell
        np.maximum(d, 1e-9, out=d)
        damp = np.minimum(1.0, reach / d)
        damp *= cell
        gxj, gyj = bgx[j], bgy[j]
        plane = gxj * c[:, None] + gyj * r[:, None]
        plane -= bs[j]
        plane *= damp
        plane += bz[j]
        np.multiply(d, d, out=d)
        np.divide(1.0, d, out=d)                     # weights 1 / d²
        plane *= d
        out[r, c] = plane.sum(axis=1) / d.sum(axis=1)
    return out

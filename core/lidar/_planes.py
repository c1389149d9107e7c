"""Least-squares planes over the valid cells of square windows (numpy/scipy only, private).

The plane of a window is fitted from its moments: the count ``n`` of valid cells, the
sums of their column and row offsets and of the offsets' squares and product (the
moments of the 0/1 weights with the integer kernels), and the sums of ``z``, ``z dx``
and ``z dy`` (and ``z²``). The former are small integers, exact in float64 whatever
the order of summation: they are summed here in integer arithmetic by shifted
additions (a few times cheaper than the float64 correlations), and are the values
``scipy.ndimage.correlate1d`` gives, bit for bit. The sums of ``z`` keep scipy's
separable correlations (rows, then columns), so their rounding is unchanged. The plane
formulas are then evaluated only at the cells asked for (elementwise: the same bits as
on the whole raster).

Used by the hole fill and the continuity growing of :mod:`._surface` (which
re-exports these names).
"""
from __future__ import annotations

import numpy as np
from scipy import ndimage

__all__ = ["gradient_at", "gradient_of", "plane_fit", "plane_fit_where", "plane_gradient"]

#: Rows per band of :func:`gradient_at`, :func:`plane_fit` and :func:`plane_fit_where`
#: (bounds the moment rasters' memory), at least :data:`BAND_CELLS` cells a band.
BAND = 64
#: Cells per band (a narrow raster takes more rows a band: fewer margin rows).
BAND_CELLS = 1 << 17
#: Cells per strip of :func:`gradient_of` (bounds its temporaries).
STRIP = 2048


def _band_rows(cols: int) -> int:
    """Rows per band of a raster ``cols`` wide."""
    return max(int(BAND), int(BAND_CELLS) // max(1, cols))


def _int_type(bound: int):
    """Return the smallest signed integer type holding ``-bound .. bound``."""
    for t in (np.int8, np.int16, np.int32):
        if bound <= np.iinfo(t).max:
            return t
    return np.int64


def _pairs(p, r, n, axis):
    """``(p[i - d], p[i + d])`` for ``d = 1 .. r`` along ``axis`` of ``p`` padded by ``r``."""
    for d in range(1, r + 1):
        lo, hi = slice(r - d, r - d + n), slice(r + d, r + d + n)
        if axis == 1:
            yield d, p[:, lo], p[:, hi]
        else:
            yield d, p[lo], p[hi]


def _int_moments(valid, r: int):
    """Sum the integer moments of the valid cells of every (2r+1)² window.

    Returns ``(n, sx, sy, sxx, syy, sxy)``: the count of valid cells and the sums of
    their column offset, row offset, squares and product (integer rasters; zero
    outside the raster, as scipy's constant mode).
    """
    rows, cols = valid.shape
    s2 = r * (r + 1) * (2 * r + 1) // 3               # sum of d² over -r .. r
    rt = _int_type(max(2 * r + 1, s2))                # bounds of the row sums
    ct = _int_type((2 * r + 1) * s2)                  # and of the window sums
    p = np.zeros((rows, cols + 2 * r), rt)
    p[:, r:r + cols] = valid
    b = p[:, r:r + cols].copy()                       # sum of 1, d, d² along each row
    o, q = np.zeros_like(b), np.zeros_like(b)
    for d, lo, hi in _pairs(p, r, cols, 1):
        s = lo + hi
        b += s
        q += s * rt(d * d)
        o += (hi - lo) * rt(d)
    del p
    pads = []
    for a in (b, o, q):                               # the same along the columns
        c = np.zeros((rows + 2 * r, cols), ct)
        c[r:r + rows] = a
        pads.append(c)
    pb, po, pq = pads
    n, sx, sxx = (c[r:r + rows].copy() for c in pads)
    sy, syy, sxy = np.zeros_like(n), np.zeros_like(n), np.zeros_like(n)
    for (d, lb, hb), (_, lo, ho), (_, lq, hq) in zip(
            _pairs(pb, r, rows, 0), _pairs(po, r, rows, 0), _pairs(pq, r, rows, 0)):
        s = lb + hb
        n += s
        syy += s * ct(d * d)
        sy += (hb - lb) * ct(d)
        sx += lo + ho
        sxy += (ho - lo) * ct(d)
        sxx += lq + hq
    return n, sx, sy, sxx, syy, sxy


def _moments(z, valid, radius: int, *, spread: bool = False):
    """Window sums of every (2r+1)² window (see the module's docstring).

    Returns a dict of rasters: ``n, sx, sy, sxx, syy, sxy`` (integers), ``sz, sxz, syz``
    and, with ``spread``, ``szz`` (float64, scipy's correlation order).
    """
    r = int(radius)
    off = np.arange(-r, r + 1, dtype=np.float64)
    box = np.ones(2 * r + 1)
    zw = np.where(valid, np.asarray(z, np.float64) - 0.0, 0.0)   # float32 rasters: in float64

    def corr(a, kx, ky):
        a = ndimage.correlate1d(a, kx, axis=1, mode="constant")
        return ndimage.correlate1d(a, ky, axis=0, mode="constant")

    m = dict(zip(("n", "sx", "sy", "sxx", "syy", "sxy"), _int_moments(valid, r)))
    rows = ndimage.correlate1d(zw, box, axis=1, mode="constant")
    m["sz"] = ndimage.correlate1d(rows, box, axis=0, mode="constant")
    m["syz"] = ndimage.correlate1d(rows, off, axis=0, mode="constant")
    del rows
    m["sxz"] = corr(zw, off, box)
    if spread:
        m["szz"] = corr(zw * zw, box, box)
    return m


def _planes(m, at=None, *, spread: bool = False):
    """Moments and least-squares plane of the windows of :func:`_moments` at cells ``at``.

    ``at``: flat indices of the cells (None: every cell). Returns a dict: ``n``, ``mx,
    my, mz`` (means of column, row and z offset), ``det`` (of the coordinate
    covariance), ``gx, gy`` (rise per cell) and, with ``spread``, ``czz`` (variance of
    z) and the covariances ``cxz, cyz``. ``zc`` is 0: a reference taken from the raster
    (its mean) would change the rounding with the extent, and a chunk of a catalog
    would differ from the merged cloud in the last bits.
    """
    def get(key):
        a = m[key] if at is None else m[key].ravel()[at]
        return a.astype(np.float64, copy=False)

    n = get("n")
    with np.errstate(invalid="ignore", divide="ignore"):
        mx, my, mz = get("sx") / n, get("sy") / n, get("sz") / n
        cxx = get("sxx") / n - mx * mx
        cyy = get("syy") / n - my * my
        cxy = get("sxy") / n - mx * my
        cxz = get("sxz") / n - mx * mz
        cyz = get("syz") / n - my * mz
        out = dict(n=n, mx=mx, my=my, mz=mz, zc=0.0)
        if spread:
            out.update(czz=get("szz") / n - mz * mz, cxz=cxz, cyz=cyz)
        det = cxx * cyy - cxy * cxy
        out.update(det=det, gx=(cyy * cxz - cxy * cyz) / det, gy=(cxx * cyz - cxy * cxz) / det)
    return out


def _window_planes(z, valid, radius: int, *, spread: bool = False, at=None):
    """:func:`_planes` of :func:`_moments` (every cell, or the flat cells ``at``)."""
    return _planes(_moments(z, valid, radius, spread=spread), at, spread=spread)


def _gradient(p, radius: int, cell: float):
    """``(gx, gy)`` per metre of :func:`_planes` ``p``: 0 where the window spans no plane."""
    r = int(radius)
    gx, gy, det = p["gx"], p["gy"], p["det"]
    full = (r * (r + 1) / 3.0) ** 2                 # det of a complete window
    bad = ~(det > 1e-3 * full) | ~np.isfinite(gx) | ~np.isfinite(gy)
    gx[bad] = 0.0
    gy[bad] = 0.0
    return gx / cell, gy / cell


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
    return _gradient(_window_planes(z, valid, int(radius)), radius, cell)


def gradient_at(z, valid, radius: int, cell: float, rr, cc):
    """:func:`plane_gradient` at the cells ``(rr, cc)`` only, band by band.

    Each band of rows (:func:`_band_rows`) is computed with ``radius`` rows of margin
    on either side (the windows of its cells see exactly the rows they see in the whole
    raster, and a window's sums do not depend on where the raster starts), and the
    plane formulas are evaluated at the cells asked for only, so the values are those
    of :func:`plane_gradient`, bit for bit, without a dozen full-raster moment rasters
    at once.

    Parameters
    ----------
    z, valid, radius, cell
        As for :func:`plane_gradient`.
    rr, cc : ndarray of int
        Rows and columns of the cells wanted, sorted by row (``np.nonzero`` order).

    Returns
    -------
    tuple of ndarray
        ``(gx, gy)`` at those cells.
    """
    r = int(radius)
    rows, cols = z.shape
    band = _band_rows(cols)
    gx = np.empty(rr.size)
    gy = np.empty(rr.size)
    cut = np.searchsorted(rr, np.arange(0, rows + band, band))
    for b0 in range(0, rows, band):
        i0, i1 = cut[b0 // band], cut[b0 // band + 1]
        if i0 == i1:
            continue
        lo, hi = max(0, b0 - r), min(rows, b0 + band + r)
        at = (rr[i0:i1] - lo).astype(np.int64) * cols + cc[i0:i1]
        p = _window_planes(z[lo:hi], valid[lo:hi], r, at=at)
        gx[i0:i1], gy[i0:i1] = _gradient(p, r, cell)
    return gx, gy


def gradient_of(z, valid, radius: int, cell: float, rr, cc):
    """:func:`plane_gradient` at a few cells ``(rr, cc)``, from their own windows only.

    The ``(2r+1)²`` windows of :data:`STRIP` cells are laid side by side in one strip
    ``2r+1`` rows high, cells outside the raster invalid (as the constant mode of the
    whole raster has them): the centre of each window sees exactly its own cells in the
    same order, so the values are :func:`plane_gradient`'s bit for bit, at a cost that
    follows the cells asked for rather than the raster.

    Parameters
    ----------
    z, valid, radius, cell
        As for :func:`plane_gradient`.
    rr, cc : ndarray of int
        Rows and columns of the cells wanted (any order).

    Returns
    -------
    tuple of ndarray
        ``(gx, gy)`` at those cells.
    """
    r = int(radius)
    w = 2 * r + 1
    rows, cols = z.shape
    off = np.arange(-r, r + 1)
    gx, gy = np.empty(rr.size), np.empty(rr.size)
    for s in range(0, rr.size, STRIP):
        wr = rr[s:s + STRIP, None, None] + off[None, :, None]
        wc = cc[s:s + STRIP, None, None] + off[None, None, :]
        ok = (wr >= 0) & (wr < rows) & (wc >= 0) & (wc < cols)
        wr, wc = np.clip(wr, 0, rows - 1), np.clip(wc, 0, cols - 1)
        ok &= valid[wr, wc]
        strip = [a.transpose(1, 0, 2).reshape(w, -1) for a in (np.where(ok, z[wr, wc], 0.0), ok)]
        at = r * strip[0].shape[1] + np.arange(r, strip[0].shape[1], w)   # the centres
        p = _window_planes(strip[0], strip[1], r, at=at)
        gx[s:s + STRIP], gy[s:s + STRIP] = _gradient(p, r, cell)
    return gx, gy


def plane_fit(z, valid, radius: int):
    """Least-squares plane over the valid cells of every (2r+1)² window, with its fit.

    Parameters
    ----------
    z, valid, radius
        As for :func:`plane_gradient`.

    Returns
    -------
    tuple of ndarray
        ``(rms, centre, gx, gy)``: RMS residual of the plane, its height at the
        window centre and its rise per cell along columns and rows; rms and centre
        are NaN where fewer than 6 valid cells or a degenerate layout.
    """
    r = int(radius)
    rows, cols = z.shape
    band = _band_rows(cols)
    out = [np.empty(z.shape) for _ in range(4)]
    for b0 in range(0, rows, band):        # bands with r rows of margin: same values,
        lo, hi = max(0, b0 - r), min(rows, b0 + band + r)   # bounded moment rasters
        n = min(band, rows - b0)
        at = slice((b0 - lo) * cols, (b0 - lo + n) * cols)
        for o, v in zip(out, _plane_fit(z[lo:hi], valid[lo:hi], r, at)):
            o[b0:b0 + n] = v.reshape(n, cols)
    return tuple(out)


def plane_fit_where(z, valid, radius: int, select, where=None):
    """:func:`plane_fit` band by band, keeping the planes only at the cells ``select`` picks.

    Parameters
    ----------
    z, valid, radius
        As for :func:`plane_fit`.
    select : callable
        ``select(rows, at, rms, centre, gx, gy)`` with ``rows`` a slice of the
        raster's rows, ``at`` the flat indices (within those rows, increasing) of the
        cells considered and the planes' values there; returns ``(keep, extra)``: which
        of those cells are kept (bool) and one more value per cell.
    where : ndarray of bool, optional
        The cells that may be kept (the planes are evaluated there only); all if None.

    Returns
    -------
    tuple
        ``(mask, (centre, gx, gy, extra))``: the raster of kept cells and the values at
        them in row-major order (``np.flatnonzero(mask)``), those of :func:`plane_fit`
        bit for bit, without its four full-size rasters.
    """
    r = int(radius)
    rows, cols = z.shape
    band = _band_rows(cols)
    mask = np.zeros(z.shape, bool)
    parts = ([], [], [], [])
    for b0 in range(0, rows, band):
        lo, hi = max(0, b0 - r), min(rows, b0 + band + r)
        n = min(band, rows - b0)
        at = (np.arange(n * cols) if where is None else np.flatnonzero(where[b0:b0 + n]))
        if at.size == 0:
            continue
        rms, centre, gx, gy = _plane_fit(z[lo:hi], valid[lo:hi], r, at + (b0 - lo) * cols)
        keep, extra = select(slice(b0, b0 + n), at, rms, centre, gx, gy)
        mask[b0:b0 + n].ravel()[at[keep]] = True
        for p, v in zip(parts, (centre, gx, gy, extra)):
            p.append(v[keep])
    return mask, tuple(np.concatenate(p) if p else np.empty(0) for p in parts)


def _plane_fit(z, valid, radius: int, at=None):
    """:func:`plane_fit` of one raster at once (at the flat cells ``at``: 1-D values)."""
    m = _window_planes(z, valid, radius, spread=True, at=at)
    gx, gy = m["gx"], m["gy"]
    with np.errstate(invalid="ignore"):
        rms = np.sqrt(np.maximum(m["czz"] - gx * m["cxz"] - gy * m["cyz"], 0.0))
        centre = m["mz"] - gx * m["mx"] - gy * m["my"] + m["zc"]
    bad = ~(m["det"] > 0.1) | (m["n"] < 6)
    rms[bad] = np.nan
    centre[bad] = np.nan
    return rms, centre, gx, gy

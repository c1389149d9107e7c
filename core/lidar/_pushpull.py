"""Push-pull fill of the morphological filters' rasters, band by band (private).

The pyramid of :func:`._raster.fill`: each level sums the weighted values and weights
of 2 x 2 blocks aligned on the lattice, fills the coarser level recursively, and takes
its bilinear upsampling (``ndimage.zoom`` order 1) where a cell has no weight. The
block sums and the upsampling are made in bands of rows, and the result is written
into the weighted values' own buffer: no padded copy and no upsampled raster of the
whole level (at 0.2 pts/m² a level-0 float32 raster is 20 MB per million points). The
values are those of the whole-array form bit for bit (the same sums in the same order;
an order-1 zoom reads one coarse row either side, given as a margin).
"""
from __future__ import annotations

import numpy as np
from scipy import ndimage

__all__ = ["push_pull", "zoom_at"]

#: Coarse rows per band.
ROWS = 64


def push_pull(vw, w, r0=0, c0=0):
    """Fill the cells of no weight of ``vw / w`` by a push-pull pyramid.

    Parameters
    ----------
    vw : ndarray of float
        Weighted values (0 where ``w`` is 0); overwritten by the result, except when the
        pyramid ends at this level (the result is then a new array).
    w : ndarray of bool or number
        Weights.
    r0, c0 : int
        Lattice index of the raster's corner cell (the blocks are aligned on it).

    Returns
    -------
    ndarray
        The filled raster, of ``vw``'s type.
    """
    rows, cols = w.shape
    if rows <= 2 and cols <= 2 or (w.all() if w.dtype == bool else (w > 0).all()):
        out = np.divide(vw, w, out=np.zeros_like(vw), where=w > 0)
        if not (w > 0).all():
            out[w == 0] = vw.sum() / w.sum()
        return out
    pr, pc = r0 % 2, c0 % 2
    cvw, cw = _block_sums(vw, w, pr, pc)
    coarse = push_pull(cvw, cw, r0 // 2, c0 // 2)
    del cvw, cw
    _upsample_into(vw, w, coarse, pr, pc)
    return vw


def _block_sums(vw, w, pr, pc):
    """Return the sums of ``vw`` (float64) and ``w`` over the 2 x 2 lattice blocks."""
    rows, cols = w.shape
    r2, c2 = (rows + pr + 1) // 2, (cols + pc + 1) // 2
    if w.dtype.kind in "biu":
        wt = np.int32 if w.size < 2 ** 31 else np.int64   # a block holds at most w.size
    else:
        wt = np.result_type(w.dtype, np.float64)
    cvw, cw = np.empty((r2, c2)), np.empty((r2, c2), wt)
    for b0 in range(0, r2, ROWS):
        b1 = min(r2, b0 + ROWS)
        lo, hi = max(0, 2 * b0 - pr), min(rows, 2 * b1 - pr)
        top = lo - (2 * b0 - pr)
        for src, dst, kw in ((vw, cvw, {"dtype": np.float64}), (w, cw, {})):
            band = np.zeros((2 * (b1 - b0), 2 * c2), src.dtype)
            band[top:top + hi - lo, pc:pc + cols] = src[lo:hi]
            dst[b0:b1] = band.reshape(b1 - b0, 2, c2, 2).sum(axis=(1, 3), **kw)
    return cvw, cw


def _upsample_into(vw, w, coarse, pr, pc):
    """``vw / w`` where ``w`` > 0, else the order-1 zoom of ``coarse``, in ``vw``."""
    rows, cols = w.shape
    rc = coarse.shape[0]
    dtype = np.result_type(vw.dtype, np.float32)
    for b0 in range(0, rc, ROWS):
        b1 = min(rc, b0 + ROWS)
        f0, f1 = max(0, 2 * b0 - pr), min(rows, 2 * b1 - pr)
        if f0 >= f1:
            continue
        vb, wb = vw[f0:f1], w[f0:f1]
        hole = ~wb if wb.dtype == bool else ~(wb > 0)
        if wb.dtype != bool:                          # boolean weights: vw / 1 is vw
            np.divide(vb, wb, out=vb, where=~hole)
        nh = int(np.count_nonzero(hole))
        if nh * 4 < hole.size:                        # few holes: the zoom at them only
            hr, hc = np.nonzero(hole)
            vb[hr, hc] = zoom_at(coarse, hr + (f0 + pr), hc + pc).astype(dtype)
            continue
        m0, m1 = max(0, b0 - 1), min(rc, b1 + 1)          # a coarse row of margin
        up = ndimage.zoom(coarse[m0:m1], 2, order=1, mode="nearest", grid_mode=True,
                          output=dtype)
        up = up[f0 + pr - 2 * m0:f1 + pr - 2 * m0, pc:pc + cols]
        vb[hole] = up[hole]


def zoom_at(coarse, rr, cc):
    """``ndimage.zoom(coarse, 2, order=1, mode="nearest", grid_mode=True)`` at (rr, cc), float64.

    The same arithmetic as scipy's ``NI_ZoomShift``: an even output index ``2i`` lies at
    ``i - 0.25`` (taps ``i - 1``, ``i``, weights 0.25, 0.75), an odd one at ``i + 0.25``
    (taps ``i``, ``i + 1``, weights 0.75, 0.25), taps clamped at the edges; each term is
    value x row weight x column weight, added to 0.0 rows outer, columns inner - the
    same bits (``tests/core/test_push_pull_bands.py``), computed only where read.
    """
    rows, cols = coarse.shape
    (r0, r1, a0, a1), (c0, c1, b0, b1) = _taps(rr, rows), _taps(cc, cols)
    flat = np.ascontiguousarray(coarse).ravel()
    r0 *= cols
    r1 *= cols
    t = np.zeros(rr.size)
    for r, a in ((r0, a0), (r1, a1)):
        for c, b in ((c0, b0), (c1, b1)):
            v = flat[r + c].astype(np.float64)
            v *= a
            v *= b
            t += v
    return t


def _taps(i, n):
    """Lower and upper taps and weights of :func:`zoom_at` along one axis."""
    odd = (i & 1).astype(bool)
    h = i >> 1
    lo = np.maximum(np.where(odd, h, h - 1), 0)
    hi = np.minimum(np.where(odd, h + 1, h), n - 1)
    w0 = np.where(odd, 0.75, 0.25)
    return lo, hi, w0, 1.0 - w0

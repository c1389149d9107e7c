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

__all__ = ["push_pull"]

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
        m0, m1 = max(0, b0 - 1), min(rc, b1 + 1)          # a coarse row of margin
        up = ndimage.zoom(coarse[m0:m1], 2, order=1, mode="nearest", grid_mode=True,
                          output=dtype)
        up = up[f0 + pr - 2 * m0:f1 + pr - 2 * m0, pc:pc + cols]
        vb, wb = vw[f0:f1], w[f0:f1]
        hole = ~wb if wb.dtype == bool else ~(wb > 0)
        if wb.dtype != bool:                          # boolean weights: vw / 1 is vw
            np.divide(vb, wb, out=vb, where=~hole)
        vb[hole] = up[hole]

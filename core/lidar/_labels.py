"""Per-point labels of the recommended filter against its DTM (step 7; private).

Moved out of :mod:`.recommended` (module size); see its docstring for the method.
"""
from __future__ import annotations

import numpy as np
from scipy import ndimage

from ..classes import GROUND, LOW_NOISE
from ..classes import UNCLASSIFIED as OBJECT
from . import _raster as R  # noqa: N812

__all__ = ["label_points"]


#: Stencil of a central-difference slope cell (:func:`._raster.slope`).
_CROSS = ndimage.generate_binary_structure(2, 1)


def label_points(z, dtm, pc, opt, last=None, base=0.0, moved=None):
    """Per-point classes against the DTM with a slope-dependent tolerance.

    Parameters
    ----------
    z : ndarray
        Heights.
    dtm : ndarray
        Cell-centred DTM raster (heights above ``base``; float32 or float64).
    pc : PointCells
        Per-point cell look-ups.
    opt : RecommendedOptions
        Options.
    last : dict, optional
        The previous call's DTM and classes (filled here when empty): only the points
        reading a cell whose value changed are labelled again
        (:meth:`._raster.PointCells.reading`; a slope cell can change only where the DTM
        changed in it or its 4 neighbours, the central differences' stencil), the others
        keep their class - the same classes as labelling every point. The DTM is kept,
        not copied: the caller must not change it in place afterwards.
    base : float
        Height of the DTM's zero (:func:`._heights.height_base`).
    moved : ndarray of bool, optional
        ``R.changed(last["dtm"], dtm)`` taken by the caller (``last["dtm"]`` may then be
        None: the previous DTM need not be held).

    Returns
    -------
    ndarray of uint8
        2 ground, 1 object, 7 low noise.
    """
    if last:
        moved = R.changed(last["dtm"], dtm) if moved is None else moved
        pts = pc.reading(moved, ndimage.binary_dilation(moved, structure=_CROSS))
        del moved
        cls = last["classes"].copy()
    else:
        pts = None
        cls = np.empty(z.size, dtype=np.uint8)
    n = z.size if pts is None else pts.size
    # the slope raster where there are fewer cells than points to label, else the slope
    # at their cells only (no full-size raster at low density): the same values
    slope = R.slope(dtm, pc.grid.cell) if n >= dtm.size else None
    for s in range(0, n, R.CHUNK):                   # in blocks: same values, in cache
        p = slice(s, s + R.CHUNK) if pts is None else pts[s:s + R.CHUNK]
        dz = pc.bilinear(dtm, p)                     # float64
        np.subtract(z[p] - base if base else z[p], dz, out=dz)   # z[p] may be a view
        tol = pc.nearest(slope, p) if slope is not None else \
            R.slope_at(dtm, pc.grid.cell, pc.idx[p])
        if opt.scaler != 1.0:                        # x 1.0 is exact: skipped
            tol *= opt.scaler
        tol += opt.threshold
        c = np.full(dz.size, OBJECT, dtype=np.uint8)
        np.copyto(c, GROUND, where=np.abs(dz) <= tol)
        np.maximum(tol, opt.low_noise_depth, out=tol)
        np.copyto(c, LOW_NOISE, where=dz < np.negative(tol, out=tol))   # never both
        cls[p] = c
    if last is not None:
        last.update(dtm=dtm, classes=cls)
    return cls

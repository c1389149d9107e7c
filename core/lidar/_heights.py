"""Height rasters of the recommended filter: float32 storage and exact box means (private).

The filter's rasters (cell minima, fills, openings, trend, DTM) hold heights relative
to :func:`height_base` in float32 (:data:`HEIGHT`): within 1,024 m of the base float32
resolves 2**-14 m (0.06 mm), finer than the quantisation of LAS heights (0.1 mm-1 cm),
at half the memory and memory traffic of float64. Sums, planes, gradients and the
per-point differences are taken in float64 from the stored values. Moved out of
:mod:`._raster` (module size).
"""
from __future__ import annotations

import numpy as np

__all__ = ["BAND", "HEIGHT", "OccupiedMinima", "box_mean", "height_base"]

#: Rows per band of :func:`box_mean` and :func:`._raster.slope` (bounds their temporaries).
BAND = 128

#: Storage type of the height rasters (see the module docstring).
HEIGHT = np.float32


def height_base(zmin):
    """Origin of the float32 height rasters (:data:`HEIGHT`): the median of ``zmin``.

    Rounded to a multiple of 1,024 m, so the rasters of most clouds (and of the chunks
    of a catalog, whose medians differ) share it: heights in metres are then stored as
    they are (0 within 512 m of sea level), the rest within about 512 m + the relief of
    it. The median, not the minimum: a blunder 1e6 m low must not move the terrain
    1e6 m from the origin. NaNs (empty cells) are ignored.

    >>> height_base(np.array([np.nan, -1e6, 1650.2, 1700.0]))
    2048.0
    >>> height_base(np.array([12.5, 300.0]))
    0.0
    """
    z = np.asarray(zmin, np.float64)
    z = z[np.isfinite(z)]
    if z.size == 0:
        return 0.0
    return float(1024.0 * np.round(np.median(z) / 1024.0))


#: resolution of :func:`box_mean` (2**-20 of the unit, about 1 micrometre)
_BOX_SCALE = float(2 ** 20)


def box_mean(a, size: int, subtract_from=None):
    """Mean over a ``size`` x ``size`` box, computed exactly at a resolution of 2**-20.

    Edges are repeated (like ``uniform_filter`` with mode "nearest").

    scipy's ``uniform_filter`` keeps a running sum along each line, so the rounding of
    a cell's mean depends on where the line starts: a catalog chunk and the merged cloud
    would differ in the last bits. Here the values are rounded to 2**-20 and summed as
    integers, so each mean depends only on the cells in its box (and is computed in
    bands of :data:`BAND` rows: integer sums do not depend on the band either).

    With ``subtract_from`` (a float raster of the same shape) the means are subtracted
    from it in place, band by band, and it is returned.

    >>> float(box_mean(np.arange(9.0).reshape(3, 3), 3)[1, 1])
    4.0
    """
    size = int(size)
    a = np.asarray(a)
    if a.dtype not in (np.float32, np.float64):
        a = a.astype(np.float64)
    if size <= 1:
        if subtract_from is not None:
            subtract_from -= a
            return subtract_from
        return a.copy()
    rows, cols = a.shape
    h = size // 2
    cidx = np.clip(np.arange(-h, cols + size - h - 1), 0, cols - 1)
    out = np.empty(a.shape, a.dtype) if subtract_from is None else None
    for b0 in range(0, rows, BAND):
        n = min(BAND, rows - b0)
        ridx = np.clip(np.arange(b0 - h, b0 + n + size - h - 1), 0, rows - 1)
        q = np.rint(a[ridx].astype(np.float64) * _BOX_SCALE).astype(np.int64)
        q = _window_sums(q, size, n, axis=0)
        q = _window_sums(np.take(q, cidx, axis=1), size, cols, axis=1)
        if subtract_from is None:
            out[b0:b0 + n] = q / (_BOX_SCALE * size * size)
        else:
            subtract_from[b0:b0 + n] -= q / (_BOX_SCALE * size * size)
    return out if subtract_from is None else subtract_from


def _window_sums(q, size: int, n: int, axis: int):
    """Return the sums of ``size`` consecutive entries of ``q`` along ``axis`` (n of them)."""
    cs = np.cumsum(q, axis=axis)
    shape = list(cs.shape)
    shape[axis] = 1
    cs = np.concatenate((np.zeros(shape, cs.dtype), cs), axis=axis)
    return (np.take(cs, np.arange(size, size + n), axis=axis)
            - np.take(cs, np.arange(n), axis=axis))


class OccupiedMinima:
    """A minimum raster kept as its values at the occupied cells; ``raster()`` remakes it.

    After ``uses`` calls of ``raster()`` the values are dropped (a further call fails).
    """

    def __init__(self, zmin, cells, uses=None):
        self.shape, self.dtype, self.cells, self.uses = zmin.shape, zmin.dtype, cells, uses
        self.values = zmin.ravel()[cells]

    def raster(self):
        """Return the raster again: NaN where empty, the same values bit for bit."""
        out = np.full(self.shape, np.nan, self.dtype)
        out.ravel()[self.cells] = self.values
        if self.uses is not None:
            self.uses -= 1
            if self.uses <= 0:
                self.cells = self.values = None
        return out

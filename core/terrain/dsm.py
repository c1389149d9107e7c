"""Digital surface model (highest return per cell) and normalised DSM / canopy height.

* **DSM**: every cell takes the highest return falling in it (optionally first returns
  only, the usual choice for a canopy surface); cells with no return are nodata, or
  optionally filled from the nearest non-empty cell within ``fill_distance``.
* **nDSM / CHM**: ``DSM − DTM`` on the same grid (Hyyppä et al. 2008; for forests the
  canopy height model). Negative heights (DSM below the DTM: noise, interpolation
  overshoot) can be clamped to 0.

Points are binned in chunks (:func:`accumulate_max`), so the memory needed is the grid
plus one chunk, whatever the size of the point cloud.

References
----------
Hyyppä, J. et al. (2008). Review of methods of small-footprint airborne laser scanning
for extracting forest inventory data in boreal forests. Int. J. Remote Sensing 29(5),
1339–1366.
"""
from __future__ import annotations

from typing import Iterable, Optional, Sequence

import numpy as np

from ..progress import Monitor
from .grid import GridSpec, check_memory


def accumulate_max(grid: GridSpec, out: np.ndarray, x, y, z) -> int:
    """Update ``out`` (grid-shaped, NaN = empty) with the per-cell maximum of ``z``.

    Points outside the grid are ignored. Returns the number of points binned.
    """
    row, col, inside = grid.cell_index(x, y)
    z = np.asarray(z, dtype=np.float64)
    ok = inside & np.isfinite(z)
    if not ok.any():
        return 0
    lin = row[ok] * grid.ncols + col[ok]
    zz = z[ok]
    order = np.lexsort((zz, lin))          # by cell, then by height
    lin, zz = lin[order], zz[order]
    last = np.ones(lin.size, bool)
    last[:-1] = lin[1:] != lin[:-1]        # highest point of each cell
    cells, top = lin[last], zz[last]
    flat = out.reshape(-1)
    flat[cells] = np.fmax(flat[cells], top)
    return int(ok.sum())


def fill_nearest(data: np.ndarray, cell: float, fill_distance: float) -> np.ndarray:
    """Fill NaN cells from the nearest valid cell no farther than ``fill_distance``."""
    if fill_distance <= 0:
        return data
    from scipy import ndimage
    empty = ~np.isfinite(data)
    if not empty.any() or empty.all():
        return data
    dist, (ri, ci) = ndimage.distance_transform_edt(empty, sampling=cell,
                                                    return_indices=True)
    out = data.copy()
    take = empty & (dist <= fill_distance)
    out[take] = data[ri[take], ci[take]]
    return out


def dsm_grid(x, y, z, grid: GridSpec, *, fill_distance: float = 0.0,
             memory_limit: Optional[int] = None) -> np.ndarray:
    """DSM from arrays: highest ``z`` per cell (select first returns before calling)."""
    check_memory(grid, arrays=2, limit=memory_limit)
    out = np.full(grid.shape, np.nan)
    accumulate_max(grid, out, x, y, z)
    return fill_nearest(out, grid.cell, fill_distance)


def dsm_from_chunks(chunks: Iterable, grid: GridSpec, *, n_total: Optional[int] = None,
                    first_only: bool = False, exclude_classes: Sequence[int] = (7, 18),
                    fill_distance: float = 0.0, memory_limit: Optional[int] = None,
                    progress=None, cancel=None) -> np.ndarray:
    """DSM from an iterable of point chunks (e.g. :func:`.las_io.iter_las_chunks`).

    Each chunk is ``(start, PointData)`` or a ``PointData`` with ``x, y, z`` and, as
    needed, ``return_number`` and ``classification`` dimensions.

    Parameters
    ----------
    first_only : bool
        Keep only first returns (``return_number == 1``).
    exclude_classes : sequence of int
        Classes never used (default 7 low noise and 18 high noise).
    fill_distance : float
        Fill empty cells from the nearest non-empty cell within this distance
        (0 = leave them nodata).

    Raises
    ------
    ValueError
        When no point remains after the selection.
    """
    mon = Monitor(progress, cancel)
    check_memory(grid, arrays=2, limit=memory_limit)
    out = np.full(grid.shape, np.nan)
    used = seen = 0
    excl = np.asarray(sorted(set(int(c) for c in exclude_classes)), dtype=np.int64)
    for item in chunks:
        mon.check()
        pd = item[1] if isinstance(item, tuple) else item
        keep = np.ones(len(pd), bool)
        if first_only:
            keep &= np.asarray(pd["return_number"]) == 1
        if excl.size:
            keep &= ~np.isin(np.asarray(pd["classification"]), excl)
        used += accumulate_max(grid, out, pd.x[keep], pd.y[keep], pd.z[keep])
        seen += len(pd)
        if n_total:
            mon.update(0.9 * seen / n_total)
    if used == 0:
        raise ValueError("No point is left for the DSM after the selection (first returns "
                         f"only: {first_only}; excluded classes: {list(excl)}) inside the "
                         "grid extent; relax the selection or check the extent.")
    out = fill_nearest(out, grid.cell, fill_distance)
    mon.update(1.0)
    return out


def ndsm(dsm: np.ndarray, dtm: np.ndarray, *, clamp_negative: bool = True) -> np.ndarray:
    """Normalised DSM (canopy/object height) ``DSM − DTM``; NaN where either is NaN."""
    dsm = np.asarray(dsm, dtype=np.float64)
    dtm = np.asarray(dtm, dtype=np.float64)
    if dsm.shape != dtm.shape:
        raise ValueError(f"DSM {dsm.shape} and DTM {dtm.shape} are not on the same grid; "
                         "compute the DSM on the DTM's grid.")
    out = dsm - dtm
    if clamp_negative:
        out = np.where(out < 0, 0.0, out)
    return out

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

from ..errors import InputError
from ..progress import Monitor
from ..reporting import Report
from .grid import GridSpec, check_memory, pick_per_cell


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
    top = pick_per_cell(lin, zz, "highest")   # highest point of each cell
    cells, top = lin[top], zz[top]
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
        raise InputError("No point is left for the DSM after the selection (first returns "
                         "only: {first}; excluded classes: {excluded}) inside the "
                         "grid extent; relax the selection or check the extent.",
                         first=first_only, excluded=list(excl))
    out = fill_nearest(out, grid.cell, fill_distance)
    mon.update(1.0)
    return out


def ndsm(dsm: np.ndarray, dtm: np.ndarray, *, clamp_negative: bool = True) -> np.ndarray:
    """Normalised DSM (canopy/object height) ``DSM − DTM``; NaN where either is NaN."""
    dsm = np.asarray(dsm, dtype=np.float64)
    dtm = np.asarray(dtm, dtype=np.float64)
    if dsm.shape != dtm.shape:
        raise InputError("DSM {dsm} and DTM {dtm} are not on the same grid; "
                         "compute the DSM on the DTM's grid.", dsm=dsm.shape, dtm=dtm.shape)
    out = dsm - dtm
    if clamp_negative:
        out = np.where(out < 0, 0.0, out)
    return out


def dsm_report(name: str, n_points: int, grid: GridSpec, grid_source: str,
               surface: np.ndarray, ndsm_grid: Optional[np.ndarray] = None, *,
               first_only: bool, classes, excluded, clamp: bool, elapsed: float,
               lang: str = "en", units=None) -> Report:
    """Report content of a DSM (and nDSM) run.

    Parameters
    ----------
    name : str
        Input file name; ``n_points`` its points.
    grid, grid_source : GridSpec, str
        The output grid and where it came from ("DTM grid", "LAS file", …).
    surface, ndsm_grid : ndarray
        The DSM and the nDSM (None when not made).
    first_only, classes, excluded, clamp
        The settings shown.
    """
    from ..reporting import KeyValues, T, translator
    from .dtm import grid_stats
    from .report import grid_report
    method = [("method", T("highest return per cell")),
              ("first returns only", T("yes") if first_only else T("no")),
              ("classes used", ", ".join(map(str, classes)) or T("all")),
              ("excluded classes", ", ".join(map(str, excluded)) or T("none"))]
    inputs = [("input", name), ("points in file", n_points), ("grid source", T(grid_source))]
    if units is not None and not units.metric:
        # the report speaks metres (DEVELOPERS.md, Units): grid and heights converted
        from ..io.units import units_rows
        from .grid import GridSpec
        inputs += units_rows(units)
        grid = GridSpec(xmin=grid.xmin * units.h, ymax=grid.ymax * units.h,
                        cell=grid.cell * units.h, ncols=grid.ncols, nrows=grid.nrows,
                        crs=grid.crs, nodata=grid.nodata)
        surface = surface * units.v
        ndsm_grid = None if ndsm_grid is None else ndsm_grid * units.v
    rep = grid_report(
        "DSM / nDSM report", method_rows=method, input_rows=inputs, grid=grid,
        data=surface, stats=grid_stats(surface), elapsed=elapsed,
        citation="Digital surface model: highest return per cell; nDSM = DSM − DTM.",
        tr=translator(lang))
    if ndsm_grid is not None:
        st = grid_stats(ndsm_grid)
        valid = ndsm_grid[np.isfinite(ndsm_grid)]
        rep.section("nDSM").add(KeyValues([
            ("cells with a value", st["valid_cells"]), ("max height", st["max"], "m"),
            ("cells ≥ 2 m", int((valid >= 2).sum())),
            ("negative heights clamped", T("yes") if clamp else T("no"))]))
    return rep

"""Grid definition shared by every gridding tool (IDW, kriging, DSM).

A :class:`GridSpec` is a north-up raster lattice: upper-left corner ``(xmin, ymax)``,
square cells of side ``cell``, ``nrows × ncols`` cells, a CRS and a nodata value.
Cell ``(r, c)`` covers ``[xmin + c·cell, xmin + (c+1)·cell] × [ymax − (r+1)·cell,
ymax − r·cell]`` and its value belongs to the cell *centre* (pixel-is-area, the
convention of :mod:`.raster_io` and of ``gdal_grid``).

The extent comes from the data (:func:`grid_from_points`), from a given
``(xmin, xmax, ymin, ymax)`` box or from an existing raster (:func:`grid_like`). By
default it is snapped outward to multiples of the cell size so that grids of the
same cell size made from neighbouring tiles line up cell for cell.

:func:`distance_mask` marks cells farther than a maximum distance from any point, so
that no terrain is invented under data gaps (water, buildings removed by the ground
filter, missing strips) unless the caller explicitly asks to fill them.

:func:`check_memory` refuses a grid whose working arrays would not fit in the
available memory, naming the size it would need.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Optional, Sequence, Tuple

import numpy as np

from .. import system as _system
from ..errors import InputError
from ..io.raster import DEFAULT_NODATA

#: Default number of bytes of working memory per cell (float64 value + variance +
#: neighbour bookkeeping for a row block is amortised separately).
BYTES_PER_CELL = 8


@dataclass(frozen=True)
class GridSpec:
    """A north-up grid of square cells.

    Attributes
    ----------
    xmin, ymax : float
        Upper-left corner of the grid (CRS units).
    cell : float
        Cell size (CRS units, > 0).
    ncols, nrows : int
        Grid size in cells.
    crs : str or None
        'EPSG:n' or WKT; carried to the output raster.
    nodata : float
        Value written for cells without an estimate.
    """

    xmin: float
    ymax: float
    cell: float
    ncols: int
    nrows: int
    crs: Optional[str] = None
    nodata: float = DEFAULT_NODATA

    @property
    def xmax(self) -> float:
        """Return the east edge of the grid."""
        return self.xmin + self.ncols * self.cell

    @property
    def ymin(self) -> float:
        """Return the south edge of the grid."""
        return self.ymax - self.nrows * self.cell

    @property
    def shape(self) -> Tuple[int, int]:
        """Return ``(rows, columns)``."""
        return (self.nrows, self.ncols)

    @property
    def size(self) -> int:
        """Return the number of cells."""
        return self.nrows * self.ncols

    @property
    def extent(self) -> Tuple[float, float, float, float]:
        """``(xmin, xmax, ymin, ymax)``."""
        return (self.xmin, self.xmax, self.ymin, self.ymax)

    @property
    def geotransform(self) -> Tuple[float, float, float, float, float, float]:
        """GDAL geotransform ``(xmin, cell, 0, ymax, 0, -cell)``."""
        return (self.xmin, self.cell, 0.0, self.ymax, 0.0, -self.cell)

    def x_centers(self) -> np.ndarray:
        """X of the cell centres of each column (length ``ncols``)."""
        return self.xmin + (np.arange(self.ncols) + 0.5) * self.cell

    def y_centers(self) -> np.ndarray:
        """Y of the cell centres of each row, north to south (length ``nrows``)."""
        return self.ymax - (np.arange(self.nrows) + 0.5) * self.cell

    def block_centers(self, row0: int, row1: int) -> Tuple[np.ndarray, np.ndarray]:
        """Flattened (row-major) x, y of the cell centres of rows ``row0:row1``."""
        xc = self.x_centers()
        yc = self.ymax - (np.arange(row0, row1) + 0.5) * self.cell
        xx = np.broadcast_to(xc[None, :], (row1 - row0, self.ncols)).ravel()
        yy = np.broadcast_to(yc[:, None], (row1 - row0, self.ncols)).ravel()
        return xx, yy

    def cell_index(self, x, y) -> Tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Row, column and an inside-the-grid flag of points ``x, y``.

        Points on the east or south outer edge belong to the last column/row.
        """
        x = np.asarray(x, dtype=np.float64)
        y = np.asarray(y, dtype=np.float64)
        col = np.floor((x - self.xmin) / self.cell).astype(np.int64)
        row = np.floor((self.ymax - y) / self.cell).astype(np.int64)
        col[(col == self.ncols) & (x <= self.xmax)] = self.ncols - 1
        row[(row == self.nrows) & (y >= self.ymin)] = self.nrows - 1
        inside = (col >= 0) & (col < self.ncols) & (row >= 0) & (row < self.nrows)
        return row, col, inside

    def with_crs(self, crs: Optional[str]) -> "GridSpec":
        """Return a copy of the grid with another CRS."""
        return replace(self, crs=crs)

    def describe(self) -> dict:
        """Human-readable facts for reports."""
        return {"cell size": self.cell, "columns": self.ncols, "rows": self.nrows,
                "xmin": self.xmin, "xmax": self.xmax, "ymin": self.ymin,
                "ymax": self.ymax, "nodata": self.nodata}


def check_cell_size(cell: float) -> float:
    """Validate a cell size; returns it as float."""
    try:
        cell = float(cell)
    except (TypeError, ValueError):
        raise InputError("cell_size must be a number, got {value}.", value=repr(cell)) from None
    if not math.isfinite(cell) or cell <= 0:
        raise InputError("cell_size must be a positive number of CRS units (metres), got "
                         "{value}; give e.g. 1.0 for a 1 m grid.", value=cell)
    return cell


def _snap(lo: float, hi: float, cell: float, align: bool) -> Tuple[float, int]:
    """Start and number of cells covering ``[lo, hi]``."""
    if align:
        start = math.floor(lo / cell + 1e-9) * cell
        stop = math.ceil(hi / cell - 1e-9) * cell
    else:
        start = lo
        stop = lo + math.ceil((hi - lo) / cell - 1e-9) * cell
    n = int(round((stop - start) / cell))
    return start, max(n, 1)


#: Largest grid any gridder builds (issue 19): 250 million cells (a 15.8 km square at
#: 1 m, 2 GB per float64 array). Larger grids are refused before anything is allocated,
#: with the cell size that would fit.
MAX_GRID_CELLS = 250_000_000


def check_grid_size(ncols: int, nrows: int, cell: float, *,
                    limit: int = MAX_GRID_CELLS) -> None:
    """Refuse a grid of more than ``limit`` cells (a typo'd cell size, a lying header).

    Raises
    ------
    InputError
        Naming the grid, the limit and a cell size that would fit.
    """
    cells = int(ncols) * int(nrows)
    if cells > limit:
        from ..errors import InputError
        fit = cell * math.sqrt(cells / limit)
        raise InputError(
            "The grid would have {ncols} × {nrows} = {cells} cells (cell size {cell}), more "
            "than the {limit} this toolbox builds at once. Use a cell size of at least "
            "{fit}, a smaller extent, or a tile catalog. No output was written.",
            ncols=f"{int(ncols):,}", nrows=f"{int(nrows):,}", cells=f"{cells:,}",
            cell=f"{cell:g}", limit=f"{limit:,}", fit=f"{math.ceil(fit * 100) / 100:g}")


def grid_from_extent(extent: Sequence[float], cell_size: float, *, crs: Optional[str] = None,
                     nodata: float = DEFAULT_NODATA, align: bool = True) -> GridSpec:
    """Grid covering ``extent = (xmin, xmax, ymin, ymax)``.

    Parameters
    ----------
    extent : 4 floats
        ``(xmin, xmax, ymin, ymax)`` in CRS units.
    cell_size : float
        Cell size (> 0).
    align : bool
        Snap the extent outward to multiples of ``cell_size`` (default). Otherwise the
        grid starts exactly at ``(xmin, ymax)`` and is extended east/south to whole
        cells.
    """
    cell = check_cell_size(cell_size)
    if extent is None or len(extent) != 4:
        raise InputError("extent must be (xmin, xmax, ymin, ymax).")
    xmin, xmax, ymin, ymax = (float(v) for v in extent)
    if not all(math.isfinite(v) for v in (xmin, xmax, ymin, ymax)):
        raise InputError("extent has non-finite values: {extent}.", extent=extent)
    if xmax < xmin or ymax < ymin:
        raise InputError("extent must be (xmin, xmax, ymin, ymax) with xmin <= xmax and "
                         "ymin <= ymax, got {extent}.", extent=tuple(extent))
    x0, ncols = _snap(xmin, xmax, cell, align)
    check_grid_size(ncols, max(int(math.ceil((ymax - ymin) / cell - 1e-9)), 1), cell)
    if align:
        y0, nrows = _snap(ymin, ymax, cell, True)
        ytop = y0 + nrows * cell
    else:
        nrows = max(int(math.ceil((ymax - ymin) / cell - 1e-9)), 1)
        ytop = ymax
    return GridSpec(xmin=x0, ymax=ytop, cell=cell, ncols=ncols, nrows=nrows, crs=crs,
                    nodata=float(nodata))


def grid_from_points(x, y, cell_size: float, *, extent: Optional[Sequence[float]] = None,
                     crs: Optional[str] = None, nodata: float = DEFAULT_NODATA,
                     align: bool = True) -> GridSpec:
    """Grid covering the points (or ``extent`` when given), snapped to the cell size."""
    if extent is None:
        x = np.asarray(x, dtype=np.float64)
        y = np.asarray(y, dtype=np.float64)
        if x.size == 0:
            raise InputError("No points to define the grid extent from.")
        extent = (float(x.min()), float(x.max()), float(y.min()), float(y.max()))
    return grid_from_extent(extent, cell_size, crs=crs, nodata=nodata, align=align)


def grid_like(geotransform: Sequence[float], shape: Tuple[int, int], *,
              crs: Optional[str] = None, nodata: Optional[float] = DEFAULT_NODATA) -> GridSpec:
    """Grid of an existing north-up raster with square cells."""
    gt = tuple(float(v) for v in geotransform)
    if gt[2] != 0 or gt[4] != 0 or gt[1] <= 0 or gt[5] >= 0:
        raise InputError("Only north-up rasters are supported (geotransform {gt}).", gt=gt)
    if abs(gt[1] + gt[5]) > 1e-9 * gt[1]:
        raise InputError("Only square cells are supported; the raster has "
                         "{w} × {h} cells.", w=gt[1], h=-gt[5])
    nodata = DEFAULT_NODATA if nodata is None else float(nodata)
    return GridSpec(xmin=gt[0], ymax=gt[3], cell=gt[1], ncols=int(shape[1]),
                    nrows=int(shape[0]), crs=crs, nodata=nodata)


def available_memory() -> int:
    """Bytes of memory available to this process (:func:`..system.available_memory`)."""
    return _system.available_memory()


def _human(nbytes: float) -> str:
    for unit in ("B", "KiB", "MiB", "GiB", "TiB", "PiB"):
        if abs(nbytes) < 1024 or unit == "PiB":
            return f"{nbytes:.1f} {unit}"
        nbytes /= 1024.0
    return f"{nbytes:.1f} PiB"  # pragma: no cover


def check_memory(grid: GridSpec, *, arrays: int = 2, bytes_per_value: int = 8,
                 limit: Optional[int] = None) -> int:
    """Refuse a grid whose ``arrays`` full-size arrays would not fit in memory.

    Parameters
    ----------
    grid : GridSpec
    arrays : int
        Number of full-grid arrays the caller keeps (e.g. value + variance).
    bytes_per_value : int
        Bytes per cell per array (8 for float64).
    limit : int, optional
        Memory budget in bytes; default: 80 % of the available memory.

    Returns
    -------
    int
        Bytes needed.

    Raises
    ------
    ValueError
        Naming the grid size, the memory needed and the budget, and the fix.
    """
    need = int(grid.size) * int(arrays) * int(bytes_per_value)
    budget = int(0.8 * available_memory()) if limit is None else int(limit)
    if need > budget:
        raise InputError(
            "The grid of {ncols} × {nrows} cells ({cells} cells at {cell} m) would need "
            "{need} of memory but only {budget} is available. Use a larger cell size or a "
            "smaller extent.", ncols=grid.ncols, nrows=grid.nrows, cells=f"{grid.size:,}",
            cell=f"{grid.cell:g}", need=_human(need), budget=_human(budget))
    return need


def mean_spacing(n_points: int, area: float) -> float:
    """Mean point spacing ``sqrt(area / n)`` (CRS units)."""
    if n_points <= 0 or area <= 0:
        return float("nan")
    return math.sqrt(area / n_points)


def default_max_distance(grid: GridSpec, n_points: int, *, factor: float = 5.0) -> float:
    """Automatic gap distance: ``max(factor × mean point spacing, 2 × cell)``.

    The mean spacing is ``sqrt(grid area / n_points)``; with the default factor 5 a
    cell is left empty when its nearest point is farther than five typical point
    spacings (and never closer than two cells).
    """
    area = grid.size * grid.cell * grid.cell
    s = mean_spacing(n_points, area)
    if not math.isfinite(s):
        return 2.0 * grid.cell
    return max(factor * s, 2.0 * grid.cell)


def resolve_max_distance(grid: GridSpec, n_points: int, max_distance: Optional[float],
                         *, fill: bool = False) -> Optional[float]:
    """Return the gap distance a gridder uses.

    ``None`` (no mask) when ``fill``, the :func:`default_max_distance` when
    ``max_distance`` is None, else ``max_distance`` after checking it is positive.
    """
    if fill:
        return None
    if max_distance is None:
        return default_max_distance(grid, n_points)
    if not (max_distance > 0):
        raise InputError("max_distance must be > 0 (m), got {value}; leave it empty "
                         "for the automatic value or fill the gaps instead.",
                         value=max_distance)
    return float(max_distance)


def distance_mask(tree, grid: GridSpec, max_distance: float, *, row0: int = 0,
                  row1: Optional[int] = None, workers: int = -1) -> np.ndarray:
    """Return True for cells of rows ``row0:row1`` with a point within ``max_distance``.

    ``tree`` is a :class:`scipy.spatial.cKDTree` of the points' (x, y).
    """
    row1 = grid.nrows if row1 is None else row1
    xx, yy = grid.block_centers(row0, row1)
    d, _ = tree.query(np.column_stack([xx, yy]), k=1,
                      distance_upper_bound=float(max_distance) * (1 + 1e-12),
                      workers=workers)
    return np.isfinite(d).reshape(row1 - row0, grid.ncols)


def row_blocks(nrows: int, ncols: int, cells_per_block: int):
    """Yield ``(row0, row1)`` blocks of about ``cells_per_block`` cells."""
    rows = max(1, int(cells_per_block) // max(ncols, 1))
    for r0 in range(0, nrows, rows):
        yield r0, min(nrows, r0 + rows)


def pick_per_cell(key, z, which: str = "lowest") -> np.ndarray:
    """Return the index of one point per distinct ``key`` (cell id), chosen by height.

    The one per-cell picker of the toolbox (PTD's seeds and de-duplication, the
    DSM's highest point, the buildings' ground DTM): points are sorted by (cell,
    height) — ties in height keep their input order — and of each cell's run the
    ``"lowest"``, the ``"median"`` (the middle one, ``count // 2`` from the lowest) or
    the ``"highest"`` point is taken.

    Parameters
    ----------
    key : array of int
        Cell id of every point (any integers, e.g. a row-major flat index; -1 is a
        cell like any other).
    z : array of float
        Heights.
    which : {"lowest", "median", "highest"}

    Returns
    -------
    ndarray of int
        Indices into ``key``/``z``, one per occupied cell, in increasing cell order.

    Examples
    --------
    >>> pick_per_cell(np.array([3, 1, 3, 3, 1]), np.array([5., 2., 1., 3., 0.]))
    array([4, 2])
    >>> pick_per_cell(np.array([3, 1, 3, 3, 1]), np.array([5., 2., 1., 3., 0.]), "median")
    array([1, 3])
    """
    key = np.asarray(key)
    if key.size == 0:
        return np.zeros(0, dtype=np.int64)
    order = np.lexsort((z, key))
    k = key[order]
    starts = np.flatnonzero(np.r_[True, k[1:] != k[:-1]])
    if which == "lowest":
        return order[starts]
    ends = np.r_[starts[1:], k.size]
    if which == "highest":
        return order[ends - 1]
    assert which == "median", which           # a programming error, not the user's
    return order[starts + (ends - starts) // 2]

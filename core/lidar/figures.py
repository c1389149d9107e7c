"""Figures of the LiDAR reports: class map, Type I / II error map, LSQ tiles, sweep plot.

Every figure is an inline SVG (:mod:`..reporting.svg`) with a legend, units and, for
maps, a scale bar and a north arrow; its ``figure_id`` is stable (``class-map``,
``error-map``, ``tile-map``, ``sweep-plot``) so tests and readers can find it.

Maps are plan-view rasters of bounded size (at most :data:`MAX_CELLS` cells a side
whatever the cloud): points are binned with one ``np.bincount`` over
``(cell, category)`` and each cell shows its most frequent category (arg-max), so
building a map is O(n) and vectorised.

References
----------
Sithole, G. & Vosselman, G. (2004). Experimental comparison of filter algorithms for
bare-Earth extraction from airborne laser scanning point clouds. ISPRS Journal of
Photogrammetry and Remote Sensing 59(1-2), 85-101 (Type I / Type II errors and their
maps).
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Callable, Optional, Sequence

import numpy as np

from ..reporting import Figure, T, svg

__all__ = ["MAX_CELLS", "PlanGrid", "plan_grid", "majority_grid", "class_map",
           "error_map", "tile_map", "sweep_plot", "CLASS_COLOURS"]

#: Largest side of a map raster, in cells.
MAX_CELLS = 400
EMPTY = -1
#: ASPRS class colours of the class map.
CLASS_COLOURS = {2: "#b07a2a", 1: "#2f8f4e", 7: "#d62728", 0: "#9e9e9e", 18: "#ff7f0e"}
OTHER_CLASS_COLOUR = "#6a3d9a"
EMPTY_COLOUR = "#ffffff"
CLASS_LABELS = {2: "ground", 1: "other (object)", 7: "low noise", 0: "never classified",
                18: "high noise"}
ERROR_COLOURS = ("#d9d9d9", "#d7301f", "#2c7fb8")
ERROR_LABELS = ("correct", "Type I (ground rejected)", "Type II (object accepted)")
STATUS_COLOURS = {1: "#1a9850", 2: "#fdae61", 0: "#bdbdbd", 3: "#d73027", -1: "#74add1"}
MAP_PX = 360


@dataclass(frozen=True)
class PlanGrid:
    """A north-up grid of square cells: column 0 at ``x0``, row 0 at the top ``y1``."""

    x0: float
    y1: float
    cell: float
    nx: int
    ny: int

    @property
    def size(self) -> int:
        """Number of cells."""
        return self.nx * self.ny

    def index(self, x, y) -> np.ndarray:
        """Return the flat cell index (row-major, row 0 north) of every point."""
        col = np.clip(((np.asarray(x) - self.x0) / self.cell).astype(np.int64), 0, self.nx - 1)
        row = np.clip(((self.y1 - np.asarray(y)) / self.cell).astype(np.int64), 0, self.ny - 1)
        return row * self.nx + col


def plan_grid(x, y, *, min_cell: float = 0.0, max_cells: int = MAX_CELLS) -> PlanGrid:
    """Return the grid of a plan-view map of the points ``x, y``.

    Parameters
    ----------
    x, y : array_like
        Point coordinates (metres), at least one point.
    min_cell : float
        Smallest cell side (metres); by default three mean point spacings, so a cell
        holds about nine points.
    max_cells : int
        Largest number of cells on either side (the cell grows to respect it).

    Returns
    -------
    PlanGrid
        The grid covering every point.
    """
    xmin, xmax = float(np.min(x)), float(np.max(x))
    ymin, ymax = float(np.min(y)), float(np.max(y))
    span = max(xmax - xmin, ymax - ymin)
    if not min_cell > 0:
        area = max((xmax - xmin) * (ymax - ymin), span, 1e-9)
        min_cell = 3.0 * math.sqrt(area / max(np.size(x), 1))
    cell = max(min_cell, span / max(max_cells - 1, 1), 1e-6)
    nx = min(max_cells, int((xmax - xmin) / cell + 1e-9) + 1)
    ny = min(max_cells, int((ymax - ymin) / cell + 1e-9) + 1)
    return PlanGrid(xmin, ymin + ny * cell, cell, nx, ny)


def majority_grid(grid: PlanGrid, x, y, codes, ncodes: int) -> np.ndarray:
    """Return the most frequent code of every cell (``-1`` where no point falls).

    One ``np.bincount`` over ``cell * ncodes + code`` and an arg-max per cell; ties go
    to the smaller code.

    Parameters
    ----------
    grid : PlanGrid
        The cells.
    x, y : array_like
        Point coordinates.
    codes : array_like of int
        Category of every point, ``0 <= code < ncodes``.
    ncodes : int
        Number of categories.

    Returns
    -------
    ndarray of int, shape (ny, nx)
        Majority code per cell, row 0 north.
    """
    key = grid.index(x, y) * ncodes + np.asarray(codes, dtype=np.int64)
    counts = np.bincount(key, minlength=grid.size * ncodes).reshape(grid.size, ncodes)
    out = counts.argmax(axis=1)
    out[counts.sum(axis=1) == 0] = EMPTY
    return out.reshape(grid.ny, grid.nx)


def _map_svg(codes: np.ndarray, colours: Sequence[str], grid: PlanGrid, entries,
             title: str, legend_title: str) -> str:
    """Draw a categorical map with legend, scale bar (m) and north arrow."""
    scale = MAP_PX / max(grid.nx, grid.ny)
    w, h = grid.nx * scale, grid.ny * scale
    legend_w = 12 + 7 * max(len(str(label)) for _, label in entries)
    parts = [svg.category_image(10, 10, w, h, codes, colours, empty=EMPTY_COLOUR),
             svg.scale_bar(20, h + 22, min(w / 2, 150), grid.cell / scale, unit="m"),
             svg.north_arrow(w + 25, 12),
             svg.legend(w + 45, 24, entries, title=legend_title)]
    return svg.figure(int(w + 60 + legend_w), int(max(h + 35, 30 + 14 * len(entries))),
                      _ltr(parts), title=title)


def _ltr(parts) -> list:
    """Lay the figure out left to right in RTL pages too (the text is still shaped)."""
    return ['<g direction="ltr">', *parts, "</g>"]


def _cell_caption(grid: PlanGrid):
    return T("Plan view, north up; cells of {cell} m, each showing the most frequent value "
             "of its points; white: no point.", cell=round(grid.cell, 2))


def _class_label(value: int, tr) -> str:
    return tr(CLASS_LABELS.get(value, "other class"))


def class_map(x, y, classes, tr: Callable[[str], str]) -> Figure:
    """Return the class map: each cell coloured by its most frequent ASPRS class.

    Parameters
    ----------
    x, y : array_like
        Point coordinates (metres).
    classes : array_like of int
        ASPRS class of every point.
    tr : callable
        Translator of the text drawn in the figure.

    Returns
    -------
    Figure
        ``figure_id`` ``class-map``.
    """
    values, codes = np.unique(np.asarray(classes), return_inverse=True)
    grid = plan_grid(x, y)
    cells = majority_grid(grid, x, y, codes, values.size)
    colours = [CLASS_COLOURS.get(int(v), OTHER_CLASS_COLOUR) for v in values]
    shown = np.unique(cells[cells >= 0])
    entries = [(colours[i], f"{int(values[i])} {_class_label(int(values[i]), tr)}")
               for i in shown] + [(EMPTY_COLOUR, tr("no point"))]
    body = _map_svg(cells, colours, grid, entries, tr("Class map"), tr("ASPRS class"))
    return Figure(body, _cell_caption(grid), figure_id="class-map")


def error_map(x, y, error_codes, tr: Callable[[str], str]) -> Figure:
    """Return the Type I / Type II error map of a filter against reference labels.

    A cell with at least one error shows its more frequent error type (Type I: reference
    ground rejected; Type II: object accepted as ground); a cell without error is grey.

    Parameters
    ----------
    x, y : array_like
        Point coordinates (metres).
    error_codes : array_like of int
        Per point 0 correct, 1 Type I, 2 Type II (:func:`~.accuracy.error_codes`).
    tr : callable
        Translator of the text drawn in the figure.

    Returns
    -------
    Figure
        ``figure_id`` ``error-map``.
    """
    codes = np.asarray(error_codes, dtype=np.int64)
    grid = plan_grid(x, y)
    idx = grid.index(x, y)
    counts = np.bincount(idx * 3 + codes, minlength=grid.size * 3).reshape(grid.size, 3)
    cells = np.where(counts[:, 2] > counts[:, 1], 2, 1)
    cells[counts[:, 1:].sum(axis=1) == 0] = 0
    cells[counts.sum(axis=1) == 0] = EMPTY
    entries = [(c, tr(label)) for c, label in zip(ERROR_COLOURS, ERROR_LABELS)]
    entries.append((EMPTY_COLOUR, tr("no point")))
    body = _map_svg(cells.reshape(grid.ny, grid.nx), ERROR_COLOURS, grid, entries,
                    tr("Error map"), tr("Filter error"))
    caption = T("Plan view, north up; cells of {cell} m: red where rejected ground "
                "(Type I) dominates the errors of the cell, blue where accepted objects "
                "(Type II) do, grey without error.", cell=round(grid.cell, 2))
    return Figure(body, caption, figure_id="error-map")


def tile_map(grid, status, tr: Callable[[str], str], names: dict) -> Figure:
    """Return the LSQ tile-status map (one cell per tile, or coarser for huge grids).

    Parameters
    ----------
    grid : TileGrid
        The LSQ tiles (:class:`~.lsq.TileGrid`).
    status : array_like of int
        Status of every tile (:data:`~.lsq.STATUS_NAMES`).
    tr : callable
        Translator of the text drawn in the figure.
    names : dict
        Status code -> English name.

    Returns
    -------
    Figure
        ``figure_id`` ``tile-map``.
    """
    codes_all = sorted(names)
    status = np.asarray(status, dtype=np.int64)
    code = np.searchsorted(codes_all, status)
    centres = grid.centres
    plan = plan_grid(centres[:, 0], centres[:, 1], min_cell=grid.size)
    plan = PlanGrid(plan.x0 - grid.size / 2, plan.y1 - grid.size / 2, plan.cell,
                    plan.nx, plan.ny)
    cells = majority_grid(plan, centres[:, 0], centres[:, 1], code, len(codes_all))
    colours = [STATUS_COLOURS.get(c, OTHER_CLASS_COLOUR) for c in codes_all]
    present = np.unique(code)
    entries = [(colours[i], tr(names[codes_all[i]])) for i in present]
    entries.append((EMPTY_COLOUR, tr("no point")))
    body = _map_svg(cells, colours, plan, entries, tr("Tile map"), tr("Tile status"))
    caption = T("Plan view, north up; one cell per tile of {size} m (or the most frequent "
                "status of a block of tiles when there are many).", size=grid.size)
    return Figure(body, caption, figure_id="tile-map")


def sweep_plot(rows, best, tr: Callable[[str], str]) -> Optional[Figure]:
    """Return Type I, Type II, total error and kappa against the slope threshold.

    Only the rows with the best setting's radius and height tolerance are drawn (one
    line per measure); the best threshold is marked with a dashed line.

    Parameters
    ----------
    rows : sequence of SweepRow
        The sweep (:class:`~.slope.SweepRow`).
    best : SweepRow
        The chosen setting.
    tr : callable
        Translator of the text drawn in the figure.

    Returns
    -------
    Figure or None
        ``figure_id`` ``sweep-plot``; None without any finite value.
    """
    sel = sorted((r for r in rows if r.radius == best.radius
                  and r.height_tolerance == best.height_tolerance), key=lambda r: r.slope)
    theta = np.array([r.slope for r in sel], float)
    series = [("#d7301f", "Type I error", [r.type1 for r in sel]),
              ("#2c7fb8", "Type II error", [r.type2 for r in sel]),
              ("#252525", "Total error", [r.total for r in sel]),
              ("#31a354", "Kappa", [r.kappa for r in sel])]
    values = np.array([s[2] for s in series], float)
    if not np.isfinite(values).any():
        return None
    frame, px, py = svg.axes((60, 15, 380, 230), (theta.min(), theta.max()),
                             (min(0.0, np.nanmin(values)), np.nanmax(values)),
                             xlabel=tr("Slope threshold θ (degrees)"),
                             ylabel=tr("Percent (%)"))
    parts = [frame, svg.vline(float(px(best.slope)), 15, 245)]
    for colour, _, vals in series:
        parts.append(svg.polyline(px(theta), py(np.array(vals, float)), colour))
    entries = [(c, tr(label) + " (%)") for c, label, _ in series]
    entries.append(("#777777", tr("best threshold")))
    parts.append(svg.legend(455, 24, entries, shape="line"))
    body = svg.figure(660, 290, _ltr(parts), title=tr("Errors against the slope threshold"))
    caption = T("Radius {r} m, height tolerance {h} m; the dashed line marks the chosen "
                "threshold.", r=best.radius, h=best.height_tolerance)
    return Figure(body, caption, figure_id="sweep-plot")

"""DTM methods as algorithm objects, one registry, and the one runner from a cloud to a DTM.

As for the ground filters (:mod:`..lidar.filters`), each interpolation method is a
small object written once — :class:`IdwMethod` (Shepard 1968, ``gdal_grid -a
invdistnn``), :class:`KrigingMethod` (Matheron 1963; Cressie 1993) and
:class:`TinMethod` (Delaunay 1934, ``gdal_grid -a linear``) — registered in
:data:`DTM_METHODS` and run the same by the single-file algorithms (``idwdtm``,
``krigingdtm``, ``tindtm``), the one-step ``lidartodtm`` and the catalog chunks.

:func:`read_ground` reads the points (lengths in metres, :mod:`..io.units`) and lays
the grid; :func:`make_dtm` interpolates and refuses an empty result;
:func:`write_dtm` writes the rasters in the data's units; :func:`dtm_report` builds the
report content (rendered by :mod:`..reporting` only). The Processing algorithms map
their parameters onto these calls and nothing else.

Examples
--------
>>> import numpy as np
>>> from geomatics_toolbox.core.terrain.grid import grid_from_extent
>>> x, y = np.array([0.5, 1.5, 0.5, 1.5]), np.array([0.5, 0.5, 1.5, 1.5])
>>> grid = grid_from_extent((0.0, 2.0, 0.0, 2.0), 1.0)
>>> method = dtm_method("idw", IdwOptions(neighbours=4))
>>> out = method.interpolate(x, y, x + y, grid, fill=True)
>>> np.round(out.z, 3).tolist()
[[2.0, 3.0], [1.0, 2.0]]
"""
from __future__ import annotations

import os
import time
from dataclasses import dataclass, field, replace
from typing import Any, Callable, Dict, Optional, Sequence

import numpy as np

from ..coords import check_projected
from ..errors import InputError
from ..io.points import ClassPoints, read_class_points, write_grid
from ..io.units import units_rows
from ..progress import Monitor
from ..reporting import Report, T, translator
from . import report as terrain_report
from .grid import GridSpec, grid_from_points
from .idw import DEFAULT_POWER

__all__ = ["DtmOutcome", "DtmMethod", "IdwOptions", "IdwMethod", "KrigingOptions",
           "KrigingMethod", "TinOptions", "TinMethod", "DtmSpec", "DTM_METHODS",
           "register_dtm_method", "dtm_method", "DtmRun", "read_ground", "make_dtm",
           "write_dtm", "dtm_report", "grid_stats", "check_dtm_input",
           "MIN_DISTINCT_POINTS", "distinct_positions"]


@dataclass
class DtmOutcome:
    """What a DTM method returns.

    Attributes
    ----------
    z : ndarray
        Heights on the grid (NaN = nodata).
    extras : dict of str to ndarray
        Further rasters by name (kriging: ``variance``, ``std``).
    details : object
        The method's own result (:class:`~.kriging.KrigingResult`,
        :class:`~.tin.TinResult`) for the report.
    n_points : int
        Points used.
    """

    z: np.ndarray
    extras: Dict[str, np.ndarray] = field(default_factory=dict)
    details: Any = None
    n_points: int = 0


class DtmMethod:
    """Base of the DTM method objects: ``interpolate`` plus report facts.

    Subclasses set :attr:`key`, :attr:`title`, :attr:`citation`, :attr:`band_name`,
    keep their options dataclass in :attr:`options` and implement :meth:`interpolate`.
    """

    key = "dtm"
    title = "DTM report"
    citation = ""
    band_name = "DTM"
    options_type: Any = None

    def __init__(self, options=None):
        self.options = options if options is not None else (
            self.options_type() if self.options_type else None)

    def interpolate(self, x, y, z, grid: GridSpec, *, max_distance: Optional[float] = None,
                    fill: bool = False, workers: int = -1,
                    monitor: Optional[Monitor] = None) -> DtmOutcome:
        """Interpolate points (metres) onto ``grid``."""
        raise NotImplementedError

    def within(self, x, y) -> DtmMethod:
        """Return the method for only the points ``x, y`` (default: unchanged).

        E.g. a catalog chunk's ground within reach: neighbourhoods cut to the points there.
        """
        return self

    def metadata(self, outcome: DtmOutcome) -> Dict[str, str]:
        """GeoTIFF metadata of the DTM (``method`` and more)."""
        return {"method": self.key}

    def method_rows(self, outcome: DtmOutcome, *, fill: bool,
                    max_distance: Optional[float]) -> list:
        """Report rows of the method's settings."""
        return []

    def input_rows(self, outcome: DtmOutcome) -> list:
        """Extra report rows of the input (default: none)."""
        return []

    def report_sections(self, report: Report, outcome: DtmOutcome, tr) -> None:
        """Append method-specific report sections (default: none)."""


def _gaps(fill: bool, max_distance) -> tuple:
    return ("gaps", T("filled") if fill else (max_distance or T("automatic")),
            "m" if max_distance and not fill else "")


# ============================================================================ IDW
@dataclass(frozen=True)
class IdwOptions:
    """Options of :class:`IdwMethod` (see :func:`~.idw.idw_grid`).

    ``tie_order='gdal'`` orders equidistant neighbours like ``gdal_grid``'s quadtree
    (built over the whole point set); ``'xy'`` orders them by their coordinates,
    which does not depend on the other points: the catalog chunks use it, so a tile
    with its buffer gives the cells of the merged cloud exactly.
    """

    power: float = DEFAULT_POWER
    neighbours: int = 12
    radius: Optional[float] = None
    min_points: int = 0
    tie_order: str = "gdal"

    def __post_init__(self):
        """Refuse an invalid option (the InputError templates of :mod:`.idw`)."""
        from .idw import TIE_ORDERS
        if not self.power > 0:
            raise InputError("The IDW power (POWER) must be > 0, got {value}: give 2 "
                             "(GDAL's default) or 3.", value=self.power)
        if int(self.neighbours) < 0:
            raise InputError("max_points must be >= 0 (0 = every point within the radius), "
                             "got {value}.", value=self.neighbours)
        if self.radius is not None and not self.radius > 0:
            raise InputError("radius must be > 0 (or None for no radius), got {value}.",
                             value=self.radius)
        if int(self.min_points) < 0:
            raise InputError("min_points must be >= 0, got {value}.", value=self.min_points)
        if self.tie_order not in TIE_ORDERS:
            raise InputError("tie_order must be one of {choices}, got {value}.",
                             choices=", ".join(TIE_ORDERS), value=self.tie_order)


class IdwMethod(DtmMethod):
    """Inverse distance weighting over the nearest neighbours (Shepard 1968)."""

    key = "idw"
    title = "IDW DTM report"
    citation = ("Shepard (1968) inverse distance weighting, semantics of gdal_grid -a "
                "invdistnn.")
    band_name = "DTM (IDW)"
    options_type = IdwOptions

    def interpolate(self, x, y, z, grid, *, max_distance=None, fill=False, workers=-1,
                    monitor=None) -> DtmOutcome:
        """Run :func:`~.idw.idw_grid`."""
        from .idw import idw_grid
        o, mon = self.options, monitor or Monitor()
        zz = idw_grid(x, y, z, grid, power=o.power, max_points=o.neighbours,
                      radius=o.radius, min_points=o.min_points, max_distance=max_distance,
                      fill=fill, workers=workers, tie_order=o.tie_order,
                      progress=mon.update, cancel=mon.cancelled)
        return DtmOutcome(zz, n_points=int(np.size(x)))

    def within(self, x, y):
        """Fewer points than NEIGHBOURS: all of them.

        As ``gdal_grid invdistnn`` uses the neighbours it finds.
        """
        n, o = int(np.size(x)), self.options
        if not 0 < n < o.neighbours:
            return self
        return IdwMethod(replace(o, neighbours=n, min_points=min(o.min_points, n)))

    def metadata(self, outcome):
        """``IDW p=… k=… radius=… min_points=…``."""
        o = self.options
        return {"method": f"IDW p={o.power:g} k={o.neighbours} radius={o.radius or 0:g} "
                          f"min_points={o.min_points}"}

    def method_rows(self, outcome, *, fill, max_distance):
        """Power, neighbours, radius, minimum points, gaps."""
        o = self.options
        return [("method", T("inverse distance weighting (Shepard 1968)")),
                ("power", o.power), ("neighbours", o.neighbours),
                ("search radius", o.radius if o.radius else T("unlimited"),
                 "m" if o.radius else ""),
                ("minimum points", o.min_points), _gaps(fill, max_distance)]


# ============================================================================ kriging
@dataclass(frozen=True)
class KrigingOptions:
    """Options of :class:`KrigingMethod` (see :func:`~.kriging.kriging_grid`)."""

    model: str = "spherical"
    variogram: Any = None
    drift: str = "none"
    neighbours: int = 16
    fit_points: int = 3000
    nlags: int = 12
    max_lag: Any = "auto"
    cv_points: int = 0
    seed: int = 0

    def __post_init__(self):
        """Refuse an invalid option (the InputError templates of :mod:`.kriging`)."""
        from .kriging import DRIFTS, MODELS
        if self.model not in MODELS:
            raise InputError("variogram model must be one of {choices}; got {model}.",
                             choices=", ".join(MODELS), model=repr(self.model))
        if self.drift not in DRIFTS:
            raise InputError("drift must be one of {choices}; got {drift}.",
                             choices=", ".join(DRIFTS), drift=repr(self.drift))
        if int(self.fit_points) < 10:
            raise InputError("fit_points must be at least 10, got {value}.",
                             value=self.fit_points)
        if int(self.nlags) < 2:
            raise InputError("nlags must be at least 2, got {value}.", value=self.nlags)


class KrigingMethod(DtmMethod):
    """Local-neighbourhood ordinary or universal kriging with a variance raster."""

    key = "kriging"
    title = "Kriging DTM report"
    citation = ("Local-neighbourhood kriging with a variogram fitted by PyKrige's "
                "estimator on a random subsample; Matheron (1963), Cressie (1993).")
    band_name = "DTM (kriging)"
    options_type = KrigingOptions

    @property
    def kind(self) -> str:
        """``ordinary`` or ``universal (linear drift)``."""
        return "ordinary" if self.options.drift == "none" else "universal (linear drift)"

    def interpolate(self, x, y, z, grid, *, max_distance=None, fill=False, workers=-1,
                    monitor=None) -> DtmOutcome:
        """Run :func:`~.kriging.kriging_grid`."""
        from .kriging import kriging_grid
        o, mon = self.options, monitor or Monitor()
        res = kriging_grid(x, y, z, grid, model=o.model, variogram=o.variogram,
                           drift=o.drift, n_closest=o.neighbours, fit_points=o.fit_points,
                           nlags=o.nlags, max_lag=o.max_lag, max_distance=max_distance,
                           fill=fill, cv_points=o.cv_points, seed=o.seed, workers=workers,
                           progress=mon.update, cancel=mon.cancelled)
        return DtmOutcome(res.z, {"variance": res.variance, "std": res.std}, res,
                          res.n_points)

    def within(self, x, y):
        """Fewer distinct positions than NEIGHBOURS: all of them."""
        k = self.options.neighbours
        n = distinct_positions(x, y, k) if np.size(x) else k
        return self if n >= k else KrigingMethod(replace(self.options, neighbours=n))

    def metadata(self, outcome):
        """Kind, model, neighbours and the variogram."""
        from .kriging import describe_variogram
        v = outcome.details.variogram
        return {"method": f"{self.kind} kriging, {self.options.model} variogram, "
                          f"{self.options.neighbours} neighbours",
                "variogram": "; ".join(f"{a}={b}" for a, b in describe_variogram(v))}

    def method_rows(self, outcome, *, fill, max_distance):
        """Kind, variogram model, neighbours, gaps."""
        res = outcome.details
        return [("method", T(self.kind + " kriging")), ("variogram model", res.variogram.model),
                ("neighbours per cell", res.n_closest),
                ("gaps", T("filled") if fill else res.max_distance, "" if fill else "m")]

    def input_rows(self, outcome):
        """Duplicate positions merged."""
        return [("duplicate x,y merged", outcome.details.n_merged)]

    def report_sections(self, report, outcome, tr):
        """Variogram, variance and cross-validation."""
        terrain_report.kriging_sections(report, outcome.details, tr=tr)


# ============================================================================ TIN
@dataclass(frozen=True)
class TinOptions:
    """Options of :class:`TinMethod`: the longest triangle edge kept (None = auto)."""

    max_edge: Optional[float] = None

    def __post_init__(self):
        """Refuse a non-positive edge limit (None = automatic)."""
        if self.max_edge is not None and not self.max_edge > 0:
            raise InputError("max_edge must be > 0 m (or None for the automatic limit), "
                             "got {value}.", value=self.max_edge)


class TinMethod(DtmMethod):
    """Linear interpolation in the Delaunay triangles (``gdal_grid -a linear``).

    The gap distance of a catalog (``max_distance``) is its edge limit; with
    ``fill`` every triangle is kept. Fewer than three points give an empty grid.
    """

    key = "tin"
    title = "TIN DTM report"
    band_name = "DTM (TIN)"
    options_type = TinOptions

    def interpolate(self, x, y, z, grid, *, max_distance=None, fill=False, workers=-1,
                    monitor=None) -> DtmOutcome:
        """Run :func:`~.tin.tin_grid`."""
        from .tin import tin_grid
        mon = monitor or Monitor()
        if np.size(x) < 3:
            return DtmOutcome(np.full(grid.shape, np.nan), n_points=int(np.size(x)))
        edge = self.options.max_edge if self.options.max_edge else max_distance
        res = tin_grid(x, y, z, grid, max_edge=edge, fill=fill, progress=mon.update,
                       cancel=mon.cancelled)
        return DtmOutcome(res.z, details=res, n_points=res.n_points)

    def metadata(self, outcome):
        """``TIN linear (Delaunay)`` and the edge limit."""
        res = outcome.details
        edge = res.max_edge if res is not None else None
        return {"method": "TIN linear (Delaunay) "
                          + ("gaps filled" if edge is None else f"max edge {edge:g} m")}


# ============================================================================ registry
@dataclass(frozen=True)
class DtmSpec:
    """A registered DTM method: key, English label, ``make(options=None)``."""

    key: str
    label: str
    make: Callable[..., DtmMethod]


#: every DTM method, by key (insertion order = the catalog's choice order)
DTM_METHODS: Dict[str, DtmSpec] = {}


def register_dtm_method(key: str, label: str, make: Callable[..., DtmMethod]) -> DtmSpec:
    """Register ``make(options=None) -> DtmMethod`` under ``key``."""
    DTM_METHODS[key] = DtmSpec(key, label, make)
    return DTM_METHODS[key]


def dtm_method(key: str, options=None) -> DtmMethod:
    """Return the method object of ``key`` (default options when None)."""
    return DTM_METHODS[key].make(options)


register_dtm_method("idw", "IDW", IdwMethod)
register_dtm_method("kriging", "Kriging", KrigingMethod)
register_dtm_method("tin", "TIN", TinMethod)


# ============================================================================ runner
@dataclass
class DtmRun:
    """One cloud → DTM run: the points, the grid, the outcome, stats and timing."""

    path: str
    points: ClassPoints
    grid: GridSpec
    method: DtmMethod
    outcome: DtmOutcome
    stats: Dict[str, float]
    crs_source: str = "LAS file"
    fill: bool = False
    max_distance: Optional[float] = None
    seconds: float = 0.0


def grid_stats(arr) -> dict:
    """Return the valid and nodata cells, min and max of a grid.

    >>> grid_stats(np.array([[1.0, np.nan], [3.0, 2.0]]))["valid_cells"]
    3
    """
    ok = np.isfinite(arr)
    return {"valid_cells": int(ok.sum()), "nodata_cells": int((~ok).sum()),
            "min": float(arr[ok].min()) if ok.any() else float("nan"),
            "max": float(arr[ok].max()) if ok.any() else float("nan")}


def read_ground(path, classes: Sequence[int], *, cell: float, units, extent=None,
                crs: Optional[str] = None, cancel=None):
    """Points of ``classes`` in metres and the grid over them.

    Parameters
    ----------
    path : path
        LAS/LAZ file.
    classes : sequence of int
        Classes used (empty = all).
    cell : float
        Cell size (m).
    units : Units
        The cloud's linear units (:mod:`..io.units`); coordinates are converted to
        metres, the extent (data units) too.
    extent : (xmin, xmax, ymin, ymax), optional
        Only points inside, and the grid over it (data units).
    crs : str, optional
        CRS of the grid (checked to be projected).

    Returns
    -------
    (ClassPoints, GridSpec)
    """
    pts = read_class_points(path, classes, extent=extent, cancel=cancel)
    check_projected(pts.x, pts.y, pts.z, crs=crs)
    pts.units = units
    pts.x, pts.y, pts.z = units.xyz_to_metres(pts.x, pts.y, pts.z)
    box = tuple(v * units.h for v in extent) if extent is not None else None
    return pts, grid_from_points(pts.x, pts.y, cell, extent=box, crs=crs)


#: fewest points at distinct positions a DTM is interpolated from (a plane needs three)
MIN_DISTINCT_POINTS = 3


def distinct_positions(x, y, limit: int) -> int:
    """Count the distinct (x, y) positions (to the millimetre), up to ``limit``.

    O(n) with an early stop, no sort: a DTM's millions of ground points pass after
    looking for ``limit`` different positions (``np.unique`` over the rows took 1.6 s
    CPU for 2.5 M points).

    >>> distinct_positions([0.0, 0.0, 1.0, 0.0004], [0.0, 0.0, 0.0, 0.0], 3)
    2
    >>> distinct_positions([0.0, 1.0, 2.0, 3.0], [0.0, 0.0, 0.0, 0.0], 3)
    3
    """
    x, y = np.asarray(x, dtype=np.float64), np.asarray(y, dtype=np.float64)
    if len(x) > 4096:       # a subset's count never exceeds the whole's: stop early
        head = distinct_positions(x[:4096], y[:4096], limit)
        if head >= limit:
            return head
    xy = np.round(np.column_stack([x, y]), 3)
    other = np.ones(len(xy), dtype=bool)
    found = 0
    while found < limit and other.any():
        found += 1
        other &= np.any(xy != xy[np.argmax(other)], axis=1)
    return found


def check_dtm_input(points: ClassPoints, cell: float, path) -> None:
    """Refuse points a DTM cannot be made of (too few positions, too large a cell).

    Fewer than :data:`MIN_DISTINCT_POINTS` distinct positions, or a cell size larger
    than the points' extent (a one-cell DTM).

    Raises
    ------
    InputError
        With the counts / the cell size and the extent (m), and the fix.
    """
    x = np.asarray(points.x, dtype=np.float64)
    y = np.asarray(points.y, dtype=np.float64)
    if x.size == 0:
        return                                  # read_ground has refused already
    distinct = distinct_positions(x, y, MIN_DISTINCT_POINTS)
    if distinct < MIN_DISTINCT_POINTS:
        raise InputError(
            "The {n} point(s) of {path} lie at only {distinct} distinct position(s): a "
            "DTM needs at least {minimum} points at different positions. Use a cloud with "
            "more ground points (check CLASSES, or run a ground filter first). No output "
            "was written.", n=int(x.size), path=path, distinct=distinct,
            minimum=MIN_DISTINCT_POINTS)
    width, height = float(x.max() - x.min()), float(y.max() - y.min())
    if cell > max(width, height):
        raise InputError(
            "CELL_SIZE {cell} m is larger than the extent of the points of {path} "
            "({width} m x {height} m): the DTM would be a single cell. Give a cell size "
            "smaller than the extent (typically 0.5 to 2 m for a LiDAR DTM). No output "
            "was written.", cell=f"{cell:g}", path=path, width=f"{width:.3f}",
            height=f"{height:.3f}")


def make_dtm(path, points: ClassPoints, grid: GridSpec, method: DtmMethod, *,
             max_distance: Optional[float] = None, fill: bool = False,
             crs_source: str = "LAS file", monitor: Optional[Monitor] = None) -> DtmRun:
    """Interpolate ``points`` with ``method``; refuse a DTM without a valid cell.

    Raises
    ------
    InputError
        No cell with a value (too few points, too far apart, on one line).
    """
    check_dtm_input(points, grid.cell, path)
    t0 = time.perf_counter()
    outcome = method.interpolate(points.x, points.y, points.z, grid,
                                 max_distance=max_distance, fill=fill, monitor=monitor)
    stats = grid_stats(outcome.z)
    if stats["valid_cells"] == 0:
        raise InputError(
            "The DTM from {n} point(s) of {path} has no cell with a value: the points "
            "are too few, too far apart or nearly on one line for this method and "
            "cell size. Use more ground points (a ground filter first), a larger "
            "maximum edge / distance, or fill the gaps. No output was written.",
            n=len(points), path=path)
    return DtmRun(os.fspath(path), points, grid, method, outcome, stats, crs_source, fill,
                  max_distance, time.perf_counter() - t0)


def write_dtm(run: DtmRun, path, *, extra: Optional[str] = None, source=None) -> str:
    """Write the DTM (or the extra raster ``extra``: ``variance`` or ``std``) as GeoTIFF."""
    meta = {**run.method.metadata(run.outcome),
            "source": os.path.basename(source or run.path)}
    if extra is None:
        return write_grid(path, run.outcome.z, run.grid, metadata=meta,
                          band_name=run.method.band_name, units=run.points.units)
    std = extra == "std"
    return write_grid(path, run.outcome.extras[extra], run.grid, metadata=meta,
                      band_name="kriging standard deviation" if std else "kriging variance",
                      units=run.points.units, quantity="height" if std else "height2")


def _input_rows(run: DtmRun, name: str) -> list:
    pts = run.points
    classes = ", ".join(f"{c}: {n}" for c, n in sorted(pts.class_counts.items()))
    rows = [("input", name), ("points in file", pts.n_total),
            ("classes present (class: count)", classes), ("points used", len(pts)),
            ("classes used", ", ".join(map(str, pts.classes)) or T("all")),
            ("CRS source", T(run.crs_source))]
    return rows + units_rows(pts.units)


def dtm_report(run: DtmRun, *, lang: str = "en", name: Optional[str] = None,
               elapsed: Optional[float] = None) -> Report:
    """Report content of a DTM run (grid report + the method's sections).

    ``name`` is the input's name shown (default: the file's base name).
    """
    m, o = run.method, run.outcome
    tr = translator(lang)
    if isinstance(m, TinMethod) and o.details is not None:
        return terrain_report.tin_report(o.details, name or os.path.basename(run.path),
                                         run.points.n_total, run.grid,
                                         units=run.points.units)
    rep = terrain_report.grid_report(
        m.title, method_rows=m.method_rows(o, fill=run.fill, max_distance=run.max_distance),
        input_rows=_input_rows(run, name or os.path.basename(run.path)) + m.input_rows(o),
        grid=run.grid, data=o.z, stats=run.stats,
        elapsed=run.seconds if elapsed is None else elapsed, citation=m.citation, tr=tr)
    m.report_sections(rep, o, tr)
    return rep

"""ONE registry of ground filters and the array verb that runs them.

Every ground filter of the toolbox is one :class:`~._filter.GroundFilter` algorithm
object registered here once (:func:`register_ground_filter`): the single-file
algorithms, the catalog chunks (:mod:`._chunks`), the one-step ``lidartodtm`` and the
shipped model's builder all take it from :data:`GROUND_FILTERS`, so a new filter
written once appears everywhere and runs the same in each.

:func:`classify_points` is the pure array code (arrays in, classes out): the point
selection of :mod:`._selection` (returns, low-outlier pre-filter, input noise classes
kept), the filter on the candidates, the output classes assembled.
:func:`~.pipeline.classify_file` is the thin file runner around it (reading, output
contract, writing, report).

Examples
--------
>>> import numpy as np
>>> from geomatics_toolbox.core.io.las import PointData
>>> gx, gy = np.meshgrid(np.arange(0.0, 60.0), np.arange(0.0, 60.0))
>>> x, y = gx.ravel(), gy.ravel()
>>> z = 0.05 * x
>>> z[[100, 2000]] += 8.0                        # two points on objects
>>> cls = np.zeros(x.size, np.uint8)
>>> cls[5] = 18                                  # high noise in the input: kept
>>> pts = PointData(x, y, z, {"classification": cls})
>>> out = classify_points(pts, ground_filter("slope_exact"))
>>> int(out[5]), int(out[100]), int(out[2000]), int((out == 2).sum())
(18, 1, 1, 3597)
"""
from __future__ import annotations

import time
from dataclasses import dataclass, field, replace
from typing import Callable, Dict, Optional

import numpy as np

from ..progress import Monitor
from ._filter import FilterOutcome, GroundFilter, KeepFilter, check_classes
from ._selection import Selection, SelectionOptions, assemble_classes, select_points
from ._summary import cloud_summary
from .ptd import NOISE_PREFILTER as _PTD_NOISE

__all__ = ["FilterSpec", "GROUND_FILTERS", "RECOMMENDED_FILTER", "register_ground_filter",
           "ground_filter", "default_ground_filter", "default_selection", "classify_points",
           "run_filter", "FilterRun"]

RECOMMENDED_FILTER = "groundfilter"


@dataclass(frozen=True)
class FilterSpec:
    """A registered ground filter.

    Attributes
    ----------
    key : str
        Registry key (the catalog's GROUND_FILTER choice; stable).
    label : str
        English label (a message id).
    make : callable
        ``make(options=None) -> GroundFilter`` (default options when None).
    selection : SelectionOptions
        The point selection of its single-file algorithm's defaults.
    algorithm : str
        Id of the single-file Processing algorithm that runs it.
    tiling : bool
        Lays tiles or grids over the points (anchored on a catalog's global origin).
    """

    key: str
    label: str
    make: Callable[..., GroundFilter]
    selection: SelectionOptions = field(default_factory=SelectionOptions)
    algorithm: str = ""
    tiling: bool = False


#: every ground filter, by key (insertion order = the catalog's choice order)
GROUND_FILTERS: Dict[str, FilterSpec] = {}


def register_ground_filter(key: str, label: str, make: Callable[..., GroundFilter], *,
                           selection: Optional[SelectionOptions] = None,
                           algorithm: str = "", tiling: bool = False) -> FilterSpec:
    """Register ``make(options=None) -> GroundFilter`` under ``key``; returns the spec."""
    spec = FilterSpec(key, label, make, selection or SelectionOptions(), algorithm, tiling)
    GROUND_FILTERS[key] = spec
    return spec


def ground_filter(key: str, options=None) -> GroundFilter:
    """Return the algorithm object of filter ``key`` (default options when None)."""
    return GROUND_FILTERS[key].make(options)


def default_selection(key: str) -> SelectionOptions:
    """Return a copy of the point selection of filter ``key``'s single-file defaults."""
    return replace(GROUND_FILTERS[key].selection)


def default_ground_filter() -> str:
    """Return the recommended filter's key when it is registered, else improved LSQ."""
    return RECOMMENDED_FILTER if RECOMMENDED_FILTER in GROUND_FILTERS else "lsq_improved"


@dataclass
class FilterRun:
    """What :func:`run_filter` did: the classes, the selection and the filter's outcome."""

    classes: np.ndarray
    selection: Selection
    outcome: FilterOutcome
    seconds: Dict[str, float] = field(default_factory=dict)


def run_filter(points, algorithm: GroundFilter, selection: Optional[SelectionOptions] = None,
               *, origin=None, monitor: Optional[Monitor] = None) -> FilterRun:
    """Select the points, run ``algorithm`` on the candidates, assemble the classes.

    Parameters
    ----------
    points : PointData
        Coordinates (metres) with the dimensions the selection needs
        (``classification``; ``return_number`` and ``number_of_returns`` for
        ``returns='last'``).
    algorithm : GroundFilter
        The method (see :mod:`._filter`).
    selection : SelectionOptions, optional
        Returns, noise pre-filter, input noise classes (dataclass defaults when None).
    origin : (float, float), optional
        Anchor of the tiles and grids. None: a 'cloud'-lattice filter (the default
        :attr:`~._filter.GroundFilter.lattice`) is anchored at the corner of
        ``points`` (smallest x and y of every point), a 'world'-lattice one (PTD) on its
        lattice through 0. A catalog chunk passes the corner of all the catalog's
        points (:mod:`._summary`): the same anchor as a single-file run of the merged
        cloud, by construction.
    monitor : Monitor, optional
        Progress and cancel.

    Returns
    -------
    FilterRun
        Full-length classes (uint8), the selection and the filter's outcome.
    """
    mon = monitor or Monitor()
    opt = (selection or SelectionOptions()).validate()
    t0 = time.perf_counter()
    if origin is None and getattr(algorithm, "lattice", "cloud") == "cloud" and len(points):
        origin = tuple(cloud_summary(points.x, points.y)["corner"])
    sel = select_points(points, returns=opt.returns, noise=opt.noise,
                        noise_radius=opt.noise_radius, noise_threshold=opt.noise_threshold,
                        keep_noise_classes=opt.keep_noise_classes, origin=origin,
                        progress=mon.sub(0.0, 0.15).update, cancel=mon.cancelled)
    t_sel = time.perf_counter()
    cand = sel.candidates
    dims = points.dims              # every point; the filter leaves the others out
    outcome = algorithm.classify(points.x, points.y, points.z,
                                 return_number=dims.get("return_number"),
                                 number_of_returns=dims.get("number_of_returns"),
                                 classification=dims.get("classification"),
                                 candidates=None if cand.all() else cand,
                                 origin=origin, monitor=mon.sub(0.15, 1.0))
    n = int(np.count_nonzero(cand))
    outcome.classes = check_classes(algorithm.name, outcome.classes, n)
    classes = assemble_classes(sel, outcome.classes, dims.get("classification"))
    return FilterRun(classes, sel, outcome,
                     dict(select=t_sel - t0, filter=time.perf_counter() - t_sel))


def classify_points(points, algorithm: GroundFilter,
                    selection: Optional[SelectionOptions] = None, *, origin=None,
                    monitor: Optional[Monitor] = None) -> np.ndarray:
    """ASPRS classes of ``points`` by ``algorithm`` (see :func:`run_filter`).

    Returns
    -------
    ndarray of uint8
        One class per point: 2 ground, 1 other, 7 low noise, input noise kept.
    """
    return run_filter(points, algorithm, selection, origin=origin, monitor=monitor).classes


# ============================================================================ the filters
def _lsq(mode):
    def make(options=None):
        from .lsq import LsqFilter, LsqOptions
        return LsqFilter(options or LsqOptions(mode=mode))
    return make


def _slope(mode):
    def make(options=None):
        from .slope import SlopeFilter, SlopeOptions
        return SlopeFilter(options or SlopeOptions(mode=mode))
    return make


def _recommended(options=None):
    from .recommended import recommended_filter
    return recommended_filter(options)


def _ptd(options=None):
    from .ptd import ptd_filter
    return ptd_filter(options)


def _keep(options=None):
    return KeepFilter()


_NO_PREFILTER = SelectionOptions(noise=False)
register_ground_filter("keep", "Keep the classes in the files", _keep,
                       selection=_NO_PREFILTER)
register_ground_filter("lsq_faithful", "LSQ surfaces (faithful)", _lsq("faithful"),
                       algorithm="lsqgroundfilter", tiling=True)
register_ground_filter("lsq_improved", "LSQ surfaces (improved)", _lsq("improved"),
                       algorithm="lsqgroundfilter", tiling=True)
register_ground_filter("slope_exact", "Slope filter (exact)", _slope("exact"),
                       algorithm="slopegroundfilter")
register_ground_filter("slope_adaptive", "Slope filter (terrain-adaptive)",
                       _slope("adaptive"), algorithm="slopegroundfilter", tiling=True)
register_ground_filter(RECOMMENDED_FILTER, "Ground filter (recommended)", _recommended,
                       selection=_NO_PREFILTER, algorithm="groundfilter", tiling=True)
register_ground_filter("ptd", "Ground filter (progressive TIN densification)", _ptd,
                       selection=SelectionOptions(noise=_PTD_NOISE), algorithm="ptdgroundfilter",
                       tiling=True)

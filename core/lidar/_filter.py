"""The ground-filter protocol: algorithm objects that classify arrays of points.

In the style of lidR's ``classify_ground(las, algorithm = csf())``: small algorithm
objects own the method; one verb (:func:`.filters.classify_points` for arrays,
:func:`.pipeline.classify_file` for files, a catalog chunk for tiles) owns the
plumbing, so a filter written once runs the same everywhere.

An algorithm is an object with

``name`` (str), ``title`` (report title, an English message id), ``citation``;
``classify(x, y, z, *, return_number=None, number_of_returns=None, classification=None,
candidates=None, origin=None, monitor=None)``
    classify the selected points and return a :class:`FilterOutcome` (``classes``: uint8
    per candidate, 2 ground, 1 other, 0 never classified, 7 low noise). The arrays hold
    every point read (metres); ``candidates`` (bool, one per point; None: every point)
    says which the filter classifies - the others take no part. A filter that cannot
    leave points out in place takes copies (:func:`candidate_arrays`); the recommended
    filter leaves them out without copying the coordinates (3 x 8 B/point).
    ``origin`` (x, y), when given, anchors every grid or tile
    the method lays over the points on the lattice through that point, so that the
    chunks of a catalog equal a run on the merged cloud (``lattice``: 'cloud', the
    default, is given the corner of the whole cloud; 'world', the method's own lattice
    through 0, is given None — :func:`.filters.run_filter`);
``settings()``
    ``[(label, value[, unit]), ...]`` for the report's parameter table;
``report_sections(run, report, tr)``
    append method-specific sections to the report (may do nothing);
``text_outputs(run)``
    ``{role: text}`` of extra text outputs (e.g. the LSQ tile CSV).

:class:`GroundFilter` provides every member but ``classify``. A filter written as a
plain function ``classify(x, y, z, *, return_number=None, number_of_returns=None,
options=None, progress=None, cancel=None[, origin=None]) -> uint8 classes`` plugs in
with :class:`FunctionFilter` (or :class:`OptionsFilter` for labelled report rows).
"""
from __future__ import annotations

import dataclasses
import inspect
from dataclasses import dataclass, field
from typing import Any, Callable, Dict, List, Optional

import numpy as np

from .. import classes as asprs
from ..errors import InputError
from ..progress import Monitor

__all__ = ["FilterOutcome", "GroundFilter", "FunctionFilter", "OptionsFilter",
           "KeepFilter", "options_or_default", "check_classes", "candidate_arrays"]


@dataclass
class FilterOutcome:
    """What a ground filter returns for the points it was given.

    Attributes
    ----------
    classes : ndarray of uint8
        One class per point: 2 ground, 1 other, 0 never classified, 7 low noise.
    details : object
        Method-specific result (e.g. :class:`~.lsq.LsqResult`) for the report.
    stats : dict
        Work counters shown in the report.
    """

    classes: np.ndarray
    details: Any = None
    stats: Dict[str, float] = field(default_factory=dict)

    @property
    def ground(self) -> np.ndarray:
        """Boolean ground mask."""
        return self.classes == asprs.GROUND


def check_classes(name: str, classes, n: int) -> np.ndarray:
    """``classes`` as uint8; refuse an answer that is not one class per point.

    >>> check_classes("demo", [2, 1], 2).dtype.name
    'uint8'
    """
    cls = np.asarray(classes)
    if cls.shape != (n,):
        raise InputError("The ground filter {name} returned {got} classes for {n} points.",
                         name=name, got=int(cls.size), n=n)
    return cls.astype(np.uint8, copy=False)


def candidate_arrays(candidates, *arrays):
    """``arrays`` at the ``candidates`` (copies; all of them as given when None; None kept).

    >>> candidate_arrays(np.array([True, False, True]), np.arange(3), None)
    (array([0, 2]), None)
    """
    if candidates is None:
        return arrays
    return tuple(None if a is None else np.asarray(a)[candidates] for a in arrays)


def options_or_default(options, cls):
    """``options`` if given (must be a ``cls``), else ``cls()``.

    >>> from dataclasses import dataclass
    >>> @dataclass
    ... class Opt:
    ...     a: int = 1
    >>> options_or_default(None, Opt)
    Opt(a=1)
    """
    if options is None:
        return cls()
    if not isinstance(options, cls):
        raise TypeError(f"options must be a {cls.__name__}, got {type(options).__name__}")
    return options


class GroundFilter:
    """Base of the ground-filter algorithm objects (see the module docstring).

    Subclasses set :attr:`name`, :attr:`title`, :attr:`citation`, keep their options
    dataclass in :attr:`options` and implement :meth:`classify`.
    """

    name = "groundfilter"
    title = "Ground filter"
    citation: Optional[str] = None
    #: 'cloud': grids and tiles anchored at the corner of the whole cloud (a catalog
    #: gives its chunks the corner of all its tiles); 'world': on the method's own
    #: lattice through 0 whatever the extent (PTD); 'none': lays no grid
    lattice = "cloud"
    #: True when :meth:`classify` reads ``return_number`` / ``number_of_returns`` (the
    #: file runner decodes them only then, or for ``returns='last'``); no filter here does
    uses_returns = False

    def __init__(self, options=None):
        self.options = options

    def classify(self, x, y, z, *, return_number=None, number_of_returns=None,
                 classification=None, candidates=None, origin=None,
                 monitor: Optional[Monitor] = None) -> FilterOutcome:
        """Classify the selected points; see the module docstring."""
        raise NotImplementedError

    def settings(self) -> List[tuple]:
        """Report rows ``(label, value)`` of the options (dataclass fields by default)."""
        if self.options is None or not dataclasses.is_dataclass(self.options):
            return []
        return [(f.name.replace("_", " "), _setting(getattr(self.options, f.name)))
                for f in dataclasses.fields(self.options)]

    def report_sections(self, run, report, tr) -> None:
        """Append method-specific sections to ``report`` (default: none)."""

    def text_outputs(self, run) -> Dict[str, str]:
        """Extra text outputs ``{role: text}`` (default: none)."""
        return {}


def _setting(value):
    if isinstance(value, (list, tuple)):
        return ", ".join(f"{v:g}" if isinstance(v, float) else str(v) for v in value)
    return "–" if value is None else value


class FunctionFilter(GroundFilter):
    """Adapter for a filter written as a plain function returning uint8 classes.

    Parameters
    ----------
    func : callable
        ``func(x, y, z, *, return_number=None, number_of_returns=None, options=None,
        progress=None, cancel=None) -> uint8 classes`` (2 ground, 1 other, 0 none,
        7 low noise); it also receives ``origin`` when its signature takes one.
    options : object, optional
        Passed through as ``options`` (a dataclass shows in the report).
    name, title, citation : str
        Identity of the method in reports.
    lattice : {'cloud', 'world', 'none'}
        Where the method lays its grids (:attr:`GroundFilter.lattice`).
    """

    def __init__(self, func: Callable, options=None, *, name: str, title: str,
                 citation: Optional[str] = None, lattice: str = "cloud"):
        super().__init__(options)
        self.func = func
        self.name, self.title, self.citation = name, title, citation
        self.lattice = lattice
        try:
            self._takes_origin = "origin" in inspect.signature(func).parameters
        except (TypeError, ValueError):
            self._takes_origin = False

    def classify(self, x, y, z, *, return_number=None, number_of_returns=None,
                 classification=None, candidates=None, origin=None,
                 monitor: Optional[Monitor] = None) -> FilterOutcome:
        """Call the function and check its answer (one class per point)."""
        mon = monitor or Monitor()
        kw = {"origin": origin} if self._takes_origin else {}
        x, y, z, return_number, number_of_returns = candidate_arrays(
            candidates, x, y, z, return_number, number_of_returns)
        cls = self.func(x, y, z, return_number=return_number,
                        number_of_returns=number_of_returns, options=self.options,
                        progress=mon.update, cancel=mon.cancelled, **kw)
        return FilterOutcome(check_classes(self.name, cls, np.size(x)))


class OptionsFilter(FunctionFilter):
    """A :class:`FunctionFilter` whose report rows have labels and units.

    Parameters
    ----------
    func, options, name, title, citation, lattice
        As :class:`FunctionFilter`.
    labels : dict of str to str
        Report label (an English message id) per options field; fields left out are
        not shown.
    """

    def __init__(self, func, options, *, name, title, citation, labels, lattice="cloud"):
        super().__init__(func, options, name=name, title=title, citation=citation,
                         lattice=lattice)
        self.labels = labels

    def settings(self):
        """Report rows ``(label, value)``; None shows as 'derived from the cloud'."""
        from ..reporting import T
        return [(label, T("derived from the cloud") if getattr(self.options, f) is None
                 else getattr(self.options, f)) for f, label in self.labels.items()]


class KeepFilter(GroundFilter):
    """The "filter" that keeps the classes already in the input (e.g. vendor classes).

    >>> KeepFilter().classify([0.0, 1.0], [0.0, 1.0], [5.0, 6.0],
    ...                       classification=[2, 5]).classes.tolist()
    [2, 5]
    """

    name = "keep"
    title = "Keep the classes in the files"
    lattice = "none"           # lays no grid: needs no anchor

    def classify(self, x, y, z, *, return_number=None, number_of_returns=None,
                 classification=None, candidates=None, origin=None,
                 monitor: Optional[Monitor] = None) -> FilterOutcome:
        """Return the input classes (never classified when the input has none)."""
        n = np.size(x) if candidates is None else int(np.count_nonzero(candidates))
        if classification is None:
            return FilterOutcome(np.zeros(n, np.uint8))
        return FilterOutcome(np.array(candidate_arrays(candidates, classification)[0],
                                      dtype=np.uint8))

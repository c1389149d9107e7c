"""One LiDAR ground-filter pipeline: ``classify_file(src, algorithm, outputs, monitor)``.

In the style of lidR's ``classify_ground(las, algorithm = csf())``: one verb owns the
plumbing and small algorithm objects own the method.

:func:`classify_file` owns

* reading the LAS/LAZ file (:mod:`~..io.las`) and refusing clouds in degrees
  (:func:`~..coords.check_projected`) before anything is written;
* point selection (:class:`SelectionOptions`): all returns, or last returns only
  (``return_number == number_of_returns``; files without return information count
  every point as a single, hence last, return; first and intermediate returns get
  class 1 and never reject a last return);
* the shared low-outlier pre-filter (:func:`~.noise.flag_low_outliers`, class 7);
* points the input already marks as noise (7, 18) kept as they are
  (``keep_noise_classes``);
* class bookkeeping: ASPRS 2 ground, 1 other, 7 low noise, 0 never classified; every
  other attribute, VLR, EVLR and the CRS are copied bit for bit
  (:func:`~..io.las.write_las_like`);
* the output contract (:class:`~..io.contract.OutputContract`): every output checked
  against every input and each other before anything is read, written under a
  temporary name and renamed only when all succeeded; an error, cancel or SIGTERM
  leaves nothing;
* progress and cancel (:class:`~..progress.Monitor`) and the report content
  (:class:`~..reporting.Report`).

The algorithm protocol
----------------------
An algorithm is an object with

``name`` (str) and ``title`` (report title, an English message id), ``citation``;
``classify(x, y, z, *, return_number=None, number_of_returns=None, monitor=None)``
    classify the selected points (arrays of the candidates only, metres) and return a
    :class:`FilterOutcome` (``classes``: uint8 per point, 2 ground, 1 other, 0 never
    classified; ``details``: anything the report needs);
``settings()``
    ``[(label, value[, unit]), ...]`` for the report's parameter table;
``report_sections(run, report, tr)``
    append method-specific sections to the report (may do nothing);
``text_outputs(run)``
    ``{role: text}`` of extra text outputs (e.g. the LSQ tile CSV).

:class:`GroundFilter` provides every member but ``classify``. A filter written as a
plain function ``classify(x, y, z, *, return_number=None, number_of_returns=None,
options=None, progress=None, cancel=None) -> uint8 classes`` plugs in with
:class:`FunctionFilter`::

    from .pipeline import FunctionFilter, FilterOutputs, classify_file
    from .ptd import classify, PtdOptions

    PTD = FunctionFilter(classify, PtdOptions(), name="ptd",
                         title="Ground filter (progressive TIN densification)",
                         citation="Axelsson, P. (2000). ...")
    run = classify_file("in.laz", PTD, FilterOutputs(cloud="out.laz"))

Examples
--------
>>> from .slope import SlopeFilter, SlopeOptions            # doctest: +SKIP
>>> run = classify_file("tile.laz", SlopeFilter(SlopeOptions(radius=5)),
...                     FilterOutputs(cloud="c.laz", report="r.html"))  # doctest: +SKIP
"""
from __future__ import annotations

import dataclasses
import math
import os
import time
from dataclasses import dataclass, field
from typing import Any, Callable, Dict, List, Optional

import numpy as np

from ..coords import check_projected
from ..errors import InputError
from ..io.contract import OutputContract
from ..io.las import PointData, las_info, read_las, write_las_like
from ..progress import Monitor
from ..reporting import KeyValues, Paragraph, Report, T, Table, render_html, translator
from .noise import flag_low_outliers

__all__ = ["RETURNS", "GROUND_CLASS", "NONGROUND_CLASS", "NOISE_CLASS", "UNCLASSIFIED_CLASS",
           "last_return_mask", "select_points", "classify_file", "parse_number_list",
           "SelectionOptions", "Selection", "FilterOutcome", "GroundFilter",
           "FunctionFilter", "FilterOutputs", "ClassifyRun", "LAS_SUFFIXES"]

RETURNS = ("all", "last")
GROUND_CLASS = 2
NONGROUND_CLASS = 1
NOISE_CLASS = 7
UNCLASSIFIED_CLASS = 0
INPUT_NOISE_CLASSES = (7, 18)
LAS_SUFFIXES = (".las", ".laz")
CLASS_NAMES = {GROUND_CLASS: "ground", NONGROUND_CLASS: "other (object)",
               NOISE_CLASS: "low noise", UNCLASSIFIED_CLASS: "never classified",
               18: "high noise"}


def parse_number_list(text, name: str) -> List[float]:
    """Parse ``"40, 44, 48"`` or ``"40:60:4"`` (start:stop:step, stop included) as floats."""
    if isinstance(text, (list, tuple, np.ndarray)):
        vals = [float(v) for v in text]
    else:
        t = str(text or "").strip()
        if not t:
            raise ValueError(f"{name} is empty; give numbers like '40, 44, 48' or a range "
                             "'40:60:4'.")
        try:
            if ":" in t:
                parts = [float(p) for p in t.split(":")]
                if len(parts) != 3 or parts[2] <= 0 or parts[1] < parts[0]:
                    raise ValueError
                a, b, step = parts
                count = int(math.floor((b - a) / step + 1e-9)) + 1
                if count > 1000:
                    raise ValueError
                vals = [round(a + k * step, 10) for k in range(count)]
            else:
                vals = [float(p) for p in t.replace(";", ",").replace(" ", ",").split(",")
                        if p.strip()]
        except ValueError:
            raise ValueError(f"{name} '{text}' is not a list of numbers; use '40, 44, 48' or "
                             "start:stop:step like '40:60:4' (at most 1000 values).") from None
    if not vals:
        raise ValueError(f"{name} holds no numbers.")
    return vals


def last_return_mask(return_number, number_of_returns) -> np.ndarray:
    """Return True for last (or single) returns; no return information counts as last."""
    rn = np.asarray(return_number).astype(np.int64)
    nr = np.asarray(number_of_returns).astype(np.int64)
    unknown = (rn == 0) | (nr == 0)
    return unknown | (rn >= nr)


@dataclass
class SelectionOptions:
    """Which points a filter sees (shared by every ground filter).

    Parameters
    ----------
    returns : {'all', 'last'}
        Classify every point, or last (and single) returns only.
    noise : bool
        Run the low-outlier pre-filter (:func:`~.noise.flag_low_outliers`) first.
    noise_radius, noise_threshold : float
        Metres; its cell and depth below the neighbours.
    keep_noise_classes : bool
        Points the input marks 7 or 18 keep their class and take no part.
    """

    returns: str = "all"
    noise: bool = True
    noise_radius: float = 5.0
    noise_threshold: float = 1.0
    keep_noise_classes: bool = True

    def validate(self) -> SelectionOptions:
        """Raise :class:`InputError` on an invalid option; returns self."""
        if self.returns not in RETURNS:
            raise InputError("returns must be 'all' or 'last', got {returns!r}.",
                             returns=self.returns)
        if self.noise and not (self.noise_radius > 0 and self.noise_threshold > 0):
            raise InputError("NOISE_RADIUS and NOISE_THRESHOLD must be > 0 metres (e.g. 5 "
                             "and 1), or switch the NOISE pre-filter off.")
        return self


@dataclass
class Selection:
    """Which points are filtered, and why the others are not."""

    candidates: np.ndarray        # classified and used as neighbours
    low_outliers: np.ndarray      # flagged by the pre-filter (class 7)
    not_last: np.ndarray          # first/intermediate returns in "last" mode (class 1)
    input_noise: np.ndarray       # class 7/18 in the input, kept as they are
    unknown_returns: int = 0


def select_points(pd, *, returns: str = "all", noise: bool = True, noise_radius: float = 5.0,
                  noise_threshold: float = 1.0, keep_noise_classes: bool = True,
                  progress=None, cancel=None) -> Selection:
    """Build the candidate set of a ground filter from a :class:`PointData`.

    Parameters
    ----------
    pd : PointData
        Coordinates with ``classification`` (and the return numbers for
        ``returns='last'``).
    returns, noise, noise_radius, noise_threshold, keep_noise_classes
        See :class:`SelectionOptions`.
    progress, cancel : callable, optional
        Progress and cancel callables of the noise pre-filter.

    Returns
    -------
    Selection
        The masks of the candidates and of the excluded points.
    """
    SelectionOptions(returns, noise, noise_radius, noise_threshold,
                     keep_noise_classes).validate()
    n = len(pd)
    in_noise = np.zeros(n, dtype=bool)
    if keep_noise_classes and "classification" in pd.dims:
        in_noise = np.isin(pd["classification"], INPUT_NOISE_CLASSES)
    not_last = np.zeros(n, dtype=bool)
    unknown = 0
    if returns == "last":
        rn, nr = pd["return_number"], pd["number_of_returns"]
        not_last = ~last_return_mask(rn, nr)
        unknown = int(np.count_nonzero((rn == 0) | (nr == 0)))
    base = ~in_noise & ~not_last
    low = np.zeros(n, dtype=bool)
    if noise and base.any():
        idx = np.flatnonzero(base)
        low[idx] = flag_low_outliers(pd.x[idx], pd.y[idx], pd.z[idx], radius=noise_radius,
                                     threshold=noise_threshold, progress=progress,
                                     cancel=cancel)
    cand = base & ~low
    if not cand.any():
        raise InputError("No point is left to filter after the return/noise selection "
                         "({n} points read, {not_last} not last "
                         "returns, {noise} already noise, "
                         "{low} low outliers). Use returns='all' "
                         "or disable the noise pre-filter.",
                         n=n,
                         not_last=int(np.count_nonzero(not_last)),
                         noise=int(np.count_nonzero(in_noise)),
                         low=int(np.count_nonzero(low)))
    return Selection(cand, low, not_last, in_noise, unknown)


def assemble_classes(sel: Selection, candidate_classes: np.ndarray,
                     original=None) -> np.ndarray:
    """Full-length ASPRS classes from the filter's classes of the candidates.

    Parameters
    ----------
    sel : Selection
        The point selection.
    candidate_classes : ndarray of uint8
        One class per candidate (2, 1 or 0).
    original : ndarray, optional
        The input classification (kept for the input's noise points).

    Returns
    -------
    ndarray of uint8
        2 ground, 1 other (and non-last returns), 7 low outliers, input noise kept.
    """
    cls = np.full(sel.candidates.size, NONGROUND_CLASS, dtype=np.uint8)
    cls[sel.candidates] = candidate_classes
    cls[sel.low_outliers] = NOISE_CLASS
    if sel.input_noise.any() and original is not None:
        cls[sel.input_noise] = np.asarray(original)[sel.input_noise]
    return cls


# ============================================================================ protocol
@dataclass
class FilterOutcome:
    """What a ground filter returns for the points it was given.

    Attributes
    ----------
    classes : ndarray of uint8
        One class per point: 2 ground, 1 other, 0 never classified.
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
        return self.classes == GROUND_CLASS


class GroundFilter:
    """Base of the ground-filter algorithm objects (see the module docstring).

    Subclasses set :attr:`name`, :attr:`title`, :attr:`citation`, keep their options
    dataclass in :attr:`options` and implement :meth:`classify`.
    """

    name = "groundfilter"
    title = "Ground filter"
    citation: Optional[str] = None

    def __init__(self, options=None):
        self.options = options

    def classify(self, x, y, z, *, return_number=None, number_of_returns=None,
                 monitor: Optional[Monitor] = None) -> FilterOutcome:
        """Classify the selected points; see the module docstring."""
        raise NotImplementedError

    def settings(self) -> List[tuple]:
        """Report rows ``(label, value)`` of the options (dataclass fields by default)."""
        if self.options is None or not dataclasses.is_dataclass(self.options):
            return []
        return [(f.name.replace("_", " "), _setting(getattr(self.options, f.name)))
                for f in dataclasses.fields(self.options)]

    def report_sections(self, run: ClassifyRun, report: Report, tr) -> None:
        """Append method-specific sections to ``report`` (default: none)."""

    def text_outputs(self, run: ClassifyRun) -> Dict[str, str]:
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
        progress=None, cancel=None) -> uint8 classes`` (2 ground, 1 other, 0 none).
    options : object, optional
        Passed through as ``options`` (a dataclass shows in the report).
    name, title, citation : str
        Identity of the method in reports.
    """

    def __init__(self, func: Callable, options=None, *, name: str, title: str,
                 citation: Optional[str] = None):
        super().__init__(options)
        self.func = func
        self.name, self.title, self.citation = name, title, citation

    def classify(self, x, y, z, *, return_number=None, number_of_returns=None,
                 monitor: Optional[Monitor] = None) -> FilterOutcome:
        """Call the function and check its answer (one class per point)."""
        mon = monitor or Monitor()
        cls = np.asarray(self.func(x, y, z, return_number=return_number,
                                   number_of_returns=number_of_returns, options=self.options,
                                   progress=mon.update, cancel=mon.cancelled))
        if cls.shape != (np.size(x),):
            raise ValueError(f"{self.name} returned {cls.shape} classes for {np.size(x)} "
                             "points.")
        return FilterOutcome(cls.astype(np.uint8))


# ============================================================================ the verb
@dataclass
class FilterOutputs:
    """Requested outputs of :func:`classify_file` (None = not requested).

    Attributes
    ----------
    cloud : path, optional
        The classified cloud (.las/.laz; every point, classes replaced).
    ground : path, optional
        Ground points only (.las/.laz).
    report : path, optional
        The HTML report.
    text : dict of str to path
        Extra text outputs by role (the algorithm's :meth:`GroundFilter.text_outputs`).
    names : dict of str to str
        Parameter name per role, used in error messages (default: the role).
    inputs : dict of str to path
        Other files the run reads (checked: never written).
    lang : str
        Report language.
    render : callable, optional
        ``render(report) -> html`` (default :func:`~..reporting.render_html` in ``lang``).
    """

    cloud: Optional[str] = None
    ground: Optional[str] = None
    report: Optional[str] = None
    text: Dict[str, str] = field(default_factory=dict)
    names: Dict[str, str] = field(default_factory=dict)
    inputs: Dict[str, Any] = field(default_factory=dict)
    lang: str = "en"
    render: Optional[Callable[[Report], str]] = None

    def by_role(self) -> Dict[str, Optional[str]]:
        """Every requested output by role."""
        roles = {"cloud": self.cloud, "ground": self.ground, "report": self.report,
                 **self.text}
        return {k: os.fspath(v) for k, v in roles.items() if v not in (None, "")}

    def name(self, role: str) -> str:
        """Parameter name of ``role``."""
        return self.names.get(role, role)


@dataclass
class ClassifyRun:
    """Everything :func:`classify_file` did: counts, classes, timing, report content."""

    input: str
    points: PointData
    classes: np.ndarray
    selection: Selection
    outcome: FilterOutcome
    selection_options: SelectionOptions
    outputs: Dict[str, str]
    seconds: Dict[str, float] = field(default_factory=dict)
    report: Optional[Report] = None

    @property
    def n_points(self) -> int:
        """Points read."""
        return int(self.classes.size)

    def count(self, cls: int) -> int:
        """Points of ASPRS class ``cls`` in the output."""
        return int(np.count_nonzero(self.classes == cls))

    @property
    def n_ground(self) -> int:
        """Ground points (class 2)."""
        return self.count(GROUND_CLASS)

    @property
    def n_nonground(self) -> int:
        """Other points (class 1)."""
        return self.count(NONGROUND_CLASS)

    @property
    def n_noise(self) -> int:
        """Class-7 points in the output (pre-filter, filter and kept input noise)."""
        return self.count(NOISE_CLASS)

    @property
    def n_prefiltered(self) -> int:
        """Low outliers flagged by the pre-filter (a part of :attr:`n_noise`)."""
        return int(np.count_nonzero(self.selection.low_outliers))

    @property
    def n_not_last(self) -> int:
        """First and intermediate returns (``returns='last'``)."""
        return int(np.count_nonzero(self.selection.not_last))

    @property
    def n_input_noise(self) -> int:
        """Points kept as the input's noise classes."""
        return int(np.count_nonzero(self.selection.input_noise))

    def counts(self) -> Dict[int, int]:
        """Points per output class."""
        vals, cnt = np.unique(self.classes, return_counts=True)
        return {int(k): int(c) for k, c in zip(vals, cnt)}


def _check_request(outputs: FilterOutputs) -> Dict[str, str]:
    roles = outputs.by_role()
    if not roles:
        raise InputError("Give at least one output: the classified cloud, the ground "
                         "cloud or the report.")
    for role in ("cloud", "ground"):
        if role in roles and not roles[role].lower().endswith(LAS_SUFFIXES):
            raise InputError("The output {name} must end in .las or .laz "
                             "(got {path}).",
                             name=outputs.name(role),
                             path=roles[role])
    return roles


def read_cloud(src, *, returns: bool = True, monitor: Optional[Monitor] = None) -> PointData:
    """Read coordinates, classification and return numbers; refuse degree clouds.

    Parameters
    ----------
    src : path
        LAS/LAZ file (:func:`~..io.las.read_las` refuses missing, non-LAS and empty
        files with a clear error).
    returns : bool
        Also read ``return_number`` and ``number_of_returns``.
    monitor : Monitor, optional
        Progress and cancel of the read.

    Returns
    -------
    PointData
        The points.
    """
    info = las_info(src)
    check_projected(crs=info.crs, what=f"The point cloud {src}")
    dims = ["classification"] + (["return_number", "number_of_returns"] if returns else [])
    mon = monitor or Monitor()
    pd = read_las(src, dims, progress=mon.update, cancel=mon.cancelled)
    check_projected(pd.x, pd.y, pd.z, what=f"The point cloud {src}")
    # Every length parameter is in metres (DEVELOPERS.md, Units): filter in metres.
    pd.x, pd.y, pd.z = info.units.xyz_to_metres(pd.x, pd.y, pd.z)
    return pd


def classify_file(src, algorithm: GroundFilter, outputs: FilterOutputs,
                  monitor: Optional[Monitor] = None, *,
                  selection: Optional[SelectionOptions] = None) -> ClassifyRun:
    """Classify ground in a LAS/LAZ file with ``algorithm``; write all outputs or none.

    Parameters
    ----------
    src : path
        Input LAS/LAZ file (projected CRS, metres).
    algorithm : GroundFilter
        The method (see the module docstring for the protocol).
    outputs : FilterOutputs
        The requested outputs and their parameter names.
    monitor : Monitor, optional
        Progress and cancel.
    selection : SelectionOptions, optional
        Returns, noise pre-filter, input noise classes (defaults of the dataclass).

    Returns
    -------
    ClassifyRun
        Counts, classes, timing and the report content.

    Raises
    ------
    InputError
        Outputs that clash with the input or each other, bad extensions, a cloud in
        degrees, nothing left to filter, an empty ground output.
    Cancelled
        When the monitor's cancel returns True (nothing is written).
    """
    t0 = time.perf_counter()
    mon = monitor or Monitor()
    sel_opt = (selection or SelectionOptions()).validate()
    roles = _check_request(outputs)
    contract = OutputContract({outputs.name(r): p for r, p in roles.items()},
                              inputs={"INPUT": src, **outputs.inputs})
    with contract as out:
        pd = read_cloud(src, monitor=mon.sub(0.0, 0.1))
        t_read = time.perf_counter()
        sel = select_points(pd, **dataclasses.asdict(sel_opt), progress=mon.sub(0.1, 0.2).update,
                            cancel=mon.cancelled)
        t_sel = time.perf_counter()
        outcome = _run_filter(algorithm, pd, sel.candidates, mon.sub(0.2, 0.85))
        t_filter = time.perf_counter()
        cls = assemble_classes(sel, outcome.classes, pd["classification"])
        run = ClassifyRun(os.fspath(src), pd, cls, sel, outcome, sel_opt, roles)
        if "ground" in roles and run.n_ground == 0:
            raise InputError("No point was classified as ground, so the ground-only output "
                             "would be empty; check the filter's parameters.")
        _write_clouds(src, run, out, outputs, mon.sub(0.85, 0.98))
        t_write = time.perf_counter()
        run.seconds = dict(read=t_read - t0, select=t_sel - t_read, filter=t_filter - t_sel,
                           write=t_write - t_filter, total=time.perf_counter() - t0)
        run.report = filter_report(run, algorithm, lang=outputs.lang)
        _write_texts(run, algorithm, out, outputs)
        mon.check()
    mon.update(1.0)
    return run


def _run_filter(algorithm, pd: PointData, cand: np.ndarray, mon: Monitor) -> FilterOutcome:
    """Call ``algorithm.classify`` on the candidates (no copy when all are)."""
    take = (lambda a: a) if cand.all() else (lambda a: a[cand])
    outcome = algorithm.classify(take(pd.x), take(pd.y), take(pd.z),
                                 return_number=take(pd["return_number"]),
                                 number_of_returns=take(pd["number_of_returns"]),
                                 monitor=mon)
    if np.shape(outcome.classes) != (int(np.count_nonzero(cand)),):
        raise ValueError(f"{algorithm.name} returned {np.shape(outcome.classes)} classes for "
                         f"{int(np.count_nonzero(cand))} points.")
    return outcome


def _write_clouds(src, run: ClassifyRun, out: OutputContract, outputs: FilterOutputs,
                  mon: Monitor) -> None:
    dims = {"classification": run.classes}
    if "cloud" in run.outputs:
        write_las_like(src, out.path(outputs.name("cloud")), dimensions=dims,
                       progress=mon.sub(0.0, 0.8).update, cancel=mon.cancelled)
    if "ground" in run.outputs:
        write_las_like(src, out.path(outputs.name("ground")), dimensions=dims,
                       mask=run.classes == GROUND_CLASS, progress=mon.sub(0.8, 1.0).update,
                       cancel=mon.cancelled)


def _write_texts(run: ClassifyRun, algorithm, out: OutputContract,
                 outputs: FilterOutputs) -> None:
    if "report" in run.outputs:
        render = outputs.render or (lambda rep: render_html(rep, lang=outputs.lang))
        out.write_text(outputs.name("report"), render(run.report))
    texts = algorithm.text_outputs(run) if outputs.text else {}
    for role in outputs.text:
        if role not in texts:
            raise ValueError(f"{algorithm.name} has no text output {role!r}.")
        out.write_text(outputs.name(role), texts[role])


# ============================================================================ report
def filter_report(run: ClassifyRun, algorithm, *, lang: str = "en") -> Report:
    """Report content of one :func:`classify_file` run (common part + the method's).

    Parameters
    ----------
    run : ClassifyRun
        The run.
    algorithm : GroundFilter
        The method (adds its own sections).
    lang : str
        Language of the text drawn inside figures.

    Returns
    -------
    Report
        Title, summary, input, classes, class map, selection, parameters, method
        sections, computation and outputs.
    """
    tr = translator(lang)
    n = run.n_points
    rep = Report(algorithm.title, citation=algorithm.citation)
    rep.summary.append(Paragraph(T("{n} points: {g} ground, {o} other, {z} low outliers.",
                                   n=n, g=run.n_ground, o=run.n_nonground, z=run.n_noise)))
    rep.section("Input").add(KeyValues([
        ("Point cloud", run.input), ("Points", n),
        ("CRS", _crs_label(run.points) or T("none")),
        *_units_rows(run.points)]))
    rows = [(k, T(CLASS_NAMES.get(k, "other class")), c, 100.0 * c / n)
            for k, c in sorted(run.counts().items())]
    rep.section("Output classes (ASPRS)").add(
        Table(["Class", "Meaning", "Points", "%"], rows, digits=[0, None, 0, 2]))
    _class_map_section(rep, run, tr)
    rep.section("Point selection").add(KeyValues(_selection_rows(run)))
    rep.section("Parameters").add(KeyValues(algorithm.settings()))
    algorithm.report_sections(run, rep, tr)
    sec = run.seconds
    filt = sec.get("filter") or 0.0
    rep.section("Computation").add(KeyValues([
        ("Reading (s)", sec.get("read")), ("Point selection and low outliers (s)",
                                           sec.get("select")),
        ("Filter (s)", filt), ("Writing (s)", sec.get("write")),
        ("Total (s)", sec.get("total")),
        ("Filter speed (points/s)", n / filt if filt > 0 else None)], digits=2))
    rows = [(T(_ROLE_LABELS.get(r, r)), p) for r, p in run.outputs.items()]
    rep.section("Outputs").add(Table(["Output", "File"], rows))
    return rep


_ROLE_LABELS = {"cloud": "classified cloud", "ground": "ground cloud", "report": "report",
                "csv": "tile table (CSV)"}


def _selection_rows(run: ClassifyRun) -> list:
    opt = run.selection_options
    rows = [("Returns filtered", T("all returns") if opt.returns == "all"
             else T("last returns only")),
            ("Low-outlier pre-filter", opt.noise)]
    if opt.noise:
        rows += [("Low-outlier search cell (m)", opt.noise_radius),
                 ("Low-outlier depth below neighbours (m)", opt.noise_threshold)]
    rows += [("Low outliers flagged by the pre-filter", run.n_prefiltered),
             ("Keep existing noise classes (7, 18)", opt.keep_noise_classes),
             ("Input noise points kept", run.n_input_noise)]
    if opt.returns == "last":
        rows += [("Non-last returns (class 1)", run.n_not_last),
                 ("Points without return information (taken as last)",
                  run.selection.unknown_returns)]
    return rows


def _units_rows(pd: PointData) -> list:
    from ..io.units import units_note
    note = units_note(pd.info.units) if pd.info else None
    return [("Linear units", note)] if note is not None else []


def _crs_label(pd: PointData) -> str:
    from ..io.crs import crs_label
    try:
        return crs_label(pd.info.crs) if pd.info else ""
    except ValueError:
        return str(pd.info.crs)


def _class_map_section(rep: Report, run: ClassifyRun, tr) -> None:
    """Add the plan-view class map (cell colour = majority class) of the output."""
    from .figures import class_map
    rep.section("Class map").add(class_map(run.points.x, run.points.y, run.classes, tr))

"""The file runner of the ground filters: ``classify_file(src, algorithm, outputs, monitor)``.

In the style of lidR's ``classify_ground(las, algorithm = csf())``: one verb owns the
plumbing and small algorithm objects (:mod:`._filter`, registered once in
:mod:`.filters`) own the method. The pure array work (point selection, the filter,
the output classes) is :func:`.filters.run_filter`; :func:`classify_file` adds only

* reading the LAS/LAZ file (:mod:`~..io.las`) and refusing clouds in degrees
  (:func:`~..coords.check_projected`) before anything is written;
* the output contract (:class:`~..io.contract.OutputContract`): every output checked
  against every input and each other before anything is read, written under a
  temporary name and renamed only when all succeeded; an error, cancel or SIGTERM
  leaves nothing; every other attribute, VLR, EVLR and the CRS are copied bit for bit
  (:func:`~..io.las.write_las_like`);
* the report content (:class:`~..reporting.Report`, :mod:`._filter_report`), built
  only when a report is asked for.

The protocol (:class:`GroundFilter`, :class:`FunctionFilter`, :class:`FilterOutcome`)
and the point selection (:class:`SelectionOptions`, :func:`select_points`) are
re-exported here for existing callers.

Examples
--------
>>> from .filters import ground_filter                       # doctest: +SKIP
>>> run = classify_file("tile.laz", ground_filter("slope_exact"),
...                     FilterOutputs(cloud="c.laz", report="r.html"))  # doctest: +SKIP
"""
from __future__ import annotations

import os
import time
from dataclasses import dataclass, field
from typing import Any, Callable, Dict, Optional

import numpy as np

from .. import classes as asprs
from ..coords import check_not_too_sparse, check_projected
from ..errors import InputError
from ..io.contract import OutputContract
from ..io.las import LAS_SUFFIXES, PointData, las_info, read_las, write_las_like
from ..parsing import parse_number_list
from ..progress import Monitor
from ..reporting import Report, T, render_html
from . import _selection
from ._filter import FilterOutcome, FunctionFilter, GroundFilter, OptionsFilter
from ._filter_report import filter_report
from ._selection import (
    Selection,
    SelectionOptions,
    assemble_classes,
    last_return_mask,
    select_points,
)
from .filters import run_filter

__all__ = ["RETURNS", "GROUND_CLASS", "NONGROUND_CLASS", "NOISE_CLASS", "UNCLASSIFIED_CLASS",
           "last_return_mask", "select_points", "classify_file", "parse_number_list",
           "SelectionOptions", "Selection", "FilterOutcome", "GroundFilter",
           "FunctionFilter", "OptionsFilter", "FilterOutputs", "ClassifyRun", "LAS_SUFFIXES",
           "assemble_classes", "read_cloud", "filter_report"]

#: largest cloud whose decoded records are kept to write the outputs from (points;
#: about 35 bytes each, ~0.7 GB at the limit): the input is decoded once, not once more
#: per output; a larger cloud is decoded again rather than held twice in memory
KEEP_RECORDS_MAX = 20_000_000
RETURNS = _selection.RETURNS
GROUND_CLASS = int(asprs.GROUND)
NONGROUND_CLASS = int(asprs.UNCLASSIFIED)
NOISE_CLASS = int(asprs.LOW_NOISE)
UNCLASSIFIED_CLASS = int(asprs.NEVER_CLASSIFIED)


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
        """Points per output class (a bincount: np.unique sorted the 4 M classes, 0.07 s)."""
        per_class = np.bincount(self.classes)
        return {int(k): int(per_class[k]) for k in np.flatnonzero(per_class)}


def _check_request(outputs: FilterOutputs) -> Dict[str, str]:
    roles = outputs.by_role()
    if not roles:
        raise InputError("Give at least one output: the classified cloud, the ground "
                         "cloud or the report.")
    return roles


def read_cloud(src, *, returns: bool = True, keep_records: bool = False,
               monitor: Optional[Monitor] = None) -> PointData:
    """Read coordinates, classification and return numbers; refuse degree clouds.

    Parameters
    ----------
    src : path
        LAS/LAZ file (:func:`~..io.las.read_las` refuses missing, non-LAS and empty
        files with a clear error).
    returns : bool
        Also read ``return_number`` and ``number_of_returns``.
    keep_records : bool
        Keep the decoded records so the outputs are written without decoding the input
        again (up to :data:`KEEP_RECORDS_MAX` points; larger files are decoded twice
        rather than held in memory twice).
    monitor : Monitor, optional
        Progress and cancel of the read.

    Returns
    -------
    PointData
        The points.
    """
    info = las_info(src)
    what = T("The point cloud {path}", path=src)
    check_projected(crs=info.crs, what=what)
    dims = ["classification"] + (["return_number", "number_of_returns"] if returns else [])
    mon = monitor or Monitor()
    pd = read_las(src, dims, keep_records=keep_records and info.count <= KEEP_RECORDS_MAX,
                  progress=mon.update, cancel=mon.cancelled)
    check_projected(pd.x, pd.y, pd.z, what=what)
    # Every length parameter is in metres (DEVELOPERS.md, Units): filter in metres.
    pd.x, pd.y, pd.z = info.units.xyz_to_metres(pd.x, pd.y, pd.z)
    check_not_too_sparse(pd.x, pd.y, what=what)
    return pd


def classify_file(src, algorithm: GroundFilter, outputs: FilterOutputs,
                  monitor: Optional[Monitor] = None, *,
                  selection: Optional[SelectionOptions] = None, origin=None) -> ClassifyRun:
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
    origin : (float, float), optional
        Global lattice of the filter's tiles and grids (as a catalog's chunks).

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
                              inputs={"INPUT": src, **outputs.inputs},
                              point_clouds=[outputs.name(r) for r in ("cloud", "ground")])
    with contract as out:
        # return numbers only when something reads them (0.05 s CPU and 8 B/point on 4 M)
        pd = read_cloud(src, returns=sel_opt.returns == "last"
                        or getattr(algorithm, "uses_returns", True),
                        keep_records=bool({"cloud", "ground"} & set(roles)),
                        monitor=mon.sub(0.0, 0.1))
        t_read = time.perf_counter()
        fr = run_filter(pd, algorithm, sel_opt, origin=origin, monitor=mon.sub(0.1, 0.85))
        t_filter = time.perf_counter()
        run = ClassifyRun(os.fspath(src), pd, fr.classes, fr.selection, fr.outcome, sel_opt,
                          roles)
        if "ground" in roles and run.n_ground == 0:
            raise InputError("No point was classified as ground, so the ground-only output "
                             "would be empty; check the filter's parameters.")
        _write_clouds(src, run, out, outputs, mon.sub(0.85, 0.98))
        t_write = time.perf_counter()
        select = fr.seconds.get("select", 0.0)
        run.seconds = dict(read=t_read - t0, select=select,
                           filter=t_filter - t_read - select, write=t_write - t_filter,
                           total=time.perf_counter() - t0)
        if "report" in roles:
            run.report = filter_report(run, algorithm, lang=outputs.lang)
        _write_texts(run, algorithm, out, outputs)
        mon.check()
    mon.update(1.0)
    return run


def _write_clouds(src, run: ClassifyRun, out: OutputContract, outputs: FilterOutputs,
                  mon: Monitor) -> None:
    dims = {"classification": run.classes}
    if "cloud" in run.outputs:
        write_las_like(src, out.path(outputs.name("cloud")), dimensions=dims,
                       records=run.points.records, progress=mon.sub(0.0, 0.8).update,
                       cancel=mon.cancelled)
    if "ground" in run.outputs:
        write_las_like(src, out.path(outputs.name("ground")), dimensions=dims,
                       mask=run.classes == asprs.GROUND, records=run.points.records,
                       progress=mon.sub(0.8, 1.0).update,
                       cancel=mon.cancelled)


def _write_texts(run: ClassifyRun, algorithm, out: OutputContract,
                 outputs: FilterOutputs) -> None:
    if "report" in run.outputs:
        render = outputs.render or (lambda rep: render_html(rep, lang=outputs.lang))
        out.write_text(outputs.name("report"), render(run.report))
    texts = algorithm.text_outputs(run) if outputs.text else {}
    for role in outputs.text:
        if role not in texts:
            raise InputError("The ground filter {name} has no text output {role}.",
                             name=algorithm.name, role=role)
        out.write_text(outputs.name(role), texts[role])

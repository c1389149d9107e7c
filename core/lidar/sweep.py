"""Threshold sweep of the slope filter on a labelled LAS/LAZ file, with its report.

Vosselman (2000) slope rule evaluated for every threshold against reference labels
with the error measures of Sithole & Vosselman (2004): Type I, Type II, total error
and Cohen's kappa. Outputs (CSV table, HTML report, cloud classified with the best
setting) go through one :class:`~..io.contract.OutputContract`.
"""
from __future__ import annotations

import math
import os
import time
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Sequence

import numpy as np

from ..errors import InputError
from ..io.contract import OutputContract
from ..io.las import check_las_file, las_info, read_las, write_las_like
from ..progress import Monitor
from ..reporting import (
    Figure,
    KeyValues,
    Paragraph,
    Report,
    T,
    Table,
    render_html,
    translator,
)
from . import slope as sf
from ._raster import check_filter_points
from ._slope_kernel import (
    SlopeStats,
    allowed_rise,
    bounded_max_slope,
    check_height,
    check_radius,
    check_slope,
    filter_xyz,
    point_mask,
    slope_tan,
    take_points,
)
from .accuracy import assess, error_codes, ground_mask
from .figures import error_map, sweep_plot
from .pipeline import (
    GROUND_CLASS,
    SelectionOptions,
    assemble_classes,
    read_cloud,
    select_points,
)
from .slope import (
    DEFAULT_HEIGHT_TOLERANCE,
    DEFAULT_RADIUS,
    MODES,
    SLOPE_METRICS,
    terrain_trend,
)

__all__ = ["sweep_file", "SweepSummary", "sweep_report", "SweepRow", "SweepResult",
           "threshold_sweep"]


@dataclass
class SweepRow:
    """One setting of the sweep and its accuracy against the reference."""

    radius: float
    slope: float
    height_tolerance: float
    allowed_rise: float
    n_ground: int
    a: int
    b: int
    c: int
    d: int
    type1: float
    type2: float
    total: float
    kappa: float

    def as_dict(self) -> dict:
        """Return the row as a dict."""
        return dict(self.__dict__)


@dataclass
class SweepResult:
    """All rows of a sweep and the best one by ``metric``."""

    rows: List[SweepRow]
    metric: str
    best: SweepRow
    n_points: int
    n_reference_ground: int
    mode: str
    best_ground: Optional[np.ndarray] = None

    HEADERS = ("radius_m", "slope_deg", "height_tolerance_m", "allowed_rise_at_r_m",
               "n_ground", "a", "b", "c", "d", "type1_pct", "type2_pct", "total_pct",
               "kappa_pct")

    def table(self) -> List[tuple]:
        """Return one tuple per setting, in the order of :attr:`HEADERS`."""
        return [(r.radius, r.slope, r.height_tolerance, r.allowed_rise, r.n_ground, r.a, r.b,
                 r.c, r.d, r.type1, r.type2, r.total, r.kappa) for r in self.rows]

    def to_csv(self) -> str:
        """CSV text (comma separated, '.' decimals, header row)."""
        lines = [",".join(self.HEADERS)]
        for row in self.table():
            cells = []
            for v in row:
                if isinstance(v, (int, np.integer)):
                    cells.append(str(int(v)))
                else:
                    cells.append("" if not math.isfinite(v) else f"{v:.6g}")
            lines.append(",".join(cells))
        return "\n".join(lines) + "\n"


def _metric_key(row: SweepRow, metric: str) -> float:
    val = getattr(row, metric)
    if not math.isfinite(val):
        return math.inf
    return -val if SLOPE_METRICS[metric] else val


def _sweep_settings(slopes, radii, height_tolerance, metric, mode):
    """Return the checked ``(slopes, radii, tolerances)`` lists of a sweep."""
    if metric not in SLOPE_METRICS:
        raise InputError("metric must be one of {choices}, got {metric}.",
                         choices=", ".join(SLOPE_METRICS), metric=repr(metric))
    if mode not in MODES:
        raise InputError("mode must be one of {choices}, got {mode}.",
                         choices=", ".join(MODES), mode=repr(mode))
    slopes = [check_slope(s) for s in np.atleast_1d(np.asarray(slopes, dtype=float))]
    radii = [check_radius(r) for r in np.atleast_1d(np.asarray(radii, dtype=float))]
    if not slopes or not radii:
        raise InputError("Give at least one slope threshold and one radius to sweep.")
    hs = [check_height(v) for v in np.atleast_1d(np.asarray(height_tolerance, dtype=float))]
    if not hs:
        raise InputError("Give at least one height tolerance (e.g. 0).")
    return slopes, radii, hs


def threshold_sweep(x, y, z, reference_ground, *, slopes: Sequence[float] = (
        40, 44, 48, 52, 56, 60), radii: Sequence[float] = (DEFAULT_RADIUS,),
        height_tolerance=DEFAULT_HEIGHT_TOLERANCE, classify=None, neighbours=None,
        mode: str = "exact", metric: str = "total", trend_cell: float = 10.0,
        trend_window: float = 60.0, progress=None, cancel=None) -> SweepResult:
    """Filter accuracy for every (radius, slope) setting, one neighbourhood pass per radius.

    For each radius the exact per-point required slope ``S_i`` is computed once
    over the range of the thresholds (:func:`max_slope`); every threshold is
    then a single comparison ``S_i > tan(theta)`` giving labels identical to
    :func:`slope_filter` with that setting. Points outside ``classify`` count as
    non-ground. Errors follow Sithole & Vosselman (2004): Type I (ground
    rejected), Type II (objects accepted: the forest study's "error" column),
    total and Cohen's kappa, all in percent.

    Parameters
    ----------
    x, y, z : array_like
        Coordinates.
    reference_ground : array_like of bool
        Reference labels (True = ground), one per point.
    slopes : sequence of float
        Thresholds in degrees, each in (0, 90).
    radii : sequence of float
        Radii in metres, each > 0.
    height_tolerance : float or sequence of float
        Metres (>= 0); a sequence sweeps it too (one pass per radius and
        tolerance).
    metric : {"total", "kappa", "type1", "type2"}
        Criterion for the best setting: lowest error, or highest kappa. Ties go
        to the first setting in radius, slope order.
    classify, neighbours, mode, trend_cell, trend_window
        As in :func:`slope_filter`.

    Returns
    -------
    SweepResult

    Raises
    ------
    InputError
        Fewer than 2 points or every point at one x/y position (as :func:`slope_filter`),
        reference labels that do not match, an invalid option.
    """
    x, y, z = filter_xyz(x, y, z)
    check_filter_points(x, y, sf.MIN_POINTS)        # the slope filter's own refusals
    ref = np.asarray(reference_ground, dtype=bool).ravel()
    if ref.size != x.size:
        raise InputError("The reference has {labels} labels but the cloud has {n} "
                         "points; the reference must label the same points in the same "
                         "order.", labels=int(ref.size), n=int(x.size))
    slopes, radii, hs = _sweep_settings(slopes, radii, height_tolerance, metric, mode)
    cm = point_mask(classify, x.size, "classify")
    nm = point_mask(neighbours, x.size, "neighbours")
    mon = Monitor(progress, cancel)
    zz = z
    if mode == "adaptive":
        zz = z - terrain_trend(x, y, z, cell=trend_cell, window=trend_window,
                               neighbours=nm, cancel=cancel)
    lo, hi = min(slopes), max(slopes)
    rows: List[SweepRow] = []
    passes = [(r, h) for r in radii for h in hs]
    px, py, pz = take_points(x, y, zz, cm)
    qx, qy, qz = take_points(x, y, zz, nm)
    best_key, best_ground = None, None
    for k, (r, h) in enumerate(passes):
        v = np.full(x.size, np.nan)
        if cm.any():
            v[cm] = bounded_max_slope(px, py, pz, qx, qy, qz, radius=r, height=h,
                                       t_lo=slope_tan(lo), t_hi=slope_tan(hi), cell=None,
                                       mon=mon.sub(k / len(passes), (k + 1) / len(passes)),
                                       stats=SlopeStats())
        for s in slopes:
            pred = cm & ~(v > slope_tan(s))
            acc = assess(pred, ref)
            row = SweepRow(radius=r, slope=s, height_tolerance=h,
                           allowed_rise=float(allowed_rise(r, s)),
                           n_ground=int(np.count_nonzero(pred)), a=acc.a, b=acc.b,
                           c=acc.c, d=acc.d, type1=acc.type1, type2=acc.type2,
                           total=acc.total, kappa=acc.kappa)
            rows.append(row)
            key = _metric_key(row, metric)
            if best_key is None or key < best_key:
                best_key, best_ground = key, pred
    best = min(rows, key=lambda row: _metric_key(row, metric))
    mon.update(1.0)
    return SweepResult(rows=rows, metric=metric, best=best, n_points=x.size,
                       n_reference_ground=int(np.count_nonzero(ref)), mode=mode,
                       best_ground=best_ground)



@dataclass
class SweepSummary:
    """Result of :func:`sweep_file`."""

    result: SweepResult
    input: str
    reference: str
    n_points: int
    n_evaluated: int
    outputs: Dict[str, str]
    settings: Dict[str, object]
    seconds: float = 0.0
    report: Optional[Report] = field(default=None, repr=False)
    error_map: Optional[Figure] = field(default=None, repr=False)


def _load_reference(reference, ground_classes, pd, mon: Monitor) -> np.ndarray:
    if reference in (None, "", "input"):
        return ground_mask(pd["classification"], ground_classes)
    check_las_file(reference)
    info = las_info(reference)
    if info.count != len(pd):
        raise InputError("The reference cloud {reference} has {n_ref} points but the "
                         "input has {n_input}; the reference must hold the same points in "
                         "the same order (or use the input's own classification).",
                         reference=reference,
                         n_ref=info.count,
                         n_input=len(pd))
    ref = read_las(reference, ["classification"], progress=mon.update, cancel=mon.cancelled)
    tol = max(max(info.scales[:2]), max(pd.info.scales[:2]) if pd.info else 0.0, 1e-6)
    if (np.abs(ref.x - pd.x).max() > tol) or (np.abs(ref.y - pd.y).max() > tol):
        raise InputError("The reference cloud {reference} has as many points as the input "
                         "but not the same coordinates in the same order; give the labelled "
                         "copy of the same cloud.", reference=reference)
    return ground_mask(ref["classification"], ground_classes)


def _check_grid(slopes, radii, hs, metric, mode):
    slopes = [sf.check_slope(s) for s in slopes]
    radii = [sf.check_radius(r) for r in radii]
    hs = [sf.check_height(h) for h in hs]
    if not slopes or not radii or not hs:
        raise InputError("Give at least one slope, one radius and one height tolerance.")
    if len(slopes) * len(radii) * len(hs) > 5000:
        raise InputError("More than 5000 settings requested; narrow the lists.")
    if metric not in sf.SLOPE_METRICS:
        raise InputError("metric must be one of {choices}, got "
                         "{metric!r}.",
                         choices=', '.join(sf.SLOPE_METRICS),
                         metric=metric)
    if mode not in sf.MODES:
        raise InputError("mode must be one of {choices}, got {mode!r}.",
                         choices=', '.join(sf.MODES),
                         mode=mode)
    return slopes, radii, hs


def sweep_file(src, *, reference=None, ground_classes: Sequence[int] = (GROUND_CLASS,),
               slopes: Sequence[float] = (30, 35, 40, 44, 48, 52, 56, 60),
               radii: Sequence[float] = (sf.DEFAULT_RADIUS,),
               height_tolerances: Sequence[float] = (sf.DEFAULT_HEIGHT_TOLERANCE,),
               metric: str = "total", selection: Optional[SelectionOptions] = None,
               mode: str = "exact", trend_cell: float = 10.0, trend_window: float = 60.0,
               csv_output=None, html_output=None, output=None, names=None,
               lang: str = "en", render=None, progress=None, cancel=None) -> SweepSummary:
    """Threshold sweep of the slope filter on a labelled LAS/LAZ file.

    Parameters
    ----------
    src : path
        The cloud (its classification never influences the filtering).
    reference : path, optional
        ``None``/``"input"``: the input's own classification (e.g. the ISPRS samples);
        else a labelled copy of the same points in the same order.
    ground_classes : sequence of int
        Reference classes counted as ground.
    slopes, radii, height_tolerances : sequence of float
        The grid of settings (degrees, metres, metres).
    metric : {'total', 'kappa', 'type1', 'type2'}
        How the best setting is chosen.
    selection : SelectionOptions, optional
        Returns and noise pre-filter; ``keep_noise_classes`` defaults to False here
        because the input's classes are usually the labels under test.
    mode, trend_cell, trend_window
        As in :func:`~.slope.slope_filter`.
    csv_output, html_output, output : path, optional
        Sweep table, report, cloud classified with the best setting.
    names : dict, optional
        Parameter names of the outputs for error messages.
    lang : str
        Report language.
    render : callable, optional
        ``render(report) -> html`` (default :func:`~..reporting.render_html` in ``lang``).
    progress, cancel : callable, optional
        Progress and cancel.

    Returns
    -------
    SweepSummary
        The sweep, counts and report content.
    """
    t0 = time.perf_counter()
    mon = Monitor(progress, cancel)
    names = {"csv": "OUTPUT_CSV", "report": "OUTPUT_HTML", "cloud": "OUTPUT", **(names or {})}
    sel_opt = (selection or SelectionOptions(keep_noise_classes=False)).validate()
    slopes, radii, hs = _check_grid(slopes, radii, height_tolerances, metric, mode)
    roles = {k: os.fspath(v) for k, v in (("csv", csv_output), ("report", html_output),
                                          ("cloud", output)) if v}
    ref_in = None if reference in (None, "", "input") else reference
    with OutputContract({names[k]: v for k, v in roles.items()},
                        inputs={"INPUT": src, "REFERENCE": ref_in},
                        point_clouds=[names["cloud"]]) as out:
        pd = read_cloud(src, monitor=mon.sub(0.0, 0.05))
        ref = _load_reference(ref_in, ground_classes, pd, mon.sub(0.05, 0.1))
        if not ref.any():
            raise InputError("The reference marks no point as ground (classes "
                             "{classes}); check the reference "
                             "or the ground classes.",
                             classes=', '.join(map(str, ground_classes)))
        sel = select_points(pd, **vars(sel_opt), progress=mon.sub(0.1, 0.15).update,
                            cancel=mon.cancelled)
        res = threshold_sweep(pd.x, pd.y, pd.z, ref, slopes=slopes, radii=radii,
                                 height_tolerance=hs, classify=sel.candidates,
                                 neighbours=sel.candidates, mode=mode, metric=metric,
                                 trend_cell=trend_cell, trend_window=trend_window,
                                 progress=mon.sub(0.15, 0.9).update, cancel=mon.cancelled)
        settings = dict(slopes_deg=", ".join(f"{s:g}" for s in slopes),
                        radii_m=", ".join(f"{r:g}" for r in radii),
                        height_tolerances_m=", ".join(f"{h:g}" for h in hs), metric=metric,
                        returns=sel_opt.returns, noise_prefilter=sel_opt.noise, mode=mode,
                        ground_classes=", ".join(map(str, ground_classes)))
        summary = SweepSummary(
            result=res, input=os.fspath(src),
            reference=os.fspath(ref_in) if ref_in else _OWN_LABELS,
            n_points=len(pd), n_evaluated=int(np.count_nonzero(sel.candidates)),
            outputs=roles, settings=settings)
        summary.error_map = error_map(pd.x, pd.y, error_codes(res.best_ground, ref),
                                      translator(lang))
        if output:
            best = res.best_ground[sel.candidates]
            cls = assemble_classes(sel, np.where(best, 2, 1).astype(np.uint8),
                                   pd["classification"])
            write_las_like(src, out.path(names["cloud"]), dimensions={"classification": cls},
                           progress=mon.sub(0.9, 0.98).update, cancel=mon.cancelled)
        if csv_output:
            out.write_text(names["csv"], res.to_csv())
        summary.seconds = time.perf_counter() - t0
        summary.report = sweep_report(summary, lang=lang)
        if html_output:
            render = render or (lambda rep: render_html(rep, lang=lang))
            out.write_text(names["report"], render(summary.report))
        mon.check()
    mon.update(1.0)
    return summary


_OWN_LABELS = "input classification"
_METRIC_LABELS = {"total": "lowest total error", "kappa": "highest kappa",
                  "type1": "lowest Type I error", "type2": "lowest Type II error"}


def sweep_report(summary: SweepSummary, *, lang: str = "en") -> Report:
    """Report content of :func:`sweep_file`: best setting, all settings, error chart.

    Parameters
    ----------
    summary : SweepSummary
        The sweep.
    lang : str
        Language of the text drawn in the chart.

    Returns
    -------
    Report
        The content, rendered by :func:`~..reporting.render_html`.
    """
    res, b = summary.result, summary.result.best
    rep = Report("Slope filter threshold sweep", citation=T(
        "Reference: {ref} Error measures: {ref2}",
        ref="Vosselman, G. (2000). Slope based filtering of laser altimetry data. IAPRS "
            "XXXIII-B3, 935–942.",
        ref2="Sithole, G. & Vosselman, G. (2004), ISPRS J. Photogramm. Remote Sens. "
             "59(1-2), 85-101."))
    rep.summary.append(Paragraph(T(
        "{n} points, {e} filtered (the others — low outliers, non-last returns — count as "
        "non-ground); {g} reference ground points.", n=summary.n_points,
        e=summary.n_evaluated, g=res.n_reference_ground)))
    ref = summary.reference
    rep.section("Inputs").add(KeyValues([("Point cloud", summary.input),
                                         ("Reference", T(ref) if ref == _OWN_LABELS else ref)]))
    rep.section("Best setting").add(KeyValues([
        ("Chosen by", T(_METRIC_LABELS[res.metric])), ("Radius r (m)", b.radius),
        ("Slope threshold θ (degrees)", b.slope), ("Height tolerance h (m)",
                                                   b.height_tolerance),
        ("Type I error (%)", b.type1), ("Type II error (%)", b.type2),
        ("Total error (%)", b.total), ("Kappa (%)", b.kappa)], digits=2)).add(Paragraph(
            "Type I = reference ground rejected (b/(a+b)); Type II = objects accepted as "
            "ground (c/(c+d)), which alone always favours low thresholds; total = (b+c)/n; "
            "kappa = Cohen's kappa.", "note"))
    headers = ["r (m)", "θ (°)", "h (m)", "Allowed rise at r (m)", "Ground points", "a",
               "b", "c", "d", "Type I %", "Type II %", "Total %", "Kappa %"]
    rows = [(("★ " if row is b else "") + f"{row.radius:g}", row.slope, row.height_tolerance,
             row.allowed_rise, row.n_ground, row.a, row.b, row.c, row.d, row.type1,
             row.type2, row.total, row.kappa) for row in res.rows]
    sec = rep.section("All settings")
    _sweep_figure(sec, res, translator(lang))
    sec.add(Table(headers, rows, digits=2))
    if summary.error_map is not None:
        rep.section("Error map of the best setting").add(summary.error_map)
    st = summary.settings
    rep.section("Parameters").add(KeyValues([
        ("Slope thresholds θ (degrees)", st["slopes_deg"]), ("Radii r (m)", st["radii_m"]),
        ("Height tolerances h (m)", st["height_tolerances_m"]),
        ("Best by", T(_METRIC_LABELS[st["metric"]])),
        ("Returns filtered", T("all returns") if st["returns"] == "all"
         else T("last returns only")),
        ("Low-outlier pre-filter", st["noise_prefilter"]), ("Mode", T(st["mode"])),
        ("Reference ground classes", st["ground_classes"])]))
    rep.section("Computation").add(KeyValues([("Total (s)", summary.seconds)], digits=1))
    return rep


def _sweep_figure(sec, res, tr) -> None:
    """Add the plot of the errors against θ (best radius and height tolerance)."""
    fig = sweep_plot(res.rows, res.best, tr)
    if fig is not None:
        sec.add(fig)




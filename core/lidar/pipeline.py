"""File-level slope filtering and threshold sweep: LAS/LAZ in, classified LAS/LAZ, CSV, HTML out.

The Processing algorithms ``slopegroundfilter`` and ``slopethresholdsweep`` are thin
wrappers over :func:`classify_file` and :func:`sweep_file`; everything here is
Qt-free and tested headless.

Point selection (which points are classified and which may reject others):

* ``returns="all"`` (default, as in the forest study): every point is classified
  and every point serves as a neighbour.
* ``returns="last"``: only last returns (``return_number == number_of_returns``;
  files without return information, where either field is 0, count every point as
  a single, hence last, return) are classified *and* serve as neighbours. First
  and intermediate returns of multi-return pulses are given class 1 (a later
  return of the same pulse lies below them, so they are not bare earth) and never
  reject a last return.
* Low outliers (:func:`~.noise.flag_low_outliers`, on by default) get class 7 and
  are removed from both sets before filtering: one stray low point would otherwise
  reject every ground point within ``r`` of it.
* Points the input already marks as noise (class 7 or 18) keep their class and
  are excluded from both sets when ``keep_noise_classes`` is on (default). Every
  other input class is ignored (the filter never reads it to decide anything).

Output classes: 2 ground, 1 non-ground (unclassified), 7 low noise; all other
attributes are copied bit for bit (:func:`~.las_io.write_las_like`).
"""
from __future__ import annotations

import math
import os
import time
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Sequence

import numpy as np

from ..io.contract import atomic_output, check_not_input
from ..io.las import check_las_file, las_info, read_las, write_las_like
from ..progress import Monitor
from ..reporting.html import esc, fmt, html_page, html_params, html_table
from . import slope as sf
from .accuracy import ground_mask
from .noise import flag_low_outliers

__all__ = ["RETURNS", "GROUND_CLASS", "NONGROUND_CLASS", "NOISE_CLASS",
           "last_return_mask", "select_points", "classify_file", "sweep_file",
           "ClassifySummary", "SweepSummary", "parse_number_list"]

RETURNS = ("all", "last")
GROUND_CLASS = 2
NONGROUND_CLASS = 1
NOISE_CLASS = 7
INPUT_NOISE_CLASSES = (7, 18)


def parse_number_list(text, name: str) -> List[float]:
    """``"40, 44, 48"`` or ``"40:60:4"`` (start:stop:step, stop included) -> floats."""
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
    """True for last (or single) returns; points without return information count as last."""
    rn = np.asarray(return_number).astype(np.int64)
    nr = np.asarray(number_of_returns).astype(np.int64)
    unknown = (rn == 0) | (nr == 0)
    return unknown | (rn >= nr)


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
    """Build the candidate set of :mod:`~.slope_filter` from a :class:`PointData`."""
    if returns not in RETURNS:
        raise ValueError(f"returns must be 'all' or 'last', got {returns!r}.")
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
        raise ValueError("No point is left to filter after the return/noise selection "
                         f"({n} points read, {int(np.count_nonzero(not_last))} not last "
                         f"returns, {int(np.count_nonzero(in_noise))} already noise, "
                         f"{int(np.count_nonzero(low))} low outliers). Use returns='all' "
                         "or disable the noise pre-filter.")
    return Selection(cand, low, not_last, in_noise, unknown)


def _classes(sel: Selection, ground: np.ndarray, original) -> np.ndarray:
    cls = np.full(ground.size, NONGROUND_CLASS, dtype=np.uint8)
    cls[ground] = GROUND_CLASS
    cls[sel.low_outliers] = NOISE_CLASS
    if sel.input_noise.any():
        cls[sel.input_noise] = np.asarray(original)[sel.input_noise]
    return cls


def _check_outputs(src, *outputs) -> None:
    seen = set()
    for out in outputs:
        if not out:
            continue
        check_not_input(out, src)
        key = os.path.abspath(os.fspath(out))
        if key in seen:
            raise ValueError(f"The same output path {out} is given twice; choose distinct "
                             "outputs.")
        seen.add(key)


def _check_las_out(path, name: str) -> None:
    if path and not str(path).lower().endswith((".las", ".laz")):
        raise ValueError(f"{name} must end in .las or .laz (got {path}).")


# ============================================================================ classify
@dataclass
class ClassifySummary:
    """Counts, settings, timing and work statistics of :func:`classify_file`."""

    input: str
    output: Optional[str]
    ground_output: Optional[str]
    html_output: Optional[str]
    n_points: int
    n_ground: int
    n_nonground: int
    n_noise: int
    n_not_last: int
    n_input_noise: int
    n_unknown_returns: int
    settings: Dict[str, object]
    stats: Dict[str, float] = field(default_factory=dict)
    seconds: Dict[str, float] = field(default_factory=dict)

    def as_dict(self) -> dict:
        return dict(self.__dict__)


def classify_file(src, dst=None, *, ground_output=None, html_output=None,
                  radius: float = sf.DEFAULT_RADIUS, slope: float = sf.DEFAULT_SLOPE,
                  height_tolerance: float = sf.DEFAULT_HEIGHT_TOLERANCE,
                  returns: str = "all", noise: bool = True, noise_radius: float = 5.0,
                  noise_threshold: float = 1.0, keep_noise_classes: bool = True,
                  mode: str = "exact", trend_cell: float = 10.0, trend_window: float = 60.0,
                  lang: str = "en", progress=None, cancel=None) -> ClassifySummary:
    """Slope-filter a LAS/LAZ file: classified copy, optional ground-only copy and report.

    Parameters are those of :func:`~.slope_filter.slope_filter` and
    :func:`select_points`; ``dst`` (classes 2/1/7, everything else preserved),
    ``ground_output`` (ground points only) and ``html_output`` are each optional
    but at least one must be given. All parameters are validated before any
    output is written; each output is written atomically.
    """
    t0 = time.perf_counter()
    mon = Monitor(progress, cancel)
    if not (dst or ground_output or html_output):
        raise ValueError("Give at least one output: the classified cloud, the ground "
                         "cloud or the HTML report.")
    check_las_file(src)
    _check_las_out(dst, "The classified output")
    _check_las_out(ground_output, "The ground output")
    _check_outputs(src, dst, ground_output, html_output)
    sf._check_radius(radius)
    sf._check_slope(slope)
    sf._check_height(height_tolerance)
    if returns not in RETURNS:
        raise ValueError(f"returns must be 'all' or 'last', got {returns!r}.")
    if mode not in sf.MODES:
        raise ValueError(f"mode must be one of {', '.join(sf.MODES)}, got {mode!r}.")
    pd = _read_input(src, returns, mon.sub(0.0, 0.1))
    t_read = time.perf_counter()
    sel = select_points(pd, returns=returns, noise=noise, noise_radius=noise_radius,
                        noise_threshold=noise_threshold,
                        keep_noise_classes=keep_noise_classes, **_cb(mon.sub(0.1, 0.2)))
    t_sel = time.perf_counter()
    res = sf.slope_filter(pd.x, pd.y, pd.z, radius=radius, slope=slope,
                          height_tolerance=height_tolerance, classify=sel.candidates,
                          neighbours=sel.candidates, mode=mode, trend_cell=trend_cell,
                          trend_window=trend_window, **_cb(mon.sub(0.2, 0.85)))
    t_filter = time.perf_counter()
    cls = _classes(sel, res.ground, pd["classification"])
    settings = dict(radius_m=float(radius), slope_deg=float(slope),
                    height_tolerance_m=float(height_tolerance), returns=returns,
                    noise_prefilter=bool(noise), noise_radius_m=float(noise_radius),
                    noise_threshold_m=float(noise_threshold),
                    keep_noise_classes=bool(keep_noise_classes), mode=mode)
    if mode == "adaptive":
        settings.update(trend_cell_m=float(trend_cell), trend_window_m=float(trend_window))
    summary = ClassifySummary(
        input=os.fspath(src), output=dst and os.fspath(dst),
        ground_output=ground_output and os.fspath(ground_output),
        html_output=html_output and os.fspath(html_output), n_points=len(pd),
        n_ground=int(np.count_nonzero(cls == GROUND_CLASS)),
        n_nonground=int(np.count_nonzero(cls == NONGROUND_CLASS)),
        n_noise=int(np.count_nonzero(sel.low_outliers)),
        n_not_last=int(np.count_nonzero(sel.not_last)),
        n_input_noise=int(np.count_nonzero(sel.input_noise)),
        n_unknown_returns=sel.unknown_returns, settings=settings, stats=dict(res.stats))
    if dst:
        write_las_like(src, dst, dimensions={"classification": cls}, **_cb(mon.sub(0.85, 0.95)))
    if ground_output:
        write_las_like(src, ground_output, dimensions={"classification": cls},
                       mask=cls == GROUND_CLASS, **_cb(mon.sub(0.95, 0.99)))
    t_write = time.perf_counter()
    summary.seconds = dict(read=t_read - t0, noise=t_sel - t_read, filter=t_filter - t_sel,
                           write=t_write - t_filter, total=t_write - t0)
    if html_output:
        text = classify_report(summary, res, lang=lang)
        with atomic_output(html_output) as tmp:
            with open(tmp, "w", encoding="utf-8") as fh:
                fh.write(text)
    mon.update(1.0)
    return summary


def _cb(mon: Monitor) -> dict:
    return {"progress": mon.update, "cancel": mon.cancelled}


def _read_input(src, returns: str, mon: Monitor):
    """Coordinates, classification and (for ``returns='last'``) the return numbers;
    :func:`read_las` refuses missing, non-LAS and empty files with a clear error.
    """
    dims = ["classification"]
    if returns == "last":
        dims += ["return_number", "number_of_returns"]
    return read_las(src, dims, **_cb(mon))


def _method_html(radius, slope, h, mode) -> str:
    t = math.tan(math.radians(slope))
    txt = (f"<p>Vosselman (2000) slope-based filter: a point is <b>non-ground</b> when a "
           f"neighbour at horizontal distance 0 &lt; d ≤ r = {fmt(radius, 2)} m lies more than "
           f"d·tan θ + h below it (θ = {fmt(slope, 2)}°, tan θ = {fmt(t, 4)}, "
           f"h = {fmt(h, 2)} m); otherwise ground. Single pass, neighbours from the whole "
           "selected cloud, exact (identical to a brute-force check of every pair).</p>")
    if mode == "adaptive":
        txt += ("<p><b>Adaptive mode (this toolbox's extension, not Vosselman's):</b> the "
                "rule is applied to heights above a smooth low terrain trend (minimum grid, "
                "morphological opening, mean filter), so long natural slopes steeper than θ "
                "are not rejected while abrupt objects still are.</p>")
    return txt


def _rise_table(radius, slope, h) -> str:
    ds = [radius / 4, radius / 2, 3 * radius / 4, radius]
    rows = [(fmt(d, 2), float(sf.allowed_rise(d, slope)) + h) for d in ds]
    return "<h2>Allowed rise above a neighbour</h2>" + html_table(
        ("distance d (m)", "allowed rise d·tan θ + h (m)"), rows, digits=2)


def classify_report(summary: ClassifySummary, res: "sf.SlopeFilterResult", *,
                    lang: str = "en") -> str:
    """HTML report of :func:`classify_file`."""
    st = summary.settings
    n = summary.n_points
    rows = [("ground (2)", summary.n_ground, 100.0 * summary.n_ground / n),
            ("non-ground (1)", summary.n_nonground, 100.0 * summary.n_nonground / n),
            ("low outliers (7)", summary.n_noise, 100.0 * summary.n_noise / n)]
    if summary.n_not_last:
        rows.append(("  of which non-last returns (1)", summary.n_not_last,
                     100.0 * summary.n_not_last / n))
    if summary.n_input_noise:
        rows.append(("input noise kept (7/18)", summary.n_input_noise,
                     100.0 * summary.n_input_noise / n))
    body = [f"<p>Input: <code>{esc(summary.input)}</code> — {n} points.</p>",
            _method_html(st["radius_m"], st["slope_deg"], st["height_tolerance_m"],
                         st["mode"]),
            "<h2>Result</h2>",
            html_table(("class", "points", "%"), rows, digits=2),
            _rise_table(st["radius_m"], st["slope_deg"], st["height_tolerance_m"]),
            html_params(st, title="Parameters")]
    if summary.n_unknown_returns and st["returns"] == "last":
        body.append(f'<p class="note">{summary.n_unknown_returns} points carry no return '
                    "information (return number or number of returns 0) and were treated "
                    "as single, i.e. last, returns.</p>")
    sec = summary.seconds
    stats = summary.stats
    pts = stats.get("points", 0) or 0
    perf = [("time total (s)", sec.get("total", float("nan"))),
            ("time filter (s)", sec.get("filter", float("nan"))),
            ("filter speed (points/s)", pts / sec["filter"] if sec.get("filter") else
             float("nan")),
            ("points settled by the raster bounds (%)",
             100.0 * stats.get("settled_by_bound", 0) / pts if pts else float("nan")),
            ("exact pair tests", stats.get("pairs_tested", 0)),
            ("grid cell (m)", stats.get("cell_size", float("nan")))]
    body.append("<h2>Computation</h2>" + html_table(("item", "value"), perf, digits=3))
    outs = [(k, v) for k, v in (("classified cloud", summary.output),
                                ("ground cloud", summary.ground_output)) if v]
    if outs:
        body.append("<h2>Outputs</h2>" + html_table(("output", "path"), outs))
    body.append('<p class="note">Reference: Vosselman, G. (2000). Slope based filtering of '
                "laser altimetry data. IAPRS XXXIII-B3, 935–942.</p>")
    return html_page("Ground filter (slope-based)", "\n".join(body), lang=lang)


# ============================================================================ sweep
@dataclass
class SweepSummary:
    """Result of :func:`sweep_file`."""

    result: "sf.SweepResult"
    input: str
    reference: str
    n_points: int
    n_evaluated: int
    csv_output: Optional[str]
    html_output: Optional[str]
    output: Optional[str]
    settings: Dict[str, object]
    seconds: float = 0.0


def _load_reference(src, reference, ground_classes, pd, mon) -> np.ndarray:
    if reference in (None, "", "input"):
        return ground_mask(pd["classification"], ground_classes)
    check_las_file(reference)
    info = las_info(reference)
    if info.count != len(pd):
        raise ValueError(f"The reference cloud {reference} has {info.count} points but the "
                         f"input has {len(pd)}; the reference must hold the same points in "
                         "the same order (or use the input's own classification).")
    ref = read_las(reference, ["classification"], **_cb(mon))
    tol = max(max(info.scales[:2]), max(pd.info.scales[:2]) if pd.info else 0.0, 1e-6)
    if (np.abs(ref.x - pd.x).max() > tol) or (np.abs(ref.y - pd.y).max() > tol):
        raise ValueError(f"The reference cloud {reference} has as many points as the input "
                         "but not the same coordinates in the same order; give the labelled "
                         "copy of the same cloud.")
    return ground_mask(ref["classification"], ground_classes)


def sweep_file(src, *, reference=None, ground_classes: Sequence[int] = (GROUND_CLASS,),
               slopes: Sequence[float] = (30, 35, 40, 44, 48, 52, 56, 60),
               radii: Sequence[float] = (sf.DEFAULT_RADIUS,),
               height_tolerances: Sequence[float] = (sf.DEFAULT_HEIGHT_TOLERANCE,),
               metric: str = "total", returns: str = "all", noise: bool = True,
               noise_radius: float = 5.0, noise_threshold: float = 1.0,
               keep_noise_classes: bool = False, mode: str = "exact",
               trend_cell: float = 10.0, trend_window: float = 60.0, csv_output=None,
               html_output=None, output=None, lang: str = "en", progress=None,
               cancel=None) -> SweepSummary:
    """Threshold sweep of the slope filter on a labelled LAS/LAZ file.

    ``reference`` is ``None``/``"input"`` (the input's own classification, e.g. the
    ISPRS reference samples: class 2 = ground) or the path of a labelled copy of
    the same cloud (same points, same order). The input classification never
    influences the filtering itself. Points excluded from filtering (low
    outliers, non-last returns) count as predicted non-ground. ``output``
    optionally receives the cloud classified with the best setting.
    ``keep_noise_classes`` defaults to False here because the input's classes are
    usually the labels under test.
    """
    t0 = time.perf_counter()
    mon = Monitor(progress, cancel)
    check_las_file(src)
    _check_las_out(output, "The classified output")
    _check_outputs(src, csv_output, html_output, output)
    if reference not in (None, "", "input"):
        _check_outputs(reference, csv_output, html_output, output)
    slopes = [sf._check_slope(s) for s in slopes]
    radii = [sf._check_radius(r) for r in radii]
    hs = [sf._check_height(h) for h in height_tolerances]
    if not slopes or not radii or not hs:
        raise ValueError("Give at least one slope, one radius and one height tolerance.")
    if len(slopes) * len(radii) * len(hs) > 5000:
        raise ValueError("More than 5000 settings requested; narrow the lists.")
    if metric not in sf.SLOPE_METRICS:
        raise ValueError(f"metric must be one of {', '.join(sf.SLOPE_METRICS)}, got "
                         f"{metric!r}.")
    if mode not in sf.MODES:
        raise ValueError(f"mode must be one of {', '.join(sf.MODES)}, got {mode!r}.")
    pd = _read_input(src, returns, mon.sub(0.0, 0.05))
    ref = _load_reference(src, reference, ground_classes, pd, mon.sub(0.05, 0.1))
    if not ref.any():
        raise ValueError(f"The reference marks no point as ground (classes "
                         f"{', '.join(map(str, ground_classes))}); check the reference or "
                         "the ground classes.")
    sel = select_points(pd, returns=returns, noise=noise, noise_radius=noise_radius,
                        noise_threshold=noise_threshold,
                        keep_noise_classes=keep_noise_classes, **_cb(mon.sub(0.1, 0.15)))
    res = sf.threshold_sweep(pd.x, pd.y, pd.z, ref, slopes=slopes, radii=radii,
                             height_tolerance=hs, classify=sel.candidates,
                             neighbours=sel.candidates, mode=mode, metric=metric,
                             trend_cell=trend_cell, trend_window=trend_window,
                             **_cb(mon.sub(0.15, 0.9)))
    settings = dict(slopes_deg=", ".join(fmt(s, 2) for s in slopes),
                    radii_m=", ".join(fmt(r, 2) for r in radii),
                    height_tolerances_m=", ".join(fmt(h, 2) for h in hs),
                    metric=metric, returns=returns, noise_prefilter=bool(noise),
                    noise_radius_m=float(noise_radius),
                    noise_threshold_m=float(noise_threshold), mode=mode,
                    reference="input classification" if reference in (None, "", "input")
                    else os.fspath(reference),
                    ground_classes=", ".join(map(str, ground_classes)))
    summary = SweepSummary(result=res, input=os.fspath(src), reference=settings["reference"],
                           n_points=len(pd),
                           n_evaluated=int(np.count_nonzero(sel.candidates)),
                           csv_output=csv_output and os.fspath(csv_output),
                           html_output=html_output and os.fspath(html_output),
                           output=output and os.fspath(output), settings=settings)
    if output:
        cls = _classes(sel, res.best_ground, pd["classification"])
        write_las_like(src, output, dimensions={"classification": cls},
                       **_cb(mon.sub(0.9, 0.98)))
    if csv_output:
        with atomic_output(csv_output) as tmp:
            with open(tmp, "w", encoding="utf-8", newline="") as fh:
                fh.write(res.to_csv())
    summary.seconds = time.perf_counter() - t0
    if html_output:
        with atomic_output(html_output) as tmp:
            with open(tmp, "w", encoding="utf-8") as fh:
                fh.write(sweep_report(summary, lang=lang))
    mon.update(1.0)
    return summary


_COLOURS = ("#1f5f8b", "#b42318", "#1a7f37", "#9a6700", "#6e40c9", "#444444")


_DASH = {"total": "", "Type I": ' stroke-dasharray="6 3"', "Type II": ' stroke-dasharray="2 3"'}


def svg_lines(series, *, xlabel: str, ylabel: str, title: str = "", width: int = 600,
              height: int = 330) -> str:
    """Multi-line chart as inline SVG.

    ``series`` = [(group label, style, xs, ys), ...]: one colour per group label,
    one dash pattern per style ("total" solid, "Type I" dashed, "Type II" dotted).
    """
    if not series:
        return ""
    xs = np.concatenate([np.asarray(s[2], float) for s in series])
    ys = np.concatenate([np.asarray(s[3], float) for s in series])
    ok = np.isfinite(xs) & np.isfinite(ys)
    if not ok.any():
        return ""
    x0, x1 = float(xs[ok].min()), float(xs[ok].max())
    y0, y1 = 0.0, (float(ys[ok].max()) * 1.08) or 1.0
    if x1 == x0:
        x0, x1 = x0 - 1, x1 + 1
    ml, mr, mt, mb = 50, 160, 24, 40
    pw, ph = width - ml - mr, height - mt - mb

    def px(v):
        return ml + (v - x0) / (x1 - x0) * pw

    def py(v):
        return mt + ph - (v - y0) / (y1 - y0) * ph

    parts = [f'<rect x="{ml}" y="{mt}" width="{pw}" height="{ph}" fill="none" '
             'stroke="#888"/>']
    for k in range(6):
        yv = y0 + (y1 - y0) * k / 5
        parts.append(f'<text x="{ml - 5}" y="{py(yv) + 3:.1f}" font-size="10" '
                     f'text-anchor="end">{yv:.3g}</text>')
    for xv in np.unique(xs[ok])[:: max(1, int(np.unique(xs[ok]).size // 12) + 1)]:
        parts.append(f'<text x="{px(xv):.1f}" y="{mt + ph + 14}" font-size="10" '
                     f'text-anchor="middle">{xv:.4g}</text>')
    groups = list(dict.fromkeys(s[0] for s in series))
    for group, style, sx, sy in series:
        sx, sy = np.asarray(sx, float), np.asarray(sy, float)
        good = np.isfinite(sx) & np.isfinite(sy)
        col = _COLOURS[groups.index(group) % len(_COLOURS)]
        pts = " ".join(f"{px(a):.1f},{py(b):.1f}" for a, b in zip(sx[good], sy[good]))
        parts.append(f'<polyline points="{pts}" fill="none" stroke="{col}" '
                     f'stroke-width="1.8"{_DASH.get(style, "")}/>')
    yk = mt + 12
    for group in groups:
        col = _COLOURS[groups.index(group) % len(_COLOURS)]
        parts.append(f'<text x="{ml + pw + 8}" y="{yk}" font-size="11" fill="{col}">'
                     f"{esc(group)}</text>")
        yk += 15
    yk += 6
    for style, dash in _DASH.items():
        parts.append(f'<line x1="{ml + pw + 8}" y1="{yk - 4}" x2="{ml + pw + 36}" '
                     f'y2="{yk - 4}" stroke="#333" stroke-width="1.8"{dash}/>'
                     f'<text x="{ml + pw + 42}" y="{yk}" font-size="11">{esc(style)}</text>')
        yk += 15
    parts.append(f'<text x="{ml + pw / 2:.0f}" y="{height - 6}" font-size="11" '
                 f'text-anchor="middle">{esc(xlabel)}</text>')
    parts.append(f'<text x="12" y="{mt + ph / 2:.0f}" font-size="11" text-anchor="middle" '
                 f'transform="rotate(-90 12 {mt + ph / 2:.0f})">{esc(ylabel)}</text>')
    if title:
        parts.append(f'<text x="{width / 2:.0f}" y="14" font-size="12" '
                     f'text-anchor="middle">{esc(title)}</text>')
    return (f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
            f'viewBox="0 0 {width} {height}" direction="ltr" role="img">'
            f"<title>{esc(title)}</title>" + "".join(parts) + "</svg>")


def sweep_report(summary: SweepSummary, *, lang: str = "en") -> str:
    """HTML report of :func:`sweep_file`: the table, the best setting and a chart."""
    res = summary.result
    b = res.best
    label = {"total": "lowest total error", "kappa": "highest kappa",
             "type1": "lowest Type I error", "type2": "lowest Type II error"}[res.metric]
    body = [f"<p>Input: <code>{esc(summary.input)}</code> — {summary.n_points} points "
            f"({summary.n_evaluated} filtered; the others — low outliers, non-last returns — "
            f"count as non-ground). Reference: {esc(summary.reference)} "
            f"({res.n_reference_ground} ground points).</p>",
            "<h2>Best setting</h2>",
            f"<p>By {label}: <b>r = {fmt(b.radius, 2)} m, θ = {fmt(b.slope, 2)}°, "
            f"h = {fmt(b.height_tolerance, 2)} m</b> — total {fmt(b.total, 2)} %, "
            f"Type I {fmt(b.type1, 2)} %, Type II {fmt(b.type2, 2)} %, "
            f"kappa {fmt(b.kappa, 1)} %.</p>",
            '<p class="note">Type I = reference ground rejected (b/(a+b)); Type II = objects '
            "accepted as ground (c/(c+d)) — the forest study's \"error\" column, which alone "
            "always favours low thresholds; total = (b+c)/n; kappa = Cohen's kappa "
            "(Sithole &amp; Vosselman 2004).</p>"]
    headers = ("r (m)", "θ (°)", "h (m)", "allowed rise at r (m)", "ground pts", "a", "b",
               "c", "d", "Type I %", "Type II %", "total %", "kappa %")
    rows = []
    for row in res.rows:
        mark = row is b
        cells = [fmt(row.radius, 2), fmt(row.slope, 2), fmt(row.height_tolerance, 2),
                 fmt(row.allowed_rise, 2), row.n_ground, row.a, row.b, row.c, row.d,
                 fmt(row.type1, 2), fmt(row.type2, 2), fmt(row.total, 2), fmt(row.kappa, 1)]
        if mark:
            cells = [f"★ {c}" if i == 0 else c for i, c in enumerate(cells)]
        rows.append(cells)
    body.append("<h2>All settings</h2>" + html_table(headers, rows))
    series = []
    passes = sorted({(r.radius, r.height_tolerance) for r in res.rows})
    for r, h in passes[:len(_COLOURS)]:
        sub = [row for row in res.rows if row.radius == r and row.height_tolerance == h]
        tag = f"r = {r:g} m, h = {h:g} m"
        xs = [row.slope for row in sub]
        series.append((tag, "total", xs, [row.total for row in sub]))
        series.append((tag, "Type I", xs, [row.type1 for row in sub]))
        series.append((tag, "Type II", xs, [row.type2 for row in sub]))
    if len({row.slope for row in res.rows}) > 1:
        body.append(svg_lines(series, xlabel="slope threshold θ (°)", ylabel="error (%)",
                              title="Errors against the threshold"))
        if len(passes) > len(_COLOURS):
            body.append(f'<p class="note">Chart limited to the first {len(_COLOURS)} '
                        "radius/tolerance combinations; the table holds all.</p>")
    body.append(html_params(summary.settings, title="Parameters"))
    body.append(f'<p class="note">Computed in {summary.seconds:.1f} s: one exact '
                "neighbourhood pass per radius and tolerance (per-point required slope), "
                "then one comparison per threshold.</p>")
    return html_page("Slope filter threshold sweep", "\n".join(body), lang=lang)

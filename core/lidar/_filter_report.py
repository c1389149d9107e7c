"""Report content of one ground-filter file run (:func:`.pipeline.classify_file`).

The common part (input, output classes, class map, point selection, parameters,
computation, outputs) plus the method's own sections
(:meth:`~._filter.GroundFilter.report_sections`); rendered by
:func:`~..reporting.render_html` only.
"""
from __future__ import annotations

from ..classes import NAMES as CLASS_NAMES
from ..io.units import units_rows
from ..reporting import KeyValues, Paragraph, Report, T, Table, translator

__all__ = ["filter_report"]


def filter_report(run, algorithm, *, lang: str = "en") -> Report:
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
        *units_rows(run.points.info.units if run.points.info else None)]))
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


def _selection_rows(run) -> list:
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


def _crs_label(pd) -> str:
    from ..io.crs import crs_label
    try:
        return crs_label(pd.info.crs) if pd.info else ""
    except ValueError:
        return str(pd.info.crs)


def _class_map_section(rep: Report, run, tr) -> None:
    """Add the plan-view class map (cell colour = majority class) of the output."""
    from .figures import class_map
    rep.section("Class map").add(class_map(run.points.x, run.points.y, run.classes, tr))

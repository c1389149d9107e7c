"""Content of the GCP rectification / accuracy report (rendered by :mod:`..reporting`).

Every transformation of :mod:`.transforms` is shown side by side by the seed paper's
criteria (Tishreen Univ. J. Eng. Sci. 38(2), 2016; see :mod:`.accuracy`) on the
honest residuals — independent check points, else leave-one-out — with the
recommendation and why, the GCPs dropped by the refinement, each transformation's
parameters, and the criteria C1–C7 of the transformation used with its
residual-vector figure. Every visible string is an English message id translated
from ``i18n/strings/rect2.json``.
"""
from __future__ import annotations

from typing import List, Optional

import numpy as np

from ..reporting import Figure, Formula, KeyValues, Paragraph, Report, T, Table, svg, translator
from .accuracy import CITATION, _crs_name
from .assess import Assessment
from .compare import TIE
from .transforms import KINDS

#: English names of the transformations (message ids)
KIND_NAMES = {"linear": "linear", "helmert": "Helmert", "polynomial1": "polynomial order 1",
              "polynomial2": "polynomial order 2", "polynomial3": "polynomial order 3",
              "projective": "projective", "tps": "thin-plate spline"}
_C4 = {"strict": "pass (strict)", "accepted": "pass", "rejected": "fail", None: "–"}
_VERDICT = {"accepted": "accepted", "rejected": "rejected", "undetermined": "undetermined",
            "accepted (bias warning)": "accepted (bias warning)",
            "rejected (bias warning)": "rejected (bias warning)",
            "not computed": "not computed"}


def _u(text: str, unit: str) -> T:
    """Return a header ``text (unit)`` whose unit is data."""
    return T(text + " ({unit})", unit=unit)


def _mark(ok) -> object:
    return "–" if ok is None else T("pass" if ok else "fail")


def _basis(a: Assessment) -> str:
    return "check points" if a.comparison.basis == "check" else "leave-one-out"


def build_report(a: Assessment, *, extra: Optional[dict] = None, lang: str = "en",
                 title: str = "GCP rectification — accuracy report") -> Report:
    """Build the report of an :class:`~.assess.Assessment`.

    Parameters
    ----------
    a : Assessment
        The evaluated GCP set.
    extra : dict, optional
        ``{English label: value}`` rows added to the set-up table (e.g. the output).
    lang : str
        Language of the text inside the SVG figures.
    title : str
        Report title (a message id).

    Returns
    -------
    Report
    """
    tr = translator(lang)
    rep = Report(title, citation=CITATION)
    rep.summary.extend(_summary(a, tr))
    _setup(rep, a, extra or {})
    _comparison(rep, a, tr)
    _criteria(rep, a)
    _points(rep, a)
    _figure(rep, a, tr)
    _bias(rep, a)
    _dropped(rep, a)
    _orders(rep, a)
    _parameters(rep, a)
    _notes(rep, a)
    return rep


def _summary(a: Assessment, tr) -> List[Paragraph]:
    r = a.selected
    out = [Paragraph(T("Transformation used: {kind}.", kind=tr(KIND_NAMES[a.kind]))),
           Paragraph(T("Verdict of the criteria C4–C6: {verdict}.",
                       verdict=tr(_VERDICT.get(a.verdict, a.verdict))),
                     "ok" if a.verdict.startswith("accepted") else "fail")]
    if a.comparison.recommended:
        best = a.comparison.results[a.comparison.recommended]
        key = ("Recommended: {kind}, the transformation with the fewest parameters whose "
               "check-point RMS_T is within {tie} % of the best ({value} {unit})."
               if a.comparison.basis == "check" else
               "Recommended: {kind}, the transformation with the fewest parameters whose "
               "leave-one-out RMS_T is within {tie} % of the best ({value} {unit}).")
        out.append(Paragraph(T(key, kind=tr(KIND_NAMES[best.kind]), tie=round(100 * TIE),
                               value=_best(a), unit=a.acc.units)))
    else:
        out.append(Paragraph(T("No transformation can be recommended: too few GCPs to "
                               "judge them on independent residuals; add GCPs."), "fail"))
    out.append(Paragraph(T("Never judged by the fit residuals: a thin-plate spline passes "
                           "through every GCP (fit residuals zero)."), "note"))
    if not r.ok:  # pragma: no cover - assess_gcps refuses this
        out.append(Paragraph(T("The transformation used could not be fitted."), "fail"))
    return out


def _best(a: Assessment) -> float:
    basis = a.comparison.basis
    return round(min(r.score(basis) for r in a.comparison.results.values()
                     if r.supported), 4)


def _setup(rep: Report, a: Assessment, extra: dict) -> None:
    g, s, u = a.gcps, a.selected.fit, a.acc.units
    rows = [("GCP source", g.source or "–"), ("CRS", _crs_name(a.acc.crs)),
            ("map units", u), ("transformation", T(KIND_NAMES[a.kind])),
            ("GCPs used in the fit (n)", a.selected.n_gcps),
            ("check points", int(g.check_mask.sum())),
            ("disabled points", int((~g.enabled).sum())),
            ("GR (ground resolution)", round(a.acc.gr, 4), u),
            ("map scale S = 20000·GR", f"1 : {s.scale:.0f}"),
            ("RMS_T band 4·GR … 6·GR", f"{s.band[0]:.3f} … {s.band[1]:.3f}", u),
            ("per-point limit 0.25 mm·S", round(s.point_limit, 3), u)]
    if a.acc.image_size:
        rows.append(("image size", f"{a.acc.image_size[0]} × {a.acc.image_size[1]} px"))
    rows += list(extra.items())
    rep.section("Set-up").add(KeyValues(rows, digits=None))


def _status(a: Assessment, kind: str):
    r = a.comparison.results[kind]
    if not r.ok:
        return T("cannot fit")
    tags = []
    if kind == a.kind:
        tags.append("used")
    if kind == a.comparison.recommended:
        tags.append("recommended")
    if not tags:
        tags.append("supported" if r.supported else "too few GCPs to judge")
    return T(" + ".join(tags))


def _comparison(rep: Report, a: Assessment, tr) -> None:
    c = a.comparison
    u = a.acc.units
    sec = rep.section("Transformations side by side")
    sec.add(Paragraph(T("Judged on the {basis} residuals by the paper's criteria; the fit "
                        "RMS_T is shown for reference only.", basis=tr(_basis(a)))))
    rows = []
    for kind in KINDS:
        if kind not in c.results:
            continue
        r = c.results[kind]
        h = r.check if c.basis == "check" else r.loo
        rows.append([T(KIND_NAMES[kind]), r.n_parameters, r.n_gcps,
                     None if r.fit is None else r.fit.rms_t,
                     None if r.loo is None else r.loo.rms_t,
                     None if r.check is None else r.check.rms_t,
                     T(_C4[None if h is None else h.c4]), _mark(None if h is None else h.c5),
                     _mark(None if h is None else h.c6),
                     T(_VERDICT.get(r.verdict(c.basis), r.verdict(c.basis))),
                     _status(a, kind)])
    sec.add(Table(["transformation", "parameters", "n", _u("fit RMS_T", u),
                   _u("LOO RMS_T", u), _u("check RMS_T", u), "C4", "C5", "C6", "verdict",
                   "status"], rows, digits=4))
    fig = comparison_figure(a, tr)
    if fig:
        sec.add(Figure(fig, "Honest RMS_T of every transformation (lower is better); the "
                            "dashed line is the 6·GR tolerance.", "transform-comparison"))


def comparison_figure(a: Assessment, tr) -> str:
    """SVG bar chart of the honest RMS_T per transformation ('' when none is judged)."""
    c = a.comparison
    kinds = [k for k in KINDS if k in c.results and np.isfinite(c.results[k].score(c.basis))]
    if not kinds:
        return ""
    vals = [c.results[k].score(c.basis) for k in kinds]
    colours = ["#1a7f37" if k == c.recommended else "#1f5f8b" for k in kinds]
    return svg.bar_chart([tr(KIND_NAMES[k]) for k in kinds], vals, colours=colours,
                         unit=a.acc.units, limit=a.selected.fit.band[1],
                         ylabel=tr("check-point RMS_T" if c.basis == "check" else
                                   "leave-one-out RMS_T"))


def _criteria(rep: Report, a: Assessment) -> None:
    r, u = a.selected, a.acc.units
    s = r.fit
    rows = [[T("C2 RMS_x, RMS_y (divisor n)"), f"{s.rms_x:.3f}, {s.rms_y:.3f} {u}", "–"],
            [T("C2 RMS_T (divisor n)"), f"{s.rms_t:.3f} {u} = {s.rms_t / a.acc.gr:.2f} px",
             "–"],
            [T("RMS_T with divisor n − N ({tool})", tool="QGIS Georeferencer"),
             "–" if s.rms_t_qgis is None else f"{s.rms_t_qgis:.3f} {u}", "–"],
            [T("C4 RMS_T within 4·GR … 6·GR"),
             f"{s.rms_t:.3f} / {s.band[0]:.3f} … {s.band[1]:.3f}", T(_C4[s.c4])],
            [T("C5 every RMS_i ≤ 0.25 mm·S"),
             f"{s.largest_rms:.3f} ({s.largest_id}) / {s.point_limit:.3f}", _mark(s.c5)],
            [T("C6 ≥ 68 % of points with RMS_i ≤ RMS_T"),
             f"{s.n_within}/{s.n} = {100 * s.frac_within:.1f} %", _mark(s.c6)],
            [T("C6 strict: ≥ 90 %"), f"{100 * s.frac_within:.1f} %", _mark(s.c6_strict)],
            [T("C7 no directional bias"), len(s.bias["flags"]) if s.bias else "–",
             _mark(s.c7)]]
    for label, h in (("leave-one-out RMS_T", r.loo), ("independent check points RMS_T",
                                                       r.check)):
        rows.append([T(label), "–" if h is None else f"{h.rms_t:.3f} {u} (n = {h.n})",
                     "–" if h is None else T(_C4[h.c4])])
    sec = rep.section("Criteria of the transformation used (fit residuals)")
    sec.add(Table(["criterion", "value", "result"], rows))
    if a.kind == "tps":
        sec.add(Paragraph(T("The thin-plate spline passes through every GCP: its fit "
                            "residuals are zero and only the leave-one-out and check-point "
                            "rows judge it."), "note"))


def _points(rep: Report, a: Assessment) -> None:
    r, u, g = a.selected, a.acc.units, a.gcps
    s, lo = r.fit, r.loo
    pix = g.pixel[g.fit_mask]
    rows = [[pid, pix[k, 0], pix[k, 1], s.vx[k], s.vy[k], s.rms_i[k], s.c_i[k],
             None if lo is None else lo.rms_i[k],
             T("yes" if s.within[k] else "no"), T("yes" if not s.over_limit[k] else "no")]
            for k, pid in enumerate(s.ids)]
    sec = rep.section("Residuals of the GCPs")
    sec.add(Table(["id", "col", "row", _u("v_x", u), _u("v_y", u), _u("RMS_i", u),
                   "C_i", _u("LOO |v|", u), "≤ RMS_T", "≤ limit"], rows))
    if r.check is not None:
        c = r.check
        cpix = g.pixel[g.check_mask]
        crow = [[pid, cpix[k, 0], cpix[k, 1], c.vx[k], c.vy[k], c.rms_i[k]]
                for k, pid in enumerate(c.ids)]
        sec.add(Table(["id", "col", "row", _u("v_x", u), _u("v_y", u), _u("|v|", u)],
                      crow,
                      caption="Independent check points (not used in the fit)"))


def _figure(rep: Report, a: Assessment, tr) -> None:
    r, g = a.selected, a.gcps
    honest = a.kind == "tps" and r.loo is not None
    s = r.loo if honest else r.fit
    xy = g.map[g.fit_mask]
    vx, vy, labels = s.vx, s.vy, list(s.ids)
    if r.check is not None:
        xy = np.vstack([xy, g.map[g.check_mask]])
        vx, vy = np.concatenate([vx, r.check.vx]), np.concatenate([vy, r.check.vy])
        labels += [f"{i}*" for i in r.check.ids]
    frame = None
    if a.acc.image_size:
        w, h = a.acc.image_size
        t = np.linspace(0.0, 1.0, 11)
        cols = np.concatenate([t * w, np.full_like(t, w), (1 - t) * w, np.zeros_like(t)])
        rows = np.concatenate([np.zeros_like(t), t * h, np.full_like(t, h), (1 - t) * h])
        fx, fy = r.transform.forward(cols, rows)
        frame = np.column_stack([fx, fy])
    fig = svg.vector_plot(xy[:, 0], xy[:, 1], vx, vy, labels=labels, frame=frame,
                          unit=a.acc.units, xlabel=tr("map X"), ylabel=tr("map Y"))
    cap = ("Leave-one-out residual vectors at the GCPs (the spline's fit residuals are "
           "zero); check points marked '*'; grey outline: the image footprint."
           if honest else
           "Residual vectors v = predicted − given at the GCPs, exaggerated by the printed "
           "factor; check points marked '*'; grey outline: the image footprint.")
    rep.section("Residual vectors over the image footprint").add(
        Figure(fig, cap, "residual-vectors"))


def _bias(rep: Report, a: Assessment) -> None:
    s, u = a.selected.fit, a.acc.units
    if not s.bias or a.kind == "tps":
        return
    rows = [[T(q["quadrant"]), q["n"], f"{q['vx_pos']}/{q['vx_neg']}",
             f"{q['vy_pos']}/{q['vy_neg']}", q["mean_vx"], q["mean_vy"],
             T("flagged") if q["flag"] else "–"] for q in s.bias["quadrants"]]
    sec = rep.section("C7 bias checks")
    sec.add(Table(["quadrant", "n", "v_x +/−", "v_y +/−", _u("mean v_x", u),
                   _u("mean v_y", u), "flag"], rows))
    rad = s.bias.get("radial") or {}
    if "mean_inner" in rad:
        sec.add(Paragraph(T("Mean radial residual (positive = away from the image centre): "
                            "inner {inner} {unit} (n = {n_inner}), edge {edge} {unit} "
                            "(n = {n_edge}).", inner=round(rad["mean_inner"], 3), unit=u,
                            n_inner=rad["n_inner"], edge=round(rad["mean_edge"], 3),
                            n_edge=rad["n_edge"])))
    for ax in ("v_x", "v_y"):
        sg = s.bias["signs"][ax]
        if sg["p_value"] < 0.05:
            sec.add(Paragraph(T("{axis} signs unbalanced: {pos} positive, {neg} negative "
                                "(sign test p = {p}).", axis=ax, pos=sg["positive"],
                                neg=sg["negative"], p=round(sg["p_value"], 3)), "fail"))


def _dropped(rep: Report, a: Assessment) -> None:
    u = a.acc.units
    sec = rep.section("GCPs dropped by the refinement")
    if a.tolerance is None:
        sec.add(Paragraph(T("Refinement was not requested (REFINE off).")))
        return
    sec.add(Paragraph(T("Tolerance {tol} {unit}: the worst GCP was dropped and the "
                        "transformation refitted while its residual exceeded it.",
                        tol=round(a.tolerance, 4), unit=u)))
    if not a.dropped:
        sec.add(Paragraph(T("No GCP exceeded the tolerance."), "ok"))
        return
    sec.add(Table(["id", _u("residual", u), "GCPs left"],
                  [[d["id"], d["residual"], d["n_after"]] for d in a.dropped], digits=4))


def _orders(rep: Report, a: Assessment) -> None:
    u, acc = a.acc.units, a.acc
    rows = []
    for t, o in sorted(acc.results.items()):
        if not o.ok:
            rows.append([t, o.n_terms, o.n_gcps, o.redundancy, None, None, None, None, None,
                         "–", T("cannot fit")])
            continue
        s = o.stats
        rows.append([t, o.n_terms, o.n_gcps, o.redundancy, s.rms_t, s.rms_t_qgis, o.loo_rms,
                     None if o.check is None else o.check.rms_t, 100 * s.frac_within,
                     T(_VERDICT.get(s.verdict, s.verdict)),
                     T("recommended" if acc.recommended == t else
                       ("supported" if o.supported else "too few GCPs to judge"))])
    sec = rep.section("Polynomial orders 1, 2, 3 by the paper's criteria (fit residuals)")
    sec.add(Table(["order", "N", "n", "n − N", _u("RMS_T", u), _u("RMS_T n−N", u),
                   _u("LOO RMS_T", u), _u("check RMS_T", u), "% ≤ RMS_T", "verdict",
                   "status"], rows))
    drops = acc.selected.drops
    if drops:
        sec.add(Table(["id", _u("RMS_i", u), _u("RMS_T after", u), "n after"],
                      [[d["id"], d["rms_i"], d["rms_t_after"], d["n_after"]] for d in drops],
                      caption=T("Suggested points to drop for order {order} (over the "
                                "per-point limit, one at a time; check them first).",
                                order=acc.order)))


def _parameters(rep: Report, a: Assessment) -> None:
    sec = rep.section("Parameters of each transformation")
    for kind in KINDS:
        r = a.comparison.results.get(kind)
        if r is None or not r.ok:
            continue
        p = r.transform.parameters()
        if kind in ("linear", "helmert"):
            rows = [(_PARAM_LABELS[k], v) for k, v in p.items()]
            sec.add(KeyValues(rows, caption=T(KIND_NAMES[kind]), digits=None))
        elif kind == "projective":
            m = np.asarray(p["matrix"])
            sec.add(Table(["", "col", "row", "1"], [[n] + list(m[i]) for i, n in
                                                      enumerate(("X·w", "Y·w", "w"))],
                          caption=T(KIND_NAMES[kind]), digits=None))
        elif kind.startswith("polynomial"):
            terms = r.transform.model.as_dict()["terms"]
            sec.add(Table(["term", "X", "Y"],
                          [[t, x, y] for t, x, y in zip(terms, p["coefficients_X"],
                                                         p["coefficients_Y"])],
                          caption=T(KIND_NAMES[kind]), digits=None))
        else:
            sec.add(KeyValues([("control points", p["control_points"])],
                              caption=T(KIND_NAMES[kind])))
    sec.add(Formula("Helmert: X = shift_X + s·cos θ·col + s·sin θ·row;  "
                    "Y = shift_Y + s·sin θ·col − s·cos θ·row"))


_PARAM_LABELS = {"shift_x": "shift X", "shift_y": "shift Y", "scale_x": "scale X",
                 "scale_y": "scale Y", "scale": "scale", "rotation_deg": "rotation (°)"}


def _notes(rep: Report, a: Assessment) -> None:
    sec = rep.section("Notes")
    for text in ("Pixel convention: GDAL pixel/line, (0, 0) = top-left corner of the image, "
                 "rows grow downwards.",
                 "Residuals v = predicted − given (map units).",
                 T("RMS_T uses the divisor n (paper); the {tool} divides by n − N.",
                   tool="QGIS Georeferencer"),
                 "C6: for normally distributed residuals only about 63 % of the points are "
                 "expected within RMS_T, so the 68 % rule fails about half of the time by "
                 "chance alone; read it together with C4, C5 and the check points."):
        sec.add(Paragraph(text, "note"))
    if not a.gcps.check_mask.any():
        sec.add(Paragraph("No independent check points (role 'check'): the transformations "
                          "are judged on leave-one-out residuals.", "note"))

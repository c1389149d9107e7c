"""Ground-filter accuracy of two LAS/LAZ files (the runner of :mod:`.accuracy`).

Reads the classified cloud and the reference (another cloud, or another dimension of
the same one), checks they hold the same points in the same CRS, and measures the
Type I / Type II / total error and kappa with :func:`.accuracy.assess` (Sithole &
Vosselman 2004); :func:`accuracy_report` builds the report content. The measures
themselves (:mod:`.accuracy`) read no file.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Optional, Sequence

import numpy as np

from ..errors import InputError
from ..io.points import parse_classes as _parse_classes
from .accuracy import GROUND, FilterAccuracy, assess, error_codes, ground_mask


def parse_classes(text, *, name: str = "ground classes") -> tuple:
    """Parse a non-empty class list (the project's one parser, :func:`..io.points.parse_classes`).

    >>> parse_classes("2, 8 11")
    (2, 8, 11)
    """
    return _parse_classes(text, name=name, allow_empty=False)


@dataclass(frozen=True)
class CloudAssessment:
    """Result of :func:`assess_clouds`."""

    accuracy: FilterAccuracy
    predicted_ground: np.ndarray
    reference_ground: np.ndarray
    classes: dict          # filtered class value -> (reference ground, reference object)
    x: Optional[np.ndarray] = field(default=None, repr=False)   # for the error map
    y: Optional[np.ndarray] = field(default=None, repr=False)

    def error_codes(self) -> np.ndarray:
        """Per point: 0 correct, 1 Type I, 2 Type II."""
        return error_codes(self.predicted_ground, self.reference_ground)


def _check_pair(classified, reference) -> None:
    """Refuse a reference cloud in another CRS (compared by meaning, both named).

    The same file as both is allowed: a reference assessed against itself is the
    sanity check of a scoring setup (total error 0).
    """
    import os

    from ..errors import InputError
    from ..io.crs import crs_label, same_crs
    from ..io.las import las_info
    a, b = las_info(classified), las_info(reference)
    if a.crs and b.crs and not same_crs(a.crs, b.crs):
        raise InputError("The classified cloud {a} is in {crs_a} but the reference cloud "
                         "{b} is in {crs_b}; give two files of the same points.",
                         a=os.path.basename(os.fspath(classified)), crs_a=crs_label(a.crs),
                         b=os.path.basename(os.fspath(reference)), crs_b=crs_label(b.crs))


def assess_clouds(classified, reference=None, *, field: str = "classification",
                  ground_classes=(GROUND,), reference_field: str = "classification",
                  reference_ground_classes=(GROUND,), xy_tolerance: float | None = None,
                  progress=None, cancel=None) -> CloudAssessment:
    """Assess a classified LAS/LAZ cloud against reference labels (Sithole & Vosselman 2004).

    Parameters
    ----------
    classified : path
        The filtered cloud.
    reference : path, optional
        A reference cloud holding the same points in the same order (e.g. the
        ISPRS reference sample). When omitted, ``reference_field`` is read from
        ``classified`` itself (e.g. a second, classification-like dimension).
    field, reference_field : str
        Dimensions holding the filtered and the reference classes (any laspy
        dimension name: ``classification``, ``user_data``, an extra dimension...).
    ground_classes, reference_ground_classes : sequence of int
        Class values that mean "ground" (default ASPRS 2).
    xy_tolerance : float, optional
        Metres. With a reference cloud, the x/y of the two clouds must agree within
        this (default: twice the coarser of the two files' scales), which catches
        clouds of the same length but in a different order.
    progress, cancel : callable, optional

    Returns
    -------
    CloudAssessment

    Raises
    ------
    ValueError
        Unreadable files, missing dimensions, clouds of different length or
        order, or the same dimension given as both labels.
    """
    from ..io.las import read_las
    from ..progress import Monitor
    mon = Monitor(progress, cancel)
    ground_classes = parse_classes(ground_classes)
    reference_ground_classes = parse_classes(reference_ground_classes,
                                             name="reference ground classes")
    if reference is None or str(reference) == "":
        if reference_field == field:
            raise InputError(
                "Without a reference cloud the reference labels must come from another "
                "dimension of the classified cloud, but both are '{field}'. Give a "
                "reference cloud, or the name of the reference dimension.", field=field)
        pd = read_las(classified, (field, reference_field), progress=mon.sub(0, .9).update,
                      cancel=cancel)
        pred, ref = pd[field], pd[reference_field]
    else:
        _check_pair(classified, reference)
        pd = read_las(classified, (field,), progress=mon.sub(0, .45).update, cancel=cancel)
        rd = read_las(reference, (reference_field,), progress=mon.sub(.45, .9).update,
                      cancel=cancel)
        if len(rd) != len(pd):
            raise InputError(
                "The classified cloud has {n} points but the reference cloud has "
                "{m}; both must hold the same points in the same order (filter the "
                "reference file itself, do not thin or merge it).", n=len(pd), m=len(rd))
        tol = xy_tolerance
        if tol is None:
            tol = 2.0 * max(max(pd.info.scales[:2]), max(rd.info.scales[:2]))
        dxy = max(float(np.max(np.abs(pd.x - rd.x))), float(np.max(np.abs(pd.y - rd.y))))
        if dxy > tol:
            raise InputError(
                "The classified and reference clouds have the same number of points but "
                "their coordinates differ by up to {dxy} m (tolerance {tol} m): "
                "they are not the same points in the same order.", dxy=f"{dxy:.3f}",
                tol=f"{tol:.3f}")
        pred, ref = pd[field], rd[reference_field]
    mon.check()
    p = ground_mask(pred, ground_classes)
    r = ground_mask(ref, reference_ground_classes)
    acc = assess(p, r)
    vals, inv = np.unique(np.asarray(pred), return_inverse=True)
    rg = np.bincount(inv, weights=r, minlength=vals.size).astype(np.int64)
    tot = np.bincount(inv, minlength=vals.size)
    classes = {int(v): (int(g), int(t - g)) for v, g, t in zip(vals, rg, tot)}
    mon.update(1.0)
    return CloudAssessment(acc, p, r, classes, pd.x, pd.y)


# ----------------------------------------------------------------------------- report
CITATION = ("Measures of the ISPRS filter test: {ref}",
            "Sithole, G. & Vosselman, G. (2004), ISPRS J. Photogramm. Remote Sens. 59(1-2), "
            "85-101.")


@dataclass(frozen=True)
class AssessmentInputs:
    """What :func:`assess_clouds` compared (shown in the report)."""

    classified: str
    reference: Optional[str]
    field: str = "classification"
    reference_field: str = "classification"
    ground_classes: Sequence[int] = (GROUND,)
    reference_ground_classes: Sequence[int] = (GROUND,)


def accuracy_report(res: CloudAssessment, inputs: AssessmentInputs, *,
                    lang: str = "en"):
    """Build the filter-accuracy report (Sithole & Vosselman 2004 measures).

    Parameters
    ----------
    res : CloudAssessment
        The comparison (:func:`assess_clouds`).
    inputs : AssessmentInputs
        The files, dimensions and ground classes compared.
    lang : str
        Language of the text drawn in the error map.

    Returns
    -------
    Report
        Inputs, cross matrix, errors, error map (when coordinates are known) and the
        reference labels of every filtered class.
    """
    from ..reporting import KeyValues, Paragraph, Report, T, Table, translator
    a = res.accuracy
    rep = Report("Ground filter accuracy", citation=T(CITATION[0], ref=CITATION[1]))
    rep.summary.append(Paragraph(T(
        "Type I {t1} %, Type II {t2} %, total {tot} %, kappa {k} % over {n} points.",
        t1=_r2(a.type1), t2=_r2(a.type2), tot=_r2(a.total), k=_r2(a.kappa), n=a.n)))
    rep.section("Inputs").add(KeyValues(_input_rows(inputs)))
    rep.section("Cross matrix (points)").add(Table(
        ["", "filtered ground", "filtered object", "total"],
        [(T("reference ground"), a.a, a.b, a.a + a.b),
         (T("reference object"), a.c, a.d, a.c + a.d),
         (T("total"), a.a + a.c, a.b + a.d, a.n)], digits=0))
    share = np.array([a.b, a.c], float) / max(a.b + a.c, 1) * 100
    rep.section("Errors (%)").add(KeyValues([
        ("Type I (ground rejected) = b/(a+b)", a.type1),
        ("Type II (object accepted) = c/(c+d)", a.type2),
        ("Total = (b+c)/n", a.total), ("Cohen's kappa", a.kappa)], digits=2)).add(
        Paragraph(T("Of all misclassified points, {p1} % are Type I and {p2} % Type II.",
                    p1=round(float(share[0]), 1), p2=round(float(share[1]), 1)), "note"))
    if res.x is not None and a.n:
        from .figures import error_map
        rep.section("Error map").add(error_map(res.x, res.y, res.error_codes(),
                                               translator(lang)))
    rep.section("Reference labels of every filtered class").add(Table(
        ["filtered class", "reference ground", "reference object", "points"],
        [(k, g, o, g + o) for k, (g, o) in sorted(res.classes.items())], digits=0))
    return rep


def _r2(v: float) -> float:
    return round(float(v), 2) if np.isfinite(v) else v


def _input_rows(inputs: AssessmentInputs) -> list:
    from ..reporting import T
    return [("filtered cloud", inputs.classified), ("its class dimension", inputs.field),
            ("its ground classes", ", ".join(map(str, inputs.ground_classes))),
            ("reference", inputs.reference or T("(dimension of the filtered cloud)")),
            ("reference class dimension", inputs.reference_field),
            ("reference ground classes",
             ", ".join(map(str, inputs.reference_ground_classes)))]

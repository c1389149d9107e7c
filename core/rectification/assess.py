"""One assessment of a GCP set: refinement, the polynomial criteria and every transformation.

Glue between :mod:`.accuracy` (the seed paper's criteria C1–C7 for polynomial orders
1–3; Tishreen Univ. J. Eng. Sci. 38(2), 2016) and :mod:`.compare` (every
transformation of :mod:`.transforms` judged on leave-one-out and check-point
residuals). Outlier removal follows ``gdalwarp -refine_gcps``: the worst GCP is
dropped while its residual exceeds the tolerance (default the C5 limit ``5·GR``).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import List, Optional, Sequence

import numpy as np

from ..errors import InputError
from ..io.gcp import GCPSet
from ..progress import Monitor
from .accuracy import GcpAccuracy, evaluate_gcps
from .compare import Comparison, TransformResult, c5_limit, compare_transforms, refine_gcps
from .transforms import KINDS, MIN_POINTS, fit_transform

#: the transformation choice that lets the comparison decide
RECOMMENDED = "recommended"


@dataclass
class Assessment:
    """A GCP set judged for one transformation, with every other one side by side.

    Attributes
    ----------
    acc : GcpAccuracy
        The polynomial evaluation (orders 1–3 and the paper's criteria) of the GCPs kept.
    comparison : Comparison
        Every transformation on the GCPs kept (check / leave-one-out residuals).
    kind : str
        The transformation used (one of :data:`~.transforms.KINDS`).
    requested : str
        What was asked: a kind or :data:`RECOMMENDED`.
    dropped : list of dict
        GCPs removed by the refinement (``id``, ``residual``, ``n_after``), in order.
    tolerance : float or None
        Refinement tolerance (map units) when refinement ran.
    """

    acc: GcpAccuracy
    comparison: Comparison
    kind: str
    requested: str
    dropped: List[dict] = field(default_factory=list)
    tolerance: Optional[float] = None
    min_gcps: Optional[int] = None

    @property
    def gcps(self) -> GCPSet:
        """Return the GCP set after refinement (dropped points disabled)."""
        return self.acc.gcps

    @property
    def selected(self) -> TransformResult:
        """Return the evaluation of the transformation used."""
        return self.comparison.results[self.kind]

    @property
    def is_polynomial(self) -> bool:
        """Return True when the transformation used is a polynomial."""
        return self.kind.startswith("polynomial")

    @property
    def verdict(self) -> str:
        """Return the criteria's verdict.

        Polynomials: on the fit residuals (the paper). Other transformations: on the
        honest residuals (check points, else leave-one-out), since a thin-plate
        spline's fit residuals are zero.
        """
        if self.is_polynomial:
            return self.acc.results[int(self.kind[-1])].stats.verdict
        return self.selected.verdict(self.comparison.basis)

    def summary_numbers(self) -> dict:
        """Return the flat numbers of the Processing outputs (NaN when not available)."""
        out = self.acc.summary_numbers() if self.is_polynomial else self._numbers()
        out["N_DROPPED"] = len(self.dropped)
        r = self.selected
        out["HONEST_RMS_T"] = r.score(self.comparison.basis) if r.ok else float("nan")
        return out

    def _numbers(self) -> dict:
        nan = float("nan")
        r = self.selected
        s, loo, c = r.fit, r.loo, r.check
        return {
            "RMS_X": s.rms_x, "RMS_Y": s.rms_y, "RMS_T": s.rms_t,
            "RMS_T_QGIS": nan if s.rms_t_qgis is None else s.rms_t_qgis,
            "GR": self.acc.gr, "SCALE": s.scale, "N_GCP": r.n_gcps,
            "REDUNDANCY": r.n_gcps - r.n_parameters // 2 if self.kind != "tps" else 0,
            "N_WITHIN": s.n_within, "LOO_RMS_T": nan if loo is None else loo.rms_t,
            "CHECK_RMS_T": nan if c is None else c.rms_t, "N_CHECK": 0 if c is None else c.n,
            "RECOMMENDED_ORDER": self.acc.recommended or 0,
            "ACCEPTED": 1 if self.verdict.startswith("accepted") else 0,
        }


def affine_gr(gcps: GCPSet) -> float:
    """Return the ground resolution ``sqrt|det J|`` of the affine fit of the GCPs."""
    m = gcps.fit_mask
    t = fit_transform("polynomial1", gcps.pixel[m], gcps.map[m])
    gr = t.model.pixel_size()
    if not (np.isfinite(gr) and gr > 0):
        raise InputError("The GCP map coordinates do not span an area (they are identical "
                         "or lie on one line), so no ground resolution follows from them; "
                         "check the map X and Y columns of the GCP file.")
    return float(gr)


def _refined(gcps: GCPSet, kind: str, tolerance: float, min_gcps: Optional[int]):
    fit = gcps.fit_mask
    idx = np.flatnonzero(fit)
    if min_gcps is not None and min_gcps < MIN_POINTS[kind]:
        raise InputError("MIN_GCPS = {min_gcps} is below the {need} GCPs the "
                         "{kind} transformation needs; raise it or leave it empty.",
                         min_gcps=min_gcps,
                         need=MIN_POINTS[kind],
                         kind=kind)
    keep, dropped = refine_gcps(kind, gcps.pixel[fit], gcps.map[fit],
                                [gcps.ids[i] for i in idx], tolerance=tolerance,
                                min_count=min_gcps)
    out = gcps.with_crs(gcps.crs)
    out.enabled[idx[~keep]] = False
    if dropped:
        out.notes.append(f"Refinement dropped {len(dropped)} GCP(s) whose residual exceeded "
                         f"{tolerance:.4g} map units: "
                         + ", ".join(d["id"] for d in dropped) + ".")
    return out, dropped


def assess_gcps(gcps: GCPSet, *, kind: str = "polynomial2", order: Optional[int] = None,
                gr: Optional[float] = None, image_size: Optional[Sequence[int]] = None,
                units: str = "m", refine: bool = False, tolerance: Optional[float] = None,
                min_gcps: Optional[int] = None, kinds: Sequence[str] = KINDS,
                progress=None, cancel=None) -> Assessment:
    """Refine (optionally), evaluate and compare a GCP set for transformation ``kind``.

    Parameters
    ----------
    gcps : GCPSet
        Enabled role-'gcp' points are fitted; role-'check' points only judge.
    kind : str
        One of :data:`~.transforms.KINDS` or :data:`RECOMMENDED` (the transformation
        with the lowest check-point / leave-one-out error, see
        :func:`~.compare.compare_transforms`).
    order : int, optional
        Polynomial order judged by the paper's criteria when ``kind`` is not a
        polynomial (default: the recommended order, else 1).
    gr : float, optional
        Ground resolution (map units per pixel); default ``sqrt|det J|`` of the affine fit.
    image_size : (width, height), optional
        Image size in pixels (bias checks, plot footprint, coverage).
    units : str
        Map unit name for the report.
    refine : bool
        Drop the worst GCP while its residual exceeds ``tolerance`` (``-refine_gcps``).
    tolerance : float, optional
        Refinement tolerance in map units (default the C5 limit ``5·GR``).
    min_gcps : int, optional
        Refinement stops at this many GCPs (default the transformation's minimum + 2).
    kinds : sequence of str
        Transformations compared.
    progress, cancel : callable, optional
        Progress and cancel callbacks (:class:`~..progress.Monitor`).

    Returns
    -------
    Assessment
    """
    mon = Monitor(progress, cancel)
    if kind != RECOMMENDED and kind not in KINDS:
        raise InputError("Unknown transformation {kind!r}; use one of "
                         "{choices} or {recommended}.",
                         kind=kind,
                         choices=', '.join(KINDS),
                         recommended=RECOMMENDED)
    if int(gcps.fit_mask.sum()) < 2:
        raise InputError("Only {n} enabled GCPs (role 'gcp'); every "
                         "transformation needs at least 2 (linear, Helmert) or 3.",
                         n=int(gcps.fit_mask.sum()))
    gr = affine_gr(gcps) if gr is None else float(gr)
    kinds = tuple(dict.fromkeys(list(kinds) + ([kind] if kind in KINDS else [])))
    requested = kind
    if kind == RECOMMENDED:
        first = compare_transforms(gcps, kinds=kinds, gr=gr, image_size=image_size)
        if first.recommended is None:
            raise InputError("No transformation can be recommended: no transformation "
                             "has enough GCPs to be judged on independent residuals; add "
                             "GCPs.")
        kind = first.recommended
    mon.step(0.2)
    dropped, tol = [], None
    if refine:
        tol = c5_limit(gr) if tolerance is None else float(tolerance)
        gcps, dropped = _refined(gcps, kind, tol, min_gcps)
    mon.step(0.3)
    cmp_ = compare_transforms(gcps, kinds=kinds, gr=gr, image_size=image_size)
    if not cmp_.results[kind].ok:
        raise cmp_.results[kind].failure      # the fit's own (translatable) InputError
    mon.step(0.6)
    poly = int(kind[-1]) if kind.startswith("polynomial") else None
    if poly is None:
        poly = order if order in (1, 2, 3) and gcps.fit_mask.sum() >= MIN_POINTS[
            f"polynomial{order}"] else 1
    sub = mon.sub(0.6, 1.0)
    acc = evaluate_gcps(gcps, order=poly, gr=gr, image_size=image_size, units=units,
                        progress=sub.update, cancel=cancel)
    return Assessment(acc, cmp_, kind, requested, dropped, tol, min_gcps)


def honest_label(basis: str) -> str:
    """Return the English name of the residuals a comparison is judged on."""
    return "check points" if basis == "check" else "leave-one-out"


def finite(v) -> Optional[float]:
    """Return ``v`` as a float, or None when it is missing or not finite."""
    return None if v is None or not math.isfinite(float(v)) else float(v)

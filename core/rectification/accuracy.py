"""Accuracy report of a GCP polynomial rectification (criteria C1–C7 of the seed paper).

Criteria (Tishreen Univ. J. Eng. Sci. 38(2), 2016; residuals ``v = predicted − given``
in map units, ``n`` GCPs, ``N`` coefficients per axis):

* C1 per-point ``RMS_i = sqrt(v_xi² + v_yi²)``;
* C2 total ``RMS_T = sqrt(Σ(v_xi² + v_yi²)/n)`` (divisor ``n``, as in the paper's
  tables), with ``RMS_x``, ``RMS_y``. The QGIS Georeferencer's "mean error"
  (``QgsGeoreferencerMainWindow::calculateMeanError``) divides by ``n − N`` instead:
  ``sqrt(Σ(v_xi² + v_yi²)/(n − N))`` — reported as well, labelled;
* C3 contribution ``C_i = RMS_i / RMS_T``;
* C4 tolerance from the ground resolution ``GR``: map scale ``S = 20000·GR`` (a
  0.25 mm map element seen over 5 pixels) and the analogue rule ``RMS_T ≤
  (0.2…0.3 mm)·S`` become the band ``4·GR … 6·GR``: ``RMS_T ≤ 4·GR`` meets the strict
  end, ``≤ 6·GR`` is accepted, above is rejected;
* C5 per-point limit ``RMS_i ≤ 0.25 mm·S = 5·GR``;
* C6 distribution: at least 68 % (strict variant 90 %) of the points have
  ``RMS_i ≤ RMS_T``;
* C7 no directional bias: sign balance of ``v_x``, ``v_y`` per image quadrant,
  inner vs edge mean radial residual, and a residual-vector plot.

Beyond the paper: independent check points (never used in the fit), leave-one-out
residuals of every GCP, all three orders side by side with a recommended order
(never one the redundancy cannot support) and suggested points to drop.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Sequence

import numpy as np

from ..errors import InputError
from ..io.crs import crs_label
from ..io.gcp import GCPSet
from ..progress import Monitor
from .polynomial import (
    MAX_CONDITION,
    IllConditionedError,
    PolynomialModel,
    fit_polynomial,
    leave_one_out,
    n_terms,
    residuals,
)
from .residuals import (  # noqa: F401 - re-exported: the accuracy module's public names
    BAND_MM,
    POINT_LIMIT_MM,
    RULE_68,
    RULE_90,
    SCALE_FACTOR,
    ResidualStats,
    bias_checks,
    evaluate_residuals,
)

CITATION = ("Criteria after: Tishreen University Journal for Research and Scientific Studies "
            "— Engineering Sciences Series 38(2), 2016, 'criteria to judge the geometric "
            "correction of satellite images by 2-D polynomials'.")



def min_redundancy(order: int) -> int:
    """Return the redundancy ``n − N`` needed before an order is *recommended*.

    ``max(2, ⌈N/2⌉)``: order 1 needs n ≥ 5, order 2 n ≥ 9, order 3 n ≥ 15.
    """
    return max(2, math.ceil(n_terms(order) / 2))


@dataclass
class OrderResult:
    """Evaluation of one polynomial order on a GCP set."""

    order: int
    n_terms: int
    n_gcps: int
    model: Optional[PolynomialModel] = None
    error: Optional[str] = None
    failure: Optional[Exception] = None     # the fit's own (translatable) error
    stats: Optional[ResidualStats] = None
    pixel_res: Optional[np.ndarray] = None  # (n, 2) col,row residuals in pixels
    loo: Optional[np.ndarray] = None  # (n, 2) leave-one-out residuals, map units
    loo_rms: Optional[float] = None
    check: Optional[ResidualStats] = None
    check_pixel_res: Optional[np.ndarray] = None
    drops: List[dict] = field(default_factory=list)

    @property
    def ok(self) -> bool:
        """Return True when the order could be fitted."""
        return self.model is not None

    @property
    def redundancy(self) -> int:
        """Return the redundancy ``n − N``."""
        return self.n_gcps - self.n_terms

    @property
    def supported(self) -> bool:
        """The redundancy is at least :func:`min_redundancy`."""
        return self.ok and self.redundancy >= min_redundancy(self.order)

    def as_dict(self) -> dict:
        """Return the evaluation as a JSON-ready dict."""
        d = {"order": self.order, "n_terms_per_axis": self.n_terms, "n_gcps": self.n_gcps,
             "redundancy": self.redundancy, "min_redundancy_to_recommend":
                 min_redundancy(self.order), "supported": self.supported, "error": self.error}
        if self.ok:
            d["model"] = self.model.as_dict()
            d["fit"] = self.stats.as_dict()
            d["pixel_residuals"] = self.pixel_res.tolist()
            d["leave_one_out"] = {"residuals": self.loo.tolist(), "rms_t": self.loo_rms}
            d["check_points"] = None if self.check is None else self.check.as_dict()
            d["suggested_drops"] = self.drops
        return d


@dataclass
class GcpAccuracy:
    """The whole report: the chosen order, all three orders and a recommendation."""

    gcps: GCPSet
    order: int
    gr: Optional[float]
    gr_source: str
    image_size: Optional[tuple]
    results: Dict[int, OrderResult]
    recommended: Optional[int]
    recommendation: str
    crs: str = ""
    units: str = "map units"
    notes: List[str] = field(default_factory=list)

    @property
    def selected(self) -> OrderResult:
        """Return the evaluation of the chosen order."""
        return self.results[self.order]

    @property
    def verdict(self) -> str:
        """Return the verdict of the chosen order."""
        r = self.selected
        return r.stats.verdict if r.ok else "not computed"

    def summary_numbers(self) -> dict:
        """Flat numbers for Processing outputs (NaN when not available)."""
        r = self.selected
        nan = float("nan")
        s = r.stats
        c = r.check
        return {
            "RMS_X": s.rms_x if s else nan, "RMS_Y": s.rms_y if s else nan,
            "RMS_T": s.rms_t if s else nan,
            "RMS_T_QGIS": s.rms_t_qgis if s and s.rms_t_qgis is not None else nan,
            "GR": self.gr if self.gr is not None else nan,
            "SCALE": s.scale if s and s.scale else nan,
            "N_GCP": r.n_gcps, "REDUNDANCY": r.redundancy,
            "N_WITHIN": s.n_within if s else 0,
            "LOO_RMS_T": r.loo_rms if r.loo_rms is not None else nan,
            "CHECK_RMS_T": c.rms_t if c else nan,
            "N_CHECK": c.n if c else 0,
            "RECOMMENDED_ORDER": self.recommended if self.recommended else 0,
            "ACCEPTED": 1 if self.verdict.startswith("accepted") else 0,
        }

    def as_dict(self) -> dict:
        """Return the whole evaluation as a JSON-ready dict."""
        g = self.gcps
        return {
            "title": "GCP polynomial rectification — accuracy report",
            "source": g.source, "crs": self.crs, "units": self.units,
            "order": self.order, "verdict": self.verdict,
            "gr": self.gr, "gr_source": self.gr_source,
            "image_size": list(self.image_size) if self.image_size else None,
            "recommended_order": self.recommended, "recommendation": self.recommendation,
            "conventions": {
                "pixel": "GDAL pixel/line: (0,0) = top-left corner of the top-left pixel, "
                         "rows grow downwards",
                "residual": "v = predicted − given (map units); pixel residual = given "
                            "pixel − inverse(given map point)",
                "rms_t": "sqrt(Σ(vx²+vy²)/n); rms_t_qgis_n_minus_N = sqrt(Σ(vx²+vy²)/(n−N))"
                         " as the QGIS Georeferencer",
            },
            "points": [{"id": i, "col": float(p[0]), "row": float(p[1]), "X": float(m[0]),
                        "Y": float(m[1]), "enabled": bool(e), "role": str(r)}
                       for i, p, m, e, r in zip(g.ids, g.pixel, g.map, g.enabled, g.role)],
            "orders": {str(k): v.as_dict() for k, v in self.results.items()},
            "notes": self.notes + list(g.notes),
            "citation": CITATION,
        }


def _evaluate_order(g: GCPSet, order: int, gr, image_size, *, max_condition,
                    centre_map_from=None) -> OrderResult:
    fit = g.fit_mask
    pix, mp = g.pixel[fit], g.map[fit]
    ids = [i for i, k in zip(g.ids, fit) if k]
    w = None if g.weight is None else g.weight[fit]
    res = OrderResult(order, n_terms(order), int(fit.sum()))
    try:
        model = fit_polynomial(pix, mp, order=order, weights=w, max_condition=max_condition)
    except (ValueError, IllConditionedError) as exc:
        res.error = str(exc)
        res.failure = exc if isinstance(exc, InputError) else InputError(str(exc))
        return res
    res.model = model
    vx, vy = residuals(model, pix, mp)
    centre = None
    if image_size is not None:
        cx, cy = model.forward(np.array([image_size[0] / 2.0]), np.array([image_size[1] / 2.0]))
        centre = (float(cx[0]), float(cy[0]))
    res.stats = evaluate_residuals(vx, vy, ids=ids, gr=gr, n_terms_per_axis=model.n_terms,
                                   pixel=pix, map_xy=mp, image_size=image_size,
                                   centre_map=centre)
    ic, ir = model.inverse(mp[:, 0], mp[:, 1])
    res.pixel_res = np.column_stack([pix[:, 0] - ic, pix[:, 1] - ir])
    lx, ly = leave_one_out(model, pix, mp)
    res.loo = np.column_stack([lx, ly])
    ok = np.isfinite(lx) & np.isfinite(ly)
    res.loo_rms = (math.sqrt(float(np.mean(lx[ok] ** 2 + ly[ok] ** 2)))
                   if ok.all() and model.redundancy > 0 else None)
    chk = g.check_mask
    if chk.any():
        cpix, cmp_ = g.pixel[chk], g.map[chk]
        cvx, cvy = residuals(model, cpix, cmp_)
        res.check = evaluate_residuals(cvx, cvy, ids=[i for i, k in zip(g.ids, chk) if k],
                                       gr=gr)
        cc, cr = model.inverse(cmp_[:, 0], cmp_[:, 1])
        res.check_pixel_res = np.column_stack([cpix[:, 0] - cc, cpix[:, 1] - cr])
    res.drops = _suggest_drops(pix, mp, ids, w, order, gr, max_condition)
    return res


def _suggest_drops(pix, mp, ids, w, order, gr, max_condition) -> List[dict]:
    """Drop the worst point over the C5 limit and refit, one at a time.

    Stops when the redundancy would fall below :func:`min_redundancy` or a quarter of
    the points are dropped.
    """
    if gr is None:
        return []
    limit = POINT_LIMIT_MM * 1e-3 * SCALE_FACTOR * gr
    keep = np.ones(len(ids), bool)
    out = []
    max_drop = len(ids) // 4
    while len(out) < max_drop:
        n = int(keep.sum())
        if n - 1 - n_terms(order) < min_redundancy(order):
            break
        try:
            m = fit_polynomial(pix[keep], mp[keep], order=order,
                               weights=None if w is None else w[keep],
                               max_condition=max_condition)
        except ValueError:
            break
        vx, vy = residuals(m, pix[keep], mp[keep])
        r = np.hypot(vx, vy)
        k = int(np.argmax(r))
        if r[k] <= limit:
            break
        idx = np.flatnonzero(keep)[k]
        keep[idx] = False
        try:
            m2 = fit_polynomial(pix[keep], mp[keep], order=order,
                                weights=None if w is None else w[keep],
                                max_condition=max_condition)
        except ValueError:
            break
        vx2, vy2 = residuals(m2, pix[keep], mp[keep])
        rms2 = math.sqrt(float(np.mean(vx2 ** 2 + vy2 ** 2)))
        out.append({"id": ids[idx], "rms_i": float(r[k]), "rms_t_after": rms2,
                    "n_after": int(keep.sum())})
    return out


def _recommend(results: Dict[int, OrderResult]):
    cands = [r for r in results.values() if r.supported]
    if not cands:
        avail = [r for r in results.values() if r.ok]
        why = ("no order has enough redundancy to be recommended (order t needs "
               "n − N ≥ max(2, ⌈N/2⌉): n ≥ 5, 9, 15 GCPs for orders 1, 2, 3)")
        if avail:
            why += f"; with {avail[0].n_gcps} GCPs add points before trusting any order"
        return None, why
    use_check = all(r.check is not None and r.check.n >= 3 for r in cands)
    key = "check-point RMS_T" if use_check else "leave-one-out RMS_T"

    def score(r):
        v = r.check.rms_t if use_check else r.loo_rms
        return float("inf") if v is None else v

    best = min(score(r) for r in cands)
    pick = min((r for r in cands if score(r) <= 1.10 * best), key=lambda r: r.order)
    parts = [f"order {r.order}: {score(r):.3f}" for r in cands]
    unsupported = [r.order for r in results.values() if r.ok and not r.supported]
    why = (f"order {pick.order}: the lowest supported order whose {key} is within 10 % of "
           f"the best ({'; '.join(parts)})")
    if unsupported:
        why += (f"; order(s) {', '.join(map(str, unsupported))} not considered: redundancy "
                "too small")
    return pick.order, why


#: convex-hull share of the image below which the report warns about extrapolation
MIN_COVERAGE = 0.3


def coverage(pixel: np.ndarray, image_size) -> float:
    """Share of the image area inside the convex hull of the GCP image positions."""
    pts = np.unique(np.asarray(pixel, float), axis=0)
    if len(pts) < 3:
        return 0.0
    try:
        from scipy.spatial import ConvexHull
        area = ConvexHull(pts).volume
    except Exception:  # noqa: BLE001 - degenerate (collinear) hull
        return 0.0
    return float(area / (float(image_size[0]) * float(image_size[1])))


def evaluate_gcps(gcps: GCPSet, *, order: int = 2, gr: Optional[float] = None,
                  image_size: Optional[Sequence[int]] = None, orders=(1, 2, 3),
                  max_condition: float = MAX_CONDITION, units: str = "m", crs: str = "",
                  progress=None, cancel=None) -> GcpAccuracy:
    """Evaluate a GCP set for ``order`` and, side by side, every order of ``orders``.

    Parameters
    ----------
    gcps : GCPSet
        Points (disabled ones ignored; role 'check' kept out of the fit).
    order : {1, 2, 3}
        The order to judge (the one the rectification uses).
    gr : float, optional
        Ground resolution (map units per pixel). Default: the ground pixel size implied
        by the affine (order-1) fit, ``sqrt(|det J|)``.
    image_size : (width, height), optional
        Image size in pixels (quadrants, radial bias, footprint of the plot).
    orders : iterable of int
        Orders compared (always includes ``order``).
    max_condition : float
        Condition-number limit of :func:`~.polynomial.fit_polynomial`.

    Raises
    ------
    ValueError
        When the requested ``order`` cannot be fitted (too few or degenerate GCPs);
        other orders that cannot be fitted are reported as such.
    """
    mon = Monitor(progress, cancel)
    if order not in (1, 2, 3):
        raise InputError("order must be 1, 2 or 3, got {value}.", value=repr(order))
    if gr is not None and not (np.isfinite(gr) and gr > 0):
        raise InputError("GR (ground resolution) must be a positive number, got {value}; "
                         "leave it empty to derive it from the GCPs.", value=repr(gr))
    fit = gcps.fit_mask
    if fit.sum() < 3:
        raise InputError("Only {n} enabled GCPs (role 'gcp'); a polynomial "
                         "needs at least 3 (order 1), 6 (order 2) or 10 (order 3).",
                         n=int(fit.sum()))
    notes = []
    gr_source = "given"
    if gr is None:
        try:
            aff = fit_polynomial(gcps.pixel[fit], gcps.map[fit], order=1,
                                 max_condition=max_condition)
        except ValueError as exc:
            raise InputError("Cannot derive the ground resolution: {error}",
                             error=exc) from None
        gr = aff.pixel_size()
        if not (np.isfinite(gr) and gr > 0):
            raise InputError(
                "The GCP map coordinates do not span an area (they are identical or lie "
                "on one line), so no ground resolution follows from them; check the map "
                "X and Y columns of the GCP file.")
        gr_source = "from the GCPs (affine fit: sqrt|det J|)"
    mon.step(0.05)
    results = {}
    todo = sorted(set(orders) | {order})
    for k, t in enumerate(todo):
        results[t] = _evaluate_order(gcps, t, gr, image_size, max_condition=max_condition)
        mon.step(0.05 + 0.9 * (k + 1) / len(todo))
    if not results[order].ok:
        raise results[order].failure
    rec, why = _recommend(results)
    cov = coverage(gcps.pixel[fit], image_size) if image_size is not None else None
    if cov is not None and cov < MIN_COVERAGE:
        notes.append(f"The GCPs cover only {100 * cov:.0f} % of the image (convex hull): "
                     "outside it the polynomial extrapolates, and orders 2–3 can bend "
                     "strongly there. Add GCPs near the image edges and corners.")
    if gcps.check_mask.sum() == 0:
        notes.append("No independent check points (role 'check'): accuracy is judged on the "
                     "fit residuals and leave-one-out residuals only.")
    mon.update(1.0)
    return GcpAccuracy(gcps, order, float(gr), gr_source,
                       tuple(int(v) for v in image_size) if image_size is not None else None,
                       results, rec, why, crs or gcps.crs, units, notes)


def _crs_name(crs: str) -> str:
    """Return a display label of the CRS (``'unknown'`` when none)."""
    return crs_label(crs) or "unknown"

"""Every transformation judged by the seed paper's criteria on honest residuals.

The criteria C1–C6 of the seed paper (Tishreen Univ. J. Eng. Sci. 38(2), 2016; see
:mod:`.accuracy`) are applied to three residual sets of each transformation of
:mod:`.transforms`, side by side:

* fit residuals (what the Georeferencer shows; zero for the thin-plate spline, so they
  never decide anything here);
* leave-one-out residuals (each GCP predicted by a fit without it);
* independent check points (role 'check', never fitted).

The recommendation uses the check points when there are at least three, else the
leave-one-out residuals — never the fit residuals — and picks, among the supported
transformations within 10 % of the best error, the one with the fewest parameters.
Outlier removal follows ``gdalwarp -refine_gcps``: drop the worst GCP while it exceeds
a tolerance (default the C5 limit ``5·GR``), down to a minimum count.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Sequence

import numpy as np

from ..errors import InputError
from ..io.gcp import GCPSet
from .accuracy import POINT_LIMIT_MM, SCALE_FACTOR, ResidualStats, evaluate_residuals
from .transforms import KINDS, MIN_POINTS, N_PARAMETERS, Transform, fit_transform, loo_residuals

#: share above the best error within which the simplest transformation is preferred
TIE = 0.10
#: redundancy per axis (n − parameters/2) a parametric transformation needs to be
#: recommended
MIN_REDUNDANCY = 2


@dataclass
class TransformResult:
    """One transformation evaluated on a GCP set."""

    kind: str
    n_gcps: int
    transform: Optional[Transform] = None
    #: Why the fit failed (its template is translated when it reaches the user).
    failure: Optional[InputError] = None
    fit: Optional[ResidualStats] = None
    loo: Optional[ResidualStats] = None
    check: Optional[ResidualStats] = None

    @property
    def ok(self) -> bool:
        """True when the transformation could be fitted."""
        return self.transform is not None

    @property
    def error(self) -> Optional[str]:
        """The failure's English message, or None."""
        return None if self.failure is None else str(self.failure)

    @property
    def n_parameters(self) -> int:
        """Parameters of the transformation (thin-plate spline: ``2·(n + 3)``)."""
        return N_PARAMETERS.get(self.kind, 2 * (self.n_gcps + 3))

    @property
    def supported(self) -> bool:
        """Fitted, with honest residuals and enough redundancy to be recommended."""
        if not self.ok or self.loo is None:
            return False
        return self.kind == "tps" or \
            self.n_gcps - self.n_parameters / 2 >= MIN_REDUNDANCY

    def score(self, basis: str) -> float:
        """RMS_T of the check points (``basis='check'``) or of the LOO residuals."""
        s = self.check if basis == "check" else self.loo
        return float("inf") if s is None else s.rms_t

    def verdict(self, basis: str) -> str:
        """Return the criteria's verdict on the honest residuals (check points or LOO)."""
        s = self.check if basis == "check" else self.loo
        return "not computed" if s is None else s.verdict


@dataclass
class Comparison:
    """All transformations side by side with a recommendation."""

    results: Dict[str, TransformResult]
    basis: str
    recommended: Optional[str]
    reason: str
    gr: float
    dropped: List[dict] = field(default_factory=list)

    def ranking(self) -> List[str]:
        """Supported kinds from the lowest to the highest honest error."""
        ok = [r for r in self.results.values() if r.supported]
        return [r.kind for r in sorted(ok, key=lambda r: r.score(self.basis))]


def _evaluate(kind: str, g: GCPSet, gr: float, image_size) -> TransformResult:
    fit = g.fit_mask
    pix, mp = g.pixel[fit], g.map[fit]
    ids = [i for i, k in zip(g.ids, fit) if k]
    res = TransformResult(kind, int(fit.sum()))
    w = None if g.weight is None else g.weight[fit]
    try:
        t = fit_transform(kind, pix, mp, weights=w)
    except InputError as exc:
        res.failure = exc
        return res
    res.transform = t
    vx, vy = t.residuals(pix, mp)
    n_axis = None if kind == "tps" else t.n_parameters // 2
    res.fit = evaluate_residuals(vx, vy, ids=ids, gr=gr, n_terms_per_axis=n_axis, pixel=pix,
                                 map_xy=mp, image_size=image_size)
    lx, ly = loo_residuals(kind, pix, mp, model=t, weights=w)
    okl = np.isfinite(lx) & np.isfinite(ly)
    if okl.all():
        res.loo = evaluate_residuals(lx, ly, ids=ids, gr=gr)
    chk = g.check_mask
    if chk.any():
        cvx, cvy = t.residuals(g.pixel[chk], g.map[chk])
        res.check = evaluate_residuals(cvx, cvy, ids=[i for i, k in zip(g.ids, chk) if k],
                                       gr=gr)
    return res


def _recommend(results: Dict[str, TransformResult], basis: str):
    cands = [r for r in results.values() if r.supported and math.isfinite(r.score(basis))]
    label = "check-point RMS_T" if basis == "check" else "leave-one-out RMS_T"
    if not cands:
        return None, ("no transformation has enough GCPs to be judged on independent "
                      "residuals; add GCPs")
    best = min(r.score(basis) for r in cands)
    near = [r for r in cands if r.score(basis) <= (1 + TIE) * best]
    pick = min(near, key=lambda r: (r.n_parameters, r.score(basis)))
    parts = "; ".join(f"{r.kind}: {r.score(basis):.4g}" for r in
                      sorted(cands, key=lambda r: r.score(basis)))
    return pick.kind, (f"{pick.kind}: the fewest parameters among the transformations "
                       f"whose {label} is within {100 * TIE:.0f} % of the best ({parts})")


def compare_transforms(gcps: GCPSet, *, kinds: Sequence[str] = KINDS, gr: float,
                       image_size=None) -> Comparison:
    """Evaluate every transformation of ``kinds`` on ``gcps`` and recommend one.

    Parameters
    ----------
    gcps : GCPSet
        Enabled role-'gcp' points are fitted; role-'check' points only judge.
    kinds : sequence of str
        Transformations to compare (default all of :data:`~.transforms.KINDS`).
    gr : float
        Ground resolution (map units per pixel) for the criteria C4–C5.
    image_size : (width, height), optional
        For the directional-bias checks (C7) of the fit residuals.

    Returns
    -------
    Comparison
        ``basis`` is 'check' with at least 3 check points, else 'loo'.
    """
    if not (gr is not None and np.isfinite(gr) and gr > 0):
        raise InputError("GR (ground resolution) must be a positive number, got {gr!r}.", gr=gr)
    results = {k: _evaluate(k, gcps, gr, image_size) for k in kinds}
    basis = "check" if int(gcps.check_mask.sum()) >= 3 else "loo"
    rec, why = _recommend(results, basis)
    return Comparison(results, basis, rec, why, float(gr))


def refine_gcps(kind: str, pixel_xy, map_xy, ids, *, tolerance: float,
                min_count: Optional[int] = None):
    """Drop the worst GCP while its residual exceeds ``tolerance`` (``-refine_gcps``).

    Residuals are fit residuals, except for the thin-plate spline (zero at every GCP)
    whose leave-one-out residuals are used. Stops at ``min_count`` points (default the
    transformation's minimum plus 2).

    Returns
    -------
    keep : ndarray of bool
        Points kept.
    dropped : list of dict
        In order: ``id``, ``residual`` (map units), ``n_after``.
    """
    pix, mp = np.asarray(pixel_xy, float), np.asarray(map_xy, float)
    if not (np.isfinite(tolerance) and tolerance > 0):
        raise InputError("The refine tolerance must be a positive distance, got "
                         "{tolerance!r}.", tolerance=tolerance)
    floor = MIN_POINTS[kind] + 2 if min_count is None else int(min_count)
    keep = np.ones(len(pix), bool)
    dropped = []
    while keep.sum() > max(floor, MIN_POINTS[kind]):
        idx = np.flatnonzero(keep)
        if kind == "tps":
            vx, vy = loo_residuals(kind, pix[idx], mp[idx])
        else:
            vx, vy = fit_transform(kind, pix[idx], mp[idx]).residuals(pix[idx], mp[idx])
        r = np.nan_to_num(np.hypot(vx, vy), nan=0.0)
        k = int(np.argmax(r))
        if r[k] <= tolerance:
            break
        keep[idx[k]] = False
        dropped.append({"id": str(ids[idx[k]]), "residual": float(r[k]),
                        "n_after": int(keep.sum())})
    return keep, dropped


def c5_limit(gr: float) -> float:
    """Return the C5 per-point limit ``0.25 mm·S = 5·GR`` (the default tolerance)."""
    return POINT_LIMIT_MM * 1e-3 * SCALE_FACTOR * gr

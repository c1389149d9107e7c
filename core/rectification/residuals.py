"""Residual statistics of a GCP fit: criteria C1–C7 of the seed paper (see :mod:`.accuracy`).

Tishreen Univ. J. Eng. Sci. 38(2), 2016: per-point and total RMS, contributions, the
ground-resolution tolerance band, the per-point limit, the 68 % distribution rule and
the directional-bias checks.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import List, Optional, Sequence

import numpy as np

from ..errors import InputError

#: fraction of points that must have RMS_i ≤ RMS_T (C6) and its strict variant
RULE_68 = 0.68
RULE_90 = 0.90
#: mm on the map of the per-point limit (C5) and the tolerance band (C4)
POINT_LIMIT_MM = 0.25
BAND_MM = (0.2, 0.3)
SCALE_FACTOR = 20000.0


# ---------------------------------------------------------------------- residual stats
@dataclass
class ResidualStats:
    """Criteria C1–C6 (and C7 when positions are known) for one set of residuals."""

    ids: List[str]
    vx: np.ndarray
    vy: np.ndarray
    rms_i: np.ndarray
    c_i: np.ndarray
    rms_x: float
    rms_y: float
    rms_t: float
    n: int
    n_terms: Optional[int]
    rms_t_qgis: Optional[float]
    rms_x_qgis: Optional[float]
    rms_y_qgis: Optional[float]
    gr: Optional[float]
    n_within: int
    largest_id: str
    largest_rms: float
    largest_c: float
    bias: Optional[dict] = None

    # --- derived criteria
    @property
    def frac_within(self) -> float:
        """Return the share of points with RMS_i ≤ RMS_T (C6)."""
        return self.n_within / self.n if self.n else float("nan")

    @property
    def within(self) -> np.ndarray:
        """Return a mask of the points with RMS_i ≤ RMS_T."""
        return self.rms_i <= self.rms_t + 1e-12

    @property
    def scale(self) -> Optional[float]:
        """Map scale number ``S = 20000·GR``."""
        return None if self.gr is None else SCALE_FACTOR * self.gr

    @property
    def band(self):
        """``(4·GR, 6·GR)`` — RMS_T tolerance band (C4)."""
        if self.gr is None:
            return None
        s = self.scale
        return (BAND_MM[0] * 1e-3 * s, BAND_MM[1] * 1e-3 * s)

    @property
    def point_limit(self) -> Optional[float]:
        """``0.25 mm·S = 5·GR`` (C5)."""
        return None if self.gr is None else POINT_LIMIT_MM * 1e-3 * self.scale

    @property
    def over_limit(self) -> np.ndarray:
        """Return a mask of the points over the C5 limit."""
        lim = self.point_limit
        return np.zeros(self.n, bool) if lim is None else self.rms_i > lim

    @property
    def c4(self) -> Optional[str]:
        """'strict' (≤ 4·GR), 'accepted' (≤ 6·GR) or 'rejected'; None without GR."""
        if self.band is None:
            return None
        lo, hi = self.band
        if self.rms_t <= lo:
            return "strict"
        return "accepted" if self.rms_t <= hi else "rejected"

    @property
    def c5(self) -> Optional[bool]:
        """Return True when no point exceeds the C5 limit (None without GR)."""
        return None if self.gr is None else not self.over_limit.any()

    @property
    def c6(self) -> bool:
        """Return True when ≥ 68 % of the points are within RMS_T (C6)."""
        return self.frac_within >= RULE_68

    @property
    def c6_strict(self) -> bool:
        """Return True when ≥ 90 % of the points are within RMS_T."""
        return self.frac_within >= RULE_90

    @property
    def c7(self) -> Optional[bool]:
        """Return True without directional-bias flag (C7; None without positions)."""
        return None if self.bias is None else not self.bias["flags"]

    @property
    def verdict(self) -> str:
        """Return 'accepted' when C4 (≤ 6·GR), C5 and C6 hold, else 'rejected'.

        'undetermined' without GR. A C7 bias flag adds ' (bias warning)'.
        """
        if self.gr is None:
            return "undetermined"
        ok = self.c4 in ("strict", "accepted") and self.c5 and self.c6
        out = "accepted" if ok else "rejected"
        if self.c7 is False:
            out += " (bias warning)"
        return out

    def reasons(self) -> List[str]:
        """Plain-language list of failed criteria."""
        out = []
        if self.gr is not None:
            lo, hi = self.band
            if self.c4 == "rejected":
                out.append(f"C4: RMS_T {self.rms_t:.3f} > 6·GR = {hi:.3f}")
            if not self.c5:
                bad = [i for i, o in zip(self.ids, self.over_limit) if o]
                out.append(f"C5: {len(bad)} point(s) over the point limit "
                           f"{self.point_limit:.3f}: {', '.join(bad)}")
        if not self.c6:
            out.append(f"C6: only {self.n_within}/{self.n} ({100 * self.frac_within:.0f} %) "
                       "points within RMS_T (< 68 %)")
        if self.c7 is False:
            out.extend("C7: " + f for f in self.bias["flags"])
        return out

    def as_dict(self) -> dict:
        """Return the criteria as a JSON-ready dict."""
        d = {
            "n": self.n, "rms_x": self.rms_x, "rms_y": self.rms_y, "rms_t": self.rms_t,
            "divisor": "n",
            "n_terms_per_axis": self.n_terms,
            "rms_t_qgis_n_minus_N": self.rms_t_qgis, "rms_x_qgis_n_minus_N": self.rms_x_qgis,
            "rms_y_qgis_n_minus_N": self.rms_y_qgis,
            "n_within_rms_t": self.n_within, "fraction_within_rms_t": self.frac_within,
            "rule_68": self.c6, "rule_90": self.c6_strict,
            "largest": {"id": self.largest_id, "rms_i": self.largest_rms, "c_i": self.largest_c},
            "gr": self.gr, "scale": self.scale,
            "band": list(self.band) if self.band else None,
            "point_limit": self.point_limit,
            "c4": self.c4, "c5": self.c5, "c6": self.c6, "c7": self.c7,
            "verdict": self.verdict, "reasons": self.reasons(),
            "points": [{"id": i, "vx": float(a), "vy": float(b), "rms_i": float(r),
                        "c_i": float(c), "within_rms_t": bool(w), "over_limit": bool(o)}
                       for i, a, b, r, c, w, o in zip(self.ids, self.vx, self.vy, self.rms_i,
                                                      self.c_i, self.within, self.over_limit)],
            "bias": self.bias,
        }
        return d


def evaluate_residuals(vx, vy, *, ids: Optional[Sequence] = None, gr: Optional[float] = None,
                       n_terms_per_axis: Optional[int] = None,
                       pixel: Optional[np.ndarray] = None,
                       map_xy: Optional[np.ndarray] = None,
                       image_size: Optional[Sequence[int]] = None,
                       centre_map: Optional[Sequence[float]] = None) -> ResidualStats:
    """Criteria C1–C6 (C7 when positions are given) for residuals ``vx, vy``.

    Parameters
    ----------
    vx, vy : array_like (n,)
        Residuals ``predicted − given`` in map units.
    ids : sequence, optional
        Point ids (default '1' … 'n').
    gr : float, optional
        Ground resolution (pixel size on the ground, map units); enables C4, C5.
    n_terms_per_axis : int, optional
        ``N``; enables the QGIS-style RMS with divisor ``n − N``.
    pixel, map_xy, image_size, centre_map : optional
        GCP image positions ``(col, row)``, map positions, image ``(width, height)`` and
        the map position of the image centre, for the bias checks (C7).

    Examples
    --------
    >>> s = evaluate_residuals([1.0, -1.0], [0.0, 0.0], gr=0.5)
    >>> round(s.rms_t, 3), s.c4
    (1.0, 'strict')
    """
    vx = np.asarray(vx, float).ravel()
    vy = np.asarray(vy, float).ravel()
    n = vx.size
    if n == 0 or vy.size != n:
        raise InputError("vx and vy must be non-empty and of equal length.")
    if not (np.isfinite(vx).all() and np.isfinite(vy).all()):
        raise InputError("residuals contain NaN or infinite values.")
    if gr is not None and not (np.isfinite(gr) and gr > 0):
        raise InputError("GR (ground resolution) must be a positive number, got {value}.",
                         value=repr(gr))
    ids = [str(i) for i in (ids if ids is not None else range(1, n + 1))]
    rms_i = np.hypot(vx, vy)
    ssx, ssy = float(np.sum(vx ** 2)), float(np.sum(vy ** 2))
    rms_x, rms_y = math.sqrt(ssx / n), math.sqrt(ssy / n)
    rms_t = math.sqrt((ssx + ssy) / n)
    c_i = rms_i / rms_t if rms_t > 0 else np.zeros(n)
    q_t = q_x = q_y = None
    if n_terms_per_axis is not None and n > n_terms_per_axis:
        dof = n - n_terms_per_axis
        q_t = math.sqrt((ssx + ssy) / dof)
        q_x, q_y = math.sqrt(ssx / dof), math.sqrt(ssy / dof)
    elif n_terms_per_axis is not None and n == n_terms_per_axis:
        q_t = q_x = q_y = 0.0  # QGIS shows 0 when n equals the minimum
    k = int(np.argmax(rms_i))
    s = ResidualStats(ids, vx, vy, rms_i, c_i, rms_x, rms_y, rms_t, n, n_terms_per_axis,
                      q_t, q_x, q_y, None if gr is None else float(gr),
                      int(np.sum(rms_i <= rms_t + 1e-12)), ids[k], float(rms_i[k]),
                      float(c_i[k]))
    if pixel is not None:
        s.bias = bias_checks(vx, vy, np.asarray(pixel, float), map_xy=map_xy,
                             image_size=image_size, centre_map=centre_map)
    return s


def _binom_two_sided(k: int, n: int) -> float:
    """Two-sided sign-test p-value of ``k`` positives among ``n`` (p = 0.5)."""
    if n == 0:
        return 1.0
    from scipy.stats import binomtest
    return float(binomtest(int(k), int(n), 0.5).pvalue)


def bias_checks(vx, vy, pixel, *, map_xy=None, image_size=None, centre_map=None) -> dict:
    """C7: directional bias of residuals over the image.

    * per image quadrant (split at the image centre, or the GCP centroid without an
      image size): counts of positive/negative ``v_x``, ``v_y`` and the mean residual
      vector; a quadrant with ≥ 3 points whose residuals all share one sign on an axis,
      or whose mean exceeds 2 standard errors, is flagged;
    * over all points: two-sided sign test per axis (flag when p < 0.05);
    * inner vs edge: the radial component of each residual (positive = pointing away
      from the image centre, in map space) is averaged over the inner and the outer half
      of the points (split at the median normalised image radius); opposite signs with a
      difference above two standard errors, or a correlation between radius and radial
      residual with |t| > 2.8, are flagged — the "negative inside, positive at the
      edges" pattern that asks for a higher order.
    """
    vx = np.asarray(vx, float)
    vy = np.asarray(vy, float)
    col, row = pixel[:, 0], pixel[:, 1]
    if image_size is not None:
        cc, rc = image_size[0] / 2.0, image_size[1] / 2.0
        hw, hh = image_size[0] / 2.0, image_size[1] / 2.0
    else:
        cc, rc = float(col.mean()), float(row.mean())
        hw = float(np.max(np.abs(col - cc))) or 1.0
        hh = float(np.max(np.abs(row - rc))) or 1.0
    rms = math.sqrt(float(np.mean(vx ** 2 + vy ** 2)) / 2.0) or 1e-30
    flags = []
    quads = []
    names = (("upper-left", (col < cc) & (row < rc)), ("upper-right", (col >= cc) & (row < rc)),
             ("lower-left", (col < cc) & (row >= rc)), ("lower-right", (col >= cc) & (row >= rc)))
    for name, m in names:
        k = int(m.sum())
        q = {"quadrant": name, "n": k,
             "vx_pos": int((vx[m] > 0).sum()), "vx_neg": int((vx[m] < 0).sum()),
             "vy_pos": int((vy[m] > 0).sum()), "vy_neg": int((vy[m] < 0).sum()),
             "mean_vx": float(vx[m].mean()) if k else float("nan"),
             "mean_vy": float(vy[m].mean()) if k else float("nan")}
        q["flag"] = ""
        if k >= 3:
            one_sided = [ax for ax, pos, neg in (("v_x", q["vx_pos"], q["vx_neg"]),
                                                  ("v_y", q["vy_pos"], q["vy_neg"]))
                         if pos == k or neg == k]
            big = [ax for ax, mean in (("v_x", q["mean_vx"]), ("v_y", q["mean_vy"]))
                   if abs(mean) > 2 * rms / math.sqrt(k)]
            why = sorted(set(one_sided) & set(big)) if one_sided else []
            if why:
                q["flag"] = f"{name}: all {', '.join(why)} of one sign and mean beyond 2 SE"
                flags.append(q["flag"])
        quads.append(q)
    signs = {}
    for ax, v in (("v_x", vx), ("v_y", vy)):
        pos, neg = int((v > 0).sum()), int((v < 0).sum())
        p = _binom_two_sided(pos, pos + neg)
        signs[ax] = {"positive": pos, "negative": neg, "p_value": p}
        if p < 0.05:
            flags.append(f"{ax} signs unbalanced ({pos} positive, {neg} negative, "
                         f"sign test p = {p:.3f})")
    radial = None
    if map_xy is not None:
        mxy = np.asarray(map_xy, float)
        c = np.asarray(centre_map, float) if centre_map is not None else mxy.mean(axis=0)
        d = mxy - c
        dist = np.hypot(d[:, 0], d[:, 1])
        with np.errstate(invalid="ignore", divide="ignore"):
            rad = np.where(dist > 0, (vx * d[:, 0] + vy * d[:, 1]) / dist, 0.0)
        # normalised image radius: 0 at the centre, 1 at the corners
        rnorm = np.hypot((col - cc) / hw, (row - rc) / hh) / math.sqrt(2.0)
        med = float(np.median(rnorm))
        inner = rnorm <= med
        split = f"normalised image radius ≤ median ({med:.2f}; 1 = image corner)"
        radial = {"split": split, "n_inner": int(inner.sum()), "n_edge": int((~inner).sum()),
                  "radial": rad.tolist(), "radius": rnorm.tolist()}
        pattern = None
        if inner.sum() >= 2 and (~inner).sum() >= 2:
            mi, me = float(rad[inner].mean()), float(rad[~inner].mean())
            se = math.sqrt(float(rad[inner].var(ddof=1)) / inner.sum()
                           + float(rad[~inner].var(ddof=1)) / (~inner).sum())
            radial.update(mean_inner=mi, mean_edge=me, se_difference=se)
            if mi * me < 0 and abs(me - mi) > 2 * se:
                pattern = (mi, me)
        if rad.size >= 6 and np.ptp(rnorm) > 0 and np.ptp(rad) > 0:
            r_corr = float(np.corrcoef(rnorm, rad)[0, 1])
            t = r_corr * math.sqrt((rad.size - 2) / max(1e-12, 1 - r_corr ** 2))
            radial.update(correlation=r_corr, t_value=t)
            if abs(t) > 2.8 and pattern is None and "mean_inner" in radial:
                pattern = (radial["mean_inner"], radial["mean_edge"])
        if pattern is not None:
            mi, me = pattern
            trend = ("growing outwards towards the edges" if me > mi else
                     "growing inwards towards the edges")
            flags.append(f"radial pattern: mean radial residual {mi:+.3f} inside, "
                         f"{me:+.3f} at the edges ({trend}) — raise the order")
    return {"quadrants": quads, "signs": signs, "radial": radial, "flags": flags,
            "centre_pixel": [cc, rc]}


# ---------------------------------------------------------------------- full evaluation

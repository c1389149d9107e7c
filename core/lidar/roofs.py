"""Parametric roof models fitted to a building's roof points (LOD2 roof shapes).

Model-driven reconstruction in the manner of Henn et al. (2013) and Huang et al.
(2013): the footprint rectangle (centre, axes, half sizes; ``u`` along the long axis)
fixes the frame, and a few roof primitives are fitted to the roof points by robust
least squares:

* ``flat``   — ``z = h``;
* ``shed``   — one plane ``z = a + b u + c v`` (mono-pitch);
* ``gabled`` — ``z = r − s |w − w0|`` with the ridge along ``u`` (``w = v``) or across
  it (``w = u``), ``w0`` the ridge offset (searched);
* ``hipped`` — ``z = e + s · min(b − |v|, a − |u|)``: equal pitch on all four sides,
  ridge along the long axis (a pyramid when the footprint is square).

Every fit is a trimmed least squares (fit, keep the points within 2.5 robust sigmas
and at least 0.1 m, refit, twice), so a parapet, a chimney or canopy left over the
roof does not bend it. The models are compared by their truncated mean squared
residual ``C = mean(min(r², c²))`` (c = 0.3 m): a model with more parameters replaces
a simpler one only when ``C + σ0² < 0.7 (C_simpler + σ0²)`` (σ0 = 0.05 m, the noise
floor of a roof); a plane tilted less than ``flat_angle`` is flat; when the best model
leaves fewer than 70 % of the points within 0.3 m the roof is ``complex`` (its
heights then come from the roof points themselves).

References
----------
Henn, A., Gröger, G., Stroh, V., Plümer, L. (2013). Model driven reconstruction of
roofs from sparse LIDAR point clouds. ISPRS J. Photogramm. Remote Sens. 76, 17–29.
Huang, H., Brenner, C., Sester, M. (2013). A generative statistical approach to
automatic 3D building roof reconstruction from laser scanning data. ISPRS J.
Photogramm. Remote Sens. 79, 29–43.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Dict, List

import numpy as np

__all__ = ["RoofModel", "fit_roof", "fit_roof_in_frame", "ROOF_TYPES"]

ROOF_TYPES = ("flat", "shed", "gabled", "hipped", "complex")
_C = 0.3            # truncation of the residual (m)
_FLOOR = 0.05 ** 2  # noise floor of a roof (m²)
_GAIN = 0.7         # a richer model must cut the cost to 70 %


@dataclass
class RoofModel:
    """A fitted roof: kind, frame (centre, unit axes u/v, half sizes a ≥ b), parameters.

    ``z(x, y)`` evaluates the roof surface anywhere; ``ridge`` and ``eave`` are its
    highest point and its lowest point on the outline (absolute heights).
    """

    kind: str
    centre: np.ndarray
    axes: np.ndarray
    half: np.ndarray
    params: Dict[str, float] = field(default_factory=dict)
    cost: float = 0.0
    inliers: float = 1.0
    n_points: int = 0

    def local(self, x, y):
        """(u, v) of ``x, y``."""
        d = np.stack([np.asarray(x) - self.centre[0], np.asarray(y) - self.centre[1]], -1)
        return d @ self.axes[0], d @ self.axes[1]

    def z_uv(self, u, v):
        """Roof height at local ``u, v``."""
        p, a, b = self.params, self.half[0], self.half[1]
        if self.kind in ("flat", "complex"):
            return np.full(np.shape(u), p["h"])
        if self.kind == "shed":
            return p["a"] + p["b"] * u + p["c"] * v
        if self.kind == "gabled":
            w = v if p["along_u"] else u
            return p["r"] - p["s"] * np.abs(w - p["w0"])
        return p["e"] + p["s"] * np.minimum(b - np.abs(v), a - np.abs(u))

    def z(self, x, y):
        """Roof height at ``x, y``."""
        return self.z_uv(*self.local(x, y))

    def _outline_samples(self, n: int = 33):
        t = np.linspace(-1, 1, n)
        a, b = self.half
        u = np.concatenate([t * a, t * a, np.full(n, a), np.full(n, -a)])
        v = np.concatenate([np.full(n, b), np.full(n, -b), t * b, t * b])
        return u, v

    @property
    def ridge(self) -> float:
        """Highest roof height over the footprint."""
        if self.kind in ("flat", "complex"):
            return float(self.params["h"])
        u, v = self._outline_samples()
        zz = [self.z_uv(u, v).max()]
        if self.kind == "gabled":
            zz.append(self.params["r"])
        if self.kind == "hipped":
            zz.append(self.params["e"] + self.params["s"] * self.half[1])
        return float(max(zz))

    @property
    def eave(self) -> float:
        """Lowest roof height on the outline."""
        u, v = self._outline_samples()
        return float(self.z_uv(u, v).min())

    @property
    def slope_deg(self) -> float:
        """Roof pitch (degrees); 0 for flat and complex."""
        p = self.params
        if self.kind == "shed":
            return math.degrees(math.atan(math.hypot(p["b"], p["c"])))
        if self.kind in ("gabled", "hipped"):
            return math.degrees(math.atan(abs(p["s"])))
        return 0.0

    def corners(self) -> np.ndarray:
        """Footprint corners (4, 2), counter-clockwise in x, y."""
        a, b = self.half
        uv = np.array([[-a, -b], [a, -b], [a, b], [-a, b]])
        xy = self.centre + uv[:, :1] * self.axes[0] + uv[:, 1:] * self.axes[1]
        x, y = xy[:, 0], xy[:, 1]
        if 0.5 * np.sum(x * np.roll(y, -1) - np.roll(x, -1) * y) < 0:
            xy = xy[::-1]
        return xy


def _trimmed_lstsq(design, z, iterations: int = 2):
    """Least squares of ``z`` on ``design`` refitted on its inliers; (coef, residuals)."""
    keep = np.ones(z.size, bool)
    coef = np.zeros(design.shape[1])
    for _ in range(iterations + 1):
        if keep.sum() < design.shape[1] + 1:
            break
        coef = np.linalg.lstsq(design[keep], z[keep], rcond=None)[0]
        res = z - design @ coef
        mad = np.median(np.abs(res[keep] - np.median(res[keep])))
        keep = np.abs(res) <= max(2.5 * 1.4826 * mad, 0.1)
    return coef, z - design @ coef


def _cost(res) -> float:
    return float(np.mean(np.minimum(res * res, _C * _C)))


def _candidates(u, v, z, a, b) -> List[tuple]:
    """(kind, params, residuals, n_params) of every primitive."""
    one = np.ones_like(z)
    out = []
    coef, res = _trimmed_lstsq(one[:, None], z)
    out.append(("flat", {"h": float(coef[0])}, res, 1))
    coef, res = _trimmed_lstsq(np.column_stack([one, u, v]), z)
    out.append(("shed", {"a": float(coef[0]), "b": float(coef[1]), "c": float(coef[2])},
                res, 3))
    best = None
    for along_u, w, half in ((True, v, b), (False, u, a)):
        for w0 in np.linspace(-0.3, 0.3, 13) * half:
            coef, res = _trimmed_lstsq(np.column_stack([one, -np.abs(w - w0)]), z)
            c = _cost(res)
            if coef[1] > 0 and (best is None or c < best[0]):
                best = (c, {"r": float(coef[0]), "s": float(coef[1]), "w0": float(w0),
                            "along_u": bool(along_u)}, res)
    if best is not None:
        out.append(("gabled", best[1], best[2], 3))
    coef, res = _trimmed_lstsq(np.column_stack([one, np.minimum(b - np.abs(v),
                                                                a - np.abs(u))]), z)
    if coef[1] > 0:
        out.append(("hipped", {"e": float(coef[0]), "s": float(coef[1])}, res, 2))
    return out


def fit_roof(x, y, z, centre, axes, half, *, flat_angle: float = 10.0) -> RoofModel:
    """Fit the roof in the rectangle's frame, turned by up to ±10° when that fails.

    When the first fit leaves many points off the roof (a frame from sparse points is a
    few degrees off, which a steep roof turns into residuals of decimetres), frames
    turned by ±3, ±6 and ±10° are tried too. See :func:`fit_roof_in_frame` for the
    parameters; the model with the lowest truncated cost among the non-complex fits
    wins.
    """
    model = fit_roof_in_frame(x, y, z, centre, axes, half, flat_angle=flat_angle)
    if model.inliers >= 0.85 and model.kind != "complex" or np.size(z) < 6:
        return model
    best = model
    xy = np.column_stack([np.asarray(x, float), np.asarray(y, float)])
    for deg in (-10.0, -6.0, -3.0, 3.0, 6.0, 10.0):
        a = np.radians(deg)
        rot = np.array([[np.cos(a), -np.sin(a)], [np.sin(a), np.cos(a)]])
        ax = np.asarray(axes, float) @ rot.T
        d = xy - np.asarray(centre, float)
        h = np.array([np.abs(d @ ax[0]).max(), np.abs(d @ ax[1]).max()])
        m = fit_roof_in_frame(x, y, z, centre, ax, h, flat_angle=flat_angle)
        if m.kind != "complex" and (best.kind == "complex" or m.cost < best.cost):
            best = m
    return best


def fit_roof_in_frame(x, y, z, centre, axes, half, *,
                      flat_angle: float = 10.0) -> RoofModel:
    """Fit the roof primitives in one frame and choose one (see the module docstring).

    Parameters
    ----------
    x, y, z : array_like
        Roof points of one building (metres).
    centre, axes, half : array_like
        Footprint rectangle: centre (2,), unit axes (2, 2; rows u, v), half sizes (2,).
    flat_angle : float
        Planes tilted less than this (degrees) are flat.

    Returns
    -------
    RoofModel
    """
    axes = np.asarray(axes, dtype=float)
    half = np.asarray(half, dtype=float)
    if half[1] > half[0]:                       # u along the long side
        axes, half = axes[::-1].copy(), half[::-1].copy()
    model = RoofModel("complex", np.asarray(centre, float), axes, half,
                      n_points=int(np.size(z)))
    z = np.asarray(z, dtype=float)
    if z.size < 6:
        model.params = {"h": float(np.percentile(z, 99)) if z.size else float("nan")}
        return model
    u, v = model.local(x, y)
    cands = _candidates(u, v, z, half[0], half[1])
    costs = {k: (_cost(r) + _FLOOR, p, r) for k, p, r, _n in cands}
    kind = "flat"
    tilted = [k for k in ("shed", "gabled") if k in costs]
    if tilted:
        k3 = min(tilted, key=lambda k: costs[k][0])
        if costs[k3][0] < _GAIN * costs["flat"][0]:
            kind = k3
    if kind == "gabled" and "hipped" in costs and \
            costs["hipped"][0] < _GAIN * costs["gabled"][0]:
        kind = "hipped"
    if kind == "flat" and "hipped" in costs and \
            costs["hipped"][0] < _GAIN * costs["flat"][0]:
        kind = "hipped"           # a pyramid
    cost, params, res = costs[kind]
    model.kind, model.params, model.cost = kind, params, cost - _FLOOR
    model.inliers = float(np.mean(np.abs(res) <= _C))
    if kind == "shed" and model.slope_deg < flat_angle:
        model.kind, model.params = "flat", costs["flat"][1]
        model.inliers = float(np.mean(np.abs(costs["flat"][2]) <= _C))
    if model.inliers < 0.7:
        model.kind, model.params = "complex", {"h": float(np.percentile(z, 99))}
    return model

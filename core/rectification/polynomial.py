"""2-D polynomial image → map transformations of order 1, 2 and 3 (GCP rectification).

The model of the seed paper (Tishreen Univ. J. Eng. Sci. 38(2), 2016, *criteria to
judge the geometric correction of satellite images by 2-D polynomials*) writes each
map coordinate as a polynomial of the image coordinates ``(u, v)``::

    order 1:  a0 + a1·u + a2·v                                  (3 terms)
    order 2:  … + a3·u² + a4·u·v + a5·v²                        (6 terms)
    order 3:  … + a6·u³ + a7·u²·v + a8·u·v² + a9·v³             (10 terms)

and solves each axis by least squares. With ``t`` the order there are
``N = (t+1)(t+2)/2`` coefficients per axis (``M = 2N`` in all) and at least ``N``
ground control points (GCPs) are needed; ``n − N`` is the redundancy.

Conventions
-----------
* Image coordinates are GDAL *pixel/line* coordinates: ``(0, 0)`` is the top-left
  **corner** of the top-left pixel, the centre of that pixel is ``(0.5, 0.5)``, the
  column grows to the right and the row grows **downwards** (see
  :mod:`.gcp_io` for how QGIS ``.points`` files and CSV files are converted).
* Before fitting, image coordinates are centred on the GCP centroid and divided by
  one common scale (the largest distance of a GCP from the centroid), so that
  ``|u|, |v| ≤ 1`` at the GCPs: cubic terms of raw pixel coordinates (10¹⁰ for a
  2000-pixel image) would make the normal equations useless. Map coordinates are
  centred too (projected coordinates of 10⁵–10⁶ m would otherwise eat digits).
* Residuals are ``v = predicted − given`` in map units.

The coefficients reported by :meth:`PolynomialModel.raw_coefficients` are those of the
same polynomial written in raw pixel/line coordinates (what ERDAS IMAGINE and the
paper print); they are derived analytically from the normalised ones.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from math import comb
from typing import Optional, Sequence

import numpy as np

from ..errors import InputError

#: exponents (i, j) of u^i·v^j in the paper's term order
TERMS = ((0, 0), (1, 0), (0, 1),
         (2, 0), (1, 1), (0, 2),
         (3, 0), (2, 1), (1, 2), (0, 3))
TERM_NAMES = ("1", "u", "v", "u²", "u·v", "v²", "u³", "u²·v", "u·v²", "v³")

#: condition number of the normalised design matrix above which a fit is refused
MAX_CONDITION = 1.0e6
#: … and above which it is accepted with a warning
WARN_CONDITION = 1.0e3


def n_terms(order: int) -> int:
    """Return the number of coefficients per axis ``N = (t+1)(t+2)/2`` (3, 6, 10)."""
    _check_order(order)
    return (order + 1) * (order + 2) // 2


def min_gcps(order: int) -> int:
    """Minimum number of GCPs for ``order`` (= :func:`n_terms`)."""
    return n_terms(order)


def _check_order(order) -> int:
    if order not in (1, 2, 3) or isinstance(order, bool):
        raise InputError("order must be 1, 2 or 3 (polynomial order), got {value}.",
                         value=repr(order))
    return int(order)


def design_matrix(u, v, order: int) -> np.ndarray:
    """Rows ``[1, u, v, u², u·v, v², u³, u²·v, u·v², v³][:N]`` for each point."""
    u = np.asarray(u, float).ravel()
    v = np.asarray(v, float).ravel()
    return np.column_stack([u ** i * v ** j for i, j in TERMS[:n_terms(order)]])


def _design_du(u, v, order):
    cols = []
    for i, j in TERMS[:n_terms(order)]:
        cols.append(i * u ** max(i - 1, 0) * v ** j if i else np.zeros_like(u))
    return np.column_stack(cols)


def _design_dv(u, v, order):
    cols = []
    for i, j in TERMS[:n_terms(order)]:
        cols.append(j * u ** i * v ** max(j - 1, 0) if j else np.zeros_like(u))
    return np.column_stack(cols)


@dataclass
class Normaliser:
    """Affine normalisation ``u = (x − x0)/s, v = (y − y0)/s`` (one common scale)."""

    x0: float
    y0: float
    scale: float

    @classmethod
    def fit(cls, xy: np.ndarray) -> "Normaliser":
        """Return the normaliser of ``xy``: centroid and largest distance from it."""
        c = xy.mean(axis=0)
        s = float(np.max(np.hypot(xy[:, 0] - c[0], xy[:, 1] - c[1]))) if len(xy) else 1.0
        return cls(float(c[0]), float(c[1]), s if s > 0 else 1.0)

    def apply(self, x, y):
        """Return ``x, y`` normalised."""
        return ((np.asarray(x, float) - self.x0) / self.scale,
                (np.asarray(y, float) - self.y0) / self.scale)

    def as_dict(self) -> dict:
        """Return the normaliser as a dict."""
        return {"x0": self.x0, "y0": self.y0, "scale": self.scale}


class IllConditionedError(InputError):
    """The GCP geometry cannot support the requested order (collinear or clustered)."""


@dataclass
class PolynomialModel:
    """A fitted forward polynomial (image → map) and its fitted inverse (map → image).

    Attributes
    ----------
    order : int
        1, 2 or 3.
    coef_x, coef_y : ndarray (N,)
        Coefficients of ``X − X0`` and ``Y − Y0`` in the normalised ``(u, v)``.
    pixel_norm : Normaliser
        Normalisation of the image coordinates.
    map_norm : Normaliser
        Centring of the map coordinates (its ``scale`` normalises the inverse fit).
    inv_coef_col, inv_coef_row : ndarray (N,)
        Inverse polynomial (normalised map → normalised image), fitted on the same GCPs
        by least squares as GDAL does; :meth:`inverse` refines it by Newton iteration.
    condition : float
        2-norm condition number of the (weighted) normalised design matrix.
    n : int
        Number of GCPs used.
    weights : ndarray or None
        Weights used (None = equal weights).
    leverage : ndarray (n,)
        Diagonal of the hat matrix (for leave-one-out residuals).
    warnings : list of str
        Non-fatal remarks about the geometry.
    """

    order: int
    coef_x: np.ndarray
    coef_y: np.ndarray
    pixel_norm: Normaliser
    map_norm: Normaliser
    inv_coef_col: np.ndarray
    inv_coef_row: np.ndarray
    condition: float
    n: int
    weights: Optional[np.ndarray] = None
    leverage: Optional[np.ndarray] = None
    warnings: list = field(default_factory=list)

    # ------------------------------------------------------------------ sizes
    @property
    def n_terms(self) -> int:
        """Coefficients per axis ``N``."""
        return n_terms(self.order)

    @property
    def n_parameters(self) -> int:
        """Total parameters ``M = 2N``."""
        return 2 * self.n_terms

    @property
    def redundancy(self) -> int:
        """``n − N`` (degrees of freedom per axis)."""
        return self.n - self.n_terms

    # ------------------------------------------------------------------ transforms
    def forward(self, col, row):
        """Map coordinates ``(X, Y)`` of image points ``(col, row)`` (pixel/line)."""
        col = np.asarray(col, float)
        shape = col.shape
        u, v = self.pixel_norm.apply(col.ravel(), np.asarray(row, float).ravel())
        a = design_matrix(u, v, self.order)
        x = a @ self.coef_x + self.map_norm.x0
        y = a @ self.coef_y + self.map_norm.y0
        return x.reshape(shape), y.reshape(shape)

    def jacobian(self, col, row):
        """Partial derivatives ``(dX/dcol, dX/drow, dY/dcol, dY/drow)`` at ``(col, row)``."""
        u, v = self.pixel_norm.apply(np.ravel(col), np.ravel(row))
        du, dv = _design_du(u, v, self.order), _design_dv(u, v, self.order)
        s = self.pixel_norm.scale
        return (du @ self.coef_x / s, dv @ self.coef_x / s,
                du @ self.coef_y / s, dv @ self.coef_y / s)

    def inverse_polynomial(self, x, y):
        """Image coordinates from the fitted inverse polynomial alone (as GDAL does)."""
        x = np.asarray(x, float)
        shape = x.shape
        p, q = self.map_norm.apply(x.ravel(), np.asarray(y, float).ravel())
        a = design_matrix(p, q, self.order)
        s = self.pixel_norm.scale
        col = a @ self.inv_coef_col * s + self.pixel_norm.x0
        row = a @ self.inv_coef_row * s + self.pixel_norm.y0
        return col.reshape(shape), row.reshape(shape)

    def inverse(self, x, y, *, refine: bool = True, tol: float = 1e-9, max_iter: int = 20):
        """Image coordinates ``(col, row)`` of map points ``(X, Y)``.

        Starts from the fitted inverse polynomial and, with ``refine``, runs Newton
        iterations on the forward polynomial until ``forward(inverse(X)) = X`` to
        ``tol`` pixels, so the two directions are exactly consistent.
        """
        x = np.asarray(x, float)
        shape = x.shape
        xf, yf = x.ravel(), np.asarray(y, float).ravel()
        col, row = self.inverse_polynomial(xf, yf)
        if not refine:
            return col.reshape(shape), row.reshape(shape)
        for _ in range(max_iter):
            fx, fy = self.forward(col, row)
            ex, ey = xf - fx, yf - fy
            a, b, c, d = self.jacobian(col, row)
            det = a * d - b * c
            with np.errstate(divide="ignore", invalid="ignore"):
                dcol = (d * ex - b * ey) / det
                drow = (-c * ex + a * ey) / det
            ok = np.isfinite(dcol) & np.isfinite(drow)
            col = np.where(ok, col + np.where(ok, dcol, 0), col)
            row = np.where(ok, row + np.where(ok, drow, 0), row)
            if np.nanmax(np.abs(np.concatenate([dcol[ok], drow[ok], [0.0]]))) < tol:
                break
        return col.reshape(shape), row.reshape(shape)

    def pixel_size(self, col=None, row=None) -> float:
        """Return the ground size of a pixel ``sqrt(|det J|)`` (map units).

        At the GCP centroid by default — the ground resolution GR implied by the fit.
        """
        if col is None:
            col, row = self.pixel_norm.x0, self.pixel_norm.y0
        a, b, c, d = self.jacobian(col, row)
        return float(np.sqrt(np.abs(a * d - b * c))[0])

    # ------------------------------------------------------------------ coefficients
    def raw_coefficients(self):
        """Coefficients ``(cx, cy)`` of ``X, Y`` as polynomials of raw ``(col, row)``.

        Expands ``u = (col − c0)/s, v = (row − r0)/s`` binomially; returned in the
        paper's term order (a0 … a9 / b0 … b9). Badly conditioned for order 3 and large
        images — use them for reporting, not for computing.
        """
        c0, r0, s = self.pixel_norm.x0, self.pixel_norm.y0, self.pixel_norm.scale
        index = {t: k for k, t in enumerate(TERMS[:self.n_terms])}
        out = []
        for coef, offset in ((self.coef_x, self.map_norm.x0), (self.coef_y, self.map_norm.y0)):
            raw = np.zeros(self.n_terms)
            for k, (i, j) in enumerate(TERMS[:self.n_terms]):
                f = coef[k] / s ** (i + j)
                for a in range(i + 1):
                    for b in range(j + 1):
                        raw[index[(a, b)]] += (f * comb(i, a) * (-c0) ** (i - a)
                                               * comb(j, b) * (-r0) ** (j - b))
            raw[0] += offset
            out.append(raw)
        return out[0], out[1]

    def as_dict(self) -> dict:
        """JSON-ready description (normalised and raw coefficients)."""
        cx, cy = self.raw_coefficients()
        names = list(TERM_NAMES[:self.n_terms])
        return {
            "order": self.order, "n_gcps": self.n, "n_terms_per_axis": self.n_terms,
            "n_parameters": self.n_parameters, "redundancy": self.redundancy,
            "condition_number": self.condition,
            "terms": names,
            "normalisation": {"pixel": self.pixel_norm.as_dict(),
                              "map": self.map_norm.as_dict()},
            "coefficients_normalised": {"X": self.coef_x.tolist(), "Y": self.coef_y.tolist()},
            "coefficients_raw_pixel": {"X": cx.tolist(), "Y": cy.tolist()},
            "weighted": self.weights is not None,
            "warnings": list(self.warnings),
        }


# ---------------------------------------------------------------------- fitting
_ILL = ("Cannot fit a polynomial of order {order}: the normal equations are "
        "ill-conditioned (condition number {cond} > {limit}) because ")
#: Why the GCP geometry is degenerate (:func:`_diagnose`), as complete message templates.
ILL_CONDITIONED = {
    "collinear": _ILL + (
        "the GCPs are (nearly) collinear: their spread across the best-fit line is {minor} "
        "px against {major} px along it, so the transformation across the line is "
        "undetermined. Add GCPs away from that line."),
    "clustered": _ILL + (
        "the GCPs are clustered: only {distinct} distinct image positions (points closer "
        "than {tol} px counted once) for the {need} coefficients per axis of order "
        "{order}. Spread GCPs over the image."),
    "undetermined": _ILL + (
        "the GCP positions do not determine the {need} coefficients of order {order} (e.g. "
        "they lie on a conic or a few lines, which a polynomial of this order cannot tell "
        "apart). Add GCPs spread over the whole image or lower the order."),
}


def _diagnose(uv: np.ndarray, order: int, pixel_xy: np.ndarray):
    """Why the GCP geometry is degenerate: a key of :data:`ILL_CONDITIONED`, its fields."""
    n_needed = n_terms(order)
    c = pixel_xy - pixel_xy.mean(axis=0)
    sv = np.linalg.svd(c, compute_uv=False) if len(c) > 1 else np.array([0.0, 0.0])
    major = sv[0] / np.sqrt(max(len(c), 1))
    minor = (sv[1] if len(sv) > 1 else 0.0) / np.sqrt(max(len(c), 1))
    if major > 0 and minor / major < 1e-3:
        return "collinear", dict(minor=f"{minor:.3g}", major=f"{major:.3g}")
    # distinct positions: merge points closer than 1e-3 of the spread
    tol = max(major, 1e-12) * 1e-3
    keys = np.round(pixel_xy / tol).astype(np.int64)
    distinct = len({tuple(k) for k in keys})
    if distinct < n_needed:
        return "clustered", dict(distinct=distinct, tol=f"{tol:.3g}", need=n_needed)
    return "undetermined", dict(need=n_needed)


def fit_polynomial(pixel_xy, map_xy, *, order: int, weights: Optional[Sequence] = None,
                   max_condition: float = MAX_CONDITION) -> PolynomialModel:
    """Least-squares polynomial image → map (and map → image) from GCPs.

    Parameters
    ----------
    pixel_xy : array (n, 2)
        GCP image coordinates ``(col, row)``, GDAL pixel/line convention.
    map_xy : array (n, 2)
        GCP map coordinates ``(X, Y)``.
    order : {1, 2, 3}
        Polynomial order (terms in the paper's order, see module docstring).
    weights : array (n,), optional
        Positive weights (e.g. ``1/σ²`` of each GCP); equal weights by default.
    max_condition : float
        Refuse the fit when the condition number of the normalised design matrix
        exceeds this (default 1e6): the GCPs are then (nearly) collinear or clustered.

    Returns
    -------
    PolynomialModel

    Raises
    ------
    ValueError
        Too few GCPs for the order, non-finite coordinates, bad weights.
    IllConditionedError
        Degenerate GCP geometry, with an explanation and a fix.

    References
    ----------
    Tishreen Univ. J. Eng. Sci. 38(2), 2016 (polynomial model and criteria);
    GDAL ``gdal_crs.cpp`` fits the same model (used as the oracle in the tests).
    """
    order = _check_order(order)
    pix = np.asarray(pixel_xy, float)
    mp = np.asarray(map_xy, float)
    if pix.ndim != 2 or pix.shape[1] != 2 or mp.shape != pix.shape:
        raise InputError("pixel_xy and map_xy must both be (n, 2) arrays, got {a} and {b}.",
                         a=pix.shape, b=mp.shape)
    n = len(pix)
    need = n_terms(order)
    if n < need:
        if n >= 3:
            raise InputError(
                "A polynomial of order {order} needs at least {need} enabled GCPs "
                "({need} coefficients per axis); only {n} given. Add GCPs or lower the "
                "order (order {possible} is possible).", order=order, need=need, n=n,
                possible=max(t for t in (1, 2, 3) if n_terms(t) <= n))
        raise InputError(
            "A polynomial of order {order} needs at least {need} enabled GCPs "
            "({need} coefficients per axis); only {n} given. Add GCPs or lower the order.",
            order=order, need=need, n=n)
    if not (np.isfinite(pix).all() and np.isfinite(mp).all()):
        raise InputError("GCP coordinates contain NaN or infinite values; fix the GCP file.")
    w = None
    if weights is not None:
        w = np.asarray(weights, float).ravel()
        if w.shape != (n,) or not np.isfinite(w).all() or (w <= 0).any():
            raise InputError("GCP weights must be finite positive numbers, one per GCP "
                             "(e.g. 1/sigma²); remove zero or negative weights.")
    pn = Normaliser.fit(pix)
    mn = Normaliser.fit(mp)
    u, v = pn.apply(pix[:, 0], pix[:, 1])
    a = design_matrix(u, v, order)
    sw = np.sqrt(w) if w is not None else np.ones(n)
    aw = a * sw[:, None]
    sv = np.linalg.svd(aw, compute_uv=False)
    cond = float(sv[0] / sv[-1]) if sv[-1] > 0 else float("inf")
    if not np.isfinite(cond) or cond > max_condition:
        key, fields = _diagnose(np.column_stack([u, v]), order, pix)
        raise IllConditionedError(ILL_CONDITIONED[key], order=order, cond=f"{cond:.3g}",
                                  limit=f"{max_condition:.3g}", **fields)
    rhs = np.column_stack([mp[:, 0] - mn.x0, mp[:, 1] - mn.y0]) * sw[:, None]
    coef, *_ = np.linalg.lstsq(aw, rhs, rcond=None)
    # inverse polynomial: normalised map -> normalised pixel, same order
    p, q = mn.apply(mp[:, 0], mp[:, 1])
    b = design_matrix(p, q, order) * sw[:, None]
    inv, *_ = np.linalg.lstsq(b, np.column_stack([u, v]) * sw[:, None], rcond=None)
    # leverage (hat diagonal) for leave-one-out residuals
    qm, _ = np.linalg.qr(aw)
    lev = np.sum(qm ** 2, axis=1)
    warnings = []
    if cond > WARN_CONDITION:
        warnings.append(f"condition number {cond:.3g} is high: the GCP geometry only weakly "
                        f"determines the order-{order} terms; check the distribution.")
    if n == need:
        warnings.append(f"exactly {need} GCPs for order {order}: zero redundancy, the fit "
                        "passes through every GCP and residuals say nothing about accuracy.")
    return PolynomialModel(order, coef[:, 0].copy(), coef[:, 1].copy(), pn, mn,
                           inv[:, 0].copy(), inv[:, 1].copy(), cond, n, w, lev, warnings)


def residuals(model: PolynomialModel, pixel_xy, map_xy):
    """Residuals ``v = predicted − given`` (map units) at the given points."""
    pix = np.asarray(pixel_xy, float)
    mp = np.asarray(map_xy, float)
    px, py = model.forward(pix[:, 0], pix[:, 1])
    return px - mp[:, 0], py - mp[:, 1]


def leave_one_out(model: PolynomialModel, pixel_xy, map_xy):
    """Leave-one-out residuals of the GCPs used in the fit (map units).

    Exact for linear least squares: ``e_i / (1 − h_ii)`` with ``h`` the hat-matrix
    diagonal; NaN where a point has leverage 1 (the fit cannot do without it).
    """
    vx, vy = residuals(model, pixel_xy, map_xy)
    h = model.leverage
    with np.errstate(divide="ignore", invalid="ignore"):
        d = 1.0 - h
        bad = d < 1e-9
        lx = np.where(bad, np.nan, vx / np.where(bad, 1, d))
        ly = np.where(bad, np.nan, vy / np.where(bad, 1, d))
    return lx, ly

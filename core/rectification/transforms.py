"""Image → map transformations of the QGIS Georeferencer and gdalwarp, fitted from GCPs.

Every transformation maps GDAL pixel/line coordinates ``(col, row)`` (corner
convention, rows downwards) to map coordinates ``(X, Y)`` and back:

* ``linear``: shift and scale per axis, ``X = a + sx·col``, ``Y = b + sy·row``
  (the Georeferencer's *Linear*; 2 GCPs; least squares per axis);
* ``helmert``: similarity (shift, one scale, one rotation) of the image coordinates
  as QGIS stores them, ``(col, −row)``; 2 GCPs; linear least squares in
  ``a = s·cos θ, b = s·sin θ`` (Helmert 1872; the same optimum as Umeyama 1991);
* ``polynomial1…3``: the seed paper's polynomials (:mod:`.polynomial`);
* ``projective``: 8-parameter homography by the normalised direct linear transform
  (Hartley & Zisserman 2003, *Multiple View Geometry*, Alg. 4.2); 4 GCPs;
* ``tps``: thin-plate spline (Bookstein 1989), an exact interpolant through every
  GCP as GDAL's ``GCP_TPS`` transformer (``gdalwarp -tps``); 3 GCPs. Its fit residuals
  are zero: only leave-one-out and check-point residuals judge it.

Each fit refuses near-degenerate GCP sets with the reason, reports its parameters
(:meth:`Transform.parameters`) and its minimum point count (:data:`MIN_POINTS`).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Optional

import numpy as np

from ..errors import InputError
from .polynomial import MAX_CONDITION, PolynomialModel, fit_polynomial, leave_one_out

KINDS = ("linear", "helmert", "polynomial1", "polynomial2", "polynomial3", "projective",
         "tps")
#: minimum GCP count of each transformation
MIN_POINTS = {"linear": 2, "helmert": 2, "polynomial1": 3, "polynomial2": 6,
              "polynomial3": 10, "projective": 4, "tps": 3}
#: parameters of each transformation (tps: 2·(n + 3), see :meth:`Transform.n_parameters`)
N_PARAMETERS = {"linear": 4, "helmert": 4, "polynomial1": 6, "polynomial2": 12,
                "polynomial3": 20, "projective": 8}
#: relative spread below which a GCP set counts as degenerate
DEGENERATE = 1e-6


def check_kind(kind: str) -> str:
    """Return ``kind`` if it is one of :data:`KINDS`, else raise a clear error."""
    if kind not in KINDS:
        raise InputError("Unknown transformation {kind!r}; use one of {choices}.",
                         kind=kind,
                         choices=', '.join(KINDS))
    return kind


@dataclass
class Transform:
    """A fitted transformation (subclasses implement the maths).

    Attributes
    ----------
    kind : str
        One of :data:`KINDS`.
    n : int
        Number of GCPs fitted.
    warnings : list of str
        Non-fatal remarks about the geometry.
    """

    kind: str
    n: int
    warnings: list = field(default_factory=list)

    @property
    def min_points(self) -> int:
        """Minimum GCP count of this transformation."""
        return MIN_POINTS[self.kind]

    @property
    def n_parameters(self) -> int:
        """Number of parameters (both axes)."""
        return N_PARAMETERS.get(self.kind, 2 * (self.n + 3))

    @property
    def is_affine(self) -> bool:
        """True when the transformation is affine (exactly a GDAL geotransform)."""
        return self.kind in ("linear", "helmert", "polynomial1")

    def forward(self, col, row):  # pragma: no cover - abstract
        """Return map ``(X, Y)`` of image points ``(col, row)``."""
        raise NotImplementedError

    def inverse(self, x, y):  # pragma: no cover - abstract
        """Return image ``(col, row)`` of map points ``(X, Y)``."""
        raise NotImplementedError

    def parameters(self) -> dict:  # pragma: no cover - abstract
        """Return the named parameters of the fit."""
        raise NotImplementedError

    def residuals(self, pixel_xy, map_xy):
        """Return residuals ``v = predicted − given`` (map units)."""
        pix, mp = np.asarray(pixel_xy, float), np.asarray(map_xy, float)
        x, y = self.forward(pix[:, 0], pix[:, 1])
        return x - mp[:, 0], y - mp[:, 1]

    def geotransform(self) -> tuple:
        """Return the GDAL geotransform of an affine transformation."""
        x0, y0 = self.forward(np.array([0.0]), np.array([0.0]))
        x1, y1 = self.forward(np.array([1.0]), np.array([0.0]))
        x2, y2 = self.forward(np.array([0.0]), np.array([1.0]))
        return (float(x0[0]), float(x1[0] - x0[0]), float(x2[0] - x0[0]),
                float(y0[0]), float(y1[0] - y0[0]), float(y2[0] - y0[0]))


def _vec(a):
    a = np.asarray(a, float)
    return a.ravel(), a.shape


# ---------------------------------------------------------------------- affine kinds
@dataclass
class AffineTransform(Transform):
    """Linear, Helmert (and any affine) transformation ``X = A·(col, row) + t``."""

    matrix: np.ndarray = None  # 2×2
    shift: np.ndarray = None  # 2

    def forward(self, col, row):
        """Return map ``(X, Y)`` of image points ``(col, row)``."""
        c, shape = _vec(col)
        r = np.asarray(row, float).ravel()
        x = self.matrix[0, 0] * c + self.matrix[0, 1] * r + self.shift[0]
        y = self.matrix[1, 0] * c + self.matrix[1, 1] * r + self.shift[1]
        return x.reshape(shape), y.reshape(shape)

    def inverse(self, x, y):
        """Return image ``(col, row)`` of map points ``(X, Y)`` (exact)."""
        xv, shape = _vec(x)
        d = np.column_stack([xv - self.shift[0], np.asarray(y, float).ravel() - self.shift[1]])
        cr = np.linalg.solve(self.matrix, d.T).T
        return cr[:, 0].reshape(shape), cr[:, 1].reshape(shape)

    def parameters(self) -> dict:
        """Return shifts and scales (linear) or scale, rotation and shift (Helmert)."""
        tx, ty = (float(v) for v in self.shift)
        if self.kind == "linear":
            return {"shift_x": tx, "shift_y": ty, "scale_x": float(self.matrix[0, 0]),
                    "scale_y": float(self.matrix[1, 1])}
        a, b = float(self.matrix[0, 0]), float(self.matrix[1, 0])
        return {"shift_x": tx, "shift_y": ty, "scale": math.hypot(a, b),
                "rotation_deg": math.degrees(math.atan2(b, a))}


def _spread(values) -> float:
    return float(np.ptp(values)) if len(values) else 0.0


def fit_linear(pixel_xy, map_xy) -> AffineTransform:
    """Fit shift + scale per axis (``X`` from ``col``, ``Y`` from ``row``) by least squares.

    Raises
    ------
    InputError
        When all GCPs share (nearly) one column or one row.
    """
    pix, mp = np.asarray(pixel_xy, float), np.asarray(map_xy, float)
    span = max(_spread(pix[:, 0]), _spread(pix[:, 1]), 1e-300)
    for axis, name in ((0, "column"), (1, "row")):
        if _spread(pix[:, axis]) <= DEGENERATE * span:
            raise InputError("Linear transformation: all GCPs lie in one image {name}, so "
                             "the scale along it is undetermined; add GCPs at other "
                             "{name}s.", name=name)
    sx, tx = np.polyfit(pix[:, 0], mp[:, 0], 1)
    sy, ty = np.polyfit(pix[:, 1], mp[:, 1], 1)
    return AffineTransform("linear", len(pix), matrix=np.array([[sx, 0.0], [0.0, sy]]),
                           shift=np.array([tx, ty]))


def fit_helmert(pixel_xy, map_xy) -> AffineTransform:
    """Fit a similarity of ``(col, −row)`` (QGIS's pixel coordinates) to ``(X, Y)``.

    Linear least squares in ``(a, b, tx, ty)`` with ``X = tx + a·c + b·row``,
    ``Y = ty + b·c − a·row`` (``c`` = col): ``a = s·cos θ``, ``b = s·sin θ``.

    Raises
    ------
    InputError
        When the GCPs have fewer than two distinct image positions.
    """
    pix, mp = np.asarray(pixel_xy, float), np.asarray(map_xy, float)
    c, r = pix[:, 0], -pix[:, 1]
    if max(_spread(c), _spread(r)) <= 0:
        raise InputError("Helmert transformation: all GCPs share one image position; "
                         "at least two distinct points are needed.")
    cc, rc, mc = c.mean(), r.mean(), mp.mean(axis=0)
    dc, dr, dx, dy = c - cc, r - rc, mp[:, 0] - mc[0], mp[:, 1] - mc[1]
    q = float(np.sum(dc ** 2 + dr ** 2))
    a = float(np.sum(dc * dx + dr * dy)) / q
    b = float(np.sum(dc * dy - dr * dx)) / q
    # in (col, row): X = a·col + b·row + tx, Y = b·col − a·row + ty
    matrix = np.array([[a, b], [b, -a]])
    shift = mc - matrix @ np.array([cc, -rc])
    return AffineTransform("helmert", len(pix), matrix=matrix, shift=shift)


# ---------------------------------------------------------------------- polynomial
@dataclass
class PolynomialTransform(Transform):
    """The seed paper's polynomial of order 1–3 (:class:`~.polynomial.PolynomialModel`)."""

    model: PolynomialModel = None

    def forward(self, col, row):
        """Return map ``(X, Y)`` of image points ``(col, row)``."""
        return self.model.forward(col, row)

    def inverse(self, x, y):
        """Return image ``(col, row)`` of map points (Newton-refined inverse)."""
        return self.model.inverse(x, y)

    def parameters(self) -> dict:
        """Return the raw-pixel coefficients of ``X`` and ``Y``."""
        cx, cy = self.model.raw_coefficients()
        return {"coefficients_X": cx.tolist(), "coefficients_Y": cy.tolist(),
                "condition_number": self.model.condition}


# ---------------------------------------------------------------------- projective
def _normalising(xy: np.ndarray) -> np.ndarray:
    """Hartley's similarity: centroid to the origin, RMS distance sqrt(2).

    (The RMS variant, as scikit-image; Hartley & Zisserman use the mean distance.)
    """
    c = xy.mean(axis=0)
    d = math.sqrt(float(np.mean((xy[:, 0] - c[0]) ** 2 + (xy[:, 1] - c[1]) ** 2)))
    s = math.sqrt(2.0) / d if d > 0 else 1.0
    return np.array([[s, 0, -s * c[0]], [0, s, -s * c[1]], [0, 0, 1.0]])


def _apply_h(h: np.ndarray, x, y):
    xv, shape = _vec(x)
    yv = np.asarray(y, float).ravel()
    w = h[2, 0] * xv + h[2, 1] * yv + h[2, 2]
    return ((h[0, 0] * xv + h[0, 1] * yv + h[0, 2]) / w).reshape(shape), \
        ((h[1, 0] * xv + h[1, 1] * yv + h[1, 2]) / w).reshape(shape)


@dataclass
class ProjectiveTransform(Transform):
    """Homography ``(X, Y, 1) ~ H·(col, row, 1)`` with ``H[2, 2] = 1``."""

    matrix: np.ndarray = None

    def forward(self, col, row):
        """Return map ``(X, Y)`` of image points ``(col, row)``."""
        return _apply_h(self.matrix, col, row)

    def inverse(self, x, y):
        """Return image ``(col, row)`` of map points (exact inverse homography)."""
        return _apply_h(np.linalg.inv(self.matrix), x, y)

    def parameters(self) -> dict:
        """Return the 3×3 matrix (``H[2, 2] = 1``, 8 free parameters)."""
        return {"matrix": self.matrix.tolist()}


def fit_projective(pixel_xy, map_xy) -> ProjectiveTransform:
    """Fit a homography by the normalised direct linear transform (H&Z Alg. 4.2).

    Raises
    ------
    InputError
        With fewer than 4 GCPs, when three quarters of them are collinear in the image
        (the homography is then undetermined), or when the image horizon of the fit
        crosses the GCPs.
    """
    pix, mp = np.asarray(pixel_xy, float), np.asarray(map_xy, float)
    ts, td = _normalising(pix), _normalising(mp)
    s = np.column_stack([pix, np.ones(len(pix))]) @ ts.T
    d = np.column_stack([mp, np.ones(len(mp))]) @ td.T
    n = len(pix)
    a = np.zeros((2 * n, 9))
    a[:n, 0:3] = s
    a[:n, 6:9] = -d[:, [0]] * s
    a[n:, 3:6] = s
    a[n:, 6:9] = -d[:, [1]] * s
    _, sv, vt = np.linalg.svd(a)
    if n > 4 and sv[-2] <= DEGENERATE * sv[0] or n == 4 and sv[-1] <= DEGENERATE * sv[0]:
        raise InputError("Projective transformation: the GCP geometry does not determine "
                         "the 8 parameters (three or more of the points are collinear); "
                         "spread GCPs over the whole image.")
    h = np.linalg.inv(td) @ vt[-1].reshape(3, 3) @ ts
    h = h / h[2, 2]
    w = h[2, 0] * pix[:, 0] + h[2, 1] * pix[:, 1] + 1.0
    if not ((w > 0).all() or (w < 0).all()):
        raise InputError("Projective transformation: the fitted horizon line crosses the "
                         "GCPs (the fit folds the image); the GCPs do not fit a projective "
                         "mapping — check them or use a polynomial.")
    return ProjectiveTransform("projective", n, matrix=h)


# ---------------------------------------------------------------------- thin-plate spline
def gdal_inverts_tps_exactly() -> bool:
    """Tell whether the GDAL in use inverts its thin-plate spline exactly (GDAL ≥ 3.8).

    GDAL up to 3.7 maps map → image with a second spline fitted to the GCPs the other
    way round; GDAL 3.8 takes that spline's value only as the first guess and refines it
    by Newton-Raphson on the forward spline (``GDALGenericInverse2D``), so that
    ``forward(inverse(p)) == p``. The two differ by up to a few hundredths of a pixel
    between GCPs. Without GDAL the exact inverse is used.
    """
    try:
        from osgeo import gdal
    except ImportError:  # pragma: no cover - GDAL ships with QGIS
        return True
    return int(gdal.VersionInfo("VERSION_NUM")) >= 3080000


#: Newton-Raphson iterations of the exact inverse (quadratic convergence: 3-5 suffice)
_NEWTON_ITERATIONS = 30


@dataclass
class TpsTransform(Transform):
    """Thin-plate spline through every GCP, forward and inverse as the GDAL in use.

    ``exact_inverse`` (GDAL ≥ 3.8): the inverse solves ``forward(col, row) = (X, Y)``
    by Newton-Raphson from the map → image spline's value; otherwise (GDAL < 3.8) it
    is that separately fitted spline, as GDAL computed it then.
    """

    fwd: object = None
    inv: object = None
    exact_inverse: bool = True

    def forward(self, col, row):
        """Return map ``(X, Y)`` of image points ``(col, row)``."""
        c, shape = _vec(col)
        out = self.fwd(np.column_stack([c, np.asarray(row, float).ravel()]))
        return out[:, 0].reshape(shape), out[:, 1].reshape(shape)

    def inverse(self, x, y):
        """Return image ``(col, row)`` of map points ``(X, Y)`` as the GDAL in use does."""
        xv, shape = _vec(x)
        target = np.column_stack([xv, np.asarray(y, float).ravel()])
        out = self.inv(target)
        if self.exact_inverse and len(target):
            out = self._refine(target, out)
        return out[:, 0].reshape(shape), out[:, 1].reshape(shape)

    def _refine(self, target: np.ndarray, guess: np.ndarray) -> np.ndarray:
        """Newton-Raphson on the forward spline, all points at once.

        The Jacobian comes from central differences of the forward spline (steps of
        1e-6 of the coordinates' magnitude); iteration stops when every point
        reproduces its map position to 1e-12 of its magnitude. Points whose iteration
        does not converge to a finite value keep the first guess.
        """
        p = guess.copy()
        tol = np.maximum(np.abs(target).max(axis=1), 1.0) * 1e-12
        active = np.ones(len(p), bool)
        for _ in range(_NEWTON_ITERATIONS):
            idx = np.flatnonzero(active)
            if not idx.size:
                break
            q = p[idx]
            h = np.maximum(np.abs(q).max(axis=1), 1.0)[:, None] * 1e-6
            dx, dy = np.zeros_like(q), np.zeros_like(q)
            dx[:, 0], dy[:, 1] = h[:, 0], h[:, 0]
            vals = self.fwd(np.concatenate([q, q + dx, q - dx, q + dy, q - dy]))
            f, fxp, fxm, fyp, fym = np.split(vals, 5)
            r = f - target[idx]
            done = np.abs(r).max(axis=1) <= tol[idx]
            jac = np.stack([(fxp - fxm) / (2 * h), (fyp - fym) / (2 * h)], axis=2)
            step = np.zeros_like(q)
            ok = ~done & (np.abs(np.linalg.det(jac)) > 0)
            if ok.any():
                step[ok] = np.linalg.solve(jac[ok], r[ok][:, :, None])[:, :, 0]
            p[idx] = q - step
            active[idx[done | ~ok]] = False
        bad = ~np.isfinite(p).all(axis=1)
        p[bad] = guess[bad]
        return p

    def parameters(self) -> dict:
        """Return the number of control points (the spline passes through each)."""
        return {"control_points": self.n, "kernel": "r²·log r, affine trend",
                "inverse": "exact (Newton-Raphson)" if self.exact_inverse
                else "map → image spline"}


def _tps(src: np.ndarray, dst: np.ndarray):
    from scipy.interpolate import RBFInterpolator
    c = src.mean(axis=0)
    s = float(np.max(np.abs(src - c))) or 1.0
    o = dst.mean(axis=0)
    f = RBFInterpolator((src - c) / s, dst - o, kernel="thin_plate_spline", degree=1)
    return lambda xy: f((xy - c) / s) + o


def fit_tps(pixel_xy, map_xy, *, exact_inverse: Optional[bool] = None) -> TpsTransform:
    """Fit the thin-plate spline (Bookstein 1989) as GDAL's ``GCP_TPS`` transformer.

    ``exact_inverse``: invert the forward spline exactly (GDAL ≥ 3.8) or use the
    map → image spline (GDAL < 3.8); default: as the GDAL in use
    (:func:`gdal_inverts_tps_exactly`).

    Raises
    ------
    InputError
        With repeated image positions or collinear GCPs.
    """
    pix, mp = np.asarray(pixel_xy, float), np.asarray(map_xy, float)
    _, counts = np.unique(pix, axis=0, return_counts=True)
    if (counts > 1).any():
        raise InputError("Thin-plate spline: two GCPs share one image position; the "
                         "spline must pass through both. Remove the repeated point.")
    c = pix - pix.mean(axis=0)
    sv = np.linalg.svd(c, compute_uv=False)
    if sv[-1] <= DEGENERATE * sv[0]:
        raise InputError("Thin-plate spline: the GCPs are collinear in the image; add "
                         "GCPs away from that line.")
    try:
        exact = gdal_inverts_tps_exactly() if exact_inverse is None else bool(exact_inverse)
        return TpsTransform("tps", len(pix), fwd=_tps(pix, mp), inv=_tps(mp, pix),
                            exact_inverse=exact)
    except np.linalg.LinAlgError as exc:
        raise InputError("Thin-plate spline: singular system ({exc}); check for repeated "
                         "or collinear GCPs.", exc=exc) from None


# ---------------------------------------------------------------------- dispatch
def fit_transform(kind: str, pixel_xy, map_xy, *, weights=None,
                  max_condition: float = MAX_CONDITION) -> Transform:
    """Fit transformation ``kind`` from GCPs ``pixel_xy`` (col, row) → ``map_xy``.

    Parameters
    ----------
    kind : str
        One of :data:`KINDS`.
    pixel_xy, map_xy : array (n, 2)
        GCP image (GDAL pixel/line, corner convention) and map coordinates.
    weights : array (n,), optional
        Least-squares weights (polynomials only; the other fits are unweighted as in
        QGIS and GDAL).
    max_condition : float
        Condition-number limit of the polynomial fits.

    Returns
    -------
    Transform

    Raises
    ------
    InputError
        Too few GCPs for ``kind`` or a degenerate geometry, with the reason.
    """
    check_kind(kind)
    pix, mp = np.asarray(pixel_xy, float), np.asarray(map_xy, float)
    need = MIN_POINTS[kind]
    if len(pix) < need:
        raise InputError("The {kind} transformation needs at least {need} GCPs; only "
                         "{n} given. Add GCPs or choose a simpler transformation.",
                         kind=kind,
                         need=need,
                         n=len(pix))
    if kind.startswith("polynomial"):
        model = fit_polynomial(pix, mp, order=int(kind[-1]), weights=weights,
                               max_condition=max_condition)           # InputError if degenerate
        return PolynomialTransform(kind, len(pix), model.warnings, model=model)
    fit = {"linear": fit_linear, "helmert": fit_helmert, "projective": fit_projective,
           "tps": fit_tps}[kind]
    return fit(pix, mp)


def loo_residuals(kind: str, pixel_xy, map_xy, *, model: Optional[Transform] = None,
                  weights=None):
    """Leave-one-out residuals (map units): each GCP predicted by a fit without it.

    Polynomials use the exact hat-matrix shortcut; the other kinds refit ``n`` times
    (GCP sets are small). NaN where the remaining points cannot be fitted.
    """
    pix, mp = np.asarray(pixel_xy, float), np.asarray(map_xy, float)
    if kind.startswith("polynomial"):
        m = model if model is not None else fit_transform(kind, pix, mp, weights=weights)
        return leave_one_out(m.model, pix, mp)
    n = len(pix)
    out = np.full((n, 2), np.nan)
    keep = np.ones(n, bool)
    for i in range(n):
        keep[i] = False
        try:
            t = fit_transform(kind, pix[keep], mp[keep])
            out[i] = np.ravel(t.residuals(pix[i:i + 1], mp[i:i + 1]))
        except (InputError, np.linalg.LinAlgError):
            pass
        keep[i] = True
    return out[:, 0], out[:, 1]

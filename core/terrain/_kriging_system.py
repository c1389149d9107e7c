"""The kriging system (private; see :mod:`.kriging`).

Local or global solves, prediction and leave-one-out cross-validation.
"""
from __future__ import annotations

from typing import Dict, Optional, Tuple

import numpy as np
from scipy.spatial import cKDTree

from ..errors import InputError
from ..progress import Monitor
from ..system import limit_blas_threads
from ._kriging_base import (
    DRIFTS,
    EPS,
    GLOBAL_MAX_POINTS,
    Variogram,
    _check_xyz,
    merge_duplicates,
)


class Kriging:
    """Local-neighbourhood (or global) ordinary/universal kriging predictor.

    Parameters
    ----------
    x, y, z : array_like
        Data points (duplicates in (x, y) are merged).
    variogram : Variogram
        From :func:`fit_variogram` or :func:`given_variogram`.
    drift : {'none', 'linear'}
        'none' = ordinary kriging; 'linear' = universal kriging with a linear drift.
    n_closest : int
        Neighbours per estimate (default 16). Equal to the number of points → global
        kriging (one system).
    workers : int
        Threads for the KD-tree queries.
    """

    def __init__(self, x, y, z, *, variogram: Variogram, drift: str = "none",
                 n_closest: int = 16, workers: int = -1):
        x, y, z = _check_xyz(x, y, z)
        self.n_input = int(x.size)
        x, y, z, self.n_merged = merge_duplicates(x, y, z)
        if drift not in DRIFTS:
            raise InputError("drift must be one of {choices}; got {drift}.",
                             choices=", ".join(DRIFTS), drift=repr(drift))
        n_closest = int(n_closest)
        check_neighbours(n_closest, int(x.size), drift)
        self.x0, self.y0 = float(x.mean()), float(y.mean())
        self.x, self.y, self.z = x - self.x0, y - self.y0, z
        self.variogram = variogram
        self.drift = drift
        self.n_closest = n_closest
        self.workers = workers
        self.tree = cKDTree(np.column_stack([self.x, self.y]))
        self._lu = None
        self.is_global = n_closest == x.size and x.size <= GLOBAL_MAX_POINTS

    @property
    def n_points(self) -> int:
        """Return the number of data points."""
        return int(self.x.size)

    @property
    def n_extra(self) -> int:
        """Return the number of Lagrange rows (1, or 3 with a linear drift)."""
        return 1 + (2 if self.drift == "linear" else 0)

    def block_cells(self, budget: int = 160_000_000) -> int:
        """Cells per batch so that the batched systems use about ``budget`` bytes."""
        m = self.n_closest + self.n_extra
        return int(max(64, min(65536, budget // (m * m * 8 * 6))))

    # ---------------------------------------------------------------- local solve
    def _solve_local(self, qx, qy, d0, idx) -> Tuple[np.ndarray, np.ndarray]:
        """Kriging estimates and variances at query points given their neighbours."""
        m, n = idx.shape
        e = self.n_extra
        px = self.x[idx] - qx[:, None]
        py = self.y[idx] - qy[:, None]
        dd = np.hypot(px[:, :, None] - px[:, None, :], py[:, :, None] - py[:, None, :])
        a = np.zeros((m, n + e, n + e))
        a[:, :n, :n] = self.variogram(dd)
        del dd
        di = np.arange(n)
        a[:, di, di] = 0.0
        a[:, :n, n] = 1.0
        a[:, n, :n] = 1.0
        b = np.zeros((m, n + e))
        g0 = self.variogram(d0)
        g0[d0 <= EPS] = 0.0
        b[:, :n] = g0
        b[:, n] = 1.0
        if self.drift == "linear":
            s = np.maximum(np.abs(px).max(axis=1), np.abs(py).max(axis=1))
            s = np.where(s > 0, s, 1.0)[:, None]
            fx, fy = px / s, py / s
            a[:, :n, n + 1], a[:, n + 1, :n] = fx, fx
            a[:, :n, n + 2], a[:, n + 2, :n] = fy, fy
            # drift at the query point is (0, 0) in query-centred coordinates
        sol = _batched_solve(a, b)
        zhat = np.einsum("ij,ij->i", sol[:, :n], self.z[idx])
        var = np.einsum("ij,ij->i", sol, b)
        return zhat, np.maximum(var, 0.0)

    def _global_factor(self):
        if self._lu is None:
            import scipy.linalg
            n, e = self.n_points, self.n_extra
            xy = np.column_stack([self.x, self.y])
            from scipy.spatial.distance import cdist
            a = np.zeros((n + e, n + e))
            a[:n, :n] = self.variogram(cdist(xy, xy))
            np.fill_diagonal(a[:n, :n], 0.0)
            a[:n, n] = a[n, :n] = 1.0
            if self.drift == "linear":
                a[:n, n + 1] = a[n + 1, :n] = self.x
                a[:n, n + 2] = a[n + 2, :n] = self.y
            try:
                self._lu = scipy.linalg.lu_factor(a, check_finite=False)
            except (np.linalg.LinAlgError, ValueError) as exc:
                raise InputError("The global kriging system is singular ({error}); use "
                                 "fewer neighbours or add a nugget.", error=exc) from exc
        return self._lu

    def _solve_global(self, qx, qy) -> Tuple[np.ndarray, np.ndarray]:
        import scipy.linalg
        from scipy.spatial.distance import cdist
        n, e = self.n_points, self.n_extra
        d0 = cdist(np.column_stack([qx, qy]), np.column_stack([self.x, self.y]))
        b = np.zeros((qx.size, n + e))
        g0 = self.variogram(d0)
        g0[d0 <= EPS] = 0.0
        b[:, :n] = g0
        b[:, n] = 1.0
        if self.drift == "linear":
            b[:, n + 1] = qx
            b[:, n + 2] = qy
        sol = scipy.linalg.lu_solve(self._global_factor(), b.T, check_finite=False).T
        zhat = sol[:, :n] @ self.z
        var = np.einsum("ij,ij->i", sol, b)
        return zhat, np.maximum(var, 0.0)

    # ---------------------------------------------------------------- public
    def predict(self, xq, yq, *, max_distance: Optional[float] = None,
                progress=None, cancel=None) -> Tuple[np.ndarray, np.ndarray]:
        """Estimates and kriging variances at points ``(xq, yq)`` (CRS coordinates).

        Points whose nearest data point is farther than ``max_distance`` get NaN.
        """
        mon = Monitor(progress, cancel)
        qx = np.asarray(xq, np.float64).ravel() - self.x0
        qy = np.asarray(yq, np.float64).ravel() - self.y0
        out = np.full(qx.size, np.nan)
        var = np.full(qx.size, np.nan)
        step = self.block_cells() if not self.is_global else 2048
        for s0 in range(0, qx.size, step):
            s1 = min(qx.size, s0 + step)
            bx, by = qx[s0:s1], qy[s0:s1]
            if self.is_global and max_distance is None:
                ok = np.ones(bx.size, bool)
            else:
                k = 1 if self.is_global else self.n_closest
                d, idx = self.tree.query(np.column_stack([bx, by]), k=k,
                                         workers=self.workers)
                d = d.reshape(bx.size, -1)
                idx = idx.reshape(bx.size, -1)
                ok = np.ones(bx.size, bool) if max_distance is None else \
                    d[:, 0] <= max_distance
            if ok.any():
                if self.is_global:
                    zz, vv = self._solve_global(bx[ok], by[ok])
                else:
                    zz, vv = self._solve_local(bx[ok], by[ok], d[ok], idx[ok])
                tmp_z = np.full(bx.size, np.nan)
                tmp_v = np.full(bx.size, np.nan)
                tmp_z[ok], tmp_v[ok] = zz, vv
                out[s0:s1], var[s0:s1] = tmp_z, tmp_v
            mon.step(s1 / qx.size)
        return out, var

    def check_cross_validation(self) -> None:
        """Refuse leave-one-out cross-validation here (:func:`check_cross_validation`)."""
        check_cross_validation(self.n_closest, self.n_points)

    def cross_validate(self, n: int = 1000, *, seed: int = 0) -> Dict[str, float]:
        """Leave-one-out cross-validation on a random subsample of ``n`` points.

        Each selected point is predicted from its ``n_closest`` nearest *other*
        points with the same variogram. Returns ``n``, ``me`` (mean error,
        estimate − observed), ``rmse``, ``mae``, ``mse_std`` (mean standardised
        error, ideally 0), ``rmsse`` (root mean square standardised error, ideally 1).
        """
        n = int(min(n, self.n_points))
        if n < 1:
            raise InputError("cross-validation needs at least one point.")
        self.check_cross_validation()
        rng = np.random.default_rng(seed)
        sel = np.sort(rng.choice(self.n_points, n, replace=False))
        qx, qy = self.x[sel], self.y[sel]
        errs, stds = [], []
        step = self.block_cells()
        for s0 in range(0, n, step):
            s1 = min(n, s0 + step)
            d, idx = self.tree.query(np.column_stack([qx[s0:s1], qy[s0:s1]]),
                                     k=self.n_closest + 1, workers=self.workers)
            own = idx == sel[s0:s1, None]
            # drop the point itself (distance 0: the first column after merging)
            keep = ~own
            keep[~own.any(axis=1), -1] = False
            d = d[keep].reshape(s1 - s0, self.n_closest)
            idx = idx[keep].reshape(s1 - s0, self.n_closest)
            zz, vv = self._solve_local(qx[s0:s1], qy[s0:s1], d, idx)
            errs.append(zz - self.z[sel[s0:s1]])
            stds.append(np.sqrt(vv))
        err = np.concatenate(errs)
        std = np.concatenate(stds)
        with np.errstate(divide="ignore", invalid="ignore"):
            zs = err / std
        zs = zs[np.isfinite(zs)]
        return {"n": int(n), "me": float(err.mean()), "rmse": float(np.sqrt(np.mean(err ** 2))),
                "mae": float(np.mean(np.abs(err))),
                "mse_std": float(zs.mean()) if zs.size else float("nan"),
                "rmsse": float(np.sqrt(np.mean(zs ** 2))) if zs.size else float("nan")}


def check_neighbours(n_closest: int, n_points: int, drift: str) -> None:
    """Refuse a neighbourhood kriging cannot be solved with, naming the user's parameters.

    The messages name the kriging algorithm's parameters (Neighbours per cell,
    ``NEIGHBOURS``; ``KRIGING_TYPE``), which is what the user can change; ``n_closest``
    is the same number in this module.

    Raises
    ------
    InputError
        Fewer neighbours than the kriging system needs (2 ordinary, 4 universal), fewer
        distinct points than that, or more neighbours than distinct points.

    Examples
    --------
    >>> check_neighbours(16, 100, "none")
    >>> try:
    ...     check_neighbours(16, 10, "none")
    ... except InputError as e:
    ...     print(str(e).split(": ")[1])
    set NEIGHBOURS to 10 or fewer, or use a cloud with more ground points.
    """
    if drift == "linear":
        if n_points < 4:
            raise InputError("Universal kriging (KRIGING_TYPE 1) needs at least 4 distinct "
                             "point positions, got {n}: choose ordinary kriging "
                             "(KRIGING_TYPE 0) or use a cloud with more ground points.",
                             n=n_points)
        if n_closest < 4:
            raise InputError("Universal kriging (KRIGING_TYPE 1) needs at least 4 "
                             "Neighbours per cell (NEIGHBOURS), got {value}: set NEIGHBOURS "
                             "to 4 or more, or choose ordinary kriging (KRIGING_TYPE 0).",
                             value=n_closest)
    elif n_closest < 2:
        raise InputError("Ordinary kriging needs at least 2 Neighbours per cell "
                         "(NEIGHBOURS), got {value}: set NEIGHBOURS to 2 or more.",
                         value=n_closest)
    if n_closest > n_points:
        raise InputError("Only {n} distinct point positions to krige from, but Neighbours "
                         "per cell (NEIGHBOURS) is {k}: set NEIGHBOURS to {n} or fewer, or "
                         "use a cloud with more ground points.", n=n_points, k=n_closest)


def check_cross_validation(n_closest: int, n_points: int) -> None:
    """Refuse leave-one-out cross-validation when no point can be left out.

    Raises
    ------
    InputError
        Naming NEIGHBOURS and CV_POINTS (the kriging algorithm's parameters).
    """
    if n_closest >= n_points:
        raise InputError("Cross-validation (CV_POINTS) leaves each point out, so "
                         "Neighbours per cell (NEIGHBOURS = {k}) must be fewer than the "
                         "{n} distinct point positions: set NEIGHBOURS to {m} or fewer, "
                         "or CV_POINTS to 0.", k=n_closest, n=n_points, m=n_points - 1)


def single_threaded_blas():
    """Run small batched LAPACK solves with one BLAS thread (:func:`..system.limit_blas_threads`).

    OpenBLAS otherwise starts its thread pool for every 17×17 system, which on a
    loaded machine makes ``numpy.linalg.solve`` over 10⁵ tiny systems 10–20× slower.
    """
    return limit_blas_threads(1)


def _batched_solve(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Solve ``a[i] @ s[i] = b[i]``; singular systems fall back to least squares."""
    try:
        with single_threaded_blas():
            return np.linalg.solve(a, b[..., None])[..., 0]
    except np.linalg.LinAlgError:
        out = np.empty_like(b)
        for i in range(a.shape[0]):
            try:
                out[i] = np.linalg.solve(a[i], b[i])
            except np.linalg.LinAlgError:
                out[i] = np.linalg.lstsq(a[i], b[i], rcond=None)[0]
        return out

"""Variogram models and their least-squares fit, in PyKrige's parameter convention.

The five models of Kitanidis (1997) with the parameterisation PyKrige (Murphy et al.
2022) uses — ``[slope, nugget]`` (linear), ``[scale, exponent, nugget]`` (power),
``[partial sill, range, nugget]`` (gaussian, spherical, exponential; ``range`` is the
practical range: the exponential model reaches 95 % of its sill at ``range``) — and
PyKrige's estimator: ``scipy.optimize.least_squares`` with a soft-L1 loss from PyKrige's
starting point within PyKrige's bounds, optionally with its logistic weighting of the
short lags. Written here so that kriging needs nothing beyond numpy and scipy (QGIS
ships both); ``tests/core/test_kriging.py`` checks every function against PyKrige.

References
----------
Kitanidis, P.K. (1997). Introduction to Geostatistics: Applications in Hydrogeology.
Cambridge University Press. Chapter 2 (variogram models).
Murphy, B., Yurchak, R., Müller, S. (2022). GeoStat-Framework/PyKrige v1.7
(``variogram_models``, ``core._calculate_variogram_model``).

Examples
--------
>>> float(spherical([2.0, 10.0, 0.5], np.array([10.0]))[0])
2.5
>>> float(exponential([1.0, 3.0, 0.0], np.array([3.0]))[0])   # 1 - e^-3 of the sill
0.950212931632136
"""
from __future__ import annotations

from typing import Callable, Dict, Tuple

import numpy as np
from scipy.optimize import least_squares


def linear(params, d):
    """``slope · d + nugget``; params ``[slope, nugget]``."""
    slope, nugget = float(params[0]), float(params[1])
    return slope * d + nugget


def power(params, d):
    """``scale · d^exponent + nugget``; params ``[scale, exponent, nugget]``."""
    scale, exponent, nugget = (float(v) for v in params[:3])
    return scale * d ** exponent + nugget


def gaussian(params, d):
    """``psill · (1 − exp(−d² / (4/7 · range)²)) + nugget``."""
    psill, range_, nugget = (float(v) for v in params[:3])
    return psill * (1.0 - np.exp(-(d ** 2.0) / (range_ * 4.0 / 7.0) ** 2.0)) + nugget


def exponential(params, d):
    """``psill · (1 − exp(−3 d / range)) + nugget``."""
    psill, range_, nugget = (float(v) for v in params[:3])
    return psill * (1.0 - np.exp(-d / (range_ / 3.0))) + nugget


def spherical(params, d):
    """``psill · (1.5 h − 0.5 h³) + nugget`` for ``h = d / range ≤ 1``, the sill beyond."""
    psill, range_, nugget = (float(v) for v in params[:3])
    d = np.asarray(d, dtype=float)
    inside = psill * ((3.0 * d) / (2.0 * range_) - (d ** 3.0) / (2.0 * range_ ** 3.0)) + nugget
    return np.where(d <= range_, inside, psill + nugget)


MODEL_FUNCTIONS: Dict[str, Callable] = {"linear": linear, "power": power,
                                        "gaussian": gaussian, "spherical": spherical,
                                        "exponential": exponential}


def _residuals(params, lags, semi, func, weight):
    resid = func(params, lags) - semi
    if weight:   # logistic weights: ~1 at short lags, ~0 at the longest, centre at 70 %
        span = np.amax(lags) - np.amin(lags)
        k = 2.1972 / (0.1 * span)
        centre = 0.7 * span + np.amin(lags)
        w = 1.0 / (1.0 + np.exp(-k * (centre - lags)))
        resid = resid * (w / np.sum(w))
    return resid


def fit_model(lags, semivariance, model: str, func: Callable, weight: bool) -> np.ndarray:
    """Least-squares fit of ``func`` to a binned semivariogram (PyKrige's estimator).

    Bounds keep the partial sill, range and nugget non-negative, the nugget below the
    largest semivariance, the range within the largest lag and the power exponent in
    ``[0.001, 1.999]``.
    """
    lags = np.asarray(lags, dtype=float)
    semi = np.asarray(semivariance, dtype=float)
    smax, smin = float(np.amax(semi)), float(np.amin(semi))
    lmax, lmin = float(np.amax(lags)), float(np.amin(lags))
    if model == "linear":
        x0 = [(smax - smin) / (lmax - lmin), smin]
        bounds = ([0.0, 0.0], [np.inf, smax])
    elif model == "power":
        x0 = [(smax - smin) / (lmax - lmin), 1.1, smin]
        bounds = ([0.0, 0.001, 0.0], [np.inf, 1.999, smax])
    else:
        x0 = [smax - smin, 0.25 * lmax, smin]
        bounds = ([0.0, 0.0, 0.0], [10.0 * smax, lmax, smax])
    res = least_squares(_residuals, x0, bounds=bounds, loss="soft_l1",
                        args=(lags, semi, func, weight))
    return res.x


def all_pairs_semivariogram(xy: np.ndarray, z: np.ndarray,
                            nlags: int) -> Tuple[np.ndarray, np.ndarray]:
    """Return the binned semivariogram ``lags, semi`` of every pair of points.

    ``nlags`` equal bins from the shortest to the longest distance (PyKrige's binning);
    empty bins are dropped.
    """
    from scipy.spatial.distance import pdist
    d = pdist(xy)
    g = 0.5 * pdist(np.asarray(z, dtype=float)[:, None], metric="sqeuclidean")
    dmin, dmax = float(np.amin(d)), float(np.amax(d))
    step = (dmax - dmin) / nlags
    edges = [dmin + n * step for n in range(nlags)] + [dmax + 0.001]
    lags, semi = [], []
    for lo, hi in zip(edges[:-1], edges[1:]):
        sel = (d >= lo) & (d < hi)
        if np.any(sel):
            lags.append(float(np.mean(d[sel])))
            semi.append(float(np.mean(g[sel])))
    return np.asarray(lags), np.asarray(semi)

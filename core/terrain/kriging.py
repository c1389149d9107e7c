"""Ordinary and universal kriging for LiDAR-size point sets.

Kriging (Matheron 1963; Cressie 1993) estimates ``z*(s0) = Σ λ_i z(s_i)`` with the
weights of the best linear unbiased predictor under a variogram model ``γ(h)``:

* **ordinary kriging** (OK): unknown constant mean, ``Σ λ_i = 1``;
* **universal kriging** (UK) with a linear drift: mean ``a + b·x + c·y``, constraints
  ``Σ λ_i = 1, Σ λ_i x_i = x0, Σ λ_i y_i = y0``.

The kriging variance ``σ²(s0) = Σ λ_i γ(s_i − s0) + μᵀ f(s0)`` is returned with every
estimate.

Why not plain PyKrige: ``pykrige.ok.OrdinaryKriging`` builds the full ``n × n``
distance matrix both to fit the variogram and to predict (even with
``n_closest_points``), which needs 8 TB for 1 M points. Here

1. the variogram is fitted **with PyKrige's estimator** (binned experimental
   semivariogram + ``scipy.optimize.least_squares`` with a soft-L1 loss, PyKrige's
   bounds; re-implemented in :mod:`.variogram`, so kriging needs only numpy and
   scipy, and checked against PyKrige by the tests) on pairs drawn around
   ``fit_points`` random points (default 3000) up to
   the distances local kriging actually uses (three times the typical distance to
   the ``n_closest``-th neighbour), so that the nugget and the short-range shape —
   which set the weights and the variance — are well sampled; or taken from the
   user (nugget / sill / range);
2. prediction is done in **local neighbourhoods** (the ``n_closest`` points of each
   cell, from a KD-tree): for every cell a small kriging system is assembled and all
   systems of a block of cells are solved at once with a batched LAPACK solve
   (``numpy.linalg.solve``), so memory is bounded by the block and time grows
   linearly with the number of cells;
3. when ``n_closest`` equals the number of points, the single global system is
   factorised once and solved for all cells, which is exactly PyKrige's global
   ordinary/universal kriging (same matrices, same variogram functions).

What is approximated, honestly: (a) the variogram is fitted on a sample of pairs, so
the fitted nugget/sill/range vary slightly with it (fixed by ``seed``), and by default
only at local lags: the "sill" and "range" then describe the local scale, not the
whole field (choose ``max_lag='half'`` for the classical field-scale fit);
(b) local-neighbourhood kriging is not global kriging: only the ``n_closest`` nearest
points are weighted and the unknown mean is re-estimated in every neighbourhood
(quasi-stationarity, Journel & Huijbregts 1978). On terrain this follows the relief
better than one global mean (lowest hold-out RMSE on the four ISPRS samples in
``benchmarks/results/dtm.md``), but the two differ — by centimetres typically, by
decimetres to metres at borders, gaps and steep slopes; (c) with a linear drift the
variogram is fitted on the residuals of a least-squares plane, not jointly with the
drift (the usual practical shortcut, biased for strong trends); (d) points with
identical (x, y) are merged (mean height) because they make the kriging system
singular.

References
----------
Sepehr journal (~2020, in Persian): DTM of a Zagros forest (Doroud, Lorestan) from
airborne LiDAR by IDW (powers 2 and 3) and kriging, judged on check points — the
spec this module implements (``shared/docs/seeds/02-slope-filter-idw-kriging.md``).
Matheron, G. (1963). Principles of geostatistics. Economic Geology 58(8), 1246–1266.
Cressie, N. (1993). Statistics for Spatial Data, revised ed. Wiley. §3.2–3.4.
Journel, A.G., Huijbregts, C.J. (1978). Mining Geostatistics. Academic Press
(maximum lag of half the field size for the experimental variogram).
Murphy, B., Yurchak, R., Müller, S. (2022). GeoStat-Framework/PyKrige v1.7.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Dict, Optional, Sequence, Tuple, Union

import numpy as np
from scipy.spatial import cKDTree

from ..errors import InputError
from ..progress import Monitor
from . import variogram as variogram_models
from ._kriging_base import (  # noqa: F401 - the public names of this module
    DRIFTS,
    EPS,
    GLOBAL_MAX_POINTS,
    MODELS,
    Variogram,
    _check_xyz,
    merge_duplicates,
    variogram_function,
)
from ._kriging_system import (  # noqa: F401
    Kriging,
    check_cross_validation,
    check_neighbours,
    single_threaded_blas,
)
from .grid import GridSpec, check_memory, distance_mask, resolve_max_distance, row_blocks


def _plane_residuals(x, y, z):
    a = np.column_stack([np.ones_like(x), x - x.mean(), y - y.mean()])
    coef, *_ = np.linalg.lstsq(a, z, rcond=None)
    return z - a @ coef


def _bin_and_fit(d, g, used_lag, nlags, model, func, weight):
    edges = np.linspace(0.0, used_lag, nlags + 1)
    which = np.clip(np.searchsorted(edges, d, side="right") - 1, 0, nlags - 1)
    cnt = np.bincount(which, minlength=nlags)
    lags = np.bincount(which, weights=d, minlength=nlags)
    semi = np.bincount(which, weights=g, minlength=nlags)
    ok = cnt > 0
    lags, semi = lags[ok] / cnt[ok], semi[ok] / cnt[ok]
    if lags.size < 3:
        raise InputError("Only {n} of the {nlags} lag classes hold point pairs, too few "
                         "to fit a variogram (3 are needed): give a larger Maximum lag "
                         "(MAX_LAG), more Lag classes (NLAGS) or more Points for the "
                         "variogram fit (FIT_POINTS).", n=int(lags.size), nlags=nlags)
    return lags, semi, variogram_models.fit_model(lags, semi, model, func, weight)


def _resolve_lag(xy, sel, mode, max_lag, n_neighbours) -> Optional[float]:
    """Return the maximum lag of a fit: local scale ('auto'), a value, or None ('half')."""
    if mode == "auto":
        n = xy.shape[0]
        k = int(min(n - 1, max(2, n_neighbours)))
        dk, _ = cKDTree(xy).query(xy[sel], k=k + 1)
        used_lag = 3.0 * float(np.median(dk[:, -1]))
        if not used_lag > 0:
            raise InputError("All points coincide; a variogram cannot be fitted.")
        return used_lag
    if mode == "value":
        used_lag = float(max_lag)
        if not math.isfinite(used_lag) or used_lag <= 0:
            raise InputError("max_lag must be > 0, got {value}.", value=max_lag)
        return used_lag
    return None


def _sample_pairs(xy, z, sel, mode, used_lag):
    """Return distances and semivariances ``½(z_i − z_j)²`` of the fitting pairs.

    Pairs are every point within ``used_lag`` of each anchor ``sel`` when few enough,
    otherwise every pair among the anchors (up to ``used_lag``; half the largest
    distance when ``used_lag`` is None). Returns ``d, g, used_lag``.
    """
    n = xy.shape[0]
    area = max(float(np.ptp(xy[:, 0])) * float(np.ptp(xy[:, 1])), 1e-12)
    expected = n / area * math.pi * used_lag ** 2 if used_lag else np.inf
    if mode in ("auto", "value") and expected <= 2000:
        lists = cKDTree(xy).query_ball_point(xy[sel], used_lag)
        counts = np.fromiter((len(v) for v in lists), np.int64, sel.size)
        ii = np.repeat(sel, counts)
        jj = (np.fromiter((j for v in lists for j in v), np.int64, int(counts.sum()))
              if counts.sum() else np.empty(0, np.int64))
        keep = jj != ii
        ii, jj = ii[keep], jj[keep]
        d = np.hypot(xy[ii, 0] - xy[jj, 0], xy[ii, 1] - xy[jj, 1])
        return d, 0.5 * (z[ii] - z[jj]) ** 2, used_lag
    from scipy.spatial.distance import pdist
    d = pdist(xy[sel])
    g = 0.5 * pdist(z[sel][:, None], metric="sqeuclidean")
    if used_lag is None:
        used_lag = 0.5 * float(d.max())
    keep = d <= used_lag
    return d[keep], g[keep], used_lag


def fit_variogram(x, y, z, *, model: str = "spherical", fit_points: int = 3000,
                  nlags: int = 12, max_lag: Union[None, float, str] = "auto",
                  n_neighbours: int = 16, weight: bool = False, detrend: bool = False,
                  nugget_floor: float = 0.01, seed: int = 0) -> Variogram:
    """Fit a variogram model with PyKrige's estimator on a sample of point pairs.

    The experimental semivariogram ``γ(h) = ½ mean (z_i − z_j)²`` of pairs binned by
    distance is fitted with PyKrige's routine (``scipy.optimize.least_squares``,
    soft-L1 loss, PyKrige's bounds; the range is bounded by the largest lag).

    Parameters
    ----------
    x, y, z : array_like
        Points.
    model : {'linear', 'power', 'gaussian', 'spherical', 'exponential'}
    fit_points : int
        Number of randomly chosen points the pairs are drawn from (all points if
        fewer).
    nlags : int
        Number of equal-width lag bins between 0 and ``max_lag``.
    max_lag : 'auto', 'half', float or None
        ``'auto'`` (default): the scale local kriging actually uses — three times the
        median distance from a point to its ``n_neighbours``-th neighbour; pairs are
        every point within that distance of each of ``fit_points`` random anchor
        points, so short lags (and hence the nugget) are well sampled. ``'half'``:
        half the largest distance between ``fit_points`` random points (Journel &
        Huijbregts 1978), all pairs among them. A number: that lag (anchor pairs when
        they are few enough, otherwise all pairs of a random subsample). ``None``:
        every pair of a random subsample, binned exactly as PyKrige does (from the
        smallest to the largest distance).
    n_neighbours : int
        Neighbourhood size the ``'auto'`` lag is derived from.
    weight : bool
        PyKrige's logistic weighting favouring short lags.
    detrend : bool
        Fit on the residuals of a least-squares plane (for universal kriging).
    nugget_floor : float
        The fitted nugget is raised to at least this fraction of the model
        semivariance at ``max_lag`` (default 1 %; not with ``max_lag=None``). Without
        it the fit often returns a zero nugget for LiDAR terrain, and the Gaussian and
        power (exponent → 2) models then give near-singular kriging systems
        (leave-one-out RMSE ×20, standardised errors in the hundreds).
    seed : int
        Seed of the random choice of points.
    """
    func = variogram_function(model)
    x, y, z = _check_xyz(x, y, z)
    fit_points = int(fit_points)
    if fit_points < 10:
        raise InputError("fit_points must be at least 10, got {value}.", value=fit_points)
    nlags = int(nlags)
    if nlags < 2:
        raise InputError("nlags must be at least 2, got {value}.", value=nlags)
    if detrend:
        z = _plane_residuals(x, y, z)
    rng = np.random.default_rng(seed)
    n = x.size
    sel = (np.sort(rng.choice(n, fit_points, replace=False)) if n > fit_points
           else np.arange(n))
    x0, y0 = float(x.mean()), float(y.mean())
    xy = np.column_stack([x - x0, y - y0])
    mode = max_lag if isinstance(max_lag, str) or max_lag is None else "value"
    if mode not in ("auto", "half", "value", None):
        raise InputError("max_lag must be 'auto', 'half', a distance or None; got {value}.",
                         value=repr(max_lag))
    if mode is None:
        lags, semi = variogram_models.all_pairs_semivariogram(xy[sel], z[sel], nlags)
        params = variogram_models.fit_model(lags, semi, model, func, weight)
        used_lag = None
        n_pairs = sel.size * (sel.size - 1) // 2
    else:
        used_lag = _resolve_lag(xy, sel, mode, max_lag, n_neighbours)
        d, g, used_lag = _sample_pairs(xy, z, sel, mode, used_lag)
        if d.size < nlags:
            raise InputError("Only {n} point pairs are closer than the maximum lag "
                             "({lag} m), fewer than the {nlags} lag classes: give a larger "
                             "Maximum lag (MAX_LAG) or more Points for the variogram fit "
                             "(FIT_POINTS), or give the variogram's sill and range.",
                             n=int(d.size), lag=f"{used_lag:g}", nlags=nlags)
        if not np.any(g > 0):
            raise InputError("The heights do not vary between the sampled point pairs, so "
                             "no variogram can be fitted; give the variogram parameters or "
                             "use the IDW DTM.")
        n_pairs = int(d.size)
        lags, semi, params = _bin_and_fit(d, g, used_lag, nlags, model, func, weight)
    params = [float(v) for v in params]
    floored = False
    if mode is not None and nugget_floor > 0:
        top = float(func(params, np.array([used_lag]))[0])
        if params[-1] < nugget_floor * top:
            params[-1] = nugget_floor * top
            floored = True
    return Variogram(model=model, params=params, fitted=True, n_fit=int(sel.size),
                     max_lag=used_lag, lags=np.asarray(lags), semivariance=np.asarray(semi),
                     n_pairs=int(n_pairs), nugget_floored=floored)


def given_variogram(model: str, *, nugget: float = 0.0, sill: Optional[float] = None,
                    range_: Optional[float] = None, slope: Optional[float] = None,
                    scale: Optional[float] = None,
                    exponent: Optional[float] = None) -> Variogram:
    """Return a user-specified variogram (sill is the total sill, nugget included)."""
    variogram_function(model)
    nugget = float(nugget)
    if not math.isfinite(nugget) or nugget < 0:
        raise InputError("nugget must be >= 0, got {value}.", value=nugget)
    if model == "linear":
        if slope is None or not slope >= 0:
            raise InputError("The linear variogram needs a slope (VARIOGRAM_SLOPE) of 0 or "
                             "more: give VARIOGRAM_SLOPE in m²/m, or leave every variogram "
                             "number empty to fit the variogram.")
        return Variogram(model, [float(slope), nugget])
    if model == "power":
        if scale is None or not scale > 0 or exponent is None or not 0 < exponent < 2:
            raise InputError("The power variogram needs a scale (VARIOGRAM_SCALE) above 0 "
                             "and an exponent (VARIOGRAM_EXPONENT) between 0 and 2, both "
                             "excluded: give both, or leave every variogram number empty to "
                             "fit the variogram.")
        return Variogram(model, [float(scale), float(exponent), nugget])
    if sill is None or range_ is None:
        raise InputError("This variogram model needs both the sill (VARIOGRAM_SILL) and the "
                         "range (VARIOGRAM_RANGE), the nugget (VARIOGRAM_NUGGET) being "
                         "optional: give both, or leave every variogram number empty to fit "
                         "the variogram.")
    if not sill > nugget:
        raise InputError("The sill (VARIOGRAM_SILL = {sill}) must be larger than the nugget "
                         "(VARIOGRAM_NUGGET = {nugget}): the sill includes the nugget.",
                         sill=sill, nugget=nugget)
    if not range_ > 0:
        raise InputError("The range (VARIOGRAM_RANGE) must be > 0 m, got {value}.",
                         value=range_)
    return Variogram(model, [float(sill) - nugget, float(range_), nugget])


@dataclass
class KrigingResult:
    """Output of :func:`kriging_grid`."""

    z: np.ndarray
    variance: np.ndarray
    variogram: Variogram
    drift: str
    n_closest: int
    n_points: int
    n_merged: int
    max_distance: Optional[float]
    cross_validation: Optional[Dict[str, float]] = None

    @property
    def std(self) -> np.ndarray:
        """Return the kriging standard deviation (square root of the variance)."""
        return np.sqrt(self.variance)


def kriging_grid(x, y, z, grid: GridSpec, *, model: str = "spherical",
                 variogram: Optional[Variogram] = None, drift: str = "none",
                 n_closest: int = 16, fit_points: int = 3000, nlags: int = 12,
                 max_lag: Union[None, float, str] = "auto", weight: bool = False,
                 max_distance: Optional[float] = None, fill: bool = False,
                 cv_points: int = 0, seed: int = 0, workers: int = -1,
                 memory_limit: Optional[int] = None, progress=None,
                 cancel=None) -> KrigingResult:
    """Krige points onto ``grid`` with a variance raster (see module docstring).

    Parameters
    ----------
    x, y, z : array_like
        Points (e.g. ground returns).
    grid : GridSpec
        Target grid (values at cell centres).
    model : str
        Variogram model to fit (ignored when ``variogram`` is given).
    variogram : Variogram, optional
        User parameters (:func:`given_variogram`); otherwise fitted.
    drift : {'none', 'linear'}
        Ordinary or universal (linear drift) kriging.
    n_closest : int
        Neighbours per cell (default 16).
    fit_points, nlags, max_lag, weight, seed
        Variogram fitting, see :func:`fit_variogram`.
    max_distance : float, optional
        Cells farther than this from any point are nodata; default
        :func:`.grid.default_max_distance`; ignored when ``fill``.
    cv_points : int
        Leave-one-out cross-validation on this many random points (0 = off).
    progress, cancel : callable, optional
        See :class:`~.progress.Monitor`.

    Returns
    -------
    KrigingResult
        ``z`` and ``variance`` arrays of ``grid.shape`` (NaN = nodata), the variogram,
        and the cross-validation summary when asked.
    """
    mon = Monitor(progress, cancel)
    check_memory(grid, arrays=2, limit=memory_limit)
    x, y, z = _check_xyz(x, y, z)
    mon.step(0.0)
    if variogram is None and float(np.ptp(z)) == 0.0:
        return _flat_result(x, y, z, grid, model=model, drift=drift, n_closest=n_closest,
                            max_distance=max_distance, fill=fill, cv_points=cv_points,
                            workers=workers, mon=mon)
    # the neighbourhood before the variogram fit, whose own refusal would hide it; the
    # distinct positions are counted only when they may matter (few points)
    n_closest = int(n_closest)
    few = n_closest >= x.size
    n_distinct = merge_duplicates(x, y, z)[0].size if few else x.size
    check_neighbours(n_closest, n_distinct, drift)
    if int(cv_points) > 0:
        check_cross_validation(n_closest, n_distinct)
    if variogram is None:
        variogram = fit_variogram(x, y, z, model=model, fit_points=fit_points, nlags=nlags,
                                  max_lag=max_lag, n_neighbours=n_closest, weight=weight,
                                  detrend=(drift == "linear"), seed=seed)
    mon.step(0.05)
    kr = Kriging(x, y, z, variogram=variogram, drift=drift, n_closest=n_closest,
                 workers=workers)
    cv = None
    cv_points = int(cv_points)
    if cv_points > 0:
        kr.check_cross_validation()         # before the grid, not after it
    max_distance = resolve_max_distance(grid, kr.n_points, max_distance, fill=fill)
    sub = mon.sub(0.1, 0.95 if cv_points else 1.0)
    zg = np.full(grid.shape, np.nan)
    vg = np.full(grid.shape, np.nan)
    cells = max(kr.block_cells() * 4, grid.ncols)
    for r0, r1 in row_blocks(grid.nrows, grid.ncols, cells):
        xx, yy = grid.block_centers(r0, r1)
        zz, vv = kr.predict(xx, yy, max_distance=max_distance, cancel=cancel)
        zg[r0:r1] = zz.reshape(r1 - r0, -1)
        vg[r0:r1] = vv.reshape(r1 - r0, -1)
        sub.step(r1 / grid.nrows)
    if cv_points > 0:
        cv = kr.cross_validate(cv_points, seed=seed)
    mon.step(1.0)
    return KrigingResult(z=zg, variance=vg, variogram=variogram, drift=drift,
                         n_closest=kr.n_closest, n_points=kr.n_points,
                         n_merged=kr.n_merged, max_distance=max_distance,
                         cross_validation=cv)


def _flat_result(x, y, z, grid: GridSpec, *, model, drift, n_closest, max_distance, fill,
                 cv_points, workers, mon) -> KrigingResult:
    """Kriging of flat ground (every height equal): that height, with zero variance.

    Any variogram gives weights summing to one, so the estimate is the common height;
    the fitted variogram is identically zero (no spatial variation), hence zero
    kriging variance and zero cross-validation error.
    """
    xu, yu, zu, merged = merge_duplicates(x, y, z)
    max_distance = resolve_max_distance(grid, xu.size, max_distance, fill=fill)
    zg = np.full(grid.shape, float(z[0]))
    if max_distance is not None:
        tree = cKDTree(np.column_stack([xu, yu]))
        zg[~distance_mask(tree, grid, max_distance, workers=workers)] = np.nan
    vg = np.where(np.isfinite(zg), 0.0, np.nan)
    params = {"linear": [0.0, 0.0], "power": [0.0, 1.0, 0.0]}.get(model, [0.0, 0.0, 0.0])
    vario = Variogram(model=model, params=params, fitted=True, n_fit=int(xu.size))
    cv = None
    if int(cv_points) > 0:
        n = int(min(int(cv_points), xu.size))
        cv = {"n": n, "me": 0.0, "rmse": 0.0, "mae": 0.0, "mse_std": math.nan,
              "rmsse": math.nan}
    mon.step(1.0)
    return KrigingResult(z=zg, variance=vg, variogram=vario, drift=drift,
                         n_closest=int(min(n_closest, xu.size)), n_points=int(xu.size),
                         n_merged=merged, max_distance=max_distance, cross_validation=cv)


def parse_variogram_parameters(text: str, model: str) -> Optional[Variogram]:
    """Parse ``'nugget=0.01, sill=2, range=50'`` (or slope/scale/exponent) text."""
    text = (text or "").strip()
    if not text:
        return None
    vals: Dict[str, float] = {}
    for part in text.replace(";", ",").split(","):
        if not part.strip():
            continue
        if "=" not in part:
            raise InputError("Variogram parameters must be name=value pairs, e.g. "
                             "'nugget=0.01, sill=2, range=50'; got {value}.",
                             value=repr(part.strip()))
        k, v = part.split("=", 1)
        try:
            vals[k.strip().lower()] = float(v)
        except ValueError:
            raise InputError("Variogram parameter {name} is not a number: {value}.",
                             name=k.strip(), value=repr(v.strip())) from None
    allowed = {"nugget", "sill", "range", "slope", "scale", "exponent"}
    unknown = set(vals) - allowed
    if unknown:
        raise InputError("Unknown variogram parameter(s) {unknown}; use {allowed}.",
                         unknown=", ".join(sorted(unknown)), allowed=", ".join(sorted(allowed)))
    return given_variogram(model, nugget=vals.get("nugget", 0.0), sill=vals.get("sill"),
                           range_=vals.get("range"), slope=vals.get("slope"),
                           scale=vals.get("scale"), exponent=vals.get("exponent"))


def describe_variogram(v: Variogram) -> Sequence[Tuple[str, str]]:
    """Rows (name, value) for reports."""
    rows = [("model", v.model)]
    rows += [(k.replace("_", " "), f"{val:.6g}") for k, val in v.as_dict().items()]
    rows.append(("source", f"fitted on {v.n_pairs:,} pairs from {v.n_fit:,} random points"
                 if v.fitted else "user given"))
    if v.fitted:
        rows.append(("max lag", "all pairs" if v.max_lag is None else f"{v.max_lag:.6g}"))
        if v.nugget_floored:
            rows.append(("nugget", "raised to 1 % of γ(max lag) for numerical stability"))
    return rows


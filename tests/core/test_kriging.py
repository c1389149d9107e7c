"""Kriging against plain PyKrige (global and moving-window), variance, CV, bad input."""
from __future__ import annotations

import numpy as np
import pytest

from geomatics_toolbox.core.terrain.grid import GridSpec, grid_from_extent
from geomatics_toolbox.core.terrain.kriging import (
    Kriging,
    fit_variogram,
    given_variogram,
    kriging_grid,
    parse_variogram_parameters,
)

pykrige_ok = pytest.importorskip("pykrige.ok")
pykrige_uk = pytest.importorskip("pykrige.uk")


def terrain(n, seed=5, side=200.0):
    rng = np.random.default_rng(seed)
    x = rng.uniform(0, side, n) + 350000
    y = rng.uniform(0, side, n) + 5600000
    z = (420 + 0.04 * (x - 350000) + 3 * np.sin((y - 5600000) / 25)
         + 1.5 * np.cos((x - 350000) / 17) + rng.normal(0, 0.05, n))
    return x, y, z


@pytest.mark.parametrize("model", ["spherical", "exponential", "gaussian", "linear", "power"])
def test_matches_global_pykrige_ok_2k_points(model):
    x, y, z = terrain(2000)
    ok = pykrige_ok.OrdinaryKriging(x, y, z, variogram_model=model)
    grid = grid_from_extent((350000, 350200, 5600000, 5600200), 8.0)
    ref_z, ref_var = ok.execute("grid", grid.x_centers(), grid.y_centers())
    # fit with all points binned as PyKrige does -> same variogram parameters
    res = kriging_grid(x, y, z, grid, model=model, n_closest=2000, fit_points=2000, nlags=6,
                       max_lag=None, fill=True)
    np.testing.assert_allclose(res.variogram.params, ok.variogram_model_parameters,
                               rtol=1e-6, atol=1e-9)
    assert np.max(np.abs(res.z - np.asarray(ref_z))) <= 0.01
    assert np.max(np.abs(res.z - np.asarray(ref_z))) <= 1e-6
    np.testing.assert_allclose(res.variance, np.asarray(ref_var), atol=1e-6)


def test_local_solver_matches_pykrige_moving_window_and_global():
    x, y, z = terrain(300, seed=8)
    v = given_variogram("spherical", nugget=0.01, sill=6.0, range_=90.0)
    params = {"sill": 6.0, "range": 90.0, "nugget": 0.01}
    ok = pykrige_ok.OrdinaryKriging(x, y, z, variogram_model="spherical",
                                    variogram_parameters=params)
    gx = np.arange(350001.0, 350200, 9.0)
    gy = np.arange(5600001.0, 5600200, 9.0)
    ref_z, ref_var = ok.execute("grid", gx, gy, backend="loop", n_closest_points=16)
    xx, yy = np.meshgrid(gx, gy)
    kr = Kriging(x, y, z, variogram=v, n_closest=16)
    zz, vv = kr.predict(xx.ravel(), yy.ravel())
    assert np.max(np.abs(zz - np.asarray(ref_z).ravel())) <= 1e-6
    assert np.max(np.abs(vv - np.asarray(ref_var).ravel())) <= 1e-6
    # the batched local solver with every point as neighbour == PyKrige global OK
    kr_all = Kriging(x, y, z, variogram=v, n_closest=300)
    kr_all.is_global = False
    zz, vv = kr_all.predict(xx.ravel()[:150], yy.ravel()[:150])
    gz, gv = ok.execute("points", xx.ravel()[:150], yy.ravel()[:150])
    assert np.max(np.abs(zz - gz)) <= 1e-6
    assert np.max(np.abs(vv - gv)) <= 1e-6


def test_universal_kriging_linear_drift_matches_pykrige():
    x, y, z = terrain(300, seed=9)
    v = given_variogram("exponential", nugget=0.0, sill=4.0, range_=60.0)
    v = given_variogram("exponential", nugget=0.05, sill=4.0, range_=60.0)
    uk = pykrige_uk.UniversalKriging(x, y, z, variogram_model="exponential",
                                     variogram_parameters={"sill": 4.0, "range": 60.0,
                                                           "nugget": 0.05},
                                     drift_terms=["regional_linear"])
    pts = (np.array([350010.0, 350100.5, 350190.0]), np.array([5600020.0, 5600111.0,
                                                                5600180.5]))
    ref_z, ref_var = uk.execute("points", *pts)
    for is_global in (True, False):
        kr = Kriging(x, y, z, variogram=v, n_closest=300, drift="linear")
        kr.is_global = is_global
        zz, vv = kr.predict(*pts)
        assert np.max(np.abs(zz - ref_z)) <= 1e-5
        assert np.max(np.abs(vv - ref_var)) <= 1e-4


def test_exact_at_data_points_variance_and_gaps():
    x, y, z = terrain(800)
    x[0], y[0] = 350100.5, 5600100.5      # a point on a cell centre
    grid = grid_from_extent((350000, 350300, 5600000, 5600200), 1.0)  # 100 m with no data
    res = kriging_grid(x, y, z, grid, n_closest=12, max_distance=10.0)
    r, c = grid.cell_index([x[0]], [y[0]])[:2]
    assert res.z[r[0], c[0]] == pytest.approx(z[0], abs=1e-9)
    assert res.variance[r[0], c[0]] == pytest.approx(0.0, abs=1e-9)
    assert np.isnan(res.z[:, 230:]).all() and np.isnan(res.variance[:, 230:]).all()
    inner = res.variance[:, :190]
    assert np.all(inner[np.isfinite(inner)] >= 0)
    assert np.nanmax(res.variance) > 0


def test_fitted_parameters_and_cross_validation():
    x, y, z = terrain(3000)
    half = fit_variogram(x, y, z, model="spherical", fit_points=1500, max_lag="half", seed=1)
    d = half.as_dict()
    assert d["sill"] >= d["nugget"] >= 0 and d["range"] > 0 and half.n_fit == 1500
    assert half.max_lag == pytest.approx(0.5 * np.hypot(200, 200), rel=0.05)
    # default: local scale = 3 x median distance to the 16th neighbour
    v = fit_variogram(x, y, z, model="spherical", fit_points=1500, seed=1)
    spacing = np.sqrt(200 * 200 / 3000)
    assert 3 * spacing < v.max_lag < 3 * 4 * spacing and v.n_pairs > 10000
    assert v.nugget >= 0.0099 * (v(np.array([v.max_lag]))[0] - v.nugget)
    kr = Kriging(x, y, z, variogram=v, n_closest=16)
    cv = kr.cross_validate(300, seed=2)
    assert cv["n"] == 300
    # noise sd 0.05 m plus a smooth surface: LOO RMSE must be centimetric, bias ~ 0
    assert 0.03 < cv["rmse"] < 0.2 and abs(cv["me"]) < 0.02
    # the local fit gives more realistic kriging variances (RMS standardised error
    # closer to 1) than the classical half-field fit
    cv_half = Kriging(x, y, z, variogram=half, n_closest=16).cross_validate(300, seed=2)
    assert np.isfinite(cv["mse_std"]) and cv["rmsse"] > 0
    assert abs(np.log(cv["rmsse"])) < abs(np.log(cv_half["rmsse"]))


def test_parse_parameters_and_bad_input():
    v = parse_variogram_parameters("nugget=0.01, sill=2, range=50", "spherical")
    assert v.params == [1.99, 50.0, 0.01]
    with pytest.raises(ValueError, match="sill"):
        parse_variogram_parameters("nugget=3, sill=2, range=50", "spherical")
    with pytest.raises(ValueError, match="name=value"):
        parse_variogram_parameters("2, 50", "spherical")
    x, y, z = terrain(10)
    with pytest.raises(ValueError, match=r"Neighbours per cell \(NEIGHBOURS\) is 16"):
        Kriging(x, y, z, variogram=v, n_closest=16)
    with pytest.raises(ValueError, match="variogram model must be one of"):
        fit_variogram(x, y, z, model="cubic")
    grid = GridSpec(xmin=0.0, ymax=1e7, cell=0.05, ncols=2 * 10**8, nrows=2 * 10**8)
    with pytest.raises(ValueError, match="would need"):
        kriging_grid(x, y, z, grid, variogram=v, n_closest=4)


def test_flat_ground_gives_flat_dtm_with_zero_variance():
    from geomatics_toolbox.core.terrain.grid import grid_from_points
    from geomatics_toolbox.core.terrain.kriging import kriging_grid
    rng = np.random.default_rng(0)
    x, y = rng.uniform(0, 40, 500), rng.uniform(0, 40, 500)
    z = np.full(500, 7.5)
    grid = grid_from_points(x, y, 1.0, crs="EPSG:32632")
    res = kriging_grid(x, y, z, grid, n_closest=8, cv_points=20)
    ok = np.isfinite(res.z)
    assert ok.sum() > 1000 and np.all(res.z[ok] == 7.5)
    assert np.array_equal(ok, np.isfinite(res.variance)) and np.all(res.variance[ok] == 0)
    assert res.variogram.as_dict()["sill"] == 0 and res.cross_validation["rmse"] == 0


def test_neighbour_refusals_name_the_algorithm_parameters():
    """NEIGHBOURS / KRIGING_TYPE / CV_POINTS (what the user sets), never n_closest."""
    v = given_variogram("spherical", nugget=0.0, sill=2.0, range_=50.0)
    x, y, z = terrain(3)
    with pytest.raises(ValueError, match=r"Universal kriging \(KRIGING_TYPE 1\) needs at "
                                         r"least 4 distinct point positions, got 3"):
        Kriging(x, y, z, variogram=v, n_closest=3, drift="linear")
    with pytest.raises(ValueError, match=r"Ordinary kriging needs at least 2 Neighbours per "
                                         r"cell \(NEIGHBOURS\), got 1"):
        Kriging(x, y, z, variogram=v, n_closest=1)
    grid3 = grid_from_extent((x.min(), x.max(), y.min(), y.max()), 5.0)
    with pytest.raises(ValueError, match=r"Only 3 distinct point positions to krige from, "
                                         r"but Neighbours per cell \(NEIGHBOURS\) is 16"):
        kriging_grid(x, y, z, grid3, n_closest=16)       # before the variogram fit's refusal
    x, y, z = terrain(10)
    grid = grid_from_extent((x.min(), x.max(), y.min(), y.max()), 5.0)
    calls = []
    with pytest.raises(ValueError, match=r"set NEIGHBOURS to 9 or fewer, or CV_POINTS to 0"):
        kriging_grid(x, y, z, grid, variogram=v, n_closest=10, cv_points=5,
                     progress=calls.append)
    assert max(calls) < 0.1                 # refused before the grid was kriged
    cv = Kriging(x, y, z, variogram=v, n_closest=9).cross_validate(5)
    assert cv["n"] == 5 and np.isfinite(cv["rmse"])


def test_variogram_fit_refusals_name_the_algorithm_parameters():
    """MAX_LAG / NLAGS / FIT_POINTS (the dialog's), not max_lag / nlags / fit_points."""
    from geomatics_toolbox.core.errors import InputError
    g = np.arange(20.0)
    x, y = (a.ravel() for a in np.meshgrid(g, g))     # a 1 m lattice: pairs at 1, 1.41, 2 …
    z = np.sin(x) + np.cos(y)
    with pytest.raises(InputError, match=r"Only 1 of the 12 lag classes hold point pairs, too "
                                         r"few to fit a variogram \(3 are needed\): give a "
                                         r"larger Maximum lag \(MAX_LAG\)") as info:
        fit_variogram(x, y, z, max_lag=1.2, nlags=12)    # every pair within 1.2 m is at 1 m
    assert "(NLAGS)" in info.value.message("fa") and "MAX_LAG" in info.value.message("ar")
    with pytest.raises(InputError, match=r"Only 0 point pairs are closer than the maximum lag "
                                         r"\(0\.5 m\), fewer than the 12 lag classes"):
        fit_variogram(x, y, z, max_lag=0.5, nlags=12)
    assert fit_variogram(x, y, z, max_lag=5.0, nlags=12).fitted   # the named fix works

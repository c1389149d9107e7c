"""Elevation change: known fill and cut volumes, LoD, noise gives no polygon."""
from __future__ import annotations

import numpy as np
import pytest

from geomatics_toolbox.core.errors import InputError
from geomatics_toolbox.core.io.vector import read_polygons, write_label_polygons
from geomatics_toolbox.core.reporting import render_html
from geomatics_toolbox.core.reporting.i18n import has_translation
from geomatics_toolbox.core.terrain import change

GT = (500000.0, 0.5, 0.0, 4000100.0, 0.0, -0.5)


def _epochs(sigma=0.05, seed=0):
    """200 x 200 cells of 0.5 m: a 2 m fill of 20 x 30 m and a 1 m cut of 15 x 10 m."""
    rng = np.random.default_rng(seed)
    yy, xx = np.mgrid[0:200, 0:200]
    before = 100 + 0.02 * xx + np.sin(yy / 20.0)
    after = before.copy()
    fill = (xx >= 20) & (xx < 60) & (yy >= 30) & (yy < 90)       # 40 x 60 cells = 600 m²
    cut = (xx >= 120) & (xx < 150) & (yy >= 140) & (yy < 160)    # 30 x 20 cells = 150 m²
    after[fill] += 2.0
    after[cut] -= 1.0
    b = before + rng.normal(0, sigma, before.shape)
    a = after + rng.normal(0, sigma, after.shape)
    return b, a, fill, cut


def test_known_fill_and_cut_volumes():
    b, a, fill, cut = _epochs()
    res = change.elevation_change(b, a, 0.5, sigma1=0.05, sigma2=0.05)
    assert res.lod == pytest.approx(1.96 * np.sqrt(2) * 0.05)
    kinds = sorted(r["kind"] for r in res.regions)
    assert kinds == ["cut", "fill"]
    f = next(r for r in res.regions if r["kind"] == "fill")
    c = next(r for r in res.regions if r["kind"] == "cut")
    assert f["volume"] == pytest.approx(2.0 * 600, rel=0.02)
    assert c["volume"] == pytest.approx(-1.0 * 150, rel=0.02)
    assert f["area"] == pytest.approx(600, rel=0.01) and c["area"] == pytest.approx(150, rel=0.01)
    assert f["mean_change"] == pytest.approx(2.0, abs=0.02)
    assert res.fill_volume == f["volume"] and res.cut_volume == c["volume"]
    assert (res.labels == f["id"])[fill].all() and (res.labels == c["id"])[cut].all()


@pytest.mark.parametrize("kind", ["gaussian", "bounded"])
def test_noise_below_the_lod_gives_no_polygon(kind):
    rng = np.random.default_rng(3)
    base = np.full((300, 300), 50.0)
    if kind == "gaussian":   # the stated accuracy: 5 % of cells beyond the LoD
        b, a = base + rng.normal(0, 0.1, base.shape), base + rng.normal(0, 0.1, base.shape)
    else:                    # every difference below the LoD
        b, a = base + rng.uniform(-0.13, 0.13, base.shape), base.copy()
    res = change.elevation_change(b, a, 1.0, sigma1=0.1, sigma2=0.1)
    assert res.regions == [] and not res.labels.any()
    if kind == "gaussian":
        assert (np.abs(res.diff) > res.lod).mean() > 0.03   # the test is not vacuous


def test_polygons_written_with_attributes(tmp_path):
    b, a, fill, cut = _epochs()
    res = change.elevation_change(b, a, 0.5, sigma1=0.05, sigma2=0.05)
    recs = {r["id"]: r for r in res.regions}
    n = write_label_polygons(tmp_path / "c.gpkg", res.labels, GT, crs="EPSG:32632",
                             layer_name="change",
                             fields=[("id", "int"), ("kind", "str"), ("area", "float"),
                                     ("volume", "float")], records=recs)
    assert n == 2
    from osgeo import ogr
    polys = read_polygons(tmp_path / "c.gpkg")
    for attrs, wkt in polys:
        area = ogr.CreateGeometryFromWkt(wkt).GetArea()
        assert area == pytest.approx(attrs["area"])
        assert attrs["volume"] == recs[attrs["id"]]["volume"]


def test_bad_inputs_and_report():
    with pytest.raises(InputError, match="sigma1"):
        change.lod95(-1, 0.1)
    with pytest.raises(InputError, match="different grids"):
        change.elevation_change(np.zeros((3, 3)), np.zeros((3, 4)), 1.0, sigma1=0.1,
                                sigma2=0.1)
    b, a, _, _ = _epochs()
    res = change.elevation_change(b, a, 0.5, sigma1=0.05, sigma2=0.05)
    rep = change.change_report(res, ("a.tif", "b.tif"), 0.05, 0.05)
    missing = {m for m in rep.messages() for lang in ("ar", "fa")
               if not has_translation(m, lang)}
    assert not missing, missing
    html = render_html(rep, lang="ar")
    assert 'id="change-map"' in html and 'id="change-histogram"' in html


def test_sigma_from_residuals_is_their_rmse():
    e = np.array([0.1, -0.2, 0.05, np.nan, 0.3])
    assert change.sigma_from_residuals(e) == pytest.approx(
        np.sqrt(np.mean(np.array([0.1, -0.2, 0.05, 0.3]) ** 2)))
    with pytest.raises(InputError, match="2 usable check-point residuals"):
        change.sigma_from_residuals([0.1, np.nan, 0.2])


def test_resampling_onto_another_grid_is_bilinear(tmp_path):
    """A plane written on a 1 m grid reads back exactly on a shifted 0.5 m grid."""
    from geomatics_toolbox.core.io.raster import read_raster_on_grid, write_geotiff
    yy, xx = np.mgrid[0:100, 0:100]
    x, y = 1000 + xx + 0.5, 2100 - yy - 0.5
    write_geotiff(tmp_path / "a.tif", 2 * (x - 1000) + 3 * (y - 2000),
                  geotransform=(1000, 1, 0, 2100, 0, -1), crs="EPSG:32632")
    r = read_raster_on_grid(tmp_path / "a.tif", (1010.25, 0.5, 0, 2090.25, 0, -0.5), (60, 70))
    xs, ys = np.meshgrid(1010.25 + 0.5 * (np.arange(70) + 0.5),
                         2090.25 - 0.5 * (np.arange(60) + 0.5))
    assert r.data.shape == (60, 70)
    assert np.abs(r.data - (2 * (xs - 1000) + 3 * (ys - 2000))).max() < 1e-4
    out = read_raster_on_grid(tmp_path / "a.tif", (950, 1, 0, 2090, 0, -1), (10, 100))
    assert np.isnan(out.data[:, :50]).all() and np.isfinite(out.data[:, 50:]).all()

"""geomatics:elevationchange through processing.run: σ from a DTM accuracy run, rasters
on different grids resampled onto the first one's grid (known geometry)."""
from __future__ import annotations

import numpy as np
import pytest
from qgis.core import QgsProcessingException

from geomatics_toolbox.core.io.raster import read_raster, write_geotiff

CRS = "EPSG:32632"
X0, Y0 = 500000.0, 4000100.0


def _plane(xx, yy):
    return 100.0 + 0.01 * (xx - X0) + 0.02 * (yy - Y0)


def _dem(path, cell, nx, ny, *, fill=0.0, x0=X0, y0=Y0):
    """A plane on a north-up grid, + ``fill`` m over the 20 x 30 m box x0+20..40, y0-50..-20."""
    xx, yy = np.meshgrid(x0 + cell * (np.arange(nx) + 0.5), y0 - cell * (np.arange(ny) + 0.5))
    z = _plane(xx, yy)
    box = (xx > X0 + 20) & (xx < X0 + 40) & (yy > Y0 - 50) & (yy < Y0 - 20)
    z = np.where(box, z + fill, z)
    write_geotiff(path, z, geotransform=(x0, cell, 0.0, y0, 0.0, -cell), crs=CRS)
    return str(path)


@pytest.fixture(scope="module")
def epochs(tmp_path_factory):
    d = tmp_path_factory.mktemp("change")
    before = _dem(d / "before.tif", 0.5, 200, 200)
    # after: a 2 m fill, on a 1 m grid shifted by 0.25 m, larger than the first
    after = _dem(d / "after.tif", 1.0, 110, 110, fill=2.0, x0=X0 - 5.25, y0=Y0 + 5.25)
    return d, before, after


def test_second_raster_is_resampled_onto_the_first_grid(qgis_processing, epochs):
    d, before, after = epochs
    res = qgis_processing.run("geomatics:elevationchange", {
        "INPUT": before, "INPUT_AFTER": after, "SIGMA1": 0.05, "SIGMA2": 0.05,
        "OUTPUT": str(d / "diff.tif"), "OUTPUT_POLYGONS": str(d / "chg.gpkg")})
    r = read_raster(res["OUTPUT"])
    assert r.shape == (200, 200) and r.geotransform == (X0, 0.5, 0.0, Y0, 0.0, -0.5)
    diff = r.masked()
    # bilinear on a plane is exact away from the box edges (1 m blur at the edges)
    xx, yy = np.meshgrid(X0 + 0.5 * (np.arange(200) + 0.5), Y0 - 0.5 * (np.arange(200) + 0.5))
    inner = (xx > X0 + 21.5) & (xx < X0 + 38.5) & (yy > Y0 - 48.5) & (yy < Y0 - 21.5)
    far = (np.abs(xx - (X0 + 30)) > 12) | (np.abs(yy - (Y0 - 35)) > 17)
    assert np.nanmax(np.abs(diff[inner] - 2.0)) < 1e-4
    assert np.nanmax(np.abs(diff[far])) < 1e-4
    # the bilinear edges trade volume between the sides: 2 m x 600 m² within 2 %
    assert res["N_REGIONS"] == 1 and res["CUT_VOLUME"] == 0
    assert res["FILL_VOLUME"] == pytest.approx(2.0 * 600, rel=0.02)


def test_different_crs_is_refused(qgis_processing, epochs, tmp_path):
    d, before, _ = epochs
    other = tmp_path / "other.tif"
    write_geotiff(other, np.zeros((10, 10)), geotransform=(X0, 1, 0, Y0, 0, -1),
                  crs="EPSG:32633")
    with pytest.raises(QgsProcessingException, match="different CRSs"):
        qgis_processing.run("geomatics:elevationchange", {
            "INPUT": before, "INPUT_AFTER": str(other), "OUTPUT": str(tmp_path / "x.tif")})
    assert not (tmp_path / "x.tif").exists()


def test_sigma_from_a_dtm_accuracy_run(qgis_processing, epochs):
    d, before, after = epochs
    rng = np.random.default_rng(5)
    x = X0 + rng.uniform(50, 90, 40)
    y = Y0 - rng.uniform(50, 90, 40)
    err = rng.normal(0.03, 0.08, 40)               # check = DTM - error
    csv = d / "cp.csv"
    csv.write_text("id,x,y,z\n" + "".join(
        f"p{i},{a:.3f},{b:.3f},{_plane(a, b) - e:.5f}\n"
        for i, (a, b, e) in enumerate(zip(x, y, err))) + f"far,{X0 + 900},{Y0},100\n")
    acc = qgis_processing.run("geomatics:dtmaccuracy", {
        "DTM": before, "CHECKPOINTS_CSV": str(csv), "CSV_CRS": CRS,
        "OUTPUT": str(d / "resid.gpkg")})
    assert acc["N"] == 40 and acc["N_OUTSIDE"] == 1
    rmse = float(np.sqrt(np.mean(err ** 2)))
    assert acc["RMSE"] == pytest.approx(rmse, abs=2e-5)
    res = qgis_processing.run("geomatics:elevationchange", {
        "INPUT": before, "INPUT_AFTER": after, "SIGMA1": 9.0, "RESIDUALS1": acc["OUTPUT"],
        "SIGMA2": 0.05, "OUTPUT": str(d / "diff2.tif")})
    # the typed σ₁ = 9 m is replaced by the residual RMSE (the 'outside' point is not used)
    assert res["LOD"] == pytest.approx(1.96 * np.sqrt(rmse ** 2 + 0.05 ** 2), abs=1e-4)
    both = qgis_processing.run("geomatics:elevationchange", {
        "INPUT": before, "INPUT_AFTER": after, "RESIDUALS1": acc["OUTPUT"],
        "RESIDUALS2": acc["OUTPUT"], "OUTPUT": str(d / "diff3.tif")})
    assert both["LOD"] == pytest.approx(1.96 * np.sqrt(2) * rmse, abs=1e-4)


def test_residual_layer_without_error_field_is_refused(qgis_processing, epochs, tmp_path):
    d, before, after = epochs
    from geomatics_toolbox.core.io.points import write_points_layer
    bad = tmp_path / "bad.gpkg"
    write_points_layer(bad, np.array([X0 + 1.0]), np.array([Y0 - 1.0]), np.array([1.0]),
                       {"id": ["a"]}, crs=CRS, layer_name="pts")
    with pytest.raises(QgsProcessingException, match="no 'error' field"):
        qgis_processing.run("geomatics:elevationchange", {
            "INPUT": before, "INPUT_AFTER": after, "RESIDUALS1": str(bad),
            "OUTPUT": str(tmp_path / "x.tif")})


def test_epochs_as_raster_layers(qgis_processing, epochs):
    """RASTER / RASTER_AFTER (layers or paths) give the same result as INPUT / INPUT_AFTER."""
    from qgis.core import QgsRasterLayer
    d, before, after = epochs
    lyr = QgsRasterLayer(after, "after")
    assert lyr.isValid()
    by_layer = qgis_processing.run("geomatics:elevationchange", {
        "RASTER": before, "RASTER_AFTER": lyr, "SIGMA1": 0.05, "SIGMA2": 0.05,
        "OUTPUT": str(d / "diff_l.tif")})
    by_file = qgis_processing.run("geomatics:elevationchange", {
        "INPUT": before, "INPUT_AFTER": after, "SIGMA1": 0.05, "SIGMA2": 0.05,
        "OUTPUT": str(d / "diff_f.tif")})
    assert by_layer["FILL_VOLUME"] == by_file["FILL_VOLUME"] > 0
    assert np.array_equal(read_raster(by_layer["OUTPUT"]).data,
                          read_raster(by_file["OUTPUT"]).data)
    with pytest.raises(QgsProcessingException, match="given twice"):
        qgis_processing.run("geomatics:elevationchange", {
            "INPUT": before, "RASTER": before, "INPUT_AFTER": after,
            "OUTPUT": str(d / "x.tif")})
    with pytest.raises(QgsProcessingException, match="An epoch is missing"):
        qgis_processing.run("geomatics:elevationchange", {
            "INPUT": before, "OUTPUT": str(d / "x.tif")})

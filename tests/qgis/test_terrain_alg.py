"""Terrain algorithms through processing.run: IDW, kriging, DSM/nDSM, DTM accuracy."""
from __future__ import annotations

import numpy as np
import pytest
from qgis.core import QgsProcessingException

from geomatics_toolbox.core.io.raster import read_raster
from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile


@pytest.fixture(scope="module")
def scene(tmp_path_factory):
    d = tmp_path_factory.mktemp("terrain")
    tile = generate_tile(extent=(100.0, 100.0), density=2.0, seed=4, n_buildings=2,
                         n_halls=0)
    laz = d / "tile.laz"
    write_tile(tile, laz, crs="EPSG:32632")
    nocrs = d / "nocrs.laz"
    write_tile(tile, nocrs, crs=None)
    cp = tile.checkpoints(n=12, min_spacing=3.0)
    csv = cp.to_csv(d / "cp.csv", extra=[("far", tile.bounds[2] + 500, tile.bounds[3], 200.0)])
    return {"dir": d, "tile": tile, "laz": str(laz), "nocrs": str(nocrs), "csv": str(csv),
            "cp": cp}


def test_idw_dtm_and_accuracy(qgis_processing, scene):
    d = scene["dir"]
    res = qgis_processing.run("geomatics:idwdtm", {
        "INPUT": scene["laz"], "CLASSES": "2", "CELL_SIZE": 1.0, "POWER": 3.0,
        "NEIGHBOURS": 12, "OUTPUT": str(d / "idw.tif"), "OUTPUT_HTML": str(d / "idw.html")})
    r = read_raster(res["OUTPUT"])
    assert "32632" in r.crs or "UTM zone 32N" in r.crs
    assert r.nodata == -9999 and r.geotransform[1] == 1.0
    assert r.geotransform[0] % 1.0 == 0 and r.geotransform[3] % 1.0 == 0
    assert res["N_POINTS"] > 1000 and res["VALID_CELLS"] > 3000
    assert "IDW" in (d / "idw.html").read_text(encoding="utf-8")
    acc = qgis_processing.run("geomatics:dtmaccuracy", {
        "DTM": res["OUTPUT"], "CHECKPOINTS_CSV": scene["csv"],
        "OUTPUT": str(d / "resid.gpkg"), "OUTPUT_HTML": str(d / "acc.html")})
    assert acc["N"] == 12 and acc["N_OUTSIDE"] == 1 and acc["N_NODATA"] == 0
    # synthetic terrain, 5 cm noise: a 1 m IDW DTM is good to a few cm at open ground
    assert 0 < acc["RMSE"] < 0.3 and acc["R"] > 0.99
    assert acc["ACCURACY_95"] == pytest.approx(1.96 * acc["RMSE"])
    html = (d / "acc.html").read_text(encoding="utf-8")
    assert "<svg" in html and "outside the DTM" in html
    from qgis.core import QgsVectorLayer
    lyr = QgsVectorLayer(acc["OUTPUT"], "r", "ogr")
    feats = list(lyr.getFeatures())
    assert len(feats) == 13
    assert sorted(f["status"] for f in feats).count("outside DTM") == 1


def test_kriging_dtm_variance_and_cv(qgis_processing, scene):
    d = scene["dir"]
    res = qgis_processing.run("geomatics:krigingdtm", {
        "INPUT": scene["laz"], "CELL_SIZE": 2.0, "VARIOGRAM": 3, "NEIGHBOURS": 12,
        "CV_POINTS": 200, "FIT_POINTS": 1500, "OUTPUT": str(d / "kr.tif"),
        "OUTPUT_VARIANCE": str(d / "kr_var.tif"), "OUTPUT_HTML": str(d / "kr.html")})
    z = read_raster(res["OUTPUT"]).masked()
    v = read_raster(res["OUTPUT_VARIANCE"]).masked()
    assert np.array_equal(np.isfinite(z), np.isfinite(v)) and np.nanmin(v) >= 0
    assert res["SILL"] >= res["NUGGET"] >= 0 and res["RANGE"] > 0
    assert np.isfinite(res["CV_RMSE"]) and res["CV_RMSE"] < 0.5
    html = (d / "kr.html").read_text(encoding="utf-8")
    assert "nugget" in html and "cross-validation" in html
    # user-given variogram, universal kriging
    res2 = qgis_processing.run("geomatics:krigingdtm", {
        "INPUT": scene["laz"], "CELL_SIZE": 2.0, "KRIGING_TYPE": 1, "VARIOGRAM": 4,
        "VARIOGRAM_NUGGET": 0.01, "VARIOGRAM_SILL": 5, "VARIOGRAM_RANGE": 40, "NEIGHBOURS": 12,
        "OUTPUT": str(d / "uk.tif")})
    assert res2["NUGGET"] == pytest.approx(0.01) and res2["SILL"] == pytest.approx(5.0)


def test_dsm_and_ndsm(qgis_processing, scene):
    d = scene["dir"]
    dtm = qgis_processing.run("geomatics:idwdtm", {
        "INPUT": scene["laz"], "CELL_SIZE": 1.0, "FILL_GAPS": True,
        "OUTPUT": str(d / "dtm_fill.tif")})["OUTPUT"]
    res = qgis_processing.run("geomatics:dsm", {
        "INPUT": scene["laz"], "FIRST_RETURNS": True, "DTM": dtm,
        "OUTPUT": str(d / "dsm.tif"), "OUTPUT_NDSM": str(d / "ndsm.tif"),
        "OUTPUT_HTML": str(d / "dsm.html")})
    a = read_raster(res["OUTPUT"])
    b = read_raster(dtm)
    assert a.geotransform == b.geotransform and a.shape == b.shape
    nd = read_raster(res["OUTPUT_NDSM"]).masked()
    assert np.nanmin(nd) >= 0 and res["NDSM_MAX"] > 2.0     # trees/buildings stand up


def test_bad_inputs_clear_errors_no_output(qgis_processing, scene):
    d = scene["dir"]
    cases = [
        ({"INPUT": scene["laz"], "CLASSES": "9"}, "No ground points in the input class"),
        ({"INPUT": scene["nocrs"]}, "no CRS"),
        ({"INPUT": scene["laz"], "CELL_SIZE": 0.0}, "Cell size must be > 0"),
        ({"INPUT": scene["laz"], "CELL_SIZE": 0.0001}, "this toolbox builds at once"),
        ({"INPUT": scene["laz"], "NEIGHBOURS": 10 ** 7}, r"Neighbours \(NEIGHBOURS\) is 10000000"),
    ]
    for i, (params, msg) in enumerate(cases):
        out = d / f"bad{i}.tif"
        with pytest.raises(QgsProcessingException, match=msg):
            qgis_processing.run("geomatics:idwdtm", dict(params, OUTPUT=str(out)))
        assert not out.exists()
    out = d / "badk.tif"
    with pytest.raises(QgsProcessingException, match=r"Neighbours per cell \(NEIGHBOURS\) is "
                                                     r"10000000: set NEIGHBOURS to \d+ or fewer"):
        qgis_processing.run("geomatics:krigingdtm", {
            "INPUT": scene["laz"], "NEIGHBOURS": 10 ** 7, "OUTPUT": str(out)})
    assert not out.exists()


def test_checkpoints_in_other_crs(qgis_processing, scene, tmp_path):
    from qgis.core import (
        QgsCoordinateReferenceSystem,
        QgsCoordinateTransform,
        QgsFeature,
        QgsGeometry,
        QgsPoint,
        QgsProject,
        QgsVectorLayer,
    )
    d = scene["dir"]
    dtm = qgis_processing.run("geomatics:idwdtm", {
        "INPUT": scene["laz"], "OUTPUT": str(d / "dtm_crs.tif")})["OUTPUT"]
    cp = scene["cp"]
    lyr = QgsVectorLayer("PointZ?crs=EPSG:4326&field=name:string", "cp", "memory")
    tr = QgsCoordinateTransform(QgsCoordinateReferenceSystem("EPSG:32632"),
                                QgsCoordinateReferenceSystem("EPSG:4326"),
                                QgsProject.instance())
    feats = []
    for i, x, y, z in zip(cp.id, cp.x, cp.y, cp.z):
        p = tr.transform(float(x), float(y))
        f = QgsFeature(lyr.fields())
        f.setGeometry(QgsGeometry(QgsPoint(p.x(), p.y(), float(z))))
        f.setAttributes([str(i)])
        feats.append(f)
    lyr.dataProvider().addFeatures(feats)
    html = tmp_path / "x.html"
    with pytest.raises(QgsProcessingException, match="EPSG:4326 but the DTM is in EPSG:32632"):
        qgis_processing.run("geomatics:dtmaccuracy", {
            "DTM": dtm, "CHECKPOINTS": lyr, "OUTPUT_HTML": str(html)})
    assert not html.exists()
    ok = qgis_processing.run("geomatics:dtmaccuracy", {
        "DTM": dtm, "CHECKPOINTS": lyr, "REPROJECT": True, "ID_FIELD": "name",
        "OUTPUT_HTML": str(html)})
    assert ok["N"] == 12 and ok["RMSE"] < 0.3
    csv_ok = qgis_processing.run("geomatics:dtmaccuracy", {
        "DTM": dtm, "CHECKPOINTS_CSV": scene["csv"]})
    assert ok["RMSE"] == pytest.approx(csv_ok["RMSE"], abs=2e-3)


def test_extent_crs_override_and_gap_mask(qgis_processing, scene):
    d = scene["dir"]
    x0, y0 = scene["tile"].bounds[:2]
    ext = f"{x0 + 10.3},{x0 + 40.7},{y0 + 20.2},{y0 + 50.9} [EPSG:32632]"
    res = qgis_processing.run("geomatics:idwdtm", {
        "INPUT": scene["nocrs"], "CRS": "EPSG:32632", "EXTENT": ext, "CELL_SIZE": 0.5,
        "OUTPUT": str(d / "ext.tif")})
    r = read_raster(res["OUTPUT"])
    assert r.geotransform == (x0 + 10.0, 0.5, 0.0, y0 + 51.0, 0.0, -0.5)
    assert r.shape == (62, 62)
    assert "32632" in r.crs or "UTM zone 32N" in r.crs
    # a tiny max distance leaves cells without a point nearby empty (never invented)
    tight = qgis_processing.run("geomatics:idwdtm", {
        "INPUT": scene["laz"], "CELL_SIZE": 0.5, "MAX_DISTANCE": 0.3,
        "OUTPUT": str(d / "tight.tif")})
    loose = qgis_processing.run("geomatics:idwdtm", {
        "INPUT": scene["laz"], "CELL_SIZE": 0.5, "FILL_GAPS": True,
        "OUTPUT": str(d / "loose.tif")})
    assert tight["NODATA_CELLS"] > 1000 and loose["NODATA_CELLS"] == 0

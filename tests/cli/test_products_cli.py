"""qgis_process smoke tests of the LiDAR products on the demo tile, with defaults."""
from __future__ import annotations

import importlib.util
import sys
from pathlib import Path

import numpy as np
import pytest

from geomatics_toolbox.core.io.raster import read_raster

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "tests"))
from cityjson_check import assert_valid_cityjson  # noqa: E402


@pytest.fixture(scope="module")
def demo(tmp_path_factory):
    spec = importlib.util.spec_from_file_location("make_demo_data",
                                                  ROOT / "scripts" / "make_demo_data.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    d = tmp_path_factory.mktemp("products_cli")
    return d, str(mod.make_demo(d / "demo")["laz"])


def test_tindtm_defaults(qgis_process, demo):
    d, laz = demo
    res = qgis_process.run("geomatics:tindtm", INPUT=laz,
                           OUTPUT="TEMPORARY_OUTPUT")["results"]
    assert res["N_POINTS"] > 50_000 and res["VALID_CELLS"] > 0.8 * 300 * 300
    assert res["OUTPUT"].endswith(".tif")  # the temporary folder is gone on exit
    html = d / "tin.html"
    res = qgis_process.run("geomatics:tindtm", INPUT=laz, CELL_SIZE=2,
                           OUTPUT=str(d / "tin.tif"), OUTPUT_HTML=str(html),
                           REPORT_LANGUAGE=3)["results"]
    dtm = read_raster(d / "tin.tif").masked()
    assert 150 < np.nanmin(dtm) and np.nanmax(dtm) < 300
    assert res["VALID_CELLS"] == np.isfinite(dtm).sum()
    text = html.read_text(encoding="utf-8")
    assert 'dir="rtl"' in text and "<svg" in text


def test_tindtm_no_ground_is_a_clear_error(qgis_process, demo):
    d, laz = demo
    msg = qgis_process.run_expect_failure("geomatics:tindtm", INPUT=laz, CLASSES="9",
                                          OUTPUT=str(d / "none.tif"))
    assert "No ground points in the input class filter" in msg
    assert "Traceback" not in msg and not (d / "none.tif").exists()


def test_lidarqa_defaults(qgis_process, demo):
    d, laz = demo
    html = d / "qa.html"
    res = qgis_process.run("geomatics:lidarqa", INPUT=laz, OUTPUT=str(d / "qa.tif"),
                           OUTPUT_HTML=str(html), REPORT_LANGUAGE=2)["results"]
    # the demo tile: ~4 pts/m² of all returns (make_demo_data.DEMO)
    assert 3.0 < res["DENSITY"] < 5.0 and 0 < res["GROUND_DENSITY"] < res["DENSITY"]
    assert res["GROUND_WINDOW"] == 1.0 and res["DTM_CELL"] in (0.5, 1.0)
    dens = read_raster(d / "qa.tif").masked()
    assert dens.shape == (60, 60)
    text = html.read_text(encoding="utf-8")
    assert 'dir="rtl"' in text and 'id="density-map"' in text and 'id="gap-map"' in text


def test_elevationchange_clouds_defaults(qgis_process, demo):
    import laspy
    d, laz = demo
    las = laspy.read(laz)
    x0, y0 = las.header.mins[:2]
    box = ((las.x > x0 + 100) & (las.x <= x0 + 140) & (las.y > y0 + 100)
           & (las.y <= y0 + 130))                        # a 40 x 30 m fill of 2 m
    las.z = np.where(box, las.z + 2.0, las.z)
    after = d / "after.laz"
    las.write(str(after))
    html = d / "change.html"
    res = qgis_process.run("geomatics:elevationchange", INPUT=laz, INPUT_AFTER=str(after),
                           OUTPUT=str(d / "diff.tif"), OUTPUT_POLYGONS=str(d / "chg.gpkg"),
                           OUTPUT_HTML=str(html))["results"]
    assert res["N_REGIONS"] >= 1 and res["CUT_VOLUME"] == 0
    assert res["FILL_VOLUME"] == pytest.approx(2.0 * 40 * 30, rel=0.08)
    assert res["LOD"] == pytest.approx(1.96 * np.sqrt(0.02))
    assert (d / "chg.gpkg").exists() and 'id="change-map"' in html.read_text("utf-8")


def test_elevationchange_mixed_inputs_error(qgis_process, demo):
    d, laz = demo
    msg = qgis_process.run_expect_failure(
        "geomatics:elevationchange", INPUT=laz, INPUT_AFTER=str(d / "diff.tif"),
        OUTPUT=str(d / "x.tif"))
    assert "two rasters or two point clouds" in msg and "Traceback" not in msg


def test_buildings_defaults(qgis_process, demo):
    import laspy

    from geomatics_toolbox.core.io.vector import read_polygons
    d, laz = demo
    res = qgis_process.run("geomatics:buildings", INPUT=laz, OUTPUT=str(d / "b.gpkg"),
                           OUTPUT_CLOUD=str(d / "b.laz"), OUTPUT_HTML=str(d / "b.html"),
                           OUTPUT_CITYJSON=str(d / "b.city.json"),
                           OUTPUT_OBJ=str(d / "b.obj"), REPORT_LANGUAGE=3)["results"]
    doc = assert_valid_cityjson(d / "b.city.json")        # schema + cjval's checks
    assert len(doc["CityObjects"]) == res["N_BUILDINGS"]
    assert res["OUTPUT_OBJ"].endswith("b.obj")
    polys = read_polygons(d / "b.gpkg")
    assert res["N_BUILDINGS"] == len(polys) >= 5
    assert all(a["height_m"] > 2 and a["storeys"] >= 1 for a, _ in polys)
    src, out = laspy.read(laz), laspy.read(str(d / "b.laz"))
    changed = np.asarray(out.classification) != np.asarray(src.classification)
    assert (np.asarray(out.classification)[changed] == 6).all()
    assert np.array_equal(np.asarray(out.intensity), np.asarray(src.intensity))
    assert 'id="footprint-map"' in (d / "b.html").read_text("utf-8")


def test_classify_defaults(qgis_process, demo):
    import laspy
    d, laz = demo
    res = qgis_process.run("geomatics:classify", INPUT=laz, OUTPUT=str(d / "asprs.laz"),
                           OUTPUT_HTML=str(d / "asprs.html"), REPORT_LANGUAGE=2)["results"]
    got = np.asarray(laspy.read(str(d / "asprs.laz")).classification)
    assert {2, 3, 4, 5, 6, 7} <= set(np.unique(got).tolist())
    assert res["N_POINTS"] == got.size and res["N_BUILDING"] == (got == 6).sum() > 1000
    assert 'dir="rtl"' in (d / "asprs.html").read_text("utf-8")

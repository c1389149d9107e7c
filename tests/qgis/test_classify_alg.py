"""geomatics:classify through processing.run: classes, preserved attributes, errors."""
from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest
from qgis.core import QgsProcessingException

from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from cityjson_check import assert_valid_cityjson  # noqa: E402


@pytest.fixture(scope="module")
def scene(tmp_path_factory):
    d = tmp_path_factory.mktemp("classify_alg")
    tile = generate_tile(extent=(120.0, 120.0), density=4.0, seed=3, n_buildings=3,
                         n_halls=0, hill_height=0.0, cliff_height=0.0)
    laz = d / "tile.laz"
    write_tile(tile, laz, crs="EPSG:32632")
    return d, tile, str(laz)


def test_classify_writes_asprs_classes(qgis_processing, scene):
    import laspy
    d, tile, laz = scene
    out = d / "c.laz"
    res = qgis_processing.run("geomatics:classify", {
        "INPUT": laz, "HEIGHT_ABOVE_GROUND": True, "OUTPUT": str(out),
        "OUTPUT_HTML": str(d / "c.html")})
    b = laspy.read(str(out))
    a = laspy.read(laz)
    got = np.asarray(b.classification)
    assert res["N_POINTS"] == len(got) == len(tile)
    assert res["N_GROUND"] == (got == 2).sum() and res["N_BUILDING"] == (got == 6).sum()
    assert res["N_VEGETATION"] == np.isin(got, (3, 4, 5)).sum() > 1000
    assert res["N_BUILDINGS"] >= 2
    # against the true classes of the synthetic tile
    truth = tile.classification
    assert (truth[got == 6] == 6).mean() > 0.95
    assert (got[truth == 2] == 2).mean() > 0.97
    for name in ("intensity", "gps_time", "return_number", "point_source_id"):
        assert np.array_equal(np.asarray(a[name]), np.asarray(b[name]))
    hag = np.asarray(b["HeightAboveGround"])
    assert np.abs(hag[got == 2]).max() < 1.0 and (hag[got == 5] > 1.5 - 1e-3).all()
    assert 'id="class-map"' in (d / "c.html").read_text(encoding="utf-8")


def test_classify_keep_ground_and_bad_options(qgis_processing, scene):
    import laspy
    d, tile, laz = scene
    out = d / "k.laz"
    qgis_processing.run("geomatics:classify", {"INPUT": laz, "GROUND": 1,
                                               "BUILDINGS": False, "OUTPUT": str(out)})
    got = np.asarray(laspy.read(str(out)).classification)
    assert np.array_equal(got == 2, tile.classification == 2)
    assert not (got == 6).any()
    bad = d / "bad.laz"
    with pytest.raises(QgsProcessingException, match=r"Vegetation heights must satisfy 0 < "
                       r"Low vegetation up to \(LOW_VEGETATION = 3\.0 m\) < Medium vegetation "
                       r"up to \(MEDIUM_VEGETATION = 1\.0 m\): give e\.g\. 0\.5 and 1\.5\."):
        qgis_processing.run("geomatics:classify", {"INPUT": laz, "LOW_VEGETATION": 3.0,
                                                   "MEDIUM_VEGETATION": 1.0,
                                                   "OUTPUT": str(bad)})
    assert not bad.exists()


def test_buildings_city_models(qgis_processing, tmp_path):
    """geomatics:buildings on the city scene: no bridge building, roof types, CityJSON
    and OBJ written, storey height applied; the footprints keep their attributes."""
    from geomatics_toolbox.core.io.vector import read_polygons
    from geomatics_toolbox.synthetic.city import city_scene, write_scene
    scene = city_scene(density=4.0)
    scene.classification[np.isin(scene.classification, (5, 6, 17))] = 1
    laz = write_scene(scene, tmp_path / "city.laz")
    res = qgis_processing.run("geomatics:buildings", {
        "INPUT": laz, "STOREY_HEIGHT": 2.5, "OUTPUT": str(tmp_path / "b.gpkg"),
        "OUTPUT_CITYJSON": str(tmp_path / "b.city.json"), "OUTPUT_OBJ": str(tmp_path / "b.obj"),
        "OUTPUT_HTML": str(tmp_path / "b.html")})
    assert res["N_BUILDINGS"] == 5
    polys = read_polygons(tmp_path / "b.gpkg")
    types = sorted(a["roof_type"] for a, _ in polys)
    assert types == ["flat", "flat", "flat", "gabled", "hipped"]
    assert all(a["storeys"] == max(1, int(a["volume_m3"] / a["area_m2"] // 2.5))
               for a, _ in polys)
    doc = assert_valid_cityjson(tmp_path / "b.city.json")  # schema + cjval's checks
    assert doc["type"] == "CityJSON" and len(doc["CityObjects"]) == 5
    assert (tmp_path / "b.obj").read_text().count("\no building_") == 5
    html = (tmp_path / "b.html").read_text(encoding="utf-8")
    import re
    assert "1 bridges or decks refused" in re.sub(r"<[^>]+>", "", html)
    bad = tmp_path / "bad.gpkg"
    with pytest.raises(QgsProcessingException, match="STOREY_HEIGHT"):
        qgis_processing.run("geomatics:buildings", {"INPUT": laz, "STOREY_HEIGHT": 1.0,
                                                    "OUTPUT": str(bad)})
    assert not bad.exists()

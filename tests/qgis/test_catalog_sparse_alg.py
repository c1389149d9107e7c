"""geomatics:catalog through processing.run on sparse tiles: a lake tile with no ground
within reach, a header-only tile, a catalog with no ground at all (en and ar)."""
from __future__ import annotations

import numpy as np
import pytest

from geomatics_toolbox.core.io.las import read_las, write_las
from geomatics_toolbox.core.io.raster import read_raster
from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile

ALG = "geomatics:catalog"
SIDE = 120.0
ORIGIN = (500_000.0, 4_000_000.0)


def _tiles(d, lake: float):
    """2 x 2 tiles of 120 m; a lake (class 9, flat) of ``lake`` m from the upper-right
    corner (160 m: t11 and a 40 m band of its neighbours, wider than BUFFER 30)."""
    d.mkdir()
    for i in range(2):
        for j in range(2):
            t = generate_tile(extent=(SIDE, SIDE), origin=(ORIGIN[0] + SIDE * i,
                                                           ORIGIN[1] + SIDE * j),
                              density=1.0, seed=10 * i + j)
            wet = (t.x >= ORIGIN[0] + 2 * SIDE - lake) & (t.y >= ORIGIN[1] + 2 * SIDE - lake)
            t.classification[wet] = 9
            t.z[wet] = 190.0
            write_tile(t, d / f"t{i}{j}.laz")
    e = np.empty(0)                                   # a header-only tile in the list
    write_las(d / "t20.laz", e, e, e, dimensions={"classification": np.empty(0, np.uint8)},
              crs="EPSG:32632", point_format=6, version="1.4", scale=0.01)
    return d


def _params(tiles, out, **extra):
    return {"INPUT": str(tiles), "GROUND_FILTER": 0, "CELL_SIZE": 2.0, "BUFFER": 30.0,
            "WORKERS": 1, "OUTPUT_FOLDER": str(out), **extra}


def test_lake_tile_and_header_only_tile_finish_with_warnings(qgis_processing, warning_feedback,
                                                             tmp_path):
    tiles = _tiles(tmp_path / "tiles", 160.0)
    out, html = tmp_path / "out", tmp_path / "r.html"
    fb = warning_feedback
    res = qgis_processing.run(ALG, _params(tiles, out, OUTPUT_HTML=str(html),
                                           REPORT_LANGUAGE=2), feedback=fb)
    assert res["N_TILES"] == 4 and res["N_FAILED"] == 0
    lake = read_raster(out / "t11_dtm.tif")
    assert lake.data.shape == (60, 60) and np.all(lake.data == lake.nodata)
    assert np.all(read_las(out / "t11_classified.laz", ("classification",))
                  ["classification"] == 9)
    land = read_raster(out / "t00_dtm.tif")
    assert np.mean(land.data != land.nodata) > 0.9
    assert not (out / "t20_dtm.tif").exists()
    t11 = [w for w in fb.warnings if w.startswith("Tile t11:")]
    assert len(t11) == 1 and "no ground point in the tile nor within its 30 m buffer (its " \
        "points by class: 9: " in t11[0] and t11[0].endswith("its DTM is nodata."), fb.warnings
    assert any("t20.laz has no points (a header only); it is left out of the catalog." in w
               for w in fb.warnings), fb.warnings
    assert not any(w.startswith(("Tile t00", "Tile t01", "Tile t10")) for w in fb.warnings)
    text = html.read_text(encoding="utf-8")
    assert "البلاطة" in text and "لا نقطة أرض في البلاطة ولا ضمن هامشها" in text
    assert "t20.laz" in text and "استُبعد من الفهرس" in text


def test_lake_warning_in_arabic(qgis_processing, arabic_ui, warning_feedback, tmp_path):
    tiles = _tiles(tmp_path / "tiles", 160.0)
    fb = warning_feedback
    res = qgis_processing.run(ALG, _params(tiles, tmp_path / "out"), feedback=fb)
    assert res["N_FAILED"] == 0
    t11 = [w for w in fb.warnings if "t11" in w]
    assert len(t11) == 1 and t11[0].startswith("البلاطة") and "بلا بيانات" in t11[0], \
        fb.warnings


def test_catalog_without_ground_refused_with_the_fix(qgis_processing, tmp_path):
    from qgis.core import QgsProcessingException
    tiles = _tiles(tmp_path / "tiles", 1000.0)        # every tile under water
    out = tmp_path / "out"
    with pytest.raises(QgsProcessingException,
                       match=r"No tile of the catalog has a ground point \(4 tiles, \d+ "
                             r"points, by class: 9: \d+\).*none is ground \(class 2\): "
                             r"choose a ground filter \(GROUND_FILTER\)"):
        qgis_processing.run(ALG, _params(tiles, out))
    assert not out.exists() or not any(out.rglob("*"))


def test_offshore_tile_too_sparse_for_the_default_filter(qgis_processing, warning_feedback,
                                                         tmp_path):
    """The default ground filter on a sea tile of 3 returns (needs 10): the run finishes,
    the land tile is classified, the sea tile named with the filter's reason."""
    d = tmp_path / "tiles"
    d.mkdir()
    write_tile(generate_tile(extent=(150.0, 150.0), origin=ORIGIN, density=1.0, seed=1),
               d / "land.laz")
    x = ORIGIN[0] + 1000 + np.array([10.0, 80.0, 140.0])
    y = ORIGIN[1] + np.array([20.0, 120.0, 60.0])
    write_las(d / "sea.laz", x, y, np.full(3, 190.0),
              dimensions={"classification": np.ones(3, np.uint8)}, crs="EPSG:32632",
              point_format=6, version="1.4", scale=0.01)
    fb = warning_feedback
    out = tmp_path / "out"
    params = _params(d, out, BUFFER=50.0)
    del params["GROUND_FILTER"]                      # the default: the recommended filter
    res = qgis_processing.run(ALG, params, feedback=fb)
    assert res["N_TILES"] == 2 and res["N_FAILED"] == 0
    sea = [w for w in fb.warnings if w.startswith("Tile sea:")]
    assert len(sea) == 1 and "the ground filter cannot classify its 3 points (tile and " \
        "buffer): A ground filter needs at least 10 points, got 3" in sea[0], fb.warnings
    assert np.all(read_las(out / "sea_classified.laz", ("classification",))
                  ["classification"] == 1)
    land = read_las(out / "land_classified.laz", ("classification",))["classification"]
    assert np.mean(land == 2) > 0.2

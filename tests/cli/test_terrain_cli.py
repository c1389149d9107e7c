"""qgis_process smoke tests: one run per terrain algorithm, plus one failure."""
from __future__ import annotations

import pytest

from geomatics_toolbox.core.io.raster import read_raster
from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile


@pytest.fixture(scope="module")
def data(tmp_path_factory):
    d = tmp_path_factory.mktemp("terrain_cli")
    tile = generate_tile(extent=(80.0, 80.0), density=2.0, seed=2, n_buildings=1, n_halls=0)
    laz = d / "t.laz"
    write_tile(tile, laz, crs="EPSG:32632")
    csv = tile.checkpoints(n=8, min_spacing=3.0).to_csv(d / "cp.csv", z_decimals=6)
    return d, str(laz), csv


def test_idw_kriging_dsm_accuracy_cli(qgis_process, data):
    d, laz, csv = data
    idw = qgis_process.run("geomatics:idwdtm", INPUT=laz, CELL_SIZE=1, POWER=3,
                           OUTPUT=str(d / "idw.tif"), OUTPUT_HTML=str(d / "idw.html"))
    assert idw["results"]["N_POINTS"] > 1000
    assert read_raster(d / "idw.tif").crs
    kr = qgis_process.run("geomatics:krigingdtm", INPUT=laz, CELL_SIZE=2, NEIGHBOURS=12,
                          OUTPUT=str(d / "kr.tif"), OUTPUT_VARIANCE=str(d / "krv.tif"))
    assert kr["results"]["SILL"] > 0 and (d / "krv.tif").exists()
    ds = qgis_process.run("geomatics:dsm", INPUT=laz, DTM=str(d / "idw.tif"),
                          OUTPUT=str(d / "dsm.tif"), OUTPUT_NDSM=str(d / "ndsm.tif"))
    assert ds["results"]["VALID_CELLS"] > 1000 and (d / "ndsm.tif").exists()
    acc = qgis_process.run("geomatics:dtmaccuracy", DTM=str(d / "idw.tif"),
                           CHECKPOINTS_CSV=csv, OUTPUT=str(d / "res.gpkg"),
                           OUTPUT_HTML=str(d / "acc.html"))
    assert acc["results"]["N"] == 8 and acc["results"]["RMSE"] < 0.3
    assert (d / "acc.html").exists() and (d / "res.gpkg").exists()


def test_cli_bad_class_filter(qgis_process, data):
    d, laz, _ = data
    msg = qgis_process.run_expect_failure("geomatics:idwdtm", INPUT=laz, CLASSES="9",
                                          OUTPUT=str(d / "none.tif"))
    assert "No ground points in the input class filter" in msg
    assert not (d / "none.tif").exists()


def test_cli_ndsm_onto_the_dtm_refused_dtm_intact(qgis_process, data):
    import hashlib
    d, laz, _ = data
    qgis_process.run("geomatics:idwdtm", INPUT=laz, CELL_SIZE=2, OUTPUT=str(d / "dtm2.tif"))
    before = hashlib.sha256((d / "dtm2.tif").read_bytes()).hexdigest()
    msg = qgis_process.run_expect_failure("geomatics:dsm", INPUT=laz, DTM=str(d / "dtm2.tif"),
                                          OUTPUT=str(d / "dsm2.tif"),
                                          OUTPUT_NDSM=str(d / "dtm2.tif"),
                                          OUTPUT_HTML=str(d / "dsm2.html"))
    assert "is the same file as the input DTM" in msg and "Traceback" not in msg
    assert hashlib.sha256((d / "dtm2.tif").read_bytes()).hexdigest() == before
    assert not (d / "dsm2.tif").exists() and not (d / "dsm2.html").exists()
    assert not [p.name for p in d.iterdir() if ".part-" in p.name]

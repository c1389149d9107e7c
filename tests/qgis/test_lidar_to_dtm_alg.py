"""geomatics:lidartodtm — the chain all or nothing (issue 9), equal to the three steps.

A normal run equals ground filter → idwdtm → dtmaccuracy run one after another (same
classes, same DTM cells, same RMSE); a failing last step, an unwritable report folder,
check points outside the cloud or a cloud in degrees leave nothing at any output path
or temporary name, and the inputs byte-identical.
"""
from __future__ import annotations

import hashlib

import laspy
import numpy as np
import pytest
from qgis.core import QgsProcessingException

from geomatics_toolbox.algorithms.lidar_to_dtm import ground_filter
from geomatics_toolbox.core.io import contract
from geomatics_toolbox.core.io.raster import read_raster
from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile


def _digest(path) -> str:
    return hashlib.sha256(open(path, "rb").read()).hexdigest()


@pytest.fixture(scope="module")
def data(tmp_path_factory):
    d = tmp_path_factory.mktemp("lidartodtm")
    tile = generate_tile(extent=(80.0, 80.0), density=2.0, seed=5, n_buildings=1, n_halls=0)
    laz = d / "tile.laz"
    write_tile(tile, laz, crs="EPSG:32632")
    cp = tile.checkpoints(n=10, min_spacing=3.0)
    return {"dir": d, "laz": str(laz), "csv": cp.to_csv(d / "cp.csv"), "cp": cp}


def _params(data, folder, **extra):
    return {"INPUT": data["laz"], "CHECKPOINTS_CSV": data["csv"], "CELL_SIZE": 1.0,
            "OUTPUT": str(folder / "classified.laz"), "OUTPUT_DTM": str(folder / "dtm.tif"),
            "OUTPUT_RESIDUALS": str(folder / "res.gpkg"),
            "OUTPUT_HTML": str(folder / "accuracy.html"),
            "OUTPUT_FILTER_HTML": str(folder / "filter.html"),
            "OUTPUT_DTM_HTML": str(folder / "dtm.html"), **extra}


OUTS = ("classified.laz", "dtm.tif", "res.gpkg", "accuracy.html", "filter.html", "dtm.html")


def _nothing_left(folder, data, before):
    assert {p: _digest(p) for p in before} == before
    assert not [n for n in OUTS if (folder / n).exists()]
    assert not [p.name for p in folder.iterdir() if contract.is_temp(p)]


def test_equals_the_three_algorithms_in_sequence(qgis_processing, data, tmp_path):
    one = tmp_path / "one"
    one.mkdir()
    res = qgis_processing.run("geomatics:lidartodtm", _params(data, one))
    # the same three steps, one after another
    seq = tmp_path / "seq"
    seq.mkdir()
    _, _, alg_id = ground_filter()
    extra = {"MODE": 1} if alg_id == "lsqgroundfilter" else {}
    qgis_processing.run(f"geomatics:{alg_id}", {
        "INPUT": data["laz"], "OUTPUT": str(seq / "c.laz"), **extra})
    qgis_processing.run("geomatics:idwdtm", {
        "INPUT": str(seq / "c.laz"), "CLASSES": [2], "CELL_SIZE": 1.0,
        "NEIGHBOURS": 12, "OUTPUT": str(seq / "dtm.tif")})
    acc = qgis_processing.run("geomatics:dtmaccuracy", {
        "DTM": str(seq / "dtm.tif"), "CHECKPOINTS_CSV": data["csv"],
        "OUTPUT": str(seq / "res.gpkg")})
    a = laspy.read(one / "classified.laz").classification
    b = laspy.read(seq / "c.laz").classification
    np.testing.assert_array_equal(np.asarray(a), np.asarray(b))
    assert res["N_GROUND"] == int(np.count_nonzero(np.asarray(b) == 2)) > 1000
    d1, d2 = read_raster(str(one / "dtm.tif"), 1), read_raster(str(seq / "dtm.tif"), 1)
    assert d1.geotransform == d2.geotransform
    m1, m2 = d1.masked(), d2.masked()
    assert np.isfinite(m1).sum() > 5000
    np.testing.assert_array_equal(m1, m2)
    assert res["N"] == acc["N"] == 10
    assert res["RMSE"] == pytest.approx(acc["RMSE"], abs=1e-12)
    assert 0.0 < res["RMSE"] < 0.5          # a sound DTM of the synthetic terrain
    for name in OUTS:
        assert (one / name).stat().st_size > 0, name
    assert not [p.name for p in one.iterdir() if contract.is_temp(p)]


def test_last_step_failing_leaves_nothing(qgis_processing, data, tmp_path, monkeypatch):
    real = contract.OutputContract.write_text

    def failing(self, name, text):
        if name == "OUTPUT_HTML":
            open(self.path(name), "w").write("<html>half")
            raise OSError(28, "No space left on device")
        return real(self, name, text)

    monkeypatch.setattr(contract.OutputContract, "write_text", failing)
    before = {p: _digest(p) for p in (data["laz"], data["csv"])}
    with pytest.raises(QgsProcessingException, match="No space left on device"):
        qgis_processing.run("geomatics:lidartodtm", _params(data, tmp_path))
    _nothing_left(tmp_path, data, before)


def test_unwritable_report_folder_refused_before_any_step(qgis_processing, data, tmp_path):
    blocker = tmp_path / "blocked"
    blocker.write_text("not a folder")
    before = {p: _digest(p) for p in (data["laz"], data["csv"])}
    with pytest.raises(QgsProcessingException, match="cannot be written") as info:
        qgis_processing.run("geomatics:lidartodtm", _params(
            data, tmp_path, OUTPUT_HTML=str(blocker / "accuracy.html")))
    assert "Traceback" not in str(info.value)
    _nothing_left(tmp_path, data, before)


@pytest.mark.parametrize("case,message", [
    ("outside", "None of the 2 check points lies within"),
    ("duplicate", "(?i)duplicat|twice|same"),
    ("onto_input", "is the same file as the input CHECKPOINTS_CSV"),
])
def test_bad_inputs_refused_before_anything_is_written(qgis_processing, data, tmp_path,
                                                       case, message):
    csv = tmp_path / "cp_bad.csv"
    if case == "outside":
        csv.write_text("id,x,y,z\n1,5000000.0,10.0,1.0\n2,5000010.0,20.0,1.0\n")
    elif case == "duplicate":
        cp = data["cp"]
        rows = [f"{i},{x:.3f},{y:.3f},{z:.4f}\n" for i, x, y, z in
                zip(cp.id, cp.x, cp.y, cp.z)]
        csv.write_text("id,x,y,z\n" + "".join(rows) + rows[0])
    else:
        csv.write_text(open(data["csv"]).read())
    extra = {"CHECKPOINTS_CSV": str(csv)}
    if case == "onto_input":
        extra["OUTPUT_HTML"] = str(csv)
    before = {p: _digest(p) for p in (data["laz"], str(csv))}
    with pytest.raises(QgsProcessingException, match=message):
        qgis_processing.run("geomatics:lidartodtm", _params(data, tmp_path, **extra))
    outs = [n for n in OUTS if (tmp_path / n).exists() and n != "accuracy.html"]
    assert {p: _digest(p) for p in before} == before
    assert not outs
    assert not [p.name for p in tmp_path.iterdir() if contract.is_temp(p)]


def test_cloud_in_degrees_refused(qgis_processing, tmp_path):
    tile = generate_tile(extent=(60.0, 60.0), density=1.0, seed=3, n_buildings=0,
                         n_halls=0)
    laz = tmp_path / "geo.laz"
    write_tile(tile, laz, crs="EPSG:4326")
    csv = tmp_path / "cp.csv"
    csv.write_text("id,x,y,z\n1,10,10,1\n")
    before = {p: _digest(p) for p in (str(laz), str(csv))}
    with pytest.raises(QgsProcessingException, match="geographic CRS"):
        qgis_processing.run("geomatics:lidartodtm", _params(
            {"laz": str(laz), "csv": str(csv)}, tmp_path))
    _nothing_left(tmp_path, {}, before)

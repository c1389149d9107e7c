"""The shipped model is all or nothing: its last step publishes every output (issue 9).

The model's children write temporaries; ``geomatics:publishoutputs`` moves them to the
model outputs through one output contract. A run whose report destination cannot be
written (a path under /proc: chmod does not stop root) leaves nothing at any
destination and the inputs byte-identical; a normal run gives the same classes, DTM and
RMSE as ``geomatics:lidartodtm`` (itself equal to the three algorithms in sequence).
"""
from __future__ import annotations

import hashlib
from pathlib import Path

import laspy
import numpy as np
import pytest
from qgis.core import QgsProcessingException, QgsProcessingFeedback

from geomatics_toolbox.core.io import contract
from geomatics_toolbox.core.io.publish import publish_files
from geomatics_toolbox.core.io.raster import read_raster
from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile

MODEL = Path(__file__).resolve().parents[2] / "models" / "lidar_to_dtm.model3"
OUTS = {"Classified point cloud": "classified.laz", "Ground filter report": "filter.html",
        "DTM": "dtm.tif", "DTM report": "dtm.html",
        "Check-point residuals": "res.gpkg", "DTM accuracy report": "accuracy.html"}


def _digest(path) -> str:
    return hashlib.sha256(Path(path).read_bytes()).hexdigest()


@pytest.fixture(scope="module")
def data(tmp_path_factory):
    d = tmp_path_factory.mktemp("modelpublish")
    tile = generate_tile(extent=(80.0, 80.0), density=2.0, seed=5, n_buildings=1, n_halls=0)
    laz = d / "tile.laz"
    write_tile(tile, laz, crs="EPSG:32632")
    cp = tile.checkpoints(n=10, min_spacing=3.0)
    return {"laz": str(laz), "csv": cp.to_csv(d / "cp.csv")}


@pytest.fixture(scope="module")
def model(qgis_app):
    from qgis.core import QgsProcessingModelAlgorithm
    m = QgsProcessingModelAlgorithm()
    assert m.fromFile(str(MODEL))
    return m


class _Feedback(QgsProcessingFeedback):
    """Collects the errors a model run reports (the model wraps the child's message)."""

    def __init__(self):
        super().__init__()
        self.errors = []

    def reportError(self, error, fatalError=False):  # noqa: N802,N803 - QGIS API
        self.errors.append(error)


def _params(data, folder, **override):
    outs = {f"publish:{label}": str(folder / name) for label, name in OUTS.items()}
    outs.update(override)
    return {"INPUT": data["laz"], "CHECKPOINTS_CSV": data["csv"], "CELL_SIZE": 1.0,
            "POWER": 3.0, **outs}


def test_model_outputs_come_from_the_publish_step(model):
    children = model.childAlgorithms()
    assert children["publish"].algorithmId() == "geomatics:publishoutputs"
    for child_id, child in children.items():
        assert bool(child.modelOutputs()) == (child_id == "publish"), child_id
    names = sorted(d.name() for d in model.destinationParameterDefinitions())
    assert names == sorted(f"publish:{label}" for label in OUTS)


def test_unwritable_report_destination_leaves_nothing(qgis_processing, model, data,
                                                      tmp_path):
    before = {p: _digest(p) for p in (data["laz"], data["csv"])}
    bad = "/proc/geomatics-no-such-folder/accuracy.html"
    feedback = _Feedback()
    with pytest.raises(QgsProcessingException, match="Publish all outputs") as raised:
        qgis_processing.run(model, _params(data, tmp_path,
                                           **{"publish:DTM accuracy report": bad}),
                            feedback=feedback)
    # QGIS 3.22 reports the failing step's message through feedback.reportError and
    # raises "Error encountered while running <step>"; QGIS 3.40 reports nothing and
    # raises "Error encountered while running <step>: <its message>"
    errors = " ".join(feedback.errors + [str(raised.value)])
    assert "cannot be written" in errors and "Traceback" not in errors, errors
    assert {p: _digest(p) for p in before} == before
    assert sorted(p.name for p in tmp_path.iterdir()) == []
    assert not Path(bad).exists()


def test_model_equals_its_three_steps_in_sequence(qgis_processing, model, data,
                                                   tmp_path):
    """Same classes, DTM cells and RMSE as the model's steps run one after another."""
    m, seq = tmp_path / "model", tmp_path / "seq"
    m.mkdir()
    seq.mkdir()
    res = qgis_processing.run(model, _params(data, m))
    filter_id = model.childAlgorithms()["groundfilter"].algorithmId()
    qgis_processing.run(filter_id, {"INPUT": data["laz"], "OUTPUT": str(seq / "c.laz")})
    qgis_processing.run("geomatics:idwdtm", {
        "INPUT": str(seq / "c.laz"), "CLASSES": "2", "CELL_SIZE": 1.0, "POWER": 3.0,
        "OUTPUT": str(seq / "dtm.tif")})
    acc = qgis_processing.run("geomatics:dtmaccuracy", {
        "DTM": str(seq / "dtm.tif"), "CHECKPOINTS_CSV": data["csv"],
        "OUTPUT": str(seq / "res.gpkg")})
    for name in OUTS.values():
        assert (m / name).stat().st_size > 0, name
    assert not [p.name for p in m.iterdir() if contract.is_temp(p)]
    a = np.asarray(laspy.read(m / "classified.laz").classification)
    b = np.asarray(laspy.read(seq / "c.laz").classification)
    assert np.count_nonzero(b == 2) > 1000
    np.testing.assert_array_equal(a, b)
    d1, d2 = read_raster(str(m / "dtm.tif")), read_raster(str(seq / "dtm.tif"))
    assert d1.geotransform == d2.geotransform
    assert np.isfinite(d1.masked()).sum() > 5000
    np.testing.assert_array_equal(d1.masked(), d2.masked())
    assert res["publish:DTM"] == str(m / "dtm.tif")
    # the RMSE of the model's residual layer equals the accuracy step's
    from osgeo import ogr
    ds = ogr.Open(str(m / "res.gpkg"))
    err = np.array([f.GetField("error") for f in ds.GetLayer()
                    if f.GetField("status") == "used"], dtype=float)
    assert err.size == acc["N"] == 10
    assert 0.0 < acc["RMSE"] < 0.5
    assert float(np.sqrt(np.mean(err ** 2))) == pytest.approx(acc["RMSE"], abs=1e-9)


def test_publish_files_converts_and_refuses_an_input(tmp_path):
    src = tmp_path / "a.html"
    src.write_text("<p>report</p>")
    page = tmp_path / "page.html"                   # an input with the output's format
    page.write_text("<p>input</p>")
    with pytest.raises(ValueError, match="same file as the input INPUT"):
        publish_files({"OUTPUT_HTML": (str(src), str(page), "file")},
                      inputs={"INPUT": str(page)})
    assert page.read_text() == "<p>input</p>"
    with pytest.raises(ValueError, match="choose a destination ending in .html"):
        publish_files({"OUTPUT_HTML": (str(src), str(tmp_path / "r.txt"), "file")})
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a.html", "page.html"]
    out = publish_files({"OUTPUT_HTML": (str(src), str(tmp_path / "r.html"), "file")})
    assert out == {"OUTPUT_HTML": str(tmp_path / "r.html")}
    assert (tmp_path / "r.html").read_text() == "<p>report</p>"

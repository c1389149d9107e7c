"""The LAS → ground filter → DTM → accuracy Processing model under qgis_process."""
from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from geomatics_toolbox.core.io.raster import read_raster
from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile

ROOT = Path(__file__).resolve().parents[2]
MODEL = ROOT / "models" / "lidar_to_dtm.model3"
OUTPUT_LABELS = ("Classified point cloud", "Ground filter report", "DTM", "DTM report",
                 "Check-point residuals", "DTM accuracy report")


@pytest.fixture(scope="module")
def demo(tmp_path_factory):
    d = tmp_path_factory.mktemp("model")
    tile = generate_tile(extent=(120.0, 120.0), density=2.0, seed=6)
    write_tile(tile, d / "demo.laz", crs="EPSG:32632")
    tile.checkpoints(n=15, min_spacing=4.0).to_csv(d / "checkpoints.csv", xy_decimals=2,
                                                   z_decimals=3)
    return d


def run_model(qgis_process, model, d, **extra):
    out = d / str(model.stem).replace(":", "_")
    out.mkdir(exist_ok=True)
    params = {"INPUT": d / "demo.laz", "CHECKPOINTS_CSV": d / "checkpoints.csv",
              "CELL_SIZE": 1, "POWER": 3,
              "publish:Classified point cloud": out / "ground.laz",
              "publish:Ground filter report": out / "filter.html",
              "publish:DTM": out / "dtm.tif", "publish:DTM report": out / "dtm.html",
              "publish:Check-point residuals": out / "residuals.gpkg",
              "publish:DTM accuracy report": out / "accuracy.html", **extra}
    res = qgis_process.run(str(model), **{k: str(v) for k, v in params.items()})
    return res, out


def check_outputs(res, out):
    assert (out / "dtm.tif").exists() and (out / "accuracy.html").exists()
    r = read_raster(out / "dtm.tif")
    assert "32632" in r.crs or "UTM zone 32N" in r.crs
    html = (out / "accuracy.html").read_text(encoding="utf-8")
    assert "RMSE" in html and "<svg" in html
    log = " ".join(res.get("log", {}).get("info", []))
    assert "RMSE" in log


def test_chain_with_slope_filter(qgis_process, demo):
    """The same chain built with the Vosselman slope filter (always available)."""
    model = demo / "slope_chain.model3"
    subprocess.run([sys.executable, str(ROOT / "scripts" / "build_model.py"), "--filter",
                    "slope", "--out", str(model)], check=True, capture_output=True)
    # built on this QGIS, the outputs keep their publish: names (3.40 would save
    # internal_version=Version2 and call them "dtm", … without build_model's pin)
    import xml.etree.ElementTree as ET
    versions = [o.get("value") for o in ET.parse(model).getroot()
                if o.get("name") == "internal_version"]
    assert versions in ([], ["Version1"]), versions
    res, out = run_model(qgis_process, model, demo)
    check_outputs(res, out)
    assert sorted(k for k in res["results"] if k.startswith("publish:")) == sorted(
        f"publish:{label}" for label in OUTPUT_LABELS)


def test_model_output_names_pinned_to_version1(qgis_app):
    """A model that QGIS made Version2 (3.40: outputs "dtm", …) is reloaded as Version1."""
    sys.path.insert(0, str(ROOT / "scripts"))
    try:
        import build_model
    finally:
        sys.path.remove(str(ROOT / "scripts"))
    model = build_model.build("slope")
    variant = model.toVariant()
    variant["internal_version"] = "Version2"
    assert model.loadVariant(variant)
    names = sorted(d.name() for d in model.destinationParameterDefinitions())
    if "internal_version" in model.toVariant():  # QGIS with Version2 models (3.40)
        assert len(names) == len(OUTPUT_LABELS) and not [
            n for n in names if n.startswith("publish:")], names   # "dtm", …
    else:                                         # QGIS 3.22: Version1 only
        assert names == sorted(f"publish:{label}" for label in OUTPUT_LABELS)
    build_model.pin_output_names(model)
    assert sorted(d.name() for d in model.destinationParameterDefinitions()) == sorted(
        f"publish:{label}" for label in OUTPUT_LABELS)
    assert model.toVariant().get("internal_version", "Version1") == "Version1"
    assert {label for label, *_ in build_model.OUTPUTS} == set(OUTPUT_LABELS)


def test_shipped_model(qgis_process, demo):
    assert MODEL.exists(), f"{MODEL} missing: run `make model`"
    listing = qgis_process.call("list").stdout
    assert "geomatics:groundfilter" in listing
    res, out = run_model(qgis_process, MODEL, demo)
    check_outputs(res, out)
    # the provider also offers the shipped model as geomatics:lidar_to_dtm
    if "geomatics:lidar_to_dtm" in listing:
        res, out = run_model(qgis_process, Path("geomatics:lidar_to_dtm"), demo)
        check_outputs(res, out)


def test_shipped_model_is_valid_and_sets_every_child_parameter(qgis_app):
    """validate() finds no issue, and a parameter added to a child fails this test."""
    from qgis.core import QgsApplication, QgsProcessingModelAlgorithm

    from geomatics_toolbox.algorithms.base import _groups
    model = QgsProcessingModelAlgorithm()
    assert model.fromFile(str(MODEL))
    ok, issues = model.validate()
    assert ok and not issues, issues
    registry = QgsApplication.processingRegistry()
    expected_filter = ("geomatics:groundfilter"
                       if registry.algorithmById("geomatics:groundfilter") is not None
                       else "geomatics:lsqgroundfilter")
    children = model.childAlgorithms()
    assert children["groundfilter"].algorithmId() == expected_filter, "run make model"
    for child_id, child in children.items():
        alg = registry.algorithmById(child.algorithmId())
        wanted = {d.name() for d in alg.parameterDefinitions() if not d.isDestination()}
        unset = wanted - set(child.parameterSources())
        assert not unset, f"{child_id} does not set {sorted(unset)}: run make model"
    order = [p.parameterName() for p in model.orderedParameters()]
    assert order[0] == "INPUT" and order[-2:] == ["CHECKPOINTS", "CHECKPOINTS_CSV"]
    filter_params = [n for n in order[1:] if n not in ("CELL_SIZE", "POWER") and
                     n in {d.name() for d in registry.algorithmById(
                         expected_filter).parameterDefinitions()}]
    # the filter's own settings (none for the recommended filter) come before the DTM's
    assert all(order.index("CELL_SIZE") > order.index(n) for n in filter_params)
    for d in model.destinationParameterDefinitions():
        label = d.name().split(":", 1)[1]
        assert (label == "DTM" or not label.isupper()) and label == d.description(), d.name()
    for d in model.parameterDefinitions():
        assert "optional" not in d.description().lower(), d.description()
    # offered by the provider under a translated title in its own translated group
    shipped = registry.algorithmById("geomatics:lidar_to_dtm")
    assert shipped is not None
    assert shipped.displayName() == "LiDAR to DTM with accuracy"
    assert shipped.group() == _groups()["terrain"] and shipped.groupId() == "terrain"
    assert shipped.createInstance().displayName() == shipped.displayName()

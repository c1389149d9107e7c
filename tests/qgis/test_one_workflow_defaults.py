"""One entry per workflow: lidartodtm, the shipped model and the three algorithms agree.

With nothing but the inputs and the outputs given (every other parameter at its
default), ``geomatics:lidartodtm``, the model ``lidar_to_dtm`` and ground filter →
``idwdtm`` → ``dtmaccuracy`` give bit-identical classes and DTM cells and the same
RMSE. The input is a raw cloud (every class 1) with planted low outliers, so a
different low-outlier default (NOISE) or IDW power in any entry point would show.
"""
from __future__ import annotations

from pathlib import Path

import laspy
import numpy as np
import pytest

from geomatics_toolbox.core.io.raster import read_raster
from geomatics_toolbox.core.lidar.filters import GROUND_FILTERS, default_ground_filter
from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile

MODEL = Path(__file__).resolve().parents[2] / "models" / "lidar_to_dtm.model3"


@pytest.fixture(scope="module")
def raw(tmp_path_factory):
    d = tmp_path_factory.mktemp("oneworkflow")
    tile = generate_tile(extent=(90.0, 90.0), density=2.0, seed=21, n_buildings=1,
                         n_halls=0, n_low_outliers=30)
    laz = d / "tile.laz"
    write_tile(tile, laz, crs="EPSG:32632")
    las = laspy.read(str(laz))
    las.classification = np.ones(len(las.points), np.uint8)      # a raw cloud
    las.write(str(laz))
    cp = tile.checkpoints(n=10, min_spacing=3.0)
    return {"laz": str(laz), "csv": cp.to_csv(d / "cp.csv")}


def _classes(path) -> np.ndarray:
    return np.asarray(laspy.read(str(path)).classification)


def test_defaults_agree_bit_for_bit(qgis_processing, raw, tmp_path):
    from qgis.core import QgsProcessingModelAlgorithm
    one, seq, mod = (tmp_path / n for n in ("one", "seq", "model"))
    for d in (one, seq, mod):
        d.mkdir()
    res = qgis_processing.run("geomatics:lidartodtm", {
        "INPUT": raw["laz"], "CHECKPOINTS_CSV": raw["csv"],
        "OUTPUT": str(one / "c.laz"), "OUTPUT_DTM": str(one / "dtm.tif")})
    alg_id = GROUND_FILTERS[default_ground_filter()].algorithm
    qgis_processing.run(f"geomatics:{alg_id}", {"INPUT": raw["laz"],
                                                 "OUTPUT": str(seq / "c.laz")})
    qgis_processing.run("geomatics:idwdtm", {"INPUT": str(seq / "c.laz"),
                                             "OUTPUT": str(seq / "dtm.tif")})
    acc = qgis_processing.run("geomatics:dtmaccuracy", {
        "DTM": str(seq / "dtm.tif"), "CHECKPOINTS_CSV": raw["csv"]})
    model = QgsProcessingModelAlgorithm()
    assert model.fromFile(str(MODEL))
    assert model.childAlgorithms()["groundfilter"].algorithmId() == f"geomatics:{alg_id}"
    qgis_processing.run(model, {
        "INPUT": raw["laz"], "CHECKPOINTS_CSV": raw["csv"],
        "publish:Classified point cloud": str(mod / "c.laz"),
        "publish:DTM": str(mod / "dtm.tif"),
        "publish:DTM accuracy report": str(mod / "acc.html")})
    a, b, c = (_classes(d / "c.laz") for d in (one, seq, mod))
    assert np.count_nonzero(b == 2) > 5000
    np.testing.assert_array_equal(a, b)
    np.testing.assert_array_equal(c, b)
    dtms = [read_raster(str(d / "dtm.tif")) for d in (one, seq, mod)]
    assert dtms[0].geotransform == dtms[1].geotransform == dtms[2].geotransform
    assert np.isfinite(dtms[1].masked()).sum() > 6000
    for d in (dtms[0], dtms[2]):
        np.testing.assert_array_equal(d.masked(), dtms[1].masked())
    assert res["N"] == acc["N"] == 10
    assert res["RMSE"] == acc["RMSE"]


@pytest.mark.parametrize("lang", ["ar", "fa"])
def test_model_is_translated_with_description_and_help(qgis_app, lang, monkeypatch):
    """The shipped model shows its title, description, help and labels in ar/fa."""
    from qgis.core import QgsProcessingModelAlgorithm
    from qgis.PyQt.QtCore import QCoreApplication, QTranslator

    from geomatics_toolbox.algorithms import helptext
    from geomatics_toolbox.provider import provider
    root = Path(__file__).resolve().parents[2]
    plain = QgsProcessingModelAlgorithm()          # the file's own (English) labels
    assert plain.fromFile(str(MODEL))
    english = {d.name(): d.description() for d in plain.parameterDefinitions()}
    assert set(english.values()) <= set(provider.MODEL_LABELS)
    description, help_text = provider.LIDAR_TO_DTM_TEXTS
    assert "Model Designer" in help_text
    translator = QTranslator()
    assert translator.load(str(root / "i18n" / f"geomatics_toolbox_{lang}.qm"))
    QCoreApplication.installTranslator(translator)
    monkeypatch.setattr(helptext, "user_locale", lambda: lang)
    try:
        model = provider.shipped_model(str(MODEL))
        assert model.displayName() != "LiDAR to DTM with accuracy"
        assert model.shortDescription() not in ("", description)
        assert model.shortHelpString().startswith('<div dir="rtl">')
        assert "Model Designer" not in model.shortHelpString()
        left = [d.name() for d in model.parameterDefinitions()
                if d.description() == english[d.name()]]
        assert left == [], f"labels left in English under {lang}: {left}"
    finally:
        QCoreApplication.removeTranslator(translator)


def test_lidartodtm_decodes_its_input_once(qgis_processing, raw, tmp_path, monkeypatch):
    """Filter, classified cloud, DTM and accuracy from ONE decode of the input LAZ."""
    from geomatics_toolbox.core.io import las as las_io
    calls = []
    real = las_io._chunks

    def counting(reader, path, chunk_size):
        calls.append(str(path))
        return real(reader, path, chunk_size)

    monkeypatch.setattr(las_io, "_chunks", counting)
    qgis_processing.run("geomatics:lidartodtm", {
        "INPUT": raw["laz"], "CHECKPOINTS_CSV": raw["csv"],
        "OUTPUT": str(tmp_path / "c.laz"), "OUTPUT_DTM": str(tmp_path / "dtm.tif"),
        "OUTPUT_FILTER_HTML": str(tmp_path / "f.html"),
        "OUTPUT_DTM_HTML": str(tmp_path / "d.html")})
    assert calls == [raw["laz"]]
    assert (tmp_path / "dtm.tif").stat().st_size > 0

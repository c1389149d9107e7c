"""Core InputError messages reach the user in the QGIS interface language."""
from __future__ import annotations

import pickle

import pytest
from qgis.core import QgsProcessingException

from geomatics_toolbox.core.errors import FSI, PDI, InputError
from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile


def test_input_error_is_english_template_translated_on_demand():
    e = InputError("{path} holds no check points.", path="/data/cp.csv")
    assert isinstance(e, ValueError) and str(e) == "/data/cp.csv holds no check points."
    assert e.message("en") == str(e)
    ar = e.message("ar")
    assert ar == f"لا يحتوي {FSI}/data/cp.csv{PDI} على أي نقاط تحقق."
    assert e.message("fa") == f"{FSI}/data/cp.csv{PDI} هیچ نقطهٔ چکی ندارد."
    # untranslated text stays English; pickling (Dask workers) keeps the template
    assert InputError("no such template {x}", x=1).message("ar") == "no such template 1"
    back = pickle.loads(pickle.dumps(e))
    assert back.message("ar") == ar and str(back) == str(e)


def test_core_error_in_arabic_through_processing_run(qgis_processing, arabic_ui, tmp_path):
    tile = generate_tile(extent=(60.0, 60.0), density=2.0, seed=3, n_buildings=1, n_halls=0)
    laz = tmp_path / "tile.laz"
    write_tile(tile, laz, crs="EPSG:32632")
    dtm = qgis_processing.run("geomatics:idwdtm", {
        "INPUT": str(laz), "CELL_SIZE": 2.0, "OUTPUT": str(tmp_path / "dtm.tif")})["OUTPUT"]
    missing = tmp_path / "nothere.csv"
    report = tmp_path / "acc.html"
    with pytest.raises(QgsProcessingException) as info:
        qgis_processing.run("geomatics:dtmaccuracy", {
            "DTM": dtm, "CHECKPOINTS_CSV": str(missing), "OUTPUT_HTML": str(report)})
    assert str(info.value) == f"ملف نقاط التحقق غير موجود: {FSI}{missing}{PDI}."
    assert not report.exists()


def test_kriging_neighbours_refusal_in_arabic_names_the_dialog_label(qgis_processing,
                                                                     arabic_ui, tmp_path):
    """The Arabic message names the label of the dialog and the qgis_process id."""
    import numpy as np

    from geomatics_toolbox.core.io.las import write_las
    rng = np.random.default_rng(5)
    src = tmp_path / "ten.las"
    write_las(src, 500_000 + rng.uniform(0, 20, 10), 4_000_000 + rng.uniform(0, 20, 10),
              100 + rng.uniform(0, 2, 10), dimensions={"classification": np.full(10, 2, "u1")},
              crs="EPSG:32632")
    with pytest.raises(QgsProcessingException) as info:
        qgis_processing.run("geomatics:krigingdtm", {
            "INPUT": str(src), "CELL_SIZE": 1.0, "NEIGHBOURS": 16,
            "OUTPUT": str(tmp_path / "dtm.tif")})
    assert str(info.value) == (
        f"لا توجد إلا {FSI}10{PDI} مواضع متمايزة للنقاط للكريغينغ، لكن «عدد الجيران لكل "
        f"خلية» (NEIGHBOURS) هو {FSI}16{PDI}: اجعل قيمة NEIGHBOURS \u200f{FSI}10{PDI} أو "
        "أقل، أو استخدم سحابة نقاط فيها نقاط أرض أكثر.")
    # the label as the Arabic dialog shows it (the translation of the parameter's label)
    import json
    from pathlib import Path
    base = Path(__file__).resolve().parents[2] / "i18n" / "strings" / "base.json"
    label = json.loads(base.read_text(encoding="utf-8"))["Neighbours per cell"]["ar"]
    assert f"«{label}» (NEIGHBOURS)" in str(info.value)

"""GSD calculator algorithms through processing.run in a headless QGIS."""
import csv

import pytest

P100 = {"DISTANCE": 5.88, "SENSOR_WIDTH": 6.123, "IMAGE_WIDTH": 3648, "FOCAL_LENGTH": 4.6}


def test_golden_numbers_through_processing(qgis_processing, tmp_path):
    html = tmp_path / "gsd.html"
    res = qgis_processing.run("geomatics:gsdcalculator",
                              {**P100, "TARGET_GSD": 0.21, "OUTPUT_HTML": str(html)})
    assert res["GSD"] == pytest.approx(0.21455, abs=5e-6)
    assert res["SIGMA_XYZ"] == pytest.approx(1.287, abs=5e-4)
    assert res["DENSE_RESOLUTION"] == pytest.approx(0.858, abs=5e-4)
    assert res["FOOTPRINT_WIDTH"] == pytest.approx(7.827, abs=5e-4)
    assert res["DISTANCE_FOR_TARGET"] == pytest.approx(5.755, abs=5e-4)
    assert res["RATIO_XYZ"] is None
    text = html.read_text(encoding="utf-8")
    assert "0.21455" in text and "1.2873" in text and "7.82679" in text


def test_rounded_and_ratios(qgis_processing):
    res = qgis_processing.run("geomatics:gsdcalculator",
                              {**P100, "ROUND_GSD": True, "OBSERVED_SXYZ": 7.6,
                               "OBSERVED_DENSE_STD": 1.4})
    assert res["SIGMA_XYZ"] == pytest.approx(1.26)
    assert res["DENSE_RESOLUTION"] == pytest.approx(0.84)
    assert round(res["RATIO_XYZ"], 2) == 6.03
    assert res["RATIO_DENSE"] == pytest.approx(1.4 / 0.84)


def test_camera_preset(qgis_processing):
    from geomatics_toolbox.algorithms.gsd_calculator import CAMERA_KEYS
    res = qgis_processing.run("geomatics:gsdcalculator",
                              {"CAMERA": CAMERA_KEYS.index("nikon_p100"), "DISTANCE": 5.88})
    assert res["GSD"] == pytest.approx(0.21455, abs=5e-6)
    assert res["FOOTPRINT_HEIGHT"] == pytest.approx(5.88 * 4.592 / 4.6)


@pytest.mark.parametrize("params, name", [
    ({**P100, "DISTANCE": 0}, "DISTANCE"),                     # QGIS's own minimum check
    ({"DISTANCE": 5.88, "SENSOR_WIDTH": 6.123, "IMAGE_WIDTH": 3648}, "FOCAL_LENGTH"),
])
def test_bad_input_raises_processing_exception(qgis_processing, params, name):
    from qgis.core import QgsProcessingException
    with pytest.raises(QgsProcessingException) as err:
        qgis_processing.run("geomatics:gsdcalculator", params)
    assert name in str(err.value) and name.lower() not in str(err.value)


def _label(name):
    from qgis.core import QgsApplication
    alg = QgsApplication.processingRegistry().algorithmById("geomatics:gsdcalculator")
    return alg.parameterDefinition(name).description()


@pytest.mark.parametrize("params, name, rest", [
    ({**P100, "FOCAL_LENGTH": 0}, "FOCAL_LENGTH", "must be > 0 mm, got 0 mm. Enter the true"),
    ({**P100, "IMAGE_WIDTH": 0}, "IMAGE_WIDTH", "must be > 0 px, got 0 px."),
    ({**P100, "SENSOR_WIDTH": 0}, "SENSOR_WIDTH", "must be > 0 mm, got 0 mm."),
    ({**P100, "PYRAMID_LEVEL": 1.5}, "PYRAMID_LEVEL", "must be in (0, 1], got 1.5."),
    ({**P100, "SUBSAMPLING_STEP": 0.5}, "SUBSAMPLING_STEP", "must be ≥ 1 px, got 0.5 px."),
    ({**P100, "K_M": 0.0}, "K_M", "must be > 0 px, got 0 px."),
    ({**P100, "K_S": 0.0}, "K_S", "must be > 0, got 0."),
    ({**P100, "TARGET_GSD": 0.0}, "TARGET_GSD", "must be > 0 cm/px, got 0 cm/px."),
    ({**P100, "IMAGE_HEIGHT": 0.0}, "IMAGE_HEIGHT", "must be > 0 px, got 0 px."),
    # was "sensor_size must be > 0 mm": a core name the dialog never shows
    ({**P100, "SENSOR_HEIGHT": 0.0}, "SENSOR_HEIGHT", "must be > 0 mm, got 0 mm."),
    ({**P100, "STEREO_BASE": 0.0}, "STEREO_BASE", "must be > 0 m, got 0 m."),
    ({**P100, "OBSERVED_SXYZ": 0.0}, "OBSERVED_SXYZ", "must be > 0 mm, got 0 mm."),
])
def test_bad_option_named_as_the_dialog_and_qgis_process_show_it(qgis_processing, params,
                                                                 name, rest):
    """The calculator names the parameter by its dialog label and its qgis_process name
    (was the core keyword upper-cased, K_M — and 'sensor_size' for SENSOR_HEIGHT)."""
    from qgis.core import QgsProcessingException

    from geomatics_toolbox.algorithms.gsd_calculator import GsdCalculatorAlgorithm
    with pytest.raises(QgsProcessingException) as err:
        qgis_processing.run("geomatics:gsdcalculator", params)
    text = str(err.value)
    assert text.startswith(f"\u201c{_label(name)}\u201d ({name}) {rest}"), text
    outside = text.replace(_label(name), "")
    assert not [k for k in GsdCalculatorAlgorithm.KEYWORD_PARAMETERS if k in outside]


def test_bad_option_named_as_the_parameter_in_arabic(qgis_processing, arabic_ui):
    """Under an Arabic interface: the Arabic dialog label (the translation of the
    parameter's label) and the qgis_process name, bidi-isolated."""
    import json
    from pathlib import Path

    from qgis.core import QgsProcessingException

    from geomatics_toolbox.core.errors import FSI, PDI
    strings = Path(__file__).resolve().parents[2] / "i18n" / "strings" / "base.json"
    label = json.loads(strings.read_text(encoding="utf-8"))["Sensor height (mm)"]["ar"]
    with pytest.raises(QgsProcessingException) as err:
        qgis_processing.run("geomatics:gsdcalculator", {**P100, "SENSOR_HEIGHT": 0.0})
    assert str(err.value) == (
        f"يجب أن يكون {FSI}«{FSI}{label}{PDI}» ({FSI}SENSOR_HEIGHT{PDI}){PDI} {FSI}> 0{PDI}"
        f"{FSI} mm{PDI}، وأُعطي {FSI}0{PDI}{FSI} mm{PDI}.{FSI}{PDI}")


def test_negative_focal_length_refused_by_qgis(qgis_processing):
    from qgis.core import QgsProcessingException
    with pytest.raises(QgsProcessingException, match="FOCAL_LENGTH"):
        qgis_processing.run("geomatics:gsdcalculator", {**P100, "FOCAL_LENGTH": -4.6})


def test_batch_table(qgis_processing, tmp_path):
    src = tmp_path / "cams.csv"
    with open(src, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(["label", "camera", "distance", "sensor_width", "image_width",
                    "focal_length", "observed_sxyz"])
        w.writerow(["paper", "", 5.88, 6.123, 3648, 4.6, 3.85])
        w.writerow(["p4rtk", "dji_p4rtk", 100, "", "", "", ""])
    out = tmp_path / "gsd_out.csv"
    res = qgis_processing.run("geomatics:gsdbatch", {"INPUT": str(src), "ROUND_GSD": True,
                                                     "OUTPUT": str(out)})
    assert res["OUTPUT"] == str(out)
    rows = list(csv.DictReader(open(out, newline="")))
    assert [r["label"] for r in rows] == ["paper", "p4rtk"]
    assert float(rows[0]["sigma_xyz_mm"]) == pytest.approx(1.26)
    assert round(float(rows[0]["ratio_xyz"]), 2) == 3.06
    assert float(rows[1]["gsd_cm"]) == pytest.approx(round(100 / 36.5, 2), abs=0.011)


def test_batch_bad_row_names_row_and_column(qgis_processing, tmp_path):
    from qgis.core import QgsProcessingException
    src = tmp_path / "bad.csv"
    src.write_text("distance,sensor_width,image_width,focal_length\n5.88,6.123,3648,4.6\n"
                   "5.88,6.123,3648,-1\n")
    out = tmp_path / "never.csv"
    with pytest.raises(QgsProcessingException, match="Row 2.*focal_length"):
        qgis_processing.run("geomatics:gsdbatch", {"INPUT": str(src), "OUTPUT": str(out)})
    assert not out.exists()
    assert not list(tmp_path.glob(".never*")), "temporary left behind"


def test_batch_output_is_input_refused_and_input_untouched(qgis_processing, tmp_path):
    from qgis.core import QgsProcessingException
    src = tmp_path / "cams.csv"
    text = "distance,sensor_width,image_width,focal_length\n5.88,6.123,3648,4.6\n"
    src.write_text(text)
    with pytest.raises(QgsProcessingException, match="(?i)input"):
        qgis_processing.run("geomatics:gsdbatch", {"INPUT": str(src), "OUTPUT": str(src)})
    assert src.read_text() == text
    assert sorted(p.name for p in tmp_path.iterdir()) == ["cams.csv"]


def test_distance_default_is_valid_and_custom_needs_camera(qgis_processing, qgis_app):
    from qgis.core import QgsApplication, QgsProcessingContext
    alg = QgsApplication.processingRegistry().algorithmById("geomatics:gsdcalculator")
    assert alg.parameterDefinition("DISTANCE").defaultValue() == 100.0
    res = qgis_processing.run("geomatics:gsdcalculator",
                              {k: v for k, v in P100.items() if k != "DISTANCE"})
    assert res["GSD"] == pytest.approx(100 * 6.123 * 100 / (3648 * 4.6))
    ok, msg = alg.checkParameterValues({"CAMERA": 0, "DISTANCE": 5.88, "SENSOR_WIDTH": 6.1,
                                        "IMAGE_WIDTH": 3648}, QgsProcessingContext())
    assert not ok and "FOCAL_LENGTH" in msg and "Custom" in msg
    ok, msg = alg.checkParameterValues({**P100}, QgsProcessingContext())
    assert ok, msg
    assert alg.shortDescription()


@pytest.mark.parametrize("lang, index, title", [
    ("ar", 2, "المسافة الأرضية"), ("fa", 3, "نمونه‌برداری زمینی")])
def test_report_in_the_requested_language(qgis_processing, tmp_path, lang, index, title):
    html = tmp_path / f"gsd_{lang}.html"
    qgis_processing.run("geomatics:gsdcalculator",
                        {**P100, "OUTPUT_HTML": str(html), "REPORT_LANGUAGE": index})
    text = html.read_text(encoding="utf-8")
    assert f'lang="{lang}" dir="rtl"' in text
    assert '<bdi dir="ltr">0.21455</bdi>' in text
    assert "Results" not in text and "Inputs" not in text

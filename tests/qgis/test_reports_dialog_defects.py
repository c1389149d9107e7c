"""Report, log and default defects of issue 19 ("Dialogs, reports, translations"):
reports carry date, plugin version, project and operator and name the real files (the
model's steps read temporaries); GCP log lines in the interface language with the unit
symbol; rectifygcp defaults to the transformation its own report recommends."""
from __future__ import annotations

import configparser
import datetime as dt
import re
from pathlib import Path

import pytest

from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile

ROOT = Path(__file__).resolve().parents[2]


def _version() -> str:
    parser = configparser.ConfigParser(interpolation=None)
    parser.read(ROOT / "metadata.txt", encoding="utf-8")
    return parser.get("general", "version")


@pytest.fixture(scope="module")
def scene(tmp_path_factory):
    d = tmp_path_factory.mktemp("reports")
    tile = generate_tile(extent=(80.0, 80.0), density=2.0, seed=11, n_buildings=1,
                         n_halls=0)
    laz = d / "survey_2026.laz"
    write_tile(tile, laz, crs="EPSG:32632")
    cp = tile.checkpoints(n=10, min_spacing=3.0)
    csv = cp.to_csv(d / "gnss_checks.csv")
    return {"dir": d, "laz": str(laz), "csv": str(csv)}


def _about(html: str) -> dict:
    table = re.search(r'<table class="about" id="report-about">(.*?)</table>', html, re.S)
    assert table, "no about table"
    rows = re.findall(r"<tr><th>(.*?)</th><td><bdi dir=\"ltr\">(.*?)</bdi></td></tr>",
                      table.group(1))
    return dict(rows)


def test_report_carries_date_version_project_operator(qgis_processing, scene):
    d = scene["dir"]
    before = dt.datetime.now().astimezone()
    qgis_processing.run("geomatics:idwdtm", {
        "INPUT": scene["laz"], "CELL_SIZE": 2.0, "OUTPUT": str(d / "a.tif"),
        "OUTPUT_HTML": str(d / "a.html"), "REPORT_PROJECT": "Zagros <forest> 2026",
        "REPORT_OPERATOR": "S. Surveyor"})
    about = _about((d / "a.html").read_text(encoding="utf-8"))
    assert about["Plugin version"] == _version()
    assert about["Project"] == "Zagros &lt;forest&gt; 2026"      # escaped data
    assert about["Operator"] == "S. Surveyor"
    stamp = dt.datetime.strptime(about["Date"][:16], "%Y-%m-%d %H:%M")
    assert abs((stamp - before.replace(tzinfo=None)).total_seconds()) < 600
    assert re.fullmatch(r"\d{4}-\d\d-\d\d \d\d:\d\d UTC[+-]\d\d:\d\d", about["Date"])
    # unset: no empty rows; in Persian the labels are translated
    qgis_processing.run("geomatics:idwdtm", {
        "INPUT": scene["laz"], "CELL_SIZE": 2.0, "OUTPUT": str(d / "b.tif"),
        "OUTPUT_HTML": str(d / "b.html"), "REPORT_LANGUAGE": 3})
    about = _about((d / "b.html").read_text(encoding="utf-8"))
    assert set(about) == {"تاریخ", "نسخهٔ افزونه"}


def test_every_report_algorithm_has_project_and_operator(qgis_app):
    from qgis.core import QgsProcessingParameterFileDestination

    from geomatics_toolbox.algorithms import all_algorithms
    for alg in all_algorithms():
        alg.initAlgorithm()
        html = [p for p in alg.destinationParameterDefinitions()
                if isinstance(p, QgsProcessingParameterFileDestination)
                and "html" in p.fileFilter().lower()]
        if html and alg.name() != "publishoutputs":
            names = {p.name() for p in alg.parameterDefinitions()}
            assert {"REPORT_LANGUAGE", "REPORT_PROJECT", "REPORT_OPERATOR"} <= names, \
                alg.name()


def test_model_reports_name_the_published_files(qgis_processing, scene):
    """The model's steps read temporaries: its reports said "input OUTPUT.laz" and
    named /tmp/processing_… files."""
    d = scene["dir"] / "model"
    d.mkdir()
    res = qgis_processing.run("geomatics:lidar_to_dtm", {
        "INPUT": scene["laz"], "CHECKPOINTS_CSV": scene["csv"], "CELL_SIZE": 1.0,
        "publish:Classified point cloud": str(d / "classified_2026.laz"),
        "publish:DTM": str(d / "dtm_2026.tif"),
        "publish:DTM report": str(d / "dtm_report.html"),
        "publish:DTM accuracy report": str(d / "accuracy.html"),
        "REPORT_PROJECT": "Zagros 2026", "REPORT_OPERATOR": "S. Surveyor"})
    assert res["publish:DTM"] == str(d / "dtm_2026.tif")
    dtm_report = (d / "dtm_report.html").read_text(encoding="utf-8")
    accuracy = (d / "accuracy.html").read_text(encoding="utf-8")
    for text in (dtm_report, accuracy):
        assert "processing_" not in text and "OUTPUT." not in text
    assert "classified_2026.laz" in dtm_report
    assert "dtm_2026.tif" in accuracy
    # the model's project and operator reach every report of the chain
    for text in (dtm_report, accuracy):
        about = _about(text)
        assert about["Project"] == "Zagros 2026" and about["Operator"] == "S. Surveyor"


def test_relabel_replaces_paths_then_names(tmp_path):
    from geomatics_toolbox.core.io.publish import relabel_html
    page = tmp_path / "r.html"
    page.write_text("<td>/tmp/processing_x/ab/OUTPUT.tif</td><td>OUTPUT.tif</td>"
                    "<td>OUTPUT.laz</td>", encoding="utf-8")
    relabel_html(str(page), {"/tmp/processing_x/ab/OUTPUT.tif": "/data/dtm.tif",
                             "/tmp/processing_x/cd/OUTPUT.laz": "/data/c.laz"})
    assert page.read_text(encoding="utf-8") == (
        "<td>/data/dtm.tif</td><td>dtm.tif</td><td>c.laz</td>")


# --------------------------------------------------------------------------- GCP
def _gcp_case(tmp_path):
    from geomatics_toolbox.core.io import gcp as gcp_io
    from geomatics_toolbox.synthetic import gcp as gcp_synthetic
    pix, mp, _, _ = gcp_synthetic.synthetic_gcps(2, noise=1.0, seed=3)
    pix = pix / 8.0
    w, h = int(pix[:, 0].max() + 20), int(pix[:, 1].max() + 20)
    img = gcp_synthetic.write_test_image(tmp_path / "img.tif", w, h)
    g = gcp_io.make_gcps(None, pix, mp)
    pts = tmp_path / "img.tif.points"
    pts.write_text(gcp_io.points_text(g, crs_wkt="EPSG:22780"))
    return str(img), str(pts)


class _Log:
    def __init__(self):
        from qgis.core import QgsProcessingFeedback

        class F(QgsProcessingFeedback):
            def __init__(self, sink):
                super().__init__()
                self.sink = sink

            def pushInfo(self, info):  # noqa: N802
                self.sink.lines.append(info)

            def pushWarning(self, warning):  # noqa: N802
                self.sink.lines.append(warning)

        self.lines = []
        self.feedback = F(self)


def test_rectifygcp_defaults_to_what_its_report_recommends(qgis_processing, tmp_path):
    """The default was polynomial order 1, which the report itself rejects on this
    order-2 distortion; the default is now the recommended transformation."""
    img, pts = _gcp_case(tmp_path)
    res = qgis_processing.run("geomatics:rectifygcp", {
        "INPUT": img, "GCP_FILE": pts, "OUTPUT": str(tmp_path / "r.tif")})
    assert res["RECOMMENDED_TRANSFORMATION"] == "polynomial2"
    assert res["RECOMMENDED_ORDER"] == 2
    assert res["TRANSFORMATION_USED"] == res["RECOMMENDED_TRANSFORMATION"]
    # the old default (order 1), which the same report ranks below order 2: its
    # leave-one-out RMS_T is 2.97 m against 2.04 m
    old = qgis_processing.run("geomatics:rectifygcp", {
        "INPUT": img, "GCP_FILE": pts, "TRANSFORMATION": 0, "ORDER": 1,
        "OUTPUT": str(tmp_path / "o1.tif")})
    assert old["TRANSFORMATION_USED"] == "polynomial1"
    assert old["RECOMMENDED_TRANSFORMATION"] == "polynomial2"
    assert old["HONEST_RMS_T"] > 1.3 * res["HONEST_RMS_T"]
    # the command line of earlier versions (ORDER only) keeps its meaning
    only = qgis_processing.run("geomatics:rectifygcp", {
        "INPUT": img, "GCP_FILE": pts, "ORDER": 3, "OUTPUT": str(tmp_path / "o3.tif")})
    assert only["TRANSFORMATION_USED"] == "polynomial3"


@pytest.mark.parametrize("lang", ["ar", "fa"])
def test_gcp_log_lines_translated_with_unit_symbol(qgis_processing, tmp_path, lang):
    """GCP log lines and the unit "metre" stayed English in Arabic."""
    from qgis.core import QgsSettings
    from qgis.PyQt.QtCore import QCoreApplication, QTranslator
    qm = ROOT / "i18n" / f"geomatics_toolbox_{lang}.qm"
    if not qm.exists():
        pytest.skip("run `make qm` first")
    img, pts = _gcp_case(tmp_path)
    settings = QgsSettings()
    old = (settings.value("locale/overrideFlag"), settings.value("locale/userLocale"))
    settings.setValue("locale/overrideFlag", True)
    settings.setValue("locale/userLocale", lang)
    translator = QTranslator()
    assert translator.load(str(qm))
    QCoreApplication.installTranslator(translator)
    log = _Log()
    try:
        qgis_processing.run("geomatics:gcpaccuracyreport", {
            "INPUT": img, "GCP_FILE": pts, "REFINE": True}, feedback=log.feedback)
        qgis_processing.run("geomatics:rectifygcp", {
            "INPUT": img, "GCP_FILE": pts, "OUTPUT": str(tmp_path / "r.tif")},
            feedback=log.feedback)
    finally:
        QCoreApplication.removeTranslator(translator)
        for key, value in zip(("locale/overrideFlag", "locale/userLocale"), old):
            if value is None:
                settings.remove(key)
            else:
                settings.setValue(key, value)
    ours = [s for s in log.lines if ("RMS_T" in s or ".tif" in s)
            and not s.startswith("Results:")]      # (QGIS's own line)
    assert len(ours) >= 4, log.lines
    for line in ours:
        assert "metre" not in line, line
        if "RMS_T =" in line:
            assert re.search(r"\d m\b", line), line          # the unit symbol
        plain = re.sub(r"\(\w+\)|RMS_T|polynomial\d|linear|helmert|projective|tps|\S*/\S*|"
                       r"\S+\.tif|\bn\b|\bN\b", " ", line)
        assert not re.search(r"[A-Za-z]{3,}", plain), line

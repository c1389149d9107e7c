"""Terrain algorithms keep the output contract and refuse bad input clearly (issue 9).

Every case asserts a clear message, byte-identical inputs and nothing at any output
path or temporary name (``.<stem>.part-<hex><ext>``).
"""
from __future__ import annotations

import hashlib

import numpy as np
import pytest
from qgis.core import QgsProcessingException

from geomatics_toolbox.core.io import contract
from geomatics_toolbox.core.io.raster import read_raster
from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile


def _digest(path) -> str:
    return hashlib.sha256(open(path, "rb").read()).hexdigest()


def _leftovers(folder):
    """Files of ``folder`` that are contract temporaries."""
    return sorted(p.name for p in folder.iterdir() if contract.is_temp(p))


@pytest.fixture(scope="module")
def data(tmp_path_factory):
    d = tmp_path_factory.mktemp("terrain_contract")
    tile = generate_tile(extent=(80.0, 80.0), density=2.0, seed=2, n_buildings=1, n_halls=0)
    laz = d / "tile.laz"
    write_tile(tile, laz, crs="EPSG:32632")
    cp = tile.checkpoints(n=8, min_spacing=3.0)
    return {"dir": d, "tile": tile, "laz": str(laz), "csv": cp.to_csv(d / "cp.csv"), "cp": cp}


@pytest.fixture(scope="module")
def dtm(qgis_processing, data):
    return qgis_processing.run("geomatics:idwdtm", {
        "INPUT": data["laz"], "CELL_SIZE": 1.0, "FILL_GAPS": True,
        "OUTPUT": str(data["dir"] / "dtm.tif")})["OUTPUT"]


def _refused(qgis_processing, alg, params, message, inputs, outputs):
    """Run expecting ``message``; inputs unchanged, no output nor temporary left."""
    before = {p: _digest(p) for p in inputs}
    with pytest.raises(QgsProcessingException, match=message) as info:
        qgis_processing.run(alg, params)
    assert "Traceback" not in str(info.value) and "RuntimeError" not in str(info.value)
    assert {p: _digest(p) for p in inputs} == before
    for out in outputs:
        assert not out.exists(), out
        assert not _leftovers(out.parent), _leftovers(out.parent)
    return str(info.value)


def test_dsm_ndsm_onto_its_dtm_refused(qgis_processing, data, dtm, tmp_path):
    dsm = tmp_path / "dsm.tif"
    _refused(qgis_processing, "geomatics:dsm", {
        "INPUT": data["laz"], "DTM": dtm, "OUTPUT": str(dsm), "OUTPUT_NDSM": dtm},
        "is the same file as the input DTM", [dtm, data["laz"]], [dsm])


def test_kriging_dtm_and_variance_at_one_path_refused(qgis_processing, data, tmp_path):
    out = tmp_path / "k.tif"
    _refused(qgis_processing, "geomatics:krigingdtm", {
        "INPUT": data["laz"], "CELL_SIZE": 2.0, "OUTPUT": str(out),
        "OUTPUT_VARIANCE": str(out)},
        "outputs OUTPUT and OUTPUT_VARIANCE are both", [data["laz"]], [out])


def test_dtmaccuracy_report_onto_the_checkpoints_refused(qgis_processing, data, dtm,
                                                         tmp_path):
    res = tmp_path / "res.gpkg"
    _refused(qgis_processing, "geomatics:dtmaccuracy", {
        "DTM": dtm, "CHECKPOINTS_CSV": data["csv"], "OUTPUT": str(res),
        "OUTPUT_HTML": data["csv"]},
        "is the same file as the input CHECKPOINTS_CSV", [dtm, data["csv"]], [res])


def _cases(data, dtm, folder, report):
    return [
        ("geomatics:idwdtm", {"INPUT": data["laz"], "OUTPUT": str(folder / "idw.tif"),
                              "OUTPUT_HTML": report}, [folder / "idw.tif"]),
        ("geomatics:krigingdtm", {"INPUT": data["laz"], "CELL_SIZE": 3.0, "NEIGHBOURS": 8,
                                  "OUTPUT": str(folder / "kr.tif"),
                                  "OUTPUT_VARIANCE": str(folder / "krv.tif"),
                                  "OUTPUT_HTML": report},
         [folder / "kr.tif", folder / "krv.tif"]),
        ("geomatics:dsm", {"INPUT": data["laz"], "DTM": dtm,
                           "OUTPUT": str(folder / "dsm.tif"),
                           "OUTPUT_NDSM": str(folder / "ndsm.tif"), "OUTPUT_HTML": report},
         [folder / "dsm.tif", folder / "ndsm.tif"]),
        ("geomatics:dtmaccuracy", {"DTM": dtm, "CHECKPOINTS_CSV": data["csv"],
                                   "OUTPUT": str(folder / "res.gpkg"),
                                   "OUTPUT_HTML": report}, [folder / "res.gpkg"]),
    ]


def test_unwritable_report_folder_leaves_nothing(qgis_processing, data, dtm, tmp_path):
    # a "folder" that is a file cannot be written, even by root
    blocker = tmp_path / "blocked"
    blocker.write_text("not a folder")
    report = str(blocker / "report.html")
    for alg, params, outs in _cases(data, dtm, tmp_path, report):
        msg = _refused(qgis_processing, alg, params, "cannot be written",
                       [data["laz"], dtm, data["csv"]], outs)
        assert "choose a folder" in msg


def test_report_failing_last_leaves_no_partial_result(qgis_processing, data, dtm, tmp_path,
                                                      monkeypatch):
    """The report is the last output written; when it fails the rasters vanish too."""
    real = contract.OutputContract.write_text

    def failing(self, name, text):
        if name == "OUTPUT_HTML":
            open(self.path(name), "w").write("<html>half")
            raise OSError(28, "No space left on device")
        return real(self, name, text)

    monkeypatch.setattr(contract.OutputContract, "write_text", failing)
    report = str(tmp_path / "report.html")
    for alg, params, outs in _cases(data, dtm, tmp_path, report):
        _refused(qgis_processing, alg, params, "No space left on device",
                 [data["laz"], dtm, data["csv"]], [*outs, tmp_path / "report.html"])


def test_cloud_in_degrees_refused(qgis_processing, data, tmp_path):
    tile = data["tile"]
    lon = 9.0 + (tile.x - tile.x.min()) * 1e-5      # about 1 m per 1e-5 degree
    lat = 45.0 + (tile.y - tile.y.min()) * 1e-5
    geo = tmp_path / "geo.laz"
    import laspy
    las = laspy.read(data["laz"])
    header = laspy.LasHeader(point_format=las.header.point_format.id, version="1.4")
    header.scales = (1e-7, 1e-7, 0.001)
    header.offsets = (9.0, 45.0, 0.0)
    out = laspy.LasData(header)
    out.x, out.y, out.z = lon, lat, np.asarray(las.z)
    out.classification = np.asarray(las.classification)
    out.write(geo)
    for alg in ("geomatics:idwdtm", "geomatics:krigingdtm", "geomatics:dsm"):
        dest = tmp_path / "geo_dtm.tif"
        msg = _refused(qgis_processing, alg, {"INPUT": str(geo), "CRS": "EPSG:4326",
                                              "OUTPUT": str(dest)},
                       "degrees", [geo], [dest])
        assert "Reproject" in msg
        # without a CRS record the degree-sized coordinates give it away
        _refused(qgis_processing, alg, {"INPUT": str(geo), "CRS": "EPSG:32632",
                                        "OUTPUT": str(dest)},
                 "degrees", [geo], [dest])


def test_flat_ground_kriging_gives_flat_dtm_with_zero_variance(qgis_processing, tmp_path):
    laspy = pytest.importorskip("laspy")
    rng = np.random.default_rng(3)
    n = 2000
    header = laspy.LasHeader(point_format=6, version="1.4")
    header.scales = (0.001, 0.001, 0.001)
    header.offsets = (500000.0, 4000000.0, 0.0)
    las = laspy.LasData(header)
    las.x = 500000.0 + rng.uniform(0, 50, n)
    las.y = 4000000.0 + rng.uniform(0, 50, n)
    las.z = np.full(n, 123.25)
    las.classification = np.full(n, 2, np.uint8)
    flat = tmp_path / "flat.las"
    las.write(flat)
    res = qgis_processing.run("geomatics:krigingdtm", {
        "INPUT": str(flat), "CRS": "EPSG:32632", "CELL_SIZE": 2.0, "CV_POINTS": 50,
        "OUTPUT": str(tmp_path / "flat.tif"), "OUTPUT_VARIANCE": str(tmp_path / "v.tif")})
    z = read_raster(res["OUTPUT"]).masked()
    v = read_raster(res["OUTPUT_VARIANCE"]).masked()
    assert np.isfinite(z).sum() > 500
    assert np.nanmin(z) == np.nanmax(z) == pytest.approx(123.25)
    assert np.nanmax(v) == 0.0 and np.array_equal(np.isfinite(z), np.isfinite(v))
    assert res["SILL"] == 0.0 and res["CV_RMSE"] == 0.0


@pytest.mark.parametrize("dup", ["id", "position"])
def test_duplicated_checkpoints_named(qgis_processing, data, dtm, tmp_path, dup):
    cp = data["cp"]
    rows = [f"{i},{x:.3f},{y:.3f},{z:.4f}" for i, x, y, z in zip(cp.id, cp.x, cp.y, cp.z)]
    i0, x0, y0, z0 = cp.id[2], cp.x[2], cp.y[2], cp.z[2]
    if dup == "id":      # the same point observed twice, a 2 m blunder the second time
        rows.append(f"{i0},{x0:.3f},{y0:.3f},{z0 + 2.0:.4f}")
    else:                # a renamed copy at the same position
        rows.append(f"X{i0},{x0:.3f},{y0:.3f},{z0 + 2.0:.4f}")
    csv = tmp_path / "dup.csv"
    csv.write_text("id,x,y,z\n" + "\n".join(rows) + "\n")
    html, res = tmp_path / "dup.html", tmp_path / "dup.gpkg"
    msg = _refused(qgis_processing, "geomatics:dtmaccuracy", {
        "DTM": dtm, "CHECKPOINTS_CSV": str(csv), "OUTPUT": str(res),
        "OUTPUT_HTML": str(html)}, f"Duplicated check points \\(same {dup}",
        [dtm, csv], [html, res])
    assert f"row 3 (id {i0})" in msg and f"row {len(rows)}" in msg


def test_residual_layer_committed_with_the_report(qgis_processing, data, dtm, tmp_path):
    from qgis.core import QgsVectorLayer
    res = qgis_processing.run("geomatics:dtmaccuracy", {
        "DTM": dtm, "CHECKPOINTS_CSV": data["csv"], "OUTPUT": str(tmp_path / "r.gpkg"),
        "OUTPUT_HTML": str(tmp_path / "r.html")})
    lyr = QgsVectorLayer(res["OUTPUT"], "r", "ogr")
    assert lyr.isValid() and lyr.featureCount() == 8 and lyr.crs().authid() == "EPSG:32632"
    errors = sorted(f["error"] for f in lyr.getFeatures())
    assert np.sqrt(np.mean(np.square(errors))) == pytest.approx(res["RMSE"], rel=1e-9)
    assert not _leftovers(tmp_path)


def test_legacy_class_text_and_enum_agree(qgis_processing, data, tmp_path):
    a = qgis_processing.run("geomatics:idwdtm", {
        "INPUT": data["laz"], "CLASSES": "2,9", "OUTPUT": str(tmp_path / "a.tif")})
    b = qgis_processing.run("geomatics:idwdtm", {
        "INPUT": data["laz"], "CLASSES": [2, 9], "OUTPUT": str(tmp_path / "b.tif")})
    assert a["N_POINTS"] == b["N_POINTS"] > 500
    with pytest.raises(QgsProcessingException):
        qgis_processing.run("geomatics:idwdtm", {
            "INPUT": data["laz"], "CLASSES": "2.7", "OUTPUT": str(tmp_path / "c.tif")})
    assert not (tmp_path / "c.tif").exists()


@pytest.mark.parametrize("lang", ["ar", "fa"])
def test_reports_in_the_requested_language_with_figures(qgis_processing, data, dtm, tmp_path,
                                                        lang):
    from geomatics_toolbox.core.reporting import translator
    index = {"ar": 2, "fa": 3}[lang]
    idw = tmp_path / "idw.html"
    qgis_processing.run("geomatics:idwdtm", {
        "INPUT": data["laz"], "OUTPUT": str(tmp_path / "i.tif"), "OUTPUT_HTML": str(idw),
        "REPORT_LANGUAGE": index})
    acc = tmp_path / "acc.html"
    qgis_processing.run("geomatics:dtmaccuracy", {
        "DTM": dtm, "CHECKPOINTS_CSV": data["csv"], "OUTPUT_HTML": str(acc),
        "REPORT_LANGUAGE": index})
    tr = translator(lang)
    for path, figures, title in ((idw, ["hillshade"], "IDW DTM report"),
                                 (acc, ["residual-map", "error-vs-height"],
                                  "DTM accuracy against check points")):
        html = path.read_text(encoding="utf-8")
        assert f'lang="{lang}" dir="rtl"' in html and tr(title) in html
        for fid in figures:
            assert f'<figure id="{fid}">' in html
        assert "Legend" not in html and tr("Legend") in html


def test_residual_layer_styled_by_error(qgis_processing, data, dtm, tmp_path):
    from qgis.core import QgsVectorLayer
    res = qgis_processing.run("geomatics:dtmaccuracy", {
        "DTM": dtm, "CHECKPOINTS_CSV": data["csv"], "OUTPUT": str(tmp_path / "s.gpkg")})
    lyr = QgsVectorLayer(res["OUTPUT"], "s", "ogr")
    assert lyr.isValid() and lyr.renderer().type() == "graduatedSymbol"
    r = lyr.renderer()
    assert r.classAttribute() == "error" and len(r.ranges()) == 7
    colours = [rg.symbol().color().name() for rg in r.ranges()]
    assert colours[0] == "#2166ac" and colours[-1] == "#b2182b"
    assert lyr.featureCount() == 8 and not _leftovers(tmp_path)

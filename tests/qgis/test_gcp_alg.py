"""GCP rectification algorithms through processing.run in a headless QGIS."""
from __future__ import annotations

import hashlib
import json

import numpy as np
import pytest

from geomatics_toolbox.core.io import gcp as gcp_io
from geomatics_toolbox.synthetic import gcp as gcp_synthetic

EPSG = "EPSG:22780"


def sha(path) -> str:
    with open(path, "rb") as fh:
        return hashlib.sha256(fh.read()).hexdigest()


def make_case(tmp_path, name="img", order=2, scale=8.0, seed=3, crs_line=True):
    """A small image and its Georeferencer .points file (1/8-scale image-1 GCPs)."""
    pix, mp, _, _ = gcp_synthetic.synthetic_gcps(order, noise=1.0, seed=seed)
    pix = pix / scale
    w, h = int(pix[:, 0].max() + 20), int(pix[:, 1].max() + 20)
    img = gcp_synthetic.write_test_image(tmp_path / f"{name}.tif", w, h)
    g = gcp_io.make_gcps(None, pix, mp)
    pts = tmp_path / f"{name}.tif.points"
    pts.write_text(gcp_io.points_text(g, crs_wkt=EPSG if crs_line else ""))
    return img, pts, pix, mp


def test_rectify_through_processing(qgis_processing, tmp_path):
    from osgeo import gdal
    img, pts, _, _ = make_case(tmp_path)
    before = sha(img)
    out = tmp_path / "rect.tif"
    html = tmp_path / "rect.html"
    res = qgis_processing.run("geomatics:rectifygcp", {
        "INPUT": str(img), "GCP_FILE": str(pts), "ORDER": 2, "RESAMPLING": 0,
        "OUTPUT": str(out), "OUTPUT_HTML": str(html)})
    assert res["OUTPUT"] == str(out) and out.exists() and html.exists()
    assert res["N_GCP"] == 22 and res["REDUNDANCY"] == 16
    assert res["GR"] == pytest.approx(8 * gcp_synthetic.IMAGE1_GR, rel=0.01)
    assert res["RMS_T"] == pytest.approx(1.0 * np.sqrt(16 / 22) * np.sqrt(2), rel=0.5)
    assert res["RMS_T_QGIS"] > res["RMS_T"]
    ds = gdal.Open(str(out))
    assert "22780" in ds.GetProjection()
    assert ds.GetGeoTransform()[1] == pytest.approx(res["GR"])
    assert sha(img) == before
    assert "RMS_T" in html.read_text(encoding="utf-8")


def test_points_file_next_to_the_image_is_found(qgis_processing, tmp_path):
    img, pts, _, _ = make_case(tmp_path)
    assert pts.name == "img.tif.points"
    res = qgis_processing.run("geomatics:gcpaccuracyreport", {"INPUT": str(img),
                                                              "ORDER": 2})
    assert res["N_GCP"] == 22


def test_rectify_batch_of_two_images(qgis_processing, tmp_path):
    outs = []
    for k in range(2):
        img, pts, _, _ = make_case(tmp_path, name=f"b{k}", seed=k)
        out = tmp_path / f"b{k}_rect.tif"
        res = qgis_processing.run("geomatics:rectifygcp", {
            "INPUT": str(img), "GCP_FILE": str(pts), "ORDER": 1 + k, "OUTPUT": str(out),
            "RESAMPLING": 1, "RESOLUTION": 10.0})
        outs.append(out)
        assert out.exists() and res["N_GCP"] == 22
    from osgeo import gdal
    assert gdal.Open(str(outs[0])).GetGeoTransform()[1] == pytest.approx(10.0)


def test_accuracy_report_all_orders_and_outputs(qgis_processing, tmp_path):
    img, pts, _, _ = make_case(tmp_path, order=2)
    paths = {k: tmp_path / f"r.{k.split('_')[1].lower()}" for k in
             ("OUTPUT_HTML", "OUTPUT_CSV", "OUTPUT_JSON")}
    res = qgis_processing.run("geomatics:gcpaccuracyreport", {
        "INPUT": str(img), "GCP_FILE": str(pts), "ORDER": 2, "GR": 7.28,
        **{k: str(v) for k, v in paths.items()}})
    for p in paths.values():
        assert p.exists()
    assert res["GR"] == pytest.approx(7.28) and res["SCALE"] == pytest.approx(145600)
    assert res["RECOMMENDED_ORDER"] in (2, 3)
    assert res["RMS_T_ORDER1"] > res["RMS_T_ORDER2"] > 0 and res["RMS_T_ORDER3"] > 0
    d = json.loads(paths["OUTPUT_JSON"].read_text(encoding="utf-8"))
    fit = d["orders"]["2"]["fit"]
    assert fit["rms_t"] == pytest.approx(res["RMS_T"])
    assert res["ACCEPTED"] == int(fit["c4"] in ("strict", "accepted") and fit["c5"]
                                  and fit["c6"])
    assert set(d["orders"]) == {"1", "2", "3"}
    assert len(paths["OUTPUT_CSV"].read_text().splitlines()) == 23


def test_accuracy_report_from_point_layer_with_check_points(qgis_processing, tmp_path):
    from qgis.core import QgsFeature, QgsField, QgsGeometry, QgsPointXY, QgsVectorLayer
    from qgis.PyQt.QtCore import QVariant
    _, _, pix, mp = make_case(tmp_path)
    lyr = QgsVectorLayer(f"Point?crs={EPSG}", "gcps", "memory")
    pr = lyr.dataProvider()
    pr.addAttributes([QgsField("name", QVariant.String), QgsField("px", QVariant.Double),
                      QgsField("py", QVariant.Double), QgsField("kind", QVariant.String),
                      QgsField("w", QVariant.Double)])
    lyr.updateFields()
    feats = []
    for k, ((c, r), (x, y)) in enumerate(zip(pix, mp)):
        f = QgsFeature(lyr.fields())
        f.setGeometry(QgsGeometry.fromPointXY(QgsPointXY(x, y)))
        f.setAttributes([f"P{k + 1}", float(c), float(r), "check" if k % 5 == 0 else "gcp",
                         2.0 if k == 3 else 1.0])
        feats.append(f)
    pr.addFeatures(feats)
    res = qgis_processing.run("geomatics:gcpaccuracyreport", {
        "GCP_LAYER": lyr, "COL_FIELD": "px", "ROW_FIELD": "py", "ID_FIELD": "name",
        "ROLE_FIELD": "kind", "WEIGHT_FIELD": "w", "ORDER": 2})
    assert res["N_CHECK"] == 5 and res["N_GCP"] == 17
    assert 0 < res["CHECK_RMS_T"] < 10


@pytest.mark.parametrize("encoding,stem", [
    ("cp1256", "نقطة تحقق"),            # Arabic Windows, Excel "CSV"
    ("cp1256", "ايستگاه کنترل"),        # Persian Windows (cp1256 has ي for ی)
    ("utf-8-sig", "ایستگاه کنترل"),     # Excel "CSV UTF-8"
    ("cp1252", "Château-Süd"),          # Western Windows
])
def test_gcp_names_in_a_windows_code_page_reach_the_accuracy_report(qgis_processing,
                                                                    tmp_path, encoding,
                                                                    stem):
    """A GCP table saved by Excel on an Arabic or Persian machine, read here (UTF-8
    Linux): the names were garbled in the report ('äÞØÉ ÊÍÞÞ 1', read as cp1252) or
    the file refused (گ); they now reach the HTML and CSV reports as written."""
    img, _, pix, mp = make_case(tmp_path)
    names = [f"{stem} {k + 1}" for k in range(len(pix))]
    table = tmp_path / "gcps.csv"
    table.write_bytes((f"# CRS: {EPSG}\nid,col,row,x,y\n" + "".join(
        f"{n},{float(c)!r},{float(r)!r},{float(x)!r},{float(y)!r}\n"   # numpy 2: no np.float64(..)
        for n, (c, r), (x, y) in zip(names, pix, mp))
    ).encode(encoding))
    html, csv = tmp_path / "r.html", tmp_path / "r.csv"
    res = qgis_processing.run("geomatics:gcpaccuracyreport", {
        "INPUT": str(img), "GCP_FILE": str(table), "ORDER": 2, "OUTPUT_HTML": str(html),
        "OUTPUT_CSV": str(csv)})
    assert res["N_GCP"] == 22
    text = html.read_text(encoding="utf-8")
    assert all(n in text for n in names)
    rows = csv.read_text(encoding="utf-8-sig").splitlines()
    assert [r.split(",")[0] for r in rows[1:]] == names


@pytest.mark.parametrize("case, message", [
    ("no_crs", "no CRS"),
    ("order3_few", "at least 10"),
    ("outside", "outside the image"),
    ("no_gcps", "No GCPs"),
])
def test_bad_input_clear_error_nothing_written(qgis_processing, tmp_path, case, message):
    from qgis.core import QgsProcessingException
    img, pts, pix, mp = make_case(tmp_path, crs_line=case != "no_crs")
    if case == "order3_few":
        g = gcp_io.read_points(pts)
        pts.write_text(gcp_io.points_text(g.subset(np.arange(len(g)) < 8)))
    if case == "outside":
        g = gcp_io.read_points(pts)
        g.pixel[3, 0] = 1e5
        pts.write_text(gcp_io.points_text(g))
    if case == "no_gcps":
        pts.unlink()
        pts = tmp_path / "unrelated.csv"
        pts.write_text("id,col,row,X,Y\n")
    before = sha(img)
    out = tmp_path / "never.tif"
    html = tmp_path / "never.html"
    params = {"INPUT": str(img), "GCP_FILE": "" if case == "no_gcps" else str(pts),
              "ORDER": 3 if case == "order3_few" else 2, "OUTPUT": str(out),
              "OUTPUT_HTML": str(html)}
    with pytest.raises(QgsProcessingException, match=message):
        qgis_processing.run("geomatics:rectifygcp", params)
    assert not out.exists() and not html.exists()
    assert sha(img) == before
    leftovers = sorted(p.name for p in tmp_path.iterdir())
    assert leftovers == sorted(["img.tif", pts.name]), leftovers


def test_non_geotiff_output_refused(qgis_processing, tmp_path):
    from qgis.core import QgsProcessingException
    img, pts, _, _ = make_case(tmp_path)
    with pytest.raises(QgsProcessingException, match="GeoTIFF"):
        qgis_processing.run("geomatics:rectifygcp", {"INPUT": str(img), "GCP_FILE": str(pts),
                                                     "OUTPUT": str(tmp_path / "o.img")})
    assert not (tmp_path / "o.img").exists()


def test_geographic_gcps_need_a_projected_target(qgis_processing, tmp_path):
    from osgeo import gdal, osr
    from qgis.core import QgsProcessingException
    pix, mp, _, _ = gcp_synthetic.synthetic_gcps(1, noise=0.5, seed=1)
    pix = pix / 8.0
    utm = mp - mp.mean(axis=0) + [500000.0, 3900000.0]  # somewhere in UTM zone 37N
    src, dst = osr.SpatialReference(), osr.SpatialReference()
    src.ImportFromEPSG(32637)
    dst.ImportFromEPSG(4326)
    for s in (src, dst):
        s.SetAxisMappingStrategy(osr.OAMS_TRADITIONAL_GIS_ORDER)
    lonlat = np.array(osr.CoordinateTransformation(src, dst).TransformPoints(utm.tolist()))
    img = gcp_synthetic.write_test_image(tmp_path / "geo.tif", int(pix[:, 0].max() + 20),
                                         int(pix[:, 1].max() + 20))
    pts = tmp_path / "geo.points"
    g = gcp_io.make_gcps(None, pix, lonlat[:, :2])
    pts.write_text(gcp_io.points_text(g, crs_wkt="EPSG:4326"))
    with pytest.raises(QgsProcessingException, match="geographic"):
        qgis_processing.run("geomatics:gcpaccuracyreport", {"GCP_FILE": str(pts)})
    out = tmp_path / "geo_rect.tif"
    res = qgis_processing.run("geomatics:rectifygcp", {
        "INPUT": str(img), "GCP_FILE": str(pts), "ORDER": 1, "TARGET_CRS": "EPSG:32637",
        "OUTPUT": str(out)})
    assert res["GR"] == pytest.approx(8 * gcp_synthetic.IMAGE1_GR, rel=0.02)
    assert res["RMS_T"] < 5.0
    ds = gdal.Open(str(out))
    assert "32637" in ds.GetProjection() or "UTM zone 37N" in ds.GetProjection()
    assert ds.GetGeoTransform()[0] == pytest.approx(utm[:, 0].min(), abs=200)


def _names(folder):
    return sorted(p.name for p in folder.iterdir())


@pytest.mark.parametrize("alg, output", [("gcpaccuracyreport", "OUTPUT_CSV"),
                                         ("gcpaccuracyreport", "OUTPUT_HTML"),
                                         ("gcpaccuracyreport", "OUTPUT_JSON"),
                                         ("rectifygcp", "OUTPUT_HTML")])
def test_output_on_the_gcp_file_is_refused(qgis_processing, tmp_path, alg, output):
    from qgis.core import QgsProcessingException
    img, pts, _, _ = make_case(tmp_path)
    before, before_img, names = sha(pts), sha(img), _names(tmp_path)
    params = {"INPUT": str(img), "GCP_FILE": str(pts), "ORDER": 1, output: str(pts)}
    if alg == "rectifygcp":
        params["OUTPUT"] = str(tmp_path / "rect.tif")
    with pytest.raises(QgsProcessingException, match="same file as the input GCP_FILE"):
        qgis_processing.run(f"geomatics:{alg}", params)
    assert sha(pts) == before and sha(img) == before_img
    assert _names(tmp_path) == names


def test_output_on_the_points_file_found_next_to_the_image_is_refused(qgis_processing,
                                                                      tmp_path):
    from qgis.core import QgsProcessingException
    img, pts, _, _ = make_case(tmp_path)
    before, names = sha(pts), _names(tmp_path)
    with pytest.raises(QgsProcessingException, match="GCP_FILE"):
        qgis_processing.run("geomatics:gcpaccuracyreport", {"INPUT": str(img),
                                                            "OUTPUT_CSV": str(pts)})
    assert sha(pts) == before and _names(tmp_path) == names


def test_two_outputs_on_one_path_refused(qgis_processing, tmp_path):
    from qgis.core import QgsProcessingException
    img, pts, _, _ = make_case(tmp_path)
    names = _names(tmp_path)
    same = str(tmp_path / "r.txt")
    with pytest.raises(QgsProcessingException, match="both"):
        qgis_processing.run("geomatics:gcpaccuracyreport", {
            "INPUT": str(img), "GCP_FILE": str(pts), "OUTPUT_CSV": same,
            "OUTPUT_JSON": same})
    assert _names(tmp_path) == names


def test_report_failure_leaves_no_rectified_image(qgis_processing, tmp_path, monkeypatch):
    """All-or-nothing: the warp succeeded, the report failed -> nothing at all."""
    from qgis.core import QgsProcessingException

    from geomatics_toolbox.core.rectification import report

    def broken(*_a, **_k):
        raise OSError("disk full while writing the report")

    monkeypatch.setattr(report, "build_report", broken)
    img, pts, _, _ = make_case(tmp_path)
    old = tmp_path / "rect.tif"
    old.write_bytes(b"an older result")
    names = _names(tmp_path)
    with pytest.raises(QgsProcessingException, match="disk full"):
        qgis_processing.run("geomatics:rectifygcp", {
            "INPUT": str(img), "GCP_FILE": str(pts), "ORDER": 1, "OUTPUT": str(old),
            "OUTPUT_HTML": str(tmp_path / "rect.html")})
    assert _names(tmp_path) == names
    assert old.read_bytes() == b"an older result"


def test_report_in_unwritable_folder_clear_error_nothing_written(qgis_processing, tmp_path):
    """The report's folder is a file (unwritable even for root): refused up front."""
    from qgis.core import QgsProcessingException
    img, pts, _, _ = make_case(tmp_path)
    blocker = tmp_path / "blocker"
    blocker.write_text("not a folder")
    names = _names(tmp_path)
    with pytest.raises(QgsProcessingException, match="cannot be written"):
        qgis_processing.run("geomatics:rectifygcp", {
            "INPUT": str(img), "GCP_FILE": str(pts), "ORDER": 1,
            "OUTPUT": str(tmp_path / "rect.tif"),
            "OUTPUT_HTML": str(blocker / "rect.html")})
    assert _names(tmp_path) == names and blocker.read_text() == "not a folder"


def test_identical_map_coordinates_named(qgis_processing, tmp_path):
    from qgis.core import QgsProcessingException
    img, pts, _, _ = make_case(tmp_path)
    g = gcp_io.read_points(pts)
    g.map[6] = g.map[2]
    g.map[11] = g.map[2]
    pts.write_text(gcp_io.points_text(g))
    names = _names(tmp_path)
    with pytest.raises(QgsProcessingException,
                       match=r"identical map coordinates.*3, 7, 12 at X") as exc:
        qgis_processing.run("geomatics:gcpaccuracyreport", {
            "INPUT": str(img), "GCP_FILE": str(pts), "OUTPUT_HTML": str(tmp_path / "r.html")})
    assert "GR" not in str(exc.value)
    assert _names(tmp_path) == names


def _kind_case(tmp_path, kind, noise=0.3, outlier=None):
    """Image-1 GCPs through a known ``kind`` (+ noise, + an outlier) as a .points file."""
    pix, mp, _, size = gcp_synthetic.transformed_gcps(kind, noise=noise, seed=11)
    if outlier is not None:
        mp = mp.copy()
        mp[outlier] += (25.0, -20.0)
    pts = tmp_path / f"{kind}.points"
    pts.write_text(gcp_io.points_text(gcp_io.make_gcps(None, pix, mp), crs_wkt=EPSG))
    return pts, size


@pytest.mark.parametrize("kind", ["helmert", "projective", "polynomial2"])
def test_recommended_transformation_is_the_true_model(qgis_processing, tmp_path, kind):
    pts, size = _kind_case(tmp_path, kind)
    res = qgis_processing.run("geomatics:gcpaccuracyreport", {
        "GCP_FILE": str(pts), "IMAGE_WIDTH": size[0], "IMAGE_HEIGHT": size[1],
        "TRANSFORMATION": 8})
    assert res["RECOMMENDED_TRANSFORMATION"] == kind
    assert res["TRANSFORMATION_USED"] == kind
    # the honest (leave-one-out) error of the true model is about the noise: 0.3 m/axis
    assert 0.2 < res["HONEST_RMS_T"] < 0.8


def test_refine_drops_the_outlier_and_tps_warps(qgis_processing, tmp_path):
    from osgeo import gdal
    pts, size = _kind_case(tmp_path, "polynomial1", outlier=4)
    img = gcp_synthetic.write_test_image(tmp_path / "big.tif", size[0] // 4, size[1] // 4)
    pix, mp, _, _ = gcp_synthetic.transformed_gcps("polynomial1", noise=0.3, seed=11)
    mp[4] += (25.0, -20.0)
    small = tmp_path / "small.points"
    small.write_text(gcp_io.points_text(gcp_io.make_gcps(None, pix / 4, mp), crs_wkt=EPSG))
    res = qgis_processing.run("geomatics:gcpaccuracyreport", {
        "GCP_FILE": str(pts), "IMAGE_WIDTH": size[0], "IMAGE_HEIGHT": size[1],
        "TRANSFORMATION": 1, "REFINE": True})
    assert res["N_DROPPED"] == 1 and res["N_GCP"] == 21
    assert res["RMS_T"] < 1.0  # the 32 m outlier is gone
    out = tmp_path / "tps.tif"
    res = qgis_processing.run("geomatics:rectifygcp", {
        "INPUT": str(img), "GCP_FILE": str(small), "TRANSFORMATION": 7, "REFINE": True,
        "REFINE_TOLERANCE": 10.0, "OUTPUT": str(out)})
    assert res["TRANSFORMATION_USED"] == "tps" and res["N_DROPPED"] == 1
    assert gdal.Open(str(out)).GetMetadataItem("RECTIFICATION").startswith("GCP tps, 21 ")

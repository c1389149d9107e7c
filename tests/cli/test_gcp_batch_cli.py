"""qgis_process run of the batch GCP rectification on three generated images."""
from __future__ import annotations

import csv

from geomatics_toolbox.core.io import gcp as gcp_io
from geomatics_toolbox.synthetic import gcp as gcp_synthetic

KINDS = ("helmert", "projective", "polynomial2")


def _folder(tmp_path):
    """Three 1/8-scale images, each with image-1 GCPs through a different known model."""
    src = tmp_path / "scans"
    src.mkdir()
    for k, kind in enumerate(KINDS):
        pix, mp, _, size = gcp_synthetic.transformed_gcps(kind, noise=0.3, seed=k)
        pix = pix / 8.0
        gcp_synthetic.write_test_image(src / f"img{k}.tif", size[0] // 8 + 1,
                                             size[1] // 8 + 1)
        (src / f"img{k}.tif.points").write_text(gcp_io.points_text(
            gcp_io.make_gcps(None, pix, mp), crs_wkt="EPSG:22780"))
    (src / "no_points.tif").write_bytes((src / "img0.tif").read_bytes())  # skipped
    return src


def test_rectifybatch_cli_three_images(qgis_process, tmp_path):
    from osgeo import gdal
    src = _folder(tmp_path)
    out = tmp_path / "rectified"
    summary = tmp_path / "summary.csv"
    html = tmp_path / "summary.html"
    res = qgis_process.run("geomatics:rectifybatch", INPUT_FOLDER=src, TRANSFORMATION=8,
                           OUTPUT_FOLDER=out, OUTPUT_CSV=summary, OUTPUT_HTML=html)
    r = res["results"]
    assert r["N_IMAGES"] == 3 and r["N_RECTIFIED"] == 3
    rows = list(csv.DictReader(summary.open(encoding="utf-8")))
    assert [row["image"] for row in rows] == ["img0.tif", "img1.tif", "img2.tif"]
    # the recommended transformation of each image is its true model
    assert [row["transformation"] for row in rows] == list(KINDS)
    for row in rows:
        assert row["honest_basis"] == "loo" and 0 < float(row["honest_rms_t"]) < 1.0
        ds = gdal.Open(row["output"])
        assert ds is not None and "22780" in ds.GetProjection()
        assert ds.GetMetadataItem("RECTIFICATION").startswith(
            f"GCP {row['transformation']}, 22 GCPs")
    assert sorted(p.name for p in out.iterdir()) == [
        "img0_rectified.tif", "img1_rectified.tif", "img2_rectified.tif"]
    assert "batch summary" in html.read_text(encoding="utf-8")


def test_rectifybatch_cli_bad_image_reported_others_done(qgis_process, tmp_path):
    src = _folder(tmp_path)
    (src / "img1.tif.points").write_text("mapX,mapY,pixelX,pixelY,enable\n1,2,3,-4,1\n")
    out = tmp_path / "rectified"
    summary = tmp_path / "summary.csv"
    res = qgis_process.run("geomatics:rectifybatch", INPUT_FOLDER=src, TRANSFORMATION=5,
                           OUTPUT_FOLDER=out, OUTPUT_CSV=summary, GCP_CRS="EPSG:22780")
    assert res["results"]["N_RECTIFIED"] == 2
    rows = {row["image"]: row for row in csv.DictReader(summary.open(encoding="utf-8"))}
    assert rows["img1.tif"]["error"] and not rows["img0.tif"]["error"]
    assert not (out / "img1_rectified.tif").exists()
    assert not [p for p in out.iterdir() if ".part-" in p.name]


def test_rectifybatch_output_folder_is_not_the_input(qgis_process, tmp_path):
    src = _folder(tmp_path)
    msg = qgis_process.run_expect_failure("geomatics:rectifybatch", INPUT_FOLDER=src,
                                          OUTPUT_FOLDER=src)
    assert "OUTPUT_FOLDER must differ" in msg


def test_rectifybatch_summary_on_an_input_points_file_is_refused(qgis_process, tmp_path):
    src = _folder(tmp_path)
    pts = src / "img2.tif.points"
    before = pts.read_text()
    msg = qgis_process.run_expect_failure("geomatics:rectifybatch", INPUT_FOLDER=src,
                                          OUTPUT_FOLDER=tmp_path / "out", OUTPUT_CSV=pts)
    assert "OUTPUT_CSV" in msg and pts.read_text() == before
    assert not (tmp_path / "out").exists()


# ---------------------------------------------------------- issue 22: batches that refuse
def test_rectifybatch_colliding_outputs_refused_up_front(qgis_process, tmp_path):
    src = _folder(tmp_path)
    (src / "img0.png").write_bytes((src / "img0.tif").read_bytes())      # same stem
    (src / "img0.png.points").write_text((src / "img0.tif.points").read_text())
    out = tmp_path / "rectified"
    msg = qgis_process.run_expect_failure("geomatics:rectifybatch", INPUT_FOLDER=src,
                                          OUTPUT_FOLDER=out)
    assert "would both be written as img0_rectified.tif" in msg
    assert not out.exists()


def test_rectifybatch_output_folder_through_a_symlink_refused(qgis_process, tmp_path):
    src = _folder(tmp_path)
    link = tmp_path / "link"
    link.symlink_to(src, target_is_directory=True)
    before = sorted(p.name for p in src.iterdir())
    msg = qgis_process.run_expect_failure("geomatics:rectifybatch", INPUT_FOLDER=src,
                                          OUTPUT_FOLDER=link)
    assert "OUTPUT_FOLDER must differ" in msg
    assert sorted(p.name for p in src.iterdir()) == before


def test_rectifybatch_every_image_failed_ends_non_zero(qgis_process, tmp_path):
    src = _folder(tmp_path)
    for k in range(3):
        (src / f"img{k}.tif.points").write_text("mapX,mapY,pixelX,pixelY,enable\n1,2,3,-4,1\n")
    out = tmp_path / "rectified"
    summary = tmp_path / "summary.csv"
    msg = qgis_process.run_expect_failure("geomatics:rectifybatch", INPUT_FOLDER=src,
                                          OUTPUT_FOLDER=out, OUTPUT_CSV=summary,
                                          GCP_CRS="EPSG:22780")
    assert "None of the 3 images could be rectified" in msg
    assert not summary.exists()
    assert not [p for p in out.iterdir() if p.name.endswith(".tif")]

"""qgis_process smoke tests for the GCP rectification algorithms."""
from __future__ import annotations

import numpy as np

from geomatics_toolbox.core.io import gcp as gcp_io
from geomatics_toolbox.synthetic import gcp as gcp_synthetic


def _case(tmp_path, crs="EPSG:22780"):
    pix, mp, _, _ = gcp_synthetic.synthetic_gcps(2, noise=1.0, seed=5)
    pix = pix / 8.0
    img = gcp_synthetic.write_test_image(tmp_path / "img.tif", int(pix[:, 0].max() + 20),
                                         int(pix[:, 1].max() + 20))
    pts = tmp_path / "img.tif.points"
    pts.write_text(gcp_io.points_text(gcp_io.make_gcps(None, pix, mp), crs_wkt=crs))
    return img, pts


def test_rectifygcp_cli(qgis_process, tmp_path):
    img, pts = _case(tmp_path)
    out = tmp_path / "rect.tif"
    html = tmp_path / "rect.html"
    res = qgis_process.run("geomatics:rectifygcp", INPUT=img, GCP_FILE=pts, ORDER=2,
                           OUTPUT=out, OUTPUT_HTML=html)
    r = res["results"]
    assert out.exists() and html.exists()
    assert r["N_GCP"] == 22 and r["RMS_T"] > 0
    assert np.isfinite(r["RMS_T_QGIS"])


def test_gcpaccuracyreport_cli(qgis_process, tmp_path):
    img, pts = _case(tmp_path)
    csv_path = tmp_path / "res.csv"
    res = qgis_process.run("geomatics:gcpaccuracyreport", GCP_FILE=pts, INPUT=img, ORDER=1,
                           GR=7.28, OUTPUT_CSV=csv_path)
    r = res["results"]
    assert csv_path.exists()
    assert r["RMS_T_ORDER1"] > r["RMS_T_ORDER2"]
    assert r["RECOMMENDED_ORDER"] in (2, 3)


def test_missing_crs_cli_fails_cleanly(qgis_process, tmp_path):
    img, pts = _case(tmp_path, crs="")
    out = tmp_path / "never.tif"
    msg = qgis_process.run_expect_failure("geomatics:rectifygcp", INPUT=img, GCP_FILE=pts,
                                          ORDER=1, OUTPUT=out)
    assert "no CRS" in msg and "GCP_CRS" in msg
    assert not out.exists()

"""qgis_process smoke tests of the LiDAR products on the demo tile, with defaults."""
from __future__ import annotations

import importlib.util
from pathlib import Path

import numpy as np
import pytest

from geomatics_toolbox.core.io.raster import read_raster

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="module")
def demo(tmp_path_factory):
    spec = importlib.util.spec_from_file_location("make_demo_data",
                                                  ROOT / "scripts" / "make_demo_data.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    d = tmp_path_factory.mktemp("products_cli")
    return d, str(mod.make_demo(d / "demo")["laz"])


def test_tindtm_defaults(qgis_process, demo):
    d, laz = demo
    res = qgis_process.run("geomatics:tindtm", INPUT=laz,
                           OUTPUT="TEMPORARY_OUTPUT")["results"]
    assert res["N_POINTS"] > 50_000 and res["VALID_CELLS"] > 0.8 * 300 * 300
    assert res["OUTPUT"].endswith(".tif")  # the temporary folder is gone on exit
    html = d / "tin.html"
    res = qgis_process.run("geomatics:tindtm", INPUT=laz, CELL_SIZE=2,
                           OUTPUT=str(d / "tin.tif"), OUTPUT_HTML=str(html),
                           REPORT_LANGUAGE=3)["results"]
    dtm = read_raster(d / "tin.tif").masked()
    assert 150 < np.nanmin(dtm) and np.nanmax(dtm) < 300
    assert res["VALID_CELLS"] == np.isfinite(dtm).sum()
    text = html.read_text(encoding="utf-8")
    assert 'dir="rtl"' in text and "<svg" in text


def test_tindtm_no_ground_is_a_clear_error(qgis_process, demo):
    d, laz = demo
    msg = qgis_process.run_expect_failure("geomatics:tindtm", INPUT=laz, CLASSES="9",
                                          OUTPUT=str(d / "none.tif"))
    assert "No ground points in the input class filter" in msg
    assert "Traceback" not in msg and not (d / "none.tif").exists()

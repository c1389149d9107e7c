"""qgis_process smoke tests for the slope filter algorithms."""
from __future__ import annotations

import csv

import numpy as np
import pytest


@pytest.fixture(scope="module")
def tile_path(tmp_path_factory):
    from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile
    tile = generate_tile(extent=(80, 80), density=3.0, seed=4)
    path = tmp_path_factory.mktemp("slopecli") / "tile.laz"
    write_tile(tile, path)
    return path


def test_cli_slope_ground_filter(qgis_process, tile_path, tmp_path):
    from geomatics_toolbox.core.io.las import read_las
    out = tmp_path / "c.laz"
    res = qgis_process.run("geomatics:slopegroundfilter", INPUT=tile_path, RADIUS=3,
                           SLOPE=44, HEIGHT_TOLERANCE=0, OUTPUT=out)
    r = res["results"]
    cls = read_las(out, ["classification"])["classification"]
    assert r["N_GROUND"] == np.count_nonzero(cls == 2) > 0


def test_cli_slope_ground_filter_bad_slope(qgis_process, tile_path, tmp_path):
    out = tmp_path / "never.laz"
    msg = qgis_process.run_expect_failure("geomatics:slopegroundfilter", INPUT=tile_path,
                                          SLOPE=90, OUTPUT=out)
    assert "between 0 and 90" in msg
    assert not out.exists()


def test_cli_slope_threshold_sweep(qgis_process, tile_path, tmp_path):
    out_csv, html = tmp_path / "s.csv", tmp_path / "s.html"
    res = qgis_process.run("geomatics:slopethresholdsweep", INPUT=tile_path,
                           SLOPES="40:60:4", RADII=3, HEIGHT_TOLERANCES=0,
                           OUTPUT_CSV=out_csv, OUTPUT_HTML=html)
    r = res["results"]
    rows = list(csv.DictReader(out_csv.open()))
    assert [float(x["slope_deg"]) for x in rows] == [40, 44, 48, 52, 56, 60]
    assert r["BEST_TOTAL"] == pytest.approx(min(float(x["total_pct"]) for x in rows),
                                            rel=1e-5)
    assert html.exists()

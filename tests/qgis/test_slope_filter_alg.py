"""Slope filter algorithms through processing.run in a headless QGIS."""
from __future__ import annotations

import csv

import numpy as np
import pytest

from geomatics_toolbox.core.io.las import read_las, write_las
from geomatics_toolbox.core.lidar import pipeline as sp
from geomatics_toolbox.core.lidar import slope as sf


@pytest.fixture(scope="module")
def tile_path(tmp_path_factory):
    from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile
    tile = generate_tile(extent=(100, 100), density=4.0, seed=21)
    path = tmp_path_factory.mktemp("slopealg") / "tile.laz"
    write_tile(tile, path)
    return str(path)


def test_filter_through_processing(qgis_processing, tile_path, tmp_path):
    out, gout, html = tmp_path / "c.laz", tmp_path / "g.laz", tmp_path / "r.html"
    res = qgis_processing.run("geomatics:slopegroundfilter", {
        "INPUT": tile_path, "RADIUS": 5.0, "SLOPE": 44.0, "HEIGHT_TOLERANCE": 0.1,
        "OUTPUT": str(out), "GROUND_OUTPUT": str(gout), "OUTPUT_HTML": str(html)})
    pd = read_las(out, ["classification"])
    cls = pd["classification"]
    assert res["N_GROUND"] == np.count_nonzero(cls == 2) > 0
    assert res["N_POINTS"] == len(pd)
    assert res["N_NONGROUND"] == np.count_nonzero(cls == 1)
    assert res["N_NOISE"] == np.count_nonzero(cls == 7) > 0     # same meaning as groundfilter
    assert len(read_las(gout)) == res["N_GROUND"]
    assert "Allowed rise" in html.read_text(encoding="utf-8")
    # identical to the core filter with the same selection
    src = read_las(tile_path, ["classification"])
    sel = sp.select_points(src)
    core = sf.slope_filter(src.x, src.y, src.z, radius=5.0, slope=44.0, height_tolerance=0.1,
                           classify=sel.candidates, neighbours=sel.candidates)
    np.testing.assert_array_equal(cls == 2, core.ground)


def test_filter_last_returns_adaptive(qgis_processing, tile_path, tmp_path):
    out = tmp_path / "c.las"
    res = qgis_processing.run("geomatics:slopegroundfilter", {
        "INPUT": tile_path, "RETURNS": 1, "MODE": 1, "NOISE": False, "OUTPUT": str(out)})
    # no pre-filter: the only class-7 points are the input's own noise, kept
    kept = np.count_nonzero(read_las(tile_path, ["classification"])["classification"] == 7)
    assert res["N_NOISE"] == kept == np.count_nonzero(read_las(out, ["classification"])
                                                      ["classification"] == 7)
    assert out.exists() and res["N_GROUND"] > 0


@pytest.mark.parametrize("params, text", [
    ({"RADIUS": 0.0}, "radius"),
    ({"SLOPE": 90.0}, "between 0 and 90"),
    ({"SLOPE": 0.0}, "between 0 and 90"),
])
def test_filter_bad_input(qgis_processing, tile_path, tmp_path, params, text):
    from qgis.core import QgsProcessingException
    out = tmp_path / "never.laz"
    with pytest.raises(QgsProcessingException) as err:
        qgis_processing.run("geomatics:slopegroundfilter",
                            {"INPUT": tile_path, "OUTPUT": str(out), **params})
    assert text in str(err.value)
    assert not out.exists()


def test_filter_empty_cloud(qgis_processing, tmp_path):
    from qgis.core import QgsProcessingException
    empty = tmp_path / "empty.las"
    write_las(empty, np.zeros(0), np.zeros(0), np.zeros(0))
    out = tmp_path / "never.laz"
    with pytest.raises(QgsProcessingException, match="empty"):
        qgis_processing.run("geomatics:slopegroundfilter",
                            {"INPUT": str(empty), "OUTPUT": str(out)})
    assert not out.exists()


def test_sweep_through_processing(qgis_processing, tile_path, tmp_path):
    csv_path, html, out = tmp_path / "s.csv", tmp_path / "s.html", tmp_path / "best.laz"
    res = qgis_processing.run("geomatics:slopethresholdsweep", {
        "INPUT": tile_path, "SLOPES": "30:60:10", "RADII": "3, 8",
        "HEIGHT_TOLERANCES": "0, 0.2", "METRIC": 1, "OUTPUT_CSV": str(csv_path),
        "OUTPUT_HTML": str(html), "OUTPUT": str(out)})
    rows = list(csv.DictReader(csv_path.open()))
    assert len(rows) == res["N_SETTINGS"] == 16
    best = max(rows, key=lambda r: float(r["kappa_pct"]))
    assert res["BEST_KAPPA"] == pytest.approx(float(best["kappa_pct"]), rel=1e-5)
    assert res["BEST_SLOPE"] == float(best["slope_deg"])
    assert "Best setting" in html.read_text(encoding="utf-8")
    # the best-setting cloud has the best row's ground count
    assert np.count_nonzero(read_las(out, ["classification"])["classification"] == 2) == int(
        best["n_ground"])


def test_sweep_reference_of_different_length(qgis_processing, tile_path, tmp_path):
    from qgis.core import QgsProcessingException
    ref = tmp_path / "short.las"
    write_las(ref, np.arange(10.0), np.arange(10.0), np.zeros(10),
              dimensions={"classification": np.full(10, 2, np.uint8)})
    csv_path = tmp_path / "never.csv"
    with pytest.raises(QgsProcessingException, match="same points"):
        qgis_processing.run("geomatics:slopethresholdsweep", {
            "INPUT": tile_path, "REFERENCE": str(ref), "OUTPUT_CSV": str(csv_path)})
    assert not csv_path.exists()


def test_sweep_bad_slope_list(qgis_processing, tile_path, tmp_path):
    from qgis.core import QgsProcessingException
    csv_path = tmp_path / "never.csv"
    with pytest.raises(QgsProcessingException, match="between 0 and 90"):
        qgis_processing.run("geomatics:slopethresholdsweep", {
            "INPUT": tile_path, "SLOPES": "40, 95", "OUTPUT_CSV": str(csv_path)})
    assert not csv_path.exists()

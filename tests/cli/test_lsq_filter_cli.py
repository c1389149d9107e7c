"""qgis_process smoke tests for the LSQ ground filter and the filter accuracy."""
from __future__ import annotations

import laspy
import numpy as np
import pytest


@pytest.fixture(scope="module")
def laz(tmp_path_factory):
    from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile
    tile = generate_tile(extent=(90, 90), density=3.0, seed=8)
    path = tmp_path_factory.mktemp("lsqcli") / "tile.laz"
    write_tile(tile, path)
    return path


def _same_except_class(src, dst):
    a, b = laspy.read(src), laspy.read(dst)
    assert dst.suffix == ".laz" and b.header.are_points_compressed
    assert a.header.point_format.id == b.header.point_format.id
    assert a.header.point_count == b.header.point_count
    for name in a.point_format.dimension_names:
        if name != "classification":
            assert np.array_equal(a[name], b[name]), name
    return b


def test_cli_lsq_ground_filter_laz(qgis_process, laz, tmp_path):
    out, html = tmp_path / "classified.laz", tmp_path / "report.html"
    res = qgis_process.run("geomatics:lsqgroundfilter", INPUT=laz, OUTPUT=out, OUTPUT_HTML=html,
                 TILE_SIZE=45, THRESHOLD=0.5, ORDER=2, MODE=1)
    r = res["results"]
    b = _same_except_class(laz, out)
    cls = np.asarray(b.classification)
    assert r["N_GROUND"] == np.count_nonzero(cls == 2) > 0
    assert r["N_OTHER"] == np.count_nonzero(cls == 1)
    assert set(np.unique(cls)) <= {1, 2, 7, 18}
    src = np.asarray(laspy.read(laz).classification)     # the input's noise classes kept
    noise = np.isin(src, (7, 18))
    assert np.array_equal(cls[noise], src[noise])
    assert "ZMin" in html.read_text(encoding="utf-8")
    acc = qgis_process.run("geomatics:groundfilteraccuracy", INPUT=out, REFERENCE=laz)["results"]
    assert acc["A"] + acc["B"] + acc["C"] + acc["D"] == len(cls)
    assert 0 <= acc["TOTAL"] < 15


def test_cli_isprs_sample(qgis_process, isprs_dir, tmp_path):
    """The ISPRS reference file (LAS 1.2, format 0, classes 2/1) filtered and assessed."""
    src = isprs_dir / "samp54.laz"
    out = tmp_path / "samp54_lsq.laz"
    qgis_process.run("geomatics:lsqgroundfilter", INPUT=src, OUTPUT=out, TILE_SIZE=50,
           THRESHOLD=1.0, MODE=0)
    _same_except_class(src, out)
    r = qgis_process.run("geomatics:groundfilteraccuracy", INPUT=out, REFERENCE=src)["results"]
    assert abs(r["TOTAL"] - 4.04) <= 1.5


def test_cli_bad_threshold_writes_nothing(qgis_process, laz, tmp_path):
    out = tmp_path / "never.laz"
    msg = qgis_process.run_expect_failure("geomatics:lsqgroundfilter", INPUT=laz, OUTPUT=out,
                                THRESHOLD=0)
    assert "THRESHOLD must be a positive number" in msg
    assert not out.exists()

"""Output contract and input sanity of the LiDAR filters through processing.run (issue 9)."""
from __future__ import annotations

import os

import numpy as np
import pytest

from geomatics_toolbox.core.io.las import write_las

LSQ = "geomatics:lsqgroundfilter"
SLOPE = "geomatics:slopegroundfilter"


@pytest.fixture(scope="module")
def tile(tmp_path_factory):
    from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile
    t = generate_tile(extent=(80, 80), density=3.0, seed=5)
    path = tmp_path_factory.mktemp("contract") / "tile.laz"
    write_tile(t, path)
    return path


def _fails(qgis_processing, alg, params, text):
    from qgis.core import QgsProcessingException
    with pytest.raises(QgsProcessingException) as err:
        qgis_processing.run(alg, {k: str(v) for k, v in params.items()})
    assert text in str(err.value), str(err.value)
    return str(err.value)


def test_lsq_output_equal_ground_output_refused(qgis_processing, tile, tmp_path):
    before = tile.read_bytes()
    same = tmp_path / "same.laz"
    msg = _fails(qgis_processing, LSQ, {"INPUT": tile, "OUTPUT": same, "GROUND_OUTPUT": same},
                 "give each output its own file")
    assert "OUTPUT" in msg and "GROUND_OUTPUT" in msg
    assert os.listdir(tmp_path) == [] and tile.read_bytes() == before


def test_lsq_output_equal_input_refused(qgis_processing, tile, tmp_path):
    before = tile.read_bytes()
    _fails(qgis_processing, LSQ, {"INPUT": tile, "OUTPUT": tile}, "same file as the input")
    assert tile.read_bytes() == before
    assert not [p for p in os.listdir(tile.parent) if ".part" in p]


def test_slope_unwritable_report_leaves_no_partial_result(qgis_processing, tile, tmp_path):
    before = tile.read_bytes()
    out = tmp_path / "classified.laz"
    from qgis.core import QgsProcessingException
    with pytest.raises(QgsProcessingException):
        qgis_processing.run(SLOPE, {"INPUT": str(tile), "OUTPUT": str(out),
                                    "OUTPUT_HTML": "/proc/geomatics_report.html"})
    assert os.listdir(tmp_path) == []          # no classified cloud, no temporary
    assert tile.read_bytes() == before


@pytest.mark.parametrize("alg", [LSQ, SLOPE])
@pytest.mark.parametrize("crs", ["EPSG:4326", None])
def test_cloud_in_degrees_refused(qgis_processing, tmp_path, alg, crs):
    rng = np.random.default_rng(2)
    n = 3000
    src = tmp_path / "lonlat.las"
    write_las(src, 36.29 + rng.uniform(0, 0.001, n), 33.51 + rng.uniform(0, 0.001, n),
              700 + rng.uniform(0, 15, n), crs=crs, scale=1e-7)
    msg = _fails(qgis_processing, alg, {"INPUT": src, "OUTPUT": tmp_path / "o.laz"},
                 "--filters.reprojection.out_srs=EPSG:326xx")
    assert "TILE_SIZE" not in msg
    assert sorted(os.listdir(tmp_path)) == ["lonlat.las"]

"""scripts/make_demo_data.py: standalone run, sizes, check points, determinism."""
from __future__ import annotations

import csv
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from geomatics_toolbox.core.io import las as las_io
from geomatics_toolbox.synthetic.lidar import generate_tile

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "scripts" / "make_demo_data.py"


@pytest.fixture(scope="module")
def demo(tmp_path_factory):
    out = tmp_path_factory.mktemp("demo") / "demo"
    # standalone, from another working directory: the script imports the checkout itself
    res = subprocess.run([sys.executable, str(SCRIPT), "--out", str(out)],
                         cwd=str(out.parent), capture_output=True, text=True, timeout=300)
    assert res.returncode == 0, res.stderr
    return out


def _read_csv(path):
    with open(path, newline="", encoding="utf-8") as fh:
        rows = list(csv.DictReader(fh))
    return rows


def test_outputs_exist_and_nothing_else(demo):
    assert sorted(p.name for p in demo.iterdir()) == ["checkpoints.csv", "checkpoints.gpkg",
                                                      "demo.laz"]


def test_demo_laz(demo):
    laz = demo / "demo.laz"
    assert laz.stat().st_size <= 2_000_000
    info = las_io.las_info(laz)
    assert info.version == "1.4" and info.point_format == 6 and info.compressed
    assert info.count > 250_000
    assert info.crs and "32632" in info.crs
    data = las_io.read_las(laz, ("classification",))
    assert set(np.unique(data["classification"])) == {2, 5, 6, 7, 18}


def test_checkpoints_csv_and_gpkg(demo):
    rows = _read_csv(demo / "checkpoints.csv")
    assert list(rows[0]) == ["id", "x", "y", "z"]
    assert len(rows) == 62
    x = np.array([float(r["x"]) for r in rows])
    y = np.array([float(r["y"]) for r in rows])
    z = np.array([float(r["z"]) for r in rows])
    # the true terrain of the demo tile (same generator parameters)
    sys.path.insert(0, str(SCRIPT.parent))
    try:
        import make_demo_data as mdd
    finally:
        sys.path.remove(str(SCRIPT.parent))
    tile = generate_tile(seed=2, **mdd.DEMO)
    np.testing.assert_allclose(z, tile.terrain(x, y), atol=6e-4)
    assert tile.open_ground(x, y).all()

    from osgeo import ogr, osr
    ds = ogr.Open(str(demo / "checkpoints.gpkg"))
    layer = ds.GetLayer("checkpoints")
    assert layer.GetFeatureCount() == 62
    assert ogr.GT_HasZ(layer.GetGeomType())
    ref = osr.SpatialReference()
    ref.ImportFromEPSG(32632)
    assert layer.GetSpatialRef().IsSame(ref)
    feats = sorted(layer, key=lambda f: f.GetField("id"))
    for f, r in zip(feats, rows):
        g = f.GetGeometryRef()
        assert f.GetField("id") == int(r["id"])
        assert g.GetX() == pytest.approx(float(r["x"]), abs=1e-6)
        assert g.GetY() == pytest.approx(float(r["y"]), abs=1e-6)
        assert g.GetZ() == pytest.approx(float(r["z"]), abs=1e-6)
        assert f.GetField("z") == pytest.approx(float(r["z"]), abs=1e-6)


def test_deterministic(demo, tmp_path):
    again = tmp_path / "again"
    res = subprocess.run([sys.executable, str(SCRIPT), "--out", str(again)],
                         capture_output=True, text=True, timeout=300)
    assert res.returncode == 0, res.stderr
    for name in ("checkpoints.csv", "checkpoints.gpkg"):
        assert (again / name).read_bytes() == (demo / name).read_bytes(), name
    a = las_io.read_las(demo / "demo.laz", ("classification", "gps_time", "intensity"))
    b = las_io.read_las(again / "demo.laz", ("classification", "gps_time", "intensity"))
    for attr in ("x", "y", "z"):
        assert np.array_equal(getattr(a, attr), getattr(b, attr))
    for name in a.dims:
        assert np.array_equal(a[name], b[name])

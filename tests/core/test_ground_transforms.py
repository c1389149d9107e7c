"""Invariances of the recommended ground filter that must hold exactly (issue 21, stress
round 2), and the transformations of ``benchmarks/_ground_transforms.py``.

* a cloud moved by a UTM-like offset gets the very same classes (the raster is anchored
  on the cloud itself), and so does a cloud moved up or down by a multiple of 1,024 m:
  heights are stored in float32 above a base rounded to 1,024 m (``_heights``); another
  vertical shift changes their float32 rounding and may flip a tie (fusa +30 m or
  +2,000 m: 1 point of 277,573; ``bench_ground.py --transforms``);
* a LAS 1.4 cloud (WKT CRS) in US survey feet gets the classes of its metre copy through
  the file path (the feet are converted on reading; a unit bug is silent nonsense).
"""
from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

BENCH = Path(__file__).resolve().parents[2] / "benchmarks"
FT = 1200.0 / 3937.0


def _transforms():
    sys.path.insert(0, str(BENCH))
    try:
        import _ground_transforms
    finally:
        sys.path.remove(str(BENCH))
    return _ground_transforms


@pytest.fixture(scope="module")
def tile():
    from geomatics_toolbox.synthetic.lidar import generate_tile
    t = generate_tile(extent=(120.0, 120.0), origin=(0.0, 0.0), density=2.0, seed=3,
                      n_buildings=3)
    return tuple(np.asarray(a, float) for a in (t.x, t.y, t.z))


@pytest.mark.parametrize("offset", [(500_000.0, 5_000_000.0, 2_048.0),
                                    (612_345.67, 4_198_765.43, -1_024.0),
                                    (0.123, 0.456, 0.0)])
def test_recommended_classes_do_not_depend_on_the_coordinate_origin(tile, offset):
    from geomatics_toolbox.core.lidar.recommended import recommended_filter
    x, y, z = tile
    f = recommended_filter()
    c0 = f.classify(x, y, z).classes
    c = f.classify(x + offset[0], y + offset[1], z + offset[2]).classes
    assert np.array_equal(c, c0), int(np.count_nonzero(c != c0))
    assert np.bincount(c0, minlength=8)[[1, 2]].min() > 5_000       # both classes present


def _las14(path, x, y, z, wkt, scale):
    import laspy
    h = laspy.LasHeader(point_format=6, version="1.4")
    h.scales = [scale] * 3
    h.offsets = [np.floor(v.min()) for v in (x, y, z)]
    h.vlrs.append(laspy.vlrs.known.WktCoordinateSystemVlr(wkt))
    las = laspy.LasData(h)
    las.x, las.y, las.z = x, y, z
    las.write(str(path))
    return str(path)


def test_las14_wkt_in_us_survey_feet_gives_the_metre_copys_classes(tile, tmp_path):
    from osgeo import osr

    from geomatics_toolbox.core.io.las import las_info
    from geomatics_toolbox.core.lidar.filters import default_selection, ground_filter
    from geomatics_toolbox.core.lidar.pipeline import FilterOutputs, classify_file
    x, y, z = tile
    x, y = x + 500_000.37, y + 4_000_000.41          # no point on a cell edge in either file
    srs = osr.SpatialReference()
    srs.ImportFromEPSG(32632)
    m = _las14(tmp_path / "m.las", x, y, z, srs.ExportToWkt(), 0.0001)
    srs.SetLinearUnitsAndUpdateParameters("US survey foot", FT)
    ft = _las14(tmp_path / "ft.las", x / FT, y / FT, z / FT, srs.ExportToWkt(), 0.0001)
    assert las_info(ft).units.horizontal.symbol == "ftUS"
    assert las_info(ft).units.vertical.symbol == "ftUS"
    out = {}
    for k, src in (("m", m), ("ft", ft)):
        out[k] = classify_file(src, ground_filter("groundfilter"),
                               FilterOutputs(cloud=str(tmp_path / f"out_{k}.las")),
                               selection=default_selection("groundfilter")).classes
    assert np.array_equal(out["m"], out["ft"]), int(np.count_nonzero(out["m"] != out["ft"]))
    assert np.count_nonzero(out["m"] == 2) > 5_000


def test_under_canopy_is_the_3x3_cell_top_more_than_2_m_above_the_point():
    gt = _transforms()
    gx, gy = np.meshgrid(np.arange(10) + 0.5, np.arange(10) + 0.5)
    x, y = np.append(gx.ravel(), 4.5), np.append(gy.ravel(), 4.5)
    z = np.append(np.zeros(100), 10.0)                 # one crown point over cell (4, 4)
    ground = np.append(np.ones(100, bool), False)
    under = gt.under_canopy(x, y, z, ground)
    near = (np.abs(x - 4.5) <= 1.0) & (np.abs(y - 4.5) <= 1.0) & ground
    assert np.array_equal(under, near) and under.sum() == 9
    z[-1] = 1.9                                        # a shrub: not canopy
    assert not gt.under_canopy(x, y, z, ground).any()


def test_canopy_keep_removes_only_vendor_ground_under_canopy_seeded():
    gt = _transforms()
    rng = np.random.default_rng(0)
    n = 20_000
    x, y = rng.uniform(0, 100, n), rng.uniform(0, 100, n)
    tree = x < 50                                      # the west half is forest
    vclass = np.where(np.arange(n) % 2 == 0, 2, 5).astype(np.uint8)
    z = np.where((vclass == 5) & tree, 15.0, 0.0)
    d = dict(x=x, y=y, z=z, vclass=vclass)
    a, b, c = gt.canopy_keep(d, 0.1, 1), gt.canopy_keep(d, 0.1, 1), gt.canopy_keep(d, 0.1, 2)
    assert np.array_equal(a, b) and not np.array_equal(a, c)
    assert a[vclass == 5].all()                        # every non-ground point kept
    east = (vclass == 2) & (x > 52)
    assert a[east].all()                               # open ground kept
    west = (vclass == 2) & (x < 48)
    assert 0.08 < a[west].mean() < 0.12                # 10 % of the ground under canopy
    thin = gt.canopy_keep(d, 0.1, 1, thin=0.5)
    assert not (thin & ~a).any() and abs(thin.sum() / 100.0 ** 2 - 0.5) < 0.05


def test_rotation_keeps_distances_and_dense_copy_repeats_each_point():
    gt = _transforms()
    rng = np.random.default_rng(1)
    x, y = rng.uniform(0, 90, 500), rng.uniform(0, 90, 500)
    u, v = gt.rotated(x, y, 30.0)
    assert np.allclose(np.hypot(u - u[0], v - v[0]), np.hypot(x - x[0], y - y[0]))
    assert np.isclose(np.arctan2(v[1] - v[0], u[1] - u[0])
                      - np.arctan2(y[1] - y[0], x[1] - x[0]), np.radians(30.0))
    n = 4_000
    d = dict(x=rng.uniform(0, 300, n), y=rng.uniform(0, 300, n), z=np.zeros(n),
             vclass=np.where(np.arange(n) < 100, 6, 2).astype(np.uint8))
    d["x"][:100], d["y"][:100] = 150.0, 150.0          # the "buildings" at the centre
    xd, yd, zd, cd, (cx, cy) = gt.dense_copy(d, 5, 1)
    inside = (np.abs(d["x"] - 150) <= 60) & (np.abs(d["y"] - 150) <= 60)
    assert (cx, cy) == (150.0, 150.0) and xd.size == 5 * inside.sum()
    assert np.abs(xd - np.repeat(d["x"][inside], 5)).max() <= 0.2
    assert np.array_equal(cd, np.repeat(d["vclass"][inside], 5))


def test_transforms_table_has_a_row_per_case_and_the_invariance_rows():
    gt = _transforms()
    rows = [dict(t="canopy", file="f", case="5%", seed=1, filter=w, n=100, rmse=r, bad=b,
                 cpu=0.1, ground=0.12) for w, r, b in (("oracle", 0.3, 2.0),
                                                       ("recommended", 0.2, 0.05),
                                                       ("smrf", 7.0, 32.0))]
    rows += [dict(t="rotate", file="f", case="rotate", filter="recommended", n=100,
                  rmse=1.0, bad=2.47, cpu=0.1, changed=267, diff=0.99)]
    md = gt.transforms_md(rows)
    assert "| f | 5% | 1 | 100 | 0.12 | 0.30 / 2.00 | 0.20 / 0.05 | 7.00 / 32.00 |" in md
    assert "| f | rotated 30° + offset | 100 | 1.00 / 2.47 | 267 | 0.990 |" in md

"""float32 height rasters of the recommended filter (``_heights``; issue 21, <= 200 B/pt).

The filter holds its rasters as float32 heights above a base (the median cell minimum
rounded to 1,024 m) and computes sums, planes, gradients and per-point differences in
float64. These tests pin the storage (exact float32 of the float64 minimum above the
base, resolution 2**-15 m within 512 m of it), the float32 forms of the raster helpers
against their float64 forms, and the base's robustness and invariance.
"""
from __future__ import annotations

import numpy as np
import pytest

from geomatics_toolbox.core.lidar import _raster as R  # noqa: N812
from geomatics_toolbox.core.lidar import recommended as rec
from geomatics_toolbox.synthetic.lidar import generate_tile


def test_height_base_is_the_median_rounded_to_1024_m_and_ignores_blunders_and_nan():
    z = np.array([np.nan, -1e6, 1650.2, 1700.0, 1710.0])
    assert R.height_base(z) == 2048.0                 # the minimum (-1e6) would be far off
    assert R.height_base(np.array([12.5, 300.0, 511.0])) == 0.0
    assert R.height_base(np.array([-600.0, -700.0])) == -1024.0
    assert R.height_base(np.full(3, np.nan)) == 0.0


def _cells(seed=3, n=4000, lift=0.0):
    rng = np.random.default_rng(seed)
    x, y = rng.uniform(0, 60, n), rng.uniform(0, 40, n)
    z = 1700 + 0.2 * x + rng.normal(0, 0.5, n) + lift
    return x, y, z, R.PointCells(x, y, R.Grid.around(x, y, 1.0))


def test_cell_min_above_the_base_is_the_float32_of_the_float64_minimum():
    x, y, z, pc = _cells()
    base = pc.height_base(z)
    assert base == 2048.0
    got = pc.cell_min(z, base=base)
    ref = pc.cell_min(z)
    assert got.dtype == np.float32 and ref.dtype == np.float64
    np.testing.assert_array_equal(np.isnan(got), np.isnan(ref))
    np.testing.assert_array_equal(got, (ref - base).astype(np.float32))
    ok = ~np.isnan(ref)                               # |z - base| < 512: 2**-15 m at worst
    assert np.abs(got[ok].astype(np.float64) + base - ref[ok]).max() <= 2.0 ** -15
    mask = z < 1705
    np.testing.assert_array_equal(pc.cell_min(z, mask, base=base),
                                  (pc.cell_min(z, mask) - base).astype(np.float32))


def test_bilinear_of_a_float32_raster_is_taken_in_float64():
    x, y, z, pc = _cells()
    r32 = pc.cell_min(z, base=2048.0)
    r32 = np.where(np.isnan(r32), np.float32(-300.0), r32)
    got = pc.bilinear(r32)
    assert got.dtype == np.float64
    np.testing.assert_array_equal(got, pc.bilinear(r32.astype(np.float64)))


def test_float32_forms_of_the_raster_helpers_equal_the_float64_forms_of_the_same_values():
    rng = np.random.default_rng(5)
    z64 = (-300 + np.cumsum(rng.normal(0, 0.4, (150, 90)), axis=1)).astype(np.float32)
    z32, z64 = z64, z64.astype(np.float64)            # the same values in both types
    for size in (1, 5, 27):
        got = R.box_mean(z32, size)
        assert got.dtype == np.float32
        np.testing.assert_array_equal(got, R.box_mean(z64, size).astype(np.float32))
    s32 = R.slope(z32, 0.5, dtype=np.float32)
    assert s32.dtype == np.float32
    np.testing.assert_array_equal(s32, R.slope(z64, 0.5).astype(np.float32))
    cells = np.arange(z32.size)
    np.testing.assert_array_equal(R.slope_at(z32, 0.5, cells), R.slope(z64, 0.5).ravel())
    np.testing.assert_array_equal(R.opening(z32, 3), R.opening(z64, 3).astype(np.float32))
    valid = rng.random(z32.shape) > 0.4
    f32, f64 = R.fill(z32, valid), R.fill(z64, valid)
    assert f32.dtype == np.float32
    assert np.abs(f32 - f64).max() < 1e-4             # the coarse levels summed in float64
    a, b = z32.copy(), z32.copy()
    b[3, 4] = -b[3, 4]
    b[5, 6] = np.nextafter(b[5, 6], np.float32(0))
    assert np.flatnonzero(R.changed(a, b)).tolist() == [3 * 90 + 4, 5 * 90 + 6]


@pytest.mark.parametrize("lift", [2048.0, -1024.0])
def test_classes_do_not_change_when_the_cloud_is_lifted_by_a_multiple_of_1024_m(lift):
    """Heights quantised to 2**-16 m: lifted by 1,024 k m they are the same heights above
    the base (which moves with them), so every raster and every class is the same; held
    as float32 absolute heights they would be rounded to 2**-12 m at 2,500 m."""
    t = generate_tile(extent=(120.0, 120.0), density=4.0, seed=11)
    x, y = np.asarray(t.x, float), np.asarray(t.y, float)
    z = np.round((np.asarray(t.z, float) + 400.0) * 2.0 ** 16) / 2.0 ** 16
    ref = rec.classify(x, y, z)
    assert 0 < np.count_nonzero(ref == 2) < ref.size
    np.testing.assert_array_equal(rec.classify(x, y, z + lift), ref)

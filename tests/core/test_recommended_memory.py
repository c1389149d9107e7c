"""Banded and in-place raster steps of the recommended filter equal the plain expressions.

The filter's memory was cut (issue 21: at most 200 bytes per point) by computing the
large rasters in bands of rows, in place, or only at the cells that are read. Each form
must give bit for bit what the whole-raster expression it replaced gives (the class sha1
goldens of tests/core/test_ground_filters.py rest on it); the references below are
those expressions.
"""
from __future__ import annotations

import numpy as np
import pytest
from scipy import ndimage

from geomatics_toolbox.core.lidar import _lowcells as L  # noqa: N812
from geomatics_toolbox.core.lidar import _raster as R  # noqa: N812
from geomatics_toolbox.core.lidar import _surface as S  # noqa: N812
from geomatics_toolbox.core.lidar import recommended as rec

#: shapes around the band sizes (64 and 128 rows), thin rasters and a single row
SHAPES = [(1, 9), (2, 5), (3, 3), (63, 7), (129, 40), (257, 31), (300, 2)]


def _terrain(shape, seed, holes=0.3):
    rng = np.random.default_rng(seed)
    r, c = np.mgrid[:shape[0], :shape[1]]
    z = 100 + 0.3 * c - 0.2 * r + 2 * np.sin(r / 7.0) + rng.normal(0, 0.3, shape)
    z[rng.random(shape) < 0.05] += 15                  # objects
    valid = rng.random(shape) > holes
    return z, valid


def _plain_box_mean(a, size):
    q = np.rint(np.asarray(a, np.float64) * 2.0 ** 20).astype(np.int64)
    h = size // 2
    for axis in (0, 1):
        n = q.shape[axis]
        cs = np.cumsum(np.take(q, np.clip(np.arange(-h, n + size - h - 1), 0, n - 1),
                               axis=axis), axis=axis)
        cs = np.concatenate((np.zeros_like(np.take(cs, [0], axis=axis)), cs), axis=axis)
        q = np.take(cs, np.arange(size, size + n), axis=axis) - np.take(cs, np.arange(n),
                                                                         axis=axis)
    return q / (2.0 ** 20 * size * size)


@pytest.mark.parametrize("shape", SHAPES)
def test_box_mean_slope_and_opening_equal_the_whole_raster_expressions(shape):
    z, _ = _terrain(shape, 1)
    for size in (3, 37, 55, 301):
        np.testing.assert_array_equal(R.box_mean(z, size), _plain_box_mean(z, size))
    for cell in (1.0, 0.3):
        if min(shape) >= 2:
            gy, gx = np.gradient(z, cell)
            np.testing.assert_array_equal(R.slope(z, cell), np.hypot(gx, gy))
    for r in (1, 3, 18):
        size = 2 * r + 1
        want = ndimage.maximum_filter(ndimage.minimum_filter(z, size=size, mode="nearest"),
                                      size=size, mode="nearest")
        np.testing.assert_array_equal(R.opening(z, r), want)


@pytest.mark.parametrize("shape", SHAPES[2:])
def test_push_pull_with_boolean_weights_equals_float_weights(shape):
    z, valid = _terrain(shape, 2, holes=0.6)
    w = valid.astype(np.float64)
    for anchor in ((0, 0), (3, 5)):
        want = R.push_pull(np.where(valid, z, 0.0) * w, w, *anchor)
        np.testing.assert_array_equal(R.fill(z, valid, anchor), want)


def test_plane_fit_where_equals_plane_fit_at_the_kept_cells():
    z, valid = _terrain((300, 45), 3)
    rms, centre, gx, gy = S.plane_fit(z, valid, 3)

    def select(b, at, rms_b, centre_b, gx_b, gy_b):
        return (rms_b < 0.6) & ((b.start + at // z.shape[1]) % 3 != 0), np.hypot(gx_b, gy_b)

    mask, (c, x, y, extra) = S.plane_fit_where(z, valid, 3, select)
    want = (rms < 0.6) & (np.arange(300) % 3 != 0)[:, None]
    np.testing.assert_array_equal(mask, want)
    assert want.sum() > 1000
    for got, ref in ((c, centre), (x, gx), (y, gy), (extra, np.hypot(gx, gy))):
        np.testing.assert_array_equal(got, ref[want])
    where = (np.arange(z.size) % 7 != 0).reshape(z.shape)   # planes at some cells only
    mask, (c, x, y, extra) = S.plane_fit_where(z, valid, 3, select, where=where)
    np.testing.assert_array_equal(mask, want & where)
    for got, ref in ((c, centre), (x, gx), (y, gy), (extra, np.hypot(gx, gy))):
        np.testing.assert_array_equal(got, ref[want & where])


def test_growing_step_equals_the_whole_raster_candidates():
    """grow_ground's banded candidates against the plain whole-raster expressions."""
    z, valid = _terrain((200, 60), 4, holes=0.1)
    skip = ~valid
    obj = np.zeros(z.shape, bool)
    obj[40:160, 10:50] = True                        # a wide object area over terrain
    obj &= valid
    opt = rec.RecommendedOptions()
    dtm = np.full(z.shape, 100.0)
    rms, centre, gx, gy = S.plane_fit(z, valid, 3)
    with np.errstate(invalid="ignore"):
        steep = np.hypot(gx, gy)
        tol = opt.grow_tol + opt.scaler * steep
        cand = (obj & ~skip & (rms <= opt.grow_rms) & (np.abs(z - centre) <= tol)
                & (steep <= opt.grow_max_slope) & (z - dtm <= opt.grow_max_rise))
    got_cand, (c, x, y, t) = S.plane_fit_where(
        z, valid, 3, lambda b, *m: S._grow_candidates(b, *m, z, 1.0, opt), where=obj & ~skip)
    got_cand &= z - dtm <= opt.grow_max_rise
    np.testing.assert_array_equal(got_cand, cand)
    assert cand.sum() > 100
    left = rec.grow_ground(z, obj, skip, dtm, 1.0, opt)
    assert (left <= obj).all() and left.sum() < obj.sum()


def test_tangent_fill_in_place_equals_a_new_raster():
    z, valid = _terrain((150, 70), 5, holes=0.4)
    zg = np.where(valid, z, np.nan)
    need = np.random.default_rng(0).random(z.shape) < 0.7
    want = S.tangent_fill(zg.copy(), valid, 1.0, need=need)
    own = zg.copy()
    got = S.tangent_fill(own, valid, 1.0, need=need, overwrite=True)
    assert got is own
    np.testing.assert_array_equal(got, want)
    assert np.isfinite(want[need]).all()


def test_block_any_equals_the_block_minimum_test():
    rng = np.random.default_rng(6)
    mask = rng.random((61, 47)) < 0.02
    for f in (2, 3, 16):
        for anchor in ((0, 0), (5, 9)):
            want = L._block_min(np.where(mask, 0.0, np.nan), f, anchor)[0] == 0.0
            np.testing.assert_array_equal(L._block_any(mask, f, anchor), want)


@pytest.mark.parametrize("shape", SHAPES[2:])
def test_in_place_trend_opening_and_closing_equal_the_plain_expressions(shape):
    z, valid = _terrain(shape, 7)
    for size in (1, 3, 55):
        own = z.copy()
        assert R.box_mean(z, size, subtract_from=own) is own
        np.testing.assert_array_equal(own, z - _plain_box_mean(z, size) if size > 1 else
                                      z - z)
    slope = np.random.default_rng(8).uniform(0.1, 0.6, shape)
    want = rec.progressive_objects(z, 1.0, 9.0, slope, lambda f: None)
    own = z.copy()
    np.testing.assert_array_equal(
        rec.progressive_objects(own, 1.0, 9.0, slope, lambda f: None, overwrite=True), want)
    assert want.any()
    zmin = np.where(valid, z, np.nan)
    zmin[1::7, 1::5] -= 12.0                           # pits below their closing
    zf = R.fill(zmin, valid)
    clo = -R.opening(-zf, 1)
    with np.errstate(invalid="ignore"):
        pits = ((clo - zmin) > 5.0) & valid
    got_pits, got_clo = L.closing_pits(zmin, 5.0)
    np.testing.assert_array_equal(got_clo, clo)
    np.testing.assert_array_equal(got_pits, pits)
    assert pits.any() or min(shape) < 8


@pytest.mark.parametrize("shape", SHAPES)
def test_slope_at_cells_and_banded_hole_indices_equal_the_whole_raster(shape):
    """label_points' slope at the points' cells, tangent_fill's hole indices by bands."""
    z, valid = _terrain(shape, 9)
    z[valid & (np.arange(z.size).reshape(shape) % 11 == 0)] = np.nan   # unfilled cells
    cells = np.random.default_rng(10).integers(0, z.size, 500).astype(np.int32)
    for cell in (1.0, 0.3):
        np.testing.assert_array_equal(R.slope_at(z, cell, cells),
                                      R.slope(z, cell).ravel()[cells])
        np.testing.assert_array_equal(R.slope_at(z, cell, np.arange(z.size)),
                                      R.slope(z, cell).ravel())
    hr, hc = S._nonzero(~valid)
    want = np.nonzero(~valid)
    assert hr.dtype == np.int32 and hc.dtype == np.int32
    np.testing.assert_array_equal(hr, want[0])
    np.testing.assert_array_equal(hc, want[1])
    wide = np.random.default_rng(11).random((700, 1001)) < 0.3     # 3 bands of 261 rows
    for m in (wide, wide[:, :1], np.zeros((5, 0), bool)):
        got = S._nonzero(m)
        for a, b in zip(got, np.nonzero(m)):
            np.testing.assert_array_equal(a, b)


@pytest.mark.parametrize("shape", SHAPES[2:])
def test_fill_in_place_and_surface_with_a_rebuilt_minimum_equal_the_plain_ones(shape):
    z, valid = _terrain(shape, 11, holes=0.5)
    want = R.fill(z, valid, (3, 5))
    own = z.copy()
    np.testing.assert_array_equal(R.fill(own, valid, (3, 5), overwrite=True), want)
    zmin = np.where(valid, z, np.nan)
    zmin[1::9, 2::7] -= 12.0
    grid = R.Grid(0.0, 0.0, 1.0, shape[0], shape[1])
    opt = rec.RecommendedOptions(cell=1.0, threshold=0.3)
    ref = rec.surface(zmin.copy(), grid, opt, lambda f: None)
    got = rec.surface(zmin.copy(), grid, opt, lambda f: None, remake=zmin.copy)
    np.testing.assert_array_equal(got, ref)


def _plain_low_cells(zmin, cell, step=5.0, window=25.0, share=0.08, share_coarse=0.03,
                     anchor=(0, 0)):
    """low_cells as it was before its banded steps (padded block copy, expanded closing)."""
    def block_min(z, f, anchor):
        rows, cols = z.shape
        pr, pc = anchor[0] % f, anchor[1] % f
        r2, c2 = -(-(rows + pr) // f), -(-(cols + pc) // f)
        zp = np.full((r2 * f, c2 * f), np.inf)
        zp[pr:pr + rows, pc:pc + cols] = z
        zp[np.isnan(zp)] = np.inf
        out = zp.reshape(r2, f, c2, f).min(axis=(1, 3))
        out[np.isinf(out)] = np.nan
        return out, (anchor[0] // f, anchor[1] // f)

    pits = L.closing_pits(zmin, step, anchor)[0]
    occupied = ~np.isnan(zmin)
    k = 2 * max(1, int(round(window / cell))) + 1
    occ = ndimage.uniform_filter(occupied.astype(np.float32), k, mode="constant")
    frac = ndimage.uniform_filter(pits.astype(np.float32), k, mode="constant")
    canopy = frac > share * np.maximum(occ, 1e-6)
    for f in L.FACTORS:
        coarse, canchor = block_min(zmin, f, anchor)
        np.testing.assert_array_equal(L._block_min(zmin, f, anchor)[0], coarse)
        cpits, clo = L.closing_pits(coarse, step, canchor)
        area = L._block_any(canopy, f, anchor)
        n_area = np.count_nonzero(area & ~np.isnan(coarse))
        if np.count_nonzero(cpits & area) < share_coarse * max(1, n_area):
            break
    pr, pc = anchor[0] % f, anchor[1] % f
    big = np.repeat(np.repeat(clo, f, axis=0), f, axis=1)[pr:pr + zmin.shape[0],
                                                          pc:pc + zmin.shape[1]]
    with np.errstate(invalid="ignore"):
        under = ((big - zmin) > step) & occupied
    return np.where(canopy, under, pits), canopy


@pytest.mark.parametrize("shape", [(150, 90), (300, 41), (333, 200)])
def test_low_cells_banded_blocks_equal_the_padded_and_expanded_rasters(shape):
    """A canopy (few ground cells 20 m below it) over part of the raster, pits elsewhere."""
    rng = np.random.default_rng(12)
    r, c = np.mgrid[:shape[0], :shape[1]]
    zmin = 50 + 0.1 * c + rng.normal(0, 0.2, shape)
    forest = (c > shape[1] // 3)
    zmin[forest] += 20 + rng.normal(0, 1, forest.sum())
    ground = forest & (rng.random(shape) < 0.15)
    zmin[ground] -= 20
    zmin[rng.random(shape) < 0.3] = np.nan
    zmin[3::17, 5::13] -= 9.0                          # isolated pits in the open
    for anchor in ((0, 0), (5, 7)):
        want, canopy = _plain_low_cells(zmin, 1.0, anchor=anchor)
        got = L.low_cells(zmin, 1.0, anchor=anchor)
        assert canopy.any() and got.canopy_scale > 0
        np.testing.assert_array_equal(got.low, want)


def test_tangent_fill_lists_its_holes_by_bands_with_the_same_values(monkeypatch):
    """More holes than a batch: listed band by band (bands of 3 rows here), batched."""
    z, valid = _terrain((300, 333), 13, holes=0.45)
    zg = np.where(valid, z, np.nan)
    need = np.random.default_rng(14).random(z.shape) < 0.8
    assert np.count_nonzero(~valid & need) > 2 * S.BATCH
    monkeypatch.setattr(S, "HOLE_BAND", 1000)
    got = S.tangent_fill(zg.copy(), valid, 1.0, need=need)
    monkeypatch.setattr(S, "BATCH", 10 ** 9)           # one batch of the whole list
    want = S.tangent_fill(zg.copy(), valid, 1.0, need=need)
    np.testing.assert_array_equal(got, want)
    assert np.isfinite(want[need]).all()

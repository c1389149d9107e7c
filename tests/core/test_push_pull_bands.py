"""The banded push-pull fill (core/lidar/_pushpull.py) equals the whole-array pyramid.

The reference is the whole-array form it replaced (padded 2 x 2 block sums, the
upsampled raster of each whole level): the values must be the same bit for bit, since
the recommended filter's class sha1 goldens (tests/core/test_ground_filters.py) rest on
them. Values with wide exponent ranges make a different summation order visible.
"""
from __future__ import annotations

import numpy as np
import pytest
from scipy import ndimage

from geomatics_toolbox.core.lidar import _pushpull as P  # noqa: N812
from geomatics_toolbox.core.lidar import _raster as R  # noqa: N812


def _reference(vw, w, r0=0, c0=0):
    """The whole-array push-pull (before the bands)."""
    rows, cols = w.shape
    if rows <= 2 and cols <= 2 or (w > 0).all():
        out = np.divide(vw, w, out=np.zeros_like(vw), where=w > 0)
        if not (w > 0).all():
            out[w == 0] = vw.sum() / w.sum()
        return out
    pr, pc = r0 % 2, c0 % 2
    r2, c2 = (rows + pr + 1) // 2, (cols + pc + 1) // 2
    pad = ((pr, 2 * r2 - rows - pr), (pc, 2 * c2 - cols - pc))
    cvw = np.pad(vw, pad).reshape(r2, 2, c2, 2).sum(axis=(1, 3), dtype=np.float64)
    cw = np.pad(w, pad).reshape(r2, 2, c2, 2).sum(axis=(1, 3))
    coarse = _reference(cvw, cw, r0 // 2, c0 // 2)
    up = ndimage.zoom(coarse, 2, order=1, mode="nearest", grid_mode=True,
                      output=np.result_type(vw.dtype, np.float32))
    up = up[pr:pr + rows, pc:pc + cols]
    return np.divide(vw, w, out=up, where=w > 0)


def _raster(shape, seed, holes, dtype):
    rng = np.random.default_rng(seed)
    # heights with every exponent from 2**-30 to 2**12: a sum in another order rounds
    # differently somewhere
    z = rng.choice([-1.0, 1.0], shape) * 2.0 ** rng.uniform(-30, 12, shape)
    z = (z + rng.normal(0, 1e-3, shape)).astype(dtype)
    valid = rng.random(shape) > holes
    return z, valid


SHAPES = [(1, 9), (3, 3), (5, 2), (64, 7), (127, 40), (129, 129), (257, 31), (300, 301),
          (513, 3)]


@pytest.mark.parametrize("shape", SHAPES)
@pytest.mark.parametrize("dtype", [np.float32, np.float64])
def test_banded_push_pull_equals_the_whole_array_pyramid(shape, dtype, monkeypatch):
    for rows_per_band in (1, 3, 64):
        monkeypatch.setattr(P, "ROWS", rows_per_band)
        for seed, holes in ((1, 0.3), (2, 0.8), (3, 0.995), (4, 0.05)):  # 0.05: zoom_at
            z, valid = _raster(shape, seed, holes, dtype)
            if not valid.any():
                continue
            for anchor in ((0, 0), (1, 0), (3, 5), (-7, 2)):
                want = _reference(np.where(valid, z, 0.0), valid, *anchor)
                got = R.fill(z, valid, anchor)
                assert got.dtype == want.dtype
                np.testing.assert_array_equal(got.view(np.uint8), want.view(np.uint8))
                own = z.copy()
                got = R.fill(own, valid, anchor, overwrite=True)
                np.testing.assert_array_equal(got.view(np.uint8), want.view(np.uint8))


def test_float_weights_and_no_level_left():
    z, valid = _raster((40, 33), 4, 0.5, np.float64)
    w = valid * np.random.default_rng(5).uniform(0.5, 2.0, valid.shape)
    want = _reference(z * w, w, 3, 1)
    got = P.push_pull(z * w, w, 3, 1)
    np.testing.assert_array_equal(got.view(np.uint8), want.view(np.uint8))
    full = np.ones((4, 5), bool)                     # every weight positive: no pyramid
    np.testing.assert_array_equal(P.push_pull(z[:4, :5].copy(), full), z[:4, :5])


def test_zoom_at_is_scipys_zoom_bit_for_bit():
    """The upsampling at the few hole cells of a band (``_pushpull.zoom_at``) gives the bits
    of ``ndimage.zoom(order=1, grid_mode=True, mode="nearest")``: every output cell of
    rasters of 1-40 rows and columns, float32/float64, wide exponents, signed zeros."""
    rng = np.random.default_rng(0)
    for it in range(200):
        m, n = rng.integers(1, 40, 2)
        c = rng.choice([-1.0, 1.0], (m, n)) * 2.0 ** rng.uniform(-30, 12, (m, n))
        if it % 3 == 0:
            c = c.astype(np.float32)
        if it % 5 == 0:
            c[rng.random(c.shape) < 0.3] = 0.0
            c[rng.random(c.shape) < 0.1] = -0.0
        for dtype in (np.float32, np.float64):
            want = ndimage.zoom(c, 2, order=1, mode="nearest", grid_mode=True, output=dtype)
            rr, cc = np.nonzero(np.ones(want.shape, bool))
            got = P.zoom_at(c, rr, cc).astype(dtype).reshape(want.shape)
            np.testing.assert_array_equal(got.view(np.uint8), want.view(np.uint8))

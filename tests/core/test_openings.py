"""The progressive openings (core/lidar/_openings.py) equal an opening of the last opening
by each radius, bit for bit: the 3 x 3 erosion chain on a whole raster, the plain
openings with cells outside the footprint."""
from __future__ import annotations

import numpy as np
import pytest

from geomatics_toolbox.core.lidar import _raster as R  # noqa: N812
from geomatics_toolbox.core.lidar._openings import erode3, openings


def _plain(z, radii, outside=None):
    """Each opening of the last one (:func:`_raster.opening`), copies kept."""
    out, cur = [], z.copy()
    for r in radii:
        nxt = R.opening(cur.copy(), r, outside=outside)
        out.append((r, cur.copy(), nxt.copy()))
        cur = nxt
    return out


@pytest.mark.parametrize("shape", [(60, 45), (1, 30), (30, 1), (2, 2), (7, 3)])
@pytest.mark.parametrize("overwrite", [False, True])
def test_openings_equal_the_opening_of_each_opening(shape, overwrite):
    rng = np.random.default_rng(sum(shape))
    z = rng.normal(0, 3, shape).astype(np.float32)
    z[rng.random(shape) < 0.1] += 20.0               # objects of every width
    z.ravel()[::7] = np.round(z.ravel()[::7])        # ties
    radii = np.arange(1, 13)
    want = _plain(z, radii)
    got = [(r, c.copy(), o.copy()) for r, c, o in openings(z.copy(), radii, overwrite)]
    for (r0, c0, o0), (r1, c1, o1) in zip(want, got):
        assert r0 == r1
        assert np.array_equal(c0, c1) and np.array_equal(o0, o1)


def test_openings_with_cells_outside_or_other_radii_open_the_last_opening():
    rng = np.random.default_rng(4)
    z = rng.normal(0, 3, (40, 50)).astype(np.float32)
    outside = np.zeros(z.shape, bool)
    outside[:10, :10] = True                          # a corner outside the footprint
    for radii, out in ((np.arange(1, 9), outside), (np.array([1, 3, 4]), None)):
        want = _plain(z, radii, out)
        got = [(r, c.copy(), o.copy()) for r, c, o in openings(z.copy(), radii, False, out)]
        for (_, c0, o0), (_, c1, o1) in zip(want, got):
            ok = ~out if out is not None else np.ones(z.shape, bool)
            assert np.array_equal(o0[ok], o1[ok]) and np.array_equal(c0[ok], c1[ok])


def test_erode3_is_the_separable_3_by_3_minimum():
    from scipy import ndimage
    rng = np.random.default_rng(2)
    for shape in [(5, 5), (1, 4), (4, 1), (2, 3), (31, 17)]:
        z = rng.normal(size=shape)
        want = ndimage.minimum_filter(z, size=3, mode="nearest")
        assert np.array_equal(erode3(z.copy(), np.empty(z.size)), want)


@pytest.mark.parametrize("size", [3, 5, 9, 37, 101])
def test_dilate_is_scipys_maximum_filter(size):
    from scipy import ndimage

    from geomatics_toolbox.core.lidar._openings import dilate
    rng = np.random.default_rng(size)
    for shape in [(60, 45), (1, 30), (30, 1), (2, 2)]:
        z = rng.normal(size=shape).astype(np.float32)
        z.ravel()[::5] = -np.inf
        want = ndimage.maximum_filter(z, size=size, mode="nearest")
        assert np.array_equal(dilate(z, size), want)
        out = np.empty_like(z)
        assert dilate(z, size, out=out) is out and np.array_equal(out, want)


@pytest.mark.parametrize("radius", [1, 2, 18, 27, 60])
def test_opening_by_tables_is_scipys_opening(radius):
    """R.opening(tables=True) (dense clouds' closings, trend and slope openings) gives the
    bits of the scipy filters, with and without cells outside, in place or not."""
    rng = np.random.default_rng(radius)
    for shape in [(60, 45), (1, 30), (30, 1), (2, 2), (130, 7)]:
        z = rng.normal(0, 3, shape).astype(np.float32)
        z[rng.random(shape) < 0.1] += 20.0
        z.ravel()[::7] = np.round(z.ravel()[::7])    # ties
        outside = rng.random(shape) < 0.2
        for out in (None, outside):
            want = R.opening(z.copy(), radius, outside=out)
            a = z.copy()
            got = R.opening(a, radius, outside=out, tables=True)
            assert np.array_equal(got, want)
            assert np.array_equal(R.opening(a, radius, out=a, outside=out, tables=True), want)
        neg = -z                                      # a closing, as closing_pits takes it
        assert np.array_equal(-R.opening(neg.copy(), radius, tables=True),
                              -R.opening(neg.copy(), radius))


@pytest.mark.parametrize("size", [3, 7, 15])
def test_dilate_mask_is_scipys_maximum_filter(size):
    """The growing step's square dilation of bool rasters: the cells of scipy's filter."""
    from scipy import ndimage
    rng = np.random.default_rng(size)
    for shape in [(60, 45), (1, 30), (30, 1), (2, 2), (300, 7)]:
        for share in (0.01, 0.3):
            m = rng.random(shape) < share
            want = ndimage.maximum_filter(m, size=size, mode="constant")
            got = R.dilate_mask(m, size)
            assert got.dtype == bool and np.array_equal(got, want)

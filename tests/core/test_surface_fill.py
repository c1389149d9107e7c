"""Tangent-plane hole filling of the recommended filter's provisional DTM (core/lidar/_surface)."""
from __future__ import annotations

import numpy as np
import pytest

from geomatics_toolbox.core.lidar import _raster as R  # noqa: N812
from geomatics_toolbox.core.lidar import _surface as S  # noqa: N812


def _grid(rows=40, cols=50):
    return np.mgrid[0:rows, 0:cols].astype(float)


@pytest.mark.parametrize("cell", [0.5, 1.0, 2.0])
def test_plane_gradient_exact_on_planes_even_next_to_holes(cell):
    yy, xx = _grid()
    z = 100.0 + 0.3 * xx * cell - 0.7 * yy * cell
    valid = np.ones(z.shape, bool)
    valid[10:20, 15:30] = False                   # one-sided windows along the hole
    gx, gy = S.plane_gradient(z, valid, 3, cell)
    ok = valid
    assert np.allclose(gx[ok], 0.3, atol=1e-9) and np.allclose(gy[ok], -0.7, atol=1e-9)


def test_plane_gradient_zero_where_the_window_is_collinear():
    yy, xx = _grid(9, 9)
    valid = np.zeros(xx.shape, bool)
    valid[4, :] = True                            # one row: no plane
    gx, gy = S.plane_gradient(2.0 * xx + yy, valid, 2, 1.0)
    assert np.allclose(gy[4], 0.0) and np.allclose(gx[4], 0.0)


def test_integer_window_moments_equal_scipy_correlations():
    """The window moments of the valid cells, summed in integers by shifted additions,
    are scipy's float64 correlations bit for bit (any radius, tiny rasters, every
    integer width), and the z sums are scipy's correlations in scipy's order."""
    from scipy import ndimage

    from geomatics_toolbox.core.lidar import _planes as P  # noqa: N812
    rng = np.random.default_rng(11)
    for shape, r, share in (((1, 1), 1, 0.5), ((2, 9), 3, 0.7), ((9, 2), 2, 0.7),
                            ((40, 31), 1, 0.5), ((40, 31), 3, 0.8), ((33, 47), 5, 0.6),
                            ((25, 30), 6, 0.9), ((60, 70), 13, 0.95), ((90, 100), 40, 1.0)):
        valid = rng.random(shape) < share
        z = 100.0 + rng.normal(0, 3, shape)
        got = P._moments(z, valid, r, spread=True)
        off = np.arange(-r, r + 1, dtype=np.float64)
        box = np.ones(2 * r + 1)
        w = valid.astype(np.float64)
        zw = np.where(valid, z, 0.0)

        def corr(a, kx, ky):
            a = ndimage.correlate1d(a, kx, axis=1, mode="constant")
            return ndimage.correlate1d(a, ky, axis=0, mode="constant")
        want = dict(n=corr(w, box, box), sx=corr(w, off, box), sy=corr(w, box, off),
                    sxx=corr(w, off * off, box), syy=corr(w, box, off * off),
                    sxy=corr(w, off, off), sz=corr(zw, box, box), sxz=corr(zw, off, box),
                    syz=corr(zw, box, off), szz=corr(zw * zw, box, box))
        assert got.keys() == want.keys()
        for key, ref in want.items():
            a = got[key]
            np.testing.assert_array_equal(a.astype(np.float64), ref, err_msg=f"{key} r={r}")
            if "z" not in key:
                assert np.issubdtype(a.dtype, np.integer)
        if r == 40:                     # full windows: 81 rows of sum(d², -40..40) > int16
            assert got["sxx"].dtype == np.int32 and got["sxx"].max() == 81 * (40 * 41 * 81 // 3)


def test_tangent_fill_equals_a_brute_force_fill_scan_and_tree():
    """Every hole cell is the Shepard mean of the tangent planes of its 12 nearest border
    cells ordered by (d², row, column offset), bit for bit: cells near a border (lattice
    scan, offsets tabulated) and deep in a 60-cell-wide hole (beyond the scan: KD-tree)."""
    from geomatics_toolbox.core.lidar import _lattice_knn as K  # noqa: N812
    rng = np.random.default_rng(21)
    rows, cols, cell, reach, k = 130, 120, 0.8, 10.0, 12
    z = 50.0 + rng.normal(0, 1, (rows, cols)).cumsum(axis=1) * 0.2
    valid = rng.random((rows, cols)) < 0.7
    valid[20:120, 25:115] = False                     # hole cells up to 45 from a border
    got = S.tangent_fill(np.where(valid, z, np.nan), valid, cell, radius=3, neighbours=k,
                         reach=reach)
    gx, gy = S.plane_gradient(z, valid, 3, cell)
    ring = valid & ~np.all([np.roll(np.pad(valid, 1, constant_values=True), (a, b), (0, 1))
                            [1:-1, 1:-1] for a in (-1, 0, 1) for b in (-1, 0, 1)], axis=0)
    rr, cc = np.nonzero(ring)
    hr, hc = np.nonzero(~valid)
    pick = (rng.random(hr.size) < 0.1) | ((abs(hr - 70) < 8) & (abs(hc - 70) < 8))
    hr, hc = hr[pick], hc[pick]                       # a sample, and the deepest cells
    dr, dc = rr[None, :] - hr[:, None], cc[None, :] - hc[:, None]
    d2 = dr * dr + dc * dc
    order = np.lexsort((dc, dr, d2), axis=1)[:, :k]
    j = order
    d2, dc, dr = (np.take_along_axis(a, order, 1).astype(float) for a in (d2, dc, dr))
    assert (d2[:, -1] > K.SCAN_D2).sum() > 100 and (d2[:, -1] <= K.SCAN_D2).sum() > 500
    d = np.maximum(np.sqrt(d2) * cell, 1e-9)
    damp = np.minimum(1.0, reach / d) * cell
    plane = ((gx[rr, cc][j] * -dc - gy[rr, cc][j] * dr) * damp + z[rr, cc][j]) * (1.0 / (d * d))
    want = plane.sum(axis=1) / (1.0 / (d * d)).sum(axis=1)
    np.testing.assert_array_equal(got[hr, hc], want)
    np.testing.assert_array_equal(got[valid], z[valid])
    batch, few = S.BATCH, S.FEW_HOLES
    try:                     # batches of a few hundred: scan and tree rows in the same batch
        for S.BATCH, S.FEW_HOLES in ((257, 10 ** 6), (257, 0), (1000, 1000)):
            again = S.tangent_fill(np.where(valid, z, np.nan), valid, cell, radius=3,
                                   neighbours=k, reach=reach)
            np.testing.assert_array_equal(again, got)
    finally:
        S.BATCH, S.FEW_HOLES = batch, few


def test_tangent_fill_reproduces_a_plane():
    yy, xx = _grid()
    z = 50.0 + 0.4 * xx + 0.25 * yy
    valid = np.ones(z.shape, bool)
    valid[12:20, 20:27] = False                   # every hole cell within reach
    out = S.tangent_fill(np.where(valid, z, np.nan), valid, 1.0)
    assert np.allclose(out, z, atol=1e-9)


def test_tangent_fill_keeps_a_crest_the_tin_cuts():
    """Roof-shaped ridge (slopes 0.4) with its 8 m crest band removed."""
    yy, xx = _grid(40, 41)
    z = 100.0 - 0.4 * np.abs(xx - 20.0)
    valid = np.abs(xx - 20.0) > 4.0
    zin = np.where(valid, z, np.nan)
    tin = R.fill_tin(zin, valid)
    tan = S.tangent_fill(zin, valid, 1.0)
    crest = (xx == 20.0) & (yy > 5) & (yy < 35)
    assert np.all(z[crest] - tin[crest] > 1.5)            # the TIN cuts 1.6 m off
    assert np.all(np.abs(tan[crest] - z[crest]) < 0.5)    # tangent planes keep it
    assert np.array_equal(tan[valid], z[valid])


def test_tangent_fill_damps_far_extrapolation():
    """A 40 m hole on a 0.5 slope: nothing beyond the border planes' reach of 10 m."""
    yy, xx = _grid(60, 100)
    z = 0.5 * xx
    valid = xx < 30                                # only the west side is known
    out = S.tangent_fill(np.where(valid, z, np.nan), valid, 1.0, reach=10.0)
    far = out[:, 80]
    assert np.all(far <= 29 * 0.5 + 10 * 0.5 + 1e-9)
    assert np.allclose(out[10:50, 35], z[10:50, 35], atol=1e-9)   # within reach: the plane


def test_tangent_fill_few_borders_falls_back():
    z = np.full((5, 5), np.nan)
    valid = np.zeros((5, 5), bool)
    valid[2, 2] = True
    z[2, 2] = 7.0
    assert np.allclose(S.tangent_fill(z, valid, 1.0), 7.0)


def test_fill_only_where_read_is_identical_there():
    """A fill restricted to the cells the points read equals the full fill there, and
    bilinear values and slopes at the points never touch an unfilled cell."""
    rng = np.random.default_rng(3)
    x, y = rng.uniform(0, 200, 4000), rng.uniform(0, 150, 4000)   # 0.13 pts/m²
    z = 50 + 0.1 * x + np.sin(y / 9.0)
    pc = R.PointCells(x, y, R.Grid.around(x, y, 1.0))
    zmin = pc.cell_min(z)
    valid = ~np.isnan(zmin)
    need = pc.read_mask()
    assert 0.2 < need.mean() < 0.95
    full = S.tangent_fill(zmin, valid, 1.0)
    part = S.tangent_fill(zmin, valid, 1.0, need=need)
    np.testing.assert_array_equal(part[need], full[need])
    assert np.isnan(part[~need]).all()
    np.testing.assert_array_equal(pc.bilinear(part), pc.bilinear(full))
    np.testing.assert_array_equal(pc.nearest(R.slope(part, 1.0)),
                                  pc.nearest(R.slope(full, 1.0)))


def _old_window_planes(z, valid, r, spread=False):
    """The float64 whole-raster planes of 41aabe4 (scipy correlations of every moment,
    then the formulas on every cell): the independent oracle of ``_planes``."""
    from scipy import ndimage
    off = np.arange(-r, r + 1, dtype=np.float64)
    box = np.ones(2 * r + 1)
    w = valid.astype(np.float64)
    zw = np.where(valid, np.asarray(z, np.float64), 0.0)

    def corr(a, kx, ky):
        return ndimage.correlate1d(ndimage.correlate1d(a, kx, axis=1, mode="constant"),
                                   ky, axis=0, mode="constant")
    n = corr(w, box, box)
    with np.errstate(invalid="ignore", divide="ignore"):
        mx, my, mz = corr(w, off, box) / n, corr(w, box, off) / n, corr(zw, box, box) / n
        cxx = corr(w, off * off, box) / n - mx * mx
        cyy = corr(w, box, off * off) / n - my * my
        cxy = corr(w, off, off) / n - mx * my
        cxz = corr(zw, off, box) / n - mx * mz
        cyz = corr(zw, box, off) / n - my * mz
        det = cxx * cyy - cxy * cxy
        gx, gy = (cyy * cxz - cxy * cyz) / det, (cxx * cyz - cxy * cxz) / det
        out = dict(n=n, mx=mx, my=my, mz=mz, det=det, gx=gx, gy=gy)
        if spread:
            out.update(czz=corr(zw * zw, box, box) / n - mz * mz, cxz=cxz, cyz=cyz)
    return out


@pytest.mark.parametrize("shape,r,share,dtype", [
    ((1, 1), 1, 0.6, np.float64), ((1, 40), 2, 0.7, np.float64), ((40, 1), 2, 0.7, np.float32),
    ((150, 90), 3, 0.6, np.float64), ((70, 2100), 3, 0.85, np.float32),
    ((60, 80), 9, 0.3, np.float64)])
def test_planes_at_cells_equal_the_whole_raster_float64_planes(shape, r, share, dtype):
    """Gradients and fits evaluated at the cells asked for (bands, strips, ``where``)
    equal the old whole-raster float64 formulas bit for bit (review: the other tests
    take their planes from the code under test)."""
    from geomatics_toolbox.core.lidar import _planes as P  # noqa: N812
    rng = np.random.default_rng(sum(shape) + r)
    valid = rng.random(shape) < share
    valid[:, : shape[1] // 3] &= rng.random((shape[0], shape[1] // 3)) < 0.3   # ragged holes
    z = (50.0 + np.cumsum(rng.normal(0, 0.5, shape), axis=1)).astype(dtype)
    old = _old_window_planes(z, valid, r, spread=True)
    full = (r * (r + 1) / 3.0) ** 2
    bad = ~(old["det"] > 1e-3 * full) | ~np.isfinite(old["gx"]) | ~np.isfinite(old["gy"])
    ogx, ogy = np.where(bad, 0.0, old["gx"]) / 1.5, np.where(bad, 0.0, old["gy"]) / 1.5
    rr, cc = np.nonzero(rng.random(shape) < 0.4)
    for got in (P.gradient_at(z, valid, r, 1.5, rr, cc), P.gradient_of(z, valid, r, 1.5, rr, cc)):
        np.testing.assert_array_equal(got[0], ogx[rr, cc])
        np.testing.assert_array_equal(got[1], ogy[rr, cc])
    np.testing.assert_array_equal(P.plane_gradient(z, valid, r, 1.5)[0], ogx)
    with np.errstate(invalid="ignore"):
        rms = np.sqrt(np.maximum(old["czz"] - old["gx"] * old["cxz"] - old["gy"] * old["cyz"], 0))
        centre = old["mz"] - old["gx"] * old["mx"] - old["gy"] * old["my"]
    gone = ~(old["det"] > 0.1) | (old["n"] < 6)
    rms[gone], centre[gone] = np.nan, np.nan
    for a, b in zip(P.plane_fit(z, valid, r), (rms, centre, old["gx"], old["gy"])):
        np.testing.assert_array_equal(a, b)
    where = rng.random(shape) < 0.5
    mask, (c, gx, gy, extra) = P.plane_fit_where(
        z, valid, r, lambda rows, at, rms_, centre_, gx_, gy_: (np.isfinite(rms_), rms_), where)
    want = where & np.isfinite(rms)
    np.testing.assert_array_equal(mask, want)
    for a, b in zip((c, gx, gy, extra), (centre, old["gx"], old["gy"], rms)):
        np.testing.assert_array_equal(a, b[want])

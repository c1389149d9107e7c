"""Steps of the recommended filter: detrending before the opening, continuity growing."""
from __future__ import annotations

import numpy as np
import pytest
from scipy import ndimage

from geomatics_toolbox.core.errors import InputError
from geomatics_toolbox.core.lidar import _raster as R  # noqa: N812
from geomatics_toolbox.core.lidar import recommended as rec

CELL = 1.0


def _grid(n=300):
    return R.Grid(0.0, 0.0, CELL, n, n)


def _cols_rows(n=300):
    return np.meshgrid(np.arange(n, dtype=float), np.arange(n, dtype=float))


def test_trend_removes_a_plane_and_keeps_a_roof_on_the_downhill_side():
    """A plane's trend is the plane; on a 0.3 hillside, a 14 m roof at the uphill level
    stands above the detrended terrain on its downhill side by its wall height."""
    c, r = _cols_rows()
    z = 100.0 + 0.3 * r
    roof = (np.abs(c - 150) < 7) & (np.abs(r - 150) < 7)
    z_b = np.where(roof, 100.0 + 0.3 * 157.0, z)
    opt = rec.RecommendedOptions()
    flat = z - rec.trend_surface(z, _grid(), opt)
    inner = (slice(140, 160), slice(140, 160))
    assert np.ptp(flat[inner]) < 1e-6                    # a plane's trend is the plane
    det = z_b - rec.trend_surface(z_b, _grid(), opt)
    ground_level = np.median(det[135:140, 140:160])      # just downhill of the building
    assert det[144, 150] - ground_level == pytest.approx(0.3 * 13, abs=0.6)
    # the opening (flat structuring element, now tilted along the trend) still flags
    # the part of the roof standing more than 2.6 m above the detrended terrain
    obj = rec.progressive_objects(det, CELL, 18.0, 0.15, lambda f: None)
    assert obj[roof & (det - ground_level > 2.6)].all()
    inner_terrain = ~roof & (np.abs(c - 150) > 12) & (np.abs(r - 150) < 100)
    assert not obj[inner_terrain].any()


def _ridge_and_box():
    """Flat ground with a rounded ridge (1.5 m high, 20 m wide) flagged as object, and a
    6 m box with walls, also flagged."""
    c, r = _cols_rows(120)
    ridge = np.clip(1.5 * (1.0 - ((c - 40.0) / 10.0) ** 2), 0.0, None)
    z = 100.0 + ridge
    box = (np.abs(c - 90) < 6) & (np.abs(r - 60) < 6)
    z[box] = 106.0
    obj = (ridge > 0.6) | box
    return z, obj, box, ridge


def test_grow_accepts_a_continuous_crest_and_not_a_walled_box():
    z, obj, box, ridge = _ridge_and_box()
    skip = np.zeros_like(obj)
    dtm = np.full(z.shape, 100.0)
    left = rec.grow_ground(z, obj, skip, dtm, CELL, rec.RecommendedOptions())
    assert left[box].all()                               # walls: never grown into
    assert not left[ridge > 0.6].any()                   # the crest is ground again
    off = rec.grow_ground(z, obj, skip, dtm, CELL, rec.RecommendedOptions(grow_iters=0))
    assert np.array_equal(off, obj)


def test_grow_stops_at_the_rise_limit_and_the_iteration_reach():
    z, obj, box, ridge = _ridge_and_box()
    skip = np.zeros_like(obj)
    low_dtm = np.full(z.shape, 99.0)                     # crest 2.5 m above: beyond 2 m
    left = rec.grow_ground(z, obj, skip, low_dtm, CELL, rec.RecommendedOptions())
    assert left[(ridge > 1.0)].all() and not left[(ridge > 0.6) & (ridge < 0.9)].any()
    one = rec.grow_ground(z, obj, skip, np.full(z.shape, 100.0), CELL,
                          rec.RecommendedOptions(grow_iters=1, grow_window=1.0))
    assert 0 < (obj & ~one).sum() < (obj & ~box).sum()   # one step reaches one ring


def test_new_options_are_validated():
    with pytest.raises(InputError, match="trend_window"):
        rec.RecommendedOptions(trend_window=-1.0)


def test_hole_fill_neighbours_do_not_depend_on_tree_order():
    """Equidistant lattice cells: the 12 chosen and their order depend on the offsets
    only (review G2: a KD-tree's own tie order follows the raster's extent)."""
    from scipy.spatial import cKDTree

    from geomatics_toolbox.core.lidar import _lattice_knn as K  # noqa: N812
    rng = np.random.default_rng(3)
    lat = np.unique(rng.integers(0, 40, size=(300, 2)), axis=0)
    q = rng.integers(0, 40, size=(200, 2))
    ref = K._knn(cKDTree(lat), q, 12, lat)
    for seed in range(3):
        perm = np.random.default_rng(seed).permutation(len(lat))
        got = K._knn(cKDTree(lat[perm]), q, 12, lat[perm])
        for a, b in zip(ref[:3], got[:3]):               # d2, col and row offsets
            np.testing.assert_array_equal(a, b)
        np.testing.assert_array_equal(lat[perm][got[3]], lat[ref[3]])
    d2 = ref[0]
    brute = np.sort(((lat[None, :, :] - q[:, None, :]) ** 2).sum(-1), axis=1)[:, :12]
    np.testing.assert_array_equal(d2, brute)             # the 12 nearest distances


@pytest.mark.parametrize("k", [1, 5, 12, 40, 110])
def test_lattice_scan_finds_the_kd_trees_neighbours(k):
    """scan_offsets visits the offsets in the tree's order: same cells, same order, same
    indices as the KD-tree search (_knn) for every hole cell it completes, and the deep
    hole cells it leaves (beyond SCAN_D2) are those whose k-th border is farther; the
    Near of the whole lattice and of bands of rows (the tree for those) are _knn's."""
    from scipy.spatial import cKDTree

    from geomatics_toolbox.core.lidar import _lattice_knn as K  # noqa: N812
    rng = np.random.default_rng(k)
    valid = rng.random((150, 170)) < 0.4
    valid[20:110, 30:140] = False                        # cells up to 45 from a border
    valid[0:3, :] = True                                 # borders on the raster's edge
    ring = valid & ndimage.binary_dilation(~valid, structure=np.ones((3, 3), bool))
    rr, cc = np.nonzero(ring)
    lat = np.column_stack((cc, rr)).astype(np.float64)
    hr, hc = np.nonzero(~valid)
    ref = K._knn(cKDTree(lat), np.column_stack((hc, hr)), k, lat)
    done, o, j = K.scan_offsets(K.scan_lattice(ring), hr, hc, k)
    got = [K.OFFSETS_F[2][o], K.OFFSETS_F[0][o], K.OFFSETS_F[1][o], j]    # d2, dc, dr, j
    assert 0 < np.count_nonzero(~done) < done.size      # both paths are exercised
    for a, b in zip(ref, got):
        assert a.dtype == b.dtype
        np.testing.assert_array_equal(a[done], b)
    assert (ref[0][~done, -1] > K.SCAN_D2).all()
    trees = []
    both = K.near_offsets(K.scan_lattice(ring), hr, hc, k, trees).arrays()
    assert len(trees) == 2                               # the tree built for the deep cells
    for a, b in zip(ref, both):
        np.testing.assert_array_equal(a, b)
    for rows in (1, 7, 64):                              # lattices of a few rows at a time
        K.SCAN_ROWS, keep = rows, K.SCAN_ROWS
        try:
            trees = []
            banded = K.Scan(ring).near(hr, hc, k, trees).arrays()
        finally:
            K.SCAN_ROWS = keep
        assert len(trees) == 2                           # the tree of the whole ring
        for a, b in zip(ref, banded):
            np.testing.assert_array_equal(a, b)


def test_fill_and_box_mean_of_a_crop_equal_the_full_raster_inside():
    """A raster cut at any corner (a catalog chunk) fills and box-averages to the same
    values as the whole raster, bit for bit, away from the cut."""
    rng = np.random.default_rng(5)
    z = 100.0 + rng.normal(0, 3, (200, 230)).cumsum(axis=1) * 0.01
    valid = rng.random(z.shape) < 0.15
    full = R.fill(np.where(valid, z, np.nan), valid, (0, 0))
    box = R.box_mean(full, 11)
    for r0, c0 in ((64, 128), (37, 91)):
        sub = np.s_[r0:, c0:]
        part = R.fill(np.where(valid, z, np.nan)[sub], valid[sub], (r0, c0))
        inner = np.s_[40:-40, 40:-40]
        np.testing.assert_array_equal(part[inner], full[sub][inner])
        np.testing.assert_array_equal(R.box_mean(part, 11)[inner], box[sub][inner])
    for r0, c0 in ((3, 5), (7, 1)):                          # any offset, same lattice
        sub = np.s_[r0:, c0:]
        np.testing.assert_array_equal(R.box_mean(full[sub], 11)[20:-20, 20:-20],
                                      box[sub][20:-20, 20:-20])


@pytest.mark.parametrize("hole_band", [1 << 20, 1000])
def test_fill_cache_gives_the_values_of_a_fresh_fill(hole_band, monkeypatch):
    """Successive fills sharing a cache (the refine passes) equal fresh fills bit for bit,
    and the cache is really used (most hole cells kept from the previous call); the
    holes listed band by band (bands of 1000 cells: 5 rows) keep the same."""
    from geomatics_toolbox.core.lidar import _surface as S  # noqa: N812
    monkeypatch.setattr(S, "HOLE_BAND", hole_band)
    rng = np.random.default_rng(11)
    z = 50.0 + rng.normal(0, 2, (180, 210)).cumsum(axis=0) * 0.05
    valid = rng.random(z.shape) < 0.55
    valid[60:90, 100:140] = False                                  # a building-sized hole
    need = rng.random(z.shape) < 0.9
    cache, kept = {}, []
    real = S._keeper

    def spy(*a):
        keep = real(*a)
        kept.append(0)
        if keep is None:
            return None

        def counted(hr, hc):
            ok = keep(hr, hc)
            kept[-1] += int(ok.sum())
            return ok
        return counted

    monkeypatch.setattr(S, "_keeper", spy)
    for step in range(4):
        if step:                                     # a few cells change, as in refine
            flip = rng.random(z.shape) < 0.002
            valid ^= flip
            z = np.where(rng.random(z.shape) < 0.002, z + 0.3, z)
        got = S.tangent_fill(z, valid, 1.0, need=need, cache=cache)
        ref = S.tangent_fill(z, valid, 1.0, need=need)
        np.testing.assert_array_equal(got, ref)
    kept = kept[0::2]                                    # the calls with the cache
    assert kept[0] == 0 and min(kept[1:]) > 0.3 * np.count_nonzero(~valid & need)


def test_gradient_by_bands_equals_the_whole_raster():
    """gradient_at (bands of rows with a margin) gives plane_gradient's values bit for bit,
    whatever the band size, next to holes and at the raster's edges."""
    from geomatics_toolbox.core.lidar import _planes as P  # noqa: N812
    from geomatics_toolbox.core.lidar import _surface as S  # noqa: N812
    rng = np.random.default_rng(2)
    z = 300.0 + rng.normal(0, 1, (230, 170)).cumsum(axis=1) * 0.1
    valid = rng.random(z.shape) < 0.6
    gx, gy = S.plane_gradient(z, valid, 3, 1.5)
    rr, cc = np.nonzero(valid)
    band, cells = P.BAND, P.BAND_CELLS
    try:
        for P.BAND, P.BAND_CELLS in ((7, 0), (50, 0), (256, 0), (1, 9000)):
            bx, by = S.gradient_at(z, valid, 3, 1.5, rr, cc)
            np.testing.assert_array_equal(bx, gx[rr, cc])
            np.testing.assert_array_equal(by, gy[rr, cc])
    finally:
        P.BAND, P.BAND_CELLS = band, cells


def test_plane_fit_by_bands_equals_the_whole_raster():
    """plane_fit in bands of rows gives the whole raster's rms, centre and gradients."""
    from geomatics_toolbox.core.lidar import _planes as P  # noqa: N812
    from geomatics_toolbox.core.lidar import _surface as S  # noqa: N812
    rng = np.random.default_rng(4)
    z = 80.0 + rng.normal(0, 1, (140, 120)).cumsum(axis=0) * 0.2
    valid = rng.random(z.shape) < 0.7
    ref = S._plane_fit(z, valid, 3)
    band, cells = P.BAND, P.BAND_CELLS
    try:
        for P.BAND, P.BAND_CELLS in ((5, 0), (33, 0), (256, 0), (1, 5000)):
            for a, b in zip(S.plane_fit(z, valid, 3), ref):
                np.testing.assert_array_equal(a, b.reshape(z.shape))
    finally:
        P.BAND, P.BAND_CELLS = band, cells


def test_gradient_of_few_cells_equals_the_whole_raster():
    """gradient_of (the cells' own windows side by side in a strip) gives plane_gradient's
    values bit for bit, at the raster's edges and corners, next to NaN holes, for any
    strip length and window radius; the window planes reuse their row passes exactly."""
    from geomatics_toolbox.core.lidar import _planes as P  # noqa: N812
    from geomatics_toolbox.core.lidar import _surface as S  # noqa: N812
    rng = np.random.default_rng(4)
    strip = P.STRIP
    try:
        for r in (1, 2, 3, 5):
            z = 300.0 + rng.normal(0, 1, (90, 120)).cumsum(axis=1) * 0.1
            z[rng.random(z.shape) < 0.3] = np.nan
            valid = ~np.isnan(z) & (rng.random(z.shape) < 0.8)
            gx, gy = S.plane_gradient(z, valid, r, 1.5)
            rr, cc = np.nonzero(rng.random(z.shape) < 0.3)
            rr, cc = np.r_[rr, 0, 0, 89, 89], np.r_[cc, 0, 119, 0, 119]
            for P.STRIP in (1, 37, 4096):
                bx, by = S.gradient_of(z, valid, r, 1.5, rr, cc)
                np.testing.assert_array_equal(bx, gx[rr, cc])
                np.testing.assert_array_equal(by, gy[rr, cc])
    finally:
        P.STRIP = strip


def test_separable_square_dilations_equal_binary_dilation():
    """The hole ring (3 x 3 minimum of the valid cells) and the growing front (square
    maxima) are the cells binary_dilation gives, at the raster's edges too."""
    from geomatics_toolbox.core.lidar import _surface as S  # noqa: N812
    rng = np.random.default_rng(8)
    for share in (0.01, 0.3, 0.9):
        m = rng.random((61, 47)) < share
        ring = m & ndimage.binary_dilation(~m, structure=np.ones((3, 3), bool))
        np.testing.assert_array_equal(
            m & ~ndimage.minimum_filter(m, size=3, mode="nearest"), ring)
        np.testing.assert_array_equal(S._ring(m), ring)          # by shifted ANDs
        for size in (3, 7, 13, 99):
            want = ndimage.binary_dilation(m, structure=np.ones((size, size), bool))
            np.testing.assert_array_equal(
                ndimage.maximum_filter(m, size=size, mode="constant"), want)
    for shape in ((1, 1), (1, 5), (4, 1), (2, 2)):
        m = rng.random(shape) < 0.5
        np.testing.assert_array_equal(
            S._ring(m), m & ~ndimage.minimum_filter(m, size=3, mode="nearest"))


def test_grow_ground_equals_the_plain_whole_raster_loop():
    """grow_ground (planes at the object cells, the misfits of every offset at once)
    accepts exactly the cells of the plain loop over the window's offsets with scipy's
    maximum filter, up to the raster's edges, also where the misfit refuses cells."""
    import dataclasses

    from geomatics_toolbox.core.lidar import _surface as S  # noqa: N812
    for seed, shape, iters in ((1, (90, 130), 10), (2, (40, 130), 10), (3, (64, 100), 10),
                               (1, (90, 130), 1), (4, (50, 120), 2)):
        opt = dataclasses.replace(rec.RecommendedOptions(), grow_iters=iters)
        rng = np.random.default_rng(seed)
        r, c = np.mgrid[:shape[0], :shape[1]]
        z = 100 + 0.02 * c + 0.2 * np.sin(r / 9.0) + rng.normal(0, 0.12, shape)
        skip = rng.random(shape) < 0.1
        obj = (rng.random(shape) < 0.7) & ~skip          # sparse ground: misfits decide
        obj[10:30, 5:40] = True                          # a wide object area (crest)
        dtm = z - 0.1
        z[22:38, 45:62] += 8.0                           # a building: stays an object
        obj[22:38, 45:62] = True
        z[3:40, 75:120] += 0.6                           # a low step: the misfit decides
        obj[3:40, 75:120] = True
        obj &= ~skip
        z[skip] = np.nan
        got = S.grow_ground(z, obj.copy(), skip, dtm, 1.0, opt)
        ground = ~(obj | skip)
        rad = 3
        rms, centre, gx, gy = S.plane_fit(z, ~skip, rad)
        with np.errstate(invalid="ignore"):
            steep = np.hypot(gx, gy)
            tol = opt.grow_tol + opt.scaler * steep
            cand = (obj & ~skip & (rms <= opt.grow_rms) & (np.abs(z - centre) <= tol)
                    & (steep <= opt.grow_max_slope) & (z - dtm <= opt.grow_max_rise))
        front = cand & ndimage.maximum_filter(ground, size=7, mode="constant")
        for _ in range(opt.grow_iters):
            rr, cc = np.nonzero(front)
            if rr.size == 0:
                break
            best = np.full(rr.size, np.inf)
            for dr in range(-rad, rad + 1):
                for dc in range(-rad, rad + 1):
                    if dr == dc == 0:
                        continue
                    nr, nc = rr + dr, cc + dc
                    inb = (nr >= 0) & (nr < shape[0]) & (nc >= 0) & (nc < shape[1])
                    nr, nc = np.where(inb, nr, 0), np.where(inb, nc, 0)
                    e = np.abs(z[nr, nc] - centre[rr, cc] - gx[rr, cc] * dc - gy[rr, cc] * dr)
                    best = np.minimum(best, np.where(inb & ground[nr, nc], e, np.inf))
            acc = best <= tol[rr, cc]
            front[:] = False
            front[rr[acc], cc[acc]] = True
            ground |= front
            front = cand & ~ground & ndimage.maximum_filter(front, size=7, mode="constant")
        want = obj & ~ground
        assert 0 < want.sum() < obj.sum() - 50            # cells were grown into
        if iters < 10:                                    # candidates refused by the misfit
            assert (cand & want).sum() > 20
        np.testing.assert_array_equal(got, want)


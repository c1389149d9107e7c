"""The catalog summary's cell counts (core/lidar/_summary.py): the blocked count of a
small box equals the plain whole-array count, bit for bit, on any lattice position."""
from __future__ import annotations

import numpy as np
import pytest

from geomatics_toolbox.core.lidar import _summary as S  # noqa: N812


def _plain(x, y, cell, shared=()):
    """The whole-array expressions (reference)."""
    ix = np.floor(x / cell).astype(np.int64)
    iy = np.floor(y / cell).astype(np.int64)
    x0, y0 = int(ix.min()), int(iy.min())
    ny = int(iy.max()) - y0 + 1
    occ, cnt = np.unique((ix - x0) * ny + (iy - y0), return_counts=True)
    cx, cy = occ // ny + x0, occ % ny + y0
    edge = np.zeros(occ.size, bool)
    for b in shared:
        edge |= ((cx * cell <= b[2]) & ((cx + 1) * cell >= b[0])
                 & (cy * cell <= b[3]) & ((cy + 1) * cell >= b[1]))
    values, cells = np.unique(cnt[~edge], return_counts=True)
    return {"hist": [values.tolist(), cells.tolist()],
            "keys": [cx[edge].tolist(), cy[edge].tolist()], "counts": cnt[edge].tolist()}


@pytest.mark.parametrize("block", [7, 1 << 16])
@pytest.mark.parametrize("origin,side", [((0.0, 0.0), 300.0), ((-1234.5, 5e6), 800.0),
                                         ((7e5, -3e6), 20000.0)])
def test_cell_counts_equal_the_plain_count(monkeypatch, block, origin, side):
    monkeypatch.setattr(S, "_BLOCK", block)
    rng = np.random.default_rng(1)
    n = 30000
    x = origin[0] + rng.uniform(0, side, n)
    y = origin[1] + rng.uniform(0, side / 3, n)
    x[:5] = origin[0] + 5.0 * np.arange(5)            # points on cell edges
    shared = [(origin[0] + side / 2, origin[1], origin[0] + side, origin[1] + 10.0)]
    for box in ((), shared):
        got = S.cell_counts(x, y, 5.0, box)
        assert got == _plain(x, y, 5.0, box)
    assert S.cell_counts(x, y, 5.0) == S.cloud_summary(x, y, counts=True)["cells"]


def _water_plain(x, y, z, density, median5, sparse=0.25, flat=0.15, min_area=400.0):
    """water_candidates' whole-array expressions (reference)."""
    from scipy import ndimage
    cell = max(2.0, 3.0 / np.sqrt(density))
    ix = np.floor(x / cell).astype(np.int64)
    iy = np.floor(y / cell).astype(np.int64)
    ix -= ix.min()
    iy -= iy.min()
    shape = (int(iy.max()) + 1, int(ix.max()) + 1)
    idx = iy * shape[1] + ix
    size = shape[0] * shape[1]
    cnt = np.bincount(idx, minlength=size)
    cand = (cnt > 0) & (cnt < sparse * median5 * (cell / S.DENSITY_CELL) ** 2)
    sel = np.flatnonzero(cand[idx])
    zlo = np.full(size, np.inf)
    np.minimum.at(zlo, idx[sel], z[sel])
    zhi = np.full(size, -np.inf)
    np.maximum.at(zhi, idx[sel], z[sel])
    box = np.ones((3, 3), bool)
    lo = ndimage.minimum_filter(zlo.reshape(shape), footprint=box, mode="constant",
                                cval=np.inf)
    hi = ndimage.maximum_filter(zhi.reshape(shape), footprint=box, mode="constant",
                                cval=-np.inf)
    n3 = ndimage.uniform_filter(np.where(cand, cnt, 0).reshape(shape).astype(float), 3,
                                mode="constant") * 9
    cand = cand.reshape(shape) & (hi - lo < flat) & (n3 >= 3)
    lab, k = ndimage.label(cand, structure=box)
    keep = np.bincount(lab.ravel(), minlength=k + 1) * cell * cell >= min_area
    keep[0] = False
    return keep[lab.ravel()[idx]]


@pytest.mark.parametrize("chunk", [7, 1 << 16])
def test_water_candidates_by_blocks_equal_the_whole_array_test(monkeypatch, chunk):
    """The lake scene (candidates on the lake) and a dry one, blocks of any size."""
    from geomatics_toolbox.core.lidar import _raster as R  # noqa: N812
    from geomatics_toolbox.core.lidar._recommended_filter import water_candidates
    from geomatics_toolbox.synthetic import landscapes
    monkeypatch.setattr(R, "CHUNK", chunk)
    for scene in (landscapes.lake(seed=1), landscapes.steep_cliffs(seed=2)):
        x, y, z = scene.x, scene.y, scene.z
        v = S.recommended_values(S.cloud_summary(x, y, counts=True))
        want = _water_plain(x, y, z, v["density"], v["median5"])
        got = water_candidates(x, y, z)
        assert np.array_equal(got, want)
    assert want.sum() == 0 and got.dtype == bool
    lake = landscapes.lake(seed=1)
    assert water_candidates(lake.x, lake.y, lake.z).sum() > 1000


def test_histogram_is_sparse_and_tiles_merge_to_the_whole_cloud():
    """A tile of one position is one cell of n points (not a list n long); two tiles that
    share cells along their common edge merge to the counts of the cloud as one."""
    one = S.cell_counts(np.full(200_000, 1000.2), np.full(200_000, 2000.7), 5.0)
    assert one["hist"] == [[200_000], [1]] and one["keys"] == [[], []]
    rng = np.random.default_rng(3)
    x, y = rng.uniform(0, 1000, 50_000), rng.uniform(0, 400, 50_000)
    x[:200] = 502.5                                   # a cell split by the tiles' edge
    left, right = x < 502.6, x >= 502.6
    boxes = [(0.0, 0.0, 502.6, 400.0), (502.6, 0.0, 1000.0, 400.0)]
    parts = [S.cloud_summary(x[m], y[m], counts=True) for m in (left, right)]
    parts[0]["cells"] = S.cell_counts(x[left], y[left], 5.0, [boxes[1]])
    parts[1]["cells"] = S.cell_counts(x[right], y[right], 5.0, [boxes[0]])
    assert parts[0]["cells"]["counts"] and parts[1]["cells"]["counts"]
    whole = S.recommended_values(S.cloud_summary(x, y, counts=True))
    assert S.recommended_values(S.merge(parts)) == whole
    ix = np.floor(x / 5.0).astype(np.int64) * 1000 + np.floor(y / 5.0).astype(np.int64)
    cnt = np.unique(ix, return_counts=True)[1]
    assert whole["median5"] == float(np.median(cnt))
    assert whole["density"] == x.size / (cnt.size * 25.0)


def test_a_given_extent_gives_the_same_summary_water_test_grid_and_classes():
    """The recommended filter takes the kept points' extent once (``_checks.bounds``) and
    hands it to its summary, water test, check and grid: the same results as each
    taking it again (the lake scene, 10 % of the points left out, some far outside)."""
    from geomatics_toolbox.core.lidar import _raster as R  # noqa: N812
    from geomatics_toolbox.core.lidar import recommended as rec
    from geomatics_toolbox.core.lidar._recommended_filter import water_candidates
    from geomatics_toolbox.synthetic import landscapes
    s = landscapes.lake(seed=1)
    x, y, z = (np.array(a, np.float64) for a in (s.x, s.y, s.z))
    keep = np.random.default_rng(4).random(x.size) > 0.1
    x[np.flatnonzero(~keep)[:50]] -= 5000.0            # left-out points far outside
    ext = R.bounds(x, y, keep)
    assert S.cloud_summary(x, y, counts=True, keep=keep, extent=ext) == \
        S.cloud_summary(x, y, counts=True, keep=keep)
    assert np.array_equal(water_candidates(x, y, z, keep=keep, extent=ext),
                          water_candidates(x, y, z, keep=keep))
    assert R.Grid.around(x, y, 1.0, (3.0, 4.0), keep, ext) == \
        R.Grid.around(x, y, 1.0, (3.0, 4.0), keep)
    assert np.array_equal(rec.classify(x, y, z, keep=keep, extent=ext)[keep],
                          rec.classify(x, y, z, keep=keep)[keep])


@pytest.mark.parametrize("counts", [False, True])
def test_an_empty_cloud_or_none_kept_summarises_to_no_points(counts):
    """No point (or no point kept) gives n 0 and no corner, not a reduction error (review:
    the corner was taken before the count was checked)."""
    empty = S.cloud_summary(np.empty(0), np.empty(0), counts=counts)
    none_kept = S.cloud_summary(np.arange(3.0), np.arange(3.0), keep=np.zeros(3, bool),
                              counts=counts)
    for s in (empty, none_kept):
        assert s["n"] == 0 and s["corner"] is None
        if counts:
            assert s["water"] == 0 and s["cells"]["counts"] == []

"""Per-point raster look-ups of the recommended filter (core/lidar/_raster.PointCells).

The look-ups run in blocks of points and the refine passes relabel only the points that
read a changed cell; both must give bit for bit what the plain whole-array expressions
give (the filter's class sha1 goldens rest on it).
"""
from __future__ import annotations

import numpy as np
import pytest

from geomatics_toolbox.core.lidar import _raster as R  # noqa: N812
from geomatics_toolbox.core.lidar import recommended as rec


def _plain(x, y, grid):
    """The whole-array expressions the blocked code replaced (reference)."""
    col = np.minimum(((x - grid.x0) / grid.cell).astype(np.int64), grid.cols - 1)
    row = np.minimum(((y - grid.y0) / grid.cell).astype(np.int64), grid.rows - 1)
    fx = np.clip((x - grid.x0) / grid.cell - 0.5, 0.0, grid.cols - 1.0)
    c0 = np.minimum(fx.astype(np.int64), max(grid.cols - 2, 0))
    fy = np.clip((y - grid.y0) / grid.cell - 0.5, 0.0, grid.rows - 1.0)
    r0 = np.minimum(fy.astype(np.int64), max(grid.rows - 2, 0))
    return (row * grid.cols + col, r0 * grid.cols + c0, (fx - c0).astype(np.float32),
            (fy - r0).astype(np.float32))


def _plain_bilinear(pc, raster):
    g, flat, i = pc.grid, raster.ravel(), pc.i00
    c1 = 1 if g.cols > 1 else 0
    r1 = g.cols if g.rows > 1 else 0
    top = flat[i] + (flat[i + c1] - flat[i]) * pc.fx
    bot = flat[i + r1] + (flat[i + r1 + c1] - flat[i + r1]) * pc.fx
    return top + (bot - top) * pc.fy


def _cloud(n, w, h, seed):
    rng = np.random.default_rng(seed)
    x, y = rng.uniform(0, w, n), rng.uniform(0, h, n)
    x[:3], y[:3] = w, h                           # points on the far edges
    return x, y


@pytest.mark.parametrize("chunk", [7, 1000, 1 << 16])
@pytest.mark.parametrize("shape", [(300.0, 200.0), (300.0, 0.4), (0.3, 50.0)])
def test_blocks_equal_the_whole_array_expressions(monkeypatch, chunk, shape):
    monkeypatch.setattr(R, "CHUNK", chunk)
    x, y = _cloud(5000, *shape, seed=1)
    grid = R.Grid.around(x, y, 0.7)
    pc = R.PointCells(x, y, grid)
    idx, i00, fx, fy = _plain(x, y, grid)
    np.testing.assert_array_equal(pc.idx, idx)
    np.testing.assert_array_equal(grid.index(x, y), idx)
    np.testing.assert_array_equal(pc.i00, i00)
    assert pc.fx.dtype == np.float32 and np.array_equal(pc.fx, fx)
    assert pc.fy.dtype == np.float32 and np.array_equal(pc.fy, fy)
    raster = np.random.default_rng(2).normal(size=(grid.rows, grid.cols)) * 100
    want = _plain_bilinear(pc, raster)
    got = pc.bilinear(raster)
    assert np.array_equal(got.view(np.int64), want.view(np.int64))        # same bits
    sub = np.flatnonzero(np.arange(x.size) % 3 == 1)
    assert np.array_equal(pc.bilinear(raster, sub), want[sub])
    assert np.array_equal(pc.nearest(raster, sub), raster.ravel()[idx[sub]])
    z = np.round(np.random.default_rng(3).normal(size=x.size), 1)   # ties within cells
    for mask in (None, np.arange(x.size) % 4 != 0):  # minima in blocks of whole cells
        m = np.ones(x.size, bool) if mask is None else mask
        want = np.full(grid.rows * grid.cols, np.inf)
        np.minimum.at(want, idx[m], z[m])
        want[np.isinf(want)] = np.nan
        got = pc.cell_min(z, mask)
        assert np.array_equal(got.ravel(), want, equal_nan=True)


@pytest.mark.parametrize("shape", [(120.0, 90.0), (300.0, 0.4), (0.3, 50.0)])
def test_reading_lists_every_point_whose_inputs_changed(shape):
    """Brute force: a point is listed iff one of its 4 bilinear cells or its slope
    cell is flagged (few flags: only the points of the cells near them are tested;
    many: every point), flags on the grid's edges and corners included."""
    x, y = _cloud(20000, *shape, seed=4)
    pc = R.PointCells(x, y, R.Grid.around(x, y, 1.0 if shape[0] > 100 else 0.05))
    rng = np.random.default_rng(5)
    g = pc.grid
    size = g.rows * g.cols
    c1 = 1 if g.cols > 1 else 0
    r1 = g.cols if g.rows > 1 else 0
    for share in (0.0, 0.0005, 0.001, 0.05, 0.3):
        cells = rng.random(size) < share
        slope_cells = rng.random(size) < share
        if 0 < share < 0.01:
            cells[[0, g.cols - 1, size - g.cols, size - 1]] = True       # the corners
            slope_cells[size - 1] = True
        want = np.zeros(x.size, bool)
        for c in (pc.i00, pc.i00 + c1, pc.i00 + r1, pc.i00 + r1 + c1):
            want |= cells[c]
        want |= slope_cells[pc.idx]
        got = pc.reading(cells.reshape(g.rows, g.cols), slope_cells.reshape(g.rows, g.cols))
        np.testing.assert_array_equal(got, np.flatnonzero(want))


def test_relabelling_changed_points_only_gives_the_full_labels():
    """Over a sequence of DTMs changed in a few places (as the refine passes), the
    incremental labels equal labelling every point; labels do change on the way."""
    rng = np.random.default_rng(6)
    x, y = _cloud(30000, 150.0, 100.0, seed=7)
    z = 20 + 0.05 * x + rng.normal(0, 0.4, x.size)
    pc = R.PointCells(x, y, R.Grid.around(x, y, 1.0))
    opt = rec.derive(x, y, rec.RecommendedOptions())
    dtm = 20 + 0.05 * (pc.grid.x0 + 0.5 + np.arange(pc.grid.cols))[None, :] + np.zeros(
        (pc.grid.rows, 1))
    last: dict = {}
    first = rec.label_points(z, dtm, pc, opt, last)
    assert np.array_equal(first, rec.label_points(z, dtm, pc, opt))
    prev = first
    for step in range(4):
        dtm = dtm.copy()
        r, c = rng.integers(0, pc.grid.rows, 40), rng.integers(0, pc.grid.cols, 40)
        dtm[r, c] += rng.normal(0, 0.8, 40)
        dtm[0, 0] = np.nan if step == 2 else dtm[0, 0]
        got = rec.label_points(z, dtm, pc, opt, last)
        full = rec.label_points(z, dtm, pc, opt)
        np.testing.assert_array_equal(got, full)
        assert (got != prev).any()
        prev = got


def _bits(a):
    return a.view(np.int64 if a.dtype == np.float64 else np.int32)


@pytest.mark.parametrize("base", [None, 64.0])
@pytest.mark.parametrize("shape", [(300.0, 200.0), (300.0, 0.4)])
def test_cell_min_since_an_earlier_mask_equals_a_new_computation(shape, base):
    """The refine passes take the minima again only at the cells of the points that
    turned ground or not: the same bits as a new computation, including cells that lose
    their last masked point, gain their first one, or whose only points all flip."""
    x, y = _cloud(20000, *shape, seed=5)
    grid = R.Grid.around(x, y, 0.7)
    pc = R.PointCells(x, y, grid)
    rng = np.random.default_rng(6)
    z = rng.normal(100, 3, x.size)
    old = rng.random(x.size) < 0.5
    first = pc.cell_min(z, old, base)
    for share in (0.0, 0.001, 0.05, 1.0):
        new = old.copy()
        flip = rng.random(x.size) < share
        new[flip] = ~new[flip]
        want = pc.cell_min(z, new, base)
        got = pc.cell_min(z, new, base, since=(first, ~np.isnan(first), np.flatnonzero(flip)))
        assert got.dtype == want.dtype and np.array_equal(_bits(got), _bits(want))
    gone = old & (pc.idx == pc.idx[np.flatnonzero(old)[0]])            # a cell loses all
    got = pc.cell_min(z, old & ~gone, base, since=(first, ~np.isnan(first), np.flatnonzero(gone)))
    assert np.isnan(got.ravel()[pc.idx[np.flatnonzero(gone)[0]]])
    assert np.array_equal(_bits(got), _bits(pc.cell_min(z, old & ~gone, base)))


def test_cell_min_after_height_base_reuses_its_minima_only_for_the_same_heights():
    x, y = _cloud(5000, 80.0, 60.0, seed=8)
    z = np.random.default_rng(9).normal(1500, 20, x.size)
    pc, fresh = (R.PointCells(x, y, R.Grid.around(x, y, 0.7)) for _ in range(2))
    base = pc.height_base(z)
    assert base == 1024.0
    other = z + 1.0                                   # other heights: computed anew
    assert np.array_equal(_bits(pc.cell_min(other, base=base)),
                          _bits(fresh.cell_min(other, base=base)))
    pc.height_base(z)
    got = pc.cell_min(z, base=base)
    assert got.dtype == np.float32
    assert np.array_equal(_bits(got), _bits(fresh.cell_min(z, base=base)))
    assert pc._minima is None                         # used once, then dropped
    assert np.array_equal(_bits(pc.cell_min(z, base=base)), _bits(got))


@pytest.mark.parametrize("shape", [(1, 30), (30, 1), (2, 2), (40, 37)])
def test_read_mask_is_every_cell_a_point_reads(shape):
    """The four bilinear corners of every point (scattered one by one before) and the
    occupied cells with their 4-neighbours; with ``keep``, those of the kept points."""
    rows, cols = shape
    rng = np.random.default_rng(rows * cols)
    x, y = rng.uniform(0, cols, 400), rng.uniform(0, rows, 400)
    keep = rng.random(400) < 0.3
    for k in (None, keep):
        pc = R.PointCells(x, y, R.Grid(0.0, 0.0, 1.0, rows, cols), k)
        i00 = pc.i00 if k is None else pc.i00[k]
        m = np.zeros(rows * cols, bool)
        c1, r1 = (1 if cols > 1 else 0), (cols if rows > 1 else 0)
        for off in (0, c1, r1, r1 + c1):
            m[i00 + off] = True
        cells = pc.cells
        m[cells] = True
        m[cells[cells % cols > 0] - 1] = True
        m[cells[cells % cols < cols - 1] + 1] = True
        m[cells[cells >= cols] - cols] = True
        m[cells[cells < (rows - 1) * cols] + cols] = True
        assert np.array_equal(pc.read_mask().ravel(), m)
        assert m.sum() < m.size or min(shape) <= 2

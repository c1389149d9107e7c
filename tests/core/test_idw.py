"""IDW against GDAL's gdal_grid -a invdistnn (the oracle), grid definition, bad input."""
from __future__ import annotations

import numpy as np
import pytest

from geomatics_toolbox.core.terrain.grid import (
    GridSpec,
    check_memory,
    grid_from_extent,
    grid_from_points,
    grid_like,
)
from geomatics_toolbox.core.terrain.idw import IDW, gdal_quadtree_rank, idw_grid

gdal = pytest.importorskip("osgeo.gdal")
ogr = pytest.importorskip("osgeo.ogr")
gdal.UseExceptions()


def gdal_invdistnn(x, y, z, grid, *, power, max_points, radius, min_points=0):
    """Run gdal.Grid (invdistnn) on an in-memory point layer onto ``grid``."""
    ds = gdal.GetDriverByName("Memory").Create("", 0, 0, 0, gdal.GDT_Unknown)
    lyr = ds.CreateLayer("p", geom_type=ogr.wkbPoint25D)
    defn = lyr.GetLayerDefn()
    for a, b, c in zip(x, y, z):
        f = ogr.Feature(defn)
        g = ogr.Geometry(ogr.wkbPoint25D)
        g.AddPoint(float(a), float(b), float(c))
        f.SetGeometry(g)
        lyr.CreateFeature(f)
    out = gdal.Grid("/vsimem/idw_oracle.tif", ds, format="GTiff",
                    outputType=gdal.GDT_Float64, width=grid.ncols, height=grid.nrows,
                    outputBounds=[grid.xmin, grid.ymax, grid.xmax, grid.ymin],
                    algorithm=(f"invdistnn:power={power}:max_points={max_points}:"
                               f"radius={radius}:min_points={min_points}:nodata=-9999"))
    assert out.GetGeoTransform() == grid.geotransform
    arr = out.GetRasterBand(1).ReadAsArray()
    out = None
    gdal.Unlink("/vsimem/idw_oracle.tif")
    return np.where(arr == -9999, np.nan, arr)


@pytest.fixture(scope="module")
def cloud():
    rng = np.random.default_rng(11)
    n = 2500
    x = rng.uniform(600000, 600090, n)
    y = rng.uniform(3900000, 3900070, n)
    z = 850 + 0.2 * (x - 600000) + 4 * np.sin((y - 3900000) / 9) + rng.normal(0, 0.05, n)
    # a gap (no points) in a corner, and one point exactly on a cell centre
    keep = ~((x > 600070) & (y > 3900050))
    x, y, z = x[keep], y[keep], z[keep]
    x[0], y[0] = 600010.5, 3900020.5
    return x, y, z


@pytest.mark.parametrize("power,max_points,radius,min_points", [
    (2.0, 12, 6.0, 0), (3.0, 8, 4.0, 5), (2.0, 0, 2.5, 0), (2.5, 12, 1.2, 3)])
def test_idw_equals_gdal_invdistnn(cloud, power, max_points, radius, min_points):
    x, y, z = cloud
    grid = grid_from_extent((600000, 600090, 3900000, 3900070), 1.0)
    ref = gdal_invdistnn(x, y, z, grid, power=power, max_points=max_points, radius=radius,
                         min_points=min_points)
    ours = idw_grid(x, y, z, grid, power=power, max_points=max_points, radius=radius,
                    min_points=min_points, fill=True, block_cells=1000)
    assert np.array_equal(np.isnan(ref), np.isnan(ours))
    assert np.isfinite(ref).sum() > 1000
    assert np.nanmax(np.abs(ref - ours)) <= 1e-3
    # the node on a point takes that point's height exactly (GDAL does too)
    r, c = 49, 10
    assert ours[r, c] == z[0] == ref[r, c]


def test_idw_formula_and_exactness():
    x = np.array([0.0, 1.0, 0.0, 3.0])
    y = np.array([0.0, 0.0, 2.0, 3.0])
    z = np.array([1.0, 2.0, 3.0, 4.0])
    interp = IDW(x, y, z, power=2, max_points=3)
    got = interp.predict([0.5], [0.5])[0]
    d2 = np.array([0.5, 0.5, 2.5])            # three nearest: squared distances
    w = 1 / d2
    assert got == pytest.approx((w * z[:3]).sum() / w.sum(), rel=1e-12)
    assert interp.predict([3.0], [3.0])[0] == 4.0
    # min_points not reached -> NaN (never 0)
    sparse = IDW(x, y, z, power=2, max_points=3, radius=1.2, min_points=2)
    assert np.isnan(sparse.predict([2.9], [2.9])[0])


def test_gap_mask_and_fill(cloud):
    x, y, z = cloud
    grid = grid_from_extent((600000, 600090, 3900000, 3900070), 1.0)
    masked = idw_grid(x, y, z, grid, max_points=12, max_distance=3.0)
    filled = idw_grid(x, y, z, grid, max_points=12, fill=True)
    # the empty corner (x > 70, y > 50) is nodata unless asked to fill
    assert np.isnan(masked[2:15, 80:88]).all()
    assert np.isfinite(filled).all()
    assert np.isfinite(masked).mean() > 0.9


def test_grid_alignment_and_georeferencing():
    g = grid_from_points([10.3, 19.9], [5.2, 7.7], 0.5)
    assert (g.xmin, g.xmax, g.ymin, g.ymax) == (10.0, 20.0, 5.0, 8.0)
    assert g.geotransform == (10.0, 0.5, 0.0, 8.0, 0.0, -0.5)
    assert g.x_centers()[0] == 10.25 and g.y_centers()[0] == 7.75
    row, col, inside = g.cell_index(np.array([10.0, 20.0, 20.1]), np.array([8.0, 5.0, 6.0]))
    assert list(row[:2]) == [0, 5] and list(col[:2]) == [0, 19] and list(inside) == [
        True, True, False]
    unaligned = grid_from_extent((10.3, 19.9, 5.2, 7.7), 0.5, align=False)
    assert unaligned.xmin == 10.3 and unaligned.ymax == 7.7
    assert grid_like(g.geotransform, g.shape).extent == g.extent


def test_bad_input_clear_errors():
    x = np.arange(5.0)
    with pytest.raises(ValueError, match=r"Neighbours \(NEIGHBOURS\) is 12"):
        IDW(x, x, x, max_points=12)
    with pytest.raises(ValueError, match="cell_size must be a positive"):
        grid_from_extent((0, 10, 0, 10), 0)
    with pytest.raises(ValueError, match="cell_size must be a positive"):
        grid_from_extent((0, 10, 0, 10), -1)
    with pytest.raises(ValueError, match=r"1,000,000,000 × 1,000,000,000 = .* cells"):
        grid_from_extent((0, 1e7, 0, 1e7), 0.01)      # refused before any memory check
    huge = GridSpec(xmin=0.0, ymax=1e7, cell=0.01, ncols=10**9, nrows=10**9)
    with pytest.raises(ValueError, match=r"would need .*PiB.*available"):
        check_memory(huge)
    with pytest.raises(ValueError, match="would need"):
        idw_grid(x, x, x, huge, max_points=3)
    with pytest.raises(ValueError, match=r"MIN_POINTS = 4\) cannot exceed"):
        IDW(x, x, x, max_points=3, min_points=4)


def test_ties_at_the_cut_off_follow_input_order():
    # four points at the same distance from the node (0.5, 0.5); two are used
    x = np.array([0.0, 1.0, 0.0, 1.0, 5.0])
    y = np.array([0.0, 0.0, 1.0, 1.0, 5.0])
    z = np.array([1.0, 2.0, 3.0, 4.0, 9.0])
    for perm in ([0, 1, 2, 3, 4], [3, 2, 1, 0, 4], [2, 0, 3, 1, 4]):
        p = np.array(perm)
        got = IDW(x[p], y[p], z[p], max_points=2).predict([0.5], [0.5])[0]
        assert got == pytest.approx(z[p][:2].mean())   # the two first in input order


def test_equidistant_neighbours_ordered_like_gdal_quadtree():
    # a regular 0.5 m lattice (plus a few random points): many grid nodes have
    # several points at exactly the same distance at the max_points cut-off
    rng = np.random.default_rng(3)
    gx, gy = np.meshgrid(np.arange(0, 30.01, 0.5), np.arange(0, 20.01, 0.5))
    x = np.concatenate([gx.ravel(), rng.uniform(0, 30, 50).round(2)]) + 700000
    y = np.concatenate([gy.ravel(), rng.uniform(0, 20, 50).round(2)]) + 3000000
    z = rng.normal(100, 2, x.size)
    grid = grid_from_extent((700000.0, 700030.0, 3000000.0, 3000020.0), 0.25)
    for k in (3, 5, 7):
        ref = gdal_invdistnn(x, y, z, grid, power=2, max_points=k, radius=3.0)
        ours = idw_grid(x, y, z, grid, power=2, max_points=k, radius=3.0, fill=True)
        assert np.nanmax(np.abs(ref - ours)) <= 1e-9
        by_index = idw_grid(x, y, z, grid, power=2, max_points=k, radius=3.0, fill=True,
                            tie_order="input")
        assert np.nanmax(np.abs(ref - by_index)) > 1e-3     # the ties do matter here


@pytest.mark.parametrize("kind", ["uniform", "lattice", "coincident", "line"])
def test_quadtree_order_of_a_few_points_equals_the_whole_tree(kind):
    # the tied nodes rank only the points they compare (gdal_quadtree_order); their
    # order must be the one of GDAL's quadtree over every point (gdal_quadtree_rank)
    from scipy.spatial import cKDTree

    from geomatics_toolbox.core.terrain._quadtree import gdal_quadtree_order
    rng = np.random.default_rng(7)
    n = 6000
    if kind == "uniform":
        x, y = rng.uniform(0, 100, n), rng.uniform(0, 40, n)
    elif kind == "lattice":
        x = rng.integers(0, 25, n) * 0.5 + 700000.0
        y = rng.integers(0, 40, n) * 0.5 + 3000000.0
    elif kind == "coincident":            # 2,000 points on one spot: the deepest tree
        x, y = rng.uniform(0, 30, n).round(2), rng.uniform(0, 10, n).round(2)
        x[:2000], y[:2000] = 5.0, 5.0
    else:                                 # zero height: every split along x
        x, y = rng.normal(0, 1, n), np.zeros(n)
    full = gdal_quadtree_rank(x, y)
    tree = cKDTree(np.column_stack([x, y]))
    for m in (1, 9, 300, n):
        ids = np.sort(rng.choice(n, m, replace=False))
        local = gdal_quadtree_order(x, y, ids, tree=tree)
        assert np.array_equal(np.argsort(local), np.argsort(full[ids]))


@pytest.mark.parametrize("tie_order", ["gdal", "xy"])
def test_ties_rank_only_the_tied_points(tie_order):
    rng = np.random.default_rng(3)
    gx, gy = np.meshgrid(np.arange(0, 30.01, 0.5), np.arange(0, 20.01, 0.5))
    x, y = gx.ravel() + 700000, gy.ravel() + 3000000
    x[:-1:5], y[:-1:5] = x[1::5], y[1::5]   # duplicated positions: "xy" orders them by z
    z = rng.normal(100, 2, x.size)
    interp = IDW(x, y, z, max_points=5, radius=3.0, tie_order=tie_order)
    gx, gy = np.meshgrid(700000.125 + 0.25 * np.arange(120), 3000000.125 + 0.25 * np.arange(80))
    d, _ = interp.tree.query(np.column_stack([gx.ravel(), gy.ravel()]), k=6)
    assert (d[:, 5] == d[:, 4]).sum() > 1000        # many nodes tied at the cut-off
    got = interp.predict(gx.ravel(), gy.ravel())
    assert interp._rank is None                     # the whole quadtree never built
    full = interp.tie_rank()
    ties = np.arange(0, x.size, 7)
    assert np.array_equal(np.argsort(interp.tie_keys(ties)), np.argsort(full[ties]))
    assert np.array_equal(interp.predict(gx.ravel(), gy.ravel()), got)  # full-rank path


@pytest.mark.parametrize("tie_order", ["gdal", "xy"])
def test_grid_ranks_its_tied_cells_once(tie_order, monkeypatch):
    """Cells whose cut-off neighbours tie are resolved after the blocks, in one ranking
    for the whole grid (was once per block), with the values a per-cell prediction gives."""
    xx, yy = np.meshgrid(np.arange(0.0, 60.0, 1.5), np.arange(0.0, 45.0, 1.5))
    x, y = xx.ravel(), yy.ravel()
    z = 10 + np.sin(x / 7.0) + np.cos(y / 5.0)
    grid = grid_from_extent((0, 60, 0, 45), 0.5)
    calls = []
    real = IDW._break_ties

    def counted(self, q, k, ub):
        calls.append(q.shape[0])
        return real(self, q, k, ub)

    monkeypatch.setattr(IDW, "_break_ties", counted)
    out = idw_grid(x, y, z, grid, fill=True, tie_order=tie_order, block_cells=500)
    assert len(calls) == 1 and calls[0] > 1000      # 22 blocks, one ranking
    gx, gy = grid.block_centers(0, grid.nrows)
    one = IDW(x, y, z, tie_order=tie_order)
    each = np.array([one.predict(gx[i:i + 1], gy[i:i + 1])[0] for i in range(0, gx.size, 37)])
    assert np.array_equal(out.ravel()[::37].view(np.int64), each.view(np.int64))


@pytest.mark.parametrize("tie_order", ["gdal", "xy"])
def test_dtm_bits_do_not_depend_on_the_block_size(tie_order):
    """A cell's value depends on its neighbours only: blocks of 7 cells, the default and
    one block give the same bits, ties (a lattice cloud: every cell has tied 12th and
    13th neighbours) and a radius with empty cells included."""
    xx, yy = np.meshgrid(np.arange(0.0, 60.0, 1.5), np.arange(0.0, 45.0, 1.5))
    x, y = xx.ravel(), yy.ravel()
    z = 10 + np.sin(x / 7.0) + np.cos(y / 5.0)
    keep = ~((x > 40) & (y > 30))                                     # a gap
    x, y, z = x[keep], y[keep], z[keep]
    grid = grid_from_extent((0, 60, 0, 45), 0.5)
    for radius in (None, 2.0):
        runs = [idw_grid(x, y, z, grid, radius=radius, fill=True, tie_order=tie_order,
                         block_cells=b) for b in (7, 65_536, grid.size)]
        assert np.isfinite(runs[0]).sum() > 1000
        for r in runs[1:]:
            assert np.array_equal(r.view(np.int64), runs[0].view(np.int64))

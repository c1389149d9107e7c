"""The catalog's canopy tallies (core/lidar/_canopy.py): a partition of the blocks, and
counts that add up to the merged raster's (issue 20 item 3)."""
from __future__ import annotations

import numpy as np
import pytest

from geomatics_toolbox.core.lidar import _canopy
from geomatics_toolbox.core.lidar import _lowcells as L  # noqa: N812
from geomatics_toolbox.core.lidar import _raster as R  # noqa: N812
from geomatics_toolbox.core.lidar._chunks import ChunkTask


def _tasks(boxes, buffer=30.0):
    tasks = [ChunkTask(key=f"c{i}", sources=[], bounds=b, buffer=buffer, origin=(0.0, 0.0),
                       cell_size=1.0, crs=None, ground_filter="groundfilter",
                       dtm_method="idw", max_distance=10.0, filter_origin=(3.0, -7.0))
             for i, b in enumerate(boxes)]
    _canopy.assign_peers(tasks)
    return tasks


# tiles with a gap (x 100-104), an overlap (y 95-100) and a ragged outer edge
BOXES = [(0.0, 0.0, 100.0, 100.0), (104.0, 0.0, 200.0, 95.0), (0.0, 95.0, 100.0, 190.0),
         (104.0, 95.0, 210.0, 200.0)]


@pytest.mark.parametrize("f", L.FACTORS)
def test_every_block_is_owned_by_exactly_one_chunk(f):
    """Each chunk judges ownership on its own grid (its own corner and anchor on the
    catalog's lattice); over the whole lattice every block is counted once."""
    tasks = _tasks(BOXES)
    cell = 1.5
    total = {}
    for t in tasks:
        x0, y0, x1, y1 = t.buffered_box()
        # the chunk's raster: on the lattice through the catalog's corner, around its box
        grid = R.Grid.around(np.array([x0, x1]), np.array([y0, y1]), cell,
                             origin=t.filter_origin)
        rows = -(-(grid.rows + grid.anchor[0] % f) // f)
        cols = -(-(grid.cols + grid.anchor[1] % f) // f)
        mine = _canopy.owned_blocks(t, grid, f, (rows, cols))
        r0, c0 = grid.anchor[0] // f, grid.anchor[1] // f
        for r, c in zip(*np.nonzero(mine)):
            total[(r0 + r, c0 + c)] = total.get((r0 + r, c0 + c), 0) + 1
    assert set(total.values()) == {1}
    # every block whose first cell's centre lies in a box (or in the gap) is owned
    for bx in BOXES:
        cx = 3.0 + (np.floor((bx[0] - 3.0) / (f * cell)) + 1 + 0.5 / f) * f * cell
        cy = -7.0 + (np.floor((bx[1] + 7.0) / (f * cell)) + 1 + 0.5 / f) * f * cell
        key = (int(np.floor((cy + 7.0) / (f * cell))), int(np.floor((cx - 3.0) / (f * cell))))
        assert total.get(key) == 1


def test_given_factor_is_the_one_low_cells_would_choose():
    """low_cells(factor=) with the factor choose_factor derives from canopy_counts over
    the whole raster gives the same cells and scale as low_cells' own search."""
    rng = np.random.default_rng(3)
    z = 20.0 + rng.random((240, 240)) * 8                  # canopy minima
    ground = rng.random(z.shape) < 0.12                     # sparse ground returns
    z[ground] = rng.normal(0.0, 0.2, ground.sum())
    z[rng.random(z.shape) < 0.2] = np.nan
    own = L.low_cells(z, 1.0, anchor=(5, 7))
    counts = L.canopy_counts(z, 1.0, lambda f, shape: np.ones(shape, bool), anchor=(5, 7))
    f = L.choose_factor(counts["pits"], counts["blocks"])
    given = L.low_cells(z, 1.0, anchor=(5, 7), factor=f)
    assert own.canopy_scale == given.canopy_scale == float(f) > 0
    assert np.array_equal(own.low, given.low) and own.pits == given.pits
    other = L.low_cells(z, 1.0, anchor=(5, 7), factor=L.FACTORS[-1] if f != L.FACTORS[-1]
                        else L.FACTORS[0])
    assert not np.array_equal(other.low, own.low)          # the factor matters here


def test_chunk_tallies_add_up_to_the_merged_raster_beyond_the_buffer(tmp_path, monkeypatch):
    """A closed forest (left half thinned) cut into two tiles, as tiles and as 100 m
    boxes: over the blocks farther than the buffer from the outer edge, the chunks'
    tallies summed equal the single-file run's counts, every factor. (Within the buffer of
    the outer edge a chunk's raster ends otherwise: 600 m forest, 23 of 26,779 pits.)"""
    from geomatics_toolbox.core.io.las import PointData, read_las, write_las
    from geomatics_toolbox.core.lidar import catalog as cc
    from geomatics_toolbox.core.lidar.filters import default_selection, ground_filter, run_filter
    from geomatics_toolbox.synthetic import landscapes
    s = landscapes.closed_forest(extent=300.0, density=2.0, ground_share=0.05, seed=2)
    keep = (s.x >= 150) | (np.random.default_rng(1).random(s.x.size) < 0.4)
    x, y, z = s.x[keep] + 500_000.0, s.y[keep] + 4_000_000.0, s.z[keep]
    d = tmp_path / "tiles"
    d.mkdir()
    parts = []
    for i, m in enumerate((x < 500_150.0, x >= 500_150.0)):
        write_las(d / f"t{i}.las", x[m], y[m], z[m], dimensions={"classification": np.ones(
            int(m.sum()), np.uint8)}, crs="EPSG:32632", scale=0.01)
        parts.append(read_las(d / f"t{i}.las", ("classification",)))
    pts = PointData(*(np.concatenate([getattr(p, a) for p in parts]) for a in "xyz"),
                    {"classification": np.concatenate([p["classification"] for p in parts])})
    buffer = 50.0
    cat = cc.Catalog.open(str(d))
    e = cat.extent

    def interior(grid, f, shape, origin):
        r0, c0 = grid.anchor[0] // f, grid.anchor[1] // f
        ys = origin[1] + ((r0 + np.arange(shape[0])) * f + 0.5) * grid.cell
        xs = origin[0] + ((c0 + np.arange(shape[1])) * f + 0.5) * grid.cell
        return (((ys > e[1] + buffer) & (ys < e[3] - buffer))[:, None]
                & ((xs > e[0] + buffer) & (xs < e[2] - buffer))[None, :])
    flt = ground_filter("groundfilter")
    corner = (float(pts.x.min()), float(pts.y.min()))
    flt.canopy_owned = lambda grid, f, shape: interior(grid, f, shape, corner)
    merged = run_filter(pts, flt, default_selection("groundfilter")).outcome.details
    merged = merged.canopy_counts                  # counted while it classified
    assert min(merged["pits"][:3]) > 0 and min(merged["blocks"]) > 0
    owned = _canopy.owned_blocks
    monkeypatch.setattr(_canopy, "owned_blocks", lambda t, grid, f, shape: owned(
        t, grid, f, shape) & interior(grid, f, shape, t.filter_origin))
    for size in (0.0, 100.0):
        out = tmp_path / f"out{size:g}"
        tasks = cc.plan_tasks(cat, out, ground_filter="groundfilter", dtm_method="idw",
                              cell_size=2.0, buffer=buffer, chunk_size=size)
        (out / cc.STATE_DIR).mkdir(parents=True)
        got = _canopy.settle(tasks, cc.run_here(cat, tasks, out))   # counted as they classify
        assert [got.pits, got.blocks] == [merged["pits"], merged["blocks"]], size

"""Figures of the LiDAR reports (class map, error map, tile map, sweep plot)."""
import base64
import re
import xml.etree.ElementTree as ET
import zlib

import numpy as np
import pytest

from geomatics_toolbox.core.lidar import figures as F  # noqa: N812
from geomatics_toolbox.core.lidar.lsq import STATUS_NAMES, LsqFilter, LsqOptions
from geomatics_toolbox.core.lidar.pipeline import FilterOutputs, classify_file
from geomatics_toolbox.core.lidar.sweep import SweepRow
from geomatics_toolbox.core.reporting import Figure, render_html
from geomatics_toolbox.core.reporting.i18n import has_translation


def _pixels(svg_text):
    """Decode the first embedded PNG (8-bit RGB, filter 0 rows) into (rows, cols, 3)."""
    ET.fromstring(svg_text)                       # well-formed SVG
    b64 = re.search(r'href="data:image/png;base64,([^"]+)"', svg_text).group(1)
    png = base64.b64decode(b64)
    w, h = int.from_bytes(png[16:20], "big"), int.from_bytes(png[20:24], "big")
    pos, data = 8, b""
    while pos < len(png):
        n = int.from_bytes(png[pos:pos + 4], "big")
        if png[pos + 4:pos + 8] == b"IDAT":
            data += png[pos + 8:pos + 8 + n]
        pos += 12 + n
    raw = np.frombuffer(zlib.decompress(data), np.uint8).reshape(h, 1 + 3 * w)
    assert not raw[:, 0].any()
    return raw[:, 1:].reshape(h, w, 3)


def _rgb(colour):
    return tuple(int(colour[i:i + 2], 16) for i in (1, 3, 5))


def test_majority_grid_equals_brute_force():
    rng = np.random.default_rng(1)
    x, y = rng.uniform(0, 50, 3000), rng.uniform(100, 130, 3000)
    codes = rng.integers(0, 4, 3000)
    grid = F.plan_grid(x, y, min_cell=3.0)
    got = F.majority_grid(grid, x, y, codes, 4)
    idx = grid.index(x, y)
    want = np.full(grid.size, -1)
    for cell in np.unique(idx):
        c = np.bincount(codes[idx == cell], minlength=4)
        want[cell] = int(np.argmax(c))               # ties: smallest code
    assert got.shape == (grid.ny, grid.nx) == (10, 17)
    np.testing.assert_array_equal(got.ravel(), want)


def test_plan_grid_is_bounded_whatever_the_cloud():
    x = np.array([0.0, 250_000.0, 3.0])
    y = np.array([0.0, 1.0, 90_000.0])
    g = F.plan_grid(x, y, min_cell=0.01)          # a fine cell is coarsened to the bound
    assert (g.nx, g.ny) == (F.MAX_CELLS, 144)
    assert g.cell == pytest.approx(250_000 / (F.MAX_CELLS - 1))
    # every point falls inside the grid
    assert np.all(g.index(x, y) < g.size)
    dense = F.plan_grid(np.random.default_rng(0).uniform(0, 10, 200_000),
                        np.random.default_rng(1).uniform(0, 10, 200_000))
    assert dense.cell == pytest.approx(3 * np.sqrt(100 / 200_000), rel=1e-3)


def test_class_map_is_north_up_and_coloured_by_majority():
    # north half ground (2), south half objects (1); one stray class 7 point
    gx, gy = np.meshgrid(np.arange(0, 40, 0.5), np.arange(0, 40, 0.5))
    x, y = gx.ravel(), gy.ravel()
    cls = np.where(y >= 20, 2, 1)
    cls[0] = 7
    fig = F.class_map(x, y, cls, lambda s: s)
    assert isinstance(fig, Figure) and fig.figure_id == "class-map"
    px = _pixels(fig.svg)
    assert tuple(px[0, 0]) == _rgb(F.CLASS_COLOURS[2])
    assert tuple(px[-1, -1]) == _rgb(F.CLASS_COLOURS[1])
    assert not (px == _rgb(F.CLASS_COLOURS[7])).all(axis=2).any()   # never a majority
    assert "2 ground" in fig.svg and "1 other (object)" in fig.svg
    assert "scale-bar" in fig.svg and 'class="north"' in fig.svg and " m</text>" in fig.svg


def test_error_map_shows_the_dominant_error():
    # three 10 m cells along x: correct only, 1 Type I + 2 Type II, 2 Type I + 1 Type II
    x = np.array([1, 9, 11, 12, 13, 14, 21, 22, 23, 24, 29.0])
    y = np.array([5, 5, 5, 5, 5, 5, 5, 5, 5, 5, 5.0])
    codes = np.array([0, 0, 0, 1, 2, 2, 0, 1, 1, 2, 0])
    fig = F.error_map(x, y, codes, lambda s: s)
    assert fig.figure_id == "error-map"
    grid = F.plan_grid(x, y)
    cells = grid.index(np.array([5.0, 12.5, 22.5]), np.array([5.0, 5.0, 5.0]))
    assert len(set(cells.tolist())) == 3
    px = _pixels(fig.svg).reshape(-1, 3)
    assert tuple(px[cells[0]]) == _rgb(F.ERROR_COLOURS[0])
    assert tuple(px[cells[1]]) == _rgb(F.ERROR_COLOURS[2])
    assert tuple(px[cells[2]]) == _rgb(F.ERROR_COLOURS[1])


def test_tile_map_one_cell_per_tile():
    class Grid:
        size = 50.0
        centres = np.array([[25, 25], [75, 25], [25, 75], [125, 75.0]])
    fig = F.tile_map(Grid(), np.array([1, 2, 0, -1]), lambda s: s, STATUS_NAMES)
    assert fig.figure_id == "tile-map"
    px = _pixels(fig.svg)
    assert px.shape[:2] == (2, 3)
    assert tuple(px[1, 0]) == _rgb(F.STATUS_COLOURS[1])       # south-west tile
    assert tuple(px[1, 1]) == _rgb(F.STATUS_COLOURS[2])
    assert tuple(px[0, 0]) == _rgb(F.STATUS_COLOURS[0])       # north-west tile
    assert tuple(px[0, 2]) == _rgb(F.STATUS_COLOURS[-1])
    assert tuple(px[1, 2]) == _rgb(F.EMPTY_COLOUR)
    assert "iteration cap" in fig.svg and "converged" in fig.svg


def test_sweep_plot_draws_the_best_radius_only():
    rows = [SweepRow(r, s, 0.2, 1.0, 10, 1, 1, 1, 1, s / 10, 1 + r, 2.0, 80.0)
            for r in (3.0, 5.0) for s in (30.0, 40.0, 50.0)]
    fig = F.sweep_plot(rows, rows[4], lambda s: s)
    assert fig.figure_id == "sweep-plot"
    ET.fromstring(fig.svg)
    lines = re.findall(r'<polyline points="([^"]+)"', fig.svg)
    assert len(lines) == 4 and all(len(p.split()) == 3 for p in lines)
    assert "stroke-dasharray" in fig.svg and "Type II error (%)" in fig.svg


@pytest.mark.parametrize("lang", ["ar", "fa"])
def test_figure_text_is_translated(lang):
    seen = set()

    def tr(s):
        seen.add(s)
        return s
    rng = np.random.default_rng(2)
    x, y = rng.uniform(0, 100, 500), rng.uniform(0, 100, 500)
    F.class_map(x, y, rng.choice([0, 1, 2, 7, 18, 9], 500), tr)
    F.error_map(x, y, rng.integers(0, 3, 500), tr)
    row = SweepRow(3, 40, 0.2, 1, 10, 1, 1, 1, 1, 1, 1, 1, 1)
    F.sweep_plot([row], row, tr)

    class Grid:
        size = 10.0
        centres = np.array([[5, 5], [15, 5], [5, 15], [15, 15], [25, 25.0]])
    F.tile_map(Grid(), np.array([0, 1, 2, 3, -1]), tr, STATUS_NAMES)
    assert {s for s in seen if not has_translation(s, lang)} == set()


def test_filter_report_has_class_and_tile_maps(tmp_path):
    from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile
    src = tmp_path / "t.laz"
    write_tile(generate_tile(extent=(80, 60), density=2.0, seed=3), src)
    run = classify_file(src, LsqFilter(LsqOptions(tile_size=20)),
                        FilterOutputs(report=tmp_path / "r.html", lang="ar"))
    html = (tmp_path / "r.html").read_text(encoding="utf-8")
    assert 'id="class-map"' in html and 'id="tile-map"' in html
    px = _pixels(next(b for s in run.report.sections for b in s.blocks
                      if isinstance(b, Figure) and b.figure_id == "class-map").svg)
    # the map's colours are the shares of the classes, roughly (majority per cell)
    ground = (px == _rgb(F.CLASS_COLOURS[2])).all(axis=2).mean()
    other = (px == _rgb(F.CLASS_COLOURS[1])).all(axis=2).mean()
    assert abs(ground / (ground + other) - run.n_ground / (run.n_ground + run.n_nonground)) < 0.1
    assert "خريطة الأصناف" in render_html(run.report, lang="ar")

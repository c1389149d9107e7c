"""Catalog chunks on real-world sparse tiles: water, no ground within reach, few ground
points, a header-only tile, and a catalog with no ground at all.

The reference is the merged cloud's IDW DTM on the same global lattice (as in
test_catalog): where no ground is within the gap distance it is nodata, and so must the
mosaic be; everywhere else the cells are equal.
"""
from __future__ import annotations

import os
from pathlib import Path

import numpy as np
import pytest

from geomatics_toolbox.core.errors import InputError, message_text
from geomatics_toolbox.core.io.catalog import build_vrt, find_tiles
from geomatics_toolbox.core.io.las import read_las, write_las
from geomatics_toolbox.core.io.raster import read_raster
from geomatics_toolbox.core.io.units import METRIC
from geomatics_toolbox.core.lidar import catalog as cc
from geomatics_toolbox.core.lidar._chunks import process_chunk, snap_grid
from geomatics_toolbox.core.lidar.catalog_report import catalog_report
from geomatics_toolbox.core.reporting import render_html
from geomatics_toolbox.core.terrain.dtm import IdwOptions, dtm_method, make_dtm, read_ground
from geomatics_toolbox.core.terrain.idw import idw_grid
from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile

SIDE = 250.0
ORIGIN = (500_000.0, 4_000_000.0)
BUFFER = 120.0
CELL = 2.0
WATER = 9


def _catalog(d: Path, lake: float, *, islet: int = 0, everywhere: bool = False) -> Path:
    """2 x 2 tiles of 250 m; a lake (class 9, flat) over the upper-right corner.

    ``lake``: side of the lake square measured from the catalog's upper-right corner
    (250 = tile t11 exactly; 380 = t11 and a 130 m band of its neighbours, so no ground
    is within t11's 120 m buffer). ``islet``: that many ground points of t11 kept on a
    rock in the lake. ``everywhere``: every point is water (no ground in the catalog).
    """
    d.mkdir(parents=True, exist_ok=True)
    for i in range(2):
        for j in range(2):
            t = generate_tile(extent=(SIDE, SIDE), origin=(ORIGIN[0] + SIDE * i,
                                                           ORIGIN[1] + SIDE * j),
                              density=0.8, seed=10 * i + j)
            wet = ((t.x >= ORIGIN[0] + 2 * SIDE - lake) & (t.y >= ORIGIN[1] + 2 * SIDE - lake)
                   ) | everywhere
            if islet and (i, j) == (1, 1):
                rock = np.flatnonzero(t.classification == 2)
                near = np.hypot(t.x[rock] - (ORIGIN[0] + 1.6 * SIDE),
                                t.y[rock] - (ORIGIN[1] + 1.6 * SIDE))
                wet[rock[np.argsort(near)[:islet]]] = False
            t.classification[wet] = WATER
            t.z[wet] = 190.0
            write_tile(t, d / f"t{i}{j}.laz")
    return d


def _dtm(path) -> np.ndarray:
    r = read_raster(path)
    data = r.data.astype(np.float64)
    data[data == r.nodata] = np.nan
    return data


def _chunks(d: Path, out: Path, method: str = "idw"):
    """Every chunk run in this process (no Dask), as the workers run them."""
    cat = cc.Catalog.open(str(d))
    tasks = cc.plan_tasks(cat, out, ground_filter="keep", dtm_method=method,
                          cell_size=CELL, buffer=BUFFER)
    (out / cc.STATE_DIR).mkdir(parents=True)
    stats = {t.key: process_chunk(t) for t in tasks}
    build_vrt(str(out / "m.vrt"), [t.outputs["DTM"] for t in tasks])
    return cat, tasks, stats


def _inside(grid, extent, margin):
    cx, cy = (v.reshape(grid.shape) for v in grid.block_centers(0, grid.nrows))
    return np.minimum.reduce([cx - extent[0], cy - extent[1], extent[2] - cx,
                              extent[3] - cy]) > margin


@pytest.mark.parametrize("lake,reach", [(250.0, "buffer"), (380.0, "none")])
def test_water_tile_mosaic_equals_the_merged_cloud(tmp_path, lake, reach):
    """t11 all water: its chunk finishes; its cells are the merged cloud's, nodata where
    no ground is within the gap distance (the whole tile when none is within reach)."""
    d = _catalog(tmp_path / "tiles", lake)
    cat, tasks, stats = _chunks(d, tmp_path / "out")
    s = stats["t11"]
    assert s["status"] == "done" and s["ground"] == 0
    assert (s["ground_reach"] == 0) == (reach == "none")
    mosaic = _dtm(tmp_path / "out" / "m.vrt")
    # the single-file runner on the merged cloud (read_ground -> make_dtm), IDW ties by
    # coordinates and the catalog's gap distance (its own default is 5 ground spacings)
    parts = [read_las(p, ("classification",)) for p in find_tiles(str(d))]
    write_las(tmp_path / "merged.las", *(np.concatenate([getattr(p, a) for p in parts])
                                         for a in "xyz"),
              dimensions={"classification": np.concatenate([p["classification"]
                                                            for p in parts])},
              crs="EPSG:32632", point_format=6, version="1.4", scale=0.01)
    grid = snap_grid(cat.extent, tasks[0].origin, CELL, "EPSG:32632")
    pts, _ = read_ground(tmp_path / "merged.las", [2], cell=CELL, units=METRIC)
    ref = make_dtm("merged", pts, grid, dtm_method("idw", IdwOptions(tie_order="xy")),
                   max_distance=cat.default_max_distance()).outcome.z
    assert mosaic.shape == ref.shape
    assert np.array_equal(np.isfinite(mosaic), np.isfinite(ref))
    sel = _inside(grid, cat.extent, 10.0) & np.isfinite(ref)
    assert sel.sum() > (40_000 if reach == "buffer" else 20_000)
    assert np.max(np.abs(mosaic[sel] - ref[sel])) <= 1e-4
    t11 = _dtm(tmp_path / "out" / "t11_dtm.tif")
    assert s["dtm_cells"] == int(np.isfinite(t11).sum())
    if reach == "none":
        assert s["dtm_cells"] == 0 and t11.shape == (125, 125)
    else:
        assert 0 < s["dtm_cells"] < t11.size // 2
    # the classified copy of the water tile is written, its classes kept
    got = read_las(tmp_path / "out" / "t11_classified.laz", ("classification",))
    assert np.all(got["classification"] == WATER) and len(got) == s["points"]


def test_few_ground_points_within_reach_use_the_points_there(tmp_path):
    """5 ground points on a rock in the lake, none else within t11's buffer: the chunk's
    IDW uses those 5 (neighbours clamped, as gdal_grid invdistnn uses what it finds)."""
    d = _catalog(tmp_path / "tiles", 380.0, islet=5)
    cat, tasks, stats = _chunks(d, tmp_path / "out")
    s = stats["t11"]
    assert s["status"] == "done" and s["ground"] == 5 and s["ground_reach"] == 5
    assert s["neighbours_used"] == 5
    own = read_las(d / "t11.laz", ("classification",))
    g = own["classification"] == 2
    task = next(t for t in tasks if t.key == "t11")
    grid = snap_grid(task.bounds, task.origin, CELL)
    ref = idw_grid(own.x[g], own.y[g], own.z[g], grid, max_points=5, workers=1,
                   max_distance=task.max_distance, tie_order="xy")
    got = _dtm(tmp_path / "out" / "t11_dtm.tif")
    assert np.array_equal(np.isfinite(got), np.isfinite(ref)) and np.isfinite(ref).sum() > 50
    assert np.nanmax(np.abs(got - ref)) <= 1e-4


@pytest.mark.parametrize("method", ["kriging", "tin"])
def test_few_or_no_ground_within_reach_other_methods(tmp_path, method):
    """Kriging and TIN chunks finish on a water tile with 5 / 0 ground points in reach."""
    for islet in (5, 0):
        d = _catalog(tmp_path / f"tiles{islet}", 380.0, islet=islet)
        _, _, stats = _chunks(d, tmp_path / f"out{islet}", method)
        s = stats["t11"]
        assert s["status"] == "done" and s["ground_reach"] == islet
        t11 = _dtm(tmp_path / f"out{islet}" / "t11_dtm.tif")
        assert s["dtm_cells"] == int(np.isfinite(t11).sum())
        if not islet:                       # no ground within reach: nodata
            assert s["dtm_cells"] == 0
        elif method == "kriging":           # 5 neighbours, the rock's cells kriged
            assert s["dtm_cells"] > 50 and s["neighbours_used"] == 5


def _write_header_only(path):
    e = np.empty(0)
    write_las(path, e, e, e, dimensions={"classification": np.empty(0, np.uint8)},
              crs="EPSG:32632", point_format=6, version="1.4", scale=0.01)


def test_run_warns_naming_the_tiles_without_ground_and_a_header_only_tile(tmp_path):
    """Through run_catalog (Dask): the run finishes, warnings name t11 and why (en, ar,
    fa), the report carries them; a header-only tile is left out and named."""
    from geomatics_toolbox.core.lidar.catalog_report import catalog_warnings
    d = _catalog(tmp_path / "tiles", 380.0)
    _write_header_only(d / "t20.laz")
    out = tmp_path / "out"
    res = cc.run_catalog(str(d), out, ground_filter="keep", cell_size=CELL, buffer=BUFFER,
                         workers=1)
    assert not res.failed and len(res.chunks) == 4
    assert res.settings["empty_tiles"] == ["t20.laz"]
    warnings = catalog_warnings(res)
    en = [str(InputError(w.text, **w.args)) for w in warnings]
    assert any("t20.laz has no points (a header only); it is left out" in w for w in en), en
    t11 = [w for w in en if w.startswith("Tile t11:")]
    assert len(t11) == 1, en
    assert ("no ground point in the tile nor within its 120 m buffer" in t11[0]
            and "(its points by class: 9: " in t11[0] and "its DTM is nodata" in t11[0]), t11
    assert not any(w.startswith(("Tile t00", "Tile t01", "Tile t10")) for w in en), en
    for lang in ("ar", "fa"):
        text = [InputError(w.text, **w.args).message(lang) for w in warnings]
        assert all(not t.startswith("Tile ") and "t11" in " ".join(text) for t in text), text
    html = render_html(catalog_report(res, np.asarray(res.settings["bounds"]), lang="en"),
                       lang="en")
    assert "no ground point in the tile nor within its" in html and "t20.laz" in html
    assert html.count("done, DTM nodata") == 1          # t11's row of the tile table
    assert np.isfinite(_dtm(out / "dtm.vrt")).sum() > 25_000


def test_catalog_without_any_ground_is_refused_and_leaves_nothing(tmp_path):
    d = _catalog(tmp_path / "tiles", 0.0, everywhere=True)
    out = tmp_path / "out"
    with pytest.raises(InputError, match=r"No tile of the catalog has a ground point \(4 "
                       r"tiles, 199995 points, by class: 9: 199995\).*choose a ground filter "
                       r"\(GROUND_FILTER\)") as err:
        cc.run_catalog(str(d), out, ground_filter="keep", cell_size=CELL, buffer=BUFFER,
                       workers=1)
    assert err.value.message("ar").startswith("لا توجد في أي بلاطة من الفهرس نقطة أرض")
    assert err.value.message("fa").startswith("هیچ کاشی‌ای از کاتالوگ نقطهٔ زمینی ندارد")
    assert not out.exists() or not any(out.rglob("*"))


def test_refusal_after_the_chunks_undoes_the_run_once_and_restores_the_state(tmp_path,
                                                                             monkeypatch):
    """No ground anywhere, in a folder an earlier run left without a finished chunk: this
    run's outputs go and the earlier settings come back byte for byte, in one undo (it
    ran twice: once without the state files, once more from the refusal's handler)."""
    d = _catalog(tmp_path / "tiles", 0.0, everywhere=True)
    out = tmp_path / "out"
    (out / cc.STATE_DIR).mkdir(parents=True)
    earlier = '{"earlier": "run"}'
    (out / cc.STATE_DIR / "settings.json").write_text(earlier, encoding="utf-8")
    (out / "notes.txt").write_text("mine", encoding="utf-8")
    calls = []
    undo = cc._undo_run

    def spy(*a, **k):
        calls.append(k.get("restore"))
        return undo(*a, **k)
    monkeypatch.setattr(cc, "_undo_run", spy)
    with pytest.raises(InputError, match=r"No tile of the catalog has a ground point"):
        cc.run_catalog(str(d), out, ground_filter="keep", cell_size=CELL, buffer=BUFFER,
                       workers=1)
    assert len(calls) == 1 and calls[0] is not None
    assert sorted(str(p.relative_to(out)) for p in out.rglob("*")) == [
        ".catalog", ".catalog/settings.json", "notes.txt"]
    assert (out / cc.STATE_DIR / "settings.json").read_text(encoding="utf-8") == earlier


def test_catalog_of_header_only_tiles_is_refused(tmp_path):
    d = tmp_path / "tiles"
    d.mkdir()
    for name in ("a.laz", "b.laz"):
        _write_header_only(d / name)
    with pytest.raises(InputError, match=r"Every tile of the catalog is without points "
                                         r"\(a\.laz, b\.laz\)"):
        cc.Catalog.open(str(d))


def _offshore(d: Path, n: int) -> Path:
    """A land tile and, 1 km away, a sea tile of ``n`` returns (no neighbour in reach)."""
    d.mkdir(parents=True)
    write_tile(generate_tile(extent=(150.0, 150.0), origin=ORIGIN, density=1.0, seed=1),
               d / "land.laz")
    rng = np.random.default_rng(n)
    x, y = ORIGIN[0] + 1000 + rng.uniform(0, 150, n), ORIGIN[1] + rng.uniform(0, 150, n)
    cls = np.ones(n, np.uint8)
    cls[0] = 18                                   # a bird: input noise is kept
    write_las(d / "sea.laz", x, y, 190 + rng.normal(0, 0.1, n),
              dimensions={"classification": cls, "return_number": np.ones(n, np.uint8),
                          "number_of_returns": np.ones(n, np.uint8)},
              crs="EPSG:32632", point_format=6, version="1.4", scale=0.01)
    return d


@pytest.mark.parametrize("key", ["groundfilter", "ptd", "lsq_faithful", "lsq_improved",
                                 "slope_exact", "slope_adaptive"])
def test_offshore_tile_too_sparse_for_the_filter_finishes(tmp_path, key):
    """3 returns in a tile and its buffer: too few for the ground filter (it needs 10, 6 or
    2). The chunk finishes: points unclassified (class 1, input noise 18 kept), DTM
    nodata, the filter's own reason kept for the warning; the land tile is unaffected."""
    from geomatics_toolbox.core.lidar.catalog_report import _tile_warning
    d = _offshore(tmp_path / "tiles", 3)
    cat = cc.Catalog.open(str(d))
    out = tmp_path / "out"
    tasks = cc.plan_tasks(cat, out, ground_filter=key, dtm_method="idw", cell_size=CELL,
                          buffer=50.0)
    (out / cc.STATE_DIR).mkdir(parents=True)
    stats = {t.key: process_chunk(t) for t in tasks}
    s = stats["sea"]
    got = read_las(out / "sea_classified.laz", ("classification",))["classification"]
    if key.startswith("slope"):            # the slope filter runs from 2 points
        assert "filter_error" not in s
        return
    assert s["status"] == "done" and s["ground"] == 0 and s["dtm_cells"] == 0
    assert got.tolist() == [18, 1, 1]
    assert "filter_error" in s and s["filter_error"]["template"]
    w = message_text(_tile_warning(s, 50.0), "en")
    assert message_text(_tile_warning(s, 50.0), "fa").startswith("کاشی")
    assert w.startswith("Tile sea: the ground filter cannot classify its 3 points (tile "
                        "and buffer): "), w
    assert "Its points are left unclassified (class 1, noise kept); its DTM is nodata." in w
    assert stats["land"]["ground"] > 1000 and stats["land"]["dtm_cells"] > 5000


def test_catalog_of_one_sparse_tile_refused_with_the_filters_reason(tmp_path):
    d = _offshore(tmp_path / "tiles", 3)
    out = tmp_path / "out"
    with pytest.raises(InputError, match=r"No tile of the catalog has a ground point \(1 "
                       r"tiles, 3 points, by class: 1: 2, 18: 1\).* The ground filter cannot "
                       r"classify tile sea: A ground filter needs at least 10 points, got 2"):
        cc.run_catalog([str(d / "sea.laz")], out, cell_size=CELL, buffer=50.0, workers=1)
    assert not out.exists() or not any(out.rglob("*"))


def test_square_chunks_over_a_lake_finish(tmp_path):
    """CHUNK_SIZE 200 m over the 380 m lake: chunks with points but no ground within reach
    finish with a nodata DTM; the mosaic's nodata is the merged cloud's."""
    from geomatics_toolbox.core.io.catalog import build_vrt as vrt
    d = _catalog(tmp_path / "tiles", 380.0)
    cat = cc.Catalog.open(str(d))
    out = tmp_path / "out"
    tasks = cc.plan_tasks(cat, out, ground_filter="keep", dtm_method="idw", cell_size=CELL,
                          buffer=BUFFER, chunk_size=200.0)
    (out / cc.STATE_DIR).mkdir(parents=True)
    stats = [process_chunk(t) for t in tasks]
    dry = [s for s in stats if s["status"] == "done" and s["ground_reach"] == 0]
    assert len(tasks) == 9 and dry and all(s["dtm_cells"] == 0 for s in dry)
    vrt(str(out / "m.vrt"), [t.outputs["DTM"] for t in tasks if os.path.exists(
        t.outputs["DTM"])])
    mosaic = _dtm(out / "m.vrt")[-250:, :250]        # the catalog's 500 m, from the top
    parts = [read_las(p, ("classification",)) for p in find_tiles(str(d))]
    x, y, z = (np.concatenate([getattr(p, a) for p in parts]) for a in "xyz")
    g = np.concatenate([p["classification"] for p in parts]) == 2
    grid = snap_grid(cat.extent, tasks[0].origin, CELL)
    ref = idw_grid(x[g], y[g], z[g], grid, max_distance=cat.default_max_distance(),
                   workers=1, tie_order="xy")
    assert mosaic.shape == ref.shape
    assert np.array_equal(np.isfinite(mosaic), np.isfinite(ref))


def test_kriging_chunk_whose_variogram_cannot_be_fitted_finishes(tmp_path):
    """3 ground points within reach: too few point pairs for kriging's variogram (the
    catalog has no MAX_LAG). The chunk finishes with a nodata DTM; the reason is kept."""
    from geomatics_toolbox.core.lidar.catalog_report import _tile_warning
    d = _catalog(tmp_path / "tiles", 380.0, islet=3)
    _, _, stats = _chunks(d, tmp_path / "out", "kriging")
    s = stats["t11"]
    assert s["status"] == "done" and s["ground_reach"] == 3 and s["dtm_cells"] == 0
    assert "point pairs" in s["dtm_error"]["template"]
    w = message_text(_tile_warning(s, BUFFER), "en")
    assert w.startswith("Tile t11: the DTM method cannot interpolate the 3 ground points in "
                        "the tile and its buffer: Only 6 point pairs are closer than"), w
    assert w.endswith("Its DTM is nodata."), w
    assert message_text(_tile_warning(s, BUFFER), "ar").startswith("البلاطة")
    assert stats["t00"]["dtm_cells"] > 5000 and "dtm_error" not in stats["t00"]


def test_catalog_whose_every_dtm_is_nodata_refused_with_the_reason(tmp_path):
    """Ground, but only 3 points: kriging cannot fit a variogram. Refused as the
    single-file DTM is ('no cell with a value'), with kriging's reason and the fix."""
    d = tmp_path / "tiles"
    d.mkdir()
    write_las(d / "sea.laz", ORIGIN[0] + np.array([10.0, 80.0, 140.0]),
              ORIGIN[1] + np.array([20.0, 120.0, 60.0]), np.array([1.0, 2.0, 1.5]),
              dimensions={"classification": np.full(3, 2, np.uint8)}, crs="EPSG:32632",
              point_format=6, version="1.4", scale=0.01)
    out = tmp_path / "out"
    with pytest.raises(InputError, match=r"No tile's DTM has a cell with a value \(3 ground "
                       r"points in the catalog\): Only 6 point pairs .* Choose another DTM "
                       r"method \(DTM_METHOD, e.g. IDW\)"):
        cc.run_catalog(str(d), out, ground_filter="keep", dtm_method="kriging",
                       cell_size=CELL, buffer=50.0, workers=1)
    assert not out.exists() or not any(out.rglob("*"))


# ------------------------------------------------------------------ the gap distance
def _merged_las(d: Path, dst: Path) -> Path:
    parts = [read_las(p, ("classification",)) for p in find_tiles(str(d))]
    write_las(dst, *(np.concatenate([getattr(p, a) for p in parts]) for a in "xyz"),
              dimensions={"classification": np.concatenate([p["classification"]
                                                            for p in parts])},
              crs="EPSG:32632", point_format=6, version="1.4", scale=0.01)
    return dst


@pytest.mark.parametrize("method,lake,rim", [("idw", 250.0, 667), ("idw", 380.0, 71),
                                             ("tin", 250.0, None)])
def test_catalog_gap_distance_is_the_single_file_default_of_the_merged_cloud(
        tmp_path, method, lake, rim):
    """The catalog's default gap distance was 10 mean spacings of all points (headers):
    11.18 m here, where a single-file run of the merged cloud uses 5 ground spacings
    (8.33 m over the 250 m lake, 11.05 m over the 380 m one): a 1–2-cell shore rim (667 /
    71 cells) had heights in the mosaic and none in the single-file DTM. Now it is derived
    once from every chunk's ground after the run, and the DTMs masked with it."""
    from geomatics_toolbox.core.terrain.grid import default_max_distance
    d = _catalog(tmp_path / "tiles", lake)
    res = cc.run_catalog(str(d), tmp_path / "out", ground_filter="keep", dtm_method=method,
                         cell_size=CELL, buffer=BUFFER, workers=1)
    assert not res.failed
    # the single-file runner on the merged cloud, all defaults (its own grid, its own gap)
    pts, grid = read_ground(_merged_las(d, tmp_path / "merged.las"), [2], cell=CELL,
                            units=METRIC)
    ref = make_dtm("merged", pts, grid, dtm_method(
        method, IdwOptions(tie_order="xy") if method == "idw" else None)).outcome.z
    mosaic = _dtm(tmp_path / "out" / "dtm.vrt")
    assert mosaic.shape == ref.shape == (250, 250)          # same lattice, same extent
    assert np.array_equal(np.isfinite(mosaic), np.isfinite(ref))
    assert res.settings["gap_distance"] == default_max_distance(grid, len(pts))
    old = cc.Catalog.open(str(d)).default_max_distance()
    assert old == pytest.approx(11.18, abs=0.01) and res.settings["gap_distance"] < old
    if rim is not None:   # the cells the old gap distance gave a height (the shore rim)
        wide = make_dtm("merged", pts, grid, dtm_method("idw", IdwOptions(tie_order="xy")),
                        max_distance=old).outcome.z
        assert int((np.isfinite(wide) & ~np.isfinite(ref)).sum()) == rim
        sel = _inside(grid, cc.Catalog.open(str(d)).extent, 10.0) & np.isfinite(ref)
        assert np.max(np.abs(mosaic[sel] - ref[sel])) <= 1e-4
    # the chunks' stats and markers follow the masked DTMs; the .gap.npz files are gone
    t11 = _dtm(tmp_path / "out" / "t11_dtm.tif")
    s = next(c for c in res.chunks if c["key"] == "t11")
    assert s["dtm_cells"] == int(np.isfinite(t11).sum())
    assert not list((tmp_path / "out" / cc.STATE_DIR).glob("*.gap.npz"))


@pytest.mark.parametrize("method", ["idw", "kriging", "tin"])
def test_gap_masking_afterwards_equals_the_gridders_own_limit(method):
    """A chunk's DTM without a limit, masked afterwards by the single-file rule, is the
    DTM the method makes with that limit (IDW / kriging: nearest point within d; TIN:
    triangles with an edge over 2 d dropped)."""
    from geomatics_toolbox.core.lidar._gap import chunk_gaps, mask_with_gap
    from geomatics_toolbox.core.terrain.grid import grid_from_extent
    rng = np.random.default_rng(7)
    x, y = rng.uniform(0, 60, 900), rng.uniform(0, 60, 900)
    keep = np.hypot(x - 30, y - 30) > 9                     # a pond with no point
    x, y = x[keep], y[keep]
    z = 100 + 0.05 * x + np.sin(y / 7)
    grid = grid_from_extent((0, 60, 0, 60), 1.0)
    m = dtm_method(method, IdwOptions(tie_order="xy") if method == "idw" else None)
    for d in (2.0, 3.5, 6.0):
        want = m.interpolate(x, y, z, grid, max_distance=2 * d if method == "tin" else d,
                             workers=1).z
        got = mask_with_gap(*chunk_gaps(m, x, y, z, grid), method, d)
        assert np.array_equal(np.isfinite(got), np.isfinite(want)), d
        assert 0 < np.isfinite(want).sum() < grid.size
        both = np.isfinite(want)
        assert np.max(np.abs(got[both] - want[both])) <= 1e-4       # got: float32 copy


def test_gap_distance_after_a_resume_is_the_clean_runs(tmp_path):
    """A run with a failed chunk keeps each finished chunk's .gap.npz and the provisional
    DTMs; once resumed, the DTMs are those of a run that never failed."""
    import shutil
    import struct
    d = _catalog(tmp_path / "tiles", 250.0)
    clean = cc.run_catalog(str(d), tmp_path / "clean", ground_filter="keep",
                           cell_size=CELL, buffer=0.0, workers=1)
    good = (d / "t00.laz").read_bytes()
    cut = bytearray(good[:len(good) // 2])          # fails in its worker (test_catalog)
    struct.pack_into("<q", cut, struct.unpack_from("<I", cut, 96)[0], -1)
    (d / "t00.laz").write_bytes(bytes(cut))
    out = tmp_path / "out"
    first = cc.run_catalog(str(d), out, ground_filter="keep", cell_size=CELL, buffer=0.0,
                           workers=1)
    done = sorted({"t00", "t01", "t10", "t11"} - set(first.failed))
    assert "t00" in first.failed and done     # (a neighbour reading its strip may fail too)
    dry = {c["key"] for c in first.chunks if c["ground_reach"] == 0}     # t11: the lake
    assert sorted(p.name for p in (out / cc.STATE_DIR).glob("*.gap.npz")) == [
        f"{k}.gap.npz" for k in done if k not in dry] != []
    assert first.settings["gap_distance"] == cc.Catalog.open(str(d)).default_max_distance()
    (d / "t00.laz").write_bytes(good)
    second = cc.run_catalog(str(d), out, ground_filter="keep", cell_size=CELL, buffer=0.0,
                            workers=1)
    assert not second.failed and sorted(second.skipped) == done
    assert second.settings["gap_distance"] == clean.settings["gap_distance"]
    for key in ("t00", "t01", "t10", "t11"):
        a, b = (_dtm(p / f"{key}_dtm.tif") for p in (tmp_path / "clean", out))
        assert np.array_equal(np.isfinite(a), np.isfinite(b)), key
        assert np.array_equal(a[np.isfinite(a)], b[np.isfinite(b)]), key
    assert not list((out / cc.STATE_DIR).glob("*.gap.npz"))
    shutil.rmtree(tmp_path / "clean")

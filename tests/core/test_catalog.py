"""Tile catalog on Dask: catalog run == merged-cloud run, resume, retry, cluster, bad input."""
from __future__ import annotations

import json
import os
import shutil
import socket
import struct
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from geomatics_toolbox.core.errors import InputError
from geomatics_toolbox.core.io.catalog import find_tiles, read_box
from geomatics_toolbox.core.io.las import PointData, read_las
from geomatics_toolbox.core.io.raster import read_raster
from geomatics_toolbox.core.lidar import catalog as cc
from geomatics_toolbox.core.lidar._chunks import GROUND_FILTERS, snap_grid
from geomatics_toolbox.core.lidar.filters import classify_points, default_selection, ground_filter
from geomatics_toolbox.core.terrain.grid import default_max_distance, grid_from_points
from geomatics_toolbox.core.terrain.idw import idw_grid
from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile

pytest.importorskip("distributed")

SIDE = 250.0
ORIGIN = (500_000.0, 4_000_000.0)
BUFFER = 120.0
CELL = 2.0


@pytest.fixture(scope="module")
def tiles(tmp_path_factory) -> Path:
    """Four adjacent 250 m tiles of about 50 000 points each (2 x 2)."""
    d = tmp_path_factory.mktemp("tiles")
    for i in range(2):
        for j in range(2):
            t = generate_tile(extent=(SIDE, SIDE), origin=(ORIGIN[0] + SIDE * i,
                                                           ORIGIN[1] + SIDE * j),
                              density=0.8, seed=10 * i + j)
            write_tile(t, d / f"t{i}{j}.laz")
    return d


def _merged(tiles: Path):
    paths = find_tiles(str(tiles))
    parts = [read_las(p, ("classification",)) for p in paths]
    x = np.concatenate([p.x for p in parts])
    y = np.concatenate([p.y for p in parts])
    z = np.concatenate([p.z for p in parts])
    cls0 = np.concatenate([p["classification"] for p in parts])
    return paths, x, y, z, cls0


def _filter(key, x, y, z, cls0):
    """A single-file run of the merged cloud: same filter and selection (the chunks' and
    the single file's grids both lie on the world lattice, whatever the catalog origin)."""
    return classify_points(PointData(x, y, z, {"classification": cls0}), ground_filter(key),
                           default_selection(key))


def _catalog_classes(paths, out: Path) -> np.ndarray:
    return np.concatenate([read_las(out / f"{Path(p).stem}_classified.laz",
                                    ("classification",))["classification"] for p in paths])


def _dtm(path) -> np.ndarray:
    r = read_raster(path)
    data = r.data.astype(np.float64)
    data[data == r.nodata] = np.nan
    return data


def _outer_distance(x, y, extent):
    return np.minimum.reduce([x - extent[0], y - extent[1], extent[2] - x, extent[3] - y])


@pytest.fixture(scope="module")
def local_run(tiles, tmp_path_factory):
    out = tmp_path_factory.mktemp("out_local")
    res = cc.run_catalog(str(tiles), out, ground_filter="lsq_improved", cell_size=CELL,
                         buffer=BUFFER, workers=2)
    return out, res


def test_catalog_equals_merged_run(tiles, local_run):
    out, res = local_run
    assert not res.failed and len(res.chunks) == 4
    # each neighbour tile read once as a strip for all its neighbours, not whole per chunk
    assert all(c["phases"]["strips"][1] >= 0 for c in res.chunks)
    paths, x, y, z, cls0 = _merged(tiles)
    cat = cc.Catalog.open(str(tiles))
    merged = _filter("lsq_improved", x, y, z, cls0)
    got = _catalog_classes(paths, out)
    assert got.shape == merged.shape == (cat.n_points,)
    inner = _outer_distance(x, y, cat.extent) > BUFFER
    assert inner.sum() > 20_000
    assert np.array_equal(got[inner], merged[inner])
    assert np.mean(got == merged) >= 0.999
    # DTM: IDW on the merged ground onto the same global lattice
    g = merged == 2
    grid = snap_grid(cat.extent, res.settings["origin"], CELL)
    # the gap distance of a single-file run on the catalog's classified tiles merged
    # (their ground's grid and count; classes differ from `merged` near the outer edge)
    gc = got == 2
    gap = default_max_distance(grid_from_points(x[gc], y[gc], CELL), int(gc.sum()))
    assert res.settings["gap_distance"] == gap
    ref = idw_grid(x[g], y[g], z[g], grid, max_distance=gap, workers=1, tie_order="xy")
    mosaic = _dtm(out / "dtm.vrt")
    assert mosaic.shape == ref.shape
    both = np.isfinite(ref) & np.isfinite(mosaic)
    assert both.mean() > 0.95
    assert np.array_equal(np.isfinite(ref), np.isfinite(_dtm(out / "dtm.vrt")))
    cx, cy = grid.block_centers(0, grid.nrows)
    away = (_outer_distance(cx, cy, cat.extent) > BUFFER).reshape(grid.shape) & both
    assert away.sum() > 5_000
    assert np.max(np.abs(mosaic[away] - ref[away])) <= 1e-3
    assert np.mean(np.abs(mosaic[both] - ref[both]) <= 1e-3) >= 0.99


def test_buffered_read_keeps_only_the_box(tiles):
    paths = find_tiles(str(tiles))
    box = (ORIGIN[0] + 200, ORIGIN[1] + 200, ORIGIN[0] + 300, ORIGIN[1] + 300)
    pd, src = read_box(paths, box, ("classification",), chunk_size=7_000)
    _, x, y, _, _ = _merged(tiles)
    inside = (x >= box[0]) & (x <= box[2]) & (y >= box[1]) & (y <= box[3])
    assert len(pd) == inside.sum() and set(np.unique(src)) == {0, 1, 2, 3}
    assert np.all((pd.x >= box[0]) & (pd.x <= box[2]) & (pd.y >= box[1]) & (pd.y <= box[3]))


def test_resume_and_retry(tiles, tmp_path, monkeypatch):
    out = tmp_path / "out"
    monkeypatch.setenv("GEOMATICS_TEST_FAIL_ONCE", "t01")
    first = cc.run_catalog(str(tiles), out, ground_filter="keep", cell_size=CELL,
                           buffer=50.0, workers=2)
    monkeypatch.delenv("GEOMATICS_TEST_FAIL_ONCE")
    assert not first.failed and len(first.chunks) == 4     # t01 failed once, retried
    # "interrupt": forget two finished chunks as if the run had stopped before them
    for stem in ("t10", "t11"):
        (out / ".catalog" / f"{stem}.done.json").unlink()
        (out / f"{stem}_dtm.tif").unlink()
    mtime = (out / "t00_classified.laz").stat().st_mtime_ns
    second = cc.run_catalog(str(tiles), out, ground_filter="keep", cell_size=CELL,
                            buffer=50.0, workers=1)
    assert sorted(second.skipped) == ["t00", "t01"]
    assert sorted(c["key"] for c in second.chunks if c["key"] not in second.skipped) == \
        ["t10", "t11"]
    assert (out / "t00_classified.laz").stat().st_mtime_ns == mtime
    assert second.points == sum(c["points"] for c in second.chunks
                                if c["key"] in ("t10", "t11"))


def test_cancel_keeps_finished_and_removes_unfinished(tiles, tmp_path):
    out = tmp_path / "out"
    calls = []

    def cancel():
        calls.append(1)
        return len(calls) > 3

    with pytest.raises(cc.Cancelled):
        cc.run_catalog(str(tiles), out, ground_filter="lsq_faithful", cell_size=CELL,
                       buffer=50.0, workers=1, cancel=cancel)
    if not any((out / ".catalog").glob("*.done.json")):     # cancelled before any chunk
        assert not out.exists()         # finished: nothing left (test_catalog_resume.py)
        return
    leftovers = [p.name for p in out.iterdir() if ".part-" in p.name]
    assert leftovers == []
    for marker in (out / ".catalog").glob("*.done.json"):
        stem = marker.name.split(".")[0]
        assert (out / f"{stem}_classified.laz").exists()


def test_bad_inputs(tiles, tmp_path):
    with pytest.raises(InputError, match="contains input tiles"):
        cc.run_catalog(str(tiles), tiles, ground_filter="keep")
    other = tmp_path / "utm33"
    other.mkdir()
    shutil.copy(tiles / "t00.laz", other / "a.laz")
    write_tile(generate_tile(extent=(50.0, 50.0), density=0.5), other / "b.laz",
               crs="EPSG:32633")
    with pytest.raises(InputError, match="different CRSs"):
        cc.Catalog.open(str(other))
    with pytest.raises(InputError, match="No LAS/LAZ tile"):
        cc.Catalog.open(str(tmp_path / "nothing*.laz"))
    with pytest.raises(InputError, match="Unknown ground filter"):
        cc.run_catalog(str(tiles), tmp_path / "o", ground_filter="nope")
    bad = tmp_path / "bad"
    bad.mkdir()
    (bad / "junk.laz").write_bytes(b"not a point cloud" * 10)
    with pytest.raises(InputError, match=r"1 tile\(s\) cannot be read \(junk\.laz: .*not "
                                         r"a LAS/LAZ file") as err:
        cc.Catalog.open(str(bad))
    assert err.value.template.startswith("{n} tile(s) cannot be read")


def test_vpc_input(tiles, tmp_path):
    feats = [{"type": "Feature", "assets": {"data": {"href": str(p)}}}
             for p in sorted(tiles.glob("*.laz"))]
    vpc = tmp_path / "cat.vpc"
    vpc.write_text(json.dumps({"type": "FeatureCollection", "features": feats}))
    cat = cc.Catalog.open(str(vpc))
    assert len(cat.tiles) == 4 and cat.extent == pytest.approx(
        (ORIGIN[0], ORIGIN[1], ORIGIN[0] + 2 * SIDE, ORIGIN[1] + 2 * SIDE), abs=0.05)
    assert cat.query((ORIGIN[0] + 10, ORIGIN[1] + 10, ORIGIN[0] + 20, ORIGIN[1] + 20)) == [0]


def _free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


@pytest.fixture
def dask_cluster(tmp_path):
    """A real ``dask scheduler`` and two ``dask worker`` processes on 127.0.0.1."""
    dask_bin = Path(sys.executable).with_name("dask")
    if not dask_bin.exists():
        pytest.skip("the dask command-line tool is not installed")
    port = _free_port()
    addr = f"tcp://127.0.0.1:{port}"
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(
        [str(Path(sys.executable).parents[1] / "plugin-path"),
         os.environ.get("PYTHONPATH", "")]))
    log = open(tmp_path / "dask.log", "w")
    procs = [subprocess.Popen([str(dask_bin), "scheduler", "--host", "127.0.0.1", "--port",
                               str(port), "--dashboard-address", ":0"],
                              env=env, stdout=log, stderr=log, start_new_session=True)]
    try:
        for _ in range(2):
            procs.append(subprocess.Popen(
                [str(dask_bin), "worker", addr, "--nthreads", "1", "--nworkers", "1",
                 "--host", "127.0.0.1", "--no-dashboard"],
                env=env, stdout=log, stderr=log, start_new_session=True))
        from distributed import Client
        with Client(addr, timeout="30s") as client:
            client.wait_for_workers(2, timeout=60)
        yield addr
    finally:
        for p in procs:
            p.terminate()
        for p in procs:
            try:
                p.wait(timeout=15)
            except subprocess.TimeoutExpired:
                p.kill()
                p.wait(timeout=5)
        log.close()


def test_external_cluster_matches_local(tiles, tmp_path, dask_cluster):
    local = tmp_path / "local"
    remote = tmp_path / "remote"
    cc.run_catalog(str(tiles), local, ground_filter="lsq_faithful", cell_size=CELL,
                   buffer=60.0, workers=1)
    res = cc.run_catalog(str(tiles), remote, ground_filter="lsq_faithful", cell_size=CELL,
                         buffer=60.0, scheduler=dask_cluster)
    assert not res.failed and res.scheduler == dask_cluster
    assert len({c["worker"] for c in res.chunks}) == 2
    paths = find_tiles(str(tiles))
    assert np.array_equal(_catalog_classes(paths, local), _catalog_classes(paths, remote))
    a = _dtm(local / "dtm.vrt")
    b = _dtm(remote / "dtm.vrt")
    assert np.array_equal(np.isnan(a), np.isnan(b)) and np.nanmax(np.abs(a - b)) == 0.0


def test_chunk_failing_twice_is_reported_and_others_finish(tiles, tmp_path):
    src = tmp_path / "tiles"
    shutil.copytree(tiles, src)
    data = bytearray((src / "t11.laz").read_bytes())
    # points cut and the chunk-table offset set to "unknown" (-1, as streaming writers
    # leave it): damage the header cannot reveal, so it fails in its worker (a plainly
    # truncated tile is refused up front: test_hostile_catalog)
    cut = data[:len(data) // 2]
    struct.pack_into("<q", cut, struct.unpack_from("<I", cut, 96)[0], -1)
    (src / "t11.laz").write_bytes(bytes(cut))
    out = tmp_path / "out"
    res = cc.run_catalog(str(src), out, ground_filter="keep", cell_size=CELL, buffer=0.0,
                         workers=2)
    assert list(res.failed) == ["t11"] and "truncated or corrupt" in res.failed["t11"]
    assert sorted(c["key"] for c in res.chunks) == ["t00", "t01", "t10"]
    assert not (out / "t11_classified.laz").exists()
    assert not [p for p in out.iterdir() if ".part-" in p.name]
    assert read_raster(out / "dtm.vrt").data.shape == (250, 250)


# ---------------------------------------------------------------- regular chunk sizes
CHUNK = 200.0    # cuts across the 250 m tiles: chunk edges at 200 and 400 m


def _sorted_classes(x, y, z, cls):
    """Classes ordered by coordinates (cm integers): matches points across files."""
    order = np.lexsort((np.round(z * 100), np.round(y * 100), np.round(x * 100)))
    return cls[order], order


def _chunk_outputs(out: Path):
    parts = [read_las(p, ("classification",)) for p in sorted(out.glob("chunk_*.laz"))]
    return (np.concatenate([p.x for p in parts]), np.concatenate([p.y for p in parts]),
            np.concatenate([p.z for p in parts]),
            np.concatenate([p["classification"] for p in parts]), len(parts))


@pytest.fixture(scope="module")
def big_tiles(tmp_path_factory) -> Path:
    """Four adjacent 400 m tiles (2 x 2, 80 000 points each): room for a 240 m buffer."""
    d = tmp_path_factory.mktemp("big_tiles")
    for i in range(2):
        for j in range(2):
            t = generate_tile(extent=(400.0, 400.0), origin=(ORIGIN[0] + 400.0 * i,
                                                             ORIGIN[1] + 400.0 * j),
                              density=0.5, seed=20 + 10 * i + j)
            write_tile(t, d / f"b{i}{j}.laz")
    return d


# the improved LSQ's reach: each of its 4 levels (100, 50, 25, 12.5 m tiles, windows
# grown by 25 %) seeds the next, so 1.25 x 187.5 m = 234 m of data shape a point's class
LSQ_IMPROVED_REACH = 240.0


@pytest.fixture(scope="module")
def chunk_run(big_tiles, tmp_path_factory):
    out = tmp_path_factory.mktemp("out_chunks")
    res = cc.run_catalog(str(big_tiles), out, ground_filter="lsq_improved", cell_size=CELL,
                         buffer=LSQ_IMPROVED_REACH, chunk_size=300.0, workers=2)
    return out, res


def test_chunk_size_plans_squares_and_reads_only_their_boxes(tiles, tmp_path):
    cat = cc.Catalog.open(str(tiles))
    tasks = cc.plan_tasks(cat, tmp_path, ground_filter="keep", dtm_method="idw",
                          cell_size=CELL, buffer=30.0, chunk_size=CHUNK)
    assert [t.key for t in tasks] == [f"chunk_{500000 + 200 * i}_{4000000 + 200 * j}"
                                      for j in range(3) for i in range(3)]
    centre = next(t for t in tasks if t.key == "chunk_500200_4000200")
    assert centre.tile is None and len(centre.sources) == 4      # crosses all four tiles
    corner = next(t for t in tasks if t.key == "chunk_500000_4000000")
    assert [Path(p).stem for p in corner.sources] == ["t00"]     # 200 + 30 < 250
    # work estimate (largest first): decoding 4 files + 260^2 m2 vs 1 file + 230^2 m2
    n = cat.n_points / 4
    assert centre.cost == pytest.approx(4 * n + n * 260 ** 2 / SIDE ** 2, rel=0.02)
    assert corner.cost == pytest.approx(n + n * 230 ** 2 / SIDE ** 2, rel=0.02)
    with pytest.raises(InputError, match="multiple of CELL_SIZE"):
        cc.plan_tasks(cat, tmp_path, ground_filter="keep", dtm_method="idw",
                      cell_size=CELL, buffer=30.0, chunk_size=201.0)


def test_chunk_size_run_equals_merged_run(big_tiles, chunk_run):
    """Chunks of 300 m cut across the 400 m tiles; the run equals the merged cloud's."""
    out, res = chunk_run
    assert not res.failed and len(res.chunks) == 9
    assert all(set(c["phases"]) == {"read", "filter", "dtm", "write"} for c in res.chunks)
    _, x, y, z, cls0 = _merged(big_tiles)
    cat = cc.Catalog.open(str(big_tiles))
    merged = _filter("lsq_improved", x, y, z, cls0)
    cx, cy, cz, got, n_files = _chunk_outputs(out)
    assert n_files == 9 and got.size == x.size     # every point in exactly one chunk
    got_sorted, corder = _sorted_classes(cx, cy, cz, got)
    ref_sorted, rorder = _sorted_classes(x, y, z, merged)
    assert np.allclose(cx[corder], x[rorder], atol=0.006)
    inner = _outer_distance(x[rorder], y[rorder], cat.extent) > LSQ_IMPROVED_REACH
    assert inner.sum() > 40_000
    assert np.array_equal(got_sorted[inner], ref_sorted[inner])
    assert np.mean(got_sorted == ref_sorted) >= 0.999
    g = merged == 2
    grid = snap_grid(cat.extent, res.settings["origin"], CELL)
    ref = idw_grid(x[g], y[g], z[g], grid, max_distance=res.settings["gap_distance"],
                   workers=1, tie_order="xy")
    mosaic = _dtm(out / "dtm.vrt")
    assert mosaic.shape == (grid.nrows + 50, grid.ncols + 50)    # 900 m of chunks
    mosaic = mosaic[50:, :grid.ncols]                           # rows from the top
    gx, gy = grid.block_centers(0, grid.nrows)
    away = (_outer_distance(gx, gy, cat.extent) > LSQ_IMPROVED_REACH).reshape(grid.shape)
    away &= np.isfinite(ref) & np.isfinite(mosaic)
    assert away.sum() > 20_000
    assert np.max(np.abs(mosaic[away] - ref[away])) <= 1e-3


def test_tin_dtm_equals_merged_tin_along_internal_edges(tiles, tmp_path):
    from geomatics_toolbox.core.terrain.tin import tin_grid
    out = tmp_path / "tin"
    res = cc.run_catalog(str(tiles), out, ground_filter="keep", dtm_method="tin",
                         cell_size=CELL, buffer=40.0, chunk_size=CHUNK, workers=2)
    assert not res.failed
    _, x, y, z, cls0 = _merged(tiles)
    cat = cc.Catalog.open(str(tiles))
    g = cls0 == 2
    grid = snap_grid(cat.extent, res.settings["origin"], CELL)
    # a single-file TIN's edge limit: twice the gap distance (tin.default_max_edge)
    ref = tin_grid(x[g], y[g], z[g], grid, max_edge=2 * res.settings["gap_distance"]).z
    mosaic = _dtm(out / "dtm.vrt")[50:, :grid.ncols]
    gx, gy = (v.reshape(grid.shape) for v in grid.block_centers(0, grid.nrows))
    e = cat.extent
    edges = [e[0] + 200, e[0] + 250, e[0] + 400]                # chunk and tile edges
    band = np.zeros(grid.shape, bool)
    for k in edges:
        band |= np.abs(gx - k) <= 2 * CELL
        band |= np.abs(gy - (e[1] + k - e[0])) <= 2 * CELL
    sel = band & (_outer_distance(gx, gy, e) > 40.0) & np.isfinite(ref)
    assert sel.sum() > 1_000
    assert np.array_equal(np.isfinite(mosaic[sel]), np.isfinite(ref[sel]))
    assert np.nanmax(np.abs(mosaic[sel] - ref[sel])) <= 1e-3


def test_adaptive_slope_is_anchored_on_the_global_origin(tiles, tmp_path):
    out = tmp_path / "slope"
    res = cc.run_catalog(str(tiles), out, ground_filter="slope_adaptive", cell_size=CELL,
                         buffer=BUFFER, workers=2)
    assert not res.failed and GROUND_FILTERS["slope_adaptive"].tiling
    paths, x, y, z, cls0 = _merged(tiles)
    cat = cc.Catalog.open(str(tiles))
    merged = _filter("slope_adaptive", x, y, z, cls0)
    got = _catalog_classes(paths, out)
    inner = _outer_distance(x, y, cat.extent) > BUFFER
    assert np.array_equal(got[inner], merged[inner])
    assert np.mean(got == merged) >= 0.999


def test_chunks_keep_the_extra_bytes_dimensions_every_tile_has(tiles, tmp_path):
    """Box-mode chunks mix tiles: extra-bytes dimensions common to all are carried over."""
    from geomatics_toolbox.core.io.las import las_info, write_las
    src = tmp_path / "src"
    src.mkdir()
    for k, p in enumerate(find_tiles(str(tiles))):
        pd = read_las(p, ("classification", "intensity"))
        extra = {"hag": "f4", "pulse": "u2"} if k else {"pulse": "u2", "hag": "f4", "only0": "i1"}
        dims = {"classification": pd["classification"], "intensity": pd["intensity"],
                "hag": (pd.z - 90.0).astype("f4"),
                "pulse": (np.arange(len(pd)) % 60000 + k).astype("u2")}
        if not k:
            dims["only0"] = np.ones(len(pd), "i1")
        write_las(src / Path(p).name, pd.x, pd.y, pd.z, dimensions=dims, crs="EPSG:32632",
                  extra_dims=extra)
    out = tmp_path / "out"
    res = cc.run_catalog(str(src), out, ground_filter="keep", cell_size=CELL, buffer=10.0,
                         chunk_size=CHUNK, workers=1)
    assert not res.failed
    files = sorted(out.glob("chunk_*.laz"))
    assert len(files) == 9
    info = las_info(str(files[4]))
    assert dict(info.extra_dims) == {"pulse": "<u2", "hag": "<f4"}    # not only0
    got = [read_las(f, ("hag", "pulse", "intensity")) for f in files]
    x, y, z = (np.concatenate([getattr(p, a) for p in got]) for a in "xyz")
    hag = np.concatenate([p["hag"] for p in got])
    np.testing.assert_allclose(hag, z - 90.0, atol=0.006)             # z rounded to 1 cm
    pulse = np.concatenate([p["pulse"] for p in got])
    ref = [read_las(src / Path(p).name, ("pulse", "intensity")) for p in find_tiles(str(src))]
    want = np.concatenate([p["pulse"] for p in ref])
    rx, ry, rz = (np.concatenate([getattr(p, a) for p in ref]) for a in "xyz")
    _, o1 = _sorted_classes(x, y, z, pulse)
    _, o2 = _sorted_classes(rx, ry, rz, want)
    assert np.array_equal(pulse[o1], want[o2])
    assert np.array_equal(np.concatenate([p["intensity"] for p in got])[o1],
                          np.concatenate([p["intensity"] for p in ref])[o2])


def test_idw_mosaic_equals_the_merged_cloud_10_m_inside(tiles, tmp_path):
    """The chunks' IDW cells equal the merged cloud's IDW to float32 precision.

    Classes kept (``keep``) so only the DTM step is compared; every cell more than
    10 m inside the catalog's outer edge, seams included. Equidistant neighbours are
    ordered by their coordinates in chunks and reference alike (``tie_order='xy'``),
    which does not depend on which other points a chunk holds.
    """
    from geomatics_toolbox.core.io.catalog import build_vrt
    from geomatics_toolbox.core.lidar._chunks import process_chunk
    cat = cc.Catalog.open(str(tiles))
    tasks = cc.plan_tasks(cat, tmp_path, ground_filter="keep", dtm_method="idw",
                          cell_size=CELL, buffer=BUFFER)
    (tmp_path / cc.STATE_DIR).mkdir()
    for t in tasks:
        process_chunk(t)
    build_vrt(str(tmp_path / "m.vrt"), [t.outputs["DTM"] for t in tasks])
    mosaic = _dtm(tmp_path / "m.vrt")
    _, x, y, z, cls0 = _merged(tiles)
    g = cls0 == 2
    grid = snap_grid(cat.extent, tasks[0].origin, CELL)
    ref = idw_grid(x[g], y[g], z[g], grid, max_distance=cat.default_max_distance(),
                   workers=1, tie_order="xy")
    assert mosaic.shape == ref.shape
    assert np.array_equal(np.isfinite(mosaic), np.isfinite(ref))
    cx, cy = (v.reshape(grid.shape) for v in grid.block_centers(0, grid.nrows))
    sel = (_outer_distance(cx, cy, cat.extent) > 10.0) & np.isfinite(ref)
    assert sel.sum() > 50_000
    assert np.max(np.abs(mosaic[sel] - ref[sel])) <= 1e-4

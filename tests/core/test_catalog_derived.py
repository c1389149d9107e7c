"""What filters derive from the whole cloud: a catalog vs the single-file run of its tiles.

A single-file filter derives some values from the whole cloud it is given: the anchor of
its grids and tiles (the cloud's corner), and the recommended filter's density (its
height tolerance: 0.35 x mean spacing within 0.25-0.5 m, and the water cell) and
median count per 5 m cell (the water test). A catalog chunk sees only its tile and
buffer; the catalog's first pass (``catalog.first_pass``, :mod:`core.lidar._summary`)
counts every tile once and gives each chunk the whole catalog's values, so a chunk
derives what a single-file run of the merged cloud derives (before it, 13 inner points
of the density step differed and the lake's water candidates were 105 / 5,410 per chunk
against 48 merged: ``benchmarks/results/catalog_exact.md``).

The recommended filter's canopy scale (``_lowcells``: the coarsest closing at which pits
are rare, over the whole raster) comes from the chunks' canopy tallies after the first
pass (:mod:`core.lidar._canopy`): the forest below.
"""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from geomatics_toolbox.core.errors import InputError
from geomatics_toolbox.core.io.las import PointData, read_las, write_las
from geomatics_toolbox.core.lidar import _chunks
from geomatics_toolbox.core.lidar import _recommended_filter as rf
from geomatics_toolbox.core.lidar import catalog as cc
from geomatics_toolbox.core.lidar import recommended as rec
from geomatics_toolbox.core.lidar.filters import (
    GROUND_FILTERS,
    classify_points,
    default_selection,
    ground_filter,
)
from geomatics_toolbox.synthetic import landscapes
from geomatics_toolbox.synthetic.lidar import generate_tile

X0, Y0 = 500_000.0, 4_000_000.0


def _write(d: Path, parts):
    """Write the tiles; return the points as stored (1 cm), in tile order."""
    d.mkdir(parents=True)
    out = []
    for i, (x, y, z, c) in enumerate(parts):
        write_las(d / f"t{i}.las", x, y, z, dimensions={"classification": c},
                  crs="EPSG:32632", scale=0.01)
        out.append(read_las(d / f"t{i}.las", ("classification",)))
    x, y, z = (np.concatenate([getattr(p, a) for p in out]) for a in "xyz")
    return PointData(x, y, z, {"classification": np.concatenate([p["classification"]
                                                                 for p in out])})


def _density_step(d: Path):
    """Two 300 m tiles at 0.3 and 1.5 pts/m² (the generator's classes, 7 and 18 among them)."""
    parts = []
    for i, rho in enumerate((0.3, 1.5)):
        t = generate_tile(extent=(300.0, 300.0), origin=(X0 + 300 * i, Y0), density=rho,
                          seed=3 + i)
        parts.append((t.x, t.y, t.z, np.asarray(t.classification, np.uint8)))
    return _write(d, parts)


def _halves(d: Path, scene):
    """A 600 m scene, its left half thinned to 0.4, cut into two 300 m tiles (class 1)."""
    rng = np.random.default_rng(0)
    keep = (scene.x >= 300) | (rng.random(scene.x.size) < 0.4)
    x, y, z = scene.x[keep] + X0, scene.y[keep] + Y0, scene.z[keep]
    c = np.ones(x.size, np.uint8)
    return _write(d, [(x[m], y[m], z[m], c[m]) for m in (x < X0 + 300, x >= X0 + 300)])


def _catalog(tiles: Path, out: Path, key: str, buffer: float):
    cat = cc.Catalog.open(str(tiles))
    tasks = cc.plan_tasks(cat, out, ground_filter=key, dtm_method="idw", cell_size=2.0,
                          buffer=buffer)
    (out / cc.STATE_DIR).mkdir(parents=True)
    cc.run_here(cat, tasks, out)     # first pass, chunks, canopy re-runs
    got = np.concatenate([read_las(t.outputs["LAS"], ("classification",))["classification"]
                          for t in tasks])
    return cat, tasks, got


def _inner(pts, cat, buffer):
    e = cat.extent
    return np.minimum.reduce([pts.x - e[0], pts.y - e[1], e[2] - pts.x, e[3] - pts.y]) > buffer


@pytest.fixture(scope="module")
def step(tmp_path_factory):
    d = tmp_path_factory.mktemp("step") / "tiles"
    return d, _density_step(d)


@pytest.mark.parametrize("key", list(GROUND_FILTERS))
def test_density_step_catalog_equals_single_file(step, tmp_path, monkeypatch, key):
    """0.3 / 1.5 pts/m²: every filter's chunks give the single-file classes beyond the
    buffer; the recommended filter's chunks take the merged cloud's tolerance (0.37 m),
    not their own (0.45 / 0.32 m before the first pass)."""
    tiles, pts = step
    seen = []
    derive = rec.derive

    def spy(*a, **k):
        out = derive(*a, **k)
        seen.append(out.threshold)
        return out
    monkeypatch.setattr(rec, "derive", spy)
    cat, _, got = _catalog(tiles, tmp_path / "out", key, 100.0)
    chunks, seen[:] = list(seen), []
    ref = classify_points(pts, ground_filter(key), default_selection(key))
    inner = _inner(pts, cat, 100.0)
    assert inner.sum() > 30_000
    assert np.array_equal(got[inner], ref[inner]), \
        f"{int((got != ref)[inner].sum())} of {int(inner.sum())} inner points differ"
    if key == "groundfilter":
        # each chunk derives once (it counts its canopy blocks while it filters), and t1
        # once more: it ran again at the catalog's canopy scale (:mod:`core.lidar._canopy`)
        assert len(chunks) == 3 * len(seen) and len(set(chunks + seen)) == 1
        assert 0.33 < seen[0] < 0.42
        assert np.array_equal(got, ref)                # every point, the edges too


def test_lake_across_tiles_catalog_equals_single_file(tmp_path, monkeypatch):
    """A 150 m lake across both tiles: the chunks flag the single-file run's water
    candidates and give its classes everywhere once the buffer spans the lake's hole
    (300 m; with 100 m, 69 shore points differ: the hole fill reaches across the lake)."""
    pts = _halves(tmp_path / "tiles", landscapes.lake(extent=600.0, density=2.0,
                                                        radius=150.0, seed=1))
    flags = []
    wc = rf.water_candidates

    def spy(*a, **k):
        out = wc(*a, **k)
        flags.append(int(out.sum()))
        return out
    monkeypatch.setattr(rf, "water_candidates", spy)
    _, _, got = _catalog(tmp_path / "tiles", tmp_path / "out", "groundfilter", 300.0)
    ref = classify_points(pts, ground_filter("groundfilter"),
                          default_selection("groundfilter"))
    # whole scene's candidates in each chunk's filter (no chunk runs again: no canopy)
    assert flags[:2] == flags[2:] * 2 and flags[2] > 100
    assert np.array_equal(got, ref), f"{int((got != ref).sum())} points differ"


def test_forest_canopy_scale_comes_from_the_whole_catalog(tmp_path, monkeypatch):
    """Closed forest, left half thinned: alone, the sparse chunk would read its low outliers
    at a 12 m canopy scale and the merged cloud at 8 m (22 of 503,113 points of the sparse
    tile differed); the chunks' canopy tallies (:mod:`core.lidar._canopy`) add up to the
    merged raster's counts, so both chunks close at 8 m and every point beyond the buffer
    equals the single-file run."""
    pts = _halves(tmp_path / "tiles", landscapes.closed_forest(extent=600.0, density=2.0,
                                                               ground_share=0.05, seed=1))
    from geomatics_toolbox.core.lidar import _lowcells
    scales, tallies = [], []
    low = _lowcells.low_cells

    def spy(*a, **k):
        out = low(*a, **k)
        scales.append(out.canopy_scale)
        if out.counts is not None:                     # a chunk's counts of its blocks
            tallies.append(out.counts)
        return out
    monkeypatch.setattr(rec.L, "low_cells", spy)
    cat, tasks, got = _catalog(tmp_path / "tiles", tmp_path / "out", "groundfilter", 100.0)
    ref = classify_points(pts, ground_filter("groundfilter"),
                          default_selection("groundfilter"))
    # the sparse chunk alone closes at 12 m, the dense one at 8 m; the counts summed give
    # 8 m, so the sparse chunk runs again at 8 m (and only it); the merged run: 8 m
    assert scales == [12.0, 8.0, 8.0, 8.0]
    alone = [_lowcells.choose_factor(t["pits"], t["blocks"]) for t in tallies]
    assert len(tallies) == 3 and alone[0] != alone[1]  # each chunk's own counts disagree
    assert tallies[2] == tallies[0]                    # the re-run counts the same blocks
    assert tasks[0].derived["canopy_factor"] == 8      # 8 cells of 1 m
    assert (tasks[1].derived or {}).get("canopy_factor") is None   # not run again
    inner = _inner(pts, cat, 100.0)
    assert np.array_equal(got[inner], ref[inner]), \
        f"{int((got != ref)[inner].sum())} inner points differ"
    # 3 points in the catalog's outer corner (x < 4 m, y > 589 m, inside the buffer of the
    # outer edge) differ, not from the canopy scale: all three runs close at 8 m (was 22)
    assert (got != ref).sum() <= 3


def test_dask_run_summarises_on_the_strip_decodes(step, tmp_path):
    """Through Dask (run_catalog, 1 local worker): the first pass rides on the strip
    tasks' decodes of the tiles (no second decode), every chunk waits for the merged
    summary (saved in ``.catalog/summary.json`` for a resume), and the classes equal the
    single-file run on every point."""
    tiles, pts = step
    out = tmp_path / "out"
    res = cc.run_catalog(str(tiles), out, ground_filter="groundfilter", buffer=100.0,
                         cell_size=2.0, workers=1)
    assert not res.failed
    got = np.concatenate([read_las(out / f"t{i}_classified.las", ("classification",))
                          ["classification"] for i in range(2)])
    ref = classify_points(pts, ground_filter("groundfilter"),
                          default_selection("groundfilter"))
    assert np.array_equal(got, ref), f"{int((got != ref).sum())} points differ"
    saved = cc._summary.load(out / cc.STATE_DIR)
    assert saved["n"] == len(pts) and saved["corner"] == [float(pts.x.min()),
                                                          float(pts.y.min())]
    assert 0.3 < saved["derived"]["density"] < 1.0 and not saved["derived"]["water_input"]
    cpu = res.settings["first_pass_seconds"][1]
    assert 0 < cpu < sum(c["phases"]["read"][1] for c in res.chunks)   # no decode of its own
    # the chunks' canopy tallies on the workers (from the strips) == in this process
    cat = cc.Catalog.open(str(tiles))
    tasks = cc.plan_tasks(cat, tmp_path / "o2", ground_filter="groundfilter",
                          dtm_method="idw", cell_size=2.0, buffer=100.0)
    (tmp_path / "o2" / cc.STATE_DIR).mkdir(parents=True)
    cc.first_pass(cat, tasks, tmp_path / "o2")
    here = cc._canopy.settle(tasks, [_chunks.process_chunk(t) for t in tasks])
    assert res.settings["canopy_counts"] == [here.pits, here.blocks]
    assert sum(here.blocks) > 0 and res.settings["canopy_factor"] == here.factor
    # the dense tile alone chose another scale: it ran again (its classes are checked above)
    assert res.settings["canopy_reruns"] == [t.key for t in here.redo] == ["t1"]


def _classes(out: Path, n: int = 2):
    return np.concatenate([read_las(out / f"t{i}_classified.las", ("classification",))
                           ["classification"] for i in range(n)])


def _provisional(tiles: Path, out: Path):
    """Every chunk finished at its own canopy scale, no settle (a crash): tasks, factors."""
    cat = cc.Catalog.open(str(tiles))
    tasks = cc.plan_tasks(cat, out, ground_filter="groundfilter", dtm_method="idw",
                          cell_size=2.0, buffer=100.0)
    (out / cc.STATE_DIR).mkdir(parents=True)
    cc.first_pass(cat, tasks, out)
    own = [_chunks.process_chunk(t)["canopy"]["factor"] for t in tasks]   # provisional
    cc.write_settings(out, cc._run_settings(tasks, cat))
    return tasks, own


def test_resume_of_provisional_chunks_runs_the_disagreeing_one_again(step, tmp_path):
    """Every chunk finished at its own canopy scale, the run stopped before settling (a
    crash): the resume has no chunk to run but sums the done markers' counts and runs
    the chunk whose scale disagrees again (t1 alone closes at 3 cells, the catalog's
    counts give 6; its classes come out the same either way here - the forest test shows
    a scale that changes them); the classes are the single-file run's."""
    tiles, pts = step
    out = tmp_path / "out"
    tasks, own = _provisional(tiles, out)
    ref = classify_points(pts, ground_filter("groundfilter"),
                          default_selection("groundfilter"))
    res = cc.run_catalog(str(tiles), out, ground_filter="groundfilter", buffer=100.0,
                         cell_size=2.0, workers=1)
    assert res.settings["canopy_reruns"] == ["t1"] and res.skipped == ["t0"]
    assert own[1] != res.settings["canopy_factor"] and own[0] in (0, res.settings[
        "canopy_factor"])
    got = _classes(out)
    assert np.array_equal(got, ref), f"{int((got != ref).sum())} points differ"
    marker = json.loads(Path(tasks[1].outputs["DONE"]).read_text())
    assert marker["canopy"]["factor"] == res.settings["canopy_factor"]
    again = cc.run_catalog(str(tiles), out, ground_filter="groundfilter", buffer=100.0,
                           cell_size=2.0, workers=1)
    assert again.settings["canopy_reruns"] == [] and again.skipped == ["t0", "t1"]


def test_cancel_in_the_canopy_reruns_keeps_the_chunks_and_the_resume_settles(step, tmp_path):
    """Cancelled after every chunk finished, when the disagreeing chunk runs again: the
    finished chunks are kept (not undone) and the resume settles. A cancelled Dask task
    may still finish on its worker, so t1's marker holds its own scale (the resume runs
    it again) or the catalog's (nothing left to run); either way the resumed classes
    are the single-file run's."""
    tiles, pts = step
    out = tmp_path / "out"
    seen = []
    with pytest.raises(cc.Cancelled):
        cc.run_catalog(str(tiles), out, ground_filter="groundfilter", buffer=100.0,
                       cell_size=2.0, workers=1, on_chunk=seen.append,
                       cancel=lambda: len(seen) == 2)
    assert sorted(cc.finished_chunks(out)) == ["t0", "t1"]
    marker = json.loads((out / cc.STATE_DIR / "t1.done.json").read_text())
    res = cc.run_catalog(str(tiles), out, ground_filter="groundfilter", buffer=100.0,
                         cell_size=2.0, workers=1)
    f, kept = res.settings["canopy_factor"], marker["canopy"]["factor"]
    assert f == 6 and kept in (3, 6)                   # t1's own scale, or the catalog's
    assert res.settings["canopy_reruns"] == ([] if kept == f else ["t1"])
    ref = classify_points(pts, ground_filter("groundfilter"),
                          default_selection("groundfilter"))
    got = _classes(out)
    assert np.array_equal(got, ref), f"{int((got != ref).sum())} points differ"


def test_resume_with_only_reruns_left_refuses_a_missing_summary(step, tmp_path):
    """Every chunk finished at its own scale and summary.json lost: t1's re-run would
    classify without the catalog's corner and density (6 points differed from the
    single-file run, and its new marker lacked its counts), so the resume is refused as
    a resume with chunks left to run is (0475c85), and nothing is touched."""
    tiles, _ = step
    out = tmp_path / "out"
    tasks, own = _provisional(tiles, out)
    assert own[1] == 3                                    # the catalog's factor is 6
    (out / cc.STATE_DIR / "summary.json").unlink()
    before = {t.key: Path(t.outputs["DONE"]).read_text() for t in tasks}
    with pytest.raises(InputError) as err:
        cc.run_catalog(str(tiles), out, ground_filter="groundfilter", buffer=100.0,
                       cell_size=2.0, workers=1)
    assert "holds finished chunks of an earlier run" in str(err.value)
    assert f"{cc.STATE_DIR}/summary.json" in str(err.value)
    assert {t.key: Path(t.outputs["DONE"]).read_text() for t in tasks} == before


def test_failed_canopy_rerun_is_not_reported_done_and_the_resume_settles(
        step, tmp_path, monkeypatch):
    """t1's re-run at the catalog's scale fails (as ``_collect`` records it): t1 is failed,
    not a finished chunk at its own scale, not a re-run, its seconds not counted; its
    marker keeps its own scale, so the resume runs it again and the classes are the
    single-file run's."""
    from geomatics_toolbox.core.lidar import _dask_run
    tiles, pts = step
    out = tmp_path / "out"
    events = []

    def failing(client, redo, mon, failed, on_chunk=None):
        for t in redo:
            failed[t.key] = "RuntimeError: simulated"
            on_chunk({"key": t.key, "status": "failed", "error": failed[t.key]})
        return []
    with monkeypatch.context() as m:
        m.setattr(_dask_run, "_rerun", failing)
        res = cc.run_catalog(str(tiles), out, ground_filter="groundfilter", buffer=100.0,
                             cell_size=2.0, workers=1, on_chunk=events.append)
    assert list(res.failed) == ["t1"] and res.settings["canopy_factor"] == 6
    assert [c["key"] for c in res.chunks] == ["t0"]
    assert res.chunks[0]["canopy"]["factor"] == 6
    assert res.settings["canopy_reruns"] == [] and res.settings["canopy_seconds"] == [0, 0]
    assert [e["key"] for e in events if e["status"] == "failed"] == ["t1"]
    marker = json.loads((out / cc.STATE_DIR / "t1.done.json").read_text())
    assert marker["canopy"]["factor"] == 3
    again = cc.run_catalog(str(tiles), out, ground_filter="groundfilter", buffer=100.0,
                           cell_size=2.0, workers=1)
    assert again.settings["canopy_reruns"] == ["t1"] and again.skipped == ["t0"]
    assert not again.failed
    ref = classify_points(pts, ground_filter("groundfilter"),
                          default_selection("groundfilter"))
    got = _classes(out)
    assert np.array_equal(got, ref), f"{int((got != ref).sum())} points differ"


@pytest.fixture(scope="module")
def small_scenes(tmp_path_factory):
    """The lake and the forest at 300 m (two 150 m tiles, left half thinned), made once."""
    made = {}

    def get(kind):
        if kind not in made:
            d = tmp_path_factory.mktemp(kind) / "tiles"
            s = (landscapes.lake(extent=300.0, density=2.0, radius=75.0, seed=2)
                 if kind == "lake" else
                 landscapes.closed_forest(extent=300.0, density=2.0, ground_share=0.05,
                                          seed=2))
            rng = np.random.default_rng(1)
            keep = (s.x >= 150) | (rng.random(s.x.size) < 0.4)
            x, y, z = s.x[keep] + X0, s.y[keep] + Y0, s.z[keep]
            c = np.ones(x.size, np.uint8)
            made[kind] = d, _write(d, [(x[m], y[m], z[m], c[m])
                                       for m in (x < X0 + 150, x >= X0 + 150)])
        return made[kind]
    return get


@pytest.mark.parametrize("kind", ["lake", "forest"])
@pytest.mark.parametrize("key", [k for k in GROUND_FILTERS if k != "groundfilter"])
def test_lake_and_forest_catalog_equals_single_file(small_scenes, tmp_path, kind, key):
    """The filters that derive only their anchor from the whole cloud: a lake across the
    two tiles and a closed forest of two densities give the single-file classes beyond
    the buffer."""
    tiles, pts = small_scenes(kind)
    cat, _, got = _catalog(tiles, tmp_path / "out", key, 100.0)
    ref = classify_points(pts, ground_filter(key), default_selection(key))
    inner = _inner(pts, cat, 100.0)                # the lake's middle is sparse water
    assert inner.sum() > (1_000 if kind == "lake" else 10_000)
    assert np.array_equal(got[inner], ref[inner]), \
        f"{int((got != ref)[inner].sum())} of {int(inner.sum())} inner points differ"

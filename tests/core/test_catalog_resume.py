"""A resumed catalog run never reuses a stale first pass or mixes tile sets (issue 20).

The first pass (:mod:`core.lidar._summary`) is saved in ``.catalog/summary.json`` with the
signature of what it was made of (tiles: name, bytes, modification time, points, header
bounds; filter; buffer). A resume reuses it only for the same; a tile rewritten in place
(same name and point count) once made a resume reuse the old density silently. With
finished chunks made from the old tiles, a resume is refused (translated, tiles named);
without, the stale state is replaced and the first pass recomputed.

Cancel, failure or SIGTERM before any chunk finished (during the first pass) leave the
output folder as the run found it and the tiles byte-identical.
"""
from __future__ import annotations

import hashlib
import json
import os
import signal
import struct
import subprocess
import sys
import textwrap
from pathlib import Path

import numpy as np
import pytest

from geomatics_toolbox.core.errors import InputError
from geomatics_toolbox.core.io.las import read_las, write_las
from geomatics_toolbox.core.lidar import catalog as cc
from geomatics_toolbox.synthetic.lidar import generate_tile

pytest.importorskip("distributed")

X0, Y0 = 500_000.0, 4_000_000.0
SIDE = 150.0
OPTS = dict(ground_filter="groundfilter", cell_size=2.0, buffer=50.0, workers=1)


def _tile(path: Path, i: int, *, density: float, seed: int, n=None, width=SIDE, gap=0.0):
    t = generate_tile(extent=(width, SIDE), origin=(X0 + (SIDE + gap) * i, Y0),
                      density=density, seed=seed)
    k = slice(None) if n is None else slice(0, n)
    write_las(path, t.x[k], t.y[k], t.z[k],
              dimensions={"classification": np.asarray(t.classification, np.uint8)[k]},
              crs="EPSG:32632", scale=0.01)


@pytest.fixture()
def tiles(tmp_path) -> Path:
    d = tmp_path / "tiles"
    d.mkdir()
    _tile(d / "t0.las", 0, density=0.5, seed=1)
    _tile(d / "t1.las", 1, density=0.5, seed=2)
    return d


def _rewrite_denser(d: Path, gap: float = 0.0) -> None:
    """t1 rewritten in place: the same name and point count, twice the density (half the
    width), so the catalog's density (the recommended filter's tolerance) changes."""
    n = read_las(d / "t1.las").x.size
    _tile(d / "t1.las", 1, density=2.5, seed=7, n=n, width=SIDE / 2, gap=gap)
    assert read_las(d / "t1.las").x.size == n


def _classes(out: Path) -> np.ndarray:
    return np.concatenate([read_las(out / f"t{i}_classified.las", ("classification",))
                           ["classification"] for i in range(2)])


def _derived(out: Path) -> dict:
    s = cc._summary.load(out / cc.STATE_DIR)
    return {k: s[k] for k in ("n", "corner", "derived")}


def _listing(folder: Path) -> dict:
    return {str(p.relative_to(folder)): (p.read_bytes() if p.is_file() else None)
            for p in sorted(folder.rglob("*"))}


def _digests(d: Path) -> dict:
    return {p.name: hashlib.sha1(p.read_bytes()).hexdigest() for p in sorted(d.iterdir())}


def test_tile_rewritten_in_place_with_finished_chunks_refused(tiles, tmp_path):
    out = tmp_path / "out"
    cc.run_catalog(str(tiles), out, **OPTS)
    (out / cc.STATE_DIR / "t1.done.json").unlink()          # "interrupted" before t1
    _rewrite_denser(tiles)
    before = _listing(out)
    with pytest.raises(InputError, match=r"tiles changed since the earlier run .*\(t1\.las: "
                                         r"changed\); its finished chunks") as err:
        cc.run_catalog(str(tiles), out, **OPTS)
    assert _listing(out) == before                          # nothing touched
    for lang in ("ar", "fa"):                               # translated, the tile named
        msg = err.value.message(lang)
        assert "t1.las" in msg and "tiles changed" not in msg and "changed" not in msg


def test_tile_added_or_removed_with_finished_chunks_refused(tiles, tmp_path):
    out = tmp_path / "out"
    cc.run_catalog(str(tiles), out, **OPTS)
    (out / cc.STATE_DIR / "t1.done.json").unlink()
    _tile(tiles / "t2.las", 2, density=0.5, seed=3)
    with pytest.raises(InputError, match=r"\(t2\.las: new\)"):
        cc.run_catalog(str(tiles), out, **OPTS)
    with pytest.raises(InputError, match=r"\(t2\.las: new; t1\.las: gone\)"):
        cc.run_catalog([str(tiles / "t0.las"), str(tiles / "t2.las")], out, **OPTS)


def test_stale_first_pass_recomputed_when_no_chunk_finished(tiles, tmp_path):
    """A run stopped after its first pass (summary saved, no chunk finished), then a tile
    rewritten in place: the rerun recomputes the first pass and equals a fresh run."""
    out = tmp_path / "out"
    cc.run_catalog(str(tiles), out, **OPTS)
    for i in range(2):
        (out / cc.STATE_DIR / f"t{i}.done.json").unlink()
    stale = _derived(out)
    _rewrite_denser(tiles)
    res = cc.run_catalog(str(tiles), out, **OPTS)
    fresh_out = tmp_path / "fresh"
    fresh = cc.run_catalog(str(tiles), fresh_out, **OPTS)
    assert _derived(fresh_out) != stale                     # the rewrite moved the density
    assert _derived(out) == _derived(fresh_out)
    assert np.array_equal(_classes(out), _classes(fresh_out))
    assert res.settings["first_pass"] == "run" and res.settings["first_pass_seconds"][1] > 0
    assert fresh.settings["first_pass"] == "run"


def test_resume_reuses_a_valid_first_pass_and_says_it_spent_nothing(tiles, tmp_path):
    out = tmp_path / "out"
    first = cc.run_catalog(str(tiles), out, **OPTS)
    assert first.settings["first_pass"] == "run" and first.settings["first_pass_seconds"][1] > 0
    saved = json.loads((out / cc.STATE_DIR / "summary.json").read_text())
    assert saved["signature"]["tiles"][1][:1] == ["t1.las"]
    (out / cc.STATE_DIR / "t1.done.json").unlink()
    again = cc.run_catalog(str(tiles), out, **OPTS)
    assert again.skipped == ["t0"]
    assert again.settings["first_pass"] == "reused"
    assert again.settings["first_pass_seconds"] == [0.0, 0.0]   # was the first run's
    # the chunks count their canopy blocks while they classify: no task of its own, and
    # no chunk runs again where every chunk chose the catalog's factor (or had no canopy)
    assert first.settings["canopy_reruns"] == again.settings["canopy_reruns"] == []
    assert first.settings["canopy_seconds"] == again.settings["canopy_seconds"] == [0.0, 0.0]
    assert again.settings["canopy_counts"] == first.settings["canopy_counts"]
    assert json.loads((out / cc.STATE_DIR / "summary.json").read_text()) == saved


def test_summary_of_an_older_version_recomputed(tiles, tmp_path):
    """A summary without a signature (or of another filter) is not trusted: with no
    chunk finished it is recomputed."""
    out = tmp_path / "out"
    cc.run_catalog(str(tiles), out, **OPTS)
    path = out / cc.STATE_DIR / "summary.json"
    s = json.loads(path.read_text())
    del s["signature"]
    s["derived"]["density"] *= 3                            # what a stale pass would give
    path.write_text(json.dumps(s))
    for i in range(2):
        (out / cc.STATE_DIR / f"t{i}.done.json").unlink()
    res = cc.run_catalog(str(tiles), out, **OPTS)
    assert res.settings["first_pass"] == "run"
    assert json.loads(path.read_text())["derived"]["density"] == pytest.approx(
        s["derived"]["density"] / 3, rel=1e-12)


@pytest.mark.parametrize("damage", ["older", "missing"])
def test_untrusted_summary_with_finished_chunks_refused(tiles, tmp_path, damage):
    """With a chunk finished, a summary that cannot be trusted (older version, deleted)
    is refused for the recommended filter: the canopy tallies of a recomputed first pass
    would cover the unfinished chunks only, a scale the finished ones were not made with
    (it used to be recomputed from them)."""
    out = tmp_path / "out"
    cc.run_catalog(str(tiles), out, **OPTS)
    path = out / cc.STATE_DIR / "summary.json"
    if damage == "older":
        s = json.loads(path.read_text())
        del s["signature"]
        path.write_text(json.dumps(s))
    else:
        path.unlink()
    (out / cc.STATE_DIR / "t1.done.json").unlink()
    before = _listing(out)
    with pytest.raises(InputError, match=r"finished chunks of an earlier run but not the "
                                         r"values they were made with \(\.catalog/summary"
                                         r"\.json: missing") as err:
        cc.run_catalog(str(tiles), out, **OPTS)
    assert _listing(out) == before                          # nothing touched
    for lang in ("ar", "fa"):
        msg = err.value.message(lang)
        assert str(out) in msg and "canopy" not in msg


@pytest.mark.parametrize("damage", ["no canopy", "no factor", "factor 5", "short pits",
                                    "text blocks"])
def test_finished_chunk_without_canopy_counts_refused(tiles, tmp_path, damage):
    """A done marker without the chunk's canopy counts (written by an older version) or
    with damaged ones (no factor: a KeyError in the settle before) is refused: the
    catalog's canopy scale is chosen from every chunk's counts, and that chunk's cannot
    be summed (nothing is touched; the marker is named)."""
    out = tmp_path / "out"
    cc.run_catalog(str(tiles), out, **OPTS)
    path = out / cc.STATE_DIR / "t0.done.json"
    marker = json.loads(path.read_text())
    canopy = marker["canopy"]
    assert len(canopy["pits"]) == len(canopy["blocks"]) == 7 and canopy["factor"] == 6
    if damage == "no canopy":
        del marker["canopy"]
    elif damage == "no factor":
        del canopy["factor"]
    elif damage == "factor 5":
        canopy["factor"] = 5
    elif damage == "short pits":
        canopy["pits"] = canopy["pits"][:3]
    else:
        canopy["blocks"] = [str(v) for v in canopy["blocks"]]
    path.write_text(json.dumps(marker))
    (out / cc.STATE_DIR / "t1.done.json").unlink()
    before = _listing(out)
    with pytest.raises(InputError, match=r"not the values they were made with "
                                         r"\(\.catalog/t0\.done\.json: missing") as err:
        cc.run_catalog(str(tiles), out, **OPTS)
    assert _listing(out) == before
    for lang in ("ar", "fa"):
        msg = err.value.message(lang)
        assert ".catalog/t0.done.json" in msg and "missing" not in msg


# ------------------------------------------------------------ stopped in the first pass
def test_cancel_during_the_first_pass_leaves_nothing(tiles, tmp_path):
    out = tmp_path / "out"
    sums = _digests(tiles)
    seen = []

    def cancel():                       # polled first right after the tasks are submitted
        seen.append((out / cc.STATE_DIR / "summary.json").exists())
        return True

    with pytest.raises(cc.Cancelled):
        cc.run_catalog(str(tiles), out, cancel=cancel, **OPTS)
    assert seen[:1] == [False]                              # the first pass had not ended
    assert not out.exists()
    assert _digests(tiles) == sums


def test_cancel_in_an_existing_folder_restores_its_state(tiles, tmp_path):
    """A folder already holding a stopped run's state (no chunk finished) keeps it."""
    out = tmp_path / "out"
    out.mkdir()
    (out / "notes.txt").write_text("mine")
    cc.run_catalog(str(tiles), out, **OPTS)
    for p in (out / cc.STATE_DIR).glob("*.done.json"):
        p.unlink()
    for p in out.glob("t*_*"):
        p.unlink()
    (out / "dtm.vrt").unlink()
    before = _listing(out)
    with pytest.raises(cc.Cancelled):
        cc.run_catalog(str(tiles), out, cancel=lambda: True,
                       **{**OPTS, "buffer": 40.0})          # other settings: not refused
    assert _listing(out) == before


def _damaged(tiles: Path, d: Path) -> Path:
    """The tiles with t1 damaged where its header cannot tell (LAZ chunk table unknown)."""
    from geomatics_toolbox.synthetic.lidar import write_tile
    d.mkdir()
    for i in range(2):
        t = generate_tile(extent=(SIDE, SIDE), origin=(X0 + SIDE * i, Y0), density=0.5,
                          seed=i + 1)
        write_tile(t, d / f"t{i}.laz")
    data = bytearray((d / "t1.laz").read_bytes())
    cut = data[:len(data) // 2]
    struct.pack_into("<q", cut, struct.unpack_from("<I", cut, 96)[0], -1)
    (d / "t1.laz").write_bytes(bytes(cut))
    return d


def test_tile_failing_in_the_first_pass_leaves_nothing(tiles, tmp_path):
    """Every chunk waits for the first pass: a tile that fails to decode there fails the
    run, named, and the output folder is not left behind."""
    src = _damaged(tiles, tmp_path / "laz")
    sums = _digests(src)
    out = tmp_path / "out"
    with pytest.raises(InputError, match=r"Every chunk failed \(2 of 2\).*truncated or "
                                         r"corrupt"):
        cc.run_catalog(str(src), out, **OPTS)
    assert not out.exists()
    assert _digests(src) == sums


SIGTERM_SCRIPT = """
import sys
from geomatics_toolbox.core.lidar import catalog as cc
import os
def cancel():                           # polled right after the first pass was submitted
    print("first pass", os.path.exists({summary!r}), flush=True)
    sys.stdin.readline()                # wait for the signal
    return False
cc.run_catalog({src!r}, {out!r}, ground_filter="groundfilter", cell_size=2.0, buffer=50.0,
               workers=1, cancel=cancel)
"""


def test_sigterm_during_the_first_pass_leaves_nothing(tiles, tmp_path):
    out = tmp_path / "out"
    sums = _digests(tiles)
    code = textwrap.dedent(SIGTERM_SCRIPT.format(
        src=str(tiles), out=str(out), summary=str(out / cc.STATE_DIR / "summary.json")))
    proc = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE,
                            stdin=subprocess.PIPE, text=True, start_new_session=True)
    try:
        assert proc.stdout.readline().strip() == "first pass False"
        assert (out / cc.STATE_DIR / "settings.json").exists()      # the run had begun
        proc.send_signal(signal.SIGTERM)
        proc.wait(timeout=120)
    finally:
        if proc.poll() is None:
            os.killpg(proc.pid, signal.SIGKILL)
    assert proc.returncode != 0
    assert not out.exists()
    assert _digests(tiles) == sums


def test_changed_tile_refused_only_when_a_finished_chunk_read_it(tmp_path):
    """``keep`` derives nothing from all the tiles: a finished chunk depends only on the
    tiles its buffered box touches. A tile no finished chunk read (a damaged tile whose
    chunk failed, since repaired) may change; one a finished neighbour read may not."""
    tiles = tmp_path / "tiles"                      # 50 m apart
    tiles.mkdir()
    _tile(tiles / "t0.las", 0, density=0.5, seed=1)
    _tile(tiles / "t1.las", 1, density=0.5, seed=2, gap=50.0)
    opts = {**OPTS, "ground_filter": "keep"}
    near, far = tmp_path / "near", tmp_path / "far"
    cc.run_catalog(str(tiles), near, **{**opts, "buffer": 60.0})
    cc.run_catalog(str(tiles), far, **{**opts, "buffer": 10.0})
    for out in (near, far):
        (out / cc.STATE_DIR / "t1.done.json").unlink()
    _rewrite_denser(tiles, gap=50.0)
    with pytest.raises(InputError, match=r"\(t1\.las: changed\)"):     # t0 read t1's strip
        cc.run_catalog(str(tiles), near, **{**opts, "buffer": 60.0})
    res = cc.run_catalog(str(tiles), far, **{**opts, "buffer": 10.0})    # t0 did not
    assert res.skipped == ["t0"] and not res.failed
    assert np.array_equal(read_las(far / "t1_classified.las").x, read_las(tiles / "t1.las").x)

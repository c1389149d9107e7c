"""What a catalog derives from all of its points before its chunks run (private).

A single-file ground filter derives a few quantities from the whole cloud it is given;
a catalog chunk sees only its tile and buffer. So that a chunk equals a single-file run
of the merged cloud by construction, each such quantity is a function of a small
*summary* that merges exactly (sums, minima): every tile is summarised on a worker
(:func:`summarise`: from the decode a strip task makes of it anyway, else streamed by
:func:`tile_summary`), one task merges the summaries (:func:`final`) and every chunk
receives the result; a single-file run computes the summary of its one cloud with the
same code (:func:`cloud_summary`).

The anchor (every filter but PTD): a filter lays its grids and tiles (LSQ tiles, the
recommended filter's raster and pyramid, the slope filter's trend grid, the low-outlier
pre-filter's cells) on the lattice through the *corner* of the cloud it is given, the
smallest x and y of every point read (:func:`.filters.run_filter`). The catalog's corner
is the smallest over its tiles. (PTD lays its grids on the lattice through 0 in both.)

The recommended filter's density and water test (:func:`recommended_values`): the
points it classifies (input noise 7 and 18 aside, input water 9 counted apart) are
counted per 5 m cell of the world lattice (multiples of 5 m, whatever the extent):
the density is points per m² of occupied cells (its height tolerance and the water
cell come from it) and the water test's "sparse" is relative to the median count per
occupied cell; input water anywhere switches the water candidates off everywhere.
A tile's counts (:func:`cell_counts`) keep by key only the cells another tile's box
touches, the others as a histogram, so the merged counts (and the median) are exact
and a few kilobytes per tile.
"""
from __future__ import annotations

import json
import os
import time
from typing import Optional, Sequence

import numpy as np

from .. import classes as asprs
from ..io.las import iter_las_chunks
from ._checks import highest, lowest  # noqa: F401 - re-exported

__all__ = ["DENSITY_CELL", "SUMMARY_FILE", "cell_counts", "cloud_summary", "final", "load",
           "merge", "recommended_values", "save", "strip_summary", "summarise", "tile_summary",
           "world_cells"]

#: side (m) of the world-lattice cells over which the recommended filter counts density
DENSITY_CELL = 5.0
WATER = int(asprs.WATER)

#: the merged summary of a run, in ``<out>/.catalog/`` (a resumed run reuses it)
SUMMARY_FILE = "summary.json"


def cloud_summary(x, y, classification=None, *, counts: bool = False, keep=None,
                  extent=None) -> dict:
    """Summary of one cloud (metres): what :func:`tile_summary` gives for a tile.

    ``counts``: also the recommended filter's cell counts of the points (the caller
    passes the points that filter sees; class 9 in ``classification`` counted apart).
    ``keep`` (bool per point): summarise those points only (the same as passing them);
    ``extent``: theirs (``_checks.bounds``) when the caller has it.
    """
    x, y = np.asarray(x, np.float64), np.asarray(y, np.float64)
    n = int(x.size if keep is None else np.count_nonzero(keep))
    corner = None if not n else (extent[:2] if extent is not None
                                 else (lowest(x, keep), lowest(y, keep)))
    out = {"n": n, "corner": [float(corner[0]), float(corner[1])] if n else None}
    if counts:
        water = (np.zeros(x.size, bool) if classification is None
                 else np.asarray(classification) == WATER)
        if keep is not None:
            water &= keep
        nw = int(np.count_nonzero(water))
        if nw:                                   # the extent is not theirs then
            keep, extent = (~water if keep is None else keep & ~water), None
        out.update(water=nw, cells=cell_counts(x, y, DENSITY_CELL, keep=keep, extent=extent))
    return out


def cell_counts(x, y, cell: float, shared: Sequence = (), keep=None, extent=None) -> dict:
    """Points per occupied cell of the world lattice (multiples of ``cell`` m), mergeable.

    Cells no box of ``shared`` (other tiles' boxes, metres) touches hold this tile's
    points only: their counts go into a histogram, kept sparse (``hist``: the counts
    met and how many cells hold each — a tile of one position holds one cell of n
    points, not a list n long); the others are kept by cell (``keys``: columns and
    rows) for :func:`merge` to add up across tiles. ``keep`` (bool per point): count
    those points only; ``extent``: theirs (``_checks.bounds``) when the caller has it.
    """
    x, y = np.asarray(x, np.float64), np.asarray(y, np.float64)
    if keep is not None and keep.all():
        keep = None
    if not (x.size if keep is None else keep.any()):
        return {"hist": [[], []], "keys": [[], []], "counts": []}
    # floor(v / cell) is monotonic: the extreme cells are those of the extreme points
    lx, ly, hx, hy = extent if extent is not None else \
        (lowest(x, keep), lowest(y, keep), highest(x, keep), highest(y, keep))
    x0, y0 = int(np.floor(lx / cell)), int(np.floor(ly / cell))
    ny = int(np.floor(hy / cell)) - y0 + 1
    size = (int(np.floor(hx / cell)) - x0 + 1) * ny
    if size <= _BOX_CELLS:          # a small box: counted block by block, no per-point keys
        cnt = np.zeros(size + 1, np.int64)          # the points left out: cell ``size``
        for s in range(0, x.size, _BLOCK):
            key = world_cells(x[s:s + _BLOCK], y[s:s + _BLOCK], cell, x0, y0, ny)
            if keep is not None:
                key[~keep[s:s + _BLOCK]] = size
            cnt += np.bincount(key, minlength=size + 1)
        occ = np.flatnonzero(cnt[:size])
        cnt = cnt[occ]
    else:
        if keep is not None:
            x, y = x[keep], y[keep]
        local = world_cells(x, y, cell, x0, y0, ny)
        if int(local.max()) < 4 * local.size + 1_000_000:      # O(n) count on a small box
            cnt = np.bincount(local)
            occ = np.flatnonzero(cnt)
            cnt = cnt[occ]
        else:
            occ, cnt = np.unique(local, return_counts=True)
    cx, cy = occ // ny + x0, occ % ny + y0
    edge = np.zeros(occ.size, bool)
    for b in shared:
        edge |= ((cx * cell <= b[2]) & ((cx + 1) * cell >= b[0])
                 & (cy * cell <= b[3]) & ((cy + 1) * cell >= b[1]))
    values, cells = np.unique(cnt[~edge], return_counts=True)
    return {"hist": [values.tolist(), cells.tolist()],
            "keys": [cx[edge].tolist(), cy[edge].tolist()], "counts": cnt[edge].tolist()}


#: :func:`cell_counts` counts boxes of up to this many cells block by block, :data:`_BLOCK`
#: points at a time (the temporaries of a block stay in the processor's cache)
_BOX_CELLS = 1 << 20
_BLOCK = 1 << 16


def world_cells(x, y, cell: float, x0: int, y0: int, n: int, *,
                row_major: bool = False) -> np.ndarray:
    """Key of each point's cell of the world lattice (multiples of ``cell``), int64.

    ``(column - x0) * n + (row - y0)`` (``n`` rows), or with ``row_major``
    ``(row - y0) * n + (column - x0)`` (``n`` columns); column = floor(x / cell). The
    one world-lattice cell key of the package: the density counts here and the water
    test's cells (:func:`._recommended_filter.water_candidates`). A filter's raster lies
    on the lattice through its corner instead (``_raster.Grid.index``). The keys of
    points outside the box whose first cell is (``x0``, ``y0``) are garbage: where that
    cell's index is not negative the floor is taken by truncation (the same integer for
    every point in the box, one pass less).
    """
    a, b = (y, x) if row_major else (x, y)
    a0, b0 = (y0, x0) if row_major else (x0, y0)
    ia = _floor(a / cell, a0)
    ia -= a0
    ia *= n
    ib = _floor(b / cell, b0)
    ib -= b0
    ia += ib
    return ia


def _floor(q, first):
    """``floor(q)`` as int64 where ``q >= first`` (truncation when ``first >= 0``)."""
    if first < 0:
        np.floor(q, out=q)
    return q.astype(np.int64)


def _merge_cells(parts: Sequence[dict]) -> dict:
    """One histogram of the points per occupied cell from the tiles' :func:`cell_counts`."""
    values = [np.asarray(p["hist"][0], np.int64) for p in parts]
    cells = [np.asarray(p["hist"][1], np.int64) for p in parts]
    kx = np.concatenate([np.asarray(p["keys"][0], np.int64) for p in parts])
    ky = np.concatenate([np.asarray(p["keys"][1], np.int64) for p in parts])
    if kx.size:                         # cells several tiles touch: their counts added up
        cnt = np.concatenate([np.asarray(p["counts"], np.int64) for p in parts])
        _, inv = np.unique(np.column_stack([kx, ky]), axis=0, return_inverse=True)
        total = np.bincount(inv.ravel(), weights=cnt).astype(np.int64)
        values.append(total)
        cells.append(np.ones(total.size, np.int64))
    v, inv = np.unique(np.concatenate(values), return_inverse=True)
    c = np.bincount(inv.ravel(), weights=np.concatenate(cells), minlength=v.size)
    keep = v > 0
    return {"hist": [v[keep].tolist(), c.astype(np.int64)[keep].tolist()],
            "keys": [[], []], "counts": []}


def _median(values: np.ndarray, cells: np.ndarray) -> float:
    """``np.median`` of the counts a sparse histogram describes (mean of the middle two)."""
    cum = np.cumsum(cells)
    m = int(cum[-1])
    lo, hi = np.searchsorted(cum, [(m - 1) // 2 + 1, m // 2 + 1])
    return float(np.mean([float(values[lo]), float(values[hi])]))


def recommended_values(summary: dict) -> dict:
    """Return what the recommended filter derives from the whole cloud, from its summary.

    ``density`` (points per m² of occupied 5 m cells), ``median5`` (median points per
    occupied 5 m cell), ``water_input`` (input class 9 anywhere): the same numbers
    for a single-file run and for every chunk of a catalog of the same points.
    """
    values, cells = (np.asarray(a, np.int64) for a in summary["cells"]["hist"])
    occupied = int(cells.sum())
    n = int((values * cells).sum())
    return {"density": n / (occupied * DENSITY_CELL * DENSITY_CELL) if occupied else 0.0,
            "median5": _median(values, cells) if occupied else 0.0,
            "water_input": bool(summary.get("water", 0))}



def tile_summary(path: str, h: float = 1.0, counts: bool = False,
                 shared: Sequence = ()) -> dict:
    """Summary of one tile's points, streamed (coordinates × ``h``: metres).

    Runs on a catalog worker; returns a few numbers (no point arrays) and its own
    wall and CPU seconds (``seconds``, the pass's cost in the run's stats). ``counts``:
    the recommended filter's cell counts too (:func:`cloud_summary`) of the points it
    classifies (input noise 7 and 18 left out), ``shared`` the boxes (metres) of the
    tiles whose points may fall in this tile's cells.
    """
    parts = ((pd.x, pd.y, pd.dims.get("classification")) for _, pd in iter_las_chunks(
        path, ("classification",) if counts else (), allow_empty=True))
    return summarise(parts, h, counts, shared)


def summarise(parts, h: float = 1.0, counts: bool = False, shared: Sequence = ()) -> dict:
    """Summary of a tile's points given as ``(x, y, classification)`` parts (tile units).

    :func:`tile_summary` streams a file into it; a strip task (``_chunks.read_strip``),
    which decodes the whole tile anyway, passes its arrays: one decode serves both.
    """
    t0, c0 = time.perf_counter(), time.process_time()
    xmin = ymin = np.inf
    n = water = 0
    xs, ys = [], []
    for px, py, cls in parts:
        if not np.size(px):
            continue
        px, py = np.asarray(px, np.float64), np.asarray(py, np.float64)
        xmin, ymin = min(xmin, float(px.min())), min(ymin, float(py.min()))
        n += px.size
        if counts:
            keep = ~np.isin(cls, asprs.INPUT_NOISE)
            water += int(np.count_nonzero(keep & (cls == WATER)))
            keep &= cls != WATER
            xs.append(px[keep] * h if h != 1.0 else px[keep])
            ys.append(py[keep] * h if h != 1.0 else py[keep])
    # the minimum of the scaled values is the scaled minimum (scaling is monotonic)
    corner = [float(np.float64(xmin) * h), float(np.float64(ymin) * h)] if n else None
    out = {"n": n, "corner": corner}
    if counts:
        x, y = (np.concatenate(v) if v else np.empty(0) for v in (xs, ys))
        out.update(water=water, cells=cell_counts(x, y, DENSITY_CELL, shared))
    out["seconds"] = [time.perf_counter() - t0, time.process_time() - c0]
    return out


def strip_summary(strip: dict) -> dict:
    """Return the summary a strip task made of its decoded tile (runs where the strip is)."""
    return strip["summary"]


def final(*parts, counts: bool = False, folder=None, signature=None) -> dict:
    """Merge the tiles' summaries, derive the chunks' values, save ``summary.json``.

    Runs on a worker once every tile is summarised; returns ``{"corner", "derived", ...}``
    (``derived``: :func:`recommended_values` when ``counts``), what each chunk applies.
    ``signature``: what the summary was made of (tiles, filter, buffer), saved with it so
    that a resume reuses it only for the same (:func:`.catalog.pass_plan`).
    """
    out = merge(parts)
    out["derived"] = recommended_values(out) if counts else None
    out["signature"] = signature
    if folder is not None:
        save(folder, out)
    return out


def merge(parts: Sequence[dict]) -> dict:
    """One summary from the tiles' (exactly: the smallest corner, the counts added up)."""
    corners = np.array([p["corner"] for p in parts if p.get("corner")], np.float64)
    out = {"n": int(sum(p["n"] for p in parts)),
           "corner": [float(corners[:, 0].min()), float(corners[:, 1].min())]
           if corners.size else None,
           "seconds": [float(sum(p.get("seconds", (0, 0))[i] for p in parts))
                       for i in (0, 1)]}
    if parts and all("cells" in p for p in parts):
        out.update(water=int(sum(p["water"] for p in parts)),
                   cells=_merge_cells([p["cells"] for p in parts]))
    return out


def save(folder, summary: dict) -> None:
    """Write ``summary.json`` atomically into the run's state folder."""
    path = os.path.join(os.fspath(folder), SUMMARY_FILE)
    with open(path + ".tmp", "w", encoding="utf-8") as fh:
        json.dump(summary, fh)
    os.replace(path + ".tmp", path)


def load(folder) -> Optional[dict]:
    """Return the summary an earlier run of this folder saved, else None."""
    path = os.path.join(os.fspath(folder), SUMMARY_FILE)
    try:
        with open(path, encoding="utf-8") as fh:
            return json.load(fh)
    except (OSError, ValueError):
        return None

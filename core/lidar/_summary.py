"""What a catalog derives from all of its points before its chunks run (private).

A single-file ground filter derives a few quantities from the whole cloud it is given;
a catalog chunk sees only its tile and buffer. So that a chunk equals a single-file run
of the merged cloud by construction, each such quantity is a function of a small
*summary* that merges exactly (sums, minima): every tile is summarised on a worker
(:func:`tile_summary`, a first pass over the tiles' points), the client merges the
summaries (:func:`merge`) and hands the result to every chunk; a single-file run
computes the summary of its one cloud with the same code (:func:`cloud_summary`).

The anchor (every filter but PTD): a filter lays its grids and tiles (LSQ tiles, the
recommended filter's raster and pyramid, the slope filter's trend grid, the low-outlier
pre-filter's cells) on the lattice through the *corner* of the cloud it is given, the
smallest x and y of every point read (:func:`.filters.run_filter`). The catalog's corner
is the smallest over its tiles. (PTD lays its grids on the lattice through 0 in both.)
"""
from __future__ import annotations

import json
import os
import time
from typing import Optional, Sequence

import numpy as np

from ..io.las import iter_las_chunks

__all__ = ["SUMMARY_FILE", "cloud_summary", "load", "merge", "save", "tile_summary"]

#: the merged summary of a run, in ``<out>/.catalog/`` (a resumed run reuses it)
SUMMARY_FILE = "summary.json"


def cloud_summary(x, y) -> dict:
    """Summary of one cloud (metres): what :func:`tile_summary` gives for a tile."""
    x, y = np.asarray(x, np.float64), np.asarray(y, np.float64)
    return {"n": int(x.size), "corner": [float(x.min()), float(y.min())] if x.size else None}


def tile_summary(path: str, h: float = 1.0) -> dict:
    """Summary of one tile's points, streamed (coordinates × ``h``: metres).

    Runs on a catalog worker; returns a few numbers (no point arrays) and its own
    wall and CPU seconds (``seconds``, the pass's cost in the run's stats).
    """
    t0, c0 = time.perf_counter(), time.process_time()
    xmin = ymin = np.inf
    n = 0
    for _, pd in iter_las_chunks(path, allow_empty=True):
        if len(pd):
            xmin, ymin = min(xmin, float(pd.x.min())), min(ymin, float(pd.y.min()))
            n += len(pd)
    # the minimum of the scaled values is the scaled minimum (scaling is monotonic)
    corner = [float(np.float64(xmin) * h), float(np.float64(ymin) * h)] if n else None
    return {"n": n, "corner": corner,
            "seconds": [time.perf_counter() - t0, time.process_time() - c0]}


def merge(parts: Sequence[dict]) -> dict:
    """One summary from the tiles' (exactly: the corner is the smallest of the corners)."""
    corners = np.array([p["corner"] for p in parts if p.get("corner")], np.float64)
    return {"n": int(sum(p["n"] for p in parts)),
            "corner": [float(corners[:, 0].min()), float(corners[:, 1].min())]
            if corners.size else None,
            "seconds": [float(sum(p.get("seconds", (0, 0))[i] for p in parts))
                        for i in (0, 1)]}


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

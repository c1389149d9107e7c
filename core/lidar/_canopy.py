"""The recommended filter's canopy scale for a whole catalog (private; see :mod:`.catalog`).

Under a closed canopy the recommended filter reads its low-outlier test at a coarser
scale, the first of :data:`._lowcells.FACTORS` at which closing pits are rare in the
canopy areas of the *whole* raster (:func:`._lowcells.low_cells`). A chunk sees only
its tile and buffer, so it once chose its own factor (a forest with one half thinned:
3 of 22 points differed from a single-file run of the merged tiles).

The choice depends on two counts per factor (coarse pits in canopy blocks, occupied
canopy blocks) that add up over any partition of the blocks. After the first pass
(:mod:`._summary`: the corner, density and derived cell), each chunk tallies the blocks
it *owns* (:func:`tally_chunk`): the lattice-aligned coarse blocks whose first cell's
centre is nearest its box (L∞ distance, ties to the chunk first in the plan). One task
adds the tallies up and chooses the factor (:func:`with_canopy`, saved in
``summary.json``); every chunk then closes its canopy at that scale, as a single-file
run of the merged cloud does. Exact as long as the buffer covers the reach of the
test (the 25 m canopy window and the coarsest closing, 3 × 16 cells).

Cost: a tally reads its chunk and builds the filter's minimum raster once more.
"""
from __future__ import annotations

import time
from typing import Sequence

import numpy as np

from ..errors import InputError
from . import _summary
from ._chunks import ChunkTask, _read, apply_summary, chunk_filter, single_threaded
from ._lowcells import FACTORS, choose_factor
from .filters import default_selection, run_filter

__all__ = ["assign_peers", "has_factor", "owned_blocks", "tally_chunk", "with_canopy"]

#: metres beyond twice the buffer within which chunks may own each other's blocks
MARGIN = 100.0


def assign_peers(tasks: Sequence[ChunkTask], h: float = 1.0) -> None:
    """Give each chunk its position and the boxes (metres) of the chunks near it.

    A block a chunk's raster holds lies within its buffered box (plus a block); the
    boxes nearer to it than the chunk's own lie within twice the buffer and
    :data:`MARGIN` of the chunk.
    """
    b = np.array([t.bounds for t in tasks], np.float64).reshape(-1, 4)
    for i, t in enumerate(tasks):
        g = 2.0 * t.buffer + MARGIN / h
        near = np.flatnonzero((b[:, 0] <= b[i, 2] + g) & (b[:, 2] >= b[i, 0] - g)
                              & (b[:, 1] <= b[i, 3] + g) & (b[:, 3] >= b[i, 1] - g))
        t.index = i
        t.peers = [[int(j), *(float(v) * h for v in b[j])] for j in near]


def owned_blocks(task: ChunkTask, grid, f: int, shape) -> np.ndarray:
    """Blocks of ``f`` cells of ``grid``'s coarse raster that ``task`` counts.

    A block's first cell (its lattice index a multiple of ``f``) has its centre
    computed from the catalog's corner and the lattice index, the same in every chunk;
    the block is this chunk's when that centre is nearer its box than any peer's.
    """
    ox, oy = task.filter_origin
    cell = grid.cell
    r0, c0 = grid.anchor[0] // f, grid.anchor[1] // f
    ys = oy + ((r0 + np.arange(shape[0])) * f + 0.5) * cell
    xs = ox + ((c0 + np.arange(shape[1])) * f + 0.5) * cell

    def dist(box):
        dx = np.maximum(np.maximum(box[0] - xs, xs - box[2]), 0.0)
        dy = np.maximum(np.maximum(box[1] - ys, ys - box[3]), 0.0)
        return np.maximum(dy[:, None], dx[None, :])
    own = dist(next(p for p in task.peers if p[0] == task.index)[1:])
    mine = np.ones(shape, bool)
    for p in task.peers:
        if p[0] != task.index:
            d = dist(p[1:])
            mine &= (own < d) | ((own == d) & (task.index < p[0]))
    return mine


def _zero() -> dict:
    return {"pits": [0] * len(FACTORS), "blocks": [0] * len(FACTORS)}


def tally_chunk(task: ChunkTask, *strips, summary=None) -> dict:
    """Count the canopy blocks ``task`` owns (on a worker, after the first pass).

    Reads the chunk as :func:`._chunks.process_chunk` does (its tile, the neighbours'
    strips) and runs the recommended filter up to its minimum raster.
    """
    t0, c0 = time.perf_counter(), time.process_time()
    single_threaded()
    if summary is not None:
        apply_summary([task], summary)
    xyz, dims, core, _ = _read(task, strips if task.tile and strips else None)
    out = _zero()
    if core.any() and task.filter_origin is not None:
        pts, flt, origin = chunk_filter(task, xyz, dims)
        flt.canopy_owned = lambda grid, f, shape: owned_blocks(task, grid, f, shape)
        try:
            out = run_filter(pts, flt, default_selection(task.ground_filter),
                             origin=origin).outcome.details
        except InputError:      # too few points to filter: no raster (filter_sparse_chunk)
            pass
    return {**out, "seconds": [time.perf_counter() - t0, time.process_time() - c0]}


def with_canopy(summary: dict, *tallies, folder=None) -> dict:
    """Return the first pass's summary with the catalog's canopy factor (saved in ``folder``)."""
    pits = np.sum([t["pits"] for t in tallies], axis=0) if tallies else [0] * len(FACTORS)
    blocks = np.sum([t["blocks"] for t in tallies], axis=0) if tallies else pits
    out = dict(summary)
    # the tallies' wall and CPU seconds on the workers (the cost of the canopy scale)
    out["canopy_seconds"] = [float(sum(t.get("seconds", (0, 0))[i] for t in tallies))
                             for i in (0, 1)]
    out["derived"] = dict(summary.get("derived") or {},
                          canopy_factor=choose_factor(pits, blocks),
                          canopy_counts=[[int(v) for v in pits], [int(v) for v in blocks]])
    if folder is not None:
        _summary.save(folder, out)
    return out


def has_factor(summary) -> bool:
    """Return True when ``summary`` carries the catalog's canopy factor."""
    return isinstance(((summary or {}).get("derived") or {}).get("canopy_factor"), int)

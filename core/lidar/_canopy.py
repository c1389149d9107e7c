"""The recommended filter's canopy scale for a whole catalog (private; see :mod:`.catalog`).

Under a closed canopy the recommended filter reads its low-outlier test at a coarser
scale, the first of :data:`._lowcells.FACTORS` at which closing pits are rare in the
canopy areas of the *whole* raster (:func:`._lowcells.low_cells`). A chunk sees only
its tile and buffer, so on its own it chooses from its own raster (a forest with one
half thinned: 3 of 22 points differed from a single-file run of the merged tiles).

The choice depends on two counts per factor (coarse pits in canopy blocks, occupied
canopy blocks) that add up over any partition of the blocks. While a chunk classifies
(nothing read or built again), it counts the blocks it *owns*
(``low_cells(owned=)``; :func:`owned_blocks`: the lattice-aligned coarse blocks whose
first cell's centre is nearest its box, L∞ distance, ties to the chunk first in the
plan) and closes its canopy at its own factor, provisionally; its done marker keeps
the counts and the factor it used (``stats["canopy"]``). When every chunk has
finished, :func:`settle` adds the counts up and chooses the factor a single-file run of
the merged cloud chooses; only the chunks that have a canopy area and used another
factor are run again at it (none on a catalog whose chunks agree). Exact as long as
the buffer covers the reach of the test (the 25 m canopy window and the coarsest
closing, 3 × 16 cells). A resume sums the finished chunks' markers with the new ones.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import TYPE_CHECKING, List, Optional, Sequence

import numpy as np

from ._lowcells import FACTORS, choose_factor

if TYPE_CHECKING:                                   # pragma: no cover
    from ._chunks import ChunkTask

__all__ = ["Settled", "assign_peers", "owned_blocks", "settle", "tallies", "zero"]

#: metres beyond twice the buffer within which chunks may own each other's blocks
MARGIN = 100.0


def assign_peers(tasks: Sequence["ChunkTask"], h: float = 1.0) -> None:
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


def owned_blocks(task: "ChunkTask", grid, f: int, shape) -> np.ndarray:
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


def tallies(task: "ChunkTask", flt=None) -> bool:
    """Return True when ``task``'s filter counts its canopy blocks (:func:`settle`).

    The recommended filter in a catalog chunk that has its peers and the catalog's
    corner; ``flt``: the filter object, if made.
    """
    if flt is None:
        from .filters import GROUND_FILTERS
        spec = GROUND_FILTERS.get(task.ground_filter)
        flt = spec.make(None) if spec is not None else None
    return bool(getattr(flt, "needs_canopy", False) and task.peers
                and task.filter_origin is not None)


def zero() -> dict:
    """Return the canopy stats of a chunk that counts no block (no point, no raster)."""
    return {"pits": [0] * len(FACTORS), "blocks": [0] * len(FACTORS), "factor": 0}


@dataclass
class Settled:
    """The catalog's canopy factor (:func:`settle`) and the chunks to run again at it."""

    factor: int
    pits: List[int]
    blocks: List[int]
    redo: list = field(default_factory=list)


def settle(tasks: Sequence["ChunkTask"], chunks: Sequence[dict]) -> Optional[Settled]:
    """Choose the catalog's canopy factor from every chunk's counts; the chunks to redo.

    ``chunks``: the stats (done markers) of every chunk of ``tasks``, this run's and an
    earlier one's. None when a chunk's stats are missing (failed: the resume settles)
    or carry no counts (the filter tallies nothing). The chunks to redo are those
    that closed a canopy area at another factor (a chunk without canopy used none:
    the factor changes nothing there).
    """
    stats = {c["key"]: c for c in chunks}
    got = [(stats.get(t.key) or {}).get("canopy") for t in tasks]
    if not tasks or any(g is None for g in got):
        return None
    pits = [int(v) for v in np.sum([g["pits"] for g in got], axis=0)]
    blocks = [int(v) for v in np.sum([g["blocks"] for g in got], axis=0)]
    f = choose_factor(pits, blocks)
    return Settled(f, pits, blocks, [t for t, g in zip(tasks, got)
                                     if g["factor"] not in (0, f)])

"""Nearest lattice cells of hole cells by scanning offsets (numpy only, private).

The hole fill of :mod:`._surface` needs, for every hole cell, its ``k`` nearest border
cells ordered by (squared distance, row offset, column offset) - the order in which its
KD-tree returns them (:func:`._surface._knn`). Most hole cells have their border a few
cells away, so instead of a tree the offsets are visited in that order, nearest first,
and the first ``k`` that land on a border cell are taken: the same cells in the same
order, by construction. Hole cells that do not find ``k`` border cells within
:data:`SCAN_D2` are left to the tree.
"""
from __future__ import annotations

from typing import NamedTuple

import numpy as np
from scipy.spatial import cKDTree

__all__ = ["OFFSETS_F", "SCAN_D2", "Near", "Scan", "near_offsets", "ring_cells",
           "scan_lattice", "scan_offsets"]

#: Largest squared offset (cells²) visited by :func:`scan_offsets` (40 cells: a hole cell
#: deeper inside a hole is searched in the KD-tree). 40 rather than 24: at 0.2 pts/m² a
#: few hundred hole cells lie 24-40 cells from their 12th border cell, and the tree built
#: for them over every border cell held ~20 MB (5 M cells, 1 M points) for no gain in time.
SCAN_D2 = 40 * 40
#: Offsets tested per step (the holes done are dropped between steps).
_STEP = 24
#: ... and once fewer than :data:`_FEW` queries are left (cells deep in a hole).
_WIDE = 96
_FEW = 1024


def _offsets(d2max: int):
    """Lattice offsets ``(dc, dr, d²)`` with ``0 < d² <= d2max``, by (d², dr, dc)."""
    m = int(np.sqrt(d2max))
    dr, dc = np.mgrid[-m:m + 1, -m:m + 1]
    d2 = dr * dr + dc * dc
    keep = (d2 > 0) & (d2 <= d2max)
    dr, dc, d2 = dr[keep], dc[keep], d2[keep]
    o = np.lexsort((dc, dr, d2))
    return dc[o], dr[o], d2[o]


_OFFSETS = _offsets(SCAN_D2)
#: The offsets ``(dc, dr, d²)`` in scan order, float64 (what :func:`scan_offsets` indexes).
OFFSETS_F = tuple(a.astype(np.float64) for a in _OFFSETS)


def scan_lattice(ring, rows=None, first=None):
    """Prepare ``ring`` (bool raster of the cells searched) for :func:`scan_offsets`.

    Returns the raster padded by the scan's reach holding each ring cell's index in
    ``np.nonzero(ring)`` order (-1 elsewhere), the padding, the raster's shape, the
    first row and the padded raster's ring cells (bool, flat). ``rows = (a, b)``: only
    what a scan from rows a..b-1 reads (rows a - pad to b + pad), the indices still those
    of the whole raster (``first[i]``: ring cells in the rows before row i, else counted
    here).
    """
    nrows, cols = ring.shape
    pad = int(np.sqrt(SCAN_D2))
    a, b = (0, nrows) if rows is None else (int(rows[0]), int(rows[1]))
    lo, hi = max(0, a - pad), min(nrows, b + pad)
    it = np.int32 if ring.size < 2 ** 31 else np.int64
    index = np.full((b - a + 2 * pad, cols + 2 * pad), -1, it)
    part = ring[lo:hi]
    n0 = 0 if lo == 0 else int(first[lo] if first is not None else np.count_nonzero(ring[:lo]))
    inner = index[lo - a + pad:hi - a + pad, pad:pad + cols]
    inner[part] = np.arange(n0, n0 + np.count_nonzero(part), dtype=it)
    return index, pad, ring.shape, a, index.ravel() >= 0


def ring_cells(lattice):
    """Rows and columns of the ring cells of a whole :func:`scan_lattice` (``np.nonzero`` order)."""
    index, pad, (rows, cols), a = lattice[:4]
    if a != 0 or index.shape[0] != rows + 2 * pad:
        raise ValueError("ring_cells needs the whole lattice")  # i18n: internal
    return np.nonzero(index[pad:pad + rows, pad:pad + cols] >= 0)


def scan_offsets(lattice, r, c, k: int):
    """Find the ``k`` nearest cells of ``ring`` from each cell ``(r, c)``, ties by offset.

    Parameters
    ----------
    lattice : tuple
        :func:`scan_lattice` of the bool raster ``ring`` of the cells searched.
    r, c : ndarray of int
        Rows and columns of the query cells (not in ``ring``).
    k : int
        Neighbours wanted.

    Returns
    -------
    tuple
        ``(done, o, j)``: ``done`` flags the query cells whose ``k`` nearest lie within
        :data:`SCAN_D2`; for those (in order) ``o`` (int32, shape (m, k)) the index of
        each neighbour's offset in :data:`OFFSETS_F` (ordered by d², dr, dc: a caller
        can tabulate what depends on the offset only) and ``j`` its index in
        ``np.nonzero(ring)`` order.
    """
    index, pad, (rows, cols), r0 = lattice[:4]
    width = cols + 2 * pad
    flat = index.ravel()
    hits = lattice[4]
    delta = _OFFSETS[1].astype(np.int64) * width + _OFFSETS[0]
    m = r.size
    pick = np.zeros((m, k), np.int32)                # offset index of each neighbour
    found = np.zeros(m, np.int8 if k + _WIDE < 127 else np.int32)
    act = np.arange(m)
    base = (r.astype(np.int64) - r0 + pad) * width + (c.astype(np.int64) + pad)
    o0 = 0
    while o0 < delta.size and act.size:
        step = _STEP if act.size >= _FEW else _WIDE     # few left (deep): fewer, wider steps
        hit = hits[delta[o0:o0 + step, None] + base]    # (offsets, active), scan order
        _take(hit, act, found, pick, o0, k)
        o0 += step
        more = found[act] < k
        act, base = act[more], base[more]
    done = found == k
    pick = pick[done]
    at = delta[pick]
    at += ((r[done].astype(np.int64) - r0 + pad) * width
           + (c[done].astype(np.int64) + pad))[:, None]
    j = flat[at].astype(np.int64)
    return done, pick, j


def _take(hit, act, found, pick, o0: int, k: int):
    """Record the hits of one step: ``hit[i, h]``, offset ``o0 + i`` of query ``act[h]``.

    Each query's hits go, in offset order, to its next free slots in ``pick`` (up to
    ``k``); ``found`` counts them. The running count along the offsets is summed row
    by row in small integers and the hits listed with
    ``flatnonzero``: the same slots as a cumulative sum and a 2-D ``nonzero``, a few
    times cheaper. ``pick`` is (queries, k).
    """
    pos = hit.astype(found.dtype)
    for i in range(1, pos.shape[0]):
        pos[i] += pos[i - 1]
    total = pos[-1] + found[act]
    pos += found[act] - found.dtype.type(1)          # slot of each hit
    at = np.flatnonzero(hit & (pos < k))
    n = act.size
    oi = at // n                                     # offset (row) of each hit
    slot = act[at - oi * n]
    slot *= pick.shape[1]
    slot += pos.ravel()[at]
    pick.ravel()[slot] = oi + o0
    found[act] = np.minimum(total, k)


#: Offsets of the query point (cells, powers of two: exact in float64) that order
#: equidistant lattice cells by row offset, then column offset (see :func:`_knn`).
_TIE_ROW = 2.0 ** -14
_TIE_COL = 2.0 ** -28


def _knn(tree, q, k: int, lattice):
    """Find the ``k`` nearest lattice cells of every query cell, ties broken by offset.

    On an integer lattice many cells are equidistant, and a KD-tree returns the tied
    ones in tree order, which depends on the raster's extent (a catalog chunk and the
    merged cloud would pick different cells). Here the query point is moved by
    ``(-2**-28, -2**-14)`` cells (column, row): its squared distance to a cell at
    offset ``(dc, dr)`` is ``d² + 2**-27 dc + 2**-13 dr`` (+ a constant), so the
    tree itself returns the cells ordered by (squared distance, row offset, column
    offset) - exactly so up to 4,096 cells away (beyond, still a function of the
    offsets only). Every difference ``cell - query`` is exact in float64, hence the
    choice and its order depend only on the cells around the query, not on the extent.

    Parameters
    ----------
    tree : cKDTree
        Tree of the lattice cells ``lattice`` (``(col, row)`` integers).
    q : ndarray of int, shape (m, 2)
        Query cells ``(col, row)``.
    k : int
        Neighbours kept (at most the number of lattice cells).
    lattice : ndarray of float, shape (n, 2)
        The cells of the tree (integer values).

    Returns
    -------
    tuple of ndarray
        ``(d2, dc, dr, j)`` of shape (m, k): squared distance (cells²), column and row
        offset of the neighbour from the query cell, and its index in ``lattice``.
    """
    q = q.astype(np.float64)
    qf = q.copy()
    qf[:, 0] -= _TIE_COL
    qf[:, 1] -= _TIE_ROW
    bound = 2.0 * np.sqrt(k + 1.0)           # most hole cells have their border close by
    d, j = tree.query(qf, k=k, distance_upper_bound=bound)
    d, j = d.reshape(-1, k), j.reshape(-1, k)
    far = np.isinf(d[:, -1])
    if far.any():
        j[far] = tree.query(qf[far], k=k)[1].reshape(-1, k)
    dc = lattice[j, 0] - q[:, :1]            # integers held exactly in float64
    dr = lattice[j, 1] - q[:, 1:]
    return dc * dc + dr * dr, dc, dr, j


class Near(NamedTuple):
    """Neighbours of query cells (:func:`near_offsets`).

    ``o`` (m, k): index of each neighbour's offset in :data:`OFFSETS_F`, -1 on the rows
    the KD-tree searched; ``j`` (m, k): the neighbours' indices in ``np.nonzero(ring)``
    order; ``far``: those rows, and ``d2, dc, dr`` (len(far), k) their offsets.
    """

    o: np.ndarray
    j: np.ndarray
    far: np.ndarray
    d2: np.ndarray
    dc: np.ndarray
    dr: np.ndarray

    def arrays(self):
        """Return :func:`_knn`'s ``(d2, dc, dr, j)`` of every row."""
        out = [a[self.o] for a in (OFFSETS_F[2], OFFSETS_F[0], OFFSETS_F[1])]
        for a, b in zip(out, (self.d2, self.dc, self.dr)):
            a[self.far] = b
        return out + [self.j]


def near_offsets(scan, r, c, k: int, trees: list, ring=None) -> Near:
    """Return the ``k`` nearest cells of the cells ``(r, c)`` as a :class:`Near`.

    Scanned on the lattice (:func:`scan_offsets`: the same cells in the same order as
    :func:`_knn`); the KD-tree (built once into ``trees``, from ``ring`` when the
    lattice covers some rows only) searches the cells whose ``k`` nearest lie farther.
    """
    done, o, j = scan_offsets(scan, r, c, k)
    if done.all():
        empty = np.empty((0, k))
        return Near(o, j, np.empty(0, np.int64), empty, empty, empty)
    if not trees:
        rr, cc = ring_cells(scan) if ring is None else np.nonzero(ring)
        lattice = np.empty((rr.size, 2))             # float64: the tree keeps it, no copy
        lattice[:, 0], lattice[:, 1] = cc, rr
        trees += [cKDTree(lattice), lattice]
    far = np.flatnonzero(~done)
    d2, dc, dr, jf = _knn(trees[0], np.column_stack((c[far], r[far])), k, trees[1])
    oo = np.full((r.size, k), -1, np.int32)
    jj = np.empty((r.size, k), np.int64)
    oo[done], jj[done], jj[far] = o, j, jf
    return Near(oo, jj, far, d2, dc, dr)


class Scan:
    """:func:`near_offsets` on lattices of :data:`SCAN_ROWS` rows at a time.

    The whole padded lattice is an int32 raster (20 MB at 5 M cells); a band of rows
    gives the same neighbours (the scan reads its reach around the band, the indices
    are the whole ring's). Queries come sorted by row.
    """

    def __init__(self, ring):
        self.ring, self.lattice = ring, None
        self.first = np.concatenate(([0], np.cumsum(np.count_nonzero(ring, axis=1))))

    def near(self, r, c, k, trees) -> Near:
        """Return the :class:`Near` of the cells ``(r, c)`` (sorted by row)."""
        parts, s = [], 0
        while s < r.size:
            lat = self.lattice
            if lat is None or not lat[3] <= r[s] < lat[3] + SCAN_ROWS:
                a = int(r[s])
                lat = self.lattice = scan_lattice(self.ring, (a, a + SCAN_ROWS), self.first)
            e = int(np.searchsorted(r, lat[3] + SCAN_ROWS))
            part = near_offsets(lat, r[s:e], c[s:e], k, trees, ring=self.ring)
            parts.append(part._replace(far=part.far + s))
            s = e
        if len(parts) == 1:
            return parts[0]
        return Near(*(np.concatenate(a) for a in zip(*parts)))


#: Rows per lattice of :class:`Scan`.
SCAN_ROWS = 512

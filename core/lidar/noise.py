"""Low-outlier (noise) pre-filter shared by every ground filter.

Airborne LiDAR holds a few returns far *below* the terrain (multipath, laser
range errors, reflections off water or glass). Every ground filter that fits a
surface to the lowest points — the least-squares polynomial filter, the slope
filter, progressive TIN densification, morphological filters — is pulled down
by them ("negative blunders", Sithole & Vosselman 2004, §2.3), so they are
flagged first and given ASPRS class 7 ("low point, noise").

The test is one-sided and rank-based, which makes it safe on steep slopes,
cliffs and under vegetation (where ground is a minority of the returns):

* for each point, take its ``k`` nearest horizontal neighbours within
  ``radius`` (the point itself and points already flagged excluded);
* sort their heights and take the ``max_cluster``-th lowest, ``z_ref``;
* the point is a low outlier when ``z < z_ref - threshold``.

A cluster of up to ``max_cluster`` low points cannot shelter its members
(the reference is the first neighbour height *after* the cluster), while on a
slope, at a cliff foot or under trees the lowest neighbours are at or below the
point itself, so genuine ground is never flagged. Points with fewer than
``min_neighbors`` neighbours inside ``radius`` (isolated returns, cloud edges,
sparse scans) use their ``min_neighbors`` nearest neighbours at any distance
instead. The test is repeated (``max_iterations``) with the flagged points
removed, which peels off deeper layers of larger low clusters.

Sensitivity: on flat ground a point ``threshold`` below its neighbours is
caught; on a slope of gradient ``g`` the lowest neighbours of the block may lie
downhill, up to ``2 * sqrt(2) * radius`` away, so the detectable depth grows to
about ``threshold + g * 2.8 * radius`` (e.g. 15 m on a 20-degree slope with the
defaults). That is the price of never removing ground: gross blunders (metres to
tens of metres down, the ones that wreck a fitted surface) are caught
everywhere. Only at the lower edge of a cloud on a steep slope, where every
neighbour is uphill, can a ground point be flagged (a handful per kilometre of
edge at 60 degrees).

References
----------
Sithole, G. & Vosselman, G. (2004). Experimental comparison of filter
algorithms for bare-Earth extraction from airborne laser scanning point clouds.
ISPRS J. Photogramm. Remote Sens. 59(1-2), 85-101.
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from scipy.spatial import cKDTree

from .. import classes as asprs
from ..coords import as_xyz
from ..errors import InputError
from ..progress import Monitor

__all__ = ["flag_low_outliers", "NOISE_CLASS"]

#: ASPRS class of low points (noise).
NOISE_CLASS = int(asprs.LOW_NOISE)




def _block_reference(x, y, z, cell, rank, origin=None):
    """Rank statistic over the 3 x 3 block of grid cells around each point's cell.

    Returns ``(ref, count)``: the ``rank``-th lowest height (0-based) among the
    *other* points of the block (``+inf`` if there are not enough) and the number
    of other points in the block. Fully vectorised: one lexsort, per-cell tables
    of the lowest ``rank + 2`` heights and nine ``searchsorted`` look-ups.
    """
    n = x.size
    m = rank + 2                       # lowest values kept per cell and per block
    x0, y0 = (x.min(), y.min()) if origin is None else origin
    ix = np.floor((x - x0) / cell).astype(np.int64) + 1
    iy = np.floor((y - y0) / cell).astype(np.int64) + 1
    ny = int(iy.max()) + 2
    cid = ix * ny + iy
    del ix, iy
    zmin = float(z.min())
    span = float(z.max()) - zmin + 1.0
    if float(cid.max()) * span < 2.0 ** 52 * 1e-4:
        # one float sort on cell + height (exact to 0.1 mm here), faster than lexsort
        order = np.argsort(cid * span + (z - zmin))
    else:
        order = np.lexsort((z, cid))
    cs = cid[order]
    del cid
    first = np.flatnonzero(np.r_[True, cs[1:] != cs[:-1]])
    ucell = cs[first]
    del cs
    counts = np.diff(np.r_[first, n])
    nc = ucell.size
    rank_in = np.arange(n) - np.repeat(first, counts)
    sel = rank_in < m
    cz = np.full((nc, m), np.inf)
    ci = np.full((nc, m), -1, dtype=np.int64)
    row = np.repeat(np.arange(nc), counts)[sel]
    cz[row, rank_in[sel]] = z[order[sel]]
    ci[row, rank_in[sel]] = order[sel]
    del rank_in, sel, row
    bz = np.full((nc, 9 * m), np.inf)
    bi = np.full((nc, 9 * m), -1, dtype=np.int64)
    bcount = np.zeros(nc, dtype=np.int64)
    col = 0
    for dx in (-1, 0, 1):
        for dy in (-1, 0, 1):
            nb = ucell + dx * ny + dy
            pos = np.minimum(np.searchsorted(ucell, nb), nc - 1)
            hit = ucell[pos] == nb
            ph = pos[hit]
            bz[hit, col:col + m] = cz[ph]
            bi[hit, col:col + m] = ci[ph]
            bcount[hit] += counts[ph]
            col += m
    del cz, ci
    srt = np.argsort(bz, axis=1, kind="stable")[:, :m]
    bz = np.take_along_axis(bz, srt, axis=1)
    bi = np.take_along_axis(bi, srt, axis=1)
    del srt
    pc = np.empty(n, dtype=np.int64)
    pc[order] = np.repeat(np.arange(nc), counts)
    del order
    me = np.arange(n)
    is_low = np.zeros(n, dtype=bool)
    for j in range(rank + 1):
        is_low |= bi[pc, j] == me
    ref = np.where(is_low, bz[pc, rank + 1], bz[pc, rank])
    return ref, bcount[pc] - 1


def _knn_reference(x, y, z, query, kk, rank, workers):
    """``rank``-th lowest height among the ``kk`` nearest other points (any distance)."""
    tree = cKDTree(np.column_stack((x, y)))
    k1 = min(kk + 1, x.size)
    _, nb = tree.query(np.column_stack((x[query], y[query])), k=k1, workers=workers)
    nb = nb.reshape(query.size, k1)
    zz = np.where(nb != query[:, None], z[nb], np.inf)
    r = min(rank, k1 - 1)
    return np.partition(zz, r, axis=1)[:, r]


def flag_low_outliers(x, y, z, *, radius: float = 5.0, threshold: float = 1.0,
                      min_neighbors: int = 4, max_cluster: int = 3,
                      max_iterations: int = 3, workers: int = 1, origin=None,
                      progress=None, cancel=None) -> np.ndarray:
    """Flag points far below their horizontal neighbourhood (low noise, class 7).

    Parameters
    ----------
    x, y, z : array_like, shape (n,)
        Point coordinates in a projected CRS (metres). Must be finite.
    radius : float, default 5.0
        Metres. Side of the grid cells; a point's neighbourhood is the 3 x 3 block
        of cells around its own cell, i.e. every point within at least ``radius``
        horizontally (and at most ``2 * sqrt(2) * radius``). Use 3–5 point
        spacings; larger for sparse scans.
    threshold : float, default 1.0
        Metres. A point is flagged when it lies more than ``threshold`` below the
        ``max_cluster``-th lowest of its neighbours.
    min_neighbors : int, default 4
        Points whose block holds fewer other points use their ``min_neighbors``
        nearest neighbours at any distance instead (k-d tree). Must exceed
        ``max_cluster``.
    max_cluster : int, default 3
        Largest group of low points caught in one pass (the rank of the reference
        neighbour). 1 catches single points only.
    max_iterations : int, default 3
        Passes; each pass ignores the points flagged by the previous ones (which
        peels deeper layers of bigger low clusters) and the loop stops early when
        nothing new is found.
    workers : int, default 1
        Threads for the k-d tree queries of the sparse fallback (-1 = all cores).
    origin : (float, float), optional
        Anchors the cells on the lattice through this point (default: the cloud's
        lower-left corner), so that the chunks of a catalog flag the same points as
        the merged cloud.
    progress, cancel : callable, optional
        ``progress(fraction)`` and ``cancel() -> bool``; see
        :class:`~.progress.Monitor`.

    Returns
    -------
    numpy.ndarray of bool, shape (n,)
        True for low outliers (to be given ASPRS class 7, :data:`NOISE_CLASS`).

    Raises
    ------
    ValueError
        Mismatched lengths, non-finite coordinates, or an invalid parameter.
    Cancelled
        When ``cancel()`` returns True.

    Notes
    -----
    Cost: one sort of the points in the first pass plus O(cells) table work;
    later passes re-test only the neighbourhoods of the newly flagged points
    (identical result, a fraction of the cost). Measured 0.2–0.3 s per million
    points on one core and about 60 bytes per point of extra memory (10 M point
    synthetic tile: 199 of its 200 planted low outliers found, no ground point
    flagged).

    Examples
    --------
    >>> import numpy as np
    >>> gx, gy = np.meshgrid(np.arange(20.0), np.arange(20.0))
    >>> x, y = gx.ravel(), gy.ravel()
    >>> z = 0.5 * x                      # a 27 degree slope
    >>> z[210] -= 8.0                    # one gross low point
    >>> np.flatnonzero(flag_low_outliers(x, y, z, radius=3.0)).tolist()
    [210]
    """
    x, y, z = as_xyz(x, y, z)
    _check_options(radius, threshold, min_neighbors, max_cluster, max_iterations)
    mon = Monitor(progress, cancel)
    flagged = np.zeros(x.size, dtype=bool)
    if x.size <= int(min_neighbors):
        mon.update(1.0)
        return flagged
    grid = _CellKeys.of(x, y, float(radius), origin)
    opts = dict(rank=int(max_cluster) - 1, min_neighbors=int(min_neighbors),
                threshold=float(threshold), workers=workers)
    new_idx = None                          # points flagged by the previous pass
    iters = int(max_iterations)
    for it in range(iters):
        mon.step(it / iters)
        new_idx = _noise_pass(x, y, z, grid, flagged, new_idx, mon, **opts)
        if new_idx is None or new_idx.size == 0:
            break
        flagged[new_idx] = True
    mon.update(1.0)
    return flagged


def _check_options(radius, threshold, min_neighbors, max_cluster, max_iterations) -> None:
    """Raise ValueError naming the first invalid option of :func:`flag_low_outliers`."""
    if not np.isfinite(radius) or radius <= 0:
        raise InputError("radius must be a positive number of metres, got {value}.",
                         value=radius)
    if not np.isfinite(threshold) or threshold <= 0:
        raise InputError("threshold must be a positive number of metres, got {value}.",
                         value=threshold)
    if int(max_cluster) < 1:
        raise InputError("max_cluster must be at least 1, got {value}.", value=max_cluster)
    if int(min_neighbors) <= int(max_cluster):
        raise InputError("min_neighbors ({min_neighbors}) must exceed max_cluster "
                         "({max_cluster}); raise min_neighbors.", min_neighbors=min_neighbors,
                         max_cluster=max_cluster)
    if int(max_iterations) < 1:
        raise InputError("max_iterations must be at least 1, got {value}.",
                         value=max_iterations)


@dataclass(frozen=True)
class _CellKeys:
    """Global cell key of every point (cells of side ``cell`` from ``origin``)."""

    cell: float
    origin: tuple
    key: np.ndarray
    offs: dict          # block radius (1, 2) -> key offsets of the (2r+1)^2 block

    @classmethod
    def of(cls, x, y, cell: float, anchor=None) -> _CellKeys:
        """Return the keys of the points ``x, y`` (cells on ``anchor``'s lattice)."""
        origin = (float(x.min()), float(y.min()))
        if anchor is not None:
            origin = tuple(float(a) + np.floor((o - float(a)) / cell) * cell
                           for o, a in zip(origin, anchor))
        gy = np.floor((y - origin[1]) / cell).astype(np.int64)
        ny = int(gy.max()) + 5
        key = np.floor((x - origin[0]) / cell).astype(np.int64) * ny + gy
        offs = {r: np.array([dx * ny + dy for dx in range(-r, r + 1)
                             for dy in range(-r, r + 1)]) for r in (1, 2)}
        return cls(cell, origin, key, offs)

    def retest(self, new_idx, flagged):
        """Return the points to re-test after ``new_idx`` were flagged, and the cells.

        Only points whose 3 x 3 block held a newly flagged point can change: they are
        re-tested, their blocks computed from the 5 x 5 cells around.
        """
        fk = np.unique(self.key[new_idx])
        near1 = np.unique((fk[:, None] + self.offs[1]).ravel())
        near2 = np.unique((fk[:, None] + self.offs[2]).ravel())
        return np.flatnonzero(~flagged & np.isin(self.key, near2)), near1


def _noise_pass(x, y, z, grid: _CellKeys, flagged, new_idx, mon: Monitor, *, rank: int,
                min_neighbors: int, threshold: float, workers: int):
    """Run one pass; return the newly flagged points (None: too few left to test)."""
    if new_idx is None:
        sub = np.arange(x.size)
    else:
        sub, near1 = grid.retest(new_idx, flagged)
        if sub.size <= min_neighbors:
            return None
    xs, ys, zs = x[sub], y[sub], z[sub]
    ref, count = _block_reference(xs, ys, zs, grid.cell, rank, grid.origin)
    cand = np.ones(sub.size, bool) if new_idx is None else np.isin(grid.key[sub], near1)
    sparse = np.flatnonzero(cand & (count < min_neighbors))
    if sparse.size:
        mon.check()
        rest = np.flatnonzero(~flagged)
        pos = np.searchsorted(rest, sub[sparse])
        ref[sparse] = _knn_reference(x[rest], y[rest], z[rest], pos, min_neighbors, rank,
                                     workers)
    return sub[cand & (zs < ref - threshold)]

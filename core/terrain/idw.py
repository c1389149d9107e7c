"""Inverse distance weighting (Shepard 1968) with nearest-neighbour search.

Same semantics as GDAL's ``gdal_grid -a invdistnn`` (``GDALGridInverseDistanceToAPower
NearestNeighbor``), so results can be compared cell for cell:

* estimate ``ẑ(s0) = Σ λ_i z_i`` with ``λ_i = w_i / Σ w_j`` and
  ``w_i = 1 / (d_i² + s²)^(p/2)`` (``p`` = power, ``s`` = smoothing, 0 by default);
* only points with horizontal distance ``d_i ≤ radius`` are candidates, and of those
  the ``max_points`` closest are used (``max_points = 0``: all within the radius);
* a cell with fewer than ``min_points`` neighbours (or none at all) is nodata;
* a cell centre that coincides with a point (``d² + s² < 1e-13``) takes that point's
  value exactly (with several coincident points, the first one GDAL's quadtree
  returns — reproduced here, see below);
* grid nodes are cell centres (pixel-is-area), as in GDAL ≥ 3.

Differences from GDAL, on purpose: ``radius`` may be ``None`` (pure k nearest
neighbours, GDAL requires a radius), and cells farther than ``max_distance`` from any
point can be left empty (see :func:`.grid.distance_mask`); pass ``fill=True`` to get
GDAL's behaviour exactly.

Ties: with LiDAR coordinates quantised to 1 cm, a node often has two points at exactly
the same distance at the ``max_points`` cut-off, and which one is used changes the
result by millimetres to centimetres. GDAL keeps equidistant points in the order its
point quadtree returns them; the order of the few points a tied node compares is
rebuilt from that quadtree (only when a tie actually occurs, only for those points:
``_quadtree.gdal_quadtree_order``; :func:`gdal_quadtree_rank` ranks every point) so
that ties are broken exactly as in GDAL (``tie_order='gdal'``, default; ``'input'`` =
lower input index first).

Implementation: one :class:`scipy.spatial.cKDTree` k-nearest query per block of grid
rows (all cores), then vectorised weights; memory is bounded by the block size, not by
the grid or the number of points.

References
----------
Sepehr journal (~2020, in Persian): DTM of a Zagros forest (Doroud, Lorestan) from
airborne LiDAR by IDW (powers 2 and 3) and kriging, judged on check points — the
spec this module implements (``shared/docs/seeds/02-slope-filter-idw-kriging.md``).
Shepard, D. (1968). A two-dimensional interpolation function for irregularly-spaced
data. Proc. 23rd ACM National Conference, 517–524. doi:10.1145/800186.810616

GDAL ``gdal_grid`` documentation, algorithm ``invdistnn``
(https://gdal.org/programs/gdal_grid.html).
"""
from __future__ import annotations

import math
from typing import Optional

import numpy as np
from scipy.spatial import cKDTree

from ..coords import as_xyz
from ..errors import InputError
from ..progress import Monitor
from ._quadtree import gdal_quadtree_order, gdal_quadtree_rank
from .grid import GridSpec, check_memory, resolve_max_distance, row_blocks

__all__ = ["IDW", "idw_grid", "gdal_quadtree_rank", "COINCIDENT_R2", "TIE_ORDERS",
           "DEFAULT_POWER", "DEFAULT_BLOCK_CELLS"]

#: squared distance below which a node "is on" a point (GDAL's constant)
COINCIDENT_R2 = 1e-13
#: orders of equidistant neighbours: GDAL's quadtree, input order, coordinates (x, y, z)
TIE_ORDERS = ("gdal", "input", "xy")
#: IDW power of every entry point (idwdtm, lidartodtm, the model, catalogs): GDAL's
#: invdistnn default
DEFAULT_POWER = 2.0
#: cells per block of :func:`idw_grid` (each cell's value does not depend on it): 65,536
#: keeps the neighbour arrays near 8 MB, reused from block to block (262,144 faulted
#: in fresh pages each time: 3.12 -> 2.94 s CPU for 801,025 cells, same DTM bits)
DEFAULT_BLOCK_CELLS = 65_536


def _validate(x, y, z, power, max_points, radius, min_points, smoothing):
    x, y, z = as_xyz(x, y, z, nonfinite="drop", empty_error=(
        "No points to interpolate from (check the class filter and the extent)."))
    power = float(power)
    if not math.isfinite(power) or power <= 0:
        raise InputError("The IDW power (POWER) must be > 0, got {value}: give 2 "
                         "(GDAL's default) or 3.", value=power)
    max_points = int(max_points)
    if max_points < 0:
        raise InputError("max_points must be >= 0 (0 = every point within the radius), "
                         "got {value}.", value=max_points)
    if radius is not None:
        radius = float(radius)
        if not math.isfinite(radius) or radius <= 0:
            raise InputError("radius must be > 0 (or None for no radius), got {value}.",
                             value=radius)
    if max_points == 0 and radius is None:
        raise InputError("Neighbours (NEIGHBOURS) 0 means every point within the search "
                         "radius, but no Search radius (RADIUS) was given: give RADIUS in "
                         "metres, or NEIGHBOURS such as 12.")
    if max_points > x.size:
        raise InputError("Only {n} points to interpolate from, but Neighbours (NEIGHBOURS) "
                         "is {k}: set NEIGHBOURS to {n} or fewer, or use a cloud with more "
                         "ground points.", n=int(x.size), k=max_points)
    min_points = int(min_points)
    if min_points < 0:
        raise InputError("min_points must be >= 0, got {value}.", value=min_points)
    if max_points and min_points > max_points:
        raise InputError("Minimum points (MIN_POINTS = {min_points}) cannot exceed "
                         "Neighbours (NEIGHBOURS = {max_points}): every cell would be nodata. "
                         "Lower MIN_POINTS or raise NEIGHBOURS.",
                         min_points=min_points, max_points=max_points)
    smoothing = float(smoothing)
    if not math.isfinite(smoothing) or smoothing < 0:
        raise InputError("smoothing must be >= 0, got {value}.", value=smoothing)
    return x, y, z, power, max_points, radius, min_points, smoothing


class IDW:
    """Reusable IDW interpolator over a fixed point set (builds the KD-tree once).

    Parameters
    ----------
    x, y, z : array_like
        Point coordinates and values (non-finite points are dropped).
    power : float
        Distance power ``p`` (default 2; the seed paper found 3 best).
    max_points : int
        Number of nearest neighbours used (GDAL ``max_points``, default 12;
        0 = all within ``radius``).
    radius : float, optional
        Search radius (GDAL ``radius``); ``None`` = unlimited.
    min_points : int
        Minimum neighbours for an estimate (GDAL ``min_points``, default 0).
    smoothing : float
        GDAL ``smoothing`` (default 0: exact interpolator).
    workers : int
        Threads for the KD-tree queries (-1 = all cores).
    """

    def __init__(self, x, y, z, *, power: float = 2.0, max_points: int = 12,
                 radius: Optional[float] = None, min_points: int = 0,
                 smoothing: float = 0.0, workers: int = -1, tie_order: str = "gdal"):
        if tie_order not in TIE_ORDERS:
            raise InputError("tie_order must be one of {choices}, got {value}.",
                             choices=", ".join(TIE_ORDERS), value=tie_order)
        self.tie_order = tie_order
        self._rank = None
        (self.x, self.y, self.z, self.power, self.max_points, self.radius,
         self.min_points, self.smoothing) = _validate(x, y, z, power, max_points, radius,
                                                      min_points, smoothing)
        self.workers = workers
        self.tree = cKDTree(np.column_stack([self.x, self.y]))

    @property
    def n_points(self) -> int:
        """Return the number of data points."""
        return int(self.x.size)

    def _neighbours(self, q: np.ndarray, defer: bool = False):
        """Return the ``k`` nearest of each query row (distances, indices, deferred ties).

        With ``defer``, the rows whose cut-off is tied are left unresolved and returned
        as a mask (``None`` when there is none).
        """
        ub = np.inf if self.radius is None else self.radius * (1.0 + 1e-12)
        k = self.max_points
        if k == 0:
            counts = self.tree.query_ball_point(q, self.radius * (1.0 + 1e-12),
                                                return_length=True, workers=self.workers)
            k = int(max(1, counts.max())) if counts.size else 1
            k = min(k, self.n_points)
        if self.max_points == 0 or k >= self.n_points:
            d, idx = self.tree.query(q, k=k, distance_upper_bound=ub, workers=self.workers)
            if d.ndim == 1:
                d, idx = d[:, None], idx[:, None]
            return d, idx, None
        # one extra neighbour tells whether the k-th distance is tied with the next
        d, idx = self.tree.query(q, k=k + 1, distance_upper_bound=ub, workers=self.workers)
        tied = np.isfinite(d[:, k]) & (d[:, k] == d[:, k - 1])
        d, idx = d[:, :k], idx[:, :k]
        if not tied.any():
            return d, idx, None
        if defer:
            return d, idx, tied
        d[tied], idx[tied] = self._break_ties(q[tied], k, ub)
        return d, idx, None

    def tie_keys(self, ids) -> np.ndarray:
        """Sort keys of the points ``ids`` in the tie order (any shape).

        The keys order these points among themselves exactly as :meth:`tie_rank`
        does, but only these points are ranked (GDAL's quadtree is not built for the
        whole cloud: a few hundred tied nodes of a million need a few thousand points).
        """
        ids = np.asarray(ids, np.int64)
        if self._rank is not None or self.tie_order == "input":
            return self.tie_rank()[ids] if self._rank is not None else ids
        u, inv = np.unique(ids, return_inverse=True)
        if self.tie_order == "gdal":
            rank = gdal_quadtree_order(self.x, self.y, u, tree=self.tree)
        else:                                   # "xy": coordinates, then input order
            rank = np.empty(u.size, np.int64)
            rank[np.lexsort((u, self.z[u], self.y[u], self.x[u]))] = np.arange(u.size)
        return rank[inv.ravel()].reshape(ids.shape)

    def tie_rank(self) -> np.ndarray:
        """Order used between equidistant points, for every point (computed once)."""
        if self._rank is None:
            if self.tie_order == "gdal":
                self._rank = gdal_quadtree_rank(self.x, self.y)
            elif self.tie_order == "xy":       # independent of the other points
                order = np.lexsort((self.z, self.y, self.x))
                self._rank = np.empty(self.n_points, np.int64)
                self._rank[order] = np.arange(self.n_points)
            else:
                self._rank = np.arange(self.n_points)
        return self._rank

    def _break_ties(self, q: np.ndarray, k: int, ub: float):
        """K nearest, equal distances ordered like GDAL's quadtree (or by input index).

        The KD-tree returns equidistant points in an arbitrary order.
        """
        extra = min(self.n_points, k + 16)
        while True:
            d, idx = self.tree.query(q, k=extra, distance_upper_bound=ub,
                                     workers=self.workers)
            last_tied = np.isfinite(d[:, -1]) & (d[:, -1] == d[:, k - 1])
            if not last_tied.any() or extra == self.n_points:
                break
            extra = min(self.n_points, extra * 2)
        valid = np.isfinite(d)
        safe = np.where(valid, idx, 0)
        # exact squared distances as GDAL computes them (sqrt may merge two values)
        dx = self.x[safe] - q[:, :1]
        dy = self.y[safe] - q[:, 1:2]
        r2 = np.where(valid, dx * dx + dy * dy, np.inf)
        # only points whose squared distance another point of the row shares need their
        # tie rank (ranks of a subset keep their relative order: the same sort)
        srt = np.argsort(r2, axis=1, kind="stable")
        s2 = np.take_along_axis(r2, srt, axis=1)
        same = np.zeros(r2.shape, bool)
        same[:, 1:] = s2[:, 1:] == s2[:, :-1]
        same[:, :-1] |= same[:, 1:].copy()
        same &= np.isfinite(s2)
        shared = np.empty_like(same)
        np.put_along_axis(shared, srt, same, axis=1)
        key_idx = np.full(idx.shape, np.iinfo(np.int64).max)
        key_idx[shared] = self.tie_keys(idx[shared])
        order = np.lexsort((key_idx, r2), axis=-1)
        rows = np.arange(d.shape[0])[:, None]
        return d[rows, order][:, :k], idx[rows, order][:, :k]

    def predict(self, xq, yq, *, max_distance: Optional[float] = None,
                tied: Optional[list] = None) -> np.ndarray:
        """IDW estimates at points ``(xq, yq)``; NaN where there is no estimate.

        ``max_distance``: points whose nearest data point is farther are NaN.
        ``tied`` (a list): the points whose ``max_points``-th and next neighbours are
        equidistant are not resolved here — their indices are appended to ``tied`` and
        their values are left for a later call on those points alone, so that the tie
        order of a whole grid is ranked once (:func:`idw_grid`). A point's value
        depends on that point only, so the later call gives the same bits.
        """
        q = np.column_stack([np.asarray(xq, np.float64).ravel(),
                             np.asarray(yq, np.float64).ravel()])
        if q.shape[0] == 0:
            return np.empty(0)
        d, idx, unresolved = self._neighbours(q, defer=tied is not None)
        if unresolved is not None:
            tied.append(np.flatnonzero(unresolved))
        # each row's distances ascend (missing neighbours, inf, last): every neighbour
        # exists when the last column is finite (no radius, or all within it)
        everywhere = bool(np.isfinite(d[:, -1]).all())
        valid = None if everywhere else np.isfinite(d)
        # r2 = d² (1 where no neighbour) + s², w = 1 / r2^(p/2) (0 where no neighbour):
        # in place, and without the masks when every neighbour exists (same values)
        r2 = d * d
        if not everywhere:
            r2[~valid] = 1.0
        if self.smoothing:
            r2 += self.smoothing ** 2
        idx_safe = idx if everywhere else np.where(valid, idx, 0)
        zn = self.z[idx_safe]
        half = 0.5 * self.power
        with np.errstate(divide="ignore", over="ignore"):
            if half == 1.0:                 # r2 ** 1.0 is r2
                w = np.divide(1.0, r2)
            else:
                w = r2 ** half
                np.divide(1.0, w, out=w)
        if not everywhere:
            w[~valid] = 0.0
        num = np.einsum("ij,ij->i", w, zn)
        den = w.sum(axis=1)
        with np.errstate(invalid="ignore", divide="ignore"):
            out = num / den
        bad = (den == 0) | ~np.isfinite(out)
        if self.min_points > 0:
            bad |= (d.shape[1] if everywhere else valid.sum(axis=1)) < self.min_points
        out[bad] = np.nan
        # exact value on coincident points (GDAL tests d² + s² < 1e-13 first): a row's
        # first neighbour is its nearest (missing ones have r2 = 1): it has one when
        # its first has
        hit = r2[:, 0] < COINCIDENT_R2
        if hit.any():
            ch = r2[hit] < COINCIDENT_R2
            if valid is not None:
                ch &= valid[hit]
            if (ch.sum(axis=1) > 1).any():   # several coincident points: GDAL's first
                rk = np.full(ch.shape, np.iinfo(np.int64).max)
                rk[ch] = self.tie_keys(idx_safe[hit][ch])
                first = np.argmin(rk, axis=1)
            else:
                first = np.argmax(ch, axis=1)
            out[hit] = zn[hit, first]
        if max_distance is not None:
            out[~(d[:, 0] <= max_distance)] = np.nan
        return out


def idw_grid(x, y, z, grid: GridSpec, *, power: float = DEFAULT_POWER, max_points: int = 12,
             radius: Optional[float] = None, min_points: int = 0, smoothing: float = 0.0,
             max_distance: Optional[float] = None, fill: bool = False,
             block_cells: int = DEFAULT_BLOCK_CELLS, workers: int = -1,
             tie_order: str = "gdal",
             memory_limit: Optional[int] = None, progress=None, cancel=None) -> np.ndarray:
    """Interpolate points onto ``grid`` by IDW (Shepard 1968; ``gdal_grid invdistnn``).

    Parameters
    ----------
    x, y, z : array_like
        Points (e.g. ground returns).
    grid : GridSpec
        Target grid; values belong to cell centres.
    power, max_points, radius, min_points, smoothing
        As in :class:`IDW` / ``gdal_grid -a invdistnn``.
    max_distance : float, optional
        Cells whose nearest point is farther than this are nodata (NaN). Default
        (``None``): :func:`.grid.default_max_distance` — five mean point spacings.
        Ignored when ``fill`` is True.
    fill : bool
        Interpolate every cell that has neighbours, however far (GDAL behaviour).
    block_cells : int
        Cells per processing block (bounds memory: about ``block_cells ×
        max_points × 40`` bytes).
    progress, cancel : callable, optional
        See :class:`~.progress.Monitor`.

    Returns
    -------
    ndarray, shape ``grid.shape``
        float64, NaN where there is no estimate.

    Raises
    ------
    ValueError
        Fewer points than ``max_points``, a grid that does not fit in memory, or an
        invalid parameter.
    """
    mon = Monitor(progress, cancel)
    check_memory(grid, arrays=1, limit=memory_limit)
    interp = IDW(x, y, z, power=power, max_points=max_points, radius=radius,
                 min_points=min_points, smoothing=smoothing, workers=workers,
                 tie_order=tie_order)
    max_distance = resolve_max_distance(grid, interp.n_points, max_distance, fill=fill)
    out = np.full(grid.shape, np.nan)
    mon.step(0.0)
    # cells whose cut-off neighbours tie are done last, together: the tie order (GDAL's
    # quadtree path of the points they compare) is then ranked once, not once per block
    tied, tx, ty = [], [], []
    for r0, r1 in row_blocks(grid.nrows, grid.ncols, block_cells):
        xx, yy = grid.block_centers(r0, r1)
        ties: list = []
        out[r0:r1] = interp.predict(xx, yy, max_distance=max_distance,
                                    tied=ties).reshape(r1 - r0, -1)
        for t in ties:
            tied.append(r0 * grid.ncols + t)
            tx.append(xx[t])
            ty.append(yy[t])
        mon.step(r1 / grid.nrows)
    if tied:
        out.ravel()[np.concatenate(tied)] = interp.predict(
            np.concatenate(tx), np.concatenate(ty), max_distance=max_distance)
    return out

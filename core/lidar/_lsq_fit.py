"""Batched least-squares tile fits of the LSQ ground filter (private; see :mod:`.lsq`).

Every tile's polynomial surface ``z = B·Δ`` is fitted at once: the normal equations
``BᵀWB Δ = BᵀWF`` of all tiles are accumulated with ``np.add.at``-free bincounts and
solved as one batch; the one-sided rejection (``v > T``) and the paper's stopping rule
run for every tile in vectorised steps (:class:`_TileFit`).
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import List

import numpy as np

from ..progress import Monitor

#: Term names of the polynomial, in the paper's order.
TERMS = {1: ("1", "x", "y"), 2: ("1", "x²", "y²", "x·y", "x", "y")}


def n_coefficients(order: int) -> int:
    """Return the number of polynomial coefficients: 3 for order 1, 6 for order 2."""
    return {1: 3, 2: 6}[int(order)]


def design_matrix(u, v, order: int) -> np.ndarray:
    """Design matrix ``B`` of the paper's polynomial (columns in the paper's order).

    Parameters
    ----------
    u, v : array_like
        Tile coordinates (centred and scaled).
    order : {1, 2}

    Returns
    -------
    numpy.ndarray, shape (n, 3) or (n, 6)
        ``[1, u, v]`` or ``[1, u², v², u·v, u, v]``.
    """
    u = np.asarray(u, dtype=np.float64)
    v = np.asarray(v, dtype=np.float64)
    one = np.ones_like(u)
    if int(order) == 1:
        return np.column_stack((one, u, v))
    return np.column_stack((one, u * u, v * v, u * v, u, v))


def _cols(coef):
    """Contiguous coefficient columns (fast ``take`` gathers)."""
    return [np.ascontiguousarray(coef[:, k]) for k in range(coef.shape[1])]


def _eval(coef, tid, u, v, order):
    """ẑ of points with tile index ``tid`` (coefficients per tile, paper order)."""
    c = _cols(coef)
    if order == 1:
        out = c[1].take(tid)
        out *= u
        out += c[0].take(tid)
        out += c[2].take(tid) * v
        return out
    a = c[1].take(tid)                   # u·(b1·u + b3·v + b4) + v·(b2·v + b5) + b0
    a *= u
    a += c[3].take(tid) * v
    a += c[4].take(tid)
    a *= u
    b = c[2].take(tid)
    b *= v
    b += c[5].take(tid)
    b *= v
    a += b
    a += c[0].take(tid)
    return a


def _grad(coef, tid, u, v, order, half):
    """|∇ẑ| (dimensionless slope) of the tile surfaces at the points."""
    c = _cols(coef)
    if order == 1:
        gu, gv = c[1].take(tid), c[2].take(tid)
    else:
        gu = 2 * c[1].take(tid) * u + c[3].take(tid) * v + c[4].take(tid)
        gv = 2 * c[2].take(tid) * v + c[3].take(tid) * u + c[5].take(tid)
    return np.hypot(gu, gv) / half


def _within(coef, tid, u, v, z, threshold, order, chunk=2_000_000):
    """``z − ẑ ≤ threshold`` per row, evaluated in blocks (bounded temporaries)."""
    out = np.empty(tid.size, dtype=bool)
    per_row = np.ndim(threshold) > 0
    for s in range(0, tid.size, chunk):
        sl = slice(s, s + chunk)
        res = z[sl] - _eval(coef, tid[sl], u[sl], v[sl], order)
        np.less_equal(res, threshold[sl] if per_row else threshold, out=out[sl])
    return out


# pairs (i, j), i <= j, of design columns, as exponent pairs of the monomials
_EXPO = {1: ((0, 0), (1, 0), (0, 1)),
         2: ((0, 0), (2, 0), (0, 2), (1, 1), (1, 0), (0, 1))}


def _normal_equations(tid, u, v, z, w, ntiles, order, chunk=2_000_000):
    """Batched normal equations ``BᵀWB`` and ``BᵀWz`` of every tile at once.

    Sums of monomials ``u^a v^b`` (a + b ≤ 2·order) are accumulated per tile with
    ``np.bincount``; the normal matrices are then assembled from them.
    Returns ``(N, r, szz)`` with shapes ``(ntiles, p, p)``, ``(ntiles, p)`` and
    ``(ntiles,)`` — ``szz`` is the sum of ``w·z²`` (for the kept-height σ).
    Sums are additive, so a change of the kept set is applied as the normal
    equations of the rows that entered minus those of the rows that left.
    """
    ex = _EXPO[order]
    p = len(ex)
    need = sorted({(a1 + a2, b1 + b2) for (a1, b1) in ex for (a2, b2) in ex})
    mom = {m: np.zeros(ntiles) for m in need}
    rz = {e: np.zeros(ntiles) for e in ex}
    szz = np.zeros(ntiles)
    n = tid.size
    for s in range(0, n, chunk):
        t = tid[s:s + chunk]
        uu, vv, zz = u[s:s + chunk], v[s:s + chunk], z[s:s + chunk]
        ww = None if w is None else w[s:s + chunk]
        upow = [np.ones_like(uu) if ww is None else ww]
        vpow = [np.ones_like(vv)]
        for _ in range(2 * order):
            upow.append(upow[-1] * uu)
            vpow.append(vpow[-1] * vv)
        for (a, b) in need:
            if a == 0 and b == 0 and ww is None:
                mom[(0, 0)] += np.bincount(t, minlength=ntiles)
                continue
            mom[(a, b)] += np.bincount(t, weights=upow[a] * vpow[b] if b else upow[a],
                                       minlength=ntiles)
        wz = zz if ww is None else ww * zz
        for (a, b) in ex:
            if a == 0 and b == 0:
                rz[(0, 0)] += np.bincount(t, weights=wz, minlength=ntiles)
            else:
                rz[(a, b)] += np.bincount(t, weights=upow[a] * vpow[b] * zz,
                                          minlength=ntiles)
        szz += np.bincount(t, weights=wz * zz, minlength=ntiles)
    N = np.empty((ntiles, p, p))
    for i, (a1, b1) in enumerate(ex):
        for j, (a2, b2) in enumerate(ex):
            N[:, i, j] = mom[(a1 + a2, b1 + b2)]
    r = np.stack([rz[e] for e in ex], axis=1)
    return N, r, szz


def _solve(N, r, ok):
    """Solve the tiles flagged ``ok`` whose normal matrix is well conditioned.

    Returns ``(coef, solved)``; ``solved`` is False for singular systems
    (reciprocal condition number below 1e-12, e.g. points on a line).
    """
    nt, p = r.shape
    coef = np.full((nt, p), np.nan)
    solved = np.zeros(nt, dtype=bool)
    idx = np.flatnonzero(ok)
    if idx.size == 0:
        return coef, solved
    Ns = N[idx]
    # Jacobi scaling then eigenvalues: a cheap, batched conditioning test
    d = np.sqrt(np.maximum(np.einsum("kii->ki", Ns), 1e-300))
    Ss = Ns / d[:, :, None] / d[:, None, :]
    ev = np.linalg.eigvalsh(Ss)
    good = ev[:, 0] > 1e-12 * ev[:, -1]
    if good.any():
        gi = idx[good]
        sol = np.linalg.solve(Ss[good], (r[gi] / d[good])[:, :, None])[:, :, 0]
        coef[gi] = sol / d[good]
        solved[gi] = True
    return coef, solved


@dataclass
class TileGrid:
    """Square tiles anchored at ``(x0, y0)``; only occupied tiles are listed.

    Attributes
    ----------
    x0, y0 : float
        Grid origin (min x, min y of the cloud).
    size : float
        Tile side, metres.
    ix, iy : ndarray of int
        Column and row of every occupied tile.
    """

    x0: float
    y0: float
    size: float
    ix: np.ndarray
    iy: np.ndarray

    @property
    def count(self) -> int:
        """Number of occupied tiles."""
        return int(self.ix.size)

    @property
    def centres(self) -> np.ndarray:
        """(ntiles, 2) tile centres."""
        return np.column_stack((self.x0 + (self.ix + 0.5) * self.size,
                                self.y0 + (self.iy + 0.5) * self.size))

    def local(self, tile, x, y):
        """Tile coordinates ``u, v`` (centred on the tile centre, ÷ half size)."""
        h = self.size / 2.0
        return ((x - (self.x0 + (self.ix[tile] + 0.5) * self.size)) / h,
                (y - (self.y0 + (self.iy[tile] + 0.5) * self.size)) / h)


def _tile_index(x, y, x0, y0, size):
    """Compact tile index of every point and the :class:`TileGrid`."""
    ix = np.floor((x - x0) / size).astype(np.int64)
    iy = np.floor((y - y0) / size).astype(np.int64)
    ny = int(iy.max()) + 1
    nx = int(ix.max()) + 1
    key = ix * ny + iy
    del ix, iy
    if nx * ny <= 4 * key.size + 1_000_000:
        # dense grid: O(n) compaction of the occupied tiles, no sort
        occupied = np.bincount(key, minlength=nx * ny) > 0
        ukey = np.flatnonzero(occupied)
        remap = np.cumsum(occupied) - 1
        tid = remap[key]
    else:
        ukey, tid = np.unique(key, return_inverse=True)
    grid = TileGrid(float(x0), float(y0), float(size), ukey // ny, ukey % ny)
    return tid.astype(np.int64, copy=False), grid


@dataclass
class FitOutcome:
    """Internal result of :func:`fit_tiles`."""

    coef: np.ndarray          # (ntiles, p), NaN where no surface
    status: np.ndarray        # (ntiles,) 0 no surface, 1 converged, 2 iteration cap,
    #                           3 frozen (too few points left), -1 borrowed
    iterations: np.ndarray    # (ntiles,) number of fits made
    npoints: np.ndarray       # (ntiles,) fitting points at the start
    stats: np.ndarray         # (steps, ntiles, 5): count, min, max, mean, std (NaN = done)
    agg: List[dict]           # aggregated per step
    kept: np.ndarray          # bool per fitting row: still in the kept set at the end


STATUS_NAMES = {0: "too few points", 1: "converged", 2: "iteration cap",
                3: "stopped: too few points left", -1: "borrowed neighbour surface"}


def fit_tiles(tid, u, v, z, ntiles, *, order=2, threshold=0.5, max_iterations=20,
              tolerance=0.01, min_points=None, active=None, rejection="reweighted",
              start=None, mon=None) -> FitOutcome:
    """Fit every tile at once by iterative one-sided least squares (paper step 4).

    Parameters
    ----------
    tid : ndarray of int, shape (m,)
        Tile of every fitting row, **sorted ascending**.
    u, v, z : ndarray, shape (m,)
        Tile coordinates and heights of the rows.
    ntiles : int
    order : {1, 2}
    threshold : float
        ``T``: rows with ``z − ẑ > T`` leave the kept set.
    max_iterations : int
        Fits per tile at most.
    tolerance : float
        Stop when min, max, mean and std of the kept heights all change by less.
    min_points : int, optional
        Tiles with fewer rows get no surface (default ``3 × p``).
    active : ndarray of bool, optional
        Rows taking part at all (e.g. a random subset; default all rows).
    rejection : {"reweighted", "cumulative"}
        ``"reweighted"``: each iteration the kept set is every row with
        ``v ≤ T`` against the current surface (``W = diag(v ≤ T)`` recomputed
        from all residuals, so a row can come back); ``"cumulative"``: rows once
        rejected stay out.
    start : ndarray of bool, optional
        Rows of the first fit (default all active rows); used by the improved
        mode to seed a level with the ground of the previous one.
    mon : Monitor, optional

    Returns
    -------
    FitOutcome
    """
    mon = mon or Monitor()
    fit = _TileFit(tid, u, v, z, ntiles, order=order, threshold=threshold,
                   min_points=min_points, active=active, rejection=rejection)
    fit.first_step(start)
    for it in range(1, int(max_iterations) + 1):
        # progress: share of tiles finished, blended with the iteration count
        mon.step(0.5 * (it - 1) / max_iterations
                 + 0.5 * (1 - fit.live.sum() / max(fit.n_fit_tiles, 1)))
        if not fit.live.any():
            break
        fit.iterate(it, int(max_iterations), tolerance)
    out = fit.outcome()
    mon.update(1.0)
    return out


class _TileFit:
    """State of the iterative fit of every tile (:func:`fit_tiles`).

    The working pool is every active row; with no subset it is the caller's arrays
    themselves (no copies: memory matters at tens of millions of points). Heights are
    taken relative to a per-tile origin ``zt0`` (numerical safety of the sums of
    squares) and the normal equations are updated incrementally as the kept set
    changes.
    """

    def __init__(self, tid, u, v, z, ntiles, *, order, threshold, min_points, active,
                 rejection):
        self.ntiles, self.order = ntiles, order
        self.cumulative = rejection == "cumulative"
        self.p = p = n_coefficients(order)
        self.min_points = 3 * p if min_points is None else max(int(min_points), p)
        rows = np.arange(tid.size) if active is None else np.flatnonzero(active)
        self.kept = np.zeros(tid.size, dtype=bool)
        self.zt0 = np.zeros(ntiles)
        self.cnt0 = cnt0 = np.bincount(tid[rows], minlength=ntiles)
        s0 = np.bincount(tid[rows], weights=z[rows], minlength=ntiles)
        self.zt0[cnt0 > 0] = s0[cnt0 > 0] / cnt0[cnt0 > 0]
        self.status = np.zeros(ntiles, dtype=np.int8)
        self.iterations = np.zeros(ntiles, dtype=np.int32)
        self.coef = np.full((ntiles, p), np.nan)
        self.per_row = np.ndim(threshold) > 0
        threshold = (np.asarray(threshold, dtype=np.float64) if self.per_row
                     else float(threshold))
        # step 0: every tile (also the under-populated ones), all fitting rows
        self.live = cnt0 >= self.min_points          # tiles still iterating
        self.n_fit_tiles = int(self.live.sum())
        if active is None:
            self.pool = None
            self.T, self.U, self.V = tid, u, v
            self.Z = z - self.zt0[tid]
        else:
            self.pool = rows
            self.T, self.U, self.V = tid[rows], u[rows], v[rows]
            self.Z = z[rows] - self.zt0[self.T]
        self.H = threshold if not self.per_row or self.pool is None else threshold[rows]

    def _equations(self, sel=None):
        T, U, V, Z = self.T, self.U, self.V, self.Z
        if sel is not None:
            T, U, V, Z = T[sel], U[sel], V[sel], Z[sel]
        return _normal_equations(T, U, V, Z, None, self.ntiles, self.order)

    def _minmax(self, cur):
        """Per-tile min and max of the kept heights (NaN where none)."""
        T, Z, zt0 = self.T, self.Z, self.zt0
        lo = np.full(self.ntiles, np.nan)
        hi = np.full(self.ntiles, np.nan)
        if T.size:
            starts = np.flatnonzero(np.r_[True, T[1:] != T[:-1]])
            present = T[starts]
            if cur is None:
                mn = np.minimum.reduceat(Z, starts)
                mx = np.maximum.reduceat(Z, starts)
            else:
                zz = np.where(cur, Z, np.inf)
                mn = np.minimum.reduceat(zz, starts)
                zz[~cur] = -np.inf
                mx = np.maximum.reduceat(zz, starts)
                del zz
            ok = np.isfinite(mn)
            lo[present[ok]] = mn[ok] + zt0[present[ok]]
            hi[present[ok]] = mx[ok] + zt0[present[ok]]
        return lo, hi

    def _stats(self, cnt, sz, szz, cur):
        """Per-tile count, min, max, mean, std of the kept heights."""
        lo, hi = self._minmax(cur)
        st = np.full((self.ntiles, 5), np.nan)
        st[:, 0] = cnt
        has = cnt > 0
        mean = sz[has] / cnt[has]
        st[has, 1] = lo[has]
        st[has, 2] = hi[has]
        st[has, 3] = mean + self.zt0[has]
        st[has, 4] = np.sqrt(np.maximum(szz[has] / cnt[has] - mean ** 2, 0.0))
        return st

    def first_step(self, start) -> None:
        """Record step 0 (all fitting rows) and the sums of the first kept set."""
        N0, r0, szz0 = self._equations()
        st0 = self._stats(N0[:, 0, 0], r0[:, 0], szz0, None)
        self.steps = [st0]
        self.agg = [_aggregate(st0, self.cnt0 > 0, "all fitting points",
                               active_tiles=self.n_fit_tiles)]
        self.prev = st0[:, 1:5]
        if start is None:
            self.cur = np.ones(self.T.size, dtype=bool)   # kept set within the pool
            self.N, self.r, self.szz = N0, r0, szz0
        else:
            cur = np.asarray(start, dtype=bool)
            self.cur = cur.copy() if self.pool is None else cur[self.pool]
            self.N, self.r, self.szz = self._equations(self.cur)

    def iterate(self, it: int, max_iterations: int, tolerance: float) -> None:
        """Fit every live tile once, update its kept set, statistics and status."""
        new_coef, solved = _solve(self.N, self.r, self.live & (self.N[:, 0, 0] >= self.p))
        # a tile that cannot be solved any more keeps its previous surface
        lost = self.live & ~solved
        self.status[lost & (self.iterations > 0)] = 3
        self.status[lost & (self.iterations == 0)] = 0
        self.live &= solved
        self.coef[self.live] = new_coef[self.live]
        self.iterations[self.live] += 1
        self._update_kept()
        self._record(it, max_iterations, tolerance, lost)
        self._compact()

    def _update_kept(self) -> None:
        ok = _within(self.coef, self.T, self.U, self.V, self.Z, self.H, self.order)
        if self.cumulative:
            ok &= self.cur                  # rows once rejected stay out
        # (re-weighted: W = diag(v <= T) from every row's residual.) Rows of tiles
        # that have stopped (or never started) keep their kept flag.
        new = np.where(self.live.take(self.T), ok, self.cur)
        del ok
        # the kept set changed by a few rows: update the sums incrementally
        for sel, sign in ((new & ~self.cur, 1.0), (self.cur & ~new, -1.0)):
            if sel.any():
                dN, dr, dszz = self._equations(sel)
                self.N += sign * dN
                self.r += sign * dr
                self.szz += sign * dszz
            del sel
        self.cur = new

    def _record(self, it, max_iterations, tolerance, lost) -> None:
        live = self.live
        cnt = np.rint(self.N[:, 0, 0])
        st = self._stats(cnt, self.r[:, 0], self.szz, self.cur)
        st[~live] = self.steps[-1][~live]   # finished tiles keep their last statistics
        now = st[:, 1:5]
        same = np.all(np.abs(now - self.prev) < tolerance, axis=1)
        self.prev = now
        self.steps.append(st)
        self.agg.append(_aggregate(st, self.cnt0 > 0, f"iteration {it}",
                                   active_tiles=int(live.sum())))
        conv = live & same
        self.status[conv] = 1
        small = live & (cnt < self.p)       # too few kept points left: stop here
        self.status[small] = 3
        done = conv | small | lost
        if it == max_iterations:
            self.status[live & ~done] = 2
            done |= live
        live &= ~done

    def _compact(self) -> None:
        """Drop the rows of finished tiles once they are most of the pool."""
        stay = self.live.take(self.T)
        if stay.sum() >= 0.5 * self.T.size:
            return
        fin = ~stay
        if self.pool is None:
            self.kept[fin & self.cur] = True
            self.pool = np.flatnonzero(stay)
        else:
            self.kept[self.pool[fin & self.cur]] = True
            self.pool = self.pool[stay]
        self.T, self.U, self.V = self.T[stay], self.U[stay], self.V[stay]
        self.Z, self.cur = self.Z[stay], self.cur[stay]
        if self.per_row:
            self.H = self.H[stay]

    def outcome(self) -> FitOutcome:
        """Return the :class:`FitOutcome` (coefficients with ``zt0`` moved into b0)."""
        if self.pool is None:
            self.kept |= self.cur
        else:
            self.kept[self.pool[self.cur]] = True
        coef_out = self.coef.copy()
        coef_out[:, 0] = coef_out[:, 0] + self.zt0
        coef_out[self.status == 0] = np.nan
        return FitOutcome(coef_out, self.status, self.iterations, self.cnt0,
                          np.stack(self.steps), self.agg, self.kept)


def _aggregate(st, present, label, active_tiles=None) -> dict:
    """Whole-cloud statistics of one step from per-tile statistics."""
    cnt = np.nan_to_num(st[:, 0])
    has = present & (cnt > 0)
    n = cnt[has].sum()
    if n == 0:
        return dict(step=label, points=0, zmin=np.nan, zmax=np.nan, zmean=np.nan,
                    std=np.nan, active_tiles=active_tiles)
    m = st[has, 3]
    s = st[has, 4]
    mean = float((cnt[has] * m).sum() / n)
    var = float((cnt[has] * (s * s + (m - mean) ** 2)).sum() / n)
    return dict(step=label, points=int(n), zmin=float(np.nanmin(st[has, 1])),
                zmax=float(np.nanmax(st[has, 2])), zmean=mean, std=float(np.sqrt(var)),
                active_tiles=active_tiles)

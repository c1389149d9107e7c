"""The two modes of the LSQ ground filter (private; see :mod:`.lsq`).

``faithful``: the paper's tiles, one fit per tile. ``improved``: a coarse-to-fine
cascade of overlapping windows with slope-adapted thresholds, sparse tiles borrowing
their neighbours' surfaces.
"""
from __future__ import annotations

import time

import numpy as np

from ..errors import InputError
from ._lsq_fit import (
    TileGrid,
    _eval,
    _grad,
    _tile_index,
    fit_tiles,
    n_coefficients,
)


def _too_few(order, min_points, npoints, n) -> InputError:
    p = n_coefficients(order)
    mp = 3 * p if min_points is None else max(int(min_points), p)
    return InputError(
        "Too few points: no tile has enough well-spread points to fit an order-{order} "
        "surface (at least {min_points} per tile, not all on one line; the fullest tile has "
        "{fullest} of the {n} points). Use a larger TILE_SIZE, ORDER 1, or a denser cloud.",
        order=order, min_points=mp, fullest=int(npoints.max()), n=n)


def _random_subset(tid_sorted, subset_size, seed):
    """Per tile, a random subset of at most ``subset_size`` rows (mask, sorted rows)."""
    rng = np.random.default_rng(seed)
    key = rng.random(tid_sorted.size)
    o = np.lexsort((key, tid_sorted))
    starts = np.flatnonzero(np.r_[True, tid_sorted[o][1:] != tid_sorted[o][:-1]])
    counts = np.diff(np.r_[starts, o.size])
    rank = np.arange(o.size) - np.repeat(starts, counts)
    mask = np.zeros(tid_sorted.size, dtype=bool)
    mask[o[rank < int(subset_size)]] = True
    return mask


def _borrow(coef, solved, grid):
    """Index of the tile whose surface each tile uses (itself, or nearest fitted)."""
    src = np.arange(grid.count)
    missing = np.flatnonzero(~solved)
    if missing.size and solved.any():
        from scipy.spatial import cKDTree
        good = np.flatnonzero(solved)
        c = grid.centres
        _, j = cKDTree(c[good]).query(c[missing])
        src[missing] = good[j]
    return src


def _surface_at(x, y, grid, coef, src, tid, order):
    """ẑ and |∇ẑ| of each point from the surface of tile ``src[tid]``."""
    s = src[tid]
    u, v = grid.local(s, x, y)
    zhat = _eval(coef, s, u, v, order)
    slope = _grad(coef, s, u, v, order, grid.size / 2.0)
    far = (np.abs(u) > 1) | (np.abs(v) > 1)
    if far.any():
        # borrowed surface outside its own tile: continue it linearly from the tile
        # edge (tangent plane) instead of extrapolating the quadratic
        sf = s[far]
        uc, vc = np.clip(u[far], -1, 1), np.clip(v[far], -1, 1)
        c = coef
        if order == 1:
            gu, gv = c[sf, 1], c[sf, 2]
        else:
            gu = 2 * c[sf, 1] * uc + c[sf, 3] * vc + c[sf, 4]
            gv = 2 * c[sf, 2] * vc + c[sf, 3] * uc + c[sf, 5]
        zhat[far] = (_eval(coef, sf, uc, vc, order) + gu * (u[far] - uc)
                     + gv * (v[far] - vc))
        slope[far] = np.hypot(gu, gv) / (grid.size / 2.0)
    return zhat, slope




def _faithful(x, y, z, fit_pts, x0, y0, order, tile_size, threshold, max_iterations,
              tolerance, subset_size, seed, min_points, sparse_tiles, rejection, mon,
              timings):
    t0 = time.perf_counter()
    n = x.size
    tid_all, grid = _tile_index(x, y, x0, y0, tile_size)
    if fit_pts is None:
        rows = np.argsort(tid_all, kind="stable")
        T = tid_all[rows]
    else:
        ft = tid_all[fit_pts]
        o = np.argsort(ft, kind="stable")
        rows = fit_pts[o]
        T = ft[o]
        del o, ft
    u, v = grid.local(T, x[rows], y[rows])
    Z = z[rows]
    del rows
    active = None
    if subset_size is not None:
        active = _random_subset(T, subset_size, seed)
    timings["tiling"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    out = fit_tiles(T, u, v, Z, grid.count, order=order, threshold=threshold,
                    max_iterations=max_iterations, tolerance=tolerance,
                    min_points=min_points, active=active, rejection=rejection,
                    mon=mon.sub(0.0, 0.85))
    del u, v, Z, T
    timings["fitting"] = time.perf_counter() - t0
    t0 = time.perf_counter()
    solved = out.status != 0
    if not solved.any():
        raise _too_few(order, min_points, out.npoints, n)
    status = out.status.copy()
    if sparse_tiles == "borrow":
        src = _borrow(out.coef, solved, grid)
        status[~solved] = -1
    else:
        src = np.arange(grid.count)
    surface = np.full(n, np.nan)
    blk = 2_000_000
    for s in range(0, n, blk):
        mon.step(0.85 + 0.15 * s / n)
        sl = slice(s, s + blk)
        surface[sl] = _surface_at(x[sl], y[sl], grid, out.coef, src, tid_all[sl], order)[0]
    del tid_all
    ground = z <= surface + threshold          # NaN surface → False
    thr = np.broadcast_to(np.float64(threshold), (n,))   # one value, no n-array
    timings["classification"] = time.perf_counter() - t0
    extra = dict(grid=grid, coefficients=out.coef, tile_status=status,
                 tile_iterations=out.iterations, tile_points=out.npoints,
                 tile_stats=out.stats, iteration_stats=out.agg)
    return ground, surface, thr, extra


def _window_rows(x, y, pts, x0, y0, size, overlap):
    """Replicate points into every overlapping fitting window that holds them.

    The window of tile ``(i, j)`` is the tile grown by ``overlap × size`` on every
    side. Returns ``(tile_key, point_index, nx_keys)`` for the rows, sorted by key,
    where ``key = i * ny + j``.
    """
    fx = (x[pts] - x0) / size
    fy = (y[pts] - y0) / size
    ix = np.floor(fx).astype(np.int64)
    iy = np.floor(fy).astype(np.int64)
    reach = int(np.ceil(overlap)) if overlap > 0 else 0
    ny = int(np.floor((y[pts].max() - y0) / size)) + 2 + reach
    keys, idx = [], []
    for di in range(-reach, reach + 1):
        for dj in range(-reach, reach + 1):
            ti, tj = ix + di, iy + dj
            inside = ((np.abs(fx - (ti + 0.5)) <= 0.5 + overlap)
                      & (np.abs(fy - (tj + 0.5)) <= 0.5 + overlap) & (ti >= 0) & (tj >= 0))
            keys.append((ti * ny + tj)[inside])
            idx.append(pts[inside])
    keys = np.concatenate(keys)
    idx = np.concatenate(idx)
    o = np.argsort(keys, kind="stable")
    return keys[o], idx[o], ny


def _blend(x, y, x0, y0, size, ny, ukeys, coef, solved, order, bilinear=True,
           chunk=2_000_000):
    """Surface blended between tile centres (bilinear partition of unity).

    Every point takes the surfaces of the four tiles whose centres surround it,
    each evaluated at the point, weighted bilinearly by distance to the centres;
    missing or unsolved tiles get weight 0 (the others are renormalised). Returns
    ``(zhat, slope)``; NaN where no surrounding tile has a surface.
    """
    n = x.size
    zhat = np.full(n, np.nan)
    slope = np.zeros(n)
    h = size / 2.0
    for s in range(0, n, chunk):
        xs, ys = x[s:s + chunk], y[s:s + chunk]
        fx = (xs - x0) / size - 0.5
        fy = (ys - y0) / size - 0.5
        i0 = np.floor(fx).astype(np.int64)
        j0 = np.floor(fy).astype(np.int64)
        tx, ty = fx - i0, fy - j0
        acc = np.zeros(xs.size)
        gacc = np.zeros(xs.size)
        wsum = np.zeros(xs.size)
        own_z = np.full(xs.size, np.nan)
        own_g = np.zeros(xs.size)
        if bilinear:
            corners = ((0, 0, (1 - tx) * (1 - ty)), (1, 0, tx * (1 - ty)),
                       (0, 1, (1 - tx) * ty), (1, 1, tx * ty))
        else:   # the point's own tile, fallback to the nearest neighbours
            own_i = np.floor(fx + 0.5).astype(np.int64) - i0
            own_j = np.floor(fy + 0.5).astype(np.int64) - j0
            corners = tuple((di, dj, np.where((own_i == di) & (own_j == dj), 1.0, 1e-6))
                            for di in (0, 1) for dj in (0, 1))
        for di, dj, w in corners:
            ti, tj = i0 + di, j0 + dj
            key = ti * ny + tj
            pos = np.minimum(np.searchsorted(ukeys, key), ukeys.size - 1)
            hit = (ukeys[pos] == key) & (ti >= 0) & (tj >= 0)
            hit &= solved[pos]
            if not hit.any():
                continue
            k = pos[hit]
            u = (xs[hit] - (x0 + (ti[hit] + 0.5) * size)) / h
            v = (ys[hit] - (y0 + (tj[hit] + 0.5) * size)) / h
            ww = w[hit]
            val, grd = _eval(coef, k, u, v, order), _grad(coef, k, u, v, order, h)
            acc[hit] += ww * val
            gacc[hit] += ww * grd
            wsum[hit] += ww
            if not bilinear:        # the own tile alone where it is solved (see below)
                mine = ww == 1.0
                own_z[np.flatnonzero(hit)[mine]] = val[mine]
                own_g[np.flatnonzero(hit)[mine]] = grd[mine]
        good = wsum > 0
        zz = np.full(xs.size, np.nan)
        zz[good] = acc[good] / wsum[good]
        gg = np.zeros(xs.size)
        gg[good] = gacc[good] / wsum[good]
        if not bilinear:
            # no 1e-6 leak of the neighbours into a solved tile: a tile's surface then
            # depends on its own window only, so a catalog chunk equals the merged run
            # away from its buffer edge (the leak grew across levels into class flips)
            mine = np.isfinite(own_z)
            zz[mine], gg[mine] = own_z[mine], own_g[mine]
        zhat[s:s + chunk] = zz
        slope[s:s + chunk] = gg
    return zhat, slope


def _improved(x, y, z, fit_pts, x0, y0, order, tile_size, threshold, max_iterations,
              tolerance, subset_size, seed, min_points, sparse_tiles, levels, overlap,
              slope_factor, slope_cap, blend, rejection, mon, timings):
    """Coarse-to-fine, overlapping, blended, slope-adaptive LSQ (ours, see module doc)."""
    n = x.size
    p = n_coefficients(order)
    if fit_pts is None:
        fit_pts = np.arange(n)
    seeds = None                              # bool per point: ground of the previous level
    surface = slope = None
    level_info = []
    nlev = len(levels)
    out = None
    for k, frac in enumerate(levels):
        lm = mon.sub(k / nlev, (k + 1) / nlev)
        t0 = time.perf_counter()
        size = tile_size * float(frac)
        keys, idx, ny = _window_rows(x, y, fit_pts, x0, y0, size, overlap)
        ukeys, T = np.unique(keys, return_inverse=True)
        T = T.astype(np.int64)
        del keys
        ix, iy = ukeys // ny, ukeys % ny
        h = size / 2.0
        U = (x[idx] - (x0 + (ix[T] + 0.5) * size)) / h
        V = (y[idx] - (y0 + (iy[T] + 0.5) * size)) / h
        active = None
        if subset_size is not None:
            active = _random_subset(T, subset_size, seed)
        rthr = threshold if slope is None else threshold + slope_factor * slope[idx]
        out = fit_tiles(T, U, V, z[idx], ukeys.size, order=order, threshold=rthr,
                        max_iterations=max_iterations, tolerance=tolerance,
                        min_points=min_points, active=active, rejection=rejection,
                        start=None if seeds is None else seeds[idx], mon=lm.sub(0.0, 0.8))
        solved = out.status != 0
        del T, U, V, idx
        if not solved.any():
            if k == 0:
                raise _too_few(order, min_points, out.npoints, n)
            break
        zh, sl = _blend(x, y, x0, y0, size, ny, ukeys, out.coef, solved, order,
                        bilinear=blend)
        lm.step(0.95)
        if surface is not None:
            # where the finer level has no surface, keep the coarser one
            miss = np.isnan(zh)
            zh[miss] = surface[miss]
            sl[miss] = slope[miss]
        surface, slope = zh, sl
        thr = threshold + np.minimum(slope_factor * slope, slope_cap)
        # seed of the next level: this level's ground (and everything below it)
        seeds = z <= surface + thr
        seed_n = int(seeds[fit_pts].sum())
        grid = TileGrid(float(x0), float(y0), float(size), ix, iy)
        level_info.append(dict(level=k + 1, tile_size=size, tiles=int(ukeys.size),
                               fitted=int(solved.sum()), seed_points=seed_n,
                               seconds=time.perf_counter() - t0))
        if seed_n < p:
            break
    ground = z <= surface + thr
    status = out.status.copy()
    status[status == 0] = -1        # their points took the neighbouring tiles' surfaces
    extra = dict(grid=grid, coefficients=out.coef, tile_status=status,
                 tile_iterations=out.iterations, tile_points=out.npoints,
                 tile_stats=out.stats, iteration_stats=out.agg, levels=level_info)
    return ground, surface, thr, extra

"""The exact kernel of the slope-based filter (private; see :mod:`.slope`).

Vosselman (2000): ``S_i`` = the largest slope from any neighbour within ``r`` up to the
point, computed exactly in vectorised blocks: a cell grid with per-cell minima bounds
most points without a pair test (cone bounds), the rest are settled by pair tests in
blocks of at most ``_PAIR_CHUNK`` pairs.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Optional

import numpy as np

from ..coords import as_xyz
from ..errors import InputError
from ..progress import Monitor

#: What :mod:`.slope` and :mod:`.sweep` share; everything else here is the kernel's own.
__all__ = ["SlopeStats", "allowed_rise", "bounded_max_slope", "check_height",
           "check_radius", "check_slope", "filter_xyz", "point_mask", "slope_tan",
           "take_points"]

_EPS = np.finfo(np.float64).eps
_PAIR_CHUNK = 3_000_000        # candidate pairs evaluated per vectorised block
_POINT_CHUNK = 1_000_000       # points classified per block
_MAX_CELLS = 30_000_000        # dense grid size limit (cells), ~0.5 GB
_MIN_CELL_FRACTION = 1.0 / 16  # smallest grid cell, as a fraction of r


# ============================================================================ helpers
def filter_xyz(x, y, z):
    return as_xyz(x, y, z, empty_error=(
        "The point cloud is empty: there is nothing to filter. Check the input file or "
        "the return/noise selection."))



def check_radius(radius) -> float:
    try:
        r = float(radius)
    except (TypeError, ValueError):
        raise InputError("radius must be a number of metres, got {value}.",
                         value=repr(radius)) from None
    if not math.isfinite(r) or r <= 0:
        raise InputError("radius must be a positive number of metres (> 0), got {value}; "
                         "use e.g. {example} m for airborne LiDAR.", value=radius,
                         example=10.0)
    return r


def check_slope(slope) -> float:
    try:
        s = float(slope)
    except (TypeError, ValueError):
        raise InputError("slope must be an angle in degrees, got {value}.",
                         value=repr(slope)) from None
    if not math.isfinite(s) or not 0.0 < s < 90.0:
        raise InputError("slope threshold must be an angle strictly between 0 and 90 "
                         "degrees, got {value}; typical values are 30-70 (e.g. "
                         "{example}).", value=slope, example=40.0)
    return s


def check_height(h) -> float:
    try:
        v = float(h)
    except (TypeError, ValueError):
        raise InputError("height_tolerance must be a number of metres, got {value}.",
                         value=repr(h)) from None
    if not math.isfinite(v) or v < 0:
        raise InputError("height_tolerance must be zero or a positive number of metres, "
                         "got {value}.", value=h)
    return v


def point_mask(mask, n: int, name: str) -> np.ndarray:
    if mask is None:
        return np.ones(n, dtype=bool)
    m = np.asarray(mask, dtype=bool).ravel()
    if m.size != n:
        raise InputError("{name} has {size} entries but the cloud has {n} points; give "
                         "one flag per point.", name=name, size=int(m.size), n=n)
    return m


def take_points(x, y, z, mask):
    """Return the masked coordinates (no copy when every point is selected)."""
    if mask.all():
        return x, y, z
    return x[mask], y[mask], z[mask]


def allowed_rise(distance, slope) -> np.ndarray:
    """Largest height above a neighbour at ``distance`` that is still ground.

    ``distance * tan(slope)`` (metres), e.g. 2.52 m at 3 m and 40 degrees.

    Examples
    --------
    >>> [round(float(allowed_rise(3.0, t)), 2) for t in (40, 44, 48, 52, 56, 60)]
    [2.52, 2.9, 3.33, 3.84, 4.45, 5.2]
    """
    return np.asarray(distance, dtype=np.float64) * np.tan(np.radians(slope))


def slope_tan(slope: float) -> float:
    return float(np.tan(np.radians(np.float64(slope))))


# ============================================================================ the kernel
@dataclass
class SlopeStats:
    points: int = 0
    settled_by_bound: int = 0
    pairs_tested: int = 0
    cell_size: float = 0.0
    offsets: int = 0

    def as_dict(self) -> dict:
        return dict(points=self.points, settled_by_bound=self.settled_by_bound,
                    pairs_tested=self.pairs_tested, cell_size=self.cell_size,
                    offsets=self.offsets)


def _choose_cell(qx, qy, r: float, n_q: int) -> float:
    """Grid cell (speed only, never the labels).

    About 6 neighbours per cell, but at least r/8 (bounds the number of cell
    offsets to visit) and, for large radii, at most ~400 points per cell (bounds
    the pairs inside a cell) unless that would need more than (2 * 16)^2 offsets.
    """
    w = max(float(qx.max() - qx.min()), r)
    h = max(float(qy.max() - qy.min()), r)
    density = max(n_q / (w * h), 1e-12)
    s = max(math.sqrt(6.0 / density), r / 8.0)
    s = min(s, max(math.sqrt(400.0 / density), r / 16.0))
    return float(min(s, r))


@dataclass(frozen=True)
class _CellGrid:
    """The padded square grid of one :func:`bounded_max_slope` call, with margins."""

    x0: float
    y0: float
    s: float           # cell side (m)
    pad: int           # cells of padding on every side (reach of r)
    nx: int
    ny: int
    dd: float = 0.0    # distance margin (m)
    dz: float = 0.0    # height margin (m)

    def cell_of(self, xx, yy) -> np.ndarray:
        """Return the flat (clipped) cell index of every point."""
        ix = np.floor((xx - self.x0) / self.s).astype(np.int64) + self.pad
        iy = np.floor((yy - self.y0) / self.s).astype(np.int64) + self.pad
        np.clip(ix, 0, self.nx - 1, out=ix)
        np.clip(iy, 0, self.ny - 1, out=iy)
        return iy * self.nx + ix


@dataclass
class _Neighbours:
    """Neighbour points sorted by (cell, z), with per-cell start, count, lowest z."""

    x: np.ndarray
    y: np.ndarray
    z: np.ndarray
    start: np.ndarray
    count: np.ndarray
    minz: np.ndarray


def _sort_neighbours(g: _CellGrid, qx, qy, qz) -> _Neighbours:
    """Sort the neighbour set by (cell, z) and index the cells' runs."""
    qcell = g.cell_of(qx, qy)
    order = np.lexsort((qz, qcell))
    qcell = qcell[order]
    ncell = g.nx * g.ny
    count = np.bincount(qcell, minlength=ncell).astype(np.int64)
    start = np.cumsum(count) - count
    minz = np.full(ncell, np.inf)
    qzs = qz[order]
    first = np.flatnonzero(np.r_[True, qcell[1:] != qcell[:-1]])
    minz[qcell[first]] = qzs[first]
    return _Neighbours(qx[order], qy[order], qzs, start, count, minz)


def _cell_offsets(g: _CellGrid, r: float) -> list:
    """Cell offsets within reach, ``(dmin, ox, oy, dmax)`` sorted by ``dmin``."""
    offs = []
    for oy in range(-g.pad, g.pad + 1):
        for ox in range(-g.pad, g.pad + 1):
            gx = max(abs(ox) - 1, 0) * g.s
            gy = max(abs(oy) - 1, 0) * g.s
            dmin = math.hypot(gx, gy)
            if dmin - g.dd <= r:
                dmax = math.hypot((abs(ox) + 1) * g.s, (abs(oy) + 1) * g.s)
                offs.append((dmin, ox, oy, dmax))
    offs.sort()
    return offs


def _shifted(mz2: np.ndarray, ox: int, oy: int) -> np.ndarray:
    """Return the minimum grid seen at cell + (ox, oy), inf outside."""
    ny, nx = mz2.shape
    out = np.full((ny, nx), np.inf)
    ys_dst = slice(max(0, -oy), ny - max(0, oy))
    xs_dst = slice(max(0, -ox), nx - max(0, ox))
    ys_src = slice(max(0, oy), ny - max(0, -oy))
    xs_src = slice(max(0, ox), nx - max(0, -ox))
    out[ys_dst, xs_dst] = mz2[ys_src, xs_src]
    return out


def _cone_bounds(g: _CellGrid, minz, offs, r: float, t_lo: float, t_hi: float):
    """Per-cell cone bounds ``(ub, lbfar)`` of the heights ``z - h``.

    Above ``ub`` a point surely has ``S > t_hi``; at or below ``lbfar`` no pair with a
    cell two or more cells away can exceed ``t_lo``.
    """
    mz2 = minz.reshape(g.ny, g.nx)
    ub = np.full((g.ny, g.nx), np.inf)
    lbfar = np.full((g.ny, g.nx), np.inf)
    for dmin, ox, oy, dmax in offs:
        far = max(abs(ox), abs(oy)) >= 2
        use_ub = bool(ox or oy) and dmax + 4 * g.dd <= r
        if not (far or use_ub):
            continue
        sh = _shifted(mz2, ox, oy)
        if use_ub:
            np.minimum(ub, sh + (t_hi * (dmax + 4 * g.dd) + g.dz), out=ub)
        if far:
            np.minimum(lbfar, sh + (t_lo * max(dmin - g.dd, 0.0) - g.dz), out=lbfar)
    return ub.ravel(), lbfar.ravel()


def _height_prefix(lo, hi, qzs, thr) -> np.ndarray:
    """Binary search, in each cell run ``[lo, hi)``, of the prefix with ``z < thr``."""
    n_q = qzs.size
    while True:
        open_ = lo < hi
        if not open_.any():
            return lo
        mid = (lo + hi) >> 1
        less = qzs[np.minimum(mid, n_q - 1)] < thr
        lo = np.where(open_ & less, mid + 1, lo)
        hi = np.where(open_ & ~less, mid, hi)


@dataclass
class _Block:
    """Points of P classified together (one chunk, sorted by cell)."""

    x: np.ndarray
    y: np.ndarray
    z: np.ndarray
    cell: np.ndarray
    zh: np.ndarray      # z - h
    fx: np.ndarray      # fractional position inside the cell
    fy: np.ndarray
    v: np.ndarray       # the block's bounded S


def _offset_pairs(g: _CellGrid, nb: _Neighbours, blk: _Block, idx, ox: int, oy: int, *,
                  r: float, h: float, t_lo: float, stats: SlopeStats) -> None:
    """Evaluate the candidate pairs of the points ``idx`` with the cells at (ox, oy)."""
    c2 = blk.cell[idx] + (oy * g.nx + ox)
    mz = nb.minz[c2]
    # point-to-cell distance (lower bound), in cells then metres
    fx, fy = blk.fx[idx], blk.fy[idx]
    gx = np.maximum(np.maximum(ox - fx, fx - (ox + 1)), 0.0)
    gy = np.maximum(np.maximum(oy - fy, fy - (oy + 1)), 0.0)
    dlb = np.maximum(np.sqrt(gx * gx + gy * gy) * g.s - g.dd, 0.0)
    thr = blk.zh[idx] - t_lo * dlb + g.dz       # only z_j < thr may exceed t_lo
    cand = (mz < thr) & (dlb <= r)
    if not cand.any():
        return
    idx, c2, thr = idx[cand], c2[cand], thr[cand]
    seg0 = nb.start[c2]
    m = _height_prefix(seg0.copy(), seg0 + nb.count[c2], nb.z, thr) - seg0
    _eval_pairs(idx, seg0, m, blk.x, blk.y, blk.z, nb.x, nb.y, nb.z, r, h, blk.v, stats)


def _classify_block(g: _CellGrid, nb: _Neighbours, offs, bounds, blk: _Block, *,
                    r: float, h: float, t_lo: float, t_hi: float, mon: Monitor,
                    stats: SlopeStats) -> None:
    """Bound, then evaluate the candidate pairs of one block of P (fills ``blk.v``)."""
    ub, lbfar = bounds
    sure_ng = blk.zh > ub[blk.cell]
    blk.v[sure_ng] = np.inf
    need_far = (~sure_ng) & (blk.zh > lbfar[blk.cell])
    stats.settled_by_bound += int(np.count_nonzero(sure_ng)) + int(
        np.count_nonzero(~sure_ng & ~need_far))
    act = np.flatnonzero(~sure_ng)
    act_far = need_far[act]
    for k, (_dmin, ox, oy, _dmax) in enumerate(offs):
        if k % 8 == 0:
            mon.step(k / len(offs))
            keep = blk.v[act] <= t_hi           # drop points already proven non-ground
            act, act_far = act[keep], act_far[keep]
        idx = act[act_far] if max(abs(ox), abs(oy)) >= 2 else act
        if k % 8:
            idx = idx[blk.v[idx] <= t_hi]
        if idx.size:
            _offset_pairs(g, nb, blk, idx, ox, oy, r=r, h=h, t_lo=t_lo, stats=stats)
    mon.update(1.0)


def _make_block(g: _CellGrid, px, py, pz, pcell, sel, h: float) -> _Block:
    """Gather the block ``sel`` of P with its cells and in-cell positions."""
    bx, by, bz = px[sel], py[sel], pz[sel]
    bcell = pcell[sel]
    fx = (bx - g.x0) / g.s - (bcell % g.nx - g.pad)
    fy = (by - g.y0) / g.s - (bcell // g.nx - g.pad)
    return _Block(bx, by, bz, bcell, bz - h, fx, fy, np.full(sel.size, -np.inf))


def _grid_for(px, py, pz, qx, qy, qz, r: float, h: float, cell) -> _CellGrid:
    """Return the padded grid of P and Q (cell chosen for speed) with its safety margins."""
    x0 = min(float(px.min()), float(qx.min()))
    y0 = min(float(py.min()), float(qy.min()))
    x1 = max(float(px.max()), float(qx.max()))
    y1 = max(float(py.max()), float(qy.max()))
    s = float(cell) if cell else _choose_cell(qx, qy, r, qx.size)
    s = max(s, r * _MIN_CELL_FRACTION)      # caps the number of cell offsets
    pad = int(math.floor(r / s)) + 2
    nx = int(math.floor((x1 - x0) / s)) + 1 + 2 * pad
    ny = int(math.floor((y1 - y0) / s)) + 1 + 2 * pad
    # Safety margins, far above float64 rounding of the bounds and of the
    # canonical comparison, far below any meaningful height or distance.
    cmax = max(abs(x0), abs(y0), abs(x1), abs(y1), r)
    zmax = max(float(np.abs(pz).max()), float(np.abs(qz).max()), 1.0) + h
    return _CellGrid(x0, y0, s, pad, nx, ny, dd=1e-7 * s + 256 * _EPS * cmax,
                     dz=1e-7 + 256 * _EPS * zmax)


def bounded_max_slope(px, py, pz, qx, qy, qz, *, radius: float, height: float,
                       t_lo: float, t_hi: float, cell: Optional[float] = None,
                       mon: Monitor, stats: SlopeStats, _tile: bool = False) -> np.ndarray:
    """Return ``S_i`` of every point of P against the neighbour set Q, exact where needed.

    Vosselman (2000) slope rule with the cell bounds of the module docstring. The
    result ``v`` has ``v = S`` exactly when ``t_lo < S <= t_hi``; ``v > t_hi`` when
    ``S > t_hi``; ``v <= t_lo`` when ``S <= t_lo``. Hence for every threshold ``t``
    in ``[t_lo, t_hi]``: ``(v > t) == (S > t)``.
    """
    n_p = px.size
    v = np.full(n_p, -np.inf)
    if not _tile:
        stats.points += n_p
    if qx.size == 0 or n_p == 0:
        return v
    g = _grid_for(px, py, pz, qx, qy, qz, radius, height, cell)
    if g.nx * g.ny > _MAX_CELLS and not _tile:
        # Too large for one dense grid (huge or sparse extent): exact tiling with an
        # r-wide overlap of the neighbour set, each tile on its own grid.
        return _tiled_max_slope(px, py, pz, qx, qy, qz, radius=radius, height=height,
                                t_lo=t_lo, t_hi=t_hi, cell=g.s, pad=g.pad, mon=mon,
                                stats=stats, origin=(g.x0, g.y0))
    stats.cell_size = g.s
    nb = _sort_neighbours(g, qx, qy, qz)
    mon.step(0.05)
    offs = _cell_offsets(g, radius)
    stats.offsets = len(offs)
    bounds = _cone_bounds(g, nb.minz, offs, radius, t_lo, t_hi)
    mon.step(0.1)
    # classify P in blocks, sorted by cell for memory locality
    pcell = g.cell_of(px, py)
    porder = np.argsort(pcell, kind="stable")
    n_blocks = max(1, -(-n_p // _POINT_CHUNK))
    for b in range(n_blocks):
        sel = porder[b * _POINT_CHUNK:(b + 1) * _POINT_CHUNK]
        blk = _make_block(g, px, py, pz, pcell, sel, height)
        _classify_block(g, nb, offs, bounds, blk, r=radius, h=height, t_lo=t_lo,
                        t_hi=t_hi, mon=mon.sub(0.1 + 0.9 * b / n_blocks,
                                               0.1 + 0.9 * (b + 1) / n_blocks),
                        stats=stats)
        v[sel] = blk.v
    return v


def _tiled_max_slope(px, py, pz, qx, qy, qz, *, radius, height, t_lo, t_hi, cell, pad,
                     mon, stats, origin) -> np.ndarray:
    """Run :func:`bounded_max_slope` tile by tile (Vosselman 2000 rule, exact).

    Exact because each tile's neighbour set holds every neighbour point within
    ``radius`` (plus a margin) of the tile.
    """
    r, s = radius, cell
    x0, y0 = origin
    cmax = max(abs(x0), abs(y0), float(np.abs(px).max()), float(np.abs(py).max()),
               float(np.abs(qx).max()), float(np.abs(qy).max()))
    e = r + 1e-6 * max(1.0, r) + 1024 * _EPS * cmax             # reach incl. margin
    side = max((math.sqrt(_MAX_CELLS / 2.0) - 2 * pad - 2) * s, 4.0 * e)   # tile side (m)
    stats.cell_size = s
    ptx = np.floor((px - x0) / side).astype(np.int64)
    pty = np.floor((py - y0) / side).astype(np.int64)
    ntx = int(max(ptx.max(), np.floor((qx.max() - x0 + e) / side))) + 2
    pkey = pty * ntx + ptx
    del ptx, pty
    # every neighbour point goes to each tile (at most 4) its reach overlaps
    keys, idx = [], []
    qtx = [np.floor((qx - x0 - e) / side).astype(np.int64),
           np.floor((qx - x0 + e) / side).astype(np.int64)]
    qty = [np.floor((qy - y0 - e) / side).astype(np.int64),
           np.floor((qy - y0 + e) / side).astype(np.int64)]
    allq = np.arange(qx.size)
    for a in (0, 1):
        for b in (0, 1):
            m = np.ones(qx.size, dtype=bool)
            if a:
                m &= qtx[1] != qtx[0]
            if b:
                m &= qty[1] != qty[0]
            keys.append(qty[b][m] * ntx + qtx[a][m])
            idx.append(allq[m])
    qkey = np.concatenate(keys)
    qidx = np.concatenate(idx)
    del keys, idx, qtx, qty, allq
    qo = np.argsort(qkey, kind="stable")
    qkey, qidx = qkey[qo], qidx[qo]
    po = np.argsort(pkey, kind="stable")
    pkey_s = pkey[po]
    tiles, starts = np.unique(pkey_s, return_index=True)
    ends = np.r_[starts[1:], pkey_s.size]
    v = np.full(px.size, -np.inf)
    done = 0
    for key, a, b in zip(tiles, starts, ends):
        sub = mon.sub(done / px.size, (done + (b - a)) / px.size)
        pi = po[a:b]
        qa, qb = np.searchsorted(qkey, key, "left"), np.searchsorted(qkey, key, "right")
        qi = qidx[qa:qb]
        v[pi] = bounded_max_slope(px[pi], py[pi], pz[pi], qx[qi], qy[qi], qz[qi],
                                   radius=r, height=height, t_lo=t_lo, t_hi=t_hi, cell=s,
                                   mon=sub, stats=stats, _tile=True)
        done += b - a
    return v


def _eval_pairs(idx, seg0, m, bx, by, bz, qxs, qys, qzs, r, h, bv, stats) -> None:
    """Canonical slopes of the pairs (idx[k], seg0[k] + 0..m[k]-1); max into bv."""
    pos = m > 0
    idx, seg0, m = idx[pos], seg0[pos], m[pos]
    if idx.size == 0:
        return
    csum = np.cumsum(m)
    lo = 0
    while lo < idx.size:
        base = csum[lo - 1] if lo else 0
        hi = int(np.searchsorted(csum, base + _PAIR_CHUNK, side="right"))
        hi = max(hi, lo + 1)
        ii, jj0, mm = idx[lo:hi], seg0[lo:hi], m[lo:hi]
        tot = int(mm.sum())
        stats.pairs_tested += tot
        segstart = np.cumsum(mm) - mm
        pi = np.repeat(ii, mm)
        pj = np.repeat(jj0 - segstart, mm) + np.arange(tot)
        slope = _canonical_slope(bx[pi], by[pi], bz[pi], qxs[pj], qys[pj], qzs[pj], r, h)
        segmax = np.maximum.reduceat(slope, segstart)
        bv[ii] = np.maximum(bv[ii], segmax)
        lo = hi


def _canonical_slope(xi, yi, zi, xj, yj, zj, r: float, h: float) -> np.ndarray:
    """Return the canonical pair slope ``((z_i - z_j) - h) / d``, ``-inf`` for non-neighbours."""
    dx = xi - xj
    dy = yi - yj
    d2 = dx * dx + dy * dy
    d = np.sqrt(d2)
    ok = (d2 > 0) & (d <= r)
    num = (zi - zj) - h
    with np.errstate(divide="ignore", invalid="ignore"):
        out = num / d
    out[~ok] = -np.inf
    return out

"""Slope-based ground filter of airborne laser points (Vosselman 2000), exact and fast.

Rule (Vosselman 2000, eq. 3 with the admissible height difference
``dh_max(d) = d * tan(theta) + h``): a point ``i`` is **non-ground** when some
neighbour ``j`` with ``0 < d_ij <= r`` (horizontal distance) has

    z_i - z_j > d_ij * tan(theta) + h

and **ground** otherwise. The difference is signed (a point is rejected only for
standing too high above a neighbour), neighbours come from the whole neighbour
set (not only from points already accepted) and there is a single pass, so the
result does not depend on the point order.

Exact arithmetic (the *canonical comparison*, shared by the fast filter, the
brute-force references and the threshold sweep so that all of them give
identical labels)::

    dx = x_i - x_j ; dy = y_i - y_j            (float64, input coordinates)
    d  = sqrt(dx*dx + dy*dy)                   (float64)
    j is a neighbour of i  <=>  dx*dx + dy*dy > 0  and  d <= r
    s_ij = ((z_i - z_j) - h) / d               (the pair's "required slope")
    S_i  = max over neighbours j of s_ij       (-inf without neighbours)
    i is non-ground        <=>  S_i > tan(theta),  tan(theta) = numpy.tan(numpy.radians(theta))

So a neighbour exactly at distance ``r`` counts; duplicates (same x and y, any
z) are not neighbours of each other; two points at equal height never reject
each other (``h >= 0``); a rise exactly equal to ``d * tan(theta) + h`` is
accepted as ground (up to the last bit of that float64 arithmetic). ``S_i`` is
the "required angle" ``atan(S_i)``: the smallest threshold at which ``i`` would
be ground, which is what makes the sweep one neighbourhood pass per radius.

Speed: no per-point Python loop. The neighbours are bucketed in a square grid
(cell ``s``), sorted by cell and height. Three bounds settle most points
without looking at pairs:

* a **cone upper bound** per cell (the lowest point of every cell lying wholly
  within ``r`` and its farthest possible distance) proves "non-ground" for
  points standing far above their surroundings;
* a **cone lower bound** per cell (distance-weighted minimum filter of the
  minimum grid over the cells two or more cells away) proves that no far
  neighbour can reject a point;
* per point and per candidate cell, the exact point-to-cell distance bounds
  the slope any point of that cell can produce, and only the *lowest points*
  of that cell — a prefix of its height-sorted run found by binary search —
  can exceed the threshold.

Only these candidate pairs are evaluated with the canonical comparison,
vectorised in chunks of bounded memory. Every bound carries a safety margin
far larger than float64 rounding, so pruning never changes a label: the result
is identical to the brute force (tested property).

References
----------
Vosselman, G. (2000). Slope based filtering of laser altimetry data.
International Archives of Photogrammetry and Remote Sensing XXXIII-B3,
935-942.

Sithole, G. (2001). Filtering of laser altimetry data using a slope adaptive
filter. IAPRS XXXIV-3/W4, 203-210 (motivation of the terrain-adaptive mode).

Sithole, G. & Vosselman, G. (2004). Experimental comparison of filter
algorithms for bare-Earth extraction from airborne laser scanning point
clouds. ISPRS J. Photogramm. Remote Sens. 59(1-2), 85-101 (error measures).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Sequence

import numpy as np

from ..coords import as_xyz
from ..progress import Monitor
from ..reporting import KeyValues, Paragraph, T, Table
from .accuracy import assess
from .pipeline import FilterOutcome, GroundFilter

__all__ = [
    "DEFAULT_RADIUS", "DEFAULT_SLOPE", "DEFAULT_HEIGHT_TOLERANCE", "PAPER_SETTING",
    "SLOPE_METRICS", "MODES",
    "SlopeFilterResult", "SweepRow", "SweepResult",
    "allowed_rise", "max_slope", "slope_filter", "slope_filter_reference",
    "max_slope_reference", "threshold_sweep", "terrain_trend", "SlopeOptions",
    "SlopeFilter",
]

#: Default neighbourhood radius (m). Vosselman's rule removes an object only
#: within ``r`` of its edge, so ``r`` must exceed half the width of the buildings
#: to remove: 10 m handles houses and medium blocks (ISPRS best-of-sweep radii
#: were 8-20 m; the forest study's 3 m suits forest without buildings).
DEFAULT_RADIUS = 10.0
#: Default slope threshold (degrees): the best single value over the four ISPRS
#: samples at r = 10 m (mean total error); the forest study chose 44 at r = 3 m.
DEFAULT_SLOPE = 40.0
#: Default extra height tolerance (m): absorbs ranging noise between very close
#: points (at 8 pts/m2 and 5 cm noise it cuts the synthetic total error from 5.8 %
#: to 2.2 %; ISPRS totals drop too). Vosselman's rule as published uses 0.
DEFAULT_HEIGHT_TOLERANCE = 0.2
#: The forest study's setting (spec): r = 3 m, theta = 44 degrees, no tolerance.
PAPER_SETTING = dict(radius=3.0, slope=44.0, height_tolerance=0.0)
#: Metrics the sweep can rank by, and whether higher is better.
SLOPE_METRICS = {"total": False, "kappa": True, "type1": False, "type2": False}

_EPS = np.finfo(np.float64).eps
_PAIR_CHUNK = 3_000_000        # candidate pairs evaluated per vectorised block
_POINT_CHUNK = 1_000_000       # points classified per block
_MAX_CELLS = 30_000_000        # dense grid size limit (cells), ~0.5 GB
_MIN_CELL_FRACTION = 1.0 / 16  # smallest grid cell, as a fraction of r


# ============================================================================ helpers
def _xyz(x, y, z):
    return as_xyz(x, y, z, empty_error=(
        "The point cloud is empty: there is nothing to filter. Check the input file or "
        "the return/noise selection."))



def _check_radius(radius) -> float:
    try:
        r = float(radius)
    except (TypeError, ValueError):
        raise ValueError(f"radius must be a number of metres, got {radius!r}.") from None
    if not math.isfinite(r) or r <= 0:
        raise ValueError(f"radius must be a positive number of metres (> 0), got {radius}; "
                         f"use e.g. {DEFAULT_RADIUS} m for airborne LiDAR.")
    return r


def _check_slope(slope) -> float:
    try:
        s = float(slope)
    except (TypeError, ValueError):
        raise ValueError(f"slope must be an angle in degrees, got {slope!r}.") from None
    if not math.isfinite(s) or not 0.0 < s < 90.0:
        raise ValueError(f"slope threshold must be an angle strictly between 0 and 90 "
                         f"degrees, got {slope}; typical values are 30-70 (e.g. "
                         f"{DEFAULT_SLOPE}).")
    return s


def _check_height(h) -> float:
    try:
        v = float(h)
    except (TypeError, ValueError):
        raise ValueError(f"height_tolerance must be a number of metres, got {h!r}.") from None
    if not math.isfinite(v) or v < 0:
        raise ValueError(f"height_tolerance must be zero or a positive number of metres, "
                         f"got {h}.")
    return v


def _mask(mask, n: int, name: str) -> np.ndarray:
    if mask is None:
        return np.ones(n, dtype=bool)
    m = np.asarray(mask, dtype=bool).ravel()
    if m.size != n:
        raise ValueError(f"{name} has {m.size} entries but the cloud has {n} points; give "
                         "one flag per point.")
    return m


def _take(x, y, z, mask):
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


def _tan(slope: float) -> float:
    return float(np.tan(np.radians(np.float64(slope))))


# ============================================================================ the kernel
@dataclass
class _Stats:
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
    """The padded square grid of one :func:`_bounded_max_slope` call, with margins."""

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
                  r: float, h: float, t_lo: float, stats: _Stats) -> None:
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
                    stats: _Stats) -> None:
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


def _bounded_max_slope(px, py, pz, qx, qy, qz, *, radius: float, height: float,
                       t_lo: float, t_hi: float, cell: Optional[float] = None,
                       mon: Monitor, stats: _Stats, _tile: bool = False) -> np.ndarray:
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
    """Run :func:`_bounded_max_slope` tile by tile (Vosselman 2000 rule, exact).

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
        v[pi] = _bounded_max_slope(px[pi], py[pi], pz[pi], qx[qi], qy[qi], qz[qi],
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


# ============================================================================ public API
@dataclass
class SlopeFilterResult:
    """Labels and diagnostics of :func:`slope_filter`.

    Attributes
    ----------
    ground : ndarray of bool
        True for points classified ground. False for classified non-ground
        points *and* for points that were not classified (``classify`` False).
    classified : ndarray of bool
        The points that were classified (the ``classify`` mask).
    max_slope_deg : ndarray of float
        ``atan(S_i)`` in degrees where it was computed exactly, ``+90`` for points
        proven non-ground by a bound, ``nan`` for points not classified and
        ``-90`` for points without neighbours.  Exact where it decides the label:
        comparing it with other thresholds is only valid in exact mode's
        ``[t_lo, t_hi]`` (use :func:`threshold_sweep`).
    radius, slope, height_tolerance : float
    mode : str
    stats : dict
        Work counters (points settled by bounds, pairs tested, grid cell).
    trend : ndarray or None
        The terrain trend subtracted in ``mode="adaptive"``.
    """

    ground: np.ndarray
    classified: np.ndarray
    max_slope_deg: np.ndarray
    radius: float
    slope: float
    height_tolerance: float
    mode: str
    stats: Dict[str, float] = field(default_factory=dict)
    trend: Optional[np.ndarray] = None

    @property
    def n_ground(self) -> int:
        """Points classified as ground."""
        return int(np.count_nonzero(self.ground))

    @property
    def n_nonground(self) -> int:
        """Classified points that are not ground."""
        return int(np.count_nonzero(self.classified & ~self.ground))


def max_slope(x, y, z, *, radius: float = DEFAULT_RADIUS,
              height_tolerance: float = DEFAULT_HEIGHT_TOLERANCE,
              classify=None, neighbours=None, slope_range: Sequence[float] = (1e-9, 89.999),
              cell: Optional[float] = None, progress=None, cancel=None) -> np.ndarray:
    """Per-point maximum required slope ``S_i`` (as ``tan``), exact inside a range.

    Parameters
    ----------
    x, y, z : array_like
        Coordinates (metres, projected CRS).
    radius, height_tolerance : float
        As in :func:`slope_filter`.
    classify, neighbours : array_like of bool, optional
        Points to evaluate / points serving as neighbours (default all).
    slope_range : (float, float)
        Degrees ``(lo, hi)``. The result ``v`` is exact where ``tan(lo) < S <=
        tan(hi)``, and for every threshold ``t`` in that range ``v > tan(t)``
        exactly when ``S > tan(t)``. Narrow ranges are much faster.

    Returns
    -------
    ndarray of float
        ``v`` per point (``nan`` for points not evaluated).
    """
    x, y, z = _xyz(x, y, z)
    r = _check_radius(radius)
    h = _check_height(height_tolerance)
    lo, hi = sorted(float(a) for a in slope_range)
    _check_slope(lo)
    _check_slope(hi)
    cm = _mask(classify, x.size, "classify")
    nm = _mask(neighbours, x.size, "neighbours")
    stats = _Stats()
    out = np.full(x.size, np.nan)
    out[cm] = _bounded_max_slope(x[cm], y[cm], z[cm], x[nm], y[nm], z[nm], radius=r,
                                 height=h, t_lo=_tan(lo), t_hi=_tan(hi), cell=cell,
                                 mon=Monitor(progress, cancel), stats=stats)
    return out


def terrain_trend(x, y, z, *, cell: float = 10.0, window: float = 60.0,
                  neighbours=None, origin=None, progress=None, cancel=None) -> np.ndarray:
    """Smooth low terrain trend surface at every point (for ``mode="adaptive"``).

    The lowest point per ``cell`` (a minimum grid), a morphological opening with
    a ``window``-wide square (removes buildings and canopy narrower than the
    window), empty cells filled from the nearest filled cell, a mean filter of
    the same width, then bilinear interpolation at the points. Subtracting it
    leaves the terrain's steep natural slopes out of the height differences the
    slope rule tests (the "slope normalisation" of Sithole 2001 and of
    WhiteboxTools' LidarGroundPointFilter, here as an explicit surface).

    ``origin`` (x, y) anchors the minimum grid on a global cell lattice (cells at
    ``origin + k * cell``): tiles of a catalog then share cells with a run on the
    merged cloud, and the trend equals the merged one farther than about
    ``1.5 * window + cell`` from a tile's edge. Default: the points' lower-left corner.
    """
    from scipy import ndimage

    x, y, z = _xyz(x, y, z)
    nm = _mask(neighbours, x.size, "neighbours")
    if not nm.any():
        return np.zeros(x.size)
    mon = Monitor(progress, cancel)
    xn, yn, zn = x[nm], y[nm], z[nm]
    x0, y0 = float(xn.min()), float(yn.min())
    if origin is not None:
        x0 = origin[0] + np.floor((x0 - origin[0]) / cell) * cell
        y0 = origin[1] + np.floor((y0 - origin[1]) / cell) * cell
    nx = int((xn.max() - x0) // cell) + 1
    ny = int((yn.max() - y0) // cell) + 1
    ix = np.clip(((xn - x0) // cell).astype(np.int64), 0, nx - 1)
    iy = np.clip(((yn - y0) // cell).astype(np.int64), 0, ny - 1)
    grid = np.full(ny * nx, np.inf)
    np.minimum.at(grid, iy * nx + ix, zn)
    grid = grid.reshape(ny, nx)
    empty = ~np.isfinite(grid)
    if empty.all():
        return np.zeros(x.size)
    if empty.any():
        _, (iiy, iix) = ndimage.distance_transform_edt(empty, return_indices=True)
        grid = grid[iiy, iix]
    mon.step(0.4)
    w = max(1, int(round(window / cell)) | 1)
    # Point-reflection ("odd") padding continues ramps linearly, so neither the
    # opening nor the mean filter flattens a slope near the tile edges.
    pad = w
    padded = np.pad(grid, pad, mode="reflect", reflect_type="odd") if min(grid.shape) > 1 \
        else np.pad(grid, pad, mode="edge")
    opened = ndimage.grey_opening(padded, size=(w, w), mode="nearest")
    smooth = ndimage.uniform_filter(opened, size=w, mode="nearest")[pad:-pad, pad:-pad]
    mon.step(0.8)
    # bilinear between cell centres, linear extrapolation beyond the outer centres
    fx = (x - x0) / cell - 0.5
    fy = (y - y0) / cell - 0.5
    jx = np.clip(np.floor(fx).astype(np.int64), 0, max(nx - 2, 0))
    jy = np.clip(np.floor(fy).astype(np.int64), 0, max(ny - 2, 0))
    ax = fx - jx if nx > 1 else np.zeros_like(fx)
    ay = fy - jy if ny > 1 else np.zeros_like(fy)
    jx1 = np.minimum(jx + 1, nx - 1)
    jy1 = np.minimum(jy + 1, ny - 1)
    out = ((1 - ax) * (1 - ay) * smooth[jy, jx] + ax * (1 - ay) * smooth[jy, jx1]
           + (1 - ax) * ay * smooth[jy1, jx] + ax * ay * smooth[jy1, jx1])
    mon.update(1.0)
    return out


MODES = ("exact", "adaptive")


def slope_filter(x, y, z, *, radius: float = DEFAULT_RADIUS, slope: float = DEFAULT_SLOPE,
                 height_tolerance: float = DEFAULT_HEIGHT_TOLERANCE, classify=None, neighbours=None,
                 mode: str = "exact", trend_cell: float = 10.0, trend_window: float = 60.0,
                 trend_origin=None, cell: Optional[float] = None, progress=None,
                 cancel=None) -> SlopeFilterResult:
    """Classify points as ground / non-ground with Vosselman's slope rule.

    Parameters
    ----------
    x, y, z : array_like, shape (n,)
        Coordinates in a projected CRS (metres), finite.
    radius : float, default 10
        ``r``, metres (> 0): neighbours within this horizontal distance
        (inclusive) are compared. Larger radii reject larger objects (a roof is
        removed only within ``r`` of its edge) but cost more. The forest study
        used 3 m (:data:`PAPER_SETTING`).
    slope : float, default 40
        ``theta``, degrees in (0, 90): the admissible terrain slope. A point may
        rise ``d * tan(theta)`` above a neighbour at distance ``d`` (2.90 m at
        3 m for 44 degrees).
    height_tolerance : float, default 0.2
        ``h``, metres (>= 0): extra admissible rise for every pair (absorbs
        ranging noise: ``dh_max = d * tan(theta) + h``). 0 is Vosselman's rule
        as published.
    classify : array_like of bool, optional
        Points to classify (default all). The others get ``ground = False``.
    neighbours : array_like of bool, optional
        Points that may reject others (default all). "Last returns only" means
        ``classify = neighbours = last returns``: earlier returns of a
        multi-return pulse are not ground by construction and are also not
        allowed to reject anything. Excluding low outliers (noise) means
        removing them from both masks.
    mode : {"exact", "adaptive"}
        ``"exact"``: Vosselman's rule as published. ``"adaptive"`` (this
        toolbox's extension, not Vosselman's): the rule is applied to heights
        above a smooth low terrain trend (:func:`terrain_trend`), so long steep
        natural slopes do not count against the threshold while abrupt objects
        still do; labels are then exact with respect to those normalised heights.
    trend_cell, trend_window : float
        Metres; the trend's minimum-grid cell and opening/smoothing window
        (adaptive mode only). The window should exceed the largest building.
    trend_origin : (float, float), optional
        Global anchor of the trend's cell lattice (see :func:`terrain_trend`);
        tile catalogs pass their origin so tiles equal the merged cloud.
    cell : float, optional
        Internal grid cell (metres); affects speed only, never the labels.
    progress, cancel : callable, optional
        See :class:`~.progress.Monitor`.

    Returns
    -------
    SlopeFilterResult

    Raises
    ------
    ValueError
        Empty cloud, mismatched lengths, non-finite coordinates, ``radius <= 0``,
        ``slope`` outside (0, 90), negative ``height_tolerance``, unknown mode.

    Examples
    --------
    A 2 m step is rejected at 30 degrees within 3 m (allowed rise 1.73 m at 3 m):

    >>> import numpy as np
    >>> x = np.array([0.0, 3.0]); y = np.zeros(2); z = np.array([0.0, 2.0])
    >>> slope_filter(x, y, z, radius=3.0, slope=30.0, height_tolerance=0).ground.tolist()
    [True, False]
    >>> slope_filter(x, y, z, radius=3.0, slope=40.0, height_tolerance=0).ground.tolist()
    [True, True]
    """
    x, y, z = _xyz(x, y, z)
    r = _check_radius(radius)
    theta = _check_slope(slope)
    h = _check_height(height_tolerance)
    if mode not in MODES:
        raise ValueError(f"mode must be one of {', '.join(MODES)}, got {mode!r}.")
    cm = _mask(classify, x.size, "classify")
    nm = _mask(neighbours, x.size, "neighbours")
    mon = Monitor(progress, cancel)
    trend = None
    zz = z
    if mode == "adaptive":
        trend = terrain_trend(x, y, z, cell=trend_cell, window=trend_window, neighbours=nm,
                              origin=trend_origin, progress=None, cancel=cancel)
        zz = z - trend
        mon = mon.sub(0.1, 1.0)
    t = _tan(theta)
    stats = _Stats()
    v = np.full(x.size, np.nan)
    if cm.any():
        v[cm] = _bounded_max_slope(*_take(x, y, zz, cm), *_take(x, y, zz, nm), radius=r,
                                   height=h, t_lo=t, t_hi=t, cell=cell, mon=mon,
                                   stats=stats)
    ground = cm & ~(v > t)
    mon.update(1.0)
    with np.errstate(invalid="ignore"):
        deg = np.degrees(np.arctan(v))
    return SlopeFilterResult(ground=ground, classified=cm, max_slope_deg=deg, radius=r,
                             slope=theta, height_tolerance=h, mode=mode,
                             stats=stats.as_dict(), trend=trend)


# ============================================================================ references
def max_slope_reference(x, y, z, *, radius: float, height_tolerance: float = 0.0,
                        classify=None, neighbours=None, method: str = "kdtree",
                        chunk: int = 20000, progress=None, cancel=None) -> np.ndarray:
    """Brute-force ``S_i`` over *all* neighbour pairs (the speed and truth reference).

    ``method="dense"`` forms the full distance matrix (tiny clouds only);
    ``method="kdtree"`` gathers every pair within ``r`` with
    :meth:`scipy.spatial.cKDTree.sparse_distance_matrix` (search radius padded
    by 1e-9 relative, then the canonical comparison decides), in chunks.
    Returns ``nan`` for points not classified.
    """
    from scipy.spatial import cKDTree

    x, y, z = _xyz(x, y, z)
    r = _check_radius(radius)
    h = _check_height(height_tolerance)
    cm = _mask(classify, x.size, "classify")
    nm = _mask(neighbours, x.size, "neighbours")
    mon = Monitor(progress, cancel)
    pidx = np.flatnonzero(cm)
    qidx = np.flatnonzero(nm)
    out = np.full(x.size, np.nan)
    res = np.full(pidx.size, -np.inf)
    if qidx.size and pidx.size:
        if method == "dense":
            s = _canonical_slope(x[pidx][:, None], y[pidx][:, None], z[pidx][:, None],
                                 x[qidx][None, :], y[qidx][None, :], z[qidx][None, :], r, h)
            res = s.max(axis=1)
        elif method == "kdtree":
            tq = cKDTree(np.column_stack((x[qidx], y[qidx])))
            rr = r * (1 + 1e-9) + 1e-12
            for b in range(0, pidx.size, chunk):
                mon.step(b / pidx.size)
                p = pidx[b:b + chunk]
                tp = cKDTree(np.column_stack((x[p], y[p])))
                sm = tp.sparse_distance_matrix(tq, rr, output_type="ndarray")
                i, j = sm["i"], qidx[sm["j"]]
                s = _canonical_slope(x[p][i], y[p][i], z[p][i], x[j], y[j], z[j], r, h)
                part = np.full(p.size, -np.inf)
                np.maximum.at(part, i, s)
                res[b:b + chunk] = part
        else:
            raise ValueError(f"method must be 'dense' or 'kdtree', got {method!r}.")
    out[pidx] = res
    mon.update(1.0)
    return out


def slope_filter_reference(x, y, z, *, radius: float = DEFAULT_RADIUS,
                           slope: float = DEFAULT_SLOPE,
                           height_tolerance: float = DEFAULT_HEIGHT_TOLERANCE,
                           classify=None, neighbours=None, method: str = "kdtree",
                           progress=None, cancel=None) -> np.ndarray:
    """Brute-force ground labels (bool) with exactly the canonical comparison."""
    _check_slope(slope)
    cm = _mask(classify, np.size(x), "classify")
    s = max_slope_reference(x, y, z, radius=radius, height_tolerance=height_tolerance,
                            classify=cm, neighbours=neighbours, method=method,
                            progress=progress, cancel=cancel)
    return cm & ~(s > _tan(slope))


# ============================================================================ sweep
@dataclass
class SweepRow:
    """One setting of the sweep and its accuracy against the reference."""

    radius: float
    slope: float
    height_tolerance: float
    allowed_rise: float
    n_ground: int
    a: int
    b: int
    c: int
    d: int
    type1: float
    type2: float
    total: float
    kappa: float

    def as_dict(self) -> dict:
        """Return the row as a dict."""
        return dict(self.__dict__)


@dataclass
class SweepResult:
    """All rows of a sweep and the best one by ``metric``."""

    rows: List[SweepRow]
    metric: str
    best: SweepRow
    n_points: int
    n_reference_ground: int
    mode: str
    best_ground: Optional[np.ndarray] = None

    HEADERS = ("radius_m", "slope_deg", "height_tolerance_m", "allowed_rise_at_r_m",
               "n_ground", "a", "b", "c", "d", "type1_pct", "type2_pct", "total_pct",
               "kappa_pct")

    def table(self) -> List[tuple]:
        """Return one tuple per setting, in the order of :attr:`HEADERS`."""
        return [(r.radius, r.slope, r.height_tolerance, r.allowed_rise, r.n_ground, r.a, r.b,
                 r.c, r.d, r.type1, r.type2, r.total, r.kappa) for r in self.rows]

    def to_csv(self) -> str:
        """CSV text (comma separated, '.' decimals, header row)."""
        lines = [",".join(self.HEADERS)]
        for row in self.table():
            cells = []
            for v in row:
                if isinstance(v, (int, np.integer)):
                    cells.append(str(int(v)))
                else:
                    cells.append("" if not math.isfinite(v) else f"{v:.6g}")
            lines.append(",".join(cells))
        return "\n".join(lines) + "\n"


def _metric_key(row: SweepRow, metric: str) -> float:
    val = getattr(row, metric)
    if not math.isfinite(val):
        return math.inf
    return -val if SLOPE_METRICS[metric] else val


def threshold_sweep(x, y, z, reference_ground, *, slopes: Sequence[float] = (
        40, 44, 48, 52, 56, 60), radii: Sequence[float] = (DEFAULT_RADIUS,),
        height_tolerance=DEFAULT_HEIGHT_TOLERANCE, classify=None, neighbours=None,
        mode: str = "exact", metric: str = "total", trend_cell: float = 10.0,
        trend_window: float = 60.0, progress=None, cancel=None) -> SweepResult:
    """Filter accuracy for every (radius, slope) setting, one neighbourhood pass per radius.

    For each radius the exact per-point required slope ``S_i`` is computed once
    over the range of the thresholds (:func:`max_slope`); every threshold is
    then a single comparison ``S_i > tan(theta)`` giving labels identical to
    :func:`slope_filter` with that setting. Points outside ``classify`` count as
    non-ground. Errors follow Sithole & Vosselman (2004): Type I (ground
    rejected), Type II (objects accepted: the forest study's "error" column),
    total and Cohen's kappa, all in percent.

    Parameters
    ----------
    x, y, z : array_like
        Coordinates.
    reference_ground : array_like of bool
        Reference labels (True = ground), one per point.
    slopes : sequence of float
        Thresholds in degrees, each in (0, 90).
    radii : sequence of float
        Radii in metres, each > 0.
    height_tolerance : float or sequence of float
        Metres (>= 0); a sequence sweeps it too (one pass per radius and
        tolerance).
    metric : {"total", "kappa", "type1", "type2"}
        Criterion for the best setting: lowest error, or highest kappa. Ties go
        to the first setting in radius, slope order.
    classify, neighbours, mode, trend_cell, trend_window
        As in :func:`slope_filter`.

    Returns
    -------
    SweepResult
    """
    x, y, z = _xyz(x, y, z)
    ref = np.asarray(reference_ground, dtype=bool).ravel()
    if ref.size != x.size:
        raise ValueError(f"The reference has {ref.size} labels but the cloud has {x.size} "
                         "points; the reference must label the same points in the same "
                         "order.")
    if metric not in SLOPE_METRICS:
        raise ValueError(f"metric must be one of {', '.join(SLOPE_METRICS)}, got {metric!r}.")
    if mode not in MODES:
        raise ValueError(f"mode must be one of {', '.join(MODES)}, got {mode!r}.")
    slopes = [_check_slope(s) for s in np.atleast_1d(np.asarray(slopes, dtype=float))]
    radii = [_check_radius(r) for r in np.atleast_1d(np.asarray(radii, dtype=float))]
    if not slopes or not radii:
        raise ValueError("Give at least one slope threshold and one radius to sweep.")
    hs = [_check_height(v) for v in np.atleast_1d(np.asarray(height_tolerance, dtype=float))]
    if not hs:
        raise ValueError("Give at least one height tolerance (e.g. 0).")
    cm = _mask(classify, x.size, "classify")
    nm = _mask(neighbours, x.size, "neighbours")
    mon = Monitor(progress, cancel)
    zz = z
    if mode == "adaptive":
        zz = z - terrain_trend(x, y, z, cell=trend_cell, window=trend_window,
                               neighbours=nm, cancel=cancel)
    lo, hi = min(slopes), max(slopes)
    rows: List[SweepRow] = []
    passes = [(r, h) for r in radii for h in hs]
    px, py, pz = _take(x, y, zz, cm)
    qx, qy, qz = _take(x, y, zz, nm)
    best_key, best_ground = None, None
    for k, (r, h) in enumerate(passes):
        v = np.full(x.size, np.nan)
        if cm.any():
            v[cm] = _bounded_max_slope(px, py, pz, qx, qy, qz, radius=r, height=h,
                                       t_lo=_tan(lo), t_hi=_tan(hi), cell=None,
                                       mon=mon.sub(k / len(passes), (k + 1) / len(passes)),
                                       stats=_Stats())
        for s in slopes:
            pred = cm & ~(v > _tan(s))
            acc = assess(pred, ref)
            row = SweepRow(radius=r, slope=s, height_tolerance=h,
                           allowed_rise=float(allowed_rise(r, s)),
                           n_ground=int(np.count_nonzero(pred)), a=acc.a, b=acc.b,
                           c=acc.c, d=acc.d, type1=acc.type1, type2=acc.type2,
                           total=acc.total, kappa=acc.kappa)
            rows.append(row)
            key = _metric_key(row, metric)
            if best_key is None or key < best_key:
                best_key, best_ground = key, pred
    best = min(rows, key=lambda row: _metric_key(row, metric))
    mon.update(1.0)
    return SweepResult(rows=rows, metric=metric, best=best, n_points=x.size,
                       n_reference_ground=int(np.count_nonzero(ref)), mode=mode,
                       best_ground=best_ground)


# ============================================================================ pipeline object
@dataclass
class SlopeOptions:
    """Options of :class:`SlopeFilter` (see :func:`slope_filter` for each)."""

    radius: float = DEFAULT_RADIUS
    slope: float = DEFAULT_SLOPE
    height_tolerance: float = DEFAULT_HEIGHT_TOLERANCE
    mode: str = "exact"
    trend_cell: float = 10.0
    trend_window: float = 60.0

    def validate(self) -> SlopeOptions:
        """Raise ``ValueError`` naming the bad option; returns self."""
        _check_radius(self.radius)
        _check_slope(self.slope)
        _check_height(self.height_tolerance)
        if self.mode not in MODES:
            raise ValueError(f"mode must be one of {', '.join(MODES)}, got {self.mode!r}.")
        if self.mode == "adaptive" and not (self.trend_cell > 0 and self.trend_window > 0):
            raise ValueError("TREND_CELL and TREND_WINDOW must be > 0 metres in adaptive "
                             "mode (e.g. 10 and 60).")
        return self


class SlopeFilter(GroundFilter):
    """Vosselman (2000) slope-based filter as a pipeline algorithm object."""

    name = "slope"
    title = "Ground filter (slope-based)"
    citation = T("Reference: {ref}", ref="Vosselman, G. (2000). Slope based filtering of "
                 "laser altimetry data. IAPRS XXXIII-B3, 935–942.")

    def __init__(self, options: Optional[SlopeOptions] = None):
        super().__init__((options or SlopeOptions()).validate())

    def classify(self, x, y, z, *, return_number=None, number_of_returns=None,
                 monitor: Optional[Monitor] = None) -> FilterOutcome:
        """Run :func:`slope_filter` on the selected points (every one a neighbour)."""
        mon = monitor or Monitor()
        o = self.options
        res = slope_filter(x, y, z, radius=o.radius, slope=o.slope,
                           height_tolerance=o.height_tolerance, mode=o.mode,
                           trend_cell=o.trend_cell, trend_window=o.trend_window,
                           progress=mon.update, cancel=mon.cancelled)
        cls = np.where(res.ground, 2, 1).astype(np.uint8)
        return FilterOutcome(cls, details=res, stats=dict(res.stats))

    def settings(self) -> List[tuple]:
        """Report rows: r, θ, h, mode (and the trend of the adaptive mode)."""
        o = self.options
        rows = [("Radius r (m)", o.radius), ("Slope threshold θ (degrees)", o.slope),
                ("Height tolerance h (m)", o.height_tolerance),
                ("Mode", T("Exact (Vosselman 2000)") if o.mode == "exact"
                 else T("Terrain-adaptive (toolbox extension)"))]
        if o.mode == "adaptive":
            rows += [("Adaptive mode: trend cell (m)", o.trend_cell),
                     ("Adaptive mode: trend window, > largest building (m)", o.trend_window)]
        return rows

    def report_sections(self, run, report, tr) -> None:
        """Append the method, allowed rise table and work counters."""
        o = self.options
        sec = report.section("Method")
        sec.add(Paragraph(T(
            "Vosselman (2000) slope-based filter: a point is non-ground when a neighbour at "
            "horizontal distance 0 < d ≤ r = {r} m lies more than d·tan θ + h below it "
            "(θ = {theta}°, h = {h} m); otherwise ground. Single pass, exact (identical to "
            "a brute-force check of every pair).", r=o.radius, theta=o.slope,
            h=o.height_tolerance)))
        if o.mode == "adaptive":
            sec.add(Paragraph(T(
                "Adaptive mode (this toolbox's extension, not Vosselman's): the rule is "
                "applied to heights above a smooth low terrain trend, so long natural slopes "
                "steeper than θ are not rejected while abrupt objects still are."), "note"))
        ds = [o.radius / 4, o.radius / 2, 3 * o.radius / 4, o.radius]
        sec.add(Table(["Distance d (m)", "Allowed rise d·tan θ + h (m)"],
                      [(d, float(allowed_rise(d, o.slope)) + o.height_tolerance)
                       for d in ds], caption="Allowed rise above a neighbour", digits=2))
        st = run.outcome.stats
        pts = st.get("points", 0) or 0
        sec.add(KeyValues([
            ("Points settled by the raster bounds (%)",
             100.0 * st.get("settled_by_bound", 0) / pts if pts else None),
            ("Exact pair tests", int(st.get("pairs_tested", 0))),
            ("Grid cell (m)", st.get("cell_size"))], caption="Work", digits=2))

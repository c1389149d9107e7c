"""Hole filling that continues the terrain's slope (numpy/scipy only, private).

A linear TIN or a harmonic (Laplace) fill over a hole never rises above the
hole's border: where an opening wrongly removed the crest of a ridge, an
embankment or a terrace edge, such a fill cuts the crest, and the ground points
there fall below the tolerance band (Type I errors).  Here every hole cell is
the inverse-distance weighted mean of the tangent planes of its nearest border
cells, a Shepard interpolation of first-order (gradient) data that continues the
slopes on both sides of a crest towards each other (Shepard 1968; Franke &
Nielson 1980).  The border gradients are least-squares planes over the valid
cells of a small window, and the slope term is damped beyond ``reach`` metres so
that a large hole (a building) is not extrapolated far.

The continuity growing of the recommended filter (:func:`grow_ground`) is built on
the same window planes (:func:`plane_fit_where`).

References
----------
Shepard, D. (1968). A two-dimensional interpolation function for irregularly-spaced
data. Proc. 23rd ACM National Conference, 517-524.

Franke, R. & Nielson, G. (1980). Smooth interpolation of large sets of scattered
data. Int. J. Numer. Methods Eng. 15(11), 1691-1704.
"""
from __future__ import annotations

import numpy as np
from scipy.spatial import cKDTree

from ..system import release_free_memory
from . import _lattice_knn as K  # noqa: N812
from . import _raster as R  # noqa: N812
from ._openings import erode3
from ._planes import (  # noqa: F401
    _plane_fit,
    gradient_at,
    gradient_of,
    plane_fit,
    plane_fit_where,
    plane_gradient,
)

__all__ = ["grow_ground", "plane_fit", "plane_fit_where", "plane_gradient", "tangent_fill"]

#: Hole cells processed per batch (bounds the per-batch k-neighbour arrays' memory).
BATCH = 16_384
#: Up to this many hole cells, their neighbours are found first and the border gradients
#: computed only at the border cells they read; those neighbour lists are then held
#: through the batches (deep holes' KD-tree rows: 3 float64 (m, k) arrays).
FEW_HOLES = 65_536


def tangent_fill(z, valid, cell: float, *, radius: int = 3, neighbours: int = 12,
                 reach: float = 10.0, need=None, cache=None, overwrite=False, trim=True):
    """Fill invalid cells with the weighted tangent planes of the hole borders.

    Parameters
    ----------
    z : ndarray
        Raster (NaN or anything where invalid).
    valid : ndarray of bool
        Cells to keep.
    cell : float
        Cell size (m).
    radius : int
        Half-size of the plane-fit window of the border gradients (cells).
    neighbours : int
        Border cells per hole cell (the nearest ones).
    reach : float
        Distance (m) beyond which a tangent plane's slope term stops growing.
    need : ndarray of bool, optional
        Cells that will be read; invalid cells outside it are left NaN (at low
        density most cells are empty and only those near a point are ever read).
    cache : dict, optional
        Shared by successive fills of one raster (the refine passes): a hole cell
        keeps the previous call's value when no cell changed (valid or height) within
        its ``neighbours``-th border distance plus the plane window
        (:func:`_keeper`) - the value a new computation would give, bit for bit.
    overwrite : bool
        Fill ``z`` itself (float64 or float32: the values are computed in float64
        and stored in ``z``'s type) and return it, sparing a raster: only its invalid
        cells are written, after the valid ones were read.
    trim : bool
        Hand freed pages back before the batches (sparse: the peak; dense: refaulted).

    Returns
    -------
    ndarray
        The filled raster; with fewer than 3 border cells, the linear TIN fill
        (:func:`._raster.fill_tin`).
    """
    prev = cache.copy() if cache else None
    if cache is not None:
        cache.clear()
    if valid.all():
        return z.copy()
    # valid cells with an invalid one among their 8 neighbours (a 3 x 3 minimum: the same
    # cells as dilating the invalid ones, in two separable passes)
    ring = _ring(valid)
    rr, cc = _nonzero(ring)                          # int32 where it fits, same order
    if rr.size < 3:
        return R.fill_tin(z, valid)
    k = min(int(neighbours), rr.size)
    if overwrite:
        out = z
        out[~valid] = np.nan
    else:
        out = np.where(valid, z, np.nan)
    key = (z.shape, k, int(radius), float(cell), float(reach))
    d2k = np.full(z.shape, _NONE, np.uint8) if cache is not None else None
    holes, hr, hc = _holes(prev, key, z, valid, need, out, d2k, radius)
    prev = None                                      # the previous fill's rasters: no longer read
    trees, near = [], None      # the KD-tree, built when a hole cell is deeper than the scan
    if hr is None or hr.size:
        bz = z[rr, cc]
        few = hr is not None and hr.size <= FEW_HOLES  # few holes: gradients where read
        scan = K.Scan(ring)                          # lattices of some rows at a time
        if few:
            near = scan.near(hr, hc, k, trees)
            used = np.zeros(rr.size, bool)
            used[near.j] = True
            used = np.flatnonzero(used)
            bgx, bgy = np.zeros(rr.size), np.zeros(rr.size)
            grad = gradient_of if used.size * (2 * radius + 1) ** 2 < z.size // 2 else gradient_at
            bgx[used], bgy[used] = grad(z, valid, radius, cell, rr[used], cc[used])
        else:
            bgx, bgy = gradient_at(z, valid, radius, cell, rr, cc)
    del rr, cc, ring
    trim and release_free_memory()  # the temporaries above: their pages back before the batches
    table = _weights(*K.OFFSETS_F, cell, reach)      # what depends on a scan offset only
    for s, (r, c) in _batches(holes, hr, hc):
        nb = _rows(near, s, s + r.size) if near is not None else scan.near(r, c, k, trees)
        ndc, dr, damp, w = (t[nb.o] for t in table[:4])
        if nb.far.size:                              # rows the KD-tree found
            for a, b in zip((ndc, dr, damp, w), _weights(nb.dc, nb.dr, nb.d2, cell, reach)):
                a[nb.far] = b
        if d2k is not None:
            last = table[4][nb.o[:, -1]]             # whole cells, rounded up
            last[nb.far] = np.ceil(np.sqrt(nb.d2[:, -1]))
            d2k[r, c] = np.where(last < _NONE, last, _NONE)     # too far: not kept
        # tangent plane of border cell j at the hole cell: offsets are integers, so the
        # value does not depend on where the raster starts
        j = nb.j
        plane = bgx[j] * ndc
        plane -= bgy[j] * dr
        plane *= damp
        plane += bz[j]
        plane *= w
        out[r, c] = plane.sum(axis=1) / w.sum(axis=1)
    if cache is not None:
        cache.update(key=key, valid=valid.copy(), out=out, d2k=d2k)
    return out


def _weights(dc, dr, d2, cell: float, reach: float):
    """Terms of a border cell's tangent plane that depend on its offset ``(dc, dr)`` only.

    Returns ``(-dc, dr, damp, w, last)``: the slope damping (``min(1, reach / d)``
    times the cell size), the Shepard weight ``1 / d²`` (``d`` in metres, at least
    1e-9) and the distance in whole cells rounded up, each computed elementwise as
    :func:`tangent_fill` always has (a table of the scan's offsets gives the same bits).
    """
    d = np.sqrt(d2) * cell
    np.maximum(d, 1e-9, out=d)
    damp = np.minimum(1.0, reach / d)
    damp *= cell
    np.multiply(d, d, out=d)
    np.divide(1.0, d, out=d)                         # weights 1 / d²
    return -dc, dr, damp, d, np.ceil(np.sqrt(d2))


def _holes(prev, key, z, valid, need, out, dk, radius):
    """Return the hole cells to compute: ``(holes, hr, hc)``, the raster and their lists.

    When a previous fill may keep some of the holes, they are listed band by band and
    those kept are written into ``out`` and ``dk`` and left out (``holes`` is then None:
    the lists are all that is read). When they are few they are listed. Else the lists
    are None and :func:`_batches` lists the holes band by band (at low density millions).
    """
    holes = ~valid
    if need is not None:
        holes &= need
    keep = _keeper(prev, key, z, valid, radius)
    if keep is None:
        if np.count_nonzero(holes) > FEW_HOLES:
            return holes, None, None
        return (holes,) + _nonzero(holes)
    old_out, old_dk = prev["out"], prev["d2k"]
    rs, cs = [], []
    for r, c in _bands(holes):
        same = keep(r, c)
        if same.any():
            out[r[same], c[same]] = old_out[r[same], c[same]]
            dk[r[same], c[same]] = old_dk[r[same], c[same]]
            np.logical_not(same, out=same)
            r, c = r[same], c[same]
        rs.append(r)
        cs.append(c)
    it = _index_type(valid.shape)
    return None, np.concatenate(rs or [np.empty(0, it)]), np.concatenate(cs or [np.empty(0, it)])


#: Cells per band of rows in which :func:`tangent_fill` lists its hole cells when it does
#: not hold them all at once.
HOLE_BAND = 1 << 20


def _batches(holes, hr, hc):
    """Rows and columns of the hole cells, :data:`BATCH` at a time, in row-major order.

    From the lists ``(hr, hc)`` (with the batch's start in them), or (when None) from the
    raster ``holes`` band by band (start None).
    """
    if hr is not None:
        for s in range(0, hr.size, BATCH):
            yield s, (hr[s:s + BATCH], hc[s:s + BATCH])
        return
    for r, c in _bands(holes):
        for s in range(0, r.size, BATCH):
            yield None, (r[s:s + BATCH], c[s:s + BATCH])


def _rows(near, a: int, b: int):
    """Return the rows ``a:b`` of a :class:`._lattice_knn.Near`."""
    far = (near.far >= a) & (near.far < b)
    return near._replace(o=near.o[a:b], j=near.j[a:b], far=near.far[far] - a,
                         d2=near.d2[far], dc=near.dc[far], dr=near.dr[far])


def _bands(holes):
    """Rows and columns of the True cells of ``holes``, band by band, in row-major order."""
    step = max(1, HOLE_BAND // max(1, holes.shape[1]))
    for b0 in range(0, holes.shape[0], step):
        r, c = _nonzero(holes[b0:b0 + step])
        r += b0
        yield r, c


def _index_type(shape):
    """int32 when every row and column index of a raster of ``shape`` fits, else int64."""
    return np.int32 if max(shape) < 2 ** 31 else np.int64


def _nonzero(mask):
    """``np.nonzero(mask)`` of a raster in :func:`_index_type`, band by band.

    The same cells in the same (row-major) order, without the int64 index arrays of
    the whole raster at once (at low density most cells are holes: millions of them);
    each band's cells by ``flatnonzero`` (a 2-D ``nonzero`` is several times slower).
    """
    it = _index_type(mask.shape)
    cols = max(1, mask.shape[1])
    n = int(np.count_nonzero(mask))
    rr, cc = np.empty(n, it), np.empty(n, it)
    step = max(1, (1 << 18) // cols)
    k = 0
    for b0 in range(0, mask.shape[0], step):
        f = np.flatnonzero(mask[b0:b0 + step])
        r = f // cols
        e = k + f.size
        rr[k:e] = r
        rr[k:e] += b0
        cc[k:e] = f - r * cols
        k = e
    return rr, cc


#: Share of changed cells above which :func:`_keeper` keeps nothing (after the
#: growing step or the first refine pass, 1-3 % of the cells change and under 7 % of
#: the holes could be kept: the check would cost more than it saves).
_FEW = 0.01
#: "Not computed" in a fill cache's raster of k-th neighbour distances in whole cells,
#: rounded up (farther cells are not kept either).
_NONE = np.iinfo(np.uint8).max


def _may_keep(prev, key):
    """Return whether ``prev`` (a cache) is a previous fill of the same raster and parameters."""
    return bool(prev) and prev.get("key") == key


def _keeper(prev, key, z, valid, radius):
    """``keep(hr, hc)``: the hole cells whose value in the previous fill is still exact.

    A hole cell's value depends on the border cells up to its ``k``-th distance ``D``
    (which are borders, hence the choice), their heights and their plane windows: on
    the valid flag and height of cells within ``D + 1.5 max(radius, 1)`` (1.5 > sqrt 2:
    a window's corner). When none of those changed since the previous fill and the cell
    was computed there, the old value is the new one. ``D`` is kept rounded up to whole
    cells (``prev["d2k"]``, uint8): a reach at least the true one, so a kept value is
    exact. None when nothing can be kept (no previous fill of the same raster, or too
    many changed cells to be worth a check).
    """
    if not _may_keep(prev, key):
        return None
    with np.errstate(invalid="ignore"):
        changed = np.not_equal(z, prev["out"])
        changed &= valid
        changed |= valid != prev["valid"]
    if np.count_nonzero(changed) > _FEW * changed.size:
        return None                                  # too many changes to be worth a check
    moved = np.argwhere(changed)
    del changed
    tree = cKDTree(moved) if moved.size else None
    old, pad = prev["d2k"], 1.5 * max(int(radius), 1)

    def keep(hr, hc):
        dk = old[hr, hc]
        ok = dk != _NONE
        if tree is None or not ok.any():
            return ok
        kept = np.flatnonzero(ok)
        for s in range(0, kept.size, BATCH):         # batches: bounded query arrays
            i = kept[s:s + BATCH]
            reach = dk[i].astype(np.float64) + pad
            dist = tree.query(np.column_stack((hr[i], hc[i])), k=1,
                              distance_upper_bound=float(reach.max()) + 1.0)[0]
            ok[i] = dist > reach
        return ok
    return keep


def grow_ground(zmin, obj, skip, dtm, cell, opt):
    """Object cells left after growing the ground along continuous surfaces (step 5b).

    A terrain crest (terrace edge, embankment, ridge) that the opening removed is
    continuous with the ground beside it; a roof is separated from it by a wall.
    A flagged cell becomes ground when the least-squares plane over the occupied
    cells of its window fits them within ``grow_rms`` (one continuous surface, no
    wall or vegetation in it), the cell and one of its already accepted neighbours
    both lie within ``grow_tol + scaler x slope`` of that plane, the plane is no
    steeper than ``grow_max_slope`` and the cell no more than ``grow_max_rise``
    above the provisional DTM. Repeated ``grow_iters`` times from the cells just
    accepted (whole-raster vectorised steps).

    Parameters
    ----------
    zmin : ndarray
        Minimum-z raster (NaN where empty).
    obj : ndarray of bool
        Object cells of the opening.
    skip : ndarray of bool
        Cells neither ground nor candidates (empty, low outliers).
    dtm : ndarray or callable
        Provisional DTM filled from the ground cells, or ``dtm(read, ground)`` returning
        its values at the cells ``read`` (the candidates: the other cells are never
        read), in ``np.flatnonzero(read)`` order, ``ground`` being the ground cells
        (``~(obj | skip)``; not to be changed).
    cell : float
        Cell size (m).
    opt : RecommendedOptions
        Options (``grow_*``, ``scaler``).

    Returns
    -------
    ndarray of bool
        ``obj`` without the cells grown into.
    """
    ground = ~(obj | skip)
    if not ground.any() or not (obj & ~skip).any():
        return obj
    rows, cols = zmin.shape
    rad = max(1, int(round(opt.grow_window / cell)))
    # candidates and their planes, band by band: only the candidate cells' values are kept
    cand, (centre, gx, gy, tol) = plane_fit_where(
        zmin, ~skip, rad, lambda b, at, rms, centre, gx, gy: _grow_candidates(
            b, at, rms, centre, gx, gy, zmin, cell, opt), where=obj & ~skip)
    at = np.flatnonzero(cand)                        # cells of the kept values, sorted
    dtm = dtm(cand, ground) if callable(dtm) else dtm.ravel()[at]
    with np.errstate(invalid="ignore"):
        keep = zmin.ravel()[at] - dtm <= opt.grow_max_rise
    del dtm
    cand.ravel()[at[~keep]] = False
    size = 2 * rad + 1          # square dilations as shifted ORs (the same cells)
    front = cand & R.dilate_mask(ground, size)
    for _ in range(int(opt.grow_iters)):
        rr, cc = _nonzero(front)
        if rr.size == 0:
            break
        i = np.searchsorted(at, rr.astype(np.int64) * cols + cc)
        acc = _misfit(rr, cc, centre[i], gx[i], gy[i], zmin, ground, rad) <= tol[i]
        if not acc.any():
            break
        front[:] = False
        front[rr[acc], cc[acc]] = True                   # the cells just accepted
        ground |= front
        front = cand & ~ground & R.dilate_mask(front, size)
    return obj & ~ground


#: Cells per block of :func:`_misfit` (bounds its (offsets, cells) arrays).
GROW_BLOCK = 4096


def _misfit(rr, cc, ce, ex, ey, zmin, ground, rad: int):
    """Smallest misfit of the ground cells of each cell's window to the cell's plane.

    ``|zmin - centre - gx dc - gy dr|`` over the ground cells at the offsets ``(dr, dc)``
    within ``rad`` (the cell itself excepted; inf where none), for the cells ``(rr,
    cc)`` whose planes are ``(ce, ex, ey)``: every offset at once, in blocks of
    :data:`GROW_BLOCK` cells (the minimum does not depend on the order); cells whose
    window lies inside the raster by flat indices, the others with their offsets
    clipped and masked.
    """
    rows, cols = zmin.shape
    dr, dc = np.mgrid[-rad:rad + 1, -rad:rad + 1].reshape(2, -1)
    off = (dr != 0) | (dc != 0)
    dr, dc = dr[off, None], dc[off, None]
    zf, gf = zmin.ravel(), ground.ravel()
    inner = (rr >= rad) & (rr < rows - rad) & (cc >= rad) & (cc < cols - rad)
    best = np.empty(rr.size)
    for s in range(0, rr.size, GROW_BLOCK):
        b = np.arange(s, min(s + GROW_BLOCK, rr.size))
        for part, edge in ((b[inner[b]], False), (b[~inner[b]], True)):
            nr, nc = rr[part] + dr, cc[part] + dc
            ok = True
            if edge:
                ok = (nr >= 0) & (nr < rows) & (nc >= 0) & (nc < cols)
                nr, nc = np.where(ok, nr, 0), np.where(ok, nc, 0)
            at = nr.astype(np.int64) * cols + nc
            e = np.abs(zf[at] - ce[part] - ex[part] * dc - ey[part] * dr)
            best[part] = np.where(gf[at] & ok, e, np.inf).min(axis=0, initial=np.inf)
    return best


def _ring(valid):
    """Return the valid cells with an invalid one among their 8 neighbours (none outside).

    ``valid & ~minimum_filter(valid, 3, mode="nearest")`` (the same cells) by the shifted
    minima (ANDs) of :func:`._openings.erode3`.
    """
    inner = erode3(valid.copy(), np.empty(valid.size, bool))
    np.logical_not(inner, out=inner)
    inner &= valid
    return inner


def _grow_candidates(b, at, rms, centre, gx, gy, zmin, cell, opt):
    """Candidates of :func:`grow_ground` among the object cells ``at`` and their tolerance.

    ``at``: flat indices within the rows ``b`` (a slice); the planes' values are at them.
    """
    with np.errstate(invalid="ignore"):
        steep = np.hypot(gx, gy)
        tol = opt.grow_tol + opt.scaler * steep / cell
        z = zmin[b].ravel()[at]
        cand = ((rms <= opt.grow_rms) & (np.abs(z - centre) <= tol)
                & (steep <= opt.grow_max_slope * cell))
    return cand, tol

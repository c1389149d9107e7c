"""Progressive TIN densification (PTD) ground filter after Axelsson (2000).

Pipeline (ground branch of the ELiT spec, Kostrikov et al. 2020): duplicates out ->
candidates = lowest point per ``thin`` cell (1 m) -> step filter on the TIN of the
``cell`` minima (pits and spikes out) -> seeds: the minima of ``SEED_CELLS`` x
``cell`` cells (6 m: under a closed canopy they still hold ground), and per parcel
(at most ``max_building`` wide, 3 x 3 grids offset by a third of a parcel) the
lowest of them not more than ``seed_depth`` below the parcel's ``seed_quantile``
quantile (so clusters of low outliers never seed the TIN) -> densify the TIN
until no candidate passes (distance-to-facet
and angle-to-vertex limits, one candidate per facet per iteration; Axelsson's
mirroring for candidates below their facet, and a cliff-aware mirroring for
candidates in facets that span a breakline) -> final pass of every point against
the last TIN: within the final distance plus ``final_slope`` per unit of slope (or
continuing a cliff foot or top) ground, unless it stands on lower ground (one layer:
:func:`~._tin.one_layer`), far below it low noise (class 7). Virtual
points on a frame around the cloud (every ``frame`` m) keep the TIN's edge facets
from being slivers, whose planes tilt into the vegetation.

Translation-invariant, so a catalog chunk gives the merged cloud's classes beyond
its buffer (``tests/core/test_filter_registry.py``: identical at 0.1 pts/m²): every
grid (candidate, step-filter and seed cells, parcels, frame points) lies on a
lattice fixed in world coordinates (through ``origin``, else through 0; only the
parcels at the cloud's edge adapt to it), the points are taken in one order by
position, ties of the triangulation (co-circular points, points on an edge or above
a vertex) are broken by a sub-millimetre offset hashed from each point's position
(:func:`jitter`), and no decision depends on the whole cloud (the densification
stops when no candidate passes anywhere, not on a global count).

Speed: the Delaunay TIN (Qhull) is built once, from one candidate per ``thin`` cell;
each iteration then inserts its accepted points (:func:`~._tin.insert`: only the facets
whose circumcircle holds a new point are re-triangulated, the same facets as a Qhull
rebuild), and a candidate rejected in a facet that survives (same three vertices) is
not tested again; the others are located by a vectorised walk from their previous facet
(:class:`~._tin.Tin`, no scipy barycentric transform). On one core 186,000-188,000
points/s (CPU time, load 4-5; the rebuild-per-iteration code gave 43,000-49,000 at load
5-7, alternated in one script with a 131,000-149,000 state of this one) on a 1 M-point
synthetic tile at 20 pts/m² (``benchmarks/results/ground.md``; was 4,810).

Measured on the 8 ISPRS filter-test samples at the defaults: mean total error 4.55 % (was
8.07 %; Axelsson published 4.82 % over all 15 samples, 6.32 % over these 8); 4.68 % held out
when angle and distance are chosen by leave-one-sample-out over these 8 and the 4 real files
(``benchmarks/results/ground.md``). The figure depends on where the lattice falls on a sample
(samp22 3.8-7.7 %, samp41 2.4-5.4 % over three lattice origins, before the final pass's
sliver check). A closed canopy with 5 % ground returns (``synthetic.landscapes.closed_forest``):
no canopy point is ground; Arizona mixed-conifer plot: no 1 m DTM cell over 1 m above the vendor's.

References
----------
Axelsson, P. (2000). DEM generation from laser scanner data using adaptive TIN
models. International Archives of Photogrammetry and Remote Sensing XXXIII-B4,
110-117.

Sithole, G. & Vosselman, G. (2004). Experimental comparison of filter algorithms
for bare-Earth extraction from airborne laser scanning point clouds. ISPRS J.
Photogramm. Remote Sens. 59(1-2), 85-101 (accuracy measures).
"""
from __future__ import annotations

from dataclasses import dataclass, fields
from typing import Optional

import numpy as np
from scipy.spatial import Delaunay, QhullError

from ..classes import GROUND, LOW_NOISE
from ..classes import UNCLASSIFIED as OBJECT
from ..errors import InputError
from ..progress import Cancelled, Monitor
from ..reporting import T
from . import _raster as R  # noqa: N812
from . import _tin
from ._filter import OptionsFilter
from ._filter import options_or_default as _options
from ._tin import (
    BREAKLINE_SLOPE,  # noqa: F401  (re-exported: ptd.BREAKLINE_SLOPE)
    JITTER,  # noqa: F401  (re-exported: ptd.JITTER)
    breakline_facets,
    breakline_test,
    jitter,
    mirror_test,
    one_layer,
)

__all__ = ["PtdOptions", "classify", "classify_with_tin", "ptd_filter", "Cancelled",
           "CITATION", "TITLE", "NOISE_PREFILTER"]

TITLE = "Ground filter (progressive TIN densification)"
CITATION = T("Reference: {ref}", ref="Axelsson, P. (2000). DEM generation from laser scanner "
             "data using adaptive TIN models. IAPRS XXXIII-B4, 110–117.")


#: Default of the pipeline's low-outlier pre-filter (:func:`~.noise.flag_low_outliers`)
#: for PTD: off, because the seeds skip low-outlier clusters and the final pass gives
#: points far below the TIN class 7; the pre-filter's test against every neighbour
#: flags isolated ground returns under closed canopy. The algorithm's NOISE default
#: and the benchmark (core defaults on every point) both follow it.
NOISE_PREFILTER = False

#: Seeds are picked among the minima of cells this many ``cell`` wide.
SEED_CELLS = 3

#: Seed parcels lie in this many grids per axis, offset by 1/PARCEL_OFFSETS of a parcel.
PARCEL_OFFSETS = 3

#: Ground points whose lowest gives a virtual corner its height (:func:`with_corners`).
CORNER_NEIGHBOURS = 1


@dataclass(frozen=True)
class PtdOptions:
    """Parameters of :func:`classify` (lengths in metres, angles in degrees).

    Attributes
    ----------
    cell : float
        Cell of the lowest-point reduction used for the step filter and seeds (m).
    max_building : float
        Parcel size for the seeds; must exceed the largest building (m).
    max_distance : float
        Largest distance from a candidate to its facet plane to accept it (m).
    max_angle : float
        Largest angle between the facet and the lines to its vertices (deg).
    min_edge : float
        Facets whose longest horizontal edge is shorter are not densified (m).
    max_iterations : int
        Iteration cap of the densification.
    final_distance : float
        Points within this distance of the final TIN become ground (m, <= max_distance).
    low_noise_depth : float
        Points more than this below the final TIN become low noise, class 7 (m).
    pit_step, pit_angle : float
        Step filter: a cell minimum lower (higher) than all its TIN neighbours by
        more than ``pit_step`` m and steeper than ``pit_angle`` deg to each is a pit
        (spike) and is not used to build the TIN.
    seed_quantile, seed_depth : float
        A parcel's seed is its lowest cell minimum not more than ``seed_depth`` (m)
        below the parcel's ``seed_quantile`` quantile of cell minima.
    min_points : int
        Fewest points accepted.
    mirror : {'none', 'below', 'all'}
        Which rejected candidates get Axelsson's mirror test (through the nearest
        facet vertex): none, only those below their facet, or all.
    breakline : bool
        Cliff-aware mirroring (:func:`breakline_test`) for candidates in facets that
        span a breakline (steeper than 45 degrees and rising more than
        ``max_distance``); needs ``mirror`` other than 'none'.
    thin : float
        Candidate cell: the lowest point per cell is a densification candidate, every
        other point is classified against the final TIN (m; 0 = every point).
    stop_fraction : float
        The densification stops when fewer candidates than this fraction of the
        TIN's vertices pass an iteration's tests (default 0: only when none passes;
        a fraction of the whole cloud's count makes a catalog chunk stop at another
        iteration than the merged cloud).
    frame : float
        Spacing of the virtual points on a frame around the cloud (m; 0 = its four
        corners only), :func:`with_corners`.
    final_slope : float
        The final pass accepts ``final_distance`` plus this many metres per unit of the
        facet's slope (rise/run).
    """

    cell: float = 2.0
    max_building: float = 60.0
    max_distance: float = 1.2
    max_angle: float = 24.0
    min_edge: float = 1.0
    max_iterations: int = 150
    final_distance: float = 0.5
    low_noise_depth: float = 1.5
    pit_step: float = 0.5
    pit_angle: float = 55.0
    seed_quantile: float = 0.2
    seed_depth: float = 3.0
    min_points: int = 10
    mirror: str = "below"
    breakline: bool = True
    thin: float = 1.0
    stop_fraction: float = 0.0
    frame: float = 15.0
    final_slope: float = 0.5

    def __post_init__(self):
        """Refuse invalid parameters."""
        if self.mirror not in ("none", "below", "all"):
            raise InputError("PtdOptions.mirror must be 'none', 'below' or 'all'")
        defaults = {f.name: f.default for f in fields(self)}
        for name in ("cell", "max_building", "max_distance", "max_angle",
                     "final_distance", "low_noise_depth", "pit_step"):
            if not getattr(self, name) > 0:     # the algorithm's parameter: the name upper
                raise InputError("{param} must be > 0, got {value}; give a positive value "
                                 "or leave the default ({default}).", param=name.upper(),
                                 value=getattr(self, name), default=defaults[name])
        if self.final_distance > self.max_distance:
            raise InputError("FINAL_DISTANCE ({final} m) must not exceed MAX_DISTANCE "
                             "({max} m): the final pass cannot accept points farther from "
                             "the TIN than the densification did.",
                             final=self.final_distance, max=self.max_distance)
        if not (self.thin >= 0 and 0 <= self.stop_fraction < 1):
            raise InputError("PtdOptions.thin >= 0 and 0 <= stop_fraction < 1 are required")
        if self.max_iterations < 1 or self.min_points < 4:
            raise InputError("max_iterations >= 1 and min_points >= 4 are required")


def classify(x, y, z, *, return_number=None, number_of_returns=None, options=None,
             progress=None, cancel=None, origin=None) -> np.ndarray:
    """Classify ground by progressive TIN densification (Axelsson 2000).

    Parameters
    ----------
    x, y, z : array_like of float
        Coordinates in a projected CRS, metres.
    return_number, number_of_returns : array_like of int, optional
        Accepted for API symmetry; PTD does not need them.
    options : PtdOptions, optional
        Parameters; the defaults suit 0.2-20 pts/m² airborne scans.
    progress : callable(float), optional
        Receives the fraction done in [0, 1].
    cancel : callable() -> bool, optional
        Polled between steps; when it returns True, :class:`Cancelled` is raised.
    origin : (float, float), optional
        Anchors the cells, parcels and frame points on the lattice through this
        point (catalog chunks equal the merged cloud); default: through (0, 0), so
        the classes do not depend on the cloud's extent away from its edges.

    Returns
    -------
    numpy.ndarray of uint8
        ASPRS class per point: 2 ground, 1 unclassified/object, 7 low noise.

    Raises
    ------
    ValueError
        On non-finite or degree-like coordinates, too few points or bad options.
    Cancelled
        When ``cancel()`` returned True.
    """
    cls, _ = classify_with_tin(x, y, z, options=options, progress=progress,
                               cancel=cancel, origin=origin)
    return cls


def classify_with_tin(x, y, z, *, options=None, progress=None, cancel=None, origin=None):
    """As :func:`classify`, also returning the final TIN vertices.

    Returns
    -------
    classes : numpy.ndarray of uint8
    tin : numpy.ndarray of float, shape (m, 3)
        Vertices (x, y, z) of the final TIN, including the four virtual corners.
    """
    opt = _options(options, PtdOptions)
    x, y, z = R.checked_xyz(x, y, z, opt.min_points)
    rep = Monitor(progress, cancel).step
    rep(0.0)
    # one canonical order (by world position): every tie (equal heights in a cell, equal
    # distances in a facet) is broken by where the points are, not by the input order,
    # which differs between a catalog chunk and the merged cloud
    order = np.lexsort((z, y, x))
    x, y, z = x[order], y[order], z[order]
    # every grid (candidate, step-filter and seed cells, parcels) on one lattice fixed in
    # world coordinates: through ``origin``, else through 0; a period holding whole
    # cells, parcels and half parcels
    ox, oy = (0.0, 0.0) if origin is None else (float(origin[0]), float(origin[1]))
    period = 2.0 * opt.max_building * opt.cell
    x0, y0 = R.snap_down(x.min(), ox, period), R.snap_down(y.min(), oy, period)
    xs, ys = x - x0, y - y0                       # local coordinates for Qhull
    try:
        cand = candidates(xs, ys, z, opt)
        seeds, pool = initial_ground(xs, ys, z, cand, opt)
        rep(0.1)
        jx, jy = jitter(x, y, z)
        xs, ys = xs + jx, ys + jy
        ground, tin = densify(xs, ys, z, seeds, pool, opt, rep)
        cls, tin = final_pass(xs, ys, z, ground, opt, tin)
    except QhullError as exc:          # a profile: every Delaunay step needs an area
        raise InputError("The {n} points lie on one line: progressive TIN densification "
                         "needs points spread over an area. Use the recommended ground "
                         "filter for a profile or a single scan line.", n=x.size) from exc
    rep(1.0)
    out = np.empty_like(cls)
    out[order] = cls
    return out, np.column_stack((tin.xy[:, 0] + x0, tin.xy[:, 1] + y0, tin.z))


def candidates(x, y, z, opt):
    """Return the densification candidates: the lowest point per ``thin`` cell.

    The TIN needs no more than one vertex per ``thin`` cell; every other point is
    classified by :func:`final_pass`. Positions closer than 1 cm are merged (their
    lowest point kept) so the Delaunay vertices are distinct.
    """
    uniq = _tin.dedupe_xy(x, y, z)
    if opt.thin <= 0.01:
        return uniq
    return uniq[_tin.lowest_per_cell(_cells(x[uniq], y[uniq], opt.thin), z[uniq])]


def _cells(x, y, size):
    """Cell key of every point on the ``size`` lattice through the local origin."""
    return (np.floor(y / size).astype(np.int64) << 32) + np.floor(x / size).astype(np.int64)


def initial_ground(x, y, z, uniq, opt):
    """Seeds and the densification pool (candidates minus pits and spikes)."""
    minima = uniq[_tin.lowest_per_cell(_cells(x[uniq], y[uniq], opt.cell), z[uniq])]
    bad = step_filter(x[minima], y[minima], z[minima], opt)
    keep = minima[~bad]
    # seeds come from the minima of coarser cells, which under a closed canopy still
    # hold ground (a parcel's quantile of them is a ground height)
    c3 = SEED_CELLS * opt.cell
    keep = keep[_tin.lowest_per_cell(_cells(x[keep], y[keep], c3), z[keep])]
    kx, ky, kz = x[keep], y[keep], z[keep]
    seeds = parcel_seeds(kx, ky, kz, opt, (x.min(), x.max(), y.min(), y.max()))
    bad_idx = minima[bad]
    pool = np.setdiff1d(uniq, bad_idx, assume_unique=True)
    return keep[seeds], pool


def step_filter(x, y, z, opt, passes: int = 2):
    """Flag pits and spikes among the cell minima (edge slope and step to all neighbours)."""
    bad = np.zeros(x.size, dtype=bool)
    if x.size < 4:
        return bad
    tan_a = np.tan(np.radians(opt.pit_angle))
    for _ in range(passes):
        idx = np.flatnonzero(~bad)
        if idx.size < 4:
            break
        ptr, nbr = Delaunay(np.column_stack((x[idx], y[idx])),
                            qhull_options="Qbb Qc Qz Q12").vertex_neighbor_vertices
        owner = np.repeat(np.arange(idx.size), np.diff(ptr))
        dz = z[idx][nbr] - z[idx][owner]
        length = np.hypot(x[idx][nbr] - x[idx][owner], y[idx][nbr] - y[idx][owner])
        lower = (dz > opt.pit_step) & (dz > tan_a * length)
        upper = (-dz > opt.pit_step) & (-dz > tan_a * length)
        counts = np.diff(ptr)
        pit = np.add.reduceat(lower, ptr[:-1]) == counts
        spike = np.add.reduceat(upper, ptr[:-1]) == counts
        new = (pit | spike) & (counts > 0)
        if not new.any():
            break
        bad[idx[new]] = True
    return bad


def parcel_seeds(x, y, z, opt, extent=None):
    """Return the indices of the seeds: the lowest trusted point of overlapping parcels.

    Parcels are ``max_building`` wide (half the cloud's larger side if that is
    smaller), on the lattice through the local origin (fixed in world coordinates), in
    ``PARCEL_OFFSETS`` x ``PARCEL_OFFSETS`` grids offset by a fraction of a parcel. A
    parcel that covers less than half a parcel (or the whole cloud, when narrower) of
    ``extent`` (x0, x1, y0, y1) along x or y joins its inner neighbour: such a sliver at
    the cloud's edge may hold only canopy or a roof. Only the parcels at the edge
    depend on the extent, so a catalog chunk seeds as the whole cloud does farther
    than 1.5 parcels from its cut edges. ``x, y, z`` are cell minima; in each parcel
    the seed is the lowest of them that lies no more than ``seed_depth`` below the
    parcel's ``seed_quantile`` height quantile, so a cluster of low outliers
    (multipath) smaller than that share of the parcel never seeds the TIN.
    """
    if extent is None:
        extent = (x.min(), x.max(), y.min(), y.max())
    ex0, ex1, ey0, ey1 = (float(v) for v in extent)
    size = min(opt.max_building, max(ex1 - ex0, ey1 - ey0) / 2.0)
    size = max(size, 2.0 * opt.cell)
    out = []
    offsets = [size * k / PARCEL_OFFSETS for k in range(PARCEL_OFFSETS)]
    for off_x in offsets:
        for off_y in offsets:
            col = _parcel_index(x, off_x, size, ex0, ex1)
            row = _parcel_index(y, off_y, size, ey0, ey1)
            idx = (row << 32) + col
            order = np.lexsort((z, idx))
            starts = np.flatnonzero(np.r_[True, idx[order[1:]] != idx[order[:-1]]])
            counts = np.diff(np.r_[starts, order.size])
            q = z[order[starts + np.floor(counts * opt.seed_quantile).astype(np.int64)]]
            low = z[order] < np.repeat(q - opt.seed_depth, counts)
            skip = np.add.reduceat(low, starts)
            out.append(order[starts + np.minimum(skip, counts - 1)])
    return np.unique(np.concatenate(out))


def _parcel_index(v, off, size, e0, e1):
    """Parcel column of ``v`` on the lattice ``off + k * size``.

    A parcel that covers less than half a parcel of [e0, e1] (a sliver at the edge)
    joins its inner neighbour.
    """
    col = np.floor((v - off) / size).astype(np.int64)
    lo, hi = int(np.floor((e0 - off) / size)), int(np.floor((e1 - off) / size))
    need = min(size / 2.0, e1 - e0) * (1.0 - 1e-9)
    if hi > lo and min((lo + 1) * size + off, e1) - e0 < need:
        lo += 1
    if hi > lo and e1 - max(hi * size + off, e0) < need:
        hi -= 1
    return np.clip(col, lo, hi)


def with_corners(x, y, z, ground, spacing=None):
    """Ground xyz plus virtual points on a frame 1 m outside the cloud's extent.

    The frame's corners, and points every ``spacing`` m along its sides (so no facet
    at the edge is a long sliver whose plane tilts wildly across it), take the height
    of the lowest of the ``CORNER_NEIGHBOURS`` nearest ground points: a frame point too
    high tilts its facets up into the vegetation (closed canopy, sparse seeds), one too
    low only delays the ground near it until closer vertices replace it.
    """
    gx, gy, gz = x[ground], y[ground], z[ground]
    pad = 1.0
    x0, x1, y0, y1 = x.min() - pad, x.max() + pad, y.min() - pad, y.max() + pad
    # along each side at the multiples of ``spacing`` of the local lattice (not spaced to
    # fit the extent): a catalog chunk that shares a side with the whole cloud has the
    # same frame points along it
    tx = _frame_ticks(x0, x1, spacing)
    ty = _frame_ticks(y0, y1, spacing)
    cx = np.r_[x0, tx, x1, np.full(ty.size, x1), x1, tx[::-1], x0, np.full(ty.size, x0)]
    cy = np.r_[y0, np.full(tx.size, y0), y0, ty, y1, np.full(tx.size, y1), y1, ty[::-1]]
    k = min(CORNER_NEIGHBOURS, gx.size)
    near = _tin.cKDTree(np.column_stack((gx, gy))).query(np.column_stack((cx, cy)), k=k)[1]
    return (np.r_[gx, cx], np.r_[gy, cy],
            np.r_[gz, gz[near.reshape(cx.size, k)].min(axis=1)])


def _frame_ticks(a, b, spacing):
    """Multiples of ``spacing`` strictly inside (a, b), none closer than spacing / 4 to an end."""
    if not spacing:
        return np.zeros(0)
    t = np.arange(np.ceil(a / spacing), np.floor(b / spacing) + 1) * spacing
    return t[(t > a + spacing / 4.0) & (t < b - spacing / 4.0)]


def _facet_keys(tin, vid):
    """One int64 key per facet from the sorted ids ``vid`` of its vertices (< 2**21)."""
    v = np.sort(vid[tin.simplices], axis=1).astype(np.int64)
    return (v[:, 0] << 42) | (v[:, 1] << 21) | v[:, 2]


def densify(x, y, z, seeds, pool, opt, rep):
    """Progressive densification.

    Each iteration rebuilds the TIN of the accepted points and adds, per facet, the
    candidate closest to it among those passing the distance and angle tests
    (:func:`_accepted`). A candidate rejected in a facet that is still in the new
    TIN (same three vertices) stays rejected without a new test, so only the
    candidates of new facets are located (walking from their previous facet) and
    tested. The loop stops when no candidate passes, when fewer than
    ``stop_fraction`` of the TIN's vertex count pass, or at ``max_iterations``.

    Returns
    -------
    ground : ndarray of int
        Indices of the accepted ground points.
    tin : Tin or None
        The last TIN when it was built from exactly ``ground``, else None.
    """
    is_ground = np.zeros(x.size, dtype=bool)
    is_ground[seeds] = True
    cand = pool[~is_ground[pool]]
    key = np.full(cand.size, -1, dtype=np.int64)     # facet where it was rejected
    vert = np.full(cand.size, -1, dtype=np.int64)    # one vertex of that facet
    cache = x.size + 4 * (np.ptp(x) + np.ptp(y) + 4) / max(opt.frame, 1.0) + 8 < 2 ** 21
    tin, gidx, added = None, None, None
    for it in range(opt.max_iterations):
        rep(0.1 + 0.8 * it / opt.max_iterations)
        tin, gidx = _next_tin(x, y, z, is_ground, opt, tin, gidx, added)
        vid = np.r_[gidx, x.size + np.arange(tin.z.size - gidx.size)]
        keys = _facet_keys(tin, vid) if cache else None
        test = np.flatnonzero(~np.isin(key, keys)) if cache else np.arange(cand.size)
        sub = cand[test]
        start = None
        if it > 0 and cache:
            v = vert[test]          # a point index, or x.size + a frame point's number
            pos = np.where(v < x.size, np.searchsorted(gidx, v), gidx.size + v - x.size)
            start = tin.vertex_facet[np.where(v >= 0, pos, gidx.size)]
        sel, s, d = _accepted(tin, x[sub], y[sub], z[sub], start, opt)
        if sel.size == 0 or (it > 0 and sel.size < opt.stop_fraction * gidx.size):
            return gidx, tin
        order = sel[np.lexsort((d[sel], s[sel]))]
        first = np.r_[True, s[order[1:]] != s[order[:-1]]]
        is_ground[sub[order[first]]] = True
        added = (sub[order[first]], s[order[first]])
        if cache:
            key[test], vert[test] = keys[s], vid[tin.simplices[s, 0]]
        keep = ~is_ground[cand]
        cand, key, vert = cand[keep], key[keep], vert[keep]
    return np.flatnonzero(is_ground), None


def _next_tin(x, y, z, is_ground, opt, tin, gidx, added):
    """TIN of the ground points ``is_ground`` and the frame; the indices of those points.

    After the first iteration only the points ``added`` (indices, facets of ``tin``
    holding them) are inserted into ``tin`` (:func:`~._tin.insert`; the same facets
    as a Qhull rebuild, in another order), a rebuild when that does not check out.
    """
    new = np.flatnonzero(is_ground)
    if tin is None or CORNER_NEIGHBOURS != 1:
        tin = _tin.Tin(*with_corners(x, y, z, new, opt.frame))
        d, i = _tin.cKDTree(np.column_stack((x[new], y[new]))).query(tin.xy[new.size:])
        tin.frame_near = (d, new[i])
        return tin, new
    # the frame (fixed) takes the height of its nearest ground point: before or added
    q, (d, near) = tin.xy[gidx.size:], tin.frame_near
    d1, i = _tin.cKDTree(np.column_stack((x[added[0]], y[added[0]]))).query(q)
    d, near = np.where(d1 < d, d1, d), np.where(d1 < d, added[0][i], near)
    vx, vy, vz = np.r_[x[new], q[:, 0]], np.r_[y[new], q[:, 1]], np.r_[z[new], z[near]]
    o2n = np.r_[np.searchsorted(new, gidx), new.size + np.arange(q.shape[0])]
    nt = _tin.insert(tin, vx, vy, vz, o2n, np.searchsorted(new, added[0]), added[1])
    nt = _tin.Tin(vx, vy, vz) if nt is None else nt
    nt.frame_near = (d, near)
    return nt, new


def _accepted(tin, cx, cy, cz, start, opt):
    """Candidates passing the tests of one iteration: (positions, facets, distances)."""
    s = tin.locate(cx, cy, start)
    d, _, ang, _ = tin.distances(cx, cy, cz, s)
    ok = (np.abs(d) <= opt.max_distance) & (ang <= opt.max_angle)
    d = np.abs(d)
    steep = breakline_facets(tin, opt) if opt.breakline else None
    mirror_test(tin, cx, cy, cz, s, d, ok, opt, steep)
    ok &= tin.edge[s] >= opt.min_edge if steep is None else \
        (tin.edge[s] >= opt.min_edge) | steep[s]
    return np.flatnonzero(ok), s, d


def final_pass(x, y, z, ground, opt, tin=None):
    """Classes against the final TIN: ground within ``final_distance``, 7 far below.

    The allowance grows by ``final_slope`` per unit of the facet's slope, but a point
    more than ``final_distance`` above the facet's highest vertex is never ground: a
    sliver facet (vertices nearly in line) is steep without any rise. Nor is a point
    more than ``final_distance`` plus the terrain's rise above a nearby ground vertex
    (:func:`~._tin.one_layer`: shrubs over a TIN that rose into them).

    A point in a facet spanning a breakline is also ground when it passes
    :func:`breakline_test` (it continues the cliff foot or top surface).

    ``tin`` is the :class:`~._tin.Tin` of exactly ``ground`` when the densification
    already built it. Every point is located by walking from the facet of its
    nearest TIN vertex.

    Returns
    -------
    classes : ndarray of uint8
    tin : Tin
        The final TIN.
    """
    if tin is None:
        tin = _tin.Tin(*with_corners(x, y, z, ground, opt.frame))
    steep = breakline_facets(tin, opt) if opt.breakline and opt.mirror != "none" else None
    cls = np.full(x.size, OBJECT, dtype=np.uint8)
    tan = np.sqrt(np.maximum(1.0 / np.maximum(tin.normal[:, 2], 1e-3) ** 2 - 1.0, 0.0))
    rise, cliff = tin.regional_tan(1), np.zeros(tin.z.size, dtype=bool)
    cliff[tin.simplices[breakline_facets(tin, opt)].ravel()] = True
    for a in range(0, x.size, _tin.CHUNK * 4):
        b = min(a + _tin.CHUNK * 4, x.size)
        d, dz, _, s = tin.distances(x[a:b], y[a:b], z[a:b])
        ok = np.abs(d) <= opt.final_distance + opt.final_slope * tan[s]
        # a sliver facet (vertices nearly in line) is steep without any rise: its slope
        # allowance must not take a point far above its highest vertex (a tree 6 m
        # over the mixed-conifer ground was ground)
        ok &= z[a:b] <= tin.corners[s, :, 2].max(axis=1) + opt.final_distance
        one_layer(tin, x[a:b], y[a:b], z[a:b], s, ok, ground.size, rise, cliff, opt)
        if steep is not None:       # points at a cliff edge: the densification's test
            breakline_test(tin, x[a:b], y[a:b], z[a:b], s, np.abs(d), ok, opt, steep)
        c = cls[a:b]
        c[ok] = GROUND
        c[(dz < -opt.low_noise_depth) & ~ok] = LOW_NOISE
    cls[ground] = GROUND
    return cls, tin


LABELS = {"cell": "Cell (m)", "max_building": "Parcel size, > largest building (m)",
          "max_distance": "Distance to facet (m)", "max_angle": "Angle to vertices (degrees)",
          "min_edge": "Shortest facet edge (m)", "max_iterations": "Iteration cap",
          "final_distance": "Final distance (m)", "low_noise_depth": "Low-noise depth (m)",
          "seed_quantile": "Seed quantile (fraction)", "seed_depth": "Seed depth (m)",
          "thin": "Candidate cell (m)"}


def ptd_filter(options: Optional[PtdOptions] = None) -> OptionsFilter:
    """Return PTD as a pipeline algorithm object (:func:`~.pipeline.classify_file`).

    Parameters
    ----------
    options : PtdOptions, optional
        Parameters (defaults when None).

    Returns
    -------
    OptionsFilter
        Name ``ptd``; its cells, parcels and frame lie on the lattice through 0
        (``lattice='world'``) whoever runs it.
    """
    return OptionsFilter(classify, options or PtdOptions(), name="ptd", title=TITLE,
                         citation=CITATION, labels=LABELS, lattice="world")

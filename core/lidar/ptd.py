"""Progressive TIN densification (PTD) ground filter after Axelsson (2000).

Pipeline (ground branch of the ELiT spec, Kostrikov et al. 2020): duplicates out ->
lowest point per cell -> step filter on the TIN of the cell minima (pits and spikes
out) -> seeds = lowest points of overlapping parcels larger than the largest
building -> densify the TIN (distance-to-facet and angle-to-vertex limits, one point
per facet per iteration, iteration cap; Axelsson's mirroring for candidates below
their facet, and a cliff-aware mirroring for candidates in facets that span a
breakline, so the ground at a cliff foot and top is kept) -> final pass against the
last TIN: points within the final distance become ground, points far below it low
noise (class 7).

The densification is vectorised: the Delaunay TIN (Qhull) is rebuilt once per
iteration with every point accepted in that iteration, and all candidates are
located with :func:`_tin.find_simplex` (scipy's answer for every point, also on
edges, in near-linear time). The Qhull rebuilds are most of the run time and
cannot be made incremental without changing results: on lattice-like coordinates
(ISPRS) Qhull's triangulation of cocircular points changes far from the points
added. Speed on one core: 4,810 points/s, 342 bytes/point (1 M points at 20
pts/m², ``benchmarks/results/ground.md``).

Measured on the 8 ISPRS filter-test samples at the defaults: mean total error
8.07 % (8.05 % without the cliff-aware mirroring; see
``benchmarks/results/ground.md``).

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

from dataclasses import dataclass
from typing import Optional

import numpy as np

from ..classes import GROUND, LOW_NOISE
from ..classes import UNCLASSIFIED as OBJECT
from ..errors import InputError
from ..progress import Cancelled, Monitor
from ..reporting import T
from . import _raster as R  # noqa: N812
from . import _tin
from ._filter import OptionsFilter
from ._filter import options_or_default as _options

__all__ = ["PtdOptions", "classify", "classify_with_tin", "ptd_filter", "Cancelled",
           "CITATION", "TITLE"]

TITLE = "Ground filter (progressive TIN densification)"
CITATION = T("Reference: {ref}", ref="Axelsson, P. (2000). DEM generation from laser scanner "
             "data using adaptive TIN models. IAPRS XXXIII-B4, 110–117.")


#: Facets steeper than this (degrees) and rising more than ``max_distance`` span a
#: breakline (cliff foot to cliff top) for :func:`breakline_test`.
BREAKLINE_SLOPE = 45.0


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
    seed_drop : float
        Fraction of the lowest points of each parcel skipped before picking its seed.
    min_points : int
        Fewest points accepted.
    mirror : {'none', 'below', 'all'}
        Which rejected candidates get Axelsson's mirror test (through the nearest
        facet vertex): none, only those below their facet, or all.
    breakline : bool
        Cliff-aware mirroring (:func:`breakline_test`) for candidates in facets that
        span a breakline (steeper than 45 degrees and rising more than
        ``max_distance``); needs ``mirror`` other than 'none'.
    """

    cell: float = 2.0
    max_building: float = 30.0
    max_distance: float = 1.5
    max_angle: float = 18.0
    min_edge: float = 1.0
    max_iterations: int = 150
    final_distance: float = 0.5
    low_noise_depth: float = 1.5
    pit_step: float = 0.5
    pit_angle: float = 55.0
    seed_drop: float = 0.003
    min_points: int = 10
    mirror: str = "below"
    breakline: bool = True

    def __post_init__(self):
        """Refuse invalid parameters."""
        if self.mirror not in ("none", "below", "all"):
            raise InputError("PtdOptions.mirror must be 'none', 'below' or 'all'")
        for name in ("cell", "max_building", "max_distance", "max_angle",
                     "final_distance", "low_noise_depth", "pit_step"):
            if not getattr(self, name) > 0:
                raise InputError("PtdOptions.{name} must be positive", name=name)
        if self.final_distance > self.max_distance:
            raise InputError("final_distance must not exceed max_distance")
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
        Anchors the cells and parcels on the lattice through this point (catalog
        chunks equal the merged cloud); default: the cloud's lower-left corner.

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
    x0, y0 = x.min(), y.min()
    if origin is not None:     # a period holding whole cells, parcels and half parcels
        period = 2.0 * opt.max_building * opt.cell
        x0, y0 = R.snap_down(x0, origin[0], period), R.snap_down(y0, origin[1], period)
    xs, ys = x - x0, y - y0                       # local coordinates for Qhull
    uniq = _tin.dedupe_xy(xs, ys, z)
    seeds, pool = initial_ground(xs, ys, z, uniq, opt)
    rep(0.1)
    ground, tin = densify(xs, ys, z, seeds, pool, opt, rep)
    cls, (gx, gy, gz) = final_pass(xs, ys, z, ground, opt, tin)
    rep(1.0)
    return cls, np.column_stack((gx + x0, gy + y0, gz))


def initial_ground(x, y, z, uniq, opt):
    """Seeds and the densification pool (unique positions minus pits and spikes)."""
    ncols = int(np.ptp(x) // opt.cell) + 2
    minima = uniq[_tin.lowest_per_cell(_tin.cell_index(x[uniq], y[uniq], 0.0, 0.0, opt.cell,
                                                 ncols), z[uniq])]
    bad = step_filter(x[minima], y[minima], z[minima], opt)
    keep = minima[~bad]
    seeds = parcel_seeds(x[keep], y[keep], z[keep], opt)
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
        tri = _tin.build(np.column_stack((x[idx], y[idx])))
        ptr, nbr = tri.vertex_neighbor_vertices
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


def parcel_seeds(x, y, z, opt):
    """Return the indices of the lowest point (after ``seed_drop``) of overlapping parcels.

    Parcels are ``max_building`` wide with a stride of half a parcel; the parcel
    size shrinks so that each extent edge holds at least three parcels.
    """
    size = min(opt.max_building, max(np.ptp(x), np.ptp(y)) / 3.0)
    size = max(size, 2.0 * opt.cell)
    out = []
    for ox in (0.0, size / 2.0):
        for oy in (0.0, size / 2.0):
            ncols = int((np.ptp(x) + ox) // size) + 2
            idx = _tin.cell_index(x + ox, y + oy, 0.0, 0.0, size, ncols)
            order = np.lexsort((z, idx))
            starts = np.flatnonzero(np.r_[True, idx[order[1:]] != idx[order[:-1]]])
            counts = np.diff(np.r_[starts, order.size])
            skip = np.floor(counts * opt.seed_drop).astype(np.int64)
            out.append(order[starts + skip])
    return np.unique(np.concatenate(out))


def with_corners(x, y, z, ground):
    """Ground xyz plus four virtual corners (height of the nearest ground point)."""
    gx, gy, gz = x[ground], y[ground], z[ground]
    pad = 1.0
    cx = np.array([x.min() - pad, x.max() + pad, x.max() + pad, x.min() - pad])
    cy = np.array([y.min() - pad, y.min() - pad, y.max() + pad, y.max() + pad])
    near = np.argmin(np.hypot(gx[:, None] - cx, gy[:, None] - cy), axis=0) \
        if gx.size < 200_000 else _tin.cKDTree(np.column_stack((gx, gy))).query(
            np.column_stack((cx, cy)))[1]
    return np.r_[gx, cx], np.r_[gy, cy], np.r_[gz, gz[near]]


def densify(x, y, z, seeds, pool, opt, rep):
    """Progressive densification.

    Returns
    -------
    ground : ndarray of int
        Indices of the accepted ground points.
    tin : tuple or None
        ``(tri, (gx, gy, gz))`` of the last TIN when it was built from exactly
        ``ground`` (the loop stopped because no point was accepted), else None.
    """
    is_ground = np.zeros(x.size, dtype=bool)
    is_ground[seeds] = True
    cand = pool[~is_ground[pool]]
    for it in range(opt.max_iterations):
        rep(0.1 + 0.8 * it / opt.max_iterations)
        tri = geom = None                     # free the previous TIN before the next
        gx, gy, gz = with_corners(x, y, z, np.flatnonzero(is_ground))
        tri = _tin.build(np.column_stack((gx, gy)))
        geom = _tin.facet_geometry(tri, gz)
        sel, s, d = _accepted(tri, gz, geom, x, y, z, cand, opt)
        if sel is None:
            return np.flatnonzero(is_ground), (tri, (gx, gy, gz))
        order = sel[np.lexsort((d[sel], s[sel]))]
        first = np.r_[True, s[order[1:]] != s[order[:-1]]]
        is_ground[cand[order[first]]] = True
        cand = cand[~is_ground[cand]]
    return np.flatnonzero(is_ground), None


def _accepted(tri, gz, geom, x, y, z, cand, opt):
    """Candidates passing the tests of one iteration: (positions, facets, distances).

    Positions are None when no candidate passes.
    """
    cx, cy, cz = x[cand], y[cand], z[cand]
    d, _, ang, s = _tin.distances(tri, gz, cx, cy, cz, geom=geom)
    ok = (np.abs(d) <= opt.max_distance) & (ang <= opt.max_angle)
    d = np.abs(d)
    steep = breakline_facets(geom, gz, tri, opt) if opt.breakline else None
    mirror_test(tri, gz, geom, cx, cy, cz, s, d, ok, opt, steep)
    ok &= geom[2][s] >= opt.min_edge if steep is None else \
        (geom[2][s] >= opt.min_edge) | steep[s]
    if not ok.any():
        return None, s, d
    return np.flatnonzero(ok), s, d


def mirror_test(tri, gz, geom, cx, cy, cz, s, d, ok, opt, steep=None):
    """Axelsson's mirroring for candidates near breaklines (in place).

    A rejected candidate is mirrored through the nearest vertex of
    the facet (M = 2 V - P); when M passes the distance and angle tests the
    candidate is accepted and its distance set to M's. Candidates in a steep facet
    (a facet spanning a cliff) get :func:`breakline_test` as well.
    """
    test = np.flatnonzero(~ok)
    if test.size == 0 or opt.mirror == "none":
        return
    if steep is not None:
        breakline_test(tri, gz, geom, cx, cy, cz, s, d, ok, opt, steep)
        test = np.flatnonzero(~ok)
    v = geom[1][s[test]]
    p = np.column_stack((cx[test], cy[test], cz[test]))
    if opt.mirror == "below":
        below = np.einsum("ij,ij->i", p - v[:, 0], geom[0][s[test]]) < 0
        test, v, p = test[below], v[below], p[below]
        if test.size == 0:
            return
    near = np.argmin(np.linalg.norm(p[:, None, :] - v, axis=2), axis=1)
    m = 2.0 * v[np.arange(test.size), near] - p
    dm, _, am, _ = _tin.distances(tri, gz, m[:, 0], m[:, 1], m[:, 2], geom=geom)
    good = (np.abs(dm) <= opt.max_distance) & (am <= opt.max_angle)
    ok[test[good]] = True
    d[test[good]] = np.abs(dm[good])


def breakline_facets(geom, gz, tri, opt):
    """Flag facets steeper than ``BREAKLINE_SLOPE`` that rise more than ``max_distance``."""
    rise = np.ptp(gz[tri.simplices], axis=1)
    return (geom[0][:, 2] < np.cos(np.radians(BREAKLINE_SLOPE))) & (rise > opt.max_distance)


def breakline_test(tri, gz, geom, cx, cy, cz, s, d, ok, opt, steep):
    """Mirroring at cliffs: accept a candidate that continues the terrain beyond a vertex.

    A facet that spans a breakline (:func:`breakline_facets`: cliff foot to cliff
    top) says nothing about the candidates inside it. Such a rejected candidate P
    is mirrored (M = 2 V - P, Axelsson 2000, who uses the nearest facet vertex only)
    through each of the facet's three vertices and through the three TIN vertices
    nearest to it in 3D, which at a cliff are often not vertices of its facet; only
    vertices within two cells of P count. P is accepted when some M falls in a
    facet that does not span a breakline and lies within ``final_distance`` of it
    vertically, i.e. P continues the cliff foot or cliff top surface through V.
    In place, like :func:`mirror_test`.
    """
    test = np.flatnonzero(~ok & steep[s])
    if test.size == 0:
        return
    p = np.column_stack((cx[test], cy[test], cz[test]))
    vert = np.column_stack((tri.points, gz))
    near = vert[_tin.cKDTree(vert).query(p, k=min(3, gz.size))[1]].reshape(test.size, -1, 3)
    v = np.concatenate((geom[1][s[test]], near), axis=1)
    far = (np.linalg.norm(v - p[:, None, :], axis=2) > 2.0 * opt.cell).ravel()
    m = (2.0 * v - p[:, None, :]).reshape(-1, 3)
    _, dz, _, sm = _tin.distances(tri, gz, m[:, 0], m[:, 1], m[:, 2], geom=geom)
    off = np.where(steep[sm] | far, np.inf, np.abs(dz)).reshape(test.size, -1).min(axis=1)
    good = off <= opt.final_distance
    ok[test[good]] = True
    d[test[good]] = off[good]


def final_pass(x, y, z, ground, opt, tin=None):
    """Classes against the final TIN: ground within ``final_distance``, 7 far below.

    ``tin`` is ``(tri, (gx, gy, gz))`` of the TIN of exactly ``ground`` when the
    densification already built it (Qhull gives the same TIN for the same input).
    """
    tri, (gx, gy, gz) = tin if tin is not None else (None, with_corners(x, y, z, ground))
    if tri is None:
        tri = _tin.build(np.column_stack((gx, gy)))
    d, dz, _, _ = _tin.distances(tri, gz, x, y, z)
    cls = np.full(x.size, OBJECT, dtype=np.uint8)
    cls[np.abs(d) <= opt.final_distance] = GROUND
    cls[ground] = GROUND
    cls[dz < -opt.low_noise_depth] = LOW_NOISE
    return cls, (gx, gy, gz)


LABELS = {"cell": "Cell (m)", "max_building": "Parcel size, > largest building (m)",
          "max_distance": "Distance to facet (m)", "max_angle": "Angle to vertices (degrees)",
          "min_edge": "Shortest facet edge (m)", "max_iterations": "Iteration cap",
          "final_distance": "Final distance (m)", "low_noise_depth": "Low-noise depth (m)",
          "seed_drop": "Seed drop (fraction)"}


def ptd_filter(options: Optional[PtdOptions] = None) -> OptionsFilter:
    """Return PTD as a pipeline algorithm object (:func:`~.pipeline.classify_file`).

    Parameters
    ----------
    options : PtdOptions, optional
        Parameters (defaults when None).

    Returns
    -------
    OptionsFilter
        Name ``ptd``.
    """
    return OptionsFilter(classify, options or PtdOptions(), name="ptd", title=TITLE,
                         citation=CITATION, labels=LABELS)

"""Ground filter (recommended): progressive morphology with cloud-derived parameters.

A simple-morphological-filter (SMRF) style pipeline on a minimum-surface raster
(Pingel et al. 2013, after the progressive morphological filter of Zhang et al.
2003) whose cell size, window and slope tolerance are derived from the cloud
itself (point density, terrain slope), never from labels:

1. validate; density rho over occupied 5 m cells; cell = clip(1 / sqrt(rho), 1, 1) m
   (no gain from other cells between 0.17 and 20 pts/m²).
2. minimum-z raster; empty cells filled by a push-pull pyramid, except that a filled
   cell whose occupied 3x3 neighbours differ by more than 2 x cell x slope_max + t (a
   wall, not a slope; t the height tolerance of step 7) takes the lowest of them: a fill
   half-way up a wall made the opening descend it in drops each under its threshold,
   keeping roofs of sparse clouds (0.5-2 pts/m²) as ground.
3. low outliers: cells more than 5 m below their 3x3 closing are dropped; where such
   pits are more than 8 % of the occupied cells within 25 m they are ground seen
   through a canopy, and the closing is taken at the spacing of the ground returns
   (:mod:`._lowcells`), so the terrain never climbs into the trees.
4. slope tolerance per cell = clip(0.5 x local terrain slope, 0.10, 0.60), the
   terrain slope being the gradient of the 18 m opening averaged over 18 m.
5. the large-scale terrain trend (27 m opening box-averaged over 55 m) is subtracted:
   the opening's flat structuring element then follows the regional slope instead of
   the horizontal; progressive opening with square windows of radius 1..R cells,
   R = ceil(max_window / cell); a cell whose height drops more than
   ``slope * r * cell`` is an object cell (Zhang et al. 2003; Pingel et al. 2013).
   Cells outside the occupied cells' convex hull are absent from these openings (and
   from those of steps 4-5, which are then filled from the opening there).
5b. continuity growing: a flagged cell becomes ground again when the least-squares
   plane of its 7 m window fits the occupied cells there within 0.5 m RMS, the cell
   and an accepted neighbour both lie within 0.1 m + 1.0 x slope of it, the plane
   is no steeper than 0.6 and the cell no more than 2 m above the provisional DTM;
   10 steps from the cells just accepted (reach <= 30 m). A terrain crest the opening
   removed is continuous with the ground beside it, a roof is cut off by its wall; the
   slope and rise limits keep pitched roofs and bridge decks out.
6. provisional DTM: ground cells' minima; every hole cell (object, low or empty) is the
   inverse-distance weighted mean of the tangent planes of its 12 nearest border cells,
   the border gradients being least-squares planes over the ground cells of a 7 m
   window and the slope term stopping to grow beyond 10 m (:mod:`._surface`, after
   Shepard 1968 and Franke & Nielson 1980). Unlike a linear TIN or a Laplace fill
   (Pingel et al. 2013), it does not cut the crest of a ridge or embankment that the
   opening removed.
7. per point: ground when |z - DTM| <= t + 1.0 x local DTM slope, the height tolerance
   t = 0.35 x mean point spacing within 0.25-0.5 m (the DTM at a point is interpolated
   over about one spacing); points more than max(tolerance, 1 m) below the DTM are low
   noise (class 7).
8. refine (3 passes): DTM rebuilt from the lowest ground point per cell (holes filled
   as in step 6, only where points read them), step 7 repeated.

Measured (``benchmarks/results/ground.md``): ISPRS total error mean 3.27 %, below SMRF
(PDAL's defaults, 5.75 %) on 7 of 8 samples (not samp11: 8.59 vs 8.52); 4 real files: DTM
RMSE at or below SMRF's; 12-fold leave-one-sample-out 3.31 % (ISPRS folds), 0.43 % (real);
thinned to 2, 1, 0.5 pts/m²: 35 of 36 within 1 %. Water, report: :mod:`._recommended_filter`.

References
----------
Pingel, T. J., Clarke, K. C. & McBride, W. A. (2013). An improved simple
morphological filter for the terrain classification of airborne LIDAR data.
ISPRS J. Photogramm. Remote Sens. 77, 21-30.

Zhang, K., Chen, S.-C., Whitman, D., Shyu, M.-L., Yan, J. & Zhang, C. (2003).
A progressive morphological filter for removing nonground measurements from
airborne LIDAR data. IEEE Trans. Geosci. Remote Sens. 41(4), 872-882.

Axelsson, P. (2000). DEM generation from laser scanner data using adaptive TIN
models. IAPRS XXXIII-B4, 110-117 (see :mod:`.ptd`).

Shepard, D. (1968). A two-dimensional interpolation function for irregularly-spaced
data. Proc. 23rd ACM National Conference, 517-524.

Franke, R. & Nielson, G. (1980). Smooth interpolation of large sets of scattered data.
Int. J. Numer. Methods Eng. 15(11), 1691-1704.

Sithole, G. & Vosselman, G. (2004). Experimental comparison of filter algorithms
for bare-Earth extraction from airborne laser scanning point clouds. ISPRS J.
Photogramm. Remote Sens. 59(1-2), 85-101 (accuracy measures).
"""
from __future__ import annotations

from dataclasses import dataclass, replace
from functools import partial
from typing import Optional

import numpy as np

from ..classes import GROUND
from ..errors import InputError
from ..progress import Cancelled, Monitor
from ..reporting import T
from ..system import release_free_memory as _trim
from . import _lowcells as L  # noqa: N812
from . import _raster as R  # noqa: N812
from . import _surface as S  # noqa: N812
from ._filter import OptionsFilter
from ._filter import options_or_default as _options
from ._labels import label_points
from ._surface import grow_ground
from ._terrain import outside_hull, progressive_objects, terrain_slope, trend_surface, wall_step  # noqa: F401

__all__ = ["RecommendedOptions", "classify", "derive", "recommended_filter", "OptionsFilter",
           "Cancelled", "CITATION", "TITLE"]

TITLE = "Ground filter (recommended)"
CITATION = T("References: {ref}", ref=(
    "Pingel, T. J., Clarke, K. C. & McBride, W. A. (2013). An improved simple morphological "
    "filter for the terrain classification of airborne LIDAR data. ISPRS J. Photogramm. "
    "Remote Sens. 77, 21–30. Zhang, K. et al. (2003). A progressive morphological filter "
    "for removing nonground measurements from airborne LIDAR data. IEEE TGRS 41(4), "
    "872–882."))


#: Largest ``max_window`` accepted (m): more than any building (an aircraft factory is
#: about 1 km); the progressive opening makes ``max_window / cell`` passes, and a window of
#: 1e9 m exhausted the memory before the first one.
MAX_WINDOW_LIMIT = 2000.0


@dataclass(frozen=True)
class RecommendedOptions:
    """Parameters of :func:`classify` (lengths in metres, slopes as rise/run).

    ``None`` means "derive from the cloud" (see the module docstring).

    Attributes
    ----------
    cell : float or None
        Raster cell (m). Derived: ``cell_factor / sqrt(density)`` within
        [``cell_min``, ``cell_max``].
    cell_factor, cell_min, cell_max : float
        Cell = ``cell_factor`` x mean point spacing, clipped (m).
    max_window : float
        Largest opening window (m); must exceed the largest building.
    slope : float or None
        Slope tolerance of the opening (rise/run); None derives it from the terrain.
    slope_factor, slope_min, slope_max : float
        Derived slope = ``slope_factor`` x local terrain slope, clipped.
    threshold : float or None
        Vertical tolerance of the final per-point test (m). Derived:
        ``threshold_factor`` x mean point spacing within [``threshold_min``,
        ``threshold_max``] (the DTM at a point is interpolated over about one spacing).
    threshold_factor, threshold_min, threshold_max : float
        See ``threshold``.
    scaler : float
        Extra tolerance per unit of local DTM slope (m per rise/run).
    low_step : float
        A cell more than this below its 3x3 closing is a low outlier (m) - read at
        the ground-return scale where such pits are common (:mod:`._lowcells`).
    low_window, low_share : float
        Half-size (m) of the neighbourhood, and the share of pits in it above which
        the pits are ground under a canopy, not outliers.
    low_noise_depth : float
        Points deeper than this below the DTM become class 7 (m).
    min_points : int
        Fewest points accepted.
    refine : int
        Passes that rebuild the DTM from the minima of the points labelled ground
        and relabel (3 chosen by leave-one-sample-out on ISPRS).
    fill_radius : float
        Half-size (m) of the window of the least-squares planes whose tangent planes
        fill the object holes of the provisional DTM (:mod:`._surface`).
    fill_neighbours : int
        Border cells whose tangent planes are averaged per hole cell.
    fill_reach : float
        Distance (m) beyond which a border's slope no longer extrapolates.
    trend_window, trend_smooth : float
        Radius (m) of the opening and half-size (m) of the box mean that give the
        large-scale terrain trend subtracted before the progressive opening
        (:func:`trend_surface`); 0 for either disables the detrending.
    grow : bool
        Continuity growing of the ground cells into the object cells (step 5b).
    grow_window : float
        Half-size (m) of the window of the local least-squares planes.
    grow_rms : float
        Largest RMS residual (m) of a window that counts as one continuous surface.
    grow_tol : float
        Vertical tolerance (m) of a cell and of its accepted neighbour to the plane,
        plus ``scaler`` x the plane's slope.
    grow_max_slope : float
        Planes steeper than this (rise/run) are not grown into (pitched roofs).
    grow_max_rise : float
        Cells more than this (m) above the provisional DTM are not grown into
        (bridge decks, roofs reached along a ramp).
    grow_iters : int
        Growing steps; each reaches at most ``grow_window`` further (bounds the reach).
    """

    cell: Optional[float] = None
    cell_factor: float = 1.0
    cell_min: float = 1.0
    cell_max: float = 1.0
    max_window: float = 18.0
    slope: Optional[float] = None
    slope_factor: float = 0.5
    slope_min: float = 0.1
    slope_max: float = 0.6
    threshold: Optional[float] = None
    threshold_factor: float = 0.35
    threshold_min: float = 0.25
    threshold_max: float = 0.5
    scaler: float = 1.0
    low_step: float = 5.0
    low_window: float = 25.0
    low_share: float = 0.08
    low_noise_depth: float = 1.0
    min_points: int = 10
    refine: int = 3
    fill_radius: float = 3.0
    fill_neighbours: int = 12
    fill_reach: float = 10.0
    trend_window: float = 27.0
    trend_smooth: float = 27.0
    grow: bool = True
    grow_window: float = 3.0
    grow_rms: float = 0.5
    grow_tol: float = 0.1
    grow_max_slope: float = 0.6
    grow_max_rise: float = 2.0
    grow_iters: int = 10

    def __post_init__(self):
        """Refuse non-positive lengths and slopes."""
        if self.trend_window < 0 or self.trend_smooth < 0:
            raise InputError("RecommendedOptions.trend_window and trend_smooth must not be "
                             "negative.")
        for name in ("cell_factor", "cell_min", "cell_max", "max_window", "slope_factor",
                     "slope_min", "slope_max", "threshold_factor", "threshold_min", "threshold_max",
                     "low_step", "low_noise_depth",
                     "low_window", "low_share",
                     "fill_radius", "fill_reach", "grow_window", "grow_rms", "grow_tol",
                     "grow_max_slope", "grow_max_rise"):
            if not getattr(self, name) > 0:
                raise InputError("RecommendedOptions.{name} must be positive.", name=name)
        for name in ("cell", "slope", "threshold"):
            v = getattr(self, name)
            if v is not None and not v > 0:
                raise InputError("RecommendedOptions.{name} must be positive or None "
                                 "(derived from the cloud).", name=name)
        if self.max_window > MAX_WINDOW_LIMIT:
            raise InputError(
                "The largest window (MAX_WINDOW, {value} m) must be at most {limit} m: it "
                "needs only to exceed the largest building, and every cell of it costs one "
                "more pass over the raster. Give e.g. 18 (the default) or the size of the "
                "largest building plus a margin.", value=f"{self.max_window:g}",
                limit=f"{MAX_WINDOW_LIMIT:g}")
        if self.cell_min > self.cell_max or self.threshold_min > self.threshold_max:
            raise InputError("RecommendedOptions: cell_min must not exceed cell_max, nor "
                             "threshold_min threshold_max.")
        if self.min_points < 4 or self.refine < 0 or self.grow_iters < 0:
            raise InputError("min_points must be at least 4, refine and grow_iters at "
                             "least 0.")
        if self.fill_neighbours < 1:
            raise InputError("RecommendedOptions.fill_neighbours must be at least 1.")


def derive(x, y, opt: RecommendedOptions, density=None) -> RecommendedOptions:
    """Options with the cell size and height tolerance filled in from the density.

    Parameters
    ----------
    x, y : ndarray
        Coordinates (m).
    opt : RecommendedOptions
        Options; ``cell=None`` is derived.
    density : float, optional
        Points per m² (the whole cloud's, :mod:`._summary`); default: of x, y.

    Returns
    -------
    RecommendedOptions
        ``opt`` with ``cell`` and ``threshold`` set.
    """
    if opt.cell is not None and opt.threshold is not None:
        return opt
    spacing = 1.0 / np.sqrt(density or R.density(x, y))      # every point, world 5 m cells
    cell = float(np.clip(opt.cell_factor * spacing, opt.cell_min, opt.cell_max))
    thr = float(np.clip(opt.threshold_factor * spacing, opt.threshold_min,
                        opt.threshold_max))
    return replace(opt, cell=opt.cell or cell,
                   threshold=thr if opt.threshold is None else opt.threshold)


def classify(x, y, z, *, return_number=None, number_of_returns=None, options=None,
             progress=None, cancel=None, origin=None, info=None, keep=None,
             extent=None) -> np.ndarray:
    """Classify ground with the recommended, cloud-adaptive morphological filter.

    Parameters
    ----------
    x, y, z : array_like of float
        Coordinates in a projected CRS, metres.
    return_number, number_of_returns : array_like of int, optional
        Accepted for API symmetry (ISPRS samples carry none); unused.
    options : RecommendedOptions, optional
        Parameters; ``None`` fields are derived from the cloud.
    progress : callable(float), optional
        Receives the fraction done in [0, 1].
    cancel : callable() -> bool, optional
        Polled between steps; when it returns True, :class:`Cancelled` is raised.
    origin : (float, float), optional
        Anchors the raster on the lattice through this point (catalog chunks equal
        the merged cloud); default: the cloud's lower-left corner.

    info : dict, optional
        Filled with what was derived (options with the cell, grid, low cells, slope
        tolerance, object cells) for the report (:mod:`._recommended_filter`).
    keep : ndarray of bool, optional
        The points to classify: the others take no part (their classes are garbage).
    extent : tuple, optional
        ``(lowest x, lowest y, highest x, highest y)`` of those points when the caller
        has it (``_checks.bounds``; not taken again).

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

    Examples
    --------
    >>> cls = classify(x, y, z)                                   # doctest: +SKIP
    >>> cls = classify(x, y, z, options=RecommendedOptions(max_window=30))  # doctest: +SKIP
    """
    opt = _options(options, RecommendedOptions)
    x, y, z = R.checked_xyz(x, y, z, opt.min_points, keep, extent)
    ext = extent if extent is not None else R.bounds(x, y, keep)   # for the grid
    # progress steps (22 in the openings) hand no pages back: each malloc_trim there made
    # the next step fault the same pages in again; the trims that keep the peak are below
    rep = Monitor(progress, cancel).step
    rep(0.0)
    opt = derive(x, y, opt) if keep is None else derive(x[keep], y[keep], opt) \
        if opt.cell is None or opt.threshold is None else opt
    grid = R.Grid.around(x, y, opt.cell, origin, keep, ext)
    pc = R.PointCells(x, y, grid, keep)
    base = pc.height_base(z)          # rasters of heights above it, in float32 (R.HEIGHT)
    rep(0.3)
    need = pc.read_mask()
    n = int(x.size if keep is None else keep.sum())
    if info is not None:
        info.update(options=opt, n=n, grid=grid)
    # sparse (the rasters set the peak): the per-point look-ups are not held through the
    # rasters (rebuilt: the same arrays), ``need`` kept as bits; dense: held (an argsort,
    # 0.25 s CPU per 4 M points) and the openings chained (two rasters more)
    dense = grid.rows * grid.cols < n
    zmin = R.OccupiedMinima(pc.cell_min(z, base=base), pc.cells, uses=2)  # remade to grow
    held = pc if dense else None
    del pc
    if not dense:
        bits, shape = np.packbits(need), need.shape
        del need
        need = lambda: np.unpackbits(bits, count=shape[0] * shape[1]).view(bool).reshape(shape)  # noqa: E731
    dtm = surface(zmin.raster(), grid, opt, rep, need=need, info=info, remake=zmin.raster,
                  dense=dense)
    del zmin
    dense or _trim()
    need = need() if callable(need) else need
    pc = held if dense else R.PointCells(x, y, grid, keep)
    rep(0.8)
    last = {}             # the refine passes change few cells: few points relabelled
    cls = label_points(z, dtm, pc, opt, last, base)
    del dtm
    held, pc = [pc], None
    cls = _refine(x, y, z, cls, last, held, grid, opt, need, base, keep, dense, rep)
    rep(1.0)
    return cls


def _refine(x, y, z, cls, last, held, grid, opt, need, base, keep, dense, rep):
    """Step 8 (``held = [PointCells]``: sparse, it is dropped through each fill)."""
    pc = held.pop()
    cache = {}            # the refine fills change few cells: each keeps most of the last
    flipped = None        # the points that turned ground or not in the last labelling:
    for k in range(int(opt.refine)):
        rep(0.8 + 0.2 * (k + 1) / (opt.refine + 1))
        dense or _trim()                             # the labelling's pages back
        ground = cls == GROUND
        if flipped is not None and cache.get("out") is last["dtm"]:   # the last fill's valid
            cells, values = pc.minima_of(z, ground, flipped, base)    # cells, the flipped
            pc = pc if dense else None                                # points' cells new
            zg = np.where(cache["valid"], last["dtm"], np.nan)        # (R.PointCells.cell_min)
            zg.ravel()[cells] = values
            del cells, values
        else:                    # first pass: most cells change, every point is labelled
            zg = pc.cell_min(z, ground, base=base)   # (the same classes): the surface's DTM
            last.clear()                             # is not held through the fill
        pc, ground = (pc if dense else None), None   # sparse: not held through the fill
        zg = fill_holes(zg, ~np.isnan(zg), grid, opt, need, cache, overwrite=True,
                        trim=not dense)
        moved = None
        if last:                                     # the last DTM not held further
            moved, last["dtm"] = R.changed(last["dtm"], zg), None
        dense or _trim()                             # dense: small rasters, no trims
        pc = pc if dense else R.PointCells(x, y, grid, keep)
        was, cls = cls, label_points(z, zg, pc, opt, last, base, moved=moved)
        if k + 1 < opt.refine:
            flipped = (was == GROUND) != (cls == GROUND)
            flipped = np.flatnonzero(flipped if keep is None else flipped & keep)
        del was, moved
    return cls


def surface(zmin, grid, opt, rep, need=None, info=None, cache=None, remake=None,
            dense=False):
    """Provisional bare-earth raster from the minimum surface (steps 2-6).

    Object, low and empty cells are filled by :func:`fill_holes`.

    Parameters
    ----------
    zmin : ndarray
        Minimum-z raster (NaN where empty).
    grid : Grid
        Its grid.
    opt : RecommendedOptions
        Options with ``cell`` set.
    rep : callable
        Progress step (checks cancel).
    need : ndarray of bool, optional
        Cells the caller reads (others may stay NaN).
    info : dict, optional
        Receives what was derived (``lows``, ``slope``, ``objects``).
    cache : dict, optional
        Hole-fill neighbour cache shared with later fills (:func:`fill_holes`).
    remake : callable, optional
        ``remake()`` returns ``zmin`` again: ``zmin`` is then used as scratch space and
        dropped through the openings (one raster less held), and the caller must hold
        no other reference to it.
    dense : bool
        Fewer cells than points: openings chained (:func:`._openings.openings`), the
        other openings and closings by tables (the same bits, faster), no trims.

    Returns
    -------
    ndarray
        The provisional DTM.
    """
    skip = np.isnan(zmin)                            # empty cells, then low outliers too
    outside = outside_hull(~skip) if skip.any() else None
    own = None if info is None else info.get("canopy_owned")   # a catalog chunk's tally
    lows = L.low_cells(zmin, grid.cell, step=opt.low_step, window=opt.low_window,
                       share=opt.low_share, anchor=grid.anchor,  # a catalog's factor
                       factor=None if info is None else info.get("canopy_factor"),
                       tables=dense,                     # dense: faster closings
                       owned=None if own is None else partial(own, grid))
    skip |= lows.low                                 # never ground, nor grown into
    info is not None and info.update(lows=lows)
    del lows
    dense or _trim()
    keep = ~skip
    zf = R.fill(zmin, keep, grid.anchor, overwrite=remake is not None)
    zmin = None if remake is not None else zmin      # zf's buffer: remade to grow
    R.floor_steps(zf, keep, wall_step(grid.cell, opt))
    del keep
    dense or _trim()
    slope = opt.slope if opt.slope is not None else terrain_slope(zf, grid, opt, outside,
                                                                  dense)
    dense or _trim()
    if opt.trend_window > 0 and opt.trend_smooth > 0:
        trend_surface(zf, grid, opt, True, outside, dense)   # zf: the fill's own array
        dense or _trim()
    obj = progressive_objects(zf, grid.cell, opt.max_window, slope, rep, True, outside, dense)
    del zf, outside
    dense or _trim()                                 # the openings' pages back before growing
    if np.ndim(slope):                               # the report reads min / median / max
        slope = None if info is None else np.array(  # median: partitions in place, no copy
            (slope.min(), np.median(slope, overwrite_input=True), slope.max()))
    if zmin is None:
        zmin = remake()
    if opt.grow and opt.grow_iters > 0:
        def dtm_at(read, ground):
            dense or _trim()                         # the planes' pages back before the fill
            return _fill_at(zmin, ground, read, grid, opt, cache, remake is not None, dense)
        obj = grow_ground(zmin, obj, skip, dtm_at, grid.cell, opt)
        dense or _trim()
    if info is not None:
        info.update(slope=slope, objects=obj)
    good = obj | skip                                # the bad cells, negated in place
    if good.all():
        good = skip
    np.logical_not(good, out=good)
    del obj, skip                                    # (the report's are in info)
    need = need() if callable(need) else need
    return fill_holes(zmin, good, grid, opt, need, cache, overwrite=remake is not None,
                      trim=not dense)


def _fill_at(z, valid, read, grid, opt, cache, own, dense=False):
    """:func:`fill_holes` of ``z`` at the cells ``read`` only (``np.flatnonzero`` order).

    With ``own`` (``z`` is ours) the fill is made in ``z``'s own buffer, no cache, and
    the cells ``read`` get their values back: ``z`` is unchanged at its valid cells and
    at ``read``, the cells the growing step reads (one raster less).
    """
    at = np.flatnonzero(read)
    if not own:
        return fill_holes(z, valid, grid, opt, read, cache, trim=not dense).ravel()[at]
    flat = z.ravel()
    kept = flat[at]
    out = fill_holes(z, valid, grid, opt, read, overwrite=True, trim=not dense).ravel()[at]
    flat[at] = kept
    return out


def fill_holes(z, valid, grid, opt, need=None, cache=None, overwrite=False, trim=True):
    """Fill the non-ground cells of a DTM raster with border tangent planes.

    Parameters
    ----------
    z : ndarray
        Raster of ground heights (NaN or anything where not ``valid``).
    valid : ndarray of bool
        Ground cells.
    grid : Grid
        Its grid.
    opt : RecommendedOptions
        Options (``fill_radius``, ``fill_neighbours``, ``fill_reach``).
    need : ndarray of bool, optional
        Cells that are read; other invalid cells stay NaN.
    cache : dict, optional
        Shared by the fills of one run: a hole cell keeps the neighbours of the
        previous fill where no border changed near it (identical values, fewer
        KD-tree searches).
    overwrite : bool
        Fill ``z`` in place (its invalid cells).
    trim : bool
        Hand the fill's freed pages back before its batches (sparse clouds; a dense
        cloud's peak is its points', and pages handed back are faulted in again).

    Returns
    -------
    ndarray
        The filled raster (:func:`._surface.tangent_fill`).
    """
    return S.tangent_fill(z, valid, grid.cell,
                          radius=max(1, int(round(opt.fill_radius / grid.cell))),
                          neighbours=opt.fill_neighbours, reach=opt.fill_reach, need=need,
                          cache=cache, overwrite=overwrite, trim=trim)


def recommended_filter(options: Optional[RecommendedOptions] = None):
    """Return the recommended filter as a pipeline algorithm object.

    Parameters
    ----------
    options : RecommendedOptions, optional
        Parameters (defaults when None).

    Returns
    -------
    RecommendedFilter
        Name ``groundfilter`` (:mod:`._recommended_filter`: reports what was derived).
    """
    from ._recommended_filter import RecommendedFilter
    return RecommendedFilter(options or RecommendedOptions())

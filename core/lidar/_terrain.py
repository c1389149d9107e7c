"""Large-scale terrain of the recommended filter: trend and slope tolerance (private).

Both come from a wide opening of the filled minimum raster (numpy/scipy only); moved
from :mod:`._surface` (module size), code unchanged.
"""
from __future__ import annotations

import numpy as np

from . import _raster as R  # noqa: N812

__all__ = ["terrain_slope", "trend_surface"]


def trend_surface(zf, grid, opt, subtract=False):
    """Smooth large-scale terrain trend removed before the progressive opening.

    Opening ``z - trend`` and adding the trend back is an opening whose flat
    structuring element is tilted along the regional slope (a plane is removed
    exactly, objects keep their height above it), so on hillsides the opening and its
    slope tolerance act on the height above the regional terrain rather than the
    height above a horizontal. The trend is the opening of radius ``trend_window``
    (1.5 x the default largest window, wider than any object), box-averaged over
    ``2 * trend_smooth + 1`` cells. Measured on the ISPRS samples it mostly helps the
    steep urban samp11 (at the defaults Type II 13.7 % instead of 17.2 %, total
    8.92 % instead of 9.89 %).

    Parameters
    ----------
    zf : ndarray
        Filled minimum raster.
    grid : Grid
        Its grid.
    opt : RecommendedOptions
        Options (``trend_window``, ``trend_smooth``).
    subtract : bool
        Subtract the trend from ``zf`` in place, band by band, and return ``zf`` (the
        trend raster is never held whole).

    Returns
    -------
    ndarray
        The trend raster (or ``zf - trend``).
    """
    r = max(1, int(np.ceil(opt.trend_window / grid.cell)))
    k = 2 * max(1, int(np.ceil(opt.trend_smooth / grid.cell))) + 1
    return R.box_mean(R.opening(zf, r), k, subtract_from=zf if subtract else None)


def terrain_slope(zf, grid, opt):
    """Per-cell slope tolerance from the terrain under a large-window opening.

    The opening with the largest window removes objects; its gradient, averaged over
    that window, is the local terrain slope t. Tolerance = clip(slope_factor * t,
    slope_min, slope_max): flat towns keep ``slope_min``, steep terrain gets more.

    Parameters
    ----------
    zf : ndarray
        Filled minimum raster.
    grid : Grid
        Its grid.
    opt : RecommendedOptions
        Options.

    Returns
    -------
    ndarray
        Slope tolerance per cell (rise/run).
    """
    r = max(1, int(np.ceil(opt.max_window / grid.cell)))
    t = R.slope(R.opening(zf, r), grid.cell, dtype=zf.dtype)     # float32 rasters: float32
    t = R.box_mean(t, 2 * r + 1)
    t *= opt.slope_factor
    return np.clip(t, opt.slope_min, opt.slope_max, out=t)


def wall_step(cell, opt):
    """Height difference across one filled cell that no tolerated slope explains (m).

    Two occupied cells 2 cells apart on a slope of at most the largest slope tolerance
    differ by ``2 x cell x slope`` plus the vertical tolerance; more is a wall
    (:func:`._raster.floor_steps`).
    """
    s = opt.slope if opt.slope is not None else opt.slope_max
    return 2.0 * cell * s + opt.threshold

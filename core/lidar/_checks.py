"""The one input check of every ground filter (private; re-exported by :mod:`._raster`)."""
from __future__ import annotations

import numpy as np

from ..errors import InputError


def checked_xyz(x, y, z, min_points: int, keep=None, extent=None):
    """Coordinates as float64 arrays, refused when unusable by a ground filter.

    Parameters
    ----------
    x, y, z : array_like
        Coordinates in a projected CRS (m).
    min_points : int
        Fewest points accepted.
    keep : ndarray of bool, optional
        The points the filter classifies (the counts below are theirs; every point given
        must still be finite and projected).
    extent : tuple, optional
        :func:`bounds` of the kept points when the caller has it (not taken again).

    Returns
    -------
    tuple of ndarray
        ``x, y, z`` (contiguous float64).

    Raises
    ------
    ValueError
        Unequal lengths or non-finite values (:func:`~..coords.as_xyz`).
    InputError
        Too few points, a single xy position, or coordinates in degrees.
    """
    from ..coords import as_xyz
    x, y, z = as_xyz(x, y, z, projected=True)
    check_filter_points(x, y, min_points, keep, extent)
    return x, y, z


def bounds(x, y, keep=None) -> tuple:
    """``(lowest x, lowest y, highest x, highest y)`` of the points (at ``keep`` only).

    Taken once by the recommended filter and handed to the steps that need it (its
    summary, water test, check and grid: four passes instead of eighteen). None when no
    point is kept (the steps then refuse or skip the cloud as they would alone).
    """
    if not (np.size(x) if keep is None else keep.any()):
        return None
    return lowest(x, keep), lowest(y, keep), highest(x, keep), highest(y, keep)


def lowest(v, keep=None) -> float:
    """Smallest value of ``v`` (at ``keep`` only: the minimum of ``v[keep]``, no copy)."""
    return float(v.min() if keep is None else np.min(v, where=keep, initial=np.inf))


def highest(v, keep=None) -> float:
    """Largest value of ``v`` (at ``keep`` only, no copy)."""
    return float(v.max() if keep is None else np.max(v, where=keep, initial=-np.inf))


def check_filter_points(x, y, min_points: int, keep=None, extent=None) -> None:
    """Refuse fewer than ``min_points`` points, or points all at one x/y position.

    The one check of every ground filter (:func:`checked_xyz`, the slope filter);
    ``keep`` (bool per point): of those points only; ``extent``: theirs (:func:`bounds`),
    when the caller has it.

    Raises
    ------
    InputError
        With the counts and the fix.
    """
    x = np.asarray(x)
    y = np.asarray(y)
    n = x.size if keep is None else int(np.count_nonzero(keep))
    if n < min_points:
        raise InputError("A ground filter needs at least {min_points} points, got "
                         "{n}: give a cloud that covers the ground area, or select more "
                         "returns / classes.", min_points=min_points, n=n)
    e = extent
    spread = max(e[2] - e[0], e[3] - e[1]) if e is not None else \
        max(highest(v, keep) - lowest(v, keep) for v in (x, y))
    if spread <= 0.0:
        raise InputError("All {n} points share one x/y position, so there is no terrain "
                         "to compare them with: give a cloud whose points cover the ground "
                         "area.", n=n)

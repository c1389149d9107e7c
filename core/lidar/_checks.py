"""The one input check of every ground filter (private; re-exported by :mod:`._raster`)."""
from __future__ import annotations

import numpy as np

from ..errors import InputError


def checked_xyz(x, y, z, min_points: int, keep=None):
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
    check_filter_points(x, y, min_points, keep)
    return x, y, z


def lowest(v, keep=None) -> float:
    """Smallest value of ``v`` (at ``keep`` only: the minimum of ``v[keep]``, no copy)."""
    return float(v.min() if keep is None else np.min(v, where=keep, initial=np.inf))


def highest(v, keep=None) -> float:
    """Largest value of ``v`` (at ``keep`` only, no copy)."""
    return float(v.max() if keep is None else np.max(v, where=keep, initial=-np.inf))


def check_filter_points(x, y, min_points: int, keep=None) -> None:
    """Refuse fewer than ``min_points`` points, or points all at one x/y position.

    The one check of every ground filter (:func:`checked_xyz`, the slope filter);
    ``keep`` (bool per point): of those points only.

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
    spread = max(highest(v, keep) - lowest(v, keep) for v in (x, y))
    if spread <= 0.0:
        raise InputError("All {n} points share one x/y position, so there is no terrain "
                         "to compare them with: give a cloud whose points cover the ground "
                         "area.", n=n)

"""Kriging basics shared by :mod:`.kriging` and its system (private).

The variogram models (PyKrige's conventions), the :class:`Variogram` record, input checks
and the merging of duplicate positions.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Dict, List, Optional, Tuple

import numpy as np

from ..coords import as_xyz
from ..errors import InputError
from . import variogram as variogram_models

MODELS = ("linear", "power", "gaussian", "spherical", "exponential")
DRIFTS = ("none", "linear")
#: PyKrige's "zero distance" tolerance (exact interpolation at data points)
EPS = 1e-10
#: global (single-system) solve when all points are neighbours and n is at most this
GLOBAL_MAX_POINTS = 6000


def variogram_function(model: str):
    """Return the variogram function ``f(params, d)`` of ``model`` (PyKrige's convention)."""
    funcs = variogram_models.MODEL_FUNCTIONS
    if model not in funcs:
        raise InputError("variogram model must be one of {choices}; got {model}.",
                         choices=", ".join(MODELS), model=repr(model))
    return funcs[model]


@dataclass
class Variogram:
    """A fitted (or given) variogram model in PyKrige's parameter convention.

    ``params`` is ``[slope, nugget]`` (linear), ``[scale, exponent, nugget]`` (power)
    or ``[partial sill, range, nugget]`` (gaussian, spherical, exponential; ``range``
    is the practical range as PyKrige defines it).
    """

    model: str
    params: List[float]
    fitted: bool = False
    n_fit: int = 0
    max_lag: Optional[float] = None
    lags: np.ndarray = field(default_factory=lambda: np.empty(0))
    semivariance: np.ndarray = field(default_factory=lambda: np.empty(0))
    n_pairs: int = 0
    nugget_floored: bool = False

    def __call__(self, d):
        """Return the semivariance at lag distance(s) ``d``."""
        return variogram_function(self.model)(self.params, d)

    @property
    def nugget(self) -> float:
        """Return the nugget (the semivariance at zero lag)."""
        return float(self.params[-1])

    def as_dict(self) -> Dict[str, float]:
        """Named parameters: nugget, sill, partial sill, range (or slope/scale/exponent)."""
        p = [float(v) for v in self.params]
        if self.model == "linear":
            return {"slope": p[0], "nugget": p[1]}
        if self.model == "power":
            return {"scale": p[0], "exponent": p[1], "nugget": p[2]}
        return {"nugget": p[2], "sill": p[0] + p[2], "partial_sill": p[0], "range": p[1]}


def _check_xyz(x, y, z):
    x, y, z = as_xyz(x, y, z, nonfinite="drop")
    if x.size < 3:
        raise InputError("Kriging needs at least 3 points, got {n} (check the class "
                         "filter and the extent).", n=int(x.size))
    return x, y, z


def merge_duplicates(x, y, z) -> Tuple[np.ndarray, np.ndarray, np.ndarray, int]:
    """Merge points with identical (x, y) into one with the mean z.

    Returns ``x, y, z, n_merged`` (number of points removed).
    """
    xy = np.column_stack([x, y])
    uniq, inv = np.unique(xy, axis=0, return_inverse=True)
    if uniq.shape[0] == x.size:
        return x, y, z, 0
    inv = inv.ravel()
    zsum = np.bincount(inv, weights=z, minlength=uniq.shape[0])
    cnt = np.bincount(inv, minlength=uniq.shape[0])
    return uniq[:, 0].copy(), uniq[:, 1].copy(), zsum / cnt, int(x.size - uniq.shape[0])

"""Which points a ground filter sees, and how its answer becomes the output classes.

Shared by every ground filter and every runner (one file, a catalog chunk, a model):

* point selection (:class:`SelectionOptions`): all returns, or last returns only
  (``return_number == number_of_returns``; files without return information count
  every point as a single, hence last, return; first and intermediate returns get
  class 1 and never reject a last return);
* the shared low-outlier pre-filter (:func:`~.noise.flag_low_outliers`, class 7);
* points the input already marks as noise (7, 18) kept as they are
  (``keep_noise_classes``).
"""
from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from .. import classes as asprs
from ..errors import InputError
from .noise import flag_low_outliers

__all__ = ["RETURNS", "SelectionOptions", "Selection", "select_points", "assemble_classes",
           "last_return_mask"]

RETURNS = ("all", "last")


def last_return_mask(return_number, number_of_returns) -> np.ndarray:
    """Return True for last (or single) returns; no return information counts as last.

    >>> last_return_mask([1, 1, 2, 0], [2, 1, 2, 0]).tolist()
    [False, True, True, True]
    """
    rn = np.asarray(return_number).astype(np.int64)
    nr = np.asarray(number_of_returns).astype(np.int64)
    unknown = (rn == 0) | (nr == 0)
    return unknown | (rn >= nr)


@dataclass
class SelectionOptions:
    """Which points a filter sees (shared by every ground filter).

    Parameters
    ----------
    returns : {'all', 'last'}
        Classify every point, or last (and single) returns only.
    noise : bool
        Run the low-outlier pre-filter (:func:`~.noise.flag_low_outliers`) first.
    noise_radius, noise_threshold : float
        Metres; its cell and depth below the neighbours.
    keep_noise_classes : bool
        Points the input marks 7 or 18 keep their class and take no part.
    """

    returns: str = "all"
    noise: bool = True
    noise_radius: float = 5.0
    noise_threshold: float = 1.0
    keep_noise_classes: bool = True

    def __post_init__(self):
        """Refuse an invalid option (InputError naming it)."""
        self.validate()

    def validate(self) -> SelectionOptions:
        """Raise :class:`InputError` on an invalid option; returns self."""
        if self.returns not in RETURNS:
            raise InputError("returns must be 'all' or 'last', got {returns!r}.",
                             returns=self.returns)
        if self.noise and not (self.noise_radius > 0 and self.noise_threshold > 0):
            raise InputError("NOISE_RADIUS and NOISE_THRESHOLD must be > 0 metres (e.g. 5 "
                             "and 1), or switch the NOISE pre-filter off.")
        return self


@dataclass
class Selection:
    """Which points are filtered, and why the others are not."""

    candidates: np.ndarray        # classified and used as neighbours
    low_outliers: np.ndarray      # flagged by the pre-filter (class 7)
    not_last: np.ndarray          # first/intermediate returns in "last" mode (class 1)
    input_noise: np.ndarray       # class 7/18 in the input, kept as they are
    unknown_returns: int = 0


def select_points(pd, *, returns: str = "all", noise: bool = True, noise_radius: float = 5.0,
                  noise_threshold: float = 1.0, keep_noise_classes: bool = True,
                  origin=None, progress=None, cancel=None) -> Selection:
    """Build the candidate set of a ground filter from a :class:`~..io.las.PointData`.

    Parameters
    ----------
    pd : PointData
        Coordinates with ``classification`` (and the return numbers for
        ``returns='last'``).
    returns, noise, noise_radius, noise_threshold, keep_noise_classes
        See :class:`SelectionOptions`.
    origin : (float, float), optional
        Anchors the pre-filter's cells on a global lattice (catalog chunks).
    progress, cancel : callable, optional
        Progress and cancel callables of the noise pre-filter.

    Returns
    -------
    Selection
        The masks of the candidates and of the excluded points.
    """
    SelectionOptions(returns, noise, noise_radius, noise_threshold,
                     keep_noise_classes).validate()
    n = len(pd)
    in_noise = np.zeros(n, dtype=bool)
    if keep_noise_classes and "classification" in pd.dims:
        in_noise = np.isin(pd["classification"], asprs.INPUT_NOISE)
    not_last = np.zeros(n, dtype=bool)
    unknown = 0
    if returns == "last":
        rn, nr = pd["return_number"], pd["number_of_returns"]
        not_last = ~last_return_mask(rn, nr)
        unknown = int(np.count_nonzero((rn == 0) | (nr == 0)))
    base = ~in_noise & ~not_last
    low = np.zeros(n, dtype=bool)
    if noise and base.any():
        idx = np.flatnonzero(base)
        low[idx] = flag_low_outliers(pd.x[idx], pd.y[idx], pd.z[idx], radius=noise_radius,
                                     threshold=noise_threshold, origin=origin,
                                     progress=progress, cancel=cancel)
    cand = base & ~low
    if not cand.any():
        raise InputError("No point is left to filter after the return/noise selection "
                         "({n} points read, {not_last} not last "
                         "returns, {noise} already noise, "
                         "{low} low outliers). Use returns='all' "
                         "or disable the noise pre-filter.",
                         n=n,
                         not_last=int(np.count_nonzero(not_last)),
                         noise=int(np.count_nonzero(in_noise)),
                         low=int(np.count_nonzero(low)))
    return Selection(cand, low, not_last, in_noise, unknown)


def assemble_classes(sel: Selection, candidate_classes: np.ndarray,
                     original=None) -> np.ndarray:
    """Full-length ASPRS classes from the filter's classes of the candidates.

    Parameters
    ----------
    sel : Selection
        The point selection.
    candidate_classes : ndarray of uint8
        One class per candidate (2, 1, 0 or 7).
    original : ndarray, optional
        The input classification (kept for the input's noise points).

    Returns
    -------
    ndarray of uint8
        2 ground, 1 other (and non-last returns), 7 low outliers, input noise kept.
    """
    cls = np.full(sel.candidates.size, asprs.UNCLASSIFIED, dtype=np.uint8)
    cls[sel.candidates] = candidate_classes
    cls[sel.low_outliers] = asprs.LOW_NOISE
    if sel.input_noise.any() and original is not None:
        cls[sel.input_noise] = np.asarray(original)[sel.input_noise]
    return cls

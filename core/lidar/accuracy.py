"""Accuracy of a ground filter against reference labels (ISPRS filter test).

Reference: Sithole, G. & Vosselman, G. (2004). Experimental comparison of filter
algorithms for bare-Earth extraction from airborne laser scanning point clouds.
ISPRS Journal of Photogrammetry and Remote Sensing 59(1-2), 85-101.

Cross matrix (rows = reference, columns = filtered)::

                   filtered ground   filtered object
    ref ground          a                 b
    ref object          c                 d

* Type I error  = b / (a + b)   (ground rejected as object)
* Type II error = c / (c + d)   (object accepted as ground)
* Total error   = (b + c) / n
* Cohen's kappa = (p_o - p_e) / (1 - p_e)
"""
from __future__ import annotations

from dataclasses import asdict, dataclass

import numpy as np

from .. import classes as asprs
from ..errors import InputError

GROUND = int(asprs.GROUND)


@dataclass(frozen=True)
class FilterAccuracy:
    """Cross-matrix counts and the derived errors (percent) and kappa (percent)."""

    a: int
    b: int
    c: int
    d: int

    @property
    def n(self) -> int:
        """Number of points assessed, ``a + b + c + d``."""
        return self.a + self.b + self.c + self.d

    @property
    def type1(self) -> float:
        """Type I error, percent of reference ground rejected."""
        return _pct(self.b, self.a + self.b)

    @property
    def type2(self) -> float:
        """Type II error, percent of reference objects accepted as ground."""
        return _pct(self.c, self.c + self.d)

    @property
    def total(self) -> float:
        """Total error, percent of all points misclassified."""
        return _pct(self.b + self.c, self.n)

    @property
    def kappa(self) -> float:
        """Cohen's kappa in percent (100 = perfect agreement)."""
        n = self.n
        if n == 0:
            return float("nan")
        po = (self.a + self.d) / n
        pe = ((self.a + self.b) * (self.a + self.c)
              + (self.c + self.d) * (self.b + self.d)) / (n * n)
        if pe == 1.0:
            return 100.0 if po == 1.0 else float("nan")
        return 100.0 * (po - pe) / (1.0 - pe)

    def as_dict(self) -> dict:
        """Return counts and metrics as a flat dict (for reports and Processing outputs)."""
        out = asdict(self)
        out.update(n=self.n, type1=self.type1, type2=self.type2,
                   total=self.total, kappa=self.kappa)
        return out


def _pct(num: int, den: int) -> float:
    return 100.0 * num / den if den else float("nan")


def from_counts(a: int, b: int, c: int, d: int) -> FilterAccuracy:
    """Build a :class:`FilterAccuracy` from the four cross-matrix counts.

    Examples
    --------
    The corrected samp54 counts of the LSQ paper:

    >>> acc = from_counts(3924, 54, 294, 4324)
    >>> round(acc.type1, 3), round(acc.type2, 3), round(acc.total, 3)
    (1.357, 6.366, 4.048)
    """
    for name, v in (("a", a), ("b", b), ("c", c), ("d", d)):
        if int(v) != v or v < 0:
            raise InputError("count {name} must be a non-negative integer, got {value}.",
                             name=name, value=v)
    return FilterAccuracy(int(a), int(b), int(c), int(d))


def assess(predicted_ground, reference_ground) -> FilterAccuracy:
    """Compare filtered labels with reference labels.

    Parameters
    ----------
    predicted_ground, reference_ground : array_like of bool
        Per-point "is ground" flags, same length and order. To compare ASPRS
        classification arrays use :func:`ground_mask` first (class 2 = ground).

    Returns
    -------
    FilterAccuracy

    Raises
    ------
    ValueError
        If the arrays differ in length or are empty.
    """
    p = np.asarray(predicted_ground, dtype=bool).ravel()
    r = np.asarray(reference_ground, dtype=bool).ravel()
    if p.size != r.size:
        raise InputError(
            "The classified cloud has {n} points but the reference has {m}; "
            "both must hold the same points in the same order.", n=int(p.size), m=int(r.size))
    if p.size == 0:
        raise InputError("Cannot assess an empty point cloud.")
    a = int(np.count_nonzero(p & r))
    b = int(np.count_nonzero(~p & r))
    c = int(np.count_nonzero(p & ~r))
    d = int(p.size - a - b - c)
    return FilterAccuracy(a, b, c, d)


def ground_mask(classification, ground_classes=(GROUND,)) -> np.ndarray:
    """Boolean mask of points whose class is one of ``ground_classes``."""
    return np.isin(np.asarray(classification), np.asarray(ground_classes))


def error_codes(predicted_ground, reference_ground) -> np.ndarray:
    """Per-point error code: 0 correct, 1 Type I (ground lost), 2 Type II (object kept).

    Useful as a per-point error layer for mapping where a filter fails.
    """
    p = np.asarray(predicted_ground, dtype=bool)
    r = np.asarray(reference_ground, dtype=bool)
    if p.shape != r.shape:
        raise InputError("predicted has {n} points, reference {m}; they must match point "
                         "for point.", n=int(p.size), m=int(r.size))
    out = np.zeros(p.shape, dtype=np.uint8)
    out[r & ~p] = 1
    out[~r & p] = 2
    return out

"""Validation of point coordinates shared by every filter and gridder."""
from __future__ import annotations

from typing import Optional, Tuple

import numpy as np


def as_xyz(x, y, z, *, nonfinite: str = "raise",
           empty_error: Optional[str] = None) -> Tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Coordinates as three contiguous 1-D float64 arrays of equal length.

    Parameters
    ----------
    x, y, z : array_like
        Point coordinates.
    nonfinite : {'raise', 'drop'}
        What to do with points that have a NaN or infinite coordinate: refuse them with
        a ``ValueError`` that counts them (default), or leave them out.
    empty_error : str, optional
        When given, an empty result raises ``ValueError(empty_error)``.

    Raises
    ------
    ValueError
        Arrays of different lengths, non-finite coordinates (``nonfinite='raise'``), or
        no points (with ``empty_error``).
    """
    if nonfinite not in ("raise", "drop"):
        raise ValueError(f"nonfinite must be 'raise' or 'drop', got {nonfinite!r}.")
    x, y, z = (np.ascontiguousarray(v, dtype=np.float64).ravel() for v in (x, y, z))
    if not (x.size == y.size == z.size):
        raise ValueError(f"x, y and z must have the same length (got {x.size}, {y.size}, "
                         f"{z.size}).")
    ok = np.isfinite(x) & np.isfinite(y) & np.isfinite(z)
    if not ok.all():
        if nonfinite == "raise":
            raise ValueError(
                f"{int(np.count_nonzero(~ok))} point(s) have non-finite (NaN or infinite) "
                "coordinates; remove or repair them (e.g. PDAL filters.range) first.")
        x, y, z = x[ok], y[ok], z[ok]
    if empty_error is not None and x.size == 0:
        raise ValueError(empty_error)
    return x, y, z

"""Validation of point coordinates shared by every filter and gridder.

* :func:`as_xyz` — three contiguous float64 arrays, finite, same length;
* :func:`check_projected` — refuses clouds in geographic degrees (a geographic CRS, or
  coordinates that look like longitude/latitude), which every metric filter and
  gridder would otherwise process silently and wrongly (a 50 m tile would span the
  whole planet, a 1 m DTM cell would be one pixel).
"""
from __future__ import annotations

from typing import Optional, Tuple

import numpy as np

from .errors import InputError

#: Largest horizontal extent (coordinate units) of a cloud taken for lon/lat degrees.
DEGREE_EXTENT = 5.0
#: ... when its height range exceeds this many times its horizontal extent.
DEGREE_Z_RATIO = 10.0

REPROJECT_HINT = (
    "Reproject it to a projected CRS in metres first, e.g. "
    "'pdal translate in.laz out.laz reprojection "
    "--filters.reprojection.out_srs=EPSG:326xx' (the UTM zone of the area; 327xx south "
    "of the equator), las2las -target_epsg 326xx, or QGIS 'Reproject' on a "
    "point-cloud layer.")


def as_xyz(x, y, z, *, nonfinite: str = "raise", empty_error: Optional[str] = None,
           projected: bool = False) -> Tuple[np.ndarray, np.ndarray, np.ndarray]:
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
    projected : bool, default False
        Also refuse coordinates that look like geographic degrees
        (:func:`check_projected`).

    Returns
    -------
    tuple of ndarray
        ``x, y, z``.

    Raises
    ------
    ValueError
        Arrays of different lengths, non-finite coordinates (``nonfinite='raise'``), or
        no points (with ``empty_error``); :class:`~.errors.InputError` for degrees.
    """
    if nonfinite not in ("raise", "drop"):
        raise InputError("nonfinite must be 'raise' or 'drop', got {value}.",
                         value=repr(nonfinite))
    x, y, z = (np.ascontiguousarray(v, dtype=np.float64).ravel() for v in (x, y, z))
    if not (x.size == y.size == z.size):
        raise InputError("x, y and z must have the same length (got {nx}, {ny}, {nz}).",
                         nx=int(x.size), ny=int(y.size), nz=int(z.size))
    ok = np.isfinite(x) & np.isfinite(y) & np.isfinite(z)
    if not ok.all():
        if nonfinite == "raise":
            raise InputError(
                "{n} point(s) have non-finite (NaN or infinite) "
                "coordinates; remove or repair them (e.g. PDAL filters.range) first.",
                n=int(np.count_nonzero(~ok)))
        x, y, z = x[ok], y[ok], z[ok]
    if empty_error is not None and x.size == 0:
        raise InputError(empty_error)
    if projected:
        check_projected(x, y, z)
    return x, y, z


def crs_is_geographic(crs: Optional[str]) -> bool:
    """Return True when ``crs`` is a geographic (degree) CRS (:func:`~.io.crs.is_geographic`).

    Unknown or unparsable CRSs return False (nothing to refuse).
    """
    from .io.crs import is_geographic
    try:
        return bool(crs) and bool(is_geographic(crs))
    except ValueError:
        return False


def looks_like_degrees(x, y, z) -> bool:
    """Return True when coordinates look like longitude/latitude degrees with metric z.

    The rule: every ``|x| ≤ 180`` and ``|y| ≤ 90``, a horizontal extent under
    :data:`DEGREE_EXTENT` units, and a height range more than :data:`DEGREE_Z_RATIO`
    times that extent (a 100 m wide survey spans 0.001°, its heights metres).
    """
    x, y, z = (np.asarray(v, dtype=np.float64) for v in (x, y, z))
    if x.size < 2:
        return False
    xmin, xmax, ymin, ymax = x.min(), x.max(), y.min(), y.max()
    if max(abs(xmin), abs(xmax)) > 180 or max(abs(ymin), abs(ymax)) > 90:
        return False
    extent = max(xmax - xmin, ymax - ymin)
    return bool(extent < DEGREE_EXTENT and (z.max() - z.min()) > DEGREE_Z_RATIO * extent)


def check_projected(x=None, y=None, z=None, *, crs: Optional[str] = None,
                    what: str = "The point cloud") -> None:
    """Refuse a cloud in geographic degrees with a message that says how to reproject.

    Parameters
    ----------
    x, y, z : array_like, optional
        Coordinates checked with :func:`looks_like_degrees` (skipped when None).
    crs : str, optional
        The cloud's CRS (from the LAS header), checked with :func:`crs_is_geographic`.
    what : str
        How the message names the data.

    Raises
    ------
    InputError
        When the CRS is geographic or the coordinates look like degrees.
    """
    if crs_is_geographic(crs):
        raise InputError("{what} is in a geographic CRS (longitude/latitude in degrees); "
                         "distances, tiles and slopes need metres. {hint}",
                         what=what,
                         hint=REPROJECT_HINT)
    if x is not None and looks_like_degrees(x, y, z):
        raise InputError("{what} looks like longitude/latitude in degrees (x within ±180, "
                         "y within ±90, a horizontal extent of a few units and heights in "
                         "metres); distances, tiles and slopes need metres. "
                         "{hint}", what=what, hint=REPROJECT_HINT)


#: Largest mean point spacing (m) over a cloud's bounding box a ground filter accepts:
#: airborne LiDAR has 0.5–50 points per m² (spacings of 0.14–1.4 m); one point per
#: 50 m × 50 m is no terrain sample, and the filters' rasters would cover the whole box.
MAX_MEAN_SPACING = 50.0


def check_not_too_sparse(x, y, *, what: str = "The point cloud",
                         max_spacing: float = MAX_MEAN_SPACING) -> None:
    """Refuse a cloud whose points are spread far too thin over its bounding box.

    A thousand points over 15 km² (or a few stray points kilometres away from the
    survey) would make every grid cover the whole box — minutes and gigabytes for
    nothing. Coordinates in metres.

    Raises
    ------
    InputError
        Naming the count, the area, the spacing and the fix.
    """
    x = np.asarray(x, dtype=np.float64)
    y = np.asarray(y, dtype=np.float64)
    if x.size < 2:
        return
    area = float(np.ptp(x)) * float(np.ptp(y))
    spacing = (area / x.size) ** 0.5
    if spacing > max_spacing:
        raise InputError(
            "{what} holds {n} points over {km2} km² of bounding box: a mean spacing of "
            "{s} m, far sparser than airborne LiDAR (spacings under {max} m). Check for "
            "stray points far from the survey or wrong coordinates, and crop the cloud "
            "to the surveyed area. No output was written.", what=what, n=f"{x.size:,}",
            km2=f"{area / 1e6:.2f}", s=f"{spacing:.0f}", max=f"{max_spacing:g}")

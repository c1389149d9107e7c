"""Vertical accuracy of a DTM against independent check points.

The DTM is sampled at each check point (bilinear by default, nearest cell as an
option) and the error ``e = z_DTM − z_check`` is summarised:

* N, mean error (ME, bias), mean absolute error (MAE), RMSE = sqrt(Σe²/N), standard
  deviation (N − 1), min/max error, max |e|;
* Pearson r between DTM and check heights, R² = r² (the spec's "r" of the seed
  paper, 0.9986 for IDW p = 3);
* NMAD = 1.4826 · median(|e − median(e)|), the robust spread recommended for DEM
  errors that are not normally distributed (Höhle & Höhle 2009);
* vertical accuracy at 95 % confidence = 1.96 · RMSE (ASPRS 2014, non-vegetated
  vertical accuracy, which assumes normally distributed errors without bias), and the
  95th percentile of |e| (the ASPRS measure for vegetated terrain).

Check points outside the DTM or falling on nodata are **counted and excluded** (never
read as 0); the counts are part of the result.

Bilinear sampling uses the four cell centres around the point; points in the outer
half cell are clamped to the edge row/column; a point whose own cell is nodata is
excluded; when only some of the four neighbours are nodata the weights are
renormalised over the valid ones (counted as ``n_partial``).

References
----------
ASPRS (2015). ASPRS Positional Accuracy Standards for Digital Geospatial Data,
Edition 1, Version 1.0 (November 2014). PE&RS 81(3), A1–A26.
Höhle, J., Höhle, M. (2009). Accuracy assessment of digital elevation models by means
of robust statistical methods. ISPRS J. Photogramm. Remote Sens. 64(4), 398–406.
"""
from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Dict, Optional, Sequence

import numpy as np

from ..errors import InputError

OK, OUTSIDE, NODATA = 0, 1, 2
STATUS_NAMES = {OK: "used", OUTSIDE: "outside DTM", NODATA: "DTM nodata"}
METHODS = ("bilinear", "nearest")


def sample_raster(data: np.ndarray, geotransform: Sequence[float], x, y, *,
                  method: str = "bilinear"):
    """Sample a north-up raster (NaN = nodata) at points.

    Returns
    -------
    values : ndarray
        Sampled heights (NaN where not available).
    status : ndarray of int
        0 used, 1 outside the raster, 2 on nodata.
    partial : ndarray of bool
        Bilinear estimates that renormalised over fewer than 4 valid cells.
    """
    if method not in METHODS:
        raise InputError("method must be 'bilinear' or 'nearest', got {value}.",
                         value=repr(method))
    data = np.asarray(data, dtype=np.float64)
    x = np.asarray(x, dtype=np.float64).ravel()
    y = np.asarray(y, dtype=np.float64).ravel()
    gt = tuple(float(v) for v in geotransform)
    if gt[2] != 0 or gt[4] != 0 or gt[1] <= 0 or gt[5] >= 0:
        raise InputError("Only north-up rasters are supported (geotransform {gt}).", gt=gt)
    nrows, ncols = data.shape
    fc = (x - gt[0]) / gt[1]               # fractional column (0 at the west edge)
    fr = (y - gt[3]) / gt[5]               # fractional row (0 at the north edge)
    inside = (fc >= 0) & (fc <= ncols) & (fr >= 0) & (fr <= nrows) & np.isfinite(fc + fr)
    col = np.clip(np.floor(np.where(inside, fc, 0)).astype(np.int64), 0, ncols - 1)
    row = np.clip(np.floor(np.where(inside, fr, 0)).astype(np.int64), 0, nrows - 1)
    own = data[row, col]
    status = np.full(x.size, OK, dtype=np.int8)
    status[~inside] = OUTSIDE
    status[inside & ~np.isfinite(own)] = NODATA
    values = np.where(status == OK, own, np.nan)
    partial = np.zeros(x.size, bool)
    if method == "nearest":
        return values, status, partial
    u = np.clip(np.where(inside, fc, 0) - 0.5, 0, ncols - 1)
    v = np.clip(np.where(inside, fr, 0) - 0.5, 0, nrows - 1)
    c0 = np.minimum(np.floor(u).astype(np.int64), max(ncols - 2, 0))
    r0 = np.minimum(np.floor(v).astype(np.int64), max(nrows - 2, 0))
    c1 = np.minimum(c0 + 1, ncols - 1)
    r1 = np.minimum(r0 + 1, nrows - 1)
    du, dv = u - c0, v - r0
    num = np.zeros(x.size)
    den = np.zeros(x.size)
    nvalid = np.zeros(x.size, np.int64)
    for rr, cc, w in ((r0, c0, (1 - du) * (1 - dv)), (r0, c1, du * (1 - dv)),
                      (r1, c0, (1 - du) * dv), (r1, c1, du * dv)):
        val = data[rr, cc]
        ok = np.isfinite(val)
        num += np.where(ok, val, 0.0) * np.where(ok, w, 0.0)
        den += np.where(ok, w, 0.0)
        nvalid += ok & (w > 0)
    good = status == OK
    with np.errstate(invalid="ignore", divide="ignore"):
        bil = num / den
    use = good & (den > 1e-12)
    values[use] = bil[use]
    # the point's own cell is valid but every weighted neighbour is nodata: keep own
    partial = good & (den < 1.0 - 1e-9)
    return values, status, partial


#: ASPRS Positional Accuracy Standards (2014): fewer check points than this do not
#: support a stated vertical accuracy (the statistics are then only indicative).
ASPRS_MIN_CHECK_POINTS = 20
FEW_CHECK_POINTS = (
    "Only {n} check points were compared with the DTM: ASPRS (2014) asks for at least "
    "{minimum} check points before a vertical accuracy is stated, so these statistics are "
    "indicative only. Add check points (at least {minimum}) to state an accuracy.")


def few_check_points(n_used: int) -> bool:
    """Return whether ``n_used`` check points are too few for a stated accuracy (ASPRS)."""
    return 0 < n_used < ASPRS_MIN_CHECK_POINTS


def accuracy_stats(z_dtm, z_check) -> Dict[str, float]:
    """Error statistics of ``e = z_dtm − z_check`` (finite pairs only)."""
    a = np.asarray(z_dtm, dtype=np.float64).ravel()
    b = np.asarray(z_check, dtype=np.float64).ravel()
    ok = np.isfinite(a) & np.isfinite(b)
    a, b = a[ok], b[ok]
    e = a - b
    n = int(e.size)
    nan = float("nan")
    out = {"n": n, "me": nan, "mae": nan, "rmse": nan, "std": nan, "min_error": nan,
           "max_error": nan, "max_abs_error": nan, "r": nan, "r2": nan, "nmad": nan,
           "median_error": nan, "accuracy_95": nan, "p95_abs_error": nan}
    if n == 0:
        return out
    rmse = float(np.sqrt(np.mean(e * e)))
    med = float(np.median(e))
    out.update(me=float(e.mean()), mae=float(np.abs(e).mean()), rmse=rmse,
               std=float(e.std(ddof=1)) if n > 1 else nan,
               min_error=float(e.min()), max_error=float(e.max()),
               max_abs_error=float(np.abs(e).max()), median_error=med,
               nmad=float(1.4826 * np.median(np.abs(e - med))),
               accuracy_95=1.96 * rmse,
               p95_abs_error=float(np.percentile(np.abs(e), 95)))
    if n > 1 and a.std() > 0 and b.std() > 0:
        r = float(np.corrcoef(a, b)[0, 1])
        out.update(r=r, r2=r * r)
    return out


@dataclass
class AccuracyResult:
    """Per-point sampling results and the summary statistics."""

    x: np.ndarray
    y: np.ndarray
    z_check: np.ndarray
    z_dtm: np.ndarray
    status: np.ndarray
    partial: np.ndarray
    stats: Dict[str, float]
    method: str

    @property
    def error(self) -> np.ndarray:
        """Return DTM minus check height (m) per check point."""
        return self.z_dtm - self.z_check

    @property
    def n_total(self) -> int:
        """Return the number of check points read."""
        return int(self.status.size)

    @property
    def n_outside(self) -> int:
        """Return the number of check points outside the DTM."""
        return int((self.status == OUTSIDE).sum())

    @property
    def n_nodata(self) -> int:
        """Return the number of check points on DTM nodata."""
        return int((self.status == NODATA).sum())

    @property
    def n_used(self) -> int:
        """Return the number of check points used in the statistics."""
        return int((self.status == OK).sum())

    @property
    def n_partial(self) -> int:
        """Return the number of points interpolated from fewer than four cells."""
        return int(self.partial.sum())

    def summary(self) -> Dict[str, float]:
        """Return the statistics with the point counts, as a flat dict."""
        out = dict(self.stats)
        out.update(n_total=self.n_total, n_outside=self.n_outside, n_nodata=self.n_nodata,
                   n_partial=self.n_partial)
        return out


def dtm_accuracy(dtm: np.ndarray, geotransform: Sequence[float], x, y, z, *,
                 method: str = "bilinear", nodata: Optional[float] = None,
                 min_points: int = 1) -> AccuracyResult:
    """Compare a DTM with check points.

    Parameters
    ----------
    dtm : 2-D array
        DTM heights, row 0 north; NaN (or ``nodata``) = no data.
    geotransform : 6 floats
        GDAL geotransform of ``dtm``.
    x, y, z : array_like
        Check points in the DTM's CRS (z in the DTM's vertical datum).
    method : {'bilinear', 'nearest'}
    nodata : float, optional
        Value of ``dtm`` to treat as nodata (besides NaN).
    min_points : int
        Raise when fewer check points than this can be used.

    Raises
    ------
    ValueError
        Different lengths, or fewer than ``min_points`` usable check points (with the
        counts outside / on nodata).
    """
    x = np.asarray(x, dtype=np.float64).ravel()
    y = np.asarray(y, dtype=np.float64).ravel()
    z = np.asarray(z, dtype=np.float64).ravel()
    if not (x.size == y.size == z.size):
        raise InputError("Check point x, y, z must have the same length, got {nx}, "
                         "{ny}, {nz}.", nx=int(x.size), ny=int(y.size), nz=int(z.size))
    if x.size == 0:
        raise InputError("No check points were given.")
    data = np.asarray(dtm, dtype=np.float64)
    if nodata is not None and not math.isnan(nodata):
        data = np.where(data == nodata, np.nan, data)
    vals, status, partial = sample_raster(data, geotransform, x, y, method=method)
    status = status.copy()
    status[(status == OK) & ~np.isfinite(z)] = NODATA
    vals = np.where(status == OK, vals, np.nan)
    stats = accuracy_stats(vals[status == OK], z[status == OK])
    res = AccuracyResult(x, y, z, vals, status, partial & (status == OK), stats, method)
    if res.n_used < min_points:
        raise InputError(
            "Only {used} of {total} check points can be compared with the "
            "DTM ({outside} outside its extent, {nodata} on nodata or without "
            "height). Check that the check points and the DTM are in the same CRS and "
            "overlap.", used=res.n_used, total=res.n_total, outside=res.n_outside,
            nodata=res.n_nodata)
    return res


def check_points_not_degrees(x, y, extent: Sequence[float], *, crs_label: str = "",
                             what: str = "check points") -> None:
    """Refuse check points in longitude/latitude against a DTM in a projected CRS.

    Points given without their CRS are taken to be in the DTM's; when every point lies
    within ±180 / ±90, none inside the DTM ``extent = (xmin, xmax, ymin, ymax)``, and
    that extent is not itself within ±180 / ±90, they are degrees.

    Raises
    ------
    InputError
        Naming the DTM's CRS and the fix (give the points' CRS, e.g. EPSG:4326, and
        reproject them).
    """
    x = np.asarray(x, dtype=np.float64)
    y = np.asarray(y, dtype=np.float64)
    ok = np.isfinite(x) & np.isfinite(y)
    if not ok.any():
        return
    x, y = x[ok], y[ok]
    xmin, xmax, ymin, ymax = (float(v) for v in extent)
    dtm_in_degree_range = max(abs(xmin), abs(xmax)) <= 180 and max(abs(ymin), abs(ymax)) <= 90
    looks_degrees = bool((np.abs(x) <= 180).all() and (np.abs(y) <= 90).all())
    inside = (x >= xmin) & (x <= xmax) & (y >= ymin) & (y <= ymax)
    if looks_degrees and not dtm_in_degree_range and not inside.any():
        from ..errors import InputError
        raise InputError(
            "The {what} look like longitude/latitude in degrees (x within ±180, y within "
            "±90) but the DTM is in a projected CRS ({crs}) and none of them lies on it. "
            "Give the check points' CRS (e.g. EPSG:4326) and let them be reprojected to "
            "the DTM's CRS. No output was written.", what=what, crs=crs_label or "?")


def check_duplicates(ids: Sequence, x, y, *, tolerance: float = 0.001,
                     rows: Optional[Sequence] = None, limit: int = 5) -> None:
    """Refuse duplicated check points: the same id twice, or two points at one position.

    A check point counted twice (a copy-paste, or a re-observation with a 2 m blunder)
    silently weights the RMSE; the user must decide which observation is right.

    Parameters
    ----------
    ids : sequence
        Check point ids (compared as text).
    x, y : array_like
        Horizontal coordinates.
    tolerance : float
        Points closer than this (m) are at the same position (default 1 mm).
    rows : sequence, optional
        Row label of each point for the message (default: 1-based point number).
    limit : int
        At most this many duplicate groups are named.

    Raises
    ------
    InputError
        Naming the rows (and ids) of the duplicated points.
    """
    from ..errors import InputError

    x = np.asarray(x, dtype=np.float64).ravel()
    y = np.asarray(y, dtype=np.float64).ravel()
    rows = list(rows) if rows is not None else [str(i + 1) for i in range(x.size)]
    ids = [str(i) for i in ids]
    groups = []
    for kind, (inverse, counts) in (("id", _groups(np.asarray(ids, dtype=str))),
                                    ("position", _position_groups(x, y, tolerance))):
        for g in np.flatnonzero(counts > 1):
            members = np.flatnonzero(inverse.ravel() == g)
            groups.append((kind, members))
    if not groups:
        return
    parts = [f"same {kind}: " + ", ".join(f"row {rows[i]} (id {ids[i]})" for i in members)
             for kind, members in groups[:limit]]
    more = f" and {len(groups) - limit} more" if len(groups) > limit else ""
    raise InputError(
        "Duplicated check points ({groups}{more}). Each check point must be counted once: "
        "remove or rename the duplicates (keep the observation you trust) and run again.",
        groups="; ".join(parts), more=more)


def _groups(keys: np.ndarray):
    """Return (inverse, counts) of equal keys (rows of a 2-D array, or items of a 1-D one)."""
    _, inverse, counts = np.unique(keys, axis=0, return_inverse=True, return_counts=True)
    return inverse.ravel(), counts


def _position_groups(x: np.ndarray, y: np.ndarray, tolerance: float):
    """Group the points snapped to the same ``tolerance`` cell (non-finite: alone)."""
    finite = np.isfinite(x) & np.isfinite(y)
    idx = np.arange(x.size, dtype=np.float64)
    keys = np.column_stack([np.where(finite, np.round(x / tolerance), np.nan),
                            np.where(finite, np.round(y / tolerance), idx),
                            np.where(finite, 0.0, idx)])
    keys[~finite, 0] = -1.0 - idx[~finite]
    return _groups(keys)

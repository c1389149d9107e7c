"""Input helpers for terrain models: class-filtered points from LAS/LAZ, check points
from CSV, and writing a DTM/variance GeoTIFF from a grid (any object with
``geotransform``, ``crs`` and ``nodata``, e.g. ``terrain.grid.GridSpec``).
"""
from __future__ import annotations

import csv
import io
import os
from dataclasses import dataclass
from typing import List, Optional, Sequence, Tuple

import numpy as np

from ..progress import Monitor
from .las import LasInfo, iter_las_chunks, las_info
from .raster import write_geotiff


def parse_classes(text) -> Tuple[int, ...]:
    """Parse a class filter such as ``'2'``, ``'2,8'`` or ``'2 9'``; ``''`` = all classes."""
    if text is None:
        return ()
    if isinstance(text, (list, tuple)):
        items = [str(t) for t in text]
    else:
        items = str(text).replace(";", ",").replace(" ", ",").split(",")
    out = []
    for item in items:
        item = item.strip()
        if not item:
            continue
        try:
            c = int(item)
        except ValueError:
            raise ValueError(f"Class filter must list integer LAS classes such as '2' or "
                             f"'2,8'; {item!r} is not an integer.") from None
        if not 0 <= c <= 255:
            raise ValueError(f"LAS class {c} is out of range 0–255.")
        out.append(c)
    return tuple(sorted(set(out)))


@dataclass
class ClassPoints:
    """Points of the selected classes and facts about the whole file."""

    x: np.ndarray
    y: np.ndarray
    z: np.ndarray
    info: LasInfo
    classes: Tuple[int, ...]
    n_total: int
    class_counts: dict

    def __len__(self) -> int:
        return int(self.x.size)


def read_class_points(path, classes: Sequence[int] = (2,), *,
                      extent: Optional[Sequence[float]] = None,
                      progress=None, cancel=None) -> ClassPoints:
    """Read only the points of ``classes`` (all if empty) from a LAS/LAZ file, in chunks.

    Parameters
    ----------
    extent : (xmin, xmax, ymin, ymax), optional
        Keep only points inside this box.

    Raises
    ------
    ValueError
        No point of the requested classes (the message lists the classes present).
    """
    mon = Monitor(progress, cancel)
    info = las_info(path)
    classes = tuple(classes)
    xs: List[np.ndarray] = []
    ys: List[np.ndarray] = []
    zs: List[np.ndarray] = []
    counts = np.zeros(256, np.int64)
    done = 0
    for _, chunk in iter_las_chunks(path, ("classification",)):
        mon.check()
        cls = np.asarray(chunk["classification"]).astype(np.int64)
        counts += np.bincount(cls, minlength=256)[:256]
        keep = np.isin(cls, classes) if classes else np.ones(cls.size, bool)
        if extent is not None:
            x0, x1, y0, y1 = extent
            keep &= (chunk.x >= x0) & (chunk.x <= x1) & (chunk.y >= y0) & (chunk.y <= y1)
        xs.append(chunk.x[keep])
        ys.append(chunk.y[keep])
        zs.append(chunk.z[keep])
        done += len(chunk)
        mon.update(done / max(info.count, 1))
    present = {int(c): int(n) for c, n in enumerate(counts) if n}
    x = np.concatenate(xs) if xs else np.empty(0)
    if x.size == 0:
        where = " inside the extent" if extent is not None else ""
        raise ValueError(
            f"No ground points in the input class filter: {path} has no point of class(es) "
            f"{', '.join(map(str, classes)) or 'any'}{where}. Classes present (class: "
            f"count): {present or 'none'}. Run a ground filter first or change the class "
            "filter.")
    return ClassPoints(x, np.concatenate(ys), np.concatenate(zs), info, classes,
                       int(info.count), present)


_X_NAMES = ("x", "east", "easting", "e", "lon", "longitude")
_Y_NAMES = ("y", "north", "northing", "n", "lat", "latitude")
_Z_NAMES = ("z", "h", "height", "elev", "elevation", "alt", "altitude", "ortho", "zcheck",
            "z_check")
_ID_NAMES = ("id", "name", "point", "pt", "label", "fid")


def read_checkpoints_csv(path, *, x_field: str = "", y_field: str = "",
                         z_field: str = "") -> Tuple[List[str], np.ndarray, np.ndarray,
                                                    np.ndarray]:
    """Read check points ``(ids, x, y, z)`` from a delimited text file.

    The delimiter (comma, semicolon, tab, space) is detected. With a header row the
    columns are found by name (x/east/easting, y/north/northing, z/h/height/elevation,
    optional id/name), or given by ``x_field``/``y_field``/``z_field``; without a
    header the columns are ``id, x, y, z`` (4+ columns) or ``x, y, z`` (3 columns).
    """
    path = os.fspath(path)
    if not os.path.exists(path):
        raise ValueError(f"Check point file not found: {path}.")
    with open(path, encoding="utf-8-sig") as fh:
        text = fh.read()
    lines = [ln for ln in text.splitlines() if ln.strip() and not ln.lstrip().startswith("#")]
    if not lines:
        raise ValueError(f"{path} holds no check points.")
    sample = "\n".join(lines[:20])
    try:
        dialect = csv.Sniffer().sniff(sample, delimiters=",;\t ")
        delim = dialect.delimiter
    except csv.Error:
        delim = ","
    rows = [r for r in csv.reader(io.StringIO("\n".join(lines)), delimiter=delim,
                                  skipinitialspace=True)]
    rows = [[c.strip() for c in r if c.strip() != ""] if delim == " " else
            [c.strip() for c in r] for r in rows]

    def _isnum(s):
        try:
            float(s)
            return True
        except ValueError:
            return False

    header = None
    if not all(_isnum(c) for c in rows[0][-3:]):
        header = [c.lower() for c in rows[0]]
        rows = rows[1:]

    def _find(names, given, what):
        if given:
            if header is None or given.lower() not in header:
                raise ValueError(f"Column {given!r} for {what} not found in {path} "
                                 f"(columns: {header}).")
            return header.index(given.lower())
        for nm in names:
            if header is not None and nm in header:
                return header.index(nm)
        return None

    if header is not None:
        ix = _find(_X_NAMES, x_field, "x")
        iy = _find(_Y_NAMES, y_field, "y")
        iz = _find(_Z_NAMES, z_field, "z")
        iid = _find(_ID_NAMES, "", "id")
        if ix is None or iy is None or iz is None:
            raise ValueError(f"Cannot find x, y and z columns in {path}: header is {header}. "
                             "Name them x, y, z (or easting, northing, height).")
    else:
        width = len(rows[0])
        if width >= 4:
            iid, ix, iy, iz = 0, 1, 2, 3
        elif width == 3:
            iid, ix, iy, iz = None, 0, 1, 2
        else:
            raise ValueError(f"{path}: expected at least 3 columns (x, y, z), got {width}.")
    ids, xs, ys, zs = [], [], [], []
    for k, r in enumerate(rows, start=1):
        try:
            xs.append(float(r[ix]))
            ys.append(float(r[iy]))
            zs.append(float(r[iz]))
        except (ValueError, IndexError):
            raise ValueError(f"{path}: row {k + (header is not None)} is not numeric x, y, z: "
                             f"{r}.") from None
        ids.append(r[iid] if iid is not None and iid < len(r) else str(k))
    if not xs:
        raise ValueError(f"{path} holds no check points.")
    return ids, np.array(xs), np.array(ys), np.array(zs)


def write_grid(path, data: np.ndarray, grid, *, metadata=None,
               band_name: Optional[str] = None) -> str:
    """Write a grid-shaped array (NaN = nodata) as a GeoTIFF with the grid's CRS."""
    return write_geotiff(path, data, geotransform=grid.geotransform, crs=grid.crs,
                         nodata=grid.nodata, metadata=metadata,
                         band_names=[band_name] if band_name else None)

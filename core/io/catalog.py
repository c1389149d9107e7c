"""Tile catalogs on disk: header indexing, PDAL/QGIS ``.vpc`` files, buffered box reads.

* :func:`find_tiles` — the LAS/LAZ files of a folder, a glob pattern, a list, or a
  virtual point cloud (``.vpc``: a STAC-like GeoJSON FeatureCollection written by
  ``pdal tindex`` / QGIS, one Feature per file with its asset ``href``);
* :func:`index_tiles` — header facts of every file (count, bounds, CRS) without
  reading a single point;
* :func:`read_box` — the points of several files that fall in a box, read with
  laspy's chunk iterator so that only the points inside the box are ever kept
  (a neighbour tile is never held in memory whole);
* :func:`build_vrt` — a GDAL VRT mosaic of per-tile rasters, and optionally one
  Cloud-Optimized GeoTIFF of it.
"""
from __future__ import annotations

import glob
import json
import os
from pathlib import Path
from typing import Iterable, List, Optional, Sequence, Tuple, Union

import numpy as np

from ..errors import InputError
from .las import DEFAULT_CHUNK, LAS_SUFFIXES, LasInfo, PointData, iter_las_chunks, las_info

__all__ = ["find_tiles", "index_tiles", "read_box", "build_vrt", "LAS_SUFFIXES"]

Box = Tuple[float, float, float, float]


def _is_las(path: str) -> bool:
    return path.lower().endswith(LAS_SUFFIXES)


def _vpc_files(path: str) -> List[str]:
    """LAS/LAZ files referenced by a virtual point cloud (relative hrefs resolved)."""
    try:
        with open(path, encoding="utf-8") as fh:
            doc = json.load(fh)
    except (OSError, ValueError) as exc:
        raise InputError("Cannot read the virtual point cloud {path}: {exc}. Re-create it "
                         "(e.g. pdal tindex create, or QGIS 'Build virtual point cloud').",
                         path=path,
                         exc=exc) from exc
    feats = doc.get("features") if isinstance(doc, dict) else None
    if doc.get("type") != "FeatureCollection" or not isinstance(feats, list):
        raise InputError("{path} is not a virtual point cloud (a GeoJSON FeatureCollection "
                         "with one Feature per LAS/LAZ file).", path=path)
    base = os.path.dirname(os.path.abspath(path))
    out = []
    for feat in feats:
        for asset in (feat.get("assets") or {}).values():
            href = str(asset.get("href", ""))
            if _is_las(href):
                out.append(os.path.normpath(os.path.join(base, href)))
    if not out:
        raise InputError("{path} lists no LAS/LAZ file (no asset href ends in .las/.laz).",
                         path=path)
    return out


def find_tiles(source: Union[str, os.PathLike, Sequence]) -> List[str]:
    """Resolve ``source`` (folder, glob, ``.vpc``, file or list of those) to LAS/LAZ paths.

    Raises
    ------
    InputError
        Nothing found, a missing path, or a file that is not LAS/LAZ/.vpc.
    """
    if isinstance(source, (list, tuple)):
        items = [os.fspath(s) for s in source]
    else:
        text = os.fspath(source)
        items = [s.strip() for s in text.replace("\n", ";").split(";") if s.strip()]
    files: List[str] = []
    for item in items:
        if item.lower().endswith(".vpc") and not os.path.isdir(item):
            files += _vpc_files(item)
            continue
        if os.path.isdir(item):
            found = sorted(str(p) for p in Path(item).iterdir()
                           if p.is_file() and _is_las(p.name))
        elif any(c in item for c in "*?["):
            found = sorted(p for p in glob.glob(item) if _is_las(p))
        elif _is_las(item):
            if not os.path.exists(item):
                raise InputError("Tile not found: {item}. Check the path.", item=item)
            found = [item]
        else:
            raise InputError("{item} is neither a folder, a LAS/LAZ file nor a .vpc "
                             "virtual point cloud.", item=item)
        if not found and len(items) > 1:        # one entry of a list yields nothing
            raise InputError("{item} holds no LAS/LAZ tile; correct that entry of the "
                             "list or remove it.", item=item)
        files += found
    unique = list(dict.fromkeys(os.path.abspath(f) for f in files))
    if not unique:
        raise InputError("No LAS/LAZ tile found in {source}; give a folder of .las/.laz "
                         "files, a list of files or a .vpc.", source=source)
    return unique


def index_tiles(paths: Iterable[str]) -> List[LasInfo]:
    """Header facts (count, bounds, CRS) of every tile, points unread."""
    infos = []
    for p in paths:
        try:
            infos.append(las_info(p))
        except InputError:
            raise                       # keeps its template (translated for the user)
        except ValueError as exc:
            raise InputError("Cannot read the header of {path} ({reason}); check that it is "
                             "a LAS/LAZ file and not damaged.", path=p, reason=str(exc)) from exc
    return infos


def read_box(paths: Sequence[str], box: Box, dimensions: Sequence[str] = (), *,
             chunk_size: int = DEFAULT_CHUNK, cancel=None) -> Tuple[PointData, np.ndarray]:
    """Points of ``paths`` inside ``box = (xmin, ymin, xmax, ymax)`` (closed).

    Each file is streamed chunk by chunk and only the points in the box are kept,
    so memory is bounded by the box, not by the files.

    Returns
    -------
    PointData, ndarray of int
        The points (in file order, files in the given order) and, per point, the
        index of its file in ``paths``.
    """
    xmin, ymin, xmax, ymax = box
    parts, src = [], []
    for k, path in enumerate(paths):
        for _, pd in iter_las_chunks(path, dimensions, chunk_size=chunk_size,
                                     allow_empty=True):
            if cancel is not None and cancel():
                from ..progress import Cancelled
                raise Cancelled()
            keep = (pd.x >= xmin) & (pd.x <= xmax) & (pd.y >= ymin) & (pd.y <= ymax)
            if keep.any():
                parts.append(PointData(pd.x[keep], pd.y[keep], pd.z[keep],
                                       {n: v[keep] for n, v in pd.dims.items()}))
                src.append(np.full(int(keep.sum()), k, dtype=np.int32))
    if not parts:
        empty = np.empty(0)
        return PointData(empty, empty, empty, {}), np.empty(0, np.int32)
    data = PointData(np.concatenate([p.x for p in parts]), np.concatenate([p.y for p in parts]),
                     np.concatenate([p.z for p in parts]),
                     {n: np.concatenate([p.dims[n] for p in parts]) for n in dimensions})
    return data, np.concatenate(src)


def build_vrt(vrt_path: str, rasters: Sequence[str], *, cog_path: Optional[str] = None) -> None:
    """Write a GDAL VRT mosaic of ``rasters`` (and optionally a COG copy of it)."""
    from osgeo import gdal
    gdal.UseExceptions()
    if not rasters:
        raise InputError("No tile raster to mosaic (every chunk failed?).")
    vrt = gdal.BuildVRT(os.fspath(vrt_path), [os.fspath(r) for r in rasters])
    if vrt is None:  # pragma: no cover - GDAL raises with UseExceptions
        raise InputError("GDAL could not build {path}.", path=vrt_path)
    first = gdal.Open(os.fspath(rasters[0]))
    for i in range(1, vrt.RasterCount + 1):   # BuildVRT drops the heights' band unit type
        unit = first.GetRasterBand(i).GetUnitType() if i <= first.RasterCount else ""
        if unit:
            vrt.GetRasterBand(i).SetUnitType(unit)
    first = None
    vrt.FlushCache()
    if cog_path:
        gdal.Translate(os.fspath(cog_path), vrt, format="COG",
                       creationOptions=["COMPRESS=DEFLATE", "PREDICTOR=3"])
    vrt = None

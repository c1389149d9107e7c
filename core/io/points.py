"""Point inputs and outputs for terrain models.

Class-filtered points from LAS/LAZ, check points from CSV, the residual point layer
(GeoPackage), and a DTM/variance GeoTIFF from a grid (any object with
``geotransform``, ``crs`` and ``nodata``, e.g. ``terrain.grid.GridSpec``).
"""
from __future__ import annotations

import csv
import io
import math
import os
from dataclasses import dataclass
from typing import List, Optional, Sequence, Tuple

import numpy as np

from ..errors import InputError
from ..progress import Monitor
from .las import LasInfo, iter_las_chunks, las_info
from .raster import write_geotiff
from .text import read_text
from .units import METRIC, Units


def parse_classes(text, *, name: str = "class filter",
                  allow_empty: bool = True) -> Tuple[int, ...]:
    """Parse a list of LAS classes: the one parser of the project.

    Accepts text such as ``'2'``, ``'2,8'``, ``'2; 8 11'`` or a sequence of numbers
    (e.g. the indices of a multi-select enum, where index = ASPRS class code).

    Parameters
    ----------
    text : str, sequence of int or None
        The classes.
    name : str
        What the classes are, for the message (e.g. ``'ground classes'``).
    allow_empty : bool
        When True (default) an empty value returns ``()`` (= every class); when
        False it is an error.

    Returns
    -------
    tuple of int
        Sorted, unique class codes 0–255.

    Raises
    ------
    InputError
        A non-integer item (``'2.7'`` or ``'ground'`` — never silently truncated), a
        code outside 0–255, or an empty value with ``allow_empty=False``.

    Examples
    --------
    >>> parse_classes("2, 8 11")
    (2, 8, 11)
    """
    if text is None:
        items = []
    elif isinstance(text, (list, tuple, set, np.ndarray)):
        items = [str(t) for t in np.asarray(list(text), dtype=object).ravel()]
    else:
        items = str(text).replace(";", ",").replace(" ", ",").split(",")
    out = []
    for item in (i.strip() for i in items):
        if not item:
            continue
        try:
            value = float(item)
        except ValueError:
            value = math.nan
        if not (math.isfinite(value) and value.is_integer()):
            raise InputError("The {name} must list integer LAS classes such as '2' or "
                             "'2, 8'; {item!r} is not an integer class.", name=name, item=item)
        c = int(value)
        if not 0 <= c <= 255:
            raise InputError("The {name} lists class {c}, outside the LAS range 0–255.",
                             name=name,
                             c=c)
        out.append(c)
    if not out and not allow_empty:
        raise InputError("The {name} must list at least one LAS class, e.g. '2'.", name=name)
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
    #: Units of the file; with ``read_class_points(..., metres=True)`` x, y, z are
    #: already converted to metres by them.
    units: Units = METRIC

    def __len__(self) -> int:
        """Return the number of points."""
        return int(self.x.size)


def read_class_points(path, classes: Sequence[int] = (2,), *,
                      extent: Optional[Sequence[float]] = None,
                      progress=None, cancel=None, metres: bool = False) -> ClassPoints:
    """Read only the points of ``classes`` (all if empty) from a LAS/LAZ file, in chunks.

    Parameters
    ----------
    extent : (xmin, xmax, ymin, ymax), optional
        Keep only points inside this box (in the file's CRS units).
    metres : bool, default False
        Return x, y, z converted to metres (:attr:`ClassPoints.units` says from what;
        DEVELOPERS.md, Units).

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
        args = dict(path=path, classes=", ".join(map(str, classes)) or "any",
                    present=", ".join(f"{c}: {n}" for c, n in present.items()) or "none")
        if extent is not None:
            raise InputError(
                "No ground points in the input class filter: {path} has no point of "
                "class(es) {classes} inside the extent. Classes present (class: count): "
                "{present}. Run a ground filter first or change the class filter or the "
                "extent.", **args)
        raise InputError(
            "No ground points in the input class filter: {path} has no point of class(es) "
            "{classes}. Classes present (class: count): {present}. Run a ground filter "
            "first or change the class filter.", **args)
    y, z = np.concatenate(ys), np.concatenate(zs)
    if metres:
        x, y, z = info.units.xyz_to_metres(x, y, z)
    return ClassPoints(x, y, z, info, classes, int(info.count), present, info.units)


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
    The text is decoded by :func:`.text.read_text`, the rule of GCP files too (UTF-16
    with a BOM, a declared page, UTF-8, else the Windows code page that reads the names
    as text: cp1256, cp1252 or the machine's own).
    """
    path = os.fspath(path)
    rows = _delimited_rows(path)
    header = None
    if not all(_is_number(c) for c in rows[0][-3:]):
        header = [c.lower() for c in rows[0]]
        rows = rows[1:]
    iid, ix, iy, iz = _xyz_columns(path, header, rows, (x_field, y_field, z_field))
    ids, xs, ys, zs = [], [], [], []
    for k, r in enumerate(rows, start=1):
        try:
            xs.append(float(r[ix]))
            ys.append(float(r[iy]))
            zs.append(float(r[iz]))
        except (ValueError, IndexError):
            raise InputError("{path}: row {row} is not numeric x, y, z: "
                             "{r}.",
                             path=path,
                             row=k + (header is not None),
                             r=r) from None
        ids.append(r[iid] if iid is not None and iid < len(r) else str(k))
    if not xs:
        raise InputError("{path} holds no check points.", path=path)
    return ids, np.array(xs), np.array(ys), np.array(zs)


def _is_number(text: str) -> bool:
    try:
        float(text)
    except ValueError:
        return False
    return True


def _delimited_rows(path: str) -> List[List[str]]:
    """Return the non-comment rows of a delimited text file, delimiter detected."""
    if not os.path.exists(path):
        raise InputError("Check point file not found: {path}.", path=path)
    text = read_text(path)          # the one rule of GCP and check-point files
    lines = [ln for ln in text.splitlines() if ln.strip() and not ln.lstrip().startswith("#")]
    if not lines:
        raise InputError("{path} holds no check points.", path=path)
    try:
        delim = csv.Sniffer().sniff("\n".join(lines[:20]), delimiters=",;\t ").delimiter
    except csv.Error:
        delim = ","
    rows = csv.reader(io.StringIO("\n".join(lines)), delimiter=delim, skipinitialspace=True)
    if delim == " ":
        return [[c.strip() for c in r if c.strip() != ""] for r in rows]
    return [[c.strip() for c in r] for r in rows]


def _xyz_columns(path: str, header, rows, fields) -> tuple:
    """Return the ``(id, x, y, z)`` column indices (id may be None)."""
    if header is None:
        width = len(rows[0]) if rows else 0
        if width >= 4:
            return 0, 1, 2, 3
        if width == 3:
            return None, 0, 1, 2
        raise InputError("{path}: expected at least 3 columns (x, y, z), got {width}.",
                         path=path,
                         width=width)

    def find(names, given, what):
        if given:
            if given.lower() not in header:
                raise InputError("Column {given!r} for {what} not found in {path} "
                                 "(columns: {header}).",
                                 given=given,
                                 what=what,
                                 path=path,
                                 header=header)
            return header.index(given.lower())
        return next((header.index(nm) for nm in names if nm in header), None)

    ix, iy, iz = (find(n, g, w) for n, g, w in zip((_X_NAMES, _Y_NAMES, _Z_NAMES), fields,
                                                    ("x", "y", "z")))
    if ix is None or iy is None or iz is None:
        raise InputError("Cannot find x, y and z columns in {path}: header is {header}. "
                         "Name them x, y, z (or easting, northing, height).",
                         path=path,
                         header=header)
    return find(_ID_NAMES, "", "id"), ix, iy, iz


def write_grid(path, data: np.ndarray, grid, *, metadata=None,
               band_name: Optional[str] = None, units: Optional[Units] = None,
               quantity: str = "height", in_data_units: bool = False) -> str:
    """Write a grid-shaped array (NaN = nodata) as a GeoTIFF with the grid's CRS.

    Parameters
    ----------
    units : Units, optional
        Units of the data the grid was computed from. The grid and the values are in
        metres (DEVELOPERS.md, Units); with non-metric ``units`` the raster is written
        in the data's own units: geotransform divided by ``units.h``, values by
        ``units.v`` (``quantity='height'``), ``units.v²`` (``'height2'``, a variance)
        or left as they are (``'other'``: densities, counts, flags). The band unit type
        names the unit of heights.
    in_data_units : bool
        The grid and values are already in the data's units (only the band unit type
        is written).
    """
    gt = grid.geotransform
    unit_type = None
    if units is not None and quantity in ("height", "height2"):
        unit_type = units.vertical.symbol + ("²" if quantity == "height2" else "")
    if units is not None and not units.metric and not in_data_units:
        gt = tuple(v / units.h for v in gt)
        data = np.asarray(data, dtype=np.float64)
        if quantity == "height":
            data = data / units.v
        elif quantity == "height2":
            data = data / units.v ** 2
    return write_geotiff(path, data, geotransform=gt, crs=grid.crs,
                         nodata=grid.nodata, metadata=metadata,
                         band_names=[band_name] if band_name else None,
                         unit_type=unit_type)


#: Vector formats the point writer supports (extension -> OGR driver).
VECTOR_DRIVERS = {".gpkg": "GPKG", ".geojson": "GeoJSON", ".json": "GeoJSON"}


def write_points_layer(path, x, y, z, columns, *, crs: Optional[str] = None,
                       layer_name: str = "points", style_qml: Optional[str] = None) -> str:
    """Write 3-D points with attributes as a GeoPackage or GeoJSON file (OGR).

    Parameters
    ----------
    path : path-like
        Output file (``.gpkg`` or ``.geojson``); an output-contract temporary is
        written directly.
    x, y, z : array_like
        Point coordinates (non-finite z is written as 0 in the geometry).
    columns : dict
        Field name -> sequence of values: floats (NaN -> NULL), ints or strings; the
        type of the first non-null value sets the field type.
    crs : str, optional
        'EPSG:n' or WKT of the coordinates.
    layer_name : str
        Layer name inside the file.
    style_qml : str, optional
        QGIS style (QML) stored as the layer's default style in the GeoPackage
        ``layer_styles`` table, so QGIS draws the layer with it when it loads it.

    Returns
    -------
    str
        ``path``.

    Raises
    ------
    InputError
        An extension other than ``.gpkg``/``.geojson``.
    """
    from osgeo import ogr, osr

    path = os.fspath(path)
    ext = os.path.splitext(path)[1].lower()
    if ext not in VECTOR_DRIVERS:
        raise InputError("Output {path}: the residual layer is written as a GeoPackage "
                         "(.gpkg) or GeoJSON (.geojson); choose one of these extensions.",
                         path=path)
    srs = None
    if crs:
        srs = osr.SpatialReference()
        srs.SetAxisMappingStrategy(osr.OAMS_TRADITIONAL_GIS_ORDER)
        if srs.SetFromUserInput(str(crs)) != 0:
            srs = None
    ds = ogr.GetDriverByName(VECTOR_DRIVERS[ext]).CreateDataSource(path)
    if ds is None:
        raise OSError(f"Cannot create {path}; check the folder and the file name.")
    try:
        _fill_points_layer(ds.CreateLayer(layer_name, srs, ogr.wkbPoint25D), x, y, z,
                           columns)
        if style_qml and VECTOR_DRIVERS[ext] == "GPKG":
            _write_gpkg_style(ds, layer_name, style_qml, f"{layer_name} style")
    finally:
        ds = None
    return path


def _field_kind(values) -> str:
    for v in values:
        if v is None or (isinstance(v, float) and math.isnan(v)):
            continue
        if isinstance(v, (bool, np.bool_)):
            return "int"
        if isinstance(v, (int, np.integer)):
            return "int"
        if isinstance(v, (float, np.floating)):
            return "float"
        return "str"
    return "float"


def _fill_points_layer(layer, x, y, z, columns) -> None:
    """Create the fields and add one feature per point (in one transaction)."""
    from osgeo import ogr

    types = {"int": ogr.OFTInteger64, "float": ogr.OFTReal, "str": ogr.OFTString}
    kinds = {name: _field_kind(vals) for name, vals in columns.items()}
    for name, kind in kinds.items():
        layer.CreateField(ogr.FieldDefn(name, types[kind]))
    defn = layer.GetLayerDefn()
    x, y, z = (np.asarray(v, dtype=np.float64).ravel() for v in (x, y, z))
    layer.StartTransaction()
    for i in range(x.size):  # one OGR call per feature: OGR has no array API here
        feat = ogr.Feature(defn)
        for name, kind in kinds.items():
            v = columns[name][i]
            if v is None or (kind == "float" and not np.isfinite(float(v))):
                feat.SetFieldNull(name)
            else:
                feat.SetField(name, {"int": int, "float": float, "str": str}[kind](v))
        geom = ogr.Geometry(ogr.wkbPoint25D)
        geom.AddPoint(float(x[i]), float(y[i]), float(z[i]) if np.isfinite(z[i]) else 0.0)
        feat.SetGeometry(geom)
        layer.CreateFeature(feat)
    layer.CommitTransaction()


def _write_gpkg_style(ds, layer_name: str, qml: str, style_name: str) -> None:
    """Store ``qml`` as the default style of ``layer_name`` (QGIS ``layer_styles`` table)."""
    from osgeo import ogr

    table = ds.GetLayerByName("layer_styles")
    if table is None:
        table = ds.CreateLayer("layer_styles", None, ogr.wkbNone)
        for name, kind in (("f_table_catalog", ogr.OFTString), ("f_table_schema", ogr.OFTString),
                           ("f_table_name", ogr.OFTString),
                           ("f_geometry_column", ogr.OFTString),
                           ("styleName", ogr.OFTString), ("styleQML", ogr.OFTString),
                           ("styleSLD", ogr.OFTString), ("useAsDefault", ogr.OFTInteger),
                           ("description", ogr.OFTString), ("owner", ogr.OFTString),
                           ("ui", ogr.OFTString), ("update_time", ogr.OFTDateTime)):
            field = ogr.FieldDefn(name, kind)
            if name == "useAsDefault":
                field.SetSubType(ogr.OFSTBoolean)
            table.CreateField(field)
    feat = ogr.Feature(table.GetLayerDefn())
    for name, value in (("f_table_catalog", ""), ("f_table_schema", ""),
                        ("f_table_name", layer_name), ("f_geometry_column", "geom"),
                        ("styleName", style_name), ("styleQML", qml), ("styleSLD", ""),
                        ("useAsDefault", 1), ("description", style_name), ("owner", ""),
                        ("ui", "")):
        feat.SetField(name, value)
    table.CreateFeature(feat)

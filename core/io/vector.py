"""Polygon layers (GeoPackage) from labelled rasters, with attributes.

:func:`write_label_polygons` turns a grid of region labels (0 = background) into one
polygon per label with ``gdal.Polygonize`` (4-connected, like
``scipy.ndimage.label``'s default structure) and writes them with their attribute
values to a GeoPackage layer. Used for change polygons and building footprints.
"""
from __future__ import annotations

import os
from typing import Mapping, Optional, Sequence, Tuple

import numpy as np

from .contract import atomic_output
from .raster import srs_wkt

#: OGR field types by Python type name.
_TYPES = {"int": "OFTInteger64", "float": "OFTReal", "str": "OFTString"}


def _label_layer(labels: np.ndarray, geotransform, wkt: str):
    """Polygonize ``labels`` into an in-memory OGR layer with a ``label`` field."""
    from osgeo import gdal, ogr, osr
    gdal.UseExceptions()
    h, w = labels.shape
    mem = gdal.GetDriverByName("MEM").Create("", w, h, 1, gdal.GDT_Int32)
    mem.SetGeoTransform(tuple(geotransform))
    band = mem.GetRasterBand(1)
    band.WriteArray(labels.astype(np.int32))
    srs = None
    if wkt:
        srs = osr.SpatialReference()
        srs.ImportFromWkt(wkt)
    vds = gdal.GetDriverByName("Memory").Create("", 0, 0, 0, gdal.GDT_Unknown)
    layer = vds.CreateLayer("labels", srs, ogr.wkbPolygon)
    layer.CreateField(ogr.FieldDefn("label", ogr.OFTInteger))
    gdal.Polygonize(band, band, layer, 0, [], callback=None)   # band as its own mask
    return mem, vds, layer


def write_label_polygons(path, labels: np.ndarray, geotransform: Sequence[float], *,
                         crs: Optional[str] = None, layer_name: str = "polygons",
                         fields: Sequence[Tuple[str, str]] = (),
                         records: Mapping[int, Mapping[str, object]] = ()) -> int:
    """Write one polygon per non-zero label of ``labels`` to a GeoPackage.

    Parameters
    ----------
    path : path-like
        Output .gpkg (written directly when it is a contract temporary).
    labels : 2-D int array
        Region labels, 0 = no region; row 0 north.
    geotransform : 6 floats
        GDAL geotransform of ``labels``.
    crs : str, optional
        CRS of the layer.
    layer_name : str
        Layer name.
    fields : sequence of (name, 'int' | 'float' | 'str')
        Attribute fields, in order.
    records : mapping label -> {field: value}
        Attribute values of each label; labels without a record are skipped.

    Returns
    -------
    int
        Number of polygons written.
    """
    from osgeo import gdal, ogr, osr
    gdal.UseExceptions()
    ogr.UseExceptions()
    wkt = srs_wkt(crs)
    _mem, _vds, src = _label_layer(np.asarray(labels), geotransform, wkt)
    srs = None
    if wkt:
        srs = osr.SpatialReference()
        srs.ImportFromWkt(wkt)
    n = 0
    with atomic_output(os.fspath(path)) as tmp:
        ds = ogr.GetDriverByName("GPKG").CreateDataSource(tmp)
        try:
            layer = ds.CreateLayer(layer_name, srs, ogr.wkbMultiPolygon)
            for name, kind in fields:
                layer.CreateField(ogr.FieldDefn(name, getattr(ogr, _TYPES[kind])))
            defn = layer.GetLayerDefn()
            layer.StartTransaction()
            merged = {}
            for feat in src:
                lab = feat.GetField("label")
                geom = feat.GetGeometryRef().Clone()
                if lab in merged:
                    merged[lab] = merged[lab].Union(geom)
                else:
                    merged[lab] = geom
            for lab in sorted(merged):
                rec = records.get(lab) if records else None
                if rec is None:
                    continue
                out = ogr.Feature(defn)
                for name, _kind in fields:
                    value = rec.get(name)
                    if value is not None:
                        out.SetField(name, value.item() if hasattr(value, "item") else value)
                out.SetGeometry(ogr.ForceToMultiPolygon(merged[lab]))
                layer.CreateFeature(out)
                n += 1
            layer.CommitTransaction()
        finally:
            ds = None
    return n


def check_vector_file(path) -> None:
    """Refuse a file GDAL/OGR cannot open as a vector layer (zero-byte, garbled, other).

    Raises :class:`~..errors.InputError` naming the file; reads the header only.
    """
    from osgeo import gdal

    from ..errors import InputError
    path = os.fspath(path)
    try:
        ds = gdal.OpenEx(path, gdal.OF_VECTOR)
    except RuntimeError:                 # gdal.UseExceptions() in effect
        ds = None
    if ds is None or ds.GetLayerCount() == 0:
        raise InputError("{path} is not a vector file GDAL/OGR can read (empty, damaged or "
                         "of another format); choose a valid file (e.g. GeoPackage, "
                         "shapefile or CSV).", path=path)


def read_polygons(path, layer: Optional[str] = None):
    """Read a polygon layer: list of (attributes dict, WKT) (for tests and reports)."""
    from osgeo import ogr
    ogr.UseExceptions()
    ds = ogr.Open(os.fspath(path))
    lyr = ds.GetLayerByName(layer) if layer else ds.GetLayer(0)
    out = [(feat.items(), feat.GetGeometryRef().ExportToWkt()) for feat in lyr]
    ds = None
    return out


def label_outlines(labels: np.ndarray, geotransform: Sequence[float], *,
                   tolerance: float = 0.0) -> dict:
    """Exterior ring of each non-zero label (its largest polygon), simplified.

    ``gdal.Polygonize`` of ``labels`` (the same outlines as
    :func:`write_label_polygons`), Douglas–Peucker simplification with ``tolerance``
    (CRS units; topology kept), ring without the closing point. Returns
    ``{label: (n, 2) array}``.
    """
    from osgeo import ogr
    ogr.UseExceptions()
    _mem, _vds, src = _label_layer(np.asarray(labels), geotransform, "")
    best = {}
    for feat in src:
        lab = feat.GetField("label")
        geom = feat.GetGeometryRef()
        area = geom.GetArea()
        if lab not in best or area > best[lab][0]:
            best[lab] = (area, geom.Clone())
    out = {}
    for lab, (_area, geom) in best.items():
        if tolerance > 0:
            geom = geom.SimplifyPreserveTopology(tolerance)
        ring = geom.GetGeometryRef(0)
        pts = np.array(ring.GetPoints(), dtype=float)[:, :2]
        if len(pts) > 1 and np.allclose(pts[0], pts[-1]):
            pts = pts[:-1]
        if len(pts) >= 3:
            out[int(lab)] = pts
    return out

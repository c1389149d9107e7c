"""GeoTIFF writing and reading with GDAL (north-up, pixel-is-area).

Convention: a grid of ``nrows × ncols`` cells whose upper-left *corner* is at
``(xmin, ymax)`` with square-or-rectangular cells ``(xres, yres)`` has the GDAL
geotransform ``(xmin, xres, 0, ymax, 0, -yres)``; row 0 is the northernmost row and
cell ``(r, c)`` covers ``[xmin + c·xres, xmin + (c+1)·xres] ×
[ymax − (r+1)·yres, ymax − r·yres]`` (its value belongs to the cell centre).
"""
from __future__ import annotations

import os
from dataclasses import dataclass
from typing import Optional, Sequence, Tuple

import numpy as np

from ..errors import InputError
from .contract import atomic_output
from .crs import crs_label, srs_wkt  # noqa: F401 - re-exported (historic location)

DEFAULT_NODATA = -9999.0
CREATION_OPTIONS = ("TILED=YES", "COMPRESS=DEFLATE", "PREDICTOR=3", "BIGTIFF=IF_SAFER")


def _gdal():
    from osgeo import gdal
    gdal.UseExceptions()
    return gdal


@dataclass
class Raster:
    """A single-band raster in memory."""

    data: np.ndarray
    geotransform: Tuple[float, float, float, float, float, float]
    crs: str
    nodata: Optional[float]

    @property
    def shape(self) -> Tuple[int, int]:
        """Return ``(rows, columns)``."""
        return self.data.shape

    def masked(self) -> np.ndarray:
        """Return the data as float64 with nodata cells set to NaN."""
        out = self.data.astype(np.float64, copy=True)
        if self.nodata is not None:
            out[self.data == self.nodata] = np.nan
        return out


def write_geotiff(path, data, *, geotransform: Sequence[float], crs: Optional[str] = None,
                  nodata: Optional[float] = DEFAULT_NODATA, dtype: str = "float32",
                  bands: Optional[Sequence[np.ndarray]] = None,
                  band_names: Optional[Sequence[str]] = None,
                  creation_options: Sequence[str] = CREATION_OPTIONS,
                  metadata: Optional[dict] = None,
                  unit_type: Optional[str] = None) -> str:
    """Write a tiled, compressed GeoTIFF atomically (temporary name, then rename).

    Parameters
    ----------
    path : path-like
        Output .tif path.
    data : 2-D array
        Band 1, row 0 = north. NaN cells are written as ``nodata``.
    geotransform : 6 floats
        GDAL geotransform ``(xmin, xres, 0, ymax, 0, -yres)``.
    crs : str, optional
        'EPSG:n' or WKT; written as the raster's spatial reference.
    nodata : float or None
        Nodata value (default -9999).
    bands : sequence of 2-D arrays, optional
        Extra bands (same shape) after ``data``.
    band_names : sequence of str, optional
        Band descriptions.
    unit_type : str, optional
        Unit of the values of every band (GDAL ``SetUnitType``), e.g. ``'ftUS'`` for
        heights in US survey feet (:func:`~.units.raster_units` reads it back).
    """
    gdal = _gdal()
    arrays = [np.asarray(data)] + [np.asarray(b) for b in (bands or [])]
    shape = arrays[0].shape
    if len(shape) != 2 or 0 in shape:
        raise InputError("A raster needs a non-empty 2-D array, got shape {shape}.",
                         shape=shape)
    if any(a.shape != shape for a in arrays):
        raise InputError("All bands must have the same shape.")
    gt = tuple(float(v) for v in geotransform)
    if len(gt) != 6 or gt[1] <= 0 or gt[5] >= 0:
        raise InputError("Expected a north-up geotransform (xres > 0, yres < 0), got {gt}.",
                         gt=gt)
    gdt = {"float32": gdal.GDT_Float32, "float64": gdal.GDT_Float64,
           "uint8": gdal.GDT_Byte, "int16": gdal.GDT_Int16,
           "int32": gdal.GDT_Int32, "uint16": gdal.GDT_UInt16}[dtype]
    wkt = srs_wkt(crs)
    options = list(creation_options)
    if dtype not in ("float32", "float64"):
        options = [o for o in options if not o.startswith("PREDICTOR")]
    if min(shape) < 256:
        options = [o for o in options if o != "TILED=YES"]
    with atomic_output(os.fspath(path)) as tmp:
        ds = gdal.GetDriverByName("GTiff").Create(tmp, shape[1], shape[0], len(arrays),
                                                  gdt, options)
        try:
            ds.SetGeoTransform(gt)
            if wkt:
                ds.SetProjection(wkt)
            ds.SetMetadataItem("AREA_OR_POINT", "Area")
            for key, value in (metadata or {}).items():
                ds.SetMetadataItem(str(key), str(value))
            for i, arr in enumerate(arrays, start=1):
                band = ds.GetRasterBand(i)
                out = arr
                if nodata is not None:
                    band.SetNoDataValue(float(nodata))
                    if np.issubdtype(arr.dtype, np.floating):
                        out = np.where(np.isfinite(arr), arr, nodata)
                band.WriteArray(out.astype(np.dtype(dtype), copy=False))
                if unit_type:
                    band.SetUnitType(str(unit_type))
                if band_names and i <= len(band_names):
                    band.SetDescription(str(band_names[i - 1]))
            ds.FlushCache()
        finally:
            ds = None
    return os.fspath(path)


def raster_extent(r: Raster) -> Tuple[float, float, float, float]:
    """``(xmin, xmax, ymin, ymax)`` of a north-up :class:`Raster`."""
    x0, dx, _, y0, _, dy = r.geotransform
    rows, cols = r.shape
    xs, ys = (x0, x0 + cols * dx), (y0, y0 + rows * dy)
    return (min(xs), max(xs), min(ys), max(ys))


def _open_band(path, band: int):
    """``(dataset, band)`` of a raster GDAL can read, with clear errors; no pixels read."""
    gdal = _gdal()
    path = os.fspath(path)
    if not os.path.exists(path):
        raise InputError("Raster not found: {path}. Check the path.", path=path)
    try:
        ds = gdal.Open(path)
    except RuntimeError as exc:
        raise InputError("{path} is not a raster GDAL can read: {error}", path=path,
                         error=exc) from exc
    if band < 1 or band > ds.RasterCount:
        raise InputError("{path} has {n} band(s); band {band} does not exist.", path=path,
                         n=ds.RasterCount, band=band)
    return ds, ds.GetRasterBand(band)


def check_raster_file(path) -> None:
    """Refuse a file GDAL cannot open as a raster (zero-byte, garbled, another format).

    Raises :class:`~..errors.InputError` naming the file; reads the header only.
    """
    _open_band(path, 1)


def read_raster(path, band: int = 1) -> Raster:
    """Read one band of a GDAL raster with its geotransform, CRS and nodata."""
    ds, b = _open_band(path, band)
    return Raster(b.ReadAsArray(), tuple(ds.GetGeoTransform()), ds.GetProjection(),
                  b.GetNoDataValue())


def read_raster_on_grid(path, geotransform: Sequence[float], shape: Tuple[int, int], *,
                        crs: Optional[str] = None, band: int = 1,
                        resampling: str = "bilinear") -> Raster:
    """Read one band of a raster resampled onto a north-up grid (GDAL warp, in memory).

    Cells of the target grid outside the source or on its nodata become NaN
    (``nodata`` of the result is NaN). ``crs`` is the target CRS (default: the
    source's, no reprojection).
    """
    gdal = _gdal()
    path = os.fspath(path)
    ds, b = _open_band(path, band)    # checks existence, readability, band; no pixels
    src_crs, src_nodata = ds.GetProjection(), b.GetNoDataValue()
    del ds, b
    if band != 1:
        raise InputError("Only band 1 can be resampled onto another grid.")
    rows, cols = int(shape[0]), int(shape[1])
    x0, dx, _, y0, _, dy = geotransform
    bounds = (x0, y0 + rows * dy, x0 + cols * dx, y0)
    opts = gdal.WarpOptions(format="MEM", outputBounds=bounds, width=cols, height=rows,
                            resampleAlg=resampling,
                            dstSRS=crs or src_crs or None, outputType=gdal.GDT_Float64,
                            srcNodata=src_nodata, dstNodata=float("nan"))
    try:
        ds = gdal.Warp("", path, options=opts)
    except RuntimeError as exc:
        raise InputError("{path} could not be resampled onto the grid: {error}", path=path,
                         error=exc) from exc
    return Raster(ds.GetRasterBand(1).ReadAsArray(), tuple(ds.GetGeoTransform()),
                  ds.GetProjection(), float("nan"))

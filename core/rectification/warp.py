"""Rectify (warp) an image with GCPs and a polynomial of order 1–3 through GDAL.

The input image is never modified: the GCPs are attached to an in-memory VRT copy
(``/vsimem``, ``gdal.Translate(format="VRT", GCPs=…)``, which also drops any existing
geotransform so the GCPs are what georeferences it), never with ``SetGCPs`` on the
input. ``gdal.Warp`` then resamples that VRT with the GCP polynomial transformer
(``METHOD=GCP_POLYNOMIAL``, ``MAX_GCP_ORDER=order`` — exactly what ``gdalwarp -order N``
does) into a GeoTIFF written under a temporary name and renamed only on success.

The polynomial is first fitted with :func:`~.polynomial.fit_polynomial` so that too few,
collinear or clustered GCPs are refused with a clear message before GDAL runs; GDAL
fits the same least-squares polynomial (the tests check both agree at every GCP to
1e-6 of a pixel). The default output resolution is the ground resolution ``GR``
implied by the GCPs (``sqrt|det J|`` of the affine fit, in target-CRS units).

Method and criteria: Tishreen Univ. J. Eng. Sci. 38(2), 2016 (see
:mod:`.gcp_report`).
"""
from __future__ import annotations

import os
import uuid
from dataclasses import dataclass
from typing import Optional, Sequence

import numpy as np

from ..errors import InputError
from ..io.contract import atomic_output, check_not_input
from ..io.crs import same_crs, spatial_reference
from ..io.gcp import GCPSet, check_in_image, make_gcps
from ..progress import Cancelled, Monitor
from .polynomial import MAX_CONDITION, fit_polynomial
from .transforms import check_kind, fit_transform

RESAMPLING = ("near", "bilinear", "cubic", "cubicspline", "lanczos", "average", "mode")
CREATION_OPTIONS = ("TILED=YES", "COMPRESS=DEFLATE", "BIGTIFF=IF_SAFER")


def _gdal():
    from osgeo import gdal
    gdal.UseExceptions()
    return gdal


def _srs(crs: str, what: str):
    """Return the ``osr.SpatialReference`` of ``crs`` (one CRS helper: core/io/crs.py)."""
    return spatial_reference(crs, what=what)


def image_info(path):
    """``(width, height, band_count, geotransform)`` of a raster, with clear errors."""
    gdal = _gdal()
    path = os.fspath(path)
    if not os.path.exists(path) and not path.startswith("/vsi"):
        raise InputError("Image not found: {path}. Check the path.", path=path)
    try:
        ds = gdal.Open(path, gdal.GA_ReadOnly)
    except RuntimeError as exc:
        raise InputError("{path} is not an image GDAL can read: {error}", path=path,
                         error=exc) from None
    return ds.RasterXSize, ds.RasterYSize, ds.RasterCount, tuple(ds.GetGeoTransform())


def to_crs(xy: np.ndarray, src: str, dst: str) -> np.ndarray:
    """Transform ``(n, 2)`` coordinates from CRS ``src`` to ``dst`` (x/y = east/north)."""
    if same_crs(src, dst):
        return np.asarray(xy, float).copy()
    from osgeo import osr
    ct = osr.CoordinateTransformation(_srs(src, "GCP CRS"), _srs(dst, "target CRS"))
    out = np.array(ct.TransformPoints([(float(x), float(y)) for x, y in xy]), float)
    return out[:, :2]


def ground_resolution(gcps: GCPSet, crs: Optional[str] = None) -> float:
    """Return the pixel size on the ground implied by the enabled GCPs.

    Affine fit, ``sqrt|det J|``, in the units of ``crs`` (default: the GCPs' CRS).
    """
    m = gcps.fit_mask
    mp = gcps.map[m]
    if crs and gcps.crs and not same_crs(crs, gcps.crs):
        mp = to_crs(mp, gcps.crs, crs)
    return fit_polynomial(gcps.pixel[m], mp, order=1).pixel_size()


def gcps_vrt(src_path: str, gcps: GCPSet, crs: str):
    """Return an in-memory VRT of ``src_path`` with the enabled role-'gcp' GCPs attached.

    Returns ``(dataset, vsimem_path)``; unlink the path when done.
    """
    gdal = _gdal()
    m = gcps.fit_mask
    gl = [gdal.GCP(float(x), float(y), 0.0, float(c), float(r), "", str(i))
          for (c, r), (x, y), i in zip(gcps.pixel[m], gcps.map[m],
                                       [i for i, k in zip(gcps.ids, m) if k])]
    vpath = f"/vsimem/gcp_{uuid.uuid4().hex}.vrt"
    ds = gdal.Translate(vpath, os.fspath(src_path), format="VRT", GCPs=gl,
                        outputSRS=_srs(crs, "GCP CRS").ExportToWkt())
    return ds, vpath


@dataclass
class WarpResult:
    """What :func:`rectify` wrote."""

    output: str
    order: int
    resampling: str
    resolution: float
    width: int
    height: int
    crs: str
    model: object
    kind: str = ""

    def as_dict(self) -> dict:
        """Return a JSON-ready description."""
        return {"output": self.output, "order": self.order, "kind": self.kind,
                "resampling": self.resampling,
                "resolution": self.resolution, "width": self.width, "height": self.height,
                "crs": self.crs}


def _check_options(resampling, resolution):
    if resampling not in RESAMPLING:
        raise InputError("resampling must be one of {choices}, got {value}.",
                         choices=", ".join(RESAMPLING), value=repr(resampling))
    if resolution is not None and not (np.isfinite(resolution) and resolution > 0):
        raise InputError("resolution must be a positive pixel size, got {value}; "
                         "leave it empty to use the ground resolution GR.",
                         value=repr(resolution))


#: nodes per side of the GCP grid that carries a projective fit into GDAL's TPS
PROJECTIVE_GRID = 33


def _source(src: str, gcps: GCPSet, kind: str, model):
    """In-memory VRT georeferenced for ``kind`` and the gdal.Warp transformer options.

    * polynomials: the GCPs, ``METHOD=GCP_POLYNOMIAL`` (``gdalwarp -order N``);
    * ``tps``: the GCPs, ``METHOD=GCP_TPS`` (``gdalwarp -tps``);
    * ``linear``/``helmert``: the fitted affine as the geotransform (exact);
    * ``projective``: a grid of GCPs on the fitted homography, ``METHOD=GCP_TPS``
      (GDAL 3.6 has no homography transformer; the spline through the grid departs
      from the homography by far less than a pixel, measured in the tests).
    """
    gdal = _gdal()
    if kind in ("linear", "helmert"):
        vpath = f"/vsimem/gcp_{uuid.uuid4().hex}.vrt"
        ds = gdal.Translate(vpath, src, format="VRT")
        ds.SetGCPs([], "")
        ds.SetGeoTransform(model.geotransform())
        ds.SetProjection(_srs(gcps.crs, "GCP CRS").ExportToWkt())
        return ds, vpath, {}
    if kind == "projective":
        width, height, _, _ = image_info(src)
        c, r = np.meshgrid(np.linspace(0, width, PROJECTIVE_GRID),
                           np.linspace(0, height, PROJECTIVE_GRID))
        x, y = model.forward(c.ravel(), r.ravel())
        grid = make_gcps(None, np.column_stack([c.ravel(), r.ravel()]),
                         np.column_stack([x, y]), crs=gcps.crs)
        ds, vpath = gcps_vrt(src, grid, gcps.crs)
        return ds, vpath, {"tps": True}
    ds, vpath = gcps_vrt(src, gcps, gcps.crs)
    if kind == "tps":
        return ds, vpath, {"tps": True}
    return ds, vpath, {"polynomialOrder": int(kind[-1]),
                       "transformerOptions": ["METHOD=GCP_POLYNOMIAL"]}


def _run_warp(tmp, ds, opts, sub, src):
    gdal = _gdal()
    try:
        res = gdal.Warp(tmp, ds, **opts)
    except RuntimeError as exc:
        if sub.cancelled():
            raise Cancelled("cancelled by the user") from None
        raise InputError("GDAL could not warp {path}: {error}", path=src, error=exc) from None
    if res is None:
        if sub.cancelled():
            raise Cancelled("cancelled by the user")
        raise InputError("GDAL could not warp {path}.", path=src)
    return res


def rectify(input_path, gcps: GCPSet, output_path, *, order: int = 2,
            kind: Optional[str] = None,
            target_crs: Optional[str] = None, resampling: str = "near",
            resolution: Optional[float] = None, nodata: Optional[float] = None,
            error_threshold: float = 0.125,
            creation_options: Sequence[str] = CREATION_OPTIONS,
            max_condition: float = MAX_CONDITION, progress=None, cancel=None) -> WarpResult:
    """Warp ``input_path`` with the GCP transformation ``kind`` into a GeoTIFF.

    Parameters
    ----------
    input_path : path-like
        Image to rectify (any GDAL raster; never modified).
    gcps : GCPSet
        GCPs with a CRS (``gcps.crs``); enabled role-'gcp' points are used.
    output_path : path-like
        GeoTIFF to write (temporary name, renamed on success; never the input).
    order : {1, 2, 3}
        Polynomial order (``gdalwarp -order``) when ``kind`` is not given.
    kind : str, optional
        One of :data:`~.transforms.KINDS` (default ``polynomial<order>``); see
        :func:`_source` for how each reaches GDAL.
    target_crs : str, optional
        Output CRS (default: the GCPs' CRS); GDAL reprojects after the transformation.
    resampling : str
        One of :data:`RESAMPLING` (default nearest neighbour, as in the paper).
    resolution : float, optional
        Output pixel size in target-CRS units; default the ground resolution GR
        implied by the GCPs.
    nodata : float, optional
        Output nodata value (default: the input's nodata, else 0 fills the outside).
    error_threshold : float
        GDAL approximation error in pixels (0 = exact transformer for every pixel;
        0.125 is gdalwarp's default).
    creation_options : sequence of str
        GeoTIFF creation options.
    max_condition : float
        Condition-number limit of the polynomial fits.
    progress, cancel : callable, optional
        Progress and cancel callbacks (:class:`~..progress.Monitor`).

    Returns
    -------
    WarpResult
    """
    mon = Monitor(progress, cancel)
    src, out = os.fspath(input_path), os.fspath(output_path)
    check_not_input(out, src)
    _check_options(resampling, resolution)
    kind = check_kind(kind or f"polynomial{int(order)}")
    if not gcps.crs:
        raise InputError("The GCP map coordinates have no CRS (no '#CRS:' line in the file "
                         "and none given). Set the GCP CRS (e.g. EPSG:22780) and run again.")
    gcp_srs = _srs(gcps.crs, "GCP CRS")
    tgt_srs = _srs(target_crs or gcps.crs, "target CRS")
    width, height, _, _ = image_info(src)
    check_in_image(gcps, width, height)
    m = gcps.fit_mask
    model = fit_transform(kind, gcps.pixel[m], gcps.map[m],
                          weights=None if gcps.weight is None else gcps.weight[m],
                          max_condition=max_condition)
    if gcps.weight is not None and not np.allclose(gcps.weight, gcps.weight[0]):
        model.warnings.append("GDAL's warper fits unweighted: the warp ignores the weights "
                              "(the report uses them).")
    if resolution is None:
        resolution = ground_resolution(gcps, target_crs or gcps.crs)
    mon.step(0.05)
    ds, vpath, topts = _source(src, gcps, kind, model)
    sub = mon.sub(0.05, 0.98)

    def cb(complete, _msg, _data):
        if sub.cancelled():
            return 0
        sub.update(complete)
        return 1

    opts = dict(format="GTiff", resampleAlg=resampling, srcSRS=gcp_srs.ExportToWkt(),
                dstSRS=tgt_srs.ExportToWkt(), xRes=float(resolution), yRes=float(resolution),
                errorThreshold=float(error_threshold), multithread=True,
                warpOptions=["NUM_THREADS=ALL_CPUS"],
                creationOptions=list(creation_options), callback=cb, **topts)
    if nodata is not None:
        opts["dstNodata"] = float(nodata)
    try:
        with atomic_output(out) as tmp:
            res = _run_warp(tmp, ds, opts, sub, src)
            res.SetMetadataItem("RECTIFICATION", f"GCP {kind}, {int(m.sum())} GCPs, "
                                f"resampling {resampling}")
            w, h = res.RasterXSize, res.RasterYSize
            res.FlushCache()
            res = None
    finally:
        ds = None
        _gdal().Unlink(vpath)
    mon.update(1.0)
    return WarpResult(out, int(order), resampling, float(resolution), w, h,
                      tgt_srs.ExportToWkt(), getattr(model, "model", model), kind)

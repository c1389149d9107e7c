"""Deterministic synthetic GCP sets and test images for GCP rectification.

The map coordinates are those of the 22 GCPs of image 1 of the seed paper
(Tishreen Univ. J. Eng. Sci. 38(2), 2016; Latakia, Syrian stereographic system). Their
pixel coordinates are not published, so image positions are derived from an
approximate north-up affine (GR = 0.91 m) and the map coordinates are then replaced by a
*known* polynomial of those positions (plus optional Gaussian noise): fitting must give
the polynomial back.
"""
from __future__ import annotations

import os
from typing import Optional

import numpy as np

from ..core.io.contract import atomic_output

#: map X, Y (m) of the 22 GCPs of image 1; point 2's published Y (151966.41) is a likely
#: typo for 154966.41 (it would lie 3 km south of every other point) and is corrected.
IMAGE1_MAP = np.array([
    (-305503.32, 155712.90), (-306605.36, 154966.41), (-307382.57, 155811.59),
    (-305275.79, 155327.12), (-306139.46, 155301.20), (-307411.74, 155395.24),
    (-305218.22, 154810.70), (-306186.52, 154845.97), (-307448.68, 154927.95),
    (-305210.30, 154129.08), (-306376.08, 154141.36), (-307607.09, 154469.39),
    (-306967.20, 154314.87), (-305561.98, 154023.66), (-304889.97, 155053.25),
    (-306715.73, 155352.35), (-305661.36, 154871.21), (-306733.45, 154938.08),
    (-304865.95, 154505.58), (-307874.69, 155830.68), (-307968.43, 154474.19),
    (-307987.49, 155081.25)])
IMAGE1_GR = 4363.64 / 4800.0
#: EPSG code the paper's coordinates are read in (Syrian stereographic, *reading*)
IMAGE1_EPSG = 22780


def image1_pixels(gr: float = IMAGE1_GR, margin: float = 150.0):
    """Image ``(col, row)`` of the 22 GCPs under a north-up affine with pixel size ``gr``,
    and the image size ``(width, height)`` that holds them with ``margin`` pixels."""
    x0 = IMAGE1_MAP[:, 0].min() - margin * gr
    y0 = IMAGE1_MAP[:, 1].max() + margin * gr
    col = (IMAGE1_MAP[:, 0] - x0) / gr
    row = (y0 - IMAGE1_MAP[:, 1]) / gr
    width = int(np.ceil(col.max() + margin))
    height = int(np.ceil(row.max() + margin))
    return np.column_stack([col, row]), (width, height)


def true_coefficients(order: int, gr: float = IMAGE1_GR):
    """Raw-pixel coefficients ``(cx, cy)`` (paper term order) of a realistic polynomial
    of ``order``: a 0.4° rotation, slightly different x/y scales and smooth distortion of
    10–30 m over the image."""
    n = (order + 1) * (order + 2) // 2
    th = np.deg2rad(0.4)
    cx = np.zeros(n)
    cy = np.zeros(n)
    cx[:3] = [-308100.0, gr * 1.002 * np.cos(th), gr * np.sin(th)]
    cy[:3] = [155950.0, gr * np.sin(th), -gr * 0.998 * np.cos(th)]
    if order >= 2:
        cx[3:6] = [1.2e-6, -8.0e-7, 6.0e-7]
        cy[3:6] = [-5.0e-7, 9.0e-7, 1.1e-6]
    if order >= 3:
        cx[6:10] = [2.0e-10, -1.5e-10, 1.0e-10, 1.8e-10]
        cy[6:10] = [-1.2e-10, 1.0e-10, 2.0e-10, -1.6e-10]
    return cx, cy


def eval_raw(cx, cy, col, row):
    """Evaluate raw-pixel polynomial coefficients at ``(col, row)``."""
    from ..core.rectification.polynomial import TERMS
    col = np.asarray(col, float)
    row = np.asarray(row, float)
    x = np.zeros_like(col)
    y = np.zeros_like(col)
    for k, (i, j) in enumerate(TERMS[:len(cx)]):
        t = col ** i * row ** j
        x = x + cx[k] * t
        y = y + cy[k] * t
    return x, y


def synthetic_gcps(order: int, *, noise: float = 0.0, seed: int = 0):
    """``(pixel, map, (cx, cy), image_size)``: the 22 image-1 GCPs with map coordinates
    from the known polynomial of ``order`` plus N(0, ``noise``²) per axis."""
    pix, size = image1_pixels()
    cx, cy = true_coefficients(order)
    x, y = eval_raw(cx, cy, pix[:, 0], pix[:, 1])
    if noise:
        rng = np.random.default_rng(seed)
        x = x + rng.normal(0.0, noise, x.size)
        y = y + rng.normal(0.0, noise, y.size)
    return pix, np.column_stack([x, y]), (cx, cy), size


def write_test_image(path, width: int, height: int, *, bands: int = 1,
                     dtype: str = "uint8", nodata: Optional[float] = None,
                     seed: int = 0) -> str:
    """A textured, non-georeferenced GeoTIFF (no CRS, no geotransform, no GCPs): a grid
    pattern plus noise, so that every resampling difference shows."""
    from osgeo import gdal
    gdal.UseExceptions()
    rng = np.random.default_rng(seed)
    r, c = np.mgrid[0:height, 0:width]
    gdt = {"uint8": gdal.GDT_Byte, "uint16": gdal.GDT_UInt16,
           "float32": gdal.GDT_Float32}[dtype]
    with atomic_output(os.fspath(path)) as tmp:
        ds = gdal.GetDriverByName("GTiff").Create(tmp, width, height, bands, gdt)
        for b in range(1, bands + 1):
            base = ((r // 16 + c // 16) % 2) * 120 + (r * 7 + c * 3 * b) % 97
            arr = base + rng.integers(0, 30, size=base.shape)
            band = ds.GetRasterBand(b)
            band.WriteArray(arr.astype(np.dtype(dtype)))
            if nodata is not None:
                band.SetNoDataValue(float(nodata))
        ds.FlushCache()
        ds = None
    return os.fspath(path)


#: known transformations of the image-1 positions (map = T(col, row))
TRUE_LINEAR = {"shift_x": -308100.0, "shift_y": 155950.0, "scale_x": 0.912,
               "scale_y": -0.905}
TRUE_HELMERT = {"shift_x": -308100.0, "shift_y": 155950.0, "scale": 0.91,
                "rotation_deg": 0.4}
TRUE_PROJECTIVE = np.array([[0.912, 0.0064, -308100.0],
                            [0.0061, -0.905, 155950.0],
                            [3.0e-6, -2.0e-6, 1.0]])


def transformed_gcps(kind: str, *, noise: float = 0.0, seed: int = 0):
    """``(pixel, map, truth, image_size)``: image-1 GCP positions pushed through a known
    ``linear``, ``helmert``, ``projective`` or ``polynomial1…3`` transformation plus
    N(0, ``noise``²) per axis (``truth``: its parameters)."""
    pix, size = image1_pixels()
    c, r = pix[:, 0], pix[:, 1]
    if kind == "linear":
        t = TRUE_LINEAR
        x, y = t["shift_x"] + t["scale_x"] * c, t["shift_y"] + t["scale_y"] * r
    elif kind == "helmert":
        t = TRUE_HELMERT
        a = t["scale"] * np.cos(np.radians(t["rotation_deg"]))
        b = t["scale"] * np.sin(np.radians(t["rotation_deg"]))
        x, y = t["shift_x"] + a * c + b * r, t["shift_y"] + b * c - a * r
    elif kind == "projective":
        t = TRUE_PROJECTIVE
        w = t[2, 0] * c + t[2, 1] * r + 1.0
        x = (t[0, 0] * c + t[0, 1] * r + t[0, 2]) / w
        y = (t[1, 0] * c + t[1, 1] * r + t[1, 2]) / w
    else:
        t = true_coefficients(int(kind[-1]))
        x, y = eval_raw(*t, c, r)
    if noise:
        rng = np.random.default_rng(seed)
        x = x + rng.normal(0.0, noise, x.size)
        y = y + rng.normal(0.0, noise, y.size)
    return pix, np.column_stack([x, y]), t, size

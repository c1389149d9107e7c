"""Ground sampling distance (GSD) and photogrammetric accuracy calculator.

Reference: Al Khalil, O. (2019). Proposition of a methodology to assess
photo-triangulation and dense matching algorithms accuracy in image-based 3D
documentation systems. Tishreen University Journal for Research and Scientific
Studies, Engineering Sciences Series (spec: ``seeds/04-gsd-accuracy-calculator.md``).

Units follow the paper: distances in m, sensor sizes and focal lengths in mm, image
sizes in px, GSD in cm/px, σ_meas and σ_xyz in mm, dense-cloud resolution in cm.

============================  =====================================  =========
quantity                      formula                                paper eq.
============================  =====================================  =========
GSD [cm/px]                   D·S_W·100 / (Im_w·F_R)                 5
distance for a GSD [m]        Im_w·GSD·F_R / (S_W·100)               4
footprint width [m]           D·S_W / F_R  (= Im_w·GSD/100)          1, 3
σ_meas                        k_m·GSD,  k_m = 0.3 px                 6
σ_xyz                         k_m·GSD·k_s,  k_s = 2                  7
matching step P [px]          T_s / N_p                              8a
dense resolution R_theo       P·GSD                                  8b
============================  =====================================  =========

Extensions (not in the paper, labelled as such in reports): normal-case stereo depth
precision σ_Z = (D/B)·(D/c)·σ_image (Kraus 2007, *Photogrammetry*, §4.3) and flight
planning — air base B = footprint_along·(1 − p), line spacing A =
footprint_across·(1 − q) for forward overlap p and side overlap q.

All functions accept scalars or numpy arrays (batch use) and raise ``ValueError``
naming the parameter when a value is out of range.

Examples
--------
The paper's worked example (Nikon Coolpix P100 at 5.88 m):

>>> round(float(gsd(5.88, 6.123, 3648, 4.6)), 5)
0.21455
>>> r = compute(distance=5.88, sensor_width=6.123, image_width=3648, focal_length=4.6)
>>> round(r.sigma_xyz_mm, 3), round(r.dense_resolution_cm, 3), round(r.footprint_width_m, 3)
(1.287, 0.858, 7.827)
>>> r = compute(distance=5.88, sensor_width=6.123, image_width=3648, focal_length=4.6,
...             round_gsd=True)
>>> r.gsd_cm, round(r.sigma_xyz_mm, 2), round(r.dense_resolution_cm, 2)
(0.21, 1.26, 0.84)
"""
from __future__ import annotations

import math
from dataclasses import asdict, dataclass, field
from typing import Optional

import numpy as np

from ..errors import InputError

K_M = 0.3        # px, image-measurement precision factor (Gülch 1995 via the paper)
K_M_EXPERT = 0.13
K_S = 2.0        # safety factor, natural points at close range
N_P = 0.5        # image pyramid level used for dense matching (fraction)
T_S = 2.0        # dense-matching subsampling step (px), 2 when unknown


def _check(name: str, value, *, unit: str = "", low: float = 0.0, low_inclusive=False,
           high: Optional[float] = None, high_inclusive=True, hint: str = ""):
    arr = np.asarray(value, dtype=float)
    if arr.size == 0:
        raise InputError("{name} is empty.", name=name)
    if not np.all(np.isfinite(arr)):
        raise InputError("{name} must be a finite number{unit}, got {value}.", name=name,
                         unit=(" in " + unit) if unit else "", value=repr(value))
    bad_low = arr < low if low_inclusive else arr <= low
    bad_high = np.zeros_like(bad_low) if high is None else (
        arr > high if high_inclusive else arr >= high)
    if np.any(bad_low | bad_high):
        shown = arr[bad_low | bad_high].ravel()[0]
        lo = "[" if low_inclusive else "("
        hi = "" if high is None else (f", {high:g}]" if high_inclusive else f", {high:g})")
        rng = f"in {lo}{low:g}{hi}" if high is not None else (
            f"{'≥' if low_inclusive else '>'} {low:g}")
        u = f" {unit}" if unit else ""
        raise InputError("{name} must be {range}{unit}, got {value}{unit}.{hint}",
                         name=name, range=rng, unit=u, value=f"{shown:g}",
                         hint=f" {hint}" if hint else "")
    return arr if arr.ndim else float(arr)


def _positive(name, value, unit, hint=""):
    return _check(name, value, unit=unit, hint=hint)


_FOCAL_HINT = "Enter the true focal length of the lens, not the 35 mm equivalent."


def gsd(distance, sensor_width, image_width, focal_length):
    """Ground sampling distance, cm/px (paper eq. 5).

    Parameters
    ----------
    distance : float or array
        Mean camera–object distance (flying height above ground), m.
    sensor_width : float or array
        Sensor width S_W, mm.
    image_width : float or array
        Image width Im_w, px.
    focal_length : float or array
        True focal length F_R, mm.
    """
    d = _positive("distance", distance, "m")
    sw = _positive("sensor_width", sensor_width, "mm")
    iw = _positive("image_width", image_width, "px")
    f = _positive("focal_length", focal_length, "mm", _FOCAL_HINT)
    return d * sw * 100.0 / (iw * f)


def distance_for_gsd(target_gsd, sensor_width, image_width, focal_length):
    """Distance (or flying height) that gives ``target_gsd`` cm/px, m (paper eq. 4)."""
    g = _positive("target_gsd", target_gsd, "cm/px")
    sw = _positive("sensor_width", sensor_width, "mm")
    iw = _positive("image_width", image_width, "px")
    f = _positive("focal_length", focal_length, "mm", _FOCAL_HINT)
    return iw * g * f / (sw * 100.0)


def footprint(distance, sensor_size, focal_length):
    """Ground footprint of one image side, m (paper eqs. 1, 3): D·S/F_R."""
    d = _positive("distance", distance, "m")
    s = _positive("sensor_size", sensor_size, "mm")
    f = _positive("focal_length", focal_length, "mm", _FOCAL_HINT)
    return d * s / f


def sigma_measurement(gsd_cm, *, k_m: float = K_M):
    """Image-measurement precision σ_meas = k_m·GSD, in the unit of ``gsd_cm`` (eq. 6)."""
    g = _positive("gsd", gsd_cm, "cm/px")
    k = _positive("k_m", k_m, "px")
    return k * g


def sigma_xyz(gsd_cm, *, k_m: float = K_M, k_s: float = K_S):
    """Theoretical phototriangulation accuracy σ_xyz = k_m·GSD·k_s (eq. 7)."""
    ks = _positive("k_s", k_s, "")
    return sigma_measurement(gsd_cm, k_m=k_m) * ks


def pyramid_fraction(pyramid_level, *, percent: bool = False) -> float:
    """N_p as a fraction in (0, 1]; ``percent=True`` reads 50 as 0.5."""
    if percent:
        v = _check("pyramid_level", pyramid_level, unit="%", high=100.0,
                   hint="Give the image pyramid level as a percentage in (0, 100], "
                        "e.g. 50 for half resolution.")
        return v / 100.0
    return _check("pyramid_level", pyramid_level, high=1.0,
                  hint="N_p is the image pyramid level as a fraction: 1 full resolution, "
                       "0.5 half, 0.25 quarter … 1/32.")


def matching_step(*, pyramid_level=N_P, subsampling_step=T_S, percent: bool = False):
    """Dense-matching step P = T_s / N_p, px (eq. 8a)."""
    n = pyramid_fraction(pyramid_level, percent=percent)
    t = _check("subsampling_step", subsampling_step, unit="px", low=1.0, low_inclusive=True,
               hint="T_s is the dense-matching subsampling step (1 … 16 px; 2 if unknown).")
    return t / n


def dense_resolution(gsd_cm, *, pyramid_level=N_P, subsampling_step=T_S,
                     percent: bool = False):
    """Theoretical dense-cloud resolution R_theo = P·GSD, cm (eq. 8b)."""
    g = _positive("gsd", gsd_cm, "cm/px")
    return matching_step(pyramid_level=pyramid_level, subsampling_step=subsampling_step,
                         percent=percent) * g


def observed_sigma_xyz(sx, sy, sz):
    """Return the combined 3-D standard deviation √(σx² + σy² + σz²) of per-axis values."""
    vals = [_check(n, v, low=0.0, low_inclusive=True) for n, v in
            (("observed_sx", sx), ("observed_sy", sy), ("observed_sz", sz))]
    return np.sqrt(sum(np.square(v) for v in vals))


def accuracy_ratio(observed, theoretical):
    """Observed / theoretical (the paper finds ≈3–5 for phototriangulation)."""
    o = _check("observed", observed, low=0.0, low_inclusive=True)
    t = _positive("theoretical", theoretical, "")
    return o / t


def stereo_depth_precision(distance, base, focal_length, sigma_image):
    """Normal-case stereo depth precision σ_Z = (D/B)·(D/c)·σ_image, m (extension).

    Parameters
    ----------
    distance : float
        Object distance D, m.
    base : float
        Stereo base B, m.
    focal_length : float
        Principal distance c, mm.
    sigma_image : float
        Image-measurement (parallax) precision, mm on the sensor
        (σ_px × pixel pitch).
    """
    d = _positive("distance", distance, "m")
    b = _positive("base", base, "m")
    c = _positive("focal_length", focal_length, "mm", _FOCAL_HINT)
    s = _check("sigma_image", sigma_image, unit="mm", low=0.0, low_inclusive=True)
    return (d / b) * (d / c) * s


def flight_spacing(footprint_along, footprint_across, *, forward_overlap=80.0,
                   side_overlap=70.0):
    """Air base (exposure spacing) and flight-line spacing for given overlaps (extension).

    Overlaps in percent, [0, 100). Returns ``(base_m, line_spacing_m)``.
    """
    fa = _positive("footprint_along", footprint_along, "m")
    fx = _positive("footprint_across", footprint_across, "m")
    p = _check("forward_overlap", forward_overlap, unit="%", low=0.0, low_inclusive=True,
               high=100.0, high_inclusive=False)
    q = _check("side_overlap", side_overlap, unit="%", low=0.0, low_inclusive=True,
               high=100.0, high_inclusive=False)
    return fa * (1.0 - p / 100.0), fx * (1.0 - q / 100.0)


@dataclass
class GsdResult:
    """Everything the calculator derives for one camera and distance.

    ``None`` marks quantities whose inputs were not given.
    """

    gsd_cm: float
    gsd_exact_cm: float
    pixel_pitch_um: float
    footprint_width_m: float
    footprint_height_m: Optional[float]
    sigma_meas_mm: float
    sigma_xyz_mm: float
    matching_step_px: float
    dense_resolution_cm: float
    distance_for_target_m: Optional[float] = None
    observed_sigma_xyz_mm: Optional[float] = None
    ratio_xyz: Optional[float] = None
    ratio_dense: Optional[float] = None
    stereo_base_m: Optional[float] = None
    stereo_sigma_xy_mm: Optional[float] = None
    stereo_sigma_z_mm: Optional[float] = None
    exposure_spacing_m: Optional[float] = None
    line_spacing_m: Optional[float] = None
    inputs: dict = field(default_factory=dict)

    def as_dict(self) -> dict:
        """Return every result quantity by name (without the echoed inputs)."""
        out = asdict(self)
        out.pop("inputs")
        return out


def compute(*, distance: float, sensor_width: float, image_width: float,
            focal_length: float, sensor_height: Optional[float] = None,
            image_height: Optional[float] = None, target_gsd: Optional[float] = None,
            k_m: float = K_M, k_s: float = K_S, pyramid_level: float = N_P,
            pyramid_percent: bool = False, subsampling_step: float = T_S,
            round_gsd: bool = False, observed_sx: Optional[float] = None,
            observed_sy: Optional[float] = None, observed_sz: Optional[float] = None,
            observed_sxyz: Optional[float] = None,
            observed_dense_std: Optional[float] = None,
            stereo_base: Optional[float] = None,
            forward_overlap: Optional[float] = None,
            side_overlap: Optional[float] = None) -> GsdResult:
    """Run the whole calculator for one camera and distance.

    Parameters
    ----------
    distance : float
        Camera–object distance D (or flying height above ground), m.
    sensor_width, image_width, focal_length : float
        S_W (mm), Im_w (px), true focal length F_R (mm).
    sensor_height, image_height : float, optional
        S_H (mm) and Im_h (px) for the footprint height. With only ``image_height``
        square pixels are assumed (S_H = Im_h·S_W/Im_w).
    target_gsd : float, optional
        GSD wanted, cm/px → :attr:`GsdResult.distance_for_target_m`.
    k_m, k_s : float
        Measurement factor (px, default 0.3; 0.13 for an expert operator) and safety
        factor (default 2).
    pyramid_level, pyramid_percent, subsampling_step : float, bool, float
        N_p (fraction, or percent when ``pyramid_percent``), default 0.5; T_s, default 2.
    round_gsd : bool
        Round the GSD to 0.01 cm/px before the derived quantities, as the paper does
        (σ_xyz 1.26 mm instead of 1.287 mm in its example).
    observed_sx, observed_sy, observed_sz, observed_sxyz : float, optional
        Observed check-point standard deviations, mm. ``observed_sxyz`` wins over the
        combination √(σx²+σy²+σz²) of the components.
    observed_dense_std : float, optional
        Observed dense-cloud standard deviation (e.g. M3C2), cm.
    stereo_base : float, optional
        Stereo base B, m → normal-case σ_Z (extension). Derived from the footprint
        and ``forward_overlap`` when not given.
    forward_overlap, side_overlap : float, optional
        Percent; → exposure spacing (along the image height) and line spacing
        (across, along the image width) (extension).
    """
    g_exact = float(gsd(distance, sensor_width, image_width, focal_length))
    g = round(g_exact, 2) if round_gsd else g_exact
    if not math.isfinite(g_exact):
        raise InputError("The GSD is not finite; check the inputs.")
    if g <= 0:
        raise InputError("The GSD rounds to 0 cm/px ({value}); do not round it.",
                         value=f"{g_exact:.5f}")
    res = _base_result(g, g_exact, distance, sensor_width, image_width, focal_length,
                       sensor_height, image_height, k_m=k_m, k_s=k_s,
                       pyramid_level=pyramid_level, pyramid_percent=pyramid_percent,
                       subsampling_step=subsampling_step)
    if target_gsd is not None:
        res.distance_for_target_m = float(distance_for_gsd(target_gsd, sensor_width,
                                                           image_width, focal_length))
    _add_observed(res, observed_sx, observed_sy, observed_sz, observed_sxyz,
                  observed_dense_std)
    stereo_base = _add_flight_spacing(res, forward_overlap, side_overlap, stereo_base)
    if stereo_base is not None:
        _add_stereo(res, stereo_base, distance, sensor_width, image_width, focal_length, k_m)
    res.inputs = dict(distance=distance, sensor_width=sensor_width, image_width=image_width,
                      focal_length=focal_length, sensor_height=sensor_height,
                      image_height=image_height, target_gsd=target_gsd, k_m=k_m, k_s=k_s,
                      pyramid_level=pyramid_level, pyramid_percent=pyramid_percent,
                      subsampling_step=subsampling_step, round_gsd=round_gsd)
    return res


def _base_result(g, g_exact, distance, sensor_width, image_width, focal_length,
                 sensor_height, image_height, *, k_m, k_s, pyramid_level, pyramid_percent,
                 subsampling_step) -> GsdResult:
    """GSD, footprint, σ and dense-matching quantities (paper eqs. 1-8)."""
    fw = float(footprint(distance, sensor_width, focal_length))
    fh = None
    if sensor_height is not None or image_height is not None:
        if sensor_height is None:
            ih = _positive("image_height", image_height, "px")
            sensor_height = ih * float(sensor_width) / float(image_width)
        fh = float(footprint(distance, sensor_height, focal_length))
    dense = dict(pyramid_level=pyramid_level, subsampling_step=subsampling_step,
                 percent=pyramid_percent)
    return GsdResult(
        gsd_cm=g,
        gsd_exact_cm=g_exact,
        pixel_pitch_um=1000.0 * float(sensor_width) / float(image_width),
        footprint_width_m=fw,
        footprint_height_m=fh,
        sigma_meas_mm=10.0 * float(sigma_measurement(g, k_m=k_m)),
        sigma_xyz_mm=10.0 * float(sigma_xyz(g, k_m=k_m, k_s=k_s)),
        matching_step_px=float(matching_step(**dense)),
        dense_resolution_cm=float(dense_resolution(g, **dense)),
    )


def _add_observed(res: GsdResult, sx, sy, sz, sxyz, dense_std) -> None:
    """Observed σxyz and the observed/theoretical ratios (paper section 4)."""
    if sxyz is not None:
        res.observed_sigma_xyz_mm = float(_check("observed_sxyz", sxyz, unit="mm"))
    elif None not in (sx, sy, sz):
        res.observed_sigma_xyz_mm = float(observed_sigma_xyz(sx, sy, sz))
    elif any(v is not None for v in (sx, sy, sz)):
        raise InputError("Give all three observed σx, σy, σz (mm), or the combined σxyz.")
    if res.observed_sigma_xyz_mm is not None:
        res.ratio_xyz = float(accuracy_ratio(res.observed_sigma_xyz_mm, res.sigma_xyz_mm))
    if dense_std is not None:
        res.ratio_dense = float(accuracy_ratio(dense_std, res.dense_resolution_cm))


def _add_flight_spacing(res: GsdResult, forward_overlap, side_overlap, stereo_base):
    """Exposure and line spacing; returns the stereo base to use (extension)."""
    if forward_overlap is None and side_overlap is None:
        return stereo_base
    if res.footprint_height_m is None:
        raise InputError("Flight spacing needs the footprint height: give the sensor "
                         "height (mm) or the image height (px).")
    base, line = flight_spacing(res.footprint_height_m, res.footprint_width_m,
                                forward_overlap=forward_overlap or 0.0,
                                side_overlap=side_overlap or 0.0)
    res.exposure_spacing_m = float(base) if forward_overlap is not None else None
    res.line_spacing_m = float(line) if side_overlap is not None else None
    if stereo_base is None and forward_overlap is not None:
        return float(base)
    return stereo_base


def _add_stereo(res: GsdResult, stereo_base, distance, sensor_width, image_width,
                focal_length, k_m) -> None:
    """Normal-case stereo precision σ_XY, σ_Z (extension, Kraus 2007)."""
    pitch_mm = float(sensor_width) / float(image_width)
    sigma_img_mm = _positive("k_m", k_m, "px") * pitch_mm
    res.stereo_base_m = float(_positive("stereo_base", stereo_base, "m"))
    res.stereo_sigma_z_mm = 1000.0 * float(stereo_depth_precision(
        distance, stereo_base, focal_length, sigma_img_mm))
    res.stereo_sigma_xy_mm = 1000.0 * float(distance) / float(focal_length) * sigma_img_mm

"""Report content of the GSD / photogrammetric accuracy calculator (Al Khalil 2019).

The algorithm renders it with the one report renderer in the user's language.
"""
from __future__ import annotations

from typing import Optional

from ..reporting import Formula, KeyValues, Paragraph, Report, T
from .gsd import GsdResult

#: (result attribute, English label, unit) of every result quantity, in report order.
RESULT_ROWS = (
    ("gsd_cm", "GSD used", "cm/px"),
    ("gsd_exact_cm", "GSD, unrounded", "cm/px"),
    ("pixel_pitch_um", "Pixel pitch", "µm"),
    ("footprint_width_m", "Footprint width", "m"),
    ("footprint_height_m", "Footprint height", "m"),
    ("sigma_meas_mm", "Image measurement precision σ_meas", "mm"),
    ("sigma_xyz_mm", "Theoretical phototriangulation accuracy σ_xyz", "mm"),
    ("matching_step_px", "Dense matching step P", "px"),
    ("dense_resolution_cm", "Theoretical dense-cloud resolution R_theo", "cm"),
    ("distance_for_target_m", "Distance for the target GSD", "m"),
    ("observed_sigma_xyz_mm", "Observed σxyz", "mm"),
    ("ratio_xyz", "Observed / theoretical σxyz", ""),
    ("ratio_dense", "Observed dense std / R_theo", ""),
    ("stereo_base_m", "Stereo base (extension)", "m"),
    ("stereo_sigma_xy_mm", "Stereo planimetric precision (extension)", "mm"),
    ("stereo_sigma_z_mm", "Stereo depth precision σ_Z (extension)", "mm"),
    ("exposure_spacing_m", "Exposure spacing (extension)", "m"),
    ("line_spacing_m", "Flight-line spacing (extension)", "m"),
)

_INPUT_ROWS = (
    ("distance", "Distance", "m"),
    ("sensor_width", "Sensor width", "mm"),
    ("image_width", "Image width", "px"),
    ("focal_length", "Focal length", "mm"),
    ("sensor_height", "Sensor height", "mm"),
    ("image_height", "Image height", "px"),
    ("target_gsd", "Target GSD", "cm/px"),
    ("k_m", "Measurement factor k_m", "px"),
    ("k_s", "Safety factor k_s", ""),
    ("pyramid_level", "Pyramid level N_p", ""),
    ("subsampling_step", "Subsampling step T_s", "px"),
)


def gsd_report(result: GsdResult, *, camera: Optional[str] = None) -> Report:
    """Build the calculator's report (inputs, formulas, results) as content.

    Parameters
    ----------
    result : GsdResult
        Output of :func:`~.gsd.compute` (its ``inputs`` echo the arguments).
    camera : str, optional
        Name of the camera preset used, shown as data.

    Returns
    -------
    Report
        Sections "Inputs", "Formulas" and "Results"; numbers keep six significant
        digits (Al Khalil 2019 quotes 0.21455 cm/px).
    """
    report = Report("GSD and photogrammetric accuracy")
    report.summary.append(Paragraph(T("GSD {gsd} cm/px; theoretical accuracy σ_xyz "
                                      "{sxyz} mm.", gsd=result.gsd_cm,
                                      sxyz=result.sigma_xyz_mm)))
    rows = [] if camera is None else [("Camera preset", camera, "")]
    rows += [(label, result.inputs[key], unit) for key, label, unit in _INPUT_ROWS
             if result.inputs.get(key) is not None]
    if result.inputs.get("round_gsd"):
        rows.append(("Round GSD to 0.01 cm/px like the paper", True, ""))
    report.section("Inputs").add(KeyValues(rows, digits=None))
    formulas = report.section("Formulas")
    for text in ("GSD = D·S_W·100 / (Im_W·F_R)", "footprint = D·S_W / F_R",
                 "σ_meas = k_m·GSD", "σ_xyz = k_m·GSD·k_s", "P = T_s / N_p",
                 "R_theo = P·GSD"):
        formulas.add(Formula(text))
    values = result.as_dict()
    report.section("Results").add(KeyValues(
        [(label, values[key], unit) for key, label, unit in RESULT_ROWS
         if values[key] is not None], digits=None))
    report.citation = ("Formulas and defaults from Al Khalil (2019); the paper finds observed "
                       "phototriangulation accuracy about 3–5 times the theoretical value. "
                       "Items marked (extension) are not in the paper.")
    return report

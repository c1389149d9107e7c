"""GSD / accuracy calculator: golden numbers of Al Khalil (2019), exact and rounded."""
import math

import numpy as np
import pytest

from geomatics_toolbox.core.photogrammetry import gsd
from geomatics_toolbox.core.photogrammetry.cameras import CAMERAS, camera

P100 = dict(sensor_width=6.123, image_width=3648, focal_length=4.6)


def test_gsd_exact_golden():
    assert gsd.gsd(5.88, **P100) == pytest.approx(0.21455, abs=5e-6)


def test_paper_chain_unrounded():
    r = gsd.compute(distance=5.88, **P100, target_gsd=0.21)
    assert r.gsd_cm == pytest.approx(0.21455, abs=5e-6)
    assert r.sigma_xyz_mm == pytest.approx(1.287, abs=5e-4)
    assert r.sigma_meas_mm == pytest.approx(0.6437, abs=5e-4)
    assert r.matching_step_px == 4.0
    assert r.dense_resolution_cm == pytest.approx(0.858, abs=5e-4)
    assert r.footprint_width_m == pytest.approx(7.827, abs=5e-4)
    assert r.distance_for_target_m == pytest.approx(5.755, abs=5e-4)
    assert r.pixel_pitch_um == pytest.approx(1.6787, abs=2e-3)


def test_paper_chain_rounded_like_the_paper():
    r = gsd.compute(distance=5.88, **P100, round_gsd=True)
    assert r.gsd_cm == 0.21
    assert r.gsd_exact_cm == pytest.approx(0.21455, abs=5e-6)
    assert r.sigma_xyz_mm == pytest.approx(1.26, abs=1e-9)
    assert r.dense_resolution_cm == pytest.approx(0.84, abs=1e-9)


@pytest.mark.parametrize("software, sxyz, ratio", [
    ("Metashape", 3.85, 3.06), ("Pix4D", 4.00, 3.17), ("Zephyr", 7.6, 6.03)])
def test_observed_over_theoretical_ratios(software, sxyz, ratio):
    r = gsd.compute(distance=5.88, **P100, round_gsd=True, observed_sxyz=sxyz)
    assert round(r.ratio_xyz, 2) == ratio, software


def test_ratio_from_components_and_dense_cloud():
    r = gsd.compute(distance=5.88, **P100, round_gsd=True, observed_sx=2.5,
                    observed_sy=1.61, observed_sz=2.4, observed_dense_std=1.1)
    assert r.observed_sigma_xyz_mm == pytest.approx(math.sqrt(2.5**2 + 1.61**2 + 2.4**2))
    assert r.ratio_dense == pytest.approx(1.1 / 0.84)
    with pytest.raises(ValueError, match="all three"):
        gsd.compute(distance=5.88, **P100, observed_sx=2.5)


def test_inverse_is_exact_inverse():
    rng = np.random.default_rng(3)
    d = rng.uniform(1, 500, 100)
    sw, iw, f = rng.uniform(2, 60, 100), rng.integers(1000, 12000, 100), rng.uniform(3, 100, 100)
    g = gsd.gsd(d, sw, iw, f)
    np.testing.assert_allclose(gsd.distance_for_gsd(g, sw, iw, f), d, rtol=1e-12)
    # footprint = Im_w · GSD / 100 (eqs. 1 and 3 agree)
    np.testing.assert_allclose(gsd.footprint(d, sw, f), iw * g / 100.0, rtol=1e-12)


def test_pyramid_percent_equals_fraction():
    assert gsd.matching_step(pyramid_level=50, percent=True) == 4.0
    assert gsd.matching_step(pyramid_level=0.25, subsampling_step=1) == 4.0
    assert gsd.dense_resolution(0.21, pyramid_level=1, subsampling_step=1) == 0.21


def test_dji_rule_of_thumb_h_over_36_5():
    """DJI's published GSD rule for the Phantom 4 RTK: GSD = H/36.5 cm/px."""
    c = camera("dji_p4rtk")
    g = gsd.gsd(100.0, c.sensor_width_mm, c.image_width_px, c.focal_length_mm)
    assert g == pytest.approx(100.0 / 36.5, rel=2e-3)


def test_camera_presets_are_consistent():
    assert CAMERAS["nikon_p100"].pixel_pitch_um == pytest.approx(1.6787, abs=1e-3)
    for cam in CAMERAS.values():
        # square pixels: width and height pitch agree within 1 %
        pitch_h = 1000 * cam.sensor_height_mm / cam.image_height_px
        assert cam.pixel_pitch_um == pytest.approx(pitch_h, rel=0.01), cam.key
        assert cam.source
    with pytest.raises(ValueError, match="Unknown camera preset"):
        camera("nope")


def test_stereo_extension_normal_case():
    # σ_Z = (D/B)(D/c)σ_image; D = 100 m, B = 40 m, c = 8.8 mm, σ = 0.0024 mm → 0.682 m
    assert gsd.stereo_depth_precision(100, 40, 8.8, 0.0024) == pytest.approx(
        (100 / 40) * (100 / 8.8) * 0.0024)
    r = gsd.compute(distance=100, sensor_width=13.2, image_width=5472, focal_length=8.8,
                    image_height=3648, forward_overlap=80, side_overlap=70)
    fh = 100 * 8.8 / 8.8  # sensor height 8.8 mm (square pixels) → 100 m along track
    assert r.footprint_height_m == pytest.approx(fh)
    assert r.exposure_spacing_m == pytest.approx(0.2 * fh)
    assert r.line_spacing_m == pytest.approx(0.3 * 150.0)
    assert r.stereo_base_m == pytest.approx(0.2 * fh)
    pitch = 13.2 / 5472
    assert r.stereo_sigma_z_mm == pytest.approx(
        1000 * (100 / 20) * (100 / 8.8) * 0.3 * pitch)


@pytest.mark.parametrize("kwargs, match", [
    (dict(distance=5.88, sensor_width=6.123, image_width=3648, focal_length=0), "focal_length"),
    (dict(distance=5.88, sensor_width=6.123, image_width=3648, focal_length=-4.6),
     "focal_length"),
    (dict(distance=0, sensor_width=6.123, image_width=3648, focal_length=4.6), "distance"),
    (dict(distance=-1, sensor_width=6.123, image_width=3648, focal_length=4.6), "distance"),
    (dict(distance=5.88, sensor_width=6.123, image_width=0, focal_length=4.6), "image_width"),
    (dict(distance=5.88, sensor_width=-6, image_width=3648, focal_length=4.6), "sensor_width"),
    (dict(distance=5.88, **P100, pyramid_level=0), "pyramid_level"),
    (dict(distance=5.88, **P100, pyramid_level=1.5), "pyramid_level"),
    (dict(distance=5.88, **P100, subsampling_step=0.5), "subsampling_step"),
    (dict(distance=float("nan"), **P100), "distance"),
])
def test_bad_inputs_name_the_parameter(kwargs, match):
    with pytest.raises(ValueError, match=match):
        gsd.compute(**kwargs)


def test_error_message_is_helpful():
    with pytest.raises(ValueError) as err:
        gsd.gsd(5.88, 6.123, 3648, 0)
    assert "> 0 mm" in str(err.value) and "35 mm equivalent" in str(err.value)
    with pytest.raises(ValueError) as err:
        gsd.compute(distance=5.88, **P100, pyramid_level=2)
    assert "(0, 1]" in str(err.value)

"""qgis_process smoke tests for the GSD calculator and the provider listing."""
import re

import pytest


def test_provider_and_algorithms_listed(qgis_process):
    out = qgis_process.call("list")
    assert out.returncode == 0, out.stderr
    assert "Geomatics Toolbox" in out.stdout
    for alg in ("geomatics:gsdcalculator", "geomatics:gsdbatch"):
        assert alg in out.stdout


def test_help_shows_defaults_and_units(qgis_process):
    out = qgis_process.call("help", "geomatics:gsdcalculator")
    assert out.returncode == 0, out.stderr
    plain = re.sub(r"<[^>]+>", "", out.stdout)      # the help is HTML (build_help)
    for text in ("DISTANCE", "SENSOR_WIDTH", "IMAGE_WIDTH", "FOCAL_LENGTH", "(mm)", "(px)",
                 "(m)", "K_M (default: 0.3; advanced)"):
        assert text in plain, text


def test_run_gsd_json(qgis_process, tmp_path):
    html = tmp_path / "r.html"
    res = qgis_process.run("geomatics:gsdcalculator", DISTANCE=5.88, SENSOR_WIDTH=6.123,
                           IMAGE_WIDTH=3648, FOCAL_LENGTH=4.6, OUTPUT_HTML=html)
    r = res["results"]
    assert r["GSD"] == pytest.approx(0.21455, abs=5e-6)
    assert r["SIGMA_XYZ"] == pytest.approx(1.287, abs=5e-4)
    assert html.exists()


def test_run_gsd_bad_focal_length_fails(qgis_process, tmp_path):
    html = tmp_path / "never.html"
    msg = qgis_process.run_expect_failure("geomatics:gsdcalculator", DISTANCE=5.88,
                                          SENSOR_WIDTH=6.123, IMAGE_WIDTH=3648,
                                          FOCAL_LENGTH=0, OUTPUT_HTML=html)
    # the parameter as the dialog (label) and qgis_process (name) show it, not focal_length
    assert ("\u201cFocal length, true (mm) \u2014 required with Custom\u201d (FOCAL_LENGTH) "
            "must be > 0 mm, got 0 mm") in msg
    assert not html.exists()


def test_every_algorithm_has_help_with_defaults(qgis_process):
    """`qgis_process help` works for every registered algorithm and documents defaults."""
    listing = qgis_process.call("list").stdout
    ids = sorted({line.split()[0] for line in listing.splitlines()
                  if line.strip().startswith("geomatics:")})
    assert len(ids) >= 13, ids
    for alg in ids:
        out = qgis_process.call("help", alg)
        assert out.returncode == 0, (alg, out.stderr)
        assert "Arguments" in out.stdout, alg
        if alg != "geomatics:lidar_to_dtm":  # the model documents its inputs per parameter
            assert "default" in out.stdout.lower(), alg

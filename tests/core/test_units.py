"""Linear units of clouds and rasters (core/io/units.py): feet, US survey feet, mixed."""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from geomatics_toolbox.core.io.las import las_info, write_las
from geomatics_toolbox.core.io.raster import write_geotiff
from geomatics_toolbox.core.io.units import (
    FOOT,
    METRE,
    US_FOOT,
    crs_units,
    las_units,
    linear_unit,
    raster_units,
    unit_label,
    unit_name,
)
from geomatics_toolbox.synthetic.hostile import write_geokeys_las

REAL_USFT = Path(__file__).resolve().parents[3] / "shared" / "data" / "real" / "pdal_nm_usft.laz"


def _xyz(n=50):
    rng = np.random.default_rng(1)
    return (rng.uniform(0, 100, n) + 1_500_000, rng.uniform(0, 100, n) + 1_400_000,
            rng.uniform(5000, 5010, n))


@pytest.mark.parametrize("crs,h,v,source", [
    ("EPSG:32632", METRE, METRE, "assumed"),
    ("EPSG:2994", FOOT, FOOT, "assumed"),               # Oregon Lambert, international ft
    ("EPSG:2903", US_FOOT, US_FOOT, "assumed"),         # New Mexico Central, ftUS
    ("EPSG:2903+6360", US_FOOT, US_FOOT, "crs"),        # + NAVD88 height (ftUS)
    ("EPSG:2903+5703", US_FOOT, METRE, "crs"),          # mixed: ftUS plan, metre heights
    ("EPSG:32632+5703", METRE, METRE, "crs"),
])
def test_crs_units(crs, h, v, source):
    u = crs_units(crs)
    assert (u.horizontal, u.vertical, u.vertical_source) == (h, v, source)
    assert u.h == h.metres and u.v == v.metres
    assert u.mixed == (h != v)


def test_no_crs_is_metres_and_degrees_are_angular():
    assert crs_units(None).metric and crs_units(None).vertical_source == "none"
    g = crs_units("EPSG:4326")
    assert g.horizontal.angular and np.isnan(g.h) and g.vertical == METRE


def test_factors_and_conversions():
    assert US_FOOT.metres == pytest.approx(1200 / 3937, rel=1e-15)
    assert FOOT.metres == 0.3048
    u = crs_units("EPSG:2903")
    assert u.h_to_metres(3937.0) == pytest.approx(1200.0)
    assert u.h_from_metres(1200.0) == pytest.approx(3937.0)
    x, y, z = u.xyz_to_metres(np.array([3937.0]), np.array([0.0]), np.array([3937.0]))
    assert (x[0], z[0]) == (pytest.approx(1200.0), pytest.approx(1200.0))
    assert u.area_symbol == "ftUS²"
    assert linear_unit("US survey foot", 0.304800609601219) is US_FOOT   # PROJ's rounding
    assert linear_unit(epsg=9002) is FOOT
    assert linear_unit("ftUS") is US_FOOT


@pytest.mark.parametrize("keys,h,v,source", [
    ({1024: 1, 3072: 2903, 3076: 9003, 4096: 5103, 4099: 9003}, US_FOOT, US_FOOT, "geokeys"),
    ({1024: 1, 3072: 2903, 4099: 9001}, US_FOOT, METRE, "geokeys"),   # mixed
    ({1024: 1, 3072: 2994}, FOOT, FOOT, "assumed"),
    ({1024: 1, 3072: 2903, 4096: 6360}, US_FOOT, US_FOOT, "geokeys"),  # unit of the vertical CRS
    ({1024: 1, 3072: 32632, 4096: 5703}, METRE, METRE, "geokeys"),
])
def test_las_geokeys_units(tmp_path, keys, h, v, source):
    p = write_geokeys_las(tmp_path / "k.las", *_xyz(), keys=keys)
    u = las_info(p).units
    assert (u.horizontal, u.vertical, u.vertical_source) == (h, v, source)
    assert las_units(p) == u


def test_las14_compound_wkt_units(tmp_path):
    p = tmp_path / "c.las"
    write_las(p, *_xyz(), crs="EPSG:2903+6360", version="1.4")
    u = las_info(p).units
    assert (u.horizontal, u.vertical, u.vertical_source) == (US_FOOT, US_FOOT, "crs")


def test_real_us_survey_feet_file():
    if not REAL_USFT.exists():
        pytest.skip(f"{REAL_USFT} not found (the real-data development set)")
    u = las_info(REAL_USFT).units
    assert (u.horizontal, u.vertical, u.vertical_source) == (US_FOOT, US_FOOT, "geokeys")


def test_raster_units_from_crs_and_band(tmp_path):
    from osgeo import gdal
    p = write_geotiff(tmp_path / "d.tif", np.zeros((3, 3)), geotransform=(0, 1, 0, 3, 0, -1),
                      crs="EPSG:2994")
    assert raster_units(p).horizontal == FOOT and raster_units(p).vertical == FOOT
    ds = gdal.Open(str(p), gdal.GA_Update)
    ds.GetRasterBand(1).SetUnitType("m")
    ds = None
    u = raster_units(p)
    assert (u.horizontal, u.vertical, u.vertical_source) == (FOOT, METRE, "band")


def test_unit_names_translated():
    assert unit_name(US_FOOT, "en") == "US survey foot"
    for lang in ("ar", "fa"):
        for unit in (METRE, FOOT, US_FOOT):
            name = unit_name(unit, lang)
            assert name != unit.name and not any("a" <= ch <= "z" for ch in name.lower())
    assert unit_label(FOOT, "en") == "foot (ft)"

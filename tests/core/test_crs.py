"""The one CRS helper (core/io/crs.py) against GDAL's own answers."""
import pytest

from geomatics_toolbox.core.errors import InputError
from geomatics_toolbox.core.io import crs


def test_label_parse_and_compare():
    assert crs.crs_label("EPSG:32632") == "EPSG:32632 (WGS 84 / UTM zone 32N)"
    wkt = crs.srs_wkt("EPSG:32632")
    assert wkt.startswith("PROJCS[") and crs.same_crs(wkt, "EPSG:32632")
    assert not crs.same_crs("EPSG:32632", "EPSG:32633")
    assert crs.crs_label(None) == "" and crs.srs_wkt("") == ""


def test_geographic_and_units():
    assert crs.is_geographic("EPSG:4326") and not crs.is_geographic("EPSG:32632")
    assert not crs.is_geographic("not a crs")
    # one unit vocabulary: core/io/units.py (crs.linear_unit / warp.linear_units retired)
    from geomatics_toolbox.core.io.units import crs_units
    assert crs_units("EPSG:2263").h == pytest.approx(0.3048006096, rel=1e-9)  # US ft
    assert crs_units("EPSG:32632").horizontal.name == "metre"
    assert crs_units("EPSG:4326").horizontal.angular
    assert not hasattr(crs, "linear_unit")


def test_unknown_crs_is_a_clear_input_error():
    with pytest.raises(InputError, match="Unrecognised CRS 'EPSG:0'"):
        crs.srs_wkt("EPSG:0")

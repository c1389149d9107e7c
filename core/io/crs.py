"""One CRS helper for the whole core: parse, label, compare, geographic test.

Every CRS in the core is a string GDAL's ``OSRSetFromUserInput`` accepts
(``'EPSG:32632'``, WKT, PROJ); this module is the only place that parses one.

Examples
--------
>>> crs_label("EPSG:32632")
'EPSG:32632 (WGS 84 / UTM zone 32N)'
>>> is_geographic("EPSG:4326"), is_geographic("EPSG:32632")
(True, False)
"""
from __future__ import annotations

from typing import Optional

from ..errors import InputError


def spatial_reference(crs: str, *, what: str = "CRS"):
    """Return an ``osr.SpatialReference`` (traditional x=east axis order) for ``crs``.

    Raises
    ------
    InputError
        When GDAL does not recognise ``crs``; the message names ``what``.
    """
    from osgeo import osr
    srs = osr.SpatialReference()
    try:
        ok = srs.SetFromUserInput(str(crs)) == 0
    except RuntimeError:
        ok = False
    if not ok:
        raise InputError("Unrecognised {what} {crs!r}; give e.g. 'EPSG:32632' or a WKT.",
                         what=what,
                         crs=crs)
    srs.SetAxisMappingStrategy(osr.OAMS_TRADITIONAL_GIS_ORDER)
    return srs


def srs_wkt(crs: Optional[str]) -> str:
    """Return the WKT of ``crs``; ``''`` for None or empty."""
    return spatial_reference(crs).ExportToWkt() if crs else ""


def crs_label(crs: Optional[str]) -> str:
    """Return a short label for reports: ``'EPSG:32632 (WGS 84 / UTM zone 32N)'``.

    Falls back to the CRS's name, then to the input text (at most 60 characters);
    ``''`` for None.
    """
    if not crs:
        return ""
    try:
        srs = spatial_reference(crs)
    except InputError:
        return str(crs)[:60]
    name = srs.GetName() or ""
    srs.AutoIdentifyEPSG()
    auth, code = srs.GetAuthorityName(None), srs.GetAuthorityCode(None)
    if auth and code:
        return f"{auth}:{code} ({name})" if name else f"{auth}:{code}"
    return name or str(crs)[:60]


def same_crs(a: Optional[str], b: Optional[str]) -> bool:
    """Return True when the two CRS definitions describe the same CRS."""
    if not a or not b:
        return (a or "") == (b or "")
    return bool(spatial_reference(a).IsSame(spatial_reference(b)))


def is_geographic(crs: Optional[str]) -> bool:
    """Return True for a geographic (degrees) CRS; False for projected or unknown."""
    if not crs:
        return False
    try:
        return bool(spatial_reference(crs).IsGeographic())
    except InputError:
        return False



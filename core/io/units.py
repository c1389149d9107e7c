"""Linear units of a point cloud's or raster's CRS: horizontal and vertical, to metres.

The project's rule (DEVELOPERS.md, "Units"): **every length a user types, and every
default, is in metres** (labels say "(m)"). Data in another linear unit (international
foot, US survey foot, …) is converted on reading: filters and gridders work on metres,
classes are per point, rasters are written back in the data's own CRS and units (cell
size and heights converted), and every log line, report and table names the unit of
the number it shows.

* :func:`crs_units` — units of a CRS string (EPSG code, WKT; compound CRSs give their
  vertical part's unit);
* :func:`header_units` / :func:`las_units` — units of a LAS/LAZ file: the WKT VLR, or
  the GeoTIFF keys (``ProjLinearUnitsGeoKey`` 3076, ``VerticalCSTypeGeoKey`` 4096,
  ``VerticalUnitsGeoKey`` 4099), so US files with horizontal and vertical feet (or feet
  and metres) are read as they declare;
* :func:`raster_units` — units of a GDAL raster (CRS, compound CRS, band unit type);
* :class:`Units` — ``h`` / ``v`` metres per horizontal / vertical unit, conversions,
  symbols (``'m'``, ``'ft'``, ``'ftUS'``) and translated names (:func:`unit_name`).

When nothing says the vertical unit (no vertical CRS, no key, no band unit), it is
taken equal to the horizontal one — what LAS files in feet state planes mean in
practice (PDAL, LAStools do the same); :attr:`Units.vertical_source` says ``'assumed'``.
A cloud or raster with no CRS at all is taken to be in metres (``'none'``).

Examples
--------
>>> u = crs_units("EPSG:2994")            # NAD83(HARN) / Oregon GIC Lambert (ft)
>>> u.horizontal.symbol, u.vertical.symbol, round(u.h, 4)
('ft', 'ft', 0.3048)
>>> u.h_from_metres(1.0) == 1 / 0.3048
True
>>> crs_units("EPSG:2903+6360").vertical.name
'US survey foot'
>>> crs_units("EPSG:32632").metric
True
>>> unit_name(US_FOOT, "en")
'US survey foot'
"""
from __future__ import annotations

import math
import os
from dataclasses import dataclass
from typing import Optional

import numpy as np


@dataclass(frozen=True, eq=False)
class LinearUnit:
    """A linear unit: English name (as PROJ spells it), metres per unit, symbol.

    Two units are equal when they mean the same length (metres per unit within 1e-9,
    or both degrees): PROJ, GeoTIFF keys and band unit types name one unit several
    ways, and ``LinearUnit("metre", 1.0, "m")`` is the metre whatever its EPSG code.
    """

    name: str
    metres: float
    symbol: str
    epsg: Optional[int] = None

    def __eq__(self, other) -> bool:
        """Return True when both units mean the same length."""
        if not isinstance(other, LinearUnit):
            return NotImplemented
        if self.angular or other.angular:
            return self.angular and other.angular
        return math.isclose(self.metres, other.metres, rel_tol=1e-9)

    def __hash__(self) -> int:
        """Hash by meaning (metres per unit)."""
        return hash("°") if self.angular else hash(float(f"{self.metres:.8g}"))

    @property
    def angular(self) -> bool:
        """Return True for degrees (a geographic CRS: no linear unit)."""
        return self.symbol == "°"

    @property
    def is_metre(self) -> bool:
        """Return True for the metre."""
        return self.metres == 1.0 and not self.angular

    def __str__(self) -> str:
        """Return the symbol (``'ftUS'``)."""
        return self.symbol


METRE = LinearUnit("metre", 1.0, "m", 9001)
FOOT = LinearUnit("foot", 0.3048, "ft", 9002)
US_FOOT = LinearUnit("US survey foot", 1200.0 / 3937.0, "ftUS", 9003)
DEGREE = LinearUnit("degree", math.nan, "°", 9102)

#: EPSG unit-of-measure codes (GeoTIFF ``ProjLinearUnitsGeoKey`` / ``VerticalUnitsGeoKey``
#: values) of the linear units met in survey data.
EPSG_UNITS = {u.epsg: u for u in (
    METRE, FOOT, US_FOOT,
    LinearUnit("Clarke's foot", 0.3047972654, "ftCla", 9005),
    LinearUnit("fathom", 1.8288, "fathom", 9014),
    LinearUnit("nautical mile", 1852.0, "NM", 9030),
    LinearUnit("German legal metre", 1.0000135965, "GLM", 9031),
    LinearUnit("US survey chain", 20.11684023368047, "chUS", 9033),
    LinearUnit("kilometre", 1000.0, "km", 9036),
    LinearUnit("Clarke's yard", 0.9143917962, "ydCla", 9037),
    LinearUnit("Indian foot", 0.3047995, "ftInd", 9080),
    LinearUnit("statute mile", 1609.344, "mi", 9093),
    LinearUnit("Gold Coast foot", 0.3047997101815088, "ftGC", 9094),
    LinearUnit("British foot (1936)", 0.3048007491, "ftBr36", 9095),
    LinearUnit("yard", 0.9144, "yd", 9096),
    LinearUnit("chain", 20.1168, "ch", 9097),
    LinearUnit("link", 0.201168, "lk", 9098),
    LinearUnit("centimetre", 0.01, "cm", 1033),
    LinearUnit("millimetre", 0.001, "mm", 1025),
)}

#: Band unit types (GDAL ``GetUnitType``) and names seen in files, lower case.
UNIT_ALIASES = {
    "m": METRE, "metre": METRE, "meter": METRE, "metres": METRE, "meters": METRE,
    "ft": FOOT, "foot": FOOT, "feet": FOOT, "international foot": FOOT,
    "foot (international)": FOOT, "intl foot": FOOT,
    "ftus": US_FOOT, "us-ft": US_FOOT, "us_ft": US_FOOT, "us survey foot": US_FOOT,
    "foot_us": US_FOOT, "us foot": US_FOOT, "survey foot": US_FOOT,
    "foot us": US_FOOT, "us survey feet": US_FOOT, "ft us": US_FOOT,
}


def linear_unit(name: Optional[str] = None, metres: Optional[float] = None,
                epsg: Optional[int] = None) -> LinearUnit:
    """Return the known :class:`LinearUnit` for an EPSG code, a name or a factor.

    A factor within 1e-9 (relative) of a known unit's gives that unit (PROJ names
    the same unit several ways); otherwise a new unit named ``name`` is returned.
    """
    if epsg is not None and int(epsg) in EPSG_UNITS:
        return EPSG_UNITS[int(epsg)]
    if name and str(name).strip().lower() in UNIT_ALIASES and metres is None:
        return UNIT_ALIASES[str(name).strip().lower()]
    if metres is not None and math.isfinite(metres) and metres > 0:
        for unit in EPSG_UNITS.values():
            if abs(unit.metres - metres) <= 1e-9 * unit.metres:
                return unit
        label = str(name or "unit")
        return LinearUnit(label, float(metres), label)
    if name and str(name).strip().lower() in UNIT_ALIASES:
        return UNIT_ALIASES[str(name).strip().lower()]
    return METRE


@dataclass(frozen=True, eq=False)
class Units:
    """Horizontal and vertical linear units of a dataset.

    Equal when both units mean the same lengths (:class:`LinearUnit` equality), wherever
    they were read from: a metre DTM with band unit type "m" equals one without.

    Attributes
    ----------
    horizontal, vertical : LinearUnit
    vertical_source : str
        Where the vertical unit comes from: ``'crs'`` (a compound or vertical CRS),
        ``'geokeys'`` (LAS GeoTIFF keys), ``'band'`` (a raster band's unit type),
        ``'assumed'`` (taken equal to the horizontal unit) or ``'none'`` (no CRS:
        metres assumed).
    """

    horizontal: LinearUnit = METRE
    vertical: LinearUnit = METRE
    vertical_source: str = "none"

    def __eq__(self, other) -> bool:
        """Return True when both horizontal and vertical units mean the same lengths."""
        if not isinstance(other, Units):
            return NotImplemented
        return self.horizontal == other.horizontal and self.vertical == other.vertical

    def __hash__(self) -> int:
        """Hash by meaning."""
        return hash((self.horizontal, self.vertical))

    @property
    def symbols(self) -> str:
        """``'ftUS / m'``: horizontal / vertical unit symbols (data for any language)."""
        return f"{self.horizontal.symbol} / {self.vertical.symbol}"

    @property
    def h(self) -> float:
        """Metres per horizontal unit."""
        return self.horizontal.metres

    @property
    def v(self) -> float:
        """Metres per vertical unit."""
        return self.vertical.metres

    @property
    def metric(self) -> bool:
        """Return True when both units are the metre."""
        return self.horizontal.is_metre and self.vertical.is_metre

    @property
    def mixed(self) -> bool:
        """Return True when horizontal and vertical units differ."""
        return self.horizontal != self.vertical

    @property
    def area_symbol(self) -> str:
        """Symbol of the horizontal area unit: ``'m²'``, ``'ft²'``, ``'ftUS²'``."""
        return self.horizontal.symbol + "²"

    def h_from_metres(self, value):
        """Convert a horizontal length (or array) from metres to the data's unit."""
        return value / self.h

    def v_from_metres(self, value):
        """Convert a height (or array) from metres to the data's vertical unit."""
        return value / self.v

    def h_to_metres(self, value):
        """Convert a horizontal length (or array) in the data's unit to metres."""
        return value * self.h

    def v_to_metres(self, value):
        """Convert a height (or array) in the data's vertical unit to metres."""
        return value * self.v

    def xyz_to_metres(self, x, y, z):
        """Return ``x, y, z`` in metres (the same arrays when already metric)."""
        if self.metric:
            return x, y, z
        return (np.asarray(x, dtype=np.float64) * self.h,
                np.asarray(y, dtype=np.float64) * self.h,
                np.asarray(z, dtype=np.float64) * self.v)


#: Units of data with no CRS (metres assumed).
METRIC = Units(METRE, METRE, "none")


def _srs(crs):
    from .crs import spatial_reference
    return spatial_reference(crs)


def _horizontal_of_srs(srs) -> LinearUnit:
    if srs.IsProjected():
        code = srs.GetAuthorityCode("PROJCS|UNIT")
        return linear_unit(srs.GetLinearUnitsName(), float(srs.GetLinearUnits() or 1.0),
                           int(code) if code and code.isdigit() else None)
    if srs.IsGeographic():
        return DEGREE
    if srs.IsLocal():
        return linear_unit(srs.GetLinearUnitsName(), float(srs.GetLinearUnits() or 1.0))
    return METRE


def _vertical_of_srs(srs) -> Optional[LinearUnit]:
    if not (srs.IsCompound() or srs.IsVertical()):
        return None
    code = srs.GetAuthorityCode("VERT_CS|UNIT")
    return linear_unit(srs.GetAttrValue("VERT_CS|UNIT"),
                       float(srs.GetTargetLinearUnits("VERT_CS") or 1.0),
                       int(code) if code and code.isdigit() else None)


def crs_units(crs: Optional[str], *, vertical: Optional[LinearUnit] = None,
              vertical_source: str = "") -> Units:
    """Return the :class:`Units` of a CRS ('EPSG:n', 'EPSG:h+v', WKT, PROJ).

    Parameters
    ----------
    crs : str or None
        The CRS; None or empty gives :data:`METRIC` (metres assumed).
    vertical : LinearUnit, optional
        A vertical unit known from elsewhere (LAS key, band unit); it wins over a
        vertical CRS' unit only when the CRS has none.
    vertical_source : str
        What ``vertical`` came from (``'geokeys'``, ``'band'``).

    Raises
    ------
    InputError
        When GDAL does not recognise ``crs``.
    """
    if not crs:
        if vertical is not None:
            return Units(METRE, vertical, vertical_source or "band")
        return METRIC
    srs = _srs(crs)
    horizontal = _horizontal_of_srs(srs)
    vert = _vertical_of_srs(srs)
    if vert is not None:
        return Units(horizontal, vert, "crs")
    if vertical is not None:
        return Units(horizontal, vertical, vertical_source or "band")
    return Units(horizontal, METRE if horizontal.angular else horizontal, "assumed")


def _geokeys(header):
    """``{key id: value}`` of the GeoKeyDirectory VLR of a laspy header ({} if none)."""
    import laspy
    for vlr in header.vlrs:
        if isinstance(vlr, laspy.vlrs.known.GeoKeyDirectoryVlr):
            return {k.id: (k.tiff_tag_location, k.value_offset) for k in vlr.geo_keys}
    return {}


def _key_unit(keys, key_id) -> Optional[LinearUnit]:
    loc, value = keys.get(key_id, (None, None))
    if loc == 0 and value in EPSG_UNITS:
        return EPSG_UNITS[value]
    return None


def header_units(header, crs: Optional[str] = None) -> Units:
    """Return the :class:`Units` of a laspy header.

    ``crs`` is the header's CRS as :func:`~.las.crs_of_header` returns it (read when
    not given). A WKT VLR (LAS 1.4) gives both units (compound CRS). GeoTIFF keys:
    ``ProjLinearUnitsGeoKey`` (3076) overrides the projected CRS' unit (as libgeotiff
    does); ``VerticalUnitsGeoKey`` (4099), else the unit of ``VerticalCSTypeGeoKey``
    (4096), gives the vertical unit.
    """
    if crs is None:
        from .las import crs_of_header
        crs = crs_of_header(header)
    keys = _geokeys(header)
    vertical = _key_unit(keys, 4099)
    if vertical is None:
        loc, code = keys.get(4096, (None, None))
        if loc == 0 and code and 0 < code < 32767:
            try:
                vertical = _vertical_of_srs(_srs(f"EPSG:{code}"))
            except ValueError:
                vertical = None
    units = crs_units(crs, vertical=vertical, vertical_source="geokeys")
    horizontal = _key_unit(keys, 3076)
    if horizontal is not None and not units.horizontal.angular \
            and horizontal != units.horizontal:
        vert = units.vertical if units.vertical_source != "assumed" else horizontal
        units = Units(horizontal, vert, units.vertical_source)
    return units


def las_units(path_or_info) -> Units:
    """Return the :class:`Units` of a LAS/LAZ file (a path or a ``LasInfo``)."""
    units = getattr(path_or_info, "units", None)
    if isinstance(units, Units):
        return units
    from .las import las_info
    return las_info(getattr(path_or_info, "path", path_or_info)).units


def raster_units(path_or_dataset, band: int = 1) -> Units:
    """Return the :class:`Units` of a GDAL raster: its CRS and the band's unit type."""
    from osgeo import gdal
    ds = path_or_dataset
    if isinstance(ds, (str, os.PathLike)):
        gdal.UseExceptions()
        ds = gdal.Open(os.fspath(ds))
    wkt = ds.GetProjection() or ""
    unit_type = ""
    if 1 <= band <= ds.RasterCount:
        unit_type = (ds.GetRasterBand(band).GetUnitType() or "").strip()
    vertical = UNIT_ALIASES.get(unit_type.lower()) if unit_type else None
    return crs_units(wkt or None, vertical=vertical, vertical_source="band")


# --------------------------------------------------------------------------- labels
#: Unit names as message ids (translated in i18n/strings/hostile.json).
_NAMES = {"metre": "metre", "foot": "foot", "US survey foot": "US survey foot",
          "degree": "degree"}


def unit_name(unit: LinearUnit, lang="en") -> str:
    """Return the unit's name in ``lang`` (``'US survey foot'``, ``'قدم مساحي أمريكي'``)."""
    from ..reporting.i18n import translator
    return translator(lang)(_NAMES.get(unit.name, unit.name))


def unit_label(unit: LinearUnit, lang="en") -> str:
    """Return ``'US survey foot (ftUS)'`` in ``lang`` (the symbol stays Latin)."""
    return f"{unit_name(unit, lang)} ({unit.symbol})"


def units_note(units: Units):
    """Report value saying the data's units and that lengths were converted (a ``T``).

    ``None`` for metric data (nothing to say). Rows use the label ``'Linear units'``.
    """
    from ..reporting.content import T
    if units.metric:
        return None
    return T("{h} ({hs}) horizontally, {v} ({vs}) vertically; converted to metres for "
             "the computation: lengths in this report are in metres unless a unit says "
             "otherwise.", h=T(_NAMES.get(units.horizontal.name, units.horizontal.name)),
             hs=units.horizontal.symbol,
             v=T(_NAMES.get(units.vertical.name, units.vertical.name)),
             vs=units.vertical.symbol)


def units_rows(units: Optional[Units]) -> list:
    """Return the report row(s) stating the data's units: ``[("Linear units", note)]``.

    One row for every report (filters, DTMs, DSM, QA, classification, buildings): empty
    for metric data or unknown units (nothing to say), else :func:`units_note`.
    """
    note = units_note(units) if units is not None else None
    return [("Linear units", note)] if note is not None else []

"""Ground control points (GCPs): QGIS Georeferencer ``.points`` files and CSV tables.

Pixel convention (used everywhere in this package)
--------------------------------------------------
GCP image coordinates are GDAL **pixel/line** coordinates ``(col, row)``:

* ``(0, 0)`` is the top-left **corner** of the top-left pixel; the centre of that
  pixel is ``(0.5, 0.5)`` and the image covers ``[0, width] × [0, height]``;
* ``col`` grows to the right, ``row`` grows **downwards**.

This is the convention of GDAL GCPs (``GCPPixel``/``GCPLine``), of ``gdalwarp`` and of
the QGIS Georeferencer, so files move between the three without half-pixel shifts.

QGIS ``.points`` files
----------------------
Written by the Georeferencer ("Save GCP points as…"); QGIS 3.22 writes (source:
``QgsGeoreferencerMainWindow::saveGCPs``)::

    #CRS: <WKT of the map coordinates' CRS>
    mapX,mapY,pixelX,pixelY,enable,dX,dY,residual
    -305503.32,155712.9,1023.5,-311.25,1,0.41,-0.12,0.43

QGIS ≥ 3.26 writes the same with the header ``mapX,mapY,sourceX,sourceY,…``, and old
versions wrote tab-separated rows with no ``#CRS`` line. ``pixelX``/``sourceX`` is
the column and ``pixelY``/``sourceY`` is **minus the row** (QGIS shows an image without
georeferencing with y pointing up, so rows are negative), both in the corner
convention above; hence ``col = pixelX`` and ``row = −pixelY``. ``dX, dY, residual``
are the Georeferencer's own residuals: they are kept (``qgis_residuals``) but never
used. The ``enable`` column is honoured (QGIS 3.22 itself reads it only from 5-column
rows and re-enables every point of its own 8-column files).
Points have no names in the file; they are numbered 1, 2, … in file order (the
Georeferencer's table shows the same order). QGIS ≥ 3.26 stores *source layer*
coordinates in ``sourceX/sourceY``: for an image that already has a geotransform,
pass it as ``source_geotransform`` to convert them to pixel/line.

CSV files
---------
Comma, semicolon or tab separated, one header row (names are case-insensitive,
spaces/underscores ignored), optional leading ``# CRS: …`` line:

* id: ``id``, ``name``, ``label``, ``point``, ``gcp_id`` (default: 1, 2, … in order);
* image coordinates, one of the pairs ``col,row`` / ``column,row`` / ``pixel,line``
  (row grows downwards) or ``image_x,image_y`` / ``pixelX,pixelY`` / ``sourceX,sourceY``
  (QGIS style: y is minus the row; a column of only non-negative ``image_y`` values is
  taken as rows and reported in ``notes``);
* map coordinates: ``X,Y`` / ``map_x,map_y`` / ``mapX,mapY`` / ``easting,northing``
  / ``E,N``;
* optional ``enabled`` (``enable``, ``use``: 1/0, true/false, yes/no), ``role``
  (``gcp`` or ``check`` — check points are kept apart from the fit) and ``weight``.

Both kinds of file are decoded by :mod:`.text` (UTF-16 with a BOM, a declared page,
UTF-8, else the Windows code page that reads the names as text: cp1256, cp1252 or the
machine's own), the same rule as check-point files.

``pixel_origin="center"`` says that the image coordinates are pixel-centre indices
(e.g. 0-based array indices ``[row, col]`` of the pixel holding the feature); 0.5 is
then added to both to reach the corner convention.
"""
from __future__ import annotations

import csv
import io
import os
from dataclasses import dataclass, field
from typing import List, Optional, Sequence

import numpy as np

from ..errors import InputError
from .text import read_text

ROLES = ("gcp", "check")
_ROLE_ALIASES = {"gcp": "gcp", "control": "gcp", "gcps": "gcp", "cp": "gcp", "": "gcp",
                 "check": "check", "checkpoint": "check", "chk": "check", "icp": "check",
                 "independent": "check", "test": "check", "validation": "check"}
_TRUE = {"1", "true", "yes", "y", "t", "on", "enabled"}
_FALSE = {"0", "false", "no", "n", "f", "off", "disabled"}


@dataclass
class GCPSet:
    """Ground control points with image (pixel/line) and map coordinates.

    Attributes
    ----------
    ids : list of str
        Unique point identifiers.
    pixel : ndarray (n, 2)
        ``(col, row)`` in the corner convention, row downwards.
    map : ndarray (n, 2)
        ``(X, Y)`` map coordinates.
    enabled : ndarray of bool (n,)
        Disabled points are ignored by fits and reports (but listed).
    role : ndarray of str (n,)
        ``"gcp"`` (used in the fit) or ``"check"`` (independent check point).
    weight : ndarray (n,) or None
        Optional positive least-squares weights.
    crs : str
        CRS of the map coordinates (WKT or 'EPSG:n'); '' when unknown.
    source : str
        File or layer the points came from.
    notes : list of str
        Conventions applied while reading (shown in reports).
    qgis_residuals : ndarray (n, 3) or None
        ``dX, dY, residual`` columns of a ``.points`` file, as QGIS saved them.
    """

    ids: List[str]
    pixel: np.ndarray
    map: np.ndarray
    enabled: np.ndarray
    role: np.ndarray
    weight: Optional[np.ndarray] = None
    crs: str = ""
    source: str = ""
    notes: List[str] = field(default_factory=list)
    qgis_residuals: Optional[np.ndarray] = None

    def __len__(self) -> int:
        """Return the number of points."""
        return len(self.ids)

    @property
    def fit_mask(self) -> np.ndarray:
        """Enabled points with role ``gcp`` (used in the fit)."""
        return self.enabled & (self.role == "gcp")

    @property
    def check_mask(self) -> np.ndarray:
        """Enabled independent check points."""
        return self.enabled & (self.role == "check")

    def with_crs(self, crs: str) -> "GCPSet":
        """Return a copy with ``crs`` set."""
        return GCPSet(list(self.ids), self.pixel.copy(), self.map.copy(), self.enabled.copy(),
                      self.role.copy(), None if self.weight is None else self.weight.copy(),
                      crs, self.source, list(self.notes), self.qgis_residuals)

    def subset(self, mask) -> "GCPSet":
        """Return the points where ``mask`` is true."""
        m = np.asarray(mask, bool)
        return GCPSet([i for i, k in zip(self.ids, m) if k], self.pixel[m], self.map[m],
                      self.enabled[m], self.role[m],
                      None if self.weight is None else self.weight[m], self.crs, self.source,
                      list(self.notes),
                      None if self.qgis_residuals is None else self.qgis_residuals[m])


# ---------------------------------------------------------------------- building
def make_gcps(ids, pixel, map_xy, *, enabled=None, role=None, weight=None, crs: str = "",
              source: str = "", notes=None) -> GCPSet:
    """Validate arrays and build a :class:`GCPSet` (duplicate ids, NaN, roles)."""
    pixel = np.asarray(pixel, float).reshape(-1, 2)
    map_xy = np.asarray(map_xy, float).reshape(-1, 2)
    n = len(pixel)
    ids = [str(i) for i in (ids if ids is not None else range(1, n + 1))]
    if len(ids) != n or len(map_xy) != n:
        raise InputError("GCP arrays differ in length: {ids} ids, {n} image and "
                         "{m} map coordinates.", ids=len(ids), n=n, m=len(map_xy))
    if n == 0:
        raise InputError("No ground control points found in {source}; "
                         "give at least 3 (order 1).", source=source or "the input")
    seen, dup = set(), []
    for i in ids:
        if i in seen and i not in dup:
            dup.append(i)
        seen.add(i)
    if dup:
        raise InputError("Duplicate GCP ids in {source}: {ids}. Each point needs a unique "
                         "id; rename or remove the duplicates.",
                         source=source or "the input", ids=", ".join(dup))
    bad = ~(np.isfinite(pixel).all(axis=1) & np.isfinite(map_xy).all(axis=1))
    if bad.any():
        raise InputError("GCP(s) {ids} have missing or non-finite coordinates; fix or "
                         "remove them.", ids=", ".join(np.asarray(ids)[bad]))
    enabled = np.ones(n, bool) if enabled is None else np.asarray(enabled, bool).ravel()
    role = np.array(["gcp"] * n if role is None else [str(r) for r in role], dtype=object)
    for r in role:
        if r not in ROLES:
            raise InputError("Unknown GCP role {role}; use 'gcp' or 'check'.", role=repr(r))
    w = None
    if weight is not None:
        w = np.asarray(weight, float).ravel()
        if (~np.isfinite(w) | (w <= 0)).any():
            raise InputError("GCP weights must be positive numbers; fix the weight column.")
    check_distinct_map(ids, map_xy, enabled, source)
    return GCPSet(ids, pixel, map_xy, enabled, role, w, crs or "", source, list(notes or []))


def check_distinct_map(ids, map_xy, enabled, source: str = "") -> None:
    """Refuse enabled GCPs sharing identical map coordinates, naming the points.

    Two points at one map position with different image positions contradict each
    other (and a repeated point counts twice in every criterion); a whole set at one
    position has no ground extent at all.

    Raises
    ------
    InputError
        Naming each group of points (ids) with identical map coordinates.
    """
    en = np.flatnonzero(np.asarray(enabled, bool))
    if len(en) < 2:
        return
    _, inverse, counts = np.unique(map_xy[en], axis=0, return_inverse=True,
                                   return_counts=True)
    inverse = np.asarray(inverse).ravel()
    groups = [en[inverse == k] for k in np.flatnonzero(counts > 1)]
    if not groups:
        return
    ids = np.asarray(ids, dtype=object)
    text = "; ".join(f"{', '.join(ids[g])} at X = {map_xy[g[0], 0]:.10g}, "
                     f"Y = {map_xy[g[0], 1]:.10g}" for g in groups[:10])
    more = f" (and {len(groups) - 10} more groups)" if len(groups) > 10 else ""
    raise InputError(
        "GCPs with identical map coordinates in {source}: {text}{more}. "
        "Each GCP must be a distinct ground point: fix the map coordinates of the "
        "repeated points, or disable or remove the duplicates.",
        source=source or 'the input',
        text=text,
        more=more)


def check_in_image(gcps: GCPSet, width: int, height: int, *, tolerance: float = 0.0) -> None:
    """Raise ``ValueError`` naming every enabled GCP outside ``[0, width] × [0, height]``."""
    c, r = gcps.pixel[:, 0], gcps.pixel[:, 1]
    out = gcps.enabled & ((c < -tolerance) | (c > width + tolerance)
                          | (r < -tolerance) | (r > height + tolerance))
    if out.any():
        items = ", ".join(f"{i} (col {cc:.6g}, row {rr:.6g})" for i, cc, rr in
                          zip(np.asarray(gcps.ids)[out], c[out], r[out]))
        raise InputError(
            "GCP(s) outside the image ({width} × {height} pixels, columns 0…{width}, rows "
            "0…{height} with rows growing downwards): {items}. Check that the GCP file "
            "belongs to this image and its row sign (QGIS .points store minus the row); "
            "disable or fix these points.", width=width, height=height, items=items)


# ---------------------------------------------------------------------- parsing
def _num(text, *, where: str, column: str) -> float:
    s = str(text).strip()
    try:
        v = float(s)
    except ValueError:
        raise InputError("{where}: column '{column}' must be a number, got {value}. "
                         "Fix the value (use '.' as the decimal separator).", where=where,
                         column=column, value=repr(s)) from None
    return v


def _flag(text, *, where: str, column: str) -> bool:
    s = str(text).strip().lower()
    if s in _TRUE:
        return True
    if s in _FALSE:
        return False
    raise InputError("{where}: column '{column}' must be 1/0 (or true/false), got {value}.",
                     where=where, column=column, value=repr(text))


def _read_text(path) -> str:
    path = os.fspath(path)
    if not os.path.exists(path):
        raise InputError("GCP file not found: {path}. Check the path.", path=path)
    return read_text(path)          # the one rule of GCP and check-point files


def _crs_line(line: str) -> Optional[str]:
    s = line.strip()
    if s.startswith("#"):
        body = s[1:].strip()
        if body.upper().startswith("CRS:"):
            return body[4:].strip()
    return None


def read_points(path, *, source_geotransform: Optional[Sequence[float]] = None) -> GCPSet:
    """Read a QGIS Georeferencer ``.points`` file (see module docstring).

    Parameters
    ----------
    path : path-like
        The ``.points`` file.
    source_geotransform : 6 floats, optional
        Geotransform of the image, needed only for QGIS ≥ 3.26 files of images that
        were already georeferenced (``sourceX/sourceY`` are then layer coordinates).
    """
    text = _read_text(path)
    src = os.fspath(path)
    lines = text.splitlines()
    crs = ""
    notes = ["QGIS .points: col = pixelX, row = −pixelY (corner convention, rows down)."]
    i = 0
    while i < len(lines) and (not lines[i].strip() or lines[i].lstrip().startswith("#")):
        c = _crs_line(lines[i])
        if c:
            crs = c
        i += 1
    if i >= len(lines):
        raise InputError("{path} holds no GCP rows; save the GCPs again from the "
                         "Georeferencer.", path=src)
    header = lines[i].strip()
    delim = "," if "," in header else "\t"
    cols = [h.strip() for h in header.split(delim)]
    low = [c.lower() for c in cols]
    layer_coords = False
    if low[:2] == ["mapx", "mapy"]:
        if low[2:4] == ["sourcex", "sourcey"]:
            layer_coords = True
        elif low[2:4] != ["pixelx", "pixely"]:
            raise InputError("{path}: unexpected header {header}; a Georeferencer file "
                             "starts with mapX,mapY,pixelX,pixelY (or sourceX,sourceY).",
                             path=src, header=repr(header))
        i += 1
    else:
        # very old files: no header, tab separated mapX mapY pixelX pixelY
        try:
            [float(v) for v in header.split(delim)[:4]]
        except ValueError:
            raise InputError("{path}: not a QGIS .points file (header {header}); expected "
                             "'mapX,mapY,pixelX,pixelY,enable,dX,dY,residual'.", path=src,
                             header=repr(header)) from None
    ids, pix, mp, en, qres = [], [], [], [], []
    for k in range(i, len(lines)):
        line = lines[k].strip()
        if not line or line.startswith("#"):
            continue
        parts = line.split("," if "," in line else "\t")
        where = f"{src} line {k + 1}"
        if len(parts) < 4:
            raise InputError("{where}: expected at least 4 values (mapX,mapY,pixelX,pixelY), "
                             "got {n}.", where=where, n=len(parts))
        names = ("mapX", "mapY", "pixelX", "pixelY")
        v = [_num(parts[j], where=where, column=names[j]) for j in range(4)]
        ids.append(str(len(ids) + 1))
        mp.append(v[:2])
        pix.append(v[2:4])
        en.append(_flag(parts[4], where=where, column="enable") if len(parts) > 4 else True)
        if len(parts) >= 8:
            qres.append([_num(parts[j], where=where, column=("dX", "dY", "residual")[j - 5])
                         for j in (5, 6, 7)])
    pix = np.asarray(pix, float).reshape(-1, 2)
    if layer_coords and source_geotransform is not None and not _trivial_gt(source_geotransform):
        pix = _layer_to_pixel(pix, source_geotransform)
        notes.append("sourceX/sourceY converted from source layer coordinates with the "
                     "image geotransform.")
    else:
        pix = np.column_stack([pix[:, 0], -pix[:, 1]]) if len(pix) else pix
    g = make_gcps(ids, pix, mp, enabled=en, crs=crs, source=src, notes=notes)
    if qres and len(qres) == len(ids):
        g.qgis_residuals = np.asarray(qres, float)
    if not crs:
        g.notes.append("The file has no '#CRS:' line: the map CRS must be given.")
    return g


def _trivial_gt(gt) -> bool:
    gt = [float(v) for v in gt]
    return gt[0] == 0 and gt[1] == 1 and gt[2] == 0 and gt[3] == 0 and gt[4] == 0 and \
        abs(gt[5]) == 1


def _layer_to_pixel(xy: np.ndarray, gt) -> np.ndarray:
    a = np.array([[gt[1], gt[2]], [gt[4], gt[5]]], float)
    rhs = np.column_stack([xy[:, 0] - gt[0], xy[:, 1] - gt[3]])
    return np.linalg.solve(a, rhs.T).T


_ALIASES = {
    "id": ("id", "name", "label", "point", "pointid", "gcpid", "gcp", "pt", "no", "num"),
    "col": ("col", "column", "pixel", "c", "i"),
    "row": ("row", "line", "r", "j"),
    "ix": ("imagex", "imgx", "ix", "pixelx", "sourcex", "imx", "u"),
    "iy": ("imagey", "imgy", "iy", "pixely", "sourcey", "imy", "v"),
    "x": ("x", "mapx", "easting", "east", "e", "worldx", "xmap", "groundx"),
    "y": ("y", "mapy", "northing", "north", "n", "worldy", "ymap", "groundy"),
    "enabled": ("enabled", "enable", "use", "active", "used"),
    "role": ("role", "type", "kind", "usage"),
    "weight": ("weight", "w", "wt"),
}


def _norm(name: str) -> str:
    return "".join(ch for ch in name.strip().lower() if ch.isalnum())


def _csv_rows(text: str, src: str):
    """Return ``(crs from a '# CRS:' comment, non-empty CSV rows incl. the header)``."""
    lines = text.splitlines()
    file_crs = ""
    body_start = 0
    for k, line in enumerate(lines):
        if line.strip().startswith("#"):
            c = _crs_line(line)
            if c:
                file_crs = c
            body_start = k + 1
            continue
        if line.strip():
            break
        body_start = k + 1
    body = "\n".join(lines[body_start:])
    if not body.strip():
        raise InputError("{path} is empty; it needs a header row and one row per GCP.",
                         path=src)
    first = body.splitlines()[0]
    delim = max((";", "\t", ","), key=first.count) if any(d in first for d in ";\t,") else ","
    reader = csv.reader(io.StringIO(body), delimiter=delim)
    return file_crs, [r for r in reader if any(c.strip() for c in r)]


def _csv_columns(rows, src: str):
    """Return ``(found columns, col index, row index, row sign or None, notes)``."""
    header = [_norm(h) for h in rows[0]]
    found = {}
    for key, names in _ALIASES.items():
        for name in names:
            if name in header:
                found[key] = header.index(name)
                break
    notes = []
    if "col" in found and "row" in found:
        ci, ri, sign = found["col"], found["row"], 1.0
        notes.append("CSV image coordinates read as col,row (rows grow downwards).")
    elif "ix" in found and "iy" in found:
        ci, ri, sign = found["ix"], found["iy"], None
    else:
        raise InputError("{path}: no image coordinate columns. Expected 'col,row', "
                         "'pixel,line' or 'image_x,image_y' (QGIS style, y = −row); found "
                         "columns {columns}.", path=src, columns=rows[0])
    if "x" not in found or "y" not in found:
        raise InputError("{path}: no map coordinate columns. Expected 'X,Y', 'map_x,map_y' "
                         "or 'easting,northing'; found columns {columns}.", path=src,
                         columns=rows[0])
    return found, ci, ri, sign, notes


def _csv_role(value: str, where: str) -> str:
    rv = value.strip().lower()
    if rv not in _ROLE_ALIASES:
        raise InputError("{where}: role must be 'gcp' or 'check', got {value}.",
                         where=where, value=repr(rv))
    return _ROLE_ALIASES[rv]


def _csv_records(rows, found, ci, ri, src):
    """Parse the data rows into ids, pixel, map, enabled, role and weight lists."""
    ids, pix, mp, en, role, wt = [], [], [], [], [], []
    for k, r in enumerate(rows[1:], start=2):
        where = f"{src} row {k}"

        def get(key, r=r):
            j = found[key]
            return r[j] if j < len(r) else ""

        ids.append(get("id").strip() if "id" in found else str(len(ids) + 1))
        if "id" in found and not ids[-1]:
            raise InputError("{where}: empty id.", where=where)
        pix.append([_num(r[ci] if ci < len(r) else "", where=where, column=rows[0][ci]),
                    _num(r[ri] if ri < len(r) else "", where=where, column=rows[0][ri])])
        mp.append([_num(get("x"), where=where, column=rows[0][found["x"]]),
                   _num(get("y"), where=where, column=rows[0][found["y"]])])
        en.append(_flag(get("enabled"), where=where, column="enabled")
                  if "enabled" in found and get("enabled").strip() else True)
        role.append(_csv_role(get("role"), where) if "role" in found else "gcp")
        if "weight" in found:
            wt.append(_num(get("weight"), where=where, column="weight"))
    return ids, pix, mp, en, role, wt


def read_csv(path, *, pixel_origin: str = "corner", crs: str = "") -> GCPSet:
    """Read GCPs from a CSV table (see module docstring for the accepted columns).

    Parameters
    ----------
    path : path-like
        The CSV file.
    pixel_origin : {'corner', 'center'}
        ``corner`` (default): image coordinates in the GDAL/QGIS corner convention;
        ``center``: integer values are pixel centres (0.5 is added).
    crs : str, optional
        CRS of the map coordinates when the file has no ``# CRS:`` line.
    """
    if pixel_origin not in ("corner", "center", "centre"):
        raise InputError("pixel_origin must be 'corner' or 'center', got {value}.",
                         value=repr(pixel_origin))
    src = os.fspath(path)
    file_crs, rows = _csv_rows(_read_text(path), src)
    found, ci, ri, sign, notes = _csv_columns(rows, src)
    ids, pix, mp, en, role, wt = _csv_records(rows, found, ci, ri, src)
    pix = np.asarray(pix, float).reshape(-1, 2)
    if sign is None:
        if len(pix) and (pix[:, 1] <= 0).all() and (pix[:, 1] < 0).any():
            sign = -1.0
            notes.append("CSV image_y values are negative: QGIS convention, row = −image_y.")
        else:
            sign = 1.0
            notes.append("CSV image_y values are non-negative: read as rows growing "
                         "downwards.")
    pix[:, 1] *= sign
    if pixel_origin in ("center", "centre"):
        pix = pix + 0.5
        notes.append("pixel_origin=center: 0.5 added to col and row (pixel-centre indices).")
    else:
        notes.append("pixel_origin=corner: (0, 0) is the top-left corner of the image.")
    return make_gcps(ids, pix, mp, enabled=en, role=role, weight=wt or None,
                     crs=file_crs or crs, source=src, notes=notes)


def read_gcps(path, *, pixel_origin: str = "corner", crs: str = "",
              source_geotransform: Optional[Sequence[float]] = None) -> GCPSet:
    """Read a ``.points`` file or a CSV table (chosen by content and extension).

    ``crs`` is used when the file does not name its CRS; ``pixel_origin`` applies to
    CSV tables only (``.points`` files are always in the corner convention).
    """
    p = os.fspath(path)
    head = _read_text(p)[:4096].lstrip().lower()
    is_points = p.lower().endswith(".points") or head.startswith("#crs:") or \
        head.startswith("mapx,mapy,") or head.startswith("mapx\tmapy")
    if is_points:
        g = read_points(p, source_geotransform=source_geotransform)
        if not g.crs and crs:
            g.crs = crs
        return g
    return read_csv(p, pixel_origin=pixel_origin, crs=crs)


# ---------------------------------------------------------------------- writing
def points_text(gcps: GCPSet, *, crs_wkt: Optional[str] = None, residuals=None) -> str:
    """Text of a QGIS 3.22 ``.points`` file for ``gcps`` (``residuals``: (n, 2) or None)."""
    crs_wkt = gcps.crs if crs_wkt is None else crs_wkt
    out = []
    if crs_wkt:
        out.append(f"#CRS: {crs_wkt}")
    out.append("mapX,mapY,pixelX,pixelY,enable,dX,dY,residual")
    res = np.zeros((len(gcps), 2)) if residuals is None else np.asarray(residuals, float)
    for k in range(len(gcps)):
        dx, dy = res[k]
        vals = (gcps.map[k, 0], gcps.map[k, 1], gcps.pixel[k, 0], -gcps.pixel[k, 1])
        out.append(",".join(repr(float(v)) for v in vals) + f",{int(gcps.enabled[k])},"
                   + ",".join(repr(float(v)) for v in (dx, dy, float(np.hypot(dx, dy)))))
    return "\n".join(out) + "\n"


def gcps_csv_text(gcps: GCPSet) -> str:
    """Text of a CSV table (id,col,row,X,Y,enabled,role[,weight]).

    Readable by :func:`read_csv` (corner convention).
    """
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    head = ["id", "col", "row", "X", "Y", "enabled", "role"]
    if gcps.weight is not None:
        head.append("weight")
    w.writerow(head)
    for k in range(len(gcps)):
        row = [gcps.ids[k], repr(float(gcps.pixel[k, 0])), repr(float(gcps.pixel[k, 1])),
               repr(float(gcps.map[k, 0])), repr(float(gcps.map[k, 1])),
               int(gcps.enabled[k]), gcps.role[k]]
        if gcps.weight is not None:
            row.append(repr(float(gcps.weight[k])))
        w.writerow(row)
    return buf.getvalue()

"""LOD1 and LOD2 building solids from footprints and fitted roofs (CityGML/CityJSON LODs).

Each building becomes closed, outward-facing solids (lists of planar faces):

* **LOD1** — the footprint extruded from the ground height to the roof's top (ridge)
  (Biljecki et al. 2016, LOD1.2: a block with the detailed footprint);
* **LOD2** — the fitted roof primitive of :mod:`.roofs` over the footprint rectangle:
  flat, shed, gabled (pentagon gable walls) or hipped (trapezoids and triangles), walls
  down to the ground, a ground face (LOD2.2 without superstructures); a flat or shed
  roof over any other outline too. Complex roofs, and gabled or hipped roofs over
  outlines that are not rectangles, get LOD1 only.

Faces carry the CityGML semantics GroundSurface, WallSurface, RoofSurface. Outward
orientation is checked against the solid's centre (all these solids are convex in the
footprint frame); coordinates are metres (the writer converts to the data's units).

References
----------
Biljecki, F., Ledoux, H., Stoter, J. (2016). An improved LOD specification for 3D
building models. Computers, Environment and Urban Systems 59, 25–37.
Ledoux, H. et al. (2019). CityJSON: a compact and easy-to-use encoding of the CityGML
data model. Open Geospatial Data, Software and Standards 4, 4.
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import List, Optional

import numpy as np

from ..io.cityjson import newell_normal

__all__ = ["Solid", "lod1_solid", "lod2_solid", "building_solids"]

GROUND_S, WALL_S, ROOF_S = "GroundSurface", "WallSurface", "RoofSurface"


@dataclass
class Solid:
    """A closed shell: ``faces`` are lists of (x, y, z) points, ``semantics`` one per face."""

    faces: List[np.ndarray] = field(default_factory=list)
    semantics: List[str] = field(default_factory=list)

    def add(self, points, kind: str) -> None:
        """Append a face (consecutive duplicate points dropped)."""
        p = np.asarray(points, dtype=float)
        keep = np.ones(len(p), bool)
        keep[1:] = np.any(np.abs(np.diff(p, axis=0)) > 1e-9, axis=1)
        if len(p) > 1 and np.all(np.abs(p[-1] - p[0]) <= 1e-9):
            keep[-1] = False
        p = p[keep]
        if len(p) >= 3:
            self.faces.append(p)
            self.semantics.append(kind)

    def orient_outward(self) -> "Solid":
        """Reverse the faces whose normal points towards the solid's centre."""
        centre = np.vstack(self.faces).mean(axis=0)
        for i, f in enumerate(self.faces):
            if np.dot(newell_normal(f), f.mean(axis=0) - centre) < 0:
                self.faces[i] = f[::-1].copy()
        return self


def _ccw(ring) -> np.ndarray:
    r = np.asarray(ring, dtype=float)
    area = 0.5 * np.sum(r[:, 0] * np.roll(r[:, 1], -1) - np.roll(r[:, 0], -1) * r[:, 1])
    return r if area > 0 else r[::-1]


def lod1_solid(ring, z0: float, z1: float) -> Solid:
    """Footprint ``ring`` (n, 2) extruded from ``z0`` to ``z1``."""
    r = _ccw(ring)
    n = len(r)
    s = Solid()
    s.add(np.column_stack([r[::-1], np.full(n, z0)]), GROUND_S)
    s.add(np.column_stack([r, np.full(n, z1)]), ROOF_S)
    for i in range(n):
        a, b = r[i], r[(i + 1) % n]
        s.add([[*a, z0], [*b, z0], [*b, z1], [*a, z1]], WALL_S)
    return s


def lod2_solid(model, z0: float) -> Optional[Solid]:
    """Return the roof primitive ``model`` (:class:`.roofs.RoofModel`) on walls from ``z0``."""
    kind, p = model.kind, model.params
    a, b = model.half
    if kind not in ("flat", "shed", "gabled", "hipped"):
        return None

    def xyz(pts):
        pts = np.asarray(pts, dtype=float)
        xy = model.centre + pts[:, :1] * model.axes[0] + pts[:, 1:2] * model.axes[1]
        return np.column_stack([xy, pts[:, 2]])

    s = Solid()
    corners = [(-a, -b), (a, -b), (a, b), (-a, b)]
    s.add(xyz([(u, v, z0) for u, v in corners]), GROUND_S)
    if kind in ("flat", "shed"):
        top = [(u, v, float(model.z_uv(u, v))) for u, v in corners]
        s.add(xyz(top), ROOF_S)
        for i in range(4):
            (u0, v0, t0), (u1, v1, t1) = top[i], top[(i + 1) % 4]
            s.add(xyz([(u0, v0, z0), (u1, v1, z0), (u1, v1, t1), (u0, v0, t0)]), WALL_S)
    elif kind == "gabled":
        swap = not p["along_u"]
        ha, hb = (b, a) if swap else (a, b)     # half length along / across the ridge
        r, w0 = p["r"], p["w0"]
        e1, e2 = r - p["s"] * (hb + w0), r - p["s"] * (hb - w0)

        def g(pts):   # (along, across, z) -> model frame
            return xyz([(c, l, z) if swap else (l, c, z) for l, c, z in pts])
        s.add(g([(-ha, -hb, e1), (ha, -hb, e1), (ha, w0, r), (-ha, w0, r)]), ROOF_S)
        s.add(g([(-ha, w0, r), (ha, w0, r), (ha, hb, e2), (-ha, hb, e2)]), ROOF_S)
        s.add(g([(-ha, -hb, z0), (ha, -hb, z0), (ha, -hb, e1), (-ha, -hb, e1)]), WALL_S)
        s.add(g([(-ha, hb, z0), (ha, hb, z0), (ha, hb, e2), (-ha, hb, e2)]), WALL_S)
        for end in (ha, -ha):
            s.add(g([(end, -hb, z0), (end, hb, z0), (end, hb, e2), (end, w0, r),
                     (end, -hb, e1)]), WALL_S)
    else:   # hipped, equal pitch: ridge along u from -(a-b) to (a-b)
        e = p["e"]
        r = e + p["s"] * b
        d = max(a - b, 0.0)
        s.add(xyz([(-a, -b, e), (a, -b, e), (d, 0, r), (-d, 0, r)]), ROOF_S)
        s.add(xyz([(a, b, e), (-a, b, e), (-d, 0, r), (d, 0, r)]), ROOF_S)
        s.add(xyz([(a, -b, e), (a, b, e), (d, 0, r)]), ROOF_S)
        s.add(xyz([(-a, b, e), (-a, -b, e), (-d, 0, r)]), ROOF_S)
        for i in range(4):
            (u0, v0), (u1, v1) = corners[i], corners[(i + 1) % 4]
            s.add(xyz([(u0, v0, z0), (u1, v1, z0), (u1, v1, e), (u0, v0, e)]), WALL_S)
    return s.orient_outward()


def lod2_polygon(ring, model, z0: float) -> Optional[Solid]:
    """Return a flat or shed roof over any footprint ``ring`` (LOD2).

    The outline is lifted onto the roof plane, vertical walls go down to ``z0``; every
    face is planar.
    """
    if model.kind not in ("flat", "shed"):
        return None
    r = _ccw(ring)
    top = np.asarray(model.z(r[:, 0], r[:, 1]), dtype=float)
    n = len(r)
    s = Solid()
    s.add(np.column_stack([r[::-1], np.full(n, z0)]), GROUND_S)
    s.add(np.column_stack([r, top]), ROOF_S)
    for i in range(n):
        j = (i + 1) % n
        s.add([[*r[i], z0], [*r[j], z0], [*r[j], top[j]], [*r[i], top[i]]], WALL_S)
    return s


def building_solids(b: dict, ring=None):
    """``(lod1, lod2)`` solids of a building dict of :func:`.buildings.extract_buildings`.

    ``ring``: the footprint outline (n, 2) in metres; the roof model's rectangle when
    the footprint was regularised (or none is given). LOD2 for regularised footprints
    with a flat, shed, gabled or hipped roof, and for any other outline with a flat or
    shed roof.
    """
    model = b["model"]
    z0, z1 = b["ground"], b["roof"]
    if b.get("regularised") or ring is None:
        ring = model.corners()
    lod1 = lod1_solid(ring, z0, z1)
    if b.get("regularised"):
        lod2 = lod2_solid(model, z0)
    else:
        lod2 = lod2_polygon(ring, model, z0)
    return lod1, lod2


def city_objects(res, *, outlines=None) -> list:
    """Return the buildings of a :class:`.buildings.BuildingResult` as CityJSON dicts.

    ``outlines``: ``{label: (n, 2) ring}`` (metres) of the footprints that were not
    regularised (:func:`~..io.vector.label_outlines`). Attributes are SI (metres, m²,
    m³) whatever the data's units; geometry stays in metres here.
    """
    out = []
    for b in res.buildings:
        ring = (outlines or {}).get(b["id"])
        lod1, lod2 = building_solids(b, ring)
        attrs = {"measuredHeight": round(float(b["height"]), 3),
                 "eaveHeight": round(float(b["eave_height"]), 3),
                 "storeysAboveGround": int(b["storeys"]),
                 "roofType": b["roof_type"],
                 "roofSlope": round(float(b["slope"]), 1),
                 "footprintArea": round(float(b["area"]), 2),
                 "volume": round(float(b["volume"]), 1),
                 "groundHeight": round(float(b["ground"]), 3)}
        out.append({"id": b["id"], "attributes": attrs, "lod1": lod1, "lod2": lod2})
    return out

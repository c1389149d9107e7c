"""CityJSON 2.0 and Wavefront OBJ writers for building solids (:mod:`..lidar.citymodel`).

:func:`write_cityjson` writes one ``Building`` per building with its attributes and
its LOD1 (and LOD2 where modelled) ``Solid`` geometries with semantic surfaces,
integer vertices under a ``transform`` (1 mm in the data's units), the CRS as an OGC
URL and the geographical extent — valid against the official CityJSON 2.0.2 schema.
:func:`write_obj` writes the same solids as one triangulated OBJ object per building
(coordinates relative to an origin given in a comment, as 3D viewers lose precision on
projected coordinates). Geometry comes in metres and is written in the data's units
(``h``, ``v``: metres per horizontal / vertical unit).

References
----------
CityJSON Specifications 2.0.1 (2023), https://www.cityjson.org/specs/2.0.1/.
"""
from __future__ import annotations

import json
import os
from typing import Optional, Sequence

import numpy as np

from .contract import atomic_output

__all__ = ["cityjson_document", "write_cityjson", "write_obj", "triangulate",
           "newell_normal"]

SCALE = 0.001


def _epsg_url(crs: Optional[str]) -> Optional[str]:
    if not crs:
        return None
    from .crs import spatial_reference
    try:
        srs = spatial_reference(crs)
    except Exception:  # noqa: BLE001 - an unknown CRS only loses the metadata field
        return None
    srs.AutoIdentifyEPSG()
    code = srs.GetAuthorityCode(None)
    return f"https://www.opengis.net/def/crs/EPSG/0/{code}" if code else None


class _Vertices:
    """Integer vertex pool (``round(coordinate / scale)``), shared by every geometry."""

    def __init__(self, translate):
        self.translate = np.asarray(translate, dtype=float)
        self.index = {}
        self.rows = []

    def ids(self, points) -> list:
        q = np.round((np.asarray(points, dtype=float) - self.translate) / SCALE).astype(
            np.int64)
        out = []
        for row in map(tuple, q.tolist()):
            i = self.index.get(row)
            if i is None:
                i = self.index[row] = len(self.rows)
                self.rows.append(list(row))
            out.append(i)
        # drop consecutive duplicates created by the rounding
        ring = [v for k, v in enumerate(out) if k == 0 or v != out[k - 1]]
        if len(ring) > 1 and ring[0] == ring[-1]:
            ring.pop()
        return ring


def _geometry(solid, lod: str, pool: _Vertices, to_data):
    kinds = sorted(set(solid.semantics))
    shell, values = [], []
    for face, sem in zip(solid.faces, solid.semantics):
        ring = pool.ids(to_data(face))
        if len(ring) >= 3:
            shell.append([ring])
            values.append(kinds.index(sem))
    return {"type": "Solid", "lod": lod, "boundaries": [shell],
            "semantics": {"surfaces": [{"type": k} for k in kinds], "values": [values]}}


def cityjson_document(buildings: Sequence[dict], *, crs: Optional[str] = None,
                      h: float = 1.0, v: float = 1.0, title: str = "") -> dict:
    """Return the CityJSON document of ``buildings``.

    ``buildings``: dicts with ``id``, ``attributes``, ``lod1`` and ``lod2``
    (:class:`~..lidar.citymodel.Solid` or None, metres).
    """
    def to_data(p):
        p = np.asarray(p, dtype=float)
        return np.column_stack([p[:, 0] / h, p[:, 1] / h, p[:, 2] / v])
    pts = [to_data(f) for b in buildings for s in (b["lod1"], b.get("lod2")) if s
           for f in s.faces]
    allp = np.vstack(pts) if pts else np.zeros((1, 3))
    lo, hi = allp.min(axis=0), allp.max(axis=0)
    pool = _Vertices(np.floor(lo))
    objects = {}
    for b in buildings:
        geoms = [_geometry(b["lod1"], "1.2", pool, to_data)]
        if b.get("lod2") is not None:
            geoms.append(_geometry(b["lod2"], "2.2", pool, to_data))
        objects[str(b["id"])] = {"type": "Building", "attributes": b["attributes"],
                                 "geometry": geoms}
    meta = {"geographicalExtent": [float(x) for x in (*lo, *hi)]}
    url = _epsg_url(crs)
    if url:
        meta["referenceSystem"] = url
    if title:
        meta["title"] = title
    return {"type": "CityJSON", "version": "2.0",
            "transform": {"scale": [SCALE] * 3, "translate": [float(t) for t in pool.translate]},
            "metadata": meta, "CityObjects": objects, "vertices": pool.rows}


def write_cityjson(path, buildings: Sequence[dict], **kw) -> int:
    """Write :func:`cityjson_document` to ``path``; returns the number of buildings."""
    doc = cityjson_document(buildings, **kw)
    with atomic_output(os.fspath(path)) as tmp:
        with open(tmp, "w", encoding="utf-8") as fh:
            json.dump(doc, fh, separators=(",", ":"), ensure_ascii=False)
    return len(doc["CityObjects"])


def newell_normal(points) -> np.ndarray:
    """Area-weighted normal of a polygon (Newell's method)."""
    p = np.asarray(points, dtype=float)
    q = np.roll(p, -1, axis=0)
    return 0.5 * np.array([np.sum((p[:, 1] - q[:, 1]) * (p[:, 2] + q[:, 2])),
                           np.sum((p[:, 2] - q[:, 2]) * (p[:, 0] + q[:, 0])),
                           np.sum((p[:, 0] - q[:, 0]) * (p[:, 1] + q[:, 1]))])


def triangulate(face) -> list:
    """Triangles (index triples) of a planar polygon by ear clipping in its best plane."""
    p = np.asarray(face, dtype=float)
    n = len(p)
    if n == 3:
        return [(0, 1, 2)]
    nrm = newell_normal(p)
    drop = int(np.argmax(np.abs(nrm)))
    q = p[:, [(drop + 1) % 3, (drop + 2) % 3]]      # cyclic: counter-clockwise seen
    if nrm[drop] < 0:                                # from +axis keeps its sense
        q = q[:, ::-1]
    idx = list(range(n))
    tris = []

    def cross(o, a, b):
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
    guard = 0
    while len(idx) > 3 and guard < 10 * n:
        guard += 1
        for k in range(len(idx)):
            i0, i1, i2 = idx[k - 1], idx[k], idx[(k + 1) % len(idx)]
            if cross(q[i0], q[i1], q[i2]) <= 1e-12:
                continue
            inside = False
            for j in idx:
                if j in (i0, i1, i2):
                    continue
                if (cross(q[i0], q[i1], q[j]) >= 0 and cross(q[i1], q[i2], q[j]) >= 0
                        and cross(q[i2], q[i0], q[j]) >= 0):
                    inside = True
                    break
            if not inside:
                tris.append((i0, i1, i2))
                idx.pop(k)
                break
        else:
            break
    if len(idx) == 3:
        tris.append(tuple(idx))
    return tris


def write_obj(path, buildings: Sequence[dict], *, h: float = 1.0, v: float = 1.0,
              lod: str = "lod2") -> int:
    """Write one OBJ object per building (its ``lod`` solid, LOD1 where none).

    Coordinates in the data's units relative to the origin written in the header
    comment; faces triangulated, counter-clockwise seen from outside.
    """
    solids = [(b["id"], b.get(lod) or b["lod1"]) for b in buildings]
    pts = [f for _i, s in solids for f in s.faces]
    origin = np.floor(np.vstack(pts).min(axis=0)) if pts else np.zeros(3)
    scale = np.array([h, h, v])
    lines = ["# Geomatics Toolbox buildings (" + lod + ")",
             f"# origin {origin[0] / h:.3f} {origin[1] / h:.3f} {origin[2] / v:.3f}"]
    base = 1
    for bid, s in solids:
        lines.append(f"o building_{bid}")
        verts, tris, index = [], [], {}
        for f in s.faces:
            ids = []
            for p in np.round((f - origin) / scale, 3).tolist():
                key = tuple(p)
                if key not in index:
                    index[key] = len(verts)
                    verts.append(p)
                ids.append(index[key])
            tris.extend((ids[a], ids[b], ids[c]) for a, b, c in triangulate(f))
        lines.extend(f"v {x:.3f} {y:.3f} {z:.3f}" for x, y, z in verts)
        lines.extend(f"f {a + base} {b + base} {c + base}" for a, b, c in tris)
        base += len(verts)
    with atomic_output(os.fspath(path)) as tmp:
        with open(tmp, "w", encoding="utf-8", newline="\n") as fh:
            fh.write("\n".join(lines) + "\n")
    return len(solids)

"""CityJSON validation for the tests: the official schema plus the checks of cjval.

The official validator, cjval (Rust; https://github.com/cityjson/cjval, also behind
``cjio validate`` through its Python binding ``cjvalpy``), cannot run here: ``cjvalpy``
has no wheel or sdist on the package index this machine reaches (``pip install
cjvalpy``: "from versions: none") and crates.io, needed to build cjval with cargo, is
out of reach. So this module implements, from cjval's documented list, every check it
makes beyond JSON syntax, each under cjval's name:

errors
    ``schema`` (the official CityJSON 2.0.2 schema, Draft 7, via jsonschema),
    ``duplicate_keys`` (CityObjects with the same id: JSON parsers keep the last),
    ``invalid_extensions`` (a ``+Type`` CityObject, a ``+root`` property or a ``+attr``
    attribute needs an Extension schema; any declared Extension is an error here, as its
    schema cannot be fetched offline to validate against),
    ``parents_children_consistency`` (every child exists and lists the parent in its
    ``parents``; every parent exists),
    ``wrong_vertex_index`` (every vertex index of every geometry below the number of
    vertices),
    ``semantics_arrays`` (``semantics.values`` has the shape of ``boundaries`` and every
    value is null or an index into ``semantics.surfaces``; also, beyond cjval, every
    semantic surface's ``parent``/``children`` index exists),
    ``textures`` / ``materials`` (the writer makes no appearance: one is an error until
    a real check is written for it);
warnings (cjval's; the tests require none of them either)
    ``extra_root_properties``, ``duplicate_vertices`` (identical integer vertices),
    ``unused_vertices``;
geometry (beyond cjval, which checks syntax only — val3dity's job)
    ``solid``: every shell of a Solid closed and 2-manifold (each edge used once in each
    direction), outward (positive signed volume), faces of at least 3 distinct vertices
    and planar within ``planarity`` (data units).

:func:`assert_valid_cityjson` runs everything on a written file and fails the test with
the first problems of each kind; :func:`cityjson_problems` returns them (for tests of
the checker itself on broken models).
"""
from __future__ import annotations

import json
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
SCHEMA = ROOT.parent / "shared" / "data" / "cityjson" / "cityjson-2.0.2.min.schema.json"

ROOT_PROPERTIES = {"type", "version", "extensions", "transform", "metadata", "CityObjects",
                   "vertices", "appearance", "geometry-templates"}
_DEPTH = {"MultiPoint": 1, "MultiLineString": 2, "MultiSurface": 3, "CompositeSurface": 3,
          "Solid": 4, "MultiSolid": 5, "CompositeSolid": 5, "GeometryInstance": 1}
#: nesting of ``semantics.values`` (0 = one value per boundary element of MultiPoint &c.)
_SEM_DEPTH = {"MultiPoint": 1, "MultiLineString": 1, "MultiSurface": 1,
              "CompositeSurface": 1, "Solid": 2, "MultiSolid": 3, "CompositeSolid": 3}


def _load(text: str):
    """Parse JSON, recording the duplicate keys of CityObjects (cjval's duplicate check)."""
    dups = []

    def hook(pairs):
        seen = {}
        for k, v in pairs:
            if k in seen:
                dups.append(k)
            seen[k] = v
        return seen
    return json.loads(text, object_pairs_hook=hook), dups


def _indices(b, depth):
    """Every integer of a boundary array nested ``depth`` deep."""
    if depth == 0 or not isinstance(b, list):
        yield b
        return
    for x in b:
        yield from _indices(x, depth - 1)


def _shape(a, depth):
    """Lengths of the nested arrays down to ``depth`` (None where not an array)."""
    if not isinstance(a, list):
        return None
    if depth == 1:
        return len(a)
    return [_shape(x, depth - 1) for x in a]


def check_solid(shell, vertices, planarity: float = 0.01):
    """Problems of one Solid shell (real coordinates ``vertices``) and its signed volume."""
    problems = []
    edges = {}
    vol = 0.0
    for k, surface in enumerate(shell):
        ring = surface[0]
        if len(set(ring)) < 3 or len(set(ring)) != len(ring):
            problems.append(f"surface {k}: ring {ring} has repeated or < 3 vertices")
            continue
        p = vertices[ring]
        q = np.roll(p, -1, axis=0)
        n = 0.5 * np.array([np.sum((p[:, 1] - q[:, 1]) * (p[:, 2] + q[:, 2])),
                            np.sum((p[:, 2] - q[:, 2]) * (p[:, 0] + q[:, 0])),
                            np.sum((p[:, 0] - q[:, 0]) * (p[:, 1] + q[:, 1]))])
        if np.linalg.norm(n) == 0:
            problems.append(f"surface {k}: zero area")
            continue
        n = n / np.linalg.norm(n)
        off = np.abs((p - p.mean(axis=0)) @ n).max()
        if off > planarity:
            problems.append(f"surface {k}: not planar ({off:.4f} > {planarity})")
        for a, b in zip(ring, ring[1:] + ring[:1]):
            edges[(a, b)] = edges.get((a, b), 0) + 1
        for j in range(1, len(p) - 1):
            vol += np.dot(p[0], np.cross(p[j], p[j + 1])) / 6.0
    for (a, b), c in edges.items():
        if c != 1 or edges.get((b, a)) != 1:
            problems.append(f"edge {a}-{b} used {c}x, reverse {edges.get((b, a), 0)}x: "
                            "shell not closed/2-manifold or faces not consistently oriented")
            break
    if not vol > 0:
        problems.append(f"signed volume {vol:.3f} <= 0 (shell inward)")
    return problems, vol


def _extensions(doc, out):
    """invalid_extensions (nothing may need a schema we cannot fetch); extra root keys."""
    for name in doc.get("extensions", {}) or {}:
        out["invalid_extensions"].append(f"Extension {name!r} declared: its schema cannot "
                                         "be fetched to validate against")
    for k in doc:
        if k.startswith("+"):
            out["invalid_extensions"].append(f"root property {k!r} has no schema")
        elif k not in ROOT_PROPERTIES:
            out["extra_root_properties"].append(f"root property {k!r} not in CityJSON")
    for oid, co in doc.get("CityObjects", {}).items():
        if str(co.get("type", "")).startswith("+"):
            out["invalid_extensions"].append(f"#{oid}: type {co['type']!r} has no schema")
        for a in co.get("attributes", {}) or {}:
            if a.startswith("+"):
                out["invalid_extensions"].append(f"#{oid}: attribute {a!r} has no schema")


def _hierarchy(cos, out):
    """parents_children_consistency."""
    bad = out["parents_children_consistency"]
    for oid, co in cos.items():
        for c in co.get("children", []):
            if c not in cos:
                bad.append(f"#{oid}: child #{c} does not exist")
            elif oid not in cos[c].get("parents", []):
                bad.append(f"#{c} does not list its parent #{oid}")
        for p in co.get("parents", []):
            if p not in cos:
                bad.append(f"#{oid} is an orphan (parent #{p} does not exist)")


def _semantics(where, g, out):
    """semantics_arrays: values shaped as the boundaries, each null or a surface index."""
    sem, kind = g.get("semantics"), g.get("type")
    if sem is None or kind not in _SEM_DEPTH:
        return
    d = _SEM_DEPTH[kind]
    shape = _shape(sem.get("values"), d)
    if shape != _shape(g.get("boundaries"), d):
        out["semantics_arrays"].append(f"{where}: semantics values not the shape of the "
                                       "boundaries")
    ns = len(sem.get("surfaces", []))
    vals = [v for v in _indices(sem.get("values", []), d) if v is not None] \
        if shape is not None else []
    if any(not isinstance(v, int) or not 0 <= v < ns for v in vals):
        out["semantics_arrays"].append(f"{where}: a semantics value overflows the {ns} "
                                       "surfaces")
    for si, s in enumerate(sem.get("surfaces", [])):
        refs = ([s["parent"]] if "parent" in s else []) + s.get("children", [])
        if any(not 0 <= r < ns for r in refs):
            out["semantics_arrays"].append(f"{where}: surface {si} parent/children out of "
                                           "range")


def _geometries(doc, out, planarity):
    """wrong_vertex_index, semantics_arrays, textures/materials, solids; returns used ids."""
    verts = doc.get("vertices", [])
    nv = len(verts)
    used = set()
    t = doc.get("transform", {"scale": [1, 1, 1], "translate": [0, 0, 0]})
    real = np.asarray(verts, float).reshape(-1, 3) * t["scale"] + t["translate"]
    for oid, co in doc.get("CityObjects", {}).items():
        for gi, g in enumerate(co.get("geometry", [])):
            kind, where = g.get("type"), f"#{oid} geom {gi} (lod {g.get('lod')})"
            if kind not in _DEPTH:
                continue
            idx = list(_indices(g.get("boundaries", []), _DEPTH[kind]))
            bad = [i for i in idx if not isinstance(i, int) or not 0 <= i < nv]
            if bad:
                out["wrong_vertex_index"].append(f"{where}: vertices {bad[:5]} do not "
                                                 f"exist ({nv} vertices)")
            used.update(i for i in idx if isinstance(i, int))
            for key in ("texture", "material"):
                if key in g:
                    out[key + "s"].append(f"{where}: {key} not checked here")
            _semantics(where, g, out)
            if kind == "Solid" and not bad:
                for shell in g["boundaries"]:
                    out["solid"] += [f"{where}: {p}"
                                     for p in check_solid(shell, real, planarity)[0]]
    return used


def cityjson_problems(text: str, *, schema: Path = SCHEMA, planarity: float = 0.01) -> dict:
    """Run every check on CityJSON ``text``; returns ``{check name: [problems]}``.

    Empty lists everywhere = valid. ``schema=None`` skips the schema check.
    """
    out = {k: [] for k in ("schema", "duplicate_keys", "invalid_extensions",
                           "parents_children_consistency", "wrong_vertex_index",
                           "semantics_arrays", "textures", "materials",
                           "extra_root_properties", "duplicate_vertices",
                           "unused_vertices", "solid")}
    doc, dups = _load(text)
    if schema is not None:
        import jsonschema
        validator = jsonschema.Draft7Validator(json.loads(Path(schema).read_text()))
        out["schema"] = [f"{e.message} [{'/'.join(map(str, e.absolute_path))}]"
                         for e in validator.iter_errors(doc)]
    cos = doc.get("CityObjects", {})
    out["duplicate_keys"] = [f"key {k!r} repeated" for k in dups if k in cos]
    _extensions(doc, out)
    _hierarchy(cos, out)
    used = _geometries(doc, out, planarity)
    if "appearance" in doc:
        out["textures"].append("appearance present: not checked here")
    seen = {}
    for i, v in enumerate(doc.get("vertices", [])):
        if tuple(v) in seen:
            out["duplicate_vertices"].append(f"vertex #{i} = #{seen[tuple(v)]} {v}")
        else:
            seen[tuple(v)] = i
    out["unused_vertices"] = [f"vertex #{i} unused"
                              for i in range(len(doc.get("vertices", []))) if i not in used]
    return out


def assert_valid_cityjson(path, *, schema: Path = SCHEMA, planarity: float = 0.01) -> dict:
    """Fail unless the CityJSON file passes every check (errors and warnings alike).

    Returns the parsed document.
    """
    if schema is not None and not Path(schema).exists():
        import pytest
        pytest.skip(f"the official CityJSON schema is absent: {schema}")
    text = Path(path).read_text(encoding="utf-8")
    problems = cityjson_problems(text, schema=schema, planarity=planarity)
    found = {k: v[:3] for k, v in problems.items() if v}
    assert not found, found
    return json.loads(text)

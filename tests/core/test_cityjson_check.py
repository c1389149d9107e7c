"""The CityJSON checker the tests validate every written model with (tests/cityjson_check.py:
the official schema plus cjval's checks, since cjval itself cannot run here) catches
each defect it claims to: a deliberately broken copy of a real output fails each check."""
from __future__ import annotations

import copy
import json
import sys
from pathlib import Path

import numpy as np
import pytest

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from cityjson_check import SCHEMA, assert_valid_cityjson, cityjson_problems  # noqa: E402


@pytest.fixture(scope="module")
def model(tmp_path_factory):
    """A CityJSON written by buildings_file: two buildings, LOD1 + LOD2."""
    pytest.importorskip("jsonschema")
    if not SCHEMA.exists():
        pytest.skip(f"the official CityJSON schema is absent: {SCHEMA}")
    from geomatics_toolbox.core.io.las import write_las
    from geomatics_toolbox.core.lidar.buildings_file import BuildingOutputs, buildings_file
    d = tmp_path_factory.mktemp("cjcheck")
    rng = np.random.default_rng(1)
    n = 30_000
    x, y = rng.uniform(0, 80, n), rng.uniform(0, 60, n)
    a = (x > 10) & (x < 30) & (y > 10) & (y < 25)
    b = (x > 45) & (x < 70) & (y > 30) & (y < 50)
    z = 50.0 + np.where(a, 6.0, 0.0) + np.where(b, 9.0, 0.0) + rng.normal(0, 0.02, n)
    cls = np.where(a | b, 1, 2).astype(np.uint8)
    write_las(d / "t.laz", x + 500_000, y + 4_000_000, z,
              dimensions={"classification": cls}, crs="EPSG:32632")
    res, _ = buildings_file(str(d / "t.laz"), BuildingOutputs(str(d / "b.gpkg"),
                                                              cityjson=str(d / "b.json")))
    assert len(res.buildings) == 2
    return (d / "b.json").read_text(encoding="utf-8")


def test_written_model_passes_every_check(model, tmp_path):
    problems = cityjson_problems(model)
    assert not any(problems.values()), {k: v for k, v in problems.items() if v}
    assert len(problems) == 12                  # every check ran and reported
    (tmp_path / "m.json").write_text(model, encoding="utf-8")
    doc = assert_valid_cityjson(tmp_path / "m.json")
    assert {g["lod"] for co in doc["CityObjects"].values() for g in co["geometry"]} == \
        {"1.2", "2.2"}


def _repoint_first_vertex(doc, shell, dz=0):
    """Give the first vertex of the first face a new copy of itself (raised by ``dz``)."""
    doc["vertices"].append(list(doc["vertices"][shell[0][0][0]]))
    doc["vertices"][-1][2] += dz
    shell[0][0][0] = len(doc["vertices"]) - 1


def _reverse_all(shell):
    for s in shell:
        s[0].reverse()


#: how to break a model: f(doc, city object, its first geometry, its shell, another id)
BREAKS = {
    "wrong_vertex_index": lambda d, co, g, sh, o: sh[0][0].__setitem__(
        0, len(d["vertices"]) + 3),
    "parents_children_consistency": lambda d, co, g, sh, o: co.__setitem__(
        "children", [o]),                       # the child does not name its parent
    "orphan": lambda d, co, g, sh, o: co.__setitem__("parents", ["no-such-building"]),
    "semantics_arrays": lambda d, co, g, sh, o: g["semantics"]["values"][0].append(0),
    "semantics_overflow": lambda d, co, g, sh, o: g["semantics"]["values"][0].__setitem__(
        0, len(g["semantics"]["surfaces"])),
    "invalid_extensions": lambda d, co, g, sh, o: co.__setitem__("type", "+PowerPlant"),
    "extension_declared": lambda d, co, g, sh, o: d.__setitem__("extensions", {
        "Noise": {"url": "https://example.org/noise.ext.json", "version": "2.0"}}),
    "extension_attribute": lambda d, co, g, sh, o: co["attributes"].__setitem__(
        "+colour", "red"),
    "extra_root_properties": lambda d, co, g, sh, o: d.__setitem__("myStuff", 1),
    "duplicate_vertices": lambda d, co, g, sh, o: _repoint_first_vertex(d, sh),
    "unused_vertices": lambda d, co, g, sh, o: d["vertices"].append([1, 2, 3]),
    "inward": lambda d, co, g, sh, o: _reverse_all(sh),
    "open": lambda d, co, g, sh, o: sh.pop(),
    "non_planar": lambda d, co, g, sh, o: _repoint_first_vertex(d, sh, 500),  # 0.5 m off
    "flipped_face": lambda d, co, g, sh, o: sh[0][0].reverse(),
    "schema": lambda d, co, g, sh, o: g.__setitem__("lod", 2.2),  # the schema wants a str
    "textures": lambda d, co, g, sh, o: g.__setitem__("texture",
                                                      {"rgb": {"values": [[[0]]]}}),
}


def _break(doc, how):
    ids = sorted(doc["CityObjects"])
    co = doc["CityObjects"][ids[0]]
    g = co["geometry"][0]
    BREAKS[how](doc, co, g, g["boundaries"][0], ids[1])
    return doc


CASES = [
    ("wrong_vertex_index", "wrong_vertex_index"),
    ("parents_children_consistency", "parents_children_consistency"),
    ("orphan", "parents_children_consistency"),
    ("semantics_arrays", "semantics_arrays"),
    ("semantics_overflow", "semantics_arrays"),
    ("invalid_extensions", "invalid_extensions"),
    ("extension_declared", "invalid_extensions"),
    ("extension_attribute", "invalid_extensions"),
    ("extra_root_properties", "extra_root_properties"),
    ("duplicate_vertices", "duplicate_vertices"),
    ("unused_vertices", "unused_vertices"),
    ("inward", "solid"),
    ("open", "solid"),
    ("non_planar", "solid"),
    ("flipped_face", "solid"),
    ("schema", "schema"),
    ("textures", "textures"),
]


def test_every_break_is_tried():
    assert {how for how, _ in CASES} == set(BREAKS)


@pytest.mark.parametrize("how, check", CASES)
def test_each_broken_model_is_caught(model, tmp_path, how, check):
    doc = _break(copy.deepcopy(json.loads(model)), how)
    problems = cityjson_problems(json.dumps(doc))
    assert problems[check], (how, {k: v for k, v in problems.items() if v})
    path = tmp_path / "broken.json"
    path.write_text(json.dumps(doc), encoding="utf-8")
    with pytest.raises(AssertionError, match=check):
        assert_valid_cityjson(path)


def test_duplicate_city_object_ids_are_caught(model):
    """Two CityObjects with one id (JSON parsers silently keep the last)."""
    oid = sorted(json.loads(model)["CityObjects"])[0]
    key = f'"{oid}":'
    i = model.index(key, model.index('"CityObjects"'))
    dup = model[:i] + key + '{"type":"Building"},' + model[i:]
    problems = cityjson_problems(dup)
    assert problems["duplicate_keys"], problems

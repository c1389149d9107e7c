"""Buildings on the synthetic city scene (footbridge, sheds under trees, gabled, hipped,
flat with parapet) at 2 and 10 pts/m², and their LOD1/LOD2 CityJSON and OBJ models."""
from __future__ import annotations

import math
import sys
from pathlib import Path

import numpy as np
import pytest

from geomatics_toolbox.core.lidar import buildings as core_b
from geomatics_toolbox.synthetic.city import city_scene, write_scene

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from cityjson_check import SCHEMA, assert_valid_cityjson, check_solid  # noqa: E402

ROOT = Path(__file__).resolve().parents[2]


def _extract(scene, **kw):
    cls = scene.classification.copy()
    cls[np.isin(cls, (5, 6, 17))] = 1          # as after a ground filter (9 kept)
    return core_b.extract_buildings(scene.x, scene.y, scene.z, cls, **kw)


def _match(scene, res):
    """{structure name: building dict} by the footprint's centre inside the truth."""
    xs, ys = np.meshgrid(res.grid.x_centers(), res.grid.y_centers())
    out = {}
    for b in res.buildings:
        d = res.labels == b["id"]
        cx, cy = xs[d].mean(), ys[d].mean()
        for s in scene.buildings + [scene.bridge]:
            if s.inside(cx, cy, pad=1.0):
                out[s.name] = b
    return out


@pytest.fixture(scope="module", params=[2.0, 10.0], ids=["2pts", "10pts"])
def scene_result(request):
    scene = city_scene(density=request.param)
    return scene, _extract(scene)


def test_no_bridge_building(scene_result):
    """The footbridge is not a building: no footprint over its deck; it is refused as a
    bridge (its cells are the bridge mask), while every house is found."""
    scene, res = scene_result
    found = _match(scene, res)
    assert "footbridge" not in found
    xs, ys = np.meshgrid(res.grid.x_centers(), res.grid.y_centers())
    deck = scene.bridge.inside(xs, ys)
    assert not (res.labels[deck] > 0).any()
    assert res.bridges[deck].mean() > 0.3
    assert set(found) == {b.name for b in scene.buildings}, set(found)
    assert len(res.buildings) == len(scene.buildings)


def test_heights_from_roof_points_only(scene_result):
    """Shed heights within 0.3 m under overhanging crowns (9–10 m canopy over 2.3–2.5 m
    roofs), every height within 0.3 m (the parapet is not the roof)."""
    scene, res = scene_result
    found = _match(scene, res)
    for s in scene.buildings:
        b = found[s.name]
        assert abs(b["height"] - scene.true_height(s)) <= 0.3, (s.name, b["height"],
                                                                scene.true_height(s))
    for name in ("shed under trees 1", "shed under trees 2"):
        assert found[name]["storeys"] == 1 and found[name]["height"] < 3.0


def test_lod2_roof_types(scene_result):
    scene, res = scene_result
    found = _match(scene, res)
    want = {"gabled": "gabled", "hipped": "hipped", "flat with parapet": "flat",
            "shed under trees 1": "flat", "shed under trees 2": "flat"}
    got = {k: found[k]["roof_type"] for k in want}
    assert got == want
    g = found["gabled"]
    assert g["slope"] == pytest.approx(35.0, abs=3.0)
    assert found["hipped"]["slope"] == pytest.approx(30.0, abs=3.0)
    # eaves: gabled 5 m, hipped 6 m above the base
    s = {b.name: b for b in scene.buildings}
    for name, eave in (("gabled", 5.0), ("hipped", 6.0)):
        true_eave = scene.true_height(s[name]) - (s[name].top - eave)
        assert abs(found[name]["eave_height"] - true_eave) <= 0.3


def test_storeys_follow_the_storey_height():
    scene = city_scene(density=4.0)
    a = {b["roof_type"] + str(round(b["height"])): b["storeys"] for b in _extract(
        scene, storey_height=2.5).buildings}
    b3 = _extract(scene, storey_height=3.5).buildings
    for b in b3:
        assert b["storeys"] == max(1, int(b["mean_height"] // 3.5))
    assert max(a.values()) >= max(b["storeys"] for b in b3)


def test_classify_labels_bridge_deck_and_buildings():
    """In the full classification the deck is class 17 (bridge deck), never 6; roofs 6;
    the shed roofs under crowns are 6 and the crowns over them vegetation."""
    from geomatics_toolbox.core.lidar.classify import ClassifyOptions, classify_points
    scene = city_scene(density=4.0)
    cls = scene.classification.copy()
    cls[np.isin(cls, (5, 6, 17))] = 1
    res = classify_points(scene.x, scene.y, scene.z, cls,
                          options=ClassifyOptions(ground="keep"))
    out, truth = res.classes, scene.classification
    assert not (out[truth == 17] == 6).any()
    # the deck over the valley (the ends run into the banks at under 2 m)
    span = (truth == 17) & (scene.z - scene.terrain(scene.x, scene.y) > 2.5)
    assert (out[span] == 17).mean() > 0.9, (out[span] == 17).mean()
    assert (truth[out == 6] == 6).mean() > 0.97
    assert (out[truth == 6] == 6).mean() > 0.9
    assert (out[truth == 9] == 9).all()
    assert np.isin(out[truth == 5], (3, 4, 5)).mean() > 0.97


# ------------------------------------------------------------------ 3D city models
def _check_solid(shell, vertices):
    """Closed 2-manifold, consistently outward, planar faces (tests/cityjson_check.py)."""
    problems, vol = check_solid(shell, vertices)
    assert not problems, problems
    return vol


def test_cityjson_lod1_lod2_valid(tmp_path):
    """CityJSON 2.0 from the scene: zero schema errors (official 2.0.2 schema), every
    solid closed and outward, LOD2 for the modelled roofs, volumes as measured; the OBJ
    loads in trimesh with one watertight, positive-volume object per building."""
    pytest.importorskip("jsonschema")
    if not SCHEMA.exists():
        pytest.skip(f"CityJSON schema absent: {SCHEMA}")
    from geomatics_toolbox.core.lidar.buildings_file import BuildingOutputs, buildings_file
    scene = city_scene(density=4.0)
    cls = scene.classification.copy()
    cls[np.isin(cls, (5, 6, 17))] = 1
    scene.classification = cls
    laz = write_scene(scene, tmp_path / "city.laz")
    outs = BuildingOutputs(str(tmp_path / "b.gpkg"), cityjson=str(tmp_path / "b.city.json"),
                           obj=str(tmp_path / "b.obj"))
    res, _units = buildings_file(laz, outs)
    doc = assert_valid_cityjson(tmp_path / "b.city.json")      # schema + cjval's checks
    assert doc["metadata"]["referenceSystem"].endswith("/EPSG/0/32632")
    t = doc["transform"]
    verts = np.asarray(doc["vertices"], float) * t["scale"] + t["translate"]
    assert len(doc["CityObjects"]) == len(res.buildings) == 5
    lods = {}
    by_id = {str(b["id"]): b for b in res.buildings}
    for oid, obj in doc["CityObjects"].items():
        assert obj["type"] == "Building"
        b = by_id[oid]
        assert obj["attributes"]["roofType"] == b["roof_type"]
        assert obj["attributes"]["measuredHeight"] == pytest.approx(b["height"], abs=1e-3)
        for g in obj["geometry"]:
            vol = _check_solid(g["boundaries"][0], verts)
            lods.setdefault(g["lod"], []).append(oid)
            sem = {s["type"] for s in g["semantics"]["surfaces"]}
            assert sem == {"GroundSurface", "WallSurface", "RoofSurface"}
            if g["lod"] == "2.2":
                assert vol == pytest.approx(b["volume"], rel=0.08)
    assert len(lods["1.2"]) == 5 and len(lods["2.2"]) == 5
    trimesh = pytest.importorskip("trimesh")
    scene3d = trimesh.load(str(tmp_path / "b.obj"), force="scene", split_objects=True,
                           group_material=False, process=False)
    meshes = list(scene3d.geometry.values())
    assert len(meshes) == 5
    for m in meshes:
        m.merge_vertices()
        assert m.is_watertight and m.is_winding_consistent and m.volume > 0


def test_feet_tile_gives_the_same_buildings(tmp_path):
    """The scene in US survey feet (x, y, z) gives the buildings of its metre copy:
    heights and storeys equal, areas equal (m²), footprints in feet, CityJSON in feet."""
    from osgeo import ogr

    from geomatics_toolbox.core.io.vector import read_polygons
    from geomatics_toolbox.core.lidar.buildings_file import BuildingOutputs, buildings_file
    from geomatics_toolbox.synthetic.hostile import unit_copy
    scene = city_scene(density=4.0)
    cls = scene.classification.copy()
    cls[np.isin(cls, (5, 6, 17))] = 1
    scene.classification = cls
    m = write_scene(scene, tmp_path / "m.laz")
    ft = unit_copy(m, str(tmp_path / "ft.laz"))
    rm, _ = buildings_file(m, BuildingOutputs(str(tmp_path / "m.gpkg"),
                                              cityjson=str(tmp_path / "m.json")))
    rf, uf = buildings_file(ft, BuildingOutputs(str(tmp_path / "f.gpkg"),
                                                cityjson=str(tmp_path / "f.json")))
    assert uf.horizontal.symbol == "ftUS" and not uf.metric
    assert len(rm.buildings) == len(rf.buildings) == 5
    key = sorted
    bm = key(rm.buildings, key=lambda b: b["area"])
    bf = key(rf.buildings, key=lambda b: b["area"])
    for a, b in zip(bm, bf):
        assert a["roof_type"] == b["roof_type"] and a["storeys"] == b["storeys"]
        assert b["height"] == pytest.approx(a["height"], abs=0.05)
        assert b["area"] == pytest.approx(a["area"], rel=0.03)
    ftus = 1200 / 3937
    pm = sorted(ogr.CreateGeometryFromWkt(w).GetArea() for _a, w in read_polygons(
        tmp_path / "m.gpkg"))
    pf = sorted(ogr.CreateGeometryFromWkt(w).GetArea() for _a, w in read_polygons(
        tmp_path / "f.gpkg"))
    assert np.allclose(np.asarray(pf) * ftus ** 2, pm, rtol=0.03)
    attrs = sorted((a["height_m"] for a, _w in read_polygons(tmp_path / "f.gpkg")))
    assert np.allclose(attrs, sorted(b["height"] for b in rm.buildings), atol=0.05)
    jm = assert_valid_cityjson(tmp_path / "m.json")
    jf = assert_valid_cityjson(tmp_path / "f.json")
    em, ef = jm["metadata"]["geographicalExtent"], jf["metadata"]["geographicalExtent"]
    assert ef[3] - ef[0] == pytest.approx((em[3] - em[0]) / ftus, rel=0.01)
    assert ef[5] - ef[2] == pytest.approx((em[5] - em[2]) / ftus, rel=0.01)
    assert not math.isnan(ef[0])


@pytest.mark.parametrize("name", ["lastools_fusa.laz", "pdal_nm_usft.laz"])
def test_city_models_of_real_files(name, tmp_path):
    """Real suburban houses (irregular footprints, complex roofs) and a feet forest tile:
    the CityJSON validates against the schema and every solid is closed and outward;
    the OBJ loads watertight."""
    pytest.importorskip("jsonschema")
    trimesh = pytest.importorskip("trimesh")
    src = ROOT.parent / "shared" / "data" / "real" / name
    if not src.exists() or not SCHEMA.exists():
        pytest.skip(f"shared data absent: {src} / {SCHEMA}")
    from geomatics_toolbox.core.lidar.buildings_file import BuildingOutputs, buildings_file
    outs = BuildingOutputs(str(tmp_path / "b.gpkg"), cityjson=str(tmp_path / "b.json"),
                           obj=str(tmp_path / "b.obj"))
    res, units = buildings_file(str(src), outs)
    doc = assert_valid_cityjson(tmp_path / "b.json")           # schema + cjval's checks
    assert len(doc["CityObjects"]) == len(res.buildings)
    if name.startswith("lastools"):
        assert len(res.buildings) >= 20 and not res.bridges.any()
    if not res.buildings:                       # the forest tile: a valid, empty model
        assert doc["CityObjects"] == {} and doc["vertices"] == []
        return
    t = doc["transform"]
    verts = np.asarray(doc["vertices"], float) * t["scale"] + t["translate"]
    for obj in doc["CityObjects"].values():
        for g in obj["geometry"]:
            _check_solid(g["boundaries"][0], verts)
    if res.buildings:
        sc = trimesh.load(str(tmp_path / "b.obj"), force="scene", split_objects=True,
                          group_material=False, process=False)
        for m in sc.geometry.values():
            m.merge_vertices()
            assert m.is_watertight and m.volume > 0


def test_pier_over_water_is_not_a_building():
    """A 4 m × 30 m deck 3 m above a lake (class 9 around it on three sides, the shore at
    one end) is refused; the same deck over dry ground with walls is a building."""
    rng = np.random.default_rng(2)
    n = 60_000
    x, y = rng.uniform(0, 100, n), rng.uniform(0, 100, n)
    deck = (np.abs(x - 50) <= 2) & (y >= 40) & (y <= 70)
    lake = (y > 35) & ~deck
    z = np.where(deck, 3.0, 0.0) + rng.normal(0, 0.02, n)
    cls = np.where(deck, 1, np.where(lake, 9, 2))
    keep = ~lake | (rng.random(n) < 0.5)          # water returns only now and then
    res = core_b.extract_buildings(x[keep], y[keep], z[keep], cls[keep])
    assert not res.buildings and res.bridges.any()
    dry = np.where(lake, 2, cls)
    res = core_b.extract_buildings(x, y, z, dry)
    assert len(res.buildings) == 1 and res.buildings[0]["roof_type"] == "flat"


def test_l_shaped_flat_roof_gets_lod2(tmp_path):
    """An L-shaped flat-roofed block (not a rectangle, so not regularised): LOD2 is its
    outline lifted to the roof, closed and outward, volume ≈ area × height."""
    pytest.importorskip("jsonschema")
    if not SCHEMA.exists():
        pytest.skip(f"CityJSON schema absent: {SCHEMA}")
    from geomatics_toolbox.core.io.las import write_las
    from geomatics_toolbox.core.lidar.buildings_file import BuildingOutputs, buildings_file
    rng = np.random.default_rng(5)
    n = 40_000
    x, y = rng.uniform(0, 80, n), rng.uniform(0, 80, n)
    ell = ((x > 20) & (x < 60) & (y > 20) & (y < 32)) | ((x > 20) & (x < 32) & (y > 20)
                                                          & (y < 60))
    z = 100.0 + np.where(ell, 7.0, 0.0) + rng.normal(0, 0.02, n)
    cls = np.where(ell, 1, 2).astype(np.uint8)
    laz = tmp_path / "ell.laz"
    write_las(laz, x + 500_000, y + 4_000_000, z, dimensions={"classification": cls},
              crs="EPSG:32632")
    res, _ = buildings_file(str(laz), BuildingOutputs(str(tmp_path / "b.gpkg"),
                                                      cityjson=str(tmp_path / "b.json")))
    assert len(res.buildings) == 1
    b = res.buildings[0]
    assert b["roof_type"] == "flat" and not b["regularised"]
    assert b["area"] == pytest.approx(40 * 12 + 12 * 28, rel=0.06)
    doc = assert_valid_cityjson(tmp_path / "b.json")           # schema + cjval's checks
    t = doc["transform"]
    verts = np.asarray(doc["vertices"], float) * t["scale"] + t["translate"]
    geoms = {g["lod"]: g for g in doc["CityObjects"]["1"]["geometry"]}
    assert set(geoms) == {"1.2", "2.2"}
    vol = _check_solid(geoms["2.2"]["boundaries"][0], verts)
    assert vol == pytest.approx(b["area"] * 7.0, rel=0.08)
    assert len(geoms["2.2"]["boundaries"][0]) >= 8          # six walls or more

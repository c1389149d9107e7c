"""File runners of classify and buildings: the input is decoded once; refusals up front."""
from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest

from geomatics_toolbox.core.io import las as las_io
from geomatics_toolbox.synthetic.city import city_scene, write_scene

sys.path.insert(0, str(Path(__file__).resolve().parents[1]))
from cityjson_check import assert_valid_cityjson  # noqa: E402


@pytest.fixture(scope="module")
def scene_laz(tmp_path_factory):
    """The synthetic city at 3 pts/m², buildings and bridges left unclassified (1)."""
    scene = city_scene(density=3.0)
    cls = scene.classification.copy()
    cls[np.isin(cls, (5, 6, 17))] = 1
    scene.classification = cls
    return write_scene(scene, tmp_path_factory.mktemp("runners") / "city.laz")


@pytest.fixture
def decodes(monkeypatch):
    """Paths whose point records are decoded (every full read goes through _chunks)."""
    calls = []
    real = las_io._chunks

    def counting(reader, path, chunk_size):
        calls.append(str(path))
        return real(reader, path, chunk_size)

    monkeypatch.setattr(las_io, "_chunks", counting)
    yield calls
    monkeypatch.setattr(las_io, "_chunks", real)


def _same_points(a, b):
    import laspy
    pa, pb = laspy.read(a), laspy.read(b)
    assert len(pa.points) == len(pb.points) > 10_000
    assert list(pa.point_format.dimension_names) == list(pb.point_format.dimension_names)
    assert bytes(pa.points.array.tobytes()) == bytes(pb.points.array.tobytes())
    assert pa.header.parse_crs() == pb.header.parse_crs()
    assert [(v.user_id, v.record_id) for v in pa.header.vlrs] == \
        [(v.user_id, v.record_id) for v in pb.header.vlrs]


def test_classify_decodes_the_input_once(scene_laz, tmp_path, decodes):
    """classify_file_asprs (with the height-above-ground dimension) decodes the LAZ once;
    its cloud equals a copy written by decoding the input again."""
    from geomatics_toolbox.core.lidar.classify import HAG_DIMENSION, classify_file_asprs
    res = classify_file_asprs(scene_laz, cloud=str(tmp_path / "c.laz"), hag=True)
    assert decodes == [scene_laz]
    decodes.clear()
    las_io.write_las_like(scene_laz, tmp_path / "c2.laz",
                          dimensions={"classification": res.classes.astype(np.uint8)},
                          extra={HAG_DIMENSION: res.hag})
    assert decodes == [scene_laz]                 # the check copy did decode (test can fail)
    _same_points(tmp_path / "c.laz", tmp_path / "c2.laz")
    assert (res.classes == 6).sum() > 1000


def test_buildings_decodes_the_input_once(scene_laz, tmp_path, decodes):
    """buildings_file with the classified cloud, CityJSON and OBJ decodes the LAZ once;
    the cloud equals a copy written by decoding the input again."""
    import laspy

    from geomatics_toolbox.core.lidar.buildings_file import BuildingOutputs, buildings_file
    outs = BuildingOutputs(str(tmp_path / "b.gpkg"), cloud=str(tmp_path / "b.laz"),
                           cityjson=str(tmp_path / "b.json"), obj=str(tmp_path / "b.obj"))
    res, _units = buildings_file(scene_laz, outs)
    assert decodes == [scene_laz]
    assert len(res.buildings) == 5
    assert len(assert_valid_cityjson(tmp_path / "b.json")["CityObjects"]) == 5
    decodes.clear()
    classes = np.asarray(laspy.read(tmp_path / "b.laz").classification)
    las_io.write_las_like(scene_laz, tmp_path / "b2.laz",
                          dimensions={"classification": classes})
    assert decodes == [scene_laz]
    _same_points(tmp_path / "b.laz", tmp_path / "b2.laz")
    assert (classes == 6).sum() > 1000


@pytest.mark.parametrize("which", ["lowest", "median", "highest"])
def test_pick_per_cell_against_brute_force(which):
    """The one per-cell picker (PTD, DSM, buildings' DTM) = a loop over the cells, with
    ties in height broken by input order."""
    from geomatics_toolbox.core.terrain.grid import pick_per_cell
    rng = np.random.default_rng(7)
    key = rng.integers(-1, 40, 2000)
    z = rng.integers(0, 12, 2000).astype(float)          # many equal heights
    got = pick_per_cell(key, z, which)
    want = []
    for k in np.unique(key):
        idx = np.flatnonzero(key == k)
        idx = idx[np.argsort(z[idx], kind="stable")]
        want.append(idx[{"lowest": 0, "median": idx.size // 2, "highest": -1}[which]])
    assert np.array_equal(got, want)
    assert pick_per_cell(np.zeros(0, int), np.zeros(0), which).size == 0


def test_report_states_the_options_the_extraction_ran_with():
    """The buildings report's parameters come from the result (no restated defaults):
    defaults of extract_buildings, or the values it was called with."""
    from geomatics_toolbox.core.lidar import buildings as core_b
    from geomatics_toolbox.core.lidar.classify import ClassifyOptions
    from geomatics_toolbox.core.reporting import KeyValues
    assert core_b.DEFAULTS["min_height"] == 2.0 and core_b.DEFAULTS["storey_height"] == 3.0
    assert ClassifyOptions().min_height == core_b.DEFAULTS["min_height"]
    assert ClassifyOptions().dtm_cell == core_b.DEFAULTS["cell"]
    scene = city_scene(density=2.0)
    cls = scene.classification.copy()
    cls[np.isin(cls, (5, 6, 17))] = 1
    res = core_b.extract_buildings(scene.x, scene.y, scene.z, cls, min_height=2.5,
                                   storey_height=2.8)
    assert res.params == {**core_b.DEFAULTS, "min_height": 2.5, "storey_height": 2.8}
    rep = core_b.buildings_report(res, "city.laz")
    sec = next(s for s in rep.sections if s.heading == "Parameters")
    rows = {r[0]: r[1] for b in sec.blocks if isinstance(b, KeyValues) for r in b.rows}
    assert rows["Minimum height above ground (m)"] == 2.5
    assert rows["Storey height (m)"] == 2.8
    assert rows["Maximum angle between roof normals (°)"] == 20.0


@pytest.mark.parametrize("runner", ["buildings", "classify"])
def test_wrong_cloud_extension_refused_before_reading(scene_laz, tmp_path, monkeypatch,
                                                      decodes, runner):
    """OUTPUT_CLOUD=c.tif is refused up front: the cloud is never read (no header read for
    points, no decode, no computation) and nothing is written."""
    from geomatics_toolbox.core.errors import InputError
    from geomatics_toolbox.core.lidar import pipeline
    from geomatics_toolbox.core.lidar.buildings_file import BuildingOutputs, buildings_file
    from geomatics_toolbox.core.lidar.classify import classify_file_asprs
    reads = []
    monkeypatch.setattr(pipeline, "read_cloud", lambda *a, **k: reads.append(a) or 1 / 0)
    with pytest.raises(InputError, match=r"c\.tif.*\.las or \.laz") as exc:
        if runner == "buildings":
            buildings_file(scene_laz, BuildingOutputs(str(tmp_path / "b.gpkg"),
                                                      cloud=str(tmp_path / "c.tif")))
        else:
            classify_file_asprs(scene_laz, cloud=str(tmp_path / "c.tif"),
                                report=str(tmp_path / "r.html"))
    assert reads == [] and decodes == []
    name = "OUTPUT_CLOUD" if runner == "buildings" else "OUTPUT"
    assert f"output {name} is a point cloud" in exc.value.message("en")
    assert sorted(p.name for p in tmp_path.iterdir()) == []

"""File runners of classify and buildings: the input is decoded once; refusals up front."""
from __future__ import annotations

import numpy as np
import pytest

from geomatics_toolbox.core.io import las as las_io
from geomatics_toolbox.synthetic.city import city_scene, write_scene


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
    decodes.clear()
    classes = np.asarray(laspy.read(tmp_path / "b.laz").classification)
    las_io.write_las_like(scene_laz, tmp_path / "b2.laz",
                          dimensions={"classification": classes})
    assert decodes == [scene_laz]
    _same_points(tmp_path / "b.laz", tmp_path / "b2.laz")
    assert (classes == 6).sum() > 1000

"""Every LiDAR algorithm takes a COPC (``.copc.laz``) input (issue 19.6).

A COPC file is a LAZ 1.4 file stored node by node in an octree, described by ``copc``
records (an info VLR, a hierarchy EVLR) that laspy can read but not write. Each
algorithm runs through ``processing.run`` once on a COPC file written by copclib
(``synthetic/copc.py``, independent of the plugin's LAS code) and once on a plain LAZ
holding the same points in the same order (written by laspy alone): every output must
be the same — LAS outputs point for point (without the COPC records, every other VLR and
the CRS kept), rasters cell for cell, vector layers feature for feature, every number
returned.
"""
from __future__ import annotations

import math
import warnings
from pathlib import Path

import numpy as np
import pytest

from geomatics_toolbox.core.io.las import is_copc_record, las_info
from geomatics_toolbox.core.io.raster import read_raster
from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile

copc_writer = pytest.importorskip(
    "geomatics_toolbox.synthetic.copc", reason="copclib (requirements-dev.txt) writes "
    "the COPC test inputs; pip install copclib")
pytest.importorskip("copclib", reason="copclib (requirements-dev.txt) writes the COPC "
                    "test inputs; pip install copclib")

#: results that measure speed, not the data
_TIMING = {"POINTS_PER_SECOND"}


def _laspy():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        import laspy
    return laspy


@pytest.fixture(scope="module")
def clouds(tmp_path_factory):
    """The same labelled tile as COPC and as a plain LAZ in the COPC's point order."""
    laspy = _laspy()
    d = tmp_path_factory.mktemp("copc")
    tile = generate_tile(extent=(80.0, 80.0), density=2.0, seed=5, n_buildings=1,
                         n_halls=0)
    write_tile(tile, d / "source.laz", crs="EPSG:32632")
    n = copc_writer.write_copc(d / "source.laz", d / "tile.copc.laz")
    las = laspy.read(d / "source.laz")
    las.points = las.points[copc_writer.copc_point_order(las.x, las.y, las.z)]
    las.write(d / "tile.laz")
    # a second epoch for elevationchange: 0.5 m of fill on the western half
    las.z = las.z + np.where(las.x < las.x.min() + 40.0, 0.5, 0.0)
    las.write(d / "after.laz")
    copc_writer.write_copc(d / "after.laz", d / "after.copc.laz")
    cp = tile.checkpoints(n=10, min_spacing=3.0)
    return {"copc": d / "tile.copc.laz", "plain": d / "tile.laz", "n": n,
            "copc_after": d / "after.copc.laz", "plain_after": d / "after.laz",
            "csv": cp.to_csv(d / "cp.csv"), "dir": d}


def test_the_copc_input_is_a_real_copc_file(clouds):
    """laspy's COPC reader queries it; it holds the plain file's points, octree-ordered."""
    laspy = _laspy()
    with laspy.CopcReader.open(str(clouds["copc"])) as reader:
        assert len(reader.query()) == clouds["n"] > 5000
        assert len(reader.query(level=0)) < clouds["n"] / 10
    c, p = laspy.read(clouds["copc"]), laspy.read(clouds["plain"])
    assert [v.record_id for v in c.header.vlrs if is_copc_record(v)] == [1, 10000]
    assert [v.record_id for v in c.header.evlrs if is_copc_record(v)] == [1000]
    np.testing.assert_array_equal(c.points.array, p.points.array)
    assert las_info(clouds["copc"]).crs == las_info(clouds["plain"]).crs


def _check_las(copc_out: Path, plain_out: Path) -> None:
    laspy = _laspy()
    a, b = laspy.read(copc_out), laspy.read(plain_out)
    assert len(a.points) > 0
    np.testing.assert_array_equal(a.points.array, b.points.array)
    for records in (a.header.vlrs, a.header.evlrs or []):
        assert not [v for v in records if is_copc_record(v)], copc_out
    assert las_info(copc_out).crs and las_info(copc_out).crs == las_info(plain_out).crs


def _check_raster(copc_out: Path, plain_out: Path) -> None:
    a, b = read_raster(str(copc_out)), read_raster(str(plain_out))
    assert a.geotransform == b.geotransform and a.crs == b.crs
    assert np.isfinite(a.masked()).sum() > 0
    np.testing.assert_array_equal(a.masked(), b.masked())


def _check_vector(copc_out: Path, plain_out: Path) -> None:
    from osgeo import ogr

    def rows(path):
        ds = ogr.Open(str(path))
        layer = ds.GetLayer()
        out = sorted((f.GetGeometryRef().ExportToWkt() if f.GetGeometryRef() else "",
                      tuple(str(f.GetField(i)) for i in range(f.GetFieldCount())))
                     for f in layer)
        return out
    assert rows(copc_out) == rows(plain_out)


_CHECKS = {".laz": _check_las, ".las": _check_las, ".tif": _check_raster,
           ".gpkg": _check_vector}

#: algorithm -> (its settings, its cloud inputs, its file outputs)
CASES = {
    "groundfilter": ({}, ["INPUT"], {"OUTPUT": "c.laz", "GROUND_OUTPUT": "g.laz",
                                     "OUTPUT_HTML": "r.html"}),
    "lsqgroundfilter": ({"TILE_SIZE": 40.0}, ["INPUT"],
                        {"OUTPUT": "c.laz", "GROUND_OUTPUT": "g.laz"}),
    "slopegroundfilter": ({}, ["INPUT"], {"OUTPUT": "c.laz", "GROUND_OUTPUT": "g.laz"}),
    "ptdgroundfilter": ({}, ["INPUT"], {"OUTPUT": "c.laz"}),
    "slopethresholdsweep": ({"SLOPES": "40, 50", "RADII": "8"}, ["INPUT", "REFERENCE"],
                            {"OUTPUT": "best.laz", "OUTPUT_CSV": "sweep.csv"}),
    "groundfilteraccuracy": ({}, ["INPUT", "REFERENCE"],
                             {"ERROR_OUTPUT": "errors.laz", "OUTPUT_HTML": "r.html"}),
    "idwdtm": ({"CELL_SIZE": 2.0}, ["INPUT"], {"OUTPUT": "dtm.tif"}),
    "krigingdtm": ({"CELL_SIZE": 4.0}, ["INPUT"],
                   {"OUTPUT": "dtm.tif", "OUTPUT_VARIANCE": "var.tif"}),
    "tindtm": ({"CELL_SIZE": 2.0}, ["INPUT"], {"OUTPUT": "dtm.tif"}),
    "dsm": ({"CELL_SIZE": 2.0}, ["INPUT"], {"OUTPUT": "dsm.tif"}),
    "lidarqa": ({}, ["INPUT"], {"OUTPUT": "density.tif", "OUTPUT_HTML": "qa.html"}),
    "classify": ({}, ["INPUT"], {"OUTPUT": "c.laz", "OUTPUT_HTML": "r.html"}),
    "buildings": ({}, ["INPUT"], {"OUTPUT": "b.gpkg", "OUTPUT_CLOUD": "b.laz"}),
    "elevationchange": ({}, ["INPUT", "INPUT_AFTER:after"], {"OUTPUT": "change.tif"}),
    "lidartodtm": ({"CELL_SIZE": 2.0, "CHECKPOINTS_CSV": "csv"}, ["INPUT"],
                   {"OUTPUT": "c.laz", "OUTPUT_DTM": "dtm.tif",
                    "OUTPUT_RESIDUALS": "res.gpkg", "OUTPUT_HTML": "acc.html"}),
    "lidar_to_dtm": ({"CELL_SIZE": 2.0, "CHECKPOINTS_CSV": "csv"}, ["INPUT"],
                     {"publish:Classified point cloud": "c.laz", "publish:DTM": "dtm.tif",
                      "publish:Check-point residuals": "res.gpkg",
                      "publish:DTM accuracy report": "acc.html"}),
}


def test_every_cloud_algorithm_has_a_copc_case(qgis_app):
    """A LiDAR algorithm added later fails here until it gets a case above."""
    from qgis.core import QgsApplication
    provider = QgsApplication.processingRegistry().providerById("geomatics")
    takes_clouds = {a.name() for a in provider.algorithms()
                    if any(".copc.laz" in (p.help() or "") for p in a.parameterDefinitions())}
    assert takes_clouds and takes_clouds - {"catalog"} <= set(CASES), sorted(
        takes_clouds - set(CASES))


def _run(qgis_processing, alg, settings, inputs, outputs, kind, folder, clouds):
    folder.mkdir()
    params = {k: (str(clouds["csv"]) if v == "csv" else v) for k, v in settings.items()}
    for name in inputs:                       # "NAME" or "NAME:after" (second epoch)
        name, _, epoch = name.partition(":")
        params[name] = str(clouds[f"{kind}_{epoch}" if epoch else kind])
    params.update({name: str(folder / f) for name, f in outputs.items()})
    return qgis_processing.run(f"geomatics:{alg}", params)


@pytest.mark.parametrize("alg", sorted(CASES))
def test_copc_input_gives_the_plain_file_results(qgis_processing, clouds, tmp_path, alg):
    from qgis.core import QgsApplication
    if QgsApplication.processingRegistry().algorithmById(f"geomatics:{alg}") is None:
        pytest.fail(f"geomatics:{alg} is not registered")
    settings, inputs, outputs = CASES[alg]
    a = _run(qgis_processing, alg, settings, inputs, outputs, "copc", tmp_path / "copc",
             clouds)
    b = _run(qgis_processing, alg, settings, inputs, outputs, "plain", tmp_path / "plain",
             clouds)
    checked = 0
    for name, fname in outputs.items():
        fa, fb = tmp_path / "copc" / fname, tmp_path / "plain" / fname
        assert fa.exists() and fb.exists(), name
        check = _CHECKS.get(fa.suffix)
        if check is not None:
            check(fa, fb)
            checked += 1
    assert checked
    numbers = {k for k, v in b.items() if isinstance(v, (int, float)) and k not in _TIMING}
    for k in numbers:
        if isinstance(b[k], float) and math.isnan(b[k]):
            assert math.isnan(a[k]), k
        else:
            assert a[k] == b[k], (k, a[k], b[k])


def test_catalog_of_copc_tiles(qgis_processing, clouds, tmp_path):
    """A folder of COPC tiles: classified tiles and DTMs equal the plain tiles' ones."""
    laspy = _laspy()
    las = laspy.read(clouds["plain"])
    x0 = float(np.floor(las.x.min()))
    results = {}
    for kind in ("copc", "plain"):
        tiles, out = tmp_path / f"{kind}_tiles", tmp_path / f"{kind}_out"
        tiles.mkdir()
        for i, keep in enumerate((las.x < x0 + 40.0, las.x >= x0 + 40.0)):
            part = laspy.LasData(las.header)
            part.points = las.points[keep]
            part.points = part.points[copc_writer.copc_point_order(part.x, part.y, part.z)]
            part.write(tiles / f"t{i}.laz")
            if kind == "copc":
                copc_writer.write_copc(tiles / f"t{i}.laz", tiles / f"t{i}.copc.laz")
                (tiles / f"t{i}.laz").unlink()
        results[kind] = qgis_processing.run("geomatics:catalog", {
            "INPUT": str(tiles), "GROUND_FILTER": 0, "CELL_SIZE": 2.0, "BUFFER": 20.0,
            "WORKERS": 1, "OUTPUT_FOLDER": str(out)})
        assert results[kind]["N_TILES"] == 2 and results[kind]["N_FAILED"] == 0
    copc_out, plain_out = tmp_path / "copc_out", tmp_path / "plain_out"
    dtms = sorted(copc_out.glob("*_dtm.tif"))
    assert len(dtms) == 2
    for i in range(2):
        a = next(copc_out.glob(f"t{i}*_classified.laz"))
        b = next(plain_out.glob(f"t{i}*_classified.laz"))
        _check_las(a, b)
        _check_raster(next(copc_out.glob(f"t{i}*_dtm.tif")),
                      next(plain_out.glob(f"t{i}*_dtm.tif")))


def test_copc_input_through_qgis_process(qgis_process, clouds, tmp_path):
    """The command line too: the recommended ground filter on a .copc.laz."""
    laspy = _laspy()
    res = qgis_process.run("geomatics:groundfilter", INPUT=str(clouds["copc"]),
                           OUTPUT=str(tmp_path / "c.laz"))
    out = laspy.read(tmp_path / "c.laz")
    assert len(out.points) == clouds["n"] == res["results"]["N_POINTS"]
    assert res["results"]["N_GROUND"] == int(np.count_nonzero(out.classification == 2)) > 0
    assert not [v for v in out.header.vlrs if is_copc_record(v)]


def test_las_input_help_says_what_this_qgis_loads(qgis_app):
    """PDAL: any LAS/LAZ is a layer; no PDAL: COPC only from QGIS 3.26 (native provider)."""
    from qgis.core import Qgis, QgsApplication, QgsProviderRegistry

    from geomatics_toolbox.algorithms.base import (
        copc_layers_supported,
        point_cloud_layers_supported,
    )
    providers = QgsProviderRegistry.instance().providerList()
    assert copc_layers_supported() == ("copc" in providers)
    # QGIS 3.26 added the native COPC provider; Debian's 3.22 lacks it, its 3.40 has it
    assert copc_layers_supported() == (Qgis.QGIS_VERSION_INT >= 32600)
    alg = QgsApplication.processingRegistry().algorithmById("geomatics:groundfilter")
    text = alg.parameterDefinition("INPUT").help()
    assert ".copc.laz" in text
    if point_cloud_layers_supported():
        assert "Pick a loaded point-cloud layer" in text
    elif copc_layers_supported():
        assert "no PDAL point-cloud provider" in text and "COPC files (.copc.laz) can" in text
    else:
        assert "no PDAL point-cloud provider" in text and "COPC needs QGIS 3.26" in text


def test_a_copc_output_name_is_refused_before_anything_is_written(qgis_processing, clouds,
                                                                   tmp_path):
    """Outputs are plain LAZ: a .copc.laz name would be a LAZ QGIS cannot open as COPC."""
    from qgis.core import QgsProcessingException
    before = clouds["copc"].read_bytes()
    with pytest.raises(QgsProcessingException, match="named as a COPC file"):
        qgis_processing.run("geomatics:groundfilter", {
            "INPUT": str(clouds["copc"]), "OUTPUT": str(tmp_path / "out.copc.laz")})
    assert list(tmp_path.iterdir()) == []
    assert clouds["copc"].read_bytes() == before

"""Hostile input, round 3 (issue 22) through processing.run: every case asserts the
message, byte-identical inputs and nothing at any output path or temporary name."""
from __future__ import annotations

import hashlib
import re

import numpy as np
import pytest
from qgis.core import QgsProcessingException

from geomatics_toolbox.core.io import contract
from geomatics_toolbox.core.io.las import write_las
from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile


def _digest(path) -> str:
    return hashlib.sha256(open(path, "rb").read()).hexdigest()


def _leftovers(folder):
    return sorted(p.name for p in folder.iterdir() if contract.is_temp(p))


def refused(processing, alg, params, message, inputs, outputs):
    """Run expecting ``message``; inputs unchanged, no output nor temporary left."""
    before = {str(p): _digest(p) for p in inputs}
    with pytest.raises(QgsProcessingException, match=message) as info:
        processing.run(alg, params)
    text = str(info.value)
    assert "Traceback" not in text and "RuntimeError" not in text, text
    assert {str(p): _digest(p) for p in inputs} == before
    for out in outputs:
        assert not out.exists(), out
        assert not _leftovers(out.parent), _leftovers(out.parent)
    return text


@pytest.fixture(scope="module")
def data(tmp_path_factory):
    d = tmp_path_factory.mktemp("hostile")
    tile = generate_tile(extent=(60.0, 60.0), density=2.0, seed=4, n_buildings=1, n_halls=0)
    write_tile(tile, d / "tile.laz", crs="EPSG:32632")
    return {"dir": d, "tile": tile, "laz": d / "tile.laz"}


# ----------------------------------------------------------------- 5. TIN degenerate
@pytest.mark.parametrize("kind", ["ten", "collinear"])
def test_tindtm_without_a_valid_cell_refused(qgis_processing, tmp_path, kind):
    rng = np.random.default_rng(1)
    if kind == "ten":      # ten points in a 0.4 m patch: their hull holds no cell centre
        x = 500_000.05 + rng.uniform(0, 0.4, 10)
        y = 4_000_000.05 + rng.uniform(0, 0.4, 10)
    else:                  # 400 points along a line, 1 cm off it
        t = np.linspace(0, 400, 400)
        x = 500_000 + t
        y = 4_000_000 + 0.5 * t + rng.normal(0, 0.01, t.size)
    z = 100 + rng.normal(0, 0.1, x.size)
    src = tmp_path / "few.las"
    write_las(src, x, y, z, dimensions={"classification": np.full(x.size, 2, np.uint8)},
              crs="EPSG:32632")
    out = tmp_path / "tin.tif"
    refused(qgis_processing, "geomatics:tindtm", {
        "INPUT": str(src), "CELL_SIZE": 1.0, "OUTPUT": str(out),
        "OUTPUT_HTML": str(tmp_path / "tin.html")},
        r"has no cell with a value.*No output was written" if kind == "collinear" else
        r"CELL_SIZE 1 m is larger than the extent of the points.*single cell", [src],
        [out, tmp_path / "tin.html"])


# ----------------------------------------------------------------- dtmaccuracy lon/lat
def test_dtmaccuracy_lon_lat_check_points_clear_message(qgis_processing, data, tmp_path):
    dtm = qgis_processing.run("geomatics:idwdtm", {
        "INPUT": str(data["laz"]), "CELL_SIZE": 1.0, "FILL_GAPS": True,
        "OUTPUT": str(tmp_path / "dtm.tif")})["OUTPUT"]
    csv = tmp_path / "lonlat.csv"
    csv.write_text("id,x,y,z\n" + "".join(
        f"{i},{9.0 + 1e-6 * i:.7f},{48.0 + 1e-6 * i:.7f},{200 + i}\n" for i in range(8)),
        encoding="utf-8")
    out = tmp_path / "acc.html"
    text = refused(qgis_processing, "geomatics:dtmaccuracy", {
        "DTM": dtm, "CHECKPOINTS_CSV": str(csv), "OUTPUT_HTML": str(out)},
        r"look like longitude/latitude in degrees.*EPSG:32632", [dtm, csv], [out])
    assert "Duplicated" not in text


# ----------------------------------------------------------------- 4. headers that lie
@pytest.mark.parametrize("kind,message", [
    ("vlrs", r"claims 1,069,128,089 variable-length records \(VLRs\), which cannot fit"),
    ("las10", r"declares LAS version 1\.0, which this toolbox cannot read"),
])
def test_lying_headers_refused_by_groundfilter(qgis_processing, tmp_path, kind, message):
    from geomatics_toolbox.synthetic.hostile import huge_vlr_count, las10_copy
    rng = np.random.default_rng(2)
    ok = tmp_path / "ok.las"
    write_las(ok, 500_000 + rng.uniform(0, 30, 500), 4e6 + rng.uniform(0, 30, 500),
              100 + rng.uniform(0, 1, 500), crs="EPSG:32632", version="1.2", point_format=1)
    bad = tmp_path / "bad.las"
    (huge_vlr_count if kind == "vlrs" else las10_copy)(ok, bad)
    out = tmp_path / "out.laz"
    text = refused(qgis_processing, "geomatics:groundfilter", {
        "INPUT": str(bad), "OUTPUT": str(out), "OUTPUT_HTML": str(tmp_path / "r.html")},
        message, [bad], [out, tmp_path / "r.html"])
    assert "bad.las" in text and "FileVersionNotSupported" not in text


# ----------------------------------------------------------------- 2. CRSs by meaning
def _grid_dem(path, crs, z=100.0):
    from geomatics_toolbox.core.io.raster import write_geotiff
    write_geotiff(path, np.full((20, 20), z), geotransform=(500_000, 1, 0, 4_000_020, 0, -1),
                  crs=crs)
    return path


def test_elevationchange_rasters_on_same_numbers_other_crs_refused(qgis_processing, tmp_path):
    a = _grid_dem(tmp_path / "a.tif", "EPSG:32632")
    b = _grid_dem(tmp_path / "b.tif", "EPSG:31467", z=101.0)      # same grid numbers
    out = tmp_path / "d.tif"
    refused(qgis_processing, "geomatics:elevationchange", {
        "INPUT": str(a), "INPUT_AFTER": str(b), "OUTPUT": str(out)},
        r"different CRSs: a\.tif is in EPSG:32632.*b\.tif in EPSG:31467", [a, b], [out])


def test_elevationchange_clouds_other_crs_and_same_file_refused(qgis_processing, data,
                                                                tmp_path):
    t = data["tile"]
    g = t.classification == 2
    a, b = tmp_path / "a.las", tmp_path / "b.las"
    write_las(a, t.x[g], t.y[g], t.z[g], dimensions={"classification": t.classification[g]},
              crs="EPSG:32632")
    write_las(b, t.x[g], t.y[g], t.z[g] + 1, dimensions={"classification": t.classification[g]},
              crs="EPSG:32633")
    out = tmp_path / "d.tif"
    refused(qgis_processing, "geomatics:elevationchange", {
        "INPUT": str(a), "INPUT_AFTER": str(b), "OUTPUT": str(out)},
        r"a\.las is in EPSG:32632.*b\.las in EPSG:32633", [a, b], [out])
    refused(qgis_processing, "geomatics:elevationchange", {
        "INPUT": str(a), "INPUT_AFTER": str(a), "OUTPUT": str(out)},
        r"Both epochs are the same data", [a], [out])
    copy = tmp_path / "copy.las"
    copy.write_bytes(a.read_bytes())
    refused(qgis_processing, "geomatics:elevationchange", {
        "INPUT": str(a), "INPUT_AFTER": str(copy), "OUTPUT": str(out)},
        r"Both epochs are the same data", [a, copy], [out])


# ----------------------------------------------------------------- 5. numbers that lie
@pytest.mark.parametrize("params,message", [
    ({"MAX_WINDOW": 0}, r"MAX_WINDOW must be a number > 0, got 0"),
    ({"THRESHOLD": float("nan")}, r"THRESHOLD must be a finite number, got nan"),
    ({"CELL": float("nan")}, r"CELL must be a finite number, got nan"),
    # grew past the machine's memory (np.arange of 2e9 radii) instead of a message
    ({"MAX_WINDOW": 1e9}, r"The largest window \(MAX_WINDOW, 1e\+09 m\) must be at most "
                          r"2000 m"),
])
def test_groundfilter_nonsense_numbers_refused(qgis_processing, data, tmp_path, params,
                                               message):
    out = tmp_path / "c.laz"
    refused(qgis_processing, "geomatics:groundfilter", {
        "INPUT": str(data["laz"]), "OUTPUT": str(out), **params}, message, [data["laz"]],
        [out])


# ----------------------------------------------------------------- 4. sparse over a huge box
def test_sparse_cloud_over_a_huge_extent_refused(qgis_processing, tmp_path):
    rng = np.random.default_rng(0)
    n = 1065                                       # over 15.6 km², as the probe's file
    src = tmp_path / "sparse.las"
    write_las(src, 500_000 + rng.uniform(0, 3950, n), 4e6 + rng.uniform(0, 3950, n),
              100 + rng.normal(0, 1, n), crs="EPSG:32632")
    out = tmp_path / "c.laz"
    refused(qgis_processing, "geomatics:groundfilter", {"INPUT": str(src), "OUTPUT": str(out)},
            r"1,065 points over 15\.\d\d km² of bounding box: a mean spacing of 121 m", [src],
            [out])


def test_lidartodtm_lon_lat_check_points_clear_message(qgis_processing, data, tmp_path):
    csv = tmp_path / "lonlat.csv"
    csv.write_text("id,x,y,z\n" + "".join(
        f"{i},{9.0 + 1e-6 * i:.7f},{48.0 + 1e-6 * i:.7f},{200 + i}\n" for i in range(8)),
        encoding="utf-8")
    outs = [tmp_path / "c.laz", tmp_path / "d.tif"]
    text = refused(qgis_processing, "geomatics:lidartodtm", {
        "INPUT": str(data["laz"]), "CHECKPOINTS_CSV": str(csv), "OUTPUT": str(outs[0]),
        "OUTPUT_DTM": str(outs[1])},
        r"look like longitude/latitude in degrees.*EPSG:32632", [data["laz"], csv], outs)
    assert "Duplicated" not in text


# ----------------------------------------------------------------- 5. a cloud as c.tif
@pytest.mark.parametrize("alg,cloud,extra", [
    ("geomatics:buildings", "OUTPUT_CLOUD", {"OUTPUT": "b.gpkg"}),
    ("geomatics:classify", "OUTPUT", {}),
    ("geomatics:groundfilter", "GROUND_OUTPUT", {"OUTPUT": "g.laz"}),
    ("geomatics:groundfilteraccuracy", "ERROR_OUTPUT", {}),
])
@pytest.mark.parametrize("name", ["c.tif", "c.txt"])
def test_cloud_output_with_a_wrong_extension_refused_before_any_work(
        qgis_processing, data, tmp_path, monkeypatch, name, alg, cloud, extra):
    """Review H7: refused up front (the algorithms' one output check), not by the writer
    after the computation: the reader is never reached."""
    from qgis.core import QgsApplication

    def never(*a, **k):
        raise AssertionError("process() ran before the output name was checked")
    cls = type(QgsApplication.processingRegistry().algorithmById(alg))
    monkeypatch.setattr(cls, "process", never)
    outs = [tmp_path / v for v in extra.values()] + [tmp_path / name]
    refused(qgis_processing, alg, {
        "INPUT": str(data["laz"]), cloud: str(outs[-1]),
        **{k: str(tmp_path / v) for k, v in extra.items()}},
        rf"The output {cloud} is a point cloud and cannot be written as .*"
        + name.replace(".", r"\.") + r".*\.las or \.laz", [data["laz"]], outs)


@pytest.mark.parametrize("alg,param", [
    ("geomatics:idwdtm", "POWER"), ("geomatics:idwdtm", "CELL_SIZE"),
    ("geomatics:lsqgroundfilter", "THRESHOLD"), ("geomatics:slopegroundfilter", "RADIUS"),
    ("geomatics:tindtm", "MAX_EDGE"),
])
def test_not_a_number_refused_everywhere(qgis_processing, data, tmp_path, alg, param):
    out = tmp_path / ("o.tif" if "dtm" in alg else "o.laz")
    refused(qgis_processing, alg, {"INPUT": str(data["laz"]), param: float("nan"),
                                   "OUTPUT": str(out)},
            param + r" must be a finite number, got nan", [data["laz"]], [out])


@pytest.mark.parametrize("param,source,dest,message", [
    ("DTM", "dtm", "out.txt", r"raster output cannot be written as .*out\.txt.*\.tif"),
    ("CLOUD", "cloud", "c.tif",
     r"The output OUTPUT is a point cloud and cannot be written as .*c\.tif.*\.las or \.laz"),
])
def test_publishoutputs_wrong_format_refused(qgis_processing, data, tmp_path, param, source,
                                             dest, message):
    from geomatics_toolbox.core.io.raster import write_geotiff
    dtm = write_geotiff(tmp_path / "src.tif", np.zeros((4, 4)),
                        geotransform=(500_000, 1, 0, 4e6, 0, -1), crs="EPSG:32632")
    src = {"dtm": dtm, "cloud": str(data["laz"])}[source]
    out_param = {"DTM": "OUTPUT_DTM", "CLOUD": "OUTPUT"}[param]
    out = tmp_path / dest
    text = refused(qgis_processing, "geomatics:publishoutputs", {
        param: src, out_param: str(out)}, message, [src], [out])
    assert "Cannot guess driver" not in text and ".part-" not in text


def test_ptd_on_a_profile_refused_with_a_message(qgis_processing, tmp_path):
    """500 points on one straight line (a profile): Qhull's 'initial simplex is flat'
    came out raw ('QhullError: QH6154 ...'); now a translated refusal naming the fix."""
    t = np.linspace(0, 100, 500)
    src = tmp_path / "profile.las"
    write_las(src, 500_000 + t, np.full(t.size, 4e6), 100 + 0.01 * t,
              dimensions={"classification": np.full(t.size, 2, np.uint8)}, crs="EPSG:32632")
    out = tmp_path / "c.laz"
    text = refused(qgis_processing, "geomatics:ptdgroundfilter", {
        "INPUT": str(src), "OUTPUT": str(out), "OUTPUT_HTML": str(tmp_path / "r.html")},
        r"The 500 points lie on one line: progressive TIN densification needs points spread "
        r"over an area\. Use the recommended ground filter", [src], [out, tmp_path / "r.html"])
    assert "Qhull" not in text and "QH6154" not in text


@pytest.mark.parametrize("param,dest,content,message", [
    ("DTM", "out.tif", b"", r"zero\.tif is not a raster GDAL can read"),
    ("DTM", "out.tif", b"II*\x00junk" * 50, r"zero\.tif is not a raster GDAL can read"),
    ("CLOUD", "out.laz", b"x,y,z\n1,2,3\n", r"zero\.tif is not a LAS/LAZ file"),
    ("RESIDUALS", "out.gpkg", b"SQLite format 3\x00" + b"\x00" * 100,
     r"zero\.tif is not a vector file GDAL/OGR can read \(empty, damaged"),
])
def test_publishoutputs_refuses_a_file_that_is_not_its_kind(qgis_processing, tmp_path, param,
                                                            dest, content, message):
    """A zero-byte or garbled temporary (a step killed half-way, a wrong file wired into
    the model) was copied to the destination and reported as published."""
    src = tmp_path / "zero.tif"
    src.write_bytes(content)
    out = tmp_path / dest
    out_param = {"DTM": "OUTPUT_DTM", "CLOUD": "OUTPUT", "RESIDUALS": "OUTPUT_RESIDUALS"}
    refused(qgis_processing, "geomatics:publishoutputs", {
        param: str(src), out_param[param]: str(out)}, message, [src], [out])


@pytest.mark.parametrize("page,names", [
    ("cp1252", ["Château-1", "Müller-Süd 2"]),       # Western Windows, Excel "CSV"
    ("cp1256", ["نقطة تحقق 1", "جسر الملك فهد"]),    # Arabic Windows, Excel "CSV"
    ("cp1256", ["ايستگاه يک", "پل کرج"]),            # Persian Windows (cp1256: ي for ی)
    ("utf-8-sig", ["نقطة تحقق 1", "ایستگاه یک"]),    # Excel "CSV UTF-8"
    ("utf-16", ["نقطه\u200cی چک", "Château-1"]),     # Excel "Unicode Text"
])
def test_dtmaccuracy_check_point_names_survive_in_any_encoding(qgis_processing, data,
                                                              tmp_path, page, names):
    """An Excel 'CSV' in the Windows code page of an Arabic or Persian machine, read here
    (a UTF-8 Linux machine): the names were garbled ('äÞØÉ ÊÍÞÞ 1', read as cp1252) or
    the file refused (گ is 0x90, undefined in cp1252); now the code page is judged from
    the names (core.io.text) and they reach the residual layer and the report as written."""
    from osgeo import ogr
    dtm = qgis_processing.run("geomatics:idwdtm", {
        "INPUT": str(data["laz"]), "CELL_SIZE": 1.0, "FILL_GAPS": True,
        "OUTPUT": str(tmp_path / "dtm.tif")})["OUTPUT"]
    csv = tmp_path / "cp.csv"
    sep = "\t" if page == "utf-16" else ","
    csv.write_bytes((sep.join(("id", "x", "y", "z")) + "\n" + "".join(
        sep.join(map(str, (n, 500010 + 9 * k, 4000010 + 7 * k, 100))) + "\n"
        for k, n in enumerate(names))).encode(page))
    res = qgis_processing.run("geomatics:dtmaccuracy", {
        "DTM": dtm, "CHECKPOINTS_CSV": str(csv), "OUTPUT": str(tmp_path / "res.gpkg"),
        "OUTPUT_HTML": str(tmp_path / "acc.html")})
    ds = ogr.Open(str(res["OUTPUT"]).split("|")[0])
    assert [f.GetField("id") for f in ds.GetLayer(0)] == names
    ds = None
    html = (tmp_path / "acc.html").read_text(encoding="utf-8")
    assert all(n in html for n in names)


def test_dtmaccuracy_binary_check_point_file_refused_with_the_fix(qgis_processing, data,
                                                                  tmp_path):
    """Was "'utf-8' codec can't decode byte …" (Python's words, no file, no fix)."""
    dtm = qgis_processing.run("geomatics:idwdtm", {
        "INPUT": str(data["laz"]), "CELL_SIZE": 1.0, "FILL_GAPS": True,
        "OUTPUT": str(tmp_path / "dtm.tif")})["OUTPUT"]
    csv = tmp_path / "cp.csv"
    csv.write_bytes(b"id,x,y,z\nA,500010,4000010,100\n\x00\x00PK\x03\x04")
    out = tmp_path / "acc.html"
    text = refused(qgis_processing, "geomatics:dtmaccuracy", {
        "DTM": dtm, "CHECKPOINTS_CSV": str(csv), "OUTPUT_HTML": str(out)},
        r"cp\.csv is not a text file in UTF-8 or cp1256/cp1252 \(byte 30 cannot be read\): "
        r"save "
        r"it as text in UTF-8 \(in Excel: Save As, CSV UTF-8\)", [dtm, csv], [out])
    assert "codec" not in text


@pytest.mark.parametrize("kind", ["nodata", "nan"])
def test_elevationchange_with_an_empty_epoch_refused(qgis_processing, tmp_path, kind):
    """An all-nodata (or all-NaN) after-epoch gave 'FILL 0, CUT 0, 0 regions' and an
    all-nodata difference raster without a word."""
    from geomatics_toolbox.core.io.raster import write_geotiff
    a = _grid_dem(tmp_path / "a.tif", "EPSG:32632")
    b = write_geotiff(tmp_path / "b.tif",
                      np.full((20, 20), -9999.0 if kind == "nodata" else np.nan),
                      geotransform=(500_000, 1, 0, 4_000_020, 0, -1), crs="EPSG:32632",
                      nodata=-9999.0)
    outs = [tmp_path / "d.tif", tmp_path / "p.gpkg", tmp_path / "r.html"]
    refused(qgis_processing, "geomatics:elevationchange", {
        "INPUT": str(a), "INPUT_AFTER": str(b), "OUTPUT": str(outs[0]),
        "OUTPUT_POLYGONS": str(outs[1]), "OUTPUT_HTML": str(outs[2])},
        r"The two epochs share no cell with a height in both \(400 cells with a height "
        r"before, 0 after, on a common grid of 400 cells\)", [a, b], outs)


def test_elevationchange_raster_without_crs_is_named_in_a_warning(qgis_processing,
                                                                  warning_feedback,
                                                                  tmp_path):
    from geomatics_toolbox.core.io.raster import write_geotiff

    a = _grid_dem(tmp_path / "a.tif", "EPSG:32632")
    b = write_geotiff(tmp_path / "b.tif", np.full((20, 20), 101.0),
                      geotransform=(500_000, 1, 0, 4_000_020, 0, -1), crs=None)
    fb = warning_feedback
    res = qgis_processing.run("geomatics:elevationchange", {
        "INPUT": str(a), "INPUT_AFTER": str(b), "OUTPUT": str(tmp_path / "d.tif")},
        feedback=fb)
    assert res["FILL_VOLUME"] == pytest.approx(400.0, rel=1e-6)
    assert any("b.tif has no CRS: it is taken to be in the CRS of a.tif (EPSG:32632" in w
               for w in fb.warnings), fb.warnings


@pytest.mark.parametrize("alg,param,name,content,message", [
    ("geomatics:dtmaccuracy", "DTM", "dtm.tif", b"",
     r"DTM: .*dtm\.tif is not a raster GDAL can read"),
    ("geomatics:dtmaccuracy", "DTM", "dtm.tif", b"II*\x00" + b"junk" * 64,
     r"dtm\.tif is not a raster GDAL can read"),
    ("geomatics:gsdbatch", "INPUT", "cameras.csv", b"",
     r"cameras\.csv is not a vector file GDAL/OGR can read \(empty, damaged or of another "
     r"format\); choose a valid file"),
    ("geomatics:rectifygcp", "INPUT", "image.tif", b"\x89PNG garbage",
     r"image\.tif is not a raster GDAL can read"),
])
def test_layer_file_that_cannot_be_opened_named_before_the_run(qgis_processing, tmp_path, alg,
                                                               param, name, content, message):
    """QGIS said "Could not load source layer for DTM: …/dtm.tif not found" of a file that
    exists but is empty or damaged."""
    src = tmp_path / name
    src.write_bytes(content)
    before = sorted(p.name for p in tmp_path.iterdir())
    with pytest.raises(QgsProcessingException, match=message) as info:
        qgis_processing.run(alg, {param: str(src), "CHECKPOINTS_CSV": str(tmp_path / "x.csv"),
                                  "GCP_FILE": str(tmp_path / "x.points")}
                            if alg != "geomatics:gsdbatch" else {param: str(src)})
    assert "not found" not in str(info.value)
    assert sorted(p.name for p in tmp_path.iterdir()) == before
    assert src.read_bytes() == content


@pytest.mark.parametrize("params,message", [
    ({"MAX_BUILDING": 0}, r"MAX_BUILDING must be > 0, got 0\.0; give a positive value or leave "
                          r"the default \(60"),
    ({"FINAL_DISTANCE": 3.0, "MAX_DISTANCE": 1.0},
     r"FINAL_DISTANCE \(3\.0 m\) must not exceed MAX_DISTANCE \(1\.0 m\)"),
])
def test_ptd_bad_numbers_name_the_parameter(qgis_processing, data, tmp_path, params, message):
    """Were 'PtdOptions.max_building must be positive' (the core's field, no fix)."""
    out = tmp_path / "c.laz"
    refused(qgis_processing, "geomatics:ptdgroundfilter", {
        "INPUT": str(data["laz"]), "OUTPUT": str(out), **params}, message, [data["laz"]], [out])


def test_groundfilter_keeps_extra_bytes_descriptors_byte_for_byte(qgis_processing, tmp_path):
    """Issue 22 item 6 through processing.run: the declared min/max/no-data/scale/offset
    and option bits of each ExtraBytes descriptor (laspy rewrites them as ±DBL_MAX on a
    plain round trip) come out of the ground filter exactly as read."""
    from geomatics_toolbox.synthetic.hostile import (
        extra_bytes_descriptors,
        write_extra_bytes_las,
    )
    src = tmp_path / "eb.las"
    declared = write_extra_bytes_las(src, n=400)
    out = qgis_processing.run("geomatics:groundfilter", {
        "INPUT": str(src), "OUTPUT": str(tmp_path / "c.las")})["OUTPUT"]
    got, _ = extra_bytes_descriptors(out)
    assert set(declared) == {"hag", "amp"} and set(declared) <= set(got)
    for name, raw in declared.items():
        assert got[name] == raw, name      # options, min/max, no-data, scale, offset


# ----------------------------------------------------------------- dtmaccuracy, few points
@pytest.mark.parametrize("n", [1, 2, 25])
def test_dtmaccuracy_few_check_points_warned_asprs(qgis_processing, warning_feedback,
                                                   tmp_path, n):
    dtm = _grid_dem(tmp_path / "dtm.tif", "EPSG:32632")
    csv = tmp_path / "cp.csv"
    csv.write_text("id,x,y,z\n" + "".join(
        f"{i},{500_002.5 + (i % 5) * 3},{4_000_002.5 + (i // 5) * 3},100.1\n"
        for i in range(n)), encoding="utf-8")
    fb = warning_feedback
    res = qgis_processing.run("geomatics:dtmaccuracy", {
        "DTM": str(dtm), "CHECKPOINTS_CSV": str(csv),
        "OUTPUT_HTML": str(tmp_path / "acc.html")}, feedback=fb)
    assert res["N"] == n
    html = re.sub(r"</?bdi[^>]*>", "", (tmp_path / "acc.html").read_text(encoding="utf-8"))
    warned = [w for w in fb.warnings if "ASPRS (2014) asks for at least 20 check points" in w]
    if n < 20:
        assert warned and warned[0].startswith(f"Only {n} check points"), fb.warnings
        assert "at least 20 check points before a vertical accuracy" in html
    else:
        assert not warned and "at least 20 check points" not in html


def test_dtmaccuracy_few_check_points_warning_in_arabic_report(tmp_path):
    from geomatics_toolbox.core.reporting.render import render_html
    from geomatics_toolbox.core.terrain import accuracy as acc
    from geomatics_toolbox.core.terrain import report as tr_report
    dtm = np.full((10, 10), 100.0)
    gt = (0.0, 1.0, 0.0, 10.0, 0.0, -1.0)
    res = acc.dtm_accuracy(dtm, gt, [2.5, 5.5], [2.5, 5.5], [100.1, 99.9])
    html = render_html(tr_report.accuracy_report(res, ["a", "b"], dtm, gt, dtm_name="d.tif",
                                                 crs_label="EPSG:32632"), lang="ar")
    html = re.sub(r"</?bdi[^>]*>", "", html)
    assert "تشترط ASPRS (2014) ما لا يقل عن 20 نقطة تحقق" in html


# ----------------------------------------------------------------- DTM: 1e9 m cells, 1 point
@pytest.mark.parametrize("alg", ["idwdtm", "krigingdtm", "tindtm"])
def test_dtm_cell_size_larger_than_the_cloud_refused(qgis_processing, data, tmp_path, alg):
    out = tmp_path / "dtm.tif"
    text = refused(qgis_processing, f"geomatics:{alg}", {
        "INPUT": str(data["laz"]), "CELL_SIZE": 1e9, "OUTPUT": str(out),
        "OUTPUT_HTML": str(tmp_path / "dtm.html")},
        r"CELL_SIZE 1e\+09 m is larger than the extent of the points of .*tile\.laz "
        r"\(\d+\.\d{3} m x \d+\.\d{3} m\): the DTM would be a single cell\. Give a cell "
        r"size smaller than the extent", [data["laz"]], [out, tmp_path / "dtm.html"])
    assert "59." in text                  # the 60 m tile's extent


@pytest.mark.parametrize("alg", ["idwdtm", "krigingdtm", "tindtm"])
@pytest.mark.parametrize("n", [1, 500])
def test_dtm_of_points_at_one_position_refused(qgis_processing, tmp_path, alg, n):
    src = tmp_path / "one.las"
    write_las(src, np.full(n, 500_000.0), np.full(n, 4_000_000.0), np.full(n, 100.0),
              dimensions={"classification": np.full(n, 2, np.uint8)}, crs="EPSG:32632")
    out = tmp_path / "dtm.tif"
    refused(qgis_processing, f"geomatics:{alg}", {
        "INPUT": str(src), "CELL_SIZE": 1.0, "OUTPUT": str(out)},
        rf"The {n} point\(s\) of .*one\.las lie at only 1 distinct position\(s\): a DTM "
        r"needs at least 3 points at different positions", [src], [out])


def test_dtm_refusals_in_arabic():
    from geomatics_toolbox.core.errors import InputError
    from geomatics_toolbox.core.terrain import dtm as core_dtm
    pts = core_dtm.ClassPoints(np.array([0.0, 10.0, 0.0]), np.array([0.0, 0.0, 5.0]),
                               np.zeros(3), None, (2,), 3, {})
    with pytest.raises(InputError) as info:
        core_dtm.check_dtm_input(pts, 50.0, "c.laz")
    assert "CELL_SIZE 50 m" in str(info.value)
    assert "أكبر من امتداد نقاط \u2068c.laz\u2069 (" in info.value.message("ar")
    core_dtm.check_dtm_input(pts, 5.0, "c.laz")         # 5 m < the 10 m extent: accepted


# ----------------------------------------------------------------- slope filter, one position
#: A cloud of n points at one x/y position and the slope filter's refusal (the sweep's too).
ONE_POSITION = [
    (1, r"A ground filter needs at least 2 points, got 1: give a cloud that covers the "
        r"ground area"),
    (500, r"All 500 points share one x/y position, so there is no terrain to compare them "
          r"with: give a cloud whose points cover the ground area"),
]


def _one_position_las(path, n, **dims):
    rng = np.random.default_rng(3)
    write_las(path, np.full(n, 500_000.0), np.full(n, 4_000_000.0),
              100 + rng.uniform(0, 20, n), crs="EPSG:32632", **dims)
    return path


@pytest.mark.parametrize("n,message", ONE_POSITION)
def test_slopegroundfilter_one_position_refused(qgis_processing, tmp_path, n, message):
    src = _one_position_las(tmp_path / "one.las", n)
    out, ground = tmp_path / "c.laz", tmp_path / "g.laz"
    refused(qgis_processing, "geomatics:slopegroundfilter", {
        "INPUT": str(src), "OUTPUT": str(out), "GROUND_OUTPUT": str(ground),
        "OUTPUT_HTML": str(tmp_path / "r.html")}, message, [src],
        [out, ground, tmp_path / "r.html"])


def test_slope_filter_refusal_in_persian_and_two_points_still_classified():
    from geomatics_toolbox.core.errors import InputError
    from geomatics_toolbox.core.lidar.slope import slope_filter
    with pytest.raises(InputError) as info:
        slope_filter(np.zeros(3), np.zeros(3), np.arange(3.0))
    assert "یک موقعیت x/y دارند، پس زمینی برای مقایسه" in info.value.message("fa")
    x = np.array([0.0, 3.0])
    assert slope_filter(x, np.zeros(2), np.array([0.0, 2.0]), radius=3.0, slope=30.0,
                        height_tolerance=0).ground.tolist() == [True, False]


# ----------------------------------------------------------------- kriging: NEIGHBOURS named
def _ten_ground_points(path):
    """12 ground points at 10 distinct positions (two repeated), heights 0–2 m."""
    rng = np.random.default_rng(5)
    x = 500_000.0 + rng.uniform(0, 20, 10)
    y = 4_000_000.0 + rng.uniform(0, 20, 10)
    x, y = np.r_[x, x[:2]], np.r_[y, y[:2]]
    z = 100.0 + rng.uniform(0, 2, 12)
    write_las(path, x, y, z, dimensions={"classification": np.full(12, 2, np.uint8)},
              crs="EPSG:32632")


@pytest.mark.parametrize("params,message", [
    ({}, r"Only 10 distinct point positions to krige from, but Neighbours per cell "
         r"\(NEIGHBOURS\) is 16: set NEIGHBOURS to 10 or fewer, or use a cloud with more "
         r"ground points\."),
    ({"KRIGING_TYPE": 1, "NEIGHBOURS": 3},
     r"Universal kriging \(KRIGING_TYPE 1\) needs at least 4 Neighbours per cell "
     r"\(NEIGHBOURS\), got 3: set NEIGHBOURS to 4 or more, or choose ordinary kriging "
     r"\(KRIGING_TYPE 0\)\."),
    ({"NEIGHBOURS": 10, "CV_POINTS": 5},
     r"Cross-validation \(CV_POINTS\) leaves each point out, so Neighbours per cell "
     r"\(NEIGHBOURS = 10\) must be fewer than the 10 distinct point positions: set "
     r"NEIGHBOURS to 9 or fewer, or CV_POINTS to 0\."),
], ids=["neighbours>points", "universal<4", "cv-global"])
def test_krigingdtm_too_few_points_names_neighbours(qgis_processing, tmp_path, params,
                                                    message):
    src = tmp_path / "ten.las"
    _ten_ground_points(src)
    out, var = tmp_path / "dtm.tif", tmp_path / "var.tif"
    text = refused(qgis_processing, "geomatics:krigingdtm", {
        "INPUT": str(src), "CELL_SIZE": 1.0, "OUTPUT": str(out), "OUTPUT_VARIANCE": str(var),
        **params}, message, [src], [out, var])
    assert "n_closest" not in text


def test_krigingdtm_the_named_fix_works(qgis_processing, tmp_path):
    """What the refusals say to do runs: NEIGHBOURS 10 (global), 9 with CV_POINTS."""
    src = tmp_path / "ten.las"
    _ten_ground_points(src)
    for k, cv in ((10, 0), (9, 5), (4, 0)):
        res = qgis_processing.run("geomatics:krigingdtm", {
            "INPUT": str(src), "CELL_SIZE": 1.0, "NEIGHBOURS": k, "CV_POINTS": cv,
            "KRIGING_TYPE": int(k == 4), "OUTPUT": str(tmp_path / f"d{k}.tif")})
        assert res["N_POINTS"] == 10 and res["VALID_CELLS"] > 100, (k, res)
        assert np.isfinite(res["CV_RMSE"]) == (cv > 0)


# ----------------------------------------------------------------- sweep, one position
@pytest.mark.parametrize("n,message", ONE_POSITION)
def test_slopethresholdsweep_one_position_refused(qgis_processing, tmp_path, n, message):
    src = _one_position_las(tmp_path / "one.las", n, dimensions={
        "classification": np.where(np.arange(n) % 2, 6, 2).astype("u1")})
    csv, html, out = tmp_path / "sweep.csv", tmp_path / "sweep.html", tmp_path / "c.laz"
    refused(qgis_processing, "geomatics:slopethresholdsweep", {
        "INPUT": str(src), "SLOPES": "40, 50", "RADII": "3", "OUTPUT_CSV": str(csv),
        "OUTPUT_HTML": str(html), "OUTPUT": str(out)}, message, [src], [csv, html, out])


# ----------------------------------------------------------------- DTM options named as shown
@pytest.mark.parametrize("alg,params,message", [
    ("idwdtm", {"NEIGHBOURS": 0, "RADIUS": 0.0},
     r"Neighbours \(NEIGHBOURS\) 0 means every point within the search radius, but no Search "
     r"radius \(RADIUS\) was given: give RADIUS in metres, or NEIGHBOURS such as 12\."),
    ("idwdtm", {"NEIGHBOURS": 12, "MIN_POINTS": 20},
     r"Minimum points \(MIN_POINTS = 20\) cannot exceed Neighbours \(NEIGHBOURS = 12\): every "
     r"cell would be nodata\. Lower MIN_POINTS or raise NEIGHBOURS\."),
    ("idwdtm", {"NEIGHBOURS": 10 ** 7},
     r"Only \d+ points to interpolate from, but Neighbours \(NEIGHBOURS\) is 10000000: set "
     r"NEIGHBOURS to \d+ or fewer"),
    ("lidartodtm", {"NEIGHBOURS": 10 ** 7},
     r"Only \d+ points to interpolate from, but Neighbours \(NEIGHBOURS\) is 10000000"),
    ("krigingdtm", {"MAX_LAG": 0.001},
     r"Only 0 point pairs are closer than the maximum lag \(0\.001 m\), fewer than the 12 lag "
     r"classes: give a larger Maximum lag \(MAX_LAG\) or more Points for the variogram fit "
     r"\(FIT_POINTS\)"),
    ("idwdtm", {"POWER": 0.0},
     r"The IDW power \(POWER\) must be > 0, got 0\.0: give 2 \(GDAL's default\) or 3\."),
    ("krigingdtm", {"VARIOGRAM_SILL": 1.0},
     r"This variogram model needs both the sill \(VARIOGRAM_SILL\) and the range "
     r"\(VARIOGRAM_RANGE\), the nugget \(VARIOGRAM_NUGGET\) being optional"),
    ("krigingdtm", {"VARIOGRAM_SILL": 1.0, "VARIOGRAM_NUGGET": 2.0, "VARIOGRAM_RANGE": 30.0},
     r"The sill \(VARIOGRAM_SILL = 1\.0\) must be larger than the nugget "
     r"\(VARIOGRAM_NUGGET = 2\.0\): the sill includes the nugget\."),
    ("krigingdtm", {"VARIOGRAM": 1, "VARIOGRAM_SCALE": 0.5},
     r"The power variogram needs a scale \(VARIOGRAM_SCALE\) above 0 and an exponent "
     r"\(VARIOGRAM_EXPONENT\) between 0 and 2"),
], ids=["idw-no-radius", "idw-min>neighbours", "idw-neighbours>points",
        "lidartodtm-neighbours>points", "kriging-max-lag", "idw-power", "kriging-no-range",
        "kriging-sill<nugget", "kriging-power-no-exponent"])
def test_dtm_option_refusals_name_the_parameters(qgis_processing, data, tmp_path, alg, params,
                                                 message):
    """Were 'max_points = 0 …', 'min_points (20) cannot exceed max_points (12)', 'max_lag =
    0.001; increase max_lag or fit_points': core keywords the dialog does not show."""
    out = tmp_path / "dtm.tif"
    outputs = {"OUTPUT": str(out)}
    if alg == "lidartodtm":
        cp = tmp_path / "cp.csv"
        cp.write_text("id,x,y,z\n1,500010,4000010,100\n", encoding="utf-8")
        outputs = {"OUTPUT_DTM": str(out), "OUTPUT": str(tmp_path / "c.laz"),
                   "CHECKPOINTS_CSV": str(cp)}
    text = refused(qgis_processing, f"geomatics:{alg}", {
        "INPUT": str(data["laz"]), "CELL_SIZE": 1.0, **outputs, **params}, message,
        [data["laz"]], [out, tmp_path / "c.laz"])
    assert not re.search(r"\b(max_points|min_points|max_lag|fit_points|nlags)\b", text)
    assert not re.match(r"(power|sill|range) ", text)        # the old keyword openings


@pytest.mark.parametrize("params,message", [
    ({"SUBSET_SIZE": 3, "ORDER": 2},
     r"The random fitting subset per tile \(SUBSET_SIZE\) must be at least 6 points for a "
     r"polynomial of order 2 \(ORDER\), got 3: give 6 or more, or 0 to fit every point\."),
    ({"TOLERANCE": 0.0},
     r"The stop tolerance \(TOLERANCE\) must be a positive number of metres, got 0\.0: give "
     r"e\.g\. 0\.01\."),
], ids=["subset", "tolerance"])
def test_lsqgroundfilter_option_refusals_name_the_parameters(qgis_processing, data, tmp_path,
                                                             params, message):
    """Were 'subset_size must be at least 6 points for order 2 (or None …)' and 'tolerance
    must be …': a keyword and a Python value the dialog does not show."""
    out, ground = tmp_path / "c.laz", tmp_path / "g.laz"
    text = refused(qgis_processing, "geomatics:lsqgroundfilter", {
        "INPUT": str(data["laz"]), "OUTPUT": str(out), "GROUND_OUTPUT": str(ground),
        **params}, message, [data["laz"]], [out, ground])
    assert "None" not in text and "subset_size" not in text

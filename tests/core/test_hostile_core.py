"""Hostile input, round 3 (issue 22): core cases — origin-independent TIN, ..."""
from __future__ import annotations

import numpy as np
import pytest

from geomatics_toolbox.core.errors import InputError
from geomatics_toolbox.core.terrain.accuracy import check_points_not_degrees
from geomatics_toolbox.core.terrain.grid import grid_from_points
from geomatics_toolbox.core.terrain.tin import tin_grid


def _las(v, offset, scale=0.01):
    """Coordinates as a LAS file stores them (integers × scale + offset)."""
    return np.round((v - offset) / scale) * scale + offset


def test_tin_does_not_depend_on_the_origin():
    # a lattice: every four neighbours are cocircular, so Qhull breaks ties — with the
    # cloud's absolute coordinates it broke them differently 1e8 m away (6.4 m apart in
    # 6786 of 14,400 cells before local coordinates)
    rng = np.random.default_rng(0)
    gx, gy = np.meshgrid(np.arange(0, 60, 1.5), np.arange(0, 60, 1.5))
    x, y = gx.ravel() + 512_345.67, gy.ravel() + 4_012_345.67
    z = rng.normal(100, 3, x.size)
    out = []
    for shift in (0.0, 1e8):
        xs = _las(x + shift, np.floor((x + shift).min()))
        ys = _las(y + shift, np.floor((y + shift).min()))
        out.append(tin_grid(xs, ys, z, grid_from_points(xs, ys, 0.5)).z)
    a, b = out
    assert np.array_equal(np.isnan(a), np.isnan(b))
    assert np.nanmax(np.abs(a - b)) < 1e-6


def test_lon_lat_check_points_on_a_projected_dtm_refused():
    with pytest.raises(InputError, match="look like longitude/latitude.*EPSG:32632"):
        check_points_not_degrees([9.1, 9.2], [48.1, 48.2], (500000, 500100, 5e6, 5e6 + 100),
                                 crs_label="EPSG:32632")
    # points on the DTM, or a DTM in degrees: nothing to say
    check_points_not_degrees([500050.0], [5e6 + 50], (500000, 500100, 5e6, 5e6 + 100))
    check_points_not_degrees([9.1], [48.1], (9.0, 9.5, 48.0, 48.5))


# ----------------------------------------------------------------- 4. headers that lie
def _small_las(path, n=200, version="1.2", point_format=1):
    from geomatics_toolbox.core.io.las import write_las
    rng = np.random.default_rng(3)
    write_las(path, 500_000 + rng.uniform(0, 20, n), 4e6 + rng.uniform(0, 20, n),
              100 + rng.uniform(0, 2, n), crs="EPSG:32632", version=version,
              point_format=point_format)
    return path


def test_huge_vlr_count_refused_before_reading(tmp_path):
    from geomatics_toolbox.core.io.las import las_info, read_las
    from geomatics_toolbox.synthetic.hostile import huge_vlr_count
    bad = huge_vlr_count(_small_las(tmp_path / "ok.las"), tmp_path / "bad.las")
    for reader in (las_info, read_las):
        with pytest.raises(InputError, match=r"bad\.las claims 1,069,128,089 variable-length "
                                             r"records.*cannot fit in the"):
            reader(bad)


def test_las_1_0_refused_consistently(tmp_path):
    from geomatics_toolbox.core.io.las import check_las_file, las_info
    from geomatics_toolbox.synthetic.hostile import las10_copy
    old = las10_copy(_small_las(tmp_path / "ok.las"), tmp_path / "old.las")
    for fn in (check_las_file, las_info):
        with pytest.raises(InputError, match=r"old\.las declares LAS version 1\.0, which this "
                                             r"toolbox cannot read.*set_version 1\.2"):
            fn(old)


def test_truncated_las_and_lying_evlrs_refused(tmp_path):
    import struct

    from geomatics_toolbox.core.io.las import las_info
    src = _small_las(tmp_path / "ok.las")
    data = open(src, "rb").read()
    cut = tmp_path / "cut.las"
    cut.write_bytes(data[: len(data) - 100])
    with pytest.raises(InputError, match=r"cut\.las is truncated: its header declares 200 "
                                         r"points of 28 bytes"):
        las_info(cut)
    v14 = bytearray(open(_small_las(tmp_path / "v14.las", version="1.4", point_format=6),
                         "rb").read())
    v14[235:247] = struct.pack("<QI", len(v14) - 10, 5)      # 5 EVLRs in the last 10 bytes
    lie = tmp_path / "evlr.las"
    lie.write_bytes(bytes(v14))
    with pytest.raises(InputError, match=r"evlr\.las claims 5 extended VLRs"):
        las_info(lie)
    # a VLR whose length runs into the point data
    v12 = bytearray(data)
    header_size = struct.unpack_from("<H", v12, 94)[0]
    v12[header_size + 20:header_size + 22] = struct.pack("<H", 60000)
    (tmp_path / "vlr.las").write_bytes(bytes(v12))
    with pytest.raises(InputError, match=r"variable-length record 1 of 1 runs past"):
        las_info(tmp_path / "vlr.las")


# ----------------------------------------------------------------- 5. wrong output types
@pytest.mark.parametrize("kind,src,dst,message", [
    ("cloud", "c.laz", "c.tif", r"cloud output cannot be written as .*c\.tif.*\.las or \.laz"),
    ("cloud", "c.laz", "c.txt", r"cloud output cannot be written as .*c\.txt"),
    ("raster", "d.tif", "d.txt", r"raster output cannot be written as .*d\.txt.*\.tif"),
    ("vector", "r.gpkg", "r.txt", r"vector output cannot be written as .*r\.txt.*\.gpkg"),
])
def test_publish_to_a_wrong_format_refused_before_any_copy(tmp_path, kind, src, dst, message):
    from geomatics_toolbox.core.io import contract
    from geomatics_toolbox.core.io.publish import publish_files
    s = tmp_path / src
    s.write_bytes(b"data")
    ok = tmp_path / "ok.html"
    ok_src = tmp_path / "src.html"
    ok_src.write_text("<p>report</p>")
    with pytest.raises(InputError, match=message):
        publish_files({"A": (str(ok_src), str(ok), "file"),
                       "B": (str(s), str(tmp_path / "out" / dst), kind)})
    assert not ok.exists() and not (tmp_path / "out").exists()
    assert not [p for p in tmp_path.iterdir() if contract.is_temp(p)]


# ----------------------------------------------------------------- 6. foreign metadata
def _descriptors(path):
    from geomatics_toolbox.synthetic.hostile import extra_bytes_descriptors
    return extra_bytes_descriptors(path)


@pytest.mark.parametrize("extra", [False, True])
def test_extra_bytes_descriptors_written_exactly_as_read(tmp_path, extra):
    import laspy

    from geomatics_toolbox.core.io.las import read_las, write_las_like
    from geomatics_toolbox.synthetic.hostile import write_extra_bytes_las
    src = tmp_path / "eb.las"
    declared = write_extra_bytes_las(src)
    assert _descriptors(src)[0] == declared
    n = len(read_las(src))
    dst = tmp_path / "copy.las"
    kw = {"extra": {"HeightAboveGround": np.zeros(n, np.float32)}} if extra else {}
    write_las_like(src, dst, dimensions={"classification": np.full(n, 2, np.uint8)}, **kw)
    got, _ = _descriptors(dst)
    for name, raw in declared.items():
        assert got[name] == raw, name          # options, min/max, no-data, scale, offset
    assert ("HeightAboveGround" in got) == extra
    las = laspy.read(dst)
    assert np.allclose(las["hag"], np.arange(n) * 0.5) and (las.classification == 2).all()


def test_vlr_count_is_what_was_really_read(tmp_path):
    import laspy

    from geomatics_toolbox.core.io.las import las_info, write_las_like
    from geomatics_toolbox.synthetic.hostile import padded_vlr_count
    src = _small_las(tmp_path / "ok.las")
    lie = padded_vlr_count(src, tmp_path / "lie.las")
    assert _descriptors(lie)[1] == 2 and las_info(lie).count == 200
    dst = tmp_path / "copy.las"
    write_las_like(lie, dst)
    assert _descriptors(dst)[1] == 1                          # no invented empty VLR
    assert [v.record_id for v in laspy.read(dst).header.vlrs] == [34735]


# ----------------------------------------------------------------- 2. two clouds' CRSs
def test_filter_accuracy_reference_in_another_crs_refused(tmp_path):
    from geomatics_toolbox.core.io.las import write_las
    from geomatics_toolbox.core.lidar.accuracy_file import assess_clouds
    rng = np.random.default_rng(5)
    x, y, z = 500_000 + rng.uniform(0, 20, 50), 4e6 + rng.uniform(0, 20, 50), rng.uniform(0, 2, 50)
    cls = {"classification": np.full(50, 2, np.uint8)}
    write_las(tmp_path / "a.las", x, y, z, dimensions=cls, crs="EPSG:32632", version="1.2",
              point_format=1)
    write_las(tmp_path / "b.las", x, y, z, dimensions=cls, crs="EPSG:32632")   # WKT: same
    write_las(tmp_path / "c.las", x, y, z, dimensions=cls, crs="EPSG:32633")
    assert assess_clouds(tmp_path / "a.las", tmp_path / "b.las").accuracy.total == 0.0
    with pytest.raises(InputError, match=r"a\.las is in EPSG:32632.*c\.las is in EPSG:32633"):
        assess_clouds(tmp_path / "a.las", tmp_path / "c.las")


# ----------------------------------------------------------------- 5. cloud names up front
def test_point_cloud_outputs_checked_where_the_contract_is_built(tmp_path):
    """Review H7: one check, up front, by the contract (which knows the final names)."""
    from geomatics_toolbox.core.io import contract
    with pytest.raises(InputError, match=r"The output CLOUD is a point cloud and cannot be "
                                         r"written as .*c\.tif: .*\.las or \.laz"):
        contract.OutputContract({"CLOUD": tmp_path / "c.tif", "R": tmp_path / "r.html"},
                                point_clouds=["CLOUD"])
    assert list(tmp_path.iterdir()) == []
    ok = contract.OutputContract({"CLOUD": tmp_path / "c.LAZ", "DTM": tmp_path / "d.tif"},
                                 point_clouds=["CLOUD", "OTHER"])
    assert ok.final("CLOUD") == str(tmp_path / "c.LAZ")
    tmp = contract.temp_path(tmp_path / "c.LAZ")
    assert contract.final_path(tmp) == tmp_path / "c.LAZ"           # inverse of temp_path
    contract.check_las_output("CLOUD", tmp)                        # temp checked as final
    tif = contract.temp_path(tmp_path / "c.tif")
    with pytest.raises(InputError, match=r"written as .*[/\\]c\.tif:"):   # not .c.part-…
        contract.check_las_output("CLOUD", tif)


def test_ground_filter_refuses_a_tif_cloud_before_reading(tmp_path, monkeypatch):
    from geomatics_toolbox.core.lidar import pipeline
    from geomatics_toolbox.core.lidar.filters import default_ground_filter, ground_filter

    def never(*a, **k):
        raise AssertionError("the input was read before the output name was checked")
    monkeypatch.setattr(pipeline, "read_cloud", never)
    outs = pipeline.FilterOutputs(cloud=str(tmp_path / "c.laz"),
                                  ground=str(tmp_path / "g.tif"))
    with pytest.raises(InputError, match=r"is a point cloud and cannot be written as "
                                         r".*g\.tif"):
        pipeline.classify_file(tmp_path / "in.laz", ground_filter(default_ground_filter()),
                               outs)
    assert list(tmp_path.iterdir()) == []

"""LAS/LAZ I/O (core/las_io.py): the round-trip acceptance test of issue 2 and the
bad-input errors.

The source files are built with laspy directly (not with ``write_las``), with
*random bytes* in every field of every point record — flags, return numbers,
scan angle, user data, GPS time (NaNs included) and the extra bytes — so "every
other dimension is preserved bit for bit" is checked on the raw records.
"""
from __future__ import annotations

import hashlib
import os
import shutil
from pathlib import Path

import laspy
import numpy as np
import pytest
from osgeo import osr

from geomatics_toolbox.core.io import las as las_io
from geomatics_toolbox.core.progress import Cancelled

N = 3000
EXTRA = [("hag", np.float32), ("tag", np.uint16)]
CUSTOM_VLR = ("geomatics_test", 4242, "opaque test payload", bytes(range(256)) * 3)


def _epsg_wkt(code: int) -> str:
    srs = osr.SpatialReference()
    srs.ImportFromEPSG(code)
    return srs.ExportToWkt()


def _geokey_vlr(code: int):
    """GeoKeyDirectory with ProjectedCSTypeGeoKey = code (as LAS 1.2 writers do)."""
    vlr = laspy.vlrs.known.GeoKeyDirectoryVlr()
    entries = [(1, 1, 0, 3), (1024, 0, 1, 1), (1025, 0, 1, 1), (3072, 0, 1, code)]
    keys = []
    for kid, loc, count, value in entries:
        k = laspy.vlrs.geotiff.GeoKeyEntryStruct()
        k.id, k.tiff_tag_location, k.count, k.value_offset = kid, loc, count, value
        keys.append(k)
    vlr.geo_keys_header = keys[0]
    vlr.geo_keys_header.number_of_keys = len(keys) - 1
    vlr.geo_keys = keys[1:]
    return vlr


def make_source(path: Path, *, version: str, point_format: int, seed: int = 0,
                evlr: bool = False) -> Path:
    """A LAS/LAZ with extra bytes, a CRS, a custom VLR and random point bytes."""
    header = laspy.LasHeader(point_format=point_format, version=version)
    header.add_extra_dims([laspy.ExtraBytesParams(name=n, type=t) for n, t in EXTRA])
    header.scales = np.array([0.001, 0.002, 0.01])
    header.offsets = np.array([499_000.0, 3_999_000.0, -50.0])
    if header.version.minor >= 4:
        header.vlrs.append(laspy.vlrs.known.WktCoordinateSystemVlr(_epsg_wkt(32633)))
        header.global_encoding.wkt = True
    else:
        header.vlrs.append(_geokey_vlr(32633))
    header.vlrs.append(laspy.VLR(*CUSTOM_VLR))
    rng = np.random.default_rng(seed)
    rec = laspy.ScaleAwarePointRecord.zeros(N, header=header)
    rec.array.view(np.uint8)[:] = rng.integers(0, 256, rec.array.nbytes, dtype=np.uint8)
    las = laspy.LasData(header, rec)
    if evlr:
        las.evlrs = laspy.vlrs.vlrlist.VLRList(
            [laspy.VLR("geomatics_test", 77, "an EVLR", b"\x00\xff" * 500)])
    las.write(str(path))
    return path


@pytest.fixture(scope="module")
def sources(tmp_path_factory):
    d = tmp_path_factory.mktemp("las_src")
    return {
        "14laz": make_source(d / "src14.laz", version="1.4", point_format=6, seed=1),
        "14las": make_source(d / "src14.las", version="1.4", point_format=7, seed=2),
        "12laz": make_source(d / "src12.laz", version="1.2", point_format=3, seed=3),
        "12las": make_source(d / "src12.las", version="1.2", point_format=1, seed=4),
    }


def _vlr_key(vlr):
    data = vlr.record_data_bytes() if hasattr(vlr, "record_data_bytes") else vlr.record_data
    return (vlr.user_id, vlr.record_id, vlr.description, bytes(data))


def _class_field(las) -> str:
    return "classification" if las.header.point_format.id >= 6 else "raw_classification"


def assert_same_except_classification(src, out, *, new_class, mask=None):
    """Every field of every record equal byte for byte, except the class bits."""
    a, b = laspy.read(str(src)), laspy.read(str(out))
    ra, rb = a.points.array, b.points.array
    if mask is not None:
        ra = ra[mask]
        new_class = new_class[mask]
    assert ra.dtype == rb.dtype
    assert ra.shape == rb.shape
    cfield = _class_field(a)
    for name in ra.dtype.names:
        if name == cfield:
            continue
        assert ra[name].tobytes() == rb[name].tobytes(), f"field {name} changed"
    if cfield == "raw_classification":           # formats 0-5: 5 class bits + 3 flags
        assert np.array_equal(ra[cfield] & 0xE0, rb[cfield] & 0xE0), "class flags changed"
        assert np.array_equal(rb[cfield] & 0x1F, new_class)
    else:
        assert np.array_equal(rb[cfield], new_class)
    # every laspy dimension (incl. extra bytes and bit fields) as arrays, too
    for dim in a.point_format.dimension_names:
        if dim == "classification":
            continue
        va, vb = np.asarray(a[dim]), np.asarray(b[dim])
        if mask is not None:
            va = va[mask]
        assert va.tobytes() == vb.tobytes(), f"dimension {dim} changed"
    return a, b


def assert_same_header(a, b, *, count=None):
    ha, hb = a.header, b.header
    assert hb.version == ha.version
    assert hb.point_format.id == ha.point_format.id
    assert list(hb.point_format.dimension_names) == list(ha.point_format.dimension_names)
    assert np.array_equal(hb.scales, ha.scales)
    assert np.array_equal(hb.offsets, ha.offsets)
    assert hb.global_encoding.value == ha.global_encoding.value
    assert hb.point_count == (ha.point_count if count is None else count)
    va = [_vlr_key(v) for v in ha.vlrs]
    vb = [_vlr_key(v) for v in hb.vlrs]
    assert len(vb) == len(va)
    assert vb == va
    assert las_io.crs_of_header(hb) == las_io.crs_of_header(ha)


def _new_classes(path, seed=9):
    info = las_io.las_info(path)
    top = 255 if info.point_format >= 6 else 31
    return np.random.default_rng(seed).integers(0, top + 1, info.count).astype(np.uint8)


# --------------------------------------------------------------------- round trip
@pytest.mark.parametrize("key", ["14laz", "14las", "12laz", "12las"])
def test_round_trip_changes_only_the_classification(sources, tmp_path, key):
    src = sources[key]
    data = las_io.read_las(src, ("classification",))
    assert data.info.count == N
    new = _new_classes(src)
    assert not np.array_equal(new, data["classification"])
    out = tmp_path / f"out{src.suffix}"
    assert las_io.write_las_like(src, out, dimensions={"classification": new}) == N
    a, b = assert_same_except_classification(src, out, new_class=new)
    assert_same_header(a, b)
    assert np.allclose(b.header.mins, a.header.mins) and np.allclose(b.header.maxs, a.header.maxs)
    # the CRS is the one we stored, seen by las_info as WKT (1.4) or EPSG (1.2)
    crs = las_io.las_info(out).crs
    assert crs is not None
    srs, ref = osr.SpatialReference(), osr.SpatialReference()
    srs.SetFromUserInput(crs)
    ref.ImportFromEPSG(32633)
    assert srs.IsSame(ref)
    if key.startswith("12"):
        assert crs == "EPSG:32633"
    # the extra bytes read back through read_las as well
    back = las_io.read_las(out, ("hag", "tag", "classification"))
    assert back["hag"].dtype == np.float32 and back["tag"].dtype == np.uint16
    assert np.array_equal(back["classification"], new)
    assert np.array_equal(back.x, data.x) and np.array_equal(back.z, data.z)


def test_round_trip_other_dimension_and_extra_bytes(sources, tmp_path):
    src = sources["14laz"]
    a = laspy.read(str(src))
    tag = np.arange(N, dtype=np.uint16)
    out = tmp_path / "tag.laz"
    las_io.write_las_like(src, out, dimensions={"tag": tag})
    b = laspy.read(str(out))
    assert np.array_equal(np.asarray(b["tag"]), tag)
    for name in a.points.array.dtype.names:
        if name != "tag":
            assert a.points.array[name].tobytes() == b.points.array[name].tobytes(), name


def test_mask_writes_a_subset(sources, tmp_path):
    src = sources["14laz"]
    mask = np.random.default_rng(3).random(N) < 0.3
    new = _new_classes(src, seed=4)
    out = tmp_path / "subset.laz"
    n = las_io.write_las_like(src, out, dimensions={"classification": new}, mask=mask)
    assert n == mask.sum() == las_io.las_info(out).count
    a, b = assert_same_except_classification(src, out, new_class=new, mask=mask)
    assert_same_header(a, b, count=int(mask.sum()))
    # header bounds are those of the subset
    sub = a.points[mask]
    assert np.allclose(b.header.mins, [sub.x.min(), sub.y.min(), sub.z.min()])
    assert np.allclose(b.header.maxs, [sub.x.max(), sub.y.max(), sub.z.max()])


def test_mask_and_dimensions_across_chunks(sources, tmp_path):
    """Chunked copy (small chunk_size): values land on the right points."""
    src = sources["12laz"]
    mask = np.zeros(N, bool)
    mask[::7] = True
    new = _new_classes(src, seed=5)
    out = tmp_path / "chunks.las"
    n = las_io.write_las_like(src, out, dimensions={"classification": new}, mask=mask,
                              chunk_size=333)
    assert n == mask.sum()
    assert_same_except_classification(src, out, new_class=new, mask=mask)


def test_evlrs_are_preserved(tmp_path):
    src = make_source(tmp_path / "evlr.laz", version="1.4", point_format=6, evlr=True)
    a = laspy.read(str(src))
    assert len(a.header.evlrs) == 1
    out = tmp_path / "evlr_out.laz"
    las_io.write_las_like(src, out)
    b = laspy.read(str(out))
    assert [_vlr_key(v) for v in (b.header.evlrs or [])] == [_vlr_key(v) for v in a.header.evlrs]


@pytest.mark.parametrize("src_key, out_name", [("14laz", "conv.las"), ("12laz", "conv.las"),
                                               ("14las", "conv.laz"), ("12las", "conv.laz")])
def test_las_laz_conversion(sources, tmp_path, src_key, out_name):
    src = sources[src_key]
    out = tmp_path / out_name
    las_io.write_las_like(src, out)
    raw = out.read_bytes()
    compressed = raw[104] & 0x80 != 0          # LAZ sets bit 7 of the point format id
    assert compressed == out_name.endswith(".laz")
    a, b = laspy.read(str(src)), laspy.read(str(out))
    assert a.points.array.tobytes() == b.points.array.tobytes()
    assert_same_header(a, b)
    assert las_io.las_info(out).compressed == out_name.endswith(".laz")


# --------------------------------------------------------------------- reading
def test_read_las_and_chunks_reassemble_exactly(sources):
    src = sources["14laz"]
    names = ("classification", "intensity", "gps_time", "hag", "tag", "return_number")
    full = las_io.read_las(src, names)
    las = laspy.read(str(src))
    assert np.array_equal(full.x, np.asarray(las.x)) and np.array_equal(full.y, np.asarray(las.y))
    assert full.x.dtype == np.float64
    starts, parts = [], []
    for start, chunk in las_io.iter_las_chunks(src, names, chunk_size=451):
        assert len(chunk) <= 451
        assert chunk.info.count == N
        starts.append(start)
        parts.append(chunk)
    assert starts == list(range(0, N, 451))
    for attr in ("x", "y", "z"):
        assert np.concatenate([getattr(p, attr) for p in parts]).tobytes() == \
            getattr(full, attr).tobytes()
    for name in names:
        assert np.concatenate([p[name] for p in parts]).tobytes() == full[name].tobytes()
    small = las_io.read_las(src, names, chunk_size=100)
    for name in names:
        assert small[name].tobytes() == full[name].tobytes()


def test_read_las_progress_and_info(sources):
    seen = []
    las_io.read_las(sources["12las"], ("classification",), chunk_size=500, progress=seen.append)
    assert seen and seen[-1] == pytest.approx(1.0) and seen == sorted(seen)
    info = las_io.las_info(sources["12las"])
    assert (info.version, info.point_format, info.count) == ("1.2", 1, N)
    assert "hag" in info.dimensions and info.crs == "EPSG:32633"


def test_write_las_new_file(tmp_path):
    rng = np.random.default_rng(0)
    x = 500_000 + rng.uniform(0, 50, 100)
    y = 4_000_000 + rng.uniform(0, 50, 100)
    z = rng.uniform(100, 120, 100)
    cls = rng.integers(1, 7, 100).astype(np.uint8)
    hag = rng.normal(size=100).astype(np.float32)
    for name, version, pf in (("a.laz", "1.4", 6), ("b.las", "1.2", 3)):
        out = tmp_path / name
        las_io.write_las(out, x, y, z, dimensions={"classification": cls, "hag": hag},
                         crs="EPSG:32632", version=version, point_format=pf,
                         extra_dims={"hag": "f4"})
        data = las_io.read_las(out, ("classification", "hag"))
        assert np.allclose(data.x, x, atol=0.005) and np.allclose(data.z, z, atol=0.005)
        assert np.array_equal(data["classification"], cls)
        assert np.array_equal(data["hag"], hag)
        assert "32632" in data.info.crs


# --------------------------------------------------------------------- bad input
def _empty_las(path: Path, compress=False) -> Path:
    header = laspy.LasHeader(point_format=6, version="1.4")
    with laspy.open(str(path), mode="w", header=header, do_compress=compress):
        pass
    return path


def _all_readers(path, tmp_path):
    return [
        lambda: las_io.read_las(path),
        lambda: las_io.las_info(path),
        lambda: list(las_io.iter_las_chunks(path)),
        lambda: las_io.write_las_like(path, tmp_path / "never.laz"),
    ]


def test_missing_file(tmp_path):
    missing = tmp_path / "nope.laz"
    for call in _all_readers(missing, tmp_path):
        with pytest.raises(ValueError, match="not found"):
            call()
    with pytest.raises(ValueError, match="No point cloud file"):
        las_io.read_las("")
    assert not (tmp_path / "never.laz").exists()


def test_folder_instead_of_file(tmp_path):
    with pytest.raises(ValueError, match="folder"):
        las_io.read_las(tmp_path)


@pytest.mark.parametrize("compress", [False, True])
def test_empty_cloud(tmp_path, compress):
    path = _empty_las(tmp_path / ("empty.laz" if compress else "empty.las"), compress)
    assert las_io.las_info(path).count == 0
    for call in (lambda: las_io.read_las(path),
                 lambda: list(las_io.iter_las_chunks(path)),
                 lambda: las_io.write_las_like(path, tmp_path / "never.laz")):
        with pytest.raises(ValueError, match="no points"):
            call()
    assert list(las_io.iter_las_chunks(path, allow_empty=True)) == []
    assert not (tmp_path / "never.laz").exists()


@pytest.mark.parametrize("content", [b"x,y,z\n1,2,3\n", b"", b"LAS"])
def test_text_file_named_laz(tmp_path, content):
    path = tmp_path / "points.laz"
    path.write_bytes(content)
    for call in _all_readers(path, tmp_path):
        with pytest.raises(ValueError, match="not a LAS/LAZ file"):
            call()


@pytest.mark.parametrize("major, minor", [(1, 5), (2, 0), (1, 9)])
def test_unsupported_version(sources, tmp_path, major, minor):
    path = tmp_path / "future.laz"
    shutil.copy(sources["14laz"], path)
    with open(path, "r+b") as fh:
        fh.seek(24)
        fh.write(bytes([major, minor]))
    for call in _all_readers(path, tmp_path):
        with pytest.raises(ValueError, match=f"version {major}.{minor}"):
            call()


def test_truncated_header_is_a_clear_error(sources, tmp_path):
    path = tmp_path / "short.las"
    path.write_bytes(sources["14las"].read_bytes()[:120])
    with pytest.raises(ValueError, match=str(path.name)):
        las_io.read_las(path)


@pytest.mark.parametrize("key", ["14las", "14laz"])
def test_truncated_points_are_a_clear_error(sources, tmp_path, key):
    src = sources[key]
    path = tmp_path / f"cut{src.suffix}"
    data = src.read_bytes()
    path.write_bytes(data[:int(len(data) * 0.6)])
    for call in (lambda: las_io.read_las(path),
                 lambda: list(las_io.iter_las_chunks(path, chunk_size=500)),
                 lambda: las_io.write_las_like(path, tmp_path / "never.laz")):
        with pytest.raises(ValueError, match="truncated|corrupt"):
            call()
    assert not (tmp_path / "never.laz").exists()


def test_missing_dimension(sources, tmp_path):
    src = sources["12laz"]
    with pytest.raises(ValueError, match="no dimension.*height_above_ground"):
        las_io.read_las(src, ("classification", "height_above_ground"))
    with pytest.raises(ValueError, match="height_above_ground"):
        list(las_io.iter_las_chunks(src, ("height_above_ground",)))
    out = tmp_path / "never.laz"
    with pytest.raises(ValueError, match="height_above_ground"):
        las_io.write_las_like(src, out, dimensions={"height_above_ground": np.zeros(N)})
    assert not out.exists()


def test_wrong_lengths(sources, tmp_path):
    src = sources["14laz"]
    out = tmp_path / "never.laz"
    with pytest.raises(ValueError, match="classification"):
        las_io.write_las_like(src, out, dimensions={"classification": np.zeros(N - 1, np.uint8)})
    with pytest.raises(ValueError, match="mask"):
        las_io.write_las_like(src, out, mask=np.ones(N + 1, bool))
    assert not out.exists()


def _md5(path) -> str:
    return hashlib.md5(Path(path).read_bytes()).hexdigest()


def test_output_equal_to_input_is_refused(sources, tmp_path):
    src = tmp_path / "in.laz"
    shutil.copy(sources["14laz"], src)
    before = _md5(src), os.stat(src).st_mtime_ns
    for dst in (src, tmp_path / "sub" / ".." / "in.laz", str(src)):
        (tmp_path / "sub").mkdir(exist_ok=True)
        with pytest.raises(ValueError, match="same file"):
            las_io.write_las_like(src, dst, dimensions={"classification": np.zeros(N, np.uint8)})
    link = tmp_path / "link.laz"
    link.symlink_to(src)
    with pytest.raises(ValueError, match="same file"):
        las_io.write_las_like(link, src)
    assert (_md5(src), os.stat(src).st_mtime_ns) == before
    assert sorted(p.name for p in tmp_path.iterdir()) == ["in.laz", "link.laz", "sub"]


def test_cancel_leaves_no_output(sources, tmp_path):
    src = sources["14laz"]
    out = tmp_path / "cancelled.laz"
    with pytest.raises(Cancelled):
        las_io.write_las_like(src, out, dimensions={"classification": np.zeros(N, np.uint8)},
                              cancel=lambda: True)
    assert list(tmp_path.iterdir()) == []
    # a cancel after some chunks were written leaves nothing either
    calls = []

    def cancel_later():
        calls.append(1)
        return len(calls) > 2

    with pytest.raises(Cancelled):
        las_io.write_las_like(src, out, chunk_size=500, cancel=cancel_later)
    assert list(tmp_path.iterdir()) == []


def test_failure_keeps_an_existing_output_untouched(sources, tmp_path):
    src = sources["14laz"]
    out = tmp_path / "existing.laz"
    out.write_bytes(b"previous result")

    def boom(_fraction):
        raise RuntimeError("disk full (simulated)")

    with pytest.raises(RuntimeError, match="disk full"):
        las_io.write_las_like(src, out, chunk_size=500, progress=boom)
    with pytest.raises(Cancelled):
        las_io.write_las_like(src, out, cancel=lambda: True)
    assert out.read_bytes() == b"previous result"
    assert [p.name for p in tmp_path.iterdir()] == ["existing.laz"]


def test_laz_without_backend(sources, tmp_path, monkeypatch):
    monkeypatch.setattr(laspy.LazBackend, "detect_available", staticmethod(lambda: ()))
    with pytest.raises(ValueError, match="lazrs"):
        las_io.read_las(sources["14laz"])
    # uncompressed files still work
    assert len(las_io.read_las(sources["14las"])) == N


def test_bad_chunk_size(sources):
    with pytest.raises(ValueError, match="chunk_size"):
        list(las_io.iter_las_chunks(sources["14las"], chunk_size=0))

"""Quirky LAS files for the hostile-input tests (not shipped).

* :func:`write_geokeys_las` — LAS 1.1–1.3 with any GeoTIFF keys (e.g. a US state plane
  in US survey feet with ``VerticalUnitsGeoKey``), the way US vendors deliver them;
* :func:`unit_copy` — a copy of a metre cloud in another linear unit (coordinates
  divided by the unit's length in metres), under a feet CRS: the same terrain, so a
  filter or gridder that honours units gives the same answer;
* :func:`huge_vlr_count` — a copy whose header claims ``n`` VLRs (the real-world file
  that made ``groundfilter`` grow past 6 GB);
* :func:`las10_copy` — the same points as LAS 1.0;
* :func:`write_extra_bytes_las` — ExtraBytes with declared min/max/no-data/scale/offset.
"""
from __future__ import annotations

import os
import struct
from typing import Mapping, Optional

import numpy as np

_STANDARD = ("intensity", "return_number", "number_of_returns", "classification",
             "scan_angle_rank", "user_data", "point_source_id", "gps_time")


def _geokey_vlr(keys: Mapping[int, int]):
    import laspy
    vlr = laspy.vlrs.known.GeoKeyDirectoryVlr()
    head = laspy.vlrs.geotiff.GeoKeyEntryStruct()
    head.id, head.tiff_tag_location, head.count, head.value_offset = 1, 1, 0, len(keys)
    vlr.geo_keys_header = head
    entries = []
    for kid, value in sorted(keys.items()):
        k = laspy.vlrs.geotiff.GeoKeyEntryStruct()
        k.id, k.tiff_tag_location, k.count, k.value_offset = int(kid), 0, 1, int(value)
        entries.append(k)
    head.number_of_keys = len(entries)
    vlr.geo_keys = entries
    return vlr


def write_geokeys_las(dst, x, y, z, *, keys: Mapping[int, int],
                      dimensions: Optional[Mapping[str, np.ndarray]] = None,
                      scale: float = 0.01, version: str = "1.2",
                      point_format: int = 1) -> str:
    """Write a LAS/LAZ file whose CRS is given as GeoTIFF keys.

    ``keys`` maps key ids to EPSG codes, e.g. ``{1024: 1, 3072: 2903, 3076: 9003,
    4096: 5103, 4099: 9003}`` (projected, NAD83(HARN) / New Mexico Central (ftUS),
    NAVD88 heights in US survey feet).
    """
    import laspy
    x, y, z = (np.asarray(v, dtype=np.float64) for v in (x, y, z))
    header = laspy.LasHeader(point_format=point_format, version=version)
    header.scales = np.array([scale, scale, scale])
    header.offsets = np.floor(np.array([x.min(), y.min(), z.min()]))
    header.vlrs.append(_geokey_vlr(keys))
    rec = laspy.ScaleAwarePointRecord.zeros(x.size, header=header)
    rec.x, rec.y, rec.z = x, y, z
    for name, values in (dimensions or {}).items():
        if name in rec.point_format.dimension_names:
            rec[name] = values
    with laspy.open(os.fspath(dst), mode="w", header=header,
                    do_compress=os.fspath(dst).lower().endswith(".laz")) as w:
        w.write_points(rec)
    return os.fspath(dst)


def unit_copy(src, dst, *, unit_metres: float = 1200.0 / 3937.0,
              keys: Optional[Mapping[int, int]] = None, scale: float = 0.001,
              vertical_metres: Optional[float] = None) -> str:
    """Write ``src`` (a metre cloud) with coordinates in another unit, under GeoTIFF keys.

    x, y are divided by ``unit_metres``, z by ``vertical_metres`` (default the same);
    every standard attribute (classes, returns, intensity) is kept. Default keys: the
    US-survey-feet state plane EPSG:2903 with NAVD88 heights in US survey feet.
    """
    import laspy
    las = laspy.read(os.fspath(src))
    vm = unit_metres if vertical_metres is None else vertical_metres
    if keys is None:
        keys = {1024: 1, 3072: 2903, 3076: 9003, 4096: 5103, 4099: 9003}
    dims = {n: np.asarray(las[n]) for n in _STANDARD if n in las.point_format.dimension_names}
    pf = 3 if "gps_time" in dims else 1
    if "scan_angle_rank" not in dims and "scan_angle" in las.point_format.dimension_names:
        dims["scan_angle_rank"] = np.clip(np.asarray(las["scan_angle"]) * 0.006, -90,
                                          90).astype(np.int8)
    return write_geokeys_las(dst, np.asarray(las.x) / unit_metres,
                             np.asarray(las.y) / unit_metres, np.asarray(las.z) / vm,
                             keys=keys, dimensions=dims, scale=scale, point_format=pf)


def huge_vlr_count(src, dst, n: int = 1_069_128_089) -> str:
    """Copy ``src`` (any LAS, not LAZ) with a header that claims ``n`` VLRs."""
    data = bytearray(open(os.fspath(src), "rb").read())
    data[100:104] = struct.pack("<I", n)
    open(os.fspath(dst), "wb").write(bytes(data))
    return os.fspath(dst)


def las10_copy(src, dst) -> str:
    """Copy an uncompressed LAS 1.2 file ``src`` declaring version 1.0 (same layout)."""
    data = bytearray(open(os.fspath(src), "rb").read())
    if data[24:26] != bytes([1, 2]):
        raise ValueError("las10_copy needs a LAS 1.2 source")
    data[25] = 0
    open(os.fspath(dst), "wb").write(bytes(data))
    return os.fspath(dst)


def extra_bytes_descriptors(path) -> tuple:
    """``({name: descriptor bytes}, VLR count)`` of a LAS file, read byte by byte."""
    out = {}
    with open(os.fspath(path), "rb") as fh:
        vlrs = list(_extra_bytes_vlrs(fh))
        for pos, length in vlrs:
            if pos is None:
                continue
            fh.seek(pos + 54)
            data = fh.read(length)
            for k in range(length // 192):
                raw = data[k * 192:(k + 1) * 192]
                out[raw[4:36].split(b"\0", 1)[0].decode()] = raw
    return out, len(vlrs)


def _extra_bytes_vlrs(fh):
    """Walk the VLRs of an open LAS file: one ``(pos, length)`` per VLR, ``pos`` None
    unless it is the ExtraBytes VLR (LASF_Spec, record 4)."""
    fh.seek(94)
    header_size, _, count = struct.unpack("<HII", fh.read(10))
    pos = header_size
    for _ in range(count):
        fh.seek(pos)
        head = fh.read(54)
        user = head[2:18].split(b"\0", 1)[0]
        record, length = struct.unpack("<HH", head[18:22])
        yield (pos if user == b"LASF_Spec" and record == 4 else None), length
        pos += 54 + length


def write_extra_bytes_las(dst, *, n: int = 50) -> dict:
    """LAS 1.4 with two extra-bytes dimensions whose descriptors declare their own
    min/max/no-data/scale/offset (option bits 0b11111 and 0b00111), as producers write.

    Returns ``{name: descriptor bytes}`` (192 bytes each) as written.
    """
    import laspy
    h = laspy.LasHeader(point_format=6, version="1.4")
    h.add_extra_dim(laspy.ExtraBytesParams(name="hag", type=np.int32, description="height",
                                           scales=np.array([0.01]),
                                           offsets=np.array([0.0])))
    h.add_extra_dim(laspy.ExtraBytesParams(name="amp", type=np.uint16, description="amp"))
    rec = laspy.ScaleAwarePointRecord.zeros(n, header=h)
    rec.x = 500_000 + np.arange(n, dtype=float)
    rec.y = 4e6 + np.arange(n, dtype=float)
    rec.z = 100 + np.arange(n, dtype=float)
    rec["hag"] = np.arange(n) * 0.5
    rec["amp"] = np.arange(n)
    dst = os.fspath(dst)
    with laspy.open(dst, mode="w", header=h) as w:
        w.write_points(rec)
    declared = {b"hag": (0b11111, -1000, 10000, -9999),      # raw (unscaled) int64 values
                b"amp": (0b00111, 0, 60000, 65535)}
    out = {}
    with open(dst, "r+b") as fh:
        for pos, length in list(_extra_bytes_vlrs(fh)):
            if pos is None:
                continue
            for k in range(length // 192):
                off = pos + 54 + k * 192
                fh.seek(off)
                raw = bytearray(fh.read(192))
                name = bytes(raw[4:36]).split(b"\0", 1)[0]
                opts, lo, hi, nodata = declared[name]
                raw[3] = opts
                raw[40:48] = struct.pack("<q" if name == b"hag" else "<Q", nodata)
                raw[64:72] = struct.pack("<q" if name == b"hag" else "<Q", lo)
                raw[88:96] = struct.pack("<q" if name == b"hag" else "<Q", hi)
                fh.seek(off)
                fh.write(bytes(raw))
                out[name.decode()] = bytes(raw)
    return out


def padded_vlr_count(src, dst) -> str:
    """Copy ``src`` (LAS) with 54 zero bytes after its VLRs counted as one more VLR."""
    data = bytearray(open(os.fspath(src), "rb").read())
    header_size, offset, count = struct.unpack_from("<HII", data, 94)
    pos = header_size
    for _ in range(count):
        pos += 54 + struct.unpack_from("<H", data, pos + 20)[0]
    data[pos:pos] = bytes(54)
    struct.pack_into("<II", data, 96, offset + 54, count + 1)
    if data[25] >= 4:     # LAS 1.4: the EVLR start moves too
        start = struct.unpack_from("<Q", data, 235)[0]
        if start:
            struct.pack_into("<Q", data, 235, start + 54)
    open(os.fspath(dst), "wb").write(bytes(data))
    return os.fspath(dst)

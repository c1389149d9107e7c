"""LAS/LAZ writing (private; the public names are re-exported by :mod:`.las`).

:func:`write_las_like` copies an input with some dimensions replaced and/or a subset of
points, every other attribute, VLR, EVLR and the CRS kept; :func:`write_las` writes a
new file from arrays.
"""
from __future__ import annotations

import os
from typing import Mapping, Optional

import numpy as np

from ..errors import InputError
from ..progress import Monitor
from . import las as _las
from .contract import atomic_output, check_not_input, final_path
from .crs import spatial_reference
from .las import DEFAULT_CHUNK, LasInfo, _check_dims, _laspy, _open, las_info


def check_las_name(dst) -> None:
    """Last guard: never write LAS/LAZ content under another extension (``c.tif``).

    Runs check their point-cloud outputs up front (``OutputContract(...,
    point_clouds=...)``, the algorithms' parameter check); this catches direct callers.
    """
    if not os.fspath(dst).lower().endswith(_las.LAS_SUFFIXES):
        raise InputError("A point cloud cannot be written as {path}: LAS/LAZ content under "
                         "another extension would be mistaken for another format. Choose "
                         "a file name ending in .las or .laz.",
                         path=os.fspath(final_path(dst)))


def write_las_like(src, dst, *, dimensions: Optional[Mapping[str, np.ndarray]] = None,
                   mask: Optional[np.ndarray] = None, chunk_size: int = DEFAULT_CHUNK,
                   extra: Optional[Mapping[str, np.ndarray]] = None,
                   records: Optional[list] = None, progress=None, cancel=None) -> int:
    """Copy ``src`` to ``dst`` replacing some dimensions and/or keeping a subset.

    Every attribute not named in ``dimensions`` is copied bit for bit; the point
    format, LAS version, scales, offsets, VLRs, EVLRs and CRS are those of
    ``src``; header bounds and counts are recomputed. Compression follows the
    extension of ``dst`` (.laz compressed, .las not).

    Parameters
    ----------
    src, dst : path-like
        Input and output files; ``dst`` must differ from ``src``.
    dimensions : mapping of str to array, optional
        New values per point of ``src`` (full length), e.g.
        ``{"classification": classes}``.
    mask : array of bool, optional
        Full-length selection of the points to write (e.g. ground only).
    extra : mapping of str to array, optional
        New extra-bytes dimensions (e.g. ``{"HeightAboveGround": hag}``, one value per
        point of ``src``), declared with the arrays' dtypes after the file's own
        dimensions; a name the file already has is replaced in place instead. Every
        existing field is copied byte for byte into the wider point record.
    records : list, optional
        The point records of ``src`` already decoded (``read_las(...,
        keep_records=True).records``): written from memory, ``src`` is not decoded
        again (its header is still read).

    Returns
    -------
    int
        Number of points written.
    """
    laspy = _laspy()
    mon = Monitor(progress, cancel)
    check_las_name(dst)
    check_not_input(dst, src)
    info = las_info(src)
    if info.count == 0:
        raise InputError("{path} holds no points (empty point cloud).", path=src)
    dimensions, extra = _new_values(info, dimensions, extra)
    if mask is not None:
        mask = np.asarray(mask, dtype=bool)
        if mask.shape != (info.count,):
            raise InputError("mask has shape {shape}; expected ({n},).",
                             shape=mask.shape, n=info.count)
    dst = os.fspath(dst)
    written = 0
    from laspy.vlrs.vlrlist import VLRList
    with _open(src) as reader, atomic_output(dst) as tmp:
        header = reader.header
        _drop_invented_vlrs(header)
        if extra:
            import copy
            header = copy.deepcopy(header)
            header.add_extra_dims([laspy.ExtraBytesParams(name=name, type=np.asarray(v).dtype)
                                   for name, v in extra.items()])
        _drop_copc_records(header)
        with laspy.open(tmp, mode="w", header=header,
                        do_compress=dst.lower().endswith(".laz")) as writer:
            start = 0
            for chunk in (records if records is not None
                          else _las._chunks(reader, src, chunk_size)):
                mon.check()
                stop = start + len(chunk)
                for name, values in dimensions.items():
                    chunk[name] = values[start:stop]
                if extra:
                    chunk = _widen(laspy, chunk, header, extra, start, stop)
                if mask is not None:
                    chunk = chunk[mask[start:stop]]
                if len(chunk):
                    writer.write_points(chunk)
                    written += len(chunk)
                start = stop
                mon.update(stop / info.count)
            if start != info.count:
                raise InputError("{path} declares {n} points but holds {filled}; the file "
                                 "is truncated or corrupt.", path=src, n=info.count,
                                 filled=start)
            # EVLRs of a LAZ file are read (into the reader's header) after its points;
            # records decoded earlier carry those of their own read
            source_evlrs = (getattr(records, "evlrs", None) if records is not None
                            else getattr(reader.header, "evlrs", None))
            evlrs = [v for v in (source_evlrs or []) if not is_copc_record(v)]
            if evlrs:
                writer.write_evlrs(VLRList(evlrs))
        _restore_extra_bytes_vlrs(src, tmp)
    return written


def _new_values(info: LasInfo, dimensions, extra):
    """Return the checked ``(dimensions, extra)``; an ``extra`` name the file has is a dimension."""
    dimensions = dict(dimensions or {})
    extra = dict(extra or {})
    for name in [n for n in extra if n in info.dimensions]:
        dimensions[name] = extra.pop(name)
    _check_dims(info, list(dimensions))
    for name, values in {**dimensions, **extra}.items():
        if np.shape(values) != (info.count,):
            raise InputError("New values for '{name}' have shape {shape}; "
                             "expected one per point ({n}).", name=name,
                             shape=np.shape(values), n=info.count)
    return dimensions, extra


def _vlr_table(fh):
    """``[(user_id, record_id, data offset, length)]`` of the VLRs of an open LAS/LAZ."""
    import struct
    fh.seek(94)
    header_size, _offset, count = struct.unpack("<HII", fh.read(10))
    pos, out = header_size, []
    for _ in range(count):
        fh.seek(pos)
        head = fh.read(54)
        if len(head) < 54:
            break
        user = head[2:18].split(b"\0", 1)[0]
        record, length = struct.unpack("<HH", head[18:22])
        out.append((user, record, pos + 54, length))
        pos += 54 + length
    return out


#: Bytes of one extra-bytes descriptor (LAS 1.4 R15, table 24); its name at 4:36.
_EB_STRUCT = 192


def _restore_extra_bytes_vlrs(src, dst) -> None:
    """Put the source's extra-bytes descriptors back byte for byte into ``dst``.

    laspy's writer rebuilds the extra-bytes VLR from its own dimension list: it sets the
    min/max option bits and resets min/max to ±DBL_MAX (or recomputes them), so a copy
    would lose the producer's declared min/max/no-data/scale/offset and option bits.
    Every descriptor of ``dst`` that has a source descriptor of the same name gets the
    source's 192 bytes back (descriptors of dimensions added by the copy are kept).
    """
    def descriptors(fh):
        out = []
        for user, record, off, length in _vlr_table(fh):
            if user == b"LASF_Spec" and record == 4:
                for k in range(length // _EB_STRUCT):
                    out.append(off + k * _EB_STRUCT)
        return out

    with open(os.fspath(src), "rb") as fs:
        source = {}
        for off in descriptors(fs):
            fs.seek(off)
            raw = fs.read(_EB_STRUCT)
            source.setdefault(raw[4:36].split(b"\0", 1)[0], raw)
    if not source:
        return
    with open(os.fspath(dst), "r+b") as fd:
        for off in descriptors(fd):
            fd.seek(off + 4)
            name = fd.read(32).split(b"\0", 1)[0]
            if name in source:
                fd.seek(off)
                fd.write(source[name])


def _drop_invented_vlrs(header) -> None:
    """Remove VLRs laspy made up from padding (a header VLR count larger than the file's).

    A file whose header counts one VLR more than it holds has zero bytes where the last
    VLR header should be; laspy reads them as an empty VLR (no user id, record 0, no
    data), which a copy would write out as if it were real.
    """
    keep = [v for v in header.vlrs
            if getattr(v, "user_id", "") or getattr(v, "record_id", 0)
            or bytes(getattr(v, "record_data", b"") or b"").strip(b"\0")]
    if len(keep) != len(header.vlrs):
        header.vlrs[:] = keep


def _widen(laspy, chunk, header, extra, start, stop):
    """Return the points of ``chunk`` in ``header``'s wider record, new fields from ``extra``."""
    wide = laspy.ScaleAwarePointRecord.zeros(len(chunk), header=header)
    for name in chunk.array.dtype.names:
        wide.array[name] = chunk.array[name]
    for name, values in extra.items():
        wide[name] = values[start:stop]
    return wide


def is_copc_record(vlr) -> bool:
    """Tell whether ``vlr`` is a COPC record (user id ``copc``: info, hierarchy, extents)."""
    user_id = getattr(vlr, "user_id", "")
    if isinstance(user_id, bytes):
        user_id = user_id.decode("ascii", "replace")
    return user_id.rstrip("\0").strip() == "copc"


def _drop_copc_records(header) -> None:
    """Remove the COPC records from ``header`` (its VLRs and EVLRs), keep every other.

    A COPC file (``.copc.laz``) is a LAZ 1.4 file whose points are stored in octree
    order, one LAZ chunk per octree node, described by a ``copc`` info VLR and a
    ``copc`` hierarchy EVLR. A copy with new classes (or a subset of the points) is
    written as a plain LAS/LAZ, where those records would describe chunks that no
    longer exist (and laspy cannot write them); every other VLR and EVLR — CRS,
    extra-bytes descriptions, user records — is kept.
    """
    for records in (header.vlrs, getattr(header, "evlrs", None) or []):
        records[:] = [v for v in records if not is_copc_record(v)]   # in place, in order


def write_las(dst, x, y, z, *, dimensions: Optional[Mapping[str, np.ndarray]] = None,
              crs: Optional[str] = None, point_format: int = 6, version: str = "1.4",
              scale: float = 0.01, extra_dims: Optional[Mapping[str, str]] = None) -> int:
    """Write a new LAS/LAZ file from coordinate arrays.

    Parameters
    ----------
    dst : path-like
        Output path; .laz is compressed.
    x, y, z : array_like
        Coordinates in CRS units.
    dimensions : mapping, optional
        Standard or extra dimension values (e.g. ``classification``,
        ``return_number``, ``intensity``).
    crs : str, optional
        Anything GDAL's ``SetFromUserInput`` accepts ('EPSG:32632', WKT). Stored as
        an OGC WKT VLR (LAS 1.4) or a GeoTIFF key VLR with the EPSG code (LAS < 1.4).
    extra_dims : mapping of name to numpy type name, optional
        Extra-bytes dimensions to declare, e.g. ``{"height_above_ground": "f4"}``.
    """
    laspy = _laspy()
    check_las_name(dst)
    x, y, z = (np.asarray(v, dtype=np.float64) for v in (x, y, z))
    if not (x.shape == y.shape == z.shape) or x.ndim != 1:
        raise InputError("x, y and z must be 1-D arrays of equal length.")
    header = laspy.LasHeader(point_format=point_format, version=version)
    for name, dtype in (extra_dims or {}).items():
        header.add_extra_dim(laspy.ExtraBytesParams(name=name, type=np.dtype(dtype)))
    header.scales = np.array([scale, scale, scale])
    if x.size:
        header.offsets = np.floor(np.array([x.min(), y.min(), z.min()]))
    if crs:
        _add_crs(header, crs)
    record = laspy.ScaleAwarePointRecord.zeros(x.size, header=header)
    record.x, record.y, record.z = x, y, z
    for name, values in (dimensions or {}).items():
        record[name] = values
    dst = os.fspath(dst)
    with atomic_output(dst) as tmp:
        with laspy.open(tmp, mode="w", header=header,
                        do_compress=dst.lower().endswith(".laz")) as writer:
            writer.write_points(record)
    return int(x.size)


def _add_crs(header, crs: str) -> None:
    laspy = _laspy()
    srs = spatial_reference(crs)
    if header.version.minor >= 4:
        header.vlrs.append(laspy.vlrs.known.WktCoordinateSystemVlr(srs.ExportToWkt()))
        header.global_encoding.wkt = True
        return
    srs.AutoIdentifyEPSG()
    code = srs.GetAuthorityCode(None)
    if not code:
        raise InputError("CRS {crs} has no EPSG code; LAS < 1.4 can only store "
                         "EPSG codes here. Use version 1.4.", crs=repr(crs))
    key_id = 3072 if srs.IsProjected() else 2048
    vlr = laspy.vlrs.known.GeoKeyDirectoryVlr()
    entries = [(1, 1, 0, 3), (1024, 0, 1, 1 if srs.IsProjected() else 2),
               (1025, 0, 1, 1), (key_id, 0, 1, int(code))]
    keys = []
    for kid, loc, count, value in entries:
        k = laspy.vlrs.geotiff.GeoKeyEntryStruct()
        k.id, k.tiff_tag_location, k.count, k.value_offset = kid, loc, count, value
        keys.append(k)
    vlr.geo_keys_header = keys[0]
    vlr.geo_keys_header.number_of_keys = len(keys) - 1
    vlr.geo_keys = keys[1:]
    header.vlrs.append(vlr)

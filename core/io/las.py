"""LAS/LAZ reading and writing on laspy + lazrs.

* :func:`las_info` — header facts (count, bounds, format, CRS) without reading points;
* :func:`read_las` — x, y, z (float64, scaled) and any other dimension asked for;
* :func:`iter_las_chunks` — the same, chunk by chunk, for files larger than memory;
* :func:`write_las_like` — a copy of an input with some dimensions replaced (e.g. a
  new classification) and optionally only a subset of points, preserving every
  other attribute bit for bit, the point format, version, scales/offsets, VLRs,
  EVLRs and CRS; written under a temporary name and renamed on success;
* :func:`write_las` — a new file from arrays (synthetic/demo data).

Every reader validates its input first (:func:`check_las_file`) and raises a
``ValueError`` naming the problem and the fix: missing file, not a LAS file, LAZ
without a decompression backend, unsupported version, empty cloud.
"""
from __future__ import annotations

import os
import warnings
from dataclasses import dataclass, field
from typing import Dict, Iterator, Mapping, Optional, Sequence, Tuple

import numpy as np

from ..errors import InputError
from ..progress import Monitor
from .contract import atomic_output, check_not_input
from .crs import spatial_reference
from .units import METRIC, Units, header_units

DEFAULT_CHUNK = 2_000_000
#: LAS versions laspy reads (1.0 is not among them: refused up front, with the fix).
_SUPPORTED_VERSIONS = {(1, 1), (1, 2), (1, 3), (1, 4)}
#: Bytes of a VLR header / an EVLR header (LAS 1.4 R15, 2.5 and 2.6).
_VLR_HEADER, _EVLR_HEADER = 54, 60


def _laspy():
    try:
        with warnings.catch_warnings():
            # laspy imports pyproj, which warns when its own PROJ data folder is
            # missing (Debian's pyproj); we never use pyproj for CRS handling.
            warnings.filterwarnings("ignore", message="Valid PROJ data directory",
                                    category=UserWarning)
            import laspy
    except ImportError as exc:  # pragma: no cover - install problem
        raise InputError("The Python package 'laspy' is not installed; install "
                         "laspy and lazrs (pip install laspy lazrs).") from exc
    return laspy


@dataclass
class LasInfo:
    """Header facts of a LAS/LAZ file."""

    path: str
    version: str
    point_format: int
    count: int
    scales: Tuple[float, float, float]
    offsets: Tuple[float, float, float]
    mins: Tuple[float, float, float]
    maxs: Tuple[float, float, float]
    compressed: bool
    crs: Optional[str]
    dimensions: Tuple[str, ...]
    n_vlrs: int
    #: Scalar extra-bytes dimensions as ``(name, numpy type string)``, e.g. ``("hag", "<f4")``.
    extra_dims: Tuple[Tuple[str, str], ...] = ()
    #: Horizontal and vertical linear units (:func:`~.units.header_units`); metres when
    #: the file has no CRS.
    units: Units = METRIC


@dataclass
class PointData:
    """Coordinates and requested dimensions of (a chunk of) a point cloud."""

    x: np.ndarray
    y: np.ndarray
    z: np.ndarray
    dims: Dict[str, np.ndarray] = field(default_factory=dict)
    info: Optional[LasInfo] = None
    #: the decoded point records, chunk by chunk (``read_las(keep_records=True)``): a
    #: copy of the file is written from them without decoding it again
    records: Optional[list] = field(default=None, repr=False)

    def __len__(self) -> int:
        """Return the number of points."""
        return int(self.x.size)

    def __getitem__(self, name: str) -> np.ndarray:
        """Return the extra dimension ``name`` (e.g. ``'classification'``)."""
        return self.dims[name]


def check_las_file(path) -> None:
    """Validate that ``path`` is an existing, readable LAS/LAZ file.

    Raises
    ------
    ValueError
        Missing file, a directory, not a LAS file (no ``LASF`` signature),
        LAZ with no decompression backend, or an unsupported LAS version.
    """
    if path is None or str(path) == "":
        raise InputError("No point cloud file was given; choose a .las or .laz file.")
    path = os.fspath(path)
    if not os.path.exists(path):
        raise InputError("Point cloud file not found: {path}. Check the path.", path=path)
    if os.path.isdir(path):
        raise InputError("{path} is a folder; choose a .las or .laz file.", path=path)
    with open(path, "rb") as fh:
        head = fh.read(375)
        size = os.fstat(fh.fileno()).st_size
    if len(head) < 27 or head[:4] != b"LASF":
        raise InputError(
            "{path} is not a LAS/LAZ file (it does not start with the 'LASF' "
            "signature). Choose a real .las or .laz file; convert other formats "
            "first, e.g. with PDAL (pdal translate).", path=path)
    version = (head[24], head[25])
    if version not in _SUPPORTED_VERSIONS:
        raise InputError(
            "{path} declares LAS version {version}, which this toolbox cannot read (LAS "
            "1.1 to 1.4 can be read). Convert it first, e.g. 'pdal translate in.las "
            "out.las --writers.las.minor_version=2' or 'las2las -i in.las -o out.las "
            "-set_version 1.2'.", path=path, version=f"{version[0]}.{version[1]}")
    check_header_sizes(path, head, size)
    if path.lower().endswith(".laz"):
        laspy = _laspy()
        if not laspy.LazBackend.detect_available():
            raise InputError(
                "{path} is compressed (LAZ) but no LAZ backend is installed: "
                "install the Python package 'lazrs' (pip install lazrs).", path=path)


def check_header_sizes(path, head: bytes, size: int) -> None:
    """Refuse a header whose sizes and counts cannot be true for a file of ``size`` bytes.

    Checked before laspy reads anything (a header claiming a billion VLRs made laspy
    allocate gigabytes): the header size, the offset to the point data, the VLRs
    (count × 54 bytes and each VLR's length must fit between the header and the point
    data — each VLR header is read, a few bytes each), the EVLRs (LAS 1.4) and, for an
    uncompressed file, the point records (count × record length).

    Raises
    ------
    InputError
        Naming the file, the field that lies and what to do.
    """
    import struct
    if len(head) < 227:
        raise InputError("{path} is truncated: its LAS header is incomplete ({n} of at "
                         "least 227 bytes). Re-export or re-download the file.",
                         path=path, n=len(head))
    header_size, offset, n_vlrs = struct.unpack_from("<HII", head, 94)
    fmt, rec_len, legacy_count = struct.unpack_from("<BHI", head, 104)
    fmt &= 0x3F                     # LAZ sets bit 7 (and 6) of the format
    if header_size < 227 or header_size > size or offset < header_size or offset > size:
        raise InputError(
            "{path} has an impossible LAS header: header size {hs} bytes and point data "
            "at byte {off}, in a file of {size} bytes. The file is damaged or was not "
            "written to the LAS specification; re-export it (e.g. pdal translate).",
            path=path, hs=header_size, off=offset, size=size)
    room = offset - header_size
    if n_vlrs * _VLR_HEADER > room:
        raise InputError(
            "{path} claims {n} variable-length records (VLRs), which cannot fit in the "
            "{room} bytes between its header and its point data. The header is damaged; "
            "repair or re-export the file (e.g. 'pdal translate' or 'lasinfo -repair').",
            path=path, n=f"{n_vlrs:,}", room=f"{room:,}")
    with open(path, "rb") as fh:
        pos = header_size
        for k in range(n_vlrs):
            fh.seek(pos + 20)
            raw = fh.read(2)
            length = struct.unpack("<H", raw)[0] if len(raw) == 2 else 0
            pos += _VLR_HEADER + length
            if len(raw) < 2 or pos > offset:
                raise InputError(
                    "{path}: its variable-length record {k} of {n} runs past the start of "
                    "the point data (byte {off}). The header is damaged; repair or "
                    "re-export the file (e.g. 'pdal translate' or 'lasinfo -repair').",
                    path=path, k=k + 1, n=n_vlrs, off=offset)
    count = legacy_count
    minor = head[25]
    if minor >= 4 and len(head) >= 255:
        start_evlr, n_evlrs, count64 = struct.unpack_from("<QIQ", head, 235)
        count = count64 or legacy_count
        if n_evlrs and (start_evlr < offset or start_evlr + n_evlrs * _EVLR_HEADER > size):
            raise InputError(
                "{path} claims {n} extended VLRs from byte {start}, which do not fit in "
                "its {size} bytes. The file is truncated or its header damaged; re-export "
                "or re-download it.", path=path, n=f"{n_evlrs:,}", start=start_evlr,
                size=size)
    if head[104] & 0xC0:       # LAZ: the chunk table offset opens the point data
        with open(path, "rb") as fh:
            fh.seek(offset)
            raw = fh.read(8)
        table = struct.unpack("<q", raw)[0] if len(raw) == 8 else -2
        if table != -1 and not offset + 8 <= table <= size - 8:
            raise InputError(
                "{path} is truncated: its compressed points end before their chunk table "
                "(byte {table} of a {size}-byte file). Re-export or re-download the file.",
                path=path, table=f"{table:,}", size=f"{size:,}")
    elif rec_len and fmt <= 10:
        need = offset + count * rec_len
        if need > size:
            raise InputError(
                "{path} is truncated: its header declares {count} points of {rec} bytes "
                "({need} bytes with the header) but the file has {size} bytes. Re-export "
                "or re-download the file.", path=path, count=f"{count:,}", rec=rec_len,
                need=f"{need:,}", size=f"{size:,}")


def crs_of_header(header) -> Optional[str]:
    """CRS of a LAS header as a string GDAL understands (WKT or 'EPSG:n'), or None."""
    laspy = _laspy()
    for vlr in list(header.vlrs) + list(getattr(header, "evlrs", None) or []):
        if isinstance(vlr, laspy.vlrs.known.WktCoordinateSystemVlr):
            text = vlr.string.strip("\x00 ") if isinstance(vlr.string, str) else ""
            if text:
                return text
    for vlr in header.vlrs:
        if isinstance(vlr, laspy.vlrs.known.GeoKeyDirectoryVlr):
            keys = {k.id: k for k in vlr.geo_keys}
            for key_id in (3072, 2048):  # ProjectedCSTypeGeoKey, GeographicTypeGeoKey
                key = keys.get(key_id)
                if key is not None and key.tiff_tag_location == 0 and 0 < key.value_offset < 32767:
                    return f"EPSG:{key.value_offset}"
    return None


def _units_of_header(header, crs) -> Units:
    try:
        return header_units(header, crs)
    except ValueError:      # an unparsable CRS is refused where the CRS is used
        return METRIC


def _info_from_header(path: str, header) -> LasInfo:
    crs = crs_of_header(header)
    return LasInfo(
        path=path,
        version=str(header.version),
        point_format=int(header.point_format.id),
        count=int(header.point_count),
        scales=tuple(float(v) for v in header.scales),
        offsets=tuple(float(v) for v in header.offsets),
        mins=tuple(float(v) for v in header.mins),
        maxs=tuple(float(v) for v in header.maxs),
        compressed=path.lower().endswith(".laz"),
        crs=crs,
        dimensions=tuple(header.point_format.dimension_names),
        n_vlrs=len(header.vlrs),
        extra_dims=tuple((d.name, d.dtype.str) for d in header.point_format.extra_dimensions
                         if d.num_elements == 1),
        units=_units_of_header(header, crs),
    )


def _open(path):
    laspy = _laspy()
    check_las_file(path)
    try:
        return laspy.open(os.fspath(path))
    except Exception as exc:  # laspy raises several types for broken files
        raise InputError(
            "Cannot read {path} as LAS/LAZ ({error}). The file is damaged or was not "
            "written to the LAS specification; re-export it (e.g. 'pdal translate') or "
            "download it again.", path=os.fspath(path),
            error=f"{type(exc).__name__}: {exc}"[:300]) from exc


def las_info(path) -> LasInfo:
    """Header facts of ``path`` without reading the points."""
    with _open(path) as reader:
        return _info_from_header(os.fspath(path), reader.header)


def _chunks(reader, path, chunk_size: int):
    """``reader.chunk_iterator`` that turns decoding failures into a clear ValueError."""
    it = reader.chunk_iterator(chunk_size)
    while True:
        try:
            chunk = next(it)
        except StopIteration:
            return
        except Exception as exc:  # numpy buffer errors, lazrs.LazrsError, ...
            raise InputError(
                "{path} is truncated or corrupt: its point data cannot be decoded "
                "({error}). Re-export or re-download the file.", path=os.fspath(path),
                error=f"{type(exc).__name__}: {exc}"[:300]) from exc
        yield chunk


def _check_dims(info: LasInfo, names: Sequence[str]) -> None:
    missing = [n for n in names if n not in info.dimensions]
    if missing:
        raise InputError("{path} has no dimension(s) {missing}; it has {present}.",
                         path=info.path, missing=", ".join(missing),
                         present=", ".join(info.dimensions))


def _extract(points, names: Sequence[str]) -> PointData:
    return PointData(
        x=np.asarray(points.x, dtype=np.float64),
        y=np.asarray(points.y, dtype=np.float64),
        z=np.asarray(points.z, dtype=np.float64),
        dims={n: np.array(points[n]) for n in names},
    )


def iter_las_chunks(path, dimensions: Sequence[str] = (), *,
                    chunk_size: int = DEFAULT_CHUNK,
                    allow_empty: bool = False) -> Iterator[Tuple[int, PointData]]:
    """Yield ``(start_index, PointData)`` chunks of at most ``chunk_size`` points.

    Memory use is bounded by the chunk, so files larger than memory can be
    streamed (e.g. to compute a raster or statistics).
    """
    if chunk_size <= 0:
        raise InputError("chunk_size must be positive, got {value}.", value=chunk_size)
    with _open(path) as reader:
        info = _info_from_header(os.fspath(path), reader.header)
        _check_dims(info, dimensions)
        if info.count == 0 and not allow_empty:
            raise InputError("{path} holds no points (empty point cloud).", path=path)
        start = 0
        for chunk in _chunks(reader, path, chunk_size):
            data = _extract(chunk, dimensions)
            data.info = info
            yield start, data
            start += len(data)


class _Records(list):
    """Decoded point records of a file, chunk by chunk, with the file's EVLRs."""

    evlrs: list = []


def read_las(path, dimensions: Sequence[str] = (), *, chunk_size: int = DEFAULT_CHUNK,
             keep_records: bool = False, progress=None, cancel=None) -> PointData:
    """Read coordinates and the named dimensions of a LAS/LAZ file.

    Parameters
    ----------
    path : str or path-like
        A .las or .laz file (LAS 1.1–1.4; 1.0 is refused with the fix).
    dimensions : sequence of str
        laspy dimension names to read besides x, y, z, e.g.
        ``("classification", "return_number", "number_of_returns")``.
    chunk_size : int
        Points decoded per chunk (bounds the temporary memory).
    keep_records : bool
        Keep the decoded point records (``PointData.records``) so that
        :func:`write_las_like` can write a copy without decoding the file again
        (about the file's uncompressed size in memory).
    progress, cancel : callable, optional
        See :class:`~.progress.Monitor`.

    Returns
    -------
    PointData
        ``x, y, z`` as scaled float64 coordinates, ``dims`` with the requested
        dimensions in their LAS dtype, ``info`` with the header facts.

    Raises
    ------
    ValueError
        Invalid file (see :func:`check_las_file`), empty cloud, or a requested
        dimension the file does not have.
    """
    mon = Monitor(progress, cancel)
    info = las_info(path)
    _check_dims(info, dimensions)
    if info.count == 0:
        raise InputError("{path} holds no points (empty point cloud).", path=path)
    n = info.count
    x = np.empty(n, np.float64)
    y = np.empty(n, np.float64)
    z = np.empty(n, np.float64)
    dims: Dict[str, np.ndarray] = {}
    records = _Records() if keep_records else None
    filled = 0
    with _open(path) as reader:
        for raw in _chunks(reader, path, chunk_size):
            mon.check()
            chunk = _extract(raw, dimensions)
            start, stop = filled, filled + len(chunk)
            if stop > n:
                break
            x[start:stop], y[start:stop], z[start:stop] = chunk.x, chunk.y, chunk.z
            for name, values in chunk.dims.items():
                if name not in dims:
                    dims[name] = np.empty(n, values.dtype)
                dims[name][start:stop] = values
            if records is not None:
                records.append(raw)
            filled = stop
            mon.update(stop / n)
        if records is not None:      # read after the points (LAZ): keep them for copies
            records.evlrs = list(getattr(reader.header, "evlrs", None) or [])
    if filled != n:
        raise InputError("{path} declares {n} points but holds {filled}; the file "
                         "is truncated or corrupt.", path=path, n=n, filled=filled)
    return PointData(x, y, z, dims, info, records)


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
                          else _chunks(reader, src, chunk_size)):
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

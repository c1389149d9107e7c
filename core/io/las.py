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
from typing import Dict, Iterator, Optional, Sequence, Tuple

import numpy as np

from ..errors import InputError
from ..progress import Monitor
from .units import METRIC, Units, header_units

DEFAULT_CHUNK = 2_000_000

#: File name endings of LAS/LAZ files (the one list: readers, catalogs, output checks).
LAS_SUFFIXES = (".las", ".laz")
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


def _scaled_into(view, out: np.ndarray) -> None:
    """Write laspy's scaled coordinates ``view`` into ``out`` without a temporary.

    Same arithmetic as laspy (``X * scale + offset`` in float64), hence the same bits.
    """
    raw, scale, offset = (getattr(view, a, None) for a in ("array", "scale", "offset"))
    if isinstance(raw, np.ndarray) and np.ndim(scale) == 0 and np.ndim(offset) == 0:
        np.multiply(raw, scale, out=out)
        np.add(out, offset, out=out)
    else:                                       # another laspy: its own arithmetic
        out[:] = np.asarray(view, dtype=np.float64)


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
            start, stop = filled, filled + len(raw)
            if stop > n:
                break
            for view, out in ((raw.x, x), (raw.y, y), (raw.z, z)):
                _scaled_into(view, out[start:stop])
            for name in dimensions:
                values = np.asarray(raw[name])
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


_WRITERS = ("write_las_like", "write_las", "is_copc_record")


def __getattr__(name):
    """Return a writer of :mod:`._las_write` (imported when first asked for)."""
    if name in _WRITERS:
        from . import _las_write
        return getattr(_las_write, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

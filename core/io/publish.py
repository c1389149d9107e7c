"""Publish finished temporary files to their final paths under one output contract.

The last step of a chain whose steps wrote temporaries (the shipped Processing model
``geomatics:lidar_to_dtm``): every file is copied (or converted when the destination
asks for another format) to its contract temporary, and all are renamed only when all
succeeded, so a chain whose last step fails leaves nothing at any destination.

Examples
--------
>>> publish_files({"DTM": ("/tmp/q/dtm.tif", "out/dtm.tif", "raster")},
...               inputs={"INPUT": "cloud.laz"})   # doctest: +SKIP
{'DTM': 'out/dtm.tif'}
"""
from __future__ import annotations

import shutil
from pathlib import Path
from typing import Dict, Mapping, Optional, Tuple

from ..errors import InputError
from ..progress import Cancelled
from .contract import OutputContract
from .las import las_info, write_las_like
from .raster import _gdal, check_raster_file
from .vector import check_vector_file

#: kinds of published file and how a different destination format is produced
KINDS = ("file", "cloud", "raster", "vector")


def _convert(kind: str, src: str, dst: str) -> None:
    """Write ``src`` to ``dst`` in the format ``dst``'s extension asks for."""
    if kind == "cloud":
        write_las_like(src, dst)
    elif kind == "raster":
        _gdal().Translate(dst, src)
    elif kind == "vector":
        _gdal().VectorTranslate(dst, src)
    else:
        raise InputError(
            "Cannot publish {src} as {dst}: the extensions differ; choose a "
            "destination ending in {suffix}.",
            src=src,
            dst=dst,
            suffix=Path(src).suffix)


def _driver_for(kind: str, suffix: str) -> bool:
    """Return True when GDAL/OGR can tell the one driver for ``kind`` files ``*suffix``.

    As GDAL guesses the output driver: exactly one driver that creates such files
    (GTiff wins among several); ``.txt`` (no raster driver, two vector ones) fails.
    """
    gdal = _gdal()
    ext = suffix.lower().lstrip(".")
    cap = gdal.DCAP_RASTER if kind == "raster" else gdal.DCAP_VECTOR
    found = []
    for i in range(gdal.GetDriverCount()):
        drv = gdal.GetDriver(i)
        md = drv.GetMetadata() or {}
        if md.get(cap) != "YES" or not (md.get(gdal.DCAP_CREATE) == "YES"
                                         or md.get(gdal.DCAP_CREATECOPY) == "YES"):
            continue
        if ext in (md.get(gdal.DMD_EXTENSIONS) or md.get(gdal.DMD_EXTENSION) or "").split():
            found.append(drv.ShortName)
    return len(found) == 1 or "GTiff" in found


def check_destination(kind: str, src: str, dst: str) -> None:
    """Refuse, before anything is written, a destination that cannot hold ``kind``.

    A point cloud must go to .las/.laz; a raster or vector to an extension a GDAL/OGR
    driver writes (``.txt`` is neither); a plain file keeps its extension.
    """
    suffix = Path(dst).suffix.lower()
    if kind == "cloud":
        ok = suffix in (".las", ".laz")
        wanted = ".las or .laz"
    elif kind in ("raster", "vector"):
        ok = suffix == Path(src).suffix.lower() or (suffix and _driver_for(kind, suffix))
        wanted = ".tif" if kind == "raster" else ".gpkg"
    else:
        ok = suffix == Path(src).suffix.lower()
        wanted = Path(src).suffix
    if not ok:
        raise InputError("The {kind} output cannot be written as {dst} ({suffix} is not a "
                         "{kind} format); choose a destination ending in {wanted}.",
                         kind=kind, dst=dst, suffix=suffix or "no extension",
                         wanted=wanted)


def check_source(kind: str, src: str) -> None:
    """Refuse, before anything is written, a file to publish that is not its kind.

    A zero-byte or garbled temporary (an earlier step killed half-way, a wrong file
    wired into the model) would otherwise be copied to the destination as a result.
    """
    if not Path(src).is_file():
        raise InputError("The file to publish {src} does not exist; the step that "
                         "should have written it failed or was skipped.", src=src)
    if kind == "cloud":
        if las_info(src).count == 0:        # las_info: not LAS, truncated, lying header
            raise InputError("{path} holds no points (empty point cloud).", path=src)
    elif kind == "raster":
        check_raster_file(src)
    elif kind == "vector":
        check_vector_file(src)


def publish_file(kind: str, src: str, dst: str) -> None:
    """Copy ``src`` to ``dst`` (a contract temporary), converting when needed."""
    if kind not in KINDS:
        raise InputError("Unknown output kind {kind}; expected one of {kinds}.",
                         kind=repr(kind), kinds=", ".join(KINDS))
    if not Path(src).is_file():
        raise InputError("The file to publish {src} does not exist; the step that "
                         "should have written it failed or was skipped.", src=src)
    if Path(src).suffix.lower() == Path(dst).suffix.lower():
        shutil.copyfile(src, dst)
    else:
        _convert(kind, src, dst)


def publish_files(files: Mapping[str, Tuple[str, Optional[str], str]], *,
                  inputs: Mapping[str, object] = (), cancel=None) -> Dict[str, str]:
    """Publish temporaries to their destinations: all of them or none.

    The commit step of a chain run as separate steps (the shipped model's ground
    filter → IDW DTM → DTM accuracy): destinations are checked before any copy.

    Parameters
    ----------
    files : mapping of str to (source, destination, kind)
        Output name -> temporary written by an earlier step, final path (``None`` or
        empty: not requested) and kind (``file``, ``cloud``, ``raster``, ``vector``).
    inputs : mapping of str to path(s)
        Every file the chain read: no destination may be one of them.
    cancel : callable, optional
        Returns True when the user cancelled (checked between files).

    Returns
    -------
    dict
        Output name -> final path of each published file.

    Raises
    ------
    InputError
        A destination is an input, a source or another destination, its folder cannot
        be written, or a source is missing or not its kind (a raster GDAL cannot
        open, a cloud that is not LAS/LAZ or holds no points, an unreadable vector
        file); nothing is left at any destination.
    """
    wanted = {k: v for k, v in files.items() if v[1] not in (None, "")}
    for src, dst, kind in wanted.values():
        if kind in KINDS:
            check_destination(kind, src, dst)
            check_source(kind, src)
    sources = {f"{k} (temporary)": v[0] for k, v in wanted.items()}
    with OutputContract({k: v[1] for k, v in wanted.items()},
                        inputs={**dict(inputs), **sources}) as out:
        # the earlier steps' reports name the temporaries they read: name the
        # published files instead ("input OUTPUT.laz" -> "input classified.laz")
        names = {src: out.final(k) for k, (src, _d, kind) in wanted.items()
                 if kind != "file"}
        for name, (src, _dst, kind) in wanted.items():
            if cancel is not None and cancel():
                raise Cancelled()
            publish_file(kind, src, out.path(name))
            if kind == "file" and Path(src).suffix.lower() in (".html", ".htm"):
                relabel_html(out.path(name), names)
        return {k: out.final(k) for k in wanted}


def relabel_html(path: str, names: Mapping[str, str]) -> None:
    """Name the published files in the HTML file ``path``.

    Each temporary's path, then its file name, is replaced by those of its published
    file (``names``: temporary path -> final path).
    """
    import html as _html
    text = Path(path).read_text(encoding="utf-8")
    pairs = sorted(names.items(), key=lambda kv: -len(kv[0]))
    for old, new in pairs + [(Path(o).name, Path(n).name) for o, n in pairs]:
        for a, b in ((old, new), (_html.escape(old), _html.escape(new))):
            text = text.replace(a, b)
    Path(path).write_text(text, encoding="utf-8")

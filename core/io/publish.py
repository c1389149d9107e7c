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
from .las import write_las_like
from .raster import _gdal

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


def publish_file(kind: str, src: str, dst: str) -> None:
    """Copy ``src`` to ``dst`` (a contract temporary), converting when needed."""
    if kind not in KINDS:
        raise ValueError(f"unknown kind {kind!r}; expected one of {KINDS}")
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
        be written, or a source is missing; nothing is left at any destination.
    """
    wanted = {k: v for k, v in files.items() if v[1] not in (None, "")}
    sources = {f"{k} (temporary)": v[0] for k, v in wanted.items()}
    with OutputContract({k: v[1] for k, v in wanted.items()},
                        inputs={**dict(inputs), **sources}) as out:
        for name, (src, _dst, kind) in wanted.items():
            if cancel is not None and cancel():
                raise Cancelled()
            publish_file(kind, src, out.path(name))
        return {k: out.final(k) for k in wanted}

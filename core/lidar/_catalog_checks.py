"""Up-front validation of a tile catalog (private; used by :mod:`.catalog`).

Everything a catalog run can know is wrong before any worker starts or any file is
made: unreadable, empty, duplicated or degree tiles, tiles in different CRSs or units,
absurd parameters and chunk plans, an output folder holding the tiles or another run's
results, a malformed or unreachable scheduler. Each refusal is a translated
:class:`~..errors.InputError` naming the problem and the fix.
"""
from __future__ import annotations

import math
import os
from pathlib import Path
from typing import TYPE_CHECKING, Dict, List, Sequence

import numpy as np

from ..coords import REPROJECT_HINT, crs_is_geographic
from ..errors import InputError
from ..io.crs import crs_label, same_crs
from ..io.las import LasInfo
from ..reporting.content import T
from ..terrain.grid import check_grid_size
from ._chunks import DTM_METHODS, GROUND_FILTERS

if TYPE_CHECKING:  # pragma: no cover
    from .catalog import Catalog

#: Folder of a run's state (done markers, settings) inside the output folder.
STATE_DIR = ".catalog"


def check_index(infos: List[LasInfo], unreadable: Dict[str, Exception],
                skip_unreadable: bool, empty: Sequence[str] = ()) -> None:
    """Refuse unreadable (unless skipped), mixed-CRS, degree or duplicated tiles.

    ``infos``: the tiles with points; ``empty``: those without (left out), refused
    only when no tile has a point.
    """
    if unreadable and (not skip_unreadable or not infos):
        listing = [T("{tile}: {reason}", tile=os.path.basename(p), reason=r)
                   for p, r in list(unreadable.items())[:4]]
        raise InputError("{n} tile(s) cannot be read ({listing}). Repair or remove them, "
                         "or let the catalog skip unreadable tiles (SKIP_UNREADABLE; "
                         "their neighbours then get no buffer points from them).",
                         n=len(unreadable), listing=listing)
    if not infos:
        raise InputError("Every tile of the catalog is without points ({tiles}): there is "
                         "nothing to process. Check the tiles given (INPUT): an export "
                         "that failed, or the wrong folder.",
                         tiles=", ".join(os.path.basename(p) for p in list(empty)[:6]))
    _check_bounds(infos)
    groups = _crs_groups(infos)
    if len(groups) > 1:
        listing = "; ".join(f"{os.path.basename(g[0].path)}: {crs_label(g[0].crs) or 'none'}"
                            for g in groups[:6])
        raise InputError("The tiles are in {n_crs} different CRSs ({listing}); "
                         "reproject them to one CRS (e.g. pdal translate) first.",
                         n_crs=len(groups),
                         listing=listing)
    _check_tiles(infos)


#: the range of a LAS point record's scaled integer coordinate (int32), one unit of slack
_INT32 = (-2.0 ** 31 - 1.0, 2.0 ** 31)


def _check_bounds(infos: Sequence[LasInfo]) -> None:
    """Refuse tiles whose header bounds cannot be true, from the headers alone.

    The catalog places tiles, neighbours and chunks by these bounds: bounds left at zero
    (never filled in), inverted, or outside what the scaled int32 coordinates can hold
    (a damaged header) would put a tile kilometres away or plan an absurd grid.
    """
    for t in infos:
        if not any(t.mins) and not any(t.maxs):
            raise InputError("The header of {tile} declares its bounds as all zero (never "
                             "filled in); the catalog places tiles by them. Recompute them "
                             "(e.g. 'lasinfo -repair_bb' or 'pdal translate') or remove the "
                             "tile.", tile=os.path.basename(t.path))
        for axis, name in enumerate("xyz"):
            scale, offset = t.scales[axis], t.offsets[axis]
            lo, hi = t.mins[axis], t.maxs[axis]
            ok = scale > 0 and lo <= hi and all(
                math.isfinite(v) and _INT32[0] <= (v - offset) / scale <= _INT32[1]
                for v in (lo, hi))
            if not ok:
                raise InputError(
                    "The header of {tile} declares {axis} bounds {lo} to {hi}, which its "
                    "coordinates cannot hold (scale {scale}, offset {offset}): the header is "
                    "damaged, and the catalog places tiles by it. Recompute the bounds "
                    "(e.g. 'lasinfo -repair_bb' or 'pdal translate') or remove the tile.",
                    tile=os.path.basename(t.path), axis=name, lo=f"{lo:.10g}",
                    hi=f"{hi:.10g}", scale=f"{scale:g}", offset=f"{offset:.10g}")


def _crs_groups(infos: Sequence[LasInfo]) -> List[List[LasInfo]]:
    """Tiles grouped by CRS meaning (PROJ equivalence), not by text.

    A LAS 1.4 tile's WKT and a LAS 1.2 tile's GeoTIFF keys of the same EPSG:32632 are
    one CRS; the vertical units (GeoKeys / compound CRS) must agree too.
    """
    groups: List[List[LasInfo]] = []
    for t in infos:
        for g in groups:
            if (g[0].crs == t.crs or same_crs(g[0].crs, t.crs)) and g[0].units == t.units:
                g.append(t)
                break
        else:
            groups.append([t])
    return groups


def _check_tiles(infos: Sequence[LasInfo]) -> None:
    """Refuse tiles in degrees, and duplicated tiles, from the headers."""
    t = infos[0]
    if crs_is_geographic(t.crs):
        raise InputError("The tiles ({tile}, ...) are in a geographic CRS (longitude/"
                         "latitude in degrees); tiles, buffers and cells need metres. "
                         "{hint}", tile=os.path.basename(t.path), hint=REPROJECT_HINT)
    seen: Dict[tuple, str] = {}
    dups = []
    for info in infos:
        key = (info.count, tuple(round(v, 6) for v in (*info.mins, *info.maxs)))
        if key in seen:
            dups.append(f"{os.path.basename(seen[key])} = {os.path.basename(info.path)}")
        else:
            seen[key] = info.path
    if dups:
        raise InputError("Duplicated tiles (same number of points and same extent): {pairs}. "
                         "Their points would be counted twice; remove the copies from the "
                         "catalog.", pairs="; ".join(dups[:5]))


def _check_folder(cat: Catalog, folder: Path) -> None:
    root = folder.resolve()
    inside = [p for p in cat.paths if root in Path(p).resolve().parents]
    if inside:
        raise InputError("The output folder {folder} contains input tiles "
                         "({tile}, ...); choose another folder.",
                         folder=folder,
                         tile=os.path.basename(inside[0]))
    stems = [Path(p).stem for p in cat.paths]
    if len(set(stems)) != len(stems):
        raise InputError("Two tiles have the same file name; their outputs would collide. "
                         "Rename them.")


def _check_params(ground_filter, dtm_method, cell_size, buffer, chunk_size) -> None:
    if ground_filter not in GROUND_FILTERS:
        raise InputError("Unknown ground filter {ground_filter!r}; choose one of "
                         "{choices}.",
                         ground_filter=ground_filter,
                         choices=', '.join(GROUND_FILTERS))
    if dtm_method not in DTM_METHODS:
        raise InputError("Unknown DTM method {dtm_method!r}; choose one of "
                         "{choices}.",
                         dtm_method=dtm_method,
                         choices=', '.join(DTM_METHODS))
    if not (cell_size > 0 and math.isfinite(cell_size)):
        raise InputError("CELL_SIZE must be > 0 metres (e.g. 1), got {cell_size}.",
                         cell_size=cell_size)
    if not (buffer >= 0 and math.isfinite(buffer)):
        raise InputError("BUFFER must be >= 0 metres (e.g. 100), got {buffer}.", buffer=buffer)
    if not (chunk_size >= 0 and math.isfinite(chunk_size)):
        raise InputError("CHUNK_SIZE must be >= 0 metres (0 = the tiles), got {chunk_size}.",
                         chunk_size=chunk_size)
    ratio = chunk_size / cell_size
    if chunk_size and (ratio < 1 or abs(ratio - round(ratio)) > 1e-6):
        raise InputError("CHUNK_SIZE ({chunk_size} m) must be a whole multiple of CELL_SIZE "
                         "({cell_size} m) so the chunk DTMs tile the mosaic exactly; e.g. "
                         "{example}.", chunk_size=f"{chunk_size:g}",
                         cell_size=f"{cell_size:g}",
                         example=f"{max(round(ratio), 1) * cell_size:g}")


#: Most chunks a catalog run plans (the scheduler keeps one task each).
MAX_CHUNKS = 10_000
#: Most points one chunk (with its buffer) may hold in a worker's memory (about 60 B
#: per point for coordinates, classes and the filter's arrays: 12 GB).
MAX_CHUNK_POINTS = 200_000_000


def _check_chunks(cat: Catalog, chunk_size: float, cell_size: float, buffer: float,
                  origin, *, h: float = 1.0) -> None:
    """Refuse a plan with too many chunks, or chunks too big for a worker, up front.

    Lengths in the tiles' units; ``h`` metres per unit (the messages speak metres).
    """
    e = cat.extent
    if chunk_size:
        ox, oy = origin
        nx = math.floor((e[2] - ox) / chunk_size) - math.floor((e[0] - ox) / chunk_size) + 1
        ny = math.floor((e[3] - oy) / chunk_size) - math.floor((e[1] - oy) / chunk_size) + 1
        if nx * ny > MAX_CHUNKS:
            raise InputError(
                "CHUNK_SIZE {chunk_size} m cuts the catalog ({w} × {h} m) into up to {n} "
                "chunks, more than {limit}; each chunk costs scheduling and reading "
                "overhead. Use CHUNK_SIZE 0 (one chunk per tile) or at least {fit} m.",
                chunk_size=f"{chunk_size * h:g}", w=f"{(e[2] - e[0]) * h:.0f}",
                h=f"{(e[3] - e[1]) * h:.0f}", n=f"{nx * ny:,}", limit=f"{MAX_CHUNKS:,}",
                fit=f"{math.ceil(h * math.sqrt((e[2] - e[0]) * (e[3] - e[1]) / MAX_CHUNKS)):g}")
        side = chunk_size
        check_grid_size(math.ceil((side + 2 * buffer) / cell_size),
                        math.ceil((side + 2 * buffer) / cell_size), cell_size)
        boxes = [(e[0] - buffer, e[1] - buffer, e[0] + side + buffer, e[1] + side + buffer)]
    else:
        boxes = [(b[0] - buffer, b[1] - buffer, b[2] + buffer, b[3] + buffer)
                 for b in cat.bounds]
        for b in boxes:
            check_grid_size(math.ceil((b[2] - b[0]) / cell_size),
                            math.ceil((b[3] - b[1]) / cell_size), cell_size)
    worst = max(_overlap_points(cat, b) for b in boxes)
    if worst > MAX_CHUNK_POINTS:
        raise InputError(
            "A chunk with its buffer would hold about {n} points, more than the {limit} a "
            "worker can keep in memory. Use a smaller CHUNK_SIZE (or 0 for the tiles) or "
            "a smaller BUFFER.", n=f"{worst:,.0f}", limit=f"{MAX_CHUNK_POINTS:,}")


def check_scheduler(address: str, *, timeout: float = 5.0) -> None:
    """Refuse a malformed or unreachable Dask scheduler address before anything is made.

    Accepts ``tcp://host:port``, ``tls://host:port`` or ``host:port``.
    """
    import re
    import socket
    m = re.fullmatch(r"(?:(tcp|tls)://)?(\[[0-9a-fA-F:]+\]|[A-Za-z0-9_.\-]+):(\d{1,5})",
                     address.strip())
    if not m or not 0 < int(m.group(3)) < 65536:
        raise InputError("SCHEDULER {scheduler!r} is not a Dask scheduler address; give "
                         "tcp://host:port (e.g. tcp://10.0.0.5:8786) or leave it empty for "
                         "local workers.", scheduler=address)
    host, port = m.group(2).strip("[]"), int(m.group(3))
    try:
        with socket.create_connection((host, port), timeout=timeout):
            pass
    except OSError as exc:
        raise InputError("Cannot reach the Dask scheduler {scheduler} ({exc}); start "
                         "it with 'dask scheduler' or leave SCHEDULER empty.",
                         scheduler=address, exc=exc) from exc


SETTINGS_FILE = "settings.json"


def tile_signature(info: LasInfo) -> list:
    """Return what a resume compares of a tile: name, bytes, mtime (ns), points, bounds.

    A tile rewritten in place (re-classified, re-exported, re-tiled) changes its size
    or modification time even when its name, point count and bounds stay.
    """
    st = os.stat(info.path)
    return [os.path.basename(info.path), int(st.st_size), int(st.st_mtime_ns),
            int(info.count), *(float(v) for v in (*info.mins[:2], *info.maxs[:2]))]


def _tile_changes(old: Sequence, new: Sequence, finished: Sequence, whole: bool) -> List[T]:
    """Return the tiles added, removed or changed that a finished chunk read (a sentence each).

    A finished chunk read the tiles its buffered box touches (old or new bounds), and
    every tile when its filter derives values from all of them (``whole``: the first
    pass). A tile no finished chunk read (e.g. the damaged tile of a failed chunk,
    since repaired) may change: its chunks run again.
    """
    before = {t[0]: list(t) for t in old or () if isinstance(t, (list, tuple)) and t}
    after = {t[0]: list(t) for t in new}

    def read(name):
        boxes = [s[4:8] for s in (before.get(name), after.get(name)) if s and len(s) >= 8]
        return whole or not boxes or any(
            b[0] <= f[2] and b[2] >= f[0] and b[1] <= f[3] and b[3] >= f[1]
            for b in boxes for f in finished)
    out = [T("{tile}: changed", tile=n) for n in sorted(after)
           if n in before and before[n] != after[n] and read(n)]
    out += [T("{tile}: new", tile=n) for n in sorted(set(after) - set(before)) if read(n)]
    out += [T("{tile}: gone", tile=n) for n in sorted(set(before) - set(after)) if read(n)]
    return out


def _check_resume(folder: Path, settings: dict, tasks: Sequence = (),
                  whole: bool = True) -> None:
    """Refuse to resume into a folder whose finished chunks came from other settings or tiles.

    ``tasks``: the planned chunks (those finished are compared by their buffered boxes);
    ``whole``: the filter derives values from every tile (:func:`_tile_changes`). A folder
    without finished chunks holds nothing to mix: its earlier state is replaced (a stale
    first pass is recomputed: :func:`.catalog.pass_plan`).
    """
    from ._catalog_state import finished_chunks
    path = folder / STATE_DIR / SETTINGS_FILE
    done = set(finished_chunks(folder))
    if not path.exists() or not done:
        return
    import json
    try:
        old = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, ValueError):
        old = {}
    finished = [t.buffered_box() for t in tasks if t.key in done]
    changes = _tile_changes(old.get("tiles"), settings["tiles"], finished,
                            whole or not tasks)
    if changes:
        raise InputError(
            "The tiles changed since the earlier run into {folder} ({changes}); its finished "
            "chunks were made from the old tiles and resuming would mix them. Choose another "
            "output folder, or delete that folder's outputs and its .catalog folder to start "
            "again.", folder=folder, changes=changes[:6])
    diff = [f"{k}: {old.get(k)!r} → {v!r}" for k, v in settings.items()
            if k not in ("chunks", "tiles") and old.get(k) != v]
    if diff:
        raise InputError(
            "The output folder {folder} holds the results of an earlier run with other "
            "settings ({diff}); resuming would mix them. Choose another output folder, or "
            "delete that folder's outputs and its .catalog folder to start again.",
            folder=folder, diff="; ".join(diff[:6]))


def _overlap_points(cat: Catalog, box) -> float:
    """Points of the catalog expected in ``box`` (header counts x area share)."""
    b = cat.bounds
    w = np.clip(np.minimum(b[:, 2], box[2]) - np.maximum(b[:, 0], box[0]), 0, None)
    h = np.clip(np.minimum(b[:, 3], box[3]) - np.maximum(b[:, 1], box[1]), 0, None)
    area = np.maximum((b[:, 2] - b[:, 0]) * (b[:, 3] - b[:, 1]), 1e-9)
    counts = np.array([t.count for t in cat.tiles], float)
    return float(np.sum(counts * np.minimum(w * h / area, 1.0)))


def class_listing(counts: Dict[str, int], most: int = 4) -> str:
    """``'9: 41000, 7: 3'``: classes and counts, the most frequent first (data, no words).

    >>> class_listing({"2": 5, "9": 41000, "7": 3})
    '9: 41000, 2: 5, 7: 3'
    """
    ranked = sorted(counts.items(), key=lambda kv: (-kv[1], int(kv[0])))
    return ", ".join(f"{c}: {n}" for c, n in ranked[:most]) + (
        ", …" if len(ranked) > most else "")


def no_ground_error(chunks: Sequence[dict], n_tiles: int, n_points: int,
                    ground_filter: str) -> InputError:
    """Return the refusal of a catalog in which no tile has a ground point."""
    counts: Dict[str, int] = {}
    for c in chunks:
        for k, n in (c.get("classes") or {}).items():
            counts[k] = counts.get(k, 0) + int(n)
    fix = (T("The classes already in the files are kept (GROUND_FILTER) and none is ground "
             "(class 2): choose a ground filter (GROUND_FILTER) instead, or classify the "
             "tiles first.") if ground_filter == "keep" else
           T("Check that the tiles hold terrain (not only water, noise or vegetation) and "
             "are in the right units, or choose another ground filter (GROUND_FILTER)."))
    sparse = next((c for c in chunks if c.get("filter_error")), None)
    if sparse is not None:          # the filter could not run (too few points): say why
        why = sparse["filter_error"]
        fix = T("The ground filter cannot classify tile {tile}: {reason}", tile=sparse["key"],
                reason=T(why["template"], **why["fields"]))
    return InputError("No tile of the catalog has a ground point ({tiles} tiles, {points} "
                      "points, by class: {classes}): there is no terrain to make a DTM of. "
                      "{fix} Nothing was written.", tiles=n_tiles,
                      points=n_points, classes=class_listing(counts) or "-", fix=fix)


def empty_dtm_error(chunks: Sequence[dict]) -> InputError:
    """Return the refusal of a catalog with ground but no DTM cell with a value."""
    bad = next((c for c in chunks if c.get("dtm_error")), None)
    reason = (T(bad["dtm_error"]["template"], **bad["dtm_error"]["fields"]) if bad else
              T("the ground points are too few or too far apart for this DTM method and "
                "cell size."))
    return InputError("No tile's DTM has a cell with a value ({n} ground points in the "
                      "catalog): {reason} Choose another DTM method (DTM_METHOD, e.g. IDW) "
                      "or a ground filter that finds more ground. Nothing was written.",
                      n=sum(int(c.get("ground", 0)) for c in chunks), reason=reason)

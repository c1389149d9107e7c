"""Whole LiDAR projects: tile catalogs processed chunk by chunk with buffers, on Dask.

A :class:`Catalog` indexes LAS/LAZ tiles from their headers only (a folder, a glob, a
list or a PDAL/QGIS ``.vpc``), keeps the tile bounds as a spatial index and refuses
mixed CRSs. :func:`run_catalog` processes one chunk per tile: the tile plus the points
of its neighbours within ``buffer`` metres (streamed, never whole neighbours), the
ground filter, a DTM of the tile on the global cell lattice, the buffer dropped and the
outputs written per chunk (classified tile, DTM GeoTIFF, a done marker). This is the
LAScatalog scheme of lidR (Roussel et al. 2020, Remote Sens. Environ. 251:112061) and
LAStools' ``-buffered``; tiling-dependent methods (LSQ tiles, raster grids) are
anchored on a global origin so a catalog run equals a run on the merged cloud away
from the catalog's outer edge.

Engine: Dask ``distributed`` (Rocklin 2015, Proc. SciPy): a local cluster with one
single-threaded worker process per core, or an existing cluster given by its scheduler
address (``tcp://host:8786``; start one with ``dask scheduler`` and ``dask worker``).
A failed chunk is retried once and then reported; a rerun skips finished chunks
(resume); cancel stops scheduling, removes unfinished chunk outputs and keeps the
finished ones. Memory per worker is bounded by one buffered tile.
"""
from __future__ import annotations

import json
import math
import os
import time
from dataclasses import dataclass, field
from pathlib import Path
from typing import Dict, List, Optional, Sequence

import numpy as np

from ..errors import InputError
from ..io.catalog import build_vrt, find_tiles
from ..io.contract import OutputContract, check_paths, sigterm_raises
from ..io.las import LasInfo, las_info
from ..progress import Cancelled, Monitor  # noqa: F401 - callers catch catalog.Cancelled
from . import _canopy, _summary
from ._catalog_checks import (  # noqa: F401 - MAX_*, check_scheduler: public names
    MAX_CHUNK_POINTS,
    MAX_CHUNKS,
    SETTINGS_FILE,
    STATE_DIR,
    _check_chunks,
    _check_folder,
    _check_params,
    _check_resume,
    _overlap_points,
    check_index,
    check_scheduler,
    empty_dtm_error,
    no_ground_error,
    tile_signature,
)
from ._catalog_state import check_markers, finished_chunks, untrusted_error, write_settings
from ._catalog_state import read_text as _read_text
from ._catalog_state import undo_run as _undo_run
from ._chunks import (
    DTM_METHODS,
    GROUND_FILTERS,
    ChunkTask,
    PhaseClock,
    apply_summary,
    default_ground_filter,
    is_done,
    neighbour_paths,
    process_chunk,
    register_dtm_method,
    register_ground_filter,
    snap_grid,
)
from ._dask_run import (  # noqa: F401 - CatalogResult is this module's public result type
    QUIET,
    CatalogResult,
    _client,
    _collect,
    _run_dask,
    _sweep_temps,
)
from ._gap import apply_gap, derived_gap, drop_gap_files
from .filters import ground_filter

__all__ = ["Catalog", "CatalogResult", "run_catalog", "GROUND_FILTERS", "DTM_METHODS",
           "register_ground_filter", "register_dtm_method", "default_ground_filter",
           "plan_tasks"]

def _test_fail_once() -> set:
    """Return the keys whose first attempt fails (test hook: GEOMATICS_TEST_FAIL_ONCE)."""
    return {k for k in os.environ.get("GEOMATICS_TEST_FAIL_ONCE", "").split(",") if k}


# ============================================================================ catalog
@dataclass
class Catalog:
    """Header index of a set of LAS/LAZ tiles.

    Attributes
    ----------
    tiles : list of LasInfo
        Header facts per tile (path, count, bounds, CRS).
    bounds : ndarray, shape (n, 4)
        ``xmin, ymin, xmax, ymax`` per tile (the spatial index).
    crs : str or None
        The common CRS.
    """

    tiles: List[LasInfo]
    bounds: np.ndarray
    crs: Optional[str]
    #: Tiles left out because they cannot be read (``skip_unreadable``): path -> reason.
    unreadable: Dict[str, Exception] = field(default_factory=dict)
    #: Tiles left out because they hold no point (a header only): paths.
    empty: List[str] = field(default_factory=list)

    @classmethod
    def open(cls, source, *, skip_unreadable: bool = False) -> Catalog:
        """Index ``source`` (folder, glob, list or ``.vpc``) from the headers only.

        Every header is read and checked (:func:`~..io.las.check_las_file`) before
        anything runs. Unreadable tiles (damaged, truncated, lying headers) are all
        named in one refusal; with ``skip_unreadable`` they are left out instead
        (:attr:`unreadable`) and their neighbours' buffers simply lack their points.
        Tiles without points (a header only, as tiling tools write over water) hold
        nothing for the merged cloud: left out (:attr:`empty`, named in the warnings).

        Raises
        ------
        InputError
            No tile, unreadable tiles, no tile with points or tiles in different CRSs.
        """
        infos, unreadable, empty = [], {}, []
        for path in find_tiles(source):
            try:
                info = las_info(path)
            except ValueError as exc:           # InputError included: keep it (translated)
                unreadable[path] = exc
                continue
            (infos if info.count else empty).append(info)
        check_index(infos, unreadable, skip_unreadable, [t.path for t in empty])
        bounds = np.array([[t.mins[0], t.mins[1], t.maxs[0], t.maxs[1]] for t in infos])
        return cls(infos, bounds, infos[0].crs, unreadable, [t.path for t in empty])

    @property
    def paths(self) -> List[str]:
        """Tile paths, in catalog order."""
        return [t.path for t in self.tiles]

    @property
    def n_points(self) -> int:
        """Total points of the catalog (from the headers)."""
        return int(sum(t.count for t in self.tiles))

    @property
    def extent(self) -> tuple:
        """``(xmin, ymin, xmax, ymax)`` of the whole catalog."""
        b = self.bounds
        return (float(b[:, 0].min()), float(b[:, 1].min()), float(b[:, 2].max()),
                float(b[:, 3].max()))

    def query(self, box) -> List[int]:
        """Return the indices of the tiles whose bounds intersect ``box`` (x0, y0, x1, y1)."""
        b = self.bounds
        hit = ((b[:, 0] <= box[2]) & (b[:, 2] >= box[0]) & (b[:, 1] <= box[3])
               & (b[:, 3] >= box[1]))
        return [int(i) for i in np.flatnonzero(hit)]

    def default_max_distance(self) -> float:
        """Provisional DTM gap distance, from the headers: 10 mean point spacings.

        The chunks' DTM files carry it until every chunk has finished; then the gap
        distance of a single-file run of the merged cloud replaces it (:mod:`._gap`).
        """
        e = self.extent
        area = max((e[2] - e[0]) * (e[3] - e[1]), 1e-9)
        return 10.0 * math.sqrt(area / max(self.n_points, 1))


# ============================================================================ planning
def _output_names(folder: Path, tile: str) -> Dict[str, str]:
    stem = Path(tile).stem
    suffix = Path(tile).suffix.lower()
    return {"LAS": str(folder / f"{stem}_classified{suffix}"),
            "DTM": str(folder / f"{stem}_dtm.tif"),
            "DONE": str(folder / STATE_DIR / f"{stem}.done.json")}


def _run_settings(tasks: Sequence[ChunkTask], cat: Catalog) -> dict:
    t = tasks[0]
    return dict(ground_filter=t.ground_filter, dtm_method=t.dtm_method,
                cell_size=t.cell_size, buffer=t.buffer, origin=list(t.origin),
                max_distance=None if t.derive_gap else t.max_distance,
                chunks=sorted(x.key for x in tasks),
                tiles=sorted(tile_signature(i) for i in cat.tiles))


def _cost(cat: Catalog, task: ChunkTask) -> float:
    """Relative work of a chunk (points).

    LAZ decoding of every source file it reads (whole files, streamed) plus
    filtering, gridding and writing the points of its buffered box.
    """
    counts = {t.path: t.count for t in cat.tiles}
    return float(sum(counts[p] for p in task.sources)) + _overlap_points(
        cat, task.buffered_box())


def _las_format(cat: Catalog) -> dict:
    """Writer settings of box-mode chunks (first tile's format, finest scale).

    Dimensions: the standard ones every tile has and the extra-bytes ones (same name and
    type) every tile has.
    """
    from laspy import PointFormat
    first = cat.tiles[0]
    standard = set(PointFormat(first.point_format).standard_dimension_names)
    common = set.intersection(*(set(t.dimensions) for t in cat.tiles))
    dims = [d for d in first.dimensions
            if d in common and d in standard and d not in ("X", "Y", "Z")]
    extra = dict(set.intersection(*(set(t.extra_dims) for t in cat.tiles)))
    extra = {n: extra[n] for n, _ in first.extra_dims if n in extra}      # file order
    return dict(point_format=first.point_format, version=first.version,
                scale=float(min(min(t.scales[:2]) for t in cat.tiles)),
                dimensions=dims + list(extra), extra_dims=extra)


def _tile_tasks(cat: Catalog, folder: Path, common: dict) -> List[ChunkTask]:
    tasks = []
    for i, t in enumerate(cat.tiles):
        box = tuple(float(v) for v in cat.bounds[i])
        task = ChunkTask(key=Path(t.path).stem, tile=t.path, bounds=box,
                         sources=[t.path] + neighbour_paths(cat.bounds, cat.paths, i,
                                                            common["buffer"]),
                         outputs=_output_names(folder, t.path), **common)
        task.cost = _cost(cat, task)
        tasks.append(task)
    return tasks


def _box_tasks(cat: Catalog, folder: Path, size: float, common: dict) -> List[ChunkTask]:
    """Square chunks of ``size`` on the global lattice that own at least one tile's area."""
    ox, oy = common["origin"]
    e = cat.extent
    fmt = _las_format(cat)
    suffix = Path(cat.paths[0]).suffix.lower()
    tasks = []
    for iy in range(math.floor((e[1] - oy) / size), math.floor((e[3] - oy) / size) + 1):
        for ix in range(math.floor((e[0] - ox) / size), math.floor((e[2] - ox) / size) + 1):
            box = (ox + ix * size, oy + iy * size, ox + (ix + 1) * size, oy + (iy + 1) * size)
            if not cat.query(box):
                continue
            key = f"chunk_{box[0]:.0f}_{box[1]:.0f}"
            task = ChunkTask(key=key, bounds=box, las_format=fmt, sources=[],
                             outputs=_output_names(folder, key + suffix), **common)
            task.sources = [cat.paths[j] for j in cat.query(task.buffered_box())]
            task.cost = _cost(cat, task)
            tasks.append(task)
    return tasks


def plan_tasks(cat: Catalog, folder, *, ground_filter: str, dtm_method: str,
               cell_size: float, buffer: float, origin=None, chunk_size: float = 0.0,
               max_distance: Optional[float] = None) -> List[ChunkTask]:
    """One :class:`ChunkTask` per tile, or per square of ``chunk_size`` metres (> 0).

    Validates the parameters and checks every output path against the inputs.
    """
    _check_params(ground_filter, dtm_method, cell_size, buffer, chunk_size)
    folder = Path(folder)
    _check_folder(cat, folder)
    # Lengths are metres (DEVELOPERS.md, Units); tiles in feet: the geometry (buffer,
    # cells, chunks, gap distance) in the tiles' units, the filter on metres (filter_chunk)
    units = cat.tiles[0].units
    h = units.h
    if origin is None:      # a whole kilometre, in metres whatever the tiles' units
        e = cat.extent
        origin = (math.floor(e[0] * h / 1000.0) * 1000.0 / h,
                  math.floor(e[1] * h / 1000.0) * 1000.0 / h)
    buffer, cell_size, chunk_size = (float(v) / h for v in (buffer, cell_size, chunk_size))
    md = cat.default_max_distance() if max_distance is None else float(max_distance) / h
    common = dict(buffer=buffer, origin=(float(origin[0]), float(origin[1])),
                  cell_size=cell_size, crs=cat.crs, ground_filter=ground_filter,
                  dtm_method=dtm_method, max_distance=md, units=units,
                  derive_gap=max_distance is None)
    _check_chunks(cat, chunk_size, cell_size, buffer, origin, h=h)
    tasks = (_box_tasks(cat, folder, chunk_size, common) if chunk_size
             else _tile_tasks(cat, folder, common))
    _canopy.assign_peers(tasks, h)
    outs = {f"{k}:{i}": v for i, t in enumerate(tasks) for k, v in t.outputs.items()
            if k != "DONE"}
    check_paths(outs, {"TILES": cat.paths})
    return tasks


# ============================================================================ engine
def has_first_pass(key: str) -> bool:
    """Return True when the filter ``key`` derives values from all the tiles (a first pass)."""
    flt = ground_filter(key)
    return flt is not None and getattr(flt, "lattice", "cloud") == "cloud"


def pass_plan(cat: Catalog, tasks: Sequence[ChunkTask], folder) -> Optional[dict]:
    """Return what the catalog's first pass summarises (:mod:`._summary`), or None.

    None when the filter derives nothing from the whole cloud (PTD, keep), or when an
    earlier run of this folder saved the summary of the same tiles (names, sizes,
    modification times, counts, bounds), filter and buffer (``.catalog/summary.json``
    and its signature; applied to ``tasks`` here). A summary of other tiles or settings
    is stale: recomputed. Else ``{"spec": {tile: (h, counts, shared boxes)}, "counts",
    "folder", "signature"}``: a tile's cells that another tile's box touches are counted
    by key.
    """
    flt = ground_filter(tasks[0].ground_filter) if tasks else None
    if flt is None or getattr(flt, "lattice", "cloud") != "cloud":    # has_first_pass
        return None
    state = Path(folder) / STATE_DIR
    counts = bool(getattr(flt, "needs_counts", False))
    h = float(tasks[0].units.h)
    signature = json.loads(json.dumps(dict(
        tiles=sorted(tile_signature(i) for i in cat.tiles), ground_filter=tasks[0].ground_filter,
        counts=counts, h=h, buffer=float(tasks[0].buffer))))
    summary = _summary.load(state)
    if summary is not None and summary.get("signature") == signature:
        apply_summary(tasks, summary)
        return None
    if getattr(flt, "needs_canopy", False) and finished_chunks(folder):
        # kept from 0475c85: the finished chunks' values cannot be checked against it
        raise untrusted_error(folder, [f"{STATE_DIR}/{_summary.SUMMARY_FILE}"])
    spec = {p: (h, counts, [(cat.bounds[j] * h).tolist() for j in cat.query(tuple(b))
                            if j != i]) for i, (p, b) in enumerate(zip(cat.paths, cat.bounds))}
    return {"spec": spec, "counts": counts, "folder": os.path.abspath(state),
            "signature": signature}


def first_pass(cat: Catalog, tasks: Sequence[ChunkTask], folder) -> Optional[dict]:
    """Summarise every tile in this process and give each chunk what its filter derives.

    A filter anchored on its cloud's corner (``lattice`` 'cloud') gets the corner of
    all the catalog's points, the recommended filter the density and counts of all
    of them (:mod:`._summary`), so a chunk derives what a single-file run of the merged
    cloud derives. A Dask run does the same on its workers, from the strips' decodes
    (``_dask_run``). Saved in ``.catalog/summary.json``; None when nothing is derived.
    """
    plan = pass_plan(cat, tasks, folder)
    if plan is None:
        return _summary.load(Path(folder) / STATE_DIR) if tasks else None
    summary = _summary.final(*[_summary.tile_summary(p, *plan["spec"][p]) for p in cat.paths],
                             counts=plan["counts"], folder=plan["folder"],
                             signature=plan["signature"])
    apply_summary(tasks, summary)
    return summary


def run_here(cat: Catalog, tasks: Sequence[ChunkTask], folder) -> List[dict]:
    """Do a catalog's work in this process, without Dask (tests, benchmarks); the stats.

    The first pass (:func:`first_pass`), every chunk, then the chunks run again at the
    catalog's canopy factor (:mod:`._canopy`), as :func:`run_catalog` does on its workers.
    """
    first_pass(cat, tasks, folder)
    stats = [process_chunk(t) for t in tasks]
    settle = _settler(tasks, [], Path(folder)) if has_canopy(tasks[0].ground_filter) else None
    again = {t.key: process_chunk(t) for t in (settle(stats) if settle is not None else ())}
    return [again.get(s["key"], s) for s in stats]


def run_catalog(source, out_folder, *, ground_filter: Optional[str] = None,
                dtm_method: str = "idw", cell_size: float = 1.0, buffer: float = 100.0,
                chunk_size: float = 0.0, workers: Optional[int] = None, scheduler: str = "",
                cog: bool = False, origin=None, max_distance: Optional[float] = None,
                memory_limit="auto", on_chunk=None, progress=None,
                cancel=None) -> CatalogResult:
    """Process a tile catalog chunk by chunk on Dask (see the module docstring).

    Parameters
    ----------
    source : str, path, list or Catalog
        Folder, glob, list of files, ``.vpc`` or an opened :class:`Catalog`.
    out_folder : path
        Receives ``<tile>_classified.las|laz``, ``<tile>_dtm.tif``, ``dtm.vrt``
        (and ``dtm_cog.tif``) and the resume markers in ``.catalog/``. Must not
        hold input tiles.
    ground_filter : str, optional
        Key of :data:`GROUND_FILTERS` (``keep`` = the files' own classes); default
        :func:`default_ground_filter`.
    dtm_method : str
        Key of :data:`DTM_METHODS` (``idw``, ``kriging``).
    cell_size, buffer : float
        DTM cell (m) and chunk buffer (m; wider than the filter's reach: LSQ tiles,
        slope radius and terrain trend, IDW search, TIN edge limit).
    chunk_size : float
        0: one chunk per tile. > 0: square chunks of this side (m, a multiple of
        ``cell_size``) on the global lattice, each read from the tiles it overlaps
        (only the points in its buffered box) and written as ``chunk_<x>_<y>``.
    workers : int, optional
        Local worker processes (default: CPU count). Ignored with ``scheduler``.
    scheduler : str
        Address of an existing Dask scheduler (``tcp://host:8786``); empty = local.
    origin : (float, float), optional
        Global lattice origin (default: the catalog's lower-left corner floored to km).
    max_distance : float, optional
        DTM gap distance (m); default: a single-file run's on the merged cloud, derived
        when every chunk has finished (:mod:`._gap`).
    on_chunk : callable, optional
        Called with the stats dict of every chunk as it finishes (``key``, ``status``
        'done'/'empty'/'failed', ``points``, ``seconds``, ``error``), and of every chunk
        a previous run finished (``status`` 'skipped'), e.g. for a log line per tile.

    Returns
    -------
    CatalogResult
        ``timings`` holds wall and CPU seconds of this (client) process per phase
        (index, plan, cluster start, compute, cluster close, mosaic); each chunk's
        stats hold those of its worker (read, filter, dtm, write) and its ground
        (``ground``, ``ground_reach``, ``dtm_cells``: :func:`.catalog_report.catalog_warnings`).
        InputError: bad input (nothing made), no ground or no DTM cell (outputs removed).
    """
    t0 = time.perf_counter()
    clock = PhaseClock()
    mon = Monitor(progress, cancel)
    cat = source if isinstance(source, Catalog) else Catalog.open(source)
    clock.lap("index")
    folder = Path(out_folder)
    gf = ground_filter or default_ground_filter()
    tasks = plan_tasks(cat, folder, ground_filter=gf, dtm_method=dtm_method,
                       cell_size=cell_size, buffer=buffer, origin=origin,
                       chunk_size=chunk_size, max_distance=max_distance)
    if scheduler:
        check_scheduler(scheduler)
    run_settings = _run_settings(tasks, cat)
    _check_resume(folder, run_settings, tasks, whole=has_first_pass(gf))
    previous = {t.key: is_done(t) for t in tasks}
    if has_canopy(gf):
        check_markers(folder, previous)          # every finished chunk's canopy counts
    # everything is validated: only now is anything created
    state = folder / STATE_DIR
    made = [p for p in (folder, state) if not p.exists()]
    before = {n: _read_text(state / n) for n in (SETTINGS_FILE, _summary.SUMMARY_FILE)}
    state.mkdir(parents=True, exist_ok=True)
    write_settings(folder, run_settings)
    todo = [t for t in tasks if previous[t.key] is None]
    for t in todo:
        t.fail_once = t.key in _test_fail_once()
    opts = dict(dtm_method=dtm_method, cell_size=cell_size, buffer=buffer, cog=cog,
                chunk_size=chunk_size, workers=int(workers or os.cpu_count() or 1),
                scheduler=scheduler, memory_limit=memory_limit, on_chunk=on_chunk)
    try:
        with sigterm_raises():
            return _execute(cat, tasks, todo, previous, folder, made, gf, opts, mon, clock, t0)
    except BaseException as exc:
        # cancel, failure or SIGTERM before any chunk finished (in the first pass, or every
        # chunk failed): nothing to resume, so the folder is left as this run found it; a
        # run refused after its chunks (no ground, no DTM cell) loses what it wrote
        if getattr(exc, "undo_run", False) or not finished_chunks(folder):
            _undo_run(todo, made, restore=before)
        raise


def _execute(cat, tasks, todo, previous, folder, made, gf, opts, mon, clock, t0):
    """Run the chunks (:func:`run_catalog` has validated the plan and written its state)."""
    chunks = [s for s in previous.values() if s is not None]
    failed: Dict[str, str] = {}
    on_chunk = opts["on_chunk"]
    for s in chunks if on_chunk is not None else ():
        on_chunk({**s, "status": "skipped"})
    mon.update(len(chunks) / len(tasks))
    clock.lap("plan")
    settle = _settler(tasks, chunks, folder) if has_canopy(gf) else None
    again = not todo and settle is not None and settle([])   # re-runs, no chunk left:
    plan = pass_plan(cat, todo or tasks, folder) if todo or again else None   # they need
    ran = set()              # the summary too (refused when missing or stale, 0475c85)
    if todo or again:        # plan None: nothing to pass, or a valid summary reused
        new = _run_dask(todo, tasks, folder, opts["workers"], opts["scheduler"],
                        opts["memory_limit"], mon, len(chunks), failed, clock, on_chunk,
                        plan=plan, settle=settle)
        ran = {c["key"] for c in new}   # a finished chunk run again: its new stats; a failed
        chunks = [c for c in chunks if c["key"] not in ran] + new     # re-run: not done (at
        chunks = [c for c in chunks if c["key"] not in failed]        # its own canopy scale)
    summary = _summary.load(folder / STATE_DIR) or {}
    gap = _catalog_gap(tasks, chunks, failed, opts["cell_size"], opts["dtm_method"])
    _check_outcome(chunks, failed, len(tasks), cat.n_points, gf)
    vrt, cog_path = _mosaic(cat, folder, tasks, failed, chunks, opts["cog"])
    clock.lap("mosaic")
    order = {t.key: i for i, t in enumerate(tasks)}
    chunks.sort(key=lambda c: order[c["key"]])
    settings = dict(ground_filter=gf, dtm_method=opts["dtm_method"],
                    cell_size=float(opts["cell_size"]), buffer=float(opts["buffer"]),
                    chunk_size=float(opts["chunk_size"]),
                    **_result_settings(cat, tasks, gap, summary, ran=plan is not None),
                    **_canopy_settings(settle, chunks))
    return CatalogResult(chunks=chunks, failed=failed,
                         skipped=[k for k, v in previous.items() if v is not None
                                  and k not in ran and k not in failed],
                         vrt=vrt, cog=cog_path, seconds=time.perf_counter() - t0,
                         workers=opts["workers"], scheduler=opts["scheduler"] or "local",
                         settings=settings, timings=clock.phases)


def _result_settings(cat, tasks, gap, summary, ran: bool) -> dict:
    return dict(tiles=len(tasks), points_total=cat.n_points, crs=cat.crs or "",
                # the workers' wall and CPU seconds of this run's first pass (:mod:`._summary`);
                # a resume that reuses an earlier run's summary spends none
                first_pass_seconds=(summary.get("seconds") if ran else [0.0, 0.0])
                if summary else None,
                first_pass=("run" if ran else "reused") if summary else None,
                origin=tasks[0].origin, keys=[t.key for t in tasks],
                bounds=[list(t.bounds) for t in tasks],
                # metres (tiles in feet: converted), as a single-file run reports it
                gap_distance=(gap if gap is not None else tasks[0].max_distance)
                * tasks[0].units.h,
                empty_tiles=[os.path.basename(p) for p in cat.empty])


def has_canopy(key: str) -> bool:
    """Return True when the filter ``key`` takes the catalog's canopy scale (:mod:`._canopy`)."""
    return bool(getattr(ground_filter(key), "needs_canopy", False))


def _settler(tasks, done: List[dict], folder: Path):
    """``settle(results)``: the chunks to run again at the catalog's canopy factor.

    ``done``: the stats of the chunks an earlier run finished; ``settle.got`` keeps the
    last :class:`._canopy.Settled` (None while a chunk is missing or failed).
    """
    def settle(results):
        got = settle.got = _canopy.settle(tasks, done + list(results))
        if got is None or not got.redo:
            return []
        apply_summary(got.redo, _summary.load(folder / STATE_DIR) or {}, got.factor)
        return got.redo
    settle.got = None
    return settle


def _canopy_settings(settle, chunks) -> dict:
    """Return the canopy factor, the chunks run again at it and their seconds (:mod:`._canopy`)."""
    got = None if settle is None else settle.got
    if got is None:
        return dict(canopy_factor=None, canopy_reruns=[], canopy_seconds=None)
    again = {t.key for t in got.redo} & {c["key"] for c in chunks}    # failed ones left out
    redone = [c for c in chunks if c["key"] in again]
    return dict(canopy_factor=got.factor, canopy_counts=[got.pits, got.blocks],
                canopy_reruns=sorted(again),
                # the workers' wall and CPU seconds of those re-runs: the scale's extra cost
                canopy_seconds=[float(sum(c.get(k) or 0.0 for c in redone))
                                for k in ("seconds", "cpu_seconds")])


def _catalog_gap(tasks, chunks, failed, cell_size: float, method: str) -> Optional[float]:
    """Derive the gap distance from every chunk's ground and mask the DTMs with it.

    None when the run has failed chunks (the DTMs keep the provisional distance and
    their ``.gap.npz`` for the resume) or a gap distance was given.
    """
    if not tasks[0].derive_gap or failed:
        return None
    gap = derived_gap(chunks, cell_size=float(cell_size), h=tasks[0].units.h,
                      method_key=method)
    if gap is not None:
        apply_gap(tasks, chunks, gap, method_key=method,
                  grids=lambda t: snap_grid(t.bounds, t.origin, t.cell_size, t.crs))
        drop_gap_files(tasks)
    return gap


def _check_outcome(chunks, failed, n_tiles: int, n_points: int, gf: str):
    """Refuse a run without ground, or without a DTM cell (:func:`run_catalog` undoes it).

    The single-file DTM refuses a cloud without ground points and a DTM without a valid
    cell; a catalog does the same over all its tiles (a run with failed chunks reports
    those instead). The refusal carries ``undo_run``: what this run wrote goes, once.
    """
    if failed or not chunks:
        return
    exc = None
    if not any(c.get("ground") for c in chunks):
        exc = no_ground_error(chunks, n_tiles, n_points, gf)
    elif all(c.get("dtm_cells", 1) == 0 for c in chunks):
        exc = empty_dtm_error(chunks)
    if exc is not None:
        exc.undo_run = True
        raise exc


def _mosaic(cat, folder: Path, tasks, failed, chunks, cog: bool):
    """VRT (and COG) of the chunk DTMs that exist (failed and empty chunks left out)."""
    empty = {c["key"] for c in chunks if c.get("status") == "empty"}
    rasters = [t.outputs["DTM"] for t in tasks if t.key not in failed and t.key not in empty]
    if not rasters and failed:
        key, error = next(iter(failed.items()))
        raise InputError("Every chunk failed ({n} of {total}); no DTM was made. First "
                         "failure: {key}: {error}", n=len(failed), total=len(tasks),
                         key=key, error=str(error)[:400])
    vrt = str(folder / "dtm.vrt")
    cog_path = str(folder / "dtm_cog.tif") if cog else None
    with OutputContract({"VRT": vrt, "COG": cog_path}, inputs={"TILES": cat.paths}) as out:
        build_vrt(out.path("VRT"), rasters, cog_path=out.path("COG") if cog else None)
    return vrt, cog_path

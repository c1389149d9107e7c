"""One catalog chunk: buffered read, ground filter, DTM, per-chunk outputs (runs on a worker).

Everything here is a plain function of picklable arguments so that Dask can ship
it to a worker process (local or remote). The ground filters are the registered
algorithm objects of :mod:`.filters` (the same as the single-file algorithms, run by
the same :func:`.filters.classify_points`); the DTM methods are registered here.
"""
from __future__ import annotations

import json
import math
import os
import socket
import time
from dataclasses import dataclass, field
from functools import partial
from typing import Dict, List, Optional, Sequence, Tuple

import numpy as np

from .. import classes as asprs
from ..errors import InputError
from ..io.catalog import read_box
from ..io.contract import OutputContract
from ..io.las import PointData, read_las, write_las, write_las_like
from ..io.raster import write_geotiff
from ..io.units import METRIC, Units
from ..system import peak_rss_mb
from ..terrain.dtm import (
    DTM_METHODS,
    MIN_DISTINCT_POINTS,
    IdwOptions,
    distinct_positions,
    dtm_method,
    register_dtm_method,
)
from ..terrain.grid import GridSpec
from . import _canopy, _summary
from ._gap import chunk_gaps, gap_path, ground_summary, mask_with_gap, write_marker
from .filters import (
    GROUND_FILTERS,
    RECOMMENDED_FILTER,
    default_ground_filter,
    default_selection,
    ground_filter,
    register_ground_filter,
    run_filter,
)

GROUND = int(asprs.GROUND)
__all__ = ["GROUND_FILTERS", "RECOMMENDED_FILTER", "DTM_METHODS", "register_ground_filter",
           "register_dtm_method", "default_ground_filter", "chunk_dtm", "dtm_in_reach", "ChunkTask",
           "process_chunk", "read_chunk", "read_strip", "filter_chunk", "snap_grid", "is_done",
           "neighbour_paths"]


# ============================================================================ methods
# Ground filters: the one registry of :mod:`.filters`; DTM methods: the one registry of
# :mod:`..terrain.dtm` (the same algorithm objects as the single-file algorithms).
#: IDW in chunks orders equidistant neighbours by their coordinates (not by a quadtree
#: of the chunk's points), so a chunk gives the merged cloud's cells exactly
CHUNK_IDW = IdwOptions(tie_order="xy")


def chunk_dtm(key: str, x, y, z, grid, max_distance: float) -> np.ndarray:
    """DTM of a chunk's ground points with the registered method ``key`` (one thread)."""
    return dtm_in_reach(key, x, y, z, grid, max_distance)[0]


def dtm_in_reach(key: str, x, y, z, grid, max_distance: float, *, gaps: bool = False):
    """DTM of the ground a chunk has within reach, and the neighbours used if cut.

    A part of a catalog may hold little or no ground (a lake, the sea at the coast, a
    tile of vegetation or noise only). Fewer than :data:`MIN_DISTINCT_POINTS` ground
    positions in the tile and its buffer: every cell is nodata (the merged cloud's DTM
    has no ground within the gap distance there when the buffer is wider than it; a
    single-file DTM refuses such a cloud). Fewer points than the method's neighbours:
    those points (:meth:`~..terrain.dtm.DtmMethod.within`). Ground the method refuses
    (kriging's variogram from a few points, a TIN of points on one line): nodata and the
    refusal kept. Returns ``(z, k, why)``: ``k`` the neighbours used when cut, else None;
    ``why`` the refusal (:func:`refusal`) or None. With ``gaps`` (the catalog derives
    its gap distance after the run, :mod:`._gap`) a fourth item: ``(z, gap)`` of the DTM
    without a gap limit and the distances the limit is tested on (None when no DTM).
    """
    nodata = np.full(grid.shape, np.nan)
    done = (lambda *r: r + (None,)) if gaps else (lambda *r: r)
    if distinct_positions(x, y, MIN_DISTINCT_POINTS) < MIN_DISTINCT_POINTS:
        return done(nodata, None, None)
    method = dtm_method(key, CHUNK_IDW if key == "idw" else None)
    fitted = method.within(x, y)
    used = None if fitted is method else int(fitted.options.neighbours)
    try:
        if gaps:
            full = chunk_gaps(fitted, x, y, z, grid)
            return mask_with_gap(*full, key, max_distance), used, None, full
        return (fitted.interpolate(x, y, z, grid, max_distance=max_distance, workers=1).z,
                used, None)
    except InputError as exc:           # the data of this chunk, not the settings
        return done(nodata, used, refusal(exc))


def refusal(exc: InputError) -> dict:
    """Return an :class:`InputError` as JSON for a done marker (template, fields)."""
    return {"template": exc.template,
            "fields": {k: v if isinstance(v, (int, float)) else str(v)
                       for k, v in exc.fields.items()}}


# ============================================================================ the task
@dataclass
class ChunkTask:
    """Everything a worker needs to process one chunk (a whole tile or a square box).

    Tile mode (``tile`` set): the chunk is that tile, read whole, plus the points of
    ``sources[1:]`` (its neighbours) inside the buffered box; the classified output is
    a copy of the tile with new classes (every attribute kept). Box mode
    (``tile=None``, a regular ``CHUNK_SIZE``): only the points of ``sources`` inside
    the buffered box are read, the chunk owns the points in its half-open box
    ``[xmin, xmax) x [ymin, ymax)`` and writes them as a new LAS/LAZ (``las_format``).
    """

    key: str
    sources: List[str]
    bounds: Tuple[float, float, float, float]       # xmin, ymin, xmax, ymax of the chunk
    buffer: float
    origin: Tuple[float, float]
    cell_size: float
    crs: Optional[str]
    ground_filter: str
    dtm_method: str
    max_distance: float
    tile: Optional[str] = None
    las_format: dict = field(default_factory=dict)            # box mode: writer settings
    cost: float = 0.0                                         # estimated points read
    outputs: Dict[str, str] = field(default_factory=dict)   # LAS, DTM, DONE
    fail_once: bool = False                                   # tests: first attempt fails
    strip_shares: List[float] = field(default_factory=list)  # 1 / consumers per strip
    #: Linear units of the tiles (feet tiles: the filter runs on metres, the geometry
    #: above and the chunk's outputs are in the tiles' units).
    units: Units = METRIC
    #: The catalog derives the gap distance after the run (:mod:`._gap`):
    #: ``max_distance`` is then provisional and the chunk keeps ``<key>.gap.npz``.
    derive_gap: bool = False
    #: Anchor of the filter's grids and tiles (metres): the corner of every point of
    #: the catalog, from its first pass (:mod:`._summary`), as a single-file run of the
    #: merged cloud anchors at its corner; None: the chunk's own (or PTD's lattice).
    filter_origin: Optional[Tuple[float, float]] = None
    #: What the filter derives from the whole cloud (the recommended filter's density,
    #: median count per 5 m cell, input water anywhere: ``_summary.recommended_values``),
    #: from the first pass; None: from the chunk's own points.
    derived: Optional[dict] = None
    #: Position in the plan and ``[index, xmin, ymin, xmax, ymax]`` (metres) of the chunks
    #: near it (itself included): which canopy blocks it counts (:mod:`._canopy`).
    index: int = 0
    peers: list = field(default_factory=list)

    @property
    def neighbours(self) -> List[str]:
        """Tile mode: the tiles that lend buffer points (all but the chunk's own)."""
        return self.sources[1:] if self.tile else list(self.sources)

    def buffered_box(self) -> Tuple[float, float, float, float]:
        """Chunk bounds grown by the buffer."""
        b = self.buffer
        return (self.bounds[0] - b, self.bounds[1] - b, self.bounds[2] + b, self.bounds[3] + b)


def apply_summary(tasks, summary: dict, canopy_factor: Optional[int] = None) -> None:
    """Give every chunk the catalog's corner and derived values (:func:`._summary.final`).

    ``canopy_factor``: the catalog's canopy factor (:func:`._canopy.settle`); without it
    a chunk closes its canopy at its own, provisionally.
    """
    corner = summary.get("corner")
    derived = summary.get("derived")
    if derived is not None:
        derived = {k: v for k, v in derived.items() if not k.startswith("canopy_")}
        if canopy_factor:
            derived["canopy_factor"] = int(canopy_factor)
    for t in tasks:
        t.filter_origin = None if corner is None else (float(corner[0]), float(corner[1]))
        t.derived = derived


def is_done(task: ChunkTask) -> Optional[dict]:
    """Stats of a chunk finished by an earlier run (marker and outputs present), else None."""
    done = task.outputs["DONE"]
    if not os.path.exists(done):
        return None
    try:
        with open(done, encoding="utf-8") as fh:
            stats = json.load(fh)
    except (OSError, ValueError):
        return None
    if stats.get("status") == "empty":
        return stats
    if not all(os.path.exists(task.outputs[k]) for k in ("LAS", "DTM")):
        return None
    return stats


def snap_grid(bounds, origin, cell: float, crs=None) -> GridSpec:
    """Grid covering ``bounds`` on the global cell lattice anchored at ``origin``."""
    ox, oy = origin
    c0 = math.floor((bounds[0] - ox) / cell + 1e-9)
    c1 = math.ceil((bounds[2] - ox) / cell - 1e-9)
    r0 = math.floor((bounds[1] - oy) / cell + 1e-9)
    r1 = math.ceil((bounds[3] - oy) / cell - 1e-9)
    return GridSpec(xmin=ox + c0 * cell, ymax=oy + r1 * cell, cell=cell,
                    ncols=max(c1 - c0, 1), nrows=max(r1 - r0, 1), crs=crs)


def _worker_name() -> str:
    try:
        from distributed import get_worker
        return get_worker().address
    except (ImportError, ValueError):
        return f"{socket.gethostname()}:{os.getpid()}"


class InjectedFailureError(RuntimeError):
    """A chunk's first attempt failing on purpose (tests of the retry; never in use)."""


def _fail_first_attempt(task: ChunkTask) -> None:
    flag = task.outputs["DONE"] + ".attempted"
    if not os.path.exists(flag):
        with open(flag, "w", encoding="utf-8") as fh:
            fh.write("1")
        raise InjectedFailureError(task.key)


def single_threaded() -> None:
    """Pin this process's native thread pools to one thread (one worker = one core).

    laspy's default LAZ backend decodes and encodes on a rayon pool as wide as the
    machine, and BLAS/OpenMP pools do the same: with one worker per core they would
    oversubscribe the cores (and make a 1-worker run use 2 cores). Effective when
    called before the first LAZ/BLAS use of the process (a Dask worker's first task).
    """
    for name in ("RAYON_NUM_THREADS", "OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS",
                 "MKL_NUM_THREADS"):
        os.environ[name] = "1"


class PhaseClock:
    """Wall and CPU seconds (this process, all threads) per named phase."""

    def __init__(self):
        self.phases: Dict[str, List[float]] = {}
        self._t = (time.perf_counter(), time.process_time())

    def lap(self, name: str) -> None:
        now = (time.perf_counter(), time.process_time())
        self.phases[name] = [now[0] - self._t[0], now[1] - self._t[1]]
        self._t = now


def read_strip(tile: str, boxes, dims=("classification",), summary=None) -> dict:
    """Points of ``tile`` inside any of ``boxes`` (its neighbours' buffered boxes).

    One decode of the tile serves every neighbour (a chunk no longer decodes its
    neighbours whole); ``phases`` holds the wall and CPU seconds of the read.
    ``summary`` (``h, counts, shared``): the same decode also summarises the whole tile
    for the catalog's first pass (``out["summary"]``, :func:`._summary.summarise`).
    """
    clock = PhaseClock()
    pd = read_las(tile, dims)
    made = None
    if summary is not None:
        made = _summary.summarise([(pd.x, pd.y, pd.dims.get("classification"))], *summary)
    keep = np.zeros(len(pd), bool)
    for x0, y0, x1, y1 in boxes:
        keep |= (pd.x >= x0) & (pd.x <= x1) & (pd.y >= y0) & (pd.y <= y1)
    out = {"x": pd.x[keep], "y": pd.y[keep], "z": pd.z[keep]}
    out.update({n: pd[n][keep] for n in dims})
    clock.lap("strip")
    out["phases"] = clock.phases
    if made is not None:
        out["summary"] = made
    return out


def _from_strips(strips, box):
    """Return the points of the neighbours' strips inside the buffered ``box``."""
    parts = []
    for st in strips:
        m = (st["x"] >= box[0]) & (st["x"] <= box[2]) & (st["y"] >= box[1]) & \
            (st["y"] <= box[3])
        parts.append({k: v[m] for k, v in st.items() if k not in ("phases", "summary")})
    if not parts:
        return PointData(np.empty(0), np.empty(0), np.empty(0),
                         {"classification": np.empty(0, np.uint8)})
    cat = {k: np.concatenate([p[k] for p in parts]) for k in parts[0]}
    return PointData(cat.pop("x"), cat.pop("y"), cat.pop("z"), cat)


def _read_tile_mode(task: ChunkTask, strips=None):
    own = read_las(task.tile, ("classification",), keep_records=True)
    if strips is None:
        nb, _ = read_box(task.neighbours, task.buffered_box(), ("classification",))
    else:
        nb = _from_strips(strips, task.buffered_box())
    x = np.concatenate([own.x, nb.x])
    y = np.concatenate([own.y, nb.y])
    z = np.concatenate([own.z, nb.z])
    cls = np.concatenate([own["classification"],
                          nb.dims.get("classification", np.empty(0, np.uint8))])
    core = np.zeros(x.size, bool)
    core[:len(own)] = True
    return (x, y, z), {"classification": cls}, core, own.records


def _read_box_mode(task: ChunkTask):
    pd, _ = read_box(task.sources, task.buffered_box(), task.las_format["dimensions"])
    x0, y0, x1, y1 = task.bounds
    core = (pd.x >= x0) & (pd.x < x1) & (pd.y >= y0) & (pd.y < y1)
    dims = dict(pd.dims)
    dims.setdefault("classification", np.zeros(len(pd), np.uint8))
    return (pd.x, pd.y, pd.z), dims, core


def read_chunk(task: ChunkTask):
    """Read the chunk and its buffer: ``(x, y, z), dims, core`` (core = points owned)."""
    return _read(task)[:3]


def _read(task: ChunkTask, strips=None):
    """``read_chunk`` plus the decoded records of the chunk's own tile (tile mode)."""
    if task.tile:
        return _read_tile_mode(task, strips)
    return (*_read_box_mode(task), None)


def filter_chunk(task: ChunkTask, xyz, dims, core) -> np.ndarray:
    """Classes from the chunk's ground filter for every point read (chunk and buffer).

    The registered algorithm object with the point selection of its single-file
    algorithm's defaults (input noise classes 7 and 18 kept), anchored at the corner
    of the whole catalog (``task.filter_origin``): the same call, with the same anchor,
    as a single-file run of the merged cloud.

    Raises
    ------
    InputError
        Points the filter cannot classify (too few, one position): see
        :func:`filter_sparse_chunk`.
    """
    return _filter_run(task, xyz, dims, core)[0]


def _filter_run(task: ChunkTask, xyz, dims, core):
    """Return ``(classes, canopy)``: :func:`filter_chunk`'s classes, and the canopy stats.

    ``canopy``: when the chunk tallies its canopy blocks (:mod:`._canopy`), the counts
    and the factor its classes used (``{"pits", "blocks", "factor"}``), else None.
    """
    if not core.any():
        return np.zeros(core.size, np.uint8), None
    pts, flt, origin = chunk_filter(task, xyz, dims)
    run = run_filter(pts, flt, default_selection(task.ground_filter), origin=origin)
    d = run.outcome.details
    counts = getattr(d, "canopy_counts", None)
    return run.classes, (None if counts is None else
                         dict(counts, factor=int(getattr(d, "canopy_factor", 0))))


def chunk_filter(task: ChunkTask, xyz, dims):
    """``(points in metres, the filter object given the catalog's values, its anchor)``."""
    units = task.units
    if not units.metric:              # every length of the filters is metres
        xyz = units.xyz_to_metres(*xyz)
    flt = ground_filter(task.ground_filter)
    if task.derived is not None and hasattr(flt, "summary"):
        flt.summary = dict(task.derived)
    origin = task.filter_origin if getattr(flt, "lattice", "cloud") == "cloud" else None
    if _canopy.tallies(task, flt):    # the canopy blocks this chunk counts while it filters
        flt.canopy_owned = partial(_canopy.owned_blocks, task)
    return PointData(*xyz, dims=dims), flt, None if origin is None else tuple(origin)


def filter_sparse_chunk(task: ChunkTask, xyz, dims, core):
    """:func:`filter_chunk`, or no ground where the filter cannot run: ``(cls, why, canopy)``.

    ``canopy``: see :func:`_filter_run`.

    A tile at sea or over a lake may hold, with its buffer, fewer points than the filter
    needs (10 for the recommended filter and PTD, 6 to 18 for LSQ surfaces): its points
    are left unclassified (class 1, input noise 7/18 kept) and the filter's refusal is
    returned (``{"template", "fields"}``, JSON for the done marker) for the warning.
    """
    try:
        cls, canopy = _filter_run(task, xyz, dims, core)
        return cls, None, canopy
    except InputError as exc:
        src = np.asarray(dims.get("classification", np.zeros(core.size, np.uint8)))
        cls = np.where(np.isin(src, asprs.INPUT_NOISE), src, asprs.UNCLASSIFIED)
        return cls.astype(np.uint8), refusal(exc), None


def _write_outputs(task: ChunkTask, xyz, dims, core, cls, dtm, grid, records=None) -> None:
    outputs = {k: task.outputs[k] for k in ("LAS", "DTM")}
    with OutputContract(outputs, inputs={"TILES": list(task.sources)},
                        point_clouds=["LAS"]) as out:
        if task.tile:
            write_las_like(task.tile, out.path("LAS"), dimensions={"classification": cls[core]},
                           records=records)
        else:
            fmt = task.las_format
            new = {n: v[core] for n, v in dims.items()}
            new["classification"] = cls[core]
            write_las(out.path("LAS"), *(v[core] for v in xyz), dimensions=new,
                      crs=task.crs, point_format=fmt["point_format"], version=fmt["version"],
                      scale=fmt["scale"], extra_dims=fmt.get("extra_dims"))
        # heights in the tiles' vertical unit, named on the band as single-file DTMs do
        write_geotiff(out.path("DTM"), dtm, geotransform=grid.geotransform, crs=task.crs,
                      unit_type=task.units.vertical.symbol)


def _save_gaps(task: ChunkTask, z, gap) -> None:
    """``.catalog/<key>.gap.npz``: the DTM as written (float32) without a gap limit."""
    path = gap_path(task)
    with open(path + ".tmp", "wb") as fh:
        np.savez(fh, z=np.asarray(z, np.float32), gap=np.asarray(gap, np.float64))
    os.replace(path + ".tmp", path)


def process_chunk(task: ChunkTask, *strips, summary: Optional[dict] = None) -> dict:
    """Process one chunk end to end; returns its stats (also stored in the done marker).

    ``strips`` (tile mode): the neighbours' :func:`read_strip` results, so the chunk
    decodes only its own tile, once (its classified copy is written from those
    records); without them the neighbours' points are streamed from their files. The
    stats carry wall and CPU seconds per phase (read, filter, dtm, write; ``strips``:
    this chunk's share of its neighbours' strip reads) so the benchmark can separate the
    parallel work from the serial part of a run.
    """
    single_threaded()
    clock = PhaseClock()
    if summary is not None:           # the catalog's first pass, merged on a worker
        apply_summary([task], summary)
    if task.fail_once:
        _fail_first_attempt(task)
    xyz, dims, core, records = _read(task, strips if task.tile and strips else None)
    clock.lap("read")
    n_own = int(core.sum())
    stats = dict(key=task.key, points=n_own, buffer_points=int(core.size - n_own),
                 bounds=list(task.bounds), status="empty", ground=0)
    if _canopy.tallies(task):         # counts and factor for :func:`._canopy.settle`
        stats["canopy"] = _canopy.zero()
    if n_own:
        cls, why, canopy = filter_sparse_chunk(task, xyz, dims, core)
        if why is not None:
            stats["filter_error"] = why
        if canopy is not None:
            stats["canopy"] = canopy
        clock.lap("filter")
        grid = snap_grid(task.bounds, task.origin, task.cell_size, task.crs)
        g = cls == GROUND
        dtm, used, why, *full = dtm_in_reach(task.dtm_method, xyz[0][g], xyz[1][g],
                                             xyz[2][g], grid, task.max_distance,
                                             gaps=task.derive_gap)
        if why is not None:
            stats["dtm_error"] = why
        if full and full[0] is not None:
            _save_gaps(task, *full[0])
        stats.update(ground_summary(xyz[0][g & core], xyz[1][g & core],
                                    distinct=task.dtm_method == "kriging"))
        clock.lap("dtm")
        _write_outputs(task, xyz, dims, core, cls, dtm, grid, records)
        clock.lap("write")
        counts = np.bincount(cls[core])
        # ground of the tile, and within reach (tile and buffer): the run's warnings
        stats.update(status="done", ground=int(counts[GROUND]) if counts.size > GROUND else 0,
                     ground_reach=int(np.count_nonzero(g)), neighbours_used=used,
                     dtm_cells=int(np.count_nonzero(np.isfinite(dtm))),
                     classes={str(c): int(counts[c]) for c in np.flatnonzero(counts)})
    ph = clock.phases
    if strips and task.strip_shares:
        ph["strips"] = [sum(st["phases"]["strip"][i] * share for st, share in
                            zip(strips, task.strip_shares)) for i in (0, 1)]
    stats.update(phases=ph, seconds=sum(v[0] for v in ph.values()),
                 cpu_seconds=sum(v[1] for v in ph.values()), worker=_worker_name(),
                 peak_rss_mb=peak_rss_mb())
    write_marker(task, stats)
    return stats


def neighbour_paths(bounds: np.ndarray, paths: Sequence[str], i: int, buffer: float) -> List[str]:
    """Tiles whose bounds intersect tile ``i``'s bounds grown by ``buffer``."""
    b = bounds[i]
    hit = ((bounds[:, 0] <= b[2] + buffer) & (bounds[:, 2] >= b[0] - buffer)
           & (bounds[:, 1] <= b[3] + buffer) & (bounds[:, 3] >= b[1] - buffer))
    hit[i] = False
    return [paths[j] for j in np.flatnonzero(hit)]

"""One catalog chunk: buffered read, ground filter, DTM, per-chunk outputs (runs on a worker).

Everything here is a plain function of picklable arguments so that Dask can ship
it to a worker process (local or remote). The registries of ground filters and DTM
methods live here too: adding a filter is one :func:`register_ground_filter` call.
"""
from __future__ import annotations

import json
import math
import os
import socket
import time
from dataclasses import dataclass, field
from typing import Callable, Dict, List, Optional, Sequence, Tuple

import numpy as np

from ..io.catalog import read_box
from ..io.contract import OutputContract
from ..io.las import read_las, write_las, write_las_like
from ..io.raster import write_geotiff
from ..system import peak_rss_mb
from ..terrain.grid import GridSpec

GROUND = 2


# ============================================================================ registries
@dataclass(frozen=True)
class Method:
    """A registered ground filter or DTM method."""

    key: str
    label: str
    func: Callable
    tiling: bool = False     # True: anchored on the global origin (tiles, grids)


GROUND_FILTERS: Dict[str, Method] = {}
DTM_METHODS: Dict[str, Method] = {}
RECOMMENDED_FILTER = "groundfilter"   # used as default once registered


def register_ground_filter(key: str, label: str, func: Callable, *, tiling: bool = False):
    """Register ``func(x, y, z, dims, origin) -> uint8 classes`` as a catalog filter."""
    GROUND_FILTERS[key] = Method(key, label, func, tiling)


def register_dtm_method(key: str, label: str, func: Callable):
    """Register ``func(x, y, z, grid, max_distance) -> 2-D array`` as a DTM method."""
    DTM_METHODS[key] = Method(key, label, func, True)


def default_ground_filter() -> str:
    """Return the recommended filter when it is registered, else improved LSQ."""
    return RECOMMENDED_FILTER if RECOMMENDED_FILTER in GROUND_FILTERS else "lsq_improved"


def _keep(x, y, z, dims, origin):
    return np.asarray(dims["classification"], dtype=np.uint8)


def _lsq(mode):
    def run(x, y, z, dims, origin):
        from .lsq import lsq_ground_filter
        return lsq_ground_filter(x, y, z, mode=mode, origin=origin).classification
    return run


def _slope(mode):
    def run(x, y, z, dims, origin):
        from .noise import flag_low_outliers
        from .slope import slope_filter
        low = flag_low_outliers(x, y, z)
        res = slope_filter(x, y, z, classify=~low, neighbours=~low, mode=mode,
                           trend_origin=origin)
        cls = np.where(res.ground, GROUND, 1).astype(np.uint8)
        cls[low] = 7
        return cls
    return run


def _recommended(x, y, z, dims, origin):
    from .recommended import classify
    return classify(x, y, z)


def _idw(x, y, z, grid, max_distance):
    from ..terrain.idw import idw_grid
    return idw_grid(x, y, z, grid, max_distance=max_distance, workers=1)


def _kriging(x, y, z, grid, max_distance):
    from ..terrain.kriging import kriging_grid
    return kriging_grid(x, y, z, grid, max_distance=max_distance, workers=1).z


register_ground_filter("keep", "Keep the classes in the files", _keep)
register_ground_filter("lsq_faithful", "LSQ surfaces (faithful)", _lsq("faithful"), tiling=True)
register_ground_filter("lsq_improved", "LSQ surfaces (improved)", _lsq("improved"), tiling=True)
register_ground_filter("slope_exact", "Slope filter (exact)", _slope("exact"))
register_ground_filter("slope_adaptive", "Slope filter (terrain-adaptive)", _slope("adaptive"),
                       tiling=True)
register_ground_filter(RECOMMENDED_FILTER, "Ground filter (recommended)", _recommended)
def _tin(x, y, z, grid, max_distance):
    """Delaunay TIN; the edge limit is the catalog-wide gap distance (not per chunk)."""
    from ..terrain.tin import tin_grid
    if x.size < 3:
        return np.full(grid.shape, np.nan)
    return tin_grid(x, y, z, grid, max_edge=max_distance).z


register_dtm_method("idw", "IDW", _idw)
register_dtm_method("kriging", "Kriging", _kriging)
register_dtm_method("tin", "TIN", _tin)


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

    @property
    def neighbours(self) -> List[str]:
        """Tile mode: the tiles that lend buffer points (all but the chunk's own)."""
        return self.sources[1:] if self.tile else list(self.sources)

    def buffered_box(self) -> Tuple[float, float, float, float]:
        """Chunk bounds grown by the buffer."""
        b = self.buffer
        return (self.bounds[0] - b, self.bounds[1] - b, self.bounds[2] + b, self.bounds[3] + b)


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


def _fail_first_attempt(task: ChunkTask) -> None:
    flag = task.outputs["DONE"] + ".attempted"
    if not os.path.exists(flag):
        with open(flag, "w", encoding="utf-8") as fh:
            fh.write("1")
        raise RuntimeError(f"injected failure of chunk {task.key} (test)")


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


def _read_tile_mode(task: ChunkTask):
    own = read_las(task.tile, ("classification",))
    nb, _ = read_box(task.neighbours, task.buffered_box(), ("classification",))
    x = np.concatenate([own.x, nb.x])
    y = np.concatenate([own.y, nb.y])
    z = np.concatenate([own.z, nb.z])
    cls = np.concatenate([own["classification"],
                          nb.dims.get("classification", np.empty(0, np.uint8))])
    core = np.zeros(x.size, bool)
    core[:len(own)] = True
    return (x, y, z), {"classification": cls}, core


def _read_box_mode(task: ChunkTask):
    pd, _ = read_box(task.sources, task.buffered_box(), task.las_format["dimensions"])
    x0, y0, x1, y1 = task.bounds
    core = (pd.x >= x0) & (pd.x < x1) & (pd.y >= y0) & (pd.y < y1)
    dims = dict(pd.dims)
    dims.setdefault("classification", np.zeros(len(pd), np.uint8))
    return (pd.x, pd.y, pd.z), dims, core


def read_chunk(task: ChunkTask):
    """Read the chunk and its buffer: ``(x, y, z), dims, core`` (core = points owned)."""
    return _read_tile_mode(task) if task.tile else _read_box_mode(task)


def filter_chunk(task: ChunkTask, xyz, dims, core) -> np.ndarray:
    """Classes from the chunk's ground filter for every point read (chunk and buffer)."""
    if not core.any():
        return np.zeros(core.size, np.uint8)
    cls = GROUND_FILTERS[task.ground_filter].func(*xyz, dims, task.origin)
    return np.asarray(cls, dtype=np.uint8)


def _write_outputs(task: ChunkTask, xyz, dims, core, cls, dtm, grid) -> None:
    outputs = {k: task.outputs[k] for k in ("LAS", "DTM")}
    with OutputContract(outputs, inputs={"TILES": list(task.sources)}) as out:
        if task.tile:
            write_las_like(task.tile, out.path("LAS"), dimensions={"classification": cls[core]})
        else:
            fmt = task.las_format
            new = {n: v[core] for n, v in dims.items()}
            new["classification"] = cls[core]
            write_las(out.path("LAS"), *(v[core] for v in xyz), dimensions=new,
                      crs=task.crs, point_format=fmt["point_format"], version=fmt["version"],
                      scale=fmt["scale"], extra_dims=fmt.get("extra_dims"))
        write_geotiff(out.path("DTM"), dtm, geotransform=grid.geotransform, crs=task.crs)


def process_chunk(task: ChunkTask) -> dict:
    """Process one chunk end to end; returns its stats (also stored in the done marker).

    The stats carry wall and CPU seconds per phase (read, filter, dtm, write) so the
    benchmark can separate the parallel work from the serial part of a run.
    """
    single_threaded()
    clock = PhaseClock()
    if task.fail_once:
        _fail_first_attempt(task)
    xyz, dims, core = read_chunk(task)
    clock.lap("read")
    n_own = int(core.sum())
    stats = dict(key=task.key, points=n_own, buffer_points=int(core.size - n_own),
                 bounds=list(task.bounds), status="empty", ground=0)
    if n_own:
        cls = filter_chunk(task, xyz, dims, core)
        clock.lap("filter")
        grid = snap_grid(task.bounds, task.origin, task.cell_size, task.crs)
        g = cls == GROUND
        dtm = DTM_METHODS[task.dtm_method].func(xyz[0][g], xyz[1][g], xyz[2][g], grid,
                                                task.max_distance)
        clock.lap("dtm")
        _write_outputs(task, xyz, dims, core, cls, dtm, grid)
        clock.lap("write")
        stats.update(status="done", ground=int(np.count_nonzero(cls[core] == GROUND)))
    ph = clock.phases
    stats.update(phases=ph, seconds=sum(v[0] for v in ph.values()),
                 cpu_seconds=sum(v[1] for v in ph.values()), worker=_worker_name(),
                 peak_rss_mb=peak_rss_mb())
    with open(task.outputs["DONE"], "w", encoding="utf-8") as fh:
        json.dump(stats, fh)
    return stats


def neighbour_paths(bounds: np.ndarray, paths: Sequence[str], i: int, buffer: float) -> List[str]:
    """Tiles whose bounds intersect tile ``i``'s bounds grown by ``buffer``."""
    b = bounds[i]
    hit = ((bounds[:, 0] <= b[2] + buffer) & (bounds[:, 2] >= b[0] - buffer)
           & (bounds[:, 1] <= b[3] + buffer) & (bounds[:, 3] >= b[1] - buffer))
    hit[i] = False
    return [paths[j] for j in np.flatnonzero(hit)]

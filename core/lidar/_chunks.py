"""One catalog chunk: buffered read, ground filter, DTM, per-chunk outputs (runs on a worker).

Everything here is a plain function of picklable arguments so that Dask can ship
it to a worker process (local or remote). The registries of ground filters and DTM
methods live here too: adding a filter is one :func:`register_ground_filter` call.
"""
from __future__ import annotations

import json
import math
import os
import resource
import socket
import time
from dataclasses import dataclass, field
from typing import Callable, Dict, List, Optional, Sequence, Tuple

import numpy as np

from ..io.catalog import read_box
from ..io.contract import OutputContract
from ..io.las import read_las, write_las_like
from ..io.raster import write_geotiff
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
        res = slope_filter(x, y, z, classify=~low, neighbours=~low, mode=mode)
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
register_ground_filter("slope_adaptive", "Slope filter (terrain-adaptive)", _slope("adaptive"))
register_ground_filter(RECOMMENDED_FILTER, "Ground filter (recommended)", _recommended)
register_dtm_method("idw", "IDW", _idw)
register_dtm_method("kriging", "Kriging", _kriging)


# ============================================================================ the task
@dataclass
class ChunkTask:
    """Everything a worker needs to process one chunk (one tile)."""

    key: str
    tile: str
    neighbours: List[str]
    bounds: Tuple[float, float, float, float]       # xmin, ymin, xmax, ymax of the tile
    buffer: float
    origin: Tuple[float, float]
    cell_size: float
    crs: Optional[str]
    ground_filter: str
    dtm_method: str
    max_distance: float
    outputs: Dict[str, str] = field(default_factory=dict)   # LAS, DTM, DONE
    fail_once: bool = False                                   # tests: first attempt fails

    def buffered_box(self) -> Tuple[float, float, float, float]:
        """Tile bounds grown by the buffer."""
        b = self.buffer
        return (self.bounds[0] - b, self.bounds[1] - b, self.bounds[2] + b, self.bounds[3] + b)


def is_done(task: ChunkTask) -> Optional[dict]:
    """Stats of a chunk finished by an earlier run (marker and outputs present), else None."""
    done = task.outputs["DONE"]
    if not (os.path.exists(done) and all(os.path.exists(task.outputs[k])
                                         for k in ("LAS", "DTM"))):
        return None
    try:
        with open(done, encoding="utf-8") as fh:
            return json.load(fh)
    except (OSError, ValueError):
        return None


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


def classify_chunk(task: ChunkTask):
    """Read the tile and its buffer, run the ground filter; classes of the tile's points."""
    own = read_las(task.tile, ("classification",))
    nb, _ = read_box(task.neighbours, task.buffered_box(), ("classification",))
    x = np.concatenate([own.x, nb.x])
    y = np.concatenate([own.y, nb.y])
    z = np.concatenate([own.z, nb.z])
    dims = {"classification": np.concatenate([own["classification"],
                                              nb.dims.get("classification",
                                                          np.empty(0, np.uint8))])}
    cls = GROUND_FILTERS[task.ground_filter].func(x, y, z, dims, task.origin)
    return (x, y, z), np.asarray(cls, dtype=np.uint8), len(own)


def process_chunk(task: ChunkTask) -> dict:
    """Process one chunk end to end; returns its stats (also stored in the done marker)."""
    t0 = time.perf_counter()
    if task.fail_once:
        _fail_first_attempt(task)
    (x, y, z), cls, n_own = classify_chunk(task)
    t1 = time.perf_counter()
    grid = snap_grid(task.bounds, task.origin, task.cell_size, task.crs)
    g = cls == GROUND
    dtm = DTM_METHODS[task.dtm_method].func(x[g], y[g], z[g], grid, task.max_distance)
    t2 = time.perf_counter()
    outputs = {k: task.outputs[k] for k in ("LAS", "DTM")}
    with OutputContract(outputs, inputs={"TILES": [task.tile] + list(task.neighbours)}) as out:
        write_las_like(task.tile, out.path("LAS"), dimensions={"classification": cls[:n_own]})
        write_geotiff(out.path("DTM"), dtm, geotransform=grid.geotransform, crs=task.crs)
    t3 = time.perf_counter()
    stats = dict(key=task.key, status="done", points=int(n_own), buffer_points=int(x.size - n_own),
                 ground=int(np.count_nonzero(cls[:n_own] == GROUND)), seconds=t3 - t0,
                 filter_seconds=t1 - t0, dtm_seconds=t2 - t1, worker=_worker_name(),
                 bounds=list(task.bounds),
                 peak_rss_mb=resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0)
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

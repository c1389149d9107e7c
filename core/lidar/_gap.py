"""The DTM gap distance of a catalog: the single-file default of the merged cloud.

A single-file DTM (:func:`..terrain.dtm.make_dtm`) leaves a cell empty when its
nearest ground point is farther than five mean ground spacings
(:func:`..terrain.grid.default_max_distance` of the ground points' grid and count;
a TIN drops triangles with an edge over twice that). A catalog knows its ground
points only after every chunk is filtered, so the derivation is split:

1. each chunk interpolates its DTM without a gap limit and keeps, beside it, the
   distance from every cell centre to its nearest ground point (TIN: the longest
   edge², the smallest over the triangles holding the centre) — :func:`chunk_gaps`,
   ``.catalog/<chunk>.gap.npz`` — and counts its own ground points and their box;
   the chunk's DTM file is written with a provisional limit (10 mean point spacings
   from the headers) so that a run with failed chunks still has a sane mosaic;
2. when every chunk has finished, :func:`derived_gap` derives the gap distance once,
   from the whole catalog (the ground count and box summed over the chunks = the
   merged cloud's), and :func:`apply_gap` masks every chunk's DTM with it — the
   single-file rule, so the mosaic equals a single-file run of the merged cloud by
   construction (cells within the buffer of a chunk's edge aside, as for the values).

The masking is the gridders' own test (``d <= gap``; TIN ``edge² > limit²`` drops
the triangle), applied to the same distances, so nothing is approximated.
"""
from __future__ import annotations

import json
import os
from typing import List, Optional, Sequence

import numpy as np

from ..io.raster import write_geotiff
from ..terrain.grid import GridSpec, default_max_distance, grid_from_extent

__all__ = ["GAP_SUFFIX", "apply_gap", "chunk_gaps", "derived_gap", "gap_path",
           "ground_summary", "mask_with_gap", "write_marker"]

GAP_SUFFIX = ".gap.npz"
_DONE = ".done.json"


def gap_path(task) -> str:
    """``.catalog/<chunk>.gap.npz`` beside the chunk's done marker."""
    done = task.outputs["DONE"]
    return done[:-len(_DONE)] + GAP_SUFFIX if done.endswith(_DONE) else done + GAP_SUFFIX


def nearest_distance(x, y, grid: GridSpec, *, block: int = 262_144) -> np.ndarray:
    """Distance from every cell centre of ``grid`` to its nearest point (x, y)."""
    from scipy.spatial import cKDTree
    tree = cKDTree(np.column_stack([x, y]))
    out = np.empty(grid.size)
    rows = max(1, block // max(grid.ncols, 1))
    for r0 in range(0, grid.nrows, rows):
        r1 = min(grid.nrows, r0 + rows)
        cx, cy = grid.block_centers(r0, r1)
        out[r0 * grid.ncols:r1 * grid.ncols] = tree.query(np.column_stack([cx, cy]), k=1,
                                                          workers=1)[0]
    return out.reshape(grid.shape)


def chunk_gaps(method, x, y, z, grid: GridSpec):
    """DTM of a chunk without a gap limit, and the distances its gap test reads.

    Returns ``(z, gap)``: IDW and kriging — ``gap`` the distance from each cell centre to
    its nearest point; TIN — the smallest, over the triangles holding the centre, of the
    triangle's longest edge² (``inf`` outside the hull).
    """
    if method.key == "tin":
        from ..terrain.tin import tin_grid
        res = tin_grid(x, y, z, grid, fill=True, cell_edges=True)
        return res.z, res.cell_edge2
    res = method.interpolate(x, y, z, grid, max_distance=np.inf, workers=1)
    return res.z, nearest_distance(x, y, grid)


def mask_with_gap(z: np.ndarray, gap: np.ndarray, method_key: str,
                  distance: float) -> np.ndarray:
    """``z`` with NaN where the single-file rule would leave the cell empty."""
    if method_key == "tin":             # default_max_edge = 2 x the gap distance
        limit = 2.0 * distance
        keep = gap <= limit * limit
    else:
        keep = gap <= distance
    out = np.array(z, dtype=np.float64, copy=True)
    out[~keep] = np.nan
    return out


def ground_summary(x, y, *, distinct: bool = False) -> dict:
    """Return a chunk's own ground for the derivation: count, box (distinct positions).

    ``distinct`` (kriging, which merges duplicates, counts positions): also the number of
    distinct (x, y) positions.
    """
    x, y = np.asarray(x, np.float64), np.asarray(y, np.float64)
    ok = np.isfinite(x) & np.isfinite(y)
    x, y = x[ok], y[ok]
    if not x.size:
        return {"ground_finite": 0, "ground_unique": 0, "ground_box": None}
    out = {"ground_finite": int(x.size),
           "ground_box": [float(x.min()), float(y.min()), float(x.max()), float(y.max())]}
    if distinct:
        out["ground_unique"] = int(np.unique(np.column_stack([x, y]), axis=0).shape[0])
    return out


def derived_gap(chunks: Sequence[dict], *, cell_size: float, h: float,
                method_key: str) -> Optional[float]:
    """Return the gap distance of a single-file run of the merged cloud (tiles' units).

    ``cell_size`` in metres, ``h`` metres per horizontal unit of the tiles: the
    single-file runner works in metres (the ground box and cell converted), as here.
    Kriging counts distinct positions (it merges duplicates), IDW and TIN points.
    """
    boxes = [c["ground_box"] for c in chunks if c.get("ground_box")]
    key = "ground_unique" if method_key == "kriging" else "ground_finite"
    n = int(sum(c.get(key, 0) for c in chunks))
    if not boxes or n == 0:
        return None
    b = np.asarray(boxes, np.float64) * h
    grid = grid_from_extent((b[:, 0].min(), b[:, 2].max(), b[:, 1].min(), b[:, 3].max()),
                            cell_size)
    return default_max_distance(grid, n) / h


def apply_gap(tasks, chunks: List[dict], distance: float, *, method_key: str,
              grids) -> None:
    """Mask each chunk's DTM with the catalog's ``distance`` (from its ``.gap.npz``).

    Updates ``dtm_cells`` and ``gap_distance`` in the chunk stats and done markers;
    the ``.gap.npz`` files are removed by :func:`drop_gap_files` once the mosaic is made.
    """
    stats = {c["key"]: c for c in chunks}
    for task in tasks:
        path = gap_path(task)
        s = stats.get(task.key)
        if s is None or not os.path.exists(path):
            continue
        with np.load(path) as f:
            z = mask_with_gap(f["z"], f["gap"], method_key, distance)
        grid = grids(task)
        write_geotiff(task.outputs["DTM"], z, geotransform=grid.geotransform, crs=task.crs,
                      unit_type=task.units.vertical.symbol)
        s.update(dtm_cells=int(np.count_nonzero(np.isfinite(z))), gap_distance=distance)
        _update_marker(task, s)


def write_marker(task, stats: dict) -> None:
    """Write the chunk's done marker ``stats`` atomically.

    Written under a temporary name, then renamed: a crash leaves the previous marker or
    none, never a truncated one (the worker's marker and the gap pass's update alike).
    """
    done = task.outputs["DONE"]
    tmp = done + ".tmp"
    with open(tmp, "w", encoding="utf-8") as fh:
        json.dump(stats, fh)
    os.replace(tmp, done)


def _update_marker(task, stats: dict) -> None:
    write_marker(task, {k: v for k, v in stats.items() if k != "status" or v != "skipped"})


def drop_gap_files(tasks) -> None:
    """Remove the chunks' ``.gap.npz`` (the DTMs now carry the catalog's gap distance)."""
    for task in tasks:
        path = gap_path(task)
        if os.path.exists(path):
            os.remove(path)

"""Brute-force test oracles (not shipped): the truth the fast kernels are checked against.

Moved out of ``core/lidar/slope.py``: the exact slope kernel
(:mod:`geomatics_toolbox.core.lidar._slope_kernel`) must equal these pair-by-pair
references on every point (``tests/core/test_slope_filter.py``,
``benchmarks/bench_slope.py``).
"""
from __future__ import annotations

import numpy as np

from geomatics_toolbox.core.lidar._slope_kernel import (
    _canonical_slope,
    check_height,
    check_radius,
    check_slope,
    filter_xyz,
    point_mask,
    slope_tan,
)
from geomatics_toolbox.core.lidar.slope import (
    DEFAULT_HEIGHT_TOLERANCE,
    DEFAULT_RADIUS,
    DEFAULT_SLOPE,
)
from geomatics_toolbox.core.progress import Monitor

__all__ = ["max_slope_reference", "slope_filter_reference"]


def max_slope_reference(x, y, z, *, radius: float, height_tolerance: float = 0.0,
                        classify=None, neighbours=None, method: str = "kdtree",
                        chunk: int = 20000, progress=None, cancel=None) -> np.ndarray:
    """Brute-force ``S_i`` over *all* neighbour pairs (the speed and truth reference).

    ``method="dense"`` forms the full distance matrix (tiny clouds only);
    ``method="kdtree"`` gathers every pair within ``r`` with
    :meth:`scipy.spatial.cKDTree.sparse_distance_matrix` (search radius padded
    by 1e-9 relative, then the canonical comparison decides), in chunks.
    Returns ``nan`` for points not classified.
    """
    from scipy.spatial import cKDTree

    x, y, z = filter_xyz(x, y, z)
    r = check_radius(radius)
    h = check_height(height_tolerance)
    cm = point_mask(classify, x.size, "classify")
    nm = point_mask(neighbours, x.size, "neighbours")
    mon = Monitor(progress, cancel)
    pidx = np.flatnonzero(cm)
    qidx = np.flatnonzero(nm)
    out = np.full(x.size, np.nan)
    res = np.full(pidx.size, -np.inf)
    if qidx.size and pidx.size:
        if method == "dense":
            s = _canonical_slope(x[pidx][:, None], y[pidx][:, None], z[pidx][:, None],
                                 x[qidx][None, :], y[qidx][None, :], z[qidx][None, :], r, h)
            res = s.max(axis=1)
        elif method == "kdtree":
            tq = cKDTree(np.column_stack((x[qidx], y[qidx])))
            rr = r * (1 + 1e-9) + 1e-12
            for b in range(0, pidx.size, chunk):
                mon.step(b / pidx.size)
                p = pidx[b:b + chunk]
                tp = cKDTree(np.column_stack((x[p], y[p])))
                sm = tp.sparse_distance_matrix(tq, rr, output_type="ndarray")
                i, j = sm["i"], qidx[sm["j"]]
                s = _canonical_slope(x[p][i], y[p][i], z[p][i], x[j], y[j], z[j], r, h)
                part = np.full(p.size, -np.inf)
                np.maximum.at(part, i, s)
                res[b:b + chunk] = part
        else:
            raise ValueError(f"method must be 'dense' or 'kdtree', got {method!r}.")
    out[pidx] = res
    mon.update(1.0)
    return out


def slope_filter_reference(x, y, z, *, radius: float = DEFAULT_RADIUS,
                           slope: float = DEFAULT_SLOPE,
                           height_tolerance: float = DEFAULT_HEIGHT_TOLERANCE,
                           classify=None, neighbours=None, method: str = "kdtree",
                           progress=None, cancel=None) -> np.ndarray:
    """Brute-force ground labels (bool) with exactly the canonical comparison."""
    check_slope(slope)
    cm = point_mask(classify, np.size(x), "classify")
    s = max_slope_reference(x, y, z, radius=radius, height_tolerance=height_tolerance,
                            classify=cm, neighbours=neighbours, method=method,
                            progress=progress, cancel=cancel)
    return cm & ~(s > slope_tan(slope))

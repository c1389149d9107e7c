"""PTD's exact fast point location (core/lidar/_tin.find_simplex) and bench_ground's PTD merge."""
from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest
from scipy.spatial import Delaunay

from geomatics_toolbox.core.lidar import _tin

BENCH = Path(__file__).resolve().parents[2] / "benchmarks"


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_find_simplex_equals_scipy_in_original_order_on_a_lattice(seed):
    """Lattice points (like ISPRS: y on 0.5 m, x on 6 cm) put many queries on edges,
    vertices and outside the hull, where scipy's answer depends on the query order."""
    rng = np.random.default_rng(seed)
    pts = np.column_stack((rng.integers(0, 400, 3000) * 0.06, rng.integers(0, 60, 3000) * 0.5))
    pts = np.unique(pts, axis=0)
    tri = Delaunay(pts, qhull_options="Qbb Qc Qz Q12")
    q = np.column_stack((rng.integers(-20, 420, 20000) * 0.06,
                         rng.integers(-4, 64, 20000) * 0.25))
    q = np.r_[q, pts[rng.integers(0, pts.shape[0], 2000)]]      # on vertices too
    q = q[rng.permutation(q.shape[0])]
    ref = tri.find_simplex(q)
    got = _tin.find_simplex(tri, q)
    on_edge = ~_tin._clear_inside(tri, q, ref, 1e-9)
    assert on_edge.sum() > 1000 and (ref < 0).sum() > 100       # the hard cases occur
    assert np.array_equal(got, ref)
    # a different query order gives scipy another answer for some edge points
    perm = _tin.z_order(q[:, 0], q[:, 1])
    assert not np.array_equal(tri.find_simplex(q[perm]), ref[perm])


def test_locate_outside_points_get_nearest_centroid():
    tri = Delaunay(np.array([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0]]))
    s = _tin.locate(tri, np.array([0.9, 5.0]), np.array([0.8, 5.0]))
    cen = tri.points[tri.simplices].mean(axis=1)
    assert s[1] == np.argmin(np.hypot(*(cen - [5.0, 5.0]).T))
    assert s[0] == tri.find_simplex([[0.9, 0.8]])[0]


def _bench():
    sys.path.insert(0, str(BENCH))
    try:
        import bench_ground
    finally:
        sys.path.remove(str(BENCH))
    return bench_ground


def test_merge_ptd_puts_the_speed_row_inside_the_table():
    bg = _bench()
    head = "| filter | points | wall s |\n|---|---|---|\n"
    old = ("## Throughput and peak memory\n\n" + head + "| smrf | 10 | 1.0 |\n"
           "| ptd (1 M window) | 5 | 9.0 |\n| csf (previous run) | 10 | 2.0 |\n\n"
           "Rows marked (previous run) were not re-timed.\n\n"
           "PTD rows re-measured on then with `bench_ground.py --ptd`.\n")
    speed = [dict(n=1_000_000, wall=10.0, cpu=8.0, peak_mb=100.0, base_mb=60.0, total=0.2)]
    lines = bg.merge_ptd(old, None, speed, False).splitlines()
    table = lines[2:7]
    assert all(ln.startswith("|") for ln in table) and lines[7] == ""
    assert table[3].startswith("| ptd (1 M window) | 1,000,000 | 10.0 | 8.0 | 125,000 | 100 ")
    assert table[4].startswith("| csf (previous run)")
    assert sum(ln.startswith("| ptd") for ln in lines) == 1
    assert sum(ln.startswith("PTD rows re-measured") for ln in lines) == 1
    # no ptd row yet: appended as the table's last row, before the note
    lines = bg.merge_ptd(old.replace("| ptd (1 M window) | 5 | 9.0 |\n", ""), None, speed,
                         False).splitlines()
    assert lines[6].startswith("| ptd (1 M window) | 1,000,000") and lines[7] == ""

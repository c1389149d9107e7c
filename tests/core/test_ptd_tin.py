"""PTD's TIN and point location (core/lidar/_tin.Tin) and bench_ground's PTD merge."""
from __future__ import annotations

import sys
from pathlib import Path

import numpy as np
import pytest
from scipy.spatial import Delaunay

from geomatics_toolbox.core.lidar import _tin

BENCH = Path(__file__).resolve().parents[2] / "benchmarks"


def _inside(tin, f, q, tol=1e-9):
    """Whether each point of ``q`` lies in (or on the boundary of) facet ``f``."""
    v = tin.xy[tin.simplices[f]]
    o = np.stack([(v[:, (i + 2) % 3, 0] - v[:, (i + 1) % 3, 0]) * (q[:, 1] - v[:, (i + 1) % 3, 1])
                  - (v[:, (i + 2) % 3, 1] - v[:, (i + 1) % 3, 1]) * (q[:, 0] - v[:, (i + 1) % 3, 0])
                  for i in range(3)], axis=1)
    return (o >= -tol).all(axis=1)


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_locate_finds_a_facet_holding_every_point_on_a_lattice(seed):
    """Lattice points (like ISPRS: y on 0.5 m, x on 6 cm) put many queries on edges and
    vertices: the walk returns a facet holding the point, scipy's own where that is
    unique; points outside the hull get a hull facet."""
    rng = np.random.default_rng(seed)
    pts = np.column_stack((rng.integers(0, 400, 3000) * 0.06, rng.integers(0, 60, 3000) * 0.5))
    pts = np.unique(pts, axis=0)
    tin = _tin.Tin(pts[:, 0], pts[:, 1], rng.normal(size=pts.shape[0]))
    tri = Delaunay(pts, qhull_options="Qbb Qc Qz Q12")
    q = np.column_stack((rng.integers(-20, 420, 20000) * 0.06,
                         rng.integers(-4, 64, 20000) * 0.25))
    q = np.r_[q, pts[rng.integers(0, pts.shape[0], 2000)]]      # on vertices too
    ref = tri.find_simplex(q)
    for start in (None, rng.integers(0, tin.simplices.shape[0], q.shape[0])):
        f = tin.locate(q[:, 0], q[:, 1], start)
        inside = ref >= 0
        assert _inside(tin, f[inside], q[inside]).all()
        # Qhull's facets in Qhull's order: where the point is strictly inside, same facet
        strict = inside & _inside(tin, ref.clip(0), q, tol=-1e-9)
        assert strict.sum() > 5000
        assert np.array_equal(f[strict], ref[strict])
        assert np.all(tin.neighbors[f[~inside]].min(axis=1) == -1)     # hull facets


def test_tin_facets_counter_clockwise_with_upward_normals():
    rng = np.random.default_rng(4)
    x, y = rng.uniform(0, 50, 400), rng.uniform(0, 50, 400)
    tin = _tin.Tin(x, y, 0.3 * x - 0.1 * y)
    c = tin.corners
    area = ((c[:, 1, 0] - c[:, 0, 0]) * (c[:, 2, 1] - c[:, 0, 1])
            - (c[:, 1, 1] - c[:, 0, 1]) * (c[:, 2, 0] - c[:, 0, 0]))
    assert (area > 0).all()
    assert np.allclose(tin.normal, np.array([-0.3, 0.1, 1.0]) / np.sqrt(1.1))
    d, dz, ang, f = tin.distances(np.array([10.0]), np.array([20.0]), np.array([3.0]))
    assert dz[0] == pytest.approx(3.0 - (3.0 - 2.0)) and d[0] == pytest.approx(2.0 / np.sqrt(1.1))
    assert np.all(tin.neighbors[tin.neighbors >= 0] < tin.simplices.shape[0])


def test_opposite_vertices_against_brute_force():
    rng = np.random.default_rng(5)
    x, y = rng.uniform(0, 30, 300), rng.uniform(0, 30, 300)
    tin = _tin.Tin(x, y, np.zeros(300))
    for f in range(tin.simplices.shape[0]):
        for i in range(3):
            g = tin.neighbors[f, i]
            if g < 0:
                assert tin.opposite[f, i] == -1
                continue
            shared = {tin.simplices[f, (i + 1) % 3], tin.simplices[f, (i + 2) % 3]}
            assert shared < set(tin.simplices[g])
            assert {tin.opposite[f, i]} == set(tin.simplices[g]) - shared


def test_regional_slope_keeps_a_plane_and_flattens_a_spike():
    """On a plane every facet's neighbourhood has the plane's slope; around one vertex
    standing 0.8 m above a flat 1 m grid (a shrub taken for ground) the facets are steep
    but their neighbourhoods are not."""
    rng = np.random.default_rng(6)
    x, y = rng.uniform(0, 40, 500), rng.uniform(0, 40, 500)
    tin = _tin.Tin(x, y, 0.3 * x - 0.1 * y)
    assert np.allclose(tin.regional_tan(1), np.hypot(0.3, 0.1))
    g = np.arange(0.0, 21.0)
    gx, gy = (a.ravel() for a in np.meshgrid(g, g))
    gx, gy = gx + rng.uniform(-0.2, 0.2, gx.size), gy + rng.uniform(-0.2, 0.2, gy.size)
    gz = np.where(np.hypot(gx - 10, gy - 10) < 0.5, 0.8, 0.0)
    assert np.count_nonzero(gz) == 1
    tin = _tin.Tin(gx, gy, gz)
    spike = np.flatnonzero(gz)[0]
    around = (tin.simplices == spike).any(axis=1)
    facet_tan = np.sqrt(1.0 / tin.normal[:, 2] ** 2 - 1.0)
    assert facet_tan[around].min() > 0.5
    assert (tin.regional_tan(1)[around] < 0.75 * facet_tan[around]).all()


@pytest.mark.parametrize("slope", [0.0, 0.3])
def test_one_layer_rejects_points_standing_on_lower_ground(slope):
    """Vertices on a 1 m grid over a plane rising ``slope``: a point 0.6 m above the
    ground (more than the final distance 0.5 over the rise to its lowest vertex within
    the cell, 2 m) is not ground, one 0.3 m above is; the same point beside a vertex of
    a breakline facet (a cliff foot) is not compared with it; frame points (index >=
    n_ground) never count."""
    from geomatics_toolbox.core.lidar import ptd
    opt = ptd.PtdOptions()
    rng = np.random.default_rng(7)
    g = np.arange(0.0, 21.0)
    gx, gy = (a.ravel() for a in np.meshgrid(g, g))
    gx, gy = gx + rng.uniform(-0.2, 0.2, gx.size), gy + rng.uniform(-0.2, 0.2, gy.size)
    tin = _tin.Tin(gx, gy, slope * gx)
    px, py = rng.uniform(5, 15, 200), rng.uniform(5, 15, 200)
    up = np.where(np.arange(200) % 2 == 0, 0.6, 0.3)
    pz = slope * px + up
    s = tin.locate(px, py)
    rise, no_cliff = tin.regional_tan(1), np.zeros(tin.z.size, bool)
    ok = np.ones(200, bool)
    _tin.one_layer(tin, px, py, pz, s, ok, gx.size, rise, no_cliff, opt)
    assert np.array_equal(ok, up < 0.5)
    ok = np.ones(200, bool)
    _tin.one_layer(tin, px, py, pz, s, ok, gx.size, rise, np.ones(tin.z.size, bool), opt)
    assert ok.all()
    ok = np.ones(200, bool)
    _tin.one_layer(tin, px, py, pz, s, ok, 0, rise, no_cliff, opt)
    assert ok.all()


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


def _canonical(s):
    s = np.sort(s, axis=1)
    return s[np.lexsort(s.T[::-1])]


@pytest.mark.parametrize("seed", [0, 1])
def test_insert_gives_the_facets_of_a_rebuild_with_consistent_neighbours(seed):
    """Points inserted a batch at a time (cavities re-triangulated, spliced in) give the
    facets of a Qhull rebuild, every neighbour across its shared edge, both ways."""
    rng = np.random.default_rng(seed)
    n = 6000        # the last 4: a frame around the others (as PTD's, with_corners)
    x = np.r_[rng.uniform(0, 300, n - 4), -1, 301, 301, -1]
    y = np.r_[rng.uniform(0, 200, n - 4), -1, -1, 201, 201]
    z = rng.normal(size=n)
    have = np.zeros(n, bool)
    have[rng.choice(n - 4, 200, replace=False)] = True
    have[-4:] = True
    tin = _tin.Tin(x[have], y[have], z[have])
    for batch in (50, 400, 2000, 3000):
        idx = np.flatnonzero(have)
        new = rng.choice(np.flatnonzero(~have), batch, replace=False)
        hint = tin.locate(x[new], y[new])
        have[new] = True
        now = np.flatnonzero(have)
        got = _tin.insert(tin, x[now], y[now], z[now] + 1.0, np.searchsorted(now, idx),
                          np.searchsorted(now, new), hint)
        ref = _tin.Tin(x[now], y[now], z[now] + 1.0)
        assert np.array_equal(_canonical(got.simplices), _canonical(ref.simplices))
        s, nb = got.simplices, got.neighbors
        for i in range(3):
            f = np.flatnonzero(nb[:, i] >= 0)
            g = nb[f, i]
            assert (nb[g] == f[:, None]).sum(axis=1).tolist() == [1] * f.size
            shared = np.sort(np.stack([s[f, (i + 1) % 3], s[f, (i + 2) % 3]], axis=1), axis=1)
            assert ((s[g][:, :, None] == shared[:, None, :]).any(axis=2).sum(axis=1) == 2).all()
            assert (np.sort(s[g], axis=1) != np.sort(s[f], axis=1)).any(axis=1).all()
        assert (nb < 0).sum() == (ref.neighbors < 0).sum()
        assert np.allclose(np.sort(got.edge), np.sort(ref.edge))
        # facets kept with their heights keep their geometry: the same bits as computed anew
        # (the first batch changes every height, the others none)
        for mine, anew in zip((got.corners, got.normal, got.edge),
                              _tin._geometry(got.xy, got.z, got.simplices)):
            assert np.array_equal(mine, anew)
        tin = got
    # a wrong hint (a facet not holding the point) is caught: None, the caller rebuilds
    now = np.flatnonzero(have)
    extra = np.array([[150.123, 100.456]])
    far = np.argmax(np.hypot(*(tin.xy[tin.simplices[:, 0]] - extra).T))
    assert _tin.insert(tin, np.r_[x[now], extra[:, 0]], np.r_[y[now], extra[:, 1]],
                       np.r_[z[now], 0.0], np.arange(now.size), np.array([now.size]),
                       np.array([far])) is None


def test_locate_outside_the_hull_gives_the_nearest_hull_facet_from_any_start():
    """Outside the hull the walk would stop where it leaves the TIN (path-dependent):
    the nearest hull facet (brute force over hull edges) from every start."""
    rng = np.random.default_rng(4)
    pts = rng.uniform(0, 100, (500, 2))
    tin = _tin.Tin(pts[:, 0], pts[:, 1], np.zeros(500))
    ang = rng.uniform(0, 2 * np.pi, 300)
    q = 50 + np.column_stack((np.cos(ang), np.sin(ang))) * rng.uniform(75, 120, (300, 1))
    f, i = np.nonzero(tin.neighbors < 0)
    a, b = tin.xy[tin.simplices[f, (i + 1) % 3]], tin.xy[tin.simplices[f, (i + 2) % 3]]
    t = np.clip(((q[:, None] - a) * (b - a)).sum(axis=2) / ((b - a) ** 2).sum(axis=1), 0, 1)
    dist = np.hypot(*(q[:, None] - a - t[..., None] * (b - a)).transpose(2, 0, 1))
    for start in (None, rng.integers(0, tin.simplices.shape[0], q.shape[0]),
                  np.zeros(q.shape[0], np.int64)):
        got = tin.locate(q[:, 0], q[:, 1], start)
        assert (tin.neighbors[got] < 0).any(axis=1).all()
        # the nearest hull edge's facet (distance equal to the minimum: ties at a hull
        # vertex may pick either facet of that vertex, the same one from every start)
        best = dist.min(axis=1)
        mine = np.array([dist[k, f == g].min() for k, g in enumerate(got)])
        assert np.allclose(mine, best, atol=1e-9)
        if start is None:
            first = got
        assert np.array_equal(got, first)

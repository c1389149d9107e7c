"""Tests of the synthetic labelled LiDAR generator (core/synthetic.py)."""
from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import cKDTree

from geomatics_toolbox.synthetic import lidar as syn
from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile

KW = dict(extent=(200.0, 180.0), density=3.0, seed=11)


@pytest.fixture(scope="module")
def tile():
    return generate_tile(**KW)


ARRAYS = ("x", "y", "z", "classification", "return_number", "number_of_returns",
          "intensity", "gps_time", "scan_angle", "point_source_id")


def test_dtypes_and_lengths(tile):
    n = len(tile)
    assert n > 50_000
    for name in ARRAYS:
        assert getattr(tile, name).shape == (n,), name
    assert tile.x.dtype == tile.y.dtype == tile.z.dtype == np.float64
    assert tile.classification.dtype == np.uint8
    assert tile.return_number.dtype == tile.number_of_returns.dtype == np.uint8
    assert tile.intensity.dtype == np.uint16
    assert set(tile.dimensions()) >= {"classification", "return_number",
                                      "number_of_returns", "intensity", "gps_time"}


def test_deterministic_same_seed(tile):
    again = generate_tile(**KW)
    for name in ARRAYS:
        np.testing.assert_array_equal(getattr(tile, name), getattr(again, name), name)
    cp1, cp2 = tile.checkpoints(20), again.checkpoints(20)
    np.testing.assert_array_equal(cp1.x, cp2.x)
    np.testing.assert_array_equal(cp1.z, cp2.z)


def test_other_seed_differs(tile):
    other = generate_tile(**{**KW, "seed": 12})
    assert len(other) != len(tile) or not np.array_equal(other.z, tile.z)


def test_inside_tile_and_on_the_scale_grid(tile):
    x0, y0, x1, y1 = tile.bounds
    assert tile.x.min() >= x0 - 0.05 and tile.x.max() <= x1 + 0.05
    assert tile.y.min() >= y0 - 0.05 and tile.y.max() <= y1 + 0.05
    for v in (tile.x, tile.y, tile.z):
        assert np.abs(v / 0.01 - np.round(v / 0.01)).max() < 1e-5


def test_classes_present_in_expected_proportions(tile):
    cls = tile.classification
    assert set(np.unique(cls)) == {2, 5, 6, 7, 18}
    frac = {k: np.mean(cls == k) for k in (2, 5, 6)}
    assert 0.40 < frac[2] < 0.85, frac
    assert 0.10 < frac[5] < 0.45, frac
    assert 0.02 < frac[6] < 0.25, frac
    n7, n18 = np.sum(cls == 7), np.sum(cls == 18)
    assert 3 <= n7 <= 0.001 * cls.size and 2 <= n18 <= 0.001 * cls.size


def test_ground_points_lie_on_the_true_terrain(tile):
    g = tile.classification == syn.GROUND
    resid = tile.z[g] - tile.terrain(tile.x[g], tile.y[g])
    assert np.abs(resid).max() <= 6 * tile.noise + 0.006
    assert abs(resid.mean()) < 0.01
    assert 0.8 * tile.noise < resid.std() < 1.2 * tile.noise


def test_buildings_and_vegetation_above_terrain(tile):
    cls = tile.classification
    hag = tile.z - tile.terrain(tile.x, tile.y)
    b = cls == syn.BUILDING
    assert hag[b].min() > 0.5
    # roof points (not wall points) are inside a footprint and at least ~3 m up
    d = tile.buildings.distance(tile.x[b], tile.y[b])
    roof = d == 0
    assert roof.mean() > 0.9
    assert hag[b][roof].min() > 2.5
    assert d.max() < 0.05                                 # walls: on the outline
    v = cls == syn.HIGH_VEGETATION
    assert hag[v].min() >= 0.25
    assert np.all(tile.trees.distance(tile.x[v], tile.y[v]) == 0)
    assert np.median(hag[v]) > 4


def test_noise_points_below_and_above(tile):
    hag = tile.z - tile.terrain(tile.x, tile.y)
    assert np.all(hag[tile.classification == syn.LOW_NOISE] < -1.4)
    assert np.all(hag[tile.classification == syn.HIGH_NOISE] > 39)


def test_no_ground_inside_buildings(tile):
    g = tile.classification == syn.GROUND
    assert tile.buildings.distance(tile.x[g], tile.y[g]).min() > 0


def test_building_sizes_and_roof_types():
    t = generate_tile(extent=(300.0, 300.0), density=0.5, seed=5)
    b = t.buildings
    length = 2 * b.half_length
    assert length.max() >= 60                              # a hall
    assert np.sum((length >= 8) & (length <= 15)) >= 5     # houses
    assert b.gabled.any() and (~b.gabled).any()
    assert b.kind.tolist().count(2) >= 1


def test_returns_are_consistent(tile):
    rn, nr = tile.return_number, tile.number_of_returns
    assert rn.min() == 1 and nr.min() == 1 and nr.max() <= 5
    assert np.all(rn <= nr)
    assert nr.max() >= 4
    assert np.all(np.diff(tile.gps_time) >= 0)             # acquisition order
    # within a pulse the returns follow each other 1..n with one gps_time
    starts = np.flatnonzero(rn == 1)
    assert np.all(nr[starts] == np.diff(np.append(starts, rn.size)))
    assert np.all(tile.gps_time[starts][1:] > tile.gps_time[starts][:-1])
    # later returns are lower than the first of their pulse
    first_z = np.repeat(tile.z[starts], nr[starts])
    assert np.all(tile.z <= first_z + 1e-9)


def test_canopy_penetration(tile):
    cls, rn, nr = tile.classification, tile.return_number, tile.number_of_returns
    g = cls == syn.GROUND
    under = g & (tile.trees.distance(tile.x, tile.y) == 0)
    assert under.sum() > 0.05 * np.sum(cls == syn.HIGH_VEGETATION)
    # ground under crowns comes as the last of several returns
    assert np.all(rn[under] == nr[under]) and np.all(nr[under] >= 2)
    last_of_multi = (rn == nr) & (nr > 1)
    assert 0.3 < np.mean(cls[last_of_multi] == syn.GROUND) < 0.9
    # the first return of a multi-return pulse is vegetation
    assert np.all(cls[(rn == 1) & (nr > 1)] == syn.HIGH_VEGETATION)


def test_cliff_and_steep_hillside(tile):
    t = tile.terrain
    nx, ny, d0, height, width = t.cliff
    assert height > 0 and width <= 1.0
    # sample along the cliff line, inside the tile
    x0, y0, x1, y1 = tile.bounds
    s = np.linspace(-500, 500, 4001)
    px = t.origin[0] + nx * d0 - ny * s
    py = t.origin[1] + ny * d0 + nx * s
    inside = (px > x0) & (px < x1) & (py > y0) & (py < y1)
    px, py = px[inside], py[inside]
    assert px.size > 50
    assert t.slope_deg(px, py).min() > 70                  # near-vertical step
    step = t(px + 2 * nx, py + 2 * ny) - t(px - 2 * nx, py - 2 * ny)
    off_hill = np.abs(t.hill_distance(px, py)) > 2.5 * t.hill[4]   # not on the hillside
    assert np.all(np.abs(step[off_hill] - height) < 1.5)
    assert np.all(step > 0.5 * height)
    # a steep hillside of about hill_slope_deg
    gx, gy = np.meshgrid(np.linspace(x0, x1, 150), np.linspace(y0, y1, 150))
    slope = t.slope_deg(gx, gy)
    far = np.abs(t.cliff_distance(gx, gy)) > 3
    assert 28 < slope[far].max() < 55
    # the ground points see the step too: neighbours 1-3 m apart, > 3 m height jump
    g = tile.classification == syn.GROUND
    near = g & (np.abs(t.cliff_distance(tile.x, tile.y)) < 3)
    up = near & (t.cliff_distance(tile.x, tile.y) > 0.6)
    down = near & (t.cliff_distance(tile.x, tile.y) < -0.6)
    tree = cKDTree(np.column_stack([tile.x[down], tile.y[down]]))
    d, j = tree.query(np.column_stack([tile.x[up], tile.y[up]]))
    assert np.median((tile.z[up] - tile.z[down][j])[d < 3]) > 0.6 * height


def test_density_within_tolerance(tile):
    assert abs(len(tile) / tile.area - KW["density"]) / KW["density"] < 0.03
    # first returns (pulses) are spread evenly: 20 m cells within ±35 % of the median
    first = tile.return_number == 1
    h, _, _ = np.histogram2d(tile.x[first], tile.y[first], bins=(10, 9),
                             range=[[tile.bounds[0], tile.bounds[2]],
                                    [tile.bounds[1], tile.bounds[3]]])
    med = np.median(h)
    assert h.min() > 0.65 * med and h.max() < 1.35 * med


@pytest.mark.parametrize("density", [0.5, 12.0])
def test_density_parameter(density):
    t = generate_tile(extent=(100.0, 100.0), density=density, seed=3)
    assert abs(len(t) / t.area - density) / density < 0.06


@pytest.mark.parametrize("cover", [0.1, 0.25, 0.6])
def test_tree_cover_is_the_realised_crown_cover(cover):
    t = generate_tile(extent=(200.0, 200.0), density=0.5, seed=4, tree_cover=cover)
    gx, gy = np.meshgrid(np.arange(t.bounds[0] + 0.5, t.bounds[2], 1.0),
                         np.arange(t.bounds[1] + 0.5, t.bounds[3], 1.0))
    real = np.mean(t.trees.distance(gx.ravel(), gy.ravel()) == 0)
    assert abs(real - cover) < 0.03
    assert abs(len(t) / t.area - 0.5) < 0.03


def test_checkpoints_on_open_ground(tile):
    cp = tile.checkpoints(40)
    assert len(cp) == 40 and list(cp.id) == list(range(1, 41))
    np.testing.assert_allclose(cp.z, tile.terrain(cp.x, cp.y))
    assert tile.buildings.distance(cp.x, cp.y).min() >= 3
    assert tile.trees.distance(cp.x, cp.y).min() >= 3
    assert np.abs(tile.terrain.cliff_distance(cp.x, cp.y)).min() >= 5
    assert tile.terrain.slope_deg(cp.x, cp.y).max() <= 15
    assert tile.open_ground(cp.x, cp.y).all()
    # every point within 2 m of a check point is ground (or a stray noise point)
    kd = cKDTree(np.column_stack([tile.x, tile.y]))
    near = np.unique(np.concatenate(kd.query_ball_point(np.column_stack([cp.x, cp.y]), 2.0)))
    assert np.isin(tile.classification[near], (2, 7, 18)).all()
    # spread out
    d, _ = cKDTree(np.column_stack([cp.x, cp.y])).query(np.column_stack([cp.x, cp.y]), k=2)
    assert d[:, 1].min() > 5


def test_checkpoints_impossible_request_is_clear(tile):
    with pytest.raises(ValueError, match="check points"):
        tile.checkpoints(50, min_spacing=60.0)


def test_terrain_is_defined_everywhere(tile):
    x = np.array([tile.bounds[0] - 1000.0, tile.bounds[2] + 50.0])
    z = tile.terrain(x, np.array([tile.bounds[1], tile.bounds[3] + 1e4]))
    assert np.isfinite(z).all()
    assert np.isscalar(float(tile.terrain(tile.bounds[0], tile.bounds[1])))


@pytest.mark.parametrize("kw, word", [
    (dict(density=0), "density"),
    (dict(density=-1), "density"),
    (dict(extent=(0, 100)), "extent"),
    (dict(tree_cover=1.5), "tree_cover"),
    (dict(canopy_penetration=2), "canopy_penetration"),
    (dict(n_trees=-1), "n_trees"),
])
def test_bad_parameters(kw, word):
    with pytest.raises(ValueError, match=word):
        generate_tile(**kw)


def test_knobs_switch_things_off():
    t = generate_tile(extent=(120.0, 120.0), density=2.0, seed=1, n_buildings=0,
                      n_halls=0, tree_cover=0.0, cliff_height=0.0, hill_height=0.0,
                      n_low_outliers=0, n_high_noise=0)
    assert set(np.unique(t.classification)) == {2}
    assert np.all(t.number_of_returns == 1)
    assert t.terrain.slope_deg(t.x[::50], t.y[::50]).max() < 20


def test_write_tile_round_trip(tile, tmp_path):
    from geomatics_toolbox.core.io.las import las_info, read_las
    path = tmp_path / "tile.laz"
    assert write_tile(tile, path) == len(tile)
    info = las_info(path)
    assert info.point_format == 6 and info.version == "1.4" and info.compressed
    assert info.crs and "32632" in info.crs
    data = read_las(path, ("classification", "return_number", "number_of_returns",
                           "intensity", "gps_time"))
    np.testing.assert_allclose(data.x, tile.x, atol=1e-6)
    np.testing.assert_allclose(data.z, tile.z, atol=1e-6)
    np.testing.assert_array_equal(data["classification"], tile.classification)
    np.testing.assert_array_equal(data["return_number"], tile.return_number)
    np.testing.assert_array_equal(data["number_of_returns"], tile.number_of_returns)
    np.testing.assert_array_equal(data["intensity"], tile.intensity)
    np.testing.assert_array_equal(data["gps_time"], tile.gps_time)


def test_large_tile():
    """A million-point tile (the generator is vectorised: ~0.6 s; speed lives in
    benchmarks/bench_synthetic.py, not in a timed test)."""
    t = generate_tile(extent=(400.0, 500.0), density=5.0, seed=2)
    assert len(t) > 900_000

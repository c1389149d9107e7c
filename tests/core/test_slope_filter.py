"""Tests of the Vosselman slope filter (core/slope_filter.py, core/slope_pipeline.py)."""
from __future__ import annotations

import os

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from scipy.spatial import cKDTree

from geomatics_toolbox.core.errors import InputError
from geomatics_toolbox.core.io.las import read_las, write_las, write_las_like
from geomatics_toolbox.core.lidar import _slope_kernel as sk
from geomatics_toolbox.core.lidar import pipeline as sp
from geomatics_toolbox.core.lidar import slope as sf
from geomatics_toolbox.core.lidar import sweep as sw
from geomatics_toolbox.core.lidar.pipeline import FilterOutputs, SelectionOptions
from geomatics_toolbox.core.progress import Cancelled, Monitor
from geomatics_toolbox.synthetic import oracles

SAMPLES = ("samp11", "samp12", "samp31", "samp54")


# --------------------------------------------------------------------------- property
@st.composite
def clouds(draw):
    """Clouds on a coarse lattice: many duplicates, equal heights, exact distances."""
    n = draw(st.integers(1, 90))
    step = draw(st.sampled_from([0.5, 0.6, 1.0, 0.3]))
    side = draw(st.integers(1, 9))
    ix = draw(st.lists(st.integers(0, side), min_size=n, max_size=n))
    iy = draw(st.lists(st.integers(0, side), min_size=n, max_size=n))
    iz = draw(st.lists(st.integers(-4, 4), min_size=n, max_size=n))
    zstep = draw(st.sampled_from([0.25, 0.5, 1.0, 0.3]))
    offset = draw(st.sampled_from([0.0, 512_345.67, 4_123_456.0]))
    x = offset + np.array(ix, float) * step
    y = -offset / 3 + np.array(iy, float) * step * draw(st.sampled_from([1.0, 4 / 3]))
    z = 100.0 + np.array(iz, float) * zstep
    # radii that hit lattice distances exactly (1, 2, 5 steps; 3-4-5 triangles)
    radius = step * draw(st.sampled_from([1.0, 2.0, 5.0, 1.5, 0.5])) * draw(
        st.sampled_from([1.0, 4 / 3]))
    slope = draw(st.sampled_from([10.0, 26.565051177077986, 40.0, 45.0, 60.0, 80.0]))
    h = draw(st.sampled_from([0.0, 0.0, 0.25, 0.5]))
    classify = np.array(draw(st.lists(st.booleans(), min_size=n, max_size=n)))
    neighbours = np.array(draw(st.lists(st.booleans(), min_size=n, max_size=n)))
    use_masks = draw(st.booleans())
    cell = draw(st.sampled_from([None, None, 0.07, 0.4, 1.0, 3.0]))
    return dict(x=x, y=y, z=z, radius=radius, slope=slope, h=h, cell=cell,
                classify=classify if use_masks else None,
                neighbours=neighbours if use_masks else None)


@settings(max_examples=150, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(clouds())
def test_labels_equal_brute_force(c):
    """Fast filter == dense brute force == KD-tree brute force, exactly, on every point."""
    kw = dict(radius=c["radius"], height_tolerance=c["h"], classify=c["classify"],
              neighbours=c["neighbours"])
    if np.unique(np.column_stack([c["x"], c["y"]]), axis=0).shape[0] < 2:
        with pytest.raises(InputError):     # one point / one position: refused
            sf.slope_filter(c["x"], c["y"], c["z"], slope=c["slope"], cell=c["cell"], **kw)
        return
    fast = sf.slope_filter(c["x"], c["y"], c["z"], slope=c["slope"], cell=c["cell"], **kw)
    dense = oracles.slope_filter_reference(c["x"], c["y"], c["z"], slope=c["slope"],
                                      method="dense", **kw)
    tree = oracles.slope_filter_reference(c["x"], c["y"], c["z"], slope=c["slope"],
                                     method="kdtree", **kw)
    np.testing.assert_array_equal(fast.ground, dense)
    np.testing.assert_array_equal(tree, dense)
    # the sweep's one-pass labels agree for every threshold of a range
    s = oracles.max_slope_reference(c["x"], c["y"], c["z"], method="dense", **kw)
    v = sf.max_slope(c["x"], c["y"], c["z"], slope_range=(20.0, 60.0), cell=c["cell"], **kw)
    for theta in (20.0, 26.565051177077986, 40.0, 45.0, 60.0):
        t = np.tan(np.radians(theta))
        np.testing.assert_array_equal(v > t, s > t)


def test_random_float_clouds_with_objects():
    """Larger random clouds (bounds do most of the work) still match exactly."""
    rng = np.random.default_rng(7)
    for r in (1.0, 3.0, 6.0):
        n = 4000
        x = 500_000 + rng.uniform(0, 40, n)
        y = 4_000_000 + rng.uniform(0, 40, n)
        z = 200 + 0.4 * x % 9 + rng.normal(0, 0.1, n)
        obj = rng.random(n) < 0.3
        z[obj] += rng.uniform(0.2, 15, obj.sum())
        ref = oracles.max_slope_reference(x, y, z, radius=r, height_tolerance=0.1)
        all_pairs = 2 * len(cKDTree(np.column_stack((x, y))).query_pairs(r))
        for theta in (30.0, 45.0, 60.0):
            got = sf.slope_filter(x, y, z, radius=r, slope=theta, height_tolerance=0.1)
            np.testing.assert_array_equal(got.ground, ~(ref > np.tan(np.radians(theta))))
            # the bounds prune: far fewer exact pair tests than neighbour pairs
            if r >= 3:
                assert got.stats["pairs_tested"] < 0.5 * all_pairs


def test_tiling_of_huge_extents_is_exact(monkeypatch):
    """Clouds too large for one dense grid are tiled with an r-wide overlap: same labels."""
    monkeypatch.setattr(sk, "_MAX_CELLS", 2000)
    rng = np.random.default_rng(9)
    n = 3000
    x = 600_000 + np.r_[rng.uniform(0, 30, n // 2), rng.uniform(500, 530, n // 2)]
    y = np.r_[rng.uniform(0, 30, n // 2), rng.uniform(200, 230, n // 2)]
    z = rng.normal(0, 0.3, n) + (rng.random(n) < 0.3) * rng.uniform(0, 5, n)
    ref = oracles.max_slope_reference(x, y, z, radius=2.5, height_tolerance=0.1)
    for theta in (30.0, 45.0):
        got = sf.slope_filter(x, y, z, radius=2.5, slope=theta, height_tolerance=0.1)
        np.testing.assert_array_equal(got.ground, ~(ref > np.tan(np.radians(theta))))


# --------------------------------------------------------------------------- edge cases
def test_neighbour_exactly_at_radius_is_included():
    x = np.array([0.0, 3.0])
    y = np.zeros(2)
    z = np.array([2.6, 0.0])          # 2.6 m above a point 3 m away; 40 deg allows 2.517
    assert sf.slope_filter(x, y, z, radius=3.0, slope=40, height_tolerance=0).ground.tolist() \
        == [False, True]
    assert sf.slope_filter(x, y, z, radius=2.999, slope=40,
                           height_tolerance=0).ground.tolist() == [True, True]
    # a 3-4-5 triangle: d = 5 exactly
    x, y, z = np.array([0.0, 3.0]), np.array([0.0, 4.0]), np.array([5.0, 0.0])
    assert sf.slope_filter(x, y, z, radius=5.0, slope=44, height_tolerance=0).ground.tolist() \
        == [False, True]


def test_duplicates_are_not_neighbours_and_equal_heights_never_reject():
    x = np.array([1.0, 1.0, 1.0, 2.0])
    y = np.array([1.0, 1.0, 1.0, 1.0])
    z = np.array([0.0, 50.0, 50.0, 50.0])   # 50 m stacked above point 0 (d = 0)
    g = sf.slope_filter(x, y, z, radius=3.0, slope=45, height_tolerance=0).ground
    # points 1 and 2 stand exactly on point 0 (d = 0: not neighbours) and level with
    # point 3, so they are ground; point 3 is 1 m from point 0 and 50 m above it
    assert g.tolist() == [True, True, True, False]
    flat = sf.slope_filter(np.arange(5.0), np.zeros(5), np.full(5, 7.0), radius=2,
                           slope=1.0, height_tolerance=0).ground
    assert flat.all()


def test_rise_equal_to_the_allowed_rise_is_ground():
    t = np.tan(np.radians(40.0))
    x, y = np.array([0.0, 2.0]), np.zeros(2)
    z = np.array([2.0 * t, 0.0])           # (2t - 0)/2 == t exactly in float64
    assert sf.slope_filter(x, y, z, radius=2, slope=40, height_tolerance=0).ground.all()
    z2 = np.array([np.nextafter(2.0 * t, 10.0), 0.0])
    assert sf.slope_filter(x, y, z2, radius=2, slope=40,
                           height_tolerance=0).ground.tolist() == [False, True]


def test_signed_difference_and_height_tolerance():
    x, y, z = np.array([0.0, 1.0]), np.zeros(2), np.array([0.0, 1.5])
    g = sf.slope_filter(x, y, z, radius=2, slope=45, height_tolerance=0).ground
    assert g.tolist() == [True, False]       # only the higher point is rejected
    g = sf.slope_filter(x, y, z, radius=2, slope=45, height_tolerance=0.6).ground
    assert g.tolist() == [True, True]        # 1.5 <= 1 * tan45 + 0.6


def test_neighbour_and_classify_masks():
    x, y, z = np.array([0.0, 1.0, 2.0]), np.zeros(3), np.array([0.0, 5.0, 5.0])
    res = sf.slope_filter(x, y, z, radius=1.5, slope=45, height_tolerance=0,
                          neighbours=[False, True, True])
    assert res.ground.tolist() == [True, True, True]   # the low point cannot reject
    res = sf.slope_filter(x, y, z, radius=1.5, slope=45, height_tolerance=0,
                          classify=[True, False, True])
    assert res.ground.tolist() == [True, False, True]
    assert res.classified.tolist() == [True, False, True]


# --------------------------------------------------------------------------- golden
def test_golden_allowed_rise_of_the_forest_study():
    rises = [round(float(sf.allowed_rise(3.0, t)), 2) for t in (40, 44, 48, 52, 56, 60)]
    assert rises == [2.52, 2.90, 3.33, 3.84, 4.45, 5.20]


@pytest.mark.parametrize("theta, rise", [(40, 2.52), (44, 2.90), (48, 3.33), (52, 3.84),
                                         (56, 4.45), (60, 5.20)])
def test_golden_filter_switches_at_the_allowed_rise(theta, rise):
    x, y = np.array([0.0, 3.0]), np.zeros(2)
    below = sf.slope_filter(x, y, np.array([rise - 0.01, 0.0]), radius=3.0, slope=theta,
                            height_tolerance=0)
    above = sf.slope_filter(x, y, np.array([rise + 0.01, 0.0]), radius=3.0, slope=theta,
                            height_tolerance=0)
    assert below.ground.tolist() == [True, True]
    assert above.ground.tolist() == [False, True]


def test_sweep_rows_equal_single_runs_and_pick_best():
    rng = np.random.default_rng(3)
    n = 3000
    x, y = rng.uniform(0, 60, n), rng.uniform(0, 60, n)
    z = 0.2 * x + rng.normal(0, 0.05, n)
    obj = rng.random(n) < 0.35
    z[obj] += rng.uniform(0.3, 12, obj.sum())
    slopes = [30, 40, 44, 50, 60]
    res = sw.threshold_sweep(x, y, z, ~obj, slopes=slopes, radii=[2.0, 5.0],
                             height_tolerance=[0.0, 0.1])
    assert len(res.rows) == 20
    for row in res.rows:
        single = sf.slope_filter(x, y, z, radius=row.radius, slope=row.slope,
                                 height_tolerance=row.height_tolerance)
        assert single.n_ground == row.n_ground
        assert row.a + row.b + row.c + row.d == n
    assert res.best.total == min(r.total for r in res.rows)
    kap = sw.threshold_sweep(x, y, z, ~obj, slopes=slopes, radii=[2.0], metric="kappa")
    assert kap.best.kappa == max(r.kappa for r in kap.rows)
    # Type II alone favours the lowest threshold (the forest study's caveat)
    t2 = sw.threshold_sweep(x, y, z, ~obj, slopes=slopes, radii=[2.0], metric="type2")
    assert t2.best.slope == 30
    assert res.to_csv().splitlines()[0].startswith("radius_m,slope_deg,height_tolerance_m")


def test_adaptive_mode_keeps_steep_natural_slopes():
    """A 50 degree hillside with houses: exact rejects the slope, adaptive keeps it."""
    rng = np.random.default_rng(5)
    n = 20000
    x, y = rng.uniform(0, 150, n), rng.uniform(0, 150, n)
    z = np.tan(np.radians(50)) * x + rng.normal(0, 0.03, n)
    ground = np.ones(n, bool)
    for cx, cy in ((40, 40), (100, 110), (70, 20)):
        box = (np.abs(x - cx) < 6) & (np.abs(y - cy) < 6)
        z[box] = np.tan(np.radians(50)) * (cx + 6) + 7.0     # roof above the slope
        ground[box] = False
    kw = dict(radius=5.0, slope=40.0, height_tolerance=0.2)
    exact = sf.slope_filter(x, y, z, **kw)
    adaptive = sf.slope_filter(x, y, z, mode="adaptive", trend_cell=5, trend_window=30, **kw)
    from geomatics_toolbox.core.lidar.accuracy import assess
    e, a = assess(exact.ground, ground), assess(adaptive.ground, ground)
    assert e.type1 > 80          # Vosselman's rule rejects a slope steeper than theta
    assert a.type1 < 5
    assert a.total < 6
    assert adaptive.trend is not None


# --------------------------------------------------------------------------- bad input
@pytest.mark.parametrize("kw, msg", [
    (dict(radius=0), "radius"), (dict(radius=-1), "radius"), (dict(radius=np.nan), "radius"),
    (dict(slope=0), "between 0 and 90"), (dict(slope=90), "between 0 and 90"),
    (dict(slope=-5), "between 0 and 90"), (dict(slope=120), "between 0 and 90"),
    (dict(height_tolerance=-0.1), "height_tolerance"), (dict(mode="fast"), "mode"),
])
def test_bad_parameters(kw, msg):
    x = np.arange(5.0)
    with pytest.raises(ValueError, match=msg):
        sf.slope_filter(x, x, x, **kw)


def test_bad_arrays():
    with pytest.raises(ValueError, match="empty"):
        sf.slope_filter([], [], [])
    with pytest.raises(ValueError, match="same length"):
        sf.slope_filter([1.0, 2.0], [1.0], [1.0, 2.0])
    with pytest.raises(ValueError, match="non-finite"):
        sf.slope_filter([1.0, np.nan], [1.0, 2.0], [1.0, 2.0])
    with pytest.raises(ValueError, match="reference has 2 labels"):
        sw.threshold_sweep([1.0, 2.0, 3.0], [0.0] * 3, [0.0] * 3, [True, False])
    with pytest.raises(ValueError, match="classify has 2"):
        sf.slope_filter([1.0, 2.0, 3.0], [0.0] * 3, [0.0] * 3, classify=[True, False])


def test_cancel_and_progress():
    rng = np.random.default_rng(0)
    x, y, z = rng.uniform(0, 50, (3, 5000))
    seen = []
    sf.slope_filter(x, y, z, radius=3, progress=seen.append)
    assert seen[-1] == 1.0 and all(b >= a for a, b in zip(seen, seen[1:]))
    with pytest.raises(Cancelled):
        sf.slope_filter(x, y, z, radius=3, cancel=lambda: True)


# --------------------------------------------------------------------------- files
@pytest.fixture(scope="module")
def small_tile(tmp_path_factory):
    from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile
    tile = generate_tile(extent=(120, 120), density=4.0, seed=11, n_low_outliers=6)
    path = tmp_path_factory.mktemp("slope") / "tile.laz"
    write_tile(tile, path)
    return tile, str(path)


def test_classify_file_preserves_attributes_and_classes(small_tile, tmp_path):
    import laspy
    tile, src = small_tile
    out, gout, html = tmp_path / "c.laz", tmp_path / "g.las", tmp_path / "r.html"
    s = sp.classify_file(src, sf.SlopeFilter(sf.SlopeOptions(radius=5, slope=40)),
                         FilterOutputs(cloud=out, ground=gout, report=html))
    a, b = laspy.read(src), laspy.read(out)
    for dim in a.point_format.dimension_names:
        if dim != "classification":
            np.testing.assert_array_equal(np.asarray(a[dim]), np.asarray(b[dim]), dim)
    cls = np.asarray(b.classification)
    assert set(np.unique(cls)) <= {1, 2, 7, 18}
    assert s.n_ground == np.count_nonzero(cls == 2) > 0
    # the file's own noise classes are kept, the pre-filter's low outliers are 7
    np.testing.assert_array_equal(cls[tile.classification == 18], 18)
    g = laspy.read(gout)
    assert len(g.x) == s.n_ground and set(np.unique(g.classification)) == {2}
    text = html.read_text(encoding="utf-8")
    assert "Vosselman" in text and "Allowed rise" in text
    # identical to the core filter on the same selection
    pd = read_las(src, ["classification"])
    sel = sp.select_points(pd)
    core = sf.slope_filter(pd.x, pd.y, pd.z, radius=5, slope=40, classify=sel.candidates,
                           neighbours=sel.candidates)
    np.testing.assert_array_equal(cls == 2, core.ground)


def test_last_returns_only(small_tile, tmp_path):
    import laspy
    tile, src = small_tile
    out = tmp_path / "last.las"
    s = sp.classify_file(src, sf.SlopeFilter(sf.SlopeOptions(radius=5, slope=40)),
                         FilterOutputs(cloud=out), selection=SelectionOptions(returns="last"))
    cls = np.asarray(laspy.read(out).classification)
    not_last = tile.return_number < tile.number_of_returns
    assert s.n_not_last == np.count_nonzero(not_last) > 0
    assert np.all(cls[not_last & ~np.isin(tile.classification, (7, 18))] == 1)


def test_filter_ignores_input_classification(small_tile, tmp_path):
    import laspy
    _, src = small_tile
    scrambled = tmp_path / "scrambled.laz"
    n = laspy.read(src).header.point_count
    write_las_like(src, scrambled, dimensions={
        "classification": np.random.default_rng(0).choice([1, 2, 5, 6], n).astype(np.uint8)})
    a, b = tmp_path / "a.las", tmp_path / "b.las"
    keep = SelectionOptions(keep_noise_classes=False)
    sp.classify_file(src, sf.SlopeFilter(), FilterOutputs(cloud=a), selection=keep)
    sp.classify_file(scrambled, sf.SlopeFilter(), FilterOutputs(cloud=b), selection=keep)
    np.testing.assert_array_equal(laspy.read(a).classification, laspy.read(b).classification)


def test_file_bad_input_writes_nothing(small_tile, tmp_path):
    _, src = small_tile
    out = tmp_path / "o.laz"
    outs = FilterOutputs(cloud=out, report=tmp_path / "r.html")
    for kw, msg in ((dict(radius=0), "radius"), (dict(slope=90), "between 0 and 90"),
                    (dict(slope=0), "between 0 and 90")):
        with pytest.raises(ValueError, match=msg):
            sp.classify_file(src, sf.SlopeFilter(sf.SlopeOptions(**kw)), outs)
        assert not out.exists() and not (tmp_path / "r.html").exists()
    with pytest.raises(ValueError, match="returns"):
        sp.classify_file(src, sf.SlopeFilter(), outs,
                         selection=SelectionOptions(returns="first"))
    with pytest.raises(ValueError, match="same file"):
        sp.classify_file(src, sf.SlopeFilter(), FilterOutputs(cloud=src))
    empty = tmp_path / "empty.las"
    write_las(empty, np.zeros(0), np.zeros(0), np.zeros(0))
    with pytest.raises(ValueError, match="empty"):
        sp.classify_file(empty, sf.SlopeFilter(), FilterOutputs(cloud=out))
    assert not out.exists()
    with pytest.raises(Cancelled):
        sp.classify_file(src, sf.SlopeFilter(), FilterOutputs(cloud=out),
                         Monitor(cancel=lambda: True))
    assert not out.exists()
    assert not [p for p in os.listdir(tmp_path) if ".part" in p]


def test_sweep_file_reference_checks(small_tile, tmp_path):
    tile, src = small_tile
    csv, html = tmp_path / "s.csv", tmp_path / "s.html"
    other = tmp_path / "other.las"
    write_las(other, tile.x[:100], tile.y[:100], tile.z[:100])
    with pytest.raises(ValueError, match="same points"):
        sw.sweep_file(src, reference=other, csv_output=csv, html_output=html)
    assert not csv.exists() and not html.exists()
    # a labelled copy of the same cloud is accepted and equals the input's own labels
    ref = tmp_path / "ref.laz"
    write_las_like(src, ref)
    a = sw.sweep_file(src, reference=ref, slopes=[35, 45], radii=[5])
    b = sw.sweep_file(src, slopes=[35, 45], radii=[5], csv_output=csv, html_output=html)
    assert [r.total for r in a.result.rows] == [r.total for r in b.result.rows]
    assert csv.read_text().count("\n") == 3
    assert "Best setting" in html.read_text(encoding="utf-8")


def test_parse_number_list():
    assert sp.parse_number_list("40:60:4", "SLOPES") == [40, 44, 48, 52, 56, 60]
    assert sp.parse_number_list("3, 5;10", "RADII") == [3, 5, 10]
    with pytest.raises(ValueError, match="SLOPES"):
        sp.parse_number_list("40-60", "SLOPES")


# --------------------------------------------------------------------------- ISPRS
ISPRS_LIMITS = {"samp11": 21.0, "samp12": 11.0, "samp31": 8.0, "samp54": 5.5}


@pytest.mark.slow
@pytest.mark.parametrize("sample", SAMPLES)
def test_isprs_best_of_sweep(isprs_dir, sample, tmp_path):
    csv = tmp_path / f"{sample}_sweep.csv"
    html = tmp_path / f"{sample}_sweep.html"
    s = sw.sweep_file(isprs_dir / f"{sample}.laz", slopes=list(range(25, 66, 5)),
                      radii=[5, 10, 20], height_tolerances=[0.0, 0.2], csv_output=csv,
                      html_output=html)
    best = s.result.best
    assert best.total <= ISPRS_LIMITS[sample], best
    assert best.total == min(r.total for r in s.result.rows)
    lines = csv.read_text().splitlines()
    assert len(lines) == 1 + 9 * 3 * 2
    assert html.exists()


@pytest.mark.slow
def test_isprs_adaptive_mode_improves_steep_sample(isprs_dir):
    """The terrain-adaptive extension lowers samp11's (steep slopes) error at the defaults."""
    pd = read_las(isprs_dir / "samp11.laz", ["classification"])
    sel = sp.select_points(pd, keep_noise_classes=False)
    ref = pd["classification"] == 2
    from geomatics_toolbox.core.lidar.accuracy import assess
    tot = {}
    for mode in ("exact", "adaptive"):
        r = sf.slope_filter(pd.x, pd.y, pd.z, mode=mode, classify=sel.candidates,
                            neighbours=sel.candidates)
        tot[mode] = assess(r.ground, ref).total
    assert tot["adaptive"] < tot["exact"] - 2.0, tot


@pytest.mark.parametrize("n,message", [
    (1, r"A ground filter needs at least 2 points, got 1"),
    (500, r"All 500 points share one x/y position, so there is no terrain to compare them "
          r"with"),
])
def test_sweep_and_max_slope_refuse_one_position_as_the_filter_does(n, message):
    """The sweep scored every setting 'all ground' on one x/y position; now refused."""
    x, y = np.full(n, 7.0), np.full(n, 3.0)
    z = np.random.default_rng(1).uniform(0, 20, n)
    with pytest.raises(InputError, match=message):
        sw.threshold_sweep(x, y, z, np.ones(n, bool), slopes=[40.0], radii=[3.0])
    with pytest.raises(InputError, match=message):
        sf.max_slope(x, y, z)
    with pytest.raises(InputError) as info:
        sw.threshold_sweep(x, y, z, np.ones(n, bool), slopes=[40.0], radii=[3.0])
    assert info.value.message("ar") != str(info.value)          # translated
    two = sw.threshold_sweep([0.0, 3.0], [0.0, 0.0], [0.0, 2.0], [True, False],
                             slopes=[30.0], radii=[3.0], height_tolerance=0.0)
    assert two.best.n_ground == 1 and two.best.total == 0.0     # 2 points still swept

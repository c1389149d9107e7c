"""Recommended ground filter and progressive TIN densification (core/lidar/{recommended,ptd})."""
from __future__ import annotations

import hashlib
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st
from scipy.spatial import Delaunay

from geomatics_toolbox.core.errors import InputError
from geomatics_toolbox.core.lidar import ptd, recommended
from geomatics_toolbox.core.lidar.accuracy import assess
from geomatics_toolbox.core.progress import Cancelled

ROOT = Path(__file__).resolve().parents[2]

SAMPLES = ["samp11", "samp12", "samp22", "samp31", "samp41", "samp53", "samp54", "samp61"]

#: 8 ISPRS samples at the defaults: sha1 of the uint8 classes and the total error (%) of
#: the recommended filter (research harness /work/scratch/g3: tangent-plane hole fill,
#: detrending, continuity growing; identical totals), then of PTD at its defaults (1 m
#: candidate cells, 60 m parcels with seeds from 6 m cell minima, frame points, angle 24,
#: distance 1.2 m, final pass + 0.5 m per unit slope; every grid on a world lattice
#: through 0, 3 x 3 offset parcel grids, densified until no candidate passes: mean
#: 4.58 % (was 4.50 % with grids fitted to the extent; 4.66 % before the final pass
#: stopped taking points far above a sliver facet; also through qgis_process,
#: tests/cli/test_ptd_filter_cli.py). The final pass's one-layer rule (no ground point
#: more than the final distance plus the terrain's rise above a ground vertex within a
#: cell of its facet or the facets next to it, ``_tin.one_layer``): samp11 12.11 ->
#: 12.19, samp12 3.26 -> 3.14, samp22 3.70 -> 3.64, samp31 2.01 -> 1.76, samp41 5.32 ->
#: 5.47, samp53 4.40 -> 4.42, samp54/61 identical (mean 4.58 -> 4.55).
#: Mirrored points outside the TIN's hull take the nearest hull facet (the walk's stop
#: depended on the facets' order): samp11 12.1942 -> 12.1889, the other seven identical.
#: Low-outlier cells read at the ground-return scale under canopy (``_lowcells``):
#: samp41 2.5732 -> 2.6089, samp53 3.1997 -> 3.2259, the other six identical. Hole
#: fill k-NN searched within a short radius first (ties at the 12th neighbour resolve
#: differently): samp11/12/22/53/61 move by -0.012..+0.004 (mean 3.368). Height
#: tolerance 0.35 x mean point spacing within 0.25-0.5 m (was 0.5 m; factor chosen by
#: the 12-fold leave-one-sample-out, bench_ground.py --loso12): mean 3.240. Catalog =
#: single file (translation-invariant hole fill: the 12 nearest border cells by (distance,
#: row, col offset); push-pull and coarse blocks aligned on the origin lattice; exact box
#: means; plane moments without a raster-wide mean): samp11 +0.055, samp53 +0.017,
#: samp54 -0.023, samp12/61 -0.003 (mean 3.251). A filled cell between occupied neighbours
#: differing by more than 2 x cell x slope_max + t takes the lowest (walls stay one step,
#: ``_raster.floor_steps``): samp11 -0.27, samp12 +0.34, samp22 -0.04, samp31 -0.14, samp41
#: -0.11, samp53 +0.34, samp54 -0.10, samp61 +0.24 (mean 3.282; 7 of 8 below SMRF).
#: Density over every point on 5 m cells of the world lattice (multiples of 5 m, not from
#: the cloud's corner; no subsample), so a catalog's tiles add up to it (issue 20,
#: ``_summary``): samp11 8.5793 -> 8.5925, samp12 2.8147 -> 2.8205, samp31 1.2716 ->
#: 1.2681, samp41 2.5465 -> 2.5376, the other four identical (mean 3.2825 -> 3.2833).
#: Cells outside the occupied cells' convex hull absent from the openings
#: (``_terrain.outside_hull``): samp53 3.5721 -> 3.5517, the other seven identical
#: (mean 3.2833 -> 3.2808). The trend surface and slope tolerance with those cells
#: absent (``_terrain._opened``): samp53 3.5517 -> 3.5022 (mean 3.2746).
RESEARCH = {
    "samp11": ("89d2ed096b883a82114bffacdb8119c744815f36", 8.5925,
               "983b1075164a6726c3d2db4e61b76a827592368c", 12.1889),
    "samp12": ("f8c329be1febd5c6075873dbab222e14f29829a2", 2.8205,
               "0a819e9b934d7019d4ddf2954a63c9756187e496", 3.1390),
    "samp22": ("10989347a5ed22f485fd7685f3eb95e17c95873c", 2.7243,
               "9b8c85b1faa7d58fdcb0cbd3970515d33b4fc644", 3.6354),
    "samp31": ("e5dffe822b953dc19a15557d487aa2863c757138", 1.2681,
               "bb7950614bc0d233c813a97e4de7d4b32c3b133a", 1.7636),
    "samp41": ("e176abb1d684b601cab84147dff21e96ba35d296", 2.5376,
               "308016efc6d2038f6b8e30c45fe4f1f033fcd309", 5.4670),
    "samp53": ("35ab2fe92fe8db211b18f7d68a758806aa62e441", 3.5022,
               "153ff4fcf22ff71a653f4c0d3c7cb8e0dfb68b09", 4.4185),
    "samp54": ("e16ef223def7d8df242b73e41252fe3b23fb664a", 2.5209,
               "0b17ecbe5410050229e43a6bc717649725984bfc", 3.2993),
    "samp61": ("875931dd079293dc42b32902dae5566750fe8582", 2.2305,
               "c1d38c4f89aeb685b3b04a5dd2bb5538dc2d810c", 2.5043),
}


def scene(slope=0.0, cliff=0.0, seed=0, spacing=1.0, size=120.0):
    """Jittered ground grid + two 12x12 m boxes 6 m high + optional cliff at x = 80 m."""
    rng = np.random.default_rng(seed)
    g = np.arange(0.0, size, spacing)
    gx, gy = [a.ravel() + rng.uniform(-0.2, 0.2, a.size) * spacing
              for a in np.meshgrid(g, g)]

    def terrain(x):
        return 100.0 + slope * x + np.where(x > 80.0, cliff, 0.0)

    inside = np.zeros(gx.size, bool)
    for bx, by in [(20.0, 20.0), (40.0, 70.0)]:
        inside |= (np.abs(gx - bx) < 6) & (np.abs(gy - by) < 6)
    z = terrain(gx) + rng.normal(0, 0.03, gx.size)
    z[inside] = terrain(gx[inside]).max() + 6.0 + rng.normal(0, 0.03, inside.sum())
    return gx, gy, z, np.where(inside, 1, 2).astype(np.uint8)


@pytest.mark.parametrize("slope,cliff", [
    (0.0, 0.0), (0.2, 0.0),
    pytest.param(0.0, 5.0, marks=pytest.mark.slow),
    pytest.param(0.1, 4.0, marks=pytest.mark.slow)])
def test_ptd_known_geometry_every_point_right(slope, cliff):
    x, y, z, truth = scene(slope=slope, cliff=cliff)
    cls = ptd.classify(x, y, z)
    assert cls.dtype == np.uint8
    wrong = np.flatnonzero(cls != truth)
    assert wrong.size == 0, (wrong.size, x[wrong][:5], y[wrong][:5])


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_ptd_closed_canopy_dtm_within_1_m_of_the_terrain(seed):
    """A closed canopy over rolling hills, 5 % of the returns on the ground: no canopy
    point becomes ground and the TIN of the ground points stays within 1 m of the true
    terrain (before the frame points and seeds from coarser cells: 700 canopy points
    ground, DTM up to 19 m in the trees)."""
    from scipy.interpolate import LinearNDInterpolator

    from geomatics_toolbox.synthetic.landscapes import closed_forest
    s = closed_forest(extent=150.0, density=1.5, ground_share=0.05, seed=seed)
    cls = ptd.classify(s.x, s.y, s.z)
    g, truth = cls == 2, s.classification == 2
    assert np.count_nonzero(g & ~truth) == 0
    assert np.count_nonzero(g & truth) > 0.9 * np.count_nonzero(truth)
    gx, gy = np.meshgrid(np.arange(5.0, 145.0), np.arange(5.0, 145.0))
    dtm = LinearNDInterpolator(np.column_stack((s.x[g], s.y[g])), s.z[g])(gx, gy)
    assert np.nanmax(np.abs(dtm - s.terrain(gx, gy))) < 1.0


def test_ptd_mixedconifer_no_dtm_cell_1_m_above_the_vendor_dtm():
    """Issue 21: no canopy or shrub patch in PTD's DTM on the shared forest file. 1 m IDW
    DTMs (12 nearest, power 2) of PTD's and the vendor's ground, on the cells inside the
    vendor ground's hull, as ``../shared/data/real/README.md`` scores them: before the
    final pass's one-layer rule 12 cells were 1.03-1.26 m above (shrubs, a tree's foot)
    and 26 PTD ground points more than 1 m above the known terrain; now 0 and 3."""
    import laspy
    from scipy.spatial import cKDTree

    src = ROOT.parent / "shared" / "data" / "real" / "lidr_mixedconifer_terrain.laz"
    if not src.exists():
        pytest.skip(f"shared real data absent: {src} (see ../shared/data/real/README.md)")
    las = laspy.read(str(src))
    x, y, z = (np.asarray(v, float) for v in (las.x, las.y, las.z))
    g, v = ptd.classify(x, y, z) == 2, np.asarray(las.classification) == 2
    cx, cy = (a.ravel() + 0.5 for a in np.meshgrid(np.floor(x.min()) + np.arange(90.0),
                                                  np.floor(y.min()) + np.arange(90.0)))
    inside = Delaunay(np.column_stack((x[v], y[v]))).find_simplex(
        np.column_stack((cx, cy))) >= 0
    q = np.column_stack((cx[inside], cy[inside]))

    def idw(m):
        d, j = cKDTree(np.column_stack((x[m], y[m]))).query(q, k=12)
        w = np.maximum(d, 1e-9) ** -2.0
        return (w * z[m][j]).sum(axis=1) / w.sum(axis=1)

    above = idw(g) - idw(v)
    assert q.shape[0] > 8000 and above.max() < 1.0, (np.sort(above)[-5:])
    u, w = x - 481260.0, y - 3812921.0          # the README's synthetic terrain T(u, v)
    terrain = (2300 + 0.10 * u - 0.06 * w + 4.0 * np.sin(2 * np.pi * u / 160 + 0.7)
               * np.sin(2 * np.pi * w / 120 + 0.3) + 1.5 * np.cos(2 * np.pi * (u - 0.5 * w) / 75))
    assert np.count_nonzero(g & (z - terrain > 1.0)) <= 3


@pytest.mark.parametrize("slope", [0.0, 0.2])
def test_recommended_known_geometry_every_point_right(slope):
    x, y, z, truth = scene(slope=slope)
    cls = recommended.classify(x, y, z)
    assert np.array_equal(cls, truth)


@pytest.mark.parametrize("mod", [ptd, recommended])
def test_low_outliers_become_class_7(mod):
    x, y, z, _ = scene()
    z = z.copy()
    z[[100, 5000, 9000]] -= 8.0
    cls = mod.classify(x, y, z)
    assert set(np.flatnonzero(cls == 7)) == {100, 5000, 9000}


@settings(max_examples=20, deadline=None, suppress_health_check=[HealthCheck.too_slow])
@given(seed=st.integers(0, 10_000), n=st.integers(60, 600),
       tilt=st.floats(-0.5, 0.5), n_obj=st.integers(0, 40),
       dist=st.floats(0.2, 2.0), ang=st.floats(3.0, 30.0), frac=st.floats(0.1, 1.0),
       cliff=st.sampled_from([0.0, 3.0, 6.0]))
def test_ptd_accepted_ground_within_limits_of_final_tin(seed, n, tilt, n_obj, dist, ang,
                                                         frac, cliff):
    """Also with a cliff, where the cliff-aware mirroring accepts points."""
    rng = np.random.default_rng(seed)
    x, y = rng.uniform(0, 80, n), rng.uniform(0, 80, n)
    z = tilt * x + np.sin(y / 9.0) * 2.0 + rng.normal(0, 0.1, n) + np.where(x > 40, cliff, 0)
    obj = rng.choice(n, size=min(n_obj, n), replace=False)
    z[obj] += rng.uniform(-5, 15, obj.size)
    opt = ptd.PtdOptions(max_distance=dist, max_angle=ang, final_distance=dist * frac)
    cls, tin = ptd.classify_with_tin(x, y, z, options=opt)
    assert set(np.unique(cls)) <= {1, 2, 7}
    tri = Delaunay(tin[:, :2])
    g = np.flatnonzero(cls == 2)
    s = tri.find_simplex(np.column_stack((x[g], y[g])))
    assert np.all(s >= 0)
    v = tin[tri.simplices[s]]
    nrm = np.cross(v[:, 1] - v[:, 0], v[:, 2] - v[:, 0])
    nrm /= np.linalg.norm(nrm, axis=1)[:, None]
    d = np.abs(np.einsum("ij,ij->i", np.column_stack((x[g], y[g], z[g])) - v[:, 0], nrm))
    # plus final_slope m per unit of facet slope, or in a facet spanning a breakline,
    # where the cliff-aware test accepted it
    tan = np.sqrt(np.maximum(1.0 / nrm[:, 2] ** 2 - 1.0, 0.0))
    cliff = (np.abs(nrm[:, 2]) < np.cos(np.radians(ptd.BREAKLINE_SLOPE))) \
        & (np.ptp(v[:, :, 2], axis=1) > opt.max_distance)
    assert np.all((d <= opt.final_distance + opt.final_slope * tan + 1e-6) | cliff)


@pytest.mark.parametrize("mod", [ptd, recommended])
def test_bad_input(mod):
    x, y, z, _ = scene(size=30.0)
    with pytest.raises(InputError, match="at least"):
        mod.classify(x[:3], y[:3], z[:3])
    zz = z.copy()
    zz[5] = np.nan
    with pytest.raises(ValueError, match="non-finite"):
        mod.classify(x, y, zz)
    with pytest.raises(InputError, match="degrees"):
        mod.classify(7.0 + x * 1e-5, 45.0 + y * 1e-5, z)
    with pytest.raises(ValueError, match="same length"):
        mod.classify(x, y[:-1], z)
    with pytest.raises(InputError, match="one x/y position"):
        mod.classify(np.full(20, 500.0), np.full(20, 500.0), np.arange(20.0))


def test_bad_options():
    with pytest.raises(InputError, match="max_window"):
        recommended.RecommendedOptions(max_window=0)
    with pytest.raises(InputError, match="fill_neighbours"):
        recommended.RecommendedOptions(fill_neighbours=0)
    with pytest.raises(InputError, match="fill_reach"):
        recommended.RecommendedOptions(fill_reach=0.0)
    with pytest.raises(InputError, match=r"FINAL_DISTANCE \(2\.0 m\) must not exceed "
                                         r"MAX_DISTANCE \(1\.0 m\)"):
        ptd.PtdOptions(max_distance=1.0, final_distance=2.0)
    with pytest.raises(InputError, match=r"MAX_BUILDING must be > 0, got 0"):
        ptd.PtdOptions(max_building=0)
    with pytest.raises(InputError, match=r"MAX_WINDOW, 3000 m\) must be at most 2000 m"):
        recommended.RecommendedOptions(max_window=3000.0)


@pytest.mark.parametrize("mod", [ptd, recommended])
def test_progress_and_cancel(mod):
    x, y, z, _ = scene(size=60.0)
    seen = []
    mod.classify(x, y, z, progress=seen.append)
    assert seen[-1] == 1.0 and all(0.0 <= f <= 1.0 for f in seen)
    assert seen == sorted(seen)
    calls = []
    with pytest.raises(Cancelled):
        mod.classify(x, y, z, cancel=lambda: calls.append(1) or len(calls) > 2)


def _load(isprs_dir, name):
    import laspy
    las = laspy.read(str(isprs_dir / f"{name}.laz"))
    x, y, z = (np.asarray(v, float) for v in (las.x, las.y, las.z))
    return x, y, z, np.asarray(las.classification) == 2


@pytest.mark.parametrize("sample", SAMPLES)
def test_recommended_isprs_golden_identical_to_research(isprs_dir, sample):
    x, y, z, ref = _load(isprs_dir, sample)
    cls = recommended.classify(x, y, z)
    sha, total = RESEARCH[sample][:2]
    assert assess(cls == 2, ref).total == pytest.approx(total, abs=1e-4)
    assert hashlib.sha1(cls.tobytes()).hexdigest() == sha


def test_recommended_isprs_mean_and_wins(isprs_dir):
    totals = [RESEARCH[s][1] for s in SAMPLES]
    assert np.mean(totals) == pytest.approx(3.2746, abs=0.0001)
    smrf = dict(samp11=8.52, samp12=3.60, samp22=3.59, samp31=3.55, samp41=12.20,
                samp53=7.99, samp54=4.28, samp61=2.28)     # pysmrf, PDAL defaults
    assert sum(RESEARCH[s][1] < smrf[s] for s in SAMPLES) == 7


@pytest.mark.slow
@pytest.mark.parametrize("sample", SAMPLES)
def test_ptd_isprs_golden_identical_to_research(isprs_dir, sample):
    x, y, z, ref = _load(isprs_dir, sample)
    cls = ptd.classify(x, y, z)
    sha, total = RESEARCH[sample][2:]
    assert assess(cls == 2, ref).total == pytest.approx(total, abs=1e-4)
    assert hashlib.sha1(cls.tobytes()).hexdigest() == sha


def test_pipeline_writes_classes_and_keeps_attributes(tmp_path):
    import laspy

    from geomatics_toolbox.core.io.las import read_las
    from geomatics_toolbox.core.lidar.pipeline import (
        FilterOutputs,
        SelectionOptions,
        classify_file,
    )
    from geomatics_toolbox.core.reporting import render_html
    from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile
    tile = generate_tile(extent=(60, 60), density=4.0, seed=3)
    src = tmp_path / "t.laz"
    write_tile(tile, src)
    out, html = tmp_path / "c.laz", tmp_path / "r.html"
    run = classify_file(src, recommended.recommended_filter(),
                        FilterOutputs(cloud=out, report=html),
                        selection=SelectionOptions(noise=False, keep_noise_classes=False))
    a, b = laspy.read(str(src)), laspy.read(str(out))
    cls = read_las(out, ["classification"])["classification"]
    x, y, z = (np.asarray(v, float) for v in (a.x, a.y, a.z))
    expect = recommended.classify(x, y, z)
    assert np.array_equal(cls, expect)
    assert set(np.unique(cls)) <= {1, 2, 7}
    for dim in ("X", "Y", "Z", "intensity", "return_number", "gps_time"):
        if dim in a.point_format.dimension_names:
            assert np.array_equal(np.asarray(a[dim]), np.asarray(b[dim])), dim
    assert b.header.parse_crs() == a.header.parse_crs()
    assert "Raster cell (m)" in render_html(run.report, lang="en")
    assert html.exists()


@pytest.mark.parametrize("lang", ["ar", "fa"])
def test_reports_fully_translated(tmp_path, lang):
    """Every message of the recommended and PTD reports has an ar/fa translation."""
    from geomatics_toolbox.core.lidar.pipeline import FilterOutputs, classify_file
    from geomatics_toolbox.core.reporting.i18n import has_translation
    from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile
    src = tmp_path / "t.laz"
    write_tile(generate_tile(extent=(60, 60), density=2.0, seed=3), src)
    reports = [classify_file(src, alg, FilterOutputs(report=tmp_path / "r.html",
                                                     lang=lang)).report
               for alg in (recommended.recommended_filter(), ptd.ptd_filter())]
    missing = {m for r in reports for m in r.messages() if not has_translation(m, lang)}
    assert not missing, sorted(missing)


def test_recommended_one_cell_wide_strip():
    """A strip narrower than one raster cell (a single row) is flat ground, no crash."""
    x = np.linspace(0.0, 100.0, 1000)
    y = np.random.default_rng(0).uniform(0.0, 0.5, 1000)
    z = 0.02 * x
    z[500] += 5.0
    cls = recommended.classify(x, y, z)
    assert np.flatnonzero(cls != 2).tolist() == [500]


def test_catalog_default_is_the_recommended_filter():
    from geomatics_toolbox.core.io.las import PointData
    from geomatics_toolbox.core.lidar.filters import (
        classify_points,
        default_ground_filter,
        default_selection,
        ground_filter,
    )
    assert default_ground_filter() == "groundfilter"
    x, y, z, _ = scene(size=40.0)
    cls = classify_points(PointData(x, y, z), ground_filter("groundfilter"),
                          default_selection("groundfilter"))
    assert np.array_equal(cls, recommended.classify(x, y, z))

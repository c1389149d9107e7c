"""Walls stay one step in the opening's raster (``_raster.floor_steps``): sparse roofs."""
from pathlib import Path

import numpy as np
import pytest

from geomatics_toolbox.core.lidar import _raster as R  # noqa: N812
from geomatics_toolbox.core.lidar import recommended

ROOT = Path(__file__).resolve().parents[2]
REAL = ROOT.parent / "shared" / "data" / "real"


def _brute(z, valid, step):
    out = z.copy()
    for r in range(z.shape[0]):
        for c in range(z.shape[1]):
            if valid[r, c]:
                continue
            w = valid[max(0, r - 1):r + 2, max(0, c - 1):c + 2]
            v = z[max(0, r - 1):r + 2, max(0, c - 1):c + 2][w]
            if v.size and v.max() - v.min() > step:
                out[r, c] = min(out[r, c], v.min())
    return out


@pytest.mark.parametrize("shape", [(300, 257), (5, 7), (129, 3), (1, 4)])
def test_floor_steps_is_the_3x3_rule_cell_by_cell(shape):
    rng = np.random.default_rng(3)
    z = rng.normal(0.0, 3.0, shape)
    valid = rng.random(shape) < 0.4
    want = _brute(z, valid, 2.0)
    got = R.floor_steps(z.copy(), valid, 2.0)
    assert np.array_equal(got, want)
    assert np.array_equal(got[valid], z[valid])          # occupied cells never change
    assert (got != z).sum() > 0 if shape[0] > 1 else True


def test_floor_steps_does_not_depend_on_where_the_raster_starts():
    rng = np.random.default_rng(5)
    z = rng.normal(0.0, 3.0, (400, 60))
    valid = rng.random(z.shape) < 0.3
    whole = R.floor_steps(z.copy(), valid, 1.5)
    part = R.floor_steps(z[37:].copy(), valid[37:], 1.5)
    assert np.array_equal(whole[38:], part[1:])           # beyond the cut's 1-row reach


def test_wall_step_is_the_steepest_tolerated_slope_across_two_cells_plus_the_tolerance():
    opt = recommended.RecommendedOptions(threshold=0.4)
    assert recommended.wall_step(1.0, opt) == pytest.approx(2 * 0.6 + 0.4)
    opt = recommended.RecommendedOptions(threshold=0.4, slope=0.2)
    assert recommended.wall_step(2.0, opt) == pytest.approx(2 * 2.0 * 0.2 + 0.4)


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_thinned_suburban_roofs_are_not_ground(seed):
    """fusa thinned to 0.5 pts/m²: 561 / 484 / 813 vendor roof points were ground before."""
    import laspy
    src = REAL / "lastools_fusa.laz"
    if not src.exists():
        pytest.skip(f"shared real data absent: {src} (see ../shared/data/real/README.md)")
    las = laspy.read(str(src))
    x, y, z = (np.asarray(v, float) for v in (las.x, las.y, las.z))
    c = np.asarray(las.classification)
    keep = ~np.isin(c, (7, 18))
    dens = keep.sum() / (np.ptp(x) * np.ptp(y))
    sel = keep & (np.random.default_rng(seed).random(keep.size) < 0.5 / dens)
    cls = recommended.classify(x[sel], y[sel], z[sel])
    roof = c[sel] == 6
    assert np.count_nonzero((cls == 2) & roof) < 100       # 561 / 484 / 813 before floor_steps
    ground = c[sel] == 2
    assert np.mean(cls[ground] == 2) > 0.97                 # the ground stays ground

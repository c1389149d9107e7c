"""The filter protocol's ``candidates``: the points left out take no part.

Every filter is given every point and a candidate mask (``filters.run_filter`` no
longer copies the candidates' coordinates: 3 x 8 B/point); its classes must equal those
of a run on copies of the candidates alone. The points left out here sit 60 m outside
the cloud and 40 m below it: counted in the grid's extent, a cell minimum, the density,
the water test or the read mask, they would change the classes.
"""
from __future__ import annotations

import numpy as np
import pytest

from geomatics_toolbox.core.lidar import _summary as S  # noqa: N812
from geomatics_toolbox.core.lidar._recommended_filter import water_candidates
from geomatics_toolbox.core.lidar.filters import GROUND_FILTERS, ground_filter
from geomatics_toolbox.synthetic import landscapes


def _scene(water_class: bool, cliffs: bool = False):
    """The lake (or cliffs) with 300 input-noise points (class 7) far outside and below it.

    The lake has water (class 9, else flat sparse returns); on the cliffs a grid corner
    moved by the points left out changes 248 classes of the recommended filter.
    """
    s = landscapes.steep_cliffs(seed=2) if cliffs else landscapes.lake(seed=1)
    x, y, z = s.x.copy(), s.y.copy(), s.z.copy()
    cls = s.classification.copy() if water_class else np.full(x.size, 1, np.uint8)
    out = np.random.default_rng(5).choice(x.size, 300, replace=False)
    x[out[:150]] = x.min() - 61.3                    # left of the cloud
    y[out[150:]] = y.min() - 47.7                    # below it
    z[out] -= 40.0                                   # and below the terrain
    cls[out] = 7
    cand = np.ones(x.size, bool)
    cand[out] = False
    return x, y, z, cls, cand


#: every filter on each scene, but PTD (it reads no class) on the lake with water only
CASES = [(key, water, cliffs) for key in GROUND_FILTERS
         for water, cliffs in [(True, False), (False, False), (False, True)]
         if key != "ptd" or (water and not cliffs)]


@pytest.mark.parametrize("key, water_class, cliffs", CASES)
def test_candidates_equal_a_run_on_their_copies(key, water_class, cliffs):
    x, y, z, cls, cand = _scene(water_class, cliffs)
    flt = ground_filter(key)
    got = flt.classify(x, y, z, classification=cls, candidates=cand)
    want = flt.classify(x[cand], y[cand], z[cand], classification=cls[cand])
    assert got.classes.shape == (cand.sum(),)
    np.testing.assert_array_equal(got.classes, want.classes)
    if key == "groundfilter":
        d, e = got.details, want.details
        assert (d.points, d.counts, d.water_input, d.water_candidates, d.cell) == \
            (e.points, e.counts, e.water_input, e.water_candidates, e.cell)
        assert d.density == e.density
        # the scene exercises both water paths: input class 9, else flat sparse returns
        if not cliffs:
            assert (d.water_input > 1000) if water_class else (d.water_candidates > 1000)
    if key == "keep":
        np.testing.assert_array_equal(got.classes, cls[cand])


def test_summary_and_water_test_of_the_kept_points():
    x, y, z, cls, cand = _scene(False)
    assert S.cloud_summary(x, y, cls, counts=True, keep=cand) == \
        S.cloud_summary(x[cand], y[cand], cls[cand], counts=True)
    assert S.cell_counts(x, y, 5.0, keep=cand) == S.cell_counts(x[cand], y[cand], 5.0)
    got = water_candidates(x, y, z, keep=cand)
    want = water_candidates(x[cand], y[cand], z[cand])
    assert want.sum() > 1000 and not got[~cand].any()
    np.testing.assert_array_equal(got[cand], want)

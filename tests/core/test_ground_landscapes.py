"""The recommended ground filter on per-landscape synthetic scenes with known terrain.

Each scene (``synthetic/landscapes.py``) holds a case the ISPRS samples barely cover;
the DTM of the filter's ground points (1 m IDW, as the real-data benchmark scores
it) is compared with the true terrain inside a 5 m margin.
"""
from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial import cKDTree

from geomatics_toolbox.core.lidar import _lowcells, recommended
from geomatics_toolbox.synthetic import landscapes


def dtm_errors(scene, ground):
    """DTM (1 m IDW of the ground points, 12 neighbours, power 2) minus the terrain."""
    x0, x1 = scene.x.min() + 5, scene.x.max() - 5
    y0, y1 = scene.y.min() + 5, scene.y.max() - 5
    cx, cy = (a.ravel() for a in np.meshgrid(np.arange(x0, x1), np.arange(y0, y1)))
    d, j = cKDTree(np.column_stack((scene.x[ground], scene.y[ground]))).query(
        np.column_stack((cx, cy)), k=12)
    w = np.maximum(d, 1e-9) ** -2.0
    return (w * scene.z[ground][j]).sum(axis=1) / w.sum(axis=1) - scene.terrain(cx, cy)


@pytest.mark.parametrize("density, share", [(1.5, 0.05), (4.0, 0.15)])
def test_closed_forest_terrain_stays_on_the_ground(density, share):
    s = landscapes.closed_forest(density=density, ground_share=share, seed=1)
    cls = recommended.classify(s.x, s.y, s.z)
    e = dtm_errors(s, cls == 2)
    assert np.sqrt(np.mean(e * e)) < 0.3
    assert np.mean(np.abs(e) > 1.0) < 0.01
    above = s.z > s.terrain(s.x, s.y) + 1.0
    assert not np.any((cls == 7) & above)          # no tree is a "low outlier"
    assert np.mean(cls[s.classification == 2] == 2) > 0.95


def test_closed_forest_plain_closing_test_fails():
    """The 1-cell closing alone (the previous rule) puts the terrain in the canopy."""
    s = landscapes.closed_forest(ground_share=0.05, seed=1)
    cls = recommended.classify(s.x, s.y, s.z,
                               options=recommended.RecommendedOptions(low_share=1.0))
    assert np.mean(np.abs(dtm_errors(s, cls == 2)) > 1.0) > 0.5


def test_low_cells_open_pit_flagged_canopy_specks_kept():
    rng = np.random.default_rng(0)
    z = 100.0 + rng.normal(0, 0.05, (80, 80))
    z[40, 40] = 80.0                                   # a multipath pit in the open
    res = _lowcells.low_cells(z, 1.0)
    assert res.low[40, 40] and res.low.sum() == 1 and res.canopy_share == 0.0
    canopy = 120.0 + rng.uniform(0, 5, (80, 80))       # crowns, 20 m up
    specks = rng.random((80, 80)) < 0.12               # ground seen through gaps
    canopy[specks] = 100.0 + rng.normal(0, 0.05, specks.sum())
    res = _lowcells.low_cells(canopy, 1.0)
    assert res.pits > 0.5 * specks.sum()               # the closing test alone fails
    assert not res.low[specks].any()
    assert res.canopy_share > 0.9 and res.canopy_scale >= 2.0


def test_low_cells_empty_raster():
    res = _lowcells.low_cells(np.full((5, 5), np.nan), 1.0)
    assert not res.low.any() and res.pits == 0


def test_lake_water_kept_out_of_ground():
    """Input class 9 keeps its class; without it, flat sparse returns are candidates."""
    from geomatics_toolbox.core.lidar._recommended_filter import water_candidates
    s = landscapes.lake(seed=1)
    water = s.classification == 9
    flt = recommended.recommended_filter()
    out = flt.classify(s.x, s.y, s.z, classification=s.classification)
    assert (out.classes[water] == 9).all()
    assert np.mean(out.classes[~water] == 2) > 0.99
    assert out.details.water_input == water.sum()
    cand = water_candidates(s.x, s.y, s.z)
    assert cand[water].mean() > 0.4 and cand[~water].mean() < 0.001
    out = flt.classify(s.x, s.y, s.z)                       # no classes in the input
    assert not (out.classes[cand] == 2).any() and (out.classes[cand] == 1).all()
    assert out.details.water_candidates == cand.sum()
    assert np.mean(out.classes[~water] == 2) > 0.99


def test_no_water_candidates_on_dry_land():
    s = landscapes.steep_cliffs(seed=2)
    from geomatics_toolbox.core.lidar._recommended_filter import water_candidates
    assert not water_candidates(s.x, s.y, s.z).any()


@pytest.mark.parametrize("lang", ["ar", "fa"])
def test_derived_report_of_a_forest(lang):
    """What ran is reported (cell, windows, canopy scale, ground share), translated."""
    from geomatics_toolbox.core.reporting.i18n import has_translation
    s = landscapes.closed_forest(ground_share=0.05, seed=1)
    d = recommended.recommended_filter().classify(s.x, s.y, s.z).details
    from geomatics_toolbox.core.lidar._raster import density
    assert isinstance(d.density_of, float)          # the height tolerance's, counted once
    from geomatics_toolbox.core.lidar._recommended_filter import _largest_object
    obj, cell = d.largest_object_of                 # nor the widest object measured
    want = _largest_object(obj, cell)
    rows = dict(d.rows())
    assert want > 0 and rows["Largest object found (m)"] == round(want, 1)
    assert d.largest_object_of == want == d.largest_object
    assert d.density == density(s.x, s.y)
    assert rows["Raster cell (m)"] == 1.0 and d.windows == [float(r) for r in range(1, 19)]
    assert d.canopy_share > 0.9 and d.canopy_scale >= 2.0 and d.pits > 0
    assert abs(d.ground_share - np.mean(s.classification == 2)) < 0.02
    msgs = [w.text for w in d.warnings()]
    assert any(m.startswith("Few ground returns") for m in msgs)
    assert any(m.startswith("Ground seen through a canopy") for m in msgs)
    labels = [k for k, _ in d.rows()] + msgs + ["Derived from the cloud (what ran)",
                                                 rows["Opening windows (m)"].text]
    assert not [m for m in labels if not has_translation(m, lang)]


def test_steep_cliffs_ground_kept_at_the_edges():
    """45° slopes cut by 12 m cliffs: the ground on both sides of each cliff is kept."""
    s = landscapes.steep_cliffs(seed=1)
    cls = recommended.classify(s.x, s.y, s.z)
    ground = s.classification == 2
    assert np.mean(cls[ground] != 2) < 0.01                       # Type I
    for c in (50.0, 100.0):                                       # cliff lines (x)
        near = ground & (np.abs(s.x - c) < 3.0) & (np.abs(s.x - c) > 0.5)
        assert np.mean(cls[near] == 2) > 0.95
    e = dtm_errors(s, cls == 2)
    assert np.mean(np.abs(e) > 1.0) < 0.05

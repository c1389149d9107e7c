"""Steps of the recommended filter: detrending before the opening, continuity growing."""
from __future__ import annotations

import numpy as np
import pytest

from geomatics_toolbox.core.errors import InputError
from geomatics_toolbox.core.lidar import _raster as R  # noqa: N812
from geomatics_toolbox.core.lidar import recommended as rec

CELL = 1.0


def _grid(n=300):
    return R.Grid(0.0, 0.0, CELL, n, n)


def _cols_rows(n=300):
    return np.meshgrid(np.arange(n, dtype=float), np.arange(n, dtype=float))


def test_trend_removes_a_plane_and_keeps_a_roof_on_the_downhill_side():
    """A plane's trend is the plane; on a 0.3 hillside, a 14 m roof at the uphill level
    stands above the detrended terrain on its downhill side by its wall height."""
    c, r = _cols_rows()
    z = 100.0 + 0.3 * r
    roof = (np.abs(c - 150) < 7) & (np.abs(r - 150) < 7)
    z_b = np.where(roof, 100.0 + 0.3 * 157.0, z)
    opt = rec.RecommendedOptions()
    flat = z - rec.trend_surface(z, _grid(), opt)
    inner = (slice(140, 160), slice(140, 160))
    assert np.ptp(flat[inner]) < 1e-6                    # a plane's trend is the plane
    det = z_b - rec.trend_surface(z_b, _grid(), opt)
    ground_level = np.median(det[135:140, 140:160])      # just downhill of the building
    assert det[144, 150] - ground_level == pytest.approx(0.3 * 13, abs=0.6)
    # the opening (flat structuring element, now tilted along the trend) still flags
    # the part of the roof standing more than 2.6 m above the detrended terrain
    obj = rec.progressive_objects(det, CELL, 18.0, 0.15, lambda f: None)
    assert obj[roof & (det - ground_level > 2.6)].all()
    inner_terrain = ~roof & (np.abs(c - 150) > 12) & (np.abs(r - 150) < 100)
    assert not obj[inner_terrain].any()


def _ridge_and_box():
    """Flat ground with a rounded ridge (1.5 m high, 20 m wide) flagged as object, and a
    6 m box with walls, also flagged."""
    c, r = _cols_rows(120)
    ridge = np.clip(1.5 * (1.0 - ((c - 40.0) / 10.0) ** 2), 0.0, None)
    z = 100.0 + ridge
    box = (np.abs(c - 90) < 6) & (np.abs(r - 60) < 6)
    z[box] = 106.0
    obj = (ridge > 0.6) | box
    return z, obj, box, ridge


def test_grow_accepts_a_continuous_crest_and_not_a_walled_box():
    z, obj, box, ridge = _ridge_and_box()
    skip = np.zeros_like(obj)
    dtm = np.full(z.shape, 100.0)
    left = rec.grow_ground(z, obj, skip, dtm, CELL, rec.RecommendedOptions())
    assert left[box].all()                               # walls: never grown into
    assert not left[ridge > 0.6].any()                   # the crest is ground again
    off = rec.grow_ground(z, obj, skip, dtm, CELL, rec.RecommendedOptions(grow_iters=0))
    assert np.array_equal(off, obj)


def test_grow_stops_at_the_rise_limit_and_the_iteration_reach():
    z, obj, box, ridge = _ridge_and_box()
    skip = np.zeros_like(obj)
    low_dtm = np.full(z.shape, 99.0)                     # crest 2.5 m above: beyond 2 m
    left = rec.grow_ground(z, obj, skip, low_dtm, CELL, rec.RecommendedOptions())
    assert left[(ridge > 1.0)].all() and not left[(ridge > 0.6) & (ridge < 0.9)].any()
    one = rec.grow_ground(z, obj, skip, np.full(z.shape, 100.0), CELL,
                          rec.RecommendedOptions(grow_iters=1, grow_window=1.0))
    assert 0 < (obj & ~one).sum() < (obj & ~box).sum()   # one step reaches one ring


def test_new_options_are_validated():
    with pytest.raises(InputError, match="trend_window"):
        rec.RecommendedOptions(trend_window=-1.0)

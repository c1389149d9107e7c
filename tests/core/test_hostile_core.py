"""Hostile input, round 3 (issue 22): core cases — origin-independent TIN, ..."""
from __future__ import annotations

import numpy as np
import pytest

from geomatics_toolbox.core.errors import InputError
from geomatics_toolbox.core.terrain.accuracy import check_points_not_degrees
from geomatics_toolbox.core.terrain.grid import grid_from_points
from geomatics_toolbox.core.terrain.tin import tin_grid


def _las(v, offset, scale=0.01):
    """Coordinates as a LAS file stores them (integers × scale + offset)."""
    return np.round((v - offset) / scale) * scale + offset


def test_tin_does_not_depend_on_the_origin():
    # a lattice: every four neighbours are cocircular, so Qhull breaks ties — with the
    # cloud's absolute coordinates it broke them differently 1e8 m away (6.4 m apart in
    # 6786 of 14,400 cells before local coordinates)
    rng = np.random.default_rng(0)
    gx, gy = np.meshgrid(np.arange(0, 60, 1.5), np.arange(0, 60, 1.5))
    x, y = gx.ravel() + 512_345.67, gy.ravel() + 4_012_345.67
    z = rng.normal(100, 3, x.size)
    out = []
    for shift in (0.0, 1e8):
        xs = _las(x + shift, np.floor((x + shift).min()))
        ys = _las(y + shift, np.floor((y + shift).min()))
        out.append(tin_grid(xs, ys, z, grid_from_points(xs, ys, 0.5)).z)
    a, b = out
    assert np.array_equal(np.isnan(a), np.isnan(b))
    assert np.nanmax(np.abs(a - b)) < 1e-6


def test_lon_lat_check_points_on_a_projected_dtm_refused():
    with pytest.raises(InputError, match="look like longitude/latitude.*EPSG:32632"):
        check_points_not_degrees([9.1, 9.2], [48.1, 48.2], (500000, 500100, 5e6, 5e6 + 100),
                                 crs_label="EPSG:32632")
    # points on the DTM, or a DTM in degrees: nothing to say
    check_points_not_degrees([500050.0], [5e6 + 50], (500000, 500100, 5e6, 5e6 + 100))
    check_points_not_degrees([9.1], [48.1], (9.0, 9.5, 48.0, 48.5))

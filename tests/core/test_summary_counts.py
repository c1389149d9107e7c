"""The catalog summary's cell counts (core/lidar/_summary.py): the blocked count of a
small box equals the plain whole-array count, bit for bit, on any lattice position."""
from __future__ import annotations

import numpy as np
import pytest

from geomatics_toolbox.core.lidar import _summary as S  # noqa: N812


def _plain(x, y, cell, shared=()):
    """The whole-array expressions (reference)."""
    ix = np.floor(x / cell).astype(np.int64)
    iy = np.floor(y / cell).astype(np.int64)
    x0, y0 = int(ix.min()), int(iy.min())
    ny = int(iy.max()) - y0 + 1
    occ, cnt = np.unique((ix - x0) * ny + (iy - y0), return_counts=True)
    cx, cy = occ // ny + x0, occ % ny + y0
    edge = np.zeros(occ.size, bool)
    for b in shared:
        edge |= ((cx * cell <= b[2]) & ((cx + 1) * cell >= b[0])
                 & (cy * cell <= b[3]) & ((cy + 1) * cell >= b[1]))
    return {"hist": np.bincount(cnt[~edge]).tolist(),
            "keys": [cx[edge].tolist(), cy[edge].tolist()], "counts": cnt[edge].tolist()}


@pytest.mark.parametrize("block", [7, 1 << 16])
@pytest.mark.parametrize("origin,side", [((0.0, 0.0), 300.0), ((-1234.5, 5e6), 800.0),
                                         ((7e5, -3e6), 20000.0)])
def test_cell_counts_equal_the_plain_count(monkeypatch, block, origin, side):
    monkeypatch.setattr(S, "_BLOCK", block)
    rng = np.random.default_rng(1)
    n = 30000
    x = origin[0] + rng.uniform(0, side, n)
    y = origin[1] + rng.uniform(0, side / 3, n)
    x[:5] = origin[0] + 5.0 * np.arange(5)            # points on cell edges
    shared = [(origin[0] + side / 2, origin[1], origin[0] + side, origin[1] + 10.0)]
    for box in ((), shared):
        got = S.cell_counts(x, y, 5.0, box)
        assert got == _plain(x, y, 5.0, box)
    assert S.cell_counts(x, y, 5.0) == S.cloud_summary(x, y, counts=True)["cells"]

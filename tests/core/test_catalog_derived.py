"""Derived parameters in catalog chunks vs a single-file run of the merged cloud.

The recommended filter derives its height tolerance from the density of the points it
sees (``recommended.derive``: 0.35 x mean spacing, clipped to 0.25-0.5 m). A chunk sees
its tile and buffer, the single-file run the whole cloud: next to a tile of another
density the two tolerances differ, and so may a few classes (DEVELOPERS.md, the
recommended filter's "Not catalog-exact"). Everything else in the filter is
catalog-exact on these tiles: given the merged run's tolerance, every chunk gives the
merged run's classes. (The DTM gap distance, derived once for the whole catalog, is
test_catalog_sparse's.)
"""
from __future__ import annotations

import dataclasses
from pathlib import Path

import numpy as np
import pytest

from geomatics_toolbox.core.io.catalog import find_tiles
from geomatics_toolbox.core.io.las import PointData, read_las
from geomatics_toolbox.core.lidar import _chunks
from geomatics_toolbox.core.lidar import catalog as cc
from geomatics_toolbox.core.lidar import recommended as rec
from geomatics_toolbox.core.lidar.filters import (
    GROUND_FILTERS,
    classify_points,
    default_selection,
    ground_filter,
)
from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile

BUFFER = 100.0


def _two_tiles(d: Path, densities) -> Path:
    d.mkdir(parents=True)
    for i, rho in enumerate(densities):
        t = generate_tile(extent=(300.0, 300.0), origin=(500_000.0 + 300 * i, 4_000_000.0),
                          density=rho, seed=3 + i)
        write_tile(t, d / f"t{i}.laz")
    return d


def _run_chunks(cat, out: Path):
    tasks = cc.plan_tasks(cat, out, ground_filter="groundfilter", dtm_method="idw",
                          cell_size=1.0, buffer=BUFFER)
    (out / cc.STATE_DIR).mkdir(parents=True)
    cc.first_pass(cat, tasks, out)
    for t in tasks:
        _chunks.process_chunk(t)
    return tasks


@pytest.mark.parametrize("densities,differ", [((0.3, 1.5), True), ((0.5, 8.0), False)])
def test_recommended_tolerance_is_derived_per_chunk(tmp_path, monkeypatch, densities,
                                                    differ):
    """0.3 / 1.5 pts/m²: the chunks derive 0.45 and 0.32 m, the merged cloud 0.37 m, and a
    few points of the sparse tile differ (at most 0.5 % of its inner points; 15 of 5,606
    measured); given the merged run's tolerance the chunks give its classes exactly.
    0.5 / 8 pts/m²: every tolerance clips to 0.25 m and the classes are equal."""
    d = _two_tiles(tmp_path / "tiles", densities)
    paths = find_tiles(str(d))
    parts = [read_las(p, ("classification",)) for p in paths]
    x, y, z = (np.concatenate([getattr(p, a) for p in parts]) for a in "xyz")
    cls0 = np.concatenate([p["classification"] for p in parts])
    tile = np.concatenate([np.full(len(p), i) for i, p in enumerate(parts)])
    cat = cc.Catalog.open(str(d))
    seen = []
    derive = rec.derive

    def spy(xx, yy, opt):
        out = derive(xx, yy, opt)
        seen.append(out.threshold)
        return out
    monkeypatch.setattr(rec, "derive", spy)
    _run_chunks(cat, tmp_path / "chunks")
    per_chunk, seen[:] = list(seen), []
    merged = classify_points(PointData(x, y, z, {"classification": cls0}),
                             ground_filter("groundfilter"), default_selection("groundfilter"))
    (whole,) = seen

    def catalog_classes(out):
        return np.concatenate([read_las(out / f"{Path(p).stem}_classified.laz",
                                        ("classification",))["classification"] for p in paths])
    e = cat.extent
    inner = np.minimum.reduce([x - e[0], y - e[1], e[2] - x, e[3] - y]) > BUFFER
    diff = catalog_classes(tmp_path / "chunks") != merged
    if differ:
        assert per_chunk[0] > whole > per_chunk[1]
        sparse = inner & (tile == 0)
        assert 0 < diff[inner].sum() and diff[sparse].sum() <= 0.005 * sparse.sum()
    else:
        assert per_chunk == [whole, whole] == [0.25, 0.25]
        assert not diff[inner].any()
    # the merged run's tolerance given to every chunk: its classes, exactly
    opts = dataclasses.replace(GROUND_FILTERS["groundfilter"].make(None).options,
                               threshold=whole)
    monkeypatch.setattr(_chunks, "ground_filter",
                        lambda key, options=None: GROUND_FILTERS[key].make(opts))
    _run_chunks(cat, tmp_path / "given")
    assert np.array_equal(catalog_classes(tmp_path / "given")[inner], merged[inner])

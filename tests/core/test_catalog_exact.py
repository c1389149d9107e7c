"""A catalog of real tiles vs the single-file run, for every registered ground filter.

Two real files (``../shared/data/real``: the Arizona conifers, metres, and the New
Mexico woodland in US survey feet) are cut into 2 x 2 tiles at the middle of their box,
classes reset to 1 (input noise kept), as a user's unclassified tiles. The catalog's
own planning and chunk code runs every chunk in this process with the default buffer
(100 m: wider than these files, so every chunk holds the whole cloud and only the
anchoring of grids and tiles can differ).

Pinned: every filter's catalog classes equal the single-file run of the whole file, as
the single-file algorithm runs it, point for point. The catalog's first pass
(``catalog.first_pass``, :mod:`core.lidar._summary`) gives every chunk the corner of
all the catalog's points, where a single-file run anchors its grids and tiles (PTD: both
on its lattice through 0). Before it the chunks were anchored on the catalog's
kilometre origin and differed (``benchmarks/results/catalog_exact.md``) — conifers: LSQ
faithful 1,503 of 37,657 points, recommended 53, PTD 38, slope adaptive 17, LSQ improved
16; US feet: LSQ faithful 170, recommended 10, LSQ improved 1.
"""
from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest

from geomatics_toolbox.core import classes as asprs
from geomatics_toolbox.core.io.las import PointData, las_info, read_las, write_las
from geomatics_toolbox.core.lidar import catalog as cc
from geomatics_toolbox.core.lidar.filters import (
    GROUND_FILTERS,
    classify_points,
    default_selection,
    ground_filter,
)

REAL = Path(__file__).resolve().parents[2].parent / "shared" / "data" / "real"
FILES = ["lidr_mixedconifer_terrain.laz", "pdal_nm_usft.laz"]


@pytest.fixture(scope="module")
def tiles(tmp_path_factory):
    made = {}

    def get(name):
        if name not in made:
            src = REAL / name
            if not src.exists():
                pytest.skip(f"shared real data absent: {src} (see ../shared/data/real/README.md)")
            folder = tmp_path_factory.mktemp("exact") / "tiles"
            made[name] = (folder, *_split(src, folder))
        return made[name]
    return get


def _split(src: Path, folder: Path):
    """2 x 2 tiles cut at the middle; the whole cloud in tile order, its units."""
    info = las_info(src)
    pd = read_las(src, ("classification",))
    cls = np.where(np.isin(pd["classification"], asprs.INPUT_NOISE), pd["classification"],
                   asprs.UNCLASSIFIED).astype(np.uint8)
    mx, my = 0.5 * (pd.x.min() + pd.x.max()), 0.5 * (pd.y.min() + pd.y.max())
    folder.mkdir(parents=True)
    order = []
    for i, mi in enumerate((pd.x < mx, pd.x >= mx)):
        for j, mj in enumerate((pd.y < my, pd.y >= my)):
            m = mi & mj
            write_las(folder / f"t{i}{j}.las", pd.x[m], pd.y[m], pd.z[m],
                      dimensions={"classification": cls[m]}, crs=info.crs, scale=0.01)
            order.append(np.flatnonzero(m))
    o = np.concatenate(order)
    return PointData(pd.x[o], pd.y[o], pd.z[o], {"classification": cls[o]}), info.units


def _catalog(folder: Path, out: Path, key: str):
    cat = cc.Catalog.open(str(folder))
    tasks = cc.plan_tasks(cat, out, ground_filter=key, dtm_method="idw", cell_size=2.0,
                          buffer=100.0)
    (out / cc.STATE_DIR).mkdir(parents=True, exist_ok=True)
    cc.run_here(cat, tasks, out)     # first pass, chunks, canopy re-runs
    return tasks, np.concatenate([read_las(t.outputs["LAS"], ("classification",))
                                  ["classification"] for t in tasks])


@pytest.mark.parametrize("name", FILES, ids=["conifers", "feet"])
@pytest.mark.parametrize("key", list(GROUND_FILTERS))
def test_catalog_of_real_tiles_equals_the_single_file_run(tiles, tmp_path, name, key):
    folder, pts, units = tiles(name)
    _, got = _catalog(folder, tmp_path / "out", key)
    x, y, z = units.xyz_to_metres(pts.x, pts.y, pts.z)
    ref = classify_points(PointData(x, y, z, pts.dims), ground_filter(key),
                          default_selection(key))
    assert got.shape == ref.shape == (len(pts),)
    assert np.array_equal(got, ref), f"{int((got != ref).sum())} of {got.size} points differ"
    if key != "keep":
        assert 0.05 * got.size < np.count_nonzero(got == asprs.GROUND) < got.size

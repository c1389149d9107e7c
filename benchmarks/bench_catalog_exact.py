"""Catalog vs single file, per registered ground filter: which classes differ, and why.

Each of the 4 real files (``../shared/data/real``) is cut into 2 x 2 tiles at the middle
of its box (classes reset to 1, input noise 7/18 kept, as a user's unclassified tiles);
the catalog's planning and chunk code runs every chunk in this process (buffer = the
catalog default, 100 m), and its classes are compared, point by point, with

the filter's single-file run on the whole file, as the single-file algorithm runs it
(``classify_points`` with ``origin=None``: anchored at the cloud's corner; the catalog's
first pass gives its chunks the corner of all its tiles).

Also three synthetic scenes where tiles differ (``--scenes``): a density step (two
300 m tiles at 0.3 / 1.5 pts/m²), a closed forest and a lake across two tiles (600 m,
left half thinned to 0.4 of 2 pts/m²), buffer 100 m, compared with the single-file run
on the points farther than the buffer from the catalog's outer edge.

Writes ``benchmarks/results/catalog_exact.md``. CPU seconds are this process's.
"""
from __future__ import annotations

import argparse
import os
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests"))
import conftest  # noqa: E402,F401  (imports the checkout as geomatics_toolbox)

from geomatics_toolbox.core import classes as asprs  # noqa: E402
from geomatics_toolbox.core.io.las import PointData, las_info, read_las, write_las  # noqa: E402
from geomatics_toolbox.core.lidar import catalog as cc  # noqa: E402
from geomatics_toolbox.core.lidar.filters import (  # noqa: E402
    GROUND_FILTERS,
    classify_points,
    default_selection,
    ground_filter,
)

REAL = ROOT.parent / "shared" / "data" / "real"
OUT = ROOT / "benchmarks" / "results" / "catalog_exact.md"
BUFFER = 100.0


def split_2x2(path: Path, folder: Path):
    """Write the file's 2 x 2 tiles (classes reset); return (x, y, z, cls) in tile order."""
    info = las_info(path)
    pd = read_las(path, ("classification",))
    cls = np.where(np.isin(pd["classification"], asprs.INPUT_NOISE),
                   pd["classification"], asprs.UNCLASSIFIED).astype(np.uint8)
    mx = 0.5 * (pd.x.min() + pd.x.max())
    my = 0.5 * (pd.y.min() + pd.y.max())
    parts = []
    folder.mkdir(parents=True)
    for i, mi in enumerate((pd.x < mx, pd.x >= mx)):
        for j, mj in enumerate((pd.y < my, pd.y >= my)):
            m = mi & mj
            write_las(folder / f"t{i}{j}.las", pd.x[m], pd.y[m], pd.z[m],
                      dimensions={"classification": cls[m]}, crs=info.crs, scale=0.01)
            parts.append(m)
    order = np.concatenate([np.flatnonzero(m) for m in parts])
    return pd.x[order], pd.y[order], pd.z[order], cls[order], info.units


def catalog_classes(tiles: Path, out: Path, key: str):
    cat = cc.Catalog.open(str(tiles))
    tasks = cc.plan_tasks(cat, out, ground_filter=key, dtm_method="idw", cell_size=2.0,
                          buffer=BUFFER)
    (out / cc.STATE_DIR).mkdir(parents=True, exist_ok=True)
    cc.run_here(cat, tasks, out)     # first pass, chunks, canopy re-runs
    cls = np.concatenate([read_las(t.outputs["LAS"], ("classification",))["classification"]
                          for t in tasks])
    return cls, tasks[0].origin, cat


def single(x, y, z, cls, key, units, origin=None):
    if not units.metric:
        x, y, z = units.xyz_to_metres(x, y, z)
        if origin is not None:
            origin = (units.h_to_metres(origin[0]), units.h_to_metres(origin[1]))
    return classify_points(PointData(x, y, z, {"classification": cls}), ground_filter(key),
                           default_selection(key), origin=origin)


def real_rows(keys, tmp: Path):
    rows = []
    for path in sorted(REAL.glob("*.laz")):
        tiles = tmp / path.stem / "tiles"
        x, y, z, cls, units = split_2x2(path, tiles)
        for key in keys:
            t0, c0 = time.perf_counter(), time.process_time()
            got, _, _ = catalog_classes(tiles, tmp / path.stem / key, key)
            one = single(x, y, z, cls, key, units)
            rows.append((path.stem, key, x.size, int((got != one).sum()),
                         time.process_time() - c0, time.perf_counter() - t0))
            print(*rows[-1], flush=True)
    return rows


def _scene(kind: str):
    from geomatics_toolbox.synthetic import landscapes
    from geomatics_toolbox.synthetic.lidar import generate_tile
    if kind == "density step":
        parts = [generate_tile(extent=(300.0, 300.0), origin=(300.0 * i, 0.0), density=rho,
                               seed=3 + i) for i, rho in enumerate((0.3, 1.5))]
        return (np.concatenate([p.x for p in parts]), np.concatenate([p.y for p in parts]),
                np.concatenate([p.z for p in parts]),
                np.concatenate([np.asarray(p.classification) for p in parts]))
    s = (landscapes.closed_forest(extent=600.0, density=2.0, ground_share=0.05, seed=1)
         if kind == "forest" else landscapes.lake(extent=600.0, density=2.0, radius=150.0, seed=1))
    rng = np.random.default_rng(0)
    keep = (s.x >= 300) | (rng.random(s.x.size) < 0.4)
    x, y, z = s.x[keep], s.y[keep], s.z[keep]
    return x, y, z, np.ones(x.size, np.uint8)     # unclassified input: water candidates run


def scene_rows(tmp: Path):
    rows = []
    for kind in ("density step", "forest", "lake"):
        x, y, z, cls = _scene(kind)
        x0 = x.min()
        x, y = x - x0 + 500_000.0, y - y.min() + 4_000_000.0
        d = tmp / kind.replace(" ", "_") / "tiles"
        d.mkdir(parents=True)
        half = 500_000.0 + 300.0
        parts = []
        for i, m in enumerate((x < half, x >= half)):
            write_las(d / f"t{i}.las", x[m], y[m], z[m], dimensions={"classification": cls[m]},
                      crs="EPSG:32632", scale=0.01)
            parts.append(read_las(d / f"t{i}.las", ("classification",)))   # as stored (1 cm)
        x, y, z = (np.concatenate([getattr(p, a) for p in parts]) for a in "xyz")
        cls = np.concatenate([p["classification"] for p in parts])
        t0, c0 = time.perf_counter(), time.process_time()
        got, _, cat = catalog_classes(d, d.parent / "out", "groundfilter")
        from geomatics_toolbox.core.io.units import METRIC
        merged = single(x, y, z, cls, "groundfilter", METRIC)
        e = cat.extent
        inner = np.minimum.reduce([x - e[0], y - e[1], e[2] - x, e[3] - y]) > BUFFER
        rows.append((kind, int(inner.sum()), int((got != merged)[inner].sum()),
                     int((got != merged).sum()), x.size, time.process_time() - c0,
                     time.perf_counter() - t0))
        print(*rows[-1], flush=True)
    return rows


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--quick", action="store_true", help="keep and recommended filters only")
    ap.add_argument("--scenes", action="store_true", help="the three synthetic scenes only")
    ap.add_argument("--out", default=str(OUT))
    a = ap.parse_args(argv)
    keys = ["keep", "groundfilter"] if a.quick else list(GROUND_FILTERS)
    load = os.getloadavg()[0] if hasattr(os, "getloadavg") else float("nan")
    with tempfile.TemporaryDirectory() as tmp:
        tmp = Path(tmp)
        real = [] if a.scenes else real_rows(keys, tmp)
        scenes = scene_rows(tmp)
    lines = ["# Catalog vs single file, per registered filter (`bench_catalog_exact.py`)", "",
             f"Load average at start {load:.1f} (2 cores shared: wall times are of a "
             "loaded machine). Classes differing between the catalog (2 x 2 tiles cut at "
             "the middle, buffer 100 m, chunks run in this process after the catalog's "
             "first pass) and the single-file run of the whole file.", ""]
    if real:
        lines += ["| file | filter | points | catalog ≠ single | CPU s | wall s |",
                  "|---|---|---:|---:|---:|---:|"]
        lines += [f"| {f} | {k} | {n:,} | {a1:,} | {c:.1f} | {w:.1f} |"
                  for f, k, n, a1, c, w in real]
        lines.append("")
    lines += ["Synthetic scenes (recommended filter, two tiles, buffer 100 m): points "
              "farther than the buffer from the outer edge that differ from the single-file "
              "run.", "",
              "| scene | inner points | differ (inner) | differ (all) | points | CPU s | wall s |",
              "|---|---:|---:|---:|---:|---:|---:|"]
    lines += [f"| {k} | {i:,} | {d:,} | {da:,} | {n:,} | {c:.1f} | {w:.1f} |"
              for k, i, d, da, n, c, w in scenes]
    Path(a.out).write_text("\n".join(lines) + "\n", encoding="utf-8")
    print("\n".join(lines))


if __name__ == "__main__":
    main()

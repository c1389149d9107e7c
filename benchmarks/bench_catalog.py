"""Tile catalog on Dask: wall time and points/s with 1 and 2 workers, peak memory per
worker, the same work on the merged cloud, and a DTM seam check along every internal
tile edge. Tiles are generated into a temporary folder (never committed).

    python benchmarks/bench_catalog.py                 # 25 tiles x 4 M points (100 M)
    python benchmarks/bench_catalog.py --quick         # 4 tiles x 0.2 M points
    python benchmarks/bench_catalog.py --tiles 9 --points 500000

Writes benchmarks/results/catalog.md.
"""
from __future__ import annotations

import argparse
import datetime
import math
import platform
import resource
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests"))
import conftest  # noqa: E402,F401  (imports the checkout as geomatics_toolbox)

from geomatics_toolbox.core.io.las import read_las  # noqa: E402
from geomatics_toolbox.core.io.raster import read_raster  # noqa: E402
from geomatics_toolbox.core.lidar import catalog as cc  # noqa: E402
from geomatics_toolbox.core.lidar._chunks import DTM_METHODS, GROUND_FILTERS, snap_grid  # noqa: E402
from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile  # noqa: E402

DENSITY = 5.0


def generate(folder: Path, n_side: int, points: int) -> float:
    side = math.sqrt(points / DENSITY)
    for i in range(n_side):
        for j in range(n_side):
            t = generate_tile(extent=(side, side), origin=(500_000.0 + side * i,
                                                           4_000_000.0 + side * j),
                              density=DENSITY, seed=100 * i + j)
            write_tile(t, folder / f"t{i:02d}{j:02d}.laz")
            del t
    return side


def dtm(path) -> np.ndarray:
    r = read_raster(path)
    d = r.data.astype(np.float64)
    d[d == r.nodata] = np.nan
    return d


def merged_run(folder: Path, args, origin, cat):
    t0 = time.perf_counter()
    parts = [read_las(p, ("classification",)) for p in cat.paths]
    x = np.concatenate([p.x for p in parts])
    y = np.concatenate([p.y for p in parts])
    z = np.concatenate([p.z for p in parts])
    c0 = np.concatenate([p["classification"] for p in parts])
    del parts
    cls = GROUND_FILTERS[args.filter].func(x, y, z, {"classification": c0}, origin)
    g = cls == 2
    grid = snap_grid(cat.extent, origin, args.cell)
    ref = DTM_METHODS["idw"].func(x[g], y[g], z[g], grid, cat.default_max_distance())
    secs = time.perf_counter() - t0
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    return ref, secs, peak


def seam_check(mosaic, ref, cat, side, n_side, origin, cell, buffer):
    """Max |catalog - merged| in the 2 cells either side of every internal edge."""
    grid = snap_grid(cat.extent, origin, cell)
    cx, cy = grid.block_centers(0, grid.nrows)
    cx, cy = cx.reshape(grid.shape), cy.reshape(grid.shape)
    e = cat.extent
    away = np.minimum.reduce([cx - e[0], cy - e[1], e[2] - cx, e[3] - cy]) > buffer
    band = np.zeros(grid.shape, bool)
    for k in range(1, n_side):
        band |= np.abs(cx - (e[0] + k * side)) <= 2 * cell
        band |= np.abs(cy - (e[1] + k * side)) <= 2 * cell
    sel = band & away & np.isfinite(mosaic) & np.isfinite(ref)
    if not sel.any():
        return float("nan"), 0
    return float(np.max(np.abs(mosaic[sel] - ref[sel]))), int(sel.sum())


def main(argv=None):
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--tiles", type=int, default=25, help="tiles (a square number)")
    ap.add_argument("--points", type=int, default=4_000_000, help="points per tile")
    ap.add_argument("--filter", default="lsq_faithful")
    ap.add_argument("--cell", type=float, default=1.0)
    ap.add_argument("--buffer", type=float, default=60.0)
    ap.add_argument("--merged-max", type=int, default=30_000_000,
                    help="run the merged cloud only up to this many points")
    args = ap.parse_args(argv)
    if args.quick:
        args.tiles, args.points = 4, 200_000
    n_side = int(round(math.sqrt(args.tiles)))
    rows = []
    with tempfile.TemporaryDirectory(prefix="bench_catalog_") as tmp:
        tmp = Path(tmp)
        (tmp / "tiles").mkdir()
        t0 = time.perf_counter()
        side = generate(tmp / "tiles", n_side, args.points)
        gen_s = time.perf_counter() - t0
        cat = cc.Catalog.open(str(tmp / "tiles"))
        results = {}
        for w in (1, 2):
            res = cc.run_catalog(str(tmp / "tiles"), tmp / f"out{w}", ground_filter=args.filter,
                                 cell_size=args.cell, buffer=args.buffer, workers=w)
            results[w] = res
            peak = max(c["peak_rss_mb"] for c in res.chunks)
            rows.append((f"catalog, {w} worker(s)", res.seconds, res.points_per_second,
                         peak, len(res.failed)))
        origin = results[1].settings["origin"]
        seam = ("not run (merged cloud too large)", "")
        if cat.n_points <= args.merged_max:
            ref, secs, peak = merged_run(tmp / "tiles", args, origin, cat)
            rows.append(("merged cloud, 1 process", secs, cat.n_points / secs, peak, 0))
            mosaic = dtm(tmp / "out2" / "dtm.vrt")
            seam = seam_check(mosaic, ref, cat, side, n_side, origin, args.cell, args.buffer)
    speedup = results[1].seconds / results[2].seconds
    write_table(args, cat, side, gen_s, rows, speedup, seam)


def write_table(args, cat, side, gen_s, rows, speedup, seam):
    lines = [
        "# Tile catalog on Dask",
        "",
        f"{datetime.date.today()}, {platform.node()} ({platform.machine()}, "
        f"Python {platform.python_version()}); arguments: "
        f"{' '.join(sys.argv[1:]) or '(defaults)'}.",
        "",
        f"{len(cat.tiles)} generated tiles of {side:.0f} m × {side:.0f} m, "
        f"{cat.n_points:,} points in total (generation {gen_s:.0f} s, not timed below); "
        f"ground filter `{args.filter}`, IDW DTM at {args.cell:g} m, buffer {args.buffer:g} m. "
        "Peak memory: largest resident set of one worker process (catalog) or of the "
        "process (merged).",
        "",
        "| run | wall time (s) | points/s | peak memory (MB) | failed tiles |",
        "|---|---|---|---|---|",
    ]
    lines += [f"| {r[0]} | {r[1]:.1f} | {r[2]:,.0f} | {r[3]:.0f} | {r[4]} |" for r in rows]
    lines += ["", f"Speed-up 2 workers vs 1: {speedup:.2f}×.", ""]
    if isinstance(seam[0], float):
        lines.append(f"Seam check: max |catalog DTM − merged DTM| over {seam[1]:,} cells within "
                     f"2 cells of an internal tile edge (away from the outer edge): "
                     f"{seam[0] * 1000:.3f} mm.")
    else:
        lines.append(f"Seam check: {seam[0]}.")
    out = HERE / "results" / "catalog.md"
    out.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print("\n".join(lines))


if __name__ == "__main__":
    main()

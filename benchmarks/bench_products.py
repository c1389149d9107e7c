"""Benchmark: LiDAR products (TIN DTM, buildings) against their peers.

Rows (each peer run in the same script, so machine load cancels out):

1. TIN DTM vs ``gdal_grid -a linear`` (``gdal.Grid``, ``radius=0`` = nodata outside the
   hull, GDAL_NUM_THREADS=ALL_CPUS) on 1 M synthetic ground points (1 cm coordinates)
   → 1 km² at 1 m (1 M cells): time ratio ours/GDAL (target ≤ 1.0), max |difference|
   over every cell (target ≤ 1e-3 m). GDAL gets the points twice: in grid-local
   coordinates (an exact translation; the like-for-like oracle) and in raw UTM
   coordinates, where its barycentric arithmetic loses millimetres (shown, not hidden).
2. Building footprints on a synthetic tile: completeness, correctness (buildings
   ≥ 50 m²), mean footprint IoU, height RMSE; Whitebox Workflows'
   ``classify_buildings_in_lidar`` on the same tile when the package runs offline.

Usage: ``.venv/bin/python benchmarks/bench_products.py [--quick]``; writes
``benchmarks/results/products.md``.
"""
from __future__ import annotations

import argparse
import datetime
import platform
import sys
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
RESULTS = ROOT / "benchmarks" / "results" / "products.md"
sys.path.insert(0, str(ROOT / "benchmarks"))

from bench_dtm import gdal_grid, gdal_points, synthetic_ground  # noqa: E402

from geomatics_toolbox.core.terrain.grid import grid_from_extent  # noqa: E402
from geomatics_toolbox.core.terrain.tin import tin_grid  # noqa: E402


def tin_rows(n: int, side: float, decimals: int, raw: bool) -> list:
    """Ours vs gdal_grid -a linear at one coordinate resolution; Markdown rows."""
    x, y, z, ext = synthetic_ground(n, side, seed=3, decimals=decimals)
    # duplicate x, y (1 cm coordinates) leave the TIN undefined: Qhull keeps one of them
    _, first = np.unique(np.column_stack([x, y]), axis=0, return_index=True)
    x, y, z = x[np.sort(first)], y[np.sort(first)], z[np.sort(first)]
    grid = grid_from_extent(ext, 1.0)
    t = time.perf_counter()
    ours = tin_grid(x, y, z, grid, fill=True).z
    t_ours = time.perf_counter() - t
    local = grid_from_extent((0.0, side, 0.0, side), 1.0)
    ref, t_gdal = gdal_grid(gdal_points(x - grid.xmin, y - grid.ymin, z), local,
                            "linear:radius=0:nodata=-9999")
    runs = [("grid-local", ref, t_gdal)]
    if raw:
        runs.append(("raw UTM", *gdal_grid(gdal_points(x, y, z), grid,
                                           "linear:radius=0:nodata=-9999")))
    rows = []
    for label, other, t_other in runs:
        both = np.isfinite(ours) & np.isfinite(other)
        d = np.abs(ours - other)[both]
        mism = int((np.isfinite(ours) != np.isfinite(other)).sum())
        rows.append(f"| {n:,} | {10.0 ** -decimals:g} m | {n - x.size} | {label} | "
                    f"{grid.size:,} | {t_ours:.2f} | {t_other:.2f} | {t_ours / t_other:.2f} | "
                    f"{d.max():.2e} | {int((d > 1e-3).sum())} | {mism} |")
    return rows


def bench_tin(n: int, side: float) -> list:
    """Row 1: ours vs gdal_grid -a linear; returns Markdown lines."""
    rows = tin_rows(n, side, 2, True) + tin_rows(n, side, 6, False)
    return ["## 1. TIN DTM vs `gdal_grid -a linear`", "",
            "Duplicate x, y are dropped before both runs (Qhull keeps one of them, "
            "either may win). On a 1 cm lattice four or more points can also lie on one "
            "circle, where the Delaunay triangulation is not unique and the two Qhull "
            "runs may pick different diagonals (the cells > 1 mm of the 1 cm rows); with "
            "1 µm coordinates the points are in general position.", "",
            "| points | coordinate step | duplicates dropped | GDAL coordinates | cells | "
            "ours (s) | gdal_grid (s) | time ratio ours/GDAL | max abs diff (m) | "
            "cells > 1 mm | nodata mismatches |",
            "|---|---|---|---|---|---|---|---|---|---|---|", *rows, ""]


def whitebox_row(tile) -> str:
    """Whitebox Workflows' classify_buildings_in_lidar on the same tile, if it can run."""
    try:
        import inspect

        import whitebox_workflows as wbw
    except ImportError:
        return ("Whitebox Workflows: not installed (`pip install -r "
                "requirements-bench.txt`); no figures.")
    sig = inspect.signature(wbw.WbEnvironment().classify_buildings_in_lidar)
    if "building_footprints" in sig.parameters:
        return (f"Whitebox Workflows {getattr(wbw, '__version__', '')}: installed and runs "
                f"offline, but `classify_buildings_in_lidar{sig}` takes the building "
                "footprints as an input (it labels the points inside given polygons); it "
                "does not extract buildings, so it has no completeness, correctness, IoU "
                "or height figures to compare. No figures are given for it.")
    return "Whitebox Workflows: unexpected signature; not run."


def bench_buildings() -> list:
    """Row 2: building footprints on synthetic tiles; returns Markdown lines."""
    from geomatics_toolbox.core.lidar.buildings import extract_buildings
    from geomatics_toolbox.synthetic.buildings_eval import building_accuracy
    from geomatics_toolbox.synthetic.lidar import generate_tile
    rows = []
    tile = None
    for seed, side, density in ((4, 220.0, 5.0), (7, 300.0, 4.0), (11, 300.0, 2.0)):
        tile = generate_tile(extent=(side, side), density=density, seed=seed)
        cls = tile.classification.copy()
        cls[np.isin(cls, (5, 6))] = 1
        t = time.perf_counter()
        res = extract_buildings(tile.x, tile.y, tile.z, cls)
        dt = time.perf_counter() - t
        a = building_accuracy(tile, res.labels, res.grid,
                              [b["height"] for b in res.buildings])
        rows.append(f"| ours | {seed} | {side:g} m | {density:g} | {len(tile):,} | "
                    f"{a['n_true']} | {a['n_detected']} | {a['completeness']:.3f} | "
                    f"{a['correctness']:.3f} | {a['mean_iou']:.3f} | "
                    f"{a['height_rmse']:.3f} | {dt:.1f} |")
    return ["## 2. Building footprints on synthetic tiles (buildings ≥ 50 m²)", "",
            "Targets: completeness and correctness ≥ 0.95, mean IoU ≥ 0.85, height RMSE "
            "≤ 0.3 m. Input classes 5 and 6 are reset to 1 (as after a ground filter).",
            "", "| method | seed | tile | density (pts/m²) | points | true | detected | "
            "completeness | correctness | mean IoU | height RMSE (m) | time (s) |",
            "|---|---|---|---|---|---|---|---|---|---|---|---|", *rows, "",
            whitebox_row(tile), ""]


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args(argv)
    n, side = (100_000, 316.0) if args.quick else (1_000_000, 1000.0)
    lines = ["# LiDAR products benchmark", "",
             f"{datetime.date.today()} on {platform.node()} "
             f"({platform.processor() or platform.machine()}), arguments: "
             f"{' '.join(argv or sys.argv[1:]) or '(none)'}.", ""]
    lines += bench_tin(n, side)
    lines += bench_buildings()
    RESULTS.parent.mkdir(exist_ok=True)
    RESULTS.write_text("\n".join(lines) + "\n", encoding="utf-8")
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    sys.exit(main())

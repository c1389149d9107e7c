#!/usr/bin/env python3
"""The whole job against its floor: LAZ → recommended filter → classified LAZ + 1 m IDW DTM.

Rows (each in a fresh single-threaded child, CPU seconds beside wall seconds):

* **job** — what ``geomatics:lidartodtm`` does without the accuracy step: the one
  engine's ``classify_file`` (recommended filter, its default selection, classified LAZ
  written from the records decoded once) and the DTM runner (``core/terrain/dtm.py``:
  1 m IDW of the ground points, GeoTIFF);
* **floor** — the work no implementation of that job can skip, measured in the same
  script on the same file: LAZ decode, LAZ encode of the same points, one KD-tree build
  over the ground points and one 12-neighbour query per DTM cell.

The issue's target: job ≤ 1.5 × floor, and the input decoded once (counted here and in
``tests/qgis/test_one_workflow_defaults.py``). Wall times on a shared machine are noisy;
the ratio uses CPU seconds. One pair of runs varies by ±0.1 in the ratio even idle, so
``--runs`` pairs (default 5) alternate floor and job and the ratio is that of the mean
CPU seconds; every pair is listed. ``--quick`` uses 0.5 M points instead of 4 M. The
results file's first section is rewritten; the sections after it (``## …``, earlier
runs and their notes) are kept.

Usage::

    .venv/bin/python benchmarks/bench_job.py [--quick] [--points N] [--runs N]
"""
from __future__ import annotations

import argparse
import json
import os
import sys
import tempfile
import time
from pathlib import Path

from _probe import run_python

ROOT = Path(__file__).resolve().parents[1]
RESULTS = ROOT / "benchmarks" / "results" / "job.md"

_JOB = r"""
import json, sys
sys.path.insert(0, {bench!r})
from _probe import Probe
from geomatics_toolbox.core.io import las as las_io
from geomatics_toolbox.core.lidar.filters import default_selection, ground_filter
from geomatics_toolbox.core.lidar.pipeline import FilterOutputs, classify_file
from geomatics_toolbox.core.io.points import ClassPoints
from geomatics_toolbox.core.terrain import dtm as core_dtm
from geomatics_toolbox.core.terrain.grid import grid_from_points
# modules the job imports lazily, imported before the probe as the floor's are (laspy
# alone, with pyproj and requests, is 0.3-0.4 s CPU): the rows compare work on points
import laspy, osgeo.gdal
from geomatics_toolbox.core.lidar import recommended, _recommended_filter
from geomatics_toolbox.core.io import _las_write
from geomatics_toolbox.core.terrain import idw
decodes = []
real = las_io._chunks
def counting(reader, path, chunk_size):
    decodes.append(str(path))
    return real(reader, path, chunk_size)
las_io._chunks = counting
probe = Probe()
run = classify_file({src!r}, ground_filter("groundfilter"),
                    FilterOutputs(cloud={out!r}), selection=default_selection("groundfilter"))
t_filter = probe.result()
g = run.classes == 2
pd = run.points
pts = ClassPoints(pd.x[g], pd.y[g], pd.z[g], pd.info, (2,), run.n_points, run.counts(),
                  units=pd.info.units)
grid = grid_from_points(pts.x, pts.y, 1.0, crs=pd.info.crs)
dtm = core_dtm.make_dtm({src!r}, pts, grid, core_dtm.IdwMethod())
core_dtm.write_dtm(dtm, {tif!r})
res = probe.result()
print(json.dumps(dict(res, filter_cpu=t_filter["cpu"], decodes=len(decodes),
                      n=run.n_points, ground=int(g.sum()), cells=grid.size)))
"""

_FLOOR = r"""
import json, sys
sys.path.insert(0, {bench!r})
import numpy as np, laspy
from scipy.spatial import cKDTree
from _probe import Probe
probe = Probe()
las = laspy.read({src!r})                                   # decode
las.write({out!r})                                          # encode
x, y, z = np.asarray(las.x), np.asarray(las.y), np.asarray(las.z)
g = np.asarray(las.classification) == 2
tree = cKDTree(np.column_stack((x[g], y[g])))               # one KD-tree build
x0, y0 = x[g].min(), y[g].min()
nx, ny = int(np.ceil(x[g].max() - x0)), int(np.ceil(y[g].max() - y0))
cx, cy = np.meshgrid(x0 + 0.5 + np.arange(nx), y0 + 0.5 + np.arange(ny))
d, i = tree.query(np.column_stack((cx.ravel(), cy.ravel())), k=12, workers=1)  # one query
res = probe.result()
print(json.dumps(dict(res, n=int(x.size), cells=int(cx.size))))
"""


def make_cloud(path: Path, n_points: int) -> None:
    from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile
    density = 5.0
    side = (n_points / density) ** 0.5
    write_tile(generate_tile(extent=(side, side), density=density, seed=1), path)


def _mean(rows: list) -> dict:
    """Mean of the rows' timings; the highest peak; the counts of the first row."""
    out = dict(rows[0])
    for key in ("wall", "cpu", "filter_cpu"):
        if key in out:
            out[key] = sum(r[key] for r in rows) / len(rows)
    out["peak_mb"] = max(r["peak_mb"] for r in rows)
    out["decodes"] = max(r.get("decodes", 1) for r in rows)
    return out


def _history() -> list:
    """The results file's sections after its first one (earlier runs, notes), kept."""
    if not RESULTS.exists():
        return []
    lines = RESULTS.read_text(encoding="utf-8").splitlines()
    start = next((i for i, line in enumerate(lines) if line.startswith("## ")), len(lines))
    return lines[start:] + [""] if start < len(lines) else []


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true")
    ap.add_argument("--points", type=int, default=None)
    ap.add_argument("--runs", type=int, default=5, help="alternated floor/job pairs")
    args = ap.parse_args(argv)
    n = args.points or (500_000 if args.quick else 4_000_000)
    bench = str(Path(__file__).resolve().parent)
    jobs, floors, loads = [], [], [os.getloadavg()[0]]
    with tempfile.TemporaryDirectory() as tmp:
        src = Path(tmp) / "cloud.laz"
        make_cloud(src, n)
        for _ in range(max(1, args.runs)):
            floors.append(run_python(_FLOOR.format(bench=bench, src=str(src),
                                                   out=str(Path(tmp) / "floor.laz"))))
            jobs.append(run_python(_JOB.format(bench=bench, src=str(src),
                                               out=str(Path(tmp) / "job.laz"),
                                               tif=str(Path(tmp) / "dtm.tif"))))
            loads.append(os.getloadavg()[0])
    job, floor = _mean(jobs), _mean(floors)
    load = os.getloadavg()
    ratio_cpu = job["cpu"] / floor["cpu"]
    ratio_wall = job["wall"] / floor["wall"]
    pairs = " ".join(f"{j['cpu']:.2f} / {f['cpu']:.2f} = {j['cpu'] / f['cpu']:.2f};"
                     for j, f in zip(jobs, floors))
    lines = [
        "# The whole job against its floor (`benchmarks/bench_job.py`)", "",
        f"LAZ → recommended ground filter → classified LAZ + 1 m IDW DTM, {job['n']:,} "
        f"points ({job['ground']:,} ground, {job['cells']:,} DTM cells); the floor is "
        "LAZ decode + LAZ encode + one KD-tree build and one 12-neighbour query per cell, "
        "measured in the same script on the same file. CPU seconds are summed over "
        "threads (the LAZ codec and BLAS may use both cores: CPU exceeds wall idle). "
        f"Means of {len(jobs)} alternated floor/job pairs (peak: the highest).", "",
        "| row | wall (s) | CPU (s) | peak (MB) | points/s (CPU) | input decodes |",
        "|---|---:|---:|---:|---:|---:|",
        f"| job | {job['wall']:.2f} | {job['cpu']:.2f} | {job['peak_mb']:.0f} | "
        f"{job['n'] / job['cpu']:,.0f} | {job['decodes']} |",
        f"| floor | {floor['wall']:.2f} | {floor['cpu']:.2f} | {floor['peak_mb']:.0f} | "
        f"{floor['n'] / floor['cpu']:,.0f} | 1 |",
        f"| **job / floor** | {ratio_wall:.2f} | **{ratio_cpu:.2f}** | | | |", "",
        f"Job / floor CPU of each pair: {pairs.rstrip(';')}. Filter step alone (decode, "
        f"filter, encode): {job['filter_cpu']:.2f} s CPU (mean). Load average (1 min) "
        f"{min(loads):.1f}–{max(loads):.1f} during the runs ({load[1]:.1f} over 5 min) on "
        "a shared 2-core machine: wall times are inflated under load, the ratio is taken "
        "on CPU seconds. Target: ≤ 1.5.", "",
    ]
    if not args.quick:
        RESULTS.write_text("\n".join(lines + _history()), encoding="utf-8")
    print("\n".join(lines))
    print(json.dumps(dict(job=job, floor=floor)), file=sys.stderr)
    return 0


if __name__ == "__main__":
    t0 = time.perf_counter()
    sys.exit(main())

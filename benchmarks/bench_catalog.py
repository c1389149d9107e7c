"""Tile catalog on Dask: wall time, points/s, CPU seconds per phase, serial fraction.

Generates a square catalog of LAZ tiles into a temporary folder (never committed,
removed at the end), runs the catalog with 1 and 2 local workers and reports:

* wall time and points/s per run, peak memory (resident set) per worker;
* CPU seconds per phase — inside the chunks (strips: their share of the neighbour
  reads; read, filter, dtm, write) and in the client (index, plan, cluster start,
  compute, cluster close, mosaic) — and the serial part (everything outside a chunk),
  its fraction of the 1-worker run, and the 2-worker speed-up it predicts on two idle
  cores (load-independent: chunk CPU seconds, largest chunks first), next to the
  measured one;
* a DTM seam check along every internal tile edge: each edge is recomputed from the
  points of a band of 2 x buffer on either side of it (a different decomposition) and
  compared with the catalog mosaic within 2 cells of the edge; and, when the catalog
  fits in memory (``--merged-max``), the same work on the merged cloud.

    python benchmarks/bench_catalog.py --points 100e6      # 25 tiles x 4 M (the target)
    python benchmarks/bench_catalog.py --quick             # 4 tiles x 0.2 M, a minute
    python benchmarks/bench_catalog.py --points 24e6 --tiles 16

Writes benchmarks/results/catalog.md (``--out`` to write elsewhere).
"""
from __future__ import annotations

import argparse
import datetime
import json
import math
import os
import platform
import resource
import shutil
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE.parent / "tests"))
import conftest  # noqa: E402,F401  (imports the checkout as geomatics_toolbox)

from geomatics_toolbox.core.io.las import (  # noqa: E402
    PointData,  # noqa: E402
    iter_las_chunks,
    read_las,
)
from geomatics_toolbox.core.io.raster import read_raster  # noqa: E402
from geomatics_toolbox.core.lidar import catalog as cc  # noqa: E402
from geomatics_toolbox.core.lidar._chunks import (  # noqa: E402
    DTM_METHODS,
    GROUND_FILTERS,
    chunk_dtm,
    snap_grid,
)
from geomatics_toolbox.core.lidar.filters import (  # noqa: E402
    classify_points,
    default_selection,
    ground_filter,
)


def _classify(key, x, y, z, c0):
    """A single-file run of the merged cloud (same filter and selection; the chunks' grids
    and the single file's lie on the same world lattice)."""
    return classify_points(PointData(x, y, z, {"classification": c0}), ground_filter(key),
                           default_selection(key))
from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile  # noqa: E402

DENSITY = 5.0
CHUNK_PHASES = ("strips", "read", "filter", "dtm", "write")   # strips: share of neighbour reads
CLIENT_PHASES = ("index", "plan", "cluster start", "compute", "cluster close", "mosaic")


def generate(folder: Path, n_side: int, per_tile: int) -> float:
    """Write ``n_side`` x ``n_side`` adjacent tiles of ``per_tile`` points; tile side (m)."""
    side = math.sqrt(per_tile / DENSITY)
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


def lpt_makespan(costs, workers: int) -> float:
    """Longest-processing-time-first schedule length of ``costs`` on ``workers``."""
    loads = [0.0] * workers
    for c in sorted(costs, reverse=True):
        k = loads.index(min(loads))
        loads[k] += c
    return max(loads)


def _children_cpu() -> float:
    """CPU seconds of this process's finished children (the local Dask workers)."""
    ru = resource.getrusage(resource.RUSAGE_CHILDREN)
    return ru.ru_utime + ru.ru_stime


def analyse(res, worker_cpu: float) -> dict:
    """Per-phase sums, serial part and per-worker figures of one run.

    ``worker_cpu``: CPU seconds of the worker processes over their whole life (start-up
    imports, Dask bookkeeping and the chunks), measured when the cluster closed.
    """
    done = [c for c in res.chunks if c["key"] not in res.skipped and "phases" in c]
    chunk = {p: [sum(c["phases"].get(p, (0, 0))[0] for c in done),
                 sum(c["phases"].get(p, (0, 0))[1] for c in done)] for p in CHUNK_PHASES}
    chunk_wall = sum(c["seconds"] for c in done)
    chunk_cpu = [c["cpu_seconds"] for c in done]
    workers = {}
    for c in done:
        w = workers.setdefault(c["worker"], dict(chunks=0, busy=0.0, peak=0.0))
        w["chunks"] += 1
        w["busy"] += c["seconds"]
        w["peak"] = max(w["peak"], c["peak_rss_mb"])
    compute = res.timings.get("compute", [0.0, 0.0])[0]
    for w in workers.values():
        w["idle"] = compute - w["busy"]
    return dict(wall=res.seconds, pps=res.points_per_second, chunk=chunk,
                worker_cpu=worker_cpu, client_cpu=sum(v[1] for v in res.timings.values()),
                chunk_wall=chunk_wall, chunk_cpu=chunk_cpu, workers=workers,
                client={p: res.timings.get(p, [0.0, 0.0]) for p in CLIENT_PHASES},
                # the first pass on the workers (core/lidar/_summary.py), summed over tiles
                first_pass=res.settings.get("first_pass_seconds") or [0.0, 0.0],
                # the chunks run again at the catalog's canopy scale (core/lidar/_canopy.py;
                # the counts themselves are taken inside the chunks' filter phase)
                canopy=res.settings.get("canopy_seconds") or [0.0, 0.0],
                canopy_reruns=len(res.settings.get("canopy_reruns") or []))


def merged_run(cat, args, origin):
    t0 = time.perf_counter()
    parts = [read_las(p, ("classification",)) for p in cat.paths]
    x = np.concatenate([p.x for p in parts])
    y = np.concatenate([p.y for p in parts])
    z = np.concatenate([p.z for p in parts])
    c0 = np.concatenate([p["classification"] for p in parts])
    del parts
    cls = _classify(args.filter, x, y, z, c0)
    g = cls == 2
    grid = snap_grid(cat.extent, origin, args.cell)
    ref = chunk_dtm(args.dtm, x[g], y[g], z[g], grid, cat.default_max_distance())
    secs = time.perf_counter() - t0
    peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024.0
    return ref, secs, peak


def _edges(cat, n_side, side):
    """Internal tile edges as (axis, position, lo, hi): axis 0 = vertical line x = pos."""
    e = cat.extent
    out = []
    for k in range(1, n_side):
        for m in range(n_side):
            out.append((0, e[0] + k * side, e[1] + m * side, e[1] + (m + 1) * side))
            out.append((1, e[1] + k * side, e[0] + m * side, e[0] + (m + 1) * side))
    return out


def _band_points(cat, boxes):
    """Points (x, y, z, classification) of every box, each tile decoded once."""
    parts = [[] for _ in boxes]
    for i, path in enumerate(cat.paths):
        tb = cat.bounds[i]
        mine = [k for k, b in enumerate(boxes)
                if b[0] <= tb[2] and b[2] >= tb[0] and b[1] <= tb[3] and b[3] >= tb[1]]
        for _, pd in iter_las_chunks(path, ("classification",)):
            for k in mine:
                b = boxes[k]
                keep = (pd.x >= b[0]) & (pd.x <= b[2]) & (pd.y >= b[1]) & (pd.y <= b[3])
                if keep.any():
                    parts[k].append((pd.x[keep], pd.y[keep], pd.z[keep],
                                     pd["classification"][keep]))
    return parts


def band_seam_check(cat, mosaic_path, args, origin, n_side, side):
    """Max |mosaic - band recomputation| within 2 cells of every internal edge.

    Each edge segment is recomputed from the points of the box that extends
    ``2 * buffer`` beyond it on every side (filter with the same global origin, then
    the DTM), a decomposition unlike the catalog's; cells within 2 cells of the edge
    are then ``2 * buffer - 2 cells`` from that box's rim, beyond the filter's reach.
    """
    mos = read_raster(mosaic_path)
    mz = mos.data.astype(np.float64)
    mz[mz == mos.nodata] = np.nan
    gt = mos.geotransform
    w = 2.0 * args.buffer
    e = cat.extent
    md = cat.default_max_distance()
    edges = _edges(cat, n_side, side)
    boxes = [(pos - w, lo - w, pos + w, hi + w) if axis == 0 else
             (lo - w, pos - w, hi + w, pos + w) for axis, pos, lo, hi in edges]
    bands = _band_points(cat, boxes)
    diffs = []
    for (axis, pos, lo, hi), box, parts in zip(edges, boxes, bands):
        x, y, z, c0 = (np.concatenate([p[k] for p in parts]) for k in range(4))
        cls = _classify(args.filter, x, y, z, c0)
        g = cls == 2
        grid = snap_grid(box, origin, args.cell)
        ref = chunk_dtm(args.dtm, x[g], y[g], z[g], grid, md)
        cx, cy = (v.reshape(grid.shape) for v in grid.block_centers(0, grid.nrows))
        across = cx - pos if axis == 0 else cy - pos
        along = cy if axis == 0 else cx
        outer = np.minimum.reduce([cx - e[0], cy - e[1], e[2] - cx, e[3] - cy])
        sel = ((np.abs(across) <= 2 * args.cell) & (along >= lo) & (along <= hi)
               & (outer > args.buffer) & np.isfinite(ref))
        col = np.round((cx[sel] - gt[0]) / gt[1] - 0.5).astype(int)
        row = np.round((cy[sel] - gt[3]) / gt[5] - 0.5).astype(int)
        d = np.abs(mz[row, col] - ref[sel])
        diffs.append(d[np.isfinite(d)])
    d = np.concatenate(diffs)
    if not d.size:
        return float("nan"), 0, 0, float("nan")
    return float(d.max()), int(d.size), int(np.sum(d > 1e-3)), float(np.quantile(d, 0.999))


def merged_seam_check(mosaic, ref, cat, side, n_side, origin, cell, buffer):
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
    mosaic = mosaic[:grid.nrows, :grid.ncols]
    sel = band & away & np.isfinite(mosaic) & np.isfinite(ref)
    if not sel.any():
        return float("nan"), 0
    return float(np.max(np.abs(mosaic[sel] - ref[sel]))), int(sel.sum())


def parse(argv):
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--points", type=float, default=100e6, help="total points (100e6)")
    ap.add_argument("--tiles", type=int, default=25, help="tiles, a square number (25)")
    ap.add_argument("--quick", action="store_true", help="4 tiles x 0.2 M points")
    ap.add_argument("--filter", default="lsq_faithful", choices=sorted(GROUND_FILTERS))
    ap.add_argument("--dtm", default="idw", choices=sorted(DTM_METHODS))
    ap.add_argument("--cell", type=float, default=1.0)
    ap.add_argument("--buffer", type=float, default=60.0)
    ap.add_argument("--chunk-size", type=float, default=0.0, help="m; 0 = the tiles")
    ap.add_argument("--workers", default="1,2", help="worker counts to run (1,2)")
    ap.add_argument("--merged-max", type=float, default=30e6,
                    help="run the merged cloud only up to this many points")
    ap.add_argument("--no-seam", action="store_true", help="skip the band seam check")
    ap.add_argument("--out", default=str(HERE / "results" / "catalog.md"))
    args = ap.parse_args(argv)
    if args.quick:
        args.tiles, args.points = 4, 0.8e6
    return args


def main(argv=None):
    args = parse(argv)
    n_side = int(round(math.sqrt(args.tiles)))
    per_tile = int(args.points / n_side ** 2)
    tmp = Path(tempfile.mkdtemp(prefix="bench_catalog_"))
    try:
        (tmp / "tiles").mkdir()
        t0 = time.perf_counter()
        side = generate(tmp / "tiles", n_side, per_tile)
        gen_s = time.perf_counter() - t0
        print(f"generated {n_side ** 2} tiles of {per_tile:,} points in {gen_s:.0f} s",
              flush=True)
        cat = cc.Catalog.open(str(tmp / "tiles"))
        runs = {}
        for w in (int(v) for v in args.workers.split(",")):
            load0 = os.getloadavg()[0]
            ch0 = _children_cpu()
            res = cc.run_catalog(str(tmp / "tiles"), tmp / f"out{w}",
                                 ground_filter=args.filter, dtm_method=args.dtm,
                                 cell_size=args.cell, buffer=args.buffer,
                                 chunk_size=args.chunk_size, workers=w)
            runs[w] = (res, analyse(res, _children_cpu() - ch0), (load0, os.getloadavg()[0]))
            print(f"{w} worker(s): {res.seconds:.1f} s, failed {len(res.failed)}",
                  json.dumps({k: v for k, v in runs[w][1].items() if k != "chunk_cpu"}),
                  flush=True)
            Path(args.out).write_text(report(args, cat, side, gen_s, runs, None, None),
                                      encoding="utf-8")      # partial results survive
        last = tmp / f"out{max(runs)}" / "dtm.vrt"
        origin = next(iter(runs.values()))[0].settings["origin"]
        seam = None if args.no_seam else band_seam_check(cat, last, args, origin, n_side,
                                                         side)
        merged = None
        if cat.n_points <= args.merged_max:
            ref, secs, peak = merged_run(cat, args, origin)
            merged = (secs, peak, merged_seam_check(dtm(last), ref, cat, side, n_side, origin,
                                                    args.cell, args.buffer))
    finally:
        shutil.rmtree(tmp, ignore_errors=True)
    text = report(args, cat, side, gen_s, runs, seam, merged)
    Path(args.out).write_text(text, encoding="utf-8")
    print(text)


def _run_rows(cat, runs, merged):
    lines = ["| run | wall time (s) | points/s | peak memory per worker (MB) | chunks per "
             "worker | worker idle (s) | load avg (start → end) |",
             "|---|---|---|---|---|---|---|"]
    for w, (_res, a, load) in sorted(runs.items()):
        ws = sorted(a["workers"].values(), key=lambda v: -v["chunks"])
        peaks = " / ".join(f"{v['peak']:.0f}" for v in ws)
        counts = " / ".join(str(v["chunks"]) for v in ws)
        idle = " / ".join(f"{v['idle']:.1f}" for v in ws)
        lines.append(f"| catalog, {w} worker(s) | {a['wall']:.1f} | {a['pps']:,.0f} | "
                     f"{peaks} | {counts} | {idle} | {load[0]:.1f} → {load[1]:.1f} |")
    if merged:
        secs, peak, _ = merged
        lines.append(f"| merged cloud, 1 process | {secs:.1f} | {cat.n_points / secs:,.0f} | "
                     f"{peak:.0f} | – | – | – |")
    return lines


def _phase_rows(runs):
    lines = ["| phase | " + " | ".join(f"{w} worker(s): wall s / CPU s" for w in sorted(runs))
             + " |", "|---|" + "---|" * len(runs)]
    lines.append("| first pass: summaries, strips' decodes aside (sum, workers) | " + " | ".join(
        f"{runs[w][1]['first_pass'][0]:.1f} / {runs[w][1]['first_pass'][1]:.1f}"
        for w in sorted(runs)) + " |")
    lines.append("| chunks run again at the catalog's canopy scale (sum, workers) | " + " | ".join(
        f"{runs[w][1]['canopy'][0]:.1f} / {runs[w][1]['canopy'][1]:.1f} "
        f"({runs[w][1].get('canopy_reruns', 0)} chunks)"
        for w in sorted(runs)) + " |")
    for p in CHUNK_PHASES:
        lines.append(f"| chunks: {p} (sum) | " + " | ".join(
            f"{runs[w][1]['chunk'][p][0]:.1f} / {runs[w][1]['chunk'][p][1]:.1f}"
            for w in sorted(runs)) + " |")
    for p in CLIENT_PHASES:
        lines.append(f"| client: {p} | " + " | ".join(
            f"{runs[w][1]['client'][p][0]:.1f} / {runs[w][1]['client'][p][1]:.1f}"
            for w in sorted(runs)) + " |")
    return lines


def predicted_times(a, n_workers: int) -> dict:
    """Serial part and predicted idle-machine times for 1 and 2 workers, from CPU seconds.

    ``a`` is the analysis of one run with ``n_workers`` workers. Serial ``S``: the
    client process's CPU outside the compute phase (index, plan, cluster start and
    close, mosaic) plus one worker's CPU outside its chunks (start-up imports, Dask
    bookkeeping: every worker pays it, in parallel). Parallel: the chunks' CPU seconds,
    scheduled longest-first. The client's CPU during compute (scheduler, nannies) is a
    rate ``r`` per second of run: free on the idle second core with 1 worker, taken
    from the two workers' cores with 2: ``T2 = (S + makespan) / (1 - r / 2)``.
    """
    par = sum(a["chunk_cpu"])
    startup = max(a["worker_cpu"] - par, 0.0) / n_workers
    client = sum(v[1] for k, v in a["client"].items() if k != "compute")
    comp = a["client"]["compute"]
    rate = comp[1] / comp[0] if comp[0] > 0 else 0.0
    serial = client + startup
    t1 = serial + par
    t2 = (serial + lpt_makespan(a["chunk_cpu"], 2)) / (1.0 - rate / 2.0)
    return dict(par=par, startup=startup, client=client, rate=rate, serial=serial,
                t1=t1, t2=t2)


def _amdahl(runs):
    """Serial part and predicted speed-up from CPU seconds (load-independent)."""
    w = min(runs)
    a = runs[w][1]
    p = predicted_times(a, w)
    f = (p["t2"] * 2 - p["t1"]) / p["t1"]     # Amdahl's f from the predicted times
    thr = max(a["chunk"][k][1] / max(a["chunk"][k][0], 1e-9) for k in CHUNK_PHASES)
    lines = [f"From the {w}-worker run, CPU seconds: chunks {p['par']:.1f} (the parallel "
             f"work); client process outside the compute phase {p['client']:.1f} (index, "
             f"plan, cluster start/close, mosaic) and worker start-up/bookkeeping "
             f"{p['startup']:.1f} per worker (CPU outside the chunks; each worker pays it "
             f"once, in parallel): the serial part, {p['serial']:.1f} s. During compute "
             f"the client process (scheduler, nannies) used {p['rate'] * 1000:.0f} ms of "
             f"CPU per second of run. Largest CPU/wall ratio of a chunk phase: {thr:.2f} "
             "(≤ 1: one thread per worker).",
             "",
             f"Predicted on two idle cores from these CPU seconds (serial part + "
             f"longest-first schedule of the chunk CPU times, client overhead taken from "
             f"the workers' cores): 1 worker {p['t1']:.0f} s, 2 workers {p['t2']:.0f} s → "
             f"**{p['t1'] / p['t2']:.2f}×**, i.e. an effective **serial fraction "
             f"{max(f, 0.0):.3f}** (Amdahl, including load imbalance and the scheduler). "
             "The model counts CPU only: two busy cores sharing memory bandwidth, caches "
             "and a lower turbo clock are not in it — only an idle-machine run shows them."]
    if 1 in runs and 2 in runs:
        meas = runs[1][1]["wall"] / runs[2][1]["wall"]
        lines += ["", f"Measured wall-clock speed-up 2 workers vs 1: **{meas:.2f}×** "
                  "(depends on the machine load shown above)."]
    return lines


def report(args, cat, side, gen_s, runs, seam, merged) -> str:
    cmd = "python benchmarks/bench_catalog.py " + " ".join(sys.argv[1:])
    lines = [
        "# Tile catalog on Dask",
        "",
        "Re-run (self-contained: generates the tiles into a temporary folder and removes "
        "it; about 1 GB of LAZ per 100 M points): `python benchmarks/bench_catalog.py "
        "--points 100e6` (25 tiles × 4 M points, 1 then 2 local workers). Wall-clock "
        "figures need an otherwise idle machine; the CPU seconds per phase, the serial "
        "fraction and the predicted speed-up do not.",
        "",
        f"{datetime.datetime.now(datetime.timezone.utc):%Y-%m-%d %H:%M} UTC, "
        f"{platform.node()} ({platform.machine()}, {os.cpu_count()} cores, Python "
        f"{platform.python_version()}); load average before the run "
        f"{runs[min(runs)][2][0]:.1f}. Command: `{cmd.strip()}`.",
        "",
        f"{len(cat.tiles)} generated tiles of {side:.0f} m × {side:.0f} m, "
        f"{cat.n_points:,} points in total (generation {gen_s:.0f} s, not timed below); "
        f"ground filter `{args.filter}`, {args.dtm.upper()} DTM at {args.cell:g} m, buffer "
        f"{args.buffer:g} m, chunks: "
        f"{'the tiles' if not args.chunk_size else f'{args.chunk_size:g} m squares'}. "
        "Peak memory: largest resident set of each worker process (catalog) or of the "
        "process (merged).",
        "",
    ]
    lines += _run_rows(cat, runs, merged)
    lines += ["", "CPU seconds per phase (chunks: summed over all chunks, in the workers; "
              "client: the process that runs the catalog):", ""]
    lines += _phase_rows(runs)
    lines += [""] + _amdahl(runs) + [""]
    if seam:
        lines.append(f"Seam check (every internal tile edge recomputed from a band of "
                     f"±{2 * args.buffer:g} m): |catalog DTM − band DTM| over {seam[1]:,} "
                     f"cells within 2 cells of an edge: max {seam[0] * 1000:.3f} mm, "
                     f"99.9th percentile {seam[3] * 1000:.3f} mm, {seam[2]} cell(s) "
                     "over 1 mm.")
    if merged:
        err, n = merged[2]
        lines.append(f"Merged cloud: max |catalog DTM − merged DTM| over {n:,} cells within "
                     f"2 cells of an internal edge (away from the outer edge): "
                     f"{err * 1000:.3f} mm.")
    else:
        lines.append(f"Merged cloud: not run ({cat.n_points:,} points > --merged-max "
                     f"{args.merged_max:,.0f}: it does not fit in memory here).")
    return "\n".join(lines) + "\n"


if __name__ == "__main__":
    main()

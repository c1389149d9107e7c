"""Benchmark of the Vosselman slope filter: ISPRS accuracy, throughput, memory, brute force.

Run:  .venv/bin/python benchmarks/bench_slope.py [--quick]

Rows written to ``benchmarks/results/slope.md``:

1. ISPRS reference samples (``../shared/data/isprs``; skipped with a message when
   absent): total / Type I / Type II error and kappa at the default setting, at
   the forest study's setting, in the terrain-adaptive mode, and the best of a
   sweep over θ, r and h (best by total error), next to published peers.
2. Throughput and peak memory on the synthetic 10 M point tile
   (:func:`core.synthetic.generate_tile`, 1 km x 1 km at 10 pts/m2) at r = 3 m and
   r = 10 m. Each run is a fresh subprocess with one thread (OMP/BLAS threads = 1);
   peak memory is that process's peak resident set ``VmHWM`` from
   ``/proc/self/status``, reset just before the filter (``/proc/self/clear_refs``),
   so it covers the filter plus everything already resident (Python, numpy, scipy and
   the 240 MB of loaded coordinates: the *baseline*). ``ru_maxrss`` is not used: on
   Linux it keeps the parent's peak across fork/exec.
3. Speed reference: the brute force (``cKDTree.sparse_distance_matrix`` of every
   pair within r, then the canonical comparison) on a 1 M point window of the same
   tile, with a check that both give identical labels.

``--quick`` uses a 1 M point tile, a 100 k brute-force window and a smaller sweep.
"""
from __future__ import annotations

import argparse
import os
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
from _probe import run_python

ROOT = Path(__file__).resolve().parents[1]
ISPRS = Path(os.environ.get("GEOMATICS_ISPRS_DIR", ROOT.parent / "shared" / "data" / "isprs"))
RESULTS = ROOT / "benchmarks" / "results" / "slope.md"
SAMPLES = ("samp11", "samp12", "samp31", "samp54")
# Published totals (%) for context (anchors.md): CSF per sample (Zhang 2016) and the
# LSQ polynomial seed paper.
CSF = {"samp11": 12.01, "samp12": 2.97, "samp31": 1.61, "samp54": 3.18}
LSQ = {"samp11": 22.1, "samp12": 6.44, "samp31": 3.03, "samp54": 4.04}
LIMITS = {"samp11": 21.0, "samp12": 11.0, "samp31": 8.0, "samp54": 5.5}




# ----------------------------------------------------------------------------- ISPRS
def isprs_rows(quick: bool):
    from geomatics_toolbox.core.io.las import read_las
    from geomatics_toolbox.core.lidar import pipeline as sp
    from geomatics_toolbox.core.lidar import slope as sf
    from geomatics_toolbox.core.lidar import sweep as slope_sweep
    from geomatics_toolbox.core.lidar.accuracy import assess

    if not (ISPRS / "samp11.laz").exists():
        return None, f"ISPRS samples not found in {ISPRS}; ISPRS rows skipped."
    slopes = list(range(20, 72, 4)) if quick else list(range(20, 71, 2))
    radii = [3, 5, 10, 20] if quick else [3, 5, 8, 10, 15, 20, 30]
    hs = [0.0, 0.2] if quick else [0.0, 0.1, 0.2, 0.3, 0.5]
    rows = []
    common = {"exact": {}, "adaptive": {}}
    for name in SAMPLES:
        pd = read_las(ISPRS / f"{name}.laz", ["classification"])
        ref = pd["classification"] == 2
        sel = sp.select_points(pd, keep_noise_classes=False)
        out = {"sample": name, "n": len(pd), "low_outliers": int(sel.low_outliers.sum())}
        settings = {
            "default": dict(mode="exact"),
            "paper": dict(mode="exact", **sf.PAPER_SETTING),
            "adaptive": dict(mode="adaptive"),
        }
        for key, kw in settings.items():
            t = time.perf_counter()
            r = sf.slope_filter(pd.x, pd.y, pd.z, classify=sel.candidates,
                                neighbours=sel.candidates, **kw)
            acc = assess(r.ground, ref)
            out[key] = dict(acc.as_dict(), seconds=time.perf_counter() - t)
        for mode in ("exact", "adaptive"):
            t = time.perf_counter()
            sw = slope_sweep.threshold_sweep(pd.x, pd.y, pd.z, ref, slopes=slopes,
                                             radii=radii, height_tolerance=hs,
                                             classify=sel.candidates,
                                             neighbours=sel.candidates, mode=mode)
            b = sw.best
            out[f"best_{mode}"] = dict(b.as_dict(), seconds=time.perf_counter() - t,
                                       settings=len(sw.rows))
            for row in sw.rows:
                key = (row.radius, row.slope, row.height_tolerance)
                common[mode].setdefault(key, []).append(row.total)
        rows.append(out)
        print(f"{name}: default {out['default']['total']:.2f} %, best "
              f"{out['best_exact']['total']:.2f} % (r={out['best_exact']['radius']:g}, "
              f"θ={out['best_exact']['slope']:g}, h={out['best_exact']['height_tolerance']:g})",
              flush=True)
    best_common = {}
    for mode, table in common.items():
        key, vals = min(table.items(), key=lambda kv: (np.mean(kv[1]), kv[0]))
        best_common[mode] = dict(radius=key[0], slope=key[1], height_tolerance=key[2],
                                 totals=vals, mean=float(np.mean(vals)))
    return rows, dict(slopes=slopes, radii=radii, hs=hs, common=best_common)


# ----------------------------------------------------------------------------- speed
_CHILD = r"""
import json, os, sys
import numpy as np
from geomatics_toolbox.core.lidar import slope as sf
from geomatics_toolbox.core.lidar import sweep
from geomatics_toolbox.synthetic import oracles
x = np.load({xyz!r} + ".x.npy"); y = np.load({xyz!r} + ".y.npy"); z = np.load({xyz!r} + ".z.npy")
sel = None
if {window!r}:
    x0, y0, side = {window!r}
    m = (x < x0 + side) & (y < y0 + side)
    x, y, z = x[m].copy(), y[m].copy(), z[m].copy()
sys.path.insert(0, {bench!r})
from _probe import Probe
probe = Probe()
if {what!r} == "sweep":
    ref = np.load({xyz!r} + ".g.npy")
    sw = sweep.threshold_sweep(x, y, z, ref, slopes=list(range(20, 71, 2)), radii=[{radius}],
                            height_tolerance={h})
    labels = sw.best_ground
    stats = dict(settings=len(sw.rows), best_slope=sw.best.slope, best_total=sw.best.total)
elif {what!r} == "fast":
    res = sf.slope_filter(x, y, z, radius={radius}, slope={slope}, height_tolerance={h})
    labels = res.ground
    stats = res.stats
else:
    s = oracles.max_slope_reference(x, y, z, radius={radius}, height_tolerance={h})
    labels = ~(s > np.tan(np.radians({slope})))
    stats = {{}}
measured = probe.result()
if {labels_out!r}:
    np.save({labels_out!r}, labels)
print(json.dumps(dict(n=int(x.size), **measured, n_ground=int(labels.sum()), stats=stats)))
"""


def run_child(xyz: str, *, what: str, radius: float, slope: float = 40.0, h: float = 0.2,
              window=None, labels_out: str = "") -> dict:
    code = _CHILD.format(xyz=xyz, window=window, what=what, radius=radius, slope=slope,
                         h=h, labels_out=labels_out, bench=str(ROOT / "benchmarks"))
    return run_python(code)


def speed_rows(quick: bool, tmp: str):
    from geomatics_toolbox.synthetic.lidar import generate_tile

    side = 316.23 if quick else 1000.0
    t = time.perf_counter()
    tile = generate_tile(extent=(side, side), density=10.0, seed=7)
    gen = time.perf_counter() - t
    xyz = os.path.join(tmp, "tile")
    np.save(xyz + ".x.npy", tile.x)
    np.save(xyz + ".y.npy", tile.y)
    np.save(xyz + ".z.npy", tile.z)
    np.save(xyz + ".g.npy", tile.classification == 2)
    n = len(tile)
    x0, y0 = float(tile.x.min()), float(tile.y.min())
    del tile
    print(f"tile: {n} points ({gen:.1f} s to generate)", flush=True)
    rows = []
    for radius in (3.0, 10.0):
        res = run_child(xyz, what="fast", radius=radius)
        rows.append(dict(res, radius=radius))
        print(f"r={radius:g}: {res['n'] / res['wall']:.0f} points/s, peak "
              f"{res['peak_mb']:.0f} MB", flush=True)
    sweep = run_child(xyz, what="sweep", radius=3.0)
    print(f"sweep of {sweep['stats']['settings']} thresholds: {sweep['wall']:.1f} s", flush=True)
    # brute force on a window of ~1 M points (100 k in quick mode)
    wside = 100.0 if quick else 316.23
    window = (x0, y0, wside)
    fast_lab, brute_lab = os.path.join(tmp, "fast.npy"), os.path.join(tmp, "brute.npy")
    f = run_child(xyz, what="fast", radius=3.0, window=window, labels_out=fast_lab)
    b = run_child(xyz, what="brute", radius=3.0, window=window, labels_out=brute_lab)
    same = bool(np.array_equal(np.load(fast_lab), np.load(brute_lab)))
    print(f"brute force {b['wall']:.1f} s vs fast {f['wall']:.2f} s on {b['n']} points; "
          f"identical labels: {same}", flush=True)
    return dict(n=n, gen=gen, rows=rows, brute=b, fast=f, same=same, side=side, sweep=sweep)


# ----------------------------------------------------------------------------- report
def _f(v, d=2):
    return "–" if v is None or not np.isfinite(v) else f"{v:.{d}f}"


def write_markdown(isprs, isprs_info, speed, quick: bool) -> str:
    lines = ["# Slope-based ground filter (Vosselman 2000) — benchmark", "",
             f"Generated by `benchmarks/bench_slope.py{' --quick' if quick else ''}` on "
             f"{time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())}; machine shared with "
             "other jobs (timings noisy; ratios are from the same script).", ""]
    lines += ["## ISPRS reference samples", ""]
    if isprs is None:
        lines += [f"_{isprs_info}_", ""]
    else:
        lines += [
            "Total error (%) — Type I / Type II / kappa in the detailed table. Low-outlier "
            "pre-filter on (its points count as non-ground). *default*: r = 10 m, θ = 40°, "
            "h = 0.2 m, exact; *paper*: the forest study's r = 3 m, θ = 44°, h = 0; "
            "*adaptive*: default setting in the terrain-adaptive mode (toolbox extension); "
            "*best*: best total of the sweep over θ = "
            f"{isprs_info['slopes'][0]}…{isprs_info['slopes'][-1]}° (step "
            f"{isprs_info['slopes'][1] - isprs_info['slopes'][0]}), r = "
            f"{', '.join(map(str, isprs_info['radii']))} m, h = "
            f"{', '.join(map(str, isprs_info['hs']))} m "
            f"({len(isprs_info['slopes']) * len(isprs_info['radii']) * len(isprs_info['hs'])} "
            "settings, one exact pass per (r, h)).", "",
            "| sample | points | default | paper 3 m/44°/0 | adaptive | best exact (r, θ, h) "
            "| best adaptive | issue limit | CSF (Zhang 2016) | LSQ seed paper |",
            "|---|---|---|---|---|---|---|---|---|---|"]
        for r in isprs:
            be, ba = r["best_exact"], r["best_adaptive"]
            ok = "met" if be["total"] <= LIMITS[r["sample"]] else "NOT met"
            lines.append(
                f"| {r['sample']} | {r['n']} | {_f(r['default']['total'])} | "
                f"{_f(r['paper']['total'])} | {_f(r['adaptive']['total'])} | "
                f"**{_f(be['total'])}** ({be['radius']:g} m, {be['slope']:g}°, "
                f"{be['height_tolerance']:g} m) | {_f(ba['total'])} ({ba['radius']:g} m, "
                f"{ba['slope']:g}°, {ba['height_tolerance']:g} m) | ≤ {LIMITS[r['sample']]} "
                f"({ok}) | {CSF[r['sample']]} | {LSQ[r['sample']]} |")
        mean = {k: np.mean([r[k]["total"] for r in isprs])
                for k in ("default", "paper", "adaptive", "best_exact", "best_adaptive")}
        lines.append(f"| mean | | {_f(mean['default'])} | {_f(mean['paper'])} | "
                     f"{_f(mean['adaptive'])} | {_f(mean['best_exact'])} | "
                     f"{_f(mean['best_adaptive'])} | | "
                     f"{_f(np.mean(list(CSF.values())))} | {_f(np.mean(list(LSQ.values())))} |")
        lines += ["", "Best single setting for all four samples (lowest mean total of the same "
                  "sweep):", "", "| mode | r | θ | h | samp11 | samp12 | samp31 | samp54 | "
                  "mean |", "|---|---|---|---|---|---|---|---|---|"]
        for mode, c in isprs_info["common"].items():
            lines.append(f"| {mode} | {c['radius']:g} m | {c['slope']:g}° | "
                         f"{c['height_tolerance']:g} m | "
                         + " | ".join(_f(v) for v in c["totals"]) + f" | {_f(c['mean'])} |")
        lines += ["", "Detail (Type I / Type II / total / kappa, %; sweep time):", "",
                  "| sample | setting | Type I | Type II | total | kappa | time (s) |",
                  "|---|---|---|---|---|---|---|"]
        for r in isprs:
            for key in ("default", "paper", "adaptive", "best_exact", "best_adaptive"):
                v = r[key]
                lines.append(f"| {r['sample']} | {key} | {_f(v['type1'])} | {_f(v['type2'])} "
                             f"| {_f(v['total'])} | {_f(v['kappa'], 1)} | "
                             f"{_f(v['seconds'], 2)} |")
        best_r = sorted({r["best_exact"]["radius"] for r in isprs})
        lines += ["", "The slope rule keeps roof interiors farther than r from an edge and "
                  "rejects terrain steeper than θ, so the best setting depends on the scene "
                  f"(best exact radii: {', '.join(f'{v:g}' for v in best_r)} m). The forest "
                  "study's 3 m radius leaves most roofs as ground on these urban samples. "
                  "In adaptive mode the terrain slope is removed first, so lower θ values "
                  "win. CSF and SMRF (anchors) remain better on these samples.", ""]
    lines += ["## Throughput and memory (synthetic tile)", ""]
    if speed is None:
        lines += ["_skipped_", ""]
    else:
        side = speed["side"]
        lines += [f"Tile: {speed['n']:,} points ({side * side / 1e6:.2f} km² at 10 pts/m², "
                  f"`core.synthetic.generate_tile(extent=({side:g}, {side:g}), density=10, "
                  "seed=7)`), θ = 40°, h = 0.2 m, "
                  "exact mode, one thread. Peak = `VmHWM` (peak resident set) of a fresh "
                  "subprocess, reset before filtering, so it includes the *baseline* "
                  "(interpreter, libraries and the loaded coordinates, resident before "
                  "filtering).", "",
                  "| radius | points | wall (s) | CPU (s) | points/s (wall) | points/s (CPU) | "
                  "baseline (MB) | peak (MB) | settled by bounds | exact pair tests | "
                  "grid cell (m) |",
                  "|---|---|---|---|---|---|---|---|---|---|---|"]
        for r in speed["rows"]:
            st = r["stats"]
            settled = 100 * st["settled_by_bound"] / st["points"]
            lines.append(f"| {r['radius']:g} m | {r['n']:,} | {r['wall']:.2f} | "
                         f"{r['cpu']:.2f} | {r['n'] / r['wall']:,.0f} | "
                         f"{r['n'] / r['cpu']:,.0f} | {r['base_mb']:.0f} | "
                         f"{r['peak_mb']:.0f} | {settled:.1f} % "
                         f"| {st['pairs_tested']:,} | {st['cell_size']:.2f} |")
        r3 = speed["rows"][0]
        pps = r3["n"] / r3["wall"]
        lines += ["", f"Targets at r = 3 m: ≥ 300 000 points/s on one core → "
                  f"{pps:,.0f} wall-clock, {r3['n'] / r3['cpu']:,.0f} per CPU second "
                  f"({'met' if pps >= 3e5 else 'NOT met'}); "
                  f"peak ≤ 4 GB → {r3['peak_mb'] / 1024:.2f} GB "
                  f"({'met' if r3['peak_mb'] <= 4096 else 'NOT met'}).", ""]
        sw, r3 = speed["sweep"], speed["rows"][0]
        lines += ["### Threshold sweep cost", "",
                  f"Sweep of θ = 20…70° step 2 ({sw['stats']['settings']} settings) at r = 3 m "
                  f"on the whole tile: {sw['wall']:.1f} s wall ({sw['cpu']:.1f} s CPU), peak "
                  f"{sw['peak_mb']:.0f} MB, against {r3['wall']:.1f} s for one single-θ run: "
                  "one exact pass gives every threshold (best total "
                  f"{sw['stats']['best_total']:.2f} % at θ = {sw['stats']['best_slope']:g}° "
                  "against the tile's true classes).", ""]
        b, f = speed["brute"], speed["fast"]
        lines += ["### Speed reference: brute force", "",
                  f"Window of {b['n']:,} points of the same tile, r = 3 m, θ = 40°, h = 0.2 m.",
                  "", "| method | wall (s) | points/s | peak (MB) |", "|---|---|---|---|",
                  f"| brute force: cKDTree.sparse_distance_matrix, every pair within r | "
                  f"{b['wall']:.1f} | {b['n'] / b['wall']:,.0f} | {b['peak_mb']:.0f} |",
                  f"| this filter (bounds + exact candidate pairs) | {f['wall']:.2f} | "
                  f"{f['n'] / f['wall']:,.0f} | {f['peak_mb']:.0f} |", "",
                  f"Speed-up {b['wall'] / f['wall']:.0f}×; labels identical to the brute "
                  f"force: **{'yes' if speed['same'] else 'NO'}** "
                  f"({f['n_ground']:,} vs {b['n_ground']:,} ground points).", ""]
    text = "\n".join(lines) + "\n"
    RESULTS.parent.mkdir(parents=True, exist_ok=True)
    RESULTS.write_text(text, encoding="utf-8")
    return text


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="1 M tile, smaller sweep")
    ap.add_argument("--skip-speed", action="store_true", help="ISPRS rows only")
    args = ap.parse_args(argv)
    isprs, info = isprs_rows(args.quick)
    speed = None
    if not args.skip_speed:
        with tempfile.TemporaryDirectory() as tmp:
            speed = speed_rows(args.quick, tmp)
    print(write_markdown(isprs, info, speed, args.quick))
    return 0


if __name__ == "__main__":
    sys.exit(main())

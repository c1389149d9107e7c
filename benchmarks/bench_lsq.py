"""Benchmark of the tiled least-squares polynomial (LSQ) ground filter.

Run:  .venv/bin/python benchmarks/bench_lsq.py [--quick]

Writes ``benchmarks/results/lsq.md`` with:

1. ISPRS reference samples (``../shared/data/isprs``; skipped with a message when
   absent): faithful mode at the paper's tile sizes for T = 0.5, 0.75, 1.0 m (with
   and without the paper's optional gross-outlier pre-step, and iterated to
   convergence instead of the paper's 5 iterations), improved mode with its ONE
   default parameter set, an ablation of every improved-mode idea, and CSF (PyPI
   ``cloth-simulation-filter``) with its documented defaults and the best of a small
   grid — total / Type I / Type II error and kappa (Sithole & Vosselman 2004).
2. Throughput and peak memory on the synthetic tile of ``core.synthetic`` (10 M
   points: 1 km x 1 km at 10 pts/m²) and peak memory at 20 M points. Each run is a
   fresh subprocess with one thread (OMP/BLAS = 1); peak memory is that process's
   ``VmHWM`` (peak resident set, /proc/self/status) reset just before the filter via
   /proc/self/clear_refs, so it covers the filter plus what was already resident
   (Python, numpy, scipy and the loaded coordinates: the *baseline*).
3. LSQ next to CSF on a 1 M point synthetic tile: time and error against the
   generator's labels.

``--quick`` uses 1 M / 2 M point tiles and a smaller CSF grid.
"""
from __future__ import annotations

import argparse
import datetime
import itertools
import os
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
from _probe import run_python

ROOT = Path(__file__).resolve().parents[1]
ISPRS = Path(os.environ.get("GEOMATICS_ISPRS_DIR", ROOT.parent / "shared" / "data" / "isprs"))
RESULTS = ROOT / "benchmarks" / "results" / "lsq.md"
PAPER = {"samp31": (100, 3.03), "samp54": (50, 4.04), "samp12": (100, 6.44),
         "samp11": (50, 22.1)}
CSF_PUBLISHED = {"samp11": 12.01, "samp12": 2.97, "samp31": 1.61, "samp54": 3.18}




def _acc(pred, ref):
    from geomatics_toolbox.core.lidar.accuracy import assess
    return assess(pred, ref)


# ----------------------------------------------------------------------------- CSF
def csf_ground(x, y, z, *, cloth_resolution=None, rigidness=None, slope_smooth=None,
               class_threshold=None):
    """Ground mask by CSF (Zhang et al. 2016); None keeps the package default."""
    import CSF
    csf = CSF.CSF()
    if cloth_resolution is not None:
        csf.params.cloth_resolution = float(cloth_resolution)
    if rigidness is not None:
        csf.params.rigidness = int(rigidness)
    if slope_smooth is not None:
        csf.params.bSloopSmooth = bool(slope_smooth)
    if class_threshold is not None:
        csf.params.class_threshold = float(class_threshold)
    xyz = np.column_stack((x - x.min(), y - y.min(), z - z.min()))
    csf.setPointCloud(xyz)
    ground, non_ground = CSF.VecInt(), CSF.VecInt()
    devnull = os.open(os.devnull, os.O_WRONLY)
    saved = os.dup(1)
    try:                        # CSF prints its progress on stdout
        sys.stdout.flush()
        os.dup2(devnull, 1)
        csf.do_filtering(ground, non_ground)
    finally:
        os.dup2(saved, 1)
        os.close(devnull)
        os.close(saved)
    mask = np.zeros(x.size, dtype=bool)
    mask[np.asarray(ground, dtype=np.int64)] = True
    return mask


def csf_grid(quick):
    res = (0.5, 1.0, 2.0)
    rig = (1, 2, 3)
    smooth = (True, False) if not quick else (True,)
    return [dict(cloth_resolution=a, rigidness=b, slope_smooth=c)
            for a, b, c in itertools.product(res, rig, smooth)]


# ----------------------------------------------------------------------------- ISPRS
def isprs_section(quick):
    from geomatics_toolbox.core.io.las import read_las
    from geomatics_toolbox.core.lidar.lsq import lsq_ground_filter

    if not (ISPRS / "samp11.laz").exists():
        return None, f"ISPRS samples not found in {ISPRS}; ISPRS rows skipped."
    data = {}
    for name in PAPER:
        pd = read_las(ISPRS / f"{name}.laz", ("classification",))
        data[name] = (pd.x, pd.y, pd.z, pd["classification"] == 2)
    out = {"faithful": {}, "improved": {}, "ablation": {}, "csf": {}}

    def run(name, **kw):
        x, y, z, ref = data[name]
        t = time.perf_counter()
        r = lsq_ground_filter(x, y, z, **kw)
        dt = time.perf_counter() - t
        a = _acc(r.ground, ref)
        return dict(total=a.total, type1=a.type1, type2=a.type2, kappa=a.kappa, time=dt,
                    pps=x.size / dt)

    # faithful
    for name, (tile, _) in PAPER.items():
        rows = {}
        for T in (0.5, 0.75, 1.0):
            rows[("noise", T)] = run(name, tile_size=tile, threshold=T, noise=True)
            rows[("plain", T)] = run(name, tile_size=tile, threshold=T, noise=False)
            rows[("converged", T)] = run(name, tile_size=tile, threshold=T, noise=True,
                                         max_iterations=100)
            rows[("cumulative", T)] = run(name, tile_size=tile, threshold=T, noise=True,
                                          rejection="cumulative")
        out["faithful"][name] = rows
        print(f"faithful {name}: " + ", ".join(
            f"{k[0]} T{k[1]} {v['total']:.2f}" for k, v in rows.items()), flush=True)
    # improved, one parameter set
    for name in PAPER:
        out["improved"][name] = run(name, mode="improved")
    print("improved: " + ", ".join(f"{k} {v['total']:.2f}"
                                   for k, v in out["improved"].items()), flush=True)
    # ablation: each idea removed (or a variant) with everything else at the defaults
    variants = {
        "defaults": {},
        "no low-outlier pre-filter": dict(noise=False),
        "single level (tile 50 m)": dict(levels=(1.0,)),
        "levels 50, 25, 12.5 m": dict(levels=(1.0, 0.5, 0.25)),
        "levels 100 … 6.25 m": dict(levels=(2.0, 1.0, 0.5, 0.25, 0.125)),
        "no window overlap": dict(overlap=0.0),
        "overlap 0.5": dict(overlap=0.5),
        "no slope term": dict(slope_factor=0.0),
        "slope term uncapped": dict(slope_cap=float("inf")),
        "bilinear blending across seams": dict(blend=True),
        "20 iterations": dict(max_iterations=20),
        "cumulative rejection": dict(rejection="cumulative"),
        "T = 0.75": dict(threshold=0.75),
    }
    for label, kw in variants.items():
        out["ablation"][label] = {name: run(name, mode="improved", **kw)["total"]
                                  for name in PAPER}
        print(f"ablation {label}: {np.mean(list(out['ablation'][label].values())):.2f}",
              flush=True)
    # CSF
    grid = csf_grid(quick)
    for name in PAPER:
        x, y, z, ref = data[name]
        t = time.perf_counter()
        g = csf_ground(x, y, z)
        dt = time.perf_counter() - t
        a = _acc(g, ref)
        res = {"default": dict(total=a.total, type1=a.type1, type2=a.type2, kappa=a.kappa,
                               time=dt, pps=x.size / dt)}
        for k, kw in enumerate(grid):
            a = _acc(csf_ground(x, y, z, **kw), ref)
            res[k] = dict(total=a.total, type1=a.type1, type2=a.type2, kappa=a.kappa)
        out["csf"][name] = res
        best = min(range(len(grid)), key=lambda k: res[k]["total"])
        print(f"CSF {name}: default {res['default']['total']:.2f}, best "
              f"{res[best]['total']:.2f} {grid[best]}", flush=True)
    out["csf_grid"] = grid
    return out, None


# ----------------------------------------------------------------------------- speed
_CHILD = r"""
import json, os, sys
import numpy as np
from geomatics_toolbox.core.lidar.lsq import lsq_ground_filter
x = np.load({xyz!r} + ".x.npy"); y = np.load({xyz!r} + ".y.npy"); z = np.load({xyz!r} + ".z.npy")
sys.path.insert(0, {bench!r})
from _probe import Probe
probe = Probe()
if {what!r} == "csf":
    from bench_lsq import csf_ground
    ground = csf_ground(x, y, z)
    timings = {{}}
else:
    res = lsq_ground_filter(x, y, z, mode={what!r}.split("+")[0], tile_size=50.0,
                            threshold=0.5, noise=True if "+noise" in {what!r} else None)
    ground = res.ground
    timings = {{k: v for k, v in res.timings.items()}}
measured = probe.result()
if {labels_out!r}:
    np.save({labels_out!r}, ground)
print(json.dumps(dict(n=int(x.size), **measured, timings=timings)))
"""


def run_child(xyz, what, labels_out=""):
    code = _CHILD.format(xyz=xyz, what=what, labels_out=labels_out,
                         bench=str(ROOT / "benchmarks"))
    return run_python(code)


def make_tile(tmp, side, seed, name):
    from geomatics_toolbox.synthetic.lidar import generate_tile
    t = time.perf_counter()
    tile = generate_tile(extent=(side, side), density=10.0, seed=seed)
    gen = time.perf_counter() - t
    xyz = os.path.join(tmp, name)
    np.save(xyz + ".x.npy", tile.x)
    np.save(xyz + ".y.npy", tile.y)
    np.save(xyz + ".z.npy", tile.z)
    truth = tile.classification == 2
    n = len(tile)
    del tile
    print(f"{name}: {n} points ({gen:.1f} s to generate)", flush=True)
    return xyz, truth, n


def speed_section(quick, tmp):
    rows = []
    side10 = 316.23 if quick else 1000.0
    side20 = 447.2 if quick else 1414.2
    xyz, truth, n = make_tile(tmp, side10, 7, "tile10")
    for what in ("faithful", "faithful+noise", "improved"):
        lab = os.path.join(tmp, f"{what}.npy")
        r = run_child(xyz, what, lab)
        a = _acc(np.load(lab), truth)
        rows.append(dict(r, what=what, tile="10M" if not quick else "1M", total=a.total,
                         type1=a.type1, type2=a.type2))
        print(f"{what}: {r['n'] / r['wall']:.0f} points/s, peak {r['peak_mb']:.0f} MB, "
              f"total {a.total:.2f} %", flush=True)
    for f in ("x", "y", "z"):
        os.remove(f"{xyz}.{f}.npy")
    xyz, truth, n = make_tile(tmp, side20, 8, "tile20")
    r = run_child(xyz, "faithful")
    rows.append(dict(r, what="faithful", tile="20M" if not quick else "2M"))
    print(f"20M faithful: peak {r['peak_mb']:.0f} MB, {r['n'] / r['wall']:.0f} points/s",
          flush=True)
    for f in ("x", "y", "z"):
        os.remove(f"{xyz}.{f}.npy")
    # side by side with CSF on a 1 M point tile (CSF is far slower)
    xyz, truth, n = make_tile(tmp, 316.23, 9, "tile1")
    side = []
    for what in ("faithful", "improved", "csf"):
        lab = os.path.join(tmp, f"s_{what}.npy")
        r = run_child(xyz, what, lab)
        a = _acc(np.load(lab), truth)
        side.append(dict(r, what=what, total=a.total, type1=a.type1, type2=a.type2,
                         kappa=a.kappa))
        print(f"1M {what}: {r['wall']:.1f} s, total {a.total:.2f} %", flush=True)
    return rows, side


# ----------------------------------------------------------------------------- report
def f2(v):
    return "–" if v is None or not np.isfinite(v) else f"{v:.2f}"


def write_md(isprs, isprs_msg, speed, side, quick):
    now = datetime.datetime.now(datetime.timezone.utc).strftime("%Y-%m-%d %H:%M UTC")
    L = ["# Least-squares polynomial (LSQ) ground filter — benchmark", "",
         f"Generated by `benchmarks/bench_lsq.py{' --quick' if quick else ''}` on {now}; "
         "machine with 2 cores shared with other jobs (timings are noisy; compare within "
         "this file). Errors in %, after Sithole & Vosselman (2004): Type I = ground "
         "rejected, Type II = objects accepted, total, Cohen's kappa.", ""]
    if isprs is None:
        L += [f"**{isprs_msg}**", ""]
    else:
        names = list(PAPER)
        L += ["## ISPRS samples — faithful mode (the paper)", "",
              "Order 2, the paper's tile sizes (samp31/samp12 100 m, samp11/samp54 50 m), "
              "5 iterations at most (the paper's tables), re-weighted one-sided rejection. "
              "*pre-step*: the paper's optional gross-outlier removal (our shared "
              "low-outlier filter, class 7). Best T per sample in bold.", "",
              "| sample | tile | paper total | T | with pre-step | without | iterated to "
              "convergence | cumulative rejection |", "|---|---|---|---|---|---|---|---|"]
        for name in names:
            rows = isprs["faithful"][name]
            best = min((0.5, 0.75, 1.0), key=lambda T: rows[("noise", T)]["total"])
            for T in (0.5, 0.75, 1.0):
                v = f2(rows[("noise", T)]["total"])
                v = f"**{v}**" if T == best else v
                L.append(f"| {name} | {PAPER[name][0]} m | {PAPER[name][1]} | {T} | {v} | "
                         f"{f2(rows[('plain', T)]['total'])} | "
                         f"{f2(rows[('converged', T)]['total'])} | "
                         f"{f2(rows[('cumulative', T)]['total'])} |")
        bests = {n: min(isprs["faithful"][n][("noise", T)]["total"] for T in (0.5, .75, 1.))
                 for n in names}
        L += ["", "Acceptance (issue 3): best T within 1.5 points of the paper "
              "(samp11: ≤ 22.1): " + ", ".join(
                  f"{n} {bests[n]:.2f} vs {PAPER[n][1]} "
                  f"({'met' if (bests[n] <= 22.1 if n == 'samp11' else abs(bests[n] - PAPER[n][1]) <= 1.5) else 'NOT met'})"  # noqa: E501
                  for n in names) + f"; mean {np.mean(list(bests.values())):.2f} "
              "(paper 8.90).", "",
              "Iterating one-sided rejection to convergence keeps lowering the surface "
              "where a quadratic cannot follow the terrain (samp11, samp12), hence the "
              "paper's 5-iteration cap as the default.", ""]
        imp = isprs["improved"]
        L += ["## ISPRS samples — improved mode (ours), ONE parameter set", "",
              "Defaults: tile 50 m, T 0.5 m, levels 100/50/25/12.5 m fitted on windows "
              "grown by 25 % per side and started from the previous level's ground, "
              "threshold T + min(2.5·|∇ẑ|, 1 m), low-outlier pre-filter, 5 iterations. "
              "Chosen on these same four samples (there is no held-out data here), so "
              "read the numbers as a fit, not a prediction.", "",
              "| sample | Type I | Type II | total | kappa | paper total | CSF default "
              "(here) | CSF best of grid (here) | CSF published (Zhang 2016) | points/s |",
              "|---|---|---|---|---|---|---|---|---|---|"]
        grid = isprs["csf_grid"]
        for name in names:
            r = imp[name]
            c = isprs["csf"][name]
            bk = min(range(len(grid)), key=lambda k: c[k]["total"])
            L.append(f"| {name} | {f2(r['type1'])} | {f2(r['type2'])} | **{f2(r['total'])}**"
                     f" | {f2(r['kappa'])} | {PAPER[name][1]} | {f2(c['default']['total'])} "
                     f"| {f2(c[bk]['total'])} | {CSF_PUBLISHED[name]} | {r['pps']:.0f} |")
        mean_imp = np.mean([imp[n]["total"] for n in names])
        csf_def = np.mean([isprs["csf"][n]["default"]["total"] for n in names])
        csf_best = np.mean([min(isprs["csf"][n][k]["total"] for k in range(len(grid)))
                            for n in names])
        common = min(range(len(grid)),
                     key=lambda k: np.mean([isprs["csf"][n][k]["total"] for n in names]))
        csf_common = np.mean([isprs["csf"][n][common]["total"] for n in names])
        L += [f"| mean | | | **{mean_imp:.2f}** | | 8.90 | {csf_def:.2f} | {csf_best:.2f} "
              f"| 4.94 | |", "",
              f"Acceptance: mean total {mean_imp:.2f} % (≤ 5.0: "
              f"{'met' if mean_imp <= 5.0 else 'NOT met'}), samp11 {imp['samp11']['total']:.2f}"
              f" % (≤ 14: {'met' if imp['samp11']['total'] <= 14 else 'NOT met'}).", "",
              f"CSF grid (per sample best): cloth resolution {{0.5, 1, 2}} m × rigidness "
              f"{{1, 2, 3}}{' × slope smoothing on/off' if len(grid) > 9 else ''}; "
              "defaults = the package's (resolution 1 m, rigidness 3, slope smoothing on, "
              f"class threshold 0.5 m). Best single CSF setting for all four samples: "
              f"{grid[common]} → mean {csf_common:.2f} %.", "",
              "### Improved mode: each idea measured (mean total over the four samples)", "",
              "| variant (everything else at the defaults) | samp31 | samp54 | samp12 | "
              "samp11 | mean |", "|---|---|---|---|---|---|"]
        for label, vals in isprs["ablation"].items():
            L.append(f"| {label} | " + " | ".join(f2(vals[n]) for n in names)
                     + f" | {np.mean(list(vals.values())):.2f} |")
        L += ["", "Also tried during development and dropped (measured worse on the mean "
              "or on samp11): a per-tile threshold from the spread of the residuals below "
              "the surface; seeding each level with a stricter threshold than the one used "
              "to classify; clamping a finer surface to at most 0.5–1 m above the coarser "
              "one (samp11 > 30 %); the slope term taken from the coarser level; the "
              "finest (6.25 m) level only on steep terrain.", ""]
    if speed:
        L += ["## Throughput and memory (synthetic tile, `core.synthetic`)", "",
              "Tile 50 m, T 0.5 m, one thread, fresh subprocess per run; *faithful+noise* "
              "adds the low-outlier pre-filter (the Processing algorithm's default). "
              "Peak = VmHWM "
              "reset before the filter (includes the baseline: interpreter, libraries, "
              "loaded x/y/z). Error against the generator's labels (ground = class 2).", "",
              "| run | points | wall (s) | CPU (s) | points/s | baseline (MB) | peak (MB) "
              "| total | Type I | Type II |", "|---|---|---|---|---|---|---|---|---|---|"]
        for r in speed:
            L.append(f"| {r['what']} ({r['tile']}) | {r['n']} | {r['wall']:.2f} | "
                     f"{r['cpu']:.2f} | {r['n'] / r['wall']:.0f} | {r['base_mb']:.0f} | "
                     f"{r['peak_mb']:.0f} | {f2(r.get('total'))} | {f2(r.get('type1'))} | "
                     f"{f2(r.get('type2'))} |")
        f10 = next(r for r in speed if r["what"] == "faithful")
        f20 = speed[-1]
        L += ["", f"Targets: faithful ≥ 1 M points/s on the {f10['tile']} tile: "
              f"{f10['n'] / f10['wall'] / 1e6:.2f} M/s "
              f"({'met' if f10['n'] / f10['wall'] >= 1e6 else 'NOT met'}); peak ≤ 3 GB at "
              f"{f20['tile']} points: {f20['peak_mb'] / 1024:.2f} GB "
              f"({'met' if f20['peak_mb'] <= 3072 else 'NOT met'}).", ""]
        stages = f10.get("timings", {})
        if stages:
            L += ["Faithful stages (s): " + ", ".join(
                f"{k} {v:.2f}" for k, v in stages.items() if k != "points_per_second"), ""]
    if side:
        L += ["## Side by side with CSF on a 1 M point synthetic tile", "",
              "| filter | wall (s) | points/s | peak (MB) | total | Type I | Type II | kappa |",
              "|---|---|---|---|---|---|---|---|"]
        for r in side:
            L.append(f"| {r['what']} | {r['wall']:.2f} | {r['n'] / r['wall']:.0f} | "
                     f"{r['peak_mb']:.0f} | {f2(r['total'])} | {f2(r['type1'])} | "
                     f"{f2(r['type2'])} | {f2(r['kappa'])} |")
        L += ["", "CSF with the package defaults. The synthetic tile has a 35° forested "
              "hillside and a 5 m cliff, where fixed-threshold LSQ loses ground.", ""]
    RESULTS.parent.mkdir(parents=True, exist_ok=True)
    RESULTS.write_text("\n".join(L) + "\n", encoding="utf-8")
    print(f"wrote {RESULTS}")


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="smaller tiles and CSF grid")
    ap.add_argument("--no-speed", action="store_true", help="ISPRS rows only")
    args = ap.parse_args(argv)
    isprs, msg = isprs_section(args.quick)
    if msg:
        print(msg, flush=True)
    speed = side = None
    if not args.no_speed:
        with tempfile.TemporaryDirectory() as tmp:
            speed, side = speed_section(args.quick, tmp)
    write_md(isprs, msg, speed, side, args.quick)


if __name__ == "__main__":
    main()

"""Benchmark of every ground filter of ours against SMRF and CSF, same script, same data.

Run:  .venv/bin/python benchmarks/bench_ground.py [--quick] [--no-speed]

Writes ``benchmarks/results/ground.md``:

1. ISPRS samples (``../shared/data/isprs`` or ``$GEOMATICS_ISPRS_DIR``; skipped with a
   message when absent): Type I, Type II, total error and kappa (Sithole & Vosselman
   2004; class 7 counts as non-ground) of LSQ faithful / improved, slope exact /
   adaptive, PTD, the recommended filter, SMRF (pysmrf 1.0.2 with PDAL's defaults:
   cell 1 m, window 18 m, slope 0.15, threshold 0.5 m, scalar 1.25) and CSF
   (cloth-simulation-filter defaults), each core function at its defaults on every
   point.
2. Leave-one-sample-out of the recommended defaults over GRID (detrending x continuity
   growing x slope scaler, 112 sets): each fold picks the set with the lowest mean
   total on the 7 other samples and is scored on the held-out one.
3. Throughput and peak memory on one core on a synthetic tile (10 M points at 20
   pts/m², ``synthetic.lidar.generate_tile``; 1 M with ``--quick``): every run in a
   fresh subprocess with OMP/BLAS threads = 1 (``_probe.run_python``), peak = VmHWM
   after a reset, so it includes the resident baseline (coordinates, Python, numpy).
   PTD runs on a 1 M point window of the tile (one Qhull rebuild per iteration, about
   100 iterations, make the full tile take too long for a benchmark run); the table
   says so.

``--ptd`` re-measures only PTD (its ISPRS rows, its rows on the real files scored by
``_ground_real``, its leave-one-sample-out over PTD_GRID on those 12 files, and its
speed row) and merges them into the existing ``ground.md``, leaving every other row
as it was and noting when. ``--stress`` merges the section of the 4 real files thinned
to 2 / 1 / 0.5 pts/m² with 3 seeds, every filter beside the oracle (the vendor ground of
the same subset; ``_ground_stress.py``). ``--transforms`` merges stress round 2: closed
canopy, a dense crop, offsets and a rotation, units and no input classes through the
file path (``_ground_transforms.py``). ``--phases`` merges the recommended filter on the
ISPRS samples with the grid's corner moved by sub-cell and whole-cell shifts
(``_ground_phases.py``).
"""
from __future__ import annotations

import argparse
import datetime
import itertools
import os
import platform
import sys
import tempfile
import time
from pathlib import Path

import numpy as np
from _probe import run_python

ROOT = Path(__file__).resolve().parents[1]
ISPRS = Path(os.environ.get("GEOMATICS_ISPRS_DIR", ROOT.parent / "shared" / "data" / "isprs"))
if not (ISPRS / "samp11.laz").exists() and Path("/work/shared/data/isprs/samp11.laz").exists():
    ISPRS = Path("/work/shared/data/isprs")
RESULTS = ROOT / "benchmarks" / "results" / "ground.md"
SAMPLES = ["samp11", "samp12", "samp22", "samp31", "samp41", "samp53", "samp54", "samp61"]
FILTERS = ["lsq_faithful", "lsq_improved", "slope_exact", "slope_adaptive", "ptd",
           "recommended", "smrf", "csf"]
SPEED_FILTERS = ["recommended", "smrf", "csf", "lsq_improved", "lsq_faithful", "slope_exact",
                 "slope_adaptive", "ptd"]
#: Leave-one-sample-out grid of the recommended filter: every combination of one choice
#: per group (each choice a dict of RecommendedOptions fields); the shipped defaults are
#: one of the combinations.
GRID = dict(
    trend=[dict(trend_window=0.0)] + [dict(trend_window=w, trend_smooth=s)
                                      for w in (27.0, 36.0, 54.0) for s in (27.0, 45.0)],
    grow=[dict(grow=False), dict(grow_tol=0.1, grow_rms=0.5), dict(grow_tol=0.2, grow_rms=0.5),
          dict(grow_tol=0.1, grow_rms=0.7)],
    scaler=[dict(scaler=v) for v in (0.8, 0.9, 1.0, 1.1)])


def grid_combos():
    """Every combination of GRID as one dict of RecommendedOptions fields."""
    return [{k: v for part in parts for k, v in part.items()}
            for parts in itertools.product(*GRID.values())]


def ground_mask(what, x, y, z):
    """Ground mask of filter ``what`` at its defaults (every point)."""
    from geomatics_toolbox.core.lidar import lsq, ptd, recommended, slope
    if what.startswith("lsq_"):
        return lsq.lsq_ground_filter(x, y, z, mode=what[4:]).classification == 2
    if what.startswith("slope_"):
        return slope.slope_filter(x, y, z, mode=what[6:]).ground
    if what == "ptd":
        return ptd.classify(x, y, z) == 2
    if what == "recommended":
        return recommended.classify(x, y, z) == 2
    if what == "smrf":
        import pysmrf
        r = pysmrf.classify(x, y, z, cellsize=1.0, windows=18, slope_threshold=0.15,
                            elevation_threshold=0.5, elevation_scaler=1.25, workers=1)
        return np.asarray(r.is_ground, bool)
    if what == "csf":
        from bench_lsq import csf_ground
        return csf_ground(x, y, z)
    raise ValueError(what)


def load(name):
    import laspy
    las = laspy.read(str(ISPRS / f"{name}.laz"))
    x, y, z = (np.asarray(v, float) for v in (las.x, las.y, las.z))
    return x, y, z, np.asarray(las.classification) == 2


def isprs_section():
    from geomatics_toolbox.core.lidar.accuracy import assess
    if not (ISPRS / "samp11.laz").exists():
        return None, f"ISPRS samples not found in {ISPRS}; ISPRS rows skipped."
    rows = {}
    for s in SAMPLES:
        x, y, z, ref = load(s)
        rows[s] = {}
        for what in FILTERS:
            t = time.perf_counter()
            acc = assess(ground_mask(what, x, y, z), ref)
            rows[s][what] = dict(acc.as_dict(), seconds=time.perf_counter() - t)
        print(s, {k: round(v["total"], 2) for k, v in rows[s].items()}, flush=True)
    return rows, ""


def loso_section():
    """Leave-one-sample-out over GRID (port of the research eval_isprs.loso)."""
    from geomatics_toolbox.core.lidar import recommended as rec
    from geomatics_toolbox.core.lidar.accuracy import assess
    combos = grid_combos()
    data = {s: load(s) for s in SAMPLES}
    tot = np.empty((len(combos), len(SAMPLES)))
    for i, kw in enumerate(combos):
        opt = rec.RecommendedOptions(**kw)
        for j, s in enumerate(SAMPLES):
            x, y, z, ref = data[s]
            tot[i, j] = assess(rec.classify(x, y, z, options=opt) == 2, ref).total
    folds = []
    for j, s in enumerate(SAMPLES):
        others = np.delete(tot, j, axis=1).mean(axis=1)
        best = int(np.argmin(others))
        folds.append((s, combos[best], float(others[best]), float(tot[best, j])))
    default = [rec.RecommendedOptions(**kw) for kw in combos].index(rec.RecommendedOptions())
    return combos, folds, tot[default]


_CHILD = r"""
import json, sys
sys.path.insert(0, {bench!r})
import numpy as np
from _probe import Probe
x = np.load({xyz!r} + ".x.npy"); y = np.load({xyz!r} + ".y.npy"); z = np.load({xyz!r} + ".z.npy")
sel = slice(None) if {window} is None else (x < x.min() + {window}) & (y < y.min() + {window})
x, y, z = np.ascontiguousarray(x[sel]), np.ascontiguousarray(y[sel]), np.ascontiguousarray(z[sel])
from bench_ground import ground_mask
p = Probe(); g = ground_mask({what!r}, x, y, z); r = p.result()
truth = np.load({xyz!r} + ".t.npy")[sel]
from geomatics_toolbox.core.lidar.accuracy import assess
a = assess(g, truth)
r.update(n=int(x.size), type1=a.type1, type2=a.type2, total=a.total, kappa=a.kappa)
print(json.dumps(r))
"""


def _kept_rows(old, only):
    """Rows of the existing speed table for filters not re-timed (marked as such)."""
    if "## Throughput" not in old:
        return []
    rows = [ln for ln in old[old.index("## Throughput"):].splitlines()
            if ln.startswith("| ") and not ln.startswith(("| filter", "|---"))]
    keep = [ln for ln in rows if ln.split("|")[1].split()[0] not in only]
    return [ln.replace(" |", " (previous run) |", 1) if "previous run" not in ln else ln
            for ln in keep]


def speed_section(quick, tmp, on_row=None, only=None):
    from geomatics_toolbox.synthetic.lidar import generate_tile
    n_target = 1_000_000 if quick else 10_000_000
    side = float(np.sqrt(n_target / 20.0))
    tile = generate_tile(extent=(side, side), density=20.0, seed=7)
    xyz = os.path.join(tmp, "tile")
    for k, v in (("x", tile.x), ("y", tile.y), ("z", tile.z),
                 ("t", tile.classification == 2)):
        np.save(f"{xyz}.{k}.npy", v)
    del tile
    rows = []
    for what in only or SPEED_FILTERS:
        window = None if what != "ptd" or quick else float(np.sqrt(1_000_000 / 20.0))
        code = _CHILD.format(bench=str(ROOT / "benchmarks"), xyz=xyz, what=what,
                             window=window)
        try:
            r = run_python(code)
        except RuntimeError as exc:
            r = {"error": str(exc)[-300:]}
        r["what"] = what
        print("speed", r, flush=True)
        rows.append(r)
        if on_row is not None:
            on_row(rows)
    return rows


def _f(v, d=2):
    return "–" if v is None or (isinstance(v, float) and not np.isfinite(v)) else f"{v:.{d}f}"


def write_md(isprs, msg, lo, speed, quick, keep_head=None, kept=()):
    now = datetime.datetime.now().isoformat(timespec="minutes")
    L = ["# Ground filters: ISPRS accuracy, leave-one-sample-out, speed", "",
         f"Generated by `benchmarks/bench_ground.py{' --quick' if quick else ''}` on {now}, "
         f"{platform.node()} ({os.cpu_count()} cores shared with other jobs), Python "
         f"{platform.python_version()}.", "",
         "Errors in percent (Sithole & Vosselman 2004); class 7 counts as non-ground. "
         "Every filter is its core function at its defaults on every point; SMRF = pysmrf "
         "1.0.2 with PDAL's defaults (cell 1 m, window 18 m, slope 0.15, threshold 0.5 m, "
         "scalar 1.25); CSF = cloth-simulation-filter defaults.", ""]
    if isprs is None:
        L += [msg, ""]
    else:
        L += ["## ISPRS samples: total error (%)", "",
              "| sample | " + " | ".join(FILTERS) + " |", "|---" * (len(FILTERS) + 1) + "|"]
        for s in SAMPLES:
            L.append(f"| {s} | " + " | ".join(_f(isprs[s][w]["total"]) for w in FILTERS)
                     + " |")
        L.append("| **mean** | " + " | ".join(
            _f(np.mean([isprs[s][w]["total"] for s in SAMPLES])) for w in FILTERS) + " |")
        wins = sum(isprs[s]["recommended"]["total"] < isprs[s]["smrf"]["total"]
                   for s in SAMPLES)
        L += ["", f"Recommended beats SMRF on {wins} of {len(SAMPLES)} samples.", "",
              "## ISPRS samples: Type I / Type II / kappa (%)", "",
              "| sample | filter | Type I | Type II | total | kappa |", "|---|---|---|---|---|---|"]
        for s in SAMPLES:
            for w in FILTERS:
                a = isprs[s][w]
                L.append(f"| {s} | {w} | {_f(a['type1'])} | {_f(a['type2'])} | "
                         f"{_f(a['total'])} | {_f(a['kappa'], 1)} |")
        L.append("")
    if lo is not None:
        combos, folds, default = lo
        L += ["## Leave-one-sample-out of the recommended defaults", "",
              f"Grid ({len(combos)} sets, one choice per group): {GRID}. Each fold "
              "chooses the set with the lowest "
              "mean total on the other 7 samples and is scored on the held-out sample.", "",
              "| held out | chosen set | mean total, other 7 | held-out total | "
              "shipped defaults on it |", "|---|---|---|---|---|"]
        for (s, kw, other, held), d in zip(folds, default):
            L.append(f"| {s} | {kw} | {other:.2f} | {held:.2f} | {d:.2f} |")
        L += ["", f"**Leave-one-sample-out mean held-out total: "
              f"{np.mean([f[3] for f in folds]):.2f} %** (shipped defaults, in-sample: "
              f"{np.mean(default):.2f} %).", ""]
    if speed:
        n = max(r.get("n", 0) for r in speed)
        L += [f"## Throughput and peak memory, one core, synthetic tile ({n:,} points, "
              f"20 pts/m²){' — QUICK run' if quick else ''}", "",
              "Wall time is inflated by other jobs on the 2-core machine; CPU time is the "
              "process's own. Peak = VmHWM after a reset, including the resident baseline.",
              "", "| filter | points | wall s | CPU s | points/s (CPU) | peak MB | base MB | "
              "bytes/point (peak) | total error % |", "|---|---|---|---|---|---|---|---|---|"]
        for r in speed:
            if "error" in r:
                L.append(f"| {r['what']} | error: {r['error'][-120:]!r} |")
                continue
            label = r["what"] + (" (1 M window)" if r["n"] < 0.5 * n else "")
            L.append(f"| {label} | {r['n']:,} | {r['wall']:.1f} | {r['cpu']:.1f} | "
                     f"{r['n'] / max(r['cpu'], 1e-9):,.0f} | {r['peak_mb']:.0f} | "
                     f"{r['base_mb']:.0f} | {r['peak_mb'] * 2**20 / r['n']:.0f} | "
                     f"{r['total']:.2f} |")
        L += list(kept)
        if kept:
            L += ["", "Rows marked (previous run) were not re-timed in this run "
                  "(`--speed-only --speed-filters`); they come from the table it replaced."]
    RESULTS.parent.mkdir(exist_ok=True)
    text = "\n".join(L) + "\n"
    if keep_head is not None:        # --speed-only: keep the ISPRS and LOSO sections
        cut = text.index("## Throughput") if "## Throughput" in text else len(text)
        text = keep_head + text[cut:]
    RESULTS.write_text(text, encoding="utf-8")
    print(RESULTS.read_text())


#: PTD's leave-one-sample-out grid over the 8 ISPRS samples and the 4 real files (the
#: shipped defaults are one of its sets): each a dict of PtdOptions fields
PTD_GRID = [dict(max_angle=a, max_distance=d) for a in (21.0, 24.0)
            for d in (1.0, 1.2, 1.5)]


def _ptd_real(options=None):
    """PTD on the real files (``_ground_real`` scoring) plus cells > 1 m above the vendor DTM."""
    import _ground_real as gr

    from geomatics_toolbox.core.lidar import ptd
    rows, data = {}, {}
    for name in gr.FILES:
        d = data[name] = gr.load_real(name)
        take = ~np.isin(d["vclass"], (7, 18))
        t = time.process_time()
        g = np.zeros(d["x"].size, bool)
        g[take] = ptd.classify(d["x"][take], d["y"][take], d["z"][take],
                               options=options) == 2
        cpu = time.process_time() - t
        e = gr.idw(d["x"][g], d["y"][g], d["z"][g], d["cx"], d["cy"]) - d["vdtm"]
        rows[name] = dict(gr.score_real(d, g), up=int(np.sum(e > 1.0)), above=float(e.max()),
                          cpu=cpu, n=int(d["x"].size))
        print(name, {k: round(v, 2) for k, v in rows[name].items()}, flush=True)
    return rows, data


def _ptd_loso(real_data):
    """Leave-one-sample-out of PTD's defaults over PTD_GRID, 12 folds (8 ISPRS + 4 real).

    Each fold picks the set with the lowest mean total error (%) on the other 11 files
    (ISPRS: Sithole & Vosselman; real: ``_ground_real.score_real``) and is scored on the
    held-out one.
    """
    import _ground_real as gr

    from geomatics_toolbox.core.lidar import ptd
    from geomatics_toolbox.core.lidar.accuracy import assess
    data = {s: load(s) for s in SAMPLES}
    names = SAMPLES + list(real_data)
    tot = np.empty((len(PTD_GRID), len(names)))
    for i, kw in enumerate(PTD_GRID):
        opt = ptd.PtdOptions(**kw)
        for j, n in enumerate(names):
            if n in data:
                x, y, z, ref = data[n]
                tot[i, j] = assess(ptd.classify(x, y, z, options=opt) == 2, ref).total
            else:
                d = real_data[n]
                take = ~np.isin(d["vclass"], (7, 18))
                g = np.zeros(d["x"].size, bool)
                g[take] = ptd.classify(d["x"][take], d["y"][take], d["z"][take],
                                       options=opt) == 2
                tot[i, j] = gr.score_real(d, g)["total"]
        print(kw, np.round(tot[i], 2), flush=True)
    folds = []
    for j, n in enumerate(names):
        others = np.delete(tot, j, axis=1).mean(axis=1)
        best = int(np.argmin(others))
        folds.append((n, PTD_GRID[best], float(others[best]), float(tot[best, j])))
    default = next(i for i, kw in enumerate(PTD_GRID)
                   if ptd.PtdOptions(**kw) == ptd.PtdOptions())
    return folds, tot[default]


def ptd_real_md(real, loso):
    """Markdown of PTD's real-file rows and its 12-fold leave-one-sample-out."""
    now = datetime.datetime.now().isoformat(timespec="minutes")
    L = ["## PTD on the real files and its leave-one-sample-out", "",
         f"`bench_ground.py --ptd` on {now}, {platform.node()} (2 cores shared with other "
         "jobs; CPU seconds are the process's own). PTD at its core defaults (= the "
         "algorithm's) on the real files, scored as in the real-file section "
         "(`_ground_real`: vendor points, ambiguous ones out; 1 m IDW DTMs inside the "
         "vendor ground's hull); *cells > 1 m up* = DTM cells more than 1 m above the "
         "vendor DTM, *highest* = the highest of them.", "",
         "| file | points | total % | Type I % | Type II % | DTM RMSE m | cells off > 1 m % "
         "| cells > 1 m up | highest above m | CPU s |",
         "|---|---|---|---|---|---|---|---|---|---|"]
    for n, r in real.items():
        L.append(f"| {n} | {r['n']:,} | {r['total']:.2f} | {r['type1']:.2f} | "
                 f"{r['type2']:.2f} | {r['rmse']:.2f} | {r['bad']:.2f} | {r['up']} | "
                 f"{r['above']:.2f} | {r['cpu']:.1f} |")
    L.append("")
    if loso:
        folds, default = loso
        L += [f"Leave-one-sample-out over {len(PTD_GRID)} sets {PTD_GRID}: each fold picks "
              "the set with the lowest mean total error on the other 11 files.", "",
              "| held out | chosen set | mean total, other 11 | held-out total | shipped "
              "defaults on it |", "|---|---|---|---|---|"]
        for (n, kw, other, held), d in zip(folds, default):
            L.append(f"| {n} | {kw} | {other:.2f} | {held:.2f} | {d:.2f} |")
        isprs = [f[3] for f in folds if f[0] in SAMPLES]
        L += ["", f"**PTD leave-one-sample-out: {np.mean([f[3] for f in folds]):.2f} % over "
              f"the 12 files, {np.mean(isprs):.2f} % over the 8 ISPRS folds** (shipped "
              f"defaults in-sample: {np.mean(default):.2f} % / "
              f"{np.mean(default[:len(SAMPLES)]):.2f} %).", ""]
    return "\n".join(L) + "\n"


def _ptd_isprs_rows():
    """PTD's total and Type I / II / kappa rows on the ISPRS samples."""
    from geomatics_toolbox.core.lidar.accuracy import assess
    rows = {}
    for s in SAMPLES:
        x, y, z, ref = load(s)
        rows[s] = assess(ground_mask("ptd", x, y, z), ref).as_dict()
        print(s, round(rows[s]["total"], 2), flush=True)
    return rows


def _ptd_speed_row(r):
    """Markdown row of PTD's speed measurement ``r`` (a ``speed_section`` row)."""
    if "error" in r:
        return f"| ptd | error: {r['error'][-120:]!r} |"
    return ("| ptd" + (" (1 M window)" if r["n"] < 5_000_000 else "")
            + f" | {r['n']:,} | {r['wall']:.1f} | {r['cpu']:.1f} | "
            f"{r['n'] / max(r['cpu'], 1e-9):,.0f} | {r['peak_mb']:.0f} | "
            f"{r['base_mb']:.0f} | {r['peak_mb'] * 2**20 / r['n']:.0f} | {r['total']:.2f} |")


def _insert_speed_row(lines, row):
    """Put ``row`` in the speed table: in place of its ptd row, else after its last row."""
    start = next((i for i, ln in enumerate(lines) if ln.startswith("## Throughput")), None)
    if start is None:
        return lines + ["", row]
    table = [i for i in range(start, len(lines)) if lines[i].startswith("|")]
    table = [i for k, i in enumerate(table) if k == 0 or i == table[k - 1] + 1]
    for i in table:
        if lines[i].startswith("| ptd"):
            return lines[:i] + [row] + lines[i + 1:]
    at = table[-1] + 1 if table else len(lines)
    return lines[:at] + [row] + lines[at:]


def merge_ptd(text, rows, speed, quick):
    """Replace PTD's column, rows and speed row of ``ground.md`` ``text``; add a note."""
    col = FILTERS.index("ptd") + 1
    out = []
    for line in text.splitlines():
        cells = line.split(" | ")
        if rows and cells[0][2:] in rows and len(cells) == len(FILTERS) + 1:
            cells[col] = _f(rows[cells[0][2:]]["total"])
            line = " | ".join(cells)
        elif rows and line.startswith("| **mean** |") and len(cells) == len(FILTERS) + 1:
            cells[col] = _f(np.mean([rows[s]["total"] for s in SAMPLES]))
            line = " | ".join(cells)
        elif rows and cells[0][2:] in rows and cells[1] == "ptd":
            a = rows[cells[0][2:]]
            line = (f"{cells[0]} | ptd | {_f(a['type1'])} | {_f(a['type2'])} | "
                    f"{_f(a['total'])} | {_f(a['kappa'], 1)} |")
        elif line.startswith("PTD speed row:") or line.startswith("PTD rows re-measured"):
            continue
        out.append(line)
    if speed:
        out = _insert_speed_row(out, _ptd_speed_row(speed[0]))
    text = "\n".join(out).rstrip("\n") + "\n"
    now = datetime.datetime.now().isoformat(timespec="minutes")
    what = " and ".join(w for w, on in (("ISPRS rows", rows), ("speed row", speed)) if on)
    text += (f"\nPTD rows re-measured on {now} with `bench_ground.py --ptd"
             f"{' --quick' if quick else ''}` ({what}; {platform.node()}, other rows "
             "from the run above).\n")
    return text


def _ground_extra(args):
    """--real / --density / --loso12 / --stress / --transforms / --phases: one section each."""
    import _ground_real as gr

    def merge(md):                       # re-read: other runs may have merged meanwhile
        text = RESULTS.read_text(encoding="utf-8") if RESULTS.exists() else ""
        RESULTS.write_text(gr.merge_section(text, md), encoding="utf-8")

    if args.real:
        filters = args.real_filters.split(",")
        rows = gr.real_section(filters)
        if rows is None:
            print(f"real files not found in {gr.REAL}; skipped")
        else:
            merge(gr.real_md(rows, filters))
    if args.isprs_recommended and (ISPRS / "samp11.laz").exists():
        from geomatics_toolbox.core.lidar.accuracy import assess
        rows = {s: assess(ground_mask("recommended", *load(s)[:3]), load(s)[3]).as_dict()
                for s in SAMPLES}
        text = RESULTS.read_text(encoding="utf-8")
        RESULTS.write_text(gr.merge_recommended_isprs(text, rows, FILTERS, SAMPLES),
                           encoding="utf-8")
    if args.loso12 and (ISPRS / "samp11.laz").exists():
        combos, folds = gr.loso12_section(load, SAMPLES)
        merge(gr.loso12_md(combos, folds))
    if args.density:
        merge(gr.density_md(gr.density_section(args.density), args.density))
    if args.stress:
        import _ground_stress as gs
        filters = args.stress_filters.split(",")
        rows = gs.stress_section(filters)
        if rows is None:
            print(f"real files not found in {gr.REAL}; stress skipped")
        else:
            merge(gs.stress_md(rows, filters))
    if args.phases and (ISPRS / "samp11.laz").exists():
        import _ground_phases as gp
        merge(gp.phases_md(gp.phases_section(load, SAMPLES), gp.smrf_corner(RESULTS)))
    if args.transforms:
        import _ground_transforms as gt
        rows = gt.transforms_section(args.transforms_filters.split(","))
        if rows is None:
            print(f"real files not found in {gr.REAL}; transforms skipped")
        else:
            merge(gt.transforms_md(rows, args.transforms_filters.split(",")))
    print(RESULTS.read_text(encoding="utf-8"))
    return 0


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="1 M point tile")
    ap.add_argument("--no-speed", action="store_true", help="ISPRS and LOSO only")
    ap.add_argument("--speed-only", action="store_true",
                    help="keep the ISPRS and LOSO sections of the existing table")
    ap.add_argument("--speed-filters", default=",".join(SPEED_FILTERS),
                    help="comma-separated filters to time with --speed-only; the other "
                         "rows of the existing speed table are kept and marked")
    ap.add_argument("--ptd", action="store_true",
                    help="re-measure PTD only (ISPRS rows, real-file rows, its 12-fold "
                         "leave-one-sample-out and speed row) and merge them")
    ap.add_argument("--no-loso", action="store_true",
                    help="with --ptd: skip PTD's leave-one-sample-out grid")
    ap.add_argument("--real", action="store_true",
                    help="score FILTERS on the real files only (merged into ground.md)")
    ap.add_argument("--real-filters", default=",".join(FILTERS),
                    help="comma-separated filters for --real")
    ap.add_argument("--density", type=int, default=0, metavar="N",
                    help="speed/memory of recommended and SMRF at 0.2/1/5/20 pts/m², N "
                         "points each (merged into ground.md)")
    ap.add_argument("--isprs-recommended", action="store_true",
                    help="re-measure the recommended filter's ISPRS rows only (merged)")
    ap.add_argument("--loso12", action="store_true",
                    help="12-fold leave-one-sample-out (ISPRS + real) of the recommended "
                         "defaults (merged into ground.md)")
    ap.add_argument("--stress", action="store_true",
                    help="the 4 real files thinned to 2 / 1 / 0.5 pts/m² (3 seeds): DTM of "
                         "the filters against the vendor's, beside the oracle (merged)")
    ap.add_argument("--stress-filters", default="recommended,ptd,lsq_improved",
                    help="comma-separated filters for --stress")
    ap.add_argument("--transforms", action="store_true",
                    help="the 4 real files transformed (closed canopy, dense crop, offsets "
                         "and rotation, units and no input classes through the file path; "
                         "_ground_transforms.py), merged")
    ap.add_argument("--phases", action="store_true",
                    help="the recommended filter on the ISPRS samples with the grid's corner "
                         "moved by sub-cell and whole-cell shifts (_ground_phases.py), merged")
    ap.add_argument("--transforms-filters", default="recommended,smrf",
                    help="comma-separated filters for --transforms")
    args = ap.parse_args(argv)
    sys.path.insert(0, str(Path(__file__).resolve().parent))
    if (args.real or args.density or args.loso12 or args.isprs_recommended or args.stress
            or args.transforms or args.phases):
        return _ground_extra(args)
    if args.ptd:
        import _ground_real as gr
        rows = _ptd_isprs_rows() if (ISPRS / "samp11.laz").exists() else None
        if rows:
            RESULTS.write_text(merge_ptd(RESULTS.read_text(encoding="utf-8"), rows, None,
                                         args.quick), encoding="utf-8")
        if (gr.REAL / f"{gr.FILES[0]}.laz").exists():
            real, real_data = _ptd_real()
            loso = _ptd_loso(real_data) if rows and not args.no_loso else None
            RESULTS.write_text(gr.merge_section(RESULTS.read_text(encoding="utf-8"),
                                                ptd_real_md(real, loso)), encoding="utf-8")
        else:
            print(f"real files not found in {gr.REAL}; PTD real rows skipped", flush=True)
        speed = None
        if not args.no_speed:
            with tempfile.TemporaryDirectory() as tmp:
                speed = speed_section(args.quick, tmp, only=["ptd"])
        RESULTS.write_text(merge_ptd(RESULTS.read_text(encoding="utf-8"), rows, speed,
                                     args.quick), encoding="utf-8")
        print(RESULTS.read_text(encoding="utf-8"))
        return 0
    if args.speed_only:
        old = RESULTS.read_text(encoding="utf-8")
        head = old[:old.index("## Throughput")] if "## Throughput" in old else old
        only = args.speed_filters.split(",")
        kept = _kept_rows(old, only)
        with tempfile.TemporaryDirectory() as tmp:
            speed_section(args.quick, tmp, only=only, on_row=lambda rows: write_md(
                None, "", None, rows, args.quick, keep_head=head, kept=kept))
        return 0
    isprs, msg = isprs_section()
    lo = loso_section() if isprs is not None else None
    speed = None
    write_md(isprs, msg, lo, speed, args.quick)       # ISPRS and LOSO first
    if not args.no_speed:
        with tempfile.TemporaryDirectory() as tmp:
            speed = speed_section(args.quick, tmp)
    write_md(isprs, msg, lo, speed, args.quick)
    return 0


if __name__ == "__main__":
    sys.exit(main())

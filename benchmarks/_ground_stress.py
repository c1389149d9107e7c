"""Stress section of bench_ground.py: the 4 real files randomly thinned (``--stress``).

Held-out files come at other densities (0.9-66 pts/m²) than the 4 shared ones, so each
shared file is thinned at random to 2, 1 and 0.5 pts/m² with 3 fixed seeds (points of
vendor classes 7 and 18 left out, as in :func:`._ground_real.ground_real`) and every
filter is scored like the real files (``_ground_real.score_real``'s DTM part): the 1 m
inverse-distance DTM of its ground points against the same DTM of the vendor ground of
the FULL file, RMSE (m) and share of cells off by more than 1 m (%). The oracle is the
perfect classifier of the same thinned subset (its vendor ground points): what is left
of its error is the price of the density itself, the rest is the filter's.
"""
from __future__ import annotations

import os
import time

import _ground_real as gr
import numpy as np

#: Target densities (pts/m² over the bounding box) and seeds of the random thinning.
DENSITIES = (2.0, 1.0, 0.5)
SEEDS = (1, 2, 3)
FILTERS = ("recommended", "ptd", "lsq_improved")


def thinned(d, target, seed):
    """Mask of the points kept when thinning ``d`` to ``target`` pts/m² (None = all)."""
    keep = ~np.isin(d["vclass"], (7, 18))
    if target is None:
        return keep
    dens = keep.sum() / (np.ptp(d["x"]) * np.ptp(d["y"]))
    return keep & (np.random.default_rng(seed).random(keep.size) < target / dens)


def _ground(what, x, y, z, vclass):
    """Ground mask of ``what`` ("oracle" = the vendor ground) on a thinned cloud."""
    if what == "oracle":
        return vclass == 2
    if what == "recommended":                     # the algorithm object users run
        from geomatics_toolbox.core.lidar.recommended import recommended_filter
        return recommended_filter().classify(
            x, y, z, classification=np.zeros(x.size, np.uint8)).classes == 2
    from bench_ground import ground_mask
    return ground_mask(what, x, y, z)


def dtm_error(d, x, y, z, g):
    """(RMSE m, cells off by more than 1 m %) of the IDW DTM of the ground ``g``."""
    if g.sum() < 3:
        return float("nan"), 100.0
    e = gr.idw(x[g], y[g], z[g], d["cx"], d["cy"]) - d["vdtm"]
    return float(np.sqrt(np.mean(e * e))), float(100.0 * np.mean(np.abs(e) > 1.0))


def stress_section(filters=FILTERS, files=None):
    """Rows (dicts) per file, density, seed and filter (oracle first); None without data."""
    if not (gr.REAL / f"{gr.FILES[0]}.laz").exists():
        return None
    rows = []
    for name in files or gr.FILES:
        d = gr.load_real(name)
        full = thinned(d, None, 0)
        dens = full.sum() / (np.ptp(d["x"]) * np.ptp(d["y"]))
        for target in DENSITIES:
            if target >= dens:
                continue
            for seed in SEEDS:
                sel = thinned(d, target, seed)
                x, y, z, vc = d["x"][sel], d["y"][sel], d["z"][sel], d["vclass"][sel]
                for what in ("oracle",) + tuple(filters):
                    t = time.process_time()
                    g = _ground(what, x, y, z, vc)
                    cpu = time.process_time() - t
                    rmse, bad = dtm_error(d, x, y, z, g)
                    rows.append(dict(file=name, density=target, seed=seed, filter=what,
                                     n=int(x.size), rmse=rmse, bad=bad, cpu=cpu))
                    print("stress", rows[-1], flush=True)
    return rows


def run_stamp():
    """(short commit of the worktree, local time to the minute) of a run."""
    import datetime
    import subprocess
    try:
        head = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                              text=True, cwd=gr.ROOT, check=True).stdout.strip()
    except (OSError, subprocess.CalledProcessError):
        head = "?"
    return head, datetime.datetime.now().strftime("%Y-%m-%dT%H:%M")


def stress_md(rows, filters=FILTERS):
    """Markdown of :func:`stress_section`."""
    load = os.getloadavg() if hasattr(os, "getloadavg") else (float("nan"),)
    head, now = run_stamp()
    cols = ("oracle",) + tuple(filters)
    L = ["## Real files thinned: DTM RMSE (m) / cells off > 1 m (%) (`--stress`)", "",
         "Each real file thinned at random to 2 / 1 / 0.5 pts/m² (bounding-box density, "
         "seeds 1 / 2 / 3, vendor classes 7 and 18 left out; `benchmarks/_ground_stress.py`)."
         " DTM scored as above against the vendor ground of the FULL file; oracle = the "
         "vendor ground of the same thinned subset (the error the density alone costs). "
         "Every filter at its defaults. CPU s = the filter's own time summed over the "
         f"table (load average {load[0]:.1f} at the end, 2 shared cores). Run {now} at "
         f"{head} (`bench_ground.py --stress`).", "",
         "| file | pts/m² | seed | points | " + " | ".join(cols) + " |",
         "|---" * (len(cols) + 4) + "|"]
    by = {}
    for r in rows:
        by.setdefault((r["file"], r["density"], r["seed"]), {})[r["filter"]] = r
    for (name, dens, seed), fr in by.items():
        n = next(iter(fr.values()))["n"]
        L.append(f"| {name} | {dens:g} | {seed} | {n:,} | " + " | ".join(
            f"{gr.fmt(fr[w]['rmse'])} / {fr[w]['bad']:.2f}" if w in fr else "–"
            for w in cols) + " |")
    cpu = {w: sum(r["cpu"] for r in rows if r["filter"] == w) for w in cols}
    L.append("| **CPU s** | | | | " + " | ".join(f"{cpu[w]:.1f}" for w in cols) + " |")
    rec = [fr for fr in by.values() if "recommended" in fr]
    fail = [k for k, fr in by.items() if "recommended" in fr and fr["recommended"]["bad"] > 1.0]
    ok_oracle = [k for k in fail if by[k]["oracle"]["bad"] <= 1.0]
    L += ["", f"Recommended: {len(rec) - len(fail)} of {len(rec)} thinned clouds with at most "
          f"1 % of the cells off by more than 1 m; the others ({len(fail)}): "
          + (", ".join(f"{k[0]} {k[1]:g} pts/m² seed {k[2]} "
                       f"({by[k]['recommended']['rmse']:.2f} m / "
                       f"{by[k]['recommended']['bad']:.2f} %)" for k in fail) or "none")
          + f" ({len(ok_oracle)} of them where the oracle stays within 1 %). Walls in "
          "sparse clouds (why fusa thinned failed before the wall rule): DEVELOPERS.md, "
          "\"The recommended ground filter\"."]
    return "\n".join(L) + "\n"

"""Real-data scoring, density table and 12-fold leave-one-sample-out of bench_ground.py.

Used by ``bench_ground.py --real`` / ``--density`` / ``--loso12`` (each merges its own
section into ``benchmarks/results/ground.md`` and leaves every other section as it was).

Real files (``../shared/data/real``, README there): the classes are reset before
filtering (only 7/18 kept, and every filter sees only the other points); feet are
converted to metres; points are scored with Type I/II/total (Sithole & Vosselman 2004)
leaving out vendor classes 0, 7, 9, 11, 12, 18, 65, 66 and the vendor non-ground points
within ±0.3 m of the TIN of the vendor ground points (ambiguous); the DTM is a 1 m
inverse-distance DTM (12 nearest points, power 2, ``gdal_grid invdistnn`` without
radius) of the filter's ground points against the same DTM of the vendor ground
points, on the cell centres inside the convex hull of the vendor ground: RMSE and the
share of cells off by more than 1 m.
"""
from __future__ import annotations

import os
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
REAL = Path(os.environ.get("GEOMATICS_REAL_DIR", ROOT.parent / "shared" / "data" / "real"))
if not (REAL / "lastools_fusa.laz").exists() and Path("/work/shared/data/real").exists():
    REAL = Path("/work/shared/data/real")
FILES = ["lastools_fusa", "pdal_nm_usft", "pdal_ign_lambert93", "lidr_mixedconifer_terrain"]
LANDSCAPE = {"lastools_fusa": "suburban, Australia (4.4 pts/m²)",
             "pdal_nm_usft": "wooded, US feet (6.4 pts/m²)",
             "pdal_ign_lambert93": "open, France, LAS 1.4 (8.3 pts/m²)",
             "lidr_mixedconifer_terrain": "closed conifer forest, Arizona (4.7 pts/m²)"}
EXCLUDED = (0, 7, 9, 11, 12, 18, 65, 66)
US_FOOT = 1200.0 / 3937.0
DENSITIES = (0.2, 1.0, 5.0, 20.0)


def idw(xg, yg, zg, qx, qy, k: int = 12, power: float = 2.0):
    """Inverse-distance heights at ``qx, qy`` from the ``k`` nearest points."""
    from scipy.spatial import cKDTree
    d, j = cKDTree(np.column_stack((xg, yg))).query(np.column_stack((qx, qy)),
                                                     k=min(k, xg.size))
    d = d.reshape(qx.size, -1)
    j = j.reshape(qx.size, -1)
    w = np.maximum(d, 1e-9) ** -power
    return (w * zg[j]).sum(axis=1) / w.sum(axis=1)


def load_real(name):
    """Points (m), vendor classes, the scoring mask, DTM cells and the vendor DTM."""
    import laspy
    from scipy.interpolate import LinearNDInterpolator
    from scipy.spatial import Delaunay
    las = laspy.read(str(REAL / f"{name}.laz"))
    f = US_FOOT if name == "pdal_nm_usft" else 1.0
    x, y, z = (np.asarray(v, float) * f for v in (las.x, las.y, las.z))
    c = np.asarray(las.classification)
    g = c == 2
    dz = z - LinearNDInterpolator(np.column_stack((x[g], y[g])), z[g])(x, y)
    score = ~np.isin(c, EXCLUDED) & ~(~g & (np.abs(dz) <= 0.3))
    x0, y0 = np.floor(x.min()), np.floor(y.min())
    cx, cy = np.meshgrid(x0 + 0.5 + np.arange(int(np.ceil(x.max() - x0))),
                         y0 + 0.5 + np.arange(int(np.ceil(y.max() - y0))))
    cx, cy = cx.ravel(), cy.ravel()
    inside = Delaunay(np.column_stack((x[g], y[g]))).find_simplex(
        np.column_stack((cx, cy))) >= 0
    cx, cy = cx[inside], cy[inside]
    return dict(x=x, y=y, z=z, vclass=c, ref=g, score=score, cx=cx, cy=cy,
                vdtm=idw(x[g], y[g], z[g], cx, cy))


def ground_real(what, d):
    """Ground mask of filter ``what`` on a real file, its classes reset but 7/18."""
    from bench_ground import ground_mask
    keep = np.isin(d["vclass"], (7, 18))
    take = ~keep
    x, y, z = d["x"][take], d["y"][take], d["z"][take]
    if what == "recommended":                     # the algorithm object users run
        from geomatics_toolbox.core.lidar.recommended import recommended_filter
        g = recommended_filter().classify(x, y, z, classification=np.zeros(x.size,
                                                                           np.uint8))
        g = g.classes == 2
    else:
        g = ground_mask(what, x, y, z)
    out = np.zeros(d["x"].size, bool)
    out[take] = g
    return out


def score_real(d, ground):
    """Type I/II/total (%) on the scored points; DTM RMSE (m) and cells off > 1 m (%)."""
    m = d["score"]
    ref, g = d["ref"][m], ground[m]
    a, b = np.sum(ref & g), np.sum(ref & ~g)
    c, e = np.sum(~ref & g), np.sum(~ref & ~g)
    out = dict(type1=100.0 * b / max(a + b, 1), type2=100.0 * c / max(c + e, 1),
               total=100.0 * (b + c) / max(m.sum(), 1))
    if ground.sum() < 3:
        return dict(out, rmse=float("nan"), bad=100.0)
    err = idw(d["x"][ground], d["y"][ground], d["z"][ground], d["cx"], d["cy"]) - d["vdtm"]
    return dict(out, rmse=float(np.sqrt(np.mean(err * err))),
                bad=float(100.0 * np.mean(np.abs(err) > 1.0)))


def real_section(filters):
    """Rows ``{file: {filter: scores}}`` (None when the folder is absent)."""
    if not (REAL / "lastools_fusa.laz").exists():
        return None
    rows = {}
    for name in FILES:
        d = load_real(name)
        rows[name] = {}
        for what in filters:
            t = time.process_time()
            r = score_real(d, ground_real(what, d))
            r["cpu"] = time.process_time() - t
            rows[name][what] = r
            print(name, what, {k: round(v, 3) for k, v in r.items()}, flush=True)
    return rows


def fmt(v) -> str:
    """Two decimals, or a dash for NaN."""
    return "–" if not np.isfinite(v) else f"{v:.2f}"


def real_md(rows, filters):
    """Markdown of :func:`real_section`."""
    L = ["## Real vendor-classified files: DTM RMSE (m) / cells off > 1 m (%)", "",
         "Scored as `../shared/data/real/README.md` says (`benchmarks/_ground_real.py`): "
         "classes reset but 7/18, feet converted to metres; 1 m IDW DTM (12 nearest, "
         "power 2) of each filter's ground against the same DTM of the vendor ground "
         "inside the vendor-ground hull. Every filter at its defaults.", "",
         "| file (landscape) | " + " | ".join(filters) + " |",
         "|---" * (len(filters) + 1) + "|"]
    for name, r in rows.items():
        L.append(f"| {name} ({LANDSCAPE[name]}) | " + " | ".join(
            f"{fmt(r[w]['rmse'])} / {fmt(r[w]['bad'])}" for w in filters) + " |")
    L.append("| **mean** | " + " | ".join(
        f"{np.mean([rows[n][w]['rmse'] for n in rows]):.2f} / "
        f"{np.mean([rows[n][w]['bad'] for n in rows]):.2f}" for w in filters) + " |")
    if "recommended" in filters and "smrf" in filters:
        ok = sum(rows[n]["recommended"]["rmse"] <= rows[n]["smrf"]["rmse"] for n in rows)
        worst = max(rows[n]["recommended"]["bad"] for n in rows)
        L += ["", f"Recommended DTM RMSE ≤ SMRF's on {ok} of {len(rows)} files; its worst "
              f"share of cells off by more than 1 m: {worst:.2f} %."]
    L += ["", "### Points: Type I / Type II / total (%)", "",
          "| file | filter | Type I | Type II | total | CPU s |", "|---|---|---|---|---|---|"]
    for name, r in rows.items():
        for w in filters:
            a = r[w]
            L.append(f"| {name} | {w} | {a['type1']:.2f} | {a['type2']:.2f} | "
                     f"{a['total']:.2f} | {a['cpu']:.1f} |")
    return "\n".join(L) + "\n"


_DENSITY_CHILD = r"""
import json, sys
sys.path.insert(0, {bench!r})
import numpy as np
from geomatics_toolbox.synthetic.lidar import generate_tile
side = ({n} / {dens}) ** 0.5
t = generate_tile(extent=(side, side), density={dens}, seed=7)
x, y, z = (np.ascontiguousarray(a) for a in (t.x, t.y, t.z))
truth = t.classification == 2
del t
from _probe import Probe
from bench_ground import ground_mask
# the generator's freed temporaries back to the system before the probe (glibc keeps
# them resident: 80-100 MB that the baseline would count, more or less depending on
# which packages the environment imported): the peak is Python, numpy, the coordinates
# and the filter, the same in every environment
import gc
from geomatics_toolbox.core.system import release_free_memory
gc.collect(); release_free_memory()
# modules imported before the probe, for every filter alike: the row times the filter,
# not Python's first import of the plugin, scipy.spatial or pysmrf
import geomatics_toolbox.core.lidar.lsq, geomatics_toolbox.core.lidar.ptd
import geomatics_toolbox.core.lidar.recommended, geomatics_toolbox.core.lidar.slope
if {what!r} == "smrf":
    import pysmrf
p = Probe(); g = ground_mask({what!r}, x, y, z); r = p.result()
r.update(n=int(x.size), total=float(100.0 * np.mean(g != truth)))
print(json.dumps(r))
"""


def density_section(n_points: int, filters=("recommended", "smrf")):
    """CPU, points/s and peak bytes/point per density, each run in a fresh process."""
    from _probe import run_python
    rows = []
    for dens in DENSITIES:
        for what in filters:
            code = _DENSITY_CHILD.format(bench=str(ROOT / "benchmarks"), n=n_points,
                                         dens=dens, what=what)
            try:
                r = run_python(code)
            except RuntimeError as exc:
                r = {"error": str(exc)[-200:]}
            r.update(what=what, density=dens)
            print("density", r, flush=True)
            rows.append(r)
    return rows


def density_md(rows, n_points):
    """Markdown of :func:`density_section`."""
    import os as _os
    load = _os.getloadavg() if hasattr(_os, "getloadavg") else ("?",)
    L = [f"## Speed and memory at every density ({n_points:,} synthetic points each, one "
         "core)", "",
         "`synthetic.lidar.generate_tile` at each density; every run in a fresh process "
         "with one thread (`_probe.run_python`), the filters' modules (ours and pysmrf) "
         "imported before the probe; CPU time is the process's own, wall time "
         "was taken on a loaded machine (2 cores shared with other engineers' jobs; load average "
         f"{load[0]:.1f} at the end). Peak = VmHWM after a reset, including the resident "
         "baseline (Python, numpy, the coordinates; the synthetic generator's freed memory "
         "handed back to the system before the probe).", "",
         "| density (pts/m²) | filter | points | CPU s | points/s (CPU) | × SMRF (CPU) | "
         "peak MB | bytes/point | total error % |", "|---|---|---|---|---|---|---|---|---|"]
    cpu = {(r["density"], r["what"]): r.get("cpu") for r in rows}
    for r in rows:
        if "error" in r:
            L.append(f"| {r['density']} | {r['what']} | error: {r['error']!r} |")
            continue
        s = cpu.get((r["density"], "smrf"))
        ratio = f"{s / r['cpu']:.2f}" if s and r["what"] != "smrf" else "–"
        L.append(f"| {r['density']} | {r['what']} | {r['n']:,} | {r['cpu']:.2f} | "
                 f"{r['n'] / max(r['cpu'], 1e-9):,.0f} | {ratio} | {r['peak_mb']:.0f} | "
                 f"{r['peak_mb'] * 2**20 / r['n']:.0f} | {r['total']:.2f} |")
    return "\n".join(L) + "\n"


def merge_section(text: str, md: str) -> str:
    """Replace the ``## `` section whose heading starts like ``md``'s (or append it)."""
    head = md.splitlines()[0]
    key = head.split("(")[0].split(":")[0].strip()
    lines = text.rstrip("\n").splitlines()
    start = next((i for i, ln in enumerate(lines) if ln.startswith(key)), None)
    if start is None:
        return text.rstrip("\n") + "\n\n" + md
    end = next((i for i in range(start + 1, len(lines)) if lines[i].startswith("## ")),
               len(lines))
    return "\n".join(lines[:start] + md.rstrip("\n").splitlines() + [""] + lines[end:]) \
        + "\n"


#: 12-fold leave-one-sample-out grid of the recommended defaults, one choice per group:
#: low-outlier canopy share (1.0 = the plain closing test everywhere) x height tolerance
#: (fixed 0.5 m, or 0.30 / 0.35 x the mean point spacing within 0.25-0.5 m); the shipped
#: defaults are one of the 12 sets (the slope scaler, 1.0, was chosen by the 8-sample
#: leave-one-sample-out of the previous grid and is not re-opened here).
GRID12 = dict(low=[dict(low_share=v) for v in (0.05, 0.08, 0.12, 1.0)],
              threshold=[dict(threshold=0.5), dict(threshold_factor=0.3),
                         dict(threshold_factor=0.35)])


def loso12_section(isprs_load, samples):
    """Every GRID12 set on the 8 ISPRS samples and the 4 real files; 12 folds.

    The score of a fold is its total error (%); each fold picks the set with the lowest
    mean total over the 11 others and is scored on the held-out one (its DTM RMSE too
    for a real file).
    """
    import itertools

    from geomatics_toolbox.core.lidar import recommended as rec
    from geomatics_toolbox.core.lidar.accuracy import assess
    combos = [{k: v for part in parts for k, v in part.items()}
              for parts in itertools.product(*GRID12.values())]
    folds = list(samples) + (FILES if (REAL / "lastools_fusa.laz").exists() else [])
    data = {s: isprs_load(s) for s in samples}
    data.update({f: load_real(f) for f in folds if f in FILES})
    tot = np.empty((len(combos), len(folds)))
    rmse = np.full((len(combos), len(folds)), np.nan)
    for i, kw in enumerate(combos):
        opt = rec.RecommendedOptions(**kw)
        for j, s in enumerate(folds):
            d = data[s]
            if s in FILES:
                keep = np.isin(d["vclass"], (7, 18))
                g = np.zeros(d["x"].size, bool)
                flt = rec.recommended_filter(opt)
                g[~keep] = flt.classify(d["x"][~keep], d["y"][~keep], d["z"][~keep],
                                        classification=np.zeros((~keep).sum(),
                                                                np.uint8)).classes == 2
                r = score_real(d, g)
                tot[i, j], rmse[i, j] = r["total"], r["rmse"]
            else:
                x, y, z, ref = d
                tot[i, j] = assess(rec.classify(x, y, z, options=opt) == 2, ref).total
        print("loso12", kw, np.round(tot[i], 2), flush=True)
    default = next(i for i, kw in enumerate(combos)
                   if rec.RecommendedOptions(**kw) == rec.RecommendedOptions())
    out = []
    for j, s in enumerate(folds):
        others = np.delete(tot, j, axis=1).mean(axis=1)
        best = int(np.argmin(others))
        out.append(dict(fold=s, chosen=combos[best], train=float(others[best]),
                        held=float(tot[best, j]), held_rmse=float(rmse[best, j]),
                        default=float(tot[default, j]),
                        default_rmse=float(rmse[default, j])))
    return combos, out


def loso12_md(combos, folds):
    """Markdown of :func:`loso12_section`."""
    L = ["## Leave-one-sample-out over 12 folds (8 ISPRS samples + 4 real files)", "",
         f"Grid ({len(combos)} sets): {GRID12} (low_share 1.0 = the plain 1-cell closing "
         "test everywhere, trend_window 0 = no detrending). Score of a fold: its total "
         "error (%; real files scored as in the section above). Each fold picks the set "
         "with the lowest mean total over the 11 other folds and is scored on the held-out "
         "one; the shipped defaults (in-sample: chosen on all 12) beside it. DTM RMSE (m) "
         "for the real files.", "",
         "| held out | chosen set | mean total, other 11 | held-out total | held-out DTM "
         "RMSE | defaults: total | defaults: DTM RMSE |", "|---|---|---|---|---|---|---|"]
    for f in folds:
        L.append(f"| {f['fold']} | {f['chosen']} | {f['train']:.2f} | {f['held']:.2f} | "
                 f"{fmt(f['held_rmse'])} | {f['default']:.2f} | {fmt(f['default_rmse'])} |")
    held = [f["held"] for f in folds]
    dflt = [f["default"] for f in folds]
    isprs = [f for f in folds if f["fold"] not in FILES]
    L += ["", f"**12-fold leave-one-sample-out mean held-out total: {np.mean(held):.2f} %** "
          f"(shipped defaults in-sample: {np.mean(dflt):.2f} %); ISPRS folds "
          f"{np.mean([f['held'] for f in isprs]):.2f} % (defaults "
          f"{np.mean([f['default'] for f in isprs]):.2f} %)."]
    return "\n".join(L) + "\n"


def merge_recommended_isprs(text: str, rows: dict, filters, samples) -> str:
    """Replace the recommended column, mean, wins line and Type I/II rows of ``text``.

    ``rows`` maps sample -> accuracy dict (type1, type2, total, kappa) of the
    recommended filter; every other filter's figures are left as they are.
    """
    col = filters.index("recommended") + 1
    smrf = filters.index("smrf") + 1
    out, totals = [], {}
    for line in text.splitlines():
        cells = line.split(" | ")
        name = cells[0][2:] if line.startswith("| ") else ""
        if name in rows and len(cells) == len(filters) + 1:
            cells[col] = f"{rows[name]['total']:.2f}"
            totals[name] = (rows[name]["total"], float(cells[smrf].rstrip(" |")))
            line = " | ".join(cells)
        elif line.startswith("| **mean** |") and len(cells) == len(filters) + 1:
            cells[col] = f"{np.mean([rows[s]['total'] for s in samples]):.2f}"
            line = " | ".join(cells)
        elif name in rows and len(cells) > 2 and cells[1] == "recommended":
            a = rows[name]
            line = (f"| {name} | recommended | {a['type1']:.2f} | {a['type2']:.2f} | "
                    f"{a['total']:.2f} | {a['kappa']:.1f} |")
        elif line.startswith("Recommended beats SMRF on") and totals:
            wins = sum(r < s for r, s in totals.values())
            line = f"Recommended beats SMRF on {wins} of {len(totals)} samples."
        out.append(line)
    return "\n".join(out) + "\n"

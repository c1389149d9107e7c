"""Benchmark: terrain models (IDW, kriging) against their peers, and DTM accuracy.

Rows (each against a peer run in the same script, so machine load cancels out):

1. IDW vs ``gdal_grid -a invdistnn`` (``gdal.Grid``, same power, max_points, radius,
   grid; GDAL_NUM_THREADS=ALL_CPUS) on 1 M synthetic ground points → 1 km² at 1 m
   (1 M cells): time ratio ours/GDAL (target ≤ 1.0) and max |difference| over every
   cell (target ≤ 1e-3 m).
2. Kriging at 10 k, 100 k, 1 M ground points → the same 1 M-cell grid: wall time and
   peak memory (``ru_maxrss`` of a fresh child process per run), against plain PyKrige
   ``OrdinaryKriging(...).execute('grid', ...)`` and PyKrige's moving-window C backend
   (``n_closest_points``), each in a child process limited to 4 GiB of address space and
   a time limit so the benchmark survives their MemoryError. A like-for-like row on a
   10 k-cell grid (where plain PyKrige can run) gives the time ratio and the maximum
   difference.
3. Holdout accuracy on the ISPRS samples: 10 % of the reference ground points are held
   out as check points; DTMs at 1 m from the other 90 % by IDW p = 2, IDW p = 3 (12
   neighbours), ordinary kriging (spherical, 16 neighbours) and ``gdal_grid -a linear``
   (Delaunay, the baseline); RMSE at the check points (bilinear sampling), over the
   check points every method covers.

Usage: ``.venv/bin/python benchmarks/bench_dtm.py [--quick]``; writes
``benchmarks/results/dtm.md``.
"""
from __future__ import annotations

import argparse
import json
import os
import platform
import resource
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
RESULTS = ROOT / "benchmarks" / "results" / "dtm.md"
ISPRS = Path(os.environ.get("GEOMATICS_ISPRS_DIR", ROOT.parent / "shared" / "data" / "isprs"))
MEM_LIMIT = 8 << 30   # for the PyKrige peers (ours is measured against 4 GiB)




from geomatics_toolbox.core.terrain.accuracy import dtm_accuracy  # noqa: E402
from geomatics_toolbox.core.terrain.grid import grid_from_extent  # noqa: E402
from geomatics_toolbox.core.terrain.idw import idw_grid  # noqa: E402
from geomatics_toolbox.core.terrain.kriging import Variogram, fit_variogram, kriging_grid  # noqa: E402


# --------------------------------------------------------------------------- data
def synthetic_ground(n: int, side: float, seed: int = 0, decimals: int = 2):
    """``n`` ground points over a ``side``×``side`` m square of realistic terrain,
    coordinates rounded to ``decimals`` (2 = the usual 1 cm LAS scale)."""
    from geomatics_toolbox.synthetic.lidar import generate_tile
    tile = generate_tile(extent=(side, side), density=min(0.05, 2e4 / side ** 2),
                         seed=seed, relief=20.0, hill_height=25.0)
    x0, y0 = 500_000.0, 4_000_000.0
    rng = np.random.default_rng(seed + 1)
    x = np.round(x0 + rng.uniform(0, side, n), decimals)
    y = np.round(y0 + rng.uniform(0, side, n), decimals)
    z = np.round(tile.terrain(x, y) + rng.normal(0, 0.05, n), decimals)
    return x, y, z, (x0, x0 + side, y0, y0 + side)


def gdal_points(x, y, z):
    """An in-memory OGR dataset of 3-D points (built via CSV, untimed)."""
    from osgeo import gdal
    gdal.UseExceptions()
    tmp = tempfile.NamedTemporaryFile("w", suffix=".csv", delete=False)
    np.savetxt(tmp, np.column_stack([x, y, z]), fmt="%.6f", delimiter=",",
               header="x,y,z", comments="")
    tmp.close()
    src = gdal.OpenEx(tmp.name, gdal.OF_VECTOR, open_options=[
        "X_POSSIBLE_NAMES=x", "Y_POSSIBLE_NAMES=y", "Z_POSSIBLE_NAMES=z"])
    mem = gdal.VectorTranslate("", src, format="Memory", layerName="pts")
    src = None
    os.unlink(tmp.name)
    return mem


def gdal_grid(ds, grid, algorithm):
    from osgeo import gdal
    gdal.SetConfigOption("GDAL_NUM_THREADS", "ALL_CPUS")
    t = time.perf_counter()
    out = gdal.Grid("/vsimem/bench_grid.tif", ds, format="GTiff",
                    outputType=gdal.GDT_Float64, width=grid.ncols, height=grid.nrows,
                    outputBounds=[grid.xmin, grid.ymax, grid.xmax, grid.ymin],
                    algorithm=algorithm)
    arr = out.GetRasterBand(1).ReadAsArray()
    dt = time.perf_counter() - t
    out = None
    gdal.Unlink("/vsimem/bench_grid.tif")
    return np.where(arr == -9999.0, np.nan, arr), dt


# --------------------------------------------------------------------------- 1. IDW
def bench_idw(n, side, cell=1.0, decimals=6):
    x, y, z, ext = synthetic_ground(n, side, decimals=decimals)
    grid = grid_from_extent(ext, cell)
    params = dict(power=2.0, max_points=12, radius=5.0)
    ds = gdal_points(x, y, z)
    ref, t_gdal = gdal_grid(ds, grid, "invdistnn:power=2:max_points=12:radius=5:"
                                      "min_points=0:nodata=-9999")
    t = time.perf_counter()
    ours = idw_grid(x, y, z, grid, fill=True, **params)
    t_ours = time.perf_counter() - t
    same_mask = bool(np.array_equal(np.isnan(ref), np.isnan(ours)))
    diff = float(np.nanmax(np.abs(ref - ours)))
    over = int(np.sum(np.abs(ref - ours) > 1e-3))
    return {"n": n, "cells": grid.size, "t_ours": t_ours, "t_gdal": t_gdal,
            "ratio": t_ours / t_gdal, "max_diff": diff, "same_nodata": same_mask,
            "cells_over_1mm": over, "decimals": decimals}


# --------------------------------------------------------------------------- 2. kriging
def child(kind, npz, out_npy, n_side, cell):
    """Run one kriging job in this (child) process; prints a JSON line."""
    d = np.load(npz)
    x, y, z = d["x"], d["y"], d["z"]
    ext = tuple(d["ext"])
    grid = grid_from_extent(ext, cell)
    vparams = list(d["vparams"])
    t = time.perf_counter()
    status = "ok"
    result = None
    try:
        if kind == "ours":
            v = Variogram("spherical", vparams) if len(vparams) else None
            res = kriging_grid(x, y, z, grid, model="spherical", variogram=v, n_closest=16,
                               fill=True)
            result = res.z
            info = {"params": res.variogram.params}
        else:
            from pykrige.ok import OrdinaryKriging
            kw = {}
            if len(vparams):     # PyKrige's list form wants the full sill: use a dict
                kw["variogram_parameters"] = {"psill": vparams[0], "range": vparams[1],
                                              "nugget": vparams[2]}
            ok = OrdinaryKriging(x, y, z, variogram_model="spherical", **kw)
            if kind == "pykrige":
                zz, _ = ok.execute("grid", grid.x_centers(), grid.y_centers())
            else:
                zz, _ = ok.execute("grid", grid.x_centers(), grid.y_centers(), backend="C",
                                   n_closest_points=16)
            result = np.asarray(zz)
            info = {"params": [float(p) for p in ok.variogram_model_parameters]}
    except MemoryError:
        status, info = "MemoryError", {}
    dt = time.perf_counter() - t
    if result is not None and out_npy:
        np.save(out_npy, np.asarray(result, dtype=np.float64))
    rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    print(json.dumps({"status": status, "time": dt, "peak_bytes": rss, **info}))


def run_child(kind, npz, out_npy, cell, *, limit_mem, timeout):
    def pre():
        if limit_mem:
            resource.setrlimit(resource.RLIMIT_AS, (MEM_LIMIT, MEM_LIMIT))
    env = dict(os.environ, OMP_NUM_THREADS="2", OPENBLAS_NUM_THREADS="2")
    t = time.perf_counter()
    try:
        p = subprocess.run([sys.executable, __file__, "--child", kind, npz, out_npy or "",
                            str(cell)], capture_output=True, text=True, timeout=timeout,
                           preexec_fn=pre, env=env)
    except subprocess.TimeoutExpired:
        return {"status": f"killed after {timeout:.0f} s", "time": time.perf_counter() - t}
    lines = [ln for ln in p.stdout.splitlines() if ln.startswith("{")]
    if p.returncode != 0 or not lines:
        err = (p.stderr.strip().splitlines() or ["?"])[-1][:120]
        return {"status": f"failed: {err}", "time": time.perf_counter() - t}
    return json.loads(lines[-1])


def bench_kriging(sizes, side, cell, tmp, *, like_cells_cell, timeout):
    rows = []
    for n in sizes:
        x, y, z, ext = synthetic_ground(n, side, seed=3)
        fitted = fit_variogram(x, y, z, model="spherical", fit_points=3000, seed=0)
        npz = os.path.join(tmp, f"k{n}.npz")
        np.savez(npz, x=x, y=y, z=z, ext=np.array(ext), vparams=np.array([]))
        npz_v = os.path.join(tmp, f"k{n}v.npz")
        np.savez(npz_v, x=x, y=y, z=z, ext=np.array(ext),
                 vparams=np.array(fitted.params))
        ours = run_child("ours", npz, None, cell, limit_mem=False, timeout=3600)
        plain = run_child("pykrige", npz, None, cell, limit_mem=True, timeout=timeout)
        cmov = run_child("pykrige_c", npz_v, None, cell, limit_mem=True, timeout=timeout)
        rows.append({"n": n, "cells": grid_from_extent(ext, cell).size, "ours": ours,
                     "pykrige": plain, "pykrige_c": cmov})
    # like-for-like: 10 k points onto a coarse grid plain PyKrige can hold in memory
    n = sizes[0]
    x, y, z, ext = synthetic_ground(n, side, seed=3)
    fitted = fit_variogram(x, y, z, model="spherical", fit_points=3000, seed=0)
    npz = os.path.join(tmp, "like.npz")
    np.savez(npz, x=x, y=y, z=z, ext=np.array(ext), vparams=np.array(fitted.params))
    a, b, c = (os.path.join(tmp, f"{k}.npy") for k in ("o", "p", "c"))
    ours = run_child("ours", npz, a, like_cells_cell, limit_mem=False, timeout=3600)
    plain = run_child("pykrige", npz, b, like_cells_cell, limit_mem=True, timeout=timeout)
    cmov = run_child("pykrige_c", npz, c, like_cells_cell, limit_mem=True, timeout=timeout)
    like = {"n": n, "cells": grid_from_extent(ext, like_cells_cell).size, "ours": ours,
            "pykrige": plain, "pykrige_c": cmov}
    zo = np.load(a) if os.path.exists(a) else None
    for key, path in (("pykrige", b), ("pykrige_c", c)):
        if zo is not None and os.path.exists(path):
            dd = np.abs(zo - np.load(path))
            like[key]["max_diff"] = float(np.nanmax(dd))
            like[key]["median_diff"] = float(np.nanmedian(dd))
            like[key]["p99_diff"] = float(np.nanpercentile(dd, 99))
    return rows, like


def bench_kriging_e2e(n, side, tmp, timeout):
    """The user's path: ``qgis_process run geomatics:krigingdtm`` on a LAZ of ``n``
    ground points → DTM + variance GeoTIFFs (+ report); wall time and peak RSS of
    the qgis_process child (``RUSAGE_CHILDREN``; the only child of a fresh runner)."""
    import shutil
    exe = shutil.which("qgis_process.bin")
    if exe is None:
        return {"status": "skipped: qgis_process.bin not found"}
    from geomatics_toolbox.core.io.las import write_las
    x, y, z, _ = synthetic_ground(n, side, seed=5)
    laz = os.path.join(tmp, "ground.laz")
    write_las(laz, x, y, z, dimensions={"classification": np.full(n, 2, np.uint8)},
              crs="EPSG:32632")
    prof = os.path.join(tmp, "qgis")
    os.makedirs(os.path.join(prof, "plugins"), exist_ok=True)
    os.makedirs(os.path.join(prof, "profile"), exist_ok=True)
    link = os.path.join(prof, "plugins", "geomatics_toolbox")
    if not os.path.exists(link):
        os.symlink(ROOT, link)
    import sysconfig
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen",
               QGIS_CUSTOM_CONFIG_PATH=os.path.join(prof, "profile"),
               QGIS_PLUGINPATH=os.path.join(prof, "plugins"),
               PYTHONPATH=sysconfig.get_paths()["purelib"])
    subprocess.run([exe, "plugins", "enable", "geomatics_toolbox"], env=env,
                   capture_output=True)
    cmd = [sys.executable, __file__, "--e2e-child", exe, laz, os.path.join(tmp, "e2e"),
           str(timeout)]
    p = subprocess.run(cmd, env=env, capture_output=True, text=True)
    lines = [ln for ln in p.stdout.splitlines() if ln.startswith("{")]
    if not lines:
        return {"status": f"failed: {(p.stderr.strip().splitlines() or ['?'])[-1][:150]}"}
    out = json.loads(lines[-1])
    out["n"] = n
    return out


def e2e_child(exe, laz, out, timeout):
    """Runs qgis_process once; reports its wall time and peak RSS as JSON."""
    os.makedirs(out, exist_ok=True)
    t = time.perf_counter()
    try:
        p = subprocess.run([exe, "--json", "run", "geomatics:krigingdtm", "--",
                            f"INPUT={laz}", "CELL_SIZE=1", "NEIGHBOURS=16",
                            f"OUTPUT={out}/dtm.tif", f"OUTPUT_VARIANCE={out}/var.tif",
                            f"OUTPUT_HTML={out}/report.html"],
                           capture_output=True, text=True, timeout=float(timeout))
    except subprocess.TimeoutExpired:
        print(json.dumps({"status": f"killed after {timeout} s"}))
        return
    dt = time.perf_counter() - t
    rss = resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss * 1024
    ok = p.returncode == 0 and os.path.exists(f"{out}/dtm.tif") and os.path.exists(
        f"{out}/var.tif")
    res = {}
    if ok:
        text = p.stdout
        res = json.loads(text[text.find("{"):]).get("results", {})
    print(json.dumps({"status": "ok" if ok else f"failed ({p.returncode})", "time": dt,
                      "peak_bytes": rss, "valid_cells": res.get("VALID_CELLS"),
                      "sill": res.get("SILL")}))


# --------------------------------------------------------------------------- 3. ISPRS
def bench_isprs(cell=1.0, seed=0):
    from geomatics_toolbox.core.io.las import read_las
    rows = []
    for name in ("samp11", "samp12", "samp31", "samp54"):
        path = ISPRS / f"{name}.laz"
        if not path.exists():
            continue
        pd = read_las(path, ("classification",))
        g = pd["classification"] == 2
        x, y, z = pd.x[g], pd.y[g], pd.z[g]
        rng = np.random.default_rng(seed)
        hold = np.zeros(x.size, bool)
        hold[rng.choice(x.size, max(1, x.size // 10), replace=False)] = True
        tx, ty, tz = x[~hold], y[~hold], z[~hold]
        cx, cy, cz = x[hold], y[hold], z[hold]
        grid = grid_from_extent((pd.x.min(), pd.x.max(), pd.y.min(), pd.y.max()), cell)
        dtms = {}
        t = time.perf_counter()
        dtms["IDW p=2 (k=12)"] = idw_grid(tx, ty, tz, grid, power=2, max_points=12, fill=True)
        dtms["IDW p=3 (k=12)"] = idw_grid(tx, ty, tz, grid, power=3, max_points=12, fill=True)
        res = kriging_grid(tx, ty, tz, grid, model="spherical", n_closest=16, fill=True,
                           seed=seed)
        dtms["OK spherical (k=16)"] = res.z
        ds = gdal_points(tx, ty, tz)
        dtms["gdal_grid -a linear"], _ = gdal_grid(ds, grid, "linear:nodata=-9999")
        elapsed = time.perf_counter() - t
        samp = {k: dtm_accuracy(v, grid.geotransform, cx, cy, cz, min_points=0)
                for k, v in dtms.items()}
        common = np.ones(cx.size, bool)
        for r in samp.values():
            common &= r.status == 0
        stats = {k: dtm_accuracy(v, grid.geotransform, cx[common], cy[common], cz[common])
                 .stats for k, v in dtms.items()}
        rows.append({"sample": name, "ground": int(x.size), "check": int(common.sum()),
                     "stats": stats, "variogram": res.variogram.as_dict(), "time": elapsed})
    return rows


# --------------------------------------------------------------------------- report
def fmt_t(r):
    if r.get("status") != "ok":
        return r.get("status", "?")
    return f"{r['time']:.1f} s"


def fmt_d(r):
    if "max_diff" not in r:
        return "–"
    return f"{r['median_diff']:.2e} / {r['p99_diff']:.2e} / {r['max_diff']:.2e}"


def fmt_m(r):
    if r.get("status") != "ok" or "peak_bytes" not in r:
        return "–"
    return f"{r['peak_bytes'] / 2 ** 30:.2f} GiB"


def write_md(idw, krig, like, e2e, isprs, args, total):
    L = ["# DTM benchmark (IDW, kriging, holdout accuracy)", "",
         f"Machine: {platform.machine()}, {os.cpu_count()} cores, shared with other jobs "
         "(timings are noisy; ratios against a peer in the same script are the figures to "
         f"read). Mode: {'quick' if args.quick else 'full'}. Total run time {total:.0f} s. "
         "Generated by `benchmarks/bench_dtm.py`.", "",
         "## 1. IDW vs `gdal_grid -a invdistnn`", "",
         "Same power 2, max_points 12, radius 5 m, min_points 0, same grid (cell centres); "
         "synthetic terrain (core/synthetic.py) with 5 cm noise; GDAL 3.6 "
         "`gdal.Grid` with GDAL_NUM_THREADS=ALL_CPUS on an in-memory point layer; ours = "
         "KD-tree build + queries + weights (all cores for the queries).", "",
         "| points | coordinates | cells | ours (s) | gdal_grid (s) | time ratio ours/GDAL "
         "| max \\|diff\\| (m) | cells > 1 mm | same nodata cells |",
         "|---|---|---|---|---|---|---|---|---|"]
    for r in idw:
        q = "1 µm (continuous)" if r["decimals"] >= 6 else "1 cm (LAS scale)"
        L.append(f"| {r['n']:,} | {q} | {r['cells']:,} | {r['t_ours']:.2f} | "
                 f"{r['t_gdal']:.2f} | **{r['ratio']:.3f}** | {r['max_diff']:.2e} | "
                 f"{r['cells_over_1mm']} | {r['same_nodata']} |")
    L += ["", "Targets: ratio ≤ 1.0, max |diff| ≤ 1e-3 m. With coordinates quantised to "
          "1 cm many cell centres have two points at exactly the same distance at the "
          "max_points cut-off; GDAL keeps the one its quadtree returns first, and ours "
          "orders equidistant points the same way (core.idw.gdal_quadtree_rank rebuilds "
          "GDAL's bucket quadtree, computed only when a tie occurs), so even those cells "
          "agree.", "",
          "## 2. Kriging at LiDAR scale", "",
          "Ours: ordinary kriging, spherical variogram fitted with PyKrige's estimator on "
          "pairs around 3000 random points at the local scale (default), 16 nearest "
          "neighbours per cell, batched local solves, "
          "variance raster computed too. Peak memory = `ru_maxrss` of a fresh child "
          "process (includes Python, NumPy, the points and the output grids). PyKrige "
          f"runs in a child limited to {MEM_LIMIT >> 30} GiB of address space (RLIMIT_AS) "
          f"and {args.timeout:.0f} s.", "",
          "| ground points | cells | ours time | ours peak | plain PyKrige "
          "`execute('grid')` | PyKrige C backend, n_closest_points=16 |",
          "|---|---|---|---|---|---|"]
    for r in krig:
        L.append(f"| {r['n']:,} | {r['cells']:,} | {fmt_t(r['ours'])} | {fmt_m(r['ours'])} "
                 f"| {fmt_t(r['pykrige'])} ({fmt_m(r['pykrige'])}) | {fmt_t(r['pykrige_c'])} "
                 f"({fmt_m(r['pykrige_c'])}) |")
    L += ["", f"Like for like on a grid plain PyKrige can hold ({like['n']:,} points → "
          f"{like['cells']:,} cells; PyKrige given our fitted variogram):", "",
          "| method | time | peak memory | \\|diff\\| vs ours (m): median / 99 % / max |",
          "|---|---|---|---|",
          f"| ours (16 neighbours) | {fmt_t(like['ours'])} | {fmt_m(like['ours'])} | – |",
          f"| plain PyKrige (global, all points) | {fmt_t(like['pykrige'])} | "
          f"{fmt_m(like['pykrige'])} | {fmt_d(like['pykrige'])} |",
          f"| PyKrige C, n_closest_points=16 | {fmt_t(like['pykrige_c'])} | "
          f"{fmt_m(like['pykrige_c'])} | {fmt_d(like['pykrige_c'])} |",
          "", "The difference to PyKrige's moving window (same 16 neighbours, same variogram) "
          "is rounding. The difference to global PyKrige is the local-neighbourhood model: "
          "global ordinary kriging estimates one mean for the whole field and pulls cells "
          "with few points in range toward it, local kriging re-estimates the mean in every "
          "neighbourhood (these 10 k points are 10 m apart on terrain with a 35° hillside "
          "and a cliff; the largest differences are at the grid border). Where the "
          "neighbourhood covers all points the two are identical (core test: 2 000 points, "
          "≤ 1e-6 m).", "",
          "End to end, as a user runs it: `qgis_process run geomatics:krigingdtm` on a LAZ "
          f"of {e2e.get('n', 0):,} ground points (LAS read, variogram fit, kriging, DTM "
          "and variance GeoTIFFs, HTML report); peak memory = `ru_maxrss` of the "
          "qgis_process process:", "",
          "| ground points | cells with a value | wall time | peak memory | status |",
          "|---|---|---|---|---|",
          f"| {e2e.get('n', 0):,} | {e2e.get('valid_cells') or 0:,} | "
          f"{e2e.get('time', float('nan')):.1f} s | {fmt_m(e2e)} | {e2e.get('status')} |",
          "", "Target: 1 M points → 1 M cells in ≤ 10 min with ≤ 4 GiB.", "",
          "## 3. Holdout accuracy on the ISPRS samples", ""]
    if not isprs:
        L.append(f"Skipped: ISPRS samples not found in {ISPRS}.")
    else:
        L += ["10 % of the reference ground points (class 2) held out at random (seed 0) "
              "as check points; DTMs at 1 m from the other 90 %, gaps filled; DTM sampled "
              "bilinearly; RMSE over the check points every method covers (gdal linear "
              "leaves the outside of the convex hull empty).", ""]
        methods = list(isprs[0]["stats"])
        L.append("| sample | ground pts | check pts | " + " | ".join(
            f"{m} RMSE (m)" for m in methods) + " |")
        L.append("|---|---|---|" + "---|" * len(methods))
        for r in isprs:
            best = min(r["stats"][m]["rmse"] for m in methods)
            cells = []
            for m in methods:
                v = r["stats"][m]["rmse"]
                cells.append(f"**{v:.3f}**" if v == best else f"{v:.3f}")
            L.append(f"| {r['sample']} | {r['ground']:,} | {r['check']:,} | " +
                     " | ".join(cells) + " |")
        L += ["", "Pearson r at the check points:", "",
              "| sample | " + " | ".join(methods) + " |", "|---|" + "---|" * len(methods)]
        for r in isprs:
            L.append(f"| {r['sample']} | " + " | ".join(
                f"{r['stats'][m]['r']:.5f}" for m in methods) + " |")
        L += ["", "Fitted variograms (spherical): " + "; ".join(
            f"{r['sample']}: nugget {r['variogram']['nugget']:.3f}, sill "
            f"{r['variogram']['sill']:.2f}, range {r['variogram']['range']:.0f} m"
            for r in isprs) + ".", "",
            "Seed paper (Doroud forest, 62 GNSS points): IDW p=2 0.234 m, IDW p=3 0.204 m, "
            "kriging 0.314 m. The ISPRS rows use held-out LiDAR ground points (same "
            "sensor as the training points), not GNSS, so they are not directly comparable."]
    RESULTS.parent.mkdir(parents=True, exist_ok=True)
    RESULTS.write_text("\n".join(L) + "\n", encoding="utf-8")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="smaller sizes")
    ap.add_argument("--child", nargs=4, metavar=("KIND", "NPZ", "OUT", "CELL"),
                    help=argparse.SUPPRESS)
    ap.add_argument("--e2e-child", nargs=4, help=argparse.SUPPRESS)
    ap.add_argument("--timeout", type=float, default=None)
    args = ap.parse_args()
    if args.e2e_child:
        e2e_child(*args.e2e_child)
        return
    if args.child:
        kind, npz, out, cell = args.child
        child(kind, npz, out or None, 0, float(cell))
        return
    t0 = time.perf_counter()
    if args.quick:
        n_idw, side, sizes, like_cell = 100_000, 316.0, [10_000, 100_000], 5.0
        args.timeout = args.timeout or 120.0
    else:
        n_idw, side, sizes, like_cell = 1_000_000, 1000.0, [10_000, 100_000, 1_000_000], 20.0
        args.timeout = args.timeout or 900.0
    print("IDW vs gdal_grid ...", flush=True)
    idw = [bench_idw(n_idw, side, decimals=6), bench_idw(n_idw, side, decimals=2)]
    print(idw, flush=True)
    print("kriging ...", flush=True)
    with tempfile.TemporaryDirectory() as tmp:
        krig, like = bench_kriging(sizes, side, 1.0, tmp, like_cells_cell=like_cell,
                                   timeout=args.timeout)
        print(krig, like, flush=True)
        print("kriging end to end (qgis_process) ...", flush=True)
        e2e = bench_kriging_e2e(sizes[-1], side, tmp, timeout=1800)
        print(e2e, flush=True)
    print("ISPRS holdout ...", flush=True)
    isprs = bench_isprs()
    for r in isprs:
        print(r["sample"], {k: round(v["rmse"], 4) for k, v in r["stats"].items()}, flush=True)
    write_md(idw, krig, like, e2e, isprs, args, time.perf_counter() - t0)
    print(f"wrote {RESULTS}")


if __name__ == "__main__":
    main()

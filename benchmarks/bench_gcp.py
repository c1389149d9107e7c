"""Benchmark / oracle rows for GCP polynomial rectification.

* golden rows: the paper's residual tables through our evaluator;
* fit oracle: our polynomial vs GDAL's GCP polynomial transformer (``gdal.Transformer``,
  ``METHOD=GCP_POLYNOMIAL``, ``MAX_GCP_ORDER=N``) — max difference at the GCPs and on a
  100 × 100 grid over the image, forward and (fitted) inverse;
* warp oracle: our ``core.warp.rectify`` vs the ``gdalwarp -order N`` command line on
  the same GCPs — pixel agreement and times;
* report time for growing GCP counts (all three orders, leave-one-out, drops).

Writes ``benchmarks/results/gcp.md``. ``--quick`` uses a 1/8-scale image instead of
1/2 (image 1 of the paper is ~3700 × 2300 px at GR 0.91 m).
"""
from __future__ import annotations

import argparse
import os
import resource
import shutil
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent
sys.path.insert(0, str(ROOT / "tests"))
import conftest  # noqa: E402,F401  (loads the checkout as geomatics_toolbox)
from osgeo import gdal  # noqa: E402

from geomatics_toolbox.core.io import gcp as gcp_io  # noqa: E402
from geomatics_toolbox.core.rectification import accuracy as gcp_report  # noqa: E402
from geomatics_toolbox.core.rectification import (  # noqa: E402
    assess,
    compare,
    polynomial,
    report,
    transforms,
    warp,
)
from geomatics_toolbox.core.reporting import render_html  # noqa: E402
from geomatics_toolbox.synthetic import gcp as gcp_synthetic  # noqa: E402

gdal.UseExceptions()
EPSG = "EPSG:22780"

IMAGE1 = """1.17 -0.19 -1.53 0.30 -2.78 -3.38 2.62 0.66 0.30 -0.74 -0.94 1.81 2.13 0.16
-0.35 -0.31 0.56 -0.09 2.26 -0.40 -1.15 -0.75 1.14 1.10 1.66 3.56 -2.08 1.14
-0.59 1.09 0.18 -1.67 -0.76 -1.22 -3.47 -0.19 2.48 2.05 -2.91 -2.71 2.05 -0.21"""
IMAGE2 = """-0.6058 7.015413 2.777543 -0.44833 -2.62182 -1.3507 -2.46768 -0.15583 -0.26112
-0.6551 -0.55613 -1.7881 -4.62027 0.847168 -2.27356 -2.27125 -7.36169 -2.51407 1.853832
-4.6648 -4.15917 -2.40171 -3.06987 1.329226 1.06743 -1.98459 7.391539 -0.8632 3.9705
-2.73658 7.896014 6.968264 0.409602 4.025989 -0.05641 4.124772 -4.05932 -2.52847 3.910402
-0.21618 2.835983 0.268075"""


def golden_rows():
    rows = []
    for name, text, gr, ids, paper in (
            ("image 1 (order 2)", IMAGE1, 0.91, None, "2.39 m, 15/21, pt 3 4.38 m C 1.83, "
             "accepted"),
            ("image 2 (order 2)", IMAGE2, 0.46, [str(i) for i in range(2, 23)],
             "4.89 m, pt 17 10.53 m C 2.15, rejected")):
        v = np.array(text.split(), float).reshape(-1, 2)
        s = gcp_report.evaluate_residuals(v[:, 0], v[:, 1], ids=ids, gr=gr,
                                          n_terms_per_axis=6)
        ours = (f"{s.rms_t:.3f} m, {s.n_within}/{s.n}, pt {s.largest_id} "
                f"{s.largest_rms:.2f} m C {s.largest_c:.2f}, {s.verdict}; "
                f"n−N divisor {s.rms_t_qgis:.3f} m")
        rows.append(f"| {name} | {paper} | {ours} |")
    return rows


def gdal_transformer(pix, mp, order, w, h):
    ds = gdal.GetDriverByName("MEM").Create("", w, h, 1)
    ds.SetGCPs([gdal.GCP(float(x), float(y), 0.0, float(c), float(r))
                for (c, r), (x, y) in zip(pix, mp)], "")
    return ds, gdal.Transformer(ds, None, ["METHOD=GCP_POLYNOMIAL",
                                           f"MAX_GCP_ORDER={order}"])


def fit_rows():
    rows = []
    for order in (1, 2, 3):
        pix, mp, _, (w, h) = gcp_synthetic.synthetic_gcps(order, noise=1.0, seed=order)
        t0 = time.perf_counter()
        for _ in range(200):
            m = polynomial.fit_polynomial(pix, mp, order=order)
        t_ours = (time.perf_counter() - t0) / 200
        t0 = time.perf_counter()
        for _ in range(200):
            ds, tr = gdal_transformer(pix, mp, order, w, h)
        t_gdal = (time.perf_counter() - t0) / 200
        gr = m.pixel_size()
        cc, rr = np.meshgrid(np.linspace(0, w, 100), np.linspace(0, h, 100))
        pts = np.column_stack([cc.ravel(), rr.ravel()])
        g_gcp = np.array(tr.TransformPoints(0, pix.tolist())[0])[:, :2]
        g_grid = np.array(tr.TransformPoints(0, pts.tolist())[0])[:, :2]
        g_inv = np.array(tr.TransformPoints(1, mp.tolist())[0])[:, :2]
        gx, gy = m.forward(pts[:, 0], pts[:, 1])
        ic, ir = m.inverse_polynomial(mp[:, 0], mp[:, 1])
        d_grid = max(np.abs(gx - g_grid[:, 0]).max(), np.abs(gy - g_grid[:, 1]).max())
        d_inv = max(np.abs(ic - g_inv[:, 0]).max(), np.abs(ir - g_inv[:, 1]).max())
        # residual difference: ours vs GDAL's prediction minus the given map point
        vx, vy = polynomial.residuals(m, pix, mp)
        dres = max(np.abs(vx - (g_gcp[:, 0] - mp[:, 0])).max(),
                   np.abs(vy - (g_gcp[:, 1] - mp[:, 1])).max())
        rows.append(f"| {order} | {len(pix)} | {m.condition:.1f} | {dres:.2e} m "
                    f"({dres / gr:.1e} GR) | {d_grid:.2e} m ({d_grid / gr:.1e} GR) | "
                    f"{d_inv:.2e} px | {1e3 * t_ours:.3f} | {1e3 * t_gdal:.3f} | "
                    f"{t_ours / t_gdal:.2f} |")
        del ds
    return rows


def warp_rows(scale: float, tmp: Path):
    rows = []
    if shutil.which("gdalwarp") is None:
        return ["| – | gdalwarp not installed: warp oracle skipped | | | | | | |"]
    for order in (1, 2, 3):
        for resampling in ("near", "bilinear"):
            pix, mp, _, _ = gcp_synthetic.synthetic_gcps(order, noise=1.0, seed=order)
            pix = np.round(pix / scale, 4)  # gdal_translate writes 4 decimals in pixels
            mp = np.round(mp, 3)
            w, h = int(pix[:, 0].max() + 40), int(pix[:, 1].max() + 40)
            img = tmp / f"in_{order}.tif"
            if not img.exists():
                gcp_synthetic.write_test_image(img, w, h, bands=3)
            g = gcp_io.make_gcps(None, pix, mp, crs=EPSG)
            out = tmp / f"ours_{order}_{resampling}.tif"
            t0 = time.perf_counter()
            res = warp.rectify(img, g, out, order=order, resampling=resampling)
            t_ours = time.perf_counter() - t0
            vrt = tmp / f"g_{order}.vrt"
            args = ["gdal_translate", "-q", "-of", "VRT", "-a_srs", EPSG]
            for (c, r), (x, y) in zip(pix, mp):
                args += ["-gcp", repr(float(c)), repr(float(r)), repr(float(x)),
                         repr(float(y))]
            subprocess.run(args + [str(img), str(vrt)], check=True)
            ref = tmp / f"ref_{order}_{resampling}.tif"
            t0 = time.perf_counter()
            subprocess.run(["gdalwarp", "-q", "-overwrite", "-order", str(order), "-r",
                            resampling, "-tr", repr(res.resolution), repr(res.resolution),
                            "-co", "TILED=YES", "-co", "COMPRESS=DEFLATE", str(vrt),
                            str(ref)], check=True)
            t_cli = time.perf_counter() - t0
            a = gdal.Open(str(out)).ReadAsArray()
            b = gdal.Open(str(ref)).ReadAsArray()
            same = a.shape == b.shape
            agree = float(np.mean(a == b)) * 100 if same else float("nan")
            maxdiff = int(np.abs(a.astype(int) - b.astype(int)).max()) if same else -1
            rows.append(f"| {order} | {resampling} | {w} × {h} × 3 | "
                        f"{res.width} × {res.height} | {agree:.4f} % | {maxdiff} | "
                        f"{t_ours:.2f} | {t_cli:.2f} | {t_ours / t_cli:.2f} |")
            for p in (out, ref):
                p.unlink()
    return rows


def report_rows():
    rows = []
    rng = np.random.default_rng(0)
    pix0, mp0, _, size0 = gcp_synthetic.synthetic_gcps(2, noise=1.0)  # warm-up (imports)
    gcp_report.evaluate_gcps(gcp_io.make_gcps(None, pix0, mp0, crs=EPSG), order=2,
                             image_size=size0)
    for n in (22, 200):  # every transformation's LOO (TPS: n refits of n points)
        pix = np.column_stack([rng.uniform(0, 4000, n), rng.uniform(0, 3000, n)])
        cx, cy = gcp_synthetic.true_coefficients(3)
        x, y = gcp_synthetic.eval_raw(cx, cy, pix[:, 0], pix[:, 1])
        mp = np.column_stack([x, y]) + rng.normal(0, 1.0, (n, 2))
        mp[: max(1, n // 50)] += 12.0  # 2 % blunders
        g = gcp_io.make_gcps(None, pix, mp, crs=EPSG)
        t0 = time.perf_counter()
        a = assess.assess_gcps(g, kind="polynomial2", gr=0.91, image_size=(4000, 3000))
        html = render_html(report.build_report(a))
        t = time.perf_counter() - t0
        acc = a.acc
        rows.append(f"| {n} | {t:.3f} | {n / t:.0f} | {acc.recommended} | "
                    f"{a.comparison.recommended} | {len(acc.selected.drops)} | "
                    f"{len(html) / 1024:.0f} kB |")
    return rows


#: gdalwarp options equal to what warp.rectify gives GDAL for each transformation
CLI_OPTIONS = {"polynomial1": ["-order", "1"], "polynomial2": ["-order", "2"],
               "polynomial3": ["-order", "3"], "tps": ["-tps"], "projective": ["-tps"],
               "linear": [], "helmert": []}


def _cli_warp(img, g, kind, model, res, tmp):
    """The gdalwarp command line on the very source warp.rectify hands to GDAL."""
    ds, vpath, _ = warp._source(str(img), g, kind, model)
    vrt = tmp / f"src_{kind}.vrt"
    gdal.Translate(str(vrt), ds, format="VRT")
    ds = None
    gdal.Unlink(vpath)
    ref = tmp / f"ref_{kind}.tif"
    t0 = time.perf_counter()
    subprocess.run(["gdalwarp", "-q", "-overwrite", *CLI_OPTIONS[kind], "-r", "near",
                    "-tr", repr(res), repr(res), "-co", "TILED=YES", "-co",
                    "COMPRESS=DEFLATE", str(vrt), str(ref)], check=True)
    return ref, time.perf_counter() - t0


def transform_rows(scale: float, tmp: Path):
    """Every transformation on image 1 pushed through a known order-2 distortion."""
    pix, mp, _, _ = gcp_synthetic.transformed_gcps("polynomial2", noise=0.5, seed=1)
    gr = gcp_synthetic.IMAGE1_GR
    g = gcp_io.make_gcps(None, pix, mp, crs=EPSG)
    cmp_ = compare.compare_transforms(g, gr=gr)
    spix = np.round(pix / scale, 4)
    gs = gcp_io.make_gcps(None, spix, mp, crs=EPSG)
    w, h = int(spix[:, 0].max() + 40), int(spix[:, 1].max() + 40)
    img = tmp / "in_kinds.tif"
    gcp_synthetic.write_test_image(img, w, h, bands=3)
    rows = []
    for kind in transforms.KINDS:
        t0 = time.perf_counter()
        for _ in range(20):
            transforms.fit_transform(kind, pix, mp)
        t_fit = (time.perf_counter() - t0) / 20
        model = transforms.fit_transform(kind, spix, mp)
        out = tmp / f"ours_{kind}.tif"
        t0 = time.perf_counter()
        res = warp.rectify(img, gs, out, kind=kind)
        t_ours = time.perf_counter() - t0
        ref, t_cli = _cli_warp(img, gs, kind, model, res.resolution, tmp)
        a = gdal.Open(str(out)).ReadAsArray()
        b = gdal.Open(str(ref)).ReadAsArray()
        agree = float(np.mean(a == b)) * 100 if a.shape == b.shape else float("nan")
        r = cmp_.results[kind]
        mark = " (recommended)" if kind == cmp_.recommended else ""
        rows.append(f"| {kind}{mark} | {r.fit.rms_t:.3f} | {r.loo.rms_t:.3f} | "
                    f"{1e3 * t_fit:.2f} | {t_ours:.2f} | {t_cli:.2f} | {agree:.4f} % | "
                    f"{' '.join(CLI_OPTIONS[kind]) or '(geotransform)'} |")
        for p in (out, ref):
            p.unlink()
    return rows


def main(argv):
    ap = argparse.ArgumentParser()
    ap.add_argument("--quick", action="store_true")
    args = ap.parse_args(argv)
    scale = 8.0 if args.quick else 2.0
    with tempfile.TemporaryDirectory(prefix="bench_gcp_") as d:
        tmp = Path(d)
        lines = ["# GCP polynomial rectification — oracle and timing rows", "",
                 f"`benchmarks/bench_gcp.py{' --quick' if args.quick else ''}`, GDAL "
                 f"{gdal.__version__}. Timings are noisy (shared 2-core machine); ratios "
                 "compare runs made in the same script.", "",
                 "## Golden numbers (paper's residual tables through our evaluator)", "",
                 "| case | paper | ours |", "|---|---|---|", *golden_rows(), "",
                 "## Fit vs GDAL's GCP polynomial transformer", "",
                 "22 GCPs of image 1 (synthetic pixels, map = known polynomial + N(0, 1 m)). "
                 "Residual difference = max |v_ours − v_GDAL| at the GCPs; grid = 100 × 100 "
                 "points over the image; inverse = fitted map→pixel polynomial at the GCPs. "
                 "Times: one fit (ours, incl. the inverse fit, SVD condition number and "
                 "leverages) vs creating GDAL's transformer.", "",
                 "| order | n | condition | max residual diff | max diff on grid | "
                 "inverse diff | ours (ms) | GDAL (ms) | ratio |",
                 "|---|---|---|---|---|---|---|---|---|", *fit_rows(), "",
                 f"## Warp vs `gdalwarp -order N` (image 1 at 1/{scale:g} scale)", "",
                 "Same GCPs (rounded to what gdal_translate writes into a VRT), same "
                 "resampling and resolution (GR). Agreement = share of identical pixel "
                 "values over all bands.", "",
                 "| order | resampling | input | output | identical pixels | max |Δ| | "
                 "ours (s) | gdalwarp CLI (s) | ratio |",
                 "|---|---|---|---|---|---|---|---|---|", *warp_rows(scale, tmp), "",
                 "## Every transformation: LOO error, fit and warp time vs gdalwarp", "",
                 "The spec's image-1 GCP positions (22) pushed through a known order-2 "
                 "distortion + N(0, 0.5 m) per axis: fit and leave-one-out RMS_T (m) of "
                 "each transformation (the recommendation uses LOO, never the fit: TPS "
                 "fits exactly). Fit = mean of 20 fits on the 22 GCPs. Warp: image 1 at "
                 f"1/{scale:g} scale, nearest neighbour, ours (warp.rectify) vs the gdalwarp "
                 "command line with the same options on the same source (the projective "
                 "homography reaches GDAL as a 33 × 33 GCP grid with -tps, linear/Helmert "
                 "as their exact geotransform).", "",
                 "| transformation | fit RMS_T (m) | LOO RMS_T (m) | fit (ms) | warp ours (s) "
                 "| gdalwarp CLI (s) | identical pixels | gdalwarp options |",
                 "|---|---|---|---|---|---|---|---|", *transform_rows(scale, tmp), "",
                 "## Report time (every transformation + orders 1–3, LOO, drops, HTML)", "",
                 "| GCPs | time (s) | GCPs/s | recommended order | recommended "
                 "transformation | suggested drops | HTML size |",
                 "|---|---|---|---|---|---|---|", *report_rows(), "",
                 f"Peak RSS of the benchmark process: "
                 f"{resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024:.0f} MiB "
                 "(resource.getrusage ru_maxrss; it holds our warps, which run in-process, "
                 "and the arrays read back for the comparison).", ""]
    out = HERE / "results" / "gcp.md"
    out.parent.mkdir(exist_ok=True)
    out.write_text("\n".join(lines), encoding="utf-8")
    print("\n".join(lines))
    return 0


if __name__ == "__main__":
    os.environ.setdefault("PROJ_DATA", "/usr/share/proj")
    sys.exit(main(sys.argv[1:]))

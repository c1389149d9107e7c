"""Stress round 2 of bench_ground.py (``--transforms``): the 4 real files transformed.

Each transformation mimics a held-out landscape or input the 4 shared files do not
cover; every filter is scored like ``--stress`` (``_ground_stress.dtm_error``: the 1 m
IDW DTM of its ground points against the same DTM of the vendor ground of the FULL,
untransformed file, RMSE m / cells off by more than 1 m %, inside the vendor ground
hull), the oracle being the vendor ground of the same transformed subset.

* ``canopy``: closed canopy — vendor ground points under canopy (nDSM > 2 m: the
  highest point of the 3 x 3 one-metre cells around the point, minus the point) are
  kept with probability 5 % / 10 % (seeds 1-3), the other points all kept
  (mixedconifer and nm_usft: 0.1-0.35 ground pts/m² left); and 25 % of them kept with
  the whole cloud then thinned to 1.5 pts/m² (the held-out closed forest: 1.5 pts/m²,
  0.14 ground pts/m²);
* ``units``: through the file path (:func:`core.lidar.pipeline.classify_file`, as
  ``qgis_process`` runs it): each metric file copied in US survey feet with GeoTIFF keys
  saying so (x, y, z / 0.3048006), nm_usft copied in metres; classes compared with the
  native file's, point by point;
* ``classes``: through the file path: every input class set to 1 (so vendor classes,
  water 9 included, cannot help) against the file as delivered;
* ``offset`` / ``rotate``: x + 500 000, y + 5 000 000, z + 2 000 m, and the same after a
  30° rotation of the plane about the tile centre (arrays, the algorithm object users
  run); classes compared with the untransformed run;
* ``dense``: a 120 x 120 m crop of fusa (x 15) and ign (x 11) around their buildings,
  every point repeated with a seeded jitter (±0.2 m in x, y; 2 cm in z): 60-70 pts/m²
  over the same landscape, as the held-out dense city block.
"""
from __future__ import annotations

import functools
import os
import tempfile
import time

import _ground_real as gr
import _ground_stress as gs
import numpy as np

FT = 1200.0 / 3937.0
OFFSET = (500_000.0, 5_000_000.0, 2_000.0)
ANGLE = 30.0
CANOPY_FILES = ("lidr_mixedconifer_terrain", "pdal_nm_usft")
CANOPY_SHARES = (0.05, 0.10)
SEEDS = (1, 2, 3)
DENSE = {"lastools_fusa": 15, "pdal_ign_lambert93": 11}
THIN_CANOPY = (0.25, 1.5)          # under-canopy ground share kept, then pts/m² overall
CROP = 120.0
FILTERS = ("recommended", "smrf")


@functools.cache
def _load(name):
    """:func:`_ground_real.load_real`, each file read once (every section reads them)."""
    return gr.load_real(name)


def under_canopy(x, y, z, ground, cell=1.0, height=2.0):
    """Mask of the ``ground`` points with a point more than ``height`` above them in
    the 3 x 3 cells of ``cell`` around them (the nDSM of the vendor data)."""
    from scipy import ndimage
    i = np.floor((x - x.min()) / cell).astype(np.int64)
    j = np.floor((y - y.min()) / cell).astype(np.int64)
    top = np.full((i.max() + 1, j.max() + 1), -np.inf)
    np.maximum.at(top, (i, j), z)
    top = ndimage.maximum_filter(top, size=3, mode="constant", cval=-np.inf)
    return ground & (top[i, j] - z > height)


def canopy_keep(d, share, seed, thin=None):
    """Points kept: all but the vendor ground under canopy, kept with prob. ``share``;
    then the whole cloud thinned at random to ``thin`` pts/m² (bounding box) if given."""
    keep = gs.thinned(d, None, 0)
    under = under_canopy(d["x"], d["y"], d["z"], d["vclass"] == 2)
    rng = np.random.default_rng(seed)
    keep &= ~(under & (rng.random(keep.size) >= share))
    if thin is not None:
        dens = keep.sum() / (np.ptp(d["x"]) * np.ptp(d["y"]))
        keep &= rng.random(keep.size) < thin / dens
    return keep


def dense_copy(d, factor, seed, crop=CROP):
    """(x, y, z, vclass) of the crop around the buildings, each point ``factor`` times."""
    b = d["vclass"] == 6
    cx, cy = (np.median(d["x"][b]), np.median(d["y"][b])) if b.any() else \
        (np.median(d["x"]), np.median(d["y"]))
    m = gs.thinned(d, None, 0) & (np.abs(d["x"] - cx) <= crop / 2) & \
        (np.abs(d["y"] - cy) <= crop / 2)
    rng = np.random.default_rng(seed)
    x, y, z, c = (np.repeat(d[k][m], factor) for k in ("x", "y", "z", "vclass"))
    x = x + rng.uniform(-0.2, 0.2, x.size)
    y = y + rng.uniform(-0.2, 0.2, y.size)
    z = z + rng.normal(0.0, 0.02, z.size)
    return x, y, z, c, (cx, cy)


def rotated(x, y, angle=ANGLE, about=None):
    """``x, y`` rotated by ``angle`` degrees about ``about`` (the bounding-box centre)."""
    cx, cy = about if about is not None else ((x.min() + x.max()) / 2, (y.min() + y.max()) / 2)
    a = np.radians(angle)
    u, v = x - cx, y - cy
    return cx + u * np.cos(a) - v * np.sin(a), cy + u * np.sin(a) + v * np.cos(a)


def _score(d, x, y, z, g, cells=None):
    if cells is None:
        return gs.dtm_error(d, x, y, z, g)
    sub = dict(d, cx=d["cx"][cells], cy=d["cy"][cells], vdtm=d["vdtm"][cells])
    return gs.dtm_error(sub, x, y, z, g)


def _run(what, x, y, z, vc):
    t = time.process_time()
    g = gs._ground(what, x, y, z, vc)
    return g, time.process_time() - t


def canopy_rows(filters=FILTERS):
    rows = []
    for name in CANOPY_FILES:
        d = _load(name)
        hull = (d["cx"].size)                   # 1 m cells inside the vendor ground hull
        cases = [(s, None, f"{s:.0%}") for s in CANOPY_SHARES] + [
            (THIN_CANOPY[0], THIN_CANOPY[1], f"{THIN_CANOPY[0]:.0%}, {THIN_CANOPY[1]:g} pts/m²")]
        for share, thin, label in cases:
            for seed in SEEDS:
                sel = canopy_keep(d, share, seed, thin)
                x, y, z, vc = (d[k][sel] for k in ("x", "y", "z", "vclass"))
                for what in ("oracle",) + tuple(filters):
                    g, cpu = _run(what, x, y, z, vc)
                    rmse, bad = _score(d, x, y, z, g)
                    rows.append(dict(t="canopy", file=name, case=label, seed=seed,
                                     filter=what, n=int(x.size), rmse=rmse, bad=bad,
                                     cpu=cpu, ground=float((vc == 2).sum() / hull)))
                    print("transforms", rows[-1], flush=True)
    return rows


def dense_rows(filters=FILTERS, seed=1):
    rows = []
    for name, factor in DENSE.items():
        d = _load(name)
        x, y, z, vc, (cx, cy) = dense_copy(d, factor, seed)
        cells = (np.abs(d["cx"] - cx) <= CROP / 2) & (np.abs(d["cy"] - cy) <= CROP / 2)
        dens = x.size / (np.ptp(x) * np.ptp(y))
        for what in ("oracle",) + tuple(filters):
            g, cpu = _run(what, x, y, z, vc)
            rmse, bad = _score(d, x, y, z, g, cells)
            rows.append(dict(t="dense", file=name, case=f"x{factor} {dens:.0f} pts/m²",
                             seed=seed, filter=what, n=int(x.size), rmse=rmse, bad=bad,
                             cpu=cpu))
            print("transforms", rows[-1], flush=True)
    return rows


def frame_rows():
    """offset / rotate: classes of the transformed cloud against the native run's."""
    rows = []
    for name in gr.FILES:
        d = _load(name)
        sel = gs.thinned(d, None, 0)
        x, y, z, vc = (d[k][sel] for k in ("x", "y", "z", "vclass"))
        g0, cpu0 = _run("recommended", x, y, z, vc)
        base = _score(d, x, y, z, g0)
        rows.append(dict(t="native", file=name, case="", filter="recommended", n=int(x.size),
                         rmse=base[0], bad=base[1], cpu=cpu0, changed=0, diff=0.0))
        print("transforms", rows[-1], flush=True)
        for case in ("offset", "rotate"):
            xt, yt = (rotated(x, y) if case == "rotate" else (x, y))
            xt, yt, zt = xt + OFFSET[0], yt + OFFSET[1], z + OFFSET[2]
            g, cpu = _run("recommended", xt, yt, zt, vc)
            rmse, bad = _score(d, x, y, z, g)
            e = gr.idw(x[g], y[g], z[g], d["cx"], d["cy"]) - gr.idw(
                x[g0], y[g0], z[g0], d["cx"], d["cy"])
            rows.append(dict(t=case, file=name, case=case, filter="recommended",
                             n=int(x.size), rmse=rmse, bad=bad, cpu=cpu,
                             changed=int(np.count_nonzero(g != g0)),
                             diff=float(np.sqrt(np.mean(e * e)))))
            print("transforms", rows[-1], flush=True)
    return rows


def _classify_file(src, tmp, tag):
    from geomatics_toolbox.core.lidar.filters import default_selection, ground_filter
    from geomatics_toolbox.core.lidar.pipeline import FilterOutputs, classify_file
    t = time.process_time()
    run = classify_file(src, ground_filter("groundfilter"),
                        FilterOutputs(cloud=os.path.join(tmp, f"{tag}.las")),
                        selection=default_selection("groundfilter"))
    return np.asarray(run.classes), time.process_time() - t


def _no_classes(src, dst):
    import laspy
    las = laspy.read(str(src))
    las.classification = np.ones(len(las.points), np.uint8)
    las.write(str(dst))
    return str(dst)


def feet_copy(src, dst):
    """``src`` (metres) with x, y, z in US survey feet and a CRS saying so.

    Point formats 0-5: :func:`synthetic.hostile.unit_copy` (GeoTIFF keys: the EPSG code
    kept, ``ProjLinearUnitsGeoKey`` and ``VerticalUnitsGeoKey`` = 9003 US survey foot,
    as libgeotiff writes a projected CRS in another unit). LAS 1.4 formats 6-10 (WKT):
    same format, points and extra bytes, 0.001 ft scale, the WKT's linear unit set to the
    US survey foot (false easting / northing converted, GDAL's
    ``SetLinearUnitsAndUpdateParameters``) and the GeoTIFF keys dropped.
    """
    import laspy

    from geomatics_toolbox.core.io.las import crs_of_header
    from geomatics_toolbox.synthetic.hostile import unit_copy
    las = laspy.read(str(src))
    if las.header.point_format.id < 6:
        code = int(crs_of_header(las.header).split(":")[1])
        return unit_copy(src, dst, unit_metres=FT, scale=0.001,
                         keys={1024: 1, 3072: code, 3076: 9003, 4099: 9003})
    from osgeo import osr
    srs = osr.SpatialReference()
    srs.ImportFromWkt(crs_of_header(las.header))
    srs.SetLinearUnitsAndUpdateParameters("US survey foot", FT)
    x, y, z = (np.asarray(v) / FT for v in (las.x, las.y, las.z))
    las.change_scaling(scales=[0.001] * 3,
                       offsets=[np.floor(v.min()) for v in (x, y, z)])
    las.x, las.y, las.z = x, y, z
    las.header.vlrs = [v for v in las.header.vlrs if not isinstance(
        v, (laspy.vlrs.known.GeoKeyDirectoryVlr, laspy.vlrs.known.GeoDoubleParamsVlr,
            laspy.vlrs.known.GeoAsciiParamsVlr, laspy.vlrs.known.WktCoordinateSystemVlr))]
    las.header.vlrs.append(laspy.vlrs.known.WktCoordinateSystemVlr(srs.ExportToWkt()))
    las.write(str(dst))
    return str(dst)


def file_rows():
    """units / classes through the file path: classes against the native file's."""
    from geomatics_toolbox.synthetic.hostile import unit_copy
    rows = []
    for name in gr.FILES:
        d = _load(name)
        src = gr.REAL / f"{name}.laz"
        with tempfile.TemporaryDirectory() as tmp:
            c0, cpu0 = _classify_file(src, tmp, "native")
            g0 = c0 == 2
            base = gs.dtm_error(d, d["x"], d["y"], d["z"], g0)
            rows.append(dict(t="file", file=name, case="as delivered", filter="recommended",
                             n=int(c0.size), rmse=base[0], bad=base[1], cpu=cpu0, changed=0,
                             diff=0.0))
            if name == "pdal_nm_usft":
                conv = unit_copy(src, os.path.join(tmp, "u.las"), unit_metres=1.0 / FT,
                                 keys={1024: 1, 3072: 26913}, scale=0.001)
                label = "in metres"
            else:
                conv = feet_copy(src, os.path.join(tmp, "u.las"))
                label = "in US survey feet"
            for case, path in ((label, conv), ("no input classes",
                                               _no_classes(src, os.path.join(tmp, "c.las")))):
                c, cpu = _classify_file(path, tmp, "out")
                g = c == 2
                rmse, bad = gs.dtm_error(d, d["x"], d["y"], d["z"], g)
                e = gr.idw(d["x"][g], d["y"][g], d["z"][g], d["cx"], d["cy"]) - gr.idw(
                    d["x"][g0], d["y"][g0], d["z"][g0], d["cx"], d["cy"])
                rows.append(dict(t="file", file=name, case=case, filter="recommended",
                                 n=int(c.size), rmse=rmse, bad=bad, cpu=cpu,
                                 changed=int(np.count_nonzero(c != c0)),
                                 diff=float(np.sqrt(np.mean(e * e)))))
                print("transforms", rows[-1], flush=True)
    return rows


def transforms_section(filters=FILTERS):
    """Rows of every transformation (None without the real files)."""
    if not (gr.REAL / f"{gr.FILES[0]}.laz").exists():
        return None
    return canopy_rows(filters) + dense_rows(filters) + frame_rows() + file_rows()


def _cell(r):
    return f"{gr.fmt(r['rmse'])} / {r['bad']:.2f}"


def transforms_md(rows, filters=FILTERS):
    """Markdown of :func:`transforms_section`."""
    load = os.getloadavg() if hasattr(os, "getloadavg") else (float("nan"),)
    head, now = gs.run_stamp()
    cols = ("oracle",) + tuple(filters)
    cpu = sum(r["cpu"] for r in rows if r["filter"] == "recommended")
    L = ["## Real files transformed: DTM RMSE (m) / cells off > 1 m (%) (`--transforms`)", "",
         "Stress round 2 (`benchmarks/_ground_transforms.py`, its docstring says how each "
         "transformation is made; seeded): closed canopy, dense crop, offsets and rotation, "
         "units and input classes through the file path. Scored as `--stress`: the 1 m IDW "
         "DTM of the filter's ground against the vendor ground DTM of the FULL "
         "untransformed file, inside the vendor-ground hull (dense: inside the crop). "
         f"Every filter at its defaults. Recommended CPU {cpu:.1f} s summed over the rows "
         "(file-path rows: read, filter and write) "
         f"(load average {load[0]:.1f} at the end, 2 shared cores). Run {now} at {head} "
         "(`bench_ground.py --transforms`).", "",
         "### Closed canopy and dense crop", "",
         "| file | case | seed | points | ground pts/m² | " + " | ".join(cols) + " |",
         "|---" * (len(cols) + 5) + "|"]
    by = {}
    for r in rows:
        if r["t"] in ("canopy", "dense"):
            by.setdefault((r["file"], r["case"], r["seed"]), {})[r["filter"]] = r
    for (name, case, seed), fr in by.items():
        r0 = next(iter(fr.values()))
        gd = f"{r0['ground']:.2f}" if "ground" in r0 else "–"
        L.append(f"| {name} | {case} | {seed} | {r0['n']:,} | {gd} | " + " | ".join(
            _cell(fr[w]) if w in fr else "–" for w in cols) + " |")
    L += ["", "### Invariance: the same cloud in another frame, unit or with no input "
          "classes (recommended)", "",
          "Points changed = points whose class differs from the native run's; DTM diff = "
          "RMS (m) of the difference between the two runs' ground DTMs.", "",
          "| file | transformation | points | DTM vs vendor | points changed | DTM diff (m) |",
          "|---|---|---|---|---|---|"]
    for r in rows:
        if r["t"] in ("native", "offset", "rotate", "file"):
            what = {"native": "none (arrays)", "offset": "+500 000 / +5 000 000 / +2 000 m",
                    "rotate": f"rotated {ANGLE:g}° + offset", "file": "file path: "
                    + r["case"]}[r["t"]]
            L.append(f"| {r['file']} | {what} | {r['n']:,} | {_cell(r)} | {r['changed']:,} "
                     f"| {r['diff']:.3f} |")
    return "\n".join(L) + "\n"

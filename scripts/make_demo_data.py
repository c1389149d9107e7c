#!/usr/bin/env python3
"""Write the demo data set: a small synthetic LiDAR tile and its check points.

Outputs (in ``--out``, default ``out/demo``), each written under a temporary name
and renamed on success, identical on every run:

* ``demo.laz`` — 300 m × 300 m, ~4 points/m², LAS 1.4 point format 6, EPSG:32632,
  ASPRS classes as ground truth (2, 5, 6, 7, 18); < 2 MB;
* ``checkpoints.csv`` — ``id,x,y,z``: 62 check points on open ground with the true
  terrain height (like the 62 GNSS check points of the DTM-accuracy spec);
* ``checkpoints.gpkg`` — the same points as a PointZ layer ``checkpoints`` with
  fields ``id`` and ``z``, same CRS.

Usage: ``python scripts/make_demo_data.py [--out DIR] [--seed N]``.
"""
from __future__ import annotations

import argparse
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

DEMO = dict(extent=(300.0, 300.0), origin=(500_000.0, 4_000_000.0), density=4.0)
CRS = "EPSG:32632"
N_CHECKPOINTS = 62




def write_checkpoints_csv(cp, path) -> None:
    """``id,x,y,z`` with centimetre x, y and millimetre z."""
    from geomatics_toolbox.core.io.contract import atomic_output
    with atomic_output(path) as tmp:
        with open(tmp, "w", encoding="utf-8", newline="\n") as fh:
            fh.write("id,x,y,z\n")
            for i, x, y, z in zip(cp.id, cp.x, cp.y, cp.z):
                fh.write(f"{int(i)},{x:.2f},{y:.2f},{z:.3f}\n")


def write_checkpoints_gpkg(cp, path, crs: str = CRS) -> None:
    """A GeoPackage PointZ layer ``checkpoints`` (fields ``id``, ``z``)."""
    from osgeo import gdal, ogr, osr

    from geomatics_toolbox.core.io.contract import atomic_output
    # a fixed gpkg_contents.last_change keeps the file identical between runs
    gdal.SetConfigOption("OGR_CURRENT_DATE", "2026-01-01T00:00:00.000Z")
    ogr.UseExceptions()
    osr.UseExceptions()
    srs = osr.SpatialReference()
    srs.SetFromUserInput(crs)
    srs.SetAxisMappingStrategy(osr.OAMS_TRADITIONAL_GIS_ORDER)
    with atomic_output(path) as tmp:
        ds = ogr.GetDriverByName("GPKG").CreateDataSource(tmp)
        layer = ds.CreateLayer("checkpoints", srs, ogr.wkbPoint25D)
        layer.CreateField(ogr.FieldDefn("id", ogr.OFTInteger))
        layer.CreateField(ogr.FieldDefn("z", ogr.OFTReal))
        defn = layer.GetLayerDefn()
        layer.StartTransaction()
        for i, x, y, z in zip(cp.id, cp.x, cp.y, cp.z):
            feat = ogr.Feature(defn)
            feat.SetField("id", int(i))
            feat.SetField("z", round(float(z), 3))
            geom = ogr.Geometry(ogr.wkbPoint25D)
            geom.AddPoint(float(round(x, 2)), float(round(y, 2)), round(float(z), 3))
            feat.SetGeometry(geom)
            layer.CreateFeature(feat)
        layer.CommitTransaction()
        ds = None  # close before the rename


def make_demo(out_dir, *, seed: int = 2) -> dict:
    """Generate the demo tile and check points into ``out_dir``; returns the paths."""
    from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile

    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    tile = generate_tile(seed=seed, **DEMO)
    cp = tile.checkpoints(N_CHECKPOINTS)
    paths = {"laz": out / "demo.laz", "csv": out / "checkpoints.csv",
             "gpkg": out / "checkpoints.gpkg"}
    write_tile(tile, paths["laz"], crs=CRS)
    write_checkpoints_csv(cp, paths["csv"])
    write_checkpoints_gpkg(cp, paths["gpkg"])
    return {"points": len(tile), "checkpoints": len(cp), **paths}


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default=str(ROOT / "out" / "demo"),
                        help="output folder (default: out/demo in the checkout)")
    parser.add_argument("--seed", type=int, default=2, help="generator seed (default 2)")
    args = parser.parse_args(argv)
    res = make_demo(args.out, seed=args.seed)
    size = res["laz"].stat().st_size / 1e6
    print(f"{res['laz']}: {res['points']} points, {size:.2f} MB")
    print(f"{res['csv']}, {res['gpkg']}: {res['checkpoints']} check points")
    return 0


if __name__ == "__main__":
    sys.exit(main())

"""Hostile input, round 3 (issue 22) through qgis_process, as the probe runs it: a non-zero
exit with the message, nothing written, inputs unchanged; a feet cloud's DTM in feet."""
from __future__ import annotations

import hashlib

import numpy as np
from osgeo import gdal

from geomatics_toolbox.core.io.las import write_las
from geomatics_toolbox.core.io.units import US_FOOT
from geomatics_toolbox.synthetic.hostile import huge_vlr_count, unit_copy


def _digest(p) -> str:
    return hashlib.sha256(open(p, "rb").read()).hexdigest()


def _cloud(path, x0=500_000.37, y0=4_000_000.41, n=3000, version="1.2", point_format=1,
           side=60.0):
    rng = np.random.default_rng(0)
    write_las(path, x0 + rng.uniform(0, side, n), y0 + rng.uniform(0, side, n),
              200 + rng.normal(0, 0.2, n),
              dimensions={"classification": np.full(n, 2, np.uint8)}, crs="EPSG:32632",
              version=version, point_format=point_format, scale=0.001)
    return path


def test_huge_vlr_count_refused_at_once(qgis_process, tmp_path):
    bad = huge_vlr_count(_cloud(tmp_path / "ok.las"), tmp_path / "bad.las")
    before = _digest(bad)
    out = tmp_path / "c.laz"
    msg = qgis_process.run_expect_failure("geomatics:groundfilter", INPUT=bad, OUTPUT=out)
    assert "bad.las claims 1,069,128,089 variable-length records" in msg
    assert "Traceback" not in msg and not out.exists() and _digest(bad) == before


def test_catalog_one_metre_chunks_refused_before_any_file(qgis_process, tmp_path):
    d = tmp_path / "tiles"
    d.mkdir()
    _cloud(d / "a.las", side=150.0)                     # 300 m × 150 m: 45,000 1-m chunks
    _cloud(d / "b.las", x0=500_150.37, version="1.4", point_format=6,   # WKT vs GeoKeys
           side=150.0)
    out = tmp_path / "out"
    msg = qgis_process.run_expect_failure("geomatics:catalog", INPUT=d, OUTPUT_FOLDER=out,
                                          CHUNK_SIZE=1, CELL_SIZE=1)
    assert "CHUNK_SIZE 1 m cuts the catalog" in msg and "different CRSs" not in msg
    assert not out.exists()


def test_feet_cloud_dtm_written_in_feet(qgis_process, tmp_path):
    m = _cloud(tmp_path / "m.las")
    ft = unit_copy(m, tmp_path / "ft.las", scale=0.0001)
    res = {}
    for k, src in (("m", m), ("ft", ft)):
        res[k] = qgis_process.run("geomatics:idwdtm", INPUT=src, CELL_SIZE=2, FILL_GAPS=True,
                                  OUTPUT=tmp_path / f"{k}.tif")["results"]
    ds = {k: gdal.Open(res[k]["OUTPUT"]) for k in res}
    gm, gf = ds["m"].GetGeoTransform(), ds["ft"].GetGeoTransform()
    assert gm[1] == 2.0 and abs(gf[1] * US_FOOT.metres - 2.0) < 1e-9
    assert ds["ft"].GetRasterBand(1).GetUnitType() == "ftUS"
    am = ds["m"].GetRasterBand(1).ReadAsArray()
    af = ds["ft"].GetRasterBand(1).ReadAsArray() * US_FOOT.metres
    assert np.median(np.abs(am - af)) < 1e-4

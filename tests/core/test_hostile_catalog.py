"""Catalogs validate everything before the first worker or file (issue 22, Build 2–3).

Each refusal names the problem, leaves the tiles byte-identical and creates nothing in
the output folder (not even ``.catalog``).
"""
from __future__ import annotations

import hashlib
import shutil

import numpy as np
import pytest

from geomatics_toolbox.core.errors import InputError
from geomatics_toolbox.core.io.las import write_las
from geomatics_toolbox.core.lidar import catalog as cc
from geomatics_toolbox.core.terrain.grid import grid_from_extent

pytest.importorskip("distributed")


def _tile(path, x0, y0, *, version="1.4", crs="EPSG:32632", n=400, seed=0):
    rng = np.random.default_rng(seed)
    write_las(path, x0 + rng.uniform(0, 100, n), y0 + rng.uniform(0, 100, n),
              200 + rng.uniform(0, 3, n),
              dimensions={"classification": np.full(n, 2, np.uint8)}, crs=crs,
              version=version, point_format=6 if version == "1.4" else 1)
    return str(path)


def _digests(paths):
    return {p: hashlib.sha256(open(p, "rb").read()).hexdigest() for p in paths}


def _refused(src, out, message, **kw):
    paths = [str(p) for p in (src if isinstance(src, list) else [])]
    before = _digests(paths)
    with pytest.raises(InputError, match=message):
        cc.run_catalog(src, out, workers=1, **kw)
    assert not out.exists(), sorted(out.rglob("*"))
    assert _digests(paths) == before


@pytest.fixture()
def tiles(tmp_path):
    d = tmp_path / "tiles"
    d.mkdir()
    return [_tile(d / "a.las", 500_000, 4_000_000, version="1.4"),      # WKT VLR
            _tile(d / "b.las", 500_100, 4_000_000, version="1.2", seed=1)]   # GeoKeys


def test_wkt_and_geokeys_of_one_crs_are_one_crs(tiles):
    from geomatics_toolbox.core.io.las import las_info
    assert las_info(tiles[0]).crs != las_info(tiles[1]).crs          # as text: different
    cat = cc.Catalog.open(tiles)
    assert len(cat.tiles) == 2


def test_different_crs_refused_with_both_named(tiles, tmp_path):
    other = _tile(tmp_path / "tiles" / "c.las", 500_200, 4_000_000, crs="EPSG:31467")
    with pytest.raises(InputError, match=r"2 different CRSs.*EPSG:32632.*c\.las: EPSG:31467"):
        cc.Catalog.open([*tiles, other])


def test_duplicate_tile_refused(tiles, tmp_path):
    copy = tmp_path / "tiles" / "a_copy.las"
    shutil.copy(tiles[0], copy)
    _refused([*tiles, str(copy)], tmp_path / "out", r"Duplicated tiles.*a\.las = a_copy\.las")


def test_degree_tiles_refused(tmp_path):
    d = tmp_path / "t"
    d.mkdir()
    geo = [_tile(d / "g.las", 9.0, 48.0, crs="EPSG:4326")]
    _refused(geo, tmp_path / "out", r"geographic CRS")


@pytest.mark.parametrize("chunk,message", [
    (1.0, r"CHUNK_SIZE 1 m cuts the catalog .* into up to 20,000 chunks, more than 10,000"),
    (1e12, r"The grid would have"),
])
def test_absurd_chunk_sizes_refused(tiles, tmp_path, chunk, message):
    _refused(tiles, tmp_path / "out", message, chunk_size=chunk)


@pytest.mark.parametrize("address,message", [
    ("not a scheduler", r"is not a Dask scheduler address"),
    ("tcp://127.0.0.1:1", r"Cannot reach the Dask scheduler tcp://127.0.0.1:1"),
])
def test_bad_scheduler_refused_before_any_file(tiles, tmp_path, address, message):
    _refused(tiles, tmp_path / "out", message, scheduler=address)


def test_truncated_tile_named_before_any_worker(tiles, tmp_path):
    data = open(tiles[1], "rb").read()
    open(tiles[1], "wb").write(data[:-500])
    _refused(tiles, tmp_path / "out", r"b\.las is truncated")


def test_rerun_with_other_settings_refused(tiles, tmp_path):
    out = tmp_path / "out"
    res = cc.run_catalog(tiles, out, workers=1, cell_size=2.0, buffer=10.0,
                         ground_filter="keep")
    assert not res.failed and (out / ".catalog" / "settings.json").exists()
    again = cc.run_catalog(tiles, out, workers=1, cell_size=2.0, buffer=10.0,
                           ground_filter="keep")
    assert sorted(again.skipped) == ["a", "b"]                  # same settings: resumed
    before = {p: p.stat().st_mtime_ns for p in out.rglob("*")}
    with pytest.raises(InputError, match=r"earlier run with other settings \(cell_size: "
                                         r"2\.0 → 1\.0"):
        cc.run_catalog(tiles, out, workers=1, cell_size=1.0, buffer=10.0,
                       ground_filter="keep")
    assert {p: p.stat().st_mtime_ns for p in out.rglob("*")} == before


def test_grid_of_a_billion_cells_refused():
    with pytest.raises(InputError, match=r"100,000 × 10,000 = 1,000,000,000 cells.*at "
                                         r"least 2"):
        grid_from_extent((0, 100_000, 0, 10_000), 1.0)


def test_truncated_laz_tile_named_before_any_worker(tmp_path):
    from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile
    d = tmp_path / "laz"
    d.mkdir()
    for k, x0 in enumerate((500_000.0, 500_060.0)):
        write_tile(generate_tile(extent=(60.0, 60.0), origin=(x0, 4e6), density=2.0, seed=k),
                   d / f"t{k}.laz")
    data = (d / "t1.laz").read_bytes()
    (d / "t1.laz").write_bytes(data[: len(data) // 2])
    _refused([str(d / "t0.laz"), str(d / "t1.laz")], tmp_path / "out",
             r"t1\.laz is truncated: its compressed points end before their chunk table")


def test_unreadable_tiles_all_named_or_skipped_on_request(tiles, tmp_path):
    from geomatics_toolbox.synthetic.hostile import huge_vlr_count
    d = tmp_path / "tiles"
    bad1 = huge_vlr_count(tiles[1], d / "c.las")
    bad2 = d / "d.las"
    bad2.write_bytes(b"junk" * 100)
    with pytest.raises(InputError, match=r"2 tile\(s\) cannot be read \(c\.las: .*claims "
                                         r"1,069,128,089 .*d\.las: .*SKIP_UNREADABLE"):
        cc.Catalog.open([*tiles, str(bad1), str(bad2)])
    cat = cc.Catalog.open([*tiles, str(bad1), str(bad2)], skip_unreadable=True)
    assert cat.paths == tiles and sorted(cat.unreadable) == [str(bad1), str(bad2)]
    with pytest.raises(InputError, match=r"2 tile\(s\) cannot be read"):
        cc.Catalog.open([str(bad1), str(bad2)], skip_unreadable=True)     # nothing left


def test_catalog_of_feet_tiles_equals_its_metre_copy(tmp_path):
    """Tiles in US survey feet: the same classes, the same DTMs (converted) as metres."""
    import laspy

    from geomatics_toolbox.core.io.raster import read_raster
    from geomatics_toolbox.core.io.units import US_FOOT, raster_units
    from geomatics_toolbox.synthetic.hostile import unit_copy
    from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile
    ft_m = US_FOOT.metres
    t = generate_tile(extent=(120.0, 80.0), origin=(500_000.37, 4_000_000.41), density=3.0,
                      seed=11, n_buildings=1, n_halls=0, scale=0.0001)
    src = tmp_path / "src"
    src.mkdir()
    write_tile(t, src / "all.las")
    las = laspy.read(src / "all.las")
    for k, half in enumerate((las.x < 500_060.37, las.x >= 500_060.37)):
        sub = laspy.LasData(las.header)
        sub.points = las.points[np.asarray(half)]
        sub.write(src / f"t{k}.las")
    dirs = {"m": tmp_path / "m", "ft": tmp_path / "ft"}
    for d in dirs.values():
        d.mkdir()
    for k in range(2):
        unit_copy(src / f"t{k}.las", dirs["m"] / f"t{k}.las", unit_metres=1.0,
                  keys={1024: 1, 3072: 32632}, scale=0.0001)
        unit_copy(src / f"t{k}.las", dirs["ft"] / f"t{k}.las", scale=0.0001)
    res = {k: cc.run_catalog(str(d), tmp_path / f"out_{k}", workers=1, cell_size=2.0,
                             buffer=30.0) for k, d in dirs.items()}
    assert not res["m"].failed and not res["ft"].failed
    for k in range(2):
        cm = laspy.read(tmp_path / "out_m" / f"t{k}_classified.las").classification
        cf = laspy.read(tmp_path / "out_ft" / f"t{k}_classified.las").classification
        assert np.array_equal(cm, cf), int(np.count_nonzero(cm != cf))
        rm = read_raster(tmp_path / "out_m" / f"t{k}_dtm.tif")
        rf = read_raster(tmp_path / "out_ft" / f"t{k}_dtm.tif")
        assert rm.shape == rf.shape
        np.testing.assert_allclose(np.array(rf.geotransform) * ft_m, rm.geotransform,
                                   atol=1e-6)
        dm, df = rm.masked(), rf.masked() * ft_m
        assert np.array_equal(np.isnan(dm), np.isnan(df))
        assert np.nanmedian(np.abs(dm - df)) < 1e-4
        # heights named on the band as a single-file DTM's (review H5: chunks had none)
        assert raster_units(tmp_path / "out_ft" / f"t{k}_dtm.tif").vertical.symbol == "ftUS"
        assert raster_units(tmp_path / "out_m" / f"t{k}_dtm.tif").vertical.symbol == "m"
        from osgeo import gdal
        ds = gdal.Open(str(tmp_path / "out_ft" / f"t{k}_dtm.tif"))
        assert ds.GetRasterBand(1).GetUnitType() == "ftUS"
    vrt = res["ft"].vrt
    assert vrt and raster_units(vrt).vertical.symbol == "ftUS", vrt   # the mosaic too


def test_every_chunk_failed_is_an_error_naming_the_first(tmp_path):
    import struct

    from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile
    d = tmp_path / "laz"
    d.mkdir()
    for k, x0 in enumerate((500_000.0, 500_060.0)):
        p = d / f"t{k}.laz"
        write_tile(generate_tile(extent=(60.0, 60.0), origin=(x0, 4e6), density=2.0, seed=k),
                   p)
        cut = bytearray(p.read_bytes())
        cut = cut[: len(cut) // 2]          # damage the header cannot reveal (see test_catalog)
        struct.pack_into("<q", cut, struct.unpack_from("<I", cut, 96)[0], -1)
        p.write_bytes(bytes(cut))
    with pytest.raises(InputError, match=r"Every chunk failed \(2 of 2\); no DTM was made. "
                                         r"First failure: t\d: .*truncated or corrupt"):
        cc.run_catalog(str(d), tmp_path / "out", workers=1, ground_filter="keep",
                       buffer=0.0, cell_size=2.0)


@pytest.mark.parametrize("damage,message", [
    ("max_x", r"The header of c\.las declares x bounds 500200\.\d* to 9000000000, which its "
              r"coordinates cannot hold \(scale 0\.\d+, offset"),
    ("zeros", r"The header of c\.las declares its bounds as all zero \(never filled in\)"),
    ("inverted", r"The header of c\.las declares y bounds 4000099\.76 to 4000000\.21"),
])
def test_tile_whose_header_bounds_lie_named(tiles, tmp_path, damage, message):
    """The catalog places tiles by their header bounds: a damaged max x was refused as
    "The grid would have 4,499,749,910 × 60 cells ... use a cell size of at least 65.73"
    (the wrong fix); zero bounds put the tile at (0, 0)."""
    import struct
    c = _tile(tmp_path / "tiles" / "c.las", 500_200, 4_000_000, version="1.2", seed=2)
    with open(c, "r+b") as fh:         # LAS 1.2 header: max x, min x, max y, min y, ...
        fh.seek(179)
        old = struct.unpack("<6d", fh.read(48))
        new = {"max_x": (9e9, *old[1:]), "zeros": (0.0,) * 6,
               "inverted": (old[0], old[1], old[3], old[2], *old[4:])}[damage]
        fh.seek(179)
        fh.write(struct.pack("<6d", *new))
    _refused([*tiles, c], tmp_path / "out", message)


@pytest.mark.parametrize("entry", ["folder", "glob"])
def test_list_entry_that_yields_no_tile_named(tiles, tmp_path, entry):
    """A folder (or pattern) in a list of sources that holds no tile was skipped without a
    word: the catalog ran on the other entries."""
    empty = tmp_path / "typo.las"            # a folder, as a mistyped export path makes
    empty.mkdir()
    item = str(empty) if entry == "folder" else str(tmp_path / "tiles" / "*.laz")
    before = _digests(tiles)
    with pytest.raises(InputError, match=r"(typo\.las|\*\.laz) holds no LAS/LAZ tile; "
                                         r"correct that entry of the list or remove it"):
        cc.run_catalog([*tiles, item], tmp_path / "out", workers=1)
    assert not (tmp_path / "out").exists() and _digests(tiles) == before
    assert len(cc.Catalog.open([*tiles]).tiles) == 2

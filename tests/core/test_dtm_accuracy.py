"""DTM accuracy golden tests, sampling, DSM/nDSM, check point CSV, GeoTIFF round trip."""
from __future__ import annotations

import numpy as np
import pytest

from geomatics_toolbox.core.io.points import parse_classes, read_checkpoints_csv, write_grid
from geomatics_toolbox.core.io.raster import read_raster
from geomatics_toolbox.core.terrain.accuracy import (
    NODATA,
    OK,
    OUTSIDE,
    accuracy_stats,
    dtm_accuracy,
    sample_raster,
)
from geomatics_toolbox.core.terrain.dsm import accumulate_max, dsm_grid, fill_nearest, ndsm
from geomatics_toolbox.core.terrain.grid import grid_from_extent

GRID = grid_from_extent((1000.0, 1100.0, 2000.0, 2080.0), 1.0, crs="EPSG:32632")


def plane(x, y):
    return 50.0 + 0.1 * (x - 1000.0) - 0.05 * (y - 2000.0)


def plane_dtm():
    xx, yy = np.meshgrid(GRID.x_centers(), GRID.y_centers())
    return plane(xx, yy)


def test_golden_known_offsets():
    dtm = plane_dtm()
    dtm[40, 40] = np.nan                                    # a nodata cell
    rng = np.random.default_rng(0)
    x = rng.uniform(1010, 1090, 20)
    y = rng.uniform(2010, 2070, 20)
    offsets = np.array([0.1, -0.2, 0.3, 0.0, 0.25, -0.15, 0.05, 0.4, -0.3, 0.2] * 2)
    z = plane(x, y) - offsets            # error = DTM - check = +offset
    x = np.append(x, [1040.5, 1500.0])   # on the nodata cell, outside the DTM
    y = np.append(y, [2039.5, 2040.0])
    z = np.append(z, [55.0, 55.0])
    res = dtm_accuracy(dtm, GRID.geotransform, x, y, z)
    s = res.stats
    assert res.n_total == 22 and res.n_used == 20
    assert res.n_nodata == 1 and res.n_outside == 1
    assert list(res.status[-2:]) == [NODATA, OUTSIDE]
    assert np.isnan(res.z_dtm[-2:]).all()                    # excluded, never 0
    e = offsets
    assert s["n"] == 20
    assert s["me"] == pytest.approx(e.mean(), abs=1e-9)
    assert s["rmse"] == pytest.approx(np.sqrt(np.mean(e ** 2)), abs=1e-9)
    assert s["mae"] == pytest.approx(np.abs(e).mean(), abs=1e-9)
    assert s["std"] == pytest.approx(e.std(ddof=1), abs=1e-9)
    assert s["max_abs_error"] == pytest.approx(0.4, abs=1e-9)
    assert s["accuracy_95"] == pytest.approx(1.96 * s["rmse"], rel=1e-12)
    med = np.median(e)
    assert s["nmad"] == pytest.approx(1.4826 * np.median(np.abs(e - med)), abs=1e-9)
    r = np.corrcoef(plane(x[:20], y[:20]), z[:20])[0, 1]
    assert s["r"] == pytest.approx(r, abs=1e-12) and s["r2"] == pytest.approx(r * r)


def test_constant_offset_gives_exact_bias_and_r_one():
    dtm = plane_dtm()
    x = np.array([1020.5, 1050.5, 1070.5, 1090.5])
    y = np.array([2010.5, 2030.5, 2060.5, 2075.5])
    res = dtm_accuracy(dtm, GRID.geotransform, x, y, plane(x, y) + 0.25, method="nearest")
    assert res.stats["me"] == pytest.approx(-0.25, abs=1e-12)
    assert res.stats["rmse"] == pytest.approx(0.25, abs=1e-12)
    assert res.stats["std"] == pytest.approx(0.0, abs=1e-12)
    assert res.stats["r"] == pytest.approx(1.0, abs=1e-12)


def test_bilinear_exact_on_plane_and_nearest():
    dtm = plane_dtm()
    x = np.array([1000.2, 1033.37, 1099.9, 1050.0])
    y = np.array([2079.9, 2041.11, 2000.1, 2040.0])
    vals, status, _ = sample_raster(dtm, GRID.geotransform, x, y)
    assert (status == OK).all()
    # bilinear reproduces a plane exactly inside the centre lattice
    np.testing.assert_allclose(vals[1:2], plane(x[1:2], y[1:2]), atol=1e-9)
    np.testing.assert_allclose(vals[3], plane(1050.0, 2040.0), atol=1e-9)
    near, _, _ = sample_raster(dtm, GRID.geotransform, x, y, method="nearest")
    assert near[1] == pytest.approx(plane(1033.5, 2041.5))


def test_no_usable_points_is_an_error():
    with pytest.raises(ValueError, match="0 of 2 check points.*2 outside"):
        dtm_accuracy(plane_dtm(), GRID.geotransform, [0.0, 1.0], [0.0, 1.0], [1.0, 2.0])
    assert np.isnan(accuracy_stats([], [])["rmse"])


def test_dsm_highest_return_and_ndsm():
    x = np.array([1000.2, 1000.7, 1000.5, 1001.5, 1099.99])
    y = np.array([2079.5, 2079.2, 2079.9, 2079.5, 2000.0])
    z = np.array([10.0, 30.0, 20.0, 5.0, 7.0])
    dsm = dsm_grid(x, y, z, GRID)
    assert dsm[0, 0] == 30.0 and dsm[0, 1] == 5.0 and dsm[-1, -1] == 7.0
    assert np.isnan(dsm[5, 5])
    out = np.full(GRID.shape, np.nan)
    accumulate_max(GRID, out, x[:2], y[:2], z[:2])
    accumulate_max(GRID, out, x[2:], y[2:], z[2:])            # chunked == at once
    np.testing.assert_array_equal(np.isnan(out), np.isnan(dsm))
    assert out[0, 0] == 30.0
    filled = fill_nearest(dsm, 1.0, 1.5)
    assert filled[1, 0] == 30.0 and np.isnan(filled[10, 10])
    dtm = np.full(GRID.shape, 12.0)
    chm = ndsm(dsm, dtm)
    assert chm[0, 0] == 18.0 and chm[0, 1] == 0.0 and np.isnan(chm[5, 5])
    assert ndsm(dsm, dtm, clamp_negative=False)[0, 1] == -7.0
    with pytest.raises(ValueError, match="same grid"):
        ndsm(dsm, dtm[:-1])


def test_checkpoint_csv_and_class_filter(tmp_path):
    p = tmp_path / "cp.csv"
    p.write_text("name;easting;northing;height\nA;1000.5;2000.5;51.2\nB;1001;2001;52\n")
    ids, x, y, z = read_checkpoints_csv(p)
    assert ids == ["A", "B"] and list(x) == [1000.5, 1001.0] and z[1] == 52.0
    q = tmp_path / "noheader.txt"
    q.write_text("1 10.0 20.0 3.5\n2 11.0 21.0 4.5\n")
    ids, x, y, z = read_checkpoints_csv(q)
    assert ids == ["1", "2"] and list(z) == [3.5, 4.5]
    bad = tmp_path / "bad.csv"
    bad.write_text("a,b,c\n1,2,3\n")
    with pytest.raises(ValueError, match="Cannot find x, y and z"):
        read_checkpoints_csv(bad)
    assert parse_classes("2, 8") == (2, 8) and parse_classes("") == ()
    with pytest.raises(ValueError, match="integer"):
        parse_classes("ground")


def test_geotiff_georeferencing_round_trip(tmp_path):
    dtm = plane_dtm()
    dtm[3, 4] = np.nan
    path = write_grid(tmp_path / "dtm.tif", dtm, GRID)
    r = read_raster(path)
    assert r.geotransform == GRID.geotransform and r.nodata == GRID.nodata
    assert "32632" in r.crs or "UTM zone 32N" in r.crs
    data = r.masked()
    assert np.isnan(data[3, 4])
    # sample known points back: the value at a cell centre is the plane there
    for px, py in [(1000.5, 2079.5), (1099.5, 2000.5), (1042.5, 2017.5)]:
        v, st, _ = sample_raster(data, r.geotransform, [px], [py], method="nearest")
        assert st[0] == OK and v[0] == pytest.approx(plane(px, py), abs=1e-4)


def test_one_parse_classes_refuses_non_integers():
    from geomatics_toolbox.core.errors import InputError
    from geomatics_toolbox.core.lidar.accuracy_file import parse_classes as lidar_parse
    for parse in (parse_classes, lidar_parse):
        assert parse("2, 8;11 ") == (2, 8, 11) and parse([9, 2, 2]) == (2, 9)
        for bad in ("2.7", "ground", "300", "-1"):
            with pytest.raises(InputError, match="class"):
                parse(bad)
    assert parse_classes("2.0") == (2,) and parse_classes(None) == ()
    with pytest.raises(InputError, match="at least one"):
        lidar_parse("")


def test_duplicated_checkpoints_named():
    from geomatics_toolbox.core.errors import InputError
    from geomatics_toolbox.core.terrain.accuracy import check_duplicates
    check_duplicates(["a", "b", "c"], [0, 1, 2], [0, 0, 0])
    check_duplicates(["a", "b"], [0, 0.002], [0, 0])              # 2 mm apart: distinct
    with pytest.raises(InputError, match=r"same id: row 1 \(id a\), row 3 \(id a\)"):
        check_duplicates(["a", "b", "a"], [0, 1, 2], [0, 0, 0])
    with pytest.raises(InputError, match=r"same position: row 2 \(id b\), row 3 \(id c\)"):
        check_duplicates(["a", "b", "c"], [0, 5, 5.0003], [0, 1, 1])
    with pytest.raises(InputError, match=r"row 8 \(id q\)"):
        check_duplicates(["p", "q"], [0, 0], [0, 0], rows=[7, 8])

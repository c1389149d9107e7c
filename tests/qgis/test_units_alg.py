"""Any linear unit (issue 22, Done-when 1): a cloud in US survey feet and its metre copy
give the same ground classes, the same DTMs (converted), the same lidarqa densities and
accuracy figures, and the reports of the feet cloud say feet.

Rule (DEVELOPERS.md, Units): lengths the user types are metres; data in feet are
converted; rasters are written in the data's own CRS and units (band unit type says
which).
"""
from __future__ import annotations

import re
from pathlib import Path

import laspy
import numpy as np
import pytest
from osgeo import gdal

from geomatics_toolbox.core.io.units import US_FOOT
from geomatics_toolbox.synthetic.hostile import unit_copy
from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile

FT = US_FOOT.metres
#: Reports in English whatever the interface language (QLocale follows the system LANG)
EN = {"REPORT_LANGUAGE": 1}
REAL_USFT = Path(__file__).resolve().parents[3] / "shared" / "data" / "real" / "pdal_nm_usft.laz"


@pytest.fixture(scope="module")
def clouds(tmp_path_factory):
    d = tmp_path_factory.mktemp("units")
    # an origin off the cell lattice and 0.1 mm coordinates: no point sits on a cell
    # edge, where the 1e-5 m difference between the two files would move it (or the
    # snapped grid) by a cell
    tile = generate_tile(extent=(100.0, 100.0), origin=(500_000.37, 4_000_000.41),
                         density=3.0, seed=7, n_buildings=2, n_halls=0, scale=0.0001)
    write_tile(tile, d / "src.las")
    m = unit_copy(d / "src.las", d / "m.las", unit_metres=1.0, keys={1024: 1, 3072: 32632},
                  scale=0.0001)
    ft = unit_copy(d / "src.las", d / "ft.las", scale=0.0001)     # EPSG:2903 + ftUS keys
    cp = tile.checkpoints(n=15, min_spacing=5.0)
    csv_m = cp.to_csv(d / "cp_m.csv", xy_decimals=4)
    with open(d / "cp_ft.csv", "w", encoding="utf-8") as fh:
        fh.write("id,x,y,z\n")
        for i, x, y, z in zip(cp.id, cp.x, cp.y, cp.z):
            fh.write(f"{i},{x / FT:.5f},{y / FT:.5f},{z / FT:.6f}\n")
    return {"dir": d, "m": m, "ft": ft, "cp_m": csv_m, "cp_ft": str(d / "cp_ft.csv")}


def _classes(path):
    return np.asarray(laspy.read(path).classification)


def _raster(path):
    ds = gdal.Open(str(path))
    b = ds.GetRasterBand(1)
    a = b.ReadAsArray().astype(float)
    a[a == b.GetNoDataValue()] = np.nan
    return a, np.array(ds.GetGeoTransform()), b.GetUnitType()


def _same_dtm(m_path, ft_path, tol=1e-3):
    am, gm, um = _raster(m_path)
    af, gf, uf = _raster(ft_path)
    assert (um, uf) == ("m", "ftUS")
    assert am.shape == af.shape
    np.testing.assert_allclose(gf * FT, gm, atol=1e-6)            # the same grid, in ftUS
    assert np.array_equal(np.isnan(am), np.isnan(af))
    # the same heights; the two files' coordinates differ by their 0.1 mm rounding,
    # which may swap a rare nearest-neighbour tie (a few mm in a few cells)
    diff = np.abs(af * FT - am)[~np.isnan(am)]
    assert np.median(diff) < 1e-4
    assert np.mean(diff > tol) < 0.005 and diff.max() < 0.05, (np.mean(diff > tol), diff.max())


def test_ground_filter_same_classes_and_feet_in_report(qgis_processing, clouds):
    d = clouds["dir"]
    out = {}
    for k in ("m", "ft"):
        out[k] = qgis_processing.run("geomatics:groundfilter", {
            "INPUT": clouds[k], "OUTPUT": str(d / f"gf_{k}.las"),
            "OUTPUT_HTML": str(d / f"gf_{k}.html"), **EN})
    cm, cf = _classes(out["m"]["OUTPUT"]), _classes(out["ft"]["OUTPUT"])
    assert np.array_equal(cm, cf), int(np.count_nonzero(cm != cf))
    assert out["m"]["N_GROUND"] == out["ft"]["N_GROUND"] > 1000
    html_ft = (d / "gf_ft.html").read_text(encoding="utf-8")
    html_m = (d / "gf_m.html").read_text(encoding="utf-8")
    assert "US survey foot" in html_ft and "ftUS" in html_ft
    assert "US survey foot" not in html_m


@pytest.mark.parametrize("alg,extra", [
    ("geomatics:idwdtm", {"POWER": 2.0, "NEIGHBOURS": 12, "FILL_GAPS": True}),
    ("geomatics:tindtm", {}),
    ("geomatics:krigingdtm", {"FIT_POINTS": 800, "NEIGHBOURS": 12, "FILL_GAPS": True}),
])
def test_dtm_same_grid_converted(qgis_processing, clouds, alg, extra):
    d = clouds["dir"]
    name = alg.split(":")[1]
    paths = {}
    for k in ("m", "ft"):
        res = qgis_processing.run(alg, {"INPUT": clouds[k], "CELL_SIZE": 2.0, **extra,
                                        "OUTPUT": str(d / f"{name}_{k}.tif"),
                                        "OUTPUT_HTML": str(d / f"{name}_{k}.html"), **EN})
        paths[k] = res["OUTPUT"]
    _same_dtm(paths["m"], paths["ft"], tol=2e-3 if name == "krigingdtm" else 1e-3)
    assert "ftUS" in (d / f"{name}_ft.html").read_text(encoding="utf-8")


def test_dsm_same_grid_converted(qgis_processing, clouds):
    d = clouds["dir"]
    for k in ("m", "ft"):
        qgis_processing.run("geomatics:dsm", {"INPUT": clouds[k], "CELL_SIZE": 2.0,
                                              "OUTPUT": str(d / f"dsm_{k}.tif"),
                                              "OUTPUT_HTML": str(d / f"dsm_{k}.html"), **EN})
    _same_dtm(d / "dsm_m.tif", d / "dsm_ft.tif")
    # the report speaks metres for both: the same cell size and heights
    html = {k: (d / f"dsm_{k}.html").read_text(encoding="utf-8") for k in ("m", "ft")}
    assert "US survey foot" in html["ft"] and "US survey foot" not in html["m"]
    for k in ("m", "ft"):
        assert re.search(r"[Cc]ell size.{0,200}?>2(\.0+)?<", html[k], re.S), k


def test_lidarqa_same_density(qgis_processing, clouds):
    d = clouds["dir"]
    res = {k: qgis_processing.run("geomatics:lidarqa", {
        "INPUT": clouds[k], "CELL_SIZE": 5.0, "OUTPUT": str(d / f"qa_{k}.tif"),
        "OUTPUT_HTML": str(d / f"qa_{k}.html"), **EN}) for k in ("m", "ft")}
    for key in ("DENSITY", "GROUND_DENSITY", "GAP_SHARE", "GROUND_WINDOW", "DTM_CELL"):
        assert res["ft"][key] == pytest.approx(res["m"][key], rel=1e-6), key
    assert res["m"]["DENSITY"] == pytest.approx(3.0, rel=0.25)   # pts/m², not per ft²
    html = (d / "qa_ft.html").read_text(encoding="utf-8")
    assert "US survey foot" in html and "pts/m²" in html
    am, gm, _ = _raster(d / "qa_m.tif")
    af, gf, _ = _raster(d / "qa_ft.tif")
    np.testing.assert_allclose(gf * FT, gm, atol=1e-6)
    # the same counts per 5 m cell, but for a point within 0.1 mm of a cell edge
    moved = np.abs(af - am) > 1e-6
    assert moved.mean() < 0.01 and np.nanmax(np.abs(af - am)) <= 1 / 25 + 1e-6


def test_dtm_accuracy_in_metres_labelled(qgis_processing, clouds):
    d = clouds["dir"]
    res = {}
    for k in ("m", "ft"):
        dtm = qgis_processing.run("geomatics:idwdtm", {
            "INPUT": clouds[k], "CELL_SIZE": 1.0, "FILL_GAPS": True,
            "OUTPUT": str(d / f"acc_dtm_{k}.tif")})["OUTPUT"]
        res[k] = qgis_processing.run("geomatics:dtmaccuracy", {
            "DTM": dtm, "CHECKPOINTS_CSV": clouds[f"cp_{k}"],
            "OUTPUT_HTML": str(d / f"acc_{k}.html"), **EN})
    assert res["m"]["N"] == res["ft"]["N"] == 15
    for key in ("RMSE", "ME", "MAE", "MAX_ABS_ERROR"):
        assert res["ft"][key] == pytest.approx(res["m"][key], abs=2e-4), key
    html = (d / "acc_ft.html").read_text(encoding="utf-8")
    assert "US survey foot" in html
    assert re.search(r"\d ftUS</text>", html)          # the residual map's scale bar
    assert re.search(r"\d m</text>", (d / "acc_m.html").read_text(encoding="utf-8"))


def test_lidar_to_dtm_same_rmse(qgis_processing, clouds):
    d = clouds["dir"]
    res = {k: qgis_processing.run("geomatics:lidartodtm", {
        "INPUT": clouds[k], "CHECKPOINTS_CSV": clouds[f"cp_{k}"], "CELL_SIZE": 1.0,
        "OUTPUT": str(d / f"l2d_{k}.las"), "OUTPUT_DTM": str(d / f"l2d_{k}.tif"),
        "OUTPUT_HTML": str(d / f"l2d_{k}.html"), **EN}) for k in ("m", "ft")}
    assert np.array_equal(_classes(res["m"]["OUTPUT"]), _classes(res["ft"]["OUTPUT"]))
    _same_dtm(res["m"]["OUTPUT_DTM"], res["ft"]["OUTPUT_DTM"])
    assert res["ft"]["RMSE"] == pytest.approx(res["m"]["RMSE"], abs=2e-4)
    assert "US survey foot" in (d / "l2d_ft.html").read_text(encoding="utf-8")


def test_real_us_survey_feet_file_and_its_metre_copy(qgis_processing, tmp_path):
    if not REAL_USFT.exists():
        pytest.skip(f"{REAL_USFT} not found (the real-data development set)")
    m = unit_copy(REAL_USFT, tmp_path / "m.las", unit_metres=1.0 / FT,
                  keys={1024: 1, 3072: 26913}, scale=0.0001)
    out = {}
    for k, src in (("m", m), ("ft", str(REAL_USFT))):
        out[k] = qgis_processing.run("geomatics:groundfilter", {
            "INPUT": src, "OUTPUT": str(tmp_path / f"out_{k}.las")})["OUTPUT"]
    cm, cf = _classes(out["m"]), _classes(out["ft"])
    assert np.array_equal(cm, cf), int(np.count_nonzero(cm != cf))   # 41 differed before


def test_elevation_change_in_feet_equals_metres(qgis_processing, clouds, tmp_path):
    """Two epochs in ftUS and their metre copies: the same
    LoD and volumes (m, m³), the difference raster the same once converted."""
    after = {}
    for k in ("m", "ft"):
        las = laspy.read(clouds[k])
        rise = 1.0 if k == "m" else 1.0 / FT                    # +1 m everywhere
        inside = (np.asarray(las.x) - np.asarray(las.x).min()) * (1.0 if k == "m" else FT) < 50
        las.z = np.asarray(las.z) + np.where(inside, rise, 0.0)
        after[k] = tmp_path / f"after_{k}.las"
        las.write(after[k])
    res = {}
    for k in ("m", "ft"):
        res[k] = qgis_processing.run("geomatics:elevationchange", {
            "INPUT": clouds[k], "INPUT_AFTER": str(after[k]), "CELL_SIZE": 2.0,
            "SIGMA1": 0.05, "SIGMA2": 0.05, "OUTPUT": str(tmp_path / f"chg_{k}.tif")})
    for key in ("LOD", "FILL_VOLUME", "CUT_VOLUME", "N_REGIONS"):
        assert res["ft"][key] == pytest.approx(res["m"][key], rel=1e-3, abs=1e-6), key
    assert res["m"]["FILL_VOLUME"] > 1000                        # ~50 m × 100 m × 1 m
    _same_dtm(res["m"]["OUTPUT"], res["ft"]["OUTPUT"], tol=1e-3)


def test_mixed_units_feet_plan_metre_heights(qgis_processing, clouds, tmp_path):
    """US data often has x, y in US survey feet and z in metres (VerticalUnitsGeoKey)."""
    d = clouds["dir"]
    mixed = unit_copy(d / "src.las", tmp_path / "mixed.las", scale=0.0001,
                      vertical_metres=1.0,
                      keys={1024: 1, 3072: 2903, 3076: 9003, 4096: 5703, 4099: 9001})
    out = {}
    for k, src in (("m", clouds["m"]), ("mixed", mixed)):
        out[k] = qgis_processing.run("geomatics:groundfilter", {
            "INPUT": src, "OUTPUT": str(tmp_path / f"gf_{k}.las")})["OUTPUT"]
    assert np.array_equal(_classes(out["m"]), _classes(out["mixed"]))
    dtm = {k: qgis_processing.run("geomatics:idwdtm", {
        "INPUT": src, "CELL_SIZE": 2.0, "POWER": 2.0, "FILL_GAPS": True,
        "OUTPUT": str(tmp_path / f"{k}.tif")})["OUTPUT"]
        for k, src in (("m", clouds["m"]), ("mixed", mixed))}
    am, gm, _ = _raster(dtm["m"])
    af, gf, uf = _raster(dtm["mixed"])
    assert uf == "m"                                   # heights stay metres
    np.testing.assert_allclose(gf * FT, gm, atol=1e-6)  # the grid in ftUS
    assert np.nanmedian(np.abs(af - am)) < 1e-4        # no vertical conversion


def _metre_dtm(path, z, unit_type):
    from geomatics_toolbox.core.io.raster import write_geotiff
    write_geotiff(path, z.astype(np.float32),
                  geotransform=(500_000.0, 2.0, 0.0, 4_000_060.0, 0.0, -2.0),
                  crs="EPSG:32632", unit_type=unit_type)
    return str(path)


@pytest.mark.parametrize("units", [("m", None), (None, "m"), ("metre", "m")])
def test_elevation_change_two_metre_dtms_one_without_band_unit(qgis_processing, tmp_path,
                                                               units):
    """Review H1: a DTM with band unit "m" and one without are both metres (either way
    round); they were refused as "metre (m) vs metre (m)"."""
    rng = np.random.default_rng(5)
    z = 100.0 + rng.normal(0.0, 0.01, (30, 30))
    before = _metre_dtm(tmp_path / "before.tif", z, units[0])
    after = _metre_dtm(tmp_path / "after.tif", z + 1.0, units[1])
    res = qgis_processing.run("geomatics:elevationchange", {
        "INPUT": before, "INPUT_AFTER": after, "SIGMA1": 0.05, "SIGMA2": 0.05, **EN,
        "OUTPUT": str(tmp_path / "chg.tif")})
    assert res["FILL_VOLUME"] == pytest.approx(30 * 30 * 4.0 * 1.0, rel=0.02)   # m³
    assert res["CUT_VOLUME"] == pytest.approx(0.0, abs=1e-6)


@pytest.mark.parametrize("lang", ["ar", "fa"])
def test_elevation_change_units_refusal_in_arabic_and_persian_is_data_only(lang):
    """Review H2: the units in the refusal are symbols (data), not English names."""
    from geomatics_toolbox.algorithms.elevation_change import check_same_crs
    from geomatics_toolbox.core.errors import InputError
    from geomatics_toolbox.core.io.units import crs_units
    with pytest.raises(InputError) as err:
        check_same_crs(None, None, "/d/before.tif", "/d/after.tif",
                       crs_units("EPSG:2903"), crs_units("EPSG:2903+5703"))
    assert "before.tif is in ftUS / ftUS, after.tif in ftUS / m" in str(err.value)
    msg = err.value.message(lang)
    assert "ftUS / m" in msg and "before.tif" in msg
    words = re.findall(r"[A-Za-z]{2,}", msg)
    assert set(words) <= {"before", "after", "tif", "ftUS", "m"}, msg


def test_lsq_tile_stats_of_a_feet_cloud_in_its_units(qgis_processing, clouds):
    """The LSQ per-tile CSV of a ftUS cloud: centres and heights in ftUS (they sit on the
    cloud), the unit in every length column's name; the metre copy's says m. The same
    tiles and fits: values equal once converted."""
    import csv
    d = clouds["dir"]
    rows = {}
    for k in ("m", "ft"):
        qgis_processing.run("geomatics:lsqgroundfilter", {
            "INPUT": clouds[k], "OUTPUT": str(d / f"lsq_{k}.las"),
            "TILE_STATS": str(d / f"lsq_{k}.csv")})
        rows[k] = list(csv.DictReader((d / f"lsq_{k}.csv").open(encoding="utf-8")))
    assert len(rows["m"]) == len(rows["ft"]) > 4
    for col in ("centre_x", "centre_y", "zmin", "zmax", "zmean", "std"):
        assert f"{col}_m" in rows["m"][0] and f"{col}_ftUS" in rows["ft"][0], col
        vm = np.array([float(r[f"{col}_m"] or "nan") for r in rows["m"]])
        vf = np.array([float(r[f"{col}_ftUS"] or "nan") for r in rows["ft"]])
        np.testing.assert_allclose(vf * FT, vm, atol=2e-3, err_msg=col)   # 3-decimal CSV
    las = laspy.read(clouds["ft"])
    cx = np.array([float(r["centre_x_ftUS"]) for r in rows["ft"]])
    assert np.asarray(las.x).min() - 300 < cx.min() and cx.max() < np.asarray(las.x).max() + 300


def test_buildings_and_classify_same_in_feet_and_reports_say_feet(qgis_processing, clouds):
    """Done-when 1 through processing.run: classify and buildings of the ftUS cloud equal
    those of its metre copy (classes, building count, areas in m², volumes in m³), and
    only the feet cloud's reports name US survey feet."""
    d = clouds["dir"]
    cls, bld = {}, {}
    for k in ("m", "ft"):
        cls[k] = qgis_processing.run("geomatics:classify", {
            "INPUT": clouds[k], "OUTPUT": str(d / f"cls_{k}.las"),
            "OUTPUT_HTML": str(d / f"cls_{k}.html"), **EN})
        bld[k] = qgis_processing.run("geomatics:buildings", {
            "INPUT": clouds[k], "OUTPUT": str(d / f"bld_{k}.gpkg"),
            "OUTPUT_HTML": str(d / f"bld_{k}.html"), **EN})
    cm, cf = _classes(cls["m"]["OUTPUT"]), _classes(cls["ft"]["OUTPUT"])
    assert np.mean(cm != cf) < 0.001, int(np.count_nonzero(cm != cf))
    for key in ("N_GROUND", "N_BUILDING", "N_VEGETATION"):
        assert cls["ft"][key] == pytest.approx(cls["m"][key], rel=0.002, abs=2), key
    assert bld["m"]["N_BUILDINGS"] == bld["ft"]["N_BUILDINGS"] == 2
    assert bld["ft"]["TOTAL_AREA"] == pytest.approx(bld["m"]["TOTAL_AREA"], rel=0.03)
    assert bld["ft"]["TOTAL_VOLUME"] == pytest.approx(bld["m"]["TOTAL_VOLUME"], rel=0.05)
    assert 50 < bld["m"]["TOTAL_AREA"] < 100 * 100                # m², not ft²
    for name in ("cls", "bld"):
        html = {k: (d / f"{name}_{k}.html").read_text(encoding="utf-8") for k in ("m", "ft")}
        assert "US survey foot" in html["ft"], name
        assert "US survey foot" not in html["m"], name

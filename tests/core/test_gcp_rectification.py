"""GCP polynomial rectification: golden numbers of the seed paper, synthetic recovery,
GDAL oracles (GCP transformer, gdalwarp -order N), QGIS .points round trip, pixel
convention and bad input."""
from __future__ import annotations

import hashlib
import json
import math
import os
import shutil
import subprocess

import numpy as np
import pytest

from geomatics_toolbox.core.errors import InputError
from geomatics_toolbox.core.io import gcp as gcp_io
from geomatics_toolbox.core.rectification import accuracy as gcp_report
from geomatics_toolbox.core.rectification import assess, export, polynomial, report, warp
from geomatics_toolbox.core.reporting import render_html
from geomatics_toolbox.synthetic import gcp as gcp_synthetic

gdal = pytest.importorskip("osgeo.gdal")
gdal.UseExceptions()

EPSG = "EPSG:22780"

IMAGE1_RES = np.array([float(t) for t in """
 1.17 -0.19 | -1.53  0.30 | -2.78 -3.38 |  2.62  0.66 |  0.30 -0.74 | -0.94  1.81 |  2.13  0.16
-0.35 -0.31 |  0.56 -0.09 |  2.26 -0.40 | -1.15 -0.75 |  1.14  1.10 |  1.66  3.56 | -2.08  1.14
-0.59  1.09 |  0.18 -1.67 | -0.76 -1.22 | -3.47 -0.19 |  2.48  2.05 | -2.91 -2.71 |  2.05 -0.21
""".replace("|", " ").split()]).reshape(-1, 2)

IMAGE2_RES = np.array([float(t) for t in """
-0.6058 7.015413 | 2.777543 -0.44833 | -2.62182 -1.3507 | -2.46768 -0.15583 | -0.26112 -0.6551
-0.55613 -1.7881 | -4.62027 0.847168 | -2.27356 -2.27125 | -7.36169 -2.51407 | 1.853832 -4.6648
-4.15917 -2.40171 | -3.06987 1.329226 | 1.06743 -1.98459 | 7.391539 -0.8632 | 3.9705 -2.73658
7.896014 6.968264 | 0.409602 4.025989 | -0.05641 4.124772 | -4.05932 -2.52847 | 3.910402 -0.21618
2.835983 0.268075
""".replace("|", " ").split()]).reshape(-1, 2)


def sha(path) -> str:
    with open(path, "rb") as fh:
        return hashlib.sha256(fh.read()).hexdigest()


def gdal_gcp_transform(pixel, map_xy, order, pts, *, width=5000, height=5000):
    """GDAL's GCP polynomial transformer (the oracle) applied to pixel points."""
    ds = gdal.GetDriverByName("MEM").Create("", width, height, 1)
    ds.SetGCPs([gdal.GCP(float(x), float(y), 0.0, float(c), float(r))
                for (c, r), (x, y) in zip(pixel, map_xy)], "")
    tr = gdal.Transformer(ds, None, ["METHOD=GCP_POLYNOMIAL", f"MAX_GCP_ORDER={order}"])
    out, ok = tr.TransformPoints(0, [(float(c), float(r)) for c, r in pts])
    assert all(ok)
    inv, ok2 = tr.TransformPoints(1, [(float(x), float(y)) for x, y in map_xy])
    return np.array(out)[:, :2], np.array(inv)[:, :2]


# ---------------------------------------------------------------------- golden numbers
def test_golden_image1_residuals():
    s = gcp_report.evaluate_residuals(IMAGE1_RES[:, 0], IMAGE1_RES[:, 1], gr=0.91,
                                      n_terms_per_axis=6)
    assert s.rms_t == pytest.approx(2.389, abs=5e-4)
    assert s.n_within == 15 and s.n == 21 and s.c6 and not s.c6_strict
    assert s.largest_id == "3"
    assert s.largest_rms == pytest.approx(4.38, abs=5e-3)
    assert s.largest_c == pytest.approx(1.83, abs=5e-3)
    assert s.scale == pytest.approx(18200)
    assert s.band == pytest.approx((3.64, 5.46))
    assert s.point_limit == pytest.approx(4.55)
    assert s.rms_i.max() < 4.5 and s.c5
    assert s.c4 == "strict" and s.verdict == "accepted"
    # QGIS Georeferencer divisor n - N (N = 6 for order 2)
    assert s.rms_t_qgis == pytest.approx(math.sqrt(np.sum(IMAGE1_RES ** 2) / (21 - 6)))


def test_golden_image2_residuals():
    ids = [str(i) for i in range(2, 23)]
    s = gcp_report.evaluate_residuals(IMAGE2_RES[:, 0], IMAGE2_RES[:, 1], ids=ids, gr=0.46,
                                      n_terms_per_axis=6)
    assert s.rms_t == pytest.approx(4.894, abs=5e-4)
    assert s.band == pytest.approx((1.84, 2.76))
    assert s.c4 == "rejected" and s.verdict == "rejected"
    assert s.largest_id == "17"
    assert s.largest_rms == pytest.approx(10.53, abs=5e-3)
    assert s.largest_c == pytest.approx(2.15, abs=5e-3)
    assert any(r.startswith("C4") for r in s.reasons())


# ---------------------------------------------------------------------- synthetic
@pytest.mark.parametrize("order", [1, 2, 3])
def test_synthetic_coefficients_come_back_exactly(order):
    pix, mp, (cx, cy), _ = gcp_synthetic.synthetic_gcps(order)
    m = polynomial.fit_polynomial(pix, mp, order=order)
    rx, ry = m.raw_coefficients()
    assert np.allclose(rx, cx, rtol=1e-6, atol=1e-9 * np.abs(cx).max())
    assert np.allclose(ry, cy, rtol=1e-6, atol=1e-9 * np.abs(cy).max())
    vx, vy = polynomial.residuals(m, pix, mp)
    assert np.abs(np.concatenate([vx, vy])).max() < 1e-6
    # and a higher-order fit finds (nearly) zero higher terms
    if order < 3:
        m3 = polynomial.fit_polynomial(pix, mp, order=3)
        hx, hy = m3.raw_coefficients()
        assert np.allclose(hx[:len(cx)], cx, rtol=1e-5, atol=1e-7)


@pytest.mark.parametrize("order", [1, 2, 3])
def test_synthetic_with_noise_residuals_match_noise(order):
    sigma = 0.5
    rms, pred_err = [], []
    for seed in range(20):
        pix, mp, (cx, cy), size = gcp_synthetic.synthetic_gcps(order, noise=sigma, seed=seed)
        m = polynomial.fit_polynomial(pix, mp, order=order)
        vx, vy = polynomial.residuals(m, pix, mp)
        rms.append(np.mean(vx ** 2 + vy ** 2) / 2)
        tx, ty = gcp_synthetic.eval_raw(cx, cy, pix[:, 0], pix[:, 1])
        fx, fy = m.forward(pix[:, 0], pix[:, 1])
        pred_err.append(np.hypot(fx - tx, fy - ty).max())
    n, nt = 22, polynomial.n_terms(order)
    # E[Σv²/n] = σ²(n − N)/n per axis
    assert math.sqrt(np.mean(rms)) == pytest.approx(sigma * math.sqrt((n - nt) / n), rel=0.12)
    assert max(pred_err) < 4 * sigma


def test_weights_equal_duplicated_points():
    pix, mp, _, _ = gcp_synthetic.synthetic_gcps(2, noise=1.0, seed=3)
    w = np.ones(len(pix))
    w[4] = 2.0
    mw = polynomial.fit_polynomial(pix, mp, order=2, weights=w)
    md = polynomial.fit_polynomial(np.vstack([pix, pix[4:5]]), np.vstack([mp, mp[4:5]]),
                                   order=2)
    grid = np.array([[100.0, 200.0], [3000.0, 2500.0]])
    assert np.allclose(mw.forward(grid[:, 0], grid[:, 1]), md.forward(grid[:, 0], grid[:, 1]),
                       atol=1e-6)


def test_leave_one_out_equals_brute_force_refit():
    pix, mp, _, _ = gcp_synthetic.synthetic_gcps(2, noise=1.0, seed=5)
    m = polynomial.fit_polynomial(pix, mp, order=2)
    lx, ly = polynomial.leave_one_out(m, pix, mp)
    for i in (0, 7, 21):
        keep = np.arange(len(pix)) != i
        mi = polynomial.fit_polynomial(pix[keep], mp[keep], order=2)
        px, py = mi.forward(pix[i:i + 1, 0], pix[i:i + 1, 1])
        assert lx[i] == pytest.approx(px[0] - mp[i, 0], abs=1e-6)
        assert ly[i] == pytest.approx(py[0] - mp[i, 1], abs=1e-6)


def test_inverse_is_consistent_with_forward():
    pix, mp, _, _ = gcp_synthetic.synthetic_gcps(3, noise=1.0, seed=1)
    m = polynomial.fit_polynomial(pix, mp, order=3)
    c = np.linspace(0, 3500, 9)
    r = np.linspace(0, 4400, 9)
    x, y = m.forward(c, r)
    ci, ri = m.inverse(x, y)
    assert np.abs(ci - c).max() < 1e-6 and np.abs(ri - r).max() < 1e-6


# ---------------------------------------------------------------------- GDAL oracles
@pytest.mark.parametrize("order", [1, 2, 3])
def test_forward_and_inverse_equal_gdal_gcp_transformer(order):
    pix, mp, _, _ = gcp_synthetic.synthetic_gcps(order, noise=1.5, seed=order)
    m = polynomial.fit_polynomial(pix, mp, order=order)
    g, ginv = gdal_gcp_transform(pix, mp, order, pix)
    fx, fy = m.forward(pix[:, 0], pix[:, 1])
    gr = m.pixel_size()
    assert np.abs(fx - g[:, 0]).max() <= 1e-6 * gr
    assert np.abs(fy - g[:, 1]).max() <= 1e-6 * gr
    # GDAL's inverse is a separately fitted polynomial; so is ours (before Newton)
    ic, ir = m.inverse_polynomial(mp[:, 0], mp[:, 1])
    assert np.abs(ic - ginv[:, 0]).max() <= 1e-6 and np.abs(ir - ginv[:, 1]).max() <= 1e-6


def _vrt_cli(src, pix, mp, dst):
    args = ["gdal_translate", "-q", "-of", "VRT", "-a_srs", EPSG]
    for (c, r), (x, y) in zip(pix, mp):
        args += ["-gcp", repr(float(c)), repr(float(r)), repr(float(x)), repr(float(y))]
    subprocess.run(args + [str(src), str(dst)], check=True)


@pytest.mark.skipif(shutil.which("gdalwarp") is None, reason="gdalwarp not installed")
@pytest.mark.parametrize("order, resampling", [(1, "near"), (2, "near"), (3, "near"),
                                               (2, "bilinear"), (3, "cubic")])
def test_warp_equals_gdalwarp_pixel_for_pixel(tmp_path, order, resampling):
    # A 1/8-scale image-1 set (GR 7.28 m) keeps the test small. The GCPs are rounded to
    # 1e-4 px and 1e-3 m because gdal_translate writes VRT GCPs with 4 decimals in pixel
    # and 13 significant digits in map units: unrounded GCPs would give the CLI oracle a
    # slightly different fit (an origin shift of ~1e-4 m) — not a difference of method.
    pix, mp, _, _ = gcp_synthetic.synthetic_gcps(order, noise=1.0, seed=7)
    pix = np.round(pix / 8.0, 4)
    mp = np.round(mp, 3)
    w, h = int(pix[:, 0].max() + 20), int(pix[:, 1].max() + 20)
    img = gcp_synthetic.write_test_image(tmp_path / "in.tif", w, h, bands=2)
    before = sha(img)
    g = gcp_io.make_gcps(None, pix, mp, crs=EPSG)
    out = tmp_path / "ours.tif"
    res = warp.rectify(img, g, out, order=order, resampling=resampling)
    _vrt_cli(img, pix, mp, tmp_path / "g.vrt")
    ref = tmp_path / "ref.tif"
    subprocess.run(["gdalwarp", "-q", "-order", str(order), "-r", resampling, "-tr",
                    repr(res.resolution), repr(res.resolution), str(tmp_path / "g.vrt"),
                    str(ref)], check=True)
    a, b = gdal.Open(str(out)), gdal.Open(str(ref))
    assert (a.RasterXSize, a.RasterYSize, a.RasterCount) == (b.RasterXSize, b.RasterYSize,
                                                             b.RasterCount)
    assert np.allclose(a.GetGeoTransform(), b.GetGeoTransform(), rtol=0, atol=1e-6)
    assert np.array_equal(a.ReadAsArray(), b.ReadAsArray())
    assert sha(img) == before
    assert res.resolution == pytest.approx(warp.ground_resolution(g))
    assert sorted(os.listdir(tmp_path)) == ["g.vrt", "in.tif", "ours.tif", "ref.tif"]


def test_pixel_convention_corner_and_rows_down(tmp_path):
    """GCPs taken from a known geotransform in the corner convention reproduce it
    exactly; warping back onto the same grid reproduces the image pixel for pixel (a
    half-pixel or row-sign error would shift or flip it)."""
    w, h = 64, 48
    gt = (500000.0, 2.0, 0.0, 4000000.0, 0.0, -2.0)
    img = gcp_synthetic.write_test_image(tmp_path / "src.tif", w, h)
    # corners and a few interior points, in the corner convention
    pix = np.array([[0, 0], [w, 0], [0, h], [w, h], [16, 8], [40, 30], [8.5, 40.5]], float)
    mp = np.column_stack([gt[0] + pix[:, 0] * gt[1], gt[3] + pix[:, 1] * gt[5]])
    # written as the QGIS Georeferencer does: pixelY = -row
    pts = tmp_path / "src.tif.points"
    pts.write_text(gcp_io.points_text(gcp_io.make_gcps(None, pix, mp), crs_wkt="EPSG:32637"))
    assert all(float(line.split(",")[3]) <= 0 for line in pts.read_text().splitlines()[2:])
    g = gcp_io.read_points(pts)
    assert np.allclose(g.pixel, pix)
    m = polynomial.fit_polynomial(g.pixel, g.map, order=1)
    x, y = m.forward(np.array([0.5]), np.array([0.5]))  # centre of the first pixel
    assert (x[0], y[0]) == pytest.approx((gt[0] + 1.0, gt[3] - 1.0))
    out = tmp_path / "back.tif"
    warp.rectify(img, g, out, order=1, resolution=2.0, error_threshold=0)
    o = gdal.Open(str(out))
    assert o.GetGeoTransform() == pytest.approx(gt)
    assert np.array_equal(o.ReadAsArray(), gdal.Open(img).ReadAsArray())


# ---------------------------------------------------------------------- .points files
QGIS_WKT = ('PROJCRS["Deir ez Zor / Levant Stereographic",BASEGEOGCRS["Deir ez Zor",'
            'DATUM["Deir ez Zor",ELLIPSOID["Clarke 1880 (IGN)",6378249.2,293.466021293627,'
            'LENGTHUNIT["metre",1]]],PRIMEM["Greenwich",0,ANGLEUNIT["degree",'
            '0.0174532925199433]],ID["EPSG",4227]],CONVERSION["Levant Stereographic",'
            'METHOD["Oblique Stereographic",ID["EPSG",9809]],PARAMETER["Latitude of natural '
            'origin",38,ANGLEUNIT["grad",0.0157079632679489],ID["EPSG",8801]],PARAMETER['
            '"Longitude of natural origin",43.5,ANGLEUNIT["grad",0.0157079632679489],ID["EPSG",'
            '8802]],PARAMETER["Scale factor at natural origin",0.9995341,SCALEUNIT["unity",1],'
            'ID["EPSG",8805]],PARAMETER["False easting",0,LENGTHUNIT["metre",1],ID["EPSG",8806]'
            '],PARAMETER["False northing",0,LENGTHUNIT["metre",1],ID["EPSG",8807]]],CS['
            'Cartesian,2],AXIS["easting (X)",east,ORDER[1],LENGTHUNIT["metre",1]],AXIS['
            '"northing (Y)",north,ORDER[2],LENGTHUNIT["metre",1]],USAGE[SCOPE["unknown"],'
            'AREA["Syria"],BBOX[32.31,35.61,37.3,42.38]],ID["EPSG",22780]]')


def georeferencer_points_file(path, pix, mp, enabled=None, header="pixelX,pixelY"):
    """A .points file exactly as QGIS 3.22's Georeferencer saves it
    (QgsGeoreferencerMainWindow::saveGCPs: '#CRS: ' + WKT, the header, then
    qgsDoubleToString values with pixelY = -row and the residual columns)."""
    lines = [f"#CRS: {QGIS_WKT}", f"mapX,mapY,{header},enable,dX,dY,residual"]
    en = np.ones(len(pix), int) if enabled is None else enabled
    for (c, r), (x, y), e in zip(pix, mp, en):
        lines.append(f"{x:.10g},{y:.10g},{c:.10g},{-r:.10g},{e},0.1,-0.2,0.2236")
    path.write_text("\n".join(lines) + "\n")
    return path


@pytest.mark.parametrize("header", ["pixelX,pixelY", "sourceX,sourceY"])
def test_points_file_round_trip_and_qgis_mean_error(tmp_path, header):
    pix, mp, _, size = gcp_synthetic.synthetic_gcps(2, noise=1.2, seed=11)
    pix = np.round(pix, 3)
    mp = np.round(mp, 2)
    en = np.ones(22, int)
    en[5] = 0
    f = georeferencer_points_file(tmp_path / "img.tif.points", pix, mp, en, header)
    g = gcp_io.read_gcps(f)
    assert len(g) == 22 and g.ids[0] == "1" and not g.enabled[5]
    assert np.allclose(g.pixel, pix) and np.allclose(g.map, mp)
    assert "22780" in g.crs and g.qgis_residuals.shape == (22, 3)
    acc = gcp_report.evaluate_gcps(g, order=2, image_size=size)
    s = acc.selected.stats
    assert s.n == 21
    # the Georeferencer's formula (calculateMeanError) applied to oracle residuals
    keep = en == 1
    gx, _ = gdal_gcp_transform(pix[keep], mp[keep], 2, pix[keep])
    vx, vy = gx[:, 0] - mp[keep, 0], gx[:, 1] - mp[keep, 1]
    qgis_mean_error = math.sqrt((np.sum(vx ** 2) + np.sum(vy ** 2)) / (21 - 6))
    assert s.rms_t_qgis == pytest.approx(qgis_mean_error, rel=1e-9)
    assert s.rms_t == pytest.approx(math.sqrt((np.sum(vx ** 2) + np.sum(vy ** 2)) / 21),
                                    rel=1e-9)
    # write -> read keeps everything
    again = tmp_path / "again.points"
    again.write_text(gcp_io.points_text(g))
    g2 = gcp_io.read_points(again)
    assert np.array_equal(g2.pixel, g.pixel) and np.array_equal(g2.map, g.map)
    assert np.array_equal(g2.enabled, g.enabled) and g2.crs == g.crs


def test_points_file_with_layer_coordinates_of_a_georeferenced_image(tmp_path):
    """QGIS >= 3.26 stores source-layer coordinates in sourceX/sourceY; with the image's
    geotransform they become pixel/line."""
    gt = (1000.0, 0.5, 0.0, 2000.0, 0.0, -0.5)
    pix = np.array([[0, 0], [10, 4], [3, 8]], float)
    src = np.column_stack([gt[0] + pix[:, 0] * gt[1], gt[3] + pix[:, 1] * gt[5]])
    f = tmp_path / "geo.points"
    f.write_text("#CRS: EPSG:32637\nmapX,mapY,sourceX,sourceY,enable,dX,dY,residual\n"
                 + "".join(f"{i},{i},{x},{y},1,0,0,0\n" for i, (x, y) in enumerate(src)))
    g = gcp_io.read_points(f, source_geotransform=gt)
    assert np.allclose(g.pixel, pix)


def test_old_tab_separated_points_file(tmp_path):
    f = tmp_path / "old.points"
    f.write_text("mapX\tmapY\tpixelX\tpixelY\n10\t20\t1\t-2\n30\t20\t5\t-2\n10\t5\t1\t-9\n")
    g = gcp_io.read_gcps(f, crs=EPSG)
    assert np.allclose(g.pixel, [[1, 2], [5, 2], [1, 9]]) and g.crs == EPSG


# ---------------------------------------------------------------------- CSV
def test_csv_conventions(tmp_path):
    base = "id,col,row,X,Y,role\nA,10,20,100,200,gcp\nB,30.5,40,300,400,check\n"
    (tmp_path / "a.csv").write_text(base)
    a = gcp_io.read_csv(tmp_path / "a.csv", crs=EPSG)
    assert a.ids == ["A", "B"] and np.allclose(a.pixel, [[10, 20], [30.5, 40]])
    assert list(a.role) == ["gcp", "check"] and a.crs == EPSG
    c = gcp_io.read_csv(tmp_path / "a.csv", pixel_origin="center")
    assert np.allclose(c.pixel, [[10.5, 20.5], [31, 40.5]])
    (tmp_path / "q.csv").write_text("name;image_x;image_y;easting;northing;enabled\n"
                                    "p1;10;-20;100;200;1\np2;30;-40;300;400;0\n")
    q = gcp_io.read_csv(tmp_path / "q.csv")
    assert np.allclose(q.pixel, [[10, 20], [30, 40]]) and list(q.enabled) == [True, False]
    (tmp_path / "p.csv").write_text("# CRS: EPSG:32637\nid,pixel,line,map_x,map_y,weight\n"
                                    "1,1,2,3,4,0.5\n")
    p = gcp_io.read_gcps(tmp_path / "p.csv")
    assert p.crs == "EPSG:32637" and p.weight.tolist() == [0.5]
    back = tmp_path / "back.csv"
    back.write_text(gcp_io.gcps_csv_text(a))
    b = gcp_io.read_csv(back)
    assert b.ids == a.ids and np.array_equal(b.pixel, a.pixel) and list(b.role) == ["gcp",
                                                                                   "check"]


# ---------------------------------------------------------------------- report
def _image1_gcps(order=2, noise=1.0, seed=0, n_check=0):
    pix, mp, _, size = gcp_synthetic.synthetic_gcps(order, noise=noise, seed=seed)
    role = ["gcp"] * len(pix)
    for k in range(n_check):
        role[3 * k + 1] = "check"
    return gcp_io.make_gcps(None, pix, mp, role=role, crs=EPSG), size


def test_report_orders_side_by_side_and_outputs():
    g, size = _image1_gcps(order=2, noise=1.0, seed=2, n_check=4)
    acc = gcp_report.evaluate_gcps(g, order=2, gr=gcp_synthetic.IMAGE1_GR, image_size=size)
    assert set(acc.results) == {1, 2, 3}
    assert acc.selected.n_gcps == 18 and acc.selected.check.n == 4
    # 18 GCPs: order 3 (N = 10) has redundancy 8 >= 5, supported; the data are order 2
    assert acc.recommended in (2, 3)
    for r in acc.results.values():
        assert r.ok and r.loo_rms is not None
    assert acc.results[1].loo_rms > acc.results[2].loo_rms  # order 1 misses the curvature
    html = render_html(report.build_report(
        assess.assess_gcps(g, kind="polynomial2", gr=gcp_synthetic.IMAGE1_GR,
                           image_size=size)))
    for text in ("RMS_T", "n − N", "C6", "<svg", "orders 1, 2, 3", "check points",
                 "Tishreen", 'id="residual-vectors"', 'id="transform-comparison"'):
        assert text in html
    rows = export.to_csv(acc).splitlines()
    assert len(rows) == 23 and rows[0].startswith("id,role,enabled,col,row")
    d = json.loads(export.to_json(acc))
    assert d["orders"]["2"]["fit"]["rms_t"] == pytest.approx(acc.selected.stats.rms_t)
    assert d["recommended_order"] == acc.recommended


def test_check_points_are_kept_out_of_the_fit():
    g, size = _image1_gcps(order=2, noise=1.0, seed=4, n_check=3)
    a = gcp_report.evaluate_gcps(g, order=2, image_size=size)
    g.map[g.check_mask] += 50.0  # corrupt only the check points
    b = gcp_report.evaluate_gcps(g, order=2, image_size=size)
    assert a.selected.stats.rms_t == pytest.approx(b.selected.stats.rms_t, rel=1e-12)
    assert b.selected.check.rms_t > 60


def test_recommendation_never_exceeds_redundancy():
    pix, mp, _, size = gcp_synthetic.synthetic_gcps(3, noise=0.3, seed=1)
    g = gcp_io.make_gcps(None, pix[:12], mp[:12], crs=EPSG)
    acc = gcp_report.evaluate_gcps(g, order=2, image_size=size)
    assert acc.results[3].ok and not acc.results[3].supported  # 12 - 10 = 2 < 5
    assert acc.recommended in (1, 2)
    g8 = gcp_io.make_gcps(None, pix[:7], mp[:7], crs=EPSG)
    acc8 = gcp_report.evaluate_gcps(g8, order=1, image_size=size)
    assert not acc8.results[3].ok and "at least 10" in acc8.results[3].error
    assert acc8.recommended in (None, 1)


def test_suggested_drops_and_radial_bias():
    pix, mp, _, size = gcp_synthetic.synthetic_gcps(1, noise=0.3, seed=8)
    mp = mp.copy()
    mp[6] += (9.0, -7.0)  # a blunder
    g = gcp_io.make_gcps(None, pix, mp, crs=EPSG)
    acc = gcp_report.evaluate_gcps(g, order=1, gr=0.91, image_size=size)
    s = acc.selected.stats
    assert s.largest_id == "7" and not s.c5
    assert acc.selected.drops[0]["id"] == "7"
    assert acc.selected.drops[0]["rms_t_after"] < 0.6
    # radial distortion fitted with order 1: residuals inwards inside, outwards at edges
    c0 = np.array(size) / 2
    d = pix - c0
    r2 = (d ** 2).sum(axis=1) / (c0 ** 2).sum()
    mp2 = np.column_stack([-308000 + 0.91 * pix[:, 0], 156000 - 0.91 * pix[:, 1]])
    mp2 += 0.91 * d * np.array([1, -1]) * (0.1 * r2)[:, None]  # up to ~170 m at corners
    g2 = gcp_io.make_gcps(None, pix, mp2, crs=EPSG)
    b = gcp_report.evaluate_gcps(g2, order=1, image_size=size).selected.stats
    assert b.c7 is False and any("radial" in f for f in b.bias["flags"])
    b3 = gcp_report.evaluate_gcps(g2, order=3, image_size=size).selected.stats
    assert b3.rms_t < 0.2 * b.rms_t


def test_coverage_warning_for_gcps_in_one_corner():
    pix, mp, _, size = gcp_synthetic.synthetic_gcps(1, noise=0.3, seed=2)
    g = gcp_io.make_gcps(None, pix, mp, crs=EPSG)
    full = gcp_report.evaluate_gcps(g, order=1, image_size=size)
    assert not any("cover only" in n for n in full.notes)
    assert gcp_report.coverage(pix, size) > 0.5
    small = gcp_report.evaluate_gcps(g, order=1, image_size=(size[0] * 3, size[1] * 3))
    assert any("cover only" in n for n in small.notes)


def test_bias_checks_rarely_flag_pure_noise():
    flagged = 0
    for seed in range(40):
        g, size = _image1_gcps(order=2, noise=1.0, seed=100 + seed)
        s = gcp_report.evaluate_gcps(g, order=2, orders=(2,), image_size=size).selected.stats
        flagged += s.c7 is False
    assert flagged <= 8, flagged


# ---------------------------------------------------------------------- bad input
def test_too_few_gcps_for_order():
    pix, mp, _, _ = gcp_synthetic.synthetic_gcps(1)
    with pytest.raises(ValueError, match="at least 6 enabled GCPs"):
        polynomial.fit_polynomial(pix[:5], mp[:5], order=2)
    with pytest.raises(ValueError, match="order must be 1, 2 or 3"):
        polynomial.fit_polynomial(pix, mp, order=4)


def test_collinear_and_clustered_gcps_refused():
    t = np.linspace(0, 1000, 8)
    pix = np.column_stack([t, 0.5 * t + 10])
    mp = np.column_stack([t * 2, t * 3])
    with pytest.raises(polynomial.IllConditionedError, match="collinear"):
        polynomial.fit_polynomial(pix, mp, order=1)
    pix2 = np.array([[0, 0], [1000, 0], [0, 1000], [500, 500], [500.0001, 500],
                     [500, 500.0001], [500.0001, 500.0001]])
    mp2 = pix2 * 2.0
    with pytest.raises(polynomial.IllConditionedError, match="clustered"):
        polynomial.fit_polynomial(pix2, mp2, order=2)


def test_duplicate_ids_non_numeric_and_outside(tmp_path):
    (tmp_path / "d.csv").write_text("id,col,row,X,Y\n1,1,2,3,4\n2,5,6,7,8\n1,9,9,9,9\n")
    with pytest.raises(ValueError, match="Duplicate GCP ids.*1"):
        gcp_io.read_csv(tmp_path / "d.csv")
    (tmp_path / "n.csv").write_text("id,col,row,X,Y\n1,1,2,3,4\n2,5,six,7,8\n")
    with pytest.raises(ValueError, match="row 3: column 'row' must be a number, got 'six'"):
        gcp_io.read_csv(tmp_path / "n.csv")
    (tmp_path / "m.csv").write_text("id,a,b,X,Y\n1,1,2,3,4\n")
    with pytest.raises(ValueError, match="no image coordinate columns"):
        gcp_io.read_csv(tmp_path / "m.csv")
    (tmp_path / "p.points").write_text("#CRS: EPSG:32637\nmapX,mapY,pixelX,pixelY,enable\n"
                                       "1,2,3,abc,1\n")
    with pytest.raises(ValueError, match="line 3: column 'pixelY'"):
        gcp_io.read_points(tmp_path / "p.points")
    g = gcp_io.make_gcps(None, [[1, 1], [120, 5], [5, -3]], [[0, 0], [1, 0], [0, 1]])
    with pytest.raises(ValueError, match=r"outside the image.*2 \(col 120.*3 \(col 5, row -3"):
        gcp_io.check_in_image(g, 100, 80)


def _failing_rectify(tmp_path, gcps, **kw):
    img = tmp_path / "in.tif"
    if not img.exists():
        gcp_synthetic.write_test_image(img, 120, 90)
    before = sha(img)
    out = tmp_path / "out" / "rect.tif"
    with pytest.raises(ValueError) as err:
        warp.rectify(img, gcps, out, **kw)
    assert sha(img) == before
    left = [p for p in tmp_path.rglob("*") if p.is_file() and p.name != "in.tif"]
    assert left == [], left
    return str(err.value)


def test_bad_input_to_rectify_writes_nothing(tmp_path):
    pix = np.array([[10, 10], [100, 12], [15, 80], [90, 85], [50, 40], [30, 60]], float)
    mp = pix * [2.0, -2.0] + [500000, 4000000]
    ok = gcp_io.make_gcps(None, pix, mp, crs="EPSG:32637")
    assert "no CRS" in _failing_rectify(tmp_path, ok.with_crs(""), order=1)
    assert "at least 10" in _failing_rectify(tmp_path, ok, order=3)
    col = gcp_io.make_gcps(None, [[10, 10], [20, 20], [30, 30], [40, 40]],
                           [[0, 0], [1, 1], [2, 2], [3, 3]], crs="EPSG:32637")
    assert "collinear" in _failing_rectify(tmp_path, col, order=1)
    out = gcp_io.make_gcps(None, np.vstack([pix, [[130, 10]]]), np.vstack([mp, [[0, 0]]]),
                           crs="EPSG:32637")
    assert "outside the image" in _failing_rectify(tmp_path, out, order=1)
    assert "resampling" in _failing_rectify(tmp_path, ok, order=1, resampling="nearest")
    img = tmp_path / "in.tif"
    with pytest.raises(ValueError, match="same file as the input"):
        warp.rectify(img, ok, img, order=1)


def test_cancel_leaves_nothing(tmp_path):
    from geomatics_toolbox.core.progress import Cancelled
    img = gcp_synthetic.write_test_image(tmp_path / "in.tif", 300, 200)
    pix = np.array([[10, 10], [290, 12], [15, 190], [280, 185], [150, 100]], float)
    g = gcp_io.make_gcps(None, pix, pix * [1.0, -1.0] + [500000, 4000000], crs="EPSG:32637")
    calls = []
    with pytest.raises(Cancelled):
        warp.rectify(img, g, tmp_path / "o.tif", order=1,
                     cancel=lambda: calls.append(1) or len(calls) > 2)
    assert sorted(p.name for p in tmp_path.iterdir()) == ["in.tif"]


def test_identical_map_coordinates_refused_naming_points():
    from geomatics_toolbox.core.errors import InputError
    pix = [[0, 0], [10, 0], [0, 10], [10, 10]]
    mp = [[5, 5], [15, 5], [5, 5], [15, 15]]
    with pytest.raises(InputError, match=r"a, c at X = 5, Y = 5"):
        gcp_io.make_gcps(["a", "b", "c", "d"], pix, mp)
    # a disabled duplicate is ignored
    g = gcp_io.make_gcps(["a", "b", "c", "d"], pix, mp, enabled=[1, 1, 0, 1])
    assert len(g) == 4


def test_collinear_map_coordinates_clear_error_not_gr():
    from geomatics_toolbox.core.errors import InputError
    pix = [[0, 0], [10, 0], [0, 10], [10, 10], [5, 3]]
    mp = [[0, 0], [1, 1], [2, 2], [3, 3], [4, 4]]
    g = gcp_io.make_gcps(None, pix, mp, crs="EPSG:22780")
    with pytest.raises(InputError, match="do not span an area"):
        gcp_report.evaluate_gcps(g, order=1)


@pytest.mark.parametrize("lang", ["ar", "fa"])
def test_ill_conditioned_messages_are_translated(lang):
    """The degenerate-geometry messages are templates with ar/fa translations."""
    from geomatics_toolbox.core.reporting.i18n import translator
    tr = translator(lang)
    for template in polynomial.ILL_CONDITIONED.values():
        assert tr(template) != template, template
    pix = np.column_stack([np.linspace(0, 1000, 8), np.linspace(0, 500, 8)])   # a line
    with pytest.raises(polynomial.IllConditionedError) as err:
        polynomial.fit_polynomial(pix, pix * 2.0, order=1)
    assert err.value.template == polynomial.ILL_CONDITIONED["collinear"]
    assert isinstance(err.value, InputError) and "collinear" in str(err.value)


def test_failed_fit_reaches_the_user_as_its_own_template():
    """assess_gcps re-raises the fit's InputError (translatable), not a bare string."""
    n = 8
    pix = np.column_stack([np.linspace(0, 1000, n), np.linspace(0, 500, n)])  # a line
    g = gcp_io.make_gcps([f"p{i}" for i in range(n)], pix, pix * 2.0 + 100.0)
    with pytest.raises(polynomial.IllConditionedError) as err:
        assess.assess_gcps(g, kind="polynomial1", gr=2.0, refine=False)
    assert err.value.template == polynomial.ILL_CONDITIONED["collinear"]

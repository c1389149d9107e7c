"""Transformations of the Georeferencer and gdalwarp: known parameters, oracles, ranking."""
from __future__ import annotations

import numpy as np
import pytest
import skimage.transform as skt  # noqa: E402  test-only oracle (requirements-dev.txt)
from osgeo import gdal  # noqa: E402

from geomatics_toolbox.core.errors import InputError
from geomatics_toolbox.core.io import gcp as gcp_io
from geomatics_toolbox.core.rectification import compare, transforms
from geomatics_toolbox.synthetic import gcp as gcp_synthetic

GR = gcp_synthetic.IMAGE1_GR
TOL = 1e-6 * GR  # "≤ 1e-6 of the pixel size"


def _grid(size, n=15):
    c, r = np.meshgrid(np.linspace(0, size[0], n), np.linspace(0, size[1], n))
    return c.ravel(), r.ravel()


def test_linear_recovers_shift_and_scale():
    pix, mp, truth, _ = gcp_synthetic.transformed_gcps("linear")
    t = transforms.fit_transform("linear", pix, mp)
    assert t.parameters() == pytest.approx(truth, rel=1e-12, abs=1e-6)
    assert t.min_points == 2 and t.n_parameters == 4


def test_helmert_recovers_scale_rotation_shift_and_equals_skimage():
    pix, mp, truth, size = gcp_synthetic.transformed_gcps("helmert")
    t = transforms.fit_transform("helmert", pix, mp)
    assert t.parameters() == pytest.approx(truth, rel=1e-10, abs=1e-6)
    pix, mp, _, _ = gcp_synthetic.transformed_gcps("helmert", noise=1.0, seed=4)
    t = transforms.fit_transform("helmert", pix, mp)
    sk = skt.SimilarityTransform()
    assert sk.estimate(np.column_stack([pix[:, 0], -pix[:, 1]]), mp)
    c, r = _grid(size)
    x, y = t.forward(c, r)
    o = sk(np.column_stack([c, -r]))
    assert np.abs(x - o[:, 0]).max() <= TOL and np.abs(y - o[:, 1]).max() <= TOL
    assert t.parameters()["scale"] == pytest.approx(sk.scale, rel=1e-12)
    assert t.parameters()["rotation_deg"] == pytest.approx(np.degrees(sk.rotation),
                                                           rel=1e-9)


def test_projective_recovers_matrix_and_equals_skimage():
    pix, mp, truth, size = gcp_synthetic.transformed_gcps("projective")
    t = transforms.fit_transform("projective", pix, mp)
    assert np.allclose(t.parameters()["matrix"], truth, rtol=1e-7, atol=1e-12)
    pix, mp, _, _ = gcp_synthetic.transformed_gcps("projective", noise=1.0, seed=2)
    t = transforms.fit_transform("projective", pix, mp)
    sk = skt.ProjectiveTransform()
    assert sk.estimate(pix, mp)
    c, r = _grid(size)
    x, y = t.forward(c, r)
    o = sk(np.column_stack([c, r]))
    assert np.abs(x - o[:, 0]).max() <= TOL and np.abs(y - o[:, 1]).max() <= TOL
    cc, rr = t.inverse(x, y)
    assert np.abs(cc - c).max() < 1e-6 and np.abs(rr - r).max() < 1e-6


def _gdal_transformer(pix, mp, options):
    ds = gdal.GetDriverByName("MEM").Create("", 10, 10)
    ds.SetGCPs([gdal.GCP(float(x), float(y), 0.0, float(c), float(r))
                for (c, r), (x, y) in zip(pix, mp)], "")
    return gdal.Transformer(ds, None, options), ds


@pytest.mark.parametrize("kind, options", [
    ("polynomial1", ["METHOD=GCP_POLYNOMIAL", "MAX_GCP_ORDER=1"]),
    ("polynomial2", ["METHOD=GCP_POLYNOMIAL", "MAX_GCP_ORDER=2"]),
    ("polynomial3", ["METHOD=GCP_POLYNOMIAL", "MAX_GCP_ORDER=3"]),
    ("tps", ["METHOD=GCP_TPS"])])
def test_polynomial_and_tps_equal_gdal_transformer(kind, options):
    pix, mp, _, size = gcp_synthetic.transformed_gcps("polynomial2", noise=1.0, seed=7)
    t = transforms.fit_transform(kind, pix, mp)
    tr, _ds = _gdal_transformer(pix, mp, options)
    c, r = _grid(size)
    o = np.array(tr.TransformPoints(0, list(zip(c.tolist(), r.tolist())))[0])
    x, y = t.forward(c, r)
    assert np.abs(x - o[:, 0]).max() <= TOL and np.abs(y - o[:, 1]).max() <= TOL
    if kind == "tps":  # the inverse is the GDAL in use's (exact from 3.8 on)
        back = np.array(tr.TransformPoints(1, o[:, :2].tolist())[0])
        cc, rr = t.inverse(o[:, 0], o[:, 1])
        assert np.abs(cc - back[:, 0]).max() < 1e-6 and np.abs(rr - back[:, 1]).max() < 1e-6
        vx, vy = t.residuals(pix, mp)
        assert np.abs(vx).max() < 1e-6 and np.abs(vy).max() < 1e-6


def test_tps_inverse_is_the_gdal_in_use():
    """GDAL ≥ 3.8 inverts its spline exactly, older GDAL fits a map → image spline.

    The two inverses are ~0.01 px apart between GCPs, so only the mode GDAL uses
    agrees with GDAL's own transformer to 1e-6 px, away from the GCPs too.
    """
    pix, mp, _, size = gcp_synthetic.transformed_gcps("polynomial2", noise=1.0, seed=7)
    tr, _ds = _gdal_transformer(pix, mp, ["METHOD=GCP_TPS"])
    c, r = _grid(size, n=23)
    x, y = transforms.fit_tps(pix, mp).forward(c, r)
    gdal_back = np.array(tr.TransformPoints(1, list(zip(x.tolist(), y.tolist())))[0])
    gdal_exact = np.abs(gdal_back[:, 0] - c).max() < 1e-6
    assert transforms.gdal_inverts_tps_exactly() == gdal_exact == (
        int(gdal.VersionInfo("VERSION_NUM")) >= 3080000)
    gaps = {}
    for exact in (True, False):
        t = transforms.fit_tps(pix, mp, exact_inverse=exact)
        cc, rr = t.inverse(x, y)
        gaps[exact] = max(np.abs(cc - gdal_back[:, 0]).max(),
                          np.abs(rr - gdal_back[:, 1]).max())
        if exact:  # forward(inverse(p)) == p
            assert np.abs(cc - c).max() < 1e-6 and np.abs(rr - r).max() < 1e-6
    assert gaps[gdal_exact] < 1e-6
    assert gaps[not gdal_exact] > 1e-3, gaps  # the other mode is measurably different


@pytest.mark.parametrize("kind, pix, message", [
    ("linear", [[5, 0], [5, 10], [5, 20]], "one image column"),
    ("helmert", [[5, 5], [5, 5], [5, 5]], "one image position"),
    ("projective", [[0, 0], [1, 1], [2, 2], [3, 3], [0, 5]], "collinear"),
    ("tps", [[0, 0], [1, 1], [2, 2], [3, 3]], "collinear"),
    ("tps", [[0, 0], [0, 0], [2, 5], [3, 1]], "share one image position"),
    ("polynomial2", [[0, 0], [1, 1], [2, 2], [3, 3], [4, 4], [5, 5]], "collinear"),
    ("projective", [[0, 0], [1, 0], [0, 1]], "at least 4"),
])
def test_degenerate_sets_refused_with_reason(kind, pix, message):
    pix = np.asarray(pix, float)
    mp = pix * 2.0 + [100.0, 200.0]
    with pytest.raises(InputError, match=message):
        transforms.fit_transform(kind, pix, mp)


def test_min_points_reported():
    assert {k: transforms.MIN_POINTS[k] for k in transforms.KINDS} == {
        "linear": 2, "helmert": 2, "polynomial1": 3, "polynomial2": 6, "polynomial3": 10,
        "projective": 4, "tps": 3}


def test_loo_of_polynomial_equals_brute_force_refit():
    pix, mp, _, _ = gcp_synthetic.transformed_gcps("polynomial2", noise=1.0, seed=1)
    lx, ly = transforms.loo_residuals("polynomial2", pix, mp)
    for i in (0, 7, 21):
        keep = np.arange(len(pix)) != i
        t = transforms.fit_transform("polynomial2", pix[keep], mp[keep])
        vx, vy = t.residuals(pix[i:i + 1], mp[i:i + 1])
        assert lx[i] == pytest.approx(vx[0], abs=1e-7)
        assert ly[i] == pytest.approx(vy[0], abs=1e-7)


@pytest.mark.parametrize("truth, noise", [("helmert", 0.5), ("projective", 0.5),
                                          ("polynomial2", 0.5), ("polynomial3", 0.1)])
def test_report_picks_the_true_model_by_loo(truth, noise):
    """Image-1 coordinates through a known distortion plus noise.

    The cubic terms of the synthetic order-3 model move points by a few metres, which
    22 GCPs with 0.5 m noise cannot tell from order 2 by LOO (order 2 then honestly
    wins); with 0.1 m noise order 3 is detectable.
    """
    pix, mp, _, size = gcp_synthetic.transformed_gcps(truth, noise=noise, seed=11)
    g = gcp_io.make_gcps(None, pix, mp, crs="EPSG:22780")
    cmp_ = compare.compare_transforms(g, gr=GR, image_size=size)
    assert cmp_.basis == "loo"
    assert cmp_.recommended == truth, cmp_.reason
    tps = cmp_.results["tps"]
    assert tps.fit.rms_t < 1e-6 and tps.loo.rms_t > 0.3  # judged on LOO, not on fit
    assert cmp_.ranking()[0] in (truth, "polynomial3", "polynomial2", "projective")


def test_check_points_decide_when_present():
    pix, mp, _, size = gcp_synthetic.transformed_gcps("projective", noise=0.5, seed=3)
    role = ["check" if k % 4 == 0 else "gcp" for k in range(len(pix))]
    g = gcp_io.make_gcps(None, pix, mp, role=role, crs="EPSG:22780")
    cmp_ = compare.compare_transforms(g, gr=GR, image_size=size)
    assert cmp_.basis == "check"
    assert cmp_.results["linear"].check.rms_t > 10 * cmp_.results["projective"].check.rms_t
    assert cmp_.recommended == "projective"


def test_refine_drops_the_blunders_and_stops():
    pix, mp, _, _ = gcp_synthetic.transformed_gcps("helmert", noise=0.3, seed=5)
    mp = mp.copy()
    mp[3, 0] += 40.0
    mp[17, 1] -= 25.0
    ids = [f"P{k + 1}" for k in range(len(pix))]
    keep, dropped = compare.refine_gcps("helmert", pix, mp, ids,
                                        tolerance=compare.c5_limit(GR))
    assert [d["id"] for d in dropped] == ["P4", "P18"]
    assert keep.sum() == 20 and dropped[-1]["n_after"] == 20
    keep, dropped = compare.refine_gcps("helmert", pix, mp, ids, tolerance=1e-3,
                                        min_count=15)
    assert keep.sum() == 15 and len(dropped) == 7


# ---------------------------------------------------------------------- warps
def _small_case(tmp_path, truth, seed=7):
    import subprocess  # noqa: F401 - used by callers through the module
    pix, mp, _, _ = gcp_synthetic.transformed_gcps(truth, noise=1.0, seed=seed)
    pix = np.round(pix / 8.0, 4)  # gdal_translate keeps 4 decimals of pixel GCPs
    mp = np.round(mp, 3)
    w, h = int(pix[:, 0].max() + 20), int(pix[:, 1].max() + 20)
    img = gcp_synthetic.write_test_image(tmp_path / "in.tif", w, h, bands=1)
    return img, pix, mp


@pytest.mark.skipif(__import__("shutil").which("gdalwarp") is None,
                    reason="gdalwarp not installed")
@pytest.mark.parametrize("resampling", ["near", "bilinear"])
def test_tps_warp_equals_gdalwarp_tps_pixel_for_pixel(tmp_path, resampling):
    import subprocess

    from geomatics_toolbox.core.rectification import warp
    img, pix, mp = _small_case(tmp_path, "polynomial2")
    g = gcp_io.make_gcps(None, pix, mp, crs="EPSG:22780")
    res = warp.rectify(img, g, tmp_path / "ours.tif", kind="tps", resampling=resampling)
    args = ["gdal_translate", "-q", "-of", "VRT", "-a_srs", "EPSG:22780"]
    for (c, r), (x, y) in zip(pix, mp):
        args += ["-gcp", repr(float(c)), repr(float(r)), repr(float(x)), repr(float(y))]
    subprocess.run(args + [str(img), str(tmp_path / "g.vrt")], check=True)
    subprocess.run(["gdalwarp", "-q", "-tps", "-r", resampling, "-tr", repr(res.resolution),
                    repr(res.resolution), str(tmp_path / "g.vrt"), str(tmp_path / "ref.tif")],
                   check=True)
    a, b = gdal.Open(str(tmp_path / "ours.tif")), gdal.Open(str(tmp_path / "ref.tif"))
    assert (a.RasterXSize, a.RasterYSize) == (b.RasterXSize, b.RasterYSize)
    assert np.allclose(a.GetGeoTransform(), b.GetGeoTransform(), rtol=0, atol=1e-6)
    assert np.array_equal(a.ReadAsArray(), b.ReadAsArray())
    assert a.GetMetadataItem("RECTIFICATION").startswith("GCP tps")


@pytest.mark.skipif(__import__("shutil").which("gdalwarp") is None,
                    reason="gdalwarp not installed")
@pytest.mark.parametrize("kind", ["linear", "helmert"])
def test_affine_kinds_warp_as_gdalwarp_of_their_geotransform(tmp_path, kind):
    """Linear and Helmert reach GDAL exactly, as a geotransform; the oracle is gdalwarp
    of a copy carrying that geotransform (gdal_translate -a_ullr cannot rotate, so the
    copy is a VRT written by GDAL's API)."""
    import subprocess

    from geomatics_toolbox.core.rectification import warp
    img, pix, mp = _small_case(tmp_path, "helmert")
    g = gcp_io.make_gcps(None, pix, mp, crs="EPSG:22780")
    res = warp.rectify(img, g, tmp_path / "ours.tif", kind=kind)
    gt = transforms.fit_transform(kind, pix, mp).geotransform()
    ref_in = gdal.Translate(str(tmp_path / "gt.vrt"), str(img), format="VRT",
                            outputSRS="EPSG:22780")
    ref_in.SetGeoTransform(gt)
    ref_in = None
    subprocess.run(["gdalwarp", "-q", "-r", "near", "-tr", repr(res.resolution),
                    repr(res.resolution), str(tmp_path / "gt.vrt"),
                    str(tmp_path / "ref.tif")], check=True)
    a, b = gdal.Open(str(tmp_path / "ours.tif")), gdal.Open(str(tmp_path / "ref.tif"))
    assert (a.RasterXSize, a.RasterYSize) == (b.RasterXSize, b.RasterYSize)
    assert np.allclose(a.GetGeoTransform(), b.GetGeoTransform(), rtol=0, atol=1e-6)
    assert np.array_equal(a.ReadAsArray(), b.ReadAsArray())


def test_projective_warp_grid_spline_stays_on_the_homography(tmp_path):
    """GDAL 3.6 has no homography transformer: the warp uses GCP_TPS through a
    33 × 33 grid on the fitted homography. Measured here: the spline departs from the
    homography by < 5e-3 px anywhere in the image (measured 0.0035 px), so the warp
    differs from an exact homography warp only where a source position falls within
    that distance of a pixel boundary."""
    from geomatics_toolbox.core.rectification import warp
    img, pix, mp = _small_case(tmp_path, "projective")
    g = gcp_io.make_gcps(None, pix, mp, crs="EPSG:22780")
    h = transforms.fit_transform("projective", pix, mp)
    w, hh, _, _ = warp.image_info(img)
    n = warp.PROJECTIVE_GRID
    c, r = np.meshgrid(np.linspace(0, w, n), np.linspace(0, hh, n))
    x, y = h.forward(c.ravel(), r.ravel())
    tr, _ds = _gdal_transformer(np.column_stack([c.ravel(), r.ravel()]),
                                np.column_stack([x, y]), ["METHOD=GCP_TPS"])
    rng = np.random.default_rng(1)
    q = rng.uniform([0, 0], [w, hh], (2000, 2))
    o = np.array(tr.TransformPoints(0, q.tolist())[0])
    ec, er = h.inverse(o[:, 0], o[:, 1])
    dev = np.hypot(ec - q[:, 0], er - q[:, 1]).max()
    assert dev < 5e-3  # measured 0.0035 px (17 × 17 grid: 0.011 px)
    res = warp.rectify(img, g, tmp_path / "p.tif", kind="projective")
    assert res.kind == "projective" and (tmp_path / "p.tif").exists()

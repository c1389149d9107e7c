"""Transformations of the Georeferencer and gdalwarp: known parameters, oracles, ranking."""
from __future__ import annotations

import numpy as np
import pytest

from geomatics_toolbox.core.errors import InputError
from geomatics_toolbox.core.io import gcp as gcp_io
from geomatics_toolbox.core.rectification import compare, transforms
from geomatics_toolbox.synthetic import gcp as gcp_synthetic

gdal = pytest.importorskip("osgeo.gdal")
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
    skt = pytest.importorskip("skimage.transform")
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
    skt = pytest.importorskip("skimage.transform")
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
    if kind == "tps":  # GDAL fits its own map -> image spline; so do we
        back = np.array(tr.TransformPoints(1, o[:, :2].tolist())[0])
        cc, rr = t.inverse(o[:, 0], o[:, 1])
        assert np.abs(cc - back[:, 0]).max() < 1e-6 and np.abs(rr - back[:, 1]).max() < 1e-6
        vx, vy = t.residuals(pix, mp)
        assert np.abs(vx).max() < 1e-6 and np.abs(vy).max() < 1e-6


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

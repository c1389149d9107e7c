"""The GCP rectification report: every transformation judged on honest residuals."""
from __future__ import annotations

import numpy as np
import pytest

from geomatics_toolbox.core.io import gcp as gcp_io
from geomatics_toolbox.core.rectification import assess, report
from geomatics_toolbox.core.reporting import render_html
from geomatics_toolbox.core.reporting.i18n import has_translation
from geomatics_toolbox.synthetic import gcp as gcp_synthetic

EPSG = "EPSG:22780"


def _gcps(kind, noise=0.5, seed=7, n_check=0, outlier=None):
    pix, mp, truth, size = gcp_synthetic.transformed_gcps(kind, noise=noise, seed=seed)
    role = np.array(["gcp"] * len(pix), dtype=object)
    role[1:1 + 3 * n_check:3] = "check"
    if outlier is not None:
        mp = mp.copy()
        mp[outlier] += (30.0, -25.0)
    return gcp_io.make_gcps(None, pix, mp, role=role, crs=EPSG), truth, size


# (polynomial3: the cubic terms of synthetic.gcp.true_coefficients(3) are below the
# 0.5 m noise on 22 points, so order 2 is within the 10 % tie and, simpler, wins.)
@pytest.mark.parametrize("kind", ["linear", "helmert", "projective", "polynomial2"])
def test_report_ranks_by_honest_error_and_picks_the_true_model(kind):
    """Spec image-1 GCPs through a known distortion + 0.5 m noise: the true model wins."""
    g, _, size = _gcps(kind)
    a = assess.assess_gcps(g, kind=assess.RECOMMENDED, image_size=size)
    assert a.kind == kind and a.comparison.recommended == kind
    assert a.comparison.basis == "loo"
    best = a.comparison.results[kind].loo.rms_t
    # its leave-one-out error is about the noise (0.5 m per axis -> ~0.71 m total)
    assert 0.4 < best < 1.1
    # TPS fits every GCP exactly yet is never recommended on its zero fit residuals
    assert a.comparison.results["tps"].fit.rms_t < 1e-6
    html = render_html(report.build_report(a))
    assert 'id="residual-vectors"' in html and 'id="transform-comparison"' in html


def test_check_points_decide_when_there_are_three():
    g, _, size = _gcps("helmert", n_check=4)
    a = assess.assess_gcps(g, kind="tps", image_size=size)
    c = a.comparison
    assert c.basis == "check"
    # 4 check points decide (not LOO): the pick is within 10 % of the best check RMS_T,
    # and a model that contains the true Helmert (never TPS, never linear)
    best = min(r.check.rms_t for r in c.results.values() if r.supported)
    assert c.results[c.recommended].check.rms_t <= 1.1 * best
    assert c.recommended not in ("tps", "linear")
    html = render_html(report.build_report(a))
    assert "check-point RMS_T is within" in html


def test_refinement_drops_the_outlier_and_the_report_lists_it():
    g, truth, size = _gcps("helmert", outlier=6)
    a = assess.assess_gcps(g, kind="helmert", image_size=size, refine=True)
    assert [d["id"] for d in a.dropped] == [g.ids[6]]
    assert a.tolerance == pytest.approx(5 * a.acc.gr)
    p = a.selected.transform.parameters()
    assert p["scale"] == pytest.approx(truth["scale"], rel=1e-3)
    assert p["rotation_deg"] == pytest.approx(truth["rotation_deg"], abs=0.01)
    html = render_html(report.build_report(a))
    assert "GCPs dropped by the refinement" in html and f">{g.ids[6]}<" in html
    # Helmert scale/rotation and the projective matrix are in the report
    assert "rotation (°)" in html and "X·w" in html


@pytest.mark.parametrize("lang", ["ar", "fa"])
def test_every_report_message_is_translated(lang):
    g, _, size = _gcps("polynomial2", n_check=3, outlier=5)
    for kind in ("polynomial2", "tps", "helmert"):
        a = assess.assess_gcps(g, kind=kind, image_size=size, refine=True)
        rep = report.build_report(a, extra={"rectified image": "x.tif", "resampling": "near",
                                            "output resolution": "1", "output size": "1"},
                                  lang=lang)
        missing = {m for m in rep.messages() if not has_translation(m, lang)}
        assert not missing, missing
        html = render_html(rep, lang=lang)
        assert f'lang="{lang}" dir="rtl"' in html


@pytest.mark.parametrize("lang", ["ar", "fa"])
def test_batch_summary_is_translated(lang):
    from geomatics_toolbox.core.rectification import batch
    rows = [batch.BatchRow("a.tif", "out/a_rectified.tif", "helmert", 22, 0.4, 0.5, "loo",
                           "accepted", 0),
            batch.BatchRow("b.tif", error="the .points file has no '#CRS:' line")]
    rep = batch.summary_report(rows)
    assert not {m for m in rep.messages() if not has_translation(m, lang)}
    assert batch.summary_csv(rows).splitlines()[1].startswith(
        "a.tif,out/a_rectified.tif,helmert,22,0.400000,0.500000,loo,accepted,0,")

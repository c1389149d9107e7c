"""Tests of the ground-filter accuracy assessment (core/filter_accuracy.py)."""
from __future__ import annotations

import numpy as np
import pytest

from geomatics_toolbox.core.io.las import write_las
from geomatics_toolbox.core.lidar.accuracy import (
    assess,
    error_codes,
    from_counts,
    ground_mask,
)
from geomatics_toolbox.core.lidar.accuracy_file import assess_clouds, parse_classes


def test_golden_paper_samp54_counts():
    """The LSQ paper's corrected samp54 counts (a 3924, b 54, c 294, d 4324)."""
    acc = from_counts(3924, 54, 294, 4324)
    assert acc.n == 8596
    assert acc.type1 == pytest.approx(1.357, abs=5e-4)
    assert acc.type2 == pytest.approx(6.366, abs=5e-4)
    # the paper prints 4.04 (truncated); the exact value is 348 / 8596 = 4.048 %
    assert acc.total == pytest.approx(4.04, abs=0.01)
    assert acc.total == pytest.approx(100 * 348 / 8596, rel=1e-12)
    # Cohen's kappa from its definition
    n = 8596
    po = (3924 + 4324) / n
    pe = ((3924 + 54) * (3924 + 294) + (294 + 4324) * (54 + 4324)) / n ** 2
    assert acc.kappa == pytest.approx(100 * (po - pe) / (1 - pe), rel=1e-12)


def test_assess_matches_counts_and_error_codes():
    rng = np.random.default_rng(0)
    ref = rng.random(1000) < 0.5
    pred = ref.copy()
    flip = rng.choice(1000, 100, replace=False)
    pred[flip] = ~pred[flip]
    acc = assess(pred, ref)
    assert acc.a == np.sum(pred & ref) and acc.b == np.sum(~pred & ref)
    assert acc.c == np.sum(pred & ~ref) and acc.d == np.sum(~pred & ~ref)
    assert acc.total == pytest.approx(10.0)
    codes = error_codes(pred, ref)
    assert np.sum(codes == 1) == acc.b and np.sum(codes == 2) == acc.c
    assert np.all(codes[pred == ref] == 0)
    assert assess(ref, ref).kappa == pytest.approx(100.0)


def test_parse_classes():
    assert parse_classes("2") == (2,)
    assert parse_classes("2, 8;11 ") == (2, 8, 11)
    assert parse_classes([2, 9]) == (2, 9)
    for bad in ("", "ground", "300", None):
        with pytest.raises(ValueError, match="class"):
            parse_classes(bad)
    assert ground_mask([1, 2, 8, 2], (2, 8)).tolist() == [False, True, True, True]


@pytest.fixture()
def clouds(tmp_path):
    rng = np.random.default_rng(1)
    n = 500
    x, y = rng.uniform(0, 100, (2, n))
    z = rng.uniform(0, 5, n)
    ref = np.where(rng.random(n) < 0.6, 2, 1).astype(np.uint8)
    pred = ref.copy()
    pred[:40] = np.where(ref[:40] == 2, 1, 2)
    pred[40:45] = 7        # noise: counts as "not ground"
    refp, predp = tmp_path / "ref.las", tmp_path / "pred.laz"
    write_las(refp, x, y, z, dimensions={"classification": ref})
    write_las(predp, x, y, z, dimensions={"classification": pred, "user_data": ref})
    return predp, refp, pred, ref, (x, y, z)


def test_assess_clouds_with_reference_cloud_and_field(clouds, tmp_path):
    predp, refp, pred, ref, _ = clouds
    expect = assess(pred == 2, ref == 2)
    a = assess_clouds(predp, refp)
    assert a.accuracy == expect
    b = assess_clouds(predp, None, reference_field="user_data")
    assert b.accuracy == expect
    # per filtered class: (reference ground, reference object)
    assert sum(g + o for g, o in a.classes.values()) == pred.size
    assert a.classes[7] == (int(np.sum(ref[40:45] == 2)), int(np.sum(ref[40:45] == 1)))
    assert np.array_equal(a.error_codes(), error_codes(pred == 2, ref == 2))


def test_assess_clouds_bad_input(clouds, tmp_path):
    predp, refp, pred, ref, (x, y, z) = clouds
    short = tmp_path / "short.las"
    write_las(short, x[:-1], y[:-1], z[:-1], dimensions={"classification": ref[:-1]})
    with pytest.raises(ValueError, match="500 points but the reference cloud has 499"):
        assess_clouds(predp, short)
    shuffled = tmp_path / "shuffled.las"
    o = np.random.default_rng(2).permutation(x.size)
    write_las(shuffled, x[o], y[o], z[o], dimensions={"classification": ref[o]})
    with pytest.raises(ValueError, match="not the same points"):
        assess_clouds(predp, shuffled)
    with pytest.raises(ValueError, match="another\\s+dimension|reference dimension"):
        assess_clouds(predp, None)
    with pytest.raises(ValueError, match="no dimension"):
        assess_clouds(predp, None, reference_field="nothing_here")


def test_isprs_reference_against_itself(isprs_dir):
    a = assess_clouds(isprs_dir / "samp54.laz", isprs_dir / "samp54.laz")
    assert (a.accuracy.a, a.accuracy.d) == (3983, 4625)
    assert a.accuracy.total == 0.0 and a.accuracy.kappa == pytest.approx(100.0)


@pytest.mark.parametrize("lang", ["ar", "fa"])
def test_accuracy_report_translated_with_error_map(tmp_path, lang):
    """The report holds the cross matrix, the errors and the error map, all in ar/fa."""
    from geomatics_toolbox.core.io.las import read_las, write_las_like
    from geomatics_toolbox.core.lidar import accuracy_file as core_fa
    from geomatics_toolbox.core.reporting import Figure, Table, render_html
    from geomatics_toolbox.core.reporting.i18n import has_translation
    from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile
    src, filt = tmp_path / "ref.laz", tmp_path / "filt.laz"
    write_tile(generate_tile(extent=(60, 40), density=2.0, seed=5), src)
    cls = read_las(src, ("classification",))["classification"].copy()
    flip = np.random.default_rng(0).random(cls.size) < 0.05
    cls[flip] = np.where(cls[flip] == 2, 1, 2)
    write_las_like(src, filt, dimensions={"classification": cls})
    res = core_fa.assess_clouds(filt, src)
    rep = core_fa.accuracy_report(res, core_fa.AssessmentInputs(str(filt), str(src)),
                                  lang=lang)
    assert [m for m in rep.messages() if not has_translation(m, lang)] == []
    blocks = [b for s in rep.sections for b in s.blocks]
    matrix = next(b for b in blocks if isinstance(b, Table)
                  and "filtered ground" in b.headers)
    a = res.accuracy
    assert [list(r[1:]) for r in matrix.rows] == [[a.a, a.b, a.a + a.b],
                                                  [a.c, a.d, a.c + a.d],
                                                  [a.a + a.c, a.b + a.d, a.n]]
    assert a.b > 0 and a.c > 0
    figs = [b for b in blocks if isinstance(b, Figure)]
    assert [f.figure_id for f in figs] == ["error-map"]
    html = render_html(rep, lang=lang)
    assert 'dir="rtl"' in html and 'id="error-map"' in html
    for word in ("Cross matrix", "Classes", "Errors (%)", "filtered ground"):
        assert word not in html

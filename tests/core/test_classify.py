"""Full ASPRS classification (core.lidar.classify) on the demo tile, the shared real
files and synthetic cases with known answers."""
from __future__ import annotations

import importlib.util
from pathlib import Path

import numpy as np
import pytest

from geomatics_toolbox.core.errors import InputError
from geomatics_toolbox.core.lidar import classify as core_c

ROOT = Path(__file__).resolve().parents[2]
REAL = ROOT.parent / "shared" / "data" / "real"


def _laspy():
    import laspy
    return laspy


def _vlrs(header):
    return [(v.user_id, v.record_id, bytes(v.record_data_bytes()) if hasattr(
        v, "record_data_bytes") else None) for v in header.vlrs]


def assert_same_but_classes(src, dst, *, extra=()):
    """Every dimension but classification (and the new ``extra`` ones) identical; VLRs,
    EVLRs, scales, offsets, point format and CRS unchanged."""
    laspy = _laspy()
    a, b = laspy.read(src), laspy.read(dst)
    assert len(a.points) == len(b.points)
    assert a.header.point_format.id == b.header.point_format.id
    assert a.header.version == b.header.version
    assert np.array_equal(a.header.scales, b.header.scales)
    assert np.array_equal(a.header.offsets, b.header.offsets)
    names = list(a.point_format.dimension_names)
    for name in names:
        if name in ("classification",):
            continue
        assert np.array_equal(np.asarray(a[name]), np.asarray(b[name])), name
    if not extra:
        assert [(v.user_id, v.record_id, v.description) for v in a.header.vlrs] == \
            [(v.user_id, v.record_id, v.description) for v in b.header.vlrs]
        for va, vb in zip(a.header.vlrs, b.header.vlrs):
            if hasattr(va, "record_data_bytes"):
                assert va.record_data_bytes() == vb.record_data_bytes()
    assert len(a.header.evlrs or []) == len(b.header.evlrs or [])
    assert (a.header.parse_crs() is None) == (b.header.parse_crs() is None)
    if a.header.parse_crs() is not None:
        assert a.header.parse_crs() == b.header.parse_crs()
    for name in extra:
        assert name in b.point_format.dimension_names
    return a, b


@pytest.fixture(scope="module")
def demo(tmp_path_factory):
    spec = importlib.util.spec_from_file_location("make_demo_data",
                                                  ROOT / "scripts" / "make_demo_data.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    d = tmp_path_factory.mktemp("classify")
    return d, str(mod.make_demo(d / "demo")["laz"])


def test_demo_tile_gets_every_class(demo):
    """The demo tile (true classes 2/5/6/7/18): 2/3/4/5/6/7 written, 18 kept; the
    building and ground points agree with the truth."""
    d, laz = demo
    laspy = _laspy()
    out = d / "c.laz"
    res = core_c.classify_file_asprs(laz, cloud=str(out), report=str(d / "c.html"))
    a, b = assert_same_but_classes(laz, out)
    got = np.asarray(b.classification)
    truth = np.asarray(a.classification)
    assert {2, 3, 4, 5, 6, 7} <= set(np.unique(got).tolist())
    assert np.array_equal(got[truth == 18], truth[truth == 18])
    assert res.counts == {int(k): int(v) for k, v in zip(*np.unique(got, return_counts=True))}
    # against the tile's true classes
    bld = got == 6
    assert (truth[bld] == 6).mean() > 0.97, (truth[bld] == 6).mean()
    assert (got[truth == 6] == 6).mean() > 0.85
    veg = np.isin(got, (3, 4, 5))
    assert (truth[veg] == 5).mean() > 0.97
    assert (got[truth == 2] == 2).mean() > 0.97
    # one engine: ground and low noise exactly as the default ground filter gives them
    from geomatics_toolbox.core.lidar.filters import (
        classify_points,
        default_ground_filter,
        default_selection,
        ground_filter,
    )
    from geomatics_toolbox.core.lidar.pipeline import read_cloud
    key = default_ground_filter()
    ref = classify_points(read_cloud(laz), ground_filter(key), default_selection(key))
    assert np.array_equal(got == 2, ref == 2) and np.array_equal(got == 7, ref == 7)
    html = (d / "c.html").read_text(encoding="utf-8")
    assert 'id="class-map"' in html and "ASPRS" in html
    assert 'id="footprint-map"' in html and res.buildings.buildings
    assert laspy.read(out).header.point_count == len(truth)


@pytest.mark.parametrize("name", ["lastools_fusa.laz", "pdal_nm_usft.laz",
                                  "pdal_ign_lambert93.laz", "lidr_mixedconifer_terrain.laz"])
def test_real_files(name, tmp_path):
    """Every shared real file: ground, vegetation by height, buildings where the vendor has
    them; all other attributes, VLRs and the CRS identical; HAG on request."""
    src = REAL / name
    if not src.exists():
        pytest.skip(f"shared real data absent: {src} (see ../shared/data/real/README.md)")
    out = tmp_path / "c.laz"
    res = core_c.classify_file_asprs(str(src), cloud=str(out))
    a, b = assert_same_but_classes(str(src), str(out))
    vendor = np.asarray(a.classification)
    got = np.asarray(b.classification)
    present = set(np.unique(got).tolist())
    assert {2, 4, 5} <= present, present
    assert present <= {1, 2, 3, 4, 5, 6, 7, 9, 18}
    # ground agrees with the vendor's on most vendor ground points
    assert (got[vendor == 2] == 2).mean() > 0.9
    if (vendor == 6).sum() > 500:
        # buildings found where the vendor has them: most vendor class-6 points are 6
        assert 6 in present and (got[vendor == 6] == 6).mean() > 0.6
        assert (vendor[got == 6] == 6).mean() > 0.6
    assert res.hag.dtype == np.float32 and np.isfinite(res.hag).all()


def test_height_above_ground_dimension(tmp_path):
    """HAG extra bytes: the existing extra-bytes dimension (treeID) keeps its values; the
    new one equals the result's heights (float32, the data's vertical unit)."""
    src = REAL / "lidr_mixedconifer_terrain.laz"
    if not src.exists():
        pytest.skip(f"shared real data absent: {src}")
    out = tmp_path / "h.laz"
    res = core_c.classify_file_asprs(str(src), cloud=str(out), hag=True)
    a, b = assert_same_but_classes(str(src), str(out), extra=[core_c.HAG_DIMENSION])
    hag = np.asarray(b[core_c.HAG_DIMENSION])
    assert np.array_equal(hag, res.hag)
    got = np.asarray(b.classification)
    assert "treeID" in a.point_format.dimension_names
    assert np.abs(hag[got == 2]).max() < 1.0
    assert hag[got == 5].min() > 1.5 - 1e-3 and hag[got == 3].max() <= 0.5 + 1e-3
    assert hag.max() > 20          # conifers to 32 m


def _scene(seed=3):
    from geomatics_toolbox.synthetic.lidar import generate_tile
    return generate_tile(extent=(120.0, 120.0), density=4.0, seed=seed, n_buildings=3,
                         n_halls=0, hill_height=0.0, cliff_height=0.0)


def test_vegetation_thresholds_and_keep_modes():
    """3/4/5 follow the height thresholds exactly; water and other classes are kept as
    asked; 'keep' takes the input's ground."""
    tile = _scene()
    cls = tile.classification.copy()
    rng = np.random.default_rng(0)
    water = np.flatnonzero(cls == 2)[rng.choice((cls == 2).sum(), 50, replace=False)]
    cls[water] = 9
    road = np.flatnonzero(cls == 2)[:40]
    cls[road] = 11
    opt = core_c.ClassifyOptions(ground="keep", low_max=1.0, medium_max=3.0)
    res = core_c.classify_points(tile.x, tile.y, tile.z, cls, options=opt)
    out = res.classes
    assert (out[water] == 9).all()
    assert not (out[road] == 11).any()          # not kept by default
    ground = cls == 2
    assert np.array_equal(out == 2, ground)      # keep: exactly the input's ground
    h = res.hag
    assert (h[out == 3] <= 1.0 + 1e-6).all() and (h[out == 3] >= 0).all()
    assert ((h[out == 4] > 1.0) & (h[out == 4] <= 3.0 + 1e-6)).all()
    assert (h[out == 5] > 3.0 - 1e-6).all()
    res2 = core_c.classify_points(tile.x, tile.y, tile.z, cls, options=core_c.ClassifyOptions(
        ground="keep", keep_other=True))
    assert (res2.classes[road] == 11).all() and (res2.classes[water] == 9).all()


def test_feet_copy_gives_the_same_classes(tmp_path):
    """A cloud in US survey feet (x, y, z) gets the same classes as its metre copy, and
    heights above ground in feet."""
    from geomatics_toolbox.synthetic.hostile import unit_copy
    from geomatics_toolbox.synthetic.lidar import write_tile
    tile = _scene(5)
    m = tmp_path / "m.laz"
    write_tile(tile, m, crs="EPSG:32632")
    ft = tmp_path / "ft.laz"
    unit_copy(str(m), str(ft))
    rm = core_c.classify_file_asprs(str(m), cloud=str(tmp_path / "cm.laz"))
    rf = core_c.classify_file_asprs(str(ft), cloud=str(tmp_path / "cf.laz"))
    agree = (rm.classes == rf.classes).mean()
    assert agree > 0.999, agree
    ok = rm.classes == rf.classes
    diff = np.abs(rf.hag[ok] * 1200 / 3937 - rm.hag[ok])
    # the two DTM grids are aligned on metres of each CRS: bilinear values differ by
    # millimetres on the terrain, a few centimetres at roof and crown edges
    assert np.median(diff) < 0.005 and np.percentile(diff, 99) < 0.05, (
        np.median(diff), np.percentile(diff, 99), diff.max())
    assert rm.counts.get(6, 0) > 100 and abs(rm.counts[6] - rf.counts.get(6, 0)) < 0.01 * \
        rm.counts[6]


def test_bad_options_are_translated_errors():
    with pytest.raises(InputError, match=r"\(LOW_VEGETATION = 2\.0 m\) < Medium vegetation up "
                                         r"to \(MEDIUM_VEGETATION = 1\.0 m\)") as info:
        core_c.ClassifyOptions(low_max=2.0, medium_max=1.0)
    assert "«الغطاء النباتي المنخفض حتى» (\u2066LOW_VEGETATION = \u20682.0\u2069 m" in \
        info.value.message("ar")
    with pytest.raises(InputError, match="Ground must be"):
        core_c.ClassifyOptions(ground="maybe")
    x = np.arange(10.0)
    with pytest.raises(InputError, match="No ground points"):
        core_c.classify_points(x, x, x, np.ones(10, int),
                               options=core_c.ClassifyOptions(ground="keep"))


def test_report_is_translated():
    from geomatics_toolbox.core.reporting import render_html
    from geomatics_toolbox.core.reporting.i18n import has_translation
    tile = _scene()
    cls = tile.classification.copy()
    res = core_c.classify_points(tile.x, tile.y, tile.z, cls,
                                 options=core_c.ClassifyOptions(ground="keep"))
    rep = core_c.classify_report(res, "t.laz", tile.x, tile.y, lang="fa")
    missing = {m for m in rep.messages() for lang in ("ar", "fa")
               if not has_translation(m, lang)}
    assert not missing, missing
    assert 'id="class-map"' in render_html(rep, lang="ar")

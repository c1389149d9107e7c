"""classify_file with a dummy algorithm object: selection, classes, contract, degrees."""
from __future__ import annotations

import os

import laspy
import numpy as np
import pytest

from geomatics_toolbox.core.coords import check_projected, looks_like_degrees
from geomatics_toolbox.core.errors import InputError
from geomatics_toolbox.core.io.las import write_las
from geomatics_toolbox.core.lidar.pipeline import (
    FilterOutputs,
    FunctionFilter,
    SelectionOptions,
    classify_file,
)


@pytest.fixture(scope="module")
def cloud(tmp_path_factory):
    rng = np.random.default_rng(4)
    n = 4000
    x = 500_000 + rng.uniform(0, 100, n)
    y = 4_000_000 + rng.uniform(0, 100, n)
    z = 100 + rng.normal(0, 0.05, n)
    z[:5] -= 20.0                      # five low outliers
    cls = np.ones(n, np.uint8)
    cls[10:15] = 18                    # five points already high noise
    rn = np.ones(n, np.uint8)
    nr = np.ones(n, np.uint8)
    nr[100:200] = 2                    # 100 first returns of two-return pulses
    path = tmp_path_factory.mktemp("pipe") / "c.las"
    write_las(path, x, y, z, dimensions={"classification": cls, "return_number": rn,
                                         "number_of_returns": nr}, crs="EPSG:32632")
    return path, z


def _above_median(x, y, z, *, return_number=None, number_of_returns=None, options=None,
                  progress=None, cancel=None):
    """Dummy filter: ground when z is at or below the median of what it is given."""
    _above_median.seen = x.size
    return np.where(z <= np.median(z), 2, 1).astype(np.uint8)


DUMMY = FunctionFilter(_above_median, name="dummy", title="Dummy filter")


def test_classes_bookkeeping_and_attributes(cloud, tmp_path):
    path, z = cloud
    out, gout, html = tmp_path / "o.laz", tmp_path / "g.las", tmp_path / "r.html"
    run = classify_file(path, DUMMY, FilterOutputs(cloud=out, ground=gout, report=html),
                        selection=SelectionOptions(returns="last"))
    a, b = laspy.read(path), laspy.read(out)
    for dim in a.point_format.dimension_names:
        if dim != "classification":
            np.testing.assert_array_equal(np.asarray(a[dim]), np.asarray(b[dim]), dim)
    cls = np.asarray(b.classification)
    assert np.all(cls[:5] == 7) and np.all(cls[10:15] == 18)     # noise, input noise kept
    assert np.all(cls[100:200] == 1)                             # not last returns
    assert _above_median.seen == 4000 - 5 - 5 - 100              # only candidates
    cand = np.ones(4000, bool)
    cand[:5] = cand[10:15] = cand[100:200] = False
    zq = np.asarray(a.z)[cand]                                   # oracle: the same rule
    assert run.n_ground == np.count_nonzero(cls == 2) == np.count_nonzero(zq <= np.median(zq))
    np.testing.assert_array_equal(cls[cand] == 2, zq <= np.median(zq))
    assert len(laspy.read(gout).x) == run.n_ground
    assert a.header.parse_crs() == b.header.parse_crs()
    assert "Dummy filter" in html.read_text(encoding="utf-8")
    vals, cnt = np.unique(cls, return_counts=True)                # oracle of counts()
    assert run.counts() == {int(v): int(c) for v, c in zip(vals, cnt)}
    assert list(run.counts()) == [1, 2, 7, 18]


def test_outputs_checked_against_inputs_and_each_other(cloud, tmp_path):
    path, _ = cloud
    same = tmp_path / "same.laz"
    with pytest.raises(InputError, match="GROUND_OUTPUT"):
        classify_file(path, DUMMY, FilterOutputs(
            cloud=same, ground=same, names={"cloud": "OUTPUT", "ground": "GROUND_OUTPUT"}))
    with pytest.raises(InputError, match="same file as the input INPUT"):
        classify_file(path, DUMMY, FilterOutputs(cloud=path))
    with pytest.raises(InputError, match="same file as the input REF"):
        classify_file(path, DUMMY, FilterOutputs(cloud=tmp_path / "r.las",
                                                 inputs={"REF": tmp_path / "r.las"}))
    with pytest.raises(InputError, match=".las or .laz"):
        classify_file(path, DUMMY, FilterOutputs(cloud=tmp_path / "o.txt"))
    assert os.listdir(tmp_path) == []


def test_failing_report_leaves_nothing(cloud, tmp_path):
    path, _ = cloud
    out = tmp_path / "o.las"
    before = path.read_bytes()
    # refused up front: the report folder cannot be written
    with pytest.raises(ValueError, match="cannot be written"):
        classify_file(path, DUMMY, FilterOutputs(cloud=out, report="/proc/report.html"))
    assert os.listdir(tmp_path) == [] and path.read_bytes() == before

    # the report fails after the cloud was written: the cloud is not kept either
    def broken(report):
        raise OSError(28, "No space left on device")
    with pytest.raises(OSError, match="No space left"):
        classify_file(path, DUMMY, FilterOutputs(cloud=out, report=tmp_path / "r.html",
                                                 render=broken))
    assert os.listdir(tmp_path) == [] and path.read_bytes() == before


def test_function_filter_with_wrong_length_is_refused(cloud, tmp_path):
    path, _ = cloud
    bad = FunctionFilter(lambda x, y, z, **kw: np.ones(3, np.uint8), name="bad", title="Bad")
    with pytest.raises(ValueError, match="bad returned"):
        classify_file(path, bad, FilterOutputs(cloud=tmp_path / "o.las"))
    assert os.listdir(tmp_path) == []


def test_degrees_refused_with_reprojection_hint(tmp_path):
    rng = np.random.default_rng(1)
    lon = 36.29 + rng.uniform(0, 0.001, 500)
    lat = 33.51 + rng.uniform(0, 0.001, 500)
    z = 700 + rng.uniform(0, 20, 500)
    for crs in ("EPSG:4326", None):
        src = tmp_path / f"deg{crs is None}.las"
        write_las(src, lon, lat, z, crs=crs, scale=1e-7)
        with pytest.raises(InputError, match="reprojection.out_srs=EPSG:326xx"):
            classify_file(src, DUMMY, FilterOutputs(cloud=tmp_path / "o.las"))
    assert not (tmp_path / "o.las").exists()


def test_looks_like_degrees_rule():
    x = np.array([36.0, 36.001])
    assert looks_like_degrees(x, [33.0, 33.001], [700, 720])
    assert not looks_like_degrees(x, [33.0, 33.001], [700, 700.001])  # flat, tiny
    assert not looks_like_degrees([0, 4], [0, 3], [1, 5])              # small local grid
    assert not looks_like_degrees([500000, 500100], [4e6, 4e6 + 1], [0, 50])
    check_projected(crs="EPSG:32632")
    with pytest.raises(InputError, match="geographic CRS"):
        check_projected(crs="EPSG:4326")


@pytest.mark.parametrize("lang", ["ar", "fa"])
def test_lidar_reports_fully_translated(tmp_path, lang):
    """Every message of the LSQ, slope and sweep reports has an ar/fa translation."""
    from geomatics_toolbox.core.lidar.lsq import LsqFilter, LsqOptions
    from geomatics_toolbox.core.lidar.slope import SlopeFilter, SlopeOptions
    from geomatics_toolbox.core.lidar.sweep import sweep_file
    from geomatics_toolbox.core.reporting import render_html
    from geomatics_toolbox.core.reporting.i18n import has_translation
    from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile
    src = tmp_path / "t.laz"
    write_tile(generate_tile(extent=(80, 80), density=2.0, seed=3), src)
    reports = [classify_file(src, alg, FilterOutputs(report=tmp_path / "r.html", lang=lang),
                             selection=SelectionOptions(returns="last")).report
               for alg in (LsqFilter(LsqOptions(mode="improved")), LsqFilter(),
                           SlopeFilter(SlopeOptions(mode="adaptive")))]
    reports.append(sweep_file(src, slopes=[30, 40], metric="kappa").report)
    missing = {m for r in reports for m in r.messages() if not has_translation(m, lang)}
    assert not missing, sorted(missing)
    html = render_html(reports[0], lang=lang)
    assert 'dir="rtl"' in html
    for word in ("Cross matrix", "Classes", "Iterations", "faithful", "converged"):
        assert f">{word}<" not in html


def test_input_decoded_once_and_outputs_equal_a_second_decode(tmp_path, monkeypatch):
    """classify_file decodes the input once and writes both clouds from those records:
    the files equal copies written by decoding the input again."""
    import laspy

    from geomatics_toolbox.core.io import las as las_io
    from geomatics_toolbox.core.lidar.filters import ground_filter
    from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile
    src = tmp_path / "t.laz"
    write_tile(generate_tile(extent=(60, 60), density=2.0, seed=4), src)
    calls = []
    real = las_io._chunks

    def counting(reader, path, chunk_size):
        calls.append(str(path))
        return real(reader, path, chunk_size)

    monkeypatch.setattr(las_io, "_chunks", counting)
    run = classify_file(src, ground_filter("slope_exact"),
                        FilterOutputs(cloud=tmp_path / "c.laz", ground=tmp_path / "g.las"))
    assert calls == [str(src)]                   # one decode for the read and both writes
    monkeypatch.setattr(las_io, "_chunks", real)
    dims = {"classification": run.classes}
    las_io.write_las_like(src, tmp_path / "c2.laz", dimensions=dims)
    las_io.write_las_like(src, tmp_path / "g2.las", dimensions=dims, mask=run.classes == 2)
    for a, b in (("c.laz", "c2.laz"), ("g.las", "g2.las")):
        pa, pb = laspy.read(tmp_path / a), laspy.read(tmp_path / b)
        assert len(pa.points) == len(pb.points) > 1000
        assert bytes(pa.points.array.tobytes()) == bytes(pb.points.array.tobytes())
        assert pa.header.parse_crs() == pb.header.parse_crs()

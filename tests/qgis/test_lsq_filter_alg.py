"""LSQ ground filter and ground filter accuracy through processing.run."""
from __future__ import annotations

import laspy
import numpy as np
import pytest

from geomatics_toolbox.core.io.las import read_las, write_las
from geomatics_toolbox.core.lidar.accuracy import assess
from geomatics_toolbox.core.lidar.lsq import lsq_ground_filter

ALG = "geomatics:lsqgroundfilter"
ACC = "geomatics:groundfilteraccuracy"


@pytest.fixture(scope="module")
def tile(tmp_path_factory):
    """A small labelled synthetic tile (LAS 1.4, format 6, CRS) and its truth."""
    from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile
    t = generate_tile(extent=(120, 120), density=4.0, seed=11)
    path = tmp_path_factory.mktemp("lsqalg") / "tile.laz"
    write_tile(t, path)
    return path, t


def _core_classes(t, **kw):
    """The core filter on the points the input does not mark as noise (7, 18 kept)."""
    noise = np.isin(t.classification, (7, 18))
    res = lsq_ground_filter(t.x[~noise], t.y[~noise], t.z[~noise], **kw)
    cls = np.asarray(t.classification, np.uint8).copy()
    cls[~noise] = res.classification
    return cls, res


def _all_dims_but(path_a, path_b, skip=("classification",)):
    a, b = laspy.read(path_a), laspy.read(path_b)
    assert a.header.point_format.id == b.header.point_format.id
    assert np.allclose(a.header.scales, b.header.scales)
    assert np.allclose(a.header.offsets, b.header.offsets)
    for name in a.point_format.dimension_names:
        if name not in skip:
            assert np.array_equal(a[name], b[name]), name
    return a, b


def test_filter_writes_classes_and_preserves_everything_else(qgis_processing, tile,
                                                             tmp_path):
    path, t = tile
    out, gout, html = tmp_path / "c.laz", tmp_path / "g.las", tmp_path / "r.html"
    res = qgis_processing.run(ALG, {"INPUT": str(path), "OUTPUT": str(out),
                                    "GROUND_OUTPUT": str(gout), "OUTPUT_HTML": str(html),
                                    "TILE_SIZE": 40, "THRESHOLD": 0.5, "MODE": 0})
    a, b = _all_dims_but(path, out)
    assert a.header.parse_crs() == b.header.parse_crs()
    cls = np.asarray(b.classification)
    # identical to the core on the same coordinates (noise pre-filter on by default;
    # the input's noise classes 7 and 18 kept, as by every registered filter)
    expect, core = _core_classes(t, tile_size=40, threshold=0.5, noise=True)
    assert np.array_equal(cls, expect)
    assert res["N_GROUND"] == np.sum(cls == 2) > 0
    assert res["N_OTHER"] == np.sum(cls == 1) and res["N_NOISE"] == np.sum(cls == 7)
    assert res["N_TILES"] == core.grid.count and res["POINTS_PER_SECOND"] > 0
    g = read_las(gout, ("classification",))
    assert len(g) == res["N_GROUND"] and np.all(g["classification"] == 2)
    text = html.read_text(encoding="utf-8")
    for word in ("ZMin", "σ", "iteration", "Parameters", "Filter speed (points/s)"):
        assert word in text
    # the faithful filter is conservative on this steep tile: few objects accepted
    acc = assess(cls == 2, t.classification == 2)
    assert acc.type2 < 2.0


def test_input_classes_ignored_but_noise_classes_kept(qgis_processing, tile, tmp_path):
    """Input ground/other classes play no part; input noise (7, 18) keeps its class."""
    path, t = tile
    pd = read_las(path, ("classification",))
    noise = np.isin(pd["classification"], (7, 18))
    assert noise.sum() >= 4
    outs = []
    for k, classes in enumerate((np.where(noise, pd["classification"], 2).astype(np.uint8),
                                 pd["classification"])):
        src = tmp_path / f"in{k}.las"
        write_las(src, pd.x, pd.y, pd.z, dimensions={"classification": classes})
        out = tmp_path / f"out{k}.las"
        qgis_processing.run(ALG, {"INPUT": str(src), "OUTPUT": str(out), "MODE": 1})
        outs.append(read_las(out, ("classification",))["classification"])
    assert np.array_equal(outs[0], outs[1])
    assert np.array_equal(outs[1][noise], pd["classification"][noise])


def test_improved_mode_and_advanced_parameters(qgis_processing, tile, tmp_path):
    import csv
    path, t = tile
    out, tiles_csv = tmp_path / "i.laz", tmp_path / "tiles.csv"
    res = qgis_processing.run(ALG, {"INPUT": str(path), "OUTPUT": str(out), "MODE": 1,
                                    "NOISE": False, "SUBSET_SIZE": 2000, "SEED": 5,
                                    "REJECTION": 1, "MAX_ITERATIONS": 8,
                                    "TILE_STATS": str(tiles_csv)})
    expect, core = _core_classes(t, mode="improved", noise=False, subset_size=2000,
                                 seed=5, rejection="cumulative", max_iterations=8)
    cls = read_las(out, ("classification",))["classification"]
    assert np.array_equal(cls, expect)
    assert res["N_NOISE"] == np.sum(cls == 7) == np.sum(t.classification == 7)   # kept
    rows = list(csv.DictReader(tiles_csv.open(encoding="utf-8")))
    assert len(rows) == int(np.sum(core.tile_iterations + 1))
    first = [r for r in rows if r["step"] == "0"]
    assert len(first) == core.grid.count
    assert sum(int(r["points"]) for r in first) == core.iteration_stats[0]["points"]
    assert "b1_x²_m" in rows[0] and "centre_x_m" in rows[0] and "zmean_m" in rows[0]


class _CancelAfter:
    """A feedback whose isCanceled() turns True after some progress reports."""

    def __new__(cls, after):
        from qgis.core import QgsProcessingFeedback

        class Fb(QgsProcessingFeedback):
            def __init__(self):
                super().__init__()
                self.calls = 0

            def setProgress(self, p):  # noqa: N802
                self.calls += 1
                if self.calls > after:
                    self.cancel()
                super().setProgress(p)
        return Fb()


@pytest.fixture(scope="module")
def n_progress_calls(qgis_processing, tile, tmp_path_factory):
    """How many progress reports a full run makes (reading, tiles, writing)."""
    path, _ = tile
    d = tmp_path_factory.mktemp("count")
    fb = _CancelAfter(10 ** 9)
    qgis_processing.run(ALG, {"INPUT": str(path), "OUTPUT": str(d / "c.laz"),
                              "GROUND_OUTPUT": str(d / "g.laz"),
                              "OUTPUT_HTML": str(d / "r.html")}, feedback=fb)
    return fb.calls


@pytest.mark.parametrize("fraction", [0.0, 0.3, 0.6, 0.95])
def test_cancel_leaves_no_output(qgis_processing, tile, tmp_path, fraction,
                                 n_progress_calls):
    """Cancelling while reading, filtering (per tile) or writing leaves no file."""
    from qgis.core import QgsProcessingException
    path, _ = tile
    assert n_progress_calls > 10
    after = min(int(fraction * n_progress_calls), n_progress_calls - 2)
    out, gout, html = tmp_path / "c.laz", tmp_path / "g.laz", tmp_path / "r.html"
    fb = _CancelAfter(after)
    with pytest.raises(QgsProcessingException, match="[Cc]ancel"):
        qgis_processing.run(ALG, {"INPUT": str(path), "OUTPUT": str(out),
                                  "GROUND_OUTPUT": str(gout), "OUTPUT_HTML": str(html)},
                            feedback=fb)
    assert fb.isCanceled()
    assert list(tmp_path.iterdir()) == []


def test_bad_input_clear_error_and_nothing_written(qgis_processing, tile, tmp_path):
    from qgis.core import QgsProcessingException
    path, _ = tile
    empty = tmp_path / "empty.las"
    write_las(empty, [], [], [])
    few = tmp_path / "few.las"
    write_las(few, [0, 1, 2, 3], [0, 2, 1, 3], [1, 2, 3, 4])
    cases = [({"INPUT": str(path), "THRESHOLD": 0}, "THRESHOLD"),
             ({"INPUT": str(path), "TILE_SIZE": 0}, "TILE_SIZE"),
             ({"INPUT": str(empty)}, "empty"),
             ({"INPUT": str(few)}, "Too few points"),
             ({"INPUT": str(path), "OUTPUT": str(path)}, "same file")]
    for params, match in cases:
        out = tmp_path / "never.laz"
        params = {"OUTPUT": str(out), "OUTPUT_HTML": str(tmp_path / "never.html"), **params}
        with pytest.raises(QgsProcessingException, match=match):
            qgis_processing.run(ALG, params)
        assert not out.exists() and not (tmp_path / "never.html").exists()


# ----------------------------------------------------------------------------- accuracy
def test_accuracy_against_reference_cloud_and_field(qgis_processing, tile, tmp_path):
    path, t = tile
    out = tmp_path / "c.laz"
    qgis_processing.run(ALG, {"INPUT": str(path), "OUTPUT": str(out)})
    cls = read_las(out, ("classification",))["classification"]
    expect = assess(cls == 2, t.classification == 2)
    html, err = tmp_path / "a.html", tmp_path / "err.laz"
    r = qgis_processing.run(ACC, {"INPUT": str(out), "REFERENCE": str(path),
                                  "OUTPUT_HTML": str(html), "ERROR_OUTPUT": str(err)})
    assert (r["A"], r["B"], r["C"], r["D"]) == (expect.a, expect.b, expect.c, expect.d)
    assert r["TOTAL"] == pytest.approx(expect.total)
    assert r["KAPPA"] == pytest.approx(expect.kappa)
    assert r["TYPE1"] == pytest.approx(expect.type1)
    codes = read_las(err, ("user_data",))["user_data"]
    assert np.sum(codes == 1) == expect.b and np.sum(codes == 2) == expect.c
    _all_dims_but(out, err, skip=("user_data",))
    assert "Type II" in html.read_text(encoding="utf-8")
    # the reference as a second dimension of the same file
    both = tmp_path / "both.las"
    write_las(both, t.x, t.y, t.z, dimensions={"classification": cls,
                                               "user_data": t.classification})
    r2 = qgis_processing.run(ACC, {"INPUT": str(both), "REFERENCE_FIELD": "user_data"})
    assert r2["TOTAL"] == pytest.approx(expect.total)


def test_accuracy_reference_of_different_length(qgis_processing, tile, tmp_path):
    from qgis.core import QgsProcessingException
    path, t = tile
    short = tmp_path / "short.las"
    write_las(short, t.x[:-3], t.y[:-3], t.z[:-3],
              dimensions={"classification": t.classification[:-3]})
    html, err = tmp_path / "a.html", tmp_path / "e.laz"
    with pytest.raises(QgsProcessingException, match="same points in the same order"):
        qgis_processing.run(ACC, {"INPUT": str(path), "REFERENCE": str(short),
                                  "OUTPUT_HTML": str(html), "ERROR_OUTPUT": str(err)})
    assert not html.exists() and not err.exists()
    with pytest.raises(QgsProcessingException, match="class"):
        qgis_processing.run(ACC, {"INPUT": str(path), "REFERENCE": str(path),
                                  "GROUND_CLASSES": "ground"})

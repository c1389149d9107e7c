"""geomatics:groundfilter and geomatics:ptdgroundfilter through processing.run."""
from __future__ import annotations

import re
from pathlib import Path

import laspy
import numpy as np
import pytest

REC = "geomatics:groundfilter"
PTD = "geomatics:ptdgroundfilter"


@pytest.fixture(scope="module")
def tile(tmp_path_factory):
    from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile
    t = generate_tile(extent=(80, 80), density=3.0, seed=5)
    path = tmp_path_factory.mktemp("ground") / "tile.laz"
    write_tile(t, path, crs="EPSG:32632")
    return path


class _Feedback:
    """A feedback recording progress that cancels after ``after`` reports."""

    def __new__(cls, after=10 ** 9):
        from qgis.core import QgsProcessingFeedback

        class Fb(QgsProcessingFeedback):
            def __init__(self):
                super().__init__()
                self.seen = []

            def setProgress(self, p):  # noqa: N802
                self.seen.append(p)
                if len(self.seen) > after:
                    self.cancel()
                super().setProgress(p)
        return Fb()


@pytest.mark.parametrize("alg", [REC, PTD])
def test_defaults_classify_and_keep_everything_else(qgis_processing, tile, tmp_path, alg):
    from geomatics_toolbox.core.lidar import ptd, recommended
    out, html = tmp_path / "c.laz", tmp_path / "r.html"
    fb = _Feedback()
    res = qgis_processing.run(alg, {"INPUT": str(tile), "OUTPUT": str(out),
                                    "OUTPUT_HTML": str(html)}, feedback=fb)
    a, b = laspy.read(str(tile)), laspy.read(str(out))
    for name in a.point_format.dimension_names:
        if name != "classification":
            assert np.array_equal(a[name], b[name]), name
    assert b.header.parse_crs() == a.header.parse_crs()
    cls = np.asarray(b.classification)
    kept = np.isin(np.asarray(a.classification), [7, 18])   # input noise keeps its class
    assert np.array_equal(cls[kept], np.asarray(a.classification)[kept])
    assert set(np.unique(cls[~kept])) <= {1, 2, 7}
    assert res["N_GROUND"] == np.count_nonzero(cls == 2) > 0
    assert res["N_NOISE"] == np.count_nonzero(cls == 7)
    # no pre-filter by default: exactly the core function's classes at its defaults
    x, y, z = (np.asarray(v, float)[~kept] for v in (a.x, a.y, a.z))
    core = recommended if alg == REC else ptd
    assert np.array_equal(cls[~kept], core.classify(x, y, z))
    if alg == PTD:
        assert ptd.TITLE in html.read_text(encoding="utf-8")
    assert fb.seen and fb.seen[-1] == pytest.approx(100.0)
    assert fb.seen == sorted(fb.seen)


@pytest.mark.parametrize("alg", [REC, PTD])
def test_cancel_clear_message_nothing_written(qgis_processing, tile, tmp_path, alg):
    from qgis.core import QgsProcessingException
    fb = _Feedback(after=3)
    with pytest.raises(QgsProcessingException, match="[Cc]ancel"):
        qgis_processing.run(alg, {"INPUT": str(tile), "OUTPUT": str(tmp_path / "c.laz"),
                                  "GROUND_OUTPUT": str(tmp_path / "g.laz"),
                                  "OUTPUT_HTML": str(tmp_path / "r.html")}, feedback=fb)
    assert fb.isCanceled()
    assert list(tmp_path.iterdir()) == []


def test_groundfilter_has_no_required_parameter_but_input_and_output(qgis_app):
    from qgis.core import QgsApplication, QgsProcessingParameterDefinition
    alg = QgsApplication.processingRegistry().algorithmById(REC)
    required = {p.name() for p in alg.parameterDefinitions()
                if not p.flags() & QgsProcessingParameterDefinition.FlagOptional
                and p.defaultValue() is None}
    assert required == {"INPUT", "OUTPUT"}
    text = alg.shortHelpString()
    assert "INPUT=tile.laz" in text
    # the help's ISPRS figure is the README's (one measured figure, stated twice)
    helped = re.search(r"ISPRS mean at the defaults (\d\.\d\d) %", text)
    readme = (Path(__file__).resolve().parents[2] / "README.md").read_text(encoding="utf-8")
    stated = re.search(r"ISPRS mean total error (\d\.\d\d) %", readme)
    assert helped and stated and helped.group(1) == stated.group(1)

"""The catalog in the dialog (issue 19): a file browser for the tiles, a log line per
tile, and a Cancel that says which finished tiles were kept for the resume."""
from __future__ import annotations

import pytest

from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile

ALG = "geomatics:catalog"


@pytest.fixture(scope="module")
def tiles(tmp_path_factory):
    d = tmp_path_factory.mktemp("cat_tiles")
    for i in range(3):
        t = generate_tile(extent=(60.0, 60.0), origin=(500_000.0 + 60 * i, 4_000_000.0),
                          density=1.0, seed=20 + i)
        write_tile(t, d / f"t{i}.laz")
    return d


class _Feedback:
    def __init__(self, cancel_after=None):
        from qgis.core import QgsProcessingFeedback

        class F(QgsProcessingFeedback):
            def __init__(self, sink):
                super().__init__()
                self.sink = sink

            def pushInfo(self, info):  # noqa: N802
                self.sink.lines.append(info)
                if (self.sink.cancel_after is not None and " done: " in info
                        and sum(" done: " in x for x in self.sink.lines)
                        >= self.sink.cancel_after):
                    self.cancel()

            def reportError(self, error, fatalError=False):  # noqa: N802,N803
                self.sink.errors.append(error)

        self.lines, self.errors, self.cancel_after = [], [], cancel_after
        self.feedback = F(self)


def test_tiles_input_is_a_file_list(qgis_app):
    """A file browser (Add File(s)… / Add Directory…), not a plain text box."""
    from qgis.core import QgsApplication, QgsProcessing, QgsProcessingContext
    from qgis.gui import QgsGui, QgsProcessingGui
    alg = QgsApplication.processingRegistry().algorithmById(ALG)
    param = alg.parameterDefinition("INPUT")
    assert param.type() == "multilayer" and param.layerType() == QgsProcessing.TypeFile
    wrapper = QgsGui.processingGuiRegistry().createParameterWidgetWrapper(
        param, QgsProcessingGui.Standard)
    widget = wrapper.createWrappedWidget(QgsProcessingContext())
    from qgis.PyQt.QtWidgets import QToolButton
    assert widget.findChildren(QToolButton)          # the "…" browser button


def test_file_list_folder_and_semicolons_give_the_same_catalog(qgis_processing, tiles,
                                                               tmp_path):
    files = [str(tiles / f"t{i}.laz") for i in range(3)]
    runs = {"list": files, "folder": str(tiles), "semicolons": ";".join(files)}
    for name, value in runs.items():
        fb = _Feedback()
        res = qgis_processing.run(ALG, {"INPUT": value, "GROUND_FILTER": 0,
                                        "CELL_SIZE": 2.0, "BUFFER": 20.0, "WORKERS": 1,
                                        "OUTPUT_FOLDER": str(tmp_path / name)},
                                  feedback=fb.feedback)
        assert res["N_TILES"] == 3 and res["N_FAILED"] == 0, name
        # one log line per tile
        done = sorted(x.split(" ")[1] for x in fb.lines if " done: " in x)
        assert done == ["t0", "t1", "t2"], fb.lines


def test_cancel_keeps_finished_tiles_and_says_so(qgis_processing, tiles, tmp_path):
    from qgis.core import QgsProcessingException
    out = tmp_path / "out"
    params = {"INPUT": str(tiles), "GROUND_FILTER": 0, "CELL_SIZE": 2.0, "BUFFER": 20.0,
              "WORKERS": 1, "OUTPUT_FOLDER": str(out)}
    fb = _Feedback(cancel_after=1)
    with pytest.raises(QgsProcessingException) as err:
        qgis_processing.run(ALG, params, feedback=fb.feedback)
    text = str(err.value)
    logged = [x.split(" ")[1] for x in fb.lines if " done: " in x]
    assert logged, fb.lines
    assert "no output was written" not in text
    n = int(text.split("Cancelled by the user. ")[1].split(" ")[0])
    # (tiles that finish while the cancel is being handled are kept and counted too)
    assert 1 <= n <= 3 and f"{n} finished tile(s) are kept in {out}" in text
    # the resume: exactly the tiles the message counted are logged as kept
    fb2 = _Feedback()
    res = qgis_processing.run(ALG, params, feedback=fb2.feedback)
    assert res["N_FAILED"] == 0
    kept = sorted(x.split(" ")[1].rstrip(":") for x in fb2.lines
                  if "finished by an earlier run" in x)
    assert len(kept) == n and set(logged) <= set(kept)
    ran = sorted(x.split(" ")[1] for x in fb2.lines if " done: " in x)
    assert sorted(kept + ran) == ["t0", "t1", "t2"]


@pytest.mark.parametrize("key", ["keep", "groundfilter"])
def test_terminate_keeps_finished_tiles_and_says_so(qgis_processing, tiles, tmp_path,
                                                    monkeypatch, key):
    """SIGTERM after tiles finished (Terminated from the catalog's sigterm_raises): the
    message names the kept tiles and the resume, not "no output was written"; with the
    recommended filter it says a kept tile may be classified again (its own canopy scale
    is kept until every tile has finished)."""
    from qgis.core import QgsProcessingException

    from geomatics_toolbox.algorithms import catalog as alg_catalog
    from geomatics_toolbox.core.io.contract import Terminated
    from geomatics_toolbox.core.lidar.filters import GROUND_FILTERS
    real = alg_catalog.core_cat.run_catalog

    def run_then_terminated(*args, **kwargs):
        real(*args, **kwargs)
        raise Terminated("Terminated by signal 15")
    monkeypatch.setattr(alg_catalog.core_cat, "run_catalog", run_then_terminated)
    out = tmp_path / "out"
    with pytest.raises(QgsProcessingException) as err:
        qgis_processing.run(ALG, {"INPUT": str(tiles), "CELL_SIZE": 2.0, "BUFFER": 20.0,
                                  "GROUND_FILTER": list(GROUND_FILTERS).index(key),
                                  "WORKERS": 1, "OUTPUT_FOLDER": str(out)},
                            feedback=_Feedback().feedback)
    text = str(err.value)
    assert "no output was written" not in text
    assert f"Terminated. 3 finished tile(s) are kept in {out}" in text
    again = ("A kept tile whose canopy scale differs from the whole catalog's is classified "
             "again by the resume.")
    assert (again in text) == (key == "groundfilter"), text


def test_tiles_classified_again_at_the_catalog_canopy_scale_are_logged(qgis_processing,
                                                                        tmp_path):
    """Two tiles of 0.3 and 1.5 pts/m² (the density step of
    tests/core/test_catalog_derived.py): alone the dense one closes its canopy at 3 cells,
    the catalog's counts give 6, so it is classified again; the log says which."""
    from geomatics_toolbox.core.lidar.filters import GROUND_FILTERS
    d = tmp_path / "tiles"
    d.mkdir()
    for i, rho in enumerate((0.3, 1.5)):
        write_tile(generate_tile(extent=(300.0, 300.0), origin=(500_000.0 + 300 * i,
                                                                 4_000_000.0),
                                 density=rho, seed=3 + i), d / f"t{i}.las")
    fb = _Feedback()
    res = qgis_processing.run(ALG, {"INPUT": str(d), "CELL_SIZE": 2.0, "BUFFER": 100.0,
                                    "GROUND_FILTER": list(GROUND_FILTERS).index("groundfilter"),
                                    "WORKERS": 1, "OUTPUT_FOLDER": str(tmp_path / "out")},
                              feedback=fb.feedback)
    assert res["N_TILES"] == 2 and res["N_FAILED"] == 0
    assert "1 tile(s) classified again at the canopy scale of the whole catalog: t1." in \
        fb.lines, fb.lines

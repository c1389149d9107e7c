"""Defaults that the cross-validation chose are the algorithms' defaults.

``benchmarks/bench_defaults.py`` picks, by leave-one-sample-out cross-validation on the
ISPRS samples, the low-outlier pre-filter (NOISE) of every ground filter and the mode of
the LSQ filter, and writes its choice into ``benchmarks/results/defaults.md``. Issue 19:
the same pre-filter was on in one filter and off in another with no reason given, and
``lsqgroundfilter`` defaulted to the mode its own help calls worse. Changing a default
(or a filter) without rerunning the cross-validation fails here.
"""
from __future__ import annotations

import json
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
RESULTS = ROOT / "benchmarks" / "results" / "defaults.md"
#: bench filter name -> (algorithm id, catalog registry key)
FILTERS = {"lsq faithful": ("lsqgroundfilter", "lsq_faithful"),
           "lsq improved": ("lsqgroundfilter", "lsq_improved"),
           "recommended": ("groundfilter", "groundfilter"),
           "ptd": ("ptdgroundfilter", "ptd"),
           "slope (exact)": ("slopegroundfilter", "slope_exact")}


def _chosen() -> dict:
    text = RESULTS.read_text(encoding="utf-8")
    match = re.search(r"<!-- defaults: (\{.*\}) -->", text)
    assert match, f"no machine-readable defaults line in {RESULTS}"
    return json.loads(match.group(1))


def test_noise_prefilter_defaults_follow_the_cross_validation(qgis_app):
    from qgis.core import QgsApplication

    from geomatics_toolbox.core.lidar.filters import default_selection
    chosen = _chosen()
    # every filter is either decided (its mean errors differ by >= 0.2 points) or a tie
    assert set(chosen["noise"]) | set(chosen["ties"]) == set(FILTERS)
    assert len(chosen["noise"]) >= 3
    for name, (alg_id, key) in FILTERS.items():
        alg = QgsApplication.processingRegistry().algorithmById(f"geomatics:{alg_id}")
        default = alg.parameterDefinition("NOISE").defaultValue()
        # the catalog's chunks use the same selection as the single-file algorithm
        assert default_selection(key).noise is default, key
        assert "cross-validation" in alg.shortHelpString()
        if name in chosen["noise"]:
            assert default is chosen["noise"][name], (alg_id, chosen["noise"][name])
    # lidartodtm / the model follow the recommended filter
    l2d = QgsApplication.processingRegistry().algorithmById("geomatics:lidartodtm")
    rec = QgsApplication.processingRegistry().algorithmById("geomatics:groundfilter")
    if l2d is not None:
        assert (l2d.parameterDefinition("NOISE").defaultValue()
                is rec.parameterDefinition("NOISE").defaultValue())


def test_lsq_mode_default_follows_the_cross_validation(qgis_app):
    from qgis.core import QgsApplication
    alg = QgsApplication.processingRegistry().algorithmById("geomatics:lsqgroundfilter")
    param = alg.parameterDefinition("MODE")
    want = {"faithful": 0, "improved": 1}[_chosen()["lsq_mode"]]
    assert param.defaultValue() == want
    assert param.options()[want].lower().startswith(_chosen()["lsq_mode"])

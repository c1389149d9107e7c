"""`qgis_process run geomatics:ptdgroundfilter -- INPUT=x.laz OUTPUT=y.laz`: the algorithm's
defaults are the core's (same classes, bit for bit, as ``ptd.classify`` at its defaults)."""
from __future__ import annotations

import hashlib

import laspy
import numpy as np
import pytest

SAMPLES = ["samp11", "samp12", "samp22", "samp31", "samp41", "samp53", "samp54", "samp61"]


#: sha1 of the uint8 classes and total error (%) of ``ptd.classify`` at its defaults (the
#: same as RESEARCH in tests/core/test_ground_filters.py).
GOLDEN = {
    "samp11": ("6aaf341d3e0b4caf6dc7ee49f5c243fe09fa76b6", 14.7645),
    "samp12": ("4c190f7e34b4d6f196656641a151a20d23b1a056", 2.9740),
    "samp22": ("ad6fd3c1239102ff680f7283bde6dd7c9583f364", 6.9314),
    "samp31": ("85aef58e831486de589b5580e36eda33635e2b58", 1.4795),
    "samp41": ("cdf42b5ac3ff21d63c9dd079bb63548c25b6046f", 2.1458),
    "samp53": ("06acb142e53e78594531febef92f51e4fd72e7dd", 11.4405),
    "samp54": ("5f57175b81aa241d185e16429ec6d47aafa8fc30", 3.4503),
    "samp61": ("5f0cae6fcf89ba97b9581379c1f36f540e868525", 3.4313),
}


@pytest.mark.slow
@pytest.mark.parametrize("sample", SAMPLES)
def test_cli_ptd_isprs_defaults_equal_the_core(qgis_process, isprs_dir, tmp_path, sample):
    from geomatics_toolbox.core.lidar.accuracy import assess
    src, out = isprs_dir / f"{sample}.laz", tmp_path / f"{sample}.laz"
    res = qgis_process.run("geomatics:ptdgroundfilter", INPUT=src, OUTPUT=out)["results"]
    a, b = laspy.read(str(src)), laspy.read(str(out))
    cls = np.asarray(b.classification)
    assert res["N_GROUND"] == np.count_nonzero(cls == 2)
    sha, total = GOLDEN[sample]
    assert assess(cls == 2, np.asarray(a.classification) == 2).total == pytest.approx(
        total, abs=1e-3)
    assert hashlib.sha1(cls.tobytes()).hexdigest() == sha

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
    "samp11": ("7f17415a797e10feddea1ec1cfa955a20946ff6d", 12.5572),
    "samp12": ("faf2b5ca1e85237a65c334af1973a2e2efd65fb6", 3.3078),
    "samp22": ("dbd610b413169c0e2d5c5a4631d26339dc2c45cd", 3.7914),
    "samp31": ("bd3519bd8fe56b252f57b13d2cb3db5b20f6610d", 2.0685),
    "samp41": ("7fa0b24c8c8973c3179969b1f14c4dce0cd645ae", 5.3691),
    "samp53": ("109d2f324b9efec24c326874213f19a8e0ebc849", 4.3633),
    "samp54": ("0b17ecbe5410050229e43a6bc717649725984bfc", 3.2993),
    "samp61": ("b88d850d46b17a01bdf957f7c13be612bd1ad762", 2.5128),
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

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
    "samp11": ("eb74f4d97c49d7315bea7b45274d038775819844", 9.0108),
    "samp12": ("7984a75a1a948f262cee25cb0d09456ef5408b87", 3.3500),
    "samp22": ("bcd9758928efff5c6287927440836cad17dddddb", 6.1426),
    "samp31": ("0ac7d976f5bfd602ff8f11f803e7ec49c3f23f47", 2.0927),
    "samp41": ("78144b761d04118a85e80e27655a330882fe5314", 2.6178),
    "samp53": ("53ae907716fd725532950d5ea35fd3ec3bed579c", 6.7340),
    "samp54": ("0d4d684fe523b6cff88a63e3282113144004da87", 3.1947),
    "samp61": ("5060bef3cc5e3cefa26877e0d8c71d90f3dd87f5", 2.8950),
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

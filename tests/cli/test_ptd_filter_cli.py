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
    "samp11": ("983b1075164a6726c3d2db4e61b76a827592368c", 12.1889),
    "samp12": ("0a819e9b934d7019d4ddf2954a63c9756187e496", 3.1390),
    "samp22": ("9b8c85b1faa7d58fdcb0cbd3970515d33b4fc644", 3.6354),
    "samp31": ("bb7950614bc0d233c813a97e4de7d4b32c3b133a", 1.7636),
    "samp41": ("308016efc6d2038f6b8e30c45fe4f1f033fcd309", 5.4670),
    "samp53": ("153ff4fcf22ff71a653f4c0d3c7cb8e0dfb68b09", 4.4185),
    "samp54": ("0b17ecbe5410050229e43a6bc717649725984bfc", 3.2993),
    "samp61": ("c1d38c4f89aeb685b3b04a5dd2bb5538dc2d810c", 2.5043),
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

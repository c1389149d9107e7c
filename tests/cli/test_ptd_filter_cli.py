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
    "samp11": ("88005880827f34f175a72ba706904e1c3661137f", 12.1073),
    "samp12": ("893367d8abfffd331ec539dc07dfa0862a00fad5", 3.2579),
    "samp22": ("bced947985aa01718d06edf889ca701706843495", 3.7027),
    "samp31": ("cc6cbc919c59bfcae9d4a18eb7a230f8000266ac", 2.0061),
    "samp41": ("8fc28f6c7d15b6ab7d63de0fb94a4901ecdcc0a2", 5.3245),
    "samp53": ("316f8a9f1dab66a0898c2f1294123e51d370e2c5", 4.3982),
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

"""`qgis_process run geomatics:groundfilter -- INPUT=x.laz OUTPUT=y.laz`, nothing else."""
from __future__ import annotations

import laspy
import numpy as np
import pytest

SAMPLES = ["samp11", "samp12", "samp22", "samp31", "samp41", "samp53", "samp54", "samp61"]
#: Total error (%) of the recommended defaults, measured with the research code
#: (/work/scratch/g3: tangent-plane hole fill, detrending, continuity growing).
TOTALS = {"samp11": 8.5925, "samp12": 2.8205, "samp22": 2.7243, "samp31": 1.2681,
          "samp41": 2.5376, "samp53": 3.5022, "samp54": 2.5209, "samp61": 2.2305}


@pytest.mark.slow
@pytest.mark.parametrize("sample", SAMPLES)
def test_cli_groundfilter_isprs_no_parameter(qgis_process, isprs_dir, tmp_path, sample):
    from geomatics_toolbox.core.lidar.accuracy import assess
    src, out = isprs_dir / f"{sample}.laz", tmp_path / f"{sample}.laz"
    res = qgis_process.run("geomatics:groundfilter", INPUT=src, OUTPUT=out)["results"]
    a, b = laspy.read(str(src)), laspy.read(str(out))
    cls = np.asarray(b.classification)
    assert res["N_GROUND"] == np.count_nonzero(cls == 2)
    acc = assess(cls == 2, np.asarray(a.classification) == 2)
    assert acc.total == pytest.approx(TOTALS[sample], abs=1e-3)


def test_cli_groundfilter_demo_tile(qgis_process, tmp_path):
    import subprocess
    import sys
    from pathlib import Path
    root = Path(__file__).resolve().parents[2]
    subprocess.run([sys.executable, str(root / "scripts" / "make_demo_data.py"), "--out",
                    str(tmp_path / "demo")], check=True, capture_output=True)
    src, out = tmp_path / "demo" / "demo.laz", tmp_path / "c.laz"
    res = qgis_process.run("geomatics:groundfilter", INPUT=src, OUTPUT=out)["results"]
    a, b = laspy.read(str(src)), laspy.read(str(out))
    cls = np.asarray(b.classification)
    assert res["N_POINTS"] == len(a.points) == len(cls)
    truth = np.asarray(a.classification) == 2
    from geomatics_toolbox.core.lidar.accuracy import assess
    assert assess(cls == 2, truth).total < 2.0

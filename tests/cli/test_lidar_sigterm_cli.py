"""SIGTERM while the LSQ filter writes 8 M points leaves nothing behind (issue 9)."""
from __future__ import annotations

import os
import signal
import subprocess
import time

import numpy as np
import pytest

from geomatics_toolbox.core.io.las import write_las


@pytest.fixture(scope="session")
def big_cloud(tmp_path_factory):
    """About 8 M points of gently sloping ground with noise, generated once."""
    rng = np.random.default_rng(0)
    n = 8_000_000
    x = 500_000 + rng.uniform(0, 1000, n)
    y = 4_000_000 + rng.uniform(0, 1000, n)
    z = 100 + 0.01 * (x - 500_000) + rng.normal(0, 0.1, n)
    path = tmp_path_factory.mktemp("big") / "big.las"
    write_las(path, x, y, z, crs="EPSG:32632")
    return path


@pytest.mark.slow
def test_sigterm_while_writing_leaves_nothing(qgis_process, big_cloud, tmp_path):
    out_dir = tmp_path / "out"
    out_dir.mkdir()
    before = big_cloud.stat()
    with open(big_cloud, "rb") as fh:
        digest = hash(fh.read())
    args = [qgis_process.exe, "--json", "run", "geomatics:lsqgroundfilter", "--",
            f"INPUT={big_cloud}", f"OUTPUT={out_dir / 'o.las'}", "NOISE=false",
            "MODE=0"]   # faithful: the fast mode (the default improved one is ~15x slower)
    proc = subprocess.Popen(args, env=qgis_process.env, stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL)
    try:
        deadline = time.monotonic() + 240
        seen = []
        while time.monotonic() < deadline and proc.poll() is None:
            seen = [p for p in os.listdir(out_dir) if ".part" in p]
            if seen and os.path.getsize(out_dir / seen[0]) > 1_000_000:
                break
            time.sleep(0.05)
        assert seen, "the run never started writing (or finished before the signal)"
        proc.send_signal(signal.SIGTERM)
        proc.wait(timeout=120)
    finally:
        if proc.poll() is None:
            proc.kill()
            proc.wait()
    assert proc.returncode != 0
    assert os.listdir(out_dir) == []                      # no temporary, no output
    assert big_cloud.stat().st_size == before.st_size
    with open(big_cloud, "rb") as fh:
        assert hash(fh.read()) == digest

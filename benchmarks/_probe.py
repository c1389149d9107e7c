"""Wall time, CPU time and peak memory of one measured step in a benchmark child process.

Peak memory is the peak resident set (``VmHWM``) after resetting the mark through
``/proc/self/clear_refs`` (Linux >= 4.0), so it covers the measured step plus the
baseline already resident; ``ru_maxrss`` is the fallback (it also counts the forked
parent's pre-exec peak, so it overstates).
"""
import json
import os
import resource
import subprocess
import sys
import time


def _status_mb(key):
    with open("/proc/self/status") as fh:
        for line in fh:
            if line.startswith(key + ":"):
                return float(line.split()[1]) / 1024.0
    return float("nan")


class Probe:
    """``p = Probe()`` just before the step, ``p.result()`` just after."""

    def __init__(self):
        self.base_mb = _status_mb("VmRSS")
        try:
            with open("/proc/self/clear_refs", "w") as fh:
                fh.write("5")
            self._hwm = True
        except OSError:
            self._hwm = False
        self._r0 = resource.getrusage(resource.RUSAGE_SELF)
        self._t0 = time.perf_counter()

    def result(self) -> dict:
        wall = time.perf_counter() - self._t0
        r1 = resource.getrusage(resource.RUSAGE_SELF)
        cpu = (r1.ru_utime - self._r0.ru_utime) + (r1.ru_stime - self._r0.ru_stime)
        peak = _status_mb("VmHWM") if self._hwm else r1.ru_maxrss / 1024.0
        return dict(wall=wall, cpu=cpu, base_mb=self.base_mb, peak_mb=peak)


def run_python(code: str) -> dict:
    """Run ``code`` in a fresh single-threaded interpreter; return its last JSON line."""
    env = dict(os.environ, OMP_NUM_THREADS="1", OPENBLAS_NUM_THREADS="1",
               MKL_NUM_THREADS="1")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         env=env, check=False)
    if out.returncode != 0:
        raise RuntimeError(out.stderr)
    return json.loads(out.stdout.strip().splitlines()[-1])

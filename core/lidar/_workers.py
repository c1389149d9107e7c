"""A local Dask cluster whose workers run in the real Python interpreter, on every platform.

``LocalCluster(processes=True)`` starts its workers with ``multiprocessing``'s spawn,
which runs ``sys.executable``: inside QGIS that is ``qgis-bin.exe`` (Windows) or the
``QGIS`` application binary (macOS), not a Python. Changing that takes
``multiprocessing.set_executable``, which changes it for every other plugin in the
QGIS process too. Instead the scheduler runs here (port 0: a free port) and the
workers are one ``python -m distributed.cli.dask_worker`` child process started with
the interpreter :func:`..system.python_executable` finds (``python.exe`` in
OSGeo4W's ``apps/PythonXY``, ``bin/python3`` in the macOS bundle, ``bin/pythonX.Y``
on Linux) and an environment built for it alone: ``PYTHONPATH`` naming the folder
that holds the plugin and the plugin's private package folder, one thread per BLAS
and Rust pool, and this process's Dask configuration (``DASK_INTERNAL_INHERIT_CONFIG``).
Nothing in this process's environment or interpreter state is changed. Inside that
child the nannies restart a crashed worker and enforce ``memory_limit`` as before.
"""
from __future__ import annotations

import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path
from typing import Dict, Optional

from .. import deps
from ..errors import InputError
from ..system import no_window_flag, python_executable

#: one worker = one core: thread pools of the native libraries limited to one thread
SINGLE_THREAD_ENV = {"RAYON_NUM_THREADS": "1", "OMP_NUM_THREADS": "1",
                     "OPENBLAS_NUM_THREADS": "1", "MKL_NUM_THREADS": "1"}
START_TIMEOUT = 180.0


def _package_parent() -> Optional[str]:
    """Folder holding this package under its import name (e.g. the QGIS plugins folder)."""
    pkg_dir = Path(os.path.abspath(__file__)).parents[2]
    name = __name__.split(".")[0]
    return str(pkg_dir.parent) if pkg_dir.name == name else None


def worker_environment(base: Optional[Dict[str, str]] = None,
                       config: Optional[dict] = None) -> Dict[str, str]:
    """Environment of the worker process (a new dict; ``os.environ`` is not changed)."""
    env = dict(os.environ if base is None else base)
    parts = [p for p in env.get("PYTHONPATH", "").split(os.pathsep) if p]
    # the plugin's private package folder, activated at plugin start (:mod:`..deps`)
    front = [p for p in [_package_parent(), *deps.WORKER_PATHS] if p and p not in parts]
    env["PYTHONPATH"] = os.pathsep.join(front + parts)
    env.update(SINGLE_THREAD_ENV)
    if config is not None:
        import dask
        env["DASK_INTERNAL_INHERIT_CONFIG"] = dask.config.serialize(config)
    return env


class LocalWorkers:
    """A scheduler in this process and its workers in one child process.

    ``close()`` shuts the workers down through the scheduler, then stops the child
    (terminate, then kill) if it is still there.
    """

    def __init__(self, cluster, process: subprocess.Popen, log):
        self.cluster = cluster
        self.process = process
        self._log = log

    @property
    def scheduler_address(self) -> str:
        return self.cluster.scheduler_address

    def log_tail(self, nbytes: int = 4000) -> str:
        """Return the end of the workers' log (for error messages)."""
        try:
            self._log.flush()
            self._log.seek(0)
            return self._log.read().decode("utf-8", "replace")[-nbytes:]
        except (OSError, ValueError):
            return ""

    def close(self) -> None:
        from distributed import Client
        try:
            if self.process.poll() is None:
                with Client(self.cluster, timeout="20s") as client:
                    client.retire_workers(close_workers=True)
        except Exception:  # noqa: BLE001 - stopping the child below in any case
            pass
        try:
            self.process.wait(timeout=30)
        except subprocess.TimeoutExpired:
            self.process.terminate()
            try:
                self.process.wait(timeout=15)
            except subprocess.TimeoutExpired:
                self.process.kill()
                self.process.wait(timeout=15)
        finally:
            self.cluster.close()
            self._log.close()


def start_local_workers(n_workers: int, *, memory_limit="auto",
                        config: Optional[dict] = None, python: Optional[str] = None,
                        timeout: float = START_TIMEOUT) -> LocalWorkers:
    """Start a scheduler here and ``n_workers`` single-threaded workers in a child process.

    Raises :class:`InputError` when no Python interpreter can be found or the workers
    do not start (with the end of their log).
    """
    import dask
    from distributed import Client, LocalCluster

    exe = python or python_executable()
    if exe is None:
        raise InputError("No Python interpreter was found to start the Dask workers "
                         "(looked beside {exe} and in {prefix}); give a Dask scheduler "
                         "address instead.", exe=sys.executable, prefix=sys.base_exec_prefix)
    with dask.config.set(config or {}):
        cluster = LocalCluster(n_workers=0, processes=True, host="127.0.0.1",
                               scheduler_port=0, dashboard_address=None, silence_logs=40,
                               scheduler_kwargs={"dashboard_address": "127.0.0.1:0"})
    env = worker_environment(config=config or {})
    limit = "0" if memory_limit in (None, 0) else str(memory_limit)
    cmd = [exe, "-m", "distributed.cli.dask_worker", cluster.scheduler_address,
           "--nworkers", str(int(n_workers)), "--nthreads", "1", "--memory-limit", limit,
           "--no-dashboard", "--host", "127.0.0.1"]
    log = tempfile.TemporaryFile()
    try:
        proc = subprocess.Popen(cmd, env=env, stdin=subprocess.DEVNULL,
                                stdout=subprocess.DEVNULL, stderr=log,
                                creationflags=no_window_flag())
    except OSError as exc:
        cluster.close()
        log.close()
        raise InputError("Cannot start the Dask workers with {exe}: {exc}", exe=exe,
                         exc=exc) from exc
    workers = LocalWorkers(cluster, proc, log)
    try:
        with Client(cluster, timeout="30s") as client:
            deadline = time.monotonic() + timeout
            while len(client.nthreads()) < n_workers:
                if proc.poll() is not None or time.monotonic() > deadline:
                    raise InputError("The local Dask workers did not start ({exe}); their "
                                     "log ends with: {log}", exe=exe,
                                     log=workers.log_tail())
                time.sleep(0.1)
    except BaseException:
        workers.close()
        raise
    return workers

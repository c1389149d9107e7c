"""Portable machine facts (core/system.py) and the catalog's local workers (_workers.py)."""
from __future__ import annotations

import multiprocessing
import os
import stat
import sys

import numpy as np
import pytest

from geomatics_toolbox.core import deps, system
from geomatics_toolbox.core.lidar import _workers


def _touch(path, text="") -> str:
    os.makedirs(os.path.dirname(path), exist_ok=True)
    with open(path, "w", encoding="utf-8") as fh:
        fh.write(text)
    os.chmod(path, os.stat(path).st_mode | stat.S_IEXEC)
    return str(path)


def _fake_interpreter(monkeypatch, *, executable, prefix, platform):
    monkeypatch.setattr(sys, "executable", str(executable))
    for name in ("exec_prefix", "base_exec_prefix", "prefix", "base_prefix"):
        monkeypatch.setattr(sys, name, str(prefix))
    monkeypatch.setattr(sys, "platform", platform)


def test_osgeo4w_layout_finds_python_exe_not_qgis_bin(tmp_path, monkeypatch):
    root = tmp_path / "OSGeo4W"
    qgis = _touch(root / "bin" / "qgis-bin.exe")
    _touch(root / "bin" / "python-qgis.bat")
    py = _touch(root / "apps" / "Python39" / "python.exe")
    _fake_interpreter(monkeypatch, executable=qgis, prefix=root / "apps" / "Python39",
                      platform="win32")
    assert system.interpreter_candidates()[0] == py
    assert system.python_executable(verify=False) == py


def test_pythonw_prefers_its_console_sibling(tmp_path, monkeypatch):
    root = tmp_path / "Python312"
    pyw = _touch(root / "pythonw.exe")
    py = _touch(root / "python.exe")
    _fake_interpreter(monkeypatch, executable=pyw, prefix=root, platform="win32")
    assert system.interpreter_candidates()[:2] == [py, pyw]
    assert system.python_executable(verify=False) == py


def test_macos_bundle_finds_bin_python3(tmp_path, monkeypatch):
    app = tmp_path / "QGIS.app" / "Contents"
    qgis = _touch(app / "MacOS" / "QGIS")
    ver = f"{sys.version_info[0]}.{sys.version_info[1]}"
    fw = app / "Frameworks" / "Python.framework" / "Versions" / ver
    py = _touch(fw / "bin" / f"python{ver}")
    _fake_interpreter(monkeypatch, executable=qgis, prefix=fw, platform="darwin")
    assert system.python_executable(verify=False) == py
    os.remove(py)                          # the official bundle: Contents/MacOS/bin/python3
    py2 = _touch(app / "MacOS" / "bin" / "python3")
    assert system.python_executable(verify=False) == py2


def test_embedded_linux_qgis_finds_the_system_interpreter(monkeypatch):
    """qgis_process.bin embeds /usr/bin/python3.X: the real one runs and answers."""
    real = os.path.join(sys.base_exec_prefix, "bin",
                        f"python{sys.version_info[0]}.{sys.version_info[1]}")
    if not os.path.exists(real):
        pytest.skip(f"{real} not present")
    monkeypatch.setattr(sys, "executable", "/usr/bin/qgis_process.bin")
    for name in ("exec_prefix", "prefix"):
        monkeypatch.setattr(sys, name, sys.base_exec_prefix)
    assert system.python_executable() == real


def test_a_python_of_another_version_is_refused(tmp_path, monkeypatch):
    other = _touch(tmp_path / "bin" / "python3", "#!/bin/sh\necho '((2, 7, 18), \"/usr\")'\n")
    _fake_interpreter(monkeypatch, executable=tmp_path / "qgis", prefix=tmp_path,
                      platform="linux")
    assert system.python_executable(verify=False) == other
    assert system.python_executable() is None


def test_another_installation_of_the_same_version_is_refused(tmp_path, monkeypatch):
    """Embedded Python on Linux: sys.executable = the first python3 on PATH (a pyenv
    shim, conda) — same version, other packages: refused, the prefix's one is taken."""
    same_version = repr((tuple(sys.version_info[:3]), "/root/.pyenv/versions/x"))
    shim = _touch(tmp_path / "shims" / "python3", f"#!/bin/sh\necho \"{same_version}\"\n")
    real = os.path.join(sys.base_exec_prefix, "bin",
                        f"python{sys.version_info[0]}.{sys.version_info[1]}")
    if not os.path.exists(real):
        pytest.skip(f"{real} not present")
    monkeypatch.setattr(sys, "executable", shim)
    for name in ("exec_prefix", "prefix"):
        monkeypatch.setattr(sys, name, sys.base_exec_prefix)
    assert system.interpreter_candidates()[0] == shim
    assert system.python_executable() == real


def test_memory_figures_are_positive_and_consistent():
    mem = system.available_memory()
    assert 64 << 20 < mem < 1 << 50
    peak = system.peak_rss_mb()
    assert 10 < peak < mem / 1048576.0 * 4


def test_memory_fallback_without_psutil(monkeypatch):
    monkeypatch.setattr(system, "_psutil", lambda: None)
    mem = system.available_memory()
    assert mem > 64 << 20
    monkeypatch.setattr(sys, "platform", "win32")          # no windll here: 4 GiB
    assert system.available_memory() == system.FALLBACK_MEMORY


def test_blas_threads_limited_inside_and_restored_after(monkeypatch):
    np.linalg.solve(np.eye(2), np.ones(2))
    monkeypatch.setitem(sys.modules, "threadpoolctl", None)   # the fallback path
    monkeypatch.setattr(system, "_SETTERS", None)
    setters = system._loaded_openblas()
    if not setters:
        pytest.skip("no OpenBLAS loaded in this process")
    before = [get() for get, _ in setters]
    with system.limit_blas_threads(1):
        assert [get() for get, _ in setters] == [1] * len(setters)
        assert np.allclose(np.linalg.solve(np.eye(3) * 4, np.ones(3)), 0.25)
    assert [get() for get, _ in setters] == before


def test_worker_environment_is_a_copy_with_the_plugin_paths(monkeypatch, tmp_path):
    monkeypatch.setattr(deps, "WORKER_PATHS", [str(tmp_path / "packages")])
    monkeypatch.setattr(_workers, "_package_parent", lambda: str(tmp_path / "plugins"))
    before = dict(os.environ)
    env = _workers.worker_environment({"PYTHONPATH": "/x", "PATH": "/bin"},
                                      config={"distributed.admin.tick.interval": "1s"})
    assert dict(os.environ) == before
    assert env["PYTHONPATH"].split(os.pathsep) == [str(tmp_path / "plugins"),
                                                   str(tmp_path / "packages"), "/x"]
    assert env["OMP_NUM_THREADS"] == "1" and env["RAYON_NUM_THREADS"] == "1"
    import dask
    cfg = dask.config.deserialize(env["DASK_INTERNAL_INHERIT_CONFIG"])
    assert cfg == {"distributed.admin.tick.interval": "1s"}


def test_local_workers_leave_interpreter_state_alone(monkeypatch):
    """Workers start from the real interpreter; set_executable and os.environ untouched."""
    pytest.importorskip("distributed")

    def refuse(*args, **kwargs):
        raise AssertionError("multiprocessing.set_executable called")

    monkeypatch.setattr(multiprocessing, "set_executable", refuse)
    env_before = dict(os.environ)
    workers = _workers.start_local_workers(2, memory_limit=None)
    try:
        from distributed import Client
        with Client(workers.cluster, timeout="30s") as client:
            info = client.run(lambda: (os.environ.get("OMP_NUM_THREADS"),
                                       __import__("sys").executable))
            assert len(info) == 2
            for omp, exe in info.values():
                assert omp == "1" and os.path.basename(exe).startswith("python")
            assert client.submit(lambda: 6 * 7).result(timeout=60) == 42
    finally:
        workers.close()
    assert workers.process.poll() is not None
    assert dict(os.environ) == env_before


def test_windows_memory_from_global_memory_status(monkeypatch):
    """Windows without psutil: GlobalMemoryStatusEx's ullAvailPhys (kernel32 stand-in)."""
    import ctypes
    calls = []

    class Kernel32:
        @staticmethod
        def GlobalMemoryStatusEx(ref):  # noqa: N802 - the Windows API name
            status = ref._obj
            calls.append(status.dwLength)
            status.ullAvailPhys = 6 << 30
            status.ullTotalPhys = 16 << 30
            return 1

    class WinDLL:
        kernel32 = Kernel32()

    monkeypatch.setattr(ctypes, "windll", WinDLL(), raising=False)
    monkeypatch.setattr(system, "_psutil", lambda: None)
    monkeypatch.setattr(sys, "platform", "win32")
    assert system.available_memory() == 6 << 30
    assert calls == [64]                      # sizeof(MEMORYSTATUSEX) on every Windows


def test_release_free_memory_is_glibc_only_and_harmless_elsewhere(monkeypatch):
    """malloc_trim on Linux/glibc; on Windows or macOS no C library is opened, False."""
    import ctypes
    monkeypatch.setattr(system, "_TRIM", None)
    if sys.platform.startswith("linux"):
        try:
            want = callable(ctypes.CDLL("libc.so.6").malloc_trim)
        except (OSError, AttributeError):            # musl or another C library
            want = False
        assert system.release_free_memory() is want
        assert system.release_free_memory() is want     # looked up once, callable again
    for platform in ("win32", "darwin"):
        monkeypatch.setattr(system, "_TRIM", None)
        monkeypatch.setattr(system.sys, "platform", platform)

        def no_cdll(*a, **k):
            raise AssertionError("no C library opened off Linux")
        monkeypatch.setattr(system.ctypes, "CDLL", no_cdll)
        assert system.release_free_memory() is False
        assert system._TRIM == []

"""Facts about the machine and the interpreter, the same way on Windows, macOS and Linux.

The QGIS process loads this package on every platform QGIS runs on, so nothing here
imports a POSIX-only module at module level or reads a Linux-only file: each figure
comes from ``psutil`` / ``threadpoolctl`` when they are installed (``distributed``
brings ``psutil``), else from a guarded standard-library fallback per platform.

* :func:`available_memory` — bytes of memory a new array can use;
* :func:`peak_rss_mb` — peak resident memory of this process;
* :func:`release_free_memory` — hand freed heap pages back (glibc ``malloc_trim``);
* :func:`limit_blas_threads` — run a block with one BLAS thread;
* :func:`python_executable` — the real Python interpreter (inside QGIS
  ``sys.executable`` is ``qgis-bin.exe`` on Windows and the ``QGIS`` binary on macOS),
  for ``python -m pip`` and for Dask worker processes.

Examples
--------
>>> available_memory() > 0
True
>>> peak_rss_mb() > 0 or peak_rss_mb() != peak_rss_mb()   # MiB, or NaN when unknown
True
"""
from __future__ import annotations

import contextlib
import ctypes
import functools
import glob
import os
import subprocess
import sys
from typing import Iterator, List, Optional

#: used when nothing tells the available memory (no psutil, no platform call)
FALLBACK_MEMORY = 4 << 30


def _psutil():
    try:
        import psutil
    except Exception:  # noqa: BLE001 - absent, or broken on this platform: fall back
        return None
    return psutil


# ---------------------------------------------------------------------------- memory
def available_memory() -> int:
    """Bytes of physical memory available to a new allocation.

    ``psutil.virtual_memory().available`` when psutil is installed; else
    ``GlobalMemoryStatusEx`` on Windows, ``sysconf`` on other systems (the free pages
    where the system reports them, else the physical memory), else 4 GiB.
    """
    ps = _psutil()
    if ps is not None:
        with contextlib.suppress(Exception):
            return int(ps.virtual_memory().available)
    if sys.platform == "win32":
        with contextlib.suppress(Exception):
            return _windows_memory_status().ullAvailPhys
        return FALLBACK_MEMORY
    sysconf = getattr(os, "sysconf", None)
    for name in ("SC_AVPHYS_PAGES", "SC_PHYS_PAGES"):
        with contextlib.suppress(ValueError, OSError, TypeError):
            pages = int(sysconf(name)) if sysconf else -1
            size = int(sysconf("SC_PAGE_SIZE")) if sysconf else -1
            if pages > 0 and size > 0:
                return pages * size
    return FALLBACK_MEMORY


def _windows_memory_status():
    class MemoryStatusEx(ctypes.Structure):
        _fields_ = [("dwLength", ctypes.c_uint32), ("dwMemoryLoad", ctypes.c_uint32),
                    ("ullTotalPhys", ctypes.c_ulonglong), ("ullAvailPhys", ctypes.c_ulonglong),
                    ("ullTotalPageFile", ctypes.c_ulonglong),
                    ("ullAvailPageFile", ctypes.c_ulonglong),
                    ("ullTotalVirtual", ctypes.c_ulonglong),
                    ("ullAvailVirtual", ctypes.c_ulonglong),
                    ("ullAvailExtendedVirtual", ctypes.c_ulonglong)]

    status = MemoryStatusEx()
    status.dwLength = ctypes.sizeof(MemoryStatusEx)
    if not ctypes.windll.kernel32.GlobalMemoryStatusEx(ctypes.byref(status)):
        raise OSError("GlobalMemoryStatusEx failed")
    return status


def peak_rss_mb() -> float:
    """Peak resident memory of this process in MiB (NaN when the system does not say).

    ``resource.getrusage`` where it exists (kilobytes on Linux, bytes on macOS), else
    psutil's peak working set (Windows) or current resident size.
    """
    try:
        import resource  # POSIX only: guarded, never at module level
    except ImportError:
        resource = None
    if resource is not None:
        peak = float(resource.getrusage(resource.RUSAGE_SELF).ru_maxrss)
        return peak / 1048576.0 if sys.platform == "darwin" else peak / 1024.0
    ps = _psutil()
    if ps is not None:
        with contextlib.suppress(Exception):
            info = ps.Process().memory_info()
            return float(getattr(info, "peak_wset", info.rss)) / 1048576.0
    return float("nan")


_TRIM: Optional[list] = None


def release_free_memory() -> bool:
    """Hand the allocator's free pages back to the system; True when that was done.

    glibc keeps memory freed by large numpy temporaries inside its heap (scattered free
    chunks cannot be returned from the top), so a long raster pipeline's resident size
    keeps the high-water mark of every step; ``malloc_trim(0)`` releases those pages
    (the memory stays reusable). glibc only, looked up once through ``ctypes``: on
    Windows, macOS or another C library it does nothing and returns False.
    """
    global _TRIM
    if _TRIM is None:
        _TRIM = []
        if sys.platform.startswith("linux"):
            with contextlib.suppress(OSError, AttributeError, TypeError):
                fn = ctypes.CDLL("libc.so.6").malloc_trim
                fn.argtypes, fn.restype = [ctypes.c_size_t], ctypes.c_int
                _TRIM.append(fn)
    for fn in _TRIM:
        fn(0)
    return bool(_TRIM)


# ---------------------------------------------------------------------------- BLAS threads
_SETTERS: Optional[list] = None
#: OpenBLAS builds: (thread-count getter, setter) symbol names
_OPENBLAS_SYMBOLS = (("openblas_get_num_threads", "openblas_set_num_threads"),
                     ("openblas_get_num_threads64_", "openblas_set_num_threads64_"),
                     ("scipy_openblas_get_num_threads64_",
                      "scipy_openblas_set_num_threads64_"),
                     ("scipy_openblas_get_num_threads", "scipy_openblas_set_num_threads"))


def _loaded_openblas() -> list:
    """(get, set) thread-count functions of the OpenBLAS libraries already loaded.

    Without threadpoolctl: the system library names and the libraries numpy/scipy
    wheels bundle, opened only if already loaded (``RTLD_NOLOAD``, POSIX).
    """
    global _SETTERS
    if _SETTERS is not None:
        return _SETTERS
    found: list = []
    noload = getattr(os, "RTLD_NOLOAD", None)
    if noload is not None:
        candidates: List[str] = ["libopenblas.so.0", "libblas.so.3", "libopenblas.dylib"]
        for mod in ("numpy", "scipy"):
            spec = sys.modules.get(mod)
            base = os.path.dirname(os.path.dirname(getattr(spec, "__file__", "") or ""))
            if base:
                candidates += sorted(glob.glob(os.path.join(base, f"{mod}.libs", "*blas*")))
                candidates += sorted(glob.glob(os.path.join(base, mod, ".dylibs", "*blas*")))
        seen = set()
        for path in candidates:
            try:
                lib = ctypes.CDLL(path, mode=noload | getattr(os, "RTLD_LAZY", 1))
            except OSError:
                continue
            for get_name, set_name in _OPENBLAS_SYMBOLS:
                get = getattr(lib, get_name, None)
                set_ = getattr(lib, set_name, None)
                if get is None or set_ is None:
                    continue
                key = ctypes.cast(get, ctypes.c_void_p).value
                if key in seen:
                    continue
                seen.add(key)
                get.restype = ctypes.c_int
                set_.argtypes = [ctypes.c_int]
                found.append((get, set_))
    _SETTERS = found
    return found


@contextlib.contextmanager
def limit_blas_threads(limit: int = 1) -> Iterator[None]:
    """Run the block with at most ``limit`` BLAS threads, restoring them afterwards.

    OpenBLAS otherwise starts its thread pool for every small system, which makes
    batched solves of 10⁵ tiny systems 10–20× slower on a loaded machine. Uses
    threadpoolctl when installed (every BLAS, every platform), else the OpenBLAS
    thread functions of the libraries already loaded; does nothing when neither is
    found.
    """
    try:
        from threadpoolctl import threadpool_limits
    except Exception:  # noqa: BLE001 - absent or broken: the OpenBLAS functions below
        threadpool_limits = None
    if threadpool_limits is not None:
        with threadpool_limits(limits=limit, user_api="blas"):
            yield
        return
    setters = _loaded_openblas()
    old = [get() for get, _ in setters]
    for _, set_ in setters:
        set_(limit)
    try:
        yield
    finally:
        for (_, set_), n in zip(setters, old):
            set_(n)


# ---------------------------------------------------------------------------- interpreter
def _is_python(path: str) -> bool:
    name = os.path.basename(path).lower()
    return bool(path) and os.path.isfile(path) and name.startswith("python") \
        and not name.endswith((".bat", ".cmd", "-config"))


def interpreter_candidates() -> List[str]:
    """List where the real interpreter of this Python may live, most likely first.

    ``sys.executable`` when it is a Python; else, for an embedding application
    (QGIS: ``qgis-bin.exe``, ``QGIS.app/Contents/MacOS/QGIS``, ``qgis_process``):
    ``python.exe`` in the prefix (Windows, OSGeo4W's ``apps/PythonXY``) or
    ``bin/pythonX.Y`` / ``bin/python3`` in the prefix (Linux, macOS), and next to the
    application binary (``bin/python3`` in the macOS bundle, OSGeo4W's ``bin``).
    """
    out: List[str] = []
    exe = sys.executable or ""
    if _is_python(exe):
        if os.path.basename(exe).lower() == "pythonw.exe":      # no console: its sibling
            out.append(os.path.join(os.path.dirname(exe), "python.exe"))
        out.append(exe)
    ver = f"{sys.version_info[0]}.{sys.version_info[1]}"
    prefixes = []
    for p in (sys.exec_prefix, sys.base_exec_prefix, sys.prefix, sys.base_prefix):
        if p and p not in prefixes:
            prefixes.append(p)
    app_dir = os.path.dirname(exe) if exe else ""
    if sys.platform == "win32":
        names = ("python.exe", f"python{ver.replace('.', '')}.exe", "python3.exe")
        dirs = prefixes + ([app_dir] if app_dir else [])
        out += [os.path.join(d, n) for d in dirs for n in names]
    else:
        names = (f"python{ver}", f"python{sys.version_info[0]}", "python")
        dirs = [os.path.join(p, "bin") for p in prefixes]
        if app_dir:
            dirs += [os.path.join(app_dir, "bin"), app_dir]
        out += [os.path.join(d, n) for d in dirs for n in names]
    seen, unique = set(), []
    for path in out:
        if path not in seen:
            seen.add(path)
            unique.append(path)
    return unique


#: what a candidate interpreter must report to be this one: version and installation
IDENTITY_CODE = ("import os, sys; print(repr((tuple(sys.version_info[:3]), "
                 "os.path.normcase(os.path.realpath(sys.base_exec_prefix)))))")


def interpreter_identity() -> str:
    """Return ``repr((version, real base prefix))`` of this interpreter."""
    return repr((tuple(sys.version_info[:3]),
                 os.path.normcase(os.path.realpath(sys.base_exec_prefix))))


@functools.cache
def _same_interpreter(path: str) -> bool:
    try:
        out = subprocess.run([path, "-c", IDENTITY_CODE], capture_output=True, text=True,
                             timeout=60, creationflags=no_window_flag())
    except (OSError, subprocess.SubprocessError):
        return False
    return out.returncode == 0 and out.stdout.strip() == interpreter_identity()


def python_executable(*, verify: bool = True) -> Optional[str]:
    """Return the Python interpreter of this process as a program (None if not found).

    With ``verify`` (default) a candidate must run and report the same version and the
    same installation (``sys.base_exec_prefix``): an embedded interpreter (QGIS on
    Linux) may set ``sys.executable`` to whatever ``python3`` comes first on ``PATH`` —
    a pyenv shim or a conda Python of the same version, with other packages — and pip
    or Dask workers run there would see another set of packages. Never changes any
    interpreter-wide setting (``multiprocessing.set_executable``).
    """
    for path in interpreter_candidates():
        if not _is_python(path):
            continue
        if not verify or _same_interpreter(path):
            return path
    return None


def no_window_flag() -> int:
    """``creationflags`` for a background child process (no console window on Windows)."""
    return getattr(subprocess, "CREATE_NO_WINDOW", 0) if sys.platform == "win32" else 0

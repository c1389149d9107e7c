"""The Python packages the toolbox needs at run time, and their private installation.

QGIS ships numpy, scipy and GDAL; the LiDAR algorithms also need ``laspy`` and
``lazrs`` (LAS/LAZ), and the tile catalog ``dask`` and ``distributed``. The pins are
the plugin's ``requirements.txt`` (shipped in the zip). Every other algorithm needs
none of them.

They are installed with QGIS's own interpreter (:func:`..system.python_executable`,
not ``qgis-bin.exe``) by ``python -m pip`` into a folder of the plugin's own under the
QGIS profile (:func:`packages_dir`), never into QGIS's site-packages, in two steps:

1. ``pip install --dry-run --report`` resolves the pins against what QGIS's Python
   already has (plus the private folder): only what is missing is planned — never
   numpy, SciPy or GDAL, which stay QGIS's own (a plan that would replace them is
   refused; SciPy is added, for QGIS's numpy, only to a QGIS that has none);
2. ``pip install --target <folder> --no-deps --upgrade name==version …`` installs
   exactly that plan.

Both take the same source: the package index pip is configured with, or a local
folder of wheels (``--no-index --find-links``) for sites without internet. At plugin
start :func:`activate` appends the folder to ``sys.path`` (QGIS's own packages keep
precedence) and to the Dask workers' ``PYTHONPATH``.

Examples
--------
>>> [r.name for r in requirements()]
['laspy', 'lazrs', 'dask', 'distributed']
>>> sorted({r.group for r in requirements()})
['catalog', 'lidar']
"""
from __future__ import annotations

import importlib
import importlib.util
import json
import os
import re
import shlex
import subprocess
import sys
from dataclasses import dataclass
from pathlib import Path
from typing import Callable, Dict, Iterable, List, Optional, Sequence

from .errors import InputError
from .system import no_window_flag, python_executable

PLUGIN_DIR = Path(__file__).resolve().parents[1]
REQUIREMENTS_FILE = PLUGIN_DIR / "requirements.txt"
#: distribution name -> (import name, group); group 'lidar' is every LiDAR algorithm,
#: 'catalog' the tile catalog (which also needs 'lidar')
PACKAGES: Dict[str, tuple] = {"laspy": ("laspy", "lidar"), "lazrs": ("lazrs", "lidar"),
                              "dask": ("dask", "catalog"),
                              "distributed": ("distributed", "catalog")}
#: QGIS's own compiled packages: never installed privately (they would shadow QGIS's)
NEVER_INSTALL = ("numpy", "scipy", "gdal", "pyqt5", "pyqt6", "qgis")
#: what every algorithm needs besides numpy and GDAL (group 'base'). QGIS ships SciPy on
#: Windows and Linux, but some macOS builds did not: when it is missing the installer adds
#: it, unpinned and constrained to QGIS's own numpy (never replacing it)
BASE_LINES = ("scipy",)
#: the private folders :func:`activate` put on ``sys.path``: the Dask workers started by
#: ``core/lidar/_workers.py`` read this list when they start (plugin start-up must not
#: import ``core.lidar``: it pulls in SciPy, which a QGIS may lack)
WORKER_PATHS: List[str] = []
#: the algorithm that installs them (named in every message about a missing package)
INSTALLER_ID = "geomatics:installdependencies"


@dataclass(frozen=True)
class Requirement:
    """One runtime requirement: the line of requirements.txt and what it is for."""

    name: str
    line: str
    import_name: str
    group: str

    def importable(self) -> bool:
        """Tell whether the module can be found on ``sys.path`` (without importing it)."""
        try:
            return importlib.util.find_spec(self.import_name) is not None
        except (ImportError, ValueError):
            return False


def _dist_name(line: str) -> str:
    match = re.match(r"\s*([A-Za-z0-9][A-Za-z0-9._-]*)", line)
    return match.group(1).lower().replace("_", "-") if match else ""


def requirements(path: Path = REQUIREMENTS_FILE) -> List[Requirement]:
    """Return the runtime requirements of ``requirements.txt`` (comments, options skipped)."""
    out = []
    for raw in Path(path).read_text(encoding="utf-8").splitlines():
        line = raw.split("#", 1)[0].strip()
        if not line or line.startswith("-"):
            continue
        name = _dist_name(line)
        import_name, group = PACKAGES.get(name, (name.replace("-", "_"), "lidar"))
        out.append(Requirement(name, line, import_name, group))
    return out


def base_requirements() -> List[Requirement]:
    """Return what every algorithm needs beyond numpy and GDAL (SciPy), group 'base'."""
    return [Requirement(_dist_name(line), line, _dist_name(line).replace("-", "_"), "base")
            for line in BASE_LINES]


def groups_closure(groups: Iterable[str]) -> List[str]:
    """Return the groups a use needs: the catalog needs the LiDAR packages too."""
    groups = set(groups)
    if "catalog" in groups:
        groups.add("lidar")
    return sorted(groups)


def missing(groups: Optional[Iterable[str]] = None) -> List[Requirement]:
    """Return the requirements of ``groups`` (default: all) whose module is not found.

    The 'base' ones (SciPy) are always included: every algorithm needs them.
    """
    wanted = None if groups is None else set(groups_closure(groups)) | {"base"}
    return [r for r in base_requirements() + requirements()
            if (wanted is None or r.group in wanted) and not r.importable()]


def check(groups: Iterable[str], *, load: bool = False) -> None:
    """Raise :class:`InputError` naming the missing packages of ``groups`` and the installer.

    With ``load`` the present ones are also imported, so a broken installation (a
    dependency of theirs missing, a wheel for another Python) is reported before the
    run with the import error, not halfway through it.
    """
    gone = missing(groups)
    if gone:
        raise InputError("This algorithm needs the Python packages {packages}, which QGIS's "
                         "Python does not have. Run 'Install the Python packages this "
                         "toolbox needs' ({installer}) from the Processing Toolbox, then "
                         "run this algorithm again.",
                         packages=", ".join(r.name for r in gone), installer=INSTALLER_ID)
    if not load:
        return
    wanted = set(groups_closure(groups))
    for req in requirements():
        if req.group not in wanted:
            continue
        try:
            importlib.import_module(req.import_name)
        except Exception as exc:  # noqa: BLE001 - any failure to load is reported
            raise InputError("The Python package {package} is installed but cannot be "
                             "loaded ({error}). Run 'Install the Python packages this "
                             "toolbox needs' ({installer}) again to repair it.",
                             package=req.name, error=f"{type(exc).__name__}: {exc}",
                             installer=INSTALLER_ID) from exc


# ---------------------------------------------------------------------------- the folder
def packages_dir(profile_dir: os.PathLike) -> Path:
    """Return the plugin's private package folder under a QGIS profile, per Python version.

    Compiled wheels (lazrs, psutil, msgpack) are built for one Python version, so a
    QGIS upgrade to another Python gets a folder of its own.
    """
    return (Path(profile_dir) / "geomatics_toolbox" /
            f"python{sys.version_info[0]}.{sys.version_info[1]}")


def activate(folder: os.PathLike) -> bool:
    """Append ``folder`` to ``sys.path`` and the Dask workers' path if it exists.

    Appended, not prepended: a package QGIS already has is never shadowed. Returns
    True when the folder is (now) on the path. Runs at plugin start, so it imports
    nothing: the workers read :data:`WORKER_PATHS` when they start.
    """
    folder = os.path.abspath(os.fspath(folder))
    if not os.path.isdir(folder):
        return False
    if folder not in sys.path:
        sys.path.append(folder)
        importlib.invalidate_caches()
    if folder not in WORKER_PATHS:
        WORKER_PATHS.append(folder)
    return True


# ---------------------------------------------------------------------------- installing
def _source_args(wheel_dir: Optional[str]) -> List[str]:
    return ["--no-index", "--find-links", str(wheel_dir)] if wheel_dir else []


def pip_base(python: str) -> List[str]:
    """``python -m pip install`` with the options every step uses."""
    return [python, "-m", "pip", "install", "--disable-pip-version-check", "--no-input"]


def resolve_command(python: str, report: str, *, wheel_dir: Optional[str] = None,
                    requirements_file: os.PathLike = REQUIREMENTS_FILE,
                    extra: Sequence[str] = (), constraints: Optional[str] = None
                    ) -> List[str]:
    """Step 1: what pip would install for the pins, given what QGIS's Python has.

    ``extra``: more requirements (SciPy when QGIS lacks it); ``constraints``: a pip
    constraints file (QGIS's numpy version).
    """
    return (pip_base(python) + ["--dry-run", "--quiet", "--report", str(report),
                                "-r", str(requirements_file)] + list(extra)
            + (["-c", str(constraints)] if constraints else []) + _source_args(wheel_dir))


def install_command(python: str, target: os.PathLike, plan: Sequence[str], *,
                    wheel_dir: Optional[str] = None) -> List[str]:
    """Step 2: exactly the planned ``name==version`` into the private folder."""
    return (pip_base(python) + ["--target", str(target), "--no-deps", "--upgrade",
                                "--progress-bar", "off"] + _source_args(wheel_dir)
            + list(plan))


def pip_environment(target: os.PathLike) -> Dict[str, str]:
    """Pip's environment: the private folder visible (so it counts as installed)."""
    env = dict(os.environ)
    parts = [p for p in env.get("PYTHONPATH", "").split(os.pathsep) if p]
    env["PYTHONPATH"] = os.pathsep.join([str(target)] + parts)
    env["PIP_DISABLE_PIP_VERSION_CHECK"] = "1"
    env["PYTHONIOENCODING"] = "utf-8"     # pip's output is read as UTF-8 (Windows code pages)
    env.pop("PIP_TARGET", None)
    env.pop("PIP_PREFIX", None)
    env.pop("PIP_USER", None)
    return env


def read_plan(report_path: os.PathLike, allowed: Iterable[str] = ()) -> List[str]:
    """``name==version`` of every distribution a pip ``--report`` would install.

    Raises :class:`InputError` when the plan would replace one of QGIS's own compiled
    packages (numpy, scipy, GDAL, PyQt) — except those in ``allowed`` (SciPy when QGIS
    has none).
    """
    allowed = {_dist_name(a) for a in allowed}
    with open(report_path, encoding="utf-8") as fh:
        report = json.load(fh)
    plan, refused = [], []
    for item in report.get("install", []):
        meta = item.get("metadata", {})
        name, version = meta.get("name", ""), meta.get("version", "")
        if _dist_name(name) in NEVER_INSTALL and _dist_name(name) not in allowed:
            refused.append(f"{name} {version}")
        else:
            plan.append(f"{name}=={version}")
    if refused:
        raise InputError("The pinned packages would need {packages} in place of the copy "
                         "QGIS ships; the installer never replaces QGIS's own packages. "
                         "Use the QGIS version this toolbox supports or install older "
                         "pins by hand.", packages=", ".join(refused))
    return plan


@dataclass
class InstallResult:
    """What :func:`install` did."""

    folder: str
    planned: List[str]
    commands: List[List[str]]
    log: str


class _OldPipError(Exception):
    """pip older than 22.2: no ``--report`` (Ubuntu 22.04 ships 22.0)."""


def _run(cmd: List[str], env: Dict[str, str], log: Callable[[str], None],
         cancel: Optional[Callable[[], bool]], on_line: Optional[Callable[[str], None]] = None
         ) -> str:
    proc = subprocess.Popen(cmd, env=env, stdin=subprocess.DEVNULL, stdout=subprocess.PIPE,
                            stderr=subprocess.STDOUT, text=True, encoding="utf-8",
                            errors="replace", creationflags=no_window_flag())
    lines = []
    assert proc.stdout is not None
    for line in proc.stdout:
        line = line.rstrip()
        lines.append(line)
        if line:
            log(line)
            if on_line is not None:
                on_line(line)
        if cancel is not None and cancel():
            proc.terminate()
            proc.wait(timeout=30)
            from .progress import Cancelled
            raise Cancelled()
    proc.wait()
    if proc.returncode != 0:
        tail = "\n".join(lines[-15:])
        if "--report" in cmd and "no such option: --report" in tail:
            raise _OldPipError()
        if "No module named pip" in tail:
            raise InputError("QGIS's Python ({python}) has no pip. Install pip for it (Debian, "
                             "Ubuntu: the package python3-pip; OSGeo4W: python3-pip in the "
                             "OSGeo4W setup), then run this algorithm again.", python=cmd[0])
        raise InputError("pip failed (exit code {code}): {command}\n{log}",
                         code=proc.returncode, command=format_command(cmd), log=tail)
    return "\n".join(lines)


def format_command(cmd: Sequence[str]) -> str:
    """Return a command as the user would type it (quoted where needed)."""
    if sys.platform == "win32":
        return subprocess.list2cmdline(list(cmd))
    return " ".join(a if re.fullmatch(r"[A-Za-z0-9_./:=@+,-]+", a) else shlex.quote(a)
                    for a in cmd)


def _install_with_old_pip(python, target, env, wheel_dir, requirements_file, commands, logs,
                          log, cancel, extra=(), constraints=None) -> List[str]:
    """Install in one step for pip < 22.2 (no ``--report``).

    The whole pinned closure goes into the folder, then QGIS's own compiled packages
    (numpy, SciPy, GDAL…) are removed from it again.
    """
    import shutil
    log("pip < 22.2 (no --report): installing every pin and its dependencies into the "
        "folder, then removing the packages QGIS ships from it.")
    cmd = (pip_base(python) + ["--target", str(target), "--upgrade", "--progress-bar", "off",
                               "-r", str(requirements_file)] + list(extra)
           + (["-c", str(constraints)] if constraints else []) + _source_args(wheel_dir))
    keep = {_dist_name(e) for e in extra}
    commands.append(cmd)
    log(format_command(cmd))
    text = _run(cmd, env, log, cancel)
    logs.append(text)
    for entry in Path(target).iterdir():
        base = re.split(r"[-.]", entry.name, maxsplit=1)[0].lower()
        if base in NEVER_INSTALL and base not in keep:
            if entry.is_dir():
                shutil.rmtree(entry, ignore_errors=True)
            else:
                entry.unlink(missing_ok=True)
            log(f"removed {entry.name} (QGIS's own package)")
    done = re.findall(r"^Successfully installed (.+)$", text, re.M)
    pairs = done[-1].split() if done else []
    return [re.sub(r"-(?=[^-]+$)", "==", p) for p in pairs
            if _dist_name(p.rsplit("-", 1)[0]) not in set(NEVER_INSTALL) - keep]


def install(target: os.PathLike, *, wheel_dir: Optional[str] = None,
            python: Optional[str] = None, log: Callable[[str], None] = print,
            progress: Optional[Callable[[float], None]] = None,
            cancel: Optional[Callable[[], bool]] = None,
            requirements_file: os.PathLike = REQUIREMENTS_FILE) -> InstallResult:
    """Install the pinned runtime packages that are missing into ``target``.

    Parameters
    ----------
    target : path
        The private folder (:func:`packages_dir`); created if needed.
    wheel_dir : str, optional
        A folder of wheels to install from instead of the package index
        (``--no-index --find-links``), for sites without internet.
    python : str, optional
        The interpreter; default :func:`..system.python_executable`.
    log, progress, cancel : callables
        Each command and every line pip prints; fraction done; stop request.
    """
    python = python or python_executable()
    if python is None:
        raise InputError("QGIS's Python interpreter was not found next to {exe} or in "
                         "{prefix}; install the packages by hand: {packages}.",
                         exe=sys.executable, prefix=sys.base_exec_prefix,
                         packages=" ".join(r.line for r in requirements(requirements_file)))
    if wheel_dir and not os.path.isdir(wheel_dir):
        raise InputError("The wheel folder {folder} does not exist.", folder=wheel_dir)
    target = Path(target)
    target.mkdir(parents=True, exist_ok=True)
    env = pip_environment(target)
    report = target / ".install-report.json"
    step = progress or (lambda f: None)
    commands, logs = [], []
    base = [r for r in base_requirements() if not r.importable()]
    constraints = None
    if base:      # SciPy missing (some macOS builds): added, built for QGIS's own numpy
        import numpy
        constraints = target / ".constraints.txt"
        constraints.write_text(f"numpy=={numpy.__version__}\n", encoding="utf-8")
    cmd = resolve_command(python, str(report), wheel_dir=wheel_dir,
                          requirements_file=requirements_file,
                          extra=[r.line for r in base],
                          constraints=str(constraints) if constraints else None)
    commands.append(cmd)
    log(format_command(cmd))
    step(0.05)
    try:
        logs.append(_run(cmd, env, log, cancel))
    except _OldPipError:
        plan = _install_with_old_pip(python, target, env, wheel_dir, requirements_file,
                                     commands, logs, log, cancel,
                                     extra=[r.line for r in base], constraints=constraints)
    else:
        try:
            plan = read_plan(report, allowed=[r.name for r in base])
        finally:
            report.unlink(missing_ok=True)
            if constraints is not None:
                constraints.unlink(missing_ok=True)
        step(0.3)
        if plan:
            cmd = install_command(python, target, plan, wheel_dir=wheel_dir)
            commands.append(cmd)
            log(format_command(cmd))
            seen = [0]

            def on_line(line: str) -> None:
                if line.startswith(("Collecting", "Processing", "Installing collected")):
                    seen[0] += 1
                    step(min(0.95, 0.3 + 0.65 * seen[0] / (len(plan) + 1)))

            logs.append(_run(cmd, env, log, cancel, on_line))
    if constraints is not None:
        constraints.unlink(missing_ok=True)
    activate(target)
    step(1.0)
    return InstallResult(folder=str(target), planned=plan, commands=commands,
                         log="\n".join(logs))

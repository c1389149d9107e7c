"""The plugin loads where QGIS runs: Windows and macOS (simulated), and without its packages.

A fresh interpreter imports QGIS, then makes the POSIX-only modules (``resource``,
``fcntl``, ``pwd``, ``grp``, ``termios``) unimportable, every ``/proc`` path unreadable
and ``sys.platform`` report ``win32`` (or ``darwin``) before it imports every module of
the plugin, starts it as QGIS does (``classFactory`` → ``initProcessing``) and lists the
algorithms of the provider; the platform helpers the QGIS process calls must answer.
The same harness with laspy, lazrs, pykrige, dask and distributed unimportable shows
that the plugin loads with no error when every runtime package is missing.
"""
from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
POSIX_ONLY = ("resource", "fcntl", "pwd", "grp", "termios")
RUNTIME = ("laspy", "lazrs", "pykrige", "dask", "distributed", "psutil", "threadpoolctl")

HARNESS = r"""
import builtins, importlib, importlib.abc, importlib.util, io, json, os, pkgutil, sys
os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
from qgis.core import QgsApplication
sys.path.append("/usr/share/qgis/python/plugins")
app = QgsApplication([], False)
app.initQgis()
from processing.core.Processing import Processing
Processing.initialize()

ROOT, BLOCKED, PLATFORM = sys.argv[1], set(sys.argv[2].split(",")), sys.argv[3]
denied = []

class Block(importlib.abc.MetaPathFinder):
    def find_spec(self, name, path=None, target=None):
        if name.split(".")[0] in BLOCKED:
            raise ModuleNotFoundError(f"No module named {name!r} (blocked)", name=name)
        return None

for mod in [m for m in sys.modules if m.split(".")[0] in BLOCKED]:
    del sys.modules[mod]
sys.meta_path.insert(0, Block())

def _is_proc(path):
    try:
        p = os.fsdecode(os.fspath(path))
    except TypeError:
        return False
    return p == "/proc" or p.startswith("/proc/")

def _guard(func, exc=PermissionError):
    def wrapper(path, *args, **kwargs):
        if _is_proc(path):
            denied.append(os.fsdecode(os.fspath(path)))
            raise exc(13, "Permission denied (simulated)", os.fsdecode(os.fspath(path)))
        return func(path, *args, **kwargs)
    return wrapper

builtins.open = io.open = _guard(io.open)
for name in ("open", "stat", "lstat", "listdir", "scandir", "access"):
    setattr(os, name, _guard(getattr(os, name)))

# the standard library of the real platform: modules that choose their implementation
# when imported are imported before sys.platform changes (only the plugin's code and
# what it imports later see the simulated platform)
for mod in ("asyncio", "concurrent.futures", "ctypes", "ctypes.util", "email", "glob",
            "http.client", "locale", "mimetypes", "multiprocessing", "platform", "shutil",
            "socket", "ssl", "subprocess", "sysconfig", "tempfile", "urllib.request",
            "uuid", "webbrowser", "xml.sax.saxutils", "zipfile"):
    importlib.import_module(mod)
import sysconfig
sysconfig.get_config_vars()          # computed (and cached) for the real platform
import numpy, scipy                  # QGIS's own compiled packages, imported as they are
# pyproj (which laspy imports, Debian's build) looks for its tools with shutil.which when
# imported; on Python 3.13 a simulated win32 sends that to the Windows-only _winapi
try:
    importlib.import_module("pyproj")
except ImportError:
    pass
if PLATFORM:
    sys.platform = PLATFORM

spec = importlib.util.spec_from_file_location(
    "geomatics_toolbox", os.path.join(ROOT, "__init__.py"), submodule_search_locations=[ROOT])
pkg = importlib.util.module_from_spec(spec)
sys.modules["geomatics_toolbox"] = pkg
spec.loader.exec_module(pkg)
errors, modules = [], []
for sub in ("core", "algorithms", "provider"):
    base = importlib.import_module("geomatics_toolbox." + sub)
    for info in pkgutil.walk_packages(base.__path__, "geomatics_toolbox." + sub + "."):
        try:
            importlib.import_module(info.name)
            modules.append(info.name)
        except Exception as exc:
            errors.append(f"{info.name}: {type(exc).__name__}: {exc}")

plugin = pkg.classFactory(None)
plugin.initProcessing()
provider = QgsApplication.processingRegistry().providerById("geomatics")
algs = sorted(a.id() for a in provider.algorithms()) if provider else []

from geomatics_toolbox.core import system
from geomatics_toolbox.core.terrain import grid, kriging
import numpy as np
facts = {"memory": system.available_memory(), "peak": system.peak_rss_mb(),
         "candidates": system.interpreter_candidates(),
         "budget_ok": grid.check_memory(grid.GridSpec(xmin=0, ymax=10, cell=1, ncols=10,
                                                      nrows=10)) == 1600}
with kriging.single_threaded_blas():
    facts["solve"] = float(np.linalg.solve(np.eye(3) * 2, np.ones(3)).sum())
import processing
facts["gsd"] = processing.run("geomatics:gsdcalculator", {
    "DISTANCE": 5.88, "SENSOR_WIDTH": 6.123, "IMAGE_WIDTH": 3648, "FOCAL_LENGTH": 4.6})["GSD"]
gf = QgsApplication.processingRegistry().createAlgorithmById("geomatics:groundfilter")
from qgis.core import QgsProcessingContext
facts["refusal"] = gf.checkParameterValues({"INPUT": "a.laz"}, QgsProcessingContext())[1]
plugin.unload()
leaked = sorted(m for m in sys.modules if m.split(".")[0] in BLOCKED)
print("RESULT:" + json.dumps(dict(algs=algs, errors=errors, modules=len(modules),
                                  denied=denied, facts=facts, leaked=leaked)))
"""


def _run(blocked, platform: str) -> dict:
    out = subprocess.run([sys.executable, "-c", HARNESS, str(ROOT), ",".join(blocked),
                          platform], capture_output=True, text=True, timeout=600)
    lines = [ln for ln in out.stdout.splitlines() if ln.startswith("RESULT:")]
    assert out.returncode == 0 and lines, f"{out.stdout}\n{out.stderr}"
    return json.loads(lines[-1][len("RESULT:"):])


@pytest.fixture(scope="module")
def expected_ids(qgis_app):
    from qgis.core import QgsApplication
    provider = QgsApplication.processingRegistry().providerById("geomatics")
    ids = sorted(a.id() for a in provider.algorithms())
    assert len(ids) >= 20 and "geomatics:catalog" in ids and "geomatics:groundfilter" in ids
    return ids


@pytest.mark.parametrize("platform", ["win32", "darwin"])
def test_plugin_loads_without_posix_modules_or_proc(expected_ids, platform):
    res = _run(POSIX_ONLY, platform)
    assert res["errors"] == []
    assert res["modules"] >= 60
    assert res["algs"] == expected_ids
    assert res["leaked"] == []
    facts = res["facts"]
    assert facts["memory"] > 0 and facts["budget_ok"] and facts["solve"] == 1.5
    assert facts["candidates"], "no interpreter candidate"
    if platform == "win32":
        assert any(c.endswith("python.exe") for c in facts["candidates"])
    assert abs(facts["gsd"] - 0.21455) < 5e-5 and "installdependencies" not in facts["refusal"]


def test_plugin_loads_with_every_runtime_package_missing(expected_ids):
    res = _run(RUNTIME + POSIX_ONLY, "win32")
    assert res["errors"] == []
    assert res["algs"] == expected_ids
    assert res["leaked"] == []
    # non-LiDAR algorithms run; LiDAR ones refuse before running, naming the installer
    assert abs(res["facts"]["gsd"] - 0.21455) < 5e-5
    refusal = res["facts"]["refusal"]
    assert "laspy, lazrs" in refusal and "geomatics:installdependencies" in refusal


def test_no_posix_only_import_or_proc_path_in_the_qgis_process():
    """The same grep as the release check: module-level POSIX imports, literal /proc."""
    bad = []
    files = [ROOT / "plugin.py", ROOT / "__init__.py"]
    for sub in ("core", "algorithms", "provider"):
        files += sorted((ROOT / sub).rglob("*.py"))
    for path in files:
        for n, line in enumerate(path.read_text(encoding="utf-8").splitlines(), 1):
            if re.match(r"^(import|from) (resource|fcntl|pwd|grp|termios)\b", line) \
                    or '"/proc/' in line or "'/proc/" in line:
                bad.append(f"{path.relative_to(ROOT)}:{n}: {line.strip()}")
    assert bad == []


MESSAGE_BAR = r"""
import importlib.abc, importlib.util, os, sys, json
os.environ["QT_QPA_PLATFORM"] = "offscreen"
from qgis.core import QgsApplication
from qgis.gui import QgsMessageBar
app = QgsApplication([], True)
app.initQgis()
sys.path.append("/usr/share/qgis/python/plugins")
from processing.core.Processing import Processing
Processing.initialize()
BLOCKED = set(sys.argv[2].split(","))
class Block(importlib.abc.MetaPathFinder):
    def find_spec(self, name, path=None, target=None):
        if name.split(".")[0] in BLOCKED:
            raise ModuleNotFoundError(name, name=name)
sys.meta_path.insert(0, Block())
class Iface:
    def __init__(self):
        self.bar = QgsMessageBar()
    def messageBar(self):
        return self.bar
spec = importlib.util.spec_from_file_location(
    "geomatics_toolbox", os.path.join(sys.argv[1], "__init__.py"),
    submodule_search_locations=[sys.argv[1]])
pkg = importlib.util.module_from_spec(spec)
sys.modules["geomatics_toolbox"] = pkg
spec.loader.exec_module(pkg)
iface = Iface()
plugin = pkg.classFactory(iface)
plugin.initGui()
from qgis.PyQt.QtWidgets import QLabel, QPushButton
items = iface.bar.items()
texts = [lab.text() for item in items for lab in item.findChildren(QLabel)]
buttons = [b.text() for item in items for b in item.findChildren(QPushButton)
           if b.objectName() == "geomatics_install_button"]
opened = []
import processing
processing.execAlgorithmDialog = lambda alg_id, *a, **k: opened.append(alg_id)
for item in items:
    for b in item.findChildren(QPushButton):
        if b.objectName() == "geomatics_install_button":
            b.click()
print("RESULT:" + json.dumps({"items": len(items), "texts": texts, "buttons": buttons,
                              "text": [i.text() for i in items], "opened": opened}))
plugin.unload()
"""


@pytest.mark.parametrize("blocked, shown", [(RUNTIME, True), ((), False)])
def test_message_bar_names_missing_packages_and_offers_install(qgis_app, blocked, shown):
    out = subprocess.run([sys.executable, "-c", MESSAGE_BAR, str(ROOT), ",".join(blocked)],
                         capture_output=True, text=True, timeout=600)
    lines = [ln for ln in out.stdout.splitlines() if ln.startswith("RESULT:")]
    assert out.returncode == 0 and lines, f"{out.stdout}\n{out.stderr}"
    res = json.loads(lines[-1][len("RESULT:"):])
    if not shown:
        assert res["items"] == 0
        return
    assert res["items"] == 1 and res["buttons"] == ["Install them…"]
    assert res["opened"] == ["geomatics:installdependencies"]
    text = " ".join(res["texts"] + res["text"])
    assert "laspy, lazrs for the LiDAR algorithms" in text
    assert "dask, distributed for the tile catalog" in text


NO_SCIPY = r"""
import importlib.abc, importlib.util, json, os, sys
os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
from qgis.core import QgsApplication
from qgis.gui import QgsMessageBar
app = QgsApplication([], True)
app.initQgis()
sys.path.append("/usr/share/qgis/python/plugins")
from processing.core.Processing import Processing
Processing.initialize()
class Block(importlib.abc.MetaPathFinder):
    def find_spec(self, name, path=None, target=None):
        if name.split(".")[0] == "scipy":
            raise ModuleNotFoundError(f"No module named {name!r}", name=name)
for mod in [m for m in sys.modules if m.split(".")[0] == "scipy"]:
    del sys.modules[mod]
sys.meta_path.insert(0, Block())
folder = os.path.join(QgsApplication.qgisSettingsDirPath(), "geomatics_toolbox",
                      "python%d.%d" % sys.version_info[:2])
if sys.argv[2] == "folder":           # a half-finished install: the folder, no SciPy
    os.makedirs(folder)
class Iface:
    def __init__(self):
        self.bar = QgsMessageBar()
    def messageBar(self):
        return self.bar
spec = importlib.util.spec_from_file_location(
    "geomatics_toolbox", os.path.join(sys.argv[1], "__init__.py"),
    submodule_search_locations=[sys.argv[1]])
pkg = importlib.util.module_from_spec(spec)
sys.modules["geomatics_toolbox"] = pkg
before = set(sys.modules)
spec.loader.exec_module(pkg)
iface = Iface()
plugin = pkg.classFactory(iface)
at_start = sorted(set(sys.modules) - before)
plugin.initGui()
provider = QgsApplication.processingRegistry().providerById("geomatics")
from geomatics_toolbox.core import deps
from geomatics_toolbox.plugin import missing_packages_text
from qgis.PyQt.QtWidgets import QPushButton
items = iface.bar.items()
buttons = [b.text() for item in items for b in item.findChildren(QPushButton)
           if b.objectName() == "geomatics_install_button"]
print("RESULT:" + json.dumps({"algs": sorted(a.id() for a in provider.algorithms()),
                              "missing": [r.name for r in deps.missing()],
                              "text": missing_packages_text(deps.missing()),
                              "items": len(items), "buttons": buttons,
                              "folder": folder, "on_path": folder in sys.path,
                              "workers": deps.WORKER_PATHS, "at_start": at_start}))
plugin.unload()
"""


@pytest.mark.parametrize("folder", ["nofolder", "folder"])
def test_without_scipy_the_plugin_loads_and_offers_the_installer(qgis_app, tmp_path, folder):
    """Some macOS QGIS builds had no SciPy: the plugin still loads, with the installer.

    Also with the private package folder already there (an install that stopped before
    SciPy): plugin start imports nothing of core.lidar (review N1: it raised ImportError).
    """
    env = dict(os.environ, QGIS_CUSTOM_CONFIG_PATH=str(tmp_path / "profile"))
    out = subprocess.run([sys.executable, "-c", NO_SCIPY, str(ROOT), folder],
                         capture_output=True, text=True, timeout=600, env=env)
    lines = [ln for ln in out.stdout.splitlines() if ln.startswith("RESULT:")]
    assert out.returncode == 0 and lines, f"{out.stdout}\n{out.stderr}"
    res = json.loads(lines[-1][len("RESULT:"):])
    assert res["algs"] == ["geomatics:installdependencies"]
    assert res["missing"] == ["scipy"]
    assert "scipy for every algorithm" in res["text"]
    assert "only the installer" in res["text"]
    assert res["items"] == 1 and res["buttons"] == ["Install them…"]
    assert res["folder"].startswith(str(tmp_path / "profile"))
    assert res["on_path"] is (folder == "folder")
    assert res["workers"] == ([res["folder"]] if folder == "folder" else [])
    heavy = [m for m in res["at_start"] if m.startswith("geomatics_toolbox.core.lidar")
             or m.split(".")[0] in ("scipy", "numpy", "jinja2", "laspy", "dask")]
    assert heavy == []

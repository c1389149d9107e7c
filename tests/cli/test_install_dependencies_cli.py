"""One-click dependencies, for real: a clean profile whose Python lacks laspy.

``qgis_process.bin`` runs the system Python, which has numpy, SciPy and GDAL but not
laspy, lazrs, dask or distributed (the venv is deliberately NOT on ``PYTHONPATH``
here). In a fresh temporary profile, with the plugin unpacked from the zip of ``make
package`` (as *Install from ZIP* does) for the offline case:

1. the plugin loads with no error and ``geomatics:groundfilter`` refuses to start,
   naming the missing packages and ``geomatics:installdependencies``;
2. ``geomatics:installdependencies`` installs them with that Python's pip into the
   profile's private folder — from a local wheel folder (``--no-index
   --find-links``, the offline mode; filled once from the index) and, in a second
   profile, from the package index pip is configured with;
3. ``geomatics:groundfilter`` then runs on the demo tile (every point kept in order,
   total error against the tile's true classes below 2 %, as in the venv's test), and
   ``geomatics:catalog`` runs its Dask worker from the real interpreter with the
   private folder on its path.
"""
from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
import zipfile
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[2]
PLUGIN = "geomatics_toolbox"
SYSTEM_PYTHON = "/usr/bin/python3"
#: the pinned wheels for the system Python, kept in the venv in use (one per Python)
WHEELHOUSE = Path(os.environ.get("GEOMATICS_WHEELHOUSE",
                                 Path(sys.prefix) / "wheelhouse-runtime"))


def _system_python_lacks_laspy() -> bool:
    out = subprocess.run([SYSTEM_PYTHON, "-c", "import laspy"], capture_output=True,
                         env={k: v for k, v in os.environ.items() if k != "PYTHONPATH"})
    return out.returncode != 0


class CleanProfile:
    """``qgis_process.bin`` in a new profile, with nothing of the venv on its path."""

    def __init__(self, base: Path, plugin_zip: Path | None = None):
        self.exe = shutil.which("qgis_process.bin")
        plugins = base / "plugins"
        plugins.mkdir(parents=True)
        if plugin_zip is None:
            (plugins / PLUGIN).symlink_to(ROOT, target_is_directory=True)
        else:                  # as Plugins > Install from ZIP does: unpacked in the profile
            with zipfile.ZipFile(plugin_zip) as zf:
                zf.extractall(plugins)
        self.profile = base / "profile"
        self.profile.mkdir()
        self.env = {k: v for k, v in os.environ.items()
                    if k not in ("PYTHONPATH", "VIRTUAL_ENV", "PYTHONHOME")}
        self.env.update(QT_QPA_PLATFORM="offscreen", QGIS_CUSTOM_CONFIG_PATH=str(self.profile),
                        QGIS_PLUGINPATH=str(plugins))
        out = self.call("plugins", "enable", PLUGIN)
        assert out.returncode == 0, out.stdout + out.stderr

    @property
    def folder(self) -> Path:
        ver = f"{sys.version_info[0]}.{sys.version_info[1]}"
        return self.profile / "profiles" / "default" / PLUGIN / f"python{ver}"

    def call(self, *args, timeout=900) -> subprocess.CompletedProcess:
        return subprocess.run([self.exe, *args], env=self.env, capture_output=True,
                              text=True, timeout=timeout)

    def run(self, alg, **params) -> subprocess.CompletedProcess:
        return self.call("--json", "run", alg, "--", *[f"{k}={v}" for k, v in params.items()])


def _results(out: subprocess.CompletedProcess) -> dict:
    assert out.returncode == 0, out.stdout + out.stderr
    return json.loads(out.stdout[out.stdout.find("{"):])["results"]


@pytest.fixture(scope="module")
def demo(tmp_path_factory):
    if shutil.which("qgis_process.bin") is None:
        pytest.skip("qgis_process.bin not found; install the Debian package qgis")
    if not _system_python_lacks_laspy():
        pytest.skip(f"{SYSTEM_PYTHON} already has laspy: the clean-profile test needs a "
                    "Python without it")
    d = tmp_path_factory.mktemp("demo")
    subprocess.run([sys.executable, str(ROOT / "scripts" / "make_demo_data.py"), "--out",
                    str(d)], check=True, capture_output=True)
    return d / "demo.laz"


@pytest.fixture(scope="module")
def wheelhouse():
    """The pinned wheels for the system Python, downloaded once from the index."""
    stamp = WHEELHOUSE / ".complete"
    req = (ROOT / "requirements.txt").read_bytes() + sys.version.encode()
    if not (stamp.exists() and stamp.read_bytes() == req):
        WHEELHOUSE.mkdir(parents=True, exist_ok=True)
        out = subprocess.run([SYSTEM_PYTHON, "-m", "pip", "download", "--quiet",
                              "--disable-pip-version-check", "--only-binary=:all:",
                              "-d", str(WHEELHOUSE), "-r", str(ROOT / "requirements.txt")],
                             capture_output=True, text=True, timeout=900)
        assert out.returncode == 0, out.stdout + out.stderr
        stamp.write_bytes(req)
    return WHEELHOUSE


@pytest.fixture(scope="module")
def plugin_zip(tmp_path_factory):
    """The installable zip of ``make package``."""
    if not list((ROOT / "i18n").glob("*.qm")):
        pytest.skip("no compiled translations (run 'make qm' first)")
    out = tmp_path_factory.mktemp("dist")
    subprocess.run([sys.executable, str(ROOT / "scripts" / "package.py"), "--out", str(out)],
                   check=True, capture_output=True, cwd=ROOT)
    (zip_path,) = out.glob(f"{PLUGIN}-*.zip")
    return zip_path


def _check_ground_filter(profile: CleanProfile, src: Path, out: Path) -> None:
    res = _results(profile.run("geomatics:groundfilter", INPUT=src, OUTPUT=out))
    import laspy
    a, b = laspy.read(str(src)), laspy.read(str(out))
    cls = np.asarray(b.classification)
    assert res["N_POINTS"] == len(a.points) == len(cls)
    from geomatics_toolbox.core.lidar.accuracy import assess
    truth = np.asarray(a.classification) == 2
    assert assess(cls == 2, truth).total < 2.0
    assert np.array_equal(np.asarray(a.x), np.asarray(b.x))       # same points, in order


def test_clean_profile_offline_wheels_then_groundfilter(demo, wheelhouse, plugin_zip,
                                                        tmp_path):
    """The plugin installed from its zip, packages from a local wheel folder."""
    profile = CleanProfile(tmp_path / "offline", plugin_zip)
    assert not (tmp_path / "offline" / "plugins" / PLUGIN).is_symlink()
    # 1. the plugin is there, the LiDAR algorithm refuses before running
    listed = profile.call("list")
    assert listed.returncode == 0 and "geomatics:gsdcalculator" in listed.stdout, \
        listed.stdout[-2000:] + listed.stderr
    assert "Traceback" not in listed.stderr and "Error" not in listed.stderr, listed.stderr
    assert profile.call("help", "geomatics:installdependencies").returncode == 0
    refused = profile.run("geomatics:groundfilter", INPUT=demo, OUTPUT=tmp_path / "x.laz")
    text = refused.stdout + refused.stderr
    assert refused.returncode != 0
    assert "laspy, lazrs" in text and "geomatics:installdependencies" in text
    assert "Traceback" not in text and not (tmp_path / "x.laz").exists()
    # 2. install from the local wheel folder (offline mode)
    res = _results(profile.run("geomatics:installdependencies", WHEEL_FOLDER=wheelhouse))
    assert Path(res["FOLDER"]) == profile.folder
    installed = {p.split("==")[0].lower() for p in res["INSTALLED"].split(", ")}
    assert {"laspy", "lazrs", "dask", "distributed"} <= installed
    assert not installed & {"numpy", "scipy", "gdal"}
    assert res["MISSING"] == ""
    assert "--no-index" in res["COMMAND"] and "--target" in res["COMMAND"]
    assert (profile.folder / "laspy").is_dir() and not (profile.folder / "numpy").exists()
    # nothing written outside the profile's private folder
    site = subprocess.run([SYSTEM_PYTHON, "-c", "import laspy"], capture_output=True)
    assert site.returncode != 0
    # 3. the LiDAR algorithm now runs in a new qgis_process (plugin start adds the folder)
    _check_ground_filter(profile, demo, tmp_path / "classified.laz")
    # the catalog from the embedded Python: its Dask workers are a child process of the
    # real interpreter (not qgis_process.bin) that finds laspy/dask in the private folder
    tiles = tmp_path / "tiles"
    tiles.mkdir()
    shutil.copy(demo, tiles / "demo.laz")
    cat = _results(profile.run("geomatics:catalog", INPUT=tiles, WORKERS=1, CELL_SIZE=2,
                               BUFFER=0, OUTPUT_FOLDER=tmp_path / "cat"))
    assert cat["N_TILES"] == 1 and cat["N_FAILED"] == 0, cat
    assert (tmp_path / "cat" / "demo_classified.laz").is_file()
    # a second run plans nothing
    again = _results(profile.run("geomatics:installdependencies", WHEEL_FOLDER=wheelhouse))
    assert again["INSTALLED"] == "" and again["MISSING"] == ""


def test_clean_profile_from_the_package_index(demo, tmp_path):
    """The default mode: pip's configured index (PyPI here and in CI)."""
    profile = CleanProfile(tmp_path / "online")
    res = _results(profile.run("geomatics:installdependencies"))
    assert "--no-index" not in res["COMMAND"]
    installed = {p.split("==")[0].lower() for p in res["INSTALLED"].split(", ")}
    assert {"laspy", "lazrs"} <= installed and res["MISSING"] == ""
    _check_ground_filter(profile, demo, tmp_path / "classified.laz")

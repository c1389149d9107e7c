"""Shared test fixtures.

The checkout is a QGIS plugin package whose folder name is arbitrary, so the tests
load it under its installed name ``geomatics_toolbox`` (the same name ``make deploy``
links it as).  Three tiers:

* ``tests/core``  — plain pytest, no QGIS;
* ``tests/qgis``  — algorithms through ``processing.run`` in a headless QGIS
  (fixture ``qgis_processing``);
* ``tests/cli``   — ``qgis_process.bin --json run geomatics:…`` with the plugin
  enabled in a temporary profile (fixture ``qgis_process``).

Tiers 2 and 3 skip, with the reason, only when QGIS is not installed.

Every tier runs QGIS in a temporary profile: ``QGIS_CUSTOM_CONFIG_PATH`` is set to a
fresh folder of this session before any ``QgsApplication`` exists (and inherited by the
QGIS and ``qgis_process`` children the tests start), so a test run never reads or writes
the user's QGIS settings (``~/.local/share/QGIS`` …) — a test that switches the interface
to Arabic cannot leave a desktop QGIS, or another run, in Arabic.
"""
from __future__ import annotations

import atexit
import importlib.util
import json
import os
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[1]
PLUGIN_NAME = "geomatics_toolbox"
ISPRS_DIR = Path(os.environ.get("GEOMATICS_ISPRS_DIR",
                                ROOT.parent / "shared" / "data" / "isprs"))


def load_plugin_package() -> None:
    """Import the checkout as package ``geomatics_toolbox`` (idempotent)."""
    if PLUGIN_NAME in sys.modules:
        return
    spec = importlib.util.spec_from_file_location(
        PLUGIN_NAME, ROOT / "__init__.py", submodule_search_locations=[str(ROOT)])
    module = importlib.util.module_from_spec(spec)
    sys.modules[PLUGIN_NAME] = module
    spec.loader.exec_module(module)


load_plugin_package()


def use_temporary_qgis_profile() -> Path:
    """Point ``QGIS_CUSTOM_CONFIG_PATH`` at a new folder, removed when the session ends.

    Set at import of this file, i.e. before any test module or fixture can build a
    ``QgsApplication``; a value from the caller's environment is replaced on purpose.
    """
    import tempfile
    folder = Path(tempfile.mkdtemp(prefix="geomatics-test-qgis-profile-"))
    atexit.register(shutil.rmtree, folder, True)
    os.environ["QGIS_CUSTOM_CONFIG_PATH"] = str(folder)
    return folder


TEST_PROFILE = use_temporary_qgis_profile()


@pytest.fixture(scope="session")
def qgis_test_profile() -> Path:
    """The session's temporary QGIS profile folder (``QGIS_CUSTOM_CONFIG_PATH``)."""
    return TEST_PROFILE


@pytest.fixture(scope="session")
def isprs_dir() -> Path:
    """Folder of the ISPRS reference samples; skips when it is absent."""
    if not (ISPRS_DIR / "samp11.laz").exists():
        pytest.skip(f"ISPRS samples not found in {ISPRS_DIR} "
                    "(set GEOMATICS_ISPRS_DIR to their folder)")
    return ISPRS_DIR


# --------------------------------------------------------------------------- QGIS
def _have_qgis() -> str | None:
    try:
        import qgis.core  # noqa: F401
    except Exception as exc:  # pragma: no cover - depends on the machine
        return f"QGIS Python bindings not importable ({exc}); install python3-qgis"
    return None


@pytest.fixture(scope="session")
def qgis_app():
    """A headless QgsApplication with Processing and our provider registered.

    Its profile is the session's temporary one (:data:`TEST_PROFILE`).
    """
    reason = _have_qgis()
    if reason:
        pytest.skip(reason)
    os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
    os.environ["QGIS_CUSTOM_CONFIG_PATH"] = str(TEST_PROFILE)
    from qgis.core import QgsApplication
    sys.path.append("/usr/share/qgis/python/plugins")
    app = QgsApplication([], False)
    app.initQgis()
    from processing.core.Processing import Processing
    Processing.initialize()
    from geomatics_toolbox.provider.provider import GeomaticsProvider
    provider = GeomaticsProvider()
    QgsApplication.processingRegistry().addProvider(provider)
    app._geomatics_provider = provider  # keep a Python reference alive
    yield app
    registry = QgsApplication.processingRegistry()
    if registry.providerById("geomatics") is not None:
        registry.removeProvider("geomatics")


@pytest.fixture
def arabic_ui(qgis_app):
    """QGIS interface language Arabic (the locale override the plugin reads)."""
    from qgis.core import QgsSettings
    settings = QgsSettings()
    old = (settings.value("locale/overrideFlag", False, type=bool),
           settings.value("locale/userLocale", ""))
    settings.setValue("locale/overrideFlag", True)
    settings.setValue("locale/userLocale", "ar")
    yield
    settings.setValue("locale/overrideFlag", old[0])
    settings.setValue("locale/userLocale", old[1])


@pytest.fixture
def warning_feedback(qgis_app):
    """A QgsProcessingFeedback keeping every pushed warning in ``.warnings``."""
    from qgis.core import QgsProcessingFeedback

    class Warnings(QgsProcessingFeedback):
        def __init__(self):
            super().__init__()
            self.warnings = []

        def pushWarning(self, text):  # noqa: N802
            self.warnings.append(text)
    return Warnings()


@pytest.fixture(scope="session")
def qgis_processing(qgis_app):
    """The ``processing`` module, ready for ``processing.run('geomatics:…')``."""
    import processing
    return processing


class QgisProcess:
    """Runs ``qgis_process.bin`` with the plugin enabled in a temporary profile."""

    def __init__(self, exe: str, base: Path):
        self.exe = exe
        self.env = dict(os.environ)
        plugins = base / "plugins"
        plugins.mkdir()
        (plugins / PLUGIN_NAME).symlink_to(ROOT, target_is_directory=True)
        profile = base / "profile"
        profile.mkdir()
        # qgis_process runs the system Python: let it see the venv's laspy/lazrs/pykrige
        site = sysconfig.get_paths()["purelib"]
        paths = [p for p in self.env.get("PYTHONPATH", "").split(os.pathsep) if p]
        if site not in paths:
            paths.append(site)
        self.env.update(QT_QPA_PLATFORM="offscreen",
                        QGIS_CUSTOM_CONFIG_PATH=str(profile),
                        QGIS_PLUGINPATH=str(plugins),
                        PYTHONPATH=os.pathsep.join(paths))
        out = self.call("plugins", "enable", PLUGIN_NAME)
        if out.returncode != 0:
            raise RuntimeError(f"could not enable the plugin: {out.stdout}{out.stderr}")

    def call(self, *args: str, timeout: float = 600) -> subprocess.CompletedProcess:
        return subprocess.run([self.exe, *args], env=self.env, capture_output=True,
                              text=True, timeout=timeout)

    def run(self, algorithm: str, **params) -> dict:
        """``qgis_process.bin --json run ALG -- K=V …``; returns the parsed JSON."""
        args = ["--json", "run", algorithm, "--"]
        args += [f"{k}={v}" for k, v in params.items()]
        out = self.call(*args)
        text = out.stdout
        start = text.find("{")
        if out.returncode != 0 or start < 0:
            raise RuntimeError(f"qgis_process failed ({out.returncode}):\n"
                               f"{out.stdout}\n{out.stderr}")
        return json.loads(text[start:])

    def run_expect_failure(self, algorithm: str, **params) -> str:
        """Run and expect a non-zero exit; returns stdout+stderr."""
        args = ["--json", "run", algorithm, "--"]
        args += [f"{k}={v}" for k, v in params.items()]
        out = self.call(*args)
        assert out.returncode != 0, f"expected failure, got success:\n{out.stdout}"
        return out.stdout + out.stderr


@pytest.fixture(scope="session")
def qgis_process(tmp_path_factory) -> QgisProcess:
    """A ``QgisProcess`` runner; skips when QGIS is not installed."""
    exe = shutil.which("qgis_process.bin")
    if exe is None:
        pytest.skip("qgis_process.bin not found; install the Debian package qgis")
    return QgisProcess(exe, tmp_path_factory.mktemp("qgis_process"))

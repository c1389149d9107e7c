"""The test session runs QGIS in a temporary profile, never the user's (review T1).

Tests switch the QGIS interface to Arabic (``locale/userLocale``); in the user's
profile that left a desktop QGIS, and other test runs on the same machine, in Arabic.
"""
from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

CHILD = r"""
import os
os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
from qgis.core import QgsApplication, QgsSettings
app = QgsApplication([], False)
app.initQgis()
print("RESULT:" + QgsApplication.qgisSettingsDirPath() + "|" + QgsSettings().fileName())
"""


def _inside(path: str, folder: Path) -> bool:
    return Path(path).resolve().is_relative_to(folder.resolve())


def test_in_process_qgis_uses_the_session_profile(qgis_app, qgis_test_profile):
    from qgis.core import QgsApplication, QgsSettings
    profile = qgis_test_profile
    assert os.environ["QGIS_CUSTOM_CONFIG_PATH"] == str(profile)
    assert _inside(QgsApplication.qgisSettingsDirPath(), profile)
    settings = QgsSettings()
    assert _inside(settings.fileName(), profile), settings.fileName()
    assert not _inside(settings.fileName(), Path.home())
    # what the locale tests write lands in that file
    settings.setValue("geomatics_test/marker", "ar")
    settings.sync()
    try:
        assert "marker=ar" in Path(settings.fileName()).read_text(encoding="utf-8")
    finally:
        settings.remove("geomatics_test")
        settings.sync()


def test_qgis_children_of_the_tests_inherit_it(qgis_test_profile):
    out = subprocess.run([sys.executable, "-c", CHILD], capture_output=True, text=True,
                         timeout=300)
    lines = [ln for ln in out.stdout.splitlines() if ln.startswith("RESULT:")]
    assert out.returncode == 0 and lines, out.stdout + out.stderr
    settings_dir, settings_file = lines[-1][len("RESULT:"):].split("|")
    assert _inside(settings_dir, qgis_test_profile)
    assert _inside(settings_file, qgis_test_profile)

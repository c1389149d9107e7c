"""QGIS desktop (Xvfb), a fresh profile in Arabic, a Python without laspy/dask: the plugin
loads with no Python error and its message bar names the missing packages with an
Install button (the real start-up path, not a stand-in iface)."""
from __future__ import annotations

import json
import os
import shutil
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PLUGIN = "geomatics_toolbox"

PROBE = r"""
import json, os
from qgis.utils import iface
from qgis.PyQt.QtCore import QTimer
from qgis.PyQt.QtWidgets import QLabel, QPushButton
import qgis.utils

def probe():
    items = [{"text": it.text(), "title": it.title(),
              "buttons": [b.text() for b in it.findChildren(QPushButton)
                          if b.objectName() == "geomatics_install_button"]}
             for it in iface.messageBar().items()]
    with open(os.environ["PROBE_OUT"], "w", encoding="utf-8") as fh:
        json.dump({"items": items, "active": qgis.utils.active_plugins}, fh,
                  ensure_ascii=False)
    if os.environ.get("PROBE_PNG"):
        iface.mainWindow().grab().save(os.environ["PROBE_PNG"])
    QTimer.singleShot(300, iface.actionExit().trigger)

QTimer.singleShot(3000, probe)
"""


def test_desktop_start_shows_the_missing_packages(tmp_path):
    if not (shutil.which("qgis") and shutil.which("xvfb-run")):
        pytest.skip("QGIS desktop or xvfb-run not installed")
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "QT_QPA_PLATFORM")}
    check = subprocess.run(["/usr/bin/python3", "-c", "import laspy"], env=env,
                           capture_output=True)
    if check.returncode == 0:
        pytest.skip("the system Python has laspy: nothing would be missing")
    plugins = tmp_path / "plugins"
    plugins.mkdir()
    (plugins / PLUGIN).symlink_to(ROOT, target_is_directory=True)
    ini = tmp_path / "profiles" / "profiles" / "default" / "QGIS" / "QGIS3.ini"
    ini.parent.mkdir(parents=True)
    ini.write_text(f"[PythonPlugins]\n{PLUGIN}=true\n\n[locale]\noverrideFlag=true\n"
                   "userLocale=ar\n", encoding="utf-8")
    probe = tmp_path / "probe.py"
    probe.write_text(PROBE, encoding="utf-8")
    out = tmp_path / "out.json"
    env.update(QGIS_PLUGINPATH=str(plugins), PROBE_OUT=str(out),
               PROBE_PNG=os.environ.get("GEOMATICS_PROBE_PNG", ""))
    try:
        run = subprocess.run(["xvfb-run", "-a", "-s", "-screen 0 1280x900x24", "qgis",
                              "--profiles-path", str(tmp_path / "profiles"), "--nologo",
                              "--noversioncheck", "--code", str(probe)],
                             env=env, capture_output=True, text=True, timeout=180)
    except subprocess.TimeoutExpired as exc:    # a modal error dialog blocked start-up
        pytest.fail(f"QGIS did not finish starting (a Python error dialog?): {exc}")
    assert out.exists(), run.stdout[-3000:] + run.stderr[-3000:]
    res = json.loads(out.read_text(encoding="utf-8"))
    assert PLUGIN in res["active"]
    # ours once, and no Python error bar from loading the plugin (QGIS 3.40 adds its own
    # "Open Sans font installation failed" offline: not ours, not a Python error)
    ours = [i for i in res["items"] if i["title"] == "صندوق أدوات الجيوماتكس"]
    others = [i for i in res["items"] if i not in ours]
    assert len(ours) == 1, res["items"]
    assert not [i for i in others if any(w in (i["title"] + i["text"]).lower() for w in
                                         ("python", "plugin", "geomatics", "error"))], others
    item = ours[0]
    assert "laspy، lazrs" in item["text"] and "dask، distributed" in item["text"]
    assert "؛ " in item["text"]                # Arabic punctuation between the groups
    assert "ليدار" in item["text"] and "فهرس البلاطات" in item["text"]
    assert item["buttons"] == ["ثبّتها…"]

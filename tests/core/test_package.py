"""The plugin zip (`make package`) ships the plugin, never tests, fixtures or dev tools."""
import subprocess
import sys
import zipfile
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def test_package_ships_no_test_fixture(tmp_path):
    if not list((ROOT / "i18n").glob("*.qm")):
        pytest.skip("no compiled translations (run 'make qm' first)")
    subprocess.run([sys.executable, str(ROOT / "scripts" / "package.py"), "--out",
                    str(tmp_path)], check=True, cwd=ROOT, capture_output=True)
    (zip_path,) = tmp_path.glob("geomatics_toolbox-*.zip")
    names = zipfile.ZipFile(zip_path).namelist()
    assert all(n.startswith("geomatics_toolbox/") for n in names)
    rel = [n.split("/", 1)[1] for n in names]
    forbidden = ("tests/", "synthetic/", "benchmarks/", "scripts/", ".ci/")
    assert not [n for n in rel if n.startswith(forbidden)]
    assert not [n for n in rel if "synthetic" in n or n.startswith("test_")]
    lowered = [n.lower() for n in rel]
    assert not [n for n in lowered if any(w in n for w in ("bench", "test", "synthetic",
                                                            "conftest", "__pycache__"))]
    assert not [n for n in rel if n.endswith((".pyc", ".ts")) or n.startswith(".")]
    # the installer reads the pins from the shipped requirements.txt; every algorithm
    # has its icon and help page
    assert "requirements.txt" in rel and "requirements-dev.txt" not in rel
    pages = [n[len("help/"):-len(".html")] for n in rel
             if n.startswith("help/") and n.count("/") == 1 and n.endswith(".html")]
    assert len(pages) >= 24
    for name in pages:                  # one help page per algorithm (build_help.py)
        assert f"provider/icons/{name}.svg" in rel, name
    # what QGIS needs is there
    for needed in ("metadata.txt", "__init__.py", "plugin.py", "core/io/contract.py",
                   "i18n/geomatics_toolbox_ar.qm", "i18n/geomatics_toolbox_fa.qm"):
        assert needed in rel, needed
    assert any(n.startswith("i18n/strings/") and n.endswith(".json") for n in rel)

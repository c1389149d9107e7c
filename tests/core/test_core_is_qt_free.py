"""The core package must never pull in Qt, QGIS or Processing."""
import doctest
import importlib
import pkgutil
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
CORE_MODULES = sorted(m.name for m in pkgutil.iter_modules([str(ROOT / "core")]))


def test_importing_every_core_module_loads_no_qt_or_qgis():
    code = f"""
import importlib.util, sys
spec = importlib.util.spec_from_file_location(
    "geomatics_toolbox", {str(ROOT / '__init__.py')!r},
    submodule_search_locations=[{str(ROOT)!r}])
mod = importlib.util.module_from_spec(spec); sys.modules["geomatics_toolbox"] = mod
spec.loader.exec_module(mod)
for name in {CORE_MODULES!r}:
    importlib.import_module("geomatics_toolbox.core." + name)
bad = sorted(m for m in sys.modules if m.split(".")[0] in
             ("qgis", "PyQt5", "PyQt6", "sip", "processing"))
print("BAD:" + ",".join(bad))
"""
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=300)
    assert out.returncode == 0, out.stderr
    assert out.stdout.strip().splitlines()[-1] == "BAD:", out.stdout
    assert len(CORE_MODULES) >= 8


@pytest.mark.parametrize("name", CORE_MODULES)
def test_core_doctests(name):
    module = importlib.import_module(f"geomatics_toolbox.core.{name}")
    failures, _ = doctest.testmod(module, optionflags=doctest.ELLIPSIS)
    assert failures == 0

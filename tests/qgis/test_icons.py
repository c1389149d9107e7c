"""Every algorithm (and the shipped model) shows its own icon, drawn by scripts/build_icons.py."""
from __future__ import annotations

import importlib.util
import os
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def _algorithms():
    from qgis.core import QgsApplication
    provider = QgsApplication.processingRegistry().providerById("geomatics")
    return list(provider.algorithms())


def test_each_algorithm_has_its_own_existing_icon(qgis_app):
    from qgis.PyQt.QtSvg import QSvgRenderer
    paths = {}
    for alg in _algorithms():
        path = alg.svgIconPath()
        assert os.path.basename(path) == f"{alg.name()}.svg", (alg.id(), path)
        assert os.path.isfile(path) and QSvgRenderer(path).isValid(), path
        paths[alg.id()] = Path(path).read_bytes()
    assert len(paths) >= 24
    assert len(set(paths.values())) == len(paths)            # no two alike
    assert "geomatics:lidar_to_dtm" in paths and "geomatics:installdependencies" in paths


def test_icons_are_up_to_date_with_the_script():
    spec = importlib.util.spec_from_file_location("build_icons",
                                                  ROOT / "scripts" / "build_icons.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    for name, (title, body) in mod.ICONS.items():
        committed = (ROOT / "provider" / "icons" / f"{name}.svg").read_text(encoding="utf-8")
        assert committed == mod.svg(title, body), f"run scripts/build_icons.py ({name})"

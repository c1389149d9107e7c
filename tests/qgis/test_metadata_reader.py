"""metadata.txt as QGIS reads it: qgis.utils.findPlugins and the Plugin Manager's parser.

Both use ``configparser.ConfigParser()`` with interpolation on, so a bare ``%`` in any
value raises ``InterpolationSyntaxError`` when that value is read and the Plugin
Manager silently drops it; every value (translated ones too) must read cleanly.
"""
from __future__ import annotations

import configparser
import os
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
PLUGIN = "geomatics_toolbox"


@pytest.fixture(scope="module")
def parser(qgis_app, tmp_path_factory):
    from qgis import utils
    plugins = tmp_path_factory.mktemp("plugins")
    (plugins / PLUGIN).symlink_to(ROOT, target_is_directory=True)
    found = dict(utils.findPlugins(str(plugins)))
    assert PLUGIN in found and found[PLUGIN] is not None
    return found[PLUGIN]


def test_every_value_reads_with_qgis_parser(parser):
    values = {key: parser.get("general", key) for key in parser.options("general")}
    for key in ("name", "description", "about", "version", "qgisMinimumVersion",
                "qgisMaximumVersion", "author", "email", "repository", "tags", "icon",
                "hasProcessingProvider", "changelog"):
        assert key.lower() in values, key
    # the Plugin Manager looks up name[ar] / description[fa] / about[ar] for the UI locale
    for lang in ("ar", "fa"):
        for key in ("description", "about"):
            text = parser.get("general", f"{key}[{lang}]")
            assert re.search(r"[\u0600-\u06FF]", text), (key, lang)
            if key == "about":
                assert "geomatics:installdependencies" in text and "laspy" in text


def test_pyplugin_installer_reads_it_without_error(qgis_app):
    """The Plugin Manager's getInstalledPlugin: version, min/max, icon, no error."""
    import sys
    sys.path.append("/usr/share/qgis/python")
    from pyplugin_installer.installer_data import Plugins
    info = Plugins().getInstalledPlugin(PLUGIN, str(ROOT), readOnly=True)
    assert info["error"] == "", info
    # its parser notes the first lookup that failed: only an optional key this file does
    # not set (name[C] for the system locale, 3.40's supportsQt6) may be there, never an
    # unreadable value
    assert re.fullmatch(r"[\w\[\]]*", info["error_details"]), info["error_details"]
    assert info["version_installed"] == "0.2.0"
    assert "laspy" in info["about"] and "installdependencies" in info["about"]
    assert os.path.isfile(info["icon"])


def test_versions_are_the_tested_ones(parser):
    assert parser.get("general", "qgisMinimumVersion") == "3.22"
    assert parser.get("general", "qgisMaximumVersion") == "3.40"


def test_about_is_current_and_names_dependencies_and_installer(parser):
    about = parser.get("general", "about")
    for word in ("laspy", "lazrs", "dask", "distributed", "geomatics:installdependencies",
                 "Install the Python packages this toolbox needs", "Arabic", "Persian",
                 "kriging", "GSD", "catalog", "offline"):
        assert word in about, word
    assert "pip install" not in about and "pykrige" not in about.lower()
    raw = (ROOT / "metadata.txt").read_text(encoding="utf-8")
    assert "%" not in raw


def test_no_invented_urls(parser):
    for key in ("homepage", "tracker", "repository"):
        value = parser.get("general", key, fallback="")
        assert value == "" or value.startswith("https://"), (key, value)
    assert not re.search(r"example\.(com|org)|your[-_]?name|TODO",
                         (ROOT / "metadata.txt").read_text(encoding="utf-8"))


def test_plain_configparser_agrees():
    cp = configparser.ConfigParser()
    cp.read(ROOT / "metadata.txt", encoding="utf-8")
    assert all(cp.get("general", k) is not None for k in cp.options("general"))

"""Release habits: licence, honest metadata, changelog in step with the version."""
import configparser
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def _meta():
    cp = configparser.ConfigParser(interpolation=None)
    cp.read(ROOT / "metadata.txt", encoding="utf-8")
    return cp["general"]


def test_licence_is_full_gpl2_or_later():
    text = (ROOT / "LICENSE").read_text(encoding="utf-8")
    assert "GNU GENERAL PUBLIC LICENSE" in text and "Version 2, June 1991" in text
    assert "END OF TERMS AND CONDITIONS" in text      # the full text, not a stub
    assert "GPL-2.0-or-later" in text and "any later version" in text
    assert len(text.splitlines()) > 330


def test_metadata_is_honest():
    meta = _meta()
    for key in ("name", "qgisMinimumVersion", "description", "about", "version", "author",
                "email", "repository"):
        assert key in meta, key
    raw = (ROOT / "metadata.txt").read_text(encoding="utf-8")
    for fake in ("invalid", "example.", "placeholder:", "example.com"):
        assert fake not in raw.lower().replace("e.g.", ""), fake
    assert meta["email"] == "" or re.fullmatch(r"[^@\s]+@[^@\s]+\.[a-z]{2,}", meta["email"])
    assert meta["version"] == "0.2.0"


def test_changelog_has_the_current_version():
    version = _meta()["version"]
    text = (ROOT / "CHANGELOG.md").read_text(encoding="utf-8")
    assert re.search(rf"^## {re.escape(version)}\b", text, re.M)
    assert version in _meta()["changelog"].split()[0]

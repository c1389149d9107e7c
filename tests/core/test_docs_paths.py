"""DEVELOPERS.md and README.md describe the code as it is: every module they name exists.

A path in backticks (``core/io/contract.py``, ``algorithms/base.py``, ``tests/qgis/``), a
bare module file name (``contract.py``) or a dotted core module (``core.lidar.filters``)
must name a file or folder of the repository.
"""
from __future__ import annotations

import re
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
DOCS = ("DEVELOPERS.md", "README.md")
TICKED = re.compile(r"`([^`\n]+)`")
DOTTED = re.compile(r"^(core(?:\.[a-z_][a-z0-9_]*)+)$")
PATHLIKE = re.compile(r"^[A-Za-z0-9_./-]+$")
TOP = ("core/", "algorithms/", "tests/", "scripts/", "benchmarks/", "synthetic/",
       "provider/", "models/", "i18n/", "help/")


def _tracked() -> set:
    out = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True,
                         check=True).stdout.split()
    return set(out)


def _named(text: str):
    """(token, kind) of every module path the text names."""
    for tok in TICKED.findall(text):
        tok = tok.strip().split("::")[0].split(" ")[0].rstrip(",.:;")
        if not tok or not PATHLIKE.match(tok) or "*" in tok or tok.startswith(("../", "/")):
            continue
        if DOTTED.match(tok):
            yield tok, "dotted"
        elif tok.startswith(TOP) and ("/" in tok.rstrip("/") or tok.endswith("/")):
            yield tok, "path"
        elif tok.endswith(".py") and "/" not in tok:
            yield tok, "file"


def _exists(tok: str, kind: str, tracked: set) -> bool:
    if kind == "path":
        tok = tok.split(":")[0]
        return (ROOT / tok).exists() or any(f.startswith(tok.rstrip("/") + "/")
                                            for f in tracked)
    if kind == "file":
        return any(f == tok or f.endswith("/" + tok) for f in tracked)
    rel = tok.replace(".", "/")
    if (ROOT / (rel + ".py")).exists() or (ROOT / rel / "__init__.py").exists():
        return True
    head, _, attr = tok.rpartition(".")       # core.lidar.filters.GROUND_FILTERS
    mod = head.replace(".", "/")
    return attr.isidentifier() and ((ROOT / (mod + ".py")).exists()
                                    or (ROOT / mod / "__init__.py").exists())


@pytest.mark.parametrize("doc", DOCS)
def test_every_module_path_named_exists(doc):
    tracked = _tracked() | {str(p.relative_to(ROOT)) for p in ROOT.rglob("*.py")
                            if ".venv" not in p.parts}
    text = (ROOT / doc).read_text(encoding="utf-8")
    named = list(_named(text))
    assert len(named) >= (10 if doc == "DEVELOPERS.md" else 3)
    missing = sorted({tok for tok, kind in named if not _exists(tok, kind, tracked)})
    assert missing == [], f"{doc} names modules that do not exist: {missing}"


def test_the_scanner_sees_stale_names():
    names = dict(_named("`las_io.py`, `core/io/contract.py`, `core.lidar.filters`, `x`"))
    assert names == {"las_io.py": "file", "core/io/contract.py": "path",
                     "core.lidar.filters": "dotted"}
    tracked = _tracked()
    assert not _exists("las_io.py", "file", tracked)
    assert _exists("core/io/contract.py", "path", tracked)

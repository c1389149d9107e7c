"""Regenerate the Qt translation files from the sources and the JSON dictionaries.

Translations live in ``i18n/strings/*.json`` (one file per topic, each mapping an
English source string to ``{"ar": ..., "fa": ...}``): they are the single source of
truth, read directly (without Qt) by the report translator in
:mod:`geomatics_toolbox.core.i18n`, and filled by this script into the
``i18n/geomatics_toolbox_<lang>.ts`` files that ``lrelease`` compiles for Qt.

Usage (``make ts`` runs it)::

    python scripts/i18n_sync.py            # pylupdate5 + fill + report missing
    python scripts/i18n_sync.py --check    # exit 1 if a source string lacks a translation
    python scripts/i18n_sync.py --export   # one-off: .ts translations -> strings/base.json

Never edit the ``.ts`` files by hand: on a merge conflict take either side and re-run
``make ts``.
"""
from __future__ import annotations

import argparse
import json
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
I18N = ROOT / "i18n"
STRINGS = I18N / "strings"
LANGS = ("ar", "fa")


def ts_path(lang: str) -> Path:
    return I18N / f"geomatics_toolbox_{lang}.ts"


def load_dictionary() -> dict:
    """Merge every ``i18n/strings/*.json`` into one ``{source: {lang: text}}``."""
    merged: dict = {}
    for path in sorted(STRINGS.glob("*.json")):
        data = json.loads(path.read_text(encoding="utf-8"))
        for source, tr in data.items():
            slot = merged.setdefault(source, {})
            for lang, text in tr.items():
                if text and lang not in slot:
                    slot[lang] = text
    return merged


def sources() -> list:
    out = subprocess.run(["git", "ls-files", "*.py"], cwd=ROOT, capture_output=True,
                         text=True, check=True).stdout.split()
    return [f for f in out if not f.startswith(("tests/", "benchmarks/", "scripts/",
                                                "synthetic/"))]


def run_pylupdate() -> None:
    files = [str(ROOT / f) for f in sources()]
    subprocess.run(["pylupdate5", "-noobsolete", *files, "-ts",
                    *[str(ts_path(lang)) for lang in LANGS]], check=True, cwd=ROOT)


def fill(dictionary: dict) -> dict:
    """Fill every message of the .ts files from the dictionary; return missing per lang."""
    missing = {}
    for lang in LANGS:
        path = ts_path(lang)
        tree = ET.parse(path)
        miss = []
        for msg in tree.getroot().iter("message"):
            source = msg.findtext("source")
            tr = msg.find("translation")
            text = dictionary.get(source, {}).get(lang)
            if text:
                tr.text = text
                tr.attrib.pop("type", None)
            elif not (tr.text or "").strip() or tr.get("type") == "unfinished":
                miss.append(source)
            for loc in msg.findall("location"):
                msg.remove(loc)
        ET.indent(tree, space="    ")
        body = ET.tostring(tree.getroot(), encoding="unicode")
        path.write_text('<?xml version="1.0" encoding="utf-8"?>\n<!DOCTYPE TS>\n' + body
                        + "\n", encoding="utf-8")
        missing[lang] = sorted(set(miss))
    return missing


def export_base() -> None:
    """Write the translations now in the .ts files to ``strings/base.json``."""
    out: dict = {}
    for lang in LANGS:
        for msg in ET.parse(ts_path(lang)).getroot().iter("message"):
            text = msg.findtext("translation")
            if text and msg.find("translation").get("type") != "unfinished":
                out.setdefault(msg.findtext("source"), {}).setdefault(lang, text)
    STRINGS.mkdir(exist_ok=True)
    (STRINGS / "base.json").write_text(json.dumps(out, ensure_ascii=False, indent=1,
                                                  sort_keys=True) + "\n", encoding="utf-8")
    print(f"{len(out)} strings -> {STRINGS / 'base.json'}")


def main() -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--check", action="store_true")
    ap.add_argument("--export", action="store_true")
    args = ap.parse_args()
    if args.export:
        export_base()
        return 0
    if not args.check:
        run_pylupdate()
    missing = fill(load_dictionary())
    bad = False
    for lang, miss in missing.items():
        if miss:
            bad = True
            print(f"{lang}: {len(miss)} source strings without a translation "
                  "(add them to a file in i18n/strings/):", file=sys.stderr)
            for s in miss[:50]:
                print(f"  {s!r}", file=sys.stderr)
    return 1 if (bad and args.check) else 0


if __name__ == "__main__":
    sys.exit(main())

"""Regenerate the Qt translation files from the sources and the JSON dictionaries.

Translations live in ``i18n/strings/*.json`` (one file per topic, each mapping an
English source string to ``{"ar": ..., "fa": ...}``): they are the single source of
truth, read directly (without Qt) by the report translator in
:mod:`geomatics_toolbox.core.i18n`, and filled by this script into the
``i18n/geomatics_toolbox_<lang>.ts`` files that ``lrelease`` compiles for Qt.

Usage (``make ts`` runs it)::

    python scripts/i18n_sync.py            # pylupdate5 + fill + report missing
    python scripts/i18n_sync.py --check    # exit 1 if a source string or an InputError
                                           # template lacks a translation
    python scripts/i18n_sync.py --export   # one-off: .ts translations -> strings/base.json

Never edit the ``.ts`` files by hand: on a merge conflict take either side and re-run
``make ts``.
"""
from __future__ import annotations

import argparse
import ast
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


def _literal(node):
    """The text of a string-literal node (implicit concatenations included), else None."""
    if isinstance(node, ast.Constant) and isinstance(node.value, str):
        return node.value
    return None


def input_error_templates() -> tuple:
    """``InputError`` templates in core/ and algorithms/, and the calls that are no template.

    Returns ``({template: "file:line"}, ["file:line: problem", ...])``. A template is the
    literal first argument of ``InputError(...)``; an f-string or a concatenation there
    is a problem (write ``InputError("... {name} ...", name=value)``). A variable
    (``InputError(str(exc))``, an already translated ``self.tr(...)``) is allowed.
    """
    templates, problems = {}, []
    for rel in sources():
        if rel.startswith(("core/", "algorithms/")):
            scan_input_errors((ROOT / rel).read_text(encoding="utf-8"), rel, templates,
                              problems)
    return templates, problems


def scan_input_errors(src: str, rel: str, templates: dict, problems: list) -> None:
    """Add the ``InputError`` templates and problems of one source file."""
    for node in ast.walk(ast.parse(src)):
        func = getattr(node, "func", None)
        if not (isinstance(node, ast.Call) and node.args and (
                getattr(func, "id", None) == "InputError"
                or getattr(func, "attr", None) == "InputError")):
            continue
        arg, where = node.args[0], f"{rel}:{node.lineno}"
        text = _literal(arg)
        if text is not None:
            templates.setdefault(text, where)
        elif isinstance(arg, (ast.JoinedStr, ast.BinOp)):
            problems.append(f"{where}: InputError message built with an f-string or +; "
                            "use a template with fields: InputError(\"... {name} ...\", "
                            "name=value)")


def tr_call_problems() -> list:
    """``tr``/``translate``/``QT_TRANSLATE_NOOP`` calls whose text is not a literal.

    pylupdate5 cannot see ``self.tr(label)``: such a string stays English. A call may
    pass a variable only when its line says ``# i18n: noop-list`` (the values are
    ``QT_TRANSLATE_NOOP`` literals elsewhere, checked at run time by the tests).
    """
    problems = []
    for rel in sources():
        if not rel.startswith("core/"):   # core translates from the JSON, not through Qt
            problems += scan_tr_calls((ROOT / rel).read_text(encoding="utf-8"), rel)
    return problems


def scan_tr_calls(src: str, rel: str) -> list:
    """Problems of one source file: tr()/translate() of a non-literal, unmarked."""
    problems, lines = [], src.splitlines()
    for node in ast.walk(ast.parse(src)):
        if not isinstance(node, ast.Call):
            continue
        name = getattr(node.func, "attr", None) or getattr(node.func, "id", None)
        if name == "tr" and node.args:
            arg = node.args[0]
        elif name in ("translate", "QT_TRANSLATE_NOOP") and len(node.args) >= 2:
            arg = node.args[1]
        else:
            continue
        if _literal(arg) is not None:
            continue
        if "i18n: noop-list" in lines[node.lineno - 1] or \
                "i18n: noop-list" in lines[getattr(node, "end_lineno", node.lineno) - 1]:
            continue
        problems.append(f"{rel}:{node.lineno}: {name}() of a non-literal is invisible "
                        "to pylupdate5 (stays English); pass a literal, or wrap the "
                        "values in QT_TRANSLATE_NOOP and mark the line '# i18n: noop-list'")
    return problems


#: exceptions whose message reaches the user; core raises InputError templates instead
PLAIN_ERRORS = ("ValueError", "RuntimeError")
#: feedback calls whose text the user reads in the log
FEEDBACK = ("pushInfo", "pushWarning", "reportError", "pushCommandInfo", "pushConsoleInfo",
            "setProgressText")
#: per-file counts of English-only messages not converted yet (a ratchet: may only fall)
MESSAGE_BASELINE = ROOT / "scripts" / "message_baseline.json"


def _is_tr(node) -> bool:
    """``self.tr(...)``/``translate(...)``, or ``.format(...)`` of one."""
    if not isinstance(node, ast.Call):
        return False
    name = getattr(node.func, "attr", None) or getattr(node.func, "id", None)
    if name in ("tr", "translate"):
        return True
    return name == "format" and _is_tr(getattr(node.func, "value", None))


def _english(node) -> bool:
    """A message argument that is English text: a literal, an f-string, a + or a
    ``.format`` of a literal (a variable or a call is judged where it is built)."""
    if _literal(node) is not None or isinstance(node, (ast.JoinedStr, ast.BinOp)):
        return True
    if isinstance(node, ast.Call) and getattr(node.func, "attr", None) == "format":
        return _english(node.func.value)
    return False


def scan_messages(src: str, rel: str) -> list:
    """English-only messages of one file: ``raise ValueError/RuntimeError("...")`` with a
    message (core and algorithms), and literal English in ``algorithms/`` raised as
    ``QgsProcessingException`` or written to the log (``feedback.pushInfo("...")``)."""
    problems, lines = [], src.splitlines()

    def marked(node) -> bool:
        """``# i18n: data`` (numbers, ids) or ``# i18n: internal`` (a programming error
        no input can cause) on the statement's first or last line."""
        ends = (node.lineno, getattr(node, "end_lineno", node.lineno))
        return any(tag in lines[n - 1] for n in ends
                   for tag in ("# i18n: data", "# i18n: internal"))

    for node in ast.walk(ast.parse(src)):
        if isinstance(node, (ast.Raise, ast.Call)) and marked(node):
            continue
        if isinstance(node, ast.Raise) and isinstance(node.exc, ast.Call):
            name = getattr(node.exc.func, "id", None) or getattr(node.exc.func, "attr", None)
            args = node.exc.args
            if name in PLAIN_ERRORS and args and not _is_tr(args[0]):
                problems.append(f"{rel}:{node.lineno}: raise {name}(...) with a message the "
                                "user reads in English: raise InputError(\"template "
                                "{field}\", field=value) with ar/fa in i18n/strings/")
            elif (name == "QgsProcessingException" and rel.startswith("algorithms/")
                  and args and _english(args[0]) and not _is_tr(args[0])):
                problems.append(f"{rel}:{node.lineno}: QgsProcessingException with literal "
                                "English: use self.tr(...) or an InputError template")
        elif (isinstance(node, ast.Call) and rel.startswith("algorithms/")
              and getattr(node.func, "attr", None) in FEEDBACK and node.args
              and _english(node.args[0]) and not _is_tr(node.args[0])):
            problems.append(f"{rel}:{node.lineno}: feedback.{node.func.attr}() of literal "
                            "English: wrap it in self.tr(...)")
    return problems


def message_problems() -> tuple:
    """``(problems, over)``: every English-only message, and the files whose count rose
    above the baseline (``scripts/message_baseline.json``)."""
    per_file, problems = {}, []
    for rel in sources():
        if rel.startswith(("core/", "algorithms/")):
            found = scan_messages((ROOT / rel).read_text(encoding="utf-8"), rel)
            problems += found
            if found:
                per_file[rel] = len(found)
    baseline = json.loads(MESSAGE_BASELINE.read_text(encoding="utf-8")) \
        if MESSAGE_BASELINE.exists() else {}
    over = [f"{rel}: {n} English-only messages (baseline {baseline.get(rel, 0)}); convert "
            "them to InputError templates / self.tr()" for rel, n in sorted(per_file.items())
            if n > baseline.get(rel, 0)]
    return problems, over


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
    ap.add_argument("--messages", action="store_true",
                    help="list every English-only message left (core, algorithms)")
    args = ap.parse_args()
    if args.export:
        export_base()
        return 0
    if not args.check:
        run_pylupdate()
    dictionary = load_dictionary()
    missing = fill(dictionary)
    bad = False
    templates, problems = input_error_templates()
    for lang in LANGS:
        miss = [t for t in templates if not dictionary.get(t, {}).get(lang)]
        if miss:
            bad = True
            print(f"{lang}: {len(miss)} InputError messages without a translation "
                  "(add them to a file in i18n/strings/):", file=sys.stderr)
            for t in miss[:50]:
                print(f"  {templates[t]}: {t!r}", file=sys.stderr)
    for problem in problems + tr_call_problems():
        bad = True
        print(problem, file=sys.stderr)
    english, over = message_problems()
    if args.messages:
        print("\n".join(english))
    for problem in over:
        bad = True
        print(problem, file=sys.stderr)
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

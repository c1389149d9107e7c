#!/usr/bin/env python3
"""Write the help pages shipped with the plugin: ``help/[<lang>/]<algorithm>.html``.

Each page is generated from the algorithm's own help string and parameter definitions
(translated with the plugin's .qm files for ar and fa), so it cannot drift from the
dialog; ``GeomaticsAlgorithm.helpUrl`` links to it with ``file://``.

Usage::

    make help-pages                                  # write help/
    .venv/bin/python scripts/build_help.py --check   # exit 1 if help/ is stale
"""
from __future__ import annotations

import argparse
import html
import os
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
HELP = ROOT / "help"
LANGS = ("en", "ar", "fa")

PAGE = """<!DOCTYPE html>
<html lang="{lang}" dir="{dir}">
<head><meta charset="utf-8"><title>{title}</title>
<style>body{{font-family:"Noto Sans","Noto Naskh Arabic",Tahoma,sans-serif;margin:1.5em;
max-width:900px}}table{{border-collapse:collapse}}td,th{{border:1px solid #bbb;
padding:.2em .5em}}code{{unicode-bidi:isolate}}</style></head>
<body>
<h1>{title}</h1>
{help}
<table><tr><th>{h_name}</th><th>{h_label}</th><th>{h_default}</th></tr>
{rows}
</table>
</body>
</html>
"""


def _load_package():
    import importlib.util
    name = "geomatics_toolbox"
    if name not in sys.modules:
        spec = importlib.util.spec_from_file_location(
            name, ROOT / "__init__.py", submodule_search_locations=[str(ROOT)])
        mod = importlib.util.module_from_spec(spec)
        sys.modules[name] = mod
        spec.loader.exec_module(mod)


def page(alg, lang: str) -> str:
    """One help page of ``alg`` in the current translation."""
    from geomatics_toolbox.core.reporting.i18n import translator
    tr = translator(lang)
    rows = []
    for d in alg.parameterDefinitions():
        default = d.defaultValue()
        rows.append("<tr><td><code dir=\"ltr\">{}</code></td><td>{}</td><td>"
                    "<bdi dir=\"ltr\">{}</bdi></td></tr>".format(
                        html.escape(d.name()), html.escape(d.description()),
                        "" if default is None else html.escape(str(default))))
    return PAGE.format(lang=lang, dir="rtl" if lang in ("ar", "fa") else "ltr",
                       title=html.escape(alg.displayName()), help=alg.shortHelpString(),
                       h_name=tr("Parameter"), h_label=tr("Label"), h_default=tr("Default"),
                       rows="\n".join(rows))


def pages() -> dict:
    """``{relative path: html}`` of every page in every language."""
    from qgis.PyQt.QtCore import QCoreApplication, QTranslator
    _load_package()
    from geomatics_toolbox.algorithms import all_algorithms
    out = {}
    for lang in LANGS:
        translator = QTranslator()
        if lang != "en":
            qm = ROOT / "i18n" / f"geomatics_toolbox_{lang}.qm"
            if not translator.load(str(qm)):
                raise SystemExit(f"cannot load {qm}: run make qm")
            QCoreApplication.installTranslator(translator)
        try:
            for alg in all_algorithms():
                alg.initAlgorithm()
                rel = Path(f"{alg.name()}.html") if lang == "en" else \
                    Path(lang) / f"{alg.name()}.html"
                out[rel] = page(alg, lang)
        finally:
            QCoreApplication.removeTranslator(translator)
    return out


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--check", action="store_true", help="exit 1 if help/ is stale")
    args = ap.parse_args(argv)
    os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
    from qgis.core import QgsApplication
    app = QgsApplication([], False)
    app.initQgis()
    wanted = pages()
    stale = [str(rel) for rel, text in wanted.items()
             if not (HELP / rel).is_file()
             or (HELP / rel).read_text(encoding="utf-8") != text]
    if args.check:
        if stale:
            print("stale help pages (run make help-pages): " + ", ".join(stale), file=sys.stderr)
        return 1 if stale else 0
    for rel, text in wanted.items():
        (HELP / rel).parent.mkdir(parents=True, exist_ok=True)
        (HELP / rel).write_text(text, encoding="utf-8")
    print(f"wrote {len(wanted)} help pages under {HELP}")
    return 0


if __name__ == "__main__":
    sys.exit(main())

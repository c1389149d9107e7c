#!/usr/bin/env python3
"""Render every dialog and every report in en/ar/fa into out/screenshots/ for review.

Dialogs: each algorithm's Processing dialog (the processing plugin's AlgorithmDialog,
as the toolbox opens it) with the plugin's translation loaded and the layout direction
of the language, grabbed as a PNG. Reports: each report algorithm of
``tests/cli/test_reports_browser.py`` run with REPORT_LANGUAGE, then photographed by
headless Chromium. Run through ``make screenshots`` (Xvfb, installs what it needs).
"""
from __future__ import annotations

import argparse
import os
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
LANGS = {"en": 1, "ar": 2, "fa": 3}      # REPORT_LANGUAGE index


def _setup():
    import importlib.util
    sys.path[:0] = [str(ROOT / "tests"), str(ROOT / "tests" / "cli"),
                    "/usr/share/qgis/python/plugins"]
    name = "geomatics_toolbox"
    if name not in sys.modules:
        spec = importlib.util.spec_from_file_location(
            name, ROOT / "__init__.py", submodule_search_locations=[str(ROOT)])
        mod = importlib.util.module_from_spec(spec)
        sys.modules[name] = mod
        spec.loader.exec_module(mod)


def dialogs(out: Path, lang: str, only=()) -> int:
    """Grab the dialog of every algorithm (or of those in ``only``) in ``lang``."""
    from processing.gui.AlgorithmDialog import AlgorithmDialog
    from qgis.core import QgsApplication
    provider = QgsApplication.processingRegistry().providerById("geomatics")
    n = 0
    for alg in provider.algorithms():
        if only and alg.name() not in only:
            continue
        dlg = AlgorithmDialog(alg.create(), False, None)
        dlg.resize(900, 700)
        dlg.show()
        QgsApplication.processEvents()
        dlg.grab().save(str(out / f"dialog_{alg.name()}_{lang}.png"))
        dlg.close()
        dlg.deleteLater()
        n += 1
    return n


def reports(out: Path, lang: str, only=()) -> int:
    """Run every checked report algorithm (or those in ``only``) in ``lang`` and
    photograph the page."""
    import browser
    import processing
    from test_reports_browser import CASES
    n = 0
    with tempfile.TemporaryDirectory() as tmp:
        for alg_id, case in CASES.items():
            if only and alg_id.split(":")[1] not in only:
                continue
            params, output, _ = case(Path(tmp))
            html = Path(tmp) / f"{alg_id.split(':')[1]}_{lang}.html"
            processing.run(alg_id, {**{k: str(v) for k, v in params.items()},
                                    output: str(html), "REPORT_LANGUAGE": LANGS[lang]})
            browser.screenshot(html, out / f"report_{alg_id.split(':')[1]}_{lang}.png")
            n += 1
    return n


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--out", default=str(ROOT / "out" / "screenshots"))
    ap.add_argument("--langs", default="en,ar,fa")
    ap.add_argument("--no-reports", action="store_true")
    ap.add_argument("--only", default="",
                    help="comma-separated algorithm names (default: all), e.g. idwdtm,dsm")
    args = ap.parse_args(argv)
    out = Path(args.out)
    out.mkdir(parents=True, exist_ok=True)
    _setup()
    # a throw-away QGIS profile: the locale set per language below never reaches the
    # user's (or another process's) settings
    profile = tempfile.mkdtemp(prefix="geomatics-screenshots-")
    os.environ["QGIS_CUSTOM_CONFIG_PATH"] = profile
    from qgis.core import QgsApplication
    from qgis.PyQt.QtCore import Qt, QTranslator
    app = QgsApplication([], True)
    app.initQgis()
    from processing.core.Processing import Processing
    Processing.initialize()
    from geomatics_toolbox.provider.provider import GeomaticsProvider
    provider = GeomaticsProvider()
    QgsApplication.processingRegistry().addProvider(provider)
    total = 0
    for lang in args.langs.split(","):
        translator, qgis_translator = QTranslator(), QTranslator()
        if lang != "en":      # the plugin's strings and QGIS's own (Run, Log, optional …)
            translator.load(str(ROOT / "i18n" / f"geomatics_toolbox_{lang}.qm"))
            qgis_translator.load(f"/usr/share/qgis/i18n/qgis_{lang}.qm")
            # as in QGIS: QGIS's translator first, the plugin's last, so that Qt consults
            # the plugin's first and its overrides (plugin.QGIS_OVERRIDES) win
            QgsApplication.installTranslator(qgis_translator)
            QgsApplication.installTranslator(translator)
        QgsApplication.setLayoutDirection(Qt.RightToLeft if lang in ("ar", "fa")
                                          else Qt.LeftToRight)
        # as QGIS started in that language: the plugin reads its locale setting
        # (restored below: the profile's own setting is left as it was)
        from qgis.core import QgsSettings
        settings = QgsSettings()
        saved = [(k, settings.value(k)) for k in ("locale/overrideFlag",
                                                   "locale/userLocale")]
        settings.setValue("locale/overrideFlag", lang != "en")
        settings.setValue("locale/userLocale", lang)
        try:
            only = tuple(filter(None, args.only.split(",")))
            total += dialogs(out, lang, only)
            if not args.no_reports:
                total += reports(out, lang, only)
        finally:
            QgsApplication.removeTranslator(translator)
            QgsApplication.removeTranslator(qgis_translator)
            for key, value in saved:
                if value is None:
                    settings.remove(key)
                else:
                    settings.setValue(key, value)
    print(f"wrote {total} screenshots to {out}")
    QgsApplication.processingRegistry().removeProvider(provider)
    return 0


if __name__ == "__main__":
    os.environ.setdefault("QT_QPA_PLATFORM", "xcb")
    sys.exit(main())

"""Every dialog label, enum option and output name of every algorithm is translated.

pylupdate5 only sees ``tr("literal")``: a label passed as ``self.tr(label)`` from a
list stays English unless the list's strings are ``QT_TRANSLATE_NOOP`` literals. This
test instantiates every algorithm with the shipped Arabic and Persian translations and
compares each visible string with its English text (`make lint` flags the call sites).
"""
from __future__ import annotations

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
#: visible strings that are the same in every language (language names, units, ids)
SAME_EVERYWHERE = {"English", "العربية", "فارسی", "RMSE (m)", "LE90 (m)", "CE90 (m)",
                   "RMSE", "IDW", "TIN", "DSM", "DTM", "nDSM"}
#: (algorithm, parameter) whose options are product names (camera models)
PRODUCT_OPTIONS = {("gsdcalculator", "CAMERA")}


def _visible(alg) -> dict:
    """{where: text} of every parameter label, enum option and output name."""
    out = {}
    for p in alg.parameterDefinitions():
        out[f"{p.name()}"] = p.description()
        for i, opt in enumerate(getattr(p, "options", lambda: [])() or []):
            out[f"{p.name()}[{i}]"] = opt
    for o in alg.outputDefinitions():
        out[f"output {o.name()}"] = o.description()
    return out


def _english_words(text: str) -> bool:
    """True when ``text`` holds a run of two or more Latin words or one long one."""
    plain = re.sub(r"\(.*?\)|\*\.\w+|[A-Z_]{2,}|\b\w+\.\w+\b", " ", text)
    return bool(re.search(r"[A-Za-z]{3,}[ -][A-Za-z]{2,}|[a-z]{6,}", plain))


@pytest.mark.parametrize("lang", ["ar", "fa"])
def test_every_label_option_and_output_is_translated(qgis_app, lang):
    from qgis.PyQt.QtCore import QCoreApplication, QTranslator

    from geomatics_toolbox.algorithms import all_algorithms
    qm = ROOT / "i18n" / f"geomatics_toolbox_{lang}.qm"
    if not qm.exists():
        pytest.skip("run `make qm` first")
    english = {}
    for alg in all_algorithms():
        alg.initAlgorithm()
        english[alg.name()] = _visible(alg)
    translator = QTranslator()
    assert translator.load(str(qm))
    QCoreApplication.installTranslator(translator)
    try:
        left = []
        for alg in all_algorithms():
            alg.initAlgorithm()
            for where, text in _visible(alg).items():
                en = english[alg.name()].get(where)
                if (alg.name(), where.split("[")[0]) in PRODUCT_OPTIONS and "[" in where:
                    continue
                if text == en and text not in SAME_EVERYWHERE and _english_words(text):
                    left.append(f"{alg.name()} {where}: {text!r}")
    finally:
        QCoreApplication.removeTranslator(translator)
    assert not left, f"{len(left)} untranslated ({lang}):\n" + "\n".join(left)

"""Help panels and report outputs follow the toolbox conventions (issue 11 item 5).

* the help leads with a summary and a ``qgis_process`` example of the algorithm itself;
* parameter ids (ALL-CAPS) appear only in ``<code>``/``<pre>`` spans (the example line
  and the one id per parameter line), never in running sentences;
* every report destination is named after its algorithm ("IDW DTM report"), not "Report".
"""
import re

import pytest

#: algorithms whose help is not converted yet, with the reason (the list only shrinks:
#: a pending algorithm that passes fails the test until it is removed from here)
PENDING: dict = {}

_CODE = re.compile(r"<(code|pre)\b[^>]*>.*?</\1>", re.S)
_CAPS = re.compile(r"\b[A-Z][A-Z0-9_]+\b")


def ids_in_prose(help_html: str, ids, words=()) -> list:
    """Parameter/output ids written in running text (outside ``<code>``/``<pre>``).

    ``words``: tokens of the human labels — an id that is also a word of a label
    (``CRS``, ``DTM``, ``RMSE``) is an abbreviation, not an id.
    """
    prose = _CODE.sub(" ", help_html)
    return [w for w in _CAPS.findall(prose) if w in set(ids) and w not in set(words)]


def _algorithms():
    from geomatics_toolbox.algorithms import all_algorithms
    out = []
    for alg in all_algorithms():
        alg.initAlgorithm()
        out.append(alg)
    return out


def _violations(alg) -> list:
    defs = list(alg.parameterDefinitions()) + list(alg.outputDefinitions())
    words = re.findall(r"[A-Za-z0-9_]+", " ".join(d.description() for d in defs))
    return ids_in_prose(alg.shortHelpString(), [d.name() for d in defs], words)


def test_checker_finds_ids_in_prose_only():
    text = ('<p>Set CELL_SIZE to 1 in the CRS of the DTM.</p><pre>qgis_process run x -- '
            'INPUT=a.laz</pre><li><b>Cell size</b> <code>CELL_SIZE</code></li>')
    ids = ["CELL_SIZE", "INPUT", "CRS", "DTM"]
    assert ids_in_prose(text, ids, words=["CRS", "DTM"]) == ["CELL_SIZE"]
    assert ids_in_prose(text, ids) == ["CELL_SIZE", "CRS", "DTM"]


def _has_example(alg) -> bool:
    help_html = alg.shortHelpString()
    return help_html.startswith("<p>") and \
        f"qgis_process run geomatics:{alg.name()} -- " in help_html


def test_help_has_no_ids_in_prose_and_leads_with_an_example(qgis_app):
    bad, example_missing, done = {}, [], []
    for alg in _algorithms():
        hits = _violations(alg)
        if alg.name() in PENDING:
            assert hits or not _has_example(alg), (
                f"{alg.name()} passes now: remove it from PENDING ({PENDING[alg.name()]})")
            continue
        if hits:
            bad[alg.name()] = sorted(set(hits))
        if not _has_example(alg):
            example_missing.append(alg.name())
        done.append(alg.name())
    assert not bad, f"ALL-CAPS ids in help prose: {bad}"
    assert not example_missing, f"no leading summary + qgis_process example: {example_missing}"
    assert len(done) >= 5


def test_every_parameter_is_listed_once_by_label(qgis_app):
    from qgis.core import QgsProcessingParameterDefinition
    for alg in _algorithms():
        if alg.name() in PENDING:
            continue
        help_html = alg.shortHelpString().split("Also returned")[0]   # outputs may reuse ids
        for p in alg.parameterDefinitions():
            if p.flags() & QgsProcessingParameterDefinition.FlagHidden:
                continue
            code = f'<code dir="ltr">{p.name()}</code>'
            assert help_html.count(code) == 1, (alg.name(), p.name())


def test_report_outputs_are_named_after_their_algorithm(qgis_app):
    from qgis.core import QgsProcessingParameterFileDestination
    unnamed = []
    for alg in _algorithms():
        for p in alg.destinationParameterDefinitions():
            if not isinstance(p, QgsProcessingParameterFileDestination):
                continue
            filt = p.fileFilter().lower()
            if "html" not in filt and ("json" not in filt or "cityjson" in filt):
                continue   # CityJSON is a data format (3D city model), not a report
            label = p.description()
            if alg.name() in PENDING:
                continue
            if label.strip().lower() in ("report", "report as json") \
                    or "report" not in label.lower():
                unnamed.append(f"{alg.name()}:{p.name()}={label!r}")
    assert not unnamed, unnamed


@pytest.mark.parametrize("lang", ["ar", "fa"])
def test_help_is_translated(qgis_app, lang):
    """The converted help, summary and notes included, reads in ar/fa (no English
    sentence of the help source left)."""
    from pathlib import Path

    from qgis.PyQt.QtCore import QCoreApplication, QTranslator
    root = Path(__file__).resolve().parents[2]
    qm = root / "i18n" / f"geomatics_toolbox_{lang}.qm"
    if not qm.exists():
        pytest.skip("run `make qm` first")
    translator = QTranslator()
    assert translator.load(str(qm))
    QCoreApplication.installTranslator(translator)
    try:
        for alg in _algorithms():
            if alg.name() in PENDING:
                continue
            # titles of cited works (<cite>) stay in their language
            prose = re.sub(r"<cite>.*?</cite>", " ", _CODE.sub(" ", alg.shortHelpString()))
            prose = re.sub(r"<[^>]+>", " ", prose)
            english = re.findall(r"\b[a-z]{4,}(?: [a-z]{3,}){3,}", prose)
            assert not english, (lang, alg.name(), english[:3])
    finally:
        QCoreApplication.removeTranslator(translator)

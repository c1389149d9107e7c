"""Toolbox conventions: tooltips (shortDescription) and shipped help pages (helpUrl)."""
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


def _algorithms(qgis_app):
    from qgis.core import QgsApplication
    provider = QgsApplication.processingRegistry().providerById("geomatics")
    return [a for a in provider.algorithms() if a.name() != "lidar_to_dtm"]


def test_every_algorithm_has_a_one_line_tooltip(qgis_app):
    for alg in _algorithms(qgis_app):
        text = alg.shortDescription()
        assert text and "\n" not in text and "<" not in text, alg.id()
        assert 10 < len(text) < 300, (alg.id(), text)


def test_help_pages_are_shipped_and_linked(qgis_app):
    from qgis.PyQt.QtCore import QUrl
    linked = 0
    for alg in _algorithms(qgis_app):
        url = alg.helpUrl()
        if not url:     # an algorithm added after the last `make help-pages`
            continue
        path = Path(QUrl(url).toLocalFile())
        assert url.startswith("file://") and path.is_file(), (alg.id(), url)
        assert path.parent.resolve() in {(ROOT / "help").resolve(),
                                         *(p.resolve() for p in (ROOT / "help").iterdir())}
        assert alg.displayName() in path.read_text(encoding="utf-8")
        linked += 1
    assert linked >= 12
    assert (ROOT / "help" / "ar" / "gsdcalculator.html").is_file()
    assert 'dir="rtl"' in (ROOT / "help" / "fa" / "gsdcalculator.html").read_text(
        encoding="utf-8")


def test_first_sentence():
    from geomatics_toolbox.algorithms.base import first_sentence
    assert first_sentence("<p>Computes the <b>GSD</b>. Then more.</p>") == \
        "Computes the GSD."
    assert first_sentence("<p>يحسب المسافة؟ ثم</p>") == "يحسب المسافة؟"

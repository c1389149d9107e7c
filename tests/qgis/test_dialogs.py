"""Dialog defects of issue 19 ("Dialogs, reports, translations"), each as QGIS's own
widgets show it: decimals of number boxes, option labels, the class chooser, help panels
right to left, toolbox names that stay distinct when elided."""
from __future__ import annotations

import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
#: double parameters in map units (may be degrees): QGIS's six decimals kept
MAP_UNIT_PARAMS = {"GR", "RESOLUTION", "REFINE_TOLERANCE"}


@pytest.fixture(scope="module")
def gui(qgis_app):
    from qgis.gui import QgsGui
    return QgsGui.processingGuiRegistry()


def _algorithms():
    from geomatics_toolbox.algorithms import all_algorithms
    out = []
    for alg in all_algorithms():
        alg.initAlgorithm()
        out.append(alg)
    return out


def _widget(gui, param):
    from qgis.core import QgsProcessingContext
    from qgis.gui import QgsProcessingGui
    wrapper = gui.createParameterWidgetWrapper(param, QgsProcessingGui.Standard)
    widget = wrapper.createWrappedWidget(QgsProcessingContext())
    return wrapper, widget


def test_number_boxes_show_sensible_decimals(gui):
    """Doubles were shown as "50.000000"."""
    from qgis.core import QgsProcessingParameterNumber
    from qgis.gui import QgsDoubleSpinBox

    from geomatics_toolbox.algorithms.base import default_decimals
    seen, bad = 0, []
    for alg in _algorithms():
        for p in alg.parameterDefinitions():
            if not (isinstance(p, QgsProcessingParameterNumber)
                    and p.dataType() == QgsProcessingParameterNumber.Double):
                continue
            wrapper, widget = _widget(gui, p)
            spins = [widget] if isinstance(widget, QgsDoubleSpinBox) else \
                widget.findChildren(QgsDoubleSpinBox)
            assert spins, (alg.name(), p.name())
            decimals = spins[0].decimals()
            if p.name() in MAP_UNIT_PARAMS:
                continue
            seen += 1
            if decimals > max(3, default_decimals(p.defaultValue())):
                bad.append(f"{alg.name()} {p.name()}: {decimals} decimals "
                           f"({spins[0].text()!r})")
            if p.defaultValue() is not None:
                text = spins[0].text()
                if re.search(r"\.\d*0000$", text):
                    bad.append(f"{alg.name()} {p.name()}: {text!r}")
    assert seen > 60
    assert not bad, "\n".join(bad)


def test_cell_size_shows_two_decimals_and_keeps_centimetres(gui):
    from qgis.gui import QgsDoubleSpinBox

    from geomatics_toolbox.algorithms.terrain import IdwDtmAlgorithm
    alg = IdwDtmAlgorithm()
    alg.initAlgorithm()
    _, widget = _widget(gui, alg.parameterDefinition("CELL_SIZE"))
    spin = widget if isinstance(widget, QgsDoubleSpinBox) else \
        widget.findChildren(QgsDoubleSpinBox)[0]
    assert spin.text() == "1.00"
    spin.setValue(0.25)
    assert spin.value() == pytest.approx(0.25)


def test_option_labels_do_not_repeat_themselves():
    """"Spherical (spherical)"."""
    bad = []
    for alg in _algorithms():
        for p in alg.parameterDefinitions():
            for opt in getattr(p, "options", lambda: [])() or []:
                m = re.fullmatch(r"(.+?) \((.+)\)", opt)
                if m and m.group(1).strip().lower() == m.group(2).strip().lower():
                    bad.append(f"{alg.name()} {p.name()}: {opt!r}")
    assert not bad, "\n".join(bad)


def test_class_picker_is_check_boxes(gui):
    """The multi-select chooser only said "1 options selected"."""
    from qgis.core import QgsProcessingParameterEnum
    from qgis.PyQt.QtWidgets import QCheckBox, QLineEdit
    n = 0
    for alg in _algorithms():
        for p in alg.parameterDefinitions():
            if isinstance(p, QgsProcessingParameterEnum) and p.allowMultiple():
                _, widget = _widget(gui, p)
                boxes = widget.findChildren(QCheckBox)
                assert len(boxes) == len(p.options()), (alg.name(), p.name())
                assert not [e for e in widget.findChildren(QLineEdit)
                            if "selected" in e.text()]
                checked = [b.text() for b in boxes if b.isChecked()]
                assert [o for i, o in enumerate(p.options())
                        if i in (p.defaultValue() or [])] == checked
                n += 1
    assert n >= 3      # CLASSES of idw, kriging, dsm, tin; EXCLUDE_CLASSES of dsm


@pytest.mark.parametrize("lang", ["ar", "fa"])
def test_help_panel_right_to_left(qgis_app, monkeypatch, lang):
    """The dialog's help panel had no dir="rtl": bullets left, fragments scrambled."""
    from qgis.PyQt.QtCore import Qt
    from qgis.PyQt.QtGui import QTextDocument

    from geomatics_toolbox.algorithms import helptext
    from geomatics_toolbox.algorithms.terrain import IdwDtmAlgorithm
    monkeypatch.setattr(helptext, "user_locale", lambda: lang)
    alg = IdwDtmAlgorithm()
    doc = QTextDocument()
    doc.setHtml(alg.shortHelpString())
    block, rtl, ltr = doc.begin(), 0, []
    while block.isValid():
        if block.text().strip():
            direction = block.blockFormat().layoutDirection()
            if direction == Qt.RightToLeft:
                rtl += 1
            else:
                ltr.append(block.text())
        block = block.next()
    assert rtl > 10
    # only the qgis_process example line stays left to right
    assert len(ltr) == 1 and ltr[0].startswith("qgis_process run geomatics:idwdtm")
    monkeypatch.setattr(helptext, "user_locale", lambda: "en")
    assert 'dir="rtl"' not in alg.shortHelpString()


@pytest.mark.parametrize("lang", ["en", "ar", "fa"])
def test_toolbox_names_distinct_when_elided(qgis_app, lang):
    """IDW and kriging showed the same elided Arabic name in the toolbox: the first 24
    characters of every name differ within its group."""
    from qgis.PyQt.QtCore import QCoreApplication, QTranslator
    translator = QTranslator()
    if lang != "en":
        qm = ROOT / "i18n" / f"geomatics_toolbox_{lang}.qm"
        if not qm.exists():
            pytest.skip("run `make qm` first")
        assert translator.load(str(qm))
        QCoreApplication.installTranslator(translator)
    try:
        heads = {}
        for alg in _algorithms():
            name = alg.displayName()
            heads.setdefault((alg.group(), name[:24]), []).append(alg.name())
    finally:
        QCoreApplication.removeTranslator(translator)
    same = {k: v for k, v in heads.items() if len(v) > 1}
    assert not same, same

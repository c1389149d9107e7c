"""Plugin life cycle and Arabic/Persian translations."""
import shutil
import subprocess
import xml.etree.ElementTree as ET
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]
EXPECTED = {
    "ar": {"provider": "صندوق أدوات الجيوماتكس", "group": "المساحة التصويرية",
           "gsd": "حاسبة دقة المسافة الأرضية للبكسل (GSD) والدقة التصويرية",
           "distance": "المسافة بين الكاميرا والجسم / ارتفاع الطيران (م)"},
    "fa": {"provider": "جعبه‌ابزار ژئوماتیک", "group": "فتوگرامتری",
           "gsd": "محاسبه‌گر GSD (فاصلهٔ نمونه‌برداری زمینی) و دقت فتوگرامتری",
           "distance": "فاصلهٔ دوربین تا شیء / ارتفاع پرواز (متر)"},
}


def test_plugin_life_cycle(qgis_app):
    from qgis.core import QgsApplication

    import geomatics_toolbox
    registry = QgsApplication.processingRegistry()
    plugin = geomatics_toolbox.classFactory(None)
    # the session fixture registered one provider already: drop it for this test
    existing = registry.providerById("geomatics")
    registry.removeProvider(existing)
    try:
        plugin.initProcessing()
        provider = registry.providerById("geomatics")
        assert provider is not None
        assert {"geomatics:gsdcalculator", "geomatics:gsdbatch"} <= {
            a.id() for a in provider.algorithms()}
        plugin.unload()
        assert registry.providerById("geomatics") is None
    finally:
        from geomatics_toolbox.provider.provider import GeomaticsProvider
        if registry.providerById("geomatics") is None:
            qgis_app._geomatics_provider = GeomaticsProvider()
            registry.addProvider(qgis_app._geomatics_provider)


def _qm(lang: str, tmp_path: Path) -> Path:
    """The compiled .qm (from `make qm`), or one compiled now from the .ts."""
    qm = ROOT / "i18n" / f"geomatics_toolbox_{lang}.qm"
    if qm.exists() and qm.stat().st_mtime >= (qm.with_suffix(".ts")).stat().st_mtime:
        return qm
    if shutil.which("lrelease") is None:
        pytest.skip("lrelease not installed (Debian package qttools5-dev-tools)")
    out = tmp_path / qm.name
    subprocess.run(["lrelease", "-silent", str(qm.with_suffix(".ts")), "-qm", str(out)],
                   check=True)
    return out


@pytest.mark.parametrize("lang", ["ar", "fa"])
def test_translations_load_and_translate(qgis_app, lang, tmp_path):
    from qgis.PyQt.QtCore import QCoreApplication, QTranslator

    from geomatics_toolbox.algorithms.gsd_calculator import GsdCalculatorAlgorithm
    from geomatics_toolbox.provider.provider import GeomaticsProvider
    translator = QTranslator()
    assert translator.load(str(_qm(lang, tmp_path)))
    QCoreApplication.installTranslator(translator)
    try:
        exp = EXPECTED[lang]
        assert GeomaticsProvider().name() == exp["provider"]
        alg = GsdCalculatorAlgorithm()
        alg.initAlgorithm()
        assert alg.displayName() == exp["gsd"]
        assert alg.group() == exp["group"]
        assert alg.parameterDefinition("DISTANCE").description() == exp["distance"]
        help_text = alg.shortHelpString()
        assert "Computes the ground" not in help_text and "Nikon Coolpix P100" in help_text
    finally:
        QCoreApplication.removeTranslator(translator)
    assert GeomaticsProvider().name() == "Geomatics Toolbox"


@pytest.mark.parametrize("lang", ["ar", "fa"])
def test_plugin_installs_translator_for_user_locale(qgis_app, lang):
    from qgis.core import QgsSettings
    from qgis.PyQt.QtCore import QCoreApplication

    from geomatics_toolbox import plugin as plugin_mod
    from geomatics_toolbox.provider.provider import GeomaticsProvider
    if not (ROOT / "i18n" / f"geomatics_toolbox_{lang}.qm").exists():
        pytest.skip("run `make qm` first to build the shipped .qm files")
    settings = QgsSettings()
    old_flag = settings.value("locale/overrideFlag", False, type=bool)
    old_locale = settings.value("locale/userLocale", "")
    settings.setValue("locale/overrideFlag", True)
    settings.setValue("locale/userLocale", lang)
    try:
        assert plugin_mod.user_locale() == lang
        p = plugin_mod.GeomaticsToolboxPlugin(None)
        assert p.translator is not None
        assert GeomaticsProvider().name() == EXPECTED[lang]["provider"]
        QCoreApplication.removeTranslator(p.translator)
    finally:
        settings.setValue("locale/overrideFlag", old_flag)
        settings.setValue("locale/userLocale", old_locale)


def test_every_algorithm_name_and_group_is_translated(qgis_app):
    """Provider, group and algorithm display names exist in both .ts files, translated."""
    from geomatics_toolbox.algorithms import all_algorithms
    from geomatics_toolbox.algorithms.base import _groups
    needed = {"Geomatics Toolbox", *(_groups().values())}
    for alg in all_algorithms():
        needed.add(alg.displayName())
    for lang in ("ar", "fa"):
        ts = ET.parse(ROOT / "i18n" / f"geomatics_toolbox_{lang}.ts")
        done = {m.findtext("source"): m.find("translation")
                for m in ts.iter("message")}
        for text in needed:
            assert text in done, f"{lang}: '{text}' missing from the .ts (run make ts)"
            tr = done[text]
            assert tr.get("type") != "unfinished" and (tr.text or "").strip(), \
                f"{lang}: '{text}' is not translated"


def _arabic_script(text: str) -> bool:
    return any("\u0600" <= ch <= "\u06ff" for ch in text)


@pytest.mark.parametrize("lang", ["ar", "fa"])
def test_every_label_and_help_is_translated_at_run_time(qgis_app, lang, tmp_path):
    """What an Arabic/Persian user sees: names, parameter labels and help, all translated
    (catches strings pylupdate5 cannot see, e.g. through '+' or a wrong context)."""
    from qgis.PyQt.QtCore import QCoreApplication, QTranslator

    from geomatics_toolbox.algorithms import all_algorithms
    translator = QTranslator()
    assert translator.load(str(_qm(lang, tmp_path)))
    QCoreApplication.installTranslator(translator)
    try:
        missing = []
        for alg in all_algorithms():
            alg.initAlgorithm()
            texts = {"name": alg.displayName(), "help": alg.shortHelpString()}
            texts.update({p.name(): p.description() for p in alg.parameterDefinitions()})
            missing += [f"{alg.name()}:{k}: {v[:60]}" for k, v in texts.items()
                        if not _arabic_script(v)]
        assert not missing, "untranslated:\n" + "\n".join(missing)
    finally:
        QCoreApplication.removeTranslator(translator)


@pytest.mark.parametrize("lang,expected", [("ar", "الفئات [اختياري]"),
                                           ("fa", "الفئات [اختیاری]")])
def test_broken_qgis_optional_label_is_overridden(qgis_app, lang, expected, tmp_path):
    """Debian QGIS 3.22's Arabic '%1 [optional]' reads '1% [اختياري]' (the label is lost);
    the plugin's translator, installed after QGIS's, restores the label."""
    from qgis.PyQt.QtCore import QCoreApplication, QTranslator
    qgis_own = QTranslator()
    qgis_qm = Path("/usr/share/qgis/i18n") / f"qgis_{lang}.qm"
    if qgis_qm.exists():
        assert qgis_own.load(str(qgis_qm))
        QCoreApplication.installTranslator(qgis_own)
    ours = QTranslator()
    assert ours.load(str(_qm(lang, tmp_path)))
    QCoreApplication.installTranslator(ours)
    try:
        assert QCoreApplication.translate("QObject", "%1 [optional]").replace(
            "%1", "الفئات") == expected
    finally:
        QCoreApplication.removeTranslator(ours)
        QCoreApplication.removeTranslator(qgis_own)

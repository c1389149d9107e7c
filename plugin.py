"""Plugin class: registers the Processing provider and the translations."""
from __future__ import annotations

import os

from qgis.core import QgsApplication
from qgis.PyQt.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, QTranslator

from .algorithms.locale import user_locale

PLUGIN_DIR = os.path.dirname(__file__)


#: Messages of QGIS itself that this plugin's translator overrides because the
#: translation shipped with QGIS 3.22 is broken: Debian's Arabic has "1% [اختياري]"
#: (the placeholder reversed), so every optional parameter of every dialog lost its label.
#: Our translator is installed after QGIS's, so Qt consults it first.
QGIS_OVERRIDES = (QT_TRANSLATE_NOOP("QObject", "%1 [optional]"),)


def install_translator(locale: str | None = None) -> QTranslator | None:
    """Load ``i18n/geomatics_toolbox_<locale>.qm`` if it exists; return the translator."""
    locale = locale or user_locale()
    qm = os.path.join(PLUGIN_DIR, "i18n", f"geomatics_toolbox_{locale}.qm")
    if not os.path.exists(qm):
        return None
    translator = QTranslator()
    if not translator.load(qm):
        return None
    QCoreApplication.installTranslator(translator)
    return translator


class GeomaticsToolboxPlugin:
    """QGIS plugin object. Has no GUI of its own: everything is in Processing."""

    def __init__(self, iface=None):
        self.iface = iface
        self.provider = None
        self.translator = install_translator()

    def initProcessing(self):  # noqa: N802 - QGIS API name
        """Create and register the Processing provider (also used by qgis_process)."""
        if self.provider is None:
            from .provider.provider import GeomaticsProvider
            self.provider = GeomaticsProvider()
            QgsApplication.processingRegistry().addProvider(self.provider)

    def initGui(self):  # noqa: N802 - QGIS API name
        self.initProcessing()

    def unload(self):
        if self.provider is not None:
            QgsApplication.processingRegistry().removeProvider(self.provider)
            self.provider = None
        if self.translator is not None:
            QCoreApplication.removeTranslator(self.translator)
            self.translator = None

"""The QGIS user-interface language (for translators and report language)."""
from __future__ import annotations

from qgis.core import QgsSettings
from qgis.PyQt.QtCore import QLocale


def user_locale() -> str:
    """Two-letter language code of the QGIS user interface (e.g. 'ar', 'fa')."""
    settings = QgsSettings()
    if settings.value("locale/overrideFlag", False, type=bool):
        name = settings.value("locale/userLocale", "") or QLocale().name()
    else:
        name = QLocale().name()
    from ..core.reporting.i18n import normalise_lang
    return normalise_lang(name)

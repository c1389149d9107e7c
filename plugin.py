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


def activate_private_packages() -> str:
    """Put the plugin's private package folder of this profile on ``sys.path``.

    ``geomatics:installdependencies`` installs the runtime packages there
    (``core/deps.py``); returns the folder.
    """
    from .core import deps
    folder = deps.packages_dir(QgsApplication.qgisSettingsDirPath())
    try:
        deps.activate(folder)
    except Exception as exc:  # noqa: BLE001 - the plugin must load to offer the installer
        from qgis.core import Qgis, QgsMessageLog
        QgsMessageLog.logMessage(f"Could not use the package folder {folder}: {exc!r}",
                                 "Geomatics Toolbox", Qgis.Warning)
    return str(folder)


def missing_packages_text(missing) -> str:
    """One translated sentence naming the missing packages and what needs them."""
    base = [r.name for r in missing if r.group == "base"]
    lidar = [r.name for r in missing if r.group == "lidar"]
    catalog = [r.name for r in missing if r.group == "catalog"]
    try:
        rtl = user_locale() in ("ar", "fa")
    except Exception:  # noqa: BLE001 - punctuation only
        rtl = False
    comma, semicolon = ("، ", "؛ ") if rtl else (", ", "; ")
    parts = []
    if base:
        parts.append(QCoreApplication.translate(
            "GeomaticsToolboxPlugin", "{packages} for every algorithm").format(
                packages=comma.join(base)))
    if lidar:
        parts.append(QCoreApplication.translate(
            "GeomaticsToolboxPlugin", "{packages} for the LiDAR algorithms").format(
                packages=comma.join(lidar)))
    if catalog:
        parts.append(QCoreApplication.translate(
            "GeomaticsToolboxPlugin", "{packages} for the tile catalog").format(
                packages=comma.join(catalog)))
    return QCoreApplication.translate(
        "GeomaticsToolboxPlugin", "QGIS's Python lacks Python packages this toolbox "
        "needs: {missing}. The other algorithms work without them.").format(
            missing=semicolon.join(parts)) if not base else QCoreApplication.translate(
        "GeomaticsToolboxPlugin", "QGIS's Python lacks Python packages this toolbox "
        "needs: {missing}. Until they are installed only the installer is offered.").format(
            missing=semicolon.join(parts))


class GeomaticsToolboxPlugin:
    """QGIS plugin object. Has no GUI of its own: everything is in Processing."""

    def __init__(self, iface=None):
        self.iface = iface
        self.provider = None
        self.translator = install_translator()
        self.packages_folder = activate_private_packages()
        self.message = None

    def initProcessing(self):  # noqa: N802 - QGIS API name
        """Create and register the Processing provider (also used by qgis_process)."""
        if self.provider is None:
            from .provider.provider import GeomaticsProvider
            self.provider = GeomaticsProvider()
            QgsApplication.processingRegistry().addProvider(self.provider)

    def initGui(self):  # noqa: N802 - QGIS API name
        self.initProcessing()
        self.show_missing_packages()

    def show_missing_packages(self):
        """A message bar naming the missing runtime packages, with an Install button."""
        from .core import deps
        missing = deps.missing()
        if not missing or self.iface is None:
            return None
        from qgis.core import Qgis
        from qgis.PyQt.QtWidgets import QPushButton
        bar = self.iface.messageBar()
        widget = bar.createMessage(
            QCoreApplication.translate("GeomaticsToolboxPlugin", "Geomatics Toolbox"),
            missing_packages_text(missing))
        button = QPushButton(QCoreApplication.translate("GeomaticsToolboxPlugin",
                                                        "Install them…"), widget)
        button.setObjectName("geomatics_install_button")
        button.clicked.connect(self.open_installer)
        widget.layout().addWidget(button)
        self.message = bar.pushWidget(widget, Qgis.Warning)
        return self.message

    def open_installer(self):
        """Open the dialog of ``geomatics:installdependencies`` (progress, log, command)."""
        from processing import execAlgorithmDialog

        from .core import deps
        execAlgorithmDialog(deps.INSTALLER_ID)
        if not deps.missing() and self.message is not None and self.iface is not None:
            self.iface.messageBar().popWidget(self.message)
            self.message = None

    def unload(self):
        if self.provider is not None:
            QgsApplication.processingRegistry().removeProvider(self.provider)
            self.provider = None
        if self.translator is not None:
            QCoreApplication.removeTranslator(self.translator)
            self.translator = None

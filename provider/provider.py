"""The Geomatics Toolbox Processing provider (id ``geomatics``)."""
from __future__ import annotations

import os

from qgis.core import QgsProcessingProvider
from qgis.PyQt.QtCore import QCoreApplication
from qgis.PyQt.QtGui import QIcon

ICON_PATH = os.path.join(os.path.dirname(__file__), "icons", "geomatics.svg")
MODELS_DIR = os.path.join(os.path.dirname(os.path.dirname(__file__)), "models")


class GeomaticsProvider(QgsProcessingProvider):
    """Registers every algorithm of the plugin under the id ``geomatics``."""

    def id(self) -> str:
        return "geomatics"

    def name(self) -> str:
        return QCoreApplication.translate("GeomaticsProvider", "Geomatics Toolbox")

    def longName(self) -> str:  # noqa: N802 - QGIS API name
        return self.name()

    def icon(self) -> QIcon:
        return QIcon(ICON_PATH)

    def svgIconPath(self) -> str:  # noqa: N802 - QGIS API name
        return ICON_PATH

    def loadAlgorithms(self) -> None:  # noqa: N802 - QGIS API name
        from ..algorithms import all_algorithms
        for alg in all_algorithms():
            self.addAlgorithm(alg)
        self._load_models()

    def _load_models(self) -> None:
        """Offer the shipped Processing models (models/*.model3) as algorithms too."""
        from qgis.core import Qgis, QgsMessageLog, QgsProcessingModelAlgorithm
        if not os.path.isdir(MODELS_DIR):
            return
        for name in sorted(os.listdir(MODELS_DIR)):
            if not name.endswith(".model3"):
                continue
            model = QgsProcessingModelAlgorithm()
            if model.fromFile(os.path.join(MODELS_DIR, name)):
                self.addAlgorithm(model)
            else:
                QgsMessageLog.logMessage(f"Could not load the model {name}",
                                         "Geomatics Toolbox", Qgis.Warning)

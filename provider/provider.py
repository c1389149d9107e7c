"""The Geomatics Toolbox Processing provider (id ``geomatics``)."""
from __future__ import annotations

import os

from qgis.core import QgsProcessingProvider
from qgis.PyQt.QtCore import QCoreApplication
from qgis.PyQt.QtGui import QIcon

ICON_PATH = os.path.join(os.path.dirname(__file__), "icons", "geomatics.svg")


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

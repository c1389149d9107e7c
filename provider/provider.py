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
        """Offer the shipped Processing models (models/*.model3) as algorithms too.

        They keep their stable ids (``geomatics:lidar_to_dtm``) but show a translated
        title and sit in the provider's own translated group.
        """
        from qgis.core import Qgis, QgsMessageLog
        if not os.path.isdir(MODELS_DIR):
            return
        for name in sorted(os.listdir(MODELS_DIR)):
            if not name.endswith(".model3"):
                continue
            model = shipped_model(os.path.join(MODELS_DIR, name))
            if model is not None:
                self.addAlgorithm(model)
            else:
                QgsMessageLog.logMessage(f"Could not load the model {name}",
                                         "Geomatics Toolbox", Qgis.Warning)


#: English group name stored in a .model3 file -> the provider's group id
MODEL_GROUP_IDS = {"LiDAR ground filtering": "lidarfiltering", "Terrain models": "terrain",
                   "Image rectification": "rectification", "Photogrammetry": "photogrammetry",
                   "Accuracy assessment": "accuracy"}


def model_titles() -> dict:
    """Translated titles of the shipped models, by model name (literal for pylupdate5)."""
    return {"lidar_to_dtm": QCoreApplication.translate("GeomaticsProvider",
                                                       "LiDAR to DTM with accuracy")}


def shipped_model(path: str):
    """A shipped model with a translated title and group, or None if it cannot load."""
    from qgis.core import QgsProcessingModelAlgorithm

    from ..algorithms.base import _groups

    class ShippedModel(QgsProcessingModelAlgorithm):
        def displayName(self) -> str:  # noqa: N802 - QGIS API name
            return model_titles().get(self.name(), self.name())

        def groupId(self) -> str:  # noqa: N802 - QGIS API name
            # a .model3 file stores only the English group name
            return MODEL_GROUP_IDS.get(super().group(), super().groupId())

        def group(self) -> str:
            return _groups().get(self.groupId(), super().group())

        def createInstance(self):  # noqa: N802 - QGIS API name
            return shipped_model(path)

        def svgIconPath(self) -> str:  # noqa: N802 - QGIS API name
            own = os.path.join(os.path.dirname(ICON_PATH), f"{self.name()}.svg")
            return own if os.path.isfile(own) else super().svgIconPath()

        def icon(self) -> QIcon:
            return QIcon(self.svgIconPath())

    model = ShippedModel()
    return model if model.fromFile(path) else None

"""The Geomatics Toolbox Processing provider (id ``geomatics``)."""
from __future__ import annotations

import os

from qgis.core import QgsProcessingProvider
from qgis.PyQt.QtCore import QT_TRANSLATE_NOOP, QCoreApplication
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
        try:
            algorithms = all_algorithms()
        except ImportError as exc:
            # a QGIS build without SciPy (some macOS ones): offer the installer alone,
            # which adds it; the plugin's message bar says so
            from ..core import deps
            if (exc.name or "").split(".")[0] not in {r.import_name for r in
                                                      deps.base_requirements()}:
                raise
            from qgis.core import Qgis, QgsMessageLog

            from ..algorithms.install_dependencies import InstallDependenciesAlgorithm
            QgsMessageLog.logMessage(f"{exc}: only {deps.INSTALLER_ID} is available until "
                                     "it is installed.", "Geomatics Toolbox", Qgis.Warning)
            self.addAlgorithm(InstallDependenciesAlgorithm())
            return
        for alg in algorithms:
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


#: labels of the shipped models' inputs and outputs (English, as in the .model3 files)
MODEL_LABELS = (
    QT_TRANSLATE_NOOP("GeomaticsProvider", "Point cloud (LAS/LAZ)"),
    QT_TRANSLATE_NOOP("GeomaticsProvider", "DTM cell size (m)"),
    QT_TRANSLATE_NOOP("GeomaticsProvider", "IDW power"),
    QT_TRANSLATE_NOOP("GeomaticsProvider",
                      "Fill data gaps in the DTM (interpolate far from ground points)"),
    QT_TRANSLATE_NOOP("GeomaticsProvider", "CRS override for a cloud without a CRS record"),
    QT_TRANSLATE_NOOP("GeomaticsProvider", "Check points (point layer)"),
    QT_TRANSLATE_NOOP("GeomaticsProvider", "Check points (CSV/TXT file: id,x,y,z)"),
    QT_TRANSLATE_NOOP("GeomaticsProvider", "Classified point cloud"),
    QT_TRANSLATE_NOOP("GeomaticsProvider", "Ground filter report"),
    QT_TRANSLATE_NOOP("GeomaticsProvider", "DTM"),
    QT_TRANSLATE_NOOP("GeomaticsProvider", "DTM report"),
    QT_TRANSLATE_NOOP("GeomaticsProvider", "Check-point residuals"),
    QT_TRANSLATE_NOOP("GeomaticsProvider", "DTM accuracy report"),
    QT_TRANSLATE_NOOP("GeomaticsProvider", "Project name (shown in the report)"),
    QT_TRANSLATE_NOOP("GeomaticsProvider", "Operator (shown in the report)"),
)


#: description and help of the shipped model lidar_to_dtm (English; translated on use)
LIDAR_TO_DTM_TEXTS = (
    QT_TRANSLATE_NOOP(
        "GeomaticsProvider",
        "The editable model of 'LiDAR to DTM with accuracy': the same steps, defaults "
        "and results; open it in the Model Designer to change a step."),
    QT_TRANSLATE_NOOP(
        "GeomaticsProvider",
        "<p>Ground filter (recommended) → DTM by IDW → DTM accuracy against check "
        "points, as a Processing model you can open and change in the Model Designer. "
        "With its defaults it gives the same classified cloud, DTM and RMSE, bit for "
        "bit, as the one-step algorithm 'LiDAR to DTM with accuracy' and as the three "
        "algorithms run one after another. Its steps write temporary files and a last "
        "step publishes them all or none: when a step fails, nothing is left at any "
        "destination.</p><p><b>Parameters</b>: the point cloud (LAS/LAZ, projected "
        "CRS), the DTM cell size (m, default 1), the IDW power (default 2), fill data "
        "gaps (default no), a CRS for a cloud without one, and the check points (a "
        "point layer or a CSV/TXT file id,x,y,z).</p><p><b>Outputs</b>: classified "
        "point cloud, DTM, DTM accuracy report; optionally the ground filter report, "
        "the DTM report and the check-point residuals.</p>"),
)


def model_texts() -> dict:
    """Translated description and help of the shipped models, by model name."""
    return {"lidar_to_dtm": tuple(
        QCoreApplication.translate("GeomaticsProvider", text)  # i18n: noop-list
        for text in LIDAR_TO_DTM_TEXTS)}


def model_labels() -> dict:
    """Translated labels of the shipped models' inputs and outputs, by English label."""
    return {label: QCoreApplication.translate("GeomaticsProvider", label)  # i18n: noop-list
            for label in MODEL_LABELS}


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

        def shortDescription(self) -> str:  # noqa: N802 - QGIS API name
            return model_texts().get(self.name(), ("", ""))[0] or super().shortDescription()

        def shortHelpString(self) -> str:  # noqa: N802 - QGIS API name
            text = model_texts().get(self.name(), ("", ""))[1]
            if not text:
                return super().shortHelpString()
            from ..algorithms.helptext import _rtl, right_to_left
            return right_to_left(text) if _rtl() else text

        def createInstance(self):  # noqa: N802 - QGIS API name
            return shipped_model(path)

        def svgIconPath(self) -> str:  # noqa: N802 - QGIS API name
            own = os.path.join(os.path.dirname(ICON_PATH), f"{self.name()}.svg")
            return own if os.path.isfile(own) else super().svgIconPath()

        def icon(self) -> QIcon:
            return QIcon(self.svgIconPath())

    model = ShippedModel()
    if not model.fromFile(path):
        return None
    labels = model_labels()       # the labels the user reads, in the interface language
    for d in model.parameterDefinitions():
        label = d.description()
        if label in labels:
            d.setDescription(labels[label])
    return model

"""Install the Python packages this toolbox needs, privately, with QGIS's own Python."""
from __future__ import annotations

from qgis.core import (
    QgsApplication,
    QgsProcessingAlgorithm,
    QgsProcessingOutputFolder,
    QgsProcessingOutputString,
    QgsProcessingParameterFile,
)

from ..core import deps
from ..core.system import python_executable
from .base import GeomaticsAlgorithm
from .helptext import build_help


def profile_packages_dir() -> str:
    """The plugin's private package folder under the current QGIS profile."""
    return str(deps.packages_dir(QgsApplication.qgisSettingsDirPath()))


class InstallDependenciesAlgorithm(GeomaticsAlgorithm):
    """``python -m pip`` the pinned runtime packages into a folder of the profile."""

    GROUP = "setup"
    WHEEL_FOLDER = "WHEEL_FOLDER"

    def name(self) -> str:
        return "installdependencies"

    def displayName(self) -> str:  # noqa: N802
        return self.tr("Install the Python packages this toolbox needs")

    def shortDescription(self) -> str:  # noqa: N802
        return self.tr("Installs laspy, lazrs, dask and distributed for QGIS's Python into "
                       "a folder of this QGIS profile.")

    def tags(self):
        return self.tr("install,pip,dependencies,packages,laspy,lazrs,dask,offline,wheels,"
                       "setup").split(",")

    def flags(self):
        return super().flags() | QgsProcessingAlgorithm.FlagHideFromModeler

    def shortHelpString(self) -> str:  # noqa: N802
        return build_help(self, self.tr(
            "The LiDAR algorithms need laspy and lazrs, the tile catalog also dask and "
            "distributed; QGIS ships the rest (numpy, SciPy, GDAL), and where a QGIS build "
            "lacks SciPy it is installed too, for QGIS's own numpy. This installs the "
            "versions the toolbox was tested with, only those QGIS's Python lacks, with "
            "that Python's pip into a folder of the current QGIS profile: QGIS's own "
            "packages are never changed or replaced, and removing the folder undoes it. "
            "The log shows every command and everything pip prints."),
            "WHEEL_FOLDER=",
            {self.WHEEL_FOLDER: self.tr(
                "For computers without internet: a folder of wheel files (.whl) downloaded "
                "elsewhere with pip download for the same Python version and system. Empty: "
                "the package index pip is configured with.")})

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add(QgsProcessingParameterFile(
            self.WHEEL_FOLDER, self.tr("Folder of wheels (offline installation)"),
            behavior=QgsProcessingParameterFile.Folder, optional=True))
        self.addOutput(QgsProcessingOutputFolder(
            "FOLDER", self.tr("Folder the packages are installed in")))
        self.addOutput(QgsProcessingOutputString("INSTALLED", self.tr("Packages installed")))
        self.addOutput(QgsProcessingOutputString("MISSING", self.tr("Packages still missing")))
        self.addOutput(QgsProcessingOutputString("COMMAND", self.tr("pip commands run")))

    def process(self, parameters, context, feedback):
        wheels = self.parameterAsFile(parameters, self.WHEEL_FOLDER, context) or None
        folder = profile_packages_dir()
        python = python_executable()
        feedback.pushInfo(self.tr("Python: {python}").format(python=python or "?"))
        feedback.pushInfo(self.tr("Folder: {folder}").format(folder=folder))
        result = deps.install(folder, wheel_dir=wheels, python=python,
                              log=feedback.pushCommandInfo, **self.core_callbacks(feedback))
        missing = [r.name for r in deps.missing()]
        if result.planned:
            feedback.pushInfo(self.tr("Installed: {packages}").format(
                packages=", ".join(result.planned)))
        else:
            feedback.pushInfo(self.tr("Nothing to install: QGIS's Python already has every "
                                      "package."))
        return {"FOLDER": result.folder, "INSTALLED": ", ".join(result.planned),
                "MISSING": ", ".join(missing),
                "COMMAND": "\n".join(deps.format_command(c) for c in result.commands)}

"""Publish outputs: the all-or-nothing last step of the shipped model.

Thin wrapper over :func:`geomatics_toolbox.core.io.publish.publish_files`.
"""
from __future__ import annotations

from qgis.core import (
    QgsProcessing,
    QgsProcessingParameterFile,
    QgsProcessingParameterFileDestination,
    QgsProcessingParameterRasterDestination,
    QgsProcessingParameterVectorDestination,
    QgsProcessingParameterVectorLayer,
)

from ..core.io.publish import publish_files
from .base import LAS_OUT_FILTER, GeomaticsAlgorithm
from .helptext import build_help


class PublishOutputsAlgorithm(GeomaticsAlgorithm):
    """Copy the temporaries of a chain to their destinations through one contract."""

    GROUP = "terrain"
    # (temporary input, destination, kind) of each published file
    FILES = (("CLOUD", "OUTPUT", "cloud"), ("FILTER_HTML", "OUTPUT_FILTER_HTML", "file"),
             ("DTM", "OUTPUT_DTM", "raster"), ("DTM_HTML", "OUTPUT_DTM_HTML", "file"),
             ("RESIDUALS", "OUTPUT_RESIDUALS", "vector"), ("HTML", "OUTPUT_HTML", "file"))
    SOURCES = ("INPUT_CLOUD", "INPUT_CHECKPOINTS_CSV")
    INPUT_CHECKPOINTS = "INPUT_CHECKPOINTS"
    OUTPUT_STYLES = {"OUTPUT_DTM": "elevation", "OUTPUT_RESIDUALS": "residuals"}

    def name(self):
        return "publishoutputs"

    def displayName(self):  # noqa: N802
        return self.tr("Publish chain outputs")

    def flags(self):
        return super().flags() | self.FlagHideFromToolbox

    def shortHelpString(self):  # noqa: N802
        return build_help(self, self.tr(
            "Copies the files written by the earlier steps of a model to their "
            "destinations, all of them or none: it is the last step of the model 'LiDAR "
            "to DTM with accuracy', so a destination that cannot be written leaves no "
            "classified cloud, DTM or report anywhere. Every destination is checked "
            "against the model's inputs, the files to publish and the other destinations "
            "first; one in another format than its file (.las for a .laz cloud) is "
            "converted."),
            "CLOUD=/tmp/ground.laz DTM=/tmp/dtm.tif OUTPUT=classified.laz OUTPUT_DTM=dtm.tif",
            {**{dest: self.tr("Unset: this file is not published.")
                for _, dest, _ in self.FILES},
             **{src: self.tr("Never overwritten: checked against every destination.")
                for src in self.SOURCES + (self.INPUT_CHECKPOINTS,)}})

    def initAlgorithm(self, config=None):  # noqa: N802
        labels = {"CLOUD": self.tr("Classified point cloud to publish"),
                  "FILTER_HTML": self.tr("Ground filter report to publish"),
                  "DTM": self.tr("DTM to publish"),
                  "DTM_HTML": self.tr("DTM report to publish"),
                  "RESIDUALS": self.tr("Check-point residuals to publish"),
                  "HTML": self.tr("DTM accuracy report to publish"),
                  "INPUT_CLOUD": self.tr("Point cloud of the chain (never overwritten)"),
                  "INPUT_CHECKPOINTS_CSV": self.tr(
                      "Check point file of the chain (never overwritten)")}
        for name in [f[0] for f in self.FILES] + list(self.SOURCES):
            self.add(QgsProcessingParameterFile(
                name, labels[name], behavior=QgsProcessingParameterFile.File,
                optional=True))
        self.add(QgsProcessingParameterVectorLayer(
            self.INPUT_CHECKPOINTS, self.tr("Check point layer of the chain (never "
                                            "overwritten)"),
            [QgsProcessing.TypeVectorPoint], optional=True))
        self.add(QgsProcessingParameterFileDestination(
            "OUTPUT", self.tr("Classified point cloud"), LAS_OUT_FILTER, optional=True))
        self.add_report_output("OUTPUT_FILTER_HTML", self.tr("Ground filter report"))
        self.add(QgsProcessingParameterRasterDestination(
            "OUTPUT_DTM", self.tr("DTM"), optional=True))
        self.add_report_output("OUTPUT_DTM_HTML", self.tr("DTM report"))
        self.add(QgsProcessingParameterVectorDestination(
            "OUTPUT_RESIDUALS", self.tr("Check-point residuals"),
            QgsProcessing.TypeVectorPoint, optional=True, createByDefault=True))
        self.add_report_output("OUTPUT_HTML", self.tr("DTM accuracy report"),
                               create_by_default=True)

    def _destination(self, parameters, context, name):
        return self.output_path(parameters, context, name) or None

    def _inputs(self, parameters, context) -> dict:
        inputs = {n: self.parameterAsFile(parameters, n, context) for n in self.SOURCES}
        layer = self.parameterAsVectorLayer(parameters, self.INPUT_CHECKPOINTS, context)
        if layer is not None:
            inputs[self.INPUT_CHECKPOINTS] = layer.source().split("|", 1)[0]
        return inputs

    def process(self, parameters, context, feedback):
        files = {}
        for src_name, dst_name, kind in self.FILES:
            src = (self.parameterAsFile(parameters, src_name, context) or "").split("|")[0]
            dst = self._destination(parameters, context, dst_name)
            if src and dst:
                files[dst_name] = (src, dst, kind)
        results = publish_files(files, inputs=self._inputs(parameters, context),
                                cancel=feedback.isCanceled if feedback else None)
        for path in results.values():
            if feedback:
                feedback.pushInfo(self.tr("Published {path}").format(path=path))
        if "OUTPUT" in results:
            self.load_cloud_on_completion(context, results["OUTPUT"],
                                          self.tr("Classified point cloud"), "OUTPUT")
        return {name: results.get(name) for _s, name, _k in self.FILES}

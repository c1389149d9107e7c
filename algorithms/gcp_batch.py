"""Batch GCP rectification of a folder of images with their .points files.

Thin wrapper over :mod:`..core.rectification.batch`.
"""
from __future__ import annotations

import os

from qgis.core import (
    QgsProcessingOutputNumber,
    QgsProcessingParameterEnum,
    QgsProcessingParameterFile,
    QgsProcessingParameterFileDestination,
    QgsProcessingParameterFolderDestination,
)

from ..core.errors import InputError
from ..core.rectification import assess, batch, warp
from .base import GeomaticsAlgorithm
from .gcp_rectification import TRANSFORMATIONS, TransformationParams, resampling_options
from .helptext import build_help


class RectifyBatchAlgorithm(TransformationParams, GeomaticsAlgorithm):
    """Rectify every image of a folder that has a Georeferencer .points file."""

    GROUP = "rectification"
    INPUT_FOLDER = "INPUT_FOLDER"
    RESAMPLING = "RESAMPLING"
    OUTPUT_FOLDER = "OUTPUT_FOLDER"
    OUTPUT_CSV = "OUTPUT_CSV"
    OUTPUT_HTML = "OUTPUT_HTML"

    def name(self):
        return "rectifybatch"

    def displayName(self):  # noqa: N802
        return self.tr("Rectify a folder of images with GCPs (batch)")

    def shortDescription(self):  # noqa: N802
        return self.tr("Warps every image of a folder with its .points file and "
                       "summarises the accuracy in one table.")

    def tags(self):
        return self.tr("georeference,gcp,batch,folder,rectification,warp,rms").split(",")

    def shortHelpString(self):  # noqa: N802
        return build_help(self, self.tr(
            "Rectifies every image of a folder that has its QGIS Georeferencer .points "
            "file next to it, with a fixed transformation or the one recommended for each "
            "image. It writes one summary table with the transformation, RMS_T, the check "
            "or leave-one-out error and the verdict of every image."),
            "INPUT_FOLDER=scans TRANSFORMATION=8 OUTPUT_FOLDER=rectified "
            "OUTPUT_CSV=summary.csv OUTPUT_HTML=batch.html",
            {self.INPUT_FOLDER: self.tr("Each image with its .points file next to it "
                                        "(scan.tif + scan.tif.points)."),
             self.TRANSFORMATION: self.tr("The last choice picks the recommended "
                                          "transformation for each image."),
             self.OUTPUT_FOLDER: self.tr("One rectified GeoTIFF per image, each written "
                                         "all or nothing.")})

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add(QgsProcessingParameterFile(
            self.INPUT_FOLDER, self.tr("Folder of images with .points files"),
            QgsProcessingParameterFile.Folder))
        self.add_transformation_params(default=8)
        self.add_gcp_crs_param()
        self.add(QgsProcessingParameterEnum(self.RESAMPLING, self.tr("Resampling"),
                                            resampling_options(self.tr), defaultValue=0))
        self.add(QgsProcessingParameterFolderDestination(
            self.OUTPUT_FOLDER, self.tr("Folder of rectified images")))
        self.add(QgsProcessingParameterFileDestination(
            self.OUTPUT_CSV, self.tr("Summary table"), self.tr("CSV files (*.csv)"),
            optional=True, createByDefault=True))
        self.add_report_output(self.OUTPUT_HTML, self.tr("Batch rectification report"),
                               create_by_default=True)
        self.add_report_language()
        self.addOutput(QgsProcessingOutputNumber("N_IMAGES", self.tr("Images found")))
        self.addOutput(QgsProcessingOutputNumber("N_RECTIFIED", self.tr("Images rectified")))

    def process(self, parameters, context, feedback):
        folder = self.parameterAsFile(parameters, self.INPUT_FOLDER, context)
        out_folder = self.parameterAsString(parameters, self.OUTPUT_FOLDER, context)
        kind = TRANSFORMATIONS[self.parameterAsEnum(parameters, self.TRANSFORMATION,
                                                    context)]
        kind = kind or f"polynomial{self.parameterAsInt(parameters, self.ORDER, context)}"
        crs = self.parameterAsCrs(parameters, self.GCP_CRS, context)
        pairs = batch.find_images(folder)
        inputs = {f"IMAGE{k}": list(pair) for k, pair in enumerate(pairs)}
        with self.output_contract(parameters, context, [self.OUTPUT_CSV, self.OUTPUT_HTML],
                                  inputs=inputs) as out:

            def log(row):
                if row.error:
                    feedback.reportError(f"{row.image}: {row.error}", False)  # i18n: data
                else:
                    word = self.log_word
                    feedback.pushInfo(self.tr(
                        "{image}: {kind}, RMS_T {rms:.4f}, {basis} RMS_T {honest:.4f}, "
                        "{verdict} → {output}").format(
                            image=row.image, kind=row.kind, rms=row.rms_t,
                            basis=word(assess.honest_label(row.basis)), honest=row.honest_rms_t,
                            verdict=word(row.verdict), output=row.output))

            rows = batch.rectify_folder(
                folder, out_folder, kind=kind, crs=crs.toWkt() if crs.isValid() else "",
                refine=self.parameterAsBool(parameters, self.REFINE, context),
                resampling=warp.RESAMPLING[self.parameterAsEnum(parameters, self.RESAMPLING,
                                                                context)],
                log=log, **self.core_callbacks(feedback))
            failed = [r for r in rows if r.error]
            if rows and len(failed) == len(rows):
                raise InputError("None of the {n} images could be rectified (first: {image}: "
                                 "{error}). Fix their GCP files and run again.",
                                 n=len(rows), image=os.path.basename(failed[0].image),
                                 error=failed[0].error)
            outputs = {self.OUTPUT_FOLDER: out_folder, "N_IMAGES": len(rows),
                       "N_RECTIFIED": sum(1 for r in rows if not r.error)}
            if out.requested(self.OUTPUT_CSV):
                out.write_text(self.OUTPUT_CSV, batch.summary_csv(rows))
                outputs[self.OUTPUT_CSV] = out.final(self.OUTPUT_CSV)
            if out.requested(self.OUTPUT_HTML):
                out.write_text(self.OUTPUT_HTML, self.render_report(
                    batch.summary_report(rows), parameters, context))
                outputs[self.OUTPUT_HTML] = out.final(self.OUTPUT_HTML)
        feedback.setProgress(100)
        return outputs

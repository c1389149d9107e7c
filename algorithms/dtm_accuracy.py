"""DTM accuracy against check points (GNSS/total-station heights)."""
from __future__ import annotations

import os

import numpy as np
from qgis.core import (
    QgsCoordinateTransform,
    QgsProcessing,
    QgsProcessingException,
    QgsProcessingOutputNumber,
    QgsProcessingParameterBoolean,
    QgsProcessingParameterCrs,
    QgsProcessingParameterEnum,
    QgsProcessingParameterFeatureSource,
    QgsProcessingParameterField,
    QgsProcessingParameterFile,
    QgsProcessingParameterRasterLayer,
    QgsProcessingParameterVectorDestination,
    QgsWkbTypes,
)
from qgis.PyQt.QtCore import QT_TRANSLATE_NOOP

from ..core.io.points import read_checkpoints_csv, write_points_layer
from ..core.io.raster import raster_extent, read_raster
from ..core.io.units import raster_units
from ..core.progress import Cancelled
from ..core.reporting import translator
from ..core.terrain import accuracy as core_acc
from ..core.terrain import report as terrain_report
from .base import GeomaticsAlgorithm
from .helptext import build_help
from .styles import residual_style

NUMBERS = (
    ("N", "n", QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Check points used")),
    ("N_OUTSIDE", "n_outside", QT_TRANSLATE_NOOP("GeomaticsAlgorithm",
                                                 "Check points outside the DTM")),
    ("N_NODATA", "n_nodata", QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Check points on DTM nodata")),
    ("ME", "me", QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Mean error (m)")),
    ("MAE", "mae", QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Mean absolute error (m)")),
    ("RMSE", "rmse", QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "RMSE (m)")),
    ("STD", "std", QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Standard deviation of the errors (m)")),
    ("MAX_ABS_ERROR", "max_abs_error", QT_TRANSLATE_NOOP("GeomaticsAlgorithm",
                                                         "Maximum absolute error (m)")),
    ("R", "r", QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Pearson r")),
    ("R2", "r2", QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "R²")),
    ("NMAD", "nmad", QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "NMAD (m)")),
    ("ACCURACY_95", "accuracy_95", QT_TRANSLATE_NOOP("GeomaticsAlgorithm",
                                                     "Vertical accuracy at 95 % = 1.96·RMSE (m)")),
)


class CheckPointInputs:
    """Check-point parameters and their reader, shared by every algorithm that measures
    a DTM against check points (a point layer with height/id fields, or a CSV file with
    its CRS). Mixed in before :class:`GeomaticsAlgorithm` so its strings keep one
    translation context."""

    CHECKPOINTS = "CHECKPOINTS"
    Z_FIELD = "Z_FIELD"
    ID_FIELD = "ID_FIELD"
    CHECKPOINTS_CSV = "CHECKPOINTS_CSV"
    CSV_CRS = "CSV_CRS"
    REPROJECT = "REPROJECT"
    METHOD = "METHOD"

    def add_checkpoint_params(self, csv_label, *, advanced=False):
        """The check-point parameters (layer with height and id fields, or a CSV file
        with its CRS, reprojection and sampling); ``advanced`` flags the last three."""
        self.add(QgsProcessingParameterFeatureSource(
            self.CHECKPOINTS, self.tr("Check points (point layer)"),
            [QgsProcessing.TypeVectorPoint], optional=True))
        self.add(QgsProcessingParameterField(
            self.Z_FIELD, self.tr("Height field (empty = geometry Z)"),
            parentLayerParameterName=self.CHECKPOINTS,
            type=QgsProcessingParameterField.Numeric, optional=True))
        self.add(QgsProcessingParameterField(
            self.ID_FIELD, self.tr("Id field"), parentLayerParameterName=self.CHECKPOINTS,
            optional=True))
        self.add(QgsProcessingParameterFile(
            self.CHECKPOINTS_CSV, csv_label, behavior=QgsProcessingParameterFile.File,
            fileFilter="Delimited text (*.csv *.txt *.xyz *.CSV *.TXT)", optional=True))
        self.add(QgsProcessingParameterCrs(
            self.CSV_CRS, self.tr("CRS of the check point file (default: DTM CRS)"),
            optional=True), advanced=advanced)
        self.add(QgsProcessingParameterBoolean(
            self.REPROJECT, self.tr("Reproject check points to the DTM CRS"), False),
            advanced=advanced)
        self.add(QgsProcessingParameterEnum(
            self.METHOD, self.tr("Sampling"), [self.tr("Bilinear"), self.tr("Nearest cell")],
            defaultValue=0), advanced=advanced)

    # ------------------------------------------------------------------ inputs
    def read_points(self, parameters, context, dtm_crs, feedback):
        source = self.parameterAsSource(parameters, self.CHECKPOINTS, context)
        csv_path = self.parameterAsFile(parameters, self.CHECKPOINTS_CSV, context)
        reproject = self.parameterAsBool(parameters, self.REPROJECT, context)
        if source is None and not csv_path:
            raise QgsProcessingException(self.tr(
                "Give the check points as a point layer (CHECKPOINTS) or a file "
                "(CHECKPOINTS_CSV)."))
        if source is not None and csv_path:
            raise QgsProcessingException(self.tr(
                "Give the check points either as a layer or as a file, not both."))
        if source is not None:
            zf = self.parameterAsString(parameters, self.Z_FIELD, context)
            idf = self.parameterAsString(parameters, self.ID_FIELD, context)
            src_crs = source.sourceCrs()
            if not zf and not QgsWkbTypes.hasZ(source.wkbType()):
                raise QgsProcessingException(self.tr(
                    "The check point layer has no Z coordinate; choose the height field "
                    "(Z_FIELD)."))
            ids, xs, ys, zs = [], [], [], []
            for k, f in enumerate(source.getFeatures(), start=1):
                g = f.geometry()
                if g is None or g.isEmpty():
                    continue
                p = next(iter(g.vertices()))
                xs.append(p.x())
                ys.append(p.y())
                if zf:
                    v = f[zf]
                    zs.append(float(v) if v is not None and str(v) != "NULL" else np.nan)
                else:
                    zs.append(p.z())
                ids.append(str(f[idf]) if idf else str(f.id() if f.id() >= 0 else k))
            if not xs:
                raise QgsProcessingException(self.tr("The check point layer has no points."))
            x, y, z = np.array(xs), np.array(ys), np.array(zs, dtype=float)
            what = self.tr("check point layer")
        else:
            ids, x, y, z = read_checkpoints_csv(csv_path)
            src_crs = self.parameterAsCrs(parameters, self.CSV_CRS, context)
            what = self.tr("check point file")
        if src_crs is not None and src_crs.isValid() and dtm_crs.isValid() \
                and src_crs != dtm_crs:
            if not reproject:
                raise QgsProcessingException(self.tr(
                    "The {} is in {} but the DTM is in {}. Reproject the check points first "
                    "or tick 'Reproject check points to the DTM CRS' (REPROJECT=true; x, y "
                    "only, heights are not converted). No output was written.").format(
                        what, src_crs.authid() or src_crs.description(),
                        dtm_crs.authid() or dtm_crs.description()))
            tr = QgsCoordinateTransform(src_crs, dtm_crs, context.transformContext())
            for i in range(x.size):
                pt = tr.transform(float(x[i]), float(y[i]))
                x[i], y[i] = pt.x(), pt.y()
            feedback.pushInfo(self.tr("Check points reprojected from {} to {}").format(
                src_crs.authid(), dtm_crs.authid()))
        elif src_crs is None or not src_crs.isValid():
            feedback.pushInfo(self.tr("Check points assumed to be in the DTM's CRS."))
        return ids, x, y, z


class DtmAccuracyAlgorithm(CheckPointInputs, GeomaticsAlgorithm):
    """DTM accuracy against check points: statistics, residual layer, HTML report."""

    GROUP = "accuracy"

    DTM = "DTM"
    BAND = "BAND"
    OUTPUT = "OUTPUT"
    OUTPUT_STYLES = {"OUTPUT": "residuals"}
    OUTPUT_HTML = "OUTPUT_HTML"

    def name(self):
        return "dtmaccuracy"

    def displayName(self):  # noqa: N802
        return self.tr("DTM accuracy against check points")

    def tags(self):
        return self.tr("dtm,dem,accuracy,rmse,check points,gnss,nmad,asprs,vertical accuracy,"
                       "validation").split(",")

    def shortHelpString(self):  # noqa: N802
        return build_help(self, self.tr(
            "Compares a DTM with independent check points (e.g. GNSS heights) and "
            "summarises the errors e = z<sub>DTM</sub> − z<sub>check</sub> as bias, mean "
            "absolute error, RMSE, NMAD, Pearson r and the vertical accuracy at 95 % = "
            "1.96·RMSE (ASPRS 2014). Check points outside the DTM or on nodata are "
            "counted and excluded, never read as 0."),
            "DTM=dtm.tif CHECKPOINTS_CSV=gnss.csv OUTPUT=residuals.gpkg "
            "OUTPUT_HTML=dtm_accuracy.html",
            {self.CHECKPOINTS: self.tr("Give the layer or the file."),
             self.CHECKPOINTS_CSV: self.tr("A header x/easting, y/northing, z/height (and "
                                           "id/name), or columns id x y z without a "
                                           "header."),
             self.REPROJECT: self.tr("x and y only: heights are not converted between "
                                     "vertical datums. Without it, check points in another "
                                     "CRS are an error."),
             self.OUTPUT: self.tr("Point layer with the error and status of each check "
                                  "point, styled by error.")})

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add(QgsProcessingParameterRasterLayer(self.DTM, self.tr("DTM")))
        self.add_number(self.BAND, self.tr("Band"), 1, minimum=1, integer=True,
                        advanced=True)
        self.add_checkpoint_params(self.tr("Check point file (CSV/TXT)"))
        self.add(QgsProcessingParameterVectorDestination(
            self.OUTPUT, self.tr("Residuals"), QgsProcessing.TypeVectorPoint, optional=True,
            createByDefault=True))
        self.add_report_output(self.OUTPUT_HTML, self.tr("DTM accuracy report"),
                               create_by_default=True)
        self.add_report_language()
        for name, _, label in NUMBERS:
            self.addOutput(QgsProcessingOutputNumber(name, self.tr(label)))  # i18n: noop-list

    # ------------------------------------------------------------------ run
    def input_files(self, parameters, context, dtm_path):
        """Every file read: the DTM, the check point file and the layer's file."""
        return {self.DTM: dtm_path, **self.checkpoint_files(parameters, context)}

    def process(self, parameters, context, feedback):
        layer = self.parameterAsRasterLayer(parameters, self.DTM, context)
        if layer is None:
            raise QgsProcessingException(self.tr("Choose a DTM raster."))
        band = self.parameterAsInt(parameters, self.BAND, context)
        method = core_acc.METHODS[self.parameterAsEnum(parameters, self.METHOD, context)]
        with self.output_contract(parameters, context, [self.OUTPUT, self.OUTPUT_HTML],
                                  self.input_files(parameters, context,
                                                   layer.source())) as out:
            r = read_raster(layer.source(), band)
            dtm_crs = layer.crs()
            feedback.setProgress(20)
            ids, x, y, z = self.read_points(parameters, context, dtm_crs, feedback)
            core_acc.check_points_not_degrees(
                x, y, raster_extent(r), crs_label=dtm_crs.authid() or dtm_crs.description())
            # Heights in metres (DEVELOPERS.md, Units): a DTM in feet, check points in
            # the DTM's units, errors reported in metres.
            units = raster_units(layer.source(), band)
            self.log_units(feedback, units)
            core_acc.check_duplicates(ids, x, y, tolerance=0.001 / units.h)
            if feedback.isCanceled():
                raise Cancelled("cancelled by the user")
            res = core_acc.dtm_accuracy(r.masked() * units.v, r.geotransform, x, y,
                                        z * units.v, method=method)
            feedback.setProgress(50)
            summary = res.summary()
            results = {name: summary[key] for name, key, _ in NUMBERS}
            feedback.pushInfo(self.tr("N = {}, RMSE = {:.4f} m, ME = {:.4f} m, r = {:.5f}; "
                                      "{} outside, {} on nodata").format(
                res.n_used, summary["rmse"], summary["me"], summary["r"], res.n_outside,
                res.n_nodata))
            if core_acc.few_check_points(res.n_used):
                feedback.pushWarning(self.tr(   # = core_acc.FEW_CHECK_POINTS
                    "Only {n} check points were compared with the DTM: ASPRS (2014) asks "
                    "for at least {minimum} check points before a vertical accuracy is "
                    "stated, so these statistics are indicative only. Add check points (at "
                    "least {minimum}) to state an accuracy.").format(
                    n=res.n_used, minimum=core_acc.ASPRS_MIN_CHECK_POINTS))
            if out.requested(self.OUTPUT):
                self.write_residuals(out.path(self.OUTPUT), res, ids, dtm_crs)
                results[self.OUTPUT] = out.final(self.OUTPUT)
            if feedback.isCanceled():
                raise Cancelled("cancelled by the user")
            if out.requested(self.OUTPUT_HTML):
                rep = terrain_report.accuracy_report(
                    res, ids, r.masked() * units.v, r.geotransform,
                    dtm_name=os.path.basename(layer.source()),
                    crs_label=dtm_crs.authid() or dtm_crs.description() or "unknown",
                    tr=translator(self.report_lang(parameters, context)), units=units)
                out.write_text(self.OUTPUT_HTML, self.render_report(rep, parameters, context))
                results[self.OUTPUT_HTML] = out.final(self.OUTPUT_HTML)
        feedback.setProgress(100)
        return results

    @staticmethod
    def write_residuals(path, res, ids, crs) -> None:
        """The residual point layer (id, x, y, z_check, z_dtm, error, abs_error, status)."""
        ok = res.status == core_acc.OK
        err = np.where(ok, res.error, np.nan)
        authid = crs.authid() if crs.isValid() else ""
        crs_text = authid if authid.upper().startswith("EPSG:") else (
            crs.toWkt() if crs.isValid() else None)
        write_points_layer(path, res.x, res.y, res.z_check, {
            "id": [str(i) for i in ids], "x": res.x, "y": res.y, "z_check": res.z_check,
            "z_dtm": np.where(ok, res.z_dtm, np.nan), "error": err,
            "abs_error": np.abs(err),
            "status": [core_acc.STATUS_NAMES[int(s)] for s in res.status]},
            crs=crs_text, layer_name="residuals", style_qml=residual_style(err))

"""Terrain models from LiDAR points: IDW DTM, kriging DTM, DSM / nDSM.

Thin wrappers over :mod:`..core.terrain.idw`, :mod:`..core.terrain.kriging`,
:mod:`..core.terrain.dsm` with the shared :mod:`..core.terrain.grid` definition.
"""
from __future__ import annotations

import os
import time

import numpy as np
from qgis.core import (
    QgsCoordinateReferenceSystem,
    QgsProcessingException,
    QgsProcessingOutputNumber,
    QgsProcessingParameterBoolean,
    QgsProcessingParameterCrs,
    QgsProcessingParameterDefinition,
    QgsProcessingParameterEnum,
    QgsProcessingParameterExtent,
    QgsProcessingParameterRasterDestination,
    QgsProcessingParameterRasterLayer,
    QgsProcessingParameterString,
)
from qgis.PyQt.QtCore import QT_TRANSLATE_NOOP

from ..core.coords import check_projected
from ..core.errors import InputError
from ..core.io.las import iter_las_chunks, las_info
from ..core.io.points import parse_classes, write_grid
from ..core.io.raster import read_raster
from ..core.io.units import Units, crs_units
from ..core.progress import Monitor
from ..core.terrain import dsm as core_dsm
from ..core.terrain import dtm as core_dtm
from ..core.terrain import idw as core_idw
from ..core.terrain import kriging as core_kriging
from ..core.terrain.grid import grid_from_extent, grid_like
from .base import GeomaticsAlgorithm
from .helptext import build_help

NAN = float("nan")



#: VARIOGRAM options (PyKrige's model name after a translated label)
VARIOGRAM_LABELS = {
    "linear": QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Linear"),
    "power": QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Power"),
    "gaussian": QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Gaussian"),
    "spherical": QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Spherical"),
    "exponential": QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Exponential"),
}

#: ASPRS LAS 1.4 R15 classes 0–22 (index = class code), for the class pickers.
ASPRS_CLASSES = (
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Created, never classified"),
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Unclassified"),
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Ground"),
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Low vegetation"),
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Medium vegetation"),
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "High vegetation"),
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Building"),
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Low point (noise)"),
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Reserved (model key-point)"),
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Water"),
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Rail"),
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Road surface"),
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Reserved (overlap)"),
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Wire – guard (shield)"),
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Wire – conductor (phase)"),
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Transmission tower"),
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Wire-structure connector (insulator)"),
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Bridge deck"),
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "High noise"),
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Overhead structure"),
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Ignored ground"),
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Snow"),
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Temporal exclusion"),
)


def _crs_string(crs: QgsCoordinateReferenceSystem) -> str:
    if crs is None or not crs.isValid():
        return ""
    authid = crs.authid()
    if authid and authid.upper().startswith("EPSG:"):
        return authid
    return crs.toWkt(QgsCoordinateReferenceSystem.WKT_PREFERRED_GDAL)


def las_units_for(info, crs: str, crs_source: str) -> Units:
    """Units of a cloud: its header's, or those of the CRS the user gave instead."""
    if crs_source == "LAS file" or not crs:
        return info.units
    return crs_units(crs)


def _qgs_crs(text: str) -> QgsCoordinateReferenceSystem:
    if not text:
        return QgsCoordinateReferenceSystem()
    crs = QgsCoordinateReferenceSystem(text)
    if not crs.isValid():
        crs = QgsCoordinateReferenceSystem.fromWkt(text)
    return crs


def _check_tif(path: str) -> None:
    if path and os.path.splitext(path)[1].lower() not in (".tif", ".tiff"):
        raise InputError("Output {path}: only GeoTIFF outputs are written; use a .tif file "
                         "name.", path=path)


class _GridAlgorithm(GeomaticsAlgorithm):
    """Shared parameters: LAS input, class filter, grid, CRS, gaps, outputs."""

    GROUP = "terrain"

    INPUT = "INPUT"
    CLASSES = "CLASSES"
    CELL_SIZE = "CELL_SIZE"
    EXTENT = "EXTENT"
    CRS = "CRS"
    MAX_DISTANCE = "MAX_DISTANCE"
    FILL_GAPS = "FILL_GAPS"
    OUTPUT = "OUTPUT"
    OUTPUT_HTML = "OUTPUT_HTML"

    def classes_param(self, name, label, default):
        """Multi-select enum of the ASPRS classes (option index = class code).

        Old comma text such as ``"2,8"`` is still accepted (``qgis_process``).
        """
        options = [f"{c} — {self.tr(n)}"  # i18n: noop-list
                   for c, n in enumerate(ASPRS_CLASSES)]
        param = QgsProcessingParameterEnum(
            name, label, options,
            allowMultiple=True, defaultValue=list(default), optional=True)
        # check boxes, not the chooser that only says "1 options selected"
        param.setMetadata({"widget_wrapper": {"useCheckBoxes": True, "columns": 2}})
        return param

    def classes(self, parameters, name, context):
        """Selected class codes (``()`` = every class)."""
        return parse_classes(self.parameterAsEnums(parameters, name, context))

    def add_input_params(self, *, classes_default=(2,)):
        self.add_las_input(self.INPUT, self.tr("Point cloud (LAS/LAZ)"))
        self.add(self.classes_param(self.CLASSES, self.tr("Classes used (none = all)"),
                                    classes_default))
        self.add_number(self.CELL_SIZE, self.tr("Cell size (m)"), 1.0, minimum=0.0)
        self.add(QgsProcessingParameterExtent(self.EXTENT, self.tr("Extent"), optional=True))
        self.add(QgsProcessingParameterCrs(
            self.CRS, self.tr("CRS (overrides the LAS file's CRS)"), optional=True))

    def add_gap_params(self):
        self.add_number(self.MAX_DISTANCE, self.tr("Maximum distance to data (m, 0 = auto)"),
                        0.0, minimum=0.0, advanced=True)
        self.add(QgsProcessingParameterBoolean(
            self.FILL_GAPS, self.tr("Fill data gaps (interpolate far from data)"), False),
            advanced=True)

    def add_html(self):
        self.add_report_output(self.OUTPUT_HTML, self.report_label())
        self.add_report_language()

    def report_label(self):
        return self.tr("Report")

    def common_notes(self):
        """Help notes of the shared grid parameters (see :func:`.helptext.build_help`)."""
        return {
            self.EXTENT: self.tr("Default: the extent of the selected points, snapped "
                                 "outward to whole cells so that tiles line up."),
            self.CRS: self.tr("Needed when the LAS file has no CRS."),
            self.MAX_DISTANCE: self.tr("0 = five mean point spacings (at least two "
                                       "cells); cells farther from any point are nodata."),
            self.FILL_GAPS: self.tr("Interpolates every cell, ignoring the maximum "
                                    "distance."),
            self.OUTPUT: self.tr("GeoTIFF (float32, nodata −9999) in the cloud's CRS."),
        }

    # ---------------------------------------------------------------- helpers
    def resolve_crs(self, parameters, context, las_crs):
        given = self.parameterAsCrs(parameters, self.CRS, context)
        if given is not None and given.isValid():
            return _crs_string(given), "parameter CRS"
        if las_crs:
            return las_crs, "LAS file"
        raise QgsProcessingException(self.tr(
            "The point cloud has no CRS record and no CRS was given; set the CRS parameter "
            "(e.g. EPSG:32632). No output was written."))

    def extent_box(self, parameters, context, crs_text):
        if parameters.get(self.EXTENT) in (None, ""):
            return None
        rect = self.parameterAsExtent(parameters, self.EXTENT, context, _qgs_crs(crs_text))
        if rect is None or rect.isNull() or rect.isEmpty():
            return None
        return (rect.xMinimum(), rect.xMaximum(), rect.yMinimum(), rect.yMaximum())

    def cell_size(self, parameters, context):
        cell = self.parameterAsDouble(parameters, self.CELL_SIZE, context)
        if not cell > 0:
            raise InputError("Cell size must be > 0 (metres); give e.g. 1.0. No output was "
                             "written.")
        return cell

    def gap_options(self, parameters, context):
        fill = self.parameterAsBool(parameters, self.FILL_GAPS, context)
        maxd = self.parameterAsDouble(parameters, self.MAX_DISTANCE, context)
        return fill, (maxd if maxd > 0 else None)

    def load_points(self, parameters, context, feedback):
        """Return ``(path, points in metres, grid, CRS source)`` (core ``read_ground``)."""
        path = self.las_input_path(parameters, context, self.INPUT)
        classes = self.classes(parameters, self.CLASSES, context)
        info = las_info(path)
        crs, crs_source = self.resolve_crs(parameters, context, info.crs)
        box = self.extent_box(parameters, context, crs)
        cell = self.cell_size(parameters, context)
        cb = self.core_callbacks(feedback)
        feedback.pushInfo(self.tr("Reading points of class(es) {} from {}").format(
            ", ".join(map(str, classes)) or self.tr("all"), path))
        units = las_units_for(info, crs, crs_source)
        self.log_units(feedback, units)
        pts, grid = core_dtm.read_ground(path, classes, cell=cell, units=units, extent=box,
                                         crs=crs, cancel=cb["cancel"])
        feedback.pushInfo(self.tr("{} of {} points selected").format(len(pts), pts.n_total))
        return path, pts, grid, crs_source

    def run_method(self, parameters, context, feedback, method, out, rasters=()):
        """Read, interpolate with ``method``, write OUTPUT (+ ``rasters``: {name: extra})
        and the report; the output numbers shared by every DTM algorithm."""
        path, pts, grid, crs_source = self.load_points(parameters, context, feedback)
        fill, maxd = self.gap_options(parameters, context)
        run = core_dtm.make_dtm(path, pts, grid, method, max_distance=maxd, fill=fill,
                                crs_source=crs_source,
                                monitor=Monitor(**self.core_callbacks(feedback)))
        core_dtm.write_dtm(run, out.path(self.OUTPUT))
        results = {self.OUTPUT: out.final(self.OUTPUT), "N_POINTS": run.outcome.n_points,
                   "VALID_CELLS": run.stats["valid_cells"],
                   "NODATA_CELLS": run.stats["nodata_cells"]}
        for name, extra in dict(rasters).items():
            if out.requested(name):
                core_dtm.write_dtm(run, out.path(name), extra=extra)
                results[name] = out.final(name)
        if out.requested(self.OUTPUT_HTML):
            rep = core_dtm.dtm_report(run, lang=self.report_lang(parameters, context))
            out.write_text(self.OUTPUT_HTML, self.render_report(rep, parameters, context))
            results[self.OUTPUT_HTML] = out.final(self.OUTPUT_HTML)
        return run, results

    def contract(self, parameters, context, rasters, inputs):
        """The output contract of the rasters + the report; rasters must be GeoTIFF."""
        out = self.output_contract(parameters, context, [*rasters, self.OUTPUT_HTML],
                                   inputs=inputs)
        for name in rasters:
            _check_tif(out.final(name))
        return out

    grid_stats = staticmethod(core_dtm.grid_stats)


class IdwDtmAlgorithm(_GridAlgorithm):
    """IDW DTM (gdal_grid invdistnn semantics)."""

    OUTPUT_STYLES = {"OUTPUT": "elevation"}
    POWER = "POWER"
    NEIGHBOURS = "NEIGHBOURS"
    RADIUS = "RADIUS"
    MIN_POINTS = "MIN_POINTS"

    def report_label(self):
        return self.tr("IDW DTM report")

    def name(self):
        return "idwdtm"

    def displayName(self):  # noqa: N802
        return self.tr("DTM by inverse distance weighting (IDW)")

    def tags(self):
        return self.tr("dtm,dem,idw,inverse distance,interpolation,lidar,ground,gdal_grid,"
                       "invdistnn,raster").split(",")

    def shortHelpString(self):  # noqa: N802
        return build_help(self, self.tr(
            "Interpolates a terrain raster from the ground points of a LAS/LAZ file by "
            "inverse distance weighting (Shepard 1968) over the nearest neighbours of each "
            "cell centre. It follows <code>gdal_grid -a invdistnn</code> but works in "
            "blocks on a KD-tree, so a million points take seconds."),
            "INPUT=ground.laz CELL_SIZE=1 POWER=3 NEIGHBOURS=12 OUTPUT=dtm.tif "
            "OUTPUT_HTML=idw.html",
            {**self.common_notes(),
             self.POWER: self.tr("The seed paper found 3 best (RMSE 0.204 m at 62 GNSS "
                                 "points)."),
             self.NEIGHBOURS: self.tr("Nearest points used per cell; 0 = every point "
                                      "within the search radius."),
             self.RADIUS: self.tr("Only points within this distance are used."),
             self.MIN_POINTS: self.tr("Cells with fewer points within the search radius "
                                      "are nodata.")})

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add_input_params()
        self.add_number(self.POWER, self.tr("Power p"), core_idw.DEFAULT_POWER, minimum=0.0)
        self.add_number(self.NEIGHBOURS, self.tr("Neighbours (0 = all within radius)"), 12,
                        minimum=0, integer=True)
        self.add_number(self.RADIUS, self.tr("Search radius (m, 0 = unlimited)"), 0.0,
                        minimum=0.0)
        self.add_number(self.MIN_POINTS, self.tr("Minimum points"), 0, minimum=0,
                        integer=True, advanced=True)
        self.add_gap_params()
        self.add(QgsProcessingParameterRasterDestination(self.OUTPUT, self.tr("IDW DTM")))
        self.add_html()
        for name, label in (("N_POINTS", self.tr("Points interpolated")),
                            ("VALID_CELLS", self.tr("Cells with a value")),
                            ("NODATA_CELLS", self.tr("Nodata cells"))):
            self.addOutput(QgsProcessingOutputNumber(name, label))

    def process(self, parameters, context, feedback):
        radius = self.parameterAsDouble(parameters, self.RADIUS, context)
        method = core_dtm.IdwMethod(core_dtm.IdwOptions(
            power=self.parameterAsDouble(parameters, self.POWER, context),
            neighbours=self.parameterAsInt(parameters, self.NEIGHBOURS, context),
            radius=radius if radius > 0 else None,
            min_points=self.parameterAsInt(parameters, self.MIN_POINTS, context)))
        path = self.las_input_path(parameters, context, self.INPUT)
        with self.contract(parameters, context, [self.OUTPUT], {self.INPUT: path}) as out:
            _, results = self.run_method(parameters, context, feedback, method, out)
        return results


class KrigingDtmAlgorithm(_GridAlgorithm):
    """Kriging DTM with variance raster, fitted variogram and cross-validation."""

    KRIGING_TYPE = "KRIGING_TYPE"
    VARIOGRAM = "VARIOGRAM"
    VARIOGRAM_PARAMS = "VARIOGRAM_PARAMS"        # old text form, hidden, still accepted
    VARIOGRAM_NUGGET = "VARIOGRAM_NUGGET"
    VARIOGRAM_SILL = "VARIOGRAM_SILL"
    VARIOGRAM_RANGE = "VARIOGRAM_RANGE"
    VARIOGRAM_SLOPE = "VARIOGRAM_SLOPE"
    VARIOGRAM_SCALE = "VARIOGRAM_SCALE"
    VARIOGRAM_EXPONENT = "VARIOGRAM_EXPONENT"
    NEIGHBOURS = "NEIGHBOURS"
    FIT_POINTS = "FIT_POINTS"
    NLAGS = "NLAGS"
    MAX_LAG = "MAX_LAG"
    CV_POINTS = "CV_POINTS"
    SEED = "SEED"
    VARIANCE_AS_STD = "VARIANCE_AS_STD"
    OUTPUT_VARIANCE = "OUTPUT_VARIANCE"
    OUTPUT_STYLES = {"OUTPUT": "elevation", "OUTPUT_VARIANCE": "variance"}

    TYPES = ("ordinary", "universal")

    def report_label(self):
        return self.tr("Kriging DTM report")

    def name(self):
        return "krigingdtm"

    def displayName(self):  # noqa: N802
        return self.tr("DTM by kriging (ordinary / universal)")

    def tags(self):
        return self.tr("dtm,dem,kriging,variogram,geostatistics,pykrige,interpolation,lidar,"
                       "variance,cross-validation").split(",")

    def shortHelpString(self):  # noqa: N802
        return build_help(self, self.tr(
            "Kriges the ground points of a LAS/LAZ file onto a raster (ordinary kriging, "
            "or universal kriging with a linear drift) and can also write the kriging "
            "variance. The variogram is fitted on a random sample or given by you, and "
            "each cell is kriged from its nearest points, so a million points take about "
            "a minute."),
            "INPUT=ground.laz CELL_SIZE=1 VARIOGRAM=3 NEIGHBOURS=16 CV_POINTS=1000 "
            "OUTPUT=dtm.tif OUTPUT_VARIANCE=variance.tif",
            {**self.common_notes(),
             self.VARIOGRAM_SILL: self.tr("Give nugget, sill and range to skip the fit; "
                                          "the sill includes the nugget."),
             self.VARIOGRAM_SLOPE: self.tr("Linear model only."),
             self.VARIOGRAM_SCALE: self.tr("Power model only."),
             self.VARIOGRAM_EXPONENT: self.tr("Power model only."),
             self.NEIGHBOURS: self.tr("Local kriging: the mean is re-estimated in every "
                                      "neighbourhood; as many neighbours as points "
                                      "(up to 6000) gives global kriging, identical to "
                                      "PyKrige."),
             self.MAX_LAG: self.tr("0 = three times the typical distance to the farthest "
                                   "neighbour used; for a field-scale fit give about half "
                                   "the extent."),
             self.CV_POINTS: self.tr("Leave-one-out check on this many random points; an "
                                     "RMS standardised error near 1 means realistic "
                                     "variances."),
             self.SEED: self.tr("Makes the sample of the variogram fit reproducible."),
             self.OUTPUT_VARIANCE: self.tr("In m², or in m as a standard deviation.")})

    def variogram(self, parameters, context, model):
        """The user's variogram (numbers, or the old text form), or None to fit one."""
        names = (self.VARIOGRAM_NUGGET, self.VARIOGRAM_SILL, self.VARIOGRAM_RANGE,
                 self.VARIOGRAM_SLOPE, self.VARIOGRAM_SCALE, self.VARIOGRAM_EXPONENT)
        given = {n: (None if parameters.get(n) in (None, "")
                     else self.parameterAsDouble(parameters, n, context)) for n in names}
        if any(v is not None for v in given.values()):
            return core_kriging.given_variogram(
                model, nugget=given[self.VARIOGRAM_NUGGET] or 0.0,
                sill=given[self.VARIOGRAM_SILL], range_=given[self.VARIOGRAM_RANGE],
                slope=given[self.VARIOGRAM_SLOPE], scale=given[self.VARIOGRAM_SCALE],
                exponent=given[self.VARIOGRAM_EXPONENT])
        return core_kriging.parse_variogram_parameters(
            self.parameterAsString(parameters, self.VARIOGRAM_PARAMS, context), model)

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add_input_params()
        self.add(QgsProcessingParameterEnum(
            self.KRIGING_TYPE, self.tr("Kriging type"),
            [self.tr("Ordinary"), self.tr("Universal (linear drift)")], defaultValue=0))
        self.add(QgsProcessingParameterEnum(
            self.VARIOGRAM, self.tr("Variogram model"),
            [self.tr(VARIOGRAM_LABELS[m]) for m in core_kriging.MODELS],  # i18n: noop-list
            defaultValue=core_kriging.MODELS.index("spherical")))
        self.add_number(self.VARIOGRAM_NUGGET, self.tr("Variogram nugget (m², empty = fit)"),
                        None, minimum=0.0, optional=True)
        self.add_number(self.VARIOGRAM_SILL,
                        self.tr("Variogram sill, nugget included (m², empty = fit)"), None,
                        minimum=0.0, optional=True)
        self.add_number(self.VARIOGRAM_RANGE,
                        self.tr("Variogram practical range (m, empty = fit)"), None,
                        minimum=0.0, optional=True)
        self.add_number(self.VARIOGRAM_SLOPE, self.tr("Linear variogram slope (m²/m)"), None,
                        minimum=0.0, optional=True, advanced=True)
        self.add_number(self.VARIOGRAM_SCALE, self.tr("Power variogram scale"), None,
                        minimum=0.0, optional=True, advanced=True)
        self.add_number(self.VARIOGRAM_EXPONENT, self.tr("Power variogram exponent (0–2)"),
                        None, minimum=0.0, maximum=2.0, optional=True, advanced=True)
        legacy = QgsProcessingParameterString(
            self.VARIOGRAM_PARAMS, self.tr("Variogram parameters as text (old form)"),
            optional=True)
        legacy.setFlags(legacy.flags() | QgsProcessingParameterDefinition.FlagHidden)
        self.add(legacy)
        self.add_number(self.NEIGHBOURS, self.tr("Neighbours per cell"), 16, minimum=2,
                        integer=True)
        self.add_number(self.FIT_POINTS, self.tr("Points for the variogram fit"), 3000,
                        minimum=10, integer=True, advanced=True)
        self.add_number(self.NLAGS, self.tr("Lag classes"), 12, minimum=2, integer=True,
                        advanced=True)
        self.add_number(self.MAX_LAG, self.tr("Maximum lag (m, 0 = auto: local scale)"), 0.0,
                        minimum=0.0, advanced=True)
        self.add_number(self.CV_POINTS, self.tr("Cross-validation points (0 = off)"), 0,
                        minimum=0, integer=True)
        self.add_number(self.SEED, self.tr("Random seed"), 0, minimum=0, integer=True,
                        advanced=True)
        self.add_gap_params()
        self.add(QgsProcessingParameterRasterDestination(self.OUTPUT, self.tr("Kriging DTM")))
        self.add(QgsProcessingParameterBoolean(
            self.VARIANCE_AS_STD, self.tr("Write standard deviation instead of variance"),
            False))
        self.add(QgsProcessingParameterRasterDestination(
            self.OUTPUT_VARIANCE, self.tr("Kriging variance"), optional=True,
            createByDefault=True))
        self.add_html()
        for name, label in (("NUGGET", self.tr("Nugget")), ("SILL", self.tr("Sill")),
                            ("RANGE", self.tr("Range")),
                            ("N_POINTS", self.tr("Points kriged")),
                            ("VALID_CELLS", self.tr("Cells with a value")),
                            ("CV_ME", self.tr("Cross-validation mean error")),
                            ("CV_RMSE", self.tr("Cross-validation RMSE")),
                            ("CV_MSE", self.tr("Cross-validation mean standardised error"))):
            self.addOutput(QgsProcessingOutputNumber(name, label))

    def process(self, parameters, context, feedback):
        path = self.las_input_path(parameters, context, self.INPUT)
        model = core_kriging.MODELS[self.parameterAsEnum(parameters, self.VARIOGRAM, context)]
        max_lag = self.parameterAsDouble(parameters, self.MAX_LAG, context)
        method = core_dtm.KrigingMethod(core_dtm.KrigingOptions(
            model=model, variogram=self.variogram(parameters, context, model),
            drift="linear" if self.parameterAsEnum(parameters, self.KRIGING_TYPE, context)
            else "none",
            neighbours=self.parameterAsInt(parameters, self.NEIGHBOURS, context),
            fit_points=self.parameterAsInt(parameters, self.FIT_POINTS, context),
            nlags=self.parameterAsInt(parameters, self.NLAGS, context),
            max_lag=max_lag if max_lag > 0 else "auto",
            cv_points=self.parameterAsInt(parameters, self.CV_POINTS, context),
            seed=self.parameterAsInt(parameters, self.SEED, context)))
        extra = "std" if self.parameterAsBool(parameters, self.VARIANCE_AS_STD, context) \
            else "variance"
        with self.contract(parameters, context, [self.OUTPUT, self.OUTPUT_VARIANCE],
                           {self.INPUT: path}) as out:
            run, results = self.run_method(parameters, context, feedback, method, out,
                                           {self.OUTPUT_VARIANCE: extra})
        res = run.outcome.details
        feedback.pushInfo(self.tr("Variogram: {}").format(
            ", ".join(f"{a} {b}" for a, b in core_kriging.describe_variogram(res.variogram))))
        vd, cv, nan = res.variogram.as_dict(), res.cross_validation or {}, float("nan")
        results.pop("NODATA_CELLS")
        results.update(NUGGET=vd.get("nugget", nan), SILL=vd.get("sill", nan),
                       RANGE=vd.get("range", nan), CV_ME=cv.get("me", nan),
                       CV_RMSE=cv.get("rmse", nan), CV_MSE=cv.get("mse_std", nan))
        return results


class DsmAlgorithm(_GridAlgorithm):
    """DSM (highest return per cell) and nDSM/CHM = DSM − DTM."""

    FIRST_RETURNS = "FIRST_RETURNS"
    EXCLUDE_CLASSES = "EXCLUDE_CLASSES"
    FILL_DISTANCE = "FILL_DISTANCE"
    DTM = "DTM"
    CLAMP_NEGATIVE = "CLAMP_NEGATIVE"
    OUTPUT_NDSM = "OUTPUT_NDSM"
    OUTPUT_STYLES = {"OUTPUT": "elevation", "OUTPUT_NDSM": "height"}

    def report_label(self):
        return self.tr("DSM report")

    def name(self):
        return "dsm"

    def displayName(self):  # noqa: N802
        return self.tr("DSM and nDSM / canopy height model")

    def tags(self):
        return self.tr("dsm,ndsm,chm,canopy height,surface model,first returns,lidar,"
                       "raster").split(",")

    def shortHelpString(self):  # noqa: N802
        return build_help(self, self.tr(
            "Builds a digital surface model from a LAS/LAZ file: each cell takes the "
            "highest return falling in it. With a DTM it also writes the normalised DSM "
            "(canopy height model in forests) = DSM − DTM on the DTM's grid."),
            "INPUT=cloud.laz CELL_SIZE=1 FIRST_RETURNS=true DTM=dtm.tif OUTPUT=dsm.tif "
            "OUTPUT_NDSM=chm.tif",
            {**self.common_notes(),
             self.EXCLUDE_CLASSES: self.tr("By default low and high noise."),
             self.FIRST_RETURNS: self.tr("The usual canopy surface."),
             self.FILL_DISTANCE: self.tr("Empty cells take the nearest value within this "
                                         "distance; 0 = leave them nodata."),
             self.DTM: self.tr("Its grid and CRS replace the cell size, extent and CRS, so "
                               "that DSM and DTM align cell for cell."),
             self.OUTPUT_NDSM: self.tr("Needs a DTM.")})

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add_input_params(classes_default=())
        self.add(self.classes_param(self.EXCLUDE_CLASSES, self.tr("Excluded classes"),
                                    (7, 18)))
        self.add(QgsProcessingParameterBoolean(
            self.FIRST_RETURNS, self.tr("First returns only"), False))
        self.add_number(self.FILL_DISTANCE, self.tr("Fill empty cells up to (m)"), 0.0,
                        minimum=0.0, advanced=True)
        self.add(QgsProcessingParameterRasterLayer(
            self.DTM, self.tr("DTM (for the nDSM; its grid is used)"), optional=True))
        self.add(QgsProcessingParameterBoolean(
            self.CLAMP_NEGATIVE, self.tr("Clamp negative nDSM heights to 0"), True))
        self.add(QgsProcessingParameterRasterDestination(self.OUTPUT, self.tr("DSM")))
        self.add(QgsProcessingParameterRasterDestination(
            self.OUTPUT_NDSM, self.tr("nDSM / canopy height model"), optional=True,
            createByDefault=False))
        self.add_html()
        for name, label in (("VALID_CELLS", self.tr("DSM cells with a value")),
                            ("NDSM_MAX", self.tr("Maximum nDSM height"))):
            self.addOutput(QgsProcessingOutputNumber(name, label))

    @staticmethod
    def check_cloud_projected(info, crs):
        """Refuse a cloud in degrees (its header extent); an empty one is refused later."""
        if info.count:
            check_projected([info.mins[0], info.maxs[0]], [info.mins[1], info.maxs[1]],
                            [info.mins[2], info.maxs[2]], crs=crs)

    def target_grid(self, parameters, context, info, dtm_layer, want_ndsm):
        """(grid, DTM array or None, grid source): the DTM's grid, else from the cloud."""
        if dtm_layer is not None:
            r = read_raster(dtm_layer.source())
            crs = _crs_string(dtm_layer.crs()) or r.crs
            given = self.parameterAsCrs(parameters, self.CRS, context)
            las_crs = _crs_string(given) if given.isValid() else info.crs
            if las_crs and crs and not _qgs_crs(las_crs) == _qgs_crs(crs):
                raise QgsProcessingException(self.tr(
                    "The point cloud CRS ({}) differs from the DTM CRS ({}); give a DTM in "
                    "the point cloud's CRS. No output was written.").format(
                        _qgs_crs(las_crs).authid() or "custom",
                        _qgs_crs(crs).authid() or "custom"))
            self.check_cloud_projected(info, las_crs or crs)
            return grid_like(r.geotransform, r.shape, crs=crs), r.masked(), "DTM grid"
        if want_ndsm:
            raise QgsProcessingException(self.tr(
                "The nDSM needs a DTM: give the DTM parameter (e.g. the output of the "
                "IDW DTM algorithm). No output was written."))
        crs, crs_source = self.resolve_crs(parameters, context, info.crs)
        self.check_cloud_projected(info, crs)
        # The DSM grid is in the cloud's own units: the cell size (m) is converted.
        cell = self.cell_size(parameters, context) / las_units_for(info, crs, crs_source).h
        box = self.extent_box(parameters, context, crs)
        if box is None:
            box = (info.mins[0], info.maxs[0], info.mins[1], info.maxs[1])
        return grid_from_extent(box, cell, crs=crs), None, crs_source

    def process(self, parameters, context, feedback):
        t0 = time.time()
        path = self.las_input_path(parameters, context, self.INPUT)
        classes = self.classes(parameters, self.CLASSES, context)
        excl = self.classes(parameters, self.EXCLUDE_CLASSES, context)
        first = self.parameterAsBool(parameters, self.FIRST_RETURNS, context)
        fill_d = self.parameterAsDouble(parameters, self.FILL_DISTANCE, context)
        clamp = self.parameterAsBool(parameters, self.CLAMP_NEGATIVE, context)
        dtm_layer = self.parameterAsRasterLayer(parameters, self.DTM, context)
        inputs = {self.INPUT: path, self.DTM: dtm_layer.source() if dtm_layer else None}
        with self.contract(parameters, context, [self.OUTPUT, self.OUTPUT_NDSM],
                           inputs) as out:
            info = las_info(path)
            grid, dtm, crs_source = self.target_grid(parameters, context, info, dtm_layer,
                                                     out.requested(self.OUTPUT_NDSM))
            units = las_units_for(info, grid.crs, crs_source)
            self.log_units(feedback, units)
            fill_d = fill_d / units.h
            dims = ["classification"] + (["return_number"] if first else [])
            cb = self.core_callbacks(feedback)

            def chunks():
                for start, chunk in iter_las_chunks(path, dims):
                    if classes:
                        keep = np.isin(chunk["classification"], classes)
                        chunk.x, chunk.y, chunk.z = (chunk.x[keep], chunk.y[keep],
                                                     chunk.z[keep])
                        chunk.dims = {n: a[keep] for n, a in chunk.dims.items()}
                    yield start, chunk

            surf = core_dsm.dsm_from_chunks(chunks(), grid, n_total=info.count,
                                            first_only=first, exclude_classes=excl,
                                            fill_distance=fill_d, **cb)
            meta = {"method": f"highest {'first ' if first else ''}return per cell",
                    "source": os.path.basename(path)}
            write_grid(out.path(self.OUTPUT), surf, grid, metadata=meta, band_name="DSM",
                       units=units, in_data_units=True)
            stats = self.grid_stats(surf)
            results = {self.OUTPUT: out.final(self.OUTPUT), "VALID_CELLS": stats["valid_cells"],
                       "NDSM_MAX": float("nan")}
            nd = None
            if dtm is not None and out.requested(self.OUTPUT_NDSM):
                nd = core_dsm.ndsm(surf, dtm, clamp_negative=clamp)
                write_grid(out.path(self.OUTPUT_NDSM), nd, grid, metadata=meta,
                           band_name="nDSM", units=units, in_data_units=True)
                results[self.OUTPUT_NDSM] = out.final(self.OUTPUT_NDSM)
                results["NDSM_MAX"] = self.grid_stats(nd)["max"]
            if out.requested(self.OUTPUT_HTML):
                rep = core_dsm.dsm_report(
                    os.path.basename(path), info.count, grid, crs_source, surf, nd,
                    first_only=first, classes=classes, excluded=excl, clamp=clamp,
                    elapsed=time.time() - t0, lang=self.report_lang(parameters, context),
                    units=units)
                out.write_text(self.OUTPUT_HTML, self.render_report(rep, parameters, context))
                results[self.OUTPUT_HTML] = out.final(self.OUTPUT_HTML)
        return results

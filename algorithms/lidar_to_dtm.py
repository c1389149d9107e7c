"""LiDAR to DTM with accuracy in one step: ground filter → IDW DTM → DTM accuracy.

The all-or-nothing counterpart of the shipped graphical model
(``models/lidar_to_dtm.model3``): the three steps run under ONE output contract, so a
failure in the last step (or a cancel, or SIGTERM) leaves no classified cloud and no
DTM behind. Everything that can be checked is checked before the first step writes:
every output path against every input and each other, the CRS (present, projected),
the check points (readable, no duplicates, inside the cloud's extent).

The steps call the same core functions as ``lsqgroundfilter``/``groundfilter``
(:func:`..core.lidar.pipeline.classify_file`), ``idwdtm``
(:func:`..core.terrain.idw.idw_grid` on the classified cloud's ground points) and
``dtmaccuracy`` (:func:`..core.terrain.accuracy.dtm_accuracy`), so a run gives the same
DTM and the same RMSE as the three algorithms run one after another.
"""
from __future__ import annotations

import os
from dataclasses import replace

from qgis.core import (
    QgsCoordinateReferenceSystem,
    QgsProcessing,
    QgsProcessingOutputNumber,
    QgsProcessingParameterBoolean,
    QgsProcessingParameterCrs,
    QgsProcessingParameterFileDestination,
    QgsProcessingParameterRasterDestination,
    QgsProcessingParameterVectorDestination,
)

from ..core.coords import check_projected
from ..core.errors import InputError
from ..core.io.las import las_info
from ..core.io.points import ClassPoints
from ..core.io.raster import read_raster
from ..core.io.units import crs_units
from ..core.lidar import filters as core_filters
from ..core.lidar.filters import default_ground_filter
from ..core.lidar.pipeline import FilterOutputs, classify_file
from ..core.progress import Monitor
from ..core.reporting import T, translator
from ..core.terrain import accuracy as core_acc
from ..core.terrain import dtm as core_dtm
from ..core.terrain import idw as core_idw
from ..core.terrain import report as terrain_report
from ..core.terrain.grid import grid_from_points
from .base import LAS_OUT_FILTER, GeomaticsAlgorithm
from .dtm_accuracy import NUMBERS, CheckPointInputs, DtmAccuracyAlgorithm
from .helptext import build_help
from .terrain import _check_tif, _crs_string


def ground_filter():
    """``(algorithm object, selection options, id)`` of the ground step.

    The catalog's and the model's default filter from the one registry
    (:func:`..core.lidar.filters.default_ground_filter`: the recommended filter) with
    the point selection of its single-file algorithm's defaults, so a run with the
    defaults equals that algorithm with its defaults.
    """
    key = default_ground_filter()
    return (core_filters.ground_filter(key), core_filters.default_selection(key),
            core_filters.GROUND_FILTERS[key].algorithm)


class LidarToDtmAlgorithm(CheckPointInputs, GeomaticsAlgorithm):
    """Ground filter, IDW DTM and DTM accuracy through one output contract."""

    GROUP = "terrain"

    INPUT = "INPUT"
    CELL_SIZE = "CELL_SIZE"
    POWER = "POWER"
    NEIGHBOURS = "NEIGHBOURS"
    FILL_GAPS = "FILL_GAPS"
    CRS = "CRS"
    OUTPUT = "OUTPUT"
    OUTPUT_DTM = "OUTPUT_DTM"
    OUTPUT_RESIDUALS = "OUTPUT_RESIDUALS"
    OUTPUT_STYLES = {"OUTPUT_DTM": "elevation", "OUTPUT_RESIDUALS": "residuals"}
    OUTPUT_FILTER_HTML = "OUTPUT_FILTER_HTML"
    OUTPUT_DTM_HTML = "OUTPUT_DTM_HTML"
    OUTPUT_HTML = "OUTPUT_HTML"
    OUTPUTS = (OUTPUT, OUTPUT_DTM, OUTPUT_RESIDUALS, OUTPUT_FILTER_HTML, OUTPUT_DTM_HTML,
               OUTPUT_HTML)

    def name(self):
        return "lidartodtm"

    def displayName(self):  # noqa: N802
        return self.tr("LiDAR to DTM with accuracy")

    def tags(self):
        return self.tr("lidar,ground,filter,dtm,dem,idw,accuracy,rmse,check points,"
                       "chain,all-or-nothing").split(",")

    def shortHelpString(self):  # noqa: N802
        return build_help(self, self.tr(
            "Classifies the ground of a LiDAR point cloud, interpolates an IDW DTM from "
            "the ground points and measures its accuracy against check points, in one "
            "step. It writes all its outputs or none, and its results equal those of the "
            "three algorithms run one after another."),
            "INPUT=tile.laz CHECKPOINTS_CSV=gnss.csv CELL_SIZE=1 OUTPUT=classified.laz "
            "OUTPUT_DTM=dtm.tif OUTPUT_HTML=accuracy.html",
            {self.INPUT: self.tr("In a projected CRS (metres)."),
             self.POWER: self.tr("The seed paper found 3 best (RMSE 0.204 m at 62 GNSS "
                                 "points)."),
             self.CHECKPOINTS: self.tr("Give the layer or the file; duplicates and points "
                                       "outside the cloud's extent are refused before "
                                       "anything is written."),
             self.OUTPUT: self.tr("Classified by the recommended ground filter (the "
                                  "improved least-squares filter where it is not "
                                  "installed).")})

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add_las_input(self.INPUT)
        self.add_noise_params(default=ground_filter()[1].noise)
        self.add_number(self.CELL_SIZE, self.tr("DTM cell size (m)"), 1.0, minimum=0.0)
        self.add_number(self.POWER, self.tr("IDW power"), core_idw.DEFAULT_POWER, minimum=0.0)
        self.add_number(self.NEIGHBOURS, self.tr("IDW neighbours"), 12, minimum=1,
                        integer=True, advanced=True)
        self.add(QgsProcessingParameterBoolean(
            self.FILL_GAPS,
            self.tr("Fill data gaps in the DTM (interpolate far from ground points)"),
            False), advanced=True)
        self.add(QgsProcessingParameterCrs(
            self.CRS, self.tr("CRS override for a cloud without a CRS record"),
            optional=True), advanced=True)
        self.add_checkpoint_params(self.tr("Check points (CSV/TXT file: id,x,y,z)"),
                                   advanced=True)
        self.add(QgsProcessingParameterFileDestination(
            self.OUTPUT, self.tr("Classified point cloud"), LAS_OUT_FILTER))
        self.add(QgsProcessingParameterRasterDestination(self.OUTPUT_DTM, self.tr("DTM")))
        self.add(QgsProcessingParameterVectorDestination(
            self.OUTPUT_RESIDUALS, self.tr("Check-point residuals"),
            QgsProcessing.TypeVectorPoint, optional=True, createByDefault=True))
        self.add_report_output(self.OUTPUT_HTML, self.tr("DTM accuracy report"),
                               create_by_default=True)
        self.add_report_output(self.OUTPUT_FILTER_HTML, self.tr("Ground filter report"))
        self.add_report_output(self.OUTPUT_DTM_HTML, self.tr("DTM report"))
        self.add_report_language()
        self.addOutput(QgsProcessingOutputNumber("N_GROUND", self.tr("Ground points")))
        for name, _, label in NUMBERS:
            self.addOutput(QgsProcessingOutputNumber(name, self.tr(label)))  # i18n: noop-list

    # ------------------------------------------------------------------ checks

    def resolve_crs(self, parameters, context, info) -> str:
        """The DTM's CRS: the CRS parameter, else the cloud's; refused if geographic."""
        given = self.parameterAsCrs(parameters, self.CRS, context)
        crs = _crs_string(given) if given is not None and given.isValid() else info.crs
        if not crs:
            raise InputError(self.tr(
                "The point cloud has no CRS record and no CRS was given; set the CRS "
                "parameter (e.g. EPSG:32632). No output was written."))
        check_projected(crs=crs, what=T("The point cloud {path}", path=info.path))
        return crs

    def check_extent(self, info, ids, x, y) -> None:
        """Refuse check points none of which lies within the cloud's extent."""
        (x0, y0, _), (x1, y1, _) = info.mins, info.maxs
        inside = (x >= x0) & (x <= x1) & (y >= y0) & (y <= y1)
        if not inside.any():
            raise InputError(self.tr(
                "None of the {n} check points lies within the point cloud's extent "
                "(x {x0:.1f}–{x1:.1f}, y {y0:.1f}–{y1:.1f}); are they in another CRS? "
                "No output was written.").format(n=len(ids), x0=x0, x1=x1, y0=y0, y1=y1))

    def input_files(self, parameters, context, src) -> dict:
        """Every file read: the cloud, the check point file and the layer's file."""
        return {self.INPUT: src, **self.checkpoint_files(parameters, context)}

    # ------------------------------------------------------------------ run
    def process(self, parameters, context, feedback):
        src = self.las_input_path(parameters, context, self.INPUT)
        if not src:
            raise InputError(self.tr("Choose the point cloud (a .las or .laz file)."))
        mon = Monitor(**self.core_callbacks(feedback))
        lang = self.report_lang(parameters, context)
        with self.output_contract(parameters, context, self.OUTPUTS,
                                  self.input_files(parameters, context, src)) as out:
            for name in (self.OUTPUT, self.OUTPUT_DTM):
                if not out.requested(name):
                    raise InputError(self.tr("Choose an output file for {}.").format(
                        self.parameterDefinition(name).description()))
            _check_tif(out.final(self.OUTPUT_DTM))
            # 1. everything that can be checked before the first write
            info = las_info(src)
            if info.count == 0:           # before the check points are set against it
                raise InputError("{path} holds no points (empty point cloud).", path=src)
            crs = self.resolve_crs(parameters, context, info)
            qcrs = QgsCoordinateReferenceSystem(crs)
            if not qcrs.isValid():
                qcrs = QgsCoordinateReferenceSystem.fromWkt(crs)
            ids, x, y, z = self.read_points(parameters, context, qcrs, feedback)
            core_acc.check_points_not_degrees(
                x, y, (info.mins[0], info.maxs[0], info.mins[1], info.maxs[1]),
                crs_label=qcrs.authid() or qcrs.description())
            self.units = info.units if info.crs else crs_units(crs)
            self.log_units(feedback, self.units)
            core_acc.check_duplicates(ids, x, y, tolerance=0.001 / self.units.h)
            self.check_extent(info, ids, x, y)
            # 2. ground filter (writes the classified cloud to its contract temporary)
            run = self.classify(parameters, context, src, out, lang, mon.sub(0.0, 0.7))
            # 3. IDW DTM from the classified cloud's ground points
            dtm, grid = self.idw(parameters, context, run, out, crs, lang, mon.sub(0.7, 0.9))
            # 4. accuracy of the DTM just written
            results = self.accuracy(parameters, context, out, (ids, x, y, z), qcrs, lang)
            mon.check()
        results["N_GROUND"] = run.n_ground
        results.update({name: out.final(name) for name in self.OUTPUTS
                        if out.final(name)})
        self.load_cloud_on_completion(context, results[self.OUTPUT],
                                      self.tr("Classified point cloud"), self.OUTPUT)
        feedback.setProgress(100)
        return results

    def classify(self, parameters, context, src, out, lang, mon):
        """Step 1: the ground filter through the pipeline, onto the contract temps."""
        algorithm, selection, _ = ground_filter()
        selection = replace(
            selection, noise=self.parameterAsBool(parameters, self.NOISE, context),
            noise_radius=self.parameterAsDouble(parameters, self.NOISE_RADIUS, context),
            noise_threshold=self.parameterAsDouble(parameters, self.NOISE_THRESHOLD, context))
        report = (out.path(self.OUTPUT_FILTER_HTML)
                  if out.requested(self.OUTPUT_FILTER_HTML) else None)
        outputs = FilterOutputs(
            cloud=out.path(self.OUTPUT), report=report,
            names={"cloud": self.OUTPUT, "report": self.OUTPUT_FILTER_HTML}, lang=lang,
            render=lambda rep: self.render_report(rep, parameters, context))
        return classify_file(src, algorithm, outputs, mon, selection=selection)

    def idw(self, parameters, context, run, out, crs, lang, mon):
        """Step 2: the IDW DTM (idwdtm's core runner) of the classified points.

        The ground points come from the points the filter step decoded (equal, bit for
        bit, to reading the classified cloud again), so the input is decoded once.
        """
        cell = self.parameterAsDouble(parameters, self.CELL_SIZE, context)
        if not cell > 0:
            raise InputError(self.tr("Cell size must be > 0 (metres); give e.g. 1.0."))
        g = run.classes == 2
        if not g.any():
            raise InputError(self.tr("The ground filter found no ground point; no DTM can "
                                     "be interpolated. No output was written."))
        pd = run.points
        pts = ClassPoints(pd.x[g], pd.y[g], pd.z[g], pd.info, (2,), run.n_points,
                          run.counts(), units=self.units)
        grid = grid_from_points(pts.x, pts.y, cell, crs=crs)
        method = core_dtm.IdwMethod(core_dtm.IdwOptions(
            power=self.parameterAsDouble(parameters, self.POWER, context),
            neighbours=self.parameterAsInt(parameters, self.NEIGHBOURS, context)))
        dtm_run = core_dtm.make_dtm(out.final(self.OUTPUT), pts, grid, method,
                                    fill=self.parameterAsBool(parameters, self.FILL_GAPS,
                                                              context), monitor=mon)
        core_dtm.write_dtm(dtm_run, out.path(self.OUTPUT_DTM))
        if out.requested(self.OUTPUT_DTM_HTML):
            rep = core_dtm.dtm_report(dtm_run, lang=lang)
            out.write_text(self.OUTPUT_DTM_HTML, self.render_report(rep, parameters, context))
        return dtm_run.outcome.z, grid

    def accuracy(self, parameters, context, out, points, qcrs, lang) -> dict:
        """Step 3: dtmaccuracy's core calls on the DTM just written."""
        ids, x, y, z = points
        method = core_acc.METHODS[self.parameterAsEnum(parameters, self.METHOD, context)]
        r = read_raster(out.path(self.OUTPUT_DTM), 1)
        v = self.units.v     # heights in metres (DEVELOPERS.md, Units)
        res = core_acc.dtm_accuracy(r.masked() * v, r.geotransform, x, y, z * v,
                                    method=method)
        summary = res.summary()
        if out.requested(self.OUTPUT_RESIDUALS):
            DtmAccuracyAlgorithm.write_residuals(out.path(self.OUTPUT_RESIDUALS), res, ids,
                                                 qcrs)
        if out.requested(self.OUTPUT_HTML):
            rep = terrain_report.accuracy_report(
                res, ids, r.masked() * v, r.geotransform,
                dtm_name=os.path.basename(out.final(self.OUTPUT_DTM)),
                crs_label=qcrs.authid() or qcrs.description() or "unknown",
                tr=translator(lang), units=self.units)
            out.write_text(self.OUTPUT_HTML, self.render_report(rep, parameters, context))
        return {name: summary[key] for name, key, _ in NUMBERS}

"""Process a LiDAR tile catalog with buffers on Dask (Processing algorithm)."""
from __future__ import annotations

import numpy as np
from qgis.core import (
    QgsProcessing,
    QgsProcessingException,
    QgsProcessingOutputNumber,
    QgsProcessingOutputRasterLayer,
    QgsProcessingParameterBoolean,
    QgsProcessingParameterEnum,
    QgsProcessingParameterFolderDestination,
    QgsProcessingParameterMultipleLayers,
    QgsProcessingParameterString,
)

from ..core.io.contract import Terminated
from ..core.lidar import catalog as core_cat
from ..core.lidar.catalog_report import catalog_report, catalog_warnings
from ..core.progress import Cancelled
from .base import GeomaticsAlgorithm
from .helptext import build_help


class CatalogAlgorithm(GeomaticsAlgorithm):
    """Ground filter + DTM over a folder of tiles, chunk by chunk with buffers."""

    GROUP = "lidarfiltering"
    REQUIRES = ("catalog",)

    INPUT = "INPUT"
    GROUND_FILTER = "GROUND_FILTER"
    DTM_METHOD = "DTM_METHOD"
    CELL_SIZE = "CELL_SIZE"
    BUFFER = "BUFFER"
    CHUNK_SIZE = "CHUNK_SIZE"
    WORKERS = "WORKERS"
    SCHEDULER = "SCHEDULER"
    COG = "COG"
    SKIP_UNREADABLE = "SKIP_UNREADABLE"
    OUTPUT_FOLDER = "OUTPUT_FOLDER"
    OUTPUT_HTML = "OUTPUT_HTML"
    OUTPUT_VRT = "OUTPUT_VRT"
    N_TILES = "N_TILES"
    N_FAILED = "N_FAILED"
    POINTS_PER_SECOND = "POINTS_PER_SECOND"

    def name(self) -> str:
        return "catalog"

    def displayName(self) -> str:  # noqa: N802
        return self.tr("Process a LiDAR tile catalog")

    def shortDescription(self) -> str:  # noqa: N802
        return self.tr("Ground filter and DTM over a whole folder of LAS/LAZ tiles, in "
                       "parallel, without seams.")

    def _filter_labels(self) -> dict:
        return {"keep": self.tr("Keep the classes already in the files"),
                "lsq_faithful": self.tr("LSQ surfaces, faithful (the paper)"),
                "lsq_improved": self.tr("LSQ surfaces, improved (ours)"),
                "slope_exact": self.tr("Slope filter, exact (Vosselman 2000)"),
                "slope_adaptive": self.tr("Slope filter, terrain-adaptive"),
                "groundfilter": self.tr("Ground filter (recommended)"),
                "ptd": self.tr("Ground filter (progressive TIN densification)")}

    def _dtm_labels(self) -> dict:
        return {"idw": self.tr("IDW"), "kriging": self.tr("Kriging"), "tin": self.tr("TIN")}

    def shortHelpString(self) -> str:  # noqa: N802
        return build_help(self, self.tr(
            "Classifies ground and builds a DTM for every tile of a LiDAR project, each "
            "tile read with a buffer of its neighbours' points so that results have no "
            "seams. Tiles run in parallel on Dask, locally or on a cluster; a rerun skips "
            "finished tiles."),
            "INPUT=/data/tiles GROUND_FILTER=2 BUFFER=100 CELL_SIZE=1 "
            "OUTPUT_FOLDER=/data/out OUTPUT_HTML=catalog.html",
            {self.INPUT: self.tr("All tiles must share one CRS. Tiles without points are "
                                 "left out; tiles without ground within reach (a lake, the "
                                 "sea) get a nodata DTM. Both are named in the log and the "
                                 "report."),
             self.GROUND_FILTER: self.tr("The first choice keeps the classes already in "
                                         "the files."),
             self.DTM_METHOD: self.tr("Cells are nodata where a DTM of all the tiles as one "
                                      "file would leave them empty: farther than five mean "
                                      "ground spacings from ground (TIN: triangles with an "
                                      "edge over twice that), derived from the whole catalog "
                                      "once every tile is done."),
             self.BUFFER: self.tr("Must exceed the filter's reach (about 100 m for the "
                                  "recommended filter, 240 m for the improved LSQ, 120 m "
                                  "for the terrain-adaptive slope filter) and the DTM "
                                  "search distance."),
             self.CHUNK_SIZE: self.tr("0 processes whole tiles; a size (a multiple of "
                                      "the cell size) cuts the catalog into squares "
                                      "read from the tiles they overlap."),
             self.SCHEDULER: self.tr("e.g. tcp://host:8786."),
             self.SKIP_UNREADABLE: self.tr("Off: a damaged or truncated tile stops the run "
                                           "before anything is written, naming every such "
                                           "tile. On: those tiles are left out (named in "
                                           "the log) and their neighbours get no buffer "
                                           "points from them."),
             self.OUTPUT_FOLDER: self.tr("Must not hold the input tiles; receives the "
                                         "classified tiles, one DTM per tile and a VRT "
                                         "mosaic."),
             self.OUTPUT_HTML: self.tr("A map of the tiles by status, and time and points "
                                       "per second per worker.")})

    def initAlgorithm(self, config=None):  # noqa: N802
        # a file list with "Add File(s)…" / "Add Directory…" in the dialog; on the
        # command line INPUT=folder, INPUT=a.laz;b.laz, INPUT=x.vpc or INPUT repeated
        self.add(QgsProcessingParameterMultipleLayers(
            self.INPUT, self.tr("Tiles: LAS/LAZ files, folders or a .vpc"),
            QgsProcessing.TypeFile))
        fl = self._filter_labels()
        keys = list(core_cat.GROUND_FILTERS)
        self.add(QgsProcessingParameterEnum(
            self.GROUND_FILTER, self.tr("Ground filter"),
            [fl.get(k, core_cat.GROUND_FILTERS[k].label) for k in keys],
            defaultValue=keys.index(core_cat.default_ground_filter())))
        dl = self._dtm_labels()
        self.add(QgsProcessingParameterEnum(
            self.DTM_METHOD, self.tr("DTM method"),
            [dl.get(k, core_cat.DTM_METHODS[k].label) for k in core_cat.DTM_METHODS],
            defaultValue=0))
        self.add_number(self.CELL_SIZE, self.tr("DTM cell size (m)"), 1.0, minimum=0.0)
        self.add_number(self.BUFFER, self.tr("Buffer around each tile (m)"), 100.0,
                        minimum=0.0)
        self.add_number(self.CHUNK_SIZE, self.tr("Chunk size (m, 0 = the tiles)"), 0.0,
                        minimum=0.0)
        self.add_number(self.WORKERS, self.tr("Worker processes (0 = one per core)"), 0,
                        minimum=0, integer=True)
        self.add(QgsProcessingParameterString(
            self.SCHEDULER, self.tr("Dask scheduler address (empty = local)"), "",
            optional=True), advanced=True)
        self.add(QgsProcessingParameterBoolean(
            self.COG, self.tr("Also write one Cloud-Optimized GeoTIFF"), False))
        self.add(QgsProcessingParameterBoolean(
            self.SKIP_UNREADABLE, self.tr("Skip unreadable tiles"), False), advanced=True)
        self.add_report_language()
        self.add(QgsProcessingParameterFolderDestination(
            self.OUTPUT_FOLDER, self.tr("Output folder")))
        self.add_report_output(self.OUTPUT_HTML, self.tr("Tile catalog report"),
                               create_by_default=True)
        self.addOutput(QgsProcessingOutputRasterLayer(
            self.OUTPUT_VRT, self.tr("DTM mosaic (VRT)")))
        for name, label in ((self.N_TILES, self.tr("Tiles")),
                            (self.N_FAILED, self.tr("Failed tiles")),
                            (self.POINTS_PER_SECOND, self.tr("Points per second"))):
            self.addOutput(QgsProcessingOutputNumber(name, label))

    def tiles_source(self, parameters, context) -> list:
        """The INPUT entries (files, folders, globs, .vpc), ';'-separated ones split."""
        items = self.parameterAsFileList(parameters, self.INPUT, context)
        return [s.strip() for item in items for s in str(item).split(";") if s.strip()]

    def log_chunk(self, feedback, done: list):
        """A log line per tile as it finishes (``done`` collects the finished keys)."""
        def log(stats):
            key, status = stats.get("key"), stats.get("status")
            if status == "failed":
                feedback.reportError(self.tr("Tile {0} failed: {1}").format(
                    key, stats.get("error")), False)
                return
            done.append(key)
            if status == "skipped":
                feedback.pushInfo(self.tr("Tile {key}: finished by an earlier run, "
                                          "kept.").format(key=key))
            elif status == "empty":
                feedback.pushInfo(self.tr("Tile {key}: no point of its own, no DTM.")
                                  .format(key=key))
            else:
                feedback.pushInfo(self.tr(
                    "Tile {key} done: {points} points, {ground} ground, {seconds:.1f} s.")
                    .format(key=key, points=stats.get("points", 0),
                            ground=stats.get("ground", 0),
                            seconds=float(stats.get("seconds") or 0.0)))
        return log

    def process(self, parameters, context, feedback) -> dict:
        source = self.tiles_source(parameters, context)
        folder = self.parameterAsString(parameters, self.OUTPUT_FOLDER, context)
        fkey = list(core_cat.GROUND_FILTERS)[
            self.parameterAsEnum(parameters, self.GROUND_FILTER, context)]
        dkey = list(core_cat.DTM_METHODS)[
            self.parameterAsEnum(parameters, self.DTM_METHOD, context)]
        workers = self.parameterAsInt(parameters, self.WORKERS, context)
        cat = core_cat.Catalog.open(
            source, skip_unreadable=self.parameterAsBool(parameters, self.SKIP_UNREADABLE,
                                                         context))
        for path, reason in cat.unreadable.items():
            feedback.reportError(self.tr("Tile {path} skipped: {reason}").format(
                path=path, reason=self.input_error_message(reason)), False)
        done = []
        with self.output_contract(parameters, context, [self.OUTPUT_HTML],
                                  inputs={"INPUT": cat.paths}) as out:
            try:
                res = self.run_tiles(cat, folder, fkey, dkey, workers, parameters, context,
                               feedback, done)
            except (Cancelled, Terminated) as exc:
                kept = core_cat.finished_chunks(folder)
                if not kept:
                    raise
                if isinstance(exc, Terminated):
                    message = self.tr(
                        "Terminated. {n} finished tile(s) are kept in {folder}: run again "
                        "with the same settings to resume; unfinished tiles left nothing.")
                else:
                    message = self.tr(
                        "Cancelled by the user. {n} finished tile(s) are kept in {folder}: "
                        "run again with the same settings to resume; unfinished tiles left "
                        "nothing.")
                message = message.format(n=len(kept), folder=folder)
                if core_cat.has_canopy(fkey):   # kept at their own canopy scale, some may be
                    message += " " + self.tr(   # re-run: the catalog's is known at the end
                        "A kept tile whose canopy scale differs from the whole catalog's is "
                        "classified again by the resume.")
                raise QgsProcessingException(message) from None
            again = res.settings.get("canopy_reruns") or []
            if again:           # the extra time: tiles whose own canopy scale disagreed
                feedback.pushInfo(self.tr(
                    "{n} tile(s) classified again at the canopy scale of the whole catalog: "
                    "{keys}.").format(n=len(again), keys=", ".join(again)))
            for warning in catalog_warnings(res):
                feedback.pushWarning(self.core_message(warning))
            if out.requested(self.OUTPUT_HTML):
                report = catalog_report(res, np.asarray(res.settings["bounds"]),
                                        lang=self.report_lang(parameters, context))
                out.write_text(self.OUTPUT_HTML, self.render_report(report, parameters,
                                                                    context))
        if res.vrt:
            self.load_layer_on_completion(context, res.vrt, self.tr("DTM mosaic (VRT)"),
                                          self.OUTPUT_VRT, "elevation")
        return {self.OUTPUT_FOLDER: folder, self.OUTPUT_HTML: out.final(self.OUTPUT_HTML),
                self.OUTPUT_VRT: res.vrt,
                self.N_TILES: len(res.chunks), self.N_FAILED: len(res.failed),
                self.POINTS_PER_SECOND: res.points_per_second}

    def run_tiles(self, cat, folder, fkey, dkey, workers, parameters, context, feedback,
                  done):
        """run_catalog with the parameters, a log line per tile."""
        return core_cat.run_catalog(
            cat, folder, ground_filter=fkey, dtm_method=dkey,
            cell_size=self.parameterAsDouble(parameters, self.CELL_SIZE, context),
            buffer=self.parameterAsDouble(parameters, self.BUFFER, context),
            chunk_size=self.parameterAsDouble(parameters, self.CHUNK_SIZE, context),
            workers=workers or None,
            scheduler=self.parameterAsString(parameters, self.SCHEDULER, context).strip(),
            cog=self.parameterAsBool(parameters, self.COG, context),
            on_chunk=self.log_chunk(feedback, done), **self.core_callbacks(feedback))

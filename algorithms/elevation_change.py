"""Elevation change between two epochs (two clouds or two rasters), core.terrain.change."""
from __future__ import annotations

import os

import numpy as np
from qgis.core import (
    QgsProcessing,
    QgsProcessingOutputNumber,
    QgsProcessingParameterFile,
    QgsProcessingParameterRasterDestination,
    QgsProcessingParameterRasterLayer,
    QgsProcessingParameterString,
    QgsProcessingParameterVectorDestination,
    QgsProcessingParameterVectorLayer,
)

from ..core.errors import InputError
from ..core.io.crs import crs_label, same_crs
from ..core.io.las import las_info
from ..core.io.points import parse_classes, read_class_points, write_grid
from ..core.io.raster import read_raster, read_raster_on_grid
from ..core.io.units import raster_units
from ..core.io.vector import write_label_polygons
from ..core.lidar.qa import check_projected
from ..core.terrain import change as core_change
from ..core.terrain.accuracy import OK as USED
from ..core.terrain.accuracy import STATUS_NAMES
from ..core.terrain.grid import grid_from_extent, grid_like
from ..core.terrain.tin import tin_grid
from .base import GeomaticsAlgorithm
from .helptext import build_help

EPOCH_FILTER = ("Point clouds or rasters (*.las *.laz *.LAS *.LAZ *.tif *.tiff *.TIF "
                "*.TIFF)")
FIELDS = [("id", "int"), ("kind", "str"), ("area_m2", "float"),
          ("mean_change_m", "float"), ("volume_m3", "float")]


def _is_las(path: str) -> bool:
    return os.path.splitext(path)[1].lower() in (".las", ".laz")


def check_two_epochs(before: str, after: str) -> None:
    """Refuse the same file (or two byte-identical files) as both epochs."""
    same = os.path.exists(before) and os.path.exists(after) and os.path.samefile(before,
                                                                                 after)
    if not same and os.path.getsize(before) == os.path.getsize(after):
        import hashlib

        def digest(p):
            h = hashlib.sha256()
            with open(p, "rb") as fh:
                for block in iter(lambda: fh.read(1 << 20), b""):
                    h.update(block)
            return h.digest()
        same = digest(before) == digest(after)
    if same:
        raise InputError("Both epochs are the same data ({before} and {after}); the change "
                         "would be zero everywhere. Give the surveys of two dates.",
                         before=before, after=after)


def check_same_crs(crs_a, crs_b, path_a, path_b, units_a=None, units_b=None) -> None:
    """Refuse two epochs whose CRSs (or linear units) differ in meaning, both named."""
    if crs_a and crs_b and not same_crs(crs_a, crs_b):
        raise InputError("The two epochs are in different CRSs: {a} is in {crs_a}, {b} in "
                         "{crs_b}. Reproject one into the other's CRS first.",
                         a=os.path.basename(path_a), crs_a=crs_label(crs_a),
                         b=os.path.basename(path_b), crs_b=crs_label(crs_b))
    if units_a is not None and units_b is not None and units_a != units_b:
        raise InputError("The two epochs have different linear units (horizontal / "
                         "vertical): {a} is in {ua}, {b} in {ub}. Convert one into the "
                         "other's units first.",
                         a=os.path.basename(path_a), ua=units_a.symbols,
                         b=os.path.basename(path_b), ub=units_b.symbols)


class ElevationChangeAlgorithm(GeomaticsAlgorithm):
    """Difference raster, LoD95 and cut/fill polygons of two epochs."""

    GROUP = "terrain"
    INPUT = "INPUT"
    INPUT_AFTER = "INPUT_AFTER"
    RASTER = "RASTER"
    RASTER_AFTER = "RASTER_AFTER"
    SIGMA1 = "SIGMA1"
    SIGMA2 = "SIGMA2"
    RESIDUALS1 = "RESIDUALS1"
    RESIDUALS2 = "RESIDUALS2"
    CLASSES = "CLASSES"
    CELL_SIZE = "CELL_SIZE"
    MIN_AREA = "MIN_AREA"
    OUTPUT = "OUTPUT"
    OUTPUT_POLYGONS = "OUTPUT_POLYGONS"
    OUTPUT_HTML = "OUTPUT_HTML"
    OUTPUT_STYLES = {"OUTPUT": "change", "OUTPUT_POLYGONS": "change_polygons"}

    def name(self):
        return "elevationchange"

    def displayName(self):  # noqa: N802
        return self.tr("Elevation change between two epochs (cut / fill)")

    def shortDescription(self):  # noqa: N802
        return self.tr("Difference of two surveys with a 95 % level of detection, and "
                       "cut and fill polygons with volumes.")

    def tags(self):
        return self.tr("change,difference,dod,cut,fill,volume,epochs,lod,monitoring,"
                       "lidar,dtm,dsm").split(",")

    def shortHelpString(self):  # noqa: N802
        return build_help(self, self.tr(
            "Subtracts an earlier surface from a later one (two rasters on one grid, or two "
            "LAS/LAZ clouds gridded by TIN) and keeps the change beyond the level of "
            "detection LoD95 = 1.96·√(σ₁² + σ₂²). Significant cells form cut and fill "
            "polygons with area, mean change and volume."),
            "INPUT=dtm_2021.tif INPUT_AFTER=dtm_2024.tif SIGMA1=0.08 SIGMA2=0.06 "
            "OUTPUT=change.tif OUTPUT_POLYGONS=change.gpkg",
            {self.INPUT: self.tr("A GeoTIFF, or a LAS/LAZ cloud in the same CRS as the "
                                 "other epoch."),
             self.SIGMA1: self.tr("The vertical accuracy of the epoch, e.g. the RMSE of "
                                  "the DTM accuracy tool."),
             self.RESIDUALS1: self.tr("The residual layer of a DTM accuracy run on this "
                                      "epoch: σ becomes the RMSE of its residuals (status "
                                      "used) and the typed σ is ignored."),
             self.INPUT_AFTER: self.tr("A raster on another grid in the same CRS is "
                                       "resampled (bilinear) onto the first one's grid."),
             self.RASTER: self.tr("A raster layer of the project or a raster file; give "
                                  "each epoch once, as a file or as a raster layer."),
             self.MIN_AREA: self.tr("Smaller regions are dropped: noise alone exceeds the "
                                    "LoD in 5 % of cells."),
             self.OUTPUT: self.tr("GeoTIFF of after − before (m)."),
             self.OUTPUT_POLYGONS: self.tr("GeoPackage with kind (cut / fill), area, mean "
                                           "change and volume.")})

    def initAlgorithm(self, config=None):  # noqa: N802
        for name, label in ((self.INPUT, self.tr("Before (raster or point cloud)")),
                            (self.INPUT_AFTER, self.tr("After (raster or point cloud)"))):
            self.add(QgsProcessingParameterFile(
                name, label, behavior=QgsProcessingParameterFile.File,
                fileFilter=EPOCH_FILTER, optional=True))
        for name, label in ((self.RASTER, self.tr("Before as a raster layer (instead of a "
                                                  "file)")),
                            (self.RASTER_AFTER, self.tr("After as a raster layer (instead "
                                                        "of a file)"))):
            self.add(QgsProcessingParameterRasterLayer(name, label, optional=True))
        self.add_number(self.SIGMA1, self.tr("Vertical accuracy before σ₁ (m)"), 0.1,
                        minimum=0.0)
        self.add_number(self.SIGMA2, self.tr("Vertical accuracy after σ₂ (m)"), 0.1,
                        minimum=0.0)
        for name, label in ((self.RESIDUALS1, self.tr("σ₁ from a DTM accuracy run "
                                                       "(residual layer, optional)")),
                            (self.RESIDUALS2, self.tr("σ₂ from a DTM accuracy run "
                                                       "(residual layer, optional)"))):
            self.add(QgsProcessingParameterVectorLayer(
                name, label, [QgsProcessing.TypeVectorPoint], optional=True))
        self.add(QgsProcessingParameterString(
            self.CLASSES, self.tr("Classes used (clouds)"), defaultValue="2", optional=True),
            advanced=True)
        self.add_number(self.CELL_SIZE, self.tr("Cell size (m, clouds)"), 1.0, minimum=0.0,
                        advanced=True)
        self.add_number(self.MIN_AREA, self.tr("Minimum region area (m², 0 = 8 cells)"),
                        0.0, minimum=0.0)
        self.add(QgsProcessingParameterRasterDestination(self.OUTPUT,
                                                         self.tr("Difference")))
        self.add(QgsProcessingParameterVectorDestination(
            self.OUTPUT_POLYGONS, self.tr("Change polygons"), optional=True,
            createByDefault=True))
        self.add_report_output(self.OUTPUT_HTML, self.tr("Elevation change report"))
        self.add_report_language()
        for name, label in (("LOD", self.tr("Level of detection LoD95 (m)")),
                            ("FILL_VOLUME", self.tr("Fill volume above the LoD (m³)")),
                            ("CUT_VOLUME", self.tr("Cut volume above the LoD (m³)")),
                            ("N_REGIONS", self.tr("Change regions"))):
            self.addOutput(QgsProcessingOutputNumber(name, label))

    def epochs(self, before, after, parameters, context, feedback):
        """Both surfaces on one grid: rasters as they are, clouds by TIN."""
        if _is_las(before) != _is_las(after):
            raise InputError("Give two rasters or two point clouds, not one of each.")
        check_two_epochs(before, after)
        if not _is_las(before):
            self.units = raster_units(before)
            return self.raster_epochs(before, after, feedback)
        classes = parse_classes(self.parameterAsString(parameters, self.CLASSES, context))
        cell = self.parameterAsDouble(parameters, self.CELL_SIZE, context)
        if not cell > 0:
            raise InputError("Cell size must be > 0 (m); give e.g. 1.0.")
        ia, ib = las_info(before), las_info(after)
        check_same_crs(ia.crs, ib.crs, before, after, ia.units, ib.units)
        self.units = ia.units
        cell = cell / ia.units.h        # the grid is in the clouds' own units
        box = (max(ia.mins[0], ib.mins[0]), min(ia.maxs[0], ib.maxs[0]),
               max(ia.mins[1], ib.mins[1]), min(ia.maxs[1], ib.maxs[1]))
        if box[0] >= box[1] or box[2] >= box[3]:
            raise InputError("The two point clouds do not overlap; check their CRS.")
        grid = grid_from_extent(box, cell, crs=ia.crs or ib.crs)
        cb = self.core_callbacks(feedback)
        out = []
        for path in (before, after):
            pts = read_class_points(path, classes, extent=box, cancel=cb["cancel"])
            check_projected(pts.x, pts.y)
            out.append(tin_grid(pts.x, pts.y, pts.z, grid, cancel=cb["cancel"]).z)
        return out[0], out[1], grid

    def raster_epochs(self, before, after, feedback):
        """Both rasters on the first one's grid; the second resampled when it differs."""
        ra, rb = read_raster(before), read_raster(after)
        check_same_crs(ra.crs, rb.crs, before, after, raster_units(before),
                       raster_units(after))
        if bool(ra.crs) != bool(rb.crs):    # nothing to compare: say which one is taken
            feedback.pushWarning(self.tr(
                "{0} has no CRS: it is taken to be in the CRS of {1} ({2}); check that "
                "it is.").format(os.path.basename(after if ra.crs else before),
                                 os.path.basename(before if ra.crs else after),
                                 crs_label(ra.crs or rb.crs)))
        if abs(ra.geotransform[2]) > 0 or abs(ra.geotransform[4]) > 0:
            raise InputError("The first raster is rotated; warp it north-up first.")
        grid = grid_like(ra.geotransform, ra.shape, crs=ra.crs)
        if ra.shape == rb.shape and np.abs(np.subtract(ra.geotransform,
                                                       rb.geotransform)).max() <= 1e-6:
            return ra.masked(), rb.masked(), grid
        feedback.pushInfo(self.tr(
            "The second raster ({0} × {1} cells of {2:g} m) is resampled (bilinear) onto "
            "the first one's grid ({3} × {4} cells of {5:g} m).").format(
                rb.shape[1], rb.shape[0], abs(rb.geotransform[1]), ra.shape[1],
                ra.shape[0], abs(ra.geotransform[1])))
        rb = read_raster_on_grid(after, ra.geotransform, ra.shape, crs=ra.crs or None)
        if not np.isfinite(rb.data).any():
            raise InputError("The two rasters do not overlap; check their extents and CRS.")
        return ra.masked(), rb.data, grid

    def sigmas(self, parameters, context, feedback):
        """σ₁, σ₂ typed, or the RMSE of a DTM accuracy run's residual layer; its path."""
        out, paths = [], {}
        for sig, res in ((self.SIGMA1, self.RESIDUALS1), (self.SIGMA2, self.RESIDUALS2)):
            layer = self.parameterAsVectorLayer(parameters, res, context)
            if layer is None:
                out.append(self.parameterAsDouble(parameters, sig, context))
                continue
            names = layer.fields().names()
            if "error" not in names:
                raise InputError("{layer} has no 'error' field: give the residual layer "
                                 "written by the DTM accuracy tool.", layer=layer.name())
            ok = "status" in names
            errors = [f["error"] for f in layer.getFeatures()
                      if not ok or str(f["status"]) == STATUS_NAMES[USED]]
            errors = [e for e in errors if isinstance(e, (int, float))]
            value = core_change.sigma_from_residuals(errors, layer.name())
            feedback.pushInfo(self.tr("{0} = {1:.4f} m: RMSE of {2} check-point residuals "
                                      "of {3}").format(sig, value, len(errors),
                                                       layer.name()))
            out.append(value)
            paths[res] = layer.source().split("|")[0]
        return out[0], out[1], paths

    def epoch_paths(self, parameters, context):
        """The two epochs' paths: each from its file parameter or its raster layer."""
        out = []
        for fname, rname in ((self.INPUT, self.RASTER),
                             (self.INPUT_AFTER, self.RASTER_AFTER)):
            path = self.parameterAsFile(parameters, fname, context)
            layer = self.parameterAsRasterLayer(parameters, rname, context)
            if path and layer is not None:
                raise InputError("An epoch is given twice ({file} and {layer}); give it "
                                 "once, as a file or as a raster layer.", file=fname,
                                 layer=rname)
            if layer is not None:
                path = layer.source()
                if not os.path.isfile(path):
                    raise InputError("The raster layer {layer} is not a local file "
                                     "({path}); save it as a GeoTIFF first.", layer=rname,
                                     path=path)
            if not path:
                raise InputError("An epoch is missing: give {file} (a raster or a point "
                                 "cloud file) or {layer} (a raster layer).", file=fname,
                                 layer=rname)
            out.append(path)
        return out

    def process(self, parameters, context, feedback):
        before, after = self.epoch_paths(parameters, context)
        s1, s2, res_paths = self.sigmas(parameters, context, feedback)
        min_area = self.parameterAsDouble(parameters, self.MIN_AREA, context)
        names = [self.OUTPUT, self.OUTPUT_POLYGONS, self.OUTPUT_HTML]
        with self.output_contract(parameters, context, names,
                                  inputs={self.INPUT: before, self.INPUT_AFTER: after,
                                          **res_paths}) as out:
            a, b, grid = self.epochs(before, after, parameters, context, feedback)
            # heights, areas and volumes in metres (DEVELOPERS.md, Units); the grid and
            # the difference raster stay in the data's own units
            u = self.units
            self.log_units(feedback, u)
            res = core_change.elevation_change(a * u.v, b * u.v, grid.cell * u.h,
                                               sigma1=s1, sigma2=s2, min_area=min_area,
                                               **self.core_callbacks(feedback))
            write_grid(out.path(self.OUTPUT), res.diff / u.v, grid,
                       band_name="after - before", units=u, in_data_units=True,
                       metadata={"lod95": f"{res.lod:.4f}"})
            if out.requested(self.OUTPUT_POLYGONS):
                recs = {r["id"]: {"id": r["id"], "kind": r["kind"], "area_m2": r["area"],
                                  "mean_change_m": r["mean_change"],
                                  "volume_m3": r["volume"]} for r in res.regions}
                write_label_polygons(out.path(self.OUTPUT_POLYGONS), res.labels,
                                     grid.geotransform, crs=grid.crs, layer_name="change",
                                     fields=FIELDS, records=recs)
            if out.requested(self.OUTPUT_HTML):
                rep = core_change.change_report(
                    res, (os.path.basename(before), os.path.basename(after)), s1, s2)
                out.write_text(self.OUTPUT_HTML, self.render_report(rep, parameters,
                                                                    context))
        results = {n: out.final(n) for n in names if out.requested(n)}
        results.update(LOD=res.lod, FILL_VOLUME=res.fill_volume, CUT_VOLUME=res.cut_volume,
                       N_REGIONS=len(res.regions))
        return results

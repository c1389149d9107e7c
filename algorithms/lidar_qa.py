"""Point density and quality report with parameter advice (core.lidar.qa)."""
from __future__ import annotations

import os

from qgis.core import (
    QgsProcessingOutputNumber,
    QgsProcessingParameterRasterDestination,
    QgsProcessingParameterString,
)

from ..core.io.las import las_info, read_las
from ..core.io.points import parse_classes
from ..core.io.raster import write_geotiff
from ..core.lidar import qa as core_qa
from .base import GeomaticsAlgorithm
from .helptext import build_help

BANDS = ("density of all returns (pts/m²)", "density of last returns (pts/m²)",
         "density of ground points (pts/m²)", "gap (1 = returns but no ground)")


class LidarQaAlgorithm(GeomaticsAlgorithm):
    """Density rasters, histograms, gaps, duplicates, noise, and parameter advice."""

    GROUP = "lidarfiltering"
    INPUT = "INPUT"
    CELL_SIZE = "CELL_SIZE"
    GROUND_CLASSES = "GROUND_CLASSES"
    OUTPUT = "OUTPUT"
    OUTPUT_HTML = "OUTPUT_HTML"
    OUTPUT_STYLES = {"OUTPUT": "density"}

    def name(self):
        return "lidarqa"

    def displayName(self):  # noqa: N802
        return self.tr("Point density and quality (with parameter advice)")

    def shortDescription(self):  # noqa: N802
        return self.tr("Density rasters, gaps, duplicates and noise of a cloud, and the "
                       "filter window and DTM cell its density supports.")

    def tags(self):
        return self.tr("density,quality,qa,lasinfo,gaps,duplicates,noise,scan angle,"
                       "returns,advice,lidar").split(",")

    def shortHelpString(self):  # noqa: N802
        return build_help(self, self.tr(
            "Checks a LAS/LAZ cloud before processing: density of all, last and ground "
            "returns, gaps without ground, duplicates, noise share and scan angles. It then "
            "states which settings the density supports: ground filter window, DTM cell "
            "size, LOD1 only below 1 pt/m², and the radius and tile of the slope-based and "
            "LSQ filters."),
            "INPUT=tile.laz CELL_SIZE=5 OUTPUT=density.tif OUTPUT_HTML=qa.html",
            {self.INPUT: self.tr("In a projected CRS (metres); a cloud in degrees is "
                                 "refused."),
             self.OUTPUT: self.tr("GeoTIFF with four bands: all returns, last returns, "
                                  "ground (pts/m²) and gap (1/0)."),
             self.OUTPUT_HTML: self.tr("Maps, histograms and the advice.")})

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add_las_input(self.INPUT, self.tr("Point cloud (LAS/LAZ)"))
        self.add_number(self.CELL_SIZE, self.tr("Cell size (m)"), 5.0, minimum=0.0)
        self.add(QgsProcessingParameterString(
            self.GROUND_CLASSES, self.tr("Ground classes"), defaultValue="2"), advanced=True)
        self.add(QgsProcessingParameterRasterDestination(
            self.OUTPUT, self.tr("Density rasters")))
        self.add_report_output(self.OUTPUT_HTML, self.tr("Point density and quality report"))
        self.add_report_language()
        for name, label in (("DENSITY", self.tr("Density of all returns (pts/m²)")),
                            ("GROUND_DENSITY", self.tr("Ground density (pts/m²)")),
                            ("GAP_SHARE", self.tr("Share of cells without ground")),
                            ("DUPLICATES", self.tr("Duplicate points")),
                            ("NOISE_SHARE", self.tr("Noise share")),
                            ("GROUND_WINDOW", self.tr("Ground filter window (m)")),
                            ("DTM_CELL", self.tr("Recommended DTM cell (m)"))):
            self.addOutput(QgsProcessingOutputNumber(name, label))

    def process(self, parameters, context, feedback):
        path = self.las_input_path(parameters, context, self.INPUT)
        cell = self.parameterAsDouble(parameters, self.CELL_SIZE, context)
        ground = parse_classes(self.parameterAsString(parameters, self.GROUND_CLASSES,
                                                      context)) or (2,)
        info = las_info(path)
        angle = next((d for d in ("scan_angle", "scan_angle_rank") if d in info.dimensions),
                     None)
        dims = ["classification", "return_number", "number_of_returns"] + \
            ([angle] if angle else [])
        cb = self.core_callbacks(feedback)
        with self.output_contract(parameters, context, [self.OUTPUT, self.OUTPUT_HTML],
                                  inputs={self.INPUT: path}) as out:
            pts = read_las(path, dims, **cb)
            # Densities per m² and cells in metres (DEVELOPERS.md, Units).
            units = info.units
            self.log_units(feedback, units)
            pts.x, pts.y, pts.z = units.xyz_to_metres(pts.x, pts.y, pts.z)
            sa = pts[angle] if angle else None
            if angle == "scan_angle":
                sa = sa * 0.006  # LAS 1.4: 0.006° per unit
            res = core_qa.lidar_qa(pts.x, pts.y, pts.z, pts["classification"],
                                   pts["return_number"], pts["number_of_returns"],
                                   scan_angle=sa, cell_size=cell, crs=info.crs,
                                   ground_classes=ground)
            g = res.grid
            write_geotiff(out.path(self.OUTPUT), res.density_all,
                          geotransform=tuple(v / units.h for v in g.geotransform),
                          crs=g.crs, bands=[res.density_last, res.density_ground,
                                            res.gaps.astype(float)],
                          band_names=BANDS, metadata={"source": os.path.basename(path)})
            if out.requested(self.OUTPUT_HTML):
                out.write_text(self.OUTPUT_HTML, self.render_report(
                    core_qa.qa_report(res, os.path.basename(path), units=units), parameters,
                    context))
        a = res.advice
        results = {self.OUTPUT: out.final(self.OUTPUT), "DENSITY": res.density,
                   "GROUND_DENSITY": res.ground_density, "GAP_SHARE": res.gap_share,
                   "DUPLICATES": res.n_duplicates,
                   "NOISE_SHARE": res.n_noise / max(res.n_points, 1),
                   "GROUND_WINDOW": a["ground_window"], "DTM_CELL": a["dtm_cell"]}
        if out.requested(self.OUTPUT_HTML):
            results[self.OUTPUT_HTML] = out.final(self.OUTPUT_HTML)
        return results

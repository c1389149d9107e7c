"""TIN DTM: Delaunay linear interpolation of the ground points (core.terrain.tin)."""
from __future__ import annotations

from qgis.core import (
    QgsProcessingOutputNumber,
    QgsProcessingParameterBoolean,
    QgsProcessingParameterRasterDestination,
)

from ..core.terrain import dtm as core_dtm
from .helptext import build_help
from .terrain import _GridAlgorithm


class TinDtmAlgorithm(_GridAlgorithm):
    """DTM by linear interpolation in the Delaunay triangles of the ground points."""

    MAX_EDGE = "MAX_EDGE"
    OUTPUT_STYLES = {"OUTPUT": "elevation"}

    def name(self):
        return "tindtm"

    def displayName(self):  # noqa: N802
        return self.tr("DTM by TIN (Delaunay linear interpolation)")

    def shortDescription(self):  # noqa: N802
        return self.tr("Terrain raster from the planes of the ground points' Delaunay "
                       "triangles, gaps left empty.")

    def tags(self):
        return self.tr("dtm,dem,tin,delaunay,triangulation,linear,gdal_grid,blast2dem,"
                       "lidar,ground,raster").split(",")

    def report_label(self):
        return self.tr("TIN DTM report")

    def shortHelpString(self):  # noqa: N802
        return build_help(self, self.tr(
            "Triangulates the ground points of a LAS/LAZ file (Delaunay) and gives every "
            "cell centre the height of the plane of its triangle, as <code>gdal_grid -a "
            "linear</code> does. Triangles with an edge longer than the maximum are "
            "dropped, so gaps under buildings or water stay nodata unless you fill them."),
            "INPUT=ground.laz CELL_SIZE=0.5 MAX_EDGE=0 OUTPUT=dtm.tif OUTPUT_HTML=tin.html",
            {**self.common_notes(),
             self.MAX_EDGE: self.tr("0 = ten mean point spacings (at least four cells); "
                                    "cells in longer triangles are nodata."),
             self.FILL_GAPS: self.tr("Keeps every triangle, bridging gaps inside the "
                                     "convex hull with flat facets.")})

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add_input_params()
        self.add_number(self.MAX_EDGE, self.tr("Maximum triangle edge (m, 0 = auto)"), 0.0,
                        minimum=0.0)
        self.add(QgsProcessingParameterBoolean(
            self.FILL_GAPS, self.tr("Fill gaps (keep long triangles)"), False),
            advanced=True)
        self.add(QgsProcessingParameterRasterDestination(self.OUTPUT, self.tr("TIN DTM")))
        self.add_html()
        for name, label in (("N_POINTS", self.tr("Points triangulated")),
                            ("N_TRIANGLES", self.tr("Triangles")),
                            ("VALID_CELLS", self.tr("Cells with a value")),
                            ("NODATA_CELLS", self.tr("Nodata cells"))):
            self.addOutput(QgsProcessingOutputNumber(name, label))

    def process(self, parameters, context, feedback):
        path = self.las_input_path(parameters, context, self.INPUT)
        max_edge = self.parameterAsDouble(parameters, self.MAX_EDGE, context)
        method = core_dtm.TinMethod(core_dtm.TinOptions(
            max_edge=max_edge if max_edge > 0 else None))
        with self.contract(parameters, context, [self.OUTPUT], {self.INPUT: path}) as out:
            run, results = self.run_method(parameters, context, feedback, method, out)
        results["N_TRIANGLES"] = run.outcome.details.n_triangles
        return results

"""TIN DTM: Delaunay linear interpolation of the ground points (core.terrain.tin)."""
from __future__ import annotations

import os

from qgis.core import (
    QgsProcessingOutputNumber,
    QgsProcessingParameterBoolean,
    QgsProcessingParameterRasterDestination,
)

from ..core.io.points import write_grid
from ..core.lidar.qa import check_projected
from ..core.terrain import tin as core_tin
from ..core.terrain.report import tin_report
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
        fill = self.parameterAsBool(parameters, self.FILL_GAPS, context)
        with self.contract(parameters, context, [self.OUTPUT], {self.INPUT: path}) as out:
            path, pts, grid, crs_source = self.load_points(parameters, context, feedback)
            check_projected(pts.x, pts.y)
            res = core_tin.tin_grid(pts.x, pts.y, pts.z, grid,
                                    max_edge=max_edge if max_edge > 0 else None, fill=fill,
                                    **self.core_callbacks(feedback))
            meta = {"method": "TIN linear (Delaunay) "
                    + ("gaps filled" if fill else f"max edge {res.max_edge:g} m"),
                    "source": os.path.basename(path)}
            stats = self.grid_stats(res.z)
            self.refuse_empty_grid(stats, res.n_points, path)
            write_grid(out.path(self.OUTPUT), res.z, grid, metadata=meta,
                       band_name="DTM (TIN)", units=pts.units)
            if out.requested(self.OUTPUT_HTML):
                out.write_text(self.OUTPUT_HTML, self.render_report(
                    tin_report(res, os.path.basename(path), pts.n_total, grid,
                               units=pts.units), parameters,
                    context))
        results = {self.OUTPUT: out.final(self.OUTPUT), "N_POINTS": res.n_points,
                   "N_TRIANGLES": res.n_triangles, "VALID_CELLS": stats["valid_cells"],
                   "NODATA_CELLS": stats["nodata_cells"]}
        if out.requested(self.OUTPUT_HTML):
            results[self.OUTPUT_HTML] = out.final(self.OUTPUT_HTML)
        return results

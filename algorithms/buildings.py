"""Building footprints with heights from a ground-classified cloud (core.lidar.buildings)."""
from __future__ import annotations

import os

import numpy as np
from qgis.core import (
    QgsProcessingOutputNumber,
    QgsProcessingParameterFileDestination,
    QgsProcessingParameterString,
    QgsProcessingParameterVectorDestination,
)

from ..core.errors import InputError
from ..core.io.las import las_info, read_las, write_las_like
from ..core.io.points import parse_classes
from ..core.io.vector import write_label_polygons
from ..core.lidar import buildings as core_b
from ..core.lidar.qa import check_projected
from .base import GeomaticsAlgorithm
from .helptext import build_help
from .terrain import LAS_FILTER

FIELDS = [("id", "int"), ("height_m", "float"), ("area_m2", "float"),
          ("volume_m3", "float"), ("storeys", "int"), ("roof_type", "str"),
          ("ground_z", "float"), ("roof_z", "float")]


class BuildingsAlgorithm(GeomaticsAlgorithm):
    """Footprints (GeoPackage) with height, area, volume, storeys, roof type."""

    GROUP = "lidarfiltering"
    INPUT = "INPUT"
    GROUND_CLASSES = "GROUND_CLASSES"
    MIN_HEIGHT = "MIN_HEIGHT"
    MAX_ANGLE = "MAX_ANGLE"
    MIN_PATCH_AREA = "MIN_PATCH_AREA"
    MIN_AREA = "MIN_AREA"
    CELL_SIZE = "CELL_SIZE"
    OUTPUT = "OUTPUT"
    OUTPUT_CLOUD = "OUTPUT_CLOUD"
    OUTPUT_HTML = "OUTPUT_HTML"
    OUTPUT_STYLES = {"OUTPUT": "footprints"}

    def name(self):
        return "buildings"

    def displayName(self):  # noqa: N802
        return self.tr("Building footprints with heights")

    def shortDescription(self):  # noqa: N802
        return self.tr("Roof planes found by region growing above the DTM, as footprints "
                       "with height, area, volume, storeys and roof type.")

    def tags(self):
        return self.tr("buildings,footprints,roofs,lod1,extraction,height,volume,storeys,"
                       "class 6,lidar").split(",")

    def shortHelpString(self):  # noqa: N802
        return build_help(self, self.tr(
            "Extracts buildings from a ground-classified LAS/LAZ cloud: points above the "
            "ground TIN are fitted with local planes, and neighbours with agreeing normals "
            "grow into roof patches. Patches large enough become footprints with height, "
            "area, volume, storeys and roof type; trees are rejected because their points "
            "are not planar."),
            "INPUT=ground_filtered.laz MIN_HEIGHT=2 MAX_ANGLE=20 OUTPUT=buildings.gpkg "
            "OUTPUT_CLOUD=classified.laz",
            {self.INPUT: self.tr("Ground in class 2 (run a ground filter first), in a "
                                 "projected CRS (metres)."),
             self.MIN_HEIGHT: self.tr("The specification gives 1.5–2 m."),
             self.OUTPUT: self.tr("GeoPackage polygons with height, area, volume, storeys, "
                                  "roof type, ground and roof heights.")})

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add_las_input(self.INPUT, self.tr("Point cloud (LAS/LAZ)"))
        self.add(QgsProcessingParameterString(
            self.GROUND_CLASSES, self.tr("Ground classes"), defaultValue="2"), advanced=True)
        self.add_number(self.MIN_HEIGHT, self.tr("Minimum height above ground (m)"), 2.0,
                        minimum=0.0)
        self.add_number(self.MAX_ANGLE, self.tr("Maximum angle between roof normals (°)"),
                        20.0, minimum=1.0, maximum=90.0)
        self.add_number(self.MIN_PATCH_AREA, self.tr("Minimum roof patch area (m²)"), 15.0,
                        minimum=0.0)
        self.add_number(self.MIN_AREA, self.tr("Minimum building area (m²)"), 15.0,
                        minimum=0.0)
        self.add_number(self.CELL_SIZE, self.tr("Cell size (m)"), 0.5, minimum=0.0,
                        advanced=True)
        self.add(QgsProcessingParameterVectorDestination(self.OUTPUT,
                                                         self.tr("Building footprints")))
        self.add(QgsProcessingParameterFileDestination(
            self.OUTPUT_CLOUD, self.tr("Classified cloud (class 6 = building)"),
            LAS_FILTER, optional=True, createByDefault=False))
        self.add(QgsProcessingParameterFileDestination(
            self.OUTPUT_HTML, self.tr("Building footprints report"), self.tr("HTML files (*.html)"),
            optional=True, createByDefault=False))
        self.add_report_language()
        for name, label in (("N_BUILDINGS", self.tr("Buildings")),
                            ("TOTAL_AREA", self.tr("Total footprint area (m²)")),
                            ("TOTAL_VOLUME", self.tr("Total volume (m³)"))):
            self.addOutput(QgsProcessingOutputNumber(name, label))

    def params(self, parameters, context) -> dict:
        cell = self.parameterAsDouble(parameters, self.CELL_SIZE, context)
        if not cell > 0:
            raise InputError("Cell size must be > 0 (m); give e.g. 0.5.")
        return {"min_height": self.parameterAsDouble(parameters, self.MIN_HEIGHT, context),
                "max_angle": self.parameterAsDouble(parameters, self.MAX_ANGLE, context),
                "min_patch_area": self.parameterAsDouble(parameters, self.MIN_PATCH_AREA,
                                                         context),
                "min_area": self.parameterAsDouble(parameters, self.MIN_AREA, context),
                "cell": cell}

    def process(self, parameters, context, feedback):
        path = self.las_input_path(parameters, context, self.INPUT)
        p = self.params(parameters, context)
        ground = parse_classes(self.parameterAsString(parameters, self.GROUND_CLASSES,
                                                      context)) or (2,)
        names = [self.OUTPUT, self.OUTPUT_CLOUD, self.OUTPUT_HTML]
        cb = self.core_callbacks(feedback)
        with self.output_contract(parameters, context, names,
                                  inputs={self.INPUT: path}) as out:
            info = las_info(path)
            pts = read_las(path, ["classification"], cancel=cb["cancel"])
            check_projected(pts.x, pts.y)
            res = core_b.extract_buildings(pts.x, pts.y, pts.z, pts["classification"],
                                           ground_classes=ground, crs=info.crs, **p, **cb)
            recs = {b["id"]: {"id": b["id"], "height_m": b["height"], "area_m2": b["area"],
                              "volume_m3": b["volume"], "storeys": b["storeys"],
                              "roof_type": b["roof_type"], "ground_z": b["ground"],
                              "roof_z": b["roof"]} for b in res.buildings}
            write_label_polygons(out.path(self.OUTPUT), res.labels, res.grid.geotransform,
                                 crs=info.crs, layer_name="buildings", fields=FIELDS,
                                 records=recs)
            if out.requested(self.OUTPUT_CLOUD):
                cls = np.where(res.is_building, 6, pts["classification"]).astype(
                    pts["classification"].dtype)
                write_las_like(path, out.path(self.OUTPUT_CLOUD),
                               dimensions={"classification": cls})
            if out.requested(self.OUTPUT_HTML):
                rep = core_b.buildings_report(res, os.path.basename(path), p)
                out.write_text(self.OUTPUT_HTML, self.render_report(rep, parameters,
                                                                    context))
        results = {n: out.final(n) for n in names if out.requested(n)}
        self.load_cloud_on_completion(context, results.get(self.OUTPUT_CLOUD),
                                      self.tr("Classified cloud (class 6 = building)"),
                                      self.OUTPUT_CLOUD)
        results.update(N_BUILDINGS=len(res.buildings),
                       TOTAL_AREA=float(sum(b["area"] for b in res.buildings)),
                       TOTAL_VOLUME=float(sum(b["volume"] for b in res.buildings)))
        return results

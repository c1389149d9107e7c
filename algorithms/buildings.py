"""Building footprints with heights from a ground-classified cloud (core.lidar.buildings)."""
from __future__ import annotations

from qgis.core import (
    QgsProcessingOutputNumber,
    QgsProcessingParameterFileDestination,
    QgsProcessingParameterString,
    QgsProcessingParameterVectorDestination,
)

from ..core.errors import InputError
from ..core.io.points import parse_classes
from ..core.lidar.buildings import DEFAULTS as BUILDING_DEFAULTS
from ..core.lidar.buildings_file import BuildingOutputs, buildings_file
from .base import LAS_IN_FILTER, GeomaticsAlgorithm
from .helptext import build_help

CITYJSON_FILTER = "CityJSON (*.city.json *.json)"
OBJ_FILTER = "Wavefront OBJ (*.obj)"


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
    STOREY_HEIGHT = "STOREY_HEIGHT"
    OUTPUT = "OUTPUT"
    OUTPUT_CLOUD = "OUTPUT_CLOUD"
    OUTPUT_CITYJSON = "OUTPUT_CITYJSON"
    OUTPUT_OBJ = "OUTPUT_OBJ"
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
            "grow into roof patches; trees are rejected because their points are not "
            "planar. Each footprint gets a roof model fitted to its roof points only (flat, "
            "shed, gabled, hipped or complex), so canopy over a roof does not raise it; "
            "heights, eave heights, area, volume and storeys follow from it. A deck whose "
            "surface runs on into the ground at both ends (a bridge) is not a building. "
            "Optional LOD1/LOD2 CityJSON and OBJ 3D models. Clouds in feet are converted: "
            "heights, areas and volumes are in metres, geometry in the data's CRS."),
            "INPUT=ground_filtered.laz OUTPUT=buildings.gpkg OUTPUT_CITYJSON=city.json "
            "OUTPUT_OBJ=city.obj OUTPUT_CLOUD=classified.laz",
            {self.INPUT: self.tr("Ground in class 2 (run a ground filter first), in a "
                                 "projected CRS (metres)."),
             self.MIN_HEIGHT: self.tr("The specification gives 1.5–2 m."),
             self.STOREY_HEIGHT: self.tr("Storeys = mean roof height above ground / this "
                                         "height (the specification gives 2.5–3.5 m)."),
             self.OUTPUT: self.tr("GeoPackage polygons with height, area, volume, storeys, "
                                  "roof type, ground and roof heights."),
             self.OUTPUT_CITYJSON: self.tr("CityJSON 2.0: each building as an LOD1 block "
                                           "and, for rectangular footprints with a flat, "
                                           "shed, gabled or hipped roof, an LOD2 solid "
                                           "with roof, wall and ground surfaces.")})

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add_las_input(self.INPUT, self.tr("Point cloud (LAS/LAZ)"))
        self.add(QgsProcessingParameterString(
            self.GROUND_CLASSES, self.tr("Ground classes"), defaultValue="2"), advanced=True)
        d = BUILDING_DEFAULTS
        self.add_number(self.MIN_HEIGHT, self.tr("Minimum height above ground (m)"),
                        d["min_height"], minimum=0.0)
        self.add_number(self.MAX_ANGLE, self.tr("Maximum angle between roof normals (°)"),
                        d["max_angle"], minimum=1.0, maximum=90.0)
        self.add_number(self.MIN_PATCH_AREA, self.tr("Minimum roof patch area (m²)"),
                        d["min_patch_area"], minimum=0.0)
        self.add_number(self.MIN_AREA, self.tr("Minimum building area (m²)"),
                        d["min_area"], minimum=0.0)
        self.add_number(self.CELL_SIZE, self.tr("Cell size (m)"), d["cell"], minimum=0.0,
                        advanced=True)
        self.add_number(self.STOREY_HEIGHT, self.tr("Storey height (m)"),
                        d["storey_height"], minimum=2.0, maximum=5.0)
        self.add(QgsProcessingParameterVectorDestination(self.OUTPUT,
                                                         self.tr("Building footprints")))
        self.add(QgsProcessingParameterFileDestination(
            self.OUTPUT_CLOUD, self.tr("Classified cloud (class 6 = building)"),
            LAS_IN_FILTER, optional=True, createByDefault=False))
        self.add(QgsProcessingParameterFileDestination(
            self.OUTPUT_CITYJSON, self.tr("3D city model (CityJSON, LOD1 and LOD2)"),
            CITYJSON_FILTER, optional=True, createByDefault=False))
        self.add(QgsProcessingParameterFileDestination(
            self.OUTPUT_OBJ, self.tr("3D model for viewers (OBJ)"), OBJ_FILTER,
            optional=True, createByDefault=False))
        self.add_report_output(self.OUTPUT_HTML, self.tr("Building footprints report"))
        self.add_report_language()
        for name, label in (("N_BUILDINGS", self.tr("Buildings")),
                            ("TOTAL_AREA", self.tr("Total footprint area (m²)")),
                            ("TOTAL_VOLUME", self.tr("Total volume (m³)"))):
            self.addOutput(QgsProcessingOutputNumber(name, label))

    def params(self, parameters, context) -> dict:
        cell = self.parameterAsDouble(parameters, self.CELL_SIZE, context)
        if not cell > 0:
            raise InputError("Cell size must be > 0 (m); give e.g. 0.5.")
        storey = self.parameterAsDouble(parameters, self.STOREY_HEIGHT, context)
        if not 2.0 <= storey <= 5.0:
            raise InputError("Storey height must be between 2 and 5 m (typically 2.5–3.5); "
                             "got {value} m.", value=storey)
        return {"min_height": self.parameterAsDouble(parameters, self.MIN_HEIGHT, context),
                "max_angle": self.parameterAsDouble(parameters, self.MAX_ANGLE, context),
                "min_patch_area": self.parameterAsDouble(parameters, self.MIN_PATCH_AREA,
                                                         context),
                "min_area": self.parameterAsDouble(parameters, self.MIN_AREA, context),
                "storey_height": storey, "cell": cell}

    def process(self, parameters, context, feedback):
        path = self.las_input_path(parameters, context, self.INPUT)
        p = self.params(parameters, context)
        ground = parse_classes(self.parameterAsString(parameters, self.GROUND_CLASSES,
                                                      context)) or (2,)
        names = (self.OUTPUT, self.OUTPUT_CLOUD, self.OUTPUT_CITYJSON, self.OUTPUT_OBJ,
                 self.OUTPUT_HTML)
        footprints, *others = (self.output_path(parameters, context, n) or None
                               for n in names)
        outputs = BuildingOutputs(footprints, *others, names=names)
        res, units = buildings_file(
            path, outputs, ground_classes=ground, params=p,
            render=lambda rep: self.render_report(rep, parameters, context),
            lang=self.report_lang(parameters, context), **self.core_callbacks(feedback))
        results = {self.OUTPUT: footprints}
        for n, value in zip(names[1:], (outputs.cloud, outputs.cityjson, outputs.obj,
                                        outputs.report)):
            if value:
                results[n] = value
        self.load_cloud_on_completion(context, results.get(self.OUTPUT_CLOUD),
                                      self.tr("Classified cloud (class 6 = building)"),
                                      self.OUTPUT_CLOUD)
        feedback.pushInfo(self.tr("{} buildings; data units (horizontal / vertical): "
                                  "{}").format(len(res.buildings), units.symbols))
        results.update(N_BUILDINGS=len(res.buildings),
                       TOTAL_AREA=float(sum(b["area"] for b in res.buildings)),
                       TOTAL_VOLUME=float(sum(b["volume"] for b in res.buildings)))
        return results

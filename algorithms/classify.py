"""Full ASPRS classification of a LAS/LAZ cloud (core.lidar.classify)."""
from __future__ import annotations

from qgis.core import (
    QgsProcessingOutputNumber,
    QgsProcessingParameterBoolean,
    QgsProcessingParameterEnum,
    QgsProcessingParameterFileDestination,
)

from ..core.lidar import classify as core_c
from .base import LAS_OUT_FILTER, GeomaticsAlgorithm
from .helptext import build_help


class ClassifyAlgorithm(GeomaticsAlgorithm):
    """Ground, vegetation by height, buildings, noise; water and other classes kept."""

    GROUP = "lidarfiltering"
    INPUT = "INPUT"
    GROUND = "GROUND"
    LOW_VEGETATION = "LOW_VEGETATION"
    MEDIUM_VEGETATION = "MEDIUM_VEGETATION"
    BUILDINGS = "BUILDINGS"
    MIN_HEIGHT = "MIN_HEIGHT"
    KEEP_OTHER = "KEEP_OTHER"
    HEIGHT_ABOVE_GROUND = "HEIGHT_ABOVE_GROUND"
    OUTPUT = "OUTPUT"
    OUTPUT_HTML = "OUTPUT_HTML"
    GROUND_MODES = ("filter", "keep")

    def name(self):
        return "classify"

    def displayName(self):  # noqa: N802
        return self.tr("Classify point cloud (ASPRS classes)")

    def shortDescription(self):  # noqa: N802
        return self.tr("Ground, low/medium/high vegetation, buildings and low noise in one "
                       "run; water and the other attributes kept.")

    def tags(self):
        return self.tr("lidar,las,laz,classification,asprs,ground,vegetation,building,"
                       "noise,water,height above ground,normalize").split(",")

    def shortHelpString(self):  # noqa: N802
        return build_help(self, self.tr(
            "Writes standard ASPRS classes into a copy of a LAS/LAZ cloud: 2 ground (the "
            "recommended ground filter, or the input's class 2 kept), 3/4/5 low/medium/high "
            "vegetation by height above a TIN of the ground, 6 building (roof planes, "
            "bridges refused), 7 low noise; water (9) and noise (18) are kept. Every other "
            "attribute, the VLRs and the CRS are copied unchanged. Heights are in metres "
            "also for clouds in feet (converted)."),
            "INPUT=tile.laz OUTPUT=classified.laz HEIGHT_ABOVE_GROUND=true",
            {self.INPUT: self.tr("A .las or .laz file in a projected CRS."),
             self.GROUND: self.tr("Keep the input's class 2 when it was already filtered."),
             self.LOW_VEGETATION: self.tr("Default 0.5 m and 1.5 m: the IGN LiDAR HD "
                                          "vegetation classes."),
             self.MIN_HEIGHT: self.tr("The specification gives 1.5–2 m."),
             self.KEEP_OTHER: self.tr("Classes 8 and 10–255 (rail, road, wires, bridge "
                                      "decks, vendor classes) keep their class."),
             self.HEIGHT_ABOVE_GROUND: self.tr("A float extra dimension HeightAboveGround "
                                               "in the cloud's vertical unit (as PDAL's "
                                               "filters.hag_delaunay).")}) + self.tr(
            "<p>References: ASPRS LAS 1.4 R15, standard point classes; Kostrikov, S. et al. "
            "(2020), ISPRS IJGI 9(11), 650; IGN (2023), LiDAR HD classes.</p>")

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add_las_input(self.INPUT, self.tr("Point cloud (LAS/LAZ)"))
        self.add(QgsProcessingParameterEnum(
            self.GROUND, self.tr("Ground"),
            [self.tr("Recommended ground filter"), self.tr("Keep the input's class 2")],
            defaultValue=0))
        d = core_c.ClassifyOptions()
        self.add_number(self.LOW_VEGETATION, self.tr("Low vegetation up to (m)"), d.low_max,
                        minimum=0.0)
        self.add_number(self.MEDIUM_VEGETATION, self.tr("Medium vegetation up to (m)"),
                        d.medium_max, minimum=0.0)
        self.add(QgsProcessingParameterBoolean(
            self.BUILDINGS, self.tr("Find buildings (class 6)"), True))
        self.add_number(self.MIN_HEIGHT, self.tr("Minimum building height above ground (m)"),
                        d.min_height, minimum=0.0, advanced=True)
        self.add(QgsProcessingParameterBoolean(
            self.KEEP_OTHER, self.tr("Keep other input classes"), False), advanced=True)
        self.add(QgsProcessingParameterBoolean(
            self.HEIGHT_ABOVE_GROUND, self.tr("Add height above ground"), False))
        self.add_report_language()
        self.add(QgsProcessingParameterFileDestination(
            self.OUTPUT, self.tr("Classified point cloud"), LAS_OUT_FILTER))
        self.add_report_output(self.OUTPUT_HTML, self.tr("Classification report"))
        for name, label in (("N_POINTS", self.tr("Points read")),
                            ("N_GROUND", self.tr("Ground points (class 2)")),
                            ("N_VEGETATION", self.tr("Vegetation points (classes 3-5)")),
                            ("N_BUILDING", self.tr("Building points (class 6)")),
                            ("N_NOISE", self.tr("Low noise points (class 7)")),
                            ("N_BUILDINGS", self.tr("Buildings"))):
            self.addOutput(QgsProcessingOutputNumber(name, label))

    def options(self, parameters, context) -> core_c.ClassifyOptions:
        """Core options from the parameters (validated by the core: translated errors)."""
        return core_c.ClassifyOptions(
            ground=self.GROUND_MODES[self.parameterAsEnum(parameters, self.GROUND, context)],
            low_max=self.parameterAsDouble(parameters, self.LOW_VEGETATION, context),
            medium_max=self.parameterAsDouble(parameters, self.MEDIUM_VEGETATION, context),
            buildings=self.parameterAsBool(parameters, self.BUILDINGS, context),
            min_height=self.parameterAsDouble(parameters, self.MIN_HEIGHT, context),
            keep_other=self.parameterAsBool(parameters, self.KEEP_OTHER, context))

    def process(self, parameters, context, feedback):
        src = self.las_input_path(parameters, context, self.INPUT)
        opt = self.options(parameters, context)
        cloud = self.parameterAsFileOutput(parameters, self.OUTPUT, context)
        report = (self.parameterAsFileOutput(parameters, self.OUTPUT_HTML, context)
                  if parameters.get(self.OUTPUT_HTML) not in (None, "") else None)
        res = core_c.classify_file_asprs(
            src, cloud=cloud, report=report or None, options=opt,
            hag=self.parameterAsBool(parameters, self.HEIGHT_ABOVE_GROUND, context),
            render=lambda rep: self.render_report(rep, parameters, context),
            lang=self.report_lang(parameters, context),
            names=(self.OUTPUT, self.OUTPUT_HTML), **self.core_callbacks(feedback))
        c = res.counts
        nb = len(res.buildings.buildings) if res.buildings is not None else 0
        feedback.pushInfo(self.tr("{} points: {} ground, {} vegetation, {} building, {} low "
                                  "noise; {} buildings").format(
            int(res.classes.size), c.get(2, 0), c.get(3, 0) + c.get(4, 0) + c.get(5, 0),
            c.get(6, 0), c.get(7, 0), nb))
        self.load_cloud_on_completion(context, cloud, self.tr("Classified point cloud"),
                                      self.OUTPUT)
        out = {self.OUTPUT: cloud, "N_POINTS": int(res.classes.size),
               "N_GROUND": c.get(2, 0), "N_VEGETATION": c.get(3, 0) + c.get(4, 0) + c.get(5, 0),
               "N_BUILDING": c.get(6, 0), "N_NOISE": c.get(7, 0), "N_BUILDINGS": nb}
        if report:
            out[self.OUTPUT_HTML] = report
        return out

"""Recommended ground filter and progressive TIN densification (Processing algorithms)."""
from __future__ import annotations

import math

from qgis.core import (
    QgsProcessingOutputNumber,
    QgsProcessingParameterBoolean,
    QgsProcessingParameterFileDestination,
)

from ..core.errors import InputError
from ..core.lidar import ptd as core_ptd
from ..core.lidar import recommended as core_rec
from ..core.lidar.filters import ground_filter
from ..core.lidar.pipeline import SelectionOptions
from .base import LAS_OUT_FILTER
from .helptext import build_help
from .lidar_common import LidarFilterMixin


class _GroundCommon(LidarFilterMixin):
    """Input, outputs, output numbers and the run shared by both filters."""

    INPUT = "INPUT"
    OUTPUT = "OUTPUT"
    GROUND_OUTPUT = "GROUND_OUTPUT"
    OUTPUT_HTML = "OUTPUT_HTML"
    KEEP_NOISE = "KEEP_NOISE"

    def tags(self):
        return self.tr("lidar,las,laz,ground,filter,classification,dtm,bare earth,"
                       "point cloud").split(",")

    def add_input(self):
        self.add_las_input(self.INPUT, self.tr("Point cloud (LAS/LAZ)"))

    def common_notes(self) -> dict:
        """Help notes of the input, outputs and noise options of both filters."""
        return {
            self.INPUT: self.tr("A .las or .laz file in a projected CRS (metres)."),
            self.OUTPUT: self.tr("Every point with class 2 ground, 1 other or 7 low "
                                 "noise; every other attribute, VLR and the CRS copied "
                                 "unchanged."),
            self.GROUND_OUTPUT: self.tr("Only the ground points."),
            self.KEEP_NOISE: self.tr("Points already classified 7 or 18 keep their class "
                                     "and take no part."),
            self.NOISE: self.tr("Points far below their neighbours (multipath) get class 7 "
                                "and take no part: one stray low point would reject every "
                                "ground point around it.") + " " + self.noise_note(),
            self.NOISE_RADIUS: self.tr("Side of the cells searched for lower neighbours."),
            self.NOISE_THRESHOLD: self.tr("A point this far below the points around it is "
                                          "a low outlier."),
        }

    def add_outputs(self):
        self.add(QgsProcessingParameterBoolean(
            self.KEEP_NOISE, self.tr("Keep existing noise classes (7, 18)"), True),
            advanced=True)
        self.add_report_language()
        self.add(QgsProcessingParameterFileDestination(
            self.OUTPUT, self.tr("Classified point cloud"), LAS_OUT_FILTER))
        self.add(QgsProcessingParameterFileDestination(
            self.GROUND_OUTPUT, self.tr("Ground points"), LAS_OUT_FILTER, optional=True,
            createByDefault=False))
        self.add_report_output(self.OUTPUT_HTML, self.tr("Ground filter report"))
        for name, label in (("N_POINTS", self.tr("Points read")),
                            ("N_GROUND", self.tr("Ground points (class 2)")),
                            ("N_NONGROUND", self.tr("Non-ground points (class 1)")),
                            ("N_NOISE", self.tr("Low outliers (class 7)")),
                            ("POINTS_PER_SECOND", self.tr("Filter speed (points/s)"))):
            self.addOutput(QgsProcessingOutputNumber(name, label))

    def selection(self, parameters, context) -> SelectionOptions:
        """The pipeline's point selection (all returns; noise pre-filter as asked)."""
        noise = self.parameterAsBool(parameters, self.NOISE, context)
        nr = self.parameterAsDouble(parameters, self.NOISE_RADIUS, context)
        nt = self.parameterAsDouble(parameters, self.NOISE_THRESHOLD, context)
        return SelectionOptions(returns="all", noise=noise, noise_radius=nr,
                                noise_threshold=nt,
                                keep_noise_classes=self.parameterAsBool(
                                    parameters, self.KEEP_NOISE, context)).validate()

    def run_filter(self, parameters, context, feedback, algorithm) -> dict:
        """Classify INPUT with ``algorithm`` through the pipeline; the output numbers."""
        src = self.las_input_path(parameters, context, self.INPUT)
        selection = self.selection(parameters, context)
        outputs = self.filter_outputs(parameters, context, cloud=self.OUTPUT,
                                      ground=self.GROUND_OUTPUT, report=self.OUTPUT_HTML)
        return self.classify_and_publish(src, algorithm, outputs, selection, context,
                                         feedback)


class GroundFilterAlgorithm(_GroundCommon):
    """The recommended ground filter: no parameter to set."""

    CELL = "CELL"
    MAX_WINDOW = "MAX_WINDOW"
    SLOPE = "SLOPE"
    THRESHOLD = "THRESHOLD"
    REFINE = "REFINE"

    def name(self):
        return "groundfilter"

    def displayName(self):  # noqa: N802
        return self.tr("Ground filter (recommended)")

    def shortDescription(self):  # noqa: N802
        return self.tr("Classifies ground in a LAS/LAZ cloud with no parameter to set.")

    def shortHelpString(self):  # noqa: N802
        return build_help(self, self.tr(
            "Classifies a LAS/LAZ point cloud into ground (class 2), other points (class 1) "
            "and low noise (class 7) with no parameter to set: a progressive morphological "
            "filter (Pingel et al. 2013) whose cell, slope and height tolerances are derived "
            "from the cloud, applied to the terrain with its regional slope removed; "
            "terrain crests it removed are grown back, then passes rebuild the terrain and "
            "re-test every point. Under a closed canopy lone ground returns are kept, so "
            "the terrain never climbs into the trees; water classified 9 in the input keeps "
            "its class, and flat, sparse patches that look like water get class 1, never "
            "ground. The report lists every value derived and warns on hard clouds. Total "
            "error with each sample held out of the choice of the defaults (8 ISPRS "
            "samples, 4 real vendor-classified files): 3.31 % on the ISPRS samples, "
            "0.43 % on the real files (SMRF with PDAL's defaults: 5.75 % and 2.65 %); "
            "ISPRS mean at the defaults 3.27 %."),
            "INPUT=tile.laz OUTPUT=classified.laz OUTPUT_HTML=groundfilter.html",
            {**self.common_notes(),
             self.CELL: self.tr("0 = derived from the point density (about 1 m)."),
             self.MAX_WINDOW: self.tr("Must exceed the largest building."),
             self.SLOPE: self.tr("0 = half the local terrain slope (0.10 to 0.60)."),
             self.THRESHOLD: self.tr("0 = 0.35 × the mean point spacing, 0.25 to 0.5 m; "
                                     "plus 1.0 m per unit of terrain slope."),
             self.REFINE: self.tr("Passes that rebuild the terrain from the accepted "
                                  "points.")}) + self.tr(
            "<p>References: Pingel, T. J., Clarke, K. C. &amp; McBride, W. A. (2013), ISPRS "
            "J. Photogramm. Remote Sens. 77, 21–30; Zhang, K. et al. (2003), IEEE TGRS "
            "41(4), 872–882.</p>")

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add_input()
        d = core_rec.RecommendedOptions()
        self.add_number(self.CELL, self.tr("Raster cell, 0 = derived (m)"), 0.0,
                        minimum=0.0, advanced=True)
        self.add_number(self.MAX_WINDOW, self.tr("Largest window, > largest building (m)"),
                        d.max_window, minimum=0.0, advanced=True)
        self.add_number(self.SLOPE, self.tr("Slope tolerance, 0 = derived (rise/run)"),
                        0.0, minimum=0.0, advanced=True)
        self.add_number(self.THRESHOLD, self.tr("Height tolerance, 0 = derived (m)"), 0.0,
                        minimum=0.0, advanced=True)
        self.add_number(self.REFINE, self.tr("Refinement passes"), d.refine, minimum=0,
                        integer=True, advanced=True)
        self.add(QgsProcessingParameterBoolean(
            self.NOISE, self.tr("Remove low outliers first (class 7)"), False),
            advanced=True)
        self.add_number(self.NOISE_RADIUS, self.tr("Low-outlier search cell (m)"), 5.0,
                        minimum=0.0, advanced=True)
        self.add_number(self.NOISE_THRESHOLD,
                        self.tr("Low-outlier depth below neighbours (m)"), 1.0,
                        minimum=0.0, advanced=True)
        self.add_outputs()

    def options(self, parameters, context) -> core_rec.RecommendedOptions:
        """Options from the advanced overrides (0 = derived / default)."""
        def num(name, zero_ok):
            value = self.parameterAsDouble(parameters, name, context)
            if not (math.isfinite(value) and (value > 0 or (zero_ok and value == 0))):
                raise InputError("{name} must be a number {rule}, got {value}; give a "
                                 "value or leave the default.", name=name, value=value,
                                 rule=">= 0 (0 = derived)" if zero_ok else "> 0")
            return value
        kw = dict(cell=num(self.CELL, True) or None, slope=num(self.SLOPE, True) or None,
                  threshold=num(self.THRESHOLD, True) or None,
                  max_window=num(self.MAX_WINDOW, False),
                  refine=self.parameterAsInt(parameters, self.REFINE, context))
        return core_rec.RecommendedOptions(**kw)

    def process(self, parameters, context, feedback):
        opts = self.options(parameters, context)
        feedback.pushInfo(self.tr("Recommended ground filter: window {} m, {} refinement "
                                  "passes; cell and tolerances derived from the cloud "
                                  "(see the report)").format(opts.max_window, opts.refine))
        return self.run_filter(parameters, context, feedback,
                               ground_filter("groundfilter", opts))


class PtdGroundFilterAlgorithm(_GroundCommon):
    """Progressive TIN densification (Axelsson 2000)."""

    CELL = "CELL"
    MAX_BUILDING = "MAX_BUILDING"
    MAX_DISTANCE = "MAX_DISTANCE"
    MAX_ANGLE = "MAX_ANGLE"
    MIN_EDGE = "MIN_EDGE"
    MAX_ITERATIONS = "MAX_ITERATIONS"
    FINAL_DISTANCE = "FINAL_DISTANCE"
    LOW_NOISE_DEPTH = "LOW_NOISE_DEPTH"
    SEED_QUANTILE = "SEED_QUANTILE"
    SEED_DEPTH = "SEED_DEPTH"
    THIN = "THIN"
    BREAKLINE = "BREAKLINE"

    def name(self):
        return "ptdgroundfilter"

    def displayName(self):  # noqa: N802
        return self.tr("Ground filter (progressive TIN densification)")

    def shortDescription(self):  # noqa: N802
        return self.tr("Axelsson's progressive TIN densification ground filter.")

    def shortHelpString(self):  # noqa: N802
        return build_help(self, self.tr(
            "Classifies a LAS/LAZ point cloud into ground (class 2), other points (class 1) "
            "and low noise (class 7) by progressive TIN densification (Axelsson 2000): the "
            "lowest trusted point of each parcel larger than the largest building seeds a "
            "TIN, which takes the candidates (the lowest point per candidate cell) close "
            "enough to its facets until none is added; every other point is ground when it "
            "lies close to the final TIN. Its mean total error on the 8 ISPRS samples is "
            "4.55 % at the defaults (Axelsson published 4.82 % over all 15 samples): use "
            "the recommended ground filter unless you need a TIN filter."),
            "INPUT=tile.laz OUTPUT=classified.laz MAX_BUILDING=100",
            {**self.common_notes(),
             self.CELL: self.tr("Lowest point per cell for the step filter and the seeds."),
             self.MAX_BUILDING: self.tr("Larger than the largest building."),
             self.MAX_DISTANCE: self.tr("Densification limit: distance of a point to its "
                                        "facet."),
             self.MAX_ANGLE: self.tr("Densification limit: angle under which a point is "
                                     "seen from the facet's vertices."),
             self.FINAL_DISTANCE: self.tr("Points this close to the final TIN are ground."),
             self.LOW_NOISE_DEPTH: self.tr("Points deeper below the final TIN get class 7."),
             self.SEED_QUANTILE: self.tr("A parcel's seed is its lowest point not more "
                                         "than the seed depth below this quantile of "
                                         "the parcel's lowest points per cell, so a "
                                         "cluster of low outliers never seeds the TIN."),
             self.SEED_DEPTH: self.tr("See the seed quantile."),
             self.THIN: self.tr("The lowest point per cell of this size is a candidate "
                                "of the TIN; every other point is classified by its "
                                "distance to the final TIN (0 = every point)."),
             self.BREAKLINE: self.tr(
                 "Points in a TIN facet that spans a cliff (steeper than 45° and higher "
                 "than the distance to facet) are mirrored through nearby TIN vertices and "
                 "accepted when the mirror lies on the cliff foot or top within the final "
                 "distance, so the ground right at the cliff edge is kept.")}) + self.tr(
            "<p>Reference: Axelsson, P. (2000). <cite>DEM generation from laser scanner "
            "data using adaptive TIN models</cite>. IAPRS XXXIII-B4, 110–117.</p>")

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add_input()
        d = core_ptd.PtdOptions()
        self.add_number(self.CELL, self.tr("Cell (m)"), d.cell, minimum=0.0)
        self.add_number(self.MAX_BUILDING, self.tr("Parcel size, > largest building (m)"),
                        d.max_building, minimum=0.0)
        self.add_number(self.MAX_DISTANCE, self.tr("Distance to facet (m)"), d.max_distance,
                        minimum=0.0)
        self.add_number(self.MAX_ANGLE, self.tr("Angle to vertices (degrees)"), d.max_angle,
                        minimum=0.0, maximum=90.0)
        self.add_number(self.FINAL_DISTANCE, self.tr("Final distance (m)"),
                        d.final_distance, minimum=0.0)
        self.add_number(self.LOW_NOISE_DEPTH, self.tr("Low-noise depth (m)"),
                        d.low_noise_depth, minimum=0.0)
        self.add_number(self.MIN_EDGE, self.tr("Shortest facet edge (m)"), d.min_edge,
                        minimum=0.0, advanced=True)
        self.add_number(self.MAX_ITERATIONS, self.tr("Iteration cap"), d.max_iterations,
                        minimum=1, integer=True, advanced=True)
        self.add_number(self.SEED_QUANTILE, self.tr("Seed quantile (%)"),
                        100.0 * d.seed_quantile, minimum=0.0, maximum=50.0, advanced=True)
        self.add_number(self.SEED_DEPTH, self.tr("Seed depth (m)"), d.seed_depth,
                        minimum=0.0, advanced=True)
        self.add_number(self.THIN, self.tr("Candidate cell (m)"), d.thin, minimum=0.0,
                        advanced=True)
        self.add(QgsProcessingParameterBoolean(
            self.BREAKLINE, self.tr("Cliff-aware mirroring"), d.breakline), advanced=True)
        self.add_noise_params(default=core_ptd.NOISE_PREFILTER)
        self.add_outputs()

    def options(self, parameters, context) -> core_ptd.PtdOptions:
        """Options from the parameters."""
        def num(name):
            return self.parameterAsDouble(parameters, name, context)
        return core_ptd.PtdOptions(
            cell=num(self.CELL), max_building=num(self.MAX_BUILDING),
            max_distance=num(self.MAX_DISTANCE), max_angle=num(self.MAX_ANGLE),
            final_distance=num(self.FINAL_DISTANCE),
            low_noise_depth=num(self.LOW_NOISE_DEPTH), min_edge=num(self.MIN_EDGE),
            max_iterations=self.parameterAsInt(parameters, self.MAX_ITERATIONS, context),
            seed_quantile=num(self.SEED_QUANTILE) / 100.0, seed_depth=num(self.SEED_DEPTH),
            thin=num(self.THIN),
            breakline=self.parameterAsBool(parameters, self.BREAKLINE, context))

    def process(self, parameters, context, feedback):
        opts = self.options(parameters, context)
        feedback.pushInfo(self.tr("PTD: parcels {} m, distance {} m, angle {}°").format(
            opts.max_building, opts.max_distance, opts.max_angle))
        return self.run_filter(parameters, context, feedback, ground_filter("ptd", opts))

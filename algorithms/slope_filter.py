"""Vosselman slope-based ground filter and its threshold sweep (Processing algorithms)."""
from __future__ import annotations

from qgis.core import (
    QgsProcessingOutputNumber,
    QgsProcessingOutputString,
    QgsProcessingParameterBoolean,
    QgsProcessingParameterEnum,
    QgsProcessingParameterFileDestination,
    QgsProcessingParameterString,
)

from ..core.lidar import pipeline as core_sp
from ..core.lidar import slope as core_sf
from ..core.lidar.filters import ground_filter
from ..core.lidar.pipeline import SelectionOptions
from ..core.lidar.sweep import sweep_file
from .base import LAS_OUT_FILTER
from .helptext import build_help
from .lidar_common import LidarFilterMixin

RETURN_KEYS = list(core_sp.RETURNS)            # all, last
MODE_KEYS = list(core_sf.MODES)                # exact, adaptive
METRIC_KEYS = ["total", "kappa", "type1", "type2"]




class _SlopeCommon(LidarFilterMixin):
    """Parameters shared by the filter and the sweep."""

    GROUP = "lidarfiltering"

    INPUT = "INPUT"
    RETURNS = "RETURNS"
    MODE = "MODE"
    TREND_CELL = "TREND_CELL"
    TREND_WINDOW = "TREND_WINDOW"

    def add_input(self):
        self.add_las_input(self.INPUT, self.tr("Point cloud (LAS/LAZ)"))

    def common_notes(self):
        """Help notes of the shared parameters (see :func:`.helptext.build_help`)."""
        return {
            self.RETURNS: self.tr("All returns: every return is classified and is a "
                                  "neighbour (the forest study). Last returns only: first "
                                  "and intermediate returns get class 1; files without "
                                  "return numbers count every point as a last return."),
            self.NOISE: self.tr("Points far below their neighbours (multipath) get class 7 "
                                "and take no part: one stray low point would reject every "
                                "ground point around it.") + " " + self.noise_note(),
            self.MODE: self.tr("Terrain-adaptive (this toolbox's extension) applies the "
                               "rule to heights above a smooth low terrain trend, so "
                               "natural slopes steeper than θ are kept (ISPRS samp11: "
                               "total error 21.0 % → 16.4 %); use a lower θ, about "
                               "30–35°, in this mode."),
        }

    def add_selection_params(self):
        self.add(QgsProcessingParameterEnum(
            self.RETURNS, self.tr("Returns filtered"),
            [self.tr("All returns"), self.tr("Last returns only")], defaultValue=0))
        self.add_noise_params()
        self.add_report_language()

    def add_mode_params(self):
        self.add(QgsProcessingParameterEnum(
            self.MODE, self.tr("Mode"),
            [self.tr("Exact (Vosselman 2000)"),
             self.tr("Terrain-adaptive (toolbox extension)")], defaultValue=0))
        self.add_number(self.TREND_CELL, self.tr("Adaptive mode: trend cell (m)"), 10.0,
                        minimum=0.0, advanced=True)
        self.add_number(self.TREND_WINDOW,
                        self.tr("Adaptive mode: trend window, > largest building (m)"),
                        60.0, minimum=0.0, advanced=True)

    def selection(self, parameters, context, kw, *, keep_noise: bool) -> SelectionOptions:
        """The pipeline's point selection from the parameters."""
        return SelectionOptions(returns=kw["returns"], noise=kw["noise"],
                                noise_radius=kw["noise_radius"],
                                noise_threshold=kw["noise_threshold"],
                                keep_noise_classes=keep_noise)

    def common_kwargs(self, parameters, context) -> dict:
        mode = MODE_KEYS[self.parameterAsEnum(parameters, self.MODE, context)]
        cell = self.parameterAsDouble(parameters, self.TREND_CELL, context)
        window = self.parameterAsDouble(parameters, self.TREND_WINDOW, context)
        if mode == "adaptive" and not (cell > 0 and window > 0):
            raise ValueError(self.tr("TREND_CELL and TREND_WINDOW must be > 0 metres in "
                                     "adaptive mode (e.g. 10 and 60)."))
        nr = self.parameterAsDouble(parameters, self.NOISE_RADIUS, context)
        nt = self.parameterAsDouble(parameters, self.NOISE_THRESHOLD, context)
        noise = self.parameterAsBool(parameters, self.NOISE, context)
        if noise and not (nr > 0 and nt > 0):
            raise ValueError(self.tr("NOISE_RADIUS and NOISE_THRESHOLD must be > 0 metres "
                                     "(e.g. 5 and 1), or switch the NOISE pre-filter off."))
        return dict(returns=RETURN_KEYS[self.parameterAsEnum(parameters, self.RETURNS,
                                                             context)],
                    noise=noise, noise_radius=nr, noise_threshold=nt, mode=mode,
                    trend_cell=cell, trend_window=window)


class SlopeGroundFilterAlgorithm(_SlopeCommon):
    """Vosselman (2000) slope-based ground filter, exact."""

    RADIUS = "RADIUS"
    SLOPE = "SLOPE"
    HEIGHT_TOLERANCE = "HEIGHT_TOLERANCE"
    KEEP_NOISE = "KEEP_NOISE"
    OUTPUT = "OUTPUT"
    GROUND_OUTPUT = "GROUND_OUTPUT"
    OUTPUT_HTML = "OUTPUT_HTML"

    def name(self):
        return "slopegroundfilter"

    def displayName(self):  # noqa: N802
        return self.tr("Ground filter (slope-based)")

    def tags(self):
        return self.tr("lidar,las,laz,ground,filter,classification,dtm,bare earth,vosselman,"
                       "slope,point cloud").split(",")

    def shortHelpString(self):  # noqa: N802
        return build_help(self, self.tr(
            "Classifies a LAS/LAZ point cloud into ground (class 2) and non-ground (class "
            "1) with Vosselman's (2000) slope-based filter: a point is non-ground when a "
            "neighbour within the radius r lies more than d·tan θ + h below it. The filter "
            "is exact and fast (about a million points per second at r = 3 m); tune r and "
            "θ to your data with the slope filter threshold sweep."),
            "INPUT=cloud.laz RADIUS=3 SLOPE=44 HEIGHT_TOLERANCE=0 OUTPUT=classified.laz "
            "OUTPUT_HTML=slope.html",
            {**self.common_notes(),
             self.RADIUS: self.tr("Must exceed half the width of the largest building to "
                                  "remove; a larger radius costs more time."),
             self.SLOPE: self.tr("The steepest terrain kept, between 0 and 90°; the allowed "
                                 "rise at 3 m is 2.52 m at 40°, 2.90 m at 44° and 3.84 m at "
                                 "52°."),
             self.HEIGHT_TOLERANCE: self.tr("Extra rise allowed for every pair, absorbs "
                                            "ranging noise; 0 is the published rule."),
             self.KEEP_NOISE: self.tr("Points already in class 7 or 18 keep their class "
                                      "and take no part."),
             self.OUTPUT: self.tr("Every point with classes 2, 1 and 7; every other "
                                  "attribute is copied unchanged.")})

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add_input()
        self.add_number(self.RADIUS, self.tr("Radius r (m)"), core_sf.DEFAULT_RADIUS,
                        minimum=0.0)
        self.add_number(self.SLOPE, self.tr("Slope threshold θ (degrees)"),
                        core_sf.DEFAULT_SLOPE, minimum=0.0, maximum=90.0)
        self.add_number(self.HEIGHT_TOLERANCE, self.tr("Height tolerance h (m)"),
                        core_sf.DEFAULT_HEIGHT_TOLERANCE, minimum=0.0)
        self.add_selection_params()
        self.add_mode_params()
        self.add(QgsProcessingParameterBoolean(
            self.KEEP_NOISE, self.tr("Keep existing noise classes (7, 18)"), True),
            advanced=True)
        self.add(QgsProcessingParameterFileDestination(
            self.OUTPUT, self.tr("Classified point cloud"), LAS_OUT_FILTER))
        self.add(QgsProcessingParameterFileDestination(
            self.GROUND_OUTPUT, self.tr("Ground points"), LAS_OUT_FILTER, optional=True,
            createByDefault=False))
        self.add_report_output(self.OUTPUT_HTML, self.tr("Slope ground filter report"))
        for name, label in (("N_POINTS", self.tr("Points read")),
                            ("N_GROUND", self.tr("Ground points (class 2)")),
                            ("N_NONGROUND", self.tr("Non-ground points (class 1)")),
                            ("N_NOISE", self.tr("Low outliers (class 7)")),
                            ("POINTS_PER_SECOND", self.tr("Filter speed (points/s)"))):
            self.addOutput(QgsProcessingOutputNumber(name, label))

    def process(self, parameters, context, feedback):
        src = self.las_input_path(parameters, context, self.INPUT)
        kw = self.common_kwargs(parameters, context)
        opts = core_sf.SlopeOptions(
            radius=self.parameterAsDouble(parameters, self.RADIUS, context),
            slope=self.parameterAsDouble(parameters, self.SLOPE, context),
            height_tolerance=self.parameterAsDouble(parameters, self.HEIGHT_TOLERANCE,
                                                    context),
            mode=kw["mode"], trend_cell=kw["trend_cell"], trend_window=kw["trend_window"])
        selection = self.selection(parameters, context, kw, keep_noise=self.parameterAsBool(
            parameters, self.KEEP_NOISE, context))
        outputs = self.filter_outputs(parameters, context, cloud=self.OUTPUT,
                                      ground=self.GROUND_OUTPUT, report=self.OUTPUT_HTML)
        feedback.pushInfo(self.tr("Slope filter: r = {} m, θ = {}°, h = {} m, {} returns, "
                                  "mode {}").format(opts.radius, opts.slope,
                                                    opts.height_tolerance, kw["returns"],
                                                    kw["mode"]))
        algorithm = ground_filter(f"slope_{opts.mode}", opts)
        return self.classify_and_publish(src, algorithm, outputs, selection, context,
                                         feedback)


class SlopeThresholdSweepAlgorithm(_SlopeCommon):
    """Accuracy of the slope filter over a list of thresholds, radii and tolerances."""

    REFERENCE = "REFERENCE"
    GROUND_CLASSES = "GROUND_CLASSES"
    SLOPES = "SLOPES"
    RADII = "RADII"
    HEIGHT_TOLERANCES = "HEIGHT_TOLERANCES"
    METRIC = "METRIC"
    OUTPUT_CSV = "OUTPUT_CSV"
    OUTPUT_HTML = "OUTPUT_HTML"
    OUTPUT = "OUTPUT"

    def name(self):
        return "slopethresholdsweep"

    def displayName(self):  # noqa: N802
        return self.tr("Slope filter threshold sweep")

    def tags(self):
        return self.tr("lidar,ground,filter,vosselman,slope,threshold,tuning,accuracy,"
                       "type I,type II,kappa,isprs").split(",")

    def shortHelpString(self):  # noqa: N802
        return build_help(self, self.tr(
            "Runs the slope-based ground filter for every combination of slope thresholds "
            "θ, radii r and height tolerances h, and measures each against reference "
            "labels: Type I and Type II errors, total error and Cohen's kappa (Sithole "
            "&amp; Vosselman 2004). It then picks the best setting, at the cost of one "
            "neighbourhood pass per radius and tolerance."),
            "INPUT=samp31.laz SLOPES=40:60:4 RADII=3 HEIGHT_TOLERANCES=0 "
            "OUTPUT_CSV=sweep.csv OUTPUT_HTML=sweep.html",
            {**self.common_notes(),
             self.INPUT: self.tr("Its classification is never used to filter."),
             self.REFERENCE: self.tr("A labelled copy of the same points in the same "
                                     "order, e.g. the ISPRS reference samples."),
             self.GROUND_CLASSES: self.tr("Every other class counts as an object."),
             self.SLOPES: self.tr("A list such as 40, 44, 48 or start:stop:step."),
             self.RADII: self.tr("Each value is one neighbourhood pass."),
             self.OUTPUT_CSV: self.tr("One row per setting with the cross matrix and the "
                                      "errors in percent.")})

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add_input()
        self.add_las_input(self.REFERENCE,
                           self.tr("Reference cloud (empty = the input's classification)"),
                           optional=True)
        self.add(QgsProcessingParameterString(
            self.GROUND_CLASSES, self.tr("Reference ground classes"), defaultValue="2"))
        self.add(QgsProcessingParameterString(
            self.SLOPES, self.tr("Slope thresholds θ (degrees; list or start:stop:step)"),
            defaultValue="30, 35, 40, 44, 48, 52, 56, 60"))
        self.add(QgsProcessingParameterString(
            self.RADII, self.tr("Radii r (m; list)"), defaultValue="10"))
        self.add(QgsProcessingParameterString(
            self.HEIGHT_TOLERANCES, self.tr("Height tolerances h (m; list)"),
            defaultValue="0.2"))
        self.add(QgsProcessingParameterEnum(
            self.METRIC, self.tr("Best by"),
            [self.tr("Lowest total error"), self.tr("Highest kappa"),
             self.tr("Lowest Type I error"), self.tr("Lowest Type II error")],
            defaultValue=0))
        self.add_selection_params()
        self.add_mode_params()
        self.add(QgsProcessingParameterFileDestination(
            self.OUTPUT_CSV, self.tr("Sweep table"), self.tr("CSV files (*.csv)")))
        self.add_report_output(self.OUTPUT_HTML, self.tr("Slope threshold sweep report"),
                               create_by_default=True)
        self.add(QgsProcessingParameterFileDestination(
            self.OUTPUT, self.tr("Classified with the best setting"), LAS_OUT_FILTER,
            optional=True, createByDefault=False))
        for name, label in (("BEST_RADIUS", self.tr("Best radius (m)")),
                            ("BEST_SLOPE", self.tr("Best slope threshold (degrees)")),
                            ("BEST_HEIGHT_TOLERANCE", self.tr("Best height tolerance (m)")),
                            ("BEST_TYPE1", self.tr("Type I error at the best setting (%)")),
                            ("BEST_TYPE2", self.tr("Type II error at the best setting (%)")),
                            ("BEST_TOTAL", self.tr("Total error at the best setting (%)")),
                            ("BEST_KAPPA", self.tr("Kappa at the best setting (%)")),
                            ("N_SETTINGS", self.tr("Settings evaluated"))):
            self.addOutput(QgsProcessingOutputNumber(name, label))
        self.addOutput(QgsProcessingOutputString("BEST_SETTING", self.tr("Best setting")))

    def process(self, parameters, context, feedback):
        src = self.las_input_path(parameters, context, self.INPUT)
        ref = self.las_input_path(parameters, context, self.REFERENCE) or None
        csv = self.parameterAsFileOutput(parameters, self.OUTPUT_CSV, context)
        html = self.parameterAsFileOutput(parameters, self.OUTPUT_HTML, context)
        out = self.parameterAsFileOutput(parameters, self.OUTPUT, context)
        slopes = core_sp.parse_number_list(
            self.parameterAsString(parameters, self.SLOPES, context), "SLOPES")
        radii = core_sp.parse_number_list(
            self.parameterAsString(parameters, self.RADII, context), "RADII")
        hs = core_sp.parse_number_list(
            self.parameterAsString(parameters, self.HEIGHT_TOLERANCES, context),
            "HEIGHT_TOLERANCES")
        classes = [int(c) for c in core_sp.parse_number_list(
            self.parameterAsString(parameters, self.GROUND_CLASSES, context),
            "GROUND_CLASSES")]
        metric = METRIC_KEYS[self.parameterAsEnum(parameters, self.METRIC, context)]
        kw = self.common_kwargs(parameters, context)
        feedback.pushInfo(self.tr("Sweeping {} thresholds × {} radii × {} tolerances").format(
            len(slopes), len(radii), len(hs)))
        s = sweep_file(src, reference=ref, ground_classes=classes, slopes=slopes,
                       radii=radii, height_tolerances=hs, metric=metric,
                       selection=self.selection(parameters, context, kw, keep_noise=False),
                       mode=kw["mode"], trend_cell=kw["trend_cell"],
                       trend_window=kw["trend_window"], csv_output=csv or None,
                       html_output=html or None, output=out or None,
                       lang=self.report_lang(parameters, context),
                       render=lambda rep: self.render_report(rep, parameters, context),
                       **self.core_callbacks(feedback))
        b = s.result.best
        for row in s.result.rows:
            feedback.pushInfo(f"r={row.radius:g} θ={row.slope:g} h={row.height_tolerance:g}: "
                              f"I {row.type1:.2f} % II {row.type2:.2f} % total "
                              f"{row.total:.2f} % κ {row.kappa:.1f}")  # i18n: data
        best = f"r={b.radius:g} m, θ={b.slope:g}°, h={b.height_tolerance:g} m"
        feedback.pushInfo(self.tr("Best ({}): {} — total {:.2f} %").format(metric, best,
                                                                           b.total))
        result = {"BEST_RADIUS": b.radius, "BEST_SLOPE": b.slope,
                  "BEST_HEIGHT_TOLERANCE": b.height_tolerance, "BEST_TYPE1": b.type1,
                  "BEST_TYPE2": b.type2, "BEST_TOTAL": b.total, "BEST_KAPPA": b.kappa,
                  "N_SETTINGS": len(s.result.rows), "BEST_SETTING": best}
        if csv:
            result[self.OUTPUT_CSV] = csv
        if html:
            result[self.OUTPUT_HTML] = html
        if out:
            result[self.OUTPUT] = out
        return result

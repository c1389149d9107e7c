"""GSD / photogrammetric accuracy calculator (single camera, and batch over a table)."""
from __future__ import annotations

import math
import os

from qgis.core import (
    QgsFeature,
    QgsFeatureSink,
    QgsField,
    QgsFields,
    QgsProcessing,
    QgsProcessingException,
    QgsProcessingOutputNumber,
    QgsProcessingParameterBoolean,
    QgsProcessingParameterEnum,
    QgsProcessingParameterFeatureSink,
    QgsProcessingParameterFeatureSource,
    QgsWkbTypes,
)
from qgis.PyQt.QtCore import QVariant

from ..core.errors import InputError
from ..core.io.contract import OutputContract
from ..core.photogrammetry import gsd as core_gsd
from ..core.photogrammetry.cameras import CAMERAS
from ..core.photogrammetry.report import gsd_report
from ..core.progress import Cancelled
from .base import GeomaticsAlgorithm
from .helptext import build_help

CAMERA_KEYS = ["custom"] + list(CAMERAS)

# (result attribute, output name, unit) of every numeric output, in report order.
NUMERIC_OUTPUTS = (
    ("gsd_cm", "GSD", "cm/px"),
    ("gsd_exact_cm", "GSD_EXACT", "cm/px"),
    ("pixel_pitch_um", "PIXEL_PITCH", "µm"),
    ("footprint_width_m", "FOOTPRINT_WIDTH", "m"),
    ("footprint_height_m", "FOOTPRINT_HEIGHT", "m"),
    ("sigma_meas_mm", "SIGMA_MEAS", "mm"),
    ("sigma_xyz_mm", "SIGMA_XYZ", "mm"),
    ("matching_step_px", "MATCHING_STEP", "px"),
    ("dense_resolution_cm", "DENSE_RESOLUTION", "cm"),
    ("distance_for_target_m", "DISTANCE_FOR_TARGET", "m"),
    ("observed_sigma_xyz_mm", "OBSERVED_SIGMA_XYZ", "mm"),
    ("ratio_xyz", "RATIO_XYZ", ""),
    ("ratio_dense", "RATIO_DENSE", ""),
    ("stereo_base_m", "STEREO_BASE", "m"),
    ("stereo_sigma_xy_mm", "STEREO_SIGMA_XY", "mm"),
    ("stereo_sigma_z_mm", "STEREO_SIGMA_Z", "mm"),
    ("exposure_spacing_m", "EXPOSURE_SPACING", "m"),
    ("line_spacing_m", "LINE_SPACING", "m"),
)


def _optional(parameters, name):
    """Value of an optional numeric parameter, or None when not given."""
    value = parameters.get(name)
    if value is None or value == "":
        return None
    try:
        value = float(value)
    except (TypeError, ValueError):
        raise InputError("{name}: '{value}' is not a number.", name=name, value=value) from None
    return None if math.isnan(value) else value


class GsdCalculatorAlgorithm(GeomaticsAlgorithm):
    """GSD, footprint and theoretical photogrammetric accuracy for one camera."""

    GROUP = "photogrammetry"

    CAMERA = "CAMERA"
    DISTANCE = "DISTANCE"
    SENSOR_WIDTH = "SENSOR_WIDTH"
    IMAGE_WIDTH = "IMAGE_WIDTH"
    FOCAL_LENGTH = "FOCAL_LENGTH"
    SENSOR_HEIGHT = "SENSOR_HEIGHT"
    IMAGE_HEIGHT = "IMAGE_HEIGHT"
    TARGET_GSD = "TARGET_GSD"
    ROUND_GSD = "ROUND_GSD"
    K_M = "K_M"
    K_S = "K_S"
    PYRAMID_LEVEL = "PYRAMID_LEVEL"
    PYRAMID_PERCENT = "PYRAMID_PERCENT"
    SUBSAMPLING_STEP = "SUBSAMPLING_STEP"
    OBSERVED_SX = "OBSERVED_SX"
    OBSERVED_SY = "OBSERVED_SY"
    OBSERVED_SZ = "OBSERVED_SZ"
    OBSERVED_SXYZ = "OBSERVED_SXYZ"
    OBSERVED_DENSE_STD = "OBSERVED_DENSE_STD"
    STEREO_BASE = "STEREO_BASE"
    FORWARD_OVERLAP = "FORWARD_OVERLAP"
    SIDE_OVERLAP = "SIDE_OVERLAP"
    OUTPUT_HTML = "OUTPUT_HTML"
    #: default camera–object distance / flying height, m (a typical drone survey)
    DEFAULT_DISTANCE = 100.0
    #: core keyword (and the names :mod:`core.photogrammetry.gsd` checks) -> parameter
    KEYWORD_PARAMETERS = {
        "distance": DISTANCE, "sensor_width": SENSOR_WIDTH, "image_width": IMAGE_WIDTH,
        "focal_length": FOCAL_LENGTH, "sensor_height": SENSOR_HEIGHT,
        "sensor_size": SENSOR_HEIGHT, "image_height": IMAGE_HEIGHT,
        "target_gsd": TARGET_GSD, "k_m": K_M, "k_s": K_S, "pyramid_level": PYRAMID_LEVEL,
        "subsampling_step": SUBSAMPLING_STEP, "observed_sx": OBSERVED_SX,
        "observed_sy": OBSERVED_SY, "observed_sz": OBSERVED_SZ,
        "observed_sxyz": OBSERVED_SXYZ, "observed_dense_std": OBSERVED_DENSE_STD,
        "stereo_base": STEREO_BASE, "forward_overlap": FORWARD_OVERLAP,
        "side_overlap": SIDE_OVERLAP}

    def name(self):
        return "gsdcalculator"

    def displayName(self):  # noqa: N802
        return self.tr("GSD and photogrammetric accuracy calculator")

    def tags(self):
        return self.tr("gsd,ground sampling distance,flying height,footprint,accuracy,"
                       "photogrammetry,drone,flight planning,dense matching").split(",")

    def shortDescription(self):  # noqa: N802
        return self.tr("Ground sampling distance, footprint and theoretical "
                       "photogrammetric accuracy of a camera at a distance.")

    def shortHelpString(self):  # noqa: N802
        observed = self.tr("Optional: gives the ratio of the observed to the theoretical "
                           "accuracy.")
        extension = self.tr("Not in the paper: gives the exposure and line spacing.")
        return build_help(self, self.tr(
            "Computes the ground sampling distance (GSD) and footprint of a camera at a "
            "given distance or flying height, and the theoretical accuracy of "
            "phototriangulation and of a dense-matching cloud (Al Khalil 2019). The "
            "paper's Nikon Coolpix P100 at 5.88 m (sensor width 6.123 mm, image width "
            "3648 px, focal length 4.6 mm) gives a GSD of 0.21455 cm/px, σxyz 1.287 mm "
            "and a footprint 7.827 m wide."),
            "DISTANCE=5.88 SENSOR_WIDTH=6.123 IMAGE_WIDTH=3648 FOCAL_LENGTH=4.6 "
            "OUTPUT_HTML=gsd.html",
            {self.CAMERA: self.tr("Fills the sensor, image and focal length values; values "
                                  "you enter override the preset."),
             self.DISTANCE: self.tr("Camera–object distance, or flying height above "
                                    "ground."),
             self.FOCAL_LENGTH: self.tr("The true focal length, not the 35 mm equivalent."),
             self.SENSOR_HEIGHT: self.tr("For the footprint height and the flight "
                                         "spacing."),
             self.IMAGE_HEIGHT: self.tr("For the footprint height and the flight spacing."),
             self.TARGET_GSD: self.tr("Gives the distance that achieves it."),
             self.ROUND_GSD: self.tr("Rounds the GSD before the derived quantities, as "
                                     "the paper does."),
             self.K_M: self.tr("0.13 for an expert operator."),
             self.PYRAMID_LEVEL: self.tr("A fraction in (0, 1], or a percentage."),
             self.OBSERVED_SX: observed, self.OBSERVED_SY: observed,
             self.OBSERVED_SZ: observed, self.OBSERVED_SXYZ: observed,
             self.OBSERVED_DENSE_STD: observed,
             self.STEREO_BASE: self.tr("Not in the paper: gives the normal-case σZ."),
             self.FORWARD_OVERLAP: extension, self.SIDE_OVERLAP: extension}) + self.tr(
            "<p><b>Formulas</b>: GSD [cm/px] = D·S<sub>W</sub>·100/(Im<sub>W</sub>·F<sub>R</sub>); "
            "footprint = D·S<sub>W</sub>/F<sub>R</sub>; σ<sub>meas</sub> = k<sub>m</sub>·GSD; "
            "σ<sub>xyz</sub> = k<sub>m</sub>·GSD·k<sub>s</sub>; matching step P = "
            "T<sub>s</sub>/N<sub>p</sub>; dense resolution R<sub>theo</sub> = P·GSD.</p>")

    def initAlgorithm(self, config=None):  # noqa: N802
        names = [self.tr("Custom (enter the values below)")] + [c.name for c in CAMERAS.values()]
        self.add(QgsProcessingParameterEnum(self.CAMERA, self.tr("Camera preset"), names,
                                            defaultValue=0))
        self.add_number(self.DISTANCE, self.tr("Camera–object distance / flying height (m)"),
                        self.DEFAULT_DISTANCE, minimum=1e-3)
        required = self.tr("Required with the Custom camera; overrides the preset.")
        self.add_number(self.SENSOR_WIDTH, self.tr("Sensor width (mm) — required with "
                                                   "Custom"),
                        minimum=0.0, optional=True, help_text=required, decimals=3)
        self.add_number(self.IMAGE_WIDTH, self.tr("Image width (px) — required with "
                                                  "Custom"),
                        minimum=0.0, optional=True, help_text=required, decimals=0)
        self.add_number(self.FOCAL_LENGTH, self.tr("Focal length, true (mm) — required "
                                                   "with Custom"),
                        minimum=0.0, optional=True, help_text=required, decimals=3)
        self.add_number(self.SENSOR_HEIGHT, self.tr("Sensor height (mm)"), minimum=0.0,
                        optional=True, advanced=True, decimals=3)
        self.add_number(self.IMAGE_HEIGHT, self.tr("Image height (px)"), minimum=0.0,
                        optional=True, advanced=True, decimals=0)
        self.add_number(self.TARGET_GSD, self.tr("Target GSD (cm/px)"), minimum=0.0,
                        optional=True)
        self.add(QgsProcessingParameterBoolean(
            self.ROUND_GSD, self.tr("Round GSD to 0.01 cm/px like the paper"), False))
        self.add_number(self.K_M, self.tr("Measurement factor k_m (px)"), core_gsd.K_M,
                        minimum=0.0, advanced=True)
        self.add_number(self.K_S, self.tr("Safety factor k_s"), core_gsd.K_S, minimum=0.0,
                        advanced=True)
        self.add_number(self.PYRAMID_LEVEL, self.tr("Dense matching pyramid level N_p "
                                                    "(fraction, or % if checked below)"),
                        core_gsd.N_P, minimum=0.0, advanced=True)
        self.add(QgsProcessingParameterBoolean(
            self.PYRAMID_PERCENT, self.tr("Pyramid level is a percentage"), False),
            advanced=True)
        self.add_number(self.SUBSAMPLING_STEP, self.tr("Dense matching subsampling step "
                                                       "T_s (px)"),
                        core_gsd.T_S, minimum=0.0, advanced=True)
        for name, label in ((self.OBSERVED_SX, self.tr("Observed σx (mm)")),
                            (self.OBSERVED_SY, self.tr("Observed σy (mm)")),
                            (self.OBSERVED_SZ, self.tr("Observed σz (mm)")),
                            (self.OBSERVED_SXYZ, self.tr("Observed σxyz (mm)")),
                            (self.OBSERVED_DENSE_STD,
                             self.tr("Observed dense-cloud std (cm)"))):
            self.add_number(name, label, minimum=0.0, optional=True, advanced=True,
                            decimals=3)
        self.add_number(self.STEREO_BASE, self.tr("Stereo base B (m) [extension]"),
                        minimum=0.0, optional=True, advanced=True)
        self.add_number(self.FORWARD_OVERLAP, self.tr("Forward overlap (%) [extension]"),
                        minimum=0.0, maximum=99.9, optional=True, advanced=True)
        self.add_number(self.SIDE_OVERLAP, self.tr("Side overlap (%) [extension]"),
                        minimum=0.0, maximum=99.9, optional=True, advanced=True)
        self.add_report_output(self.OUTPUT_HTML, self.tr("GSD calculator report"))
        self.add_report_language()
        for _, out, unit in NUMERIC_OUTPUTS:
            self.addOutput(QgsProcessingOutputNumber(out, f"{out} ({unit})" if unit else out))

    # ------------------------------------------------------------------ running
    def checkParameterValues(self, parameters, context):  # noqa: N802
        """Refuse a Custom camera without its values before the run starts."""
        ok, msg = super().checkParameterValues(parameters, context)
        if not ok:
            return ok, msg
        try:
            self.camera_inputs(parameters, context)
        except InputError as exc:
            return False, self.input_error_message(exc)
        return True, ""

    def camera_inputs(self, parameters, context) -> dict:
        """Sensor/image/focal values from the preset, overridden by entered values."""
        index = self.parameterAsEnum(parameters, self.CAMERA, context)
        key = CAMERA_KEYS[index]
        preset = CAMERAS.get(key)
        values = {}
        if preset is not None:
            values = dict(sensor_width=preset.sensor_width_mm,
                          sensor_height=preset.sensor_height_mm,
                          image_width=preset.image_width_px,
                          image_height=preset.image_height_px,
                          focal_length=preset.focal_length_mm)
        for key_, name in (("sensor_width", self.SENSOR_WIDTH),
                           ("image_width", self.IMAGE_WIDTH),
                           ("focal_length", self.FOCAL_LENGTH),
                           ("sensor_height", self.SENSOR_HEIGHT),
                           ("image_height", self.IMAGE_HEIGHT)):
            v = _optional(parameters, name)
            if v is not None:
                values[key_] = v
        for key_, name, unit in (("sensor_width", self.SENSOR_WIDTH, "mm"),
                                 ("image_width", self.IMAGE_WIDTH, "px"),
                                 ("focal_length", self.FOCAL_LENGTH, "mm")):
            if key_ not in values:
                raise InputError(self.tr(
                    "{name} ({unit}) is required with the Custom camera: enter it or "
                    "choose a camera preset.").format(name=name, unit=unit))
        return values

    def process(self, parameters, context, feedback):
        camera = self.camera_inputs(parameters, context)
        distance = self.parameterAsDouble(parameters, self.DISTANCE, context)
        with self.output_contract(parameters, context, [self.OUTPUT_HTML]) as out:
            try:
                result = core_gsd.compute(distance=distance, **camera,
                                          **self.options(parameters, context))
            except InputError as exc:
                raise named_as_parameter(exc, self) from None
            values = result.as_dict()
            outputs = {}
            for attr, name, unit in NUMERIC_OUTPUTS:
                outputs[name] = values[attr]
                if values[attr] is not None:
                    feedback.pushInfo(f"{name}: {values[attr]:.6g} {unit}")  # i18n: data
            if out.requested(self.OUTPUT_HTML):
                index = self.parameterAsEnum(parameters, self.CAMERA, context)
                preset = CAMERAS.get(CAMERA_KEYS[index])
                report = gsd_report(result, camera=preset.name if preset else None)
                out.write_text(self.OUTPUT_HTML,
                               self.render_report(report, parameters, context))
                outputs[self.OUTPUT_HTML] = out.final(self.OUTPUT_HTML)
        feedback.setProgress(100)
        return outputs

    def options(self, parameters, context) -> dict:
        """Keyword arguments of :func:`core.photogrammetry.gsd.compute` besides the camera."""
        return dict(
            target_gsd=_optional(parameters, self.TARGET_GSD),
            round_gsd=self.parameterAsBool(parameters, self.ROUND_GSD, context),
            k_m=self.parameterAsDouble(parameters, self.K_M, context),
            k_s=self.parameterAsDouble(parameters, self.K_S, context),
            pyramid_level=self.parameterAsDouble(parameters, self.PYRAMID_LEVEL, context),
            pyramid_percent=self.parameterAsBool(parameters, self.PYRAMID_PERCENT, context),
            subsampling_step=self.parameterAsDouble(parameters, self.SUBSAMPLING_STEP,
                                                    context),
            observed_sx=_optional(parameters, self.OBSERVED_SX),
            observed_sy=_optional(parameters, self.OBSERVED_SY),
            observed_sz=_optional(parameters, self.OBSERVED_SZ),
            observed_sxyz=_optional(parameters, self.OBSERVED_SXYZ),
            observed_dense_std=_optional(parameters, self.OBSERVED_DENSE_STD),
            stereo_base=_optional(parameters, self.STEREO_BASE),
            forward_overlap=_optional(parameters, self.FORWARD_OVERLAP),
            side_overlap=_optional(parameters, self.SIDE_OVERLAP))


def named_as_parameter(error: InputError, algorithm: "GsdCalculatorAlgorithm") -> InputError:
    """The core's refusal naming the parameter as the dialog and ``qgis_process`` show it.

    :func:`core_gsd.compute` names its keyword (``k_m``, or ``sensor_size`` for the
    sensor height of the footprint), which is the column name of a ``gsdbatch`` table;
    the calculator's user set “Measurement factor k_m (px)”, ``K_M`` on the command
    line: the field becomes ``“<label>” (K_M)``, the label translated like the dialog's.
    """
    name = error.fields.get("name")
    parameter = algorithm.KEYWORD_PARAMETERS.get(name)
    if parameter is None:
        return error
    return InputError(error.template, **{**error.fields,
                                         "name": algorithm.parameter_named(parameter)})


class GsdBatchAlgorithm(GeomaticsAlgorithm):
    """The GSD calculator over a table of cameras and distances."""

    GROUP = "photogrammetry"

    INPUT = "INPUT"
    ROUND_GSD = "ROUND_GSD"
    OUTPUT = "OUTPUT"

    # input column → compute() keyword
    COLUMNS = {
        "distance": "distance", "sensor_width": "sensor_width",
        "image_width": "image_width", "focal_length": "focal_length",
        "sensor_height": "sensor_height", "image_height": "image_height",
        "target_gsd": "target_gsd", "k_m": "k_m", "k_s": "k_s",
        "pyramid_level": "pyramid_level", "subsampling_step": "subsampling_step",
        "observed_sx": "observed_sx", "observed_sy": "observed_sy",
        "observed_sz": "observed_sz", "observed_sxyz": "observed_sxyz",
        "observed_dense_std": "observed_dense_std", "forward_overlap": "forward_overlap",
        "side_overlap": "side_overlap", "stereo_base": "stereo_base",
    }

    def name(self):
        return "gsdbatch"

    def displayName(self):  # noqa: N802
        return self.tr("GSD calculator over a table of cameras and distances")

    def shortHelpString(self):  # noqa: N802
        return build_help(self, self.tr(
            "Runs the GSD and accuracy calculator for every row of a table (CSV, "
            "spreadsheet or any layer) and writes a table with the inputs and all "
            "results. A row with an invalid value stops the run with an error naming the "
            "row and the column."),
            "INPUT=cameras.csv OUTPUT=gsd_results.csv",
            {self.INPUT: self.tr(
                "Columns (any case): <i>camera</i> (optional preset key: nikon_p100, "
                "dji_p4rtk, dji_p1_35, phaseone_ixm100_80), <i>distance</i> (m, required), "
                "<i>sensor_width</i> (mm), <i>image_width</i> (px), <i>focal_length</i> "
                "(mm) — required without a preset — and optionally sensor_height, "
                "image_height, target_gsd, k_m, k_s, pyramid_level, subsampling_step, "
                "observed_sx, observed_sy, observed_sz, observed_sxyz, observed_dense_std, "
                "forward_overlap, side_overlap, stereo_base (units as in the single "
                "calculator)."),
             self.ROUND_GSD: self.tr("Rounds the GSD before the derived quantities, as "
                                     "the paper does."),
             self.OUTPUT: self.tr("The input columns plus gsd_cm, footprint_width_m, "
                                  "sigma_xyz_mm, dense_resolution_cm and every other "
                                  "result.")})

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add(QgsProcessingParameterFeatureSource(
            self.INPUT, self.tr("Table of cameras and distances"),
            [QgsProcessing.TypeVector]))
        self.add(QgsProcessingParameterBoolean(
            self.ROUND_GSD, self.tr("Round GSD to 0.01 cm/px like the paper"), False))
        self.add(QgsProcessingParameterFeatureSink(
            self.OUTPUT, self.tr("GSD results"), QgsProcessing.TypeVector))

    def process(self, parameters, context, feedback):
        source = self.parameterAsSource(parameters, self.INPUT, context)
        if source is None:
            raise QgsProcessingException(self.invalidSourceError(parameters, self.INPUT))
        names = {f.name().lower(): f.name() for f in source.fields()}
        if "distance" not in names:
            raise InputError(self.tr(
                "The table has no 'distance' column (m); columns found: {0}.").format(
                    ", ".join(names.values())))
        round_gsd = self.parameterAsBool(parameters, self.ROUND_GSD, context)
        result_names = [a for a, _, _ in NUMERIC_OUTPUTS]
        # Every row is computed before anything is written: a bad row leaves no output.
        rows = []
        total = source.featureCount() or 1
        for i, feat in enumerate(source.getFeatures()):
            if feedback.isCanceled():
                raise Cancelled()
            res = self.compute_row(i + 1, feat, names, round_gsd)
            rows.append((feat, [res[a] for a in result_names]))
            feedback.setProgress(90.0 * (i + 1) / total)
        fields = QgsFields(source.fields())
        for attr in result_names:
            fields.append(QgsField(attr, QVariant.Double))
        geometry = source.wkbType() if source.wkbType() else QgsWkbTypes.NoGeometry
        dest = self.write_rows(parameters, context, fields, geometry, source.sourceCrs(),
                               rows)
        feedback.setProgress(100)
        return {self.OUTPUT: dest}

    def compute_row(self, row: int, feat, names: dict, round_gsd: bool) -> dict:
        """The calculator's results for one table row; errors name the row and column."""
        kwargs = {}
        preset_key = feat[names["camera"]] if "camera" in names else None
        if preset_key not in (None, "") and str(preset_key) != "NULL":
            cam = CAMERAS.get(str(preset_key).strip())
            if cam is None:
                raise InputError(self.tr(
                    "Row {row}: unknown camera '{cam}'; known: {known}.").format(
                        row=row, cam=preset_key, known=", ".join(CAMERAS)))
            kwargs.update(sensor_width=cam.sensor_width_mm,
                          sensor_height=cam.sensor_height_mm,
                          image_width=cam.image_width_px,
                          image_height=cam.image_height_px,
                          focal_length=cam.focal_length_mm)
        for col, kw in self.COLUMNS.items():
            if col not in names:
                continue
            raw = feat[names[col]]
            if raw is None or str(raw).strip() in ("", "NULL"):
                continue
            try:
                kwargs[kw] = float(raw)
            except (TypeError, ValueError):
                raise InputError(self.tr(
                    "Row {row}, column '{col}': '{val}' is not a number.").format(
                        row=row, col=col, val=raw)) from None
        missing = [c for c in ("distance", "sensor_width", "image_width", "focal_length")
                   if c not in kwargs]
        if missing:
            raise InputError(self.tr(
                "Row {row}: missing {cols}; give the columns or a camera preset.").format(
                    row=row, cols=", ".join(missing)))
        try:
            return core_gsd.compute(round_gsd=round_gsd, **kwargs).as_dict()
        except ValueError as exc:
            raise InputError(self.tr("Row {row}: {err}").format(row=row, err=exc)) from exc

    def write_rows(self, parameters, context, fields, geometry, crs, rows) -> str:
        """Write the result table through the output contract; returns its destination.

        A file destination is written under a temporary name and renamed only when
        complete, and may not be the input table; other destinations (a temporary or
        memory layer, a database) are written directly once every row is computed.
        """
        value = parameters.get(self.OUTPUT) if parameters else None
        static = value.sink.staticValue() if hasattr(value, "sink") else value
        if str(static or "") in ("", "TEMPORARY_OUTPUT") or \
                not _is_file_destination(str(static).split("|")[0]):
            # a temporary (memory) layer or a database: parameterAsSink alone names it,
            # and puts it on the load list once (naming it twice loaded nothing)
            return self.fill_sink(parameters, context, fields, geometry, crs, rows)
        final = self.parameterAsOutputLayer(parameters, self.OUTPUT, context)
        input_path = self.source_path(parameters, context)
        path = final.split("|")[0]
        inputs = {self.INPUT: input_path} if input_path else {}
        with OutputContract({self.OUTPUT: path}, inputs=inputs) as out:
            tmp = out.path(self.OUTPUT)
            self.fill_sink({**parameters, self.OUTPUT: tmp}, context, fields, geometry,
                           crs, rows)
        return path

    def fill_sink(self, parameters, context, fields, geometry, crs, rows) -> str:
        """Create the sink of ``parameters[OUTPUT]``, add every row, flush and close it."""
        sink, dest = self.parameterAsSink(parameters, self.OUTPUT, context, fields,
                                          geometry, crs)
        if sink is None:
            raise QgsProcessingException(self.invalidSinkError(parameters, self.OUTPUT))
        for feat, values in rows:
            out = QgsFeature(fields)
            out.setGeometry(feat.geometry())
            out.setAttributes(list(feat.attributes()) + values)
            if not sink.addFeature(out, QgsFeatureSink.FastInsert):
                raise OSError(self.tr("Could not write the result table: {0}").format(
                    sink.lastError() if hasattr(sink, "lastError") else dest))
        del sink  # flushes and closes the file
        return dest

    def source_path(self, parameters, context) -> str:
        """Local file behind the input table ('' for a memory or database layer)."""
        layer = self.parameterAsVectorLayer(parameters, self.INPUT, context)
        if layer is not None:
            path = layer.source().split("|")[0]
        else:
            value = parameters.get(self.INPUT)
            path = value.split("|")[0] if isinstance(value, str) else ""
        if path.startswith("file://"):
            path = path[len("file://"):].split("?")[0]
        return path if os.path.exists(path) else ""


def _is_file_destination(path: str) -> bool:
    """True for a plain file path (not memory:, a database URI or an OGR/postgres URI)."""
    return bool(path) and not path.startswith(("memory:", "postgres:", "postgis:", "ogr:",
                                              "spatialite:", "dbname=")) and \
        os.path.isdir(os.path.dirname(os.path.abspath(path)))

"""GCP polynomial rectification (orders 1–3) and its accuracy report.

Thin wrappers over :mod:`..core.io.gcp`, :mod:`..core.rectification.polynomial`,
:mod:`..core.rectification.accuracy` and :mod:`..core.rectification.warp`.
"""
from __future__ import annotations

import math
import os

import numpy as np
from qgis.core import (
    QgsProcessing,
    QgsProcessingException,
    QgsProcessingOutputNumber,
    QgsProcessingOutputString,
    QgsProcessingParameterBoolean,
    QgsProcessingParameterCrs,
    QgsProcessingParameterEnum,
    QgsProcessingParameterFeatureSource,
    QgsProcessingParameterField,
    QgsProcessingParameterFile,
    QgsProcessingParameterFileDestination,
    QgsProcessingParameterRasterDestination,
    QgsProcessingParameterRasterLayer,
    QgsWkbTypes,
)
from qgis.PyQt.QtCore import QT_TRANSLATE_NOOP

from ..core.errors import InputError
from ..core.io import gcp as gcp_io
from ..core.io.units import EPSG_UNITS, UNIT_ALIASES, LinearUnit, crs_units
from ..core.rectification import assess, export, report, warp
from .base import GeomaticsAlgorithm
from .helptext import build_help
from .locale import user_locale

PIXEL_ORIGINS = ("corner", "center")

#: RESAMPLING options: GDAL's method name after a translated label.
RESAMPLING_LABELS = {
    "near": QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Nearest neighbour (near)"),
    "bilinear": QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Bilinear"),
    "cubic": QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Cubic convolution (cubic)"),
    "cubicspline": QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Cubic spline (cubicspline)"),
    "lanczos": QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Lanczos windowed sinc (lanczos)"),
    "average": QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Average"),
    "mode": QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Most frequent value (mode)"),
}


def resampling_options(tr) -> list:
    """RESAMPLING enum options in ``warp.RESAMPLING`` order, translated by ``tr``."""
    return [tr(RESAMPLING_LABELS[k]) for k in warp.RESAMPLING]  # i18n: noop-list

NUMBERS = (
    ("RMS_X", QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "RMS_x (map units, divisor n)")),
    ("RMS_Y", QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "RMS_y (map units, divisor n)")),
    ("RMS_T", QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "RMS_T (map units, divisor n)")),
    ("RMS_T_QGIS", QT_TRANSLATE_NOOP("GeomaticsAlgorithm",
                                     "RMS_T with divisor n − N (QGIS Georeferencer)")),
    ("GR", QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Ground resolution GR (map units/pixel)")),
    ("SCALE", QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Map scale number S = 20000·GR")),
    ("N_GCP", QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "GCPs used in the fit")),
    ("REDUNDANCY", QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Redundancy n − N")),
    ("N_WITHIN", QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Points with RMS_i ≤ RMS_T")),
    ("LOO_RMS_T", QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Leave-one-out RMS_T (map units)")),
    ("CHECK_RMS_T", QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Check-point RMS_T (map units)")),
    ("N_CHECK", QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Independent check points")),
    ("RECOMMENDED_ORDER", QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Recommended order (0 = none)")),
    ("ACCEPTED", QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Accepted by criteria C4–C6 (1/0)")),
    ("N_DROPPED", QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "GCPs dropped by the refinement")),
    ("HONEST_RMS_T", QT_TRANSLATE_NOOP(
        "GeomaticsAlgorithm",
        "Check-point (else leave-one-out) RMS_T of the transformation used")),
)

#: TRANSFORMATION options: index -> core kind (None: polynomial of order ORDER)
TRANSFORMATIONS = (None, "polynomial1", "polynomial2", "polynomial3", "linear", "helmert",
                   "projective", "tps", assess.RECOMMENDED)

def unit_symbol(unit: str) -> str:
    """The symbol of a linear unit name ("metre" -> "m", "US survey foot" -> "ftUS").

    The one unit table of ``core/io/units.py``; an unknown name is returned as is.
    """
    key = str(unit or "").strip().lower()
    known = {u.name.lower(): u for u in EPSG_UNITS.values()}
    return (known.get(key) or UNIT_ALIASES.get(key) or LinearUnit(unit, 1.0, unit)).symbol


class TransformationParams:
    """The transformation choice shared by the single-image and the batch tools:
    TRANSFORMATION (see :data:`TRANSFORMATIONS`), ORDER, REFINE and GCP_CRS. Mixed in
    before :class:`GeomaticsAlgorithm` so its strings keep one translation context."""

    TRANSFORMATION = "TRANSFORMATION"
    ORDER = "ORDER"
    REFINE = "REFINE"
    GCP_CRS = "GCP_CRS"

    @staticmethod
    def log_word(text: str) -> str:
        """A word of the core's results (verdict, basis) in the interface language."""
        from ..core.reporting import translator
        try:
            lang = user_locale()
        except Exception:  # noqa: BLE001 - the log language is cosmetic
            lang = "en"
        return translator(lang)(text)

    def add_gcp_crs_param(self):
        """GCP_CRS: the CRS of the map coordinates when the .points file has none."""
        self.add(QgsProcessingParameterCrs(self.GCP_CRS, self.tr(
            "CRS of the GCP map coordinates (if the file does not say)"), optional=True))

    def add_transformation_params(self, *, default):
        """TRANSFORMATION (option ``default`` preselected), ORDER and REFINE."""
        self.add(QgsProcessingParameterEnum(
            self.TRANSFORMATION, self.tr("Transformation"),
            [self.tr("polynomial of the order set below"), self.tr("polynomial order 1 (affine)"),
             self.tr("polynomial order 2"), self.tr("polynomial order 3"),
             self.tr("linear (shift and scale per axis)"),
             self.tr("Helmert (shift, scale, rotation)"),
             self.tr("projective (homography)"), self.tr("thin-plate spline"),
             self.tr("recommended (lowest check-point / leave-one-out error)")],
            defaultValue=default))
        self.add_number(self.ORDER, self.tr("Polynomial order (1–3)"), 1, minimum=1,
                        maximum=3, integer=True)
        self.add(QgsProcessingParameterBoolean(
            self.REFINE, self.tr("Refine GCPs: drop the worst while over the tolerance"),
            defaultValue=False))


class _GcpBase(TransformationParams, GeomaticsAlgorithm):
    """Shared parameters and GCP loading."""

    GROUP = "rectification"

    INPUT = "INPUT"
    GCP_FILE = "GCP_FILE"
    GCP_LAYER = "GCP_LAYER"
    COL_FIELD = "COL_FIELD"
    ROW_FIELD = "ROW_FIELD"
    ID_FIELD = "ID_FIELD"
    ENABLED_FIELD = "ENABLED_FIELD"
    ROLE_FIELD = "ROLE_FIELD"
    WEIGHT_FIELD = "WEIGHT_FIELD"
    PIXEL_ORIGIN = "PIXEL_ORIGIN"
    REFINE_TOLERANCE = "REFINE_TOLERANCE"
    MIN_GCPS = "MIN_GCPS"
    GR = "GR"
    OUTPUT_HTML = "OUTPUT_HTML"

    def gcp_notes(self):
        """Help notes of the shared GCP parameters (see :func:`.helptext.build_help`)."""
        return {
            self.GCP_FILE: self.tr("A QGIS Georeferencer .points file or a CSV table with "
                                   "id, col, row, X, Y and optional enabled, role (gcp or "
                                   "check) and weight. Give the file or a point layer."),
            self.GCP_LAYER: self.tr("Its geometry gives the map coordinates; the fields "
                                    "below give the image coordinates."),
            self.GCP_CRS: self.tr("Needed when the file does not state its CRS."),
            self.TRANSFORMATION: self.tr("The last choice picks the transformation with the "
                                         "lowest check-point or leave-one-out error.") + " "
            + self.tr("A run that gives the polynomial order but no transformation (the "
                      "command line of earlier versions) uses a polynomial of that order."),
            self.REFINE: self.tr("Drops the worst point while a residual exceeds the "
                                 "tolerance, keeping at least the minimum number of GCPs."),
            self.GR: self.tr("Sets the map scale S = 20000·GR and the tolerance band 4·GR "
                             "to 6·GR of the criteria (Tishreen Univ. J. Eng. Sci. 38(2), "
                             "2016)."),
        }

    def add_gcp_parameters(self, raster_optional: bool):
        self.add(QgsProcessingParameterRasterLayer(
            self.INPUT, self.tr("Image (raster) to rectify") if not raster_optional else
            self.tr("Image (raster) the GCPs were measured on"), optional=raster_optional))
        self.add(QgsProcessingParameterFile(
            self.GCP_FILE, self.tr("GCP file (.points or CSV)"),
            QgsProcessingParameterFile.File, "", None, True,
            self.tr("GCP files (*.points *.csv *.txt);;All files (*.*)")))
        self.add(QgsProcessingParameterFeatureSource(
            self.GCP_LAYER, self.tr("…or GCP point layer"), [QgsProcessing.TypeVectorPoint],
            optional=True))
        for name, label in ((self.COL_FIELD, self.tr("Layer field: image column")),
                            (self.ROW_FIELD, self.tr("Layer field: image row")),
                            (self.ID_FIELD, self.tr("Layer field: point id")),
                            (self.ENABLED_FIELD, self.tr("Layer field: enabled (1/0)")),
                            (self.ROLE_FIELD, self.tr("Layer field: role (gcp/check)")),
                            (self.WEIGHT_FIELD, self.tr("Layer field: weight (> 0)"))):
            self.add(QgsProcessingParameterField(name, label, None, self.GCP_LAYER,
                                                 QgsProcessingParameterField.Any,
                                                 optional=True),
                     advanced=name not in (self.COL_FIELD, self.ROW_FIELD))
        self.add(QgsProcessingParameterEnum(
            self.PIXEL_ORIGIN, self.tr("Image coordinates refer to"),
            [self.tr("pixel corners: (0,0) = top-left corner of the image (GDAL/QGIS)"),
             self.tr("pixel centres: integer = centre of a pixel (0-based indices)")],
            defaultValue=0), advanced=True)
        self.add_gcp_crs_param()
        self.add_transformation_params(default=len(TRANSFORMATIONS) - 1)
        self.add_number(self.REFINE_TOLERANCE, self.tr(
            "Refinement tolerance (map units) [default: C5 limit 5·GR]"), minimum=0.0,
            optional=True, advanced=True, decimals=None)
        self.add_number(self.MIN_GCPS, self.tr(
            "Minimum GCPs kept by the refinement [default: minimum + 2]"), minimum=0,
            integer=True, optional=True, advanced=True)
        self.add_number(self.GR, self.tr("Ground resolution GR (map units/pixel) "
                                         "[default: from the GCPs]"), minimum=0.0,
                        optional=True, decimals=None)

    def add_numbers_outputs(self):
        """Declare the summary numbers and the transformation names as outputs."""
        for name, label in NUMBERS:
            self.addOutput(QgsProcessingOutputNumber(name, self.tr(label)))  # i18n: noop-list
        self.addOutput(QgsProcessingOutputString("TRANSFORMATION_USED",
                                                 self.tr("Transformation used")))
        self.addOutput(QgsProcessingOutputString("RECOMMENDED_TRANSFORMATION",
                                                 self.tr("Recommended transformation")))

    def kind(self, parameters, context) -> str:
        """Return the core transformation kind chosen by TRANSFORMATION and ORDER."""
        order_only = (parameters.get(self.TRANSFORMATION) in (None, "")
                      and parameters.get(self.ORDER) not in (None, ""))
        k = None if order_only else TRANSFORMATIONS[
            self.parameterAsEnum(parameters, self.TRANSFORMATION, context)]
        return k or f"polynomial{self.parameterAsInt(parameters, self.ORDER, context)}"

    def assess(self, parameters, context, gcps, size, unit, callbacks):
        """Refine (REFINE), evaluate and compare the GCPs for the chosen transformation."""
        min_gcps = self._optional_number(parameters, self.MIN_GCPS)
        return assess.assess_gcps(
            gcps, kind=self.kind(parameters, context),
            order=self.parameterAsInt(parameters, self.ORDER, context),
            gr=self._optional_number(parameters, self.GR), image_size=size, units=unit,
            refine=self.parameterAsBool(parameters, self.REFINE, context),
            tolerance=self._optional_number(parameters, self.REFINE_TOLERANCE),
            min_gcps=None if min_gcps is None else int(min_gcps), **callbacks)

    # ------------------------------------------------------------------ helpers
    def _optional_number(self, parameters, name):
        v = parameters.get(name)
        if v is None or v == "":
            return None
        try:
            v = float(v)
        except (TypeError, ValueError):
            raise InputError("{name}: '{value}' is not a number.", name=name,
                             value=v) from None
        return None if math.isnan(v) or v == 0 else v

    def raster_path(self, parameters, context, required: bool):
        layer = self.parameterAsRasterLayer(parameters, self.INPUT, context)
        if layer is None:
            if required:
                raise QgsProcessingException(self.tr(
                    "INPUT: no image given or it cannot be opened; give a raster file."))
            return None
        path = layer.source().split("|")[0]
        if not os.path.exists(path):
            raise QgsProcessingException(self.tr(
                "INPUT: {0} is not a local raster file; save the image to a file first.")
                .format(path))
        return path

    def crs_param(self, parameters, name, context) -> str:
        crs = self.parameterAsCrs(parameters, name, context)
        return crs.toWkt() if crs is not None and crs.isValid() else ""

    def load_gcps(self, parameters, context, raster):
        gfile = self.parameterAsFile(parameters, self.GCP_FILE, context)
        origin = PIXEL_ORIGINS[self.parameterAsEnum(parameters, self.PIXEL_ORIGIN, context)]
        crs = self.crs_param(parameters, self.GCP_CRS, context)
        layer_given = parameters.get(self.GCP_LAYER) not in (None, "")
        if gfile and layer_given:
            raise QgsProcessingException(self.tr(
                "Give either GCP_FILE or GCP_LAYER, not both."))
        gt = None
        if raster:
            gt = warp.image_info(raster)[3]
        if gfile:
            g = gcp_io.read_gcps(gfile, pixel_origin=origin, crs=crs, source_geotransform=gt)
            if crs and g.crs and not warp.same_crs(crs, g.crs):
                g.notes.append("GCP_CRS differs from the '#CRS:' line of the file; the "
                               "file's CRS was used.")
            return g, gfile
        if layer_given:
            return self.load_layer(parameters, context, origin), self.layer_path(parameters)
        if raster and os.path.exists(raster + ".points"):
            g = gcp_io.read_gcps(raster + ".points", crs=crs, source_geotransform=gt)
            g.notes.append("GCP file found next to the image (the Georeferencer's "
                           "<image>.points).")
            return g, raster + ".points"
        raise QgsProcessingException(self.tr(
            "No GCPs: give a GCP file (GCP_FILE, .points or CSV) or a point layer "
            "(GCP_LAYER with COL_FIELD and ROW_FIELD); no <image>.points file was found "
            "next to the image either."))

    def layer_path(self, parameters):
        """File behind GCP_LAYER when it is a file (for the output contract), else None."""
        value = parameters.get(self.GCP_LAYER)
        if isinstance(value, str):
            path = value.split("|")[0]
            return path if os.path.exists(path) else None
        try:
            path = value.source().split("|")[0]
        except AttributeError:
            return None
        return path if os.path.exists(path) else None

    def _feature_record(self, feat, k, fields):
        """``(id, [col, row], [X, Y], enabled, role, weight or None)`` of one feature."""
        geom = feat.geometry()
        if geom is None or geom.isEmpty():
            raise QgsProcessingException(self.tr(
                "GCP layer feature {0} has no geometry.").format(feat.id()))
        pt = (geom.asMultiPoint()[0] if QgsWkbTypes.isMultiType(geom.wkbType())
              else geom.asPoint())
        where = f"GCP layer feature {feat.id()}"
        vals = [self._number_field(feat, fields[key], where)
                for key in (self.COL_FIELD, self.ROW_FIELD)]
        pid = str(feat[fields[self.ID_FIELD]]) if fields[self.ID_FIELD] else str(k)
        enabled = True
        if fields[self.ENABLED_FIELD]:
            raw = feat[fields[self.ENABLED_FIELD]]
            enabled = str(raw).strip().lower() not in ("0", "false", "no", "null", "none",
                                                       "")
        role = "gcp"
        if fields[self.ROLE_FIELD]:
            rv = str(feat[fields[self.ROLE_FIELD]] or "").strip().lower()
            if rv not in gcp_io._ROLE_ALIASES:
                raise InputError("{where}: role must be 'gcp' or 'check', got {value}.",
                                 where=where, value=repr(rv))
            role = gcp_io._ROLE_ALIASES[rv]
        weight = (self._number_field(feat, fields[self.WEIGHT_FIELD], where)
                  if fields[self.WEIGHT_FIELD] else None)
        return pid, vals, [pt.x(), pt.y()], enabled, role, weight

    @staticmethod
    def _number_field(feat, name, where):
        raw = feat[name]
        try:
            return float(raw)
        except (TypeError, ValueError):
            raise InputError("{where}: field '{name}' must be a number, got {value}.",
                             where=where, name=name, value=repr(raw)) from None

    def load_layer(self, parameters, context, origin):
        source = self.parameterAsSource(parameters, self.GCP_LAYER, context)
        if source is None:
            raise QgsProcessingException(self.invalidSourceError(parameters, self.GCP_LAYER))
        fields = {}
        for key in (self.COL_FIELD, self.ROW_FIELD, self.ID_FIELD, self.ENABLED_FIELD,
                    self.ROLE_FIELD, self.WEIGHT_FIELD):
            names = self.parameterAsFields(parameters, key, context)
            fields[key] = names[0] if names else None
        if not fields[self.COL_FIELD] or not fields[self.ROW_FIELD]:
            raise QgsProcessingException(self.tr(
                "GCP_LAYER needs COL_FIELD and ROW_FIELD: the fields holding the image "
                "column and row of each point."))
        ids, pix, mp, en, role, wt = [], [], [], [], [], []
        for k, feat in enumerate(source.getFeatures(), start=1):
            rec = self._feature_record(feat, k, fields)
            for lst, v in zip((ids, pix, mp, en, role, wt), rec):
                if v is not None:
                    lst.append(v)
        pix = np.asarray(pix, float).reshape(-1, 2)
        notes = []
        if len(pix) and (pix[:, 1] <= 0).all() and (pix[:, 1] < 0).any():
            pix[:, 1] = -pix[:, 1]
            notes.append("Row field values are negative: QGIS convention, row = −value.")
        if origin == "center":
            pix = pix + 0.5
            notes.append("Pixel centres: 0.5 added to col and row.")
        crs = source.sourceCrs()
        return gcp_io.make_gcps(ids, pix, mp, enabled=en, role=role, weight=wt or None,
                                crs=crs.toWkt() if crs.isValid() else "",
                                source=f"layer {parameters.get(self.GCP_LAYER)}", notes=notes)

    def prepare(self, gcps, target_crs: str = ""):
        """Require a CRS; bring geographic GCPs into a projected target CRS."""
        if not gcps.crs:
            raise QgsProcessingException(self.tr(
                "The GCP map coordinates have no CRS: the file has no '#CRS:' line and "
                "GCP_CRS is not set. Set GCP_CRS (e.g. EPSG:22780) and run again."))
        unit = crs_units(gcps.crs).horizontal
        if unit.angular:
            if target_crs and not crs_units(target_crs).horizontal.angular:
                g = gcps.with_crs(target_crs)
                g.map = warp.to_crs(gcps.map, gcps.crs, target_crs)
                g.notes.append("GCP map coordinates transformed from the geographic GCP CRS "
                               "to the target CRS before fitting (as the QGIS "
                               "Georeferencer does).")
                return g, crs_units(target_crs).horizontal.name
            raise QgsProcessingException(self.tr(
                "The GCP CRS is geographic (degrees): the accuracy criteria need map units "
                "of length. Set TARGET_CRS (or GCP_CRS) to a projected CRS, e.g. the UTM "
                "zone of the image."))
        return gcps, unit.name

    def numbers(self, a):
        """Processing outputs of an :class:`~..core.rectification.assess.Assessment`."""
        out = a.summary_numbers()
        out = {k: (None if isinstance(v, float) and math.isnan(v) else v)
               for k, v in out.items()}
        out["TRANSFORMATION_USED"] = a.kind
        out["RECOMMENDED_TRANSFORMATION"] = a.comparison.recommended or ""
        return out

    def report_html(self, a, parameters, context, extra=None) -> str:
        """HTML accuracy report of an assessment in the report language."""
        lang = self.report_lang(parameters, context)
        return self.render_report(report.build_report(a, extra=extra, lang=lang),
                                  parameters, context)

    def log_assessment(self, a, unit, feedback):
        """Push the transformation, its RMS, honest error, verdict and drops to the log
        (in the interface language; the unit as its symbol)."""
        word = self.log_word
        sym = unit_symbol(unit)
        r = a.selected
        c = a.comparison
        feedback.pushInfo(self.tr(
            "{kind}: fit RMS_T = {fit:.4f} {unit}, {basis} RMS_T = {honest:.4f} {unit} "
            "(n = {n}); verdict: {verdict}.").format(
                kind=a.kind, fit=r.fit.rms_t, unit=sym,
                basis=word(assess.honest_label(c.basis)), honest=r.score(c.basis),
                n=r.n_gcps, verdict=word(a.verdict)))
        if c.recommended:
            ranking = "; ".join(f"{k}: {c.results[k].score(c.basis):.4g}"
                                for k in c.ranking())
            feedback.pushInfo(self.tr(
                "Recommended transformation: {kind}, the fewest parameters among those "
                "within 10 % of the best {basis} RMS_T ({ranking} {unit}).").format(
                    kind=c.recommended, basis=word(assess.honest_label(c.basis)),
                    ranking=ranking, unit=sym))
        else:
            feedback.pushInfo(self.tr(
                "No transformation has enough GCPs to be judged on independent residuals; "
                "add GCPs."))
        for d in a.dropped:
            feedback.pushWarning(self.tr(
                "Refinement dropped GCP {id} (residual {residual:.4f} {unit}; {left} "
                "left).").format(id=d["id"], residual=d["residual"], unit=sym,
                                 left=d["n_after"]))




class RectifyGcpAlgorithm(_GcpBase):
    """Warp an image with GCPs and a polynomial of order 1–3, with the accuracy report."""

    TARGET_CRS = "TARGET_CRS"
    RESAMPLING = "RESAMPLING"
    RESOLUTION = "RESOLUTION"
    NODATA = "NODATA"
    OUTPUT = "OUTPUT"

    def name(self):
        return "rectifygcp"

    def displayName(self):  # noqa: N802
        return self.tr("Rectify image with GCPs")

    def tags(self):
        return self.tr("georeference,georeferencer,gcp,ground control points,polynomial,"
                       "rectification,warp,gdalwarp,rms,accuracy").split(",")

    def shortHelpString(self):  # noqa: N802
        return build_help(self, self.tr(
            "Rectifies (warps) an image with ground control points through GDAL: a "
            "polynomial of order 1–3, a linear, Helmert, projective or thin-plate-spline "
            "transformation, or the one with the lowest check-point error. It writes the "
            "accuracy report by the paper's criteria and never modifies the input image."),
            "INPUT=scan.tif GCP_FILE=scan.tif.points TRANSFORMATION=8 REFINE=true "
            "OUTPUT=scan_rect.tif OUTPUT_HTML=scan_rect.html",
            {**self.gcp_notes(),
             self.TARGET_CRS: self.tr("GDAL reprojects after the transformation."),
             self.RESAMPLING: self.tr("Nearest neighbour, as in the paper."),
             self.NODATA: self.tr("Default: the input's nodata, else 0.")})

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add_gcp_parameters(raster_optional=False)
        self.add(QgsProcessingParameterCrs(self.TARGET_CRS, self.tr(
            "Target CRS [default: the GCP CRS]"), optional=True))
        self.add(QgsProcessingParameterEnum(self.RESAMPLING, self.tr("Resampling"),
                                            resampling_options(self.tr), defaultValue=0))
        self.add_number(self.RESOLUTION, self.tr("Output resolution (target CRS units) "
                                                 "[default: GR]"), minimum=0.0, optional=True,
                        decimals=None)
        self.add_number(self.NODATA, self.tr("Output nodata value"), optional=True,
                        advanced=True)
        self.add(QgsProcessingParameterRasterDestination(self.OUTPUT,
                                                         self.tr("Rectified image")))
        self.add_report_output(self.OUTPUT_HTML, self.tr("GCP rectification report"),
                               create_by_default=True)
        self.add_report_language()
        self.add_numbers_outputs()

    def process(self, parameters, context, feedback):
        raster = self.raster_path(parameters, context, required=True)
        out_path = self.parameterAsOutputLayer(parameters, self.OUTPUT, context)
        if os.path.splitext(out_path)[1].lower() not in (".tif", ".tiff"):
            raise QgsProcessingException(self.tr(
                "OUTPUT must be a GeoTIFF file (.tif); got {0}.").format(out_path))
        parameters = dict(parameters, **{self.OUTPUT: out_path})
        target = self.crs_param(parameters, self.TARGET_CRS, context)
        gcps, gcp_path = self.load_gcps(parameters, context, raster)
        with self.output_contract(parameters, context, [self.OUTPUT, self.OUTPUT_HTML],
                                  inputs={self.INPUT: raster, "GCP_FILE": gcp_path}) as out:
            gcps, unit = self.prepare(gcps, target)
            width, height, _, _ = warp.image_info(raster)
            gcp_io.check_in_image(gcps, width, height)
            cb = self.core_callbacks(feedback)
            a = self.assess(parameters, context, gcps, (width, height), unit, {
                "progress": (lambda f: cb["progress"](0.1 * f)) if cb["progress"] else None,
                "cancel": cb["cancel"]})
            self.log_assessment(a, unit, feedback)
            resampling = warp.RESAMPLING[self.parameterAsEnum(parameters, self.RESAMPLING,
                                                              context)]
            res = warp.rectify(
                raster, a.gcps, out.path(self.OUTPUT), kind=a.kind,
                target_crs=target or None, resampling=resampling,
                resolution=self._optional_number(parameters, self.RESOLUTION),
                nodata=(None if parameters.get(self.NODATA) in (None, "") else
                        self.parameterAsDouble(parameters, self.NODATA, context)),
                progress=(lambda f: cb["progress"](0.1 + 0.9 * f)) if cb["progress"] else None,
                cancel=cb["cancel"])
            for note in res.model.warnings:
                feedback.pushWarning(note)
            outputs = {self.OUTPUT: out.final(self.OUTPUT)}
            outputs.update(self.numbers(a))
            if out.requested(self.OUTPUT_HTML):
                extra = {"rectified image": out.final(self.OUTPUT), "resampling": resampling,
                         "output resolution": f"{res.resolution:.6g}",
                         "output size": f"{res.width} × {res.height} px"}
                out.write_text(self.OUTPUT_HTML, self.report_html(a, parameters, context,
                                                                  extra))
                outputs[self.OUTPUT_HTML] = out.final(self.OUTPUT_HTML)
        label = self.tr(RESAMPLING_LABELS[resampling])  # i18n: noop-list
        feedback.pushInfo(self.tr(
            "Wrote {path}: {width} × {height} px at {resolution:.6g} {unit}/px, resampling "
            "{resampling}.").format(path=outputs[self.OUTPUT], width=res.width,
                                     height=res.height, resolution=res.resolution,
                                     unit=unit_symbol(unit), resampling=label))
        feedback.setProgress(100)
        return outputs


class GcpAccuracyReportAlgorithm(_GcpBase):
    """Accuracy report of a GCP set for orders 1–3, without warping."""

    IMAGE_WIDTH = "IMAGE_WIDTH"
    IMAGE_HEIGHT = "IMAGE_HEIGHT"
    OUTPUT_CSV = "OUTPUT_CSV"
    OUTPUT_JSON = "OUTPUT_JSON"

    def name(self):
        return "gcpaccuracyreport"

    def displayName(self):  # noqa: N802
        return self.tr("GCP accuracy report")

    def tags(self):
        return self.tr("georeference,gcp,ground control points,rms,residuals,accuracy,"
                       "check points,leave-one-out,polynomial,georeferencer").split(",")

    def shortHelpString(self):  # noqa: N802
        return build_help(self, self.tr(
            "Judges a set of ground control points without warping: every transformation "
            "side by side by the paper's criteria on check points and leave-one-out "
            "residuals. It recommends one transformation, says why, and suggests points "
            "to drop."),
            "INPUT=scan.tif GCP_FILE=scan.tif.points TRANSFORMATION=8 GR=0.91 "
            "OUTPUT_HTML=gcp.html OUTPUT_CSV=residuals.csv",
            {**self.gcp_notes(),
             self.INPUT: self.tr("Gives the image size; without it give the image width "
                                 "and height, or the GCP centroid is used."),
             self.OUTPUT_CSV: self.tr("One row per point with its residuals in map units "
                                      "and pixels.")})

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add_gcp_parameters(raster_optional=True)
        self.add_number(self.IMAGE_WIDTH, self.tr("Image width (px) if no image is given"),
                        minimum=0, integer=True, optional=True, advanced=True)
        self.add_number(self.IMAGE_HEIGHT, self.tr("Image height (px) if no image is "
                                                   "given"),
                        minimum=0, integer=True, optional=True, advanced=True)
        self.add_report_output(self.OUTPUT_HTML, self.tr("GCP accuracy report"),
                               create_by_default=True)
        self.add(QgsProcessingParameterFileDestination(
            self.OUTPUT_CSV, self.tr("Residuals table"), self.tr("CSV files (*.csv)"),
            optional=True, createByDefault=False))
        self.add(QgsProcessingParameterFileDestination(
            self.OUTPUT_JSON, self.tr("GCP accuracy report as JSON"),
            self.tr("JSON files (*.json)"),
            optional=True, createByDefault=False))
        self.add_report_language()
        self.add_numbers_outputs()
        for t in (1, 2, 3):
            self.addOutput(QgsProcessingOutputNumber(
                f"RMS_T_ORDER{t}", self.tr("RMS_T of order {} (map units)").format(t)))
            self.addOutput(QgsProcessingOutputNumber(
                f"LOO_RMS_T_ORDER{t}", self.tr("Leave-one-out RMS_T of order {}").format(t)))

    def process(self, parameters, context, feedback):
        raster = self.raster_path(parameters, context, required=False)
        gcps, gcp_path = self.load_gcps(parameters, context, raster)
        names = [self.OUTPUT_HTML, self.OUTPUT_CSV, self.OUTPUT_JSON]
        with self.output_contract(parameters, context, names,
                                  inputs={self.INPUT: raster, "GCP_FILE": gcp_path}) as out:
            gcps, unit = self.prepare(gcps)
            size = self.image_size(parameters, raster)
            if size is not None:
                gcp_io.check_in_image(gcps, *size)
            a = self.assess(parameters, context, gcps, size, unit,
                            self.core_callbacks(feedback))
            self.log_summary(a.acc, a.acc.order, unit, feedback)
            self.log_assessment(a, unit, feedback)
            outputs = self.numbers(a)
            for t in (1, 2, 3):
                r = a.acc.results.get(t)
                ok = r is not None and r.ok
                outputs[f"RMS_T_ORDER{t}"] = r.stats.rms_t if ok else None
                outputs[f"LOO_RMS_T_ORDER{t}"] = r.loo_rms if ok else None
            writers = {self.OUTPUT_HTML: lambda: self.report_html(a, parameters, context),
                       self.OUTPUT_CSV: lambda: export.to_csv(a.acc),
                       self.OUTPUT_JSON: lambda: export.to_json(a.acc)}
            for name in names:
                if out.requested(name):
                    out.write_text(name, writers[name]())
                    outputs[name] = out.final(name)
        feedback.setProgress(100)
        return outputs

    def image_size(self, parameters, raster):
        """``(width, height)`` from the image, IMAGE_WIDTH/IMAGE_HEIGHT, or None."""
        if raster:
            width, height, _, _ = warp.image_info(raster)
            return (width, height)
        w = self._optional_number(parameters, self.IMAGE_WIDTH)
        h = self._optional_number(parameters, self.IMAGE_HEIGHT)
        return (int(w), int(h)) if w and h else None

    def log_summary(self, acc, order, unit, feedback):
        """Push the RMS, verdict and recommended order to the log."""
        s = acc.selected.stats
        sym = unit_symbol(unit)
        qgis = "–" if s.rms_t_qgis is None else f"{s.rms_t_qgis:.4f}"
        feedback.pushInfo(self.tr(
            "Order {order}: RMS_T = {rms:.4f} {unit} (divisor n), {qgis} {unit} (divisor "
            "n − N); {within}/{n} within RMS_T; verdict: {verdict}.").format(
                order=order, rms=s.rms_t, unit=sym, qgis=qgis, within=s.n_within, n=s.n,
                verdict=self.log_word(acc.verdict)))
        if acc.recommended:
            feedback.pushInfo(self.tr("Recommended polynomial order: {order}.").format(
                order=acc.recommended))
        else:
            feedback.pushInfo(self.tr(
                "No polynomial order has enough redundancy to be recommended (n ≥ 5, 9, "
                "15 GCPs for orders 1, 2, 3)."))

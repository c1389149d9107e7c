"""Ground filter accuracy against reference labels (Processing algorithm)."""
from __future__ import annotations

from qgis.core import (
    QgsProcessingOutputNumber,
    QgsProcessingParameterFileDestination,
    QgsProcessingParameterString,
)
from qgis.PyQt.QtCore import QT_TRANSLATE_NOOP

from ..core.io.las import write_las_like
from ..core.lidar import accuracy_file as core_fa
from ..core.progress import Cancelled
from .base import LAS_OUT_FILTER, GeomaticsAlgorithm
from .helptext import build_help


class GroundFilterAccuracyAlgorithm(GeomaticsAlgorithm):
    """Type I / Type II / total error and kappa of a ground filter (ISPRS measures)."""

    GROUP = "accuracy"

    INPUT = "INPUT"
    FIELD = "FIELD"
    GROUND_CLASSES = "GROUND_CLASSES"
    REFERENCE = "REFERENCE"
    REFERENCE_FIELD = "REFERENCE_FIELD"
    REFERENCE_GROUND_CLASSES = "REFERENCE_GROUND_CLASSES"
    OUTPUT_HTML = "OUTPUT_HTML"
    ERROR_OUTPUT = "ERROR_OUTPUT"

    OUTPUTS = (("a", "A", QT_TRANSLATE_NOOP(
                   "GeomaticsAlgorithm", "reference ground → filtered ground")),
               ("b", "B", QT_TRANSLATE_NOOP(
                   "GeomaticsAlgorithm", "reference ground → filtered object (Type I)")),
               ("c", "C", QT_TRANSLATE_NOOP(
                   "GeomaticsAlgorithm", "reference object → filtered ground (Type II)")),
               ("d", "D", QT_TRANSLATE_NOOP(
                   "GeomaticsAlgorithm", "reference object → filtered object")),
               ("n", "N", QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "points")),
               ("type1", "TYPE1", QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Type I error (%)")),
               ("type2", "TYPE2", QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Type II error (%)")),
               ("total", "TOTAL", QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Total error (%)")),
               ("kappa", "KAPPA", QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Cohen's kappa (%)")))

    def name(self):
        return "groundfilteraccuracy"

    def displayName(self):  # noqa: N802
        return self.tr("Ground filter accuracy")

    def tags(self):
        return self.tr("lidar,ground,filter,accuracy,type i,type ii,total error,kappa,"
                       "isprs,reference,confusion matrix").split(",")

    def shortHelpString(self):  # noqa: N802
        return build_help(self, self.tr(
            "Compares a filtered point cloud with reference labels using the measures of "
            "the ISPRS filter test (Sithole &amp; Vosselman 2004): the cross matrix, "
            "Type I = b/(a+b), Type II = c/(c+d), total error and Cohen's kappa. An "
            "optional per-point error cloud shows where the filter fails."),
            "INPUT=classified.laz REFERENCE=samp54.laz OUTPUT_HTML=accuracy.html "
            "ERROR_OUTPUT=errors.laz",
            {self.GROUND_CLASSES: self.tr("A list such as 2,8 is accepted; every other "
                                          "class counts as an object."),
             self.REFERENCE: self.tr("Checked: equal count and coordinates. When empty, "
                                     "the reference labels are read from another dimension "
                                     "of the filtered cloud."),
             self.REFERENCE_FIELD: self.tr("E.g. user_data or an extra dimension when "
                                           "there is no reference cloud."),
             self.ERROR_OUTPUT: self.tr("A copy of the filtered cloud; style it by "
                                        "user_data to map the errors.")})

    def initAlgorithm(self, config=None):  # noqa: N802
        self.add_las_input(self.INPUT, self.tr("Filtered point cloud (LAS/LAZ)"))
        self.add(QgsProcessingParameterString(
            self.FIELD, self.tr("Class dimension of the filtered cloud"), "classification"),
            advanced=True)
        self.add(QgsProcessingParameterString(
            self.GROUND_CLASSES, self.tr("Ground classes of the filtered cloud"), "2"))
        self.add_las_input(self.REFERENCE,
                           self.tr("Reference point cloud (same points, same order)"),
                           optional=True)
        self.add(QgsProcessingParameterString(
            self.REFERENCE_FIELD, self.tr("Reference class dimension"), "classification"))
        self.add(QgsProcessingParameterString(
            self.REFERENCE_GROUND_CLASSES, self.tr("Reference ground classes"), "2"))
        self.add_report_language()
        self.add_report_output(self.OUTPUT_HTML, self.tr("Ground filter accuracy report"))
        self.add(QgsProcessingParameterFileDestination(
            self.ERROR_OUTPUT, self.tr("Per-point error layer (user_data: 0 correct, "
                                       "1 Type I, 2 Type II)"),
            LAS_OUT_FILTER, optional=True, createByDefault=False))
        for _, out, label in self.OUTPUTS:
            self.addOutput(QgsProcessingOutputNumber(
                out, f"{out}: {self.tr(label)}"))  # i18n: noop-list

    def process(self, parameters, context, feedback):
        src = self.las_input_path(parameters, context, self.INPUT)
        ref = self.las_input_path(parameters, context, self.REFERENCE) or None
        html_out = self.parameterAsFileOutput(parameters, self.OUTPUT_HTML, context)
        err_out = self.parameterAsFileOutput(parameters, self.ERROR_OUTPUT, context)
        field = self.parameterAsString(parameters, self.FIELD, context).strip()
        ref_field = self.parameterAsString(parameters, self.REFERENCE_FIELD, context).strip()
        gc = core_fa.parse_classes(self.parameterAsString(parameters, self.GROUND_CLASSES,
                                                          context))
        rgc = core_fa.parse_classes(
            self.parameterAsString(parameters, self.REFERENCE_GROUND_CLASSES, context),
            name="reference ground classes")
        contract = self.output_contract(parameters, context,
                                         [self.OUTPUT_HTML, self.ERROR_OUTPUT],
                                         inputs={self.INPUT: src, self.REFERENCE: ref})
        cb = self.core_callbacks(feedback)
        res = core_fa.assess_clouds(
            src, ref, field=field, ground_classes=gc, reference_field=ref_field,
            reference_ground_classes=rgc,
            progress=(lambda f: cb["progress"](0.7 * f)) if cb["progress"] else None,
            cancel=cb["cancel"])
        acc = res.accuracy.as_dict()
        for key, out, label in self.OUTPUTS:
            feedback.pushInfo(  # i18n: data
                f"{out} ({self.tr(label)}): {acc[key]:.6g}")  # i18n: noop-list
        with contract as out:
            if err_out:
                write_las_like(src, out.path(self.ERROR_OUTPUT),
                               dimensions={"user_data": res.error_codes()},
                               progress=(lambda f: cb["progress"](0.7 + 0.29 * f))
                               if cb["progress"] else None, cancel=cb["cancel"])
            if html_out:
                inputs = core_fa.AssessmentInputs(src, ref, field, ref_field, gc, rgc)
                report = core_fa.accuracy_report(
                    res, inputs, lang=self.report_lang(parameters, context))
                out.write_text(self.OUTPUT_HTML,
                               self.render_report(report, parameters, context))
            if feedback.isCanceled():
                raise Cancelled("cancelled by the user")
        feedback.setProgress(100)
        result = {out: acc[key] for key, out, _ in self.OUTPUTS}
        if html_out:
            result[self.OUTPUT_HTML] = html_out
        if err_out:
            result[self.ERROR_OUTPUT] = err_out
        return result

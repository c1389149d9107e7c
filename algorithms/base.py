"""Common base for every Geomatics Toolbox Processing algorithm.

Subclasses set ``GROUP`` to one of the keys of :data:`GROUPS`, implement
``name``/``displayName``/``shortHelpString``/``initAlgorithm`` and put their work in
:meth:`GeomaticsAlgorithm.process` (not ``processAlgorithm``, and not ``run``,
which is QgsProcessingAlgorithm's own method): the base class turns
core ``ValueError``/``OSError``, cancellation and unexpected errors into a
:class:`QgsProcessingException` with a clear message, so that every failure is
reported as a failure and never as a silent success.

Translations: call ``self.tr('…')`` with a string literal inside the subclass body
(pylupdate5 then files it under the subclass's name, which is the context
:meth:`tr` uses at run time).
"""
from __future__ import annotations

import os
import re
import traceback

from qgis.core import (
    QgsProcessingAlgorithm,
    QgsProcessingContext,
    QgsProcessingException,
    QgsProcessingParameterBoolean,
    QgsProcessingParameterDefinition,
    QgsProcessingParameterFile,
    QgsProcessingParameterNumber,
    QgsProcessingUtils,
    QgsProviderRegistry,
)
from qgis.PyQt.QtCore import QT_TRANSLATE_NOOP, QCoreApplication, QUrl
from qgis.PyQt.QtGui import QIcon

from ..core import deps
from ..core.errors import InputError, message_text
from ..core.io.contract import OutputContract, Terminated, atomic_output
from ..core.progress import Cancelled
from ..core.reporting import T, about_rows, render_html
from .locale import user_locale

ICON_DIR = os.path.join(os.path.dirname(os.path.dirname(__file__)), "provider", "icons")
ICON = os.path.join(ICON_DIR, "geomatics.svg")
#: help pages shipped with the plugin (scripts/build_help.py writes them)
HELP_DIR = os.path.join(os.path.dirname(os.path.dirname(__file__)), "help")


def first_sentence(html: str) -> str:
    """The first sentence of an HTML help text, as plain text."""
    text = re.sub(r"<[^>]+>", "", html or "")
    text = re.sub(r"\s+", " ", text).strip()
    match = re.match(r"(.+?[.!?。؟])(\s|$)", text)
    sentence = match.group(1) if match else text
    if len(sentence) > 200:      # a tooltip, not a paragraph
        sentence = sentence[:200].rsplit(" ", 1)[0].rstrip(",;:") + " …"
    return sentence


def plugin_version() -> str:
    """The ``version`` of the plugin's metadata.txt ('' when unreadable)."""
    import configparser
    parser = configparser.ConfigParser(interpolation=None)
    try:
        parser.read(os.path.join(os.path.dirname(os.path.dirname(__file__)), "metadata.txt"),
                    encoding="utf-8")
        return parser.get("general", "version", fallback="")
    except (OSError, configparser.Error):
        return ""


def default_decimals(value, most: int = 6) -> int:
    """Decimals needed to show ``value`` exactly (at most ``most``); 0 for None."""
    if value is None:
        return 0
    text = f"{float(value):.{most}f}".rstrip("0")
    return len(text.split(".")[1]) if "." in text else 0


def _groups():
    # Literal translate() calls so that pylupdate5 finds the group names.
    return {
        "lidarfiltering": QCoreApplication.translate("GeomaticsAlgorithm",
                                                     "LiDAR ground filtering"),
        "terrain": QCoreApplication.translate("GeomaticsAlgorithm", "Terrain models"),
        "rectification": QCoreApplication.translate("GeomaticsAlgorithm",
                                                    "Image rectification"),
        "photogrammetry": QCoreApplication.translate("GeomaticsAlgorithm", "Photogrammetry"),
        "accuracy": QCoreApplication.translate("GeomaticsAlgorithm", "Accuracy assessment"),
        "setup": QCoreApplication.translate("GeomaticsAlgorithm", "Set-up"),
    }


GROUPS = tuple(_groups())

#: File filter of LAS/LAZ inputs given as files.
LAS_IN_FILTER = "LAS/LAZ point clouds (*.las *.laz *.LAS *.LAZ)"
#: file filter of a classified-cloud output (the one definition; imported by the algorithms)
LAS_OUT_FILTER = "LAZ point cloud (*.laz);;LAS point cloud (*.las)"
_LAS_EXTENSIONS = (".las", ".laz")


def point_cloud_layers_supported(path: str | None = None) -> bool:
    """True when this QGIS build can open LAS/LAZ as point-cloud layers (PDAL provider),
    or, given ``path``, that file (a ``.copc.laz`` needs no PDAL from QGIS 3.26 on).

    Debian's QGIS 3.22 is built without PDAL: there LiDAR inputs are file paths.
    """
    try:
        from qgis.core import QgsProcessingParameterPointCloudLayer  # noqa: F401
    except ImportError:  # QGIS < 3.18
        return False
    providers = QgsProviderRegistry.instance().providerList()
    if "pdal" in providers:
        return True
    return bool(path) and path.lower().endswith(".copc.laz") and "copc" in providers


#: parameter types read with parameterAsOutputLayer (loaded into the map on request)
LAYER_DESTINATIONS = ("rasterDestination", "vectorDestination", "sink")


def copc_layers_supported() -> bool:
    """True when this QGIS build reads COPC files (.copc.laz) as point-cloud layers.

    QGIS 3.26 and later have a native ``copc`` provider that needs no PDAL.
    """
    return "copc" in QgsProviderRegistry.instance().providerList()


class GeomaticsAlgorithm(QgsProcessingAlgorithm):
    """Base class: groups, icon, translation, error handling, core callbacks."""

    GROUP = "photogrammetry"
    #: groups of runtime packages (core/deps.py) the algorithm always needs; a LiDAR
    #: input or a .las/.laz path given adds 'lidar'
    REQUIRES: tuple = ()

    # ---------------------------------------------------------------- metadata
    def tr(self, text: str) -> str:
        """Translate ``text``: the class's own context first, then its base classes'
        (shared strings written in a common base), then the shared ``GeomaticsAlgorithm`` context
        (``QT_TRANSLATE_NOOP`` help pieces), then ``@default`` (pylupdate5's context
        for ``tr`` aliases such as ``tr = self.tr``)."""
        for cls in type(self).__mro__:
            if cls is GeomaticsAlgorithm:
                break
            out = QCoreApplication.translate(cls.__name__, text)  # i18n: noop-list
            if out != text:
                return out
        for context in ("GeomaticsAlgorithm", "@default"):
            out = QCoreApplication.translate(context, text)  # i18n: noop-list
            if out != text:
                return out
        return text

    def createInstance(self):  # noqa: N802 - QGIS API name
        return type(self)()

    def group(self) -> str:
        return _groups()[self.GROUP]

    def groupId(self) -> str:  # noqa: N802 - QGIS API name
        return self.GROUP

    def icon(self) -> QIcon:
        return QIcon(self.svgIconPath())

    def svgIconPath(self) -> str:  # noqa: N802 - QGIS API name
        """The algorithm's own icon (``provider/icons/<name>.svg``, scripts/build_icons.py)."""
        path = os.path.join(ICON_DIR, f"{self.name()}.svg")
        return path if os.path.isfile(path) else ICON

    def shortDescription(self) -> str:  # noqa: N802 - QGIS API name
        """Toolbox tooltip: the first sentence of the help (override for a better one)."""
        return first_sentence(self.shortHelpString())

    def helpUrl(self) -> str:  # noqa: N802 - QGIS API name
        """The help page shipped with the plugin, in the interface language if present."""
        try:
            lang = user_locale()
        except Exception:  # noqa: BLE001 - the help language is cosmetic
            lang = "en"
        for sub in ((lang,) if lang and lang != "en" else ()) + ("",):
            path = os.path.join(HELP_DIR, sub, f"{self.name()}.html")
            if os.path.isfile(path):
                return QUrl.fromLocalFile(path).toString()
        return ""

    # ---------------------------------------------------------------- parameters
    def parameter_named(self, name: str):
        """A parameter as the user sees it, for an :class:`InputError` field:
        ``“<dialog label>” (NAME)`` — the label in the message's language (translated
        from the same strings as the dialog's), ``NAME`` as ``qgis_process`` takes it."""
        definition = self.parameterDefinition(name)
        label = definition.description() if definition is not None else name
        return T("\u201c{label}\u201d ({name})", label=T(label), name=name)

    def add_number(self, name: str, label: str, default=None, *, minimum=None,
                   maximum=None, integer: bool = False, optional: bool = False,
                   advanced: bool = False, help_text: str | None = None,
                   decimals: int | str | None = "auto"):
        """Add a numeric parameter (double unless ``integer``); returns it.

        ``decimals``: digits the dialog's spin box shows (QGIS shows six: "50.000000");
        ``"auto"`` = two, or as many as the default needs (at most six); ``None`` keeps
        QGIS's six (values in map units, which may be degrees).
        """
        kind = (QgsProcessingParameterNumber.Integer if integer
                else QgsProcessingParameterNumber.Double)
        param = QgsProcessingParameterNumber(name, label, kind, default, optional)
        if minimum is not None:
            param.setMinimum(minimum)
        if maximum is not None:
            param.setMaximum(maximum)
        if not integer and decimals is not None:
            if decimals == "auto":
                decimals = max(2, default_decimals(default))
            param.setMetadata({**param.metadata(),
                               "widget_wrapper": {"decimals": int(decimals)}})
        return self.add(param, advanced=advanced, help_text=help_text)

    def add(self, param, *, advanced: bool = False, help_text: str | None = None):
        """Add any parameter, optionally flagged advanced; returns it."""
        if advanced:
            param.setFlags(param.flags() | QgsProcessingParameterDefinition.FlagAdvanced)
        if help_text:
            param.setHelp(help_text)
        self.addParameter(param)
        return param

    # ---------------------------------------------------------------- LiDAR inputs
    def las_input_note(self) -> str:
        """What this QGIS build can load as a point-cloud layer, and how to give the input.

        With PDAL any LAS/LAZ is a layer; without it (Debian's QGIS 3.22 and 3.40) plain
        LAS/LAZ files are not, but QGIS 3.26 and later read COPC (.copc.laz) natively.
        Every LiDAR algorithm reads all three from a path.
        """
        if point_cloud_layers_supported():
            return self.tr("Pick a loaded point-cloud layer or a .las, .laz or .copc.laz "
                           "file.")
        if copc_layers_supported():
            return self.tr("This QGIS build has no PDAL point-cloud provider: .las/.laz "
                           "files cannot be loaded as layers here, COPC files (.copc.laz) "
                           "can (QGIS 3.26 and later read them without PDAL). Give the "
                           ".las, .laz or .copc.laz file.")
        return self.tr("This QGIS build has no PDAL point-cloud provider, so point clouds "
                       "cannot be loaded as layers (COPC needs QGIS 3.26 or later): give "
                       "the .las, .laz or .copc.laz file.")

    def add_las_input(self, name: str = "INPUT", description: str | None = None, *,
                      optional: bool = False, help_text: str | None = None):
        """Add a LAS/LAZ input: a point-cloud layer where PDAL exists, else a file.

        Either way ``qgis_process`` accepts a path. Read it back with
        :meth:`las_input_path`. The parameter's help says which kind it is and why.
        """
        description = description or self.tr("Point cloud (LAS/LAZ)")
        note = self.las_input_note()
        help_text = f"{help_text} {note}" if help_text else note
        self._las_params = getattr(self, "_las_params", set()) | {name}
        if point_cloud_layers_supported():
            from qgis.core import QgsProcessingParameterPointCloudLayer
            param = QgsProcessingParameterPointCloudLayer(name, description,
                                                          optional=optional)
        else:
            param = QgsProcessingParameterFile(
                name, description, behavior=QgsProcessingParameterFile.File,
                fileFilter=LAS_IN_FILTER, optional=optional)
        return self.add(param, help_text=help_text)

    def las_input_path(self, parameters, context, name: str = "INPUT") -> str:
        """Path of the LAS/LAZ file behind an :meth:`add_las_input` parameter ('' if unset).

        Raises :class:`InputError` when a picked layer is not a local .las/.laz file.
        """
        param = self.parameterDefinition(name)
        if isinstance(param, QgsProcessingParameterFile) or param is None:
            return self.parameterAsFile(parameters, name, context) or ""
        layer = self.parameterAsPointCloudLayer(parameters, name, context)
        if layer is None:
            value = parameters.get(name) if parameters else None
            return str(value) if isinstance(value, str) else ""
        path = layer.source().split("|")[0]
        if not (os.path.isfile(path) and path.lower().endswith(_LAS_EXTENSIONS)):
            raise InputError(self.tr(
                "The point-cloud layer '{name}' is not a local .las/.laz file ({source}): "
                "export it to LAS/LAZ first.").format(name=layer.name(), source=path))
        return path

    def load_cloud_on_completion(self, context, path: str, name: str,
                                 output_name: str = "OUTPUT") -> bool:
        """Ask QGIS to load a written LAS/LAZ output as a point-cloud layer, if it can."""
        if not path or context is None or not point_cloud_layers_supported(path):
            return False
        details = QgsProcessingContext.LayerDetails(name, context.project(), output_name,
                                                    QgsProcessingUtils.LayerHint.PointCloud)
        context.addLayerToLoadOnCompletion(path, details)
        self.style_output(context, output_name, path, "classes")
        return True

    # Shared low-outlier pre-filter (core.noise.flag_low_outliers) of the ground filters
    NOISE = "NOISE"
    NOISE_RADIUS = "NOISE_RADIUS"
    NOISE_THRESHOLD = "NOISE_THRESHOLD"

    #: help note on the NOISE default (QT_TRANSLATE_NOOP: pylupdate5 files it)
    NOISE_DEFAULT_NOTE = QT_TRANSLATE_NOOP(
        "GeomaticsAlgorithm",
        "Its default was chosen by leave-one-sample-out cross-validation over the ISPRS "
        "samples and synthetic forest, cliff, lake and bridge scenes "
        "(benchmarks/results/defaults.md).")

    def noise_note(self) -> str:
        """The translated :data:`NOISE_DEFAULT_NOTE`."""
        return self.tr(self.NOISE_DEFAULT_NOTE)  # i18n: noop-list

    def add_noise_params(self, default: bool = True) -> None:
        """NOISE (default ``default``), NOISE_RADIUS (m, 5) and NOISE_THRESHOLD (m, 1)."""
        self.add(QgsProcessingParameterBoolean(
            self.NOISE, self.tr("Remove low outliers first (class 7)"), default))
        self.add_number(self.NOISE_RADIUS, self.tr("Low-outlier search cell (m)"), 5.0,
                        minimum=0.0, advanced=True)
        self.add_number(self.NOISE_THRESHOLD,
                        self.tr("Low-outlier depth below neighbours (m)"), 1.0,
                        minimum=0.0, advanced=True)

    # ---------------------------------------------------------------- running
    @staticmethod
    def core_callbacks(feedback) -> dict:
        """``progress``/``cancel`` keyword arguments for a core function."""
        if feedback is None:
            return {"progress": None, "cancel": None}
        return {"progress": lambda f: feedback.setProgress(100.0 * f),
                "cancel": feedback.isCanceled}

    def log_units(self, feedback, units) -> None:
        """Log the data's linear units when they are not metres (DEVELOPERS.md, Units).

        Every length parameter is in metres; data in feet are converted, and the log
        says so once, in the interface language.
        """
        if feedback is None or units is None or units.metric:
            return
        from ..core.io.units import unit_label
        try:
            lang = user_locale()
        except Exception:  # noqa: BLE001 - cosmetic
            lang = "en"
        feedback.pushInfo(self.tr(
            "The data are in {} horizontally and {} vertically; they are converted to "
            "metres, so every length you give and every length in this log is in "
            "metres.").format(unit_label(units.horizontal, lang),
                              unit_label(units.vertical, lang)))

    # ---------------------------------------------------------------- reports
    REPORT_LANGUAGE = "REPORT_LANGUAGE"
    REPORT_PROJECT = "REPORT_PROJECT"
    REPORT_OPERATOR = "REPORT_OPERATOR"
    #: REPORT_LANGUAGE options: index -> language code ('' = the QGIS interface language)
    REPORT_LANGUAGES = ("", "en", "ar", "fa")

    def add_report_output(self, name: str, label: str, *,
                          create_by_default: bool = False) -> None:
        """Add the optional HTML report destination ``name`` (one definition for every
        algorithm: the file filter, optional, created only when asked unless
        ``create_by_default``)."""
        from qgis.core import QgsProcessingParameterFileDestination
        self.add(QgsProcessingParameterFileDestination(
            name, label, self.tr("HTML files (*.html)"), optional=True,
            createByDefault=create_by_default))

    def add_report_language(self) -> None:
        """Add REPORT_LANGUAGE (advanced enum; default: the QGIS interface language) and
        the optional REPORT_PROJECT and REPORT_OPERATOR shown at the top of reports."""
        from qgis.core import QgsProcessingParameterEnum, QgsProcessingParameterString
        self.add(QgsProcessingParameterEnum(
            self.REPORT_LANGUAGE, self.tr("Report language"),
            [self.tr("Interface language"), "English", "العربية", "فارسی"],
            defaultValue=0), advanced=True)
        self.add(QgsProcessingParameterString(
            self.REPORT_PROJECT, self.tr("Project name (shown in the report)"),
            optional=True), advanced=True)
        self.add(QgsProcessingParameterString(
            self.REPORT_OPERATOR, self.tr("Operator (shown in the report)"),
            optional=True), advanced=True)

    def report_lang(self, parameters=None, context=None) -> str:
        """Language code for reports: REPORT_LANGUAGE if set, else the UI language."""
        if parameters is not None and self.parameterDefinition(self.REPORT_LANGUAGE):
            index = self.parameterAsEnum(parameters, self.REPORT_LANGUAGE, context)
            if 0 < index < len(self.REPORT_LANGUAGES):
                return self.REPORT_LANGUAGES[index]
        try:
            return user_locale()
        except Exception:  # noqa: BLE001 - the report language is cosmetic
            return "en"

    def render_report(self, report, parameters=None, context=None) -> str:
        """HTML of a core :class:`~..core.reporting.Report` in the report language, with
        the date, the plugin version and the optional project and operator on top."""
        return render_html(report, lang=self.report_lang(parameters, context),
                           about=self.report_about(parameters, context))

    def report_about(self, parameters=None, context=None) -> list:
        """Rows naming when, with which version and for whom a report was made."""
        def text(name):
            if parameters is None or not self.parameterDefinition(name):
                return None
            return (self.parameterAsString(parameters, name, context) or "").strip() or None
        return about_rows(version=plugin_version(), project=text(self.REPORT_PROJECT),
                          operator=text(self.REPORT_OPERATOR))

    def checkpoint_files(self, parameters, context, *, csv="CHECKPOINTS_CSV",
                         layer="CHECKPOINTS") -> dict:
        """Files behind the check-point inputs (CSV file, OGR layer's file), by parameter.

        For the output contract's same-file checks; an unset input or a non-file layer
        maps to None.
        """
        files = {csv: self.parameterAsFile(parameters, csv, context) or None}
        lyr = (self.parameterAsVectorLayer(parameters, layer, context)
               if parameters.get(layer) not in (None, "") else None)
        if lyr is not None and lyr.providerType() == "ogr":
            path = lyr.source().split("|")[0]
            files[layer] = path if os.path.exists(path) else None
        return files

    # ---------------------------------------------------------------- outputs
    def output_contract(self, parameters, context, outputs, inputs=()) -> OutputContract:
        """The :class:`OutputContract` of this run.

        ``outputs``: names of file-destination parameters (unset optional ones are
        skipped); ``inputs``: ``{parameter name: path or list of paths}`` of every file
        read. Raises a clear error before anything is written when an output is an
        input or two outputs share a path.
        """
        paths = {}
        for name in outputs:
            path = self.output_path(parameters, context, name)
            if path:
                paths[name] = path
        return OutputContract(paths, inputs=dict(inputs),
                              point_clouds=self.las_destinations())

    def las_destinations(self) -> list:
        """Names of the file destinations that are LAS/LAZ point clouds (by file filter)."""
        import re

        from qgis.core import QgsProcessingParameterFileDestination
        names = []
        for d in self.parameterDefinitions():
            if isinstance(d, QgsProcessingParameterFileDestination):
                exts = {e.lower() for e in re.findall(r"\*\.(\w+)", d.fileFilter() or "")}
                if exts and exts <= {"las", "laz"}:
                    names.append(d.name())
        return names

    def check_outputs(self, parameters, context) -> None:
        """Refuse a point-cloud output not named .las/.laz before anything runs.

        ``OUTPUT_CLOUD=c.tif`` would otherwise be found by the writer, after the whole
        computation. The one check of every algorithm (:func:`check_las_output`).
        """
        from ..core.io.contract import check_las_output
        for name in self.las_destinations():
            value = parameters.get(name) if parameters else None
            if value in (None, ""):
                continue
            path = self.parameterAsFileOutput(parameters, name, context)
            if path:
                check_las_output(name, path)

    #: style kind (:data:`.styles.KINDS`) of each layer output, by parameter name
    OUTPUT_STYLES: dict = {}

    def output_path(self, parameters, context, name: str) -> str:
        """The path of output ``name`` ('' when an optional one is unset).

        Call it once per output and run: a temporary output gets a new name at every
        call. Raster and vector destinations are read with ``parameterAsOutputLayer``,
        which puts them on the context's list of layers to load when the user asked
        for that (dialog, batch, model); :data:`OUTPUT_STYLES` then styles them.
        """
        value = parameters.get(name) if parameters else None
        if value is None or value == "":
            return ""
        param = self.parameterDefinition(name)
        if param is not None and param.type() in LAYER_DESTINATIONS:
            path = self.parameterAsOutputLayer(parameters, name, context)
            self.style_output(context, name, path)
        else:
            path = self.parameterAsFileOutput(parameters, name, context)
        return path or ""

    def style_output(self, context, name: str, path: str, kind: str | None = None) -> bool:
        """Style the layer ``path`` of output ``name`` once QGIS loads it (if it does)."""
        from .styles import style_on_completion
        return style_on_completion(context, path, kind or self.OUTPUT_STYLES.get(name))

    def load_layer_on_completion(self, context, path: str, name: str, output_name: str,
                                 kind: str | None = None, *, raster: bool = True) -> bool:
        """Ask QGIS to load a written file that is no destination parameter (the
        catalog's VRT) as a layer of the run's project, styled as ``kind``."""
        if not path or context is None or context.project() is None:
            return False
        hint = (QgsProcessingUtils.LayerHint.Raster if raster
                else QgsProcessingUtils.LayerHint.Vector)
        context.addLayerToLoadOnCompletion(path, QgsProcessingContext.LayerDetails(
            name, context.project(), output_name, hint))
        self.style_output(context, output_name, path, kind)
        return True

    @staticmethod
    def write_text(path: str, text: str) -> str:
        """Write a text output (HTML, CSV, JSON) atomically; returns ``path``."""
        with atomic_output(path) as tmp:
            with open(tmp, "w", encoding="utf-8", newline="") as fh:
                fh.write(text)
        return path

    def process(self, parameters, context, feedback) -> dict:  # pragma: no cover
        """Do the work; return the outputs dict. Subclasses implement this."""
        raise NotImplementedError

    @staticmethod
    def input_error_message(exc: InputError) -> str:
        """An :class:`InputError` in the QGIS interface language (English if untranslated).

        Core errors carry an English template and fields; the template is translated
        from ``i18n/strings/*.json`` like report text.
        """
        try:
            lang = user_locale()
        except Exception:  # noqa: BLE001 - the message language is cosmetic
            lang = "en"
        message = getattr(exc, "message", None)
        return message(lang) if callable(message) else str(exc)

    @staticmethod
    def core_message(message) -> str:
        """A core sentence (:class:`~..core.reporting.content.T`, e.g. a warning) in the
        QGIS interface language (English if untranslated)."""
        try:
            lang = user_locale()
        except Exception:  # noqa: BLE001 - the message language is cosmetic
            lang = "en"
        return message_text(message, lang)

    # ---------------------------------------------------------------- packages
    def required_packages(self, parameters) -> list:
        """Runtime package groups this run needs (``REQUIRES`` plus 'lidar' for LAS/LAZ)."""
        groups = set(self.REQUIRES)
        las_params = getattr(self, "_las_params", set())
        for name, value in (parameters or {}).items():
            if name in las_params and value not in (None, ""):
                groups.add("lidar")
            elif isinstance(value, str) and value.lower().endswith(_LAS_EXTENSIONS):
                groups.add("lidar")
        return sorted(groups)

    def missing_packages_message(self, parameters) -> str:
        """'' when every package this run needs is there, else the translated message."""
        try:
            deps.check(self.required_packages(parameters), load=True)
        except InputError as exc:
            return self.input_error_message(exc)
        return ""

    def unreadable_layer_message(self, parameters) -> str:
        """'' when every raster/vector layer given as a file opens, else the message.

        QGIS would say "Could not load source layer for DTM: … not found" of a file
        that exists but is empty, damaged or of another format.
        """
        from qgis.core import (
            QgsProcessingParameterFeatureSource,
            QgsProcessingParameterRasterLayer,
            QgsProcessingParameterVectorLayer,
        )

        from ..core.io.raster import check_raster_file
        from ..core.io.vector import check_vector_file
        vector = (QgsProcessingParameterVectorLayer, QgsProcessingParameterFeatureSource)
        for definition in self.parameterDefinitions():
            if isinstance(definition, QgsProcessingParameterRasterLayer):
                check = check_raster_file
            elif isinstance(definition, vector):
                check = check_vector_file
            else:
                continue
            value = (parameters or {}).get(definition.name())
            path = value.split("|")[0] if isinstance(value, str) else ""
            if not os.path.isfile(path):       # a layer id, a URI or a missing file
                continue
            try:
                check(path)
            except InputError as exc:
                return f"{definition.name()}: {self.input_error_message(exc)}"  # i18n: data
        return ""

    def checkParameterValues(self, parameters, context):  # noqa: N802
        """Refuse the run before it starts: a missing package, an unreadable layer file."""
        message = (self.missing_packages_message(parameters)
                   or self.unreadable_layer_message(parameters))
        if message:
            return False, message
        return super().checkParameterValues(parameters, context)

    def check_numbers(self, parameters, context) -> None:
        """Refuse a number parameter given as NaN or infinity (``THRESHOLD=nan``).

        QGIS passes such text through as a float, which comparisons like ``> 0`` then
        silently turn into "use the default"; refused before anything runs.
        """
        import math

        from qgis.core import QgsProcessingParameterNumber
        for definition in self.parameterDefinitions():
            if not isinstance(definition, QgsProcessingParameterNumber):
                continue
            name = definition.name()
            if parameters is None or parameters.get(name) in (None, ""):
                continue
            value = self.parameterAsDouble(parameters, name, context)
            if not math.isfinite(value):
                raise InputError("{name} must be a finite number, got {value}; give a value "
                                 "or leave the default.", name=name, value=value)

    def processAlgorithm(self, parameters, context, feedback):  # noqa: N802
        try:
            message = self.missing_packages_message(parameters)
            if message:
                raise QgsProcessingException(message)
            self.check_numbers(parameters, context)
            self.check_outputs(parameters, context)
            return self.process(parameters, context, feedback)
        except QgsProcessingException:
            raise
        except Cancelled:
            raise QgsProcessingException(QCoreApplication.translate(
                "GeomaticsAlgorithm", "Cancelled by the user; no output was written.")) from None
        except Terminated:
            raise QgsProcessingException(QCoreApplication.translate(
                "GeomaticsAlgorithm", "Terminated; no output was written.")) from None
        except InputError as exc:
            raise QgsProcessingException(self.input_error_message(exc)) from None
        except (ValueError, OSError) as exc:
            if feedback is not None:
                feedback.pushDebugInfo(traceback.format_exc())
            raise QgsProcessingException(str(exc)) from exc
        except MemoryError:
            raise QgsProcessingException(QCoreApplication.translate(
                "GeomaticsAlgorithm",
                "Out of memory. Use a coarser cell size, a smaller extent or fewer "
                "points; no output was written.")) from None
        except Exception as exc:  # noqa: BLE001 - report every failure as such
            if feedback is not None:
                feedback.pushDebugInfo(traceback.format_exc())
            raise QgsProcessingException(f"{type(exc).__name__}: {exc}") from exc  # i18n: data

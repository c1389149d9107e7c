"""Styles of the layers the algorithms load into the map.

An algorithm names the kind of each layer output (``OUTPUT_STYLES = {"OUTPUT":
"elevation"}``); :meth:`.base.GeomaticsAlgorithm.output_contract` reads layer
destinations with ``parameterAsOutputLayer`` (which puts them on the context's
load-on-completion list when the user asked for them: the dialog's "Open output file
after running algorithm", a batch's "Load layers on completion", a model output) and
attaches a :class:`LayerStyler` to each, which styles the layer once QGIS has loaded it:

* ``elevation`` (DTM, DSM, the catalog's VRT) — hypsometric colour ramp over the 2–98 %
  cumulative cut, plus a second named style "Hillshade" (multidirectional) in the
  layer's style manager (Layer ▸ Styles);
* ``height`` (nDSM / canopy height), ``variance`` (kriging variance), ``density``
  (point density, band 1), ``change`` (after − before, a diverging ramp symmetric about
  zero); ``change`` and ``density`` are the report's own ramps (``svg.RAMPS``), so a
  layer and the report's map of the same raster have the same colours;
* ``footprints`` (graduated by ``height_m`` and extruded by it in 3D views),
  ``change_polygons`` (cut red, fill blue), ``residuals`` (diverging by ``error``: the
  style the writer stored in the GeoPackage, :func:`residual_style`);
* ``classes`` — a point cloud with the ASPRS classification renderer.

QGIS keeps only a raw pointer to a post-processor: :data:`_KEEP` holds the Python
objects so they outlive the algorithm run.
"""
from __future__ import annotations

import collections

import numpy as np
from qgis.core import (
    QgsCategorizedSymbolRenderer,
    QgsColorRampShader,
    QgsFillSymbol,
    QgsGradientColorRamp,
    QgsGradientStop,
    QgsGraduatedSymbolRenderer,
    QgsHillshadeRenderer,
    QgsMapLayerType,
    QgsMarkerSymbol,
    QgsProcessingLayerPostProcessorInterface,
    QgsRasterBandStats,
    QgsRasterShader,
    QgsRendererCategory,
    QgsRendererRange,
    QgsSingleBandPseudoColorRenderer,
)
from qgis.PyQt.QtCore import QCoreApplication
from qgis.PyQt.QtGui import QColor

from ..core.reporting import svg

#: post-processors handed to QGIS (which keeps raw pointers): kept alive here
_KEEP: collections.deque = collections.deque(maxlen=1024)

#: the report's ramp (``core/reporting/svg.py`` RAMPS) of each kind that a report also
#: maps: the layer and the report's figure of the same raster share one colour table
REPORT_RAMPS = {"change": "diverging", "density": "viridis"}


def _report_ramp(name: str) -> tuple:
    """``svg.RAMPS[name]`` (evenly spaced RGB anchors, interpolated linearly as
    :func:`svg.colourise` does) as (position 0–1, "#rrggbb") stops."""
    anchors = svg.RAMPS[name]
    last = len(anchors) - 1
    return tuple((i / last, "#" + "".join(f"{c:02x}" for c in rgb))
                 for i, rgb in enumerate(anchors))


#: colour ramps by layer kind: (position 0–1, colour)
RAMPS = {
    # hypsometric tints: lowland green, upland ochre, summit white
    "elevation": ((0.0, "#1a6e3c"), (0.2, "#5fa052"), (0.4, "#c9d88a"),
                  (0.6, "#e8c77f"), (0.8, "#b07845"), (1.0, "#f4f1ee")),
    # heights above ground (nDSM / canopy height): yellow-green
    "height": ((0.0, "#ffffcc"), (0.25, "#c2e699"), (0.5, "#78c679"),
               (0.75, "#31a354"), (1.0, "#006837")),
    # kriging variance: yellow-orange-red (more uncertain = darker)
    "variance": ((0.0, "#ffffb2"), (0.25, "#fecc5c"), (0.5, "#fd8d3c"),
                 (0.75, "#f03b20"), (1.0, "#bd0026")),
    # after - before: red = loss (cut), white = no change, blue = gain (fill);
    # point density: viridis — both the report's own ramps
    **{kind: _report_ramp(name) for kind, name in REPORT_RAMPS.items()},
}
RASTER_KINDS = ("elevation", "height", "variance", "change", "density")
VECTOR_KINDS = ("footprints", "change_polygons", "residuals")
KINDS = RASTER_KINDS + VECTOR_KINDS + ("classes",)


def _style_names():
    # literal translate() calls so that pylupdate5 finds them
    return {"colour": QCoreApplication.translate("GeomaticsAlgorithm", "Colour ramp"),
            "hillshade": QCoreApplication.translate("GeomaticsAlgorithm", "Hillshade"),
            "cut": QCoreApplication.translate("GeomaticsAlgorithm", "Cut (surface lowered)"),
            "fill": QCoreApplication.translate("GeomaticsAlgorithm",
                                               "Fill (surface raised)")}


def color_ramp(kind: str) -> QgsGradientColorRamp:
    """The :data:`RAMPS` entry ``kind`` as a QGIS gradient ramp."""
    stops = RAMPS[kind]
    ramp = QgsGradientColorRamp(QColor(stops[0][1]), QColor(stops[-1][1]), False,
                                [QgsGradientStop(p, QColor(c)) for p, c in stops[1:-1]])
    return ramp


def raster_range(layer, kind: str, band: int = 1):
    """(min, max) of the colour ramp: the 2–98 % cumulative cut, adapted to the kind.

    ``change`` is symmetric about zero, ``height`` and ``density`` start at zero.
    """
    provider = layer.dataProvider()
    lo, hi = provider.cumulativeCut(band, 0.02, 0.98)
    if not (lo == lo and hi == hi) or hi <= lo:     # NaN or constant: plain min / max
        stats = provider.bandStatistics(band, QgsRasterBandStats.Min | QgsRasterBandStats.Max)
        lo, hi = stats.minimumValue, stats.maximumValue
    if kind == "change":
        limit = max(abs(lo), abs(hi)) or 1.0
        return -limit, limit
    if kind in ("height", "density"):
        lo = 0.0
    if hi <= lo:
        hi = lo + 1.0
    return float(lo), float(hi)


def ramp_shader(kind: str, lo: float, hi: float) -> QgsRasterShader:
    """A raster shader interpolating the kind's ramp linearly from ``lo`` to ``hi``
    (values outside take the end colours)."""
    shader_fn = QgsColorRampShader(lo, hi, color_ramp(kind), QgsColorRampShader.Interpolated)
    items = []
    for pos, colour in RAMPS[kind]:
        value = lo + pos * (hi - lo)
        items.append(QgsColorRampShader.ColorRampItem(value, QColor(colour),
                                                      f"{value:.2f}"))
    shader_fn.setColorRampItemList(items)
    shader_fn.setClip(False)
    shader = QgsRasterShader()
    shader.setRasterShaderFunction(shader_fn)
    shader.setMinimumValue(lo)
    shader.setMaximumValue(hi)
    return shader


def pseudocolor_renderer(layer, kind: str, band: int = 1):
    """A single-band pseudocolour renderer with the kind's ramp over its range."""
    lo, hi = raster_range(layer, kind, band)
    renderer = QgsSingleBandPseudoColorRenderer(layer.dataProvider(), band,
                                                ramp_shader(kind, lo, hi))
    renderer.setClassificationMin(lo)
    renderer.setClassificationMax(hi)
    return renderer


def style_raster(layer, kind: str) -> None:
    """Colour ramp (and, for elevations, a second "Hillshade" style) on ``layer``."""
    names = _style_names()
    if kind == "elevation":
        shade = QgsHillshadeRenderer(layer.dataProvider(), 1, 315.0, 45.0)
        shade.setMultiDirectional(True)
        layer.setRenderer(shade)
        manager = layer.styleManager()
        manager.addStyleFromLayer(names["hillshade"])
        layer.setRenderer(pseudocolor_renderer(layer, kind))
        current = manager.currentStyle()
        if current != names["colour"]:
            manager.renameStyle(current, names["colour"])
    else:
        layer.setRenderer(pseudocolor_renderer(layer, kind))
    layer.triggerRepaint()


def _graduated(layer, field: str, kind: str, classes: int = 5):
    from qgis.core import QgsClassificationQuantile
    renderer = QgsGraduatedSymbolRenderer(field)
    renderer.setSourceSymbol(QgsFillSymbol.createSimple(
        {"color": "#cccccc", "outline_color": "#333333", "outline_width": "0.2"}))
    renderer.setClassificationMethod(QgsClassificationQuantile())
    renderer.updateClasses(layer, classes)
    renderer.updateColorRamp(color_ramp(kind))
    return renderer


def footprints_3d(field: str = "height_m"):
    """A 3D renderer extruding polygons by ``field`` (None where the 3D library is
    missing)."""
    try:
        from qgis._3d import (
            Qgs3DTypes,
            QgsPhongMaterialSettings,
            QgsPolygon3DSymbol,
            QgsVectorLayer3DRenderer,
        )
        from qgis.core import QgsAbstract3DSymbol, QgsProperty
    except ImportError:
        return None
    symbol = QgsPolygon3DSymbol()
    symbol.setAltitudeClamping(Qgs3DTypes.AltClampRelative)
    symbol.setExtrusionHeight(0.0)
    props = symbol.dataDefinedProperties()
    props.setProperty(QgsAbstract3DSymbol.PropertyExtrusionHeight,
                      QgsProperty.fromField(field))
    symbol.setDataDefinedProperties(props)
    material = QgsPhongMaterialSettings()
    material.setDiffuse(QColor("#d9b38c"))
    material.setAmbient(QColor("#6b5a48"))
    # QGIS 3.40 names it setMaterialSettings; 3.22 has only setMaterial
    set_material = getattr(symbol, "setMaterialSettings", None) or symbol.setMaterial
    set_material(material)
    return QgsVectorLayer3DRenderer(symbol)


def residual_renderer(errors) -> QgsGraduatedSymbolRenderer:
    """Graduated renderer on ``error``: the report's diverging classes
    (``svg.DIVERGING``, blue below zero, red above), symmetric about zero up to the
    largest absolute error, with the report's legend labels."""
    err = np.asarray(errors, dtype=float)
    limit = float(np.nanmax(np.abs(err))) if np.isfinite(err).any() else 1.0
    edges = svg.class_edges(limit)
    edges[0], edges[-1] = -1e9, 1e9
    ranges = []
    for i, (colour, label) in enumerate(svg.diverging_legend_entries(limit)):
        symbol = QgsMarkerSymbol.createSimple({"name": "circle", "color": colour,
                                              "size": "3", "outline_color": "#222222"})
        ranges.append(QgsRendererRange(float(edges[i]), float(edges[i + 1]), symbol, label))
    return QgsGraduatedSymbolRenderer("error", ranges)


def residual_style(errors) -> str:
    """QML of :func:`residual_renderer`, which the residual writer stores in the
    GeoPackage as the layer's default style (QGIS draws it so whenever the file is
    opened; :func:`style_residuals` applies it to the layer a run loads)."""
    from qgis.core import QgsVectorLayer
    from qgis.PyQt.QtXml import QDomDocument

    layer = QgsVectorLayer("Point?field=error:double", "residuals", "memory")
    layer.setRenderer(residual_renderer(errors))
    doc = QDomDocument()
    layer.exportNamedStyle(doc)
    return doc.toString()


def _is_residual_renderer(renderer) -> bool:
    return (renderer is not None and renderer.type() == "graduatedSymbol"
            and renderer.classAttribute() == "error" and len(renderer.ranges()) > 0)


def style_residuals(layer) -> None:
    """The residual style on a loaded residual layer, computed once: the default style
    the writer stored in the GeoPackage (Processing loads results without it); only
    an output without one (GeoJSON) is classed here from its features."""
    if _is_residual_renderer(layer.renderer()):
        return                                  # loaded with its default style already
    _msg, ok = layer.loadDefaultStyle()
    if ok and _is_residual_renderer(layer.renderer()):
        return
    errors = [f["error"] for f in layer.getFeatures()
              if isinstance(f["error"], (int, float))]
    layer.setRenderer(residual_renderer(errors))


def style_vector(layer, kind: str) -> None:
    """Renderer (and 3D renderer for footprints) of a vector output."""
    if kind == "footprints":
        layer.setRenderer(_graduated(layer, "height_m", "height"))
        # height in the data's own vertical unit where the layer has it (a 3D view of a
        # feet CRS extrudes in feet); metres otherwise
        renderer3d = footprints_3d("height_z" if layer.fields().indexOf("height_z") >= 0
                                   else "height_m")
        if renderer3d is not None:
            layer.setRenderer3D(renderer3d)
    elif kind == "change_polygons":
        names = _style_names()
        cats = []
        for value, colour in (("cut", RAMPS["change"][0][1]),
                              ("fill", RAMPS["change"][-1][1])):
            symbol = QgsFillSymbol.createSimple({"color": colour, "outline_color": "#333333",
                                                 "outline_width": "0.2"})
            symbol.setOpacity(0.7)
            cats.append(QgsRendererCategory(value, symbol, names[value]))
        layer.setRenderer(QgsCategorizedSymbolRenderer("kind", cats))
    elif kind == "residuals":
        style_residuals(layer)
    layer.triggerRepaint()


def style_point_cloud(layer) -> None:
    """The ASPRS classification renderer (QGIS's default class colours and names)."""
    from qgis.core import QgsPointCloudClassifiedRenderer
    renderer = QgsPointCloudClassifiedRenderer()
    renderer.setAttribute("Classification")
    renderer.setCategories(QgsPointCloudClassifiedRenderer.defaultCategories())
    layer.setRenderer(renderer)
    layer.triggerRepaint()


def apply_style(layer, kind: str) -> None:
    """Style ``layer`` as ``kind`` (one of :data:`KINDS`)."""
    if kind not in KINDS:
        raise ValueError(  # i18n: internal
            f"unknown layer style {kind!r}; one of {', '.join(KINDS)}")
    if layer is None or not layer.isValid():
        return
    ltype = layer.type()
    if kind in RASTER_KINDS and ltype == QgsMapLayerType.RasterLayer:
        style_raster(layer, kind)
    elif kind in VECTOR_KINDS and ltype == QgsMapLayerType.VectorLayer:
        style_vector(layer, kind)
    elif kind == "classes" and ltype == QgsMapLayerType.PointCloudLayer:
        style_point_cloud(layer)


class LayerStyler(QgsProcessingLayerPostProcessorInterface):
    """Styles a layer once QGIS has loaded it after the algorithm run."""

    def __init__(self, kind: str):
        super().__init__()
        if kind not in KINDS:
            raise ValueError(f"unknown layer style {kind!r}")  # i18n: internal
        self.kind = kind

    def postProcessLayer(self, layer, context, feedback):  # noqa: N802 - QGIS API
        try:
            apply_style(layer, self.kind)
        except Exception as exc:  # noqa: BLE001 - a style never fails a finished run
            if feedback is not None:
                feedback.pushWarning(QCoreApplication.translate(
                    "GeomaticsAlgorithm", "Could not style the layer {name}: {error}")
                    .format(name=layer.name(), error=exc))


def style_on_completion(context, path: str, kind: str | None) -> bool:
    """Attach the style ``kind`` to ``path`` if the context will load it; True if so."""
    if not kind or not path or context is None:
        return False
    if not context.willLoadLayerOnCompletion(path):
        return False
    styler = LayerStyler(kind)
    _KEEP.append(styler)
    context.layerToLoadOnCompletionDetails(path).setPostProcessor(styler)
    return True

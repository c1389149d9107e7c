"""Results on the map, styled (issue 19, item 4).

Each run goes the way the Processing dialog and the batch dialog go: layer outputs as
``QgsProcessingOutputLayerDefinition(value, project)`` ("Open output file after running
algorithm" / "Load layers on completion"), ``processing.run`` with a context, then
QGIS's own ``Postprocessing.handleAlgorithmResults`` — the step that loads the layers,
runs our post-processors and reports "The following layers were not correctly
generated". Every layer output must be on ``context.layersToLoadOnCompletion()``, load,
and carry its style (renderer type, ramp colours, 3D renderer).
"""
from __future__ import annotations

import os

import pytest

from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile


@pytest.fixture(scope="module")
def scene(tmp_path_factory):
    d = tmp_path_factory.mktemp("onmap")
    tile = generate_tile(extent=(80.0, 80.0), density=2.0, seed=7, n_buildings=2,
                         n_halls=0)
    laz = d / "tile.laz"
    write_tile(tile, laz, crs="EPSG:32632")
    cp = tile.checkpoints(n=10, min_spacing=3.0)
    csv = cp.to_csv(d / "cp.csv")
    return {"dir": d, "tile": tile, "laz": str(laz), "csv": str(csv)}


class Recorder:
    """A feedback that keeps every error and warning."""

    def __init__(self):
        from qgis.core import QgsProcessingFeedback

        class _F(QgsProcessingFeedback):
            def __init__(self, sink):
                super().__init__()
                self.sink = sink

            def reportError(self, error, fatalError=False):  # noqa: N802
                self.sink.errors.append(error)
                super().reportError(error, fatalError)

            def pushWarning(self, warning):  # noqa: N802
                self.sink.warnings.append(warning)
                super().pushWarning(warning)

        self.errors, self.warnings = [], []
        self.feedback = _F(self)


def gui_run(processing, alg_id, params, *, project=None):
    """Run ``alg_id`` as the dialog does with the "open output" boxes ticked; return
    (results, context, project, recorder, load list before loading)."""
    from processing.gui.Postprocessing import handleAlgorithmResults
    from processing.tools import dataobjects
    from qgis.core import (
        QgsApplication,
        QgsProcessingOutputLayerDefinition,
        QgsProcessingParameterFeatureSink,
        QgsProcessingParameterRasterDestination,
        QgsProcessingParameterVectorDestination,
        QgsProject,
    )
    project = project or QgsProject()
    alg = QgsApplication.processingRegistry().createAlgorithmById(alg_id)
    params = dict(params)
    for out in alg.destinationParameterDefinitions():
        if out.name() in params and isinstance(out, (
                QgsProcessingParameterRasterDestination,
                QgsProcessingParameterVectorDestination, QgsProcessingParameterFeatureSink)):
            params[out.name()] = QgsProcessingOutputLayerDefinition(params[out.name()],
                                                                    project)
    rec = Recorder()
    context = dataobjects.createContext(rec.feedback)
    context.setProject(project)
    # onFinish: as the dialog, leave result layers (memory layers) in the context for
    # handleAlgorithmResults instead of handing them to the caller
    res = processing.run(alg_id, params, feedback=rec.feedback, context=context,
                         onFinish=lambda *_: None)
    pending = {path: (details.outputName, details.postProcessor())
               for path, details in context.layersToLoadOnCompletion().items()}
    # QGIS 3.22: (alg, context, feedback, showResults, parameters); 3.40 dropped the
    # unused showResults: pass the parameters by name
    ok = handleAlgorithmResults(alg, context, rec.feedback, parameters=params)
    assert ok, rec.errors
    assert not [e for e in rec.errors if "not correctly generated" in e], rec.errors
    return res, context, project, rec, pending


def layer_of(project, path):
    """The project layer whose source is ``path``."""
    for lyr in project.mapLayers().values():
        if lyr.source().split("|")[0] == path:
            return lyr
    raise AssertionError(f"{path} not loaded; layers: "
                         f"{[lyr.source() for lyr in project.mapLayers().values()]}")


def ramp_colours(layer):
    """(renderer type, colours of the shader items) of a pseudocolour raster layer."""
    r = layer.renderer()
    items = r.shader().rasterShaderFunction().colorRampItemList()
    return r.type(), [i.color.name() for i in items]


def assert_raster_style(project, path, kind):
    from geomatics_toolbox.algorithms.styles import RAMPS
    lyr = layer_of(project, path)
    rtype, colours = ramp_colours(lyr)
    assert rtype == "singlebandpseudocolor"
    assert colours == [c for _, c in RAMPS[kind]]
    items = lyr.renderer().shader().rasterShaderFunction().colorRampItemList()
    assert items[0].value < items[-1].value
    if kind == "change":       # symmetric about zero
        assert items[0].value == pytest.approx(-items[-1].value)
    if kind in ("height", "density"):
        assert items[0].value == 0
    return lyr


def test_idw_dtm_loaded_with_ramp_and_hillshade_style(qgis_processing, scene):
    d = scene["dir"]
    res, ctx, project, rec, pending = gui_run(qgis_processing, "geomatics:idwdtm", {
        "INPUT": scene["laz"], "CELL_SIZE": 1.0, "OUTPUT": str(d / "idw.tif"),
        "OUTPUT_HTML": str(d / "idw.html")})
    assert set(pending) == {res["OUTPUT"]}
    name, post = pending[res["OUTPUT"]]
    assert name == "OUTPUT" and post is not None
    lyr = assert_raster_style(project, res["OUTPUT"], "elevation")
    from qgis.core import QgsProcessingUtils  # noqa: F401

    from geomatics_toolbox.algorithms.styles import raster_range
    lo, hi = raster_range(lyr, "elevation")
    items = lyr.renderer().shader().rasterShaderFunction().colorRampItemList()
    assert (items[0].value, items[-1].value) == pytest.approx((lo, hi))
    # the 2–98 % cut of the DTM, inside its min–max
    import numpy as np

    from geomatics_toolbox.core.io.raster import read_raster
    z = read_raster(res["OUTPUT"]).masked()
    assert np.nanmin(z) <= lo < hi <= np.nanmax(z)
    assert lo == pytest.approx(np.nanpercentile(z, 2), abs=0.5)
    manager = lyr.styleManager()
    assert set(manager.styles()) == {"Colour ramp", "Hillshade"}
    assert manager.currentStyle() == "Colour ramp"
    manager.setCurrentStyle("Hillshade")
    assert lyr.renderer().type() == "hillshade"
    assert lyr.renderer().multiDirectional()


def test_tin_dtm_temporary_output_loads_without_error(qgis_processing, scene):
    """A temporary output used to be named twice (two temporaries): QGIS then said
    "The following layers were not correctly generated"."""
    res, ctx, project, rec, pending = gui_run(qgis_processing, "geomatics:tindtm", {
        "INPUT": scene["laz"], "CELL_SIZE": 1.0, "OUTPUT": "TEMPORARY_OUTPUT"})
    assert os.path.isfile(res["OUTPUT"])
    assert set(pending) == {res["OUTPUT"]}
    assert not rec.errors
    assert_raster_style(project, res["OUTPUT"], "elevation")


def test_no_duplicate_parameter_at_start(qgis_app, monkeypatch):
    """"Duplicate parameter REPORT_LANGUAGE registered for alg tindtm" at every start:
    QGIS refuses the second addParameter (returns False) and logs it."""
    from qgis.core import QgsProcessingAlgorithm

    from geomatics_toolbox.algorithms import all_algorithms
    from geomatics_toolbox.algorithms.base import GeomaticsAlgorithm
    refused = []
    original = QgsProcessingAlgorithm.addParameter

    def recording(self, param, createOutput=True):  # noqa: N803
        ok = original(self, param, createOutput)
        if not ok:
            refused.append((self.name(), param.name()))
        return ok

    monkeypatch.setattr(GeomaticsAlgorithm, "addParameter", recording)
    for alg in all_algorithms():
        alg.initAlgorithm()
    assert refused == []


def test_kriging_dtm_and_variance(qgis_processing, scene):
    d = scene["dir"]
    res, ctx, project, rec, pending = gui_run(qgis_processing, "geomatics:krigingdtm", {
        "INPUT": scene["laz"], "CELL_SIZE": 4.0, "NEIGHBOURS": 8, "CV_POINTS": 0,
        "FIT_POINTS": 500, "OUTPUT": str(d / "kr.tif"),
        "OUTPUT_VARIANCE": "TEMPORARY_OUTPUT"})
    assert set(pending) == {res["OUTPUT"], res["OUTPUT_VARIANCE"]}
    assert pending[res["OUTPUT_VARIANCE"]][0] == "OUTPUT_VARIANCE"
    assert_raster_style(project, res["OUTPUT"], "elevation")
    assert_raster_style(project, res["OUTPUT_VARIANCE"], "variance")


def test_dsm_and_ndsm(qgis_processing, scene):
    d = scene["dir"]
    dtm = qgis_processing.run("geomatics:idwdtm", {
        "INPUT": scene["laz"], "CELL_SIZE": 1.0, "FILL_GAPS": True,
        "OUTPUT": str(d / "dtm_for_ndsm.tif")})["OUTPUT"]
    res, ctx, project, rec, pending = gui_run(qgis_processing, "geomatics:dsm", {
        "INPUT": scene["laz"], "DTM": dtm, "OUTPUT": "TEMPORARY_OUTPUT",
        "OUTPUT_NDSM": str(d / "ndsm.tif")})
    assert set(pending) == {res["OUTPUT"], res["OUTPUT_NDSM"]}
    assert_raster_style(project, res["OUTPUT"], "elevation")
    lyr = assert_raster_style(project, res["OUTPUT_NDSM"], "height")
    assert len(lyr.styleManager().styles()) == 1      # no hillshade for heights


def test_lidarqa_density(qgis_processing, scene):
    res, ctx, project, rec, pending = gui_run(qgis_processing, "geomatics:lidarqa", {
        "INPUT": scene["laz"], "CELL_SIZE": 5.0, "OUTPUT": "TEMPORARY_OUTPUT"})
    assert set(pending) == {res["OUTPUT"]}
    lyr = assert_raster_style(project, res["OUTPUT"], "density")
    assert lyr.renderer().band() == 1


def renderer_classes(renderer):
    """(lower, upper, colour, label) of each class of a graduated renderer."""
    return [(round(r.lowerValue(), 9), round(r.upperValue(), 9),
             r.symbol().color().name(), r.label()) for r in renderer.ranges()]


@pytest.mark.parametrize("kind", ["change", "density"])
def test_layer_ramp_is_the_report_ramp(qgis_app, kind):
    """A change / density layer and the report's map of the same raster show the same
    colour for every value: the QGIS shader against ``svg.colourise`` (±1 of 255:
    QGIS rounds, the report truncates), inside and outside the range."""
    import numpy as np

    from geomatics_toolbox.algorithms import styles
    from geomatics_toolbox.core.reporting import svg
    name = styles.REPORT_RAMPS[kind]
    assert [c for _, c in styles.RAMPS[kind]] == [
        "#" + "".join(f"{v:02x}" for v in rgb) for rgb in svg.RAMPS[name]]
    lo, hi = (-2.0, 2.0) if kind == "change" else (0.0, 17.5)
    shader = styles.ramp_shader(kind, lo, hi)
    values = np.linspace(lo - 1.0, hi + 1.0, 97)
    qgis = np.array([shader.shade(float(v))[1:4] for v in values])
    report = svg.colourise(values[None, :], lo, hi, name)[0, :, :3].astype(int)
    assert np.abs(qgis - report).max() <= 1


@pytest.fixture
def count_residual_renderers(monkeypatch):
    """Counts how often the residual renderer is computed in the run."""
    from geomatics_toolbox.algorithms import styles
    calls = []
    real = styles.residual_renderer

    def counted(errors):
        calls.append(len(errors))
        return real(errors)

    monkeypatch.setattr(styles, "residual_renderer", counted)
    return calls


def test_dtmaccuracy_residuals(qgis_processing, scene, count_residual_renderers):
    from qgis.core import QgsVectorLayer

    from geomatics_toolbox.core.reporting import svg
    d = scene["dir"]
    dtm = qgis_processing.run("geomatics:idwdtm", {
        "INPUT": scene["laz"], "CELL_SIZE": 1.0, "OUTPUT": str(d / "dtm_acc.tif")})["OUTPUT"]
    count_residual_renderers.clear()
    res, ctx, project, rec, pending = gui_run(qgis_processing, "geomatics:dtmaccuracy", {
        "DTM": dtm, "CHECKPOINTS_CSV": scene["csv"], "OUTPUT": "TEMPORARY_OUTPUT"})
    assert set(pending) == {res["OUTPUT"]}
    lyr = layer_of(project, res["OUTPUT"])
    r = lyr.renderer()
    assert r.type() == "graduatedSymbol" and r.classAttribute() == "error"
    ranges = r.ranges()
    assert len(ranges) >= 5
    # diverging: blue below zero, red above, symmetric class edges
    inner = [(x.lowerValue(), x.upperValue()) for x in ranges[1:-1]]
    assert inner[0][0] == pytest.approx(-inner[-1][1])
    errors = [f["error"] for f in lyr.getFeatures() if f["error"] is not None]
    assert max(abs(e) for e in errors) == pytest.approx(inner[-1][1] * len(ranges)
                                                        / (len(ranges) - 2), rel=1e-6)
    # the report's classes and colours
    assert [x.symbol().color().name() for x in ranges] == list(svg.DIVERGING)
    # styled once: the renderer computed when the GeoPackage was written (its default
    # style) is the one on the loaded layer — no second pass over the features
    assert count_residual_renderers == [lyr.featureCount()]
    later = QgsVectorLayer(res["OUTPUT"], "opened later", "ogr")
    assert later.renderer().type() == "graduatedSymbol"
    assert renderer_classes(later.renderer()) == renderer_classes(r)


def test_dtmaccuracy_residuals_geojson_styled_from_features(qgis_processing, scene,
                                                            count_residual_renderers):
    """A GeoJSON output stores no style: the loaded layer is classed from its
    features, with the same classes as the report."""
    from geomatics_toolbox.core.reporting import svg
    d = scene["dir"]
    dtm = qgis_processing.run("geomatics:idwdtm", {
        "INPUT": scene["laz"], "CELL_SIZE": 1.0, "OUTPUT": str(d / "dtm_gj.tif")})["OUTPUT"]
    out = str(d / "residuals.geojson")
    res, ctx, project, rec, pending = gui_run(qgis_processing, "geomatics:dtmaccuracy", {
        "DTM": dtm, "CHECKPOINTS_CSV": scene["csv"], "OUTPUT": out})
    lyr = layer_of(project, out)
    r = lyr.renderer()
    assert r.type() == "graduatedSymbol" and r.classAttribute() == "error"
    errors = [f["error"] for f in lyr.getFeatures() if f["error"] is not None]
    limit = max(abs(e) for e in errors)
    assert [x.label() for x in r.ranges()] == [
        label for _, label in svg.diverging_legend_entries(limit)]
    assert count_residual_renderers[-1] == len(errors)


def test_buildings_footprints_extruded(qgis_processing, scene):
    res, ctx, project, rec, pending = gui_run(qgis_processing, "geomatics:buildings", {
        "INPUT": scene["laz"], "OUTPUT": "TEMPORARY_OUTPUT"})
    assert res["N_BUILDINGS"] >= 1
    assert set(pending) == {res["OUTPUT"]}
    lyr = layer_of(project, res["OUTPUT"])
    r = lyr.renderer()
    assert r.type() == "graduatedSymbol" and r.classAttribute() == "height_m"
    from geomatics_toolbox.algorithms.styles import RAMPS
    assert r.ranges()[-1].symbol().color().name() == RAMPS["height"][-1][1]
    heights = [f["height_m"] for f in lyr.getFeatures()]
    assert r.ranges()[-1].upperValue() == pytest.approx(max(heights))
    r3d = lyr.renderer3D()
    assert r3d is not None and r3d.type() == "vector"
    from qgis.core import QgsAbstract3DSymbol
    sym = r3d.symbol()
    prop = sym.dataDefinedProperties().property(QgsAbstract3DSymbol.PropertyExtrusionHeight)
    # extruded by the height in the data's vertical unit (equal to height_m in metres)
    assert prop.isActive() and prop.field() == "height_z"
    assert [f["height_z"] for f in lyr.getFeatures()] == pytest.approx(heights)


def test_footprints_3d_guarded_without_3d_library(monkeypatch):
    import builtins

    from geomatics_toolbox.algorithms import styles
    real = builtins.__import__

    def no_3d(name, *args, **kwargs):
        if name.startswith("qgis._3d") or name == "qgis._3d":
            raise ImportError("no 3D library")
        return real(name, *args, **kwargs)

    monkeypatch.setattr(builtins, "__import__", no_3d)
    assert styles.footprints_3d() is None


def test_elevation_change_raster_and_polygons(qgis_processing, scene):
    import numpy as np

    from geomatics_toolbox.core.io.raster import read_raster
    d = scene["dir"]
    dtm = qgis_processing.run("geomatics:idwdtm", {
        "INPUT": scene["laz"], "CELL_SIZE": 1.0, "FILL_GAPS": True,
        "OUTPUT": str(d / "before.tif")})["OUTPUT"]
    r = read_raster(dtm)
    z = r.masked().copy()
    z[10:30, 10:30] += 2.0      # fill
    z[40:60, 40:60] -= 1.5      # cut
    from osgeo import gdal
    after = str(d / "after.tif")
    gdal.Translate(after, dtm)          # same grid, CRS and band unit as the before DTM
    ds = gdal.Open(after, gdal.GA_Update)
    band = ds.GetRasterBand(1)
    band.WriteArray(np.where(np.isfinite(z), z, band.GetNoDataValue()).astype("float32"))
    ds = band = None
    res, ctx, project, rec, pending = gui_run(qgis_processing, "geomatics:elevationchange", {
        "INPUT": dtm, "INPUT_AFTER": after, "SIGMA1": 0.05, "SIGMA2": 0.05,
        "OUTPUT": "TEMPORARY_OUTPUT", "OUTPUT_POLYGONS": "TEMPORARY_OUTPUT"})
    assert set(pending) == {res["OUTPUT"], res["OUTPUT_POLYGONS"]}
    lyr = assert_raster_style(project, res["OUTPUT"], "change")
    items = lyr.renderer().shader().rasterShaderFunction().colorRampItemList()
    assert items[-1].value == pytest.approx(2.0, abs=1e-3)   # ±max(|cut|, |fill|)
    poly = layer_of(project, res["OUTPUT_POLYGONS"])
    pr = poly.renderer()
    assert pr.type() == "categorizedSymbol" and pr.classAttribute() == "kind"
    cats = {c.value(): c.symbol().color().name() for c in pr.categories()}
    assert cats == {"cut": "#b2182b", "fill": "#2166ac"}
    kinds = sorted(f["kind"] for f in poly.getFeatures())
    assert kinds == ["cut", "fill"]
    assert np.isfinite(res["LOD"])


def test_lidartodtm_outputs(qgis_processing, scene):
    d = scene["dir"]
    res, ctx, project, rec, pending = gui_run(qgis_processing, "geomatics:lidartodtm", {
        "INPUT": scene["laz"], "CHECKPOINTS_CSV": scene["csv"], "CELL_SIZE": 1.0,
        "OUTPUT": str(d / "l2d.laz"), "OUTPUT_DTM": "TEMPORARY_OUTPUT",
        "OUTPUT_RESIDUALS": "TEMPORARY_OUTPUT", "OUTPUT_HTML": str(d / "l2d.html")})
    # the classified cloud is a file output: loaded only where QGIS reads LAS (PDAL)
    assert set(pending) == {res["OUTPUT_DTM"], res["OUTPUT_RESIDUALS"]}
    assert_raster_style(project, res["OUTPUT_DTM"], "elevation")
    assert layer_of(project, res["OUTPUT_RESIDUALS"]).renderer().classAttribute() == "error"


def test_shipped_model_outputs(qgis_processing, scene):
    d = scene["dir"]
    res, ctx, project, rec, pending = gui_run(qgis_processing, "geomatics:lidar_to_dtm", {
        "INPUT": scene["laz"], "CHECKPOINTS_CSV": scene["csv"], "CELL_SIZE": 1.0,
        "publish:Classified point cloud": str(d / "model.laz"),
        "publish:DTM": str(d / "model_dtm.tif"),
        "publish:Check-point residuals": str(d / "model_res.gpkg"),
        "publish:DTM accuracy report": str(d / "model.html")})
    assert set(pending) == {res["publish:DTM"], res["publish:Check-point residuals"]}
    assert_raster_style(project, res["publish:DTM"], "elevation")
    lyr = layer_of(project, res["publish:Check-point residuals"])
    assert lyr.renderer().classAttribute() == "error"


def test_batch_rows_each_loaded_and_styled(qgis_processing, scene):
    """The batch dialog: one context per row, every row's layers loaded."""
    from qgis.core import QgsProject
    d = scene["dir"]
    project = QgsProject()
    paths = []
    for i, cell in enumerate((1.0, 2.0)):
        res, *_ = gui_run(qgis_processing, "geomatics:idwdtm", {
            "INPUT": scene["laz"], "CELL_SIZE": cell, "OUTPUT": str(d / f"batch{i}.tif")},
            project=project)
        paths.append(res["OUTPUT"])
    for p in paths:
        assert_raster_style(project, p, "elevation")
    assert len(project.mapLayers()) == 2


def test_catalog_vrt_loaded(qgis_processing, tmp_path):
    tiles = tmp_path / "tiles"
    tiles.mkdir()
    for i in range(2):
        t = generate_tile(extent=(60.0, 60.0), origin=(500_000.0 + 60 * i, 4_000_000.0),
                          density=1.0, seed=i)
        write_tile(t, tiles / f"t{i}.laz")
    res, ctx, project, rec, pending = gui_run(qgis_processing, "geomatics:catalog", {
        "INPUT": str(tiles), "GROUND_FILTER": 0, "CELL_SIZE": 2.0, "BUFFER": 20.0,
        "WORKERS": 1, "OUTPUT_FOLDER": str(tmp_path / "out")})
    vrt = str(tmp_path / "out" / "dtm.vrt")
    assert res["OUTPUT_VRT"] == vrt
    assert set(pending) == {vrt}
    assert pending[vrt][0] == "OUTPUT_VRT"
    assert_raster_style(project, vrt, "elevation")


def test_classified_cloud_renderer(qgis_app, monkeypatch, tmp_path):
    """Debian's 3.22 has no PDAL, so no LAS layer loads here: the code path is tested up
    to QGIS's loading (the layer is registered, with the post-processor), and the
    post-processor on a point-cloud layer object."""
    from qgis.core import (
        QgsPointCloudLayer,
        QgsProcessingContext,
        QgsProcessingUtils,
        QgsProject,
    )

    from geomatics_toolbox.algorithms import base, styles
    from geomatics_toolbox.algorithms.ground_filter import GroundFilterAlgorithm
    alg = GroundFilterAlgorithm()
    alg.initAlgorithm()
    ctx = QgsProcessingContext()
    ctx.setProject(QgsProject())
    path = str(tmp_path / "c.laz")
    monkeypatch.setattr(base, "point_cloud_layers_supported", lambda p=None: False)
    assert not alg.load_cloud_on_completion(ctx, path, "Classified", "OUTPUT")
    assert not ctx.layersToLoadOnCompletion()
    monkeypatch.setattr(base, "point_cloud_layers_supported", lambda p=None: True)
    assert alg.load_cloud_on_completion(ctx, path, "Classified", "OUTPUT")
    details = ctx.layersToLoadOnCompletion()[path]
    assert details.layerTypeHint == QgsProcessingUtils.LayerHint.PointCloud
    post = details.postProcessor()
    assert post is not None and post.kind == "classes"
    layer = QgsPointCloudLayer(path, "c", "pdal")
    styles.style_point_cloud(layer)          # apply_style skips invalid layers
    r = layer.renderer()
    assert r.type() == "classified" and r.attribute() == "Classification"
    codes = {c.value() for c in r.categories()}
    assert {1, 2, 3, 4, 5, 6, 7, 9, 17, 18} <= codes


def test_copc_loads_without_pdal_where_qgis_has_copc(monkeypatch):
    from geomatics_toolbox.algorithms import base

    class _Reg:
        def __init__(self, names):
            self.names = names

        def providerList(self):  # noqa: N802
            return self.names

    class _Registry:
        names = []

        @classmethod
        def instance(cls):
            return _Reg(cls.names)

    monkeypatch.setattr(base, "QgsProviderRegistry", _Registry)
    _Registry.names = ["ogr", "gdal"]
    assert not base.point_cloud_layers_supported("a.copc.laz")
    _Registry.names = ["ogr", "gdal", "copc"]
    assert base.point_cloud_layers_supported("a.copc.laz")
    assert not base.point_cloud_layers_supported("a.laz")
    _Registry.names = ["pdal"]
    assert base.point_cloud_layers_supported("a.laz")


def test_rectified_image_loaded(qgis_processing, tmp_path):
    """The rectified image (a raster destination) loads; QGIS's own RGB style fits it."""
    import sys
    sys.path.insert(0, os.path.dirname(__file__))
    from test_reports_dialog_defects import _gcp_case
    img, pts = _gcp_case(tmp_path)
    res, ctx, project, rec, pending = gui_run(qgis_processing, "geomatics:rectifygcp", {
        "INPUT": img, "GCP_FILE": pts, "OUTPUT": "TEMPORARY_OUTPUT"})
    assert set(pending) == {res["OUTPUT"]}
    lyr = layer_of(project, res["OUTPUT"])
    assert lyr.isValid() and lyr.bandCount() >= 1


#: layer outputs QGIS's own default style suits: a rectified image (RGB), a table
UNSTYLED = {("rectifygcp", "OUTPUT"), ("gsdbatch", "OUTPUT")}


def test_every_layer_output_declares_its_style(qgis_app):
    """A new raster or vector output must say how it is drawn (OUTPUT_STYLES)."""
    from geomatics_toolbox.algorithms import all_algorithms
    from geomatics_toolbox.algorithms.base import LAYER_DESTINATIONS
    from geomatics_toolbox.algorithms.styles import KINDS
    missing, n = [], 0
    for alg in all_algorithms():
        alg.initAlgorithm()
        for p in alg.destinationParameterDefinitions():
            if p.type() not in LAYER_DESTINATIONS or (alg.name(), p.name()) in UNSTYLED:
                continue
            n += 1
            if alg.OUTPUT_STYLES.get(p.name()) not in KINDS:
                missing.append(f"{alg.name()} {p.name()}")
    assert n >= 15 and not missing, missing


@pytest.mark.parametrize("dest", ["TEMPORARY_OUTPUT", "table.csv", "memory:"])
def test_gsd_batch_table_loaded(qgis_processing, tmp_path, dest):
    """The result table (a feature sink) loads once, with no "not correctly generated"."""
    src = tmp_path / "cams.csv"
    src.write_text("label,distance,sensor_width,image_width,focal_length\n"
                   "paper,5.88,6.123,3648,4.6\n")
    out = str(tmp_path / dest) if dest.endswith(".csv") else dest
    res, ctx, project, rec, pending = gui_run(qgis_processing, "geomatics:gsdbatch", {
        "INPUT": str(src), "OUTPUT": out})
    assert len(pending) == 1
    layers = list(project.mapLayers().values())
    assert len(layers) == 1 and layers[0].featureCount() == 1
    assert "gsd_cm" in layers[0].fields().names()

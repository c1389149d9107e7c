#!/usr/bin/env python3
"""Build the shipped Processing model ``models/lidar_to_dtm.model3``.

LAS/LAZ → ground filter (the default of the one filter registry,
``core.lidar.filters.default_ground_filter``: the recommended ``geomatics:groundfilter``)
→ IDW DTM (``geomatics:idwdtm`` with its defaults) → DTM accuracy against check points
(``geomatics:dtmaccuracy``) → publish (``geomatics:publishoutputs``). The first three
write temporaries; the publish step copies them to the classified cloud, DTM, residual
layer and report destinations (the model outputs) through one output contract, so a
failing last step leaves nothing at any destination. Every child parameter is written
into the model (the exposed ones as model inputs, the others as their defaults), so a
parameter added to a child makes ``tests/cli/test_model_cli.py`` fail until ``make model`` is rerun.

The model is built with the QGIS API (``QgsProcessingModelAlgorithm``) so that it is
reproducible and reviewable; rerun this script after changing a parameter.

Usage::

    make model     # = .venv/bin/python scripts/build_model.py [--filter auto|lsq|slope]

Run the model (plugin enabled in the QGIS profile)::

    qgis_process.bin run models/lidar_to_dtm.model3 -- INPUT=out/demo/demo.laz \\
        CHECKPOINTS_CSV=out/demo/checkpoints.csv CELL_SIZE=1 \\
        "publish:Classified point cloud=out/model/ground.laz" \\
        publish:DTM=out/model/dtm.tif "publish:DTM accuracy report=out/model/accuracy.html"
"""
from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DEFAULT_OUT = ROOT / "models" / "lidar_to_dtm.model3"

MODEL_NAME = "lidar_to_dtm"                 # stable id: geomatics:lidar_to_dtm
TITLE = "LiDAR to DTM with accuracy"        # shown (translated) by the provider
GROUP, GROUP_ID = "Terrain models", "terrain"

#: ground filters in order of preference; the first registered one is used
FILTERS = {
    "recommended": "geomatics:groundfilter",
    "lsq": "geomatics:lsqgroundfilter",
    "slope": "geomatics:slopegroundfilter",
}
#: DTM settings exposed as model inputs (IDW child parameter -> model default; None =
#: the child's default, so the model equals idwdtm and lidartodtm with their defaults)
DTM_SETTINGS = {"CELL_SIZE": 1.0, "POWER": None, "FILL_GAPS": False, "CRS": None}
#: human labels of the model inputs that differ from the child's own label
LABELS = {"CELL_SIZE": "DTM cell size (m)", "POWER": "IDW power",
          "FILL_GAPS": "Fill data gaps in the DTM (interpolate far from ground points)",
          "CRS": "CRS override for a cloud without a CRS record",
          "CHECKPOINTS": "Check points (point layer)",
          "CHECKPOINTS_CSV": "Check points (CSV/TXT file: id,x,y,z)"}
#: (model output name, publish step output, mandatory, (source child, its output)) — the
#: names the user sees; every model output comes from the final publish step
OUTPUTS = (("Classified point cloud", "OUTPUT", True, ("groundfilter", "OUTPUT")),
           ("Ground filter report", "OUTPUT_FILTER_HTML", False,
            ("groundfilter", "OUTPUT_HTML")),
           ("DTM", "OUTPUT_DTM", True, ("dtm", "OUTPUT")),
           ("DTM report", "OUTPUT_DTM_HTML", False, ("dtm", "OUTPUT_HTML")),
           ("Check-point residuals", "OUTPUT_RESIDUALS", False, ("accuracy", "OUTPUT")),
           ("DTM accuracy report", "OUTPUT_HTML", True, ("accuracy", "OUTPUT_HTML")))
PUBLISH = "geomatics:publishoutputs"
#: publish step input fed by each model output's source temporary
PUBLISH_SOURCES = {"OUTPUT": "CLOUD", "OUTPUT_FILTER_HTML": "FILTER_HTML",
                   "OUTPUT_DTM": "DTM", "OUTPUT_DTM_HTML": "DTM_HTML",
                   "OUTPUT_RESIDUALS": "RESIDUALS", "OUTPUT_HTML": "HTML"}
#: publish step inputs protected by its same-file checks (model inputs)
PUBLISH_PROTECTED = {"INPUT_CLOUD": "INPUT", "INPUT_CHECKPOINTS_CSV": "CHECKPOINTS_CSV",
                     "INPUT_CHECKPOINTS": "CHECKPOINTS"}


def pick_filter(requested: str = "auto") -> str:
    """Algorithm id of the ground filter: the filter registry's default when registered."""
    from qgis.core import QgsApplication
    registry = QgsApplication.processingRegistry()
    if requested != "auto":
        return FILTERS[requested]
    from geomatics_toolbox.core.lidar.filters import GROUND_FILTERS, default_ground_filter
    for alg_id in (f"geomatics:{GROUND_FILTERS[default_ground_filter()].algorithm}",
                   *FILTERS.values()):
        if registry.algorithmById(alg_id) is not None:
            return alg_id
    raise SystemExit("no geomatics ground filter registered")


def _is_destination(defn) -> bool:
    return bool(defn.isDestination())


def build(filter_key: str = "auto"):
    """The model: cloud → ground filter → IDW DTM → DTM accuracy, every parameter set."""
    from qgis.core import (
        QgsApplication,
        QgsProcessingModelAlgorithm,
        QgsProcessingModelParameter,
    )
    from qgis.core import QgsProcessingModelChildParameterSource as Src
    from qgis.PyQt.QtCore import QPointF

    registry = QgsApplication.processingRegistry()
    filter_id = pick_filter(filter_key)
    algs = {"groundfilter": registry.algorithmById(filter_id),
            "dtm": registry.algorithmById("geomatics:idwdtm"),
            "accuracy": registry.algorithmById("geomatics:dtmaccuracy"),
            "publish": registry.algorithmById(PUBLISH)}
    missing = [k for k, a in algs.items() if a is None]
    if missing:
        raise SystemExit(f"algorithms not registered: {missing}")
    m = QgsProcessingModelAlgorithm(MODEL_NAME, GROUP, GROUP_ID)
    y = [40.0]
    order = []        # model inputs in the order a user thinks of them

    def expose(defn, name=None, default=None, label=None):
        """Add a clone of a child's parameter as a model input; returns its name."""
        p = defn.clone()
        name = name or defn.name()
        p.setName(name)
        if label or name in LABELS:
            p.setDescription(label or LABELS[name])
        if default is not None:
            p.setDefaultValue(default)
        mp = QgsProcessingModelParameter(name)
        mp.setPosition(QPointF(120.0, y[0]))
        y[0] += 55.0
        m.addModelParameter(p, mp)
        order.append(name)
        return name

    sources = {k: {} for k in algs}
    gf = algs["groundfilter"]
    # 1. the cloud, 2. ground filter settings (its non-advanced parameters)
    sources["groundfilter"]["INPUT"] = Src.fromModelParameter(
        expose(gf.parameterDefinition("INPUT")))
    for d in gf.parameterDefinitions():
        if d.name() == "INPUT" or _is_destination(d) or \
                d.flags() & d.FlagAdvanced or d.name() == "REPORT_LANGUAGE":
            continue
        name = d.name() if d.name() not in DTM_SETTINGS else f"FILTER_{d.name()}"
        sources["groundfilter"][d.name()] = Src.fromModelParameter(expose(d, name))
    # 2b. project and operator, shown on every report of the chain (advanced, optional)
    _expose_report_fields(algs, expose, sources)
    # 3. DTM settings
    idw = algs["dtm"]
    for name, default in DTM_SETTINGS.items():
        sources["dtm"][name] = Src.fromModelParameter(
            expose(idw.parameterDefinition(name), default=default))
    sources["dtm"]["INPUT"] = Src.fromChildOutput("groundfilter", "OUTPUT")
    sources["dtm"]["CLASSES"] = Src.fromStaticValue("2")
    # 4. check points: a point layer or a CSV file
    acc = algs["accuracy"]
    for name in ("CHECKPOINTS", "CHECKPOINTS_CSV"):
        sources["accuracy"][name] = Src.fromModelParameter(
            expose(acc.parameterDefinition(name)))
    sources["accuracy"]["DTM"] = Src.fromChildOutput("dtm", "OUTPUT")
    # 5. the publish step: every child wrote a temporary; this one step moves them all
    for _label, output, _mandatory, (child_id, child_output) in OUTPUTS:
        sources["publish"][PUBLISH_SOURCES[output]] = Src.fromChildOutput(
            child_id, child_output)
    for name, model_param in PUBLISH_PROTECTED.items():
        sources["publish"][name] = Src.fromModelParameter(model_param)
    # every other child parameter: its default, written into the model explicitly
    for child_id, alg in algs.items():
        for d in alg.parameterDefinitions():
            if d.name() not in sources[child_id] and not _is_destination(d):
                sources[child_id][d.name()] = Src.fromStaticValue(d.defaultValue())
    _add_children(m, algs, sources)
    m.setParameterOrder(order)
    m.setHelpContent({
        "ALG_DESC": (
            "Classifies the ground of a LiDAR point cloud, interpolates a DTM from it by "
            "IDW and measures the DTM's accuracy against check points. Example: a "
            "classified tile with 15 check points gives the classified cloud, a 1 m DTM "
            "and a report with RMSE, NMAD and the 95 % vertical accuracy. Its steps write "
            "temporary files and a last step publishes them all or none: when any step "
            "fails (e.g. the report folder cannot be written) no classified cloud, DTM or "
            "report is left at any destination. The one-step algorithm 'LiDAR to DTM with "
            "accuracy' (geomatics:lidartodtm) also checks the CRS, the check points and "
            "every output path before its first step writes."),
        "ALG_CREATOR": "Geomatics Toolbox",
        "ALG_HELP_CREATOR": "Geomatics Toolbox",
        "TITLE": TITLE,
        "FILTER": filter_id,
    })
    return m


def _expose_report_fields(algs, expose, sources) -> None:
    """REPORT_PROJECT / REPORT_OPERATOR as model inputs, passed to every child."""
    from qgis.core import QgsProcessingModelChildParameterSource as Src
    for name in ("REPORT_PROJECT", "REPORT_OPERATOR"):
        defn = algs["groundfilter"].parameterDefinition(name)
        if defn is None:
            continue
        model_name = expose(defn)
        for child_id in ("groundfilter", "dtm", "accuracy"):
            if algs[child_id].parameterDefinition(name) is not None:
                sources[child_id][name] = Src.fromModelParameter(model_name)


def _add_children(m, algs, sources) -> None:
    """Add the four child algorithms with their parameter sources and outputs."""
    from qgis.core import QgsProcessingModelChildAlgorithm, QgsProcessingModelOutput
    from qgis.PyQt.QtCore import QPointF
    descriptions = {"groundfilter": f"Ground filter ({algs['groundfilter'].displayName()})",
                    "dtm": "DTM by IDW", "accuracy": "DTM accuracy against check points",
                    "publish": "Publish all outputs (all or nothing)"}
    for i, (child_id, alg) in enumerate(algs.items()):
        c = QgsProcessingModelChildAlgorithm(alg.id())
        c.setChildId(child_id)
        c.setDescription(descriptions[child_id])
        c.setPosition(QPointF(480.0, 80.0 + 180.0 * i))
        for pname, src in sources[child_id].items():
            c.addParameterSources(pname, [src])
        outs = {}
        for out_name, child_output, mandatory, _source in OUTPUTS:
            if child_id != "publish":
                continue
            o = QgsProcessingModelOutput(out_name, out_name)
            o.setChildId(child_id)
            o.setChildOutputName(child_output)
            o.setMandatory(mandatory)
            outs[out_name] = o
        c.setModelOutputs(outs)
        m.addChildAlgorithm(c)


def pin_output_names(model) -> None:
    """Keep the model outputs' names ``publish:<label>`` whichever QGIS builds the model.

    QGIS 3.40 makes new models ``internal_version=Version2``, whose outputs are named
    after their labels alone (``dtm`` instead of ``publish:DTM``), so the same command
    line, the demo and the tests would fail on one of the two versions. QGIS 3.22 knows
    only Version1, and every QGIS reads a model saved as Version1 (or without the
    option) with the ``<child>:<label>`` names: reload the model as Version1, which
    rebuilds its output parameters under those names.
    """
    variant = model.toVariant()
    if variant.get("internal_version", "Version1") == "Version1":
        return
    variant["internal_version"] = "Version1"
    if not model.loadVariant(variant):
        raise SystemExit("could not reload the model as internal_version Version1")


def _register_provider():
    """Register the plugin's provider so the filter's parameter definitions are copied."""
    import importlib.util

    from qgis.core import QgsApplication
    name = "geomatics_toolbox"
    if name not in sys.modules:
        spec = importlib.util.spec_from_file_location(
            name, ROOT / "__init__.py", submodule_search_locations=[str(ROOT)])
        mod = importlib.util.module_from_spec(spec)
        sys.modules[name] = mod
        spec.loader.exec_module(mod)
    try:
        from geomatics_toolbox.provider.provider import GeomaticsProvider
        provider = GeomaticsProvider()
        QgsApplication.processingRegistry().addProvider(provider)
        return provider
    except Exception as exc:  # noqa: BLE001 - fall back to the static definitions
        print(f"warning: provider not loaded ({exc}); using static parameter definitions",
              file=sys.stderr)
        return None


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--filter", choices=["auto", *sorted(FILTERS)], default="auto",
                    help="ground filter (auto: the recommended one when registered)")
    ap.add_argument("--out", default=str(DEFAULT_OUT))
    args = ap.parse_args(argv)
    os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
    from qgis.core import QgsApplication
    app = QgsApplication([], False)
    app.initQgis()
    provider = _register_provider()
    try:
        model = build(args.filter)
        pin_output_names(model)
        out = Path(args.out)
        out.parent.mkdir(parents=True, exist_ok=True)
        tmp = out.with_name(out.name + ".part")
        if not model.toFile(str(tmp)):
            print(f"could not write {out}", file=sys.stderr)
            return 1
        os.replace(tmp, out)
        print(f"wrote {out} (ground filter: {model.helpContent().get('FILTER')})")
    finally:
        if provider is not None:
            QgsApplication.processingRegistry().removeProvider(provider)
        app.exitQgis()
    return 0


if __name__ == "__main__":
    sys.exit(main())

#!/usr/bin/env python3
"""Build the shipped Processing model ``models/lidar_to_dtm.model3``.

LAS/LAZ → ground filter (``geomatics:lsqgroundfilter``) → IDW DTM
(``geomatics:idwdtm``, p = 3, 12 neighbours: the seed paper's best setting) →
DTM accuracy against check points (``geomatics:dtmaccuracy``), with the classified
cloud, the DTM, the residual layer and the reports as model outputs.

The model is built with the QGIS API (``QgsProcessingModelAlgorithm``) so that it is
reproducible and reviewable; rerun this script after changing a parameter.

Usage::

    .venv/bin/python scripts/build_model.py [--filter lsq|slope] [--out models/lidar_to_dtm.model3]

Run the model (plugin enabled in the QGIS profile)::

    qgis_process.bin run models/lidar_to_dtm.model3 -- INPUT=out/demo/demo.laz \\
        CHECKPOINTS_CSV=out/demo/checkpoints.csv CELL_SIZE=1 \\
        groundfilter:CLASSIFIED=out/model/ground.laz dtm:DTM=out/model/dtm.tif \\
        accuracy:RESIDUALS=out/model/residuals.gpkg accuracy:ACCURACY_REPORT=out/model/accuracy.html
"""
from __future__ import annotations

import argparse
import os
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
DEFAULT_OUT = ROOT / "models" / "lidar_to_dtm.model3"

# ground filter choices: algorithm id, extra parameters (name -> model parameter spec)
FILTERS = {
    "lsq": ("geomatics:lsqgroundfilter", "LSQ polynomial ground filter",
            [("ORDER", "Polynomial order of the ground filter", 2, 1, 2, True),
             ("TILE_SIZE", "Ground filter tile size (m)", 50.0, 0.0, None, False),
             ("THRESHOLD", "Ground filter threshold T (m)", 0.5, 0.0, None, False)]),
    "slope": ("geomatics:slopegroundfilter", "Vosselman slope ground filter",
              [("RADIUS", "Slope filter radius r (m)", 3.0, 0.0, None, False),
               ("SLOPE", "Slope threshold θ (degrees)", 44.0, 0.0, 90.0, False)]),
}


def build(filter_key: str = "lsq"):
    from qgis.core import (
        QgsProcessingModelAlgorithm,
        QgsProcessingModelChildAlgorithm,
        QgsProcessingModelOutput,
        QgsProcessingModelParameter,
        QgsProcessingParameterBoolean,
        QgsProcessingParameterCrs,
        QgsProcessingParameterFile,
        QgsProcessingParameterNumber,
    )
    from qgis.core import QgsProcessingModelChildParameterSource as Src
    from qgis.PyQt.QtCore import QPointF

    alg_id, filter_label, filter_params = FILTERS[filter_key]
    m = QgsProcessingModelAlgorithm("lidar_to_dtm", "Terrain models", "terrain")
    m.setHelpContent({
        "ALG_DESC": ("LiDAR point cloud → ground filter → IDW DTM (p = 3, 12 neighbours) "
                     "→ DTM accuracy against check points (RMSE, r, NMAD, 95 % accuracy). "
                     f"Ground filter: {filter_label}."),
        "INPUT": "LAS/LAZ point cloud (with a CRS record, or give CRS).",
        "CHECKPOINTS_CSV": "Check points: CSV with id,x,y,z in the DTM's CRS.",
        "CELL_SIZE": "DTM cell size in metres (default 1).",
        "POWER": "IDW power (default 3, the seed paper's best).",
        "CRS": "Optional CRS override for a point cloud without a CRS record.",
        "FILL_GAPS": ("Interpolate every DTM cell; by default cells farther than five mean "
                      "point spacings from a ground point stay nodata (no invented terrain)."),
    })
    y = 60.0

    def add_param(defn, x=120.0):
        nonlocal y
        mp = QgsProcessingModelParameter(defn.name())
        mp.setPosition(QPointF(x, y))
        y += 60.0
        m.addModelParameter(defn, mp)

    las = QgsProcessingParameterFile("INPUT", "Point cloud (LAS/LAZ)",
                                     fileFilter="LAS/LAZ point clouds (*.las *.laz *.LAS *.LAZ)")
    add_param(las)
    add_param(QgsProcessingParameterFile(
        "CHECKPOINTS_CSV", "Check points (CSV: id,x,y,z)",
        fileFilter="Delimited text (*.csv *.txt *.CSV *.TXT)"))
    add_param(QgsProcessingParameterNumber("CELL_SIZE", "DTM cell size (m)",
                                           QgsProcessingParameterNumber.Double, 1.0,
                                           False, 0.01))
    add_param(QgsProcessingParameterNumber("POWER", "IDW power", QgsProcessingParameterNumber
                                           .Double, 3.0, False, 0.1))
    add_param(QgsProcessingParameterCrs("CRS", "CRS override (optional)", optional=True))
    add_param(QgsProcessingParameterBoolean(
        "FILL_GAPS", "Fill data gaps in the DTM (interpolate far from ground points)",
        False))
    from qgis.core import QgsApplication
    registered = QgsApplication.processingRegistry().algorithmById(alg_id)
    for name, label, default, lo, hi, integer in filter_params:
        src = registered.parameterDefinition(name) if registered is not None else None
        if src is not None:             # same type, default and limits as the filter
            p = src.clone()
            p.setDescription(label)
        else:
            kind = (QgsProcessingParameterNumber.Integer if integer
                    else QgsProcessingParameterNumber.Double)
            p = QgsProcessingParameterNumber(name, label, kind, default, False, lo)
            if hi is not None:
                p.setMaximum(hi)
        add_param(p)

    def child(child_id, algorithm, description, x, yy, sources, outputs):
        c = QgsProcessingModelChildAlgorithm(algorithm)
        c.setChildId(child_id)
        c.setDescription(description)
        c.setPosition(QPointF(x, yy))
        for pname, src in sources.items():
            c.addParameterSources(pname, [src])
        outs = {}
        for out_name, child_output, label in outputs:
            o = QgsProcessingModelOutput(out_name)
            o.setChildId(child_id)
            o.setChildOutputName(child_output)
            o.setDescription(label)
            # the classified cloud, the DTM and the accuracy report must be named; the
            # other reports and the residual layer are optional
            o.setMandatory(out_name in ("CLASSIFIED", "DTM", "ACCURACY_REPORT"))
            outs[out_name] = o
        c.setModelOutputs(outs)
        m.addChildAlgorithm(c)
        return c

    fsources = {"INPUT": Src.fromModelParameter("INPUT")}
    for name, *_ in filter_params:
        fsources[name] = Src.fromModelParameter(name)
    child("groundfilter", alg_id, f"Ground filter ({filter_label})", 420.0, 80.0, fsources,
          [("CLASSIFIED", "OUTPUT", "Ground-classified point cloud"),
           ("FILTER_REPORT", "OUTPUT_HTML", "Ground filter report")])
    child("dtm", "geomatics:idwdtm", "DTM by IDW", 420.0, 240.0, {
        "INPUT": Src.fromChildOutput("groundfilter", "OUTPUT"),
        "CLASSES": Src.fromStaticValue("2"),
        "CELL_SIZE": Src.fromModelParameter("CELL_SIZE"),
        "POWER": Src.fromModelParameter("POWER"),
        "NEIGHBOURS": Src.fromStaticValue(12),
        "RADIUS": Src.fromStaticValue(0.0),
        "CRS": Src.fromModelParameter("CRS"),
        "FILL_GAPS": Src.fromModelParameter("FILL_GAPS"),
    }, [("DTM", "OUTPUT", "DTM (IDW)"), ("DTM_REPORT", "OUTPUT_HTML", "DTM report")])
    child("accuracy", "geomatics:dtmaccuracy", "DTM accuracy against check points", 420.0,
          400.0, {
              "DTM": Src.fromChildOutput("dtm", "OUTPUT"),
              "CHECKPOINTS_CSV": Src.fromModelParameter("CHECKPOINTS_CSV"),
              "METHOD": Src.fromStaticValue(0),
          }, [("RESIDUALS", "OUTPUT", "Check point residuals"),
              ("ACCURACY_REPORT", "OUTPUT_HTML", "DTM accuracy report")])
    return m


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
    ap.add_argument("--filter", choices=sorted(FILTERS), default="lsq")
    ap.add_argument("--out", default=str(DEFAULT_OUT))
    args = ap.parse_args(argv)
    os.environ.setdefault("QT_QPA_PLATFORM", "offscreen")
    from qgis.core import QgsApplication
    app = QgsApplication([], False)
    app.initQgis()
    provider = _register_provider()
    try:
        model = build(args.filter)
        out = Path(args.out)
        out.parent.mkdir(parents=True, exist_ok=True)
        tmp = out.with_name(out.name + ".part")
        if not model.toFile(str(tmp)):
            print(f"could not write {out}", file=sys.stderr)
            return 1
        os.replace(tmp, out)
        print(f"wrote {out} (ground filter: {FILTERS[args.filter][0]})")
    finally:
        if provider is not None:
            QgsApplication.processingRegistry().removeProvider(provider)
        app.exitQgis()
    return 0


if __name__ == "__main__":
    sys.exit(main())

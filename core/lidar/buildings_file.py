"""File runner of the building extraction: footprints, classified cloud, 3D city models.

:func:`buildings_file` reads a ground-classified LAS/LAZ (coordinates converted to
metres, :func:`.pipeline.read_cloud`), runs :func:`.buildings.extract_buildings` and
writes, all or none through one :class:`~..io.contract.OutputContract`:

* footprints (GeoPackage) with height, eave height, area, volume, storeys, roof type
  and slope — SI units (metres, m², m³), geometry in the data's CRS units; ``ground_z``,
  ``roof_z`` and ``height_z`` in the data's vertical unit (what a 3D view extrudes by
  in a feet CRS);
* optionally a copy of the cloud with class 6 on the buildings' points
  (:func:`.buildings.building_points`), every other attribute and VLR unchanged;
* optionally LOD1/LOD2 **CityJSON** 2.0 and an **OBJ** of the same solids
  (:mod:`.citymodel`, :mod:`~..io.cityjson`), vertices in the data's units;
* optionally the report (:func:`.buildings.buildings_report`).
"""
from __future__ import annotations

import os
from dataclasses import dataclass
from typing import Optional

import numpy as np

from ..progress import Monitor

__all__ = ["BuildingOutputs", "buildings_file", "FIELDS"]

FIELDS = [("id", "int"), ("height_m", "float"), ("eave_height_m", "float"),
          ("area_m2", "float"), ("volume_m3", "float"), ("storeys", "int"),
          ("roof_type", "str"), ("roof_slope_deg", "float"), ("ground_z", "float"),
          ("roof_z", "float"), ("height_z", "float")]


@dataclass
class BuildingOutputs:
    """Output paths (None = not asked) and their parameter names (for messages)."""

    footprints: str
    cloud: Optional[str] = None
    cityjson: Optional[str] = None
    obj: Optional[str] = None
    report: Optional[str] = None
    names: tuple = ("OUTPUT", "OUTPUT_CLOUD", "OUTPUT_CITYJSON", "OUTPUT_OBJ",
                    "OUTPUT_HTML")


def _records(res, v: float) -> dict:
    """Attribute rows of the footprints (``ground_z``/``roof_z`` in the data's z unit)."""
    return {b["id"]: {"id": b["id"], "height_m": b["height"],
                      "eave_height_m": b["eave_height"], "area_m2": b["area"],
                      "volume_m3": b["volume"], "storeys": b["storeys"],
                      "roof_type": b["roof_type"], "roof_slope_deg": b["slope"],
                      "ground_z": b["ground"] / v, "roof_z": b["roof"] / v,
                      "height_z": b["height"] / v}
            for b in res.buildings}


def buildings_file(src, outputs: BuildingOutputs, *, ground_classes=(2,), params=None,
                   render=None, lang: str = "en", progress=None, cancel=None):
    """Extract the buildings of ``src`` and write every requested output, or none.

    Parameters
    ----------
    src : path
        Ground-classified LAS/LAZ in a projected CRS (any linear unit).
    outputs : BuildingOutputs
    ground_classes : sequence of int
    params : dict, optional
        Keyword options of :func:`.buildings.extract_buildings` (metres).
    render : callable(Report) -> str, optional
        HTML renderer; default :func:`~..reporting.render_html` in ``lang``.

    Returns
    -------
    (BuildingResult, Units)
    """
    from ..io.cityjson import write_cityjson, write_obj
    from ..io.contract import OutputContract
    from ..io.las import write_las_like
    from ..io.vector import label_outlines, write_label_polygons
    from ..reporting import render_html
    from .buildings import building_points, buildings_report, extract_buildings
    from .citymodel import city_objects
    from .classify import height_above_ground
    from .pipeline import read_cloud
    mon = Monitor(progress, cancel)
    params = dict(params or {})
    n = outputs.names
    paths = dict(zip(n, (outputs.footprints, outputs.cloud, outputs.cityjson, outputs.obj,
                         outputs.report)))
    with OutputContract(paths, inputs={"INPUT": src}, point_clouds=[n[1]]) as out:
        # the decoded records are kept for the cloud copy: the input is decoded once
        pd = read_cloud(src, returns=False, keep_records=out.requested(n[1]),
                        monitor=mon.sub(0.0, 0.1))
        units = pd.info.units
        h, v = units.h, units.v
        cls = pd["classification"]
        res = extract_buildings(pd.x, pd.y, pd.z, cls, ground_classes=ground_classes,
                                crs=pd.info.crs, progress=mon.sub(0.1, 0.85).update,
                                cancel=mon.cancelled, **params)
        gt = np.asarray(res.grid.geotransform, dtype=float) / h     # back to data units
        write_label_polygons(out.path(n[0]), res.labels, gt, crs=pd.info.crs,
                             layer_name="buildings", fields=FIELDS,
                             records=_records(res, v))
        if out.requested(n[1]):
            hag = pd.z - height_above_ground(pd.x, pd.y, res.grid, res.dtm)
            flag = building_points(res, pd.x, pd.y, pd.z, hag, cls)
            write_las_like(src, out.path(n[1]), dimensions={
                "classification": np.where(flag, 6, cls).astype(cls.dtype)},
                records=pd.records, progress=mon.sub(0.85, 0.95).update, cancel=mon.cancelled)
        if out.requested(n[2]) or out.requested(n[3]):
            irregular = np.isin(res.labels, [b["id"] for b in res.buildings
                                             if not b["regularised"]])
            outlines = label_outlines(np.where(irregular, res.labels, 0),
                                      res.grid.geotransform, tolerance=res.grid.cell)
            objs = city_objects(res, outlines=outlines)
            if out.requested(n[2]):
                write_cityjson(out.path(n[2]), objs, crs=pd.info.crs, h=h, v=v,
                               title=os.path.basename(os.fspath(src)))
            if out.requested(n[3]):
                write_obj(out.path(n[3]), objs, h=h, v=v)
        if out.requested(n[4]):
            rep = buildings_report(res, os.path.basename(os.fspath(src)), units=units,
                                   lang=lang)
            out.write_text(n[4], (render or (lambda r: render_html(r, lang=lang)))(rep))
        mon.check()
    mon.update(1.0)
    return res, units

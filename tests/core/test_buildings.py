"""Building footprints against the synthetic generator's true buildings."""
from __future__ import annotations

import numpy as np
import pytest

from geomatics_toolbox.core.errors import InputError
from geomatics_toolbox.core.lidar import buildings as core_b
from geomatics_toolbox.synthetic.buildings_eval import building_accuracy
from geomatics_toolbox.synthetic.lidar import generate_tile


@pytest.fixture(scope="module")
def tile_result():
    tile = generate_tile(extent=(220.0, 220.0), density=5.0, seed=4, n_buildings=12)
    cls = tile.classification.copy()
    cls[np.isin(cls, (5, 6))] = 1          # as after a ground filter: 2 or 1 only
    return tile, core_b.extract_buildings(tile.x, tile.y, tile.z, cls)


def test_accuracy_meets_the_targets(tile_result):
    tile, res = tile_result
    acc = building_accuracy(tile, res.labels, res.grid,
                            [b["height"] for b in res.buildings])
    assert acc["n_true"] >= 8
    assert acc["completeness"] >= 0.95 and acc["correctness"] >= 0.95, acc
    assert acc["mean_iou"] >= 0.85 and acc["height_rmse"] <= 0.3, acc


def test_attributes_and_roof_types(tile_result):
    tile, res = tile_result
    for b in res.buildings:
        assert b["area"] > 0 and b["volume"] > 0 and b["storeys"] == max(1, int(
            b["height"] // 3))
        assert b["volume"] <= b["area"] * b["height"] * 1.05
    acc_types = []
    for b in res.buildings:
        k = b["id"]
        d = res.labels == k
        xs, ys = np.meshgrid(res.grid.x_centers(), res.grid.y_centers())
        u, v = tile.buildings.local(slice(None), xs[d].mean(), ys[d].mean())
        i = int(np.argmin(np.hypot(np.clip(np.abs(u) - tile.buildings.half_length, 0, None),
                                   np.clip(np.abs(v) - tile.buildings.half_width, 0, None))))
        acc_types.append((b["roof_type"] == "pitched") == bool(tile.buildings.gabled[i]))
    assert np.mean(acc_types) >= 0.9
    # roof points flagged as buildings are true building points (class 6)
    assert (tile.classification[res.is_building] == 6).mean() > 0.97


def test_no_ground_is_refused():
    x = np.arange(10.0)
    with pytest.raises(InputError, match="No ground points"):
        core_b.extract_buildings(x, x, x, np.ones(10, int))


def test_report_and_polygons(tile_result, tmp_path):
    from geomatics_toolbox.core.io.vector import read_polygons, write_label_polygons
    from geomatics_toolbox.core.reporting import render_html
    from geomatics_toolbox.core.reporting.i18n import has_translation
    tile, res = tile_result
    rep = core_b.buildings_report(res, "t.laz", {"min_height": 2, "max_angle": 20,
                                                 "min_patch_area": 15, "min_area": 15})
    missing = {m for m in rep.messages() for lang in ("ar", "fa")
               if not has_translation(m, lang)}
    assert not missing, missing
    assert 'id="footprint-map"' in render_html(rep, lang="fa")
    recs = {b["id"]: {"id": b["id"], "area": b["area"]} for b in res.buildings}
    n = write_label_polygons(tmp_path / "b.gpkg", res.labels, res.grid.geotransform,
                             crs="EPSG:32632", fields=[("id", "int"), ("area", "float")],
                             records=recs)
    assert n == len(res.buildings)
    from osgeo import ogr
    for attrs, wkt in read_polygons(tmp_path / "b.gpkg"):
        assert ogr.CreateGeometryFromWkt(wkt).GetArea() == pytest.approx(attrs["area"])

"""Terrain reports: Report content, figures with legend/scale bar, fully translated."""
from __future__ import annotations

import re

import numpy as np
import pytest

from geomatics_toolbox.core.reporting import T, render_html, translator
from geomatics_toolbox.core.reporting.i18n import has_translation
from geomatics_toolbox.core.reporting.svg import nice_length, png_data_uri
from geomatics_toolbox.core.terrain import report as tr_report
from geomatics_toolbox.core.terrain.accuracy import dtm_accuracy
from geomatics_toolbox.core.terrain.grid import grid_from_extent
from geomatics_toolbox.core.terrain.kriging import kriging_grid

FIGURE_TEXT = ["terrain (hillshade)", "nodata", "Legend", "Hillshade", "Residual map",
               "not used (outside / nodata)", "Error DTM − check (m)", "check height (m)",
               "error DTM − check (m)", "zero error", "Error against height",
               "outside DTM", "DTM nodata", "used"]


@pytest.fixture(scope="module")
def reports():
    rng = np.random.default_rng(1)
    grid = grid_from_extent((0, 60, 0, 40), 1.0, crs="EPSG:32632")
    x, y = rng.uniform(0, 60, 800), rng.uniform(0, 40, 800)
    z = 100 + 0.1 * x + np.sin(y / 5)
    kr = kriging_grid(x, y, z, grid, n_closest=8, cv_points=30)
    kr.z[:5, :7] = np.nan                                     # a nodata corner
    stats = {"valid_cells": int(np.isfinite(kr.z).sum()),
             "nodata_cells": int(np.isnan(kr.z).sum()),
             "min": float(np.nanmin(kr.z)), "max": float(np.nanmax(kr.z))}
    rep = tr_report.grid_report(
        "Kriging DTM report", method_rows=[("method", T("ordinary kriging"))],
        input_rows=[("input", "t.laz"), ("points used", 800)], grid=grid, data=kr.z,
        stats=stats, elapsed=1.0, citation="Shepard (1968) inverse distance weighting, "
        "semantics of gdal_grid -a invdistnn.")
    tr_report.kriging_sections(rep, kr)
    cx, cy = np.array([10.0, 30.0, 50.0, 200.0]), np.array([10.0, 20.0, 30.0, 20.0])
    cz = 100 + 0.1 * cx + np.sin(cy / 5) + np.array([0.05, -0.2, 0.1, 0])
    res = dtm_accuracy(kr.z, grid.geotransform, cx, cy, cz)
    acc = tr_report.accuracy_report(res, ["a", "b", "c", "far"], kr.z, grid.geotransform,
                                    dtm_name="dtm.tif", crs_label="EPSG:32632")
    return rep, acc, res, kr.z, grid.geotransform


def test_every_report_message_translated(reports):
    for rep in reports[:2]:
        for lang in ("ar", "fa"):
            missing = [m for m in rep.messages() + FIGURE_TEXT if not has_translation(m, lang)]
            assert not missing, (lang, missing)


def test_figures_have_ids_legend_units_and_scale_bar(reports):
    rep, _, res, dtm, gt = reports
    acc = tr_report.accuracy_report(res, ["a", "b", "c", "far"], dtm, gt,
                                    dtm_name="dtm.tif", crs_label="EPSG:32632",
                                    tr=translator("ar"))
    html = render_html(rep, lang="fa")
    assert 'dir="rtl"' in html and 'id="hillshade"' in html
    html = render_html(acc, lang="ar")
    for fid in ("residual-map", "error-vs-height"):
        assert f'id="{fid}"' in html
    for fig in re.findall(r"<figure.*?</figure>", html, flags=re.S):
        assert 'class="legend"' in fig and " m<" in fig or "(م)" in fig
    maps = re.findall(r'<figure id="(?:hillshade|residual-map)".*?</figure>', html + render_html(
        rep, lang="en"), flags=re.S)
    assert len(maps) == 2 and all('class="scale-bar"' in m for m in maps)
    # translated figure text, not English
    assert translator("ar")("Residual map") in html and "Residual map" not in html


def test_residual_map_colours_by_error(reports):
    _, _, res, dtm, gt = reports
    fig = tr_report.residual_map_figure(res, ["a", "b", "c", "far"], dtm, gt)
    tips = re.findall(r"<circle[^>]*fill=\"(#[0-9a-f]{6})\"[^>]*><title>([^<]*)</title>",
                      fig.svg)
    colour = dict((t.split(":")[0], c) for c, t in tips)
    assert colour["far"] == "#000000"                           # outside: not used
    # error = DTM − check: b's check is 0.2 m low -> DTM above -> darkest red;
    # a and c are 0.05 / 0.1 m high -> DTM below -> blue side, c darker than a
    assert colour["b"] == "#b2182b"
    assert colour["c"] in ("#2166ac", "#67a9cf", "#d1e5f0") and colour["a"] != colour["b"]


def test_hillshade_flat_is_uniform_and_nodata_kept():
    z = np.full((20, 30), 5.0)
    z[0, 0] = np.nan
    hs = tr_report.hillshade(z, 1.0)
    assert np.isnan(hs[0, 0]) and np.nanstd(hs) < 1e-12
    assert np.nanmax(hs) == pytest.approx(np.cos(np.radians(45)))


def test_png_and_scale_helpers():
    uri = png_data_uri(np.zeros((3, 4, 3), np.uint8))
    import base64
    raw = base64.b64decode(uri.split(",", 1)[1])
    assert raw[:8] == b"\x89PNG\r\n\x1a\n" and int.from_bytes(raw[16:20], "big") == 4
    assert nice_length(137) == 100 and nice_length(0.7) == 0.5 and nice_length(3) == 2

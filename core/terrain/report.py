"""Report content of the terrain tools: IDW, kriging, TIN, DSM/nDSM and DTM accuracy.

Each ``*_report`` function returns a :class:`~..reporting.Report` (rendered once by
:func:`~..reporting.render_html` in the user's language) with SVG figures: a hillshade
preview of the grid with nodata shown (``figure_id="hillshade"``), and for the DTM
accuracy a residual map of the check points over the DTM extent
(``"residual-map"``) and the error against height (``"error-vs-height"``). Figures
carry a legend, units and a scale bar; their text is translated with ``tr``.

References
----------
Shepard, D. (1968). A two-dimensional interpolation function for irregularly-spaced
data. Proc. 23rd ACM National Conference, 517–524.
Matheron, G. (1963). Principles of geostatistics. Economic Geology 58(8), 1246–1266.
Cressie, N. (1993). Statistics for Spatial Data, revised ed. Wiley.
Horn, B.K.P. (1981). Hill shading and the reflectance map. Proc. IEEE 69(1), 14–47.
Höhle, J., Höhle, M. (2009). Accuracy assessment of digital elevation models by means
of robust statistical methods. ISPRS J. Photogramm. Remote Sens. 64(4), 398–406.
"""
from __future__ import annotations

from typing import Callable, Sequence

import numpy as np

from ..io.units import units_rows
from ..reporting import Figure, KeyValues, Paragraph, Report, T, Table, svg
from . import accuracy as acc

Translator = Callable[[str], str]
MAP_PX = 420


def _identity(text: str) -> str:
    return text


def hillshade(dtm: np.ndarray, cell: float, *, azimuth: float = 315.0,
              altitude: float = 45.0) -> np.ndarray:
    """Return Horn's (1981) hillshade in 0…1 of a north-up grid (NaN where nodata).

    Parameters
    ----------
    dtm : 2-D array
        Heights, row 0 north, NaN = nodata.
    cell : float
        Cell size (same unit as the heights).
    azimuth, altitude : float
        Sun direction and elevation (degrees).
    """
    z = np.asarray(dtm, dtype=np.float64)
    ok = np.isfinite(z)
    if not ok.any():
        return np.full(z.shape, np.nan)
    filled = np.where(ok, z, np.nanmean(z))
    p = np.pad(filled, 1, mode="edge")
    dzdx = ((p[:-2, 2:] + 2 * p[1:-1, 2:] + p[2:, 2:])
            - (p[:-2, :-2] + 2 * p[1:-1, :-2] + p[2:, :-2])) / (8 * cell)
    dzdy = ((p[2:, :-2] + 2 * p[2:, 1:-1] + p[2:, 2:])
            - (p[:-2, :-2] + 2 * p[:-2, 1:-1] + p[:-2, 2:])) / (8 * cell)
    slope = np.arctan(np.hypot(dzdx, dzdy))
    aspect = np.arctan2(dzdy, -dzdx)
    zen, az = np.radians(90.0 - altitude), np.radians(360.0 - azimuth + 90.0)
    shade = (np.cos(zen) * np.cos(slope) + np.sin(zen) * np.sin(slope) * np.cos(az - aspect))
    return np.where(ok, np.clip(shade, 0.0, 1.0), np.nan)


def _preview(data: np.ndarray, max_px: int = MAP_PX) -> np.ndarray:
    """Decimate a grid to at most ``max_px`` rows and columns (every k-th cell)."""
    step = max(1, int(np.ceil(max(data.shape) / max_px)))
    return data[::step, ::step]


def hillshade_figure(dtm: np.ndarray, geotransform: Sequence[float], *,
                     tr: Translator = _identity, unit: str = "m",
                     caption: str = "Hillshade of the grid; nodata cells in magenta.") -> Figure:
    """Return the hillshade preview figure (``figure_id='hillshade'``)."""
    cell = abs(float(geotransform[1]))
    shade = _preview(hillshade(dtm, cell))
    rows, cols = shade.shape
    scale = MAP_PX / max(rows, cols)
    w, h = cols * scale, rows * scale
    grey = np.nan_to_num(shade, nan=0.0) * 215 + 40
    rgb = np.repeat(grey[:, :, None], 3, axis=2).astype(np.uint8)
    rgb[~np.isfinite(shade)] = svg.NODATA_COLOUR
    units_per_px = cell * dtm.shape[1] / w
    nodata = int((~np.isfinite(dtm)).sum())
    parts = [svg.image(10, 10, w, h, rgb),
             svg.scale_bar(20, h, min(w / 3, 150), units_per_px, unit=unit),
             svg.north_arrow(w - 10, 18),
             svg.legend(w + 25, 24, [("#bbbbbb", tr("terrain (hillshade)")),
                                     ("#ff00ff", tr("nodata") + f" ({nodata})")],
                        title=tr("Legend"))]
    return Figure(svg.figure(int(w + 190), int(h + 25), parts, title=tr("Hillshade")),
                  caption=caption, figure_id="hillshade")


def _map_transform(extent, width_px):
    x0, x1, y0, y1 = extent
    scale = width_px / max(x1 - x0, y1 - y0, 1e-9)
    return scale, (lambda x: 10 + (np.asarray(x) - x0) * scale), (
        lambda y: 10 + (y1 - np.asarray(y)) * scale)


def residual_map_figure(res: acc.AccuracyResult, ids: Sequence, dtm: np.ndarray,
                        geotransform: Sequence[float], *,
                        tr: Translator = _identity, units=None) -> Figure:
    """Return the check points coloured by error over the DTM (``'residual-map'``).

    ``units`` (:class:`~..io.units.Units`) of a DTM in feet: its coordinates stay in
    feet (the scale bar says so), its heights (``dtm``) are already metres.
    """
    gt = geotransform
    rows, cols = dtm.shape
    extent = (gt[0], gt[0] + gt[1] * cols, gt[3] + gt[5] * rows, gt[3])
    used = res.status == acc.OK
    pts_x = np.concatenate([[extent[0], extent[1]], res.x[np.isfinite(res.x)]])
    pts_y = np.concatenate([[extent[2], extent[3]], res.y[np.isfinite(res.y)]])
    view = (pts_x.min(), pts_x.max(), pts_y.min(), pts_y.max())
    scale, px, py = _map_transform(view, MAP_PX)
    w = (view[1] - view[0]) * scale
    h = (view[3] - view[2]) * scale
    h_unit = units.horizontal if units is not None else None
    shade = _preview(hillshade(dtm, abs(gt[1]) * (h_unit.metres if h_unit else 1.0)))
    grey = np.nan_to_num(shade, nan=1.0) * 120 + 120
    rgb = np.repeat(grey[:, :, None], 3, axis=2).astype(np.uint8)
    limit = float(np.nanmax(np.abs(res.error[used]))) if used.any() else 1.0
    colours = svg.diverging_colours(res.error, limit)
    colours = [c if used[i] else "#000000" for i, c in enumerate(colours)]
    tips = [f"{ids[i]}: {res.error[i]:+.3f} m" if used[i] else f"{ids[i]}: "
            + tr(acc.STATUS_NAMES[int(res.status[i])]) for i in range(res.n_total)]
    entries = svg.diverging_legend_entries(limit)
    if (~used).any():
        entries.append(("#000000", tr("not used (outside / nodata)")))
    parts = [svg.image(float(px(extent[0])), float(py(extent[3])),
                       (extent[1] - extent[0]) * scale, (extent[3] - extent[2]) * scale, rgb),
             svg.circles(px(res.x), py(res.y), colours, titles=tips),
             svg.scale_bar(20, h + 5, min(w / 3, 150), 1.0 / scale,
                           unit=h_unit.symbol if h_unit else "m"),
             svg.north_arrow(w - 5, 18),
             svg.legend(w + 30, 24, entries, title=tr("Error DTM − check (m)"),
                        shape="circle")]
    return Figure(svg.figure(int(w + 220), int(h + 30), parts, title=tr("Residual map")),
                  caption="Check points coloured by error (blue: DTM below, red: DTM "
                          "above) over the DTM hillshade.", figure_id="residual-map")


def error_height_figure(res: acc.AccuracyResult, *, tr: Translator = _identity) -> Figure:
    """Return the error against check height scatter (``'error-vs-height'``)."""
    used = res.status == acc.OK
    zc, err = res.z_check[used], res.error[used]
    lim = float(np.abs(err).max()) if err.size else 1.0
    frame, px, py = svg.axes((60, 15, 380, 230), (zc.min(), zc.max()) if zc.size else (0, 1),
                             (-lim, lim), xlabel=tr("check height (m)"),
                             ylabel=tr("error DTM − check (m)"))
    rmse = float(np.sqrt(np.mean(err ** 2))) if err.size else float("nan")
    zero = (f'<line x1="60" x2="440" y1="{py(0):.1f}" y2="{py(0):.1f}" stroke="#444" '
            'stroke-dasharray="4 3"/>')
    band = "".join(f'<line x1="60" x2="440" y1="{py(s * rmse):.1f}" y2="{py(s * rmse):.1f}" '
                   'stroke="#b2182b" stroke-dasharray="2 2"/>' for s in (-1, 1)
                   if np.isfinite(rmse))
    parts = [frame, zero, band,
             svg.circles(px(zc), py(err), svg.diverging_colours(err, lim), r=3.5),
             svg.legend(455, 24, [("#444444", tr("zero error")),
                                  ("#b2182b", "± RMSE" + f" = {rmse:.3f} m")],
                        title=tr("Legend"))]
    return Figure(svg.figure(640, 290, parts, title=tr("Error against height")),
                  caption="Error against check-point height: a trend reveals a vertical "
                          "datum or scale problem.", figure_id="error-vs-height")


def _grid_rows(grid_shape, cell, extent, stats) -> list:
    rows, cols = grid_shape
    return [("grid", f"{cols} × {rows}", "cells"), ("cell size", cell, "m"),
            ("extent (xmin, xmax, ymin, ymax)", ", ".join(f"{v:.3f}" for v in extent)),
            ("cells with a value", stats["valid_cells"]),
            ("nodata cells", stats["nodata_cells"]),
            ("min height", stats["min"], "m"), ("max height", stats["max"], "m")]


def grid_report(title: str, *, method_rows: Sequence, input_rows: Sequence, grid,
                data: np.ndarray, stats: dict, citation: str, elapsed: float,
                tr: Translator = _identity) -> Report:
    """Return the report of a gridded model (IDW DTM, kriging DTM, DSM).

    Parameters
    ----------
    title : str
        Report title (English message id).
    method_rows, input_rows : sequence of (label, value[, unit])
        Method parameters and input facts (labels are message ids).
    grid : GridSpec
        The output grid.
    data : 2-D array
        The output grid values (NaN = nodata), shown as a hillshade.
    stats : dict
        ``valid_cells``, ``nodata_cells``, ``min``, ``max``.
    citation : str
        Method reference (message id).
    elapsed : float
        Run time (s).
    tr : callable
        Translator for the figure text.
    """
    rep = Report(title, citation=citation)
    rep.summary.append(Paragraph(T("{valid} cells with a value, {nodata} nodata cells.",
                                   valid=stats["valid_cells"], nodata=stats["nodata_cells"])))
    rep.section("Method").add(KeyValues(list(method_rows)))
    rep.section("Input").add(KeyValues(list(input_rows)))
    res = rep.section("Result")
    res.add(KeyValues(_grid_rows(grid.shape, grid.cell, grid.extent, stats)
                      + [("run time", round(elapsed, 1), "s")]))
    res.add(hillshade_figure(data, grid.geotransform, tr=tr))
    return rep


def kriging_sections(rep: Report, result, *, tr: Translator = _identity) -> Report:
    """Add the variogram, variance and cross-validation sections of a kriging run."""
    v = result.variogram
    sec = rep.section("Variogram")
    sec.add(KeyValues([(k.replace("_", " "), val) for k, val in v.as_dict().items()]
                      + [("model", v.model)], digits=4))
    if v.fitted and v.lags.size:
        sec.add(Table(["lag (m)", "experimental γ (m²)", "model γ (m²)"],
                      [list(r) for r in zip(v.lags, v.semivariance, v(v.lags))], digits=4,
                      caption="Experimental and fitted semivariogram"))
    var = result.variance[np.isfinite(result.variance)]
    if var.size:
        sec.add(KeyValues([("mean kriging standard deviation", float(np.sqrt(var).mean()), "m"),
                           ("max kriging standard deviation", float(np.sqrt(var).max()), "m")],
                          digits=4))
    cv = result.cross_validation
    if cv:
        rep.section("Leave-one-out cross-validation").add(KeyValues([
            ("points", cv["n"]), ("mean error ME", cv["me"], "m"), ("RMSE", cv["rmse"], "m"),
            ("MAE", cv["mae"], "m"), ("mean standardised error (ideal 0)", cv["mse_std"]),
            ("RMS standardised error (ideal 1)", cv["rmsse"])], digits=4))
    return rep


def accuracy_report(res: acc.AccuracyResult, ids: Sequence, dtm: np.ndarray,
                    geotransform: Sequence[float], *, dtm_name: str, crs_label: str,
                    tr: Translator = _identity, max_rows: int = 500, units=None) -> Report:
    """Return the DTM accuracy report: statistics, residual map, error vs height, table.

    The statistics follow the ASPRS Positional Accuracy Standards (2014): vertical
    accuracy at 95 % = 1.96·RMSE; NMAD after Höhle & Höhle (2009).
    """
    s = res.summary()
    rep = Report("DTM accuracy against check points",
                 citation="ASPRS Positional Accuracy Standards for Digital Geospatial Data "
                          "(2014); NMAD after Höhle & Höhle (2009), ISPRS J. 64(4), 398–406.")
    rep.summary.append(Paragraph(T("N = {n}, RMSE = {rmse} m, mean error = {me} m.",
                                   n=s["n"], rmse=round(s["rmse"], 4), me=round(s["me"], 4))))
    if acc.few_check_points(res.n_used):
        rep.summary.append(Paragraph(T(acc.FEW_CHECK_POINTS, n=res.n_used,
                                       minimum=acc.ASPRS_MIN_CHECK_POINTS), kind="fail"))
    rep.section("Input").add(KeyValues([
        ("DTM", dtm_name), ("CRS", crs_label),
        *units_rows(units), ("sampling", T(res.method)),
        ("check points given", res.n_total), ("used", res.n_used),
        ("outside the DTM (excluded)", res.n_outside),
        ("on DTM nodata or without height (excluded)", res.n_nodata),
        ("bilinear with some nodata neighbours (renormalised)", res.n_partial)]))
    rep.section("Statistics (error = DTM − check)").add(KeyValues([
        ("N", s["n"]), ("mean error ME", s["me"], "m"), ("median error", s["median_error"], "m"),
        ("mean absolute error MAE", s["mae"], "m"), ("RMSE", s["rmse"], "m"),
        ("standard deviation", s["std"], "m"), ("min error", s["min_error"], "m"),
        ("max error", s["max_error"], "m"), ("max |error|", s["max_abs_error"], "m"),
        ("NMAD", s["nmad"], "m"),
        ("vertical accuracy 95 % = 1.96·RMSE (ASPRS 2014)", s["accuracy_95"], "m"),
        ("95th percentile of |error|", s["p95_abs_error"], "m")], digits=4))
    figs = rep.section("Figures")
    figs.add(residual_map_figure(res, ids, dtm, geotransform, tr=tr, units=units))
    figs.add(error_height_figure(res, tr=tr))
    order = np.argsort(-np.nan_to_num(np.abs(res.error), nan=-1.0))[:max_rows]
    ok = res.status == acc.OK
    rows = [[str(ids[i]), res.x[i], res.y[i], res.z_check[i],
             res.z_dtm[i] if ok[i] else None, res.error[i] if ok[i] else None,
             T(acc.STATUS_NAMES[int(res.status[i])])] for i in order]
    rep.section("Residuals (largest |error| first)").add(Table(
        ["id", "x (m)", "y (m)", "z check (m)", "z DTM (m)", "error (m)", "status"], rows,
        digits=3))
    return rep


def tin_report(res, name: str, n_in_file: int, grid, *, units=None) -> Report:
    """Report of a TIN DTM run: input and grid, triangles, cells and a height map.

    ``res`` is a :class:`~.tin.TinResult` (Delaunay 1934; Barber et al. 1996, Qhull),
    ``name`` the input's file name and ``n_in_file`` its number of points.
    """
    from ..reporting.svg import svg_raster
    ok = np.isfinite(res.z)
    rep = Report("TIN DTM report", citation=T(
        "Delaunay (1934); Barber et al. (1996), {library}; same method as {command}.",
        library="Qhull", command="gdal_grid -a linear"))
    rep.section("Input and grid").add(KeyValues([
        ("Input", name),
        *units_rows(units),
        ("Points in file", n_in_file),
        ("Points triangulated", res.n_points),
        ("Grid (columns × rows)", f"{grid.ncols} × {grid.nrows}"),
        ("Cell size (m)", grid.cell)]))
    rep.section("Result").add(KeyValues([
        ("Triangles", res.n_triangles),
        ("Triangles dropped (edge too long)", res.n_long),
        ("Maximum triangle edge (m)", res.max_edge if res.max_edge else np.nan),
        ("Cells with a value", int(ok.sum())),
        ("Nodata cells", int((~ok).sum())),
        ("Minimum height (m)", float(res.z[ok].min()) if ok.any() else np.nan),
        ("Maximum height (m)", float(res.z[ok].max()) if ok.any() else np.nan)])
    ).add(Figure(svg_raster(res.z, unit="m"), "TIN DTM heights", "dtm-map"))
    if res.max_edge is None:
        rep.sections[-1].add(Paragraph("Gaps were filled: long triangles were kept.",
                                       "note"))
    return rep

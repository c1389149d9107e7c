"""Report content and tile table of the LSQ ground filter (:class:`~.lsq.LsqFilter`).

Method: tiled least-squares polynomial filter, Damascus Univ. J. Eng. Sci. 29(2),
2013 (the paper's Tables 1–2 are the iteration tables below); accuracy terms after
Sithole & Vosselman (2004).
"""
from __future__ import annotations

import csv
import io
from typing import List

import numpy as np

from ..reporting import Paragraph, T, Table
from ._lsq_fit import STATUS_NAMES, TERMS

MAX_TILE_ROWS = 200
STATUS_LABELS = {"too few points": "too few points", "converged": "converged",
                 "iteration cap": "iteration cap"}


def lsq_settings(opt) -> List[tuple]:
    """Report rows of :class:`~.lsq.LsqOptions`.

    Parameters
    ----------
    opt : LsqOptions
        The options.

    Returns
    -------
    list of tuple
        ``(label, value)`` rows.
    """
    poly = " + ".join(f"b{i}·{t}" if t != "1" else "b0" for i, t in enumerate(TERMS[opt.order]))
    return [("Mode", T("Faithful (paper)") if opt.mode == "faithful"
             else T("Improved (coarse-to-fine, slope-adaptive)")),
            ("Polynomial order", opt.order), ("Polynomial", poly),
            ("Tile size (m)", opt.tile_size), ("Threshold T (m)", opt.threshold),
            ("Maximum iterations", opt.max_iterations if opt.max_iterations else T("default")),
            ("Stop tolerance (m)", opt.tolerance),
            ("Fitting subset per tile", opt.subset_size or T("all points")),
            ("Random seed", opt.seed),
            ("Minimum points per tile", opt.min_points or T("default")),
            ("Under-populated tiles", T("borrow the nearest surface")
             if opt.sparse_tiles == "borrow" else T("leave unclassified")),
            ("Rejection", T("reweighted every iteration") if opt.rejection == "reweighted"
             else T("cumulative"))]


def _stat_rows(rows) -> list:
    return [(_step(r["step"]), r["points"], r["zmin"], r["zmax"], r["zmean"], r["std"])
            for r in rows]


def _step(label: str):
    if label in ("fitting points", "all fitting points"):
        return T(label)
    if label.startswith("iteration "):
        return T("iteration {k}", k=int(label.split()[1]))
    return label


def lsq_sections(res, report, tr) -> None:
    """Append the LSQ sections (iterations, levels, fullest tile, tiles) to ``report``.

    Parameters
    ----------
    res : LsqResult
        The filter's result.
    report : Report
        The report to extend.
    tr : callable
        Translator for text drawn inside figures.
    """
    hdr = ["Step", "Points", "ZMin", "ZMax", "ZMean", "σ"]
    it_rows = [(*row, s["active_tiles"] if s["active_tiles"] is not None else "")
               for row, s in zip(_stat_rows(res.iteration_stats), res.iteration_stats)]
    sec = report.section("Iterations, all tiles")
    sec.add(Paragraph("Kept heights after each iteration, aggregated over the tiles (a tile "
                      "that has stopped keeps its last values); the layout of the paper's "
                      "Tables 1–2.", "note"))
    sec.add(Table([*hdr, "Tiles still iterating"], it_rows, digits=2))
    if res.params["mode"] == "improved" and res.levels:
        report.section("Coarse-to-fine levels").add(Table(
            ["Level", "Tile size (m)", "Tiles", "Fitted", "Ground seeds", "Seconds"],
            [(d["level"], d["tile_size"], d["tiles"], d["fitted"], d["seed_points"],
              d["seconds"]) for d in res.levels], digits=2)).add(Paragraph(
                "The iteration and tile tables describe the finest level.", "note"))
    order = np.argsort(-res.tile_points, kind="stable")
    big = int(order[0])
    report.section(T("Fullest tile ({col}, {row}), iteration by iteration",
                     col=int(res.grid.ix[big]), row=int(res.grid.iy[big]))).add(
        Table(hdr, _stat_rows(res.tile_table(big)), digits=2))
    _tile_sections(res, report, order, tr)


def _tile_sections(res, report, order, tr) -> None:
    sec = report.section("Tiles")
    _tile_map(res, sec, tr)
    sec.add(Table(["Status", "Tiles"], [(T(k), v) for k, v in res.status_counts().items()]))
    st = res.tile_stats
    rows = []
    for t in order[:MAX_TILE_ROWS]:
        last = st[min(int(res.tile_iterations[t]), st.shape[0] - 1), t]
        rows.append((int(res.grid.ix[t]), int(res.grid.iy[t]), int(res.tile_points[t]),
                     int(res.tile_iterations[t]), T(STATUS_NAMES[int(res.tile_status[t])]),
                     int(np.nan_to_num(last[0])), last[1], last[2], last[3], last[4]))
    sec.add(Table(["Column", "Row", "Fitting points", "Iterations", "Status", "Kept",
                   "ZMin", "ZMax", "ZMean", "σ"], rows, digits=2))
    if res.grid.count > MAX_TILE_ROWS:
        sec.add(Paragraph(T("Showing the {k} fullest of {n} tiles.", k=MAX_TILE_ROWS,
                            n=res.grid.count), "note"))


def _tile_map(res, sec, tr) -> None:
    """Add the tile-status map (converged, iteration cap, too few points, ...)."""
    from .figures import tile_map
    sec.add(tile_map(res.grid, res.tile_status, tr, STATUS_NAMES))


def tile_csv(res, units=None) -> str:
    """One row per tile and step (the paper's Tables 1–2 for every tile).

    Parameters
    ----------
    res : LsqResult
        The filter's result (computed in metres: DEVELOPERS.md, Units).
    units : Units, optional
        The cloud's linear units: tile centres are written in its horizontal unit and
        heights in its vertical unit (so they sit on the cloud), and every length column
        names its unit (``centre_x_ftUS``, ``zmean_m``). None: metres.

    Returns
    -------
    str
        CSV text with the tile's final coefficients (paper's term order; the fit of
        heights in metres on tile coordinates in metres, whatever the data's units:
        ``b*_m`` columns).
    """
    from ..io.units import METRIC
    units = units or METRIC
    hs, vs = units.horizontal.symbol, units.vertical.symbol
    fh = io.StringIO()
    w = csv.writer(fh, lineterminator="\n")
    terms = TERMS[res.params["order"]]
    w.writerow(["tile_col", "tile_row", f"centre_x_{hs}", f"centre_y_{hs}", "status",
                "step", "points", f"zmin_{vs}", f"zmax_{vs}", f"zmean_{vs}", f"std_{vs}"]
               + [f"b{i}_{t}_m" for i, t in enumerate(terms)])
    centres = units.h_from_metres(res.grid.centres)
    for t in range(res.grid.count):
        head = [int(res.grid.ix[t]), int(res.grid.iy[t]), f"{centres[t, 0]:.3f}",
                f"{centres[t, 1]:.3f}", STATUS_NAMES[int(res.tile_status[t])]]
        coef = [f"{c:.6g}" for c in res.coefficients[t]]
        for k in range(int(res.tile_iterations[t]) + 1):
            st = res.tile_stats[k, t]
            heights = units.v_from_metres(np.asarray(st[1:], dtype=np.float64))
            w.writerow(head + [k, int(np.nan_to_num(st[0]))]
                       + [f"{v:.3f}" if np.isfinite(v) else "" for v in heights] + coef)
    return fh.getvalue()

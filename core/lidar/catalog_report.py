"""Report of a catalog run: summary, tile map by status and time, per tile and per worker.

Content only (:class:`~..reporting.Report`); the algorithm renders it. The tile map is
an inline SVG (figure id ``tile-status``) drawn from the header bounds: finished tiles
shaded by processing time, tiles of an earlier run grey, failed tiles red.
"""
from __future__ import annotations

from html import escape
from typing import Callable, List, Optional

from ..reporting import Figure, KeyValues, Paragraph, Report, T, Table, svg, translator

_DONE_LIGHT = (199, 233, 192)   # fast
_DONE_DARK = (0, 109, 44)       # slow
_SKIPPED = "#bdbdbd"
_FAILED = "#d7301f"


def _shade(f: float) -> str:
    f = min(max(f, 0.0), 1.0)
    rgb = [round(a + (b - a) * f) for a, b in zip(_DONE_LIGHT, _DONE_DARK)]
    return "#{:02x}{:02x}{:02x}".format(*rgb)


def _legend(tr, y: int) -> str:
    items = ((_shade(0.0), tr("fast")), (_shade(1.0), tr("slow")),
             (_SKIPPED, tr("finished earlier")), (_FAILED, tr("failed")))
    out = []
    for k, (colour, label) in enumerate(items):
        x = 10 + 130 * k
        out.append(f'<rect x="{x}" y="{y}" width="14" height="14" fill="{colour}"/>'
                   + svg.text(x + 20, y + 12, label, size=12))
    return "".join(out)


def tile_status_svg(result, tiles_bounds, *, width: int = 520,
                    tr: Optional[Callable[[str], str]] = None) -> str:
    """SVG map of the tiles coloured by status and processing time."""
    tr = tr or (lambda s: s)
    b = tiles_bounds
    x0, y0 = float(b[:, 0].min()), float(b[:, 1].min())
    span = max(float(b[:, 2].max()) - x0, float(b[:, 3].max()) - y0, 1e-9)
    scale = (width - 20) / span
    height = int((float(b[:, 3].max()) - y0) * scale) + 20
    times = [c["seconds"] for c in result.chunks if c["key"] not in result.skipped]
    tmin, tmax = (min(times), max(times)) if times else (0.0, 1.0)
    stats = {c["key"]: c for c in result.chunks}
    parts = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" '
             f'height="{height + 30}" role="img">']
    for key, bb in zip(result.settings["keys"], b):
        if key in result.failed:
            colour = _FAILED
        elif key in result.skipped or key not in stats:
            colour = _SKIPPED
        else:
            colour = _shade((stats[key]["seconds"] - tmin) / max(tmax - tmin, 1e-9))
        px = 10 + (bb[0] - x0) * scale
        py = 10 + height - 20 - (bb[3] - y0) * scale
        w, h = (bb[2] - bb[0]) * scale, (bb[3] - bb[1]) * scale
        tip = f"{key}: {stats[key]['seconds']:.1f} s" if key in stats else key
        parts.append(f'<rect x="{px:.1f}" y="{py:.1f}" width="{w:.1f}" height="{h:.1f}" '
                     f'fill="{colour}" stroke="#333"><title dir="ltr">{escape(tip)}</title></rect>'
                     f'<text x="{px + w / 2:.1f}" y="{py + h / 2:.1f}" font-size="11" '
                     f'text-anchor="middle" direction="ltr" dir="ltr">{escape(key)}</text>')
    parts.append(_legend(tr, height + 8))
    parts.append("</svg>")
    return "".join(parts)


def _tile_warning(c: dict, buffer: float) -> Optional[T]:
    """Why a finished tile's DTM lacks ground (None: it has its own, enough)."""
    from ._catalog_checks import class_listing
    key, reach = c["key"], c.get("ground_reach")
    if reach is None:                   # a marker written before these counts existed
        return None
    classes = class_listing(c.get("classes") or {})
    why = c.get("filter_error")
    if why:
        return T("Tile {tile}: the ground filter cannot classify its {n} points (tile and "
                 "buffer): {reason} Its points are left unclassified (class 1, noise kept); "
                 "its DTM is nodata.", tile=key, n=c.get("points", 0) + c.get(
                     "buffer_points", 0), reason=T(why["template"], **why["fields"]))
    if reach == 0:
        return T("Tile {tile}: no ground point in the tile nor within its {buffer} m buffer "
                 "(its points by class: {classes}); its DTM is nodata.", tile=key,
                 buffer=f"{buffer:g}", classes=classes)
    why = c.get("dtm_error")
    if why:
        return T("Tile {tile}: the DTM method cannot interpolate the {n} ground points in the "
                 "tile and its buffer: {reason} Its DTM is nodata.", tile=key, n=reach,
                 reason=T(why["template"], **why["fields"]))
    if c.get("dtm_cells") == 0:
        return T("Tile {tile}: only {n} ground point(s) in the tile and its buffer, at "
                 "fewer than 3 distinct positions; its DTM is nodata.", tile=key, n=reach)
    if c.get("neighbours_used"):
        return T("Tile {tile}: only {n} ground points in the tile and its buffer, fewer "
                 "than the DTM method's neighbours; its cells are interpolated from those "
                 "{n} points.", tile=key, n=reach)
    if c.get("ground") == 0:
        return T("Tile {tile}: no ground point of its own (its points by class: {classes}); "
                 "its DTM has values only within reach of the ground in its buffer "
                 "({cells} cells), elsewhere nodata.", tile=key, classes=classes,
                 cells=c.get("dtm_cells", 0))
    return None


def _status(c: dict, skipped) -> T:
    """Status of a chunk in the tile table (a DTM without a value cell said so)."""
    if c["key"] in skipped:
        return T("finished earlier")
    return T("done, DTM nodata") if c.get("dtm_cells") == 0 else T("done")


def catalog_warnings(result) -> List[T]:
    """Warnings of a run: tiles without points (left out) and tiles without ground.

    Tiles of water, sea, vegetation or noise only have no ground of their own: their
    DTM cells are nodata where no ground is within reach (as the merged cloud's DTM),
    and the warning says why (the classes of their points).
    """
    s = result.settings
    out = [T("{tile} has no points (a header only); it is left out of the catalog.",
             tile=name) for name in s.get("empty_tiles", [])]
    for c in result.chunks:
        if c.get("status") in ("done", "skipped") or c["key"] in result.skipped:
            w = _tile_warning(c, s["buffer"])
            if w is not None:
                out.append(w)
    return out


def catalog_report(result, tiles_bounds, *, lang: str = "en") -> Report:
    """Build the :class:`Report` of a :class:`~.catalog.CatalogResult`."""
    s = result.settings
    rep = Report(T("Tile catalog processing"), citation=T("References: {ref}", ref=(
        "Roussel et al. (2020) lidR: an R package for analysis of Airborne Laser Scanning "
        "data. Remote Sens. Environ. 251:112061; Rocklin (2015) Dask. Proc. 14th Python in "
        "Science Conf.")))
    n_done = len(result.chunks) - len(result.skipped)
    rep.summary.append(Paragraph(T("{done} tiles processed, {skipped} finished earlier, "
                                   "{failed} failed.", done=n_done,
                                   skipped=len(result.skipped), failed=len(result.failed)),
                                 "fail" if result.failed else "ok"))
    warnings = catalog_warnings(result)
    if warnings:
        rep.summary.append(Paragraph(T("{n} warning(s): tiles without points or without "
                                       "ground (see Warnings).", n=len(warnings)), "note"))
    rep.section(T("Run")).add(KeyValues([
        (T("Ground filter"), s["ground_filter"]), (T("DTM method"), s["dtm_method"]),
        (T("Cell size"), s["cell_size"], "m"), (T("Buffer"), s["buffer"], "m"),
        (T("Maximum distance to data"), s.get("gap_distance"), "m"),
        (T("Chunk size (0 = the tiles)"), s.get("chunk_size", 0.0), "m"),
        (T("Tiles"), s["tiles"]), (T("Points in the catalog"), s["points_total"]),
        (T("Workers"), result.workers), (T("Dask scheduler"), result.scheduler),
        (T("Wall time"), result.seconds, "s"),
        (T("Points per second (overall)"), result.points_per_second)], digits=1))
    rep.section(T("Tiles")).add(Figure(
        tile_status_svg(result, tiles_bounds, tr=translator(lang)),
        T("Tiles coloured by status and processing time"), figure_id="tile-status")).add(
        Table([T("Tile"), T("Status"), T("Points"), T("Ground"), T("Seconds"), T("Worker")],
              [[c["key"], _status(c, result.skipped), c["points"], c["ground"], c["seconds"],
                c["worker"]] for c in result.chunks]
              + [[k, T("failed"), "", "", "", msg] for k, msg in result.failed.items()],
              digits=1))
    if warnings:
        sec = rep.section(T("Warnings"))
        for w in warnings:
            sec.add(Paragraph(w, "note"))
    rep.section(T("Workers")).add(Table(
        [T("Worker"), T("Tiles"), T("Points"), T("Busy seconds"), T("Points per second")],
        [[w, v["chunks"], v["points"], v["seconds"], v["points_per_second"]]
         for w, v in sorted(result.per_worker().items())], digits=0))
    return rep

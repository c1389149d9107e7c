"""Self-contained HTML reports with inline SVG plots (no Qt, no external assets).

Every report is one HTML file that opens in QGIS's Results Viewer or any browser
and can be attached to a delivery. Right-to-left languages (Arabic, Persian) are
supported through ``lang``: the page direction follows the language, numbers and
tables stay left-to-right.
"""
from __future__ import annotations

import html
import math
from typing import Iterable, Mapping, Optional, Sequence

import numpy as np

RTL_LANGS = {"ar", "fa", "he", "ur", "ps", "ckb"}

_CSS = """
body{font-family:"Noto Sans","Segoe UI",Tahoma,Arial,sans-serif;margin:1.5em;color:#222;
max-width:1100px}
h1{font-size:1.4em;border-bottom:2px solid #1f5f8b;padding-bottom:.2em}
h2{font-size:1.15em;margin-top:1.4em;color:#1f5f8b}
table{border-collapse:collapse;margin:.5em 0;direction:ltr}
th,td{border:1px solid #bbb;padding:.2em .6em;text-align:right;font-variant-numeric:tabular-nums}
th{background:#eef3f7;text-align:center}
td.text{text-align:left}
.ok{color:#1a7f37;font-weight:bold}.fail{color:#b42318;font-weight:bold}
.note{color:#555;font-size:.9em}
svg{background:#fff;border:1px solid #ddd;margin:.3em 0}
"""


def esc(value) -> str:
    """HTML-escape ``value`` (converted to str)."""
    return html.escape(str(value), quote=True)


def fmt(value, digits: Optional[int] = 3) -> str:
    """Format a number for a report: ``digits`` fixed decimals (``None``: six significant
    digits, e.g. 0.21455 or 3648), integers plain, NaN as '–'.
    """
    if value is None:
        return "–"
    if isinstance(value, (bool, np.bool_)):
        return "yes" if value else "no"
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    try:
        v = float(value)
    except (TypeError, ValueError):
        return esc(value)
    if not math.isfinite(v):
        return "–"
    if digits is None:
        return f"{v:.6g}"
    return f"{v:.{digits}f}"


def html_page(title: str, body_html: str, *, lang: str = "en") -> str:
    """A complete HTML document; ``dir=rtl`` for Arabic, Persian and other RTL languages."""
    direction = "rtl" if (lang or "en")[:2] in RTL_LANGS else "ltr"
    return (f'<!DOCTYPE html>\n<html lang="{esc(lang)}" dir="{direction}">\n<head>\n'
            f'<meta charset="utf-8">\n<title>{esc(title)}</title>\n<style>{_CSS}</style>\n'
            f"</head>\n<body>\n<h1>{esc(title)}</h1>\n{body_html}\n</body>\n</html>\n")


def html_table(headers: Sequence[str], rows: Iterable[Sequence], *,
               digits: Optional[int] = 3,
               caption: Optional[str] = None) -> str:
    """An HTML table; numbers are formatted with :func:`fmt`, strings escaped."""
    out = ["<table>"]
    if caption:
        out.append(f"<caption>{esc(caption)}</caption>")
    out.append("<tr>" + "".join(f"<th>{esc(h)}</th>" for h in headers) + "</tr>")
    for row in rows:
        cells = []
        for v in row:
            if isinstance(v, str):
                cells.append(f'<td class="text">{esc(v)}</td>')
            else:
                cells.append(f"<td>{fmt(v, digits)}</td>")
        out.append("<tr>" + "".join(cells) + "</tr>")
    out.append("</table>")
    return "\n".join(out)


def html_params(params: Mapping[str, object], *, title: str = "Parameters",
                digits: int = 4) -> str:
    """A two-column table of parameter names and values under an ``<h2>`` title."""
    rows = [(str(k), v if not isinstance(v, (list, tuple)) else ", ".join(map(str, v)))
            for k, v in params.items()]
    return f"<h2>{esc(title)}</h2>\n" + html_table(("parameter", "value"), rows,
                                                   digits=digits)


# ----------------------------------------------------------------------- SVG plots
class _Axes:
    """Linear mapping from data to SVG pixel coordinates with a margin."""

    def __init__(self, xlim, ylim, width, height, margin=(55, 15, 20, 40), equal=False):
        self.w, self.h = width, height
        self.ml, self.mr, self.mt, self.mb = margin
        x0, x1 = _pad(*xlim)
        y0, y1 = _pad(*ylim)
        if equal:
            sx = (width - self.ml - self.mr) / (x1 - x0)
            sy = (height - self.mt - self.mb) / (y1 - y0)
            s = min(sx, sy)
            cx, cy = (x0 + x1) / 2, (y0 + y1) / 2
            hx = (width - self.ml - self.mr) / s / 2
            hy = (height - self.mt - self.mb) / s / 2
            x0, x1, y0, y1 = cx - hx, cx + hx, cy - hy, cy + hy
        self.x0, self.x1, self.y0, self.y1 = x0, x1, y0, y1

    def px(self, x):
        return self.ml + (np.asarray(x, float) - self.x0) / (self.x1 - self.x0) * (
            self.w - self.ml - self.mr)

    def py(self, y):
        return self.h - self.mb - (np.asarray(y, float) - self.y0) / (self.y1 - self.y0) * (
            self.h - self.mt - self.mb)

    def frame(self, xlabel: str, ylabel: str) -> str:
        parts = [f'<rect x="{self.ml}" y="{self.mt}" width="{self.w - self.ml - self.mr}" '
                 f'height="{self.h - self.mt - self.mb}" fill="none" stroke="#888"/>']
        for t in _ticks(self.x0, self.x1):
            x = float(self.px(t))
            parts.append(f'<line x1="{x:.1f}" y1="{self.h - self.mb}" x2="{x:.1f}" '
                         f'y2="{self.h - self.mb + 4}" stroke="#888"/>'
                         f'<text x="{x:.1f}" y="{self.h - self.mb + 15}" font-size="10" '
                         f'text-anchor="middle">{_tick_label(t)}</text>')
        for t in _ticks(self.y0, self.y1):
            y = float(self.py(t))
            parts.append(f'<line x1="{self.ml - 4}" y1="{y:.1f}" x2="{self.ml}" y2="{y:.1f}" '
                         f'stroke="#888"/><text x="{self.ml - 6}" y="{y + 3:.1f}" '
                         f'font-size="10" text-anchor="end">{_tick_label(t)}</text>')
        parts.append(f'<text x="{(self.ml + self.w - self.mr) / 2:.0f}" y="{self.h - 5}" '
                     f'font-size="11" text-anchor="middle">{esc(xlabel)}</text>')
        parts.append(f'<text x="12" y="{(self.mt + self.h - self.mb) / 2:.0f}" font-size="11" '
                     f'text-anchor="middle" transform="rotate(-90 12 '
                     f'{(self.mt + self.h - self.mb) / 2:.0f})">{esc(ylabel)}</text>')
        return "\n".join(parts)


def _pad(lo, hi):
    lo, hi = float(lo), float(hi)
    if not (math.isfinite(lo) and math.isfinite(hi)):
        return 0.0, 1.0
    if hi <= lo:
        d = abs(lo) * 0.05 or 1.0
        return lo - d, hi + d
    d = (hi - lo) * 0.05
    return lo - d, hi + d


def _ticks(lo, hi, n=5):
    span = hi - lo
    raw = span / n
    mag = 10 ** math.floor(math.log10(raw))
    step = min((m * mag for m in (1, 2, 2.5, 5, 10) if m * mag >= raw), default=mag * 10)
    start = math.ceil(lo / step) * step
    return [start + i * step for i in range(int((hi - start) / step) + 1)]


def _tick_label(t):
    return f"{t:.6g}"


def _svg(width, height, body, title):
    return (f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
            f'viewBox="0 0 {width} {height}" direction="ltr" role="img">'
            f"<title>{esc(title)}</title>\n{body}\n</svg>")


def svg_scatter(x, y, *, xlabel: str = "x", ylabel: str = "y", title: str = "",
                one_to_one: bool = False, width: int = 460, height: int = 400,
                max_points: int = 5000, labels: Optional[Sequence[str]] = None) -> str:
    """Scatter plot as inline SVG; ``one_to_one`` draws the y = x line (observed vs
    predicted). At most ``max_points`` points are drawn (evenly subsampled).
    """
    x = np.asarray(x, float)
    y = np.asarray(y, float)
    ok = np.isfinite(x) & np.isfinite(y)
    x, y = x[ok], y[ok]
    if x.size == 0:
        return _svg(width, height, '<text x="20" y="30">no data</text>', title)
    idx = np.linspace(0, x.size - 1, min(x.size, max_points)).astype(int)
    lo = min(x.min(), y.min()) if one_to_one else None
    hi = max(x.max(), y.max()) if one_to_one else None
    ax = _Axes((lo, hi) if one_to_one else (x.min(), x.max()),
               (lo, hi) if one_to_one else (y.min(), y.max()), width, height)
    parts = [ax.frame(xlabel, ylabel)]
    if one_to_one:
        a, b = ax.x0, ax.x1
        parts.append(f'<line x1="{float(ax.px(a)):.1f}" y1="{float(ax.py(a)):.1f}" '
                     f'x2="{float(ax.px(b)):.1f}" y2="{float(ax.py(b)):.1f}" '
                     'stroke="#b42318" stroke-dasharray="4 3"/>')
    px, py = ax.px(x[idx]), ax.py(y[idx])
    parts.append("".join(f'<circle cx="{a:.1f}" cy="{b:.1f}" r="2.5" fill="#1f5f8b" '
                         'fill-opacity="0.7"/>' for a, b in zip(px, py)))
    if labels is not None and len(labels) == ok.size:
        lab = np.asarray(labels, dtype=object)[ok][idx]
        parts.append("".join(f'<text x="{a + 4:.1f}" y="{b - 3:.1f}" font-size="9">'
                             f"{esc(t)}</text>" for a, b, t in zip(px, py, lab)))
    if title:
        parts.append(f'<text x="{width / 2:.0f}" y="12" font-size="12" '
                     f'text-anchor="middle">{esc(title)}</text>')
    return _svg(width, height, "\n".join(parts), title)


def svg_histogram(values, *, bins: int = 20, xlabel: str = "value", title: str = "",
                  width: int = 460, height: int = 300) -> str:
    """Histogram of finite ``values`` as inline SVG, with a line at zero if in range."""
    v = np.asarray(values, float)
    v = v[np.isfinite(v)]
    if v.size == 0:
        return _svg(width, height, '<text x="20" y="30">no data</text>', title)
    counts, edges = np.histogram(v, bins=bins)
    ax = _Axes((edges[0], edges[-1]), (0, counts.max()), width, height)
    parts = [ax.frame(xlabel, "count")]
    y0 = float(ax.py(0))
    for c, a, b in zip(counts, edges[:-1], edges[1:]):
        xa, xb, yc = float(ax.px(a)), float(ax.px(b)), float(ax.py(c))
        parts.append(f'<rect x="{xa:.1f}" y="{yc:.1f}" width="{max(xb - xa - 1, 0.5):.1f}" '
                     f'height="{y0 - yc:.1f}" fill="#8fbf5a" stroke="#5b8a2e"/>')
    if edges[0] < 0 < edges[-1]:
        x = float(ax.px(0))
        parts.append(f'<line x1="{x:.1f}" y1="{ax.mt}" x2="{x:.1f}" y2="{y0:.1f}" '
                     'stroke="#b42318" stroke-dasharray="4 3"/>')
    if title:
        parts.append(f'<text x="{width / 2:.0f}" y="12" font-size="12" '
                     f'text-anchor="middle">{esc(title)}</text>')
    return _svg(width, height, "\n".join(parts), title)


def svg_vectors(x, y, dx, dy, *, scale: Optional[float] = None, labels=None,
                extent: Optional[Sequence[float]] = None, title: str = "",
                xlabel: str = "x", ylabel: str = "y", unit: str = "m",
                width: int = 560, height: int = 480, invert_y: bool = False) -> str:
    """Residual-vector (quiver) plot: an arrow ``(dx, dy)·scale`` at each ``(x, y)``.

    Parameters
    ----------
    x, y : array_like
        Arrow origins (e.g. GCP positions on the image footprint).
    dx, dy : array_like
        Vector components (e.g. residuals v_x, v_y in map units).
    scale : float, optional
        Exaggeration factor; default makes the longest arrow ~12 % of the extent.
        The scale and a reference arrow length are printed in the plot.
    extent : (xmin, ymin, xmax, ymax), optional
        Frame to draw (e.g. the image footprint), drawn as a grey rectangle.
    invert_y : bool
        True when ``y`` grows downwards (image rows).
    """
    x, y, dx, dy = (np.asarray(a, float) for a in (x, y, dx, dy))
    if extent is None:
        extent = (x.min(), y.min(), x.max(), y.max())
    xmin, ymin, xmax, ymax = (float(v) for v in extent)
    span = max(xmax - xmin, ymax - ymin) or 1.0
    length = np.hypot(dx, dy)
    lmax = float(length.max()) if length.size else 0.0
    if scale is None:
        scale = 0.12 * span / lmax if lmax > 0 else 1.0
    sign = -1.0 if invert_y else 1.0
    ax = _Axes((xmin, xmax), (ymin, ymax) if not invert_y else (-ymax, -ymin),
               width, height, equal=True)

    def yy(v):
        return ax.py(sign * np.asarray(v, float))

    parts = [ax.frame(xlabel, ylabel)]
    fx0, fx1 = float(ax.px(xmin)), float(ax.px(xmax))
    fy0, fy1 = sorted((float(yy(ymin)), float(yy(ymax))))
    parts.append(f'<rect x="{fx0:.1f}" y="{fy0:.1f}" width="{fx1 - fx0:.1f}" '
                 f'height="{fy1 - fy0:.1f}" fill="#f4f4f4" stroke="#aaa"/>')
    parts.append('<defs><marker id="ah" markerWidth="8" markerHeight="6" refX="7" refY="3" '
                 'orient="auto"><path d="M0,0 L8,3 L0,6 z" fill="#b42318"/></marker></defs>')
    x0, y0 = ax.px(x), yy(y)
    x1, y1 = ax.px(x + dx * scale), yy(y + dy * scale)
    for i in range(x.size):
        parts.append(f'<circle cx="{x0[i]:.1f}" cy="{y0[i]:.1f}" r="2.5" fill="#1f5f8b"/>'
                     f'<line x1="{x0[i]:.1f}" y1="{y0[i]:.1f}" x2="{x1[i]:.1f}" '
                     f'y2="{y1[i]:.1f}" stroke="#b42318" stroke-width="1.5" '
                     'marker-end="url(#ah)"/>')
        if labels is not None:
            parts.append(f'<text x="{x0[i] + 4:.1f}" y="{y0[i] + 11:.1f}" font-size="9">'
                         f"{esc(labels[i])}</text>")
    ref = _nice(lmax) if lmax > 0 else 1.0
    ref_px = float(ax.px(xmin + ref * scale) - ax.px(xmin))
    parts.append(f'<line x1="{ax.ml + 10}" y1="{ax.mt + 12}" x2="{ax.ml + 10 + ref_px:.1f}" '
                 f'y2="{ax.mt + 12}" stroke="#b42318" stroke-width="1.5" '
                 'marker-end="url(#ah)"/>'
                 f'<text x="{ax.ml + 14 + ref_px:.1f}" y="{ax.mt + 15}" font-size="10">'
                 f"{_tick_label(ref)} {esc(unit)} (×{scale:.4g})</text>")
    if title:
        parts.append(f'<text x="{width / 2:.0f}" y="12" font-size="12" '
                     f'text-anchor="middle">{esc(title)}</text>')
    return _svg(width, height, "\n".join(parts), title)


def _nice(v: float) -> float:
    mag = 10 ** math.floor(math.log10(v))
    for m in (1, 2, 5, 10):
        if m * mag >= v * 0.5:
            return m * mag
    return 10 * mag

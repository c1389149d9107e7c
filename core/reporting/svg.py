"""Small SVG building blocks for report figures (no plotting dependency).

Every figure of a report is an inline SVG string made from these helpers: a raster
image (PNG data URI), point symbols, axes, a colour legend, a scale bar and a north
arrow. Text passed in must already be translated (the callers hold a translator);
numbers and units are written left to right inside ``direction="ltr"`` text.

Examples
--------
>>> svg = figure(200, 100, [scale_bar(10, 90, 50.0, 1.0, unit="m")])
>>> svg.startswith("<svg")
True
"""
from __future__ import annotations

import base64
import math
import re
import struct
import zlib
from typing import Callable, Iterable, Optional, Sequence, Tuple
from xml.sax.saxutils import escape

import numpy as np

#: Diverging colours (blue - white - red), ColorBrewer RdBu reversed, 7 classes.
DIVERGING = ("#2166ac", "#67a9cf", "#d1e5f0", "#f7f7f7", "#fddbc7", "#ef8a62", "#b2182b")
NODATA_COLOUR = (255, 0, 255)
FONT = 'font-family="sans-serif" font-size="11"'


def esc(text) -> str:
    """Escape text for SVG."""
    return escape(str(text), {'"': "&quot;"})


#: estimated right edge of a legend, written by :func:`legend`, read by :func:`figure`
_LEGEND_RIGHT = re.compile(r'<g class="legend" data-right="(\d+)">')


def text_width(value, size: int = 11, bold: bool = False) -> float:
    """Rough rendered width of ``value`` in pixels (sans-serif, Latin or Arabic script)."""
    return len(str(value)) * size * (0.66 if bold else 0.6)


def figure(width: int, height: int, parts: Iterable[str], *, title: str = "") -> str:
    """Return a complete ``<svg>`` element of ``width`` × ``height`` pixels.

    The width grows to hold every legend (their labels are translated, so their length
    depends on the language).
    """
    parts = list(parts)
    rights = [int(m) for p in parts for m in _LEGEND_RIGHT.findall(p)]
    width = max([int(width)] + [r + 8 for r in rights])
    head = (f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
            f'viewBox="0 0 {width} {height}" role="img">')
    label = f"<title>{esc(title)}</title>" if title else ""
    return head + label + "".join(parts) + "</svg>"


#: Hebrew, Arabic, Syriac, Thaana, N'Ko … and the Arabic presentation forms
_RTL_CHARS = re.compile("[\u0590-\u08ff\ufb1d-\ufdff\ufe70-\ufefc]")
_FLIP = {"start": "end", "end": "start", "middle": "middle"}


def text(x: float, y: float, value, *, anchor: str = "start", size: int = 11,
         ltr: bool = False, bold: bool = False) -> str:
    """Return a ``<text>`` element; ``ltr`` for numbers, units and ids.

    The direction is explicit, never inherited from the page: right-to-left text
    (Arabic, Persian) gets ``direction="rtl"`` with the anchor mirrored, so that
    ``anchor="start"`` always means "extends to the right of ``x``" and a layout
    (legend beside a north arrow) is the same on an RTL and an LTR page.
    """
    rtl = not ltr and bool(_RTL_CHARS.search(str(value)))
    if rtl:
        anchor = _FLIP.get(anchor, anchor)
    extra = f' direction="{"rtl" if rtl else "ltr"}" unicode-bidi="embed"'
    weight = ' font-weight="bold"' if bold else ""
    return (f'<text x="{x:.1f}" y="{y:.1f}" text-anchor="{anchor}" font-family="sans-serif" '
            f'font-size="{size}"{weight}{extra}>{esc(value)}</text>')


def png_data_uri(rgb: np.ndarray) -> str:
    """Encode an ``(rows, cols, 3)`` uint8 array as a PNG ``data:`` URI (no dependency)."""
    rgb = np.ascontiguousarray(rgb, dtype=np.uint8)
    rows, cols = rgb.shape[:2]
    raw = np.concatenate([np.zeros((rows, 1), np.uint8), rgb.reshape(rows, cols * 3)], axis=1)

    def chunk(kind: bytes, data: bytes) -> bytes:
        return (struct.pack(">I", len(data)) + kind + data
                + struct.pack(">I", zlib.crc32(kind + data) & 0xFFFFFFFF))

    png = (b"\x89PNG\r\n\x1a\n"
           + chunk(b"IHDR", struct.pack(">IIBBBBB", cols, rows, 8, 2, 0, 0, 0))
           + chunk(b"IDAT", zlib.compress(raw.tobytes(), 6)) + chunk(b"IEND", b""))
    return "data:image/png;base64," + base64.b64encode(png).decode("ascii")


def image(x: float, y: float, width: float, height: float, rgb: np.ndarray) -> str:
    """Return an ``<image>`` showing ``rgb`` (pixelated, not smoothed)."""
    return (f'<image x="{x:.1f}" y="{y:.1f}" width="{width:.1f}" height="{height:.1f}" '
            f'preserveAspectRatio="none" style="image-rendering:pixelated" '
            f'href="{png_data_uri(rgb)}"/>')


def nice_length(max_length: float) -> float:
    """Largest 1-2-5 × 10^k not above ``max_length`` (for scale bars and ticks)."""
    if not max_length > 0:
        return 0.0
    base = 10.0 ** math.floor(math.log10(max_length))
    return max(m * base for m in (1, 2, 5) if m * base <= max_length)


def scale_bar(x: float, y: float, max_px: float, units_per_px: float, *,
              unit: str = "m") -> str:
    """Return a scale bar at ``(x, y)`` no longer than ``max_px`` pixels."""
    length = nice_length(max_px * units_per_px)
    if not length > 0:
        return ""
    px = length / units_per_px
    half = px / 2
    return (f'<g class="scale-bar"><rect x="{x:.1f}" y="{y:.1f}" width="{half:.1f}" '
            f'height="5" fill="#222"/><rect x="{x + half:.1f}" y="{y:.1f}" '
            f'width="{half:.1f}" height="5" fill="#fff" stroke="#222"/>'
            + text(x, y - 3, "0", ltr=True, size=10)
            + text(x + px, y - 3, f"{length:g} {unit}", anchor="end", ltr=True, size=10)
            + "</g>")


def north_arrow(x: float, y: float) -> str:
    """Return a small north arrow with its tip at ``(x, y)``."""
    return (f'<g class="north"><path d="M{x:.1f},{y:.1f} l6,16 l-6,-5 l-6,5 z" fill="#222"/>'
            + text(x, y + 28, "N", anchor="middle", size=10, ltr=True) + "</g>")


def legend(x: float, y: float, entries: Sequence[Tuple[str, str]], *, title: str = "",
           shape: str = "rect") -> str:
    """Return a legend: ``entries`` are ``(colour, label)``; ``shape`` rect, circle or line."""
    right = max([x + text_width(title, bold=True)] + [x + 15 + text_width(label, 10)
                                                       for _, label in entries])
    parts = [f'<g class="legend" data-right="{math.ceil(right)}">']
    if title:
        parts.append(text(x, y, title, bold=True))
        y += 6
    for i, (colour, label) in enumerate(entries):
        yy = y + 14 * i
        if shape == "line":
            parts.append(f'<line x1="{x:.1f}" y1="{yy + 5:.1f}" x2="{x + 10:.1f}" '
                         f'y2="{yy + 5:.1f}" stroke="{colour}" stroke-width="2"/>')
        elif shape == "circle":
            parts.append(f'<circle cx="{x + 5:.1f}" cy="{yy + 5:.1f}" r="4.5" '
                         f'fill="{colour}" stroke="#333" stroke-width="0.6"/>')
        else:
            parts.append(f'<rect x="{x:.1f}" y="{yy:.1f}" width="10" height="10" '
                         f'fill="{colour}" stroke="#333" stroke-width="0.6"/>')
        parts.append(text(x + 15, yy + 9, label, size=10))
    parts.append("</g>")
    return "".join(parts)


def class_edges(limit: float, n: int = len(DIVERGING)) -> np.ndarray:
    """Symmetric class edges ``-limit … +limit`` for a diverging scale of ``n`` classes."""
    limit = float(limit) if limit > 0 else 1.0
    return np.linspace(-limit, limit, n + 1)


def diverging_colours(values, limit: float) -> list:
    """Colour of each value on the :data:`DIVERGING` scale symmetric about zero."""
    edges = class_edges(limit)
    idx = np.clip(np.searchsorted(edges, np.asarray(values, float), side="right") - 1,
                  0, len(DIVERGING) - 1)
    return [DIVERGING[i] for i in idx]


def diverging_legend_entries(limit: float, unit: str = "m", digits: int = 2) -> list:
    """``(colour, 'a … b unit')`` for each diverging class (outer classes open-ended)."""
    edges = class_edges(limit)
    out = []
    for i, colour in enumerate(DIVERGING):
        lo, hi = edges[i], edges[i + 1]
        if i == 0:
            label = f"< {hi:+.{digits}f} {unit}"
        elif i == len(DIVERGING) - 1:
            label = f"> {lo:+.{digits}f} {unit}"
        else:
            label = f"{lo:+.{digits}f} … {hi:+.{digits}f} {unit}"
        out.append((colour, label))
    return out


def axes(box: Tuple[float, float, float, float], xlim: Tuple[float, float],
         ylim: Tuple[float, float], *, xlabel: str, ylabel: str,
         ticks: int = 5) -> Tuple[str, Callable, Callable]:
    """Draw axes in ``box`` = (left, top, width, height) with ticks and labels.

    Returns the markup and the two data-to-pixel functions ``(px(x), py(y))``.
    """
    left, top, width, height = box
    x0, x1 = _padded(*xlim)
    y0, y1 = _padded(*ylim)

    def px(v):
        return left + (np.asarray(v, float) - x0) / (x1 - x0) * width

    def py(v):
        return top + height - (np.asarray(v, float) - y0) / (y1 - y0) * height

    parts = [f'<rect x="{left}" y="{top}" width="{width}" height="{height}" fill="none" '
             'stroke="#444"/>']
    for v in _ticks(x0, x1, ticks):
        parts.append(f'<line x1="{px(v):.1f}" y1="{top + height}" x2="{px(v):.1f}" '
                     f'y2="{top + height + 4}" stroke="#444"/>')
        parts.append(text(float(px(v)), top + height + 15, f"{v:g}", anchor="middle",
                          ltr=True, size=10))
    for v in _ticks(y0, y1, ticks):
        parts.append(f'<line x1="{left - 4}" y1="{py(v):.1f}" x2="{left}" y2="{py(v):.1f}" '
                     'stroke="#444"/>')
        parts.append(text(left - 6, float(py(v)) + 3, f"{v:g}", anchor="end", ltr=True,
                          size=10))
    parts.append(text(left + width / 2, top + height + 32, xlabel, anchor="middle"))
    parts.append(f'<g transform="translate({left - 42},{top + height / 2}) rotate(-90)">'
                 + text(0, 0, ylabel, anchor="middle") + "</g>")
    return "".join(parts), px, py


def _padded(lo: float, hi: float) -> Tuple[float, float]:
    lo, hi = float(lo), float(hi)
    if not (math.isfinite(lo) and math.isfinite(hi)):
        return 0.0, 1.0
    if hi <= lo:
        return lo - 0.5, hi + 0.5
    pad = 0.05 * (hi - lo)
    return lo - pad, hi + pad


def _ticks(lo: float, hi: float, n: int) -> np.ndarray:
    step = nice_length((hi - lo) / max(n, 1)) or 1.0
    if (hi - lo) / step > 2 * n:
        step *= 2
    first = math.ceil(lo / step) * step
    return np.round(np.arange(first, hi + step * 1e-9, step), 10)


def circles(xs, ys, colours: Sequence[str], *, r: float = 4.5,
            titles: Optional[Sequence[str]] = None) -> str:
    """Return filled circles with an optional tooltip each."""
    parts = []
    for i, (x, y, c) in enumerate(zip(np.asarray(xs, float), np.asarray(ys, float),
                                      colours)):
        tip = f"<title>{esc(titles[i])}</title>" if titles is not None else ""
        parts.append(f'<circle cx="{x:.1f}" cy="{y:.1f}" r="{r}" fill="{c}" stroke="#222" '
                     f'stroke-width="0.7">{tip}</circle>')
    return "".join(parts)


def hex_rgb(colour: str) -> Tuple[int, int, int]:
    """Return the ``(r, g, b)`` of ``#rrggbb``."""
    c = colour.lstrip("#")
    return int(c[0:2], 16), int(c[2:4], 16), int(c[4:6], 16)


def category_image(x: float, y: float, width: float, height: float, codes: np.ndarray,
                   colours: Sequence[str], *, empty: str = "#ffffff") -> str:
    """Return an ``<image>`` of a categorical raster: ``codes[r, c]`` indexes ``colours``.

    Negative codes (no data) take the ``empty`` colour; row 0 is drawn at the top.
    """
    palette = np.array([hex_rgb(c) for c in colours] + [hex_rgb(empty)], np.uint8)
    idx = np.where(np.asarray(codes) < 0, len(colours), codes)
    return image(x, y, width, height, palette[idx])


def polyline(xs, ys, colour: str, *, width: float = 1.8) -> str:
    """Return a polyline through the finite points ``(xs, ys)`` (pixels) with markers."""
    xs, ys = np.asarray(xs, float), np.asarray(ys, float)
    ok = np.isfinite(xs) & np.isfinite(ys)
    pts = " ".join(f"{a:.1f},{b:.1f}" for a, b in zip(xs[ok], ys[ok]))
    dots = "".join(f'<circle cx="{a:.1f}" cy="{b:.1f}" r="2.5" fill="{colour}"/>'
                   for a, b in zip(xs[ok], ys[ok]))
    return (f'<polyline points="{pts}" fill="none" stroke="{colour}" '
            f'stroke-width="{width}"/>' + dots)


def vline(x: float, top: float, bottom: float, *, colour: str = "#777777") -> str:
    """Return a dashed vertical line at ``x`` (e.g. a chosen threshold)."""
    return (f'<line x1="{x:.1f}" y1="{top:.1f}" x2="{x:.1f}" y2="{bottom:.1f}" '
            f'stroke="{colour}" stroke-dasharray="4 3"/>')


# ------------------------------------------------------------ raster maps and bar charts
#: Colour ramps as anchor colours (RGB 0-255), interpolated linearly.
RAMPS = {
    "viridis": [(68, 1, 84), (59, 82, 139), (33, 145, 140), (94, 201, 98), (253, 231, 37)],
    "diverging": [(178, 24, 43), (239, 138, 98), (247, 247, 247), (103, 169, 207),
                  (33, 102, 172)],
    "gaps": [(240, 240, 240), (200, 30, 30)],
}


def _png(rgba: np.ndarray) -> bytes:
    """Encode an (h, w, 4) uint8 array as a PNG file."""
    h, w = rgba.shape[:2]
    raw = b"".join(b"\x00" + rgba[r].tobytes() for r in range(h))

    def chunk(tag: bytes, data: bytes) -> bytes:
        return (struct.pack(">I", len(data)) + tag + data
                + struct.pack(">I", zlib.crc32(tag + data) & 0xFFFFFFFF))

    return (b"\x89PNG\r\n\x1a\n" + chunk(b"IHDR", struct.pack(">IIBBBBB", w, h, 8, 6, 0, 0, 0))
            + chunk(b"IDAT", zlib.compress(raw, 9)) + chunk(b"IEND", b""))


def colourise(values: np.ndarray, vmin: float, vmax: float, ramp: str = "viridis"
              ) -> np.ndarray:
    """Return the RGBA (uint8) of a 2-D array on a colour ramp; NaN is transparent."""
    anchors = np.array(RAMPS[ramp], float)
    span = (vmax - vmin) or 1.0
    t = np.clip((np.nan_to_num(values, nan=vmin) - vmin) / span, 0, 1) * (len(anchors) - 1)
    i = np.minimum(t.astype(int), len(anchors) - 2)
    f = (t - i)[..., None]
    rgb = anchors[i] * (1 - f) + anchors[i + 1] * f
    alpha = np.where(np.isfinite(values), 255, 0)[..., None]
    return np.concatenate([rgb, alpha], axis=-1).astype(np.uint8)


def _fmt(v: float) -> str:
    return f"{v:.3g}"


def svg_raster(values, *, title: str = "", unit: str = "", ramp: str = "viridis",
               vmin: Optional[float] = None, vmax: Optional[float] = None,
               max_pixels: int = 400) -> str:
    """Draw a raster map (row 0 north) as an embedded PNG with a labelled colour bar.

    NaN cells are transparent. Large rasters are decimated to ``max_pixels`` a side.
    """
    a = np.asarray(values, float)
    step = max(1, int(np.ceil(max(a.shape) / max_pixels)))
    a = a[::step, ::step]
    ok = a[np.isfinite(a)]
    lo = float(ok.min()) if vmin is None and ok.size else float(vmin or 0.0)
    hi = float(ok.max()) if vmax is None and ok.size else float(vmax if vmax is not None
                                                                 else 1.0)
    png = base64.b64encode(_png(colourise(a, lo, hi, ramp))).decode("ascii")
    h, w = a.shape
    scale = 360.0 / max(h, w)
    iw, ih = w * scale, h * scale
    bar = colourise(np.linspace(hi, lo, 64)[:, None], lo, hi, ramp)
    bar_png = base64.b64encode(_png(bar)).decode("ascii")
    width, height = iw + 110, ih + 40
    return (f'<svg xmlns="http://www.w3.org/2000/svg" width="{width:.0f}" '
            f'height="{height:.0f}" viewBox="0 0 {width:.0f} {height:.0f}">'
            + text(5, 15, title, size=12) +
            f'<image x="5" y="25" width="{iw:.1f}" height="{ih:.1f}" '
            f'style="image-rendering:pixelated" preserveAspectRatio="none" '
            f'href="data:image/png;base64,{png}"/>'
            f'<image x="{iw + 15:.1f}" y="25" width="14" height="{ih:.1f}" '
            f'preserveAspectRatio="none" href="data:image/png;base64,{bar_png}"/>'
            + text(iw + 33, 33, f"{_fmt(hi)} {unit}", ltr=True)
            + text(iw + 33, ih + 25, f"{_fmt(lo)} {unit}", ltr=True) + "</svg>")


def svg_bars(labels: Sequence, values: Sequence[float], *, xlabel: str = "",
             ylabel: str = "", title: str = "", colour: str = "#1f5f8b") -> str:
    """Draw a bar chart (histograms of classes, returns, binned values)."""
    vals = np.asarray(values, float)
    n = max(len(vals), 1)
    width, height, left, bottom = 560, 260, 60, 40
    bw = (width - left - 10) / n
    top = float(vals.max()) if vals.size and vals.max() > 0 else 1.0
    parts = [f'<svg xmlns="http://www.w3.org/2000/svg" width="{width}" height="{height}" '
             f'viewBox="0 0 {width} {height}">',
             text(left, 14, title, size=12)]
    every = max(1, n // 12)
    for i, (lab, v) in enumerate(zip(labels, vals)):
        h = (height - bottom - 25) * v / top
        x = left + i * bw
        parts.append(f'<rect x="{x:.1f}" y="{height - bottom - h:.1f}" '
                     f'width="{max(bw - 1, 0.5):.1f}" height="{h:.1f}" fill="{colour}">'
                     f'<title>{esc(str(lab))}: {_fmt(v)}</title></rect>')
        if i % every == 0:
            parts.append(text(x + bw / 2, height - bottom + 14, lab, anchor="middle",
                              size=10, ltr=True))
    parts += [text(left, height - bottom + 20 + 12, xlabel),
              text(5, 30, f"{ylabel} (max {_fmt(top)})"), "</svg>"]
    return "".join(parts)


# ---------------------------------------------------------------- GCP residual figures
def data_text(x: float, y: float, value, **kw) -> str:
    """Return :func:`text` marked as data (``dir="ltr"``: numbers, units, ids)."""
    return text(x, y, value, ltr=True, **kw).replace("<text ", '<text dir="ltr" ', 1)


def _equal_box(dx: float, dy: float, width: float = 440.0, max_height: float = 440.0):
    """``(width, height)`` of a plot box with equal scales on both axes."""
    dx, dy = max(dx, 1e-12), max(dy, 1e-12)
    h = width * dy / dx
    return (width, h) if h <= max_height else (max_height * dx / dy, max_height)


def vector_plot(x, y, dx, dy, *, labels: Optional[Sequence[str]] = None, frame=None,
                unit: str = "m", xlabel: str = "X", ylabel: str = "Y") -> str:
    """Residual-vector (quiver) plot with equal axes: an arrow ``(dx, dy)·k`` at each point.

    ``frame`` (m, 2) is an outline drawn in grey (e.g. the image footprint); the
    exaggeration ``k`` makes the longest arrow 12 % of the extent and is printed with a
    reference arrow.
    """
    x, y, dx, dy = (np.asarray(a, float) for a in (x, y, dx, dy))
    pts = np.column_stack([x, y]) if frame is None else np.vstack([np.column_stack([x, y]),
                                                                   frame])
    lo, hi = pts.min(axis=0), pts.max(axis=0)
    span = float(max(hi - lo)) or 1.0
    lmax = float(np.hypot(dx, dy).max()) if dx.size else 0.0
    k = 0.12 * span / lmax if lmax > 0 else 1.0
    bw, bh = _equal_box(*(hi - lo))
    markup, px, py = axes((70, 30, bw, bh), (lo[0], hi[0]), (lo[1], hi[1]), xlabel=xlabel,
                          ylabel=ylabel, ticks=4)
    parts = [markup, '<defs><marker id="gcp-ah" markerWidth="8" markerHeight="6" refX="7" '
             'refY="3" orient="auto"><path d="M0,0 L8,3 L0,6 z" fill="#b42318"/></marker>'
             "</defs>"]
    if frame is not None:
        path = " ".join(f"{px(a):.1f},{py(b):.1f}" for a, b in frame)
        parts.append(f'<polygon points="{path}" fill="#f4f4f4" stroke="#999"/>')
    for i in range(x.size):
        x0, y0 = float(px(x[i])), float(py(y[i]))
        x1, y1 = float(px(x[i] + k * dx[i])), float(py(y[i] + k * dy[i]))
        parts.append(f'<circle cx="{x0:.1f}" cy="{y0:.1f}" r="2.5" fill="#1f5f8b"/>'
                     f'<line x1="{x0:.1f}" y1="{y0:.1f}" x2="{x1:.1f}" y2="{y1:.1f}" '
                     'stroke="#b42318" stroke-width="1.5" marker-end="url(#gcp-ah)"/>')
        if labels is not None:
            parts.append(data_text(x0 + 4, y0 + 11, labels[i], size=9))
    ref = nice_length(lmax) or 1.0
    ref_px = float(px(lo[0] + ref * k) - px(lo[0]))
    parts.append(f'<line x1="80" y1="18" x2="{80 + ref_px:.1f}" y2="18" stroke="#b42318" '
                 'stroke-width="1.5" marker-end="url(#gcp-ah)"/>'
                 + data_text(86 + ref_px, 21, f"{ref:g} {unit} (×{k:.4g})", size=10))
    return figure(int(bw + 100), int(bh + 80), parts)


def bar_chart(labels: Sequence[str], values: Sequence[float], *,
              colours: Optional[Sequence[str]] = None, unit: str = "m",
              limit: Optional[float] = None, ylabel: str = "") -> str:
    """Horizontal bar chart, one labelled bar per value, with an optional dashed limit.

    ``ylabel`` names the measured quantity (shown under the bars with ``unit``).
    """
    v = np.asarray(values, float)
    n = len(labels)
    top = max(float(np.nanmax(v)) if n else 1.0, limit or 0.0) or 1.0
    left, width, row = 170, 330, 24
    height = n * row + 50
    colours = colours or ["#1f5f8b"] * n

    def px(x):
        return left + float(x) / top * width

    parts = [f'<line x1="{left}" y1="10" x2="{left}" y2="{n * row + 14}" stroke="#444"/>']
    for i, (lab, val) in enumerate(zip(labels, v)):
        y = 14 + i * row
        parts.append(f'<rect x="{left}" y="{y:.1f}" width="{px(val) - left:.1f}" '
                     f'height="{row - 8}" fill="{colours[i]}"/>')
        parts.append(text(left - 6, y + row - 12, lab, anchor="end", size=11, ltr=True))
        parts.append(data_text(px(val) + 4, y + row - 12, f"{val:.3g}", size=10))
    if limit:
        parts.append(f'<line x1="{px(limit):.1f}" y1="8" x2="{px(limit):.1f}" '
                     f'y2="{n * row + 16}" stroke="#b42318" stroke-dasharray="5 3"/>')
    parts.append(f'<text x="{left + width / 2:.1f}" y="{n * row + 40}" text-anchor="middle" '
                 f'{FONT}>{esc(ylabel)} <tspan dir="ltr">({esc(unit)})</tspan></text>')
    return figure(left + width + 60, height, parts)

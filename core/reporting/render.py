"""The one HTML renderer of every report (Jinja2, autoescaped, in any language).

Examples
--------
>>> from .content import Report, Table
>>> r = Report("DTM accuracy")
>>> _ = r.section("Statistics").add(Table(["n", "RMSE (m)"], [[12, 0.0234]]))
>>> html = render_html(r, lang="fa")
>>> 'dir="rtl"' in html
True
"""
from __future__ import annotations

import math
import re
from typing import Any, Callable, Optional, Sequence, Tuple

import jinja2
import markupsafe
import numpy as np

from .content import Figure, Formula, KeyValues, Paragraph, Report, T, Table
from .i18n import direction, normalise_lang, translator

CSS = """
body{font-family:"Noto Sans","Noto Naskh Arabic","Vazirmatn","Segoe UI",Tahoma,Arial,
sans-serif;margin:1.5em;color:#222;max-width:1100px}
h1{font-size:1.4em;border-bottom:2px solid #1f5f8b;padding-bottom:.2em}
h2{font-size:1.15em;margin-top:1.4em;color:#1f5f8b}
table{border-collapse:collapse;margin:.5em 0}
th,td{border:1px solid #bbb;padding:.2em .6em;font-variant-numeric:tabular-nums}
td.num{text-align:right}
th{background:#eef3f7;text-align:center}
caption{font-weight:bold;text-align:start;padding:.2em 0}
.ok{color:#1a7f37;font-weight:bold}.fail{color:#b42318;font-weight:bold}
.note{color:#555;font-size:.9em}
.formula{font-family:monospace;unicode-bidi:isolate;direction:ltr;display:inline-block}
figure{margin:.8em 0}figcaption{color:#444;font-size:.92em}
svg{background:#fff;border:1px solid #ddd;max-width:100%;height:auto}
td,th{overflow-wrap:break-word}
td.num,.qty{white-space:nowrap}
table.about{font-size:.9em;color:#444}table.about th{background:#f6f6f6;text-align:start}
"""

_TEMPLATE = """<!DOCTYPE html>
<html lang="{{ lang }}" dir="{{ dir }}">
<head>
<meta charset="utf-8">
<title>{{ title }}</title>
<style>{{ css }}</style>
</head>
<body>
<h1>{{ title }}</h1>
{% if about %}<table class="about" id="report-about">
{% for a in about %}<tr><th>{{ a.label }}</th><td>{{ a.value }}</td></tr>
{% endfor %}</table>
{% endif %}{% for p in summary %}<p class="{{ p.kind }}">{{ p.html }}</p>
{% endfor %}
{% for sec in sections %}<section>
<h2>{{ sec.heading }}</h2>
{% for b in sec.blocks %}{{ b }}
{% endfor %}</section>
{% endfor %}
{% if citation %}<p class="note">{{ citation }}</p>{% endif %}
</body>
</html>
"""

_ENV = jinja2.Environment(autoescape=True, keep_trailing_newline=True,
                          undefined=jinja2.StrictUndefined)
_PAGE = _ENV.from_string(_TEMPLATE)
esc = markupsafe.escape


def fmt_number(value: Any, digits: Optional[int] = 3) -> str:
    """Format a number: ``digits`` decimals (``None``: six significant), NaN as '–'."""
    if value is None:
        return "–"
    if isinstance(value, (bool, np.bool_)):
        return "✓" if value else "✗"
    if isinstance(value, (int, np.integer)):
        return str(int(value))
    v = float(value)
    if not math.isfinite(v):
        return "–"
    return f"{v:.6g}" if digits is None else f"{v:.{digits}f}"


def _is_number(value: Any) -> bool:
    return isinstance(value, (int, float, np.integer, np.floating, bool, np.bool_)) or (
        value is None)


def bdi(text: Any) -> markupsafe.Markup:
    """Bidi-isolate data (numbers, ids, paths, units) inside translated text."""
    return markupsafe.Markup('<bdi dir="ltr">{}</bdi>').format(text)


class _Renderer:
    def __init__(self, tr: Callable[[str], str]):
        self.tr = tr

    def message(self, m) -> markupsafe.Markup:
        """Translate a message; its ``{fields}`` are filled bidi-isolated."""
        if m is None or m == "":
            return markupsafe.Markup("")
        if isinstance(m, T):
            text = esc(self.tr(m.text))
            args = {k: (self.message(v) if isinstance(v, T)
                        else bdi(fmt_number(v, None) if _is_number(v) else v))
                    for k, v in m.args.items()}
            return markupsafe.Markup(str(text).format(**args)) if args else text
        return esc(self.tr(str(m)))

    def cell(self, value, digits) -> markupsafe.Markup:
        if isinstance(value, T):
            return markupsafe.Markup("<td>{}</td>").format(self.message(value))
        if isinstance(value, markupsafe.Markup):
            return markupsafe.Markup("<td>{}</td>").format(value)
        if _is_number(value):
            return markupsafe.Markup('<td class="num">{}</td>').format(
                bdi(fmt_number(value, digits)))
        return markupsafe.Markup("<td>{}</td>").format(bdi(value))

    def quantity(self, value, unit: str, digits) -> markupsafe.Markup:
        """Render a value with its unit as one cell.

        A unit symbol (m, s, m²) stays with its number in ONE left-to-right isolate, so
        an RTL page shows "1.000 m", never "m 1.000"; a unit word with a translation
        ("cells") follows the number in the page's own direction.
        """
        if isinstance(value, T):
            return markupsafe.Markup("<td>{} {}</td>").format(self.message(value),
                                                               bdi(unit))
        shown = fmt_number(value, digits) if _is_number(value) else value
        cls = ' class="num"' if _is_number(value) else ""
        word = self.tr(unit)
        if word != unit and re.search(r"[A-Za-z]{3}", unit):
            return markupsafe.Markup("<td{}>{} {}</td>").format(
                markupsafe.Markup(cls), bdi(shown), esc(word))
        return markupsafe.Markup(
            '<td{}><bdi dir="ltr" class="qty"><span class="v">{}</span> '
            '<span class="u">{}</span></bdi></td>').format(markupsafe.Markup(cls), shown, unit)

    def table(self, b: Table) -> markupsafe.Markup:
        ncol = len(b.headers)
        digits = list(b.digits) if isinstance(b.digits, (list, tuple)) else [b.digits] * max(
            ncol, max((len(r) for r in b.rows), default=0))
        parts = [markupsafe.Markup("<table>")]
        if b.caption:
            parts.append(markupsafe.Markup("<caption>{}</caption>").format(
                self.message(b.caption)))
        parts.append(markupsafe.Markup("<tr>") + markupsafe.Markup("").join(
            markupsafe.Markup("<th>{}</th>").format(self.message(h)) for h in b.headers)
            + markupsafe.Markup("</tr>"))
        for row in b.rows:
            parts.append(markupsafe.Markup("<tr>") + markupsafe.Markup("").join(
                self.cell(v, digits[i] if i < len(digits) else 3) for i, v in enumerate(row))
                + markupsafe.Markup("</tr>"))
        parts.append(markupsafe.Markup("</table>"))
        return markupsafe.Markup("\n").join(parts)

    def keyvalues(self, b: KeyValues) -> markupsafe.Markup:
        rows = []
        for row in b.rows:
            label, value = row[0], row[1]
            unit = row[2] if len(row) > 2 else ""
            shown = self.quantity(value, unit, b.digits) if unit else self.cell(value,
                                                                                b.digits)
            rows.append(markupsafe.Markup("<tr><th>{}</th>{}</tr>").format(
                self.message(label), shown))
        cap = (markupsafe.Markup("<caption>{}</caption>").format(self.message(b.caption))
               if b.caption else "")
        return markupsafe.Markup("<table>{}{}</table>").format(
            cap, markupsafe.Markup("").join(rows))

    def block(self, b) -> markupsafe.Markup:
        if isinstance(b, Paragraph):
            return markupsafe.Markup('<p class="{}">{}</p>').format(b.kind, self.message(b.text))
        if isinstance(b, Formula):
            return markupsafe.Markup('<p><span class="formula" dir="ltr">{}</span></p>').format(
                b.text)
        if isinstance(b, Table):
            return self.table(b)
        if isinstance(b, KeyValues):
            return self.keyvalues(b)
        if isinstance(b, Figure):
            return markupsafe.Markup(
                '<figure{}>{}<figcaption>{}</figcaption></figure>').format(
                markupsafe.Markup(' id="{}"').format(b.figure_id) if b.figure_id else "",
                markupsafe.Markup(b.svg), self.message(b.caption))
        raise TypeError(f"Unknown report block {type(b).__name__}")


def render_html(report: Report, *, lang: str = "en",
                tr: Optional[Callable[[str], str]] = None,
                about: Optional[Sequence[Tuple[str, Any]]] = None) -> str:
    """Render a :class:`~.content.Report` as one self-contained HTML page.

    Parameters
    ----------
    report : Report
        The content, built by the domain code.
    lang : str
        Language of the page (``'en'``, ``'ar'``, ``'fa'``): sets ``lang`` and ``dir``
        and the translator.
    tr : callable, optional
        Translator overriding the JSON dictionaries (e.g. Qt's in the plugin).
    about : sequence of (label, value), optional
        Who and what made the report (:func:`about_rows`: date, plugin version, project,
        operator), shown under the title; labels are message ids, values data.

    Returns
    -------
    str
        The HTML document.
    """
    lang = normalise_lang(lang)
    r = _Renderer(tr or translator(lang))
    sections = [{"heading": r.message(s.heading), "blocks": [r.block(b) for b in s.blocks]}
                for s in report.sections]
    summary = [{"kind": p.kind, "html": r.message(p.text)} for p in report.summary]
    rows = [{"label": r.message(label), "value": bdi(value)}
            for label, value in (about or ()) if value not in (None, "")]
    return _PAGE.render(lang=lang, dir=direction(lang), title=r.message(report.title),
                        css=markupsafe.Markup(CSS), summary=summary, sections=sections,
                        about=rows,
                        citation=r.message(report.citation) if report.citation else "")


def about_rows(*, version: Optional[str] = None, project: Optional[str] = None,
               operator: Optional[str] = None, when=None) -> list:
    """Return the ``about`` rows of :func:`render_html`.

    Date and time (local, with its UTC offset), plugin version, and the optional
    project and operator.

    >>> import datetime as dt
    >>> when = dt.datetime(2026, 11, 25, 21, 5, tzinfo=dt.timezone.utc)
    >>> about_rows(version="0.3.0", operator="S. Surveyor", when=when)
    [('Date', '2026-11-25 21:05 UTC+00:00'), ('Plugin version', '0.3.0'), \
('Operator', 'S. Surveyor')]
    """
    import datetime as dt
    when = when or dt.datetime.now().astimezone()
    offset = when.strftime("%z") or "+0000"
    rows = [("Date", f"{when:%Y-%m-%d %H:%M} UTC{offset[:3]}:{offset[3:]}"),
            ("Plugin version", version), ("Project", project), ("Operator", operator)]
    return [(label, value) for label, value in rows if value not in (None, "")]

"""Report rendering (HTML, SVG figures). Imports no domain sub-package.

Public API: the content model (:class:`Report`, :class:`Section`, :class:`Paragraph`,
:class:`Table`, :class:`KeyValues`, :class:`Figure`, :class:`Formula`, :class:`T`), the
renderer :func:`render_html` and the translator :func:`translator`.
"""
from .content import Figure, Formula, KeyValues, Paragraph, Report, Section, T, Table
from .i18n import direction, translator
from .render import about_rows, render_html

__all__ = ["Figure", "Formula", "KeyValues", "Paragraph", "Report", "Section", "T", "Table",
           "about_rows", "direction", "render_html", "translator"]

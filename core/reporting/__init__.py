"""Report rendering (HTML, SVG figures). Imports no domain sub-package.

Public API: the content model (:class:`Report`, :class:`Section`, :class:`Paragraph`,
:class:`Table`, :class:`KeyValues`, :class:`Figure`, :class:`Formula`, :class:`T`), the
renderer :func:`render_html` and the translator :func:`translator`.

The renderer (Jinja2, numpy) is imported on first use: the plugin reads the interface
language through :mod:`.i18n` when QGIS starts it, and start-up stays light.
"""
from .content import Figure, Formula, KeyValues, Paragraph, Report, Section, T, Table
from .i18n import direction, translator

_RENDER = ("about_rows", "render_html")


def __getattr__(name):
    """``render_html`` and ``about_rows`` from :mod:`.render`, imported when first used."""
    if name in _RENDER:
        from . import render
        return getattr(render, name)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")

__all__ = ["Figure", "Formula", "KeyValues", "Paragraph", "Report", "Section", "T", "Table",
           "about_rows", "direction", "render_html", "translator"]

"""Errors the core raises for bad input.

:class:`InputError` is a :class:`ValueError` whose message names the problem and
the fix; the Processing base class shows it as a plain message (no traceback), while
any other exception is reported with its traceback in the log.

The message is an English template with named fields, like report text
(:class:`~.reporting.content.T`): ``InputError("{path} holds no check points.",
path=p)``. ``str(error)`` is the English text; :meth:`InputError.message` translates
the template into the user's language from the same dictionaries as the reports
(``i18n/strings/*.json``) and fills the fields, bidi-isolated, afterwards.
``make lint`` fails when a template has no Arabic or Persian translation.

Examples
--------
>>> e = InputError("Cell size must be > 0 (m), got {cell}.", cell=-1)
>>> str(e)
'Cell size must be > 0 (m), got -1.'
>>> isinstance(e, ValueError)
True
"""
from __future__ import annotations

import string

#: First-strong isolate / pop directional isolate: a field (path, number, id) keeps
#: its own direction inside right-to-left text.
FSI, PDI = "\u2068", "\u2069"


class _Formatter(string.Formatter):
    """``str.format`` with every field wrapped in ``before``/``after``."""

    def __init__(self, before: str = "", after: str = ""):
        super().__init__()
        self.before, self.after = before, after

    def format_field(self, value, format_spec):  # noqa: D102 - string.Formatter API
        return self.before + super().format_field(value, format_spec) + self.after


def _field_text(value, lang: str):
    """Return a field in ``lang``: nested errors and ``T`` sentences translated, data as is.

    A field may be an :class:`InputError` (its own message), a list or tuple of them
    (joined by ``'; '``) or a :class:`~.reporting.content.T` (a translatable sentence
    around data, e.g. ``T("The point cloud {path}", path=p)``); anything else is data
    (paths, numbers, unit symbols) and is shown as given.
    """
    if isinstance(value, InputError):
        return value.message(lang)
    if isinstance(value, (list, tuple)) and value and all(
            isinstance(v, InputError) or _is_t(v) for v in value):
        return "; ".join(_field_text(v, lang) for v in value)
    if _is_t(value):
        from .reporting.i18n import normalise_lang, translator
        lang = normalise_lang(lang)
        text = translator(lang)(value.text) if lang != "en" else value.text
        args = {k: _field_text(v, lang) for k, v in value.args.items()}
        if not args:
            return text
        fmt = _Formatter() if lang == "en" else _Formatter(FSI, PDI)
        try:
            return fmt.vformat(text, (), args)
        except (KeyError, IndexError, ValueError):  # a broken translation: English
            return _Formatter().vformat(value.text, (), args)
    return value


def message_text(message, lang: str) -> str:
    """Return a :class:`~.reporting.content.T` sentence (or plain text) in ``lang``.

    Warnings the core returns as ``T`` (e.g. a catalog run's) are shown in the log in
    the interface language, fields bidi-isolated as in :meth:`InputError.message`.

    >>> from geomatics_toolbox.core.reporting.content import T
    >>> message_text(T("Tile {tile} failed.", tile="t1"), "en")
    'Tile t1 failed.'
    """
    return str(_field_text(message, lang))


def _is_t(value) -> bool:
    """Return True for a :class:`~.reporting.content.T` (without importing reporting)."""
    cls = type(value)
    return cls.__name__ == "T" and cls.__module__.endswith("reporting.content")


def _rebuild(cls, template, fields):
    return cls(template, **fields)


class InputError(ValueError):
    """Bad input or parameters: the message says what is wrong and how to fix it.

    Parameters
    ----------
    template : str
        English message; with ``fields``, a :meth:`str.format` template.
    **fields
        Values of the template's fields (numbers, paths, ids: data, not translated).
    """

    def __init__(self, template: str = "", **fields):
        self.template = str(template)
        self.fields = fields
        super().__init__(self._fill(self.template, _Formatter(),
                                    {k: _field_text(v, "en") for k, v in fields.items()}))

    def _fill(self, template: str, formatter: _Formatter, values=None) -> str:
        if not self.fields:
            return template
        return formatter.vformat(template, (), values or self.fields)

    def __reduce__(self):
        """Keep template and fields across pickling (Dask workers raise these)."""
        return _rebuild, (type(self), self.template, self.fields)

    def message(self, lang) -> str:
        """Return the message in ``lang`` (English when the template has no translation).

        Fields are bidi-isolated (FSI … PDI) in a translated message; string fields
        that are themselves translatable sentences (hints) are translated too.
        """
        from .reporting.i18n import has_translation, normalise_lang, translator
        lang = normalise_lang(lang)
        if lang == "en" or not has_translation(self.template, lang):
            return str(self)
        tr = translator(lang)
        values = {k: tr(v) if isinstance(v, str) and " " in v and has_translation(v, lang)
                  else _field_text(v, lang) for k, v in self.fields.items()}
        try:
            return self._fill(tr(self.template), _Formatter(FSI, PDI), values)
        except (KeyError, IndexError, ValueError):  # a broken translation: English
            return str(self)

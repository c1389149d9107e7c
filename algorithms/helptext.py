"""Help panels of the algorithms, built from their parameter definitions.

Every ``shortHelpString`` is :func:`build_help`: a two-sentence summary, a
``qgis_process`` example (the only place where parameter ids appear in running text),
then one line per parameter by its (translated) label with its default, and the id
once in a ``<code>`` span. Labels and defaults come from the definitions themselves,
so the help cannot drift from the dialog. Write the per-parameter notes in plain words:
tests/qgis/test_help_text.py fails when an ALL-CAPS id appears outside ``<code>``.
"""
from __future__ import annotations

import html

from qgis.core import (
    QgsProcessingDestinationParameter,
    QgsProcessingOutputNumber,
    QgsProcessingParameterBoolean,
    QgsProcessingParameterDefinition,
    QgsProcessingParameterEnum,
    QgsProcessingParameterNumber,
)
from qgis.PyQt.QtCore import QT_TRANSLATE_NOOP, QCoreApplication

from .locale import user_locale

#: the help's own words (QT_TRANSLATE_NOOP so that pylupdate5 files them)
_WORDS = (
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Example"),
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Parameters"),
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "Also returned"),
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "default: {}"),
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "optional"),
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "advanced"),
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "yes"),
    QT_TRANSLATE_NOOP("GeomaticsAlgorithm", "no"),
)


def _tr(text: str) -> str:
    return QCoreApplication.translate("GeomaticsAlgorithm", text)  # i18n: noop-list


def _ltr(text: str) -> str:
    return f'<bdi dir="ltr">{html.escape(text)}</bdi>'


def _number(value) -> str:
    try:
        number = float(value)
    except (TypeError, ValueError):
        return str(value)
    return f"{number:g}"


def default_text(param) -> str:
    """The default of ``param`` as a user reads it ('' when there is none to show)."""
    value = param.defaultValue()
    if isinstance(param, QgsProcessingDestinationParameter):
        return ""
    if isinstance(param, QgsProcessingParameterBoolean):
        return _tr("yes") if value else _tr("no")
    if isinstance(param, QgsProcessingParameterEnum):
        options = param.options()
        picked = value if isinstance(value, (list, tuple)) else (
            [] if value in (None, "") else [value])
        names = [options[int(i)] for i in picked
                 if str(i).lstrip("-").isdigit() and 0 <= int(i) < len(options)]
        return html.escape(", ".join(names)) if names else ""
    if value is None or value == "":
        return ""
    if isinstance(param, QgsProcessingParameterNumber):
        return _ltr(_number(value))
    return _ltr(str(value))


def _param_line(param, note: str) -> str:
    bits = [f"<b>{html.escape(param.description())}</b> "
            f'<code dir="ltr">{html.escape(param.name())}</code>']
    default = default_text(param)
    flags = param.flags()
    details = []
    if default:
        details.append(_tr("default: {}").format(default))
    elif flags & QgsProcessingParameterDefinition.FlagOptional:
        details.append(_tr("optional"))
    if flags & QgsProcessingParameterDefinition.FlagAdvanced:
        details.append(_tr("advanced"))
    if details:
        bits.append(" (" + "; ".join(details) + ")")
    if note:
        bits.append(f". {note}")
    return "<li>" + "".join(bits) + "</li>"


def _initialised(alg):
    """``alg``, or a fresh initialised instance if its initAlgorithm has not run yet."""
    if alg.parameterDefinitions():
        return alg
    fresh = alg.createInstance()
    fresh.initAlgorithm()
    return fresh


def build_help(alg, summary: str, example: str, notes: dict | None = None) -> str:
    """HTML help of ``alg``: summary, ``qgis_process`` example, parameters, results.

    ``summary``: two translated sentences; ``example``: the ``NAME=value`` arguments of
    a ``qgis_process run`` line; ``notes``: ``{parameter id: translated note}``.
    """
    notes = notes or {}
    source = _initialised(alg)      # keeps the definitions alive while they are read
    lines = [_param_line(p, notes.get(p.name(), "")) for p in source.parameterDefinitions()
             if not p.flags() & QgsProcessingParameterDefinition.FlagHidden]
    # ids only: the output labels are not all in the translation files yet
    numbers = [f'<code dir="ltr">{html.escape(o.name())}</code>'
               for o in source.outputDefinitions() if isinstance(o, QgsProcessingOutputNumber)]
    parts = [f"<p>{summary}</p>",
             f"<p><b>{_tr('Example')}</b></p>",
             # a wrapping <code> paragraph, not <pre>: a long unbreakable line widens the
             # dialog's help panel and, right-to-left, scrolls the prose out of view
             f'<p dir="ltr"><code>qgis_process run geomatics:{alg.name()} -- '
             f"{html.escape(example)}</code></p>",
             f"<p><b>{_tr('Parameters')}</b></p>",
             "<ul>" + "".join(lines) + "</ul>"]
    if numbers:
        parts.append(f"<p><b>{_tr('Also returned')}</b>: " + "; ".join(numbers) + "</p>")
    return right_to_left("".join(parts)) if _rtl() else "".join(parts)


def _rtl() -> bool:
    """True when the QGIS interface language is written right to left (ar, fa)."""
    try:
        from ..core.reporting.i18n import direction
        return direction(user_locale()) == "rtl"
    except Exception:  # noqa: BLE001 - the direction is cosmetic
        return False


def right_to_left(text: str) -> str:
    """``text`` (help HTML) laid out right to left: ``dir="rtl"`` on the panel and on
    every paragraph and list (Qt's rich text does not inherit a div's direction), except
    the blocks marked ``dir="ltr"`` (the command line example)."""
    import re
    text = re.sub(r"<(p|ul|ol|li)>", r'<\1 dir="rtl">', text)
    return f'<div dir="rtl">{text}</div>'


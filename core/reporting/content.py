"""Report content: what a report says, built by the domain code, rendered once.

Domain modules (``core/lidar``, ``core/terrain``, ...) return a :class:`Report` made
of :class:`Section` objects holding blocks — :class:`Paragraph`, :class:`Table`,
:class:`KeyValues`, :class:`Figure`, :class:`Formula` — and never write HTML.
:func:`~.render.render_html` turns it into one self-contained HTML page in the
requested language.

Translation rule (so that the i18n test can check every report):

* headings, titles, captions, paragraph texts, table headers and key labels are
  English message ids, translated by the renderer (put their Arabic and Persian in
  ``i18n/strings/*.json``); ``{name}`` fields are filled after translation from the
  block's ``args`` and shown bidi-isolated;
* table cells and key values are data (numbers, ids, file names, units) shown as they
  are and bidi-isolated — wrap a cell in :class:`T` to translate it (e.g. a status).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any, Dict, List, Optional, Sequence, Union


@dataclass(frozen=True)
class T:
    """A translatable message id with optional ``{field}`` arguments."""

    text: str
    args: Dict[str, Any] = field(default_factory=dict)

    def __init__(self, text: str, **args: Any):
        object.__setattr__(self, "text", text)
        object.__setattr__(self, "args", dict(args))


Message = Union[str, T]


@dataclass
class Paragraph:
    """A sentence or two; ``kind`` is ``'text'``, ``'note'``, ``'ok'`` or ``'fail'``."""

    text: Message
    kind: str = "text"


@dataclass
class Formula:
    """A formula or code (always left to right, never translated)."""

    text: str


@dataclass
class Table:
    """A table of data; numbers are formatted with ``digits`` decimals.

    ``digits`` may be one int for every numeric cell or a sequence, one per column
    (``None``: six significant digits).
    """

    headers: Sequence[Message]
    rows: Sequence[Sequence[Any]]
    caption: Optional[Message] = None
    digits: Union[Optional[int], Sequence[Optional[int]]] = 3


@dataclass
class KeyValues:
    """Label -> value pairs (parameters, summary figures)."""

    rows: Sequence[Sequence[Any]]          # (label: Message, value[, unit: str])
    caption: Optional[Message] = None
    digits: Optional[int] = 3


@dataclass
class Figure:
    """An inline SVG figure with a caption.

    ``svg`` is markup produced by :mod:`~.svg` (trusted, not escaped); text inside it
    should already be translated (the SVG helpers take a translator).
    """

    svg: str
    caption: Message = ""
    figure_id: str = ""


Block = Union[Paragraph, Formula, Table, KeyValues, Figure]


@dataclass
class Section:
    """A titled part of a report."""

    heading: Message
    blocks: List[Block] = field(default_factory=list)

    def add(self, block: Block) -> Section:
        """Append a block; returns the section for chaining."""
        self.blocks.append(block)
        return self


@dataclass
class Report:
    """A whole report: title, optional summary lines, sections.

    Parameters
    ----------
    title : str or T
        Report title (translated).
    sections : list of Section
        Body of the report, in order.
    summary : list of Paragraph
        Lines shown under the title (verdict, key figures).
    citation : str or T, optional
        Method reference shown at the end.
    """

    title: Message
    sections: List[Section] = field(default_factory=list)
    summary: List[Paragraph] = field(default_factory=list)
    citation: Optional[Message] = None

    def section(self, heading: Message) -> Section:
        """Append and return a new section."""
        sec = Section(heading)
        self.sections.append(sec)
        return sec

    def messages(self) -> List[str]:
        """Every translatable message id in the report (for the i18n tests)."""
        found = [self.title, self.citation, *(p.text for p in self.summary)]
        for sec in self.sections:
            found.append(sec.heading)
            for b in sec.blocks:
                found.extend(_block_messages(b))
        return [m.text if isinstance(m, T) else m for m in found
                if isinstance(m, T) or (isinstance(m, str) and m)]


def _block_messages(b: Block) -> list:
    """Return the translatable messages of one block (cells only when wrapped in T)."""
    if isinstance(b, Paragraph):
        return [b.text]
    if isinstance(b, Figure):
        return [b.caption]
    if isinstance(b, Table):
        cells = [c for row in b.rows for c in row if isinstance(c, T)]
        return [*b.headers, b.caption, *cells]
    if isinstance(b, KeyValues):
        cells = [c for row in b.rows for c in row[1:] if isinstance(c, T)]
        return [b.caption, *(row[0] for row in b.rows), *cells]
    return []

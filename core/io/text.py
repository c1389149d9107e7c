r"""Text files the user writes by hand or in a spreadsheet: one decoding rule.

GCP lists (``.points``, CSV) and check-point files are read with the same rule, in
this order:

1. a UTF-16 byte-order mark → UTF-16 (Excel's "Unicode Text");
2. a code page the file names in a first comment line, ``# encoding: cp1256``
   (``# coding=…`` too; both readers skip ``#`` lines; a UTF-8 byte-order mark wins),
   or the caller's ``encoding``;
3. UTF-8, with or without a byte-order mark (QGIS, Excel's "CSV UTF-8"), strictly;
4. otherwise the Windows ANSI code page that reads the file's *names* as text: the
   machine's own page (cp1256 on Arabic/Persian Windows, cp1252 in Western locales,
   cp932 in Japan …; none on UTF-8 systems such as Linux and macOS) and the two pages
   of this toolbox's users, :data:`CODE_PAGES` (Windows-1256 Arabic/Persian,
   Windows-1252 Western), are each decoded and judged word by word
   (:func:`reading_faults`): a reading whose words mix scripts (``Straك``), start with
   a vowel sign, hold spacing accents (``˜``), or run accented Latin capitals into
   small letters (``äÞØÉ``, an Arabic word read as Latin) is mojibake. The reading with
   the fewest faults, then the most letters outside ASCII, wins; a tie between readings
   that differ — the machine's own page breaks it on Windows — is refused.

A file with NUL bytes (binary), with bytes the named page does not define, or whose
names read equally well in two pages is refused naming the file and the fix (save as
CSV UTF-8, or name the page in a first line): names never come out garbled silently.
Only names and ids can hold non-ASCII text; numbers read the same in every one of
these encodings.

Windows-1256 has no Persian yeh ``ی`` (U+06CC): Persian text saved in it carries the
Arabic yeh ``ي`` (0xED), which is what comes back; UTF-8 keeps ``ی``. Keheh ``ک``
(0x98), peh, tcheh, jeh, gaf and the zero-width non-joiner are in the page.

Examples
--------
>>> decode_text("id,x\nP1,1\n".encode("utf-8-sig"), "a.csv")
('id,x\nP1,1\n', 'utf-8')
>>> decode_text("Ch\u00e2teau-\u00d8st,1\n".encode("cp1252"), "a.csv")
('Château-Øst,1\n', 'cp1252')
>>> decode_text("\u0646\u0642\u0637\u0629,1\n".encode("cp1256"), "a.csv")[1]
'cp1256'
"""
from __future__ import annotations

import codecs
import locale
import os
import re
import unicodedata
from typing import List, Optional, Tuple

from ..errors import InputError

#: Windows code pages tried for a file that is not UTF-8, besides the machine's own:
#: Arabic/Persian, then Western.
CODE_PAGES = ("cp1256", "cp1252")

__all__ = ["CODE_PAGES", "decode_text", "read_text", "reading_faults", "system_code_page"]

#: ``# encoding: cp1256`` / ``# -*- coding: cp1256 -*-`` in one of the first two lines
_DECLARED = re.compile(rb"^[ \t]*#[^\r\n]*?\b(?:en)?coding[ \t]*[:=][ \t]*([-\w.]+)",
                       re.IGNORECASE | re.MULTILINE)
#: runs of ASCII letters and non-ASCII characters (ASCII digits/punctuation split them)
_TOKEN = re.compile(r"[^\x00-\x40\x5b-\x60\x7b-\x7f]+")
_MAX_TOKENS = 20_000
#: letters whose Unicode name does not start with their script
_LATIN_NAMED = ("MICRO SIGN", "FEMININE ORDINAL INDICATOR", "MASCULINE ORDINAL INDICATOR")
_SAME_SCRIPT = {"HIRAGANA": "CJK", "KATAKANA": "CJK", "HALFWIDTH": "CJK"}


def system_code_page() -> Optional[str]:
    """Return the Windows ANSI code page of this machine, or None on UTF/ASCII systems.

    ``locale.getencoding`` (Python ≥ 3.11) ignores UTF-8 mode; older Pythons use the
    preferred encoding. Linux and macOS (UTF-8) give None: nothing says which Windows
    page a file from a colleague's machine is in.
    """
    getter = getattr(locale, "getencoding", None)
    try:
        enc = getter() if getter else locale.getpreferredencoding(False)
        enc = codecs.lookup(enc).name if enc else ""
    except (LookupError, ValueError):
        enc = ""
    return enc if enc and not enc.startswith(("utf", "ascii")) else None


def _not_text(path, offset: int, encoding: str) -> InputError:
    return InputError("{path} is not a text file in UTF-8 or {encoding} (byte {offset} "
                      "cannot be read): save it as text in UTF-8 (in Excel: Save As, CSV "
                      "UTF-8) and run again.", path=os.fspath(path), encoding=encoding,
                      offset=offset)


def _unclear(path, pages, samples) -> InputError:
    return InputError("{path} is not saved in UTF-8 and its names read equally well in "
                      "more than one Windows code page ({pages}; for example {samples}): "
                      "they would come out garbled. Save it as text in UTF-8 (in Excel: "
                      "Save As, CSV UTF-8), or name its code page in a first line such as "
                      "# encoding: cp1256, and run again.", path=os.fspath(path),
                      pages=", ".join(pages), samples=" | ".join(samples))


def _script(ch: str) -> str:
    if ch < "\x80":
        return "LATIN"
    name = unicodedata.name(ch, "")
    if name.startswith(_LATIN_NAMED):
        return "LATIN"
    first = name.split(" ", 1)[0]
    return _SAME_SCRIPT.get(first, first)


def _word_faults(word: str) -> Tuple[int, int]:
    """``(faults, non-ASCII letters)`` of one word (letters, marks, format characters)."""
    scripts, non_ascii, bad = set(), 0, 0
    cats = [unicodedata.category(c) for c in word]
    if cats[0][0] == "M":
        bad += 1                                        # a vowel sign starts no word
    run = 0
    for k, (ch, cat) in enumerate(zip(word, cats)):
        if cat == "Sk" or cat == "Lm" and _script(ch) == "MODIFIER":
            bad += 1                                    # ˜ ˆ ¨ ´: accents are precomposed
            continue
        if cat[0] in "LM":
            scripts.add(_script(ch))
        if cat[0] != "L":
            continue
        wide = ch >= "\x80"
        non_ascii += wide
        run = run + 1 if wide else 0
        if run == 3:
            bad += scripts == {"LATIN"}                 # ÄÞØ: 3 accented letters in a row
        if k and cat == "Lu" and cats[k - 1] == "Ll" and (wide or word[k - 1] >= "\x80"):
            bad += 1                                    # äÞ: small then accented capital
    letters = sum(c[0] == "L" for c in cats)
    if len(scripts) > 1:
        bad += 1                                        # Straك, Peًón
    elif scripts == {"LATIN"} and letters >= 2 and non_ascii == letters:
        bad += 1                                        # Ýí: a Latin word of accents only
    return bad, non_ascii


def reading_faults(text: str) -> Tuple[int, int]:
    """Judge one reading of a file: ``(faults, non-ASCII letters in clean words)``.

    Words are runs of letters, marks and format characters (the zero-width
    non-joiner of Persian) between digits, punctuation, symbols and spaces; only words
    with a non-ASCII character are judged (the first 20,000).

    >>> reading_faults("P1,Château,Müller-Süd")
    (0, 3)
    >>> reading_faults("äÞØÉ1")                      # نقطة (cp1256) read as cp1252
    (3, 0)
    >>> reading_faults("نقطة1,چک 2")
    (0, 6)
    """
    faults = letters = 0
    for n, m in enumerate(_TOKEN.finditer(text)):
        if n >= _MAX_TOKENS:
            break
        token = m.group()
        if token.isascii():
            continue
        word: List[str] = []
        for ch in token + " ":
            if unicodedata.category(ch)[0] in "LMC" or unicodedata.category(ch) == "Sk":
                word.append(ch)
                continue
            if word and not "".join(word).isascii():
                bad, wide = _word_faults("".join(word))
                faults += bad
                letters += 0 if bad else wide
            word = []
    return faults, letters


def _declared(raw: bytes) -> Optional[str]:
    head = b"\n".join(raw.splitlines()[:2])
    m = _DECLARED.search(head)
    return m.group(1).decode("ascii") if m else None


def _pages(machine: Optional[str]) -> List[str]:
    return list(dict.fromkeys(p for p in (machine,) + CODE_PAGES if p))


def _legacy(raw: bytes, path, machine: Optional[str]) -> Tuple[str, str]:
    """Return ``(text, page)`` of the reading of ``raw`` with the fewest faults."""
    pages = _pages(machine)
    readings = []
    first_error = None
    for page in pages:
        try:
            text = raw.decode(page)
        except UnicodeDecodeError as exc:
            first_error = first_error or (exc.start, page)
            continue
        readings.append((page, text) + reading_faults(text))
    if not readings:
        raise _not_text(path, first_error[0], first_error[1])
    if len({r[1] for r in readings}) == 1:
        return readings[0][1], readings[0][0]
    fewest = min(r[2] for r in readings)
    best = [r for r in readings if r[2] == fewest]
    most = max(r[3] for r in best)
    best = [r for r in best if r[3] == most]
    if len({r[1] for r in best}) == 1:
        return best[0][1], best[0][0]
    if machine in [r[0] for r in best]:
        return next((r[1], r[0]) for r in best if r[0] == machine)
    raise _unclear(path, [r[0] for r in best], _samples([r[1] for r in best]))


def _samples(texts: List[str]) -> List[str]:
    """Return the first word on which the readings differ, in each reading."""
    k = next((i for i, cs in enumerate(zip(*texts)) if len(set(cs)) > 1), 0)
    out = []
    for t in texts:
        a = k
        while a > 0 and not t[a - 1].isspace() and t[a - 1] not in ",;\t":
            a -= 1
        b = k
        while b < len(t) and not t[b].isspace() and t[b] not in ",;\t":
            b += 1
        out.append(t[a:b][:40])
    return out


def decode_text(raw: bytes, path, *, encoding: Optional[str] = None,
                machine: Optional[str] = None) -> Tuple[str, str]:
    """Decode a user's text file by the module's rule.

    Parameters
    ----------
    raw : bytes
        The file's content.
    path : path-like
        Named in the refusals.
    encoding : str, optional
        The file's encoding when the caller knows it (a file's own ``# encoding:``
        line names it otherwise).
    machine : str, optional
        The machine's code page (default :func:`system_code_page`).

    Returns
    -------
    (str, str)
        The text and the encoding it was read in (``utf-16``, ``utf-8`` or the page).

    Raises
    ------
    InputError
        NUL bytes outside UTF-16, bytes the named page does not define, or names
        that read equally well in two code pages.
    """
    if raw.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)):
        try:
            return raw.decode("utf-16"), "utf-16"
        except UnicodeDecodeError as exc:
            raise _not_text(path, exc.start, "UTF-16") from None
    machine = machine if machine is not None else system_code_page()
    nul = raw.find(b"\x00")
    if nul >= 0:
        raise _not_text(path, nul, "/".join(_pages(machine)))
    named = encoding or (None if raw.startswith(codecs.BOM_UTF8) else _declared(raw))
    if named:
        try:
            page = codecs.lookup(named).name
            return raw.decode(page), page
        except LookupError:
            raise _not_text(path, 0, named) from None
        except UnicodeDecodeError as exc:
            raise _not_text(path, exc.start, named) from None
    try:
        return raw.decode("utf-8-sig"), "utf-8"
    except UnicodeDecodeError:
        pass
    return _legacy(raw, path, machine)


def read_text(path, *, encoding: Optional[str] = None) -> str:
    """Return the text of ``path`` decoded by :func:`decode_text` (the file must exist)."""
    with open(os.fspath(path), "rb") as fh:
        raw = fh.read()
    return decode_text(raw, path, encoding=encoding)[0]

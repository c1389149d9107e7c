r"""Text files the user writes by hand or in a spreadsheet: one decoding rule.

GCP lists (``.points``, CSV) and check-point files are read with the same rule, in
this order:

1. a UTF-16 byte-order mark → UTF-16 (Excel's "Unicode Text");
2. UTF-8, with or without a byte-order mark (QGIS, Excel's "CSV UTF-8");
3. otherwise the machine's Windows ANSI code page — what Excel's plain "CSV" writes
   on that machine: Windows-1252 in Western locales, Windows-1256 for Arabic and
   Persian, cp932 in Japan … — or Windows-1252 where the system encoding is UTF-8
   (Linux, macOS).

A file with NUL bytes (binary) or with bytes the code page does not define is
refused naming the file, the byte and the fix (save as CSV UTF-8). Only names and
ids can hold non-ASCII text; numbers read the same in every one of these encodings.

Examples
--------
>>> decode_text("id,x\nP1,1\n".encode("utf-8-sig"), "a.csv")
('id,x\nP1,1\n', 'utf-8')
>>> decode_text("Ch\u00e2teau,1\n".encode("cp1252"), "a.csv", legacy="cp1252")
('Château,1\n', 'cp1252')
"""
from __future__ import annotations

import codecs
import locale
import os
from typing import Optional, Tuple

from ..errors import InputError

#: The 8-bit fallback where the system's encoding is not a Windows code page.
LEGACY_DEFAULT = "cp1252"

__all__ = ["LEGACY_DEFAULT", "decode_text", "legacy_encoding", "read_text"]


def legacy_encoding() -> str:
    """Return the Windows ANSI code page of this machine (``cp1252``, ``cp1256`` …).

    ``locale.getencoding`` (Python ≥ 3.11) ignores UTF-8 mode; older Pythons use the
    preferred encoding. A UTF or ASCII system encoding (Linux, macOS) gives
    :data:`LEGACY_DEFAULT`; any other page is kept (``cp932`` on Japanese Windows).
    """
    getter = getattr(locale, "getencoding", None)
    try:
        enc = getter() if getter else locale.getpreferredencoding(False)
        enc = codecs.lookup(enc).name if enc else ""
    except (LookupError, ValueError):
        enc = ""
    return enc if enc and not enc.startswith(("utf", "ascii")) else LEGACY_DEFAULT


def _not_text(path, offset: int, encoding: str) -> InputError:
    return InputError("{path} is not a text file in UTF-8 or {encoding} (byte {offset} "
                      "cannot be read): save it as text in UTF-8 (in Excel: Save As, CSV "
                      "UTF-8) and run again.", path=os.fspath(path), encoding=encoding,
                      offset=offset)


def decode_text(raw: bytes, path, *, legacy: Optional[str] = None) -> Tuple[str, str]:
    """Decode a user's text file by the module's rule.

    Parameters
    ----------
    raw : bytes
        The file's content.
    path : path-like
        Named in the refusal.
    legacy : str, optional
        The 8-bit code page tried last (default :func:`legacy_encoding`).

    Returns
    -------
    (str, str)
        The text and the encoding it was read in (``utf-16``, ``utf-8`` or the page).

    Raises
    ------
    InputError
        NUL bytes outside UTF-16, or bytes no rule can read.
    """
    if raw.startswith((codecs.BOM_UTF16_LE, codecs.BOM_UTF16_BE)):
        try:
            return raw.decode("utf-16"), "utf-16"
        except UnicodeDecodeError as exc:
            raise _not_text(path, exc.start, "UTF-16") from None
    nul = raw.find(b"\x00")
    if nul >= 0:
        raise _not_text(path, nul, legacy or legacy_encoding())
    try:
        return raw.decode("utf-8-sig"), "utf-8"
    except UnicodeDecodeError:
        pass
    enc = legacy or legacy_encoding()
    try:
        return raw.decode(enc), enc
    except UnicodeDecodeError as exc:
        raise _not_text(path, exc.start, enc) from None


def read_text(path, *, legacy: Optional[str] = None) -> str:
    """Return the text of ``path`` decoded by :func:`decode_text` (the file must exist)."""
    with open(os.fspath(path), "rb") as fh:
        raw = fh.read()
    return decode_text(raw, path, legacy=legacy)[0]

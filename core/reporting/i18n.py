"""Qt-free translation of report text (Arabic, Persian) and text direction.

The translations are the plugin's JSON dictionaries ``i18n/strings/*.json`` (one
``{english: {"ar": ..., "fa": ...}}`` mapping per topic) — the same source the Qt
``.ts`` files are generated from (``scripts/i18n_sync.py``), so a report string and a
dialog string are translated once. Reports built in core, in tests or on Dask workers
need no Qt to be translated.

Examples
--------
>>> tr = translator("en")
>>> tr("Total error")
'Total error'
"""
from __future__ import annotations

import functools
import json
from pathlib import Path
from typing import Callable, Dict

#: Languages written right to left.
RTL_LANGS = frozenset({"ar", "fa", "he", "ur", "ps", "ckb"})

STRINGS_DIR = Path(__file__).resolve().parents[2] / "i18n" / "strings"


def normalise_lang(lang) -> str:
    """Return the two-letter language code: ``fa_IR`` -> ``fa``, empty -> ``en``."""
    text = str(lang or "en").strip().replace("-", "_").split(".")[0]
    code = (text.split("_")[0] or "en").lower()
    # 'C' / 'POSIX' (headless runs) and anything that is not a language code -> English
    return code if len(code) in (2, 3) and code.isalpha() and code != "c" else "en"


def direction(lang) -> str:
    """Return ``rtl`` for right-to-left languages, else ``ltr``."""
    return "rtl" if normalise_lang(lang) in RTL_LANGS else "ltr"


@functools.lru_cache(maxsize=1)
def _dictionary() -> Dict[str, Dict[str, str]]:
    merged: Dict[str, Dict[str, str]] = {}
    for path in sorted(STRINGS_DIR.glob("*.json")):
        for source, tr in json.loads(path.read_text(encoding="utf-8")).items():
            slot = merged.setdefault(source, {})
            for lang, text in tr.items():
                if text:
                    slot.setdefault(lang, text)
    return merged


def has_translation(text: str, lang) -> bool:
    """Return True when ``text`` has a translation into ``lang`` (English always has)."""
    lang = normalise_lang(lang)
    return lang == "en" or bool(_dictionary().get(text, {}).get(lang))


def translator(lang) -> Callable[[str], str]:
    """Return a function translating English report text into ``lang``.

    Unknown strings are returned unchanged (English), so a missing translation shows
    as English rather than failing; the i18n tests list such strings.

    Parameters
    ----------
    lang : str
        Language code (``'en'``, ``'ar'``, ``'fa'``; region suffixes are ignored).
    """
    lang = normalise_lang(lang)
    if lang == "en":
        return lambda text: text
    table = _dictionary()

    def tr(text: str) -> str:
        return table.get(text, {}).get(lang) or text

    return tr

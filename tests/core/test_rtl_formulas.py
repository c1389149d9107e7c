"""Arabic/Persian translations keep formula terms such as ``N = {n}`` in one
left-to-right isolate (U+2066 … U+2069): without it a right-to-left paragraph shows
"8 = N" (found in the Arabic DTM-accuracy report)."""
from __future__ import annotations

import json
import re
from pathlib import Path

STRINGS = Path(__file__).resolve().parents[2] / "i18n" / "strings"
TERM = re.compile(r"(?:0 < d ≤ )?[A-Za-zθ_]\w*\s*=\s*\{[^}]*\}°?")


def _unisolated(text: str) -> list[str]:
    """Formula terms of ``text`` that are not inside an LRI…PDI isolate."""
    bad, depth, pos = [], 0, 0
    for m in TERM.finditer(text):
        depth += text.count("\u2066", pos, m.start()) - text.count("\u2069", pos, m.start())
        pos = m.start()
        if depth <= 0:
            bad.append(m.group(0))
    return bad


def test_unisolated_detector():
    assert _unisolated("N = {n}، RMSE = {r} م") == ["N = {n}", "RMSE = {r}"]
    assert _unisolated("\u2066N = {n}\u2069، \u2066RMSE = {r}\u2069 م") == []


def test_formula_terms_isolated_in_rtl_translations():
    bad = []
    for path in sorted(STRINGS.glob("*.json")):
        for english, tr in json.loads(path.read_text(encoding="utf-8")).items():
            for lang in ("ar", "fa"):
                hits = _unisolated(tr.get(lang, ""))
                if hits:
                    bad.append(f"{path.name} [{lang}] {english[:50]!r}: {hits}")
    assert not bad, "wrap these in U+2066 … U+2069:\n" + "\n".join(bad)

"""One glossary per language, enforced on every translation in ``i18n/strings/*.json``.

A *check point* (independent point that measures accuracy: نقطة تحقق / نقطهٔ چک) is not
a *control point* (a point that fits the model: نقطة ضبط / نقطهٔ کنترل): a surveyor
reads a different quantity. Filter, sensor, DTM and LiDAR each have one word.
"""
from __future__ import annotations

import json
import re
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]

#: English that names a check point (or a check height) ...
CHECK = re.compile(r"check[ -]?points?|\b(?:DTM −|z|=) check\b|\bcheck height\b", re.I)
#: ... and English that also names control points (then both words may appear)
CONTROL = re.compile(r"control|gcp|georef", re.I)

#: {language: [(concept, the one word, pattern of the words it replaced)]}
GLOSSARY = {
    "ar": [("filter", "مرشح (filtering: ترشيح)", r"فلتر|فلاتر|مرشّح"),
           ("sensor", "مستشعر", r"حساس(?!ي)"),
           ("DTM", "نموذج التضاريس الرقمي", r"نموذج الارتفاعات الرقمي|نماذج الارتفاعات الرقمية")],
    "fa": [("LiDAR", "لایدار", r"لیدار"),
           ("filter", "فیلتر", r"پالایه"),
           ("sensor", "حسگر", r"سنجنده"),
           ("DTM", "مدل رقومی زمین", r"مدل رقومی ارتفاع(?!ی)")],
}
#: the check-point word (must appear) and the control-point word (must not) per language
CHECK_WORDS = {"ar": ("تحقق", "ضبط"), "fa": ("چک", "کنترل")}


def _translations():
    for path in sorted((ROOT / "i18n" / "strings").glob("*.json")):
        for english, langs in json.loads(path.read_text(encoding="utf-8")).items():
            yield path.name, english, langs


@pytest.mark.parametrize("lang", sorted(GLOSSARY))
def test_one_word_per_concept(lang):
    bad = []
    for name, _english, langs in _translations():
        text = langs.get(lang, "")
        for concept, word, pattern in GLOSSARY[lang]:
            for m in re.finditer(pattern, text):
                bad.append(f"{name}: {concept} should be {word!r}, found {m.group(0)!r} "
                           f"in {text[max(0, m.start() - 30):m.end() + 30]!r}")
    assert not bad, f"{len(bad)} glossary breaks ({lang}):\n" + "\n".join(bad)


@pytest.mark.parametrize("lang", sorted(CHECK_WORDS))
def test_check_point_is_not_control_point(lang):
    check_word, control_word = CHECK_WORDS[lang]
    bad, n = [], 0
    for name, english, langs in _translations():
        text = langs.get(lang, "")
        if not text or not CHECK.search(english):
            continue
        n += 1
        if check_word not in text:
            bad.append(f"{name}: no {check_word!r} for {english[:80]!r}: {text[:120]!r}")
        if control_word in text and not CONTROL.search(english):
            bad.append(f"{name}: {control_word!r} (control point) for a check point in "
                       f"{english[:80]!r}: {text[:160]!r}")
    assert n > 50      # the rule ran over the check-point strings
    assert not bad, f"{len(bad)} check points named otherwise ({lang}):\n" + "\n".join(bad)


def test_rules_catch_the_old_drift():
    """The patterns match the words that were used before the glossary."""
    samples = {"ar": ("مرشّح الأرض", "فلتر الميل", "عرض الحساس",
                      "نموذج الارتفاعات الرقمي للأرض"),
               "fa": ("کاشی‌های لیدار", "پالایهٔ زمین", "مدل رقومی ارتفاع")}
    for lang, texts in samples.items():
        for text in texts:
            assert any(re.search(p, text) for _, _, p in GLOSSARY[lang]), text
    assert CHECK.search("Check points (point layer)")
    assert CHECK.search("error DTM − check (m)")
    assert not CONTROL.search("Check points (point layer)")

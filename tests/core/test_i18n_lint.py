"""The i18n part of `make lint` (scripts/i18n_sync.py --check): error templates and
tr() calls."""
from __future__ import annotations

import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
sys.path.insert(0, str(ROOT / "scripts"))
import i18n_sync  # noqa: E402


def test_every_input_error_template_of_the_tree_is_translated():
    templates, problems = i18n_sync.input_error_templates()
    assert len(templates) >= 90 and problems == []
    dictionary = i18n_sync.load_dictionary()
    missing = [t for t in templates for lang in ("ar", "fa") if not dictionary.get(t, {})
               .get(lang)]
    assert missing == []
    assert "{path} holds no check points." in templates


def test_scanner_flags_fstrings_and_untranslated_templates():
    src = ('def f(p, n):\n'
           '    raise InputError(f"{p} is bad")\n'
           '    raise InputError("A brand new message about {n}.", n=n)\n'
           '    raise InputError(str(p))\n')
    templates, problems = {}, []
    i18n_sync.scan_input_errors(src, "core/x.py", templates, problems)
    assert list(templates) == ["A brand new message about {n}."]
    assert len(problems) == 1 and problems[0].startswith("core/x.py:2: InputError")
    assert "A brand new message about {n}." not in i18n_sync.load_dictionary()


def test_scanner_flags_tr_of_a_variable_unless_marked():
    src = ('class A:\n'
           '    def f(self, label, labels):\n'
           '        self.tr("literal")\n'
           '        self.tr(label)\n'
           '        [self.tr(x) for x in labels]  # i18n: noop-list\n')
    problems = i18n_sync.scan_tr_calls(src, "algorithms/a.py")
    assert [p.split(":")[1] for p in problems] == ["4"]
    assert i18n_sync.tr_call_problems() == []


def test_no_english_only_user_message_left():
    """core/ raises InputError templates, algorithms/ logs and raises through self.tr()."""
    problems, over = i18n_sync.message_problems()
    assert problems == [] and over == []


def test_message_scanner_flags_english_and_respects_markers():
    core = ('def f(p):\n'
            '    raise ValueError(f"{p} is bad")\n'
            '    raise RuntimeError("disk gone")\n'
            '    raise ValueError\n'
            '    raise ValueError(self.tr("fine"))\n'
            '    raise ValueError("kind")  # i18n: internal\n')
    found = i18n_sync.scan_messages(core, "core/x.py")
    assert sorted(p.split(":")[1] for p in found) == ["2", "3"]
    alg = ('class A:\n'
           '    def run(self, feedback, n):\n'
           '        feedback.pushInfo(f"{n} points")\n'
           '        feedback.pushInfo(self.tr("{} points").format(n))\n'
           '        feedback.pushInfo(f"{n}")  # i18n: data\n'
           '        raise QgsProcessingException("Bad input")\n'
           '        raise QgsProcessingException(self.tr("Bad input"))\n')
    found = i18n_sync.scan_messages(alg, "algorithms/a.py")
    assert sorted(p.split(":")[1] for p in found) == ["3", "6"]

"""The examples in the core's docstrings run (``make test`` runs them: this test).

Every module of ``geomatics_toolbox.core`` is imported under its package name and its
doctests are run with :mod:`doctest`; an example that no longer matches the code fails.
Examples that need files or data carry ``# doctest: +SKIP``.
"""
from __future__ import annotations

import doctest
import importlib
import pkgutil

import pytest

import geomatics_toolbox.core as core

MODULES = sorted(m.name for m in pkgutil.walk_packages(core.__path__, core.__name__ + "."))


def test_the_core_has_examples():
    found = 0
    for name in MODULES:
        finder = doctest.DocTestFinder()
        found += sum(len(t.examples) for t in finder.find(importlib.import_module(name)))
    assert found >= 30


@pytest.mark.parametrize("name", MODULES)
def test_docstring_examples(name):
    module = importlib.import_module(name)
    result = doctest.testmod(module, optionflags=doctest.ELLIPSIS | doctest.NORMALIZE_WHITESPACE,
                             verbose=False)
    assert result.failed == 0, f"{result.failed} of {result.attempted} examples fail in {name}"

"""Errors the core raises for bad input.

:class:`InputError` is a :class:`ValueError` whose message names the problem and
the fix; the Processing base class shows it as a plain message (no traceback), while
any other exception is reported with its traceback in the log.
"""
from __future__ import annotations


class InputError(ValueError):
    """Bad input or parameters: the message says what is wrong and how to fix it."""

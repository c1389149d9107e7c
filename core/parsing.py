"""Parsers of the text parameters users type (number lists and ranges).

>>> parse_number_list("40:60:4", "SLOPES")
[40.0, 44.0, 48.0, 52.0, 56.0, 60.0]
>>> parse_number_list("3, 5;10", "RADII")
[3.0, 5.0, 10.0]
"""
from __future__ import annotations

import math
from typing import List

import numpy as np

from .errors import InputError

__all__ = ["parse_number_list"]


def _range(t: str) -> List[float]:
    parts = [float(p) for p in t.split(":")]
    if len(parts) != 3 or parts[2] <= 0 or parts[1] < parts[0]:
        raise ValueError
    a, b, step = parts
    count = int(math.floor((b - a) / step + 1e-9)) + 1
    if count > 1000:
        raise ValueError
    return [round(a + k * step, 10) for k in range(count)]


def parse_number_list(text, name: str) -> List[float]:
    """Parse ``"40, 44, 48"`` or ``"40:60:4"`` (start:stop:step, stop included) as floats.

    Raises
    ------
    InputError
        Empty text, or text that is not a list of numbers or a range.
    """
    if isinstance(text, (list, tuple, np.ndarray)):
        vals = [float(v) for v in text]
    else:
        t = str(text or "").strip()
        if not t:
            raise InputError("{name} is empty; give numbers like '40, 44, 48' or a range "
                             "'40:60:4'.", name=name)
        try:
            vals = _range(t) if ":" in t else [
                float(p) for p in t.replace(";", ",").replace(" ", ",").split(",")
                if p.strip()]
        except ValueError:
            raise InputError("{name} '{text}' is not a list of numbers; use '40, 44, 48' or "
                             "start:stop:step like '40:60:4' (at most 1000 values).",
                             name=name, text=text) from None
    if not vals:
        raise InputError("{name} holds no numbers.", name=name)
    return vals

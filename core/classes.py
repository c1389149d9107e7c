"""ASPRS point classes (LAS 1.4 R15, Table 17): the one constant set of the core.

Every module that reads or writes LAS classes uses these names; ``np.uint8`` so that
array assignments keep the LAS type.

>>> int(GROUND), int(LOW_NOISE), int(HIGH_NOISE)
(2, 7, 18)
>>> sorted(int(c) for c in INPUT_NOISE)
[7, 18]
"""
from __future__ import annotations

import numpy as np

__all__ = ["NEVER_CLASSIFIED", "UNCLASSIFIED", "GROUND", "LOW_VEGETATION",
           "MEDIUM_VEGETATION", "HIGH_VEGETATION", "BUILDING", "LOW_NOISE", "WATER",
           "BRIDGE_DECK", "HIGH_NOISE", "INPUT_NOISE", "NAMES"]

NEVER_CLASSIFIED = np.uint8(0)    #: created, never classified
UNCLASSIFIED = np.uint8(1)        #: processed but not ground ("other")
GROUND = np.uint8(2)
LOW_VEGETATION = np.uint8(3)
MEDIUM_VEGETATION = np.uint8(4)
HIGH_VEGETATION = np.uint8(5)
BUILDING = np.uint8(6)
LOW_NOISE = np.uint8(7)
WATER = np.uint8(9)
BRIDGE_DECK = np.uint8(17)
HIGH_NOISE = np.uint8(18)

#: classes an input already marks as noise (kept as they are by the ground filters)
INPUT_NOISE = (LOW_NOISE, HIGH_NOISE)

#: English names (report message ids) of the classes the ground filters write
NAMES = {int(GROUND): "ground", int(UNCLASSIFIED): "other (object)",
         int(LOW_NOISE): "low noise", int(NEVER_CLASSIFIED): "never classified",
         int(HIGH_NOISE): "high noise"}

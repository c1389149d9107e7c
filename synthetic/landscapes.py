"""Per-landscape synthetic ALS scenes with known terrain (Qt-free, deterministic).

The hard cases of a ground filter that the ISPRS samples barely hold, each small
enough for a unit test and each with the true terrain as a function:

* :func:`closed_forest` - a closed canopy over rolling hills where only a few per
  cent of the returns reach the ground (the plot that put the terrain in the trees);
* :func:`steep_cliffs` - a 45 degree mountainside cut by vertical cliffs, with trees;
* :func:`lake` - a lake in a hollow: flat, sparse water returns (class 9) and banks;
* :func:`bridge` - a road bridge (deck, class 17) across a valley.

Every function returns a :class:`Scene`: ``x, y, z`` (m), ``classification`` (ASPRS:
2 ground, 5 vegetation, 9 water, 17 bridge deck) and ``terrain(x, y)``, the true bare
earth (under a lake, the water level: what a DTM should show there).

Example
-------
>>> s = closed_forest(extent=100.0, density=1.5, ground_share=0.05, seed=1)
>>> bool((s.classification == 2).mean() < 0.1)
True
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Callable

import numpy as np

GROUND, VEGETATION, WATER, BRIDGE = 2, 5, 9, 17

__all__ = ["Scene", "closed_forest", "steep_cliffs", "lake", "bridge"]


@dataclass(frozen=True, eq=False)
class Scene:
    """Points, their true classes and the true terrain function."""

    x: np.ndarray
    y: np.ndarray
    z: np.ndarray
    classification: np.ndarray
    terrain: Callable

    def __len__(self) -> int:
        return int(self.x.size)


def _pulses(rng, extent: float, density: float):
    n = rng.poisson(density * extent * extent)
    return rng.uniform(0, extent, n), rng.uniform(0, extent, n)


def _hills(x, y, base=300.0, amp=6.0):
    return (base + 0.08 * x - 0.05 * y + amp * np.sin(x / 23.0) * np.cos(y / 31.0)
            + 0.5 * amp * np.sin((x + 2 * y) / 47.0))


def _canopy(rng, x, y, terrain, height, frac_ground, extent):
    """Returns of a closed canopy: crowns of ``height`` m over ``terrain``."""
    nt = int(extent * extent / 30.0)                      # one crown per 30 m²
    tx, ty = rng.uniform(-5, extent + 5, nt), rng.uniform(-5, extent + 5, nt)
    th = height * rng.uniform(0.7, 1.2, nt)
    from scipy.spatial import cKDTree
    d, j = cKDTree(np.column_stack((tx, ty))).query(np.column_stack((x, y)))
    top = th[j] * np.clip(1.0 - (d / 4.0) ** 2 * 0.5, 0.4, 1.0)   # rounded crowns
    ground = rng.random(x.size) < frac_ground
    depth = rng.uniform(0.0, 0.6, x.size) ** 2                    # most near the top
    z = terrain(x, y) + np.where(ground, rng.normal(0, 0.05, x.size),
                                 top * (1.0 - depth))
    cls = np.where(ground, GROUND, VEGETATION).astype(np.uint8)
    return z, cls


def closed_forest(*, extent: float = 150.0, density: float = 1.5,
                  ground_share: float = 0.05, height: float = 22.0,
                  seed: int = 0) -> Scene:
    """A closed canopy over rolling hills; ``ground_share`` of the returns are ground.

    Parameters
    ----------
    extent : float
        Side of the square scene (m).
    density : float
        Returns per m².
    ground_share : float
        Share of the returns that reach the ground (0.05: a dense forest).
    height : float
        Typical tree height (m).
    seed : int
        Random seed.
    """
    rng = np.random.default_rng(seed)
    x, y = _pulses(rng, extent, density)
    z, cls = _canopy(rng, x, y, _hills, height, ground_share, extent)
    return Scene(x, y, z, cls, _hills)


def steep_cliffs(*, extent: float = 150.0, density: float = 2.0, slope: float = 1.0,
                 cliff: float = 12.0, tree_share: float = 0.3, seed: int = 0) -> Scene:
    """A mountainside of gradient ``slope`` (1.0 = 45°) with two vertical cliffs.

    The slope rises along x; cliffs of ``cliff`` m (rising over 0.5 m) cross it at
    x = extent/3 and 2 extent/3; trees of 15 m cover ``tree_share`` of the scene.
    """
    rng = np.random.default_rng(seed)
    c1, c2 = extent / 3.0, 2.0 * extent / 3.0

    def terrain(x, y):
        x = np.asarray(x, float)
        y = np.asarray(y, float)
        step = cliff * (np.clip((x - c1) / 0.5, 0, 1) + np.clip((x - c2) / 0.5, 0, 1))
        return 500.0 + slope * x + 3.0 * np.sin(y / 17.0) + step

    x, y = _pulses(rng, extent, density)
    in_trees = (np.sin(x / 9.0) * np.sin(y / 11.0)) > 1.0 - 2.0 * tree_share
    zf, cf = _canopy(rng, x, y, terrain, 15.0, 0.3, extent)
    z = np.where(in_trees, zf, terrain(x, y) + rng.normal(0, 0.05, x.size))
    cls = np.where(in_trees, cf, GROUND).astype(np.uint8)
    return Scene(x, y, z, cls, terrain)


def lake(*, extent: float = 200.0, density: float = 2.0, radius: float = 60.0,
         water_return: float = 0.1, seed: int = 0) -> Scene:
    """A lake of ``radius`` m in a hollow; water returns ``water_return`` x as dense.

    The water (class 9) lies flat at the level of the shore; the banks rise 4 m over
    20 m around it. ``terrain`` is the bare earth, the water level over the lake.
    """
    rng = np.random.default_rng(seed)
    cx = cy = extent / 2.0
    level = 200.0

    def terrain(x, y):
        r = np.hypot(np.asarray(x, float) - cx, np.asarray(y, float) - cy)
        bank = level + 4.0 * np.clip((r - radius) / 20.0, 0.0, 1.0)
        return np.where(r < radius, level, bank) + 0.01 * np.asarray(x, float)

    x, y = _pulses(rng, extent, density)
    r = np.hypot(x - cx, y - cy)
    on_water = r < radius
    keep = ~on_water | (rng.random(x.size) < water_return)
    x, y, on_water = x[keep], y[keep], on_water[keep]
    z = terrain(x, y) + rng.normal(0, 0.03, x.size)
    cls = np.where(on_water, WATER, GROUND).astype(np.uint8)
    return Scene(x, y, z, cls, terrain)


def bridge(*, extent: float = 200.0, density: float = 4.0, deck_height: float = 8.0,
           deck_width: float = 12.0, seed: int = 0) -> Scene:
    """A bridge deck (class 17) ``deck_height`` m above a 60 m wide valley floor.

    The valley runs along y with 1:2 sides; the deck crosses it along x at
    y = extent/2 and meets the ground at both rims (its ramps are ground).
    """
    rng = np.random.default_rng(seed)
    mid = extent / 2.0

    def terrain(x, y):
        d = np.abs(np.asarray(x, float) - mid)
        return 100.0 + deck_height * np.clip((d - 30.0) / (2.0 * deck_height), 0.0, 1.0) \
            + 0.0 * np.asarray(y, float)

    x, y = _pulses(rng, extent, density)
    g = terrain(x, y)
    on_deck = (np.abs(y - mid) < deck_width / 2.0) & (g < 100.0 + deck_height - 0.5)
    z = np.where(on_deck, 100.0 + deck_height, g) + rng.normal(0, 0.03, x.size)
    cls = np.where(on_deck, BRIDGE, GROUND).astype(np.uint8)
    return Scene(x, y, z, cls, terrain)

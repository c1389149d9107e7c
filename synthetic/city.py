"""Synthetic city scene with known answers: roof types, a footbridge, sheds under trees.

``city_scene(density=2.0, seed=0)`` returns a :class:`CityScene`: airborne-like points
(x, y, z, classes, returns, intensity) over a 200 m × 160 m tile and the truth of every
structure in it:

* a **gabled** house (12 × 8 m, eaves 5 m, 35°), a **hipped** house (14 × 10 m, eaves
  6 m, 30°, equal pitch all round), a **flat** roof at 9 m with a 1 m **parapet**
  (0.3 m wide) — roofs overhang their walls by 0.5 m (eaves), a few wall points sit
  under the eaves;
* two **sheds** (6 × 4 m at 2.5 m, 5 × 5 m at 2.3 m, flat) under overhanging crowns:
  pulses hit the crown first and, with the canopy's penetration probability, the roof
  under it;
* a **footbridge** (3 m × 65 m deck, 0.3 m above the banks) across a 50 m wide, 6 m deep
  river valley: the deck joins the ground at both ends; the 14 m wide water surface
  returns a pulse with probability 0.3 (class 9), none under the deck;
* scattered trees (class 5), ground (class 2, σ 3 cm).

Truth heights (:attr:`Structure.height`) are the top of the roof surface (ridge, or the
flat roof without its parapet) minus the mean terrain along the outside of the
outline, as :mod:`.buildings_eval` defines them.

Qt-free, deterministic, vectorised over points (loops over the few objects only).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Dict, List, Tuple

import numpy as np

GROUND, VEG, BUILDING, WATER, BRIDGE = 2, 5, 6, 9, 17
ORIGIN = (600_000.0, 5_000_000.0)
EXTENT = (200.0, 160.0)
RIVER_U, RIVER_HALF, RIVER_DEPTH, WATER_HALF = 150.0, 25.0, 6.0, 7.0


@dataclass(frozen=True)
class Structure:
    """One structure: rectangle (centre, half sizes, angle), roof kind and heights."""

    name: str
    kind: str            # 'gabled', 'hipped', 'flat', 'bridge'
    cx: float
    cy: float
    half_length: float   # along u (the ridge of gabled and hipped roofs)
    half_width: float
    angle: float         # radians of u from +x
    eave: float          # eave height above the base (m); the roof of flat/shed
    pitch: float = 0.0   # degrees
    parapet: float = 0.0  # parapet height above a flat roof (m)
    base: float = 0.0    # terrain height the building stands on (set by the scene)

    def local(self, x, y):
        """(u, v) of ``x, y`` in the structure's frame."""
        dx, dy = np.asarray(x) - self.cx, np.asarray(y) - self.cy
        c, s = math.cos(self.angle), math.sin(self.angle)
        return dx * c + dy * s, -dx * s + dy * c

    def inside(self, x, y, pad: float = 0.0):
        """True for points inside the rectangle grown by ``pad`` m."""
        u, v = self.local(x, y)
        return (np.abs(u) <= self.half_length + pad) & (np.abs(v) <= self.half_width + pad)

    def roof(self, x, y):
        """Roof height (absolute) at ``x, y`` (no footprint test; parapet included)."""
        u, v = self.local(x, y)
        t = math.tan(math.radians(self.pitch))
        a, b = self.half_length, self.half_width
        if self.kind == "gabled":
            rise = (b - np.abs(v)) * t
        elif self.kind == "hipped":
            rise = np.minimum(b - np.abs(v), a - np.abs(u)) * t
        else:
            rise = np.zeros(np.shape(u))
        z = self.base + self.eave + rise
        if self.parapet:
            edge = np.minimum(a - np.abs(u), b - np.abs(v)) < 0.3
            z = np.where(edge, z + self.parapet, z)
        return z

    @property
    def top(self) -> float:
        """Height of the highest roof point above the base (parapet excluded)."""
        t = math.tan(math.radians(self.pitch))
        return self.eave + (self.half_width * t if self.kind in ("gabled", "hipped")
                            else 0.0)

    def corners(self) -> np.ndarray:
        """Corners (4, 2), counter-clockwise."""
        c, s = math.cos(self.angle), math.sin(self.angle)
        uv = np.array([[1, 1], [-1, 1], [-1, -1], [1, -1]]) * [self.half_length,
                                                                 self.half_width]
        return np.column_stack([self.cx + uv[:, 0] * c - uv[:, 1] * s,
                                self.cy + uv[:, 0] * s + uv[:, 1] * c])


@dataclass
class CityScene:
    """Points and truth of :func:`city_scene`."""

    x: np.ndarray
    y: np.ndarray
    z: np.ndarray
    classification: np.ndarray
    return_number: np.ndarray
    number_of_returns: np.ndarray
    intensity: np.ndarray
    buildings: List[Structure]
    bridge: Structure
    density: float
    seed: int
    trees: np.ndarray = field(default_factory=lambda: np.zeros((0, 5)))

    def __len__(self) -> int:
        return int(self.x.size)

    @staticmethod
    def terrain(x, y):
        """True terrain: a gentle plane cut by the river valley (x = origin + 150 m)."""
        u = np.asarray(x) - ORIGIN[0]
        v = np.asarray(y) - ORIGIN[1]
        z = 100.0 + 0.01 * u + 0.005 * v
        d = np.abs(u - RIVER_U)
        valley = np.where(d < RIVER_HALF, RIVER_DEPTH * np.cos(np.pi * d / (2 * RIVER_HALF))
                          ** 2, 0.0)
        return z - valley

    def true_height(self, b: Structure) -> float:
        """Top of the roof minus the mean terrain 0.5 m outside the outline."""
        t = np.linspace(-1, 1, 50)
        hl, hw = b.half_length + 0.5, b.half_width + 0.5
        uu = np.concatenate([t * hl, t * hl, np.full(50, hl), np.full(50, -hl)])
        vv = np.concatenate([np.full(50, hw), np.full(50, -hw), t * hw, t * hw])
        c, s = math.cos(b.angle), math.sin(b.angle)
        g = self.terrain(b.cx + uu * c - vv * s, b.cy + uu * s + vv * c).mean()
        return float(b.base + b.top - g)

    def dimensions(self) -> Dict[str, np.ndarray]:
        """Per-point attributes for :func:`~..core.io.las.write_las` (point format 6)."""
        return {"classification": self.classification, "return_number": self.return_number,
                "number_of_returns": self.number_of_returns, "intensity": self.intensity}


def _structures() -> Tuple[List[Structure], Structure]:
    ox, oy = ORIGIN
    b = [Structure("gabled", "gabled", ox + 40, oy + 40, 6.0, 4.0, math.radians(20), 5.0,
                   35.0),
         Structure("hipped", "hipped", ox + 40, oy + 110, 7.0, 5.0, math.radians(-15), 6.0,
                   30.0),
         Structure("flat with parapet", "flat", ox + 95, oy + 45, 10.0, 7.5,
                   math.radians(5), 9.0, 0.0, 1.0),
         Structure("shed under trees 1", "flat", ox + 95, oy + 115, 3.0, 2.0,
                   math.radians(10), 2.5),
         Structure("shed under trees 2", "flat", ox + 100, oy + 140, 2.5, 2.5, 0.0, 2.3)]
    bridge = Structure("footbridge", "bridge", ox + RIVER_U, oy + 80, 32.5, 1.5, 0.0, 0.3)
    return b, bridge


#: trees: (x, y, height, crown radius, crown base) relative to the origin
_TREES = np.array([
    [99.0, 119.5, 9.0, 3.5, 3.5],      # over shed 1 (north-east corner)
    [90.0, 111.0, 8.0, 3.0, 3.0],      # over shed 1 (south-west corner)
    [103.5, 143.5, 10.0, 3.5, 4.0],    # over shed 2
    [20.0, 140.0, 14.0, 4.5, 5.0], [60.0, 15.0, 12.0, 4.0, 4.0],
    [125.0, 20.0, 11.0, 4.0, 4.0], [185.0, 140.0, 15.0, 5.0, 5.0],
    [70.0, 80.0, 9.0, 3.0, 3.0]])


def city_scene(*, density: float = 2.0, seed: int = 0, penetration: float = 0.35,
               noise: float = 0.03) -> CityScene:
    """Generate the scene at ``density`` pulses per m² (see the module docstring)."""
    rng = np.random.default_rng([seed, int(density * 100)])
    ox, oy = ORIGIN
    w, h = EXTENT
    n = rng.poisson(density * w * h)
    px = np.round(ox + rng.uniform(0, w, n), 2)
    py = np.round(oy + rng.uniform(0, h, n), 2)
    ground = CityScene.terrain(px, py)
    blds, bridge = _structures()
    based = []
    for b in blds:   # each building stands on the highest terrain under it
        cu = np.linspace(-1, 1, 7)
        uu, vv = np.meshgrid(cu * b.half_length, cu * b.half_width)
        c, s = math.cos(b.angle), math.sin(b.angle)
        base = CityScene.terrain(b.cx + uu * c - vv * s, b.cy + uu * s + vv * c).max()
        based.append(Structure(**{**b.__dict__, "base": float(base)}))
    blds = based
    # the deck: straight between the terrain at its two ends, 0.3 m above it
    ends = CityScene.terrain(np.array([bridge.cx - bridge.half_length,
                                       bridge.cx + bridge.half_length]),
                             np.array([bridge.cy, bridge.cy]))
    # surface under the crowns: roof, deck or ground, and its class
    surf = ground.copy()
    scls = np.full(n, GROUND, np.uint8)
    for b in blds:
        m = b.inside(px, py)
        surf[m] = b.roof(px[m], py[m])
        scls[m] = BUILDING
    on_deck = bridge.inside(px, py)
    uu, _ = bridge.local(px[on_deck], py[on_deck])
    t = (uu + bridge.half_length) / (2 * bridge.half_length)
    surf[on_deck] = ends[0] + (ends[1] - ends[0]) * t + bridge.eave
    scls[on_deck] = BRIDGE
    water = (np.abs(px - ox - RIVER_U) < WATER_HALF) & ~on_deck
    wl = 100.0 + 0.01 * RIVER_U + 0.005 * (py - oy) - RIVER_DEPTH + 0.8
    surf[water] = wl[water]
    scls[water] = WATER
    keep_pulse = ~water | (rng.random(n) < 0.3)
    # crowns: first return in the crown, last return through it with the penetration
    crown_top = np.full(n, -np.inf)
    crown_bot = np.full(n, np.inf)
    for tx, ty, th, tr, tb in _TREES:
        d = np.hypot(px - ox - tx, py - oy - ty) / tr
        m = d < 1.0
        g = CityScene.terrain(ox + tx, oy + ty)
        top = g + tb + (th - tb) * np.sqrt(1 - d[m] ** 2)
        crown_top[m] = np.maximum(crown_top[m], top)
        crown_bot[m] = np.minimum(crown_bot[m], g + tb)
    hit = np.isfinite(crown_top) & (crown_top > surf + 0.5)
    xs, ys, zs, cs, rn, nr = [], [], [], [], [], []
    # pulses that miss every crown: one return on their surface
    one = keep_pulse & ~hit
    xs.append(px[one])
    ys.append(py[one])
    zs.append(surf[one] + rng.normal(0, noise, one.sum()))
    cs.append(scls[one])
    rn.append(np.ones(one.sum(), np.uint8))
    nr.append(np.ones(one.sum(), np.uint8))
    # crown pulses: 1-2 vegetation returns, then the surface with the penetration
    idx = np.flatnonzero(hit)
    nveg = rng.choice([1, 2], idx.size, p=[0.6, 0.4])
    pen = (rng.random(idx.size) < penetration) & ((scls[idx] != WATER) | (
        rng.random(idx.size) < 0.3))
    total = nveg + pen
    for k in (1, 2):
        m = nveg >= k
        depth = rng.exponential(0.4 * k, m.sum())
        z = np.maximum(crown_top[idx[m]] - depth, crown_bot[idx[m]])
        xs.append(px[idx[m]])
        ys.append(py[idx[m]])
        zs.append(z)
        cs.append(np.full(m.sum(), VEG, np.uint8))
        rn.append(np.full(m.sum(), k, np.uint8))
        nr.append(total[m].astype(np.uint8))
    m = pen
    xs.append(px[idx[m]])
    ys.append(py[idx[m]])
    zs.append(surf[idx[m]] + rng.normal(0, noise, m.sum()))
    cs.append(scls[idx[m]])
    rn.append((nveg[m] + 1).astype(np.uint8))
    nr.append(total[m].astype(np.uint8))
    # walls under the eaves (0.5 m inside the roof outline): a few points
    for b in blds:
        per = 4 * (b.half_length + b.half_width - 1.0)
        k = rng.poisson(0.05 * density * per * b.eave)
        t = rng.uniform(0, per, k)
        a, bb = b.half_length - 0.5, b.half_width - 0.5
        side = np.minimum((t // (per / 4)).astype(int), 3)
        f = (t % (per / 4)) / (per / 4) * 2 - 1
        u = np.choose(side, [f * a, np.full(k, a), f * a, np.full(k, -a)])
        v = np.choose(side, [np.full(k, -bb), f * bb, np.full(k, bb), f * bb])
        c, s = math.cos(b.angle), math.sin(b.angle)
        wx, wy = b.cx + u * c - v * s, b.cy + u * s + v * c
        xs.append(np.round(wx, 2))
        ys.append(np.round(wy, 2))
        zs.append(b.base + rng.uniform(0.2, b.eave - 0.3, k))
        cs.append(np.full(k, BUILDING, np.uint8))
        rn.append(np.ones(k, np.uint8))
        nr.append(np.ones(k, np.uint8))
    x, y, z = np.concatenate(xs), np.concatenate(ys), np.round(np.concatenate(zs), 2)
    cls = np.concatenate(cs)
    order = np.lexsort((x, np.floor((y - oy) / 2.0)))       # scan-line-like order
    inten = np.where(cls == VEG, 30000, np.where(cls == BUILDING, 18000, 21000))
    inten = (inten + rng.normal(0, 2000, cls.size)).clip(0, 65535).astype(np.uint16)
    return CityScene(x[order], y[order], z[order], cls[order],
                     np.concatenate(rn)[order], np.concatenate(nr)[order], inten[order],
                     blds, bridge, float(density), int(seed), _TREES.copy())


def write_scene(scene: CityScene, path, *, crs: str = "EPSG:32632") -> str:
    """Write the scene as LAS 1.4 / point format 6 (``.laz`` compressed)."""
    from ..core.io.las import write_las
    write_las(path, scene.x, scene.y, scene.z, dimensions=scene.dimensions(), crs=crs,
              point_format=6, version="1.4", scale=0.01)
    return str(path)

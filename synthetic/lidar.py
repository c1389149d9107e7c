"""Synthetic, labelled airborne LiDAR tiles (Qt-free, vectorised, deterministic).

Quick API
=========

```python
from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile

tile = generate_tile(extent=(300, 300), density=5.0, seed=1)  # ~450 000 points
tile.x, tile.y, tile.z             # float64 (m), already rounded to the 1 cm LAS grid
tile.classification                # uint8 ASPRS: 2 ground, 5 high vegetation,
                                   #   6 building, 7 low noise, 18 high noise
tile.return_number                 # uint8, 1..number_of_returns
tile.number_of_returns             # uint8, 1..5
tile.intensity                     # uint16
tile.gps_time                      # float64 s (points are in acquisition order)
tile.scan_angle                    # float32 degrees (across track)
tile.point_source_id               # uint16 flight line id
tile.terrain(x, y)                 # TRUE bare-earth height at any x, y (arrays)
tile.terrain.slope_deg(x, y)       # true terrain slope (degrees)
tile.open_ground(x, y)             # bool: clear of buildings, crowns and the cliff
cp = tile.checkpoints(n=62)        # CheckPoints(id, x, y, z): "GNSS" check points
write_tile(tile, "out/demo.laz", crs="EPSG:32632")   # LAS 1.4, point format 6
```

Constants ``GROUND, HIGH_VEGETATION, BUILDING, LOW_NOISE, HIGH_NOISE`` name the
classes; ``NOISE_CLASSES = (7, 18)``. ``tile.buildings`` and ``tile.trees`` hold the
object parameters (footprints, roof types, crown sizes) for finer checks.
``len(tile)`` is the point count; ``tile.dimensions()`` returns the per-point
attributes as a dict ready for :func:`~.las_io.write_las`.

Scene design
============

The scene combines the situations that the ISPRS filter test (Sithole & Vosselman
2004, *Experimental comparison of filter algorithms for bare-Earth extraction from
airborne laser scanning point clouds*, ISPRS J. 59(1–2)) showed to be hard for
ground filters:

* **rolling terrain** with a regional tilt (a few superimposed waves, ``relief``);
* a **steep hillside** (``hill_height`` over a band whose maximum slope is
  ``hill_slope_deg``) with a forest patch on it — "vegetation on slopes";
* a **terrace step / cliff** (``cliff_height`` over about 1 m, i.e. a near-vertical
  discontinuity) — the "discontinuity" scenes;
* **buildings of several sizes**: houses 8–15 m (mostly gabled), medium blocks
  15–40 m (flat or gabled) and large halls 60–100 m long (flat roofs, which defeat
  small filter windows); buildings stand on the highest terrain of their footprint
  ("buildings on slopes"); walls are almost unsampled, as in ALS, with a few wall
  points;
* **trees** (conifers with conical and broadleaves with ellipsoidal crowns) in
  forest patches and scattered, with **partial canopy penetration**: a pulse that
  hits a crown gives 1–4 vegetation returns and, with a probability that grows
  towards the crown edge (``canopy_penetration``), a last return on the ground;
* a few **low outliers** (class 7, metres below ground — multipath) and a few
  **high noise** points (class 18, birds/atmosphere).

Points are a Poisson process in plan (pulse positions) thinned so that the mean
density of *all* returns equals ``density``; flight lines run north–south, which
sets ``gps_time``, ``scan_angle`` and ``point_source_id``. Coordinates are rounded
to the 1 cm LAS grid (``scale``) *before* heights are computed, so ground points
satisfy ``z == terrain(x, y) + N(0, noise)`` exactly in memory and in the file.

Everything is vectorised: pulses are generated cell by cell already in spatial
order, and buildings and crowns find their pulses through row ranges of that
order, so the only Python loops run over objects (buildings, batches of trees),
never over points. 10 M points take a few seconds.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Dict, Optional, Tuple

import numpy as np

GROUND = 2
HIGH_VEGETATION = 5
BUILDING = 6
LOW_NOISE = 7
HIGH_NOISE = 18
NOISE_CLASSES = (LOW_NOISE, HIGH_NOISE)

# pulse kinds (internal)
_K_GROUND, _K_ROOF, _K_TREE, _K_WALL, _K_LOW, _K_HIGH = 0, 1, 2, 3, 4, 5

_FLIGHT_ALTITUDE = 1000.0   # m above ground, sets the scan angles
_SPEED = 60.0               # m/s
_LINE_SPACING = 400.0       # m between north-south flight lines
_GPS_T0 = 3.3e8             # adjusted standard GPS time of the first line (s)
_PAIR_BATCH = 4_000_000     # candidate (object, point) pairs per batch (memory bound)


# --------------------------------------------------------------------------- terrain
@dataclass(frozen=True, eq=False)
class Terrain:
    """The true bare-earth surface of a tile: ``terrain(x, y) -> z``.

    Defined everywhere (also outside the tile), smooth except for the cliff, which
    rises ``cliff_height`` over ``cliff_width`` metres (a smoothstep), and fully
    vectorised. Built by :func:`generate_tile`; use it to check a DTM.

    Attributes
    ----------
    origin : tuple of float
        Lower-left corner of the tile (x0, y0).
    base : float
        Height at the origin before relief (m).
    tilt : tuple of float
        Regional gradient (dz/dx, dz/dy).
    waves : ndarray, shape (k, 4)
        Rolling relief: rows (kx, ky, amplitude, phase) of ``a·sin(kx·u + ky·v + φ)``.
    hill : tuple of float
        (nx, ny, d0, height, width): ``height·(1 + tanh((n·p − d0)/width))/2``.
    cliff : tuple of float
        (nx, ny, d0, height, width): ``height·smoothstep((n·p − d0)/width + ½)``.
    """

    origin: Tuple[float, float]
    base: float
    tilt: Tuple[float, float]
    waves: np.ndarray
    hill: Tuple[float, float, float, float, float]
    cliff: Tuple[float, float, float, float, float]

    def _local(self, x, y):
        return (np.asarray(x, dtype=np.float64) - self.origin[0],
                np.asarray(y, dtype=np.float64) - self.origin[1])

    def __call__(self, x, y) -> np.ndarray:
        """True terrain height at ``x, y`` (arrays or scalars, CRS units)."""
        u, v = self._local(x, y)
        z = self.base + self.tilt[0] * u + self.tilt[1] * v
        for kx, ky, amp, phase in self.waves:
            z = z + amp * np.sin(kx * u + ky * v + phase)
        nx, ny, d0, h, w = self.hill
        if h:
            z = z + 0.5 * h * (1.0 + np.tanh((nx * u + ny * v - d0) / w))
        nx, ny, d0, h, w = self.cliff
        if h:
            s = np.clip((nx * u + ny * v - d0) / w + 0.5, 0.0, 1.0)
            z = z + h * s * s * (3.0 - 2.0 * s)
        return z

    def cliff_distance(self, x, y) -> np.ndarray:
        """Signed horizontal distance (m) from the centre line of the cliff."""
        u, v = self._local(x, y)
        nx, ny, d0, _h, _w = self.cliff
        return nx * u + ny * v - d0

    def hill_distance(self, x, y) -> np.ndarray:
        """Signed horizontal distance (m) from the middle of the steep hillside."""
        u, v = self._local(x, y)
        nx, ny, d0, _h, _w = self.hill
        return nx * u + ny * v - d0

    def gradient(self, x, y, *, h: float = 0.02) -> Tuple[np.ndarray, np.ndarray]:
        """Numerical gradient (dz/dx, dz/dy) by central differences of step ``h``."""
        x = np.asarray(x, dtype=np.float64)
        y = np.asarray(y, dtype=np.float64)
        gx = (self(x + h, y) - self(x - h, y)) / (2 * h)
        gy = (self(x, y + h) - self(x, y - h)) / (2 * h)
        return gx, gy

    def slope_deg(self, x, y, *, h: float = 0.02) -> np.ndarray:
        """True terrain slope in degrees at ``x, y``."""
        gx, gy = self.gradient(x, y, h=h)
        return np.degrees(np.arctan(np.hypot(gx, gy)))


# --------------------------------------------------------------------------- objects
@dataclass(frozen=True, eq=False)
class Buildings:
    """Rectangular buildings (one entry per building, all arrays of equal length).

    ``cx, cy`` centre; ``half_length`` (along the ridge, local u axis) and
    ``half_width``; ``angle`` of the u axis (radians from +x); ``base`` the terrain
    height the building stands on (max over its footprint); ``eave`` the wall height
    above ``base``; ``pitch`` roof pitch in degrees (0 for flat roofs); ``kind`` 0
    house, 1 medium, 2 hall.
    """

    cx: np.ndarray
    cy: np.ndarray
    half_length: np.ndarray
    half_width: np.ndarray
    angle: np.ndarray
    base: np.ndarray
    eave: np.ndarray
    pitch: np.ndarray
    kind: np.ndarray

    def __len__(self) -> int:
        return int(self.cx.size)

    @property
    def gabled(self) -> np.ndarray:
        """True for gabled roofs."""
        return self.pitch > 0

    def local(self, i, x, y) -> Tuple[np.ndarray, np.ndarray]:
        """Coordinates (u along the ridge, v across) of ``x, y`` in building(s) ``i``."""
        dx = x - self.cx[i]
        dy = y - self.cy[i]
        c, s = np.cos(self.angle[i]), np.sin(self.angle[i])
        return dx * c + dy * s, -dx * s + dy * c

    def roof_z(self, i, x, y) -> np.ndarray:
        """Roof height of building(s) ``i`` at ``x, y`` (no footprint test)."""
        _u, v = self.local(i, x, y)
        rise = np.clip(self.half_width[i] - np.abs(v), 0, None) * np.tan(
            np.radians(self.pitch[i]))
        return self.base[i] + self.eave[i] + rise

    def distance(self, x, y) -> np.ndarray:
        """Horizontal distance from each point to the nearest footprint (0 inside).

        Returns an array of shape ``(len(x),)``; evaluated in blocks of points.
        """
        x = np.atleast_1d(np.asarray(x, dtype=np.float64))
        y = np.atleast_1d(np.asarray(y, dtype=np.float64))
        out = np.full(x.shape, np.inf)
        if not len(self):
            return out
        step = max(1, 2_000_000 // len(self))
        for s in range(0, x.size, step):
            u, v = self.local(slice(None), x[s:s + step, None], y[s:s + step, None])
            du = np.clip(np.abs(u) - self.half_length, 0, None)
            dv = np.clip(np.abs(v) - self.half_width, 0, None)
            out[s:s + step] = np.hypot(du, dv).min(axis=1)
        return out

    def corners(self) -> np.ndarray:
        """Footprint corners, shape ``(n, 4, 2)`` (x, y), counter-clockwise."""
        su = np.array([1, -1, -1, 1])[None, :]
        sv = np.array([1, 1, -1, -1])[None, :]
        u = su * self.half_length[:, None]
        v = sv * self.half_width[:, None]
        c, s = np.cos(self.angle)[:, None], np.sin(self.angle)[:, None]
        return np.stack([self.cx[:, None] + u * c - v * s,
                         self.cy[:, None] + u * s + v * c], axis=-1)


@dataclass(frozen=True, eq=False)
class Trees:
    """Trees (arrays of equal length).

    ``cx, cy`` stem position; ``height`` tree height and ``crown_base`` height of the
    crown bottom, both above the local ground; ``radius`` crown radius; ``conifer``
    True for a conical crown, False for an ellipsoidal one. Crowns follow the local
    terrain (heights are above the ground under each point).
    """

    cx: np.ndarray
    cy: np.ndarray
    height: np.ndarray
    crown_base: np.ndarray
    radius: np.ndarray
    conifer: np.ndarray

    def __len__(self) -> int:
        return int(self.cx.size)

    def crown_top(self, i, rho) -> np.ndarray:
        """Height above ground of the crown surface of tree(s) ``i`` at ``rho = r/R``."""
        h, hb = self.height[i], self.crown_base[i]
        rho = np.clip(rho, 0.0, 1.0)
        cone = h - (h - hb) * rho
        half = 0.5 * (h - hb)
        ell = hb + half + half * np.sqrt(1.0 - rho * rho)
        return np.where(self.conifer[i], cone, ell)

    def crown_bottom(self, i, rho) -> np.ndarray:
        """Height above ground of the crown underside of tree(s) ``i`` at ``rho``."""
        h, hb = self.height[i], self.crown_base[i]
        rho = np.clip(rho, 0.0, 1.0)
        half = 0.5 * (h - hb)
        ell = hb + half - half * np.sqrt(1.0 - rho * rho)
        return np.where(self.conifer[i], hb, ell)

    def distance(self, x, y) -> np.ndarray:
        """Horizontal distance from each point to the nearest crown edge (0 inside)."""
        x = np.atleast_1d(np.asarray(x, dtype=np.float64))
        y = np.atleast_1d(np.asarray(y, dtype=np.float64))
        out = np.full(x.shape, np.inf)
        if not len(self):
            return out
        step = max(1, 2_000_000 // len(self))
        for s in range(0, x.size, step):
            d = np.hypot(x[s:s + step, None] - self.cx, y[s:s + step, None] - self.cy)
            out[s:s + step] = np.clip(d - self.radius, 0, None).min(axis=1)
        return out


@dataclass(frozen=True, eq=False)
class CheckPoints:
    """Check points with their true terrain height (like GNSS check points)."""

    id: np.ndarray
    x: np.ndarray
    y: np.ndarray
    z: np.ndarray

    def __len__(self) -> int:
        return int(self.x.size)

    def to_csv(self, path, *, xy_decimals: int = 3, z_decimals: int = 4, extra=()) -> str:
        """Write ``id,x,y,z`` (header line, one point per line, ``extra`` rows of
        ``(id, x, y, z)`` appended) and return the path as a string."""
        rows = [(int(i), x, y, z) for i, x, y, z in zip(self.id, self.x, self.y, self.z)]
        with open(path, "w", encoding="utf-8", newline="\n") as fh:
            fh.write("id,x,y,z\n")
            for i, x, y, z in [*rows, *extra]:
                fh.write(f"{i},{x:.{xy_decimals}f},{y:.{xy_decimals}f},{z:.{z_decimals}f}\n")
        return str(path)


# --------------------------------------------------------------------------- tile
@dataclass(eq=False)
class SyntheticTile:
    """A generated tile: per-point arrays, the true terrain and the scene objects.

    Per-point arrays (all of length ``len(tile)``, in acquisition order):
    ``x, y, z`` (float64), ``classification`` (uint8), ``return_number``,
    ``number_of_returns`` (uint8), ``intensity`` (uint16), ``gps_time`` (float64),
    ``scan_angle`` (float32, degrees), ``point_source_id`` (uint16).
    """

    x: np.ndarray
    y: np.ndarray
    z: np.ndarray
    classification: np.ndarray
    return_number: np.ndarray
    number_of_returns: np.ndarray
    intensity: np.ndarray
    gps_time: np.ndarray
    scan_angle: np.ndarray
    point_source_id: np.ndarray
    terrain: Terrain
    buildings: Buildings
    trees: Trees
    origin: Tuple[float, float]
    extent: Tuple[float, float]
    density: float
    seed: int
    noise: float
    scale: float = 0.01
    params: Dict[str, object] = field(default_factory=dict)

    def __len__(self) -> int:
        return int(self.x.size)

    @property
    def bounds(self) -> Tuple[float, float, float, float]:
        """(xmin, ymin, xmax, ymax) of the tile (not of the points)."""
        x0, y0 = self.origin
        return x0, y0, x0 + self.extent[0], y0 + self.extent[1]

    @property
    def area(self) -> float:
        """Tile area in m²."""
        return float(self.extent[0] * self.extent[1])

    def dimensions(self) -> Dict[str, np.ndarray]:
        """Per-point attributes keyed by laspy dimension name (point format 6)."""
        return {
            "classification": self.classification,
            "return_number": self.return_number,
            "number_of_returns": self.number_of_returns,
            "intensity": self.intensity,
            "gps_time": self.gps_time,
            # point formats 6-10 store the scan angle in 0.006° steps
            "scan_angle": np.round(self.scan_angle / 0.006).astype(np.int16),
            "point_source_id": self.point_source_id,
        }

    def open_ground(self, x, y, *, clearance: float = 3.0,
                    cliff_clearance: float = 5.0, max_slope_deg: Optional[float] = None,
                    margin: float = 0.0) -> np.ndarray:
        """True where ``x, y`` is open ground.

        Open ground is at least ``clearance`` m from every building footprint and
        crown edge, ``cliff_clearance`` m from the cliff line, inside the tile by
        ``margin`` m and, if ``max_slope_deg`` is given, not steeper than that.
        """
        x = np.atleast_1d(np.asarray(x, dtype=np.float64))
        y = np.atleast_1d(np.asarray(y, dtype=np.float64))
        x0, y0, x1, y1 = self.bounds
        ok = (x >= x0 + margin) & (x <= x1 - margin) & (y >= y0 + margin) & (y <= y1 - margin)
        if self.terrain.cliff[3]:
            ok &= np.abs(self.terrain.cliff_distance(x, y)) >= cliff_clearance
        if max_slope_deg is not None:
            ok &= self.terrain.slope_deg(x, y) <= max_slope_deg
        idx = np.flatnonzero(ok)
        if idx.size:
            keep = self.buildings.distance(x[idx], y[idx]) >= clearance
            idx = idx[keep]
            keep = self.trees.distance(x[idx], y[idx]) >= clearance
            ok[:] = False
            ok[idx[keep]] = True
        return ok

    def checkpoints(self, n: int = 62, *, seed: Optional[int] = None,
                    clearance: float = 3.0, max_slope_deg: float = 15.0,
                    margin: float = 10.0, min_spacing: Optional[float] = None) -> CheckPoints:
        """Check points on open ground with their true terrain height.

        Mimics a GNSS check-point survey: points spread over the tile (at least
        ``min_spacing`` m apart, default ``0.4·sqrt(area/n)``), on open ground (see
        :meth:`open_ground`) of gentle slope. Deterministic for a given tile and
        ``seed`` (default: the tile's seed).

        Returns
        -------
        CheckPoints
            ``id`` (1..n), ``x``, ``y`` (rounded to 1 cm) and the true ``z``.

        Raises
        ------
        ValueError
            If fewer than ``n`` such points can be found.
        """
        if n < 1:
            raise ValueError(f"n must be at least 1, got {n}")
        rng = np.random.default_rng([self.seed if seed is None else seed, 7_919])
        spacing = 0.4 * math.sqrt(self.area / n) if min_spacing is None else min_spacing
        x0, y0, x1, y1 = self.bounds
        cand_n = max(50 * n, 2000)
        cx = np.round(rng.uniform(x0, x1, cand_n), 2)
        cy = np.round(rng.uniform(y0, y1, cand_n), 2)
        ok = self.open_ground(cx, cy, clearance=clearance, max_slope_deg=max_slope_deg,
                              margin=margin)
        cx, cy = cx[ok], cy[ok]
        chosen = []
        for i in range(cx.size):        # greedy thinning over candidates, not points
            if chosen:
                sel = np.asarray(chosen)
                if np.min(np.hypot(cx[sel] - cx[i], cy[sel] - cy[i])) < spacing:
                    continue
            chosen.append(i)
            if len(chosen) == n:
                break
        if len(chosen) < n:
            raise ValueError(
                f"Only {len(chosen)} of {n} check points fit on open ground "
                f"(clearance {clearance} m, spacing {spacing:.1f} m); lower n, "
                "clearance or min_spacing, or use a larger tile.")
        sel = np.asarray(chosen)
        x, y = cx[sel], cy[sel]
        return CheckPoints(np.arange(1, n + 1), x, y, self.terrain(x, y))


# --------------------------------------------------------------------------- helpers
def _concat_ranges(lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """Concatenation of ``arange(lo[i], hi[i])`` for all i, without a Python loop."""
    n = hi - lo
    total = int(n.sum())
    if total == 0:
        return np.empty(0, np.int64)
    offsets = np.cumsum(n) - n
    return np.arange(total, dtype=np.int64) + np.repeat(lo - offsets, n)


@dataclass
class _Grid:
    """Pulses ordered by cell (rows of ``hr`` m, columns of ``wc`` m)."""

    ncx: int
    nry: int
    wc: float
    hr: float
    starts: np.ndarray   # len ncx*nry + 1, first pulse of each cell

    def pairs(self, x0, x1, y0, y1):
        """Candidate (object, pulse index) row ranges for local bounding boxes.

        Yields ``(obj, idx)`` batches of at most about ``_PAIR_BATCH`` pairs.
        """
        ix0 = np.clip(np.floor(x0 / self.wc).astype(np.int64), 0, self.ncx - 1)
        ix1 = np.clip(np.floor(x1 / self.wc).astype(np.int64), 0, self.ncx - 1)
        iy0 = np.clip(np.floor(y0 / self.hr).astype(np.int64), 0, self.nry - 1)
        iy1 = np.clip(np.floor(y1 / self.hr).astype(np.int64), 0, self.nry - 1)
        valid = (x1 >= 0) & (y1 >= 0) & (x0 <= self.ncx * self.wc) & (y0 <= self.nry * self.hr)
        nrows = np.where(valid, iy1 - iy0 + 1, 0)
        obj = np.repeat(np.arange(x0.size), nrows)
        offs = np.cumsum(nrows) - nrows
        row = iy0[obj] + np.arange(obj.size) - np.repeat(offs, nrows)
        lo = self.starts[row * self.ncx + ix0[obj]]
        hi = self.starts[row * self.ncx + ix1[obj] + 1]
        cum = np.cumsum(hi - lo)
        cuts = np.searchsorted(cum, np.arange(_PAIR_BATCH, cum[-1] if cum.size else 0,
                                              _PAIR_BATCH), side="right")
        bounds = np.concatenate([[0], cuts, [obj.size]]).astype(np.int64)
        for a, b in zip(bounds[:-1], bounds[1:]):
            if b > a:
                idx = _concat_ranges(lo[a:b], hi[a:b])
                yield np.repeat(obj[a:b], hi[a:b] - lo[a:b]), idx


def _poisson_pulses(rng, width, height, rate):
    """Poisson pulse positions (local coordinates), generated in cell order."""
    per_cell = 6.0
    wc = math.sqrt(per_cell / rate / 2.0)
    ncx = max(1, int(math.ceil(width / wc)))
    nry = max(1, int(math.ceil(height / (2.0 * wc))))
    wc, hr = width / ncx, height / nry
    counts = rng.poisson(rate * wc * hr, size=ncx * nry)
    starts = np.zeros(counts.size + 1, np.int64)
    np.cumsum(counts, out=starts[1:])
    cell = np.repeat(np.arange(counts.size, dtype=np.int64), counts)
    x = (cell % ncx + rng.random(cell.size)) * wc
    y = (cell // ncx + rng.random(cell.size)) * hr
    return x, y, _Grid(ncx, nry, wc, hr, starts)


def _make_terrain(rng, origin, width, height, *, base_height, relief, hill_height,
                  hill_slope_deg, cliff_height) -> Terrain:
    size = max(width, height)
    # rolling relief: waves of 0.25..1.5 tile sizes; total amplitude relief/2
    k = 6
    lam = size * rng.uniform(0.25, 1.5, k)
    theta = rng.uniform(0, 2 * np.pi, k)
    amp = lam / lam.sum() * (relief / 2.0)
    waves = np.column_stack([2 * np.pi / lam * np.cos(theta),
                             2 * np.pi / lam * np.sin(theta),
                             amp, rng.uniform(0, 2 * np.pi, k)])
    tilt = tuple(rng.uniform(-0.015, 0.015, 2))
    # steep hillside: a tanh ramp across a band near one side of the tile
    a = rng.uniform(0, 2 * np.pi)
    nx, ny = math.cos(a), math.sin(a)
    centre_d = nx * width / 2 + ny * height / 2
    half_span = 0.5 * (abs(nx) * width + abs(ny) * height)
    d0 = centre_d + rng.choice([-1, 1]) * rng.uniform(0.2, 0.35) * 2 * half_span
    hill_w = (hill_height / (2.0 * math.tan(math.radians(hill_slope_deg)))
              if hill_height else 1.0)
    hill = (nx, ny, d0, float(hill_height), hill_w)
    # cliff (terrace step) through the middle third, not parallel to the hillside
    b = a + rng.uniform(0.35, 0.65) * np.pi * rng.choice([-1, 1])
    cnx, cny = math.cos(b), math.sin(b)
    px, py = rng.uniform(0.35, 0.65) * width, rng.uniform(0.35, 0.65) * height
    cliff = (cnx, cny, cnx * px + cny * py, float(cliff_height), 1.0)
    return Terrain(tuple(map(float, origin)), float(base_height),
                   (float(tilt[0]), float(tilt[1])), waves, hill, cliff)


def _place_buildings(rng, terrain, origin, width, height, n_houses, n_medium,
                     n_halls) -> Buildings:
    ox, oy = origin
    specs = [(2, n_halls), (1, n_medium), (0, n_houses)]
    rows = []                               # (cx, cy, a, b, ang, eave, pitch, kind)
    circles = []                            # (cx, cy, r) for overlap tests
    for kind, count in specs:               # loop over buildings, not points
        for _ in range(count):
            if kind == 2:
                length = rng.uniform(60, 100)
                wid = rng.uniform(25, 45)
                eave = rng.uniform(8, 12)
                pitch = 0.0
            elif kind == 1:
                length = rng.uniform(15, 40)
                wid = rng.uniform(10, min(20, length))
                eave = rng.uniform(6, 15)
                pitch = rng.uniform(20, 35) if rng.random() < 0.5 else 0.0
            else:
                length = rng.uniform(8, 15)
                wid = length * rng.uniform(0.6, 1.0)
                eave = rng.uniform(3, 6)
                pitch = rng.uniform(25, 45) if rng.random() < 0.75 else 0.0
            a, b = length / 2, wid / 2
            r = math.hypot(a, b)
            for _attempt in range(300):
                cx = rng.uniform(r + 2, width - r - 2) if width > 2 * r + 4 else None
                cy = rng.uniform(r + 2, height - r - 2) if height > 2 * r + 4 else None
                ang = rng.uniform(0, np.pi)
                if cx is None or cy is None:
                    break
                if circles:
                    c = np.asarray(circles)
                    if np.any(np.hypot(c[:, 0] - cx, c[:, 1] - cy) < c[:, 2] + r + 4):
                        continue
                if terrain.cliff[3]:
                    d = terrain.cliff_distance(ox + cx, oy + cy)
                    if abs(d) < r + 3:
                        continue
                rows.append((cx, cy, a, b, ang, eave, pitch, kind))
                circles.append((cx, cy, r))
                break
    if not rows:
        empty = np.empty(0)
        return Buildings(empty, empty, empty, empty, empty, empty, empty, empty,
                         np.empty(0, np.int8))
    arr = np.asarray(rows, dtype=np.float64)
    cx, cy = arr[:, 0] + ox, arr[:, 1] + oy
    a, b, ang = arr[:, 2], arr[:, 3], arr[:, 4]
    # base: highest terrain over a 7 x 7 grid of the footprint
    g = np.linspace(-1, 1, 7)
    gu, gv = np.meshgrid(g, g)
    gu, gv = gu.ravel()[None, :] * a[:, None], gv.ravel()[None, :] * b[:, None]
    c, s = np.cos(ang)[:, None], np.sin(ang)[:, None]
    base = terrain(cx[:, None] + gu * c - gv * s, cy[:, None] + gu * s + gv * c).max(axis=1)
    return Buildings(cx, cy, a, b, ang, base, arr[:, 5], arr[:, 6],
                     arr[:, 7].astype(np.int8))


def _crown_cover_curve(x, y, radius, origin, width, height) -> np.ndarray:
    """Fraction of the tile under the union of the first k crowns, for k = 1..n.

    Crowns are rasterised on a grid of about 1 m (at most ~4 M cells); each cell
    remembers the first crown covering it, so the whole curve costs one pass.
    """
    cell = max(1.0, math.sqrt(width * height / 4e6))
    ncx, ncy = max(1, int(math.ceil(width / cell))), max(1, int(math.ceil(height / cell)))
    lx, ly = x - origin[0], y - origin[1]
    ix0 = np.clip(np.floor((lx - radius) / cell).astype(np.int64), 0, ncx - 1)
    ix1 = np.clip(np.floor((lx + radius) / cell).astype(np.int64), 0, ncx - 1)
    iy0 = np.clip(np.floor((ly - radius) / cell).astype(np.int64), 0, ncy - 1)
    iy1 = np.clip(np.floor((ly + radius) / cell).astype(np.int64), 0, ncy - 1)
    nx, ny = ix1 - ix0 + 1, iy1 - iy0 + 1
    first = np.full(ncx * ncy, x.size, np.int64)
    per = nx * ny
    # in batches of trees so the (tree, cell) pairs stay below ~8 M
    cum = np.cumsum(per)
    cuts = np.searchsorted(cum, np.arange(8_000_000, cum[-1] if cum.size else 0, 8_000_000))
    for a, b in zip(np.r_[0, cuts], np.r_[cuts, x.size]):
        if b <= a:
            continue
        t = np.repeat(np.arange(a, b), per[a:b])
        j = np.arange(t.size) - np.repeat(np.cumsum(per[a:b]) - per[a:b], per[a:b])
        cx = ix0[t] + j % nx[t]
        cy = iy0[t] + j // nx[t]
        inside = np.hypot((cx + 0.5) * cell - lx[t], (cy + 0.5) * cell - ly[t]) <= radius[t]
        np.minimum.at(first, cy[inside] * ncx + cx[inside], t[inside])
    counts = np.bincount(first[first < x.size], minlength=x.size)
    return np.cumsum(counts) / float(ncx * ncy)


def _place_trees(rng, terrain, buildings, origin, width, height, tree_cover,
                 n_trees) -> Tuple[Trees, float]:
    """Trees in forest patches (one on the hillside) and scattered; (trees, cover)."""
    ox, oy = origin
    area = width * height
    e = np.empty(0)
    none = Trees(e, e, e, e, e, np.empty(0, bool)), 0.0
    if n_trees is None:
        if tree_cover <= 0:
            return none
        mean_area = np.pi * 10.5                   # E[R^2] of the crown radii below
        m = int(tree_cover * area / mean_area * (3.0 + 8.0 * tree_cover)) + 50
    elif n_trees <= 0:
        return none
    else:
        m = int(n_trees * 1.8) + 20
    # forest patches (one on the steep hillside) plus scattered trees
    n_patch = max(1, int(round(area / 40_000)))
    pc = np.column_stack([rng.uniform(0, width, n_patch), rng.uniform(0, height, n_patch)])
    nx, ny, d0, hh, _w = terrain.hill
    if hh:
        # move the first patch onto the hillside: project onto the line n·p = d0
        t = d0 - (nx * pc[0, 0] + ny * pc[0, 1])
        pc[0] = np.clip(pc[0] + t * np.array([nx, ny]), 0, [width, height])
    sigma = max(15.0, 0.12 * math.sqrt(area))
    which = rng.integers(0, n_patch, m)
    clustered = rng.random(m) < 0.75 - 0.6 * max(0.0, tree_cover - 0.3)
    x = np.where(clustered, pc[which, 0] + rng.normal(0, sigma, m), rng.uniform(0, width, m))
    y = np.where(clustered, pc[which, 1] + rng.normal(0, sigma, m), rng.uniform(0, height, m))
    conifer = rng.random(m) < 0.5
    h = rng.uniform(6, 25, m)
    radius = np.clip(h * rng.uniform(0.15, 0.25, m), 1.5, 6.0)
    crown_base = h * np.where(conifer, rng.uniform(0.15, 0.35, m), rng.uniform(0.3, 0.5, m))
    inside = (x >= 0) & (x <= width) & (y >= 0) & (y <= height)
    x, y = x + ox, y + oy
    ok = inside.copy()
    if terrain.cliff[3]:
        ok &= np.abs(terrain.cliff_distance(x, y)) > radius + 1.5
    idx = np.flatnonzero(ok)
    if len(buildings) and idx.size:
        keep = buildings.distance(x[idx], y[idx]) > radius[idx] + 1.5
        idx = idx[keep]
    if not idx.size:
        return none
    curve = _crown_cover_curve(x[idx], y[idx], radius[idx], origin, width, height)
    if n_trees is None:        # as many trees as it takes to reach the cover
        k = min(idx.size, int(np.searchsorted(curve, tree_cover)) + 1)
    else:
        k = min(idx.size, n_trees)
    idx = idx[:k]
    trees = Trees(x[idx], y[idx], h[idx], crown_base[idx], radius[idx], conifer[idx])
    return trees, float(curve[k - 1])


# --------------------------------------------------------------------------- main
def generate_tile(*, extent: Tuple[float, float] = (300.0, 300.0),
                  origin: Tuple[float, float] = (500_000.0, 4_000_000.0),
                  density: float = 5.0, seed: int = 0,
                  n_buildings: Optional[int] = None, n_halls: Optional[int] = None,
                  tree_cover: float = 0.25, n_trees: Optional[int] = None,
                  canopy_penetration: float = 0.4, base_height: float = 200.0,
                  relief: float = 12.0, hill_height: float = 25.0,
                  hill_slope_deg: float = 35.0, cliff_height: float = 5.0,
                  noise: float = 0.05, n_low_outliers: Optional[int] = None,
                  n_high_noise: Optional[int] = None, wall_fraction: float = 0.05,
                  scale: float = 0.01) -> SyntheticTile:
    """Generate a deterministic, labelled airborne LiDAR tile.

    The scene follows the scene types of the ISPRS filter test (Sithole &
    Vosselman 2004): rolling terrain, a steep forested hillside, a terrace step
    (cliff), buildings from small houses to 100 m halls, trees with partial canopy
    penetration and a few low outliers and high noise points — with the ASPRS
    class of every point as ground truth (see the module docstring).

    Parameters
    ----------
    extent : (float, float)
        Width (x) and height (y) of the tile in metres.
    origin : (float, float)
        Lower-left corner in CRS units (default a UTM-like 500000, 4000000).
    density : float
        Mean density of all returns, points per m² (e.g. 0.5–20).
    seed : int
        Seed of the ``numpy.random.Generator``; equal seeds give identical tiles.
    n_buildings : int, optional
        Houses plus medium buildings (default about 1.5 per hectare, 85 % houses).
    n_halls : int, optional
        Large halls 60–100 m long (default one per 9 ha; at least one when the
        tile is at least 140 m on each side).
    tree_cover : float
        Target fraction of the tile under tree crowns (0–0.8); ignored when
        ``n_trees`` is given.
    n_trees : int, optional
        Number of trees.
    canopy_penetration : float
        Mean probability (0–1) that a pulse hitting a crown also returns from the
        ground; higher at the crown edge than at the stem.
    base_height : float
        Terrain height at the origin (m).
    relief : float
        Peak-to-peak amplitude of the rolling relief (m).
    hill_height, hill_slope_deg : float
        Height of the steep hillside (m; 0 disables it) and its maximum slope (°).
    cliff_height : float
        Height of the terrace step, rising over about 1 m (m; 0 disables it).
    noise : float
        Standard deviation of the height noise of ground points (m); roofs get
        0.6 × this, vegetation is rough by construction.
    n_low_outliers, n_high_noise : int, optional
        Number of class 7 points 1.5–15 m below ground and class 18 points
        40–250 m above it (default: 2e-5 of the points, at least 3 and 2 when
        the tile has 10 000 points or more).
    wall_fraction : float
        Wall points per m² of wall, as a fraction of ``density`` (walls are
        nearly unsampled in ALS).
    scale : float
        Coordinate resolution; x, y, z are rounded to it (the LAS scale).

    Returns
    -------
    SyntheticTile
        Points (in acquisition order), the true :class:`Terrain`, the
        :class:`Buildings` and :class:`Trees`.

    Raises
    ------
    ValueError
        For a non-positive extent or density, or parameters out of range.
    """
    width, height = (float(v) for v in extent)
    if not (width > 0 and height > 0 and math.isfinite(width * height)):
        raise ValueError(f"extent must be two positive sizes in metres, got {extent}")
    if not (density > 0 and math.isfinite(density)):
        raise ValueError(f"density must be a positive number of points per m², got {density}")
    if not 0 <= tree_cover <= 0.8:
        raise ValueError(f"tree_cover must be between 0 and 0.8, got {tree_cover}")
    if not 0 <= canopy_penetration <= 1:
        raise ValueError(f"canopy_penetration must be between 0 and 1, got {canopy_penetration}")
    if not 0 < hill_slope_deg < 85:
        raise ValueError(f"hill_slope_deg must be between 0 and 85, got {hill_slope_deg}")
    if noise < 0 or scale <= 0:
        raise ValueError("noise must be >= 0 and scale > 0")
    for name, val in (("n_buildings", n_buildings), ("n_halls", n_halls),
                      ("n_trees", n_trees), ("n_low_outliers", n_low_outliers),
                      ("n_high_noise", n_high_noise)):
        if val is not None and val < 0:
            raise ValueError(f"{name} must be >= 0, got {val}")

    rng = np.random.default_rng(seed)
    ox, oy = float(origin[0]), float(origin[1])
    area = width * height
    ha = area / 10_000.0
    target = density * area

    terrain = _make_terrain(rng, (ox, oy), width, height, base_height=base_height,
                            relief=relief, hill_height=hill_height,
                            hill_slope_deg=hill_slope_deg, cliff_height=cliff_height)
    if n_buildings is None:
        n_buildings = int(round(1.5 * ha))
    n_medium = int(round(0.15 * n_buildings))
    n_houses = n_buildings - n_medium
    if n_halls is None:
        n_halls = max(1 if min(width, height) >= 140 else 0, int(round(ha / 9.0)))
    buildings = _place_buildings(rng, terrain, (ox, oy), width, height, n_houses,
                                 n_medium, n_halls)
    trees, crown_frac = _place_trees(rng, terrain, buildings, (ox, oy), width, height,
                                     tree_cover, n_trees)

    # ---- pulses: Poisson in plan, over-generated then thinned to the density
    # expected returns per pulse from the crown cover; 3 % more pulses than needed
    mean_ret = 1.83 + min(0.97, canopy_penetration * 7.0 / 6.0)   # per crown pulse
    est = (1.0 + crown_frac * (mean_ret - 1.0)) / 1.03
    px, py, grid = _poisson_pulses(rng, width, height, density / est)
    npulse = px.size
    px = np.round((px + ox) / scale) * scale
    py = np.round((py + oy) / scale) * scale
    kind = np.zeros(npulse, np.int8)
    obj = np.full(npulse, -1, np.int32)

    if len(buildings):
        r = np.hypot(buildings.half_length, buildings.half_width) + 2 * scale
        lx, ly = buildings.cx - ox, buildings.cy - oy
        for o, idx in grid.pairs(lx - r, lx + r, ly - r, ly + r):
            u, v = buildings.local(o, px[idx], py[idx])
            inside = ((np.abs(u) <= buildings.half_length[o])
                      & (np.abs(v) <= buildings.half_width[o]))
            kind[idx[inside]] = _K_ROOF
            obj[idx[inside]] = o[inside]
    if len(trees):
        top_h = np.full(npulse, -np.inf)
        rr = trees.radius + 2 * scale
        lx, ly = trees.cx - ox, trees.cy - oy
        for o, idx in grid.pairs(lx - rr, lx + rr, ly - rr, ly + rr):
            rho = np.hypot(px[idx] - trees.cx[o], py[idx] - trees.cy[o]) / trees.radius[o]
            inside = (rho < 1.0) & (kind[idx] != _K_ROOF)
            o, idx, rho = o[inside], idx[inside], rho[inside]
            h = trees.crown_top(o, rho)
            np.maximum.at(top_h, idx, h)
            win = h >= top_h[idx]
            kind[idx[win]] = _K_TREE
            obj[idx[win]] = o[win]
        del top_h

    # ---- returns per pulse, then thinning of whole pulses to the target density
    is_tree = kind == _K_TREE
    n_veg = np.zeros(npulse, np.int8)
    pen = np.zeros(npulse, bool)
    t_idx = np.flatnonzero(is_tree)
    if t_idx.size:
        n_veg[t_idx] = rng.choice(np.array([1, 2, 3, 4], np.int8), size=t_idx.size,
                                  p=[0.45, 0.33, 0.16, 0.06])
        rho_t = np.hypot(px[t_idx] - trees.cx[obj[t_idx]],
                         py[t_idx] - trees.cy[obj[t_idx]]) / trees.radius[obj[t_idx]]
        p_pen = np.clip(canopy_penetration * (0.5 + rho_t), 0.0, 0.97)
        pen[t_idx] = rng.random(t_idx.size) < p_pen
    n_ret = np.where(is_tree, n_veg + pen, 1).astype(np.int8)

    # walls: a few points on the outlines (count from wall area)
    wx, wy, wz = _wall_points(rng, buildings, terrain, density * wall_fraction, scale)
    n_noise_default = max(0, int(round(2e-5 * target)))
    small = target < 10_000             # no forced outliers on toy tiles
    n_low = (max(0 if small else 3, n_noise_default) if n_low_outliers is None
             else int(n_low_outliers))
    n_high = (max(0 if small else 2, n_noise_default) if n_high_noise is None
              else int(n_high_noise))
    extra = wx.size + n_low + n_high
    total = int(n_ret.sum(dtype=np.int64))
    keep_p = min(1.0, max(0.0, target - extra) / total) if total else 1.0
    keep = rng.random(npulse) < keep_p
    px, py, kind, obj, n_veg, pen, n_ret = (a[keep] for a in
                                            (px, py, kind, obj, n_veg, pen, n_ret))

    # noise pulses
    lx = np.round((ox + rng.uniform(0, width, n_low + n_high)) / scale) * scale
    ly = np.round((oy + rng.uniform(0, height, n_low + n_high)) / scale) * scale
    px = np.concatenate([px, wx, lx])
    py = np.concatenate([py, wy, ly])
    kind = np.concatenate([kind, np.full(wx.size, _K_WALL, np.int8),
                           np.full(n_low, _K_LOW, np.int8), np.full(n_high, _K_HIGH, np.int8)])
    obj = np.concatenate([obj, np.full(extra, -1, np.int32)])
    n_veg = np.concatenate([n_veg, np.zeros(extra, np.int8)])
    pen = np.concatenate([pen, np.zeros(extra, bool)])
    n_ret = np.concatenate([n_ret, np.ones(extra, np.int8)])
    wall_z = wz

    # ---- acquisition: north-south flight lines (alternating direction) scanned in
    # zigzag scan lines across track -> point order, gps_time, scan angle, source id
    line = np.floor((px - ox) / _LINE_SPACING).astype(np.int64)
    xc = ox + (line + 0.5) * _LINE_SPACING
    along = np.where(line % 2 == 0, py - oy, oy + height - py)
    step = 1.0 / math.sqrt(density)                 # along-track scan-line spacing
    k = np.floor(along / step)
    across = np.clip(px - xc + _LINE_SPACING / 2, 0, _LINE_SPACING)
    across = np.where(k % 2 == 0, across, _LINE_SPACING - across)
    order = np.argsort((line * (height / step + 2) + k) * (_LINE_SPACING + 1) + across,
                       kind="stable")
    # wall points keep their z through the reordering
    pz_wall = np.full(px.size, np.nan)
    pz_wall[kind == _K_WALL] = wall_z
    px, py, kind, obj, n_veg, pen, n_ret, line, xc, pz_wall = (
        a[order] for a in (px, py, kind, obj, n_veg, pen, n_ret, line, xc, pz_wall))
    # pulses are emitted at a constant rate within a line
    first_of_line = np.searchsorted(line, line, side="left")
    n_in_line = np.bincount(line - line.min()) if line.size else np.zeros(1, np.int64)
    dt = (height / _SPEED) / np.maximum(n_in_line[line - line.min()], 1) if line.size else 0
    rank = np.arange(px.size) - first_of_line
    gps = _GPS_T0 + line * 900.0 + rank * dt
    del along, k, across, order, first_of_line, rank, dt
    scan = np.degrees(np.arctan((px - xc) / _FLIGHT_ALTITUDE)).astype(np.float32)

    # ---- expand pulses to returns
    npulse = px.size
    ground_at_pulse = terrain(px, py)
    cum = np.cumsum(n_ret, dtype=np.int64)
    first = cum - n_ret
    npts = int(cum[-1]) if npulse else 0
    pi = np.repeat(np.arange(npulse, dtype=np.int32 if npulse < 2**31 else np.int64),
                   n_ret)
    rn = (np.arange(npts, dtype=np.int64) - first[pi] + 1).astype(np.uint8)
    del cum, first
    psid = (line + 1).astype(np.uint16)
    del line, xc
    kp = kind[pi]
    x = px[pi]
    y = py[pi]
    g = ground_at_pulse[pi]
    del px, py, ground_at_pulse
    z = np.empty(npts)
    cls = np.empty(npts, np.uint8)
    inten = np.empty(npts, np.float32)

    veg = (kp == _K_TREE) & (rn <= n_veg[pi])
    gnd = (kp == _K_GROUND) | ((kp == _K_TREE) & ~veg)
    m = np.flatnonzero(gnd)
    z[m] = g[m] + rng.normal(0, noise, m.size)
    cls[m] = GROUND
    under = kp[m] == _K_TREE
    inten[m] = rng.normal(21000, 3500, m.size) * np.where(under, 0.45, 1.0)

    m = np.flatnonzero(kp == _K_ROOF)
    if m.size:
        o = obj[pi[m]]
        z[m] = buildings.roof_z(o, x[m], y[m]) + rng.normal(0, 0.6 * noise, m.size)
        cls[m] = BUILDING
        roof_ref = np.random.default_rng([seed, 101]).uniform(9000, 36000, len(buildings))
        inten[m] = roof_ref[o] + rng.normal(0, 1500, m.size)

    m = np.flatnonzero(kp == _K_WALL)
    if m.size:
        z[m] = pz_wall[pi[m]]
        cls[m] = BUILDING
        inten[m] = rng.normal(15000, 4000, m.size)

    m = np.flatnonzero(veg)
    if m.size:
        o = obj[pi[m]]
        rho = np.hypot(x[m] - trees.cx[o], y[m] - trees.cy[o]) / trees.radius[o]
        top = trees.crown_top(o, rho)
        bottom = trees.crown_bottom(o, rho)
        thick = np.maximum(top - bottom, 0.05)
        r_m = rn[m]
        nv = n_veg[pi[m]]
        inc = np.where(r_m == 1, rng.exponential(0.3, m.size),
                       rng.exponential(1.0, m.size) * thick / (nv + 1.0))
        cs = np.cumsum(inc)
        starts = np.flatnonzero(r_m == 1)
        base = cs[starts] - inc[starts]
        depth = cs - np.repeat(base, np.diff(np.append(starts, m.size)))
        depth = np.minimum(depth, thick * 0.98)
        z[m] = g[m] + np.maximum(top - depth, 0.3)
        cls[m] = HIGH_VEGETATION
        inten[m] = rng.normal(30000, 6000, m.size) / (0.6 + 0.4 * r_m)

    m = np.flatnonzero(kp == _K_LOW)
    z[m] = g[m] - rng.uniform(1.5, 15.0, m.size)
    cls[m] = LOW_NOISE
    inten[m] = rng.uniform(200, 3000, m.size)
    m = np.flatnonzero(kp == _K_HIGH)
    z[m] = g[m] + rng.uniform(40.0, 250.0, m.size)
    cls[m] = HIGH_NOISE
    inten[m] = rng.uniform(200, 3000, m.size)

    del g, kp, veg, gnd, m
    np.divide(z, scale, out=z)
    np.round(z, out=z)
    z *= scale
    return SyntheticTile(
        x=x, y=y, z=z, classification=cls, return_number=rn,
        number_of_returns=n_ret[pi].astype(np.uint8),
        intensity=np.clip(inten, 0, 65535).astype(np.uint16),
        gps_time=gps[pi], scan_angle=scan[pi],
        point_source_id=psid[pi],
        terrain=terrain, buildings=buildings, trees=trees, origin=(ox, oy),
        extent=(width, height), density=float(density), seed=int(seed),
        noise=float(noise), scale=float(scale),
        params=dict(n_buildings=n_buildings, n_halls=n_halls, tree_cover=tree_cover,
                    n_trees=len(trees), canopy_penetration=canopy_penetration,
                    base_height=base_height, relief=relief, hill_height=hill_height,
                    hill_slope_deg=hill_slope_deg, cliff_height=cliff_height,
                    n_low_outliers=n_low, n_high_noise=n_high,
                    wall_fraction=wall_fraction))


def _wall_points(rng, buildings, terrain, rate, scale):
    """A few points on building walls: uniform on the outline, up to the eave."""
    if not len(buildings) or rate <= 0:
        e = np.empty(0)
        return e, e, e
    perim = 4.0 * (buildings.half_length + buildings.half_width)
    n = rng.poisson(rate * perim * buildings.eave)
    o = np.repeat(np.arange(len(buildings)), n)
    if o.size == 0:
        e = np.empty(0)
        return e, e, e
    a, b = buildings.half_length[o], buildings.half_width[o]
    s = rng.uniform(0, 1, o.size) * perim[o]        # arc length along the outline
    # walk the outline: +u side, +v side, -u side, -v side
    u = np.where(s < 2 * b, a, np.where(s < 2 * b + 2 * a, a - (s - 2 * b),
                                        np.where(s < 4 * b + 2 * a, -a,
                                                 -a + (s - 4 * b - 2 * a))))
    v = np.where(s < 2 * b, -b + s, np.where(s < 2 * b + 2 * a, b,
                                             np.where(s < 4 * b + 2 * a,
                                                      b - (s - 2 * b - 2 * a), -b)))
    # 2 cm outside the wall so the point's (x, y) is outside the footprint
    u = u + np.sign(u) * (np.abs(u) >= a) * 0.02
    v = v + np.sign(v) * (np.abs(v) >= b) * 0.02
    c, sn = np.cos(buildings.angle[o]), np.sin(buildings.angle[o])
    x = np.round((buildings.cx[o] + u * c - v * sn) / scale) * scale
    y = np.round((buildings.cy[o] + u * sn + v * c) / scale) * scale
    ground = terrain(x, y)
    eave_z = buildings.base[o] + buildings.eave[o]
    z = ground + rng.uniform(0.3, 1.0, o.size) * (eave_z - ground)
    return x, y, z


def write_tile(tile: SyntheticTile, path, *, crs: Optional[str] = "EPSG:32632",
               point_format: int = 6) -> int:
    """Write a tile as LAS 1.4 (``.las``) or LAZ (``.laz``), atomically.

    Parameters
    ----------
    tile : SyntheticTile
        From :func:`generate_tile`.
    path : path-like
        Output file; the extension chooses compression.
    crs : str, optional
        CRS stored as an OGC WKT VLR (default UTM 32N, 'EPSG:32632').
    point_format : int
        6 (default) or 7 (adds zero RGB).

    Returns
    -------
    int
        Number of points written.
    """
    from ..core.io.las import write_las
    if point_format not in (6, 7):
        raise ValueError(f"point_format must be 6 or 7, got {point_format}")
    return write_las(path, tile.x, tile.y, tile.z, dimensions=tile.dimensions(),
                     crs=crs, point_format=point_format, version="1.4", scale=tile.scale)

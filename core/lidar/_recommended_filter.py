"""The recommended filter as an algorithm object: water kept out, what ran reported.

:class:`RecommendedFilter` wraps :func:`.recommended.classify` for the one engine of
:mod:`.filters` and adds what the bare function cannot know or say:

* **water** - points the input already classifies as water (ASPRS 9) keep class 9 and
  take no part (a lake surface is not the terrain and pulls a DTM down at its shores).
  In a cloud without class 9, *water candidates* are flagged: returns in cells with
  less than a quarter of the cloud's median point count whose heights spread less than
  0.15 m, in flat sparse patches of at least 400 m² (water reflects few pulses and lies
  flat); they get class 1 and are reported, never ground.
* **the report of what ran** (:class:`Derived`): density, cell, windows, slope
  tolerance, thresholds, trend, low-outlier cells and canopy scale, the largest object,
  ground share and class counts, with warnings where the cloud looks like a case the
  filter is weak on (few ground returns, canopy, water, objects as wide as the largest
  window, very low density).
"""
from __future__ import annotations

from dataclasses import dataclass, field
from typing import List, Optional

import numpy as np
from scipy import ndimage

from .. import classes as asprs
from ..progress import Monitor
from ..reporting import KeyValues, Paragraph, T
from . import _raster as R  # noqa: N812
from ._filter import FilterOutcome, OptionsFilter, check_classes
from ._summary import (
    DENSITY_CELL,
    cloud_summary,
    highest,
    lowest,
    recommended_values,
    world_cells,
)

__all__ = ["Derived", "RecommendedFilter", "water_candidates", "LABELS"]

WATER = int(asprs.WATER)
LABELS = {"cell": "Raster cell (m)", "max_window": "Largest window (m)",
          "slope": "Slope tolerance (rise/run)", "threshold": "Height tolerance (m)",
          "scaler": "Extra tolerance per unit of terrain slope (m)",
          "low_noise_depth": "Low-noise depth (m)", "refine": "Refinement passes",
          "trend_window": "Regional trend window (m)",
          "grow": "Continuity growing of terrain crests"}


def water_candidates(x, y, z, *, density: Optional[float] = None,
                     median5: Optional[float] = None, sparse: float = 0.25,
                     flat: float = 0.15, min_area: float = 400.0, keep=None,
                     extent=None) -> np.ndarray:
    """Flat, sparse returns in patches of at least ``min_area`` m² (likely water).

    Cells are 3 mean point spacings wide (at least 2 m) on the world lattice
    (multiples of the cell); a cell is a candidate when it holds fewer than ``sparse`` x
    the cloud's median count of the occupied cells (the median per occupied 5 m cell,
    scaled to the cell's area) and the heights of such cells in its 3 x 3 block (at
    least 3 points) spread less than ``flat`` m; candidate cells that touch form
    patches, kept when their area reaches ``min_area``. The density and median are
    the whole cloud's (a catalog's first pass, :mod:`._summary`): a chunk then flags
    the single-file run's cells (a patch cut by the chunk's edge aside).

    Parameters
    ----------
    x, y, z : ndarray
        Coordinates (m).
    density, median5 : float, optional
        Points per m² of occupied 5 m cells and median points per occupied 5 m cell
        (:func:`._summary.recommended_values`); default: those of these points.
    sparse, flat, min_area : float
        Thresholds (share of the median count, m, m²).
    keep : ndarray of bool, optional
        The points to test (the others take no part and are not flagged).
    extent : tuple, optional
        Theirs (``_checks.bounds``), when the caller has it.

    Returns
    -------
    ndarray of bool
        One flag per point.
    """
    n = np.size(x)
    out = np.zeros(n, bool)
    if keep is not None and keep.all():
        keep = None
    if (n if keep is None else np.count_nonzero(keep)) < 100:
        return out
    if density is None or median5 is None:
        own = recommended_values(cloud_summary(x, y, counts=True, keep=keep))
        density, median5 = own["density"], own["median5"]
    cell = max(2.0, 3.0 / np.sqrt(density))
    x, y = np.asarray(x, np.float64), np.asarray(y, np.float64)
    # floor(v / cell) is monotonic: the first and last cells are the extreme points'
    lx, ly, hx, hy = extent if extent is not None else \
        (lowest(x, keep), lowest(y, keep), highest(x, keep), highest(y, keep))
    x0, y0 = np.floor(lx / cell), np.floor(ly / cell)
    shape = (int(np.floor(hy / cell) - y0) + 1, int(np.floor(hx / cell) - x0) + 1)
    size = shape[0] * shape[1]

    # every point's cell once (int32 where the raster allows), block by block (the
    # temporaries stay in the processor's cache); the points left out get the extra cell
    # ``size``, which is never a candidate: one count, and no second pass over the points
    idx = np.empty(n, np.int32 if size < 2 ** 31 - 1 else np.int64)
    cnt = np.zeros(size + 1, np.int64)               # counted per block: bincount casts
    for s in range(0, n, R.CHUNK):                   # its input to int64 (a 4 M-point
        b = slice(s, s + R.CHUNK)                    # int32 array: a 32 MB copy)
        i = world_cells(x[b], y[b], cell, int(x0), int(y0), shape[1], row_major=True)
        if keep is not None:                         # points left out may lie outside
            i[~keep[b]] = size
        lo = int(i.min())                            # the block's span of cells only
        c = np.bincount(i - lo)
        cnt[lo:lo + c.size] += c
        idx[b] = i
    cand = cnt > 0                                   # occupied, and sparse:
    cand &= cnt < sparse * median5 * (cell / DENSITY_CELL) ** 2
    cand[size] = False
    if not cand.any():
        return out
    sel = np.flatnonzero(cand[idx])                  # the points of the sparse cells
    cnt, cand = cnt[:size], cand[:size]
    at = idx[sel]
    zlo = np.full(size, np.inf)
    np.minimum.at(zlo, at, z[sel])
    zhi = np.full(size, -np.inf)
    np.maximum.at(zhi, at, z[sel])
    box = np.ones((3, 3), bool)                      # heights and count over 3 x 3 cells
    lo = ndimage.minimum_filter(zlo.reshape(shape), footprint=box, mode="constant",
                                cval=np.inf)
    hi = ndimage.maximum_filter(zhi.reshape(shape), footprint=box, mode="constant",
                                cval=-np.inf)
    n3 = ndimage.uniform_filter(np.where(cand, cnt, 0).reshape(shape).astype(float), 3,
                                mode="constant") * 9
    cand = cand.reshape(shape) & (hi - lo < flat) & (n3 >= 3)
    if not cand.any():
        return out
    lab, k = ndimage.label(cand, structure=box)
    area = np.bincount(lab.ravel(), minlength=k + 1) * cell * cell
    big = area >= min_area
    big[0] = False
    if not big.any():
        return out
    keep_cell = np.append(big[lab.ravel()], False)   # per cell (not the extra one)
    return keep_cell[idx]


@dataclass
class Derived:
    """What the recommended filter derived from the cloud and did (report content)."""

    points: int = 0
    cell: float = 0.0
    windows: List[float] = field(default_factory=list)
    slope: tuple = (0.0, 0.0, 0.0)
    threshold: float = 0.0
    scaler: float = 0.0
    low_step: float = 0.0
    low_noise_depth: float = 0.0
    trend_window: float = 0.0
    pits: int = 0
    low_cells: int = 0
    canopy_share: float = 0.0
    canopy_scale: float = 0.0
    #: the coarse factor used under canopy (0: none) and, in a catalog chunk, the canopy
    #: counts of the blocks it owns (``_lowcells.low_cells(owned=)``, :mod:`._canopy`)
    canopy_factor: int = 0
    canopy_counts: Optional[dict] = None
    #: the object raster and its cell (or a fixed width, m): the widest object is measured
    #: when first asked, so a run without a report does not label the objects (0.08 s CPU
    #: on 4 M points)
    largest_object_of: object = field(default=0.0, repr=False, compare=False)
    ground_share: float = 0.0
    water_input: int = 0
    water_candidates: int = 0
    counts: dict = field(default_factory=dict)
    #: the density that ran (the whole cloud's, :mod:`._summary`), or ``(x, y)`` to count
    #: when first asked
    density_of: object = field(default=None, repr=False, compare=False)

    @property
    def largest_object(self) -> float:
        """Widest side (m) of the connected object regions' bounding boxes."""
        if isinstance(self.largest_object_of, tuple):
            self.largest_object_of = _largest_object(*self.largest_object_of)
        return float(self.largest_object_of or 0.0)

    @property
    def density(self) -> float:
        """Points per m² over the occupied 5 m cells (:func:`._raster.density`)."""
        if isinstance(self.density_of, tuple):
            self.density_of = float(R.density(*self.density_of))
        return float(self.density_of or 0.0)

    def warnings(self) -> list:
        """Return the warnings (translatable) where the filter is weak on the cloud."""
        out = []
        if self.ground_share < 0.15:
            out.append(T("Few ground returns: {pct} % of the points are ground. The terrain "
                         "rests on sparse points; check the DTM under dense vegetation.",
                         pct=round(100.0 * self.ground_share, 1)))
        if self.canopy_share > 0:
            out.append(T("Ground seen through a canopy over {pct} % of the cloud: low "
                         "outliers there were tested at the {scale} m spacing of the ground "
                         "returns.", pct=round(100.0 * self.canopy_share, 1),
                         scale=round(self.canopy_scale, 1)))
        if self.water_input:
            out.append(T("{n} water points (class 9 in the input) were kept out of the "
                         "ground.", n=self.water_input))
        if self.water_candidates:
            out.append(T("{n} flat, sparse returns look like water: they were given class 1, "
                         "not ground. Classify water as 9 to keep it out explicitly.",
                         n=self.water_candidates))
        if self.windows and self.largest_object >= self.windows[-1]:
            out.append(T("An object as wide as the largest window ({w} m) was found: if a "
                         "building is wider, raise the largest window.", w=self.windows[-1]))
        if self.density < 0.5:
            out.append(T("Low density ({rho} points/m²): small objects and breaklines are "
                         "poorly sampled.", rho=round(self.density, 2)))
        return out

    def rows(self) -> list:
        """Report rows ``(label, value)``."""
        w = self.windows
        return [("Points filtered", self.points),
                ("Point density (points/m², occupied area)", round(self.density, 3)),
                ("Raster cell (m)", self.cell),
                ("Opening windows (m)", T("{a} to {b} m, {n} steps", a=w[0], b=w[-1], n=len(w))
                 if w else None),
                ("Slope tolerance, min / median / max (rise/run)",
                 " / ".join(f"{v:.2f}" for v in self.slope)),
                ("Height tolerance (m)", self.threshold),
                ("Extra tolerance per unit of terrain slope (m)", self.scaler),
                ("Regional trend window (m)", self.trend_window),
                ("Low-outlier depth below the closing (m)", self.low_step),
                ("Closing pits / low-outlier cells", f"{self.pits} / {self.low_cells}"),
                ("Share under canopy (%)", round(100.0 * self.canopy_share, 1)),
                ("Ground-return spacing under canopy (m)", self.canopy_scale or None),
                ("Largest object found (m)", round(self.largest_object, 1)),
                ("Low-noise depth (m)", self.low_noise_depth),
                ("Ground share (%)", round(100.0 * self.ground_share, 1)),
                ("Water points kept (input class 9)", self.water_input),
                ("Water candidates (class 1)", self.water_candidates)]


def _largest_object(obj, cell: float) -> float:
    """Widest side (m) of the bounding boxes of the connected object regions."""
    if obj is None or not obj.any():
        return 0.0
    lab, _ = ndimage.label(obj)
    sides = [max(s[0].stop - s[0].start, s[1].stop - s[1].start)
             for s in ndimage.find_objects(lab)]
    return float(max(sides)) * cell


def derived(info: dict, classes: np.ndarray, water_input: int, water_cand: int) -> Derived:
    """:class:`Derived` from the ``info`` that :func:`.recommended.classify` filled."""
    opt, lows, slope = info["options"], info["lows"], info["slope"]
    cell = float(opt.cell)
    radii = np.arange(1, max(1, int(np.ceil(opt.max_window / cell))) + 1)
    s = np.broadcast_to(np.asarray(slope, float), (1,) if np.ndim(slope) == 0 else
                        np.shape(slope))
    per_class = np.bincount(classes)
    vals = np.flatnonzero(per_class)
    cnt = per_class[vals]
    n = max(1, int(info["n"]))
    return Derived(
        points=int(info["n"]), density_of=info.get("density"), cell=cell,
        windows=[float(r * cell) for r in radii],
        slope=(float(s.min()), float(np.median(s)), float(s.max())),
        threshold=opt.threshold, scaler=opt.scaler, low_step=opt.low_step,
        low_noise_depth=opt.low_noise_depth,
        trend_window=opt.trend_window if opt.trend_smooth > 0 else 0.0,
        pits=lows.pits, low_cells=int(np.count_nonzero(lows.low)),
        canopy_share=lows.canopy_share, canopy_scale=lows.canopy_scale,
        canopy_factor=lows.factor, canopy_counts=lows.counts,
        largest_object_of=(info.get("objects"), cell),
        ground_share=float(np.count_nonzero(classes == 2)) / n,
        water_input=int(water_input), water_candidates=int(water_cand),
        counts={int(k): int(c) for k, c in zip(vals, cnt)})


class RecommendedFilter(OptionsFilter):
    """The recommended filter (``groundfilter``) with water handling and its report.

    Parameters
    ----------
    options : RecommendedOptions
        Parameters (``None`` fields derived from the cloud).

    Attributes
    ----------
    summary : dict or None
        What it derives from the whole cloud (:func:`._summary.recommended_values`:
        density, median count per 5 m cell, input water anywhere). None: from the
        points it is given (a single-file run); a catalog sets the whole catalog's
        (its first pass), so every chunk derives what a single-file run of the merged
        cloud derives.
    """

    #: a catalog's first pass counts the points per 5 m cell for it (:mod:`._summary`)
    needs_counts = True
    #: and its chunks tally the canopy counts of their blocks (:mod:`._canopy`)
    needs_canopy = True
    summary: Optional[dict] = None
    #: set by a catalog chunk: ``owned(grid, f, shape)``, the canopy blocks it counts
    #: (``Derived.canopy_counts``) while it classifies
    canopy_owned = None

    def __init__(self, options):
        from .recommended import CITATION, TITLE, classify
        super().__init__(classify, options, name="groundfilter", title=TITLE,
                         citation=CITATION, labels=LABELS)

    def classify(self, x, y, z, *, return_number=None, number_of_returns=None,
                 classification=None, candidates=None, origin=None,
                 monitor: Optional[Monitor] = None) -> FilterOutcome:
        """Classify; input water (9) kept, water candidates class 1; :class:`Derived`.

        The points outside ``candidates`` take no part (no copy of the coordinates).
        """
        mon = monitor or Monitor()
        x, y, z = (np.asarray(a, dtype=np.float64) for a in (x, y, z))
        n = x.size
        water = (np.asarray(classification) == WATER if classification is not None
                 else np.zeros(n, bool))
        keep = None if candidates is None else np.asarray(candidates, bool)
        ext = R.bounds(x, y, keep)          # once for the summary, water test, check, grid
        s = self.summary or recommended_values(cloud_summary(
            x, y, classification, counts=True, keep=keep, extent=ext))
        cand_water = (np.zeros(n, bool) if s["water_input"] else
                      water_candidates(x, y, z, density=s["density"], median5=s["median5"],
                                       keep=keep, extent=ext))
        take = ~(water | cand_water)
        if keep is not None:
            take &= keep
        # a catalog's canopy factor (its chunks' canopy counts summed, :mod:`._canopy`)
        info: dict = {"density": s["density"], "canopy_factor": s.get("canopy_factor"),
                      "canopy_owned": self.canopy_owned}
        cls = np.full(n, 1, np.uint8)
        from .recommended import derive  # the tolerance from the whole cloud's density
        every = take.all()
        opts = derive(x, y, self.options, density=s["density"])
        same = np.count_nonzero(take) == (n if keep is None else np.count_nonzero(keep))
        got = self.func(x, y, z, options=opts, progress=mon.update, cancel=mon.cancelled,
                        origin=origin, info=info, keep=None if every else take,
                        extent=ext if same else None)         # take = keep: their extent
        dry = not (water.any() or cand_water.any())   # then ``take`` is ``keep``: got's
        if dry:                                       # classes (the others dropped below)
            cls = got
        else:
            cls[take] = got[take]
            cls[water] = WATER
        count = (lambda m: 0) if dry else (lambda m: int(np.count_nonzero(  # noqa: E731
            m if keep is None else m & keep)))
        cls = check_classes(self.name, cls if keep is None else cls[keep],
                            n if keep is None else int(np.count_nonzero(keep)))
        return FilterOutcome(cls, details=derived(info, cls, count(water), count(cand_water)))

    def report_sections(self, run, report, tr) -> None:
        """Add "Derived from the cloud" (values that ran) and the warnings."""
        d = run.outcome.details
        if not isinstance(d, Derived):
            return
        sec = report.section("Derived from the cloud (what ran)")
        sec.add(KeyValues(d.rows()))
        for w in d.warnings():
            sec.add(Paragraph(w))

"""Elevation change between two epochs with a level of detection.

The difference ``after − before`` of two co-registered surfaces (DTM or DSM) is
significant where it exceeds the level of detection at 95 % confidence,
``LoD95 = 1.96·√(σ₁² + σ₂²)`` (Brasington et al. 2003; Wheaton et al. 2010), with
σ₁, σ₂ the vertical accuracies (RMSE) of the two epochs. Significant cells are grouped
into 4-connected regions of one sign (fill > 0, cut < 0); regions smaller than a
minimum area are dropped, so that the 5 % of cells pure noise pushes beyond the LoD
do not become change polygons. Each region has its area, mean change and volume
(Σ change × cell area).

References
----------
Brasington, J., Langham, J., Rumsby, B. (2003). Methodological sensitivity of
morphometric estimates of coarse fluvial sediment transport. Geomorphology 53, 299–316.
Wheaton, J. M., Brasington, J., Darby, S. E., Sear, D. A. (2010). Accounting for
uncertainty in DEMs from repeat topographic surveys. ESPL 35, 136–156.
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import List

import numpy as np

from ..errors import InputError
from ..reporting import Figure, KeyValues, Paragraph, Report, T, Table
from ..reporting.svg import svg_bars, svg_raster

#: Default minimum region size in cells when no minimum area is given: with
#: independent cell errors 2.5 % of cells exceed +LoD (and 2.5 % −LoD), and the expected
#: number of 4-connected clusters of ≥ 8 such cells is about 4e-4 per million cells.
#: Errors correlated between neighbouring cells (interpolated DTMs) need a larger area.
MIN_CELLS = 8


def lod95(sigma1: float, sigma2: float) -> float:
    """Return the level of detection at 95 %: ``1.96·√(σ₁² + σ₂²)`` (m)."""
    for name, s in (("sigma1", sigma1), ("sigma2", sigma2)):
        if not (s >= 0 and math.isfinite(s)):
            raise InputError("{name} (vertical accuracy of an epoch) must be ≥ 0 m, got "
                             "{s}; give e.g. the RMSE of a DTM accuracy run.", name=name, s=s)
    return 1.96 * math.sqrt(sigma1 ** 2 + sigma2 ** 2)


def sigma_from_residuals(errors, name: str = "the residual layer") -> float:
    """Vertical accuracy of an epoch from DTM-accuracy residuals: their RMSE (m).

    ``errors``: the ``error`` (DTM − check) of the check points a DTM-accuracy run
    used (status 'used'); non-finite values are ignored. The RMSE, not the standard
    deviation, so that a bias of the epoch counts in its level of detection.
    """
    e = np.asarray(errors, dtype=np.float64).ravel()
    e = e[np.isfinite(e)]
    if e.size < 3:
        raise InputError("{name} holds {n} usable check-point residuals (field 'error', "
                         "status 'used'); give the residual layer of a DTM accuracy run "
                         "with at least 3, or type σ instead.", name=name, n=int(e.size))
    return float(np.sqrt(np.mean(e * e)))


@dataclass
class ChangeResult:
    """Difference raster, significant regions and volumes (see :func:`elevation_change`)."""

    diff: np.ndarray
    labels: np.ndarray
    lod: float
    cell: float
    regions: List[dict] = field(default_factory=list)

    @property
    def fill_volume(self) -> float:
        """Volume of the fill regions (m³, ≥ 0)."""
        return float(sum(r["volume"] for r in self.regions if r["volume"] > 0))

    @property
    def cut_volume(self) -> float:
        """Volume of the cut regions (m³, ≤ 0)."""
        return float(sum(r["volume"] for r in self.regions if r["volume"] < 0))

    @property
    def net_volume_all(self) -> float:
        """Net volume over every valid cell, significant or not (m³)."""
        return float(np.nansum(self.diff) * self.cell * self.cell)


def elevation_change(before: np.ndarray, after: np.ndarray, cell: float, *,
                     sigma1: float, sigma2: float, min_area: float = 0.0,
                     progress=None, cancel=None) -> ChangeResult:
    """Difference of two surfaces on one grid and its significant change regions.

    Parameters
    ----------
    before, after : 2-D ndarray
        Heights of the two epochs on the same grid (NaN = nodata).
    cell : float
        Cell size (m).
    sigma1, sigma2 : float
        Vertical accuracy (RMSE, m) of each epoch.
    min_area : float
        Smallest region kept (m²); 0 = :data:`MIN_CELLS` cells.
    progress, cancel : callable, optional
        See :class:`~..progress.Monitor`.

    Returns
    -------
    ChangeResult
        ``regions``: one dict per kept region (``id``, ``kind`` 'fill'/'cut',
        ``area`` m², ``mean_change`` m, ``volume`` m³, ``cells``).
    """
    from scipy import ndimage

    from ..progress import Monitor
    mon = Monitor(progress, cancel)
    a = np.asarray(before, float)
    b = np.asarray(after, float)
    if a.shape != b.shape:
        raise InputError("The two epochs are on different grids ({a_shape} and {b_shape} "
                         "cells); resample one onto the other's grid first.",
                         a_shape=a.shape,
                         b_shape=b.shape)
    both = np.isfinite(a) & np.isfinite(b)
    if not both.any():          # an all-nodata epoch, or no overlap: no change is no answer
        raise InputError("The two epochs share no cell with a height in both ({n_a} cells "
                         "with a height before, {n_b} after, on a common grid of {n} "
                         "cells): one of them is empty (all nodata) or they do not overlap. "
                         "Check the two rasters, their nodata values and their extents.",
                         n_a=int(np.isfinite(a).sum()), n_b=int(np.isfinite(b).sum()),
                         n=a.size)
    lod = lod95(sigma1, sigma2)
    diff = b - a
    min_cells = max(1, int(math.ceil(min_area / (cell * cell)))) if min_area > 0 \
        else MIN_CELLS
    labels = np.zeros(a.shape, np.int32)
    regions: List[dict] = []
    for sign, kind in ((1, "fill"), (-1, "cut")):
        mon.step(0.1 if sign > 0 else 0.5)
        lab, n = ndimage.label(np.nan_to_num(sign * diff, nan=0.0) > lod)
        if not n:
            continue
        idx = np.arange(1, n + 1)
        cells = ndimage.sum_labels(np.ones_like(diff), lab, idx)
        total = ndimage.sum_labels(np.nan_to_num(diff), lab, idx)
        remap = np.zeros(n + 1, np.int32)
        for k in idx[cells >= min_cells]:
            rid = len(regions) + 1
            remap[k] = rid
            c, s = cells[k - 1], total[k - 1]
            regions.append({"id": rid, "kind": kind, "cells": int(c),
                            "area": float(c * cell * cell), "mean_change": float(s / c),
                            "volume": float(s * cell * cell)})
        labels = np.where(remap[lab] > 0, remap[lab], labels)
    mon.step(1.0)
    return ChangeResult(diff, labels, lod, float(cell), regions)


def change_report(res: ChangeResult, names, sigma1: float, sigma2: float) -> Report:
    """Build the report: LoD, volumes, change map, histogram, region table."""
    rep = Report("Elevation change report",
                 citation="Brasington et al. (2003); Wheaton et al. (2010): "
                 "LoD95 = 1.96·√(σ₁² + σ₂²).")
    d = res.diff[np.isfinite(res.diff)]
    rep.summary = [Paragraph(T("{n} change regions above the level of detection "
                               "({lod} m).", n=len(res.regions), lod=f"{res.lod:.3f}"))]
    rep.section("Epochs and level of detection").add(KeyValues([
        ("Before", names[0]), ("After", names[1]),
        ("Vertical accuracy before σ₁ (m)", sigma1),
        ("Vertical accuracy after σ₂ (m)", sigma2),
        ("Level of detection LoD95 (m)", res.lod),
        ("Cell size (m)", res.cell), ("Cells compared", int(d.size))]))
    rep.section("Volumes").add(KeyValues([
        ("Fill volume above the LoD (m³)", res.fill_volume),
        ("Cut volume above the LoD (m³)", res.cut_volume),
        ("Net volume over all cells, without the LoD (m³)", res.net_volume_all)]))
    span = max(float(np.abs(d).max()) if d.size else 1.0, res.lod * 2, 1e-6)
    sec = rep.section("Maps")
    sec.add(Figure(svg_raster(res.diff, unit="m", ramp="diverging", vmin=-span, vmax=span),
                   "Change after − before (m): red cut, blue fill", "change-map"))
    if d.size:
        counts, edges = np.histogram(np.clip(d, -span, span), bins=40, range=(-span, span))
        sec.add(Figure(svg_bars([f"{e:.2f}" for e in edges[:-1]], counts),
                       "Histogram of the change (m)", "change-histogram"))
    top = sorted(res.regions, key=lambda r: -abs(r["volume"]))[:30]
    rep.section("Change regions").add(Table(
        ["Id", "Kind", "Area (m²)", "Mean change (m)", "Volume (m³)"],
        [[r["id"], T(r["kind"]), r["area"], r["mean_change"], r["volume"]] for r in top],
        caption="Largest regions by volume", digits=[0, None, 1, 3, 2]))
    return rep

"""Point density and quality of a LiDAR cloud, with numeric parameter advice.

Density rasters (all returns, last returns, ground), histograms of returns and
classes, gaps (cells with returns but no ground point), duplicate points, noise share
(ASPRS classes 7 and 18), scan-angle range, and the advice of the ELiT workflow
(Kostrikov et al. 2020) made explicit: the ground window grows as the density falls
(1–2 pts/m² → 2 m), about 0.6 pts/m² supports LOD1 building models only, the DTM cell
follows the ground point spacing, and the settings of our ground filters follow the
window.

References
----------
Kostrikov, S., Pudlo, R., Bubnov, D., Vasiliev, V. (2020). ELiT, multifunctional
web-software for feature extraction from 3D LiDAR point clouds. ISPRS IJGI 9(11), 650.
ASPRS (2019). LAS specification 1.4 R15 (classes, return numbers, scan angle).
"""
from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Dict, List, Optional, Tuple

import numpy as np

from .. import classes as asprs
from ..errors import InputError
from ..reporting import Figure, KeyValues, Paragraph, Report, T, Table
from ..reporting.svg import svg_bars, svg_raster
from ..terrain.grid import GridSpec, grid_from_points

#: Candidate DTM cell sizes (m), smallest first.
NICE_CELLS = (0.25, 0.5, 1.0, 2.0, 5.0, 10.0)
#: ASPRS noise classes (low noise, high noise).
NOISE_CLASSES = tuple(int(c) for c in asprs.INPUT_NOISE)


@dataclass
class QaResult:
    """Density rasters, counts and advice of one cloud (see :func:`lidar_qa`)."""

    grid: GridSpec
    density_all: np.ndarray
    density_last: np.ndarray
    density_ground: np.ndarray
    gaps: np.ndarray
    n_points: int
    n_last: int
    n_ground: int
    n_duplicates: int
    n_noise: int
    class_counts: Dict[int, int]
    return_counts: Dict[int, int]
    scan_angle: Optional[Tuple[float, float]]
    covered_area: float
    advice: Dict[str, object] = field(default_factory=dict)

    @property
    def density(self) -> float:
        """Mean density of all returns over the covered cells (pts/m²)."""
        return self.n_points / self.covered_area if self.covered_area else float("nan")

    @property
    def ground_density(self) -> float:
        """Mean ground density over the covered cells (pts/m²)."""
        return self.n_ground / self.covered_area if self.covered_area else float("nan")

    @property
    def gap_share(self) -> float:
        """Share of covered cells without a ground point."""
        covered = self.density_all > 0
        return float(self.gaps.sum() / max(covered.sum(), 1))


def check_projected(x, y) -> None:
    """Refuse coordinates that look like longitude/latitude degrees.

    Raises
    ------
    InputError
        All x within ±180, all y within ±90 and an extent under 2 units.
    """
    x = np.asarray(x)
    y = np.asarray(y)
    if x.size and np.abs(x).max() <= 180 and np.abs(y).max() <= 90 and \
            max(np.ptp(x), np.ptp(y)) < 2:
        raise InputError(
            "The point cloud seems to be in degrees (longitude/latitude): densities per "
            "m² and cell sizes in metres would be meaningless. Reproject it to a "
            "projected CRS in metres (e.g. UTM) first, e.g. with PDAL filters.reprojection.")


def ground_window(density: float) -> float:
    """Return the ground-filter window (m) for a density of all returns (pts/m²).

    ``2·sqrt(1.5 / density)``, rounded to 1 m above 1.5 m and to 0.5 m below, at least
    0.5 m: 1–2 pts/m² → 2 m, 0.6 pts/m² → 3 m, 8 pts/m² → 1 m (ELiT's 2 m at 1–2
    pts/m², keeping about six returns per window).
    """
    if not density > 0:
        return float("nan")
    raw = 2.0 * math.sqrt(1.5 / density)
    return max(0.5, float(round(raw)) if raw >= 1.5 else round(raw * 2) / 2)


def dtm_cell(ground_density: float) -> float:
    """Return the smallest of :data:`NICE_CELLS` not below the ground point spacing."""
    if not ground_density > 0:
        return float("nan")
    spacing = 1.0 / math.sqrt(ground_density)
    return next((c for c in NICE_CELLS if c >= spacing - 1e-9), NICE_CELLS[-1])


def advise(density: float, ground_density: float, gap_share: float,
           noise_share: float) -> Dict[str, object]:
    """Return the numeric advice for a cloud.

    Keys: ``ground_window`` (m), ``dtm_cell`` (m), ``lod`` ('LOD1' below 1 pt/m²,
    else 'LOD2'), ``slope_radius`` and ``lsq_tile`` (m, settings of our slope-based
    and LSQ ground filters), ``denoise`` (True when the noise share exceeds 0.1 %)
    and ``gaps_large`` (True when more than 20 % of the covered cells have no ground).
    """
    window = ground_window(density)
    return {"ground_window": window, "dtm_cell": dtm_cell(ground_density),
            "lod": "LOD1" if density < 1.0 else "LOD2",
            "slope_radius": window if math.isfinite(window) else float("nan"),
            "lsq_tile": max(25.0, 15.0 * window) if math.isfinite(window) else float("nan"),
            "denoise": bool(noise_share > 0.001),
            "gaps_large": bool(gap_share > 0.2)}


def _duplicates(x, y, z) -> int:
    """Count points repeating an earlier point's x, y, z (to the millimetre)."""
    key = np.column_stack([np.round(x * 1000), np.round(y * 1000), np.round(z * 1000)])
    return int(x.size - np.unique(key, axis=0).shape[0])


def _count(grid: GridSpec, x, y, keep=None) -> np.ndarray:
    row, col, inside = grid.cell_index(x, y)
    if keep is not None:
        inside &= keep
    flat = np.bincount(row[inside] * grid.ncols + col[inside], minlength=grid.size)
    return flat.reshape(grid.shape)


def lidar_qa(x, y, z, classification, return_number, number_of_returns, *,
             scan_angle=None, cell_size: float = 5.0, crs: Optional[str] = None,
             ground_classes=(2,)) -> QaResult:
    """Density rasters, counts and parameter advice of one cloud.

    Parameters
    ----------
    x, y, z : ndarray
        Coordinates (projected, metres).
    classification, return_number, number_of_returns : ndarray
        LAS dimensions.
    scan_angle : ndarray, optional
        Scan angle (degrees) of each point.
    cell_size : float
        Cell of the density rasters (m, default 5).
    crs : str, optional
        CRS of the rasters.
    ground_classes : sequence of int
        Classes counted as ground (default 2).

    Returns
    -------
    QaResult
    """
    if not cell_size > 0:
        raise InputError("Cell size must be > 0 (m), got {cell_size}; give e.g. 5.",
                         cell_size=cell_size)
    check_projected(x, y)
    cls = np.asarray(classification).astype(np.int64)
    rn = np.asarray(return_number).astype(np.int64)
    nr = np.asarray(number_of_returns).astype(np.int64)
    grid = grid_from_points(x, y, cell_size, crs=crs)
    area = grid.cell * grid.cell
    ground = np.isin(cls, ground_classes)
    last = rn >= nr
    n_all = _count(grid, x, y)
    dens = {k: _count(grid, x, y, m) / area for k, m in
            (("last", last), ("ground", ground))}
    covered = n_all > 0
    gaps = covered & (dens["ground"] == 0)
    classes = np.bincount(cls, minlength=1)
    returns = np.bincount(np.clip(rn, 0, 15), minlength=1)
    n_noise = int(np.isin(cls, NOISE_CLASSES).sum())
    sa = None
    if scan_angle is not None and np.size(scan_angle):
        sa = (float(np.min(scan_angle)), float(np.max(scan_angle)))
    res = QaResult(grid, n_all / area, dens["last"], dens["ground"], gaps, int(x.size),
                   int(last.sum()), int(ground.sum()), _duplicates(x, y, z), n_noise,
                   {int(c): int(n) for c, n in enumerate(classes) if n},
                   {int(r): int(n) for r, n in enumerate(returns) if n}, sa,
                   float(covered.sum() * area))
    res.advice = advise(res.density, res.ground_density, res.gap_share,
                        n_noise / max(res.n_points, 1))
    return res


def advice_lines(res: QaResult) -> List[Tuple[str, dict]]:
    """Return the advice as (English message id, fields) pairs for a report."""
    a = res.advice
    lines = [("Ground filter window: {w} m (density {d} pts/m²).",
              {"w": f"{a['ground_window']:g}", "d": f"{res.density:.2f}"}),
             ("Recommended DTM cell size: {c} m (ground density {g} pts/m²).",
              {"c": f"{a['dtm_cell']:g}", "g": f"{res.ground_density:.2f}"}),
             ("Slope-based ground filter: radius {r} m; LSQ ground filter: tile {t} m.",
              {"r": f"{a['slope_radius']:g}", "t": f"{a['lsq_tile']:g}"})]
    if a["lod"] == "LOD1":
        lines.append(("Density below 1 pt/m²: building models at LOD1 only (footprints "
                      "and heights, no roof shapes).", {}))
    else:
        lines.append(("Density supports LOD2 building models (roof planes).", {}))
    if a["denoise"]:
        lines.append(("Noise share above 0.1 %: keep the low-outlier removal on.", {}))
    if a["gaps_large"]:
        lines.append(("More than 20 % of the covered cells have no ground point: leave "
                      "DTM gaps as nodata or use a TIN with a maximum edge length.", {}))
    return lines


def qa_report(res: QaResult, name: str, *, units=None) -> Report:
    """Build the report of :func:`lidar_qa` (maps, histograms, advice).

    ``units`` (:class:`~..io.units.Units`) are the cloud's when it is not in metres:
    the report then says that densities and areas were computed in metres.
    """
    from ..io.units import units_rows
    rep = Report("Point density and quality report",
                 citation="Kostrikov et al. (2020), ELiT, ISPRS IJGI 9(11):650; "
                 "ASPRS LAS 1.4.")
    rep.summary = [Paragraph(T(m, **f)) for m, f in advice_lines(res)]
    sa = res.scan_angle
    rep.section("Summary").add(KeyValues([
        ("Input", name),
        *units_rows(units),
        ("Points", res.n_points), ("Last returns", res.n_last),
        ("Ground points", res.n_ground),
        ("Covered area (m²)", res.covered_area),
        ("Density of all returns (pts/m²)", res.density),
        ("Ground density (pts/m²)", res.ground_density),
        ("Share of cells without ground", res.gap_share),
        ("Duplicate points", res.n_duplicates),
        ("Noise share", res.n_noise / max(res.n_points, 1)),
        ("Scan angle range (°)", f"{sa[0]:.1f} … {sa[1]:.1f}" if sa else "–")]))
    rep.section("Maps").add(Figure(svg_raster(res.density_all, unit="pts/m²"),
                                   "Density of all returns (pts/m²)", "density-map")
                            ).add(Figure(svg_raster(res.density_ground, unit="pts/m²"),
                                         "Ground density (pts/m²)", "ground-density-map")
                                  ).add(Figure(svg_raster(
                                      res.gaps.astype(float), ramp="gaps", vmin=0,
                                      vmax=1), "Cells with returns but no ground point "
                                      "(red)", "gap-map"))
    rc = sorted(res.return_counts.items())
    cc = sorted(res.class_counts.items())
    rep.section("Histograms").add(
        Figure(svg_bars([r for r, _ in rc], [n for _, n in rc]), "Points per return "
               "number", "returns-histogram")).add(
        Figure(svg_bars([c for c, _ in cc], [n for _, n in cc]), "Points per class",
               "classes-histogram")).add(
        Table(["Class", "Points"], cc, digits=0))
    return rep

"""Full ASPRS classification of an airborne cloud: ground, vegetation, buildings, noise.

One verb (:func:`classify_points`, arrays in, classes out) and its thin file runner
(:func:`classify_file_asprs`: read, classify, write through the output contract,
report content). The steps, in the order of the ELiT non-ground branch (Kostrikov et
al. 2020):

1. **Ground (2)** — the registry's default ground filter (the recommended one,
   :func:`.filters.default_ground_filter`) with its single-file point selection, as
   ``geomatics:groundfilter`` runs it (input noise 7/18 kept, low outliers 7); or, with
   ``ground="keep"``, the input's own class 2 (and 7) as they are.
2. **Height above ground** — a TIN DTM of the ground points (Delaunay, linear inside
   each triangle; one point per cell where the ground is denser than the grid,
   :func:`.buildings.ground_dtm`) on a ``dtm_cell`` grid, sampled
   bilinearly at every point (lidR ``normalize_height(las, tin())``, PDAL
   ``filters.hag_delaunay``).
3. **Building (6)** — roof planes found by :func:`.buildings.extract_buildings` on the
   same DTM, plus the other points over a footprint up to the roof; a structure the
   building step refuses as a bridge (its deck runs on into the ground at both ends)
   is **bridge deck (17)**.
4. **Vegetation (3/4/5)** — every other point above the ground by its height:
   ``0 ≤ h ≤ low_max`` low, ``low_max < h ≤ medium_max`` medium, higher high. The
   defaults 0.5 m and 1.5 m are the IGN LiDAR HD classes (végétation basse < 50 cm,
   moyenne 50 cm – 1.5 m, haute > 1.5 m; IGN, *LiDAR HD – point sur les
   traitements*, geoservices.ign.fr, 2023). Points below the DTM that are not low
   outliers stay 1.
5. **Kept** — water (9) and input noise (7, 18) always; every other input class
   (8, 10–17, 19–255: rail, road, wires, towers, bridge decks, vendor classes) when
   ``keep_other`` is set.

Thresholds are in metres whatever the CRS: a cloud in feet is converted on reading
(:mod:`~..io.units`) and heights above ground are written in its own vertical unit.

References
----------
Kostrikov, S. et al. (2020). ELiT, multifunctional web-software for feature extraction
from 3D LiDAR point clouds. ISPRS IJGI 9(11), 650.
ASPRS (2019). LAS Specification 1.4 R15, Table 17 (standard point classes).
Roussel, J.-R. et al. (2020). lidR: an R package for analysis of Airborne Laser
Scanning (ALS) data. Remote Sensing of Environment 251, 112061 (normalize_height).
"""
from __future__ import annotations

import os
import time
from dataclasses import dataclass, field
from typing import Dict, Optional

import numpy as np

from ..errors import InputError
from ..io.units import METRIC, Units
from ..progress import Monitor
from .buildings import DEFAULTS as BUILDING_DEFAULTS

__all__ = ["ClassifyOptions", "Classification", "classify_points", "classify_file_asprs",
           "classify_report", "ASPRS_NAMES", "HAG_DIMENSION"]

NEVER, OTHER, GROUND, LOW_VEG, MEDIUM_VEG, HIGH_VEG, BUILDING, LOW_NOISE = range(8)
WATER, BRIDGE_DECK, HIGH_NOISE = 9, 17, 18
#: Classes this verb writes itself; every other input class is kept on request.
WRITTEN = (OTHER, GROUND, LOW_VEG, MEDIUM_VEG, HIGH_VEG, BUILDING, LOW_NOISE)
#: Name of the extra-bytes dimension written on request (PDAL's name).
HAG_DIMENSION = "HeightAboveGround"
ASPRS_NAMES = {0: "never classified", 1: "unclassified", 2: "ground",
               3: "low vegetation", 4: "medium vegetation", 5: "high vegetation",
               6: "building", 7: "low noise", 8: "model key point", 9: "water",
               10: "rail", 11: "road surface", 12: "overlap", 13: "wire guard",
               14: "wire conductor", 15: "transmission tower", 16: "wire connector",
               17: "bridge deck", 18: "high noise"}


@dataclass(frozen=True)
class ClassifyOptions:
    """Options of :func:`classify_points` (lengths in metres).

    Attributes
    ----------
    ground : {'filter', 'keep'}
        Classify ground with the recommended filter, or keep the input's class 2.
    low_max, medium_max : float
        Upper heights above ground of low (3) and medium (4) vegetation (m).
    buildings : bool
        Find buildings (class 6); off, every object above ground is vegetation.
    keep_other : bool
        Keep input classes other than 0–7 (water 9 and noise 18 are always kept).
    dtm_cell : float
        Cell of the TIN DTM the heights are measured from (m).
    min_height, storey_height : float
        Building options (see :func:`.buildings.extract_buildings`).
    """

    ground: str = "filter"
    low_max: float = 0.5
    medium_max: float = 1.5
    buildings: bool = True
    keep_other: bool = False
    dtm_cell: float = BUILDING_DEFAULTS["cell"]
    min_height: float = BUILDING_DEFAULTS["min_height"]
    storey_height: float = BUILDING_DEFAULTS["storey_height"]

    def __post_init__(self):
        """Validate the options (translated errors)."""
        if self.ground not in ("filter", "keep"):
            raise InputError("Ground must be 'filter' (the recommended ground filter) or "
                             "'keep' (the input's class 2); got {value!r}.",
                             value=self.ground)
        if not (np.isfinite(self.low_max) and np.isfinite(self.medium_max)
                and 0 < self.low_max < self.medium_max):
            raise InputError("Vegetation heights must satisfy 0 < Low vegetation up to "
                             "(LOW_VEGETATION = {low} m) < Medium vegetation up to "
                             "(MEDIUM_VEGETATION = {medium} m): give e.g. 0.5 and 1.5.",
                             low=self.low_max, medium=self.medium_max)
        if not (np.isfinite(self.dtm_cell) and self.dtm_cell > 0):
            raise InputError("Cell size must be > 0 (m); give e.g. 0.5.")


@dataclass
class Classification:
    """Result of :func:`classify_points`.

    ``classes`` (uint8, one per point), ``hag`` (height above the DTM in the data's
    vertical unit, float32), the input and output class counts, the
    :class:`~.buildings.BuildingResult` (None when buildings are off) and timings.
    """

    classes: np.ndarray
    hag: np.ndarray
    input_counts: Dict[int, int]
    counts: Dict[int, int]
    buildings: object = None
    options: ClassifyOptions = field(default_factory=ClassifyOptions)
    units: Units = METRIC
    seconds: Dict[str, float] = field(default_factory=dict)
    n_low_outliers: int = 0


def _counts(classes) -> Dict[int, int]:
    c = np.bincount(np.asarray(classes, dtype=np.int64), minlength=256)
    return {int(k): int(c[k]) for k in np.flatnonzero(c)}


def _ground_step(x, y, z, cls_in, opt, mon):
    """Classes 2/1/7 (input noise kept) from the recommended filter or the input."""
    from ..io.las import PointData
    from .filters import default_ground_filter, default_selection, ground_filter, run_filter
    if opt.ground == "keep":
        out = np.where(np.isin(cls_in, (GROUND, LOW_NOISE, HIGH_NOISE)), cls_in, OTHER)
        if np.count_nonzero(out == GROUND) < 3:
            raise InputError("No ground points (class 2) in the cloud: run a ground filter "
                             "first (e.g. the slope-based or LSQ ground filter).")
        return out.astype(np.uint8), 0
    # the one registry's default filter (the recommended one) with its single-file
    # point selection, exactly as geomatics:groundfilter runs it
    key = default_ground_filter()
    run = run_filter(PointData(x, y, z, {"classification": cls_in}), ground_filter(key),
                     default_selection(key), monitor=mon)
    return run.classes, int(np.count_nonzero(run.selection.low_outliers))


def height_above_ground(x, y, grid, dtm) -> np.ndarray:
    """Bilinear sample of a DTM grid at ``x, y`` (edge cells extended)."""
    fx = (np.asarray(x) - grid.xmin) / grid.cell - 0.5
    fy = (grid.ymax - np.asarray(y)) / grid.cell - 0.5
    c0 = np.clip(np.floor(fx).astype(np.int64), 0, max(grid.ncols - 2, 0))
    r0 = np.clip(np.floor(fy).astype(np.int64), 0, max(grid.nrows - 2, 0))
    c1 = np.minimum(c0 + 1, grid.ncols - 1)
    r1 = np.minimum(r0 + 1, grid.nrows - 1)
    tx = np.clip(fx - c0, 0.0, 1.0)
    ty = np.clip(fy - r0, 0.0, 1.0)
    top = dtm[r0, c0] * (1 - tx) + dtm[r0, c1] * tx
    bottom = dtm[r1, c0] * (1 - tx) + dtm[r1, c1] * tx
    return top * (1 - ty) + bottom * ty


def _on_bridges(res, x, y, hag, *, min_hag: float = 0.5) -> np.ndarray:
    """Points over a refused bridge deck at least ``min_hag`` m above the DTM."""
    flag = np.zeros(np.shape(x), bool)
    if res.bridges is None or not res.bridges.any():
        return flag
    r, c, inside = res.grid.cell_index(x, y)
    idx = np.flatnonzero(inside)
    idx = idx[res.bridges[r[idx], c[idx]]]
    flag[idx[hag[idx] >= min_hag]] = True
    return flag


def classify_points(x, y, z, classification=None, *, options: Optional[ClassifyOptions] = None,
                    units: Units = METRIC, crs=None, progress=None,
                    cancel=None) -> Classification:
    """ASPRS classes 2/3/4/5/6/7 (9 and noise kept) of a cloud; see the module docstring.

    Parameters
    ----------
    x, y, z : array_like of float
        Coordinates in the cloud's CRS units (``units`` converts them to metres).
    classification : array_like of int, optional
        The input classes (water, noise and, on request, other classes are kept;
        ``ground='keep'`` takes its class 2).
    options : ClassifyOptions, optional
        Thresholds (metres) and switches.
    units : Units
        Linear units of the cloud (:func:`~..io.units.las_units`).
    crs : str, optional
        CRS of the footprint grid.
    progress, cancel : callable, optional
        See :class:`~..progress.Monitor`.

    Returns
    -------
    Classification

    Examples
    --------
    >>> res = classify_points(x, y, z, cls)                           # doctest: +SKIP
    >>> res.counts[6], res.hag.max()                                   # doctest: +SKIP
    """
    from ..terrain.grid import grid_from_points
    from .buildings import building_points, extract_buildings, ground_dtm
    opt = options or ClassifyOptions()
    mon = Monitor(progress, cancel)
    t0 = time.perf_counter()
    xm, ym, zm = units.xyz_to_metres(x, y, z)
    xm, ym, zm = (np.asarray(a, dtype=np.float64) for a in (xm, ym, zm))
    n = xm.size
    cls_in = (np.zeros(n, np.uint8) if classification is None
              else np.asarray(classification).astype(np.uint8))
    if cls_in.shape != (n,):
        raise InputError("The classification has {got} values for {n} points.",
                         got=int(cls_in.size), n=n)
    cls, n_low = _ground_step(xm, ym, zm, cls_in, opt, mon.sub(0.0, 0.45))
    t_ground = time.perf_counter()
    ground = cls == GROUND
    if np.count_nonzero(ground) < 3:
        raise InputError("No point was classified as ground, so no height above ground "
                         "can be measured; check the input.")
    grid = grid_from_points(xm, ym, opt.dtm_cell, crs=crs)
    dtm = ground_dtm(xm[ground], ym[ground], zm[ground], grid)
    hag = zm - height_above_ground(xm, ym, grid, dtm)
    mon.step(0.6)
    t_dtm = time.perf_counter()
    res = None
    is_bld = np.zeros(n, bool)
    deck = np.zeros(n, bool)
    if opt.buildings:
        res = extract_buildings(xm, ym, zm, cls, min_height=opt.min_height,
                                storey_height=opt.storey_height, crs=crs,
                                dtm=(grid, dtm), progress=mon.sub(0.6, 0.95).update,
                                cancel=mon.cancelled)
        is_bld = building_points(res, xm, ym, zm, hag, cls)
        deck = _on_bridges(res, xm, ym, hag)
    t_bld = time.perf_counter()
    free = cls == OTHER
    out = cls.copy()
    out[free & (hag >= 0) & (hag <= opt.low_max)] = LOW_VEG
    out[free & (hag > opt.low_max) & (hag <= opt.medium_max)] = MEDIUM_VEG
    out[free & (hag > opt.medium_max)] = HIGH_VEG
    out[free & is_bld] = BUILDING
    out[free & deck & ~is_bld] = BRIDGE_DECK
    keep = cls_in == WATER
    if opt.keep_other:
        keep |= ~np.isin(cls_in, WRITTEN)
    out[keep] = cls_in[keep]
    mon.step(1.0)
    t_end = time.perf_counter()
    return Classification(out, (hag / units.v).astype(np.float32), _counts(cls_in),
                          _counts(out), res, opt, units,
                          dict(ground=t_ground - t0, dtm=t_dtm - t_ground,
                               buildings=t_bld - t_dtm, vegetation=t_end - t_bld,
                               total=t_end - t0), n_low)


def classify_file_asprs(src, *, cloud: str, report: Optional[str] = None,
                        options: Optional[ClassifyOptions] = None, hag: bool = False,
                        render=None, lang: str = "en", names=None, progress=None,
                        cancel=None) -> Classification:
    """Classify a LAS/LAZ file and write the classified copy (and report) all or none.

    Every attribute but the classification, every VLR/EVLR and the CRS are copied
    unchanged (:func:`~..io.las.write_las_like`); ``hag`` adds the float32 extra-bytes
    dimension ``HeightAboveGround`` (the data's vertical unit; the extra-bytes VLR is
    rewritten to declare it).

    Parameters
    ----------
    src : path
        Input LAS/LAZ in a projected CRS.
    cloud : path
        Classified output (.las/.laz).
    report : path, optional
        HTML report.
    options : ClassifyOptions, optional
    hag : bool
        Also write the height above ground.
    render : callable(Report) -> str, optional
        HTML renderer (the algorithm's, in the interface language); default
        :func:`~..reporting.render_html` in ``lang``.
    names : (str, str), optional
        Parameter names of the cloud and report outputs in error messages.

    Returns
    -------
    Classification
    """
    from ..io.contract import OutputContract
    from ..io.las import write_las_like
    from ..reporting import render_html
    from .pipeline import read_cloud
    mon = Monitor(progress, cancel)
    cloud_name, report_name = names or ("OUTPUT", "OUTPUT_HTML")
    outputs = {cloud_name: cloud, report_name: report}
    with OutputContract(outputs, inputs={"INPUT": src}, point_clouds=[cloud_name]) as out:
        t0 = time.perf_counter()
        # records kept for the copy: the input is decoded once (up to KEEP_RECORDS_MAX)
        pd = read_cloud(src, returns=False, keep_records=True, monitor=mon.sub(0.0, 0.1))
        t_read = time.perf_counter() - t0
        # read_cloud converts the coordinates to metres; heights go back to the data's
        # vertical unit for the HeightAboveGround dimension
        units = pd.info.units
        res = classify_points(pd.x, pd.y, pd.z, pd["classification"], options=options,
                              crs=pd.info.crs, progress=mon.sub(0.1, 0.85).update,
                              cancel=mon.cancelled)
        res.hag = (res.hag / units.v).astype(np.float32)
        res.units = units
        t1 = time.perf_counter()
        write_las_like(src, out.path(cloud_name),
                       dimensions={"classification": res.classes.astype(
                           pd["classification"].dtype)},
                       extra={HAG_DIMENSION: res.hag} if hag else None,
                       records=pd.records, progress=mon.sub(0.85, 0.98).update,
                       cancel=mon.cancelled)
        res.seconds.update(read=t_read, write=time.perf_counter() - t1)
        if out.requested(report_name):
            rep = classify_report(res, os.path.basename(os.fspath(src)), pd.x, pd.y,
                                  lang=lang)
            out.write_text(report_name, (render or (lambda r: render_html(r, lang=lang)))(rep))
        mon.check()
    mon.update(1.0)
    return res


def classify_report(res: Classification, name: str, x, y, *, lang: str = "en"):
    """Report content: summary, class counts (input and output), class map, settings."""
    from ..io.units import units_rows
    from ..reporting import KeyValues, Paragraph, Report, T, Table, translator
    from .figures import class_map
    tr = translator(lang)
    opt = res.options
    n = int(res.classes.size)
    rep = Report("ASPRS classification report",
                 citation="ASPRS LAS 1.4 R15 standard classes; vegetation heights after "
                 "IGN LiDAR HD (2023); Kostrikov et al. (2020), ELiT.")
    c = res.counts
    rep.summary.append(Paragraph(T(
        "{n} points: {g} ground, {v} vegetation, {b} building, {z} low noise.", n=n,
        g=c.get(GROUND, 0), v=c.get(LOW_VEG, 0) + c.get(MEDIUM_VEG, 0) + c.get(HIGH_VEG, 0),
        b=c.get(BUILDING, 0), z=c.get(LOW_NOISE, 0))))
    nb = len(res.buildings.buildings) if res.buildings is not None else 0
    rep.section("Input").add(KeyValues([("Point cloud", name), ("Points", n),
                                        *units_rows(res.units), ("Buildings", nb)]))
    keys = sorted(set(res.input_counts) | set(c))
    rows = [(k, T(ASPRS_NAMES.get(k, "other class")), res.input_counts.get(k, 0),
             c.get(k, 0), 100.0 * c.get(k, 0) / max(n, 1)) for k in keys]
    rep.section("Classes (ASPRS)").add(Table(["Class", "Meaning", "Input points",
                                              "Output points", "% of output"], rows,
                                             digits=[0, None, 0, 0, 2]))
    rep.section("Class map").add(class_map(x, y, res.classes, tr))
    if res.buildings is not None and res.buildings.buildings:
        from .buildings import buildings_section
        buildings_section(rep, res.buildings)
    rep.section("Parameters").add(KeyValues([
        ("Ground", T("recommended ground filter") if opt.ground == "filter"
         else T("input class 2 kept")),
        ("Low vegetation up to (m)", opt.low_max),
        ("Medium vegetation up to (m)", opt.medium_max),
        ("Buildings (class 6)", opt.buildings),
        ("Minimum building height above ground (m)", opt.min_height),
        ("Keep other input classes", opt.keep_other),
        ("DTM cell size (m)", opt.dtm_cell)]))
    sec = res.seconds
    rep.section("Computation").add(KeyValues([
        ("Reading (s)", sec.get("read")), ("Ground (s)", sec.get("ground")),
        ("DTM and heights (s)", sec.get("dtm")), ("Buildings (s)", sec.get("buildings")),
        ("Writing (s)", sec.get("write"))], digits=2))
    return rep

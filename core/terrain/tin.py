"""TIN DTM: linear interpolation on the Delaunay triangulation of the ground points.

Every cell centre inside a triangle takes the plane through its three vertices
(barycentric weights), the method of ``gdal_grid -a linear`` and of lidR's
``tin()``; the triangulation is Qhull's (Barber et al. 1996) through
:class:`scipy.spatial.Delaunay`. Triangles with an edge longer than ``max_edge`` are
dropped, so a gap in the ground points (under a building, over water) stays nodata
instead of being bridged by a long flat facet — unless the caller asks to fill it.
Cells outside the convex hull of the points are always nodata (a TIN does not
extrapolate). Grid conventions are those of :mod:`.grid` (cell centres, snapping).

References
----------
Delaunay, B. (1934). Sur la sphère vide. Bull. Acad. Sci. URSS, 6, 793–800.
Barber, C. B., Dobkin, D. P., Huhdanpaa, H. (1996). The Quickhull algorithm for
convex hulls. ACM TOMS 22(4), 469–483.
"""
from __future__ import annotations

from dataclasses import dataclass
from typing import Optional

import numpy as np

from ..coords import as_xyz
from ..errors import InputError
from ..progress import Monitor
from .grid import GridSpec, check_memory, default_max_distance

#: Cells interpolated per block (bounds the memory of the barycentric arrays).
BLOCK_CELLS = 1 << 20


@dataclass
class TinResult:
    """A TIN DTM and facts for the report.

    Attributes
    ----------
    z : ndarray
        Grid of heights (NaN = nodata), shape ``grid.shape``.
    n_points : int
        Points triangulated.
    n_triangles : int
        Triangles of the Delaunay triangulation.
    n_long : int
        Triangles dropped for an edge longer than ``max_edge``.
    max_edge : float or None
        Edge limit used (None when gaps are filled).
    cell_edge2 : ndarray or None
        With ``cell_edges``: per cell, the smallest longest-edge² of the kept triangles
        holding its centre (``inf`` outside them) — the edge test of another limit,
        applied afterwards (a catalog's gap distance, :mod:`..lidar._gap`).
    """

    z: np.ndarray
    n_points: int
    n_triangles: int
    n_long: int
    max_edge: Optional[float]
    cell_edge2: Optional[np.ndarray] = None


def default_max_edge(grid: GridSpec, n_points: int) -> float:
    """Return the automatic edge limit: twice :func:`.grid.default_max_distance`.

    A cell in the middle of an accepted edge is then at most the IDW gap distance
    (five mean point spacings, at least two cells) from a data point.
    """
    return 2.0 * default_max_distance(grid, n_points)


#: Quantum (m) of the local coordinates the triangulation sees: finer than any LAS
#: scale in use (0.001–0.01 m), coarse enough that the same cloud moved by a whole
#: number of quanta gives bit-identical local coordinates.
LOCAL_QUANTUM = 1e-4


def _local(v):
    """Local coordinates of ``v`` on the :data:`LOCAL_QUANTUM` lattice and their origin.

    ``round(v / q)`` are whole numbers (exact in float64 up to 9e15 q); subtracting
    their minimum is exact, so the local coordinates — and with them Qhull's
    triangulation and every tie it breaks — do not depend on where the cloud lies.
    """
    k = np.round(v / LOCAL_QUANTUM)
    k0 = float(k.min())
    return (k - k0) * LOCAL_QUANTUM, k0 * LOCAL_QUANTUM


def _triangulate(x, y):
    """Delaunay triangulation of the quantised local coordinates (the topology).

    Returns ``(tri, x0, y0, xy)``: ``xy`` are the exact local coordinates ``x - x0``,
    ``y - y0`` the planes are interpolated on (a plane is reproduced to 1e-9 m).
    """
    from scipy.spatial import Delaunay, QhullError
    xl, x0 = _local(x)
    yl, y0 = _local(y)
    try:
        tri = Delaunay(np.column_stack([xl, yl]))
    except QhullError as exc:
        raise InputError(
            "The points cannot be triangulated (fewer than three points, or all on one "
            "line); a TIN DTM needs ground points spread over an area.") from exc
    return tri, x0, y0, np.column_stack([x - x0, y - y0])


def _spatial_order(x, y) -> np.ndarray:
    """Return an order of the points by coarse cells (row-major): Qhull runs faster."""
    side = max(float(np.ptp(x)), float(np.ptp(y)), 1e-9) / max(np.sqrt(x.size) / 8, 1.0)
    cx = np.floor((x - x.min()) / side).astype(np.int64)
    cy = np.floor((y - y.min()) / side).astype(np.int64)
    return np.lexsort((cx, cy))


def _edge2(tri) -> np.ndarray:
    """Squared edge lengths of every simplex, ``(m, 3)``."""
    p = tri.points[tri.simplices]                       # (m, 3, 2)
    e = p - np.roll(p, 1, axis=1)
    return np.einsum("mki,mki->mk", e, e)


def _long_triangles(tri, max_edge: float) -> np.ndarray:
    """Flag the simplices with an edge longer than ``max_edge``."""
    return (_edge2(tri) > max_edge * max_edge).any(axis=1)


def _cell_ranges(lo, hi, origin, cell, n, flip=False):
    """First and last cell index whose centre lies in ``[lo, hi]`` (clipped)."""
    if flip:   # rows count southwards from ymax
        lo, hi = origin - hi, origin - lo
    else:
        lo, hi = lo - origin, hi - origin
    first = np.maximum(np.ceil(lo / cell - 0.5), 0).astype(np.int64)
    last = np.minimum(np.floor(hi / cell - 0.5), n - 1).astype(np.int64)
    return first, last


def _rasterise(tri, xy, z, keep, grid: GridSpec, x0: float, y0: float,
               mon, edge2=None):
    """Scan-convert the kept triangles: every cell centre inside gets the plane value.

    Candidate cells are the cell centres in each triangle's bounding box, enumerated in
    chunks of about :data:`BLOCK_CELLS`; a centre on a shared edge gets the same value
    from either triangle (the surface is continuous). With ``edge2`` (the longest
    edge² of every simplex) also returns, per cell, the smallest of those of the kept
    triangles holding its centre (``inf`` elsewhere): ``(z, cell_edge2)``.
    """
    simp = tri.simplices[keep]
    e2 = None if edge2 is None else edge2[keep]
    emin = None if edge2 is None else np.full(grid.size, np.inf)
    px = xy[:, 0][simp]                               # (m, 3), local coordinates
    py = xy[:, 1][simp]
    c0, c1 = _cell_ranges(px.min(1), px.max(1), grid.xmin - x0, grid.cell, grid.ncols)
    r0, r1 = _cell_ranges(py.min(1), py.max(1), grid.ymax - y0, grid.cell, grid.nrows,
                          flip=True)
    nc = np.clip(c1 - c0 + 1, 0, None)
    count = nc * np.clip(r1 - r0 + 1, 0, None)
    out = np.full(grid.size, np.nan)
    cum = np.cumsum(count)
    bounds = np.searchsorted(cum, np.arange(BLOCK_CELLS, cum[-1] + BLOCK_CELLS,
                                            BLOCK_CELLS)) if cum.size and cum[-1] else []
    t0 = 0
    for k, t1 in enumerate(bounds):
        t1 = min(int(t1) + 1, len(simp))
        sl = slice(t0, t1)
        ids = np.repeat(np.arange(t0, t1), count[sl])
        offset = np.arange(ids.size) - np.repeat(cum[sl] - count[sl] - (cum[t0 - 1] if t0
                                                                         else 0), count[sl])
        col = c0[ids] + offset % nc[ids]
        row = r0[ids] + offset // np.maximum(nc[ids], 1)
        qx = grid.xmin - x0 + (col + 0.5) * grid.cell
        qy = grid.ymax - y0 - (row + 0.5) * grid.cell
        ax, ay = px[ids], py[ids]
        det = (ay[:, 1] - ay[:, 2]) * (ax[:, 0] - ax[:, 2]) + \
            (ax[:, 2] - ax[:, 1]) * (ay[:, 0] - ay[:, 2])
        l0 = ((ay[:, 1] - ay[:, 2]) * (qx - ax[:, 2])
              + (ax[:, 2] - ax[:, 1]) * (qy - ay[:, 2])) / det
        l1 = ((ay[:, 2] - ay[:, 0]) * (qx - ax[:, 2])
              + (ax[:, 0] - ax[:, 2]) * (qy - ay[:, 2])) / det
        l2 = 1.0 - l0 - l1
        eps = -1e-12
        inside = (l0 >= eps) & (l1 >= eps) & (l2 >= eps)
        zt = z[simp[ids[inside]]]
        flat = row[inside] * grid.ncols + col[inside]
        out[flat] = l0[inside] * zt[:, 0] + l1[inside] * zt[:, 1] + l2[inside] * zt[:, 2]
        if emin is not None:        # the smallest over a centre's triangles (shared edges)
            ev = e2[ids[inside]]
            smaller = ev < emin[flat]
            while smaller.any():
                emin[flat[smaller]] = ev[smaller]
                smaller = ev < emin[flat]
        t0 = t1
        mon.step((k + 1) / len(bounds))
        if t0 >= len(simp):
            break
    if emin is not None:
        return out.reshape(grid.shape), emin.reshape(grid.shape)
    return out.reshape(grid.shape)


def tin_grid(x, y, z, grid: GridSpec, *, max_edge: Optional[float] = None,
             fill: bool = False, cell_edges: bool = False, progress=None,
             cancel=None) -> TinResult:
    """Interpolate points onto ``grid`` linearly inside their Delaunay triangles.

    Parameters
    ----------
    x, y, z : array_like
        Ground points (CRS units, metres).
    grid : GridSpec
        Output grid; values belong to cell centres.
    max_edge : float, optional
        Longest triangle edge kept (m); cells in longer triangles are nodata. Default:
        :func:`default_max_edge`.
    fill : bool
        Keep every triangle (``max_edge`` ignored): gaps inside the hull are bridged.
    cell_edges : bool
        Also return :attr:`TinResult.cell_edge2` (another edge limit applied later).
    progress, cancel : callable, optional
        See :class:`~..progress.Monitor`.

    Returns
    -------
    TinResult

    Raises
    ------
    InputError
        Fewer than three points, collinear points, or a non-positive ``max_edge``.

    Notes
    -----
    Equals ``gdal_grid -a linear:radius=0`` (Qhull triangulation, nodata outside the
    hull) for points in general position.
    """
    x, y, z = as_xyz(x, y, z, empty_error="No points to triangulate.")
    if x.size < 3:
        raise InputError("A TIN needs at least three points, got {n}.", n=x.size)
    if max_edge is not None and not max_edge > 0:
        raise InputError("max_edge must be > 0 (m), got {max_edge}; leave it empty for "
                         "the automatic value or fill the gaps instead.", max_edge=max_edge)
    check_memory(grid, arrays=2)
    mon = Monitor(progress, cancel)
    mon.step(0.0)
    order = _spatial_order(x, y)
    x, y, z = x[order], y[order], z[order]
    tri, x0, y0, xy = _triangulate(x, y)
    mon.step(0.3)
    edge = None if fill else (max_edge or default_max_edge(grid, x.size))
    e2 = _edge2(tri).max(axis=1) if cell_edges else None
    bad = (_long_triangles(tri, edge) if edge is not None
           else np.zeros(len(tri.simplices), bool))
    out = _rasterise(tri, xy, z, ~bad, grid, x0, y0, mon.sub(0.3, 1.0), edge2=e2)
    out, cell_e2 = out if cell_edges else (out, None)
    return TinResult(out, int(x.size), int(len(tri.simplices)), int(bad.sum()), edge,
                     cell_e2)

"""Vectorised TIN of progressive TIN densification (scipy Qhull, private).

After Axelsson, P. (2000). DEM generation from laser scanner data using adaptive
TIN models. IAPRS XXXIII-B4, 110-117.

:class:`Tin` wraps one Qhull Delaunay triangulation with what the densification
reads: counter-clockwise facets with their neighbours, unit normals, vertices and
longest edges, and a point location that walks the triangulation from a given
start facet (all queries at once, in numpy). The walk replaces scipy's
``find_simplex``, whose first call computes a barycentric transform for every
facet — as long as the triangulation itself — on every rebuild.
"""
from __future__ import annotations

import numpy as np
from scipy.spatial import Delaunay, cKDTree

from ..terrain.grid import pick_per_cell

__all__ = ["Tin", "cell_index", "lowest_per_cell", "dedupe_xy", "cKDTree", "one_layer"]

#: Points per block of the vectorised per-point steps (bounds temporary memory).
CHUNK = 1 << 17
#: Longest walk (facets crossed) of :meth:`Tin.locate` before scipy takes over.
MAX_WALK = 4096
#: Qhull options of every TIN. ``Q5`` skips Qhull's final outer-plane check
#: (qh_check_maxout: bounds for its own verification, coplanar-point bookkeeping); the
#: facets, their order and neighbours are the same (checked equal on all 57 TINs of a
#: 1 M-point densification) and Qhull runs 11-16 % faster.
QHULL_OPTIONS = "Qbb Qc Qz Q12 Q5"


def cell_index(x, y, x0, y0, cell, ncols):
    """Row-major flat cell index of every point on a grid with origin (x0, y0)."""
    col = ((x - x0) // cell).astype(np.int64)
    row = ((y - y0) // cell).astype(np.int64)
    return row * ncols + col


def lowest_per_cell(idx, z):
    """Return the indices of the lowest point of every occupied cell (``idx`` = flat cell ids)."""
    return pick_per_cell(idx, z, "lowest")


def dedupe_xy(x, y, z, resolution: float = 0.01):
    """Return the indices of the lowest point of each ``resolution``-sized xy cell.

    Delaunay needs distinct xy positions; the other points of a cell are
    classified afterwards against the final surface.

    Parameters
    ----------
    x, y, z : ndarray
        Coordinates (m).
    resolution : float
        Cell size (m).

    Returns
    -------
    ndarray of int
        Indices of the kept points.
    """
    # rounded, not floored: positions on a centimetre grid (LAS scale 0.01) fall in the
    # same cell whatever the local origin (floor(x / 0.01) flips on rounding)
    idx = ((np.round(y / resolution).astype(np.int64) << 32)
           + np.round(x / resolution).astype(np.int64))
    return lowest_per_cell(idx, z)


class Tin:
    """Delaunay TIN of the vertices (x, y, z), built once by Qhull.

    Attributes
    ----------
    xy : ndarray, shape (m, 2)
        Vertex positions.
    z : ndarray, shape (m,)
        Vertex heights.
    simplices, neighbors : ndarray of int, shape (k, 3)
        Counter-clockwise facets; ``neighbors[f, i]`` is the facet across the edge
        opposite vertex ``i`` (-1 on the hull).
    normal : ndarray, shape (k, 3)
        Unit upward normals.
    corners : ndarray, shape (k, 3, 3)
        Facet vertices (x, y, z).
    edge : ndarray, shape (k,)
        Longest horizontal edge of each facet.
    vertex_facet : ndarray, shape (m,)
        One facet of each vertex (a walk's start).

    Parameters
    ----------
    x, y, z : ndarray
        Vertices; distinct xy positions.
    """

    def __init__(self, x, y, z):
        self.xy = np.column_stack((x, y))
        self.z = np.asarray(z, dtype=float)
        tri = Delaunay(self.xy, qhull_options=QHULL_OPTIONS)
        s, nb = tri.simplices.copy(), tri.neighbors.copy()
        del tri
        p = self.xy[s]
        cw = ((p[:, 1, 0] - p[:, 0, 0]) * (p[:, 2, 1] - p[:, 0, 1])
              - (p[:, 1, 1] - p[:, 0, 1]) * (p[:, 2, 0] - p[:, 0, 0])) < 0
        s[cw, 1], s[cw, 2] = s[cw, 2], s[cw, 1].copy()
        nb[cw, 1], nb[cw, 2] = nb[cw, 2], nb[cw, 1].copy()
        self.simplices, self.neighbors = s, nb
        self.vertex_facet = np.zeros(self.z.size, dtype=np.int64)
        self.vertex_facet[s.ravel()] = np.repeat(np.arange(s.shape[0]), 3)
        c = np.concatenate((self.xy[s], self.z[s][..., None]), axis=2)
        n = np.cross(c[:, 1] - c[:, 0], c[:, 2] - c[:, 0])
        n /= np.linalg.norm(n, axis=1)[:, None] + 1e-300
        n *= np.where(n[:, 2] < 0, -1.0, 1.0)[:, None]
        self.normal, self.corners = n, c
        e = np.stack([np.hypot(*(c[:, i, :2] - c[:, (i + 1) % 3, :2]).T) for i in range(3)])
        self.edge = e.max(axis=0)
        self._tree = None
        self._opposite = None

    def regional_tan(self, rings: int = 1):
        """Tangent of the slope of each facet's neighbourhood (facet and edge neighbours).

        The slope of the area-weighted mean normal of the facet and the facets across
        its edges, ``rings`` times over: a steep facet on steep terrain keeps its slope,
        one that is steep only because a vertex stands above its neighbours (a shrub
        taken for ground) does not, since the facets around that vertex tilt every way.
        """
        c = self.corners
        n = np.cross(c[:, 1] - c[:, 0], c[:, 2] - c[:, 0])     # length = 2 x area, up
        for _ in range(rings):
            n = n + np.where(self.neighbors[..., None] >= 0, n[self.neighbors], 0.0).sum(axis=1)
        return np.hypot(n[:, 0], n[:, 1]) / np.maximum(n[:, 2], 1e-300)

    @property
    def opposite(self):
        """Vertex of each edge neighbour opposite the shared edge, shape (k, 3); -1 on the hull."""
        if self._opposite is None:
            s, nb = self.simplices, self.neighbors
            g = np.where(nb >= 0, nb, 0)
            shared = np.stack([s[:, (i + 1) % 3] + s[:, (i + 2) % 3] for i in range(3)], axis=1)
            self._opposite = np.where(nb >= 0, s[g].sum(axis=2) - shared, -1)
        return self._opposite

    @property
    def tree(self):
        """KD-tree of the vertices in xy (built when first asked for)."""
        if self._tree is None:
            self._tree = cKDTree(self.xy)
        return self._tree

    def locate(self, qx, qy, start=None):
        """Facet of every query point, walking from ``start`` (one facet per point).

        Visibility walk: a point is moved across the edge it lies farthest outside
        of until it is inside (or on the boundary of) its facet. A point outside the
        hull stops at the hull facet where its walk leaves the TIN. Without ``start``
        the walk starts at a facet of the nearest vertex.

        Parameters
        ----------
        qx, qy : ndarray
            Query points.
        start : ndarray of int, optional
            Start facet per point.

        Returns
        -------
        ndarray of int64
            A facet holding each point (its nearest hull facet when outside).
        """
        qx, qy = np.asarray(qx, float), np.asarray(qy, float)
        if start is None:
            start = self.vertex_facet[self.tree.query(np.column_stack((qx, qy)))[1]] \
                if qx.size else np.zeros(0, np.int64)
        f = np.array(start, dtype=np.int64)
        act = np.arange(qx.size)
        for _ in range(MAX_WALK):
            if act.size == 0:
                return f
            out, nb = self._outside(f[act], qx[act], qy[act])
            move = out & (nb >= 0)
            f[act[move]] = nb[move]
            act = act[move]
        # a safety net never seen to trigger: Qhull rebuilds the same facets in the
        # same order (only their vertex order differs), so scipy's index is ours
        rest = Delaunay(self.xy, qhull_options=QHULL_OPTIONS).find_simplex(
            np.column_stack((qx[act], qy[act])))
        f[act[rest >= 0]] = rest[rest >= 0]
        return f

    def _outside(self, f, px, py):
        """Whether each point is outside its facet ``f``, and the facet to move to."""
        sv = self.simplices[f]
        o = np.empty((f.size, 3))
        for i in range(3):
            a, b = self.xy[sv[:, (i + 1) % 3]], self.xy[sv[:, (i + 2) % 3]]
            o[:, i] = (b[:, 0] - a[:, 0]) * (py - a[:, 1]) - (b[:, 1] - a[:, 1]) * (px - a[:, 0])
        worst = np.argmin(o, axis=1)
        rows = np.arange(f.size)
        return o[rows, worst] < 0, self.neighbors[f, worst]

    def distances(self, qx, qy, qz, facet=None):
        """Signed perpendicular distance, vertical offset and largest vertex angle.

        Parameters
        ----------
        qx, qy, qz : ndarray
            Query points.
        facet : ndarray of int, optional
            Facet of every query point (:meth:`locate` when None).

        Returns
        -------
        tuple
            ``(d, dz, angle_deg, facet)``: ``d`` the signed distance to the facet
            plane (positive above), ``dz`` the vertical offset from the facet and
            ``angle_deg`` the largest angle between the facet and the lines from the
            point to the facet's three vertices (Axelsson 2000).
        """
        if facet is None:
            facet = self.locate(qx, qy)
        d, dz, angle = (np.empty(facet.size) for _ in range(3))
        for a in range(0, facet.size, CHUNK):
            b = min(a + CHUNK, facet.size)
            nn, v = self.normal[facet[a:b]], self.corners[facet[a:b]]
            q = np.column_stack((qx[a:b], qy[a:b], qz[a:b]))
            d[a:b] = np.einsum("ij,ij->i", q - v[:, 0], nn)
            dz[a:b] = d[a:b] / np.maximum(nn[:, 2], 1e-6)
            length = np.sqrt(((q[:, None, :] - v) ** 2).sum(axis=2)).min(axis=1)
            angle[a:b] = np.degrees(np.arcsin(np.clip(np.abs(d[a:b]) / np.maximum(length, 1e-9),
                                                      0.0, 1.0)))
        return d, dz, angle, facet


#: Facets steeper than this (degrees) and rising more than ``max_distance`` span a
#: breakline (cliff foot to cliff top) for :func:`breakline_test`.
BREAKLINE_SLOPE = 45.0


def mirror_test(tin, cx, cy, cz, s, d, ok, opt, steep=None):
    """Axelsson's mirroring for candidates near breaklines (in place).

    A rejected candidate is mirrored through the nearest vertex of
    the facet (M = 2 V - P); when M passes the distance and angle tests the
    candidate is accepted and its distance set to M's. Candidates in a steep facet
    (a facet spanning a cliff) get :func:`breakline_test` as well.
    """
    test = np.flatnonzero(~ok)
    if test.size == 0 or opt.mirror == "none":
        return
    if steep is not None:
        breakline_test(tin, cx, cy, cz, s, d, ok, opt, steep)
        test = np.flatnonzero(~ok)
    v = tin.corners[s[test]]
    p = np.column_stack((cx[test], cy[test], cz[test]))
    if opt.mirror == "below":
        below = np.einsum("ij,ij->i", p - v[:, 0], tin.normal[s[test]]) < 0
        test, v, p = test[below], v[below], p[below]
        if test.size == 0:
            return
    near = np.argmin(((p[:, None, :] - v) ** 2).sum(axis=2), axis=1)
    m = 2.0 * v[np.arange(test.size), near] - p
    start = tin.vertex_facet[tin.simplices[s[test], near]]
    dm, _, am, _ = tin.distances(m[:, 0], m[:, 1], m[:, 2], tin.locate(m[:, 0], m[:, 1], start))
    good = (np.abs(dm) <= opt.max_distance) & (am <= opt.max_angle)
    ok[test[good]] = True
    d[test[good]] = np.abs(dm[good])


def breakline_facets(tin, opt):
    """Flag facets steeper than ``BREAKLINE_SLOPE`` that rise more than ``max_distance``."""
    rise = np.ptp(tin.z[tin.simplices], axis=1)
    return (tin.normal[:, 2] < np.cos(np.radians(BREAKLINE_SLOPE))) & (rise > opt.max_distance)


def breakline_test(tin, cx, cy, cz, s, d, ok, opt, steep):
    """Mirroring at cliffs: accept a candidate that continues the terrain beyond a vertex.

    A facet that spans a breakline (:func:`breakline_facets`: cliff foot to cliff
    top) says nothing about the candidates inside it. Such a rejected candidate P
    is mirrored (M = 2 V - P, Axelsson 2000, who uses the nearest facet vertex only)
    through each of the facet's three vertices and through the three TIN vertices
    nearest to it in 3D, which at a cliff are often not vertices of its facet; only
    vertices within two cells of P count. P is accepted when some M falls in a
    facet that does not span a breakline and lies within ``final_distance`` of it
    vertically, i.e. P continues the cliff foot or cliff top surface through V.
    In place, like :func:`mirror_test`.
    """
    test = np.flatnonzero(~ok & steep[s])
    if test.size == 0:
        return
    p = np.column_stack((cx[test], cy[test], cz[test]))
    vert = np.column_stack((tin.xy, tin.z))
    near = cKDTree(vert).query(p, k=min(3, tin.z.size))[1].reshape(test.size, -1)
    vid = np.concatenate((tin.simplices[s[test]], near), axis=1)
    v = vert[vid]
    far = (np.linalg.norm(v - p[:, None, :], axis=2) > 2.0 * opt.cell).ravel()
    m = (2.0 * v - p[:, None, :]).reshape(-1, 3)
    sm = tin.locate(m[:, 0], m[:, 1], tin.vertex_facet[vid.ravel()])
    _, dz, _, _ = tin.distances(m[:, 0], m[:, 1], m[:, 2], sm)
    off = np.where(steep[sm] | far, np.inf, np.abs(dz)).reshape(test.size, -1).min(axis=1)
    good = off <= opt.final_distance
    ok[test[good]] = True
    d[test[good]] = off[good]


def one_layer(tin, x, y, z, s, ok, n_ground, rise, cliff, opt):
    """Ground is one layer: un-accept (in place) points standing on lower ground.

    A point of ``ok`` more than ``final_distance`` plus the terrain's rise over the
    distance (``rise``: the tangent of the slope of its facet's neighbourhood,
    :meth:`Tin.regional_tan`) above a ground vertex within ``cell`` of its facet or
    the three facets next to it is not ground; vertices of facets that span a
    breakline (``cliff``, :func:`breakline_facets`) are not compared with, as a cliff
    top stands above its foot. In low vegetation the lowest return of a 1 m cell is
    often a shrub, so the TIN rises into it and the final pass's band took the
    shrub's upper returns (mixed-conifer: cells up to +1.26 m above the vendor DTM);
    the ground vertices beside them give them away.
    """
    if n_ground == 0:
        return
    vid = np.concatenate((tin.simplices, tin.opposite), axis=1)     # per facet
    real = (vid >= 0) & (vid < n_ground)       # not missing, not a virtual frame point
    vid = np.where(real, vid, 0)
    real &= ~cliff[vid]
    floor = np.where(real, tin.z[vid], np.inf).min(axis=1)
    idx = np.flatnonzero(ok)
    # only a point above its neighbourhood's lowest vertex by more than the final
    # distance can fail (the rise term is >= 0): the others skip the distances
    idx = idx[z[idx] - floor[s[idx]] > opt.final_distance]
    if idx.size == 0:
        return
    f = s[idx]
    v, near = vid[f], real[f]
    dist = np.hypot(tin.xy[v, 0] - x[idx, None], tin.xy[v, 1] - y[idx, None])
    near &= dist <= opt.cell
    over = near & (z[idx, None] - tin.z[v] > opt.final_distance + rise[f, None] * dist)
    ok[idx[over.any(axis=1)]] = False

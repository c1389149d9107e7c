"""Vectorised TIN of progressive TIN densification (scipy Qhull, private).

After Axelsson, P. (2000). DEM generation from laser scanner data using adaptive
TIN models. IAPRS XXXIII-B4, 110-117.

:class:`Tin` wraps one Qhull Delaunay triangulation with what the densification
reads: counter-clockwise facets with their neighbours, unit normals, vertices and
longest edges, and a point location that walks the triangulation from a given
start facet (all queries at once, in numpy). The walk replaces scipy's
``find_simplex``, whose first call computes a barycentric transform for every
facet — as long as the triangulation itself — on every rebuild. :func:`insert` adds
points to a TIN by re-triangulating (Qhull) only the facets whose circumcircle holds one
of them (Bowyer-Watson's cavity) and splicing the new facets in.
"""
from __future__ import annotations

import numpy as np
from scipy.spatial import Delaunay, QhullError, cKDTree

from ..terrain.grid import pick_per_cell

__all__ = ["Tin", "cell_index", "lowest_per_cell", "dedupe_xy", "cKDTree", "one_layer", "insert",
           "jitter"]

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


#: Amplitude (m) of :func:`jitter`.
JITTER = 1e-4


def jitter(x, y, z):
    """Return a tiny xy offset of every point, a fixed function of its world position.

    Points on a centimetre grid are often exactly co-circular, on a facet's edge or
    right above a TIN vertex; Qhull's triangulation of such ties, and the facet such a
    point is located in, would depend on the other points (the extent of the cloud,
    the order Qhull meets them). Offsets of at most ``JITTER`` / 2 hashed from the
    position (x, y, z) rounded to a millimetre break every tie the same way in a
    catalog chunk and in the whole cloud.
    """
    kx, ky, kz = (np.round(np.asarray(v) * 1000.0).astype(np.int64).view(np.uint64)
                  for v in (x, y, z))
    with np.errstate(over="ignore"):
        h = _mix(kx * np.uint64(0x9E3779B97F4A7C15) ^ _mix(ky ^ _mix(kz)))
        u = (h >> np.uint64(11)).astype(np.float64) / float(1 << 53) - 0.5
        v = (_mix(h) >> np.uint64(11)).astype(np.float64) / float(1 << 53) - 0.5
    return JITTER * u, JITTER * v


def _mix(h):
    """SplitMix64 finaliser of uint64 ``h`` (wrapping)."""
    with np.errstate(over="ignore"):
        h = (h ^ (h >> np.uint64(30))) * np.uint64(0xBF58476D1CE4E5B9)
        h = (h ^ (h >> np.uint64(27))) * np.uint64(0x94D049BB133111EB)
        return h ^ (h >> np.uint64(31))


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

    def __init__(self, x, y, z, topology=None, known=None):
        self.xy = np.column_stack((x, y))
        self.z = np.asarray(z, dtype=float)
        if topology is None:
            tri = Delaunay(self.xy, qhull_options=QHULL_OPTIONS)
            s, nb = _ccw(self.xy, tri.simplices.copy(), tri.neighbors.copy())
            del tri
        else:
            s, nb = topology
        self.simplices, self.neighbors = s, nb
        self.vertex_facet = np.zeros(self.z.size, dtype=np.int64)
        self.vertex_facet[s.ravel()] = np.repeat(np.arange(s.shape[0]), 3)
        if known is None:
            self.corners, self.normal, self.edge = _geometry(self.xy, self.z, s)
        else:       # (rows, corners, normal, edge) of facets an insert left as they were
            rows, c, n, e = known
            self.corners, self.normal = np.empty((s.shape[0], 3, 3)), np.empty((s.shape[0], 3))
            self.edge = np.empty(s.shape[0])
            self.corners[rows], self.normal[rows], self.edge[rows] = c, n, e
            redo = np.ones(s.shape[0], dtype=bool)
            redo[rows] = False
            redo = np.flatnonzero(redo)
            self.corners[redo], self.normal[redo], self.edge[redo] = _geometry(
                self.xy, self.z, s[redo])
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
        hull = [np.zeros(0, np.int64)]
        for _ in range(MAX_WALK):
            if act.size == 0:
                break
            out, nb = self._outside(f[act], qx[act], qy[act])
            move = out & (nb >= 0)
            hull.append(act[out & (nb < 0)])
            f[act[move]] = nb[move]
            act = act[move]
        if act.size == 0:
            # outside the hull the walk stops at a hull facet that depends on the path
            # (on the facets' order): take the nearest one instead
            hull = np.concatenate(hull)
            f[hull] = self._nearest_hull(qx[hull], qy[hull])
            return f
        # a safety net never seen to trigger (scipy's facets matched by their vertices)
        tri = Delaunay(self.xy, qhull_options=QHULL_OPTIONS)
        rest = tri.find_simplex(np.column_stack((qx[act], qy[act])))
        ours = {tuple(v): i for i, v in enumerate(np.sort(self.simplices, axis=1).tolist())}
        for j, r in zip(act[rest >= 0], rest[rest >= 0]):
            f[j] = ours.get(tuple(sorted(tri.simplices[r].tolist())), f[j])
        return f

    def _nearest_hull(self, px, py):
        """Hull facet nearest to each point (ties: the hull edge of lowest vertex ids)."""
        f, i = np.nonzero(self.neighbors < 0)
        a, b = self.simplices[f, (i + 1) % 3], self.simplices[f, (i + 2) % 3]
        order = np.argsort(_edge_keys(a, b, self.z.size))
        f, a, b = f[order], self.xy[a[order]], self.xy[b[order]]
        out = np.empty(px.size, dtype=np.int64)
        step = max(1, CHUNK // max(f.size, 1))
        for lo in range(0, px.size, step):
            p = np.column_stack((px[lo:lo + step], py[lo:lo + step]))[:, None, :]
            ab, ap = b - a, p - a
            t = (ap * ab).sum(axis=2) / np.maximum((ab * ab).sum(axis=1), 1e-300)
            # the foot of the perpendicular, or exactly an end (equal distances tie exactly)
            foot = np.where(t[..., None] <= 0, a, np.where(t[..., None] >= 1, b,
                                                           a + t[..., None] * ab))
            out[lo:lo + step] = f[np.argmin(((p - foot) ** 2).sum(axis=2), axis=1)]
        return out

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


def _geometry(xy, z, s):
    """Corners (x, y, z), unit upward normals and longest horizontal edge of facets ``s``."""
    c = np.concatenate((xy[s], z[s][..., None]), axis=2)
    n = np.cross(c[:, 1] - c[:, 0], c[:, 2] - c[:, 0])
    n /= np.linalg.norm(n, axis=1)[:, None] + 1e-300
    n *= np.where(n[:, 2] < 0, -1.0, 1.0)[:, None]
    e = np.stack([np.hypot(*(c[:, i, :2] - c[:, (i + 1) % 3, :2]).T) for i in range(3)])
    return c, n, e.max(axis=0)


def _ccw(xy, s, nb):
    """Facets ``s`` and neighbours ``nb`` reordered counter-clockwise (in place)."""
    p = xy[s]
    cw = ((p[:, 1, 0] - p[:, 0, 0]) * (p[:, 2, 1] - p[:, 0, 1])
          - (p[:, 1, 1] - p[:, 0, 1]) * (p[:, 2, 0] - p[:, 0, 0])) < 0
    s[cw, 1], s[cw, 2] = s[cw, 2], s[cw, 1].copy()
    nb[cw, 1], nb[cw, 2] = nb[cw, 2], nb[cw, 1].copy()
    return s, nb


def _edge_keys(a, b, m):
    """One int64 key per edge (a, b) of vertex ids < ``m``, whatever its direction."""
    a, b = np.asarray(a, np.int64), np.asarray(b, np.int64)
    return np.minimum(a, b) * m + np.maximum(a, b)


def insert(tin, x, y, z, old_to_new, added, hint):
    """TIN of ``tin``'s vertices plus ``added``, re-triangulated only where they fall.

    The facets whose circumcircle holds an added point (the cavity, found by walking
    out from the facet holding it) are the ones a Delaunay rebuild replaces (Bowyer-
    Watson); the others stay. The cavity is re-triangulated by Qhull from its vertices
    and the added points (those of its facets fall inside the cavity) and spliced in.

    Parameters
    ----------
    tin : Tin
        The TIN before.
    x, y, z : ndarray
        Every vertex of the new TIN (heights may differ from ``tin``'s).
    old_to_new : ndarray of int
        Index in ``x`` of each vertex of ``tin`` (same xy).
    added : ndarray of int
        Indices in ``x`` of the added points.
    hint : ndarray of int
        Facet of ``tin`` holding each added point.

    Returns
    -------
    Tin or None
        None when the cavity's new facets do not tile it exactly (a Qhull tie
        decided otherwise): the caller rebuilds the TIN.
    """
    xy = np.column_stack((x, y))
    gone = _cavity(tin, xy[added], hint)
    s_old = old_to_new[tin.simplices]
    sub = np.r_[np.unique(s_old[gone]), added]
    try:
        tri = Delaunay(xy[sub], qhull_options=QHULL_OPTIONS)
    except QhullError:
        return None
    ts, tn = _ccw(xy[sub], tri.simplices.copy(), tri.neighbors.copy())
    f, i = np.nonzero(gone[:, None] & ((tin.neighbors < 0) | ~gone[tin.neighbors]))
    bkey = _edge_keys(s_old[f, (i + 1) % 3], s_old[f, (i + 2) % 3], x.size)
    ek = np.stack([_edge_keys(sub[ts[:, (j + 1) % 3]], sub[ts[:, (j + 2) % 3]], x.size)
                   for j in range(3)], axis=1)
    # flood the cavity from the facets of the added points, never across its boundary
    cross = (tn >= 0) & ~np.isin(ek, bkey)
    inside = np.zeros(ts.shape[0], dtype=bool)
    front = np.flatnonzero((ts >= sub.size - added.size).any(axis=1))
    while front.size:
        inside[front] = True
        nxt = tn[front][cross[front]]
        front = np.unique(nxt[~inside[nxt]])
    return _splice(tin, x, y, z, s_old, gone, sub[ts[inside]], ek[inside], (f, i, bkey),
                   added.size)


def _cavity(tin, p, hint):
    """Facets of ``tin`` whose circumcircle holds one of the points ``p`` (walk from ``hint``)."""
    nf = tin.simplices.shape[0]
    gone = np.zeros(nf, dtype=bool)
    gone[hint] = True
    fp, ff = np.arange(p.shape[0], dtype=np.int64), np.asarray(hint, np.int64)
    seen = np.unique(fp * nf + ff)
    while fp.size:
        g = tin.neighbors[ff].ravel()
        key = np.unique(np.repeat(fp, 3)[g >= 0] * nf + g[g >= 0])
        key = key[~np.isin(key, seen, assume_unique=True)]
        seen = np.union1d(seen, key)
        fp, ff = key // nf, key % nf
        v = tin.xy[tin.simplices[ff]] - p[fp][:, None, :]        # (k, 3, 2), CCW
        w = (v ** 2).sum(axis=2)
        det = (w[:, 0] * (v[:, 1, 0] * v[:, 2, 1] - v[:, 2, 0] * v[:, 1, 1])
               + w[:, 1] * (v[:, 2, 0] * v[:, 0, 1] - v[:, 0, 0] * v[:, 2, 1])
               + w[:, 2] * (v[:, 0, 0] * v[:, 1, 1] - v[:, 1, 0] * v[:, 0, 1]))
        fp, ff = fp[det > 0], ff[det > 0]
        gone[ff] = True
    return gone


def _area(x, y, s):
    """Total area of the triangles ``s``."""
    return np.abs((x[s[:, 1]] - x[s[:, 0]]) * (y[s[:, 2]] - y[s[:, 0]])
                  - (y[s[:, 1]] - y[s[:, 0]]) * (x[s[:, 2]] - x[s[:, 0]])).sum() / 2.0


def _splice(tin, x, y, z, s_old, gone, new, ek, boundary, n_added):
    """Return the TIN with the facets ``gone`` replaced by ``new`` (edge keys ``ek``), or None."""
    f, i, bkey = boundary
    nk, nn = int((~gone).sum()), new.shape[0]
    a0 = _area(x, y, s_old[gone])
    if nn != gone.sum() + 2 * n_added or abs(_area(x, y, new) - a0) > 1e-9 * max(a0, 1.0):
        return None
    flat = ek.ravel()
    order = np.argsort(flat, kind="stable")
    u, first, cnt = np.unique(flat[order], return_index=True, return_counts=True)
    single = cnt == 1
    if (cnt > 2).any() or single.sum() != bkey.size:
        return None
    bi = np.searchsorted(u[single], bkey)        # boundary edge -> its single new slot
    if not np.array_equal(u[single][np.minimum(bi, single.sum() - 1)], bkey):
        return None
    newid = np.full(gone.size, -1, dtype=np.int64)
    newid[~gone] = np.arange(nk)
    nb = np.full((nk + nn, 3), -1, dtype=np.int64)
    g = tin.neighbors[~gone]
    nb[:nk] = np.where(g >= 0, newid[np.maximum(g, 0)], -1)
    a, b = order[first[~single]], order[first[~single] + 1]      # shared inner edges
    nb[nk + a // 3, a % 3], nb[nk + b // 3, b % 3] = nk + b // 3, nk + a // 3
    e = order[first[single]][bi]                 # new slot of each boundary edge
    out = tin.neighbors[f, i]
    nb[nk + e // 3, e % 3] = np.where(out >= 0, newid[np.maximum(out, 0)], -1)
    o = out >= 0
    slot = np.argmax(tin.neighbors[out[o]] == f[o, None], axis=1)
    nb[newid[out[o]], slot] = nk + e[o] // 3
    # facets kept with the same vertex heights (frame points' heights change) keep their
    # geometry: the same numbers from the same vertices in the same order
    same = np.flatnonzero(~gone & (tin.z[tin.simplices] == z[s_old]).all(axis=1))
    known = (newid[same], tin.corners[same], tin.normal[same], tin.edge[same])
    return Tin(x, y, z, topology=(np.concatenate((s_old[~gone], new)), nb), known=known)


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

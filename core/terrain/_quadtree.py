"""GDAL's point quadtree order, for breaking IDW ties exactly as ``gdal_grid`` does.

Private to :mod:`.idw`. ``gdal_grid`` keeps equidistant neighbours in the order its
``CPLQuadTree`` returns them; :func:`gdal_quadtree_rank` rebuilds that order for every
point, :func:`gdal_quadtree_order` for a few points only (the ones a tied grid node
actually compares), with the same result and without building the whole tree.
"""
from __future__ import annotations

import numpy as np

__all__ = ["gdal_quadtree_rank", "gdal_quadtree_order"]


def _split(r, ratio):
    """Two halves of rectangles ``r`` along their longer side (each ``ratio`` of it)."""
    a0, a1, b0, b1 = r
    w, h = a1 - a0, b1 - b0
    sx = w > h
    cut1 = np.where(sx, a0 + w * ratio, b0 + h * ratio)
    cut2 = np.where(sx, a1 - w * ratio, b1 - h * ratio)
    first = (a0, np.where(sx, cut1, a1), b0, np.where(sx, b1, cut1))
    second = (np.where(sx, cut2, a0), a1, np.where(sx, b0, cut2), b1)
    return sx, cut1, first, second


def gdal_quadtree_rank(x, y, *, capacity: int = 8, ratio: float = 0.55) -> np.ndarray:
    """Rank of every point in the order GDAL's point quadtree returns them.

    ``gdal_grid`` inserts the points, in input order, into a ``CPLQuadTree`` over the
    points' bounding box (bucket capacity 8; a full leaf splits into four quadrants
    made by two successive splits of the longer side, each part 55 % of its parent so
    that they overlap; a point goes to the first quadrant that contains it). A
    search returns the features leaf by leaf in depth-first order, and within a leaf
    in input order. GDAL keeps equidistant neighbours in that order, so it decides
    which of two equidistant points is used at the ``max_points`` cut-off. Because a
    leaf splits exactly when a 9th point reaches it, the final tree depends only on
    the point set, and this vectorised level-by-level construction reproduces it.
    """
    x = np.asarray(x, np.float64)
    y = np.asarray(y, np.float64)
    n = x.size
    if n == 0:
        return np.empty(0, np.int64)

    def split(r):
        return _split(r, ratio)

    rects = tuple(np.array([v]) for v in (x.min(), x.max(), y.min(), y.max()))
    # the points still descending, compacted each level (contiguous arrays instead of
    # gathers from the full ones); a point leaves with its key and depth when its node
    # stops splitting (at most ``capacity`` points, or a degenerate rectangle)
    ax, ay = x, y
    ai = np.arange(n)
    anode = np.zeros(n, np.int64)
    akey = np.zeros(n, np.int64)
    key = np.zeros(n, np.int64)
    depth = np.zeros(n, np.int64)
    deep = []
    level = 0
    while ai.size:
        cnt = np.bincount(anode, minlength=rects[0].size)
        full_nodes = np.flatnonzero(cnt > capacity)
        if full_nodes.size == 0:
            break
        r = tuple(v[full_nodes] for v in rects)
        sx, cut, h1, h2 = split(r)
        sx1, cut_1, q1, q2 = split(h1)
        sx2, cut_2, q3, q4 = split(h2)
        quads = (q1, q2, q3, q4)
        same = np.zeros(full_nodes.size, bool)
        for qd in quads:
            same |= (qd[0] == r[0]) & (qd[1] == r[1]) & (qd[2] == r[2]) & (qd[3] == r[3])
        remap = np.full(cnt.size, -1, np.int64)
        ok_nodes = np.flatnonzero(~same)
        remap[full_nodes[ok_nodes]] = ok_nodes
        p = remap[anode]
        sel = p >= 0
        if not sel.all():
            out = ~sel
            key[ai[out]] = akey[out]
            depth[ai[out]] = min(level, 30)
            ax, ay, ai, akey, p = ax[sel], ay[sel], ai[sel], akey[sel], p[sel]
        if ai.size == 0:
            break
        second_half = ~(np.where(sx[p], ax, ay) <= cut[p])
        sxh = np.where(second_half, sx2[p], sx1[p])
        cuth = np.where(second_half, cut_2[p], cut_1[p])
        second_quad = ~(np.where(sxh, ax, ay) <= cuth)
        choice = 2 * second_half.astype(np.int64) + second_quad
        if level < 30:
            akey = akey * 4 + choice
        else:
            d = np.zeros(n, np.uint8)
            d[ai] = choice
            deep.append(d)
        anode = p * 4 + choice
        rects = tuple(np.stack([qd[i] for qd in quads], axis=1).ravel() for i in range(4))
        level += 1
    if ai.size:
        key[ai] = akey
        depth[ai] = min(level, 30)
    key = key << (2 * (depth.max() - depth))
    order = np.lexsort([np.arange(n)] + deep[::-1] + [key])
    rank = np.empty(n, np.int64)
    rank[order] = np.arange(n)
    return rank


def _full_boxes(x, y, tree, box, capacity):
    """Whether each half-open box ``(x0, x1] × (y0, y1]`` holds more than ``capacity`` points.

    A KD-tree query for ``capacity + 1`` neighbours inside the box's inscribed disc
    settles the crowded boxes; the others are counted exactly from the points of the
    enclosing square (few, since such a box holds at most a few points per square of
    its shorter side).
    """
    x0, x1, y0, y1 = box
    cx, cy = 0.5 * (x0 + x1), 0.5 * (y0 + y1)
    hx, hy = 0.5 * (x1 - x0), 0.5 * (y1 - y0)
    margin = 1e-9 * (np.abs(cx) + np.abs(cy) + hx + hy)
    centres = np.column_stack([cx, cy])
    full = np.zeros(x0.size, bool)
    r_in = np.minimum(hx, hy) - margin
    k = capacity + 1
    if k <= tree.n:
        pos = np.flatnonzero(r_in > 0)
        if pos.size:
            d, _ = tree.query(centres[pos], k=k)
            d = d.reshape(pos.size, k)
            full[pos] = d[:, -1] < r_in[pos]
    todo = np.flatnonzero(~full)
    if todo.size:
        r_out = np.maximum(hx, hy)[todo] + margin[todo]
        found = tree.query_ball_point(centres[todo], r_out, p=np.inf, return_sorted=False)
        lens = np.fromiter((len(f) for f in found), np.int64, todo.size)
        cand = np.fromiter((i for f in found for i in f), np.int64, int(lens.sum()))
        node = np.repeat(np.arange(todo.size), lens)
        px, py = x[cand], y[cand]
        inside = ((px > x0[todo][node]) & (px <= x1[todo][node])
                  & (py > y0[todo][node]) & (py <= y1[todo][node]))
        full[todo] = np.bincount(node[inside], minlength=todo.size) > capacity
    return full


def gdal_quadtree_order(x, y, ids, *, tree, capacity: int = 8,
                        ratio: float = 0.55) -> np.ndarray:
    """Rank of the points ``ids`` among themselves in GDAL's quadtree order.

    Same relative order as ``gdal_quadtree_rank(x, y)[ids]``, without building the
    tree for every point: each of these points descends its own path (the quadrant
    choices depend only on its coordinates and on the node's rectangle), and a node
    splits when more than ``capacity`` points fall in it — the points of a node are
    exactly those of a half-open box ``(x0, x1] × (y0, y1]`` (each choice compares
    one coordinate with one cut), counted with ``tree`` (a ``cKDTree`` over all the
    points ``(x, y)``). ``ids`` must be distinct; the cost grows with their number
    and the tree depth, not with the number of points.
    """
    x = np.asarray(x, np.float64)
    y = np.asarray(y, np.float64)
    ids = np.asarray(ids, np.int64)
    m = ids.size
    if m == 0:
        return np.empty(0, np.int64)
    bounds = (x.min(), x.max(), y.min(), y.max())
    px, py = x[ids], y[ids]
    rect = [np.full(m, v) for v in bounds]
    # each node's points: x0 < x <= x1 and y0 < y <= y1 (x0, y0 start below every point)
    box = [np.full(m, bounds[0] - 1.0), np.full(m, bounds[1]),
           np.full(m, bounds[2] - 1.0), np.full(m, bounds[3])]
    choices = []
    act = np.arange(m)
    node = np.zeros(m, np.int64)          # the node each point is in (compact labels)
    while act.size:
        r = tuple(v[act] for v in rect)
        sx, cut, h1, h2 = _split(r, ratio)
        sx1, cut_1, q1, q2 = _split(h1, ratio)
        sx2, cut_2, q3, q4 = _split(h2, ratio)
        quads = (q1, q2, q3, q4)
        same = np.zeros(act.size, bool)
        for qd in quads:
            same |= (qd[0] == r[0]) & (qd[1] == r[1]) & (qd[2] == r[2]) & (qd[3] == r[3])
        go = ~same
        labels, first, inv = np.unique(node[act[go]], return_index=True,
                                       return_inverse=True)
        rep = act[go][first]              # one point per node: the box is the node's
        go[go] = _full_boxes(x, y, tree, [v[rep] for v in box], capacity)[inv.ravel()]
        if not go.any():
            break
        act = act[go]
        sx, cut, sx1, cut_1, sx2, cut_2 = (v[go] for v in (sx, cut, sx1, cut_1, sx2, cut_2))
        quads = tuple(tuple(c[go] for c in qd) for qd in quads)
        ax, ay = px[act], py[act]
        second_half = ~(np.where(sx, ax, ay) <= cut)
        sxh = np.where(second_half, sx2, sx1)
        cuth = np.where(second_half, cut_2, cut_1)
        second_quad = ~(np.where(sxh, ax, ay) <= cuth)
        for along_x, c, second in ((sx, cut, second_half), (sxh, cuth, second_quad)):
            for axis, sel in ((0, along_x), (2, ~along_x)):
                lo, hi = axis, axis + 1
                up = sel & second
                down = sel & ~second
                box[lo][act[up]] = np.maximum(box[lo][act[up]], c[up])
                box[hi][act[down]] = np.minimum(box[hi][act[down]], c[down])
        choice = 2 * second_half.astype(np.int64) + second_quad
        for i in range(4):
            rect[i][act] = np.choose(choice, [qd[i] for qd in quads])
        node[act] = node[act] * 4 + choice
        node[act] = np.unique(node[act], return_inverse=True)[1].ravel()
        level = np.zeros(m, np.uint8)
        level[act] = choice
        choices.append(level)
    order = np.lexsort([ids] + choices[::-1])
    rank = np.empty(m, np.int64)
    rank[order] = np.arange(m)
    return rank

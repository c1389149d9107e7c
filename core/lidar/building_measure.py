"""Per-building measures: roof model, heights from roof points, bridges refused.

Each footprint of :func:`.buildings.extract_buildings` is measured on its own
``ndimage.find_objects`` window and its own points (one sort by label), so the work is
linear in the number of buildings:

* **roof** — the roof primitives of :mod:`.roofs` fitted to the roof-plane points over
  the footprint, in the frame of its rectangle (the regularised one, else the smallest
  rectangle of its roof points); canopy over a roof is not a roof point and the trimmed
  fit leaves parapets and chimneys out, so heights come from the roof alone;
* **ground** — the mean DTM along the outside of the outline (where walls meet the
  terrain); height = ridge − ground, eave height = lowest roof edge − ground;
* **volume** — Σ (roof − DTM) × cell area over the footprint; **storeys** = the mean
  height (volume / area) divided by the storey height, at least 1;
* **bridges** — a structure whose surface runs on into the ground at *both* ends of its
  long axis is not a building (Kostrikov et al. 2020 take buildings as closed to the
  ground; a deck is open under it and joins the terrain at its abutments): at each
  end, within ``reach`` m beyond the outline, most cells' lowest point lies within
  ``step`` m of the roof edge (no wall: the deck goes on) and that continuing surface
  comes down to within ``touch`` m of the DTM. A building's end walls drop to the
  ground; a terraced house's neighbour roof continues but stays high above the DTM.
  A deck surrounded by water — at least half of the points in a 1.5 m band around it
  in class 9, where the input has water — is refused too (a pier or jetty joins the
  shore at one end only).
"""
from __future__ import annotations

import math

import numpy as np

from .roofs import fit_roof

__all__ = ["measure_buildings"]


def _rect_of(points_xy, rect):
    from .buildings import min_area_rectangle
    if rect is not None:
        return rect
    if len(points_xy) >= 4:
        return min_area_rectangle(points_xy)
    c = points_xy.mean(axis=0) if len(points_xy) else np.zeros(2)
    return c, np.eye(2), np.array([0.5, 0.5])


def _bridge_ends(win_xy, cells, zlow, dtm, model, *, step, touch, reach, cell):
    """Return True when the surface goes on into the ground beyond both ends of the long axis."""
    from scipy import ndimage
    it = max(1, int(math.ceil(reach / cell)))
    band = ndimage.binary_dilation(cells, np.ones((3, 3)), iterations=it) & ~cells
    xs, ys = win_xy
    u, v = model.local(xs[band], ys[band])
    a, b = model.half
    zl, g = zlow[band], dtm[band]
    roof_edge = model.z_uv(np.clip(u, -a, a), np.clip(v, -b, b))
    for sign in (1.0, -1.0):
        end = (sign * u > a - cell) & (np.abs(v) < b)
        ok = end & np.isfinite(zl)
        if ok.sum() < 2:
            return False
        cont = ok & (roof_edge - zl < step)
        if cont.sum() < 0.5 * ok.sum():
            return False
        if not (zl[cont] - g[cont] < touch).any():
            return False
    return True


def _over_water(cells, water, win, *, share: float = 0.5, cell: float = 0.5) -> bool:
    """Return True when most points around the structure (a 1.5 m band) are water (9)."""
    from scipy import ndimage
    if water is None:
        return False
    band = ndimage.binary_dilation(cells, np.ones((3, 3)),
                                   iterations=max(1, int(math.ceil(1.5 / cell)))) & ~cells
    n_all, n_water = water[0][win][band].sum(), water[1][win][band].sum()
    return n_all > 0 and n_water >= share * n_all


def measure_buildings(grid, lab, nlab, rects, x, y, z, keep, dtm, zlow, roof_f, *,
                      min_height: float, flat_angle: float, storey_height: float,
                      water=None):
    """Measure every footprint; drop bridges. Returns (labels, buildings, roof, bridges).

    ``x, y, z, keep``: the candidate points and their roof-plane flag; ``zlow``: lowest
    non-noise point per cell (NaN where none); ``water``: (points, water points) per
    cell, or None when the cloud has no class 9; ``roof_f``: highest roof point per cell,
    filled from the nearest. The returned ``roof`` raster holds the fitted roof height
    over each footprint (``roof_f`` elsewhere); ``bridges`` is a boolean raster of the
    refused decks.
    """
    from scipy import ndimage

    from .buildings import _window, group_by_label
    row, col, inside = grid.cell_index(x[keep], y[keep])
    b_lab = lab[row[inside], col[inside]]
    kx, ky, kz = x[keep][inside], y[keep][inside], z[keep][inside]
    order, starts = group_by_label(b_lab, nlab)
    ra, ca, a_in = grid.cell_index(x, y)
    z_all = z[a_in]
    a_order, a_starts = group_by_label(lab[ra[a_in], ca[a_in]], nlab)
    objs = ndimage.find_objects(lab, max_label=nlab)
    mask = lab > 0
    roof = roof_f.copy()
    bridges = np.zeros(grid.shape, bool)
    xc, yc = grid.x_centers(), grid.y_centers()
    out, drop = [], np.zeros(nlab + 1, bool)
    for k in range(1, nlab + 1):
        if objs[k - 1] is None:
            drop[k] = True
            continue
        win = _window(objs[k - 1], max(3, int(math.ceil(3.0 / grid.cell))), grid.shape)
        cells = lab[win] == k
        sel = order[starts[k]:starts[k + 1]]
        pxy = np.column_stack([kx[sel], ky[sel]])
        centre, axes, half = _rect_of(pxy, rects[k - 1])
        model = fit_roof(kx[sel], ky[sel], kz[sel], centre, axes, half,
                         flat_angle=flat_angle)
        xs, ys = np.meshgrid(xc[win[1]], yc[win[0]])
        d = dtm[win]
        if _bridge_ends((xs, ys), cells, zlow[win], d, model, step=1.0,
                        touch=0.75 * min_height, reach=3.0, cell=grid.cell) or \
                _over_water(cells, water, win, cell=grid.cell):
            bridges[win] |= cells
            drop[k] = True
            continue
        ring = ndimage.binary_dilation(cells, np.ones((3, 3)), iterations=2) & ~mask[win]
        g = float(np.nanmean(d[ring]) if np.isfinite(d[ring]).any()
                  else np.nanmean(d[cells]))
        if model.kind == "complex":
            # no primitive fits: the points over the footprint up to 1 m above its
            # highest roof-plane point (ridges and edges are not planar; canopy higher
            # over the roof is left out)
            zr = roof_f[win][cells]
            top = float(kz[sel].max()) if sel.size else float(zr.max())
            za = z_all[a_order[a_starts[k]:a_starts[k + 1]]]
            za = za[za <= top + 1.0]
            ridge = float(np.percentile(za, 99)) if za.size else top
            eave = float(np.percentile(kz[sel], 5)) if sel.size else float(zr.min())
        else:
            zr = model.z(xs[cells], ys[cells])
            ridge, eave = model.ridge, model.eave
        roof[win][cells] = zr
        area = float(cells.sum() * grid.cell ** 2)
        volume = float(np.nansum(zr - d[cells]) * grid.cell ** 2)
        mean_h = volume / area if area > 0 else 0.0
        out.append({"id": k, "height": ridge - g, "eave_height": eave - g, "area": area,
                    "volume": volume, "mean_height": mean_h,
                    "storeys": max(1, int(mean_h // storey_height)), "ground": g,
                    "roof": ridge, "roof_type": model.kind, "slope": model.slope_deg,
                    "model": model, "regularised": rects[k - 1] is not None,
                    "n_roof_points": int(sel.size)})
    lab = lab.copy()
    lab[drop[lab]] = 0
    relabel = np.zeros(nlab + 1, np.int32)
    relabel[~drop] = np.arange(int((~drop).sum()))
    relabel[0] = 0
    lab = relabel[lab]
    for i, b in enumerate(out, start=1):
        b["id"] = i
    return lab, out, roof, bridges

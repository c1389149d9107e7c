"""Accuracy of building footprints against a synthetic tile's true buildings.

Object-based completeness and correctness (Rutzinger, Rottensteiner & Pfeifer 2009)
for buildings of at least ``min_area`` m²: a true and a detected building match when
their footprints on the grid overlap with IoU ≥ 0.5. Mean IoU over matched true
buildings; height RMSE of the matches, the true height being the top of the roof
minus the mean true terrain along the outside of the outline (where walls meet the
ground), the definition the extractor uses.
"""
from __future__ import annotations

import numpy as np


def true_masks(buildings, grid) -> list:
    """One boolean footprint mask per true building (cell centres inside)."""
    xx, yy = np.meshgrid(grid.x_centers(), grid.y_centers())
    out = []
    for i in range(len(buildings)):
        u, v = buildings.local(i, xx, yy)
        out.append((np.abs(u) <= buildings.half_length[i])
                   & (np.abs(v) <= buildings.half_width[i]))
    return out


def true_height(tile, i: int, *, offset: float = 0.5) -> float:
    """Top of roof minus the mean true terrain just outside the outline (m)."""
    b = tile.buildings
    t = np.linspace(-1, 1, 50)
    hl, hw = b.half_length[i] + offset, b.half_width[i] + offset
    uu = np.concatenate([t * hl, t * hl, np.full(50, hl), np.full(50, -hl)])
    vv = np.concatenate([np.full(50, hw), np.full(50, -hw), t * hw, t * hw])
    c, s = np.cos(b.angle[i]), np.sin(b.angle[i])
    ground = tile.terrain(b.cx[i] + uu * c - vv * s, b.cy[i] + uu * s + vv * c).mean()
    top = b.base[i] + b.eave[i] + b.half_width[i] * np.tan(np.radians(b.pitch[i]))
    return float(top - ground)


def building_accuracy(tile, labels, grid, heights, *, min_area: float = 50.0) -> dict:
    """Completeness, correctness, mean IoU and height RMSE (see the module docstring).

    ``labels``: footprint labels on ``grid`` (0 = none, k = detected building k);
    ``heights``: height of detected building k at index k - 1.
    """
    truth = true_masks(tile.buildings, grid)
    cell2 = grid.cell ** 2
    big = [i for i, m in enumerate(truth) if 4 * tile.buildings.half_length[i]
           * tile.buildings.half_width[i] >= min_area]
    det_ids = [k for k in range(1, int(labels.max()) + 1)
               if (labels == k).sum() * cell2 >= min_area]
    ious, errs, matched_det = [], [], set()
    for i in big:
        best, best_k = 0.0, 0
        for k in np.unique(labels[truth[i]]):
            if k == 0:
                continue
            d = labels == k
            iou = (d & truth[i]).sum() / (d | truth[i]).sum()
            if iou > best:
                best, best_k = iou, int(k)
        if best >= 0.5:
            ious.append(best)
            matched_det.add(best_k)
            errs.append(heights[best_k - 1] - true_height(tile, i))
    correct = [k for k in det_ids if k in matched_det or any(
        ((labels == k) & truth[i]).sum() / ((labels == k) | truth[i]).sum() >= 0.5
        for i in range(len(truth)))]
    return {"n_true": len(big), "n_detected": len(det_ids), "matched": len(ious),
            "completeness": len(ious) / max(len(big), 1),
            "correctness": len(correct) / max(len(det_ids), 1),
            "mean_iou": float(np.mean(ious)) if ious else float("nan"),
            "height_rmse": float(np.sqrt(np.mean(np.square(errs)))) if errs
            else float("nan")}


def match_footprints(truth_masks, truth_heights, labels, heights, cell: float, *,
                     min_area: float = 50.0) -> dict:
    """Object completeness / correctness, mean IoU and height RMSE of any footprints.

    ``truth_masks``: boolean rasters (one per reference building, on the grid of
    ``labels``); ``truth_heights``: their heights; ``labels``/``heights`` as in
    :func:`building_accuracy`. A reference building and a detection match at IoU ≥ 0.5
    (Rutzinger et al. 2009); only footprints of at least ``min_area`` m² count. Each
    comparison reads the bounding box of the two footprints only.
    """
    from scipy import ndimage
    cell2 = cell ** 2
    nlab = int(labels.max()) if labels.size else 0
    objs = ndimage.find_objects(labels, max_label=nlab) if nlab else []
    sizes = np.bincount(labels.ravel(), minlength=nlab + 1)
    det_ids = [k for k in range(1, nlab + 1) if sizes[k] * cell2 >= min_area]
    big = [i for i, m in enumerate(truth_masks) if m.sum() * cell2 >= min_area]
    ious, errs, matched = [], [], set()
    for i in big:
        m = truth_masks[i]
        best, best_k = 0.0, 0
        for k in np.unique(labels[m]):
            if k == 0:
                continue
            d = labels == k
            iou = (d & m).sum() / (d | m).sum()
            if iou > best:
                best, best_k = iou, int(k)
        if best >= 0.5:
            ious.append(best)
            matched.add(best_k)
            errs.append(heights[best_k - 1] - truth_heights[i])
    del objs
    return {"n_true": len(big), "n_detected": len(det_ids), "matched": len(ious),
            "completeness": len(ious) / max(len(big), 1),
            "correctness": len([k for k in det_ids if k in matched]) / max(len(det_ids), 1),
            "mean_iou": float(np.mean(ious)) if ious else float("nan"),
            "height_rmse": float(np.sqrt(np.mean(np.square(errs)))) if errs
            else float("nan")}

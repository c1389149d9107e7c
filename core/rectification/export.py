"""CSV and JSON text of a GCP accuracy evaluation (:class:`~.accuracy.GcpAccuracy`).

The per-point residual table and the whole evaluation as JSON, for the criteria of
Tishreen Univ. J. Eng. Sci. 38(2), 2016 (see :mod:`.accuracy`).
"""
from __future__ import annotations

import csv
import io
import json
import math

import numpy as np

from .accuracy import GcpAccuracy


def to_csv(acc: GcpAccuracy) -> str:
    """Return the per-point CSV: every point (GCPs, check points, disabled points)."""
    r = acc.selected
    s = r.stats
    g = acc.gcps
    buf = io.StringIO()
    w = csv.writer(buf, lineterminator="\n")
    w.writerow(["id", "role", "enabled", "col", "row", "X", "Y", "order", "vx", "vy", "rms_i",
                "c_i", "v_col_px", "v_row_px", "rms_i_px", "loo_vx", "loo_vy", "loo_rms_i",
                "within_rms_t", "over_point_limit"])
    fit_ids = {pid: k for k, pid in enumerate(s.ids)}
    chk_ids = {pid: k for k, pid in enumerate(r.check.ids)} if r.check else {}

    def f(v):
        return "" if v is None or not np.isfinite(v) else f"{float(v):.6f}"

    for k, pid in enumerate(g.ids):
        base = [pid, g.role[k], int(g.enabled[k]), f(g.pixel[k, 0]), f(g.pixel[k, 1]),
                f(g.map[k, 0]), f(g.map[k, 1]), acc.order]
        if pid in fit_ids and g.fit_mask[k]:
            j = fit_ids[pid]
            lo = r.loo[j]
            w.writerow(base + [f(s.vx[j]), f(s.vy[j]), f(s.rms_i[j]), f(s.c_i[j]),
                               f(r.pixel_res[j, 0]), f(r.pixel_res[j, 1]),
                               f(np.hypot(*r.pixel_res[j])), f(lo[0]), f(lo[1]),
                               f(np.hypot(*lo)), int(s.within[j]), int(s.over_limit[j])])
        elif pid in chk_ids and g.check_mask[k]:
            j = chk_ids[pid]
            c = r.check
            w.writerow(base + [f(c.vx[j]), f(c.vy[j]), f(c.rms_i[j]), "",
                               f(r.check_pixel_res[j, 0]), f(r.check_pixel_res[j, 1]),
                               f(np.hypot(*r.check_pixel_res[j])), "", "", "", "",
                               int(c.over_limit[j])])
        else:
            w.writerow(base + [""] * 12)
    return buf.getvalue()


def to_json(acc: GcpAccuracy) -> str:
    """Return the whole evaluation as JSON (NaN written as null)."""
    def clean(o):
        if isinstance(o, dict):
            return {str(k): clean(v) for k, v in o.items()}
        if isinstance(o, (list, tuple)):
            return [clean(v) for v in o]
        if isinstance(o, np.ndarray):
            return clean(o.tolist())
        if isinstance(o, (np.floating, float)):
            return float(o) if math.isfinite(float(o)) else None
        if isinstance(o, (np.integer,)):
            return int(o)
        if isinstance(o, np.bool_):
            return bool(o)
        return o
    return json.dumps(clean(acc.as_dict()), indent=1, ensure_ascii=False)

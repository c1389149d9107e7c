"""Grid-phase section of bench_ground.py: the ISPRS samples with the grid moved (``--phases``).

The held-out ISPRS samples are run with the grid anchored at their own lower-left
corner, which falls anywhere on the scene: that corner is one draw among the grid's
phases. Here the recommended filter runs at its defaults on each shared sample with the
raster's corner moved to ``(x.min() - dx, y.min() - dy)`` (``classify(origin=...)``) for
a fixed set of shifts: sub-cell shifts change which cell each point falls in (binning),
whole-cell shifts change only where the raster and the fill pyramid's blocks start. The
mean over the shifts is the expectation on a sample seen at a random phase.
"""
from __future__ import annotations

import os
import time

import numpy as np

#: Grid shifts (dx, dy) in metres (cells of 1 m at ISPRS density): the corner, the three
#: half-cell ones, a quarter-cell one, a whole-cell one, and two empty bands along the
#: raster's lower and left edges (16 and 32 cells: the fill pyramid's blocks of 32 and 64
#: cells then start elsewhere on the data).
SHIFTS = ((0.0, 0.0), (0.5, 0.0), (0.0, 0.5), (0.5, 0.5), (0.25, 0.75), (3.0, 5.0),
          (16.0, 16.0), (32.0, 32.0))


def phases_section(load, samples, shifts=SHIFTS):
    """Total error (%) per sample and shift of the recommended filter; CPU s; load."""
    from geomatics_toolbox.core.lidar import recommended as rec
    from geomatics_toolbox.core.lidar.accuracy import assess
    rows, t0, load0 = {}, time.process_time(), os.getloadavg()[0]
    for s in samples:
        x, y, z, ref = load(s)
        rows[s] = [assess(rec.classify(x, y, z, origin=(x.min() - dx, y.min() - dy)) == 2,
                          ref).total for dx, dy in shifts]
        print(s, " ".join(f"{v:.2f}" for v in rows[s]), flush=True)
    return dict(rows=rows, shifts=list(shifts), cpu=time.process_time() - t0,
                load=(load0, os.getloadavg()[0]))


def phases_md(res, smrf=None):
    """Markdown section; ``smrf`` maps sample -> SMRF total (its corner run) if known."""
    shifts, rows = res["shifts"], res["rows"]
    head = " | ".join(f"({dx:g}, {dy:g})" for dx, dy in shifts)
    L = ["## ISPRS grid phases (recommended filter, grid corner moved)", "",
         "Total error (%) of the recommended filter at its defaults with the raster's "
         "corner at (x.min() - dx, y.min() - dy), shifts (dx, dy) in metres (1 m cells): "
         "(0, 0) is the corner every other table uses. Sub-cell shifts change the cell of "
         "every point; (3, 5), (16, 16) and (32, 32) only where the raster and the push-pull "
         "fill's blocks start.", "",
         f"| sample | {head} | mean | max - min |" + (" SMRF (corner) |" if smrf else ""),
         "|---|" + "---|" * (len(shifts) + 2) + ("---|" if smrf else "")]
    t = np.array([rows[s] for s in rows])
    for s, r in zip(rows, t):
        L.append(f"| {s} | " + " | ".join(f"{v:.2f}" for v in r)
                 + f" | {r.mean():.2f} | {np.ptp(r):.2f} |"
                 + (f" {smrf[s]:.2f} |" if smrf and s in smrf else ""))
    m = t.mean(axis=0)
    L.append("| **mean** | " + " | ".join(f"{v:.3f}" for v in m)
             + f" | {t.mean():.3f} | {np.ptp(m):.3f} |" + (" |" if smrf else ""))
    L += ["", f"Mean over the {len(shifts)} shifts and {len(rows)} samples: "
          f"**{t.mean():.3f} %** (corner {m[0]:.3f} %, worst shift {m.max():.3f} %). "
          f"CPU {res['cpu']:.0f} s for the section, load average {res['load'][0]:.1f} at "
          f"the start and {res['load'][1]:.1f} at the end (other jobs on the 2 cores)."]
    return "\n".join(L) + "\n"


def smrf_corner(results):
    """SMRF's total per sample from the first ISPRS table of ``results`` (a path); {}."""
    if not results.exists():
        return {}
    col, out = None, {}
    for line in results.read_text(encoding="utf-8").splitlines():
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if col is None and cells[:1] == ["sample"] and "smrf" in cells:
            col = cells.index("smrf")
        elif col is not None:
            if not line.startswith("|"):
                break
            if cells[0].startswith("samp"):
                out[cells[0]] = float(cells[col])
    return out

"""benchmarks/_ground_stress.py: thinning and the stress table of bench_ground.py --stress."""
import sys
from pathlib import Path

import numpy as np

BENCH = Path(__file__).resolve().parents[2] / "benchmarks"


def _stress():
    sys.path.insert(0, str(BENCH))
    try:
        import _ground_stress
    finally:
        sys.path.remove(str(BENCH))
    return _ground_stress


def test_thinning_is_seeded_and_leaves_classes_7_and_18_out():
    gs = _stress()
    rng = np.random.default_rng(0)
    n = 40_000
    d = dict(x=rng.uniform(0, 100, n), y=rng.uniform(0, 100, n),
             vclass=np.where(np.arange(n) % 10 == 0, 7, 2).astype(np.uint8))
    full = gs.thinned(d, None, 0)
    assert full.sum() == n - n // 10                      # every 10th point is class 7
    a, b, c = gs.thinned(d, 1.0, 1), gs.thinned(d, 1.0, 1), gs.thinned(d, 1.0, 2)
    assert np.array_equal(a, b) and not np.array_equal(a, c)
    assert not (a & (d["vclass"] == 7)).any()
    dens = a.sum() / (np.ptp(d["x"]) * np.ptp(d["y"]))
    assert abs(dens - 1.0) < 0.05                         # 1 pt/m² over the bounding box


def test_stress_table_counts_the_clouds_over_one_percent():
    gs = _stress()
    rows = []
    for seed, (rec, orc) in enumerate(((0.3, 0.0), (2.5, 0.0), (1.5, 1.2)), 1):
        for what, bad in (("oracle", orc), ("recommended", rec)):
            rows.append(dict(file="f", density=0.5, seed=seed, filter=what, n=100 * seed,
                             rmse=0.1 * seed, bad=bad, cpu=0.5))
    md = gs.stress_md(rows, ("recommended",))
    lines = md.splitlines()
    assert lines[0].startswith("## Real files thinned")
    assert "| f | 0.5 | 2 | 200 | 0.20 / 0.00 | 0.20 / 2.50 |" in lines
    assert "| **CPU s** | | | | 1.5 | 1.5 |" in lines
    assert ("Recommended: 1 of 3 thinned clouds with at most 1 % of the cells off by more "
            "than 1 m; the others (2): f 0.5 pts/m² seed 2 (0.20 m / 2.50 %), f 0.5 pts/m² "
            "seed 3 (0.30 m / 1.50 %) (1 of them where the oracle stays within 1 %).") in md

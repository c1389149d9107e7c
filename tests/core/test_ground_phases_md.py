"""benchmarks/_ground_phases.py: the grid-phase table of bench_ground.py --phases."""
import sys
from pathlib import Path

BENCH = Path(__file__).resolve().parents[2] / "benchmarks"


def _phases():
    sys.path.insert(0, str(BENCH))
    try:
        import _ground_phases
    finally:
        sys.path.remove(str(BENCH))
    return _ground_phases


def test_phases_table_means_per_sample_and_per_shift():
    gp = _phases()
    res = dict(rows={"samp11": [8.0, 9.0, 10.0, 9.0, 8.5, 9.5], "samp41": [2.0] * 6},
               shifts=list(gp.SHIFTS[:6]), cpu=12.3, load=(4.0, 6.5))
    md = gp.phases_md(res, {"samp11": 8.52, "samp41": 12.2})
    lines = md.splitlines()
    assert lines[0] == "## ISPRS grid phases (recommended filter, grid corner moved)"
    assert ("| sample | (0, 0) | (0.5, 0) | (0, 0.5) | (0.5, 0.5) | (0.25, 0.75) | (3, 5) | "
            "mean | max - min | SMRF (corner) |") in lines
    assert "| samp11 | 8.00 | 9.00 | 10.00 | 9.00 | 8.50 | 9.50 | 9.00 | 2.00 | 8.52 |" in lines
    assert gp.SHIFTS[0] == (0.0, 0.0) and len(set(gp.SHIFTS)) == len(gp.SHIFTS) >= 6
    assert "| samp41 | 2.00 | 2.00 | 2.00 | 2.00 | 2.00 | 2.00 | 2.00 | 0.00 | 12.20 |" in lines
    assert ("| **mean** | 5.000 | 5.500 | 6.000 | 5.500 | 5.250 | 5.750 | 5.500 | 1.000 | |"
            in lines)
    assert ("**5.500 %** (corner 5.000 %, worst shift 6.000 %). CPU 12 s for the section, "
            "load average 4.0 at the start and 6.5 at the end") in md


def test_smrf_corner_reads_the_first_isprs_table(tmp_path):
    gp = _phases()
    p = tmp_path / "ground.md"
    p.write_text("# t\n\n| sample | ptd | recommended | smrf | csf |\n|---|---|---|---|---|\n"
                 "| samp11 | 12.19 | 8.59 | 8.52 | 37.90 |\n"
                 "| samp41 | 5.47 | 2.54 | 12.20 | 41.59 |\n"
                 "| **mean** | 4.55 | 3.27 | 5.75 | 20.84 |\n\n| sample | smrf |\n|---|---|\n"
                 "| samp11 | 1.00 |\n", encoding="utf-8")
    assert gp.smrf_corner(p) == {"samp11": 8.52, "samp41": 12.2}
    assert gp.smrf_corner(tmp_path / "missing.md") == {}

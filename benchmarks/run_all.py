"""Run every benchmarks/bench_*.py and index their Markdown tables.

Each benchmark script writes its own table to benchmarks/results/<topic>.md; this
runner calls them one after another (so they do not compete for the 2 cores) and
writes benchmarks/results/README.md listing what ran, how long it took and where the
table is. Extra arguments (e.g. --quick) are passed through to every script.
"""
import datetime
import platform
import subprocess
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
RESULTS = HERE / "results"


def main(argv):
    RESULTS.mkdir(exist_ok=True)
    scripts = sorted(HERE.glob("bench_*.py"))
    if argv == ["--index-only"]:
        return write_index([(s.name, None, None) for s in scripts], argv)
    rows = []
    for script in scripts:
        print(f"== {script.name}", flush=True)
        t0 = time.perf_counter()
        proc = subprocess.run([sys.executable, str(script), *argv], cwd=HERE.parent)
        rows.append((script.name, proc.returncode, time.perf_counter() - t0))
    return write_index(rows, argv)


def write_index(rows, argv):
    """Write results/README.md: one line per benchmark with the first lines of its table."""
    lines = [
        "# Benchmark results",
        "",
        ("Index of the tables each benchmark wrote on its last run (each table states "
         "its own date, machine and arguments)." if argv == ["--index-only"] else
         f"Run {datetime.datetime.now().isoformat(timespec='seconds')} on "
         f"{platform.node()} ({platform.processor() or platform.machine()}, "
         f"Python {platform.python_version()}), arguments: {' '.join(argv) or '(none)'}."),
        "",
        "| script | exit | wall time (s) | table |",
        "|---|---|---|---|",
    ]
    for name, rc, secs in rows:
        table = f"{name[len('bench_'):-3]}.md"
        rc_text = "–" if rc is None else str(rc)
        secs_text = "–" if secs is None else f"{secs:.1f}"
        lines.append(f"| {name} | {rc_text} | {secs_text} | [{table}]({table}) |")
    (RESULTS / "README.md").write_text("\n".join(lines) + "\n", encoding="utf-8")
    print((RESULTS / "README.md").read_text())
    return max((rc or 0 for _, rc, _ in rows), default=0)


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))

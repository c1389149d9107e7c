"""Build the installable plugin zip: dist/geomatics_toolbox-<version>.zip.

Contains the tracked plugin sources (no tests, benchmarks, CI or dev scripts) and the
compiled translations (i18n/*.qm), under the folder name QGIS expects.
"""
import argparse
import configparser
import subprocess
import zipfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
PLUGIN = "geomatics_toolbox"
EXCLUDE_DIRS = ("tests/", "benchmarks/", ".ci/", "scripts/", ".github/", "synthetic/")
EXCLUDE_FILES = {".gitignore", "Makefile", "pytest.ini", "ruff.toml", "requirements-dev.txt",
                 "requirements-bench.txt", "DEVELOPERS.md"}
#: translation sources: the plugin loads the compiled .qm (and i18n/strings/*.json)
EXCLUDE_SUFFIXES = (".ts",)


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--out", default="dist")
    args = ap.parse_args()
    meta = configparser.ConfigParser()
    meta.read(ROOT / "metadata.txt", encoding="utf-8")
    version = meta["general"]["version"]
    files = subprocess.run(["git", "ls-files"], cwd=ROOT, capture_output=True, text=True,
                           check=True).stdout.split()
    files = [f for f in files if not f.startswith(EXCLUDE_DIRS) and f not in EXCLUDE_FILES
             and not f.endswith(EXCLUDE_SUFFIXES)]
    qms = sorted(str(p.relative_to(ROOT)) for p in (ROOT / "i18n").glob("*.qm"))
    if not qms:
        raise SystemExit("No compiled translations: run 'make qm' first.")
    out = ROOT / args.out
    out.mkdir(parents=True, exist_ok=True)
    target = out / f"{PLUGIN}-{version}.zip"
    tmp = target.with_suffix(".zip.part")
    with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED) as zf:
        for rel in sorted(set(files + qms)):
            zf.write(ROOT / rel, f"{PLUGIN}/{rel}")
    tmp.replace(target)
    print(f"{target} ({len(set(files + qms))} files)")


if __name__ == "__main__":
    main()

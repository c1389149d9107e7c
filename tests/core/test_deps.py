"""core/deps.py: the runtime requirements and the private, two-step pip installation."""
from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

from geomatics_toolbox.core import deps
from geomatics_toolbox.core.errors import InputError

ROOT = Path(__file__).resolve().parents[2]


def test_requirements_are_the_shipped_pins_with_a_purpose():
    reqs = deps.requirements()
    lines = [ln.split("#")[0].strip() for ln in
             deps.REQUIREMENTS_FILE.read_text(encoding="utf-8").splitlines()]
    assert [r.line for r in reqs] == [ln for ln in lines if ln and not ln.startswith("-")]
    assert {r.name: r.group for r in reqs} == {"laspy": "lidar", "lazrs": "lidar",
                                               "dask": "catalog", "distributed": "catalog"}
    assert not {r.name for r in reqs} & set(deps.NEVER_INSTALL)
    assert all("==" in r.line for r in reqs)           # pinned: what the tests ran


def test_missing_and_check_name_the_packages_and_the_installer(monkeypatch, tmp_path):
    req = tmp_path / "requirements.txt"
    req.write_text("# comment\nlaspy==2.7.0\nno-such-package-xyz==1.0  # x\n-r other.txt\n",
                   encoding="utf-8")
    reqs = deps.requirements(req)
    assert [(r.name, r.import_name) for r in reqs] == [("laspy", "laspy"),
                                                       ("no-such-package-xyz",
                                                        "no_such_package_xyz")]
    monkeypatch.setattr(deps, "requirements", lambda path=None: reqs)
    assert [r.name for r in deps.missing(["lidar"])] == ["no-such-package-xyz"]
    with pytest.raises(InputError) as err:
        deps.check(["lidar"])
    assert "no-such-package-xyz" in str(err.value)
    assert "geomatics:installdependencies" in str(err.value)
    deps.check([])                                       # nothing needed: no error


def test_catalog_group_includes_lidar():
    assert deps.groups_closure(["catalog"]) == ["catalog", "lidar"]


def test_commands_never_touch_site_packages(tmp_path):
    resolve = deps.resolve_command("/py", tmp_path / "r.json", wheel_dir="/wheels")
    assert resolve[:4] == ["/py", "-m", "pip", "install"]
    assert "--dry-run" in resolve and "--report" in resolve
    assert resolve[-3:] == ["--no-index", "--find-links", "/wheels"]
    install = deps.install_command("/py", tmp_path / "t", ["laspy==2.7.0"])
    assert install[install.index("--target") + 1] == str(tmp_path / "t")
    assert "--no-deps" in install and "--no-index" not in install
    assert install[-1] == "laspy==2.7.0"


def test_plan_refuses_to_replace_qgis_packages(tmp_path):
    report = tmp_path / "r.json"
    items = [{"metadata": {"name": "laspy", "version": "2.7.0"}},
             {"metadata": {"name": "toolz", "version": "1.2.0"}}]
    report.write_text(json.dumps({"version": "1", "install": items}), encoding="utf-8")
    assert deps.read_plan(report) == ["laspy==2.7.0", "toolz==1.2.0"]
    items.append({"metadata": {"name": "numpy", "version": "2.2.0"}})
    report.write_text(json.dumps({"version": "1", "install": items}), encoding="utf-8")
    with pytest.raises(InputError, match="numpy 2.2.0"):
        deps.read_plan(report)


def test_folder_is_per_profile_and_python_and_appended(tmp_path, monkeypatch):
    folder = deps.packages_dir(tmp_path / "profiles" / "default")
    ver = f"python{sys.version_info[0]}.{sys.version_info[1]}"
    assert folder == tmp_path / "profiles" / "default" / "geomatics_toolbox" / ver
    monkeypatch.setattr(sys, "path", list(sys.path))
    monkeypatch.setattr(deps, "WORKER_PATHS", [])
    assert not deps.activate(folder)                    # absent: nothing added
    folder.mkdir(parents=True)
    assert deps.activate(folder) and deps.activate(folder)
    assert sys.path[-1] == str(folder) and sys.path.count(str(folder)) == 1
    assert deps.WORKER_PATHS == [str(folder)]


ACTIVATE = r"""
import importlib.util, json, os, sys
root, folder = sys.argv[1], sys.argv[2]
spec = importlib.util.spec_from_file_location(
    "geomatics_toolbox", os.path.join(root, "__init__.py"),
    submodule_search_locations=[root])
pkg = importlib.util.module_from_spec(spec)
sys.modules["geomatics_toolbox"] = pkg
spec.loader.exec_module(pkg)
before = set(sys.modules)
from geomatics_toolbox.core import deps
ok = deps.activate(folder)
print("RESULT:" + json.dumps({"ok": ok, "paths": deps.WORKER_PATHS,
                              "new": sorted(set(sys.modules) - before)}))
"""


def test_activate_at_plugin_start_imports_nothing_heavy(tmp_path):
    """Plugin start activates the folder: no core.lidar, no SciPy, no numpy (review N1)."""
    folder = tmp_path / "packages"
    folder.mkdir()
    out = subprocess.run([sys.executable, "-c", ACTIVATE, str(ROOT), str(folder)],
                         capture_output=True, text=True, timeout=300)
    lines = [ln for ln in out.stdout.splitlines() if ln.startswith("RESULT:")]
    assert out.returncode == 0 and lines, out.stdout + out.stderr
    res = json.loads(lines[-1][len("RESULT:"):])
    assert res["ok"] and res["paths"] == [str(folder)]
    ours = [m for m in res["new"] if m.startswith("geomatics_toolbox")]
    assert ours == ["geomatics_toolbox.core", "geomatics_toolbox.core.deps",
                    "geomatics_toolbox.core.errors", "geomatics_toolbox.core.system"], ours
    heavy = [m for m in res["new"]
             if m.split(".")[0] in ("scipy", "numpy", "jinja2", "laspy", "dask")]
    assert heavy == []


def test_workers_read_the_activated_folder_when_they_start(tmp_path, monkeypatch):
    from geomatics_toolbox.core.lidar import _workers
    monkeypatch.setattr(deps, "WORKER_PATHS", [])
    folder = tmp_path / "packages"
    folder.mkdir()
    monkeypatch.setattr(sys, "path", list(sys.path))
    deps.activate(folder)
    env = _workers.worker_environment({"PYTHONPATH": "/x"})
    assert str(folder) in env["PYTHONPATH"].split(os.pathsep)


def test_pip_environment_is_a_copy(tmp_path, monkeypatch):
    monkeypatch.setenv("PIP_TARGET", "/elsewhere")
    before = dict(os.environ)
    env = deps.pip_environment(tmp_path)
    assert dict(os.environ) == before
    assert env["PYTHONPATH"].split(os.pathsep)[0] == str(tmp_path)
    assert "PIP_TARGET" not in env


def test_format_command_quotes_spaces():
    assert deps.format_command(["/p y", "-m", "pip"]) == "'/p y' -m pip"


def test_install_with_a_python_without_pip_says_how_to_get_it(tmp_path):
    fake = tmp_path / "python3"
    fake.write_text("#!/bin/sh\necho '/fake: No module named pip' >&2\nexit 1\n")
    fake.chmod(0o755)
    with pytest.raises(InputError, match="has no pip"):
        deps.install(tmp_path / "target", python=str(fake), log=lambda s: None)
    assert not list((tmp_path / "target").glob("*.json"))


def test_a_package_that_cannot_load_is_reported_before_the_run(monkeypatch, tmp_path):
    """find_spec sees distributed, but a dependency of it is gone: check(load=True) says so."""
    broken = tmp_path / "brokenpkg_xyz"
    broken.mkdir()
    (broken / "__init__.py").write_text("import click_missing_dependency_xyz\n")
    monkeypatch.syspath_prepend(str(tmp_path))
    req = deps.Requirement("brokenpkg-xyz", "brokenpkg-xyz==1.0", "brokenpkg_xyz", "lidar")
    monkeypatch.setattr(deps, "requirements", lambda path=None: [req])
    deps.check(["lidar"])                                # present: the cheap check passes
    with pytest.raises(InputError) as err:
        deps.check(["lidar"], load=True)
    text = str(err.value)
    assert "brokenpkg-xyz" in text and "click_missing_dependency_xyz" in text
    assert "geomatics:installdependencies" in text


OLD_PIP = r"""#!/bin/sh
# a pip 22.0 stand-in: no --report; --target writes the closure (numpy included)
for a in "$@"; do
  if [ "$a" = "--report" ]; then echo "no such option: --report" >&2; exit 2; fi
done
t=""; prev=""
for a in "$@"; do [ "$prev" = "--target" ] && t="$a"; prev="$a"; done
mkdir -p "$t/laspy" "$t/laspy-2.7.0.dist-info" "$t/numpy" "$t/numpy-2.2.6.dist-info" \
         "$t/numpy.libs"
echo "Successfully installed laspy-2.7.0 numpy-2.2.6 lazy-importer-0.1.0"
"""


def test_old_pip_without_report_installs_then_drops_qgis_packages(tmp_path):
    fake = tmp_path / "python3"
    fake.write_text(OLD_PIP)
    fake.chmod(0o755)
    target = tmp_path / "target"
    lines = []
    res = deps.install(target, python=str(fake), log=lines.append)
    assert sorted(p.name for p in target.iterdir()) == ["laspy", "laspy-2.7.0.dist-info"]
    assert res.planned == ["laspy==2.7.0", "lazy-importer==0.1.0"]
    assert len(res.commands) == 2 and "--report" in res.commands[0]
    assert "--target" in res.commands[1] and "-r" in res.commands[1]
    assert any("removed numpy" in ln for ln in lines)


FAKE_PIP = r"""#!/bin/sh
# records its arguments; the dry run writes a report planning scipy and laspy
echo "$@" >> "$ARGS_LOG"
prev=""
for a in "$@"; do
  if [ "$prev" = "--report" ]; then
    printf '{"version": "1", "install": [' > "$a"
    printf '{"metadata": {"name": "scipy", "version": "1.10.1"}}, ' >> "$a"
    printf '{"metadata": {"name": "laspy", "version": "2.7.0"}}]}' >> "$a"
  fi
  if [ "$prev" = "-c" ]; then cat "$a" >> "$ARGS_LOG"; fi
  prev="$a"
done
"""


def test_missing_scipy_is_added_for_qgis_own_numpy(tmp_path, monkeypatch):
    """A QGIS without SciPy (some macOS builds): scipy is planned, numpy held fixed."""
    import numpy
    fake = tmp_path / "python3"
    fake.write_text(FAKE_PIP)
    fake.chmod(0o755)
    args = tmp_path / "args.log"
    monkeypatch.setenv("ARGS_LOG", str(args))
    monkeypatch.setattr(deps.Requirement, "importable", lambda self: self.group != "base")
    assert [r.name for r in deps.missing(["lidar"])] == ["scipy"]
    res = deps.install(tmp_path / "t", python=str(fake), log=lambda s: None)
    resolve = args.read_text().splitlines()[0].split()
    assert "scipy" in resolve and "-c" in resolve
    assert f"numpy=={numpy.__version__}" in args.read_text()     # QGIS's numpy held
    assert res.planned == ["scipy==1.10.1", "laspy==2.7.0"]
    assert not list((tmp_path / "t").glob(".constraints.txt"))
    report = tmp_path / "r.json"        # a scipy in the plan while QGIS has one: refused
    report.write_text('{"install": [{"metadata": {"name": "scipy", "version": "1.10.1"}}]}')
    with pytest.raises(InputError, match="scipy 1.10.1"):
        deps.read_plan(report)

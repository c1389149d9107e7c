"""The output contract and the report renderer (issue 9): basic behaviour."""
import os
import signal
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest

from geomatics_toolbox.core.errors import InputError
from geomatics_toolbox.core.io.contract import OutputContract, atomic_output
from geomatics_toolbox.core.reporting import Paragraph, Report, T, Table, render_html


def _listing(folder: Path):
    return sorted(p.name for p in folder.iterdir())


def test_all_outputs_renamed_together(tmp_path):
    with OutputContract({"A": tmp_path / "a.txt", "B": tmp_path / "b.txt", "C": None}) as out:
        out.write_text("A", "a")
        out.write_text("B", "b")
        assert _listing(tmp_path) == sorted(Path(out.path(k)).name for k in "AB")
    assert _listing(tmp_path) == ["a.txt", "b.txt"]
    assert (tmp_path / "a.txt").read_text() == "a"


def test_failure_leaves_nothing_and_keeps_existing_files(tmp_path):
    (tmp_path / "a.txt").write_text("old")
    with pytest.raises(RuntimeError, match="boom"):
        with OutputContract({"A": tmp_path / "a.txt", "B": tmp_path / "b.txt"}) as out:
            out.write_text("A", "new")
            raise RuntimeError("boom")
    assert _listing(tmp_path) == ["a.txt"]
    assert (tmp_path / "a.txt").read_text() == "old"


def test_nested_atomic_output_writes_the_contract_temp(tmp_path):
    with OutputContract({"A": tmp_path / "a.txt"}) as out:
        with atomic_output(out.path("A")) as inner:
            assert inner == out.path("A")
            Path(inner).write_text("x")
    assert _listing(tmp_path) == ["a.txt"]


@pytest.mark.parametrize("how", ["same", "symlink", "hardlink"])
def test_output_equal_to_an_input_is_refused(tmp_path, how):
    src = tmp_path / "gcps.points"
    src.write_text("mapX,mapY\n")
    target = src
    if how == "symlink":
        target = tmp_path / "link.points"
        target.symlink_to(src)
    elif how == "hardlink":
        target = tmp_path / "hard.points"
        os.link(src, target)
    with pytest.raises(InputError, match=r"OUTPUT_CSV .* same file as the input GCPS"):
        OutputContract({"OUTPUT_CSV": target}, inputs={"GCPS": src})
    assert src.read_text() == "mapX,mapY\n"


def test_two_outputs_at_one_path_refused(tmp_path):
    with pytest.raises(InputError, match="OUTPUT and OUTPUT_VARIANCE are both"):
        OutputContract({"OUTPUT": tmp_path / "x.tif", "OUTPUT_VARIANCE": tmp_path / "x.tif"})


def test_sigterm_mid_write_leaves_nothing(tmp_path):
    code = textwrap.dedent(f"""
        import sys, time
        from geomatics_toolbox.core.io.contract import OutputContract
        with OutputContract({{"A": {str(tmp_path / 'a.bin')!r}}}) as out:
            with open(out.path("A"), "wb") as fh:
                fh.write(b"x" * 1000)
                fh.flush()
                print("writing", flush=True)
                time.sleep(30)
    """)
    proc = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, text=True)
    assert proc.stdout.readline().strip() == "writing"
    proc.send_signal(signal.SIGTERM)
    proc.wait(timeout=20)
    assert proc.returncode != 0
    assert _listing(tmp_path) == []


def test_render_rtl_translates_and_isolates():
    r = Report("Report")
    r.section("Parameters").add(Table(["Parameter", "Value"], [["x.laz", 0.5]]))
    r.summary.append(Paragraph(T("{n} points", n=3)))
    html = render_html(r, lang="fa")
    assert '<html lang="fa" dir="rtl">' in html
    assert '<bdi dir="ltr">x.laz</bdi>' in html and '<bdi dir="ltr">0.500</bdi>' in html
    assert "<script" not in render_html(Report("<script>x</script>"))


def test_unwritable_output_folder_is_a_clear_error_before_anything_is_written(tmp_path):
    # /proc refuses new files even for root (chmod does not stop root)
    with pytest.raises(InputError, match=r"folder /proc .* cannot be written"):
        OutputContract({"A": tmp_path / "a.txt", "B": "/proc/report.html"})
    assert list(tmp_path.iterdir()) == []


def test_language_codes():
    from geomatics_toolbox.core.reporting.i18n import normalise_lang
    assert [normalise_lang(x) for x in ("C", "POSIX", "fa_IR", "ar-SA", "", None, "en_US.UTF-8")] \
        == ["en", "en", "fa", "ar", "en", "en", "en"]

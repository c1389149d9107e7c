"""Report layout in a real browser: numbers are never broken mid-token.

The GCP report table broke "2/2" and long numbers across lines (``overflow-wrap:
anywhere`` on every cell). Chromium lays the report out at a narrow width; a script
counts the lines of every numeric cell's text (Range.getClientRects).
"""
from __future__ import annotations

import re

import numpy as np
import pytest

from geomatics_toolbox.core.io import gcp as gcp_io
from geomatics_toolbox.core.rectification import assess, report
from geomatics_toolbox.core.reporting import render_html
from geomatics_toolbox.synthetic import gcp as gcp_synthetic

MEASURE = """<script>
document.querySelectorAll('td').forEach(function (td) {
  var r = document.createRange(); r.selectNodeContents(td);
  var tops = new Set(Array.from(r.getClientRects()).map(function (q) {
    return Math.round(q.top); }));
  td.setAttribute('data-lines', String(tops.size));
});
</script></body>"""


@pytest.fixture(scope="module")
def browser():
    import importlib.util
    from pathlib import Path
    spec = importlib.util.spec_from_file_location(
        "geomatics_browser", Path(__file__).resolve().parents[1] / "browser.py")
    mod = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(mod)
    if mod.chromium() is None:
        pytest.skip("Chromium not installed (Debian package 'chromium')")
    return mod


@pytest.mark.parametrize("lang", ["en", "ar"])
def test_gcp_report_numbers_stay_on_one_line(browser, tmp_path, lang):
    pix, mp, _, size = gcp_synthetic.transformed_gcps("polynomial2", noise=0.5, seed=7)
    role = np.array(["gcp"] * len(pix), dtype=object)
    role[1:13:3] = "check"
    g = gcp_io.make_gcps(None, pix, mp, role=role, crs="EPSG:22780")
    a = assess.assess_gcps(g, kind=assess.RECOMMENDED, image_size=size)
    html = render_html(report.build_report(a), lang=lang)
    page = tmp_path / "gcp.html"
    page.write_text(html.replace("</body>", MEASURE), encoding="utf-8")
    out = browser._run(["--window-size=700,2000", "--dump-dom", page.as_uri()], 120)
    assert out.returncode == 0 and "data-lines" in out.stdout, out.stderr[-2000:]
    cells = re.findall(r'<td class="num" data-lines="(\d+)">(.*?)</td>', out.stdout)
    assert len(cells) > 100
    broken = [re.sub(r"<[^>]+>", "", text) for n, text in cells if int(n) > 1]
    assert not broken, broken[:10]
    # fractions such as "15/21" are one token too
    fractions = re.findall(r'<td[^>]*data-lines="(\d+)"[^>]*>(?:<[^>]+>)*\d+/\d+', out.stdout)
    assert all(n == "1" for n in fractions)

"""Render HTML in Debian's headless Chromium and read what a user would see.

``dump_dom(path)`` returns the DOM after Chromium parsed and laid out the page;
``screenshot(path, png)`` writes a PNG. Both run Chromium with a throw-away profile
and no network services, so they work offline and leave nothing behind.
``english_leftovers(dom)`` lists English words outside data (``<bdi>``, ``dir="ltr"``
spans, formulas, ``<style>``) that are not on the allow-list of units, ids and acronyms.
"""
from __future__ import annotations

import re
import shutil
import subprocess
import tempfile
from html.parser import HTMLParser
from pathlib import Path

FLAGS = ("--headless", "--no-sandbox", "--disable-gpu", "--disable-quic", "--no-first-run",
         "--disable-background-networking", "--disable-component-update", "--disable-sync")

#: Words allowed untranslated in an Arabic/Persian report: units, acronyms, symbols.
ALLOWED = {
    "cm", "mm", "px", "µm", "km", "deg", "gsd", "dtm", "dsm", "ndsm", "rmse", "nmad",
    "lidar", "las", "laz", "idw", "isprs", "gcp", "gcps", "epsg", "crs", "svg", "html",
    "csv", "tin", "qgis", "pdal", "lsq", "asprs", "kappa", "utm", "wgs", "tif", "tiff",
    "geotiff", "xyz", "theo", "meas", "sub", "max", "min", "std",
    "xmin", "xmax", "ymin", "ymax", "zmin", "zmax",   # coordinate names (ids)
    "nugget", "sill", "pykrige", "dask",   # terms glossed in parentheses, libraries
    # authors cited in the reports (names are not translated)
    "vosselman", "sithole", "khalil", "shepard", "matheron", "cressie", "kraus", "gülch",
    "axelsson", "zhang", "kriging", "tan", "cos", "sin", "log", "exp",
    "elit", "pts", "pingel", "kostrikov", "rabbani",   # software, units, authors
}


def chromium() -> str | None:
    """Path of the Chromium executable, or None."""
    for name in ("chromium", "chromium-browser", "google-chrome"):
        exe = shutil.which(name)
        if exe:
            return exe
    return None


def _run(args, timeout: float) -> subprocess.CompletedProcess:
    exe = chromium()
    if exe is None:
        raise RuntimeError("Chromium not found: install the Debian package 'chromium'")
    with tempfile.TemporaryDirectory(prefix="chromium-profile-") as profile:
        return subprocess.run([exe, *FLAGS, f"--user-data-dir={profile}", *args],
                              capture_output=True, text=True, timeout=timeout)


def dump_dom(html_path, *, timeout: float = 120) -> str:
    """The serialised DOM of ``html_path`` as headless Chromium builds it."""
    out = _run(["--dump-dom", Path(html_path).resolve().as_uri()], timeout)
    if out.returncode != 0 or "<html" not in out.stdout:
        raise RuntimeError(f"chromium failed ({out.returncode}): {out.stderr[-2000:]}")
    return out.stdout


def screenshot(html_path, png_path, *, width: int = 1100, height: int = 1400,
               timeout: float = 120) -> Path:
    """Write a PNG screenshot of ``html_path``; returns its path."""
    png = Path(png_path).resolve()
    out = _run([f"--screenshot={png}", f"--window-size={width},{height}",
                "--hide-scrollbars", Path(html_path).resolve().as_uri()], timeout)
    if not png.exists():
        raise RuntimeError(f"chromium wrote no screenshot ({out.returncode}): "
                           f"{out.stderr[-2000:]}")
    return png


class _Page(HTMLParser):
    """Collects the root's lang/dir, figure ids and text outside data spans."""

    DATA_TAGS = {"bdi", "style", "script", "code"}

    def __init__(self):
        super().__init__(convert_charrefs=True)
        self.lang = self.dir = None
        self.figures = []
        self.texts = []
        self._stack = []          # (tag, is_data)

    def handle_starttag(self, tag, attrs):
        attrs = dict(attrs)
        if tag == "html":
            self.lang, self.dir = attrs.get("lang"), attrs.get("dir")
        if tag == "figure" and attrs.get("id"):
            self.figures.append(attrs["id"])
        parent_data = bool(self._stack and self._stack[-1][1])
        is_data = (parent_data or tag in self.DATA_TAGS
                   or (attrs.get("dir") == "ltr" and tag not in ("html", "body"))
                   or "formula" in (attrs.get("class") or ""))
        if tag not in {"br", "meta", "img", "hr", "input", "link"}:
            self._stack.append((tag, is_data))

    def handle_endtag(self, tag):
        for i in range(len(self._stack) - 1, -1, -1):
            if self._stack[i][0] == tag:
                del self._stack[i:]
                break

    def handle_data(self, data):
        if data.strip() and not (self._stack and self._stack[-1][1]):
            self.texts.append(data.strip())


def parse(dom: str) -> _Page:
    """Parse a DOM dump: ``.lang``, ``.dir``, ``.figures`` (ids), ``.texts``."""
    page = _Page()
    page.feed(dom)
    return page


def english_leftovers(texts, allowed=ALLOWED) -> list:
    """Text pieces holding an English word that is neither data nor allow-listed.

    A word is English when it is Latin letters only, at least three long and not
    all capitals (acronyms such as RMSE are ids); file names and words with digits
    or underscores are data.
    """
    out = []
    for text in texts:
        words = [w for w in re.findall(r"[A-Za-zÀ-ÿ][\w'.\-]*", text)
                 if re.fullmatch(r"[A-Za-z]{3,}", w) and not w.isupper()
                 and w.lower() not in allowed]
        if words:
            out.append(text)
    return out


#: Measures the laid-out page: value/unit order of every ``bdi.qty`` and the boxes of
#: each figure's legend, north arrow and scale bar (appended to a copy of the page).
_PROBE = """<script>(function () {
  function box(e) { var r = e.getBoundingClientRect(); return [r.left, r.top, r.right, r.bottom]; }
  var out = {qty: [], figures: []};
  document.querySelectorAll("bdi.qty").forEach(function (q) {
    out.qty.push({text: q.textContent, value: box(q.querySelector(".v")),
                  unit: box(q.querySelector(".u"))});
  });
  document.querySelectorAll("figure svg").forEach(function (s) {
    var boxes = {};
    ["legend", "north", "scale-bar"].forEach(function (c) {
      var g = s.querySelector("g." + c);
      if (g) { boxes[c] = box(g); }
    });
    out.figures.push({id: s.closest("figure").id || "", svg: box(s), boxes: boxes});
  });
  var pre = document.createElement("pre");
  pre.id = "layout-probe";
  pre.textContent = JSON.stringify(out);
  document.body.appendChild(pre);
})();</script>"""


def layout(html_path, *, timeout: float = 120) -> dict:
    """Boxes (left, top, right, bottom in CSS px) measured in Chromium's layout.

    ``{"qty": [{"text", "value", "unit"}], "figures": [{"id", "svg", "boxes": {"legend",
    "north", "scale-bar"}}]}``.
    """
    import json
    html = Path(html_path).read_text(encoding="utf-8")
    with tempfile.TemporaryDirectory(prefix="layout-") as tmp:
        probe = Path(tmp) / "probe.html"
        probe.write_text(html.replace("</body>", _PROBE + "</body>", 1), encoding="utf-8")
        out = _run(["--window-size=1100,1400", "--dump-dom", probe.as_uri()], timeout)
    match = re.search(r'<pre id="layout-probe">(.*?)</pre>', out.stdout, re.S)
    if not match:
        raise RuntimeError(f"no layout probe in the DOM ({out.returncode}): "
                           f"{out.stderr[-2000:]}")
    import html as html_lib
    return json.loads(html_lib.unescape(match.group(1)))


def overlap(a, b) -> bool:
    """True when boxes ``a`` and ``b`` (left, top, right, bottom) intersect."""
    if not a or not b:
        return False
    return a[0] < b[2] and b[0] < a[2] and a[1] < b[3] and b[1] < a[3]


def layout_problems(lay: dict) -> list:
    """Units shown before their number, legends over north arrows / scale bars or
    outside their figure."""
    out = [f"unit before number: {q['text']!r}" for q in lay["qty"]
           if not q["value"][2] <= q["unit"][0] + 0.5]
    for f in lay["figures"]:
        b = f["boxes"]
        for other in ("north", "scale-bar"):
            if overlap(b.get("legend"), b.get(other)):
                out.append(f"figure {f['id']}: legend overlaps the {other}")
        for name, r in b.items():
            s = f["svg"]
            if r[0] < s[0] - 1 or r[2] > s[2] + 1:
                out.append(f"figure {f['id']}: {name} outside the figure ({r} vs {s})")
    return out

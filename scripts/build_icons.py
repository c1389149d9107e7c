#!/usr/bin/env python3
"""Draw the per-algorithm toolbox icons: provider/icons/<algorithm name>.svg.

Simple 32 × 32 pictograms in one palette, drawn here as SVG text so they stay small,
crisp at 16 px and consistent. Each algorithm has its own (``icon()`` in
algorithms/base.py picks ``<name()>.svg``); rerun after adding an algorithm and commit
the files (tests/qgis/test_icons.py checks that every algorithm has one).

Usage: ``python scripts/build_icons.py``.
"""
from __future__ import annotations

from pathlib import Path

OUT = Path(__file__).resolve().parents[1] / "provider" / "icons"

# palette
GROUND, TERRAIN, POINT, ACCENT, RED, GREY, BLUE, DARK, PAPER = (
    "#8c5a2b", "#5b9a3c", "#2f6fa8", "#e58a00", "#c0392b", "#7d8a93", "#1f5f8b",
    "#33414b", "#fdfdfd")


def svg(title: str, body: str) -> str:
    return ('<svg xmlns="http://www.w3.org/2000/svg" width="32" height="32" '
            'viewBox="0 0 32 32">\n'
            f"  <title>{title}</title>\n{body}</svg>\n")


def dots(points, fill=POINT, r=1.4) -> str:
    return "".join(f'  <circle cx="{x}" cy="{y}" r="{r}" fill="{fill}"/>\n'
                   for x, y in points)


def line(d, stroke, width=2.0, extra="") -> str:
    return (f'  <path d="{d}" fill="none" stroke="{stroke}" stroke-width="{width}" '
            f'stroke-linecap="round" stroke-linejoin="round"{extra}/>\n')


def shape(d, fill, stroke="none", width=1.0) -> str:
    return (f'  <path d="{d}" fill="{fill}" stroke="{stroke}" stroke-width="{width}" '
            'stroke-linejoin="round"/>\n')


GROUND_LINE = "M2 25 L9 21 L15 23 L22 18 L30 21"
GROUND_DOTS = [(5, 23.3), (12, 22), (18.5, 20.6), (26, 19.5)]
ABOVE_DOTS = [(6, 12), (11, 8), (16, 14), (21, 7), (26, 11)]


def cloud_over_ground(mark: str = "") -> str:
    return (shape(GROUND_LINE + " L30 30 L2 30 Z", "#e9dcc9") + line(GROUND_LINE, GROUND)
            + dots(ABOVE_DOTS, GREY) + dots(GROUND_DOTS, GROUND) + mark)


def grid(x0, y0, n, cell, fills) -> str:
    out = ""
    for i in range(n):
        for j in range(n):
            out += (f'  <rect x="{x0 + j * cell}" y="{y0 + i * cell}" width="{cell}" '
                    f'height="{cell}" fill="{fills[(i * n + j) % len(fills)]}" '
                    f'stroke="{PAPER}" stroke-width="0.6"/>\n')
    return out


def page(x=17, y=13) -> str:
    return (shape(f"M{x} {y} h11 l3 3 v14 h-14 Z", PAPER, DARK, 1.2)
            + line(f"M{x + 3} {y + 7} h8 M{x + 3} {y + 10.5} h8 M{x + 3} {y + 14} h5",
                   GREY, 1.2))


def camera(x=3, y=5) -> str:
    return (shape(f"M{x} {y + 3} h4 l2 -3 h6 l2 3 h4 v11 h-18 Z", DARK)
            + f'  <circle cx="{x + 9}" cy="{y + 8.5}" r="3.6" fill="{PAPER}"/>\n'
            + f'  <circle cx="{x + 9}" cy="{y + 8.5}" r="2" fill="{BLUE}"/>\n')


def crosshair(x, y, color=RED) -> str:
    return (f'  <circle cx="{x}" cy="{y}" r="3" fill="none" stroke="{color}" '
            'stroke-width="1.4"/>\n'
            + line(f"M{x - 5} {y} h3 M{x + 2} {y} h3 M{x} {y - 5} v3 M{x} {y + 2} v3",
                   color, 1.4))


ICONS = {
    "groundfilter": ("Ground filter (recommended)", cloud_over_ground(
        shape("M25 2 l1.6 3.3 3.6 .5 -2.6 2.5 .6 3.6 -3.2 -1.7 -3.2 1.7 .6 -3.6 "
              "-2.6 -2.5 3.6 -.5 Z", ACCENT))),
    "ptdgroundfilter": ("Progressive TIN densification", shape(
        "M2 26 L9 20 L15 24 L22 17 L30 22 L30 30 L2 30 Z", "#e9dcc9")
        + line("M2 26 L9 20 L15 24 L22 17 L30 22 M9 20 L9 30 M15 24 L22 30 M22 17 L22 30 "
               "M9 20 L15 30 M15 24 L15 30", GROUND, 1.4)
        + dots([(9, 20), (15, 24), (22, 17), (2, 26), (30, 22)], GROUND, 1.6)
        + dots([(6, 9), (12, 13), (18, 7), (25, 10)], GREY)),
    "lsqgroundfilter": ("Least-squares ground filter", dots(
        [(4, 22), (8, 19), (12, 20), (16, 17), (20, 17), (24, 14), (28, 13)], GROUND)
        + dots([(7, 9), (13, 6), (19, 10), (25, 6)], GREY)
        + line("M2 23 C10 19 18 18 30 12", ACCENT, 2.2)),
    "slopegroundfilter": ("Slope-based ground filter", cloud_over_ground(
        line("M16 14 L9 21 M16 14 L23 21", RED, 1.4, ' stroke-dasharray="2 1.5"')
        + line("M12.5 17.5 A5 5 0 0 0 19.5 17.5", RED, 1.2))),
    "slopethresholdsweep": ("Slope threshold sweep", line(
        "M4 28 L28 22 M4 28 L26 14 M4 28 L22 7 M4 28 L15 4", BLUE, 1.6)
        + line("M4 28 L28 28", DARK, 1.6)
        + dots([(28, 22), (26, 14), (22, 7), (15, 4)], ACCENT, 1.8)),
    "classify": ("Classify point cloud (ASPRS)", line(GROUND_LINE, GROUND)
        + dots(GROUND_DOTS, GROUND)
        + shape("M17 18 v-8 h8 v7", "#d9d9d9", RED, 1.4)
        + dots([(19, 10), (23, 10), (21, 10)], RED, 1.3)
        + f'  <circle cx="8" cy="12" r="4.5" fill="{TERRAIN}"/>\n'
        + line("M8 16.5 V21", GROUND, 1.6)),
    "catalog": ("Process a LiDAR tile catalog", grid(4, 4, 2, 12, ["#cfe3f3", "#e3efd6"])
        + shape("M8 8 h16 v16 h-16 Z", "none", ACCENT, 1.6)
        + line("M2 2 h28 v28 h-28 Z", GREY, 1.0, ' stroke-dasharray="2 2"')
        + dots([(10, 10), (14, 13), (19, 11), (22, 20), (12, 21), (17, 18)], POINT, 1.2)),
    "lidarqa": ("Point density and quality", grid(2, 2, 3, 7, [
        "#fde0c5", "#f9b27a", "#e58a00", "#f9b27a", "#c0392b", "#fde0c5", "#e58a00",
        "#fde0c5", "#f9b27a"])
        + f'  <circle cx="21" cy="20" r="6" fill="{PAPER}" fill-opacity="0.8" '
          f'stroke="{DARK}" stroke-width="2"/>\n'
        + line("M25.5 24.5 L30 29", DARK, 3)),
    "buildings": ("Building footprints with heights", shape(
        "M6 27 V13 L13 9 L26 13 V27 Z", "#dfe4e8", DARK, 1.4)
        + shape("M6 13 L13 9 L26 13 L19 17 Z", RED, DARK, 1.2)
        + line("M19 17 V27", DARK, 1.2) + line("M29 27 V13", ACCENT, 1.6)
        + line("M27.5 14.5 L29 13 L30.5 14.5", ACCENT, 1.4)
        + line("M3 27.5 H30", GROUND, 1.6)),
    "idwdtm": ("DTM by inverse distance weighting", grid(2, 2, 4, 7, [
        "#e3efd6", "#cfe5b8", "#b5d693", "#9cc770"])
        + f'  <circle cx="16" cy="16" r="9" fill="none" stroke="{BLUE}" '
          'stroke-width="1.2" stroke-dasharray="2 1.5"/>\n'
        + dots([(16, 16)], ACCENT, 2.2) + dots([(9, 11), (22, 10), (23, 22), (10, 22)],
                                                POINT, 1.6)
        + line("M16 16 L9 11 M16 16 L22 10 M16 16 L23 22 M16 16 L10 22", BLUE, 1.0)),
    "krigingdtm": ("DTM by kriging", line("M3 28 H29 M3 28 V4", DARK, 1.4)
        + line("M3 24 C9 13 13 9 20 8 H29", BLUE, 2.2)
        + dots([(6, 21), (9, 16), (13, 12), (17, 10), (21, 8.5), (25, 8), (28, 9)],
               ACCENT, 1.4)
        + line("M3 24 H6", RED, 1.6)),
    "dsm": ("DSM and nDSM", line(GROUND_LINE, GROUND, 1.6)
        + f'  <circle cx="8" cy="15" r="4.5" fill="{TERRAIN}"/>\n'
        + shape("M17 21 V12 H25 V20", "#dfe4e8", DARK, 1.2)
        + line("M2 18 C4 10 12 9 13 15 L17 12 H25 L30 14", ACCENT, 2)),
    "tindtm": ("DTM by TIN", shape("M3 26 L10 6 L20 11 L29 4 L28 24 L15 28 Z", "#e3efd6")
        + line("M3 26 L10 6 L20 11 L29 4 L28 24 L15 28 Z M10 6 L15 28 M20 11 L15 28 "
               "M20 11 L28 24 M3 26 L15 28 M10 6 L20 11", TERRAIN, 1.3)
        + dots([(3, 26), (10, 6), (20, 11), (29, 4), (28, 24), (15, 28)], GROUND, 1.6)),
    "elevationchange": ("Elevation change between two epochs", shape(
        "M2 18 C8 12 12 12 16 16 S24 24 30 16 V30 H2 Z", "#e9dcc9")
        + line("M2 18 C8 12 12 12 16 16 S24 24 30 16", GROUND, 1.6)
        + line("M2 18 C8 18 12 20 16 16 S24 12 30 16", BLUE, 1.6,
               ' stroke-dasharray="2.5 1.5"')
        + line("M5 6 h6 M8 3 v6", TERRAIN, 2) + line("M21 6 h6", RED, 2)),
    "lidartodtm": ("LiDAR to DTM with accuracy", dots(
        [(3, 8), (6, 5), (8, 10), (4, 13), (9, 15), (6, 19), (3, 23), (8, 24)], POINT, 1.3)
        + line("M11.5 16 H16 M14 13.5 L16.5 16 L14 18.5", DARK, 1.6)
        + grid(19, 8, 2, 5, ["#cfe5b8", "#9cc770", "#b5d693", "#e3efd6"])
        + line("M21 24 l2 2.5 l4.5 -5", TERRAIN, 2)),
    "publishoutputs": ("Publish outputs", shape(
        "M3 9 h9 l2 3 h15 v15 h-26 Z", "#f5d9a8", DARK, 1.2)
        + line("M16 24 V15 M12.5 18.5 L16 15 L19.5 18.5", DARK, 1.8)),
    "rectifygcp": ("Rectify image with GCPs", shape(
        "M4 8 L15 5 L13 18 L3 19 Z", "#cfe3f3", GREY, 1.2)
        + line("M16 12 H19 M17.5 10.5 L19.5 12 L17.5 13.5", DARK, 1.4)
        + shape("M20 6 H30 V16 H20 Z", "#cfe3f3", BLUE, 1.4) + crosshair(25, 24)
        + dots([(4, 8), (15, 5), (13, 18), (3, 19)], RED, 1.3)),
    "gcpaccuracyreport": ("GCP accuracy report", page(3, 3)
        + crosshair(23, 21)
        + line("M23 21 L28 16", ACCENT, 1.6) + line("M26.5 15.5 L28 16 L27.5 17.5",
                                                     ACCENT, 1.2)),
    "rectifybatch": ("Rectify a folder of images", shape(
        "M8 3 H29 V18 H8 Z", "#e8eef3", GREY, 1.0)
        + shape("M5 7 H26 V22 H5 Z", "#d6e4ef", GREY, 1.0)
        + shape("M2 11 H23 V26 H2 Z", "#cfe3f3", BLUE, 1.4) + crosshair(12.5, 18.5)),
    "gsdcalculator": ("GSD and photogrammetric accuracy calculator", camera(7, 1)
        + line("M16 16 L6 27 M16 16 L26 27", GREY, 1.0, ' stroke-dasharray="1.5 1.5"')
        + grid(9, 27, 1, 4, [ACCENT]) + line("M3 29 H29", GROUND, 1.4)),
    "gsdbatch": ("GSD calculator over a table", camera(1, 1)
        + grid(14, 14, 3, 5.5, [PAPER, "#e8eef3"])
        + shape("M14 14 h16.5 v16.5 h-16.5 Z", "none", DARK, 1.2)),
    "groundfilteraccuracy": ("Ground filter accuracy", line(GROUND_LINE, GROUND)
        + dots(GROUND_DOTS, GROUND)
        + line("M4 11 l3 3 l6 -7", TERRAIN, 2.4) + line("M19 6 l7 7 M26 6 l-7 7", RED, 2.4)),
    "dtmaccuracy": ("DTM accuracy against check points", shape(
        "M2 20 C9 15 15 17 22 13 S28 12 30 12 V30 H2 Z", "#e3efd6")
        + line("M2 20 C9 15 15 17 22 13 S28 12 30 12", TERRAIN, 1.6)
        + shape("M7 10 l3 5 h-6 Z", RED) + line("M7 15 V18", RED, 1.4)
        + shape("M20 4 l3 5 h-6 Z", RED) + line("M20 9 V14", RED, 1.4)
        + line("M25 22 h5 M25 25 h5 M25 28 h3", DARK, 1.2)),
    "installdependencies": ("Install the Python packages", shape(
        "M5 13 L16 8 L27 13 V25 L16 30 L5 25 Z", "#f5d9a8", DARK, 1.3)
        + line("M5 13 L16 18 L27 13 M16 18 V30", DARK, 1.2)
        + line("M16 2 V11 M12.5 7.5 L16 11 L19.5 7.5", BLUE, 2.2)),
    "lidar_to_dtm": ("LiDAR to DTM with accuracy (model)", dots(
        [(4, 6), (8, 4), (6, 10)], POINT, 1.4)
        + shape("M13 4 h7 v6 h-7 Z", "#e9dcc9", GROUND, 1.2)
        + shape("M13 14 h7 v6 h-7 Z", "#cfe5b8", TERRAIN, 1.2)
        + shape("M13 24 h7 v6 h-7 Z", "#fde0c5", ACCENT, 1.2)
        + line("M9 7 H13 M16.5 10 V14 M16.5 20 V24", DARK, 1.4)
        + line("M23 27 l2 2.5 l4.5 -5", TERRAIN, 2)),
}


def main() -> None:
    OUT.mkdir(parents=True, exist_ok=True)
    for name, (title, body) in sorted(ICONS.items()):
        (OUT / f"{name}.svg").write_text(svg(title, body), encoding="utf-8")
    print(f"wrote {len(ICONS)} icons to {OUT}")


if __name__ == "__main__":
    main()

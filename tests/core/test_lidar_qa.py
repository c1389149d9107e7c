"""Point density and quality: densities, gaps, duplicates, noise, advice figures."""
from __future__ import annotations

import numpy as np
import pytest

from geomatics_toolbox.core.errors import InputError
from geomatics_toolbox.core.lidar import qa
from geomatics_toolbox.core.reporting import render_html
from geomatics_toolbox.core.reporting.i18n import has_translation


def _cloud(density=2.0, seed=0):
    """A 100 x 100 m cloud: ground everywhere except a 20 x 20 m roof (class 6)."""
    rng = np.random.default_rng(seed)
    n = int(density * 100 * 100)
    x = rng.uniform(0, 100, n) + 500000.0
    y = rng.uniform(0, 100, n) + 4000000.0
    z = rng.normal(100, 0.1, n)
    roof = (x - 500000 >= 40) & (x - 500000 < 60) & (y - 4000000 >= 40) & \
        (y - 4000000 < 60)
    cls = np.where(roof, 6, 2)
    cls[:10] = 7
    rn = np.ones(n, int)
    nr = np.ones(n, int)
    nr[10:1010] = 2            # 1000 first-of-two returns: not last returns
    return x, y, z, cls, rn, nr, roof


def test_densities_gaps_counts():
    x, y, z, cls, rn, nr, roof = _cloud()
    x[-5:], y[-5:], z[-5:] = x[:5], y[:5], z[:5]          # five duplicates
    res = qa.lidar_qa(x, y, z, cls, rn, nr, scan_angle=np.linspace(-20, 18, x.size),
                      cell_size=5.0)
    assert res.grid.shape == (20, 20)
    assert res.n_points == x.size and res.n_last == x.size - 1000
    assert res.n_duplicates == 5 and res.n_noise == 10
    assert res.covered_area == pytest.approx(100 * 100)
    assert res.density == pytest.approx(2.0, rel=1e-9)
    assert res.ground_density == pytest.approx((cls == 2).sum() / 1e4)
    # the 20 x 20 m roof is exactly 16 gap cells of 5 m (no ground point in them)
    assert res.gaps.sum() == 16 and res.gap_share == pytest.approx(16 / 400)
    assert res.density_all.sum() * 25 == pytest.approx(x.size)
    assert res.scan_angle == (-20.0, 18.0)
    assert res.class_counts[6] == roof.sum() and res.return_counts == {1: x.size}


@pytest.mark.parametrize("density,window,lod", [(1.0, 2.0, "LOD2"), (1.5, 2.0, "LOD2"),
                                                (2.0, 2.0, "LOD2"), (0.6, 3.0, "LOD1"),
                                                (8.0, 1.0, "LOD2"), (30.0, 0.5, "LOD2")])
def test_advice_follows_the_elit_rules(density, window, lod):
    a = qa.advise(density, density / 2, 0.0, 0.0)
    assert a["ground_window"] == window and a["lod"] == lod
    spacing = 1 / np.sqrt(density / 2)
    assert a["dtm_cell"] >= spacing and a["dtm_cell"] in qa.NICE_CELLS
    smaller = [c for c in qa.NICE_CELLS if c < a["dtm_cell"]]
    assert not smaller or smaller[-1] < spacing


def test_degrees_and_bad_cell_are_refused():
    x, y, z, cls, rn, nr, _ = _cloud(density=0.1)
    with pytest.raises(InputError, match="degrees"):
        qa.lidar_qa(x / 1e4 - 40, y / 1e5, z, cls, rn, nr)
    with pytest.raises(InputError, match="Cell size"):
        qa.lidar_qa(x, y, z, cls, rn, nr, cell_size=0)




def test_report_has_maps_and_translations():
    x, y, z, cls, rn, nr, _ = _cloud()
    rep = qa.qa_report(qa.lidar_qa(x, y, z, cls, rn, nr), "t.laz")
    missing = [m for m in rep.messages() for lang in ("ar", "fa")
               if not has_translation(m, lang)]
    assert not missing
    html = render_html(rep, lang="fa")
    for fid in ("density-map", "gap-map", "returns-histogram", "classes-histogram"):
        assert f'id="{fid}"' in html
    window = rep.summary[0].text                    # the ground window at 2 pts/m²
    assert window.text.startswith("Ground filter window") and window.args["w"] == "2"

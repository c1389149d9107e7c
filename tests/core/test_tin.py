"""TIN DTM against GDAL's gdal_grid -a linear (the oracle), gaps, bad input."""
from __future__ import annotations

import numpy as np
import pytest

from geomatics_toolbox.core.errors import InputError
from geomatics_toolbox.core.terrain.grid import grid_from_extent
from geomatics_toolbox.core.terrain.tin import tin_grid

gdal = pytest.importorskip("osgeo.gdal")
ogr = pytest.importorskip("osgeo.ogr")
gdal.UseExceptions()


def gdal_linear(x, y, z, grid):
    """gdal.Grid linear (radius=0: nodata outside the hull) onto ``grid``.

    Coordinates are given to GDAL relative to the grid's lower-left corner (an exact
    translation): GDAL's barycentric coefficients lose millimetres at UTM magnitudes.
    """
    ds = gdal.GetDriverByName("Memory").Create("", 0, 0, 0, gdal.GDT_Unknown)
    lyr = ds.CreateLayer("p", geom_type=ogr.wkbPoint25D)
    defn = lyr.GetLayerDefn()
    for a, b, c in zip(x - grid.xmin, y - grid.ymin, z):
        f = ogr.Feature(defn)
        g = ogr.Geometry(ogr.wkbPoint25D)
        g.AddPoint(float(a), float(b), float(c))
        f.SetGeometry(g)
        lyr.CreateFeature(f)
    w, h = grid.xmax - grid.xmin, grid.ymax - grid.ymin
    out = gdal.Grid("/vsimem/tin_oracle.tif", ds, format="GTiff",
                    outputType=gdal.GDT_Float64, width=grid.ncols, height=grid.nrows,
                    outputBounds=[0.0, h, w, 0.0], algorithm="linear:radius=0:nodata=-9999")
    arr = out.GetRasterBand(1).ReadAsArray()
    out = None
    gdal.Unlink("/vsimem/tin_oracle.tif")
    return np.where(arr == -9999, np.nan, arr)


@pytest.fixture(scope="module")
def cloud():
    rng = np.random.default_rng(5)
    n = 6000
    x = rng.uniform(600000, 600120, n)
    y = rng.uniform(3900000, 3900090, n)
    z = 850 + 0.2 * (x - 600000) + 4 * np.sin((y - 3900000) / 9)
    keep = ~((np.abs(x - 600060) < 12) & (np.abs(y - 3900045) < 10))  # a 24 x 20 m gap
    return x[keep], y[keep], z[keep]


def test_tin_equals_gdal_linear(cloud):
    x, y, z = cloud
    grid = grid_from_extent((600000, 600120, 3900000, 3900090), 0.5)
    ours = tin_grid(x, y, z, grid, fill=True).z
    ref = gdal_linear(x, y, z, grid)
    assert np.array_equal(np.isnan(ours), np.isnan(ref))
    assert np.isfinite(ours).sum() > 0.97 * grid.size
    assert np.nanmax(np.abs(ours - ref)) < 1e-6


def test_tin_reproduces_a_plane_exactly():
    rng = np.random.default_rng(1)
    x, y = rng.uniform(0, 50, 800), rng.uniform(0, 50, 800)
    z = 3.0 + 0.1 * x - 0.25 * y
    grid = grid_from_extent((0, 50, 0, 50), 1.0)
    res = tin_grid(x, y, z, grid, fill=True)
    xx, yy = np.meshgrid(grid.x_centers(), grid.y_centers())
    ok = np.isfinite(res.z)
    assert ok.sum() > 0.9 * grid.size
    assert np.allclose(res.z[ok], (3.0 + 0.1 * xx - 0.25 * yy)[ok], atol=1e-9)


def test_gap_stays_nodata_unless_filled(cloud):
    x, y, z = cloud
    grid = grid_from_extent((600000, 600120, 3900000, 3900090), 1.0)
    kept = tin_grid(x, y, z, grid, max_edge=6.0)
    filled = tin_grid(x, y, z, grid, fill=True)
    xx, yy = np.meshgrid(grid.x_centers(), grid.y_centers())
    inner = (np.abs(xx - 600060) < 9) & (np.abs(yy - 3900045) < 7)
    assert np.isnan(kept.z[inner]).all() and np.isfinite(filled.z[inner]).all()
    assert kept.n_long > 0 and filled.n_long == 0 and filled.max_edge is None
    # away from the gap both agree
    far = ~((np.abs(xx - 600060) < 16) & (np.abs(yy - 3900045) < 14))
    both = far & np.isfinite(kept.z)
    assert both.sum() > 0.9 * far.sum()
    assert np.array_equal(kept.z[both], filled.z[both])


def test_bad_inputs():
    grid = grid_from_extent((0, 10, 0, 10), 1.0)
    with pytest.raises(InputError, match="at least three"):
        tin_grid([0, 1], [0, 1], [0, 1], grid)
    with pytest.raises(InputError, match="cannot be triangulated"):
        tin_grid([0, 1, 2, 3], [0, 1, 2, 3], [0, 1, 2, 3], grid)
    with pytest.raises(InputError, match="max_edge"):
        tin_grid([0, 5, 0], [0, 0, 5], [1, 1, 1], grid, max_edge=-1.0)


def test_cancel_and_progress(cloud):
    from geomatics_toolbox.core.progress import Cancelled
    x, y, z = cloud
    grid = grid_from_extent((600000, 600120, 3900000, 3900090), 1.0)
    seen = []
    tin_grid(x, y, z, grid, progress=seen.append)
    assert seen[-1] == 1.0 and seen == sorted(seen)
    with pytest.raises(Cancelled):
        tin_grid(x, y, z, grid, cancel=lambda: True)


def test_report_content_is_built_in_core(cloud):
    """The TIN report (core/terrain/report.tin_report) states the run's own figures."""
    from geomatics_toolbox.core.reporting import KeyValues, render_html
    from geomatics_toolbox.core.reporting.i18n import has_translation
    from geomatics_toolbox.core.terrain.report import tin_report
    x, y, z = cloud
    grid = grid_from_extent((600000, 600120, 3900000, 3900090), 1.0)
    res = tin_grid(x, y, z, grid, max_edge=6.0)
    rep = tin_report(res, "ground.laz", len(x) + 7, grid)
    rows = {str(r[0]): r[1] for s in rep.sections for b in s.blocks
            if isinstance(b, KeyValues) for r in b.rows}
    ok = np.isfinite(res.z)
    assert rows["Points in file"] == len(x) + 7 and rows["Points triangulated"] == len(x)
    assert rows["Triangles"] == res.n_triangles and rows["Triangles dropped (edge too long)"] \
        == res.n_long > 0
    assert rows["Cells with a value"] == ok.sum() and rows["Nodata cells"] == (~ok).sum()
    assert rows["Minimum height (m)"] == pytest.approx(np.nanmin(res.z))
    assert rows["Grid (columns × rows)"] == "120 × 90"
    assert not [m for m in rep.messages() for lang in ("ar", "fa")
                if not has_translation(m, lang)]
    assert 'id="dtm-map"' in render_html(rep, lang="ar")
    filled = tin_report(tin_grid(x, y, z, grid, fill=True), "g.laz", len(x), grid)
    assert "Gaps were filled: long triangles were kept." in filled.messages()

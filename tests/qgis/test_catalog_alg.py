"""geomatics:catalog through processing.run: outputs, report, refusal of a bad folder."""
from __future__ import annotations

import numpy as np
import pytest

from geomatics_toolbox.core.io.las import read_las
from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile

ALG = "geomatics:catalog"


@pytest.fixture(scope="module")
def tiles(tmp_path_factory):
    d = tmp_path_factory.mktemp("tiles")
    for i in range(2):
        t = generate_tile(extent=(120.0, 120.0), origin=(500_000.0 + 120 * i, 4_000_000.0),
                          density=1.0, seed=i)
        write_tile(t, d / f"t{i}.laz")
    return d


def test_catalog_outputs_and_report(qgis_processing, tiles, tmp_path):
    out = tmp_path / "out"
    html = tmp_path / "report.html"
    res = qgis_processing.run(ALG, {"INPUT": str(tiles), "GROUND_FILTER": 0,
                                    "CELL_SIZE": 2.0, "BUFFER": 30.0, "WORKERS": 1,
                                    "OUTPUT_FOLDER": str(out), "OUTPUT_HTML": str(html),
                                    "REPORT_LANGUAGE": 3})
    assert res["N_TILES"] == 2 and res["N_FAILED"] == 0 and res["POINTS_PER_SECOND"] > 0
    for i in range(2):
        src = read_las(tiles / f"t{i}.laz", ("classification",))
        got = read_las(out / f"t{i}_classified.laz", ("classification",))
        assert np.array_equal(src["classification"], got["classification"])  # kept
        assert (out / f"t{i}_dtm.tif").exists()
    assert (out / "dtm.vrt").exists()
    text = html.read_text(encoding="utf-8")
    assert 'id="tile-status"' in text or "tile-status" in text
    assert 'dir="rtl"' in text


def test_output_folder_holding_the_tiles_is_refused(qgis_processing, tiles):
    from qgis.core import QgsProcessingException
    with pytest.raises(QgsProcessingException, match="contains input tiles"):
        qgis_processing.run(ALG, {"INPUT": str(tiles), "GROUND_FILTER": 0,
                                  "OUTPUT_FOLDER": str(tiles)})
    assert not list(tiles.glob("*_dtm.tif"))


def test_chunk_size_and_tin(qgis_processing, tiles, tmp_path):
    """CHUNK_SIZE=100 cuts the two 120 m tiles into 3 x 2 chunks; TIN is a DTM_METHOD option."""
    out = tmp_path / "out"
    from qgis.core import QgsApplication
    alg = QgsApplication.processingRegistry().algorithmById(ALG)
    options = alg.parameterDefinition("DTM_METHOD").options()
    res = qgis_processing.run(ALG, {"INPUT": str(tiles), "GROUND_FILTER": 0,
                                    "DTM_METHOD": options.index("TIN"), "CELL_SIZE": 2.0,
                                    "BUFFER": 30.0, "CHUNK_SIZE": 100.0, "WORKERS": 1,
                                    "OUTPUT_FOLDER": str(out)})
    assert res["N_TILES"] == 6 and res["N_FAILED"] == 0
    names = sorted(p.name for p in out.glob("chunk_*.laz"))
    assert names == [f"chunk_{500000 + 100 * i}_{4000000 + 100 * j}_classified.laz"
                     for i in range(3) for j in range(2)]
    n_src = sum(len(read_las(p)) for p in tiles.glob("t*.laz"))
    assert sum(len(read_las(out / n)) for n in names) == n_src

"""Every algorithm answers an invalid option in the interface language (Arabic here).

One refused case per algorithm, run through ``processing.run`` with the QGIS interface
in Arabic: the message must be Arabic (English only inside the bidi-isolated fields:
paths, numbers, parameter names). ``make lint`` (scripts/i18n_sync.py) keeps every
message a translated template; this test proves the user sees the translation.
"""
from __future__ import annotations

import re

import pytest
from qgis.core import QgsProcessingException

from geomatics_toolbox.core.errors import FSI, PDI
from geomatics_toolbox.synthetic.lidar import generate_tile, write_tile


@pytest.fixture(scope="module")
def data(tmp_path_factory):
    d = tmp_path_factory.mktemp("errors_ar")
    tile = generate_tile(extent=(60.0, 60.0), density=2.0, seed=3, n_buildings=1, n_halls=0)
    laz = d / "tile.laz"
    write_tile(tile, laz, crs="EPSG:32632")
    import numpy as np

    from geomatics_toolbox.core.io.raster import write_geotiff
    tif = d / "dtm.tif"
    write_geotiff(tif, np.full((10, 10), 100.0, np.float32),
                  geotransform=(500000.0, 1.0, 0.0, 4000010.0, 0.0, -1.0), crs="EPSG:32632")
    (d / "cams.csv").write_text("name,height\na,100\n", encoding="utf-8")
    return {"dir": d, "laz": str(laz), "missing": str(d / "nothere.laz"), "tif": str(tif)}


@pytest.fixture
def arabic_ui(arabic_ui):
    """QGIS interface language Arabic (tests/conftest.py's locale override) with the
    plugin's Qt translations installed, as the plugin does at start-up in an Arabic QGIS."""
    from pathlib import Path

    from qgis.PyQt.QtCore import QCoreApplication, QTranslator
    translator = QTranslator()
    qm = Path(__file__).resolve().parents[2] / "i18n" / "geomatics_toolbox_ar.qm"
    assert translator.load(str(qm)), "run `make qm` first"
    QCoreApplication.installTranslator(translator)
    yield
    QCoreApplication.removeTranslator(translator)


def _cases(d):
    laz, out, missing = d["laz"], str(d["dir"] / "o"), d["missing"]
    return {
        "gsdcalculator": {"K_M": 0.0},
        "gsdbatch": {"INPUT": str(d["dir"] / "cams.csv"), "OUTPUT": out + ".csv"},
        "rectifygcp": {"INPUT": d["tif"], "GCP_FILE": str(d["dir"] / "g.points"),
                       "OUTPUT": out + "_r.tif"},
        "gcpaccuracyreport": {"GCP_FILE": str(d["dir"] / "g.points")},
        "rectifybatch": {"INPUT_FOLDER": str(d["dir"] / "nofolder"),
                         "OUTPUT_FOLDER": out + "_b"},
        "idwdtm": {"INPUT": laz, "POWER": 0.0, "OUTPUT": out + ".tif"},
        "krigingdtm": {"INPUT": laz, "VARIOGRAM_SILL": 1.0, "OUTPUT": out + ".tif"},
        "dsm": {"INPUT": laz, "CELL_SIZE": 0.0, "OUTPUT": out + ".tif"},
        "tindtm": {"INPUT": laz, "CELL_SIZE": 0.0, "OUTPUT": out + ".tif"},
        "dtmaccuracy": {"DTM": d["tif"],
                        "CHECKPOINTS_CSV": str(d["dir"] / "cp.csv")},
        "lidartodtm": {"INPUT": laz, "CELL_SIZE": 0.0, "OUTPUT": out + ".laz",
                       "OUTPUT_DTM": out + ".tif", "CHECKPOINTS_CSV": str(d["dir"] / "cp.csv")},
        "publishoutputs": {"CLOUD": missing, "OUTPUT": out + ".laz"},
        "slopegroundfilter": {"INPUT": laz, "RADIUS": 0.0, "OUTPUT": out + ".laz"},
        "slopethresholdsweep": {"INPUT": laz, "SLOPES": "forty", "OUTPUT_CSV": out + ".csv"},
        "lsqgroundfilter": {"INPUT": laz, "TILE_SIZE": 0.0, "OUTPUT": out + ".laz"},
        "groundfilteraccuracy": {"INPUT": laz, "FIELD": "classification",
                                 "REFERENCE_FIELD": "classification"},
        "catalog": {"INPUT": str(d["dir"] / "nofolder"), "OUTPUT_FOLDER": out + "_c"},
        "lidarqa": {"INPUT": missing, "OUTPUT": out + ".tif"},
        "elevationchange": {"BEFORE": str(d["dir"] / "a.tif"),
                            "AFTER": str(d["dir"] / "b.tif"), "OUTPUT": out + ".tif"},
        "buildings": {"INPUT": missing, "OUTPUT": out + ".gpkg"},
        "classify": {"INPUT": missing, "OUTPUT": out + ".laz"},
        "groundfilter": {"INPUT": laz, "NOISE": True, "NOISE_RADIUS": 0.0,
                         "OUTPUT": out + ".laz"},
        "ptdgroundfilter": {"INPUT": laz, "MAX_DISTANCE": 1.0, "FINAL_DISTANCE": 2.0,
                            "OUTPUT": out + ".laz"},
    }


#: algorithms with no option a user can get wrong
NO_OPTIONS = {"installdependencies"}


def _arabic(message: str) -> bool:
    """Arabic text, English (Latin words) only inside the isolated fields."""
    outside = re.sub(f"{FSI}.*?{PDI}", " ", message, flags=re.S)
    outside = re.sub(r"\b[A-Z][A-Z0-9_]+\b|\.\w+|[A-Za-z]+\.(?:las|laz|tif|csv)\b", " ",
                     outside)
    latin_run = re.search(r"[A-Za-z]{3,}[ -][A-Za-z]{3,}", outside)
    return bool(re.search("[\u0600-\u06FF]", message)) and latin_run is None


def test_every_algorithm_has_a_case(qgis_app, data):
    from geomatics_toolbox.algorithms import all_algorithms
    ids = {a.name() for a in all_algorithms()}
    assert set(_cases(data)) | NO_OPTIONS == ids


@pytest.mark.parametrize("alg", sorted(_cases({"dir": __import__("pathlib").Path("."),
                                               "laz": "", "missing": "", "tif": ""})))
def test_invalid_option_is_refused_in_arabic(qgis_processing, arabic_ui, data, alg):
    params = _cases(data)[alg]
    with pytest.raises(QgsProcessingException) as info:
        qgis_processing.run(f"geomatics:{alg}", params)
    # QGIS's own prefix of a refused checkParameterValues (QGIS translates it itself)
    message = str(info.value).replace("Unable to execute algorithm\n", "")
    assert _arabic(message), f"{alg}: {message!r}"

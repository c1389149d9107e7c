"""Units compared by meaning, and unit facts shown in ar/fa as data (review H1, H2, H6, X2).

Two rasters or clouds are in the same units when their units mean the same lengths,
wherever the unit was read from (CRS, GeoKeys, band unit type, assumed). Messages
shown to Arabic and Persian users carry no English words: only their translated
template, and data (paths, numbers, unit symbols) bidi-isolated.
"""
from __future__ import annotations

import re

import numpy as np
import pytest

from geomatics_toolbox.core.coords import check_not_too_sparse
from geomatics_toolbox.core.errors import FSI, PDI, InputError
from geomatics_toolbox.core.io.units import (
    FOOT,
    METRE,
    US_FOOT,
    LinearUnit,
    Units,
    crs_units,
    units_rows,
)
from geomatics_toolbox.core.reporting.content import T


def english_words(message: str, *data: str) -> list:
    """Latin words of ``message`` that are not in the data it shows (paths, names, symbols).

    The fields of a translated message are bidi-isolated (FSI … PDI); each must be data,
    not an English sentence, so every Latin word must come from ``data``.
    """
    allowed = set(re.findall(r"[A-Za-z_]{2,}", " ".join(data)))
    words = re.findall(r"[A-Za-z_]{2,}", message.replace(FSI, " ").replace(PDI, " "))
    return [w for w in words if w not in allowed]


def test_units_equal_by_meaning_whatever_their_source():
    crs = crs_units("EPSG:32632")                                  # vertical 'assumed'
    band = crs_units("EPSG:32632", vertical=METRE, vertical_source="band")
    assert crs.vertical_source != band.vertical_source
    assert crs == band and band == crs and hash(crs) == hash(band)   # review H1: was !=
    assert LinearUnit("metre", 1.0, "m") == METRE                 # no EPSG code: same unit
    assert LinearUnit("Meter", 1.0, "meter", None) == METRE
    assert crs_units("EPSG:2903") != band                          # ftUS vs m
    assert FOOT != US_FOOT                                         # 2 ppm apart: different
    assert crs_units("EPSG:2903+5703") != crs_units("EPSG:2903")   # mixed vs all ftUS
    assert crs_units("EPSG:4326").horizontal == crs_units("EPSG:4258").horizontal  # degrees
    assert crs_units("EPSG:2903").symbols == "ftUS / ftUS"
    assert crs_units("EPSG:2903+5703").symbols == "ftUS / m"
    assert not hasattr(Units, "describe")                          # English; gone (H2)


@pytest.mark.parametrize("lang", ["ar", "fa"])
def test_sparse_cloud_refusal_has_no_english_words(lang):
    what = T("The point cloud {path}", path="/data/survey x.laz")
    with pytest.raises(InputError) as err:
        check_not_too_sparse(np.array([0.0, 3000.0, 0.0, 3000.0]),
                             np.array([0.0, 0.0, 3000.0, 3000.0]), what=what)
    en = str(err.value)
    assert en.startswith("The point cloud /data/survey x.laz holds 4 points"), en
    msg = err.value.message(lang)
    assert "/data/survey x.laz" in msg
    assert english_words(msg, "/data/survey x.laz") == [], msg
    assert "The point cloud" not in msg


@pytest.mark.parametrize("lang", ["ar", "fa"])
def test_catalog_refusal_of_unreadable_tiles_in_the_users_language(tmp_path, lang):
    """Review H6: the reasons of the unreadable tiles were English text in ar/fa."""
    from geomatics_toolbox.core.io.las import write_las
    from geomatics_toolbox.core.lidar.catalog import Catalog
    good = tmp_path / "good.las"
    write_las(good, np.array([0.0, 1.0]) + 5e5, np.array([0.0, 1.0]) + 4e6,
              np.array([1.0, 2.0]), crs="EPSG:32632")
    (tmp_path / "junk.las").write_bytes(b"junk" * 100)
    (tmp_path / "short.las").write_bytes(good.read_bytes()[:300])
    with pytest.raises(InputError) as err:
        Catalog.open(str(tmp_path))
    en = str(err.value)
    assert en.startswith("2 tile(s) cannot be read (junk.las: ") and "; short.las: " in en
    msg = err.value.message(lang)
    assert "junk.las" in msg and "short.las" in msg
    paths = [str(tmp_path / n) for n in ("junk.las", "short.las")]
    names = "SKIP_UNREADABLE LAS LAZ LASF las laz PDAL pdal translate"   # in translations
    assert english_words(msg, names, *paths) == [], msg


def test_one_units_row_for_every_report():
    assert units_rows(None) == [] and units_rows(crs_units("EPSG:32632")) == []
    (label, note), = units_rows(crs_units("EPSG:2903"))
    assert label == "Linear units" and note.args["hs"] == "ftUS"

"""Missing runtime packages: LiDAR algorithms refuse before running, translated; the
others need none; the installer algorithm is registered with its help."""
from __future__ import annotations

import pytest
from qgis.core import QgsProcessingException

from geomatics_toolbox.core import deps

ALL_MISSING = [r for r in deps.requirements()]


@pytest.fixture
def nothing_installed(monkeypatch):
    """Every runtime package reported missing (the packages stay importable)."""
    def fake(groups=None):
        wanted = None if groups is None else set(deps.groups_closure(groups))
        return [r for r in ALL_MISSING if wanted is None or r.group in wanted]
    monkeypatch.setattr(deps, "missing", fake)


@pytest.fixture
def ui_language(qgis_app):
    from qgis.core import QgsSettings
    settings = QgsSettings()
    old = (settings.value("locale/overrideFlag", False, type=bool),
           settings.value("locale/userLocale", ""))

    def set_lang(lang):
        settings.setValue("locale/overrideFlag", True)
        settings.setValue("locale/userLocale", lang)
    yield set_lang
    settings.setValue("locale/overrideFlag", old[0])
    settings.setValue("locale/userLocale", old[1])


def _alg(alg_id):
    from qgis.core import QgsApplication
    alg = QgsApplication.processingRegistry().createAlgorithmById(alg_id)
    assert alg is not None, alg_id
    return alg


@pytest.mark.parametrize("lang, words", [
    ("en", ("laspy, lazrs", "geomatics:installdependencies", "Processing Toolbox")),
    ("ar", ("laspy, lazrs", "geomatics:installdependencies", "صندوق أدوات المعالجة")),
    ("fa", ("laspy, lazrs", "geomatics:installdependencies", "جعبه‌ابزار پردازش"))])
def test_lidar_algorithm_refuses_before_running(qgis_processing, nothing_installed,
                                                ui_language, tmp_path, lang, words):
    ui_language(lang)
    out = tmp_path / "c.laz"
    src = tmp_path / "in.laz"
    src.write_bytes(b"not read")
    with pytest.raises(QgsProcessingException) as err:
        qgis_processing.run("geomatics:groundfilter", {"INPUT": str(src), "OUTPUT": str(out)})
    for word in words:
        assert word in str(err.value), (word, str(err.value))
    assert "dask" not in str(err.value)          # the catalog's packages are not named
    assert not out.exists()


def test_catalog_names_its_own_packages(qgis_app, nothing_installed, ui_language):
    ui_language("en")
    ok, msg = _alg("geomatics:catalog").checkParameterValues({}, None)
    assert not ok and "laspy, lazrs, dask, distributed" in msg


@pytest.mark.parametrize("alg_id, params", [
    ("geomatics:gsdcalculator", {"DISTANCE": 100, "SENSOR_WIDTH": 13.2,
                                 "IMAGE_WIDTH": 5472, "FOCAL_LENGTH": 8.8}),
    ("geomatics:elevationchange", {"INPUT": "/data/before.tif", "INPUT_AFTER": "after.tif"}),
])
def test_other_algorithms_need_no_package(qgis_app, nothing_installed, alg_id, params):
    alg = _alg(alg_id)
    assert alg.required_packages(params) == []
    assert alg.missing_packages_message(params) == ""


def test_gsd_runs_with_every_package_missing(qgis_processing, nothing_installed):
    res = qgis_processing.run("geomatics:gsdcalculator", {
        "DISTANCE": 5.88, "SENSOR_WIDTH": 6.123, "IMAGE_WIDTH": 3648, "FOCAL_LENGTH": 4.6})
    assert res["GSD"] == pytest.approx(0.21455, abs=5e-5)


def test_which_algorithms_need_which_packages(qgis_app):
    from qgis.core import QgsApplication
    provider = QgsApplication.processingRegistry().providerById("geomatics")
    needs = {}
    for alg in provider.algorithms():
        if not hasattr(alg, "required_packages"):
            continue                                  # the shipped model
        fresh = alg.create()
        las = sorted(getattr(fresh, "_las_params", ()))
        needs[alg.name()] = (fresh.required_packages({n: "x.laz" for n in las}), las)
    assert needs["catalog"][0] == ["catalog"]
    for name in ("groundfilter", "lsqgroundfilter", "slopegroundfilter", "ptdgroundfilter",
                 "idwdtm", "tindtm", "krigingdtm", "dsm", "lidarqa", "buildings",
                 "lidartodtm", "groundfilteraccuracy"):
        assert needs[name][0] == ["lidar"] and needs[name][1], name
    for name in ("gsdcalculator", "gsdbatch", "rectifygcp", "gcpaccuracyreport",
                 "rectifybatch", "installdependencies"):
        assert needs[name] == ([], []), name


def test_installer_is_registered_with_help(qgis_app):
    alg = _alg("geomatics:installdependencies")
    assert alg.group() and alg.displayName() == \
        "Install the Python packages this toolbox needs"
    text = alg.shortHelpString()
    assert "WHEEL_FOLDER" in text and "pip" in text
    assert {o.name() for o in alg.outputDefinitions()} == {"FOLDER", "INSTALLED", "MISSING",
                                                          "COMMAND"}


def test_installer_through_processing_run_plans_nothing_when_all_present(
        qgis_processing, monkeypatch, tmp_path):
    """Offline mode, an empty wheel folder: the venv has every pin, so nothing is planned."""
    from geomatics_toolbox.algorithms import install_dependencies as mod
    target = tmp_path / "packages"
    monkeypatch.setattr(mod, "profile_packages_dir", lambda: str(target))
    wheels = tmp_path / "wheels"
    wheels.mkdir()
    res = qgis_processing.run("geomatics:installdependencies", {"WHEEL_FOLDER": str(wheels)})
    assert res["FOLDER"] == str(target) and target.is_dir()
    assert res["INSTALLED"] == "" and res["MISSING"] == ""
    assert "--dry-run" in res["COMMAND"] and f"--find-links {wheels}" in res["COMMAND"]
    assert list(target.iterdir()) == []


def test_installer_refuses_a_missing_wheel_folder(qgis_processing, monkeypatch, tmp_path):
    from geomatics_toolbox.algorithms import install_dependencies as mod
    monkeypatch.setattr(mod, "profile_packages_dir", lambda: str(tmp_path / "p"))
    with pytest.raises(QgsProcessingException):
        qgis_processing.run("geomatics:installdependencies",
                            {"WHEEL_FOLDER": str(tmp_path / "absent")})

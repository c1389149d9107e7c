"""Every algorithm that reads LAS/LAZ refuses a missing file, an empty cloud and a text
file named .laz with a QgsProcessingException that names the problem — and writes nothing."""
import laspy
import pytest

# algorithm id → (input parameter, output parameter, output extension, extra parameters)
LAS_ALGORITHMS = {
    "geomatics:lsqgroundfilter": ("INPUT", "OUTPUT", ".laz", {}),
    "geomatics:slopegroundfilter": ("INPUT", "OUTPUT", ".laz", {}),
    "geomatics:idwdtm": ("INPUT", "OUTPUT", ".tif", {"CRS": "EPSG:32632"}),
    "geomatics:krigingdtm": ("INPUT", "OUTPUT", ".tif", {"CRS": "EPSG:32632"}),
    "geomatics:dsm": ("INPUT", "OUTPUT", ".tif", {"CRS": "EPSG:32632"}),
}


@pytest.fixture(scope="module")
def bad_inputs(tmp_path_factory):
    d = tmp_path_factory.mktemp("badlas")
    empty = d / "empty.las"
    header = laspy.LasHeader(point_format=6, version="1.4")
    rec = laspy.ScaleAwarePointRecord.zeros(0, header=header)
    with laspy.open(str(empty), mode="w", header=header) as w:
        w.write_points(rec)
    text = d / "notes.laz"
    text.write_text("x,y,z\n1,2,3\n")
    import numpy as np

    from geomatics_toolbox.core.io.las import write_las
    rng = np.random.default_rng(3)
    whole = d / "whole.las"
    write_las(whole, 500_000 + rng.uniform(0, 50, 3000), 4e6 + rng.uniform(0, 50, 3000),
              100 + rng.uniform(0, 1, 3000), crs="EPSG:32632",
              dimensions={"classification": np.full(3000, 2, np.uint8)})
    cut = d / "cut.las"
    cut.write_bytes(whole.read_bytes()[:60_000])
    (d / "cp.csv").write_text("id,x,y,z\n1,500010,4000010,100.5\n2,500020,4000030,100.4\n"
                              "3,500040,4000020,100.6\n", encoding="utf-8")
    return {"missing": (d / "nope.laz", "not found"),
            "empty": (empty, "no points"),
            "text": (text, "not a LAS/LAZ file"),
            "truncated": (cut, "is truncated")}


@pytest.mark.parametrize("kind", ["missing", "empty", "text", "truncated"])
@pytest.mark.parametrize("alg", sorted(LAS_ALGORITHMS))
def test_bad_las_input(qgis_processing, bad_inputs, tmp_path, alg, kind):
    from qgis.core import QgsProcessingException
    in_name, out_name, ext, extra = LAS_ALGORITHMS[alg]
    path, message = bad_inputs[kind]
    out = tmp_path / f"out{ext}"
    with pytest.raises(QgsProcessingException) as err:
        qgis_processing.run(alg, {in_name: str(path), out_name: str(out), **extra})
    text = str(err.value)
    assert message in text and str(path.name) in text, text
    assert not out.exists()
    assert [p.name for p in tmp_path.iterdir()] == []


#: every other algorithm that reads a LAS/LAZ file (issue 22: every algorithm refuses
#: bad input), with the mandatory parameters that are not the cloud
OTHER_LAS_ALGORITHMS = {
    "geomatics:groundfilter": {}, "geomatics:ptdgroundfilter": {},
    "geomatics:slopethresholdsweep": {}, "geomatics:groundfilteraccuracy": {"REFERENCE":
                                                                           "whole.las"},
    "geomatics:tindtm": {"CRS": "EPSG:32632"}, "geomatics:lidarqa": {},
    "geomatics:lidartodtm": {"CRS": "EPSG:32632", "CHECKPOINTS_CSV": "cp.csv"},
    "geomatics:buildings": {},
    "geomatics:classify": {},
}


@pytest.mark.parametrize("kind", ["missing", "empty", "text", "truncated"])
@pytest.mark.parametrize("alg", sorted(OTHER_LAS_ALGORITHMS))
def test_bad_las_input_every_other_algorithm(qgis_processing, bad_inputs, tmp_path, alg,
                                             kind):
    """Every destination of the algorithm is given a path: none may exist afterwards, no
    temporary name is left, and the input is byte-identical."""
    import hashlib

    from qgis.core import QgsApplication, QgsProcessingException
    path, message = bad_inputs[kind]
    digest = hashlib.sha256(path.read_bytes()).hexdigest() if path.exists() else None
    folder = bad_inputs["text"][0].parent                   # the good files beside them
    params = {"INPUT": str(path), **{k: str(folder / v) if v.endswith((".las", ".csv")) else v
                                     for k, v in OTHER_LAS_ALGORITHMS[alg].items()}}
    for p in QgsApplication.processingRegistry().algorithmById(alg).parameterDefinitions():
        if p.isDestination():
            params[p.name()] = str(tmp_path / f"{p.name()}.{p.defaultFileExtension()}")
    with pytest.raises(QgsProcessingException) as err:
        qgis_processing.run(alg, params)
    text = str(err.value)
    assert message in text and str(path.name) in text, text
    assert "Traceback" not in text and "Error:" not in text.split(str(path.name))[0], text
    assert [p.name for p in tmp_path.iterdir()] == []
    if digest:
        assert hashlib.sha256(path.read_bytes()).hexdigest() == digest


def test_core_las_reader_names_the_same_problems(bad_inputs):
    from geomatics_toolbox.core.io.las import read_las
    for path, message in bad_inputs.values():
        with pytest.raises(ValueError, match=message):
            read_las(path)

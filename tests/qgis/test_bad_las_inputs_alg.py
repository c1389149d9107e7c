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
    return {"missing": (d / "nope.laz", "not found"),
            "empty": (empty, "no points"),
            "text": (text, "not a LAS/LAZ file")}


@pytest.mark.parametrize("kind", ["missing", "empty", "text"])
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


def test_core_las_reader_names_the_same_problems(bad_inputs):
    from geomatics_toolbox.core.io.las import read_las
    for path, message in bad_inputs.values():
        with pytest.raises(ValueError, match=message):
            read_las(path)

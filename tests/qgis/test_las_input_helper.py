"""The base-class LiDAR input helper: a point-cloud layer where PDAL exists, else a file."""
import pytest


def _alg(qgis_app):
    from geomatics_toolbox.algorithms.base import GeomaticsAlgorithm

    class Probe(GeomaticsAlgorithm):
        def name(self):
            return "probe"

        def initAlgorithm(self, config=None):  # noqa: N802
            self.add_las_input()
            self.add_las_input("REFERENCE", "Reference", optional=True)

    alg = Probe()
    alg.initAlgorithm()
    return alg


def test_parameter_kind_matches_the_build(qgis_app):
    from qgis.core import QgsProcessingParameterFile, QgsProviderRegistry

    from geomatics_toolbox.algorithms.base import point_cloud_layers_supported
    alg = _alg(qgis_app)
    has_pdal = "pdal" in QgsProviderRegistry.instance().providerList()
    assert point_cloud_layers_supported() is has_pdal
    param = alg.parameterDefinition("INPUT")
    if has_pdal:
        assert param.type() == "pointcloud"
        assert "point-cloud layer" in param.help()
    else:
        assert isinstance(param, QgsProcessingParameterFile)
        assert "no PDAL point-cloud provider" in param.help()
        assert "*.laz" in param.fileFilter()
    assert alg.parameterDefinition("REFERENCE").flags() & param.FlagOptional


def test_path_comes_back_from_a_path(qgis_app, tmp_path):
    from qgis.core import QgsProcessingContext
    alg = _alg(qgis_app)
    las = tmp_path / "cloud.las"
    las.write_bytes(b"LASF")
    ctx = QgsProcessingContext()
    if alg.parameterDefinition("INPUT").type() == "file":
        assert alg.las_input_path({"INPUT": str(las)}, ctx) == str(las)
    assert alg.las_input_path({}, ctx, "REFERENCE") == ""


@pytest.mark.parametrize("has_pdal", [False])
def test_no_layer_loaded_without_pdal(qgis_app, has_pdal, tmp_path):
    from qgis.core import QgsProcessingContext

    from geomatics_toolbox.algorithms.base import point_cloud_layers_supported
    if point_cloud_layers_supported() is not has_pdal:
        pytest.skip("this QGIS build has a PDAL provider")
    ctx = QgsProcessingContext()
    alg = _alg(qgis_app)
    assert alg.load_cloud_on_completion(ctx, str(tmp_path / "c.laz"), "Classified") is False
    assert not ctx.layersToLoadOnCompletion()

"""Every LiDAR algorithm declares its clouds through add_las_input (issue 11.2).

``qgis_process help`` lists each LAS input; on a build without a PDAL point-cloud
provider (Debian's 3.22) the input is a file whose help says why no point-cloud layer
can be picked. Paths keep working under ``qgis_process`` (the other CLI tests run them).
"""
from __future__ import annotations

import pytest

#: algorithm -> its LAS/LAZ inputs (catalog takes a list of files and folders)
LAS_INPUTS = {
    "lsqgroundfilter": ["INPUT"],
    "slopegroundfilter": ["INPUT"],
    "slopethresholdsweep": ["INPUT", "REFERENCE"],
    "groundfilteraccuracy": ["INPUT", "REFERENCE"],
    "idwdtm": ["INPUT"],
    "krigingdtm": ["INPUT"],
    "dsm": ["INPUT"],
    "lidartodtm": ["INPUT"],
}
#: algorithms still landing on other branches: checked when registered
LATER = {"groundfilter": ["INPUT"], "ptdgroundfilter": ["INPUT"], "tindtm": ["INPUT"],
         "lidarqa": ["INPUT"], "buildings": ["INPUT"]}


def test_every_las_input_uses_the_helper(qgis_app):
    from qgis.core import QgsApplication, QgsProcessingParameterFile

    from geomatics_toolbox.algorithms.base import LAS_IN_FILTER, point_cloud_layers_supported
    provider = QgsApplication.processingRegistry().providerById("geomatics")
    algs = {a.name(): a for a in provider.algorithms()}
    checked = {**LAS_INPUTS, **{k: v for k, v in LATER.items() if k in algs}}
    assert set(LAS_INPUTS) <= set(algs)
    for name, inputs in checked.items():
        for pname in inputs:
            p = algs[name].parameterDefinition(pname)
            assert p is not None, (name, pname)
            if point_cloud_layers_supported():
                assert p.type() == "pointcloud", (name, pname)
            else:
                assert isinstance(p, QgsProcessingParameterFile), (name, pname)
                assert p.fileFilter() == LAS_IN_FILTER, (name, pname)
                assert "no PDAL point-cloud provider" in p.help(), (name, pname)


@pytest.mark.parametrize("alg", ["lsqgroundfilter", "groundfilteraccuracy", "idwdtm",
                                 "lidartodtm"])
def test_qgis_process_help_lists_the_las_input(qgis_process, alg):
    out = qgis_process.call("help", f"geomatics:{alg}")
    assert out.returncode == 0, out.stderr
    text = out.stdout
    for pname in LAS_INPUTS[alg]:
        block = text[text.index(f"\n{pname}: "):]
        block = block[:block.index("Acceptable values")]
        if "Argument type:\tpointcloud" in block or "point cloud layer" in block.lower():
            continue              # a build with PDAL: a loaded layer or a path
        assert "Argument type:\tfile" in block, block
        assert "no PDAL point-cloud provider" in block, block

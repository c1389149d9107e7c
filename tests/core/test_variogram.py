"""core/terrain/variogram.py equals PyKrige (the test oracle; kriging no longer needs it)."""
from __future__ import annotations

import numpy as np
import pytest

from geomatics_toolbox.core.terrain import variogram as vg

pk_core = pytest.importorskip("pykrige.core")
pk_models = pytest.importorskip("pykrige.variogram_models")

PARAMS = {"linear": [0.3, 0.2], "power": [0.5, 1.4, 0.1], "gaussian": [2.0, 35.0, 0.2],
          "spherical": [2.0, 35.0, 0.2], "exponential": [2.0, 35.0, 0.2]}


@pytest.mark.parametrize("model", sorted(PARAMS))
def test_model_functions_equal_pykrige(model):
    d = np.linspace(0.0, 80.0, 321)
    ref = getattr(pk_models, f"{model}_variogram_model")(PARAMS[model], d)
    assert np.array_equal(vg.MODEL_FUNCTIONS[model](PARAMS[model], d), ref)


def _cloud(n=600, seed=3):
    rng = np.random.default_rng(seed)
    xy = rng.uniform(0, 200, (n, 2))
    z = np.sin(xy[:, 0] / 30.0) * 5 + 0.02 * xy[:, 1] + rng.normal(0, 0.3, n)
    return xy, z


@pytest.mark.parametrize("model", sorted(PARAMS))
@pytest.mark.parametrize("weight", [False, True])
def test_all_pairs_fit_equals_pykrige(model, weight):
    xy, z = _cloud()
    func = vg.MODEL_FUNCTIONS[model]
    lags, semi = vg.all_pairs_semivariogram(xy, z, 12)
    params = vg.fit_model(lags, semi, model, func, weight)
    rl, rs, rp = pk_core._initialize_variogram_model(
        xy, z, model, None, getattr(pk_models, f"{model}_variogram_model"), 12, weight,
        "euclidean")
    assert np.array_equal(lags, rl) and np.array_equal(semi, rs)
    assert np.allclose(params, rp, rtol=1e-9, atol=1e-12)


def test_kriging_imports_no_pykrige():
    import subprocess
    import sys
    code = ("import sys; sys.modules['pykrige'] = None\n"
            "from geomatics_toolbox.core.terrain import kriging\n"
            "import numpy as np\n"
            "rng = np.random.default_rng(0); x, y = rng.uniform(0, 50, (2, 300))\n"
            "v = kriging.fit_variogram(x, y, np.sin(x / 9) + y / 40, model='spherical')\n"
            "print(v.fitted, len(v.params))")
    out = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True,
                         timeout=300)
    assert out.returncode == 0, out.stderr
    assert out.stdout.split() == ["True", "3"]

"""The numba kernels give the same numbers as pure Python (NUMBA_DISABLE_JIT=1)."""

import json
import os
import subprocess
import sys

import numpy as np
import pytest

SCRIPT = r"""
import json, numpy as np
from floatmoor.metocean import (WaveSpec, WindSpec, CurrentSpec, realise_waves, realise_wind,
                                current_speed)
r = realise_waves(WaveSpec(hs=4.0, tp=9.0), duration=300.0, seed=4, water_depth=60.0,
                  n_frequencies=40)
pts = np.array([[0.0, 0.0, -3.0], [5.0, 2.0, -30.0], [1.0, 1.0, 1.5]])
k = r.kinematics([0.0, 3.3], pts)
w = realise_wind(WindSpec(u10=20.0), duration=300.0, seed=4, n_frequencies=50)
out = {"eta": r.elevation_series(300, 0.5, x=3.0).tolist(),
       "direct": r.elevation(np.arange(5) * 0.7, 1.0, 2.0).tolist(),
       "vel": k["velocity"].tolist(), "acc": k["acceleration"].tolist(),
       "p": k["pressure"].tolist(), "wind": w.speed_series(100, 1.0).tolist(),
       "cur": current_speed(CurrentSpec(z=(0.0, -40.0), speed=(1.0, 0.3)),
                            np.linspace(-60, 2, 9), 60.0).tolist(),
       "pow": current_speed(CurrentSpec(profile="power_law", speed=(1.0,)),
                            np.linspace(-60, 2, 9), 60.0).tolist()}
print(json.dumps(out))
"""


def _run(disable_jit: bool) -> dict:
    env = dict(os.environ)
    env["NUMBA_DISABLE_JIT"] = "1" if disable_jit else "0"
    res = subprocess.run([sys.executable, "-c", SCRIPT], env=env, capture_output=True, text=True,
                         timeout=300, check=True)
    return json.loads(res.stdout)


@pytest.mark.slow  # reason: two fresh interpreters (~10 s); run with `pytest -m slow`
def test_kernels_without_jit_match_jit():
    pure, jit = _run(True), _run(False)
    for key in jit:
        np.testing.assert_allclose(np.array(pure[key]), np.array(jit[key]), rtol=1e-12,
                                   atol=1e-12, err_msg=key)

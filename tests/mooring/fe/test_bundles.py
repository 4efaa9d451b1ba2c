"""Kernel bundles (floatmoor.mooring.fe.bundles) and the FELine trial / accept protocol: the
bundles hold the line's own arrays, the kernels run on bundles built outside FELine, advance is
repeatable from the accepted state, and the multi-line path also runs as plain Python."""

import os
import subprocess
import sys

import numpy as np
import pytest

from floatmoor.mooring.fe import FELine
from floatmoor.mooring.fe import kernels as K
from floatmoor.mooring.fe.bundles import LineParams, LineState, new_state, new_work

from .conftest import oc3_spec

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.dirname(__file__))))


def _line(n=12):
    line = FELine(oc3_spec(n=n))
    line.solve_static()
    line.start()
    return line


def test_bundle_arrays_are_the_lines_own():
    line = _line()
    b = line.bundle
    assert b.now.r is line.r and b.now.v is line.v and b.now.f is line.fn
    assert b.now.fs is line.fs and b.par.P is line.P and b.par.E is line.E_dynamic
    assert isinstance(b.par, LineParams) and isinstance(b.trial, LineState)
    with pytest.raises(RuntimeError):
        _ = FELine(oc3_spec(n=4)).bundle  # not started


def test_trial_accept_reject_protocol():
    line = _line()
    r_acc = line.r.copy()
    rf = line.r[-1] + np.array([-0.5, 0.0, 0.1])
    vf = np.array([-0.5, 0.0, 0.1])
    F1 = line.advance(0.1, 0.1, rf, vf)
    assert line.has_trial and line.trial_time == 0.1 and line.time == 0.0
    np.testing.assert_array_equal(line.r, r_acc)           # accepted state untouched
    line.advance(0.1, 0.1, rf + 1.0, vf)                     # another trial ...
    F2 = line.advance(0.1, 0.1, rf, vf)                      # ... and the first again
    np.testing.assert_array_equal(F1, F2)                    # repeatable from the accepted state
    line.reject()
    assert not line.has_trial and line.trial_time == 0.0
    with pytest.raises(RuntimeError):
        line.accept()
    line.advance(0.1, 0.1, rf, vf)
    trial_r = line.bundle.trial.r.copy()
    line.accept()
    assert line.time == 0.1 and not line.has_trial
    np.testing.assert_array_equal(line.r, trial_r)
    np.testing.assert_array_equal(line.r[-1], rf)


def test_kernel_on_bundles_built_outside_the_line_equals_advance():
    """ga_advance called directly on fresh bundles (copies of the line's accepted state) gives
    bit for bit the trial state of FELine.advance."""
    line = _line()
    n = line.n_nodes
    now = LineState(line.r.copy(), line.v.copy(), line.a.copy(), line.fn.copy(),
                    line.fs.copy())
    trial, step, w = new_state(n, K.N_FS), new_state(n, K.N_FS), new_work(n)
    rf = line.r[-1] + np.array([-1.0, 0.2, 0.3])
    vf = np.array([-2.0, 0.4, 0.6])
    st = K.ga_advance(0.2, 0.2, 2, 5, rf, vf, now, trial, step, line.params(), w)
    line.advance(0.2, 0.2, rf, vf, substeps=2)
    assert st == 0 and w.stats[0] == line.newton_iterations > 0
    for a, b in zip(trial, line.bundle.trial):
        np.testing.assert_array_equal(a, b)
    np.testing.assert_array_equal(w.tens, line.tensions)


_NOJIT_MULTI = """
import numpy as np
from tests.mooring.fe.test_multi import _motion, _system
from floatmoor.mooring.fe.body import FEMooring
from floatmoor.mooring.fe.from_system import specs_from_system
ms = _system()
fm = FEMooring(specs_from_system(ms, element_length=60.0), ms.fairleads, fast=True)
fm.solve_static(np.zeros(6))
fm.start()
assert fm._packed is not None
for k in range(1, 4):
    pose, vel = _motion(k * 0.2)
    Q = fm.advance(k * 0.2, 0.2, pose, vel)
    fm.accept()
print(" ".join(repr(float(x)) for x in Q))
"""


def test_multi_line_kernels_run_without_jit():
    """body_advance / body_accept on the typed list of line bundles also run as plain Python
    (NUMBA_DISABLE_JIT=1) and give the numbers of the compiled kernels."""
    vals = []
    for flag in ("1", "0"):
        env = dict(os.environ, NUMBA_DISABLE_JIT=flag)
        out = subprocess.run([sys.executable, "-c", _NOJIT_MULTI], env=env, cwd=ROOT,
                             capture_output=True, text=True, check=True)
        vals.append([float(x) for x in out.stdout.strip().splitlines()[-1].split()])
    assert np.allclose(vals[0], vals[1], rtol=1e-9, atol=1e-9 * np.abs(vals[1]).max())

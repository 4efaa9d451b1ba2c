"""Predictor-corrector catenary solves (scene ``solver: {catenary: predictor}``) against the exact
Newton solve of the same line (:func:`floatmoor.mooring.catenary.line_kernel`, itself checked
against closed forms and MoorPy in test_catenary.py / test_multisegment.py).

The bounds follow from the method (floatmoor.mooring.catenary_step): after the predictor and
one Newton correction the error is of the order of the square of the correction (below
STEP_TOL = 1e-4 relative, so <~1e-8 relative); the anchor tension with seabed friction keeps
the predictor's error (below (1 + cb) STEP_TOL).
"""

import math
import os
import subprocess
import sys

import numpy as np
import pytest

from floatmoor.mooring.catenary import (
    OUT_HA,
    OUT_HF,
    OUT_ITER,
    OUT_LB,
    OUT_SIZE,
    OUT_VA,
    OUT_VF,
    line_kernel,
)
from floatmoor.mooring.catenary_step import STEP_TOL, WARM_SIZE, line_step_kernel

# chain - polyester - chain in the style of Wang (2016) table 5.2 (as test_multisegment.py)
CPC = (np.array([1200.0, 1200.0, 250.0]), np.array([332.7e6, 172.8e6, 332.7e6]),
       np.array([1350.0, 60.0, 1350.0]), np.zeros(3))
CHAIN = (np.array([900.0]), np.array([384.243e6]), np.array([698.09]), np.zeros(1))


def exact(xf, zf, line, cb):
    out = np.zeros(OUT_SIZE)
    st = line_kernel(xf, zf, *line, 0, line[0].size, cb, True, 0.0, 0.0, np.zeros(64), out)
    assert st == 0
    return out


def path(x0, z0, amp, n, step):
    """A smooth fairlead path (surge-heave ellipse, slow drift) with ``step`` m per call."""
    s = np.arange(n) * step
    return x0 + amp * np.sin(s / amp) + 0.2 * s, z0 + 0.3 * amp * np.sin(0.7 * s / amp)


@pytest.mark.parametrize("line, x0, z0, cb", [(CPC, 2600.0, 141.3, 0.0),
                                             (CPC, 2640.0, 141.3, 0.0),
                                             (CHAIN, 820.0, 250.0, 0.0),
                                             (CHAIN, 800.0, 250.0, 0.6)])
def test_follows_the_exact_solution_along_a_path(line, x0, z0, cb):
    """400 calls along a 10 cm-per-call path (a storm's RK4 stage moves a fairlead by a few
    cm): fairlead forces within 1e-8 of the exact solve, anchor forces within 1e-8 (without
    friction) or (1 + cb) STEP_TOL (with), and almost every call is the one-evaluation step."""
    warm = np.zeros((1, WARM_SIZE))
    out = np.zeros(OUT_SIZE)
    xs, zs = path(x0, z0, 8.0, 400, 0.1)
    steps = 0
    for xf, zf in zip(xs, zs):
        assert line_step_kernel(xf, zf, *line, 0, line[0].size, cb, True, warm, 0, STEP_TOL,
                                np.zeros(64), out) == 0
        ref = exact(xf, zf, line, cb)
        t = math.hypot(ref[OUT_HF], ref[OUT_VF])
        assert abs(out[OUT_HF] - ref[OUT_HF]) <= 1e-8 * t
        assert abs(out[OUT_VF] - ref[OUT_VF]) <= 1e-8 * t
        anchor_tol = 1e-8 if cb == 0.0 else (1.0 + cb) * STEP_TOL
        assert abs(out[OUT_HA] - ref[OUT_HA]) <= anchor_tol * t
        assert abs(out[OUT_VA] - ref[OUT_VA]) <= anchor_tol * t
        assert out[OUT_LB] == pytest.approx(ref[OUT_LB], rel=1e-4, abs=1e-3)
        steps += out[OUT_ITER] == 0.0
    assert steps >= 390


def test_a_jump_falls_back_to_the_exact_solve():
    """A 30 m jump of the fairlead: the correction exceeds the tolerance, the exact Newton
    solve takes over (its iterations reported) and gives the exact result."""
    warm = np.zeros((1, WARM_SIZE))
    out = np.zeros(OUT_SIZE)
    for xf in (2500.0, 2530.0):
        assert line_step_kernel(xf, 141.3, *CPC, 0, 3, 0.0, True, warm, 0, STEP_TOL,
                                np.zeros(64), out) == 0
        assert out[OUT_ITER] > 0  # first call: cold; second: the jump
        ref = exact(xf, 141.3, CPC, 0.0)
        assert out[OUT_HF] == pytest.approx(ref[OUT_HF], rel=1e-9)
        assert out[OUT_VF] == pytest.approx(ref[OUT_VF], rel=1e-9)


def test_slack_to_taut_is_crossed():
    """From horizontally slack (H = 0, the exact solve's branch) to 33 kN of horizontal
    tension: within 1e-7 of the tension throughout (near slack the line's curvature is
    largest, H itself a few N)."""
    warm = np.zeros((1, WARM_SIZE))
    out = np.zeros(OUT_SIZE)
    for xf in np.linspace(2490.0, 2550.0, 601):
        assert line_step_kernel(xf, 141.3, *CPC, 0, 3, 0.0, True, warm, 0, STEP_TOL,
                                np.zeros(64), out) == 0
        ref = exact(xf, 141.3, CPC, 0.0)
        t = math.hypot(ref[OUT_HF], ref[OUT_VF])
        assert abs(out[OUT_HF] - ref[OUT_HF]) <= 1e-7 * t
        assert abs(out[OUT_VF] - ref[OUT_VF]) <= 1e-7 * t
    assert ref[OUT_HF] > 3e4


def test_lift_off_of_the_whole_line_is_crossed():
    """A chain pulled from a long grounded part to lifted off its anchor (the touchdown point
    reaches the anchor): every call within 1e-8 of the exact solve."""
    warm = np.zeros((1, WARM_SIZE))
    out = np.zeros(OUT_SIZE)
    for xf in np.linspace(760.0, 860.0, 1001):  # 10 cm a call; lifted off above 850 m
        assert line_step_kernel(xf, 250.0, *CHAIN, 0, 1, 0.0, True, warm, 0, STEP_TOL,
                                np.zeros(64), out) == 0
        ref = exact(xf, 250.0, CHAIN, 0.0)
        t = math.hypot(ref[OUT_HF], ref[OUT_VF])
        assert abs(out[OUT_HF] - ref[OUT_HF]) <= 1e-8 * t
        assert abs(out[OUT_VA] - ref[OUT_VA]) <= 1e-8 * t
    assert ref[OUT_VA] > 0.0  # really lifted off at the end


def test_runs_without_jit():
    """The same numbers as plain Python (NUMBA_DISABLE_JIT=1)."""
    code = ("import numpy as np; from floatmoor.mooring.catenary_step import line_step_kernel;"
            "L=(np.array([1200.,1200.,250.]),np.array([332.7e6,172.8e6,332.7e6]),"
            "np.array([1350.,60.,1350.]),np.zeros(3)); w=np.zeros((1,8)); o=np.zeros(10)\n"
            "for x in (2500., 2500.1, 2500.2): line_step_kernel(x,141.3,*L,0,3,0.,True,w,0,"
            "1e-4,np.zeros(64),o)\nprint(repr(float(o[0])), repr(float(o[1])))")
    outs = []
    for flag in ("1", "0"):
        env = dict(os.environ, NUMBA_DISABLE_JIT=flag)
        r = subprocess.run([sys.executable, "-c", code], env=env, capture_output=True,
                           text=True, check=True)
        outs.append([float(v) for v in r.stdout.split()])
    np.testing.assert_allclose(outs[0], outs[1], rtol=1e-14)

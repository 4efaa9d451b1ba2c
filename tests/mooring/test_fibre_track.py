"""Fibre ropes in the quasi-static time domain: the linearisation about the slowly varying
tension (:func:`floatmoor.mooring.fibre_system.fibre_track_update`).

The line model of the time loop is driven through prescribed fairlead motions exactly as
:func:`floatmoor.solvers.td_kernel.td_steps` does (the catenary solve at the step's pose, the
record, then the update of the slowly varying tensions and of the linearised segments).  The
expected numbers are independent of the update: the working-curve statics of
:class:`floatmoor.mooring.MooringSystem` (the secant iteration, verified against the direct
integration of the extensible catenary in ``test_fibre_system.py``) for slow motions, and the
constant-EA linearisation about the mean position (:meth:`MooringSystem.linearised_fibre`,
the dynamic stiffness ``EA_dyn(T_mean)``, DNV (2008) / Falkenberg et al. (2017)) for fast ones.
"""

from __future__ import annotations

import math
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from floatmoor.core.config import Node
from floatmoor.io.mooring_section import parse_mooring
from floatmoor.mooring.catenary import OUT_HF, OUT_SIZE, OUT_VF
from floatmoor.mooring.fibre_system import DEFAULT_TIME_CONSTANT, fibre_track, fibre_track_update
from floatmoor.mooring.system import system_force_kernel

ROOT = Path(__file__).resolve().parents[2]
TAU = 300.0
X_MEAN = 2.0  # m surge offset: the up-wave lines from 16 % to 22 % MBS, the others to 10 %


def taut_system(**extra):
    """Four taut all-polyester lines (185 mm rope, ``polyester_default``), 300 m out and down
    to the seabed at 150 m (the taut system of ``tests/solvers/test_fibre_dynamics.py``)."""
    lines = []
    for k, (sx, sy) in enumerate(((1, 1), (-1, 1), (-1, -1), (1, -1))):
        fx, fy = 31.5 * sx, 31.75 * sy
        az = math.atan2(fy, fx)
        lines.append({"name": f"line{k + 1}",
                      "anchor": {"x": fx + 300 * math.cos(az), "y": fy + 300 * math.sin(az)},
                      "fairlead": [fx, fy, -8.7]})
    data = {"line_types": {"poly": {
        "material": "polyester", "diameter": 0.185, "mass_per_length": 22.59,
        "density": 1380.0, "elastic_modulus": 6.43e9, "mbs": 8.5e6, "cdn": 1.8, "cdt": 0.18,
        "fibre": "polyester_default"}},
        "defaults": {"segments": [{"type": "poly", "length": 327.5}]}, "lines": lines, **extra}
    return parse_mooring(Node(data, file="mooring.yaml"), water_depth=150.0)


def surge(x):
    p = np.zeros(6)
    p[0] = x
    return p


def drive(system, poses, dt, tau, pose0):
    """Fairlead tensions (n_poses, n_lines) of the time loop's lines over the prescribed poses
    (one per step of ``dt``), linearised about ``pose0`` at the start."""
    lin = system.linearised_fibre(pose0)  # evaluates the system at pose0 (the start tensions)
    fib = fibre_track(system, tau, dt)
    cat = lin.catenary_arrays()
    active = lin.active.copy()
    warm = lin.warm.copy()
    n = lin.n_lines
    work, rot = np.zeros(64), np.zeros((3, 3))
    line_out, force, stiff = np.zeros((n, OUT_SIZE)), np.zeros(6), np.zeros((6, 6))
    out = np.zeros((len(poses), n))
    for k, p in enumerate(poses):
        bad = system_force_kernel(p, *cat, active, warm, False, work, rot, line_out, force,
                                  stiff)
        assert bad < 0
        out[k] = np.hypot(line_out[:, OUT_HF], line_out[:, OUT_VF])
        if fib.on:
            fibre_track_update(fib, cat, active, line_out)
    return out


def slow_then_fast(system, tau, dt=0.5, ramp=20 * TAU, hold=10 * TAU, period=10.0, amp=0.5,
                   n_periods=3):
    """Surge ramped (smooth step) from 0 to X_MEAN over ``ramp`` s, held for ``hold`` s, then
    ``n_periods`` of a harmonic oscillation of ``amp`` m and ``period`` s about X_MEAN."""
    t1 = np.arange(0.0, ramp, dt) / ramp
    x = list(X_MEAN * t1 * t1 * (3.0 - 2.0 * t1))
    x += [X_MEAN] * int(round(hold / dt))
    n_hold_end = len(x)
    t = np.arange(int(round(n_periods * period / dt)) + 1) * dt
    x += list(X_MEAN + amp * np.sin(2 * np.pi * t / period))
    poses = [surge(v) for v in x]
    return drive(system, poses, dt, tau, surge(0.0)), n_hold_end, t


@pytest.fixture(scope="module")
def system():
    return taut_system()


@pytest.fixture(scope="module")
def runs(system):
    return {tau: slow_then_fast(system, tau) for tau in (TAU, math.inf)}


def test_default_time_constant_is_the_fe_one_and_the_scene_key(system):
    assert system.fibre_time_constant == DEFAULT_TIME_CONSTANT == 300.0
    assert taut_system(fibre_time_constant=120.0).fibre_time_constant == 120.0
    assert math.isinf(taut_system(fibre_time_constant=math.inf).fibre_time_constant)
    from floatmoor.core.errors import SceneError
    with pytest.raises(SceneError):
        taut_system(fibre_time_constant=0.0)


def test_slow_offset_follows_the_working_curve_statics(system, runs):
    """A slow ramp of the offset (20 tau) and a hold (10 tau): the tensions are those of the
    working-curve statics at the held offset (the lag left after the hold is below exp(-10)
    of the ramp's lag; tolerance 1e-5 relative).  The fixed-mean rule (tau = inf) stays on the
    dynamic line through the start tensions: more than 2 % off on the most loaded line."""
    t_ref = system.tensions(surge(X_MEAN))["fairlead_tension"].values
    tens, n_hold, _ = runs[TAU]
    np.testing.assert_allclose(tens[n_hold - 1], t_ref, rtol=1e-5)
    fixed, _, _ = runs[math.inf]
    i = int(np.argmax(t_ref))
    assert abs(fixed[n_hold - 1, i] / t_ref[i] - 1.0) > 0.02
    # the start is the working curve's; the up-wave line gains > 20 %
    t0 = system.tensions(surge(0.0))["fairlead_tension"].values
    np.testing.assert_allclose(tens[0], t0, rtol=1e-9)
    assert t_ref[i] > 1.2 * t0[i]


def test_fast_oscillation_sees_the_dynamic_stiffness_about_the_slow_tension(system, runs):
    """After the slow ramp and hold, a 10 s harmonic surge of 0.5 m (3 periods, << tau): the
    crest-to-trough tension range is that of the lines linearised with EA_dyn(T_mean) at the
    held offset (:meth:`MooringSystem.linearised_fibre` there) within 0.5 %.  (The slowly
    varying tension creeps by about (t / tau) (EA_dyn / k_w - 1) of the tension amplitude
    over a time t; with T_s integrating a sine that creep is the same at a crest and the next
    trough, so it cancels in the range.)  The working curve's tangent (the lower bound) and
    the fixed-mean rule (linearised at the zero offset) are each more than 3 % off on the
    most loaded line."""
    tens, n_hold, t = runs[TAU]
    fast = tens[n_hold:]
    fixed = runs[math.inf][0][n_hold:]
    lin = system.linearised_fibre(surge(X_MEAN))
    tangent = system.linearised_fibre(surge(X_MEAN), "tangent")

    def at(s, k):
        x = X_MEAN + 0.5 * math.sin(2 * math.pi * t[k] / 10.0)
        return s.tensions(surge(x))["fairlead_tension"].values

    i = int(np.argmax(at(lin, 0)))
    for kc, kt in ((5, 15), (25, 35), (45, 55)):  # crest and trough (t = 2.5, 7.5 s, ...)
        d_ref = at(lin, kc) - at(lin, kt)
        np.testing.assert_allclose(fast[kc] - fast[kt], d_ref, rtol=5e-3)
        d_tan = at(tangent, kc)[i] - at(tangent, kt)[i]
        assert abs(d_tan / d_ref[i] - 1.0) > 0.03
        assert abs((fixed[kc, i] - fixed[kt, i]) / d_ref[i] - 1.0) > 0.03


_SCRIPT = """
import math, sys
import numpy as np
sys.path.insert(0, {root!r})
from tests.mooring.test_fibre_track import slow_then_fast, taut_system
tens, n_hold, _ = slow_then_fast(taut_system(), 50.0, dt=1.0, ramp=200.0, hold=100.0,
                                 n_periods=1)
np.save({out!r}, tens)
"""


def test_same_numbers_without_jit(tmp_path):
    """The update under ``NUMBA_DISABLE_JIT=1`` (a subprocess) gives the compiled numbers
    (a short run, tau = 50 s: relative 1e-12)."""
    out = tmp_path / "nojit.npy"
    env = dict(os.environ, NUMBA_DISABLE_JIT="1", PYTHONPATH=str(ROOT))
    subprocess.run([sys.executable, "-c", _SCRIPT.format(root=str(ROOT), out=str(out))],
                   check=True, env=env, cwd=str(ROOT), timeout=300)
    ref, _, _ = slow_then_fast(taut_system(), 50.0, dt=1.0, ramp=200.0, hold=100.0,
                               n_periods=1)
    np.testing.assert_allclose(np.load(out), ref, rtol=1e-12)

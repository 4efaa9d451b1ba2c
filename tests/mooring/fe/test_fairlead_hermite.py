"""Fairlead motion inside a sub-stepped advance (``kernels.ga_advance``): the cubic Hermite
curve through the fairlead's position and velocity at both ends of the advance.

Expected numbers, independent of the interpolation under test:

* a cubic Hermite curve reproduces a quadratic motion exactly (position and velocity), so an
  advance of ``4 dt`` in 4 sub-steps along a constant-acceleration fairlead motion must give the
  state of 4 advances of ``dt`` each handed the exact motion, to round-off of the Newton
  iteration (tolerance 1e-12 m here);
* for a smooth motion the curve is within ``|x''''| dt^4 / 384`` of the path, so on the OC3 line
  (surge 3 m at 15 s, coupling step 0.1 s: 2e-8 m) the sub-stepped run must agree with the run
  handed the exact motion at every line step far below the discretisation errors (bound 1e-4 of
  the tension range; the linear interpolation of position and velocity used before gave
  4e-3 of the range, benchmarks/RESULTS.md);
* a single step (one sub-step, no halving) hands the kernel the end values unchanged, so the
  default coupled path is unchanged (pinned by tests/test_bit_identity.py).
"""

import numpy as np

from floatmoor.mooring.fe import FELine
from floatmoor.mooring.fe.prescribed import HarmonicMotion, run_prescribed

from .conftest import oc3_spec


def _started(n, tol=1e-6):
    line = FELine(oc3_spec(n=n))
    line.solve_static()
    line.start(tol=tol)
    return line


def test_quadratic_fairlead_motion_is_followed_exactly_by_the_sub_steps():
    dt = 0.05
    acc = np.array([-0.6, 0.1, 0.4])        # m/s^2, constant
    vel0 = np.array([0.3, -0.05, 0.2])      # m/s at t = 0
    a = _started(12, tol=1e-12)
    b = _started(12, tol=1e-12)
    r0 = a.r[-1].copy()

    def pos(t):
        return r0 + vel0 * t + 0.5 * acc * t * t

    def vel(t):
        return vel0 + acc * t

    # both lines start at rest (fairlead velocity 0, not the motion's 0.3 m/s): bring them to
    # the same moving state with identical exact steps first
    for k in range(1, 5):
        t = k * dt
        a.step(t, dt, pos(t), vel(t))
        b.step(t, dt, pos(t), vel(t))
    for m in range(2):
        t0 = 4 * dt * (m + 1)
        a.step(t0 + 4 * dt, 4 * dt, pos(t0 + 4 * dt), vel(t0 + 4 * dt), substeps=4)
        for k in range(1, 5):
            t = t0 + k * dt
            b.step(t, dt, pos(t), vel(t))
    assert np.allclose(a.r, b.r, rtol=0.0, atol=1e-9)
    assert np.allclose(a.v, b.v, rtol=0.0, atol=1e-8)
    fa = np.linalg.norm(a.fn[-1])
    fb = np.linalg.norm(b.fn[-1])
    assert abs(fa - fb) < 1e-6 * fb


def test_sub_steps_follow_the_exact_smooth_motion():
    motion = HarmonicMotion(amplitude=(-3.0, 0.0, 0.0), period=15.0, ramp=15.0)
    nsub, dt = 4, 0.1
    a = _started(20)
    da = run_prescribed(a, motion, 30.0, dt, substeps=nsub)
    b = _started(20)
    db = run_prescribed(b, motion, 30.0, dt / nsub, record_every=nsub)
    Ta = da.fairlead_tension.values
    Tb = db.fairlead_tension.values
    assert Ta.shape == Tb.shape
    rng = np.ptp(Tb[150:])
    assert rng > 3e5                        # a real tension cycle (N)
    assert np.max(np.abs(Ta - Tb)) < 1e-4 * rng

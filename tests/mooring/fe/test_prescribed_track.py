"""A prescribed fairlead track evaluated in one go (``TimeSeriesMotion.track``, what
:func:`run_prescribed` takes) gives the numbers of one call per step: checked element by
element, and on a whole run against the per-step path (a motion without ``track``)."""

import numpy as np

from floatmoor.mooring.fe import FELine
from floatmoor.mooring.fe.prescribed import TimeSeriesMotion, run_prescribed

from .conftest import oc3_spec


def _series(seed=3, nt=400, dt=0.1):
    rng = np.random.default_rng(seed)
    t = np.arange(nt) * dt
    xyz = np.cumsum(rng.normal(0.0, 0.05, (nt, 3)), axis=0)
    return TimeSeriesMotion(t=t, xyz=xyz)


def test_track_equals_one_call_per_time_bit_for_bit():
    m = _series()
    rng = np.random.default_rng(7)
    # inside, on the samples, and outside the series (held at the ends)
    times = np.concatenate([rng.uniform(-5.0, 45.0, 500), m.t[::7], [m.t[-1], 1e3, -1e3]])
    pos, vel = m.track(times)
    for k, tk in enumerate(times):
        p, v = m(float(tk))
        assert np.array_equal(pos[k], p) and np.array_equal(vel[k], v), tk


class _PerStep:
    """The same motion without ``track``: run_prescribed calls it once per step."""

    def __init__(self, m):
        self.m = m

    def __call__(self, t):
        return self.m(t)


def test_run_with_the_track_is_the_run_step_by_step():
    m = _series()
    out = []
    for motion in (m, _PerStep(m)):
        line = FELine(oc3_spec(n=20))
        line.solve_static()
        line.start()
        out.append(run_prescribed(line, motion, 30.0, 0.1))
    a, b = out
    assert np.array_equal(a.fairlead_force.values, b.fairlead_force.values)
    assert np.array_equal(a.time.values, b.time.values)
    assert a.fairlead_tension.values.max() > 0.0

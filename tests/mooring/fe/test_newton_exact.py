"""The opt-in ``newton: fast`` generalised-alpha iteration against the exact one (the
default): the same discrete equation, solved from a predictor that takes the fairlead's
acceleration into account and stopped one iteration earlier when the quadratic-convergence
estimate of the next correction is below the tolerance.

Expected numbers: a state accepted by the fast iteration must be within the position tolerance
``tol`` (1e-6 m) of the state the exact iteration reaches at a tolerance far below it (1e-12 m,
i.e. converged to round-off), step by step from the same start (the definition of the
tolerance; independent of the iteration under test).  Over a run the OC3 line with its
touchdown is sensitive (``test_newton_modified``): the tension statistics must agree to 0.2 %
of the maximum, or to twice the exact iteration's own spread when its fairlead amplitude is
changed by 1e-9 (relative), whichever is larger, with at least 10 % fewer iterations."""

import numpy as np
import pytest

from floatmoor.core.config import Node
from floatmoor.mooring.fe import FELine
from floatmoor.mooring.fe import kernels as K
from floatmoor.mooring.fe.line import NEWTON_MODES
from floatmoor.mooring.fe.options import parse_fe_options
from floatmoor.mooring.fe.prescribed import HarmonicMotion, run_prescribed

from .conftest import oc3_spec


def _started(newton, n=30):
    line = FELine(oc3_spec(n=n))
    line.solve_static()
    line.start(newton=newton)
    return line


def test_accepted_state_within_tol_of_the_converged_step():
    tol = 1e-6
    line = _started("exact")
    motion = HarmonicMotion(amplitude=(-3.0, 0.0, 0.0), period=15.0, ramp=15.0)
    run_prescribed(line, motion, 20.0, 0.1)      # a moving line with touchdown
    b = line.bundle
    exact = b.par._replace(newton=K.NW_PREDICT | K.NW_QSTOP, tol=tol)
    ref = b.par._replace(newton=0, tol=1e-12)
    n = line.n_nodes
    r0 = line.r[-1].copy()
    worst = 0.0
    its = [0, 0]
    for dt in (0.1, 0.1, 0.05, 0.1, 0.2):
        t1 = line.time + dt
        disp, vel = motion(t1)
        rf = r0 + np.asarray(disp) - np.asarray(motion(line.time)[0])
        rf, vf = np.ascontiguousarray(rf), np.ascontiguousarray(vel, dtype=float)
        out = []
        for i, par in enumerate((exact, ref)):
            it = K.gen_alpha_step(t1, dt, rf, vf, b.now, b.step, par, b.work)
            assert it > 0
            its[i] += it
            out.append(b.step.r.copy())
        worst = max(worst, np.abs(out[0] - out[1])[1:n - 1].max())
    assert worst <= tol, worst
    assert its[0] < its[1]


@pytest.mark.parametrize("amplitude,period", [((-3.0, 0.0, 0.0), 15.0),   # surge
                                              ((-2.0, 0.0, 2.0), 9.0)])   # surge and heave
def test_default_iteration_matches_the_plain_one(amplitude, period):
    motion = HarmonicMotion(amplitude=amplitude, period=period, ramp=period)
    nudged = HarmonicMotion(amplitude=tuple(a * (1 + 1e-9) for a in amplitude), period=period,
                            ramp=period)
    out = {}
    for key, newton, m in (("exact", "exact", motion), ("fast", "fast", motion),
                           ("nudged", "exact", nudged)):
        line = _started(newton)
        T = run_prescribed(line, m, 60.0, 0.1).fairlead_tension.values
        T = T[len(T) // 2:]
        out[key] = (np.array([T.max(), T.min(), T.mean(), T.std()]), line.newton_iterations)
    (s0, it0), (s1, it1), (s2, _) = out["exact"], out["fast"], out["nudged"]
    bound = np.maximum(2e-3 * s0[0], 2.0 * np.abs(s2 - s0))
    assert np.all(np.abs(s1 - s0) < bound), (s1 - s0, bound)
    assert it1 < 0.9 * it0, (it1, it0)


def test_fast_option_is_read_from_a_scene():
    assert NEWTON_MODES == ("force", "exact", "modified", "fast")
    o = parse_fe_options(Node({"newton": "fast"}, "scene.yaml", "mooring.finite_element"))
    assert o.start_kw()["newton"] == "fast"
    line = _started("fast", n=5)
    assert line.bundle.par.newton == K.NW_PREDICT | K.NW_QSTOP

"""The default generalised-alpha iteration, ``newton: force``: stopped in force terms (the force
imbalance of the free nodes, summed, below ``TENSION_TOL`` of the line's weight in air, times
``1 - alpha_f``), the last iterate accepted with its forces, from the predictor with the
fairlead's trapezoidal prediction.

Expected numbers: step by step from the same start, every element tension of the accepted
state within the stop's own bound (``TENSION_TOL`` times the weight, the order of the step's
tension error by the force balance of the free nodes) of the state the exact iteration reaches
converged to round-off (position tolerance 1e-12 m): the definition of the tolerance,
independent of the iteration under test.  Over a run the OC3 line's tension statistics agree
with the exact iteration's (1 um stop) to 0.2 % of the maximum, or twice the exact iteration's
own spread when the fairlead amplitude is changed by 1e-9 (the test of ``newton: fast``), with
at least 15 % fewer force evaluations per step."""

import numpy as np
import pytest

from floatmoor.core.config import Node
from floatmoor.mooring.fe import FELine
from floatmoor.mooring.fe import kernels as K
from floatmoor.mooring.fe.options import parse_fe_options
from floatmoor.mooring.fe.prescribed import HarmonicMotion, run_prescribed

from .conftest import oc3_spec


def _started(newton="force", n=30, **kw):
    line = FELine(oc3_spec(n=n, **kw))
    line.solve_static()
    line.start(newton=newton)
    return line


def test_force_stop_is_opt_in():
    line = _started()
    assert line.bundle.par.newton == K.NW_TRAPEZ | K.NW_FORCE
    o = parse_fe_options(Node({}, "scene.yaml", "mooring.finite_element"))
    assert o.start_kw()["newton"] == "exact"
    o = parse_fe_options(Node({"newton": "force"}, "scene.yaml", "mooring.finite_element"))
    assert o.start_kw()["newton"] == "force"


@pytest.mark.parametrize("amplitude,period", [((-3.0, 0.0, 0.0), 15.0),   # touchdown moving
                                              ((6.0, 0.0, 0.0), 8.0)])    # slack and snap
def test_accepted_tensions_within_the_bound_of_the_converged_step(amplitude, period):
    line = _started()
    motion = HarmonicMotion(amplitude=amplitude, period=period, ramp=period)
    run_prescribed(line, motion, 2.0 * period, 0.1)
    b = line.bundle
    ref = b.par._replace(newton=0, tol=1e-12, maxit=100)
    n = line.n_nodes
    weight = 9.80665 * line.P[1:n - 1, K.NP_MASS].sum()
    bound = K.TENSION_TOL * weight
    r0 = line.r[-1].copy() - np.asarray(motion(line.time)[0])
    worst = 0.0
    evals = []
    t = line.time
    for dt in (0.1, 0.1, 0.05, 0.1, 0.2, 0.1, 0.1):
        t1 = t + dt
        disp, vel = motion(t1)
        rf = np.ascontiguousarray(r0 + np.asarray(disp))
        vf = np.ascontiguousarray(vel, dtype=float)
        tens = []
        for par in (b.par._replace(maxit=100), ref):
            it = K.gen_alpha_step(t1, dt, rf, vf, b.now, b.step, par, b.work)
            assert it > 0
            evals.append(it)
            tens.append(b.work.tens.copy())
        worst = max(worst, np.abs(tens[0] - tens[1]).max())
        # march on with the converged state (the next step from the same start for both)
        for a, s in zip(b.now[:4], b.step[:4]):
            a[:] = s
        t = t1
    assert worst <= bound, (worst, bound)
    assert sum(evals[0::2]) < sum(evals[1::2])


@pytest.mark.parametrize("amplitude,period", [((-3.0, 0.0, 0.0), 15.0),   # surge
                                              ((-2.0, 0.0, 2.0), 9.0)])   # surge and heave
def test_force_stop_matches_the_exact_iteration(amplitude, period):
    motion = HarmonicMotion(amplitude=amplitude, period=period, ramp=period)
    nudged = HarmonicMotion(amplitude=tuple(a * (1 + 1e-9) for a in amplitude), period=period,
                            ramp=period)
    out = {}
    for key, newton, m in (("exact", "exact", motion), ("force", "force", motion),
                           ("nudged", "exact", nudged)):
        line = _started(newton)
        ds = run_prescribed(line, m, 60.0, 0.1)
        T = ds.fairlead_tension.values
        T = T[len(T) // 2:]
        steps = ds.time.size - 1
        # force evaluations per step: the exact iteration evaluates its accepted state once
        # more (not counted in its iterations) unless it stopped on the residual; at most one
        evals = line.newton_iterations / steps + (1.0 if newton == "exact" else 0.0)
        out[key] = (np.array([T.max(), T.min(), T.mean(), T.std()]), evals)
    (s0, e0), (s1, e1), (s2, _) = out["exact"], out["force"], out["nudged"]
    bound = np.maximum(2e-3 * s0[0], 2.0 * np.abs(s2 - s0))
    assert np.all(np.abs(s1 - s0) < bound), (s1 - s0, bound)
    assert e1 < 0.85 * e0, (e1, e0)


def test_full_ea_line_converges_with_the_force_stop():
    """The OC3 line at EA = 3.84e14 N (stiff elements: tension estimates, round-off floor of
    the stop) completes a surge cycle at dt 0.2 s with the default iteration and gives the
    maximum tension of the exact iteration within 0.5 % (test_fe_extreme's tolerance)."""
    import warnings

    from floatmoor.core.errors import FloatmoorWarning
    motion = HarmonicMotion(amplitude=(-3.0, 0.0, 0.0), period=15.0, ramp=15.0)
    tmax = {}
    for newton in ("force", "exact"):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore", FloatmoorWarning)
            line = FELine(oc3_spec(n=50, ea=3.84e14))
        line.solve_static()
        line.start(newton=newton)
        T = run_prescribed(line, motion, 45.0, 0.2).fairlead_tension.values
        assert np.all(np.isfinite(T))
        tmax[newton] = T[T.size // 3:].max()
    assert tmax["force"] == pytest.approx(tmax["exact"], rel=5e-3)

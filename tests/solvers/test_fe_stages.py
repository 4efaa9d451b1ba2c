"""``solver: {fe_stages: linear}`` (the default since 2026-11-28): the coupled FE lines' stage
variation from the catenary stiffness at the step start instead of a catenary solve at every
RK4 stage (``fe_stages: catenary``).

The yardsticks are independent of the option: the derivative of the mooring force by central
differences of the catenary force, and the exact path's own time-step error (dt 0.1 s against
0.05 s), which the approximation must stay far below.
"""

import warnings

import numpy as np
import pytest

from floatmoor.analyses.simulate import simulate
from floatmoor.core.errors import SceneError
from floatmoor.io.build import build
from floatmoor.io.scene import load_scene
from floatmoor.io.solver_section import SolverSpec, fe_stages, parse_solver
from floatmoor.solvers.fe_coupling import pose_stiffness_into
from tests.solvers.test_time_domain_fe import ROOT, _built, _scene


def test_pose_stiffness_is_the_derivative_of_the_mooring_force():
    """``pose_stiffness_into`` turns the catenary stiffness -dQ/d[dt, theta] into dQ/dx for
    the pose [x, y, z, roll, pitch, yaw]: equal to central differences of the mooring force
    (12 lines of the Floatel-like mooring) at a displaced, heeled and yawed pose, where the
    Euler-angle columns differ from the small-rotation ones by 15 %."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        m = build(load_scene(ROOT / "scenes" / "floatel_100yr.yaml")).mooring
    x = np.array([12.0, 3.0, -0.5, 0.02, -0.03, 0.15])
    _, K = m.force_and_stiffness(x)
    D = np.zeros((6, 6))
    pose_stiffness_into(K, x, D)
    h = np.array([1e-3, 1e-3, 1e-3, 1e-5, 1e-5, 1e-5])
    J = np.zeros((6, 6))
    for k in range(6):
        d = np.zeros(6)
        d[k] = h[k]
        J[:, k] = (m.force(x + d) - m.force(x - d)) / (2.0 * h[k])
    scale = np.abs(J).max(axis=0)
    np.testing.assert_array_less(np.abs(D - J).max(axis=0), 1e-6 * scale)
    # the roll and pitch columns are not the small-rotation ones at this pose
    assert np.abs(-K[:, 3] - J[:, 3]).max() > 0.1 * scale[3]


@pytest.mark.parametrize("mixed", [False, True], ids=["all-fe", "two-fe-ten-qs"])
def test_linear_stages_far_inside_the_time_step_error(tmp_path, mixed):
    """240 s of irregular waves (Hs 10 m), dt 0.1 s: the fairlead tensions and the motion with
    ``fe_stages: linear`` (the default) and its stiffness solved at every step
    (``fe_stiffness_interval: 0``) differ from the catenary stages by less than 1 % of
    the catenary stages' own time-step error (dt 0.1 against 0.05 s), for all lines finite-element and for two FE lines
    among ten quasi-static ones (whose catenaries stay in the stages).  Measured: 1.3 N against
    951 N (all FE), 2.0 N against 1483 N (mixed), 2e-5 m against 1e-2 m of motion; the option
    does change the numbers (the two paths are not the same arithmetic).  The default keeps the
    stiffness for 1.0 s (``fe_stiffness_interval``): within 10 % of the time-step error of the
    every-step run (measured, all FE: 17 N against 951 N, 3.1e-4 m against 9.5e-3 m; the
    stiffness only scales the stage-to-stage change of the force)."""
    env = {"name": "sea", "waves": {"spectrum": "jonswap", "hs": 10.0, "tp": 14.0,
                                   "heading_deg": 0.0}}
    kw = {}
    if mixed:
        kw = dict(model="quasi-static",
                  per_line={"line6": "finite-element", "line7": "finite-element"})
    b = _built(_scene(tmp_path, environment=env, n_elements=10, **kw))
    runs = {}
    for dt, mode, every in ((0.1, "catenary", 0.0), (0.1, "linear", 0.0),
                            (0.05, "catenary", 0.0), (0.1, "linear", 1.0)):
        runs[dt, mode, every] = simulate(b, seed=3, duration=240.0, dt=dt, ramp=40.0,
                                         solver=SolverSpec(fe_stages=mode,
                                                           fe_stiffness_interval=every))
    exact, linear, fine, held = runs.values()
    T, TL, TF, TH = (r.line_tension.values for r in (exact, linear, fine, held))
    X, XL, XF, XH = (r.motion.values[:, :3] for r in (exact, linear, fine, held))
    dt_error_T = np.abs(T - TF[::2]).max()
    dt_error_X = np.abs(X - XF[::2]).max()
    assert 0.0 < np.abs(TL - T).max() < 0.01 * dt_error_T
    assert 0.0 < np.abs(XL - X).max() < 0.01 * dt_error_X
    assert TL.max() == pytest.approx(T.max(), rel=1e-5)
    assert 0.0 < np.abs(TH - TL).max() < 0.1 * dt_error_T
    assert 0.0 < np.abs(XH - XL).max() < 0.1 * dt_error_X
    # linear with the stiffness every 1.0 s is the default: only the others are named
    assert "solver" not in held.attrs
    assert exact.attrs["solver"] == "catenary exact, memory convolution, FE stages catenary"
    assert linear.attrs["solver"].endswith("FE stiffness every 0 s")


def test_fe_stages_key():
    """The scene key takes catenary or linear; anything else is a SceneError naming the key;
    ``linear`` is the default (no key, no spec), ``catenary`` is not."""
    from floatmoor.core.config import Node

    assert parse_solver(Node({"fe_stages": "linear"}, file="s.yaml", path="solver")) \
        .fe_stages == "linear"
    assert parse_solver(Node({}, file="s.yaml", path="solver")).fe_stages == "linear"
    assert parse_solver(Node({}, file="s.yaml", path="solver")).is_default
    assert parse_solver(Node({"fe_stages": "linear"}, file="s.yaml", path="solver")).is_default
    assert not parse_solver(Node({"fe_stages": "catenary"}, file="s.yaml",
                                 path="solver")).is_default
    assert fe_stages(None) == "linear"
    with pytest.raises(SceneError, match="fe_stages"):
        parse_solver(Node({"fe_stages": "quadratic"}, file="s.yaml", path="solver"))


def test_held_stiffness_across_a_line_release(tmp_path):
    """Line6 released at 30.05 s (between two stiffness solves of the default 1.0 s at dt
    0.1 s: the release solves it again at once): the run with the kept stiffness stays as
    close to the every-step run after the release as before it (motion within 10 % of the
    time step's error above, 9.5e-3 m; measured 2.3e-4 m before, 2.6e-4 m in the 1.2 s after
    and 3.5e-4 m to the end; within twice the difference before), line6 is zero from the
    release in both.  Without the solve at the release (the stiffness of the released line kept
    until the next regular solve) the difference after it was 7.4e-4 m: this test failed
    (checked 2026-11-28 on a copy of the kernel)."""
    env = {"name": "sea", "waves": {"spectrum": "jonswap", "hs": 10.0, "tp": 14.0,
                                   "heading_deg": 0.0}}
    b = _built(_scene(tmp_path, environment=env, n_elements=10,
                      forces={"line_failure": {"line6": 30.05}}))
    every, held = (simulate(b, seed=3, duration=60.0, dt=0.1, ramp=10.0,
                            solver=SolverSpec(fe_stiffness_interval=iv)) for iv in (0.0, 1.0))
    t = every.time.values
    d = np.abs(held.motion.values[:, :3] - every.motion.values[:, :3]).max(axis=1)
    before, after = (t >= 20.0) & (t < 30.0), t >= 30.05
    assert 0.0 < d[before].max() and d[after].max() < 2.0 * d[before].max()
    assert d.max() < 1e-3
    for r in (every, held):
        T6 = r.line_tension.sel(line="line6").values
        assert (T6[after] == 0.0).all() and (T6[t < 30.0] > 0.0).all()


def test_fe_stiffness_interval_key():
    """``fe_stiffness_interval``: a number of seconds from 0 to 10 (default 1.0, which is
    the default spec); anything else a SceneError naming the key."""
    from floatmoor.core.config import Node
    from floatmoor.io.solver_section import FE_STIFFNESS_INTERVAL

    node = Node({"fe_stiffness_interval": 0.5}, file="s.yaml", path="solver")
    assert parse_solver(node).fe_stiffness_interval == 0.5
    assert not parse_solver(node).is_default
    assert parse_solver(Node({}, file="s.yaml", path="solver")).fe_stiffness_interval \
        == FE_STIFFNESS_INTERVAL == 1.0
    for bad in (-0.1, 11.0, "1 s", True):
        with pytest.raises(SceneError, match=r"s.yaml: solver.fe_stiffness_interval"):
            parse_solver(Node({"fe_stiffness_interval": bad}, file="s.yaml", path="solver"))

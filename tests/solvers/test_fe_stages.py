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
    ``fe_stages: linear`` (the default) differ from the catenary stages by less than 1 % of
    the catenary stages' own time-step error (dt 0.1 against 0.05 s), for all lines finite-element and for two FE lines
    among ten quasi-static ones (whose catenaries stay in the stages).  Measured: 1.3 N against
    951 N (all FE), 2.0 N against 1483 N (mixed), 2e-5 m against 1e-2 m of motion; the option
    does change the numbers (the two paths are not the same arithmetic)."""
    env = {"name": "sea", "waves": {"spectrum": "jonswap", "hs": 10.0, "tp": 14.0,
                                   "heading_deg": 0.0}}
    kw = {}
    if mixed:
        kw = dict(model="quasi-static",
                  per_line={"line6": "finite-element", "line7": "finite-element"})
    b = _built(_scene(tmp_path, environment=env, n_elements=10, **kw))
    runs = {}
    for dt, mode in ((0.1, "catenary"), (0.1, "linear"), (0.05, "catenary")):
        runs[dt, mode] = simulate(b, seed=3, duration=240.0, dt=dt, ramp=40.0,
                                  solver=SolverSpec(fe_stages=mode))
    exact, linear, fine = runs[0.1, "catenary"], runs[0.1, "linear"], runs[0.05, "catenary"]
    T, TL, TF = (r.line_tension.values for r in (exact, linear, fine))
    X, XL, XF = (r.motion.values[:, :3] for r in (exact, linear, fine))
    dt_error_T = np.abs(T - TF[::2]).max()
    dt_error_X = np.abs(X - XF[::2]).max()
    assert 0.0 < np.abs(TL - T).max() < 0.01 * dt_error_T
    assert 0.0 < np.abs(XL - X).max() < 0.01 * dt_error_X
    assert TL.max() == pytest.approx(T.max(), rel=1e-5)
    # linear is the default: only the catenary stages are named in the result
    assert "solver" not in linear.attrs
    assert exact.attrs["solver"] == "catenary exact, memory convolution, FE stages catenary"


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

"""The slender-element force model on the Floatel-like semi (setup from the scene and the
vessel file), and the viscous-drift hooks for the other models."""

import math
import warnings
from pathlib import Path
from types import SimpleNamespace

import numpy as np
import pytest

from floatmoor.core.config import Node
from floatmoor.core.errors import SceneError
from floatmoor.forces.base import SetupContext
from floatmoor.forces.slender import (
    SlenderElements,
    drift_database,
    hull_current_table,
    linear_damping_matrix,
)
from floatmoor.forces.slender_kernels import slender_packed_into
from floatmoor.forces.waves import wave_components
from floatmoor.io.build import build
from floatmoor.io.viscous_drift_section import ViscousDriftSpec, parse_viscous_drift

ROOT = Path(__file__).resolve().parents[2]
SCENE = ROOT / "scenes" / "floatel_100yr.yaml"


@pytest.fixture(scope="module")
def built():
    return build(SCENE)


def _ctx(built, spec, duration=200.0, dt=0.1, waves=True):
    n_steps = int(round(duration / dt))
    env = built.scene.environment
    comp = None
    if waves:
        comp = wave_components(env.waves, duration=duration, seed=3, h=0.5 * dt,
                               water_depth=built.scene.site.water_depth,
                               gravity=built.scene.site.gravity)
    return SetupContext(built=built, seed=3, dt=dt, n_steps=n_steps, ramp=20.0, yaw0=0.0,
                        options=SimpleNamespace(viscous_drift=spec), waves=comp)


def test_mean_current_force_hand_computed(built):
    """Current only, body at rest: F_x = U^2 (4 C_col L_col + 2 C_pont L_pont), L_col the
    wetted column length 4.375 m (table 6.1, survival draft), L_pont 90 m, C from table 6.3:
    0.94^2 (4 x 7687.5 x 4.375 + 2 x 1768.1 x 90) = 0.8836 x 452,789 = 400,084 N.
    (The seed's tuning eq. 6.5 / table 6.4 used the full column length 18.875 m.)"""
    m = SlenderElements()
    m.setup(_ctx(built, ViscousDriftSpec(model="slender_elements")))
    f = m.mean_force()
    U = float(built.scene.environment.current.speed[0])
    assert U == pytest.approx(0.94)
    expected = U ** 2 * (4 * 7687.5 * 4.375 + 2 * 1768.1 * 90.0)
    assert f[0] == pytest.approx(expected, rel=1e-9)
    assert abs(f[1]) < 1e-6 * expected and abs(f[5]) < 1e-6 * expected * 50


def test_model_force_equals_packed_kernel(built):
    m = SlenderElements()
    m.setup(_ctx(built, ViscousDriftSpec(model="slender_elements")))
    rng = np.random.default_rng(0)
    R = np.zeros((3, 3))
    sc = np.zeros(6)
    for j in (0, 401, 1999, 3000):
        x = np.array([12.0, -3.0, 0.4, 0.02, -0.03, 0.3]) * rng.uniform(0.5, 1.5, 6)
        v_yaw = rng.normal(size=6) * np.array([1.0, 1.0, 0.5, 0.01, 0.01, 0.01])
        # pose rate: horizontal velocity turned to earth axes; rotation rates unchanged
        c, s = math.cos(x[5]), math.sin(x[5])
        rate = v_yaw.copy()
        rate[0] = c * v_yaw[0] - s * v_yaw[1]
        rate[1] = s * v_yaw[0] + c * v_yaw[1]
        f_py = np.zeros(6)
        m.force(j * m.h, x, rate, f_py)
        f_k = np.zeros(6)
        slender_packed_into(j, x, v_yaw, *m.kernel_arrays(), R, sc, f_k)
        assert np.allclose(f_k, f_py, rtol=1e-7, atol=1e-6)  # float32 tables (NUMBA_DISABLE_JIT)
        assert np.abs(f_k[0]) > 0.0


def test_ramp_and_wave_force(built):
    """Ramped waves: at t = 0 only the current acts; later the wave kinematics add a
    fluctuating force an order of magnitude above the current force (Hs 16 m)."""
    m = SlenderElements()
    m.setup(_ctx(built, ViscousDriftSpec(model="slender_elements")))
    f0 = np.zeros(6)
    m.force(0.0, np.zeros(6), np.zeros(6), f0)
    assert np.allclose(f0, m.mean_force())
    fx = []
    for j in range(400, 4000, 7):
        f = np.zeros(6)
        m.force(j * m.h, np.zeros(6), np.zeros(6), f)
        fx.append(f[0])
    assert np.std(fx) > 3.0 * abs(f0[0])


def test_double_counting_hook(built):
    v = built.vessel
    tab = np.asarray(v.current_coefficients.coefficients, float)
    ctx = _ctx(built, ViscousDriftSpec(model="slender_elements"), waves=False)
    with pytest.warns(Warning, match="surge"):
        out = hull_current_table(ctx, tab, v)
    assert np.all(out[:, 0] == 0.0) and np.all(out[:, 1] == 0.0)
    ctx2 = _ctx(built, ViscousDriftSpec(model="slender_elements", double_counting=False),
                waves=False)
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert hull_current_table(ctx2, tab, v) is tab
    assert hull_current_table(_ctx(built, None, waves=False), tab, v) is tab


def test_correction_formula_hooks(built):
    spec = ViscousDriftSpec(model="correction_formula", column_diameters=(12.5,) * 4,
                            main_column_diameter=12.5, extra_damping=2.0)
    ctx = _ctx(built, spec, waves=False)
    db = built.vessel.database
    out = drift_database(ctx, db)
    w = db.omega.values
    i0 = int(np.argmin(np.abs(db.wave_direction.values)))
    k = w ** 2 / 9.80665
    B = 1000.0 * k * np.exp(-1.25 * (k * 12.5) ** 2) * 50.0
    pot = db.mean_drift_force.isel(wave_direction=i0).sel(influenced_dof="surge").values
    new = out.mean_drift_force.isel(wave_direction=i0).sel(influenced_dof="surge").values
    assert np.allclose(new, pot * (1 + 0.25 * 0.94) + B * (10 * 0.94 + 16.0))
    D = linear_damping_matrix(ctx, built.vessel.linear_damping)
    assert D[0, 0] == pytest.approx(3 * 1.5e6) and D[2, 2] == built.vessel.linear_damping[2, 2]
    assert drift_database(_ctx(built, None, waves=False), db) is db


def test_scene_section_parser():
    spec = parse_viscous_drift(Node({"model": "slender_elements", "stretching": "constant",
                                     "drag": {"column": {"c2y": 4144.37}}}, "s.yaml",
                                    "forces.viscous_drift"))
    assert spec.wheeler is False and spec.drag == {"column": {"c2y": 4144.37}}
    with pytest.raises(SceneError, match="forces.viscous_drift.column_diameters"):
        parse_viscous_drift(Node({"model": "slender_elements", "column_diameters": [1]},
                                 "s.yaml", "forces.viscous_drift"))
    with pytest.raises(SceneError, match="drift: newman"):
        parse_viscous_drift(Node({"model": "correction_formula", "column_diameters": [12.5]},
                                 "s.yaml", "forces.viscous_drift"), drift="qtf")
    with pytest.raises(SceneError, match="model"):
        parse_viscous_drift(Node({"model": "morison"}, "s.yaml", "forces.viscous_drift"))
    cf = parse_viscous_drift(Node({"model": "correction_formula",
                                   "column_diameters": [12.5, 12.5, 14.0, 14.0]}, "s.yaml",
                                  "forces.viscous_drift"))
    assert cf.main_column_diameter == 14.0 and cf.correction_formula().d_sum == 53.0


def test_scene_level_helpers_for_the_frequency_domain(built):
    """corrected_drift_database / viscous_linear_damping need no SetupContext (FD use) and
    give the same as the time-domain hooks."""
    from floatmoor.forces.slender import corrected_drift_database, viscous_linear_damping
    spec = ViscousDriftSpec(model="correction_formula", column_diameters=(12.5,) * 4,
                            main_column_diameter=12.5, extra_damping=0.5)
    a = corrected_drift_database(built, spec)
    b = drift_database(_ctx(built, spec, waves=False), built.vessel.database)
    assert np.array_equal(a.mean_drift_force.values, b.mean_drift_force.values)
    assert corrected_drift_database(built, None) is built.vessel.database
    D = viscous_linear_damping(spec, built.vessel.linear_damping)
    assert D[1, 1] == pytest.approx(1.5 * built.vessel.linear_damping[1, 1])


def test_without_waves_current_only(built):
    m = SlenderElements()
    m.setup(_ctx(built, ViscousDriftSpec(model="slender_elements"), waves=False))
    f = np.zeros(6)
    m.force(50.0, np.zeros(6), np.zeros(6), f)
    assert f[0] == pytest.approx(0.94 ** 2 * (4 * 7687.5 * 4.375 + 2 * 1768.1 * 90.0), rel=1e-9)

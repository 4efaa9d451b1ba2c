"""Viscous drift in the coupled time domain: slender elements in the numba loop, the
double-counting rule, the correction formula on the Newman drift and the extra damping."""

import warnings
from pathlib import Path

import numpy as np
import pytest

from floatmoor.core.config import Node
from floatmoor.forces import select_models
from floatmoor.io.build import build
from floatmoor.io.forces_section import ForcesSpec, parse_forces
from floatmoor.io.viscous_drift_section import ViscousDriftSpec
from floatmoor.solvers.time_domain import assemble, integrate

ROOT = Path(__file__).resolve().parents[2]
SCENE = ROOT / "scenes" / "floatel_100yr.yaml"


@pytest.fixture(scope="module")
def floatel():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return build(SCENE)


def _opts(**kw):
    return ForcesSpec(viscous_drift=ViscousDriftSpec(**kw))


def test_scene_key_selects_the_model(floatel):
    spec = parse_forces(Node({"viscous_drift": {"model": "slender_elements"}}, "s.yaml",
                             "forces"))
    assert "slender_elements" in select_models(floatel, spec)
    assert "slender_elements" not in select_models(floatel, None)
    spec = parse_forces(Node({"viscous_drift": {"model": "correction_formula",
                                                "column_diameters": [12.5] * 4}}, "s.yaml",
                             "forces"))
    assert "slender_elements" not in select_models(floatel, spec)


def test_kernel_slender_force_equals_model(floatel):
    """The loop's slender-element part at recorded steps equals the model's Python ``force``
    at the same (t, pose, pose rate), also with the body turned 0.5 rad in yaw."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        a0 = assemble(floatel, seed=2, dt=0.2, duration=200.0, ramp=30.0,
                      options=_opts(model="slender_elements"))
        for yaw in (0.0, 0.5):
            start = a0.x0.copy()
            start[5] += yaw
            a = assemble(floatel, seed=2, dt=0.2, duration=200.0, ramp=30.0,
                         options=_opts(model="slender_elements"),
                         start_pose=start if yaw else None)
            r = integrate(a, built=floatel, record_forces=True)
            q = r.force_models.index("slender_elements")
            m = a.models["slender_elements"]
            for n in (0, 151, 600, 999):
                out = np.zeros(6)
                m.force(r.time[n], r.motion[n], r.velocity[n], out)
                assert np.abs(out[0]) > 1e3
                assert np.allclose(r.forces[n, q], out, rtol=1e-9, atol=1e-6 * np.abs(out).max())


def test_double_counting_in_the_run(floatel):
    """With slender elements the hull current force is zero in the covered DOFs (warning);
    with double_counting: false it stays."""
    with pytest.warns(Warning, match="double counting"):
        a = assemble(floatel, seed=1, dt=0.2, duration=50.0,
                     options=_opts(model="slender_elements"))
    cur = a.models["current"]
    assert np.all(cur.table[:, 0] == 0.0) and np.all(cur.table[:, 1] == 0.0)
    assert cur.mean_force()[0] == 0.0
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        b = assemble(floatel, seed=1, dt=0.2, duration=50.0,
                     options=_opts(model="slender_elements", double_counting=False))
    assert b.models["current"].mean_force()[0] > 1e5
    # static start: the slender elements carry the mean current force instead (hand value in
    # test_slender_model: 400,084 N)
    assert a.models["slender_elements"].mean_force()[0] == pytest.approx(400084.0, rel=1e-4)


def test_correction_formula_in_newman_drift_and_damping(floatel):
    """The Newman drift uses the corrected mean drift coefficients: its mean force is
    sum a_k^2 D_corr(w_k); the extra damping raises surge/sway linear damping."""
    spec = dict(model="correction_formula", column_diameters=(12.5,) * 4,
                main_column_diameter=12.5, extra_damping=1.0)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        a = assemble(floatel, seed=4, dt=0.5, duration=600.0, options=_opts(**spec))
        b = assemble(floatel, seed=4, dt=0.5, duration=600.0)
    r = a.waves.realisation
    w = r.omega
    k = w ** 2 / 9.80665
    B = 1000.0 * k * np.exp(-1.25 * (k * 12.5) ** 2) * 50.0
    pot = b.models["drift_newman"].mean_force()[0]
    visc = np.sum(r.amplitude ** 2 * B * (10 * 0.94 + 16.0))
    # the potential part scaled by (1 + 0.25 U); viscous part added (waves along +x).  The
    # model interpolates the corrected coefficients from the database frequencies, here B is
    # evaluated at the component frequencies: 1.5e-5 relative difference measured
    assert a.models["drift_newman"].mean_force()[0] == pytest.approx(
        pot * (1 + 0.25 * 0.94) + visc, rel=1e-4)
    assert visc > 0.5 * pot   # the viscous part matters in the 100-year sea
    assert a.models["damping_linear"].matrix[0, 0] == pytest.approx(
        2.0 * b.models["damping_linear"].matrix[0, 0])


def test_inertia_option_needs_coefficients(floatel):
    from floatmoor.core.errors import SceneError
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with pytest.raises(SceneError, match="inertia_per_length"):
            assemble(floatel, seed=1, dt=0.2, duration=50.0,
                     options=_opts(model="slender_elements", inertia=True))

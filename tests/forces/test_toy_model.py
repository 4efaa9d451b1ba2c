"""A new force model of an existing kind is one class and its registry entry, nothing else.

The toy model below, a constant thrust fixed to the body (it turns with the yaw), is defined
only here: it registers itself and adds one term of the ``restoring`` kind (a constant force
and a zero matrix on the pose) in ``contribute``.  No solver, kernel or assembly code knows it.
The run starts at the static equilibrium *without* the thrust, so the time loop alone has to
carry the body to the new equilibrium.  Expected offset: the linear static response
``K^-1 F`` with ``K`` the hydrostatic restoring plus the analytic mooring stiffness from the
statics at the start pose (independent of the time loop), for a thrust small enough that the
mooring stays linear over the offset.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest

from floatmoor.forces import REGISTRY, ForceModel, register
from floatmoor.forces.kernels import to_earth
from floatmoor.io.build import build
from floatmoor.io.scene import load_scene
from floatmoor.solvers.statics import solve_equilibrium as equilibrium
from floatmoor.solvers.time_domain import assemble, integrate

ROOT = Path(__file__).resolve().parents[2]
SCENE = ROOT / "scenes" / "floatel_100yr.yaml"
THRUST = np.array([3.0e5, -1.5e5, 0.0, 0.0, 0.0, 2.0e6])  # N, N, -, -, -, N m (body axes)
CALM = ["hydrostatics", "mooring", "radiation", "damping_linear"]


@pytest.fixture
def thruster():
    """Register the toy model for one test and remove it afterwards."""

    @register
    class ConstantThruster(ForceModel):
        name = "toy_thruster"
        description = "constant thrust in body axes"

        def setup(self, ctx):
            self.thrust = THRUST.copy()
            self._freeze()

        def force(self, t, pose, velocity, out):
            out += to_earth(self.thrust, float(pose[5]))

        def contribute(self, asm):
            asm.add_restoring(self.name, self.thrust, np.zeros((6, 6)))

    yield ConstantThruster
    del REGISTRY["toy_thruster"]


@pytest.fixture(scope="module")
def built():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        return build(load_scene(SCENE))


def test_constant_thruster_moves_the_body_to_its_static_offset(thruster, built):
    calm = assemble(built, seed=1, dt=0.2, duration=20.0, models=CALM)
    x_start = calm.x0
    a = assemble(built, seed=1, dt=0.2, duration=4000.0, models=CALM + ["toy_thruster"],
                 start_pose=x_start)
    assert "toy_thruster" in a.models
    r = integrate(a, record_forces=True, built=built)
    # the recorded force of the toy term: the thrust turned by the yaw (earth axes)
    q = r.force_models.index("toy_thruster")
    for n in (0, len(r.time) // 2, len(r.time) - 1):
        np.testing.assert_allclose(r.forces[n, q], to_earth(THRUST, r.motion[n, 5]),
                                   rtol=1e-12, atol=1e-6)
    # expected offset: linear statics K^-1 F at the start pose (yaw ~ 0 there)
    eq = equilibrium(built.mooring, hydrostatic_stiffness=calm.asm.restoring,
                     external_force=calm.asm.const_force, x0=x_start)
    K = calm.asm.restoring + eq.mooring_stiffness
    expected = np.linalg.solve(K, THRUST)
    late = r.time >= 2000.0
    got = r.motion[late].mean(axis=0) - x_start
    for k in (0, 1, 5):  # surge, sway (m) and yaw (rad): the loaded DOFs
        assert abs(got[k] - expected[k]) <= 0.02 * abs(expected[k]), (k, got[k], expected[k])
    assert abs(expected[0]) > 0.3  # an offset that the test can see


def test_thruster_in_the_static_start(thruster, built):
    """Through the assembly, the static start includes the toy term too (its constant is part
    of the restoring kind's constant force)."""
    calm = assemble(built, seed=1, dt=0.2, duration=20.0, models=CALM)
    a = assemble(built, seed=1, dt=0.2, duration=20.0, models=CALM + ["toy_thruster"])
    np.testing.assert_allclose(a.asm.const_force, calm.asm.const_force + THRUST)
    assert a.x0[0] - calm.x0[0] > 0.3

"""A new force model of an existing kind is one class and its registry entry, nothing else,
and it serves both domains.

The toy model below, a constant thrust fixed to the body (it turns with the yaw), is defined
only here: it registers itself, says that every scene wants it (``wanted``) and adds one term of
the ``restoring`` kind (a constant force and a zero matrix on the pose) in ``contribute``.  No
solver, kernel, assembly or frequency-domain code knows it: the frequency domain takes its
terms of that linear kind as they are (the default ``frequency_domain``).  The TD run starts at
the static equilibrium *without* the thrust, so the time loop alone has to carry the body to
the new equilibrium.  Expected offset: the linear static response ``K^-1 F`` with ``K`` the
hydrostatic restoring plus the analytic mooring stiffness from the statics at the start pose
(independent of both domains), for a thrust small enough that the mooring stays linear over the
offset.  A second toy, a constant push given as a precomputed force series, shows a model of a
kind without a frequency-domain form: the frequency domain refuses it by name until the model
gives its own ``frequency_domain`` (its mean force), and then carries it.
"""

from __future__ import annotations

import warnings
from pathlib import Path

import numpy as np
import pytest

from floatmoor.analyses.frequency_domain import frequency_domain_result
from floatmoor.core.errors import SceneError
from floatmoor.forces import REGISTRY, FDTerms, ForceModel, register, select_models
from floatmoor.forces.kernels import to_earth
from floatmoor.io.build import build
from floatmoor.io.scene import load_scene
from floatmoor.solvers.statics import solve_equilibrium as equilibrium
from floatmoor.solvers.time_domain import assemble, integrate

ROOT = Path(__file__).resolve().parents[2]
SCENE = ROOT / "scenes" / "floatel_100yr.yaml"
THRUST = np.array([3.0e5, -1.5e5, 0.0, 0.0, 0.0, 2.0e6])  # N, N, -, -, -, N m (body axes)
CALM = ["hydrostatics", "mooring", "radiation", "damping_linear"]
TOL_POSE = np.array([1e-4, 1e-4, 1e-4, 1e-7, 1e-7, 1e-7])
"""The two statics solves (the FD's iterated on the mean yaw) agree to their tolerance (m, rad)."""


@pytest.fixture
def thruster():
    """Register the toy model for one test and remove it afterwards."""

    @register
    class ConstantThruster(ForceModel):
        name = "toy_thruster"
        description = "constant thrust in body axes"

        @classmethod
        def wanted(cls, built, options):
            return built.vessel is not None

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


def test_thruster_appears_in_both_domains(thruster, built):
    """The scene's model choice (``wanted``) gives the toy to both domains; the frequency
    domain reads its restoring term as it is: its mean position moves by K^-1 F (the same
    independent expectation as the time loop's) and equals the time domain's static start
    with the thrust."""
    assert "toy_thruster" in select_models(built, built.scene.forces)
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        fd = frequency_domain_result(built, models=CALM + ["toy_thruster"])
        calm = frequency_domain_result(built, models=CALM)
        scene_fd = frequency_domain_result(built)
    assert "toy_thruster" in fd.models and "toy_thruster" in scene_fd.models
    assert "toy_thruster" not in calm.models
    a = assemble(built, seed=1, dt=0.2, duration=20.0, models=CALM + ["toy_thruster"])
    assert np.all(np.abs(fd.mean - a.x0) <= TOL_POSE), fd.mean - a.x0
    eq = equilibrium(built.mooring, hydrostatic_stiffness=a.asm.restoring,
                     external_force=a.asm.const_force - THRUST, x0=calm.mean)
    K = a.asm.restoring + eq.mooring_stiffness
    expected = np.linalg.solve(K, THRUST)
    got = fd.mean - calm.mean
    for k in (0, 1, 5):
        assert abs(got[k] - expected[k]) <= 0.02 * abs(expected[k]), (k, got[k], expected[k])


PUSH = np.array([2.0e5, 0.0, 0.0, 0.0, 0.0, 0.0])  # N, earth axes


@pytest.fixture
def push():
    """A constant push as a precomputed force series (the ``series`` kind, which has no
    frequency-domain form of its own); its subclass adds ``frequency_domain``."""

    @register
    class ConstantPush(ForceModel):
        name = "toy_push"
        description = "constant push in earth axes, as a force series"

        def setup(self, ctx):
            self.series = np.tile(PUSH, (ctx.n_samples, 1))
            self._freeze()

        def force(self, t, pose, velocity, out):
            out += PUSH

        def mean_force(self):
            return PUSH.copy()

        def contribute(self, asm):
            asm.add_series(self.name, self.series)

    @register
    class ConstantPushFD(ConstantPush):
        name = "toy_push_fd"

        def frequency_domain(self, fd):
            return FDTerms(mean_force=PUSH.copy())

    yield ConstantPush
    del REGISTRY["toy_push"], REGISTRY["toy_push_fd"]


def test_model_without_frequency_domain_form_is_refused_by_name(push, built):
    """A model whose term the frequency domain cannot read is refused (SceneError naming it,
    no silent omission); with its own ``frequency_domain`` it is carried, and its mean force
    gives the same mean position as the time domain's static start."""
    with pytest.raises(SceneError, match="toy_push"):
        frequency_domain_result(built, models=CALM + ["toy_push"])
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        fd = frequency_domain_result(built, models=CALM + ["toy_push_fd"])
    assert "toy_push_fd" in fd.models
    np.testing.assert_array_equal(fd.mean_force_model[list(fd.models).index("toy_push_fd")],
                                  PUSH)
    a = assemble(built, seed=1, dt=0.2, duration=20.0, models=CALM + ["toy_push_fd"])
    assert np.all(np.abs(fd.mean - a.x0) <= TOL_POSE), fd.mean - a.x0
    assert fd.mean[0] - frequency_domain_result(built, models=CALM).mean[0] > 0.3


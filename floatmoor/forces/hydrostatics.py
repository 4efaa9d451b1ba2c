"""Hydrostatic and gravity restoring, additional stiffness, and linear / quadratic damping.

Hydrostatics: ``F = F_0 - C x`` in the yaw-following frame (roll and pitch are angles about
its axes), turned into earth axes, with ``C`` the vessel's ``total_restoring`` (hydrostatic +
gravity + additional stiffness, about the reference point, linear about the zero pose: roll and
pitch are small rotations here) and ``F_0`` the constant buoyancy-minus-weight force at the zero
pose (:func:`floatmoor.io.build.net_buoyancy_force`, the same ``static_force`` the statics use).

Damping: ``F = -D_l nu`` and ``F_i = -sum_j D_q,ij nu_j |nu_j|`` with the vessel's matrices and
the velocity ``nu`` in the yaw-following frame (the damping turns with the body), turned into
earth axes.  ``force(t, pose, velocity, out)`` takes the pose rate and returns earth axes, as the
time-domain kernel does.
"""

from __future__ import annotations

import numpy as np

from .base import ForceModel, KernelAssembly, SetupContext, register
from .kernels import matvec_sub_into, quadratic_damping_into, to_earth, to_yaw_frame

__all__ = ["Hydrostatics", "LinearDamping", "QuadraticDamping"]


@register
class Hydrostatics(ForceModel):
    name = "hydrostatics"
    description = "buoyancy - weight + linear hydrostatic, gravity and additional restoring"

    def setup(self, ctx: SetupContext):
        v = ctx.built.vessel
        self.restoring = np.array(v.total_restoring, float)
        self.const_force = np.array(ctx.built.static_force, float).reshape(6)
        self._freeze()

    def force(self, t, pose, velocity, out):
        f = self.const_force.copy()
        matvec_sub_into(self.restoring, np.asarray(pose, float), f)
        out += to_earth(f, float(pose[5]))

    def stiffness(self, pose=None):
        return self.restoring.copy()

    def mean_force(self):
        return self.const_force.copy()

    def contribute(self, asm: KernelAssembly):
        asm.add_restoring(self.name, self.const_force, self.restoring)


@register
class LinearDamping(ForceModel):
    name = "damping_linear"
    description = "linear damping matrix of the vessel file"

    def setup(self, ctx: SetupContext):
        inputs = ctx.inputs  # the scene's rules (extra damping, Wang (2016) section 6.6)
        D = None if inputs is None else inputs.linear_damping
        self.matrix = np.array(ctx.built.vessel.linear_damping if D is None else D, float)
        self._freeze()

    def force(self, t, pose, velocity, out):
        f = np.zeros(6)
        matvec_sub_into(self.matrix, to_yaw_frame(velocity, float(pose[5])), f)
        out += to_earth(f, float(pose[5]))

    def damping_linearized(self, *args, **kwargs):
        return self.matrix.copy()

    def contribute(self, asm: KernelAssembly):
        asm.add_damping(self.name, self.matrix)


@register
class QuadraticDamping(ForceModel):
    name = "damping_quadratic"
    description = "quadratic damping matrix of the vessel file, F = -D_q v|v|"

    def setup(self, ctx: SetupContext):
        self.matrix = np.array(ctx.built.vessel.quadratic_damping, float)
        self._freeze()

    def force(self, t, pose, velocity, out):
        f = np.zeros(6)
        quadratic_damping_into(self.matrix, to_yaw_frame(velocity, float(pose[5])), f)
        out += to_earth(f, float(pose[5]))

    def damping_linearized(self, velocity_std):
        """Stochastic linearisation for Gaussian velocity of std sigma: D_q sqrt(8/pi) sigma_j."""
        s = np.asarray(velocity_std, float).reshape(6)
        return self.matrix * (np.sqrt(8.0 / np.pi) * s)[None, :]

    def contribute(self, asm: KernelAssembly):
        asm.add_quadratic_damping(self.name, self.matrix)

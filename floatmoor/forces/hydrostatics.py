"""Hydrostatic and gravity restoring and additional stiffness.

``F = F_0 - C x`` in the yaw-following frame (roll and pitch are angles about
its axes), turned into earth axes, with ``C`` the vessel's ``total_restoring`` (hydrostatic +
gravity + additional stiffness, about the reference point, linear about the zero pose: roll and
pitch are small rotations here) and ``F_0`` the constant buoyancy-minus-weight force at the zero
pose (:func:`floatmoor.io.build.net_buoyancy_force`, the same ``static_force`` the statics use).
One ``restoring`` term; the frequency domain reads it as it is (the static balance and the
restoring of the statics, the linear stiffness), by the default
:meth:`~floatmoor.forces.base.ForceModel.frequency_domain`.
"""

from __future__ import annotations

import numpy as np

from .base import ForceModel, KernelAssembly, SetupContext, register
from .kernels import matvec_sub_into, to_earth

__all__ = ["Hydrostatics"]


@register
class Hydrostatics(ForceModel):
    name = "hydrostatics"
    description = "buoyancy - weight + linear hydrostatic, gravity and additional restoring"

    @classmethod
    def wanted(cls, built, options) -> bool:
        return built.vessel is not None

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

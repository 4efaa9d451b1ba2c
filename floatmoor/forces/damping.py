"""Linear and quadratic damping matrices of the vessel file, in both domains.

``F = -D_l nu`` and ``F_i = -sum_j D_q,ij nu_j |nu_j|`` with the vessel's matrices (every entry,
off-diagonal terms included) and the velocity ``nu`` in the yaw-following frame (the damping
turns with the body), turned into earth axes.  ``force(t, pose, velocity, out)`` takes the pose
rate and returns earth axes, as the time-domain kernel does.  The linear damping is the one of
the scene's rules (:func:`floatmoor.io.build.model_inputs`: raised in surge and sway by the
correction formula's ``extra_damping``).

Frequency domain (the default :meth:`~floatmoor.forces.base.ForceModel.frequency_domain`: the
terms as they are): ``D_l`` turned to earth axes at the mean heading on the WF and LF motion;
``D_q`` whole, linearised by the solver on the total velocity (Caughey (1963):
``B_eq,ij = sqrt(8/pi) sigma_j D_q,ij`` with sigma_j the standard deviation of the yaw-frame
velocity j, :func:`floatmoor.solvers.frequency_domain.equivalent_quadratic_damping`).
"""

from __future__ import annotations

import numpy as np

from .base import ForceModel, KernelAssembly, SetupContext, register
from .kernels import matvec_sub_into, quadratic_damping_into, to_earth, to_yaw_frame

__all__ = ["LinearDamping", "QuadraticDamping"]


@register
class LinearDamping(ForceModel):
    name = "damping_linear"
    description = "linear damping matrix of the vessel file"

    @classmethod
    def wanted(cls, built, options) -> bool:
        return bool(np.any(built.vessel.linear_damping != 0.0))

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

    @classmethod
    def wanted(cls, built, options) -> bool:
        return bool(np.any(built.vessel.quadratic_damping != 0.0))

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

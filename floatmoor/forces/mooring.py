"""Quasi-static mooring adapter: catenary lines at the instantaneous fairlead positions.

The mooring force is that of :class:`floatmoor.mooring.MooringSystem` (force in earth axes,
moment about the displaced reference point) at the current pose: fairleads move with the body
(full rotation), anchors are fixed.  The time loop calls the numba
:func:`floatmoor.mooring.system.system_force_kernel` directly with warm starts.

Line failure (transient ALS): ``forces.line_failure`` names lines and the time (s) at which each
breaks; from that time on the line is inactive.  Lines listed as ``failed_lines`` in the mooring
section are removed from the start (by :func:`floatmoor.io.build.build`).

Frequency domain: the same :class:`~floatmoor.mooring.MooringSystem` gives the mean position
(the static balance under the other models' mean forces, as the time domain's static start),
its tangent stiffness there and the line tensions
(:mod:`floatmoor.analyses.frequency_domain`); :meth:`QuasiStaticMooring.frequency_domain` adds
nothing more.  Line failure times are a time-domain event: the frequency domain sees the
intact system (a failed line is removed with ``failed_lines``).
"""

from __future__ import annotations

import math

import numpy as np

from ..core.errors import SceneError
from .base import FDContext, FDTerms, ForceModel, KernelAssembly, SetupContext, register

__all__ = ["QuasiStaticMooring"]


@register
class QuasiStaticMooring(ForceModel):
    name = "mooring"
    description = "quasi-static catenary lines at the instantaneous fairlead positions"

    @classmethod
    def wanted(cls, built, options) -> bool:
        return built.mooring is not None

    def frequency_domain(self, fd: FDContext) -> FDTerms:
        """No terms of its own: the frequency domain takes the mooring through the statics
        (module docstring)."""
        return FDTerms()

    def setup(self, ctx: SetupContext):
        system = ctx.built.mooring
        self.system = system
        fail = np.full(system.n_lines, math.inf)
        failures = getattr(ctx.options, "line_failure", None) or {}
        for name, t in dict(failures).items():
            if name not in system.names:
                raise SceneError(getattr(ctx.options, "file", None), "forces.line_failure",
                                 "names of mooring lines: " + ", ".join(system.names), name)
            fail[system.names.index(name)] = float(t)
        self.fail_time = fail
        self._freeze()

    def linearise_fibre(self, pose):
        """Fibre ropes: use (in :meth:`force` and the time loop) the lines linearised about
        ``pose`` with the dynamic stiffness at the mean tensions
        (:meth:`floatmoor.mooring.MooringSystem.linearised_fibre`); returns that system.  The
        time loop then moves that linearisation with the slowly varying tensions
        (``fibre_time_constant``); this Python force keeps the start one (equal to the loop's
        with ``fibre_time_constant: .inf``)."""
        lin = self.system.linearised_fibre(pose)
        object.__setattr__(self, "_dynamic_system", lin)
        return lin

    def _system_at(self, t):
        system = getattr(self, "_dynamic_system", None) or self.system
        failed = [n for n, tf in zip(system.names, self.fail_time) if t >= tf]
        return system.without_lines(failed) if failed else system

    def force(self, t, pose, velocity, out):
        out += self._system_at(t).force(np.asarray(pose, float))

    def stiffness(self, pose=None, t: float = 0.0):
        return self._system_at(t).stiffness(pose)

    def channels(self):
        return ["force", "line_tension", "anchor_tension"]

    def contribute(self, asm: KernelAssembly):
        asm.add_mooring(self.name, self.system, self.fail_time)

"""Wave drift damping: the change of the mean wave drift force with the slow body velocity.

A body moving slowly with velocity ``U`` along the waves meets them at the encounter frequency
and its mean drift force changes; for small ``U`` the change is a damping of the low-frequency
motion.  Aranha's formula (Aranha (1994); DNV-RP-C205 section 7.4) gives it from the mean drift
coefficients ``C(w)`` along the direction of travel ``e`` of the waves::

    b = 2 int S(w) (w/g) (4 C(w) + w dC/dw) dw,     B = b e e^T   (surge/sway, earth axes)

(:func:`floatmoor.forces.spectral.aranha_drift_damping`), summed over the sea's directions
(every wave system and spreading direction with its own spectrum and coefficients).  The
coefficients are those of the drift model (the scene's rules: corrected by the viscous
correction formula when the scene selects it), at the body heading; the spectrum is the
scene's target spectrum on the frequency domain's grid (the database's frequency range, step
``frequency_domain: d_omega``, 0.005 rad/s by default), so the time and the frequency domain
carry the same matrix at the same heading.

Time domain: one ``lf_damping`` term ``F = -B (x' - x'_WF)``: ``B`` at the start heading (the
heading of the wave forces, fixed in earth axes like them) on the pose rate less the linear
wave-frequency velocity (the one the wind and current use, :mod:`floatmoor.solvers.
wf_velocity`), so it damps the low-frequency motion only, as in the frequency domain, whose LF
system carries it (:meth:`WaveDriftDamping.frequency_domain`).

Scene: ``forces: {wave_drift_damping: true}`` (both domains); off by default.  It needs waves
and the database's ``mean_drift_force``.
"""

from __future__ import annotations

import math

import numpy as np

from ..core.errors import SceneError
from ..metocean.spectra import sea_directions
from .base import FDContext, FDTerms, ForceModel, KernelAssembly, SetupContext, register
from .spectral import DEFAULT_D_OMEGA, aranha_drift_damping, wave_frequency_grid

__all__ = ["WaveDriftDamping", "aranha_matrix"]


def aranha_matrix(omega, directions, spectra, coefficients, gravity: float) -> np.ndarray:
    """Aranha's wave drift damping (6, 6), earth axes, of a sea of several directions:
    ``sum_d b_d e_d e_d^T`` with each direction's spectrum ``spectra[d]`` (n,) on ``omega`` and
    mean drift coefficients ``coefficients[d]`` (n, 6) in earth axes (module docstring)."""
    B = np.zeros((6, 6))
    for d, beta in enumerate(directions):
        e = np.array([math.cos(beta), math.sin(beta)])
        Bd = aranha_drift_damping(omega, spectra[d], coefficients[d][:, :2] @ e, gravity,
                                  float(beta))
        B = Bd if d == 0 else B + Bd
    return B


@register
class WaveDriftDamping(ForceModel):
    name = "wave_drift_damping"
    description = "wave drift damping (Aranha) on the low-frequency motion"

    @classmethod
    def wanted(cls, built, options) -> bool:
        return (bool(getattr(options, "wave_drift_damping", False))
                and built.scene.environment.waves is not None)

    @staticmethod
    def _database(v, inputs):
        db = v.database if inputs is None or inputs.drift_database is None \
            else inputs.drift_database
        if "mean_drift_force" not in db:
            raise SceneError(v.file, "database", "a database with mean_drift_force for the wave "
                             "drift damping (or forces: {wave_drift_damping: false})")
        return db

    def frequency_domain(self, fd: FDContext) -> FDTerms:
        """The damping of the LF motion at the mean heading (module docstring)."""
        if not (fd.linear and fd.has_waves):
            return FDTerms()
        from .waves import fd_drift_coefficients
        db = self._database(fd.built.vessel, fd.inputs)
        C = fd_drift_coefficients(fd, db)
        return FDTerms(lf_damping=aranha_matrix(fd.omega, fd.directions, fd.spectra, C,
                                                fd.gravity))

    def setup(self, ctx: SetupContext):
        from .base import FDContext as _FD
        built = ctx.built
        v = built.vessel
        db = self._database(v, ctx.inputs)
        fd_opts = getattr(built.scene, "frequency_domain", None)
        omega = wave_frequency_grid(db, getattr(fd_opts, "d_omega", None) or DEFAULT_D_OMEGA)
        directions, spectra = sea_directions(built.scene.environment.waves, omega)
        fd = _FD(built=built, options=ctx.options, inputs=ctx.inputs, omega=omega,
                 mu=np.zeros(1), directions=directions, spectra=spectra, yaw=ctx.yaw0,
                 linear=True)
        self.matrix = np.ascontiguousarray(self.frequency_domain(fd).lf_damping)
        self._freeze()

    def force(self, t, pose, velocity, out, wf_velocity=None):
        """Add ``-B (x' - x'_WF)`` for the pose rate ``velocity`` (6,) and, optionally, the
        linear wave-frequency velocity ``wf_velocity`` (6,) at time t (earth axes)."""
        q = np.asarray(velocity, float).copy()
        if wf_velocity is not None:
            q -= np.asarray(wf_velocity, float)
        out -= self.matrix @ q

    def damping_linearized(self, *args, **kwargs):
        return self.matrix.copy()

    def contribute(self, asm: KernelAssembly):
        asm.add_lf_damping(self.name, self.matrix)

"""Wind and current forces, quadratic in the velocity of the flow relative to the body.

``F = C(theta_rel) |U - v|^2`` (Wang (2016) eq. 2.24 and 2.26 without their linearisation, so that
the wind and current damping ``-2 C U v`` come out of the model): ``U`` the flow velocity
(horizontal, earth axes), ``v`` the horizontal low-frequency velocity of the body reference
point (by default the solver removes its linear wave-frequency velocity from the body velocity,
scene option ``forces: {relative_velocity: low_frequency | total}``), ``theta_rel``
the direction of travel of the relative flow measured from the body x axis (it follows the
body's yaw), ``C`` the vessel's coefficient table (body axes; forces turned to earth axes by the
yaw).  See :func:`floatmoor.forces.kernels.relative_flow_force_into`.

Wind: ``U(t) = U_mean + r(t) u(t)`` at the wind coefficients' reference height, ``u`` the gust
realised from the scene's spectrum (NPD by default) by
:func:`floatmoor.metocean.realise_wind` with frequencies at bin centres on an FFT grid (repeat
period >= the duration), seed stream derived from the run seed; ``r`` the ramp.

Current: the speed at the still-water line (``z = 0``) of the scene's profile, constant in time.
"""

from __future__ import annotations

import math

import numpy as np

from ..core.errors import SceneError
from ..metocean.current import current_speed
from ..metocean.realisation import realise_wind
from ..metocean.wind import wind_mean_speed, wind_spectrum
from .base import ForceModel, KernelAssembly, SetupContext, register
from .kernels import relative_flow_force_into
from .series import complex_envelope, grid_for
from .terms import as_kernel_array

__all__ = ["Wind", "Current", "derived_seed"]

WIND_STREAM = 1


def derived_seed(seed: int, stream: int) -> int:
    """An independent 32-bit seed for stream ``stream`` of a run seed (stream 0 = the seed)."""
    if stream == 0:
        return int(seed)
    return int(np.random.SeedSequence([int(seed), int(stream)]).generate_state(1)[0])


def _table(vessel, attr, what):
    tab = getattr(vessel, attr)
    if tab is None:
        raise SceneError(vessel.file, attr, f"{what} coefficients in the vessel file (the scene "
                         f"has {what}; exclude it in the forces section to run without)")
    return (np.ascontiguousarray(tab.heading, float),
            np.ascontiguousarray(tab.coefficients, float))


class _FlowModel(ForceModel):
    def _tables(self):
        """Writeable copies of the (frozen) coefficient tables: the argument types of the time
        loop's call, so that relative_flow_force_into is compiled once."""
        return as_kernel_array(self.table_heading, float), as_kernel_array(self.table, float)

    def force(self, t, pose, velocity, out, wf_velocity=None):
        """Add the force at time t (s) for the pose and the pose rate ``velocity`` (earth).

        ``wf_velocity`` (6,), optional: the wave-frequency part of ``velocity`` to remove, so that
        the flow is taken relative to the low-frequency velocity (Wang (2016) eq. 2.24, 2.26; the
        solver passes its linear WF velocity, see :mod:`floatmoor.solvers.wf_velocity`)."""
        coef = np.zeros(6)
        vx, vy = float(velocity[0]), float(velocity[1])
        if wf_velocity is not None:
            vx -= float(wf_velocity[0])
            vy -= float(wf_velocity[1])
        relative_flow_force_into(self._speed_at(t), self.heading, vx, vy, float(pose[5]), 1.0,
                                 *self._tables(), coef, out)

    def mean_force(self):
        out = np.zeros(6)
        coef = np.zeros(6)
        relative_flow_force_into(self.mean_speed, self.heading, 0.0, 0.0, 0.0, 1.0,
                                 *self._tables(), coef, out)
        return out

    def damping_linearized(self, yaw: float = 0.0):
        """-dF/dv (6x6) at rest, by central differences of the exact force (N s/m)."""
        D = np.zeros((6, 6))
        th, tab = self._tables()
        for k in (0, 1):
            dv = 1e-4 * max(1.0, self.mean_speed)
            fp = np.zeros(6)
            fm = np.zeros(6)
            v = np.zeros(6)
            v[k] = dv
            coef = np.zeros(6)
            relative_flow_force_into(self.mean_speed, self.heading, v[0], v[1], yaw, 1.0,
                                     th, tab, coef, fp)
            v[k] = -dv
            relative_flow_force_into(self.mean_speed, self.heading, v[0], v[1], yaw, 1.0,
                                     th, tab, coef, fm)
            D[:, k] = -(fp - fm) / (2 * dv)
        return D


@register
class Wind(_FlowModel):
    name = "wind"
    description = "wind (mean + gust), quadratic in the relative velocity"

    def setup(self, ctx: SetupContext):
        spec = ctx.built.scene.environment.wind
        v = ctx.built.vessel
        self.table_heading, self.table = _table(v, "wind_coefficients", "wind")
        ref = v.wind_coefficients.reference_height or spec.reference_height
        mean = float(wind_mean_speed(spec, float(ref)))
        h = ctx.sample_dt
        duration = ctx.n_steps * ctx.dt
        gust = np.zeros(ctx.n_samples)
        if spec.spectrum != "constant" and spec.u10 > 0.0:
            from dataclasses import replace
            spec_ref = replace(spec, reference_height=float(ref))
            # the realisation's default upper frequency, then an FFT grid with bins <= 1/duration
            f_hi = spec.f_max
            if f_hi is None:  # where S(f) falls below 1e-3 of its maximum (as realise_wind)
                f = np.logspace(-5, 1.5, 3000)
                s = wind_spectrum(spec_ref, f)
                f_hi = float(f[np.nonzero(s >= 1e-3 * s.max())[0][-1]])
            f_hi = min(float(f_hi), 0.5 / h)
            grid = grid_for(0.0, 2.0 * math.pi / duration, h, duration)
            n = max(1, int(math.ceil(2.0 * math.pi * f_hi / grid.dw)))
            real = realise_wind(spec_ref, duration=duration, seed=derived_seed(ctx.seed, WIND_STREAM),
                                n_frequencies=n, f_min=0.0, f_max=n * grid.dw / (2.0 * math.pi),
                                random_frequencies=False)
            c = real.amplitude * np.exp(1j * real.phase)
            gust = complex_envelope(real.omega, c, ctx.n_samples, h, grid).real
            mean = float(real.mean)
        ramp = ctx.ramp_series()
        self.heading = float(spec.heading)
        self.mean_speed = mean
        self.speed = np.ascontiguousarray(mean + ramp * gust)
        self.h = h
        self._freeze()

    def _speed_at(self, t):
        return float(self.speed[int(round(t / self.h))])

    def channels(self):
        return ["force", "wind_speed"]

    def contribute(self, asm: KernelAssembly):
        asm.add_relative_flow(self.name, speed=self.speed, heading=self.heading,
                              table_heading=self.table_heading, table=self.table)


@register
class Current(_FlowModel):
    name = "current"
    description = "current, quadratic in the relative velocity"

    def setup(self, ctx: SetupContext):
        scene = ctx.built.scene
        spec = scene.environment.current
        v = ctx.built.vessel
        self.table_heading, self.table = _table(v, "current_coefficients", "current")
        inputs = ctx.inputs  # the scene's rules (double counting, Wang (2016) section 6.1.2)
        if inputs is not None and inputs.current_table is not None:
            self.table = np.ascontiguousarray(inputs.current_table, float)
        self.mean_speed = float(np.asarray(current_speed(spec, np.array([0.0]),
                                                          scene.site.water_depth)).reshape(-1)[0])
        self.heading = float(spec.heading)
        self._freeze()

    def _speed_at(self, t):
        return self.mean_speed

    def contribute(self, asm: KernelAssembly):
        asm.add_relative_flow(self.name, speed=self.mean_speed, heading=self.heading,
                              table_heading=self.table_heading, table=self.table)

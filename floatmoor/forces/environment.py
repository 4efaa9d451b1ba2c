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

Frequency domain (:meth:`_FlowModel.frequency_domain`, the same coefficient tables, speeds and
kernel :func:`~floatmoor.forces.kernels.relative_flow_force_into`): the mean force at rest at
the mean body heading (Wang (2016) eq. 2.39), the damping ``-dF/dv`` of the horizontal
velocity at rest by central differences of that force (LF motion only; Wang (2016) eq. 2.24,
2.26 relative to the LF velocity), and for wind the gust force spectrum ``b b^T S_u(mu)`` with
``b = dF/dU = 2 U C`` along the wind (the scene's gust spectrum at the coefficients' reference
height, as the time domain's realisation).
"""

from __future__ import annotations

import math

import numpy as np

from ..core.errors import SceneError
from ..metocean.current import current_speed
from ..metocean.realisation import realise_wind
from ..metocean.wind import wind_mean_speed, wind_spectrum
from .base import FDContext, FDTerms, ForceModel, KernelAssembly, SetupContext, register
from .kernels import relative_flow_force_into
from .series import complex_envelope, derived_seed, grid_for
from .spectral import gust_force_spectrum
from .terms import as_kernel_array

__all__ = ["Wind", "Current", "derived_seed"]

WIND_STREAM = 1


def _table(vessel, attr, what):
    tab = getattr(vessel, attr)
    if tab is None:
        raise SceneError(vessel.file, attr, f"{what} coefficients in the vessel file (the scene "
                         f"has {what}; exclude it in the forces section to run without)")
    return (np.ascontiguousarray(tab.heading, float),
            np.ascontiguousarray(tab.coefficients, float))


def flow_force(speed: float, heading: float, table_heading, table, *, yaw: float = 0.0,
               vx: float = 0.0, vy: float = 0.0) -> np.ndarray:
    """``C(theta_rel) |U - v|^2`` (6,) (N, N m; earth axes) of a flow of ``speed`` (m/s) towards
    ``heading`` (rad) on a body at heading ``yaw`` moving with (vx, vy) (m/s, earth axes)."""
    out = np.zeros(6)
    coef = np.zeros(6)
    relative_flow_force_into(float(speed), float(heading), float(vx), float(vy), float(yaw),
                             1.0, as_kernel_array(table_heading, float),
                             as_kernel_array(table, float), coef, out)
    return out


def flow_damping(speed: float, heading: float, table_heading, table, *,
                 yaw: float = 0.0) -> np.ndarray:
    """``-dF/dv`` (6, 6) of :func:`flow_force` at rest, columns surge and sway (earth axes), by
    central differences of the exact force (N s/m); zero without flow."""
    D = np.zeros((6, 6))
    if not speed > 0.0:
        return D
    th = as_kernel_array(table_heading, float)
    tab = as_kernel_array(table, float)
    dv = 1e-4 * max(1.0, speed)
    for k in (0, 1):
        v = np.zeros(2)
        v[k] = dv
        fp = flow_force(speed, heading, th, tab, yaw=yaw, vx=v[0], vy=v[1])
        fm = flow_force(speed, heading, th, tab, yaw=yaw, vx=-v[0], vy=-v[1])
        D[:, k] = -(fp - fm) / (2 * dv)
    return D


class _FlowModel(ForceModel):
    def frequency_domain(self, fd: FDContext) -> FDTerms:
        """Mean force at rest at the mean heading; at the mean position also the damping of
        the LF motion and (wind) the gust force spectrum (module docstring)."""
        th, tab, speed, heading = self.flow_inputs(fd.built, fd.inputs)
        mean = flow_force(speed, heading, th, tab, yaw=fd.yaw)
        info = {"mean_speed": speed}
        if not fd.linear:
            return FDTerms(mean_force=mean, info=info)
        spectrum = self._force_spectrum(fd, th, tab, speed, heading)
        return FDTerms(mean_force=mean, lf_damping=flow_damping(speed, heading, th, tab,
                                                                 yaw=fd.yaw),
                       lf_force_spectrum=spectrum, info=info)

    def _force_spectrum(self, fd, th, tab, speed, heading):
        return None

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
        """-dF/dv (6x6) at rest, by central differences of the exact force (N s/m)
        (:func:`flow_damping`)."""
        return flow_damping(self.mean_speed, self.heading, *self._tables(), yaw=yaw)


@register
class Wind(_FlowModel):
    name = "wind"
    description = "wind (mean + gust), quadratic in the relative velocity"

    @classmethod
    def wanted(cls, built, options) -> bool:
        return built.scene.environment.wind is not None

    @staticmethod
    def reference_height(built) -> float:
        """Height (m) of the vessel's wind coefficients (else the scene's wind reference)."""
        return float(built.vessel.wind_coefficients.reference_height
                     or built.scene.environment.wind.reference_height)

    @classmethod
    def flow_inputs(cls, built, inputs=None):
        """(table headings, table, mean speed at the coefficients' height, heading)."""
        spec = built.scene.environment.wind
        th, tab = _table(built.vessel, "wind_coefficients", "wind")
        return th, tab, float(wind_mean_speed(spec, cls.reference_height(built))), \
            float(spec.heading)

    def _force_spectrum(self, fd, th, tab, speed, heading):
        """Gust force spectrum b b^T S_u(mu), b = dF/dU = 2 U C along the wind."""
        from dataclasses import replace
        spec = fd.built.scene.environment.wind
        if speed <= 0.0 or spec.spectrum == "constant":
            return np.zeros((fd.mu.size, 6, 6))
        spec_ref = replace(spec, reference_height=self.reference_height(fd.built))
        s_u = np.asarray(wind_spectrum(spec_ref, fd.mu / (2.0 * math.pi)), float) / (2.0 * math.pi)
        C = flow_force(1.0, heading, th, tab, yaw=fd.yaw)  # C(theta) turned to earth axes
        return gust_force_spectrum(2.0 * speed * C, s_u)

    def setup(self, ctx: SetupContext):
        spec = ctx.built.scene.environment.wind
        self.table_heading, self.table, mean, _ = self.flow_inputs(ctx.built)
        ref = self.reference_height(ctx.built)
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

    @classmethod
    def wanted(cls, built, options) -> bool:
        return built.scene.environment.current is not None

    @classmethod
    def flow_inputs(cls, built, inputs=None):
        """(table headings, table, speed at z = 0, heading); the table of the scene's rules
        (``inputs.current_table``: double counting with slender elements, Wang (2016) section
        6.1.2) when given."""
        scene = built.scene
        spec = scene.environment.current
        th, tab = _table(built.vessel, "current_coefficients", "current")
        if inputs is not None and inputs.current_table is not None:
            tab = np.ascontiguousarray(inputs.current_table, float)
        speed = float(np.asarray(current_speed(spec, np.array([0.0]),
                                               scene.site.water_depth)).reshape(-1)[0])
        return th, tab, speed, float(spec.heading)

    def setup(self, ctx: SetupContext):
        self.table_heading, self.table, self.mean_speed, self.heading = \
            self.flow_inputs(ctx.built, ctx.inputs)
        self._freeze()

    def _speed_at(self, t):
        return self.mean_speed

    def contribute(self, asm: KernelAssembly):
        asm.add_relative_flow(self.name, speed=self.mean_speed, heading=self.heading,
                              table_heading=self.table_heading, table=self.table)

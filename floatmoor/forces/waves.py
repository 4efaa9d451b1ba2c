"""Wave forces: first-order excitation and second-order slow drift (Newman's approximation).

Both are precomputed as time series before the time loop, at the half-step samples the
integrator needs, by FFT (:mod:`floatmoor.forces.series`).  They are evaluated

* at the **mean position** of the body (the origin of the earth frame, where the database's
  phase reference lies): the body's slow horizontal excursion does not shift the wave phase, as
  is common practice in SIMO/aNySIM-type analyses of moored units (the phase error is k x_LF,
  e.g. 0.05 rad for a 7 m offset in 15 s waves);
* for the body heading ``yaw0`` of the static start (the wave headings relative to the body are
  ``direction - yaw0``; body-axis forces are turned to earth axes by ``yaw0``).  A slowly varying
  yaw does not re-interpolate the transfer functions.

Realisation: the scene's sea state is realised by :func:`floatmoor.metocean.realise_waves` with
frequencies at the centres of equal bins of width ``dw = 2 pi / (N h)`` (``h`` = dt/2, ``N`` >=
duration / h): the sum repeats only after N h >= the simulated duration, and every series is an
exact FFT.  The wave seed stream is the run's seed itself, so ``wave_elevation`` equals
``realise_waves(..., seed=seed, random_frequencies=False)`` on the same bins.

First order (eq. 2.23, the 1st-order part of q_wa)::

    F_i(t) = Re sum_k a_k X_i(w_k, beta_k - yaw0) exp(i (w_k t + phi_k))     (exp(+i w t))

Slow drift, Newman (1974): with the mean drift coefficients D_i(w, beta) (N/m^2 per squared
amplitude) and the off-diagonal QTF approximated by T_jk = (D_j + D_k)/2::

    F_i(t) = sum_j sum_k a_j a_k T_jk cos((w_j - w_k) t + phi_j - phi_k)
           = Re[ A_D,i(t) conj(A(t)) ],   A = sum a_k e^{i theta_k},  A_D,i = sum a_k D_i,k e^{i theta_k}

which holds the mean drift ``sum a_k^2 D_k`` and only difference-frequency terms (no sum
frequencies).  Cross-direction terms (spreading, several wave systems) use the same arithmetic
mean.

Several wave systems (:class:`~floatmoor.metocean.config.WaveSystems`): each system is realised
with its own seed stream (the first system the run's seed itself) on one common FFT grid, and
the components of all systems are summed by every force (:func:`wave_components`).

Which drift model a scene gets (:func:`drift_method`): ``forces: drift`` when given, else the
full QTF when the database has one, the sea has one direction and the correction formula is
off, Newman's approximation when the database has mean drift coefficients, else none.

Frequency domain (each model's ``frequency_domain``, on the FD's grid and directions): the
excitation per unit amplitude of every direction (first order); the mean drift
``2 sum_d int C_d S_d dw`` and the slow-drift spectrum of Newman's approximation across the
directions (:func:`floatmoor.forces.spectral.newman_drift_spectrum_directions`) or of the QTF
(one direction; its mean drift from the QTF's diagonal, as the time domain's).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..core.errors import SceneError
from ..hydro.database import interpolate_heading
from ..metocean.config import WaveSpec, wave_systems
from ..metocean.realisation import WAVE_SYSTEM_STREAM, WaveRealisation, realise_waves, system_seed
from ..metocean.spectra import default_omega_range, spreading_directions
from .base import FDContext, FDTerms, ForceModel, KernelAssembly, SetupContext, register
from .series import FrequencyGrid, complex_envelope, grid_for
from .spectral import (
    interp0,
    mean_drift_force,
    newman_drift_spectrum_directions,
    qtf_drift_spectrum,
    qtf_function,
)

__all__ = ["WaveComponents", "wave_components", "FirstOrderWave", "DriftNewman", "DriftQTF",
           "qtf_pair_sum", "drift_method", "fd_drift_coefficients", "sea_is_unidirectional",
           "body_axes_to_earth", "transfer_at", "WAVE_SYSTEM_STREAM"]




@dataclass(frozen=True, eq=False)
class WaveComponents:
    """The wave components of one run and the grid they lie on (grid None: direct sums)."""

    realisation: WaveRealisation
    grid: FrequencyGrid | None

    @property
    def omega(self):
        return self.realisation.omega

    def coefficients(self) -> np.ndarray:
        """a_k exp(i phi_k), complex (n,)."""
        r = self.realisation
        return r.amplitude * np.exp(1j * r.phase)

    def elevation(self, n_samples: int, h: float) -> np.ndarray:
        """Elevation (m) at the origin at t = j h, j < n_samples."""
        return complex_envelope(self.omega, self.coefficients(), n_samples, h, self.grid).real


def wave_components(spec, *, duration: float, seed: int, h: float, water_depth: float,
                    gravity: float) -> WaveComponents:
    """Realise the sea ``spec`` (a :class:`~floatmoor.metocean.config.WaveSpec`, or several
    systems, :class:`~floatmoor.metocean.config.WaveSystems`) on an FFT grid with sampling step
    ``h`` (s) (see the module docstring).

    Several systems share one grid: its bins start at the lowest system's lower frequency, its
    step is at most 2 pi / duration (or the sea's ``n_frequencies`` over the whole band), and
    each system is realised over the bins that cover its own band, with its own seed stream
    (system k >= 1: :data:`WAVE_SYSTEM_STREAM` + k)."""
    systems = wave_systems(spec)
    if len(systems) == 1:
        return _single_system_components(systems[0], duration=duration, seed=seed, h=h,
                                         water_depth=water_depth, gravity=gravity)
    bands = [_band(s) for s in systems]
    lo = min(b[0] for b in bands)
    hi = max(b[1] for b in bands)
    n_freq = getattr(spec, "n_frequencies", None)
    if n_freq is not None:
        grid = grid_for(lo, (hi - lo) / int(n_freq), h, 0.0)
    else:
        grid = grid_for(lo, 2.0 * math.pi / duration, h, duration)
    parts = []
    for k, (sys_k, (lo_k, hi_k)) in enumerate(zip(systems, bands)):
        i0 = int(math.floor((lo_k - lo) / grid.dw + 1e-9))
        i1 = max(i0 + 1, int(math.ceil((hi_k - lo) / grid.dw - 1e-9)))
        parts.append(realise_waves(sys_k, duration=duration,
                                   seed=system_seed(seed, k),
                                   water_depth=water_depth, n_frequencies=i1 - i0,
                                   omega_min=lo + i0 * grid.dw, omega_max=lo + i1 * grid.dw,
                                   random_frequencies=False, g=gravity))
    real = WaveRealisation(
        omega=np.concatenate([r.omega for r in parts]),
        amplitude=np.concatenate([r.amplitude for r in parts]),
        phase=np.concatenate([r.phase for r in parts]),
        direction=np.concatenate([r.direction for r in parts]),
        k=np.concatenate([r.k for r in parts]), water_depth=parts[0].water_depth,
        domega=grid.dw, spec=None, seed=int(seed), duration=float(duration))
    return WaveComponents(realisation=real, grid=grid)


def _band(spec: WaveSpec) -> tuple[float, float]:
    """The frequency band (rad/s) of a system: its discretisation's, else the default."""
    lo_d, hi_d = default_omega_range(spec)
    lo = lo_d if spec.omega_min is None else float(spec.omega_min)
    hi = hi_d if spec.omega_max is None else float(spec.omega_max)
    if not 0.0 < lo < hi:
        raise SceneError(None, "waves.omega_min/omega_max", "0 < omega_min < omega_max (rad/s)",
                         (lo, hi))
    return lo, hi


def _single_system_components(spec, *, duration, seed, h, water_depth, gravity):
    lo, hi = _band(spec)
    if spec.n_frequencies is not None:
        dw_max = (hi - lo) / int(spec.n_frequencies)
        grid = grid_for(lo, dw_max, h, 0.0)
    else:
        grid = grid_for(lo, 2.0 * math.pi / duration, h, duration)
    n = max(1, int(math.ceil((hi - lo) / grid.dw - 1e-9)))
    if spec.n_frequencies is not None:
        n = int(spec.n_frequencies)
    real = realise_waves(spec, duration=duration, seed=seed, water_depth=water_depth,
                         n_frequencies=n, omega_min=lo, omega_max=lo + n * grid.dw,
                         random_frequencies=False, g=gravity)
    return WaveComponents(realisation=real, grid=grid)


def sea_is_unidirectional(waves) -> bool:
    """True when every component of the sea ``waves`` travels in one direction (the systems
    share their heading and none is spread)."""
    dirs = set()
    for s in wave_systems(waves):
        d, _ = spreading_directions(s)
        dirs.update(round(math.remainder(float(b), 2.0 * math.pi), 9) for b in d)
    return len(dirs) <= 1


def drift_method(built, options) -> str:
    """The drift model a scene gets: ``qtf``, ``newman`` or ``none`` (module docstring).  The
    correction formula with ``drift: qtf`` is a SceneError
    (:func:`floatmoor.forces.slender.refuse_qtf_with_correction`)."""
    from .slender import refuse_qtf_with_correction
    waves = built.scene.environment.waves
    if waves is None:
        return "none"
    db = built.vessel.database
    drift = getattr(options, "drift", None)
    correction = refuse_qtf_with_correction(getattr(options, "viscous_drift", None), drift,
                                            file=getattr(options, "file", None),
                                            key="forces.drift")
    if drift is not None:
        return drift
    if "difference_frequency_qtf" in db and not correction and sea_is_unidirectional(waves):
        return "qtf"
    if "mean_drift_force" in db:
        return "newman"
    return "none"


def transfer_at(db, variable: str, omega, direction, *, file=None) -> np.ndarray:
    """``db[variable]`` (dims omega, wave_direction, influenced_dof) at the components'
    (omega_k, direction_k): (n, 6), linear in heading and in omega, zero outside the database's
    frequency range (with a SceneError if a component with significant energy falls outside)."""
    omega = np.asarray(omega, float)
    direction = np.asarray(direction, float)
    w_db = np.asarray(db["omega"].values, float)
    out = np.zeros((omega.size, 6), complex if variable == "excitation_force" else float)
    for beta in np.unique(direction):
        sel = direction == beta
        tab = _at_heading(db, variable, float(beta), file)  # (n_omega, 6)
        for d in range(6):
            if np.iscomplexobj(tab):
                out[sel, d] = (np.interp(omega[sel], w_db, tab[:, d].real, left=0.0, right=0.0)
                               + 1j * np.interp(omega[sel], w_db, tab[:, d].imag, left=0.0,
                                                right=0.0))
            else:
                out[sel, d] = np.interp(omega[sel], w_db, tab[:, d], left=0.0, right=0.0)
    return out


def _at_heading(db, variable: str, beta: float, file, dim: str = "wave_direction"):
    """``db[variable]`` at heading ``beta``: the database's own slice when the heading is one
    of its headings, else linear interpolation.  NaN (not computed, e.g. below a QTF grid) is
    taken as 0; a heading where the quantity is NaN at every frequency is a SceneError."""
    heads = np.asarray(db[dim].values, float)
    diff = np.abs(np.angle(np.exp(1j * (heads - beta))))
    if diff.min() < 1e-9:
        tab = db[variable].isel({dim: int(np.argmin(diff))}).values
    else:
        try:
            tab = interpolate_heading(db, variable, beta, dim=dim)
        except Exception as exc:  # DatabaseError: heading not covered
            raise SceneError(file, f"{variable} at wave heading {math.degrees(beta):.1f} deg",
                             "a heading inside the database's range", str(exc)) from None
    tab = np.asarray(tab)
    if np.all(np.isnan(tab)):
        raise SceneError(file, f"{variable} at wave heading {math.degrees(beta):.1f} deg",
                         "values at that heading (the database has NaN there)")
    return np.nan_to_num(tab)


def body_axes_to_earth(f: np.ndarray, yaw: float) -> np.ndarray:
    """Turn (..., 6) body-axis generalized forces into earth axes by the heading ``yaw``."""
    c, s = math.cos(yaw), math.sin(yaw)
    out = np.array(f, copy=True)
    for a, b in ((0, 1), (3, 4)):
        out[..., a] = c * f[..., a] - s * f[..., b]
        out[..., b] = s * f[..., a] + c * f[..., b]
    return out


def fd_drift_coefficients(fd: FDContext, db) -> np.ndarray:
    """(n_dir, n, 6) mean drift coefficients C_wa(w) of every direction of ``fd`` on its WF
    grid, earth axes at the mean heading, zero outside the database's frequencies; NaN taken as
    zero, with a warning where it holds more than 1 % of a direction's wave energy."""
    w_db = np.asarray(db["omega"].values, float)
    T = fd.rotation
    out = np.zeros((fd.directions.size, fd.omega.size, 6))
    for d, beta in enumerate(fd.directions):
        c = interpolate_heading(db, "mean_drift_force", float(beta) - fd.yaw)  # (n_db, 6)
        if np.any(np.isnan(c)):
            bad = np.isnan(c).any(axis=1)
            S = fd.spectra[d]
            frac = float(np.trapezoid(np.where(interp0(fd.omega, w_db, bad.astype(float)) > 0,
                                               S, 0), fd.omega)
                         / max(np.trapezoid(S, fd.omega), 1e-300))
            if frac > 0.01:
                fd.warn(f"mean_drift_force is NaN where {100 * frac:.1f} % of the wave energy "
                        "lies; taken as zero there")
            c = np.nan_to_num(c)
        out[d] = interp0(fd.omega, w_db, c) @ T.T
    return out


def _check_range(comp: WaveComponents, db, vessel_file, what: str):
    w_db = np.asarray(db["omega"].values, float)
    r = comp.realisation
    e = r.amplitude ** 2
    outside = (r.omega < w_db[0]) | (r.omega > w_db[-1])
    frac = e[outside].sum() / max(e.sum(), 1e-300)
    if frac > 0.01:
        raise SceneError(vessel_file, "database",
                         f"{what} over the sea state's frequencies {r.omega.min():.3f}-"
                         f"{r.omega.max():.3f} rad/s", f"{w_db[0]:.3f}-{w_db[-1]:.3f} rad/s "
                         f"({100 * frac:.1f} % of the wave energy outside)")


class _SeriesModel(ForceModel):
    """A force precomputed as a time series (n_samples, 6) at the half-step samples."""

    def force(self, t, pose, velocity, out):
        j = int(round(t / self.h))
        if not 0 <= j < self.series.shape[0] or abs(j * self.h - t) > 1e-9 * max(1.0, t):
            raise ValueError(f"{self.name}: t = {t} s is not a sample time (step {self.h} s)")
        out += self.series[j]

    def contribute(self, asm: KernelAssembly):
        asm.add_series(self.name, self.series)

    def mean_force(self):
        return self._mean.copy()


@register
class FirstOrderWave(_SeriesModel):
    """First-order wave excitation from the database's excitation transfer functions."""

    name = "wave1"
    description = "first-order wave excitation (transfer functions x wave realisation)"

    @classmethod
    def wanted(cls, built, options) -> bool:
        return built.scene.environment.waves is not None

    def frequency_domain(self, fd: FDContext) -> FDTerms:
        """The excitation per unit amplitude of every direction of ``fd`` on its grid, at the
        heading relative to the mean body heading, earth axes (Wang (2016) eq. 2.40)."""
        if not (fd.linear and fd.has_waves):
            return FDTerms()
        v = fd.built.vessel
        db = v.database
        if "excitation_force" not in db:
            raise SceneError(v.file, "database", "a database with excitation_force for waves")
        w_db = np.asarray(db["omega"].values, float)
        T = fd.rotation
        X = np.zeros((fd.directions.size, fd.omega.size, 6), complex)
        for d, beta in enumerate(fd.directions):
            Xd = interpolate_heading(db, "excitation_force", float(beta) - fd.yaw)  # (n_db, 6)
            X[d] = interp0(fd.omega, w_db, Xd) @ T.T
        return FDTerms(wf_excitation=X)

    def setup(self, ctx: SetupContext):
        v = ctx.built.vessel
        comp = ctx.waves
        db = v.database
        if "excitation_force" not in db:
            raise SceneError(v.file, "database", "a database with excitation_force for waves")
        _check_range(comp, db, v.file, "excitation_force")
        r = comp.realisation
        X = transfer_at(db, "excitation_force", r.omega, r.direction - ctx.yaw0, file=v.file)
        c = comp.coefficients()[:, None] * X
        f = complex_envelope(r.omega, c, ctx.n_samples, ctx.sample_dt, comp.grid).real
        f = body_axes_to_earth(f, ctx.yaw0) * ctx.ramp_series()[:, None]
        self.h = ctx.sample_dt
        self.series = np.ascontiguousarray(f)
        self._mean = np.zeros(6)
        self._freeze()


@register
class DriftNewman(_SeriesModel):
    """Mean and slowly varying wave drift by Newman's approximation (module docstring)."""

    name = "drift_newman"
    description = "mean + slow wave drift, Newman's approximation of the mean drift coefficients"

    @classmethod
    def wanted(cls, built, options) -> bool:
        return drift_method(built, options) == "newman"

    @staticmethod
    def _database(v, inputs):
        db = v.database if inputs is None or inputs.drift_database is None \
            else inputs.drift_database
        if "mean_drift_force" not in db:
            raise SceneError(v.file, "database", "a database with mean_drift_force for the "
                             "drift model (or exclude drift in the forces section)")
        return db

    def frequency_domain(self, fd: FDContext) -> FDTerms:
        """Mean drift ``2 sum_d int C_d S_d dw`` (eq. 2.37) and, at the mean position, the
        slow-drift force spectrum of Newman's approximation over all pairs of directions
        (eq. 2.38, :func:`~floatmoor.forces.spectral.newman_drift_spectrum_directions`); the
        coefficients those of the scene's rules (correction formula at the mean heading)."""
        if not fd.has_waves:
            return FDTerms()
        db = self._database(fd.built.vessel, fd.inputs)
        C = fd_drift_coefficients(fd, db)
        mean = mean_drift_force(fd.omega, fd.spectra[0], C[0])
        for d in range(1, fd.directions.size):
            mean = mean + mean_drift_force(fd.omega, fd.spectra[d], C[d])
        info = {"drift_method": "newman"}
        if not fd.linear:
            return FDTerms(mean_force=mean, info=info)
        S = newman_drift_spectrum_directions(fd.omega, fd.spectra, C, fd.mu)
        return FDTerms(mean_force=mean, lf_force_spectrum=S, info=info)

    def setup(self, ctx: SetupContext):
        v = ctx.built.vessel
        comp = ctx.waves
        # the scene's rules (correction formula, Wang (2016) eq. 6.6)
        db = self._database(v, ctx.inputs)
        _check_range(comp, db, v.file, "mean_drift_force")
        r = comp.realisation
        D = transfer_at(db, "mean_drift_force", r.omega, r.direction - ctx.yaw0, file=v.file)
        a = comp.coefficients()
        if comp.grid is not None:
            A = complex_envelope(r.omega, a[:, None], ctx.n_samples, ctx.sample_dt, comp.grid,
                                 carrier=False)
            AD = complex_envelope(r.omega, a[:, None] * D, ctx.n_samples, ctx.sample_dt,
                                  comp.grid, carrier=False)
        else:
            A = complex_envelope(r.omega, a[:, None], ctx.n_samples, ctx.sample_dt)
            AD = complex_envelope(r.omega, a[:, None] * D, ctx.n_samples, ctx.sample_dt)
        f = (AD * np.conj(A)).real
        mean = np.sum(r.amplitude[:, None] ** 2 * D, axis=0)
        f = body_axes_to_earth(f, ctx.yaw0)
        mean = body_axes_to_earth(mean, ctx.yaw0)
        # ramp the fluctuation only: the run starts in equilibrium with the mean drift
        ramp = ctx.ramp_series()[:, None]
        f = mean + ramp * (f - mean)
        self.h = ctx.sample_dt
        self.series = np.ascontiguousarray(f)
        self._mean = mean
        self._freeze()


def qtf_pair_sum(idx: np.ndarray, A: np.ndarray, q_omega: np.ndarray, Q: np.ndarray,
                 omega: np.ndarray, n_diff: int) -> np.ndarray:
    """Coefficients of the difference-frequency force on the grid, per difference index.

    ``idx`` (n,) grid indices of the components (increasing), ``A`` (n,) complex amplitudes
    a e^{i phi}, ``Q`` (n_q, n_q, 6) complex QTF on ``q_omega`` (both axes), ``omega`` (n,).
    Returns ``c`` (n_diff, 6) complex with ``F(t) = Re sum_d c_d exp(i d dw t)`` equal to
    ``Re sum_j sum_k A_j conj(A_k) Q(w_j, w_k) exp(i (w_j - w_k) t)`` over all ordered pairs
    (Q Hermitian: the pairs j < k are folded onto j > k, doubling them).  Q is bilinear in
    both frequencies and zero outside its grid.
    """
    n = omega.size
    nq = q_omega.size
    pos = np.interp(omega, q_omega, np.arange(nq), left=-1.0, right=-1.0)
    inside = pos >= 0.0
    i0 = np.clip(np.floor(pos).astype(np.int64), 0, nq - 2)
    fr = np.clip(pos - i0, 0.0, 1.0)
    out = np.zeros((n_diff, 6), complex)
    for d in range(n):
        j = np.arange(d, n)            # component j = k + d (higher frequency)
        k = j - d
        shift = idx[j] - idx[k]
        ok = inside[j] & inside[k] & (shift < n_diff)
        if not ok.any():
            continue
        j, k, shift = j[ok], k[ok], shift[ok]
        a, b = i0[j], i0[k]
        u, w = fr[j][:, None], fr[k][:, None]
        q = ((1 - u) * (1 - w) * Q[a, b] + u * (1 - w) * Q[a + 1, b] + (1 - u) * w * Q[a, b + 1]
             + u * w * Q[a + 1, b + 1])
        prod = (A[j] * np.conj(A[k]))[:, None] * q
        if d > 0:
            prod = 2.0 * prod
        np.add.at(out, shift, prod)
    return out


@register
class DriftQTF(_SeriesModel):
    """Mean and slowly varying drift from the database's full difference-frequency QTF.

    ``F_i(t) = Re sum_j sum_k A_j conj(A_k) Q_i(w_j, w_k) exp(i (w_j - w_k) t)`` over the wave
    components (all ordered pairs; ``Q(w, w)`` is the mean drift coefficient), evaluated by FFT
    over the difference frequencies (:func:`qtf_pair_sum`).  Unidirectional seas only (the
    database holds QTFs for one heading per entry; bidirectional QTFs are not modelled).
    """

    name = "drift_qtf"
    description = "mean + slow wave drift from the full difference-frequency QTF"

    @classmethod
    def wanted(cls, built, options) -> bool:
        return drift_method(built, options) == "qtf"

    def frequency_domain(self, fd: FDContext) -> FDTerms:
        """Mean drift ``2 int Q(w, w) S dw`` (the QTF's diagonal, as the time domain's) and, at
        the mean position, the slow-drift spectrum of the full QTF (one direction)."""
        if not fd.has_waves:
            return FDTerms()
        v = fd.built.vessel
        db = v.database
        if "difference_frequency_qtf" not in db:
            raise SceneError(v.file, "database", "a difference_frequency_qtf for drift: qtf "
                             "(or drift: newman)")
        if fd.directions.size != 1:
            raise SceneError(None, "environment.waves", "a unidirectional sea for the QTF drift "
                             "model (use drift: newman with spreading or several directions)",
                             f"{fd.directions.size} directions")
        q = qtf_function(db, float(fd.directions[0]) - fd.yaw, fd.rotation)
        S = fd.spectra[0]
        mean = mean_drift_force(fd.omega, S, np.real(q(fd.omega, fd.omega)))
        info = {"drift_method": "qtf"}
        if not fd.linear:
            return FDTerms(mean_force=mean, info=info)
        return FDTerms(mean_force=mean, lf_force_spectrum=qtf_drift_spectrum(fd.omega, S, q, fd.mu),
                       info=info)

    def setup(self, ctx: SetupContext):
        v = ctx.built.vessel
        comp = ctx.waves
        db = v.database
        if "difference_frequency_qtf" not in db:
            raise SceneError(v.file, "database", "a difference_frequency_qtf for drift: qtf "
                             "(or drift: newman)")
        r = comp.realisation
        dirs = np.unique(r.direction)
        if dirs.size != 1:
            raise SceneError(None, "environment.waves.spreading", "a unidirectional sea for "
                             "the QTF drift model (use drift: newman with spreading)",
                             f"{dirs.size} directions")
        if comp.grid is None:
            raise SceneError(None, "waves", "wave components on an FFT grid for drift: qtf")
        Q = _at_heading(db, "difference_frequency_qtf", float(dirs[0] - ctx.yaw0), v.file,
                        dim="qtf_wave_direction")
        q_omega = np.asarray(db["qtf_omega"].values, float)
        if not np.allclose(q_omega, db["qtf_omega_2"].values):
            raise SceneError(v.file, "database", "the same frequencies on both QTF axes")
        grid = comp.grid
        idx = np.rint((r.omega - grid.w0) / grid.dw).astype(np.int64)
        A = comp.coefficients()
        omega = r.omega
        order = np.argsort(idx, kind="stable")  # several systems: by frequency (pair sum)
        if np.any(order != np.arange(order.size)):
            idx, A, omega = idx[order], A[order], omega[order]
        n_diff = min(grid.N, int(idx.max() - idx.min()) + 1)
        c = qtf_pair_sum(idx, A, q_omega, Q, omega, n_diff)
        C = np.zeros((grid.N, 6), complex)
        C[:n_diff] = c
        f = (np.fft.ifft(C, axis=0) * grid.N).real
        j = np.arange(ctx.n_samples) % grid.N
        f = f[j]
        mean = c[0].real.copy()
        f = body_axes_to_earth(f, ctx.yaw0)
        mean = body_axes_to_earth(mean, ctx.yaw0)
        ramp = ctx.ramp_series()[:, None]
        f = mean + ramp * (f - mean)
        self.h = ctx.sample_dt
        self.series = np.ascontiguousarray(f)
        self._mean = mean
        self._freeze()

"""Irregular realisations of waves and wind gust: sums of cosines from a spectrum.

A realisation is a small frozen object holding plain read-only arrays, which the force models
sample (``elevation``, ``kinematics``, ``speed``) or copy into their own kernels.

Frequency discretisation (the choice, and why the series does not repeat)
--------------------------------------------------------------------------
The frequency range [w_min, w_max] is cut into N equal bins of width dw.  By default

* N = ceil((w_max - w_min) * duration / (2 pi)), so that dw <= 2 pi / duration: even an equally
  spaced discretisation would have its repetition period 2 pi / dw >= the simulation length;
* each component frequency is drawn uniformly at random *inside* its bin
  (``random_frequencies=True``), so the frequencies are incommensurate and the sum never repeats
  exactly; at the lag 2 pi / dw the phase shift of every component is uniform on (-pi, pi), so
  the series is uncorrelated with itself there (tested).

The amplitude of the component in bin i is a_i = sqrt(2 S(w_i) dw) (the deterministic-amplitude
method), or, with ``random_amplitudes``, Rayleigh distributed with E[a_i^2] = 2 S(w_i) dw (which
makes the elevation exactly Gaussian).  Phases are uniform on [0, 2 pi).  With directional
spreading every frequency bin carries one component per direction with weight w_j
(a_ij = sqrt(2 S(w_i) dw w_j)) and an independent phase.

Spectral cut-offs: by default w_min and w_max bound the interval outside of which S(w) stays
below 1e-3 of its peak (:func:`floatmoor.metocean.spectra.default_omega_range`); for the
Heidrun 100-year sea state this is 0.204 ... 1.590 rad/s and leaves out 0.24 % of m0.  Wind:
f from 0 to the frequency where S(f) falls below 1e-3 of its maximum, in bins of width
<= 1/duration (NPD at 36 m/s: 0-0.741 Hz, 8009 components for 3 hours).  The NPD spectrum
decays only as f^-5/3, so this band holds 30.6 of its 35.6 m^2/s^2 (gust std 5.53 instead of
5.97 m/s; the NPD turbulence-intensity formula itself gives 0.153 * 36 = 5.50 m/s); the energy
above 0.74 Hz has no effect on the slow drift of a moored unit.  Both ranges may be set in the
spec or as arguments.

Random numbers: ``numpy.random.default_rng(seed)``, drawn in a fixed order (frequencies, phases,
then amplitudes), so the same seed and inputs give a bit-identical series.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from numba import njit

from floatmoor.core.constants import GRAVITY, RHO_WATER
from floatmoor.core.errors import SceneError
from floatmoor.metocean.config import WaveSpec, WindSpec
from floatmoor.metocean.kinematics import (
    airy_kinematics,
    airy_kinematics_into,
    surface_elevation_into,
    wavenumber,
)
from floatmoor.metocean.spectra import (
    default_omega_range,
    spectrum_gamma,
    spreading_directions,
    wave_spectrum,
)
from floatmoor.metocean.wind import wind_mean_speed, wind_spectrum

__all__ = ["WaveRealisation", "WindRealisation", "realise_waves", "realise_wind",
           "cosine_sum_uniform_into", "SPECTRAL_CUTOFF", "derived_seed", "system_seed",
           "WAVE_SYSTEM_STREAM"]

SPECTRAL_CUTOFF = 1e-3
"""Default cut-off: components are kept where S exceeds this fraction of its maximum."""

_RESYNC = 256

WAVE_SYSTEM_STREAM = 100
"""Seed stream of wave system k >= 1 of a sea is ``WAVE_SYSTEM_STREAM + k`` (system 0: the run's
seed itself, so a sea of one system is realised as before)."""


def derived_seed(seed: int, stream: int) -> int:
    """An independent 32-bit seed for stream ``stream`` of a run seed (stream 0 = the seed)."""
    if stream == 0:
        return int(seed)
    return int(np.random.SeedSequence([int(seed), int(stream)]).generate_state(1)[0])


def system_seed(seed: int, k: int) -> int:
    """The seed of wave system ``k`` (0, 1, ...) of a run seed (:data:`WAVE_SYSTEM_STREAM`)."""
    return derived_seed(seed, 0 if k == 0 else WAVE_SYSTEM_STREAM + k)


@njit(cache=True)
def cosine_sum_uniform_into(omega, amplitude, phase, t0, dt, work, out):
    """out[n] += sum_i a_i cos(w_i (t0 + n dt) + phi_i) on a uniform time grid.

    Uses the rotation recurrence for a_i cos/sin of successive steps (no trigonometric call
    per step), re-synchronised with exact cos/sin every 256 steps (error ~1e-13 relative to the
    amplitude sum).  ``work`` is a (4, n_components) scratch array.  Adds into ``out`` (zero it
    first).
    """
    nt = out.shape[0]
    m = omega.shape[0]
    c = work[0]
    s = work[1]
    cd = work[2]
    sd = work[3]
    for i in range(m):
        cd[i] = math.cos(omega[i] * dt)
        sd[i] = math.sin(omega[i] * dt)
    for n in range(nt):
        if n % _RESYNC == 0:
            for i in range(m):
                arg = omega[i] * (t0 + n * dt) + phase[i]
                c[i] = amplitude[i] * math.cos(arg)
                s[i] = amplitude[i] * math.sin(arg)
        acc = 0.0
        for i in range(m):
            ci = c[i]
            si = s[i]
            acc += ci
            c[i] = ci * cd[i] - si * sd[i]
            s[i] = si * cd[i] + ci * sd[i]
        out[n] += acc


def _readonly(a) -> np.ndarray:
    a = np.ascontiguousarray(a, dtype=float)
    a.setflags(write=False)
    return a


def _check_duration(duration) -> float:
    try:
        d = float(duration)
    except (TypeError, ValueError):
        raise SceneError(None, "analysis.duration", "a number > 0 (s)", duration) from None
    if not math.isfinite(d) or d <= 0.0:
        raise SceneError(None, "analysis.duration", "a number > 0 (s)", duration)
    return d


def _check_seed(seed) -> int:
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
        raise SceneError(None, "analysis.seeds", "a non-negative integer seed", seed)
    return int(seed)


def _time_array(t) -> np.ndarray:
    ta = np.asarray(t, dtype=float)
    if np.any(~np.isfinite(ta)):
        raise SceneError(None, "t", "finite times (s)", t)
    return ta


def _bins(lo: float, hi: float, n: int, rng, random_frequencies: bool):
    edges = np.linspace(lo, hi, n + 1)
    width = np.diff(edges)
    if random_frequencies:
        centre = edges[:-1] + width * rng.uniform(size=n)
    else:
        centre = 0.5 * (edges[:-1] + edges[1:])
    return centre, width


# --------------------------------------------------------------------------- waves

@dataclass(frozen=True, eq=False)
class WaveRealisation:
    """An irregular sea: components ``eta = sum a cos(w t - k (x cos b + y sin b) + phi)``.

    Attributes (read-only arrays of equal length n): ``omega`` (rad/s), ``amplitude`` (m),
    ``phase`` (rad), ``direction`` (rad, direction of travel), ``k`` (rad/m);
    ``water_depth`` (m, inf for deep water), ``domega`` (rad/s, bin width), plus the
    ``spec``, ``seed`` and ``duration`` (s) it was made for.
    """

    omega: np.ndarray
    amplitude: np.ndarray
    phase: np.ndarray
    direction: np.ndarray
    k: np.ndarray
    water_depth: float
    domega: float
    spec: WaveSpec | None = None
    seed: int | None = None
    duration: float | None = None
    gamma: float | None = None
    cos_dir: np.ndarray = field(init=False, repr=False)
    sin_dir: np.ndarray = field(init=False, repr=False)

    def __post_init__(self):
        for name in ("omega", "amplitude", "phase", "direction", "k"):
            object.__setattr__(self, name, _readonly(getattr(self, name)))
        n = self.omega.size
        if any(getattr(self, a).shape != (n,) for a in ("amplitude", "phase", "direction", "k")):
            raise ValueError("omega, amplitude, phase, direction and k must be 1-D of equal length")
        object.__setattr__(self, "cos_dir", _readonly(np.cos(self.direction)))
        object.__setattr__(self, "sin_dir", _readonly(np.sin(self.direction)))

    @property
    def n_components(self) -> int:
        """Number of cosine components."""
        return int(self.omega.size)

    @property
    def m0(self) -> float:
        """Variance of the realised elevation process, sum a^2/2 (m^2)."""
        return float(0.5 * np.sum(self.amplitude ** 2))

    @property
    def hs(self) -> float:
        """4 sqrt(m0) of the discretised spectrum (m)."""
        return 4.0 * math.sqrt(self.m0)

    def elevation(self, t, x: float = 0.0, y: float = 0.0) -> np.ndarray:
        """Surface elevation (m) at (x, y) (m) and times ``t`` (s), same shape as ``t``."""
        ta = _time_array(t)
        flat = np.ascontiguousarray(ta.ravel())
        out = np.empty_like(flat)
        surface_elevation_into(self.omega, self.amplitude, self.phase, self.k * self.cos_dir,
                               self.k * self.sin_dir, flat, float(x), float(y), out)
        return out.reshape(ta.shape)

    def elevation_series(self, n: int, dt: float, t0: float = 0.0, x: float = 0.0,
                         y: float = 0.0) -> np.ndarray:
        """Elevation (m) at (x, y) on the uniform grid t0 + i dt, i < n (fast recurrence)."""
        out = np.zeros(int(n))
        phase = self.phase - self.k * (self.cos_dir * float(x) + self.sin_dir * float(y))
        work = np.empty((4, self.omega.size))
        cosine_sum_uniform_into(self.omega, self.amplitude, phase, float(t0), float(dt), work, out)
        return out

    def kinematics(self, t, points, *, wheeler: bool = True, g: float = GRAVITY,
                   rho: float = RHO_WATER) -> dict:
        """Airy kinematics at ``points`` (m, 3) and times ``t`` (s).

        See :func:`floatmoor.metocean.kinematics.airy_kinematics` (velocity, acceleration,
        dynamic pressure, eta).
        """
        depth = None if math.isinf(self.water_depth) else self.water_depth
        return airy_kinematics(self.omega, self.amplitude, self.phase, self.k, self.direction, t,
                               points, water_depth=depth, wheeler=wheeler, g=g, rho=rho)

    def kinematics_work(self) -> np.ndarray:
        """A scratch array of the shape :meth:`kinematics_into` needs, (3, n_components)."""
        return np.empty((3, self.n_components))

    def kinematics_into(self, t: float, points, work, velocity, acceleration, pressure, eta, *,
                        wheeler: bool = True, g: float = GRAVITY, rho: float = RHO_WATER):
        """Allocation-free kinematics at one time into preallocated outputs.

        ``points`` (m, 3); ``work`` from :meth:`kinematics_work`; outputs ``velocity`` and
        ``acceleration`` (m, 3), ``pressure`` and ``eta`` (m,).  Shapes are checked here because
        the kernel does not bounds-check; a time loop may call the kernel directly instead.
        """
        m = points.shape[0]
        if (work.shape != (3, self.n_components) or points.shape != (m, 3)
                or velocity.shape != (m, 3) or acceleration.shape != (m, 3)
                or pressure.shape != (m,) or eta.shape != (m,)):
            raise ValueError("kinematics_into: work (3, n_components), points/velocity/"
                             "acceleration (m, 3), pressure/eta (m,) expected")
        airy_kinematics_into(self.omega, self.amplitude, self.phase, self.k, self.cos_dir,
                             self.sin_dir, float(self.water_depth), float(g), float(rho),
                             bool(wheeler), float(t), points, work, velocity, acceleration,
                             pressure, eta)


def realise_waves(spec: WaveSpec, *, duration: float, seed: int, water_depth: float | None = None,
                  n_frequencies: int | None = None, omega_min: float | None = None,
                  omega_max: float | None = None, random_frequencies: bool = True,
                  random_amplitudes: bool | None = None, cutoff: float = SPECTRAL_CUTOFF,
                  g: float = GRAVITY) -> WaveRealisation:
    """Realise the sea state ``spec`` as a sum of cosines.

    Parameters
    ----------
    spec : WaveSpec
        Sea state.  Its ``omega_min``, ``omega_max``, ``n_frequencies`` and
        ``random_amplitudes`` are used unless overridden by the arguments.
    duration : float
        Simulation length (s) the discretisation must not repeat within.
    seed : int
        Seed of ``numpy.random.default_rng``.
    water_depth : float or None
        Water depth (m) for the dispersion relation; None: deep water.
    n_frequencies : int, optional
        Number of frequency bins (default: see module docstring).
    omega_min, omega_max : float, optional
        Frequency range (rad/s) (default: spectral cut-off).
    random_frequencies : bool
        Draw each frequency uniformly inside its bin (default True).
    random_amplitudes : bool, optional
        Rayleigh amplitudes (default: ``spec.random_amplitudes``).
    cutoff : float
        Fraction of the spectral peak that defines the default range.

    Returns
    -------
    WaveRealisation
    """
    duration = _check_duration(duration)
    seed = _check_seed(seed)
    directions, weights = spreading_directions(spec)
    gamma = spectrum_gamma(spec)
    wave_spectrum(spec, np.array([1.0]))  # validates name, hs, tp, gamma
    lo_d, hi_d = default_omega_range(spec, cutoff)
    lo = spec.omega_min if omega_min is None else omega_min
    hi = spec.omega_max if omega_max is None else omega_max
    lo = lo_d if lo is None else float(lo)
    hi = hi_d if hi is None else float(hi)
    if not (0.0 < lo < hi and math.isfinite(hi)):
        raise SceneError(None, "waves.omega_min/omega_max", "0 < omega_min < omega_max (rad/s)",
                         (lo, hi))
    n = spec.n_frequencies if n_frequencies is None else n_frequencies
    if n is None:
        n = max(16, int(math.ceil((hi - lo) * duration / (2.0 * math.pi))))
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 1:
        raise SceneError(None, "waves.n_frequencies", "an integer >= 1", n)
    n = int(n)
    rand_amp = spec.random_amplitudes if random_amplitudes is None else bool(random_amplitudes)

    rng = np.random.default_rng(seed)
    w, dw = _bins(lo, hi, n, rng, random_frequencies)
    s = wave_spectrum(spec, w)
    nd = directions.size
    phase = rng.uniform(0.0, 2.0 * np.pi, size=(n, nd))
    var = s[:, None] * dw[:, None] * weights[None, :]  # S dw w_j
    if rand_amp:
        amp = rng.rayleigh(scale=np.sqrt(var))
    else:
        amp = np.sqrt(2.0 * var)
    omega = np.repeat(w, nd)
    direction = np.tile(directions, n)
    depth = math.inf if water_depth is None else float(water_depth)
    k = wavenumber(omega, None if math.isinf(depth) else depth, g)
    return WaveRealisation(omega=omega, amplitude=amp.ravel(), phase=phase.ravel(),
                           direction=direction, k=k, water_depth=depth,
                           domega=float(dw[0]), spec=spec, seed=seed, duration=duration,
                           gamma=gamma)


# --------------------------------------------------------------------------- wind

@dataclass(frozen=True, eq=False)
class WindRealisation:
    """Wind speed at the reference height: ``u(t) = mean + sum a cos(2 pi f t + phi)``.

    Attributes: ``f`` (Hz), ``amplitude`` (m/s), ``phase`` (rad) read-only arrays; ``mean``
    (m/s, 1-hour mean at ``reference_height``), ``heading`` (rad), ``df`` (Hz).
    """

    f: np.ndarray
    amplitude: np.ndarray
    phase: np.ndarray
    mean: float
    heading: float = 0.0
    reference_height: float = 10.0
    df: float = 0.0
    spec: WindSpec | None = None
    seed: int | None = None
    duration: float | None = None
    omega: np.ndarray = field(init=False, repr=False)

    def __post_init__(self):
        for name in ("f", "amplitude", "phase"):
            object.__setattr__(self, name, _readonly(getattr(self, name)))
        if not (self.f.shape == self.amplitude.shape == self.phase.shape) or self.f.ndim != 1:
            raise ValueError("f, amplitude and phase must be 1-D of equal length")
        object.__setattr__(self, "omega", _readonly(2.0 * np.pi * self.f))

    @property
    def n_components(self) -> int:
        return int(self.f.size)

    @property
    def variance(self) -> float:
        """Variance of the realised gust process, sum a^2/2 (m^2/s^2)."""
        return float(0.5 * np.sum(self.amplitude ** 2))

    def speed(self, t) -> np.ndarray:
        """Wind speed (m/s), mean plus gust, at times ``t`` (s); same shape as ``t``."""
        ta = _time_array(t)
        flat = np.ascontiguousarray(ta.ravel())
        out = np.empty_like(flat)
        zeros = np.zeros_like(self.omega)
        surface_elevation_into(self.omega, self.amplitude, self.phase, zeros, zeros, flat, 0.0, 0.0,
                               out)
        return (out + self.mean).reshape(ta.shape)

    def speed_series(self, n: int, dt: float, t0: float = 0.0) -> np.ndarray:
        """Wind speed (m/s) on the uniform grid t0 + i dt, i < n (fast recurrence)."""
        out = np.full(int(n), float(self.mean))
        work = np.empty((4, self.omega.size))
        cosine_sum_uniform_into(self.omega, self.amplitude, self.phase, float(t0), float(dt), work,
                                out)
        return out


def _default_f_max(spec: WindSpec, cutoff: float) -> float:
    f = np.logspace(-5, 1.5, 3000)
    s = wind_spectrum(spec, f)
    if s.max() <= 0.0:
        return 0.0
    keep = np.nonzero(s >= cutoff * s.max())[0]
    return float(f[keep[-1]])


def realise_wind(spec: WindSpec, *, duration: float, seed: int, n_frequencies: int | None = None,
                 f_min: float | None = None, f_max: float | None = None,
                 random_frequencies: bool = True, random_amplitudes: bool = False,
                 cutoff: float = SPECTRAL_CUTOFF) -> WindRealisation:
    """Realise the gust of ``spec`` at its reference height.

    Parameters
    ----------
    spec : WindSpec
        Wind.  ``constant`` gives no components.
    duration : float
        Simulation length (s).
    seed : int
        Seed of ``numpy.random.default_rng``.
    n_frequencies, f_min, f_max : optional
        Discretisation (default: bins of width <= 1/duration from 0 Hz to the spectral cut-off;
        ``spec.f_min`` etc. are used when set).
    random_frequencies, random_amplitudes : bool
        As for :func:`realise_waves`.

    Returns
    -------
    WindRealisation
    """
    duration = _check_duration(duration)
    seed = _check_seed(seed)
    try:
        u10 = float(spec.u10)
    except (TypeError, ValueError):
        raise SceneError(None, "wind.u10", "a number >= 0 (m/s)", spec.u10) from None
    if not math.isfinite(u10) or u10 < 0.0:
        raise SceneError(None, "wind.u10", "a number >= 0 (m/s)", spec.u10)
    mean = wind_mean_speed(spec)
    empty = np.zeros(0)
    if spec.spectrum == "constant" or u10 == 0.0:
        return WindRealisation(f=empty, amplitude=empty, phase=empty, mean=mean,
                               heading=float(spec.heading),
                               reference_height=float(spec.reference_height), spec=spec, seed=seed,
                               duration=duration)
    lo = spec.f_min if f_min is None else f_min
    hi = spec.f_max if f_max is None else f_max
    lo = 0.0 if lo is None else float(lo)
    hi = _default_f_max(spec, cutoff) if hi is None else float(hi)
    if not (0.0 <= lo < hi and math.isfinite(hi)):
        raise SceneError(None, "wind.f_min/f_max", "0 <= f_min < f_max (Hz)", (lo, hi))
    n = spec.n_frequencies if n_frequencies is None else n_frequencies
    if n is None:
        n = max(16, int(math.ceil((hi - lo) * duration)))
    if isinstance(n, bool) or not isinstance(n, (int, np.integer)) or n < 1:
        raise SceneError(None, "wind.n_frequencies", "an integer >= 1", n)
    n = int(n)
    rng = np.random.default_rng(seed)
    f, df = _bins(lo, hi, n, rng, random_frequencies)
    s = wind_spectrum(spec, f)
    phase = rng.uniform(0.0, 2.0 * np.pi, size=n)
    if random_amplitudes:
        amp = rng.rayleigh(scale=np.sqrt(s * df))
    else:
        amp = np.sqrt(2.0 * s * df)
    return WindRealisation(f=f, amplitude=amp, phase=phase, mean=mean, heading=float(spec.heading),
                           reference_height=float(spec.reference_height), df=float(df[0]),
                           spec=spec, seed=seed, duration=duration)

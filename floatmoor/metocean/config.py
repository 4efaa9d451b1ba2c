"""Validated, frozen descriptions of the environment (sea state, wind, current).

These are plain data: the scene reader (:mod:`floatmoor.io`) fills them from YAML and the
metocean functions and force models turn them into spectra, realisations and forces.  SI units;
headings in radians, the direction the waves, wind or current travel towards, measured from +x
towards +y.
"""

from __future__ import annotations

from dataclasses import dataclass, field

__all__ = ["WaveSpec", "WaveSystems", "WindSpec", "CurrentSpec", "Environment", "WAVE_SPECTRA",
           "WIND_SPECTRA", "CURRENT_PROFILES", "SPREADING_FUNCTIONS", "wave_systems",
           "total_hs"]

WAVE_SPECTRA = ("jonswap", "pierson_moskowitz", "torsethaugen")
WIND_SPECTRA = ("npd", "api", "constant")
CURRENT_PROFILES = ("piecewise_linear", "power_law")
SPREADING_FUNCTIONS = ("none", "cos2s")


@dataclass(frozen=True, kw_only=True)
class WaveSpec:
    """An irregular short-term sea state.

    spectrum: one of :data:`WAVE_SPECTRA`; hs: significant wave height Hm0 (m); tp: peak period
    (s); gamma: JONSWAP peak enhancement (None: DNV-RP-C205 rule from Tp/sqrt(Hs)); heading:
    mean direction of travel (rad); spreading: one of :data:`SPREADING_FUNCTIONS` with exponent
    ``spreading_s`` and ``n_directions`` directions; omega_min/omega_max (rad/s) and
    n_frequencies: the discretisation of a realisation (None: chosen by the realisation, see
    :mod:`floatmoor.metocean.realisation`); random_amplitudes: Rayleigh-distributed amplitudes
    instead of deterministic ones.
    """

    spectrum: str = "jonswap"
    hs: float
    tp: float
    gamma: float | None = None
    heading: float = 0.0
    spreading: str = "none"
    spreading_s: float = 4.0
    n_directions: int = 1
    omega_min: float | None = None
    omega_max: float | None = None
    n_frequencies: int | None = None
    random_amplitudes: bool = False


@dataclass(frozen=True, kw_only=True)
class WaveSystems:
    """A sea state of several wave systems (e.g. a wind sea and a swell from another
    direction), each a :class:`WaveSpec` (spectrum, Hs, Tp, gamma, heading, spreading) without
    its own discretisation.  The systems are independent: their spectra add, the realisation
    sums their components (each system its own random phases) and every force sums over them.

    omega_min/omega_max (rad/s) and n_frequencies: the discretisation of the whole sea (None:
    each system's default band on one common frequency grid, see
    :func:`floatmoor.forces.waves.wave_components`); random_amplitudes: for every system.
    """

    systems: tuple[WaveSpec, ...]
    names: tuple[str, ...] = ()
    omega_min: float | None = None
    omega_max: float | None = None
    n_frequencies: int | None = None
    random_amplitudes: bool = False

    @property
    def hs(self) -> float:
        """Significant wave height of the whole sea, 4 sqrt(m0) = sqrt(sum Hs_i^2) (m)."""
        return total_hs(self)

    @property
    def dominant(self) -> WaveSpec:
        """The system with the largest Hs (the first of equal ones)."""
        return max(self.systems, key=lambda s: s.hs)


def wave_systems(waves) -> tuple[WaveSpec, ...]:
    """The wave systems of ``waves`` (a :class:`WaveSpec`, a :class:`WaveSystems` or None),
    each with the sea's discretisation and ``random_amplitudes``: () without waves."""
    if waves is None:
        return ()
    if isinstance(waves, WaveSpec):
        return (waves,)
    from dataclasses import replace
    return tuple(replace(s, omega_min=waves.omega_min, omega_max=waves.omega_max,
                         n_frequencies=waves.n_frequencies,
                         random_amplitudes=waves.random_amplitudes) for s in waves.systems)


def total_hs(waves) -> float:
    """4 sqrt(m0) of ``waves`` (m): Hs of one system, sqrt(sum Hs_i^2) of several (their
    variances add); 0 without waves."""
    import math
    if isinstance(waves, WaveSpec):
        return float(waves.hs)
    return math.sqrt(sum(s.hs ** 2 for s in wave_systems(waves)))


@dataclass(frozen=True, kw_only=True)
class WindSpec:
    """Wind: 1-hour mean speed ``u10`` at 10 m above the mean water line (m/s), with a gust
    spectrum (one of :data:`WIND_SPECTRA`; ``constant`` means no gust) and a heading (rad).
    ``reference_height`` is the height (m) at which the wind force coefficients apply."""

    spectrum: str = "npd"
    u10: float
    heading: float = 0.0
    reference_height: float = 10.0
    f_min: float | None = None
    f_max: float | None = None
    n_frequencies: int | None = None


@dataclass(frozen=True, kw_only=True)
class CurrentSpec:
    """Current: speed against depth and a heading (rad).

    ``piecewise_linear``: ``z`` (m, <= 0, from the surface down) and ``speed`` (m/s) at those
    levels, constant below the deepest level given.  ``power_law``: surface speed ``speed[0]``
    decaying as ((z + d)/d)^exponent with water depth d (DNV-RP-C205 eq. 4.3 uses 1/7).
    """

    profile: str = "piecewise_linear"
    z: tuple[float, ...] = (0.0,)
    speed: tuple[float, ...] = (0.0,)
    heading: float = 0.0
    exponent: float = 1.0 / 7.0


@dataclass(frozen=True, kw_only=True)
class Environment:
    """The environment of a scene; a component that is None is not modelled (and not built).
    ``waves``: one sea state (:class:`WaveSpec`) or several wave systems (:class:`WaveSystems`)."""

    waves: WaveSpec | WaveSystems | None = None
    wind: WindSpec | None = None
    current: CurrentSpec | None = None
    name: str = ""
    source: str | None = field(default=None, compare=False)

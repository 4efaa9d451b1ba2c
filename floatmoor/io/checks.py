"""Checks that involve more than one section of a scene (run by :func:`load_scene` last).

Each check takes the built :class:`~floatmoor.io.scene.Scene` and warns
(:class:`~floatmoor.FloatmoorWarning`) or raises :class:`~floatmoor.SceneError`.  Later sections
add their cross-checks to :data:`SCENE_CHECKS`.
"""

from __future__ import annotations

import math
import warnings
from collections.abc import Callable
from typing import TYPE_CHECKING

from ..core.errors import FloatmoorWarning, SceneError

if TYPE_CHECKING:  # pragma: no cover
    from .scene import Scene

__all__ = ["SCENE_CHECKS", "check_dt_resolves_waves", "check_time_step_resolves_waves",
           "check_wave_resolution", "highest_wave_frequency"]

STEPS_PER_PEAK_PERIOD = 20
"""Fewer time steps per wave peak period than this are warned about (a fixed-step integrator
needs of the order of 20 steps per period of the dominant wave-frequency load for the response
amplitude to be accurate to about a percent)."""


def _warn(message: str) -> None:
    warnings.warn(message, FloatmoorWarning, stacklevel=4)


def highest_wave_frequency(waves) -> float:
    """The highest frequency (rad/s) of the wave realisation of ``waves`` (a WaveSpec): its
    ``discretisation.omega_max``, else the default range's upper end (where the spectrum
    falls below :data:`~floatmoor.metocean.realisation.SPECTRAL_CUTOFF` of its peak)."""
    if waves.omega_max is not None:
        return float(waves.omega_max)
    from ..metocean.realisation import SPECTRAL_CUTOFF, default_omega_range
    return float(default_omega_range(waves, SPECTRAL_CUTOFF)[1])


def check_dt_resolves_waves(file, key: str, dt: float, waves, *, where: str = "") -> None:
    """SceneError (naming ``file`` and ``key``) when the time step ``dt`` (s) cannot represent
    the wave components of ``waves`` (a WaveSpec): above the Nyquist limit pi / omega_max of the
    highest component (:func:`highest_wave_frequency`; each system of a sea of several) the
    waves alias to lower frequencies and
    the realisation cannot be put on the time grid (a time step in milliseconds typed for
    seconds is the usual cause)."""
    from ..metocean.config import wave_systems
    for w in wave_systems(waves):      # every system of a sea of several
        w_max = highest_wave_frequency(w)
        limit = math.pi / w_max
        if dt > limit:
            raise SceneError(file, key, f"a time step that resolves the sea state{where}: dt <= "
                             f"pi/omega_max = {limit:.3g} s (the highest wave component, "
                             f"omega_max = {w_max:.3g} rad/s, for Hs {w.hs:g} m, Tp "
                             f"{w.tp:g} s)", dt, f"{w.tp / dt:.3g} steps per peak period; "
                             f"use dt <= Tp/{STEPS_PER_PEAK_PERIOD} = "
                             f"{w.tp / STEPS_PER_PEAK_PERIOD:.3g} s (in seconds)")


def check_time_step_resolves_waves(scene: Scene) -> None:
    """Refuse a dt above the Nyquist limit pi/omega_max of the highest wave component
    (:func:`check_dt_resolves_waves`); warn when dt gives fewer than 20 steps per Tp."""
    from ..metocean.config import wave_systems
    waves = scene.environment.waves
    if waves is None:
        return
    dt = scene.analysis.dt
    check_dt_resolves_waves(scene.file, "analysis.dt", dt, waves)
    where = f"{scene.file}: analysis.dt"
    tp = min(w.tp for w in wave_systems(waves))  # the shortest peak period of the systems
    if dt > tp / STEPS_PER_PEAK_PERIOD:
        _warn(f"{where}: dt = {dt:g} s gives {tp / dt:.3g} steps per peak period "
              f"(Tp = {tp:g} s); use dt <= Tp/{STEPS_PER_PEAK_PERIOD} = "
              f"{tp / STEPS_PER_PEAK_PERIOD:.3g} s")


def check_wave_resolution(scene: Scene) -> None:
    """Warn when an explicit wave discretisation is coarser than 2 pi/duration: with equally
    spaced components the series would repeat within the simulation (the realisation draws the
    frequencies at random inside their bins, so it does not repeat exactly, but the spectral
    resolution is still coarser than the simulation can show)."""
    waves = scene.environment.waves
    if waves is None or None in (waves.omega_min, waves.omega_max, waves.n_frequencies):
        return
    dw = (waves.omega_max - waves.omega_min) / waves.n_frequencies
    period = 2.0 * math.pi / dw
    duration = scene.analysis.duration
    if period < duration:
        needed = math.ceil((waves.omega_max - waves.omega_min) * duration / (2.0 * math.pi))
        _warn(f"{scene.environment.source or scene.file}: waves.discretisation.n_frequencies: "
              f"{waves.n_frequencies} frequencies over [{waves.omega_min:g}, {waves.omega_max:g}]"
              f" rad/s repeat every 2 pi/domega = {period:.4g} s, shorter than the duration "
              f"{duration:g} s; use at least {needed} frequencies (or leave n_frequencies out)")


def check_realisation_size(scene: Scene) -> None:
    """SceneError when the wave or wind realisation would hold more components than
    :data:`~floatmoor.io.environment.MAX_WAVE_COMPONENTS` / ``MAX_FREQUENCIES``: without an
    explicit ``n_frequencies`` their number grows with the duration (one per 2 pi/duration), so
    a very long duration would otherwise hang in the realisation."""
    from ..metocean.realisation import SPECTRAL_CUTOFF, _default_f_max, default_omega_range
    from .environment import MAX_FREQUENCIES, MAX_WAVE_COMPONENTS

    duration = scene.analysis.duration
    env = scene.environment
    src = env.source or scene.file
    from ..metocean.config import wave_systems
    waves = env.waves
    if waves is not None and waves.n_frequencies is None:
        n, lo, hi = 0, math.inf, -math.inf
        for w in wave_systems(waves):  # every system's components on the common grid
            lo_d, hi_d = default_omega_range(w, SPECTRAL_CUTOFF)
            lo_w = lo_d if w.omega_min is None else w.omega_min
            hi_w = hi_d if w.omega_max is None else w.omega_max
            n += max(16, math.ceil((hi_w - lo_w) * duration / (2.0 * math.pi))) * w.n_directions
            lo, hi = min(lo, lo_w), max(hi, hi_w)
        n_dir = sum(w.n_directions for w in wave_systems(waves))
        if n > MAX_WAVE_COMPONENTS:
            raise SceneError(scene.file, "analysis.duration", "a duration whose wave "
                             f"realisation has at most {MAX_WAVE_COMPONENTS:,} components",
                             duration, f"{n:,} components (one per 2 pi/duration over "
                             f"[{lo:.3g}, {hi:.3g}] rad/s, x {n_dir} directions, "
                             f"from {src}); their tables would need {n * 96 / 1e6:.3g} MB and "
                             "every time step would sum them all")
    wind = env.wind
    if wind is not None and wind.n_frequencies is None and wind.spectrum != "constant":
        lo = 0.0 if wind.f_min is None else wind.f_min
        hi = _default_f_max(wind, SPECTRAL_CUTOFF) if wind.f_max is None else wind.f_max
        n = max(16, math.ceil((hi - lo) * duration))
        if n > MAX_FREQUENCIES:
            raise SceneError(scene.file, "analysis.duration", "a duration whose wind "
                             f"realisation has at most {MAX_FREQUENCIES:,} frequencies",
                             duration, f"{n:,} frequencies (one per 1/duration up to "
                             f"{hi:.3g} Hz, from {src})")


SCENE_CHECKS: tuple[Callable[[Scene], None], ...] = (
    check_realisation_size,
    check_time_step_resolves_waves,
    check_wave_resolution,
)
"""Cross-section checks, run in this order on every loaded scene."""

"""Checks that involve more than one section of a scene (run by :func:`load_scene` last).

Each check takes the built :class:`~floatmoor.io.scene.Scene` and warns
(:class:`~floatmoor.FloatmoorWarning`) or raises :class:`~floatmoor.SceneError`.  Later sections
add their cross-checks to :data:`SCENE_CHECKS`.
"""

from __future__ import annotations

import math
import warnings
from typing import TYPE_CHECKING, Callable

from ..core.errors import FloatmoorWarning

if TYPE_CHECKING:  # pragma: no cover
    from .scene import Scene

__all__ = ["SCENE_CHECKS", "check_time_step_resolves_waves", "check_wave_resolution"]

STEPS_PER_PEAK_PERIOD = 20
"""Fewer time steps per wave peak period than this are warned about (a fixed-step integrator
needs of the order of 20 steps per period of the dominant wave-frequency load for the response
amplitude to be accurate to about a percent)."""


def _warn(message: str) -> None:
    warnings.warn(message, FloatmoorWarning, stacklevel=4)


def check_time_step_resolves_waves(scene: "Scene") -> None:
    """Warn when dt is coarse for the waves: fewer than 20 steps per Tp, or dt above the Nyquist
    limit pi/omega_max of the highest wave component requested."""
    waves = scene.environment.waves
    if waves is None:
        return
    dt = scene.analysis.dt
    where = f"{scene.file}: analysis.dt"
    if dt > waves.tp / STEPS_PER_PEAK_PERIOD:
        _warn(f"{where}: dt = {dt:g} s gives {waves.tp / dt:.3g} steps per peak period "
              f"(Tp = {waves.tp:g} s); use dt <= Tp/{STEPS_PER_PEAK_PERIOD} = "
              f"{waves.tp / STEPS_PER_PEAK_PERIOD:.3g} s")
    if waves.omega_max is not None and dt > math.pi / waves.omega_max:
        _warn(f"{where}: dt = {dt:g} s cannot represent waves up to omega_max = "
              f"{waves.omega_max:g} rad/s (Nyquist: dt <= pi/omega_max = "
              f"{math.pi / waves.omega_max:.3g} s); they alias to lower frequencies")


def check_wave_resolution(scene: "Scene") -> None:
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


SCENE_CHECKS: tuple[Callable[["Scene"], None], ...] = (
    check_time_step_resolves_waves,
    check_wave_resolution,
)
"""Cross-section checks, run in this order on every loaded scene."""

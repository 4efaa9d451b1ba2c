"""Current speed against depth (steady, no turbulence).

* ``piecewise_linear``: speeds given at levels z (m, <= 0, measured up from the mean water
  line), linear in between, constant below the deepest level and above the shallowest one
  (so z > 0, e.g. the crest of a wave, gets the surface value).
* ``power_law``: v(z) = v0 ((z + d)/d)^alpha for -d <= z <= 0 (DNV-RP-C205 eq. 4.3 uses
  alpha = 1/7 for tidal current), v0 = ``speed[0]`` the surface speed; z > 0 gets v0, z < -d
  gets 0.

The direction of travel is ``spec.heading`` at every depth.  :func:`current_speed` is the
vectorised Python entry point; :func:`piecewise_linear_speed_into` and
:func:`power_law_speed_into` are the numba kernels behind it for use in time loops.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from floatmoor.core.errors import SceneError
from floatmoor.metocean.config import CURRENT_PROFILES, CurrentSpec

__all__ = ["current_speed", "current_velocity", "current_levels", "piecewise_linear_speed_into",
           "power_law_speed_into", "CURRENT_PROFILE_KERNELS"]


@njit(cache=True)
def piecewise_linear_speed_into(z_levels, speeds, z, out):
    """Piecewise-linear speed at heights ``z`` (m) written into ``out`` (m/s).

    ``z_levels`` must be strictly increasing (deepest first), ``speeds`` the speed there.
    Constant beyond the first and last level.
    """
    n = z_levels.shape[0]
    for i in range(z.shape[0]):
        zi = z[i]
        if zi <= z_levels[0]:
            out[i] = speeds[0]
        elif zi >= z_levels[n - 1]:
            out[i] = speeds[n - 1]
        else:
            j = 0
            while z_levels[j + 1] < zi:
                j += 1
            w = (zi - z_levels[j]) / (z_levels[j + 1] - z_levels[j])
            out[i] = (1.0 - w) * speeds[j] + w * speeds[j + 1]


@njit(cache=True)
def power_law_speed_into(v0, exponent, water_depth, z, out):
    """Power-law speed v0 ((z + d)/d)^exponent at heights ``z`` (m) into ``out`` (m/s)."""
    for i in range(z.shape[0]):
        zi = z[i]
        if zi >= 0.0:
            out[i] = v0
        elif zi <= -water_depth:
            out[i] = 0.0
        else:
            out[i] = v0 * ((zi + water_depth) / water_depth) ** exponent


CURRENT_PROFILE_KERNELS = {"piecewise_linear": piecewise_linear_speed_into,
                           "power_law": power_law_speed_into}
"""Registry: profile name -> numba kernel (see the kernels for their arguments)."""


def current_levels(spec: CurrentSpec) -> tuple[np.ndarray, np.ndarray]:
    """Validated levels of a piecewise-linear profile, sorted deepest first.

    Returns ``(z_levels, speeds)`` as float arrays; z strictly increasing.
    """
    z = np.asarray(spec.z, dtype=float).ravel()
    v = np.asarray(spec.speed, dtype=float).ravel()
    if z.size == 0 or z.size != v.size:
        raise SceneError(None, "current.levels", "a non-empty list of [z, speed] pairs "
                         "(same number of z and speed values)", (tuple(spec.z), tuple(spec.speed)))
    if np.any(~np.isfinite(z)) or np.any(z > 0.0):
        raise SceneError(None, "current.levels", "levels z <= 0 m (measured up from the mean "
                         "water line)", tuple(spec.z))
    if np.any(~np.isfinite(v)) or np.any(v < 0.0):
        raise SceneError(None, "current.levels", "speeds >= 0 m/s (direction from heading_deg)",
                         tuple(spec.speed))
    order = np.argsort(z)
    z, v = z[order], v[order]
    if np.any(np.diff(z) <= 0.0):
        raise SceneError(None, "current.levels", "distinct levels z", tuple(spec.z))
    return z, v


def _check_spec(spec: CurrentSpec, water_depth: float) -> float:
    if spec.profile not in CURRENT_PROFILES:
        raise SceneError(None, "current.profile", "one of: " + ", ".join(CURRENT_PROFILES),
                         spec.profile)
    try:
        d = float(water_depth)
    except (TypeError, ValueError):
        raise SceneError(None, "site.water_depth", "a number > 0 (m)", water_depth) from None
    if not math.isfinite(d) or d <= 0.0:
        raise SceneError(None, "site.water_depth", "a finite number > 0 (m)", water_depth)
    return d


def current_speed(spec: CurrentSpec, z, water_depth: float) -> np.ndarray:
    """Current speed (m/s) at heights ``z`` (m, z up from the mean water line).

    Parameters
    ----------
    spec : CurrentSpec
        The current profile.
    z : array_like
        Heights (m); any shape.  z > 0 returns the surface value.
    water_depth : float
        Water depth d (m), > 0; used by the power law.

    Returns
    -------
    numpy.ndarray
        Speed (m/s), same shape as ``z``.
    """
    d = _check_spec(spec, water_depth)
    za = np.asarray(z, dtype=float)
    flat = np.ascontiguousarray(za.ravel())
    out = np.empty_like(flat)
    if spec.profile == "piecewise_linear":
        zl, v = current_levels(spec)
        piecewise_linear_speed_into(zl, v, flat, out)
    else:
        v = np.asarray(spec.speed, dtype=float).ravel()
        if v.size < 1 or not math.isfinite(v[0]) or v[0] < 0.0:
            raise SceneError(None, "current.speed", "a surface speed >= 0 m/s", tuple(spec.speed))
        alpha = float(spec.exponent)
        if not math.isfinite(alpha) or alpha <= 0.0:
            raise SceneError(None, "current.exponent", "a number > 0", spec.exponent)
        power_law_speed_into(float(v[0]), alpha, d, flat, out)
    return out.reshape(za.shape)


def current_velocity(spec: CurrentSpec, z, water_depth: float) -> np.ndarray:
    """Current velocity (m/s), shape ``z.shape + (3,)``: (v cos heading, v sin heading, 0)."""
    v = current_speed(spec, z, water_depth)
    out = np.zeros(v.shape + (3,))
    out[..., 0] = v * math.cos(spec.heading)
    out[..., 1] = v * math.sin(spec.heading)
    return out

"""Wind: mean profiles and gust spectra (one-sided, in Hz, units m^2/s).

* NPD / Froya model (DNV-RP-C205 sec. 2.3.2, eqs. 2.19ff; also ISO 19901-1 and NORSOK N-003):

  - spectrum, U0 the 1-hour mean speed at 10 m (m/s), z the height (m), f in Hz::

        S(f) = 320 (U0/10)^2 (z/10)^0.45 / (1 + ft^n)^(5/(3n)),  n = 0.468,
        ft   = 172 f (z/10)^(2/3) (U0/10)^-0.75

  - profile with averaging time T (s), T0 = 3600 s, H = 10 m::

        U(T, z) = U0 (1 + C ln(z/H)) (1 - 0.41 I_U(z) ln(T/T0)),
        C       = 5.73e-2 sqrt(1 + 0.148 U0),
        I_U(z)  = 0.06 (1 + 0.043 U0) (z/H)^-0.22

* API model (API RP 2A-WSD, 22nd ed., sec. 2.3.2; the same form is in API RP 2SK, 3rd ed.,
  sec. 6.3.2)::

        S(f) = sigma(z)^2 / fp / (1 + 1.5 f/fp)^(5/3),  fp = a U(z)/z,  a = 0.025,
        sigma(z) = I(z) U(z),  I(z) = 0.15 (z/zs)^-0.125 for z <= zs = 20 m,
                                     0.15 (z/zs)^-0.275 above,

  and the 1-hour mean profile U(z) = U0 (z/10)^0.125.  The spectrum integrates to sigma^2.

* constant wind: no gust; mean speed from the NPD profile (1-hour average).
"""

from __future__ import annotations

import math
from collections.abc import Callable

import numpy as np

from floatmoor.core.errors import SceneError, check_positive
from floatmoor.metocean.config import WindSpec

__all__ = ["npd_wind_spectrum", "npd_wind_profile", "npd_turbulence_intensity",
           "api_wind_spectrum", "api_wind_profile", "api_turbulence_intensity",
           "constant_wind_spectrum", "wind_spectrum", "wind_mean_speed", "WIND_SPECTRUM_FUNCTIONS",
           "WIND_PROFILE_FUNCTIONS"]


def _check_nonneg(value, key: str) -> float:
    try:
        v = float(value)
    except (TypeError, ValueError):
        raise SceneError(None, key, "a number >= 0", value) from None
    if not math.isfinite(v) or v < 0.0:
        raise SceneError(None, key, "a number >= 0", value)
    return v


def _f_array(f) -> np.ndarray:
    fa = np.asarray(f, dtype=float)
    if np.any(~np.isfinite(fa)) or np.any(fa < 0.0):
        raise SceneError(None, "f", "finite frequencies >= 0 Hz", fa[~np.isfinite(fa) | (fa < 0)][:3])
    return fa


def _z_array(z, key="wind.reference_height") -> np.ndarray:
    za = np.asarray(z, dtype=float)
    if np.any(~np.isfinite(za)) or np.any(za <= 0.0):
        raise SceneError(None, key, "heights > 0 m above the mean water line", z)
    return za


# --------------------------------------------------------------------------- NPD

def npd_wind_spectrum(f, u10: float, z: float = 10.0) -> np.ndarray:
    """NPD (Froya) gust spectrum, DNV-RP-C205 sec. 2.3.2 (eqs. 2.19ff).

    Parameters
    ----------
    f : array_like
        Frequencies (Hz), >= 0.
    u10 : float
        1-hour mean wind speed at 10 m above the mean water line (m/s), >= 0.
    z : float
        Height above the mean water line (m), > 0.

    Returns
    -------
    numpy.ndarray
        One-sided S(f) in m^2/s (variance of the longitudinal gust per Hz).
    """
    u0 = _check_nonneg(u10, "wind.u10")
    fa = _f_array(f)
    z = float(_z_array(z))
    n = 0.468
    if u0 == 0.0:
        return np.zeros_like(fa)
    ft = 172.0 * fa * (z / 10.0) ** (2.0 / 3.0) * (u0 / 10.0) ** -0.75
    return 320.0 * (u0 / 10.0) ** 2 * (z / 10.0) ** 0.45 / (1.0 + ft ** n) ** (5.0 / (3.0 * n))


def npd_turbulence_intensity(z, u10: float) -> np.ndarray:
    """NPD turbulence intensity I_U(z) = 0.06 (1 + 0.043 U0) (z/10)^-0.22 (-)."""
    u0 = _check_nonneg(u10, "wind.u10")
    za = _z_array(z)
    return 0.06 * (1.0 + 0.043 * u0) * (za / 10.0) ** -0.22


def npd_wind_profile(z, u10: float, averaging_s: float = 3600.0) -> np.ndarray:
    """NPD mean wind speed at height z for averaging time T (DNV-RP-C205 sec. 2.3.2).

    Parameters
    ----------
    z : array_like
        Heights above the mean water line (m), > 0.
    u10 : float
        1-hour mean wind speed at 10 m (m/s).
    averaging_s : float
        Averaging time T (s), 0 < T <= 3600 (the model is defined for T <= T0 = 1 hour).

    Returns
    -------
    numpy.ndarray
        U(T, z) in m/s.
    """
    u0 = _check_nonneg(u10, "wind.u10")
    t = check_positive(averaging_s, "wind.averaging_s")
    if t > 3600.0 * (1.0 + 1e-12):
        raise SceneError(None, "wind.averaging_s", "an averaging time <= 3600 s "
                         "(the NPD profile is defined for T <= 1 hour)", averaging_s)
    za = _z_array(z)
    c = 5.73e-2 * math.sqrt(1.0 + 0.148 * u0)
    iu = 0.06 * (1.0 + 0.043 * u0) * (za / 10.0) ** -0.22
    return u0 * (1.0 + c * np.log(za / 10.0)) * (1.0 - 0.41 * iu * math.log(t / 3600.0))


# --------------------------------------------------------------------------- API

def api_turbulence_intensity(z) -> np.ndarray:
    """API RP 2A turbulence intensity I(z) = 0.15 (z/20)^-0.125 (z <= 20 m), ^-0.275 above."""
    za = _z_array(z)
    zs = 20.0
    return np.where(za <= zs, 0.15 * (za / zs) ** -0.125, 0.15 * (za / zs) ** -0.275)


def api_wind_profile(z, u10: float) -> np.ndarray:
    """API RP 2A 1-hour mean profile U(z) = U0 (z/10)^0.125 (m/s)."""
    u0 = _check_nonneg(u10, "wind.u10")
    return u0 * (_z_array(z) / 10.0) ** 0.125


def api_wind_spectrum(f, u_mean: float, z: float, a: float = 0.025) -> np.ndarray:
    """API RP 2A / 2SK gust spectrum.

    Parameters
    ----------
    f : array_like
        Frequencies (Hz), >= 0.
    u_mean : float
        1-hour mean wind speed at height z (m/s).
    z : float
        Height above the mean water line (m).
    a : float
        Peak-frequency coefficient, fp = a U(z)/z; API gives 0.01 <= a <= 0.1, 0.025 typical.

    Returns
    -------
    numpy.ndarray
        One-sided S(f) in m^2/s; integrates to sigma(z)^2 = (I(z) U(z))^2.
    """
    u = _check_nonneg(u_mean, "wind.u10")
    fa = _f_array(f)
    z = float(_z_array(z))
    a = check_positive(a, "wind.api_a")
    if u == 0.0:
        return np.zeros_like(fa)
    sigma = float(api_turbulence_intensity(z)) * u
    fp = a * u / z
    return sigma ** 2 / fp / (1.0 + 1.5 * fa / fp) ** (5.0 / 3.0)


def constant_wind_spectrum(f, u10: float = 0.0, z: float = 10.0) -> np.ndarray:
    """No gust: S(f) = 0 (m^2/s)."""
    return np.zeros_like(_f_array(f))


# --------------------------------------------------------------------------- registries

def _npd(spec: WindSpec, f):
    return npd_wind_spectrum(f, spec.u10, spec.reference_height)


def _api(spec: WindSpec, f):
    z = spec.reference_height
    return api_wind_spectrum(f, float(api_wind_profile(z, spec.u10)), z)


def _constant(spec: WindSpec, f):
    return constant_wind_spectrum(f)


WIND_SPECTRUM_FUNCTIONS: dict[str, Callable[[WindSpec, np.ndarray], np.ndarray]] = {
    "npd": _npd, "api": _api, "constant": _constant}
"""Registry: gust spectrum name -> function(spec, f) giving S(f) (m^2/s) at the reference height."""

WIND_PROFILE_FUNCTIONS: dict[str, Callable[[float, float], np.ndarray]] = {
    "npd": lambda z, u10: npd_wind_profile(z, u10, 3600.0),
    "api": api_wind_profile,
    "constant": lambda z, u10: npd_wind_profile(z, u10, 3600.0),
}
"""Registry: name -> 1-hour mean profile U(z, u10) used with that gust spectrum."""


def _lookup(name):
    if name not in WIND_SPECTRUM_FUNCTIONS:
        raise SceneError(None, "wind.spectrum",
                         "one of: " + ", ".join(sorted(WIND_SPECTRUM_FUNCTIONS)), name)
    return WIND_SPECTRUM_FUNCTIONS[name]


def wind_spectrum(spec: WindSpec, f) -> np.ndarray:
    """Gust spectrum S(f) (m^2/s, f in Hz) of ``spec`` at its reference height."""
    return _lookup(spec.spectrum)(spec, f)


def wind_mean_speed(spec: WindSpec, z: float | None = None) -> float:
    """1-hour mean wind speed (m/s) at height ``z`` (default: ``spec.reference_height``)."""
    _lookup(spec.spectrum)
    z = spec.reference_height if z is None else z
    return float(WIND_PROFILE_FUNCTIONS[spec.spectrum](z, spec.u10))

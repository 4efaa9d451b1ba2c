"""Wave spectra: one-sided S(omega) in m^2 s/rad, with Hm0 = 4 sqrt(m0).

Models (all from DNV-RP-C205, DNV (2010), chapter 3.5, "Wave spectra"):

* :func:`pierson_moskowitz` -- S_PM(w) = 5/16 Hs^2 wp^4 w^-5 exp(-5/4 (w/wp)^-4), wp = 2 pi/Tp.
  Its zeroth moment is exactly Hs^2/16 (substitute u = 5/4 (w/wp)^-4).
* :func:`jonswap` -- S_J(w) = A_gamma S_PM(w) gamma^exp(-(w - wp)^2 / (2 sigma^2 wp^2)),
  sigma = 0.07 for w <= wp and 0.09 above.  gamma None: the DNV-RP-C205 rule (:func:`dnv_gamma`).
  **Normalisation**: A_gamma is computed *numerically*, A_gamma = 1 / I(gamma) with
  I(gamma) = int_0^inf 5 x^-5 exp(-5/4 x^-4) gamma^exp(-(x-1)^2/(2 sigma^2)) dx (x = w/wp), by
  adaptive quadrature once per gamma, so that 4 sqrt(m0) equals Hs to quadrature accuracy.
  DNV's closed-form approximation A_gamma = 1 - 0.287 ln(gamma) is available as
  :func:`dnv_jonswap_normalisation` and agrees within about 1-2 % for 1 <= gamma <= 7 (tested).
* :func:`torsethaugen` -- the two-peak (wind sea + swell) model of Torsethaugen and Haver (2004,
  "Simplified double peak spectral model for ocean waves", ISOPE), as given in DNV-RP-C205
  sec. 3.5.6.  Each peak j is S_j(w) = Hs_j^2/16 * Tp_j/(2 pi) * G0 A_gamma_j x^-4 exp(-x^-4)
  gamma_j^exp(-(x-1)^2/(2 sigma^2)), x = w Tp_j/(2 pi).  As for JONSWAP, G0 A_gamma_j is computed
  numerically (1 / int x^-4 exp(-x^-4) gamma^... dx) instead of the parametric
  G0 = 3.26, A_gamma = (1 + 1.1 ln(gamma)^1.19)/gamma; since Hs_1^2 + Hs_2^2 = Hs^2 the total
  then has 4 sqrt(m0) = Hs.

Directional spreading: the cos-2s (Longuet-Higgins) function
D(theta) = Gamma(s+1) / (2 sqrt(pi) Gamma(s+1/2)) cos^(2s)((theta - theta_m)/2) on
[theta_m - pi, theta_m + pi], discretised by :func:`spreading_directions`.

Invalid parameters raise :class:`floatmoor.core.errors.SceneError` (key path ``waves.<name>``).
"""

from __future__ import annotations

import math
from collections.abc import Callable
from functools import lru_cache

import numpy as np
from scipy import integrate
from scipy.special import gammaln

from floatmoor.core.errors import SceneError, check_positive
from floatmoor.metocean.config import SPREADING_FUNCTIONS, WaveSpec, wave_systems

__all__ = ["dnv_gamma", "jonswap", "pierson_moskowitz", "torsethaugen", "torsethaugen_parameters",
           "dnv_jonswap_normalisation", "wave_spectrum", "WAVE_SPECTRUM_FUNCTIONS", "sea_directions",
           "spectral_moment", "spectrum_gamma", "cos2s_spreading", "spreading_directions",
           "default_omega_range"]

SIGMA_LOW = 0.07
"""JONSWAP spectral width parameter for w <= wp (DNV-RP-C205 sec. 3.5.5)."""
SIGMA_HIGH = 0.09
"""JONSWAP spectral width parameter for w > wp."""


# --------------------------------------------------------------------------- validation helpers

def _check_gamma(gamma, key: str = "waves.gamma") -> float:
    try:
        g = float(gamma)
    except (TypeError, ValueError):
        raise SceneError(None, key, "a number >= 1 (JONSWAP peak enhancement) or null", gamma) \
            from None
    if not math.isfinite(g) or g < 1.0:
        raise SceneError(None, key, "a number >= 1 (JONSWAP peak enhancement) or null", gamma,
                         hint="gamma = 1 gives Pierson-Moskowitz; null applies the DNV rule")
    return g


def _omega_array(omega) -> np.ndarray:
    w = np.asarray(omega, dtype=float)
    if np.any(~np.isfinite(w)) or np.any(w < 0.0):
        raise SceneError(None, "omega", "finite angular frequencies >= 0 rad/s",
                         w[~np.isfinite(w) | (w < 0.0)][:3])
    return w


# --------------------------------------------------------------------------- JONSWAP / PM

def dnv_gamma(hs: float, tp: float) -> float:
    """JONSWAP peak enhancement factor from the DNV-RP-C205 (sec. 3.5.5.5) rule.

    gamma = 5 for Tp/sqrt(Hs) <= 3.6; exp(5.75 - 1.15 Tp/sqrt(Hs)) for 3.6 < Tp/sqrt(Hs) < 5;
    1 for Tp/sqrt(Hs) >= 5 (Tp in s, Hs in m).

    Parameters
    ----------
    hs : float
        Significant wave height (m), > 0.
    tp : float
        Peak period (s), > 0.

    Returns
    -------
    float
        gamma (-), between 1 and 5.
    """
    hs = check_positive(hs, "waves.hs")
    tp = check_positive(tp, "waves.tp")
    r = tp / math.sqrt(hs)
    if r <= 3.6:
        return 5.0
    if r < 5.0:
        return math.exp(5.75 - 1.15 * r)
    return 1.0


def _peak_factor(x: np.ndarray, gamma: float) -> np.ndarray:
    """gamma ** exp(-(x-1)^2 / (2 sigma^2)) with x = w/wp."""
    if gamma == 1.0:
        return np.ones_like(x)
    sigma = np.where(x <= 1.0, SIGMA_LOW, SIGMA_HIGH)
    return gamma ** np.exp(-0.5 * ((x - 1.0) / sigma) ** 2)


def _quad_normaliser(shape: Callable[[float], float]) -> float:
    """int_0^inf shape(x) dx split at the peak x = 1 and the sigma switch."""
    parts = [(1e-6, 0.6), (0.6, 1.0), (1.0, 1.6), (1.6, 8.0), (8.0, np.inf)]
    total = 0.0
    for a, b in parts:
        val, _ = integrate.quad(shape, a, b, epsabs=0.0, epsrel=1e-11, limit=200)
        total += val
    return total


@lru_cache(maxsize=256)
def _jonswap_integral(gamma: float) -> float:
    """I(gamma) = int 5 x^-5 exp(-5/4 x^-4) gamma^r(x) dx (=1 for gamma=1)."""
    def shape(x):
        s = SIGMA_LOW if x <= 1.0 else SIGMA_HIGH
        return 5.0 * x ** -5 * math.exp(-1.25 * x ** -4) * gamma ** math.exp(
            -0.5 * ((x - 1.0) / s) ** 2)
    return _quad_normaliser(shape)


@lru_cache(maxsize=256)
def _torsethaugen_integral(gamma: float) -> float:
    """int x^-4 exp(-x^-4) gamma^r(x) dx (= Gamma(3/4)/4 for gamma = 1)."""
    def shape(x):
        s = SIGMA_LOW if x <= 1.0 else SIGMA_HIGH
        return x ** -4 * math.exp(-(x ** -4)) * gamma ** math.exp(-0.5 * ((x - 1.0) / s) ** 2)
    return _quad_normaliser(shape)


def dnv_jonswap_normalisation(gamma: float) -> float:
    """DNV-RP-C205 closed-form JONSWAP normalising factor A_gamma = 1 - 0.287 ln(gamma).

    Not used by :func:`jonswap` (which normalises numerically); provided for comparison.
    """
    return 1.0 - 0.287 * math.log(_check_gamma(gamma))


def pierson_moskowitz(omega, hs: float, tp: float) -> np.ndarray:
    """Pierson-Moskowitz spectrum (DNV-RP-C205 eq. 3.5.5.1).

    Parameters
    ----------
    omega : array_like
        Angular frequencies (rad/s), >= 0.
    hs : float
        Significant wave height Hm0 (m).
    tp : float
        Peak period (s).

    Returns
    -------
    numpy.ndarray
        S(omega) in m^2 s/rad, same shape as ``omega``; 0 at omega = 0.
    """
    hs = check_positive(hs, "waves.hs")
    tp = check_positive(tp, "waves.tp")
    w = _omega_array(omega)
    wp = 2.0 * np.pi / tp
    out = np.zeros_like(w)
    pos = w > 0.0
    x = w[pos] / wp
    out[pos] = (hs * hs / 16.0) / wp * 5.0 * x ** -5 * np.exp(-1.25 * x ** -4)
    return out


def jonswap(omega, hs: float, tp: float, gamma: float | None = None) -> np.ndarray:
    """JONSWAP spectrum (DNV-RP-C205 sec. 3.5.5), normalised numerically to Hm0 = Hs.

    Parameters
    ----------
    omega : array_like
        Angular frequencies (rad/s), >= 0.
    hs : float
        Significant wave height Hm0 (m).
    tp : float
        Peak period (s).
    gamma : float or None
        Peak enhancement factor (>= 1); None applies :func:`dnv_gamma`.

    Returns
    -------
    numpy.ndarray
        S(omega) in m^2 s/rad.  ``4 * sqrt(int S domega) == hs`` (see module docstring).
    """
    hs = check_positive(hs, "waves.hs")
    tp = check_positive(tp, "waves.tp")
    g = dnv_gamma(hs, tp) if gamma is None else _check_gamma(gamma)
    w = _omega_array(omega)
    wp = 2.0 * np.pi / tp
    out = np.zeros_like(w)
    pos = w > 0.0
    x = w[pos] / wp
    out[pos] = ((hs * hs / 16.0) / wp * 5.0 * x ** -5 * np.exp(-1.25 * x ** -4)
                * _peak_factor(x, g) / _jonswap_integral(g))
    return out


# --------------------------------------------------------------------------- Torsethaugen

def torsethaugen_parameters(hs: float, tp: float) -> dict:
    """Parameters of the two peaks of the Torsethaugen-Haver (2004) spectrum.

    Returns a dict with ``regime`` ("wind_sea" if Tp <= Tpf, else "swell"), ``tpf`` (s) and
    per peak (1 = primary, at Tp; 2 = secondary) ``hs1, tp1, gamma1, hs2, tp2, gamma2``.

    Constants (DNV-RP-C205 sec. 3.5.6): af = 6.6 s m^-1/3, ae = 2 s m^-1/2, Tu = 25 s,
    a1 = 0.5, a10 = 0.7, a2 = 0.3, a20 = 0.6, a3 = 6, b1 = 2 s, kg = 35.
    """
    hs = check_positive(hs, "waves.hs")
    tp = check_positive(tp, "waves.tp")
    g = 9.80665
    af, ae, tu = 6.6, 2.0, 25.0
    tpf = af * hs ** (1.0 / 3.0)
    if tp <= tpf:  # wind-sea dominated
        tl = ae * math.sqrt(hs)
        eps_l = min(1.0, max(0.0, (tpf - tp) / (tpf - tl))) if tpf > tl else 1.0
        rpw = 0.7 + 0.3 * math.exp(-((eps_l / 0.5) ** 2))
        hs1 = rpw * hs
        gamma1 = 35.0 * (2.0 * math.pi / g * hs1 / tp ** 2) ** 0.857
        hs2 = hs * math.sqrt(max(0.0, 1.0 - rpw * rpw))
        tp2 = tpf + 2.0
        regime = "wind_sea"
    else:  # swell dominated
        eps_u = min(1.0, (tp - tpf) / (tu - tpf)) if tu > tpf else 1.0
        rps = 0.6 + 0.4 * math.exp(-((eps_u / 0.3) ** 2))
        hs1 = rps * hs
        gamma1 = 35.0 * (2.0 * math.pi / g * hs / tpf ** 2) ** 0.857 * (1.0 + 6.0 * eps_u)
        hs2 = hs * math.sqrt(max(0.0, 1.0 - rps * rps))
        tp2 = af * hs2 ** (1.0 / 3.0) if hs2 > 0.0 else tpf
        regime = "swell"
    return {"regime": regime, "tpf": tpf, "hs1": hs1, "tp1": tp, "gamma1": max(1.0, gamma1),
            "hs2": hs2, "tp2": tp2, "gamma2": 1.0}


def _torsethaugen_peak(w: np.ndarray, hs_j: float, tp_j: float, gamma_j: float) -> np.ndarray:
    out = np.zeros_like(w)
    if hs_j <= 0.0:
        return out
    wp = 2.0 * np.pi / tp_j
    pos = w > 0.0
    x = w[pos] / wp
    out[pos] = ((hs_j * hs_j / 16.0) / wp * x ** -4 * np.exp(-(x ** -4)) * _peak_factor(x, gamma_j)
                / _torsethaugen_integral(gamma_j))
    return out


def torsethaugen(omega, hs: float, tp: float) -> np.ndarray:
    """Torsethaugen two-peak spectrum (Torsethaugen and Haver 2004; DNV-RP-C205 sec. 3.5.6).

    Parameters
    ----------
    omega : array_like
        Angular frequencies (rad/s), >= 0.
    hs : float
        Total significant wave height Hm0 (m).
    tp : float
        Peak period of the primary (dominant) peak (s).

    Returns
    -------
    numpy.ndarray
        S(omega) in m^2 s/rad; each peak normalised numerically so that 4 sqrt(m0) = Hs.
    """
    p = torsethaugen_parameters(hs, tp)
    w = _omega_array(omega)
    return (_torsethaugen_peak(w, p["hs1"], p["tp1"], p["gamma1"])
            + _torsethaugen_peak(w, p["hs2"], p["tp2"], p["gamma2"]))


# --------------------------------------------------------------------------- registry

def _jonswap_spec(spec: WaveSpec, omega):
    return jonswap(omega, spec.hs, spec.tp, spec.gamma)


def _pm_spec(spec: WaveSpec, omega):
    return pierson_moskowitz(omega, spec.hs, spec.tp)


def _torsethaugen_spec(spec: WaveSpec, omega):
    return torsethaugen(omega, spec.hs, spec.tp)


WAVE_SPECTRUM_FUNCTIONS: dict[str, Callable[[WaveSpec, np.ndarray], np.ndarray]] = {
    "jonswap": _jonswap_spec,
    "pierson_moskowitz": _pm_spec,
    "torsethaugen": _torsethaugen_spec,
}
"""Registry: spectrum name -> function(spec, omega) returning S(omega) (m^2 s/rad)."""


def _lookup_spectrum(name):
    try:
        return WAVE_SPECTRUM_FUNCTIONS[name]
    except (KeyError, TypeError):
        raise SceneError(None, "waves.spectrum",
                         "one of: " + ", ".join(sorted(WAVE_SPECTRUM_FUNCTIONS)), name) from None


def wave_spectrum(spec: WaveSpec, omega) -> np.ndarray:
    """S(omega) (m^2 s/rad) of the sea state ``spec``, dispatching on ``spec.spectrum``.

    An unknown spectrum name raises SceneError listing the available names.  The
    ``gamma`` of ``spec`` is used by JONSWAP only (a gamma given for another spectrum is
    rejected, since it would silently be ignored).
    """
    fun = _lookup_spectrum(spec.spectrum)
    if spec.gamma is not None and spec.spectrum != "jonswap":
        raise SceneError(None, "waves.gamma", f"null for spectrum {spec.spectrum!r} "
                         "(gamma applies to jonswap only)", spec.gamma)
    return fun(spec, omega)


def spectrum_gamma(spec: WaveSpec) -> float | None:
    """The JONSWAP gamma actually used for ``spec`` (None for other spectra)."""
    if spec.spectrum != "jonswap":
        return None
    return dnv_gamma(spec.hs, spec.tp) if spec.gamma is None else _check_gamma(spec.gamma)


def spectral_moment(omega, s, n: int = 0) -> float:
    """n-th spectral moment m_n = int omega^n S(omega) domega by the trapezoidal rule."""
    w = np.asarray(omega, dtype=float)
    return float(np.trapezoid(w ** n * np.asarray(s, dtype=float), w))


def default_omega_range(spec: WaveSpec, cutoff: float = 1e-3) -> tuple[float, float]:
    """Default frequency range (rad/s) of a realisation.

    The interval outside of which S(omega) stays below ``cutoff`` times its maximum
    (found on a fine logarithmic grid from 0.05 wp to 20 wp).  For the Heidrun 100-year sea
    state (JONSWAP, gamma 1.68) and cutoff 1e-3 this is 0.59 wp ... 4.6 wp and leaves out
    0.24 % of m0.
    """
    wp = 2.0 * np.pi / check_positive(spec.tp, "waves.tp")
    w = wp * np.logspace(np.log10(0.05), np.log10(20.0), 4000)
    s = wave_spectrum(spec, w)
    keep = np.nonzero(s >= cutoff * s.max())[0]
    return float(w[keep[0]]), float(w[keep[-1]])


# --------------------------------------------------------------------------- spreading

def cos2s_spreading(theta, mean_direction: float, s: float) -> np.ndarray:
    """cos-2s directional spreading density D(theta) (1/rad), integrating to 1 over 2 pi.

    D = Gamma(s+1) / (2 sqrt(pi) Gamma(s+1/2)) cos^(2s)((theta - mean)/2).
    """
    s = check_positive(s, "waves.spreading_s")
    th = np.asarray(theta, dtype=float)
    c = math.exp(gammaln(s + 1.0) - gammaln(s + 0.5)) / (2.0 * math.sqrt(math.pi))
    return c * np.abs(np.cos(0.5 * (th - mean_direction))) ** (2.0 * s)


def spreading_directions(spec: WaveSpec) -> tuple[np.ndarray, np.ndarray]:
    """Directions (rad) and weights (summing to 1) of the discretised spreading of ``spec``.

    ``spreading == "none"`` or ``n_directions == 1``: the single direction ``spec.heading``.
    ``"cos2s"``: ``n_directions`` equal bins of width 2 pi / n centred on the heading; each
    weight is the integral of :func:`cos2s_spreading` over its bin (Simpson, 33 points), so the
    weights are exact bin energies and sum to 1.
    """
    if spec.spreading not in SPREADING_FUNCTIONS:
        raise SceneError(None, "waves.spreading", "one of: " + ", ".join(SPREADING_FUNCTIONS),
                         spec.spreading)
    n = spec.n_directions
    if not isinstance(n, (int, np.integer)) or isinstance(n, bool) or n < 1:
        raise SceneError(None, "waves.n_directions", "an integer >= 1", n)
    heading = float(spec.heading)
    if spec.spreading == "none" or n == 1:
        return np.array([heading]), np.array([1.0])
    width = 2.0 * np.pi / n
    centres = heading + width * (np.arange(n) - (n - 1) / 2.0)
    weights = np.empty(n)
    for i, c in enumerate(centres):
        th = np.linspace(c - width / 2, c + width / 2, 33)
        weights[i] = integrate.simpson(cos2s_spreading(th, heading, spec.spreading_s), x=th)
    weights /= weights.sum()
    return centres, weights


def sea_directions(waves, omega) -> tuple[np.ndarray, np.ndarray]:
    """The energy of a sea by direction of travel on the frequencies ``omega`` (rad/s).

    ``waves``: a :class:`WaveSpec` or a :class:`~floatmoor.metocean.config.WaveSystems` (or
    None).  Every system's spectrum times the weight of each of its spreading directions
    (:func:`spreading_directions`); directions within 1e-9 rad of each other merged (their
    spectra added).  Returns ``(directions (n_dir,) rad, spectra (n_dir, n) m^2 s/rad)``, whose
    sum over directions is the sea's spectrum; (0,) and (0, n) without waves.  A single
    long-crested system gives its heading and its spectrum itself.
    """
    w = np.asarray(omega, float)
    dirs: list[float] = []
    spectra: list[np.ndarray] = []
    for spec in wave_systems(waves):
        s = wave_spectrum(spec, w)
        d, weight = spreading_directions(spec)
        for beta, f in zip(d, weight):
            for k, other in enumerate(dirs):
                if abs(math.remainder(float(beta) - other, 2.0 * math.pi)) < 1e-9:
                    spectra[k] = spectra[k] + s * f
                    break
            else:
                dirs.append(float(beta))
                spectra.append(s * f if f != 1.0 else s)
    return np.array(dirs, float), np.array(spectra, float).reshape(len(dirs), w.size)


"""Fatigue damage from tension spectra (Gaussian tension process, frequency domain).

Spectra are one-sided in ``omega`` (rad/s), units N^2 s/rad; spectral moments
``m_n = int omega^n S d omega``; rates in Hz (cycles per second).  Damage of a duration ``T`` (s)
on the T-N curve ``n = a_D s^-m`` with ``s`` the tension range over the RBS.  Every function
takes the standard deviations already divided by the RBS (``sigma / RBS``) through the moments
scaled by ``1/RBS^2`` -- :func:`moments` does it when given ``rbs``.

Methods
-------
* :func:`narrow_band` (Rayleigh ranges, Bendat): ``D = nu0 T (2 sqrt(2) sigma)^m
  Gamma(1 + m/2) / a_D``, ``nu0 = sqrt(m2/m0) / 2 pi``.  Exact for a narrow-band process,
  conservative otherwise.
* :func:`combined_spectrum` (DNV 2008 Ch.2 Sec.2 D, "combined spectrum"): narrow band on the sum
  of the LF and WF spectra, ``sigma^2 = sigma_L^2 + sigma_W^2``, ``nu_y = sqrt(lambda_L nu_L^2 +
  lambda_W nu_W^2)``, ``lambda = sigma_i^2 / sigma^2``.  Conservative for a bimodal tension.
* :func:`dual_narrow_band` (DNV 2008 Ch.2 Sec.2 D after Jiao & Moan 1990): the combined-spectrum
  damage times ``rho = nu_P/nu_y [lambda_L^(m/2+2) (1 - sqrt(lambda_W/lambda_L)) +
  sqrt(pi lambda_L lambda_W) m Gamma(m/2 + 1/2) / Gamma(m/2 + 1)] + nu_W/nu_y lambda_W^(m/2)``
  with ``nu_P = sqrt(lambda_L^2 nu_L^2 + lambda_L lambda_W nu_W^2 delta_W^2)`` and the WF
  bandwidth ``delta_W = sqrt(1 - m1^2/(m0 m2))`` (Vanmarcke 1972).
* :func:`dirlik` (Dirlik 1985): the empirical range density from ``m0, m1, m2, m4``, integrated
  in closed form, at the rate of peaks ``nu_p = sqrt(m4/m2) / 2 pi``.
* :func:`simple_summation`: ``D_L + D_W`` (narrow band on each; non-conservative, for reference).
"""

from __future__ import annotations

import math

import numpy as np

__all__ = [
    "METHODS",
    "bimodal_damage",
    "combined_spectrum",
    "dirlik",
    "dual_narrow_band",
    "gaussian_realisation",
    "moments",
    "narrow_band",
    "narrow_band_moments",
    "simple_summation",
]


def moments(omega, spectrum, orders=(0, 1, 2, 4), *, rbs: float = 1.0) -> np.ndarray:
    """Spectral moments ``m_n = int omega^n S d omega`` (trapezoid) of ``spectrum`` along its
    first axis (any trailing shape), divided by ``rbs^2``; shape ``(len(orders),) + trailing``."""
    w = np.asarray(omega, float)
    S = np.asarray(spectrum, float) / (rbs * rbs)
    shape = (-1,) + (1,) * (S.ndim - 1)
    return np.stack([np.trapezoid(S * (w ** k).reshape(shape), w, axis=0) for k in orders])


def _nb_factor(m: float) -> float:
    return 2.0 ** (1.5 * m) * math.gamma(1.0 + 0.5 * m)


def narrow_band_moments(m0, m2, duration: float, a_d: float, m: float):
    """Narrow-band damage from the moments ``m0`` (variance / RBS^2) and ``m2`` (rad^2/s^2)."""
    m0 = np.asarray(m0, float)
    m2 = np.asarray(m2, float)
    with np.errstate(divide="ignore", invalid="ignore"):
        nu0 = np.where(m0 > 0, np.sqrt(m2 / np.where(m0 > 0, m0, 1.0)), 0.0) / (2.0 * math.pi)
    return nu0 * duration * np.maximum(m0, 0.0) ** (0.5 * m) * _nb_factor(m) / a_d


def narrow_band(sigma, nu0, duration: float, a_d: float, m: float):
    """``D = nu0 T (2 sqrt(2) sigma)^m Gamma(1 + m/2) / a_D`` (``sigma`` over the RBS,
    ``nu0`` the zero up-crossing rate in Hz)."""
    return (np.asarray(nu0, float) * duration * (2.0 * math.sqrt(2.0) * np.asarray(sigma, float))
            ** m * math.gamma(1.0 + 0.5 * m) / a_d)


def _split(mom_l, mom_w):
    """sigma^2, nu (Hz) of each band and their lambdas from moment stacks (0, 1, 2, 4)."""
    s2l, s2w = mom_l[0], mom_w[0]
    s2 = s2l + s2w
    with np.errstate(divide="ignore", invalid="ignore"):
        nul = np.where(s2l > 0, np.sqrt(mom_l[2] / np.where(s2l > 0, s2l, 1)), 0) / (2 * math.pi)
        nuw = np.where(s2w > 0, np.sqrt(mom_w[2] / np.where(s2w > 0, s2w, 1)), 0) / (2 * math.pi)
        lam_l = np.where(s2 > 0, s2l / np.where(s2 > 0, s2, 1), 0.0)
    return s2l, s2w, s2, nul, nuw, lam_l, 1.0 - lam_l


def combined_spectrum(mom_l, mom_w, duration: float, a_d: float, m: float):
    """DNV (2008) combined-spectrum damage from the moment stacks of the LF and WF tension
    (orders 0, 1, 2, 4 over RBS^2)."""
    _, _, s2, nul, nuw, lam_l, lam_w = _split(np.asarray(mom_l), np.asarray(mom_w))
    nuy = np.sqrt(lam_l * nul ** 2 + lam_w * nuw ** 2)
    return narrow_band(np.sqrt(s2), nuy, duration, a_d, m)


def dual_narrow_band(mom_l, mom_w, duration: float, a_d: float, m: float):
    """DNV (2008) dual narrow-band damage (Jiao & Moan 1990): combined-spectrum damage times
    the correction ``rho`` of the module docstring."""
    mom_l, mom_w = np.asarray(mom_l, float), np.asarray(mom_w, float)
    _, s2w, s2, nul, nuw, lam_l, lam_w = _split(mom_l, mom_w)
    with np.errstate(divide="ignore", invalid="ignore"):
        delta_w = np.sqrt(np.clip(1.0 - mom_w[1] ** 2 / (mom_w[0] * mom_w[2]), 0.0, 1.0))
        delta_w = np.where(s2w > 0, delta_w, 0.0)
        nuy = np.sqrt(lam_l * nul ** 2 + lam_w * nuw ** 2)
        nup = np.sqrt(lam_l ** 2 * nul ** 2 + lam_l * lam_w * nuw ** 2 * delta_w ** 2)
        ratio = np.sqrt(np.where(lam_l > 0, lam_w / np.where(lam_l > 0, lam_l, 1.0), 0.0))
        g = m * math.gamma(0.5 * m + 0.5) / math.gamma(0.5 * m + 1.0)
        rho = (nup / nuy * (lam_l ** (0.5 * m + 2.0) * (1.0 - ratio)
                            + np.sqrt(math.pi * lam_l * lam_w) * g)
               + nuw / nuy * lam_w ** (0.5 * m))
        rho = np.where(nuy > 0, rho, 0.0)
    d_c = narrow_band(np.sqrt(s2), nuy, duration, a_d, m)
    return rho * d_c


def dirlik(mom, duration: float, a_d: float, m: float):
    """Dirlik (1985) damage from the moment stack (orders 0, 1, 2, 4 over RBS^2)."""
    m0, m1, m2, m4 = (np.asarray(x, float) for x in mom)
    with np.errstate(divide="ignore", invalid="ignore"):
        xm = m1 / m0 * np.sqrt(m2 / m4)
        gam = m2 / np.sqrt(m0 * m4)
        d1 = 2.0 * (xm - gam ** 2) / (1.0 + gam ** 2)
        r = (gam - xm - d1 ** 2) / (1.0 - gam - d1 + d1 ** 2)
        d2 = (1.0 - gam - d1 + d1 ** 2) / (1.0 - r)
        d3 = 1.0 - d1 - d2
        q = 1.25 * (gam - d3 - d2 * r) / d1
        nup = np.sqrt(m4 / m2) / (2.0 * math.pi)
        e_sm = (2.0 * np.sqrt(m0)) ** m * (d1 * q ** m * math.gamma(1.0 + m)
                                          + 2.0 ** (0.5 * m) * math.gamma(1.0 + 0.5 * m)
                                          * (d2 * np.abs(r) ** m + d3))
        out = nup * duration * e_sm / a_d
    return np.where(m0 > 0, out, 0.0)


def simple_summation(mom_l, mom_w, duration: float, a_d: float, m: float):
    """``D_L + D_W``, narrow band on each band separately (non-conservative)."""
    mom_l, mom_w = np.asarray(mom_l, float), np.asarray(mom_w, float)
    return (narrow_band_moments(mom_l[0], mom_l[2], duration, a_d, m)
            + narrow_band_moments(mom_w[0], mom_w[2], duration, a_d, m))


METHODS = ("combined_spectrum", "dual_narrow_band", "dirlik", "simple_summation")
"""Spectral methods for a bimodal (LF + WF) tension, by name."""


def bimodal_damage(method: str, mom_l, mom_w, duration: float, a_d: float, m: float):
    """Damage of an LF + WF tension by ``method`` (one of :data:`METHODS`); ``mom_l``, ``mom_w``
    the moment stacks (orders 0, 1, 2, 4, over RBS^2; the bands assumed uncorrelated).  Dirlik
    uses the moments of the sum."""
    if method == "combined_spectrum":
        return combined_spectrum(mom_l, mom_w, duration, a_d, m)
    if method == "dual_narrow_band":
        return dual_narrow_band(mom_l, mom_w, duration, a_d, m)
    if method == "dirlik":
        return dirlik(np.asarray(mom_l, float) + np.asarray(mom_w, float), duration, a_d, m)
    if method == "simple_summation":
        return simple_summation(mom_l, mom_w, duration, a_d, m)
    raise KeyError(f"unknown spectral method {method!r}; methods: {', '.join(METHODS)}")


def gaussian_realisation(omega, spectrum, duration: float, dt: float, seed: int = 0):
    """A stationary Gaussian history with the one-sided spectrum ``S(omega)`` (linear
    interpolation, zero outside the given range): random phases on the FFT grid of the record
    (``d omega = 2 pi / duration``), deterministic amplitudes ``sqrt(2 S d omega)``.  Returns
    ``(t, x)``; the record is periodic with period ``duration``."""
    n = round(duration / dt)
    n += n % 2
    dw = 2.0 * math.pi / (n * dt)
    wk = np.arange(n // 2 + 1) * dw
    Sk = np.interp(wk, np.asarray(omega, float), np.asarray(spectrum, float), left=0.0,
                   right=0.0)
    amp = np.sqrt(2.0 * Sk * dw)
    amp[0] = 0.0
    amp[-1] = 0.0
    phase = np.random.default_rng(seed).uniform(0.0, 2.0 * math.pi, wk.size)
    x = np.fft.irfft(amp * np.exp(1j * phase) * (n / 2.0), n)
    return np.arange(n) * dt, x

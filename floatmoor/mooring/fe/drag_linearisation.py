"""Stochastic (Gaussian) linearisation of Morison drag for the frequency-domain line model.

A drag force ``f = k |u| u`` on a relative velocity ``u`` that is Gaussian with mean ``m`` (the
current) and covariance ``Sigma`` (the line's own motion) is replaced by the mean force plus a
linear damping on the fluctuation, ``C = E[df/du]`` (the equivalent linearisation that minimises
the mean square error for Gaussian inputs: Atalik & Utku's form of the least-squares
linearisation; ANSYS (2013) eq. 9-75 takes the drag damping of a dynamic cable from the RMS of
the relative velocity over all frequencies in the same way).

- one direction (tangential drag): ``C = 2 k E|u|`` with
  ``E|u| = s sqrt(2/pi) exp(-m^2 / 2 s^2) + m erf(m / (s sqrt 2))``; without current
  ``C = sqrt(8/pi) k s`` (Borgman's result).
- the normal plane (two directions): ``C = k E[|u| I + u u^T / |u|]``, evaluated in the
  principal axes of ``Sigma``: Gauss-Legendre along the major axis split at the kink ``u = 0``,
  Gauss-Hermite along the minor axis (exact for the rank-one covariance of a line moving in its
  own plane).
"""

from __future__ import annotations

import math

import numpy as np
from numpy.polynomial.hermite_e import hermegauss
from numpy.polynomial.legendre import leggauss
from scipy.special import erf

__all__ = ["drag_damping_1d", "drag_damping_2d", "mean_abs_gaussian"]

_XL, _WL = leggauss(16)
_XH, _WH = hermegauss(16)
_WH = _WH / math.sqrt(2.0 * math.pi)
_SPAN = 8.0


def mean_abs_gaussian(m, s):
    """``E|u|`` for ``u ~ N(m, s^2)`` (arrays broadcast); ``|m|`` where ``s = 0``."""
    m = np.asarray(m, float)
    s = np.asarray(s, float)
    ss = np.where(s > 0, s, 1.0)
    val = (ss * math.sqrt(2.0 / math.pi) * np.exp(-0.5 * (m / ss) ** 2)
           + m * erf(m / (ss * math.sqrt(2.0))))
    return np.where(s > 0, val, np.abs(m))


def drag_damping_1d(k, m, s):
    """Linearised damping ``2 k E|u|`` (N s/m) of ``f = k |u| u``, ``u ~ N(m, s^2)``."""
    return 2.0 * np.asarray(k, float) * mean_abs_gaussian(m, s)


def _major_rule(c):
    """Nodes and weights (standard normal weight included) on [-8, 8] split at ``c`` (n,)."""
    c = np.clip(c, -_SPAN, _SPAN)
    a = np.stack([np.full_like(c, -_SPAN), c], axis=1)      # (n, 2) lower ends
    b = np.stack([c, np.full_like(c, _SPAN)], axis=1)
    h = 0.5 * (b - a)
    x = 0.5 * (a + b)[..., None] + h[..., None] * _XL        # (n, 2, q)
    w = h[..., None] * _WL * np.exp(-0.5 * x * x) / math.sqrt(2.0 * math.pi)
    n = c.shape[0]
    return x.reshape(n, -1), w.reshape(n, -1)


def drag_damping_2d(k, mean, cov):
    """Linearised damping matrices ``k E[|u| I + u u^T / |u|]`` (n, 2, 2) for ``n`` Gaussian
    2-vectors with means ``mean`` (n, 2) and covariances ``cov`` (n, 2, 2), drag factors ``k``
    (n,) (N s^2/m^2)."""
    mean = np.asarray(mean, float)
    cov = np.asarray(cov, float)
    lam, V = np.linalg.eigh(0.5 * (cov + np.swapaxes(cov, 1, 2)))   # ascending
    lam = np.maximum(lam, 0.0)
    mp = np.einsum("nji,nj->ni", V, mean)                  # mean in the principal axes
    s1 = np.sqrt(lam[:, 1])
    s2 = np.sqrt(lam[:, 0])
    # kink of the major axis at u1' = 0
    safe = np.where(s1 > 0, s1, 1.0)
    c = np.where(s1 > 0, -mp[:, 1] / safe, 0.0)
    x1, w1 = _major_rule(c)                                # (n, q1)
    u1 = mp[:, 1, None, None] + s1[:, None, None] * x1[:, :, None]      # (n, q1, 1)
    u2 = mp[:, 0, None, None] + s2[:, None, None] * _XH[None, None, :]  # (n, 1, q2)
    u1, u2 = np.broadcast_arrays(u1, u2)
    w = w1[:, :, None] * _WH[None, None, :]
    r = np.sqrt(u1 * u1 + u2 * u2)
    rs = np.where(r > 0, r, 1.0)
    e_r = np.sum(w * r, axis=(1, 2))
    a11 = np.sum(w * np.where(r > 0, u1 * u1 / rs, 0.0), axis=(1, 2))
    a22 = np.sum(w * np.where(r > 0, u2 * u2 / rs, 0.0), axis=(1, 2))
    a12 = np.sum(w * np.where(r > 0, u1 * u2 / rs, 0.0), axis=(1, 2))
    # matrix in the principal axes (order: minor = 0, major = 1)
    Cp = np.empty((mean.shape[0], 2, 2))
    Cp[:, 0, 0] = e_r + a22
    Cp[:, 1, 1] = e_r + a11
    Cp[:, 0, 1] = Cp[:, 1, 0] = a12
    C = np.einsum("nij,njk,nlk->nil", V, Cp, V)
    return np.asarray(k, float)[:, None, None] * C

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

from .frequency_kernels import drag_2d

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


def drag_damping_2d(k, mean, cov):
    """Linearised damping matrices ``k E[|u| I + u u^T / |u|]`` (n, 2, 2) for ``n`` Gaussian
    2-vectors with means ``mean`` (n, 2) and covariances ``cov`` (n, 2, 2), drag factors ``k``
    (n,) (N s^2/m^2)."""
    mean = np.ascontiguousarray(mean, float)
    cov = np.ascontiguousarray(cov, float)
    k = np.ascontiguousarray(np.broadcast_to(np.asarray(k, float), mean.shape[:1]))
    out = np.empty((mean.shape[0], 2, 2))
    drag_2d(k, mean, cov, _XL, _WL, _XH, _WH, _SPAN, out)
    return out

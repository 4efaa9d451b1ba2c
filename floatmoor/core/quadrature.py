"""Quadrature weights shared by the frequency-domain computations."""

from __future__ import annotations

import numpy as np

__all__ = ["trapezoid_weights"]


def trapezoid_weights(w) -> np.ndarray:
    """Weights of the trapezoidal rule on the (possibly uneven) grid ``w``: ``sum(q * f)``
    equals ``numpy.trapezoid(f, w)``."""
    dw = np.diff(w)
    q = np.zeros_like(w)
    q[:-1] += 0.5 * dw
    q[1:] += 0.5 * dw
    return q

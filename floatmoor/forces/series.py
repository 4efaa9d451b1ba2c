"""Sums of many harmonics on a uniform time grid: by FFT when the frequencies lie on a grid.

A realisation with frequencies ``w_k = w0 + m_k dw`` (integers ``m_k``) and a sampling step
``h`` with ``dw h = 2 pi / N`` (integer ``N``) gives

    sum_k c_k exp(i w_k t_j) = exp(i w0 t_j) * N * ifft(C)[j mod N],   C[m_k] += c_k

exactly (to round-off), at a cost of one FFT of length N instead of n_components x n_samples
cosines.  :func:`grid_for` chooses such a grid; :func:`complex_envelope` evaluates a sum either
way (FFT on a grid, direct sum otherwise, e.g. a regular wave of arbitrary frequency).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..metocean.realisation import derived_seed

__all__ = ["FrequencyGrid", "grid_for", "complex_envelope", "harmonic_sum", "derived_seed"]


@dataclass(frozen=True)
class FrequencyGrid:
    """Frequencies ``w0 + m dw`` (rad/s) sampled every ``h`` s with ``dw h N = 2 pi``."""

    w0: float
    dw: float
    h: float
    N: int

    @property
    def repeat_period(self) -> float:
        """Period (s) after which a sum on this grid repeats."""
        return self.N * self.h


def _good_size(n: int) -> int:
    """Smallest 2^a 3^b 5^c >= n (fast FFT sizes)."""
    best = 1 << max(0, (n - 1).bit_length())
    p5 = 1
    while p5 < best:
        p35 = p5
        while p35 < best:
            v = p35
            while v < n:
                v *= 2
            best = min(best, v)
            p35 *= 3
        p5 *= 5
    return best


def grid_for(omega_min: float, dw_max: float, h: float, min_period: float) -> FrequencyGrid:
    """A grid with step <= ``dw_max`` (rad/s) and repeat period >= ``min_period`` (s).

    The bins start at ``omega_min``; the first frequency (bin centre) is ``omega_min + dw/2``.
    """
    n_req = max(int(math.ceil(2.0 * math.pi / (dw_max * h) - 1e-9)),
                int(math.ceil(min_period / h - 1e-9)), 8)
    N = _good_size(n_req)
    dw = 2.0 * math.pi / (N * h)
    return FrequencyGrid(w0=float(omega_min) + 0.5 * dw, dw=dw, h=float(h), N=N)


def _on_grid(omega: np.ndarray, grid: FrequencyGrid | None):
    if grid is None or omega.size == 0:
        return None
    m = (omega - grid.w0) / grid.dw
    mi = np.rint(m)
    if np.all(np.abs(m - mi) < 1e-6) and mi.min() >= 0 and mi.max() < grid.N:
        return mi.astype(np.int64)
    return None


def complex_envelope(omega, coeffs, n_samples: int, h: float, grid: FrequencyGrid | None = None,
                     *, carrier: bool = True) -> np.ndarray:
    """``sum_k coeffs[k, ...] exp(i omega_k t_j)`` at ``t_j = j h``, j < n_samples.

    omega : (n,) rad/s; coeffs : (n, ...) complex.  With ``carrier=False`` the common factor
    ``exp(i w0 t)`` of a grid is left out (the slowly varying envelope, for products such as the
    drift force where it cancels); without a grid the direct sum is always returned with its
    carrier (``carrier=False`` is then refused).  Returns (n_samples, ...) complex.
    """
    omega = np.asarray(omega, float)
    coeffs = np.asarray(coeffs, complex)
    tail = coeffs.shape[1:]
    idx = _on_grid(omega, grid)
    j = np.arange(n_samples)
    if idx is not None and abs(grid.h - h) <= 1e-12 * h:
        C = np.zeros((grid.N,) + tail, complex)
        np.add.at(C, idx, coeffs)
        s = np.fft.ifft(C, axis=0) * grid.N
        out = s[j % grid.N]
        if carrier:
            ph = np.exp(1j * ((grid.w0 * h) * j % (2.0 * np.pi)))
            out = out * ph.reshape((-1,) + (1,) * len(tail))
        return out
    if not carrier:
        raise ValueError("carrier=False needs frequencies on the grid")
    out = np.zeros((n_samples,) + tail, complex)
    t = j * h
    for k in range(omega.size):  # few components (regular waves, tests)
        out += np.exp(1j * omega[k] * t).reshape((-1,) + (1,) * len(tail)) * coeffs[k]
    return out


def harmonic_sum(omega, coeffs, n_samples: int, h: float, grid: FrequencyGrid | None = None):
    """Real part of :func:`complex_envelope`: ``sum_k Re(c_k exp(i w_k t_j))``."""
    return complex_envelope(omega, coeffs, n_samples, h, grid).real

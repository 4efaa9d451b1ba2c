"""Sums of decaying exponentials fitted to retardation functions: the recursive (state-space)
radiation memory of the scene option ``solver: {memory: state_space}``.

The time loop's convolution (:mod:`floatmoor.solvers.td_kernel`) needs, once per step, the sum
``S_{n+1} = sum_{j>=1} K_j v_{n+1-j}`` of the sampled retardation function ``K_j = K(j dt)`` of
a DOF pair with the past velocities.  With ``K_j ~ Re sum_r c_r z_r^j`` (|z_r| < 1) it is
``Re sum_r c_r y_r(n+1)`` with the recursion ``y_r(n+1) = z_r (v_n + y_r(n))``, y_r(0) = 0: a
discrete-time state-space realisation of the memory (Kristiansen et al. (2005); Perez & Fossen
(2009) review the identification methods), a few complex multiplications per pair and step
instead of a sum over the whole memory (1200 samples of the flagship's 120 s at dt 0.1 s).  The
rest of the scheme (the instantaneous ``K_0`` term, the interpolation between steps) is the
convolution's, so the only approximation is the fit of ``K_j``, j >= 1.

Fit: the exponents by the eigensystem realisation (Kung (1978): SVD of the Hankel matrix of the
samples, on every ``decimate``-th sample), the smallest order whose least-squares residues
(on every sample) reach ``rel_tol`` (relative L2 error over j >= 1); unstable roots dropped.
The sum of the samples (the memory at zero frequency, which damps the slow drift) is kept to
round-off by a heavily weighted row of the least squares.

Accuracy on the flagship storm (3 hours, seed 1, benchmarks/RESULTS.md): fits of 0.2-0.9 %,
max offset and max tension within 0.03-0.07 % of the convolution, the order of the time-step
error at dt = 0.1 s; standard deviations within 0.03 %.
"""

from __future__ import annotations

import numpy as np

__all__ = ["fit_exponentials", "FIT_REL_TOL", "MAX_ORDER"]

FIT_REL_TOL = 0.01
"""Relative L2 error of the fitted retardation function (j >= 1) to reach."""

MAX_ORDER = 60
"""Largest ERA order tried (the roots kept, one per conjugate pair, are about half of it)."""


def _hankel_svd(k: np.ndarray, decimate: int):
    """The Hankel matrices of ``k`` (every ``decimate``-th sample) and the SVD of the first:
    computed once per DOF pair and shared by every order tried."""
    y = k[::decimate]
    m = (y.size - 1) // 2
    H = np.array([y[i:i + m] for i in range(m)])
    H1 = np.array([y[i + 1:i + 1 + m] for i in range(m)])
    U, s, Vt = np.linalg.svd(H)
    return H1, U, s, Vt


def _roots(hankel, order: int, decimate: int) -> np.ndarray:
    """Discrete roots z (per sample) of an ERA realisation of the given order from
    :func:`_hankel_svd`."""
    H1, U, s, Vt = hankel
    r = min(order, int(np.sum(s > s[0] * 1e-12)))
    if r == 0:
        return np.zeros(0, complex)
    Si = 1.0 / np.sqrt(s[:r])
    A = (Si[:, None] * U[:, :r].T) @ H1 @ (Vt[:r].T * Si[None, :])
    mu = np.linalg.eigvals(A).astype(complex)
    mu = mu[(np.abs(mu) < 1.0) & (np.abs(mu) > 0.0)]
    return np.exp(np.log(mu) / decimate)


def _residues(k: np.ndarray, z: np.ndarray):
    """Least-squares residues c of ``k_j ~ Re sum c_r z_r^j`` (j = 1..n) over the roots with
    Im z >= 0 (a conjugate pair as one complex root), and the fitted samples."""
    z = z[z.imag >= -1e-14]
    j = np.arange(1, k.size + 1)
    phi = z[None, :] ** j[:, None]
    basis = np.hstack([phi.real, -phi.imag[:, np.abs(z.imag) > 1e-14]])
    # the sum of the samples (the zero-frequency memory: the slow drift's radiation force)
    # as a heavily weighted row, i.e. kept to round-off
    w = 1e3 * np.sqrt(k.size)
    a = np.vstack([basis, w * basis.sum(axis=0)])
    coef, *_ = np.linalg.lstsq(a, np.append(k, w * k.sum()), rcond=None)
    c = coef[:z.size].astype(complex)
    c[np.abs(z.imag) > 1e-14] += 1j * coef[z.size:]
    return z, c, basis @ coef


def fit_exponentials(k, *, rel_tol: float = FIT_REL_TOL, max_order: int = MAX_ORDER,
                     decimate: int = 5):
    """Fit ``k_j ~ Re sum_r c_r z_r^j`` to the samples ``k`` = (K_1, K_2, ...) of one DOF pair.

    Returns ``(z, c, err)``: complex roots (|z| < 1) and residues, and the relative L2 error of
    the fit; the smallest order reaching ``rel_tol`` (else the best up to ``max_order``)."""
    k = np.asarray(k, float)
    norm = float(np.sqrt(np.sum(k * k)))
    if norm == 0.0:
        return np.zeros(0, complex), np.zeros(0, complex), 0.0
    decimate = max(1, min(decimate, k.size // 40))
    best = (np.zeros(0, complex), np.zeros(0, complex), 1.0)
    hankel = _hankel_svd(k, decimate)
    for order in range(2, max_order + 1, 2):
        z, c, fit = _residues(k, _roots(hankel, order, decimate))
        err = float(np.sqrt(np.sum((fit - k) ** 2)) / norm)
        if err < best[2]:
            best = (z, c, err)
        if err <= rel_tol:
            break
    return best

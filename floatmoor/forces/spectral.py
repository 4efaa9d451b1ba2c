"""Frequency-domain forms of the wave and wind forces (plain arrays in and out).

The force models' ``frequency_domain`` hooks (:mod:`floatmoor.forces.waves`,
:mod:`floatmoor.forces.environment`, :mod:`floatmoor.forces.wave_drift_damping`) build their
mean forces, force spectra and damping with these functions; the frequency-domain solver
(:mod:`floatmoor.solvers.frequency_domain`) re-exports them.  Conventions: one-sided spectra
in rad/s, SI units, exp(+i w t); equation numbers are Wang (2016)'s.

A sea of several directions (wave systems, directional spreading) is given as the spectra
``S_d(w)`` of its directions ``d`` and the coefficients ``C_d`` at each direction.  First-order
responses and mean drift add over the directions; the slowly varying drift force of Newman's
approximation couples every pair of components, across directions too, with the arithmetic
mean of their coefficients ``T_jk = (C_j + C_k)/2`` -- the rule of the time domain's
:class:`~floatmoor.forces.waves.DriftNewman`, which writes ``F = Re[A_D conj(A)]`` over all
components (:func:`newman_drift_spectrum_directions`).
"""

from __future__ import annotations

import math

import numpy as np

from ..core.quadrature import trapezoid_weights
from ..hydro.database import interpolate_heading

__all__ = ["DEFAULT_D_OMEGA", "wave_frequency_grid", "interp0", "mean_drift_force", "newman_drift_spectrum",
           "newman_drift_spectrum_directions", "qtf_drift_spectrum", "gust_force_spectrum",
           "aranha_drift_damping", "qtf_function"]


DEFAULT_D_OMEGA = 0.005
"""rad/s, the default step of the wave-frequency grid (``frequency_domain: d_omega``)."""


def wave_frequency_grid(db, d_omega: float = DEFAULT_D_OMEGA) -> np.ndarray:
    """The wave-frequency grid (rad/s) of the frequency domain: the database's frequency range
    in steps of about ``d_omega`` (at least as many points as the database has)."""
    w_db = np.asarray(db["omega"].values, float)
    n_w = int(round((w_db[-1] - w_db[0]) / d_omega)) + 1
    return np.linspace(w_db[0], w_db[-1], max(n_w, w_db.size))


def _trapz(y, x, axis=0):
    return np.trapezoid(y, x, axis=axis)


def interp0(x_new, x, y):
    """Linear interpolation along axis 0 of y (any trailing shape), constant outside."""
    x = np.asarray(x, float)
    idx = np.clip(np.searchsorted(x, x_new) - 1, 0, x.size - 2)
    f = np.clip((x_new - x[idx]) / (x[idx + 1] - x[idx]), 0.0, 1.0)
    f = f.reshape((-1,) + (1,) * (np.ndim(y) - 1))
    return (1.0 - f) * y[idx] + f * y[idx + 1]


def mean_drift_force(omega, s_eta, coefficients):
    """Mean wave drift force 2 int C(w) S(w) dw (eq. 2.37/2.39), (6,) N and N m.

    coefficients : (n, 6) mean drift force per squared wave amplitude C_wa(w), N/m^2."""
    return 2.0 * _trapz(np.asarray(coefficients, float) * np.asarray(s_eta, float)[:, None],
                        np.asarray(omega, float))


def newman_drift_spectrum(omega, s_eta, coefficients, mu):
    """Slowly varying drift force cross-spectra by Newman's approximation (eq. 2.38):

        S_ij(mu) = 8 int C_i(w + mu/2) C_j(w + mu/2) S(w) S(w + mu) dw.

    Parameters
    ----------
    omega : (n,) uniform or not, rad/s; s_eta : (n,) wave spectrum m^2 s/rad.
    coefficients : (n, d) mean drift coefficients C_wa(w) (N/m^2); zero outside the grid.
    mu : (m,) difference frequencies, rad/s (>= 0).

    Returns
    -------
    (m, d, d) real, N^2 s/rad (N^2 m^2 s/rad for moments).
    """
    w = np.asarray(omega, float)
    s = np.asarray(s_eta, float)
    C = np.asarray(coefficients, float)
    mu = np.asarray(mu, float)
    d = C.shape[1]
    q = trapezoid_weights(w) * s
    out = np.zeros((mu.size, d, d))
    for a in range(0, mu.size, 128):  # blocks of difference frequencies, vectorised
        mb = mu[a:a + 128]
        s2 = np.interp((w[None, :] + mb[:, None]).ravel(), w, s, right=0.0)
        s2 = s2.reshape(mb.size, w.size)
        wm = (w[None, :] + 0.5 * mb[:, None]).ravel()
        cm = np.stack([np.interp(wm, w, C[:, j], right=0.0).reshape(mb.size, w.size)
                       for j in range(d)], axis=-1)  # (block, n, d)
        out[a:a + mb.size] = 8.0 * np.matmul(np.swapaxes(cm * (q * s2)[..., None], 1, 2), cm)
    return out


def newman_drift_spectrum_directions(omega, spectra, coefficients, mu):
    """:func:`newman_drift_spectrum` of a sea of several directions.

    ``spectra`` (n_dir, n) the elevation spectrum of each direction, ``coefficients``
    (n_dir, n, d) its mean drift coefficients.  Every pair of components, within and across
    directions, carries ``T = (C_j + C_k)/2`` (module docstring), so

        S_ij(mu) = 8 int sum_{d,e} T_i T_j S_d(w) S_e(w + mu) dw,  T = (C_d + C_e)(w + mu/2)/2,

    summed in O(n_dir) as ``2 int (A2 B0 + A1 B1^T + B1 A1^T + A0 B2) dw`` with
    ``A_k = sum_d C_d^(k) S_d(w)`` and ``B_k`` likewise with ``S_d(w + mu)`` (``C^(0) = 1``,
    ``C^(1) = C``, ``C^(2) = C C^T``).  One direction: exactly :func:`newman_drift_spectrum`.
    """
    spectra = np.asarray(spectra, float)
    coefficients = np.asarray(coefficients, float)
    if spectra.shape[0] == 1:
        return newman_drift_spectrum(omega, spectra[0], coefficients[0], mu)
    w = np.asarray(omega, float)
    mu = np.asarray(mu, float)
    d_all = coefficients.shape[2]
    used = np.nonzero(np.any(coefficients != 0.0, axis=(0, 1)))[0]  # DOFs with a drift force
    coefficients = coefficients[:, :, used]
    n_dir, d = spectra.shape[0], used.size
    q = trapezoid_weights(w)
    out = np.zeros((mu.size, d, d))
    for a in range(0, mu.size, 64):
        mb = mu[a:a + 64]
        s2 = _interp_right0(w, spectra.T, (w[None, :] + mb[:, None]))      # (b, n, n_dir)
        cm = _interp_right0(w, coefficients.transpose(1, 0, 2).reshape(w.size, -1),
                            (w[None, :] + 0.5 * mb[:, None]))
        cm = cm.reshape(mb.size, w.size, n_dir, d)                        # (b, n, n_dir, d)
        s1 = spectra.T[None]                                               # (1, n, n_dir)
        b0 = s2.sum(axis=-1)                                               # (b, n)
        a0 = s1.sum(axis=-1)                                               # (1, n)
        wgt = q[None, :, None] * (s1 * b0[..., None] + a0[..., None] * s2)  # (b, n, n_dir)
        cw = (cm * wgt[..., None]).reshape(mb.size, -1, d)
        t14 = np.matmul(np.swapaxes(cw, 1, 2), cm.reshape(mb.size, -1, d))
        a1 = np.einsum("bnkj,nk->bnj", cm, q[:, None] * spectra.T)          # (b, n, d)
        b1 = np.einsum("bnkj,bnk->bnj", cm, s2)
        t2 = np.matmul(np.swapaxes(a1, 1, 2), b1)
        out[a:a + mb.size] = 2.0 * (t14 + t2 + np.swapaxes(t2, 1, 2))
    full = np.zeros((mu.size, d_all, d_all))
    full[:, used[:, None], used[None, :]] = out
    return full


def _interp_right0(x, table, x_new):
    """``table`` (n, ...) linearly interpolated along axis 0 at ``x_new`` (any shape, each
    >= x[0]) on the increasing grid ``x``; zero beyond ``x[-1]`` (as ``np.interp(...,
    right=0.0)``).  Returns ``x_new.shape + table.shape[1:]``."""
    x_new = np.asarray(x_new, float)
    i = np.clip(np.searchsorted(x, x_new, side="right") - 1, 0, x.size - 2)
    f = (x_new - x[i]) / (x[i + 1] - x[i])
    f = f.reshape(f.shape + (1,) * (table.ndim - 1))
    out = (1.0 - f) * table[i] + f * table[i + 1]
    out[x_new > x[-1]] = 0.0
    return out


def qtf_drift_spectrum(omega, s_eta, qtf, mu):
    """Slowly varying drift force cross-spectra from a full difference-frequency QTF:

        S_ij(mu) = 8 int Re[Q_i(w, w + mu) conj(Q_j(w, w + mu))] S(w) S(w + mu) dw.

    qtf : callable (w1 (n,), w2 (n,)) -> (n, d) complex, the QTF per squared amplitude at the
    frequency pairs (zero outside its grid).  With Q(w1, w2) = C((w1 + w2)/2) this equals
    :func:`newman_drift_spectrum`."""
    w = np.asarray(omega, float)
    s = np.asarray(s_eta, float)
    mu = np.asarray(mu, float)
    q = trapezoid_weights(w) * s
    out = None
    for a in range(0, mu.size, 128):  # blocks of difference frequencies, vectorised
        mb = mu[a:a + 128]
        w2 = (w[None, :] + mb[:, None]).ravel()
        s2 = np.interp(w2, w, s, right=0.0).reshape(mb.size, w.size)
        Q = np.asarray(qtf(np.tile(w, mb.size), w2), complex)
        Q = Q.reshape(mb.size, w.size, -1)
        if out is None:
            out = np.zeros((mu.size, Q.shape[-1], Q.shape[-1]))
        out[a:a + mb.size] = 8.0 * np.real(
            np.matmul(np.swapaxes(Q * (q * s2)[..., None], 1, 2), np.conj(Q)))
    return out


def gust_force_spectrum(force_per_gust, s_u):
    """Wind gust force cross-spectra 4 U^2 C C^T S_u(mu) = b b^T S_u with b = dF/du = 2 U C.

    force_per_gust : (6,) b = 2 U C (N s/m, N s for moments); s_u : (m,) gust spectrum of the
    longitudinal wind speed in rad/s, m^2/s^2 s/rad.  Returns (m, 6, 6) real."""
    b = np.asarray(force_per_gust, float)
    return np.asarray(s_u, float)[:, None, None] * np.outer(b, b)[None]


def aranha_drift_damping(omega, s_eta, coefficient_along, gravity, direction):
    """Wave drift damping, Aranha's deep-water formula along the wave direction:

        b = 2 int S(w) (w/g) (4 C(w) + w dC/dw) dw,   B = b e e^T (surge/sway block)

    with C the mean drift coefficient along the direction of travel e = (cos, sin).
    Returns (6, 6).  (Aranha 1994, J. Fluid Mech.; as in DNV-RP-C205 sec. 7.4.)"""
    w = np.asarray(omega, float)
    C = np.asarray(coefficient_along, float)
    dC = np.gradient(C, w)
    b = 2.0 * _trapz(np.asarray(s_eta) * (w / gravity) * (4.0 * C + w * dC), w)
    e = np.array([math.cos(direction), math.sin(direction)])
    B = np.zeros((6, 6))
    B[:2, :2] = b * np.outer(e, e)
    return B


def qtf_function(db, heading_rel: float, T: np.ndarray):
    """Callable (w1, w2) -> (n, 6) complex QTF at the relative heading, earth axes (``T`` the
    (6, 6) rotation to earth axes); bilinear in (w1, w2), zero outside the QTF grid."""
    from scipy.interpolate import RegularGridInterpolator
    q = interpolate_heading(db, "difference_frequency_qtf", heading_rel, dim="qtf_wave_direction")
    w1 = np.asarray(db["qtf_omega"].values, float)
    w2 = np.asarray(db["qtf_omega_2"].values, float)
    q = np.nan_to_num(q) @ T.T
    re = RegularGridInterpolator((w1, w2), q.real, bounds_error=False, fill_value=0.0)
    im = RegularGridInterpolator((w1, w2), q.imag, bounds_error=False, fill_value=0.0)

    def f(a, b):
        pts = np.column_stack([a, b])
        return re(pts) + 1j * im(pts)
    return f

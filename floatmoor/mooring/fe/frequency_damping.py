"""Low-frequency mooring-line damping of a FE line from its frequency response.

The slow (LF) horizontal motion of a moored floater is damped to a large part by the drag on
the mooring lines: the line is dragged sideways through the water as the fairlead moves, and
the wave-frequency (WF) motion of the line, superposed on the slow one, raises the drag's
linearised damping (Lie, Gao & Moan (2007); Yang, Chen & Huang (2016)).  Here the lumped-mass
FE line of :mod:`~floatmoor.mooring.fe.frequency` (ANSYS (2013) eq. 9-75: structural and added
mass, axial and geometric stiffness about the static shape, internal damping, drag linearised
stochastically about the current) is driven at its fairlead by several uncorrelated *bands* of
motion (the WF and the LF fairlead cross-spectra); the drag is linearised with the node velocity
covariance summed over the bands and iterated to convergence.  The line's fairlead impedance

    Z(w) = -dF/dx_f = (K_e + i w C_e)(I - X_{n-2}(w)) + i w C_d,f          (3 x 3, complex)

(``F`` the force of the line on the fairlead, ``K_e, C_e`` the stiffness and internal damping
of the top element, ``X_{n-2}`` the motion of the node below the fairlead per unit fairlead
displacement, ``C_d,f`` the linearised drag of the fairlead node itself, which the coupled time
domain also applies to the body) is then evaluated at the requested frequencies: its real part
is the line's dynamic stiffness (the quasi-static catenary stiffness in the limit w -> 0) and
``Im Z / w`` the line's damping matrix at the fairlead (N s/m).

Seabed: by default every node free with vertical springs on the nodes in static contact
(``"fe"``: no cut parameter and the whole line's drag), each spring the slope of the FE line's
own smoothed contact law at the node's static penetration, so that the static limit is the FE
line's tangent stiffness; seabed friction is left out as in the frequency response.
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass

import numpy as np

from ...core.errors import FloatmoorWarning
from ...core.quadrature import trapezoid_weights
from .frequency import (
    SEABED_FD_MODELS,
    _assemble,
    _drag_damping,
    _mask,
    _normal_basis,
    _transfer,
    line_statics,
)
from .frequency_kernels import spectral_moments

__all__ = ["FairleadImpedance", "fairlead_impedance", "harmonic_band"]


@dataclass(frozen=True, kw_only=True)
class FairleadImpedance:
    """Result of :func:`fairlead_impedance` (earth axes, SI).

    omega : (k,) rad/s, the evaluation frequencies; impedance : (k, 3, 3) complex, N/m;
    stiffness = Re impedance (N/m), damping = Im impedance / omega (N s/m), (k, 3, 3);
    tension_transfer : (k, 3) complex, N/m, the fairlead (top element) tension per unit
    fairlead displacement along each earth axis;
    node_velocity_std : (n,) m/s, the speed std of every node over all bands (trace of the
    velocity covariance), node_velocity_covariance : (n, 3, 3) (m/s)^2, earth axes;
    fairlead_velocity_std : (3,) m/s per earth axis; drag : (n, 3, 3) the
    linearised drag damping of the nodes (N s/m, a warm start for a next call); iterations,
    converged.
    """

    omega: np.ndarray
    impedance: np.ndarray
    tension_transfer: np.ndarray
    stiffness: np.ndarray
    damping: np.ndarray
    node_velocity_std: np.ndarray
    node_velocity_covariance: np.ndarray
    fairlead_velocity_std: np.ndarray
    drag: np.ndarray
    iterations: int
    converged: bool


def harmonic_band(omega: float, amplitude: float, axis: int = 0, rel: float = 1e-3):
    """A band ``(w, S)`` for :func:`fairlead_impedance` holding the variance ``a^2 / 2`` of a
    harmonic fairlead motion ``a sin(omega t)`` along earth ``axis``: three frequencies
    ``omega (1 -+ rel)``, ``omega`` with the spectrum at the middle one (trapezoidal rule)."""
    w = float(omega) * np.array([1.0 - rel, 1.0, 1.0 + rel])
    S = np.zeros((3, 3, 3))
    S[1, axis, axis] = 0.5 * amplitude ** 2 / (rel * omega)
    return w, S


def _as_cross(omega, psd):
    S = np.asarray(psd)
    if S.shape == (omega.size, 3):
        Sx = np.zeros((omega.size, 3, 3), complex)
        Sx[:, [0, 1, 2], [0, 1, 2]] = S
        return Sx
    if S.shape == (omega.size, 3, 3):
        return S.astype(complex)
    raise ValueError(f"a band's motion_psd must have shape ({omega.size}, 3) or "
                     f"({omega.size}, 3, 3), got {S.shape}")


def fairlead_impedance(line, bands, omega_eval, *, seabed: str = "fe", drag: bool = True,
                       tol: float = 1e-3, max_iterations: int = 50,
                       relaxation: float = 0.7, drag0=None) -> FairleadImpedance:
    """Fairlead impedance (dynamic stiffness and damping) of a FE line moving with several
    uncorrelated bands of fairlead motion (see the module docstring).

    Parameters
    ----------
    line : FELine in static equilibrium (after ``solve_static``), with its current.
    bands : sequence of ``(omega, motion_psd)``: each an increasing grid (rad/s, moments by the
        trapezoidal rule on it) and the fairlead displacement spectrum on it, m^2 s/rad, auto-
        spectra (n_w, 3) or a cross-spectral matrix (n_w, 3, 3), earth axes.  The node velocity
        covariances of the bands add up (uncorrelated bands, e.g. LF and WF).
    omega_eval : (k,) rad/s, > 0, where the impedance is evaluated.
    seabed : one of :data:`~floatmoor.mooring.fe.frequency.SEABED_FD_MODELS` (``"fe"``).
    drag : False leaves the drag out (the line's internal damping only).
    tol : convergence on the relative change of the damping (Frobenius norm over the
        evaluation frequencies) between two drag linearisations.
    relaxation : weight of the new linearised drag in each iteration.
    drag0 : (n, 3, 3), optional: the nodes' linearised drag to start from (``drag`` of an
        earlier result of the same line), instead of the guess from the fairlead velocity.
    """
    if seabed not in SEABED_FD_MODELS:
        raise ValueError(f"seabed must be one of {SEABED_FD_MODELS}, got {seabed!r}")
    we = np.ascontiguousarray(omega_eval, float).ravel()
    if we.size == 0 or np.any(we <= 0):
        raise ValueError("omega_eval must hold frequencies > 0")
    st = line_statics(line)
    model, info, e, q = _assemble(st, seabed, 0.05, contact_tangent=True)
    if seabed == "least_squares" and "cut_node" in info:
        raise ValueError("seabed 'least_squares' is not supported here (its springs depend on "
                         "the motion of one band); use 'fe', 'spring' or 'pinned'")
    n = st.r.shape[0]
    nb = _normal_basis(q)
    kax = st.kax_eps / st.L0
    prep = []
    for w, psd in bands:
        w = np.ascontiguousarray(w, float)
        prep.append((w, _as_cross(w, psd), trapezoid_weights(w), w * w,
                     np.zeros((w.size, n, 3, 3), complex),
                     kax[None, :] + 1j * w[:, None] * (st.B / st.L0)[None, :]))
    scratch_e = np.zeros((we.size, n, 3, 3), complex)
    small = (np.zeros((n, 3, 3), complex), np.zeros((n, 3, 3), complex),
             np.zeros((3, 3), complex), np.zeros((3, 3), complex), np.zeros((3, 3), complex))
    cov_v = np.zeros((n, 3, 3))
    cov_b = np.zeros((n, 3, 3))
    # first guess of the node velocity covariance: the fairlead's, scaled by (s / L)^2
    sv_f = sum(np.real(np.trapezoid(w2[:, None, None] * Sx, w, axis=0))
               for w, Sx, _, w2, _, _ in prep)
    frac = ((st.s - st.s[model.base]) / (st.s[-1] - st.s[model.base])).clip(0.0, 1.0)
    cov_v[:] = frac[:, None, None] ** 2 * sv_f[None]
    if not drag:
        Cd = np.zeros((n, 3, 3))
    elif drag0 is not None:
        Cd = np.array(drag0, float)
    else:
        Cd = _drag_damping(st, nb, q, cov_v)
    Ko, Co = model.Ko[-1], model.Co[-1]
    converged = False
    prev = None
    iterations = 0
    for it in range(1, max_iterations + 1):
        iterations = it
        Mm, Km, Cm, Kom, Com = _mask(model, model.K, model.C0 + Cd)
        X = _transfer(we, Mm, Cm, Km, Kom, Com, (scratch_e, *small))
        Z = np.einsum("ab,kbc->kac", Ko, np.eye(3)[None] - X[:, n - 2]).astype(complex)
        Z += 1j * we[:, None, None] * (np.einsum("ab,kbc->kac", Co, np.eye(3)[None]
                                                 - X[:, n - 2]) + Cd[n - 1][None])
        B = Z.imag / we[:, None, None]
        # top element: tension (kax + i w B / L0) e . (x_f - x_{n-2}) per unit fairlead motion
        g_top = kax[-1] + 1j * we * st.B[-1] / st.L0[-1]
        tT = g_top[:, None] * np.einsum("a,kab->kb", e[-1], np.eye(3)[None] - X[:, n - 2])
        if not drag:
            converged = True
            break
        if prev is not None and (np.linalg.norm(B - prev)
                                 <= tol * max(np.linalg.norm(B), 1e-300)):
            converged = True
            break
        prev = B
        cov_v[:] = 0.0
        for w, Sx, wt, w2, Xb, gain in prep:
            _transfer(w, Mm, Cm, Km, Kom, Com, (Xb, *small))
            tr = np.zeros((w.size, n - 1, 3), complex)
            spectral_moments(Xb, Sx, e, gain, wt, w2, model.base, tr, np.zeros((w.size, n - 1)),
                             np.zeros(n - 1), cov_b)
            cov_v += cov_b
        Cd_new = _drag_damping(st, nb, q, cov_v)
        Cd = relaxation * Cd_new + (1.0 - relaxation) * Cd
    if not converged:
        warnings.warn(f"line {st.name}: the drag linearisation of the fairlead impedance did not "
                      f"converge in {max_iterations} iterations", FloatmoorWarning, stacklevel=2)
    if not drag:
        cov_v[:] = np.nan  # not computed without drag
    return FairleadImpedance(
        omega=we, impedance=Z, tension_transfer=tT, stiffness=Z.real.copy(), damping=B,
        node_velocity_std=np.sqrt(np.maximum(np.trace(cov_v, axis1=1, axis2=2), 0.0)),
        node_velocity_covariance=cov_v.copy(),
        fairlead_velocity_std=np.sqrt(np.maximum(np.diagonal(cov_v[n - 1]), 0.0)), drag=Cd,
        iterations=iterations, converged=converged)

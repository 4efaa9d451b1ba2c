"""Frequency-domain response of a moored floater (MIMOSA-style): wave-frequency and low-frequency.

This module holds the numerics on plain arrays (no scene, no xarray); the user API
:func:`floatmoor.frequency_domain` (:mod:`floatmoor.analyses.frequency_domain`) builds the
arrays from a scene, adds the mean offset, the Rayleigh maxima and the per-line tensions.
Theory: Wang (2016) section 2.2.2, eq. 2.34-2.49; the equation numbers below are that
document's.

Conventions: DOF order surge, sway, heave, roll, pitch, yaw; SI units; exp(+i w t) (a harmonic
x = Re[X exp(i w t)], so M xdd + B xd + K x -> (K - w^2 M + i w B) X); one-sided spectra in
rad/s (wave elevation m^2 s/rad, force N^2 s/rad, response unit^2 s/rad).

Wave frequency (eq. 2.34, 2.40, 2.41)
    H(w) = [K - w^2 (M + A(w)) + i w (B(w) + B_lin + B_eq)]^-1 X(w),   S_x(w) = |H|^2 S_eta(w)
    with K the hydrostatic plus the linearised mooring stiffness at the mean position.

Low frequency (eq. 2.35, 2.38, 2.44-2.46)
    H_LF(mu) = [K - mu^2 M_LF + i mu B_LF]^-1 where M_LF = M + A(0) in the horizontal DOFs
    (surge, sway, yaw) and zero in heave, roll and pitch, which then follow the slowly varying
    loads quasi-statically (static condensation).  Cross-spectral matrices
    S_x(mu) = H S_F H^H with S_F the slowly varying drift force (Newman's approximation,
    eq. 2.38 for every pair of DOFs, or the full difference-frequency QTF) plus the wind gust
    force 4 U^2 C C^T S_u(mu).

Quadratic damping: stochastic linearisation of B_q v|v| for a zero-mean Gaussian velocity,
B_eq = sqrt(8/pi) sigma_v B_q (Caughey 1963; e.g. Faltinsen 1990), with sigma_v the standard
deviation of the total (WF + LF) velocity, iterated to convergence.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..core.dofs import DOF_NAMES
from ..core.errors import ConvergenceError, NumericalError, SceneError
from ..core.quadrature import trapezoid_weights

__all__ = [
    "SQRT_8_OVER_PI", "HORIZONTAL_DOFS", "spectral_moment", "response_std_tz",
    "wave_frequency_rao", "response_cross_spectrum", "newman_drift_spectrum",
    "qtf_drift_spectrum", "gust_force_spectrum", "lf_transfer", "equivalent_quadratic_damping",
    "mean_drift_force", "aranha_drift_damping", "FDOptions", "TENSION_MODELS", "DRIFT_METHODS", "LINE_DAMPING_MODELS",
    "FDModel", "FDSolution", "solve_frequency_domain",
]

SQRT_8_OVER_PI = math.sqrt(8.0 / math.pi)
HORIZONTAL_DOFS = (0, 1, 5)
"""Surge, sway, yaw: the DOFs with mass in the low-frequency system."""


def _trapz(y, x, axis=0):
    return np.trapezoid(y, x, axis=axis)


# -- spectral statistics ------------------------------------------------------------------------
def spectral_moment(omega, s, n: int = 0, axis: int = 0):
    """n-th spectral moment m_n = int w^n S(w) dw (trapezoidal rule along ``axis``)."""
    w = np.asarray(omega, float)
    s = np.asarray(s, float)
    shape = [1] * s.ndim
    shape[axis] = w.size
    return _trapz(w.reshape(shape) ** n * s, w, axis=axis)


def response_std_tz(omega, s, axis: int = 0):
    """Standard deviation sqrt(m0) (eq. 2.41/2.46) and mean zero up-crossing period
    Tz = 2 pi sqrt(m0/m2) (s) of one-sided spectra ``s`` along ``axis``.

    Tz is NaN where m0 or m2 is zero (no response)."""
    m0 = spectral_moment(omega, s, 0, axis)
    m2 = spectral_moment(omega, s, 2, axis)
    std = np.sqrt(np.maximum(m0, 0.0))
    with np.errstate(divide="ignore", invalid="ignore"):
        tz = np.where((m0 > 0) & (m2 > 0), 2.0 * np.pi * np.sqrt(m0 / np.where(m2 > 0, m2, 1.0)),
                      np.nan)
    return std, tz


# -- wave frequency -----------------------------------------------------------------------------
def wave_frequency_rao(omega, mass, added_mass, damping, stiffness, excitation):
    """Motion RAOs per unit wave amplitude (eq. 2.40).

    Parameters
    ----------
    omega : (n,) rad/s.
    mass : (6, 6) rigid-body mass matrix (kg, kg m, kg m^2).
    added_mass : (n, 6, 6) or (6, 6) added mass A(w) [force i, motion j].
    damping : (n, 6, 6) or (6, 6) total linear(ised) damping B(w) (radiation + linear + equivalent).
    stiffness : (6, 6) restoring (hydrostatic + mooring), N/m, N, N m/rad.
    excitation : (n, 6) complex excitation force per unit wave amplitude (N/m, N m/m).

    Returns
    -------
    (n, 6) complex RAOs (m/m, rad/m), exp(+i w t).
    """
    w = np.asarray(omega, float)
    A = np.broadcast_to(np.asarray(added_mass, float), (w.size, 6, 6))
    B = np.broadcast_to(np.asarray(damping, float), (w.size, 6, 6))
    Z = (np.asarray(stiffness, float)[None] - w[:, None, None] ** 2 * (np.asarray(mass)[None] + A)
         + 1j * w[:, None, None] * B)
    try:
        H = np.linalg.solve(Z, np.asarray(excitation, complex)[..., None])[..., 0]
    except np.linalg.LinAlgError:
        raise NumericalError("singular impedance matrix in the wave-frequency RAOs",
                             where="frequency domain, wave frequency",
                             remedy="a DOF has no mass, damping or stiffness (check the vessel "
                                    "matrices and the database)") from None
    if not np.all(np.isfinite(H)):
        raise NumericalError("non-finite RAOs", where="frequency domain, wave frequency",
                             remedy="check the database for NaN excitation or added mass")
    return H


def response_cross_spectrum(H, s_in):
    """Cross-spectral matrices of the response: S_x = H S_F H^H.

    H : (n, p, q) complex transfer matrices; s_in : (n, q, q) input cross-spectra (real or
    Hermitian).  Returns (n, p, p) complex Hermitian (its diagonal is real)."""
    return np.einsum("nij,njk,nlk->nil", H, s_in, np.conj(H))


# -- slowly varying excitation ------------------------------------------------------------------
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


# -- low frequency ------------------------------------------------------------------------------
def lf_transfer(mu, mass, damping, stiffness, impedance=None):
    """Low-frequency transfer matrices H(mu) = [K - mu^2 M + i mu B + Z_x(mu)]^-1, (m, 6, 6)
    complex (eq. 2.45 in matrix form).  Give M and B zero in the DOFs that follow
    quasi-statically.  ``impedance`` (m, 6, 6) complex, optional: a frequency-dependent
    impedance Z_x added to it (the mooring lines' dynamic stiffness and damping beyond the
    quasi-static catenary, ``line_damping: fe``)."""
    mu = np.asarray(mu, float)
    Z = (np.asarray(stiffness, float)[None] - mu[:, None, None] ** 2 * np.asarray(mass, float)[None]
         + 1j * mu[:, None, None] * np.asarray(damping, float)[None])
    if impedance is not None:
        Z = Z + np.asarray(impedance, complex)
    try:
        return np.linalg.inv(Z)
    except np.linalg.LinAlgError:
        raise NumericalError("singular low-frequency impedance", where="frequency domain, LF",
                             remedy="the mooring gives no stiffness in a DOF (check the lines "
                                    "and the hydrostatic stiffness)") from None


def equivalent_quadratic_damping(quadratic_damping, sigma_v):
    """Stochastic linearisation of B_q v|v| for a zero-mean Gaussian velocity of standard
    deviation sigma_v: B_eq = sqrt(8/pi) sigma_v B_q, DOF by DOF (diagonal of B_q).

    quadratic_damping : (6, 6) (only the diagonal is used); sigma_v : (6,) m/s, rad/s.
    Returns (6, 6) diagonal, N s/m .. N m s/rad."""
    bq = np.diag(np.asarray(quadratic_damping, float))
    return np.diag(SQRT_8_OVER_PI * bq * np.asarray(sigma_v, float))


def aranha_drift_damping(omega, s_eta, coefficient_along, gravity, direction):
    """Wave drift damping, Aranha's deep-water formula along the wave direction:

        b = 2 int S(w) (w/g) (4 C(w) + w dC/dw) dw,   B = b e e^T (surge/sway block)

    with C the mean drift coefficient along the direction of travel e = (cos, sin).
    Returns (6, 6).  (Aranha 1994, J. Fluids Struct.; as in DNV-RP-C205 sec. 7.4.)"""
    w = np.asarray(omega, float)
    C = np.asarray(coefficient_along, float)
    dC = np.gradient(C, w)
    b = 2.0 * _trapz(np.asarray(s_eta) * (w / gravity) * (4.0 * C + w * dC), w)
    e = np.array([math.cos(direction), math.sin(direction)])
    B = np.zeros((6, 6))
    B[:2, :2] = b * np.outer(e, e)
    return B


TENSION_MODELS = ("quasi_static", "dynamic")
LINE_DAMPING_MODELS = ("none", "fe")
DRIFT_METHODS = ("auto", "newman", "qtf")

@dataclass(frozen=True, kw_only=True)
class FDOptions:
    """Options of :func:`floatmoor.frequency_domain` (scene section
    ``frequency_domain:`` when present, read by :mod:`floatmoor.io.fd_section`).

    duration : s, the storm duration for the number of cycles N = duration / Tz (3 h).
    tension_model : ``quasi_static``, or ``dynamic``: the WF tension of every line from its FE
        model in the frequency domain (:mod:`floatmoor.analyses.fd_line_dynamics`; LF stays
        quasi-static unless ``line_damping: fe``).
    drift : ``auto`` (the full QTF when the database has one, else Newman), ``newman``, ``qtf``.
    wave_drift_damping : add Aranha's wave drift damping to the LF system.
    lf_cutoff_period : s, upper end of the LF band (2 pi / period rad/s).
    n_lf : number of LF frequencies from 0 to the cut-off.
    d_omega : rad/s, step of the WF grid.
    heading_iterations : fixed-point iterations on the mean yaw for the relative headings.
    line_current_drag : include the static current drag on the mooring lines in the mean
        position (default false: the catenary lines carry no current).  Each line's statics
        are solved in the scene's current profile with its FE model
        (:class:`~floatmoor.mooring.fe.current_statics.LineCurrentStatics`), and the difference
        from still water is added to the catenary force; the mean pose, the static tensions
        and the linearisation (mooring stiffness, tension gradients, the dynamic line model)
        are then taken there, and the drag's own change with the pose (central differences)
        is added to the mooring stiffness and the tension gradients
        (:mod:`floatmoor.analyses.frequency_domain`).
    line_damping : ``none`` (default: the quasi-static catenary gives the LF system stiffness
        and no damping) or ``fe``: the mooring lines' LF impedance from their FE model in the
        frequency domain, driven by the WF and LF fairlead motion, the drag linearised with
        both and iterated with the response; the increment over the static stiffness (line drag
        damping and the drag's dynamic stiffening) enters the LF system at every LF frequency
        (:mod:`floatmoor.analyses.fd_line_damping`).
    """

    duration: float = 10800.0
    tension_model: str = "quasi_static"
    drift: str = "auto"
    wave_drift_damping: bool = False
    lf_cutoff_period: float = 30.0
    n_lf: int = 1200
    d_omega: float = 0.005
    heading_iterations: int = 4
    line_current_drag: bool = False
    line_damping: str = "none"

    def __post_init__(self):
        def bad(key, expected, found):
            raise SceneError(None, f"frequency_domain.{key}", expected, found)
        for key in ("duration", "lf_cutoff_period", "d_omega"):
            v = getattr(self, key)
            if not (isinstance(v, (int, float)) and math.isfinite(v) and v > 0):
                bad(key, "a number > 0", v)
        if self.tension_model not in TENSION_MODELS:
            bad("tension_model", "one of: " + ", ".join(TENSION_MODELS)
                + " (dynamic WF tension from the FE line model is not available yet)",
                self.tension_model)
        if self.drift not in DRIFT_METHODS:
            bad("drift", "one of: " + ", ".join(DRIFT_METHODS), self.drift)
        if not isinstance(self.n_lf, int) or self.n_lf < 50:
            bad("n_lf", "an integer >= 50", self.n_lf)
        if not isinstance(self.heading_iterations, int) or self.heading_iterations < 1:
            bad("heading_iterations", "an integer >= 1", self.heading_iterations)
        if not isinstance(self.wave_drift_damping, bool):
            bad("wave_drift_damping", "true or false", self.wave_drift_damping)
        if not isinstance(self.line_current_drag, bool):
            bad("line_current_drag", "true or false", self.line_current_drag)
        if self.line_damping not in LINE_DAMPING_MODELS:
            bad("line_damping", "one of: " + ", ".join(LINE_DAMPING_MODELS), self.line_damping)


# -- the coupled solution -----------------------------------------------------------------------
@dataclass(frozen=True, kw_only=True)
class FDModel:
    """A linearised moored floater about its mean position (all arrays SI, DOF order).

    omega : (n,) wave frequencies (rad/s); wave_spectrum : (n,) S_eta (m^2 s/rad).
    mass : (6, 6) rigid-body mass; added_mass, radiation_damping : (n, 6, 6) on ``omega``.
    excitation : (n, 6) complex first-order excitation per unit amplitude at the wave heading.
    stiffness : (6, 6) hydrostatic + mooring at the mean position.
    linear_damping, quadratic_damping : (6, 6) of the vessel.
    lf_added_mass : (6, 6) A(0) (or its stand-in); lf_extra_damping : (6, 6) wind, current and
    wave drift damping.  mu : (m,) low-frequency grid (rad/s).
    lf_force_spectrum : (m, 6, 6) slowly varying force cross-spectra (drift + gust).
    lf_impedance : (m, 6, 6) complex or None, added to the LF impedance (:func:`lf_transfer`):
    the mooring lines' dynamic stiffness and damping (``line_damping: fe``).
    max_iter, tol : the stochastic linearisation loop.
    """

    omega: np.ndarray
    wave_spectrum: np.ndarray
    mass: np.ndarray
    added_mass: np.ndarray
    radiation_damping: np.ndarray
    excitation: np.ndarray
    stiffness: np.ndarray
    linear_damping: np.ndarray
    quadratic_damping: np.ndarray = field(default_factory=lambda: np.zeros((6, 6)))
    lf_added_mass: np.ndarray
    lf_extra_damping: np.ndarray = field(default_factory=lambda: np.zeros((6, 6)))
    mu: np.ndarray
    lf_force_spectrum: np.ndarray
    lf_impedance: np.ndarray | None = None
    max_iter: int = 50
    tol: float = 1e-4


@dataclass(frozen=True, kw_only=True)
class FDSolution:
    """Result of :func:`solve_frequency_domain`.

    rao : (n, 6) complex WF RAOs; wf_spectrum : (n, 6) WF response spectra;
    wf_covariance, wf_velocity_covariance : (6, 6); lf_transfer : (m, 6, 6);
    lf_cross_spectrum : (m, 6, 6) complex; lf_spectrum : (m, 6) (its real diagonal);
    lf_covariance, lf_velocity_covariance : (6, 6); lf_mass, lf_damping : (6, 6) as used;
    equivalent_damping : (6, 6) from the quadratic damping; iterations : int.
    """

    rao: np.ndarray
    wf_spectrum: np.ndarray
    wf_covariance: np.ndarray
    wf_velocity_covariance: np.ndarray
    lf_transfer: np.ndarray
    lf_cross_spectrum: np.ndarray
    lf_spectrum: np.ndarray
    lf_covariance: np.ndarray
    lf_velocity_covariance: np.ndarray
    lf_mass: np.ndarray
    lf_damping: np.ndarray
    equivalent_damping: np.ndarray
    iterations: int


def _covariances(omega, cross):
    """Covariance of displacement and velocity from (n, d, d) Hermitian cross-spectra."""
    c = np.real(_trapz(cross, omega, axis=0))
    cv = np.real(_trapz(np.asarray(omega)[:, None, None] ** 2 * cross, omega, axis=0))
    return c, cv


def solve_frequency_domain(model: FDModel) -> FDSolution:
    """Wave-frequency RAOs and spectra, low-frequency spectra, with the quadratic damping
    linearised stochastically on the total velocity and iterated (see the module docstring).

    Raises
    ------
    ConvergenceError
        When the equivalent damping does not settle within ``model.max_iter`` iterations.
    """
    w = np.asarray(model.omega, float)
    S = np.asarray(model.wave_spectrum, float)
    mu = np.asarray(model.mu, float)
    M_lf = np.zeros((6, 6))
    ix = np.ix_(HORIZONTAL_DOFS, HORIZONTAL_DOFS)
    M_lf[ix] = (np.asarray(model.mass) + np.asarray(model.lf_added_mass))[ix]
    quadratic = np.any(np.diag(model.quadratic_damping) != 0.0)
    B_eq = np.zeros((6, 6))
    if quadratic:
        # start from 5 % of critical damping in the DOFs with quadratic damping (the undamped
        # first pass would be singular at resonance); the iteration removes this guess
        mA = np.diag(model.mass) + np.diag(np.asarray(model.added_mass)[len(w) // 2])
        crit = 2.0 * np.sqrt(np.abs(np.diag(model.stiffness)) * np.abs(mA))
        B_eq = np.diag(np.where(np.diag(model.quadratic_damping) != 0.0, 0.05 * crit, 0.0))
    it = 0
    while True:
        it += 1
        B_wf = model.radiation_damping + (model.linear_damping + B_eq)[None]
        H = wave_frequency_rao(w, model.mass, model.added_mass, B_wf, model.stiffness,
                               model.excitation)
        wf_cross = H[:, :, None] * np.conj(H)[:, None, :] * S[:, None, None]
        c_wf, cv_wf = _covariances(w, wf_cross)
        B_lf = np.zeros((6, 6))
        B_lf[ix] = (model.linear_damping + B_eq + model.lf_extra_damping)[ix]
        Hl = lf_transfer(mu, M_lf, B_lf, model.stiffness, model.lf_impedance)
        lf_cross = response_cross_spectrum(Hl, model.lf_force_spectrum)
        c_lf, cv_lf = _covariances(mu, lf_cross)
        if not quadratic:
            break
        sigma_v = np.sqrt(np.maximum(np.diag(cv_wf) + np.diag(cv_lf), 0.0))
        B_new = equivalent_quadratic_damping(model.quadratic_damping, sigma_v)
        diff = np.abs(np.diag(B_new) - np.diag(B_eq))
        change = float(np.max(diff / np.maximum(np.abs(np.diag(B_new)), 1e-30)))
        if change < model.tol:
            break  # the results above were computed with B_eq, within tol of B_new
        if it >= model.max_iter:
            k = int(np.argmax(diff))
            raise ConvergenceError(
                f"stochastic linearisation of the quadratic damping did not converge in {it} "
                f"iterations (relative change {change:.2e})", where=f"frequency domain, DOF "
                f"{DOF_NAMES[k]}", remedy="check the quadratic damping of the vessel file")
        B_eq = B_new
    wf_spec = np.real(np.einsum("nii->ni", wf_cross))
    lf_spec = np.real(np.einsum("nii->ni", lf_cross))
    return FDSolution(rao=H, wf_spectrum=wf_spec, wf_covariance=c_wf, wf_velocity_covariance=cv_wf,
                      lf_transfer=Hl, lf_cross_spectrum=lf_cross, lf_spectrum=lf_spec,
                      lf_covariance=c_lf, lf_velocity_covariance=cv_lf, lf_mass=M_lf,
                      lf_damping=B_lf, equivalent_damping=B_eq, iterations=it)

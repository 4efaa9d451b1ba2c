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

Quadratic damping: stochastic linearisation of F_i = -sum_j B_q,ij v_j|v_j| for zero-mean
Gaussian velocities, B_eq = sqrt(8/pi) B_q diag(sigma_v) (Caughey 1963; e.g. Faltinsen 1990):
every entry of the matrix, off-diagonal couplings included, with sigma_v the standard
deviations of the total (WF + LF) velocity in the yaw frame at the mean heading, iterated to
convergence.

A sea of several directions (wave systems, spreading): ``excitation`` (n_dir, n, 6) with the
directions' spectra ``direction_spectra``; the WF cross-spectra add over the directions
(independent components), :func:`wf_directions` gives each direction's RAO and spectrum.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np

from ..core.dofs import DOF_NAMES
from ..core.errors import ConvergenceError, NumericalError, SceneError
from ..core.frames import yaw_rotation6
from ..forces.spectral import (
    DEFAULT_D_OMEGA,
    aranha_drift_damping,
    gust_force_spectrum,
    mean_drift_force,
    newman_drift_spectrum,
    qtf_drift_spectrum,
)

__all__ = [
    "SQRT_8_OVER_PI", "HORIZONTAL_DOFS", "spectral_moment", "response_std_tz",
    "wave_frequency_rao", "response_cross_spectrum", "newman_drift_spectrum",
    "qtf_drift_spectrum", "gust_force_spectrum", "lf_transfer", "equivalent_quadratic_damping",
    "mean_drift_force", "aranha_drift_damping", "FDOptions", "TENSION_MODELS", "DRIFT_METHODS", "LINE_DAMPING_MODELS",
    "FDModel", "FDSolution", "solve_frequency_domain", "wf_directions",
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


# -- slowly varying excitation: the forms of the force models (floatmoor.forces.spectral) ------


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
    """Stochastic linearisation of ``F_i = -sum_j B_ij v_j |v_j|`` for zero-mean Gaussian
    velocities of standard deviations ``sigma_v`` (Caughey 1963): the equivalent linear
    coefficients are ``E[dF_i/dv_k] = B_ik 2 E|v_k| = sqrt(8/pi) sigma_k B_ik``, so every entry
    of B, off-diagonal couplings included, is linearised on the velocity it multiplies:
    ``B_eq = sqrt(8/pi) B diag(sigma)``.

    quadratic_damping : (6, 6); sigma_v : (6,) m/s, rad/s.  Returns (6, 6), N s/m .. N m s/rad.
    """
    return SQRT_8_OVER_PI * np.asarray(quadratic_damping, float) \
        * np.asarray(sigma_v, float)[None, :]


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
    drift : ``auto`` (the scene's choice, ``forces: drift``: by default the full QTF when the
        database has one and the sea one direction, else Newman), ``newman``, ``qtf``: the
        drift model of the frequency domain alone (:func:`floatmoor.forces.waves.drift_method`).
    wave_drift_damping : None (the scene's ``forces: wave_drift_damping``, in both domains), or
        true/false: Aranha's wave drift damping in the frequency domain alone
        (:mod:`floatmoor.forces.wave_drift_damping`; a note says when it differs from the
        scene's time domain).
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
    wave_drift_damping: bool | None = None
    lf_cutoff_period: float = 30.0
    n_lf: int = 1200
    d_omega: float = DEFAULT_D_OMEGA
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
        if self.wave_drift_damping is not None and not isinstance(self.wave_drift_damping, bool):
            bad("wave_drift_damping", "true or false", self.wave_drift_damping)
        if not isinstance(self.line_current_drag, bool):
            bad("line_current_drag", "true or false", self.line_current_drag)
        if self.line_damping not in LINE_DAMPING_MODELS:
            bad("line_damping", "one of: " + ", ".join(LINE_DAMPING_MODELS), self.line_damping)


# -- the coupled solution -----------------------------------------------------------------------
@dataclass(frozen=True, kw_only=True)
class FDModel:
    """A linearised moored floater about its mean position (all arrays SI, DOF order).

    omega : (n,) wave frequencies (rad/s); wave_spectrum : (n,) S_eta (m^2 s/rad), the sea's.
    mass : (6, 6) rigid-body mass; added_mass, radiation_damping : (n, 6, 6) on ``omega``.
    excitation : (n, 6) complex first-order excitation per unit amplitude at the wave heading, or
    (n_dir, n, 6) for a sea of several directions, whose spectra are ``direction_spectra``
    (n_dir, n) (summing to ``wave_spectrum``) and directions ``directions`` (n_dir,) rad.
    stiffness : (6, 6) hydrostatic + mooring at the mean position.
    linear_damping : (6, 6) earth axes at the mean heading; quadratic_damping : (6, 6) on the
    yaw-frame velocity (every entry; linearised on the velocity in the yaw frame at the mean
    heading ``yaw`` and turned to earth axes, :func:`equivalent_quadratic_damping`).
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
    direction_spectra: np.ndarray | None = None
    directions: np.ndarray | None = None
    yaw: float = 0.0
    max_iter: int = 50
    tol: float = 1e-4


@dataclass(frozen=True, kw_only=True)
class FDSolution:
    """Result of :func:`solve_frequency_domain`.

    rao : (n, 6) complex WF RAOs (None for a sea of several directions); raos : (n_dir, n, 6)
    the RAOs of every direction (:func:`wf_directions`); wf_spectrum : (n, 6) WF response
    spectra (all directions);
    wf_covariance, wf_velocity_covariance : (6, 6); lf_transfer : (m, 6, 6);
    lf_cross_spectrum : (m, 6, 6) complex; lf_spectrum : (m, 6) (its real diagonal);
    lf_covariance, lf_velocity_covariance : (6, 6); lf_mass, lf_damping : (6, 6) as used;
    equivalent_damping : (6, 6) from the quadratic damping; iterations : int.
    """

    rao: np.ndarray | None
    raos: np.ndarray
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


def _wf_response(w, model: FDModel, damping):
    """WF response cross-spectra (n, 6, 6) complex, sum over the sea's directions of
    H_d H_d^H S_d, and the RAOs: (n, 6) for one direction, (n_dir, n, 6) for several."""
    X = np.asarray(model.excitation, complex)
    if X.ndim == 2:
        S = np.asarray(model.wave_spectrum, float)
        H = wave_frequency_rao(w, model.mass, model.added_mass, damping, model.stiffness, X)
        return H[:, :, None] * np.conj(H)[:, None, :] * S[:, None, None], H
    Sd = np.asarray(model.direction_spectra, float)
    H = np.stack([wave_frequency_rao(w, model.mass, model.added_mass, damping, model.stiffness,
                                     X[d]) for d in range(X.shape[0])])
    cross = np.einsum("dni,dnj,dn->nij", H, np.conj(H), Sd)
    return cross, H


def wf_directions(model: FDModel, sol: FDSolution):
    """The WF transfer of each direction of the sea: a list of (RAO (n, 6) complex, spectrum
    (n,)) whose responses add (one pair for a unidirectional sea)."""
    if sol.raos.shape[0] == 1 and model.direction_spectra is None:
        return [(sol.raos[0], np.asarray(model.wave_spectrum, float))]
    return [(sol.raos[d], np.asarray(model.direction_spectra[d], float))
            for d in range(sol.raos.shape[0])]


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
    mu = np.asarray(model.mu, float)
    M_lf = np.zeros((6, 6))
    ix = np.ix_(HORIZONTAL_DOFS, HORIZONTAL_DOFS)
    M_lf[ix] = (np.asarray(model.mass) + np.asarray(model.lf_added_mass))[ix]
    Bq = np.asarray(model.quadratic_damping, float)
    quadratic = bool(np.any(Bq != 0.0))
    T = yaw_rotation6(model.yaw) if model.yaw != 0.0 else None
    B_eq = np.zeros((6, 6))
    if quadratic:
        # start from 5 % of critical damping in the DOFs with quadratic damping (the undamped
        # first pass would be singular at resonance); the iteration removes this guess
        mA = np.diag(model.mass) + np.diag(np.asarray(model.added_mass)[len(w) // 2])
        crit = 2.0 * np.sqrt(np.abs(np.diag(model.stiffness)) * np.abs(mA))
        B_eq = np.diag(np.where(np.diag(Bq) != 0.0, 0.05 * crit, 0.0))
    it = 0
    while True:
        it += 1
        B_wf = model.radiation_damping + (model.linear_damping + B_eq)[None]
        wf_cross, H = _wf_response(w, model, B_wf)
        c_wf, cv_wf = _covariances(w, wf_cross)
        B_lf = np.zeros((6, 6))
        B_lf[ix] = (model.linear_damping + B_eq + model.lf_extra_damping)[ix]
        Hl = lf_transfer(mu, M_lf, B_lf, model.stiffness, model.lf_impedance)
        lf_cross = response_cross_spectrum(Hl, model.lf_force_spectrum)
        c_lf, cv_lf = _covariances(mu, lf_cross)
        if not quadratic:
            break
        cv = cv_wf + cv_lf
        if T is not None:  # the velocity in the yaw frame at the mean heading
            cv = T.T @ cv @ T
        sigma_v = np.sqrt(np.maximum(np.diag(cv), 0.0))
        B_new = equivalent_quadratic_damping(Bq, sigma_v)
        if T is not None:
            B_new = T @ B_new @ T.T
        diff = np.abs(B_new - B_eq)
        change = float(np.max(diff / np.maximum(np.abs(B_new), 1e-30)))
        if change < model.tol:
            break  # the results above were computed with B_eq, within tol of B_new
        if it >= model.max_iter:
            k = int(np.unravel_index(np.argmax(diff), diff.shape)[1])
            raise ConvergenceError(
                f"stochastic linearisation of the quadratic damping did not converge in {it} "
                f"iterations (relative change {change:.2e})", where=f"frequency domain, DOF "
                f"{DOF_NAMES[k]}", remedy="check the quadratic damping of the vessel file")
        B_eq = B_new
    wf_spec = np.real(np.einsum("nii->ni", wf_cross))
    if H.ndim == 2:
        rao, raos = H, H[None]
    else:
        rao, raos = None, H
    lf_spec = np.real(np.einsum("nii->ni", lf_cross))
    return FDSolution(rao=rao, raos=raos, wf_spectrum=wf_spec, wf_covariance=c_wf, wf_velocity_covariance=cv_wf,
                      lf_transfer=Hl, lf_cross_spectrum=lf_cross, lf_spectrum=lf_spec,
                      lf_covariance=c_lf, lf_velocity_covariance=cv_lf, lf_mass=M_lf,
                      lf_damping=B_lf, equivalent_damping=B_eq, iterations=it)

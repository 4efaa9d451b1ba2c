"""Frequency-domain analysis of a scene, MIMOSA-style (user API).

>>> from floatmoor.frequency_domain import frequency_domain, format_table
>>> ds = frequency_domain("scenes/floatel_100yr.yaml")
>>> print(format_table(ds))

(``import floatmoor.frequency_domain as fd; fd(scene)`` also works: the module is callable.)

What is computed (seed 002, Wang 2016, section 2.2.2 eq. 2.34-2.49 and section 2.3)
----------------------------------------------------------------------------------------
1. **Mean** (eq. 2.39): static equilibrium (:func:`floatmoor.solvers.statics.equilibrium`, the
   same vessel, mooring and net buoyancy as every solver via :func:`floatmoor.io.build.build`)
   under the mean wind force C_wi(theta) U^2 (U the 1-hour mean speed at the coefficients'
   reference height), the current force C_cu(theta) V^2 (V the current speed at the still
   water line, z = 0) and the mean wave drift 2 int C_wa(w) S(w) dw.  Coefficients are taken at
   the heading relative to the body; the mean yaw is iterated (``heading_iterations``).
2. **Wave frequency** (eq. 2.34, 2.40-2.43): RAOs from the database (A(w), B(w), X(w) linearly
   interpolated on a fine grid of step ``d_omega`` over the database's frequency range) with the
   hydrostatic restoring plus the mooring's analytic stiffness at the mean position and the
   vessel's linear (and linearised quadratic) damping.  A quasi-static mooring adds no damping.
3. **Low frequency** (eq. 2.35, 2.38, 2.44-2.48): surge, sway and yaw with mass M + A(0)
   (the database's ``zero_frequency_added_mass``, else A at its lowest frequency: see the
   attribute ``lf_added_mass_source``); heave, roll and pitch follow quasi-statically.  Damping:
   vessel linear damping, quadratic damping linearised stochastically (iterated), wind and
   current damping -dF/dv of F = C(theta_rel) |U - v|^2 at the mean velocities, optionally
   Aranha's wave drift damping.  Excitation: slowly varying drift by Newman's approximation
   (eq. 2.38) or the full difference-frequency QTF when the database has one, plus the wind
   gust 4 U^2 C C^T S_u (the scene's gust spectrum, NPD by default).  Integrated from 0 to the
   LF cut-off 2 pi / ``lf_cutoff_period`` (30 s: the LF band of seed section 2.2.2).
4. **Maxima**: Rayleigh most probable maxima sigma sqrt(2 ln N), N = duration / Tz with Tz of
   each response spectrum; significant = 2 sigma (eq. 2.42/2.47).  Combination (eq. 2.49):
   X_max = X_mean + max(X_LF,max + X_WF,sig, X_WF,max + X_LF,sig) (and X_min likewise).
5. **Line tensions** (quasi-static, seed section 2.3.1): T(mean) from the catenary; the LF and
   WF tension processes are g . x with g = dT/dpose the line's tangent stiffness at the mean
   position (central differences of the catenary, i.e. the tension change per fairlead
   displacement along the line's direction); their std, Tz and maxima as above, combined with
   eq. 2.49.  Columns as figure 5.9: static, std LF, max LF, WF base, std WF, max WF, max total,
   safety factor MBS / max total; WF base = max total - max WF (eq. 2.60: the tension at the
   offset X_max - X_WF,max, from which the WF maximum is added).  ``tension_max_total_catenary``
   re-evaluates the catenary at the most likely pose giving that excursion (the conditional
   mean pose of the Gaussian responses), which shows the effect of the line's nonlinearity.
6. **Viscous drift** (seed 002 chapter 6; the scene key ``forces: viscous_drift``):
   ``model: correction_formula`` replaces the potential mean drift coefficients by eq. 6.6
   (:func:`floatmoor.forces.slender.corrected_drift_database`, the same coefficients as the
   time domain's Newman drift, evaluated at the mean yaw) in both the mean drift of item 1 and
   the slow-drift spectrum of item 3 (which then uses Newman's approximation: ``drift: qtf`` is
   refused, ``auto`` picks ``newman``); its ``extra_damping`` raises the surge and sway linear
   damping (:func:`floatmoor.forces.slender.viscous_linear_damping`, section 6.6).
   ``model: slender_elements`` (Morison strips in the time loop) has no frequency-domain
   counterpart: a :class:`FloatmoorWarning` says that the FD runs without viscous drift and with
   the hull current coefficients.  Attribute ``viscous_drift_model``.
"""

from __future__ import annotations

import math
import os
import time
import warnings
from dataclasses import asdict, fields, replace

import numpy as np
import xarray as xr

from .. import __version__
from ..core.dofs import DOF_NAMES
from ..core.errors import FloatmoorWarning, SceneError
from ..forces.slender import (corrected_drift_database, refuse_qtf_with_correction,
                              viscous_linear_damping)
from ..hydro.database import interpolate_heading
from ..io.build import BuiltScene, build
from ..io.scene import Scene
from ..metocean.current import current_speed
from ..metocean.spectra import wave_spectrum
from ..metocean.wind import wind_mean_speed, wind_spectrum
from ..post.extremes import rayleigh_max
from ..solvers.frequency_domain import (DRIFT_METHODS, TENSION_MODELS, FDModel, FDOptions,
                                       aranha_drift_damping, gust_force_spectrum,
                                       mean_drift_force, newman_drift_spectrum,
                                       qtf_drift_spectrum, response_std_tz,
                                       solve_frequency_domain)
from ..solvers.statics import solve_equilibrium

__all__ = ["FDOptions", "frequency_domain", "format_table", "combine_maxima", "tension_columns",
           "safety_factor", "TENSION_MODELS",
           "DRIFT_METHODS"]

_MIXED_UNITS = "m (surge, sway, heave), rad (roll, pitch, yaw)"
_MIXED_FORCE = "N (surge, sway, heave), N m (roll, pitch, yaw)"


# -- small helpers -----------------------------------------------------------------------------
def _rot6(yaw: float) -> np.ndarray:
    """Block-diagonal rotation body -> earth about z for force/moment 6-vectors."""
    c, s = math.cos(yaw), math.sin(yaw)
    R = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    T = np.zeros((6, 6))
    T[:3, :3] = R
    T[3:, 3:] = R
    return T


def _interp0(x_new, x, y):
    """Linear interpolation along axis 0 of y (any trailing shape), constant outside."""
    x = np.asarray(x, float)
    idx = np.clip(np.searchsorted(x, x_new) - 1, 0, x.size - 2)
    f = np.clip((x_new - x[idx]) / (x[idx + 1] - x[idx]), 0.0, 1.0)
    f = f.reshape((-1,) + (1,) * (np.ndim(y) - 1))
    return (1.0 - f) * y[idx] + f * y[idx + 1]


def _coeff_slope(table, theta: float, h: float = 1e-4) -> np.ndarray:
    return (table.at(theta + h) - table.at(theta - h)) / (2.0 * h)


def _relative_flow_damping(table, speed: float, heading: float, yaw: float) -> np.ndarray:
    """-dF/dv (6 x 6, columns surge and sway) of F = C(theta_rel) |U e - v|^2 (body axes
    rotated to earth), at v = 0: B[:, j] = 2 U C e_j - U C'(theta) n_j with
    e = (cos, sin), n = (sin, -cos) of the heading of travel (earth)."""
    if speed <= 0.0:
        return np.zeros((6, 6))
    T = _rot6(yaw)
    rel = heading - yaw
    C = T @ table.at(rel)
    dC = T @ _coeff_slope(table, rel)
    e = np.array([math.cos(heading), math.sin(heading)])
    n = np.array([math.sin(heading), -math.cos(heading)])
    B = np.zeros((6, 6))
    B[:, :2] = 2.0 * speed * np.outer(C, e) - speed * np.outer(dC, n)
    return B


def _rayleigh(std, tz, duration):
    """Most probable maxima sigma sqrt(2 ln N), N = duration / Tz; 0 where sigma is 0."""
    std = np.asarray(std, float)
    tz = np.asarray(tz, float)
    n = np.where(np.isfinite(tz) & (tz > 0), duration / np.where(tz > 0, tz, 1.0), np.nan)
    out = np.zeros_like(std)
    ok = (std > 0) & np.isfinite(n)
    if np.any(ok & (n <= 1.0)):
        raise SceneError(None, "frequency_domain.duration",
                         "a duration longer than the response periods (N = duration/Tz > 1)",
                         duration, f"Tz up to {np.nanmax(tz[ok]):.1f} s")
    out[ok] = rayleigh_max(std[ok], n[ok])
    return out, n


def combine_maxima(mean, lf_sig, lf_max, wf_sig, wf_max):
    """Eq. 2.49: X_max = X_mean + max(X_LF,max + X_WF,sig, X_WF,max + X_LF,sig).

    Returns (maximum, minimum, branch) where minimum = X_mean - the same excursion and branch
    is 1 where the LF maximum governs, 2 where the WF maximum does (arrays broadcast)."""
    a = np.asarray(lf_max) + np.asarray(wf_sig)
    b = np.asarray(wf_max) + np.asarray(lf_sig)
    exc = np.maximum(a, b)
    return np.asarray(mean) + exc, np.asarray(mean) - exc, np.where(a >= b, 1, 2)


def _qtf_function(db, heading_rel: float, T: np.ndarray):
    """Callable (w1, w2) -> (n, 6) complex QTF at the relative heading, earth axes; bilinear in
    (w1, w2), zero outside the QTF grid."""
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


def safety_factor(mbs, max_tension):
    """Safety factor MBS / maximum tension (the last column of seed figure 5.9)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.asarray(mbs, float) / np.asarray(max_tension, float)


def tension_columns(static, std_lf, tz_lf, std_wf, tz_wf, mbs, duration):
    """The line-tension columns of seed figure 5.9 from the tension statistics (N, s).

    max LF / max WF: Rayleigh sigma sqrt(2 ln N), N = duration / Tz; max total: eq. 2.49,
    static + max(max LF + 2 std WF, max WF + 2 std LF); WF base = max total - max WF (eq. 2.60);
    safety factor = MBS / max total.  Returns a dict of arrays: ``max_lf``, ``max_wf``,
    ``wf_base``, ``max_total``, ``safety_factor``, ``branch`` (1: LF max governs).
    """
    max_lf, _ = _rayleigh(std_lf, tz_lf, duration)
    max_wf, _ = _rayleigh(std_wf, tz_wf, duration)
    max_total, _, branch = combine_maxima(static, 2.0 * np.asarray(std_lf), max_lf,
                                          2.0 * np.asarray(std_wf), max_wf)
    return {"max_lf": max_lf, "max_wf": max_wf, "wf_base": max_total - max_wf,
            "max_total": max_total, "safety_factor": safety_factor(mbs, max_total),
            "branch": branch}


# -- the analysis ------------------------------------------------------------------------------
def _options_from(scene: Scene, options: FDOptions | None, overrides: dict) -> FDOptions:
    base = options
    if base is None:
        base = getattr(scene, "frequency_domain", None) or FDOptions()
    if overrides:
        known = {f.name for f in fields(FDOptions)}
        unknown = sorted(set(overrides) - known)
        if unknown:
            raise TypeError(f"unknown frequency-domain option(s) {unknown}; known: {sorted(known)}")
        base = replace(base, **overrides)
    return base


def frequency_domain(scene: Scene | BuiltScene | str | os.PathLike, *,
                     options: FDOptions | None = None, **overrides) -> xr.Dataset:
    """MIMOSA-style frequency-domain analysis of a scene (mean, LF, WF, maxima, tensions).

    Parameters
    ----------
    scene : a scene file path, a :class:`~floatmoor.io.scene.Scene` or a built scene.  It must
        name a vessel (with a hydrodynamic database) and a mooring.
    options : :class:`FDOptions`; default: the scene's ``frequency_domain`` section if any,
        else the defaults (3-hour duration, quasi-static tensions).
    **overrides : individual :class:`FDOptions` fields, e.g. ``duration=3600.0``.

    Returns
    -------
    xarray.Dataset with dimensions ``dof``, ``omega`` (WF grid), ``mu`` (LF grid), ``line``,
    ``complex``; every variable has ``units`` and ``long_name``.  Main variables: ``mean``,
    ``wf_std``, ``wf_sig``, ``wf_max``, ``wf_tz``, ``lf_std``, ``lf_sig``, ``lf_max``, ``lf_tz``,
    ``max_total``, ``min_total`` (per DOF, m and rad), the spectra, the RAOs, per line
    ``tension_static`` ... ``tension_max_total``, ``safety_factor`` (figure 5.9 columns) and the
    fairlead motion along each line.

    Raises
    ------
    SceneError for a scene without vessel or mooring, or bad options; NumericalError /
    ConvergenceError when the statics or the linearisation fail.
    """
    t_start = time.perf_counter()
    built = scene if isinstance(scene, BuiltScene) else build(scene)
    sc = built.scene
    opt = _options_from(sc, options, overrides)
    if built.vessel is None:
        raise SceneError(sc.file, "vessel", "a vessel file (the frequency domain needs its "
                         "hydrodynamic database)")
    if built.mooring is None:
        raise SceneError(sc.file, "mooring", "a mooring section or file (the frequency domain "
                         "needs the mooring stiffness and the line tensions)")
    vessel, mooring = built.vessel, built.mooring
    db = vessel.database
    env = sc.environment
    g = sc.site.gravity
    notes: list[str] = []
    viscous = getattr(getattr(sc, "forces", None), "viscous_drift", None)
    viscous_model = getattr(viscous, "model", "none") if viscous is not None else "none"
    if viscous_model == "slender_elements":
        msg = ("forces: viscous_drift: {model: slender_elements} is a time-domain model: the "
               "frequency domain uses no viscous drift for it (potential-flow drift only, and the "
               "vessel's hull current coefficients in every DOF, without the time domain's "
               "double-counting rule); model: correction_formula gives an FD viscous drift")
        warnings.warn(msg, FloatmoorWarning, stacklevel=2)
        notes.append(msg)
    correction = viscous_model == "correction_formula" and env.waves is not None

    # -- grids and wave spectrum --------------------------------------------------------------
    w_db = np.asarray(db["omega"].values, float)
    n_w = int(round((w_db[-1] - w_db[0]) / opt.d_omega)) + 1
    w = np.linspace(w_db[0], w_db[-1], max(n_w, w_db.size))
    waves = env.waves
    if waves is not None:
        S = wave_spectrum(waves, w)
        m0_true = (waves.hs / 4.0) ** 2
        covered = float(np.trapezoid(S, w) / m0_true)
        if covered < 0.99:
            msg = (f"the database frequencies {w_db[0]:.3g}-{w_db[-1]:.3g} rad/s hold only "
                   f"{100 * covered:.1f} % of the wave spectrum's m0 (Hs {waves.hs:g} m, Tp "
                   f"{waves.tp:g} s): WF responses and drift are underestimated")
            warnings.warn(msg, FloatmoorWarning, stacklevel=2)
            notes.append(msg)
        beta = float(waves.heading)
    else:
        S = np.zeros_like(w)
        covered = 1.0
        beta = 0.0
    A_w = _interp0(w, w_db, np.asarray(db["added_mass"].values, float))
    B_w = _interp0(w, w_db, np.asarray(db["radiation_damping"].values, float))

    def drift_coefficients(yaw):
        if "mean_drift_force" not in db or waves is None:
            return np.zeros((w.size, 6))
        # eq. 6.6 (viscous correction formula) when the scene selects it: the same corrected
        # coefficients as the time domain's Newman drift, here at the body heading yaw
        db_d = corrected_drift_database(built, viscous, db, yaw=yaw) if correction else db
        c = interpolate_heading(db_d, "mean_drift_force", beta - yaw)  # (n_db, 6)
        if np.any(np.isnan(c)):
            bad = np.isnan(c).any(axis=1)
            frac = float(np.trapezoid(np.where(_interp0(w, w_db, bad.astype(float)) > 0, S, 0), w)
                         / max(np.trapezoid(S, w), 1e-300))
            if frac > 0.01:
                msg = (f"mean_drift_force is NaN where {100 * frac:.1f} % of the wave energy "
                       "lies; taken as zero there")
                warnings.warn(msg, FloatmoorWarning, stacklevel=3)
                notes.append(msg)
            c = np.nan_to_num(c)
        # zero outside the database range (no extrapolation)
        cw = _interp0(w, w_db, c)
        return cw @ _rot6(yaw).T

    if waves is not None and "mean_drift_force" not in db:
        notes.append("the database has no mean_drift_force: no wave drift (mean or slowly varying)")

    wind, cur = env.wind, env.current
    wind_tab, cur_tab = vessel.wind_coefficients, vessel.current_coefficients
    U_w = 0.0
    z_wind = None
    if wind is not None:
        if wind_tab is None:
            notes.append("the scene has wind but the vessel file has no wind_coefficients: "
                         "no wind force")
        else:
            z_wind = wind_tab.reference_height or wind.reference_height
            U_w = wind_mean_speed(wind, z_wind)
    U_c = 0.0
    if cur is not None:
        if cur_tab is None:
            notes.append("the scene has current but the vessel file has no "
                         "current_coefficients: no current force")
        else:
            U_c = float(current_speed(cur, np.array([0.0]), sc.site.water_depth)[0])

    def mean_loads(yaw):
        T = _rot6(yaw)
        f_wind = T @ wind_tab.at(wind.heading - yaw) * U_w ** 2 if U_w > 0 else np.zeros(6)
        f_cur = T @ cur_tab.at(cur.heading - yaw) * U_c ** 2 if U_c > 0 else np.zeros(6)
        C = drift_coefficients(yaw)
        f_drift = mean_drift_force(w, S, C)
        return f_wind, f_cur, f_drift, C

    # -- mean position (eq. 2.39) with the yaw iterated for the relative headings --------------
    yaw = 0.0
    x0 = None
    for _ in range(opt.heading_iterations):
        f_wind, f_cur, f_drift, C_drift = mean_loads(yaw)
        f_ext = built.static_force + f_wind + f_cur + f_drift
        eq = solve_equilibrium(mooring, hydrostatic_stiffness=vessel.total_restoring,
                         external_force=f_ext, x0=x0)
        x0 = eq.pose
        if abs(eq.pose[5] - yaw) < 1e-6:
            break
        yaw = float(eq.pose[5])
    mean = eq.pose.copy()
    yaw = float(mean[5])
    T6 = _rot6(yaw)
    K = vessel.total_restoring + eq.mooring_stiffness

    # -- wave frequency ingredients ----------------------------------------------------------
    if waves is not None:
        X = interpolate_heading(db, "excitation_force", beta - yaw)  # (n_db, 6) complex
        X = _interp0(w, w_db, X) @ T6.T
    else:
        X = np.zeros((w.size, 6), complex)
    A_w = T6[None] @ A_w @ T6.T[None]
    B_w = T6[None] @ B_w @ T6.T[None]
    M = T6 @ vessel.mass_matrix @ T6.T
    if "zero_frequency_added_mass" in db:
        A0 = np.asarray(db["zero_frequency_added_mass"].values, float)
        a0_source = "database zero_frequency_added_mass"
    else:
        A0 = np.asarray(db["added_mass"].values[0], float)
        a0_source = (f"added_mass at the lowest database frequency {w_db[0]:g} rad/s "
                     "(no zero_frequency_added_mass in the database)")
    A0 = T6 @ A0 @ T6.T

    # -- low frequency ingredients -----------------------------------------------------------
    mu = np.linspace(0.0, 2.0 * math.pi / opt.lf_cutoff_period, opt.n_lf)
    has_qtf = "difference_frequency_qtf" in db
    drift_method = opt.drift
    if correction:
        refuse_qtf_with_correction(viscous, drift_method, file=sc.file,
                                   key="frequency_domain.drift")
    if drift_method == "auto":
        drift_method = "qtf" if has_qtf and not correction else "newman"
        if has_qtf and correction:
            notes.append("the correction formula (eq. 6.6) corrects the mean drift "
                         "coefficients: slow drift by Newman's approximation, not the QTF")
    if drift_method == "qtf" and not has_qtf:
        raise SceneError(sc.file, "frequency_domain.drift", "newman or auto (the database has no "
                         "difference_frequency_qtf)", "qtf")
    if waves is None:
        S_drift = np.zeros((mu.size, 6, 6))
    elif drift_method == "qtf":
        S_drift = qtf_drift_spectrum(w, S, _qtf_function(db, beta - yaw, T6), mu)
    else:
        S_drift = newman_drift_spectrum(w, S, C_drift, mu)
    S_gust = np.zeros((mu.size, 6, 6))
    B_wind = np.zeros((6, 6))
    if U_w > 0:
        C_wi = T6 @ wind_tab.at(wind.heading - yaw)
        s_u = wind_spectrum(wind, mu / (2.0 * math.pi)) / (2.0 * math.pi) if wind.spectrum != \
            "constant" else np.zeros_like(mu)
        s_u = np.asarray(s_u, float)
        S_gust = gust_force_spectrum(2.0 * U_w * C_wi, s_u)
        B_wind = _relative_flow_damping(wind_tab, U_w, wind.heading, yaw)
    B_cur = _relative_flow_damping(cur_tab, U_c, cur.heading, yaw) if U_c > 0 else np.zeros((6, 6))
    B_drift = np.zeros((6, 6))
    if opt.wave_drift_damping and waves is not None:
        e = np.array([math.cos(beta), math.sin(beta)])
        B_drift = aranha_drift_damping(w, S, C_drift[:, :2] @ e, g, beta)
    # the vessel's linear damping, raised in surge/sway by forces: viscous_drift: extra_damping
    # with the correction formula (seed 002 section 6.6; as the time domain)
    D_lin = viscous_linear_damping(viscous, np.asarray(vessel.linear_damping, float))
    model = FDModel(omega=w, wave_spectrum=S, mass=M, added_mass=A_w, radiation_damping=B_w,
                    excitation=X, stiffness=K, linear_damping=T6 @ D_lin @ T6.T,
                    quadratic_damping=vessel.quadratic_damping, lf_added_mass=A0,
                    lf_extra_damping=B_wind + B_cur + B_drift, mu=mu,
                    lf_force_spectrum=S_drift + S_gust)
    sol = solve_frequency_domain(model)

    # -- LF eigen-periods against the cut-off --------------------------------------------------
    hz = [0, 1, 5]
    Kc = K[np.ix_(hz, hz)] - K[np.ix_(hz, [2, 3, 4])] @ np.linalg.solve(
        K[np.ix_([2, 3, 4], [2, 3, 4])], K[np.ix_([2, 3, 4], hz)])
    ev = np.linalg.eigvals(np.linalg.solve(sol.lf_mass[np.ix_(hz, hz)], Kc))
    lf_periods = 2.0 * math.pi / np.sqrt(np.sort(np.abs(ev.real)))[::-1]
    if np.min(lf_periods) < opt.lf_cutoff_period:
        msg = (f"an LF natural period ({np.min(lf_periods):.1f} s) is shorter than the LF "
               f"cut-off period {opt.lf_cutoff_period:g} s: its resonance lies outside the LF "
               "band")
        warnings.warn(msg, FloatmoorWarning, stacklevel=2)
        notes.append(msg)

    # -- motion statistics ---------------------------------------------------------------------
    wf_std, wf_tz = response_std_tz(w, sol.wf_spectrum)
    lf_std, lf_tz = response_std_tz(mu, sol.lf_spectrum)
    wf_max, wf_n = _rayleigh(wf_std, wf_tz, opt.duration)
    lf_max, lf_n = _rayleigh(lf_std, lf_tz, opt.duration)
    wf_sig, lf_sig = 2.0 * wf_std, 2.0 * lf_std
    max_tot, min_tot, branch = combine_maxima(mean, lf_sig, lf_max, wf_sig, wf_max)

    # -- fairleads and lines -------------------------------------------------------------------
    names = list(mooring.names)
    active = np.asarray(mooring.active, bool)
    fl = mooring.fairlead_positions(mean)
    r = fl - mean[:3]
    d = fl[:, :2] - mooring.anchors[:, :2]
    e = np.zeros((len(names), 3))
    e[:, :2] = d / np.linalg.norm(d, axis=1)[:, None]
    a = np.zeros((len(names), 6))  # fairlead displacement along the line (outward) per pose
    a[:, :3] = e
    a[:, 3:] = np.cross(r, e)
    T_mean = mooring.tensions(mean)["fairlead_tension"].values
    steps = np.array([0.01, 0.01, 0.01, 1e-5, 1e-5, 1e-5])
    grad = np.zeros((len(names), 6))
    for k in range(6):
        dp = np.zeros(6)
        dp[k] = steps[k]
        tp = mooring.tensions(mean + dp)["fairlead_tension"].values
        tm = mooring.tensions(mean - dp)["fairlead_tension"].values
        grad[:, k] = (tp - tm) / (2 * steps[k])
    mooring.tensions(mean)  # leave the warm starts at the mean position
    tangent = np.einsum("lk,lk->l", grad[:, :3], e)  # dT/du along the line, N/m

    def proj_wf(vecs):
        h = sol.rao @ vecs.T  # (n_w, n_lines)
        return np.abs(h) ** 2 * S[:, None]

    def proj_lf(vecs):
        return np.real(np.einsum("li,nij,lj->nl", vecs, sol.lf_cross_spectrum, vecs))

    fm_wf, fm_lf = proj_wf(a), proj_lf(a)
    fm_wf_std, fm_wf_tz = response_std_tz(w, fm_wf)
    fm_lf_std, fm_lf_tz = response_std_tz(mu, fm_lf)
    tw, tl = proj_wf(np.nan_to_num(grad)), proj_lf(np.nan_to_num(grad))
    t_wf_std, t_wf_tz = response_std_tz(w, tw)
    t_lf_std, t_lf_tz = response_std_tz(mu, tl)
    cols = tension_columns(T_mean, t_lf_std, t_lf_tz, t_wf_std, t_wf_tz,
                           np.asarray(mooring.mbs, float), opt.duration)
    t_lf_max, t_wf_max, t_base, t_max = (cols[k] for k in ("max_lf", "max_wf", "wf_base",
                                                           "max_total"))
    t_branch, mbs, sf = cols["branch"], np.asarray(mooring.mbs, float), cols["safety_factor"]
    nan_failed = lambda x: np.where(active, x, np.nan)  # noqa: E731
    # Nonlinear check: the catenary tension at the most likely pose giving each line's eq. 2.49
    # tension excursion (the conditional mean of the Gaussian pose given the linear tension
    # process g . x at that value: dx = C g a / sigma per band, C the pose covariance).
    g0 = np.nan_to_num(grad)
    k_lf = np.where(t_lf_std > 0, t_lf_max / np.where(t_lf_std > 0, t_lf_std, 1.0), 0.0)
    k_wf = np.where(t_wf_std > 0, t_wf_max / np.where(t_wf_std > 0, t_wf_std, 1.0), 0.0)
    a_lf = np.where(t_branch == 1, k_lf, 2.0)
    a_wf = np.where(t_branch == 1, 2.0, k_wf)
    t_cat = np.full(len(names), np.nan)
    for i in np.nonzero(active)[0]:
        dx = np.zeros(6)
        if t_lf_std[i] > 0:
            dx += sol.lf_covariance @ g0[i] * (a_lf[i] / t_lf_std[i])
        if t_wf_std[i] > 0:
            dx += sol.wf_covariance @ g0[i] * (a_wf[i] / t_wf_std[i])
        t_cat[i] = mooring.tensions(mean + dx)["fairlead_tension"].values[i]
    mooring.tensions(mean)

    # -- the Dataset ---------------------------------------------------------------------------
    def v(dims, x, units, long_name, **extra):
        return (dims, np.asarray(x), {"units": units, "long_name": long_name, **extra})

    rao = np.stack([sol.rao.real, sol.rao.imag], axis=-1)
    data = {
        "mean": v("dof", mean, _MIXED_UNITS, "mean position (static equilibrium, eq. 2.39)"),
        "mean_force_wind": v("dof", f_wind, _MIXED_FORCE, "mean wind force C_wi U^2"),
        "mean_force_current": v("dof", f_cur, _MIXED_FORCE, "mean current force C_cu V^2"),
        "mean_force_drift": v("dof", f_drift, _MIXED_FORCE,
                              "mean wave drift force 2 int C_wa S dw (eq. 2.37)"),
        "wf_std": v("dof", wf_std, _MIXED_UNITS, "WF standard deviation (eq. 2.41)"),
        "wf_tz": v("dof", wf_tz, "s", "WF mean zero up-crossing period 2 pi sqrt(m0/m2)"),
        "wf_n_cycles": v("dof", wf_n, "1", "WF number of cycles duration / Tz"),
        "wf_sig": v("dof", wf_sig, _MIXED_UNITS, "WF significant value 2 sigma (eq. 2.42)"),
        "wf_max": v("dof", wf_max, _MIXED_UNITS,
                    "WF most probable maximum sigma sqrt(2 ln N) (eq. 2.43)"),
        "lf_std": v("dof", lf_std, _MIXED_UNITS, "LF standard deviation (eq. 2.46)"),
        "lf_tz": v("dof", lf_tz, "s", "LF mean zero up-crossing period 2 pi sqrt(m0/m2)"),
        "lf_n_cycles": v("dof", lf_n, "1", "LF number of cycles duration / Tz"),
        "lf_sig": v("dof", lf_sig, _MIXED_UNITS, "LF significant value 2 sigma (eq. 2.47)"),
        "lf_max": v("dof", lf_max, _MIXED_UNITS,
                    "LF most probable maximum sigma sqrt(2 ln N) (eq. 2.48)"),
        "max_total": v("dof", max_tot, _MIXED_UNITS, "maximum: mean + max(LFmax + WFsig, "
                       "WFmax + LFsig) (eq. 2.49)"),
        "min_total": v("dof", min_tot, _MIXED_UNITS, "minimum: mean - max(LFmax + WFsig, "
                       "WFmax + LFsig) (eq. 2.49 mirrored)"),
        "governing_branch": v("dof", branch, "1", "eq. 2.49 branch: 1 LFmax + WFsig, "
                              "2 WFmax + LFsig"),
        "wave_spectrum": v("omega", S, "m^2 s/rad", "wave elevation spectrum S_eta"),
        "rao": v(("omega", "dof", "complex"), rao, "m/m (translations), rad/m (rotations)",
                 "first-order motion RAO, exp(+i omega t) (eq. 2.40)"),
        "wf_spectrum": v(("omega", "dof"), sol.wf_spectrum,
                         "m^2 s/rad (translations), rad^2 s/rad (rotations)",
                         "WF response spectrum |H|^2 S (eq. 2.34)"),
        "lf_spectrum": v(("mu", "dof"), sol.lf_spectrum,
                         "m^2 s/rad (translations), rad^2 s/rad (rotations)",
                         "LF response spectrum (eq. 2.44)"),
        "lf_drift_force_spectrum": v(("mu", "dof"), np.einsum("nii->ni", S_drift),
                                     "N^2 s/rad (forces), N^2 m^2 s/rad (moments)",
                                     f"slowly varying wave drift force spectrum ({drift_method}, "
                                     "eq. 2.38)"),
        "lf_wind_force_spectrum": v(("mu", "dof"), np.einsum("nii->ni", S_gust),
                                    "N^2 s/rad (forces), N^2 m^2 s/rad (moments)",
                                    "wind gust force spectrum 4 U^2 C^2 S_u"),
        "stiffness": v(("dof", "dof2"), K, "N/m, N, N m/rad", "restoring at the mean position "
                       "(hydrostatic + mooring)"),
        "lf_mass": v(("dof", "dof2"), sol.lf_mass, "kg, kg m, kg m^2",
                     "LF mass M + A(0) (surge, sway, yaw)"),
        "lf_damping": v(("dof", "dof2"), sol.lf_damping, "N s/m, N s, N m s/rad",
                        "LF damping: linear + linearised quadratic + wind + current (+ drift)"),
        "lf_damping_wind": v(("dof", "dof2"), B_wind, "N s/m, N s, N m s/rad", "wind damping"),
        "lf_damping_current": v(("dof", "dof2"), B_cur, "N s/m, N s, N m s/rad",
                                "current damping"),
        "lf_damping_wave_drift": v(("dof", "dof2"), B_drift, "N s/m, N s, N m s/rad",
                                   "wave drift damping (Aranha; option)"),
        "equivalent_quadratic_damping": v(("dof", "dof2"), sol.equivalent_damping,
                                          "N s/m, N s, N m s/rad",
                                          "stochastic linearisation sqrt(8/pi) sigma_v B_q"),
        "lf_natural_period": v("lf_mode", lf_periods, "s",
                               "undamped LF natural periods (surge/sway/yaw, heave-roll-pitch "
                               "condensed)"),
        "fairlead_motion_wf_spectrum": v(("omega", "line"), fm_wf, "m^2 s/rad",
                                         "WF spectrum of the fairlead motion along the line "
                                         "(positive away from the anchor)"),
        "fairlead_motion_lf_spectrum": v(("mu", "line"), fm_lf, "m^2 s/rad",
                                         "LF spectrum of the fairlead motion along the line"),
        "fairlead_motion_wf_std": v("line", fm_wf_std, "m", "WF std of the fairlead motion "
                                    "along the line"),
        "fairlead_motion_wf_tz": v("line", fm_wf_tz, "s", "WF Tz of the fairlead motion"),
        "fairlead_motion_lf_std": v("line", fm_lf_std, "m", "LF std of the fairlead motion "
                                    "along the line"),
        "fairlead_motion_lf_tz": v("line", fm_lf_tz, "s", "LF Tz of the fairlead motion"),
        "tension_gradient": v(("line", "dof"), grad, "N/m (translations), N/rad (rotations)",
                              "dT/dpose at the mean position (central differences)"),
        "tangent_stiffness": v("line", nan_failed(tangent), "N/m",
                               "dT/du, u the fairlead displacement along the line"),
        "tension_static": v("line", nan_failed(T_mean), "N", "static (mean) fairlead tension"),
        "tension_std_lf": v("line", nan_failed(t_lf_std), "N", "LF tension std"),
        "tension_tz_lf": v("line", nan_failed(t_lf_tz), "s", "LF tension Tz"),
        "tension_max_lf": v("line", nan_failed(t_lf_max), "N", "LF tension most probable "
                            "maximum (above static)"),
        "tension_wf_base": v("line", nan_failed(t_base), "N", "WF base: max total - max WF "
                             "(eq. 2.60)"),
        "tension_std_wf": v("line", nan_failed(t_wf_std), "N", "WF tension std"),
        "tension_tz_wf": v("line", nan_failed(t_wf_tz), "s", "WF tension Tz"),
        "tension_max_wf": v("line", nan_failed(t_wf_max), "N", "WF tension most probable "
                            "maximum"),
        "tension_max_total": v("line", nan_failed(t_max), "N", "maximum tension, eq. 2.49 on "
                               "the quasi-static tension"),
        "tension_branch": v("line", t_branch, "1", "eq. 2.49 branch for the tension"),
        "tension_max_total_catenary": v(
            "line", nan_failed(t_cat), "N", "catenary tension at the most likely pose of the "
            "eq. 2.49 tension excursion (nonlinear quasi-static check of max total)"),
        "mbs": v("line", mbs, "N", "minimum breaking strength"),
        "safety_factor": v("line", nan_failed(sf), "1", "MBS / maximum tension"),
        "line_failed": v("line", ~active, "1", "line removed (failed)"),
    }
    ds = xr.Dataset(
        data,
        coords={"dof": list(DOF_NAMES), "dof2": list(DOF_NAMES),
                "omega": ("omega", w, {"units": "rad/s", "long_name": "wave frequency"}),
                "mu": ("mu", mu, {"units": "rad/s", "long_name": "low (difference) frequency"}),
                "line": names, "complex": ["re", "im"],
                "lf_mode": np.arange(lf_periods.size)})
    ds.attrs.update({
        "title": "floatmoor frequency-domain analysis (MIMOSA-style)",
        "scene": str(sc.file) if sc.file else sc.name,
        "scene_name": sc.name,
        "floatmoor_version": __version__,
        "numpy_version": np.__version__,
        "xarray_version": xr.__version__,
        "options": repr(asdict(opt)),
        "duration": opt.duration,
        "tension_model": opt.tension_model,
        "drift_method": drift_method if waves is not None else "none (no waves)",
        "viscous_drift_model": viscous_model if viscous_model != "slender_elements"
        else "slender_elements (not in the frequency domain: none)",
        "lf_added_mass_source": a0_source,
        "lf_cutoff_frequency": float(mu[-1]),
        "wave_heading": beta,
        "wind_speed_at_coefficient_height": U_w,
        "wind_coefficient_height": float(z_wind) if z_wind is not None else float("nan"),
        "current_speed_surface": U_c,
        "wave_spectrum_fraction_covered": covered,
        "linearisation_iterations": sol.iterations,
        "statics_iterations": eq.iterations,
        "notes": "; ".join(notes) if notes else "",
        "run_time_s": time.perf_counter() - t_start,
        "run_date_utc": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
    })
    return ds


# -- text output -------------------------------------------------------------------------------
def format_table(ds: xr.Dataset) -> str:
    """The MIMOSA-style report of a :func:`frequency_domain` result: motions (mean, LF, WF,
    eq. 2.49 total) and the line tension table of seed figure 5.9 (kN)."""
    out = [f"Frequency-domain analysis: {ds.attrs.get('scene_name', '')}",
           f"  duration {ds.attrs['duration']:g} s, tension model {ds.attrs['tension_model']}, "
           f"drift {ds.attrs['drift_method']}, LF mass: {ds.attrs['lf_added_mass_source']}",
           "",
           "* MOTIONS (translations m, rotations deg) *",
           "  DOF      Mean    StD LF  Max LF   StD WF  Sig WF   Max WF   Max Tot  Min Tot"]
    for i, d in enumerate(ds["dof"].values):
        f = 1.0 if i < 3 else 180.0 / math.pi
        vals = [ds[k].values[i] * f for k in ("mean", "lf_std", "lf_max", "wf_std", "wf_sig",
                                              "wf_max", "max_total", "min_total")]
        out.append(f"  {d:6s}" + "".join(f"{x:9.2f}" for x in vals))
    out += ["", "* MAXIMUM LINE TENSIONS. LF AND WF MOTION *  (kN)",
            "  Line       Static  StD LF  Max LF WF Base  StD WF  Max WF Max Tot  Safety  Max Tot",
            "                                                                      factor  catenary"]
    cols = ("tension_static", "tension_std_lf", "tension_max_lf", "tension_wf_base",
            "tension_std_wf", "tension_max_wf", "tension_max_total")
    for j, name in enumerate(ds["line"].values):
        if bool(ds["line_failed"].values[j]):
            out.append(f"  {str(name):9s}  failed (removed)")
            continue
        vals = [ds[c].values[j] / 1e3 for c in cols]
        out.append(f"  {str(name):9s}" + "".join(f"{x:8.1f}" for x in vals)
                   + f"{ds['safety_factor'].values[j]:8.2f}"
                   + f"{ds['tension_max_total_catenary'].values[j] / 1e3:9.1f}")
    out += ["  (Max Tot: eq. 2.49 on the linearised quasi-static tension; Max Tot catenary: the "
            "catenary at the most likely pose of that excursion)"]
    if ds.attrs.get("notes"):
        out += ["", "notes: " + ds.attrs["notes"]]
    return "\n".join(out)

"""Frequency-domain analysis of a scene, MIMOSA-style (user API).

>>> import floatmoor
>>> ds = floatmoor.frequency_domain("scenes/floatel_100yr.yaml")
>>> print(floatmoor.format_fd_table(ds))

:func:`frequency_domain_result` does the computation and returns an
:class:`~floatmoor.analyses.fd_result.FDResult` (numpy arrays);
:func:`frequency_domain` turns it into the Dataset (:mod:`floatmoor.analyses.fd_dataset`, one
table of variables with units).

What is computed (Wang (2016) section 2.2.2 eq. 2.34-2.49 and section 2.3)
--------------------------------------------------------------------------
1. **Mean** (eq. 2.39): static equilibrium (:func:`floatmoor.solvers.statics.solve_equilibrium`,
   the same vessel, mooring and net buoyancy as every solver via :func:`floatmoor.io.build.build`)
   under the mean wind force C_wi(theta) U^2 (U the 1-hour mean speed at the coefficients'
   reference height), the current force C_cu(theta) V^2 (V the current speed at the still
   water line, z = 0) and the mean wave drift 2 int C_wa(w) S(w) dw.  Coefficients are taken at
   the heading relative to the body; the mean yaw is iterated (``heading_iterations``).
   The catenary lines carry no current.  With ``line_current_drag`` (option, default off) the
   static current drag on the lines enters as well: each active line's FE statics in the
   scene's current profile minus its FE statics in still water
   (:class:`~floatmoor.mooring.fe.current_statics.LineCurrentStatics`) is added to the
   catenary force, iterated with the pose (and the yaw) to a fixed point; the static tensions
   get the same increment, and the linearisation (mooring stiffness and tension gradients of
   the catenary, the dynamic line model) is taken at that mean pose.  The drag's own change
   with the pose (central differences of the increment at the mean,
   :meth:`~floatmoor.mooring.fe.current_statics.LineCurrentStatics.linearise`) is added to the
   mooring stiffness and to the tension gradients (Floatel-like 100-year case: -6.5 % in the
   surge and sway stiffness, +13 % in yaw; checked against the coupled FE static pose under
   an extra load).  Fibre ropes take their dynamic stiffness at the catenary's mean
   tension at that pose (without the drag's increment).  Floatel-like 100-year case: mean surge 13.6 m against 10.5 m
   without and 14.7 m in coupled FE storms, whose lines also oscillate in the current
   (benchmarks/RESULTS.md, "FD mean position with the current drag on the lines").
2. **Wave frequency** (eq. 2.34, 2.40-2.43): RAOs from the database (A(w), B(w), X(w) linearly
   interpolated on a fine grid of step ``d_omega`` over the database's frequency range) with the
   hydrostatic restoring plus the mooring's analytic stiffness at the mean position and the
   vessel's linear (and linearised quadratic) damping.  A quasi-static mooring adds no damping.
3. **Low frequency** (eq. 2.35, 2.38, 2.44-2.48): surge, sway and yaw with mass M + A(0)
   (the database's ``zero_frequency_added_mass``, else A at its lowest frequency: see the
   attribute ``lf_added_mass_source``); heave, roll and pitch follow quasi-statically.  Damping:
   vessel linear damping, quadratic damping linearised stochastically (iterated), wind and
   current damping -dF/dv of F = C(theta_rel) |U - v|^2 at the mean velocities, optionally
   Aranha's wave drift damping; with ``line_damping: fe`` (option, default ``none``) the
   mooring lines' LF impedance from their FE models under the WF and LF fairlead motion
   (drag damping and the drag's dynamic stiffening, frequency by frequency, iterated with the
   response: :mod:`~floatmoor.analyses.fd_line_damping`; Floatel-like 100-year case: 42 % of
   the LF surge damping at the natural period, LF surge std 2.44 -> 1.71 m against 1.81 m in
   coupled FE storms, benchmarks/RESULTS.md).  Excitation: slowly varying drift by Newman's approximation
   (eq. 2.38) or the full difference-frequency QTF when the database has one, plus the wind
   gust 4 U^2 C C^T S_u (the scene's gust spectrum, NPD by default).  Integrated from 0 to the
   LF cut-off 2 pi / ``lf_cutoff_period`` (30 s: the LF band of Wang (2016) section
   2.2.2).
4. **Maxima**: Rayleigh most probable maxima sigma sqrt(2 ln N), N = duration / Tz with Tz of
   each response spectrum; significant = 2 sigma (eq. 2.42/2.47).  Combination (eq. 2.49):
   X_max = X_mean + max(X_LF,max + X_WF,sig, X_WF,max + X_LF,sig) (and X_min likewise).
5. **Line tensions** (quasi-static, Wang (2016) section 2.3.1): T(mean) from the catenary; the
   LF and WF tension processes are g . x with g = dT/dpose the line's tangent stiffness at the
   mean position (central differences of the catenary, i.e. the tension change per fairlead
   displacement along the line's direction); their std, Tz and maxima as above, combined with
   eq. 2.49.  Columns as figure 5.9: static, std LF, max LF, WF base, std WF, max WF, max
   total, safety factor MBS / max total; WF base = max total - max WF (eq. 2.60: the tension at
   the offset X_max - X_WF,max, from which the WF maximum is added).
   ``tension_max_total_catenary`` re-evaluates the catenary at the most likely pose giving that
   excursion (the conditional mean pose of the Gaussian responses), which shows the effect of
   the line's nonlinearity.  With ``tension_model: dynamic`` the WF tension std and Tz come
   from each line's FE model linearised in the frequency domain under its WF fairlead motion
   (:mod:`~floatmoor.analyses.fd_line_dynamics`; ANSYS (2013) eq. 9-75, touchdown by Ong &
   Pellegrino (2003)); the quasi-static WF std and the dynamic amplification are reported
   beside it; the LF tension stays quasi-static unless ``line_damping: fe``, which adds the FE
   lines' dynamic tension increment to the LF tension transfer (quasi-static LF std kept as
   ``tension_std_lf_quasi_static``).
6. **Viscous drift** (Wang (2016) chapter 6; the scene key ``forces: viscous_drift``):
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
import sys
import time
import warnings
from dataclasses import dataclass, fields, replace

import numpy as np
import xarray as xr

from ..core.errors import FloatmoorWarning, NumericalError, SceneError
from ..forces.slender import (
    corrected_drift_database,
    refuse_qtf_with_correction,
    viscous_linear_damping,
)
from ..hydro.database import interpolate_heading
from ..io.build import BuiltScene, build
from ..io.scene import Scene
from ..metocean.current import current_speed
from ..metocean.spectra import wave_spectrum
from ..metocean.wind import wind_mean_speed, wind_spectrum
from ..mooring.fe.current_statics import LineCurrentStatics
from ..solvers.frequency_domain import (
    FDModel,
    FDOptions,
    aranha_drift_damping,
    gust_force_spectrum,
    mean_drift_force,
    newman_drift_spectrum,
    qtf_drift_spectrum,
    response_std_tz,
    solve_frequency_domain,
)
from ..solvers.statics import solve_equilibrium
from .fd_dataset import to_dataset
from .fd_line_damping import damping_ratio, iterate_line_damping, lf_tension_spectra
from .fd_line_dynamics import dynamic_line_columns
from .fd_loads import interp0, qtf_function, relative_flow_damping, rot6
from .fd_maxima import combine_maxima, rayleigh_maxima, tension_columns
from .fd_result import FDResult

__all__ = ["frequency_domain", "frequency_domain_result", "FDOptions", "FDResult"]

LINE_CURRENT_MAX_ITER = 30
"""Iterations of the mean position with the lines' current drag (``line_current_drag``)."""
LINE_CURRENT_TOL = (1e-4, 1e-7)
"""Convergence of that iteration: pose change below 0.1 mm and 1e-7 rad."""


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
    ``complex``; every variable has ``units`` and ``long_name`` (the table
    :data:`floatmoor.analyses.fd_dataset.VARIABLES`).  Main variables: ``mean``, ``wf_std``,
    ``wf_sig``, ``wf_max``, ``wf_tz``, ``lf_std``, ``lf_sig``, ``lf_max``, ``lf_tz``,
    ``max_total``, ``min_total`` (per DOF, m and rad), the spectra, the RAOs, per line
    ``tension_static`` ... ``tension_max_total``, ``safety_factor`` (figure 5.9 columns) and the
    fairlead motion along each line.

    Raises
    ------
    SceneError for a scene without vessel or mooring, or bad options; NumericalError /
    ConvergenceError when the statics or the linearisation fail.
    """
    return to_dataset(frequency_domain_result(scene, options=options, **overrides))


def frequency_domain_result(scene: Scene | BuiltScene | str | os.PathLike, *,
                            options: FDOptions | None = None, **overrides) -> FDResult:
    """The computation of :func:`frequency_domain` (same arguments), as an :class:`FDResult`
    of numpy arrays (no xarray)."""
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
    notes = _Notes()
    viscous, viscous_model = _viscous_drift(sc, notes)
    grid = _WaveGrid.of(built.vessel.database, sc.environment.waves, opt, notes)
    loads = _MeanLoads(built, grid, viscous, notes)
    drag_lin = None
    if opt.line_current_drag:
        eq, C_drift, mean_parts, drag_lin = _mean_position_line_current(built, loads, opt, notes)
    else:
        eq, C_drift, mean_parts = _mean_position(built, loads, opt)
    eq, moor = _fibre_dynamics(built, eq, notes)
    if drag_lin is not None:
        # the lines' current drag changes with the pose: its stiffness joins the mooring's
        eq = replace(eq, mooring_stiffness=eq.mooring_stiffness + drag_lin[0],
                     total_stiffness=eq.total_stiffness + drag_lin[0])
    model, lf_parts = _linear_model(built, opt, grid, loads, eq, C_drift, viscous, notes)
    sol = solve_frequency_domain(model)
    damping_parts, line_dyn = {}, None
    if opt.line_damping == "fe":
        model, sol, damping_parts, line_dyn = _line_damping(built, mean_parts["mean"], model,
                                                            sol, notes)
    lf_periods = _lf_natural_periods(model.stiffness, sol.lf_mass, opt, notes)
    mean = mean_parts["mean"]
    motions = _motion_statistics(mean, sol, model, opt.duration)
    lines = _line_statistics(moor, mean, sol, model, opt.duration,
                             tension_offset=mean_parts.get("tension_static_line_current"),
                             gradient_offset=None if drag_lin is None else drag_lin[1])
    if line_dyn is not None:
        # the LF tension with the lines' dynamics (their impedance is in the LF motion)
        lines.update(_dynamic_lf_tension(line_dyn, lines, sol, model, opt.duration))
    if opt.tension_model == "dynamic":
        # WF tension from the FE lines in the frequency domain; LF stays quasi-static
        lines.update(dynamic_line_columns(built, mean, sol, model, lines, opt.duration))
    return FDResult(
        scene=str(sc.file) if sc.file else sc.name, scene_name=sc.name, options=opt,
        model=model, solution=sol, line_names=tuple(built.mooring.names), **mean_parts,
        statics_iterations=eq.iterations, **lf_parts, lf_natural_period=lf_periods, **motions,
        **lines, has_waves=grid.waves is not None, viscous_drift_model=viscous_model,
        wave_heading=grid.beta, wind_speed_at_coefficient_height=loads.U_w,
        wind_coefficient_height=float(loads.z_wind) if loads.z_wind is not None else float("nan"),
        current_speed_surface=loads.U_c, wave_spectrum_fraction_covered=grid.covered,
        linearisation_iterations=sol.iterations, **damping_parts, notes=tuple(notes),
        run_time_s=time.perf_counter() - t_start)


# -- the stages of the computation -------------------------------------------------------------
class _Notes(list):
    """The remarks of a run (attribute ``notes``); :meth:`warn` also shows them as warnings,
    attributed to the first caller outside this package (the user's line)."""

    def warn(self, msg: str) -> None:
        here = os.path.dirname(__file__) + os.sep
        frame, level = sys._getframe(0), 1
        while frame is not None and frame.f_code.co_filename.startswith(here):
            frame, level = frame.f_back, level + 1
        warnings.warn(msg, FloatmoorWarning, stacklevel=level)
        self.append(msg)


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


def _viscous_drift(sc: Scene, notes: _Notes):
    """The scene's viscous drift section and its model name (``none`` without one)."""
    viscous = getattr(getattr(sc, "forces", None), "viscous_drift", None)
    model = getattr(viscous, "model", "none") if viscous is not None else "none"
    if model == "slender_elements":
        notes.warn("forces: viscous_drift: {model: slender_elements} is a time-domain model: the "
                   "frequency domain uses no viscous drift for it (potential-flow drift only, and "
                   "the vessel's hull current coefficients in every DOF, without the time "
                   "domain's double-counting rule); model: correction_formula gives an FD "
                   "viscous drift")
    return viscous, model


@dataclass(frozen=True)
class _WaveGrid:
    """The WF grid ``w`` over the database's range ``w_db``, the wave spectrum ``S`` on it,
    the fraction of m0 it covers and the wave heading ``beta`` (rad)."""

    waves: object
    w_db: np.ndarray
    w: np.ndarray
    S: np.ndarray
    covered: float
    beta: float

    @classmethod
    def of(cls, db, waves, opt: FDOptions, notes: _Notes) -> _WaveGrid:
        w_db = np.asarray(db["omega"].values, float)
        n_w = int(round((w_db[-1] - w_db[0]) / opt.d_omega)) + 1
        w = np.linspace(w_db[0], w_db[-1], max(n_w, w_db.size))
        if waves is None:
            return cls(None, w_db, w, np.zeros_like(w), 1.0, 0.0)
        S = wave_spectrum(waves, w)
        m0_true = (waves.hs / 4.0) ** 2
        covered = float(np.trapezoid(S, w) / m0_true)
        if covered < 0.99:
            notes.warn(f"the database frequencies {w_db[0]:.3g}-{w_db[-1]:.3g} rad/s hold only "
                       f"{100 * covered:.1f} % of the wave spectrum's m0 (Hs {waves.hs:g} m, Tp "
                       f"{waves.tp:g} s): WF responses and drift are underestimated")
        return cls(waves, w_db, w, S, covered, float(waves.heading))


class _MeanLoads:
    """Mean wind, current and wave drift forces (earth axes) at a body yaw; the drift
    coefficients are those of the viscous correction formula (eq. 6.6) when the scene selects
    it, at that yaw."""

    def __init__(self, built: BuiltScene, grid: _WaveGrid, viscous, notes: _Notes):
        sc, vessel = built.scene, built.vessel
        env = sc.environment
        self.built, self.grid, self.viscous, self.notes = built, grid, viscous, notes
        self.db = vessel.database
        self.correction = (getattr(viscous, "model", "none") == "correction_formula"
                           and grid.waves is not None)
        if grid.waves is not None and "mean_drift_force" not in self.db:
            notes.append("the database has no mean_drift_force: no wave drift (mean or slowly "
                         "varying)")
        self.wind, self.cur = env.wind, env.current
        self.wind_tab, self.cur_tab = vessel.wind_coefficients, vessel.current_coefficients
        self.U_w, self.z_wind, self.U_c = 0.0, None, 0.0
        if self.wind is not None:
            if self.wind_tab is None:
                notes.append("the scene has wind but the vessel file has no wind_coefficients: "
                             "no wind force")
            else:
                self.z_wind = self.wind_tab.reference_height or self.wind.reference_height
                self.U_w = wind_mean_speed(self.wind, self.z_wind)
        if self.cur is not None:
            if self.cur_tab is None:
                notes.append("the scene has current but the vessel file has no "
                             "current_coefficients: no current force")
            else:
                self.U_c = float(current_speed(self.cur, np.array([0.0]),
                                               sc.site.water_depth)[0])

    def drift_coefficients(self, yaw: float) -> np.ndarray:
        """(n_w, 6) mean drift coefficients C_wa(w) on the WF grid, earth axes."""
        db, g = self.db, self.grid
        if "mean_drift_force" not in db or g.waves is None:
            return np.zeros((g.w.size, 6))
        # eq. 6.6 (viscous correction formula) when the scene selects it: the same corrected
        # coefficients as the time domain's Newman drift, here at the body heading yaw
        db_d = corrected_drift_database(self.built, self.viscous, db, yaw=yaw) \
            if self.correction else db
        c = interpolate_heading(db_d, "mean_drift_force", g.beta - yaw)  # (n_db, 6)
        if np.any(np.isnan(c)):
            bad = np.isnan(c).any(axis=1)
            frac = float(np.trapezoid(np.where(interp0(g.w, g.w_db, bad.astype(float)) > 0,
                                               g.S, 0), g.w)
                         / max(np.trapezoid(g.S, g.w), 1e-300))
            if frac > 0.01:
                self.notes.warn(f"mean_drift_force is NaN where {100 * frac:.1f} % of the wave "
                                "energy lies; taken as zero there")
            c = np.nan_to_num(c)
        # zero outside the database range (no extrapolation)
        cw = interp0(g.w, g.w_db, c)
        return cw @ rot6(yaw).T

    def __call__(self, yaw: float):
        """(wind, current, drift) forces (6,) and the drift coefficients at the yaw."""
        T = rot6(yaw)
        U_w, U_c = self.U_w, self.U_c
        f_wind = T @ self.wind_tab.at(self.wind.heading - yaw) * U_w ** 2 if U_w > 0 \
            else np.zeros(6)
        f_cur = T @ self.cur_tab.at(self.cur.heading - yaw) * U_c ** 2 if U_c > 0 \
            else np.zeros(6)
        C = self.drift_coefficients(yaw)
        f_drift = mean_drift_force(self.grid.w, self.grid.S, C)
        return f_wind, f_cur, f_drift, C


def _mean_position(built: BuiltScene, loads: _MeanLoads, opt: FDOptions):
    """Static equilibrium under the mean loads (eq. 2.39), the yaw iterated for the relative
    headings.  Returns the equilibrium, the drift coefficients of the last iteration and a dict of
    FDResult fields."""
    vessel = built.vessel
    yaw = 0.0
    x0 = None
    for _ in range(opt.heading_iterations):
        f_wind, f_cur, f_drift, C_drift = loads(yaw)
        f_ext = built.static_force + f_wind + f_cur + f_drift
        eq = solve_equilibrium(built.mooring, hydrostatic_stiffness=vessel.total_restoring,
                               external_force=f_ext, x0=x0)
        x0 = eq.pose
        if abs(eq.pose[5] - yaw) < 1e-6:
            break
        yaw = float(eq.pose[5])
    return eq, C_drift, {"mean": eq.pose.copy(), "mean_force_wind": f_wind,
                         "mean_force_current": f_cur, "mean_force_drift": f_drift}


def _mean_position_line_current(built: BuiltScene, loads: _MeanLoads, opt: FDOptions,
                                notes: _Notes):
    """:func:`_mean_position` with the static current drag on the lines (``line_current_drag``):
    the fixed point p_{k+1} = equilibrium(F_ext(yaw_k) + dF(p_k)), dF the lines' current drag
    increment (:class:`~floatmoor.mooring.fe.current_statics.LineCurrentStatics`), from dF = 0
    (the first solve is that of the default path), until the pose moves less than
    ``LINE_CURRENT_TOL`` (m, rad); the mean yaw is iterated in the same loop.  dF varies slowly
    with the pose (Floatel-like 100-year case: 20 kN/m in surge against the catenary's 310
    kN/m), so a few iterations suffice.  Adds ``mean_force_line_current`` and
    ``tension_static_line_current`` (the increment at the final pose) to the FDResult fields,
    and returns as well the increment's linearisation at the mean
    (:meth:`~floatmoor.mooring.fe.current_statics.LineCurrentStatics.linearise`: its 6x6
    stiffness and the gradients of the tension increments; None without current)."""
    if getattr(built.scene.environment, "current", None) is None:
        notes.append("line_current_drag: the scene has no current (no drag on the lines)")
        return (*_mean_position(built, loads, opt), None)
    vessel = built.vessel
    drag = None
    dF = np.zeros(6)
    x0 = None
    yaw = 0.0
    it = 0
    while it < LINE_CURRENT_MAX_ITER:
        it += 1
        f_wind, f_cur, f_drift, C_drift = loads(yaw)
        f_ext = built.static_force + f_wind + f_cur + f_drift + dF
        eq = solve_equilibrium(built.mooring, hydrostatic_stiffness=vessel.total_restoring,
                               external_force=f_ext, x0=x0)
        if x0 is not None:
            dx = np.abs(eq.pose - x0)
            if dx[:3].max() < LINE_CURRENT_TOL[0] and dx[3:].max() < LINE_CURRENT_TOL[1]:
                break
        x0 = eq.pose
        yaw = float(eq.pose[5])
        if drag is None:
            drag = LineCurrentStatics.from_scene(built.scene, built.mooring, pose=x0)
        dF = drag(x0).force
    else:
        raise NumericalError(f"no mean position with the current drag on the lines in "
                             f"{LINE_CURRENT_MAX_ITER} iterations (last pose change "
                             f"{dx[:3].max():.3g} m, {dx[3:].max():.3g} rad)",
                             where="frequency domain, mean position",
                             remedy="check the current and the lines' FE options; without "
                                    "frequency_domain: line_current_drag the lines carry no "
                                    "current")
    inc = drag(eq.pose)
    lin = drag.linearise(eq.pose)
    notes.append(f"line_current_drag: mean position with the lines' static current drag "
                 f"({inc.force[0] / 1e3:.1f} kN surge, {inc.force[1] / 1e3:.1f} kN sway; "
                 f"{it} equilibrium iterations); its stiffness in the linearisation "
                 f"({lin[0][0, 0] / 1e3:.1f} kN/m surge, {lin[0][1, 1] / 1e3:.1f} kN/m sway)")
    return eq, C_drift, {"mean": eq.pose.copy(), "mean_force_wind": f_wind,
                         "mean_force_current": f_cur, "mean_force_drift": f_drift,
                         "mean_force_line_current": inc.force,
                         "tension_static_line_current": inc.tension}, lin


def _fibre_dynamics(built: BuiltScene, eq, notes: _Notes):
    """Fibre ropes: the mean position comes from the working curve (statics); the WF/LF
    stiffness and line tensions from the lines linearised about it with the dynamic stiffness at
    the mean tensions (:meth:`floatmoor.mooring.MooringSystem.linearised_fibre`). Returns the
    equilibrium (its mooring stiffness replaced) and the mooring for the line statistics."""
    moor = built.mooring
    if not moor.has_fibre:
        return eq, moor
    lin = moor.linearised_fibre(eq.pose)
    k = lin.stiffness(eq.pose)
    notes.append("fibre ropes: mean position on the working curve, dynamics with the "
                 "dynamic stiffness at the mean tension")
    return replace(eq, mooring_stiffness=k,
                   total_stiffness=eq.total_stiffness - eq.mooring_stiffness + k), lin


def _linear_model(built: BuiltScene, opt: FDOptions, grid: _WaveGrid, loads: _MeanLoads, eq,
                  C_drift, viscous, notes: _Notes):
    """The linearised system about the mean position (WF and LF ingredients, eq. 2.34-2.38).

    Returns the :class:`FDModel` and a dict of FDResult fields (force spectra, LF damping
    parts, the drift method and the source of A(0))."""
    sc, vessel = built.scene, built.vessel
    db, w, w_db, S, beta, waves = vessel.database, grid.w, grid.w_db, grid.S, grid.beta, grid.waves
    yaw = float(eq.pose[5])
    T6 = rot6(yaw)
    K = vessel.total_restoring + eq.mooring_stiffness

    # -- wave frequency ------------------------------------------------------------------------
    A_w = interp0(w, w_db, np.asarray(db["added_mass"].values, float))
    B_w = interp0(w, w_db, np.asarray(db["radiation_damping"].values, float))
    if waves is not None:
        X = interpolate_heading(db, "excitation_force", beta - yaw)  # (n_db, 6) complex
        X = interp0(w, w_db, X) @ T6.T
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

    # -- low frequency -------------------------------------------------------------------------
    mu = np.linspace(0.0, 2.0 * math.pi / opt.lf_cutoff_period, opt.n_lf)
    has_qtf = "difference_frequency_qtf" in db
    drift_method = opt.drift
    if loads.correction:
        refuse_qtf_with_correction(viscous, drift_method, file=sc.file,
                                   key="frequency_domain.drift")
    if drift_method == "auto":
        drift_method = "qtf" if has_qtf and not loads.correction else "newman"
        if has_qtf and loads.correction:
            notes.append("the correction formula (eq. 6.6) corrects the mean drift "
                         "coefficients: slow drift by Newman's approximation, not the QTF")
    if drift_method == "qtf" and not has_qtf:
        raise SceneError(sc.file, "frequency_domain.drift", "newman or auto (the database has no "
                         "difference_frequency_qtf)", "qtf")
    if waves is None:
        S_drift = np.zeros((mu.size, 6, 6))
    elif drift_method == "qtf":
        S_drift = qtf_drift_spectrum(w, S, qtf_function(db, beta - yaw, T6), mu)
    else:
        S_drift = newman_drift_spectrum(w, S, C_drift, mu)
    wind, cur, U_w, U_c = loads.wind, loads.cur, loads.U_w, loads.U_c
    S_gust = np.zeros((mu.size, 6, 6))
    B_wind = np.zeros((6, 6))
    if U_w > 0:
        C_wi = T6 @ loads.wind_tab.at(wind.heading - yaw)
        s_u = wind_spectrum(wind, mu / (2.0 * math.pi)) / (2.0 * math.pi) if wind.spectrum != \
            "constant" else np.zeros_like(mu)
        s_u = np.asarray(s_u, float)
        S_gust = gust_force_spectrum(2.0 * U_w * C_wi, s_u)
        B_wind = relative_flow_damping(loads.wind_tab, U_w, wind.heading, yaw)
    B_cur = relative_flow_damping(loads.cur_tab, U_c, cur.heading, yaw) if U_c > 0 \
        else np.zeros((6, 6))
    B_drift = np.zeros((6, 6))
    if opt.wave_drift_damping and waves is not None:
        e = np.array([math.cos(beta), math.sin(beta)])
        B_drift = aranha_drift_damping(w, S, C_drift[:, :2] @ e, sc.site.gravity, beta)
    # the vessel's linear damping, raised in surge/sway by forces: viscous_drift: extra_damping
    # with the correction formula (Wang (2016) section 6.6; as the time domain)
    D_lin = viscous_linear_damping(viscous, np.asarray(vessel.linear_damping, float))
    model = FDModel(omega=w, wave_spectrum=S, mass=M, added_mass=A_w, radiation_damping=B_w,
                    excitation=X, stiffness=K, linear_damping=T6 @ D_lin @ T6.T,
                    quadratic_damping=vessel.quadratic_damping, lf_added_mass=A0,
                    lf_extra_damping=B_wind + B_cur + B_drift, mu=mu,
                    lf_force_spectrum=S_drift + S_gust)
    return model, {"lf_drift_force_spectrum": S_drift, "lf_wind_force_spectrum": S_gust,
                   "lf_damping_wind": B_wind, "lf_damping_current": B_cur,
                   "lf_damping_wave_drift": B_drift, "drift_method": drift_method,
                   "lf_added_mass_source": a0_source}


def _line_damping(built: BuiltScene, mean, model, sol, notes: _Notes):
    """``line_damping: fe``: the mooring lines' LF impedance from their FE models, iterated
    with the response (:func:`~floatmoor.analyses.fd_line_damping.iterate_line_damping`).
    Returns the model and solution with it, the FDResult fields and the
    :class:`~floatmoor.analyses.fd_line_damping.LineDampingResult`."""
    model, sol, res = iterate_line_damping(built, mean, model, sol)
    zeta = damping_ratio(res.damping, model.stiffness, sol.lf_mass, 0)
    notes.append(f"line_damping: fe: mooring-line LF damping {res.damping[0, 0] / 1e3:.0f} kN s/m "
                 f"in surge ({zeta:.1%} of critical) and dynamic stiffness "
                 f"{res.stiffness[0, 0] / 1e3:+.1f} kN/m at the LF surge natural frequency "
                 f"{res.omega:.4f} rad/s; {res.iterations} iterations with the response")
    return model, sol, {"lf_damping_mooring": res.damping,
                        "lf_stiffness_mooring_dynamic": res.stiffness,
                        "lf_mooring_frequency": res.omega,
                        "fairlead_damping": res.fairlead_damping,
                        "line_damping_iterations": res.iterations}, res


def _dynamic_lf_tension(res, lines: dict, sol, model, duration: float) -> dict:
    """``line_damping: fe``: the LF tension std and Tz of every line from the quasi-static
    gradient plus the FE line's dynamic increment
    (:func:`~floatmoor.analyses.fd_line_damping.lf_tension_spectra`), and the tension columns
    that depend on them; the quasi-static LF std beside it."""
    failed = np.asarray(lines["line_failed"], bool)
    S = lf_tension_spectra(res, np.nan_to_num(lines["tension_gradient"]), sol, model.mu)
    std, tz = response_std_tz(model.mu, S)
    cols = tension_columns(lines["tension_static"], std, tz, lines["tension_std_wf"],
                           lines["tension_tz_wf"], lines["mbs"], duration)

    def nan_failed(x):
        return np.where(failed, np.nan, x)

    return {"tension_std_lf": nan_failed(std), "tension_tz_lf": nan_failed(tz),
            "tension_max_lf": nan_failed(cols["max_lf"]),
            "tension_wf_base": nan_failed(cols["wf_base"]),
            "tension_max_total": nan_failed(cols["max_total"]),
            "tension_branch": cols["branch"],
            "safety_factor": nan_failed(cols["safety_factor"]),
            "tension_std_lf_quasi_static": np.asarray(lines["tension_std_lf"], float)}


def _lf_natural_periods(K, lf_mass, opt: FDOptions, notes: _Notes) -> np.ndarray:
    """Undamped LF natural periods (surge/sway/yaw, heave-roll-pitch condensed), s; a warning
    when one is shorter than the LF cut-off period."""
    hz = [0, 1, 5]
    Kc = K[np.ix_(hz, hz)] - K[np.ix_(hz, [2, 3, 4])] @ np.linalg.solve(
        K[np.ix_([2, 3, 4], [2, 3, 4])], K[np.ix_([2, 3, 4], hz)])
    ev = np.linalg.eigvals(np.linalg.solve(lf_mass[np.ix_(hz, hz)], Kc))
    lf_periods = 2.0 * math.pi / np.sqrt(np.sort(np.abs(ev.real)))[::-1]
    if np.min(lf_periods) < opt.lf_cutoff_period:
        notes.warn(f"an LF natural period ({np.min(lf_periods):.1f} s) is shorter than the LF "
                   f"cut-off period {opt.lf_cutoff_period:g} s: its resonance lies outside the LF "
                   "band")
    return lf_periods


def _motion_statistics(mean, sol, model: FDModel, duration: float) -> dict:
    """Std, Tz, significant values and Rayleigh maxima per DOF, combined by eq. 2.49."""
    wf_std, wf_tz = response_std_tz(model.omega, sol.wf_spectrum)
    lf_std, lf_tz = response_std_tz(model.mu, sol.lf_spectrum)
    wf_max, wf_n = rayleigh_maxima(wf_std, wf_tz, duration)
    lf_max, lf_n = rayleigh_maxima(lf_std, lf_tz, duration)
    wf_sig, lf_sig = 2.0 * wf_std, 2.0 * lf_std
    max_tot, min_tot, branch = combine_maxima(mean, lf_sig, lf_max, wf_sig, wf_max)
    return {"wf_std": wf_std, "wf_tz": wf_tz, "wf_n_cycles": wf_n, "wf_sig": wf_sig,
            "wf_max": wf_max, "lf_std": lf_std, "lf_tz": lf_tz, "lf_n_cycles": lf_n,
            "lf_sig": lf_sig, "lf_max": lf_max, "max_total": max_tot, "min_total": min_tot,
            "governing_branch": branch}


def _line_statistics(mooring, mean, sol, model: FDModel, duration: float,
                     tension_offset=None, gradient_offset=None) -> dict:
    """Fairlead motion along each line and the quasi-static tension columns (Wang (2016)
    section 2.3.1, figure 5.9); NaN for failed lines.  ``tension_offset`` (n_lines,): the
    lines' static current drag increment (``line_current_drag``), added to the static tension
    and to the catenary tension at the most likely pose; ``gradient_offset`` (n_lines, 6): its
    gradient with the pose, added to the catenary's tension gradients."""
    w, mu, S = model.omega, model.mu, model.wave_spectrum
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
    if tension_offset is not None:
        T_mean = T_mean + np.nan_to_num(tension_offset)
    steps = np.array([0.01, 0.01, 0.01, 1e-5, 1e-5, 1e-5])
    grad = np.zeros((len(names), 6))
    for k in range(6):
        dp = np.zeros(6)
        dp[k] = steps[k]
        tp = mooring.tensions(mean + dp)["fairlead_tension"].values
        tm = mooring.tensions(mean - dp)["fairlead_tension"].values
        grad[:, k] = (tp - tm) / (2 * steps[k])
    mooring.tensions(mean)  # leave the warm starts at the mean position
    if gradient_offset is not None:
        grad = grad + np.nan_to_num(gradient_offset)
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
    mbs = np.asarray(mooring.mbs, float)
    cols = tension_columns(T_mean, t_lf_std, t_lf_tz, t_wf_std, t_wf_tz, mbs, duration)
    t_lf_max, t_wf_max, t_branch = cols["max_lf"], cols["max_wf"], cols["branch"]
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
    if tension_offset is not None:
        t_cat = t_cat + np.nan_to_num(tension_offset)

    def nan_failed(x):
        return np.where(active, x, np.nan)

    return {"line_failed": ~active, "mbs": mbs, "tension_gradient": grad,
            "tangent_stiffness": nan_failed(tangent), "fairlead_motion_wf_spectrum": fm_wf,
            "fairlead_motion_lf_spectrum": fm_lf, "fairlead_motion_wf_std": fm_wf_std,
            "fairlead_motion_wf_tz": fm_wf_tz, "fairlead_motion_lf_std": fm_lf_std,
            "fairlead_motion_lf_tz": fm_lf_tz, "tension_static": nan_failed(T_mean),
            "tension_std_lf": nan_failed(t_lf_std), "tension_tz_lf": nan_failed(t_lf_tz),
            "tension_max_lf": nan_failed(t_lf_max), "tension_wf_base": nan_failed(cols["wf_base"]),
            "tension_std_wf": nan_failed(t_wf_std), "tension_tz_wf": nan_failed(t_wf_tz),
            "tension_max_wf": nan_failed(t_wf_max),
            "tension_max_total": nan_failed(cols["max_total"]), "tension_branch": t_branch,
            "tension_max_total_catenary": nan_failed(t_cat),
            "safety_factor": nan_failed(cols["safety_factor"])}

"""Frequency-domain analysis of a scene, MIMOSA-style (user API).

>>> import floatmoor
>>> ds = floatmoor.frequency_domain("scenes/floatel_100yr.yaml")
>>> print(floatmoor.format_fd_table(ds))

:func:`frequency_domain_result` does the computation and returns an
:class:`~floatmoor.analyses.fd_result.FDResult` (numpy arrays);
:func:`frequency_domain` turns it into the Dataset (:mod:`floatmoor.analyses.fd_dataset`, one
table of variables with units).

The models are the time domain's: the scene's force models (:func:`floatmoor.forces.
select_models`, the ``forces:`` section acting in both domains) each give their
:class:`~floatmoor.forces.base.FDTerms` (``ForceModel.frequency_domain``) at the body heading;
this module sums them into the statics of the mean position and the linear :class:`FDModel`.
The rules that combine models (viscous drift, double counting of current) come from
:func:`floatmoor.io.build.model_inputs` at each heading, as in the time domain.  The options
``drift`` and ``wave_drift_damping`` of ``frequency_domain:`` may choose otherwise for the
frequency domain alone (a note says so).  A sea of several wave systems or a spread sea is
carried direction by direction (:func:`floatmoor.metocean.spectra.sea_directions`): the
directions' first-order responses add, the slow drift couples them (Newman's approximation).

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
   vessel linear damping, quadratic damping linearised stochastically (iterated; every entry of
   the matrix), wind and current damping -dF/dv of F = C(theta_rel) |U - v|^2 at the mean
   velocities, Aranha's wave drift damping with ``forces: wave_drift_damping``; with ``line_damping: fe`` (option, default ``none``) the
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
   ``model: slender_elements`` (Morison strips in the time loop): the FD carries the strips'
   current load and its LF damping (the model's ``frequency_domain``; the hull current
   coefficients zeroed where the strips carry the current, as in the time domain), not their
   viscous wave drift: a :class:`FloatmoorWarning` says so.  Attribute ``viscous_drift_model``.
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
from ..forces import FDContext, model_class, select_models
from ..forces.environment import Wind
from ..forces.radiation import infinite_frequency_added_mass
from ..forces.slender import refuse_qtf_with_correction
from ..forces.spectral import wave_frequency_grid
from ..io.build import BuiltScene, build
from ..io.scene import Scene
from ..metocean.config import WaveSpec, total_hs, wave_systems
from ..metocean.spectra import sea_directions
from ..mooring.fe.current_statics import LineCurrentStatics
from ..solvers.frequency_domain import (
    FDModel,
    FDOptions,
    response_std_tz,
    solve_frequency_domain,
    wf_directions,
)
from ..solvers.statics import solve_equilibrium
from .fd_dataset import to_dataset
from .fd_line_damping import damping_ratio, iterate_line_damping, lf_tension_spectra
from .fd_line_dynamics import dynamic_line_columns
from .fd_loads import rot6
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
                            options: FDOptions | None = None, models: list[str] | None = None,
                            **overrides) -> FDResult:
    """The computation of :func:`frequency_domain` (same arguments), as an :class:`FDResult`
    of numpy arrays (no xarray).  ``models`` (advanced): force-model names instead of the
    scene's (:func:`floatmoor.forces.select_models`), as ``simulate(..., models=...)``."""
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
    forces = _forces_options(sc, opt, notes)
    names = select_models(built, forces) if models is None else list(models)
    if "mooring" not in names:
        raise SceneError(sc.file, "forces.exclude", "the mooring model in the frequency domain "
                         "(it gives the mean position, the stiffness and the tensions)",
                         "mooring excluded")
    sea = _Sea.of(built.vessel.database, sc.environment.waves, opt, notes)
    if sea.waves is not None and not any(n.startswith("drift_") for n in names):
        notes.append("no wave drift force (the database has no mean_drift_force, or "
                     "forces: drift: none / exclude)")
    system = _ModelSet(built, forces, names, sea, opt, notes)
    drag_lin = None
    if opt.line_current_drag:
        eq, mean_parts, drag_lin = _mean_position_line_current(built, system, opt, notes)
    else:
        eq, mean_parts = _mean_position(built, system, opt)
    eq, moor = _fibre_dynamics(built, eq, notes)
    if drag_lin is not None:
        # the lines' current drag changes with the pose: its stiffness joins the mooring's
        eq = replace(eq, mooring_stiffness=eq.mooring_stiffness + drag_lin[0],
                     total_stiffness=eq.total_stiffness + drag_lin[0])
    terms = system.terms(float(eq.pose[5]), pose=eq.pose, linear=True)
    model, lf_parts = _linear_model(built, sea, system.mu, terms, eq)
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
    viscous = getattr(getattr(forces, "viscous_drift", None), "model", "none")
    wind_speed = terms["wind"].info["mean_speed"] if "wind" in terms else 0.0
    return FDResult(
        scene=str(sc.file) if sc.file else sc.name, scene_name=sc.name, options=opt,
        model=model, solution=sol, line_names=tuple(built.mooring.names), **mean_parts,
        statics_iterations=eq.iterations, **lf_parts, lf_natural_period=lf_periods, **motions,
        **lines, has_waves=sea.waves is not None, viscous_drift_model=viscous,
        wave_heading=sea.heading, wind_speed_at_coefficient_height=wind_speed,
        wind_coefficient_height=(Wind.reference_height(built) if "wind" in terms
                                 else float("nan")),
        current_speed_surface=terms["current"].info["mean_speed"] if "current" in terms else 0.0,
        wave_spectrum_fraction_covered=sea.covered, linearisation_iterations=sol.iterations,
        models=tuple(terms), **damping_parts, notes=tuple(notes),
        run_time_s=time.perf_counter() - t_start)


# -- the stages of the computation -------------------------------------------------------------
class _Notes(list):
    """The remarks of a run (attribute ``notes``); :meth:`warn` also shows them as warnings,
    attributed to the first caller outside this package (the user's line)."""

    def warn(self, msg: str) -> None:
        here = os.path.dirname(os.path.dirname(__file__)) + os.sep
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


def _forces_options(sc: Scene, opt: FDOptions, notes: _Notes):
    """The scene's ``forces`` settings with the frequency domain's own choices of the drift
    model and the wave drift damping (``frequency_domain: drift`` other than ``auto``,
    ``wave_drift_damping`` true or false), which then differ from the scene's time domain."""
    forces = getattr(sc, "forces", None)
    changes = {}
    if opt.drift != "auto":
        refuse_qtf_with_correction(getattr(forces, "viscous_drift", None), opt.drift,
                                   file=sc.file, key="frequency_domain.drift")
        changes["drift"] = opt.drift
    scene_wdd = bool(getattr(forces, "wave_drift_damping", False))
    if opt.wave_drift_damping is not None and opt.wave_drift_damping != scene_wdd:
        changes["wave_drift_damping"] = opt.wave_drift_damping
        notes.append(f"wave drift damping {'on' if opt.wave_drift_damping else 'off'} in the "
                     f"frequency domain alone (frequency_domain: wave_drift_damping); the "
                     f"scene's time domain has it {'on' if scene_wdd else 'off'} "
                     "(forces: wave_drift_damping)")
    if not changes:
        return forces
    if forces is None:
        from ..io.forces_section import ForcesSpec
        forces = ForcesSpec(file=sc.file)
    return replace(forces, **changes)


@dataclass(frozen=True)
class _Sea:
    """The WF grid ``w`` over the database's range, the sea's energy by direction on it
    (``directions`` rad, ``spectra`` (n_dir, n)), their sum ``S``, the fraction of m0 the grid
    covers and the heading of the dominant system ``heading`` (rad)."""

    waves: object
    w: np.ndarray
    directions: np.ndarray
    spectra: np.ndarray
    S: np.ndarray
    covered: float
    heading: float

    @classmethod
    def of(cls, db, waves, opt: FDOptions, notes: _Notes) -> _Sea:
        w = wave_frequency_grid(db, opt.d_omega)
        directions, spectra = sea_directions(waves, w)
        if waves is None:
            return cls(None, w, directions, spectra, np.zeros_like(w), 1.0, 0.0)
        S = spectra[0] if spectra.shape[0] == 1 else spectra.sum(axis=0)
        hs = total_hs(waves)
        m0_true = (hs / 4.0) ** 2
        covered = float(np.trapezoid(S, w) / m0_true)
        if covered < 0.99:
            systems = wave_systems(waves)
            what = (f"Hs {hs:g} m, Tp {systems[0].tp:g} s" if len(systems) == 1 else
                    f"{len(systems)} wave systems, Hs {hs:.3g} m")
            notes.warn(f"the database frequencies {w[0]:.3g}-{w[-1]:.3g} rad/s hold only "
                       f"{100 * covered:.1f} % of the wave spectrum's m0 ({what}): WF "
                       "responses and drift are underestimated")
        dominant = waves if isinstance(waves, WaveSpec) else waves.dominant
        return cls(waves, w, directions, spectra, S, covered, float(dominant.heading))


class _ModelSet:
    """The scene's force models for the frequency domain: :meth:`terms` gives every model's
    :class:`~floatmoor.forces.base.FDTerms` at a body heading (the scene's rules that combine
    models applied at that heading, :func:`floatmoor.io.build.model_inputs`)."""

    def __init__(self, built: BuiltScene, forces, names, sea: _Sea, opt: FDOptions,
                 notes: _Notes):
        self.built, self.forces, self.names, self.sea, self.opt, self.notes = \
            built, forces, list(names), sea, opt, notes
        self.models = {n: model_class(n, key="forces")() for n in self.names}
        self.mu = np.linspace(0.0, 2.0 * math.pi / opt.lf_cutoff_period, opt.n_lf)

    def terms(self, yaw: float, *, pose=None, linear: bool = False) -> dict:
        inputs = self.built.model_inputs(self.forces, self.names, yaw=yaw)
        fd = FDContext(built=self.built, options=self.forces, inputs=inputs, omega=self.sea.w,
                       mu=self.mu, directions=self.sea.directions, spectra=self.sea.spectra,
                       yaw=float(yaw), pose=pose, linear=linear, notes=self.notes,
                       fd_options=self.opt)
        return {n: m.frequency_domain(fd) for n, m in self.models.items()}


def _sum(arrays, shape):
    """Sum of ``arrays`` in their order (the first array itself for one), zeros for none."""
    arrays = [a for a in arrays if a is not None]
    if not arrays:
        return np.zeros(shape)
    out = arrays[0]
    for a in arrays[1:]:
        out = out + a
    return out


def _static_loads(terms: dict):
    """(restoring matrix, external force) of the statics from the models' terms: the
    restoring terms' matrices and constants, and the mean forces of the others added in the
    models' order (the arithmetic of the time domain's static start)."""
    restoring = _sum([t.restoring for t in terms.values()], (6, 6))
    const = _sum([t.const_force for t in terms.values()], (6,))
    mean_env = np.zeros(6)
    for t in terms.values():
        if t.mean_force is not None:
            mean_env += t.mean_force
    return restoring, const + mean_env


def _mean_fields(terms: dict) -> dict:
    """The FDResult fields of the mean loads: wind, current and drift, and every model's."""
    def mean(names):
        for n in names:
            if n in terms and terms[n].mean_force is not None:
                return np.asarray(terms[n].mean_force, float)
        return np.zeros(6)
    return {"mean_force_wind": mean(("wind",)), "mean_force_current": mean(("current",)),
            "mean_force_drift": mean(("drift_newman", "drift_qtf")),
            "mean_force_model": np.array([np.zeros(6) if t.mean_force is None
                                          else np.asarray(t.mean_force, float)
                                          for t in terms.values()]).reshape(-1, 6)}


def _mean_position(built: BuiltScene, system: _ModelSet, opt: FDOptions):
    """Static equilibrium under the mean loads (eq. 2.39), the yaw iterated for the relative
    headings.  Returns the equilibrium and a dict of FDResult fields."""
    yaw = 0.0
    x0 = None
    for _ in range(opt.heading_iterations):
        terms = system.terms(yaw)
        C, f_ext = _static_loads(terms)
        eq = solve_equilibrium(built.mooring, hydrostatic_stiffness=C, external_force=f_ext,
                               x0=x0)
        x0 = eq.pose
        if abs(eq.pose[5] - yaw) < 1e-6:
            break
        yaw = float(eq.pose[5])
    return eq, {"mean": eq.pose.copy(), **_mean_fields(terms)}


def _mean_position_line_current(built: BuiltScene, system: _ModelSet, opt: FDOptions,
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
        return (*_mean_position(built, system, opt), None)
    drag = None
    dF = np.zeros(6)
    x0 = None
    yaw = 0.0
    it = 0
    while it < LINE_CURRENT_MAX_ITER:
        it += 1
        terms = system.terms(yaw)
        C, f_ext = _static_loads(terms)
        eq = solve_equilibrium(built.mooring, hydrostatic_stiffness=C,
                               external_force=f_ext + dF, x0=x0)
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
    return eq, {"mean": eq.pose.copy(), **_mean_fields(terms),
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


def _linear_model(built: BuiltScene, sea: _Sea, mu, terms: dict, eq):
    """The linearised system about the mean position (WF and LF ingredients, eq. 2.34-2.38)
    assembled from the models' terms at the mean heading.

    Returns the :class:`FDModel` and a dict of FDResult fields (force spectra, LF damping
    parts, the drift method and the source of A(0))."""
    vessel = built.vessel
    w = sea.w
    yaw = float(eq.pose[5])
    T6 = rot6(yaw)
    M = T6 @ vessel.mass_matrix @ T6.T
    rad = [t for t in terms.values() if t.added_mass is not None]
    if rad:
        A_w, B_w, A0 = rad[0].added_mass, rad[0].radiation_damping, rad[0].lf_added_mass
        a0_source = rad[0].info.get("lf_added_mass_source", "radiation model")
    else:  # no radiation memory (forces: retardation: false): A_inf, as the time domain
        A_inf = T6 @ infinite_frequency_added_mass(vessel.database) @ T6.T
        A_w, B_w, A0 = np.broadcast_to(A_inf, (w.size, 6, 6)), np.zeros((w.size, 6, 6)), A_inf
        a0_source = ("infinite_frequency_added_mass (no radiation model: forces: "
                     "retardation: false)")
    restoring, _ = _static_loads(terms)
    K = _sum([restoring, eq.mooring_stiffness] + [t.stiffness for t in terms.values()],
             (6, 6))
    n_dir = sea.directions.size
    X = _sum([t.wf_excitation for t in terms.values()], (max(n_dir, 1), w.size, 6))
    X = np.asarray(X, complex)
    multi = n_dir > 1
    S_drift = _sum([terms[n].lf_force_spectrum for n in ("drift_newman", "drift_qtf")
                    if n in terms], (mu.size, 6, 6))
    S_gust = terms["wind"].lf_force_spectrum if "wind" in terms else np.zeros((mu.size, 6, 6))
    drift = [n for n in ("drift_newman", "drift_qtf") if n in terms]
    lf_parts = {"lf_drift_force_spectrum": S_drift, "lf_wind_force_spectrum": S_gust,
                "lf_damping_wind": _lf_damping(terms, "wind"),
                "lf_damping_current": _lf_damping(terms, "current"),
                "lf_damping_wave_drift": _lf_damping(terms, "wave_drift_damping"),
                "drift_method": terms[drift[0]].info["drift_method"] if drift else "none",
                "lf_added_mass_source": a0_source}
    model = FDModel(omega=w, wave_spectrum=sea.S, mass=M, added_mass=A_w, radiation_damping=B_w,
                    excitation=X if multi else X[0], stiffness=K,
                    linear_damping=_sum([t.damping for t in terms.values()], (6, 6)),
                    quadratic_damping=_sum([t.quadratic_damping for t in terms.values()],
                                           (6, 6)),
                    lf_added_mass=A0,
                    lf_extra_damping=_sum([t.lf_damping for t in terms.values()], (6, 6)),
                    mu=mu, lf_force_spectrum=_sum([t.lf_force_spectrum for t in terms.values()],
                                                  (mu.size, 6, 6)),
                    direction_spectra=sea.spectra if multi else None,
                    directions=sea.directions, yaw=yaw)
    return model, lf_parts


def _lf_damping(terms: dict, name: str) -> np.ndarray:
    t = terms.get(name)
    return np.zeros((6, 6)) if t is None or t.lf_damping is None else t.lf_damping


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
    w, mu = model.omega, model.mu
    directions = wf_directions(model, sol)
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
        out = None
        for rao, S in directions:  # the directions' responses add
            h = rao @ vecs.T  # (n_w, n_lines)
            p = np.abs(h) ** 2 * S[:, None]
            out = p if out is None else out + p
        return out

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

"""User API of the time domain: ``floatmoor.simulate(scene, seed=...)`` -> xarray Dataset."""

from __future__ import annotations

import math
import time as _time
import warnings

import numpy as np
import xarray as xr

from ..core.errors import FloatmoorWarning, SceneError
from .td_dataset import TDRun, scene_text, to_dataset

__all__ = ["simulate", "result_dataset", "scene_text", "check_statistics_window",
           "YAW_WARNING_DEG"]

YAW_WARNING_DEG = 15.0
"""Yaw (deg) away from the heading of the wave forces (body yaw 0, the start heading) beyond
which a run warns that the wave forces, evaluated at that heading, no longer follow the body."""


def check_statistics_window(file, duration: float, transient: float, *,
                            key: str = "analysis.duration") -> None:
    """SceneError unless ``duration`` (s) is longer than ``transient`` (s).

    The statistics of a run (and the table of ``floatmoor run``) use the window after the
    transient; a run that ends inside the transient has none.  ``key`` names the value that was
    given (``analysis.duration``, ``--duration``, the ``duration`` argument)."""
    if not duration > transient:
        raise SceneError(file, key, f"a duration longer than the transient ({transient:g} s, "
                         "analysis.transient): the statistics window after the transient "
                         "would be empty", duration,
                         hint=f"give a duration > {transient:g} s or a shorter transient")


def simulate(scene, *, seed: int | None = None, duration: float | None = None,
             dt: float | None = None, ramp: float | None = None, transient: float | None = None,
             forces=None, record_forces: bool | None = None, models=None, waves=None,
             start_pose=None, start_velocity=None, fibre_stiffness=None,
             solver=None, progress=None) -> xr.Dataset:
    """Simulate one realisation of a scene in the time domain.

    Parameters
    ----------
    scene : Scene, BuiltScene, or path of a scene file
    seed : int, optional
        Realisation seed (default: the first of the scene's ``analysis.seeds``).  The waves use
        the seed itself; the wind gust an independent stream derived from it.
    duration, dt, ramp, transient : float, optional
        Override ``analysis`` (s).  ``transient`` only marks the start of the statistics window
        (attribute ``transient``); the series keep it.  A duration not longer than the
        transient is allowed here (short checks) with a FloatmoorWarning;
        :func:`floatmoor.run_seeds` and ``floatmoor run`` refuse it (SceneError).
    forces : :class:`floatmoor.io.forces_section.ForcesSpec`, optional
        Force options (default: the scene's ``forces`` section, if any).
    record_forces : bool, optional
        Store ``force(time, model, dof)`` (default from ``forces.record_forces``).
    models : list of model names, optional (advanced: replaces the scene's choice).
    waves : :class:`floatmoor.forces.waves.WaveComponents`, optional (advanced: e.g. a regular
        wave instead of the scene's sea state).
    start_pose, start_velocity : (6,), optional (advanced: free decay; default: static
        equilibrium at rest).
    fibre_stiffness : ``"lower"`` or ``"upper"``, optional
        Fibre-rope stiffness bound instead of the scene's ``analysis.fibre_stiffness``
        (:mod:`floatmoor.io.analysis`; ``both`` runs ``upper`` here). Attribute
        ``fibre_stiffness`` of the result when the mooring has fibre ropes.
    solver : :class:`floatmoor.io.solver_section.SolverSpec`, optional
        Options of the time loop (default: the scene's ``solver`` section, if any, else the
        exact path); attribute ``solver``.
    progress : callable, optional
        Called with the simulated time and the end time (s) every 5 % of a storm with
        finite-element lines (their storms take tens of seconds; quasi-static storms do not
        call it).

    Notes
    -----
    The first-order wave and drift forces are precomputed before the loop at the mean position
    (the origin, where the database's phase reference lies) and the start heading (body yaw 0):
    they do not follow the body's yaw or offset (attribute ``wave_force_frame``).  A run whose
    yaw moves more than :data:`YAW_WARNING_DEG` (15 deg) from that heading warns with a
    :class:`FloatmoorWarning` (attribute ``max_yaw_excursion_deg``).  Wind and current act on
    the velocity of the flow relative to the low-frequency body velocity (Wang (2016) eq. 2.24,
    2.26): the linear wave-frequency velocity is removed from the body velocity (scene option
    ``forces: {relative_velocity: low_frequency | total}``, attribute ``relative_velocity``).

    Returns
    -------
    xarray.Dataset
        ``motion(time, dof)`` (m, rad) of the body reference point, ``velocity(time, dof)``,
        ``line_tension(time, line)`` at the fairlead and ``anchor_tension(time, line)`` (N),
        ``wave_elevation(time)`` at the origin (m, when the scene has waves),
        ``force(time, model, dof)`` (N, N m; when recorded).  Attributes: ``scene`` (YAML text),
        ``scene_file``, ``scene_name``, ``seed``, ``models`` (active force models), ``dt``,
        ``duration``, ``ramp``, ``transient``, versions, ``run_time_s`` (time loop),
        ``setup_time_s``, ``created``, ``relative_velocity`` and ``relative_velocity_note``,
        ``wave_force_frame``, ``max_yaw_excursion_deg`` (with wave forces).

    Raises
    ------
    SceneError
        Bad input (names file and key).
    NumericalError
        NaN, exploding state, line far beyond MBS, failed catenary, or dt beyond the stability
        limit (names the time, DOF or line, and a likely remedy).
    """
    from ..io.build import BuiltScene, build, with_fibre_bound
    from ..io.scene import Scene, load_scene
    from ..solvers.time_domain import assemble, integrate

    t_all = _time.perf_counter()
    if isinstance(scene, BuiltScene):
        built = scene
    else:
        if not isinstance(scene, Scene):
            scene = load_scene(scene)
        built = build(scene)
        from ..io.plausibility import check_built
        check_built(built)
    sc = built.scene
    an = sc.analysis
    built = with_fibre_bound(built, fibre_stiffness)
    seed = an.seeds[0] if seed is None else seed
    if isinstance(seed, bool) or not isinstance(seed, (int, np.integer)) or seed < 0:
        raise SceneError(sc.file, "seed", "an integer seed >= 0", seed)
    duration = an.duration if duration is None else float(duration)
    dt = an.dt if dt is None else float(dt)
    ramp = an.ramp if ramp is None else float(ramp)
    transient = an.transient if transient is None else float(transient)
    if not (0.0 < dt < duration):
        raise SceneError(sc.file, "analysis.dt", f"0 < dt < duration ({duration:g} s)", dt)
    from ..io.analysis import check_time_steps
    check_time_steps(sc.file, duration, dt, key="analysis.dt")
    if not duration > transient:  # legitimate for short checks; refused by run_seeds / run
        warnings.warn(f"the duration {duration:g} s is not longer than the transient "
                      f"{transient:g} s: the run has no statistics window (floatmoor run "
                      "refuses this)", FloatmoorWarning, stacklevel=2)
    if forces is None:
        forces = getattr(sc, "forces", None)
    if record_forces is None:
        record_forces = bool(getattr(forces, "record_forces", False))
    if solver is None:
        solver = getattr(sc, "solver", None)
    a = assemble(built, seed=int(seed), dt=dt, duration=duration, ramp=ramp, options=forces,
                 models=models, waves=waves, start_pose=start_pose, solver=solver)
    r = integrate(a, record_forces=record_forces, built=built, v0=start_velocity,
                  progress=progress)
    setup = _time.perf_counter() - t_all - r.wall_time
    ds = result_dataset(r, built, seed=int(seed), dt=dt, duration=a.n_steps * dt, ramp=ramp,
                        transient=transient)
    ds.attrs["run_time_s"] = float(r.wall_time)
    ds.attrs["setup_time_s"] = float(setup)
    om = float(r.info.get("omega_max", 0.0))
    ds.attrs["stiffest_mode_period_s"] = float(2 * np.pi / om) if om > 0 else float("inf")
    ds.attrs["real_time_factor"] = float(a.n_steps * dt / max(r.wall_time, 1e-12))
    if solver is not None and not solver.is_default:
        ds.attrs["solver"] = solver.describe()
        rad = a.models.get("radiation")
        if rad is not None and rad.state_space is not None:
            ds.attrs["memory_fit_error"] = float(np.max(rad.fit_error, initial=0.0))
    wave_models = [m for m in r.models if m == "wave1" or m.startswith("drift")]
    if wave_models and r.motion.size:
        yaw0 = float(r.info.get("wave_heading_yaw", 0.0))
        excursion = float(np.degrees(np.max(np.abs(r.motion[:, 5] - yaw0))))
        ds.attrs["max_yaw_excursion_deg"] = excursion
        if excursion > YAW_WARNING_DEG:
            warnings.warn(f"the yaw reached {excursion:.1f} deg away from the heading of the "
                          f"wave forces (body yaw {math.degrees(yaw0):g} deg, seed "
                          f"{seed}); the wave forces ({', '.join(wave_models)}) are evaluated at "
                          f"the start heading and do not follow the body: beyond about "
                          f"{YAW_WARNING_DEG:g} deg that assumption is stretched",
                          FloatmoorWarning, stacklevel=2)
    if built.mooring is not None and built.mooring.has_fibre:
        ds.attrs["fibre_stiffness"] = fibre_stiffness or an.fibre_bounds[-1]
    mbs = built.mooring.mbs if built.mooring is not None else None
    if mbs is not None and r.line_tension.size:
        over = np.nonzero(r.line_tension.max(axis=0) > mbs)[0]
        for i in over:
            warnings.warn(f"line {r.line_names[i]!r}: maximum fairlead tension "
                          f"{r.line_tension[:, i].max() / 1e3:.0f} kN exceeds its MBS "
                          f"{mbs[i] / 1e3:.0f} kN (seed {seed})", FloatmoorWarning, stacklevel=2)
    return ds


def result_dataset(r, built, *, seed: int, dt: float, duration: float, ramp: float,
                   transient: float) -> xr.Dataset:
    """The :class:`~floatmoor.solvers.time_domain.TimeDomainResult` as an xarray Dataset (the
    variable table of :mod:`floatmoor.analyses.td_dataset`)."""
    return to_dataset(TDRun(r=r, built=built, seed=seed, dt=dt, duration=duration, ramp=ramp,
                            transient=transient))

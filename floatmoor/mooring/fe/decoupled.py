"""Decoupled FE analysis of the lines of a mooring system driven by a body-motion history (Wang
2016, chapter 8: the motions of a previous floater run, or a prescribed harmonic, drive dynamic
lines), with the statistics a mooring engineer compares: mean, standard deviation and maximum of
the fairlead tension FE vs quasi-static, the dynamic amplification factor

    DAF = (T_max - T_mean)_FE / (T_max - T_mean)_QS            (Wang 2016, eq. 8.1)

the maximum tension along the line and the range of the grounded length.

:func:`run_decoupled` is the engine of ``floatmoor lines`` (:mod:`floatmoor.commands.lines`).
"""

from __future__ import annotations

import time as _time

import numpy as np
import xarray as xr

from ...core.errors import ConvergenceError, NumericalError
from .from_system import spec_from_linedef
from .line import FELine
from .options import FEOptions
from .prescribed import daf, fairlead_track_from_body, quasi_static_tension, run_prescribed
from .selfcheck import line_selfcheck, selfcheck_variables, warn_broken

__all__ = ["run_decoupled", "harmonic_poses"]

_DOFS = ("surge", "sway", "heave", "roll", "pitch", "yaw")


def harmonic_poses(t, components, *, ramp: float = 0.0) -> np.ndarray:
    """Body poses (nt, 6) from harmonic components about the zero pose.

    Parameters
    ----------
    t : (nt,) s
    components : sequence of (dof, amplitude, period)
        ``dof`` index 0..5 (surge .. yaw), amplitude in m or rad, period in s; displacement
        ``amplitude * sin(2 pi t / period)``.
    ramp : float
        ``(1 - cos) / 2`` ramp over the first ``ramp`` s.
    """
    t = np.asarray(t, float)
    poses = np.zeros((t.size, 6))
    g = np.ones_like(t)
    if ramp > 0.0:
        m = t < ramp
        g[m] = 0.5 * (1.0 - np.cos(np.pi * t[m] / ramp))
    for dof, amp, period in components:
        poses[:, int(dof)] += amp * np.sin(2.0 * np.pi * t / period) * g
    return poses


def run_decoupled(system, t, poses, *, options: FEOptions | None = None, lines=None,
                  discard: float = 0.0, substeps: int | None = None,
                  reference_tension=None, progress=None, current=None,
                  line_types=None) -> xr.Dataset:
    """Drive FE models of the lines of ``system`` with the body poses ``poses`` at ``t``.

    Each line starts from its FE static equilibrium at ``poses[0]`` with zero velocity; the
    fairlead follows the track of the body (linear in between the samples); one FE body step per
    sample interval, ``substeps`` line steps in each.

    Parameters
    ----------
    system : floatmoor.mooring.MooringSystem
    t : (nt,) s, increasing, uniformly spaced
    poses : (nt, 6) m, rad
    options : FEOptions, optional
        Element length or count, seabed, friction, damping, integrator, line step (default
        :class:`FEOptions` defaults).
    lines : sequence of str, optional
        Line names (default every active line).
    discard : float
        Time from ``t[0]`` left out of the statistics (start-up transient), s.
    substeps : int, optional
        Line steps per sample interval (default ``options.substeps_for(dt)``).
    reference_tension : mapping name -> (nt,) array, optional
        Fairlead tension of the floater run (quasi-static, N), stored as ``run_tension`` to
        compare with the quasi-static tension recomputed here along the fairlead track.
    progress : callable, optional
        Called with a line of text before each line ("line k of n: NAME") and every 5 % of
        its simulated time.
    current : dict, optional
        ``current_z``, ``current_speed``, ``current_heading`` of every line (m, m/s, rad;
        :class:`FELineSpec`; default no current), as :meth:`FEMooring.from_system` takes them.
    line_types : mapping name -> LineType, optional
        Line types for the hydrodynamic coefficients of the segments (``cdn, cdt, can, cat``;
        default the ``LineType`` defaults).  :func:`floatmoor.mooring.fe.body.scene_line_inputs`
        gives both from a scene, as the coupled run uses them.

    Returns
    -------
    xarray.Dataset
        Over ``line`` and ``time``: ``fe_tension``, ``qs_tension``, ``anchor_tension``,
        ``max_tension`` (along the line), ``grounded_length``, ``touchdown_x/y``
        (and ``run_tension``); per line the statistics over the window ``fe_mean, fe_std,
        fe_max, qs_mean, qs_std, qs_max, daf, max_tension_along_line,
        max_tension_arc_length, grounded_length_min, grounded_length_max, wall_time`` and the
        self-check (``selfcheck`` ok or the broken bounds, ``selfcheck_*`` numbers:
        :mod:`.selfcheck`); all with ``units``.  A line that breaks a warning-level bound of the
        self-check raises a FloatmoorWarning.

    Raises
    ------
    NumericalError
        A line step that fails (time, line, node and a remedy), or FE statics that do not
        converge at the start pose (time ``t[0]``).
    """
    options = options or FEOptions()
    t = np.asarray(t, float)
    poses = np.asarray(poses, float)
    if t.ndim != 1 or t.size < 3 or poses.shape != (t.size, 6):
        raise ValueError("t must be (nt >= 3,) and poses (nt, 6)")
    dt = float(t[1] - t[0])
    if not np.allclose(np.diff(t), dt, rtol=1e-6, atol=1e-9):
        raise ValueError("t must be uniformly spaced")
    nsub = options.substeps_for(dt) if substeps is None else int(substeps)
    names = ([n for n, a in zip(system.names, system.active) if a] if lines is None
             else list(lines))
    window = (t - t[0]) >= discard - 1e-9
    if window.sum() < 2:
        raise ValueError(f"nothing left after discarding {discard:g} s")
    keys = ("fe", "qs", "anchor", "tmax", "lg", "xtd", "ytd")
    series = {k: [] for k in keys}
    stats = {k: [] for k in ("fe_mean", "fe_std", "fe_max", "qs_mean", "qs_std", "qs_max",
                             "daf", "tmax_line", "tmax_s", "lg_min", "lg_max", "wall",
                             "n_elements", "newton")}
    checks = []
    for il, name in enumerate(names):
        if progress is not None:
            progress(f"line {il + 1} of {len(names)}: {name}")
        w0 = _time.perf_counter()
        ld = system.lines[system.names.index(name)]
        spec = spec_from_linedef(ld, water_depth=system.water_depth, pose=poses[0],
                                 water_density=system.water_density, gravity=system.gravity,
                                 line_types=line_types, **options.spec_kw(system.water_depth),
                                 **(current or {}))
        line = FELine(spec, **options.line_kw())
        try:
            line.solve_static()
        except ConvergenceError as exc:
            raise NumericalError(f"FE statics at the start pose: {exc.what}", time=float(t[0]),
                                 where=exc.where, remedy=exc.remedy) from None
        line.start(t0=0.0, **options.start_kw())
        track = fairlead_track_from_body(t - t[0], poses, ld.fairlead)
        step_progress = None
        if progress is not None:
            def step_progress(tt, t_end, name=name, w0=w0):
                progress(f"  {name}: {100.0 * tt / t_end:3.0f} % ({tt:.0f} of {t_end:.0f} s, "
                         f"{_time.perf_counter() - w0:.0f} s)")
        try:
            ds = run_prescribed(line, track, t[-1] - t[0], dt, substeps=nsub,
                                progress=step_progress)
        except NumericalError as exc:
            raise NumericalError(exc.what, time=None if exc.time is None
                                 else float(exc.time + t[0]),
                                 where=exc.where, remedy=exc.remedy) from None
        T_fe = ds.fairlead_tension.values
        T_qs = quasi_static_tension(line, track, ds.time.values)
        series["fe"].append(T_fe)
        series["qs"].append(T_qs)
        series["anchor"].append(ds.anchor_tension.values)
        series["tmax"].append(ds.max_tension.values)
        series["lg"].append(ds.grounded_length.values)
        series["xtd"].append(ds.touchdown_x.values)
        series["ytd"].append(ds.touchdown_y.values)
        fe, qs = T_fe[window], T_qs[window]
        stats["fe_mean"].append(fe.mean())
        stats["fe_std"].append(fe.std())
        stats["fe_max"].append(fe.max())
        stats["qs_mean"].append(qs.mean())
        stats["qs_std"].append(qs.std())
        stats["qs_max"].append(qs.max())
        try:
            stats["daf"].append(daf(fe, qs))
        except ValueError:
            stats["daf"].append(np.nan)
        tm = ds.max_tension.values[window]
        k = int(np.argmax(tm))
        el = int(ds.max_tension_element.values[window][k])
        stats["tmax_line"].append(tm[k])
        stats["tmax_s"].append(0.5 * (line.s_nodes[el] + line.s_nodes[el + 1]))
        fz = line.r[-1, 2] - track.xyz[-1, 2] + track.xyz[window, 2]   # fairlead z (earth)
        speed = np.linalg.norm(np.diff(track.xyz, axis=0), axis=1) / dt
        checks.append(line_selfcheck(line, fairlead_tension=fe, max_tension=tm,
                                     fairlead_height=float(fz.max() - line.r[0, 2]),
                                     fairlead_speed=float(speed.max())))
        lg = ds.grounded_length.values[window]
        stats["lg_min"].append(lg.min())
        stats["lg_max"].append(lg.max())
        stats["wall"].append(_time.perf_counter() - w0)
        stats["n_elements"].append(line.n_nodes - 1)
        stats["newton"].append(int(line.newton_iterations))
    LT = ("line", "time")
    data = {
        "fe_tension": (LT, np.array(series["fe"]),
                       {"units": "N", "long_name": "fairlead tension, FE line"}),
        "qs_tension": (LT, np.array(series["qs"]),
                       {"units": "N", "long_name": "fairlead tension, quasi-static elastic "
                                                   "catenary along the same fairlead track"}),
        "anchor_tension": (LT, np.array(series["anchor"]),
                           {"units": "N", "long_name": "anchor tension, FE line"}),
        "max_tension": (LT, np.array(series["tmax"]),
                        {"units": "N", "long_name": "largest element tension along the FE line"}),
        "grounded_length": (LT, np.array(series["lg"]),
                            {"units": "m", "long_name": "unstretched length from the anchor to "
                                                        "the last node in seabed contact"}),
        "touchdown_x": (LT, np.array(series["xtd"]), {"units": "m",
                                                      "long_name": "touchdown node x (earth)"}),
        "touchdown_y": (LT, np.array(series["ytd"]), {"units": "m",
                                                      "long_name": "touchdown node y (earth)"}),
    }
    desc = {
        "fe_mean": ("N", "mean fairlead tension in the window, FE"),
        "fe_std": ("N", "standard deviation of the fairlead tension in the window, FE"),
        "fe_max": ("N", "maximum fairlead tension in the window, FE"),
        "qs_mean": ("N", "mean fairlead tension in the window, quasi-static"),
        "qs_std": ("N", "standard deviation of the fairlead tension in the window, "
                        "quasi-static"),
        "qs_max": ("N", "maximum fairlead tension in the window, quasi-static"),
        "daf": ("1", "dynamic amplification factor (T_max - T_mean)_FE / (T_max - T_mean)_QS "
                     "(Wang 2016, eq. 8.1)"),
        "tmax_line": ("N", "maximum element tension along the line in the window, FE"),
        "tmax_s": ("m", "unstretched arc length from the anchor of that maximum"),
        "lg_min": ("m", "smallest grounded length in the window"),
        "lg_max": ("m", "largest grounded length in the window"),
        "wall": ("s", "wall time of the line (statics and dynamics)"),
        "n_elements": ("1", "number of elements"),
        "newton": ("1", "Newton iterations of the implicit integrator"),
    }
    out_names = {"tmax_line": "max_tension_along_line", "tmax_s": "max_tension_arc_length",
                 "lg_min": "grounded_length_min", "lg_max": "grounded_length_max",
                 "wall": "wall_time", "newton": "newton_iterations"}
    for k, (unit, ln) in desc.items():
        data[out_names.get(k, k)] = ("line", np.array(stats[k]),
                                     {"units": unit, "long_name": ln})
    data.update(selfcheck_variables(checks))
    warn_broken(names, checks)
    if reference_tension is not None:
        data["run_tension"] = (LT, np.array([np.asarray(reference_tension[n], float)
                                             for n in names]),
                               {"units": "N", "long_name": "fairlead tension of the floater run "
                                                           "(quasi-static model of the run)"})
    return xr.Dataset(
        data,
        coords={"line": ("line", names, {"long_name": "mooring line"}),
                "time": ("time", t, {"units": "s", "long_name": "time of the body motion"})},
        attrs={"dt": dt, "substeps": nsub, "discard_s": float(discard),
               "statistics_window_start_s": float(t[window][0]),
               "integrator": options.integrator, "rho_inf": options.rho_inf,
               "element_length_m": options.element_length,
               "n_elements_option": (-1 if options.n_elements is None else options.n_elements
                                     if isinstance(options.n_elements, int)
                                     else list(options.n_elements)),
               "friction": "scene default (seabed_friction)" if options.friction is None
               else repr(options.friction),
               "fe_start": "static equilibrium at the first pose, zero velocity",
               "current_on_lines": "none" if not current else
               f"max {max(current['current_speed']):.3g} m/s, heading "
               f"{np.degrees(current['current_heading']):.1f} deg (direction of travel)",
               "line_types": ", ".join(sorted(line_types)) if line_types
               else "LineType defaults"})

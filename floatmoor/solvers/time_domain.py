"""Coupled 6-DOF time-domain simulation of a moored floater (quasi-static and finite-element
mooring lines).

:func:`assemble` builds the force models a scene names (and only those), the static start and
the plain arrays of the time loop; :func:`integrate` runs the numba kernel
(:mod:`floatmoor.solvers.td_kernel`: the equation of motion, the RK4 integrator, the memory
convolution, the guards) and returns a :class:`TimeDomainResult`.  The user-facing entry point
is :func:`floatmoor.simulate`.

Assumptions (documented limits)
-------------------------------
* State: the pose ``x`` (earth position of the reference point, Euler angles) and the velocity
  ``nu`` in the yaw-following frame (surge/sway velocity along the body's horizontal axes,
  heave rate, roll/pitch/yaw rates).  Large horizontal motions and any yaw: the inertia
  M + A_inf, the linear and quadratic damping and the radiation memory act on ``nu`` (they
  turn with the body); the terms of the frame turning at the yaw rate r (surge/sway
  ``-/+ r P`` and the Munk yaw moment ``u P_sway - v P_surge`` of the momentum
  P = (M + A_inf) nu) are included, so a free body conserves its earth-frame horizontal momentum
  and its energy at any yaw (tested); heave, roll and pitch keep the linear seakeeping form.  The mooring acts at the exact fairlead
  positions (full rotation); wind and current coefficients follow the relative heading.
* Roll and pitch are small rotations: the frame rotates with the yaw only, roll/pitch rates
  equal the body rates, and the hydrostatic restoring is linear (``C`` about the zero pose).
* Wave forces are precomputed at the mean position and the start heading and stay fixed in
  earth axes (see :mod:`floatmoor.forces.waves`): a body that yaws far does not see the waves
  from a new relative heading.  The radiation memory uses the history of ``nu`` in the current
  yaw frame (slowly varying yaw).
* Wind and current act on the flow velocity relative to the low-frequency body velocity (seed
  002 eq. 2.24, 2.26): with first-order waves the linear wave-frequency velocity (motion RAOs
  from :func:`floatmoor.solvers.frequency_domain.wave_frequency_rao` x the run's wave
  realisation, :mod:`floatmoor.solvers.wf_velocity`) is removed from the body velocity there;
  scene option ``forces: {relative_velocity: total}`` keeps the total velocity.  The wave drift
  damping (``lf_damping`` terms) always acts on the low-frequency velocity.
* Start: the static equilibrium under buoyancy - weight, mooring, mean wind and current at rest
  and mean wave drift (:func:`floatmoor.solvers.statics.solve_equilibrium`); the fluctuating loads
  (first-order waves, slow drift, gust) are ramped in over ``ramp`` seconds, so the run starts
  without a jump; statistics should skip ``transient`` seconds.
* Finite-element lines (scene ``mooring: {model: finite-element}`` or per line): coupled by
  :mod:`floatmoor.solvers.fe_coupling` (staggered, one FE advance per body step, the lines'
  catenary carries the change within the step; its docstring gives the scheme and limits); the
  start pose is then the static equilibrium with the FE lines' static forces.  Without FE lines
  the quasi-static kernel runs alone, as before.
* Fibre ropes (line types with a ``fibre:`` model): the quasi-static lines are linearised about
  each fibre segment's slowly varying tension, the tension low-pass filtered with time
  constant ``mooring: fibre_time_constant`` (300 s by default; ``.inf`` keeps the
  linearisation about the static mean): slowly varying offsets follow the working curve,
  wave-frequency stretches see the dynamic stiffness ``EA_dyn(T_s)``
  (:mod:`floatmoor.mooring.fibre_system` states the rule).  With coupled FE lines the
  quasi-static lines keep the fixed-mean rule.
* Output ``velocity`` is the pose rate; ``force`` is in earth axes (moments about the
  displaced reference point).
"""

from __future__ import annotations

import math
import time as _time
from dataclasses import dataclass, field

import numpy as np

from ..core.dofs import DOF_NAMES
from ..core.errors import NumericalError, SceneError
from ..forces.base import KernelAssembly, SetupContext, model_class, select_models
from ..forces.radiation import infinite_frequency_added_mass
from ..forces.terms import as_kernel_array
from ..forces.waves import wave_components
from ..mooring.catenary_step import WARM_SIZE
from ..mooring.fibre_system import fibre_track, no_fibre_track
from .statics import solve_equilibrium as equilibrium
from .td_bundles import Body, lines_bundle, new_outputs, no_lines
from .td_kernel import (
    STATUS_CATENARY,
    STATUS_GUARD,
    STATUS_NAN,
    STATUS_OK,
    STATUS_TENSION,
    td_kernel,
)
from .wf_velocity import RELATIVE_VELOCITY_MODES, wf_velocity_series

__all__ = ["RK4_LIMIT", "Assembly", "TimeDomainResult", "assemble", "integrate"]

RK4_LIMIT = 2.78
"""RK4 is stable for purely imaginary eigenvalues lambda dt up to 2 sqrt(2) = 2.83."""


@dataclass(kw_only=True)
class Assembly:
    """Everything a run needs: the models, the kernel arrays and the start state."""

    models: dict
    asm: KernelAssembly
    x0: np.ndarray
    dt: float
    n_steps: int
    inertia: np.ndarray
    waves: object = None
    equilibrium: object = None
    omega_max: float = 0.0
    relative_velocity: str = "low_frequency"
    wave_yaw: float = 0.0
    fe: object = None
    """The finite-element lines (:class:`floatmoor.solvers.fe_coupling.FECoupling`) or None."""
    solver: object = None
    """Options of the time loop (:class:`floatmoor.io.solver_section.SolverSpec`) or None (the
    exact path)."""
    fibre_start: object = None
    """Fibre ropes: ``(system, tm)`` the nonlinear mooring system and its segment mean tensions
    at the linearisation point (the start of the slowly varying tensions), or None."""

    @property
    def wf_velocity(self):
        """The linear WF velocity (n_samples, 6) at the half-step samples (earth axes) removed
        from the body velocity in the wind and current relative velocity, or None."""
        return self.asm.wf_velocity if self.asm.has_wf_velocity else None


@dataclass(kw_only=True)
class TimeDomainResult:
    """Raw arrays of one run (SI units); ``time`` (n,), ``motion``/``velocity`` (n, 6),
    ``line_tension``/``anchor_tension`` (n, n_lines), ``forces`` (n, n_models, 6) or None,
    ``wave_elevation`` (n,) or None; ``models`` active model names; ``line_names``;
    ``wall_time`` (s) of the time loop; ``setup_time`` (s)."""

    time: np.ndarray
    motion: np.ndarray
    velocity: np.ndarray
    line_tension: np.ndarray
    anchor_tension: np.ndarray
    forces: np.ndarray | None
    force_models: list
    wave_elevation: np.ndarray | None
    models: list
    line_names: list
    x0: np.ndarray
    wall_time: float = 0.0
    setup_time: float = 0.0
    info: dict = field(default_factory=dict)
    fe_lines: list = field(default_factory=list)
    """Names of the lines modelled with finite elements (coupled; empty: all quasi-static)."""
    fe_records: dict | None = None
    """FE channels (n, n_lines), NaN for quasi-static lines: ``max_tension_along_line``,
    ``grounded_length``, ``touchdown_tension`` (N, m, N); None without FE lines."""
    fe_objects: list = field(default_factory=list)
    """The :class:`~floatmoor.mooring.fe.line.FELine` of each FE line after the run (their
    energy audit and parameters, for the self-check of the results)."""


def assemble(built, *, seed: int, dt: float, duration: float, ramp: float = 0.0,
             options=None, models: list[str] | None = None, waves=None,
             start_pose=None, solver=None) -> Assembly:
    """Build the models and the kernel arrays of one run.

    Parameters
    ----------
    built : :class:`floatmoor.io.build.BuiltScene` (needs a vessel).
    seed : int; dt : float (s); duration : float (s); ramp : float (s).
    options : the scene's ``forces`` settings (or None).
    models : model names (default: the scene's, :func:`floatmoor.forces.select_models`).
    waves : a :class:`floatmoor.forces.waves.WaveComponents` to use instead of realising the
        scene's sea state (e.g. a regular wave); needs ``models`` to include ``wave1``.
    start_pose : (6,) start pose instead of the static equilibrium (free decay).
    solver : the scene's ``solver`` options (:class:`floatmoor.io.solver_section.SolverSpec`)
        or None: the exact path.
    """
    if built.vessel is None:
        raise SceneError(built.scene.file, "vessel", "a vessel for a time-domain simulation")
    if not (dt > 0.0 and duration > dt):
        raise SceneError(built.scene.file, "analysis", "0 < dt < duration", (dt, duration))
    n_steps = int(round(duration / dt))
    names = select_models(built, options) if models is None else list(models)
    v = built.vessel
    site = built.scene.site
    if waves is None and built.scene.environment.waves is not None and (
            "wave1" in names or any(n.startswith("drift") for n in names)):
        waves = wave_components(built.scene.environment.waves, duration=n_steps * dt, seed=seed,
                                h=0.5 * dt, water_depth=site.water_depth, gravity=site.gravity)
    ctx = SetupContext(built=built, seed=int(seed), dt=float(dt), n_steps=n_steps,
                       ramp=float(ramp), yaw0=0.0, options=options, waves=waves,
                       inputs=built.model_inputs(options, names, yaw=0.0), solver=solver)
    active = {}
    for name in names:
        m = model_class(name, key="forces")()
        m.setup(ctx)
        active[name] = m
    asm = KernelAssembly(n_samples=ctx.n_samples, sample_dt=ctx.sample_dt)
    for m in active.values():
        m.contribute(asm)
    a_inf = infinite_frequency_added_mass(v.database)
    inertia = np.asarray(v.mass_matrix, float) + a_inf
    asm.inertia = inertia
    # static start
    mean_env = np.zeros(6)
    for name, m in active.items():
        if name not in ("hydrostatics", "mooring"):
            mean_env += m.mean_force()
    C = asm.restoring
    eq = None
    if start_pose is not None:
        x0 = np.asarray(start_pose, float).reshape(6)
    elif built.mooring is not None and "mooring" in active:
        # the catenary warm starts are cached in the MooringSystem: reset them so that the
        # same seed gives a bit-identical run whatever ran before
        built.mooring.warm[:] = 0.0
        try:
            eq = equilibrium(built.mooring, hydrostatic_stiffness=C,
                             external_force=asm.const_force + mean_env)
        except NumericalError as exc:
            raise NumericalError(f"no static equilibrium to start from under the mean loads "
                                 f"({exc.what})", time=0.0, where=exc.where,
                                 remedy=exc.remedy) from exc
        x0 = eq.pose.copy()
    else:
        x0 = np.zeros(6)
        held = np.abs(np.diag(C)) > 0.0
        if held.any():
            sub = np.ix_(held, held)
            x0[held] = np.linalg.solve(C[sub], (asm.const_force + mean_env)[held])
    fibre_lin = fibre_start = None
    if "mooring" in active and built.mooring is not None and built.mooring.has_fibre:
        fibre_lin = _fibre_dynamics(built, asm, active["mooring"], eq, C, mean_env)
        fibre_start = (built.mooring, _segment_tensions(built.mooring))
    # highest natural frequency of the linearised system (stability check)
    K_lin = C.copy()
    if fibre_lin is not None:
        K_lin = K_lin + fibre_lin.stiffness(x0)
    elif eq is not None:
        K_lin = K_lin + eq.mooring_stiffness
    elif built.mooring is not None and "mooring" in active:
        K_lin = K_lin + built.mooring.stiffness(x0)
    lam = np.linalg.eigvals(np.linalg.solve(inertia, K_lin))
    omega_max = float(np.sqrt(np.max(np.abs(lam))))
    # linear wave-frequency velocity for the wind and current relative velocity (Wang (2016)
    # eq. 2.24, 2.26: relative to the low-frequency body velocity)
    mode = getattr(options, "relative_velocity", "low_frequency")
    if mode not in RELATIVE_VELOCITY_MODES:
        raise SceneError(getattr(options, "file", None), "forces.relative_velocity",
                         "one of: " + ", ".join(RELATIVE_VELOCITY_MODES), mode)
    flows_lf = (mode == "low_frequency" and ("wind" in active or "current" in active))
    lf_terms = bool(asm.terms["lf_damping"])  # on the low-frequency velocity whatever the mode
    if waves is not None and "wave1" in active and (flows_lf or lf_terms):
        asm.wf_velocity = wf_velocity_series(
            waves, v.database, n_samples=ctx.n_samples, h=ctx.sample_dt,
            ramp=ctx.ramp_series(), mass=np.asarray(v.mass_matrix, float), stiffness=K_lin,
            linear_damping=asm.damping_linear,
            quadratic_damping=asm.damping_quadratic if asm.has_damping_quadratic else None,
            radiation="radiation" in active, a_inf=a_inf, yaw0=ctx.yaw0, file=v.file)
        asm.has_wf_velocity = flows_lf
        asm.lf_wf_velocity = lf_terms
    # finite-element lines (coupled; only imported when the scene selects some)
    fe = None
    lm = getattr(built.mooring, "line_models", None)
    if "mooring" in active and lm is not None and lm.any_finite_element:
        from .fe_coupling import setup as fe_setup
        fe = fe_setup(built, pose=x0, fail_time=active["mooring"].fail_time, dt=float(dt))
        if fe is not None and start_pose is None:
            from .fe_coupling import start_equilibrium
            x0 = start_equilibrium(fe, built.mooring, x0=x0, hydrostatic_stiffness=C,
                                   external_force=asm.const_force + mean_env)
            built.mooring.warm[:] = 0.0
    return Assembly(models=active, asm=asm, x0=x0, dt=float(dt), n_steps=n_steps,
                    inertia=inertia, waves=waves, equilibrium=eq, omega_max=omega_max,
                    relative_velocity=mode, wave_yaw=ctx.yaw0, fe=fe, solver=solver,
                    fibre_start=fibre_start)


def _fibre_dynamics(built, asm, model, eq, C, mean_env):
    """Fibre ropes in the quasi-static time domain: the kernel's lines start as the constant-EA
    linearisation about the static equilibrium under the mean loads (the working curve there),
    every fibre segment with its dynamic stiffness at its mean tension (then moved with the
    slowly varying tension in the loop, :func:`_fibre_track`)
    (:meth:`floatmoor.mooring.MooringSystem.linearised_fibre`; rule and sources in
    :mod:`floatmoor.mooring.fibre_system`). With a given start pose the linearisation point is
    still that equilibrium. Returns the linearised system."""
    if eq is not None:
        pose = eq.pose
    else:
        built.mooring.warm[:] = 0.0
        pose = equilibrium(built.mooring, hydrostatic_stiffness=C,
                           external_force=asm.const_force + mean_env).pose
    lin = model.linearise_fibre(pose)
    lin.warm[:] = 0.0
    asm.replace_mooring_system(lin)
    return lin


def _segment_tensions(system):
    """Segment mean tensions (N,) of the system's last evaluation."""
    from ..mooring.fibre_system import _mean_tensions
    return _mean_tensions(system)


def _fibre_track(a: Assembly):
    """The time loop's fibre bundle: the linearisation follows the slowly varying tensions
    (time constant ``fibre_time_constant`` of the mooring system) with quasi-static lines only;
    off (the fixed-mean rule) with ``inf`` or coupled FE lines."""
    if a.fibre_start is None or a.fe is not None:
        return no_fibre_track()
    system, tm = a.fibre_start
    return fibre_track(system, system.fibre_time_constant, a.dt, tm)


def _guard_limits(built) -> np.ndarray:
    depth = built.scene.site.water_depth
    trans = max(2.0 * depth, 200.0)
    return np.array([trans, trans, max(depth, 50.0), 1.0, 1.0, 1e3])


def kernel_bundles(a: Assembly, *, record_forces: bool = False, v0=None,
                   tension_guard: float = 10.0, built=None):
    """The bundles ``(body, terms, lines, out)`` of :func:`floatmoor.solvers.td_kernel.td_steps`
    for a run of ``a`` (NumericalError when ``dt`` is beyond the RK4 stability limit); the
    catenary solves of ``a.solver`` (:func:`floatmoor.io.solver_section.catenary_tol`)."""
    from ..io.solver_section import catenary_tol
    asm = a.asm
    dt = a.dt
    n = a.n_steps
    if a.omega_max * dt > RK4_LIMIT:
        raise NumericalError(
            f"time step {dt:g} s is beyond the RK4 stability limit for the stiffest mode "
            f"(natural period {2 * math.pi / a.omega_max:.3g} s, omega dt = "
            f"{a.omega_max * dt:.2f} > {RK4_LIMIT})", time=0.0, where="integrator",
            remedy=f"use dt <= {RK4_LIMIT / a.omega_max * 0.9:.3g} s")
    minv = np.linalg.inv(a.inertia)
    moor = asm.mooring
    if moor is not None:
        lines = lines_bundle(True, moor.catenary_arrays(), moor.active.copy(),
                             np.zeros((moor.n_lines, WARM_SIZE)),
                             as_kernel_array(asm.fail_time, float),
                             as_kernel_array(moor.mbs, float), _fibre_track(a),
                             catenary_tol(a.solver))
    else:
        lines = no_lines()
    n_lines = lines.mbs.shape[0]
    terms = asm.force_terms()
    out = new_outputs(n, n_lines, len(asm.part_names), record_parts=bool(record_forces))
    x0 = as_kernel_array(a.x0, float)
    v0 = np.zeros(6) if v0 is None else as_kernel_array(v0, float)
    guard = _guard_limits(built) if built is not None else np.array([1e4, 1e4, 1e3, 1.0, 1.0, 1e3])
    body = Body(int(n), float(dt), as_kernel_array(a.inertia, float), minv, x0, v0, guard,
                float(tension_guard), bool(record_forces))
    return body, terms, lines, out


def integrate(a: Assembly, *, record_forces: bool = False, v0=None, tension_guard: float = 10.0,
              built=None, progress=None) -> TimeDomainResult:
    """Run the time loop of an :class:`Assembly`.  ``progress``: called with the simulated
    time and the end time (s) every 5 % of a run with finite-element lines (quasi-static runs
    take seconds and do not call it).

    Raises
    ------
    NumericalError
        NaN or an exploding state (names the time and DOF), a line tension above
        ``tension_guard`` x MBS or a failed catenary solve (names the time and line), or a time
        step beyond the integrator's stability limit (before running).
    """
    t_start = _time.perf_counter()
    asm = a.asm
    dt = a.dt
    n = a.n_steps
    body, terms, lines, out = kernel_bundles(a, record_forces=record_forces, v0=v0,
                                             tension_guard=tension_guard, built=built)
    moor = asm.mooring
    line_names = list(moor.names) if moor is not None else []
    mbs = lines.mbs
    n_lines = len(line_names)
    part_names = asm.part_names
    x0 = body.x0
    guard = body.guard
    setup_time = _time.perf_counter() - t_start
    t0 = _time.perf_counter()
    fe_records = None
    fe_info = {}
    status = out.status
    if a.fe is None:
        td_kernel(body, terms, lines, out)
    else:
        from ..io.solver_section import fe_stages, fe_stiffness_interval, is_auto, run_threads
        from .fe_coupling import FE_RECORDS, auto_threads, raise_fe_status
        from .fe_coupling import run as fe_run
        threads = run_threads(a.solver)
        auto = is_auto(a.solver)
        fe_status, fe_out = fe_run(a.fe, body, terms, lines, out, x0=x0, n_lines=n_lines,
                                   threads=threads, fe_stages=fe_stages(a.solver),
                                   stiffness_interval=fe_stiffness_interval(a.solver),
                                   progress=progress, auto=auto)
        if auto:    # the threads the run took (the lines are started: auto_threads can tell)
            threads = auto_threads(a.fe.mooring.lines, threads)
        raise_fe_status(a.fe, fe_status)
        status[:] = fe_status[:3]
        fe_records = dict(zip(FE_RECORDS, fe_out))
        fe_info = {"fe_substeps": int(a.fe.substeps), "fe_threads": int(threads),
                   "fe_newton_iterations": int(a.fe.mooring.counters[:, 0].sum()),
                   "fe_step_halvings": int(a.fe.mooring.counters[:, 1].sum()),
                   "fe_elements": [int(ln.n_nodes - 1) for ln in a.fe.mooring.lines]}
    motion, velocity, t_fair, t_anchor, parts = out[:5]
    wall = _time.perf_counter() - t0
    _raise_on_status(status, dt, line_names, mbs, tension_guard, guard)
    time = np.arange(n + 1) * dt
    forces = None
    force_models = []
    if record_forces:
        # the models' order, the precomputed series last
        kinds = dict(zip(part_names, asm.part_kinds))
        force_models = ([m for m in a.models if m in kinds and kinds[m] != "series"]
                        + [m for m in part_names if kinds[m] == "series"])
        forces = parts[:, [part_names.index(m) for m in force_models], :]
    eta = None
    if a.waves is not None:
        eta = a.waves.elevation(2 * n + 1, 0.5 * dt)[::2]
    return TimeDomainResult(time=time, motion=motion, velocity=velocity, line_tension=t_fair,
                            anchor_tension=t_anchor, forces=forces, force_models=force_models,
                            wave_elevation=eta, models=list(a.models), line_names=line_names,
                            x0=a.x0.copy(), wall_time=wall, setup_time=setup_time,
                            info={"omega_max": a.omega_max,
                                  "relative_velocity": a.relative_velocity,
                                  "wf_velocity_removed": bool(asm.has_wf_velocity),
                                  "wave_heading_yaw": a.wave_yaw, **fe_info},
                            fe_lines=[] if a.fe is None else list(a.fe.names),
                            fe_records=fe_records,
                            fe_objects=[] if a.fe is None else list(a.fe.mooring.lines))


def _raise_on_status(status, dt, line_names, mbs, tension_guard, guard):
    code, step, idx = (int(s) for s in status)
    if code == STATUS_OK:
        return
    t = step * dt
    if code == STATUS_NAN:
        raise NumericalError("NaN or infinite value in the state", time=t,
                             where=f"DOF {DOF_NAMES[idx]}",
                             remedy="reduce dt, or add damping to that DOF")
    if code == STATUS_GUARD:
        unit = "m" if idx < 3 else "rad"
        raise NumericalError(f"the motion exploded (|{DOF_NAMES[idx]} - start| > "
                             f"{guard[idx]:g} {unit})", time=t, where=f"DOF {DOF_NAMES[idx]}",
                             remedy="reduce dt; check that the DOF has restoring and damping "
                                    "(mooring, hydrostatics) and the loads are not far beyond "
                                    "the mooring capacity")
    if code == STATUS_TENSION:
        raise NumericalError(f"line tension above {tension_guard:g} x MBS "
                             f"({tension_guard * mbs[idx] / 1e3:.0f} kN)", time=t,
                             where=f"line {line_names[idx]!r}",
                             remedy="reduce dt; check the line lengths, EA and anchor "
                                    "positions, or the loads against the mooring capacity")
    if code == STATUS_CATENARY:
        raise NumericalError("the catenary solve failed", time=t,
                             where=f"line {line_names[idx]!r}",
                             remedy="reduce dt; the line may be overstretched (offset beyond "
                                    "its length) - check the mooring layout and the loads")
    raise NumericalError(f"unknown status {code}", time=t)

"""Finite-element mooring lines coupled to the 6-DOF time-domain solver (staggered coupling).

A scene selects FE lines with ``mooring: {model: finite-element}`` (all lines) or per line
``lines[i].model`` (:mod:`floatmoor.mooring.fe.options`).  :func:`setup` builds them
(:class:`floatmoor.mooring.fe.body.FEMooring`, all lines of the body advanced in one numba call
per body step, :mod:`floatmoor.mooring.fe.multi`); :func:`run` integrates body and lines in
one numba kernel (:func:`td_fe_kernel`) that calls the resumable RK4 step of the quasi-static
solver (:func:`floatmoor.solvers.td_kernel.td_steps`) once per body step.  Runs without FE lines
never import this module: the quasi-static kernel is unchanged (bit-identical results) and its
compilation does not include the FE kernels.

Coupling scheme (staggered, one FE advance per body step)
---------------------------------------------------------
Over the body step t_n -> t_{n+1} the mooring force at every RK4 stage (pose x_s) is

    F = F_QS,others(x_s) + F_QS,FE(x_s) + [F_FE(t_n) - F_QS,FE(x_n)]

where F_QS,FE is the elastic catenary of the FE lines themselves (the quasi-static kernel
evaluates it anyway) and F_FE(t_n) the generalised force of the FE lines in their accepted
state at t_n.  The catenary carries the stage-to-stage change of the quasi-static part exactly
(4th order, as for quasi-static lines); only the dynamic part D = F_FE - F_QS,FE (line drag
and inertia, dynamic stiffness, seabed friction, the small FE-vs-catenary static difference) is
held constant over the step, a first-order lag of dt/2 in D alone.  After the body step the FE
lines are advanced to t_{n+1} (generalised-alpha, ``finite_element.dt`` / ``substeps`` line
steps per body step) with the fairleads at the new pose and moving with the new velocity (the
Euler-angle rates turned into the angular velocity in earth axes,
omega = [phi' cos(psi) cos(theta) - theta' sin(psi), phi' sin(psi) cos(theta) + theta' cos(psi),
psi' - phi' sin(theta)], so the fairlead velocity is the exact rate of its position) and the
state is accepted.  Nothing is iterated: one FE advance per body step, as many as a decoupled
run.  Mooring damping is not added anywhere; it comes out of the line drag in D.  The lag
gives an error of first order in dt in the dynamic part only (measured: tests and
benchmarks/RESULTS.md); a predictor-corrector (a second FE advance per step) was not used
because the FE lines are >90 % of the run time.

``solver: {fe_stages: linear}`` (the default since 2026-11-28; ``catenary`` the stages above):
F_QS,FE(x_s) - F_QS,FE(x_n) is taken as
(dQ/dx)(x_n) (x_s - x_n), the catenaries' 6x6 stiffness at the step start turned into pose
coordinates (:func:`pose_stiffness_into`), so the stages solve no catenary of the FE lines (one
solve with stiffness per line and step instead of five solves); the dropped term is of second
order in the stage displacement (a fraction of a metre).  Stage 1 (x_s = x_n) gets the same
force up to round-off.  Both are models of the lines' variation within the step (the FE lines'
own is held, D); their difference on the flagship storm, 0.0003-0.0006 % of the maximum
tension, is far below the time step's own error (0.018 % at dt 0.1 s, benchmarks/RESULTS.md).
The stiffness is solved every ``round(fe_stiffness_interval / dt)`` body steps (``solver:
{fe_stiffness_interval: 1.0}`` s by default; 0: every step) and at a step where a line is
released, and kept in between (:class:`FERun` ``kfe_every``): on the flagship storm each
line's maximum moved by at most 0.004 % (benchmarks/RESULTS.md, "A mesh by segment").

Start: the body at the static equilibrium of the quasi-static model (as for quasi-static
lines), the FE lines in their own static equilibrium with friction at that pose
(:meth:`FEMooring.solve_static`), at rest.  The small static difference FE vs catenary (0.02 %
of the tension with 50 elements) enters D and the body settles at the FE equilibrium.

Scope and limits
----------------
* Line failure (ALS), as for quasi-static lines.  Lines removed from the start (mooring
  ``failed_lines``) are not built: absent from the start equilibrium and the run, zero
  tension throughout.  A FE line with a failure time t_f (``forces.line_failure``) is part of
  the start equilibrium (as a quasi-static line with a failure time: the run starts intact)
  and is released at the first body step n with n dt >= t_f (the step at which the
  quasi-static kernel deactivates a line): from t_n on it exerts no force on the body (its
  generalised force leaves F_FE and its catenary leaves F_QS,FE, so D loses it too), it is no
  longer advanced (its last state is frozen, the free end is not simulated: the line falling
  to the seabed has no effect on the body) and its outputs are zero (``line_tension``,
  ``anchor_tension``, ``max_tension_along_line``, ``touchdown_tension``; ``grounded_length``
  NaN: not modelled).  Inside the kernel: a mask ``on`` per FE line, no allocation; an intact
  run does the same operations as before.
* The FE lines see the scene's current (profile and heading, relative-velocity drag); wave
  kinematics on the lines are not modelled in coupled runs.
* Outputs for FE lines: ``line_tension`` / ``anchor_tension`` are the FE fairlead and anchor
  tensions (magnitude of the end forces); ``max_tension_along_line``, ``grounded_length`` and
  ``touchdown_tension`` (NaN for quasi-static lines) come from
  :func:`floatmoor.mooring.fe.kernels.record_into` at every step.
* A failing FE step raises NumericalError naming the time, the line and node and a remedy; the
  tension guard (``tension_guard`` x MBS) also applies to the FE tensions.

Threads
-------
``solver: {threads: N}`` (:mod:`floatmoor.io.solver_section`): the FE lines of the body are
advanced in N threads at every body step (:class:`FERun` ``mode`` a
:class:`~floatmoor.mooring.fe.multi.ParallelLines`, kernel
:func:`~floatmoor.mooring.fe.multi.body_advance_parallel`); results bit for bit those of one
thread.  One thread (the default) compiles and runs the serial kernel only.  numba's thread
count is set around the run and restored (:func:`numba_threads`).
"""

from __future__ import annotations

import math
from contextlib import contextmanager
from dataclasses import dataclass
from typing import NamedTuple

import numpy as np
from numba import njit

from ..core.errors import NumericalError, SceneError
from ..core.frames import rotation_matrix_into
from ..mooring.fe.body import FEMooring, scene_line_inputs
from ..mooring.fe.lanes_body import LaneLines, lanes_fit, lanes_mode, store_lines
from ..mooring.fe.layout import KERNEL_JIT
from ..mooring.fe.line import FELine
from ..mooring.fe.multi import (
    FEBody,
    add_line_wrench,
    advance_lines,
    line_list,
    lines_mode,
    record_lines,
)
from ..mooring.system import system_force_kernel
from .td_kernel import (
    STATUS_CATENARY,
    STATUS_OK,
    STATUS_TENSION,
    _pose_rate,
    new_run_state,
    set_status,
    td_steps,
)

__all__ = ["FECoupling", "FERun", "setup", "run", "td_fe_kernel", "STATUS_FE", "FE_RECORDS",
           "pose_stiffness_into"]

STATUS_FE = 5
"""Status code of :func:`td_fe_kernel` when a FE line step failed (status[2] the FE line,
status[3] the code of :func:`floatmoor.mooring.fe.kernels.ga_advance`)."""

FE_RECORDS = ("max_tension_along_line", "grounded_length", "touchdown_tension")


class FERun(NamedTuple):
    """The FE lines' place in a coupled run (:func:`td_fe_kernel`), beside the body side
    (:class:`~floatmoor.mooring.fe.multi.FEBody`) and the lines' typed list of
    :class:`~floatmoor.mooring.fe.bundles.LineBundle`."""

    index: np.ndarray
    """(n_fe,) int64 positions of the FE lines among all lines."""
    active: np.ndarray
    """(n_lines,) bool: True for the intact FE lines (the catenary of F_QS,FE)."""
    warm: np.ndarray
    """(n_lines, 2) catenary warm starts of F_QS,FE."""
    nsub: int
    """Line steps per body step."""
    max_split: int
    """Step halvings allowed per line step."""
    records: np.ndarray
    """(3, n_steps+1, n_lines) out: max tension along the line, grounded length, touchdown
    tension of the FE lines (NaN for the others)."""
    mode: object
    """:class:`~floatmoor.mooring.fe.multi.SerialLines` or
    :class:`~floatmoor.mooring.fe.multi.ParallelLines`: the lines advanced one after the
    other or in threads (:func:`~floatmoor.mooring.fe.multi.advance_lines`; bit-identical)."""
    linear: bool
    """``solver: {fe_stages: linear}``: the FE lines' catenaries left out of the RK4 stages,
    their stage variation linearised at the step start (module docstring)."""
    kfe: np.ndarray
    """(6, 6) the catenary stiffness of the FE lines at the step start, solved every
    ``kfe_every`` th step (``solver: {fe_stiffness_interval}``) and kept in between."""
    kfe_every: int
    """Body steps between the solves of ``kfe`` (1: every step)."""
    w6: np.ndarray
    """(3, 6) scratch: the pose rate, the body's velocity in earth axes, F_QS,FE."""


@dataclass(kw_only=True)
class FECoupling:
    """The FE lines of a run: ``mooring`` the :class:`FEMooring`, ``names`` its lines,
    ``index`` their positions in the mooring system (int64), ``substeps`` line steps per body
    step, ``fail_time`` (n_fe,) failure time of each FE line (s; inf: intact)."""

    mooring: FEMooring
    names: list
    index: np.ndarray
    substeps: int
    options: object
    fail_time: np.ndarray = None


def setup(built, *, pose, fail_time=None, dt: float) -> FECoupling | None:
    """The FE lines a scene selects, built at the start ``pose`` (None when it has none).

    Parameters
    ----------
    built : BuiltScene
    pose : (6,) start pose, m and rad.
    fail_time : (n_lines,) failure times of the mooring model (s; inf: none); a FE line with
        a finite time is released in the run at that time (module docstring).
    dt : body time step, s.

    Raises
    ------
    SceneError
        FE options that cannot be coupled (``finite_element.integrator: explicit``, kept for
        decoupled comparison runs).
    """
    system = built.mooring
    lm = getattr(system, "line_models", None)
    if system is None or lm is None or not lm.any_finite_element:
        return None
    if lm.options.integrator != "generalized_alpha":
        raise SceneError(system.source, "mooring.finite_element.integrator",
                         "generalized_alpha for lines coupled to the body (the explicit scheme "
                         "is for decoupled comparison runs: floatmoor lines)",
                         lm.options.integrator)
    fm, names = FEMooring.from_system(system, pose=pose, **scene_line_inputs(built.scene, system))
    if fm is None:
        return None
    index = np.array([system.names.index(n) for n in names], np.int64)
    fail = np.full(len(names), math.inf)
    if fail_time is not None:
        fail[:] = np.asarray(fail_time, float)[index]
    return FECoupling(mooring=fm, names=list(names), index=index,
                      substeps=fm.options.substeps_for(dt), options=fm.options, fail_time=fail)


def start_equilibrium(c: FECoupling, system, *, x0, hydrostatic_stiffness, external_force,
                      tol: float = 1e-3, max_iter: int = 10):
    """Static equilibrium with the FE lines: the quasi-static equilibrium corrected by the
    static difference of the FE lines, D(x) = F_FE,static(x) - F_QS,FE(x) (line current drag,
    the FE-vs-catenary difference), by the fixed-point iteration x_{k+1} = equilibrium(external
    + D(x_k)) from ``x0`` (D varies slowly with x: a few iterations).  Returns the pose (6,).

    Raises
    ------
    NumericalError
        No convergence in ``max_iter`` iterations (``tol`` in m, ``tol`` / 100 in rad), or FE
        statics that fail.
    """
    from ..core.errors import ConvergenceError
    from .statics import solve_equilibrium as equilibrium

    qs_fe = system.without_lines([n for n, a in zip(system.names, system.active)
                                  if a and n not in c.names])
    fm = c.mooring
    x = np.asarray(x0, float).copy()
    step = np.inf
    for _ in range(max_iter):
        try:
            D = fm.solve_static(x) - qs_fe.force(x)
        except ConvergenceError as exc:
            raise NumericalError(f"FE statics at the start pose: {exc.what}", time=0.0,
                                 where=exc.where, remedy=exc.remedy) from None
        system.warm[:] = 0.0
        xn = equilibrium(system, hydrostatic_stiffness=hydrostatic_stiffness,
                         external_force=external_force + D, x0=x).pose
        dx = np.abs(xn - x)
        step = max(dx[:3].max() / tol, dx[3:].max() / (tol / 100.0))
        x = xn
        if step <= 1.0:
            return x
    raise NumericalError(f"no static equilibrium with the finite-element lines in {max_iter} "
                         f"iterations (last pose change {step * tol:.3g} m)", time=0.0,
                         where="mooring (finite-element lines)",
                         remedy="check the FE line options (elements, seabed) and the current "
                                "on the lines; a line far from its catenary shape")


@njit(**KERNEL_JIT)
def _record_fe(n, fe_index, fe_out, recs, on, t_fair, t_anchor):
    """Row ``n`` of the outputs of the FE lines (``fe.records``, the tensions ``t_fair``,
    ``t_anchor``; ``fe.index`` their rows) from the channels of their accepted states,
    ``fe.mode.recs`` (:func:`~floatmoor.mooring.fe.multi.record_lines`, written where each
    line was accepted)."""
    for i in range(fe_index.shape[0]):
        j = fe_index[i]
        if not on[i]:  # released line: zero tensions, grounded length not modelled
            t_fair[n, j] = 0.0
            t_anchor[n, j] = 0.0
            fe_out[0, n, j] = 0.0
            fe_out[1, n, j] = np.nan
            fe_out[2, n, j] = 0.0
            continue
        rec = recs[i]
        t_fair[n, j] = math.sqrt(rec[0] ** 2 + rec[1] ** 2 + rec[2] ** 2)
        t_anchor[n, j] = math.sqrt(rec[3] ** 2 + rec[4] ** 2 + rec[5] ** 2)
        fe_out[0, n, j] = rec[6]
        fe_out[1, n, j] = rec[11]
        fe_out[2, n, j] = rec[8]


@njit(**KERNEL_JIT)
def _release_failed(t, fe, fail_time, body):
    """Release the FE lines whose failure time is reached at ``t`` (``t >= fail_time``, the
    test of the quasi-static kernel): ``body.on`` and ``fe.active`` False, and ``body.Q``
    summed again over the remaining lines from their end ``body.forces`` and lever
    ``body.arm`` s (as :func:`body_advance` sums it).  Returns True when a line was released."""
    fe_index = fe.index
    on = body.on
    forces = body.forces
    Q = body.Q
    changed = False
    for i in range(fe_index.shape[0]):
        j = fe_index[i]
        if on[i] and t >= fail_time[j]:
            on[i] = False
            fe.active[j] = False
            for c in range(3):
                forces[i, c] = 0.0
            changed = True
    if changed:
        for k in range(6):
            Q[k] = 0.0
        for i in range(fe_index.shape[0]):
            if on[i]:
                add_line_wrench(i, body.arm, forces, Q)
    return changed


@njit(cache=True)
def pose_stiffness_into(K, x, out):
    """``out`` (6, 6) = dQ/dx at the pose ``x``, the derivative of the mooring force and
    moment ``Q`` (earth axes, about the displaced reference point) with respect to the pose
    [x, y, z, roll, pitch, yaw], from the catenary stiffness ``K`` = -dQ/d[dt, theta] of
    :func:`~floatmoor.mooring.system.system_force_kernel` (small rotations ``theta`` in earth
    axes): ``theta = T(x) d[roll, pitch, yaw]`` with the Euler-rate matrix ``T`` of the
    angular velocity used for the fairleads (module docstring), so ``out = -K diag(I, T)``."""
    cph = math.cos(x[4])
    sph = math.sin(x[4])
    cps = math.cos(x[5])
    sps = math.sin(x[5])
    # T: rows the earth axes, columns d roll, d pitch, d yaw
    t00 = cps * cph
    t01 = -sps
    t10 = sps * cph
    t11 = cps
    t20 = -sph
    for i in range(6):
        out[i, 0] = -K[i, 0]
        out[i, 1] = -K[i, 1]
        out[i, 2] = -K[i, 2]
        out[i, 3] = -(K[i, 3] * t00 + K[i, 4] * t10 + K[i, 5] * t20)
        out[i, 4] = -(K[i, 3] * t01 + K[i, 4] * t11)
        out[i, 5] = -K[i, 5]


@njit(cache=True)
def td_fe_kernel(body, terms, lines, state, out, fe, fe_body, fe_lines, n0, n1):
    """:func:`floatmoor.solvers.td_kernel.td_kernel` with FE lines (scheme: module docstring;
    :func:`run` records the started state, row 0, before the first call),
    body steps ``n0`` to ``n1 - 1`` (the whole run: 0 to ``body.n_steps + 1``; :func:`run`
    calls it in pieces to report progress, each piece continuing from the state the last
    one left: the same arithmetic as one call).

    Body side: the bundles of :func:`floatmoor.solvers.td_kernel.td_steps` (``body``,
    ``terms``, ``lines``, ``state`` at the start state with ``has_mcorr``, ``out`` with
    ``out.status`` (4,) here; the catenary data hold every line, FE lines included,
    ``lines.active`` their state).  FE side: ``fe`` (:class:`FERun`: positions of the FE lines,
    their catenary mask and warm starts, line steps per body step, the records out),
    ``fe_body`` (:class:`~floatmoor.mooring.fe.multi.FEBody`: ``Q`` the generalised force of
    the FE lines in the started state, updated every step; ``arm`` and ``forces`` the lever arms
    and end forces of the started state; ``on`` True for the intact FE lines, set False at their
    ``fail_time``) and ``fe_lines`` (typed list of
    :class:`~floatmoor.mooring.fe.bundles.LineBundle`).  Status 5 (:data:`STATUS_FE`): FE
    step failed, ``status[2]`` the FE line, ``status[3]`` the kernel code, the line's
    ``work.info`` the time and node.
    """
    n_steps = body.n_steps
    dt = body.dt
    tension_guard = body.tension_guard
    x = state.x
    v = state.v
    mcorr = state.mcorr
    fail_time = lines.fail_time
    mbs = lines.mbs
    t_fair = out.t_fair
    t_anchor = out.t_anchor
    status = out.status
    if n0 == 0:
        for k in range(status.shape[0]):
            status[k] = 0
    fe_index = fe.index
    active_fe = fe.active
    warm_fe = fe.warm
    Q = fe_body.Q
    n_fe = fe_index.shape[0]
    prate = fe.w6[0]
    vel = fe.w6[1]
    fq = fe.w6[2]
    linear = fe.linear
    # the fields read at every step taken out of their bundles once: in this kernel (with
    # reference counting, for the typed list) each read of a bundle's field counts the
    # references of all its arrays (3 % of the coupled flagship, perf 2026-11-28)
    mode = fe.mode
    recs = mode.recs
    fe_out = fe.records
    cat = lines.cat
    kfe = fe.kfe
    nsub = fe.nsub
    max_split = fe.max_split
    on_fe = fe_body.on
    swork = state.work
    srot = state.rot
    sline = state.line_out
    mlin = state.mlin
    mref = state.mref
    kfe_every = fe.kfe_every
    for n in range(n0, n1):
        # line failures (ALS): released from t_n on, as the quasi-static kernel does
        released = _release_failed(n * dt, fe, fail_time, fe_body)
        # dynamic part of the FE lines at t_n: D = F_FE(t_n) - F_QS,FE(x_n), held over the step;
        # linear stages: the catenaries' stiffness every kfe_every th step and at a release
        if not linear or released or n % kfe_every == 0:
            bad = system_force_kernel(x, cat.anchors, cat.fairleads, cat.seg_L, cat.seg_EA,
                                      cat.seg_w, cat.seg_P, cat.line_start, cat.cb, cat.seabed,
                                      active_fe, warm_fe, linear, swork, srot, sline, fq, kfe)
            if bad >= 0:
                set_status(status, STATUS_CATENARY, n, bad)
                return
        if linear:
            # stages: F_QS,others(x_s) + F_FE(t_n) + dF_QS,FE/dx (x_s - x_n)
            pose_stiffness_into(kfe, x, mlin)
            for k in range(6):
                mcorr[k] = Q[k]
                mref[k] = x[k]
        else:
            for k in range(6):
                mcorr[k] = Q[k] - fq[k]
        td_steps(n, n + 1, body, terms, lines, state, out)
        if status[0] != STATUS_OK:
            return
        # row n: the FE tensions at t_n replace the catenary's for the FE lines
        _record_fe(n, fe_index, fe_out, recs, on_fe, t_fair, t_anchor)
        for i in range(n_fe):
            j = fe_index[i]
            if t_fair[n, j] > tension_guard * mbs[j]:
                set_status(status, STATUS_TENSION, n, j)
                return
        if n == n_steps:
            return
        # FE lines to t_{n+1}: fairleads at the new pose, angular velocity in earth axes
        _pose_rate(x, v, prate)
        cph = math.cos(x[4])
        sph = math.sin(x[4])
        cps = math.cos(x[5])
        sps = math.sin(x[5])
        vel[0] = prate[0]
        vel[1] = prate[1]
        vel[2] = prate[2]
        vel[3] = prate[3] * cps * cph - prate[4] * sps
        vel[4] = prate[3] * sps * cph + prate[4] * cps
        vel[5] = prate[5] - prate[3] * sph
        st = advance_lines(mode, (n + 1) * dt, dt, nsub, max_split, x, vel, fe_body,
                           fe_lines)
        if st < 0:
            status[0] = STATUS_FE
            status[1] = n + 1
            status[2] = fe_body.fail[0]
            status[3] = st
            return


td_fe_kernel_lanes = njit(**KERNEL_JIT)(td_fe_kernel.py_func)
""":func:`td_fe_kernel` for lines as SIMD lanes (``fe.mode`` a
:class:`~floatmoor.mooring.fe.lanes_body.LaneLines`), without the typed list (``fe_lines``
None) and so without reference counting: the lanes hold the lines' states, a failing lane's
information reaches its line through ``store_lines`` after the run (the counts were 3 % of the
coupled flagship, perf 2026-11-28)."""


def run(c: FECoupling, body, terms, moor, out, *, x0, n_lines: int, threads: int = 1,
        fe_stages: str = "linear", stiffness_interval: float = 0.0, progress=None,
        auto: bool = False):
    """Start the FE lines at ``x0`` and run :func:`td_fe_kernel` with the bundles of
    ``td_kernel`` (``body``, ``terms``, ``moor`` the :class:`~.td_bundles.Lines`, ``out``;
    the outputs are filled, their status left alone).  Returns ``(status (4,), fe_out (3,
    n+1, n_lines))``; the FE channels are NaN for quasi-static lines.  ``threads`` > 1:
    the lines advance in that many threads (numba's count set for the kernel and restored
    after it; bit-identical results, :func:`floatmoor.mooring.fe.multi.body_advance_parallel`);
    1: the serial kernel; ``auto`` (``solver: {threads: auto}``): ``threads`` is the most
    allowed, :func:`auto_threads` chooses.  ``fe_stages`` ``"linear"`` (default): the FE lines' catenaries left out
    of the RK4 stages, their stage variation linearised at the step start (module docstring);
    ``"catenary"`` (``solver: {fe_stages: catenary}``): their catenaries solved at every stage.
    ``stiffness_interval`` (s, linear stages): the catenaries' stiffness solved every
    ``round(stiffness_interval / dt)`` body steps (at least every step) and when a line is
    released, kept in between (``solver: {fe_stiffness_interval}``, 1.0 s by default there; 0
    here: every step).  ``progress``: called with the
    simulated time (s) and the run's end time after every :data:`PROGRESS_PIECES` th of the
    run (the kernel runs in that many pieces; the same numbers as one piece).

    Raises
    ------
    NumericalError
        FE statics that do not converge at the start pose.
    """
    from ..core.errors import ConvergenceError

    fm = c.mooring
    try:
        fm.solve_static(x0)
    except ConvergenceError as exc:
        raise NumericalError(f"FE statics at the start pose: {exc.what}", time=0.0,
                             where=exc.where, remedy=exc.remedy) from None
    fm.start(**c.options.start_kw())  # generalised-alpha (checked in setup)
    lines = fm.lines
    # generalised force of the started lines (dynamic EA), as body_advance will report it
    ends = np.array([ln.fn[-1] for ln in lines])
    Q = np.ascontiguousarray(fm._sum(np.asarray(x0, float), ends))
    n_steps = body.n_steps
    status = np.zeros(4, np.int64)
    active_fe = np.zeros(n_lines, np.bool_)
    active_fe[c.index] = True
    # lever arms and end forces of the started state (for a release of a line at t = 0)
    R = np.zeros((3, 3))
    x0 = np.asarray(x0, float)
    rotation_matrix_into(x0[3], x0[4], x0[5], R)
    arm = np.ascontiguousarray(fm.fairleads_body @ R.T)
    forces = np.ascontiguousarray(ends, dtype=float)
    nf = len(lines)
    on = np.ones(nf, np.bool_)
    fm.counters = np.zeros((nf, 2))
    out = out._replace(status=status)
    linear = fe_stages == "linear"
    if linear:
        # the body side's stages solve the catenaries of the other (quasi-static) lines only
        active = moor.active.copy()
        active[c.index] = False
        moor = moor._replace(active=active)
    st = new_run_state(body, terms, moor, out, has_mcorr=True, has_mlin=linear)
    fe_body = FEBody(fair_b=np.ascontiguousarray(fm.fairleads_body), R=np.zeros((3, 3)),
                     rf=np.zeros((nf, 3)), vf=np.zeros((nf, 3)), arm=arm, Q=Q, forces=forces,
                     on=on, fail=np.zeros(1, np.int64), counters=fm.counters)
    fe = FERun(index=np.ascontiguousarray(c.index), active=active_fe,
               warm=np.zeros((n_lines, 2)), nsub=int(c.substeps),
               max_split=int(FELine.MAX_SPLIT),
               records=np.full((3, n_steps + 1, n_lines), np.nan),
               mode=_mode(lines, auto_threads(lines, threads) if auto else threads),
               linear=linear, kfe=np.zeros((6, 6)),
               kfe_every=max(1, int(round(stiffness_interval / body.dt))) if linear else 1,
               w6=np.zeros((3, 6)))
    fl = line_list(lines)
    # the started state's channels (row 0)
    record_lines(on, fl, fe.mode.recs)
    lanes = isinstance(fe.mode, LaneLines)
    n_total = n_steps + 1
    pieces = PROGRESS_PIECES if progress is not None else 1
    with numba_threads(fe.mode.threads):
        for p in range(pieces):
            n0 = n_total * p // pieces
            n1 = n_total * (p + 1) // pieces
            if n1 > n0 and lanes:
                td_fe_kernel_lanes(body, terms, moor, st, out, fe, fe_body, None, n0, n1)
            elif n1 > n0:
                td_fe_kernel(body, terms, moor, st, out, fe, fe_body, fl, n0, n1)
            if status[0] != 0:
                break
            if progress is not None:
                progress(min(n1, n_steps) * body.dt, n_steps * body.dt)
    if isinstance(fe.mode, LaneLines):
        store_lines(fe.mode, lines)
    fm.on[:] = on
    t_end = int(status[1]) * body.dt
    for ln in lines:
        ln.set_time(t_end)
    return status, fe.records


LANES = True
"""One thread: the FE lines of the body advance as SIMD lanes (:mod:`~floatmoor.mooring.fe.lanes_body`,
bit for bit the line-by-line kernel's numbers, faster: benchmarks/RESULTS.md) when they fit one
lane group (the same node count, options shared per block of four); False: line by line."""


def auto_threads(lines, pool: int) -> int:
    """The threads of ``solver: {threads: auto}`` for the FE lines ``lines`` with ``pool``
    threads available: one when the lines fit one lane group (:func:`lanes_fit`; on one thread
    they then advance as SIMD lanes, which the lines in two threads no longer beat: the
    flagship's 3600 s, benchmarks/RESULTS.md, "FE lanes vectorised"), else the whole pool."""
    if LANES and lanes_fit(lines):
        return 1
    return max(1, int(pool))


def _mode(lines, threads: int):
    """The mode bundle of :func:`~floatmoor.mooring.fe.multi.advance_lines`: threads, lanes
    (:data:`LANES`) or the lines one after the other."""
    mode = lines_mode(len(lines), threads)
    if LANES and mode.threads == 1 and lanes_fit(lines):
        return lanes_mode(lines, mode.recs)
    return mode


PROGRESS_PIECES = 20
"""Pieces a coupled FE storm runs in when progress is reported (a line per 5 % of the run)."""


GOMP_SPINCOUNT = "100000"
"""How long a waiting OpenMP thread of the FE lines spins before it sleeps (libgomp's
``GOMP_SPINCOUNT``) when the cores are idle.  The threads meet twice per body step (~0.3 ms
of line work, ~0.06 ms of body work between): sleeping threads (``OMP_WAIT_POLICY=PASSIVE``)
wake too late and made two threads no faster than one on an idle machine, while a bounded
spin covers the body work (2 threads 1.57x faster than one); but with other processes busy on
the cores a spinning thread holds a core its partner needs (one 900 s run 8x slower than with
one thread), so there the threads sleep (benchmarks/RESULTS.md, "FE lines in threads on an
idle machine")."""


def idle_cores(sample: float = 0.1) -> float | None:
    """Idle cores of the machine over ``sample`` seconds (from ``/proc/stat``: idle and iowait
    time over all time, times the cores), or None where that cannot be read."""
    import os
    import time

    def read():
        with open("/proc/stat") as f:
            v = [float(x) for x in f.readline().split()[1:]]
        return sum(v), v[3] + (v[4] if len(v) > 4 else 0.0)

    try:
        t0, i0 = read()
        time.sleep(sample)
        t1, i1 = read()
    except (OSError, ValueError, IndexError):
        return None
    if t1 <= t0:
        return None
    return (i1 - i0) / (t1 - t0) * (os.cpu_count() or 1)


def wait_policy(n: int, idle: float | None) -> tuple[str, str]:
    """The OpenMP setting for ``n`` threads with ``idle`` cores free (None: unknown):
    ``("GOMP_SPINCOUNT", GOMP_SPINCOUNT)`` when the threads find idle cores (all but a quarter
    of a core), else ``("OMP_WAIT_POLICY", "PASSIVE")``."""
    if idle is not None and idle >= n - 0.25:
        return "GOMP_SPINCOUNT", GOMP_SPINCOUNT
    return "OMP_WAIT_POLICY", "PASSIVE"


@contextmanager
def numba_threads(n: int):
    """numba's thread count ``n`` inside the block (of this thread), the previous one after it;
    nothing for one thread (the serial kernels do not use the pool).  Before numba starts its
    threads (the first call in a process), unless the environment chooses a wait policy itself
    (``OMP_WAIT_POLICY`` or ``GOMP_SPINCOUNT``), it gets the one of :func:`wait_policy` for the
    cores idle at that moment (:func:`idle_cores`, 0.1 s; decided once per process: libgomp
    reads it when it loads)."""
    n = int(n)
    if n <= 1:
        yield
        return
    import os

    import numba
    if "OMP_WAIT_POLICY" not in os.environ and "GOMP_SPINCOUNT" not in os.environ:
        key, value = wait_policy(n, idle_cores())
        os.environ[key] = value
    before = numba.get_num_threads()
    numba.set_num_threads(min(n, int(numba.config.NUMBA_NUM_THREADS)))
    try:
        yield
    finally:
        numba.set_num_threads(before)


def raise_fe_status(c: FECoupling, status) -> None:
    """NumericalError for a failed FE step (status 5), naming time, line, node and remedy
    (:meth:`FELine.step_error`, with the coupled run's remedy for a failed Newton iteration)."""
    if int(status[0]) != STATUS_FE:
        return
    ln = c.mooring.lines[int(status[2])]
    code = int(status[3])
    remedy = None
    if code in (-1, -2, -3):
        remedy = (f"reduce dt or set mooring.finite_element.dt (line steps per body step; the "
                  f"step was already halved {FELine.MAX_SPLIT} times), add elements, or check "
                  "for a slack line hit by a snap load")
    raise ln.step_error(code, remedy=remedy, coupled=True)

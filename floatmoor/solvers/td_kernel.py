"""The numba time loop of the coupled 6-DOF time-domain solver (one kernel, no allocation).

Equation of motion (Wang (2016) eq. 2.56; Cummins form) for the pose ``x`` = [x, y, z, roll,
pitch, yaw] of the body reference point and its velocity ``nu`` in the yaw-following frame
(``x'`` = [Rz(yaw) nu_xy, nu_z, nu_roll, nu_pitch, nu_yaw], small roll and pitch):

    (M + A_inf) nu' + c(nu) = T' (F_0 - C x) + T' F_moor(x) - D_l nu - D_q nu|nu|
        - int_0^t K(t - s) nu(s) ds + T' (F_wave1 + F_drift + F_wind + F_current + ...)

with P = (M + A_inf) nu, c = [-r P_sway, r P_surge, 0, 0, 0, u P_sway - v P_surge] the terms of
the frame turning at the yaw rate r (no work, earth-frame horizontal momentum kept), and T'
turning earth-axis forces and moments into the yaw-following frame (the hydrostatic term is
formed directly in that frame).

Integrator: classical 4th-order Runge-Kutta with a fixed step ``dt``.  The precomputed series
(waves, drift, wind speed) are sampled every dt/2 so every stage reads an exact sample.  The
convolution is the trapezoidal rule on the step grid; at a stage time t_n + c dt the history
velocities are interpolated linearly between the step values, which splits it into
``dt [K_0 v_stage / 2 + (1 - c) S_n + c S_{n+1}]`` with ``S_n = sum_{j>=1} K_j v_{n-j}``: one
new sum per step (S_{n+1} is the next step's S_n), kept in a ring buffer of past velocities.
Order: 4 for the instantaneous forces, 2 for the memory term (measured: the max offset and
tension of the Floatel-like 3-hour storm converge at about second order, 0.07 % error at
dt = 0.1 s, benchmarks/RESULTS.md).  Stability: RK4 is stable for oscillatory modes up to
omega dt = 2.83 (imaginary axis); the solver checks omega_max dt of the linearised system
(inertia M + A_inf, hydrostatics + mooring stiffness) before running.

Why RK4: every force here (quasi-static catenaries, relative-velocity wind and current,
quadratic damping) is an explicit function of the state, so an explicit method needs no
equilibrium iterations or Jacobians per step; rigid-body modes of moored floaters have periods
above ~5 s, so dt = 0.1 s is far inside the stability limit and the step is set by accuracy
(wave periods), where a 4th-order method is cheap.  Implicit Newmark-type schemes pay off only
for stiff FE line models (not used with quasi-static lines).

The forces are summed by kind of term (:mod:`floatmoor.forces.terms`): the kernel loops over
the kinds in a fixed order and over each kind's terms, writing one row of ``parts`` per term;
the total force is the sum of the rows in that order.  The kernels take the bundles of
:mod:`floatmoor.forces.terms` and :mod:`floatmoor.solvers.td_bundles`.

Opt-in approximations (scene ``solver:``, :mod:`floatmoor.io.solver_section`; the default is
the exact path above): a :class:`~.td_bundles.PredictorLines` bundle (``lines.step_tol`` > 0)
takes the predictor-corrector catenary solves of :mod:`floatmoor.mooring.catenary_step` (the
predictor alone at stage 2; :func:`line_forces` chooses on the bundle's type, so the kernel of
an exact run has no predictor-corrector code), ``memory.ss`` the
recursive history sum of :mod:`floatmoor.hydro.memory_fit` instead of the convolution sum.

Structure of a step (:func:`td_steps`): line failures and the convolution sum, the first
stage at t_n (:func:`_stage`), the record and its tension guard (:func:`_record`), the rest of
the RK4 step (:func:`rk4_step`), the state guards (:func:`_state_status`) and the velocity
history.  Status codes (named constants, :data:`STATUS_NAMES`) in ``status[0]``, the step in
``status[1]``, the DOF or line in ``status[2]``.  The helpers of a step are compiled inline
(``inline='always'``, numba IR): as separate functions taking the bundles each one cost a full
compilation with its Python wrapper (+40 % compile time of the first run, measured), inline
they cost what the one loop did before; they stay callable on their own from Python.
"""

from __future__ import annotations

import math

from numba import njit
from numba.extending import overload

from ..forces.kernels import relative_flow_force_into, turn_horizontal
from ..forces.slender_kernels import strips_into
from ..mooring.catenary import OUT_HA, OUT_HF, OUT_VA, OUT_VF
from ..mooring.catenary_step import system_force_step_kernel
from ..mooring.fibre_system import fibre_step
from ..mooring.system import system_force_kernel
from .td_bundles import PredictorLines, new_state

__all__ = ["td_kernel", "td_steps", "rk4_step", "start_state", "STATUS_OK", "STATUS_NAN",
           "STATUS_GUARD", "STATUS_TENSION", "STATUS_CATENARY", "STATUS_NAMES"]

INTERNAL = dict(no_cpython_wrapper=True, no_cfunc_wrapper=True, _nrt=False)
"""numba options of the kernels called only from compiled code (:func:`_rhs`, :func:`_accel`,
the choice of :func:`line_forces`): no Python or C wrapper (unboxing the bundles' ~70 arrays
was 2,000 lines of LLVM IR per wrapper), and no reference counting (``_nrt=False``: the kernels
allocate nothing and only borrow their arguments; with it, every use of a bundle counted the
references of all its arrays, 1,700 calls and 20,000 ``extractvalue`` in the unoptimised IR of
:func:`td_steps`, which LLVM then spent seconds removing).  Same arithmetic; numba refuses to
compile an allocation under ``_nrt=False``, so an allocation added later fails loudly."""

STATUS_OK = 0
"""Every step done."""
STATUS_NAN = 1
"""NaN or inf in the state (``status[2]`` the DOF)."""
STATUS_GUARD = 2
"""A DOF beyond its guard limit |x - x0| > guard (``status[2]`` the DOF)."""
STATUS_TENSION = 3
"""A line tension beyond ``tension_guard`` x MBS (``status[2]`` the line)."""
STATUS_CATENARY = 4
"""A catenary solve failed (``status[2]`` the line)."""
STATUS_NAMES = {STATUS_OK: "ok", STATUS_NAN: "nan", STATUS_GUARD: "guard",
                STATUS_TENSION: "tension", STATUS_CATENARY: "catenary"}


@njit(cache=True, inline='always')
def set_status(status, code, step, index):
    """``status[:3] = code, step, index``."""
    status[0] = code
    status[1] = step
    status[2] = index


@njit(cache=True, **INTERNAL)
def _rhs(j, c, dt, x, v, terms, lines, st, stage=0):
    """Total force ``st.f`` (6,) and the force of every term ``st.parts`` (n_terms, 6), earth
    axes (moments about the displaced reference point), at sample j (time j dt/2), stage
    fraction c, pose ``x`` and yaw-frame velocity ``v``: the kinds in the order of
    :data:`floatmoor.forces.terms.KINDS`, each over its terms.  ``st.mcorr`` is added to the
    mooring force when ``st.has_mcorr`` (the dynamic part of coupled FE lines,
    :mod:`floatmoor.solvers.fe_coupling`), and with ``st.has_mlin`` also
    ``st.mlin @ (x - st.mref)`` (their linearised stage variation, ``fe_stages: linear``).  Returns -1, or the index of a line whose catenary
    failed.  ``stage`` the RK4 stage (0-3): with the predictor-corrector catenaries
    (:class:`~.td_bundles.PredictorLines`) stage 2 takes the predictor alone (its pose is within millimetres
    of stage 1's, :func:`floatmoor.mooring.catenary_step.system_force_step_kernel`)."""
    parts = st.parts
    cy = math.cos(x[5])
    sy = math.sin(x[5])
    for p in range(parts.shape[0]):
        for k in range(6):
            parts[p, k] = 0.0
    r = 0
    # restoring: constant and matrix on the pose, yaw-following frame (roll and pitch are
    # about its axes), then to earth
    rest = terms.restoring
    for t in range(rest.matrix.shape[0]):
        for i in range(6):
            s = rest.const[t, i]
            for k in range(6):
                s -= rest.matrix[t, i, k] * x[k]
            parts[r, i] = s
        turn_horizontal(parts[r], cy, sy)
        r += 1
    # mooring (earth axes)
    if lines.on:
        bad = line_forces(j, x, lines, st, stage)
        if bad >= 0:
            return bad
        for i in range(6):
            parts[r, i] = st.fm[i]
        if st.has_mcorr:
            for i in range(6):
                parts[r, i] += st.mcorr[i]
            if st.has_mlin:
                mlin = st.mlin
                mref = st.mref
                for i in range(6):
                    s = 0.0
                    for k in range(6):
                        s += mlin[i, k] * (x[k] - mref[k])
                    parts[r, i] += s
        r += 1
    # damping on the yaw-frame velocities: linear, then quadratic
    dl = terms.damping.matrix
    for t in range(dl.shape[0]):
        for i in range(6):
            s = 0.0
            for k in range(6):
                s += dl[t, i, k] * v[k]
            parts[r, i] = -s
        turn_horizontal(parts[r], cy, sy)
        r += 1
    dq = terms.quadratic_damping.matrix
    for t in range(dq.shape[0]):
        for i in range(6):
            s = 0.0
            for k in range(6):
                s += dq[t, i, k] * v[k] * abs(v[k])
            parts[r, i] = -s
        turn_horizontal(parts[r], cy, sy)
        r += 1
    # radiation memory on the yaw-frame velocity history
    mem = terms.memory
    if mem.on:
        n_pairs = mem.i.shape[0]
        for p in range(n_pairs):
            i = mem.i[p]
            jj = mem.j[p]
            parts[r, i] -= dt * (0.5 * mem.kernel[p, 0] * v[jj] + (1.0 - c) * st.s0[p]
                                 + c * st.s1[p])
        if n_pairs > 0:
            turn_horizontal(parts[r], cy, sy)
        r += 1
    # relative flow (wind, current): relative to the earth velocity of the reference point,
    # less the linear wave-frequency velocity when given (the low-frequency velocity, Wang
    # (2016) eq. 2.24, 2.26)
    flow = terms.flow
    vx = cy * v[0] - sy * v[1]
    vy = sy * v[0] + cy * v[1]
    if flow.has_wf:
        vx -= flow.wf_velocity[j, 0]
        vy -= flow.wf_velocity[j, 1]
    for t in range(flow.heading.shape[0]):
        nh = flow.n_heading[t]
        js = j if flow.varies[t] else 0
        relative_flow_force_into(flow.speed[t, js], flow.heading[t], vx, vy, x[5], 1.0,
                                 flow.table_heading[t, :nh], flow.table[t, :nh], st.coef,
                                 parts[r])
        r += 1
    # low-frequency damping (wave drift damping): earth axes, on the pose rate less the linear
    # wave-frequency velocity when given
    lfd = terms.lf_damping
    for t in range(lfd.matrix.shape[0]):
        for i in range(6):
            s = 0.0
            for k in range(6):
                if k == 0:
                    qk = cy * v[0] - sy * v[1]
                elif k == 1:
                    qk = sy * v[0] + cy * v[1]
                else:
                    qk = v[k]
                if lfd.has_wf:
                    qk -= lfd.wf_velocity[j, k]
                s += lfd.matrix[t, i, k] * qk
            parts[r, i] = -s
        r += 1
    # strips (slender elements): drag with the total body velocity (Wang (2016) eq. 6.7-6.8)
    sl = terms.strips
    if sl.on:
        strips_into(j, x, v, sl, st.rot, st.sl_sc, parts[r])
        r += 1
    # precomputed series
    series = terms.series
    for q in range(series.shape[0]):
        for i in range(6):
            parts[r, i] = series[q, j, i]
        r += 1
    f = st.f
    for i in range(6):
        s = 0.0
        for p in range(r):
            s += parts[p, i]
        f[i] = s
    return -1


@njit(cache=True, inline='always')
def _exact_line_forces(j, x, lines, st):
    """The exact catenary solves of :func:`line_forces`."""
    cat = lines.cat
    # want_k typed bool like the statics' calls (a literal False would compile a second
    # specialisation of system_force_kernel); j >= 0, so it is False
    want_k = j < 0
    return system_force_kernel(x, cat.anchors, cat.fairleads, cat.seg_L, cat.seg_EA,
                               cat.seg_w, cat.seg_P, cat.line_start, cat.cb, cat.seabed,
                               lines.active, lines.warm, want_k, st.work, st.rot, st.line_out,
                               st.fm, st.stiff)


@njit(cache=True, inline='always')
def _predictor_line_forces(x, lines, st, stage):
    """The predictor-corrector catenary solves of :func:`line_forces`."""
    cat = lines.cat
    return system_force_step_kernel(x, cat.anchors, cat.fairleads, cat.seg_L, cat.seg_EA,
                                    cat.seg_w, cat.seg_P, cat.line_start, cat.cb, cat.seabed,
                                    lines.active, lines.warm, lines.step_tol, stage == 2,
                                    st.work, st.rot, st.line_out, st.fm)


def line_forces(j, x, lines, st, stage):
    """Mooring force ``st.fm`` (and ``st.line_out``) of the quasi-static lines at pose ``x``:
    the exact catenary solves for a :class:`~.td_bundles.Lines` bundle, the predictor-corrector
    solves for a :class:`~.td_bundles.PredictorLines` one (stage 2 the predictor alone).
    Returns -1 or the index of a line whose catenary failed.  Compiled, the choice is made on
    the bundle's type (:func:`_line_forces_typed`): the time loop of an exact run neither
    contains nor compiles the predictor-corrector code."""
    if isinstance(lines, PredictorLines):
        return _predictor_line_forces(x, lines, st, stage)
    return _exact_line_forces(j, x, lines, st)


@overload(line_forces, jit_options=INTERNAL)
def _line_forces_typed(j, x, lines, st, stage):
    cls = getattr(lines, "instance_class", None)
    if cls is not None and issubclass(cls, PredictorLines):
        def predictor(j, x, lines, st, stage):
            return _predictor_line_forces(x, lines, st, stage)
        return predictor

    def exact(j, x, lines, st, stage):
        return _exact_line_forces(j, x, lines, st)
    return exact



@njit(cache=True, **INTERNAL)
def _accel(x, v, f, inertia, minv, mom, g, a):
    """Yaw-frame acceleration ``a`` from the earth-axis force ``f``: turn it into the
    yaw-following frame and solve (M + A_inf) a = f_h - c with the generalized momentum
    P = (M + A_inf) v and the terms of the frame turning at the yaw rate r = v[5]:
    c_surge = -r P_sway, c_sway = r P_surge, c_yaw = u P_sway - v P_surge (the Munk moment of
    the horizontal velocity (u, v) and momentum).  They do no work (v . c = 0) and keep the
    earth-frame horizontal momentum; heave, roll and pitch keep the linear seakeeping form
    (small rotations).  ``mom``, ``g`` (6,) scratch."""
    cy = math.cos(x[5])
    sy = math.sin(x[5])
    for i in range(6):
        g[i] = f[i]
    turn_horizontal(g, cy, -sy)
    for i in range(6):
        s = 0.0
        for k in range(6):
            s += inertia[i, k] * v[k]
        mom[i] = s
    r = v[5]
    g[0] += r * mom[1]
    g[1] -= r * mom[0]
    g[5] -= v[0] * mom[1] - v[1] * mom[0]
    for i in range(6):
        s = 0.0
        for k in range(6):
            s += minv[i, k] * g[k]
        a[i] = s


@njit(cache=True)
def _pose_rate(x, v, out):
    """Pose rate from the yaw-frame velocity: horizontal velocity turned by yaw; heave and the
    (small-angle) roll, pitch and yaw rates as they are."""
    cy = math.cos(x[5])
    sy = math.sin(x[5])
    out[0] = cy * v[0] - sy * v[1]
    out[1] = sy * v[0] + cy * v[1]
    for k in range(2, 6):
        out[k] = v[k]


@njit(cache=True, inline='always')
def _stage(j, c, x, v, k, body, terms, lines, st):
    """Stage ``k`` of RK4 at sample j, fraction c, state (x, v): the force (``st.f``,
    ``st.parts``), the pose rate ``st.q[k]`` and the acceleration ``st.a[k]``.  Returns -1 or
    the index of a line whose catenary failed."""
    bad = _rhs(j, c, body.dt, x, v, terms, lines, st, k)
    if bad >= 0:
        return bad
    _pose_rate(x, v, st.q[k])
    _accel(x, v, st.f, body.inertia, body.minv, st.mom, st.g, st.a[k])
    return -1


@njit(cache=True, inline='always')
def rk4_step(n, body, terms, lines, st):
    """Stages 2, 3 and 4 (at t + dt/2, t + dt/2 and t + dt: force samples 2n+1, 2n+1, 2n+2)
    and the update of ``st.x``, ``st.v`` to t_{n+1}, the first stage at t_n being evaluated
    (:func:`_stage` with k = 0, whose forces the caller records).  Returns -1 or the index of
    a line whose catenary failed."""
    dt = body.dt
    x = st.x
    v = st.v
    xs = st.xs
    vs = st.vs
    q = st.q
    a = st.a
    for k in range(1, 4):
        c = 0.5
        j = 2 * n + 1
        if k == 3:
            c = 1.0
            j = 2 * n + 2
        for i in range(6):
            xs[i] = x[i] + c * dt * q[k - 1, i]
            vs[i] = v[i] + c * dt * a[k - 1, i]
        bad = _stage(j, c, xs, vs, k, body, terms, lines, st)
        if bad >= 0:
            return bad
    for i in range(6):
        x[i] += dt / 6.0 * (q[0, i] + 2.0 * q[1, i] + 2.0 * q[2, i] + q[3, i])
        v[i] += dt / 6.0 * (a[0, i] + 2.0 * a[1, i] + 2.0 * a[2, i] + a[3, i])
    return -1


@njit(cache=True, inline='always')
def _fail_lines(t, lines):
    """Lines whose failure time is reached at ``t`` become inactive."""
    if lines.on:
        for i in range(lines.active.shape[0]):
            if lines.active[i] and t >= lines.fail_time[i]:
                lines.active[i] = False


@njit(cache=True, inline='always')
def _memory_sum(n, mem, st):
    """Convolution sum S_{n+1} = sum_{j=1}^{n_k-1} K_j v_{n+1-j} into ``st.s1``; the history
    is stored twice (columns p and p + n_k) so that the window is contiguous without a
    modulo.  With ``mem.ss`` the recursion of the fitted exponentials instead (called once
    per step n, ``st.v`` = v_n)."""
    n_pairs = mem.i.shape[0]
    if mem.ss:
        # recursive history sum (floatmoor.hydro.memory_fit): y <- z (v_n + y), S = Re(c y)
        for p in range(n_pairs):
            vj = st.v[mem.j[p]]
            s = 0.0
            for r in range(mem.ss_z.shape[1]):
                y = mem.ss_z[p, r] * (vj + mem.ss_y[p, r])
                mem.ss_y[p, r] = y
                s += (mem.ss_c[p, r] * y).real
            st.s1[p] = s
        return
    hist = st.hist
    n_k = hist.shape[1] // 2
    b = (n + 1) % n_k + n_k
    kernel = mem.kernel
    # four pairs at a time in four independent sums (each summed in the same order as one
    # pair alone, so the same bits; the one-pair loop waits on its adder, 2x slower)
    p = 0
    while p + 4 <= n_pairs:
        k0 = kernel[p]
        k1 = kernel[p + 1]
        k2 = kernel[p + 2]
        k3 = kernel[p + 3]
        h0 = hist[mem.j[p]]
        h1 = hist[mem.j[p + 1]]
        h2 = hist[mem.j[p + 2]]
        h3 = hist[mem.j[p + 3]]
        s0 = 0.0
        s1 = 0.0
        s2 = 0.0
        s3 = 0.0
        for m in range(1, n_k):
            c = b - m
            s0 += k0[m] * h0[c]
            s1 += k1[m] * h1[c]
            s2 += k2[m] * h2[c]
            s3 += k3[m] * h3[c]
        st.s1[p] = s0
        st.s1[p + 1] = s1
        st.s1[p + 2] = s2
        st.s1[p + 3] = s3
        p += 4
    while p < n_pairs:
        k0 = kernel[p]
        h0 = hist[mem.j[p]]
        s = 0.0
        for m in range(1, n_k):
            s += k0[m] * h0[b - m]
        st.s1[p] = s
        p += 1


@njit(cache=True, inline='always')
def _push_history(n1, st):
    """Step velocity ``st.v`` at step n1 into the ring buffer; S_{n1} becomes the sum of the
    step (``s0 = s1``)."""
    hist = st.hist
    n_k = hist.shape[1] // 2
    c0 = n1 % n_k
    for k in range(6):
        hist[k, c0] = st.v[k]
        hist[k, c0 + n_k] = st.v[k]
    for p in range(st.s0.shape[0]):
        st.s0[p] = st.s1[p]


@njit(cache=True, inline='always')
def _record(n, body, lines, st, out):
    """Row ``n`` of the outputs from the first stage at t_n (pose, pose rate, line tensions,
    the force of every term).  Returns -1, or the first line whose fairlead tension exceeds
    ``tension_guard`` x MBS (nothing recorded after it)."""
    x = st.x
    for k in range(6):
        out.motion[n, k] = x[k]
        out.velocity[n, k] = st.q[0, k]
    line_out = st.line_out
    for i in range(line_out.shape[0]):
        tf = math.sqrt(line_out[i, OUT_HF] ** 2 + line_out[i, OUT_VF] ** 2)
        out.t_fair[n, i] = tf
        out.t_anchor[n, i] = math.sqrt(line_out[i, OUT_HA] ** 2 + line_out[i, OUT_VA] ** 2)
        if tf > body.tension_guard * lines.mbs[i]:
            return i
    r = n if body.record_parts else 0
    parts = st.parts
    for p in range(parts.shape[0]):
        for k in range(6):
            out.parts[r, p, k] = parts[p, k]
    return -1


@njit(cache=True, inline='always')
def _state_status(x, v, x0, guard):
    """(code, DOF) of the first DOF with a NaN/inf state (STATUS_NAN) or beyond its guard
    (STATUS_GUARD); (STATUS_OK, -1) when none."""
    for k in range(6):
        if not (math.isfinite(x[k]) and math.isfinite(v[k])):
            return STATUS_NAN, k
        if abs(x[k] - x0[k]) > guard[k]:
            return STATUS_GUARD, k
    return STATUS_OK, -1


@njit(cache=True, no_cfunc_wrapper=True, _nrt=False)
def td_steps(n_first, n_last, body, terms, lines, st, out):
    """Steps ``n_first .. n_last - 1`` of the loop of :func:`td_kernel` (resumable: the state
    is carried in ``st`` and the line states in ``lines``).

    Step ``n``: line failures, the convolution sum, the first stage at ``t_n = n dt``, the
    record of row ``n``, with fibre ropes the update of their slowly varying tensions and
    linearised segments (:func:`~floatmoor.mooring.fibre_system.fibre_track_update`, only when
    ``lines.fibre.on``), then (unless ``n == body.n_steps``) the rest of the RK4 step to
    ``t_{n+1}`` and the state guards.  Bundles: ``body`` :class:`~.td_bundles.Body`, ``terms``
    :class:`~floatmoor.forces.terms.ForceTerms`, ``lines`` :class:`~.td_bundles.Lines`, ``st``
    :class:`~.td_bundles.State`, ``out`` :class:`~.td_bundles.Outputs`.  On failure sets
    ``out.status`` (code, step, DOF or line) and returns.
    """
    status = out.status
    for n in range(n_first, n_last):
        _fail_lines(n * body.dt, lines)
        _memory_sum(n, terms.memory, st)
        # stage 0 as a typed int (n - n): a literal 0 would compile a second _rhs
        bad = _stage(2 * n, 0.0, st.x, st.v, n - n, body, terms, lines, st)
        if bad >= 0:
            set_status(status, STATUS_CATENARY, n, bad)
            return
        bad = _record(n, body, lines, st, out)
        if bad >= 0:
            set_status(status, STATUS_TENSION, n, bad)
            return
        fibre_step(lines.fibre, lines.cat, lines.active, st.line_out)
        if n == body.n_steps:
            break
        bad = rk4_step(n, body, terms, lines, st)
        if bad >= 0:
            set_status(status, STATUS_CATENARY, n, bad)
            return
        code, k = _state_status(st.x, st.v, body.x0, body.guard)
        if code != STATUS_OK:
            set_status(status, code, n + 1, k)
            return
        _push_history(n + 1, st)


@njit(cache=True)
def start_state(x0, v0, x, v, hist):
    """Start state from pose ``x0`` and pose rate ``v0``: ``x`` the pose, ``v`` the yaw-frame
    velocity (horizontal velocity turned; roll/pitch rates are already about the yaw-following
    axes); the history ring buffer ``hist`` starts with it."""
    for k in range(6):
        x[k] = x0[k]
        v[k] = v0[k]
    cy0 = math.cos(x[5])
    sy0 = math.sin(x[5])
    v[0] = cy0 * v0[0] + sy0 * v0[1]
    v[1] = -sy0 * v0[0] + cy0 * v0[1]
    n_k = hist.shape[1] // 2
    for k in range(6):
        hist[k, 0] = v[k]
        hist[k, n_k] = v[k]


def new_run_state(body, terms, lines, out, *, has_mcorr: bool = False,
                  has_mlin: bool = False):
    """The :class:`~.td_bundles.State` of a run, at the start state of ``body``."""
    mem = terms.memory
    st = new_state(out.parts.shape[1], lines.cat.anchors.shape[0], mem.i.shape[0],
                   max(1, mem.kernel.shape[1]), has_mcorr=has_mcorr,
                   has_mlin=has_mlin)
    start_state(body.x0, body.v0, st.x, st.v, st.hist)
    mem.ss_y[...] = 0.0  # the state-space memory starts at rest, like the history
    return st


def td_kernel(body, terms, lines, out):
    """Integrate ``body.n_steps`` RK4 steps from pose ``body.x0`` and pose rate ``body.v0``;
    fill ``out`` (:class:`~.td_bundles.Outputs`) at every step; ``out.status`` the outcome.

    A Python function: the allocation and the start state are done here and the loop is one
    numba call (:func:`td_steps`), so the loop is compiled once (a numba wrapper around it
    would compile the step code a second time).
    """
    st = new_run_state(body, terms, lines, out)
    out.status[:] = 0
    td_steps(0, body.n_steps + 1, body, terms, lines, st, out)

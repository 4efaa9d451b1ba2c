"""The numba time loop of the coupled 6-DOF time-domain solver (one kernel, no allocation).

Equation of motion (seed 002 eq. 2.56; Cummins form) for the pose ``x`` = [x, y, z, roll,
pitch, yaw] of the body reference point and its velocity ``nu`` in the yaw-following frame
(``x'`` = [Rz(yaw) nu_xy, nu_z, nu_roll, nu_pitch, nu_yaw], small roll and pitch):

    (M + A_inf) nu' + c(nu) = T' (F_0 - C x) + T' F_moor(x) - D_l nu - D_q nu|nu|
        - int_0^t K(t - s) nu(s) ds + T' (F_wave1 + F_drift + F_wind + F_current)

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

Status codes returned in ``status[0]`` (``status[1]`` the step, ``status[2]`` the DOF or line):
0 ok, 1 NaN/inf in the state, 2 a DOF beyond its guard limit, 3 a line tension beyond
``tension_guard`` x MBS, 4 a catenary solve failed.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from ..forces.base import (PART_CURRENT, PART_DAMPING_LINEAR, PART_DAMPING_QUADRATIC,
                           PART_HYDROSTATICS, PART_MOORING, PART_RADIATION, PART_SERIES,
                           PART_SLENDER, PART_WIND)
from ..forces.kernels import relative_flow_force_into, turn_horizontal
from ..forces.slender_kernels import slender_packed_into
from ..mooring.catenary import OUT_HA, OUT_HF, OUT_VA, OUT_VF
from ..mooring.system import system_force_kernel

__all__ = ["td_kernel", "td_steps", "td_scratch", "start_state", "STATUS_OK", "STATUS_NAN", "STATUS_GUARD", "STATUS_TENSION",
           "STATUS_CATENARY"]

STATUS_OK, STATUS_NAN, STATUS_GUARD, STATUS_TENSION, STATUS_CATENARY = range(5)


@njit(cache=True)
def _rhs(j, c, dt, x, v, const_force, restoring, dl, has_dl, dq, has_dq, ret_kernel, ret_i,
         ret_j, s0, s1, series, has_wind, wind_speed, wind_heading, wind_th, wind_tab, has_cur,
         cur_speed, cur_heading, cur_th, cur_tab, has_vwf, v_wf,
         has_sl, sl_fel, sl_iel, sl_eta, sl_u, sl_a, sl_par, sl_cur, sl_ramp, sl_sc,
         has_moor, anchors, fairleads,
         seg_L, seg_EA, seg_w, seg_P, line_start, cb, seabed, active, warm, work, rot, line_out, fm, stiff, coef,
         has_mcorr, mcorr, parts, f):
    """Total force ``f`` (6,) and its parts (N_PARTS, 6), all in earth axes (moments about
    the displaced reference point), at sample j (time j dt/2), stage fraction c, pose ``x`` and
    yaw-frame velocity ``v``.  ``mcorr`` (6,) is added to the mooring force when ``has_mcorr``
    (the dynamic part of coupled FE lines, :mod:`floatmoor.solvers.fe_coupling`).  Returns -1,
    or the index of a line whose catenary failed."""
    cy = math.cos(x[5])
    sy = math.sin(x[5])
    for p in range(parts.shape[0]):
        for k in range(6):
            parts[p, k] = 0.0
    # hydrostatics (yaw-following frame: roll and pitch are about its axes), then to earth
    for i in range(6):
        s = const_force[i]
        for k in range(6):
            s -= restoring[i, k] * x[k]
        parts[PART_HYDROSTATICS, i] = s
    turn_horizontal(parts[PART_HYDROSTATICS], cy, sy)
    # mooring (earth axes)
    if has_moor:
        bad = system_force_kernel(x, anchors, fairleads, seg_L, seg_EA, seg_w, seg_P, line_start,
                                  cb, seabed, active, warm, False, work, rot, line_out, fm, stiff)
        if bad >= 0:
            return bad
        for i in range(6):
            parts[PART_MOORING, i] = fm[i]
        if has_mcorr:
            for i in range(6):
                parts[PART_MOORING, i] += mcorr[i]
    # damping on the yaw-frame velocities
    if has_dl:
        for i in range(6):
            s = 0.0
            for k in range(6):
                s += dl[i, k] * v[k]
            parts[PART_DAMPING_LINEAR, i] = -s
        turn_horizontal(parts[PART_DAMPING_LINEAR], cy, sy)
    if has_dq:
        for i in range(6):
            s = 0.0
            for k in range(6):
                s += dq[i, k] * v[k] * abs(v[k])
            parts[PART_DAMPING_QUADRATIC, i] = -s
        turn_horizontal(parts[PART_DAMPING_QUADRATIC], cy, sy)
    # radiation memory on the yaw-frame velocity history
    if ret_i.shape[0] > 0:
        for p in range(ret_i.shape[0]):
            i = ret_i[p]
            jj = ret_j[p]
            parts[PART_RADIATION, i] -= dt * (0.5 * ret_kernel[p, 0] * v[jj] + (1.0 - c) * s0[p]
                                              + c * s1[p])
        turn_horizontal(parts[PART_RADIATION], cy, sy)
    # wind and current: relative to the earth velocity of the reference point, less the linear
    # wave-frequency velocity when given (the low-frequency velocity, seed 002 eq. 2.24, 2.26)
    vx = cy * v[0] - sy * v[1]
    vy = sy * v[0] + cy * v[1]
    if has_vwf:
        vx -= v_wf[j, 0]
        vy -= v_wf[j, 1]
    if has_wind:
        relative_flow_force_into(wind_speed[j], wind_heading, vx, vy, x[5], 1.0, wind_th,
                                 wind_tab, coef, parts[PART_WIND])
    if has_cur:
        relative_flow_force_into(cur_speed, cur_heading, vx, vy, x[5], 1.0, cur_th, cur_tab,
                                 coef, parts[PART_CURRENT])
    # slender elements: drag strips with the total body velocity (seed 002 eq. 6.7-6.8)
    if has_sl:
        slender_packed_into(j, x, v, sl_fel, sl_iel, sl_eta, sl_u, sl_a, sl_par, sl_cur, sl_ramp,
                            rot, sl_sc, parts[PART_SLENDER])
    # precomputed series
    for q in range(series.shape[0]):
        for i in range(6):
            parts[PART_SERIES + q, i] = series[q, j, i]
    for i in range(6):
        s = 0.0
        for p in range(parts.shape[0]):
            s += parts[p, i]
        f[i] = s
    return -1


@njit(cache=True)
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


def td_kernel(n_steps, dt, inertia, minv, x0, v0, const_force, restoring, dl, has_dl, dq,
              has_dq, ret_kernel, ret_i, ret_j, hist, series, has_wind, wind_speed, wind_heading,
              wind_th, wind_tab, has_cur, cur_speed, cur_heading, cur_th, cur_tab, has_vwf, v_wf,
              has_sl, sl_fel, sl_iel, sl_eta, sl_u, sl_a, sl_par, sl_cur, sl_ramp, has_moor,
              anchors, fairleads, seg_L, seg_EA, seg_w, seg_P, line_start, cb, seabed, active,
              fail_time, mbs, warm, guard, tension_guard, record_parts, motion, velocity, t_fair,
              t_anchor, parts_out, status):
    """Integrate ``n_steps`` RK4 steps from pose ``x0`` and pose rate ``v0``; fill the outputs
    at every step.

    ``inertia`` = M + A_inf and ``minv`` its inverse (6, 6), yaw-following frame.  Outputs:
    motion (pose) and velocity (pose rate) (n_steps+1, 6); t_fair, t_anchor (n_steps+1,
    n_lines) in N; parts_out (n_steps+1, N_PARTS, 6) (earth axes) when ``record_parts`` else
    (1, N_PARTS, 6) scratch; status (3,) int64.  ``hist`` (6, 2 n_k) ring buffer of the
    yaw-frame step velocities, stored twice (zeros on entry); ``guard`` (6,) largest
    |x - x0| allowed per DOF.  ``v_wf`` (n_samples, 6) the linear wave-frequency velocity
    (earth axes) removed from the body velocity in the wind and current relative velocity when
    ``has_vwf`` (else a (1, 6) dummy).

    A Python function: the allocation, the start state and the loop are three numba calls
    (:func:`td_scratch`, :func:`start_state`, :func:`td_steps`), so the loop is compiled once
    (a numba wrapper around it would compile the step code a second time).
    """
    (mcorr, s0, s1, parts, work, rot, line_out, fm, stiff, coef, sl_sc, xs, vs, f, mom, g, q,
     a) = td_scratch(parts_out.shape[1], anchors.shape[0], ret_i.shape[0])
    x = x0.copy()
    v = v0.copy()
    start_state(x0, v0, x, v, hist)
    status[0] = 0
    status[1] = 0
    status[2] = 0
    td_steps(0, n_steps + 1, n_steps, dt, inertia, minv, x0, const_force, restoring, dl, has_dl,
             dq, has_dq, ret_kernel, ret_i, ret_j, hist, series, has_wind, wind_speed,
             wind_heading, wind_th, wind_tab, has_cur, cur_speed, cur_heading, cur_th, cur_tab,
             has_vwf, v_wf, has_sl, sl_fel, sl_iel, sl_eta, sl_u, sl_a, sl_par, sl_cur, sl_ramp,
             has_moor, anchors, fairleads, seg_L, seg_EA, seg_w, seg_P, line_start, cb, seabed,
             active, fail_time, mbs, warm, guard, tension_guard, record_parts, motion, velocity,
             t_fair, t_anchor, parts_out, status, False, mcorr, x, v, s0, s1, parts, work, rot,
             line_out, fm, stiff, coef, sl_sc, xs, vs, f, mom, g, q, a)


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


@njit(cache=True)
def td_scratch(n_parts, n_lines, n_pairs):
    """Work arrays of :func:`td_steps` (allocated once per run, outside the step loop):
    ``(mcorr, s0, s1, parts, work, rot, line_out, fm, stiff, coef, sl_sc, xs, vs, f, mom, g, q,
    a)`` in the order of its arguments."""
    return (np.zeros(6), np.zeros(n_pairs), np.zeros(n_pairs), np.zeros((n_parts, 6)),
            np.zeros(64), np.zeros((3, 3)), np.zeros((n_lines, 10)), np.zeros(6),
            np.zeros((6, 6)), np.zeros(6), np.zeros(6), np.zeros(6), np.zeros(6), np.zeros(6),
            np.zeros(6), np.zeros(6), np.zeros((4, 6)), np.zeros((4, 6)))


@njit(cache=True)
def td_steps(n_first, n_last, n_steps, dt, inertia, minv, x0, const_force, restoring, dl, has_dl,
             dq, has_dq, ret_kernel, ret_i, ret_j, hist, series, has_wind, wind_speed,
             wind_heading, wind_th, wind_tab, has_cur, cur_speed, cur_heading, cur_th, cur_tab,
             has_vwf, v_wf, has_sl, sl_fel, sl_iel, sl_eta, sl_u, sl_a, sl_par, sl_cur, sl_ramp,
             has_moor, anchors, fairleads, seg_L, seg_EA, seg_w, seg_P, line_start, cb, seabed,
             active, fail_time, mbs, warm, guard, tension_guard, record_parts, motion, velocity,
             t_fair, t_anchor, parts_out, status, has_mcorr, mcorr, x, v, s0, s1, parts, work,
             rot, line_out, fm, stiff, coef, sl_sc, xs, vs, f, mom, g, q, a):
    """Steps ``n_first .. n_last - 1`` of the loop of :func:`td_kernel` (resumable: the state
    ``x, v, hist, s0`` and the line states ``active, warm`` are carried in the arrays).

    Step ``n``: record the outputs at ``t_n = n dt`` (row ``n``), then (unless ``n ==
    n_steps``) one RK4 step to ``t_{n+1}``.  ``mcorr`` (6,), when ``has_mcorr``, is added to the
    mooring force at every stage of these steps (held constant).  Sets ``status`` and returns on
    failure.  The remaining arguments are scratch arrays (:func:`td_scratch`).
    """
    n_parts = parts_out.shape[1]
    n_lines = anchors.shape[0]
    n_pairs = ret_i.shape[0]
    n_k = hist.shape[1] // 2
    for n in range(n_first, n_last):
        t = n * dt
        if has_moor:
            for i in range(n_lines):
                if active[i] and t >= fail_time[i]:
                    active[i] = False
        # convolution sum S_{n+1} = sum_{j=1}^{n_k-1} K_j v_{n+1-j}; the history is stored
        # twice (columns p and p + n_k) so that the window is contiguous without a modulo
        b = (n + 1) % n_k + n_k
        for p in range(n_pairs):
            jj = ret_j[p]
            s = 0.0
            for m in range(1, n_k):
                s += ret_kernel[p, m] * hist[jj, b - m]
            s1[p] = s
        # stage 1 (also the record at t_n)
        bad = _rhs(2 * n, 0.0, dt, x, v, const_force, restoring, dl, has_dl, dq, has_dq,
                   ret_kernel, ret_i, ret_j, s0, s1, series, has_wind, wind_speed, wind_heading,
                   wind_th, wind_tab, has_cur, cur_speed, cur_heading, cur_th, cur_tab, has_vwf,
                   v_wf, has_sl, sl_fel, sl_iel, sl_eta, sl_u, sl_a, sl_par, sl_cur, sl_ramp, sl_sc,
                   has_moor, anchors, fairleads, seg_L, seg_EA, seg_w, seg_P, line_start, cb, seabed,
                   active, warm, work, rot, line_out, fm, stiff, coef, has_mcorr, mcorr, parts, f)
        if bad >= 0:
            status[0] = 4
            status[1] = n
            status[2] = bad
            return
        _pose_rate(x, v, q[0])
        for k in range(6):
            motion[n, k] = x[k]
            velocity[n, k] = q[0, k]
        for i in range(n_lines):
            tf = math.sqrt(line_out[i, OUT_HF] ** 2 + line_out[i, OUT_VF] ** 2)
            t_fair[n, i] = tf
            t_anchor[n, i] = math.sqrt(line_out[i, OUT_HA] ** 2 + line_out[i, OUT_VA] ** 2)
            if tf > tension_guard * mbs[i]:
                status[0] = 3
                status[1] = n
                status[2] = i
                return
        r = n if record_parts else 0
        for p in range(n_parts):
            for k in range(6):
                parts_out[r, p, k] = parts[p, k]
        if n == n_steps:
            break
        _accel(x, v, f, inertia, minv, mom, g, a[0])
        # stages 2, 3 and 4: at t + dt/2, t + dt/2 and t + dt (force samples 2n+1, 2n+1, 2n+2)
        for st in range(1, 4):
            c = 0.5
            j = 2 * n + 1
            if st == 3:
                c = 1.0
                j = 2 * n + 2
            for k in range(6):
                xs[k] = x[k] + c * dt * q[st - 1, k]
                vs[k] = v[k] + c * dt * a[st - 1, k]
            bad = _rhs(j, c, dt, xs, vs, const_force, restoring, dl,
                       has_dl, dq, has_dq, ret_kernel, ret_i, ret_j, s0, s1, series, has_wind,
                       wind_speed, wind_heading, wind_th, wind_tab, has_cur, cur_speed,
                       cur_heading, cur_th, cur_tab, has_vwf, v_wf, has_sl, sl_fel, sl_iel, sl_eta,
                       sl_u, sl_a, sl_par, sl_cur, sl_ramp, sl_sc, has_moor, anchors, fairleads,
                       seg_L, seg_EA, seg_w, seg_P, line_start, cb, seabed, active, warm, work,
                       rot, line_out, fm, stiff, coef, has_mcorr, mcorr, parts, f)
            if bad >= 0:
                status[0] = 4
                status[1] = n
                status[2] = bad
                return
            _pose_rate(xs, vs, q[st])
            _accel(xs, vs, f, inertia, minv, mom, g, a[st])
        for k in range(6):
            x[k] += dt / 6.0 * (q[0, k] + 2.0 * q[1, k] + 2.0 * q[2, k] + q[3, k])
            v[k] += dt / 6.0 * (a[0, k] + 2.0 * a[1, k] + 2.0 * a[2, k] + a[3, k])
        for k in range(6):
            if not (math.isfinite(x[k]) and math.isfinite(v[k])):
                status[0] = 1
                status[1] = n + 1
                status[2] = k
                return
            if abs(x[k] - x0[k]) > guard[k]:
                status[0] = 2
                status[1] = n + 1
                status[2] = k
                return
        c0 = (n + 1) % n_k
        for k in range(6):
            hist[k, c0] = v[k]
            hist[k, c0 + n_k] = v[k]
        for p in range(n_pairs):
            s0[p] = s1[p]

"""All FE lines of one body in one numba call per body step (:class:`FEMooring` fast path).

The per-line Python work of :meth:`FELine.advance` (argument checks, ~45 arguments unboxed per
numba call, end forces, copies on accept) was about 40 % of the time of a 12-line storm.  Here
the fairlead kinematics, the generalised-alpha advance of every line (:func:`kernels.ga_advance`,
unchanged), the end forces and their generalised force on the body are one call
(:func:`body_advance`), and :func:`body_accept` commits every line.  The per-line arrays are
the lines' own (numba typed lists hold references: no copies), so every :class:`FELine` stays
valid for its other methods.
"""

from __future__ import annotations

import numpy as np
from numba import njit

from ...core.frames import rotation_matrix_into
from .kernels import ga_advance

__all__ = ["body_advance", "body_accept", "add_line_wrench"]


@njit(cache=True)
def body_advance(t1, dt, nsub, max_split, pose, vel, fair_b, R, rf_all, vf_all, arm, Q, forces,
                 fail, on, counters, r, v, a, fn, fs, rA, vA, aA, fnA, fs1, rB, vB, aB, fA, rfk,
                 vfk, P, E, S, cur_z, cur_u, wk, fric, coef, tol, maxit, q, tens, Mb, Dg, Of, BX,
                 Rk, W, Yk, T1, da, info, stats):
    """Trial advance of every line of a body to ``t1`` with the body at ``pose`` moving with
    ``vel`` (angular velocity in earth axes, rad/s).

    Writes the fairlead positions / velocities ``rf_all, vf_all`` (n, 3), the lever arms
    ``arm`` (n, 3), the force of each line on its fairlead ``forces`` (n, 3) N and the
    generalised force ``Q`` (6,) (N, N m about the displaced reference point, earth axes);
    ``counters`` (n, 2) += Newton iterations and step halvings.  ``on`` (n,) bool: lines with
    ``on[i]`` False are released (failed, ALS): not advanced (their state stays as it was),
    zero force, no contribution to ``Q``.  Returns 0, or the failing status of
    :func:`kernels.ga_advance` with ``fail[0]`` the line index (its ``info`` holds the time and
    the node).
    """
    rotation_matrix_into(pose[3], pose[4], pose[5], R)
    for k in range(6):
        Q[k] = 0.0
    nl = fair_b.shape[0]
    for i in range(nl):
        for c in range(3):
            arm[i, c] = R[c, 0] * fair_b[i, 0] + R[c, 1] * fair_b[i, 1] + R[c, 2] * fair_b[i, 2]
        rf_all[i, 0] = pose[0] + arm[i, 0]
        rf_all[i, 1] = pose[1] + arm[i, 1]
        rf_all[i, 2] = pose[2] + arm[i, 2]
        vf_all[i, 0] = vel[0] + vel[4] * arm[i, 2] - vel[5] * arm[i, 1]
        vf_all[i, 1] = vel[1] + vel[5] * arm[i, 0] - vel[3] * arm[i, 2]
        vf_all[i, 2] = vel[2] + vel[3] * arm[i, 1] - vel[4] * arm[i, 0]
        if not on[i]:
            for c in range(3):
                forces[i, c] = 0.0
            continue
        st_i = stats[i]
        st_i[0] = 0.0
        st_i[1] = 0.0
        st = ga_advance(t1, dt, nsub, max_split, r[i], v[i], a[i], fn[i], fs[i], rf_all[i],
                        vf_all[i], rA[i], vA[i], aA[i], fnA[i], fs1[i], rB[i], vB[i], aB[i],
                        fA[i], rfk[i], vfk[i], P[i], E[i], S[i], cur_z[i], cur_u[i], wk[i],
                        fric[i], coef[i], tol[i], maxit[i], q[i], tens[i], Mb[i], Dg[i], Of[i],
                        BX[i], Rk[i], W[i], Yk[i], T1[i], da[i], info[i], st_i)
        counters[i, 0] += st_i[0]
        counters[i, 1] += st_i[1]
        if st < 0:
            fail[0] = i
            return st
        f = fnA[i]
        n = f.shape[0]
        for c in range(3):
            forces[i, c] = f[n - 1, c]
        add_line_wrench(i, arm, forces, Q)
    return 0


@njit(cache=True)
def add_line_wrench(i, arm, forces, Q):
    """``Q`` (6,) += the force of line ``i`` on its fairlead ``forces[i]`` (N, earth axes) and
    its moment ``arm[i] x forces[i]`` about the displaced reference point (N m)."""
    for c in range(3):
        Q[c] += forces[i, c]
    Q[3] += arm[i, 1] * forces[i, 2] - arm[i, 2] * forces[i, 1]
    Q[4] += arm[i, 2] * forces[i, 0] - arm[i, 0] * forces[i, 2]
    Q[5] += arm[i, 0] * forces[i, 1] - arm[i, 1] * forces[i, 0]


@njit(cache=True)
def body_accept(on, r, v, a, fn, fs, rA, vA, aA, fnA, fs1):
    """Commit the trial state of every line with ``on[i]`` (the copies of
    :meth:`FELine.accept`); released lines keep their state."""
    for i in range(len(r)):
        if not on[i]:
            continue
        r[i][:, :] = rA[i]
        v[i][:, :] = vA[i]
        a[i][:, :] = aA[i]
        fn[i][:, :] = fnA[i]
        fs[i][:, :] = fs1[i]


def typed_lists(lines, names):
    """Numba typed lists of the attributes ``names`` of ``lines`` (references, no copies)."""
    from numba.typed import List

    out = []
    for nm in names:
        lst = List()
        for ln in lines:
            lst.append(getattr(ln, nm))
        out.append(lst)
    return out


# the per-line arguments of body_advance after ``fail, on, counters``, as FELine attribute names
LINE_ARGS = ("r", "v", "a", "fn", "fs", "_r1", "_v1", "_a1", "_Rr", "_fs1", "_rB", "_vB",
             "_aB", "_f1", "_rfk", "_vfk", "P", "E_dynamic", "S", "cur_z", "cur_u", "wk")
SCALAR_ARGS = ("fric", "coef", "tol", "maxit")
WORK_ARGS = ("_q", "_tens", "_Mb", "_Dg", "_Of", "_BX", "_Rk", "_W", "_Yk", "_T1", "_da",
             "_info", "_stats")


def pack(lines):
    """Arguments of :func:`body_advance` / :func:`body_accept` for started lines: the typed
    lists (per-line arrays) and the per-line scalars as arrays."""
    per_line = typed_lists(lines, LINE_ARGS)
    work = typed_lists(lines, WORK_ARGS)
    fric = np.array([ln.fric_code for ln in lines], dtype=np.int64)
    coef = np.array([ln.coef for ln in lines], dtype=np.float64)
    tol = np.array([ln.tol for ln in lines], dtype=np.float64)
    maxit = np.array([ln.maxit for ln in lines], dtype=np.int64)
    return per_line, (fric, coef, tol, maxit), work

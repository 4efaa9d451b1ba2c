"""One generalised-alpha step of a block of :data:`~.lanes.LW` lines as SIMD lanes: the
iteration of :func:`~.gen_alpha.gen_alpha_step` with the lanes in lock step.

Every lane runs the line kernel's iteration: the same predictor, iterates, convergence tests,
halving of a correction that raised the residual, modified-Newton refresh and failure codes.
The passes over the nodes (kinematics, forces, residual, solve, correction) run on all lanes at
once; the decisions are taken lane by lane.  A lane that has converged or failed keeps its
accelerations, so the passes that still run for the others recompute its forces at its own
final state (the same numbers); its results are those of the line kernel bit for bit.

Per-lane inputs and outputs sit in the work arrays (:mod:`.lanes`): ``lf`` (step size, ``cK``,
``cC``, Newton control), ``li`` (status, iterations, ...), ``fair`` (the fairlead's position and
velocity at the end of the step), ``info`` (failure information as ``LineWork.info``).
"""

from __future__ import annotations

import math

from numba import njit

from .elements import bar_push, release_bars, start_tension_estimates, update_tension_estimates
from .gen_alpha import (
    NEWTON_THETA,
    NW_FORCE,
    NW_KEEP,
    NW_PREDICT,
    NW_QSTOP,
    NW_TRAPEZ,
    TENSION_TOL,
    all_taut,
)
from .lanes import (
    BF_BEND,
    BF_FRIC,
    BF_MAXIT,
    BF_MODE,
    BF_STIFF,
    LANE_JIT,
    LF_ALPHA,
    LF_CC,
    LF_CK,
    LF_DMAX,
    LF_DPREV,
    LF_DT,
    LF_FBAR,
    LF_FCAP,
    LF_FTOL,
    LF_IMB,
    LF_RES,
    LF_RESP,
    LF_RMAX,
    LF_TTOL,
    LI_FRESH,
    LI_FSTOP,
    LI_IMAX,
    LI_IT,
    LI_NSTIFF,
    LI_RET,
    LI_SOLVE,
    LI_ST,
    LW,
    ix,
    lanes_in,
)
from .lanes_blocks import band_solve, tridiag_resolve, tridiag_solve
from .lanes_forces import forces_into, geometry, lane_rows, mass_blocks, tangents
from .layout import EL_C1, EL_L0, EPS_MACH, FR_DISPVEL, KERNEL_JIT, N_EL, N_FS, N_NP, S_ZC
from .seabed import friction_decide

# Newton status of a lane (li[LI_ST])
ST_RUN, ST_DONE, ST_RES, ST_IDLE = 0, 1, 2, 3


@njit(**LANE_JIT)
def predict(b, n, coef, mode, lf, fair, r, v, a, r1, v1, a1):
    """:func:`~.gen_alpha.predict` of block ``b`` (step sizes ``lf[LF_DT]``, the fairlead's
    end position and velocity in ``fair[0:3]``, ``fair[3:6]``; the deviations are kept in
    ``fair[6:9]``)."""
    lw = lanes_in(r, 3 * n)
    for i in range(n):
        inner = 0 < i < n - 1
        for k in range(3):
            for l in range(lw):
                a1[b, ix(i, k, 3, l)] = a[b, ix(i, k, 3, l)] if inner else 0.0
    for k in range(3):
        for l in range(lw):
            dt = lf[b, ix(LF_DT, 0, 1, l)]
            dev = fair[b, ix(k, 0, 1, l)] - (r[b, ix(n - 1, k, 3, l)]
                                              + dt * v[b, ix(n - 1, k, 3, l)])
            if mode & NW_PREDICT:
                dev -= 0.5 * dt * dt * a[b, ix(n - 2, k, 3, l)]
            elif mode & NW_TRAPEZ:
                dev -= 0.5 * dt * (fair[b, ix(3 + k, 0, 1, l)] - v[b, ix(n - 1, k, 3, l)])
            fair[b, ix(6 + k, 0, 1, l)] = dev
        for i in range(1, n - 1):
            for l in range(lw):
                dt = lf[b, ix(LF_DT, 0, 1, l)]
                beta = coef[b, ix(0, 2, 4, l)]
                a1[b, ix(i, k, 3, l)] += (fair[b, ix(6 + k, 0, 1, l)] * (i / (n - 1.0))
                                          / (beta * dt * dt))
    for k in range(3):
        for l in range(lw):
            r1[b, ix(0, k, 3, l)] = r[b, ix(0, k, 3, l)]
            v1[b, ix(0, k, 3, l)] = 0.0
            r1[b, ix(n - 1, k, 3, l)] = fair[b, ix(k, 0, 1, l)]
            v1[b, ix(n - 1, k, 3, l)] = fair[b, ix(3 + k, 0, 1, l)]


@njit(inline="always")
def _kin(b, i, k, l, coef, lf, r, v, a, a1k, r1, v1):
    """The generalised-alpha positions and velocities (:func:`~.gen_alpha.kinematics`) of node
    ``i``, component ``k``, lane ``l`` at the acceleration ``a1k`` (:func:`kinematics`,
    :func:`correct`, :func:`back`)."""
    dt = lf[b, ix(LF_DT, 0, 1, l)]
    beta = coef[b, ix(0, 2, 4, l)]
    gamma = coef[b, ix(0, 3, 4, l)]
    aa = a[b, ix(i, k, 3, l)]
    r1[b, ix(i, k, 3, l)] = (r[b, ix(i, k, 3, l)] + dt * v[b, ix(i, k, 3, l)]
                             + dt * dt * ((0.5 - beta) * aa + beta * a1k))
    v1[b, ix(i, k, 3, l)] = v[b, ix(i, k, 3, l)] + dt * ((1.0 - gamma) * aa + gamma * a1k)


@njit(**LANE_JIT)
def kinematics(b, n, coef, lf, r, v, a, a1, r1, v1):
    """:func:`~.gen_alpha.kinematics` of block ``b``."""
    lw = lanes_in(r, 3 * n)
    for i in range(1, n - 1):
        for k in range(3):
            for l in range(lw):
                _kin(b, i, k, l, coef, lf, r, v, a, a1[b, ix(i, k, 3, l)], r1, v1)


@njit(**LANE_JIT)
def residual(b, n, coef, a, a1, fn, f1, Mb, fresh, Dg, R, lf, force):
    """:func:`~.gen_alpha.residual` of block ``b``: the residual into ``R``, its squared norm
    into ``lf[LF_RES]`` and, with ``force``, the force imbalance (:func:`~.gen_alpha.imbalance`)
    into ``lf[LF_IMB]``; with ``fresh`` the inertia block added to ``Dg``."""
    lw = lanes_in(a, 3 * n)
    for l in range(lw):
        lf[b, ix(LF_RES, 0, 1, l)] = 0.0
        lf[b, ix(LF_IMB, 0, 1, l)] = 0.0
    for i in range(1, n - 1):
        for l in range(lw):
            am = coef[b, ix(0, 0, 4, l)]
            af = coef[b, ix(0, 1, 4, l)]
            b0 = (1.0 - am) * a1[b, ix(i, 0, 3, l)] + am * a[b, ix(i, 0, 3, l)]
            b1 = (1.0 - am) * a1[b, ix(i, 1, 3, l)] + am * a[b, ix(i, 1, 3, l)]
            b2 = (1.0 - am) * a1[b, ix(i, 2, 3, l)] + am * a[b, ix(i, 2, 3, l)]
            res = lf[b, ix(LF_RES, 0, 1, l)]
            for k in range(3):
                s = (0.0 + Mb[b, ix(i, 3 * k, 9, l)] * b0 + Mb[b, ix(i, 3 * k + 1, 9, l)] * b1
                     + Mb[b, ix(i, 3 * k + 2, 9, l)] * b2)
                if fresh:
                    Dg[b, ix(i, 3 * k, 9, l)] += (1.0 - am) * Mb[b, ix(i, 3 * k, 9, l)]
                    Dg[b, ix(i, 3 * k + 1, 9, l)] += (1.0 - am) * Mb[b, ix(i, 3 * k + 1, 9, l)]
                    Dg[b, ix(i, 3 * k + 2, 9, l)] += (1.0 - am) * Mb[b, ix(i, 3 * k + 2, 9, l)]
                rk = (1.0 - af) * f1[b, ix(i, k, 3, l)] + af * fn[b, ix(i, k, 3, l)] - s
                R[b, ix(i, k, 3, l)] = rk
                res += rk * rk
            lf[b, ix(LF_RES, 0, 1, l)] = res
            if force:
                lf[b, ix(LF_IMB, 0, 1, l)] += (abs(R[b, ix(i, 0, 3, l)])
                                               + abs(R[b, ix(i, 1, 3, l)])
                                               + abs(R[b, ix(i, 2, 3, l)]))


@njit(**LANE_JIT)
def correct(b, n, da, a1, solve, lf, li, bad, coef, r, v, a, r1, v1):
    """:func:`~.gen_alpha.correct` of the lanes with ``solve[b, l]``: ``a1 += da``, the largest
    correction into ``lf[LF_DMAX]`` and its node into ``li[LI_IMAX]``, the first node of a NaN
    correction into ``bad[b, l]`` (-1: none); and the positions and velocities ``r1``, ``v1``
    of the new accelerations (:func:`kinematics`, in the same pass: the next iteration's force
    evaluation needs them; a lane not corrected gets the numbers it has)."""
    lw = lanes_in(da, 3 * n)
    for l in range(lw):
        lf[b, ix(LF_DMAX, 0, 1, l)] = 0.0
        li[b, ix(LI_IMAX, 0, 1, l)] = 1
        bad[b, l] = -1
    # per node, the three components' largest |d| in registers (the same sequence of strict
    # comparisons as component by component: the first component on ties, a NaN never
    # larger), then one update of the lane's running values: a third of the loop-carried
    # loads and stores (7 % of the flagship's lanes replay was this pass, perf 2026-11-28)
    for i in range(1, n - 1):
        for l in range(lw):
            on = solve[b, l] != 0
            d0 = da[b, ix(i, 0, 3, l)]
            d1 = da[b, ix(i, 1, 3, l)]
            d2 = da[b, ix(i, 2, 3, l)]
            o0 = a1[b, ix(i, 0, 3, l)]
            o1 = a1[b, ix(i, 1, 3, l)]
            o2 = a1[b, ix(i, 2, 3, l)]
            n0 = o0 + d0 if on else o0
            n1 = o1 + d1 if on else o1
            n2 = o2 + d2 if on else o2
            a1[b, ix(i, 0, 3, l)] = n0
            a1[b, ix(i, 1, 3, l)] = n1
            a1[b, ix(i, 2, 3, l)] = n2
            _kin(b, i, 0, l, coef, lf, r, v, a, n0, r1, v1)
            _kin(b, i, 1, l, coef, lf, r, v, a, n1, r1, v1)
            _kin(b, i, 2, l, coef, lf, r, v, a, n2, r1, v1)
            nan = not (math.isfinite(d0) and math.isfinite(d1) and math.isfinite(d2))
            bl = bad[b, l]
            bad[b, l] = i if (on and nan and bl < 0) else bl
            dm = lf[b, ix(LF_DMAX, 0, 1, l)]
            cur = dm
            ad = abs(d0)
            cur = ad if ad > cur else cur
            ad = abs(d1)
            cur = ad if ad > cur else cur
            ad = abs(d2)
            cur = ad if ad > cur else cur
            up = on and cur > dm
            lf[b, ix(LF_DMAX, 0, 1, l)] = cur if up else dm
            im = li[b, ix(LI_IMAX, 0, 1, l)]
            li[b, ix(LI_IMAX, 0, 1, l)] = i if up else im


@njit(**LANE_JIT)
def back(b, n, da, a1, lf, li, coef, r, v, a, r1, v1):
    """Take back the part ``lf[LF_ALPHA]`` of the last correction in the lanes with
    ``li[LI_SOLVE]`` -1 (:func:`~.gen_alpha._back`), and their positions and velocities as
    :func:`correct`."""
    lw = lanes_in(da, 3 * n)
    for i in range(1, n - 1):
        for k in range(3):
            for l in range(lw):
                on = li[b, ix(LI_SOLVE, 0, 1, l)] == -1
                old = a1[b, ix(i, k, 3, l)]
                new = old - lf[b, ix(LF_ALPHA, 0, 1, l)] * da[b, ix(i, k, 3, l)] if on else old
                a1[b, ix(i, k, 3, l)] = new
                _kin(b, i, k, l, coef, lf, r, v, a, new, r1, v1)


@njit(**LANE_JIT)
def take_resolved(b, n, xr, dx, mask, li):
    """The corrections of the solving lanes that reused their factorisation (``li[LI_SOLVE]``
    1, ``mask[b, l]`` 0): their sweeps' result ``xr`` into ``dx``."""
    lw = lanes_in(dx, 3 * n)
    for i in range(1, n - 1):
        for k in range(3):
            for l in range(lw):
                keep = mask[b, l] == 0 and li[b, ix(LI_SOLVE, 0, 1, l)] == 1
                old = dx[b, ix(i, k, 3, l)]
                dx[b, ix(i, k, 3, l)] = xr[b, ix(i, k, 3, l)] if keep else old


@njit(**LANE_JIT)
def force_scales(b, n, r, E, weight, lf):
    """:func:`~.forces.force_tolerances` of every lane of block ``b`` at ``r``: ``ftol``,
    ``fcap`` and the force-terms tolerance ``max(TENSION_TOL weight, rfloor)`` into ``lf``
    (``weight``: the lanes' node-weight scale and weight in air, state independent)."""
    lw = lanes_in(r, 3 * n)
    for l in range(lw):
        lf[b, ix(LF_RMAX, 0, 1, l)] = 0.0
        lf[b, ix(LF_FTOL, 0, 1, l)] = 0.0
    for i in range(n):
        for l in range(lw):
            # the same three max in the same order, the running value in a register per node
            m = max(lf[b, ix(LF_RMAX, 0, 1, l)], abs(r[b, ix(i, 0, 3, l)]))
            m = max(m, abs(r[b, ix(i, 1, 3, l)]))
            lf[b, ix(LF_RMAX, 0, 1, l)] = max(m, abs(r[b, ix(i, 2, 3, l)]))
    for j in range(n - 1):
        for l in range(lw):
            rmax = lf[b, ix(LF_RMAX, 0, 1, l)]
            lf[b, ix(LF_FTOL, 0, 1, l)] = max(
                lf[b, ix(LF_FTOL, 0, 1, l)],
                E[b, ix(j, EL_C1, N_EL, l)] * EPS_MACH * (2.0 + 2.0 * rmax
                                                          / E[b, ix(j, EL_L0, N_EL, l)]))
    for l in range(lw):
        fround = lf[b, ix(LF_FTOL, 0, 1, l)]
        ftol = weight[b, l]
        lf[b, ix(LF_FCAP, 0, 1, l)] = max(1e3 * ftol, math.sqrt(3.0 * n) * fround)
        lf[b, ix(LF_FTOL, 0, 1, l)] = max(ftol, math.sqrt(3.0 * n) * fround)
        lf[b, ix(LF_TTOL, 0, 1, l)] = max(TENSION_TOL * weight[b, LW + l],
                                          3.0 * (n - 2) * fround)


@njit(**KERNEL_JIT)
def block_step(b, n, par, s0, fs, s1, w, known):
    """One generalised-alpha step of the running lanes of block ``b`` (``w.li[LI_ST]``
    :data:`ST_RUN`; the others :data:`ST_IDLE`) from the states ``s0`` to ``s1``
    (:func:`~.gen_alpha.gen_alpha_step` lane by lane; ``fs`` the friction state of the step).
    The step size of each lane in ``w.lf[LF_DT]``, its fairlead at the end of the step in
    ``w.fair``.  Each lane's result in ``w.li[LI_RET]``: the iterations (> 0) or the failure
    code (-1 no convergence, -2 singular matrix, -3 NaN; ``w.info`` as the line kernel's).
    ``known``: ``w.el`` and ``w.q`` already hold the element geometry and node tangents of
    ``s0`` in every lane that steps (``w.geo``, :func:`~.lanes_advance.block_advance`): they
    are not computed again (the same numbers)."""
    P = par.P
    E = par.E
    coef = par.coef
    flags = par.flags
    lf = w.lf
    li = w.li
    info = w.info
    mode = flags[b, BF_MODE]
    maxit = flags[b, BF_MAXIT]
    bend = flags[b, BF_BEND] != 0
    stiff = flags[b, BF_STIFF] != 0
    fric = flags[b, BF_FRIC]
    modified = (mode & NW_KEEP) > 0
    by_force = (mode & NW_FORCE) > 0
    r, v, a, fn = s0.r, s0.v, s0.a, s0.f
    r1, v1, a1, f1 = s1.r, s1.v, s1.a, s1.f
    force_scales(b, n, r, E, par.weight, lf)
    for l in range(LW):
        nst = 0
        if stiff and li[b, ix(LI_ST, 0, 1, l)] == ST_RUN:
            nst = start_tension_estimates(lane_rows(r, b, n, 3, l), lane_rows(v, b, n, 3, l),
                                          lane_rows(P, b, n, N_NP, l),
                                          lane_rows(E, b, n - 1, N_EL, l),
                                          w.act[b].reshape((n - 1, LW))[:, l])
        li[b, ix(LI_NSTIFF, 0, 1, l)] = nst
    if not known:
        geometry(b, n, r, w.el)
        tangents(b, n, w.el, w.q)
    mass_blocks(b, n, P, w.q, w.Mb)
    predict(b, n, coef, mode, lf, w.fair, r, v, a, r1, v1, a1)
    for l in range(LW):
        dt = lf[b, ix(LF_DT, 0, 1, l)]
        af = coef[b, ix(0, 1, 4, l)]
        lf[b, ix(LF_CK, 0, 1, l)] = (1.0 - af) * coef[b, ix(0, 2, 4, l)] * dt * dt
        lf[b, ix(LF_CC, 0, 1, l)] = (1.0 - af) * coef[b, ix(0, 3, 4, l)] * dt
    # the predictor's positions and velocities; from then on correct and back keep r1, v1
    # those of a1
    kinematics(b, n, coef, lf, r, v, a, a1, r1, v1)
    if fric == FR_DISPVEL:
        for l in range(LW):
            if li[b, ix(LI_ST, 0, 1, l)] == ST_RUN:
                friction_decide(lane_rows(r1, b, n, 3, l), lane_rows(v1, b, n, 3, l), fric,
                                lane_rows(fs, b, n, N_FS, l), par.S[b * LW + l, S_ZC])
    running = 0
    for l in range(LW):
        li[b, ix(LI_IT, 0, 1, l)] = 0
        li[b, ix(LI_FRESH, 0, 1, l)] = 1
        li[b, ix(LI_RET, 0, 1, l)] = 0
        lf[b, ix(LF_RESP, 0, 1, l)] = math.inf
        lf[b, ix(LF_ALPHA, 0, 1, l)] = 1.0
        lf[b, ix(LF_DPREV, 0, 1, l)] = 0.0
        if li[b, ix(LI_ST, 0, 1, l)] == ST_RUN:
            if maxit <= 0:
                # no iteration allowed: not converged (gen_alpha_step's loop does not run)
                li[b, ix(LI_ST, 0, 1, l)] = -1
            else:
                running += 1
    while running > 0:
        fresh_any = False
        for l in range(LW):
            if li[b, ix(LI_ST, 0, 1, l)] == ST_RUN:
                li[b, ix(LI_IT, 0, 1, l)] += 1
                fresh_any = fresh_any or li[b, ix(LI_FRESH, 0, 1, l)] != 0
        forces_into(b, n, par, r1, v1, fs, f1, w, fresh_any, stiff)
        residual(b, n, coef, a, a1, fn, f1, w.Mb, fresh_any, w.Dg, w.R, lf, by_force)
        nsolve = 0
        nfresh = 0
        nback = 0
        for l in range(LW):
            w.mask[b, l] = 0
            li[b, ix(LI_SOLVE, 0, 1, l)] = 0
            if li[b, ix(LI_ST, 0, 1, l)] != ST_RUN:
                continue
            p = b * LW + l
            it = li[b, ix(LI_IT, 0, 1, l)]
            res = lf[b, ix(LF_RES, 0, 1, l)]
            fbar = 0.0
            nst = li[b, ix(LI_NSTIFF, 0, 1, l)]
            if nst > 0:
                fbar = bar_push(w.act[b].reshape((n - 1, LW))[:, l],
                                w.tens[b].reshape((n - 1, LW))[:, l])
            if not math.isfinite(res):
                info[p, 1] = 1
                li[b, ix(LI_ST, 0, 1, l)] = -3
                continue
            fresh = li[b, ix(LI_FRESH, 0, 1, l)] != 0
            res_prev = lf[b, ix(LF_RESP, 0, 1, l)]
            alpha = lf[b, ix(LF_ALPHA, 0, 1, l)]
            if not fresh and it > 1 and res > NEWTON_THETA * NEWTON_THETA * res_prev:
                li[b, ix(LI_FRESH, 0, 1, l)] = 1
                li[b, ix(LI_IT, 0, 1, l)] = it - 1
                continue
            if res > res_prev and alpha > 1.0 / 1024.0 and nst == 0:
                lf[b, ix(LF_ALPHA, 0, 1, l)] = alpha * 0.5
                li[b, ix(LI_SOLVE, 0, 1, l)] = -1
                nback += 1
                continue
            lf[b, ix(LF_ALPHA, 0, 1, l)] = 1.0
            lf[b, ix(LF_RESP, 0, 1, l)] = res
            af = coef[b, ix(0, 1, 4, l)]
            fstop = by_force and all_taut(w.tens[b].reshape((n - 1, LW))[:, l])
            li[b, ix(LI_FSTOP, 0, 1, l)] = 1 if fstop else 0
            if fstop:
                ttol = lf[b, ix(LF_TTOL, 0, 1, l)]
                if it > 1 and lf[b, ix(LF_IMB, 0, 1, l)] <= (1.0 - af) * ttol and fbar <= ttol:
                    li[b, ix(LI_ST, 0, 1, l)] = ST_RES
                    continue
            elif it > 1:
                ftol = lf[b, ix(LF_FTOL, 0, 1, l)]
                if math.sqrt(res) <= ftol and fbar <= ftol:
                    li[b, ix(LI_ST, 0, 1, l)] = ST_RES
                    continue
            lf[b, ix(LF_FBAR, 0, 1, l)] = fbar
            li[b, ix(LI_SOLVE, 0, 1, l)] = 1
            nsolve += 1
            if fresh:
                w.mask[b, l] = 1
                nfresh += 1
        if nback > 0:
            back(b, n, w.dx, a1, lf, li, coef, r, v, a, r1, v1)
        if nsolve > 0:
            if nfresh > 0:
                if bend:
                    band_solve(b, n, w.Dg, w.Of, w.BX, w.R, w.Y, w.T1, w.dx, w.mask, w.bad)
                elif modified:
                    # keep as a constant: the forward sweep vectorises
                    tridiag_solve(b, n, w.Dg, w.Of, w.R, w.W, w.Y, w.dx, True, w.mask, w.bad,
                                  w.OfK)
                else:
                    tridiag_solve(b, n, w.Dg, w.Of, w.R, w.W, w.Y, w.dx, False, w.mask, w.bad,
                                  w.OfK)
                for l in range(LW):
                    if w.mask[b, l] != 0 and w.bad[b, l] >= 0:
                        info[b * LW + l, 1] = w.bad[b, l]
                        li[b, ix(LI_ST, 0, 1, l)] = -2
                        li[b, ix(LI_SOLVE, 0, 1, l)] = 0
            if nsolve > nfresh:
                tridiag_resolve(b, n, w.OfK, w.R, w.W, w.Y, w.xr)
                take_resolved(b, n, w.xr, w.dx, w.mask, li)
            for l in range(LW):
                if li[b, ix(LI_SOLVE, 0, 1, l)] != 1:
                    w.mask[b, l] = 0
                    continue
                w.mask[b, l] = 1
                if li[b, ix(LI_FRESH, 0, 1, l)] != 0:
                    reuse = modified and li[b, ix(LI_NSTIFF, 0, 1, l)] == 0 and not bend
                    li[b, ix(LI_FRESH, 0, 1, l)] = 1 if not reuse else 0
                if li[b, ix(LI_NSTIFF, 0, 1, l)] > 0:
                    dt = lf[b, ix(LF_DT, 0, 1, l)]
                    beta = coef[b, ix(0, 2, 4, l)]
                    update_tension_estimates(
                        lane_rows(r1, b, n, 3, l), lane_rows(w.dx, b, n, 3, l),
                        beta * dt * dt, lf[b, ix(LF_CK, 0, 1, l)], lane_rows(P, b, n, N_NP, l),
                        lane_rows(E, b, n - 1, N_EL, l),
                        w.Of[b].reshape((n - 1, 3, 3, LW))[:, :, :, l],
                        w.tens[b].reshape((n - 1, LW))[:, l],
                        w.act[b].reshape((n - 1, LW))[:, l])
            correct(b, n, w.dx, a1, w.mask, lf, li, w.bad, coef, r, v, a, r1, v1)
            for l in range(LW):
                if w.mask[b, l] == 0:
                    continue
                p = b * LW + l
                info[p, 1] = li[b, ix(LI_IMAX, 0, 1, l)]
                if w.bad[b, l] >= 0:
                    info[p, 1] = w.bad[b, l]
                    li[b, ix(LI_ST, 0, 1, l)] = -3
                    continue
                dmax = lf[b, ix(LF_DMAX, 0, 1, l)]
                dprev = lf[b, ix(LF_DPREV, 0, 1, l)]
                dt = lf[b, ix(LF_DT, 0, 1, l)]
                beta = coef[b, ix(0, 2, 4, l)]
                bdt = dmax * beta * dt * dt
                tol = par.tol[b, l]
                fcap = lf[b, ix(LF_FCAP, 0, 1, l)]
                fbar = lf[b, ix(LF_FBAR, 0, 1, l)]
                res = lf[b, ix(LF_RES, 0, 1, l)]
                if li[b, ix(LI_FSTOP, 0, 1, l)] != 0:
                    lf[b, ix(LF_DPREV, 0, 1, l)] = dmax
                    continue
                if bdt <= tol and math.sqrt(res) <= fcap and fbar <= fcap:
                    li[b, ix(LI_ST, 0, 1, l)] = ST_DONE
                    continue
                if (mode & NW_QSTOP) and not modified and 0.0 < dmax < dprev:
                    rho = dmax / dprev
                    if (rho * rho * dmax * beta * dt * dt <= tol and math.sqrt(res) <= fcap
                            and fbar <= fcap):
                        li[b, ix(LI_ST, 0, 1, l)] = ST_DONE
                        continue
                if modified and 0.0 < dmax < dprev:
                    rho = dmax / dprev
                    if (rho / (1.0 - rho) * dmax * beta * dt * dt <= tol
                            and math.sqrt(res) <= fcap and fbar <= fcap):
                        li[b, ix(LI_ST, 0, 1, l)] = ST_DONE
                        continue
                lf[b, ix(LF_DPREV, 0, 1, l)] = dmax
        running = 0
        for l in range(LW):
            if li[b, ix(LI_ST, 0, 1, l)] == ST_RUN:
                if li[b, ix(LI_IT, 0, 1, l)] >= maxit:
                    li[b, ix(LI_ST, 0, 1, l)] = -1
                else:
                    running += 1
    # accepted states: a lane converged on its correction is evaluated once more (a lane
    # converged on its residual keeps the forces of its last iterate: the same numbers)
    final = False
    for l in range(LW):
        final = final or li[b, ix(LI_ST, 0, 1, l)] == ST_DONE
    if final:
        forces_into(b, n, par, r1, v1, fs, f1, w, False, stiff)
    for l in range(LW):
        st = li[b, ix(LI_ST, 0, 1, l)]
        if st == ST_IDLE:
            continue
        if st < 0:
            li[b, ix(LI_RET, 0, 1, l)] = st
            continue
        if li[b, ix(LI_NSTIFF, 0, 1, l)] > 0 or stiff:
            release_bars(w.act[b].reshape((n - 1, LW))[:, l], w.tens[b].reshape((n - 1, LW))[:, l])
        li[b, ix(LI_RET, 0, 1, l)] = li[b, ix(LI_IT, 0, 1, l)]
        f1l = lane_rows(f1, b, n, 3, l)
        for i in range(n):
            for k in range(3):
                if not math.isfinite(f1l[i, k]):
                    info[b * LW + l, 1] = i
                    li[b, ix(LI_RET, 0, 1, l)] = -3
                    break
            if li[b, ix(LI_RET, 0, 1, l)] < 0:
                break

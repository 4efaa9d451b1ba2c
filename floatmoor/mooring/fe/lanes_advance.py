"""The advance of a group of lines as SIMD lanes over a body step: :func:`~.advance.ga_advance`
lane by lane (sub-steps, halving of a failed or energy-creating sub-step, the energy audit,
the friction and fibre state after every accepted sub-step), the lanes of a block stepping in
lock step (:func:`~.lanes_step.block_step`), each with its own sub-step size; then the commit of
the trial state (:func:`accept`) and a lane's output channels (:func:`record`).
"""

from __future__ import annotations

import numpy as np
from numba import njit

from .advance import record_into
from .energy import (
    AU_EBAD,
    AU_ETMIN,
    AU_EWORST,
    AU_NBAD,
    AU_NPEN,
    AU_PEN,
    AU_SPLITS,
    AU_TMIN,
    AU_TPEN,
    AU_TTMIN,
    AU_TWORST,
    AU_WORST,
    AUDIT_FLOOR,
    AUDIT_HARD,
    AUDIT_REL,
    PEN_FLOOR,
    PEN_WEIGHTS,
    _largest,
)
from .fibre_law import EL_LAW, fibre_commit
from .lanes import (
    BF_FIBRE,
    BF_FRIC,
    EC_A,
    EC_B,
    EC_E0,
    EC_STIFF,
    LANE_JIT,
    LF_BUD0,
    LF_DT,
    LF_EFLOOR,
    LF_EN0,
    LF_PW0,
    LF_T,
    LI_POS,
    LI_RET,
    LI_SRC,
    LI_ST,
    LI_SZ,
    LW,
    N_EC,
    accepted,
    ix,
    lanes_in,
    trial,
)
from .lanes_forces import geometry, lane_rows, tangents
from .lanes_step import ST_IDLE, ST_RUN, block_step
from .layout import (
    EL_B,
    EL_C1,
    EL_C2,
    EL_C3,
    EL_L0,
    FR_DISPVEL,
    FR_NONE,
    FR_VDQ,
    KERNEL_JIT,
    N_EL,
    N_FS,
    N_NP,
    N_S,
    NP_KS,
    NP_MAC,
    NP_MAN,
    NP_MASS,
    NP_MAT,
    NP_W,
    S_DC,
    S_ZC,
)
from .seabed import friction_commit

# columns of LaneWork.eo (energy pass): mechanical energy, power, budget, summed weight,
# seabed penetration over its bound and its node, and accumulators
EO_EN, EO_PW, EO_BUD, EO_WSUM, EO_PEN, EO_IPEN, EO_UE, EO_KE = range(8)


@njit(**LANE_JIT)
def energy(b, n, P, E, EC, SC, r, v, f, el, q, eo):
    """:func:`~.energy.line_energy` of every lane of block ``b`` (``el, q`` of the state, from
    its force evaluation or :func:`~.lanes_forces.geometry` and
    :func:`~.lanes_forces.tangents`) into ``eo`` (``EO_*``), the sums in the line kernel's
    order."""
    lw = lanes_in(r, 3 * n)
    for l in range(lw):
        eo[b, ix(EO_UE, 0, 1, l)] = 0.0
        eo[b, ix(EO_PW, 0, 1, l)] = 0.0
    for j in range(n - 1):
        for l in range(lw):
            L0 = E[b, ix(j, EL_L0, N_EL, l)]
            eps = el[b, ix(j, 3, 4, l)] / L0 - 1.0
            on = (E[b, ix(j, EL_LAW, N_EL, l)] == 0.0 and EC[b, ix(j, EC_STIFF, N_EC, l)] == 0.0
                  and eps > 0.0)
            c1 = E[b, ix(j, EL_C1, N_EL, l)]
            c2 = E[b, ix(j, EL_C2, N_EL, l)]
            c3 = E[b, ix(j, EL_C3, N_EL, l)]
            e0 = EC[b, ix(j, EC_E0, N_EC, l)]
            A = EC[b, ix(j, EC_A, N_EC, l)]
            B = EC[b, ix(j, EC_B, N_EC, l)]
            up = eps >= e0
            T = (c1 * eps + c2 * eps * eps + c3 * eps * eps * eps if up
                 else A * eps * eps + B * eps * eps * eps)
            U = (L0 * (A * e0 ** 3 / 3.0 + B * e0 ** 4 / 4.0
                       + c1 * (eps * eps - e0 * e0) / 2.0 + c2 * (eps ** 3 - e0 ** 3) / 3.0
                       + c3 * (eps ** 4 - e0 ** 4) / 4.0) if up
                 else L0 * (A * eps ** 3 / 3.0 + B * eps ** 4 / 4.0))
            ldot = (el[b, ix(j, 0, 4, l)] * (v[b, ix(j + 1, 0, 3, l)] - v[b, ix(j, 0, 3, l)])
                    + el[b, ix(j, 1, 4, l)] * (v[b, ix(j + 1, 1, 3, l)] - v[b, ix(j, 1, 3, l)])
                    + el[b, ix(j, 2, 4, l)] * (v[b, ix(j + 1, 2, 3, l)] - v[b, ix(j, 2, 3, l)]))
            ue = eo[b, ix(EO_UE, 0, 1, l)]
            eo[b, ix(EO_UE, 0, 1, l)] = ue + U if on else ue
            pw = eo[b, ix(EO_PW, 0, 1, l)]
            pw = pw + T * ldot if on else pw
            if j == n - 2:
                Bj = E[b, ix(j, EL_B, N_EL, l)]
                xs = eps / e0
                sm = xs * xs * (3.0 - 2.0 * xs) if xs < 1.0 else 1.0
                Td = Bj * sm * ldot / L0
                fair = (el[b, ix(j, 0, 4, l)] * v[b, ix(j + 1, 0, 3, l)]
                        + el[b, ix(j, 1, 4, l)] * v[b, ix(j + 1, 1, 3, l)]
                        + el[b, ix(j, 2, 4, l)] * v[b, ix(j + 1, 2, 3, l)])
                pw = pw + Td * fair if (on and Bj != 0.0) else pw
            eo[b, ix(EO_PW, 0, 1, l)] = pw
    for l in range(lw):
        eo[b, ix(EO_KE, 0, 1, l)] = 0.0
        eo[b, ix(EO_EN, 0, 1, l)] = 0.0     # (eg, the potential energy, until the end)
        eo[b, ix(EO_WSUM, 0, 1, l)] = 0.0
        eo[b, ix(EO_PEN, 0, 1, l)] = 0.0
        eo[b, ix(EO_IPEN, 0, 1, l)] = 0.0
    for i in range(1, n - 1):
        for l in range(lw):
            vx = v[b, ix(i, 0, 3, l)]
            vy = v[b, ix(i, 1, 3, l)]
            vz = v[b, ix(i, 2, 3, l)]
            vv = vx * vx + vy * vy + vz * vz
            vq = vx * q[b, ix(i, 0, 3, l)] + vy * q[b, ix(i, 1, 3, l)] + vz * q[b, ix(i, 2, 3, l)]
            eo[b, ix(EO_KE, 0, 1, l)] += 0.5 * (
                (P[b, ix(i, NP_MASS, N_NP, l)] + P[b, ix(i, NP_MAC, N_NP, l)]) * vv
                + P[b, ix(i, NP_MAN, N_NP, l)] * (vv - vq * vq)
                + P[b, ix(i, NP_MAT, N_NP, l)] * vq * vq)
            w = P[b, ix(i, NP_W, N_NP, l)]
            eo[b, ix(EO_WSUM, 0, 1, l)] += abs(w)
            eg = eo[b, ix(EO_EN, 0, 1, l)] + w * r[b, ix(i, 2, 3, l)]
            pw = eo[b, ix(EO_PW, 0, 1, l)] + (f[b, ix(i, 0, 3, l)] * vx + f[b, ix(i, 1, 3, l)] * vy
                                              + f[b, ix(i, 2, 3, l)] * vz + w * vz)
            pen = SC[b, ix(0, S_ZC, N_S, l)] - r[b, ix(i, 2, 3, l)]
            ks = P[b, ix(i, NP_KS, N_NP, l)]
            on = pen > 0.0 and ks > 0.0
            dpen = max(0.5 * max(w, 1e-12) / ks, SC[b, ix(0, S_DC, N_S, l)])
            inr = pen < dpen
            x = pen / dpen
            gp = pen * x * (2.0 - x) if inr else pen
            es = (ks * (2.0 * pen ** 3 / (3.0 * dpen) - pen ** 4 / (4.0 * dpen * dpen)) if inr
                  else ks * (5.0 * dpen * dpen / 12.0 + 0.5 * (pen * pen - dpen * dpen)))
            eo[b, ix(EO_EN, 0, 1, l)] = eg + es if on else eg
            eo[b, ix(EO_PW, 0, 1, l)] = pw - ks * gp * vz if on else pw
            lim = max(PEN_WEIGHTS * max(w, 0.0) / ks, PEN_FLOOR)
            pm = eo[b, ix(EO_PEN, 0, 1, l)]
            deeper = on and pen / lim > pm
            eo[b, ix(EO_PEN, 0, 1, l)] = pen / lim if deeper else pm
            ip = eo[b, ix(EO_IPEN, 0, 1, l)]
            eo[b, ix(EO_IPEN, 0, 1, l)] = float(i) if deeper else ip
    for l in range(lw):
        ke = eo[b, ix(EO_KE, 0, 1, l)]
        ue = eo[b, ix(EO_UE, 0, 1, l)]
        eo[b, ix(EO_EN, 0, 1, l)] = ke + ue + eo[b, ix(EO_EN, 0, 1, l)]
        eo[b, ix(EO_BUD, 0, 1, l)] = ke + ue


@njit(**LANE_JIT)
def masked_copy(b, rows, mask, src, dst):
    """Block row ``b`` of ``src`` into that of ``dst`` (``rows`` entries per lane) in the lanes
    with ``mask[b, l]`` 1.  One array per call: the arrays of a state tuple are not arguments,
    so not ``noalias``, and the copy of several at once does not vectorise."""
    lw = lanes_in(mask, 1)
    every = True
    for l in range(lw):
        every = every and mask[b, l] != 0
    if every:
        # every lane (the usual case): a plain copy of the row (9 % of the flagship's lanes
        # replay went to the masked loop below, perf 2026-11-28)
        for i in range(rows * lw):
            dst[b, np.uintp(i)] = src[b, np.uintp(i)]
        return
    for i in range(rows):
        for l in range(lw):
            m = mask[b, l] != 0
            s = src[b, ix(i, 0, 1, l)]      # both loaded, then selected: a load inside the
            d = dst[b, ix(i, 0, 1, l)]      # select's branch keeps the loop scalar
            dst[b, ix(i, 0, 1, l)] = s if m else d


@njit(**KERNEL_JIT)
def take_step(b, n, mask, step, trial):
    """The sub-step result ``step`` (positions, velocities, accelerations, forces) into the
    trial state of the lanes with ``mask[b, l]`` 1."""
    masked_copy(b, 3 * n, mask, step.r, trial.r)
    masked_copy(b, 3 * n, mask, step.v, trial.v)
    masked_copy(b, 3 * n, mask, step.a, trial.a)
    masked_copy(b, 3 * n, mask, step.f, trial.f)


@njit(**KERNEL_JIT)
def copy_state(b, n, mask, src, dst, with_fs):
    """The state ``src`` into ``dst`` for the lanes with ``mask[b, l]`` 1 (``with_fs``: the
    friction state too)."""
    masked_copy(b, 3 * n, mask, src.r, dst.r)
    masked_copy(b, 3 * n, mask, src.v, dst.v)
    masked_copy(b, 3 * n, mask, src.a, dst.a)
    masked_copy(b, 3 * n, mask, src.f, dst.f)
    if with_fs:
        masked_copy(b, N_FS * n, mask, src.fs, dst.fs)


@njit(inline="always")
def _uses_fs(flags, b):
    """Block ``b`` keeps a friction state: seabed friction or a fibre law (a block with neither
    never reads or writes it, so its copies are skipped)."""
    return flags[b, BF_FRIC] != FR_NONE or flags[b, BF_FIBRE] != 0


@njit(**KERNEL_JIT)
def block_advance(b, n, t1, dt, nsub, max_split, g, on):
    """Trial advance of the lanes of block ``b`` with ``on[b * LW + l]`` from their accepted
    state to ``t1`` in ``nsub`` generalised-alpha steps (:func:`~.advance.ga_advance`, lane by
    lane), the fairleads' end positions and velocities in ``g.work.fair[9:15]``.  Each lane's
    status into ``g.work.status`` (0, or the failure code with ``g.work.info``: time, node,
    code); ``g.work.stats`` += iterations and halvings; ``g.work.audit`` as ``LineWork.audit``.
    """
    par = g.par
    now = accepted(g, b)
    tr = trial(g, b)
    w = g.work
    lf = w.lf
    li = w.li
    fair = w.fair
    info = w.info
    stats = w.stats
    au = w.audit
    eo = w.eo
    fric = par.flags[b, BF_FRIC]
    nlanes = 0
    for l in range(LW):
        p = b * LW + l
        w.status[p] = 0
        w.mask[b, l] = 1 if on[p] else 0
        nlanes += 1 if on[p] else 0
    if nlanes == 0:
        return
    # the first sub-step from the accepted state need not compute its geometry and tangents
    # when the last force evaluation of every stepping lane was at that state (w.geo 2)
    geo_known = w.geo[b] == 2
    w.geo[b] = 0
    # energy of the accepted state: the start of the first sub-step, as the advance that
    # produced it left it (every lane of the block: w.eacc, the same numbers) or evaluated
    known = True
    for l in range(LW):
        w.etr[b, ix(0, 0, 1, l)] = 0.0
        if w.mask[b, l] != 0 and w.eacc[b, ix(0, 0, 1, l)] != 1.0:
            known = False
    if known:
        for l in range(LW):
            lf[b, ix(LF_EN0, 0, 1, l)] = w.eacc[b, ix(1, 0, 1, l)]
            lf[b, ix(LF_PW0, 0, 1, l)] = w.eacc[b, ix(2, 0, 1, l)]
            lf[b, ix(LF_BUD0, 0, 1, l)] = w.eacc[b, ix(3, 0, 1, l)]
            lf[b, ix(LF_EFLOOR, 0, 1, l)] = w.eacc[b, ix(4, 0, 1, l)]
    else:
        geometry(b, n, now.r, w.el)
        tangents(b, n, w.el, w.q)
        geo_known = True
        energy(b, n, par.P, par.E, par.EC, par.SC, now.r, now.v, now.f, w.el, w.q, eo)
        for l in range(LW):
            lf[b, ix(LF_EN0, 0, 1, l)] = eo[b, ix(EO_EN, 0, 1, l)]
            lf[b, ix(LF_PW0, 0, 1, l)] = eo[b, ix(EO_PW, 0, 1, l)]
            lf[b, ix(LF_BUD0, 0, 1, l)] = eo[b, ix(EO_BUD, 0, 1, l)]
            lf[b, ix(LF_EFLOOR, 0, 1, l)] = AUDIT_FLOOR * eo[b, ix(EO_WSUM, 0, 1, l)]
    # the trial state starts as the accepted one: its friction state is copied
    if _uses_fs(par.flags, b):
        for i in range(n):
            for k in range(N_FS):
                for l in range(LW):
                    if w.mask[b, l] != 0:
                        tr.fs[b, ix(i, k, N_FS, l)] = now.fs[b, ix(i, k, N_FS, l)]
    t0 = t1 - dt
    full = 1
    for _ in range(max_split):
        full *= 2
    total = nsub * full
    hmin = dt / total
    for l in range(LW):
        li[b, ix(LI_POS, 0, 1, l)] = 0 if w.mask[b, l] != 0 else total
        li[b, ix(LI_SZ, 0, 1, l)] = full
    # no sub-step accepted into the trial state yet: a step from the accepted state writes its
    # result straight into the trial buffer (a lane that fails it starts again from the
    # accepted state), else into g.step, copied into the trial for the lanes that accept it
    clean = True
    last_full = False
    while True:
        running = 0
        at_start = 0
        for l in range(LW):
            p = b * LW + l
            ps = li[b, ix(LI_POS, 0, 1, l)]
            if ps >= total or w.status[p] < 0:
                # idle: finite numbers for its share of the passes (never used)
                li[b, ix(LI_ST, 0, 1, l)] = ST_IDLE
                lf[b, ix(LF_DT, 0, 1, l)] = dt
                for k in range(3):
                    fair[b, ix(k, 0, 1, l)] = now.r[b, ix(n - 1, k, 3, l)]
                    fair[b, ix(3 + k, 0, 1, l)] = now.v[b, ix(n - 1, k, 3, l)]
                continue
            sz = li[b, ix(LI_SZ, 0, 1, l)]
            if ps + sz > total:
                sz = total - ps
                li[b, ix(LI_SZ, 0, 1, l)] = sz
            s = (ps + sz) / total
            c = s * (s - 1.0)
            for k in range(3):
                r0k = now.r[b, ix(n - 1, k, 3, l)]
                v0k = now.v[b, ix(n - 1, k, 3, l)]
                rf1 = fair[b, ix(9 + k, 0, 1, l)]
                vf1 = fair[b, ix(12 + k, 0, 1, l)]
                fair[b, ix(k, 0, 1, l)] = r0k + s * (rf1 - r0k) + c * (
                    (2.0 * s - 1.0) * (r0k - rf1) + dt * ((s - 1.0) * v0k + s * vf1))
                fair[b, ix(3 + k, 0, 1, l)] = v0k + s * (vf1 - v0k) + 3.0 * c * (
                    v0k + vf1 - 2.0 * (rf1 - r0k) / dt)
            lf[b, ix(LF_T, 0, 1, l)] = t0 + (ps + sz) * hmin
            lf[b, ix(LF_DT, 0, 1, l)] = sz * hmin
            li[b, ix(LI_ST, 0, 1, l)] = ST_RUN
            li[b, ix(LI_SRC, 0, 1, l)] = 1 if ps == 0 else 0
            running += 1
            at_start += 1 if ps == 0 else 0
        if running == 0:
            break
        # (after the loop: each lane's element tensions are those of its last accepted
        # sub-step, as a line's after ga_advance)
        # the step starts from the accepted state (first sub-step of every running lane) or
        # from the trial state (a lane at its first sub-step gets the accepted state copied)
        direct = clean and at_start == running
        if at_start == running:
            src = now
        else:
            if at_start > 0:
                for l in range(LW):
                    w.mask[b, l] = li[b, ix(LI_SRC, 0, 1, l)] if \
                        li[b, ix(LI_ST, 0, 1, l)] == ST_RUN else 0
                copy_state(b, n, w.mask, now, tr, False)
            src = tr
        res = tr if direct else g.step
        block_step(b, n, par, src, tr.fs, res, w, geo_known and at_start == nlanes)
        geo_known = False
        # energy of the sub-step results (el, q of their force evaluation)
        energy(b, n, par.P, par.E, par.EC, par.SC, res.r, res.v, res.f, w.el, w.q, eo)
        naccept = 0
        for l in range(LW):
            p = b * LW + l
            w.mask[b, l] = 0
            if li[b, ix(LI_ST, 0, 1, l)] == ST_IDLE:
                continue
            it = li[b, ix(LI_RET, 0, 1, l)]
            sz = li[b, ix(LI_SZ, 0, 1, l)]
            tk = lf[b, ix(LF_T, 0, 1, l)]
            if it < 0:
                if sz > 1:
                    li[b, ix(LI_SZ, 0, 1, l)] = sz // 2
                    stats[p, 1] += 1
                    continue
                info[p, 0] = tk
                info[p, 2] = it
                w.status[p] = it
                continue
            en1 = eo[b, ix(EO_EN, 0, 1, l)]
            pw1 = eo[b, ix(EO_PW, 0, 1, l)]
            bud1 = eo[b, ix(EO_BUD, 0, 1, l)]
            pen = eo[b, ix(EO_PEN, 0, 1, l)]
            ipen = int(eo[b, ix(EO_IPEN, 0, 1, l)])
            en0 = lf[b, ix(LF_EN0, 0, 1, l)]
            pw0 = lf[b, ix(LF_PW0, 0, 1, l)]
            bud0 = lf[b, ix(LF_BUD0, 0, 1, l)]
            efloor = lf[b, ix(LF_EFLOOR, 0, 1, l)]
            created = en1 - en0 - 0.5 * sz * hmin * (pw0 + pw1)
            budget = max(bud0, bud1)
            if created > max(AUDIT_REL * budget, efloor):
                if sz > 1:
                    li[b, ix(LI_SZ, 0, 1, l)] = sz // 2
                    stats[p, 1] += 1
                    au[p, AU_SPLITS] += 1
                    continue
                ratio = created / max(budget, efloor)
                au[p, AU_NBAD] += 1
                au[p, AU_EBAD] += created
                jw = _largest(w.tens[b].reshape((n - 1, LW))[:, l])
                if ratio > au[p, AU_WORST]:
                    au[p, AU_WORST] = ratio
                    au[p, AU_TWORST] = tk
                    au[p, AU_EWORST] = jw
                if ratio > AUDIT_HARD:
                    info[p, 0] = tk
                    info[p, 1] = jw
                    info[p, 2] = -4
                    w.status[p] = -4
                    continue
            if pen > au[p, AU_PEN]:
                au[p, AU_PEN] = pen
                au[p, AU_TPEN] = tk
                au[p, AU_NPEN] = ipen
                if pen > 1.0:
                    info[p, 0] = tk
                    info[p, 1] = ipen
                    info[p, 2] = -5
                    w.status[p] = -5
                    continue
            # (indexed, not through a lane view: a view is a call into numba's reshape helper)
            for j in range(n - 1):
                tj = w.tens[b, ix(j, 0, 1, l)]
                if tj < au[p, AU_TMIN]:
                    au[p, AU_TMIN] = tj
                    au[p, AU_TTMIN] = tk
                    au[p, AU_ETMIN] = j
            lf[b, ix(LF_EN0, 0, 1, l)] = en1
            lf[b, ix(LF_PW0, 0, 1, l)] = pw1
            lf[b, ix(LF_BUD0, 0, 1, l)] = bud1
            stats[p, 0] += it
            w.mask[b, l] = 1
            naccept += 1
        last_full = naccept == nlanes
        if naccept > 0:
            if not direct:
                take_step(b, n, w.mask, g.step, tr)
            clean = False
            for l in range(LW):
                if w.mask[b, l] == 0:
                    continue
                p = b * LW + l
                for j in range(n - 1):
                    w.tacc[b, ix(j, 0, 1, l)] = w.tens[b, ix(j, 0, 1, l)]
                sz = li[b, ix(LI_SZ, 0, 1, l)]
                Sl = par.S[p]
                fib = Sl.shape[0] > N_S
                # the lane views only for a friction law that keeps a state or a fibre line
                # (each view is a call into numba's reshape helper: this loop 10.3 -> 6.3
                # kcycles per block step on the flagship, which has neither; RESULTS.md)
                if fric == FR_VDQ or fric == FR_DISPVEL or fib:
                    rl = lane_rows(tr.r, b, n, 3, l)
                    fsl = lane_rows(tr.fs, b, n, N_FS, l)
                    Pl = lane_rows(par.P, b, n, N_NP, l)
                    friction_commit(rl, lane_rows(tr.v, b, n, 3, l),
                                    lane_rows(w.q, b, n, 3, l), fric, fsl, Pl, Sl, Sl[S_ZC])
                    if fib and _has_fibre(par.E, b, n, l):
                        fibre_commit(rl, fsl, Pl, lane_rows(par.E, b, n - 1, N_EL, l), Sl,
                                     sz * hmin)
                ps = li[b, ix(LI_POS, 0, 1, l)] + sz
                li[b, ix(LI_POS, 0, 1, l)] = ps
                while sz < full and ps % (2 * sz) == 0:
                    sz *= 2
                li[b, ix(LI_SZ, 0, 1, l)] = sz
    # el and q of the last sub-step's force evaluation: the trial state's in every lane, when
    # every lane stepped and accepted in it (a lane done earlier has them overwritten)
    w.geo[b] = 1 if last_full else 0
    for l in range(LW):
        if on[b * LW + l] and w.status[b * LW + l] == 0:
            for j in range(n - 1):
                w.tens[b, ix(j, 0, 1, l)] = w.tacc[b, ix(j, 0, 1, l)]
            # the end state's energy: the next advance's start once the trial is accepted
            w.etr[b, ix(0, 0, 1, l)] = 1.0
            w.etr[b, ix(1, 0, 1, l)] = lf[b, ix(LF_EN0, 0, 1, l)]
            w.etr[b, ix(2, 0, 1, l)] = lf[b, ix(LF_PW0, 0, 1, l)]
            w.etr[b, ix(3, 0, 1, l)] = lf[b, ix(LF_BUD0, 0, 1, l)]
            w.etr[b, ix(4, 0, 1, l)] = lf[b, ix(LF_EFLOOR, 0, 1, l)]


@njit(**KERNEL_JIT)
def _has_fibre(E, b, n, l):
    for j in range(n - 1):
        if E[b, ix(j, EL_LAW, N_EL, l)] != 0.0:
            return True
    return False


@njit(**KERNEL_JIT)
def accept(b, n, g, on):
    """Commit the trial state of the lanes of block ``b`` with ``on[b * LW + l]``
    (:func:`~.advance.accept_trial`): the block's two state buffers swap roles, and a lane not
    ``on`` first gets its accepted state copied into the trial buffer, so that it keeps it."""
    w = g.work
    off = 0
    for l in range(LW):
        w.mask[b, l] = 0 if on[b * LW + l] else 1
        off += 0 if on[b * LW + l] else 1
        if on[b * LW + l]:
            for k in range(5):
                w.eacc[b, ix(k, 0, 1, l)] = w.etr[b, ix(k, 0, 1, l)]
    if off > 0:
        copy_state(b, n, w.mask, accepted(g, b), trial(g, b), _uses_fs(g.par.flags, b))
    g.cur[b] = 1 - g.cur[b]
    w.geo[b] = 2 if w.geo[b] == 1 else 0


@njit(**KERNEL_JIT)
def record(g, p, n, out):
    """The output channels of lane row ``p``'s accepted state into ``out``
    (:func:`~.advance.record_into`; the element tensions of its last force evaluation)."""
    b = p // LW
    l = p % LW
    now = accepted(g, b)
    record_into(lane_rows(now.r, b, n, 3, l), lane_rows(now.f, b, n, 3, l),
                g.work.tens[b].reshape((n - 1, LW))[:, l], g.par.S[p, S_ZC], g.par.s_nodes[p],
                out)

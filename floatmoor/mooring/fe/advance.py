"""The advance of a line over a body step: generalised-alpha sub-steps with halving and the
energy audit (:func:`ga_advance`), the commit of a trial state, the explicit comparison step, and
the output channels of a state."""

from __future__ import annotations

import math

from numba import njit

from .blocks import _inv3
from .bundles import LineParams, LineState, LineWork
from .elements import node_mass
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
    _largest,
    line_energy,
)
from .fibre_law import fibre_commit
from .flat import copy_nodes, energy_sums, energy_terms, flat
from .forces import line_forces
from .gen_alpha import gen_alpha_step
from .layout import KERNEL_JIT, N_S, S_DC, S_ZC
from .seabed import friction_commit, friction_decide


@njit(cache=True, inline="always")
def accept_trial(ln):
    """Commit the trial state of the line bundle ``ln`` (``ln.trial`` -> ``ln.now``: the copies
    of :meth:`FELine.accept`).  Element by element: a slice assignment compiles numba's
    shape-mismatch error message (string formatting, about 3 s of a first run)."""
    now = ln.now
    tr = ln.trial
    ec = ln.work.energy
    for k in range(ec.shape[1]):
        ec[1, k] = ec[0, k]
    copy_nodes(flat(tr.r), flat(tr.v), flat(tr.a), flat(tr.f), flat(now.r), flat(now.v),
               flat(now.a), flat(now.f))
    for i in range(tr.r.shape[0]):
        for k in range(tr.fs.shape[1]):
            now.fs[i, k] = tr.fs[i, k]


@njit(**KERNEL_JIT)
def explicit_step(t1, dt, rf1, vf1, s, par, w):
    """Semi-implicit (symplectic) Euler step: ``v += dt M^-1 f(r, v)``, ``r += dt v``; the
    fairlead node follows ``rf1, vf1``.  Updates ``s.r, s.v`` in place (``s`` a
    :class:`~.bundles.LineState`), the forces at the start of the step into ``s.f``, the
    sliding branch into ``s.fs``.  Returns -1, or the first node with a singular mass block /
    NaN."""
    r = s.r
    v = s.v
    f = s.f
    fs = s.fs
    P = par.P
    S = par.S
    W = w.W
    n = r.shape[0]
    node_mass(r, P, w.q, w.Mb)
    friction_decide(r, v, par.fric, fs, S[S_ZC])
    line_forces(r, v, fs, par, bool(False), 0.0, 0.0, f, w)  # noqa: UP018
    for i in range(1, n - 1):
        if not _inv3(w.Mb[i], W[i]):
            return i
        for k in range(3):
            acc = W[i, k, 0] * f[i, 0] + W[i, k, 1] * f[i, 1] + W[i, k, 2] * f[i, 2]
            v[i, k] += dt * acc
            r[i, k] += dt * v[i, k]
            if not math.isfinite(r[i, k]):
                return i
    for k in range(3):
        r[n - 1, k] = rf1[k]
        v[n - 1, k] = vf1[k]
    return -1


@njit(**KERNEL_JIT)
def end_forces(r, v, P, f, tens, out):
    """Force of the line on its end points (N, earth axes): ``out[0:3]`` on the anchor,
    ``out[3:6]`` on the fairlead.  It is minus the nodal force of the end node without its
    inertia: the pull of the adjacent element plus the end node's share of weight, drag and
    seabed load (minus the reaction a support must provide)."""
    n = r.shape[0]
    for k in range(3):
        out[k] = f[0, k]
        out[3 + k] = f[n - 1, k]


@njit(**KERNEL_JIT)
def record_into(r, f, tens, zc, s_nodes, out):
    """Output channels of one step into ``out`` (13,): fairlead force (3), anchor force (3),
    max element tension, its element, touchdown element tension, touchdown x, y, grounded
    length (m, unstretched to the last node in seabed contact), touchdown node (-1: none)."""
    n = r.shape[0]
    for k in range(3):
        out[k] = f[n - 1, k]
        out[3 + k] = f[0, k]
    jm = 0
    for j in range(1, n - 1):
        if tens[j] > tens[jm]:
            jm = j
    out[6] = tens[jm]
    out[7] = jm
    itd = -1
    for i in range(n - 1, -1, -1):
        if r[i, 2] < zc:
            itd = i
            break
    if itd >= 0:
        out[8] = tens[min(itd, n - 2)]
        out[9] = r[itd, 0]
        out[10] = r[itd, 1]
        out[11] = s_nodes[itd]
    else:
        out[8] = math.sqrt(f[0, 0] ** 2 + f[0, 1] ** 2 + f[0, 2] ** 2)
        out[9] = r[0, 0]
        out[10] = r[0, 1]
        out[11] = 0.0
    out[12] = itd


@njit(cache=True, inline="always")
def ga_advance(t1, dt, nsub, max_split, rf1, vf1, now, trial, step, par, w):
    """Trial advance of a line from its accepted state ``now`` (:class:`~.bundles.LineState`
    at ``t1 - dt``) to ``t1`` in ``nsub`` generalised-alpha steps with the fairlead moving
    to ``rf1`` / ``vf1``; a step whose Newton iteration fails is halved (down to
    1/2^max_split of a sub-step) and the step size grows back after each completed pair.
    Inside the advance the fairlead follows the cubic Hermite curve through its accepted
    position and velocity and ``rf1`` / ``vf1`` (the linear interpolation of both used before
    moved the position along the chord while the velocity turned: up to ``a dt^2 / 8`` off the
    path, 0.7 mm for the OC3 line at 3 m / 15 s, a force of ~10 kN on an 18-22 m element of
    EA 3.8e8 N, and sub-stepped runs converged to a different answer; benchmarks/RESULTS.md).
    Trial state into ``trial``; ``step`` holds each sub-step's result; ``w``
    (:class:`~.bundles.LineWork`): ``w.stats[0]`` += Newton iterations, ``w.stats[1]`` +=
    halvings, ``w.rf, w.vf`` the sub-step's fairlead.

    The bundles may also be plain tuples in the same field order: the entry point for one line
    called from Python (numba types a plain tuple of arrays from its C fingerprint, a named
    tuple through Python, ~0.3 us per field, 15 us per call for the ~50 arrays of a line).
    Compiled inline into the numba step loops that call it (:func:`.multi` kernel,
    ``prescribed._run_steps``): numba links and re-optimises the whole callee tree in every
    compiled entry point, so a separate ``ga_advance`` under a step loop costs one more pass
    over :func:`~.gen_alpha.gen_alpha_step` (~3 s of cold compile); the arithmetic is the same.

    Energy audit: every sub-step's energy balance (:func:`~.energy.line_energy`) is checked; a sub-step
    that creates more than :data:`AUDIT_REL` of the line's energy budget (or the floor
    :data:`AUDIT_FLOOR`) is halved like a failed one (``w.stats[1]``, ``w.audit[AU_SPLITS]``);
    at the smallest sub-step it is accepted and recorded in ``w.audit`` (count, energy, worst
    ratio, its time and element), unless it created more than :data:`AUDIT_HARD` of the
    budget (status -4).  The audit reads the states only: a run whose steps create no energy
    is bit for bit the run without it.  Also recorded per accepted sub-step: the deepest
    seabed penetration over its bound (status -5 beyond it, :data:`PEN_WEIGHTS`) and the most
    negative element tension.

    Returns 0, or the failing status of :func:`~.gen_alpha.gen_alpha_step` (-1, -2, -3) or of the audit
    (-4 energy, -5 seabed) with ``w.info[0]`` the time (s) and ``w.info[1]`` the node (-4: the
    element of the largest tension).
    """
    s0 = LineState(*now)
    s1 = LineState(*trial)
    s2 = LineState(*step)
    lp = LineParams(*par)
    lw = LineWork(*w)
    r, v, a, fn, fs = s0
    rA, vA, aA, fnA, fs1 = s1
    rB, vB, aB, fA, _ = s2
    rf = lw.rf
    vf = lw.vf
    info = lw.info
    stats = lw.stats
    au = lw.audit
    fric = lp.fric
    P = lp.P
    E = lp.E
    S = lp.S
    q = lw.q
    n = r.shape[0]
    # energy of the accepted state: the start of the first sub-step (line_energy), as the
    # advance that produced the state left it (LineWork.energy: the same state and element
    # geometry, the same numbers) or evaluated here (after start, or an accept from Python
    # of a state this kernel did not end)
    ec = lw.energy
    if ec[1, 0] == 1.0:
        en0 = ec[1, 1]
        pw0 = ec[1, 2]
        bud0 = ec[1, 3]
        wsum = ec[1, 4]
    else:
        en0, pw0, bud0, wsum, _, _ = line_energy(r, v, fn, P, E, S, lw.el, q, True)
    ec[0, 0] = 0.0
    efloor = AUDIT_FLOOR * wsum
    # the trial state starts as the accepted one: its friction state is copied (a step
    # updates it), the first sub-step reads the nodes straight from the accepted state (s01:
    # the same values, no copy) and every completed sub-step writes its result into the trial
    for i in range(n):
        for k in range(fs.shape[1]):
            fs1[i, k] = fs[i, k]
    s01 = LineState(r, v, a, fn, fs1)
    t0 = t1 - dt
    full = 1
    for _ in range(max_split):
        full *= 2
    total = nsub * full          # sub-step grid in units of the smallest step
    hmin = dt / total
    pos = 0
    sz = full
    while pos < total:
        if pos + sz > total:
            sz = total - pos
        s = (pos + sz) / total
        # fairlead inside the advance: cubic Hermite through the end positions and velocities
        # (position and velocity consistent, exact for a quadratic motion), written as the
        # linear interpolation plus a correction with the factor s (s - 1), which is exactly
        # zero at s = 1: a single step (nsub 1, no halving) takes rf1, vf1 as before
        c = s * (s - 1.0)
        for k in range(3):
            r0k = r[n - 1, k]
            v0k = v[n - 1, k]
            rf[k] = r0k + s * (rf1[k] - r0k) + c * ((2.0 * s - 1.0) * (r0k - rf1[k])
                                                    + dt * ((s - 1.0) * v0k + s * vf1[k]))
            vf[k] = v0k + s * (vf1[k] - v0k) + 3.0 * c * (v0k + vf1[k]
                                                          - 2.0 * (rf1[k] - r0k) / dt)
        tk = t0 + (pos + sz) * hmin
        it = gen_alpha_step(tk, sz * hmin, rf, vf, s01 if pos == 0 else s1, s2, lp, lw)
        if it < 0:
            if sz > 1:
                sz //= 2
                stats[1] += 1
                continue
            info[0] = tk
            info[2] = it
            return it
        # energy audit: a step may not create energy (line_energy); one that does is halved,
        # and at the smallest sub-step it is recorded (or stops the run beyond AUDIT_HARD)
        # (line_energy with geom False: its terms vectorised, summed in its order; the same
        # numbers)
        energy_terms(flat(rB), flat(vB), flat(fA), flat(P), flat(E), flat(lw.el), flat(q),
                     S[S_ZC], S[S_DC], flat(lw.ew))
        en1, pw1, bud1, _, pen, ipen = energy_sums(rB, vB, P, E, lw.el, lw.ew)
        created = en1 - en0 - 0.5 * sz * hmin * (pw0 + pw1)
        budget = max(bud0, bud1)
        if created > max(AUDIT_REL * budget, efloor):
            if sz > 1:
                sz //= 2
                stats[1] += 1
                au[AU_SPLITS] += 1
                continue
            ratio = created / max(budget, efloor)
            au[AU_NBAD] += 1
            au[AU_EBAD] += created
            jw = _largest(lw.tens)
            if ratio > au[AU_WORST]:
                au[AU_WORST] = ratio
                au[AU_TWORST] = tk
                au[AU_EWORST] = jw
            if ratio > AUDIT_HARD:
                info[0] = tk
                info[1] = jw
                info[2] = -4
                return -4
        if pen > au[AU_PEN]:
            au[AU_PEN] = pen
            au[AU_TPEN] = tk
            au[AU_NPEN] = ipen
            if pen > 1.0:
                info[0] = tk
                info[1] = ipen
                info[2] = -5
                return -5
        for j in range(n - 1):
            if lw.tens[j] < au[AU_TMIN]:
                au[AU_TMIN] = lw.tens[j]
                au[AU_TTMIN] = tk
                au[AU_ETMIN] = j
        en0 = en1
        pw0 = pw1
        bud0 = bud1
        stats[0] += it
        copy_nodes(flat(rB), flat(vB), flat(aB), flat(fA), flat(rA), flat(vA), flat(aA),
                   flat(fnA))
        friction_commit(rA, vA, q, fric, fs1, P, S, S[S_ZC])
        if S.shape[0] > N_S:
            fibre_commit(rA, fs1, P, lp.E, S, sz * hmin)
        pos += sz
        while sz < full and pos % (2 * sz) == 0:
            sz *= 2
    # the end state's energy: the next advance's start once this trial is accepted
    ec[0, 0] = 1.0
    ec[0, 1] = en0
    ec[0, 2] = pw0
    ec[0, 3] = bud0
    ec[0, 4] = wsum
    return 0

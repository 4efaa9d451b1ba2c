"""Numba kernels of the lumped-mass line: nodal forces with their tangent, block-tridiagonal
solver, static Newton, generalised-alpha and explicit time steps.

Discretisation (lumped mass, as MoorDyn, OrcaFlex, Aqwa eq. 9-45 to 9-74): nodes 0 (anchor) to
``n-1`` (fairlead), element ``j`` joins nodes ``j`` and ``j+1``.  Element tension
``T = T_el(eps) + B d(eps)/dt`` (only while taut), ``eps = l / L0 - 1``.  At node ``i``: half the
mass, net weight and hydrodynamic load of the adjacent elements; the node tangent ``q`` is the
normalised sum of the adjacent element directions; Morison drag
``-k_n |v_n| v_n - k_t |v_t| v_t`` on the velocity relative to the current split along ``q``;
added mass ``m_an (I - q q^T) + m_at q q^T``; seabed springs and friction (see ``config``).

Tangent: ``K = -df/dx`` and ``C = -df/dv``; element blocks are exact for the axial force
(``dT/dl e e^T + T / l (I - e e^T)``), the drag, seabed and friction blocks are nodal (the
dependence of ``q`` and of the seabed axes on the positions is left out: a quasi-Newton
iteration that still converges quadratically for the dominant axial stiffness).

Every kernel writes into preallocated arrays; none allocates.

Very stiff elements (strain under their weight below ``E0_STIFF``) get a tension estimate in the
generalised-alpha Newton iteration (see :func:`gen_alpha_step`), kept in ``LineWork.act``.

The kernels take their arrays in a few bundles (:mod:`.bundles`): the line parameters
``par``, node states (``LineState``) and the scratch ``w`` (``LineWork``).
"""

from __future__ import annotations

import math

from numba import njit

from .bundles import LineParams, LineState, LineWork
from .fibre_law import EL_FIB, EL_LAW, fibre_commit, fibre_tension  # noqa: F401

# node parameter columns
NP_MASS, NP_W, NP_KDN, NP_KDT, NP_MAN, NP_MAT, NP_KC, NP_MAC, NP_KS, NP_CS, NP_MUA, NP_MUL, \
    NP_MD, NP_CB = range(14)
N_NP = 14
# element parameter columns; EL_LAW (0: the polynomial law C1..C3) and EL_FIB (offset of the
# fibre record in S) of fibre elements: see fibre_law
EL_L0, EL_C1, EL_C2, EL_C3, EL_B = range(5)
N_EL = 7
# scalar parameters
S_ZC, S_VR, S_CD, S_CURC, S_CURS, S_RHO, S_DC, S_BEND, S_SBLIFT = range(9)
N_S = 9
# friction codes (see config.FRICTION_MODELS); 3 = static displacement ramp
FR_NONE, FR_VEL, FR_DISPVEL, FR_STATIC, FR_VDQ = 0, 1, 2, 3, 4
# friction state columns: c_axial, c_lateral, v_prev_axial, v_prev_lateral, ref_x, ref_y,
# branch_axial, branch_lateral (model of Lu 2012: 0 stick, +-1 sliding direction in this step).
# The double-quadratic velocity ramp (FR_VDQ) keeps the horizontal speed (m/s) and the
# transition factor f of the last accepted step in columns FS_UPREV and FS_FPREV.  Column
# FS_EM, FS_TM, FS_KD (8-10) of row j: mean strain of the fibre element j, its working-curve
# tension and dynamic stiffness (fibre_law).
N_FS = 11
FS_UPREV, FS_FPREV = 0, 1
V_MEANINGFUL = 1e-8     # Lu (2012): below this a node is at rest (m/s)
D_MEANINGFUL = 1e-4     # Lu (2012): displacement ramp active beyond this (m)
V_SB = 0.01             # seabed damping switches off between -V_SB and +V_SB (m/s)
EPS_MACH = 2.220446049250313e-16
# An element is "stiff" when its strain under its own weight (in air plus submerged) is below
# E0_STIFF (OC3 chain: 1.4e-4 at EA = 3.84e8 N, 1.4e-7 at 3.84e11, 1.4e-10 at 3.84e14): its
# slack transition (strain e0 = net weight / c1) is then far narrower than the length errors of
# a Newton iterate (second-order transverse terms |dx|^2 / 2 l: 1e-6 m for dx = 6 mm on 18 m),
# and gen_alpha_step manages it by a tension estimate (see there).  Other elements keep the
# plain law and tangent, unchanged.
E0_STIFF = 1e-6
# Modified Newton (``LineParams.newton`` 1, see gen_alpha_step): the kept iteration matrix is
# rebuilt when an iteration with it lowers the residual norm by less than this factor.
NEWTON_THETA = 0.25
# bits of the ``newton`` code of LineParams (gen_alpha_step): the kept iteration matrix of the
# modified iteration, the predictor with the fairlead's extrapolated acceleration, and the stop
# on the quadratic-convergence estimate of the next correction
NW_KEEP = 1
NW_PREDICT = 2
NW_QSTOP = 4
# Energy audit of the generalised-alpha steps (ga_advance, line_energy).  Columns of
# ``LineWork.audit`` (cumulative since FELine.start): steps halved because they created energy;
# accepted steps that still created energy at the smallest step, the energy they created (J),
# the largest such creation over the step's energy budget, its time (s) and element; the
# largest seabed penetration over its bound (PEN_WEIGHTS), its time and node; the most
# negative element tension (N: an element pushing), its time and element.
AU_SPLITS, AU_NBAD, AU_EBAD, AU_WORST, AU_TWORST, AU_EWORST, AU_PEN, AU_TPEN, AU_NPEN, \
    AU_TMIN, AU_TTMIN, AU_ETMIN = range(12)
AUDIT_REL = 0.01
"""A step may create at most this fraction of the line's energy budget (kinetic plus elastic
energy, the larger of the step's two ends) ..."""
AUDIT_FLOOR = 1e-3
"""... or, when that is smaller, the work of lifting the line's submerged weight by this many
metres (1 mm: 1.8 kJ for a 2650 m chain-polyester-chain line, 0.6 kJ for the OC3 line)."""
AUDIT_HARD = 0.25
"""A step at the smallest sub-step that creates more than this fraction of the energy budget
stops the run (status -4): the line's answer is no longer bounded by its energy."""
PEN_WEIGHTS = 100.0
"""Seabed bound: no node deeper below the seabed than where its contact spring carries this
many times the node's submerged weight, nor than :data:`PEN_FLOOR`, whichever is deeper;
deeper stops the run (status -5): the node has gone through the seabed (a light fibre node
landing at 0.5 m/s on MoorDyn's seabed spring goes 13 mm deep, 100 times its static
penetration; a chain node 4.4 mm at rest on the default springs)."""
PEN_FLOOR = 0.5
"""m: the seabed bound is never shallower than this."""


@njit(cache=True)
def _current_scale(cur_z):
    """Levels per metre of the current profile (the guess of :func:`_current`; 0 for fewer
    than two levels)."""
    n = cur_z.shape[0]
    if n < 2 or not cur_z[n - 1] > cur_z[0]:
        return 0.0
    return (n - 1) / (cur_z[n - 1] - cur_z[0])


@njit(cache=True)
def _current(z, cur_z, cur_u, sc):
    """Current speed at the level ``z`` (m/s), linear between the levels ``cur_z``; ``sc`` the
    levels per metre of :func:`_current_scale`."""
    n = cur_z.shape[0]
    if n == 0:
        return 0.0
    if z <= cur_z[0] or n == 1:
        return cur_u[0]
    if z >= cur_z[n - 1]:
        return cur_u[n - 1]
    # the level interval j with cur_z[j] < z <= cur_z[j + 1]: guessed from the mean level
    # spacing and walked from there (no step for the uniform profiles the scenes build; the
    # same interval as a bisection, so the same bits).  Every node looks the current up at
    # every force evaluation.
    g = (z - cur_z[0]) * sc
    j = 0
    if g >= 1.0:
        j = min(int(g), n - 2)
    while j > 0 and cur_z[j] >= z:
        j -= 1
    while cur_z[j + 1] < z:
        j += 1
    w = (z - cur_z[j]) / (cur_z[j + 1] - cur_z[j])
    return (1.0 - w) * cur_u[j] + w * cur_u[j + 1]


@njit(cache=True)
def _tension(eps, c1, c2, c3, e0):
    """Elastic tension and dT/deps: zero in compression, the axial law beyond the small strain
    ``e0``, and in between the cubic ``A eps^2 + B eps^3`` matching the law's value and slope
    at ``e0`` (C1 at the slack transition, so Newton does not cycle on it)."""
    if eps <= 0.0:
        return 0.0, 0.0
    if eps >= e0:
        return (c1 * eps + c2 * eps * eps + c3 * eps * eps * eps,
                c1 + 2.0 * c2 * eps + 3.0 * c3 * eps * eps)
    T0 = c1 * e0 + c2 * e0 * e0 + c3 * e0 * e0 * e0
    D0 = c1 + 2.0 * c2 * e0 + 3.0 * c3 * e0 * e0
    B = (D0 * e0 - 2.0 * T0) / (e0 * e0 * e0)
    A = (T0 - B * e0 * e0 * e0) / (e0 * e0)
    return A * eps * eps + B * eps * eps * eps, 2.0 * A * eps + 3.0 * B * eps * eps


@njit(cache=True)
def _stiff(P, E, j):
    """Element ``j`` is stiff: the strain under its weight in air is below :data:`E0_STIFF`
    (the slack transition e0 uses the net weight; the weight in air keeps weightless test
    elements out)."""
    w = 9.80665 * (P[j, NP_MASS] + P[j + 1, NP_MASS]) + abs(P[j, NP_W]) + abs(P[j + 1, NP_W])
    return w < E0_STIFF * E[j, EL_C1] and E[j, EL_LAW] == 0.0


@njit(cache=True)
def _elem_tension(r, v, P, E, j):
    """Tension of element ``j`` (N) as :func:`line_forces` computes it (elastic law with the
    slack transition plus the faded-in internal damping)."""
    dx = r[j + 1, 0] - r[j, 0]
    dy = r[j + 1, 1] - r[j, 1]
    dz = r[j + 1, 2] - r[j, 2]
    ll = math.sqrt(dx * dx + dy * dy + dz * dz)
    L0 = E[j, EL_L0]
    eps = ll / L0 - 1.0
    e0 = max(abs(P[j, NP_W]) + abs(P[j + 1, NP_W]), 1e-6) / E[j, EL_C1]
    T, dTde = _tension(eps, E[j, EL_C1], E[j, EL_C2], E[j, EL_C3], e0)
    if eps > 0.0:
        ldot = (dx * (v[j + 1, 0] - v[j, 0]) + dy * (v[j + 1, 1] - v[j, 1])
                + dz * (v[j + 1, 2] - v[j, 2])) / ll
        xs = eps / e0
        sm = xs * xs * (3.0 - 2.0 * xs) if xs < 1.0 else 1.0
        T += E[j, EL_B] * sm * ldot / L0
    return T


@njit(cache=True)
def _direction_sum(r, i):
    """Sum of the unit directions of the elements adjacent to node ``i`` (not normalised;
    zero-length elements left out)."""
    n = r.shape[0]
    qx = 0.0
    qy = 0.0
    qz = 0.0
    for j in (i - 1, i):
        if 0 <= j < n - 1:
            dx = r[j + 1, 0] - r[j, 0]
            dy = r[j + 1, 1] - r[j, 1]
            dz = r[j + 1, 2] - r[j, 2]
            ll = math.sqrt(dx * dx + dy * dy + dz * dz)
            if ll > 0.0:
                qx += dx / ll
                qy += dy / ll
                qz += dz / ll
    return qx, qy, qz


@njit(cache=True)
def _set_unit(q, i, qx, qy, qz):
    """``q[i]`` the unit vector along ``(qx, qy, qz)``, or (1, 0, 0) for a zero vector."""
    nq = math.sqrt(qx * qx + qy * qy + qz * qz)
    if nq > 0.0:
        q[i, 0] = qx / nq
        q[i, 1] = qy / nq
        q[i, 2] = qz / nq
    else:
        q[i, 0] = 1.0
        q[i, 1] = 0.0
        q[i, 2] = 0.0


@njit(cache=True)
def node_tangents(r, q):
    """Unit tangent at every node (average of the adjacent element directions)."""
    n = r.shape[0]
    for i in range(n):
        qx, qy, qz = _direction_sum(r, i)
        _set_unit(q, i, qx, qy, qz)


@njit(cache=True)
def _tangents_from(el, q):
    """:func:`node_tangents` from the element directions and lengths ``el`` (n-1, 4) of
    :func:`_line_forces` (the same sums in the same order: the same bits)."""
    n = q.shape[0]
    for i in range(n):
        qx = 0.0
        qy = 0.0
        qz = 0.0
        for j in (i - 1, i):
            if 0 <= j < n - 1 and el[j, 3] > 0.0:
                qx += el[j, 0]
                qy += el[j, 1]
                qz += el[j, 2]
        _set_unit(q, i, qx, qy, qz)


@njit(cache=True)
def node_mass(r, P, q, Mb):
    """3x3 mass blocks (structural + added mass) of every node into ``Mb`` (n, 3, 3)."""
    node_tangents(r, q)
    n = r.shape[0]
    for i in range(n):
        m = P[i, NP_MASS] + P[i, NP_MAC]
        man = P[i, NP_MAN]
        mat = P[i, NP_MAT]
        for a in range(3):
            for b in range(3):
                qq = q[i, a] * q[i, b]
                d = 1.0 if a == b else 0.0
                Mb[i, a, b] = m * d + man * (d - qq) + mat * qq


@njit(cache=True)
def _node_mass_el(r, P, el, q, Mb):
    """:func:`node_mass` with the element directions and lengths computed once into ``el``
    (n-1, 4) as :func:`_line_forces` does and the tangents taken from them
    (:func:`_tangents_from`: the same sums, the same bits as :func:`node_tangents`)."""
    n = r.shape[0]
    for j in range(n - 1):
        dx = r[j + 1, 0] - r[j, 0]
        dy = r[j + 1, 1] - r[j, 1]
        dz = r[j + 1, 2] - r[j, 2]
        ll = math.sqrt(dx * dx + dy * dy + dz * dz)
        el[j, 0] = dx / ll
        el[j, 1] = dy / ll
        el[j, 2] = dz / ll
        el[j, 3] = ll
    _tangents_from(el, q)
    for i in range(n):
        m = P[i, NP_MASS] + P[i, NP_MAC]
        man = P[i, NP_MAN]
        mat = P[i, NP_MAT]
        for a in range(3):
            for b in range(3):
                qq = q[i, a] * q[i, b]
                d = 1.0 if a == b else 0.0
                Mb[i, a, b] = m * d + man * (d - qq) + mat * qq


@njit(cache=True)
def _friction_dirs(qx, qy):
    h = math.sqrt(qx * qx + qy * qy)
    if h > 1e-12:
        ax = qx / h
        ay = qy / h
    else:
        ax = 1.0
        ay = 0.0
    return ax, ay, -ay, ax


@njit(cache=True)
def dq_transition(x, xp, fp):
    """Double-quadratic transition factor (ANSYS 2013 sec. 9.x, eq. 9-62/9-64/9-65 as
    reconstructed in :mod:`floatmoor.mooring.fe.config`) and its slope ``df/dx``.

    ``x = u / v_R`` (current speed over the ramp velocity), ``xp, fp``: the same and the factor
    at the last accepted step.  ``f = 1`` for ``x >= 1``.  Below: with the anchor
    ``(xa, fa) = (min(xp, 1), fp)`` (``fa`` clipped to the reachable band
    ``[xa^2, 2 xa - xa^2]``), the loading branch (``x >= xa``: speed not lower than at the last
    step) is the quadratic with its vertex at ``(1, 1)`` through the anchor,
    ``1 - (1 - fa) ((1 - x) / (1 - xa))^2``, and the unloading branch (``x < xa``) the
    quadratic with its vertex at ``(0, 0)`` through the anchor, ``fa (x / xa)^2``.  From rest
    (anchor (0, 0)) the loading branch is ``2x - x^2`` (eq. 9-64); from full sliding (anchor
    (1, 1)) the unloading branch is ``x^2``.  ``f`` is continuous in ``x`` (kink at ``xa``), so a
    Newton iteration needs no frozen branch.
    """
    if x >= 1.0:
        return 1.0, 0.0
    xa = xp if xp < 1.0 else 1.0
    if xa <= 0.0:
        return x * (2.0 - x), 2.0 - 2.0 * x
    fa = fp
    lo = xa * xa
    hi = xa * (2.0 - xa)
    if fa < lo:
        fa = lo
    elif fa > hi:
        fa = hi
    if x >= xa:
        c = (1.0 - fa) / ((1.0 - xa) * (1.0 - xa))
        return 1.0 - c * (1.0 - x) * (1.0 - x), 2.0 * c * (1.0 - x)
    c = fa / (xa * xa)
    return c * x * x, 2.0 * c * x


@njit(cache=True)
def _dq_g(u, vR, up, fp):
    """``g = f(u / v_R) / u`` (s/m) of the double-quadratic ramp and ``dg/du``, without 0/0 at
    rest (the friction force is ``-N g (mu_a v_a a + mu_l v_l b)``)."""
    x = u / vR
    if x >= 1.0:
        return 1.0 / u, -1.0 / (u * u)
    xa = up / vR
    if xa > 1.0:
        xa = 1.0
    if xa <= 0.0:
        # 2x - x^2 from rest: g = (2 - x) / v_R
        return (2.0 - x) / vR, -1.0 / (vR * vR)
    if x < xa:
        # unloading fa (x / xa)^2: g = c x / v_R, linear in u
        fa = min(max(fp, xa * xa), xa * (2.0 - xa))
        c = fa / (xa * xa)
        return c * x / vR, c / (vR * vR)
    # loading, x >= xa > 0, so u > 0
    f, df = dq_transition(x, xa, fp)
    g = f / u
    return g, (df / vR - g) / u


@njit(cache=True)
def line_forces(r, v, fs, par, want_jac, cK, cC, f, w):
    """Nodal forces of the line and (optionally) the combined tangent ``cK K + cC C``.

    Parameters
    ----------
    r, v : (n, 3) node positions (m) and velocities (m/s), earth axes.
    fs : (n, N_FS) friction state of the last accepted step (read only;
        :func:`friction_decide` and :func:`friction_commit` update it).
    par : :class:`~.bundles.LineParams`: node parameters ``P``, element parameters ``E``,
        scalars ``S``, current profile ``cur_z, cur_u`` (levels increasing, speeds m/s;
        direction in ``S``), wave particle velocity (m/s) and acceleration (m/s^2) at the nodes
        ``wk`` (n, 6) (zeros without waves; the velocity enters the drag, the acceleration the
        fluid inertia), friction code ``fric``.
    want_jac : bool; cK, cC : weights of the tangent.
    f : (n, 3) output, total force on every node (N).
    w : :class:`~.bundles.LineWork`: ``q`` node tangents on return, ``tens`` (n-1,) element
        tensions (N); ``Dg`` (n, 3, 3), ``Of`` (n-1, 3, 3) outputs (overwritten): diagonal and
        upper off-diagonal blocks of ``cK K + cC C`` (element blocks: the lower block equals
        the upper one); ``BX`` (7, n, 3, 3): with bending (``S[S_BEND] > 0``) ``BX[0]``
        lower-minus-upper correction of the first off-diagonal, ``BX[1]`` / ``BX[2]`` the
        upper / lower second off-diagonal blocks (overwritten); ``BX[3:7]`` solver scratch.
    """
    # the flags as plain booleans: numba types a constant argument True / False as a literal
    # and compiles the large force kernel once per literal value (three times over in a coupled
    # FE storm's first run, 3-8 s each); callers pass bool(...) for the same reason
    _line_forces(r, v, fs, par, bool(want_jac), cK, cC, f, w, bool(False))  # noqa: UP018


@njit(cache=True)
def _line_forces(r, v, fs, par, want_jac, cK, cC, f, w, use_act):
    """:func:`line_forces`; with ``use_act``, ``w.act`` (n-1,) holds a tension estimate of
    every element (N, see :func:`gen_alpha_step`): an element in compression with a positive
    estimate acts as a bar, ``T = c1 eps`` (negative) with its axial tangent, instead of
    ``T = 0``, and the geometric stiffness of every element is ``max(act, 0) / l``."""
    P = par.P
    E = par.E
    S = par.S
    cur_z = par.cur_z
    cur_u = par.cur_u
    wk = par.wk
    fric = par.fric
    q = w.q
    tens = w.tens
    Dg = w.Dg
    Of = w.Of
    BX = w.BX
    act = w.act
    el = w.el
    n = r.shape[0]
    # element directions and lengths once (node_tangents' arithmetic, so q is the same)
    for j in range(n - 1):
        dx = r[j + 1, 0] - r[j, 0]
        dy = r[j + 1, 1] - r[j, 1]
        dz = r[j + 1, 2] - r[j, 2]
        ll = math.sqrt(dx * dx + dy * dy + dz * dz)
        el[j, 0] = dx / ll
        el[j, 1] = dy / ll
        el[j, 2] = dz / ll
        el[j, 3] = ll
    _tangents_from(el, q)
    # ---- elements.  Element j adds its force and tangent block to nodes j and j+1; a node's
    # sums are formed in registers in the order of the element loop (the node's own load, then
    # element i-1, then element i) and stored once: the bits of accumulating in place.
    fc0 = 0.0
    fc1 = 0.0
    fc2 = -P[0, NP_W]
    d00 = d01 = d02 = d10 = d11 = d12 = d20 = d21 = d22 = 0.0
    for j in range(n - 1):
        ll = el[j, 3]
        ex = el[j, 0]
        ey = el[j, 1]
        ez = el[j, 2]
        L0 = E[j, EL_L0]
        eps = ll / L0 - 1.0
        # slack transition strain: the element's weight over its axial stiffness
        e0 = max(abs(P[j, NP_W]) + abs(P[j + 1, NP_W]), 1e-6) / E[j, EL_C1]
        if E[j, EL_LAW] == 0.0:
            T, dTde = _tension(eps, E[j, EL_C1], E[j, EL_C2], E[j, EL_C3], e0)
        else:
            T, dTde = fibre_tension(E[j, EL_LAW], eps, fs, j, S, int(E[j, EL_FIB]), e0)
        # stiff element (slack transition narrower than E0_STIFF): managed by the tension
        # estimate of the iteration when one is given
        managed = use_act and _stiff(P, E, j)
        held = managed and act[j] > 0.0
        if held and eps < 0.0:
            # held taut by the iteration's tension estimate: bar in compression
            T = E[j, EL_C1] * eps
            dTde = E[j, EL_C1]
        B = 0.0
        Bj = E[j, EL_B]
        dvx = 0.0
        dvy = 0.0
        dvz = 0.0
        ldot = 0.0
        # (without internal damping, Bj = 0, the damping terms below are zeros added to T and
        # dT/deps, which changes no bit: left out)
        if Bj != 0.0:
            dvx = v[j + 1, 0] - v[j, 0]
            dvy = v[j + 1, 1] - v[j, 1]
            dvz = v[j + 1, 2] - v[j, 2]
            ldot = ex * dvx + ey * dvy + ez * dvz
            if held:
                # a held element keeps its full internal damping: faded over the slack
                # transition (strain e0 = weight / c1, 6e-11 for c1 = 3.84e14 N) the damping
                # force B ldot / L0 would switch on and off between two iterates
                B = Bj
                T += B * ldot / L0
            elif eps > 0.0:
                # internal damping faded in over the slack transition (smooth step)
                xs = eps / e0
                sm = xs * xs * (3.0 - 2.0 * xs) if xs < 1.0 else 1.0
                dsm = 6.0 * xs * (1.0 - xs) / e0 if xs < 1.0 else 0.0
                B = Bj * sm
                T += B * ldot / L0
                dTde += Bj * dsm * ldot / L0
        tens[j] = T
        tx = T * ex
        ty = T * ey
        tz = T * ez
        f[j, 0] = fc0 + tx
        f[j, 1] = fc1 + ty
        f[j, 2] = fc2 + tz
        fc0 = 0.0 - tx
        fc1 = 0.0 - ty
        fc2 = -P[j + 1, NP_W] - tz
        if want_jac:
            if cC == 0.0:
                # statics: a slack element gets its linear axial stiffness in the tangent so
                # that Newton pulls it taut (the residual keeps T = 0); dynamics keep the true
                # tangent.  And the geometric stiffness of a slack or nearly slack element is
                # floored at its own weight over its length (tangent only) so a slack grounded
                # node is not laterally singular
                if eps <= 0.0:
                    ka = cK * E[j, EL_C1] / L0
                else:
                    ka = cK * dTde / L0
                kg = cK * max(T, abs(P[j, NP_W]) + abs(P[j + 1, NP_W])) / ll
            else:
                ka = cK * dTde / L0
                # geometric stiffness from the tension estimate of the iteration when given
                # (the tension of a mixed displacement-tension Newton: not blown up by the
                # second-order length error of the last correction on a very stiff element)
                kg = cK * max(act[j] if managed else T, 0.0) / ll
            cb = 0.0
            kb = 0.0
            if B != 0.0:
                cb = cC * B / L0
                # position derivative of the damping force (B / L0) ldot e through ldot (not
                # symmetric): (B / (L0 l)) e dv_perp^T; the part through e is in the geometric
                # term
                kb = cK * B / (L0 * ll)
            kac = ka + cb
            # (ka + cb) e e^T + kg (I - e e^T), symmetric to the bit (e_a e_b = e_b e_a)
            ee = ex * ex
            v00 = kac * ee + kg * (1.0 - ee)
            ee = ey * ey
            v11 = kac * ee + kg * (1.0 - ee)
            ee = ez * ez
            v22 = kac * ee + kg * (1.0 - ee)
            ee = ex * ey
            v01 = kac * ee + kg * (0.0 - ee)
            v10 = v01
            ee = ex * ez
            v02 = kac * ee + kg * (0.0 - ee)
            v20 = v02
            ee = ey * ez
            v12 = kac * ee + kg * (0.0 - ee)
            v21 = v12
            if kb != 0.0:
                dpx = dvx - ldot * ex
                dpy = dvy - ldot * ey
                dpz = dvz - ldot * ez
                v00 += kb * ex * dpx
                v01 += kb * ex * dpy
                v02 += kb * ex * dpz
                v10 += kb * ey * dpx
                v11 += kb * ey * dpy
                v12 += kb * ey * dpz
                v20 += kb * ez * dpx
                v21 += kb * ez * dpy
                v22 += kb * ez * dpz
            Dg[j, 0, 0] = d00 + v00
            Dg[j, 0, 1] = d01 + v01
            Dg[j, 0, 2] = d02 + v02
            Dg[j, 1, 0] = d10 + v10
            Dg[j, 1, 1] = d11 + v11
            Dg[j, 1, 2] = d12 + v12
            Dg[j, 2, 0] = d20 + v20
            Dg[j, 2, 1] = d21 + v21
            Dg[j, 2, 2] = d22 + v22
            d00 = 0.0 + v00
            d01 = 0.0 + v01
            d02 = 0.0 + v02
            d10 = 0.0 + v10
            d11 = 0.0 + v11
            d12 = 0.0 + v12
            d20 = 0.0 + v20
            d21 = 0.0 + v21
            d22 = 0.0 + v22
            Of[j, 0, 0] = -v00
            Of[j, 0, 1] = -v01
            Of[j, 0, 2] = -v02
            Of[j, 1, 0] = -v10
            Of[j, 1, 1] = -v11
            Of[j, 1, 2] = -v12
            Of[j, 2, 0] = -v20
            Of[j, 2, 1] = -v21
            Of[j, 2, 2] = -v22
    f[n - 1, 0] = fc0
    f[n - 1, 1] = fc1
    f[n - 1, 2] = fc2
    if want_jac:
        Dg[n - 1, 0, 0] = d00
        Dg[n - 1, 0, 1] = d01
        Dg[n - 1, 0, 2] = d02
        Dg[n - 1, 1, 0] = d10
        Dg[n - 1, 1, 1] = d11
        Dg[n - 1, 1, 2] = d12
        Dg[n - 1, 2, 0] = d20
        Dg[n - 1, 2, 1] = d21
        Dg[n - 1, 2, 2] = d22
    # ---- bending (pinned ends): discrete elastica energy c_i (1 - e_a . e_b) at interior nodes
    if S[S_BEND] > 0.0:
        _bending(r, P, f, want_jac, cK, Dg, Of, BX)
    # ---- nodes: drag, clump drag, seabed, friction
    zc = S[S_ZC]
    ccos = S[S_CURC]
    csin = S[S_CURS]
    csc = _current_scale(cur_z)
    for i in range(n):
        qx = q[i, 0]
        qy = q[i, 1]
        qz = q[i, 2]
        uc = _current(r[i, 2], cur_z, cur_u, csc)
        vrx = v[i, 0] - uc * ccos - wk[i, 0]
        vry = v[i, 1] - uc * csin - wk[i, 1]
        vrz = v[i, 2] - wk[i, 2]
        vq = vrx * qx + vry * qy + vrz * qz
        vnx = vrx - vq * qx
        vny = vry - vq * qy
        vnz = vrz - vq * qz
        vn = math.sqrt(vnx * vnx + vny * vny + vnz * vnz)
        kdn = P[i, NP_KDN]
        kdt = P[i, NP_KDT]
        f[i, 0] -= kdn * vn * vnx + kdt * abs(vq) * vq * qx
        f[i, 1] -= kdn * vn * vny + kdt * abs(vq) * vq * qy
        f[i, 2] -= kdn * vn * vnz + kdt * abs(vq) * vq * qz
        # fluid inertia of the wave acceleration (Froude-Krylov + added mass, Morison):
        # (rho V l) a_w + m_an a_w,n + m_at a_w,t
        awx = wk[i, 3]
        awy = wk[i, 4]
        awz = wk[i, 5]
        if awx != 0.0 or awy != 0.0 or awz != 0.0:
            aq = awx * qx + awy * qy + awz * qz
            md = P[i, NP_MD]
            man = P[i, NP_MAN]
            mat = P[i, NP_MAT]
            f[i, 0] += md * awx + man * (awx - aq * qx) + mat * aq * qx
            f[i, 1] += md * awy + man * (awy - aq * qy) + mat * aq * qy
            f[i, 2] += md * awz + man * (awz - aq * qz) + mat * aq * qz
        kc = P[i, NP_KC]
        vr = math.sqrt(vrx * vrx + vry * vry + vrz * vrz) if kc > 0.0 else 0.0
        if kc > 0.0:
            f[i, 0] -= kc * vr * vrx
            f[i, 1] -= kc * vr * vry
            f[i, 2] -= kc * vr * vrz
        if want_jac:
            # kdn |v_n| (I - q q^T) + 2 kdt |v_q| q q^T + kdn v_n v_n^T / |v_n| (+ clump drag)
            kv = kdn * vn
            kt = 2.0 * kdt * abs(vq)
            qq = qx * qx
            v00 = kv * (1.0 - qq) + kt * qq
            qq = qy * qy
            v11 = kv * (1.0 - qq) + kt * qq
            qq = qz * qz
            v22 = kv * (1.0 - qq) + kt * qq
            qq = qx * qy
            v01 = kv * (0.0 - qq) + kt * qq
            v10 = v01
            qq = qx * qz
            v02 = kv * (0.0 - qq) + kt * qq
            v20 = v02
            qq = qy * qz
            v12 = kv * (0.0 - qq) + kt * qq
            v21 = v12
            if vn > 0.0:
                kn = kdn * vnx
                v00 += kn * vnx / vn
                v01 += kn * vny / vn
                v02 += kn * vnz / vn
                kn = kdn * vny
                v10 += kn * vnx / vn
                v11 += kn * vny / vn
                v12 += kn * vnz / vn
                kn = kdn * vnz
                v20 += kn * vnx / vn
                v21 += kn * vny / vn
                v22 += kn * vnz / vn
            if kc > 0.0:
                kr = kc * vr
                v00 += kr * 1.0
                v01 += kr * 0.0
                v02 += kr * 0.0
                v10 += kr * 0.0
                v11 += kr * 1.0
                v12 += kr * 0.0
                v20 += kr * 0.0
                v21 += kr * 0.0
                v22 += kr * 1.0
                if vr > 0.0:
                    kn = kc * vrx
                    v00 += kn * vrx / vr
                    v01 += kn * vry / vr
                    v02 += kn * vrz / vr
                    kn = kc * vry
                    v10 += kn * vrx / vr
                    v11 += kn * vry / vr
                    v12 += kn * vrz / vr
                    kn = kc * vrz
                    v20 += kn * vrx / vr
                    v21 += kn * vry / vr
                    v22 += kn * vrz / vr
            Dg[i, 0, 0] += cC * v00
            Dg[i, 0, 1] += cC * v01
            Dg[i, 0, 2] += cC * v02
            Dg[i, 1, 0] += cC * v10
            Dg[i, 1, 1] += cC * v11
            Dg[i, 1, 2] += cC * v12
            Dg[i, 2, 0] += cC * v20
            Dg[i, 2, 1] += cC * v21
            Dg[i, 2, 2] += cC * v22
        # seabed contact: spring force ks g(pen) with g(p) = p for p >= d = w / (2 ks) (half the
        # static penetration) and the cubic 2 p^2 / d - p^3 / d^2 below (same value and slope
        # at d, zero slope at contact); damping faded in with the smooth step
        # s(p / d) = 3 x^2 - 2 x^3: the force is C1 in the position, so Newton does not cycle
        # when a node touches down
        pen = zc - r[i, 2]
        if pen > 0.0 and P[i, NP_KS] > 0.0:
            ks = P[i, NP_KS]
            dpen = max(0.5 * max(P[i, NP_W], 1e-12) / ks, S[S_DC])
            if pen < dpen:
                x = pen / dpen
                gp = pen * x * (2.0 - x)
                dg = x * (4.0 - 3.0 * x)
                sm = x * x * (3.0 - 2.0 * x)
                dsm = 6.0 * x * (1.0 - x) / dpen
            else:
                gp = pen
                dg = 1.0
                sm = 1.0
                dsm = 0.0
            # the damping acts while the node moves into the seabed, not while it lifts off
            # (the seabed does not pull; a damping force fading out under a lifting node gives
            # a negative stiffness): force -cs sm h(vz), h = vz phi(vz) with phi going smoothly
            # from 1 (vz <= -V_SB) to 0 (vz >= V_SB) so that nodes resting on the seabed
            # (vz ~ 0) do not make Newton switch between two branches
            cs = P[i, NP_CS]
            vz = v[i, 2]
            if vz <= -V_SB or S[S_SBLIFT] > 0.0:
                # (S_SBLIFT, seabed ``lift_off_damping``: the damping acts both ways, as in
                # MoorDyn; it damps the bouncing of the touchdown node of a coarse line)
                h = vz
                dh = 1.0
            elif vz >= V_SB:
                h = 0.0
                dh = 0.0
            else:
                xv = (vz + V_SB) / (2.0 * V_SB)
                phi = 1.0 - xv * xv * (3.0 - 2.0 * xv)
                h = vz * phi
                dh = phi - vz * 6.0 * xv * (1.0 - xv) / (2.0 * V_SB)
            N = ks * gp
            f[i, 2] += N - cs * sm * h
            if want_jac:
                # d/dz = -d/dpen
                Dg[i, 2, 2] += cK * (ks * dg - cs * dsm * h) + cC * cs * sm * dh
            if fric != FR_NONE:
                mua = P[i, NP_MUA]
                mul = P[i, NP_MUL]
                ax, ay, bx, by = _friction_dirs(qx, qy)
                va = v[i, 0] * ax + v[i, 1] * ay
                vl = v[i, 0] * bx + v[i, 1] * by
                if fric == FR_VEL or fric == FR_VDQ:
                    vR = S[S_VR]
                    u = math.sqrt(va * va + vl * vl)
                    if fric == FR_VDQ:
                        g, gp = _dq_g(u, vR, fs[i, FS_UPREV], fs[i, FS_FPREV])
                    elif u < vR:
                        g = 2.0 / vR - u / (vR * vR)
                        gp = -1.0 / (vR * vR)
                    else:
                        g = 1.0 / u
                        gp = -1.0 / (u * u)
                    mx = mua * va * ax + mul * vl * bx
                    my = mua * va * ay + mul * vl * by
                    f[i, 0] -= N * g * mx
                    f[i, 1] -= N * g * my
                    if want_jac:
                        # through the normal force N = ks g(pen): dF/dz = ks g' (f/u) m
                        Dg[i, 0, 2] -= cK * ks * dg * g * mx
                        Dg[i, 1, 2] -= cK * ks * dg * g * my
                        A00 = mua * ax * ax + mul * bx * bx
                        A01 = mua * ax * ay + mul * bx * by
                        A11 = mua * ay * ay + mul * by * by
                        Dg[i, 0, 0] += cC * N * g * A00
                        Dg[i, 0, 1] += cC * N * g * A01
                        Dg[i, 1, 0] += cC * N * g * A01
                        Dg[i, 1, 1] += cC * N * g * A11
                        if u > 0.0:
                            s = cC * N * gp / u
                            Dg[i, 0, 0] += s * mx * v[i, 0]
                            Dg[i, 0, 1] += s * mx * v[i, 1]
                            Dg[i, 1, 0] += s * my * v[i, 0]
                            Dg[i, 1, 1] += s * my * v[i, 1]
                else:
                    Cd = S[S_CD]
                    dxr = r[i, 0] - fs[i, 4]
                    dyr = r[i, 1] - fs[i, 5]
                    for k in range(2):
                        if k == 0:
                            dk_x = ax
                            dk_y = ay
                            mu = mua
                            vk = va
                        else:
                            dk_x = bx
                            dk_y = by
                            mu = mul
                            vk = vl
                        if mu <= 0.0:
                            continue
                        dk = dxr * dk_x + dyr * dk_y
                        kx = 0.0   # stiffness-like tangent (N/m)
                        kv = 0.0   # damping-like tangent (N s/m)
                        if fric == FR_STATIC:
                            # displacement ramp with the quadratic transition 2x - x^2 (C1 at
                            # full friction, like the velocity ramp) so Newton does not stall
                            # on the kink of a linear ramp
                            xd = dk / Cd
                            if xd >= 1.0:
                                c = 1.0
                            elif xd <= -1.0:
                                c = -1.0
                            else:
                                ax_ = abs(xd)
                                c = (2.0 - ax_) * xd
                                kx = mu * N * (2.0 - 2.0 * ax_) / Cd
                        else:
                            c, kx, kv = _dispvel_coef(vk, dk, fs[i, 6 + k], fs[i, k],
                                                      fs[i, 2 + k], S[S_VR], Cd, mu * N)
                        f[i, 0] -= mu * N * c * dk_x
                        f[i, 1] -= mu * N * c * dk_y
                        if want_jac:
                            Dg[i, 0, 2] -= cK * mu * ks * dg * c * dk_x
                            Dg[i, 1, 2] -= cK * mu * ks * dg * c * dk_y
                        if want_jac and (kx > 0.0 or kv > 0.0):
                            w = cK * kx + cC * kv
                            Dg[i, 0, 0] += w * dk_x * dk_x
                            Dg[i, 0, 1] += w * dk_x * dk_y
                            Dg[i, 1, 0] += w * dk_y * dk_x
                            Dg[i, 1, 1] += w * dk_y * dk_y


@njit(cache=True)
def _dispvel_coef(vk, dk, branch, c_prev, v_prev, Cv, Cd, muN):
    """Lu (2012) combined displacement and velocity ramp (sec. 2.2.2, figure 8) for one
    direction, with the branch frozen for the time step.

    ``branch`` 0 (the node was at rest, |v| < 1e-8 m/s, at the start of the step: the previous
    coefficient holds, stick) or the sliding direction +-1.  Sliding: ``c = s max(m1, m2,
    floor)`` with the velocity ramp ``m1 = clip(s v / C_v, 0, 1)``, the displacement ramp
    ``m2 = clip(s d / C_d, 0, 1)`` from the reference (last reversal) position (active beyond
    1e-4 m), and the floor ``|c_prev|`` while the node keeps sliding the same way (no decrease
    unless it reverses).  Freezing the branch keeps ``c`` continuous within the Newton
    iteration.  Returns ``c`` and its tangents (N/m, N s/m) for the friction magnitude ``muN``.
    """
    if branch == 0.0:
        return c_prev, 0.0, 0.0
    sgn = 1.0 if branch > 0.0 else -1.0
    m1 = sgn * vk / Cv
    k1 = muN / Cv
    if m1 <= 0.0:
        m1 = 0.0
        k1 = 0.0
    elif m1 >= 1.0:
        m1 = 1.0
        k1 = 0.0
    m2 = sgn * dk / Cd
    k2 = muN / Cd
    if m2 * Cd <= D_MEANINGFUL:
        m2 = 0.0
        k2 = 0.0
    elif m2 >= 1.0:
        m2 = 1.0
        k2 = 0.0
    floor = 0.0
    if v_prev * sgn > 0.0 and c_prev * sgn > 0.0:
        floor = abs(c_prev)
    if m1 >= m2 and m1 >= floor:
        return sgn * m1, 0.0, k1
    if m2 >= floor:
        return sgn * m2, k2, 0.0
    return sgn * floor, 0.0, 0.0


@njit(cache=True)
def friction_decide(r, v, fric, fs, zc):
    """Start of a time step: freeze the branch of the Lu (2012) model from the predicted
    velocities (stick below 1e-8 m/s, else the sliding direction)."""
    if fric != FR_DISPVEL:
        return
    n = r.shape[0]
    for i in range(n):
        qx, qy, _ = _direction_sum(r, i)
        ax, ay, bx, by = _friction_dirs(qx, qy)
        for k in range(2):
            if k == 0:
                vk = v[i, 0] * ax + v[i, 1] * ay
            else:
                vk = v[i, 0] * bx + v[i, 1] * by
            if abs(vk) < V_MEANINGFUL or not (r[i, 2] < zc):
                fs[i, 6 + k] = 0.0
            else:
                fs[i, 6 + k] = 1.0 if vk > 0.0 else -1.0


@njit(cache=True)
def friction_commit(r, v, q, fric, fs, P, S, zc):
    """End of an accepted time step: store the Lu (2012) friction coefficients and the last
    sliding velocities; a reversal of the sliding direction resets the reference position.
    Double-quadratic ramp: store the horizontal speed and the transition factor of the step
    (zero for nodes off the seabed: a node touching down starts from rest, eq. 9-67)."""
    if fric == FR_VDQ:
        vR = S[S_VR]
        for i in range(r.shape[0]):
            if zc - r[i, 2] > 0.0 and P[i, NP_KS] > 0.0:
                u = math.sqrt(v[i, 0] * v[i, 0] + v[i, 1] * v[i, 1])
                f, df = dq_transition(u / vR, fs[i, FS_UPREV] / vR, fs[i, FS_FPREV])
                fs[i, FS_UPREV] = u
                fs[i, FS_FPREV] = f
            else:
                fs[i, FS_UPREV] = 0.0
                fs[i, FS_FPREV] = 0.0
        return
    if fric != FR_DISPVEL:
        return
    n = r.shape[0]
    Cd = S[S_CD]
    Cv = S[S_VR]
    for i in range(n):
        pen = zc - r[i, 2]
        if not (pen > 0.0):
            for k in range(4):
                fs[i, k] = 0.0
            fs[i, 4] = r[i, 0]
            fs[i, 5] = r[i, 1]
            continue
        ax, ay, bx, by = _friction_dirs(q[i, 0], q[i, 1])
        dxr = r[i, 0] - fs[i, 4]
        dyr = r[i, 1] - fs[i, 5]
        reset = False
        for k in range(2):
            if k == 0:
                vk = v[i, 0] * ax + v[i, 1] * ay
                dk = dxr * ax + dyr * ay
            else:
                vk = v[i, 0] * bx + v[i, 1] * by
                dk = dxr * bx + dyr * by
            c, kx, kv = _dispvel_coef(vk, dk, fs[i, 6 + k], fs[i, k], fs[i, 2 + k], Cv, Cd, 1.0)
            if abs(vk) >= V_MEANINGFUL and vk * fs[i, 2 + k] < 0.0:
                reset = True
            fs[i, k] = c
            if abs(vk) >= V_MEANINGFUL:
                fs[i, 2 + k] = vk
        if reset:
            fs[i, 4] = r[i, 0]
            fs[i, 5] = r[i, 1]


@njit(cache=True)
def _hab(ea, eb, a, b):
    """(P_a P_b)[a, b] with P = I - e e^T."""
    s = 0.0
    for m in range(3):
        s += (((1.0 if a == m else 0.0) - ea[a] * ea[m])
              * ((1.0 if m == b else 0.0) - eb[m] * eb[b]))
    return s


@njit(cache=True)
def _bending(r, P, f, want_jac, cK, Dg, Of, BX):
    """Bending at the interior nodes from the discrete elastica energy
    ``U_i = c_i (1 - e_a . e_b)``, ``c_i = EI / L_mean`` (``U ~ EI kappa^2 L / 2`` for small
    angles), ``e_a, e_b`` the directions of the elements before and after node i; the ends are
    pinned (ANSYS 2013 eq. 9-47).  Forces ``-dU/dx`` and the exact Hessian (block bandwidth 2:
    blocks (i-1, i+1) go to ``BX[1]`` / ``BX[2]``).  No allocation."""
    n = r.shape[0]
    if want_jac:
        for k in range(3):
            for j in range(n):
                for a in range(3):
                    for b in range(3):
                        BX[k, j, a, b] = 0.0
    for i in range(1, n - 1):
        c = P[i, NP_CB]
        if c <= 0.0:
            continue
        ax = r[i, 0] - r[i - 1, 0]
        ay = r[i, 1] - r[i - 1, 1]
        az = r[i, 2] - r[i - 1, 2]
        bx = r[i + 1, 0] - r[i, 0]
        by = r[i + 1, 1] - r[i, 1]
        bz = r[i + 1, 2] - r[i, 2]
        la = math.sqrt(ax * ax + ay * ay + az * az)
        lb = math.sqrt(bx * bx + by * by + bz * bz)
        ea = (ax / la, ay / la, az / la)
        eb = (bx / lb, by / lb, bz / lb)
        p = ea[0] * eb[0] + ea[1] * eb[1] + ea[2] * eb[2]
        # dp/d(delta_a) = P_a e_b / l_a, dp/d(delta_b) = P_b e_a / l_b
        ga = ((eb[0] - p * ea[0]) / la, (eb[1] - p * ea[1]) / la, (eb[2] - p * ea[2]) / la)
        gb = ((ea[0] - p * eb[0]) / lb, (ea[1] - p * eb[1]) / lb, (ea[2] - p * eb[2]) / lb)
        for k in range(3):
            f[i - 1, k] -= c * ga[k]
            f[i, k] += c * (ga[k] - gb[k])
            f[i + 1, k] += c * gb[k]
        if not want_jac:
            continue
        # Hessian of p: H_aa = -(p P_a + e_a u_a^T + u_a e_a^T) / l_a^2 with u_a = P_a e_b,
        # H_ab = P_a P_b / (l_a l_b), H_bb likewise; K = -c Hess(p)
        w = -c * cK
        for a in range(3):
            for b in range(3):
                d = 1.0 if a == b else 0.0
                haa = -(p * (d - ea[a] * ea[b]) + (ea[a] * ga[b] + ga[a] * ea[b]) * la) / (la * la)
                hbb = -(p * (d - eb[a] * eb[b]) + (eb[a] * gb[b] + gb[a] * eb[b]) * lb) / (lb * lb)
                hab = _hab(ea, eb, a, b) / (la * lb)
                hba = _hab(ea, eb, b, a) / (la * lb)
                # H_aa and H_bb are symmetric
                haa_t = haa
                hbb_t = hbb
                Dg[i - 1, a, b] += w * haa
                Dg[i, a, b] += w * (haa - hab - hba + hbb)
                Dg[i + 1, a, b] += w * hbb
                # first off-diagonal: upper (i-1, i) = -(Haa - Hab), lower (i, i-1) its
                # transpose; upper (i, i+1) = Hab - Hbb, lower (i+1, i) its transpose
                up = -w * (haa - hab)
                lo = -w * (haa_t - hba)
                Of[i - 1, a, b] += up
                BX[0, i - 1, a, b] += lo - up
                up = w * (hab - hbb)
                lo = w * (hba - hbb_t)
                Of[i, a, b] += up
                BX[0, i, a, b] += lo - up
                # second off-diagonal: (i-1, i+1) = -Hab, (i+1, i-1) its transpose
                BX[1, i - 1, a, b] += -w * hab
                BX[2, i - 1, a, b] += -w * hba


@njit(cache=True)
def solve_blocks(Dg, Of, BX, bend, rhs, i0, i1, W, Y, T1, x):
    """Solve the iteration system: block-tridiagonal, or block bandwidth 2 with bending."""
    if bend:
        return block_band_solve(Dg, Of, BX, rhs, i0, i1, Y, T1, x)
    return block_tridiag_solve(Dg, Of, rhs, i0, i1, W, Y, T1, x)


@njit(cache=True)
def block_band_solve(Dg, Of, BX, rhs, i0, i1, Y, T1, x):
    """Block Gaussian elimination (no pivoting between blocks, exact 3x3 inverses) for block
    bandwidth 2: diagonal ``Dg``, first upper ``Of[i]`` (i, i+1), first lower ``Of[i] +
    BX[0, i]`` (i+1, i), second upper ``BX[1, i]`` (i, i+2), second lower ``BX[2, i]``
    (i+2, i).  Scratch ``BX[3:7]``; ``Y`` (n, 3), ``T1`` (3, 3).  Returns -1 or the first
    singular pivot node."""
    Wi = BX[3]
    D = BX[4]
    U1 = BX[5]
    L1 = BX[6]
    n = Dg.shape[0]
    for i in range(i0, i1):
        for a in range(3):
            Y[i, a] = rhs[i, a]
            for b in range(3):
                D[i, a, b] = Dg[i, a, b]
                if i < n - 1:
                    U1[i, a, b] = Of[i, a, b]
                    L1[i, a, b] = Of[i, a, b] + BX[0, i, a, b]
    for k in range(i0, i1):
        if not _inv3(D[k], Wi[k]):
            return k
        for i in (k + 1, k + 2):
            if i >= i1:
                continue
            # M = A_ik W_k
            for a in range(3):
                for b in range(3):
                    s = 0.0
                    for m in range(3):
                        aik = L1[k, a, m] if i == k + 1 else BX[2, k, a, m]
                        s += aik * Wi[k, m, b]
                    T1[a, b] = s
            for a in range(3):
                Y[i, a] -= T1[a, 0] * Y[k, 0] + T1[a, 1] * Y[k, 1] + T1[a, 2] * Y[k, 2]
            for j in (k + 1, k + 2):
                if j >= i1:
                    continue
                for a in range(3):
                    for b in range(3):
                        s = 0.0
                        for m in range(3):
                            akj = U1[k, m, b] if j == k + 1 else BX[1, k, m, b]
                            s += T1[a, m] * akj
                        if i == j:
                            D[i, a, b] -= s
                        elif j == i + 1:
                            U1[i, a, b] -= s
                        else:  # j == i - 1: lower block (i, i-1) stored at L1[i-1]
                            L1[j, a, b] -= s
    for k in range(i1 - 1, i0 - 1, -1):
        for a in range(3):
            s = Y[k, a]
            if k + 1 < i1:
                s -= (U1[k, a, 0] * x[k + 1, 0] + U1[k, a, 1] * x[k + 1, 1]
                      + U1[k, a, 2] * x[k + 1, 2])
            if k + 2 < i1:
                s -= (BX[1, k, a, 0] * x[k + 2, 0] + BX[1, k, a, 1] * x[k + 2, 1]
                      + BX[1, k, a, 2] * x[k + 2, 2])
            T1[0, a] = s
        for a in range(3):
            x[k, a] = Wi[k, a, 0] * T1[0, 0] + Wi[k, a, 1] * T1[0, 1] + Wi[k, a, 2] * T1[0, 2]
    return -1


# --------------------------------------------------------------------------------------------
# linear algebra
# --------------------------------------------------------------------------------------------
@njit(cache=True)
def _inv3(A, out):
    a, b, c = A[0, 0], A[0, 1], A[0, 2]
    d, e, g = A[1, 0], A[1, 1], A[1, 2]
    h, k, m = A[2, 0], A[2, 1], A[2, 2]
    c00 = e * m - g * k
    c01 = -(d * m - g * h)
    c02 = d * k - e * h
    det = a * c00 + b * c01 + c * c02
    if det == 0.0 or not math.isfinite(det):
        return False
    inv = 1.0 / det
    out[0, 0] = c00 * inv
    out[1, 0] = c01 * inv
    out[2, 0] = c02 * inv
    out[0, 1] = -(b * m - c * k) * inv
    out[1, 1] = (a * m - c * h) * inv
    out[2, 1] = -(a * k - b * h) * inv
    out[0, 2] = (b * g - c * e) * inv
    out[1, 2] = -(a * g - c * d) * inv
    out[2, 2] = (a * e - b * d) * inv
    return True


@njit(cache=True)
def _inv3_vals(a, b, c, d, e, g, h, k, m):
    """:func:`_inv3` of the block ``[[a, b, c], [d, e, g], [h, k, m]]`` given by its entries
    (the same arithmetic): ``ok`` and the nine entries of the inverse by rows."""
    c00 = e * m - g * k
    c01 = -(d * m - g * h)
    c02 = d * k - e * h
    det = a * c00 + b * c01 + c * c02
    if det == 0.0 or not math.isfinite(det):
        return (False, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
    inv = 1.0 / det
    return (True, c00 * inv, -(b * m - c * k) * inv, (b * g - c * e) * inv,
            c01 * inv, (a * m - c * h) * inv, -(a * g - c * d) * inv,
            c02 * inv, -(a * k - b * h) * inv, (a * e - b * d) * inv)


@njit(cache=True)
def block_tridiag_solve(Dg, Of, rhs, i0, i1, W, Y, T1, x):
    """Solve the block-tridiagonal system on nodes ``i0 .. i1-1`` (3x3 blocks).

    Diagonal blocks ``Dg[i]``, upper blocks ``Of[i]`` (row i, column i+1) and lower blocks
    ``Of[i-1]`` (row i, column i-1): element-assembled matrices have the same coupling block on
    both sides of the diagonal, symmetric or not.  ``W`` (n,3,3), ``Y`` (n,3), ``T1`` (3,3)
    scratch; solution into ``x`` (n,3).  On return ``W[i]`` holds the inverse pivots and ``Y``
    the forward-swept right-hand side (:func:`block_tridiag_resolve` reuses them).
    Returns the first node whose pivot block is singular, or -1.

    Block Gaussian elimination: pivot ``G_i = Dg[i] - Of[i-1] W[i-1] Of[i-1]``, ``W[i] =
    G_i^-1`` (:func:`_inv3_vals`), ``y_i = rhs[i] - Of[i-1] W[i-1] y_i-1``, then the backward
    sweep ``x_i = W[i] (y_i - Of[i] x_i+1)``.  Written out on scalars (the previous pivot's
    inverse and right-hand side carried in locals): every sum keeps the order of the
    loop form, ``p0 + p1 + p2`` (the loop's leading ``0.0 +`` left out: it changes at most
    the sign of a zero, which no later product, sum or quotient by a non-zero pivot carries
    into a non-zero number).
    """
    w00 = w01 = w02 = w10 = w11 = w12 = w20 = w21 = w22 = 0.0
    y0 = y1 = y2 = 0.0
    for i in range(i0, i1):
        g00 = Dg[i, 0, 0]
        g01 = Dg[i, 0, 1]
        g02 = Dg[i, 0, 2]
        g10 = Dg[i, 1, 0]
        g11 = Dg[i, 1, 1]
        g12 = Dg[i, 1, 2]
        g20 = Dg[i, 2, 0]
        g21 = Dg[i, 2, 1]
        g22 = Dg[i, 2, 2]
        r0 = rhs[i, 0]
        r1 = rhs[i, 1]
        r2 = rhs[i, 2]
        if i > i0:
            p = i - 1
            # W[p] y[p]
            z0 = w00 * y0 + w01 * y1 + w02 * y2
            z1 = w10 * y0 + w11 * y1 + w12 * y2
            z2 = w20 * y0 + w21 * y1 + w22 * y2
            o00 = Of[p, 0, 0]
            o01 = Of[p, 0, 1]
            o02 = Of[p, 0, 2]
            o10 = Of[p, 1, 0]
            o11 = Of[p, 1, 1]
            o12 = Of[p, 1, 2]
            o20 = Of[p, 2, 0]
            o21 = Of[p, 2, 1]
            o22 = Of[p, 2, 2]
            # H = W[p] Of[p]
            h00 = w00 * o00 + w01 * o10 + w02 * o20
            h01 = w00 * o01 + w01 * o11 + w02 * o21
            h02 = w00 * o02 + w01 * o12 + w02 * o22
            h10 = w10 * o00 + w11 * o10 + w12 * o20
            h11 = w10 * o01 + w11 * o11 + w12 * o21
            h12 = w10 * o02 + w11 * o12 + w12 * o22
            h20 = w20 * o00 + w21 * o10 + w22 * o20
            h21 = w20 * o01 + w21 * o11 + w22 * o21
            h22 = w20 * o02 + w21 * o12 + w22 * o22
            # G -= Of[p] H ;  y -= Of[p] (W[p] y[p])
            g00 -= o00 * h00 + o01 * h10 + o02 * h20
            g01 -= o00 * h01 + o01 * h11 + o02 * h21
            g02 -= o00 * h02 + o01 * h12 + o02 * h22
            r0 -= o00 * z0 + o01 * z1 + o02 * z2
            g10 -= o10 * h00 + o11 * h10 + o12 * h20
            g11 -= o10 * h01 + o11 * h11 + o12 * h21
            g12 -= o10 * h02 + o11 * h12 + o12 * h22
            r1 -= o10 * z0 + o11 * z1 + o12 * z2
            g20 -= o20 * h00 + o21 * h10 + o22 * h20
            g21 -= o20 * h01 + o21 * h11 + o22 * h21
            g22 -= o20 * h02 + o21 * h12 + o22 * h22
            r2 -= o20 * z0 + o21 * z1 + o22 * z2
        Y[i, 0] = r0
        Y[i, 1] = r1
        Y[i, 2] = r2
        y0 = r0
        y1 = r1
        y2 = r2
        ok, w00, w01, w02, w10, w11, w12, w20, w21, w22 = _inv3_vals(
            g00, g01, g02, g10, g11, g12, g20, g21, g22)
        if not ok:
            return i
        W[i, 0, 0] = w00
        W[i, 0, 1] = w01
        W[i, 0, 2] = w02
        W[i, 1, 0] = w10
        W[i, 1, 1] = w11
        W[i, 1, 2] = w12
        W[i, 2, 0] = w20
        W[i, 2, 1] = w21
        W[i, 2, 2] = w22
    # backward sweep: x_i = W[i] (y_i - Of[i] x_i+1), W[n-1] (and y) of the last node still in
    # the locals
    x0 = x1 = x2 = 0.0
    for i in range(i1 - 1, i0 - 1, -1):
        s0 = Y[i, 0]
        s1 = Y[i, 1]
        s2 = Y[i, 2]
        if i < i1 - 1:
            s0 = s0 - Of[i, 0, 0] * x0 - Of[i, 0, 1] * x1 - Of[i, 0, 2] * x2
            s1 = s1 - Of[i, 1, 0] * x0 - Of[i, 1, 1] * x1 - Of[i, 1, 2] * x2
            s2 = s2 - Of[i, 2, 0] * x0 - Of[i, 2, 1] * x1 - Of[i, 2, 2] * x2
        x0 = W[i, 0, 0] * s0 + W[i, 0, 1] * s1 + W[i, 0, 2] * s2
        x1 = W[i, 1, 0] * s0 + W[i, 1, 1] * s1 + W[i, 1, 2] * s2
        x2 = W[i, 2, 0] * s0 + W[i, 2, 1] * s1 + W[i, 2, 2] * s2
        x[i, 0] = x0
        x[i, 1] = x1
        x[i, 2] = x2
    return -1


@njit(cache=True)
def block_tridiag_resolve(Of, rhs, i0, i1, W, Y, x):
    """Solve the system factorised by the last :func:`block_tridiag_solve` (its inverse pivots
    ``W`` and off-diagonal blocks ``Of``, unchanged since) for a new right-hand side ``rhs``:
    the forward and backward sweeps alone, without the pivots.  ``Y`` (n, 3) scratch; solution
    into ``x`` (n, 3)."""
    for i in range(i0, i1):
        for a in range(3):
            Y[i, a] = rhs[i, a]
        if i > i0:
            p = i - 1
            for a in range(3):
                x[p, a] = W[p, a, 0] * Y[p, 0] + W[p, a, 1] * Y[p, 1] + W[p, a, 2] * Y[p, 2]
            for a in range(3):
                Y[i, a] -= Of[p, a, 0] * x[p, 0] + Of[p, a, 1] * x[p, 1] + Of[p, a, 2] * x[p, 2]
    for i in range(i1 - 1, i0 - 1, -1):
        s0 = Y[i, 0]
        s1 = Y[i, 1]
        s2 = Y[i, 2]
        if i < i1 - 1:
            s0 -= Of[i, 0, 0] * x[i + 1, 0] + Of[i, 0, 1] * x[i + 1, 1] + Of[i, 0, 2] * x[i + 1, 2]
            s1 -= Of[i, 1, 0] * x[i + 1, 0] + Of[i, 1, 1] * x[i + 1, 1] + Of[i, 1, 2] * x[i + 1, 2]
            s2 -= Of[i, 2, 0] * x[i + 1, 0] + Of[i, 2, 1] * x[i + 1, 1] + Of[i, 2, 2] * x[i + 1, 2]
        for a in range(3):
            x[i, a] = W[i, a, 0] * s0 + W[i, a, 1] * s1 + W[i, a, 2] * s2


# --------------------------------------------------------------------------------------------
# statics
# --------------------------------------------------------------------------------------------
@njit(cache=True)
def static_newton(r, v0, fs, par, f, w, max_step=0.0):
    """Damped Newton (Levenberg-Marquardt) for the static equilibrium of the free nodes
    (1 .. n-2); the end nodes stay where they are.  ``v0`` zero velocities (n, 3); ``fs``
    friction state, ``par`` (:class:`~.bundles.LineParams`: static axial law in ``E``,
    friction code ``fric``, tolerance ``tol`` (N) and ``maxit``), nodal forces into ``f``,
    scratch ``w`` (:class:`~.bundles.LineWork`, element tensions ``w.tens``).

    A step ``(K + lam I) dx = f`` is accepted when it lowers the 2-norm of the nodal residual;
    ``lam`` (N/m) starts at 0 (pure Newton), grows by 10 from the weight of a node over its
    element length when a step fails and falls by 10 after a success.

    ``max_step`` > 0 (m; default 0: off, the iteration above exactly) adds a trust radius on
    the largest nodal move: a step longer than the radius is scaled down to it along its
    direction; a failed step quarters the radius (down to ``1e-3 max_step``, below which the
    damping ``lam`` takes over as above) and an accepted scaled step doubles it.  For lines
    with very soft modes (a grounded chain pushed sideways by current: 15-24 N/m against the
    damping floor of ~1e3 N/m) the damped steps hardly move along those modes, while a
    shortened Newton step does (:class:`~.current_statics.LineCurrentStatics`).

    ``info[0]`` iterations, ``info[1]`` final max residual (N), ``info[2]`` node with the
    largest residual.  Returns 0 when converged (max nodal residual < ``tol`` N), -1 when not,
    -2 singular tangent (``info[2]`` = node).
    """
    P = par.P
    E = par.E
    S = par.S
    tol = par.tol
    maxit = par.maxit
    Dg = w.Dg
    Of = w.Of
    BX = w.BX
    W = w.W
    Y = w.Y
    T1 = w.T1
    dx = w.dx
    rtry = w.rtry
    info = w.info
    n = r.shape[0]
    lam_min = 0.0
    for i in range(n):
        lam_min = max(lam_min, abs(P[i, NP_W]))
    lam_min /= max(E[0, EL_L0], 1e-12)
    jac = bool(True)  # noqa: UP018 (a plain boolean, not a literal: see line_forces)
    line_forces(r, v0, fs, par, jac, 1.0, 0.0, f, w)
    res2 = _res2(f, n)
    lam = 0.0
    it = 0
    radius = max_step
    trust = False
    while it < maxit:
        info[0] = it
        info[1] = _max_res(f, n)
        if info[1] < tol:
            break
        it += 1
        if lam > 0.0:
            for i in range(1, n - 1):
                for a in range(3):
                    Dg[i, a, a] += lam
        bad = solve_blocks(Dg, Of, BX, S[S_BEND] > 0.0, f, 1, n - 1, W, Y, T1, dx)
        if bad >= 0:
            if lam == 0.0:
                lam = lam_min
                line_forces(r, v0, fs, par, jac, 1.0, 0.0, f, w)
                continue
            info[2] = bad
            return -2
        trust = max_step > 0.0 and radius > 1e-6 * max_step
        scaled = _limit_step(dx, n, radius) if trust else False
        for i in range(n):
            for a in range(3):
                rtry[i, a] = r[i, a] + (dx[i, a] if 0 < i < n - 1 else 0.0)
        line_forces(rtry, v0, fs, par, jac, 1.0, 0.0, f, w)
        r2 = _res2(f, n)
        if r2 < res2 or _max_res(f, n) < tol:
            for i in range(n):
                for a in range(3):
                    r[i, a] = rtry[i, a]
            res2 = r2
            lam = lam / 10.0 if lam > 100.0 * lam_min else 0.0
            if scaled:
                radius *= 2.0
        elif trust:
            radius = 0.25 * min(radius, _max_move(dx, n))
            line_forces(r, v0, fs, par, jac, 1.0, 0.0, f, w)
        else:
            lam = lam_min if lam == 0.0 else 10.0 * lam
            if lam > 1e30:
                break
            line_forces(r, v0, fs, par, jac, 1.0, 0.0, f, w)
    line_forces(r, v0, fs, par, jac, 1.0, 0.0, f, w)
    info[0] = it
    info[1] = _max_res(f, n)
    worst = 1
    for i in range(1, n - 1):
        if (abs(f[i, 0]) + abs(f[i, 1]) + abs(f[i, 2])
                > abs(f[worst, 0]) + abs(f[worst, 1]) + abs(f[worst, 2])):
            worst = i
    info[2] = worst
    return 0 if info[1] < tol else -1


@njit(cache=True)
def _max_move(dx, n):
    m = 0.0
    for i in range(1, n - 1):
        m = max(m, dx[i, 0] * dx[i, 0] + dx[i, 1] * dx[i, 1] + dx[i, 2] * dx[i, 2])
    return math.sqrt(m)


@njit(cache=True)
def _limit_step(dx, n, radius):
    """Scale the free nodes' moves ``dx`` so that the largest is at most ``radius`` (m);
    True when scaled."""
    m = _max_move(dx, n)
    if not m > radius:
        return False
    c = radius / m
    for i in range(1, n - 1):
        for a in range(3):
            dx[i, a] *= c
    return True


@njit(cache=True)
def _res2(f, n):
    m = 0.0
    for i in range(1, n - 1):
        for a in range(3):
            m += f[i, a] * f[i, a]
    return m if math.isfinite(m) else math.inf


@njit(cache=True)
def _max_res(f, n):
    m = 0.0
    for i in range(1, n - 1):
        for a in range(3):
            if not math.isfinite(f[i, a]):
                return math.inf
            if abs(f[i, a]) > m:
                m = abs(f[i, a])
    return m


# --------------------------------------------------------------------------------------------
# energy audit
# --------------------------------------------------------------------------------------------
@njit(cache=True)
def _elastic_energy(eps, c1, c2, c3, e0, L0):
    """Elastic energy (J) of an element of unstretched length ``L0`` at strain ``eps``: the
    integral of :func:`_tension` (zero in compression, the cubic transition below ``e0``, the
    polynomial law above)."""
    if eps <= 0.0:
        return 0.0
    T0 = c1 * e0 + c2 * e0 * e0 + c3 * e0 * e0 * e0
    D0 = c1 + 2.0 * c2 * e0 + 3.0 * c3 * e0 * e0
    B = (D0 * e0 - 2.0 * T0) / (e0 * e0 * e0)
    A = (T0 - B * e0 * e0 * e0) / (e0 * e0)
    if eps < e0:
        return L0 * (A * eps ** 3 / 3.0 + B * eps ** 4 / 4.0)
    return L0 * (A * e0 ** 3 / 3.0 + B * e0 ** 4 / 4.0
                 + c1 * (eps * eps - e0 * e0) / 2.0 + c2 * (eps ** 3 - e0 ** 3) / 3.0
                 + c3 * (eps ** 4 - e0 ** 4) / 4.0)


@njit(cache=True)
def _largest(x):
    """Index of the largest entry of ``x``."""
    k = 0
    for j in range(1, x.shape[0]):
        if x[j] > x[k]:
            k = j
    return k


@njit(cache=True)
def line_energy(r, v, f, P, E, S, el, q, geom):
    """Mechanical energy of a line state and the power put into it, for the energy audit of
    the time steps (:func:`ga_advance`).

    ``E_m = sum_i (1/2 v_i^T M_i v_i + w_i z_i + U_s,i) + sum_j U_j`` over the free nodes ``i``
    (mass with added mass ``M_i`` as in :func:`node_mass`, submerged weight ``w_i``, seabed
    spring energy ``U_s``) and the elements ``j`` of the polynomial law (energy ``U_j`` of
    :func:`_elastic_energy`) that are not stiff (:func:`_stiff`: the strain of a practically
    inextensible element is known only to the Newton tolerance over its length, 5e-8 for
    1 um on 18 m, which is 2e7 N at EA = 3.84e14 N: its tension is no measure of stored
    energy, and it stores none to speak of).  Everything else is an external force on the audited system:
    ``P = sum_i (f_i + w_i e_z - N_i e_z) . v_i + sum_j T_j dl_j/dt`` (``f`` the total nodal
    force of the state, ``N_i`` the seabed spring force, ``T_j`` the elastic tension of a
    polynomial element; plus the internal damping force of the fairlead's element times the
    fairlead velocity) is the power of the fairlead, the drag (with current and waves),
    the seabed damping and friction, the internal damping and the forces of the fibre and
    stiff elements and of bending, so ``dE_m/dt = P`` holds exactly for the time-continuous line.  A time step that
    creates energy, ``E_m(t1) - E_m(t0) - dt (P(t0) + P(t1)) / 2`` positive beyond the
    trapezoidal rule's error, is wrong: the generalised-alpha scheme dissipates energy in the
    linear regime, but its unconditional stability is a linear result (Chung & Hulbert 1993)
    that does not carry over to nonlinear problems; with elements switching between slack and
    taut within a step longer than their axial period (a grounded chain pushed slack by the
    current and snapped taut again), steps gain energy and the line blows up: 12 MN along a
    slack Floatel-like line whose fairlead never passed 4 MN (docs/FE_LINES.md).

    ``el`` (n-1, 4), ``q`` (n, 3): element directions and lengths and node tangents of the
    state; ``geom`` True computes them from ``r`` (overwriting both), False takes them as they
    are (from the state's force evaluation).  Returns ``(E_m, P, budget, wsum, pen, ipen)``:
    ``budget`` the kinetic plus elastic energy (J), ``wsum`` the summed absolute submerged
    weight of the free nodes (N), ``pen`` the largest seabed penetration over its bound
    (:data:`PEN_WEIGHTS`) and ``ipen`` its node.
    """
    n = r.shape[0]
    if geom:
        for j in range(n - 1):
            dx = r[j + 1, 0] - r[j, 0]
            dy = r[j + 1, 1] - r[j, 1]
            dz = r[j + 1, 2] - r[j, 2]
            ll = math.sqrt(dx * dx + dy * dy + dz * dz)
            el[j, 0] = dx / ll
            el[j, 1] = dy / ll
            el[j, 2] = dz / ll
            el[j, 3] = ll
        _tangents_from(el, q)
    ue = 0.0
    pw = 0.0
    for j in range(n - 1):
        if E[j, EL_LAW] != 0.0 or _stiff(P, E, j):
            continue
        L0 = E[j, EL_L0]
        eps = el[j, 3] / L0 - 1.0
        if eps <= 0.0:
            continue
        c1 = E[j, EL_C1]
        e0 = max(abs(P[j, NP_W]) + abs(P[j + 1, NP_W]), 1e-6) / c1
        T, _ = _tension(eps, c1, E[j, EL_C2], E[j, EL_C3], e0)
        ue += _elastic_energy(eps, c1, E[j, EL_C2], E[j, EL_C3], e0, L0)
        ldot = (el[j, 0] * (v[j + 1, 0] - v[j, 0]) + el[j, 1] * (v[j + 1, 1] - v[j, 1])
                + el[j, 2] * (v[j + 1, 2] - v[j, 2]))
        pw += T * ldot
        if j == n - 2 and E[j, EL_B] != 0.0:
            # the internal damping force of the fairlead's element works at the fairlead
            xs = eps / e0
            sm = xs * xs * (3.0 - 2.0 * xs) if xs < 1.0 else 1.0
            Td = E[j, EL_B] * sm * ldot / L0
            pw += Td * (el[j, 0] * v[j + 1, 0] + el[j, 1] * v[j + 1, 1] + el[j, 2] * v[j + 1, 2])
    zc = S[S_ZC]
    ke = 0.0
    eg = 0.0
    wsum = 0.0
    pen_max = 0.0
    ipen = 0
    for i in range(1, n - 1):
        vx = v[i, 0]
        vy = v[i, 1]
        vz = v[i, 2]
        vv = vx * vx + vy * vy + vz * vz
        vq = vx * q[i, 0] + vy * q[i, 1] + vz * q[i, 2]
        ke += 0.5 * ((P[i, NP_MASS] + P[i, NP_MAC]) * vv + P[i, NP_MAN] * (vv - vq * vq)
                     + P[i, NP_MAT] * vq * vq)
        w = P[i, NP_W]
        wsum += abs(w)
        eg += w * r[i, 2]
        pw += f[i, 0] * vx + f[i, 1] * vy + f[i, 2] * vz + w * vz
        pen = zc - r[i, 2]
        ks = P[i, NP_KS]
        if pen > 0.0 and ks > 0.0:
            dpen = max(0.5 * max(w, 1e-12) / ks, S[S_DC])
            if pen < dpen:
                x = pen / dpen
                gp = pen * x * (2.0 - x)
                eg += ks * (2.0 * pen ** 3 / (3.0 * dpen) - pen ** 4 / (4.0 * dpen * dpen))
            else:
                gp = pen
                eg += ks * (5.0 * dpen * dpen / 12.0 + 0.5 * (pen * pen - dpen * dpen))
            pw -= ks * gp * vz
            lim = max(PEN_WEIGHTS * max(w, 0.0) / ks, PEN_FLOOR)
            if pen / lim > pen_max:
                pen_max = pen / lim
                ipen = i
    return ke + ue + eg, pw, ke + ue, wsum, pen_max, ipen


# --------------------------------------------------------------------------------------------
# dynamics
# --------------------------------------------------------------------------------------------
@njit(cache=True)
def gen_alpha_step(t1, dt, rf1, vf1, s0, s1, par, w):
    """One generalised-alpha step (Chung & Hulbert 1993) of the free nodes with Newton
    iterations on the accelerations.

    State at ``t1 - dt``: ``s0`` (:class:`~.bundles.LineState`: ``r, v, a`` (n, 3), the nodal
    force ``f``, the friction state ``fs``, whose sliding branch this step decides); fairlead
    (node n-1) position ``rf1`` and velocity ``vf1`` at ``t1``.  ``par``
    (:class:`~.bundles.LineParams`, ``coef = (alpha_m, alpha_f, beta, gamma)``, ``tol`` m,
    ``maxit``); ``w`` (:class:`~.bundles.LineWork`) scratch, element tensions ``w.tens`` and
    ``w.info``.  Trial state at ``t1`` into ``s1.r, s1.v, s1.a, s1.f`` (the caller accepts it;
    ``s1.fs`` is not used).  Residual ``M ((1-am) a1 + am a) - (1-af) f(r1, v1) - af fn``;
    mass blocks from ``r``.

    Stiff elements (:func:`_stiff`, e.g. the OC3 chain at EA = 3.84e14 N, EA / L0 = 2e13 N/m)
    are handled as in a mixed displacement-tension Newton: every stiff element carries a
    tension estimate (start: its tension at ``t1 - dt``; then the linearised tension
    ``T + dT/dl dl`` of each correction) which gives its geometric stiffness and decides
    whether it is held taut.  A held element in compression is a visco-elastic bar (``c1 eps +
    B ldot / L0``) instead of slack; it is released when its estimate is negative by more than
    the estimate's own second-order error.  Converged: residual below the round-off-aware force
    tolerance and no held element pushing.  Without this, the predictor and every large
    correction leave nanometre compressions (slack, zero tangent) in a taut stiff line and
    Newton never converges.  The residual-increase backtracking is used only for lines without
    stiff elements (for a stiff line the residual rises while Newton converges).  Lines without
    stiff elements take exactly the previous iterations.

    Modified Newton (``par.newton`` 1): the factorised iteration matrix of the first iteration
    of the step (``w.W``, ``w.Of``) is kept for the following iterations (lines without bending
    and stiff elements): such an iteration evaluates the forces without the tangent and solves
    by the forward and backward sweeps alone (:func:`block_tridiag_resolve`); when it lowers
    the residual norm by less than the factor :data:`NEWTON_THETA` it is repeated with a new
    matrix.  The iteration also stops when the error left after a correction, estimated from
    the contraction of the last two corrections ``rho = |d_k| / |d_k-1|`` as
    ``rho / (1 - rho) |d_k|`` (Hairer & Wanner 1996, sec. IV.8), is below ``tol`` (besides the
    tests of the exact iteration).  Each accepted state is within about ``tol`` of the
    converged one by that estimate, but over a run the differences from the exact iteration
    can grow past it: the re-tensioning of a nearly slack line amplifies a tension difference
    of ~1 N about 1e5 times, so in the 12-line flagship storm one lightly loaded line's
    maximum (a snap after its main peak) moves by 4-9 %, while a perturbation made once, e.g.
    of the start positions by tol, moves none by more than 0.0003 % (benchmarks/RESULTS.md);
    hence opt-in.

    Fast exact Newton (``par.newton`` :data:`NW_PREDICT` | :data:`NW_QSTOP`, opt-in): the exact
    iteration from a predictor whose fairlead deviation is taken from the fairlead's
    constant-acceleration prediction (its acceleration that of node ``n - 2``) instead of its
    constant-velocity one, stopped also when the quadratic-convergence estimate of the next
    correction, ``(|d_k| / |d_k-1|)^2 |d_k|``, is below ``tol``.  About one iteration less per
    step; each accepted state is within ``tol`` of the converged one (test_newton_exact), but
    like the modified iteration it leaves a tolerance-level error at every step, which a
    snap load can amplify (benchmarks/RESULTS.md).

    Returns the number of Newton iterations (> 0), or -1 (no convergence: ``info[1]`` = node
    with the largest correction), -2 (singular iteration matrix at node ``info[1]``), -3 (NaN).
    """
    r, v, a, fn, fs = s0
    r1 = s1.r
    v1 = s1.v
    a1 = s1.a
    f1 = s1.f
    P = par.P
    E = par.E
    S = par.S
    fric = par.fric
    coef = par.coef
    tol = par.tol
    maxit = par.maxit
    q = w.q
    tens = w.tens
    Mb = w.Mb
    Dg = w.Dg
    Of = w.Of
    BX = w.BX
    Rr = w.R
    W = w.W
    Y = w.Y
    T1 = w.T1
    da = w.dx
    info = w.info
    # element activity (> 0: taut by the tension estimate of the iteration)
    act = w.act
    am = coef[0]
    af = coef[1]
    beta = coef[2]
    gamma = coef[3]
    n = r.shape[0]
    bend = S[S_BEND] > 0.0
    # force scale: the largest node weight (in air if the net weight vanishes), but not below
    # the round-off of the axial forces: an element tension c1 (l / L0 - 1) carries the
    # relative error of l / L0 (~ 1 ulp, plus the coordinates' round-off |r| eps / L0), which
    # is several N for c1 = 3.84e14 N; summed over the 3 (n - 2) residual components
    ftol = 0.0
    rmax = 0.0
    for i in range(n):
        ftol = max(ftol, 1e-5 * abs(P[i, NP_W]), 1e-5 * 9.80665 * P[i, NP_MASS])
        for k in range(3):
            rmax = max(rmax, abs(r[i, k]))
    fround = 0.0
    nstiff = 0
    for j in range(n - 1):
        fround = max(fround, E[j, EL_C1] * EPS_MACH * (2.0 + 2.0 * rmax / E[j, EL_L0]))
        # tension estimate: the tension at the start of the step
        # (zero for the other elements: only stiff ones use it)
        act[j] = 0.0
        if _stiff(P, E, j):
            act[j] = _elem_tension(r, v, P, E, j)
            nstiff += 1
    # weight-based bound of the residual when the position correction is below tol
    fcap = max(1e3 * ftol, math.sqrt(3.0 * n) * fround)
    ftol = max(ftol, math.sqrt(3.0 * n) * fround)
    _node_mass_el(r, P, w.el, q, Mb)
    # predictor: constant acceleration, plus the fairlead's deviation from its own constant-
    # velocity prediction spread along the line in proportion to the node number (keeps the
    # element lengths nearly unchanged: essential for very stiff lines)
    for i in range(n):
        for k in range(3):
            a1[i, k] = a[i, k] if 0 < i < n - 1 else 0.0
    mode = par.newton
    for k in range(3):
        dev = rf1[k] - (r[n - 1, k] + dt * v[n - 1, k])
        if mode & NW_PREDICT:
            # deviation from the fairlead's constant-acceleration prediction, its acceleration
            # taken as that of the neighbouring node (a rigid translation is then predicted
            # exactly; without it the fairlead's whole acceleration is spread a second time)
            dev -= 0.5 * dt * dt * a[n - 2, k]
        for i in range(1, n - 1):
            a1[i, k] += dev * (i / (n - 1.0)) / (beta * dt * dt)
    for k in range(3):
        r1[0, k] = r[0, k]
        v1[0, k] = 0.0
        r1[n - 1, k] = rf1[k]
        v1[n - 1, k] = vf1[k]
    cK = (1.0 - af) * beta * dt * dt
    cC = (1.0 - af) * gamma * dt
    if fric == FR_DISPVEL:
        for i in range(1, n - 1):
            for k in range(3):
                r1[i, k] = r[i, k] + dt * v[i, k] + dt * dt * ((0.5 - beta) * a[i, k]
                                                               + beta * a1[i, k])
                v1[i, k] = v[i, k] + dt * ((1.0 - gamma) * a[i, k] + gamma * a1[i, k])
        friction_decide(r1, v1, fric, fs, S[S_ZC])
    it = 0
    conv = False
    res_prev = math.inf
    alpha = 1.0
    # modified Newton: keep the iteration matrix while it is the one of this step size
    # converged on the residual of the current iterate: its forces are those of the state
    by_res = False
    modified = (mode & NW_KEEP) > 0
    # the matrix is kept only without bending (band solver) and stiff elements (whose tension
    # estimate reads the element blocks of the current iterate)
    reuse = modified and nstiff == 0 and not bend
    fresh = True
    dprev = 0.0
    while it < maxit:
        it += 1
        for i in range(1, n - 1):
            for k in range(3):
                r1[i, k] = r[i, k] + dt * v[i, k] + dt * dt * ((0.5 - beta) * a[i, k]
                                                               + beta * a1[i, k])
                v1[i, k] = v[i, k] + dt * ((1.0 - gamma) * a[i, k] + gamma * a1[i, k])
        # (with no stiff element no element is managed by the estimate: use_act False skips
        # the per-element test, same bits)
        _line_forces(r1, v1, fs, par, bool(fresh), cK, cC, f1, w, nstiff > 0)
        # largest push of an element held as a bar in compression (the converged state must
        # not rely on it: the cable law has no compression)
        fbar = 0.0
        if nstiff > 0:
            for j in range(n - 1):
                if act[j] > 0.0 and tens[j] < 0.0:
                    fbar = max(fbar, -tens[j])
        res = 0.0
        for i in range(1, n - 1):
            # (1 - am) a1 + am a, once per node
            b0 = (1.0 - am) * a1[i, 0] + am * a[i, 0]
            b1 = (1.0 - am) * a1[i, 1] + am * a[i, 1]
            b2 = (1.0 - am) * a1[i, 2] + am * a[i, 2]
            for k in range(3):
                s = 0.0 + Mb[i, k, 0] * b0 + Mb[i, k, 1] * b1 + Mb[i, k, 2] * b2
                if fresh:
                    Dg[i, k, 0] += (1.0 - am) * Mb[i, k, 0]
                    Dg[i, k, 1] += (1.0 - am) * Mb[i, k, 1]
                    Dg[i, k, 2] += (1.0 - am) * Mb[i, k, 2]
                rk = (1.0 - af) * f1[i, k] + af * fn[i, k] - s
                Rr[i, k] = rk
                res += rk * rk
        if not math.isfinite(res):
            info[1] = 1
            return -3
        if not fresh and it > 1 and res > NEWTON_THETA * NEWTON_THETA * res_prev:
            # the kept matrix lowered the residual too little: this iterate again with a new one
            fresh = True
            it -= 1
            continue
        if res > res_prev and alpha > 1.0 / 1024.0 and nstiff == 0:
            # the last correction raised the residual (a node jumping across the seabed
            # contact, a slack element): go back half of it
            alpha *= 0.5
            for i in range(1, n - 1):
                for k in range(3):
                    a1[i, k] -= alpha * da[i, k]
            continue
        alpha = 1.0
        res_prev = res
        if it > 1 and math.sqrt(res) <= ftol and fbar <= ftol:
            # residual below ftol (N): converged even if a contact or slack kink keeps the
            # position corrections from settling
            conv = True
            by_res = True
            break
        if fresh:
            bad = solve_blocks(Dg, Of, BX, bend, Rr, 1, n - 1, W, Y, T1, da)
            if bad >= 0:
                info[1] = bad
                return -2
            fresh = not reuse
        else:
            block_tridiag_resolve(Of, Rr, 1, n - 1, W, Y, da)
        # tension estimate of the next iterate: the linearised tension T + dT/dl dl (dl from
        # the correction, dT/dl = e^T K_j e / cK from the element block, axial and damping
        # parts).  An element that Newton's second-order length error (|dx_perp|^2 / 2 l)
        # leaves slightly compressed stays a bar while its estimate is positive, and the
        # geometric stiffness uses the estimate.  Without this a very stiff line (c1 / L0 ~
        # 1e13 N/m, slack strain ~1e-10) has elements going slack at every iterate and Newton
        # does not converge.
        bs = beta * dt * dt
        for j in range(n - 1):
            if nstiff == 0 or not _stiff(P, E, j):
                continue
            dx = r1[j + 1, 0] - r1[j, 0]
            dy = r1[j + 1, 1] - r1[j, 1]
            dz = r1[j + 1, 2] - r1[j, 2]
            ll = math.sqrt(dx * dx + dy * dy + dz * dz)
            # relative correction of the element ends (m)
            cx = 0.0
            cy = 0.0
            cz = 0.0
            if j + 1 < n - 1:
                cx += da[j + 1, 0] * bs
                cy += da[j + 1, 1] * bs
                cz += da[j + 1, 2] * bs
            if j > 0:
                cx -= da[j, 0] * bs
                cy -= da[j, 1] * bs
                cz -= da[j, 2] * bs
            dl = (dx * cx + dy * cy + dz * cz) / ll
            ex = dx / ll
            ey = dy / ll
            ez = dz / ll
            kab = -(ex * (Of[j, 0, 0] * ex + Of[j, 0, 1] * ey + Of[j, 0, 2] * ez)
                    + ey * (Of[j, 1, 0] * ex + Of[j, 1, 1] * ey + Of[j, 1, 2] * ez)
                    + ez * (Of[j, 2, 0] * ex + Of[j, 2, 1] * ey + Of[j, 2, 2] * ez))
            kl = kab / cK
            Tl = tens[j] + kl * dl
            if act[j] > 0.0 and Tl <= 0.0 and -Tl < kl * (cx * cx + cy * cy + cz * cz - dl * dl) / (
                    2.0 * ll):
                # a held element is released only when its estimate is negative by more than
                # the estimate's own error, the second-order length change |c_perp|^2 / 2 l of
                # the correction times dT/dl: far from the solution a large correction must not
                # release an element of a taut stiff line (its zero tangent then lets the next
                # correction stretch it by centimetres)
                Tl = 1e-6
            act[j] = Tl
        dmax = 0.0
        imax = 1
        for i in range(1, n - 1):
            for k in range(3):
                if not math.isfinite(da[i, k]):
                    info[1] = i
                    return -3
                a1[i, k] += da[i, k]
                if abs(da[i, k]) > dmax:
                    dmax = abs(da[i, k])
                    imax = i
        info[1] = imax
        # a displacement correction beta dt^2 da below tol (m) ends the iteration if the
        # residual is also below 1e-2 node weights (for very stiff lines a tiny correction can
        # still leave a large axial force imbalance)
        if dmax * beta * dt * dt <= tol and math.sqrt(res) <= fcap and fbar <= fcap:
            conv = True
            break
        if (mode & NW_QSTOP) and not modified and 0.0 < dmax < dprev:
            # quadratic convergence, |d_k+1| ~ C |d_k|^2 with C from the last two corrections:
            # the next correction (the error left) is about rho^2 |d_k|
            rho = dmax / dprev
            if (rho * rho * dmax * beta * dt * dt <= tol and math.sqrt(res) <= fcap
                    and fbar <= fcap):
                conv = True
                break
        if modified and 0.0 < dmax < dprev:
            # error left after this correction, estimated from the contraction of the last two
            rho = dmax / dprev
            if (rho / (1.0 - rho) * dmax * beta * dt * dt <= tol and math.sqrt(res) <= fcap
                    and fbar <= fcap):
                conv = True
                break
        dprev = dmax
    if not conv:
        return -1
    for i in range(1, n - 1):
        for k in range(3):
            r1[i, k] = r[i, k] + dt * v[i, k] + dt * dt * ((0.5 - beta) * a[i, k] + beta * a1[i, k])
            v1[i, k] = v[i, k] + dt * ((1.0 - gamma) * a[i, k] + gamma * a1[i, k])
    # forces of the accepted state with the law of the converged iteration (a held element
    # keeps its damping; a bar push is below the tolerance): consistent with the residual.
    # Converged on the residual, the state is the last iterate's (the same a1, so the same
    # r1 and v1 to the bit) and f1, w.tens, w.q are already its forces: not evaluated again.
    if not by_res:
        _line_forces(r1, v1, fs, par, bool(False), cK, cC, f1, w, nstiff > 0)  # noqa: UP018
    for j in range(n - 1):
        if act[j] > 0.0 and tens[j] < 0.0:
            tens[j] = 0.0
    for i in range(n):
        for k in range(3):
            if not math.isfinite(f1[i, k]):
                info[1] = i
                return -3
    return it


@njit(cache=True, inline="always")
def accept_trial(ln):
    """Commit the trial state of the line bundle ``ln`` (``ln.trial`` -> ``ln.now``: the copies
    of :meth:`FELine.accept`).  Element by element: a slice assignment compiles numba's
    shape-mismatch error message (string formatting, about 3 s of a first run)."""
    now = ln.now
    tr = ln.trial
    for i in range(tr.r.shape[0]):
        for k in range(3):
            now.r[i, k] = tr.r[i, k]
            now.v[i, k] = tr.v[i, k]
            now.a[i, k] = tr.a[i, k]
            now.f[i, k] = tr.f[i, k]
        for k in range(tr.fs.shape[1]):
            now.fs[i, k] = tr.fs[i, k]


@njit(cache=True)
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


@njit(cache=True)
def end_forces(r, v, P, f, tens, out):
    """Force of the line on its end points (N, earth axes): ``out[0:3]`` on the anchor,
    ``out[3:6]`` on the fairlead.  It is minus the nodal force of the end node without its
    inertia: the pull of the adjacent element plus the end node's share of weight, drag and
    seabed load (minus the reaction a support must provide)."""
    n = r.shape[0]
    for k in range(3):
        out[k] = f[0, k]
        out[3 + k] = f[n - 1, k]


@njit(cache=True)
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
    over :func:`gen_alpha_step` (~3 s of cold compile); the arithmetic is the same.

    Energy audit: every sub-step's energy balance (:func:`line_energy`) is checked; a sub-step
    that creates more than :data:`AUDIT_REL` of the line's energy budget (or the floor
    :data:`AUDIT_FLOOR`) is halved like a failed one (``w.stats[1]``, ``w.audit[AU_SPLITS]``);
    at the smallest sub-step it is accepted and recorded in ``w.audit`` (count, energy, worst
    ratio, its time and element), unless it created more than :data:`AUDIT_HARD` of the
    budget (status -4).  The audit reads the states only: a run whose steps create no energy
    is bit for bit the run without it.  Also recorded per accepted sub-step: the deepest
    seabed penetration over its bound (status -5 beyond it, :data:`PEN_WEIGHTS`) and the most
    negative element tension.

    Returns 0, or the failing status of :func:`gen_alpha_step` (-1, -2, -3) or of the audit
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
    # energy of the accepted state: the start of the first sub-step (line_energy)
    en0, pw0, bud0, wsum, _, _ = line_energy(r, v, fn, P, E, S, lw.el, q, True)
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
        en1, pw1, bud1, _, pen, ipen = line_energy(rB, vB, fA, P, E, S, lw.el, q, False)
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
        for i in range(n):
            for k in range(3):
                rA[i, k] = rB[i, k]
                vA[i, k] = vB[i, k]
                aA[i, k] = aB[i, k]
                fnA[i, k] = fA[i, k]
        friction_commit(rA, vA, q, fric, fs1, P, S, S[S_ZC])
        if S.shape[0] > N_S:
            fibre_commit(rA, fs1, P, lp.E, S, sz * hmin)
        pos += sz
        while sz < full and pos % (2 * sz) == 0:
            sz *= 2
    return 0


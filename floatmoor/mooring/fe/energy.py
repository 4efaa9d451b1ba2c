"""Energy audit of the generalised-alpha steps of a line: its mechanical energy and the power
put into it (:func:`line_energy`), and the bounds a step is held to (:func:`~.advance.ga_advance`).
"""

from __future__ import annotations

from numba import njit

from .elements import (
    _elastic_energy,
    _slack_strain,
    _stiff,
    _tangents_from,
    _tension,
    element_geometry,
)
from .layout import (
    EL_B,
    EL_C1,
    EL_C2,
    EL_C3,
    EL_L0,
    EL_LAW,
    KERNEL_JIT,
    NP_KS,
    NP_MAC,
    NP_MAN,
    NP_MASS,
    NP_MAT,
    NP_W,
    S_DC,
    S_ZC,
)

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


@njit(**KERNEL_JIT)
def _largest(x):
    """Index of the largest entry of ``x``."""
    k = 0
    for j in range(1, x.shape[0]):
        if x[j] > x[k]:
            k = j
    return k


@njit(**KERNEL_JIT)
def line_energy(r, v, f, P, E, S, el, q, geom):
    """Mechanical energy of a line state and the power put into it, for the energy audit of
    the time steps (:func:`~.advance.ga_advance`).

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
        element_geometry(r, el)
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
        e0 = _slack_strain(P, E, j)
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

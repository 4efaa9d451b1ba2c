"""Element forces and tangents of the lumped-mass line: the axial law with its slack
transition, element geometry and node tangents, the nodal mass blocks, the element pass of the
force evaluation (forces and the element blocks of the tangent), bending, the elastic energy,
and the tension estimates of very stiff elements used by the generalised-alpha iteration.

Element ``j`` joins nodes ``j`` and ``j+1``.  Element tension ``T = T_el(eps) + B d(eps)/dt``
(only while taut), ``eps = l / L0 - 1``.  The node tangent ``q`` is the normalised sum of the
adjacent element directions.  Tangent ``K = -df/dx``, ``C = -df/dv``; the element blocks are
exact for the axial force (``dT/dl e e^T + T / l (I - e e^T)``).
"""

from __future__ import annotations

import math

from numba import njit

from .fibre_law import EL_FIB, EL_LAW, fibre_tension
from .layout import (
    EL_B,
    EL_C1,
    EL_C2,
    EL_C3,
    EL_L0,
    KERNEL_JIT,
    NP_CB,
    NP_MAC,
    NP_MAN,
    NP_MASS,
    NP_MAT,
    NP_W,
)

# An element is "stiff" when its strain under its own weight (in air plus submerged) is below
# E0_STIFF (OC3 chain: 1.4e-4 at EA = 3.84e8 N, 1.4e-7 at 3.84e11, 1.4e-10 at 3.84e14): its
# slack transition (strain e0 = net weight / c1) is then far narrower than the length errors of
# a Newton iterate (second-order transverse terms |dx|^2 / 2 l: 1e-6 m for dx = 6 mm on 18 m),
# and gen_alpha_step manages it by a tension estimate (see there).  Other elements keep the
# plain law and tangent, unchanged.
E0_STIFF = 1e-6


@njit(**KERNEL_JIT)
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


@njit(**KERNEL_JIT)
def _slack_strain(P, E, j):
    """Slack transition strain of element ``j``: its weight over its axial stiffness."""
    return max(abs(P[j, NP_W]) + abs(P[j + 1, NP_W]), 1e-6) / E[j, EL_C1]


@njit(**KERNEL_JIT)
def _stiff(P, E, j):
    """Element ``j`` is stiff: the strain under its weight in air is below :data:`E0_STIFF`
    (the slack transition e0 uses the net weight; the weight in air keeps weightless test
    elements out)."""
    w = 9.80665 * (P[j, NP_MASS] + P[j + 1, NP_MASS]) + abs(P[j, NP_W]) + abs(P[j + 1, NP_W])
    return w < E0_STIFF * E[j, EL_C1] and E[j, EL_LAW] == 0.0


@njit(**KERNEL_JIT)
def _elem_tension(r, v, P, E, j):
    """Tension of element ``j`` (N) as :func:`element_forces` computes it (elastic law with the
    slack transition plus the faded-in internal damping)."""
    dx = r[j + 1, 0] - r[j, 0]
    dy = r[j + 1, 1] - r[j, 1]
    dz = r[j + 1, 2] - r[j, 2]
    ll = math.sqrt(dx * dx + dy * dy + dz * dz)
    L0 = E[j, EL_L0]
    eps = ll / L0 - 1.0
    e0 = _slack_strain(P, E, j)
    T, dTde = _tension(eps, E[j, EL_C1], E[j, EL_C2], E[j, EL_C3], e0)
    if eps > 0.0:
        ldot = (dx * (v[j + 1, 0] - v[j, 0]) + dy * (v[j + 1, 1] - v[j, 1])
                + dz * (v[j + 1, 2] - v[j, 2])) / ll
        xs = eps / e0
        sm = xs * xs * (3.0 - 2.0 * xs) if xs < 1.0 else 1.0
        T += E[j, EL_B] * sm * ldot / L0
    return T


# --------------------------------------------------------------------------------------------
# geometry
# --------------------------------------------------------------------------------------------
@njit(**KERNEL_JIT)
def element_geometry(r, el):
    """Unit direction and length of every element into ``el`` (n-1, 4): ``el[j, 0:3]`` the
    direction of node ``j`` to ``j+1``, ``el[j, 3]`` the length (m)."""
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


@njit(**KERNEL_JIT)
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


@njit(**KERNEL_JIT)
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


@njit(**KERNEL_JIT)
def node_tangents(r, q):
    """Unit tangent at every node (average of the adjacent element directions)."""
    n = r.shape[0]
    for i in range(n):
        qx, qy, qz = _direction_sum(r, i)
        _set_unit(q, i, qx, qy, qz)


@njit(inline="always")
def tangent_from(el, q, i):
    """``q[i]``, the unit tangent at node ``i`` from the element directions and lengths ``el``
    (n-1, 4) of :func:`element_geometry`: the directions of its elements of non-zero length
    summed, element ``i - 1`` first (:func:`_set_unit`)."""
    n = q.shape[0]
    qx = 0.0
    qy = 0.0
    qz = 0.0
    for j in (i - 1, i):
        if 0 <= j < n - 1 and el[j, 3] > 0.0:
            qx += el[j, 0]
            qy += el[j, 1]
            qz += el[j, 2]
    _set_unit(q, i, qx, qy, qz)


@njit(**KERNEL_JIT)
def _tangents_from(el, q):
    """:func:`node_tangents` from the element directions and lengths ``el`` (n-1, 4) of
    :func:`element_geometry` (the same sums in the same order: the same bits)."""
    for i in range(q.shape[0]):
        tangent_from(el, q, i)


@njit(**KERNEL_JIT)
def _mass_blocks(P, q, Mb):
    """3x3 mass blocks (structural + added mass) of every node from the node tangents ``q``."""
    n = q.shape[0]
    for i in range(n):
        m = P[i, NP_MASS] + P[i, NP_MAC]
        man = P[i, NP_MAN]
        mat = P[i, NP_MAT]
        for a in range(3):
            for b in range(3):
                qq = q[i, a] * q[i, b]
                d = 1.0 if a == b else 0.0
                Mb[i, a, b] = m * d + man * (d - qq) + mat * qq


@njit(**KERNEL_JIT)
def node_mass(r, P, q, Mb):
    """3x3 mass blocks (structural + added mass) of every node into ``Mb`` (n, 3, 3)."""
    node_tangents(r, q)
    _mass_blocks(P, q, Mb)


@njit(**KERNEL_JIT)
def _node_mass_el(r, P, el, q, Mb):
    """:func:`node_mass` with the element directions and lengths computed once into ``el``
    (n-1, 4) (:func:`element_geometry`) and the tangents taken from them
    (:func:`_tangents_from`: the same sums, the same bits as :func:`node_tangents`)."""
    element_geometry(r, el)
    _tangents_from(el, q)
    _mass_blocks(P, q, Mb)


# --------------------------------------------------------------------------------------------
# the element pass of a force evaluation
# --------------------------------------------------------------------------------------------
@njit(**KERNEL_JIT)
def element_forces(v, fs, P, E, S, el, want_jac, cK, cC, use_act, act, tens, f, Dg, Of):
    """Axial element forces on the nodes and the element blocks of the tangent.

    ``el`` (n-1, 4) element directions and lengths (:func:`element_geometry`); ``v`` (n, 3)
    node velocities; ``fs`` the friction state (fibre columns); ``P, E, S`` the line
    parameters.  Writes every node's weight and element forces into ``f`` (n, 3), the element
    tensions into ``tens`` (n-1,) and, with ``want_jac``, the diagonal blocks ``Dg`` (n, 3, 3)
    and upper off-diagonal blocks ``Of`` (n-1, 3, 3) of ``cK K + cC C`` of the elements (the
    lower off-diagonal block equals the upper one).  With ``use_act``, ``act`` (n-1,) holds a
    tension estimate of every element (N, :func:`~.gen_alpha.gen_alpha_step`): a stiff element
    in compression with a positive estimate acts as a bar, ``T = c1 eps`` (negative) with its
    axial tangent, instead of ``T = 0``, and the geometric stiffness of every stiff element is
    ``max(act, 0) / l``.

    Element j adds its force and tangent block to nodes j and j+1; a node's sums are formed in
    registers in the order of the element loop (the node's own load, then element i-1, then
    element i) and stored once: the bits of accumulating in place.
    """
    n = f.shape[0]
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
        e0 = _slack_strain(P, E, j)
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


# --------------------------------------------------------------------------------------------
# bending
# --------------------------------------------------------------------------------------------
@njit(**KERNEL_JIT)
def _hab(ea, eb, a, b):
    """(P_a P_b)[a, b] with P = I - e e^T."""
    s = 0.0
    for m in range(3):
        s += (((1.0 if a == m else 0.0) - ea[a] * ea[m])
              * ((1.0 if m == b else 0.0) - eb[m] * eb[b]))
    return s


@njit(**KERNEL_JIT)
def bending_forces(r, P, f, want_jac, cK, Dg, Of, BX):
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


# --------------------------------------------------------------------------------------------
# energy
# --------------------------------------------------------------------------------------------
@njit(**KERNEL_JIT)
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


# --------------------------------------------------------------------------------------------
# very stiff elements: the tension estimates of the generalised-alpha iteration
# --------------------------------------------------------------------------------------------
@njit(**KERNEL_JIT)
def start_tension_estimates(r, v, P, E, act):
    """Tension estimate of every stiff element (:func:`_stiff`) at the start of a step: its
    tension in the state ``r, v`` (zero for the other elements: only stiff ones use it).
    Returns the number of stiff elements."""
    nstiff = 0
    for j in range(r.shape[0] - 1):
        act[j] = 0.0
        if _stiff(P, E, j):
            act[j] = _elem_tension(r, v, P, E, j)
            nstiff += 1
    return nstiff


@njit(**KERNEL_JIT)
def bar_push(act, tens):
    """Largest push (N) of an element held as a bar in compression: the converged state must
    not rely on it (the cable law has no compression)."""
    fbar = 0.0
    for j in range(tens.shape[0]):
        if act[j] > 0.0 and tens[j] < 0.0:
            fbar = max(fbar, -tens[j])
    return fbar


@njit(**KERNEL_JIT)
def update_tension_estimates(r1, da, bs, cK, P, E, Of, tens, act):
    """Tension estimate of every stiff element for the next iterate: the linearised tension
    ``T + dT/dl dl`` of the correction ``bs da`` (m; ``dl`` from it, ``dT/dl = e^T K_j e / cK``
    from the element block ``Of[j]``, axial and damping parts).  An element that Newton's
    second-order length error (``|dx_perp|^2 / 2 l``) leaves slightly compressed stays a bar
    while its estimate is positive, and the geometric stiffness uses the estimate.  Without
    this a very stiff line (c1 / L0 ~ 1e13 N/m, slack strain ~1e-10) has elements going slack
    at every iterate and Newton does not converge."""
    n = r1.shape[0]
    for j in range(n - 1):
        if not _stiff(P, E, j):
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


@njit(**KERNEL_JIT)
def release_bars(act, tens):
    """Tension of the accepted state: an element held as a bar in compression (a push below
    the tolerance) carries none."""
    for j in range(tens.shape[0]):
        if act[j] > 0.0 and tens[j] < 0.0:
            tens[j] = 0.0

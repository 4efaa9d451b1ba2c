"""Nodal forces and their tangent for a block of :data:`~.lanes.LW` lines as SIMD lanes: the
passes of :func:`~.forces._line_forces` (element geometry and node tangents, the axial law,
the element pass, the fluid loads, seabed contact) written over a block's lanes, operation for
operation those of the line kernels (:mod:`.elements`, :mod:`.fluid`, :mod:`.seabed`), with
every branch taken as a select so that the loop over the lanes vectorises.  What is rare or
does not vectorise runs lane by lane through the line kernels themselves on views of the
block (:func:`lane_rows`): the fibre laws' tension, seabed friction, bending, the current
profile lookup.

Every pass takes the block ``b`` and writes block rows in place (layout: :mod:`.lanes`).
"""

from __future__ import annotations

import math

from numba import njit

from .elements import bending_forces
from .fibre_law import EL_FIB, EL_LAW, fibre_tension
from .fluid import _current, _current_interval, _current_scale
from .lanes import (
    BF_BEND,
    BF_CLUMP,
    BF_DAMP,
    BF_FIBRE,
    BF_FRIC,
    BF_WAVES,
    EC_A,
    EC_B,
    EC_E0,
    EC_STIFF,
    LANE_JIT,
    LF_CC,
    LF_CK,
    LI_ST,
    LW,
    N_EC,
    ix,
    lanes_in,
)
from .layout import (
    EL_B,
    EL_C1,
    EL_C2,
    EL_C3,
    EL_L0,
    KERNEL_JIT,
    N_EL,
    N_FS,
    N_NP,
    N_S,
    NP_CS,
    NP_KC,
    NP_KDN,
    NP_KDT,
    NP_KS,
    NP_MAC,
    NP_MAN,
    NP_MASS,
    NP_MAT,
    NP_MD,
    NP_W,
    S_CURC,
    S_CURS,
    S_DC,
    S_SBLIFT,
    S_ZC,
)
from .seabed import V_SB, _friction_node


@njit(inline="always")
def live(li, b, l):
    """Lane ``l`` of block ``b`` carries a line state (running, or converged in this step:
    ``li[LI_ST]`` 0, 1 or 2); the lane-by-lane passes skip the others (idle or failed lanes,
    whose numbers are never used and may be NaN)."""
    st = li[b, ix(LI_ST, 0, 1, l)]
    return 0 <= st <= 2


@njit(inline="always")
def lane_rows(X, b, count, K, l):
    """Lane ``l`` of block ``b`` of ``X`` as a (count, K) array (a strided view): what the
    line kernels take."""
    return X[b].reshape((count, K, LW))[:, :, l]


# --------------------------------------------------------------------------------------------
# geometry
# --------------------------------------------------------------------------------------------
@njit(**LANE_JIT)
def geometry(b, n, r, el):
    """:func:`~.elements.element_geometry` of block ``b``."""
    lw = lanes_in(r, 3 * n)
    for j in range(n - 1):
        for l in range(lw):
            dx = r[b, ix(j + 1, 0, 3, l)] - r[b, ix(j, 0, 3, l)]
            dy = r[b, ix(j + 1, 1, 3, l)] - r[b, ix(j, 1, 3, l)]
            dz = r[b, ix(j + 1, 2, 3, l)] - r[b, ix(j, 2, 3, l)]
            ll = math.sqrt(dx * dx + dy * dy + dz * dz)
            el[b, ix(j, 0, 4, l)] = dx / ll
            el[b, ix(j, 1, 4, l)] = dy / ll
            el[b, ix(j, 2, 4, l)] = dz / ll
            el[b, ix(j, 3, 4, l)] = ll


@njit(inline="always")
def _unit(qx, qy, qz):
    """``elements._set_unit``: the unit vector along ``(qx, qy, qz)`` or (1, 0, 0)."""
    nq = math.sqrt(qx * qx + qy * qy + qz * qz)
    ok = nq > 0.0
    return (qx / nq if ok else 1.0), (qy / nq if ok else 0.0), (qz / nq if ok else 0.0)


@njit(**LANE_JIT)
def tangents(b, n, el, q):
    """:func:`~.elements._tangents_from` of block ``b``: the sums in the same order (``0.0``
    plus the element before, plus the element after, each only if of non-zero length)."""
    lw = lanes_in(q, 3 * n)
    for l in range(lw):
        ok = el[b, ix(0, 3, 4, l)] > 0.0
        qx = (0.0 + el[b, ix(0, 0, 4, l)]) if ok else 0.0
        qy = (0.0 + el[b, ix(0, 1, 4, l)]) if ok else 0.0
        qz = (0.0 + el[b, ix(0, 2, 4, l)]) if ok else 0.0
        ux, uy, uz = _unit(qx, qy, qz)
        q[b, ix(0, 0, 3, l)] = ux
        q[b, ix(0, 1, 3, l)] = uy
        q[b, ix(0, 2, 3, l)] = uz
    for i in range(1, n - 1):
        for l in range(lw):
            oa = el[b, ix(i - 1, 3, 4, l)] > 0.0
            ob = el[b, ix(i, 3, 4, l)] > 0.0
            sx = (0.0 + el[b, ix(i - 1, 0, 4, l)]) if oa else 0.0
            sy = (0.0 + el[b, ix(i - 1, 1, 4, l)]) if oa else 0.0
            sz = (0.0 + el[b, ix(i - 1, 2, 4, l)]) if oa else 0.0
            qx = (sx + el[b, ix(i, 0, 4, l)]) if ob else sx
            qy = (sy + el[b, ix(i, 1, 4, l)]) if ob else sy
            qz = (sz + el[b, ix(i, 2, 4, l)]) if ob else sz
            ux, uy, uz = _unit(qx, qy, qz)
            q[b, ix(i, 0, 3, l)] = ux
            q[b, ix(i, 1, 3, l)] = uy
            q[b, ix(i, 2, 3, l)] = uz
    j = n - 2
    for l in range(lw):
        ok = el[b, ix(j, 3, 4, l)] > 0.0
        qx = (0.0 + el[b, ix(j, 0, 4, l)]) if ok else 0.0
        qy = (0.0 + el[b, ix(j, 1, 4, l)]) if ok else 0.0
        qz = (0.0 + el[b, ix(j, 2, 4, l)]) if ok else 0.0
        ux, uy, uz = _unit(qx, qy, qz)
        q[b, ix(n - 1, 0, 3, l)] = ux
        q[b, ix(n - 1, 1, 3, l)] = uy
        q[b, ix(n - 1, 2, 3, l)] = uz


@njit(**LANE_JIT)
def mass_blocks(b, n, P, q, Mb):
    """:func:`~.elements._mass_blocks` of block ``b`` (the nine entries written out, ``d`` 1.0
    on the diagonal and 0.0 off it as in the loop)."""
    lw = lanes_in(q, 3 * n)
    for i in range(n):
        for l in range(lw):
            m = P[b, ix(i, NP_MASS, N_NP, l)] + P[b, ix(i, NP_MAC, N_NP, l)]
            man = P[b, ix(i, NP_MAN, N_NP, l)]
            mat = P[b, ix(i, NP_MAT, N_NP, l)]
            qx = q[b, ix(i, 0, 3, l)]
            qy = q[b, ix(i, 1, 3, l)]
            qz = q[b, ix(i, 2, 3, l)]
            qq = qx * qx
            Mb[b, ix(i, 0, 9, l)] = m * 1.0 + man * (1.0 - qq) + mat * qq
            qq = qx * qy
            Mb[b, ix(i, 1, 9, l)] = m * 0.0 + man * (0.0 - qq) + mat * qq
            qq = qx * qz
            Mb[b, ix(i, 2, 9, l)] = m * 0.0 + man * (0.0 - qq) + mat * qq
            qq = qy * qx
            Mb[b, ix(i, 3, 9, l)] = m * 0.0 + man * (0.0 - qq) + mat * qq
            qq = qy * qy
            Mb[b, ix(i, 4, 9, l)] = m * 1.0 + man * (1.0 - qq) + mat * qq
            qq = qy * qz
            Mb[b, ix(i, 5, 9, l)] = m * 0.0 + man * (0.0 - qq) + mat * qq
            qq = qz * qx
            Mb[b, ix(i, 6, 9, l)] = m * 0.0 + man * (0.0 - qq) + mat * qq
            qq = qz * qy
            Mb[b, ix(i, 7, 9, l)] = m * 0.0 + man * (0.0 - qq) + mat * qq
            qq = qz * qz
            Mb[b, ix(i, 8, 9, l)] = m * 1.0 + man * (1.0 - qq) + mat * qq


# --------------------------------------------------------------------------------------------
# elements
# --------------------------------------------------------------------------------------------
@njit(**LANE_JIT)
def axial_law(b, n, E, EC, el, Tl, Dl):
    """Elastic tension and ``dT/deps`` of every element of the polynomial law
    (:func:`~.elements._tension`: zero in compression, the cubic below the slack strain, the
    law above; the cubic's coefficients are the element constants ``EC``) into ``Tl, Dl``."""
    lw = lanes_in(el, 4 * (n - 1))
    for j in range(n - 1):
        for l in range(lw):
            ll = el[b, ix(j, 3, 4, l)]
            L0 = E[b, ix(j, EL_L0, N_EL, l)]
            c1 = E[b, ix(j, EL_C1, N_EL, l)]
            c2 = E[b, ix(j, EL_C2, N_EL, l)]
            c3 = E[b, ix(j, EL_C3, N_EL, l)]
            e0 = EC[b, ix(j, EC_E0, N_EC, l)]
            A = EC[b, ix(j, EC_A, N_EC, l)]
            B = EC[b, ix(j, EC_B, N_EC, l)]
            eps = ll / L0 - 1.0
            up = eps >= e0
            T = (c1 * eps + c2 * eps * eps + c3 * eps * eps * eps if up
                 else A * eps * eps + B * eps * eps * eps)
            D = (c1 + 2.0 * c2 * eps + 3.0 * c3 * eps * eps if up
                 else 2.0 * A * eps + 3.0 * B * eps * eps)
            taut = eps > 0.0
            Tl[b, ix(j, 0, 1, l)] = T if taut else 0.0
            Dl[b, ix(j, 0, 1, l)] = D if taut else 0.0


@njit(**KERNEL_JIT)
def fibre_law(b, n, E, EC, S, el, fs, Tl, Dl, li):
    """The fibre elements' tension and ``dT/deps`` (:func:`~.fibre_law.fibre_tension`), lane
    by lane (the :func:`live` ones), over those of :func:`axial_law`."""
    for l in range(LW):
        if not live(li, b, l):
            continue
        Sl = S[b * LW + l]
        fsl = lane_rows(fs, b, n, N_FS, l)
        for j in range(n - 1):
            law = E[b, ix(j, EL_LAW, N_EL, l)]
            if law == 0.0:
                continue
            eps = el[b, ix(j, 3, 4, l)] / E[b, ix(j, EL_L0, N_EL, l)] - 1.0
            T, D = fibre_tension(law, eps, fsl, j, Sl, int(E[b, ix(j, EL_FIB, N_EL, l)]),
                                 EC[b, ix(j, EC_E0, N_EC, l)])
            Tl[b, ix(j, 0, 1, l)] = T
            Dl[b, ix(j, 0, 1, l)] = D


@njit(**LANE_JIT)
def element_forces(b, n, v, P, E, EC, el, Tl, Dl, act, lf, want_jac, use_act, damp, tens, f,
                   Dg, Of, carry):
    """:func:`~.elements.element_forces` of block ``b`` in dynamics (``cC > 0``): the tension
    ``Tl`` / ``Dl`` of the law, the bar of a held stiff element (``use_act``), the internal
    damping (``damp``: some element has it), the element forces into ``f`` and tensions into
    ``tens``; with ``want_jac`` the element blocks into ``Dg`` and ``Of``.  ``cK`` and ``cC``
    are the lanes' ``lf`` entries; ``carry`` scratch (the node sums the line kernel keeps in
    registers)."""
    lw = lanes_in(el, 4 * (n - 1))
    for l in range(lw):
        carry[b, ix(0, 0, 1, l)] = 0.0
        carry[b, ix(1, 0, 1, l)] = 0.0
        carry[b, ix(2, 0, 1, l)] = -P[b, ix(0, NP_W, N_NP, l)]
        for k in range(9):
            carry[b, ix(3 + k, 0, 1, l)] = 0.0
    for j in range(n - 1):
        for l in range(lw):
            ll = el[b, ix(j, 3, 4, l)]
            ex = el[b, ix(j, 0, 4, l)]
            ey = el[b, ix(j, 1, 4, l)]
            ez = el[b, ix(j, 2, 4, l)]
            L0 = E[b, ix(j, EL_L0, N_EL, l)]
            eps = ll / L0 - 1.0
            T = Tl[b, ix(j, 0, 1, l)]
            dTde = Dl[b, ix(j, 0, 1, l)]
            # the bar of a held stiff element, as selects (the loads are made for every
            # element: a load under a run-time branch keeps the lane loop from vectorising)
            actl = act[b, ix(j, 0, 1, l)]
            stf = EC[b, ix(j, EC_STIFF, N_EC, l)] > 0.0
            c1 = E[b, ix(j, EL_C1, N_EL, l)]
            actj = actl if use_act else 0.0
            managed = use_act and stf
            held = managed and actj > 0.0
            bar = held and eps < 0.0
            T = c1 * eps if bar else T
            dTde = c1 if bar else dTde
            B = 0.0
            dvx = 0.0
            dvy = 0.0
            dvz = 0.0
            ldot = 0.0
            if damp:
                Bj = E[b, ix(j, EL_B, N_EL, l)]
                dvx = v[b, ix(j + 1, 0, 3, l)] - v[b, ix(j, 0, 3, l)]
                dvy = v[b, ix(j + 1, 1, 3, l)] - v[b, ix(j, 1, 3, l)]
                dvz = v[b, ix(j + 1, 2, 3, l)] - v[b, ix(j, 2, 3, l)]
                ldot = ex * dvx + ey * dvy + ez * dvz
                e0 = EC[b, ix(j, EC_E0, N_EC, l)]
                xs = eps / e0
                inr = xs < 1.0
                sm = xs * xs * (3.0 - 2.0 * xs) if inr else 1.0
                dsm = 6.0 * xs * (1.0 - xs) / e0 if inr else 0.0
                has = Bj != 0.0
                Bs = Bj * sm
                Th = T + Bj * ldot / L0
                Ts = T + Bs * ldot / L0
                Ds = dTde + Bj * dsm * ldot / L0
                fade = has and not held and eps > 0.0
                hold = has and held
                B = Bj if hold else (Bs if fade else 0.0)
                T = Th if hold else (Ts if fade else T)
                dTde = Ds if fade else dTde
            tens[b, ix(j, 0, 1, l)] = T
            tx = T * ex
            ty = T * ey
            tz = T * ez
            f[b, ix(j, 0, 3, l)] = carry[b, ix(0, 0, 1, l)] + tx
            f[b, ix(j, 1, 3, l)] = carry[b, ix(1, 0, 1, l)] + ty
            f[b, ix(j, 2, 3, l)] = carry[b, ix(2, 0, 1, l)] + tz
            carry[b, ix(0, 0, 1, l)] = 0.0 - tx
            carry[b, ix(1, 0, 1, l)] = 0.0 - ty
            carry[b, ix(2, 0, 1, l)] = -P[b, ix(j + 1, NP_W, N_NP, l)] - tz
            if want_jac:
                cK = lf[b, ix(LF_CK, 0, 1, l)]
                cC = lf[b, ix(LF_CC, 0, 1, l)]
                ka = cK * dTde / L0
                kg = cK * max(actj if managed else T, 0.0) / ll
                nz = B != 0.0
                cb = cC * B / L0 if nz else 0.0
                kb = cK * B / (L0 * ll) if nz else 0.0
                kac = ka + cb
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
                if damp:
                    kbz = kb != 0.0
                    dpx = dvx - ldot * ex
                    dpy = dvy - ldot * ey
                    dpz = dvz - ldot * ez
                    v00 = v00 + kb * ex * dpx if kbz else v00
                    v01 = v01 + kb * ex * dpy if kbz else v01
                    v02 = v02 + kb * ex * dpz if kbz else v02
                    v10 = v10 + kb * ey * dpx if kbz else v10
                    v11 = v11 + kb * ey * dpy if kbz else v11
                    v12 = v12 + kb * ey * dpz if kbz else v12
                    v20 = v20 + kb * ez * dpx if kbz else v20
                    v21 = v21 + kb * ez * dpy if kbz else v21
                    v22 = v22 + kb * ez * dpz if kbz else v22
                Dg[b, ix(j, 0, 9, l)] = carry[b, ix(3, 0, 1, l)] + v00
                Dg[b, ix(j, 1, 9, l)] = carry[b, ix(4, 0, 1, l)] + v01
                Dg[b, ix(j, 2, 9, l)] = carry[b, ix(5, 0, 1, l)] + v02
                Dg[b, ix(j, 3, 9, l)] = carry[b, ix(6, 0, 1, l)] + v10
                Dg[b, ix(j, 4, 9, l)] = carry[b, ix(7, 0, 1, l)] + v11
                Dg[b, ix(j, 5, 9, l)] = carry[b, ix(8, 0, 1, l)] + v12
                Dg[b, ix(j, 6, 9, l)] = carry[b, ix(9, 0, 1, l)] + v20
                Dg[b, ix(j, 7, 9, l)] = carry[b, ix(10, 0, 1, l)] + v21
                Dg[b, ix(j, 8, 9, l)] = carry[b, ix(11, 0, 1, l)] + v22
                carry[b, ix(3, 0, 1, l)] = 0.0 + v00
                carry[b, ix(4, 0, 1, l)] = 0.0 + v01
                carry[b, ix(5, 0, 1, l)] = 0.0 + v02
                carry[b, ix(6, 0, 1, l)] = 0.0 + v10
                carry[b, ix(7, 0, 1, l)] = 0.0 + v11
                carry[b, ix(8, 0, 1, l)] = 0.0 + v12
                carry[b, ix(9, 0, 1, l)] = 0.0 + v20
                carry[b, ix(10, 0, 1, l)] = 0.0 + v21
                carry[b, ix(11, 0, 1, l)] = 0.0 + v22
                Of[b, ix(j, 0, 9, l)] = -v00
                Of[b, ix(j, 1, 9, l)] = -v01
                Of[b, ix(j, 2, 9, l)] = -v02
                Of[b, ix(j, 3, 9, l)] = -v10
                Of[b, ix(j, 4, 9, l)] = -v11
                Of[b, ix(j, 5, 9, l)] = -v12
                Of[b, ix(j, 6, 9, l)] = -v20
                Of[b, ix(j, 7, 9, l)] = -v21
                Of[b, ix(j, 8, 9, l)] = -v22
    for l in range(lw):
        f[b, ix(n - 1, 0, 3, l)] = carry[b, ix(0, 0, 1, l)]
        f[b, ix(n - 1, 1, 3, l)] = carry[b, ix(1, 0, 1, l)]
        f[b, ix(n - 1, 2, 3, l)] = carry[b, ix(2, 0, 1, l)]
    if want_jac:
        for k in range(9):
            for l in range(lw):
                Dg[b, ix(n - 1, k, 9, l)] = carry[b, ix(3 + k, 0, 1, l)]


# --------------------------------------------------------------------------------------------
# nodes: fluid loads and seabed
# --------------------------------------------------------------------------------------------
@njit(**LANE_JIT)
def current_lookup(b, n, r, cc, memo, uc, li, miss):
    """The current speed at every node of block ``b`` (:func:`~.fluid._current`) from each
    node's last level interval ``memo`` (zero in the lanes not :func:`live`), all lanes at once;
    ``miss[b, l]``: the nodes of lane ``l`` whose level is in none of the profile's ends or
    its last interval (:func:`current_fix` looks them up).  The same arithmetic as
    :func:`~.fluid._current`: a level in the interval ``cur_z[j] < z <= cur_z[j + 1]`` has that
    interval (the profile is sorted, so it is the only one)."""
    lw = lanes_in(miss, 1)
    for l in range(lw):
        miss[b, l] = 0.0
    for i in range(n):
        for l in range(lw):
            z = r[b, ix(i, 2, 3, l)]
            lo = memo[b, ix(i, 0, 4, l)]
            hi = memo[b, ix(i, 1, 4, l)]
            w = (z - lo) / (hi - lo)
            u = (1.0 - w) * memo[b, ix(i, 2, 4, l)] + w * memo[b, ix(i, 3, 4, l)]
            low = z <= cc[b, ix(0, 0, 4, l)]
            high = z >= cc[b, ix(0, 1, 4, l)]
            u = cc[b, ix(0, 3, 4, l)] if high else u
            u = cc[b, ix(0, 2, 4, l)] if low else u
            lv = live(li, b, l)
            uc[b, ix(i, 0, 1, l)] = u if lv else 0.0
            # (bitwise: a short-circuit is a branch, which keeps the loop scalar)
            ok = low | high | ((lo < z) & (z <= hi)) | (not lv)
            m = miss[b, l]
            miss[b, l] = m if ok else m + 1.0


@njit(**KERNEL_JIT)
def current_fix(b, n, r, cur_z, cur_u, cur_n, cc, memo, uc, li, miss):
    """The nodes :func:`current_lookup` missed: :func:`~.fluid._current` lane by lane, and
    their level interval into ``memo``."""
    for l in range(LW):
        if miss[b, l] == 0.0 or not live(li, b, l):
            continue
        p = b * LW + l
        m = cur_n[p]
        cz = cur_z[p, :m]
        cu = cur_u[p, :m]
        csc = _current_scale(cz)
        for i in range(n):
            z = r[b, ix(i, 2, 3, l)]
            lo = memo[b, ix(i, 0, 4, l)]
            hi = memo[b, ix(i, 1, 4, l)]
            if (z <= cc[b, ix(0, 0, 4, l)] or z >= cc[b, ix(0, 1, 4, l)]
                    or (lo < z and z <= hi)):
                continue
            uc[b, ix(i, 0, 1, l)] = _current(z, cz, cu, csc)
            if m >= 2 and cz[0] < z < cz[m - 1]:
                j = _current_interval(z, cz, csc)
                memo[b, ix(i, 0, 4, l)] = cz[j]
                memo[b, ix(i, 1, 4, l)] = cz[j + 1]
                memo[b, ix(i, 2, 4, l)] = cu[j]
                memo[b, ix(i, 3, 4, l)] = cu[j + 1]


@njit(**LANE_JIT)
def fluid_forces(b, n, v, q, P, SC, uc, wk, lf, want_jac, waves, clump, f, Dg):
    """:func:`~.fluid.fluid_forces` of block ``b`` (current speeds ``uc`` of
    :func:`current_lookup`; ``waves``: some node has a wave acceleration, ``clump``: some node
    a clump drag)."""
    lw = lanes_in(q, 3 * n)
    for i in range(n):
        for l in range(lw):
            qx = q[b, ix(i, 0, 3, l)]
            qy = q[b, ix(i, 1, 3, l)]
            qz = q[b, ix(i, 2, 3, l)]
            u = uc[b, ix(i, 0, 1, l)]
            vrx = v[b, ix(i, 0, 3, l)] - u * SC[b, ix(0, S_CURC, N_S, l)] - wk[b, ix(i, 0, 6, l)]
            vry = v[b, ix(i, 1, 3, l)] - u * SC[b, ix(0, S_CURS, N_S, l)] - wk[b, ix(i, 1, 6, l)]
            vrz = v[b, ix(i, 2, 3, l)] - wk[b, ix(i, 2, 6, l)]
            vq = vrx * qx + vry * qy + vrz * qz
            vnx = vrx - vq * qx
            vny = vry - vq * qy
            vnz = vrz - vq * qz
            vn = math.sqrt(vnx * vnx + vny * vny + vnz * vnz)
            kdn = P[b, ix(i, NP_KDN, N_NP, l)]
            kdt = P[b, ix(i, NP_KDT, N_NP, l)]
            f0 = f[b, ix(i, 0, 3, l)] - (kdn * vn * vnx + kdt * abs(vq) * vq * qx)
            f1 = f[b, ix(i, 1, 3, l)] - (kdn * vn * vny + kdt * abs(vq) * vq * qy)
            f2 = f[b, ix(i, 2, 3, l)] - (kdn * vn * vnz + kdt * abs(vq) * vq * qz)
            # the wave terms as selects, loaded for every node (``waves`` only decides
            # whether any node has them: a load under a run-time branch keeps the lane loop
            # from vectorising)
            awx = wk[b, ix(i, 3, 6, l)]
            awy = wk[b, ix(i, 4, 6, l)]
            awz = wk[b, ix(i, 5, 6, l)]
            on = waves and (awx != 0.0 or awy != 0.0 or awz != 0.0)
            aq = awx * qx + awy * qy + awz * qz
            md = P[b, ix(i, NP_MD, N_NP, l)]
            man = P[b, ix(i, NP_MAN, N_NP, l)]
            mat = P[b, ix(i, NP_MAT, N_NP, l)]
            f0 = f0 + (md * awx + man * (awx - aq * qx) + mat * aq * qx) if on else f0
            f1 = f1 + (md * awy + man * (awy - aq * qy) + mat * aq * qy) if on else f1
            f2 = f2 + (md * awz + man * (awz - aq * qz) + mat * aq * qz) if on else f2
            kc = 0.0
            vr = 0.0
            if clump:
                kc = P[b, ix(i, NP_KC, N_NP, l)]
                hc = kc > 0.0
                vr = math.sqrt(vrx * vrx + vry * vry + vrz * vrz) if hc else 0.0
                f0 = f0 - kc * vr * vrx if hc else f0
                f1 = f1 - kc * vr * vry if hc else f1
                f2 = f2 - kc * vr * vrz if hc else f2
            f[b, ix(i, 0, 3, l)] = f0
            f[b, ix(i, 1, 3, l)] = f1
            f[b, ix(i, 2, 3, l)] = f2
            if not want_jac:
                continue
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
            pos = vn > 0.0
            kn = kdn * vnx
            v00 = v00 + kn * vnx / vn if pos else v00
            v01 = v01 + kn * vny / vn if pos else v01
            v02 = v02 + kn * vnz / vn if pos else v02
            kn = kdn * vny
            v10 = v10 + kn * vnx / vn if pos else v10
            v11 = v11 + kn * vny / vn if pos else v11
            v12 = v12 + kn * vnz / vn if pos else v12
            kn = kdn * vnz
            v20 = v20 + kn * vnx / vn if pos else v20
            v21 = v21 + kn * vny / vn if pos else v21
            v22 = v22 + kn * vnz / vn if pos else v22
            if clump:
                hc = kc > 0.0
                kr = kc * vr
                v00 = v00 + kr * 1.0 if hc else v00
                v01 = v01 + kr * 0.0 if hc else v01
                v02 = v02 + kr * 0.0 if hc else v02
                v10 = v10 + kr * 0.0 if hc else v10
                v11 = v11 + kr * 1.0 if hc else v11
                v12 = v12 + kr * 0.0 if hc else v12
                v20 = v20 + kr * 0.0 if hc else v20
                v21 = v21 + kr * 0.0 if hc else v21
                v22 = v22 + kr * 1.0 if hc else v22
                hv = hc and vr > 0.0
                kn = kc * vrx
                v00 = v00 + kn * vrx / vr if hv else v00
                v01 = v01 + kn * vry / vr if hv else v01
                v02 = v02 + kn * vrz / vr if hv else v02
                kn = kc * vry
                v10 = v10 + kn * vrx / vr if hv else v10
                v11 = v11 + kn * vry / vr if hv else v11
                v12 = v12 + kn * vrz / vr if hv else v12
                kn = kc * vrz
                v20 = v20 + kn * vrx / vr if hv else v20
                v21 = v21 + kn * vry / vr if hv else v21
                v22 = v22 + kn * vrz / vr if hv else v22
            cC = lf[b, ix(LF_CC, 0, 1, l)]
            Dg[b, ix(i, 0, 9, l)] += cC * v00
            Dg[b, ix(i, 1, 9, l)] += cC * v01
            Dg[b, ix(i, 2, 9, l)] += cC * v02
            Dg[b, ix(i, 3, 9, l)] += cC * v10
            Dg[b, ix(i, 4, 9, l)] += cC * v11
            Dg[b, ix(i, 5, 9, l)] += cC * v12
            Dg[b, ix(i, 6, 9, l)] += cC * v20
            Dg[b, ix(i, 7, 9, l)] += cC * v21
            Dg[b, ix(i, 8, 9, l)] += cC * v22


@njit(inline="always")
def contact(pen, w, ks, dc):
    """The contact law of :func:`~.seabed.seabed_forces` at the penetration ``pen`` (node
    weight ``w``, spring ``ks``, smoothing ``dc``): ``(gp, dg, sm, dsm)``, the spring's
    ``g(pen)`` and slope and the damping's smooth step and slope."""
    dpen = max(0.5 * max(w, 1e-12) / ks, dc)
    x = pen / dpen
    inr = pen < dpen
    gp = pen * x * (2.0 - x) if inr else pen
    dg = x * (4.0 - 3.0 * x) if inr else 1.0
    sm = x * x * (3.0 - 2.0 * x) if inr else 1.0
    dsm = 6.0 * x * (1.0 - x) / dpen if inr else 0.0
    return gp, dg, sm, dsm


@njit(**LANE_JIT)
def seabed_contact(b, n, r, v, P, SC, lf, want_jac, f, Dg):
    """Seabed contact of :func:`~.seabed.seabed_forces` (spring and damping) of block ``b``;
    friction: :func:`friction`."""
    lw = lanes_in(r, 3 * n)
    for i in range(n):
        for l in range(lw):
            pen = SC[b, ix(0, S_ZC, N_S, l)] - r[b, ix(i, 2, 3, l)]
            ks = P[b, ix(i, NP_KS, N_NP, l)]
            on = pen > 0.0 and ks > 0.0
            gp, dg, sm, dsm = contact(pen, P[b, ix(i, NP_W, N_NP, l)], ks,
                                      SC[b, ix(0, S_DC, N_S, l)])
            cs = P[b, ix(i, NP_CS, N_NP, l)]
            vz = v[b, ix(i, 2, 3, l)]
            both = vz <= -V_SB or SC[b, ix(0, S_SBLIFT, N_S, l)] > 0.0
            up = vz >= V_SB
            xv = (vz + V_SB) / (2.0 * V_SB)
            phi = 1.0 - xv * xv * (3.0 - 2.0 * xv)
            h = vz if both else (0.0 if up else vz * phi)
            dh = 1.0 if both else (0.0 if up else phi - vz * 6.0 * xv * (1.0 - xv) / (2.0 * V_SB))
            N = ks * gp
            f2 = f[b, ix(i, 2, 3, l)]
            f[b, ix(i, 2, 3, l)] = f2 + (N - cs * sm * h) if on else f2
            if want_jac:
                cK = lf[b, ix(LF_CK, 0, 1, l)]
                cC = lf[b, ix(LF_CC, 0, 1, l)]
                d22 = Dg[b, ix(i, 8, 9, l)]
                Dg[b, ix(i, 8, 9, l)] = (d22 + (cK * (ks * dg - cs * dsm * h) + cC * cs * sm * dh)
                                         if on else d22)


@njit(**KERNEL_JIT)
def friction(b, n, r, v, q, fs, P, S, fric, lf, want_jac, f, Dg, li):
    """Seabed friction (:func:`~.seabed._friction_node`) of every node of block ``b`` in
    contact, lane by lane, after :func:`seabed_contact` (which changes only the vertical force
    and its block entry, friction only the others: the order of the two does not matter)."""
    for l in range(LW):
        if not live(li, b, l):
            continue
        p = b * LW + l
        Sl = S[p]
        cK = lf[b, ix(LF_CK, 0, 1, l)]
        cC = lf[b, ix(LF_CC, 0, 1, l)]
        rl = lane_rows(r, b, n, 3, l)
        vl = lane_rows(v, b, n, 3, l)
        ql = lane_rows(q, b, n, 3, l)
        fsl = lane_rows(fs, b, n, N_FS, l)
        Pl = lane_rows(P, b, n, N_NP, l)
        fl = lane_rows(f, b, n, 3, l)
        Dl = Dg[b].reshape((n, 3, 3, LW))[:, :, :, l]
        for i in range(n):
            pen = Sl[S_ZC] - rl[i, 2]
            ks = Pl[i, NP_KS]
            if not (pen > 0.0 and ks > 0.0):
                continue
            gp, dg, sm, dsm = contact(pen, Pl[i, NP_W], ks, Sl[S_DC])
            _friction_node(i, rl, vl, ql[i, 0], ql[i, 1], fsl, Pl, Sl, fric, ks * gp, ks, dg,
                           want_jac, cK, cC, fl, Dl)


@njit(**KERNEL_JIT)
def bending(b, n, r, P, lf, want_jac, f, Dg, Of, BX, li):
    """Bending (:func:`~.elements.bending_forces`) of block ``b``, lane by lane (the
    :func:`live` ones; ``BX``: one (7, n, 3, 3) array per lane row)."""
    for l in range(LW):
        if not live(li, b, l):
            continue
        bending_forces(lane_rows(r, b, n, 3, l), lane_rows(P, b, n, N_NP, l),
                       lane_rows(f, b, n, 3, l), want_jac, lf[b, ix(LF_CK, 0, 1, l)],
                       Dg[b].reshape((n, 3, 3, LW))[:, :, :, l],
                       Of[b].reshape((n - 1, 3, 3, LW))[:, :, :, l], BX[b * LW + l])


@njit(inline="always")
def _elements(b, n, v, par, w, want_jac, use_act, damp, f):
    """:func:`element_forces` with ``damp`` as a constant (``want_jac`` is one)."""
    if damp:
        element_forces(b, n, v, par.P, par.E, par.EC, w.el, w.Tl, w.Dl, w.act, w.lf, want_jac,
                       use_act, True, w.tens, f, w.Dg, w.Of, w.carry)
    else:
        element_forces(b, n, v, par.P, par.E, par.EC, w.el, w.Tl, w.Dl, w.act, w.lf, want_jac,
                       use_act, False, w.tens, f, w.Dg, w.Of, w.carry)


@njit(inline="always")
def _fluid(b, n, v, par, w, want_jac, waves, clump, f):
    """:func:`fluid_forces` with ``clump`` as a constant (``want_jac`` is one)."""
    if clump:
        fluid_forces(b, n, v, w.q, par.P, par.SC, w.uc, par.wk, w.lf, want_jac, waves, True, f,
                     w.Dg)
    else:
        fluid_forces(b, n, v, w.q, par.P, par.SC, w.uc, par.wk, w.lf, want_jac, waves, False, f,
                     w.Dg)


@njit(**KERNEL_JIT)
def forces_into(b, n, par, r, v, fs, f, w, want_jac, use_act):
    """Nodal forces of block ``b`` at ``r, v`` (friction state ``fs``) into ``f`` and, with
    ``want_jac``, the tangent ``cK K + cC C`` (``cK, cC`` per lane in ``w.lf``) into ``w.Dg``,
    ``w.Of`` (``w.BX`` with bending): the passes of :func:`~.forces._line_forces` in its order
    (geometry and tangents, elements, bending, fluid loads, seabed contact and friction), the
    element tensions into ``w.tens``, the node tangents into ``w.q``.  The lane-by-lane passes
    skip the lanes that are not :func:`live` (``w.li``)."""
    flags = par.flags
    geometry(b, n, r, w.el)
    tangents(b, n, w.el, w.q)
    axial_law(b, n, par.E, par.EC, w.el, w.Tl, w.Dl)
    if flags[b, BF_FIBRE]:
        fibre_law(b, n, par.E, par.EC, par.S, w.el, fs, w.Tl, w.Dl, w.li)
    # the passes with the tangent or without it, and with the element damping or clump terms
    # or without them, are called with these flags as constants (numba compiles one version
    # per value): a run-time flag tested in the lane loop keeps LLVM from vectorising it
    # (measured: the element and fluid passes twice as fast as constants)
    if want_jac:
        _elements(b, n, v, par, w, True, use_act, flags[b, BF_DAMP] != 0, f)
    else:
        _elements(b, n, v, par, w, False, use_act, flags[b, BF_DAMP] != 0, f)
    if flags[b, BF_BEND]:
        bending(b, n, r, par.P, w.lf, want_jac, f, w.Dg, w.Of, w.BX, w.li)
    current_lookup(b, n, r, par.cur_c, w.cmemo, w.uc, w.li, w.cmiss)
    current_fix(b, n, r, par.cur_z, par.cur_u, par.cur_n, par.cur_c, w.cmemo, w.uc, w.li,
                w.cmiss)
    if want_jac:
        _fluid(b, n, v, par, w, True, flags[b, BF_WAVES] != 0, flags[b, BF_CLUMP] != 0, f)
        seabed_contact(b, n, r, v, par.P, par.SC, w.lf, True, f, w.Dg)
    else:
        _fluid(b, n, v, par, w, False, flags[b, BF_WAVES] != 0, flags[b, BF_CLUMP] != 0, f)
        seabed_contact(b, n, r, v, par.P, par.SC, w.lf, False, f, w.Dg)
    if flags[b, BF_FRIC] != 0:
        friction(b, n, r, v, w.q, fs, par.P, par.S, flags[b, BF_FRIC], w.lf, want_jac, f, w.Dg,
                 w.li)

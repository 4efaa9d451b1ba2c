"""Seabed contact and friction of the lumped-mass line: the contact spring and damping with
their smooth transitions, the friction models (velocity ramp, its double-quadratic variant,
the static displacement ramp, Lu's (2012) combined displacement and velocity ramp) and the
friction state kept between steps (:func:`friction_decide` at the start of a step,
:func:`friction_commit` after an accepted one).  See :mod:`.config` for the models."""

from __future__ import annotations

import math

from numba import njit

from .elements import _direction_sum
from .layout import (
    FR_DISPVEL,
    FR_NONE,
    FR_STATIC,
    FR_VDQ,
    FR_VEL,
    FS_FPREV,
    FS_UPREV,
    KERNEL_JIT,
    NP_CS,
    NP_KS,
    NP_MUA,
    NP_MUL,
    NP_W,
    S_CD,
    S_DC,
    S_SBLIFT,
    S_VR,
    S_ZC,
)

V_MEANINGFUL = 1e-8     # Lu (2012): below this a node is at rest (m/s)
D_MEANINGFUL = 1e-4     # Lu (2012): displacement ramp active beyond this (m)
V_SB = 0.01             # seabed damping switches off between -V_SB and +V_SB (m/s)


@njit(**KERNEL_JIT)
def _friction_dirs(qx, qy):
    h = math.sqrt(qx * qx + qy * qy)
    if h > 1e-12:
        ax = qx / h
        ay = qy / h
    else:
        ax = 1.0
        ay = 0.0
    return ax, ay, -ay, ax


@njit(**KERNEL_JIT)
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


@njit(**KERNEL_JIT)
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


@njit(**KERNEL_JIT)
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


@njit(**KERNEL_JIT)
def seabed_forces(r, v, q, fs, P, S, fric, want_jac, cK, cC, f, Dg):
    """Seabed contact and friction on every node below the seabed level, added into ``f``
    (n, 3) and, with ``want_jac``, their tangent blocks ``cK K + cC C`` into ``Dg``.

    Contact: spring force ``ks g(pen)`` with ``g(p) = p`` for ``p >= d = w / (2 ks)`` (half
    the static penetration) and the cubic ``2 p^2 / d - p^3 / d^2`` below (same value and slope
    at ``d``, zero slope at contact); damping faded in with the smooth step
    ``s(p / d) = 3 x^2 - 2 x^3``: the force is C1 in the position, so Newton does not cycle
    when a node touches down.  Friction (code ``fric``, state ``fs`` of the last accepted
    step, read only) in the horizontal axes along and across the node tangent ``q``.
    """
    zc = S[S_ZC]
    for i in range(r.shape[0]):
        pen = zc - r[i, 2]
        if not (pen > 0.0 and P[i, NP_KS] > 0.0):
            continue
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
            _friction_node(i, r, v, q[i, 0], q[i, 1], fs, P, S, fric, N, ks, dg, want_jac, cK,
                           cC, f, Dg)


@njit(**KERNEL_JIT)
def _friction_node(i, r, v, qx, qy, fs, P, S, fric, N, ks, dg, want_jac, cK, cC, f, Dg):
    """Friction on node ``i`` in contact with the normal force ``N = ks g(pen)`` (``dg`` the
    slope of ``g``), added into ``f`` and (``want_jac``) its tangent into ``Dg``."""
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
        return
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
            # displacement ramp with the quadratic transition 2x - x^2 (C1 at full friction,
            # like the velocity ramp) so Newton does not stall on the kink of a linear ramp
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
            c, kx, kv = _dispvel_coef(vk, dk, fs[i, 6 + k], fs[i, k], fs[i, 2 + k], S[S_VR],
                                      Cd, mu * N)
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


@njit(**KERNEL_JIT)
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


@njit(**KERNEL_JIT)
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

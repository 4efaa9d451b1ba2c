"""Fluid loads on the nodes of the lumped-mass line: the current profile, Morison drag on the
velocity relative to current and waves, the fluid inertia of the wave acceleration and the
drag of clump weights, with their tangent blocks.

At node ``i``: Morison drag ``-k_n |v_n| v_n - k_t |v_t| v_t`` on the relative velocity split
along the node tangent ``q``; fluid inertia ``(rho V l) a_w + m_an a_w,n + m_at a_w,t``; added
mass ``m_an (I - q q^T) + m_at q q^T`` (in the mass blocks, :mod:`.elements`).  The drag blocks
are nodal (the dependence of ``q`` on the positions is left out).
"""

from __future__ import annotations

import math

from numba import njit

from .layout import KERNEL_JIT, NP_KC, NP_KDN, NP_KDT, NP_MAN, NP_MAT, NP_MD, S_CURC, S_CURS


@njit(**KERNEL_JIT)
def _current_scale(cur_z):
    """Levels per metre of the current profile (the guess of :func:`_current`; 0 for fewer
    than two levels)."""
    n = cur_z.shape[0]
    if n < 2 or not cur_z[n - 1] > cur_z[0]:
        return 0.0
    return (n - 1) / (cur_z[n - 1] - cur_z[0])


@njit(**KERNEL_JIT)
def _current_interval(z, cur_z, sc):
    """The level interval ``j`` of ``cur_z[0] < z < cur_z[-1]`` (at least two levels, sorted):
    ``cur_z[j] < z <= cur_z[j + 1]``, guessed from the mean level spacing ``sc``
    (:func:`_current_scale`) and walked from there (no step for the uniform profiles the scenes
    build; the same interval as a bisection)."""
    n = cur_z.shape[0]
    g = (z - cur_z[0]) * sc
    j = 0
    if g >= 1.0:
        j = min(int(g), n - 2)
    while j > 0 and cur_z[j] >= z:
        j -= 1
    while cur_z[j + 1] < z:
        j += 1
    return j


@njit(**KERNEL_JIT)
def _current(z, cur_z, cur_u, sc):
    """Current speed at the level ``z`` (m/s), linear between the levels ``cur_z``; ``sc`` the
    levels per metre of :func:`_current_scale`.  Every node looks the current up at every
    force evaluation (the lanes keep each node's last interval: ``lanes_forces``)."""
    n = cur_z.shape[0]
    if n == 0:
        return 0.0
    if z <= cur_z[0] or n == 1:
        return cur_u[0]
    if z >= cur_z[n - 1]:
        return cur_u[n - 1]
    j = _current_interval(z, cur_z, sc)
    w = (z - cur_z[j]) / (cur_z[j + 1] - cur_z[j])
    return (1.0 - w) * cur_u[j] + w * cur_u[j + 1]


@njit(**KERNEL_JIT)
def fluid_forces(r, v, q, P, S, cur_z, cur_u, wk, want_jac, cC, f, Dg):
    """Drag, fluid inertia and clump drag on every node, added into ``f`` (n, 3); with
    ``want_jac`` their damping blocks times ``cC`` added into the diagonal blocks ``Dg``.

    ``r, v`` (n, 3) node positions and velocities, ``q`` (n, 3) node tangents, ``cur_z,
    cur_u`` the current profile (direction in ``S``), ``wk`` (n, 6) wave particle velocity and
    acceleration at the nodes."""
    ccos = S[S_CURC]
    csin = S[S_CURS]
    csc = _current_scale(cur_z)
    for i in range(r.shape[0]):
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
        if not want_jac:
            continue
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

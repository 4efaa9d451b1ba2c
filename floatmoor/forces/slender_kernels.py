"""Numba kernels of the slender-element (Morison strip) drag force, and its kinematics table.

Slender elements (Wang (2016) section 6.1; SIMO-style): straight line elements fixed to the body,
end points ``p1``, ``p2`` in body coordinates (m, about the body reference point).  Local axes:
``x`` from p1 to p2; for an element that is not vertical, local ``z`` is the body's ``z`` axis
made perpendicular to ``x`` ("up") and ``y = z x x``; for a vertical element (|x . z_body| >
0.999) local ``y`` is the body's ``x`` axis made perpendicular to ``x`` and ``z = x x y``.  (So a
pontoon along body y has local y = body x, local z = up; a column has local y = body x.)

Inertia (optional, off by default: the potential-flow database already carries it): ``cm_j a_j``
per unit length, ``cm_j = rho C_M A_j`` (kg/m) and ``a_j`` the wave particle acceleration along
local axis j (no body-acceleration term).

Force per unit length, quadratic drag per local axis (Wang (2016) eq. 6.3 and 6.7-6.8)::

    f = sum_j C_j |v_j| v_j e_j,    v_j = e_j . (u_current + u_wave - v_body)

``C_j = 0.5 rho C_D,j D_j`` (N s^2/m^3) for the local axes j = x, y, z; ``u_wave`` the linear wave
particle velocity at the strip, ``u_current`` the current at the strip's depth, ``v_body`` the
velocity of the strip's centre (reference point velocity + angular velocity x arm).  Each element
is integrated up to the instantaneous free surface: an element crossing the surface is cut where
it meets the elevation (the elevation at the element's MWL crossing), and the wetted part is split
into ``n_strips`` equal strips (midpoint rule).  Strips above the local surface are dry.  Forces
and moments (about the displaced reference point) are in earth axes.

Kinematics table: the wave kinematics are precomputed before the time loop (FFT) at fixed
*stations* (x, y) -- points along each element at the body's reference pose -- on a time grid of
step ``H``, at fixed *levels* z' of the stretched vertical coordinate:

* Wheeler stretching (default): a point at height z under the surface eta is evaluated at
  ``z' = (z - eta) d / (d + eta)`` (deep water ``z - eta``);
* constant stretching (``wheeler=False``): ``z' = min(z, 0)``, i.e. linear theory below the
  mean water line and the MWL velocity in the splash zone (Wang (2016) section 2.1.2, Chakrabarti).

In the loop the velocity at a strip is interpolated linearly in time, along the element between
its stations, and in z' between levels (clamped to the deepest level below it).  As for the
first-order wave forces, the horizontal wave phase is taken at the body's reference (mean)
position: the slow horizontal excursion does not shift the phase; the vertical position of the
strips follows the body exactly.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit
from numba.extending import overload

from ..core.frames import rotation_matrix_into

__all__ = ["local_axes", "slender_force_into", "slender_packed_into",
           "kinematics_at",
           "stretched_level"]


def local_axes(p1, p2):
    """Local unit axes (ex, ey, ez) in body coordinates of the element p1 -> p2 (module doc)."""
    p1 = np.asarray(p1, float)
    p2 = np.asarray(p2, float)
    ex = p2 - p1
    L = float(np.linalg.norm(ex))
    if L <= 0.0:
        raise ValueError("an element of zero length")
    ex = ex / L
    ez_body = np.array([0.0, 0.0, 1.0])
    if abs(float(ex @ ez_body)) < 0.999:
        ez = ez_body - (ez_body @ ex) * ex
        ez /= np.linalg.norm(ez)
        ey = np.cross(ez, ex)
    else:
        ex_body = np.array([1.0, 0.0, 0.0])
        ey = ex_body - (ex_body @ ex) * ex
        ey /= np.linalg.norm(ey)
        ez = np.cross(ex, ey)
    return ex, ey, ez


@njit(cache=True)
def stretched_level(z, eta, depth, wheeler):
    """The level z' (m) at which a point at height z under the surface eta is evaluated."""
    if wheeler:
        if math.isinf(depth):
            return z - eta
        return (z - eta) * depth / (depth + eta)
    return z if z < 0.0 else 0.0


@njit(cache=True)
def _eta_at(eta_tab, i0, wt, s0, s1, ws):
    a = (1.0 - ws) * eta_tab[i0, s0] + ws * eta_tab[i0, s1]
    b = (1.0 - ws) * eta_tab[i0 + 1, s0] + ws * eta_tab[i0 + 1, s1]
    return (1.0 - wt) * a + wt * b


@njit(cache=True)
def kinematics_at(u_tab, i0, wt, s0, s1, ws, zs, lev0, dlev, out):
    """Velocity (3,) at stretched level ``zs`` between stations s0, s1 (weight ws) and table
    times i0, i0 + 1 (weight wt), into ``out``.  Levels lev0 + l dlev, l = 0..nl-1 (lev0 < 0,
    the top level 0); below the deepest level the deepest value is used, above 0 the top one."""
    nl = u_tab.shape[2]
    x = (zs - lev0) / dlev
    if x <= 0.0:
        l0 = 0
        wl = 0.0
    elif x >= nl - 1:
        l0 = nl - 2
        wl = 1.0
    else:
        l0 = int(x)
        wl = x - l0
    for c in range(3):
        a = ((1.0 - wl) * ((1.0 - ws) * u_tab[i0, s0, l0, c] + ws * u_tab[i0, s1, l0, c])
             + wl * ((1.0 - ws) * u_tab[i0, s0, l0 + 1, c] + ws * u_tab[i0, s1, l0 + 1, c]))
        b = ((1.0 - wl) * ((1.0 - ws) * u_tab[i0 + 1, s0, l0, c] + ws * u_tab[i0 + 1, s1, l0, c])
             + wl * ((1.0 - ws) * u_tab[i0 + 1, s0, l0 + 1, c]
                     + ws * u_tab[i0 + 1, s1, l0 + 1, c]))
        out[c] = (1.0 - wt) * a + wt * b


@njit(cache=True)
def _current_at(cur_z, cur_speed, z):
    """Current speed at height z: linear in the table (``cur_z`` increasing and uniformly
    spaced), constant outside it."""
    n = cur_z.shape[0]
    if n == 0:
        return 0.0
    if z <= cur_z[0] or n == 1:
        return cur_speed[0]
    if z >= cur_z[n - 1]:
        return cur_speed[n - 1]
    x = (z - cur_z[0]) / (cur_z[n - 1] - cur_z[0]) * (n - 1)
    i = min(int(x), n - 2)
    w = x - i
    return (1.0 - w) * cur_speed[i] + w * cur_speed[i + 1]



@njit(cache=True, inline="always")
def _station(s, nst):
    """Stations ``k0, k1`` (0 .. nst-1, at the centres of nst equal parts of the element) and
    the weight ``ws`` of ``k1`` for the linear interpolation at the parameter ``s`` in [0, 1]
    (held constant beyond the end stations)."""
    x = s * nst - 0.5
    if x <= 0.0:
        k0 = 0
        ws = 0.0
    elif x >= nst - 1:
        k0 = max(nst - 2, 0)
        ws = 1.0 if nst > 1 else 0.0
    else:
        k0 = int(x)
        ws = x - k0
    k1 = k0 + 1 if nst > 1 else k0
    return k0, k1, ws


@njit(cache=True, inline="always")
def _trilinear(tab, i0, sa, sb, l0, c, w000, w001, w010, w011, w100, w101, w110, w111):
    """Component ``c`` of a (time, station, level, 3) table, trilinear with the given weights."""
    return (w000 * tab[i0, sa, l0, c] + w001 * tab[i0, sa, l0 + 1, c]
            + w010 * tab[i0, sb, l0, c] + w011 * tab[i0, sb, l0 + 1, c]
            + w100 * tab[i0 + 1, sa, l0, c]
            + w101 * tab[i0 + 1, sa, l0 + 1, c]
            + w110 * tab[i0 + 1, sb, l0, c]
            + w111 * tab[i0 + 1, sb, l0 + 1, c])

@njit(cache=True)
def slender_force_into(tau, tau_e, pose, vel, omega, p1, p2, ex_b, ey_b, ez_b, c2, cm, n_strips,
                       st_first, st_count, eta_tab, u_tab, a_tab, has_inertia, lev0, dlev,
                       depth, wheeler, wave_factor, cur_z, cur_speed, cur_cos, cur_sin, R, out):
    """Add the slender-element drag force and moment (earth axes) into ``out`` (6,).

    Parameters
    ----------
    tau, tau_e : float
        Time in samples of the velocity table (t / H) and of the elevation table (t / H_eta).
        Beyond a table its last sample is held.
    pose : (6,) x, y, z (m), roll, pitch, yaw (rad) of the reference point.
    vel : (3,) earth velocity (m/s) of the reference point.
    omega : (3,) angular velocity (rad/s), earth axes.
    p1, p2, ex_b, ey_b, ez_b : (ne, 3) end points (m) and local unit axes, body coordinates.
    c2 : (ne, 3) quadratic drag per unit length along local x, y, z (N s^2/m^3).
    cm : (ne, 3) inertia per unit length rho C_M A along local x, y, z (kg/m): force
        cm_j a_j with a_j the wave particle acceleration along axis j (Froude-Krylov +
        diffraction of a fixed strip; the body-acceleration (added-mass) term is left to the
        potential-flow added mass).  Used only when ``has_inertia``.
    n_strips : (ne,) int strips per element (over its wetted length).
    st_first, st_count : (ne,) int first station and number of stations of each element
        (stations at s = (i + 0.5) / st_count along the element).
    eta_tab : (nte, ns) elevation (m); u_tab : (nt, ns, nl, 3) wave velocity (m/s, earth);
        a_tab : the same for the wave acceleration (m/s^2) (any array when not has_inertia).
    lev0, dlev : deepest level (m, < 0) and level spacing (m) of u_tab.
    depth : water depth (m) (inf: deep water); wheeler : bool, Wheeler stretching.
    wave_factor : float, ramp factor on the wave kinematics (0..1).
    cur_z, cur_speed : (nc,) current profile (m, increasing; m/s); cur_cos, cur_sin : heading.
    R : (3, 3) scratch.
    """
    rotation_matrix_into(pose[3], pose[4], pose[5], R)
    nt = eta_tab.shape[0]
    if tau <= 0.0:
        i0 = 0
        wt = 0.0
    elif tau >= nt - 1:
        i0 = nt - 2
        wt = 1.0
    else:
        i0 = int(tau)
        wt = tau - i0
    nte = eta_tab.shape[0]
    if tau_e <= 0.0:
        ie = 0
        we = 0.0
    elif tau_e >= nte - 1:
        ie = nte - 2
        we = 1.0
    else:
        ie = int(tau_e)
        we = tau_e - ie
    ne = p1.shape[0]
    for e in range(ne):
        # end points and axes in earth coordinates
        a0 = pose[0] + R[0, 0] * p1[e, 0] + R[0, 1] * p1[e, 1] + R[0, 2] * p1[e, 2]
        a1 = pose[1] + R[1, 0] * p1[e, 0] + R[1, 1] * p1[e, 1] + R[1, 2] * p1[e, 2]
        a2 = pose[2] + R[2, 0] * p1[e, 0] + R[2, 1] * p1[e, 1] + R[2, 2] * p1[e, 2]
        b0 = pose[0] + R[0, 0] * p2[e, 0] + R[0, 1] * p2[e, 1] + R[0, 2] * p2[e, 2]
        b1 = pose[1] + R[1, 0] * p2[e, 0] + R[1, 1] * p2[e, 1] + R[1, 2] * p2[e, 2]
        b2 = pose[2] + R[2, 0] * p2[e, 0] + R[2, 1] * p2[e, 1] + R[2, 2] * p2[e, 2]
        L = math.sqrt((b0 - a0) ** 2 + (b1 - a1) ** 2 + (b2 - a2) ** 2)
        nst = st_count[e]
        sf = st_first[e]
        # wetted part [s_lo, s_hi] of the parameter s in [0, 1] (p1 at s = 0)
        s_lo = 0.0
        s_hi = 1.0
        dz = b2 - a2
        if abs(dz) > 1e-9 * L:
            # elevation at the MWL crossing (clamped to the element), then the parameter
            # where the element meets that surface
            sc = min(max(-a2 / dz, 0.0), 1.0)
            k0, k1, ws = _station(sc, nst)
            eta = wave_factor * _eta_at(eta_tab, ie, we, sf + k0, sf + k1, ws)
            sw = (eta - a2) / dz
            if dz < 0.0:  # p1 above p2: wet for s >= sw
                s_lo = min(max(sw, 0.0), 1.0)
            else:
                s_hi = min(max(sw, 0.0), 1.0)
        if s_hi <= s_lo:
            continue
        ns = n_strips[e]
        ds = (s_hi - s_lo) / ns
        seg = ds * L
        # local axes in earth coordinates
        ex0 = R[0, 0] * ex_b[e, 0] + R[0, 1] * ex_b[e, 1] + R[0, 2] * ex_b[e, 2]
        ex1 = R[1, 0] * ex_b[e, 0] + R[1, 1] * ex_b[e, 1] + R[1, 2] * ex_b[e, 2]
        ex2 = R[2, 0] * ex_b[e, 0] + R[2, 1] * ex_b[e, 1] + R[2, 2] * ex_b[e, 2]
        ey0 = R[0, 0] * ey_b[e, 0] + R[0, 1] * ey_b[e, 1] + R[0, 2] * ey_b[e, 2]
        ey1 = R[1, 0] * ey_b[e, 0] + R[1, 1] * ey_b[e, 1] + R[1, 2] * ey_b[e, 2]
        ey2 = R[2, 0] * ey_b[e, 0] + R[2, 1] * ey_b[e, 1] + R[2, 2] * ey_b[e, 2]
        ez0 = R[0, 0] * ez_b[e, 0] + R[0, 1] * ez_b[e, 1] + R[0, 2] * ez_b[e, 2]
        ez1 = R[1, 0] * ez_b[e, 0] + R[1, 1] * ez_b[e, 1] + R[1, 2] * ez_b[e, 2]
        ez2 = R[2, 0] * ez_b[e, 0] + R[2, 1] * ez_b[e, 1] + R[2, 2] * ez_b[e, 2]
        for i in range(ns):
            s = s_lo + (i + 0.5) * ds
            px = a0 + s * (b0 - a0)
            py = a1 + s * (b1 - a1)
            pz = a2 + s * (b2 - a2)
            k0, k1, ws = _station(s, nst)
            eta = wave_factor * _eta_at(eta_tab, ie, we, sf + k0, sf + k1, ws)
            if pz > eta:
                continue  # dry strip
            zs = stretched_level(pz, eta, depth, wheeler)
            # wave velocity (interpolated) at the strip
            x = (zs - lev0) / dlev
            nl = u_tab.shape[2]
            if x <= 0.0:
                l0 = 0
                wl = 0.0
            elif x >= nl - 1:
                l0 = nl - 2
                wl = 1.0
            else:
                l0 = int(x)
                wl = x - l0
            # trilinear weights (time, station, level)
            w000 = (1.0 - wt) * (1.0 - ws) * (1.0 - wl)
            w001 = (1.0 - wt) * (1.0 - ws) * wl
            w010 = (1.0 - wt) * ws * (1.0 - wl)
            w011 = (1.0 - wt) * ws * wl
            w100 = wt * (1.0 - ws) * (1.0 - wl)
            w101 = wt * (1.0 - ws) * wl
            w110 = wt * ws * (1.0 - wl)
            w111 = wt * ws * wl
            sa = sf + k0
            sb = sf + k1
            uw0 = wave_factor * _trilinear(u_tab, i0, sa, sb, l0, 0, w000, w001,
                                           w010, w011, w100, w101, w110, w111)
            uw1 = wave_factor * _trilinear(u_tab, i0, sa, sb, l0, 1, w000, w001,
                                           w010, w011, w100, w101, w110, w111)
            uw2 = wave_factor * _trilinear(u_tab, i0, sa, sb, l0, 2, w000, w001,
                                           w010, w011, w100, w101, w110, w111)
            if has_inertia:
                aw0 = wave_factor * _trilinear(a_tab, i0, sa, sb, l0, 0, w000, w001,
                                               w010, w011, w100, w101, w110, w111)
                aw1 = wave_factor * _trilinear(a_tab, i0, sa, sb, l0, 1, w000, w001,
                                               w010, w011, w100, w101, w110, w111)
                aw2 = wave_factor * _trilinear(a_tab, i0, sa, sb, l0, 2, w000, w001,
                                               w010, w011, w100, w101, w110, w111)
            else:
                aw0 = 0.0
                aw1 = 0.0
                aw2 = 0.0
            uc = _current_at(cur_z, cur_speed, pz)
            rx = px - pose[0]
            ry = py - pose[1]
            rz = pz - pose[2]
            vx = uc * cur_cos + uw0 - (vel[0] + omega[1] * rz - omega[2] * ry)
            vy = uc * cur_sin + uw1 - (vel[1] + omega[2] * rx - omega[0] * rz)
            vz = uw2 - (vel[2] + omega[0] * ry - omega[1] * rx)
            qx = ex0 * vx + ex1 * vy + ex2 * vz
            qy = ey0 * vx + ey1 * vy + ey2 * vz
            qz = ez0 * vx + ez1 * vy + ez2 * vz
            gx = c2[e, 0] * abs(qx) * qx * seg
            gy = c2[e, 1] * abs(qy) * qy * seg
            gz = c2[e, 2] * abs(qz) * qz * seg
            if has_inertia:
                gx += cm[e, 0] * (ex0 * aw0 + ex1 * aw1 + ex2 * aw2) * seg
                gy += cm[e, 1] * (ey0 * aw0 + ey1 * aw1 + ey2 * aw2) * seg
                gz += cm[e, 2] * (ez0 * aw0 + ez1 * aw1 + ez2 * aw2) * seg
            fx = gx * ex0 + gy * ey0 + gz * ez0
            fy = gx * ex1 + gy * ey1 + gz * ez1
            fz = gx * ex2 + gy * ey2 + gz * ez2
            out[0] += fx
            out[1] += fy
            out[2] += fz
            out[3] += ry * fz - rz * fy
            out[4] += rz * fx - rx * fz
            out[5] += rx * fy - ry * fx


@njit(cache=True)
def slender_packed_into(j, x, v, fel, iel, eta_tab, u_tab, a_tab, par, cur, ramp, R, sc, out):
    """:func:`slender_force_into` on the packed arrays of the time-domain kernel.

    j : sample index (time j h, h = dt/2); x : pose (6,); v : velocity in the yaw-following
    frame (6,) as in the solver (horizontal velocity and roll/pitch rates about the turned
    axes).  fel (ne, 21) = [p1, p2, ex, ey, ez, c2, cm]; iel (ne, 3) = [n_strips, st_first,
    st_count]; a_tab the acceleration table (used when par[7] > 0.5); par = [m (samples per
    table step), lev0, dlev, depth, wheeler, cos, sin of the current heading, inertia on,
    samples per elevation-table step];
    cur (nc, 2) = current profile [z, speed]; ramp (n_samples,) the factor on
    the wave kinematics; R (3, 3), sc (6,) scratch.  Adds into ``out`` (6,), earth axes.
    """
    cy = math.cos(x[5])
    sy = math.sin(x[5])
    sc[0] = cy * v[0] - sy * v[1]
    sc[1] = sy * v[0] + cy * v[1]
    sc[2] = v[2]
    sc[3] = cy * v[3] - sy * v[4]
    sc[4] = sy * v[3] + cy * v[4]
    sc[5] = v[5]
    n = ramp.shape[0]
    jj = j if j < n else n - 1
    slender_force_into(j / par[0], j / par[8], x, sc[0:3], sc[3:6], fel[:, 0:3], fel[:, 3:6],
                       fel[:, 6:9], fel[:, 9:12], fel[:, 12:15], fel[:, 15:18], fel[:, 18:21],
                       iel[:, 0], iel[:, 1], iel[:, 2], eta_tab, u_tab, a_tab, par[7] > 0.5,
                       par[1], par[2], par[3], par[4] > 0.5, ramp[jj], cur[:, 0], cur[:, 1],
                       par[5], par[6], R, out)


def strips_into(j, x, v, sl, R, sc, out):
    """Add the force of the strips bundle ``sl`` (:class:`~floatmoor.forces.terms.StripTerm`,
    :func:`slender_packed_into`) into ``out``; nothing for a
    :class:`~floatmoor.forces.terms.NoStrips` bundle.  Compiled, the choice is made on the
    bundle's type (:func:`_strips_into_typed`): a time loop compiled for a run without strips
    neither contains nor compiles the strip code."""
    if sl.on:
        slender_packed_into(j, x, v, sl.fel, sl.iel, sl.eta, sl.u, sl.a, sl.par, sl.cur,
                            sl.ramp, R, sc, out)


@overload(strips_into)
def _strips_into_typed(j, x, v, sl, R, sc, out):
    from .terms import NoStrips
    if getattr(sl, "instance_class", None) is NoStrips:
        def nothing(j, x, v, sl, R, sc, out):
            return None
        return nothing

    def strips(j, x, v, sl, R, sc, out):
        slender_packed_into(j, x, v, sl.fel, sl.iel, sl.eta, sl.u, sl.a, sl.par, sl.cur,
                            sl.ramp, R, sc, out)
    return strips

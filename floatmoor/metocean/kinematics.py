"""Linear (Airy) wave kinematics in finite depth, with Wheeler stretching.

Conventions: earth frame, z up, z = 0 the mean water line, seabed at z = -d.  A component i of
amplitude a, angular frequency w, wavenumber k, direction of travel beta and phase phi has the
elevation and phase angle

    eta_i   = a cos(theta),   theta = w t - k (x cos beta + y sin beta) + phi

(exp(+i w t) convention), and the linear potential-flow kinematics (e.g. Faltinsen 1990,
table 2.1, or DNV-RP-C205 table 3-1, rewritten for this phase)::

    u_h = a w  C_s(z) cos(theta)      horizontal, along beta
    w   = -a w S_s(z) sin(theta)      vertical
    du_h/dt = -a w^2 C_s(z) sin(theta)
    dw/dt   = -a w^2 S_s(z) cos(theta)
    p_dyn   = rho g a C_c(z) cos(theta)

with C_s = cosh k(z+d)/sinh kd, S_s = sinh k(z+d)/sinh kd, C_c = cosh k(z+d)/cosh kd.  These
ratios are evaluated in exponential form, e.g.
C_s = (e^{kz} + e^{-k(z+2d)}) / (1 - e^{-2kd}), which never overflows for large kd and tends to
e^{kz} in deep water (d = inf is accepted).

Wheeler stretching (``wheeler=True``): a point at height z below the instantaneous surface eta
is evaluated at z' = (z - eta) d / (d + eta) (deep water: z' = z - eta), so the free surface maps
to z' = 0 and the seabed stays at -d.  Without stretching, linear theory is evaluated at z
itself (exponential extrapolation above z = 0).  Points above the instantaneous surface are dry:
all outputs except eta are 0.  Points below the seabed are evaluated at the seabed.

The kernels are numba-compiled (``cache=True``), take arrays and scalars only and write into
preallocated outputs; they also run with NUMBA_DISABLE_JIT=1.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from floatmoor.core.constants import GRAVITY, RHO_WATER
from floatmoor.core.errors import ConvergenceError, SceneError

__all__ = ["wavenumber", "depth_factors", "surface_elevation_into", "airy_kinematics_into",
           "airy_kinematics"]


def wavenumber(omega, water_depth: float | None = None, g: float = GRAVITY) -> np.ndarray:
    """Wavenumbers k (rad/m) from the linear dispersion relation w^2 = g k tanh(k d).

    Parameters
    ----------
    omega : array_like
        Angular frequencies (rad/s), > 0.
    water_depth : float or None
        Water depth d (m); None or inf gives deep water, k = w^2/g.
    g : float
        Acceleration of gravity (m/s^2).

    Returns
    -------
    numpy.ndarray
        k (rad/m), same shape as omega; Newton iteration to a relative residual < 1e-13.
    """
    w = np.asarray(omega, dtype=float)
    if np.any(~np.isfinite(w)) or np.any(w <= 0.0):
        raise SceneError(None, "omega", "angular frequencies > 0 rad/s", w[~(w > 0)][:3])
    k0 = w * w / g
    if water_depth is None or math.isinf(water_depth):
        return k0
    d = float(water_depth)
    if not math.isfinite(d) or d <= 0.0:
        raise SceneError(None, "site.water_depth", "a number > 0 (m)", water_depth)
    # Initial guess of Eckart (1952); then Newton on f(k) = g k tanh(kd) - w^2.
    k = k0 / np.sqrt(np.tanh(np.minimum(k0 * d, 50.0)))
    for _ in range(60):
        th = np.tanh(k * d)
        f = g * k * th - w * w
        df = g * th + g * k * d * (1.0 - th * th)
        step = f / df
        k = k - step
        if np.all(np.abs(step) <= 1e-14 * k):
            break
    res = np.abs(g * k * np.tanh(k * d) - w * w) / (w * w)
    if not np.all(res < 1e-12):
        raise ConvergenceError("dispersion relation did not converge", where="wavenumber",
                               remedy="check omega and water_depth")
    return k


@njit(cache=True)
def depth_factors(k, z, depth):
    """(C_s, S_s, C_c) = (cosh k(z+d)/sinh kd, sinh k(z+d)/sinh kd, cosh k(z+d)/cosh kd).

    Overflow-free exponential form; ``depth = inf`` gives (e^{kz}, e^{kz}, e^{kz}).
    """
    e1 = math.exp(k * z)
    if math.isinf(depth):
        return e1, e1, e1
    e2 = math.exp(-k * (z + 2.0 * depth))
    q = math.exp(-2.0 * k * depth)
    return (e1 + e2) / (1.0 - q), (e1 - e2) / (1.0 - q), (e1 + e2) / (1.0 + q)


@njit(cache=True)
def surface_elevation_into(omega, amplitude, phase, kx, ky, t, x, y, out):
    """Elevation (m) at one point (x, y) for the times ``t`` (s) into ``out``."""
    n = omega.shape[0]
    for j in range(t.shape[0]):
        s = 0.0
        for i in range(n):
            s += amplitude[i] * math.cos(omega[i] * t[j] - kx[i] * x - ky[i] * y + phase[i])
        out[j] = s


@njit(cache=True)
def airy_kinematics_into(omega, amplitude, phase, k, cos_dir, sin_dir, depth, g, rho, wheeler,
                         t, points, work, velocity, acceleration, pressure, eta):
    """Linear wave kinematics at ``points`` and one time ``t``.

    Parameters
    ----------
    omega, amplitude, phase, k, cos_dir, sin_dir : (n,) arrays
        Components: rad/s, m, rad, rad/m, and the cosine/sine of the direction of travel.
    depth : float
        Water depth (m); inf for deep water.
    g, rho : float
        Gravity (m/s^2) and water density (kg/m^3) for the dynamic pressure.
    wheeler : bool
        Apply Wheeler stretching.
    t : float
        Time (s).
    points : (m, 3) array
        Earth-frame points (m).
    work : (3, n) array
        Scratch space (cos and sin of the phase angles, exp(-2 k d)).
    velocity, acceleration : (m, 3) arrays (out)
        m/s and m/s^2.
    pressure : (m,) array (out)
        Dynamic pressure (Pa), excluding hydrostatic -rho g z.
    eta : (m,) array (out)
        Elevation (m) at the points' (x, y).
    """
    n = omega.shape[0]
    deep = math.isinf(depth)
    for i in range(n):  # per-component constant exp(-2 k d) (0 in deep water)
        work[2, i] = 0.0 if deep else math.exp(-2.0 * k[i] * depth)
    for p in range(points.shape[0]):
        x = points[p, 0]
        y = points[p, 1]
        z = points[p, 2]
        e = 0.0
        for i in range(n):
            th = omega[i] * t - k[i] * (x * cos_dir[i] + y * sin_dir[i]) + phase[i]
            c = math.cos(th)
            s = math.sin(th)
            work[0, i] = c
            work[1, i] = s
            e += amplitude[i] * c
        eta[p] = e
        for j in range(3):
            velocity[p, j] = 0.0
            acceleration[p, j] = 0.0
        pressure[p] = 0.0
        if z > e:
            continue
        if z < -depth:
            z = -depth
        if wheeler:
            if deep:
                zs = z - e
            else:
                zs = (z - e) * depth / (depth + e)
        else:
            zs = z
        uh_x = 0.0
        uh_y = 0.0
        uz = 0.0
        ah_x = 0.0
        ah_y = 0.0
        az = 0.0
        pd = 0.0
        for i in range(n):
            # depth factors as in depth_factors(), with e2 = exp(-k (zs + 2d)) = q / e1 <= e1
            e1 = math.exp(k[i] * zs)
            q = work[2, i]
            e2 = q / e1 if e1 > 0.0 else 0.0
            cs = (e1 + e2) / (1.0 - q)
            ss = (e1 - e2) / (1.0 - q)
            cc = (e1 + e2) / (1.0 + q)
            aw = amplitude[i] * omega[i]
            aww = aw * omega[i]
            c = work[0, i]
            s = work[1, i]
            uh = aw * cs * c
            ah = -aww * cs * s
            uh_x += uh * cos_dir[i]
            uh_y += uh * sin_dir[i]
            ah_x += ah * cos_dir[i]
            ah_y += ah * sin_dir[i]
            uz += -aw * ss * s
            az += -aww * ss * c
            pd += amplitude[i] * cc * c
        velocity[p, 0] = uh_x
        velocity[p, 1] = uh_y
        velocity[p, 2] = uz
        acceleration[p, 0] = ah_x
        acceleration[p, 1] = ah_y
        acceleration[p, 2] = az
        pressure[p] = rho * g * pd


def airy_kinematics(omega, amplitude, phase, k, direction, t, points, *, water_depth=None,
                    wheeler: bool = True, g: float = GRAVITY, rho: float = RHO_WATER) -> dict:
    """Convenience wrapper of :func:`airy_kinematics_into` over many times.

    Parameters
    ----------
    omega, amplitude, phase, k, direction : array_like, shape (n,)
        Wave components (rad/s, m, rad, rad/m, rad direction of travel).
    t : array_like
        Times (s), scalar or 1-D (nt,).
    points : array_like, shape (m, 3)
        Points (m).
    water_depth : float or None
        Water depth (m); None: deep water.
    wheeler : bool
        Wheeler stretching (default True).

    Returns
    -------
    dict
        ``velocity`` (nt, m, 3) m/s, ``acceleration`` (nt, m, 3) m/s^2, ``pressure`` (nt, m) Pa
        (dynamic), ``eta`` (nt, m) m.
    """
    omega = np.ascontiguousarray(omega, dtype=float)
    amplitude = np.ascontiguousarray(amplitude, dtype=float)
    phase = np.ascontiguousarray(phase, dtype=float)
    k = np.ascontiguousarray(k, dtype=float)
    direction = np.asarray(direction, dtype=float)
    cos_dir = np.ascontiguousarray(np.broadcast_to(np.cos(direction), omega.shape))
    sin_dir = np.ascontiguousarray(np.broadcast_to(np.sin(direction), omega.shape))
    ta = np.atleast_1d(np.asarray(t, dtype=float))
    pts = np.ascontiguousarray(np.atleast_2d(np.asarray(points, dtype=float)))
    if pts.ndim != 2 or pts.shape[1] != 3:
        raise SceneError(None, "points", "an (m, 3) array of x, y, z (m)", pts.shape)
    depth = math.inf if water_depth is None else float(water_depth)
    if not depth > 0.0:
        raise SceneError(None, "site.water_depth", "a number > 0 (m)", water_depth)
    nt, m = ta.size, pts.shape[0]
    vel = np.empty((nt, m, 3))
    acc = np.empty((nt, m, 3))
    pres = np.empty((nt, m))
    eta = np.empty((nt, m))
    work = np.empty((3, omega.size))
    for j in range(nt):
        airy_kinematics_into(omega, amplitude, phase, k, cos_dir, sin_dir, depth, float(g),
                             float(rho), bool(wheeler), float(ta[j]), pts, work, vel[j], acc[j],
                             pres[j], eta[j])
    return {"velocity": vel, "acceleration": acc, "pressure": pres, "eta": eta}

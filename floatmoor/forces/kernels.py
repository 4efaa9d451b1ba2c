"""Numba kernels of the force models that act inside the time loop (no allocation).

They are shared by the models' Python ``force`` methods and by the time-domain kernel, and can
be called directly with plain arrays (they also run with ``NUMBA_DISABLE_JIT=1``).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

__all__ = ["table_at_into", "relative_flow_force_into", "quadratic_damping_into",
           "matvec_sub_into", "turn_horizontal", "to_yaw_frame", "to_earth"]

TWO_PI = 2.0 * math.pi


@njit(cache=True)
def table_at_into(heading, table_heading, table, out):
    """Coefficients (6,) at a relative heading (rad): periodic linear interpolation of
    ``table`` (n, 6) given at increasing ``table_heading`` (n,) spanning less than 2 pi."""
    n = table_heading.shape[0]
    h0 = table_heading[0]
    x = (heading - h0) % TWO_PI + h0
    k = n - 1
    for i in range(n - 1):
        if x < table_heading[i + 1]:
            k = i
            break
    if k == n - 1:
        x1 = table_heading[0] + TWO_PI
        k1 = 0
    else:
        x1 = table_heading[k + 1]
        k1 = k + 1
    x0 = table_heading[k]
    w = (x - x0) / (x1 - x0) if x1 > x0 else 0.0
    for d in range(6):
        out[d] = (1.0 - w) * table[k, d] + w * table[k1, d]


@njit(cache=True)
def relative_flow_force_into(speed, heading, vx, vy, yaw, ramp_factor, table_heading, table,
                             coef, out):
    """Add ``ramp_factor * C(theta_rel) |U_rel|^2`` (turned to earth axes) into ``out`` (6,).

    ``U_rel = speed (cos heading, sin heading) - (vx, vy)`` is the flow relative to the body's
    horizontal velocity at the reference point (earth axes); ``theta_rel = atan2(U_rel) - yaw``
    its direction of travel relative to the body x axis.  ``C`` (N s^2/m^2, N s^2/m) is the body-
    axis table; surge/sway forces and roll/pitch moments are turned by ``yaw`` into earth axes.
    ``coef`` (6,) scratch.  Returns nothing.
    """
    ux = speed * math.cos(heading) - vx
    uy = speed * math.sin(heading) - vy
    u2 = ux * ux + uy * uy
    if u2 <= 0.0:
        return
    theta = math.atan2(uy, ux) - yaw
    table_at_into(theta, table_heading, table, coef)
    c = math.cos(yaw)
    s = math.sin(yaw)
    f = ramp_factor * u2
    out[0] += f * (c * coef[0] - s * coef[1])
    out[1] += f * (s * coef[0] + c * coef[1])
    out[2] += f * coef[2]
    out[3] += f * (c * coef[3] - s * coef[4])
    out[4] += f * (s * coef[3] + c * coef[4])
    out[5] += f * coef[5]


@njit(cache=True)
def quadratic_damping_into(dq, v, out):
    """out_i -= sum_j dq_ij v_j |v_j| (N, N m)."""
    for i in range(6):
        s = 0.0
        for j in range(6):
            s += dq[i, j] * v[j] * abs(v[j])
        out[i] -= s


@njit(cache=True)
def matvec_sub_into(a, x, out):
    """out -= a @ x for a (6, 6)."""
    for i in range(6):
        s = 0.0
        for j in range(6):
            s += a[i, j] * x[j]
        out[i] -= s


@njit(cache=True)
def turn_horizontal(f, cy, sy):
    """Turn the horizontal components (0, 1) and (3, 4) of a 6-vector in place by the angle
    whose cosine is ``cy`` and sine ``sy`` (yaw-following frame -> earth for +yaw)."""
    a = f[0]
    b = f[1]
    f[0] = cy * a - sy * b
    f[1] = sy * a + cy * b
    a = f[3]
    b = f[4]
    f[3] = cy * a - sy * b
    f[4] = sy * a + cy * b


def to_yaw_frame(v, yaw: float):
    """A pose rate (6,) as the velocity in the yaw-following frame (new array): the horizontal
    velocity turned by -yaw; heave, roll, pitch and yaw rates unchanged (the roll and pitch
    angles are measured about the yaw-following axes)."""
    out = np.array(v, float).reshape(6)
    c, s = math.cos(yaw), math.sin(yaw)
    out[0] = c * v[0] + s * v[1]
    out[1] = -s * v[0] + c * v[1]
    return out


def to_earth(f, yaw: float):
    """A yaw-frame generalized force (6,) in earth axes (new array): the horizontal force and
    the roll/pitch moment vector turned by +yaw."""
    out = np.array(f, float).reshape(6)
    turn_horizontal(out, math.cos(yaw), math.sin(yaw))
    return out

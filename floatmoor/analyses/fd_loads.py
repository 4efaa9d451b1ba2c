"""Small numerical helpers of the frequency-domain analysis: rotations about z, interpolation
on the frequency grid, relative-flow damping and the QTF interpolant (plain arrays in and out).
"""

from __future__ import annotations

import math

import numpy as np

from ..core.frames import yaw_rotation6 as rot6
from ..hydro.database import interpolate_heading

__all__ = ["rot6", "interp0", "coeff_slope", "relative_flow_damping", "qtf_function"]


def interp0(x_new, x, y):
    """Linear interpolation along axis 0 of y (any trailing shape), constant outside."""
    x = np.asarray(x, float)
    idx = np.clip(np.searchsorted(x, x_new) - 1, 0, x.size - 2)
    f = np.clip((x_new - x[idx]) / (x[idx + 1] - x[idx]), 0.0, 1.0)
    f = f.reshape((-1,) + (1,) * (np.ndim(y) - 1))
    return (1.0 - f) * y[idx] + f * y[idx + 1]


def coeff_slope(table, theta: float, h: float = 1e-4) -> np.ndarray:
    """dC/dtheta of a heading coefficient table by central differences (step ``h`` rad)."""
    return (table.at(theta + h) - table.at(theta - h)) / (2.0 * h)


def relative_flow_damping(table, speed: float, heading: float, yaw: float) -> np.ndarray:
    """-dF/dv (6 x 6, columns surge and sway) of F = C(theta_rel) |U e - v|^2 (body axes
    rotated to earth), at v = 0: B[:, j] = 2 U C e_j - U C'(theta) n_j with
    e = (cos, sin), n = (sin, -cos) of the heading of travel (earth)."""
    if speed <= 0.0:
        return np.zeros((6, 6))
    T = rot6(yaw)
    rel = heading - yaw
    C = T @ table.at(rel)
    dC = T @ coeff_slope(table, rel)
    e = np.array([math.cos(heading), math.sin(heading)])
    n = np.array([math.sin(heading), -math.cos(heading)])
    B = np.zeros((6, 6))
    B[:, :2] = 2.0 * speed * np.outer(C, e) - speed * np.outer(dC, n)
    return B


def qtf_function(db, heading_rel: float, T: np.ndarray):
    """Callable (w1, w2) -> (n, 6) complex QTF at the relative heading, earth axes; bilinear in
    (w1, w2), zero outside the QTF grid."""
    from scipy.interpolate import RegularGridInterpolator
    q = interpolate_heading(db, "difference_frequency_qtf", heading_rel, dim="qtf_wave_direction")
    w1 = np.asarray(db["qtf_omega"].values, float)
    w2 = np.asarray(db["qtf_omega_2"].values, float)
    q = np.nan_to_num(q) @ T.T
    re = RegularGridInterpolator((w1, w2), q.real, bounds_error=False, fill_value=0.0)
    im = RegularGridInterpolator((w1, w2), q.imag, bounds_error=False, fill_value=0.0)

    def f(a, b):
        pts = np.column_stack([a, b])
        return re(pts) + 1j * im(pts)
    return f

"""Frames and rotations.

Earth-fixed frame: x, y horizontal, z up, origin at the mean water line.  A body pose is the
6-vector ``[x, y, z, roll, pitch, yaw]`` of the body reference point and its orientation as
z-y'-x'' (yaw, then pitch, then roll) Euler angles.  The rotation matrix from body to earth is

    R = Rz(yaw) @ Ry(pitch) @ Rx(roll)

so a point ``r`` fixed in the body is at ``pose[:3] + R @ r`` in the earth frame.  Roll and pitch
may be large here; solvers that linearise them say so in their own documentation.

The functions are numba-compiled (``cache=True``) and write into preallocated outputs so they can
run inside time loops.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

__all__ = ["rotation_matrix", "rotation_matrix_into", "body_points_to_earth", "yaw_rotation6"]


@njit(cache=True)
def rotation_matrix_into(roll, pitch, yaw, out):
    """Write the body-to-earth rotation matrix into ``out`` (3x3)."""
    cr, sr = np.cos(roll), np.sin(roll)
    cp, sp = np.cos(pitch), np.sin(pitch)
    cy, sy = np.cos(yaw), np.sin(yaw)
    out[0, 0] = cy * cp
    out[0, 1] = cy * sp * sr - sy * cr
    out[0, 2] = cy * sp * cr + sy * sr
    out[1, 0] = sy * cp
    out[1, 1] = sy * sp * sr + cy * cr
    out[1, 2] = sy * sp * cr - cy * sr
    out[2, 0] = -sp
    out[2, 1] = cp * sr
    out[2, 2] = cp * cr


def rotation_matrix(roll: float, pitch: float, yaw: float) -> np.ndarray:
    """Body-to-earth rotation matrix ``Rz(yaw) @ Ry(pitch) @ Rx(roll)``."""
    out = np.empty((3, 3))
    rotation_matrix_into(float(roll), float(pitch), float(yaw), out)
    return out


@njit(cache=True)
def body_points_to_earth(pose, points_body, r, out):
    """Earth coordinates of body-fixed points.

    pose: (6,) body pose; points_body: (n, 3) in body axes about the reference point;
    r: (3, 3) work array, left holding the rotation matrix; out: (n, 3) earth coordinates.
    """
    rotation_matrix_into(pose[3], pose[4], pose[5], r)
    for i in range(points_body.shape[0]):
        for k in range(3):
            out[i, k] = pose[k] + r[k, 0] * points_body[i, 0] + r[k, 1] * points_body[i, 1] \
                + r[k, 2] * points_body[i, 2]


def yaw_rotation6(yaw: float) -> np.ndarray:
    """Block-diagonal rotation (6, 6) about z by ``yaw`` (rad) for force/moment (or
    translation/rotation) 6-vectors: body axes -> earth axes."""
    c, s = math.cos(yaw), math.sin(yaw)
    T = np.eye(6)
    for a, b in ((0, 1), (3, 4)):
        T[a, a], T[a, b], T[b, a], T[b, b] = c, -s, s, c
    return T

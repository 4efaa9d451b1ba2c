"""Rotation convention: R = Rz(yaw) Ry(pitch) Rx(roll), checked against elementary rotations."""

import numpy as np

from floatmoor.core.frames import body_points_to_earth, rotation_matrix


def rx(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[1, 0, 0], [0, c, -s], [0, s, c]])


def ry(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, 0, s], [0, 1, 0], [-s, 0, c]])


def rz(a):
    c, s = np.cos(a), np.sin(a)
    return np.array([[c, -s, 0], [s, c, 0], [0, 0, 1]])


def test_rotation_matches_elementary_product_and_is_orthonormal():
    r = rotation_matrix(0.1, -0.2, 2.5)
    np.testing.assert_allclose(r, rz(2.5) @ ry(-0.2) @ rx(0.1), atol=1e-14)
    np.testing.assert_allclose(r @ r.T, np.eye(3), atol=1e-14)
    assert np.isclose(np.linalg.det(r), 1.0)


def test_yaw_90_maps_x_to_y():
    pose = np.array([10.0, 0.0, 0.0, 0.0, 0.0, np.pi / 2])
    pts = np.array([[1.0, 0.0, -5.0]])
    out = np.empty((1, 3))
    body_points_to_earth(pose, pts, np.empty((3, 3)), out)
    np.testing.assert_allclose(out, [[10.0, 1.0, -5.0]], atol=1e-14)

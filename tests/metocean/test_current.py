"""Current profiles: hand values, limits and the numba kernels against numpy."""

import numpy as np
import pytest

from floatmoor.core.errors import SceneError
from floatmoor.metocean import (
    CurrentSpec,
    current_speed,
    current_velocity,
    piecewise_linear_speed_into,
    power_law_speed_into,
)

HEIDRUN = CurrentSpec(z=(0.0, -25.0, -50.0), speed=(0.94, 0.94, 0.94))


def test_heidrun_constant_to_50m_and_below():
    # Wang (2016) table 5.5: 0.94 m/s at 0, -25, -50 m; constant below the deepest level given
    z = np.array([5.0, 0.0, -10.0, -50.0, -51.0, -300.0])
    np.testing.assert_array_equal(current_speed(HEIDRUN, z, 320.0), 0.94)


def test_piecewise_linear_hand_values():
    spec = CurrentSpec(z=(-100.0, 0.0, -20.0), speed=(0.2, 1.0, 0.8))  # any order
    z = np.array([[3.0, 0.0, -10.0], [-20.0, -60.0, -150.0]])
    # -10: halfway between 1.0 (0 m) and 0.8 (-20 m) = 0.9; -60: halfway 0.8..0.2 = 0.5
    expected = np.array([[1.0, 1.0, 0.9], [0.8, 0.5, 0.2]])
    np.testing.assert_allclose(current_speed(spec, z, 200.0), expected, rtol=1e-14)
    # kernel against numpy interpolation on many points
    zz = np.linspace(-250.0, 10.0, 1001)
    out = np.empty_like(zz)
    piecewise_linear_speed_into(np.array([-100.0, -20.0, 0.0]), np.array([0.2, 0.8, 1.0]), zz, out)
    np.testing.assert_allclose(out, np.interp(zz, [-100.0, -20.0, 0.0], [0.2, 0.8, 1.0]),
                               rtol=1e-14)


def test_power_law():
    # DNV-RP-C205 eq. 4.3 form: v = v0 ((z + d)/d)^(1/7)
    spec = CurrentSpec(profile="power_law", speed=(1.2,))
    d = 100.0
    z = np.array([1.0, 0.0, -50.0, -99.0, -100.0, -120.0])
    v = current_speed(spec, z, d)
    np.testing.assert_allclose(v, [1.2, 1.2, 1.2 * 0.5 ** (1 / 7), 1.2 * 0.01 ** (1 / 7), 0.0, 0.0],
                               rtol=1e-14)
    out = np.empty_like(z)
    power_law_speed_into(1.2, 1 / 7, d, z, out)
    np.testing.assert_array_equal(out, v)


def test_velocity_direction():
    spec = CurrentSpec(z=(0.0,), speed=(1.0,), heading=np.pi / 2)
    v = current_velocity(spec, np.array([-1.0, -2.0]), 100.0)
    assert v.shape == (2, 3)
    np.testing.assert_allclose(v[:, 1], 1.0)
    np.testing.assert_allclose(v[:, [0, 2]], 0.0, atol=1e-15)


@pytest.mark.parametrize("spec,depth", [
    (CurrentSpec(z=(0.0, 10.0), speed=(1.0, 1.0)), 100.0),      # level above the surface
    (CurrentSpec(z=(0.0, -10.0), speed=(1.0,)), 100.0),         # lengths differ
    (CurrentSpec(z=(0.0, -10.0), speed=(1.0, -0.5)), 100.0),    # negative speed
    (CurrentSpec(z=(0.0, 0.0), speed=(1.0, 0.5)), 100.0),       # repeated level
    (CurrentSpec(profile="log", z=(0.0,), speed=(1.0,)), 100.0),  # unknown profile
    (HEIDRUN, -5.0),                                            # negative depth
    (CurrentSpec(profile="power_law", speed=(1.0,), exponent=0.0), 100.0),
])
def test_bad_current_raises(spec, depth):
    with pytest.raises(SceneError):
        current_speed(spec, np.array([-1.0]), depth)

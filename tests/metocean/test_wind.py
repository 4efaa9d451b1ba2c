"""Wind spectra and profiles against hand computations of the DNV-RP-C205 / API formulas."""

import math

import numpy as np
import pytest
from scipy import integrate

from floatmoor.core.errors import SceneError
from floatmoor.metocean import (
    WindSpec,
    api_wind_profile,
    api_wind_spectrum,
    npd_wind_profile,
    npd_wind_spectrum,
    wind_mean_speed,
    wind_spectrum,
)


def test_npd_spectrum_hand_computed_10m():
    # DNV-RP-C205 sec. 2.3.2 (NPD): S(f) = 320 (U0/10)^2 (z/10)^0.45 / (1 + ft^n)^(5/(3n)),
    # ft = 172 f (z/10)^(2/3) (U0/10)^-0.75, n = 0.468.  U0 = 36 m/s, z = 10 m, f = 0.01 Hz:
    #   (3.6)^-0.75 = exp(-0.75 * 1.2809338) = 0.382624
    #   ft = 172 * 0.01 * 0.382624 = 0.658113
    #   ft^0.468 = exp(0.468 * ln 0.658113) = exp(-0.195781) = 0.822191
    #   (1.822191)^(5/1.404) = exp(3.561254 * 0.600040) = 8.47318
    #   S = 320 * 12.96 / 8.47318 = 4147.2 / 8.47318 = 489.45 m^2/s
    assert float(npd_wind_spectrum(0.01, 36.0)) == pytest.approx(489.45, rel=2e-4)


def test_npd_spectrum_hand_computed_30m():
    # U0 = 20 m/s, z = 30 m, f = 0.05 Hz:
    #   ft = 172 * 0.05 * 3^(2/3) * 2^-0.75 = 8.6 * 2.080084 * 0.594604 = 10.6367
    #   ft^0.468 = exp(0.468 * 2.364311) = 3.02368;  (4.02368)^3.561254 = exp(4.957995) = 142.31
    #   numerator 320 * 2^2 * 3^0.45 = 1280 * 1.639470 = 2098.52;  S = 14.746 m^2/s
    assert float(npd_wind_spectrum(0.05, 20.0, z=30.0)) == pytest.approx(14.746, rel=2e-4)


def test_npd_spectrum_limits():
    # f -> 0: S(0) = 320 (U0/10)^2 (z/10)^0.45; high f: slope -5/3 (Kolmogorov)
    assert float(npd_wind_spectrum(0.0, 36.0)) == pytest.approx(320 * 3.6 ** 2, rel=1e-14)
    f = np.array([1e4, 2e4])  # asymptotic only: ft^0.468 >> 1 needs very high f
    s = npd_wind_spectrum(f, 36.0)
    assert math.log(s[1] / s[0]) / math.log(2.0) == pytest.approx(-5.0 / 3.0, abs=0.01)
    assert np.all(npd_wind_spectrum(np.array([0.1, 1.0]), 0.0) == 0.0)


def test_npd_profile_hand_computed():
    # U(T, z) = U0 (1 + C ln(z/10)) (1 - 0.41 I_U ln(T/3600)),
    # C = 0.0573 sqrt(1 + 0.148 U0), I_U = 0.06 (1 + 0.043 U0) (z/10)^-0.22.
    # U0 = 36, z = 50 m, T = 600 s:
    #   C = 0.0573 * sqrt(6.328) = 0.144141;  1 + C ln 5 = 1 + 0.144141 * 1.609438 = 1.231986
    #   I_U = 0.15288 * 5^-0.22 = 0.15288 * 0.701815 = 0.107293
    #   1 - 0.41 * 0.107293 * ln(1/6) = 1 + 0.078820 = 1.078820
    #   U = 36 * 1.231986 * 1.078820 = 47.847 m/s
    assert float(npd_wind_profile(50.0, 36.0, averaging_s=600.0)) == pytest.approx(47.847,
                                                                                    rel=1e-4)
    # 1-hour mean at 10 m is U0 by definition
    assert float(npd_wind_profile(10.0, 36.0)) == pytest.approx(36.0, rel=1e-15)
    # 1-hour mean at 100 m: 36 (1 + 0.144141 ln 10) = 36 * 1.331900 = 47.948 m/s
    assert float(npd_wind_profile(100.0, 36.0)) == pytest.approx(47.948, rel=1e-4)
    z = np.array([[5.0, 10.0], [20.0, 40.0]])
    u = npd_wind_profile(z, 30.0, averaging_s=60.0)
    assert u.shape == z.shape and np.all(np.diff(u.ravel()) > 0)


def test_api_spectrum_integrates_to_sigma_squared():
    # API RP 2A: int S df = sigma^2 = (I(z) U(z))^2; I(10 m) = 0.15 (10/20)^-0.125 = 0.16358
    u = float(api_wind_profile(10.0, 30.0))
    assert u == pytest.approx(30.0)
    sigma = 0.15 * 0.5 ** -0.125 * 30.0
    val, _ = integrate.quad(lambda f: float(api_wind_spectrum(f, u, 10.0)), 0, np.inf, limit=400)
    assert val == pytest.approx(sigma ** 2, rel=1e-6)
    # peak of f S(f) at f = fp / (1.5 * 2/3) = fp ... f S = sigma^2 x/(1+1.5x)^(5/3) is max at x=1
    fp = 0.025 * 30.0 / 10.0
    f = np.linspace(0.2, 5, 100001) * fp
    assert f[np.argmax(f * api_wind_spectrum(f, u, 10.0))] == pytest.approx(fp, rel=1e-3)
    # above zs = 20 m the exponent is -0.275
    s50 = float(api_wind_spectrum(0.0, 30.0, 50.0))
    fp50 = 0.025 * 30.0 / 50.0
    assert s50 == pytest.approx((0.15 * 2.5 ** -0.275 * 30.0) ** 2 / fp50, rel=1e-12)


def test_registry_and_mean_speed():
    f = np.array([0.0, 0.01, 0.1])
    np.testing.assert_array_equal(wind_spectrum(WindSpec(u10=36.0), f), npd_wind_spectrum(f, 36.0))
    np.testing.assert_array_equal(wind_spectrum(WindSpec(spectrum="constant", u10=36.0), f), 0.0)
    s = wind_spectrum(WindSpec(spectrum="api", u10=20.0, reference_height=30.0), f)
    np.testing.assert_allclose(s, api_wind_spectrum(f, 20.0 * 3.0 ** 0.125, 30.0))
    assert wind_mean_speed(WindSpec(u10=36.0)) == pytest.approx(36.0)
    assert wind_mean_speed(WindSpec(u10=36.0, reference_height=100.0)) == pytest.approx(47.948,
                                                                                         rel=1e-4)
    with pytest.raises(SceneError) as err:
        wind_spectrum(WindSpec(spectrum="kaimal", u10=10.0), f)
    assert err.value.key == "wind.spectrum" and "npd" in str(err.value)


@pytest.mark.parametrize("call", [
    lambda: npd_wind_spectrum(0.1, -3.0),
    lambda: npd_wind_spectrum(-0.1, 10.0),
    lambda: npd_wind_spectrum(0.1, 10.0, z=0.0),
    lambda: npd_wind_profile(10.0, 30.0, averaging_s=7200.0),
    lambda: npd_wind_profile(-5.0, 30.0),
])
def test_bad_wind_input(call):
    with pytest.raises(SceneError):
        call()

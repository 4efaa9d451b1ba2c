"""Irregular realisations: statistics against the target spectrum, seeds, non-repetition."""

import math

import numpy as np
import pytest
from scipy.signal import welch

from floatmoor.core.errors import SceneError
from floatmoor.metocean import (
    WaveSpec,
    WindSpec,
    cosine_sum_uniform_into,
    jonswap,
    npd_wind_spectrum,
    realise_waves,
    realise_wind,
)

HEIDRUN = WaveSpec(hs=16.0, tp=18.2)  # Wang (2016) sec. 5.2
DUR, DT = 10800.0, 0.1
N = int(DUR / DT)
SEEDS = (1, 2, 3, 4, 5)


@pytest.fixture(scope="module")
def heidrun_series():
    out = []
    for seed in SEEDS:
        r = realise_waves(HEIDRUN, duration=DUR, seed=seed, water_depth=320.0)
        out.append((r, r.elevation_series(N, DT)))
    return out


def test_variance_matches_m0(heidrun_series):
    # m0 = Hs^2/16 = 16 m^2; 3-hour sample variance averaged over 5 seeds within 3 %.
    var = np.mean([eta.var() for _, eta in heidrun_series])
    assert var == pytest.approx(16.0 ** 2 / 16.0, rel=0.03)
    for r, _ in heidrun_series:  # the discretised spectrum keeps >= 99.5 % of m0 (cut-offs)
        assert r.m0 == pytest.approx(16.0, rel=0.02)
        assert r.m0 < 16.0 * 1.02


def test_welch_estimate_matches_target_spectrum(heidrun_series):
    # Welch PSD (one-sided, per Hz) -> per rad/s: S(w) = S(f)/(2 pi).  Compared as band energies
    # in 0.1 rad/s bands over the energetic range, averaged over the 5 seeds.
    psd = []
    for _, eta in heidrun_series:
        f, p = welch(eta, fs=1.0 / DT, nperseg=4096)
        psd.append(p)
    w = 2.0 * np.pi * f
    s_est = np.mean(psd, axis=0) / (2.0 * np.pi)
    s_tgt = jonswap(w, 16.0, 18.2)
    dw = w[1] - w[0]
    checked = 0
    for lo in np.arange(0.2, 1.2, 0.1):
        band = (w >= lo) & (w < lo + 0.1)
        e_tgt = s_tgt[band].sum() * dw
        if e_tgt < 0.002 * 16.0:
            continue
        assert s_est[band].sum() * dw == pytest.approx(e_tgt, rel=0.08), lo
        checked += 1
    assert checked >= 8
    assert w[np.argmax(s_est)] == pytest.approx(2 * np.pi / 18.2, abs=2 * dw)


def test_same_seed_bit_identical_and_different_seeds_differ(heidrun_series):
    r1, eta1 = heidrun_series[0]
    again = realise_waves(HEIDRUN, duration=DUR, seed=SEEDS[0], water_depth=320.0)
    for name in ("omega", "amplitude", "phase", "direction", "k"):
        assert np.array_equal(getattr(again, name), getattr(r1, name))
    assert np.array_equal(again.elevation_series(N, DT), eta1)
    t = np.linspace(0.0, 500.0, 777)
    assert np.array_equal(again.elevation(t, 3.0, -2.0), r1.elevation(t, 3.0, -2.0))
    eta2 = heidrun_series[1][1]
    assert not np.array_equal(eta1, eta2)
    assert abs(np.corrcoef(eta1, eta2)[0, 1]) < 0.05


def test_fast_series_equals_direct_sum(heidrun_series):
    r, eta = heidrun_series[0]
    idx = np.r_[0:300, 50_000:50_300, N - 300:N]
    direct = r.elevation(idx * DT)
    np.testing.assert_allclose(eta[idx], direct, atol=1e-9)
    # and at another point, offset start time
    fast = r.elevation_series(1000, 0.25, t0=100.0, x=50.0, y=-20.0)
    np.testing.assert_allclose(fast, r.elevation(100.0 + 0.25 * np.arange(1000), 50.0, -20.0),
                               atol=1e-9)


def test_default_discretisation_cannot_repeat_within_duration(heidrun_series):
    r = heidrun_series[0][0]
    assert 2 * np.pi / r.domega >= DUR  # equal-bin repetition period is at least the duration


def test_random_frequencies_break_repetition():
    # Deliberately coarse bins (repeat period T = 2 pi / dw = 600 s): with centred frequencies
    # the series repeats exactly after T; with a random frequency inside each bin it does not.
    # bins of dw = 2 pi/600 s starting at lo = 24.5 dw: every bin centre is an integer multiple
    # of dw, so the centred discretisation is exactly periodic with period 600 s.
    spec = WaveSpec(hs=4.0, tp=9.0)
    period = 600.0
    dw = 2 * np.pi / period
    n = 150
    lo, hi = 24.5 * dw, 24.5 * dw + n * dw
    t = np.arange(0.0, 600.0, 0.5)
    fixed = realise_waves(spec, duration=1800.0, seed=3, n_frequencies=n, omega_min=lo,
                          omega_max=hi, random_frequencies=False)
    a, b = fixed.elevation(t), fixed.elevation(t + period)
    assert np.corrcoef(a, b)[0, 1] > 0.999  # the test would detect repetition
    rand = realise_waves(spec, duration=1800.0, seed=3, n_frequencies=n, omega_min=lo,
                         omega_max=hi)
    a, b = rand.elevation(t), rand.elevation(t + period)
    assert abs(np.corrcoef(a, b)[0, 1]) < 0.2


def test_random_amplitudes_unbiased():
    # Rayleigh amplitudes: E[a^2/2] = S dw per component -> mean realised m0 over seeds ~ m0.
    spec = WaveSpec(hs=3.0, tp=8.0, random_amplitudes=True)
    m0 = [realise_waves(spec, duration=10800.0, seed=s).m0 for s in range(20)]
    det = realise_waves(WaveSpec(hs=3.0, tp=8.0), duration=10800.0, seed=0)
    assert np.mean(m0) == pytest.approx(det.m0, rel=0.03)
    assert np.std(m0) > 0.01 * det.m0  # amplitudes really are random


def test_directional_spreading_realisation():
    spec = WaveSpec(hs=5.0, tp=10.0, heading=0.5, spreading="cos2s", spreading_s=6.0,
                    n_directions=9)
    r = realise_waves(spec, duration=3600.0, seed=7, water_depth=100.0)
    assert r.n_components == 9 * (r.n_components // 9)
    assert set(np.round(np.unique(r.direction), 12)) == set(np.round(
        0.5 + 2 * np.pi / 9 * (np.arange(9) - 4), 12))
    assert r.m0 == pytest.approx(25.0 / 16.0, rel=0.01)
    # mean direction of energy = heading (symmetric spreading)
    e = r.amplitude ** 2
    assert math.atan2((e * np.sin(r.direction)).sum(), (e * np.cos(r.direction)).sum()) \
        == pytest.approx(0.5, abs=1e-9)


def test_heading_sets_direction_of_travel():
    # A crest travelling along +y appears later at larger y: eta(t, y=L) = eta(t - L/c, y=0)
    # checked for a single component (n_frequencies=1, centred).
    spec = WaveSpec(hs=1.0, tp=10.0, heading=np.pi / 2, n_frequencies=1, omega_min=0.6,
                    omega_max=0.6 + 1e-9)
    r = realise_waves(spec, duration=100.0, seed=1, random_frequencies=False)
    c = r.omega[0] / r.k[0]
    t = np.linspace(0, 50, 11)
    np.testing.assert_allclose(r.elevation(t, 0.0, 30.0), r.elevation(t - 30.0 / c, 0.0, 0.0),
                               atol=1e-12)
    np.testing.assert_allclose(r.elevation(t, 30.0, 0.0), r.elevation(t, 0.0, 0.0), atol=1e-12)


def test_realisation_arrays_read_only_and_kernel_is_additive():
    r = realise_waves(WaveSpec(hs=2.0, tp=7.0), duration=600.0, seed=1)
    with pytest.raises(ValueError):
        r.amplitude[0] = 1.0
    out = np.ones(50)
    cosine_sum_uniform_into(r.omega, r.amplitude, r.phase, 0.0, 0.5, np.empty((4, r.omega.size)),
                            out)
    np.testing.assert_allclose(out - 1.0, r.elevation(0.5 * np.arange(50)), atol=1e-10)


def test_wave_realisation_kinematics_methods():
    r = realise_waves(WaveSpec(hs=3.0, tp=9.0), duration=600.0, seed=2, water_depth=50.0)
    pts = np.array([[0.0, 0.0, -5.0], [10.0, 3.0, -20.0]])
    k = r.kinematics([1.0, 2.0], pts)
    assert k["velocity"].shape == (2, 2, 3) and k["pressure"].shape == (2, 2)
    vel, acc = np.empty((2, 3)), np.empty((2, 3))
    p, eta, work = np.empty(2), np.empty(2), np.empty((3, r.n_components))
    r.kinematics_into(2.0, pts, work, vel, acc, p, eta)
    np.testing.assert_array_equal(vel, k["velocity"][1])
    np.testing.assert_array_equal(eta, k["eta"][1])
    np.testing.assert_allclose(eta, [r.elevation(2.0, 0.0, 0.0), r.elevation(2.0, 10.0, 3.0)],
                               atol=1e-12)


@pytest.mark.parametrize("kwargs", [
    {"duration": 0.0, "seed": 1}, {"duration": -5.0, "seed": 1}, {"duration": 100.0, "seed": -1},
    {"duration": 100.0, "seed": 1.5}, {"duration": 100.0, "seed": 1, "n_frequencies": 0},
    {"duration": 100.0, "seed": 1, "omega_min": 2.0, "omega_max": 1.0},
])
def test_bad_realisation_input(kwargs):
    with pytest.raises(SceneError):
        realise_waves(WaveSpec(hs=2.0, tp=7.0), **kwargs)


# --------------------------------------------------------------------------- wind

def test_wind_realisation_statistics():
    spec = WindSpec(u10=36.0)  # Wang (2016) table 5.3
    var, psd = [], []
    for seed in range(1, 5):
        r = realise_wind(spec, duration=DUR, seed=seed)
        assert 1.0 / r.df >= DUR * (1 - 1e-12)
        u = r.speed_series(N // 2, 2 * DT)  # 0.2 s: Nyquist 2.5 Hz > f_max = 0.74 Hz
        # standard error of a T-mean of a process with spectrum S(f): sqrt(S(0)/T) = 0.62 m/s
        # here (S(0) = 320 * 3.6^2 = 4147 m^2/s); allow 3 standard errors.
        assert u.mean() == pytest.approx(36.0, abs=3 * math.sqrt(4147.2 / DUR))
        var.append(u.var())
        f, p = welch(u - u.mean(), fs=0.5 / DT, nperseg=4096)
        psd.append(p)
    fr = np.linspace(0.0, r.f.max(), 200001)
    target = np.trapezoid(npd_wind_spectrum(fr, 36.0), fr)  # variance within the realised band
    assert np.mean(var) == pytest.approx(target, rel=0.05)
    p = np.mean(psd, axis=0)
    s = npd_wind_spectrum(f, 36.0)
    df = f[1] - f[0]
    for lo, hi in [(0.005, 0.02), (0.02, 0.05), (0.05, 0.15), (0.15, 0.5)]:
        band = (f >= lo) & (f < hi)
        assert p[band].sum() * df == pytest.approx(s[band].sum() * df, rel=0.1), (lo, hi)


def test_wind_seed_and_constant():
    spec = WindSpec(u10=20.0, spectrum="api")
    a = realise_wind(spec, duration=3600.0, seed=9)
    b = realise_wind(spec, duration=3600.0, seed=9)
    c = realise_wind(spec, duration=3600.0, seed=10)
    t = np.arange(0.0, 600.0, 0.5)
    assert np.array_equal(a.speed(t), b.speed(t))
    assert not np.array_equal(a.speed(t), c.speed(t))
    np.testing.assert_allclose(a.speed_series(t.size, 0.5), a.speed(t), atol=1e-9)
    const = realise_wind(WindSpec(u10=20.0, spectrum="constant"), duration=3600.0, seed=1)
    assert const.n_components == 0
    np.testing.assert_array_equal(const.speed(t), 20.0)
    with pytest.raises(SceneError):
        realise_wind(WindSpec(u10=-1.0), duration=100.0, seed=1)

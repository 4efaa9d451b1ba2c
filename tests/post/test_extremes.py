"""Extreme-value statistics against scipy, closed forms, hand computations and Monte Carlo."""

import math

import numpy as np
import pytest
from scipy import stats

from floatmoor.core.errors import FloatmoorWarning, SceneError
from floatmoor.post import extremes as ex
from floatmoor.post.extremes import gumbel_fit, n_cycles, rayleigh_max, weibull_fit

LOC, SCALE = 3000.0, 150.0          # a line maximum of about 3 MN, in kN


def sample(n, seed):
    return stats.gumbel_r.rvs(loc=LOC, scale=SCALE, size=n, random_state=np.random.default_rng(seed))


# -- Gumbel fits ---------------------------------------------------------------------------------

@pytest.mark.parametrize("seed", range(6))
def test_mle_equals_scipy_fit(seed):
    """Our vectorised Newton MLE against scipy.stats.gumbel_r.fit (independent implementation)."""
    x = sample(20, seed)
    f = gumbel_fit(x, "mle")
    loc, scale = stats.gumbel_r.fit(x)
    assert f.loc == pytest.approx(loc, rel=1e-7)
    assert f.scale == pytest.approx(scale, rel=1e-6)


def test_moments_fit_closed_form():
    # scale = s sqrt(6)/pi, loc = mean - gamma scale (s with ddof=1)
    x = np.array([2900.0, 3100.0, 3050.0, 2980.0, 3300.0, 3010.0, 2950.0, 3120.0, 3200.0, 3075.0])
    with pytest.warns(FloatmoorWarning):
        f = gumbel_fit(x[:5], "moments")        # fewer than 10 maxima warns
    f = gumbel_fit(x, "moments")
    s = math.sqrt(sum((v - x.mean()) ** 2 for v in x) / 9)
    scale = s * math.sqrt(6) / math.pi
    assert f.scale == pytest.approx(scale, rel=1e-12)
    assert f.loc == pytest.approx(x.mean() - 0.5772156649015329 * scale, rel=1e-12)


@pytest.mark.parametrize("method", ["mle", "moments"])
def test_parameters_recovered_within_three_standard_errors(method):
    for seed in range(10):
        f = gumbel_fit(sample(500, 100 + seed), method)
        assert abs(f.loc - LOC) < 3 * f.loc_se, (seed, f)
        assert abs(f.scale - SCALE) < 3 * f.scale_se, (seed, f)
        assert abs(f.p90 - (LOC + 2.2503673273 * SCALE)) < 3 * f.fractile_se(0.9)


@pytest.mark.parametrize("method", ["mle", "moments"])
def test_standard_errors_match_the_spread_of_repeated_fits(method):
    """The asymptotic standard errors against the Monte Carlo spread of 400 fits of n = 200."""
    rng = np.random.default_rng(5)
    locs, scales, p90s = [], [], []
    for _ in range(400):
        f = gumbel_fit(LOC + SCALE * rng.gumbel(size=200), method)
        locs.append(f.loc)
        scales.append(f.scale)
        p90s.append(f.p90)
    ref = gumbel_fit(LOC + SCALE * rng.gumbel(size=200), method)
    # ref's SEs use its own fitted scale; compare with the SE at the true scale
    k = SCALE / ref.scale
    assert np.std(locs) == pytest.approx(ref.loc_se * k, rel=0.12)
    assert np.std(scales) == pytest.approx(ref.scale_se * k, rel=0.12)
    assert np.std(p90s) == pytest.approx(ref.fractile_se(0.9) * k, rel=0.12)


def test_asymptotic_covariance_constants():
    # textbook values for the Gumbel MLE: 1.10867, 0.60793, 0.25702 (x scale^2 / n)
    np.testing.assert_allclose(ex._MLE_COV, [[1.10867, 0.25702], [0.25702, 0.60793]], atol=1e-5)
    # moments: Var(scale) = (kurtosis - 1)/4 * 6/pi^2 * pi^2/6 = 1.1 exactly
    assert ex._MOM_COV[1, 1] == pytest.approx(1.1)


def test_fractiles_closed_form_and_scipy():
    f = gumbel_fit(sample(20, 3))
    for p in (0.05, 0.5, 1 / math.e, 0.9, 0.99):
        closed = f.loc - f.scale * math.log(-math.log(p))
        assert f.fractile(p) == pytest.approx(closed, rel=1e-14)
        assert f.fractile(p) == pytest.approx(stats.gumbel_r.ppf(p, f.loc, f.scale), rel=1e-12)
    assert f.mpm == f.loc == pytest.approx(f.fractile(1 / math.e))
    assert f.p90 == pytest.approx(f.loc + 2.2503673273 * f.scale)
    np.testing.assert_allclose(f.fractile([0.5, 0.9]), [f.fractile(0.5), f.fractile(0.9)])
    assert f.cdf(f.p90) == pytest.approx(0.9)
    assert f.mean == pytest.approx(stats.gumbel_r.mean(f.loc, f.scale))
    with pytest.raises(SceneError):
        f.fractile(1.0)


def test_bootstrap_is_reproducible_and_brackets_the_estimate():
    f = gumbel_fit(sample(20, 11))
    a = f.bootstrap_ci(0.9, seed=4)
    assert a == f.bootstrap_ci(0.9, seed=4)
    assert a != f.bootstrap_ci(0.9, seed=5)
    assert a[0] < f.p90 < a[1]
    b = f.bootstrap_ci(0.9, seed=4, kind="nonparametric")
    assert b[0] < f.p90 < b[1]
    with pytest.raises(SceneError):
        f.bootstrap_ci(kind="jackknife")


def test_parametric_bootstrap_coverage():
    """Coverage of the nominal 90 % interval of the 90 % fractile, 200 samples of 20 maxima.

    The percentile bootstrap under-covers a little for n = 20 (we measured 0.86); the test
    accepts 0.80 - 0.96 (about 3 binomial standard errors of 0.021 around 0.88).
    """
    rng = np.random.default_rng(123)
    true = LOC + 2.2503673273 * SCALE
    hits = 0
    for i in range(200):
        f = gumbel_fit(LOC + SCALE * rng.gumbel(size=20))
        lo, hi = f.bootstrap_ci(0.9, n_boot=300, seed=i)
        hits += lo <= true <= hi
    assert 0.80 <= hits / 200 <= 0.96


def test_probability_plot_data_and_figure():
    f = gumbel_fit(sample(20, 2))
    d = f.probability_plot_data()
    assert np.all(np.diff(d["x"]) >= 0)
    i = np.arange(1, 21)
    np.testing.assert_allclose(d["p"], (i - 0.44) / 20.12)
    np.testing.assert_allclose(d["y"], -np.log(-np.log(d["p"])))
    np.testing.assert_allclose(d["line_x"], f.loc + f.scale * d["line_y"])
    w = f.probability_plot_data("weibull")
    np.testing.assert_allclose(w["p"], i / 21)
    matplotlib = pytest.importorskip("matplotlib")
    matplotlib.use("Agg")
    ax = f.plot(unit="kN")
    assert len(ax.lines) >= 3
    import matplotlib.pyplot as plt
    plt.close(ax.figure)


@pytest.mark.parametrize("bad", [[1.0, 2.0], [1.0, np.nan, 2.0, 3.0], [5.0] * 20])
def test_gumbel_fit_rejects_bad_samples(bad):
    with pytest.raises(SceneError):
        gumbel_fit(bad)
    with pytest.raises(SceneError, match="method"):
        gumbel_fit(sample(20, 0), "lmoments")


# -- Rayleigh maxima -----------------------------------------------------------------------------

def test_rayleigh_max_hand_computation():
    """sigma = 2, N = 1000.

    ln 1000 = 6.907755; sqrt(2 ln N) = sqrt(13.815511) = 3.716922
    mpm      = 2 * 3.716922                              = 7.433844
    expected = 2 * (3.716922 + 0.577216 / 3.716922)      = 2 * 3.872216 = 7.744432
    p = 0.9:   0.9^(1/1000) = exp(-0.105361/1000) = 1 - 1.053550e-4
               sqrt(-2 ln 1.053550e-4) = sqrt(18.316431) = 4.279761 -> 8.559521
    """
    assert rayleigh_max(2.0, 1000) == pytest.approx(7.433844, abs=2e-6)
    assert rayleigh_max(2.0, 1000, kind="expected") == pytest.approx(7.744432, abs=2e-6)
    assert rayleigh_max(2.0, 1000, kind="fractile", p=0.9) == pytest.approx(8.559521, abs=2e-6)
    np.testing.assert_allclose(rayleigh_max([1.0, 2.0], 1000), [3.716922, 7.433844], atol=2e-6)


def test_rayleigh_max_against_monte_carlo():
    """Largest of N = 1000 Rayleigh peaks (sigma = 1), 4000 realisations."""
    rng = np.random.default_rng(9)
    m = np.sqrt(-2.0 * np.log(rng.random((4000, 1000)))).max(axis=1)   # inverse-CDF sampling
    assert np.quantile(m, 0.9) == pytest.approx(rayleigh_max(1.0, 1000, "fractile", 0.9), rel=0.01)
    assert np.mean(m) == pytest.approx(rayleigh_max(1.0, 1000, "expected"), rel=0.01)
    hist, edges = np.histogram(m, bins=40)
    mode = 0.5 * (edges[np.argmax(hist)] + edges[np.argmax(hist) + 1])
    assert mode == pytest.approx(rayleigh_max(1.0, 1000), abs=0.08)


def test_n_cycles_and_significant_value():
    assert n_cycles(10800.0, 10.0) == pytest.approx(1080.0)         # 3 h of 10 s waves
    assert ex.significant_value(1.635) == pytest.approx(3.27)      # Wang (2016) eq. 2.42
    with pytest.raises(SceneError, match="tz"):
        n_cycles(10800.0, 0.0)
    with pytest.raises(SceneError, match="n"):
        rayleigh_max(1.0, 1.0)
    with pytest.raises(SceneError, match="kind"):
        rayleigh_max(1.0, 100, kind="median")


# -- Weibull fit to peaks ------------------------------------------------------------------------

def test_weibull_fit_recovers_rayleigh_peaks():
    rng = np.random.default_rng(21)
    sigma = 1.5
    peaks = sigma * np.sqrt(-2.0 * np.log(rng.random(4000)))       # Rayleigh = Weibull(k=2)
    f = weibull_fit(peaks)
    assert f.shape == pytest.approx(2.0, rel=0.04)
    assert f.scale == pytest.approx(sigma * math.sqrt(2.0), rel=0.02)
    # the Weibull MPM of N peaks with k=2, scale sigma*sqrt(2) is sigma*sqrt(2 ln N)
    exact = ex.WeibullFit(shape=2.0, loc=0.0, scale=sigma * math.sqrt(2.0), n=1)
    assert exact.mpm(1000) == pytest.approx(rayleigh_max(sigma, 1000))
    assert exact.expected_max(1000) == pytest.approx(rayleigh_max(sigma, 1000, "expected"))
    assert exact.max_fractile(1000, 0.9) == pytest.approx(rayleigh_max(sigma, 1000, "fractile"))
    assert f.mpm(1000) == pytest.approx(rayleigh_max(sigma, 1000), rel=0.03)
    f3 = weibull_fit(peaks + 0.5, loc=None)
    assert f3.loc == pytest.approx(0.5, abs=0.15)
    tail = weibull_fit(peaks, threshold=1.0)
    assert tail.n == int(np.sum(peaks > 1.0))
    with pytest.raises(SceneError, match="loc"):
        weibull_fit(peaks - 1.0)

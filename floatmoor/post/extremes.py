"""Extreme-value statistics: Gumbel fits to per-seed maxima, Weibull fits to peaks, Rayleigh maxima.

Gumbel (type I largest) distribution, ``F(x) = exp(-exp(-(x - loc) / scale))``, as
:data:`scipy.stats.gumbel_r`.  Wang (2016) section 5.4.4 fits the 3-hour
maxima of 20 seeds and takes the 90 % fractile as the characteristic value.

* fractile: ``x_p = loc - scale ln(-ln p)``; most probable maximum (mode) ``= loc``
  (the 1/e = 36.8 % fractile).
* maximum likelihood (``method="mle"``): the profile equation
  ``scale = mean(x) - sum(x w) / sum(w)``, ``w = exp(-x / scale)``, solved by Newton's method
  (monotonic in ``scale``), then ``loc = -scale ln(mean(exp(-x / scale)))``.  Vectorised so
  bootstrap refits are cheap; checked against :func:`scipy.stats.gumbel_r.fit` in the tests.
* method of moments (``method="moments"``): ``scale = s sqrt(6) / pi``,
  ``loc = mean - gamma scale`` (``gamma`` Euler's constant, ``s`` with ``ddof = 1``).
* standard errors are asymptotic (large-sample).  MLE: the inverse Fisher information,
  ``Var(loc) = (1 + 6 (1 - gamma)^2 / pi^2) scale^2 / n`` (= 1.1087 scale^2 / n),
  ``Var(scale) = 6 / pi^2 scale^2 / n`` (0.6079), ``Cov = 6 (1 - gamma) / pi^2 scale^2 / n``
  (0.2570).  Moments: delta method with the Gumbel skewness ``12 sqrt(6) zeta(3) / pi^3`` and
  excess kurtosis 12/5, giving 1.1678, 1.1000 and 0.0959.  For 20 seeds they are rough; the
  bootstrap interval is the better statement of uncertainty.

Rayleigh maxima (frequency domain, Wang (2016) eq. 2.43 and 2.48): for ``N`` Rayleigh peaks with
parameter ``sigma`` (the standard deviation of a narrow-band Gaussian process),
``P(peak > a) = exp(-a^2 / (2 sigma^2))`` and the largest of ``N`` has

* most probable value ``sigma sqrt(2 ln N)`` (asymptotic, Wang's (2016) formula),
* expected value ``sigma (sqrt(2 ln N) + gamma / sqrt(2 ln N))`` (asymptotic),
* fractile ``p``: ``sigma sqrt(-2 ln(1 - p^(1/N)))`` (exact for independent peaks).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

import numpy as np
from scipy import special, stats

from ..core.errors import ConvergenceError, FloatmoorWarning, argument_error

__all__ = [
    "EULER_GAMMA", "GumbelFit", "gumbel_fit", "gumbel_reduced_variate", "WeibullFit",
    "weibull_fit", "rayleigh_max", "significant_value", "n_cycles",
]

EULER_GAMMA = float(np.euler_gamma)
_SQ6PI = math.sqrt(6.0) / math.pi

# asymptotic covariance of (loc, scale) in units of scale^2 / n
_MLE_COV = np.array([[1.0 + 6.0 * (1.0 - EULER_GAMMA) ** 2 / math.pi ** 2,
                      6.0 * (1.0 - EULER_GAMMA) / math.pi ** 2],
                     [6.0 * (1.0 - EULER_GAMMA) / math.pi ** 2, 6.0 / math.pi ** 2]])


def _moments_cov() -> np.ndarray:
    # sample mean m, sample std s of a Gumbel with variance v = pi^2/6 scale^2 (scale = 1 here)
    v = math.pi ** 2 / 6.0
    skew = 12.0 * math.sqrt(6.0) * float(special.zeta(3.0)) / math.pi ** 3
    kurt = 3.0 + 12.0 / 5.0
    var_m = v
    var_s = v * (kurt - 1.0) / 4.0
    cov_ms = skew * v / 2.0            # mu3 / (2 sigma) = skew sigma^2 / 2
    # scale = c s, loc = m - gamma c s
    c = _SQ6PI
    var_b = c * c * var_s
    cov_mb = c * cov_ms
    var_l = var_m + EULER_GAMMA ** 2 * var_b - 2.0 * EULER_GAMMA * cov_mb
    cov_lb = cov_mb - EULER_GAMMA * var_b
    return np.array([[var_l, cov_lb], [cov_lb, var_b]])


_MOM_COV = _moments_cov()
_METHODS = ("mle", "moments")


def gumbel_reduced_variate(p):
    """Gumbel reduced variate ``y = -ln(-ln p)`` of a non-exceedance probability ``p``."""
    p = np.asarray(p, dtype=float)
    if np.any(~((p > 0) & (p < 1))):
        raise argument_error("p", "probabilities strictly between 0 and 1", p)
    return -np.log(-np.log(p))


def _fit_moments(x: np.ndarray):
    """Moments fit along the last axis (vectorised)."""
    scale = x.std(axis=-1, ddof=1) * _SQ6PI
    loc = x.mean(axis=-1) - EULER_GAMMA * scale
    return loc, scale


def _fit_mle(x: np.ndarray, *, tol: float = 1e-12, maxiter: int = 100):
    """Maximum-likelihood fit along the last axis (vectorised Newton on the profile equation)."""
    m = x.mean(axis=-1, keepdims=True)
    s = x.std(axis=-1, ddof=1, keepdims=True)
    z = (x - m) / s                         # location-scale equivariance: fit standardised data
    zmin = z.min(axis=-1, keepdims=True)
    zs = z - zmin                           # >= 0, so the weights exp(-zs / b) stay <= 1
    zbar = z.mean(axis=-1, keepdims=True)
    b = np.full(zmin.shape, _SQ6PI)         # moments estimate of the standardised scale
    for _ in range(maxiter):
        w = np.exp(-zs / b)
        sw = w.sum(axis=-1, keepdims=True)
        ew = (z * w).sum(axis=-1, keepdims=True) / sw
        var_w = (z * z * w).sum(axis=-1, keepdims=True) / sw - ew * ew
        g = b - zbar + ew
        dg = 1.0 + var_w / (b * b)
        step = g / dg
        b_new = b - step
        b_new = np.where(b_new <= 0, 0.5 * b, b_new)    # keep the scale positive
        done = np.abs(b_new - b) <= tol * b
        b = b_new
        if np.all(done):
            break
    else:
        raise ConvergenceError("Gumbel maximum-likelihood fit did not converge in "
                               f"{maxiter} Newton iterations", where="gumbel_fit",
                               remedy="check the maxima (outliers, identical values) or use "
                                      "method='moments'")
    w = np.exp(-zs / b)
    loc_z = zmin - b * np.log(w.mean(axis=-1, keepdims=True))
    loc = (m + s * loc_z)[..., 0]
    scale = (s * b)[..., 0]
    return loc, scale


def _validate_sample(maxima, key="maxima", min_n=3) -> np.ndarray:
    x = np.asarray(maxima, dtype=float)
    if x.ndim != 1:
        x = np.squeeze(x)
    if x.ndim != 1:
        raise argument_error(key, "a 1-D sample (one value per seed)", f"shape {x.shape}")
    if x.size < min_n:
        raise argument_error(key, f"at least {min_n} values", x.size)
    if not np.all(np.isfinite(x)):
        raise argument_error(key, "finite values", "NaN or inf in the sample")
    if np.ptp(x) <= 1e-12 * max(1.0, float(np.max(np.abs(x)))):
        raise argument_error(key,
                             "values that differ (a Gumbel fit needs spread)", "identical values")
    return x


@dataclass(frozen=True, eq=False)
class GumbelFit:
    """A fitted Gumbel distribution of maxima (frozen).

    Attributes
    ----------
    loc, scale : float
        Location (= most probable maximum) and scale, in the unit of the data.
    method : str
        ``"mle"`` or ``"moments"``.
    data : numpy.ndarray
        The fitted maxima (a copy).
    loc_se, scale_se : float
        Asymptotic standard errors of ``loc`` and ``scale``.
    """

    loc: float
    scale: float
    method: str
    data: np.ndarray = field(repr=False)
    loc_se: float
    scale_se: float
    _cov: np.ndarray = field(repr=False)

    @property
    def n(self) -> int:
        """Number of maxima fitted."""
        return int(self.data.size)

    @property
    def dist(self):
        """The frozen :data:`scipy.stats.gumbel_r` distribution."""
        return stats.gumbel_r(loc=self.loc, scale=self.scale)

    @property
    def mpm(self) -> float:
        """Most probable maximum (the mode, ``loc``)."""
        return self.loc

    @property
    def p90(self) -> float:
        """90 % fractile (Wang (2016), section 5.4.4)."""
        return float(self.fractile(0.9))

    @property
    def mean(self) -> float:
        """Expected maximum ``loc + gamma scale``."""
        return self.loc + EULER_GAMMA * self.scale

    def fractile(self, p):
        """Value not exceeded with probability ``p``: ``loc - scale ln(-ln p)``."""
        y = gumbel_reduced_variate(p)
        out = self.loc + self.scale * y
        return float(out) if np.ndim(out) == 0 else out

    def fractile_se(self, p):
        """Asymptotic standard error of :meth:`fractile` (delta method)."""
        y = gumbel_reduced_variate(p)
        c = self._cov
        var = c[0, 0] + 2.0 * y * c[0, 1] + y * y * c[1, 1]
        out = np.sqrt(var)
        return float(out) if np.ndim(out) == 0 else out

    def cdf(self, x):
        """Non-exceedance probability of ``x``."""
        return self.dist.cdf(x)

    def bootstrap_ci(self, p: float = 0.9, *, level: float = 0.90, n_boot: int = 2000,
                     seed: int = 0, kind: str = "parametric") -> tuple[float, float]:
        """Percentile bootstrap confidence interval of the fractile ``p``.

        Parameters
        ----------
        p : float
            Fractile of interest (0.9 by default; ``1/e`` gives the MPM).
        level : float
            Confidence level of the two-sided interval.
        n_boot : int
            Number of bootstrap resamples.
        seed : int
            Seed of the :func:`numpy.random.default_rng` generator (reproducible).
        kind : str
            ``"parametric"`` (resample from the fitted Gumbel, refit with the same method) or
            ``"nonparametric"`` (resample the data with replacement).

        Returns
        -------
        (low, high) : tuple of float
            Interval limits in the unit of the data.
        """
        if not (0 < level < 1):
            raise argument_error("level", "a confidence level between 0 and 1", level)
        if int(n_boot) != n_boot or n_boot < 50:
            raise argument_error("n_boot", "an integer >= 50", n_boot)
        y = gumbel_reduced_variate(p)
        rng = np.random.default_rng(seed)
        n = self.n
        if kind == "parametric":
            u = rng.random((int(n_boot), n))
            sample = self.loc - self.scale * np.log(-np.log(u))
        elif kind == "nonparametric":
            sample = self.data[rng.integers(0, n, size=(int(n_boot), n))]
        else:
            raise argument_error("kind", "'parametric' or 'nonparametric'", kind)
        spread = np.ptp(sample, axis=1) > 0
        sample = sample[spread]
        fit = _fit_mle if self.method == "mle" else _fit_moments
        loc, scale = fit(sample)
        q = loc + scale * y
        a = 0.5 * (1.0 - level)
        lo, hi = np.quantile(q, [a, 1.0 - a])
        return float(lo), float(hi)

    def probability_plot_data(self, plotting_position: str = "gringorten") -> dict:
        """Data of a Gumbel probability plot (sorted maxima against the reduced variate).

        Parameters
        ----------
        plotting_position : str
            ``"gringorten"`` ``(i - 0.44) / (n + 0.12)`` (suited to Gumbel) or ``"weibull"``
            ``i / (n + 1)``.

        Returns
        -------
        dict
            ``x`` sorted maxima, ``p`` plotting positions, ``y`` reduced variate
            ``-ln(-ln p)``, ``line_y``/``line_x`` the fitted straight line
            ``x = loc + scale y``, and ``p90``/``mpm`` markers.
        """
        x = np.sort(self.data)
        i = np.arange(1, x.size + 1)
        if plotting_position == "gringorten":
            pp = (i - 0.44) / (x.size + 0.12)
        elif plotting_position == "weibull":
            pp = i / (x.size + 1.0)
        else:
            raise argument_error("plotting_position",
                                 "'gringorten' or 'weibull'", plotting_position)
        y = -np.log(-np.log(pp))
        ly = np.linspace(min(y.min(), -1.0) - 0.3, max(y.max(), gumbel_reduced_variate(0.9)) + 0.3,
                         50)
        return {"x": x, "p": pp, "y": y, "line_y": ly, "line_x": self.loc + self.scale * ly,
                "mpm": self.mpm, "p90": self.p90}

    def plot(self, ax=None, *, label: str = "maxima", unit: str = ""):
        """Gumbel probability plot with matplotlib (optional dependency).

        Returns the matplotlib Axes; raises ImportError naming the ``plot`` extra when
        matplotlib is missing.
        """
        try:
            import matplotlib.pyplot as plt
        except ImportError as exc:  # pragma: no cover - matplotlib is installed in CI
            raise ImportError("Gumbel plots need matplotlib: pip install floatmoor[plot]") from exc
        d = self.probability_plot_data()
        if ax is None:
            _, ax = plt.subplots(figsize=(5.5, 4.0))
        ax.plot(d["x"], d["y"], "o", label=label)
        ax.plot(d["line_x"], d["line_y"], "-",
                label=f"Gumbel {self.method}: loc {self.loc:.4g}, scale {self.scale:.4g}")
        y90 = float(gumbel_reduced_variate(0.9))
        ax.axhline(y90, ls=":", color="grey")
        ax.plot([self.p90], [y90], "s", color="C3", label=f"90 % value {self.p90:.4g}")
        ax.set_xlabel(f"maximum [{unit}]" if unit else "maximum")
        ax.set_ylabel("reduced variate -ln(-ln F)")
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize="small")
        return ax


def gumbel_fit(maxima, method: str = "mle") -> GumbelFit:
    """Fit a Gumbel distribution to a sample of maxima (e.g. one 3-hour maximum per seed).

    Parameters
    ----------
    maxima : array_like
        1-D sample, at least 3 values (a warning below 10).
    method : str
        ``"mle"`` (maximum likelihood) or ``"moments"``.

    Returns
    -------
    GumbelFit
    """
    if method not in _METHODS:
        raise argument_error("method", "one of: " + ", ".join(_METHODS), method)
    x = _validate_sample(maxima)
    if x.size < 10:
        import warnings
        warnings.warn(f"Gumbel fit to only {x.size} maxima: the fractiles are very uncertain "
                      "(Wang (2016) uses 20 seeds)", FloatmoorWarning, stacklevel=2)
    if method == "mle":
        loc, scale = _fit_mle(x[None, :])
        cov_unit = _MLE_COV
    else:
        loc, scale = _fit_moments(x[None, :])
        cov_unit = _MOM_COV
    loc, scale = float(loc[0]), float(scale[0])
    cov = cov_unit * scale * scale / x.size
    return GumbelFit(loc=loc, scale=scale, method=method, data=x.copy(),
                     loc_se=float(math.sqrt(cov[0, 0])), scale_se=float(math.sqrt(cov[1, 1])),
                     _cov=cov)


@dataclass(frozen=True, eq=False)
class WeibullFit:
    """A Weibull distribution fitted to peaks (frozen).

    ``F(x) = 1 - exp(-((x - loc) / scale)^shape)`` for ``x > loc`` (:data:`scipy.stats.weibull_min`).
    With ``shape = 2``, ``loc = 0`` and ``scale = sigma sqrt(2)`` it is the Rayleigh distribution.
    """

    shape: float
    loc: float
    scale: float
    n: int

    @property
    def dist(self):
        """The frozen :data:`scipy.stats.weibull_min` distribution."""
        return stats.weibull_min(self.shape, loc=self.loc, scale=self.scale)

    def _check_n(self, n_peaks):
        if not (np.all(np.isfinite(n_peaks)) and np.all(np.asarray(n_peaks) > 1)):
            raise argument_error("n_peaks", "a number of peaks > 1", n_peaks)

    def mpm(self, n_peaks):
        """Most probable largest of ``n_peaks`` independent peaks (asymptotic):
        the value exceeded by one peak in ``n_peaks``, ``loc + scale (ln N)^(1/shape)``."""
        self._check_n(n_peaks)
        return self.loc + self.scale * np.log(n_peaks) ** (1.0 / self.shape)

    def expected_max(self, n_peaks):
        """Expected largest of ``n_peaks`` peaks (asymptotic Gumbel form):
        ``mpm + gamma scale (ln N)^(1/shape - 1) / shape``."""
        self._check_n(n_peaks)
        ln = np.log(n_peaks)
        return (self.loc + self.scale * ln ** (1.0 / self.shape)
                + EULER_GAMMA * self.scale * ln ** (1.0 / self.shape - 1.0) / self.shape)

    def max_fractile(self, n_peaks, p: float = 0.9):
        """Fractile ``p`` of the largest of ``n_peaks`` independent peaks: ``F^-1(p^(1/N))``."""
        self._check_n(n_peaks)
        gumbel_reduced_variate(p)  # validates p
        return self.dist.ppf(np.asarray(p, float) ** (1.0 / np.asarray(n_peaks, float)))


def weibull_fit(peaks, *, loc: float | None = 0.0, threshold: float | None = None) -> WeibullFit:
    """Maximum-likelihood Weibull fit to peaks (an alternative to the Gumbel fit of maxima).

    Parameters
    ----------
    peaks : array_like
        Peak values, e.g. amplitudes above the mean from :func:`~floatmoor.post.upcrossing_peaks`.
    loc : float or None
        Fixed location (2-parameter fit, default 0); ``None`` fits it too (3-parameter fit).
    threshold : float, optional
        Only peaks above this value are fitted (tail fit); ``loc`` must then be at most the
        threshold.

    Returns
    -------
    WeibullFit
    """
    x = _validate_sample(peaks, "peaks", min_n=10)
    if threshold is not None:
        x = x[x > threshold]
        if x.size < 10:
            raise argument_error("threshold", "a threshold leaving at least 10 peaks", threshold)
    if loc is not None:
        if np.any(x <= loc):
            raise argument_error("loc", "a location below every peak", loc)
        shape, floc, scale = stats.weibull_min.fit(x, floc=float(loc))
    else:
        shape, floc, scale = stats.weibull_min.fit(x)
    if not all(np.isfinite([shape, floc, scale])) or shape <= 0 or scale <= 0:
        raise ConvergenceError("Weibull fit failed", where="weibull_fit",
                               remedy="fix the location (loc=0) or use more peaks")
    return WeibullFit(shape=float(shape), loc=float(floc), scale=float(scale), n=int(x.size))


def rayleigh_max(sigma, n, kind: str = "mpm", p: float = 0.9):
    """Largest of ``n`` Rayleigh-distributed peaks of a narrow-band Gaussian process.

    Parameters
    ----------
    sigma : float or array_like
        Standard deviation of the process (unit of the response).
    n : float or array_like
        Number of peaks (cycles) in the duration, e.g. :func:`n_cycles`.
    kind : str
        ``"mpm"`` most probable maximum ``sigma sqrt(2 ln N)`` (Wang (2016) eq. 2.43 / 2.48);
        ``"expected"`` ``sigma (sqrt(2 ln N) + gamma / sqrt(2 ln N))``;
        ``"fractile"`` exact fractile ``p`` of the largest, ``sigma sqrt(-2 ln(1 - p^(1/N)))``.
    p : float
        Non-exceedance probability for ``kind="fractile"``.

    Returns
    -------
    float or numpy.ndarray
        Maximum above the mean, unit of ``sigma``.
    """
    s = np.asarray(sigma, dtype=float)
    nn = np.asarray(n, dtype=float)
    if np.any(~np.isfinite(s)) or np.any(s < 0):
        raise argument_error("sigma", "a standard deviation >= 0", sigma)
    if np.any(~np.isfinite(nn)) or np.any(nn <= 1):
        raise argument_error("n", "a number of peaks > 1", n)
    if kind == "mpm":
        out = s * np.sqrt(2.0 * np.log(nn))
    elif kind == "expected":
        r = np.sqrt(2.0 * np.log(nn))
        out = s * (r + EULER_GAMMA / r)
    elif kind == "fractile":
        gumbel_reduced_variate(p)  # validates p
        out = s * np.sqrt(-2.0 * np.log(-np.expm1(np.log(p) / nn)))
    else:
        raise argument_error("kind", "one of: mpm, expected, fractile", kind)
    return float(out) if out.ndim == 0 else out


def significant_value(sigma):
    """Significant value ``2 sigma`` (Wang (2016) eq. 2.42 / 2.47; mean of the highest third of
    Rayleigh peaks, exactly 2.0027 sigma, rounded to 2 sigma as MIMOSA and Wang (2016) do)."""
    s = np.asarray(sigma, dtype=float)
    if np.any(~np.isfinite(s)) or np.any(s < 0):
        raise argument_error("sigma", "a standard deviation >= 0", sigma)
    out = 2.0 * s
    return float(out) if out.ndim == 0 else out


def n_cycles(duration, tz):
    """Number of cycles ``duration / tz`` (e.g. 3 h = 10800 s over the mean up-crossing period).

    Parameters
    ----------
    duration : float
        Duration in s.
    tz : float or array_like
        Mean zero up-crossing period in s.
    """
    d = np.asarray(duration, dtype=float)
    t = np.asarray(tz, dtype=float)
    if np.any(~np.isfinite(d)) or np.any(d <= 0):
        raise argument_error("duration", "a duration > 0 in s", duration)
    if np.any(~np.isfinite(t)) or np.any(t <= 0):
        raise argument_error("tz", "a mean up-crossing period > 0 in s", tz)
    out = d / t
    return float(out) if out.ndim == 0 else out

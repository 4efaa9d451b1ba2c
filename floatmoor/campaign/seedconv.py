"""Seed convergence: a confidence interval of the characteristic tension from the seed maxima.

The characteristic tension is the 90 % fractile of the Gumbel distribution fitted (maximum
likelihood) to the n seed maxima (Wang (2016) section 5.4.4).  Its confidence interval here is
the **parametric bootstrap of the pivot** ``Z = (q_hat - q) / scale_hat``: the Gumbel is a
location-scale family and the maximum-likelihood estimates are equivariant, so the distribution
of Z does not depend on the unknown location and scale.  It is simulated once per n from the
standard Gumbel (``n_boot`` samples of n maxima, refitted), and the interval is
``[q_hat - z_hi scale_hat, q_hat - z_lo scale_hat]`` with z_lo, z_hi the (1 -/+ level)/2
quantiles of Z.  The coverage is therefore exact for Gumbel maxima, up to the Monte Carlo error
of the quantiles (unlike the asymptotic-variance interval of
:meth:`floatmoor.post.extremes.GumbelFit.fractile_se`, which under-covers at n = 20).

Flag: the interval is "wide" when its half-width exceeds ``tolerance`` (default 5 %) of the
characteristic tension; the seeds that would bring it within follow from the 1/sqrt(n) shrinking
of the half-width, ``n_needed = ceil(n (half_width / (tolerance q_hat))^2)``.
"""

from __future__ import annotations

import functools
import math

import numpy as np

__all__ = ["DEFAULT_TOLERANCE", "fractile_interval", "pivot_quantiles", "seeds_needed"]

DEFAULT_TOLERANCE = 0.05
METHOD = ("parametric bootstrap of the pivot (q_hat - q) / scale_hat of the Gumbel MLE "
          "(exact coverage for Gumbel maxima up to Monte Carlo error)")


@functools.lru_cache(maxsize=64)
def pivot_quantiles(n: int, p: float = 0.9, level: float = 0.90, n_boot: int = 4000,
                    seed: int = 12345) -> tuple[float, float]:
    """Quantiles (z_lo, z_hi) of Z = (q_hat - q) / scale_hat for n standard Gumbel maxima."""
    from ..post.extremes import _fit_mle, gumbel_reduced_variate
    rng = np.random.default_rng(seed)
    x = -np.log(-np.log(rng.random((n_boot, n))))
    loc, scale = _fit_mle(x)
    y = float(gumbel_reduced_variate(p))
    z = (loc + scale * y - y) / scale          # true q of the standard Gumbel is y
    a = 0.5 * (1.0 - level)
    lo, hi = np.quantile(z, [a, 1.0 - a])
    return float(lo), float(hi)


def fractile_interval(maxima, p: float = 0.9, level: float = 0.90) -> dict:
    """Estimate and confidence interval of the Gumbel fractile ``p`` of ``maxima``.

    Returns ``q`` (estimate), ``low``, ``high``, ``half_width`` (relative, (high - low) / 2 /
    q), ``loc``, ``scale``, ``n``."""
    from ..post.extremes import _fit_mle, gumbel_reduced_variate
    x = np.asarray(maxima, float)
    n = x.size
    loc, scale = _fit_mle(x[None, :])
    loc, scale = float(loc[0]), float(scale[0])
    q = loc + scale * float(gumbel_reduced_variate(p))
    z_lo, z_hi = pivot_quantiles(n, p, level)
    low, high = q - z_hi * scale, q - z_lo * scale
    return {"q": q, "low": low, "high": high, "half_width": 0.5 * (high - low) / abs(q),
            "loc": loc, "scale": scale, "n": n}


def seeds_needed(n: int, half_width: float, tolerance: float = DEFAULT_TOLERANCE) -> int:
    """Seeds that bring the relative half-width within ``tolerance`` (1/sqrt(n) scaling)."""
    if not half_width > tolerance:
        return n
    return math.ceil(n * (half_width / tolerance) ** 2)

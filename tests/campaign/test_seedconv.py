"""Seed-convergence interval of the Gumbel 90 % fractile: coverage on synthetic Gumbel maxima."""

import math

import numpy as np
import pytest

from floatmoor.campaign.seedconv import fractile_interval, seeds_needed


@pytest.mark.parametrize("n", [20, 8])
def test_interval_covers_true_fractile_at_nominal_rate(n):
    """Maxima drawn from a Gumbel with known loc and scale: the 90 % interval must contain the
    true 90 % fractile loc - scale ln(-ln 0.9) in 90 % of the repetitions.  With R = 1500
    repetitions the binomial standard error is sqrt(0.9 0.1 / R) = 0.0077; allowed: 3 standard
    errors plus 0.01 for the Monte Carlo error of the pivot quantiles (4000 samples)."""
    rng = np.random.default_rng(2024)
    loc, scale = 3.0e6, 2.0e5
    q = loc - scale * math.log(-math.log(0.9))
    R = 1500
    hit = 0
    for _ in range(R):
        x = loc - scale * np.log(-np.log(rng.random(n)))
        ci = fractile_interval(x)
        hit += ci["low"] <= q <= ci["high"]
    cover = hit / R
    assert abs(cover - 0.90) < 3 * math.sqrt(0.09 / R) + 0.01, cover


def test_seeds_needed_scales_with_inverse_square():
    assert seeds_needed(20, 0.10, 0.05) == 80
    assert seeds_needed(20, 0.04, 0.05) == 20

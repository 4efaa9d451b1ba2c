"""Maxima of the frequency-domain analysis: Rayleigh most probable maxima, the combination of
the low- and wave-frequency maxima, and the line-tension columns (Wang (2016) eq. 2.42-2.49,
2.60, figure 5.9)."""

from __future__ import annotations

import numpy as np

from ..core.errors import SceneError
from ..post.extremes import rayleigh_max

__all__ = ["rayleigh_maxima", "combine_maxima", "safety_factor", "tension_columns"]


def rayleigh_maxima(std, tz, duration):
    """Most probable maxima sigma sqrt(2 ln N), N = duration / Tz; 0 where sigma is 0.

    Returns (maxima, N).  SceneError when a response has N <= 1 (duration too short)."""
    std = np.asarray(std, float)
    tz = np.asarray(tz, float)
    n = np.where(np.isfinite(tz) & (tz > 0), duration / np.where(tz > 0, tz, 1.0), np.nan)
    out = np.zeros_like(std)
    ok = (std > 0) & np.isfinite(n)
    if np.any(ok & (n <= 1.0)):
        raise SceneError(None, "frequency_domain.duration",
                         "a duration longer than the response periods (N = duration/Tz > 1)",
                         duration, f"Tz up to {np.nanmax(tz[ok]):.1f} s")
    out[ok] = rayleigh_max(std[ok], n[ok])
    return out, n


def combine_maxima(mean, lf_sig, lf_max, wf_sig, wf_max):
    """Eq. 2.49: X_max = X_mean + max(X_LF,max + X_WF,sig, X_WF,max + X_LF,sig).

    Returns (maximum, minimum, branch) where minimum = X_mean - the same excursion and branch
    is 1 where the LF maximum governs, 2 where the WF maximum does (arrays broadcast)."""
    a = np.asarray(lf_max) + np.asarray(wf_sig)
    b = np.asarray(wf_max) + np.asarray(lf_sig)
    exc = np.maximum(a, b)
    return np.asarray(mean) + exc, np.asarray(mean) - exc, np.where(a >= b, 1, 2)


def safety_factor(mbs, max_tension):
    """Safety factor MBS / maximum tension (the last column of Wang (2016) figure 5.9)."""
    with np.errstate(divide="ignore", invalid="ignore"):
        return np.asarray(mbs, float) / np.asarray(max_tension, float)


def tension_columns(static, std_lf, tz_lf, std_wf, tz_wf, mbs, duration):
    """The line-tension columns of Wang (2016) figure 5.9 from the tension statistics (N, s).

    max LF / max WF: Rayleigh sigma sqrt(2 ln N), N = duration / Tz; max total: eq. 2.49,
    static + max(max LF + 2 std WF, max WF + 2 std LF); WF base = max total - max WF (eq. 2.60);
    safety factor = MBS / max total.  Returns a dict of arrays: ``max_lf``, ``max_wf``,
    ``wf_base``, ``max_total``, ``safety_factor``, ``branch`` (1: LF max governs).
    """
    max_lf, _ = rayleigh_maxima(std_lf, tz_lf, duration)
    max_wf, _ = rayleigh_maxima(std_wf, tz_wf, duration)
    max_total, _, branch = combine_maxima(static, 2.0 * np.asarray(std_lf), max_lf,
                                          2.0 * np.asarray(std_wf), max_wf)
    return {"max_lf": max_lf, "max_wf": max_wf, "wf_base": max_total - max_wf,
            "max_total": max_total, "safety_factor": safety_factor(mbs, max_total),
            "branch": branch}

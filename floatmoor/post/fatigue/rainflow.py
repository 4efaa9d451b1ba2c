"""Rainflow cycle counting (ASTM E1049-85, section 5.4.4) and fatigue damage of a history.

The counting keeps half cycles: ranges that contain the starting point are counted as half
cycles as the standard's procedure finds them, and the residue left at the end of the history
is counted as half cycles (step 6 of the procedure).

Kernels (numba, ``cache=True``, no allocation): :func:`reversals_kernel` writes the turning
points of a history into a buffer; :func:`rainflow_kernel` counts the cycles of the turning
points into preallocated range / mean / count arrays.  :func:`rainflow` is the Python wrapper.
"""

from __future__ import annotations

import numpy as np
from numba import njit

__all__ = [
    "damage_from_cycles",
    "damage_from_history",
    "rainflow",
    "rainflow_kernel",
    "reversals",
    "reversals_kernel",
]


@njit(cache=True)
def reversals_kernel(x, out):
    """Turning points of ``x`` (first and last samples included, plateaus collapsed) into
    ``out`` (length >= len(x)); returns their number."""
    n = x.shape[0]
    if n == 0:
        return 0
    out[0] = x[0]
    k = 1
    slope = 0.0  # sign of the current run (0: not yet known)
    last = x[0]
    for i in range(1, n):
        d = x[i] - last
        if d == 0.0:
            continue
        if slope == 0.0:
            slope = 1.0 if d > 0.0 else -1.0
        elif (d > 0.0) != (slope > 0.0):
            out[k] = last  # the previous sample was a turning point
            k += 1
            slope = -slope
        last = x[i]
    if slope != 0.0:  # the end of the last run
        out[k] = last
        k += 1
    return k


@njit(cache=True)
def rainflow_kernel(rev, n_rev, stack, out_range, out_mean, out_count):
    """ASTM E1049-85 rainflow counting of the turning points ``rev[:n_rev]``.

    ``stack`` (length >= n_rev) is scratch; ``out_range``, ``out_mean``, ``out_count`` (length
    >= n_rev) receive each counted range, its mean and its count (1.0 or 0.5).  Returns the
    number of entries written."""
    n_out = 0
    top = 0  # number of points on the stack; the starting point S is always stack[0]
    for i in range(n_rev):
        stack[top] = rev[i]
        top += 1
        while top >= 3:
            x_rng = abs(stack[top - 1] - stack[top - 2])
            y_rng = abs(stack[top - 2] - stack[top - 3])
            if x_rng < y_rng:
                break
            if top == 3:
                # range Y contains the starting point: half cycle, drop the starting point
                out_range[n_out] = y_rng
                out_mean[n_out] = 0.5 * (stack[top - 2] + stack[top - 3])
                out_count[n_out] = 0.5
                n_out += 1
                for j in range(top - 3, top - 1):
                    stack[j] = stack[j + 1]
                top -= 1
            else:
                out_range[n_out] = y_rng
                out_mean[n_out] = 0.5 * (stack[top - 2] + stack[top - 3])
                out_count[n_out] = 1.0
                n_out += 1
                stack[top - 3] = stack[top - 1]
                top -= 2
    # residue: half cycles
    for j in range(top - 1):
        out_range[n_out] = abs(stack[j + 1] - stack[j])
        out_mean[n_out] = 0.5 * (stack[j + 1] + stack[j])
        out_count[n_out] = 0.5
        n_out += 1
    return n_out


def reversals(x) -> np.ndarray:
    """Turning points of a history (first and last points included)."""
    x = np.ascontiguousarray(x, dtype=np.float64)
    out = np.empty(max(x.size, 1))
    k = reversals_kernel(x, out)
    return out[:k].copy()


def rainflow(x):
    """Rainflow cycles of the history ``x`` (ASTM E1049-85 four-point/three-point counting
    with the starting-point rule; half cycles kept).

    Returns ``(ranges, means, counts)``, arrays of equal length; counts are 1.0 (full cycle) or
    0.5 (half cycle)."""
    x = np.ascontiguousarray(x, dtype=np.float64)
    n = max(x.size, 1)
    rev = np.empty(n)
    k = reversals_kernel(x, rev)
    stack = np.empty(n)
    rng, mean, cnt = np.empty(n), np.empty(n), np.empty(n)
    m = rainflow_kernel(rev, k, stack, rng, mean, cnt)
    return rng[:m], mean[:m], cnt[:m]


def damage_from_cycles(ranges, counts, curve, rbs: float) -> float:
    """Palmgren-Miner damage of cycles (ranges in N) on a T-N curve with RBS (N)."""
    return curve.damage(ranges, counts, rbs)


def damage_from_history(x, curve, rbs: float) -> float:
    """Damage of a tension history ``x`` (N) on a T-N curve: rainflow, then Palmgren-Miner with
    the ranges over the reference breaking strength ``rbs`` (N)."""
    rng, _, cnt = rainflow(x)
    return curve.damage(rng, cnt, rbs)

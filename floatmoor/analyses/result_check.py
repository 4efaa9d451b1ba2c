"""Checks of a result file read back: whole, finite and physically plausible.

A result that exists on disk is trusted by a resume (skipped) and by a report (fitted): a file
cut short by a full disk or a killed copy, NaN written into it, or tensions with their sign
flipped must not pass for a finished result.  Every check raises a
:class:`~floatmoor.core.errors.SceneError` naming the file, the variable and what is wrong; the
caller recomputes the result (``floatmoor run``, a campaign resume) or refuses to use it
(``floatmoor report``).

Plausibility bounds, of results floatmoor itself would write:

* tensions (fairlead and anchor) are magnitudes: >= 0;
* no tension above :data:`TENSION_GUARD` x MBS (the time loop stops with a NumericalError
  beyond it, :func:`floatmoor.solvers.time_domain.integrate`; not checked where the MBS is
  unknown);
* statistics ordered: minimum <= mean <= maximum;
* offsets >= 0, the MBS > 0.
"""

from __future__ import annotations

import math

import numpy as np

from ..core.errors import SceneError

__all__ = ["TENSION_GUARD", "check_series_file", "check_statistics", "check_fd_values"]

TENSION_GUARD = 10.0
"""Largest tension a stored result may hold, as a multiple of the line's MBS (the time loop's
own guard: no run of floatmoor writes more)."""

SERIES = ("motion", "velocity", "line_tension", "anchor_tension", "wave_elevation")
"""Time series of a ``floatmoor run`` file that are checked."""

_SLACK = 1e-6
"""Tolerance (N) below zero accepted for a tension (round-off of a slack line)."""


def _fail(path, key, expected, found, hint=None):
    raise SceneError(path, key, expected, found, hint)


def _check_mbs(path, mbs: np.ndarray) -> None:
    """MBS per line: > 0 N, or NaN where it is unknown (``mbs: unknown``, e.g. an imported
    line type: the run is valid, the design checks refuse it themselves)."""
    bad = ~np.isnan(mbs) & ~(np.isfinite(mbs) & (mbs > 0))
    if bad.any():
        _fail(path, "mbs", "an MBS > 0 N per line (NaN where unknown)", mbs.tolist())


def _first_bad(a: np.ndarray, bad: np.ndarray, names=None) -> str:
    """Where the first bad value of ``a`` sits: ``line7 at index 1200`` (a 2-D (time, line)
    array) or ``index 3``."""
    idx = [int(i) for i in np.argwhere(bad)[0]]
    v = f"{float(a[tuple(idx)]):.6g}"
    if a.ndim == 2 and names is not None and idx[1] < len(names):
        return f"{v} ({names[idx[1]]}, time index {idx[0]})"
    return f"{v} (index {', '.join(str(i) for i in idx)})"


def _finite(path, name, a, names=None):
    bad = ~np.isfinite(a)
    if bad.any():
        _fail(path, name, "finite values", _first_bad(a, bad, names),
              f"{int(bad.sum())} value(s) NaN or infinite: the file is corrupted")


def _tensions(path, name, a, mbs=None, names=None):
    _finite(path, name, a, names)
    neg = a < -_SLACK
    if neg.any():
        _fail(path, name, "tensions >= 0 N (a tension is a magnitude)",
              _first_bad(a, neg, names), f"{int(neg.sum())} negative value(s): sign-flipped "
              "or corrupted")
    if mbs is not None:
        mbs = np.asarray(mbs, float)
        with np.errstate(invalid="ignore"):
            over = a > TENSION_GUARD * mbs
        if over.any():
            _fail(path, name, f"tensions below {TENSION_GUARD:g} x MBS (the time loop stops "
                  "beyond it)", _first_bad(a, over, names), "the file is corrupted")


def check_series_file(path, nc) -> None:
    """The time series of a ``floatmoor run`` result (an open ``netCDF4.Dataset``, or an
    ``xarray.Dataset``, ``nc`` of the file ``path``): every series whole (its last time step
    readable), finite, tensions >= 0 and below :data:`TENSION_GUARD` x MBS."""
    names = None
    if "line" in nc.variables:
        try:
            names = [str(x) for x in np.asarray(nc["line"][...]).ravel()]
        except Exception:  # noqa: BLE001 - the names only decorate the message
            names = None
    mbs = None
    if "mbs" in nc.variables:
        mbs = np.asarray(nc["mbs"][...], float)
        _check_mbs(path, mbs)
    if "motion" not in nc.variables:
        _fail(path, "motion", "a floatmoor time-domain result (variable motion)", "none")
    for name in SERIES:
        if name not in nc.variables:
            continue
        var = nc[name]
        if var.shape and var.shape[0] == 0:
            _fail(path, name, "a time series", "no time steps")
        a = np.asarray(var[...], float)
        if name in ("line_tension", "anchor_tension"):
            _tensions(path, name, a, mbs, names)
        else:
            _finite(path, name, a)


def check_statistics(path, values: dict, *, failed_lines=()) -> None:
    """The per-storm statistics of a campaign storm file (:data:`floatmoor.campaign.store.
    TD_TABLE_VARS` and the others present): finite, tensions >= 0 and below
    :data:`TENSION_GUARD` x MBS, minimum <= mean <= maximum, offset >= 0."""
    mbs = values.get("mbs")
    if mbs is not None:
        mbs = np.asarray(mbs, float)
        _check_mbs(path, mbs)
    for name in ("line_tension_max", "line_tension_mean", "line_tension_min",
                 "anchor_tension_max"):
        if name in values:
            _tensions(path, name, np.asarray(values[name], float), mbs)
    lo, mean, hi = (values.get(k) for k in ("line_tension_min", "line_tension_mean",
                                             "line_tension_max"))
    if mean is not None and hi is not None:
        tol = 1e-9 * np.maximum(np.abs(np.asarray(hi, float)), 1.0)
        bad = np.asarray(mean, float) > np.asarray(hi, float) + tol
        if lo is not None:
            bad |= np.asarray(lo, float) > np.asarray(mean, float) + tol
        if bad.any():
            j = int(np.argmax(bad))
            _fail(path, "line_tension_mean", "minimum <= mean <= maximum of each line",
                  f"line index {j}: min {_num(lo, j)}, mean {_num(mean, j)}, max {_num(hi, j)}",
                  "the file is corrupted")
    for name in ("offset_max", "offset_mean"):
        if name in values:
            v = np.asarray(values[name], float)
            _finite(path, name, v)
            if np.any(v < 0):
                _fail(path, name, "an offset >= 0 m", v.tolist())
    for name in ("motion_max", "motion_min", "motion_mean", "motion_std", "line_tension_std"):
        if name in values:
            _finite(path, name, np.asarray(values[name], float))


def _num(a, j):
    return "-" if a is None else f"{float(np.asarray(a, float)[j]):.6g}"


def check_fd_values(path, values: dict) -> None:
    """The frequency-domain table of a campaign case (``tension_static``, ``tension_max_total``,
    ``mbs`` ...): finite where the line is intact (NaN where it is failed), tensions >= 0,
    the motions finite."""
    mbs = values.get("mbs")
    if mbs is not None:
        _check_mbs(path, np.asarray(mbs, float))
    failed = np.asarray(values.get("line_failed", np.zeros(0)), bool)
    for name in ("tension_static", "tension_max_total"):
        if name not in values:
            continue
        a = np.asarray(values[name], float)
        live = a if failed.shape != a.shape else a[~failed]
        _tensions(path, name, live, None)
    for name in ("max_total", "min_total", "mean"):
        if name in values:
            v = np.asarray(values[name], float)
            if not np.all(np.isfinite(v)):
                _fail(path, name, "finite values", [x if math.isfinite(x) else "nan"
                                                    for x in v.ravel().tolist()][:6])

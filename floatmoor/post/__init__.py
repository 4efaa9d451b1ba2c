"""floatmoor.post: filtering, peaks, extreme statistics and design checks of results.

Layer ``post``: imports only from ``core`` (and numpy, scipy, xarray; matplotlib optionally).

* :mod:`.timeseries` -- window, LF/WF separation (zero-phase Butterworth, 1/30 Hz), channel
  statistics, peaks between up-crossings, per-seed maxima.
* :mod:`.extremes` -- Gumbel fits of maxima, Weibull fits of peaks, Rayleigh maxima.
* :mod:`.dnv_os_e301` -- ULS/ALS design equation with the DNV-OS-E301 (2008) partial factors.
* :mod:`.report` -- self-contained HTML / Markdown / CSV / netCDF report of a set of seeds
  (:func:`build_report`; plots need matplotlib), with ALS seeds and a frequency-domain result
  beside the time domain; the ``floatmoor report`` command (:mod:`floatmoor.commands.report`)
  reads the seeds of ``floatmoor run`` and calls it.
"""

from . import dnv_os_e301
from .extremes import (
    GumbelFit,
    WeibullFit,
    gumbel_fit,
    gumbel_reduced_variate,
    n_cycles,
    rayleigh_max,
    significant_value,
    weibull_fit,
)
from .report import build_report, detect_failed_lines, summarise, transient_of
from .timeseries import (
    DEFAULT_CUTOFF_HZ,
    Peaks,
    channel_statistics,
    lowpass,
    per_seed_statistics,
    seed_maxima,
    split_lf_wf,
    statistics,
    upcrossing_peaks,
    window,
)

__all__ = [
    "dnv_os_e301", "build_report", "summarise", "detect_failed_lines", "transient_of", "GumbelFit", "WeibullFit", "gumbel_fit", "gumbel_reduced_variate",
    "n_cycles", "rayleigh_max", "significant_value", "weibull_fit", "DEFAULT_CUTOFF_HZ", "Peaks",
    "channel_statistics", "lowpass", "per_seed_statistics", "seed_maxima", "split_lf_wf",
    "statistics", "upcrossing_peaks", "window",
]

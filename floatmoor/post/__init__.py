"""floatmoor.post: filtering, peaks, extreme statistics and design checks of results.

Layer ``post``: imports from ``core`` and ``mooring`` (and numpy, scipy, xarray; matplotlib
optionally).

* :mod:`.timeseries` -- window, LF/WF separation (zero-phase Butterworth, 1/30 Hz), channel
  statistics, peaks between up-crossings, per-seed maxima.
* :mod:`.extremes` -- Gumbel fits of maxima, Weibull fits of peaks, Rayleigh maxima.
* :mod:`.design_codes` -- design codes as data (``floatmoor/data/codes``: partial factors and
  rules of DNV-OS-E301 2008, API RP 2SK 2005, DNV-ST-0119 2021, each value with its source).
* :mod:`.dnv_os_e301` -- ULS/ALS design equation with the partial factors of a code (DNV-OS-E301
  (2008) by default).
* :mod:`.capacity` -- new and end-of-life (corroded) capacity of every segment.
* :mod:`.design_statistics`, :mod:`.design_checks` -- per-seed anchor, fibre-rope, offset and
  point statistics and their checks.
* :mod:`.verdict` -- one line per limit state and check, and the verdict over all.
* :mod:`.report` -- self-contained HTML / Markdown / CSV / netCDF report of a set of seeds
  (:func:`build_report`; plots need matplotlib) whose first screen is the verdict, with ALS
  seeds, a fatigue result and a frequency-domain result; the ``floatmoor report`` command
  (:mod:`floatmoor.commands.report`) reads the seeds of ``floatmoor run`` and calls it.
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

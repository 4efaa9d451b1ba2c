"""Fatigue limit state (FLS) of mooring lines: T-N curves, rainflow counting, spectral damage.

* :mod:`.tn_curves` -- DNV (2008) S-N curves of chain, API RP 2SK (2005) T-N curves, the range
  reference (RBS, or the nominal area of an S-N curve) with the corrosion
  allowance, the fatigue safety factor and design equation.
* :mod:`.rainflow` -- ASTM E1049-85 rainflow counting (numba) and the damage of a history.
* :mod:`.spectral` -- damage from a tension spectrum: narrow band, combined spectrum and dual
  narrow band (DNV 2008; Jiao & Moan 1990) and Dirlik (1985).
* :mod:`.locations` -- fatigue locations of a quasi-static mooring (fairlead, segment tops,
  touchdown), their tension spectra from a frequency-domain result, T-N curves, damage rates.
* :mod:`.longterm` -- metocean scatter files and the long-term (annual) damage, life and check.
"""

from .rainflow import damage_from_history, rainflow, reversals
from .tn_curves import (
    DNV_CURVES,
    TNCurve,
    curve_for,
    design_check,
    fatigue_safety_factor,
    reference_breaking_strength,
    tn_curve,
)

__all__ = [
                        "DNV_CURVES",
                        "TNCurve",
                        "curve_for",
                        "damage_from_history",
                        "design_check",
                        "fatigue_safety_factor",
                        "rainflow",
                        "reference_breaking_strength",
                        "reversals",
                        "tn_curve",
]

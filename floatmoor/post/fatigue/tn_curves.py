"""T-N curves of mooring line components and the DNV-OS-E301 fatigue design check.

T-N curve (DNV 2008, Ch.2 Sec.2 D, design equation and table of T-N constants)
------------------------------------------------------------------------------
``n_c(s) = a_D s^-m``: the number of cycles to failure at the tension range ``s`` (double
amplitude) divided by the reference breaking strength (RBS) of the component.  The constants
(DNV 2008 Ch.2 Sec.2 table D1; the same numbers as API RP 2SK (2005), whose rope curves
``log10 a_D = 3.20 - 2.79 L_m`` (six strand) and ``3.25 - 3.43 L_m`` (spiral strand) DNV
evaluates at the mean load ratio ``L_m = 0.3``):

=========================================  ======  =======
component                                    m       a_D
=========================================  ======  =======
common stud (studlink) chain                  3.0     1000
common studless chain                         3.0      316
connecting links (Baldt, Kenter)              3.0      178
six/multi-strand wire rope                    4.09     231
spiral-strand wire rope                       5.05     166
=========================================  ======  =======

DNV (2008) gives no T-N curve for fibre rope (DNV-OS-E303 defers to tests); the polyester curve
here is the one of API RP 2SM (2014) / API RP 2SK (2005): ``m = 5.2, a_D = 25000`` (tension
range over the rope's MBS).  Use it with care: polyester rope fatigue is rarely governing and
the curve is a design curve from yarn and rope tests, not from DNV.

Reference breaking strength and corrosion
-----------------------------------------
Chain and steel wire wear and corrode: the fatigue damage is computed on the diameter reduced by
half the corrosion/wear allowance accumulated over the design life (mean diameter over the life,
DNV 2008 Ch.2 Sec.2; the allowance rates of its table B1 for regular inspection: 0.4 mm/year in
the splash zone, 0.3 mm/year in the catenary, 0.4 mm/year on the bottom).  The RBS is the MBS
scaled by the area, ``RBS = MBS (d_red / d)^2``.  Fibre rope takes no corrosion allowance.

Design equation (DNV 2008 Ch.2 Sec.2 D)
--------------------------------------
``1 - gamma_F d_C >= 0`` with ``d_C`` the characteristic damage over the design life and the
fatigue safety factor ``gamma_F = 5`` if ``d_F <= 0.8`` and ``gamma_F = 5 + 3 (d_F - 0.8)/0.1``
above, ``d_F`` the ratio of the characteristic damage of the adjacent line to that of the most
exposed line (lines close together share the load history: a higher factor).

User curves: a line type of the library may name a curve (``tn_curve: chain_studlink``) or give
its own constants (``tn_a_d: 500.0, tn_m: 3.0``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace

from ...core.errors import SceneError

__all__ = [
    "CORROSION_RATES_MM_PER_YEAR",
    "DNV_CURVES",
    "TNCurve",
    "curve_for",
    "design_check",
    "fatigue_safety_factor",
    "reduced_diameter",
    "reference_breaking_strength",
    "tn_curve",
]


@dataclass(frozen=True, kw_only=True)
class TNCurve:
    """One T-N curve ``n = a_d s^-m`` with ``s`` the tension range over the RBS.

    ``corrodes``: the component takes the corrosion/wear allowance (steel)."""

    name: str
    a_d: float
    m: float
    corrodes: bool = True
    source: str = ""

    def cycles_to_failure(self, s):
        """``n_c(s) = a_D s^-m`` (``s`` tension range / RBS; array or scalar)."""
        return self.a_d * s ** (-self.m)

    def damage(self, ranges, counts, rbs: float):
        """Palmgren-Miner sum of ``counts`` cycles of tension ``ranges`` (N) with RBS (N)."""
        import numpy as np
        s = np.asarray(ranges, float) / rbs
        return float(np.sum(np.asarray(counts, float) * s ** self.m) / self.a_d)


_DNV = "DNV (2008) Ch.2 Sec.2 table D1"
DNV_CURVES: dict[str, TNCurve] = {
    "chain_studlink": TNCurve(name="chain_studlink", a_d=1000.0, m=3.0, source=_DNV),
    "chain_studless": TNCurve(name="chain_studless", a_d=316.0, m=3.0, source=_DNV),
    "connecting_link": TNCurve(name="connecting_link", a_d=178.0, m=3.0, source=_DNV),
    "wire_six_strand": TNCurve(name="wire_six_strand", a_d=231.0, m=4.09, source=_DNV),
    "wire_spiral_strand": TNCurve(name="wire_spiral_strand", a_d=166.0, m=5.05, source=_DNV),
    "polyester": TNCurve(name="polyester", a_d=25000.0, m=5.2, corrodes=False,
                         source="API RP 2SM (2014) polyester rope T-N curve (DNV 2008 gives "
                         "none for fibre rope)"),
}
"""The shipped T-N curves by name."""

CORROSION_RATES_MM_PER_YEAR = {"splash": 0.4, "catenary": 0.3, "bottom": 0.4}
"""Corrosion/wear allowance of chain, mm of diameter per year, with regular inspection
(DNV 2008 Ch.2 Sec.2 table B1)."""

_MATERIAL_DEFAULT = {"chain": "chain_studless", "wire": "wire_six_strand",
                     "polyester": "polyester"}


def tn_curve(name: str) -> TNCurve:
    """The shipped curve ``name`` (KeyError listing the names otherwise)."""
    if name not in DNV_CURVES:
        raise KeyError(f"unknown T-N curve {name!r}; curves: {', '.join(DNV_CURVES)}")
    return DNV_CURVES[name]


def curve_for(line_type, *, file=None) -> TNCurve:
    """The T-N curve of a :class:`~floatmoor.mooring.line_types.LineType`.

    In order: the type's own constants (``tn_a_d``, ``tn_m``), its named curve (``tn_curve``),
    the family in its name (``chain_studlink_R4`` -> studlink chain), its material (chain ->
    studless chain, the lower curve; wire -> six strand; polyester -> polyester)."""
    a_d = getattr(line_type, "tn_a_d", None)
    m = getattr(line_type, "tn_m", None)
    named = getattr(line_type, "tn_curve", "") or ""
    if a_d is not None and m is not None:
        base = DNV_CURVES.get(named) or DNV_CURVES.get(_MATERIAL_DEFAULT.get(
            line_type.material, ""))
        corrodes = base.corrodes if base is not None else line_type.material in ("chain", "wire")
        return TNCurve(name=named or f"{line_type.name} (user)", a_d=float(a_d), m=float(m),
                       corrodes=corrodes, source=f"user-defined (line type {line_type.name})")
    if named:
        if named not in DNV_CURVES:
            raise SceneError(file, f"line_types.{line_type.name}.tn_curve",
                             "a T-N curve name, one of: " + ", ".join(DNV_CURVES), named)
        return DNV_CURVES[named]
    for key in ("chain_studlink", "chain_studless", "wire_six_strand", "wire_spiral_strand",
                "polyester"):
        if line_type.name.startswith(key):
            return DNV_CURVES[key]
    default = _MATERIAL_DEFAULT.get(line_type.material)
    if default is None:
        raise SceneError(file, f"line_types.{line_type.name}",
                         "a T-N curve for the fatigue analysis: tn_curve (one of "
                         + ", ".join(DNV_CURVES) + ") or tn_a_d and tn_m",
                         f"material {line_type.material!r} without a curve")
    return DNV_CURVES[default]


def reduced_diameter(diameter: float, rate_mm_per_year: float, design_life_years: float) -> float:
    """Nominal diameter (m) less half the allowance over the design life (the mean diameter
    over the life): ``d - 0.5 rate life``."""
    d = diameter - 0.5 * rate_mm_per_year * 1e-3 * design_life_years
    if d <= 0.0:
        raise ValueError(f"the corrosion allowance ({rate_mm_per_year} mm/year over "
                         f"{design_life_years} years) consumes the diameter {diameter} m")
    return d


def reference_breaking_strength(mbs: float, diameter: float, curve: TNCurve, *,
                                rate_mm_per_year: float, design_life_years: float) -> float:
    """RBS (N) for the fatigue analysis: MBS scaled by the area of the corroded diameter."""
    if not curve.corrodes or rate_mm_per_year <= 0.0:
        return float(mbs)
    d = reduced_diameter(diameter, rate_mm_per_year, design_life_years)
    return float(mbs) * (d / diameter) ** 2


def fatigue_safety_factor(d_f: float = 0.0) -> float:
    """DNV (2008) fatigue safety factor: 5 for ``d_F <= 0.8``, ``5 + 3 (d_F - 0.8)/0.1`` above;
    ``d_F`` = damage of the adjacent line / damage of the most exposed line."""
    if not math.isfinite(d_f) or d_f <= 0.8:
        return 5.0
    return 5.0 + 3.0 * (min(d_f, 1.0) - 0.8) / 0.1


def design_check(damage_per_year: float, design_life_years: float, gamma_f: float) -> dict:
    """DNV (2008) fatigue design equation ``1 - gamma_F d_C >= 0`` with ``d_C`` the damage over
    the design life.  Returns ``d_c``, ``utilisation`` (``gamma_F d_C``), ``life`` (years,
    ``1/damage_per_year``), ``design_life_allowed`` (``life / gamma_F``), ``ok``."""
    d_c = damage_per_year * design_life_years
    life = math.inf if damage_per_year <= 0.0 else 1.0 / damage_per_year
    return {"d_c": d_c, "gamma_f": gamma_f, "utilisation": gamma_f * d_c, "life": life,
            "allowed_life": life / gamma_f, "ok": bool(1.0 - gamma_f * d_c >= 0.0)}


def with_constants(curve: TNCurve, *, a_d: float | None = None, m: float | None = None) -> TNCurve:
    """A copy of ``curve`` with other constants (user override)."""
    return replace(curve, a_d=curve.a_d if a_d is None else a_d, m=curve.m if m is None else m,
                   source="user override of " + curve.name)

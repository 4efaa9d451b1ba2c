"""T-N and S-N curves of mooring line components and the DNV-OS-E301 fatigue design check.

Fatigue curves: ``n_c(s) = a_D s^-m``, the number of cycles to failure at the range ``s``
(double amplitude).  Two normalisations of ``s`` (:attr:`TNCurve.basis`):

* ``"stress"`` -- the S-N curves of DNV-OS-E301 (Ch.2 Sec.2, fatigue limit state): ``s`` the
  nominal stress range in MPa, the tension range over the nominal steel area; for chain the two
  legs of a link, ``A = 2 pi d^2 / 4`` (``area_factor`` 2) on the diameter reduced by the
  corrosion allowance.  Constants: stud (studlink) chain ``a_D = 1.2e11``, studless chain
  ``a_D = 6.0e10``, both ``m = 3.0`` (DNV (2008); constants and area checked against two
  reproductions of the standard, see docs/REFERENCES.md "DNV-OS-E301 fatigue curves": the
  edition's own text was not available (unverified)).
* ``"rbs"`` -- the T-N curves of API RP 2SK (2005): ``s`` the tension range over the
  reference breaking strength (RBS, the MBS on the corroded area).  Shipped with names of their
  own: studlink chain ``api_chain_studlink`` (m 3.0, a_D 1000), studless chain
  ``api_chain_studless`` (3.0, 316), Baldt/Kenter ``connecting_link`` (3.0, 178), and the
  wire ropes, whose API curves ``log10 a_D = 3.20 - 2.79 L_m`` (six strand) and ``3.25 - 3.43
  L_m`` (spiral strand) are taken at the mean load ratio ``L_m = 0.3``: ``wire_six_strand``
  (4.09, 231) and ``wire_spiral_strand`` (5.05, 166).  DNV-OS-E301's own wire rope S-N curves
  are not shipped (their constants could not be checked here).  These constants were, before,
  labelled "DNV (2008) table D1": they are API RP 2SK's, not DNV's.

=========================  =======  =========  ======  ==========================
name                       basis      a_D        m      source
=========================  =======  =========  ======  ==========================
chain_studlink             stress   1.2e11     3.0     DNV (2008)
chain_studless             stress   6.0e10     3.0     DNV (2008)
api_chain_studlink         rbs      1000       3.0     API RP 2SK (2005)
api_chain_studless         rbs      316        3.0     API RP 2SK (2005)
connecting_link            rbs      178        3.0     API RP 2SK (2005)
wire_six_strand            rbs      231        4.09    API RP 2SK (2005), L_m 0.3
wire_spiral_strand         rbs      166        5.05    API RP 2SK (2005), L_m 0.3
polyester                  rbs      25000      5.2     API RP 2SM
=========================  =======  =========  ======  ==========================

DNV (2008) gives no curve for fibre rope (DNV-OS-E303 defers to tests); the polyester curve
here is the one of API RP 2SM / API RP 2SK (2005): ``m = 5.2, a_D = 25000`` (tension range
over the rope's MBS).  Use it with care: polyester rope fatigue is rarely governing and the
curve is a design curve from yarn and rope tests, not from DNV.

Reference breaking strength and corrosion
-----------------------------------------
Chain and steel wire wear and corrode: the fatigue damage is computed on the diameter reduced by
half the corrosion/wear allowance accumulated over the design life (mean diameter over the life,
DNV 2008 Ch.2 Sec.2; the allowance rates of its table B1 for regular inspection: 0.4 mm/year in
the splash zone, 0.3 mm/year in the catenary, 0.4 mm/year on the bottom).  The RBS is the MBS
scaled by the area, ``RBS = MBS (d_red / d)^2``; an S-N curve takes the area of ``d_red``.  Fibre rope takes no corrosion allowance.

Design equation (DNV 2008 Ch.2 Sec.2 D)
--------------------------------------
``1 - gamma_F d_C >= 0`` with ``d_C`` the characteristic damage over the design life and the
fatigue safety factor of the design code (:mod:`floatmoor.post.design_codes`; its file says
where the value comes from).  DNV-OS-E301 (2008): ``gamma_F = 5`` if ``d_F <= 0.8`` and
``gamma_F = 5 + 3 (d_F - 0.8)/0.2`` above, ``d_F`` the ratio of the characteristic damage of
the adjacent line to that of the most exposed line (lines close together share the load
history: a higher factor), so that ``gamma_F`` runs from 5 to 8 -- the range the standard is
usually quoted with; the text itself could not be read here (the code file marks the value
unverified).  Before, floatmoor divided by 0.1 instead of 0.2: gamma_F reached 8 at d_F = 0.9
and 11 at d_F = 1.

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
    """One fatigue curve ``n = a_d s^-m``.

    ``basis``: ``"rbs"``, ``s`` the tension range over the RBS (T-N curve); ``"stress"``,
    ``s`` the nominal stress range in MPa, the tension range over ``area_factor pi d^2 / 4``
    (mm^2, the corroded diameter; S-N curve).  In both cases the tension range is divided by
    the curve's *range reference* (:func:`reference_breaking_strength`: the RBS in N, or the
    area in mm^2, i.e. N per MPa).  ``corrodes``: the component takes the corrosion/wear
    allowance (steel)."""

    name: str
    a_d: float
    m: float
    corrodes: bool = True
    source: str = ""
    basis: str = "rbs"
    area_factor: float = 1.0

    def __post_init__(self):
        if self.basis not in ("rbs", "stress"):
            raise ValueError(f"basis must be 'rbs' or 'stress', got {self.basis!r}")

    def cycles_to_failure(self, s):
        """``n_c(s) = a_D s^-m`` (``s`` tension range / RBS, or stress range in MPa)."""
        return self.a_d * s ** (-self.m)

    def damage(self, ranges, counts, rbs: float):
        """Palmgren-Miner sum of ``counts`` cycles of tension ``ranges`` (N) with the range
        reference ``rbs`` (RBS in N, or the nominal area in mm^2 for a stress curve)."""
        import numpy as np
        s = np.asarray(ranges, float) / rbs
        return float(np.sum(np.asarray(counts, float) * s ** self.m) / self.a_d)


_DNV = ("DNV (2008) Ch.2 Sec.2, S-N curve of the fatigue limit state (stress range in MPa on "
        "the nominal area of the two legs of a link)")
_API = "API RP 2SK (2005) T-N curve (tension range over the RBS)"
DNV_CURVES: dict[str, TNCurve] = {
    "chain_studlink": TNCurve(name="chain_studlink", a_d=1.2e11, m=3.0, basis="stress",
                              area_factor=2.0, source=_DNV),
    "chain_studless": TNCurve(name="chain_studless", a_d=6.0e10, m=3.0, basis="stress",
                              area_factor=2.0, source=_DNV),
    "api_chain_studlink": TNCurve(name="api_chain_studlink", a_d=1000.0, m=3.0, source=_API),
    "api_chain_studless": TNCurve(name="api_chain_studless", a_d=316.0, m=3.0, source=_API),
    "connecting_link": TNCurve(name="connecting_link", a_d=178.0, m=3.0, source=_API),
    "wire_six_strand": TNCurve(name="wire_six_strand", a_d=231.0, m=4.09,
                               source=_API + ", mean load ratio 0.3"),
    "wire_spiral_strand": TNCurve(name="wire_spiral_strand", a_d=166.0, m=5.05,
                                  source=_API + ", mean load ratio 0.3"),
    "polyester": TNCurve(name="polyester", a_d=25000.0, m=5.2, corrodes=False,
                         source="API RP 2SM polyester rope T-N curve (DNV 2008 gives none for "
                         "fibre rope)"),
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
    """The range reference of ``curve`` (:class:`TNCurve`): for a T-N curve the RBS (N), the
    MBS scaled by the area of the corroded diameter; for an S-N curve in MPa the nominal area
    ``area_factor pi d^2 / 4`` in mm^2 (N per MPa) on the corroded diameter (the MBS is not
    used and may be unknown)."""
    corroded = curve.corrodes and rate_mm_per_year > 0.0
    d = reduced_diameter(diameter, rate_mm_per_year, design_life_years) if corroded else diameter
    if curve.basis == "stress":
        return curve.area_factor * math.pi * (d * 1e3) ** 2 / 4.0
    if not corroded:
        return float(mbs)
    return float(mbs) * (d / diameter) ** 2


def fatigue_safety_factor(d_f: float = 0.0, code=None) -> float:
    """The fatigue safety factor ``gamma_F`` of the design code (default DNV-OS-E301 (2008): 5
    for ``d_F <= 0.8``, ``5 + 3 (d_F - 0.8)/0.2`` above, 8 at ``d_F = 1``; ``d_F`` = damage of
    the adjacent line / damage of the most exposed line; :meth:`floatmoor.post.design_codes.
    DesignCode.fatigue_factor`)."""
    from ..design_codes import DEFAULT_CODE, load_code
    return load_code(DEFAULT_CODE if code is None else code).fatigue_factor(d_f)


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

"""Mooring line types: chain, wire rope, polyester and user-defined types.

A :class:`LineType` holds the properties the quasi-static and dynamic line models need, in SI
units: mass per length, displaced volume per length (so that the submerged weight follows from
the water density), axial stiffness (static and, for fibre ropes, dynamic), minimum breaking
strength (MBS) and hydrodynamic coefficients.

Formula families (nominal diameter ``d``; ``d_mm`` in mm, ``d_m`` in m)
----------------------------------------------------------------------
``chain_studless`` / ``chain_studlink`` (grades R3, R3S, R4, R4S, R5):

* MBS [kN] = c_grade * d_mm^2 * (44 - 0.08 d_mm), with c_grade = 0.0223 (R3), 0.0249 (R3S),
  0.0274 (R4), 0.0304 (R4S), 0.0320 (R5).  Source: DNV-OS-E302 "Offshore mooring chain",
  Ch. 2 Sec. 2 (breaking test load formulas for offshore chain grades), the same formula for
  studless and studlink chain; reproduced in the Vryhof Anchor Manual (2010), chain tables.
* mass [kg/m] = 0.0199 d_mm^2 (studless), 0.0219 d_mm^2 (studlink).  Source: Vryhof Anchor
  Manual (2010), chain data tables (catalogue fit).
* EA [kN] = 0.854e8 d_m^2 (studless), 1.01e8 d_m^2 (studlink).  Source: Vryhof Anchor Manual
  (2010), elasticity of R3/R4 chain (catalogue-style fit; EA of chain is not a guaranteed
  property -- use the manufacturer's value for design).
* displaced volume = mass / 7850 kg/m^3 (solid steel; Archimedes).  Equivalent to a
  volumetric diameter of about 1.8 d.

``wire_six_strand`` (six-strand IWRC) and ``wire_spiral_strand`` (sheathed spiral strand):
typical catalogue fits, approximate (e.g. Vryhof Anchor Manual 2010 wire tables; Bridon
catalogue); verify against the manufacturer's data:

* six strand:   mass 0.0040 d_mm^2 kg/m, MBS 0.633 d_mm^2 kN, EA 4.5e7 d_m^2 kN,
  displaced volume = mass / 7850 (the voids are flooded).
* spiral strand: mass 0.0054 d_mm^2 kg/m, MBS 0.90 d_mm^2 kN, EA 9.0e7 d_m^2 kN, displaced
  volume = mass / 6000 kg/m^3 (steel plus sheathing).

``polyester`` (parallel-strand / sub-rope polyester): mass 0.00066 d_mm^2 kg/m, MBS 0.25
d_mm^2 kN (catalogue fit, e.g. 185 mm -> 8,556 kN, compare Wang (2016) table 5.2: 8,500 kN), static
axial stiffness 15 MBS and dynamic 25 MBS (mid-range of the 10-20 and 20-35 MBS quoted in
DNV-OS-E303 / API RP 2SM for polyester), displaced volume = mass / 1380 kg/m^3 (fibre density).

Submerged weight convention: ``w = (mass - rho_w * displaced_volume) * g`` per unit length.

Unknown MBS: a user type may give ``mbs: unknown`` (the MoorDyn and MAP++ importers write it:
those files give no breaking strength); the type then carries ``mbs = nan``.  Statics, motions
and tensions do not need the MBS and run; every design check that does (DNV-OS-E301 ULS/ALS,
campaign screening, fatigue on the reference breaking strength) raises a SceneError naming the
line type, where it came from and what to set (:func:`mbs_known`,
:meth:`floatmoor.mooring.system.MooringSystem.require_mbs`).  A value >= ``MBS_UNKNOWN``
(1e30 N, the placeholder written by earlier imports) is read as unknown too.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass, replace
from importlib import resources
from pathlib import Path

from ..core.config import Node
from ..core.constants import GRAVITY, RHO_WATER
from ..core.errors import SceneError
from .fibre import PRESETS as FIBRE_PRESETS
from .fibre import FibreModel

__all__ = ["LineType", "MBS_UNKNOWN", "mbs_known", "CHAIN_GRADES", "FAMILIES", "LineTypeLibrary", "default_library",
           "chain", "wire_rope", "polyester"]

MBS_UNKNOWN = 1.0e30
"""Placeholder MBS (N) written by earlier MoorDyn/MAP++ imports; read as an unknown MBS."""


def mbs_known(mbs) -> bool:
    """True when ``mbs`` (N) is a real breaking strength (finite and below ``MBS_UNKNOWN``)."""
    return math.isfinite(mbs) and mbs < MBS_UNKNOWN


def _mbs(e: Node) -> float:
    """The (required) ``mbs`` key (N, > 0) of a line type entry; ``unknown`` (or the old
    placeholder ``MBS_UNKNOWN``) gives nan."""
    if isinstance(e.raw("mbs", None), str) and e.raw("mbs").strip().lower() == "unknown":
        return math.nan
    v = e.float("mbs", gt=0.0, unit="N")
    return math.nan if v >= MBS_UNKNOWN else v


CHAIN_GRADES = {"R3": 0.0223, "R3S": 0.0249, "R4": 0.0274, "R4S": 0.0304, "R5": 0.0320}
"""Grade factor c of the chain MBS formula (DNV-OS-E302), kN/mm^2."""

STEEL_DENSITY = 7850.0
POLYESTER_DENSITY = 1380.0


MATERIALS = ("chain", "wire", "polyester", "nylon", "hmpe", "user")
"""Line materials a line-type entry may name (``material:``); the material sets defaults
(``chain``: area_factor 2), so a misspelt name must not pass as ``user``."""


STEEL_MATERIALS = ("chain", "wire")
"""Materials whose ``density`` must be that of steel (a chain lighter than water is a typo)."""

MAX_DIAMETER = 0.5
"""Largest nominal line diameter accepted, m (the largest chains and ropes are about 0.2-0.3 m;
a diameter in mm typed for m is refused)."""


@dataclass(frozen=True, kw_only=True)
class LineType:
    """Properties of one line type (SI units).

    Attributes
    ----------
    name : str
    material : str
        ``chain``, ``wire``, ``polyester`` or ``user``.
    diameter : float
        Nominal diameter, m.
    mass_per_length : float
        Mass in air per unit length, kg/m.
    displaced_volume : float
        Displaced water volume per unit length, m^3/m.
    ea : float
        Static axial stiffness, N.
    ea_dynamic : float
        Dynamic axial stiffness, N (equal to ``ea`` for steel).
    mbs : float
        Minimum breaking strength, N; nan when unknown (``mbs: unknown``, imported types).
    cdn, cdt, can, cat : float
        Normal/tangential drag and added-mass coefficients on the nominal diameter.
    source : str
        Where the numbers come from.
    tn_curve : str
        Name of the fatigue T-N curve (:data:`floatmoor.post.fatigue.tn_curves.DNV_CURVES`);
        empty: chosen from the family or material.
    tn_a_d, tn_m : float or None
        User-defined T-N constants ``n = a_D s^-m`` (``s`` the tension range over the
        reference breaking strength); both or neither.
    fibre : FibreModel or None
        Load-dependent stiffness of a fibre rope (:mod:`floatmoor.mooring.fibre`); None keeps
        the constant ``ea`` / ``ea_dynamic``.
    """

    name: str
    material: str
    diameter: float
    mass_per_length: float
    displaced_volume: float
    ea: float
    ea_dynamic: float
    mbs: float
    cdn: float = 1.2
    cdt: float = 0.4
    can: float = 1.0
    cat: float = 0.0
    source: str = ""
    tn_curve: str = ""
    tn_a_d: float | None = None
    tn_m: float | None = None
    fibre: FibreModel | None = None

    def submerged_weight(self, water_density: float = RHO_WATER, gravity: float = GRAVITY) -> float:
        """Submerged weight per unit length, N/m: ``(mass - rho V) g``."""
        return (self.mass_per_length - water_density * self.displaced_volume) * gravity


def chain(d: float, grade: str = "R4", *, studlink: bool = False, name: str | None = None) -> LineType:
    """Chain line type from its nominal diameter ``d`` (m) and grade (R3, R3S, R4, R4S, R5).

    Formulas and sources in the module docstring.
    """
    if grade not in CHAIN_GRADES:
        raise ValueError(f"unknown chain grade {grade!r}; grades: {', '.join(CHAIN_GRADES)}")
    dmm = d * 1000.0
    mass = (0.0219 if studlink else 0.0199) * dmm ** 2
    mbs = CHAIN_GRADES[grade] * dmm ** 2 * (44.0 - 0.08 * dmm) * 1e3
    ea = (1.01e8 if studlink else 0.854e8) * d ** 2 * 1e3
    kind = "studlink" if studlink else "studless"
    return LineType(name=name or f"chain_{kind}_{grade}", material="chain", diameter=d,
                    mass_per_length=mass, displaced_volume=mass / STEEL_DENSITY, ea=ea,
                    ea_dynamic=ea, mbs=mbs, cdn=2.4, cdt=1.15, can=1.0, cat=0.5,
                    source="DNV-OS-E302 MBS formula; Vryhof Anchor Manual 2010 mass and EA fits")


def wire_rope(d: float, construction: str = "six_strand", *, name: str | None = None) -> LineType:
    """Steel wire rope (``six_strand`` or ``spiral_strand``) from its nominal diameter ``d`` (m)."""
    dmm = d * 1000.0
    if construction == "six_strand":
        mass, mbs, ea, rho = 0.0040 * dmm ** 2, 0.633e3 * dmm ** 2, 4.5e10 * d ** 2, STEEL_DENSITY
    elif construction == "spiral_strand":
        mass, mbs, ea, rho = 0.0054 * dmm ** 2, 0.90e3 * dmm ** 2, 9.0e10 * d ** 2, 6000.0
    else:
        raise ValueError(f"unknown wire construction {construction!r}; use six_strand or spiral_strand")
    return LineType(name=name or f"wire_{construction}", material="wire", diameter=d,
                    mass_per_length=mass, displaced_volume=mass / rho, ea=ea, ea_dynamic=ea,
                    mbs=mbs, cdn=1.2, cdt=0.008 * math.pi, can=1.0, cat=0.0,
                    source="typical catalogue fit (approximate), see floatmoor.mooring.line_types")


def polyester(d: float, *, name: str | None = None) -> LineType:
    """Polyester rope from its nominal diameter ``d`` (m); static EA 15 MBS, dynamic 25 MBS."""
    dmm = d * 1000.0
    mass = 0.00066 * dmm ** 2
    mbs = 0.25e3 * dmm ** 2
    return LineType(name=name or "polyester", material="polyester", diameter=d,
                    mass_per_length=mass, displaced_volume=mass / POLYESTER_DENSITY,
                    ea=15.0 * mbs, ea_dynamic=25.0 * mbs, mbs=mbs, cdn=1.2, cdt=0.008 * math.pi,
                    can=1.0, cat=0.0,
                    source="catalogue fit; EA 15/25 MBS after DNV-OS-E303 / API RP 2SM ranges")


def _chain_family(studlink):
    def build(d, grade="R4", name=None):
        return chain(d, grade, studlink=studlink, name=name)
    return build


FAMILIES = {
    "chain_studless": _chain_family(False),
    "chain_studlink": _chain_family(True),
    "wire_six_strand": lambda d, grade=None, name=None: wire_rope(d, "six_strand", name=name),
    "wire_spiral_strand": lambda d, grade=None, name=None: wire_rope(d, "spiral_strand", name=name),
    "polyester": lambda d, grade=None, name=None: polyester(d, name=name),
}
"""Formula families by name: ``f(d, grade=None, name=None) -> LineType``."""

_USER_KEYS = {"material", "diameter", "mass_per_length", "displaced_volume", "density",
              "volumetric_diameter", "submerged_weight", "ea", "ea_dynamic", "elastic_modulus",
              "mbs", "cdn", "cdt", "can", "cat", "source", "tn_curve", "tn_a_d", "tn_m", "fibre"}
_FAMILY_KEYS = {"family", "grade", "diameter", "source", "mbs", "ea", "ea_dynamic", "cdn", "cdt",
                "can", "cat", "tn_curve", "tn_a_d", "tn_m", "fibre"}


def _tn_fields(e: Node) -> dict:
    """The optional fatigue T-N keys of a library entry (``tn_curve``; ``tn_a_d`` with
    ``tn_m``)."""
    out = {}
    if "tn_curve" in e:
        out["tn_curve"] = e.str("tn_curve")
    if ("tn_a_d" in e) != ("tn_m" in e):
        missing = "tn_m" if "tn_a_d" in e else "tn_a_d"
        raise e.error(missing, "both tn_a_d and tn_m (a user T-N curve n = a_D s^-m)")
    if "tn_a_d" in e:
        out["tn_a_d"] = e.float("tn_a_d", gt=0.0)
        out["tn_m"] = e.float("tn_m", gt=0.0)
    return out


POLYNOMIAL_POINTS = 41
"""Table points a polynomial tension-strain curve is sampled at (0 to ``max_strain``)."""


def _polynomial_curve(c: Node) -> tuple[tuple, tuple]:
    """``{polynomial: [c1, c2, ...], max_strain: e}``: ``T/MBS = c1 eps + c2 eps^2 + ...``
    sampled at :data:`POLYNOMIAL_POINTS` strains from 0 to ``max_strain`` (linear beyond)."""
    c.reject_unknown({"polynomial", "max_strain"})
    coef = c.list("polynomial", min_len=1)
    if not all(isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)
               for v in coef):
        raise c.error("polynomial", "a list of numbers c1, c2, ... (T/MBS = c1 eps + c2 eps^2 "
                      "+ ...)", coef)
    from .fibre import MAX_STRAIN
    e_max = c.float("max_strain", gt=0.0, le=MAX_STRAIN)
    eps = [e_max * i / (POLYNOMIAL_POINTS - 1) for i in range(POLYNOMIAL_POINTS)]
    t = [sum(ck * e ** (k + 1) for k, ck in enumerate(coef)) for e in eps]
    if any(b <= a for a, b in zip(t, t[1:])):
        raise c.error("polynomial", f"a tension increasing with the strain up to max_strain "
                      f"{e_max:g}", coef)
    return tuple(eps), tuple(t)


def _curve(n: Node, key: str) -> tuple[tuple, tuple]:
    c = n.child(key)
    if "polynomial" in c:
        return _polynomial_curve(c)
    c.reject_unknown({"strain", "tension_mbs"})
    out = []
    for k in ("strain", "tension_mbs"):
        vals = c.list(k, min_len=2)
        if not all(isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)
                   for v in vals):
            raise c.error(k, "a list of numbers", vals)
        out.append(tuple(float(v) for v in vals))
    if len(out[0]) != len(out[1]):
        raise c.error("tension_mbs", f"as many values as strain ({len(out[0])})", out[1])
    if out[0][0] != 0.0 or out[1][0] != 0.0:
        raise c.error("strain", "a curve starting at strain 0, tension 0", (out[0][0], out[1][0]))
    for k, v in zip(("strain", "tension_mbs"), out):
        if any(b <= a for a, b in zip(v, v[1:])):
            raise c.error(k, "strictly increasing values", v)
    return out[0], out[1]


def _fibre_field(e: Node) -> dict:
    """The optional ``fibre`` key of a library entry: a preset name (``polyester_default``) or
    ``{preset, working_curve: {strain, tension_mbs}, original_curve: {...},
    dynamic: {alpha, beta}, max_tension_mbs, source}`` (a preset's values overridden by the keys
    given; ``max_tension_mbs``: the largest mean tension seen, for the bedding-in); a curve
    may instead be a polynomial ``{polynomial: [c1, c2, ...], max_strain: e}`` with
    ``T/MBS = c1 eps + c2 eps^2 + ...`` (sampled into a table)."""
    if "fibre" not in e:
        return {}
    raw = e.raw("fibre")
    if isinstance(raw, str):
        return {"fibre": FIBRE_PRESETS[e.choice("fibre", FIBRE_PRESETS, what="fibre rope model")]}
    f = e.child("fibre")
    f.reject_unknown({"preset", "working_curve", "original_curve", "dynamic", "source",
                      "max_tension_mbs"})
    base = (FIBRE_PRESETS[f.choice("preset", FIBRE_PRESETS, what="fibre rope model")]
            if "preset" in f else None)
    kw = {}
    if "working_curve" in f:
        kw["working_strain"], kw["working_tension_mbs"] = _curve(f, "working_curve")
    elif base is None:
        raise f.error("working_curve", "the quasi-static working curve {strain: [...], "
                      "tension_mbs: [...]} (or a preset: polyester_default)")
    if "original_curve" in f:
        kw["original_strain"], kw["original_tension_mbs"] = _curve(f, "original_curve")
    if "dynamic" in f:
        d = f.child("dynamic")
        d.reject_unknown({"alpha", "beta"})
        kw["alpha"] = d.float("alpha", gt=0.0)
        kw["beta"] = d.float("beta", ge=0.0)
    elif base is None:
        raise f.error("dynamic", "the dynamic stiffness {alpha: EA_dyn/MBS at zero mean load, "
                      "beta: per % MBS of mean load}")
    if "max_tension_mbs" in f:
        kw["max_tension_mbs"] = f.float("max_tension_mbs", ge=0.0, lt=1.0)
    kw["source"] = f.str("source", base.source if base is not None else f"user-defined in {e.file}")
    try:
        model = replace(base, **kw) if base is not None else FibreModel(**kw)
    except ValueError as exc:
        raise f.error("", "a valid fibre rope model", str(exc)) from None
    from .fibre import unit_problems
    for key, expected, found, hint in unit_problems(model):
        raise f.error(key, expected, found, hint)
    return {"fibre": model}


FIBRE_MATERIALS = ("polyester", "nylon", "hmpe", "user")
"""Materials a fibre-rope stiffness model (``fibre:``) may be given to."""


def _check_fibre_material(e: Node, material: str) -> None:
    if "fibre" in e and material not in FIBRE_MATERIALS:
        raise e.error("fibre", f"no fibre-rope stiffness model on a {material} line type (a "
                      "working curve and mean-load dynamic stiffness describe fibre ropes: "
                      + ", ".join(m for m in FIBRE_MATERIALS if m != "user") + ")",
                      e.raw("fibre"), "a fibre entry copied onto the wrong line type?")


class LineTypeLibrary:
    """Named line types read from YAML files (the shipped library, plus user files).

    A library file has a top-level mapping ``line_types:``; each entry is either

    * a formula family: ``{family: chain_studless, grade: R4}`` (the diameter is given where the
      type is used, or in the entry as ``diameter``), optionally overriding ``mbs``/``ea``; or
    * a user type with explicit values: ``diameter`` (m), ``mass_per_length`` (kg/m), ``ea`` (N)
      or ``elastic_modulus`` (Pa, on the area of ``area_factor`` x pi d^2 / 4: 2 for chain,
      1 otherwise), ``mbs`` (N), and the displacement as one of ``displaced_volume`` (m^3/m),
      ``density`` (kg/m^3 of the material) or ``volumetric_diameter`` (m), or directly
      ``submerged_weight`` (N/m, taken as given whatever the water density).
    """

    def __init__(self, entries: Mapping[str, Node] | None = None):
        self._entries: dict[str, Node] = dict(entries or {})

    @property
    def names(self) -> list[str]:
        return sorted(self._entries)

    def __contains__(self, name):
        return name in self._entries

    def extended(self, node: Node) -> LineTypeLibrary:
        """A new library with the entries of ``node`` (a ``line_types`` mapping) added; an entry
        with an existing name replaces it."""
        entries = dict(self._entries)
        for key in node.keys():
            entries[str(key)] = node.child(key)
        return LineTypeLibrary(entries)

    def extended_from_file(self, path) -> LineTypeLibrary:
        root = Node.load(path)
        root.reject_unknown({"line_types"})
        return self.extended(root.child("line_types"))

    def get(self, name: str, *, diameter: float | None = None, node: Node | None = None,
            key: str = "type", water_density: float = RHO_WATER, gravity: float = GRAVITY):
        """Build the named line type; returns ``(LineType, submerged_weight_override_or_None)``.

        ``node``/``key`` name the place that asked for it, for error messages.
        """
        if name not in self._entries:
            err = (node.error(key, "a line type name, one of: " + ", ".join(self.names), name)
                   if node is not None else
                   SceneError(None, key, "a line type name, one of: " + ", ".join(self.names), name))
            raise err
        e = self._entries[name]
        if "family" in e:
            e.reject_unknown(_FAMILY_KEYS)
            family = e.choice("family", FAMILIES, what="line type family")
            d = e.float("diameter", None, gt=0.0, le=MAX_DIAMETER, unit="m")
            if d is None:
                d = diameter
            if d is None:
                raise (node.error("diameter", f"the nominal diameter in m of line type {name!r} "
                                  f"(a formula family: {family})")
                       if node is not None else e.error("diameter", "a diameter in m"))
            grade = None
            if family.startswith("chain"):
                grade = e.str("grade", "R4", choices=list(CHAIN_GRADES))
            lt = FAMILIES[family](d, grade=grade, name=name)
            over = {}
            if "mbs" in e:
                over["mbs"] = _mbs(e)
            for k in ("ea", "ea_dynamic", "cdn", "cdt", "can", "cat"):
                if k in e:
                    over[k] = e.float(k, gt=0.0 if k in ("ea", "ea_dynamic") else None,
                                      ge=None if k in ("ea", "ea_dynamic") else 0.0)
            if "ea" in over and "ea_dynamic" not in over and lt.material != "polyester":
                over["ea_dynamic"] = over["ea"]
            if "source" in e:
                over["source"] = e.str("source")
            over.update(_tn_fields(e))
            _check_fibre_material(e, lt.material)
            over.update(_fibre_field(e))
            return (replace(lt, **over) if over else lt), None
        e.reject_unknown(_USER_KEYS | {"area_factor"})
        d = e.float("diameter", gt=0.0, le=MAX_DIAMETER, unit="m")
        mass = e.float("mass_per_length", gt=0.0, unit="kg/m")
        material = e.str("material", "user", choices=MATERIALS)
        if "ea" in e and "elastic_modulus" in e:
            raise e.error("elastic_modulus", "either ea or elastic_modulus, not both",
                          e.raw("elastic_modulus"))
        area_factor = e.float("area_factor", 2.0 if material == "chain" else 1.0, gt=0.0)
        if "elastic_modulus" in e:
            ea = e.float("elastic_modulus", gt=0.0, unit="Pa") * area_factor * math.pi * d * d / 4
        else:
            ea = e.float("ea", gt=0.0, unit="N")
        ead = e.float("ea_dynamic", ea, gt=0.0, unit="N")
        mbs = _mbs(e)
        given = [k for k in ("displaced_volume", "density", "volumetric_diameter", "submerged_weight")
                 if k in e]
        if len(given) != 1:
            raise e.error("displaced_volume", "exactly one of displaced_volume (m^3/m), density "
                          "(kg/m^3), volumetric_diameter (m) or submerged_weight (N/m)",
                          given or SceneError.MISSING)
        w_override = None
        if given[0] == "displaced_volume":
            vol = e.float("displaced_volume", ge=0.0, unit="m^3/m")
        elif given[0] == "density":
            rho_m = e.float("density", gt=0.0, unit="kg/m^3")
            if material in STEEL_MATERIALS and not 6000.0 <= rho_m <= 9000.0:
                raise e.error("density", f"the density of steel {material} in kg/m^3 (about "
                              f"{STEEL_DENSITY:g}; 6000-9000 accepted)", rho_m)
            vol = mass / rho_m
        elif given[0] == "volumetric_diameter":
            dv = e.float("volumetric_diameter", gt=0.0, unit="m")
            vol = math.pi * dv * dv / 4
        else:
            w_override = e.float("submerged_weight", unit="N/m")
            vol = max(mass - w_override / gravity, 0.0) / water_density
        kw = {k: e.float(k, ge=0.0) for k in ("cdn", "cdt", "can", "cat") if k in e}
        _check_fibre_material(e, material)
        lt = LineType(name=name, material=material, diameter=d, mass_per_length=mass,
                      displaced_volume=vol, ea=ea, ea_dynamic=ead, mbs=mbs,
                      source=e.str("source", f"user-defined in {e.file}"), **kw, **_tn_fields(e),
                      **_fibre_field(e))
        return lt, w_override


def default_library() -> LineTypeLibrary:
    """The library shipped with floatmoor (``floatmoor/data/line_types.yaml``)."""
    path = Path(str(resources.files("floatmoor") / "data" / "line_types.yaml"))
    return LineTypeLibrary().extended_from_file(path)

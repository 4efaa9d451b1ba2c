"""Design codes as data: one YAML file per code and edition in ``floatmoor/data/codes``.

A code file holds the partial safety factors (or factors of safety) and rules of one edition of
a mooring design code, every value with its source and a ``verified`` flag (checked against a
text of the standard, or not).  :func:`load_code` reads one by key (``dnv-os-e301-2008``), alias
(``dnv-os-e301``) or path (a user's own file in the same format); :func:`available_codes` lists
the shipped ones.  A report names the code and edition it used and lists every unverified value
it used (:meth:`DesignCode.entries_used`).

Shipped codes (see each file's header for what could and could not be checked):

* ``dnv-os-e301-2008`` -- DNV-OS-E301 Position Mooring, October 2008 (the ULS/ALS factors
  verified against Wang (2016) tables 3.1 and 3.2; the rest unverified);
* ``api-rp-2sk-2005`` -- API RP 2SK, 3rd edition 2005 (working-stress factors of safety, in
  the design equation as ``gamma_mean = gamma_dyn = FoS`` on ``S_C = MBS``; unverified);
* ``dnv-st-0119-2021`` -- DNV-ST-0119 Floating wind turbine structures, June 2021, station
  keeping (dynamic analysis only; unverified).

Later editions of DNV-OS-E301 are not shipped: their values could not be confirmed from a public
text here.

File format (every *entry* is a mapping with ``source``, ``verified`` and optional ``note``)::

    key: dnv-os-e301-2008          # the name used on the command line and in campaign files
    aliases: [dnv-os-e301]
    code: DNV-OS-E301
    title: Position Mooring
    edition: October 2008
    format: partial_safety_factors # or factor_of_safety (working stress: gamma = FoS, S_C = MBS)
    consequence_classes: [1, 2]    # [] when the code has none
    analyses: [dynamic, quasi-static]
    line_tension:
      strength_factor: {value: 0.95, source: ..., verified: false}
      ULS:                         # and ALS: {analysis: {class or "any": factors}}
        source: ...
        verified: true
        dynamic: {1: {gamma_mean: 1.1, gamma_dyn: 1.5}, 2: {...}}
      common_factor: {value: 1.3, ratio: 0.667, source: ..., verified: ...}      # optional
      single_point_mooring_factor: {value: 1.2, source: ..., verified: ...}       # optional
    fatigue:
      rule: adjacent_line_ramp     # or constant
      safety_factor: {low: 5, high: 8, d_f_low: 0.8, d_f_high: 1.0, source: ..., verified: ...}
    corrosion: {source: ..., verified: ..., chain: {splash: .., catenary: .., bottom: ..},
                end_of_life_capacity: true}
    anchors: {source: ..., verified: ..., load_factors: line_tension | none,
              material_factor: {ULS: .., ALS: ..} | factor_of_safety: {type: {ULS: {analysis: ..}}},
              uplift: {source: ..., verified: ..., drag: {ULS: 0.0, ALS: 0.0}, pile: {...}}}
    fibre: {source: ..., verified: ..., seabed_contact: forbidden | allowed,
            min_tension_fraction: 0.0}
"""

from __future__ import annotations

import math
import numbers
import os
from dataclasses import dataclass, field
from pathlib import Path

from ..core.config import Node
from ..core.errors import SceneError, argument_error

__all__ = ["ANCHOR_TYPES", "CODES_DIR", "CodeValue", "DEFAULT_CODE", "DesignCode", "LineFactors",
           "available_codes", "load_code", "normalise_analysis"]

CODES_DIR = Path(__file__).resolve().parents[1] / "data" / "codes"
"""Folder of the shipped code files."""

DEFAULT_CODE = "dnv-os-e301-2008"
"""The code of a report that names none (as before code files: DNV-OS-E301, October 2008)."""

ANALYSES = ("dynamic", "quasi-static")
LIMIT_STATES = ("ULS", "ALS")
ANCHOR_TYPES = ("drag", "plate", "pile", "suction", "gravity")
"""Anchor types a mooring file may name (``lines[].anchor_type``)."""
FORMATS = ("partial_safety_factors", "factor_of_safety")


def normalise_analysis(analysis, key: str = "analysis") -> str:
    """``"dynamic"`` or ``"quasi-static"`` from the spellings users type (quasistatic,
    quasi_static, ...); SceneError otherwise."""
    an = str(analysis).lower().replace("_", "-").replace(" ", "-")
    if an == "quasistatic":
        an = "quasi-static"
    if an not in ANALYSES:
        raise argument_error(key, "one of: dynamic, quasi-static", analysis)
    return an


@dataclass(frozen=True)
class CodeValue:
    """Where a value of a code file comes from: its key ``path`` in the file, the ``source``
    text, whether it was ``verified`` against a text of the standard, and a ``note``."""

    path: str
    source: str
    verified: bool
    note: str = ""

    def describe(self) -> str:
        text = f"{self.path}: {self.source}"
        if self.note:
            text += f" ({self.note})"
        return text


@dataclass(frozen=True, kw_only=True)
class LineFactors:
    """Partial safety factors of one limit state, consequence class and analysis type."""

    limit_state: str
    consequence_class: int
    analysis: str
    gamma_mean: float
    gamma_dyn: float
    entry: CodeValue
    single_point_mooring: bool = False
    common_factor: float | None = None
    common_factor_ratio: float | None = None

    @property
    def common_factor_possible(self) -> bool:
        """Whether the code's common factor applies to this limit state, class and analysis
        (DNV-OS-E301: ULS, class 1, dynamic; never with the single-point-mooring increase)."""
        return (self.common_factor is not None and self.limit_state == "ULS"
                and self.consequence_class == 1 and self.analysis == "dynamic"
                and not self.single_point_mooring)


def _words(x) -> str:
    return " ".join(str(x).split())


@dataclass(frozen=True, eq=False)
class DesignCode:
    """One design code and edition (read with :func:`load_code`)."""

    key: str
    code: str
    title: str
    edition: str
    format: str
    consequence_classes: tuple
    analyses: tuple
    file: Path
    aliases: tuple = ()
    references: tuple = ()
    entries: dict = field(default_factory=dict)
    tree: dict = field(default_factory=dict, repr=False)

    # -- naming -------------------------------------------------------------------------------
    @property
    def name(self) -> str:
        """``"DNV-OS-E301 Position Mooring, October 2008"``."""
        return f"{self.code} {self.title}, {self.edition}"

    @property
    def has_classes(self) -> bool:
        return bool(self.consequence_classes)

    def _error(self, key, expected, found=SceneError.MISSING, hint=None):
        return SceneError(self.file, key, expected, found, hint)

    def _entry(self, path: str) -> CodeValue:
        return self.entries[path]

    def unverified(self) -> list[CodeValue]:
        """Every unverified entry of the file."""
        return [e for e in self.entries.values() if not e.verified]

    def entries_used(self, parts) -> list[CodeValue]:
        """The entries under the given key paths (e.g. ``["line_tension.ULS",
        "line_tension.strength_factor", "fatigue"]``), in file order."""
        parts = list(parts)
        return [e for p, e in self.entries.items()
                if any(p == q or p.startswith(q + ".") for q in parts)]

    # -- line tension -------------------------------------------------------------------------
    def check_class(self, consequence_class) -> int:
        """The consequence class as an int; SceneError when the code has classes and this is
        not one of them.  A code without classes accepts any (it is not used)."""
        ok = isinstance(consequence_class, numbers.Integral) or (
            isinstance(consequence_class, float) and consequence_class.is_integer())
        if isinstance(consequence_class, bool) or not ok:
            raise argument_error("consequence_class", "an integer consequence class",
                                 consequence_class)
        cc = int(consequence_class)
        if self.has_classes and cc not in self.consequence_classes:
            raise argument_error("consequence_class",
                                 f"{' or '.join(map(str, self.consequence_classes))} "
                                 f"({self.name} consequence classes)", consequence_class)
        return cc

    def check_analysis(self, analysis) -> str:
        an = normalise_analysis(analysis)
        if an not in self.analyses:
            raise argument_error(
                "analysis", f"one of: {', '.join(self.analyses)} ({self.name} gives no "
                f"{an} factors)", analysis,
                "a quasi-static analysis needs the dynamic amplification of the lines: give "
                "finite-element lines (mooring model: finite-element) or the DAF of floatmoor "
                "lines (floatmoor report --daf FILE)" if an == "quasi-static" else None)
        return an

    def line_factors(self, limit_state: str = "ULS", consequence_class: int = 2,
                     analysis: str = "dynamic", *, single_point_mooring: bool = False
                     ) -> LineFactors:
        """Partial safety factors of the line tension (SceneError for an unknown limit state,
        class or analysis the code does not cover)."""
        ls = str(limit_state).upper()
        if ls not in LIMIT_STATES:
            raise argument_error("limit_state", "one of: ULS, ALS", limit_state)
        cc = self.check_class(consequence_class)
        an = self.check_analysis(analysis)
        if single_point_mooring and ls == "ALS":
            raise argument_error("limit_state",
                                 "ULS only for a single point mooring without redundancy "
                                 "(the ALS is not applicable; remark under Wang (2016) "
                                 "table 3.1)", limit_state)
        table = self.tree["line_tension"][ls][an]
        row = table.get(cc, table.get("any")) if self.has_classes else table["any"]
        gm, gd = float(row["gamma_mean"]), float(row["gamma_dyn"])
        if single_point_mooring:
            spm = self.tree["line_tension"].get("single_point_mooring_factor")
            if spm is None:
                raise argument_error("single_point_mooring",
                                     f"a code with a single-point-mooring factor ({self.name} "
                                     "has none)", True)
            gm, gd = gm * float(spm["value"]), gd * float(spm["value"])
        cf = self.tree["line_tension"].get("common_factor")
        return LineFactors(limit_state=ls, consequence_class=cc, analysis=an, gamma_mean=gm,
                           gamma_dyn=gd, entry=self._entry(f"line_tension.{ls}"),
                           single_point_mooring=bool(single_point_mooring),
                           common_factor=None if cf is None else float(cf["value"]),
                           common_factor_ratio=None if cf is None else float(cf["ratio"]))

    @property
    def strength_factor(self) -> float:
        """``S_C / S_mbs`` of a line (0.95 in DNV-OS-E301; 1.0 in a factor-of-safety code)."""
        return float(self.tree["line_tension"]["strength_factor"]["value"])

    def factors_table(self) -> list[dict]:
        """All table factors as rows (limit state, class, analysis, gamma_mean, gamma_dyn)."""
        rows = []
        for ls in LIMIT_STATES:
            for an in ANALYSES:
                table = self.tree["line_tension"].get(ls, {}).get(an)
                if not isinstance(table, dict):
                    continue
                for cc, f in table.items():
                    if not isinstance(f, dict):
                        continue
                    rows.append({"limit_state": ls, "consequence_class": cc, "analysis": an,
                                 "gamma_mean": float(f["gamma_mean"]),
                                 "gamma_dyn": float(f["gamma_dyn"])})
        return rows

    # -- fatigue ------------------------------------------------------------------------------
    def fatigue_factor(self, d_f: float = float("nan")) -> float:
        """The fatigue safety factor ``gamma_F``: constant, or (DNV-OS-E301) the ramp from
        ``low`` at ``d_f <= d_f_low`` to ``high`` at ``d_f_high`` with the adjacent-line damage
        ratio ``d_f`` (NaN or not given: the low value)."""
        fat = self.tree["fatigue"]
        sf = fat["safety_factor"]
        if fat["rule"] == "constant":
            return float(sf["value"])
        lo, hi = float(sf["low"]), float(sf["high"])
        x0, x1 = float(sf["d_f_low"]), float(sf["d_f_high"])
        if not math.isfinite(d_f) or d_f <= x0:
            return lo
        return lo + (hi - lo) * (min(float(d_f), x1) - x0) / (x1 - x0)

    def fatigue_rule_text(self) -> str:
        fat = self.tree["fatigue"]
        sf = fat["safety_factor"]
        if fat["rule"] == "constant":
            return f"gamma_F = {float(sf['value']):g}"
        lo, hi = float(sf["low"]), float(sf["high"])
        x0, x1 = float(sf["d_f_low"]), float(sf["d_f_high"])
        return (f"gamma_F = {lo:g} for d_F <= {x0:g}, {lo:g} + {hi - lo:g} (d_F - {x0:g}) / "
                f"{x1 - x0:g} above (d_F the adjacent-line damage ratio)")

    # -- corrosion ----------------------------------------------------------------------------
    def corrosion_rates(self, material: str) -> dict:
        """Allowance rates (mm of diameter per year) by zone for a material (``chain``; empty
        for a material the code gives none for)."""
        return {str(k): float(v) for k, v in
                (self.tree.get("corrosion", {}).get(material) or {}).items()}

    @property
    def end_of_life_capacity(self) -> bool:
        """Whether the ULS/ALS capacity is the corroded (end-of-life) one."""
        return bool(self.tree.get("corrosion", {}).get("end_of_life_capacity", False))

    # -- anchors ------------------------------------------------------------------------------
    def anchor_factors(self, anchor_type: str, limit_state: str, consequence_class: int,
                       analysis: str) -> dict:
        """The anchor check of one anchor type: ``gamma_mean``, ``gamma_dyn`` (on the
        characteristic anchor tension) and ``resistance_factor`` (the characteristic holding
        capacity is divided by it: the material factor, or the factor of safety)."""
        a = self.tree["anchors"]
        ls = str(limit_state).upper()
        if anchor_type not in ANCHOR_TYPES:
            raise argument_error("anchor_type", "one of: " + ", ".join(ANCHOR_TYPES),
                                 anchor_type)
        if a.get("load_factors") == "line_tension":
            f = self.line_factors(ls, consequence_class, analysis)
            gm, gd = f.gamma_mean, f.gamma_dyn
        else:
            gm = gd = 1.0
        if "material_factor" in a:
            r = float(a["material_factor"][ls])
        else:
            r = float(a["factor_of_safety"][anchor_type][ls][normalise_analysis(analysis)])
        return {"gamma_mean": gm, "gamma_dyn": gd, "resistance_factor": r}

    def uplift_limit_deg(self, anchor_type: str, limit_state: str) -> float | None:
        """The largest uplift angle at the anchor (deg) the code accepts for the anchor type,
        None when the type is designed for uplift (no limit)."""
        v = self.tree["anchors"]["uplift"].get(anchor_type, {}).get(str(limit_state).upper())
        return None if v is None else float(v)

    # -- fibre --------------------------------------------------------------------------------
    @property
    def fibre_seabed_contact_allowed(self) -> bool:
        return str(self.tree.get("fibre", {}).get("seabed_contact", "forbidden")) == "allowed"

    @property
    def fibre_min_tension_fraction(self) -> float:
        return float(self.tree.get("fibre", {}).get("min_tension_fraction", 0.0))


# -- reading -----------------------------------------------------------------------------------
_TOP = {"key", "aliases", "code", "title", "edition", "format", "consequence_classes",
        "analyses", "references", "line_tension", "fatigue", "corrosion", "anchors", "fibre",
        "description"}
_ENTRY_KEYS = {"source", "verified", "note"}


def _plain(x):
    """A YAML value with every mapping as a dict (classes as int keys)."""
    if isinstance(x, Node):
        x = x.data
    if isinstance(x, dict):
        return {k: _plain(v) for k, v in x.items()}
    if isinstance(x, list):
        return [_plain(v) for v in x]
    return x


def _collect_entries(data, path: str, out: dict, file, node_path: str) -> None:
    """Every mapping with a ``source`` key is an entry; it must say ``verified``."""
    if not isinstance(data, dict):
        return
    if "source" in data:
        v = data.get("verified")
        if not isinstance(v, bool):
            raise SceneError(file, f"{path}.verified" if path else "verified",
                             "true or false (whether the value was checked against a text of "
                             "the standard)", SceneError.MISSING if v is None else v)
        if not isinstance(data["source"], str) or not data["source"].strip():
            raise SceneError(file, f"{path}.source", "the source of the value (text)",
                             data["source"])
        out[path] = CodeValue(path=path, source=_words(data["source"]), verified=v,
                              note=_words(data.get("note", "")))
    for k, v in data.items():
        if k in _ENTRY_KEYS:
            continue
        _collect_entries(v, f"{path}.{k}" if path else str(k), out, file, node_path)


def _require(cond, file, key, expected, found=SceneError.MISSING):
    if not cond:
        raise SceneError(file, key, expected, found)


def _factor_pair(row, file, key):
    _require(isinstance(row, dict) and {"gamma_mean", "gamma_dyn"} <= set(row), file, key,
             "a mapping {gamma_mean: ..., gamma_dyn: ...}", row)
    for k in ("gamma_mean", "gamma_dyn"):
        v = row[k]
        _require(isinstance(v, (int, float)) and not isinstance(v, bool) and 1.0 <= v <= 10.0,
                 file, f"{key}.{k}", "a partial safety factor between 1 and 10", v)


def _validate(tree: dict, file) -> None:
    """Structural checks of a code file (SceneError naming the key)."""
    _require(tree.get("format") in FORMATS, file, "format", "one of: " + ", ".join(FORMATS),
             tree.get("format"))
    classes = tree.get("consequence_classes", [])
    _require(isinstance(classes, list) and all(isinstance(c, int) and not isinstance(c, bool)
                                               for c in classes), file, "consequence_classes",
             "a list of integer classes ([] when the code has none)", classes)
    analyses = tree.get("analyses")
    _require(isinstance(analyses, list) and analyses and set(analyses) <= set(ANALYSES), file,
             "analyses", "a list among: " + ", ".join(ANALYSES), analyses)
    lt = tree.get("line_tension")
    _require(isinstance(lt, dict), file, "line_tension", "a mapping", lt)
    sf = lt.get("strength_factor")
    _require(isinstance(sf, dict) and isinstance(sf.get("value"), (int, float))
             and 0.0 < sf["value"] <= 1.0, file, "line_tension.strength_factor.value",
             "a factor in (0, 1]", None if not isinstance(sf, dict) else sf.get("value"))
    for ls in LIMIT_STATES:
        t = lt.get(ls)
        _require(isinstance(t, dict), file, f"line_tension.{ls}", "a mapping of the analyses",
                 t)
        for an in analyses:
            rows = t.get(an)
            _require(isinstance(rows, dict), file, f"line_tension.{ls}.{an}",
                     "a mapping of consequence classes (or any) to factors", rows)
            need = classes if classes else ["any"]
            for cc in need:
                _require(cc in rows or "any" in rows, file, f"line_tension.{ls}.{an}.{cc}",
                         "the factors of this consequence class")
                _factor_pair(rows.get(cc, rows.get("any")), file, f"line_tension.{ls}.{an}.{cc}")
    fat = tree.get("fatigue")
    _require(isinstance(fat, dict) and fat.get("rule") in ("constant", "adjacent_line_ramp"),
             file, "fatigue.rule", "constant or adjacent_line_ramp",
             None if not isinstance(fat, dict) else fat.get("rule"))
    sfat = fat.get("safety_factor", {})
    keys = {"value"} if fat["rule"] == "constant" else {"low", "high", "d_f_low", "d_f_high"}
    _require(isinstance(sfat, dict) and keys <= set(sfat), file, "fatigue.safety_factor",
             "the keys " + ", ".join(sorted(keys)), sfat)
    anchors = tree.get("anchors")
    _require(isinstance(anchors, dict) and anchors.get("load_factors") in ("line_tension",
                                                                              "none"),
             file, "anchors.load_factors", "line_tension or none",
             None if not isinstance(anchors, dict) else anchors.get("load_factors"))
    _require(("material_factor" in anchors) != ("factor_of_safety" in anchors), file,
             "anchors", "either material_factor or factor_of_safety")
    up = anchors.get("uplift")
    _require(isinstance(up, dict) and all(isinstance(up.get(t), dict) for t in ANCHOR_TYPES),
             file, "anchors.uplift", "the uplift limit of every anchor type: "
             + ", ".join(ANCHOR_TYPES), up)
    fib = tree.get("fibre", {})
    _require(fib.get("seabed_contact", "forbidden") in ("forbidden", "allowed"), file,
             "fibre.seabed_contact", "forbidden or allowed", fib.get("seabed_contact"))


def _candidates(name: str) -> Path | None:
    p = CODES_DIR / f"{name}.yaml"
    if p.is_file():
        return p
    for f in sorted(CODES_DIR.glob("*.yaml")):
        try:
            head = Node.load(f)
        except SceneError:
            continue
        if name in (head.data.get("aliases") or []):
            return f
    return None


def available_codes() -> list[tuple[str, str]]:
    """``(key, name)`` of the shipped codes."""
    out = []
    for f in sorted(CODES_DIR.glob("*.yaml")):
        c = load_code(f)
        out.append((c.key, c.name))
    return out


_CACHE: dict = {}


def load_code(name=DEFAULT_CODE) -> DesignCode:
    """The code of a key, alias or file path (a :class:`DesignCode`, cached per file).

    Raises
    ------
    SceneError
        An unknown name (the message lists the shipped codes) or a file that is not a valid
        code file (naming the key).
    """
    if isinstance(name, DesignCode):
        return name
    text = os.fspath(name)
    path = Path(text)
    if not (path.suffix in (".yaml", ".yml") and path.is_file()):
        found = _candidates(text.lower())
        if found is None:
            names = [f.stem for f in sorted(CODES_DIR.glob("*.yaml"))]
            raise SceneError(None, "code", "a design code, one of: " + ", ".join(names)
                             + " (or a code file in their format)", text)
        path = found
    path = path.resolve()
    stamp = (str(path), path.stat().st_mtime_ns)
    if stamp in _CACHE:
        return _CACHE[stamp]
    node = Node.load(path)
    node.reject_unknown(_TOP)
    tree = _plain(node)
    _validate(tree, path)
    entries: dict = {}
    _collect_entries(tree, "", entries, path, "")
    for need in ("line_tension.ULS", "line_tension.ALS", "line_tension.strength_factor",
                 "fatigue.safety_factor", "anchors"):
        if need not in entries and not any(p.startswith(need) for p in entries):
            raise SceneError(path, need, "a source and verified flag for the value")
    code = DesignCode(key=node.str("key"), code=node.str("code"), title=node.str("title"),
                      edition=str(node.raw("edition")), format=tree["format"],
                      consequence_classes=tuple(tree.get("consequence_classes", [])),
                      analyses=tuple(tree["analyses"]), file=path,
                      aliases=tuple(tree.get("aliases") or ()),
                      references=tuple(tree.get("references") or ()), entries=entries,
                      tree=tree)
    _CACHE[stamp] = code
    return code

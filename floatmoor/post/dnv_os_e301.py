"""Mooring line design checks by DNV-OS-E301 (ULS and ALS, partial safety factor format).

Source of every factor here
---------------------------
DNV-OS-E301 "Position Mooring", **October 2008 edition** (DNV (2008)) -- the edition cited by
Wang (2016) (reference "Veritas, D. N. (2008). Offshore standard dnv-os-e301: Position
mooring", used in its chapter 3).  Clauses: Ch.2 Sec.2 (mooring system
analysis): characteristic line tensions, characteristic capacity, and the partial safety
factors for the ULS and the ALS.  The numbers are those Wang (2016) reproduces:

* design equation, Wang (2016) eq. 3.4: ``S_C - T_C-mean gamma_mean - T_C-dyn gamma_dyn >= 0``
  (identical for ULS and ALS, Wang (2016) section 3.4.2);
* ULS factors, Wang (2016) table 3.1; ALS factors, Wang (2016) table 3.2 (consequence class 1 or
  2, dynamic or quasi-static analysis of the WF tension).  In the quasi-static rows the standard
  prints one value across both columns; it is applied to both the mean and the dynamic tension
  here (``gamma_mean = gamma_dyn``), i.e. to the total characteristic tension;
* remark 1 under table 3.1 (ULS only): "If T_C-mean > 2/3 T_C-dyn, when applying a dynamic
  analysis in consequence class 1, then a common value of 1.3 shall be applied as the partial
  factor instead of the separate static and dynamic safety factors".  Note the strict ``>``, and
  that, as written, the rule *lowers* the design tension when 2/3 < T_C-mean / T_C-dyn < 1
  (1.3 (T_m + T_d) < 1.1 T_m + 1.5 T_d there).  ``common_factor_rule="as_written"`` (default)
  applies it literally; ``"conservative"`` uses the larger of the two design tensions;
* remark 2 under table 3.1: single point moorings without redundancy, for which the ALS is not
  applicable, may be accepted with the ULS factors increased by a factor 1.2
  (``single_point_mooring=True``);
* characteristic strength of the main body of a line, ``S_C = 0.95 S_mbs`` (DNV-OS-E301
  Ch.2 Sec.2, characteristic capacity, for a line of new chain or steel wire rope components
  whose strength statistics are not documented; Wang's (2016) section 3.2 explains why the
  strength of a long line is below the average component strength but gives no number, and
  the 2008 text for fibre rope was not checked here).  The factor is a parameter
  (``strength_factor``).

The simple safety factor ``SF = S_MBS / T_C`` (Wang (2016) eq. 3.3) is what MIMOSA prints in
figure 5.9 (e.g. line 7: 8500 kN / 4762.9 kN = 1.78).

Characteristic tensions from time-domain seeds follow Wang (2016) section 5.4.4: the 3-hour
maxima of the seeds are fitted with a Gumbel distribution and its 90 % fractile is the
characteristic tension ``T_C``; ``T_C-mean`` is the mean tension (averaged over the seeds) and
``T_C-dyn = T_C - T_C-mean``.  The fractile is a parameter (``p``; ``p = 1/e`` is the most
probable maximum).

The clause lettering inside Ch.2 Sec.2 is not repeated here because it was not verified against
the text of the 2008 edition; the factors were checked against Wang's (2016) tables.

Design codes as data
--------------------
The factors live in the code file ``floatmoor/data/codes/dnv-os-e301-2008.yaml``
(:mod:`floatmoor.post.design_codes`), each with its source and whether it was verified; the
constants below are read from it.  Every function here takes ``code=`` (a key such as
``api-rp-2sk-2005`` or ``dnv-st-0119-2021``, a code file, or a
:class:`~floatmoor.post.design_codes.DesignCode`) to check with another code's factors; the
default is DNV-OS-E301 (2008).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import xarray as xr

from ..core.errors import SceneError, argument_error
from ..mooring.line_types import MBS_UNKNOWN
from .design_codes import DEFAULT_CODE, load_code, normalise_analysis
from .extremes import gumbel_fit

__all__ = [
    "STANDARD", "EDITION", "SOURCE", "ULS_FACTORS", "ALS_FACTORS", "COMMON_FACTOR",
    "COMMON_FACTOR_RATIO", "STRENGTH_FACTOR", "SPM_FACTOR", "PartialFactors", "partial_factors",
    "characteristic_strength", "design_tension", "simple_safety_factor", "line_check",
    "check_lines", "characteristic_tensions", "factors_table", "require_known_mbs",
]

STANDARD = "DNV-OS-E301"
EDITION = "DNV-OS-E301 Position Mooring, October 2008"
SOURCE = (
    "DNV-OS-E301 Position Mooring, October 2008 edition, Ch.2 Sec.2 (characteristic capacity "
    "S_C = 0.95 S_mbs; partial safety factors for ULS and ALS), as reproduced in "
    "Wang (2016) eq. 3.4, tables 3.1 and 3.2 and the remarks under "
    "table 3.1; Wang's (2016) practice for the characteristic tension is the 90 % Gumbel "
    "fractile of the 3-hour maxima of 20 seeds (section 5.4.4)")
"""A sentence a report can print: where the factors and the method come from."""

ANALYSES = ("dynamic", "quasi-static")
LIMIT_STATES = ("ULS", "ALS")

_CODE = load_code(DEFAULT_CODE)


def _table(ls):
    return {(r["consequence_class"], r["analysis"]): (r["gamma_mean"], r["gamma_dyn"])
            for r in _CODE.factors_table() if r["limit_state"] == ls}


# (consequence class, analysis of WF tension) -> (gamma_mean, gamma_dyn)
ULS_FACTORS = _table("ULS")
"""Wang (2016) table 3.1 (DNV-OS-E301 2008, ULS), read from the code file."""

ALS_FACTORS = _table("ALS")
"""Wang (2016) table 3.2 (DNV-OS-E301 2008, ALS), read from the code file."""

COMMON_FACTOR = float(_CODE.tree["line_tension"]["common_factor"]["value"])
"""Common ULS factor for consequence class 1, dynamic analysis, when T_C-mean > 2/3 T_C-dyn."""
COMMON_FACTOR_RATIO = float(_CODE.tree["line_tension"]["common_factor"]["ratio"])
STRENGTH_FACTOR = _CODE.strength_factor
"""S_C = 0.95 S_mbs."""
SPM_FACTOR = float(_CODE.tree["line_tension"]["single_point_mooring_factor"]["value"])
"""Increase of the ULS factors for single point moorings without redundancy."""


@dataclass(frozen=True, kw_only=True)
class PartialFactors:
    """Partial safety factors of one limit state, consequence class and analysis type.

    Attributes
    ----------
    limit_state : str
        ``"ULS"`` or ``"ALS"``.
    consequence_class : int
        1 or 2 (any integer for a code without classes: not used).
    analysis : str
        ``"dynamic"`` or ``"quasi-static"`` (analysis of the WF tension).
    gamma_mean, gamma_dyn : float
        Factors on the characteristic mean and dynamic tension (table values, before the
        common-factor remark, which depends on the tensions).
    single_point_mooring : bool
        Whether the 1.2 increase for single point moorings without redundancy is included.
    code : str
        Key of the design code (``dnv-os-e301-2008``).
    code_name : str
        Its name and edition.
    table_source : str
        The source of the factors as the code file gives it.
    common_factor, common_factor_ratio : float or None
        The code's common factor and its T_C-mean / T_C-dyn threshold (None: the code has none).
    verified : bool
        Whether the code file marks the factors as verified against a text of the standard.
    """

    limit_state: str
    consequence_class: int
    analysis: str
    gamma_mean: float
    gamma_dyn: float
    single_point_mooring: bool = False
    code: str = DEFAULT_CODE
    code_name: str = _CODE.name
    table_source: str = ""
    common_factor: float | None = COMMON_FACTOR
    common_factor_ratio: float | None = COMMON_FACTOR_RATIO
    verified: bool = True

    @property
    def source(self) -> str:
        if self.code == DEFAULT_CODE:
            table = "3.1 (ULS)" if self.limit_state == "ULS" else "3.2 (ALS)"
            text = f"{EDITION}, Ch.2 Sec.2; Wang (2016) table {table}"
        else:
            text = f"{self.code_name}: {self.table_source}"
            if not self.verified:
                text += " (UNVERIFIED)"
        if self.single_point_mooring:
            text += ", increased by 1.2 for a single point mooring (remark under table 3.1)"
        return text

    @property
    def common_factor_possible(self) -> bool:
        """Whether the common factor 1.3 of the remark under table 3.1 can apply.

        Not combined with the single-point-mooring increase: Wang (2016) does not say how the two
        remarks combine, so a single point mooring keeps its 1.2 x table factors.
        """
        return (self.common_factor is not None and self.limit_state == "ULS"
                and self.consequence_class == 1 and self.analysis == "dynamic"
                and not self.single_point_mooring)


def partial_factors(limit_state: str = "ULS", consequence_class: int = 2,
                    analysis: str = "dynamic", *, single_point_mooring: bool = False,
                    code=None) -> PartialFactors:
    """Partial safety factors from the design code (default DNV-OS-E301 (2008): Wang (2016)
    tables 3.1 (ULS) and 3.2 (ALS)).

    Parameters
    ----------
    limit_state : str
        ``"ULS"`` or ``"ALS"`` (case-insensitive).
    consequence_class : int
        1 or 2.
    analysis : str
        ``"dynamic"`` or ``"quasi-static"`` (type of analysis of the WF tension).
    single_point_mooring : bool
        Single point mooring without redundancy: ULS factors x 1.2, ALS not applicable.
    code : str, path or DesignCode, optional
        The design code (:func:`floatmoor.post.design_codes.load_code`).

    Returns
    -------
    PartialFactors
    """
    c = load_code(DEFAULT_CODE if code is None else code)
    if str(limit_state).upper() not in LIMIT_STATES:
        raise argument_error("limit_state", "one of: ULS, ALS", limit_state)
    if c.has_classes and (isinstance(consequence_class, bool)
                          or consequence_class not in c.consequence_classes):
        raise argument_error("consequence_class",
                             f"{' or '.join(map(str, c.consequence_classes))} ({c.code} "
                             "ULS/ALS consequence classes)", consequence_class)
    normalise_analysis(analysis)
    f = c.line_factors(limit_state, consequence_class, analysis,
                       single_point_mooring=single_point_mooring)
    return PartialFactors(limit_state=f.limit_state, consequence_class=f.consequence_class,
                          analysis=f.analysis, gamma_mean=f.gamma_mean, gamma_dyn=f.gamma_dyn,
                          single_point_mooring=f.single_point_mooring, code=c.key,
                          code_name=c.name, table_source=f.entry.source,
                          common_factor=f.common_factor,
                          common_factor_ratio=f.common_factor_ratio,
                          verified=f.entry.verified)


def characteristic_strength(mbs, strength_factor: float = STRENGTH_FACTOR):
    """Characteristic strength ``S_C = 0.95 S_mbs`` of the main body of a line.

    Parameters
    ----------
    mbs : float or array_like
        Minimum breaking strength in N.
    strength_factor : float
        0.95 by DNV-OS-E301 (chain, steel wire rope; fibre rope without further test data).

    Returns
    -------
    float or numpy.ndarray
        S_C in N.
    """
    s = np.asarray(mbs, dtype=float)
    if np.any(np.isnan(s)) or np.any(s >= MBS_UNKNOWN):
        raise argument_error("mbs", "a known minimum breaking strength in N", "unknown",
                             "a line type without MBS (mbs: unknown, e.g. an imported MoorDyn "
                             "or MAP++ file): set its mbs before any design check")
    if np.any(~np.isfinite(s)) or np.any(s <= 0):
        raise argument_error("mbs", "a minimum breaking strength > 0 in N", mbs)
    if not (0 < strength_factor <= 1):
        raise argument_error("strength_factor", "a factor in (0, 1]", strength_factor)
    out = strength_factor * s
    return float(out) if out.ndim == 0 else out


def design_tension(t_mean, t_dyn, factors: PartialFactors, *,
                   common_factor_rule: str = "as_written"):
    """Design tension ``T_C-mean gamma_mean + T_C-dyn gamma_dyn`` with the common-factor remark.

    Parameters
    ----------
    t_mean, t_dyn : float or array_like
        Characteristic mean and dynamic tension in N.
    factors : PartialFactors
        From :func:`partial_factors`.
    common_factor_rule : str
        ``"as_written"``: where ``t_mean > 2/3 t_dyn`` in ULS, consequence class 1, dynamic
        analysis, use 1.3 on both components instead of the table factors.
        ``"conservative"``: there, the larger of the two design tensions.

    Returns
    -------
    dict
        ``design_tension`` (N), ``gamma_mean``, ``gamma_dyn`` (the factors used) and
        ``common_factor_applied`` (bool), arrays of the broadcast shape.
    """
    if common_factor_rule not in ("as_written", "conservative"):
        raise argument_error("common_factor_rule",
                             "'as_written' or 'conservative'", common_factor_rule)
    tm = np.asarray(t_mean, dtype=float)
    td = np.asarray(t_dyn, dtype=float)
    tm, td = np.broadcast_arrays(tm, td)
    gm = np.full(tm.shape, factors.gamma_mean)
    gd = np.full(tm.shape, factors.gamma_dyn)
    applied = np.zeros(tm.shape, bool)
    if factors.common_factor_possible:
        cf, ratio = factors.common_factor, factors.common_factor_ratio
        applied = tm > ratio * td
        if common_factor_rule == "conservative":
            common = cf * (tm + td)
            table = factors.gamma_mean * tm + factors.gamma_dyn * td
            applied &= common > table
        gm = np.where(applied, cf, gm)
        gd = np.where(applied, cf, gd)
    return {"design_tension": gm * tm + gd * td, "gamma_mean": gm, "gamma_dyn": gd,
            "common_factor_applied": applied}


def simple_safety_factor(mbs, t_max):
    """Simple safety factor ``S_MBS / T_max`` (Wang (2016) eq. 3.3, MIMOSA's column in figure 5.9).

    Parameters
    ----------
    mbs : float or array_like
        Minimum breaking strength (any force unit).
    t_max : float or array_like
        Maximum (characteristic) tension in the same unit.
    """
    m = np.asarray(mbs, dtype=float)
    t = np.asarray(t_max, dtype=float)
    if np.any(~np.isfinite(t)) or np.any(t <= 0):
        raise argument_error("t_max", "a maximum tension > 0", t_max)
    if np.any(~np.isfinite(m)) or np.any(m <= 0):
        raise argument_error("mbs", "a minimum breaking strength > 0", mbs)
    out = m / t
    return float(out) if out.ndim == 0 else out


def require_known_mbs(mbs, lines, *, file=None, key: str = "mbs", detail: str = "",
                      purpose: str = "the DNV-OS-E301 design check") -> None:
    """SceneError when the MBS of a line is unknown (nan, or the old import placeholder
    ``MBS_UNKNOWN``): ``detail`` says which line types, from where and what to set (the
    ``unknown`` attribute of an ``mbs`` result variable,
    :meth:`floatmoor.mooring.system.MooringSystem.unknown_mbs`)."""
    lines = [str(x) for x in lines]
    m = np.broadcast_to(np.asarray(mbs, dtype=float), (len(lines),))
    bad = [ln for ln, v in zip(lines, m) if np.isnan(v) or v >= MBS_UNKNOWN]
    if bad:
        raise SceneError(file, key, f"a known minimum breaking strength (MBS) of every line, "
                         f"needed by {purpose}", f"unknown for line(s) {', '.join(bad)}",
                         detail or "set the mbs (N) of their line types in the mooring file "
                         "(types imported from MoorDyn or MAP++ files carry mbs: unknown)")


def line_check(t_mean, t_max, mbs, *, limit_state: str = "ULS", consequence_class: int = 2,
               analysis: str = "dynamic", strength_factor: float | None = None,
               single_point_mooring: bool = False, common_factor_rule: str = "as_written",
               code=None, eol_mbs=None) -> dict:
    """ULS or ALS check of one or more lines (arrays broadcast).

    Parameters
    ----------
    t_mean : float or array_like
        Characteristic mean tension T_C-mean in N.
    t_max : float or array_like
        Characteristic (maximum) tension T_C in N; T_C-dyn = T_C - T_C-mean.
    mbs : float or array_like
        Minimum breaking strength S_mbs in N (of the new line).
    limit_state, consequence_class, analysis, single_point_mooring, code
        See :func:`partial_factors`.
    strength_factor : float, optional
        S_C / S_mbs (default: the code's, 0.95 in DNV-OS-E301).
    common_factor_rule : str
        See :func:`design_tension`.
    eol_mbs : float or array_like, optional
        The MBS at the end of the design life (corroded; :mod:`floatmoor.post.capacity`): when
        given, S_C and the utilisation are on it, and ``s_c_new``, ``utilisation_new`` give the
        check with the new line.

    Returns
    -------
    dict
        ``t_c_mean``, ``t_c_dyn``, ``t_c``, ``s_mbs``, ``s_c`` (N), ``gamma_mean``,
        ``gamma_dyn``, ``common_factor_applied``, ``design_tension`` (N), ``margin``
        (``S_C - design tension``, eq. 3.4, N), ``utilisation`` (design tension / S_C),
        ``passed`` (eq. 3.4 satisfied), ``safety_factor`` (S_mbs / T_C), ``s_c_new``,
        ``utilisation_new``, and ``factors``.
    """
    c = load_code(DEFAULT_CODE if code is None else code)
    f = partial_factors(limit_state, consequence_class, analysis,
                        single_point_mooring=single_point_mooring, code=c)
    sf = c.strength_factor if strength_factor is None else strength_factor
    tm = np.asarray(t_mean, dtype=float)
    tc = np.asarray(t_max, dtype=float)
    if np.any(~np.isfinite(tm)) or np.any(tm < 0):
        raise argument_error("t_mean", "characteristic mean tensions >= 0 in N", t_mean)
    if np.any(~np.isfinite(tc)):
        raise argument_error("t_max", "finite characteristic tensions in N", t_max)
    if np.any(tc < tm):
        raise argument_error("t_max", "characteristic tensions >= the mean tensions", t_max)
    sc_new = np.asarray(characteristic_strength(mbs, sf))
    if eol_mbs is None:
        sc = sc_new
    else:
        e = np.asarray(eol_mbs, float)
        if np.any(~np.isfinite(e)) or np.any(e <= 0) or np.any(e > np.asarray(mbs, float)):
            raise argument_error("eol_mbs", "end-of-life MBS > 0 and at most the new MBS",
                                 eol_mbs)
        sc = np.asarray(characteristic_strength(e, sf))
    td = tc - tm
    d = design_tension(tm, td, f, common_factor_rule=common_factor_rule)
    tm, td, tc, smbs, sc, sc_new = np.broadcast_arrays(tm, td, tc, np.asarray(mbs, float), sc,
                                                       sc_new)
    u = d["design_tension"] / sc
    return {"t_c_mean": tm, "t_c_dyn": td, "t_c": tc, "s_mbs": smbs, "s_c": sc,
            "gamma_mean": d["gamma_mean"], "gamma_dyn": d["gamma_dyn"],
            "common_factor_applied": d["common_factor_applied"],
            "design_tension": d["design_tension"], "margin": sc - d["design_tension"],
            "utilisation": u, "passed": u <= 1.0,
            "safety_factor": smbs / tc, "s_c_new": sc_new,
            "utilisation_new": d["design_tension"] / sc_new, "factors": f}


_COLUMNS = {
    "t_c_mean": ("N", "characteristic mean tension T_C-mean"),
    "t_c_dyn": ("N", "characteristic dynamic tension T_C-dyn = T_C - T_C-mean"),
    "t_c": ("N", "characteristic tension T_C"),
    "s_mbs": ("N", "minimum breaking strength S_mbs"),
    "s_c": ("N", "characteristic strength S_C (at the end of the design life when a "
                 "corrosion allowance applies)"),
    "s_c_new": ("N", "characteristic strength S_C of the new line"),
    "gamma_mean": ("1", "partial safety factor on T_C-mean"),
    "gamma_dyn": ("1", "partial safety factor on T_C-dyn"),
    "common_factor_applied": ("1", "common factor 1.3 applied (remark under table 3.1)"),
    "design_tension": ("N", "design tension T_C-mean gamma_mean + T_C-dyn gamma_dyn"),
    "margin": ("N", "S_C - design tension (eq. 3.4, >= 0 required)"),
    "utilisation": ("1", "utilisation, design tension / S_C"),
    "utilisation_new": ("1", "utilisation of the new line, design tension / S_C new"),
    "passed": ("1", "design equation satisfied"),
    "checked": ("1", "line checked in this limit state (false: failed or not analysed)"),
    "safety_factor": ("1", "simple safety factor S_mbs / T_C"),
    "governing": ("1", "governing line of the limit state (largest utilisation)"),
}


def _per_line(value, nl, key):
    """A per-line array of analysis names from one name or a sequence."""
    if isinstance(value, str):
        return [normalise_analysis(value, key)] * nl
    vals = [normalise_analysis(v, key) for v in value]
    if len(vals) != nl:
        raise argument_error(key, f"one analysis type, or {nl} (one per line)", value)
    return vals


def check_lines(lines, mbs, *, uls_mean, uls_max, als_mean=None, als_max=None,
                consequence_class: int = 2, analysis="dynamic",
                strength_factor: float | None = None, single_point_mooring: bool = False,
                common_factor_rule: str = "as_written", code=None, eol_mbs=None) -> xr.Dataset:
    """ULS (and ALS) design check of every line, with the governing line.

    Parameters
    ----------
    lines : sequence
        Line names or numbers (the ``line`` coordinate).
    mbs : float or array_like
        Minimum breaking strength per line in N (scalar: same for all).
    uls_mean, uls_max : array_like
        Characteristic mean tension and characteristic tension per line, intact system, in N.
    als_mean, als_max : array_like, optional
        The same with one line failed (worst over the failure cases analysed).  NaN marks a line
        not checked (e.g. the failed line itself).
    consequence_class, strength_factor, single_point_mooring, common_factor_rule, code
        See :func:`line_check`.
    analysis : str or sequence of str
        The analysis type of the WF tension, one for all lines or one per line (e.g.
        finite-element lines dynamic and quasi-static lines quasi-static).
    eol_mbs : float or array_like, optional
        End-of-life MBS per line (see :func:`line_check`).

    Returns
    -------
    xarray.Dataset
        Dims ``(limit_state, line)``; every column of :func:`line_check` plus ``checked`` and
        ``governing``, each with ``units`` and ``long_name``; ``governing_line(limit_state)``,
        ``analysis(line)``; attributes ``standard``, ``code``, ``edition``, ``source``,
        ``consequence_class``, ``analysis``, ``governing_line``, ``governing_limit_state``,
        ``max_utilisation`` and ``all_passed``.
    """
    c = load_code(DEFAULT_CODE if code is None else code)
    lines = list(lines)
    nl = len(lines)
    if nl == 0:
        raise argument_error("lines", "at least one line", lines)
    if len(set(map(str, lines))) != nl:
        raise argument_error("lines", "distinct line names", lines)
    analyses = _per_line(analysis, nl, "analysis")
    cases = [("ULS", uls_mean, uls_max)]
    if (als_mean is None) != (als_max is None):
        raise argument_error("als_max" if als_max is None else "als_mean",
                             "both ALS mean and ALS characteristic tensions, or neither", None)
    if als_mean is not None:
        cases.append(("ALS", als_mean, als_max))
    mbs_arr = np.broadcast_to(np.asarray(mbs, dtype=float), (nl,))
    require_known_mbs(mbs_arr, lines)
    eol = None if eol_mbs is None else np.broadcast_to(np.asarray(eol_mbs, float), (nl,))
    columns = {k: [] for k in _COLUMNS if k != "governing"}
    sources = []
    for ls, tm, tc in cases:
        tm = np.asarray(tm, dtype=float)
        tc = np.asarray(tc, dtype=float)
        for key, arr in (("mean", tm), ("max", tc)):
            if arr.shape != (nl,):
                raise argument_error(f"{ls.lower()}_{key}", f"{nl} values (one per line)",
                                     f"shape {arr.shape}")
        checked = np.isfinite(tm) & np.isfinite(tc)
        if ls == "ULS" and not checked.all():
            raise argument_error("uls_max",
                                 "finite ULS tensions for every line (the intact system)",
                                 "NaN")
        r = {}
        for an in dict.fromkeys(analyses):
            sel = np.array([a == an for a in analyses])
            part = line_check(np.where(checked, tm, 0.0)[sel], np.where(checked, tc, 1.0)[sel],
                              mbs_arr[sel], limit_state=ls,
                              consequence_class=consequence_class, analysis=an,
                              strength_factor=strength_factor,
                              single_point_mooring=single_point_mooring,
                              common_factor_rule=common_factor_rule, code=c,
                              eol_mbs=None if eol is None else eol[sel])
            src = part.pop("factors").source
            if src not in sources:
                sources.append(src)
            for k, v in part.items():
                v = np.asarray(v)
                if k not in r:
                    r[k] = np.zeros(nl, dtype=v.dtype)
                r[k][sel] = v
        for k in columns:
            if k == "checked":
                columns[k].append(checked)
                continue
            v = np.asarray(r[k])
            if v.dtype == bool:
                v = v & checked
            elif k not in ("s_mbs", "s_c", "s_c_new"):
                v = np.where(checked, v, np.nan)
            columns[k].append(v)
    states = [cs[0] for cs in cases]
    ds = xr.Dataset(coords={"limit_state": ("limit_state", states), "line": ("line", lines)})
    for k, vals in columns.items():
        unit, long = _COLUMNS[k]
        ds[k] = xr.DataArray(np.stack(vals), dims=("limit_state", "line"),
                             attrs={"units": unit, "long_name": long})
    ds["analysis"] = xr.DataArray(np.array(analyses, dtype=object), dims=("line",),
                                  attrs={"units": "", "long_name": "analysis type of the WF tension "
                                         "(selects the partial safety factors)"})
    u = ds["utilisation"].values
    gov = np.zeros(u.shape, bool)
    gov_names = []
    for i in range(len(states)):
        if np.any(np.isfinite(u[i])):
            j = int(np.nanargmax(u[i]))
            gov[i, j] = True
            gov_names.append(str(lines[j]))
        else:
            gov_names.append("")
    ds["governing"] = xr.DataArray(gov, dims=("limit_state", "line"),
                                   attrs={"units": "1", "long_name": _COLUMNS["governing"][1]})
    ds["governing_line"] = xr.DataArray(np.array(gov_names, dtype=object), dims=("limit_state",),
                                        attrs={"long_name": "governing line per limit state"})
    i, j = np.unravel_index(np.nanargmax(u), u.shape)
    distinct = list(dict.fromkeys(analyses))
    ds.attrs.update({
        "standard": c.code, "code": c.key, "edition": c.name,
        "source": SOURCE if c.key == DEFAULT_CODE else c.name,
        "factor_sources": " | ".join(sources),
        "consequence_class": int(consequence_class),
        "analysis": distinct[0] if len(distinct) == 1 else "per line: " + ", ".join(
            f"{ln} {an}" for ln, an in zip(map(str, lines), analyses)),
        "strength_factor": float(c.strength_factor if strength_factor is None
                                 else strength_factor),
        "common_factor_rule": common_factor_rule,
        "single_point_mooring": int(bool(single_point_mooring)),
        "end_of_life_capacity": int(eol is not None),
        "governing_line": str(lines[j]), "governing_limit_state": states[i],
        "max_utilisation": float(u[i, j]),
        "all_passed": int(bool(np.all(ds["passed"].values | ~ds["checked"].values))),
    })
    return ds


def characteristic_tensions(seed_max, seed_mean, *, p: float = 0.9, method: str = "mle"
                            ) -> xr.Dataset:
    """Characteristic tensions per line from time-domain seeds (Wang (2016) section 5.4.4).

    Parameters
    ----------
    seed_max : xarray.DataArray
        Per-seed maximum tension, dims ``(seed, line)``, in N (e.g. ``line_tension_max`` of
        :func:`~floatmoor.post.per_seed_statistics`).
    seed_mean : xarray.DataArray
        Per-seed mean tension, dims ``(seed, line)``, in N.
    p : float
        Gumbel fractile taken as the characteristic tension (0.9 as Wang (2016); ``1/e`` for
        the most probable maximum).
    method : str
        Gumbel fit method, ``"mle"`` or ``"moments"``.

    Returns
    -------
    xarray.Dataset
        Per line: ``t_c_mean`` (mean over seeds), ``t_c`` (Gumbel fractile p), ``t_c_dyn``,
        ``gumbel_loc``, ``gumbel_scale``, ``gumbel_mpm``, ``gumbel_p90``, ``t_c_se``
        (asymptotic standard error of t_c), ``max_observed``, in N.
    """
    for key, da in (("seed_max", seed_max), ("seed_mean", seed_mean)):
        if not isinstance(da, xr.DataArray) or set(da.dims) != {"seed", "line"}:
            raise argument_error(key, "a DataArray with dims (seed, line)",
                                 getattr(da, "dims", type(da).__name__))
    seed_max = seed_max.transpose("seed", "line")
    seed_mean = seed_mean.transpose("seed", "line")
    lines = seed_max["line"].values if "line" in seed_max.coords else np.arange(seed_max.shape[1])
    out = {k: [] for k in ("t_c_mean", "t_c", "gumbel_loc", "gumbel_scale", "gumbel_mpm",
                           "gumbel_p90", "t_c_se", "max_observed")}
    for j in range(seed_max.shape[1]):
        fit = gumbel_fit(seed_max.values[:, j], method=method)
        out["t_c_mean"].append(float(np.mean(seed_mean.values[:, j])))
        out["t_c"].append(float(fit.fractile(p)))
        out["gumbel_loc"].append(fit.loc)
        out["gumbel_scale"].append(fit.scale)
        out["gumbel_mpm"].append(fit.mpm)
        out["gumbel_p90"].append(fit.p90)
        out["t_c_se"].append(float(fit.fractile_se(p)))
        out["max_observed"].append(float(np.max(seed_max.values[:, j])))
    unit = str(seed_max.attrs.get("units", "N"))
    longs = {
        "t_c_mean": "characteristic mean tension (mean over seeds)",
        "t_c": f"characteristic tension (Gumbel {p:.3g} fractile of seed maxima)",
        "t_c_dyn": "characteristic dynamic tension T_C - T_C-mean",
        "gumbel_loc": "Gumbel location of seed maxima",
        "gumbel_scale": "Gumbel scale of seed maxima",
        "gumbel_mpm": "Gumbel most probable maximum",
        "gumbel_p90": "Gumbel 90 % fractile of seed maxima",
        "t_c_se": "asymptotic standard error of the characteristic tension",
        "max_observed": "largest observed seed maximum",
    }
    ds = xr.Dataset(coords={"line": ("line", lines)})
    for k, v in out.items():
        ds[k] = xr.DataArray(np.asarray(v), dims=("line",),
                             attrs={"units": unit, "long_name": longs[k]})
    ds["t_c_dyn"] = xr.DataArray(ds["t_c"].values - ds["t_c_mean"].values, dims=("line",),
                                 attrs={"units": unit, "long_name": longs["t_c_dyn"]})
    ds.attrs.update({"fractile": float(p), "gumbel_method": method,
                     "n_seeds": int(seed_max.shape[0]), "source": SOURCE})
    return ds


def factors_table(code=None) -> list[dict]:
    """All table factors as rows (limit state, class, analysis, gamma_mean, gamma_dyn) for a
    report."""
    return load_code(DEFAULT_CODE if code is None else code).factors_table()

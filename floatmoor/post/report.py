"""Design report from time-domain seeds: the verdict over every limit state, as self-contained
HTML, Markdown, CSV and netCDF.

:func:`build_report` takes the per-seed result Datasets of one sea state (the simulator's format:
``motion(time, dof)`` in m / rad, ``line_tension(time, line)`` and ``anchor_tension(time,
line)`` in N, attributes ``seed``, ``scene_name``, ``scene`` (YAML), ``transient``) and writes

* ``report.html`` -- opens in a browser with no network: CSS inline, plots as base64 PNG;
* ``report.md`` -- the same tables in Markdown (plots as separate PNG files beside it);
* ``summary.csv`` -- one row per line and limit state;
* ``summary.nc`` -- the per-line check Dataset, the statistics and the other checks.

The first screen of the HTML is the answer: the verdict per limit state and check (ULS and ALS
line tension, FLS fatigue, anchor uplift and anchor load, offsets and points, fibre ropes), the
governing line with its characteristic tension, design tension and capacity (new and end of
life), the environment, the line model and the analysis type with the reason, the design code
and edition (and every unverified value of it that was used), and what the scene leaves out
that could matter.  The detail follows: per-line tables, capacity per segment, anchors, offsets,
fibre ropes, FLS, motions, the frequency domain, plots and the run's details.

Method (Wang (2016) section 5.4.4 and chapter 3): per seed, statistics in the window (default:
from the results' ``transient`` attribute); per line, a Gumbel fit of the seed maxima; the
characteristic tension is its 90 % fractile; the design check is the design equation of the
code (:mod:`floatmoor.post.design_codes`; DNV-OS-E301 (2008) by default, Wang (2016) eq. 3.4)
with the partial factors of :mod:`floatmoor.post.dnv_os_e301`.

Analysis type (which partial factors): it follows the line model of the results (``line_model``
of the seeds, :func:`resolve_analysis`): finite-element lines get the dynamic-analysis factors,
quasi-static lines the quasi-static ones, unless a dynamic amplification factor (DAF) of
``floatmoor lines`` is given for the line, which multiplies its characteristic dynamic tension
(a DAF below 1 is taken as 1) and gives it the dynamic factors.  ``analysis="dynamic"`` or
``"quasi-static"`` overrides this for every line; the report says so.

Plots need matplotlib (optional); without it the report has tables only and says so.
"""

from __future__ import annotations

import base64
import datetime as _dt
import html
from collections.abc import Sequence
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
import xarray as xr

from ..core.errors import argument_error
from . import dnv_os_e301 as dnv
from . import verdict as vd
from .design_codes import DEFAULT_CODE, load_code
from .report_tables import CSS as _CSS
from .report_tables import KN as _KN
from .report_tables import Table as _Table
from .report_tables import (
    anchor_table,
    capacity_table,
    check_fd,
    code_values_table,
    fd_lines_table,
    fd_offsets_table,
    fibre_table,
    line_key,
    line_label,
    line_table,
    motion_table,
    offset_tables,
)
from .report_tables import fmt as _fmt
from .report_tables import plots as make_plots
from .timeseries import DEFAULT_CUTOFF_HZ, per_seed_statistics

__all__ = ["ReportContext", "ReportFiles", "build_report", "resolve_analysis", "summarise"]

_line_key = line_key          # names used by other modules before the split
_ = (_CSS, _Table, _fmt)


@dataclass(frozen=True)
class ReportContext:
    """What the report takes from the scene (:func:`floatmoor.io.report_context.scene_context`):
    ``environment`` rows (label, text), ``omissions`` (what the scene leaves out that could
    matter), ``notes`` (e.g. whether the scene changed since the run), the ``mooring``
    (:class:`~floatmoor.mooring.system.MooringSystem`), its ``design`` keys
    (:class:`~floatmoor.io.mooring_design.MooringDesign`) and the ``limits``
    (:class:`~floatmoor.io.limits_section.LimitsSpec`).  Everything is optional: without a
    mooring the end-of-life capacity, anchor and fibre checks are not made (and the verdict
    says so)."""

    scene_file: str = ""
    environment: tuple = ()
    omissions: tuple = ()
    notes: tuple = ()
    mooring: object = None
    design: object = None
    limits: object = None


@dataclass(frozen=True)
class ReportFiles:
    """Paths written by :func:`build_report`, the summary Datasets and the verdict."""

    html: Path
    markdown: Path
    csv: Path
    netcdf: Path
    checks: xr.Dataset
    statistics: xr.Dataset
    characteristic: xr.Dataset
    verdict: tuple = ()
    overall: tuple = ("", "")
    capacities: xr.Dataset | None = None
    anchors: dict = field(default_factory=dict)
    offsets: dict = field(default_factory=dict)
    fibre: dict = field(default_factory=dict)
    fls: xr.Dataset | None = None
    code: object = None
    unverified: tuple = ()


def _version() -> str:
    try:
        from .. import __version__
        return str(__version__)
    except Exception:  # pragma: no cover
        return "unknown"


def _check_results(results, key):
    results = list(results)
    if not results:
        raise argument_error(key, "at least one per-seed result Dataset", "none")
    for i, ds in enumerate(results):
        if not isinstance(ds, xr.Dataset):
            raise argument_error(f"{key}[{i}]", "an xarray Dataset", type(ds).__name__)
        if "line_tension" not in ds:
            raise argument_error(f"{key}[{i}]", "a 'line_tension(time, line)' variable",
                                 list(map(str, ds.data_vars)))
        unit = ds["line_tension"].attrs.get("units", "N")
        if unit != "N":
            raise argument_error(f"{key}[{i}].line_tension.units", "'N'", unit)
    if len(results) < 3:
        raise argument_error(key, "results of at least 3 seeds for a Gumbel fit "
                                  "(Wang (2016) uses 20)",
                             len(results))
    return results


def transient_of(results) -> float | None:
    """Start of the statistics window from the results' ``transient`` attribute (s): the largest
    over the seeds, None when no result has one."""
    vals = [float(ds.attrs["transient"]) for ds in results if "transient" in ds.attrs]
    return max(vals) if vals else None


def detect_failed_lines(results) -> list:
    """Lines failed in every one of ``results``: tension exactly zero at the last sample.

    A line removed from the start (mooring ``failed_lines``) has zero tension throughout; one
    broken during the run (``forces.line_failure``) is zero from the failure on.  A line of an
    intact mooring never reaches exactly zero at the fairlead (it carries its own weight).
    """
    dead = None
    for ds in results:
        last = np.asarray(ds["line_tension"].isel(time=-1).values) <= 0.0
        dead = last if dead is None else dead & last
    return [ln for ln, d in zip(results[0]["line"].values, dead) if d]


def scene_name(ds: xr.Dataset) -> str:
    """Short scene name of a result: ``scene_name`` attribute, else the ``scene`` attribute when
    it is one line, else "unnamed scene"."""
    if ds.attrs.get("scene_name"):
        return str(ds.attrs["scene_name"])
    sc = str(ds.attrs.get("scene", "")).strip()
    return sc if sc and "\n" not in sc else "unnamed scene"


def _prepared(ds: xr.Dataset) -> xr.Dataset:
    """Add the horizontal offset ``offset = hypot(surge, sway)`` (m) when ``motion`` has them."""
    if "motion" in ds and "dof" in ds["motion"].dims and "offset" not in ds:
        dofs = [str(d) for d in ds["dof"].values]
        if "surge" in dofs and "sway" in dofs:
            m = ds["motion"]
            off = np.hypot(m.isel(dof=dofs.index("surge")).values,
                           m.isel(dof=dofs.index("sway")).values)
            ds = ds.assign(offset=(m.isel(dof=0).dims, off,
                                   {"units": "m", "long_name": "horizontal offset"}))
    return ds


def _variables(ds: xr.Dataset) -> list[str]:
    return [v for v in ("motion", "offset", "line_tension") if v in ds]


# -- analysis type -------------------------------------------------------------------------------
def line_models(results) -> list[str]:
    """``"finite-element"`` or ``"quasi-static"`` per line: the results' ``line_model``
    variable, else their ``fe_lines`` attribute, else quasi-static (a result that does not say
    is taken for quasi-static lines: the larger factors)."""
    ds = results[0]
    names = [str(v) for v in ds["line"].values]
    if "line_model" in ds:
        return [str(v) for v in np.asarray(ds["line_model"].values).astype(str)]
    fe = {str(v) for v in np.atleast_1d(ds.attrs.get("fe_lines", []))}
    return ["finite-element" if n in fe else "quasi-static" for n in names]


def resolve_analysis(models, analysis="auto", daf=None, code=None) -> dict:
    """The analysis type (partial factors) of every line and why.

    Parameters
    ----------
    models : per-line line models (:func:`line_models`).
    analysis : ``"auto"`` (follow the line model), ``"dynamic"`` or ``"quasi-static"``
        (override for every line).
    daf : mapping line index -> DAF of ``floatmoor lines`` (None: none given).
    code : the design code (its analyses: DNV-ST-0119 has no quasi-static factors).

    Returns
    -------
    dict
        ``analyses`` (per line), ``daf_measured`` and ``daf_applied`` (per line, NaN where not
        applied; the applied one is at least 1), ``override`` (bool), ``reason`` (text),
        ``summary`` (the analysis in a few words).
    """
    c = load_code(DEFAULT_CODE if code is None else code)
    n = len(models)
    measured = np.full(n, np.nan)
    for j, v in (daf or {}).items():
        measured[j] = v
    applied = np.full(n, np.nan)
    fe = np.array([m == "finite-element" for m in models])
    has_daf = np.isfinite(measured)
    an = str(analysis).lower().replace("_", "-")
    if an in ("quasistatic",):
        an = "quasi-static"
    if an not in ("auto", "dynamic", "quasi-static"):
        raise argument_error("analysis", "auto, dynamic or quasi-static", analysis)
    qs_daf = ~fe & has_daf
    n_fe, n_qs = int(fe.sum()), int((~fe).sum())
    auto = ["dynamic" if (f or d) else "quasi-static" for f, d in zip(fe, qs_daf)]
    parts = []
    if n_fe:
        parts.append(f"{n_fe} finite-element line(s): the line dynamics are in the tension "
                     "(dynamic-analysis factors)")
    if qs_daf.any():
        parts.append(f"{int(qs_daf.sum())} quasi-static line(s) with the dynamic "
                     "amplification factor of floatmoor lines on T_C-dyn (a DAF below 1 "
                     "taken as 1; dynamic-analysis factors)")
    rest = ~fe & ~qs_daf
    if rest.any():
        parts.append(f"{int(rest.sum())} quasi-static line(s): no line dynamics in the "
                     "tension (quasi-static-analysis factors; finite-element lines or "
                     "floatmoor report --daf give the dynamic ones)")
    auto_reason = "; ".join(parts)
    if an == "auto":
        analyses = auto
        applied[qs_daf] = np.maximum(measured[qs_daf], 1.0)
        reason = auto_reason
        override = False
    else:
        analyses = [an] * n
        if an == "dynamic":
            applied[qs_daf] = np.maximum(measured[qs_daf], 1.0)
        override = analyses != auto
        if not override:
            reason = f"{an} given (--analysis {an}), as the line model gives: {auto_reason}"
        else:
            model = ("finite-element" if n_qs == 0 else "quasi-static" if n_fe == 0
                     else f"{n_fe} finite-element and {n_qs} quasi-static")
            reason = (f"OVERRIDE: {an}-analysis factors given (--analysis {an}) for every "
                      f"line; the lines are {model} (the line model gives: {auto_reason})")
            if an == "dynamic" and (~fe & ~has_daf).any():
                reason += (" -- dynamic factors on quasi-static tensions without a dynamic "
                           "amplification factor")
    missing = sorted({a for a in analyses if a not in c.analyses})
    if missing:
        c.check_analysis(missing[0])           # the code's SceneError, with its hint
    kinds = sorted(set(analyses))
    summary = kinds[0] if len(kinds) == 1 else "dynamic and quasi-static (per line)"
    return {"analyses": analyses, "daf_measured": measured, "daf_applied": applied,
            "override": override, "reason": reason, "summary": summary,
            "models": list(models)}


def _with_daf(t_mean, t_c, applied):
    """T_C with the dynamic part amplified: ``T_C-mean + DAF (T_C - T_C-mean)`` where a DAF is
    applied."""
    t_mean = np.asarray(t_mean, float)
    t_c = np.asarray(t_c, float)
    f = np.where(np.isfinite(applied), applied, 1.0)
    return t_mean + f * (t_c - t_mean)


def summarise(results: Sequence[xr.Dataset], mbs, *, als_results: Sequence[xr.Dataset] | None = None,
              failed_lines: Sequence | None = None, consequence_class: int = 2,
              analysis: str = "auto", start: float | None = None, end: float | None = None,
              cutoff: float = DEFAULT_CUTOFF_HZ, p: float = 0.9, method: str = "mle",
              return_als: bool = False, code=None, daf=None, eol_mbs=None):
    """Statistics, characteristic tensions and design checks of a set of seeds.

    Parameters
    ----------
    results : sequence of xarray.Dataset
        Intact-system seeds (``line_tension`` in N, optional ``motion``).
    mbs : float or array_like
        Minimum breaking strength per line in N.
    als_results : sequence of xarray.Dataset, optional
        Seeds with one line failed (ALS); the failed line(s) are excluded from the ALS check.
    failed_lines : sequence, optional
        Names of the failed lines in ``als_results`` (default: the results' ``failed_lines``
        attribute, else :func:`detect_failed_lines`).
    consequence_class : see :func:`floatmoor.post.dnv_os_e301.partial_factors`.
    analysis : str
        ``"auto"`` (default: from the line model, :func:`resolve_analysis`), ``"dynamic"`` or
        ``"quasi-static"`` (override).
    start, end : float, optional
        Statistics window in s (default: from the ``transient`` attribute of the results,
        the largest over the seeds; the ALS seeds use their own).
    cutoff : float
        LF/WF cut-off in Hz.
    p : float
        Gumbel fractile of the characteristic tension (0.9).
    method : str
        Gumbel fit method.
    return_als : bool
        Also return ``(characteristic, statistics)`` of the ALS seeds (lines not failed; None
        without ALS results) as a fourth item.
    code : the design code (key, file or DesignCode; default DNV-OS-E301 (2008)).
    daf : mapping line name -> DAF of ``floatmoor lines`` (optional).
    eol_mbs : per-line end-of-life MBS (N) for the capacity (optional).

    Returns
    -------
    (checks, statistics, characteristic) : tuple of xarray.Dataset
        :func:`~floatmoor.post.dnv_os_e301.check_lines` output (with ``daf_measured`` and
        ``daf_applied`` per line and the attributes ``analysis_reason``,
        ``analysis_override``); per-seed statistics; the ULS characteristic tensions
        (:func:`~floatmoor.post.dnv_os_e301.characteristic_tensions`, without DAF).
    """
    c = load_code(DEFAULT_CODE if code is None else code)
    start_given = start
    results = [_prepared(ds) for ds in _check_results(results, "results")]
    if start is None:
        start = transient_of(results)
    stats = per_seed_statistics(results, start=start, end=end, cutoff=cutoff,
                                variables=_variables(results[0]))
    ct = dnv.characteristic_tensions(stats["line_tension_max"], stats["line_tension_mean"],
                                     p=p, method=method)
    lines = list(ct["line"].values)
    names = [str(v) for v in lines]
    daf_idx = None
    if daf is not None:
        unknown = [k for k in daf if str(k) not in names]
        if unknown:
            raise argument_error("daf", f"DAFs of the lines {names}", f"lines {unknown}")
        daf_idx = {names.index(str(k)): float(v) for k, v in daf.items()}
    res = resolve_analysis(line_models(results), analysis, daf_idx, c)
    applied = res["daf_applied"]
    als_mean = als_max = als_detail = None
    if als_results is not None:
        als_results = _check_results(als_results, "als_results")
        als_start = transient_of(als_results) if start_given is None else start_given
        astats = per_seed_statistics(als_results, start=als_start, end=end, cutoff=cutoff,
                                     variables=["line_tension"])
        if list(astats["line"].values) != lines:
            raise argument_error("als_results", f"the same lines as the intact results {lines}",
                                 list(astats["line"].values))
        if failed_lines is None:
            attr = als_results[0].attrs.get("failed_lines")
            if attr is not None:
                failed_lines = list(np.atleast_1d(attr))
            else:
                failed_lines = detect_failed_lines(als_results)
                if not failed_lines:
                    raise argument_error("als_results",
                                         "results with a failed line (a line whose tension is "
                                         "zero at the end of every ALS seed), or the failed "
                                         "line named (failed_lines)", "no failed line found")
        failed = {str(f) for f in failed_lines}
        if not failed <= set(names):
            raise argument_error("failed_lines", f"names of lines among {lines}", sorted(failed))
        alive = np.array([str(ln) not in failed for ln in lines])
        sub_max = astats["line_tension_max"].isel(line=np.flatnonzero(alive))
        sub_mean = astats["line_tension_mean"].isel(line=np.flatnonzero(alive))
        act = dnv.characteristic_tensions(sub_max, sub_mean, p=p, method=method)
        als_detail = (act, astats)
        als_mean = np.full(len(lines), np.nan)
        als_max = np.full(len(lines), np.nan)
        als_mean[alive] = act["t_c_mean"].values
        als_max[alive] = act["t_c"].values
        als_max = np.where(alive, _with_daf(np.nan_to_num(als_mean), np.nan_to_num(als_max),
                                            applied), np.nan)
    checks = dnv.check_lines(lines, mbs, uls_mean=ct["t_c_mean"].values,
                             uls_max=_with_daf(ct["t_c_mean"].values, ct["t_c"].values, applied),
                             als_mean=als_mean, als_max=als_max,
                             consequence_class=consequence_class, analysis=res["analyses"],
                             code=c, eol_mbs=eol_mbs)
    checks["daf_measured"] = ("line", res["daf_measured"],
                              {"units": "1", "long_name": "dynamic amplification factor of "
                               "floatmoor lines (NaN: none given)"})
    checks["daf_applied"] = ("line", applied,
                             {"units": "1", "long_name": "DAF applied to T_C-dyn (at least 1; "
                              "NaN: not applied)"})
    checks["line_model"] = ("line", np.array(res["models"], dtype=object),
                            {"units": "", "long_name": "line model of the results"})
    checks.attrs["gumbel_fractile"] = float(p)
    checks.attrs["gumbel_method"] = method
    checks.attrs["n_seeds"] = len(results)
    checks.attrs["analysis_reason"] = res["reason"]
    checks.attrs["analysis_override"] = int(res["override"])
    checks.attrs["analysis_summary"] = res["summary"]
    # lines whose utilisation equals the governing one within 0.1 % (symmetric mooring)
    u = checks["utilisation"].sel(limit_state=checks.attrs["governing_limit_state"]).values
    umax = checks.attrs["max_utilisation"]
    checks.attrs["governing_ties"] = ", ".join(
        str(ln) for ln, uj in zip(lines, u)
        if np.isfinite(uj) and uj >= umax * (1 - 1e-3) and str(ln) != checks.attrs["governing_line"])
    if als_results is not None:
        checks.attrs["n_seeds_als"] = len(als_results)
        checks.attrs["failed_lines"] = ", ".join(sorted(failed))
    if return_als:
        return checks, stats, ct, als_detail
    return checks, stats, ct


# -- the other checks ----------------------------------------------------------------------------
def _design_statistics(results, context, start, end, failed=()):
    """Per-seed design statistics of a set of seeds (None without a mooring)."""
    from .design_checks import collect
    from .design_statistics import seed_design_statistics
    if context is None or context.mooring is None:
        return None
    per = [seed_design_statistics(ds, context.mooring, start=start, end=end,
                                  limits=context.limits, failed=failed) for ds in results]
    seeds = [int(ds.attrs.get("seed", k)) for k, ds in enumerate(results)]
    return collect(per, seeds)


def _other_checks(results, als_results, checks, context, code, cc, p, start, end):
    """Anchors, offsets and fibre checks of both limit states (empty without a mooring)."""
    from .design_checks import anchor_checks, fibre_checks, offset_checks
    out = {"anchors": {}, "offsets": {}, "fibre": {}, "design_stats": {}}
    if context is None or context.mooring is None:
        return out
    analyses = [str(a) for a in checks["analysis"].values]
    sets = [("ULS", results, ())]
    if als_results is not None:
        failed = [s.strip() for s in checks.attrs.get("failed_lines", "").split(",") if s.strip()]
        sets.append(("ALS", als_results, failed))
    for ls, res_set, failed in sets:
        st_start = start if start is not None else transient_of(res_set)
        stats = _design_statistics(res_set, context, st_start, end, failed)
        out["design_stats"][ls] = stats
        out["anchors"][ls] = anchor_checks(stats, context.design, code, limit_state=ls,
                                           consequence_class=cc, analysis=analyses, p=p)
        out["offsets"][ls] = offset_checks(stats, context.limits, limit_state=ls, p=p)
        out["fibre"][ls] = fibre_checks(stats, context.mooring, code,
                                        checks.sel(limit_state=ls), limit_state=ls, p=p)
    return out


def _verdict_lines(checks, fls, other, context, als_given: bool, results=()):
    lines = [vd.line_tension_line(checks, "ULS", daf=checks["daf_applied"].values),
             vd.line_tension_line(checks, "ALS", daf=checks["daf_applied"].values),
             vd.fls_line(fls)]
    fe = vd.fe_selfcheck_line(results)
    if fe is not None:
        lines.insert(1, fe)
    limits_given = context is not None and context.limits is not None and bool(
        context.limits.offset or context.limits.points)
    for ls in ("ULS", "ALS") if als_given else ("ULS",):
        lines += vd.anchor_lines(other["anchors"].get(ls), ls)
        lines.append(vd.offset_line(other["offsets"].get(ls, {}), ls, limits_given)
                     if ls in other["offsets"] else
                     vd.VerdictLine(ls, "offsets", vd.NOT_CHECKED,
                                    text="the scene is not available"))
        f = vd.fibre_line(other["fibre"].get(ls), ls)
        if f is not None:
            lines.append(f)
    return lines


def _used_parts(checks, fls, other, capacities):
    parts = ["line_tension.strength_factor", "line_tension.ULS"]
    if "ALS" in checks["limit_state"].values:
        parts.append("line_tension.ALS")
    if int(checks.attrs.get("consequence_class", 0)) == 1:
        parts.append("line_tension.common_factor")
    if fls is not None:
        parts.append("fatigue")
    if capacities is not None:
        parts.append("corrosion")
    if other["anchors"]:
        parts.append("anchors")
    if any(v is not None for v in other["fibre"].values()):
        parts.append("fibre")
    return parts


# -- the first screen ---------------------------------------------------------------------------
def _kv_table(table_id, rows):
    out = [f'<table class="kv" id="{table_id}"><tbody>']
    out += [f"<tr><th>{html.escape(k)}</th><td>{html.escape(v)}</td></tr>" for k, v in rows]
    out.append("</tbody></table>")
    return "".join(out)


def _summary_html(title, verdict_lines, overall, checks, scene, n_seeds, context, code,
                  unverified, window_text):
    status, sentence = overall
    cls = "fail" if status == vd.FAIL else "pass"
    parts = [f'<div class="summary {cls}" id="summary">',
             f'<p class="verdict {cls}" id="verdict_line">Verdict: {html.escape(sentence)}</p>']
    vt = _Table("verdict", "Verdict per limit state and check (the governing item, its "
                "utilisation and the numbers behind it)",
                ["limit state", "check", "status", "governing", "utilisation", "detail"],
                [[v.limit_state, v.check, v.status, v.governing,
                  _fmt(v.utilisation, 3), v.text] for v in verdict_lines], status_col=2,
                text_cols=(1, 3), wide_cols=(5,))
    parts.append(f'<div class="scroll">{vt.html()}</div>')
    gls = checks.attrs["governing_limit_state"]
    c = checks.sel(limit_state=gls)
    j = [str(v) for v in c["line"].values].index(str(checks.attrs["governing_line"]))
    gov_rows = [
        ("governing line", f"{checks.attrs['governing_line']} in the {gls}"
         + (f" (equal within 0.1 %: {checks.attrs['governing_ties']})"
            if checks.attrs.get("governing_ties") else "")),
        ("case", f"{scene}: the scene's sea state, {n_seeds} seeds; statistics window "
         f"{window_text}"),
        ("T_C", f"{c['t_c'].values[j] * _KN:.0f} kN (T_C-mean {c['t_c_mean'].values[j] * _KN:.0f}"
         f" kN, T_C-dyn {c['t_c_dyn'].values[j] * _KN:.0f} kN"
         + (f", DAF {checks['daf_applied'].values[j]:.3f} applied"
            if np.isfinite(checks["daf_applied"].values[j]) else "") + ")"),
        ("design tension", f"{c['design_tension'].values[j] * _KN:.0f} kN (gamma_mean "
         f"{c['gamma_mean'].values[j]:.2f}, gamma_dyn {c['gamma_dyn'].values[j]:.2f})"),
        ("capacity S_C", f"{c['s_c'].values[j] * _KN:.0f} kN"
         + (f" end of life; {c['s_c_new'].values[j] * _KN:.0f} kN new"
            if int(checks.attrs.get("end_of_life_capacity", 0)) else " (new line)")),
        ("utilisation", f"{c['utilisation'].values[j]:.3f}"
         + (f" (new line {c['utilisation_new'].values[j]:.3f})"
            if int(checks.attrs.get("end_of_life_capacity", 0)) else "")),
    ]
    models = sorted(set(str(m) for m in checks["line_model"].values))
    an_rows = [
        ("line model", ", ".join(models) + " lines"),
        ("analysis type", checks.attrs.get("analysis_summary", checks.attrs["analysis"])
         + (" (OVERRIDE)" if int(checks.attrs.get("analysis_override", 0)) else "")),
        ("why", checks.attrs.get("analysis_reason", "")),
        ("design code", f"{code.name} (code file {code.file.name})"),
        ("consequence class", str(checks.attrs["consequence_class"])
         if code.has_classes else "not used by this code"),
        ("unverified code values used", "; ".join(f"{e.path}" for e in unverified)
         + " -- see 'Code values used'" if unverified else "none"),
    ]
    env_rows = list(context.environment) if context is not None and context.environment else [
        ("environment", "not available (the scene file was not found)")]
    parts.append('<div class="cols">')
    parts.append("<div><h3>Governing line</h3>" + _kv_table("governing", gov_rows) + "</div>")
    parts.append("<div><h3>Environment</h3>" + _kv_table("environment", env_rows) + "</div>")
    parts.append("<div><h3>Line model, analysis and code</h3>" + _kv_table("analysis", an_rows)
                 + "</div>")
    parts.append("</div>")
    omit = list(context.omissions) if context is not None else [
        "the scene file was not found: what it leaves out cannot be listed"]
    parts.append('<h3>What the scene leaves out that could matter</h3><ul class="omit" '
                 'id="omissions">' + "".join(f"<li>{html.escape(o)}</li>" for o in omit)
                 + "</ul>")
    if context is not None and context.notes:
        parts.append("<p class='note'>" + " ".join(html.escape(n) for n in context.notes)
                     + "</p>")
    parts.append("</div>")
    return "".join(parts)


def build_report(results: Sequence[xr.Dataset], mbs, out_dir, *,
                 als_results: Sequence[xr.Dataset] | None = None,
                 failed_lines: Sequence | None = None, consequence_class: int = 2,
                 analysis: str = "auto", start: float | None = None, end: float | None = None,
                 cutoff: float = DEFAULT_CUTOFF_HZ, p: float = 0.9, method: str = "mle",
                 title: str | None = None, plots: bool = True, fd: xr.Dataset | None = None,
                 failed_seeds: Sequence[str] = (), extra_meta: Sequence[tuple] = (),
                 fatigue: xr.Dataset | None = None, code=None, daf=None,
                 daf_source: str = "", context: ReportContext | None = None) -> ReportFiles:
    """Write the design report of a set of seeds (HTML, Markdown, CSV, netCDF).

    Parameters
    ----------
    results : sequence of xarray.Dataset
        Per-seed intact results (``line_tension(time, line)`` in N, ``motion(time, dof)``).
    mbs : float or array_like
        Minimum breaking strength per line in N.
    out_dir : path
        Output folder (created).
    als_results, failed_lines, consequence_class, analysis, start, end, cutoff, p, method
        As :func:`summarise`.
    title : str, optional
        Report title (default from the ``scene`` attribute).
    plots : bool
        Embed plots (needs matplotlib; skipped with a note when missing).
    fd : xarray.Dataset, optional
        A frequency-domain result of the same scene (:func:`floatmoor.frequency_domain`, or
        the file of ``floatmoor fd --out``): its per-line maximum tension and safety factor and
        its offsets are tabulated beside the time-domain values.
    failed_seeds : sequence of str
        Seeds that failed and were left out (listed in the report).
    extra_meta : sequence of (str, str)
        More rows for the report's run-details table (e.g. the results folder).
    fatigue : xarray.Dataset, optional
        A ``floatmoor fatigue`` result: adds the FLS section and verdict line (its check
        redone with the code's fatigue factor, :func:`floatmoor.post.fatigue_report.fls_check`).
    code : the design code (key, file or DesignCode; default DNV-OS-E301 (2008)).
    daf, daf_source : DAF per line name from ``floatmoor lines`` and where it comes from.
    context : ReportContext, optional
        What the scene gives: environment, omissions, mooring (end-of-life capacity, anchor,
        fibre checks), limits (offsets and points).

    Returns
    -------
    ReportFiles
    """
    c = load_code(DEFAULT_CODE if code is None else code)
    results = [_prepared(ds) for ds in _check_results(results, "results")]
    plot_start = transient_of(results) if start is None else start
    capacities = None
    eol_mbs = None
    if context is not None and context.mooring is not None:
        from .capacity import segment_capacities
        capacities = segment_capacities(context.mooring, context.design, c)
        names = [str(v) for v in results[0]["line"].values]
        if [str(n) for n in context.mooring.names] != names:
            raise argument_error("context.mooring", f"the lines of the results {names}",
                                 list(context.mooring.names))
        if c.end_of_life_capacity:
            # the corrosion's share of the line's MBS, applied to the MBS of the results
            ratio = capacities["mbs_eol_line"].values / capacities["mbs_new_line"].values
            eol_mbs = np.broadcast_to(np.asarray(mbs, float), ratio.shape) * ratio
    checks, stats, ct, als_detail = summarise(
        results, mbs, als_results=als_results, return_als=True, failed_lines=failed_lines,
        consequence_class=consequence_class, analysis=analysis, start=start, end=end,
        cutoff=cutoff, p=p, method=method, code=c, daf=daf, eol_mbs=eol_mbs)
    if daf_source:
        checks.attrs["daf_source"] = daf_source
    if c.end_of_life_capacity and eol_mbs is None:
        checks.attrs["end_of_life_missing"] = (
            "the end-of-life capacity needs the mooring file (corrosion zones of the segments), "
            "which was not given or found: S_C is the new line's")
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    if fd is not None:
        check_fd(fd, ct["line"].values)
    other = _other_checks(results, als_results, checks, context, c, consequence_class, p,
                          start, end)
    fls = None
    if fatigue is not None:
        from .fatigue_report import fls_check
        fls = fls_check(fatigue, c)
    verdict_lines = _verdict_lines(checks, fls, other, context, als_results is not None,
                                   results=results)
    overall = vd.overall(verdict_lines)
    unverified = [e for e in c.entries_used(_used_parts(checks, fls, other, capacities))
                  if not e.verified]
    used = c.entries_used(_used_parts(checks, fls, other, capacities))
    scene = scene_name(results[0])
    title = title or f"Mooring design report: {scene}"
    seeds = [int(s) for s in stats["seed"].values]
    a0 = results[0].attrs
    software = f"floatmoor {_version()} (report)"
    run_versions = sorted({str(ds.attrs["version_floatmoor"]) for ds in results
                           if "version_floatmoor" in ds.attrs})
    if run_versions:
        software += f"; results computed with floatmoor {', '.join(run_versions)}"
    window_text = f"{stats.attrs['window_start_s']:g} - {stats.attrs['window_end_s']:g} s"
    meta = [("scene", scene)]
    if a0.get("scene_file"):
        meta.append(("scene file", str(a0["scene_file"])))
    meta += [
        ("software", software),
        ("generated", _dt.datetime.now(_dt.UTC).strftime("%Y-%m-%d %H:%M UTC")),
        ("standard", dnv.SOURCE if c.key == DEFAULT_CODE else c.name),
        ("edition", c.name),
        ("code file", str(c.file.name)),
        ("consequence class", str(consequence_class)),
        ("analysis of WF tension", f"{checks.attrs['analysis']} -- "
                                   f"{checks.attrs['analysis_reason']}"),
        ("seeds", f"{len(seeds)}: {', '.join(map(str, seeds))}"),
    ]
    if checks.attrs.get("daf_source"):
        meta.append(("DAF from", checks.attrs["daf_source"]))
    if failed_seeds:
        meta.append(("failed seeds (left out)", "; ".join(map(str, failed_seeds))))
    if "dt" in a0 and "duration" in a0:
        meta.append(("simulation", f"{float(a0['duration']):g} s at dt {float(a0['dt']):g} s; "
                     f"models: {', '.join(np.atleast_1d(a0.get('models', [])).astype(str))}"))
    meta += [
        ("statistics window", window_text),
        ("LF/WF cut-off", f"{stats.attrs['cutoff_hz']:.5f} Hz ({stats.attrs['filter']})"),
        ("characteristic tension", f"Gumbel ({method}) {p:g} fractile of the seed maxima"),
        ("governing", f"{line_label(checks.attrs['governing_line'])} in "
                      f"{checks.attrs['governing_limit_state']}, "
                      f"utilisation {checks.attrs['max_utilisation']:.3f}"
                      + (f" (equal within 0.1 %: {checks.attrs['governing_ties']})"
                         if checks.attrs["governing_ties"] else "")),
        ("verdict", overall[1]),
    ]
    if "failed_lines" in checks.attrs:
        meta.append(("ALS failed line(s)", checks.attrs["failed_lines"]))
        meta.append(("ALS seeds", str(checks.attrs.get("n_seeds_als", ""))))
    if fd is not None:
        meta.append(("frequency domain", f"{fd.attrs.get('scene_name', '')}, duration "
                     f"{_fmt(float(fd.attrs.get('duration', float('nan'))), 0)} s, drift "
                     f"{fd.attrs.get('drift_method', '?')}, tension model "
                     f"{fd.attrs.get('tension_model', '?')}"))
    if other["design_stats"]:
        n_states = sum(int(s.attrs.get("candidate_states", 0))
                       for s in other["design_stats"].values() if s is not None)
        meta.append(("anchor and rope states", f"quasi-static catenary of each line at "
                     f"{n_states} recorded poses (the tautest and slackest of each line in "
                     "each seed, refined to the local extremum)"))
    if context is not None:
        meta += [("note", n) for n in context.notes]
    meta += [(str(k), str(v)) for k, v in extra_meta]
    daf_applied = checks["daf_applied"].values
    tables = [line_table(checks, ct, stats, ls, als_detail, daf_applied)
              for ls in checks["limit_state"].values]
    if capacities is not None:
        tables.append(capacity_table(capacities))
    for ls, anchors_ds in other["anchors"].items():
        tables.append(anchor_table(anchors_ds, ls))
    for ls, res in other["offsets"].items():
        tables += offset_tables(res, ls)
    for ls, fib in other["fibre"].items():
        if fib is not None:
            tables.append(fibre_table(fib, ls))
    if fatigue is not None:  # the FLS section
        from .fatigue_report import fls_meta, fls_tables
        meta += fls_meta(fatigue, fls)
        tables += fls_tables(fatigue, fls)
    mt = motion_table(stats)
    if mt is not None:
        tables.append(mt)
    if fd is not None:
        tables.append(fd_lines_table(fd, checks, ct, stats))
        ft = fd_offsets_table(fd, stats)
        if ft is not None:
            tables.append(ft)
    tables.append(code_values_table(c, used))
    figs = make_plots(results, checks, ct, stats, plot_start, end) if plots else []

    # HTML
    parts = ["<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'>",
             f"<title>{html.escape(title)}</title><style>{_CSS}</style></head><body>",
             f"<h1>{html.escape(title)}</h1>",
             _summary_html(title, verdict_lines, overall, checks, scene, len(seeds), context, c,
                           unverified, window_text)]
    for t in tables:
        parts.append(f"<h2>{html.escape(t.caption.split(':')[0])}</h2>")
        parts.append(f'<div class="scroll">{t.html()}</div>')
    parts.append("<h2>Plots</h2>")
    if figs:
        for name, caption, png in figs:
            b64 = base64.b64encode(png).decode("ascii")
            parts.append(f'<figure id="fig_{name}"><img alt="{html.escape(caption)}" '
                         f'src="data:image/png;base64,{b64}"><figcaption>{html.escape(caption)}'
                         "</figcaption></figure>")
    else:
        parts.append("<p class='note'>No plots: matplotlib is not installed "
                     "(pip install floatmoor[plot]).</p>")
    parts.append("<h2>Run details</h2>")
    parts.append('<div class="scroll"><table class="meta" id="meta"><tbody>')
    parts += [f"<tr><th class='name'>{html.escape(k)}</th><td>{html.escape(v)}</td></tr>"
              for k, v in meta]
    parts.append("</tbody></table></div>")
    scene_yaml = str(a0.get("scene", ""))
    if "\n" in scene_yaml:
        parts.append("<details><summary>scene file as run</summary><pre>"
                     f"{html.escape(scene_yaml)}</pre></details>")
    parts.append(f"<p class='note'>{html.escape(dnv.SOURCE if c.key == DEFAULT_CODE else c.name)}"
                 ".</p></body></html>")
    html_path = out / "report.html"
    html_path.write_text("".join(parts), encoding="utf-8")

    # Markdown (+ PNG files)
    md = [f"# {title}", "", f"**Verdict: {overall[1]}**", "",
          vd_table_markdown(verdict_lines), ""]
    md += ["## Environment", ""] + [f"- **{k}**: {v}" for k, v in (
        context.environment if context is not None else ())] + [""]
    md += ["## Line model, analysis and code", "",
           f"- **analysis**: {checks.attrs.get('analysis_summary')} -- "
           f"{checks.attrs.get('analysis_reason')}",
           f"- **design code**: {c.name} (code file {c.file.name})",
           "- **unverified code values used**: " + ("; ".join(e.path for e in unverified)
                                                    if unverified else "none"), ""]
    md += ["## What the scene leaves out that could matter", ""] + [
        f"- {o}" for o in (context.omissions if context is not None else ())] + [""]
    md += ["## Run details", ""] + [f"- **{k}**: {v}" for k, v in meta] + [""]
    for t in tables:
        md += [t.markdown(), ""]
    for name, caption, png in figs:
        (out / f"{name}.png").write_bytes(png)
        md.append(f"![{caption}]({name}.png)")
    md_path = out / "report.md"
    md_path.write_text("\n".join(md) + "\n", encoding="utf-8")

    # CSV
    cols = ["t_c_mean", "t_c_dyn", "t_c", "s_mbs", "s_c", "gamma_mean", "gamma_dyn",
            "common_factor_applied", "design_tension", "margin", "utilisation", "checked",
            "passed", "safety_factor", "governing", "s_c_new", "utilisation_new"]
    extra = {"td_mean[N]": ct["t_c_mean"].values, "td_std[N]":
             stats["line_tension_std"].mean("seed").values,
             "gumbel_mpm[N]": ct["gumbel_mpm"].values, "gumbel_p90[N]": ct["gumbel_p90"].values}
    if fd is not None:
        order = [line_key(fd, ln) for ln in ct["line"].values]
        extra["fd_max_total[N]"] = fd["tension_max_total"].sel(line=order).values
        extra["fd_safety_factor[1]"] = fd["safety_factor"].sel(line=order).values
    rows = ["limit_state,line," + ",".join(f"{col}[{checks[col].attrs['units']}]" for col in cols)
            + "," + ",".join(extra) + ",analysis,daf_applied[1]"]
    for ls in checks["limit_state"].values:
        cl = checks.sel(limit_state=ls)
        for j, line in enumerate(cl["line"].values):
            vals = []
            for col in cols:
                v = cl[col].values[j]
                vals.append(str(int(v)) if isinstance(v, (bool, np.bool_)) else repr(float(v)))
            # intact-system (ULS) statistics; empty in the ALS rows
            vals += [repr(float(v[j])) if ls == "ULS" else "" for v in extra.values()]
            vals += [str(checks["analysis"].values[j]), repr(float(daf_applied[j]))]
            rows.append(f"{ls},{line}," + ",".join(vals))
    csv_path = out / "summary.csv"
    csv_path.write_text("\n".join(rows) + "\n", encoding="utf-8")

    # netCDF
    nc = checks.copy()
    nc["governing_line"] = nc["governing_line"].astype(str)
    nc["analysis"] = nc["analysis"].astype(str)
    nc["line_model"] = nc["line_model"].astype(str)
    for name in ("passed", "checked", "governing", "common_factor_applied"):
        nc[name] = nc[name].astype(np.int8)
    for name, var in ct.data_vars.items():
        nc[f"uls_{name}"] = var
    for name, var in stats.data_vars.items():
        nc[f"seed_{name}"] = var
    if capacities is not None:
        for name, var in capacities.data_vars.items():
            nc[f"capacity_{name}"] = var.rename({"line": "line"})
    for ls, anchors_ds in other["anchors"].items():
        for name, var in anchors_ds.data_vars.items():
            nc[f"anchor_{ls.lower()}_{name}"] = var.astype(np.int8) if var.dtype == bool else var
    for ls, fib in other["fibre"].items():
        if fib is None:
            continue
        f2 = fib.rename({"line": "fibre_line"})
        for name, var in f2.data_vars.items():
            nc[f"fibre_{ls.lower()}_{name}"] = var.astype(np.int8) if var.dtype == bool else var
    for ls, res in other["offsets"].items():
        for kind in ("offsets", "points"):
            d = res.get(kind)
            if d is None:
                continue
            for name, var in d.data_vars.items():
                nc[f"{kind}_{ls.lower()}_{name}"] = (var.astype(np.int8) if var.dtype == bool
                                                     else var)
    for ls, st in other["design_stats"].items():
        if st is None:
            continue
        st2 = st.rename({"seed": f"seed_{ls.lower()}"}) if ls == "ALS" else st
        for name, var in st2.data_vars.items():
            if var.dtype.kind in "OU":
                continue
            nc[f"design_{ls.lower()}_{name}"] = var
    if fls is not None:
        for name, var in fls.data_vars.items():
            nc[f"fls_{name}"] = (var.astype(np.int8) if var.dtype == bool else var).rename(
                {"line": "fls_line"} if "line" in var.dims else {})
    nc.attrs["scene"] = scene
    if "\n" in scene_yaml:
        nc.attrs["scene_yaml"] = scene_yaml
    if failed_seeds:
        nc.attrs["failed_seeds"] = "; ".join(map(str, failed_seeds))
    if fd is not None:
        order = [line_key(fd, ln) for ln in nc["line"].values]
        for name, new_name in (("tension_static", "fd_tension_static"),
                               ("tension_max_total", "fd_tension_max_total"),
                               ("safety_factor", "fd_safety_factor")):
            nc[new_name] = xr.DataArray(fd[name].sel(line=order).values, dims=("line",),
                                        attrs=dict(fd[name].attrs))
    nc.attrs["software"] = f"floatmoor {_version()}"
    nc.attrs["verdict"] = overall[0]
    nc.attrs["verdict_text"] = overall[1]
    nc.attrs["verdict_lines"] = " | ".join(f"{v.label}: {v.status}" for v in verdict_lines)
    nc.attrs["unverified_code_values"] = "; ".join(e.path for e in unverified)
    nc_path = out / "summary.nc"
    nc.to_netcdf(nc_path)
    return ReportFiles(html=html_path, markdown=md_path, csv=csv_path, netcdf=nc_path,
                       checks=checks, statistics=stats, characteristic=ct,
                       verdict=tuple(verdict_lines), overall=overall, capacities=capacities,
                       anchors=other["anchors"], offsets=other["offsets"],
                       fibre=other["fibre"], fls=fls, code=c, unverified=tuple(unverified))


def vd_table_markdown(verdict_lines) -> str:
    t = _Table("verdict", "Verdict per limit state and check",
               ["limit state", "check", "status", "governing", "utilisation", "detail"],
               [[v.limit_state, v.check, v.status, v.governing, _fmt(v.utilisation, 3), v.text]
                for v in verdict_lines], status_col=2)
    return t.markdown()

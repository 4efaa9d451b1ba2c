"""Design report from time-domain seeds: self-contained HTML, Markdown, CSV and netCDF summary.

:func:`build_report` takes the per-seed result Datasets of one sea state (the simulator's format:
``motion(time, dof)`` in m / rad, ``line_tension(time, line)`` in N, attributes ``seed``,
``scene_name``, ``scene`` (YAML), ``transient``) and writes

* ``report.html`` -- opens in a browser with no network: CSS inline, plots as base64 PNG;
* ``report.md`` -- the same tables in Markdown (plots as separate PNG files beside it);
* ``summary.csv`` -- one row per line and limit state;
* ``summary.nc`` -- the per-line check Dataset and the statistics.

Tables: the header (scene, scene file and its YAML, software versions, standard edition and
clauses, seeds and failed seeds, window), per-line ULS (and ALS) tensions and checks with the
governing line highlighted, offsets and motions, and, with ``fd=``, the frequency-domain maxima
and safety factors beside the time-domain Gumbel values.  Plots: governing-line time series (the
seed with its largest maximum), Gumbel plot, tension per line, offset.

Method (Wang (2016) section 5.4.4 and chapter 3): per seed, statistics in
the window (default: from the results' ``transient`` attribute); per line, a Gumbel fit of the
seed maxima; the characteristic tension is its 90 %
fractile; the design check is the DNV-OS-E301 design equation (DNV (2008); Wang (2016)
eq. 3.4) with the partial factors of
:mod:`floatmoor.post.dnv_os_e301`.  Plots need matplotlib (optional); without it the report has
tables only and says so.
"""

from __future__ import annotations

import base64
import datetime as _dt
import html
import io
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np
import xarray as xr

from ..core.errors import SceneError, argument_error
from . import dnv_os_e301 as dnv
from .extremes import gumbel_fit
from .timeseries import DEFAULT_CUTOFF_HZ, per_seed_statistics, window

__all__ = ["ReportFiles", "build_report", "summarise"]

_KN = 1e-3


@dataclass(frozen=True)
class ReportFiles:
    """Paths written by :func:`build_report` and the summary Datasets."""

    html: Path
    markdown: Path
    csv: Path
    netcdf: Path
    checks: xr.Dataset
    statistics: xr.Dataset
    characteristic: xr.Dataset


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


def summarise(results: Sequence[xr.Dataset], mbs, *, als_results: Sequence[xr.Dataset] | None = None,
              failed_lines: Sequence | None = None, consequence_class: int = 2,
              analysis: str = "dynamic", start: float | None = None, end: float | None = None,
              cutoff: float = DEFAULT_CUTOFF_HZ, p: float = 0.9, method: str = "mle",
              return_als: bool = False):
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
    consequence_class, analysis : see :func:`floatmoor.post.dnv_os_e301.partial_factors`.
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

    Returns
    -------
    (checks, statistics, characteristic) : tuple of xarray.Dataset
        :func:`~floatmoor.post.dnv_os_e301.check_lines` output; per-seed statistics; the ULS
        characteristic tensions (:func:`~floatmoor.post.dnv_os_e301.characteristic_tensions`).
    """
    start_given = start
    results = [_prepared(ds) for ds in _check_results(results, "results")]
    if start is None:
        start = transient_of(results)
    stats = per_seed_statistics(results, start=start, end=end, cutoff=cutoff,
                                variables=_variables(results[0]))
    ct = dnv.characteristic_tensions(stats["line_tension_max"], stats["line_tension_mean"],
                                     p=p, method=method)
    lines = list(ct["line"].values)
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
        if not failed <= {str(ln) for ln in lines}:
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
    checks = dnv.check_lines(lines, mbs, uls_mean=ct["t_c_mean"].values, uls_max=ct["t_c"].values,
                             als_mean=als_mean, als_max=als_max,
                             consequence_class=consequence_class, analysis=analysis)
    checks.attrs["gumbel_fractile"] = float(p)
    checks.attrs["gumbel_method"] = method
    checks.attrs["n_seeds"] = len(results)
    # lines whose utilisation equals the governing one within 0.1 % (symmetric mooring)
    u = checks["utilisation"].sel(limit_state=checks.attrs["governing_limit_state"]).values
    umax = checks.attrs["max_utilisation"]
    checks.attrs["governing_ties"] = ", ".join(
        str(ln) for ln, uj in zip(lines, u)
        if np.isfinite(uj) and uj >= umax * (1 - 1e-3) and str(ln) != checks.attrs["governing_line"])
    if als_results is not None:
        checks.attrs["n_seeds_als"] = len(als_results)
    if als_results is not None:
        checks.attrs["failed_lines"] = ", ".join(sorted(failed))
    if return_als:
        return checks, stats, ct, als_detail
    return checks, stats, ct


# -- rendering helpers --------------------------------------------------------------------------

_CSS = """
body{font-family:system-ui,Segoe UI,Helvetica,Arial,sans-serif;margin:2em;max-width:1400px;color:#222}
.scroll{overflow-x:auto}
h1{font-size:1.5em}h2{font-size:1.2em;margin-top:1.6em;border-bottom:1px solid #ccc}
table{border-collapse:collapse;margin:0.6em 0;font-size:0.9em}
th,td{border:1px solid #bbb;padding:3px 7px;text-align:right}
th{background:#eef}td.name,th.name{text-align:left}
tr.governing td{background:#ffe08a;font-weight:bold}
td.fail{color:#b00;font-weight:bold}td.pass{color:#070}
.meta td{text-align:left}figure{display:inline-block;margin:0.5em}figcaption{font-size:0.85em}
.note{font-size:0.85em;color:#555}
pre{background:#f6f6f6;padding:0.6em;font-size:0.8em;overflow-x:auto}
"""


def _fmt(v, digits=1):
    if isinstance(v, (bool, np.bool_)):
        return "yes" if v else "no"
    if v is None or (isinstance(v, (float, np.floating)) and not np.isfinite(v)):
        return "n/a"
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    if isinstance(v, (float, np.floating)):
        return f"{v:.{digits}f}"
    return str(v)


class _Table:
    """A table rendered to HTML and Markdown from the same rows."""

    def __init__(self, table_id, caption, header, rows, *, highlight=None, status_col=None):
        self.id, self.caption, self.header, self.rows = table_id, caption, header, rows
        self.highlight = highlight or [False] * len(rows)
        self.status_col = status_col

    def html(self):
        out = [f'<table id="{self.id}"><caption>{html.escape(self.caption)}</caption><thead><tr>']
        out += [f'<th class="{"name" if i == 0 else ""}">{html.escape(h)}</th>'
                for i, h in enumerate(self.header)]
        out.append("</tr></thead><tbody>")
        for row, hl in zip(self.rows, self.highlight):
            out.append('<tr class="governing">' if hl else "<tr>")
            for i, cell in enumerate(row):
                cls = "name" if i == 0 else ""
                if i == self.status_col:
                    cls = {"PASS": "pass", "FAIL": "fail"}.get(cell, "")
                out.append(f'<td class="{cls}">{html.escape(cell)}</td>')
            out.append("</tr>")
        out.append("</tbody></table>")
        return "".join(out)

    def markdown(self):
        lines = [f"**{self.caption}**", "", "| " + " | ".join(self.header) + " |",
                 "|" + "|".join(["---"] * len(self.header)) + "|"]
        for row, hl in zip(self.rows, self.highlight):
            cells = [f"**{c}**" if hl else c for c in row]
            lines.append("| " + " | ".join(cells) + " |")
        return "\n".join(lines) + "\n"


def _check_cells(c, j: int, checked: bool) -> list[str]:
    """The design-check cells of line ``j`` of a check Dataset (kN, factors, utilisation,
    verdict, simple safety factor), shared by the ULS and ALS tables."""
    return [_fmt(c["t_c_mean"].values[j] * _KN), _fmt(c["t_c_dyn"].values[j] * _KN),
            _fmt(c["t_c"].values[j] * _KN), _fmt(c["s_c"].values[j] * _KN),
            _fmt(c["gamma_mean"].values[j], 2), _fmt(c["gamma_dyn"].values[j], 2),
            _fmt(c["design_tension"].values[j] * _KN), _fmt(c["utilisation"].values[j], 3),
            ("PASS" if c["passed"].values[j] else "FAIL") if checked else "failed line",
            _fmt(c["safety_factor"].values[j], 2)]


def _line_table(checks, ct, stats, ls, als_detail=None):
    c = checks.sel(limit_state=ls)
    if ls == "ALS" and als_detail is not None:
        return _line_table_als(checks, c, als_detail)
    header = ["line", "mean [kN]", "std [kN]", "max obs. [kN]", "Gumbel MPM [kN]",
              "Gumbel 90% [kN]", "T_C-mean [kN]", "T_C-dyn [kN]", "T_C [kN]", "S_C [kN]",
              "gamma_mean", "gamma_dyn", "design T [kN]", "utilisation", "check",
              "SF = MBS/T_C"]
    rows, hl = [], []
    std = stats["line_tension_std"].mean("seed") if ls == "ULS" else None
    for j, line in enumerate(c["line"].values):
        checked = bool(c["checked"].values[j])
        row = [str(line)]
        if ls == "ULS":
            row += [_fmt(ct["t_c_mean"].values[j] * _KN), _fmt(float(std.values[j]) * _KN),
                    _fmt(ct["max_observed"].values[j] * _KN), _fmt(ct["gumbel_mpm"].values[j] * _KN),
                    _fmt(ct["gumbel_p90"].values[j] * _KN)]
        else:
            row += ["", "", "", "", ""]
        row += _check_cells(c, j, checked)
        if bool(c["common_factor_applied"].values[j]):
            row[11] += " (common 1.3)"
        rows.append(row)
        hl.append(bool(c["governing"].values[j]))
    caption = (f"{ls}: per-line tensions and DNV-OS-E301 check (consequence class "
               f"{checks.attrs['consequence_class']}, {checks.attrs['analysis']} analysis); "
               f"governing line {c['governing_line'].item()} highlighted")
    return _Table(f"lines_{ls.lower()}", caption, header, rows, highlight=hl, status_col=14)


_ROTATIONS = ("roll", "pitch", "yaw")


def _dof_scale(dof) -> tuple[str, float]:
    """Display unit and factor of a DOF (rotations in degrees)."""
    return ("deg", 180.0 / np.pi) if str(dof) in _ROTATIONS else ("m", 1.0)


def _gumbel_or_nan(maxima):
    """(MPM, 90 % value) of a Gumbel fit of the seed maxima; NaN when it cannot be fitted."""
    mx = np.asarray(maxima, float)
    if mx.size < 3 or np.ptp(mx) <= 0:
        return np.nan, np.nan
    try:
        fit = gumbel_fit(mx)
    except SceneError:
        return np.nan, np.nan
    return fit.mpm, fit.p90


def _motion_rows(stats):
    """Per channel (horizontal offset, then each DOF): name, unit, factor, per-seed stats."""
    rows = []
    if "offset_mean" in stats:
        rows.append(("horizontal offset", "m", 1.0,
                     {k: stats[f"offset_{k}"].values for k in
                      ("mean", "std", "max", "min", "lf_max", "wf_sig")}))
    if "motion_mean" in stats:
        for j, dof in enumerate(stats["dof"].values):
            unit, f = _dof_scale(dof)
            rows.append((str(dof), unit, f, {k: stats[f"motion_{k}"].values[:, j] for k in
                                             ("mean", "std", "max", "min", "lf_max", "wf_sig")}))
    return rows


def _line_table_als(checks, c, als_detail):
    """ALS table: statistics of the ALS seeds for the lines not failed."""
    act, astats = als_detail
    names = [str(v) for v in act["line"].values]
    std = astats["line_tension_std"].mean("seed")
    header = ["line", "mean [kN]", "std [kN]", "max obs. [kN]", "Gumbel MPM [kN]",
              "Gumbel 90% [kN]", "T_C-mean [kN]", "T_C-dyn [kN]", "T_C [kN]", "S_C [kN]",
              "gamma_mean", "gamma_dyn", "design T [kN]", "utilisation", "check",
              "SF = MBS/T_C"]
    rows, hl = [], []
    for j, line in enumerate(c["line"].values):
        checked = bool(c["checked"].values[j])
        row = [str(line)]
        if checked and str(line) in names:
            k = names.index(str(line))
            row += [_fmt(act["t_c_mean"].values[k] * _KN),
                    _fmt(float(std.sel(line=_line_key(std, line))) * _KN),
                    _fmt(act["max_observed"].values[k] * _KN), _fmt(act["gumbel_mpm"].values[k] * _KN),
                    _fmt(act["gumbel_p90"].values[k] * _KN)]
        else:
            row += ["", "", "", "", ""]
        row += _check_cells(c, j, checked)
        rows.append(row)
        hl.append(bool(c["governing"].values[j]))
    caption = (f"ALS: per-line tensions of the seeds with line(s) "
               f"{checks.attrs.get('failed_lines', '?')} failed and DNV-OS-E301 check "
               f"(consequence class {checks.attrs['consequence_class']}, "
               f"{checks.attrs['analysis']} analysis); governing line "
               f"{c['governing_line'].item()} highlighted")
    return _Table("lines_als", caption, header, rows, highlight=hl, status_col=14)


def _motion_table(stats):
    rows_in = _motion_rows(stats)
    if not rows_in:
        return None
    header = ["DOF", "unit", "mean", "std", "max", "min", "LF max", "WF sig",
              "Gumbel MPM of max", "Gumbel 90% of max"]
    rows = []
    for name, unit, f, v in rows_in:
        mpm, p90 = _gumbel_or_nan(v["max"] * f)
        rows.append([name, unit, _fmt(float(v["mean"].mean()) * f, 3),
                     _fmt(float(v["std"].mean()) * f, 3), _fmt(float(np.max(v["max"])) * f, 3),
                     _fmt(float(np.min(v["min"])) * f, 3), _fmt(float(v["lf_max"].mean()) * f, 3),
                     _fmt(float(v["wf_sig"].mean()) * f, 3), _fmt(mpm, 3), _fmt(p90, 3)])
    return _Table("offsets", "Offsets and motions: mean over seeds of mean, std, LF max (mean "
                  "included) and WF significant value; max/min over all seeds; Gumbel most "
                  "probable and 90 % values of the seed maxima (rotations in degrees)",
                  header, rows)


def _fd_lines_table(fd, checks, ct, stats):
    """Frequency-domain line tensions (Wang (2016) figure 5.9 columns) beside the TD Gumbel
    values."""
    c = checks.sel(limit_state="ULS")
    header = ["line", "TD mean [kN]", "FD static [kN]", "TD Gumbel MPM [kN]",
              "TD Gumbel 90% [kN]", "FD max total [kN]", "FD max / TD MPM",
              "SF TD = MBS/T_C", "SF FD = MBS/FD max"]
    rows, hl = [], []
    for j, line in enumerate(c["line"].values):
        k = _line_key(fd, line)
        failed = bool(fd["line_failed"].sel(line=k)) if "line_failed" in fd else False
        fmax = float(fd["tension_max_total"].sel(line=k))
        mpm = float(ct["gumbel_mpm"].values[j])
        row = [str(line), _fmt(ct["t_c_mean"].values[j] * _KN),
               _fmt(float(fd["tension_static"].sel(line=k)) * _KN), _fmt(mpm * _KN),
               _fmt(ct["gumbel_p90"].values[j] * _KN)]
        if failed:
            row += ["failed", "", _fmt(c["safety_factor"].values[j], 2), ""]
        else:
            row += [_fmt(fmax * _KN), _fmt(fmax / mpm, 3), _fmt(c["safety_factor"].values[j], 2),
                    _fmt(float(fd["safety_factor"].sel(line=k)), 2)]
        rows.append(row)
        hl.append(bool(c["governing"].values[j]))
    dur = fd.attrs.get("duration", float("nan"))
    caption = (f"Frequency domain beside time domain: per-line maximum tension (FD: Wang (2016) "
               f"eq. 2.49 with Rayleigh maxima over {_fmt(float(dur), 0)} s, the columns of its "
               f"figure 5.9; TD: Gumbel fit of the seed maxima over the statistics window "
               f"{stats.attrs['window_start_s']:g} - {stats.attrs['window_end_s']:g} s)")
    return _Table("fd_lines", caption, header, rows, highlight=hl)


def _fd_offsets_table(fd, stats):
    """Frequency-domain motions (mean, Wang (2016) eq. 2.49 max/min) beside the TD statistics."""
    if "motion_mean" not in stats:
        return None
    header = ["DOF", "unit", "TD mean", "FD mean", "TD Gumbel MPM of max", "TD Gumbel 90% of max",
              "FD max total", "TD min (all seeds)", "FD min total"]
    rows = []
    fd_dofs = [str(d) for d in fd["dof"].values]
    for j, dof in enumerate(stats["dof"].values):
        if str(dof) not in fd_dofs:
            continue
        i = fd_dofs.index(str(dof))
        unit, f = _dof_scale(dof)
        mpm, p90 = _gumbel_or_nan(stats["motion_max"].values[:, j] * f)
        rows.append([str(dof), unit, _fmt(float(stats["motion_mean"].values[:, j].mean()) * f, 3),
                     _fmt(float(fd["mean"].values[i]) * f, 3), _fmt(mpm, 3), _fmt(p90, 3),
                     _fmt(float(fd["max_total"].values[i]) * f, 3),
                     _fmt(float(np.min(stats["motion_min"].values[:, j])) * f, 3),
                     _fmt(float(fd["min_total"].values[i]) * f, 3)])
    return _Table("fd_offsets", "Offsets, frequency domain beside time domain: FD mean = static "
                  "equilibrium, FD max/min total = Wang (2016) eq. 2.49; TD as in the offsets "
                  "table",
                  header, rows)


def _check_fd(fd, lines):
    if not isinstance(fd, xr.Dataset):
        raise argument_error("fd", "a frequency-domain result Dataset (floatmoor fd --out)",
                             type(fd).__name__)
    need = ("tension_static", "tension_max_total", "safety_factor", "mean", "max_total",
            "min_total")
    missing = [v for v in need if v not in fd]
    if missing or "line" not in fd.dims:
        raise argument_error("fd", "a floatmoor frequency-domain result (variables "
                             + ", ".join(need) + " over 'line' and 'dof')", f"missing {missing}")
    fd_lines = sorted(map(str, fd["line"].values))
    if fd_lines != sorted(map(str, lines)):
        raise argument_error("fd.line",
                             f"the lines of the time-domain results {list(map(str, lines))}",
                             fd_lines)


def _png(fig) -> bytes:
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=90, bbox_inches="tight")
    return buf.getvalue()


def _plots(results, checks, ct, stats, start, end):
    """Return list of (name, caption, png bytes); empty if matplotlib is missing."""
    try:
        from matplotlib.figure import Figure  # no pyplot: no global state, no backend switch
    except ImportError:
        return []

    def subplots(figsize):
        fig = Figure(figsize=figsize)
        return fig, fig.subplots()

    out = []
    gov = checks["governing_line"].sel(limit_state="ULS").item()
    # the seed with the largest maximum of the governing line
    k = int(np.argmax(stats["line_tension_max"].sel(line=_line_key(stats, gov)).values))
    first = window(results[k], start, end)
    seed_k = results[k].attrs.get("seed", k)
    # 1. governing line time series
    fig, ax = subplots((9, 3))
    tl = first["line_tension"].sel(line=_line_key(first, gov))
    ax.plot(first["time"].values, tl.values * _KN, lw=0.6)
    ax.axhline(float(ct["t_c"].sel(line=_line_key(ct, gov))) * _KN, color="C3", ls="--",
               label="T_C (Gumbel 90 %)")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("tension [kN]")
    ax.set_title(f"line {gov}, seed {seed_k} (the seed with its largest maximum)")
    ax.legend(fontsize="small")
    out.append(("timeseries_governing", f"Tension time series of the governing line {gov}, "
                f"seed {seed_k} (statistics window)", _png(fig)))
    # 2. Gumbel plot of the governing line
    fit = gumbel_fit(stats["line_tension_max"].sel(line=_line_key(stats, gov)).values * _KN,
                     method=checks.attrs.get("gumbel_method", "mle"))
    fig, ax = subplots((5.5, 4))
    fit.plot(ax, label="seed maxima", unit="kN")
    ax.set_title(f"Gumbel plot, line {gov}")
    out.append(("gumbel_governing", f"Gumbel probability plot of the seed maxima of line {gov}",
                _png(fig)))
    # 3. tension per line
    c = checks.sel(limit_state="ULS")
    x = np.arange(c.sizes["line"])
    fig, ax = subplots((8, 3.5))
    ax.plot(x, c["t_c_mean"].values * _KN, "o-", label="T_C-mean")
    ax.plot(x, c["t_c"].values * _KN, "s-", label="T_C (ULS)")
    ax.plot(x, c["design_tension"].values * _KN, "^-", label="design tension (ULS)")
    if "ALS" in checks["limit_state"].values:
        ax.plot(x, checks.sel(limit_state="ALS")["t_c"].values * _KN, "v--", label="T_C (ALS)")
    ax.plot(x, c["s_c"].values * _KN, "k:", label="S_C")
    ax.set_xticks(x, [str(v) for v in c["line"].values])
    ax.set_xlabel("line")
    ax.set_ylabel("tension [kN]")
    ax.legend(fontsize="small")
    out.append(("tension_per_line", "Characteristic and design tension per line against S_C",
                _png(fig)))
    # 4. offset
    if "motion" in first:
        fig, ax = subplots((9, 3))
        m = first["motion"]
        if "offset" in first:
            ax.plot(first["time"].values, first["offset"].values, lw=0.8, color="k",
                    label="horizontal offset")
        for dof in ("surge", "sway"):
            if "dof" in m.coords and dof in m["dof"].values:
                ax.plot(first["time"].values, m.sel(dof=dof).values, lw=0.6, label=dof)
        ax.set_xlabel("time [s]")
        ax.set_ylabel("offset [m]")
        ax.legend(fontsize="small")
        ax.set_title(f"offset, seed {seed_k}")
        out.append(("offset", f"Offset time series, seed {seed_k} (statistics window)",
                    _png(fig)))
    return out


def _line_key(ds, name):
    for v in ds["line"].values:
        if str(v) == str(name):
            return v
    raise KeyError(name)


def build_report(results: Sequence[xr.Dataset], mbs, out_dir, *,
                 als_results: Sequence[xr.Dataset] | None = None,
                 failed_lines: Sequence | None = None, consequence_class: int = 2,
                 analysis: str = "dynamic", start: float | None = None, end: float | None = None,
                 cutoff: float = DEFAULT_CUTOFF_HZ, p: float = 0.9, method: str = "mle",
                 title: str | None = None, plots: bool = True, fd: xr.Dataset | None = None,
                 failed_seeds: Sequence[str] = (), extra_meta: Sequence[tuple] = (),
                 fatigue: xr.Dataset | None = None) -> ReportFiles:
    """Write the DNV-OS-E301 report of a set of seeds (HTML, Markdown, CSV, netCDF).

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
        More rows for the report's header table (e.g. the results folder).
    fatigue : xarray.Dataset, optional
        A ``floatmoor fatigue`` result: adds the FLS section (:mod:`.fatigue_report`).

    Returns
    -------
    ReportFiles
    """
    results = [_prepared(ds) for ds in _check_results(results, "results")]
    plot_start = transient_of(results) if start is None else start
    checks, stats, ct, als_detail = summarise(results, mbs, als_results=als_results, return_als=True,
                                  failed_lines=failed_lines,
                                  consequence_class=consequence_class, analysis=analysis,
                                  start=start, end=end, cutoff=cutoff, p=p, method=method)
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    if fd is not None:
        _check_fd(fd, ct["line"].values)
    scene = scene_name(results[0])
    title = title or f"Mooring design report: {scene}"
    seeds = [int(s) for s in stats["seed"].values]
    a0 = results[0].attrs
    software = f"floatmoor {_version()} (report)"
    run_versions = sorted({str(ds.attrs["version_floatmoor"]) for ds in results
                           if "version_floatmoor" in ds.attrs})
    if run_versions:
        software += f"; results computed with floatmoor {', '.join(run_versions)}"
    meta = [("scene", scene)]
    if a0.get("scene_file"):
        meta.append(("scene file", str(a0["scene_file"])))
    meta += [
        ("software", software),
        ("generated", _dt.datetime.now(_dt.UTC).strftime("%Y-%m-%d %H:%M UTC")),
        ("standard", dnv.SOURCE),
        ("edition", dnv.EDITION),
        ("consequence class", str(consequence_class)),
        ("analysis of WF tension", analysis),
        ("seeds", f"{len(seeds)}: {', '.join(map(str, seeds))}"),
    ]
    if failed_seeds:
        meta.append(("failed seeds (left out)", "; ".join(map(str, failed_seeds))))
    if "dt" in a0 and "duration" in a0:
        meta.append(("simulation", f"{float(a0['duration']):g} s at dt {float(a0['dt']):g} s; "
                     f"models: {', '.join(np.atleast_1d(a0.get('models', [])).astype(str))}"))
    meta += [
        ("statistics window", f"{stats.attrs['window_start_s']:g} - {stats.attrs['window_end_s']:g} s"),
        ("LF/WF cut-off", f"{stats.attrs['cutoff_hz']:.5f} Hz ({stats.attrs['filter']})"),
        ("characteristic tension", f"Gumbel ({method}) {p:g} fractile of the seed maxima"),
        ("governing", f"line {checks.attrs['governing_line']} in {checks.attrs['governing_limit_state']}, "
                      f"utilisation {checks.attrs['max_utilisation']:.3f}"
                      + (f" (equal within 0.1 %: {checks.attrs['governing_ties']})"
                         if checks.attrs["governing_ties"] else "")),
        ("verdict", "all lines pass" if checks.attrs["all_passed"] else "at least one line FAILS"),
    ]
    if "failed_lines" in checks.attrs:
        meta.append(("ALS failed line(s)", checks.attrs["failed_lines"]))
        meta.append(("ALS seeds", str(checks.attrs.get("n_seeds_als", ""))))
    if fd is not None:
        meta.append(("frequency domain", f"{fd.attrs.get('scene_name', '')}, duration "
                     f"{_fmt(float(fd.attrs.get('duration', float('nan'))), 0)} s, drift "
                     f"{fd.attrs.get('drift_method', '?')}, tension model "
                     f"{fd.attrs.get('tension_model', '?')}"))
    meta += [(str(k), str(v)) for k, v in extra_meta]
    tables = [_line_table(checks, ct, stats, ls, als_detail)
              for ls in checks["limit_state"].values]
    mt = _motion_table(stats)
    if mt is not None:
        tables.append(mt)
    if fd is not None:
        tables.append(_fd_lines_table(fd, checks, ct, stats))
        ft = _fd_offsets_table(fd, stats)
        if ft is not None:
            tables.append(ft)
    if fatigue is not None:  # the FLS section
        from .fatigue_report import fls_meta, fls_tables
        meta += fls_meta(fatigue)
        tables += fls_tables(fatigue)
    figs = _plots(results, checks, ct, stats, plot_start, end) if plots else []

    # HTML
    parts = ["<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'>",
             f"<title>{html.escape(title)}</title><style>{_CSS}</style></head><body>",
             f"<h1>{html.escape(title)}</h1>", '<table class="meta" id="meta"><tbody>']
    parts += [f"<tr><th class='name'>{html.escape(k)}</th><td>{html.escape(v)}</td></tr>"
              for k, v in meta]
    parts.append("</tbody></table>")
    scene_yaml = str(a0.get("scene", ""))
    if "\n" in scene_yaml:
        parts.append("<details><summary>scene file as run</summary><pre>"
                     f"{html.escape(scene_yaml)}</pre></details>")
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
    parts.append(f"<p class='note'>{html.escape(dnv.SOURCE)}.</p></body></html>")
    html_path = out / "report.html"
    html_path.write_text("".join(parts), encoding="utf-8")

    # Markdown (+ PNG files)
    md = [f"# {title}", ""] + [f"- **{k}**: {v}" for k, v in meta] + [""]
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
            "passed", "safety_factor", "governing"]
    extra = {"td_mean[N]": ct["t_c_mean"].values, "td_std[N]":
             stats["line_tension_std"].mean("seed").values,
             "gumbel_mpm[N]": ct["gumbel_mpm"].values, "gumbel_p90[N]": ct["gumbel_p90"].values}
    if fd is not None:
        order = [_line_key(fd, ln) for ln in ct["line"].values]
        extra["fd_max_total[N]"] = fd["tension_max_total"].sel(line=order).values
        extra["fd_safety_factor[1]"] = fd["safety_factor"].sel(line=order).values
    rows = ["limit_state,line," + ",".join(f"{c}[{checks[c].attrs['units']}]" for c in cols)
            + "," + ",".join(extra)]
    for ls in checks["limit_state"].values:
        c = checks.sel(limit_state=ls)
        for j, line in enumerate(c["line"].values):
            vals = []
            for col in cols:
                v = c[col].values[j]
                vals.append(str(int(v)) if isinstance(v, (bool, np.bool_)) else repr(float(v)))
            # intact-system (ULS) statistics; empty in the ALS rows
            vals += [repr(float(v[j])) if ls == "ULS" else "" for v in extra.values()]
            rows.append(f"{ls},{line}," + ",".join(vals))
    csv_path = out / "summary.csv"
    csv_path.write_text("\n".join(rows) + "\n", encoding="utf-8")

    # netCDF
    nc = checks.copy()
    nc["governing_line"] = nc["governing_line"].astype(str)
    for name in ("passed", "checked", "governing", "common_factor_applied"):
        nc[name] = nc[name].astype(np.int8)
    for name, var in ct.data_vars.items():
        nc[f"uls_{name}"] = var
    for name, var in stats.data_vars.items():
        nc[f"seed_{name}"] = var
    nc.attrs["scene"] = scene
    if "\n" in scene_yaml:
        nc.attrs["scene_yaml"] = scene_yaml
    if failed_seeds:
        nc.attrs["failed_seeds"] = "; ".join(map(str, failed_seeds))
    if fd is not None:
        order = [_line_key(fd, ln) for ln in nc["line"].values]
        for name, new_name in (("tension_static", "fd_tension_static"),
                               ("tension_max_total", "fd_tension_max_total"),
                               ("safety_factor", "fd_safety_factor")):
            nc[new_name] = xr.DataArray(fd[name].sel(line=order).values, dims=("line",),
                                        attrs=dict(fd[name].attrs))
    nc.attrs["software"] = f"floatmoor {_version()}"
    nc_path = out / "summary.nc"
    nc.to_netcdf(nc_path)
    return ReportFiles(html=html_path, markdown=md_path, csv=csv_path, netcdf=nc_path,
                       checks=checks, statistics=stats, characteristic=ct)

"""The tables and plots of the design report (:mod:`floatmoor.post.report`).

Every table is a :class:`Table` rendered to HTML and Markdown from the same rows.  Units are
in the column headers (kN, m, deg); a column holds one unit.
"""

from __future__ import annotations

import html
import io

import numpy as np

from ..core.errors import SceneError, argument_error
from .extremes import gumbel_fit
from .timeseries import window

__all__ = ["CSS", "Table", "anchor_table", "capacity_table", "check_fd", "code_values_table",
           "fd_lines_table", "fd_offsets_table", "fibre_table", "fmt", "line_key", "line_label",
           "line_table", "motion_table", "offset_tables", "plots"]

KN = 1e-3

CSS = """
body{font-family:system-ui,Segoe UI,Helvetica,Arial,sans-serif;margin:2em;max-width:1400px;color:#222}
.scroll{overflow-x:auto;max-width:100%}
h1{font-size:1.5em}h2{font-size:1.2em;margin-top:1.6em;border-bottom:1px solid #ccc}
h3{font-size:1.0em;margin:0.8em 0 0.3em}
table{border-collapse:collapse;margin:0.6em 0;font-size:0.9em}
th,td{border:1px solid #bbb;padding:3px 7px;text-align:right;vertical-align:top}
td{white-space:nowrap}th{background:#eef}td.name,th.name,td.text{text-align:left}
td.text{white-space:normal;min-width:6em}td.wide{white-space:normal;min-width:24em;text-align:left}
caption{text-align:left;font-size:0.9em;color:#444;padding:0.2em 0;max-width:60em}
tr.governing td{background:#ffe08a;font-weight:bold}
td.fail{color:#b00;font-weight:bold}td.pass{color:#070}td.notchecked{color:#856404}
.meta td{text-align:left;white-space:normal}figure{display:inline-block;margin:0.5em}figcaption{font-size:0.85em}
.note{font-size:0.85em;color:#555}
pre{background:#f6f6f6;padding:0.6em;font-size:0.8em;overflow-x:auto}
.summary{border:2px solid #444;border-radius:6px;padding:0.8em 1.2em;margin:1em 0;background:#fcfcfc}
.summary.fail{border-color:#b00}.summary.pass{border-color:#070}
.verdict{font-size:1.3em;font-weight:bold;margin:0 0 0.4em}
.verdict.fail{color:#b00}.verdict.pass{color:#070}
.cols{display:flex;flex-wrap:wrap;gap:1.5em}.cols>div{flex:1 1 30em;min-width:0}
.kv{width:100%}.kv th{text-align:left;background:#f3f3f8;width:10em;white-space:normal}.kv td{text-align:left;white-space:normal;overflow-wrap:anywhere}
ul.omit{margin:0.3em 0;padding-left:1.4em;font-size:0.9em}
.unverified{color:#8a5a00}
"""


def fmt(v, digits=1):
    """A table cell: booleans as yes/no, NaN as n/a, floats to ``digits`` decimals."""
    if isinstance(v, (bool, np.bool_)):
        return "yes" if v else "no"
    if v is None or (isinstance(v, (float, np.floating)) and not np.isfinite(v)):
        return "n/a"
    if isinstance(v, (int, np.integer)):
        return str(int(v))
    if isinstance(v, (float, np.floating)):
        return f"{v:.{digits}f}"
    return str(v)


def line_label(name) -> str:
    """``"line 7"`` for a line named ``7``; a name that already says line stays as it is
    (``line7``, not ``line line7``)."""
    s = str(name)
    return s if s.lower().startswith("line") else f"line {s}"


class Table:
    """A table rendered to HTML and Markdown from the same rows."""

    def __init__(self, table_id, caption, header, rows, *, highlight=None, status_col=None,
                 text_cols=(), wide_cols=()):
        self.id, self.caption, self.header, self.rows = table_id, caption, header, rows
        self.highlight = highlight or [False] * len(rows)
        self.status_col = status_col
        self.text_cols = set(text_cols)
        self.wide_cols = set(wide_cols)

    def html(self):
        out = [f'<table id="{self.id}"><caption>{html.escape(self.caption)}</caption><thead><tr>']
        out += [f'<th class="{"name" if i == 0 or i in self.text_cols | self.wide_cols else ""}">'
                f"{html.escape(h)}</th>" for i, h in enumerate(self.header)]
        out.append("</tr></thead><tbody>")
        for row, hl in zip(self.rows, self.highlight):
            out.append('<tr class="governing">' if hl else "<tr>")
            for i, cell in enumerate(row):
                cls = "name" if i == 0 else ("wide" if i in self.wide_cols else
                                             "text" if i in self.text_cols else "")
                if i == self.status_col:
                    cls = {"PASS": "pass", "FAIL": "fail",
                           "NOT CHECKED": "notchecked"}.get(cell, "")
                out.append(f'<td class="{cls}">{html.escape(cell)}</td>')
            out.append("</tr>")
        out.append("</tbody></table>")
        return "".join(out)

    def markdown(self):
        lines = [f"**{self.caption}**", "", "| " + " | ".join(self.header) + " |",
                 "|" + "|".join(["---"] * len(self.header)) + "|"]
        for row, hl in zip(self.rows, self.highlight):
            cells = [f"**{c}**" if hl and c else c for c in row]
            lines.append("| " + " | ".join(cells) + " |")
        return "\n".join(lines) + "\n"


def line_key(ds, name):
    for v in ds["line"].values:
        if str(v) == str(name):
            return v
    raise KeyError(name)


# -- line tension --------------------------------------------------------------------------------
_LINE_HEADER = ["line", "mean [kN]", "std [kN]", "max obs. [kN]", "Gumbel MPM [kN]",
                "Gumbel 90% [kN]", "T_C-mean [kN]", "T_C-dyn [kN]", "T_C [kN]", "S_C [kN]",
                "gamma_mean", "gamma_dyn", "design T [kN]", "utilisation", "check",
                "SF = MBS/T_C", "S_C new [kN]", "utilisation new", "analysis", "DAF"]


def _check_cells(c, j: int, checked: bool, daf) -> list[str]:
    """The design-check cells of line ``j`` of a check Dataset (kN, factors, utilisation,
    verdict, simple safety factor, new capacity, analysis, DAF), shared by ULS and ALS."""
    cells = [fmt(c["t_c_mean"].values[j] * KN), fmt(c["t_c_dyn"].values[j] * KN),
             fmt(c["t_c"].values[j] * KN), fmt(c["s_c"].values[j] * KN),
             fmt(c["gamma_mean"].values[j], 2), fmt(c["gamma_dyn"].values[j], 2),
             fmt(c["design_tension"].values[j] * KN), fmt(c["utilisation"].values[j], 3),
             ("PASS" if c["passed"].values[j] else "FAIL") if checked else "failed line",
             fmt(c["safety_factor"].values[j], 2)]
    cells += [fmt(c["s_c_new"].values[j] * KN) if "s_c_new" in c else "",
              fmt(c["utilisation_new"].values[j], 3) if "utilisation_new" in c else "",
              str(c["analysis"].values[j]) if "analysis" in c else "",
              "" if daf is None or not np.isfinite(daf[j]) else f"{daf[j]:.3f}"]
    return cells


def _caption_tail(checks) -> str:
    tail = (f"consequence class {checks.attrs['consequence_class']}, "
            f"{checks.attrs['analysis']} analysis; {checks.attrs.get('edition', '')}")
    if int(checks.attrs.get("end_of_life_capacity", 0)):
        tail += ("; S_C is the end-of-life capacity of the weakest segment (corroded, see the "
                 "capacity table), S_C new that of the new line")
    return tail


def line_table(checks, ct, stats, ls, als_detail=None, daf=None):
    """The per-line table of a limit state (ULS: statistics of the intact seeds; ALS: of the
    seeds with the failed line)."""
    c = checks.sel(limit_state=ls)
    rows, hl = [], []
    if ls == "ALS" and als_detail is not None:
        act, astats = als_detail
        names = [str(v) for v in act["line"].values]
        std = astats["line_tension_std"].mean("seed")
    else:
        names = [str(v) for v in ct["line"].values]
        act, std = ct, stats["line_tension_std"].mean("seed")
    for j, line in enumerate(c["line"].values):
        checked = bool(c["checked"].values[j])
        row = [str(line)]
        if checked and str(line) in names:
            k = names.index(str(line))
            row += [fmt(act["t_c_mean"].values[k] * KN),
                    fmt(float(std.sel(line=line_key(std, line))) * KN),
                    fmt(act["max_observed"].values[k] * KN), fmt(act["gumbel_mpm"].values[k] * KN),
                    fmt(act["gumbel_p90"].values[k] * KN)]
        else:
            row += ["", "", "", "", ""]
        row += _check_cells(c, j, checked, daf)
        if bool(c["common_factor_applied"].values[j]):
            row[11] += " (common 1.3)"
        rows.append(row)
        hl.append(bool(c["governing"].values[j]))
    if ls == "ALS":
        caption = (f"ALS: per-line tensions of the seeds with line(s) "
                   f"{checks.attrs.get('failed_lines', '?')} failed and the design check "
                   f"({_caption_tail(checks)}); governing {line_label(c['governing_line'].item())} "
                   "highlighted")
    else:
        caption = (f"ULS: per-line tensions and the design check ({_caption_tail(checks)}); "
                   f"governing {line_label(c['governing_line'].item())} highlighted"
                   + ("; DAF: the dynamic amplification of floatmoor lines applied to T_C-dyn"
                      if daf is not None and np.isfinite(daf).any() else ""))
    return Table(f"lines_{ls.lower()}", caption, list(_LINE_HEADER), rows, highlight=hl,
                 status_col=14)


def capacity_table(cap):
    """New and end-of-life capacity of every segment (:func:`floatmoor.post.capacity.
    segment_capacities`)."""
    rows, hl = [], []
    for i, line in enumerate(cap["line"].values):
        g = int(cap["governing_segment"].values[i])
        for k in cap["segment"].values:
            if not str(cap["line_type"].values[i, k]):
                continue
            rows.append([str(line), str(int(k) + 1), str(cap["line_type"].values[i, k]),
                         str(cap["material"].values[i, k]), str(cap["zones"].values[i, k]),
                         fmt(float(cap["rate"].values[i, k]), 2),
                         fmt(float(cap["diameter"].values[i, k]) * 1e3, 1),
                         fmt(float(cap["diameter_eol"].values[i, k]) * 1e3, 1),
                         fmt(float(cap["mbs"].values[i, k]) * KN, 0),
                         fmt(float(cap["mbs_eol"].values[i, k]) * KN, 0),
                         fmt(float(cap["s_c"].values[i, k]) * KN, 0),
                         fmt(float(cap["s_c_eol"].values[i, k]) * KN, 0)])
            hl.append(int(k) == g)
    a = cap.attrs
    caption = (f"Capacity: new and end-of-life (corroded) capacity per segment, from the anchor; "
               f"design life {a['design_life']:g} years ({a['design_life_source']}); chain "
               f"corrosion {a['corrosion_rates_chain']} ({a['corrosion_source']}); wire "
               f"{a['corrosion_rates_wire']}; splash zone: {a['splash_zone']}; fibre rope: no "
               "allowance; d_EOL = d - rate x life, MBS_EOL = MBS (d_EOL/d)^2; the weakest "
               "segment of each line at the end of life highlighted")
    return Table("capacity", caption,
                 ["line", "segment", "type", "material", "zones", "rate [mm/year]",
                  "d new [mm]", "d EOL [mm]", "MBS new [kN]", "MBS EOL [kN]", "S_C new [kN]",
                  "S_C EOL [kN]"], rows, highlight=hl, text_cols=(2, 3, 4))


def anchor_table(anchors_ds, ls):
    rows, hl = [], []
    u = np.where(anchors_ds["checked"].values, anchors_ds["uplift_c"].values, np.nan)
    if not (np.nan_to_num(u) > 0).any():          # no uplift: the largest design load governs
        u = np.where(anchors_ds["checked"].values, anchors_ds["design_load"].values, np.nan)
    jg = int(np.nanargmax(u)) if np.isfinite(u).any() else -1
    for j, line in enumerate(anchors_ds["line"].values):
        if not bool(anchors_ds["checked"].values[j]):
            rows.append([str(line)] + [""] * 14 + ["failed line", ""])
            hl.append(False)
            continue
        lim = float(anchors_ds["uplift_limit"].values[j])
        up_ok = bool(anchors_ds["uplift_passed"].values[j])
        load = ("PASS" if bool(anchors_ds["load_passed"].values[j]) else "FAIL") if bool(
            anchors_ds["load_checked"].values[j]) else "NOT CHECKED"
        rows.append([str(line),
                     str(anchors_ds["anchor_type"].values[j]) + ("" if bool(
                         anchors_ds["anchor_type_given"].values[j]) else " (assumed)"),
                     fmt(anchors_ds["t_c_mean"].values[j] * KN), fmt(anchors_ds["t_c"].values[j] * KN),
                     fmt(anchors_ds["gamma_mean"].values[j], 2), fmt(anchors_ds["gamma_dyn"].values[j], 2),
                     fmt(anchors_ds["design_load"].values[j] * KN),
                     fmt(anchors_ds["capacity"].values[j] * KN), fmt(anchors_ds["resistance_factor"].values[j], 2),
                     fmt(anchors_ds["utilisation"].values[j], 3),
                     fmt(anchors_ds["h_c"].values[j] * KN), fmt(anchors_ds["v_c"].values[j] * KN),
                     fmt(anchors_ds["uplift_c"].values[j], 2),
                     "none" if not np.isfinite(lim) else fmt(lim, 1),
                     fmt(anchors_ds["grounded_length_at_max_offset"].values[j], 0),
                     "PASS" if up_ok else "FAIL", load])
        hl.append(j == jg)
    caption = (f"{ls} anchors: anchor tension at the anchor (characteristic from the seeds as "
               "the line tension), design load with the code's factors against the holding "
               "capacity over the resistance factor (material factor or factor of safety); "
               "horizontal and vertical anchor force and uplift angle (quasi-static catenary at "
               "the recorded poses), grounded length at the largest offset; the governing anchor "
               "highlighted (largest uplift, else largest design load)")
    return Table(f"anchors_{ls.lower()}", caption,
                 ["line", "type", "T_C-mean [kN]", "T_C [kN]", "gamma_mean", "gamma_dyn",
                  "design load [kN]", "capacity [kN]", "resistance factor", "utilisation",
                  "H_C [kN]", "V_C [kN]", "uplift [deg]", "allowed [deg]",
                  "grounded at max offset [m]", "uplift check", "load check"], rows,
                 highlight=hl, status_col=15, text_cols=(1, 16))


def offset_tables(res, ls):
    out = []
    off = res.get("offsets")
    if off is not None:
        rows = []
        for k, name in enumerate(off["offset_limit"].values):
            applies = bool(off["applies"].values[k])
            rows.append([str(name), str(off["limit"].values[k]),
                         fmt(off["ratio_c"].values[k], 3), fmt(off["ratio_max_seen"].values[k], 3),
                         ("PASS" if bool(off["passed"].values[k]) else "FAIL") if applies
                         else f"not in the {ls}"])
        out.append(Table(f"offset_limits_{ls.lower()}",
                         f"{ls} offset limits: characteristic ratio of the horizontal offset to "
                         "the limit in its direction (Gumbel 90 % of the seed maxima; no partial "
                         f"factor); characteristic offset {off.attrs['offset_c']:.2f} m",
                         ["limit", "definition", "offset / limit (char.)",
                          "largest seen", "check"], rows, status_col=4, text_cols=(1,)))
    pts = res.get("points")
    if pts is not None:
        rows = []
        for k, name in enumerate(pts["point"].values):
            has = bool(pts["has_limit"].values[k])
            applies = bool(pts["applies"].values[k])
            status = ("PASS" if bool(pts["passed"].values[k]) else "FAIL") if (
                has and applies) else ("no limit" if not has else f"not in the {ls}")
            rows.append([str(name), fmt(pts["horizontal_c"].values[k], 2),
                         fmt(pts["up_c"].values[k], 2), fmt(pts["down_c"].values[k], 2),
                         fmt(pts["max_horizontal"].values[k], 2),
                         fmt(pts["max_vertical"].values[k], 2), status])
        out.append(Table(f"points_{ls.lower()}",
                         f"{ls} points on the body: characteristic excursions from the point's "
                         "position at zero pose (Gumbel 90 % of the seed maxima)",
                         ["point", "horizontal [m]", "up [m]", "down [m]",
                          "horizontal limit [m]", "vertical limit [m]", "check"], rows,
                         status_col=6))
    return out


def fibre_table(fib, ls):
    rows = []
    for k, line in enumerate(fib["line"].values):
        if not bool(fib["checked"].values[k]):
            rows.append([str(line), str(fib["rope_type"].values[k])] + [""] * 7
                        + ["failed line"])
            continue
        ok = (bool(fib["slack_passed"].values[k]) and bool(fib["seabed_passed"].values[k])
              and bool(fib["strength_passed"].values[k]))
        rows.append([str(line), str(fib["rope_type"].values[k]),
                     fmt(fib["t_min_c"].values[k] * KN), fmt(fib["t_min_required"].values[k] * KN),
                     fmt(fib["seabed_length_c"].values[k], 1),
                     fmt(fib["rope_mbs"].values[k] * KN, 0), fmt(fib["rope_s_c"].values[k] * KN, 0),
                     fmt(fib["design_tension"].values[k] * KN, 0),
                     fmt(fib["utilisation"].values[k], 3), "PASS" if ok else "FAIL"])
    caption = (f"{ls} fibre ropes: no slack (characteristic minimum tension of the rope, at "
               "the lower end of its lowest rope segment), no rope on the seabed "
               f"({fib.attrs['seabed_contact']} by the code), and the rope's own strength "
               "(the line's design tension at the fairlead, an upper bound, against the rope's "
               "own characteristic strength); rope fatigue: its own T-N curve in the FLS "
               "section")
    return Table(f"fibre_{ls.lower()}", caption,
                 ["line", "rope", "min tension [kN]", "required [kN]", "on seabed [m]",
                  "rope MBS [kN]", "rope S_C [kN]", "design T [kN]", "utilisation", "check"],
                 rows, status_col=9, text_cols=(1,))


def code_values_table(code, used):
    rows = []
    for e in used:
        rows.append([e.path, "verified" if e.verified else "UNVERIFIED", e.source
                     + (f" ({e.note})" if e.note else "")])
    return Table("code_values", f"Code values used: {code.name}, file "
                 f"{code.file.name}; UNVERIFIED: not checked against the standard's text",
                 ["value", "status", "source"], rows, text_cols=(1,), wide_cols=(2,))


# -- motions and the frequency domain ------------------------------------------------------------
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


def motion_table(stats):
    rows_in = _motion_rows(stats)
    if not rows_in:
        return None
    header = ["DOF", "unit", "mean", "std", "max", "min", "LF max", "WF sig",
              "Gumbel MPM of max", "Gumbel 90% of max"]
    rows = []
    for name, unit, f, v in rows_in:
        mpm, p90 = _gumbel_or_nan(v["max"] * f)
        rows.append([name, unit, fmt(float(v["mean"].mean()) * f, 3),
                     fmt(float(v["std"].mean()) * f, 3), fmt(float(np.max(v["max"])) * f, 3),
                     fmt(float(np.min(v["min"])) * f, 3), fmt(float(v["lf_max"].mean()) * f, 3),
                     fmt(float(v["wf_sig"].mean()) * f, 3), fmt(mpm, 3), fmt(p90, 3)])
    return Table("offsets", "Offsets and motions: mean over seeds of mean, std, LF max (mean "
                 "included) and WF significant value; max/min over all seeds; Gumbel most "
                 "probable and 90 % values of the seed maxima (rotations in degrees)",
                 header, rows)


def fd_lines_table(fd, checks, ct, stats):
    """Frequency-domain line tensions (Wang (2016) figure 5.9 columns) beside the TD Gumbel
    values."""
    c = checks.sel(limit_state="ULS")
    header = ["line", "TD mean [kN]", "FD static [kN]", "TD Gumbel MPM [kN]",
              "TD Gumbel 90% [kN]", "FD max total [kN]", "FD max / TD MPM",
              "SF TD = MBS/T_C", "SF FD = MBS/FD max"]
    rows, hl = [], []
    for j, line in enumerate(c["line"].values):
        k = line_key(fd, line)
        failed = bool(fd["line_failed"].sel(line=k)) if "line_failed" in fd else False
        fmax = float(fd["tension_max_total"].sel(line=k))
        mpm = float(ct["gumbel_mpm"].values[j])
        row = [str(line), fmt(ct["t_c_mean"].values[j] * KN),
               fmt(float(fd["tension_static"].sel(line=k)) * KN), fmt(mpm * KN),
               fmt(ct["gumbel_p90"].values[j] * KN)]
        if failed:
            row += ["failed", "", fmt(c["safety_factor"].values[j], 2), ""]
        else:
            row += [fmt(fmax * KN), fmt(fmax / mpm, 3), fmt(c["safety_factor"].values[j], 2),
                    fmt(float(fd["safety_factor"].sel(line=k)), 2)]
        rows.append(row)
        hl.append(bool(c["governing"].values[j]))
    dur = fd.attrs.get("duration", float("nan"))
    caption = (f"Frequency domain beside time domain: per-line maximum tension (FD: Wang (2016) "
               f"eq. 2.49 with Rayleigh maxima over {fmt(float(dur), 0)} s, the columns of its "
               f"figure 5.9; TD: Gumbel fit of the seed maxima over the statistics window "
               f"{stats.attrs['window_start_s']:g} - {stats.attrs['window_end_s']:g} s)")
    return Table("fd_lines", caption, header, rows, highlight=hl)


def fd_offsets_table(fd, stats):
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
        rows.append([str(dof), unit, fmt(float(stats["motion_mean"].values[:, j].mean()) * f, 3),
                     fmt(float(fd["mean"].values[i]) * f, 3), fmt(mpm, 3), fmt(p90, 3),
                     fmt(float(fd["max_total"].values[i]) * f, 3),
                     fmt(float(np.min(stats["motion_min"].values[:, j])) * f, 3),
                     fmt(float(fd["min_total"].values[i]) * f, 3)])
    return Table("fd_offsets", "Offsets, frequency domain beside time domain: FD mean = static "
                 "equilibrium, FD max/min total = Wang (2016) eq. 2.49; TD as in the offsets "
                 "table", header, rows)


def check_fd(fd, lines):
    import xarray as xr
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


# -- plots ---------------------------------------------------------------------------------------
def _png(fig) -> bytes:
    buf = io.BytesIO()
    fig.savefig(buf, format="png", dpi=90, bbox_inches="tight")
    return buf.getvalue()


def plots(results, checks, ct, stats, start, end):
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
    label = line_label(gov)
    # the seed with the largest maximum of the governing line
    k = int(np.argmax(stats["line_tension_max"].sel(line=line_key(stats, gov)).values))
    first = window(results[k], start, end)
    seed_k = results[k].attrs.get("seed", k)
    # 1. governing line time series
    fig, ax = subplots((9, 3))
    tl = first["line_tension"].sel(line=line_key(first, gov))
    ax.plot(first["time"].values, tl.values * KN, lw=0.6)
    ax.axhline(float(ct["t_c"].sel(line=line_key(ct, gov))) * KN, color="C3", ls="--",
               label="T_C (Gumbel 90 %)")
    ax.set_xlabel("time [s]")
    ax.set_ylabel("tension [kN]")
    ax.set_title(f"{label}, seed {seed_k} (the seed with its largest maximum)")
    ax.legend(fontsize="small")
    out.append(("timeseries_governing", f"Tension time series of the governing {label}, "
                f"seed {seed_k} (statistics window)", _png(fig)))
    # 2. Gumbel plot of the governing line
    fit = gumbel_fit(stats["line_tension_max"].sel(line=line_key(stats, gov)).values * KN,
                     method=checks.attrs.get("gumbel_method", "mle"))
    fig, ax = subplots((5.5, 4))
    fit.plot(ax, label="seed maxima", unit="kN")
    ax.set_title(f"Gumbel plot, {label}")
    out.append(("gumbel_governing", f"Gumbel probability plot of the seed maxima of {label}",
                _png(fig)))
    # 3. tension per line
    c = checks.sel(limit_state="ULS")
    x = np.arange(c.sizes["line"])
    fig, ax = subplots((8, 3.5))
    ax.plot(x, c["t_c_mean"].values * KN, "o-", label="T_C-mean")
    ax.plot(x, c["t_c"].values * KN, "s-", label="T_C (ULS)")
    ax.plot(x, c["design_tension"].values * KN, "^-", label="design tension (ULS)")
    if "ALS" in checks["limit_state"].values:
        ax.plot(x, checks.sel(limit_state="ALS")["t_c"].values * KN, "v--", label="T_C (ALS)")
    ax.plot(x, c["s_c"].values * KN, "k:", label="S_C")
    if "s_c_new" in c and not np.allclose(c["s_c_new"].values, c["s_c"].values):
        ax.plot(x, c["s_c_new"].values * KN, color="0.6", ls=":", label="S_C new")
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

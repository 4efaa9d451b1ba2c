"""One report across a campaign's matrix: governing cases, FD against TD, seed convergence.

:func:`analyse` reads a campaign folder (:mod:`floatmoor.campaign.store`) and returns the
numbers; :func:`write_report` writes ``report.html`` (self-contained, plots as base64 PNG when
matplotlib is installed), ``report.md``, ``governing.csv``, ``td_cases.csv`` and ``summary.nc``.

* Per line and limit state (ULS: intact; ALS: failed or breaking line), the governing TD case
  (largest DNV-OS-E301 utilisation, :func:`floatmoor.campaign.screening.td_case_check`) with its
  check (T_C-mean, T_C, design tension, S_C, utilisation, pass), and the utilisation of every TD
  case and line.
* FD against TD on the cases run in both: per line, Spearman's rank correlation of the FD and TD
  utilisations over those cases and the range of the ratio TD / FD; for the cases the screening
  left out, the bound ``u_FD x max(TD/FD ratio seen)`` against the governing TD utilisation (the
  margin by which a screened-out case could not have governed, if the ratio holds).
* Seed convergence of each governing case (:mod:`floatmoor.campaign.seedconv`).
* Polar plots over the wave heading: utilisation per line (FD of every case, max over sea states
  and conditions of the limit state; TD points) and the maximum offset.

Design options: the campaign file's design code, consequence class and analysis type, unless
the report is given others (``floatmoor report DIR --code C --consequence-class N --analysis
A``): then every utilisation is recomputed with those factors from the stored tensions and the
report says so (the screening chose the TD cases with the campaign's factors).  The analysis
``auto`` follows the line model of the base scene (finite-element lines dynamic, quasi-static
lines quasi-static), as ``floatmoor report`` does; the capacity is the end-of-life one where the
code asks for it (:mod:`floatmoor.post.capacity`, from the base scene's mooring file).

The verdict has the lines of ``floatmoor report`` (:mod:`floatmoor.post.verdict`) over the
time-domain cases of each limit state: line tension (the governing case), anchor uplift and
anchor load, offsets and points, fibre ropes -- from the design statistics each storm stores
(:func:`floatmoor.post.design_statistics.add_design_statistics`), the worst case per line; the
FLS is not part of a ULS/ALS campaign (NOT CHECKED).
"""

from __future__ import annotations

import base64
import html
import io
import re
from pathlib import Path

import numpy as np

from ..post import verdict as vd
from . import store
from .screening import td_case_check
from .seedconv import DEFAULT_TOLERANCE, METHOD, fractile_interval, seeds_needed

__all__ = ["analyse", "write_report"]


class _D:
    """Design options of the report: the campaign record's, or those given to the report
    (``floatmoor report DIR --code C --consequence-class N --analysis A``), which override
    them; :attr:`source` says which, for the report text."""

    def __init__(self, d, consequence_class=None, analysis=None, code=None):
        from ..post.design_codes import load_code
        self.consequence_class = int(d["consequence_class"])
        self.analysis = d["analysis"]
        self.standard = d.get("standard", "dnv-os-e301")
        given = []
        if code is not None and load_code(code).key != load_code(self.standard).key:
            given.append(f"code {load_code(code).key} instead of the campaign's "
                         f"{load_code(self.standard).key}")
            self.standard = code
        self.code = load_code(self.standard)
        if consequence_class is not None and int(consequence_class) != self.consequence_class:
            given.append(f"consequence class {int(consequence_class)} instead of the campaign's "
                         f"{self.consequence_class}")
            self.consequence_class = int(consequence_class)
        if analysis is not None and analysis != self.analysis:
            given.append(f"{analysis} analysis instead of the campaign's {self.analysis}")
            self.analysis = analysis
        self.overridden = bool(given)
        self.source = ("given to the report (" + "; ".join(given) + "): every utilisation, FD "
                       "and TD, is recomputed with these factors from the stored tensions, but "
                       "the screening chose the time-domain cases with the campaign's factors "
                       "(the screening margins below are recomputed)" if given else
                       "of the campaign file")


def _base(rec):
    """The base scene's mooring, design keys, limits and line models (None when the scene is
    not found)."""
    from ..io.mooring_design import parse_mooring_design
    from ..io.mooring_section import parse_mooring
    from ..io.scene import load_scene
    path = rec.get("base_scene")
    if not path or not Path(path).is_file():
        return None
    scene = load_scene(path)
    node = scene.mooring_node()
    if node is None:
        return None
    site = scene.site
    system = parse_mooring(node, water_depth=site.water_depth,
                           water_density=site.water_density, gravity=site.gravity)
    models = [system.line_models.model_of(n) if system.line_models is not None
              else "quasi-static" for n in system.names]
    return {"scene": scene, "mooring": system, "design": parse_mooring_design(node),
            "limits": scene.limits, "models": models}


def _check_case(seed_max, seed_mean, mbs, eol_mbs, ls, design, analyses, skip=()):
    """The line check of one case from its seeds with the report's factors (per-line
    analysis, end-of-life capacity): ``t_c``, ``t_c_mean``, ``utilisation``,
    ``utilisation_new`` per line (NaN where not checked)."""
    from ..post.dnv_os_e301 import line_check
    base = td_case_check(seed_max, seed_mean, mbs, ls, design, skip)
    out = {k: base[k] for k in ("t_c", "t_c_mean")}
    out["utilisation"] = np.full(len(analyses), np.nan)
    out["utilisation_new"] = np.full(len(analyses), np.nan)
    for j, an in enumerate(analyses):
        if not (np.isfinite(out["t_c"][j]) and np.isfinite(out["t_c_mean"][j])):
            continue
        r = line_check(out["t_c_mean"][j], max(out["t_c"][j], out["t_c_mean"][j]), mbs[j],
                       limit_state=ls, consequence_class=design.consequence_class, analysis=an,
                       code=design.code, eol_mbs=None if eol_mbs is None else eol_mbs[j])
        out["utilisation"][j] = float(r["utilisation"])
        out["utilisation_new"][j] = float(r["utilisation_new"])
    return out


def _fd_utilisation(t_static, t_max, mbs, eol_mbs, ls, design, analyses):
    from ..post.dnv_os_e301 import line_check
    out = np.full(len(analyses), np.nan)
    for j, an in enumerate(analyses):
        tm, tc = t_static[j], t_max[j]
        if not (np.isfinite(tm) and np.isfinite(tc) and tc > 0 and tm >= 0):
            continue
        r = line_check(tm, max(tc, tm), mbs[j], limit_state=ls,
                       consequence_class=design.consequence_class, analysis=an,
                       code=design.code, eol_mbs=None if eol_mbs is None else eol_mbs[j])
        out[j] = float(r["utilisation"])
    return out


def _design_stats(out_dir, case_id, seeds):
    """The design statistics of a case's storms as the Dataset of
    :func:`floatmoor.post.design_checks.collect` (None when a storm has none)."""
    import xarray as xr
    per = []
    used = []
    for seed in seeds:
        p = store.storm_path(out_dir, case_id, seed)
        if not p.is_file():
            continue
        with xr.open_dataset(p) as ds:
            if "design_anchor_h_max" not in ds:
                return None
            d = {k[len("design_"):]: ds[k].values.copy() for k in ds.data_vars
                 if k.startswith("design_")}
            d["offset_max"] = float(ds["offset_max"].values)
            d["anchor_tension_max"] = np.where(np.isfinite(d["anchor_tension_mean"]),
                                               ds["anchor_tension_max"].values, np.nan)
            d["line"] = [str(v) for v in ds["line"].values]
            for c in ("offset_limit", "point"):
                if c in ds.coords:
                    d[c] = [str(v) for v in ds[c].values]
        per.append(d)
        used.append(int(seed))
    if len(per) < 3:
        return None
    coords = {"seed": used, "line": per[0]["line"]}
    line_vars = ("anchor_tension_max", "anchor_tension_mean", "anchor_h_max", "anchor_v_max",
                 "uplift_deg_max", "grounded_length_min", "grounded_length_at_max_offset",
                 "rope_tension_min", "rope_seabed_length_max")
    data = {k: (("seed", "line"), np.array([q[k] for q in per], float)) for k in line_vars}
    data["offset_max"] = (("seed",), np.array([q["offset_max"] for q in per]))
    if "offset_limit" in per[0]:
        coords["offset_limit"] = per[0]["offset_limit"]
        data["offset_ratio_max"] = (("seed", "offset_limit"),
                                    np.array([q["offset_ratio_max"] for q in per]))
    if "point" in per[0]:
        coords["point"] = per[0]["point"]
        for k in ("point_horizontal_max", "point_up_max", "point_down_max"):
            data[k] = (("seed", "point"), np.array([q[k] for q in per]))
    return xr.Dataset(data, coords=coords)


def _spearman(a, b) -> float:
    from scipy.stats import spearmanr
    ok = np.isfinite(a) & np.isfinite(b)
    if ok.sum() < 3 or np.ptp(a[ok]) == 0 or np.ptp(b[ok]) == 0:
        return float("nan")
    return float(spearmanr(a[ok], b[ok]).statistic)


def analyse(out_dir, tolerance: float = DEFAULT_TOLERANCE, *, consequence_class=None,
            analysis=None, code=None) -> dict:
    """The campaign report's numbers (see the module docstring).  ``code``,
    ``consequence_class`` and ``analysis`` override the campaign's design options (None: the
    campaign's)."""
    from ..post.dnv_os_e301 import line_check
    from ..post.report import resolve_analysis
    rec = store.read_record(out_dir)
    design = _D(rec["design"], consequence_class, analysis, code)
    cases = rec["cases"]
    ids = [c["case"] for c in cases]
    lines = rec["lines"]
    seeds = rec["seeds"]
    states = np.array([c["limit_state"] for c in cases])
    nc, nl = len(cases), len(lines)
    base = _base(rec)
    models = base["models"] if base is not None else ["quasi-static"] * nl
    res_an = resolve_analysis(models, design.analysis, None, design.code)
    analyses = res_an["analyses"]
    capacities = eol_ratio = None
    if base is not None:
        from ..post.capacity import segment_capacities
        capacities = segment_capacities(base["mooring"], base["design"], design.code)
        if design.code.end_of_life_capacity:
            eol_ratio = (capacities["mbs_eol_line"].values
                         / capacities["mbs_new_line"].values)
    fd = store.load_fd_table(out_dir, ids)
    u_fd = np.full((nc, nl), np.nan)
    if fd:
        for i, c in enumerate(cases):
            if np.isfinite(fd["mbs"][i]).all():
                eol = None if eol_ratio is None else fd["mbs"][i] * eol_ratio
                u_fd[i] = _fd_utilisation(fd["tension_static"][i], fd["tension_max_total"][i],
                                          fd["mbs"][i], eol, c["limit_state"], design, analyses)
    screened = np.zeros(nc, bool)     # kept by the screening rule
    sent = np.ones(nc, bool)           # sent to the time domain (run, running or failed)
    scr = Path(out_dir) / "screening.csv"
    if scr.is_file():
        rows = [r.split(",") for r in scr.read_text().splitlines()[1:] if r]
        pos = {r[0]: (int(r[2]), int(r[3])) for r in rows}
        sent = np.array([bool(pos.get(i, (1, 1))[0]) for i in ids])
        screened = np.array([bool(pos.get(i, (0, 0))[1]) for i in ids])
    st = store.load_td_statistics(out_dir, ids, seeds)
    u_td = np.full((nc, nl), np.nan)
    u_td_new = np.full((nc, nl), np.nan)
    t_c = np.full((nc, nl), np.nan)
    t_m = np.full((nc, nl), np.nan)
    n_seeds = np.zeros(nc, int)
    offset = np.full(nc, np.nan)
    eol_mbs = None
    if st:
        eol_mbs = None if eol_ratio is None else np.asarray(st["mbs"], float) * eol_ratio
        for i, c in enumerate(cases):
            mx = st["line_tension_max"][i]
            ok = np.isfinite(mx).all(axis=1)
            n_seeds[i] = int(ok.sum())
            if n_seeds[i] < 3:
                continue
            skip = tuple(lines.index(ln) for ln in _condition_lines(c["condition"]))
            r = _check_case(mx[ok], st["line_tension_mean"][i][ok], st["mbs"], eol_mbs,
                            c["limit_state"], design, analyses, skip)
            u_td[i], t_c[i], t_m[i] = r["utilisation"], r["t_c"], r["t_c_mean"]
            u_td_new[i] = r["utilisation_new"]
            offset[i] = float(np.mean(st["offset_max"][i][ok]))
    ran = n_seeds >= 3
    governing = []
    for ls in ("ULS", "ALS"):
        rows = np.nonzero((states == ls) & ran)[0]
        for j, ln in enumerate(lines):
            if rows.size == 0 or not np.isfinite(u_td[rows, j]).any():
                continue
            i = int(rows[np.nanargmax(u_td[rows, j])])
            chk = line_check(t_m[i, j], max(t_c[i, j], t_m[i, j]), st["mbs"][j], limit_state=ls,
                             consequence_class=design.consequence_class,
                             analysis=analyses[j], code=design.code,
                             eol_mbs=None if eol_mbs is None else eol_mbs[j])
            mx = st["line_tension_max"][i][:, j]
            ci = fractile_interval(mx[np.isfinite(mx)])
            # FD against TD for this line and limit state
            both = np.nonzero((states == ls) & ran & np.isfinite(u_fd[:, j]))[0]
            ratio = u_td[both, j] / u_fd[both, j]
            out_rows = np.nonzero((states == ls) & ~sent & np.isfinite(u_fd[:, j]))[0]
            u_out = float(np.nanmax(u_fd[out_rows, j])) if out_rows.size else float("nan")
            r_max = float(np.nanmax(ratio)) if ratio.size else float("nan")
            bound = u_out * r_max
            fd_gov = int(rows[np.nanargmax(u_fd[rows, j])]) if np.isfinite(
                u_fd[rows, j]).any() else -1
            all_ls = np.nonzero((states == ls) & np.isfinite(u_fd[:, j]))[0]
            fd_rank = int(1 + np.sum(u_fd[all_ls, j] > u_fd[i, j])) if np.isfinite(
                u_fd[i, j]) else -1
            governing.append({
                "limit_state": ls, "line": ln, "case": ids[i], "case_index": i,
                "sea_state": cases[i]["sea_state"], "hs": cases[i]["hs"],
                "tp": cases[i]["tp"], "wave_heading_deg": cases[i]["wave_heading_deg"],
                "wind_heading_deg": cases[i]["wind_heading_deg"],
                "current_heading_deg": cases[i]["current_heading_deg"],
                "condition": cases[i]["condition"], "n_seeds": int(n_seeds[i]),
                "t_c_mean": float(chk["t_c_mean"]), "t_c": float(chk["t_c"]),
                "design_tension": float(chk["design_tension"]), "s_c": float(chk["s_c"]),
                "s_c_new": float(chk["s_c_new"]), "utilisation_new":
                float(chk["utilisation_new"]), "analysis": analyses[j],
                "utilisation": float(chk["utilisation"]), "passed": bool(chk["passed"]),
                "gamma_mean": chk["factors"].gamma_mean, "gamma_dyn": chk["factors"].gamma_dyn,
                "u_fd": float(u_fd[i, j]), "fd_rank": fd_rank,
                "fd_governing_case": ids[fd_gov] if fd_gov >= 0 else "",
                "spearman_fd_td": _spearman(u_fd[both, j], u_td[both, j]),
                "n_both": int(both.size),
                "ratio_td_fd_min": float(np.nanmin(ratio)) if ratio.size else float("nan"),
                "ratio_td_fd_max": r_max,
                "u_fd_screened_out_max": u_out, "u_screened_out_bound": bound,
                "screening_margin": float(chk["utilisation"]) - bound,
                "t_c_low": ci["low"], "t_c_high": ci["high"],
                "t_c_half_width": ci["half_width"], "ci_wide": ci["half_width"] > tolerance,
                "seeds_needed": seeds_needed(ci["n"], ci["half_width"], tolerance),
                "in_screening": bool(screened[i]),
            })
    other = _other_checks(out_dir, cases, ids, states, seeds, n_seeds, base, design,
                          analyses)
    pending = {ls: [ids[i] for i in np.nonzero((states == ls) & sent & (n_seeds < 3))[0]]
               for ls in ("ULS", "ALS")}
    verdict = _verdict(governing, states, other, base, pending)
    return {"record": rec, "lines": lines, "cases": cases, "ids": ids, "states": states,
            "u_fd": u_fd, "u_td": u_td, "u_td_new": u_td_new, "t_c": t_c, "t_c_mean": t_m,
            "n_seeds": n_seeds, "sent": sent, "pending": pending,
            "offset": offset, "fd": fd, "governing": governing, "screened": screened,
            "tolerance": tolerance, "mbs": st["mbs"] if st else None, "design": design,
            "analysis": res_an, "capacities": capacities, "other": other,
            "verdict": verdict, "overall": vd.overall(verdict),
            "unverified": [e for e in design.code.entries_used(_used_parts(states, other,
                                                                           capacities))
                           if not e.verified]}


def _used_parts(states, other, capacities):
    parts = ["line_tension.strength_factor", "line_tension.ULS"]
    if "ALS" in set(states):
        parts.append("line_tension.ALS")
    if capacities is not None:
        parts.append("corrosion")
    if other["anchors"]:
        parts.append("anchors")
    if other["fibre"]:
        parts.append("fibre")
    return parts


def _worst(per_case: list, key: str, fn=np.nanmax):
    """Per line, the case whose ``key`` is the worst (largest by default): (Dataset rows
    stacked over cases, index of the worst case per line)."""
    import xarray as xr
    stacked = xr.concat([d for _, d in per_case], dim="case")
    vals = stacked[key].values
    vals = np.where(np.isfinite(vals), vals, -np.inf if fn is np.nanmax else np.inf)
    idx = np.argmax(vals, axis=0) if fn is np.nanmax else np.argmin(vals, axis=0)
    return stacked, idx


def _pick(stacked, idx, dim):
    """The rows of ``stacked`` (over ``case`` and ``dim``) of the worst case of each item."""
    import xarray as xr
    parts = [stacked.isel(case=int(k), **{dim: [j]}) for j, k in enumerate(idx)]
    out = xr.concat(parts, dim=dim)
    out.attrs = dict(stacked.attrs)
    return out


def _other_checks(out_dir, cases, ids, states, seeds, n_seeds, base, design, analyses):
    """Anchor, offset and fibre checks of every TD case with design statistics; per limit
    state the worst case of each line (anchors: the largest uplift angle, then the largest
    design load; fibre: the most rope on the seabed), and of each limit and point."""
    from ..post.design_checks import anchor_checks, fibre_checks, offset_checks
    out = {"anchors": {}, "offsets": {}, "fibre": {}, "missing": {"ULS": [], "ALS": []},
           "cases": {}}
    if base is None:
        return out
    for ls in ("ULS", "ALS"):
        anchor_rows, offs, fibs = [], [], []
        for i in np.nonzero((states == ls) & (n_seeds >= 3))[0]:
            stats = _design_stats(out_dir, ids[i], seeds)
            if stats is None:
                out["missing"][ls].append(ids[i])
                continue
            anchor_rows.append((ids[i], anchor_checks(stats, base["design"], design.code,
                                              limit_state=ls,
                                              consequence_class=design.consequence_class,
                                              analysis=analyses)))
            offs.append((ids[i], offset_checks(stats, base["limits"], limit_state=ls)))
            fake = xr_line_checks(stats["line"].values)
            f = fibre_checks(stats, base["mooring"], design.code, fake, limit_state=ls)
            if f is not None:
                fibs.append((ids[i], f))
        if anchor_rows:
            stacked, _ = _worst(anchor_rows, "design_load")
            up = stacked["uplift_c"].values
            load = np.where(np.isfinite(stacked["utilisation"].values),
                            stacked["utilisation"].values, stacked["design_load"].values)
            score = np.where(np.nan_to_num(up) > 0, 1e12 + np.nan_to_num(up),
                             np.nan_to_num(load, nan=-np.inf))
            idx = np.argmax(score, axis=0)
            worst = _pick(stacked, idx, "line")
            worst["case"] = ("line", np.array([anchor_rows[int(k)][0] for k in idx]))
            out["anchors"][ls] = worst
        if offs:
            res = {"offset_c": max(o["offset_c"] for _, o in offs), "offsets": None,
                   "points": None}
            for kind, dim in (("offsets", "offset_limit"), ("points", "point")):
                items = [(cid, o[kind]) for cid, o in offs if o[kind] is not None]
                if items:
                    stacked, idx = _worst(items, "ratio_c")
                    w = _pick(stacked, idx, dim)
                    w["case"] = (dim, np.array([items[int(k)][0] for k in idx]))
                    if kind == "offsets":
                        w.attrs["offset_c"] = res["offset_c"]
                    res[kind] = w
            out["offsets"][ls] = res
        if fibs:
            stacked, idx = _worst(fibs, "seabed_length_c")
            w = _pick(stacked, idx, "line")
            w["case"] = ("line", np.array([fibs[int(k)][0] for k in idx]))
            out["fibre"][ls] = w
    return out


def xr_line_checks(lines):
    """A line-check stand-in without design tensions (the fibre-rope strength is checked with
    the line tension check of the governing case instead)."""
    import xarray as xr
    n = len(lines)
    return xr.Dataset({"design_tension": ("line", np.full(n, np.nan))},
                      coords={"line": [str(v) for v in lines]})


_OLD_STORMS = ("(they were run before floatmoor stored them: run the campaign again in a new "
               "folder)")


def _verdict(governing, states, other, base, pending=None):
    """The verdict lines of the campaign (as ``floatmoor report``'s); ``pending`` (limit state
    -> case ids): cases sent to the time domain with fewer than 3 finished seeds, each limit
    state's an INCOMPLETE line naming them (the screening chose them as possibly governing,
    so the checks of the others cannot stand for the design)."""
    out = []
    for ls in ("ULS", "ALS"):
        ids = (pending or {}).get(ls) or []
        if ids:
            shown = ", ".join(ids[:5]) + (f" and {len(ids) - 5} more" if len(ids) > 5 else "")
            out.append(vd.VerdictLine(
                ls, "storms", vd.INCOMPLETE, governing=ids[0],
                text=f"{len(ids)} case(s) sent to the time domain have fewer than 3 finished "
                     f"seeds: {shown} (failed storms and their errors are in the campaign's "
                     "manifest; the same `floatmoor campaign ... --out DIR` again runs what is missing)"))
    for ls in ("ULS", "ALS"):
        g = [x for x in governing if x["limit_state"] == ls]
        if not g:
            if ls in set(states):
                out.append(vd.VerdictLine(ls, "line tension", vd.NOT_CHECKED,
                                          text="no time-domain case with 3 finished seeds"))
            else:
                out.append(vd.VerdictLine(ls, "line tension", vd.NOT_CHECKED,
                                          text="no case of this limit state in the campaign"))
            continue
        w = max(g, key=lambda x: x["utilisation"])
        n_fail = sum(1 for x in g if not x["passed"])
        text = (f"{w['line']}, case {w['case']}: T_C {w['t_c'] / 1e3:.0f} kN (mean "
                f"{w['t_c_mean'] / 1e3:.0f}), design tension {w['design_tension'] / 1e3:.0f} "
                f"kN, S_C {w['s_c'] / 1e3:.0f} kN")
        if abs(w["s_c_new"] - w["s_c"]) > 1e-6 * w["s_c"]:
            text += (f" end of life ({w['s_c_new'] / 1e3:.0f} new), utilisation "
                     f"{w['utilisation']:.3f} (new {w['utilisation_new']:.3f})")
        else:
            text += f", utilisation {w['utilisation']:.3f}"
        if n_fail:
            text += f"; {n_fail} line(s) fail"
        out.append(vd.VerdictLine(ls, "line tension", vd.PASS if w["passed"] else vd.FAIL,
                                  w["utilisation"], w["line"], text))
    out.append(vd.VerdictLine("FLS", "fatigue", vd.NOT_CHECKED,
                              text="not part of a ULS/ALS campaign (floatmoor fatigue, and "
                                   "floatmoor report --fatigue on a storm's results)"))
    limits_given = base is not None and base["limits"] is not None and bool(
        base["limits"].offset or base["limits"].points)
    for ls in ("ULS", "ALS"):
        if ls not in set(states):
            continue
        if ls not in other["anchors"]:
            ran = any(x["limit_state"] == ls for x in governing)
            why = ("the base scene is not available" if base is None else
                   "the storms carry no design statistics " + _OLD_STORMS if ran else
                   "no time-domain case with 3 finished seeds")
            for check in ("anchor uplift", "anchor load", "offsets"):
                out.append(vd.VerdictLine(ls, check, vd.NOT_CHECKED, text=why))
            continue
        gone = other.get("missing", {}).get(ls) or []
        if gone:
            # checked on the other cases only: those cannot stand for the design
            out.append(vd.VerdictLine(
                ls, "design stats", vd.INCOMPLETE, governing=gone[0],
                text=f"{len(gone)} case(s) have storms without the design statistics of the "
                     f"anchor, offset and fibre checks: {', '.join(gone[:5])} " + _OLD_STORMS))
        out += vd.anchor_lines(other["anchors"][ls], ls)
        out.append(vd.offset_line(other["offsets"].get(ls, {}), ls, limits_given))
        f = vd.fibre_line(other["fibre"].get(ls), ls)
        if f is not None:
            out.append(f)
    return out


def _condition_lines(name: str) -> list[str]:
    name = re.sub(r"_fibre-(lower|upper)$", "", name)  # the fibre stiffness bound tag
    if name == "intact":
        return []
    body = name.split("-", 1)[1]
    if name.startswith("break-"):
        body = body.rsplit("-t", 1)[0]
    return body.split("+")


# -- output -----------------------------------------------------------------------------------
_GOV_COLS = [("limit_state", "limit state", None), ("line", "line", None),
             ("sea_state", "sea state", None), ("hs", "Hs (m)", "{:g}"), ("tp", "Tp (s)", "{:g}"),
             ("wave_heading_deg", "heading (deg)", "{:g}"), ("condition", "condition", None),
             ("analysis", "analysis", None),
             ("t_c_mean", "T_C-mean (kN)", "kN"), ("t_c", "T_C (kN)", "kN"),
             ("design_tension", "design (kN)", "kN"), ("s_c", "S_C (kN)", "kN"),
             ("s_c_new", "S_C new (kN)", "kN"),
             ("utilisation", "utilisation", "{:.3f}"),
             ("utilisation_new", "utilisation new", "{:.3f}"), ("passed", "pass", None),
             ("u_fd", "FD utilisation", "{:.3f}"), ("fd_rank", "FD rank", "{}"),
             ("spearman_fd_td", "Spearman FD-TD", "{:.2f}"),
             ("screening_margin", "screening margin", "{:.3f}"),
             ("t_c_low", "T_C 90 % CI low (kN)", "kN"), ("t_c_high", "high (kN)", "kN"),
             ("t_c_half_width", "CI half-width", "{:.1%}"), ("seeds_needed", "seeds needed",
                                                             "{}")]


def _fmt(v, f):
    if f is None:
        return "PASS" if v is True else "FAIL" if v is False else str(v)
    if isinstance(v, float) and not np.isfinite(v):
        return "-"
    if f == "kN":
        return f"{v / 1e3:.0f}"
    return f.format(v)


def _governing_table(a):
    head = [c[1] for c in _GOV_COLS]
    rows = [[_fmt(g[k], f) for k, _, f in _GOV_COLS] for g in a["governing"]]
    return head, rows


def _cases_table(a):
    head = ["case", "limit state", "seeds"] + list(a["lines"]) + ["max offset (m)"]
    rows = []
    for i in np.nonzero(a["n_seeds"] >= 3)[0]:
        rows.append([a["ids"][i], a["states"][i], str(a["n_seeds"][i])]
                    + [_fmt(float(x), "{:.3f}") for x in a["u_td"][i]]
                    + [_fmt(float(a["offset"][i]), "{:.1f}")])
    return head, rows


def _md(head, rows):
    out = ["| " + " | ".join(head) + " |", "|" + "---|" * len(head)]
    out += ["| " + " | ".join(r) + " |" for r in rows]
    return "\n".join(out)


def _html_table(head, rows, mark=None):
    h = "".join(f"<th>{html.escape(x)}</th>" for x in head)
    body = []
    for k, r in enumerate(rows):
        cls = ' class="gov"' if mark and mark(k) else ""
        body.append(f"<tr{cls}>" + "".join(f"<td>{html.escape(x)}</td>" for x in r) + "</tr>")
    return f"<table><tr>{h}</tr>{''.join(body)}</table>"


def _polar_figures(a) -> dict:
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        return {}
    heads = np.array([c["wave_heading_deg"] for c in a["cases"]])
    hs = np.unique(heads)
    figs = {}
    for ls in ("ULS", "ALS"):
        rows = a["states"] == ls
        if not rows.any():
            continue
        nl = len(a["lines"])
        ncol = 4
        fig, axes = plt.subplots((nl + ncol - 1) // ncol, ncol, subplot_kw={"projection": "polar"},
                                 figsize=(3.0 * ncol, 3.0 * ((nl + ncol - 1) // ncol)))
        for j, ax in enumerate(np.ravel(axes)):
            if j >= nl:
                ax.set_visible(False)
                continue
            fdv = [np.nanmax(np.where(rows & (heads == h), a["u_fd"][:, j], np.nan))
                   if np.isfinite(np.where(rows & (heads == h), a["u_fd"][:, j], np.nan)).any()
                   else np.nan for h in hs]
            th = np.radians(np.append(hs, hs[0]))
            ax.plot(th, np.append(fdv, fdv[0]), "-", color="C0", label="FD (max)")
            td = rows & np.isfinite(a["u_td"][:, j])
            ax.plot(np.radians(heads[td]), a["u_td"][td, j], "o", color="C3", ms=3, label="TD")
            ax.set_title(a["lines"][j], fontsize=9)
            ax.tick_params(labelsize=6)
        fig.suptitle(f"{ls}: DNV-OS-E301 utilisation per line over the wave heading "
                     "(line: FD, max over sea states and conditions; dots: TD cases)")
        fig.tight_layout()
        figs[f"polar_utilisation_{ls}"] = fig
    fd = a["fd"]
    if fd and "max_total" in fd:
        mt, mn = fd["max_total"], fd["min_total"]
        off = np.hypot(np.maximum(np.abs(mt[:, 0]), np.abs(mn[:, 0])),
                       np.maximum(np.abs(mt[:, 1]), np.abs(mn[:, 1])))
        fig = plt.figure(figsize=(4.5, 4.5))
        ax = fig.add_subplot(projection="polar")
        for ls, col in (("ULS", "C0"), ("ALS", "C1")):
            rows = a["states"] == ls
            if not rows.any():
                continue
            # a heading whose cases all failed has no offset: a gap in the curve, not a warning
            v = [np.max(off[m]) if (m := rows & (heads == h) & np.isfinite(off)).any()
                 else np.nan for h in hs]
            ax.plot(np.radians(np.append(hs, hs[0])), np.append(v, v[0]), "-", color=col,
                    label=f"FD {ls}")
            td = rows & np.isfinite(a["offset"])
            ax.plot(np.radians(heads[td]), a["offset"][td], "o", ms=3, color=col,
                    label=f"TD {ls} (mean of seed maxima)")
        ax.set_title("maximum horizontal offset (m) over the wave heading", fontsize=9)
        ax.legend(fontsize=6, loc="lower left")
        figs["polar_offset"] = fig
    return figs


def _detail_tables(a) -> list:
    """The capacity, anchor, offset and fibre tables (objects with caption, html, markdown)."""
    from ..post.report_tables import anchor_table, capacity_table, fibre_table, offset_tables
    out = []
    if a["capacities"] is not None:
        out.append(capacity_table(a["capacities"]))
    o = a["other"]
    for ls, anchor_rows in o["anchors"].items():
        t = anchor_table(anchor_rows, ls)
        t.header.append("case")
        for row, cid in zip(t.rows, anchor_rows["case"].values):
            row.append(str(cid))
        t.caption = t.caption.replace(f"{ls} anchors:", f"{ls} anchors (the worst time-domain "
                                      "case of each line, named in the last column):")
        out.append(t)
    for ls, res in o["offsets"].items():
        out += offset_tables(res, ls)
    for ls, fib in o["fibre"].items():
        t = fibre_table(fib, ls)
        t.header.append("case")
        for row, cid in zip(t.rows, fib["case"].values):
            row.append(str(cid))
        out.append(t)
    return out


def write_report(out_dir, report_dir=None, tolerance: float = DEFAULT_TOLERANCE, *,
                 consequence_class=None, analysis=None, code=None) -> dict:
    """Write the campaign report; returns :func:`analyse`'s dict plus the paths written
    (``code``, ``consequence_class``, ``analysis``: see :func:`analyse`)."""
    import xarray as xr
    a = analyse(out_dir, tolerance, consequence_class=consequence_class, analysis=analysis,
                code=code)
    rd = Path(report_dir) if report_dir else Path(out_dir) / "report"
    rd.mkdir(parents=True, exist_ok=True)
    rec = a["record"]
    gh, gr = _governing_table(a)
    ch, cr = _cases_table(a)
    (rd / "governing.csv").write_text("\n".join([",".join(gh)] + [",".join(r) for r in gr])
                                      + "\n")
    (rd / "td_cases.csv").write_text("\n".join([",".join(ch)] + [",".join(r) for r in cr])
                                     + "\n")
    ds = xr.Dataset(
        {"u_fd": (("case", "line"), a["u_fd"], {"units": "1", "long_name": "FD utilisation"}),
         "u_td": (("case", "line"), a["u_td"], {"units": "1", "long_name": "TD utilisation"}),
         "t_c": (("case", "line"), a["t_c"], {"units": "N", "long_name": "TD characteristic "
                                              "tension (Gumbel 90 % of the seed maxima)"}),
         "t_c_mean": (("case", "line"), a["t_c_mean"], {"units": "N", "long_name": "TD mean "
                                                        "tension (mean over the seeds)"}),
         "n_seeds": (("case",), a["n_seeds"], {"units": "1", "long_name": "TD seeds"}),
         "max_offset": (("case",), a["offset"], {"units": "m", "long_name": "TD mean of the "
                                                 "seed maxima of the horizontal offset"}),
         "screened": (("case",), a["screened"].astype(np.int8),
                      {"units": "1", "long_name": "kept by the FD screening rule"})},
        coords={"case": a["ids"], "line": a["lines"],
                "limit_state": ("case", list(a["states"]))})
    ds["u_td_new"] = (("case", "line"), a["u_td_new"],
                      {"units": "1", "long_name": "TD utilisation of the new line"})
    ds["analysis"] = (("line",), np.array(a["analysis"]["analyses"]),
                      {"units": "", "long_name": "analysis type (partial factors) per line"})
    ds.attrs = {"campaign": rec["name"], "standard": a["design"].code.name,
                "code": a["design"].code.key,
                "consequence_class": a["design"].consequence_class,
                "analysis": a["design"].analysis,
                "analysis_reason": a["analysis"]["reason"],
                "design_options": a["design"].source,
                "verdict": a["overall"][0], "verdict_text": a["overall"][1],
                "verdict_lines": " | ".join(f"{v.label}: {v.status}" for v in a["verdict"]),
                "unverified_code_values": "; ".join(e.path for e in a["unverified"]),
                "seed_interval_method": METHOD}
    ds.to_netcdf(rd / "summary.nc")
    figs = _polar_figures(a)
    imgs = {}
    for name, fig in figs.items():
        buf = io.BytesIO()
        fig.savefig(buf, format="png", dpi=90, bbox_inches="tight")
        (rd / f"{name}.png").write_bytes(buf.getvalue())
        imgs[name] = base64.b64encode(buf.getvalue()).decode()
        import matplotlib.pyplot as plt
        plt.close(fig)
    text = _summary_text(a)
    details = _detail_tables(a)
    verdict_md = ["| limit state | check | status | governing | utilisation | detail |",
                  "|---|---|---|---|---|---|"] + [
        f"| {v.limit_state} | {v.check} | {v.status} | {v.governing} | "
        f"{_fmt(v.utilisation, '{:.3f}') if np.isfinite(v.utilisation) else '-'} | {v.text} |"
        for v in a["verdict"]]
    md = [f"# Campaign report: {rec['name']}", "", f"**Verdict: {a['overall'][1]}**", "",
          *verdict_md, "", *text, "",
          "## Governing case per line and limit state", "", _md(gh, gr), "",
          "## Utilisation of every time-domain case", "", _md(ch, cr), ""]
    for t in details:
        md += [t.markdown(), ""]
    md += [f"![{n}]({n}.png)" for n in imgs]
    (rd / "report.md").write_text("\n".join(md) + "\n")
    status_cls = "pass" if a["overall"][0] == vd.PASS else "fail"
    vrows = "".join(
        f"<tr><td>{html.escape(v.limit_state)}</td><td>{html.escape(v.check)}</td>"
        f"<td class='{ {'PASS': 'pass', 'FAIL': 'fail', 'INCOMPLETE': 'fail'}.get(v.status, 'notchecked') }'>"
        f"{html.escape(v.status)}</td><td>{html.escape(v.governing)}</td><td>"
        f"{_fmt(v.utilisation, '{:.3f}') if np.isfinite(v.utilisation) else '-'}</td>"
        f"<td style='text-align:left'>{html.escape(v.text)}</td></tr>" for v in a["verdict"])
    body = [f"<h1>Campaign report: {html.escape(rec['name'])}</h1>",
            f'<div class="summary {status_cls}" id="summary"><p class="verdict {status_cls}">'
            f"Verdict: {html.escape(a['overall'][1])}</p><table id='verdict'><tr><th>limit "
            "state</th><th>check</th><th>status</th><th>governing</th><th>utilisation</th>"
            f"<th>detail</th></tr>{vrows}</table></div>",
            "".join(f"<p>{html.escape(t)}</p>" for t in text),
            "<h2>Governing case per line and limit state</h2>",
            _html_table(gh, gr, lambda k: a["governing"][k]["utilisation"] == max(
                g["utilisation"] for g in a["governing"]
                if g["limit_state"] == a["governing"][k]["limit_state"])),
            "<h2>Utilisation of every time-domain case</h2>", _html_table(ch, cr)]
    for t in details:
        body += [f"<h2>{html.escape(t.caption.split(':')[0])}</h2>",
                 f'<div class="scroll">{t.html()}</div>']
    body += [f'<h2>{n.replace("_", " ")}</h2><img src="data:image/png;base64,{b}">'
             for n, b in imgs.items()]
    if not imgs:
        body.append("<p>No plots: matplotlib is not installed (pip install floatmoor[plot]).</p>")
    from ..post.report_tables import CSS
    css = CSS + "tr.gov{background:#fde}"
    (rd / "report.html").write_text(f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>"
                                    f"{html.escape(rec['name'])}</title><style>{css}</style>"
                                    f"</head><body>{''.join(body)}</body></html>")
    a["report_dir"] = rd
    a["summary_lines"] = text
    return a


def _summary_text(a) -> list[str]:
    rec = a["record"]
    n_td = int(np.sum(a["n_seeds"] >= 3))
    pending = sum(len(v) for v in a["pending"].values())
    d = a["design"]
    an = a["analysis"]
    out = [(f"{d.code.name}, consequence class "
            f"{d.consequence_class}, {d.analysis} analysis ({d.source}): "
            f"{an['summary']}{' (OVERRIDE)' if an['override'] else ''} -- {an['reason']}; "
            f"{len(a['cases'])} cases screened in the frequency domain, {n_td} run in the time "
            f"domain ({len(rec['seeds'])} seeds each; screening {rec['screening']})"
            + (f"; {pending} case(s) sent to the time domain have fewer than 3 finished "
               "seeds and are not in this report (campaign unfinished or failed storms)"
               if pending else "") + ".")]
    if a["unverified"]:
        out.append("unverified code values used: " + ", ".join(e.path for e in a["unverified"])
                   + f" ({d.code.file.name})")
    for ls in ("ULS", "ALS"):
        g = [x for x in a["governing"] if x["limit_state"] == ls]
        if not g:
            continue
        w = max(g, key=lambda x: x["utilisation"])
        out.append(f"{ls} governing line {w['line']}, case {w['case']} (sea state "
                   f"{w['sea_state']}, Hs {w['hs']:g} m, Tp {w['tp']:g} s, heading "
                   f"{w['wave_heading_deg']:g} deg, {w['condition']}): T_C {w['t_c'] / 1e3:.0f} "
                   f"kN, design tension {w['design_tension'] / 1e3:.0f} kN, S_C "
                   f"{w['s_c'] / 1e3:.0f} kN, utilisation {w['utilisation']:.3f} "
                   f"{'PASS' if w['passed'] else 'FAIL'}")
        margins = [x["screening_margin"] for x in g if np.isfinite(x["screening_margin"])]
        if margins:
            worst = min(g, key=lambda x: x["screening_margin"]
                        if np.isfinite(x["screening_margin"]) else np.inf)
            out.append(f"{ls} screening: the smallest margin is {worst['screening_margin']:.3f} "
                       f"(line {worst['line']}): a screened-out case, scaled by the largest TD/FD "
                       f"ratio seen ({worst['ratio_td_fd_max']:.2f}), reaches "
                       f"{worst['u_screened_out_bound']:.3f} against the governing "
                       f"{worst['utilisation']:.3f}" + (" -- it could have governed"
                                                        if worst["screening_margin"] < 0 else
                                                        ""))
        wide = [x for x in g if x["ci_wide"]]
        out.append(f"{ls} seed convergence ({METHOD}): {len(wide)} of {len(g)} governing "
                   f"line(s) have a 90 % interval of T_C wider than +-{a['tolerance']:.0%}"
                   + (": " + ", ".join(f"{x['line']} +-{x['t_c_half_width']:.1%} "
                                       f"({x['seeds_needed']} seeds needed)" for x in wide)
                      if wide else ""))
    return out

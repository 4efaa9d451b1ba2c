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

Design options: the campaign file's consequence class and analysis type, unless the report is
given others (``floatmoor report DIR --consequence-class N --analysis A``): then every
utilisation is recomputed with those factors from the stored tensions and the report says so
(the screening chose the TD cases with the campaign's factors).
"""

from __future__ import annotations

import base64
import html
import io
import re
from pathlib import Path

import numpy as np

from . import store
from .screening import td_case_check, utilisation
from .seedconv import DEFAULT_TOLERANCE, METHOD, fractile_interval, seeds_needed

__all__ = ["analyse", "write_report"]


class _D:
    """Design options of the report: the campaign record's, or those given to the report
    (``floatmoor report DIR --consequence-class N --analysis A``), which override them;
    :attr:`source` says which, for the report text."""

    def __init__(self, d, consequence_class=None, analysis=None):
        self.consequence_class = int(d["consequence_class"])
        self.analysis = d["analysis"]
        self.standard = d.get("standard", "dnv-os-e301")
        given = []
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


def _spearman(a, b) -> float:
    from scipy.stats import spearmanr
    ok = np.isfinite(a) & np.isfinite(b)
    if ok.sum() < 3 or np.ptp(a[ok]) == 0 or np.ptp(b[ok]) == 0:
        return float("nan")
    return float(spearmanr(a[ok], b[ok]).statistic)


def analyse(out_dir, tolerance: float = DEFAULT_TOLERANCE, *, consequence_class=None,
            analysis=None) -> dict:
    """The campaign report's numbers (see the module docstring).  ``consequence_class`` and
    ``analysis`` override the campaign's design options (None: the campaign's)."""
    from ..post.dnv_os_e301 import line_check
    rec = store.read_record(out_dir)
    design = _D(rec["design"], consequence_class, analysis)
    cases = rec["cases"]
    ids = [c["case"] for c in cases]
    lines = rec["lines"]
    seeds = rec["seeds"]
    states = np.array([c["limit_state"] for c in cases])
    fd = store.load_fd_table(out_dir, ids)
    nc, nl = len(cases), len(lines)
    u_fd = np.full((nc, nl), np.nan)
    if fd:
        for i, c in enumerate(cases):
            if np.isfinite(fd["mbs"][i]).all():
                u_fd[i] = utilisation(fd["tension_static"][i], fd["tension_max_total"][i],
                                      fd["mbs"][i], c["limit_state"], design)
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
    t_c = np.full((nc, nl), np.nan)
    t_m = np.full((nc, nl), np.nan)
    n_seeds = np.zeros(nc, int)
    offset = np.full(nc, np.nan)
    if st:
        for i, c in enumerate(cases):
            mx = st["line_tension_max"][i]
            ok = np.isfinite(mx).all(axis=1)
            n_seeds[i] = int(ok.sum())
            if n_seeds[i] < 3:
                continue
            skip = tuple(lines.index(ln) for ln in _condition_lines(c["condition"]))
            r = td_case_check(mx[ok], st["line_tension_mean"][i][ok], st["mbs"],
                              c["limit_state"], design, skip)
            u_td[i], t_c[i], t_m[i] = r["utilisation"], r["t_c"], r["t_c_mean"]
            offset[i] = float(np.mean(st["offset_max"][i][ok]))
    ran = n_seeds >= 3
    governing = []
    for ls in ("ULS", "ALS"):
        rows = np.nonzero((states == ls) & ran)[0]
        for j, ln in enumerate(lines):
            if rows.size == 0 or not np.isfinite(u_td[rows, j]).any():
                continue
            i = int(rows[np.nanargmax(u_td[rows, j])])
            chk = line_check(t_m[i, j], t_c[i, j], st["mbs"][j], limit_state=ls,
                             consequence_class=design.consequence_class,
                             analysis=design.analysis)
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
    return {"record": rec, "lines": lines, "cases": cases, "ids": ids, "states": states,
            "u_fd": u_fd, "u_td": u_td, "t_c": t_c, "t_c_mean": t_m, "n_seeds": n_seeds,
            "sent": sent,
            "offset": offset, "fd": fd, "governing": governing, "screened": screened,
            "tolerance": tolerance, "mbs": st["mbs"] if st else None, "design": design}


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
             ("t_c_mean", "T_C-mean (kN)", "kN"), ("t_c", "T_C (kN)", "kN"),
             ("design_tension", "design (kN)", "kN"), ("s_c", "S_C (kN)", "kN"),
             ("utilisation", "utilisation", "{:.3f}"), ("passed", "pass", None),
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
            v = [np.nanmax(np.where(rows & (heads == h), off, np.nan)) for h in hs]
            ax.plot(np.radians(np.append(hs, hs[0])), np.append(v, v[0]), "-", color=col,
                    label=f"FD {ls}")
            td = rows & np.isfinite(a["offset"])
            ax.plot(np.radians(heads[td]), a["offset"][td], "o", ms=3, color=col,
                    label=f"TD {ls} (mean of seed maxima)")
        ax.set_title("maximum horizontal offset (m) over the wave heading", fontsize=9)
        ax.legend(fontsize=6, loc="lower left")
        figs["polar_offset"] = fig
    return figs


def write_report(out_dir, report_dir=None, tolerance: float = DEFAULT_TOLERANCE, *,
                 consequence_class=None, analysis=None) -> dict:
    """Write the campaign report; returns :func:`analyse`'s dict plus the paths written
    (``consequence_class``, ``analysis``: see :func:`analyse`)."""
    import xarray as xr
    a = analyse(out_dir, tolerance, consequence_class=consequence_class, analysis=analysis)
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
    ds.attrs = {"campaign": rec["name"], "standard": "DNV-OS-E301 (October 2008)",
                "consequence_class": a["design"].consequence_class,
                "analysis": a["design"].analysis, "design_options": a["design"].source,
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
    md = [f"# Campaign report: {rec['name']}", "", *text, "",
          "## Governing case per line and limit state", "", _md(gh, gr), "",
          "## Utilisation of every time-domain case", "", _md(ch, cr), ""]
    md += [f"![{n}]({n}.png)" for n in imgs]
    (rd / "report.md").write_text("\n".join(md) + "\n")
    body = [f"<h1>Campaign report: {html.escape(rec['name'])}</h1>",
            "".join(f"<p>{html.escape(t)}</p>" for t in text),
            "<h2>Governing case per line and limit state</h2>",
            _html_table(gh, gr, lambda k: a["governing"][k]["utilisation"] == max(
                g["utilisation"] for g in a["governing"]
                if g["limit_state"] == a["governing"][k]["limit_state"])),
            "<h2>Utilisation of every time-domain case</h2>", _html_table(ch, cr)]
    body += [f'<h2>{n.replace("_", " ")}</h2><img src="data:image/png;base64,{b}">'
             for n, b in imgs.items()]
    if not imgs:
        body.append("<p>No plots: matplotlib is not installed (pip install floatmoor[plot]).</p>")
    css = ("body{font-family:sans-serif;max-width:1400px;margin:auto}table{border-collapse:"
           "collapse;font-size:12px}td,th{border:1px solid #ccc;padding:2px 5px}"
           "tr.gov{background:#fde}")
    (rd / "report.html").write_text(f"<!DOCTYPE html><html><head><meta charset='utf-8'><title>"
                                    f"{html.escape(rec['name'])}</title><style>{css}</style>"
                                    f"</head><body>{''.join(body)}</body></html>")
    a["report_dir"] = rd
    a["summary_lines"] = text
    return a


def _summary_text(a) -> list[str]:
    rec = a["record"]
    n_td = int(np.sum(a["n_seeds"] >= 3))
    pending = int(np.sum(a["sent"])) - n_td
    d = a["design"]
    out = [(f"DNV-OS-E301 Position Mooring, October 2008, consequence class "
            f"{d.consequence_class}, {d.analysis} analysis ({d.source}); "
            f"{len(a['cases'])} cases screened in the frequency domain, {n_td} run in the time "
            f"domain ({len(rec['seeds'])} seeds each; screening {rec['screening']})"
            + (f"; {pending} case(s) sent to the time domain have fewer than 3 finished "
               "seeds and are not in this report (campaign unfinished or failed storms)"
               if pending else "") + ".")]
    for ls in ("ULS", "ALS"):
        g = [x for x in a["governing"] if x["limit_state"] == ls]
        if not g:
            continue
        w = max(g, key=lambda x: x["utilisation"])
        out.append(f"{ls}: governing line {w['line']}, case {w['case']} (sea state "
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

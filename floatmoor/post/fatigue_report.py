"""The fatigue limit state (FLS) section of the design report.

:func:`fls_tables` turns the result of ``floatmoor fatigue`` (:func:`floatmoor.analyses.fatigue.
fatigue_analysis`, or its ``--out`` netCDF file) into report tables: the damage, fatigue life and
DNV (2008) check per line and location, the sea states that dominate the damage, the spectral
methods against each other and the frequency domain against the time domain (rainflow).
:func:`build_report` includes them when given ``fatigue=``; :func:`write_fls_report` writes the
section alone (Markdown and HTML).
"""

from __future__ import annotations

import html
from pathlib import Path

import numpy as np
import xarray as xr

__all__ = ["check_fatigue_result", "fls_check", "fls_meta", "fls_tables", "format_rates",
           "write_fls_report"]

_NEED = ("annual_damage", "fatigue_life", "utilisation", "check_ok", "gamma_f", "contribution",
         "damage_rate", "hs", "tp", "heading_deg", "probability")


def check_fatigue_result(ds) -> None:
    """ValueError unless ``ds`` is a ``floatmoor fatigue`` result."""
    if not isinstance(ds, xr.Dataset) or any(v not in ds for v in _NEED):
        missing = [v for v in _NEED if not isinstance(ds, xr.Dataset) or v not in ds]
        raise ValueError("expected a floatmoor fatigue result (floatmoor fatigue --out FILE.nc); "
                         f"missing {', '.join(missing)}")


def format_rates(text) -> str:
    """The corrosion attribute of a fatigue result (``repr`` of a dict of mm/year by zone, as
    ``floatmoor fatigue`` stores it) as ``"catenary 0.3, bottom 0.4 mm/year"``."""
    import ast
    try:
        d = ast.literal_eval(str(text))
    except (ValueError, SyntaxError):
        return str(text)
    if not isinstance(d, dict):
        return str(text)
    if not d or not any(float(v) for v in d.values()):
        return "none"
    return ", ".join(f"{k} {float(v):g}" for k, v in d.items()) + " mm/year"


def fls_check(ds, code=None) -> xr.Dataset:
    """The FLS design check of a fatigue result redone with a design code's fatigue safety
    factor (:meth:`floatmoor.post.design_codes.DesignCode.fatigue_factor` of the stored
    adjacent-line ratio ``d_f``): ``gamma_f(location)``, ``d_c`` (damage over the design life),
    ``utilisation`` (``gamma_F d_C``), ``check_ok`` and ``fatigue_life`` per (location, line).
    A result written before the code files used another ramp; this recomputes it."""
    from .design_codes import DEFAULT_CODE, load_code
    check_fatigue_result(ds)
    c = load_code(DEFAULT_CODE if code is None else code)
    meths = [str(m) for m in ds["method"].values]
    k = meths.index(ds.attrs.get("method", meths[0]))
    life = float(ds.attrs.get("design_life_years", np.nan))
    annual = ds["annual_damage"].values[k]
    d_f = ds["d_f"].values if "d_f" in ds else np.full(ds.sizes["location"], np.nan)
    gamma = np.array([c.fatigue_factor(float(x)) for x in d_f])
    d_c = annual * life
    util = gamma[:, None] * d_c
    out = xr.Dataset(coords={"location": ds["location"].values, "line": ds["line"].values})
    out["gamma_f"] = ("location", gamma, {"units": "1", "long_name": f"fatigue safety factor "
                      f"({c.name}: {c.fatigue_rule_text()})"})
    out["d_f"] = ("location", d_f, {"units": "1", "long_name": "adjacent-line damage ratio"})
    out["d_c"] = (("location", "line"), d_c, {"units": "1", "long_name": "damage over the "
                  "design life"})
    out["utilisation"] = (("location", "line"), util, {"units": "1",
                                                       "long_name": "gamma_F d_C (<= 1 passes)"})
    out["check_ok"] = (("location", "line"), ~np.isfinite(util) | (util <= 1.0),
                       {"units": "1", "long_name": "1 - gamma_F d_C >= 0"})
    out["fatigue_life"] = ds["fatigue_life"]
    out.attrs.update({"code": c.key, "design_life_years": life,
                      "method": str(ds.attrs.get("method", meths[0]))})
    return out


def _f(x, fmt="{:.3g}"):
    x = float(x)
    if not np.isfinite(x):
        return "-" if np.isnan(x) else "inf"
    return fmt.format(x)


def _reference(ds, j, i) -> tuple[str, str]:
    """The range reference of a (location, line) as two cells: the RBS in kN (T-N curve on
    the tension range over the RBS) and the nominal area in mm^2 (S-N curve in MPa,
    ``tn_basis`` stress); the one that does not apply is empty."""
    if "rbs" not in ds:
        return "", ""
    x = float(ds["rbs"].values[j, i])
    if "tn_basis" in ds and str(ds["tn_basis"].values[j, i]) == "stress":
        return "", _f(x, "{:.0f}")
    return _f(x / 1e3, "{:.0f}"), ""


def fls_meta(ds, check=None) -> list[tuple[str, str]]:
    """Header rows of the FLS section (``check``: :func:`fls_check`, for the governing
    location and the code)."""
    gov = (f"{ds.attrs.get('governing_line', '')} at the "
           f"{ds.attrs.get('governing_location', '')}")
    if check is not None:
        u = check["utilisation"].values
        jg, ig = np.unravel_index(np.nanargmax(u), u.shape)
        gov = (f"{check['line'].values[ig]} at the {check['location'].values[jg]} (gamma_F d_C "
               f"{u[jg, ig]:.3f}; {check['gamma_f'].attrs['long_name']})")
    return [("FLS scatter", (f"{ds.attrs.get('scatter', '')} ({ds.sizes['cell']} sea states; "
                            f"{ds.attrs.get('scatter_source', '')})")),
            ("FLS method", (f"{ds.attrs.get('method', '')} (frequency domain), design life "
                           f"{float(ds.attrs.get('design_life_years', np.nan)):g} years, "
                           "corrosion "
                           f"{format_rates(ds.attrs.get('corrosion_mm_per_year', ''))} "
                           "(half the allowance over the life: the mean diameter)")),
            ("FLS governing", gov)] + (
        [("FLS notes", str(ds.attrs["notes"]))] if ds.attrs.get("notes") else [])


def fls_tables(ds, check=None) -> list:
    """The FLS tables (objects with ``caption``, ``html()`` and ``markdown()``); ``check``:
    :func:`fls_check` (default: with DNV-OS-E301 (2008))."""
    from .report import _Table
    check_fatigue_result(ds)
    if check is None:
        check = fls_check(ds)
    meths = [str(m) for m in ds["method"].values]
    method = ds.attrs.get("method", meths[0])
    k = meths.index(method)
    locs = [str(x) for x in ds["location"].values]
    lines = [str(x) for x in ds["line"].values]
    life = float(ds.attrs.get("design_life_years", np.nan))
    cu = check["utilisation"].values
    jg0, ig0 = np.unravel_index(np.nanargmax(cu), cu.shape)
    gov = (locs[jg0], lines[ig0])
    rows, hl = [], []
    for i, ln in enumerate(lines):
        for j, loc in enumerate(locs):
            u = float(cu[j, i])
            if not np.isfinite(u):
                continue
            seg = str(ds["segment_type"].values[j, i]) if "segment_type" in ds else ""
            curve = (f"{ds['tn_curve'].values[j, i]} ({_f(ds['tn_a_d'].values[j, i], '{:g}')}, "
                     f"{_f(ds['tn_m'].values[j, i], '{:g}')})" if "tn_curve" in ds else "")
            rbs, area = _reference(ds, j, i)
            rows.append([ln, loc, seg, curve, rbs, area,
                         _f(ds["annual_damage"].values[k, j, i], "{:.3e}"),
                         _f(ds["fatigue_life"].values[j, i], "{:.4g}"),
                         _f(check["gamma_f"].values[j], "{:.2f}"), _f(u, "{:.3f}"),
                         "PASS" if bool(check["check_ok"].values[j, i]) else "FAIL"])
            hl.append((loc, ln) == gov)
    t1 = _Table("fls_lines", f"FLS fatigue life and check: fatigue damage, life and check per "
                f"line and location ({method}, design life {life:g} years; 1 - gamma_F d_C >= "
                f"0 with {check['gamma_f'].attrs['long_name']})",
                ["line", "location", "segment", "T-N curve (a_D, m)",
                 "RBS [kN] (T-N)", "area [mm²] (S-N, MPa)",
                 "annual damage", "life [years]", "gamma_F", "gamma_F d_C", "status"],
                rows, highlight=hl, status_col=10)
    jg, ig = locs.index(gov[0]), lines.index(gov[1])
    contrib = ds["contribution"].values[:, jg, ig]
    total = np.nansum(contrib)
    order = np.argsort(np.nan_to_num(contrib))[::-1][:10]
    acc = 0.0
    rows2 = []
    for c in order:
        acc += contrib[c]
        rows2.append([_f(ds["hs"].values[c], "{:.2f}"), _f(ds["tp"].values[c], "{:.2f}"),
                      _f(ds["heading_deg"].values[c], "{:.0f}"),
                      _f(ds["probability"].values[c], "{:.5f}"),
                      _f(100 * contrib[c] / total, "{:.1f}"), _f(100 * acc / total, "{:.1f}")])
    t2 = _Table("fls_cells", f"FLS dominant sea states: the sea states that dominate the damage of {gov[1]} at the "
                f"{gov[0]} (the ten largest of {ds.sizes['cell']})",
                ["Hs (m)", "Tp (s)", "direction (deg)", "probability", "share (%)",
                 "cumulative (%)"], rows2)
    abbr = {"combined_spectrum": "CS", "dual_narrow_band": "DNB", "dirlik": "Dirlik",
            "simple_summation": "SS"}
    short = [abbr.get(m, m) for m in meths]
    rows3 = []
    for j, loc in enumerate(locs):
        a = ds["annual_damage"].values[:, j, ig]
        if np.all(np.isnan(a)):
            continue
        rows3.append([loc] + [_f(x, "{:.3e}") for x in a]
                     + [_f(a[m] / a[k], "{:.3f}") for m in range(len(meths))])
    t3 = _Table("fls_methods", f"FLS spectral methods: annual damage of {gov[1]} by spectral "
                f"method and its ratio to {short[k]} ({', '.join(f'{a} {m}' for a, m in zip(short, meths))})",
                ["location"] + [f"{a} [1/year]" for a in short]
                + [f"{a} / {short[k]}" for a in short], rows3)
    tables = [t1, t2, t3]
    if ds.sizes.get("td", 0):
        rows4 = []
        for n, c in enumerate(ds["td_cell"].values):
            for j, loc in enumerate(locs):
                td = float(ds["td_damage_rate"].values[n, j, ig])
                if not np.isfinite(td):
                    continue
                rows4.append([(f"Hs {_f(ds['hs'].values[c], '{:g}')} Tp "
                              f"{_f(ds['tp'].values[c], '{:g}')} dir "
                              f"{_f(ds['heading_deg'].values[c], '{:.0f}')}"), loc,
                              _f(td * 3600.0, "{:.3e}")]
                             + [_f(ds["fd_td_ratio"].values[m, n, j, ig], "{:.3f}")
                                for m in range(len(meths))])
        t4 = _Table("fls_fd_td", f"FLS frequency domain against time domain: rainflow of one "
                    f"{float(ds.attrs.get('td_duration', np.nan)):g} s storm per sea state, seed "
                    f"{ds.attrs.get('td_seed', '')}, {gov[1]}, FD damage / TD damage",
                    ["sea state", "location", "TD damage per hour"]
                    + [f"FD / TD {abbr.get(m, m)}" for m in meths], rows4)
        tables.append(t4)
    return tables


def write_fls_report(ds, out_dir, *, title: str | None = None, code=None) -> dict:
    """Write the FLS section alone as ``fls.md`` and ``fls.html`` in ``out_dir``."""
    from .report import _CSS
    out = Path(out_dir)
    out.mkdir(parents=True, exist_ok=True)
    check = fls_check(ds, code)
    tables = fls_tables(ds, check)
    title = title or f"Fatigue limit state: {ds.attrs.get('scene_name', '')}"
    meta = fls_meta(ds, check)
    md = [f"# {title}", ""] + [f"- **{a}**: {b}" for a, b in meta] + [""]
    md += [t.markdown() for t in tables]
    md_path = out / "fls.md"
    md_path.write_text("\n".join(md) + "\n", encoding="utf-8")
    parts = ["<!DOCTYPE html><html lang='en'><head><meta charset='utf-8'>",
             f"<title>{html.escape(title)}</title><style>{_CSS}</style></head><body>"
             f"<h1>{html.escape(title)}</h1><ul>"]
    parts += [f"<li><b>{html.escape(a)}</b>: {html.escape(b)}</li>" for a, b in meta]
    parts.append("</ul>")
    for t in tables:
        parts += [f"<h2>{html.escape(t.caption.split(':')[0])}</h2>",
                  f'<div class="scroll">{t.html()}</div>']
    parts.append("</body></html>")
    html_path = out / "fls.html"
    html_path.write_text("".join(parts), encoding="utf-8")
    return {"markdown": md_path, "html": html_path}

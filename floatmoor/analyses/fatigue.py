"""Fatigue limit state (FLS) of the mooring lines over a long-term scatter diagram.

For every sea state of the scatter diagram the frequency domain (:func:`floatmoor.frequency_domain`)
gives the LF and WF tension spectra; the spectral damage (dual narrow band by default, DNV 2008
Ch.2 Sec.2 D) is summed with the cell probabilities into the annual damage of every line at its
fatigue locations; the time domain (:func:`floatmoor.simulate`, rainflow counting) is run on the
cells that carry most of the damage and its damage is compared with the frequency domain's.
:func:`fatigue_analysis` returns the result as a Dataset (``floatmoor fatigue`` prints it with
:func:`format_fatigue`; ``floatmoor report --fatigue`` reads its netCDF file).

Fatigue locations, tension spectra and the time-domain location tensions:
:mod:`floatmoor.post.fatigue.locations`.
"""

from __future__ import annotations

import math
import time
import warnings
from dataclasses import replace

import numpy as np

__all__ = ["fatigue_analysis", "format_fatigue", "DEFAULT_METHOD"]

DEFAULT_METHOD = "dual_narrow_band"


def _cell_scene(scene, scatter, i):
    """The scene with the environment of scatter cell ``i`` (waves, optional wind, no current)."""
    from ..metocean.config import Environment, WaveSpec, WindSpec
    waves = WaveSpec(spectrum=scatter.spectrum, hs=float(scatter.hs[i]), tp=float(scatter.tp[i]),
                     gamma=scatter.gamma, heading=float(scatter.heading[i]))
    wind = None
    u10 = float(scatter.u10[i])
    if math.isfinite(u10) and u10 > 0:
        wind = WindSpec(spectrum="npd", u10=u10, heading=float(scatter.heading[i]))
    env = Environment(waves=waves, wind=wind, current=None, name=scatter.label(i),
                      source=str(scatter.file) if scatter.file else None)
    return replace(scene, environment=env)


def _td_rates(built_cell, pose, mooring, locations, curves, rbs, *, seed, duration, transient,
              dt):
    """Rainflow damage per second of one TD run of a cell, (n_loc, n_lines)."""
    import floatmoor

    from ..post.fatigue.locations import line_directions, location_tensions
    from ..post.fatigue.rainflow import rainflow
    r = floatmoor.simulate(built_cell, seed=seed, duration=transient + duration,
                           transient=transient, dt=dt)
    t = r["time"].values
    keep = t >= transient
    tf = r["line_tension"].values[keep]  # (n_t, n_lines)
    pose = np.asarray(pose, float)  # the FD mean pose of the cell
    e = line_directions(mooring, pose)
    s_grid = np.linspace(-80.0, 80.0, 81)
    out = np.full(rbs.shape, np.nan)
    for i in range(mooring.n_lines):
        tab = np.empty((s_grid.size, len(locations)))
        for n, s in enumerate(s_grid):
            p = pose.copy()
            p[:3] += s * e[i]
            tab[n] = location_tensions(mooring, p, locations)[:, i]
        order = np.argsort(tab[:, 0])
        for j in range(len(locations)):
            c = curves[j, i]
            if c is None:
                continue
            x = tf[:, i] if j == 0 else np.interp(tf[:, i], tab[order, 0], tab[order, j])
            rng, _, cnt = rainflow(x)
            out[j, i] = c.damage(rng, cnt, rbs[j, i]) / duration
    mooring.tensions(pose)
    return out, float(r.attrs.get("run_time_s", np.nan))


def fatigue_analysis(scene, scatter, *, method: str = DEFAULT_METHOD, design_life: float = 20.0,
                     corrosion: dict | None = None, td_cells: int = 3, td_fraction: float = 0.5,
                     td_duration: float = 10800.0, td_transient: float = 600.0,
                     td_dt: float | None = None, seed: int = 1, progress=None):
    """Long-term fatigue of the lines of ``scene`` over the sea states of ``scatter``.

    Parameters
    ----------
    scene : scene file path or :class:`~floatmoor.io.scene.Scene` (vessel and mooring needed)
    scatter : scatter file path or :class:`~floatmoor.post.fatigue.longterm.Scatter`
    method : spectral method for the FD damage, one of
        :data:`floatmoor.post.fatigue.spectral.METHODS` (all are computed and stored)
    design_life : years
    corrosion : allowance rates (mm/year) by zone ``catenary`` (fairlead and segment tops) and
        ``bottom`` (touchdown); default DNV (2008) table B1 with regular inspection
    td_cells, td_fraction : the time domain runs the cells that carry ``td_fraction`` of the
        annual damage of the governing location, at most ``td_cells`` (0: no time domain)
    td_duration, td_transient, td_dt : length of each TD storm after the transient, s
    seed : TD realisation seed

    Returns
    -------
    xarray.Dataset (see :func:`format_fatigue`): per cell, location and line the damage rates of
    every method, the annual damage, fatigue life and DNV (2008) check, the TD/FD comparison.
    """
    import xarray as xr

    import floatmoor

    from ..io.build import build
    from ..post.fatigue.locations import (
        damage_rates,
        fatigue_locations,
        location_curves,
        location_segments,
        tension_spectra,
        undamped_lf_notes,
    )
    from ..post.fatigue.longterm import (
        Scatter,
        adjacent_ratio,
        annual_damage,
        dominant_cells,
        load_scatter,
    )
    from ..post.fatigue.spectral import METHODS, moments
    from ..post.fatigue.tn_curves import (
        CORROSION_RATES_MM_PER_YEAR,
        design_check,
        fatigue_safety_factor,
    )

    t0 = time.perf_counter()
    if method not in METHODS:
        raise KeyError(f"unknown spectral method {method!r}; methods: {', '.join(METHODS)}")
    if corrosion is None:  # the zones of the locations: catenary and bottom
        corrosion = {z: CORROSION_RATES_MM_PER_YEAR[z] for z in ("catenary", "bottom")}
    corrosion = dict(corrosion)
    sc = scene if not isinstance(scene, (str, bytes)) and hasattr(scene, "environment") \
        else floatmoor.load_scene(scene)
    sct = scatter if isinstance(scatter, Scatter) else load_scatter(
        scatter, water_depth=sc.site.water_depth, gravity=sc.site.gravity)
    built = build(sc)
    if built.mooring is None or built.vessel is None:
        from ..core.errors import SceneError
        raise SceneError(sc.file, "mooring" if built.mooring is None else "vessel",
                         "a vessel and a mooring (the fatigue analysis runs the frequency "
                         "domain on them)")
    mooring = built.mooring
    _check_corrosion(mooring, corrosion, design_life)
    locations = fatigue_locations(mooring)
    segments = location_segments(mooring, locations)
    curves, rbs, types = location_curves(mooring, locations, segments, design_life=design_life,
                                 corrosion=corrosion)
    n_c, n_loc, n_l = sct.n_cells, len(locations), mooring.n_lines
    mom_lf = np.full((4, n_c, n_loc, n_l), np.nan)
    mom_wf = np.full((4, n_c, n_loc, n_l), np.nan)
    t_mean = np.full((n_c, n_loc, n_l), np.nan)
    std_lf = np.full((n_c, n_loc, n_l), np.nan)
    std_wf = np.full((n_c, n_loc, n_l), np.nan)
    tz_lf = np.full((n_c, n_loc, n_l), np.nan)
    tz_wf = np.full((n_c, n_loc, n_l), np.nan)
    lf_scale = np.full((n_c, n_l), np.nan)
    notes: set[str] = set()
    mean_pose = np.zeros((n_c, 6))
    for c in range(n_c):
        cell = replace(built, scene=_cell_scene(sc, sct, c))
        with warnings.catch_warnings(record=True) as caught:
            warnings.simplefilter("always")
            ds = floatmoor.frequency_domain(cell)
            wf, lf, mean, scale = tension_spectra(ds, mooring, locations)
        for w in caught:
            notes.add(str(w.message).split(":")[0][:120])
        notes.update(undamped_lf_notes(ds))
        mw = moments(ds["omega"].values, wf)
        ml = moments(ds["mu"].values, lf)
        mom_lf[:, c], mom_wf[:, c] = ml, mw
        t_mean[c], lf_scale[c] = mean, scale
        std_lf[c], std_wf[c] = np.sqrt(ml[0]), np.sqrt(mw[0])
        with np.errstate(divide="ignore", invalid="ignore"):
            tz_lf[c] = 2 * math.pi * np.sqrt(ml[0] / ml[2])
            tz_wf[c] = 2 * math.pi * np.sqrt(mw[0] / mw[2])
        mean_pose[c] = ds["mean"].values
        if progress is not None:
            progress(c + 1, n_c)
    rates = damage_rates(mom_lf, mom_wf, curves[None], rbs[None])  # (method, cell, loc, line)
    k_m = METHODS.index(method)
    annual = annual_damage(np.moveaxis(rates, 1, 0), sct.probability)  # (method, loc, line)
    contrib = sct.probability[:, None, None] * rates[k_m] * 86400 * 365.25  # (cell, loc, line)
    # azimuths of the lines (anchor direction from the fairlead) for the adjacent-line ratio
    fl0 = mooring.fairlead_positions(np.zeros(6))
    az = np.arctan2(mooring.anchors[:, 1] - fl0[:, 1], mooring.anchors[:, 0] - fl0[:, 0])
    d_f = np.full(n_loc, np.nan)
    gamma = np.full(n_loc, 5.0)
    exposed = np.full(n_loc, -1)
    adjacent = np.full(n_loc, -1)
    for j in range(n_loc):
        d_f[j], exposed[j], adjacent[j] = adjacent_ratio(annual[k_m, j], az)
        gamma[j] = fatigue_safety_factor(d_f[j])
    life = np.where(annual[k_m] > 0, 1.0 / np.where(annual[k_m] > 0, annual[k_m], 1.0), np.inf)
    util = gamma[:, None] * annual[k_m] * design_life
    ok = np.array([[design_check(annual[k_m, j, i], design_life, gamma[j])["ok"]
                    if np.isfinite(annual[k_m, j, i]) else True for i in range(n_l)]
                   for j in range(n_loc)])
    # governing location and line, and the cells that dominate its damage
    jg, ig = np.unravel_index(np.nanargmax(util), util.shape)
    dom = dominant_cells(contrib[:, jg, ig], fraction=td_fraction, max_cells=td_cells)
    td = np.full((dom.size, n_loc, n_l), np.nan)
    td_time = np.full(dom.size, np.nan)
    for n, c in enumerate(dom):
        cell = replace(built, scene=_cell_scene(sc, sct, c))
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            td[n], td_time[n] = _td_rates(
                cell, mean_pose[c], mooring, locations, curves, rbs, seed=seed,
                duration=td_duration, transient=td_transient,
                dt=td_dt if td_dt is not None else sc.analysis.dt)
    with np.errstate(divide="ignore", invalid="ignore"):
        ratio = rates[:, dom] / td[None]

    def v(dims, x, units, long_name, **kw):
        return (dims, np.asarray(x), {"units": units, "long_name": long_name, **kw})

    names = list(mooring.names)
    out = xr.Dataset(
        {
            "hs": v("cell", sct.hs, "m", "significant wave height"),
            "tp": v("cell", sct.tp, "s", "peak period"),
            "heading_deg": v("cell", np.degrees(sct.heading), "deg",
                             "wave (and wind) direction of travel from +x towards +y"),
            "u10": v("cell", sct.u10, "m/s", "1-hour mean wind at 10 m (NaN: no wind)"),
            "probability": v("cell", sct.probability, "1", "probability of the sea state"),
            "damage_rate": v(("method", "cell", "location", "line"), rates, "1/s",
                             "spectral fatigue damage per second of the sea state"),
            "annual_damage": v(("method", "location", "line"), annual, "1/year",
                               "annual fatigue damage sum_i p_i d_i T_year"),
            "contribution": v(("cell", "location", "line"), contrib, "1/year",
                              f"annual damage contributed by each cell ({method})"),
            "fatigue_life": v(("location", "line"), life, "year",
                              f"fatigue life 1 / annual damage ({method})"),
            "gamma_f": v("location", gamma, "1", "DNV (2008) fatigue safety factor"),
            "d_f": v("location", d_f, "1", "damage of the adjacent line / damage of the most "
                     "exposed line"),
            "most_exposed_line": v("location", exposed, "1", "index of the most exposed line"),
            "adjacent_line": v("location", adjacent, "1", "index of its adjacent line"),
            "utilisation": v(("location", "line"), util, "1",
                             "gamma_F d_C (d_C the damage over the design life); <= 1 passes"),
            "check_ok": v(("location", "line"), ok, "1", "DNV (2008) 1 - gamma_F d_C >= 0"),
            "rbs": v(("location", "line"), rbs, "N or mm^2",
                     "range reference of the curve: T-N curves (tn_basis rbs) the reference "
                     "breaking strength in N (MBS on the corroded diameter); S-N curves in MPa "
                     "(tn_basis stress) the nominal steel area in mm^2 on the corroded "
                     "diameter"),
            "tn_basis": v(("location", "line"), [[getattr(c, "basis", "") for c in row]
                                                 for row in curves], "",
                          "rbs: tension range / RBS; stress: stress range in MPa"),
            "tn_a_d": v(("location", "line"), [[getattr(c, "a_d", np.nan) for c in row]
                                               for row in curves], "1", "T-N constant a_D"),
            "tn_m": v(("location", "line"), [[getattr(c, "m", np.nan) for c in row]
                                             for row in curves], "1", "T-N slope m"),
            "tn_curve": v(("location", "line"), [[getattr(c, "name", "") for c in row]
                                                 for row in curves], "", "T-N curve"),
            "segment_type": v(("location", "line"), types.astype(str), "",
                              "line type of the segment at the location"),
            "tension_mean": v(("cell", "location", "line"), t_mean, "N", "mean tension (FD)"),
            "tension_std_lf": v(("cell", "location", "line"), std_lf, "N", "LF tension std"),
            "tension_std_wf": v(("cell", "location", "line"), std_wf, "N", "WF tension std"),
            "tension_tz_lf": v(("cell", "location", "line"), tz_lf, "s", "LF tension Tz"),
            "tension_tz_wf": v(("cell", "location", "line"), tz_wf, "s", "WF tension Tz"),
            "lf_shape_scale": v(("cell", "line"), lf_scale, "1",
                                "FD LF tension variance / variance of the along-line "
                                "approximation (1: the approximation is exact)"),
            "td_cell": v("td", dom, "1", "index of the cells run in the time domain"),
            "td_damage_rate": v(("td", "location", "line"), td, "1/s",
                                "rainflow damage per second of the TD run"),
            "fd_td_ratio": v(("method", "td", "location", "line"), ratio, "1",
                             "FD spectral damage / TD rainflow damage"),
            "td_run_time": v("td", td_time, "s", "TD time loop wall time"),
        },
        coords={"method": list(METHODS), "location": locations, "line": names,
                "cell": np.arange(n_c), "td": np.arange(dom.size)})
    out.attrs.update({
        "title": "floatmoor fatigue limit state (FLS)",
        "scene": str(sc.file) if sc.file else sc.name, "scene_name": sc.name,
        "scatter": sct.name, "scatter_source": sct.source,
        "method": method, "design_life_years": design_life,
        "corrosion_mm_per_year": repr(corrosion),
        "td_duration": td_duration, "td_transient": td_transient, "td_seed": seed,
        "governing_location": locations[jg], "governing_line": names[ig],
        "notes": "; ".join(sorted(notes)),
        "run_time_s": time.perf_counter() - t0,
    })
    return out


def _check_corrosion(mooring, corrosion: dict, design_life: float) -> None:
    """The corrosion/wear allowances (mm/year by zone): finite, >= 0, and not consuming the
    diameter of a corroding (steel) segment over the design life (the reference breaking
    strength would be of a line with no steel left).  SceneError naming ``corrosion``
    (``--corrosion`` on the command line)."""
    from ..core.errors import SceneError
    from ..post.fatigue.tn_curves import curve_for
    key = "corrosion (--corrosion CATENARY BOTTOM)"
    for zone, rate in corrosion.items():
        if not (isinstance(rate, (int, float)) and math.isfinite(rate) and rate >= 0.0):
            raise SceneError(None, key, f"a {zone} corrosion allowance >= 0 mm/year", rate)
    for line in mooring.lines:
        for sg in line.segments:
            lt = mooring.line_types.get(sg.line_type)
            if lt is None:
                continue
            try:
                corrodes = curve_for(lt).corrodes
            except SceneError:
                continue
            if not corrodes:
                continue
            for zone, rate in corrosion.items():
                lost = rate * 1e-3 * design_life
                if lost >= lt.diameter:
                    raise SceneError(None, key, f"a {zone} allowance that leaves some of the "
                                     f"{lt.diameter * 1e3:g} mm diameter of line type "
                                     f"{lt.name!r} over the {design_life:g}-year design life "
                                     f"(below {lt.diameter * 1e3 / design_life:.3g} mm/year)",
                                     rate, f"{rate:g} mm/year x {design_life:g} years = "
                                     f"{lost * 1e3:.4g} mm; DNV-OS-E301 allowances are "
                                     "0.2-0.8 mm/year")


def format_fatigue(ds) -> str:
    """Text tables of a :func:`fatigue_analysis` result: life and check per line and location,
    the dominant cells, FD against TD."""
    from ..post.fatigue_report import format_rates
    method = ds.attrs["method"]
    locs = list(ds["location"].values)
    life_y = ds.attrs["design_life_years"]
    out = [f"Fatigue limit state: {ds.attrs.get('scene_name', '')}",
           (f"  scatter {ds.attrs['scatter']} ({ds.sizes['cell']} sea states; "
           f"{ds.attrs['scatter_source']})"),
           (f"  FD method {method}, design life {life_y:g} years, corrosion "
           f"{format_rates(ds.attrs['corrosion_mm_per_year'])}"), "",
           "* FATIGUE LIFE (years) AND DNV-OS-E301 CHECK gamma_F d_C <= 1 *",
           "  Line     " + "".join(f"{loc:>22s}" for loc in locs)]
    for i, name in enumerate(ds["line"].values):
        cells = []
        for j in range(len(locs)):
            lf = float(ds["fatigue_life"].values[j, i])
            u = float(ds["utilisation"].values[j, i])
            if not np.isfinite(u):
                cells.append(f"{'-':>22s}")
                continue
            flag = "ok" if bool(ds["check_ok"].values[j, i]) else "FAIL"
            cells.append(f"{lf:11.3g} {u:6.3f} {flag:>3s}")
        out.append(f"  {name!s:9s}" + "".join(cells))
    out.append("  (per location: fatigue life in years, utilisation gamma_F d_C, check)")
    out.append("  gamma_F per location: " + ", ".join(
        f"{loc} {g:.2f} (d_F {d:.2f})" for loc, g, d in
        zip(locs, ds["gamma_f"].values, ds["d_f"].values)))
    out.append("  T-N curves: " + ", ".join(sorted({
        f"{c} (a_D {a:g}, m {m:g})" for c, a, m in zip(
            ds["tn_curve"].values.ravel(), ds["tn_a_d"].values.ravel(),
            ds["tn_m"].values.ravel()) if c})))
    jg = locs.index(ds.attrs["governing_location"])
    ig = list(ds["line"].values).index(ds.attrs["governing_line"])
    contrib = ds["contribution"].values[:, jg, ig]
    total = np.nansum(contrib)
    order = np.argsort(np.nan_to_num(contrib))[::-1][:8]
    out += ["", (f"* CELLS THAT DOMINATE ({ds.attrs['governing_line']} "
            f"{ds.attrs['governing_location']}) *"),
            "   Hs (m)  Tp (s)  dir (deg)  probability  share of annual damage"]
    for c in order:
        out.append(f"  {ds['hs'].values[c]:7.2f} {ds['tp'].values[c]:7.2f} "
                   f"{ds['heading_deg'].values[c]:9.1f} {ds['probability'].values[c]:12.5f}"
                   f"  {100 * contrib[c] / total:6.1f} %")
    if ds.sizes.get("td", 0):
        meths = list(ds["method"].values)
        out += ["", "* FD AGAINST TD (rainflow), damage ratio FD / TD, governing location *",
                "   Hs (m)  Tp (s)  dir (deg)  line     " + "".join(f"{m:>18s}" for m in meths)]
        for n, c in enumerate(ds["td_cell"].values):
            r = ds["fd_td_ratio"].values[:, n, jg, ig]
            out.append(f"  {ds['hs'].values[c]:7.2f} {ds['tp'].values[c]:7.2f} "
                       f"{ds['heading_deg'].values[c]:9.1f}  {ds.attrs['governing_line']:8s}"
                       + "".join(f"{x:18.3f}" for x in r))
        out.append(f"  (TD: {ds.attrs['td_duration']:g} s per storm after "
                   f"{ds.attrs['td_transient']:g} s, seed {ds.attrs['td_seed']})")
    notes = [n for n in str(ds.attrs.get("notes", "")).split("; ") if n]
    warn = [n for n in notes if "no LF" in n]
    if warn:
        out[8 + ds.sizes["line"]:8 + ds.sizes["line"]] = [f"  WARNING: {n}" for n in warn]
    rest = [n for n in notes if n not in warn]
    if rest:
        out += ["", "notes: " + "; ".join(rest)]
    return "\n".join(out)

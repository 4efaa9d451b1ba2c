"""Target and realised statistics of an environment, and a readable table of them.

:func:`environment_summary` realises the waves and wind of an :class:`Environment` for one seed
and compares the statistics of the realised series with their targets;
:func:`format_summary` prints them (``floatmoor environment SCENE``).
"""

from __future__ import annotations

import math

import numpy as np

from floatmoor.core.errors import SceneError
from floatmoor.metocean.config import Environment, total_hs, wave_systems
from floatmoor.metocean.current import current_speed
from floatmoor.metocean.realisation import realise_waves, realise_wind, system_seed
from floatmoor.metocean.spectra import spectrum_gamma, wave_spectrum
from floatmoor.metocean.wind import (
    api_turbulence_intensity,
    npd_turbulence_intensity,
    wind_spectrum,
)

__all__ = ["environment_summary", "format_summary", "zero_upcrossing_waves"]


def zero_upcrossing_waves(eta: np.ndarray, dt: float) -> tuple[np.ndarray, np.ndarray]:
    """Zero-upcrossing wave heights (m) and periods (s) of a uniformly sampled elevation.

    Upcrossing times are interpolated linearly between samples; a wave is the record between
    two successive upcrossings, its height the maximum minus the minimum sample in it.
    """
    eta = np.asarray(eta, dtype=float)
    idx = np.nonzero((eta[:-1] < 0.0) & (eta[1:] >= 0.0))[0]
    if idx.size < 2:
        return np.zeros(0), np.zeros(0)
    frac = -eta[idx] / (eta[idx + 1] - eta[idx])
    t_up = (idx + frac) * dt
    periods = np.diff(t_up)
    hmax = np.maximum.reduceat(eta, idx + 1)[:-1]
    hmin = np.minimum.reduceat(eta, idx + 1)[:-1]
    return hmax - hmin, periods


def _f(x) -> float | None:
    return None if x is None else float(x)


def environment_summary(env: Environment, *, water_depth: float | None, duration: float = 10800.0,
                        dt: float = 0.1, seed: int = 1) -> dict:
    """Target and realised statistics of waves, wind and current.

    Parameters
    ----------
    env : Environment
        The environment; absent components are skipped (their entry is None).
    water_depth : float or None
        Water depth (m) (None: deep water; the current at the seabed is then not reported).
    duration : float
        Length of the realised series (s), default 3 hours.
    dt : float
        Sampling interval (s).
    seed : int
        Seed of the realisation.

    Returns
    -------
    dict
        ``{"name", "duration", "dt", "seed", "water_depth", "waves", "wind", "current"}``;
        ``waves``: spectrum, hs_target (m), tp (s), gamma, heading_deg, tz_target (s, from
        m0 and m2 over the realised frequency range),
        n_components, omega_min/omega_max (rad/s), hs_realised = 4 std (m), hmax (m),
        crest_max (m), tz_realised (s), n_waves; ``wind``: spectrum, u10 (m/s),
        reference_height (m), mean_target (m/s), std_target (m/s, spectrum over the realised
        range), std_full_spectrum (m/s), ti_target (the model's turbulence intensity formula),
        mean, std, max (m/s),
        ti (-), gust_factor (max/mean), n_components; ``current``: profile, heading_deg,
        surface, at_minus_50, seabed (m/s).
    """
    if not (isinstance(dt, (int, float)) and dt > 0 and math.isfinite(dt)):
        raise SceneError(None, "analysis.dt", "a number > 0 (s)", dt)
    if not (isinstance(duration, (int, float)) and duration >= dt and math.isfinite(duration)):
        raise SceneError(None, "analysis.duration", f"a number >= dt = {dt:g} (s)", duration)
    nt = int(round(float(duration) / dt))
    out = {"name": env.name, "duration": float(duration), "dt": float(dt), "seed": int(seed),
           "water_depth": _f(water_depth), "waves": None, "wind": None, "current": None}

    if env.waves is not None:
        systems = wave_systems(env.waves)  # one, or several independent wave systems
        reals = [realise_waves(ws, duration=duration, seed=system_seed(seed, k),
                               water_depth=water_depth) for k, ws in enumerate(systems)]
        eta = reals[0].elevation_series(nt, dt)
        for real in reals[1:]:
            eta = eta + real.elevation_series(nt, dt)
        heights, periods = zero_upcrossing_waves(eta, dt)
        # target moments over the realised frequency range (what the realisation represents)
        lo = min(float(r.omega.min()) for r in reals)
        hi = max(float(r.omega.max()) for r in reals)
        w = np.linspace(lo, hi, 20001)
        s = wave_spectrum(systems[0], w)
        for ws in systems[1:]:
            s = s + wave_spectrum(ws, w)
        m0 = float(np.trapezoid(s, w))
        m2 = float(np.trapezoid(w * w * s, w))
        dom = max(systems, key=lambda x: x.hs)
        out["waves"] = {
            "spectrum": "+".join(ws.spectrum for ws in systems),
            "hs_target": float(total_hs(env.waves)), "tp": float(dom.tp),
            "gamma": _f(spectrum_gamma(dom)), "heading_deg": math.degrees(dom.heading),
            "spreading": "+".join(ws.spreading for ws in systems),
            "n_systems": len(systems),
            "tz_target": 2.0 * math.pi * math.sqrt(m0 / m2),
            "n_components": sum(r.n_components for r in reals),
            "omega_min": lo, "omega_max": hi,
            "hs_discretised": 4.0 * math.sqrt(sum(r.m0 for r in reals)),
            "hs_realised": 4.0 * float(np.std(eta)),
            "hmax": float(heights.max()) if heights.size else 0.0,
            "crest_max": float(eta.max()),
            "tz_realised": float(periods.mean()) if periods.size else float("nan"),
            "n_waves": int(heights.size),
        }

    if env.wind is not None:
        wd = env.wind
        real = realise_wind(wd, duration=duration, seed=seed)
        u = real.speed_series(nt, dt)
        f = np.concatenate([np.linspace(0.0, 0.1, 20001)[:-1], np.logspace(-1, 3, 40000)])
        std_full = math.sqrt(float(np.trapezoid(wind_spectrum(wd, f), f)))
        if real.n_components:
            fr = np.linspace(0.0, float(real.f.max()), 20001)
            std_target = math.sqrt(float(np.trapezoid(wind_spectrum(wd, fr), fr)))
        else:
            std_target = 0.0
        ti_target = {"npd": lambda: float(npd_turbulence_intensity(wd.reference_height, wd.u10)),
                     "api": lambda: float(api_turbulence_intensity(wd.reference_height)),
                     "constant": lambda: 0.0}[wd.spectrum]()
        mean_u = float(u.mean())
        std_u = float(u.std())
        out["wind"] = {
            "spectrum": wd.spectrum, "u10": float(wd.u10), "heading_deg": math.degrees(wd.heading),
            "reference_height": float(wd.reference_height),
            "mean_target": real.mean, "std_target": std_target, "std_full_spectrum": std_full,
            "ti_target": ti_target,
            "n_components": real.n_components,
            "f_max": float(real.f.max()) if real.n_components else 0.0,
            "mean": mean_u, "std": std_u, "max": float(u.max()),
            "ti": std_u / mean_u if mean_u > 0 else 0.0,
            "gust_factor": float(u.max()) / mean_u if mean_u > 0 else float("nan"),
        }

    if env.current is not None:
        cs = env.current
        depth = 1e9 if water_depth is None else float(water_depth)
        out["current"] = {
            "profile": cs.profile, "heading_deg": math.degrees(cs.heading),
            "surface": float(current_speed(cs, 0.0, depth)),
            "at_minus_50": float(current_speed(cs, -50.0, depth)),
            "seabed": None if water_depth is None else float(current_speed(cs, -depth, depth)),
        }
    return out


def _num(x, fmt="{:.2f}") -> str:
    if x is None:
        return "-"
    if isinstance(x, float) and math.isnan(x):
        return "n/a"
    return fmt.format(x)


def format_summary(summary: dict) -> str:
    """A plain-text table of an :func:`environment_summary` result."""
    width = 74
    lines = []
    title = f"Environment: {summary.get('name') or '(unnamed)'}"
    lines.append(title)
    lines.append("=" * width)
    depth = summary.get("water_depth")
    lines.append(f"realisation: seed {summary['seed']}, {summary['duration']:.0f} s at "
                 f"dt = {summary['dt']:g} s; "
                 + ("deep water" if depth is None else f"water depth {depth:g} m"))
    row = "  {:<34s}{:>12s}{:>12s}  {:<8s}"
    head = row.format("", "target", "realised", "unit")

    wv = summary.get("waves")
    if wv is not None:
        lines += ["", f"Waves: {wv['spectrum']}, heading {wv['heading_deg']:.1f} deg, "
                  f"spreading {wv['spreading']}", head, "  " + "-" * (width - 2)]
        lines.append(row.format("significant wave height Hs (4 std)", _num(wv["hs_target"]),
                                _num(wv["hs_realised"]), "m"))
        if wv.get("n_systems", 1) > 1:
            lines.append(f"  {wv['n_systems']} wave systems: Hs of the whole sea; Tp, gamma and "
                         "heading of the system with the largest Hs")
        lines.append(row.format("peak period Tp", _num(wv["tp"]), "", "s"))
        if wv["gamma"] is not None:
            lines.append(row.format("peak enhancement gamma", _num(wv["gamma"], "{:.3f}"), "", "-"))
        lines.append(row.format("zero-upcrossing period Tz (*)", _num(wv["tz_target"]),
                                _num(wv["tz_realised"]), "s"))
        lines.append(row.format("maximum wave height Hmax", "", _num(wv["hmax"]), "m"))
        lines.append(row.format("maximum crest", "", _num(wv["crest_max"]), "m"))
        lines.append(row.format("number of zero-upcrossing waves", "", f"{wv['n_waves']:d}", "-"))
        lines.append(row.format("frequency components", "", f"{wv['n_components']:d}", "-"))
        lines.append(row.format("frequency range", "",
                                f"{wv['omega_min']:.3f}-{wv['omega_max']:.3f}", "rad/s"))
        lines.append("  (*) target 2 pi sqrt(m0/m2) over the realised frequency range")

    wi = summary.get("wind")
    if wi is not None:
        lines += ["", f"Wind: {wi['spectrum']} gust, U10 = {wi['u10']:.2f} m/s (1-hour mean), "
                  f"heading {wi['heading_deg']:.1f} deg", head, "  " + "-" * (width - 2)]
        h = f"{wi['reference_height']:g} m"
        lines.append(row.format(f"mean speed at {h}", _num(wi["mean_target"]), _num(wi["mean"]),
                                "m/s"))
        lines.append(row.format("gust std, spectrum up to f max", _num(wi["std_target"]),
                                _num(wi["std"]), "m/s"))
        lines.append(row.format("gust std, whole spectrum", _num(wi["std_full_spectrum"]), "",
                                "m/s"))
        lines.append(row.format(f"turbulence intensity ({wi['spectrum']} I(z))",
                                _num(wi["ti_target"], "{:.3f}"),
                                _num(wi["ti"], "{:.3f}"), "-"))
        lines.append(row.format("maximum speed", "", _num(wi["max"]), "m/s"))
        lines.append(row.format("gust factor (max/mean)", "", _num(wi["gust_factor"], "{:.3f}"),
                                "-"))
        lines.append(row.format("frequency components", "", f"{wi['n_components']:d}", "-"))
        lines.append(row.format("frequency range", "", f"0-{wi['f_max']:.3f}", "Hz"))

    cu = summary.get("current")
    if cu is not None:
        lines += ["", f"Current: {cu['profile']}, heading {cu['heading_deg']:.1f} deg",
                  row.format("", "speed", "", "unit"), "  " + "-" * (width - 2)]
        lines.append(row.format("at the surface", _num(cu["surface"]), "", "m/s"))
        lines.append(row.format("at z = -50 m", _num(cu["at_minus_50"]), "", "m/s"))
        lines.append(row.format("at the seabed", _num(cu["seabed"]), "", "m/s"))

    if wv is None and wi is None and cu is None:
        lines.append("(no waves, wind or current)")
    return "\n".join(line.rstrip() for line in lines)

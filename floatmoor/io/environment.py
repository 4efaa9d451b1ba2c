"""Environment files (and the inline ``environment:`` mapping of a scene).

```yaml
name: heidrun-100yr
description: free text
waves:
  spectrum: jonswap          # jonswap | pierson_moskowitz | torsethaugen
  hs: 16.0                   # m, > 0
  tp: 18.2                   # s, > 0
  gamma: null                # optional, >= 1, JONSWAP only (null: DNV-RP-C205 rule)
  heading_deg: 0.0           # direction of travel, from +x towards +y
  spreading: none            # optional: none | cos2s (then spreading_s, n_directions)
  discretisation: {omega_min: 0.2, omega_max: 2.5, n_frequencies: 400}   # optional, rad/s
  random_amplitudes: false   # optional
# or several wave systems (wind sea and swell), each with the keys above but discretisation and
# random_amplitudes, which belong to the whole sea:
# waves:
#   systems:
#     - {name: wind_sea, spectrum: jonswap, hs: 14.0, tp: 16.0, heading_deg: 0.0}
#     - {name: swell, spectrum: jonswap, hs: 4.0, tp: 22.0, gamma: 5.0, heading_deg: 45.0}
#   discretisation: {n_frequencies: 2000}                                 # optional
wind:
  spectrum: npd              # npd | api | constant
  u10: 36.0                  # 1-hour mean at 10 m, m/s
  heading_deg: 0.0
  reference_height: 10.0     # optional, m
  discretisation: {f_min: 0.001, f_max: 0.5, n_frequencies: 300}        # optional, Hz
current:
  profile: piecewise_linear  # or power_law with surface_speed and optional exponent (1/7)
  levels: [[0.0, 0.94], [-50.0, 0.94]]   # [z (m, first 0, decreasing, >= -depth), speed (m/s)]
  heading_deg: 0.0
```

Any of ``waves``, ``wind`` and ``current`` may be left out: it is then ``None`` and nothing is
built for it.  Every mistake is a :class:`~floatmoor.SceneError`; plausible-but-suspicious
values give a :class:`~floatmoor.FloatmoorWarning` (see :func:`parse_waves`, :func:`parse_wind`,
:func:`parse_current`).
"""

from __future__ import annotations

import math
import os
import warnings

from ..core.config import Node
from ..core.constants import GRAVITY
from ..core.errors import FloatmoorWarning, SceneError
from ..metocean.config import (
    CURRENT_PROFILES,
    SPREADING_FUNCTIONS,
    WAVE_SPECTRA,
    WIND_SPECTRA,
    CurrentSpec,
    Environment,
    WaveSpec,
    WaveSystems,
    WindSpec,
    wave_systems,
)

__all__ = ["load_environment", "parse_environment", "parse_waves", "parse_wave_systems",
           "parse_wind", "parse_current", "check_sea_state",
           "describe_environment", "environment_models", "peak_wavelength",
           "BREAKING_STEEPNESS", "STEEP_SEA_STEEPNESS", "MAX_PLAUSIBLE_U10",
           "MAX_PLAUSIBLE_CURRENT"]

ENVIRONMENT_KEYS = ("name", "description", "waves", "wind", "current")
WAVE_KEYS = ("spectrum", "hs", "tp", "gamma", "heading_deg", "spreading", "spreading_s",
             "n_directions", "discretisation", "random_amplitudes")
SYSTEM_KEYS = ("name", "spectrum", "hs", "tp", "gamma", "heading_deg", "spreading", "spreading_s",
               "n_directions")
WAVE_SYSTEMS_KEYS = ("systems", "discretisation", "random_amplitudes")
WIND_KEYS = ("spectrum", "u10", "heading_deg", "reference_height", "discretisation")
CURRENT_KEYS = ("profile", "levels", "surface_speed", "exponent", "heading_deg")

BREAKING_STEEPNESS = 1.0 / 10.0
"""Hs/Lp above which a sea state is refused.  Individual regular waves break at H/L = 1/7
(Michell's limit); with the most probable 3-hour maximum near 1.86 Hs, a significant steepness
of 1/10 puts the largest waves far beyond it, and such seas are not observed.  It is also the
usual symptom of Hs and Tp swapped or Tp given as a frequency."""

STEEP_SEA_STEEPNESS = 1.0 / 15.0
"""Hs/Lp above which a warning is given: severe sea states have significant steepness 1/16 to
1/20 (API RP 2MET, 2014, definition of wave steepness)."""

MAX_PLAUSIBLE_U10 = 60.0
"""m/s; a 1-hour mean wind at 10 m above this is warned about (the North Sea 100-year value is
about 36-41 m/s; 60 m/s in knots is 117 kn, typed knots are the usual cause)."""

MAX_PLAUSIBLE_CURRENT = 3.0
"""m/s; faster currents are warned about (strong ocean currents such as the Loop Current reach
about 2-2.5 m/s; typed knots are the usual cause)."""


# -- reading -----------------------------------------------------------------------------------
MAX_FREQUENCIES = 50_000
"""Most frequencies of a wave or wind discretisation (a 3-hour storm needs a few thousand for
its wave series not to repeat)."""

MAX_DIRECTIONS = 360
"""Most wave directions of a spread sea (one per degree)."""

MAX_WAVE_COMPONENTS = 200_000
"""Most wave components (frequencies x directions) of one realisation."""

MAX_WAVE_SYSTEMS = 8
"""Most wave systems of one sea state (wind sea and swells)."""


def load_environment(path: str | os.PathLike, *, water_depth: float | None = None,
                     gravity: float = GRAVITY) -> Environment:
    """Read an environment file into an :class:`~floatmoor.metocean.config.Environment`.

    Parameters
    ----------
    path:
        The YAML file (format in this module's docstring).
    water_depth:
        Water depth in m, used to refuse current levels below the seabed and for the wave length
        in the steepness check (deep water when None).
    gravity:
        m/s^2, for the wave length.
    """
    node = Node.load(path)
    return parse_environment(node, water_depth=water_depth, gravity=gravity)


def parse_environment(node: Node, *, water_depth: float | None = None,
                      gravity: float = GRAVITY) -> Environment:
    """Read an environment mapping (a whole file or a scene's inline ``environment:``)."""
    node.reject_unknown(ENVIRONMENT_KEYS)
    default_name = node.file.stem if (node.file is not None and not node.path) else ""
    name = node.str("name", default_name)
    node.str("description", "")
    waves = wind = current = None
    if "waves" in node:
        waves = parse_waves(node.child("waves"), water_depth=water_depth, gravity=gravity)
    if "wind" in node:
        wind = parse_wind(node.child("wind"))
    if "current" in node:
        current = parse_current(node.child("current"), water_depth=water_depth)
    source = str(node.file) if (node.file is not None and not node.path) else None
    return Environment(waves=waves, wind=wind, current=current, name=name, source=source)


def parse_waves(node: Node, *, water_depth: float | None = None,
                gravity: float = GRAVITY) -> WaveSpec | WaveSystems:
    """Read a ``waves:`` mapping: one sea state, or several wave systems under ``systems:``
    (:func:`parse_wave_systems`).

    Refused: Hs or Tp <= 0, gamma < 1 (and gamma for a spectrum other than JONSWAP), a
    significant steepness Hs/Lp > 1/10 (:data:`BREAKING_STEEPNESS`; Lp is the wave length at Tp
    in the site's depth), a frequency band that excludes the spectral peak, spreading settings
    without ``spreading: cos2s``.
    Warned: Hs/Lp > 1/15 (:data:`STEEP_SEA_STEEPNESS`), a most probable maximum wave
    (1.86 Hs) above the depth-limited breaking height 0.78 d, JONSWAP gamma > 7 (outside the
    range 1-7 over which it is fitted; DNV-RP-C205's rule itself gives 1 to 5).
    """
    if "systems" in node:
        return parse_wave_systems(node, water_depth=water_depth, gravity=gravity)
    node.reject_unknown(WAVE_KEYS)
    fields = _system_fields(node, water_depth=water_depth, gravity=gravity)
    disc = _discretisation(node, [fields["tp"]], fields["n_directions"])
    random_amplitudes = node.bool("random_amplitudes", False)
    return WaveSpec(**fields, **disc, random_amplitudes=random_amplitudes)


def parse_wave_systems(node: Node, *, water_depth: float | None = None,
                       gravity: float = GRAVITY) -> WaveSystems:
    """Read a ``waves:`` mapping of several wave systems::

        waves:
          systems:
            - {name: wind_sea, spectrum: jonswap, hs: 14.0, tp: 16.0, heading_deg: 0.0}
            - {name: swell, spectrum: jonswap, hs: 4.0, tp: 22.0, gamma: 5.0, heading_deg: 45.0,
               spreading: cos2s, spreading_s: 10, n_directions: 9}
          discretisation: {omega_min: 0.2, omega_max: 2.5, n_frequencies: 800}  # optional
          random_amplitudes: false                                            # optional

    Each system takes the keys of a single sea state but ``discretisation`` and
    ``random_amplitudes``, which belong to the whole sea, and checks alike (steepness, gamma,
    spreading); ``name`` is optional (``system1``, ``system2``, ...), distinct.  Refused as
    well: no system, more than :data:`MAX_WAVE_SYSTEMS`, a band that excludes a system's peak,
    more than :data:`MAX_WAVE_COMPONENTS` components.
    """
    node.reject_unknown(WAVE_SYSTEMS_KEYS)
    items = node.item_nodes("systems", min_len=1)
    if len(items) > MAX_WAVE_SYSTEMS:
        raise node.error("systems", f"at most {MAX_WAVE_SYSTEMS} wave systems",
                         f"{len(items)} systems")
    systems, names = [], []
    for i, item in enumerate(items):
        item.reject_unknown(SYSTEM_KEYS)
        names.append(item.str("name", f"system{i + 1}"))
        systems.append(WaveSpec(**_system_fields(item, water_depth=water_depth,
                                                 gravity=gravity)))
    if len(set(names)) != len(names):
        raise node.error("systems", "wave systems with distinct names", names)
    disc = _discretisation(node, [s.tp for s in systems], sum(s.n_directions for s in systems))
    return WaveSystems(systems=tuple(systems), names=tuple(names), **disc,
                       random_amplitudes=node.bool("random_amplitudes", False))


def _system_fields(node: Node, *, water_depth: float | None, gravity: float,
                   heading_key: str = "heading_deg", spectrum=None) -> dict:
    """The WaveSpec fields of one sea state or wave system (checks of :func:`parse_waves`);
    the heading read from ``heading_key`` (degrees); ``spectrum`` the default spectrum (None:
    the key is required)."""
    if spectrum is None:
        spectrum = node.choice("spectrum", WAVE_SPECTRA, what="wave spectrum")
    else:
        spectrum = node.choice("spectrum", WAVE_SPECTRA, spectrum, what="wave spectrum")
    hs = node.float("hs", gt=0.0, unit="m")
    tp = node.float("tp", gt=0.0, unit="s")
    gamma = node.float("gamma", None, ge=1.0, allow_none=True)
    if gamma is not None and spectrum != "jonswap":
        raise node.error("gamma", f"no gamma for the {spectrum} spectrum (gamma is JONSWAP's)",
                         node.raw("gamma"), "remove gamma, or use spectrum: jonswap")
    if gamma is not None and gamma > 7.0:
        _warn(node, "gamma", f"gamma = {gamma:g} is outside the range 1-7 of measured seas")
    heading = node.angle_deg(heading_key, 0.0)
    check_sea_state(node.file, node.key("hs"), hs, tp, water_depth=water_depth,
                    gravity=gravity)

    spreading = node.str("spreading", "none", choices=SPREADING_FUNCTIONS)
    if spreading == "none":
        for key in ("spreading_s", "n_directions"):
            if key in node:
                raise node.error(key, "no spreading settings for long-crested waves",
                                 node.raw(key), "set spreading: cos2s to use them")
        spreading_s, n_directions = WaveSpec.__dataclass_fields__["spreading_s"].default, 1
    else:
        spreading_s = node.float("spreading_s", WaveSpec.__dataclass_fields__["spreading_s"].default,
                                 gt=0.0)
        n_directions = node.int("n_directions", ge=2, le=MAX_DIRECTIONS)
    return {"spectrum": spectrum, "hs": hs, "tp": tp, "gamma": gamma, "heading": heading,
            "spreading": spreading, "spreading_s": spreading_s, "n_directions": n_directions}


def _discretisation(node: Node, tps: list, n_directions: int) -> dict:
    """``omega_min``, ``omega_max``, ``n_frequencies`` of a ``discretisation:`` (None when
    absent); every peak 2 pi/Tp of ``tps`` must lie in the band."""
    omega_min = omega_max = n_frequencies = None
    if "discretisation" in node:
        disc = node.child("discretisation")
        disc.reject_unknown(("omega_min", "omega_max", "n_frequencies"))
        omega_min = disc.float("omega_min", None, gt=0.0, unit="rad/s")
        omega_max = disc.float("omega_max", None, gt=0.0, unit="rad/s")
        n_frequencies = disc.int("n_frequencies", None, ge=2, le=MAX_FREQUENCIES)
        if n_frequencies is not None and n_frequencies * n_directions > MAX_WAVE_COMPONENTS:
            n = n_frequencies * n_directions
            raise disc.error("n_frequencies", f"at most {MAX_WAVE_COMPONENTS:,} wave components "
                             "(n_frequencies x n_directions)", n_frequencies,
                             f"{n_frequencies} x {n_directions} directions = {n:,} components; "
                             f"their excitation tables alone would need {n * 96 / 1e6:.3g} MB "
                             "and every time step would sum them all")
        for tp in tps:
            omega_p = 2.0 * math.pi / tp
            peak = (f"the spectral peak 2 pi/Tp = {omega_p:.4g} rad/s must lie inside "
                    "[omega_min, omega_max]")
            if omega_min is not None and not omega_min < omega_p:
                raise disc.error("omega_min", f"a number < {omega_p:.4g} (in rad/s)", omega_min,
                                 peak)
            if omega_max is not None and not omega_max > omega_p:
                raise disc.error("omega_max", f"a number > {omega_p:.4g} (in rad/s)", omega_max,
                                 peak)
        if "omega_min" in disc and "omega_max" in disc and not omega_max > omega_min:
            raise disc.error("omega_max", f"a number > omega_min = {omega_min:g} (in rad/s)",
                             omega_max)
    return {"omega_min": omega_min, "omega_max": omega_max, "n_frequencies": n_frequencies}


def check_sea_state(file, key: str, hs: float, tp: float, *, water_depth: float | None = None,
                    gravity: float = GRAVITY, stacklevel: int = 3) -> None:
    """Refuse a sea state that cannot exist, warn for an unusually steep one (the rule of scene
    files, applied also to the sea states of campaign contours and lists and of fatigue scatter
    diagrams): a significant steepness Hs/Lp above :data:`BREAKING_STEEPNESS` (1/10; Lp the
    wave length at Tp in ``water_depth``, deep water when None) is a SceneError naming ``file``
    and ``key`` (the Hs of the sea state); above :data:`STEEP_SEA_STEEPNESS` (1/15), and a most
    probable maximum wave 1.86 Hs above the depth-limited breaking height 0.78 d, a
    FloatmoorWarning."""
    length = peak_wavelength(tp, water_depth, gravity)
    steepness = hs / length
    where = "" if water_depth is None else f" in {water_depth:g} m depth"
    if steepness > BREAKING_STEEPNESS:
        raise SceneError(file, key, f"a sea state that does not break: Hs/Lp <= 1/10, i.e. Hs "
                         f"<= {BREAKING_STEEPNESS * length:.3g} m for Tp = {tp:g} s{where}", hs,
                         f"Hs/Lp = 1/{1.0 / steepness:.3g} with Lp = {length:.4g} m; "
                         "are Hs and Tp swapped, or Tp given in Hz?")
    if steepness > STEEP_SEA_STEEPNESS:
        warnings.warn(f"{file}: {key}: the sea state Hs = {hs:g} m, Tp = {tp:g} s is very "
                      f"steep: Hs/Lp = 1/{1.0 / steepness:.3g} (Lp = {length:.4g} m{where}); "
                      "severe seas have 1/16 to 1/20 (API RP 2MET)", FloatmoorWarning,
                      stacklevel=stacklevel)
    if water_depth is not None and 1.86 * hs > 0.78 * water_depth:
        warnings.warn(f"{file}: {key}: the most probable maximum wave 1.86 Hs = "
                      f"{1.86 * hs:.3g} m exceeds the depth-limited breaking height 0.78 d = "
                      f"{0.78 * water_depth:.3g} m; linear wave theory is not valid there",
                      FloatmoorWarning, stacklevel=stacklevel)


def parse_wind(node: Node) -> WindSpec:
    """Read a ``wind:`` mapping.

    Refused: u10 < 0, reference height <= 0, a gust discretisation for ``constant`` wind.
    Warned: u10 > 60 m/s (:data:`MAX_PLAUSIBLE_U10`; knots or km/h typed for m/s).
    """
    node.reject_unknown(WIND_KEYS)
    spectrum = node.choice("spectrum", WIND_SPECTRA, what="wind spectrum")
    u10 = node.float("u10", ge=0.0, unit="m/s")
    if u10 > MAX_PLAUSIBLE_U10:
        _warn(node, "u10", f"u10 = {u10:g} m/s is above any design 1-hour mean wind at 10 m "
              f"({MAX_PLAUSIBLE_U10:g} m/s); floatmoor expects m/s, not knots or km/h")
    heading = node.angle_deg("heading_deg", 0.0)
    reference_height = node.float("reference_height", 10.0, gt=0.0, unit="m")
    f_min = f_max = n_frequencies = None
    if "discretisation" in node:
        if spectrum == "constant":
            raise node.error("discretisation", "no gust discretisation for constant wind",
                             node.raw("discretisation"), "remove it, or choose a gust spectrum")
        disc = node.child("discretisation")
        disc.reject_unknown(("f_min", "f_max", "n_frequencies"))
        f_min = disc.float("f_min", None, gt=0.0, unit="Hz")
        f_max = disc.float("f_max", None, gt=0.0, unit="Hz")
        n_frequencies = disc.int("n_frequencies", None, ge=2, le=MAX_FREQUENCIES)
        if f_min is not None and f_max is not None and not f_max > f_min:
            raise disc.error("f_max", f"a number > f_min = {f_min:g} (in Hz)", f_max)
    return WindSpec(spectrum=spectrum, u10=u10, heading=heading,
                    reference_height=reference_height, f_min=f_min, f_max=f_max,
                    n_frequencies=n_frequencies)


def parse_current(node: Node, *, water_depth: float | None = None) -> CurrentSpec:
    """Read a ``current:`` mapping.

    ``piecewise_linear``: ``levels`` is a list of ``[z, speed]`` pairs, z in m (first 0.0 at the
    surface, strictly decreasing, not below the seabed ``-water_depth``), speed in m/s >= 0; the
    speed is constant below the deepest level.  ``power_law``: ``surface_speed`` (m/s) and
    ``exponent`` (default 1/7).  Refused: negative speeds (turn the heading instead), levels
    out of order, above the surface or below the seabed.  Warned: speeds above 3 m/s
    (:data:`MAX_PLAUSIBLE_CURRENT`).
    """
    node.reject_unknown(CURRENT_KEYS)
    profile = node.choice("profile", CURRENT_PROFILES, what="current profile")
    heading = node.angle_deg("heading_deg", 0.0)
    if profile == "piecewise_linear":
        for key in ("surface_speed", "exponent"):
            if key in node:
                raise node.error(key, "no power-law settings for a piecewise_linear profile",
                                 node.raw(key), "use levels: [[z, speed], ...]")
        table = node.array("levels", shape=(None, 2), unit="m and m/s")
        if table.shape[0] < 1:
            raise node.error("levels", "at least one [z, speed] level", node.raw("levels"))
        key = node.key("levels")
        raw = node.raw("levels")
        for i, (z, speed) in enumerate(table):
            item = f"{key}[{i}]"
            if i == 0 and z != 0.0:
                raise SceneError(node.file, item, "the first level at the surface, z = 0",
                                 raw[i], "give the levels from the surface (z = 0) downwards")
            if i > 0 and not z < table[i - 1, 0]:
                raise SceneError(node.file, item, f"z < {table[i - 1, 0]:g} m (levels from the "
                                 "surface downwards, z decreasing)", raw[i])
            if water_depth is not None and z < -water_depth:
                raise SceneError(node.file, item, f"a level above the seabed, z >= "
                                 f"{-water_depth:g} m (water depth {water_depth:g} m)", raw[i],
                                 "the level is below the seabed")
            if speed < 0.0:
                raise SceneError(node.file, item, "a speed >= 0 m/s", raw[i],
                                 "give the direction with heading_deg")
        z_levels = tuple(float(v) for v in table[:, 0])
        speeds = tuple(float(v) for v in table[:, 1])
        exponent = CurrentSpec.__dataclass_fields__["exponent"].default
    else:
        if "levels" in node:
            raise node.error("levels", "no levels for a power_law profile (surface_speed and "
                             "exponent)", node.raw("levels"), "or use profile: piecewise_linear")
        speed0 = node.float("surface_speed", ge=0.0, unit="m/s")
        exponent = node.float("exponent", CurrentSpec.__dataclass_fields__["exponent"].default,
                              gt=0.0)
        z_levels, speeds = (0.0,), (speed0,)
    vmax = max(speeds)
    if vmax > MAX_PLAUSIBLE_CURRENT:
        _warn(node, "levels" if profile == "piecewise_linear" else "surface_speed",
              f"a current of {vmax:g} m/s is faster than strong ocean currents "
              f"({MAX_PLAUSIBLE_CURRENT:g} m/s); floatmoor expects m/s, not knots")
    return CurrentSpec(profile=profile, z=z_levels, speed=speeds, heading=heading,
                       exponent=exponent)


# -- physics helpers used by the checks -------------------------------------------------------
def peak_wavelength(tp: float, water_depth: float | None = None, gravity: float = GRAVITY) -> float:
    """Linear (Airy) wave length in m at period ``tp`` (s) in ``water_depth`` (m; None: deep).

    Solves the dispersion relation w^2 = g k tanh(k d) by Newton's method from Eckart's
    approximation k0 = w^2 / (g sqrt(tanh(w^2 d / g))).
    """
    omega = 2.0 * math.pi / tp
    k_deep = omega * omega / gravity
    if water_depth is None or k_deep * water_depth > 20.0:
        return 2.0 * math.pi / k_deep
    d = water_depth
    k = k_deep / math.sqrt(math.tanh(k_deep * d))
    for _ in range(50):
        th = math.tanh(k * d)
        f = gravity * k * th - omega * omega
        df = gravity * (th + k * d * (1.0 - th * th))
        step = f / df
        k -= step
        if abs(step) < 1e-13 * k:
            break
    return 2.0 * math.pi / k


def _warn(node: Node, key: str, message: str) -> None:
    warnings.warn(f"{node.file}: {node.key(key)}: {message}", FloatmoorWarning, stacklevel=4)


# -- description ------------------------------------------------------------------------------
def environment_models(env: Environment) -> list[str]:
    """Model names the environment asks for, e.g. ``["waves:jonswap", "wind:npd"]``."""
    out = []
    if env.waves is not None:
        out.append("waves:" + "+".join(w.spectrum for w in wave_systems(env.waves)))
    if env.wind is not None:
        out.append(f"wind:{env.wind.spectrum}")
    if env.current is not None:
        out.append(f"current:{env.current.profile}")
    return out


def _rule_gamma_text(hs: float, tp: float) -> str:
    # DNV-RP-C205 sec. 3.5.5.5, as floatmoor.metocean.spectra.dnv_gamma (not imported here: it
    # pulls in numba and `floatmoor check` must start fast; a test checks they agree).
    r = tp / math.sqrt(hs)
    gamma = 5.0 if r <= 3.6 else (math.exp(5.75 - 1.15 * r) if r < 5.0 else 1.0)
    return f"{gamma:.3g} from the DNV-RP-C205 rule (Tp/sqrt(Hs) = {r:.3g})"


def _describe_system(w: WaveSpec, label: str, water_depth, gravity) -> list[str]:
    gamma = f"{w.gamma:g}" if w.gamma is not None else _rule_gamma_text(w.hs, w.tp)
    text = f"  waves: {label}{w.spectrum}  Hs {w.hs:g} m  Tp {w.tp:g} s"
    if w.spectrum == "jonswap":
        text += f"  gamma {gamma}"
    text += f"  heading {math.degrees(w.heading):g} deg"
    lp = peak_wavelength(w.tp, water_depth, gravity)
    out = [text, f"         steepness Hs/Lp 1/{lp / w.hs:.3g} (Lp {lp:.4g} m)"]
    if w.spreading == "none":
        out.append("         long-crested (no spreading)")
    else:
        out.append(f"         spreading {w.spreading}, s = {w.spreading_s:g}, "
                   f"{w.n_directions} directions")
    return out


def describe_environment(env: Environment, *, water_depth: float | None = None,
                         gravity: float = GRAVITY) -> list[str]:
    """Lines describing each environment model and its parameters (angles in degrees)."""
    head = f"environment: {env.name or '(unnamed)'}"
    head += f"  [file {env.source}]" if env.source else "  [inline]"
    lines = [head]
    w = env.waves
    if w is None:
        lines.append("  waves: none")
    else:
        systems = wave_systems(w)
        several = len(systems) > 1
        if several:
            lines.append(f"  waves: {len(systems)} wave systems, Hs {w.hs:.3g} m in all "
                         "(sqrt of the sum of Hs^2)")
        names = getattr(w, "names", ()) or tuple(f"system{i + 1}" for i in range(len(systems)))
        for name, ws in zip(names, systems):
            lines += _describe_system(ws, f"{name}: " if several else "", water_depth, gravity)
        disc = [f"omega_min {w.omega_min:g} rad/s" if w.omega_min is not None else None,
                f"omega_max {w.omega_max:g} rad/s" if w.omega_max is not None else None,
                f"{w.n_frequencies} frequencies" if w.n_frequencies is not None else None]
        disc = [d for d in disc if d]
        lines.append("         discretisation: " + (", ".join(disc) if disc else
                                                      "chosen by the realisation")
                     + ("; random amplitudes" if w.random_amplitudes else
                        "; deterministic amplitudes, random phases"))
    v = env.wind
    if v is None:
        lines.append("  wind: none")
    else:
        gust = "no gust" if v.spectrum == "constant" else f"{v.spectrum} gust spectrum"
        lines.append(f"  wind: {v.spectrum}  U10 {v.u10:g} m/s (1-hour mean at 10 m), {gust}"
                     f"  heading {math.degrees(v.heading):g} deg  reference height "
                     f"{v.reference_height:g} m")
        disc = [f"f_min {v.f_min:g} Hz" if v.f_min is not None else None,
                f"f_max {v.f_max:g} Hz" if v.f_max is not None else None,
                f"{v.n_frequencies} frequencies" if v.n_frequencies is not None else None]
        disc = [d for d in disc if d]
        if disc:
            lines.append("        gust discretisation: " + ", ".join(disc))
    c = env.current
    if c is None:
        lines.append("  current: none")
    elif c.profile == "power_law":
        lines.append(f"  current: power_law  surface speed {c.speed[0]:g} m/s  exponent "
                     f"{c.exponent:.4g}  heading {math.degrees(c.heading):g} deg")
    else:
        levels = ", ".join(f"{s:g} m/s at z = {z:g} m" for z, s in zip(c.z, c.speed))
        lines.append(f"  current: piecewise_linear  heading {math.degrees(c.heading):g} deg")
        lines.append(f"         {levels}; constant below z = {c.z[-1]:g} m")
    return lines

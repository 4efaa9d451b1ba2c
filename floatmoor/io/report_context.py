"""What a design report needs from the scene besides the results: the environment in words, the
mooring and its design keys, the limits, and what the scene leaves out that could matter.

:func:`scene_context` turns a loaded :class:`~floatmoor.io.scene.Scene` and the results read
back into a :class:`~floatmoor.post.report.ReportContext`; ``floatmoor report`` and the campaign
report pass it to the report writer.  The scene is the one named in the results
(``scene_file``): its fingerprint is compared with the one the results carry, and a section
that changed since the run is named in the report (the design checks guard the mooring
themselves: its catenary must give the recorded tensions).
"""

from __future__ import annotations

import json
import math

from ..post.report import ReportContext

__all__ = ["environment_rows", "omissions", "scene_context"]


def environment_rows(env, *, water_depth=None) -> list[tuple[str, str]]:
    """The environment as (label, text) rows: waves, wind, current, headings, source."""
    from .environment import _rule_gamma_text
    rows = []
    w = env.waves
    heads = []
    if w is None:
        rows.append(("waves", "none"))
    else:
        text = f"{w.spectrum.replace('_', '-')}, Hs {w.hs:g} m, Tp {w.tp:g} s"
        if w.spectrum == "jonswap":
            text += ", gamma " + (f"{w.gamma:g}" if w.gamma is not None
                                  else _rule_gamma_text(w.hs, w.tp))
        text += (", long-crested" if w.spreading == "none"
                 else f", spreading {w.spreading} (s = {w.spreading_s:g})")
        rows.append(("waves", text))
        heads.append(f"waves {math.degrees(w.heading):g}")
    v = env.wind
    if v is None:
        rows.append(("wind", "none"))
    else:
        gust = "no gust" if v.spectrum == "constant" else f"{v.spectrum.upper()} gust spectrum"
        rows.append(("wind", f"U10 {v.u10:g} m/s (1-hour mean at 10 m), {gust}"))
        heads.append(f"wind {math.degrees(v.heading):g}")
    c = env.current
    if c is None:
        rows.append(("current", "none"))
    elif c.profile == "power_law":
        rows.append(("current", f"{c.speed[0]:g} m/s at the surface, power law (exponent "
                     f"{c.exponent:.3g})"))
        heads.append(f"current {math.degrees(c.heading):g}")
    else:
        levels = ", ".join(f"{s:g} m/s at {z:g} m" for z, s in zip(c.z, c.speed))
        rows.append(("current", f"{max(c.speed):g} m/s; profile {levels}, constant below "
                     f"{c.z[-1]:g} m"))
        heads.append(f"current {math.degrees(c.heading):g}")
    rows.append(("headings", (", ".join(heads) + " deg (direction of travel, from +x towards "
                              "+y)") if heads else "none"))
    if env.name or env.source:
        rows.append(("environment", " ".join(x for x in (env.name, f"[{env.source}]"
                                                           if env.source else "") if x)))
    return rows


def omissions(scene, results, system=None) -> list[str]:
    """What the scene leaves out that could matter for the design (sentences)."""
    out = []
    a0 = results[0].attrs
    models = [str(m) for m in (a0.get("models") or [])]
    fe = set(map(str, a0.get("fe_lines", []) or []))
    names = [str(v) for v in results[0]["line"].values] if "line" in results[0].coords else []
    qs = [n for n in names if n not in fe]
    env = scene.environment
    if qs:
        out.append(f"line dynamics: {len(qs)} of {len(names)} lines are quasi-static (no line "
                   "inertia or drag in their tension); the quasi-static partial safety factors "
                   "apply unless finite-element lines or the dynamic amplification of "
                   "floatmoor lines (--daf) are given")
        if env.current is not None and max(env.current.speed) > 0:
            out.append("current drag on the lines: not modelled on the quasi-static lines; it "
                       "raises the mean tension of the lines facing the current (the frequency "
                       "domain's option frequency_domain: line_current_drag estimates it; "
                       "finite-element lines include it)")
    if any(m.startswith("drift") for m in models) or env.waves is not None:
        out.append("wave drift damping: not in the time domain (the frequency domain's "
                   "wave_drift_damping option has Aranha's)")
    fs = scene.forces
    vd = getattr(fs, "viscous_drift", None) if fs is not None else None
    if env.waves is not None and (vd is None or getattr(vd, "model", "none") == "none"):
        out.append("viscous wave drift (current and steep waves): not modelled (forces: "
                   "viscous_drift: slender_elements or correction_formula)")
    if env.waves is not None and env.waves.spreading == "none":
        out.append("wave spreading: long-crested waves")
    if "drift_newman" in models:
        out.append("second-order difference-frequency forces: Newman's approximation from the "
                   "mean drift (no full QTF)")
    out.append("marine growth on the lines (weight, diameter and drag): not modelled")
    if system is not None:
        fibre = [ln.name for ln in system.lines for s in ln.segments
                 if getattr(s, "fibre", None) is None and _is_fibre_type(system, s)]
        fibre = list(dict.fromkeys(fibre))
        if fibre:
            which = (f"all {len(fibre)} lines" if len(fibre) == system.n_lines
                     else ", ".join(fibre))
            out.append(f"fibre rope stiffness: constant EA on the fibre segments of {which} "
                       "(no load-dependent stiffness, no lower and upper bound: line type key "
                       "fibre)")
    out.append("one sea state and one heading: the design environment covers the contour "
               "of sea states and every heading (floatmoor campaign)")
    n = len(results)
    if n < 20:
        out.append(f"{n} seeds (the characteristic tension of Wang (2016) takes 20)")
    return out


def _is_fibre_type(system, seg) -> bool:
    from ..post.capacity import is_fibre
    return is_fibre(system, seg)


def _fingerprint_notes(scene, results) -> list[str]:
    from ..analyses.fingerprint import FINGERPRINT_ATTR, differing_keys, scene_fingerprint
    text = results[0].attrs.get(FINGERPRINT_ATTR)
    if not text:
        return ["the results carry no input fingerprint: the scene file could not be compared "
                "with the one of the run"]
    try:
        old = json.loads(text)
        diff = differing_keys(old, scene_fingerprint(scene))
    except Exception as exc:  # noqa: BLE001 - a note, not a failure
        return [f"the scene file could not be compared with the run ({exc})"]
    diff = [d for d in diff if d != "overrides"]
    if not diff:
        return ["the scene file is unchanged since the run (its fingerprint matches)"]
    return [f"the scene file changed since the run in: {', '.join(diff)}; the environment and "
            "limits shown are the current file's; the mooring is checked against the recorded "
            "tensions (its catenary must reproduce them)"]


def scene_context(scene, results) -> ReportContext:
    """The :class:`~floatmoor.post.report.ReportContext` of a scene and its results."""
    from .mooring_design import parse_mooring_design
    from .mooring_section import parse_mooring
    site = scene.site
    system = design = None
    node = scene.mooring_node()
    if node is not None:
        system = parse_mooring(node, water_depth=site.water_depth,
                               water_density=site.water_density, gravity=site.gravity)
        design = parse_mooring_design(node)
    return ReportContext(scene_file=str(scene.file or ""),
                         environment=tuple(environment_rows(scene.environment,
                                                            water_depth=site.water_depth)),
                         omissions=tuple(omissions(scene, results, system)),
                         notes=tuple(_fingerprint_notes(scene, results)),
                         mooring=system, design=design, limits=scene.limits)

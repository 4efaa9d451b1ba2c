"""The design verdict: one line per limit state and check, and the verdict over all of them.

Each :class:`VerdictLine` is PASS, FAIL, NOT CHECKED (a check the inputs do not allow: no
ALS results, no fatigue result, no anchor capacity, no offset limit...) or INCOMPLETE (results
the analysis itself asked for are missing: a campaign's cases sent to the time domain whose
storms failed or have not run), with the governing item, its utilisation and a sentence.
:func:`overall` is FAIL when any line fails, else INCOMPLETE when results are missing (the
checks made cannot stand for the design: the missing case may govern), else PASS -- with the
list of what was not checked when something was not.  ``floatmoor report`` exits with status 1
when the verdict is FAIL; ``floatmoor report`` of a campaign also when it is INCOMPLETE.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["FAIL", "INCOMPLETE", "NOT_CHECKED", "PASS", "VerdictLine", "anchor_lines", "fe_selfcheck_line",
           "fibre_line", "fls_line", "line_tension_line", "offset_line", "overall"]

PASS, FAIL, NOT_CHECKED, INCOMPLETE = "PASS", "FAIL", "NOT CHECKED", "INCOMPLETE"
_KN = 1e-3


@dataclass(frozen=True)
class VerdictLine:
    """One check of the verdict: ``limit_state`` (ULS, ALS, FLS), ``check`` (line tension,
    fatigue, anchor uplift, anchor load, offsets, fibre ropes), ``status``, ``utilisation``
    (governing; NaN when none), ``governing`` (line, location...) and ``text``."""

    limit_state: str
    check: str
    status: str
    utilisation: float = float("nan")
    governing: str = ""
    text: str = ""

    @property
    def label(self) -> str:
        return f"{self.limit_state} {self.check}"

    def cli(self) -> str:
        return f"{self.limit_state:<4s}{self.check:<15s}{self.status:<12s}{self.text}"


def overall(lines) -> tuple[str, str]:
    """``(status, sentence)`` of the verdict over ``lines``: FAIL when one fails, else
    INCOMPLETE when one is incomplete, else PASS; the sentence names the failing checks, the
    incomplete ones, or those not checked."""
    lines = list(lines)
    failed = [v.label for v in lines if v.status == FAIL]
    missing = [v.label for v in lines if v.status == NOT_CHECKED]
    incomplete = [v.label for v in lines if v.status == INCOMPLETE]
    if failed:
        return FAIL, "FAIL: " + ", ".join(failed)
    if incomplete:
        return INCOMPLETE, ("INCOMPLETE, no design verdict: results missing for "
                            + ", ".join(incomplete))
    if missing:
        return PASS, "PASS for the checks made; not checked: " + ", ".join(missing)
    return PASS, "PASS: every check passes"


def fe_selfcheck_line(results) -> VerdictLine | None:
    """The self-check of the finite-element lines of the seeds (their ``selfcheck`` variable,
    :mod:`floatmoor.mooring.fe.selfcheck`): FAIL naming the seeds and lines whose answer broke a
    bound a correct solution keeps, PASS when every FE line of every seed kept them; None for
    results without FE lines (or written before the self-check existed: NOT CHECKED)."""
    have = [ds for ds in results if "line_model" in ds and
            np.any(ds["line_model"].values == "finite-element")]
    if not have:
        return None
    if not all("selfcheck" in ds for ds in have):
        return VerdictLine("ULS", "FE self-check", NOT_CHECKED,
                           text="finite-element results written without the self-check: rerun "
                                "them")
    bad = []
    for ds in have:
        seed = ds.attrs.get("seed", "?")
        for n, c in zip(ds["line"].values, ds["selfcheck"].values):
            if str(c) not in ("ok", "-"):
                bad.append(f"seed {seed} {n}: {c}")
    if bad:
        return VerdictLine("ULS", "FE self-check", FAIL, governing=bad[0].split(":")[0],
                           text=f"{len(bad)} line result(s) break a bound of the FE self-check "
                                f"(their tensions are not to be used): " + "; ".join(bad[:3])
                                + (" ..." if len(bad) > 3 else ""))
    return VerdictLine("ULS", "FE self-check", PASS,
                       text=f"every finite-element line of {len(have)} seed(s) within the "
                            "tension, energy and compression bounds")


def _gov(checks, ls):
    c = checks.sel(limit_state=ls)
    u = c["utilisation"].values
    j = int(np.nanargmax(u))
    return c, j


def line_tension_line(checks, ls: str, *, daf=None) -> VerdictLine:
    """The ULS/ALS line-tension line from a check Dataset (:func:`floatmoor.post.dnv_os_e301.
    check_lines`); ``daf``: the dynamic amplification applied per line (or None)."""
    if ls not in checks["limit_state"].values:
        hint = "give the results of a failed-line scene with --als-dir" if ls == "ALS" else ""
        return VerdictLine(ls, "line tension", NOT_CHECKED,
                           text=f"no {ls} results" + (f" ({hint})" if hint else ""))
    c, j = _gov(checks, ls)
    line = str(c["line"].values[j])
    u = float(c["utilisation"].values[j])
    n_fail = int((c["checked"].values & ~c["passed"].values).sum())
    eol = "s_c_new" in c and not np.allclose(c["s_c_new"].values, c["s_c"].values)
    text = (f"{line}: T_C {c['t_c'].values[j] * _KN:.0f} kN (mean "
            f"{c['t_c_mean'].values[j] * _KN:.0f}"
            + (f", DAF {daf[j]:.3f} on T_C-dyn" if daf is not None and np.isfinite(daf[j])
               else "") + f"), design tension {c['design_tension'].values[j] * _KN:.0f} kN, "
            f"S_C {c['s_c'].values[j] * _KN:.0f} kN")
    if eol:
        text += (f" end of life ({c['s_c_new'].values[j] * _KN:.0f} new), utilisation {u:.3f} "
                 f"(new {float(c['utilisation_new'].values[j]):.3f})")
    else:
        text += f", utilisation {u:.3f}"
    ties = [str(ln) for ln, uj in zip(c["line"].values, c["utilisation"].values)
            if str(ln) != line and np.isfinite(uj) and uj >= u * (1 - 1e-3)]
    if ties:
        text += f" (equal within 0.1 %: {', '.join(ties)})"
    if ls == "ALS" and checks.attrs.get("failed_lines"):
        text += f"; failed: {checks.attrs['failed_lines']}"
    if n_fail:
        text += f"; {n_fail} line(s) fail"
    status = PASS if u <= 1.0 else FAIL
    missing = checks.attrs.get("end_of_life_missing")
    if missing and status == PASS:
        # the new line passes; the code asks for the corroded one, which is unknown
        status = NOT_CHECKED
        text += f" -- the new line passes, but {missing}"
    return VerdictLine(ls, "line tension", status, u, line, text)


def fls_line(fls) -> VerdictLine:
    """The FLS line from the recomputed fatigue check (``None``: not given)."""
    if fls is None:
        return VerdictLine("FLS", "fatigue", NOT_CHECKED,
                           text="no fatigue result (floatmoor fatigue --out F.nc, then "
                                "--fatigue F.nc)")
    u = fls["utilisation"].values
    jg, ig = np.unravel_index(np.nanargmax(u), u.shape)
    loc = str(fls["location"].values[jg])
    line = str(fls["line"].values[ig])
    ug = float(u[jg, ig])
    n_fail = int(np.sum(np.isfinite(u) & (u > 1.0)))
    n_all = int(np.sum(np.isfinite(u)))
    text = (f"{line} at the {loc}: gamma_F d_C = {float(fls['gamma_f'].values[jg]):.2f} x "
            f"{float(fls['d_c'].values[jg, ig]):.3g} = {ug:.3f}, fatigue life "
            f"{float(fls['fatigue_life'].values[jg, ig]):.4g} years")
    if n_fail:
        text += f"; FAIL at {n_fail} of {n_all} locations"
    return VerdictLine("FLS", "fatigue", PASS if ug <= 1.0 else FAIL, ug, f"{line} {loc}", text)


def anchor_lines(anchors, ls: str) -> list[VerdictLine]:
    """The anchor uplift and anchor load lines of a limit state (``anchors``: the Dataset of
    :func:`floatmoor.post.design_checks.anchor_checks`, or None when no mooring was given)."""
    if anchors is None:
        why = "the mooring of the scene is not available"
        return [VerdictLine(ls, "anchor uplift", NOT_CHECKED, text=why),
                VerdictLine(ls, "anchor load", NOT_CHECKED, text=why)]
    ok = anchors["checked"].values
    names = [str(v) for v in anchors["line"].values]
    up = anchors["uplift_c"].values
    lim = anchors["uplift_limit"].values
    fails = [n for n, a, p in zip(names, ok, anchors["uplift_passed"].values) if a and not p]
    j = int(np.nanargmax(np.where(ok, up, np.nan)))
    types = sorted(set(anchors["anchor_type"].values[ok]))
    assumed = not bool(np.all(anchors["anchor_type_given"].values[ok]))
    gl = anchors["grounded_length_at_max_offset"].values
    kg = int(np.nanargmin(np.where(ok, gl, np.nan))) if np.isfinite(gl[ok]).any() else -1
    grounded = (f"; smallest grounded length at the largest offset {gl[kg]:.0f} m "
                f"({names[kg]})" if kg >= 0 else "")
    lim_j = lim[j]
    limit_text = "no limit" if not np.isfinite(lim_j) else f"allowed {lim_j:g} deg"
    if fails:
        status = FAIL
        text = (f"{', '.join(fails)}: the anchor lifts, uplift angle {up[j]:.2f} deg at "
                f"{names[j]} ({anchors['anchor_type'].values[j]}, {limit_text})")
    else:
        status = PASS
        text = (f"largest uplift angle {up[j]:.2f} deg ({names[j]}, "
                f"{anchors['anchor_type'].values[j]}, {limit_text})")
    text += grounded + f"; anchor types {', '.join(types)}" + (
        " (drag assumed where the mooring file gives no anchor_type)" if assumed else "")
    v_up = VerdictLine(ls, "anchor uplift", status, float("nan"), names[j], text)
    load_checked = anchors["load_checked"].values & ok
    dl = anchors["design_load"].values
    jd = int(np.nanargmax(np.where(ok, dl, np.nan)))
    if not load_checked.any():
        v_load = VerdictLine(ls, "anchor load", NOT_CHECKED, float("nan"), names[jd],
                             f"largest design load {dl[jd] * _KN:.0f} kN ({names[jd]}, T_C "
                             f"{anchors['t_c'].values[jd] * _KN:.0f} kN); no anchor capacity "
                             "in the mooring file (lines[].anchor_capacity)")
    else:
        u = np.where(load_checked, anchors["utilisation"].values, np.nan)
        k = int(np.nanargmax(u))
        missing = [n for n, c, a in zip(names, load_checked, ok) if a and not c]
        status = FAIL if np.nanmax(u) > 1.0 else PASS
        text = (f"{names[k]}: design load {dl[k] * _KN:.0f} kN x "
                f"{anchors['resistance_factor'].values[k]:g} against the capacity "
                f"{anchors['capacity'].values[k] * _KN:.0f} kN, utilisation {u[k]:.3f}")
        if missing:
            text += f"; not checked (no capacity): {', '.join(missing)}"
        v_load = VerdictLine(ls, "anchor load", status, float(u[k]), names[k], text)
    return [v_up, v_load]


def offset_line(res: dict, ls: str, limits_given: bool) -> VerdictLine:
    """The offsets and points line (``res``: :func:`floatmoor.post.design_checks.
    offset_checks`)."""
    off, pts = res.get("offsets"), res.get("points")
    items = []
    if off is not None:
        for k, name in enumerate(off["offset_limit"].values):
            if bool(off["applies"].values[k]):
                items.append((float(off["ratio_c"].values[k]), f"offset {name}",
                              bool(off["passed"].values[k])))
    if pts is not None:
        for k, name in enumerate(pts["point"].values):
            if bool(pts["applies"].values[k]) and bool(pts["has_limit"].values[k]):
                items.append((float(pts["ratio_c"].values[k]), f"point {name}",
                              bool(pts["passed"].values[k])))
    offset_c = res.get("offset_c")
    if not items:
        why = ("no offset limit or point limit in the scene (limits:)" if not limits_given
               else f"no limit of the scene applies in the {ls}")
        if offset_c is not None:
            why += f"; characteristic offset {offset_c:.1f} m"
        return VerdictLine(ls, "offsets", NOT_CHECKED, text=why)
    u, name, _ = max(items, key=lambda x: x[0] if math.isfinite(x[0]) else -1.0)
    fails = [n for _, n, ok in items if not ok]
    text = (f"{name}: characteristic / limit = {u:.3f}"
            + (f"; FAIL: {', '.join(fails)}" if fails else "")
            + (f"; characteristic offset {offset_c:.1f} m" if offset_c is not None else ""))
    return VerdictLine(ls, "offsets", FAIL if fails else PASS, u, name, text)


def fibre_line(fib, ls: str) -> VerdictLine | None:
    """The fibre-rope line (None when no line has fibre rope)."""
    if fib is None:
        return None
    names = [str(v) for v in fib["line"].values]
    ok = fib["checked"].values
    problems = []
    for k, n in enumerate(names):
        if not ok[k]:
            continue
        if not fib["seabed_passed"].values[k]:
            problems.append(f"{n} rope on the seabed ({fib['seabed_length_c'].values[k]:.0f} m)")
        if not fib["slack_passed"].values[k]:
            problems.append(f"{n} slack rope (minimum tension "
                            f"{fib['t_min_c'].values[k] * _KN:.0f} kN)")
        if not fib["strength_passed"].values[k]:
            problems.append(f"{n} rope strength (utilisation "
                            f"{fib['utilisation'].values[k]:.3f})")
    tmin = np.where(ok, fib["t_min_c"].values, np.nan)
    k = int(np.nanargmin(tmin))
    summary = (f"smallest rope tension {tmin[k] * _KN:.0f} kN ({names[k]}); largest rope on the "
               f"seabed {np.nanmax(np.where(ok, fib['seabed_length_c'].values, np.nan)):.0f} m")
    util = np.where(ok, fib["utilisation"].values, np.nan)
    if np.isfinite(util).any():
        summary += f"; largest rope utilisation {np.nanmax(util):.3f}"
    else:
        summary += "; rope strength: in the line tension check (the weakest segment)"
    if problems:
        return VerdictLine(ls, "fibre ropes", FAIL, float("nan"), problems[0].split()[0],
                           "; ".join(problems[:4]) + (f" (and {len(problems) - 4} more)"
                                                      if len(problems) > 4 else ""))
    return VerdictLine(ls, "fibre ropes", PASS, float("nan"), names[k], summary)

"""Fatigue locations of the lines of a quasi-static mooring, their tension spectra from a
frequency-domain result, their T-N curves and the spectral damage rates.

Layer ``post``: the mooring (:class:`floatmoor.mooring.system.MooringSystem`) and the FD result
(:func:`floatmoor.frequency_domain`) are passed in; nothing above ``core`` is imported.

Fatigue locations of each line (quasi-static line, seabed without friction)
--------------------------------------------------------------------------
* ``fairlead``: the top segment at the fairlead (fairlead tension);
* ``segN_top``: the top end of the N-th segment from the anchor (below the fairlead segment),
  ``T = sqrt(H^2 + max(V_f - W_above, 0)^2)`` with ``W_above`` the submerged weight (and point
  loads) of the segments above (vertical equilibrium of the suspended line);
* ``touchdown``: the segment at the touchdown point, ``T = H`` (the anchor tension when no line
  lies on the seabed).

WF tension spectra: ``|H_x(w) . g|^2 S(w)`` with ``g`` the location tension's gradient with respect
to the pose (central differences of the catenary at the FD mean pose, as the FD does for the
fairlead) and ``H_x`` the FD motion RAOs (exact in the linear FD model).  LF tension spectra: the
FD's LF spectrum of the fairlead motion along the line times ``(dT/du)^2`` (``u`` the fairlead
displacement along the line), scaled per line so that the fairlead's LF variance equals the FD's
``tension_std_lf^2`` (the FD result holds the LF spectra of the motions, not their LF
cross-spectra; the scaling factor is kept as ``lf_shape_scale``).  Time domain: the fairlead
tension of the run, and for the other locations the quasi-static relation between the fairlead
tension and the location tension along the line's direction (a table at the mean pose).
"""

from __future__ import annotations

import math

import numpy as np

from ...core.errors import SceneError

__all__ = ["damage_rates", "fatigue_locations", "line_directions", "location_curves",
           "location_gradients", "location_segments", "location_tensions", "tension_spectra",
           "undamped_lf_notes"]

_POSE_STEPS = np.array([0.01, 0.01, 0.01, 1e-5, 1e-5, 1e-5])
"""Pose steps of the central differences (m, rad): those of the FD's tension gradient."""


# -- fatigue locations ---------------------------------------------------------------------------
def fatigue_locations(mooring) -> list[str]:
    """Location names of a mooring: ``fairlead``, ``segN_top`` of the segments below the top
    one (N from the anchor, the most segments of any line) and ``touchdown``."""
    nseg = max(len(line.segments) for line in mooring.lines)
    return ["fairlead"] + [f"seg{k + 1}_top" for k in range(nseg - 2, -1, -1)] + ["touchdown"]


def location_segments(mooring, locations, pose=None) -> np.ndarray:
    """(n_locations, n_lines) index of the segment (in the line, from the anchor) at each
    location; -1 where the line has no such location.  The touchdown segment is taken at
    ``pose`` (default: zero pose)."""
    t = mooring.tensions(np.zeros(6) if pose is None else pose)
    grounded = t["grounded_length"].values
    out = np.full((len(locations), mooring.n_lines), -1, int)
    for i, line in enumerate(mooring.lines):
        n = len(line.segments)
        cum = np.cumsum([s.length for s in line.segments])
        for j, loc in enumerate(locations):
            if loc == "fairlead":
                out[j, i] = n - 1
            elif loc == "touchdown":
                g = grounded[i] if np.isfinite(grounded[i]) else 0.0
                out[j, i] = int(min(np.searchsorted(cum, g), n - 1)) if g > 0 else 0
            else:
                k = int(loc[3:-4]) - 1
                out[j, i] = k if k < n - 1 else -1
    return out


def location_tensions(mooring, pose, locations) -> np.ndarray:
    """(n_locations, n_lines) tension (N) at the fatigue locations at ``pose``."""
    t = mooring.tensions(pose)
    hf = t["horizontal_fairlead"].values
    vf = t["vertical_fairlead"].values
    tf = t["fairlead_tension"].values
    ta = t["anchor_tension"].values
    grounded = t["grounded_length"].values
    out = np.full((len(locations), mooring.n_lines), np.nan)
    for i, line in enumerate(mooring.lines):
        segs = line.segments
        n = len(segs)
        for j, loc in enumerate(locations):
            if loc == "fairlead":
                out[j, i] = tf[i]
            elif loc == "touchdown":
                out[j, i] = hf[i] if grounded[i] > 0 else ta[i]
            else:
                k = int(loc[3:-4]) - 1
                if k >= n - 1:
                    continue
                w_above = sum(s.w * s.length for s in segs[k + 1:])
                w_above += sum(s.point_load for s in segs[k:n - 1])
                out[j, i] = math.hypot(hf[i], max(vf[i] - w_above, 0.0))
    return out


def location_gradients(mooring, pose, locations) -> np.ndarray:
    """(n_locations, n_lines, 6) d T_location / d pose by central differences."""
    g = np.zeros((len(locations), mooring.n_lines, 6))
    for k in range(6):
        dp = np.zeros(6)
        dp[k] = _POSE_STEPS[k]
        g[:, :, k] = (location_tensions(mooring, pose + dp, locations)
                      - location_tensions(mooring, pose - dp, locations)) / (2 * _POSE_STEPS[k])
    mooring.tensions(pose)
    return g


def line_directions(mooring, pose) -> np.ndarray:
    fl = mooring.fairlead_positions(pose)
    d = fl[:, :2] - mooring.anchors[:, :2]
    e = np.zeros((mooring.n_lines, 3))
    e[:, :2] = d / np.linalg.norm(d, axis=1)[:, None]
    return e


def tension_spectra(ds, mooring, locations):
    """WF and LF tension spectra of every location from one FD result ``ds`` (of one wave
    direction, ``rao``, or of several, ``rao_direction``: their spectra add).

    Returns ``(wf, lf, mean, scale)``: ``wf`` (n_omega, n_loc, n_lines), ``lf`` (n_mu, n_loc,
    n_lines) in N^2 s/rad, the mean tensions (n_loc, n_lines) and the per-line LF shape scale."""
    pose = np.asarray(ds["mean"].values, float)
    g = np.nan_to_num(location_gradients(mooring, pose, locations))
    if "rao" in ds:
        rao = ds["rao"].values[..., 0] + 1j * ds["rao"].values[..., 1]  # (n_w, 6)
        S = ds["wave_spectrum"].values
        h = np.einsum("wk,lik->wli", rao, g)
        wf = np.abs(h) ** 2 * S[:, None, None]
    else:
        # a sea of several directions: the directions are independent, their spectra add
        r = ds["rao_direction"].values
        rao = r[..., 0] + 1j * r[..., 1]                                  # (n_dir, n_w, 6)
        S = ds["wave_spectrum_direction"].values                          # (n_dir, n_w)
        h = np.einsum("dwk,lik->dwli", rao, g)
        wf = np.sum(np.abs(h) ** 2 * S[:, :, None, None], axis=0)
    e = line_directions(mooring, pose)
    tangent = np.einsum("lik,ik->li", g[:, :, :3], e)  # dT/du along the line
    fm = ds["fairlead_motion_lf_spectrum"].values  # (n_mu, n_lines)
    mu = ds["mu"].values
    approx = tangent[0] ** 2 * np.trapezoid(fm, mu, axis=0)
    exact = np.nan_to_num(ds["tension_std_lf"].values) ** 2
    scale = np.where(approx > 0, exact / np.where(approx > 0, approx, 1.0), 0.0)
    lf = fm[:, None, :] * (tangent ** 2)[None] * scale[None, None, :]
    mean = location_tensions(mooring, pose, locations)
    return wf, lf, mean, scale


def undamped_lf_notes(ds) -> list[str]:
    """Notes for the horizontal DOFs (surge, sway, yaw) that the FD result excites at low
    frequency without any LF damping: their LF response is bounded only by the LF frequency
    grid, so the LF tension and its damage are not reliable."""
    out = []
    b = np.asarray(ds["lf_damping"].values)
    for k, small in ((0, 1e-4), (1, 1e-4), (5, 1e-6)):  # m, m, rad: below is numerical noise
        dof = str(ds["dof"].values[k])
        if b[k, k] <= 0.0 and float(ds["lf_std"].values[k]) > small:
            out.append(f"the frequency domain has no LF {dof} damping (lf_damping 0: no linear, "
                       f"quadratic, wind or current damping in {dof}): its LF {dof} resonance "
                       "is bounded only by the LF frequency grid and the FD damage of the sea "
                       f"states that excite it is not reliable (see FD against TD): give the "
                       f"vessel a {dof} damping")
    return out


def location_curves(mooring, locations, segments, *, design_life, corrosion):
    """T-N curves (objects), range references (RBS in N, or the nominal area in mm^2 of an S-N
    curve in MPa) and segment type names per (location, line)."""
    from ...mooring.line_types import mbs_known
    from .tn_curves import curve_for, reference_breaking_strength
    n_loc, n_l = segments.shape
    curves = np.empty((n_loc, n_l), object)
    rbs = np.full((n_loc, n_l), np.nan)
    types = np.full((n_loc, n_l), "", object)
    for j, loc in enumerate(locations):
        zone = "bottom" if loc == "touchdown" else "catenary"
        for i, line in enumerate(mooring.lines):
            k = segments[j, i]
            if k < 0:
                continue
            seg = line.segments[k]
            lt = mooring.line_types.get(seg.line_type)
            if lt is None:
                raise SceneError(mooring.source or None, f"lines.{line.name}.segments[{k}].type",
                                 "a named line type (the fatigue analysis takes its T-N curve "
                                 "from the line type)", seg.line_type or "none")
            c = curve_for(lt, file=mooring.source or None)
            if c.basis == "rbs" and not mbs_known(seg.mbs):
                mooring.require_mbs(f"the fatigue analysis (T-N curve {c.name!r} of line type "
                                    f"{seg.line_type!r}: tension range over the reference "
                                    "breaking strength, RBS = MBS on the corroded area; an S-N "
                                    "curve in MPa such as chain_studless needs no MBS)")
            curves[j, i] = c
            rbs[j, i] = reference_breaking_strength(
                seg.mbs, lt.diameter, c, rate_mm_per_year=corrosion.get(zone, 0.0),
                design_life_years=design_life)
            types[j, i] = seg.line_type
    return curves, rbs, types


def damage_rates(mom_l, mom_w, curves, rbs):
    """(n_methods, ...) damage per second for every spectral method, from the LF and WF moment
    stacks ``(4, ...)`` (orders 0, 1, 2, 4, in N^2; any trailing shape, e.g. cells x locations x
    lines) on the T-N curves ``curves`` (object array of the trailing shape, None: no location)
    with the RBS ``rbs`` (N).  Vectorised per distinct curve."""
    from .spectral import METHODS, bimodal_damage
    mom_l, mom_w = np.asarray(mom_l, float), np.asarray(mom_w, float)
    rbs = np.broadcast_to(np.asarray(rbs, float), mom_l.shape[1:])
    curves = np.broadcast_to(np.asarray(curves, object), mom_l.shape[1:])
    out = np.full((len(METHODS),) + mom_l.shape[1:], np.nan)
    for c in {c for c in curves.ravel() if c is not None}:
        sel = np.vectorize(lambda x, c=c: x is c, otypes=[bool])(curves)
        r2 = rbs[sel] ** 2
        ml, mw = mom_l[:, sel] / r2, mom_w[:, sel] / r2
        with np.errstate(divide="ignore", invalid="ignore"):
            for k, meth in enumerate(METHODS):
                out[k][sel] = np.nan_to_num(bimodal_damage(meth, ml, mw, 1.0, c.a_d, c.m))
    return out

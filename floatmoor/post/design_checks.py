"""Design checks beyond the line tension: anchors, offsets and named points, fibre ropes.

The per-seed quantities come from :func:`floatmoor.post.design_statistics.
seed_design_statistics`; :func:`collect` stacks them over the seeds.  Characteristic values
are taken from the seeds as the characteristic line tension is (Wang (2016) section 5.4.4):
the Gumbel ``p`` fractile (0.9) of the seed maxima, the mean over the seeds for a mean value;
a sample whose maxima are all equal (e.g. no uplift in any seed) has that value; quantities
that must not exceed a small allowance (the uplift angle, rope on the seabed) take the larger of
the fractile and the largest value seen, and the smallest rope tension the smaller of the lower
fractile (Gumbel of the minima) and the smallest seen.

* :func:`anchor_checks` -- per line: the characteristic anchor tension (mean and maximum), the
  design anchor load with the code's factors (:meth:`floatmoor.post.design_codes.DesignCode.
  anchor_factors`) against the characteristic holding capacity of the mooring file divided by
  the code's resistance factor (no capacity given: the load is reported, the check is not
  made); the characteristic horizontal and vertical anchor force and uplift angle against the
  code's limit for the anchor type (a line without ``anchor_type`` is checked as a drag anchor,
  the type that allows no uplift; the mooring file may allow an angle per line); the grounded
  length at the largest offset.
* :func:`offset_checks` -- per offset limit the characteristic ratio of the offset to the limit
  in its direction (<= 1 passes); per named point its characteristic horizontal and vertical
  excursion against its limits.  No partial factor: the limits are the user's.
* :func:`fibre_checks` -- per line with fibre rope: no slack (the characteristic minimum tension
  of the rope above the code's fraction of its MBS, 0 in the shipped codes), no rope on the
  seabed (where the code forbids it), and the rope's own strength: the design tension against
  the rope's characteristic strength (its own MBS, no corrosion).
"""

from __future__ import annotations

import warnings

import numpy as np
import xarray as xr

from .extremes import gumbel_fit

__all__ = ["anchor_checks", "characteristic", "collect", "fibre_checks", "offset_checks"]

_LINE_VARS = ("anchor_tension_max", "anchor_tension_mean", "anchor_h_max", "anchor_v_max",
              "uplift_deg_max", "grounded_length_min", "grounded_length_at_max_offset",
              "rope_tension_min", "rope_seabed_length_max", "recompute_difference")
_UNITS = {"anchor_tension_max": ("N", "largest anchor tension in the window"),
          "anchor_tension_mean": ("N", "mean anchor tension in the window"),
          "anchor_h_max": ("N", "largest horizontal anchor force (quasi-static at the pose)"),
          "anchor_v_max": ("N", "largest vertical (upward) anchor force (quasi-static at the "
                           "pose)"),
          "uplift_deg_max": ("deg", "largest line angle above the seabed at the anchor"),
          "grounded_length_min": ("m", "smallest length of line on the seabed"),
          "grounded_length_at_max_offset": ("m", "length of line on the seabed at the largest "
                                            "offset"),
          "rope_tension_min": ("N", "smallest tension of the fibre rope (lower end of its "
                               "lowest rope segment)"),
          "rope_seabed_length_max": ("m", "largest length of fibre rope on the seabed"),
          "recompute_difference": ("1", "largest relative difference of the recomputed "
                                   "quasi-static fairlead tension from the recorded one")}


def collect(per_seed: list[dict], seeds) -> xr.Dataset:
    """Stack :func:`~floatmoor.post.design_statistics.seed_design_statistics` over seeds into a
    Dataset over ``(seed, line)``, ``(seed, offset_limit)`` and ``(seed, point)``."""
    first = per_seed[0]
    coords = {"seed": list(seeds), "line": first["line"]}
    data = {k: (("seed", "line"), np.array([s[k] for s in per_seed], float),
                {"units": _UNITS[k][0], "long_name": _UNITS[k][1]}) for k in _LINE_VARS}
    data["line_model"] = (("line",), np.asarray(first["line_model"]).astype(str),
                          {"units": "", "long_name": "line model of the run"})
    data["offset_max"] = (("seed",), np.array([s["offset_max"] for s in per_seed]),
                          {"units": "m", "long_name": "largest horizontal offset"})
    if "offset_limit" in first:
        coords["offset_limit"] = first["offset_limit"]
        data["offset_ratio_max"] = (("seed", "offset_limit"),
                                    np.array([s["offset_ratio_max"] for s in per_seed]),
                                    {"units": "1", "long_name": "largest ratio of the offset "
                                     "to the limit in its direction"})
    if "point" in first:
        coords["point"] = first["point"]
        for k, ln in (("point_horizontal_max", "largest horizontal excursion"),
                      ("point_up_max", "largest upward excursion"),
                      ("point_down_max", "largest downward excursion")):
            data[k] = (("seed", "point"), np.array([s[k] for s in per_seed]),
                       {"units": "m", "long_name": f"{ln} of the point from its position at "
                        "zero pose"})
    out = xr.Dataset(data, coords=coords)
    out.attrs["candidate_states"] = int(np.sum([s["n_evaluated"] for s in per_seed]))
    return out


def characteristic(x, p: float = 0.9, *, at_least_max: bool = False) -> float:
    """The characteristic value of per-seed maxima ``x``: the Gumbel ``p`` fractile (MLE)
    when at least 3 finite values differ, else the largest; with ``at_least_max`` never below
    the largest value seen.  NaN when no value is finite."""
    x = np.asarray(x, float)
    x = x[np.isfinite(x)]
    if x.size == 0:
        return float("nan")
    if x.size < 3 or np.ptp(x) <= 1e-12 * max(1.0, float(np.max(np.abs(x)))):
        return float(np.max(x))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        try:
            v = float(gumbel_fit(x).fractile(p))
        except Exception:  # noqa: BLE001 - a fit that fails falls back to the largest seen
            v = float(np.max(x))
    return max(v, float(np.max(x))) if at_least_max else v


def characteristic_min(x, p: float = 0.9) -> float:
    """The characteristic minimum of per-seed minima: the smaller of the Gumbel fractile of the
    minima (``-characteristic(-x)``) and the smallest value seen."""
    x = np.asarray(x, float)
    if not np.isfinite(x).any():
        return float("nan")
    return min(-characteristic(-x, p), float(np.nanmin(x)))


def anchor_checks(stats: xr.Dataset, design, code, *, limit_state: str, consequence_class: int,
                  analysis, p: float = 0.9, capacities_given=True) -> xr.Dataset:
    """Anchor load and uplift checks of every line (see the module docstring).

    ``analysis``: one analysis type or one per line (as the line check); ``design``: the
    :class:`~floatmoor.io.mooring_design.MooringDesign` (None: no anchor keys)."""
    lines = [str(v) for v in stats["line"].values]
    nl = len(lines)
    an = [analysis] * nl if isinstance(analysis, str) else list(analysis)
    cols = {k: np.full(nl, np.nan) for k in (
        "t_c_mean", "t_c", "gamma_mean", "gamma_dyn", "design_load", "capacity",
        "resistance_factor", "utilisation", "h_c", "v_c", "uplift_c", "uplift_limit",
        "grounded_length_min", "grounded_length_at_max_offset")}
    atype = np.full(nl, "", dtype=object)
    type_given = np.zeros(nl, bool)
    checked = np.zeros(nl, bool)
    load_ok = np.ones(nl, bool)
    load_checked = np.zeros(nl, bool)
    uplift_ok = np.ones(nl, bool)
    for j, ln in enumerate(lines):
        tmax = stats["anchor_tension_max"].values[:, j]
        if not np.isfinite(tmax).any():
            continue                                   # failed line
        checked[j] = True
        spec = design.anchor(ln) if design is not None else None
        t = spec.type if spec is not None and spec.type else None
        type_given[j] = t is not None
        t = t or "drag"
        atype[j] = t
        tm = float(np.nanmean(stats["anchor_tension_mean"].values[:, j]))
        tc = max(characteristic(tmax, p), tm)
        f = code.anchor_factors(t, limit_state, consequence_class, an[j])
        cols["t_c_mean"][j], cols["t_c"][j] = tm, tc
        cols["gamma_mean"][j], cols["gamma_dyn"][j] = f["gamma_mean"], f["gamma_dyn"]
        cols["design_load"][j] = f["gamma_mean"] * tm + f["gamma_dyn"] * (tc - tm)
        cols["resistance_factor"][j] = f["resistance_factor"]
        if spec is not None and spec.capacity is not None:
            cols["capacity"][j] = spec.capacity
            cols["utilisation"][j] = (cols["design_load"][j] * f["resistance_factor"]
                                      / spec.capacity)
            load_checked[j] = True
            load_ok[j] = cols["utilisation"][j] <= 1.0
        cols["h_c"][j] = characteristic(stats["anchor_h_max"].values[:, j], p)
        cols["v_c"][j] = characteristic(stats["anchor_v_max"].values[:, j], p,
                                        at_least_max=True)
        cols["uplift_c"][j] = characteristic(stats["uplift_deg_max"].values[:, j], p,
                                             at_least_max=True)
        lim = (spec.uplift_deg if spec is not None and spec.uplift_deg is not None
               else code.uplift_limit_deg(t, limit_state))
        cols["uplift_limit"][j] = np.nan if lim is None else lim
        uplift_ok[j] = lim is None or cols["uplift_c"][j] <= lim + 1e-9
        g = stats["grounded_length_min"].values[:, j]
        cols["grounded_length_min"][j] = float(np.nanmin(g)) if np.isfinite(g).any() else np.nan
        g = stats["grounded_length_at_max_offset"].values[:, j]
        cols["grounded_length_at_max_offset"][j] = (float(np.nanmin(g)) if np.isfinite(g).any()
                                                    else np.nan)
    units = {"t_c_mean": ("N", "characteristic mean anchor tension (mean over the seeds)"),
             "t_c": ("N", f"characteristic anchor tension (Gumbel {p:g} fractile of the seed "
                     "maxima)"),
             "gamma_mean": ("1", "partial safety factor on the mean anchor tension"),
             "gamma_dyn": ("1", "partial safety factor on the dynamic anchor tension"),
             "design_load": ("N", "anchor design load gamma_mean T_C-mean + gamma_dyn "
                             "T_C-dyn"),
             "capacity": ("N", "characteristic anchor holding capacity (mooring file)"),
             "resistance_factor": ("1", "material factor (or factor of safety) on the "
                                   "holding capacity"),
             "utilisation": ("1", "design load x resistance factor / capacity"),
             "h_c": ("N", "characteristic horizontal anchor force"),
             "v_c": ("N", "characteristic vertical (upward) anchor force"),
             "uplift_c": ("deg", "characteristic uplift angle at the anchor"),
             "uplift_limit": ("deg", "largest uplift angle allowed (NaN: no limit for the "
                              "anchor type)"),
             "grounded_length_min": ("m", "smallest grounded length over the seeds"),
             "grounded_length_at_max_offset": ("m", "smallest over the seeds of the grounded "
                                               "length at the largest offset")}
    ds = xr.Dataset(coords={"line": lines})
    for k, (u, ln) in units.items():
        ds[k] = ("line", cols[k], {"units": u, "long_name": ln})
    ds["anchor_type"] = ("line", atype.astype(str), {"units": "", "long_name": "anchor type "
                         "(drag when the mooring file gives none)"})
    ds["anchor_type_given"] = ("line", type_given, {"units": "1", "long_name": "anchor type "
                               "given in the mooring file"})
    ds["checked"] = ("line", checked, {"units": "1", "long_name": "anchor checked (false: "
                     "failed line)"})
    ds["load_checked"] = ("line", load_checked, {"units": "1", "long_name": "anchor load "
                          "checked (a capacity given)"})
    ds["load_passed"] = ("line", load_ok & checked, {"units": "1", "long_name": "anchor load "
                         "check passed (true where not checked)"})
    ds["uplift_passed"] = ("line", uplift_ok | ~checked, {"units": "1", "long_name": "uplift "
                           "check passed"})
    ds.attrs.update({"limit_state": limit_state, "code": code.key, "fractile": float(p)})
    return ds


def offset_checks(stats: xr.Dataset, limits, *, limit_state: str, p: float = 0.9) -> dict:
    """Offset limits and named points: ``{"offsets": Dataset(offset_limit), "points":
    Dataset(point)}`` (either None when the scene has none)."""
    out = {"offsets": None, "points": None,
           "offset_c": characteristic(stats["offset_max"].values, p)}
    if limits is None:
        return out
    if limits.offset and "offset_ratio_max" in stats:
        names = [str(v) for v in stats["offset_limit"].values]
        ratio = np.array([characteristic(stats["offset_ratio_max"].values[:, k], p)
                          for k in range(len(names))])
        applies = np.array([limit_state in o.limit_states for o in limits.offset])
        ds = xr.Dataset(coords={"offset_limit": names})
        ds["ratio_c"] = ("offset_limit", ratio, {"units": "1", "long_name": "characteristic "
                         "ratio of the offset to the limit (Gumbel fractile of the seed "
                         "maxima)"})
        ds["ratio_max_seen"] = ("offset_limit",
                                np.nanmax(stats["offset_ratio_max"].values, axis=0),
                                {"units": "1", "long_name": "largest ratio seen"})
        ds["limit"] = ("offset_limit", np.array([o.describe() for o in limits.offset]),
                       {"units": "", "long_name": "the limit"})
        ds["applies"] = ("offset_limit", applies, {"units": "1", "long_name": "the limit "
                         f"applies in the {limit_state}"})
        ds["passed"] = ("offset_limit", ~applies | (ratio <= 1.0),
                        {"units": "1", "long_name": "offset within the limit"})
        ds.attrs["offset_c"] = characteristic(stats["offset_max"].values, p)
        out["offsets"] = ds
    if limits.points and "point_horizontal_max" in stats:
        names = [str(v) for v in stats["point"].values]
        hz = np.array([characteristic(stats["point_horizontal_max"].values[:, k], p)
                       for k in range(len(names))])
        up = np.array([characteristic(stats["point_up_max"].values[:, k], p)
                       for k in range(len(names))])
        down = np.array([characteristic(stats["point_down_max"].values[:, k], p)
                         for k in range(len(names))])
        vert = np.maximum(up, down)
        mh = np.array([np.nan if q.max_horizontal is None else q.max_horizontal
                       for q in limits.points])
        mv = np.array([np.nan if q.max_vertical is None else q.max_vertical
                       for q in limits.points])
        applies = np.array([limit_state in q.limit_states for q in limits.points])
        ok = ~applies | ((~np.isfinite(mh) | (hz <= mh)) & (~np.isfinite(mv) | (vert <= mv)))
        with np.errstate(invalid="ignore"):
            ratio = np.fmax(hz / mh, vert / mv)
        ds = xr.Dataset(coords={"point": names})
        for k, v, ln in (("horizontal_c", hz, "characteristic horizontal excursion"),
                         ("up_c", up, "characteristic upward excursion"),
                         ("down_c", down, "characteristic downward excursion"),
                         ("max_horizontal", mh, "horizontal limit (NaN: none)"),
                         ("max_vertical", mv, "vertical limit (NaN: none)"),
                         ("ratio_c", ratio, "largest ratio of an excursion to its limit")):
            ds[k] = ("point", v, {"units": "m" if k != "ratio_c" else "1", "long_name": ln})
        ds["has_limit"] = ("point", np.isfinite(mh) | np.isfinite(mv),
                           {"units": "1", "long_name": "the point has a limit"})
        ds["applies"] = ("point", applies, {"units": "1", "long_name": "the limits apply in "
                         f"the {limit_state}"})
        ds["passed"] = ("point", ok, {"units": "1", "long_name": "within the limits"})
        out["points"] = ds
    return out


def fibre_checks(stats: xr.Dataset, mooring, code, line_checks, *, limit_state: str,
                 p: float = 0.9) -> xr.Dataset | None:
    """Fibre-rope checks of every line with a fibre segment (None when no line has one).

    ``line_checks``: the ULS/ALS line check Dataset of the same limit state (its design tension
    per line; NaN: the rope's strength is not checked here)."""
    from .capacity import is_fibre
    rows = []
    for j, line in enumerate(mooring.lines):
        ks = [k for k, s in enumerate(line.segments) if is_fibre(mooring, s)]
        if ks:
            rows.append((j, line, ks))
    if not rows:
        return None
    names = [ln.name for _, ln, _ in rows]
    n = len(rows)
    cols = {k: np.full(n, np.nan) for k in ("t_min_c", "t_min_required", "seabed_length_c",
                                             "rope_mbs", "rope_s_c", "design_tension",
                                             "utilisation")}
    rope_type = np.full(n, "", dtype=object)
    checked = np.zeros(n, bool)
    dt = line_checks["design_tension"].values
    lc_names = [str(v) for v in line_checks["line"].values]
    for r, (j, line, ks) in enumerate(rows):
        tmin = stats["rope_tension_min"].values[:, j]
        if not np.isfinite(tmin).any():
            continue                                   # failed line
        checked[r] = True
        mbs = min(line.segments[k].mbs for k in ks)
        rope_type[r] = ", ".join(dict.fromkeys(line.segments[k].line_type for k in ks))
        cols["rope_mbs"][r] = mbs
        cols["rope_s_c"][r] = code.strength_factor * mbs
        cols["t_min_c"][r] = characteristic_min(tmin, p)
        cols["t_min_required"][r] = code.fibre_min_tension_fraction * mbs
        cols["seabed_length_c"][r] = characteristic(stats["rope_seabed_length_max"].values[:, j],
                                                    p, at_least_max=True)
        if line.name in lc_names:
            d = float(dt[lc_names.index(line.name)])
            cols["design_tension"][r] = d
            cols["utilisation"][r] = d / cols["rope_s_c"][r]
    slack_ok = ~checked | (cols["t_min_c"] > cols["t_min_required"])
    bed_ok = ~checked | code.fibre_seabed_contact_allowed | (cols["seabed_length_c"] <= 0.0)
    strength_ok = ~checked | ~np.isfinite(cols["utilisation"]) | (cols["utilisation"] <= 1.0)
    units = {"t_min_c": ("N", "characteristic minimum tension of the rope"),
             "t_min_required": ("N", "minimum tension required (code fraction of the rope "
                                "MBS; 0: no slack)"),
             "seabed_length_c": ("m", "characteristic length of rope on the seabed"),
             "rope_mbs": ("N", "MBS of the rope (its own, no corrosion)"),
             "rope_s_c": ("N", "characteristic strength of the rope"),
             "design_tension": ("N", "design tension of the line (at the fairlead: an upper "
                                "bound of the rope's)"),
             "utilisation": ("1", "design tension / rope characteristic strength")}
    ds = xr.Dataset(coords={"line": names})
    for k, (u, ln) in units.items():
        ds[k] = ("line", cols[k], {"units": u, "long_name": ln})
    ds["rope_type"] = ("line", rope_type.astype(str), {"units": "", "long_name": "rope line "
                       "type(s)"})
    ds["checked"] = ("line", checked, {"units": "1", "long_name": "checked (false: failed "
                     "line)"})
    ds["slack_passed"] = ("line", slack_ok, {"units": "1", "long_name": "no slack"})
    ds["seabed_passed"] = ("line", bed_ok, {"units": "1", "long_name": "no rope on the "
                           "seabed"})
    ds["strength_passed"] = ("line", strength_ok, {"units": "1", "long_name": "rope strength"})
    ds.attrs.update({"limit_state": limit_state, "code": code.key,
                     "seabed_contact": "allowed" if code.fibre_seabed_contact_allowed
                     else "forbidden"})
    return ds

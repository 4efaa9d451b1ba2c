"""End-of-life (corroded) capacity of every segment of every line.

Chain (and steel wire rope where the mooring file gives a rate for it) loses diameter to
corrosion and wear: the design code's allowance (mm of diameter per year, by zone: splash,
catenary, bottom; DNV-OS-E301 (2008) table B1 in :mod:`floatmoor.post.design_codes`, or the
mooring file's ``design: corrosion``) over the design life.  At the end of the life the diameter
is ``d_EOL = d - rate x life`` (the full allowance; the fatigue check uses half of it, the mean
over the life) and the MBS is scaled by the steel area, ``MBS_EOL = MBS (d_EOL / d)^2``.  For
chain this is conservative: the MBS formula of DNV-OS-E302, ``c d^2 (44 - 0.08 d)``, falls more
slowly than ``d^2``.  Fibre rope takes no allowance.

Zones of a segment (at zero pose, the still-water position of a symmetric mooring): ``bottom``
when part of it lies on the seabed, ``catenary`` when part of it is suspended, ``splash`` when
part of it is above ``-splash_zone_depth`` (mooring file ``design: splash_zone_depth``) or, when
no depth is given, when it is the segment at the fairlead (conservative); a ``corrosion_zone``
given for the segment replaces them.  A segment spanning several zones takes the largest rate.

The ULS/ALS check of a line uses the smallest end-of-life characteristic strength over its
segments against the tension at the fairlead (an upper bound of the tension along a
quasi-static line: the tension falls with the weight of the line above).
"""

from __future__ import annotations

import numpy as np
import xarray as xr

from ..core.errors import SceneError
from .design_codes import DEFAULT_CODE, load_code

__all__ = ["FIBRE_MATERIALS", "segment_capacities"]

FIBRE_MATERIALS = ("polyester", "nylon", "hmpe", "aramid", "fibre")
"""Line-type materials that are fibre ropes (no corrosion; the fibre-rope checks apply)."""

_DEFAULT_LIFE = 20.0


def _material(mooring, seg) -> str:
    lt = mooring.line_types.get(seg.line_type)
    if lt is not None:
        return str(lt.material)
    return "fibre" if seg.fibre is not None else "user"


def is_fibre(mooring, seg) -> bool:
    """Whether a segment is fibre rope (its material, or a fibre stiffness model)."""
    return seg.fibre is not None or _material(mooring, seg) in FIBRE_MATERIALS


def segment_capacities(mooring, design=None, code=None, *, pose=None) -> xr.Dataset:
    """New and end-of-life MBS and characteristic strength of every segment.

    Parameters
    ----------
    mooring : MooringSystem
    design : MooringDesign, optional
        The design keys of the mooring file (:func:`floatmoor.io.mooring_design.
        parse_mooring_design`): design life, corrosion rates, splash-zone depth, explicit zones.
    code : design code (key, file or DesignCode), default DNV-OS-E301 (2008)
    pose : the pose of the zone geometry (default zero)

    Returns
    -------
    xarray.Dataset
        Over ``(line, segment)`` (segments from the anchor; NaN / "" beyond a line's last):
        ``line_type``, ``material``, ``zones``, ``rate`` (mm/year), ``diameter`` and
        ``diameter_eol`` (m), ``mbs`` and ``mbs_eol`` (N), ``s_c`` and ``s_c_eol`` (N, times the
        code's strength factor); per line ``mbs_eol_line`` (the smallest end-of-life MBS),
        ``governing_segment`` (its index) and ``mbs_new_line``; attributes ``design_life``,
        ``design_life_source``, ``corrosion_source``, ``end_of_life``.
    """
    c = load_code(DEFAULT_CODE if code is None else code)
    life = _DEFAULT_LIFE if design is None or design.design_life is None else design.design_life
    life_src = ("mooring file (design: design_life)" if design is not None
                and design.design_life is not None else
                f"default {_DEFAULT_LIFE:g} years (the mooring file gives no design: "
                "design_life)")
    chain_rates = (design.corrosion if design is not None and design.corrosion is not None
                   else c.corrosion_rates("chain"))
    chain_src = ("mooring file (design: corrosion)" if design is not None
                 and design.corrosion is not None else f"{c.name}, corrosion")
    wire_rates = (design.corrosion_wire if design is not None
                  and design.corrosion_wire is not None else {})
    pose = np.zeros(6) if pose is None else np.asarray(pose, float)
    t = mooring.tensions(pose)
    grounded = t["grounded_length"].values
    n, nseg = mooring.n_lines, max(len(ln.segments) for ln in mooring.lines)
    shape = (n, nseg)
    out = {k: np.full(shape, np.nan) for k in ("rate", "diameter", "diameter_eol", "mbs",
                                               "mbs_eol")}
    text = {k: np.full(shape, "", dtype=object) for k in ("line_type", "material", "zones")}
    splash_depth = None if design is None else design.splash_zone_depth
    for i, line in enumerate(mooring.lines):
        segs = line.segments
        cum = np.concatenate([[0.0], np.cumsum([s.length for s in segs])])
        lb = float(grounded[i]) if np.isfinite(grounded[i]) else 0.0
        prof = None
        if splash_depth is not None:
            prof = mooring.line_profile(line.name, pose, n_per_segment=21)
        for k, seg in enumerate(segs):
            mat = _material(mooring, seg)
            text["line_type"][i, k] = seg.line_type
            text["material"][i, k] = mat
            zones = []
            explicit = None if design is None else design.segment_zones.get((line.name, k))
            if explicit is not None:
                zones = [explicit]
            else:
                if prof is not None:
                    sel = (prof["s"] >= cum[k] - 1e-9) & (prof["s"] <= cum[k + 1] + 1e-9)
                    if np.any(prof["z"][sel] >= -splash_depth):
                        zones.append("splash")
                elif k == len(segs) - 1:
                    zones.append("splash")
                if lb > cum[k] + 1e-9:
                    zones.append("bottom")
                if lb < cum[k + 1] - 1e-9:
                    zones.append("catenary")
            text["zones"][i, k] = "+".join(dict.fromkeys(zones))
            if is_fibre(mooring, seg):
                rates = {}
            elif mat == "chain":
                rates = chain_rates
            elif mat == "wire":
                rates = wire_rates
            else:
                rates = {}
            rate = max((rates.get(z, 0.0) for z in zones), default=0.0)
            d = float(seg.diameter)
            d_eol = d - rate * 1e-3 * life
            if rate > 0 and not d_eol > 0:
                raise SceneError(getattr(design, "file", None) or mooring.source,
                                 f"lines.{line.name}.segments[{k}]",
                                 "a corrosion allowance smaller than the diameter",
                                 f"{rate:g} mm/year over {life:g} years on a diameter of "
                                 f"{d * 1e3:g} mm")
            out["rate"][i, k] = rate
            out["diameter"][i, k] = d
            out["diameter_eol"][i, k] = d_eol if rate > 0 else d
            out["mbs"][i, k] = seg.mbs
            out["mbs_eol"][i, k] = seg.mbs * (d_eol / d) ** 2 if rate > 0 and d > 0 else seg.mbs
    sf = c.strength_factor
    lines = list(mooring.names)
    seg_idx = np.arange(nseg)
    ds = xr.Dataset(coords={"line": lines, "segment": seg_idx})
    units = {"rate": ("mm/year", "corrosion and wear allowance rate (largest of the zones)"),
             "diameter": ("m", "nominal diameter, new"),
             "diameter_eol": ("m", "diameter at the end of the design life"),
             "mbs": ("N", "minimum breaking strength, new"),
             "mbs_eol": ("N", "minimum breaking strength at the end of the design life "
                         "(MBS (d_EOL / d)^2)")}
    for k, (u, ln) in units.items():
        ds[k] = (("line", "segment"), out[k], {"units": u, "long_name": ln})
    for k, ln in (("line_type", "line type"), ("material", "material"),
                  ("zones", "corrosion zones of the segment (splash, catenary, bottom)")):
        ds[k] = (("line", "segment"), text[k].astype(str), {"units": "", "long_name": ln})
    ds["s_c"] = ds["mbs"] * sf
    ds["s_c"].attrs = {"units": "N", "long_name": f"characteristic strength {sf:g} MBS, new"}
    ds["s_c_eol"] = ds["mbs_eol"] * sf
    ds["s_c_eol"].attrs = {"units": "N", "long_name": f"characteristic strength {sf:g} MBS, "
                           "end of life"}
    eol = np.where(np.isfinite(out["mbs_eol"]), out["mbs_eol"], np.inf)
    gov = np.argmin(eol, axis=1)
    ds["mbs_eol_line"] = ("line", eol[np.arange(n), gov],
                          {"units": "N", "long_name": "smallest end-of-life MBS of the line"})
    ds["mbs_new_line"] = ("line", np.nanmin(np.where(np.isfinite(out["mbs"]), out["mbs"],
                                                     np.nan), axis=1),
                          {"units": "N", "long_name": "smallest MBS of the new line"})
    ds["governing_segment"] = ("line", gov, {"units": "1", "long_name": "segment (from the "
                                             "anchor) with the smallest end-of-life MBS"})
    ds.attrs.update({"design_life": float(life), "design_life_source": life_src,
                     "corrosion_source": chain_src,
                     "corrosion_rates_chain": ", ".join(f"{z} {r:g}" for z, r in
                                                        chain_rates.items()) + " mm/year",
                     "corrosion_rates_wire": (", ".join(f"{z} {r:g}" for z, r in
                                                        wire_rates.items()) + " mm/year")
                     if wire_rates else "none",
                     "splash_zone": (f"above {-splash_depth:g} m" if splash_depth is not None
                                     else "the segment at the fairlead"),
                     "end_of_life": int(c.end_of_life_capacity), "code": c.key})
    return ds

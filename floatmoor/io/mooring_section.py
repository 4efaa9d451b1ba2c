"""The ``mooring:`` section of a scene (inline, or a mooring file) -> :class:`MooringSystem`.

Format (SI units, angles only in keys ending ``_deg``)::

    line_type_library: my_types.yaml     # optional extra library (relative to this file)
    line_types:                          # optional inline types, same format as the library
      my_chain: {material: chain, diameter: 0.084, mass_per_length: 140.4, density: 7850,
                 elastic_modulus: 6.004e10, mbs: 8.5e6}
    seabed_friction: 0.0                 # default axial seabed friction coefficient (-)
    defaults:                            # optional: used by every line that omits the key
      segments: [...]
    lines:
      - name: line1
        anchor: {radius: 853.87, azimuth_deg: 0.0}      # or {x: .., y: .., z: ..}; z defaults
                                                         # to -water_depth (on the seabed)
        fairlead: {radius: 5.2, azimuth_deg: 0.0, z: -70.0}   # body axes; or [x, y, z]
        segments:                                        # from the anchor to the fairlead
          - {type: chain_studless_R4, diameter: 0.084, length: 1200.0}
          - {type: my_poly, length: 1200.0, clump_weight: 5.0e4}   # N at its upper end
          - {type: my_chain, length: 250.0}
        seabed_friction: 0.5                             # optional, per line
    failed_lines: [line4]                                # optional, lines removed (ALS)
    model: quasi-static                  # optional: or finite-element (all lines); per line
                                         # lines[i].model overrides it
    finite_element: {element_length: 20.0}   # optional FE options (floatmoor.mooring.fe.options)
    fibre_time_constant: 300.0           # s, optional: quasi-static lines' fibre segments are
                                         # linearised about their tension low-pass filtered
                                         # with this time constant (.inf: the static mean;
                                         # floatmoor.mooring.fibre_system)
    design: {design_life: 20.0}          # optional design keys (anchor type and capacity per
                                         # line, corrosion allowance and zones): they change no
                                         # analysis; floatmoor.io.mooring_design

``clump_weight`` (submerged, N) and ``buoy_net_buoyancy`` (N) act at the upper end of the
segment that names them (the joint towards the fairlead).  Every mistake is a
:class:`~floatmoor.core.errors.SceneError` naming the file and key.  After building, the system
is solved once at zero pose: a line above its MBS there is a :class:`FloatmoorWarning` (tension
against MBS); a buoyant part that would lie on the seabed is a SceneError.  The line models and
FE options are read by :func:`floatmoor.mooring.fe.options.parse_line_models` and kept as the
attribute ``line_models`` (:class:`~floatmoor.mooring.fe.options.LineModels`) of the system.
"""

from __future__ import annotations

import math

import numpy as np

from ..core.config import Node
from ..core.constants import GRAVITY, RHO_WATER
from ..core.errors import ConvergenceError, SceneError
from ..mooring.fe.options import parse_line_models
from ..mooring.fibre_system import DEFAULT_TIME_CONSTANT
from ..mooring.line_types import MAX_DIAMETER, LineTypeLibrary, default_library
from ..mooring.system import LineDef, MooringSystem, Segment
from .mooring_design import LINE_DESIGN_KEYS, SEGMENT_DESIGN_KEYS, parse_mooring_design

__all__ = ["parse_mooring"]

_TOP_KEYS = {"line_type_library", "line_types", "seabed_friction", "defaults", "lines",
             "failed_lines", "description", "model", "finite_element",
             "fibre_time_constant", "design"}
_LINE_KEYS = {"name", "anchor", "fairlead", "segments", "seabed_friction", "model"} \
    | LINE_DESIGN_KEYS
_SEG_KEYS = {"type", "diameter", "length", "clump_weight", "buoy_net_buoyancy"} \
    | SEGMENT_DESIGN_KEYS


MAX_LENGTH_RATIO = 5.0
"""Longest line accepted, as a multiple of its anchor-fairlead distance at zero pose (catenary
moorings use 1.0-1.5; the rest of a longer line would only lie on the seabed)."""


def _point(node: Node, key: str, *, default_z=None, what: str):
    """A point given as [x, y, z], {x, y, z} or {radius, azimuth_deg, z}."""
    raw = node.raw(key, expected=f"the {what} as [x, y, z] or {{radius, azimuth_deg, z}}")
    if isinstance(raw, list):
        return tuple(node.array(key, shape=(3,), unit="m"))
    p = node.child(key)
    extra = {"above_seabed"} if key == "anchor" else set()
    if "radius" in p:
        p.reject_unknown({"radius", "azimuth_deg", "z"} | extra)
        r = p.float("radius", ge=0.0, unit="m")
        a = p.angle_deg("azimuth_deg")
        z = p.float("z", default_z, unit="m") if default_z is not None else p.float("z", unit="m")
        return (r * math.cos(a), r * math.sin(a), z)
    p.reject_unknown({"x", "y", "z"} | extra)
    x = p.float("x", unit="m")
    y = p.float("y", unit="m")
    z = p.float("z", default_z, unit="m") if default_z is not None else p.float("z", unit="m")
    return (x, y, z)


def parse_mooring(node: Node, *, water_depth: float, water_density: float = RHO_WATER,
                  gravity: float = GRAVITY, library: LineTypeLibrary | None = None,
                  check: bool = True) -> MooringSystem:
    """Build a :class:`MooringSystem` from a ``mooring:`` mapping.

    Parameters
    ----------
    node : floatmoor.core.config.Node
        The mapping (the top of a mooring file read with ``Node.load``, or the inline section).
    water_depth : float
        Water depth, m; anchors default to ``z = -water_depth``.
    water_density, gravity : float
        For the submerged weights, kg/m^3 and m/s^2.
    library : LineTypeLibrary, optional
        Base library (default: the one shipped in ``floatmoor/data/line_types.yaml``).
    check : bool
        Solve once at zero pose: warn for tension above MBS, SceneError for a buoyant part on
        the seabed.

    Returns
    -------
    MooringSystem
    """
    node.reject_unknown(_TOP_KEYS)
    line_models = parse_line_models(node)
    lib = library if library is not None else default_library()
    if "line_type_library" in node:
        path = node.path_value("line_type_library")
        lib = lib.extended_from_file(path)
    if "line_types" in node:
        lib = lib.extended(node.child("line_types"))
    cb_default = node.float("seabed_friction", 0.0, ge=0.0)
    defaults = node.child("defaults", None)
    if defaults is not None:
        defaults.reject_unknown({"segments", "seabed_friction", "fairlead", "anchor"}
                                | LINE_DESIGN_KEYS)
    lines_nodes = node.item_nodes("lines", min_len=1)
    lines = []
    names = []
    used_types = {}
    for ln in lines_nodes:
        ln.reject_unknown(_LINE_KEYS)
        name = ln.str("name")
        if name in names:
            raise ln.error("name", "a unique line name", name)
        names.append(name)
        src = ln if "anchor" in ln or defaults is None or "anchor" not in defaults else defaults
        anchor = _point(src, "anchor", default_z=-water_depth, what="anchor position (earth)")
        src = ln if "fairlead" in ln or defaults is None or "fairlead" not in defaults else defaults
        fairlead = _point(src, "fairlead", what="fairlead position (body axes)")
        if anchor[2] < -water_depth - 1e-6 * water_depth:
            raise ln.child("anchor").error("z", f"an anchor at or above the seabed "
                                                f"(z >= {-water_depth:g} m)", anchor[2]) \
                if isinstance(ln.raw("anchor", None), dict) else \
                ln.error("anchor", f"an anchor at or above the seabed (z >= {-water_depth:g} m)",
                         list(anchor))
        if anchor[2] >= fairlead[2]:
            seabed = abs(anchor[2] + water_depth) <= 1e-6 * max(water_depth, 1.0)
            raise ln.error("anchor", f"an anchor below its fairlead (fairlead z = "
                                     f"{fairlead[2]:g} m)", list(anchor),
                           f"line {name!r}: the anchor must be lower than the fairlead"
                           + (f"; it lies on the seabed, at the water depth {water_depth:g} m "
                              "of the scene's site.water_depth: is the depth above the "
                              "fairleads?" if seabed else ""))
        on_seabed = abs(anchor[2] + water_depth) <= 1e-6 * max(water_depth, 1.0)
        if not on_seabed:
            a_src = src_anchor = (ln if "anchor" in ln or defaults is None
                                  or "anchor" not in defaults else defaults)
            a_raw = src_anchor.raw("anchor", None)
            declared = isinstance(a_raw, dict) and a_raw.get("above_seabed") is True
            if not declared:
                where = a_src.child("anchor") if isinstance(a_raw, dict) else a_src
                raise where.error("z" if isinstance(a_raw, dict) else "anchor",
                                  f"an anchor on the seabed (z = {-water_depth:g} m; an anchor "
                                  "above it must be declared with above_seabed: true)",
                                  anchor[2] if isinstance(a_raw, dict) else list(anchor),
                                  f"line {name!r}: the anchor is "
                                  f"{anchor[2] + water_depth:.4g} m above the seabed")
        src = ln if "segments" in ln or defaults is None else defaults
        seg_nodes = src.item_nodes("segments", min_len=1)
        segs = []
        for k, sn in enumerate(seg_nodes):
            sn.reject_unknown(_SEG_KEYS)
            tname = sn.str("type")
            d = sn.float("diameter", None, gt=0.0, le=MAX_DIAMETER, unit="m")
            lt, w_override = lib.get(tname, diameter=d, node=sn, key="type",
                                     water_density=water_density, gravity=gravity)
            used_types.setdefault(lt.name, lt)
            length = sn.float("length", gt=0.0, unit="m")
            w = w_override if w_override is not None else lt.submerged_weight(water_density, gravity)
            clump = sn.float("clump_weight", 0.0, ge=0.0, unit="N")
            buoy = sn.float("buoy_net_buoyancy", 0.0, ge=0.0, unit="N")
            if (clump or buoy) and k == len(seg_nodes) - 1:
                raise sn.error("clump_weight" if clump else "buoy_net_buoyancy",
                               "a point load on a segment below the fairlead segment (it acts "
                               "at the segment's upper joint)", clump or buoy)
            segs.append(Segment(length=length, ea=lt.ea, w=w, mbs=lt.mbs, line_type=lt.name,
                                point_load=clump - buoy, ea_dynamic=lt.ea_dynamic,
                                mass_per_length=lt.mass_per_length, diameter=lt.diameter,
                                fibre=lt.fibre))
        total = sum(sg.length for sg in segs)
        dist = math.dist(anchor, fairlead)
        if total > MAX_LENGTH_RATIO * dist:
            raise seg_nodes[-1].error("length", f"a line at most {MAX_LENGTH_RATIO:g} x its "
                                      f"anchor-fairlead distance ({dist:.6g} m) long",
                                      segs[-1].length, f"line {name!r}: unstretched length "
                                      f"{total:.6g} m in total; a length in mm typed for m?")
        cb = ln.float("seabed_friction", defaults.float("seabed_friction", cb_default, ge=0.0)
                      if defaults is not None else cb_default, ge=0.0)
        lines.append(LineDef(name=name, anchor=anchor, fairlead=fairlead, segments=tuple(segs),
                             cb=cb, anchor_on_seabed=on_seabed))
    _check_segment_elements(node, line_models, lines)
    failed = node.list("failed_lines", [])
    for i, f in enumerate(failed):
        if f not in names:
            raise SceneError(node.file, f"{node.key('failed_lines')}[{i}]",
                             "a line name, one of: " + ", ".join(names), f)
    if failed and len(set(failed)) >= len(names):
        raise node.error("failed_lines", "some lines left intact (every line is listed as "
                         "failed: nothing would hold the floater)", failed)
    parse_mooring_design(node)   # the design keys (anchors, corrosion): refused if mistyped
    ms = MooringSystem(lines, water_depth=water_depth, water_density=water_density,
                       gravity=gravity, source=str(node.file) if node.file else "mooring (given in Python)",
                       failed=failed, line_models=line_models, line_types=used_types,
                       fibre_time_constant=_fibre_time_constant(node))
    if check:
        _check_at_zero_pose(ms, node, lines_nodes)
    return ms


def _check_segment_elements(node: Node, line_models, lines) -> None:
    """The FE lines' element counts, checked before any array is allocated (SceneError naming
    the file, the key and the first line concerned): ``finite_element.n_elements`` given per
    segment needs every FE line to have that many segments, and no FE line may have more than
    :data:`~floatmoor.mooring.fe.from_system.MAX_ELEMENTS` elements (``n_elements``, its
    list's sum, or ``element_length``'s count)."""
    from ..mooring.fe.from_system import MAX_ELEMENTS, element_counts
    opts = line_models.options
    per_line = opts.n_elements is None or isinstance(opts.n_elements, int)
    key = "element_length" if opts.n_elements is None else "n_elements"
    found = (opts.element_length if opts.n_elements is None
             else opts.n_elements if per_line else list(opts.n_elements))
    for ld in lines:
        if line_models.model_of(ld.name) != "finite-element":
            continue
        try:
            n = sum(element_counts([sg.length for sg in ld.segments],
                                   element_length=opts.element_length,
                                   n_elements=opts.n_elements))
        except ValueError:
            raise node.child("finite_element").error(
                "n_elements", f"one element count per segment of every FE line, anchor to "
                f"fairlead (line {ld.name!r} has {len(ld.segments)} segments)", found,
                "a list of counts applies to every FE line; give one integer per line "
                "(shared among its segments by length) when the lines differ") from None
        if n > MAX_ELEMENTS and "finite_element" in node:
            raise node.child("finite_element").error(
                key, f"at most {MAX_ELEMENTS:,} elements per line (a line of "
                f"{sum(sg.length for sg in ld.segments):g} m)", found,
                f"{n:,} elements for line {ld.name!r}")


def _fibre_time_constant(node: Node) -> float:
    """``fibre_time_constant`` (s, > 0; ``.inf``: the fixed-mean rule)."""
    raw = node.raw("fibre_time_constant", DEFAULT_TIME_CONSTANT)
    if isinstance(raw, float) and math.isinf(raw) and raw > 0.0:
        return math.inf
    return node.float("fibre_time_constant", DEFAULT_TIME_CONSTANT, gt=0.0, unit="s")


def _check_at_zero_pose(ms: MooringSystem, node: Node, line_nodes):
    for i, line in enumerate(ms.lines):
        single = MooringSystem([line], water_depth=ms.water_depth)
        try:
            t = single.tensions(np.zeros(6))
        except ConvergenceError as exc:
            raise line_nodes[i].error("segments", "a line that can be solved at the zero pose",
                                      f"line {line.name!r}: {exc}") from None
        tf = float(t["fairlead_tension"][0])
        if tf > line.mbs:
            a, f = np.asarray(line.anchor, float), np.asarray(line.fairlead, float)
            dist = float(np.linalg.norm(f - a))
            length = float(sum(sg.length for sg in line.segments))
            raise line_nodes[i].error(
                "segments", f"a line whose tension at zero offset is below its MBS "
                f"{line.mbs / 1e3:.1f} kN", f"{tf / 1e3:.1f} kN at the fairlead",
                f"line {line.name!r}: unstretched length {length:.6g} m, anchor-fairlead "
                f"distance {dist:.6g} m"
                + (f" (a stretch of {100 * (dist / length - 1):.3g} %)" if dist > length else "")
                + "; the line is too short or its anchor too far")

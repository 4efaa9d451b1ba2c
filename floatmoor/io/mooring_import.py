"""Shared by the MoorDyn and MAP++ importers: what a reader understood (types, points, lines,
options, what it could not map) and its mapping to a floatmoor ``mooring.yaml`` (a comment per
conversion) and :class:`~floatmoor.mooring.system.MooringSystem`.

The conversions are documented in :mod:`floatmoor.io.moordyn`.  Topology: floatmoor lines run
from a fixed anchor to a fairlead on the one floating body; a free point joining exactly two
lines becomes a joint with a point load; anything else is a SceneError naming the file line.
"""

from __future__ import annotations

import math
import warnings
from dataclasses import dataclass, field
from pathlib import Path

from ..core.config import Node, parse_yaml_text
from ..core.constants import GRAVITY, RHO_WATER
from ..core.errors import FloatmoorWarning, SceneError
from ..mooring.fe.from_system import split_elements
from ..mooring.line_types import MBS_UNKNOWN

__all__ = ["MBS_UNKNOWN", "ImpLine", "ImpPoint", "ImpType", "ImportedMooring", "MooringImport",
           "build", "fmt", "to_yaml"]

# MBS_UNKNOWN (re-exported): the placeholder earlier imports wrote; a line type whose source file
# gives no MBS is now written ``mbs: unknown`` (the import warns; design checks refuse it).


# ------------------------------------------------------------------------------------------------
# intermediate model shared with the MAP++ reader
# ------------------------------------------------------------------------------------------------
@dataclass(frozen=True, kw_only=True)
class ImpType:
    name: str
    diameter: float
    mass: float
    ea: float
    line_no: int
    ba: float | None = None          # N s, or -zeta
    ei: float = 0.0
    cd: float | None = None          # normal drag on d
    ca: float | None = None          # normal added mass on the displaced volume
    cdax: float | None = None        # MoorDyn axial drag on pi d
    caax: float | None = None
    cdt_on_d: float | None = None    # axial drag already on d
    cb: float | None = None          # MAP++ seabed friction of the type


@dataclass(frozen=True, kw_only=True)
class ImpPoint:
    id: str
    kind: str                        # fixed | vessel | free
    xyz: tuple
    line_no: int
    mass: float = 0.0
    volume: float = 0.0


@dataclass(frozen=True, kw_only=True)
class ImpLine:
    id: str
    type: str
    a: str
    b: str
    length: float
    line_no: int
    n_segments: int | None = None


@dataclass(kw_only=True)
class ImportedMooring:
    """What a reader understood: types, points, lines and options, plus what it could not map
    (``unmapped``) and the conversions it made (``notes``)."""

    file: Path
    format: str
    types: dict = field(default_factory=dict)
    points: dict = field(default_factory=dict)
    lines: list = field(default_factory=list)
    water_depth: float | None = None
    water_density: float | None = None
    gravity: float | None = None
    kbot: float | None = None
    cbot: float | None = None
    mu_axial: float | None = None
    mu_lateral: float | None = None
    unmapped: list = field(default_factory=list)
    notes: list = field(default_factory=list)


@dataclass(frozen=True, kw_only=True)
class MooringImport:
    """Result of an import: the system, the ``mooring.yaml`` text that builds it, the site
    values it implies, the conversions made and what could not be mapped."""

    system: object
    yaml_text: str
    water_depth: float
    water_density: float
    gravity: float
    notes: tuple
    unmapped: tuple
    format: str

    @property
    def fe_options(self):
        """The FE options the file implies (:class:`~floatmoor.mooring.fe.options.FEOptions`)."""
        return self.system.line_models.options



# ------------------------------------------------------------------------------------------------
# mapping: ImportedMooring -> mooring.yaml text -> MooringSystem
# ------------------------------------------------------------------------------------------------
def fmt(x: float) -> str:
    """Shortest exact text of a float that YAML 1.1 also reads as a float (``1.0e+30``)."""
    t = repr(float(x))
    if "e" in t and "." not in t.split("e")[0]:
        a, b = t.split("e")
        t = f"{a}.0e{b if b[0] in '+-' else '+' + b}"
    return t


def _chains(m: ImportedMooring):
    """Group the lines into floatmoor lines: chains anchor -> (free points) -> vessel.

    Returns a list of (name, [(ImpLine, reversed)], [free point ids between segments])."""
    path = m.file
    attached = {pid: [] for pid in m.points}
    for ln in m.lines:
        for p in (ln.a, ln.b):
            attached[p].append(ln)
    for pid, p in m.points.items():
        if p.kind.startswith("attached:"):
            if attached[pid]:
                raise SceneError(path, f"line {p.line_no}", "lines attached to fixed, vessel or "
                                 "free points (floatmoor has one floating body and no rods)",
                                 f"point {pid} attached to {p.kind[9:]!r}")
            m.unmapped.append(f"point {pid} (line {p.line_no}) on {p.kind[9:]!r}, no line")
        if p.kind == "free" and len(attached[pid]) != 2:
            raise SceneError(path, f"line {p.line_no}", "a free point joining exactly two lines "
                             "(a clump weight or buoy between two segments)",
                             f"point {pid} joining {len(attached[pid])} lines",
                             "bridles and shared lines have no floatmoor counterpart")
        if p.kind in ("fixed", "vessel") and len(attached[pid]) > 1:
            ids = ", ".join(ln.id for ln in attached[pid])
            raise SceneError(path, f"line {p.line_no}", f"one line on each {p.kind} point",
                             f"point {pid} holding lines {ids}",
                             "floatmoor lines have their own anchor and fairlead")
    out = []
    used = set()
    for start in m.lines:
        if start.id in used:
            continue
        ka, kb = m.points[start.a].kind, m.points[start.b].kind
        if "fixed" not in (ka, kb):
            continue
        seq = []
        ln, rev = start, ka != "fixed"
        joints = []
        while True:
            seq.append((ln, rev))
            used.add(ln.id)
            top = ln.a if rev else ln.b
            kind = m.points[top].kind
            if kind == "vessel":
                break
            if kind == "fixed":
                raise SceneError(path, f"line {ln.line_no}", "a line from an anchor to the "
                                 "vessel", f"line {ln.id} ending on fixed point {top}",
                                 "lines between two fixed points have no floatmoor counterpart")
            nxt = next(x for x in attached[top] if x.id != ln.id)
            joints.append(top)
            ln, rev = nxt, nxt.b == top
        name = "line" + "-".join(x.id for x, _ in seq)
        out.append((name, seq, joints))
    left = [ln for ln in m.lines if ln.id not in used]
    if left:
        ln = left[0]
        raise SceneError(path, f"line {ln.line_no}", "a line on a path from a fixed point to a "
                         "vessel point", f"line {ln.id} between points {ln.a} and {ln.b}",
                         "lines between two vessel points have no floatmoor counterpart")
    return out


def to_yaml(m: ImportedMooring, *, water_depth=None, water_density=None, gravity=None,
            model: str = "quasi-static"):
    """The floatmoor ``mooring.yaml`` text of an imported mooring, with a comment per
    conversion; returns ``(text, water_depth, water_density, gravity)``."""
    notes = list(m.notes)
    src = m.file.name
    depth_src = "the file"
    if water_depth is not None:
        depth_src = "the caller"
    elif m.water_depth is not None:
        water_depth = m.water_depth
    else:
        fixed = [p.xyz[2] for p in m.points.values() if p.kind == "fixed"]
        if not fixed:
            raise SceneError(m.file, "", "a fixed point (anchor) or a water depth option",
                             "neither")
        water_depth = -min(fixed)
        depth_src = "the deepest fixed point (the file gives no depth: OpenFAST passes its own)"
    rho = water_density if water_density is not None else (m.water_density or RHO_WATER)
    g = gravity if gravity is not None else (m.gravity or GRAVITY)
    notes.append(f"water depth {water_depth:g} m from {depth_src}; water density {rho:g} kg/m^3"
                 f" and gravity {g:g} m/s^2 "
                 + ("from the file" if m.gravity is not None else
                    "(not in the file: OpenFAST passes its own"
                    + ("; standalone MoorDyn assumes g = 9.8)" if "MoorDyn" in m.format
                       else ")"))
                 + " -- put them in the scene's site section")
    chains = _chains(m)
    used_types = [t for t in m.types.values() if any(ln.type == t.name for _, seq, _ in chains
                                                    for ln, _ in seq)]
    for t in m.types.values():
        if t not in used_types:
            m.unmapped.append(f"line type {t.name!r} (line {t.line_no}): used by no line")
    L = [f"# floatmoor mooring file imported from {src} ({m.format}).",
         "# Conversions (source values in the comments; SI units throughout):"]
    L += [f"#  - {n}" for n in notes]
    L += [f"description: imported from {src} ({m.format})", "line_types:"]
    d_seabed = []
    for t in used_types:
        L += [f"  {t.name}:",
              "    material: user",
              f"    diameter: {fmt(t.diameter)}        # m, the file's volume-equivalent diameter",
              f"    mass_per_length: {fmt(t.mass)}  # kg/m in air",
              (f"    volumetric_diameter: {fmt(t.diameter)}  # displaced volume pi d^2/4 per m "
               f"(the file's buoyancy)"),
              f"    ea: {fmt(t.ea)}               # N",
              ("    mbs: unknown   # NOT IN THE SOURCE FILE: set the real MBS (N); design "
               "checks refuse an unknown MBS")]
        if t.cd is not None:
            L.append(f"    cdn: {fmt(t.cd)}   # normal drag on d (MoorDyn Cd)")
        if t.ca is not None:
            L.append(f"    can: {fmt(t.ca)}   # normal added mass on the displaced volume "
                     f"(MoorDyn Ca)")
        if t.cdax is not None:
            L.append(f"    cdt: {fmt(math.pi * t.cdax)}   # = pi x MoorDyn CdAx {t.cdax:g}: "
                     f"MoorDyn's axial drag acts on pi d, floatmoor's on d")
        elif t.cdt_on_d is not None:
            L.append(f"    cdt: {fmt(t.cdt_on_d)}   # axial drag on d")
        if t.caax is not None:
            L.append(f"    cat: {fmt(t.caax)}   # axial added mass on the displaced volume "
                     f"(MoorDyn CaAx)")
        L.append(f"    source: {src} line {t.line_no}")
        d_seabed.append(t.diameter)
    mu_ax = m.mu_axial
    L.append(f"seabed_friction: {fmt(mu_ax or 0.0)}   # axial Coulomb coefficient of "
             "quasi-static lines" + ("" if mu_ax else " (none in the file)"))
    L.append("lines:")
    for name, seq, joints in chains:
        first, rev0 = seq[0]
        last, revn = seq[-1]
        anchor = m.points[first.b if rev0 else first.a].xyz
        fair = m.points[last.a if revn else last.b].xyz
        L += [f"  - name: {name}",
              f"    anchor: {{x: {fmt(anchor[0])}, y: {fmt(anchor[1])}, z: {fmt(anchor[2])}}}",
              f"    fairlead: [{fmt(fair[0])}, {fmt(fair[1])}, {fmt(fair[2])}]   # body axes",
              "    segments:"]
        for k, (ln, _rev) in enumerate(seq):
            extra, comment = "", ""
            if k < len(joints):
                p = m.points[joints[k]]
                load = (p.mass - rho * p.volume) * g
                if load > 0:
                    extra = f", clump_weight: {fmt(load)}"
                elif load < 0:
                    extra = f", buoy_net_buoyancy: {fmt(-load)}"
                if load:
                    comment = (f"   # N, point {p.id}: (M {p.mass:g} kg - rho V {p.volume:g} "
                               f"m^3) g")
            L.append(f"      - {{type: {ln.type}, length: {fmt(ln.length)}{extra}}}{comment}")
    # FE options
    nseg = {ln.n_segments for ln in m.lines if ln.n_segments}
    seq_counts = {sum(ln.n_segments or 0 for ln, _ in seq) for _, seq, _ in chains}
    L.append(f"model: {model}   # quasi-static catenary lines; finite-element uses the options "
             f"below")
    # NumSegs of each chain's segments: one list for all the chains that the share by length
    # of their sum would not give is written as it is
    per_seg = [[ln.n_segments or 0 for ln, _ in seq] for _, seq, _ in chains]
    by_length = all(split_elements([ln.length for ln, _ in seq], sum(c)) == c
                    for (_, seq, _), c in zip(chains, per_seg))
    fe = []
    if (nseg and not by_length and len(per_seg[0]) > 1 and min(per_seg[0]) >= 1
            and all(c == per_seg[0] for c in per_seg)):
        fe.append(f"  n_elements: {per_seg[0]}   # MoorDyn NumSegs of each segment, anchor to "
                  f"fairlead")
    elif len(seq_counts) == 1 and nseg:
        fe.append(f"  n_elements: {seq_counts.pop()}   # MoorDyn NumSegs (segments per line)")
    elif nseg:
        Ltot = sum(ln.length for ln in m.lines)
        ntot = sum(ln.n_segments for ln in m.lines)
        fe.append(f"  element_length: {fmt(Ltot / ntot)}   # lines differ in NumSegs: the mean "
                  f"segment length")
        m.unmapped.append("NumSegs differs between lines: finite_element.element_length is "
                          "the mean segment length")
    bas = {t.ba for t in used_types if t.ba is not None}
    if len(bas) == 1:
        fe.append(f"  internal_damping: {fmt(bas.pop())}   # MoorDyn BA/-zeta (N s, or -zeta)")
    elif len(bas) > 1:
        b0 = used_types[0].ba
        fe.append(f"  internal_damping: {fmt(b0)}   # BA/-zeta of type {used_types[0].name}")
        m.unmapped.append(f"BA/-zeta differs between line types {sorted(bas)}: floatmoor uses "
                          f"one value ({b0:g}) for all FE lines")
    if m.kbot is not None or m.cbot is not None:
        dref = max(d_seabed)
        kb = m.kbot if m.kbot is not None else 3.0e6
        cb = m.cbot if m.cbot is not None else 3.0e5
        fe.append(f"  seabed: {{model: springs, stiffness: {fmt(kb * dref)}, damping: "
                  f"{fmt(cb * dref)}}}   # kBot {kb:g} Pa/m and cBot {cb:g} Pa s/m x d {dref:g} m "
                  f"(per unit area -> per unit length)")
        if len(set(d_seabed)) > 1:
            m.unmapped.append("kBot, cBot: floatmoor's seabed springs are per unit length for "
                              f"all lines; the largest diameter ({dref:g} m) is used")
    if m.mu_axial or m.mu_lateral:
        fe.append(f"  friction: {{model: velocity_ramp, mu_axial: {fmt(m.mu_axial or 0.0)}, "
                  f"mu_lateral: {fmt(m.mu_lateral or 0.0)}}}   # seabed Coulomb coefficients")
    if fe:
        L.append("finite_element:")
        L += fe
    return "\n".join(L) + "\n", water_depth, rho, g


def build(m: ImportedMooring, *, water_depth=None, water_density=None, gravity=None,
           model="quasi-static", warn=True) -> MooringImport:
    from .mooring_section import parse_mooring

    text, depth, rho, g = to_yaml(m, water_depth=water_depth, water_density=water_density,
                                  gravity=gravity, model=model)
    node = Node(parse_yaml_text(text, m.file), file=m.file)
    system = parse_mooring(node, water_depth=depth, water_density=rho, gravity=g)
    unmapped = list(m.unmapped)
    unmapped.append("MBS: not in the file; the line types carry mbs: unknown (statics, motions "
                    "and tensions run; set the MBS before any design check: report, campaign, "
                    "fatigue)")
    if warn:
        warnings.warn(f"{m.file}: not mapped to floatmoor ({m.format}):\n  - "
                      + "\n  - ".join(unmapped), FloatmoorWarning, stacklevel=3)
    return MooringImport(system=system, yaml_text=text, water_depth=depth, water_density=rho,
                         gravity=g, notes=tuple(m.notes), unmapped=tuple(unmapped),
                         format=m.format)

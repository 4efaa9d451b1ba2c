"""MAP++ input files -> floatmoor mooring (:class:`MooringSystem` or ``mooring.yaml``).

MAP++ (Masciola et al. 2013; the OpenFAST MAP++ documentation) is a quasi-static model: a
``LINE DICTIONARY`` (LineType Diam MassDenInAir EA CB CIntDamp Ca Cdn Cdt), ``NODE PROPERTIES``
(Node Type X Y Z M B FX FY FZ; Type fix, vessel or connect; ``Z = depth`` puts a node on the
seabed; ``#`` marks a value MAP++ solves for), ``LINE PROPERTIES`` (Line LineType UnstrLen
NodeAnch NodeFair Flags) and ``SOLVER OPTIONS`` (``repeat a1 a2 ...`` copies every line rotated
about z by each angle in degrees).  A hand-written reader: ``openfast_io.read_MAP`` reads the
columns by position and leaves ``depth`` and ``#`` unresolved, with no line numbers in errors.

Mapping: ``Diam`` is the volume-equivalent diameter (displaced volume pi d^2/4), ``CB`` the
seabed friction coefficient of the lines of that type (``seabed_friction``), ``M``/``B`` of a
connect node a point load ``(M - rho B) g``.  ``CIntDamp``, ``Ca``, ``Cdn`` and ``Cdt`` are not
used by MAP++ (a static model) and are not imported (floatmoor's defaults apply to FE lines);
flags and solver options other than ``repeat`` are listed as not mapped.  The mapping and the
``mooring.yaml`` writer are shared with MoorDyn (:mod:`floatmoor.io.mooring_import`).
"""

from __future__ import annotations

import math

from ..core.errors import SceneError
from .moordyn import _read_lines, _split_sections, _table
from .mooring_import import (
    ImpLine,
    ImportedMooring,
    ImpPoint,
    ImpType,
    MooringImport,
    build,
)

__all__ = ["parse", "read", "read_model"]

_TYPES = ["LineType", "Diam", "MassDenInAir", "EA", "CB", "CIntDamp", "Ca", "Cdn", "Cdt"]
_NODES = ["Node", "Type", "X", "Y", "Z", "M", "B", "FX", "FY", "FZ"]
_LINES = ["Line", "LineType", "UnstrLen", "NodeAnch", "NodeFair", "Flags"]
_KIND = {"FIX": "fixed", "FIXED": "fixed", "VESSEL": "vessel", "CONNECT": "free"}


def _value(path, n, col, tok, what, depth_ok=False):
    t = tok.lstrip("#")
    if depth_ok and t.lower() == "depth":
        return "depth"
    if tok.startswith("#") and t == "":
        return None
    try:
        return float(t)
    except ValueError:
        raise SceneError(path, f"line {n}", f"{what} in column {col}"
                         + (" (a number or 'depth')" if depth_ok else ""), tok) from None


def _rows(path, tab, cols, title, min_extra=0, open_end=False):
    for n, t in tab.rows:
        ok = len(t) >= len(cols) if open_end else len(t) == len(cols)
        if not ok:
            raise SceneError(path, f"line {n}", f"{len(cols)}{' or more' if open_end else ''} "
                             f"columns in the MAP++ {title} table ({' '.join(cols)}), as in "
                             f"its header on line {tab.header_line}",
                             f"{len(t)} columns: {' '.join(t)}")
    if not tab.rows:
        raise SceneError(path, f"line {tab.header_line}", f"at least one row in the {title} "
                         "table", "none (truncated table)")


def parse(path) -> ImportedMooring:
    """Read a MAP++ input file into an :class:`ImportedMooring` (no mapping yet)."""
    path, lines = _read_lines(path)
    secs = {}
    for _kind, title_line, body in _split_sections(path, lines):
        title = lines[title_line - 1].upper()
        k = ("types" if "LINE DICTIONARY" in title else "nodes" if "NODE PROPERTIES" in title
             else "lines" if "LINE PROPERTIES" in title else "options" if "OPTIONS" in title
             else None)
        if k is None:
            raise SceneError(path, f"line {title_line}", "a MAP++ section: LINE DICTIONARY, "
                             "NODE PROPERTIES, LINE PROPERTIES or SOLVER OPTIONS",
                             lines[title_line - 1].strip())
        secs[k] = (title_line, body)
    for k, title in (("types", "LINE DICTIONARY"), ("nodes", "NODE PROPERTIES"),
                     ("lines", "LINE PROPERTIES")):
        if k not in secs:
            raise SceneError(path, "", f"a {title} section", "none",
                             "is this a MAP++ input file?")
    m = ImportedMooring(file=path, format="MAP++")
    tt = _table(path, "types", *secs["types"])
    if [h.upper() for h in tt.header[:4]] == ["NAME", "DIAM", "MASSDEN", "EA"] or \
            len(tt.header) == 10:
        raise SceneError(path, f"line {tt.header_line}", "MAP++ line dictionary columns "
                         + " ".join(_TYPES), " ".join(tt.header),
                         "this looks like a MoorDyn v2 table: use floatmoor import moordyn")
    _rows(path, tt, _TYPES, "LINE DICTIONARY")
    for n, t in tt.rows:
        vals = [_value(path, n, c + 1, t[c], _TYPES[c]) for c in range(1, 9)]
        d, mass, ea, cb = vals[0], vals[1], vals[2], vals[3]
        for c, v, what in ((2, d, "Diam > 0 (m)"), (3, mass, "MassDenInAir > 0 (kg/m)"),
                           (4, ea, "EA > 0 (N)")):
            if v is None or not v > 0:
                raise SceneError(path, f"line {n}", f"{what} in column {c}", t[c - 1])
        if cb is None or cb < 0:
            raise SceneError(path, f"line {n}", "CB >= 0 in column 5", t[4])
        if t[0] in m.types:
            raise SceneError(path, f"line {n}", "a unique line type name", t[0])
        m.types[t[0]] = ImpType(name=t[0], diameter=d, mass=mass, ea=ea, cb=cb, line_no=n)
        m.unmapped.append(f"line type {t[0]!r} (line {n}): CIntDamp {t[5]}, Ca {t[6]}, "
                          f"Cdn {t[7]}, Cdt {t[8]} (not used by MAP++, a static model; "
                          f"floatmoor's defaults apply to FE lines)")
    nt = _table(path, "points", *secs["nodes"])
    _rows(path, nt, _NODES, "NODE PROPERTIES")
    depth_nodes = []
    for n, t in nt.rows:
        kind = _KIND.get(t[1].upper())
        if kind is None:
            raise SceneError(path, f"line {n}", "a node type in column 2: fix, vessel or "
                             "connect", t[1])
        x, y = (_value(path, n, c + 1, t[c], _NODES[c]) for c in (2, 3))
        z = _value(path, n, 5, t[4], "Z", depth_ok=True)
        mass, vol = (_value(path, n, c + 1, t[c], _NODES[c]) for c in (5, 6))
        if None in (x, y, z):
            raise SceneError(path, f"line {n}", "node coordinates X, Y, Z (an initial guess "
                             "after '#' for a connect node)", " ".join(t[2:5]))
        fxyz = [t[c] for c in (7, 8, 9)]
        if any(f.lstrip("#") not in ("", "0", "0.0") for f in fxyz):
            m.unmapped.append(f"node {t[0]} (line {n}): external force FX FY FZ = "
                              f"{' '.join(fxyz)} (no floatmoor counterpart)")
        if z == "depth":
            depth_nodes.append(t[0])
        m.points[t[0]] = ImpPoint(id=t[0], kind=kind, xyz=(x, y, z), mass=mass or 0.0,
                                  volume=vol or 0.0, line_no=n)
    lt = _table(path, "lines", *secs["lines"])
    _rows(path, lt, _LINES[:-1], "LINE PROPERTIES", open_end=True)
    for n, t in lt.rows:
        if t[1] not in m.types:
            raise SceneError(path, f"line {n}", "a line type name in column 2, one of: "
                             + ", ".join(m.types), t[1])
        for c in (3, 4):
            if t[c] not in m.points:
                raise SceneError(path, f"line {n}", f"a node number in column {c + 1}, one of: "
                                 + ", ".join(m.points), t[c])
        length = _value(path, n, 3, t[2], "UnstrLen (m)")
        if length is None or not length > 0:
            raise SceneError(path, f"line {n}", "UnstrLen > 0 m in column 3", t[2])
        m.lines.append(ImpLine(id=t[0], type=t[1], a=t[3], b=t[4], length=length, line_no=n))
        if len(t) > 5:
            m.unmapped.append(f"line {t[0]} (line {n}): flags {' '.join(t[5:])} (MAP++ "
                              f"outputs and solver flags)")
    repeats = []
    if "options" in secs:
        title_line, body = secs["options"]
        for n, text in body:
            tok = text.split()
            if not tok or tok[0] in ("Option", "(-)") or tok[0].startswith("!"):
                continue
            if tok[0].lower() == "repeat":
                if len(tok) < 2:
                    raise SceneError(path, f"line {n}", "repeat followed by angles in degrees",
                                     text.strip())
                repeats += [_value(path, n, c + 1, tok[c], "an angle (deg)")
                            for c in range(1, len(tok))]
            else:
                m.unmapped.append(f"solver option {' '.join(tok)} (line {n}): MAP++ solver "
                                  f"setting")
    cbs = {t.name: t.cb for t in m.types.values()}
    m.mu_axial = m.mu_lateral = max(cbs.values()) if cbs else None
    if len(set(cbs.values())) > 1:
        m.unmapped.append(f"CB differs between line types {cbs}: floatmoor uses one seabed "
                          f"friction per line; the largest is used")
    m.notes.append("Z = depth of the MAP++ nodes " + ", ".join(depth_nodes)
                   + " -> z = -water depth" if depth_nodes else "no node at Z = depth")
    if repeats:
        _repeat(m, repeats)
    return m


def _repeat(m: ImportedMooring, angles):
    """Copies of every line and its nodes rotated about z by each angle (MAP++ ``repeat``)."""
    base_points = dict(m.points)
    base_lines = list(m.lines)
    for k, a in enumerate(angles, start=1):
        c, s = math.cos(math.radians(a)), math.sin(math.radians(a))
        ids = {}
        for pid, p in base_points.items():
            new = f"{pid}r{k}"
            x, y, z = p.xyz
            m.points[new] = ImpPoint(id=new, kind=p.kind, xyz=(c * x - s * y, s * x + c * y, z),
                                     mass=p.mass, volume=p.volume, line_no=p.line_no)
            ids[pid] = new
        for ln in base_lines:
            m.lines.append(ImpLine(id=f"{ln.id}r{k}", type=ln.type, a=ids[ln.a], b=ids[ln.b],
                                   length=ln.length, line_no=ln.line_no))
    m.notes.append("MAP++ repeat " + " ".join(f"{a:g}" for a in angles) + " deg: lines "
                   "'<n>r<k>' are line <n> rotated about z by the k-th angle")


def _resolve_depth(m: ImportedMooring, water_depth):
    if water_depth is None:
        fixed = [p.xyz[2] for p in m.points.values() if p.xyz[2] != "depth"
                 and p.kind == "fixed"]
        if any(p.xyz[2] == "depth" for p in m.points.values()):
            raise SceneError(m.file, "", "a water depth for the nodes at Z = depth (MAP++ takes "
                             "it from OpenFAST: give --water-depth)", "none")
        water_depth = -min(fixed)
    for pid, p in list(m.points.items()):
        if p.xyz[2] == "depth":
            m.points[pid] = ImpPoint(id=p.id, kind=p.kind, xyz=(p.xyz[0], p.xyz[1], -water_depth),
                                     mass=p.mass, volume=p.volume, line_no=p.line_no)
    m.water_depth = water_depth
    return water_depth


def read_model(path, *, water_depth=None, water_density=None, gravity=None,
               model: str = "quasi-static", warn: bool = True) -> MooringImport:
    """Read a MAP++ file: the system, its ``mooring.yaml`` text and what was not mapped.

    MAP++ files take the water depth, density and gravity from OpenFAST: ``water_depth`` is
    required when a node has ``Z = depth``; density and gravity default to 1025 kg/m^3 and
    9.80665 m/s^2.
    """
    m = parse(path)
    _resolve_depth(m, water_depth)
    return build(m, water_depth=m.water_depth, water_density=water_density, gravity=gravity,
                 model=model, warn=warn)


def read(path, **kw):
    """A MAP++ input file as a :class:`~floatmoor.mooring.system.MooringSystem`."""
    return read_model(path, **kw).system

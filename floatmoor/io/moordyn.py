"""MoorDyn input files (v1 and v2) -> floatmoor mooring (:class:`MooringSystem` or ``mooring.yaml``).

MoorDyn (Hall (2015), the MoorDyn v1 user's guide; the MoorDyn v2 documentation of Hall and
co-authors, "MoorDyn v2 input file") describes a mooring as
tables of line types, points and lines plus options.  The two versions differ in the columns,
not only in the section names, and MoorDyn itself reads every table by position, so a v1 file
read as v2 gives wrong numbers without an error.  This reader recognises each table's version
from its header row (column names), checks every row's column count against it and refuses a
file that mixes the versions.  A hand-written parser is used because no maintained reader gets
both versions right: ``openfast_io`` (the OpenFAST team's readers, versions 4.2 and 5.0) reads
every table in the v2 column order whatever its header says, and MoorPy's reader stops on (or
misplaces the points of) a v1 file (see ``tests/io/test_import_moordyn.py``).

Mapping to floatmoor (a comment per conversion is written into ``mooring.yaml``)
--------------------------------------------------------------------------------
* line types: ``Diam`` is MoorDyn's volume-equivalent diameter: floatmoor ``diameter`` and
  ``volumetric_diameter`` (displaced volume pi d^2/4 per m); ``MassDen`` -> ``mass_per_length``;
  ``EA`` -> ``ea``; ``Cd``/``Cdn`` -> ``cdn`` (both on d); ``Ca``/``Can`` -> ``can`` and
  ``CaAx``/``Cat`` -> ``cat`` (both on the displaced volume); ``CdAx``/``Cdt`` acts on pi d in
  MoorDyn and floatmoor's ``cdt`` on d, so ``cdt = pi CdAx``.  MoorDyn has no MBS: the imported
  type carries ``mbs: unknown`` and the import warns (set the real MBS before any design check:
  the checks that need it refuse an unknown MBS).
* ``BA/-zeta`` -> ``finite_element.internal_damping`` (same convention: N s, or -zeta);
  ``NumSegs`` -> ``finite_element.n_elements``; ``kBot``/``cBot`` (per unit area, Pa/m, Pa s/m)
  -> ``finite_element.seabed`` stiffness and damping per unit length (x the diameter); friction
  coefficients -> ``seabed_friction`` (axial, quasi-static lines) and ``finite_element.friction``.
* points: ``fixed``/``anchor`` -> anchors, ``vessel``/``coupled`` -> fairleads (body axes about
  the reference point), ``free``/``connect`` points joining exactly two lines -> a joint of one
  multi-segment floatmoor line with the point load ``(M - rho V) g`` (clump weight or buoy).
* options: water depth, density, gravity; a depth missing from the file (OpenFAST passes its
  own) is taken from the deepest fixed point.

Whatever has no floatmoor counterpart (rods, bodies, a free point's drag, EI, outputs, the
solver time step and initial-condition settings, ...) is listed in one
:class:`~floatmoor.core.errors.FloatmoorWarning`; a topology floatmoor cannot hold (a point
joining three lines, a line between two vessel points, a line on a body or rod) is a
:class:`SceneError`.  Every input error is a SceneError naming the file, ``line N`` of the file,
what was expected and what was found.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass
from pathlib import Path

from ..core.errors import SceneError
from .mooring_import import (
    MBS_UNKNOWN,
    ImpLine,
    ImportedMooring,
    ImpPoint,
    ImpType,
    MooringImport,
    build,
    fmt,
)

__all__ = [
    "MBS_UNKNOWN",
    "ImportedMooring",
    "MooringImport",
    "export",
    "parse",
    "read",
    "read_model",
]

# ------------------------------------------------------------------------------------------------
# low-level file reading
# ------------------------------------------------------------------------------------------------
MAX_INPUT_BYTES = 16 * 2**20
"""Largest MoorDyn or MAP++ input file read (real ones are a few kB; a line per segment of a
large array is well below this): a bigger file is refused before it is read."""

MAX_SEGMENTS = 10_000
"""Most segments (``NumSegs``) of one MoorDyn line: each is a finite element of the imported
line, with its state and matrices (MoorDyn models use 10-100)."""


def _read_lines(path) -> tuple[Path, list[str]]:
    path = Path(path)
    if not path.is_file():
        raise SceneError(path, "", "an existing input file",
                         "a directory" if path.is_dir() else "no such file")
    try:
        size = path.stat().st_size
        if size > MAX_INPUT_BYTES:
            raise SceneError(path, "", f"an input file of at most {MAX_INPUT_BYTES / 2**20:g} "
                             "MiB (MoorDyn and MAP++ files are a few kB)",
                             f"{size / 2**20:.1f} MiB", "is it the right file?")
        text = path.read_text(encoding="utf-8", errors="replace")
    except OSError as exc:
        raise SceneError(path, "", "a readable input file", str(exc)) from None
    return path, [ln.replace("\r", "") for ln in text.split("\n")]


def _num(path, line_no, col, token, what="a number"):
    try:
        return float(token)
    except ValueError:
        raise SceneError(path, f"line {line_no}", f"{what} in column {col}", token) from None


def _is_section(text: str) -> bool:
    return text.strip().startswith("---")


def _section_kind(title: str) -> str:
    t = " ".join(re.sub(r"[^A-Za-z ]", " ", title).upper().split())
    for kind, keys in (("types", ("LINE DICTIONARY", "LINE TYPES")),
                       ("rod_types", ("ROD DICTIONARY", "ROD TYPES")),
                       ("bodies", ("BODY LIST", "BODY PROPERTIES", "BODIES")),
                       ("rods", ("ROD LIST", "ROD PROPERTIES", "RODS")),
                       ("points", ("POINT LIST", "POINT PROPERTIES", "POINTS",
                                   "CONNECTION PROPERTIES", "CONNECTIONS", "NODE PROPERTIES")),
                       ("lines", ("LINE LIST", "LINE PROPERTIES", "LINES")),
                       ("failure", ("FAILURE",)), ("control", ("CONTROL",)),
                       ("external", ("EXTERNAL",)),
                       ("options", ("OPTIONS",)), ("outputs", ("OUTPUT",))):
        if any(k in t for k in keys):
            return kind
    if "NEED THIS LINE" in t or "INPUT FILE" in t:
        return "ignore"
    return "unknown:" + t


@dataclass
class _Table:
    kind: str
    title_line: int
    header: list
    header_line: int
    rows: list          # (line_no, tokens)


def _split_sections(path, lines):
    """Sections as (kind, title line number, body lines [(no, text)])."""
    out = []
    cur = None
    for i, text in enumerate(lines, start=1):
        if _is_section(text):
            cur = (_section_kind(text), i, [])
            out.append(cur)
        elif cur is not None:
            cur[2].append((i, text))
    return out


def _table(path, kind, title_line, body) -> _Table:
    content = [(n, t) for n, t in body if t.strip() and not t.strip().startswith("#")]
    if len(content) < 2:
        raise SceneError(path, f"line {title_line}", "a table: a row of column names, a row of "
                         "units, then the rows", f"a truncated table (the file or section ends "
                         f"after {len(content)} line{'' if len(content) == 1 else 's'})")
    (hn, ht), _units = content[0], content[1]
    rows = [(n, t.split()) for n, t in content[2:]]
    return _Table(kind, title_line, ht.split(), hn, rows)


# ------------------------------------------------------------------------------------------------
# MoorDyn tables, v1 and v2
# ------------------------------------------------------------------------------------------------
_V1_TYPES = ["LineType", "Diam", "MassDenInAir", "EA", "BA/-zeta", "Can", "Cat", "Cdn", "Cdt"]
_V2_TYPES = ["Name", "Diam", "MassDen", "EA", "BA/-zeta", "EI", "Cd", "Ca", "CdAx", "CaAx"]
_V1_POINTS = ["Node", "Type", "X", "Y", "Z", "M", "V", "FX", "FY", "FZ", "CdA", "CA"]
_V2_POINTS = ["ID", "Attachment", "X", "Y", "Z", "M", "V", "CdA", "CA"]
_V1_LINES = ["Line", "LineType", "UnstrLen", "NumSegs", "NodeAnch", "NodeFair", "Flags/Outputs"]
_V2_LINES = ["ID", "LineType", "AttachA", "AttachB", "UnstrLen", "NumSegs", "Outputs"]

_V1_MARKS = {"types": {"CAN", "CAT", "CDN", "CDT"}, "points": {"NODE", "FX", "FY", "FZ"},
             "lines": {"NODEANCH", "NODEFAIR", "FLAGS/OUTPUTS", "FLAGS"}}
_V2_MARKS = {"types": {"EI", "CD", "CA", "CDAX", "CAAX"}, "points": {"ATTACHMENT", "POINT"},
             "lines": {"ATTACHA", "ATTACHB", "OUTPUTS"}}
_LAYOUT = {("types", 1): _V1_TYPES, ("types", 2): _V2_TYPES, ("points", 1): _V1_POINTS,
           ("points", 2): _V2_POINTS, ("lines", 1): _V1_LINES, ("lines", 2): _V2_LINES}
_V2_ONLY_SECTIONS = {"rod_types", "bodies", "rods", "failure", "control", "external"}

_KIND_TITLE = {"types": "LINE TYPES", "points": "POINTS", "lines": "LINES"}


def _table_version(path, tab: _Table) -> int | None:
    """Version (1 or 2) a table's column names show, None when they show neither."""
    names = {h.upper() for h in tab.header}
    v1 = names & _V1_MARKS[tab.kind]
    v2 = names & _V2_MARKS[tab.kind]
    if v1 and v2:
        raise SceneError(path, f"line {tab.header_line}",
                         f"the column names of one MoorDyn version ({_KIND_TITLE[tab.kind]} "
                         f"table): v1 {' '.join(_LAYOUT[tab.kind, 1])} or v2 "
                         f"{' '.join(_LAYOUT[tab.kind, 2])}", " ".join(tab.header),
                         f"v1 names {sorted(v1)} and v2 names {sorted(v2)} together")
    return 1 if v1 else 2 if v2 else None


def _check_columns(path, tab: _Table, version: int, allowed_extra=()):
    cols = _LAYOUT[tab.kind, version]
    counts = {len(cols), *(len(cols) + k for k in allowed_extra)}
    if not tab.rows and tab.kind != "points":
        raise SceneError(path, f"line {tab.header_line}", f"at least one row in the "
                         f"{_KIND_TITLE[tab.kind]} table", "none (truncated table)")
    for n, toks in tab.rows:
        if len(toks) not in counts:
            if tab.kind == "lines" and len(toks) == len(cols) - 1:
                # the outputs flag column may be left out
                continue
            want = " or ".join(str(c) for c in sorted(counts))
            raise SceneError(path, f"line {n}",
                             f"{want} columns in the MoorDyn v{version} "
                             f"{_KIND_TITLE[tab.kind]} table ({' '.join(cols)}), as in its "
                             f"header on line {tab.header_line}",
                             f"{len(toks)} columns: {' '.join(toks)}")


_POINT_KINDS = {"FIXED": "fixed", "FIX": "fixed", "ANCHOR": "fixed",
                "VESSEL": "vessel", "VES": "vessel", "COUPLED": "vessel", "CPLD": "vessel",
                "FREE": "free", "CONNECT": "free", "CON": "free"}


def parse(path) -> ImportedMooring:
    """Read a MoorDyn v1 or v2 input file into an :class:`ImportedMooring` (no mapping yet)."""
    path, lines = _read_lines(path)
    sections = _split_sections(path, lines)
    kinds = [s[0] for s in sections]
    for need in ("types", "points", "lines"):
        if need not in kinds:
            raise SceneError(path, "", f"a {_KIND_TITLE[need]} section (a line starting with "
                             f"'---' naming it, then its table)", "none",
                             "is this a MoorDyn input file?")
    tables = {}
    for kind, title_line, body in sections:
        if kind in ("types", "points", "lines"):
            if kind in tables:
                raise SceneError(path, f"line {title_line}", f"one {_KIND_TITLE[kind]} section",
                                 "a second one")
            tables[kind] = _table(path, kind, title_line, body)
    versions = {k: _table_version(path, t) for k, t in tables.items()}
    known = {k: v for k, v in versions.items() if v is not None}
    if len(set(known.values())) > 1:
        v1 = [k for k, v in known.items() if v == 1]
        v2 = [k for k, v in known.items() if v == 2]
        t2 = tables[v2[0]]
        raise SceneError(path, f"line {t2.header_line}",
                         f"MoorDyn v1 column names (the {_KIND_TITLE[v1[0]]} table on line "
                         f"{tables[v1[0]].header_line} is v1: "
                         f"{' '.join(_LAYOUT[v1[0], 1])})",
                         f"v2 column names: {' '.join(t2.header)}",
                         "a file must use one version throughout")
    if known:
        version = next(iter(known.values()))
    else:  # no recognisable header: the line-type column count decides (9 in v1, >= 10 in v2)
        n = len(tables["types"].rows[0][1]) if tables["types"].rows else 10
        version = 1 if n == 9 else 2
    if version == 1:
        for kind, title_line, _body in sections:
            if kind in _V2_ONLY_SECTIONS:
                raise SceneError(path, f"line {title_line}", "the sections of a MoorDyn v1 file "
                                 "(LINE DICTIONARY, NODE PROPERTIES, LINE PROPERTIES, SOLVER "
                                 "OPTIONS, OUTPUTS)", f"the v2 section {lines[title_line - 1].strip()!r}",
                                 f"the LINE TYPES table on line {tables['types'].header_line} "
                                 f"has v1 columns")
    _check_columns(path, tables["types"], version, allowed_extra=(() if version == 1 else (1, 3)))
    _check_columns(path, tables["points"], version)
    _check_columns(path, tables["lines"], version)
    m = ImportedMooring(file=path, format=f"MoorDyn v{version}")
    _read_types(path, tables["types"], version, m)
    _read_points(path, tables["points"], version, m)
    _read_lines_table(path, tables["lines"], version, m)
    for kind, title_line, body in sections:
        if kind == "options":
            _read_options(path, body, m, version)
        elif kind == "outputs":
            outs = [t.strip() for n, t in body if t.strip() and t.strip().upper() != "END"]
            end = next((i for i, o in enumerate(outs) if o.upper().startswith("END")), None)
            outs = outs[:end] if end is not None else outs
            if outs:
                m.unmapped.append(f"outputs (line {title_line}): {', '.join(outs)} (floatmoor "
                                  f"writes its own channels)")
        elif kind in _V2_ONLY_SECTIONS or kind.startswith("unknown:"):
            rows = [t for n, t in body if t.strip()]
            name = lines[title_line - 1].strip(" -\t")
            m.unmapped.append(f"section {name!r} (line {title_line}, {max(len(rows) - 2, 0)} "
                              f"entries): no floatmoor counterpart")
    return m


def _read_types(path, tab, version, m):
    for n, t in tab.rows:
        name = t[0]
        if name in m.types:
            raise SceneError(path, f"line {n}", "a unique line type name", name)
        f = [_num(path, n, c + 1, t[c]) if c not in (0, 3, 4) else None for c in range(len(t))]
        try:
            ea = float(t[3])
        except ValueError:
            raise SceneError(path, f"line {n}", "EA as a number (N) in column 4",
                             t[3], "a nonlinear EA table file has no floatmoor counterpart"
                             ) from None
        try:
            ba = float(t[4])
        except ValueError:
            raise SceneError(path, f"line {n}", "BA/-zeta as one number in column 5",
                             t[4], "a BA|BA_D pair (two damping values) has no floatmoor "
                             "counterpart") from None
        d, mass = f[1], f[2]
        for c, v, what in ((2, d, "Diam > 0 (m)"), (3, mass, "MassDen > 0 (kg/m)"),
                           (4, ea, "EA > 0 (N)")):
            if not v > 0:
                raise SceneError(path, f"line {n}", f"{what} in column {c}", t[c - 1])
        if version == 1:
            ca, caax, cd, cdax, ei = f[5], f[6], f[7], f[8], 0.0
        else:
            ei, cd, ca, cdax, caax = f[5], f[6], f[7], f[8], f[9]
            if len(t) > 10:
                m.unmapped.append(f"line type {name!r} (line {n}): the lift coefficient Cl"
                                  + (" and the VIV frequency range dF, cF" if len(t) > 11 else "")
                                  + " (no floatmoor counterpart)")
        for _c, v, what in ((6 if version == 1 else 7, cd, "Cd"), (0, ca, "Ca"),
                           (0, cdax, "CdAx"), (0, caax, "CaAx")):
            if v < 0:
                raise SceneError(path, f"line {n}", f"{what} >= 0", v)
        if ei:
            m.unmapped.append(f"line type {name!r} (line {n}): bending stiffness EI = {ei:g} "
                              f"N m^2 (floatmoor lines have no bending stiffness)")
        m.types[name] = ImpType(name=name, diameter=d, mass=mass, ea=ea, ba=ba, ei=ei, cd=cd,
                                ca=ca, cdax=cdax, caax=caax, line_no=n)


def _read_points(path, tab, version, m):
    for n, t in tab.rows:
        pid = t[0]
        if pid in m.points:
            raise SceneError(path, f"line {n}", "a unique point ID", pid)
        raw = t[1]
        kind = _POINT_KINDS.get(raw.upper())
        if kind is None:
            if re.match(r"(?i)^(body|turbine|rod)\d*", raw):
                kind = "attached:" + raw
            else:
                raise SceneError(path, f"line {n}", "a point attachment, one of: Fixed, "
                                 "Vessel, Coupled, Free (v1 also Connect)", raw)
        x, y, z, mass, vol = (_num(path, n, c + 1, t[c]) for c in range(2, 7))
        if version == 1:
            fx, fy, fz, cda, ca = (_num(path, n, c + 1, t[c]) for c in range(7, 12))
            if fx or fy or fz:
                m.unmapped.append(f"point {pid} (line {n}): external force FX, FY, FZ = "
                                  f"{fx:g}, {fy:g}, {fz:g} (no floatmoor counterpart)")
        else:
            cda, ca = (_num(path, n, c + 1, t[c]) for c in range(7, 9))
        if (cda or ca) and kind == "free":
            m.unmapped.append(f"point {pid} (line {n}): drag area CdA = {cda:g} m^2 and added "
                              f"mass coefficient CA = {ca:g} (floatmoor joints carry only "
                              f"their submerged weight)")
        if (mass or vol) and kind != "free":
            m.unmapped.append(f"point {pid} (line {n}): mass {mass:g} kg and volume {vol:g} m^3 "
                              f"of a {raw} point (they act on the anchor or vessel, not on "
                              f"the line)")
        m.points[pid] = ImpPoint(id=pid, kind=kind, xyz=(x, y, z), mass=mass, volume=vol,
                                 line_no=n)


def _read_lines_table(path, tab, version, m):
    ids = set()
    for n, t in tab.rows:
        if version == 1:
            lid, ltype, length, nseg, a, b = t[0], t[1], t[2], t[3], t[4], t[5]
            c_len, c_seg, c_a = 3, 4, 5
        else:
            lid, ltype, a, b, length, nseg = t[0], t[1], t[2], t[3], t[4], t[5]
            c_len, c_seg, c_a = 5, 6, 3
        if lid in ids:
            raise SceneError(path, f"line {n}", "a unique line ID", lid)
        ids.add(lid)
        if ltype not in m.types:
            raise SceneError(path, f"line {n}", "a line type name in column 2, one of: "
                             + ", ".join(m.types), ltype)
        for c, p in ((c_a, a), (c_a + 1, b)):
            if p not in m.points:
                raise SceneError(path, f"line {n}", f"a point ID in column {c}, one of: "
                                 + ", ".join(m.points), p)
        length = _num(path, n, c_len, length, "the unstretched length (m)")
        if not length > 0:
            raise SceneError(path, f"line {n}", f"an unstretched length > 0 m in column {c_len}",
                             length)
        try:
            if len(nseg) > 12:
                raise ValueError
            ns = int(nseg)
            if not 1 <= ns <= MAX_SEGMENTS:
                raise ValueError
        except ValueError:
            raise SceneError(path, f"line {n}", f"a number of segments from 1 to "
                             f"{MAX_SEGMENTS:,} in column {c_seg}", nseg) from None
        m.lines.append(ImpLine(id=lid, type=ltype, a=a, b=b, length=length, n_segments=ns,
                               line_no=n))
        if len(t) == len(_LAYOUT["lines", version]) and t[-1] not in ("-", "0"):
            m.unmapped.append(f"line {lid} (line {n}): output flags {t[-1]!r}")


_OPT_DEPTH = {"WTRDPTH", "DEPTH", "WTRDEPTH"}
_OPT_RHO = {"RHO", "RHOW", "WTRDNSTY", "WTRDENS"}
_OPT_G = {"G", "GRAVITY"}
_OPT_NOTE = {
    "DTM": "the time step of MoorDyn's explicit integrator (floatmoor's implicit FE lines set "
           "their own: finite_element.dt)",
    "DTIC": "dynamic-relaxation setting (floatmoor starts from the catenary statics)",
    "TMAXIC": "dynamic-relaxation setting (floatmoor starts from the catenary statics)",
    "CDSCALEIC": "dynamic-relaxation setting (floatmoor starts from the catenary statics)",
    "THRESHIC": "dynamic-relaxation setting (floatmoor starts from the catenary statics)",
    "ECHO": "echo flag", "WRITELOG": "log level", "DTOUT": "output interval",
}


def _read_options(path, body, m, version):
    for n, text in body:
        tok = text.split()
        if not tok or tok[0].startswith("#"):
            continue
        if len(tok) < 2:
            raise SceneError(path, f"line {n}", "an option as 'value name [- description]'",
                             text.strip())
        value, name = tok[0], tok[1]
        key = name.upper()
        if key in _OPT_DEPTH | _OPT_RHO | _OPT_G | {"KBOT", "CBOT", "FRICTIONCOEFFICIENT",
                                                     "MU_KT", "MU_KA"}:
            v = _num(path, n, 1, value, f"a number for option {name}")
            if key in _OPT_DEPTH:
                m.water_depth = v
            elif key in _OPT_RHO:
                m.water_density = v
            elif key in _OPT_G:
                m.gravity = v
            elif key == "KBOT":
                m.kbot = v
            elif key == "CBOT":
                m.cbot = v
            elif key == "FRICTIONCOEFFICIENT":
                m.mu_axial = m.mu_lateral = v
            elif key == "MU_KT":
                m.mu_lateral = v
            elif key == "MU_KA":
                m.mu_axial = v
        else:
            why = _OPT_NOTE.get(key, "no floatmoor counterpart")
            m.unmapped.append(f"option {name} = {value} (line {n}): {why}")


def read_model(path, *, water_depth=None, water_density=None, gravity=None,
               model: str = "quasi-static", warn: bool = True) -> MooringImport:
    """Read a MoorDyn v1/v2 file: the system, its ``mooring.yaml`` text and what was not mapped.

    ``water_depth``, ``water_density``, ``gravity`` override the file (OpenFAST passes its own);
    ``model`` is written as the mooring file's line model.  With ``warn`` one
    :class:`FloatmoorWarning` lists everything not mapped.
    """
    return build(parse(path), water_depth=water_depth, water_density=water_density,
                 gravity=gravity, model=model, warn=warn)


def read(path, **kw):
    """A MoorDyn v1/v2 input file as a :class:`~floatmoor.mooring.system.MooringSystem`; the FE
    options it implies are ``system.line_models.options``.  Keywords as :func:`read_model`."""
    return read_model(path, **kw).system


def _share(lengths, n_line, element_length):
    """Segments per MoorDyn line: ``n_line`` for the whole floatmoor line shared in proportion
    to the lengths (largest remainder, at least one each, as the FE lines do), else one per
    ``element_length``; ``n_line`` a sequence: the segments of each floatmoor segment
    (``finite_element.n_elements`` given per segment)."""
    if n_line is not None and not isinstance(n_line, (int, float)):
        return [int(v) for v in n_line]
    if n_line is None:
        return [max(1, round(L / element_length)) for L in lengths]
    total = sum(lengths)
    exact = [n_line * L / total for L in lengths]
    counts = [max(1, math.floor(e)) for e in exact]
    order = sorted(range(len(lengths)), key=lambda k: exact[k] - math.floor(exact[k]),
                   reverse=True)
    for k in order:
        if sum(counts) >= n_line:
            break
        counts[k] += 1
    return counts


def export(system, path=None, *, n_segments: int | None = None, dt: float = 0.001) -> str:
    """MoorDyn v2 input text of a :class:`MooringSystem` (written to ``path`` when given).

    Each segment is one MoorDyn line; the joints are free points at their static position at
    zero pose with the clump (M = P / g) or buoy (V = -P / (rho g)) of the segment's point load.
    The line type diameter is the volume-equivalent one (``sqrt(4 V / pi)``) so that MoorDyn's
    buoyancy equals floatmoor's submerged weight; drag is rescaled to keep the force per metre
    (``Cd = cdn d / d_v``, ``CdAx = cdt d / (pi d_v)``).  Fairleads are ``Coupled`` points in
    body axes (the body at zero pose).
    """
    rho, g = system.water_density, system.gravity
    opts = system.line_models.options if system.line_models is not None else None
    types = {}
    type_rows = []
    seg_type = {}
    for line in system.lines:
        for k, s in enumerate(line.segments):
            lt = system.line_types.get(s.line_type)
            m = s.mass_per_length
            vol = (m - s.w / g) / rho
            if vol < 0:
                raise SceneError(system.source, f"{line.name}.segments[{k}]", "a submerged "
                                 "weight below the weight in air", s.w)
            dv = math.sqrt(4.0 * vol / math.pi)
            if (lt is not None and abs(lt.submerged_weight(rho, g) - s.w) <= 1e-12 * abs(s.w)
                    and abs(math.pi * lt.diameter ** 2 / 4 - lt.displaced_volume)
                    <= 1e-12 * lt.displaced_volume):
                dv = lt.diameter  # the volume-equivalent diameter, without round-off
            cdn = lt.cdn if lt else 1.2
            cdt = lt.cdt if lt else 0.4
            can = lt.can if lt else 1.0
            cat = lt.cat if lt else 0.0
            dn = s.diameter or dv
            key = (s.line_type, round(dv, 12), m, s.ea)
            if key not in types:
                name = s.line_type or f"type{len(types) + 1}"
                if name in {t[0] for t in types.values()}:
                    name = f"{name}_{len(types) + 1}"
                ba = opts.internal_damping if opts is not None else -0.8
                types[key] = (name,)
                type_rows.append(f"{name:<16} {fmt(dv)} {fmt(m)} {fmt(s.ea)} {fmt(ba)} 0.0 "
                                 f"{fmt(cdn * dn / dv)} {fmt(can)} "
                                 f"{fmt(cdt * dn / (math.pi * dv))} {fmt(cat)}")
            seg_type[line.name, k] = types[key][0]
    pts, lns = [], []
    for line in system.lines:
        nseg = len(line.segments)
        ids = []
        ids.append(len(pts) + 1)
        pts.append(f"{ids[-1]} Fixed {fmt(line.anchor[0])} {fmt(line.anchor[1])} "
                   f"{fmt(line.anchor[2])} 0 0 0 0")
        if nseg > 1:
            prof = system.line_profile(line.name, n_per_segment=2)
            s_joint = [sum(seg.length for seg in line.segments[:k + 1]) for k in range(nseg - 1)]
            for k, sj in enumerate(s_joint):
                i = int(min(range(len(prof["s"])), key=lambda j: abs(prof["s"][j] - sj)))
                P = line.segments[k].point_load
                mass = P / g if P > 0 else 0.0
                vol = -P / (rho * g) if P < 0 else 0.0
                ids.append(len(pts) + 1)
                pts.append(f"{ids[-1]} Free {fmt(prof['x'][i])} {fmt(prof['y'][i])} "
                           f"{fmt(prof['z'][i])} {fmt(mass)} {fmt(vol)} 0 0")
        ids.append(len(pts) + 1)
        pts.append(f"{ids[-1]} Coupled {fmt(line.fairlead[0])} {fmt(line.fairlead[1])} "
                   f"{fmt(line.fairlead[2])} 0 0 0 0")
        n_line = n_segments if n_segments is not None else (
            opts.n_elements if opts is not None else None)
        counts = _share([s.length for s in line.segments], n_line,
                        opts.element_length if opts is not None else 20.0)
        for k, (s, ns) in enumerate(zip(line.segments, counts)):
            lns.append(f"{len(lns) + 1} {seg_type[line.name, k]} {ids[k]} {ids[k + 1]} "
                       f"{fmt(s.length)} {ns} -")
    seabed = opts.seabed_for(system.water_depth) if opts is not None else None
    dmax = max(float(v) for v in [r.split()[1] for r in type_rows])
    kbot = seabed.stiffness / dmax if seabed is not None else 3.0e6
    cbot = seabed.damping / dmax if seabed is not None else 3.0e5
    cb = max(system.cb) if len(system.cb) else 0.0
    out = ["--------------------- MoorDyn Input File ------------------------------------",
           f"Exported by floatmoor from {Path(system.source).name or 'a mooring system'}",
           "----------------------- LINE TYPES ------------------------------------------",
           "Name Diam MassDen EA BA/-zeta EI Cd Ca CdAx CaAx",
           "(-) (m) (kg/m) (N) (N-s/-) (N-m^2) (-) (-) (-) (-)", *type_rows,
           "---------------------- POINTS ------------------------------------------------",
           "ID Attachment X Y Z M V CdA CA",
           "(-) (-) (m) (m) (m) (kg) (m^3) (m^2) (-)", *pts,
           "---------------------- LINES -------------------------------------------------",
           "ID LineType AttachA AttachB UnstrLen NumSegs Outputs",
           "(-) (-) (-) (-) (m) (-) (-)", *lns,
           "---------------------- OPTIONS -----------------------------------------------",
           f"{fmt(dt)} dtM - time step of the mooring integration (s)",
           f"{fmt(system.water_depth)} WtrDpth - water depth (m)",
           f"{fmt(rho)} WtrDnsty - water density (kg/m^3)",
           f"{fmt(g)} gravity - gravity (m/s^2)",
           f"{fmt(kbot)} kBot - seabed stiffness (Pa/m)",
           f"{fmt(cbot)} cBot - seabed damping (Pa-s/m)"]
    if cb > 0:
        out.append(f"{fmt(cb)} FrictionCoefficient - seabed friction coefficient (-)")
    out += ["----------------------- OUTPUTS ----------------------------------------------",
            "------------------------- need this line ------------------------------------"]
    text = "\n".join(out) + "\n"
    if path is not None:
        Path(path).write_text(text)
    return text

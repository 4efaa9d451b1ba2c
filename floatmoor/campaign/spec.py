"""Campaign files: a DNV-OS-E301 design campaign over sea states, headings and conditions.

```yaml
name: floatel-uls-als
description: free text
base_scene: ../scenes/floatel_100yr.yaml   # vessel, mooring, site, environment components
sea_states:                                # one of: contour (a file with sea_states:) or list
                                           # (a scatter diagram or a probability: SceneError,
                                           # see ULS_SEA_STATES; scatters are for fatigue)
  contour: ../metocean/heidrun_contour.yaml
  only: [1, 4]                             # optional: 1-based indices into the contour
  # list: [{name: peak, hs: 16.0, tp: 18.2, gamma: null}]
  # a sea state of several wave systems (wind sea and swell), turned with the case's wave
  # heading; each system as a scene's (floatmoor.io.environment.parse_wave_systems) with
  # heading_offset_deg from the wave heading instead of heading_deg, JONSWAP by default:
  # list: [{name: sea+swell, systems: [{hs: 14.0, tp: 16.0},
  #                                    {hs: 4.0, tp: 22.0, gamma: 5.0, heading_offset_deg: 30}]}]
headings:
  waves_deg: {start: 0, stop: 345, step: 15}   # or a list [0, 15, 30]
  wind_offset_deg: [0]                     # wind heading - wave heading (non-collinear: [0, 30])
  current_offset_deg: [0]
conditions:
  intact: true
  failed_lines: all                        # all single-line failures, or [[line6], [line6, line7]]
  line_failure: {lines: [line6], time: 1500.0}   # transient ALS: break at t (s), in the
                                           # statistics window (>= transient); lines: all too
seeds: "1-20"                              # as analysis.seeds of a scene
analysis: {duration: 12000.0, dt: 0.1, transient: 1200.0, ramp: 100.0}   # optional overrides
screening:
  time_domain: screened                    # screened | all | none
  within_percent: 10.0                     # TD for cases within X % of a line's governing FD
  top_per_line: 3                          #   utilisation, and at least the top N per line
design: {standard: dnv-os-e301-2008, consequence_class: 2, analysis: auto}
                                           # a code of floatmoor/data/codes (or a code file);
                                           # auto: the factors follow the line model
storage:
  mode: full                               # full | statistics (series only for governing cases)
  precision: float32                       # float32 | float64 of the stored series
  compression: 4                           # zlib level 0-9 (0: none), with shuffle
  sampling: {line_tension: 0.1, motion: 0.5, wave_elevation: 0.5}   # s; variables kept
```

Every mistake is a :class:`~floatmoor.core.errors.SceneError` naming the file, the key, what
was expected and what was found, raised before anything runs.  Refused as in scene files:
angles that look like radians (0.7854, 3.1416, a range to 6.2832), a sea state that cannot
exist (Hs/Lp above 1/10 in the base scene's depth: :func:`floatmoor.io.environment.
check_sea_state`; steeper than 1/15 warned), a time step above the Nyquist limit of a sea
state's highest wave component.  Refused because results would overwrite or duplicate each
other: the same direction twice (0 and 360 deg, or closer than 0.001 deg), the same sea state
or the same condition twice (also ``[line6, line7]`` and ``[line7, line6]``); case identifiers
are unique by construction (:func:`floatmoor.campaign.matrix.build_matrix`).  Sizes are checked
before anything is built: at most :data:`MAX_ANGLES` values per heading list,
:data:`MAX_CASES` cases, :data:`MAX_STORMS` storms.  The base scene is read, built and checked
for plausibility (vessel mass, stability, lines at zero offset) when the campaign is read; time
settings given on the command line (``--duration``) are checked with the base scene's
transient and the line breaks (:func:`check_times`).  Headings are the direction of travel (from +x towards +y), as
in scenes; the environment components present in the base scene are turned, the others stay
absent.  The FD screening of every case uses the base scene's ``frequency_domain:`` section
(e.g. ``tension_model: dynamic``, or ``line_current_drag: true`` for the static current drag on
the lines in the mean position, about 0.2 s more per case for the Floatel-like lines:
benchmarks/RESULTS.md); each FD file records ``fd_tension_model``, ``fd_line_current_drag``
and ``fd_line_damping``.
"""

from __future__ import annotations

import dataclasses
import math
import os
from dataclasses import dataclass, field
from pathlib import Path

from ..core.config import Node
from ..core.errors import SceneError

__all__ = [
    "STORAGE_VARIABLES",
    "CampaignSpec",
    "Condition",
    "Design",
    "Screening",
    "SeaState",
    "Storage",
    "load_campaign",
]

KEYS = ("name", "description", "base_scene", "sea_states", "headings", "conditions", "seeds",
        "analysis", "screening", "design", "storage")
STORAGE_VARIABLES = ("line_tension", "anchor_tension", "motion", "velocity", "wave_elevation")
"""Time series a result file may keep (``storage.sampling`` keys)."""
DEFAULT_SAMPLING = {"line_tension": 0.0, "motion": 0.5, "wave_elevation": 0.5}
"""Default kept series and their output interval (s; 0: every time step)."""


@dataclass(frozen=True, kw_only=True)
class SeaState:
    """One short-term sea state: name, Hs (m), Tp (s), JONSWAP gamma (None: DNV rule).  With
    ``systems`` (:class:`~floatmoor.metocean.config.WaveSpec` each, headings relative to the
    case's wave heading, names ``system_names``) a sea of several wave systems: ``hs`` is then
    the whole sea's sqrt(sum Hs_i^2) and ``tp`` the Tp of the system with the largest Hs."""
    name: str
    hs: float
    tp: float
    gamma: float | None = None
    systems: tuple = ()
    system_names: tuple = ()


@dataclass(frozen=True, kw_only=True)
class Condition:
    """A mooring condition: ``intact``, lines removed from the start (ALS) or a line breaking
    at ``break_time`` (transient ALS)."""
    kind: str                       # intact | failed | transient
    lines: tuple[str, ...] = ()
    break_time: float | None = None
    fibre_bound: str = ""           # lower | upper: fibre-rope stiffness bound ("": the scene's)

    @property
    def name(self) -> str:
        tag = f"_fibre-{self.fibre_bound}" if self.fibre_bound else ""
        if self.kind == "intact":
            return "intact" + tag
        if self.kind == "failed":
            return "failed-" + "+".join(self.lines) + tag
        return f"break-{'+'.join(self.lines)}-t{self.break_time:g}" + tag

    @property
    def limit_state(self) -> str:
        return "ULS" if self.kind == "intact" else "ALS"


@dataclass(frozen=True, kw_only=True)
class Screening:
    """FD screening rule: ``time_domain`` screened | all | none; ``within_percent`` and
    ``top_per_line`` (see the module docstring)."""
    time_domain: str = "screened"
    within_percent: float = 10.0
    top_per_line: int = 3


@dataclass(frozen=True, kw_only=True)
class Design:
    """The design code (a key of :mod:`floatmoor.post.design_codes`, or a code file), the
    consequence class and the analysis type: ``auto`` follows the line model (finite-element
    lines dynamic, quasi-static lines quasi-static), ``dynamic`` or ``quasi-static`` override
    it."""
    standard: str = "dnv-os-e301-2008"
    consequence_class: int = 2
    analysis: str = "auto"


@dataclass(frozen=True, kw_only=True)
class Storage:
    """How storm results are stored: ``mode`` full | statistics, ``precision`` of the series,
    zlib ``compression`` level (0: none), ``sampling`` {variable: output interval in s}."""
    mode: str = "full"
    precision: str = "float32"
    compression: int = 4
    sampling: tuple = tuple(DEFAULT_SAMPLING.items())
    sampling_given: bool = field(default=False, compare=False)  # else intervals are rounded

    @property
    def sampling_dict(self) -> dict:
        return dict(self.sampling)


@dataclass(frozen=True, kw_only=True)
class CampaignSpec:
    """A validated campaign file (build it with :func:`load_campaign`)."""
    name: str
    description: str = ""
    file: Path | None = field(default=None, compare=False)
    base_scene: Path
    sea_states: tuple[SeaState, ...]
    wave_headings_deg: tuple[float, ...]
    wind_offsets_deg: tuple[float, ...] = (0.0,)
    current_offsets_deg: tuple[float, ...] = (0.0,)
    conditions: tuple[Condition, ...]
    seeds: tuple[int, ...]
    analysis: tuple = ()            # (key, value) overrides of the base scene's analysis
    screening: Screening = field(default_factory=Screening)
    design: Design = field(default_factory=Design)
    storage: Storage = field(default_factory=Storage)


MAX_ANGLES = 3600
"""Most values of one heading list or range (a heading every 0.1 deg); checked before the
range is built."""

ANGLE_RESOLUTION = 1e-3
"""Two headings (or offsets) closer than this (deg, modulo 360) are the same direction."""


def _angles(node: Node, key: str, default=None) -> tuple[float, ...]:
    """A list of angles in degrees or a range ``{start, stop, step}``: each in [-360, 360],
    at most :data:`MAX_ANGLES`, distinct directions (modulo 360 deg: 0 and 360 are one
    direction), not radians (the rule of scene files, :func:`~floatmoor.core.config.
    radians_list_hint`)."""
    from ..core.config import looks_like_radians, radians_list_hint
    if key not in node:
        if default is None:
            raise node.error(key, "a list of angles in degrees or {start, stop, step}")
        return default
    value = node.raw(key)
    if isinstance(value, dict):
        r = node.child(key)
        r.reject_unknown(("start", "stop", "step"))
        start = r._check_number("start", r.raw("start", 0.0), None, -360, None, 360, "deg")
        stop = r._check_number("stop", r.raw("stop", expected="a number in deg"), None, -360,
                               None, 360, "deg")
        step = r.float("step", gt=0.0, unit="deg")
        if stop < start:
            raise r.error("stop", f"an angle >= start ({start:g} deg)", stop)
        n = math.floor((stop - start) / step + 1e-9) + 1
        if n > MAX_ANGLES:
            raise r.error("step", f"a step giving at most {MAX_ANGLES} angles (at least "
                          f"{(stop - start) / (MAX_ANGLES - 1):.3g} deg from {start:g} to "
                          f"{stop:g} deg)", step, f"{n:,} angles")
        vals = [start + i * step for i in range(n)]
        for name, v in (("step", step), ("stop", stop), ("start", start)):
            if looks_like_radians(v):
                raise r.error(name, "angles in degrees", v, f"{v:g} looks like an angle in "
                              f"radians ({math.degrees(v):.6g} deg); give the range in degrees")
    elif isinstance(value, list) and value:
        if len(value) > MAX_ANGLES:
            raise node.error(key, f"at most {MAX_ANGLES} angles", f"a list of {len(value)}")
        vals = []
        for i, v in enumerate(value):
            if isinstance(v, bool) or not isinstance(v, (int, float)) or not -360 <= v <= 360:
                raise SceneError(node.file, f"{node.key(key)}[{i}]", "an angle in degrees in "
                                 "[-360, 360]", v)
            vals.append(float(v))
    else:
        raise node.error(key, "a non-empty list of angles in degrees or {start, stop, step}",
                         value)
    hint = radians_list_hint(vals)
    if hint:
        raise node.error(key, "angles in degrees", value, hint)
    seen: dict[float, float] = {}
    for v in vals:
        d = round((v % 360.0) / ANGLE_RESOLUTION) * ANGLE_RESOLUTION % 360.0
        if d in seen:
            raise node.error(key, "distinct directions (angles modulo 360 deg)", value,
                             f"{seen[d]:g} and {v:g} deg are the same direction")
        seen[d] = v
    return tuple(float(v) for v in vals)


ULS_SEA_STATES = ("the N-year extreme sea states of a ULS/ALS check (DNV (2008)): "
                  "contour: a file of Hs-Tp contour points (sea_states: [{name, hs, tp, "
                  "gamma}]), or list: the design sea states")
NOT_FATIGUE = ("every sea state of a ULS/ALS campaign is checked at its own extreme and the "
               "worst governs: probabilities weight nothing there.  A long-term scatter "
               "diagram is the input of the fatigue limit state: floatmoor fatigue SCENE.yaml "
               "--scatter FILE")


def _sea_state(item: Node, default_name: str, water_depth: float | None = None,
               gravity: float = 9.80665) -> SeaState:
    """One sea state of a contour or list: Hs, Tp > 0, JONSWAP gamma >= 1 (null: the DNV rule),
    a sea state that can exist (:func:`~floatmoor.io.environment.check_sea_state`, the rule of
    scene files, in the base scene's water depth)."""
    from ..io.environment import check_sea_state
    item.reject_unknown(("name", "hs", "tp", "gamma", "spectrum", "probability", "description",
                         "systems"))
    if "probability" in item:
        raise item.error("probability", "no probability: " + ULS_SEA_STATES,
                         item.raw("probability"), NOT_FATIGUE)
    if "systems" in item:
        return _sea_state_systems(item, default_name, water_depth, gravity)
    if "spectrum" in item and item.raw("spectrum") != "jonswap":
        raise item.error("spectrum", "jonswap (the contour's sea states are JONSWAP)",
                         item.raw("spectrum"))
    gamma = item.float("gamma", None, ge=1.0, allow_none=True)
    if gamma is not None and gamma > 7.0:
        import warnings

        from ..core.errors import FloatmoorWarning
        warnings.warn(f"{item.file}: {item.key('gamma')}: gamma = {gamma:g} is outside the "
                      "range 1-7 of measured seas", FloatmoorWarning, stacklevel=3)
    hs = item.float("hs", gt=0.0, unit="m")
    tp = item.float("tp", gt=0.0, unit="s")
    check_sea_state(item.file, item.key("hs"), hs, tp, water_depth=water_depth, gravity=gravity,
                    stacklevel=4)
    return SeaState(name=item.str("name", default_name), hs=hs, tp=tp, gamma=gamma)


def _sea_state_systems(item: Node, default_name: str, water_depth: float | None = None,
                       gravity: float = 9.80665) -> SeaState:
    """A sea state of several wave systems (``systems:``, module docstring), each checked as a
    sea state that can exist in the base scene's depth."""
    from ..io.environment import MAX_WAVE_SYSTEMS, SYSTEM_KEYS, _system_fields
    from ..metocean.config import WaveSpec, total_hs
    for key in ("hs", "tp", "gamma", "spectrum"):
        if key in item:
            raise item.error(key, "no " + key + " beside systems (each system has its own)",
                             item.raw(key))
    nodes = item.item_nodes("systems", min_len=1)
    if len(nodes) > MAX_WAVE_SYSTEMS:
        raise item.error("systems", f"at most {MAX_WAVE_SYSTEMS} wave systems",
                         f"{len(nodes)} systems")
    allowed = tuple(k for k in SYSTEM_KEYS if k != "heading_deg") + ("heading_offset_deg",)
    systems, names = [], []
    for i, n in enumerate(nodes):
        n.reject_unknown(allowed)
        names.append(n.str("name", f"system{i + 1}"))
        systems.append(WaveSpec(**_system_fields(n, water_depth=water_depth, gravity=gravity,
                                                 heading_key="heading_offset_deg",
                                                 spectrum="jonswap")))
    if len(set(names)) != len(names):
        raise item.error("systems", "wave systems with distinct names", names)
    dominant = max(systems, key=lambda s: s.hs)
    return SeaState(name=item.str("name", default_name), hs=total_hs(
        _systems(systems)), tp=dominant.tp, gamma=None, systems=tuple(systems),
        system_names=tuple(names))


def _systems(systems):
    from ..metocean.config import WaveSystems
    return WaveSystems(systems=tuple(systems))


def _sea_states(node: Node, water_depth: float | None = None,
                gravity: float = 9.80665) -> tuple[SeaState, ...]:
    s = node.child("sea_states")
    s.reject_unknown(("contour", "scatter", "list", "only"))
    given = [k for k in ("contour", "scatter", "list") if k in s]
    if len(given) != 1:
        raise s.error("", "exactly one of contour, scatter, list", given or "none")
    key = given[0]
    if key == "scatter":
        raise s.error("scatter", ULS_SEA_STATES, s.raw("scatter"), NOT_FATIGUE)
    if key == "list":
        items = s.item_nodes("list", min_len=1)
    else:
        f = s.child_or_file(key)
        f.reject_unknown(("name", "description", "sea_states"))
        items = f.item_nodes("sea_states", min_len=1)
    states = [_sea_state(it, f"ss{i + 1}", water_depth, gravity) for i, it in enumerate(items)]
    if "only" in s:
        only = s.list("only", min_len=1)
        for i, k in enumerate(only):
            if isinstance(k, bool) or not isinstance(k, int) or not 1 <= k <= len(states):
                raise SceneError(s.file, f"{s.key('only')}[{i}]",
                                 f"a sea state number 1..{len(states)}", k)
        states = [states[k - 1] for k in only]
    names = [st.name for st in states]
    if len(set(names)) != len(names):
        raise s.error(key, "sea states with distinct names", names)
    if "only" in s and len(set(only)) != len(only):
        raise s.error("only", "distinct sea state numbers (a sea state listed twice would be "
                      "run twice)", only)
    seen: dict[tuple, str] = {}
    for st in states:
        k = (st.hs, st.tp, st.gamma)
        if k in seen:
            raise s.error(key, "distinct sea states (Hs, Tp, gamma)", f"{seen[k]} and "
                          f"{st.name}: Hs {st.hs:g} m, Tp {st.tp:g} s",
                          "the same sea state twice would be run and reported twice")
        seen[k] = st.name
    return tuple(states)


def _line_sets(node: Node, key: str, lines: list[str]) -> list[tuple[str, ...]]:
    value = node.raw(key)
    if value == "all":
        return [(ln,) for ln in lines]
    if not isinstance(value, list) or not value:
        raise node.error(key, "'all' or a non-empty list of line sets, e.g. [[line6], "
                         "[line6, line7]]", value)
    out = []
    seen: dict[frozenset, int] = {}
    for i, item in enumerate(value):
        item = [item] if isinstance(item, str) else item
        if not isinstance(item, list) or not item or any(x not in lines for x in item):
            raise SceneError(node.file, f"{node.key(key)}[{i}]",
                             "a list of line names among " + ", ".join(lines), item)
        if len(set(item)) != len(item):
            raise SceneError(node.file, f"{node.key(key)}[{i}]", "distinct line names", item)
        if len(set(item)) >= len(lines):
            raise SceneError(node.file, f"{node.key(key)}[{i}]", "some lines left intact "
                             "(nothing would hold the floater)", item)
        k = frozenset(item)
        if k in seen:
            raise SceneError(node.file, f"{node.key(key)}[{i}]", "a condition not listed "
                             "before (each would be run and reported twice)", item,
                             f"the same lines as {node.key(key)}[{seen[k]}]")
        seen[k] = i
        out.append(tuple(str(x) for x in item))
    return out


def _conditions(node: Node, lines: list[str]) -> tuple[Condition, ...]:
    c = node.child("conditions")
    c.reject_unknown(("intact", "failed_lines", "line_failure"))
    out = []
    if c.bool("intact", True):
        out.append(Condition(kind="intact"))
    if "failed_lines" in c:
        out += [Condition(kind="failed", lines=s) for s in _line_sets(c, "failed_lines", lines)]
    if "line_failure" in c:
        lf = c.child("line_failure")
        lf.reject_unknown(("lines", "time"))
        t = lf.float("time", ge=0.0, unit="s")
        for s in _line_sets(lf, "lines", lines):
            out.append(Condition(kind="transient", lines=s, break_time=t))
    if not out:
        raise c.error("", "at least one condition (intact: true, failed_lines or line_failure)",
                      "none")
    return tuple(out)


def _fibre_conditions(conditions, scene) -> tuple[Condition, ...]:
    """A base scene with ``analysis.fibre_stiffness: both`` and fibre ropes: every condition
    twice, at the lower and at the upper stiffness bound (the report then takes the governing
    case of either, and shows both)."""
    if scene.analysis.fibre_stiffness != "both":
        return conditions
    from ..io.mooring_section import parse_mooring
    site = scene.site
    ms = parse_mooring(scene.mooring_node(), water_depth=site.water_depth,
                       water_density=site.water_density, gravity=site.gravity)
    if not ms.has_fibre:
        return conditions
    return tuple(dataclasses.replace(c, fibre_bound=b) for c in conditions
                 for b in scene.analysis.fibre_bounds)


def _storage(node: Node) -> Storage:
    if "storage" not in node:
        return Storage()
    s = node.child("storage")
    s.reject_unknown(("mode", "precision", "compression", "sampling"))
    sampling = DEFAULT_SAMPLING
    if "sampling" in s:
        sm = s.child("sampling")
        sm.reject_unknown(STORAGE_VARIABLES)
        sampling = {k: sm.float(k, ge=0.0, unit="s") for k in sm.data}
    return Storage(mode=s.str("mode", "full", choices=("full", "statistics")),
                   precision=s.str("precision", "float32", choices=("float32", "float64")),
                   compression=s.int("compression", 4, ge=0, le=9),
                   sampling=tuple(sampling.items()), sampling_given="sampling" in s)


def _code(d: Node) -> str:
    """``design.standard``: a design code key or alias, or a code file relative to the
    campaign file; the code's key (or the file's path)."""
    from ..post.design_codes import load_code
    raw = d.str("standard", "dnv-os-e301-2008")
    path = d.base_dir / raw
    is_file = path.suffix in (".yaml", ".yml") and path.is_file()
    try:
        code = load_code(path if is_file else raw)
    except SceneError as exc:
        raise d.error("standard", exc.expected, raw) from None
    return str(path) if is_file else code.key


def _analysis(node: Node) -> tuple:
    if "analysis" not in node:
        return ()
    a = node.child("analysis")
    a.reject_unknown(("duration", "dt", "transient", "ramp"))
    out = []
    for k in ("duration", "dt", "transient", "ramp"):
        if k in a:
            out.append((k, a.float(k, gt=0.0, unit="s") if k in ("duration", "dt")
                        else a.float(k, ge=0.0, unit="s")))
    return tuple(out)


MAX_CASES = 50_000
"""Most cases of a campaign matrix (sea states x headings x wind offsets x current offsets x
conditions), checked before the matrix is built: each case is one frequency-domain analysis
(about 0.3 s) and a row of ``campaign.json`` and the manifest (the example campaign has
2,184)."""

MAX_STORMS = 1_000_000
"""Most time-domain storms (TD cases x seeds) of a campaign, checked before their task list is
built (with ``time_domain: all`` when the file is read, else after the screening)."""


def check_storm_count(spec: CampaignSpec, n_td_cases: int, n_seeds: int, what: str) -> None:
    """SceneError when ``n_td_cases x n_seeds`` exceeds :data:`MAX_STORMS`."""
    n = n_td_cases * n_seeds
    if n > MAX_STORMS:
        raise SceneError(spec.file, "seeds", f"at most {MAX_STORMS:,} time-domain storms "
                         "(TD cases x seeds)", f"{n_td_cases:,} {what} x {n_seeds} seeds = "
                         f"{n:,} storms", "a 3-hour storm takes seconds to minutes of a core; "
                         "split the campaign or screen more cases out")


def load_campaign(path: str | os.PathLike) -> CampaignSpec:
    """Read and validate a campaign file (and its base scene).  Refused before anything runs,
    each naming the file and key: the mistakes of the file and of the base scene (read, built
    and checked for plausibility), radians or repeated directions, a repeated sea state or
    condition, a sea state that cannot exist (the steepness rule of scene files), a matrix
    above :data:`MAX_CASES` cases, a time step that cannot resolve a sea state, a line break
    outside the statistics window."""
    from ..io.analysis import parse_seeds
    from ..io.scene import load_scene

    node = Node.load(path)
    node.reject_unknown(KEYS)
    base = node.path_value("base_scene")
    if base.is_dir():
        raise node.error("base_scene", "a scene file, not a folder", node.raw("base_scene"),
                         f"{base} is a folder")
    scene = load_scene(base)
    mnode = scene.mooring_node()
    if mnode is None:
        raise node.error("base_scene", "a scene with a mooring", str(base))
    lines = [str(ln.raw("name")) for ln in mnode.item_nodes("lines")]
    h = node.child("headings")
    h.reject_unknown(("waves_deg", "wind_offset_deg", "current_offset_deg"))
    seeds = parse_seeds(node, "seeds")
    sc = node.child("screening", None)
    screening = Screening()
    if sc is not None:
        sc.reject_unknown(("time_domain", "within_percent", "top_per_line"))
        screening = Screening(time_domain=sc.str("time_domain", "screened",
                                                 choices=("screened", "all", "none")),
                              within_percent=sc.float("within_percent", 10.0, ge=0.0, le=100.0,
                                                      unit="%"),
                              top_per_line=sc.int("top_per_line", 3, ge=0))
    d = node.child("design", None)
    design = Design()
    if d is not None:
        d.reject_unknown(("standard", "consequence_class", "analysis"))
        design = Design(standard=_code(d), consequence_class=d.int("consequence_class", 2,
                                                                    ge=1, le=2),
                        analysis=d.str("analysis", "auto", choices=("auto", "dynamic",
                                                                     "quasi-static")))
    site = scene.site
    sea_states = _sea_states(node, site.water_depth, site.gravity)
    waves = _angles(h, "waves_deg")
    wind = _angles(h, "wind_offset_deg", (0.0,))
    current = _angles(h, "current_offset_deg", (0.0,))
    conditions = _fibre_conditions(_conditions(node, lines), scene)
    sizes = (len(sea_states), len(waves), len(wind), len(current), len(conditions))
    n_cases = math.prod(sizes)
    if n_cases > MAX_CASES:
        raise node.error("headings", f"a matrix of at most {MAX_CASES:,} cases (sea states x "
                         "wave headings x wind offsets x current offsets x conditions)",
                         " x ".join(str(n) for n in sizes) + f" = {n_cases:,} cases",
                         "each case is one frequency-domain analysis and a row of the "
                         "manifest; split the campaign")
    spec = CampaignSpec(
        name=node.str("name", Path(path).stem), description=node.str("description", ""),
        file=node.file, base_scene=base, sea_states=sea_states,
        wave_headings_deg=waves, wind_offsets_deg=wind, current_offsets_deg=current,
        conditions=conditions, seeds=tuple(seeds), analysis=_analysis(node),
        screening=screening, design=design, storage=_storage(node))
    check_times(spec, scene)
    if spec.screening.time_domain == "all":
        check_storm_count(spec, n_cases, len(spec.seeds), "cases (time_domain: all)")
    _require_mbs(scene)
    _check_base(scene)
    return spec


def _check_base(scene) -> None:
    """The base scene built and checked for plausibility (vessel mass, stability, depth, the
    lines at zero offset) before any case runs: a mistake there would otherwise fail every
    case in its worker."""
    import warnings

    from ..io.build import build
    from ..io.plausibility import check_built
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # the base scene's warnings were shown when it was read
        check_built(build(scene))


def _require_mbs(scene) -> None:
    """The campaign screens and reports DNV-OS-E301 utilisations: refuse, before any case runs,
    a mooring whose line types have no MBS (``mbs: unknown``, e.g. imported)."""
    from ..io.mooring_section import parse_mooring
    site = scene.site
    parse_mooring(scene.mooring_node(), water_depth=site.water_depth,
                  water_density=site.water_density, gravity=site.gravity,
                  check=False).require_mbs("the campaign's DNV-OS-E301 screening and report")


def check_times(spec: CampaignSpec, scene, overrides: dict | None = None) -> dict:
    """The storms' time settings (duration, dt, transient, ramp: the base scene's, the
    campaign file's ``analysis``, then ``overrides`` such as ``--duration``), checked before
    anything runs: dt < duration, at most :data:`~floatmoor.io.analysis.MAX_TIME_STEPS` steps,
    a dt that resolves every sea state of the campaign, a duration longer than the transient,
    every line break inside the simulated statistics window, storage intervals multiples of dt.
    Each refusal names the campaign file and the key or option that set the value.  Returns
    the settings."""
    from ..io.analysis import check_time_steps
    from ..io.checks import check_dt_resolves_waves
    base = {"duration": scene.analysis.duration, "dt": scene.analysis.dt,
            "transient": scene.analysis.transient, "ramp": scene.analysis.ramp}
    own = dict(spec.analysis)
    given = {k for k, v in (overrides or {}).items() if v is not None}
    an = {**base, **own, **{k: float(v) for k, v in (overrides or {}).items()
                            if v is not None and k in base}}

    def key(k):
        if k in given:
            return f"--{k}"
        if k in own:
            return f"analysis.{k}"
        return f"analysis.{k} (of the base scene {spec.base_scene})"

    file = spec.file
    if not an["dt"] < an["duration"]:
        raise SceneError(file, key("dt"), f"0 < dt < duration ({an['duration']:g} s)", an["dt"])
    if "duration" in given and "dt" not in given:   # the value given names the mistake
        from ..io.analysis import MAX_TIME_STEPS
        if an["duration"] / an["dt"] > MAX_TIME_STEPS:
            raise SceneError(file, key("duration"), f"a duration of at most {MAX_TIME_STEPS:,} "
                             f"time steps of {an['dt']:g} s ({key('dt')})", an["duration"])
    check_time_steps(file, an["duration"], an["dt"], key=key("dt"))
    if not an["duration"] > an["transient"]:
        raise SceneError(file, key("duration"), f"a duration longer than the transient "
                         f"({an['transient']:g} s, {key('transient')}): the statistics window "
                         "after the transient would be empty", an["duration"])
    if not an["ramp"] < an["duration"]:
        raise SceneError(file, key("ramp"), f"a ramp shorter than the duration "
                         f"({an['duration']:g} s)", an["ramp"])
    waves = scene.environment.waves
    if waves is not None:
        import dataclasses
        for i, ss in enumerate(spec.sea_states):
            w = dataclasses.replace(waves, hs=ss.hs, tp=ss.tp, gamma=ss.gamma)
            check_dt_resolves_waves(file, key("dt"), an["dt"], w,
                                    where=f" (sea state {i + 1}, {ss.name})")
    for c in spec.conditions:
        if c.kind == "transient" and not an["transient"] <= c.break_time < an["duration"]:
            # a break before the statistics window starts would leave the transient response
            # after the break out of the maxima (the case would be checked as a failed line);
            # a break after the end of the storm never happens: the case would be stored as
            # an ALS case of an intact mooring
            raise SceneError(file, "conditions.line_failure.time", f"a time in the "
                             f"statistics window, from the transient ({an['transient']:g} s, "
                             f"{key('transient')}) to before the duration "
                             f"({an['duration']:g} s, {key('duration')})", c.break_time,
                             "the line would never break in the simulated storm"
                             if c.break_time >= an["duration"] else None)
    for k, dt_out in spec.storage.sampling:
        ratio = dt_out / an["dt"]
        if spec.storage.sampling_given and dt_out > 0 and abs(ratio - round(ratio)) > 1e-9:
            raise SceneError(file, f"storage.sampling.{k}", f"0 or a multiple of dt "
                             f"({an['dt']:g} s, {key('dt')})", dt_out)
    if len(spec.seeds) < 3 and spec.screening.time_domain != "none":
        raise SceneError(file, "seeds", "at least 3 seeds (a Gumbel fit per case)",
                         list(spec.seeds))
    return an

"""Scene files: one YAML file describing one analysis, read into a frozen :class:`Scene`.

```yaml
name: floatel-like-100yr-head-seas
description: optional free text
site: {water_depth: 150.0, water_density: 1025.0}   # gravity, air_density optional
vessel: ../vessels/floatel_like/vessel.yaml          # relative to this file; must exist (or
                                                     # the folder holding vessel.yaml)
environment: ../metocean/heidrun_100yr.yaml          # a file, or the same mapping inline
mooring: ../vessels/floatel_like/mooring.yaml        # a file, or a mapping inline
analysis: {duration: 10800.0, dt: 0.1, transient: 1200.0, ramp: 100.0, seeds: [1, 20]}
```

Required: ``site`` (with ``water_depth``).  Optional: ``name`` (default: the file name without
extension), ``description``, ``vessel``, ``environment`` (absent: calm, no wind, no current),
``mooring``, ``analysis`` (defaults in :mod:`floatmoor.io.analysis`), ``forces`` (options of the
time-domain force models, :mod:`floatmoor.io.forces_section`), ``frequency_domain`` (options of
the frequency-domain analysis, :mod:`floatmoor.io.fd_section`), ``solver`` (opt-in faster
approximations of the time loop, :mod:`floatmoor.io.solver_section`), ``limits`` (offset limits
and named points on the body for the design checks of ``floatmoor report``; they change no
analysis, :mod:`floatmoor.io.limits_section`).  Paths are relative to the
scene file's folder.  Unknown keys are refused everywhere.  The section formats are documented
in :mod:`floatmoor.io.site`, :mod:`floatmoor.io.environment`, :mod:`floatmoor.io.analysis`.

Adding a section (``forces:``, ``frequency_domain:``, ``post:``, ...)
--------------------------------------------------------------------
Write ``parse_x(scene_node, key, parsed) -> XSpec`` (and optionally ``describe`` and ``models``
functions) in a sibling module, add a field ``x: XSpec | None = None`` to :class:`Scene` and one
:class:`Section` entry to :data:`SECTIONS` below.  The allowed top-level keys, the parsing order,
``Scene.describe()`` and ``Scene.active_models()`` all follow from :data:`SECTIONS`.  Checks
that involve several sections go in :data:`floatmoor.io.checks.SCENE_CHECKS`.
"""

from __future__ import annotations

import os
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import TYPE_CHECKING, Any

from ..core.config import Node
from ..metocean.config import Environment
from .analysis import AnalysisSpec, describe_analysis, parse_analysis
from .checks import SCENE_CHECKS
from .environment import describe_environment, environment_models, parse_environment
from .forces_section import ForcesSpec, describe_forces, parse_forces
from .limits_section import LimitsSpec, describe_limits, parse_limits
from .site import SiteSpec, parse_site
from .solver_section import SolverSpec, describe_solver, parse_solver

if TYPE_CHECKING:  # pragma: no cover
    from ..solvers.frequency_domain import FDOptions

__all__ = ["Scene", "Section", "SECTIONS", "load_scene", "scene_keys"]


# -- the section parsers -------------------------------------------------------------------------
# Each takes the scene's top-level Node, its own key and the sections parsed so far (by field
# name), and returns the frozen value stored on the Scene (or the default when the key is absent).

def _parse_site(node: Node, key: str, parsed: Mapping[str, Any]) -> SiteSpec:
    return parse_site(node.child(key))


def _parse_vessel(node: Node, key: str, parsed: Mapping[str, Any]) -> Path | None:
    if key not in node:
        return None
    path = node.path_value(key)
    if path.is_dir():  # a vessel folder holds vessel.yaml (as floatmoor.hydro.load_vessel reads)
        if not (path / "vessel.yaml").is_file():
            raise node.error(key, "a vessel file, or a folder holding vessel.yaml",
                             node.raw(key), f"{path / 'vessel.yaml'} does not exist")
        path = path / "vessel.yaml"
    return path


def _parse_environment(node: Node, key: str, parsed: Mapping[str, Any]) -> Environment:
    if key not in node:
        return Environment(name="calm")
    value = node.raw(key)
    if not isinstance(value, (str, Mapping)):
        raise node.error(key, "a path to an environment file or a mapping with waves, wind, "
                         "current", value)
    site: SiteSpec = parsed["site"]
    return parse_environment(node.child_or_file(key), water_depth=site.water_depth,
                             gravity=site.gravity)


def _parse_mooring(node: Node, key: str, parsed: Mapping[str, Any]) -> Path | dict | None:
    # Validated only as an existing path or a mapping here; the lines are read by
    # floatmoor.io.mooring_section (see Scene.mooring_node()).
    if key not in node:
        return None
    value = node.raw(key)
    if isinstance(value, str):
        path = node.path_value(key)
        if path.is_dir():
            raise node.error(key, "a path to a mooring file (not a folder)", value)
        return path
    if isinstance(value, Mapping):
        return dict(value)
    raise node.error(key, "a path to a mooring file or a mapping", value)


def _parse_analysis(node: Node, key: str, parsed: Mapping[str, Any]) -> AnalysisSpec:
    if key not in node:
        return AnalysisSpec()
    return parse_analysis(node.child(key))


def _parse_forces(node: Node, key: str, parsed: Mapping[str, Any]) -> ForcesSpec | None:
    if key not in node:
        return None
    return parse_forces(node.child(key))


def _parse_solver(node: Node, key: str, parsed: Mapping[str, Any]) -> SolverSpec | None:
    if key not in node:
        return None
    return parse_solver(node.child(key))


def _parse_limits(node: Node, key: str, parsed: Mapping[str, Any]) -> LimitsSpec | None:
    if key not in node:
        return None
    return parse_limits(node.child(key))


def _parse_frequency_domain(node: Node, key: str, parsed: Mapping[str, Any]) -> FDOptions | None:
    if key not in node:  # imported only when used: the solver module is heavy
        return None
    from .fd_section import parse_frequency_domain
    return parse_frequency_domain(node, key, parsed)


def _describe_frequency_domain(options: FDOptions | None, scene: Scene) -> list[str]:
    if options is None:
        return []
    from .fd_section import describe_frequency_domain
    return describe_frequency_domain(options, scene)


def _describe_site(site: SiteSpec, scene: Scene) -> list[str]:
    return [f"site: water depth {site.water_depth:g} m, water density {site.water_density:g} "
            f"kg/m^3, air density {site.air_density:g} kg/m^3, gravity {site.gravity:g} m/s^2"]


def _describe_vessel(vessel: Path | None, scene: Scene) -> list[str]:
    return ["vessel: none" if vessel is None else f"vessel: {vessel}"]


def _describe_environment(env: Environment, scene: Scene) -> list[str]:
    return describe_environment(env, water_depth=scene.site.water_depth, gravity=scene.site.gravity)


def _describe_mooring(mooring, scene: Scene) -> list[str]:
    if mooring is None:
        return ["mooring: none"]
    if isinstance(mooring, Path):
        return [f"mooring: {mooring}"]
    return ["mooring: inline mapping with keys " + ", ".join(str(k) for k in mooring)]


def _describe_analysis(analysis: AnalysisSpec, scene: Scene) -> list[str]:
    return describe_analysis(analysis)


@dataclass(frozen=True)
class Section:
    """One top-level section of a scene file.

    key: the YAML key; field: the Scene attribute; parse(scene_node, key, parsed): the reader
    (``parsed`` holds the sections read before, by field name); required: whether the key must
    be present (the parser then need not check); describe(value, scene): lines for
    ``Scene.describe()``; models(value): model names for ``Scene.active_models()``.
    """

    key: str
    field: str
    parse: Callable[[Node, str, Mapping[str, Any]], Any]
    required: bool = False
    describe: Callable[[Any, Scene], list[str]] | None = None
    models: Callable[[Any], list[str]] | None = None


SECTIONS: tuple[Section, ...] = (
    Section("site", "site", _parse_site, required=True, describe=_describe_site),
    Section("vessel", "vessel", _parse_vessel, describe=_describe_vessel),
    Section("environment", "environment", _parse_environment, describe=_describe_environment,
            models=environment_models),
    Section("mooring", "mooring", _parse_mooring, describe=_describe_mooring,
            models=lambda m: [] if m is None else ["mooring"]),
    Section("analysis", "analysis", _parse_analysis, describe=_describe_analysis),
    Section("forces", "forces", _parse_forces, describe=describe_forces),
    Section("frequency_domain", "frequency_domain", _parse_frequency_domain,
            describe=_describe_frequency_domain),
    Section("solver", "solver", _parse_solver, describe=describe_solver),
    Section("limits", "limits", _parse_limits, describe=describe_limits),
)
"""The scene's sections in parsing order (a section may use those before it)."""

_HEADER_KEYS = ("name", "description")


def scene_keys() -> tuple[str, ...]:
    """All top-level keys a scene file may hold."""
    return _HEADER_KEYS + tuple(s.key for s in SECTIONS)


@dataclass(frozen=True, kw_only=True)
class Scene:
    """A validated scene (build it with :func:`load_scene`).

    Attributes: ``name``, ``description``, ``file`` (the scene file, None when built in Python),
    ``site`` (:class:`~floatmoor.io.site.SiteSpec`), ``vessel`` (path of the vessel file or
    None), ``environment`` (:class:`~floatmoor.metocean.config.Environment`; components that are
    None are not modelled), ``mooring`` (path, raw mapping or None), ``analysis``
    (:class:`~floatmoor.io.analysis.AnalysisSpec`), ``forces`` (options of the time-domain force
    models, :class:`~floatmoor.io.forces_section.ForcesSpec`, or None for the defaults),
    ``frequency_domain`` (:class:`~floatmoor.solvers.frequency_domain.FDOptions` or None),
    ``solver`` (:class:`~floatmoor.io.solver_section.SolverSpec` or None: the exact path),
    ``limits`` (offset limits and named points of the design checks,
    :class:`~floatmoor.io.limits_section.LimitsSpec`, or None).
    """

    name: str
    description: str = ""
    file: Path | None = field(default=None, compare=False)
    site: SiteSpec
    vessel: Path | None = None
    environment: Environment = field(default_factory=Environment)
    mooring: Path | dict | None = None
    analysis: AnalysisSpec = field(default_factory=AnalysisSpec)
    forces: ForcesSpec | None = None
    frequency_domain: FDOptions | None = None
    solver: SolverSpec | None = None
    limits: LimitsSpec | None = None

    def active_models(self) -> list[str]:
        """Names of the models this scene asks for, as ``"section:model"`` or ``"section"``
        (e.g. ``["waves:jonswap", "wind:npd", "current:piecewise_linear", "mooring"]``)."""
        out: list[str] = []
        for s in SECTIONS:
            if s.models is not None:
                out.extend(s.models(getattr(self, s.field)))
        return out

    def describe(self) -> str:
        """A readable, multi-line account of what this scene would build."""
        lines = [f"scene: {self.name}" + (f"  [{self.file}]" if self.file else "")]
        if self.description:
            lines.append(f"  {self.description.strip()}")
        for s in SECTIONS:
            if s.describe is not None:
                lines.extend(s.describe(getattr(self, s.field), self))
        models = self.active_models()
        lines.append("models: " + (", ".join(models) if models else "none"))
        return "\n".join(lines)

    def mooring_node(self) -> Node | None:
        """The ``mooring:`` section as a :class:`~floatmoor.core.config.Node` naming the right
        file and key path (the mooring file itself, or ``mooring`` in the scene file)."""
        if self.mooring is None:
            return None
        if isinstance(self.mooring, Path):
            return Node.load(self.mooring)
        return Node(self.mooring, self.file, "mooring")


def load_scene(path: str | os.PathLike) -> Scene:
    """Read and validate a scene file.

    Parameters
    ----------
    path:
        The scene YAML file; paths inside it are relative to its folder.

    Returns
    -------
    Scene
        A frozen, validated scene.

    Raises
    ------
    floatmoor.SceneError
        For every mistake, naming the file (the referenced file when the mistake is in one), the
        key path, what was expected and what was found.
    """
    node = Node.load(path)
    node.reject_unknown(scene_keys())
    name = node.str("name", Path(path).stem)
    if not name.strip():
        raise node.error("name", "a non-empty name", name)
    description = node.str("description", "")
    parsed: dict[str, Any] = {}
    for s in SECTIONS:
        if s.required and s.key not in node:
            raise node.error(s.key, f"the {s.key} section (a mapping; it is required)")
        parsed[s.field] = s.parse(node, s.key, parsed)
    scene = Scene(name=name, description=description, file=node.file, **parsed)
    for check in SCENE_CHECKS:
        check(scene)
    return scene

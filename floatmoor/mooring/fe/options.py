"""Scene options of FE lines, read from a YAML mapping with :class:`floatmoor.core.config.Node`
(every mistake a SceneError naming file, key, expected and found).

The ``mooring:`` section selects the model for all lines or per line; the FE options sit in a
``finite_element:`` mapping (all keys optional)::

    mooring:
      model: finite-element            # or quasi-static (default); per line: lines[i].model
      finite_element:
        element_length: 20.0           # m, target element length (or n_elements: per line,
                                       #   or [n1, n2, ...]: per segment, anchor to fairlead)
        integrator: generalized_alpha  # or explicit (for comparison)
        dt: 0.1                        # s, longest line step (or substeps: per body step)
        internal_damping: -0.8         # N s, or -zeta (fraction of critical per element)
        rho_inf: 0.7                   # generalised-alpha spectral radius
        newton: exact                  # 1 um position stop (default); or force: stop in force
                                       #   terms; modified: iteration matrix kept across
                                       #   iterations; fast: quadratic-estimate stop
        axial_stiffness_limit: 3.84e11 # N, optional (practically inextensible lines)
        fibre_law: two_component       # segments whose line type has a `fibre` model:
                                       #   two_component | working_curve | constant
        fibre_time_constant: 300.0     # s, mean-strain filter of two_component (fibre_law.py)
        seabed: {model: springs, stiffness: 2.7e5, damping: 2.7e4}
                                       # or {model: mud_layer, mud_depth: 0.1};
                                       #   lift_off_damping: true (damping both ways)
        friction: {model: velocity_ramp, mu_axial: 0.7, mu_lateral: 1.0, zero_crossing_period: 10.0}
                                       # model: none | velocity_ramp |
                                       #   velocity_ramp_double_quadratic |
                                       #   displacement_velocity_ramp (config.FRICTION_MODELS)

:func:`parse_fe_options` returns :class:`FEOptions`; the scene builder passes them on to
:func:`floatmoor.mooring.fe.from_system.spec_from_linedef` (:meth:`FEOptions.spec_kw`),
:class:`FELine` (:meth:`FEOptions.line_kw`) and :meth:`FELine.start`
(:meth:`FEOptions.start_kw`); :meth:`FEOptions.substeps_for` gives the line steps per body step.
:func:`parse_line_models` reads the model choice of every line of a ``mooring:`` section
together with the options (:class:`LineModels`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from ...core.config import Node
from .config import FRICTION_MODELS, SEABED_MODELS, Friction, Seabed
from .fibre_law import DEFAULT_TIME_CONSTANT
from .line import FIBRE_LAWS, NEWTON_MODES

__all__ = ["FEOptions", "parse_fe_options", "MOORING_MODELS", "INTEGRATORS", "LineModels",
           "parse_line_models"]

MOORING_MODELS = ("quasi-static", "finite-element")

INTEGRATORS = ("generalized_alpha", "explicit")

_KEYS = {"element_length", "n_elements", "internal_damping", "rho_inf", "substeps", "dt",
         "integrator", "axial_stiffness_limit", "seabed", "friction", "fibre_law",
         "fibre_time_constant", "newton"}
_SEABED_KEYS = {"model", "stiffness", "damping", "mud_depth", "contact_smoothing",
                "lift_off_damping"}
_FRICTION_KEYS = {"model", "mu_axial", "mu_lateral", "ramp_velocity", "zero_crossing_period",
                  "ramp_displacement"}


@dataclass(frozen=True, kw_only=True)
class FEOptions:
    """FE line options from a scene (SI units); ``seabed`` keeps the depth open (``None``
    values are filled in by :meth:`seabed_for`)."""

    element_length: float = 20.0
    n_elements: int | tuple[int, ...] | None = None
    """Elements of each FE line, shared among its segments in proportion to their lengths, or
    a tuple: the elements of each segment, anchor to fairlead (every FE line then has that
    many segments; checked by :func:`floatmoor.io.mooring_section.parse_mooring`)."""
    internal_damping: float = 0.0
    rho_inf: float = 0.7
    substeps: int = 1
    dt: float | None = None
    integrator: str = "generalized_alpha"
    axial_stiffness_limit: float | None = None
    seabed: dict = field(default_factory=dict)
    friction: Friction | None = None
    fibre_law: str = "two_component"
    fibre_time_constant: float = DEFAULT_TIME_CONSTANT
    newton: str = "exact"

    def seabed_for(self, water_depth: float) -> Seabed:
        """The :class:`Seabed` at ``water_depth`` (m) with the scene's settings."""
        return Seabed(depth=water_depth, **self.seabed)

    def spec_kw(self, water_depth: float) -> dict:
        """Keywords of :func:`~floatmoor.mooring.fe.from_system.spec_from_linedef`
        (element length or count, friction, seabed, internal damping)."""
        kw = {"element_length": self.element_length, "n_elements": self.n_elements,
              "internal_damping": self.internal_damping,
              "seabed": self.seabed_for(water_depth)}
        if self.friction is not None:
            kw["friction"] = self.friction
        return kw

    def line_kw(self) -> dict:
        """Keywords of :class:`~floatmoor.mooring.fe.line.FELine`."""
        return {"axial_stiffness_limit": self.axial_stiffness_limit,
                "fibre_law": self.fibre_law, "fibre_time_constant": self.fibre_time_constant}

    def start_kw(self) -> dict:
        """Keywords of :meth:`~floatmoor.mooring.fe.line.FELine.start`."""
        return {"rho_inf": self.rho_inf, "integrator": self.integrator, "newton": self.newton}

    def substeps_for(self, body_dt: float) -> int:
        """Line steps per body step of ``body_dt`` s: ``ceil(body_dt / dt)`` when ``dt`` is
        given, else ``substeps``."""
        if self.dt is None:
            return self.substeps
        return max(1, int(math.ceil(body_dt / self.dt - 1e-9)))


def parse_fe_options(node: Node | None) -> FEOptions:
    """Read a ``finite_element:`` mapping (``None``: all defaults)."""
    if node is None:
        return FEOptions()
    node.reject_unknown(_KEYS)
    kw = {}
    if "element_length" in node and "n_elements" in node:
        raise node.error("n_elements", "either element_length or n_elements, not both",
                         node.raw("n_elements"))
    if "dt" in node and "substeps" in node:
        raise node.error("dt", "either dt or substeps, not both", node.raw("dt"))
    if "element_length" in node:
        kw["element_length"] = node.float("element_length", gt=0.0, unit="m")
    if "n_elements" in node:
        kw["n_elements"] = _n_elements(node)
    if "dt" in node:
        kw["dt"] = node.float("dt", gt=0.0, unit="s")
    if "integrator" in node:
        kw["integrator"] = node.str("integrator", choices=list(INTEGRATORS))
    if "newton" in node:
        kw["newton"] = node.str("newton", choices=list(NEWTON_MODES))
    if "internal_damping" in node:
        kw["internal_damping"] = node.float("internal_damping", unit="N s (or -zeta)")
    if "rho_inf" in node:
        kw["rho_inf"] = node.float("rho_inf", ge=0.0, le=1.0)
    if "substeps" in node:
        kw["substeps"] = node.int("substeps", ge=1)
    if "axial_stiffness_limit" in node:
        kw["axial_stiffness_limit"] = node.float("axial_stiffness_limit", gt=0.0, unit="N")
    if "fibre_law" in node:
        kw["fibre_law"] = node.str("fibre_law", choices=list(FIBRE_LAWS))
    if "fibre_time_constant" in node:
        kw["fibre_time_constant"] = node.float("fibre_time_constant", gt=0.0, unit="s")
    if "seabed" in node:
        sb = node.child("seabed")
        sb.reject_unknown(_SEABED_KEYS)
        d = {}
        if "model" in sb:
            d["model"] = sb.str("model", choices=list(SEABED_MODELS))
        for k, unit in (("stiffness", "N/m per m"), ("damping", "N s/m per m"),
                        ("mud_depth", "m"), ("contact_smoothing", "m")):
            if k in sb:
                if k in ("stiffness", "mud_depth"):
                    d[k] = sb.float(k, gt=0.0, unit=unit)
                else:
                    d[k] = sb.float(k, ge=0.0, unit=unit)
        if "lift_off_damping" in sb:
            d["lift_off_damping"] = sb.bool("lift_off_damping")
        kw["seabed"] = d
    if "friction" in node:
        fr = node.child("friction")
        fr.reject_unknown(_FRICTION_KEYS)
        d = {"model": fr.choice("model", FRICTION_MODELS, what="friction model")}
        for k in ("mu_axial", "mu_lateral"):
            if k in fr:
                d[k] = fr.float(k, ge=0.0)
        for k, unit in (("ramp_velocity", "m/s"), ("zero_crossing_period", "s"),
                        ("ramp_displacement", "m")):
            if k in fr:
                d[k] = fr.float(k, gt=0.0, unit=unit)
        kw["friction"] = Friction(**d)
    return FEOptions(**kw)


def _n_elements(node: Node) -> int | tuple[int, ...]:
    """``n_elements``: an integer >= 1 (per line) or a list of them (per segment)."""
    raw = node.raw("n_elements")
    if not isinstance(raw, list):
        return node.int("n_elements", ge=1)
    expected = ("an integer >= 1 (elements per line) or a non-empty list of integers >= 1 "
                "(elements per segment, anchor to fairlead)")
    if not raw or any(isinstance(v, bool) or not isinstance(v, int) or v < 1 for v in raw):
        raise node.error("n_elements", expected, raw)
    return tuple(int(v) for v in raw)


@dataclass(frozen=True, kw_only=True)
class LineModels:
    """The line model of every line of a ``mooring:`` section and the FE options.

    ``models`` maps line name -> ``"quasi-static"`` or ``"finite-element"`` (in the order of the
    section); ``options`` are the ``finite_element:`` options (defaults when absent).
    """

    models: dict
    options: FEOptions = field(default_factory=FEOptions)

    def model_of(self, name: str) -> str:
        """The model of line ``name`` (quasi-static for a name not in the section)."""
        return self.models.get(name, "quasi-static")

    @property
    def finite_element_lines(self) -> list:
        """Names of the lines modelled with finite elements."""
        return [n for n, m in self.models.items() if m == "finite-element"]

    @property
    def any_finite_element(self) -> bool:
        return any(m == "finite-element" for m in self.models.values())


def parse_line_models(node: Node) -> LineModels:
    """Model choice of every line of a ``mooring:`` mapping (``node``) and its FE options.

    ``model:`` at the top sets the default of all lines (``quasi-static`` when absent);
    ``lines[i].model`` overrides it for one line.  A ``finite_element:`` mapping without any
    finite-element line is accepted (its options are validated) but unused.  Only the keys
    ``model`` and ``finite_element`` are read here; the rest of the section is the business of
    :func:`floatmoor.io.mooring_section.parse_mooring`.

    Raises
    ------
    SceneError
        Unknown model name (naming file, key and the names available) or bad FE option.
    """
    default = node.str("model", "quasi-static", choices=list(MOORING_MODELS))
    models = {}
    for i, ln in enumerate(node.item_nodes("lines", [])):
        name = ln.str("name") if "name" in ln else f"lines[{i}]"
        models[name] = ln.str("model", default, choices=list(MOORING_MODELS))
    options = parse_fe_options(node.child("finite_element") if "finite_element" in node
                               else None)
    return LineModels(models=models, options=options)

"""Scene options of FE lines, read from a YAML mapping with :class:`floatmoor.core.config.Node`
(every mistake a SceneError naming file, key, expected and found).

The ``mooring:`` section selects the model for all lines or per line; the FE options sit in a
``finite_element:`` mapping (all keys optional)::

    mooring:
      model: finite-element            # or quasi-static (default); per line: lines[i].model
      finite_element:
        element_length: 20.0           # m, target element length
        internal_damping: -0.8         # N s, or -zeta (fraction of critical per element)
        rho_inf: 0.7                   # generalised-alpha spectral radius
        substeps: 1                    # line steps per body step
        axial_stiffness_limit: 3.84e11 # N, optional (practically inextensible lines)
        seabed: {model: springs, stiffness: 2.7e5, damping: 2.7e4}
                                       # or {model: mud_layer, mud_depth: 0.1}
        friction: {model: velocity_ramp, mu_axial: 0.7, mu_lateral: 1.0, zero_crossing_period: 10.0}

:func:`parse_fe_options` returns :class:`FEOptions`; the scene builder passes them on to
:func:`floatmoor.mooring.fe.from_system.spec_from_linedef`, :class:`FELine` and
:meth:`FELine.start`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ...core.config import Node
from .config import FRICTION_MODELS, SEABED_MODELS, Friction, Seabed

__all__ = ["FEOptions", "parse_fe_options", "MOORING_MODELS"]

MOORING_MODELS = ("quasi-static", "finite-element")

_KEYS = {"element_length", "internal_damping", "rho_inf", "substeps", "axial_stiffness_limit",
         "seabed", "friction"}
_SEABED_KEYS = {"model", "stiffness", "damping", "mud_depth", "contact_smoothing"}
_FRICTION_KEYS = {"model", "mu_axial", "mu_lateral", "ramp_velocity", "zero_crossing_period",
                  "ramp_displacement"}


@dataclass(frozen=True, kw_only=True)
class FEOptions:
    """FE line options from a scene (SI units); ``seabed`` keeps the depth open (``None``
    values are filled in by :meth:`seabed_for`)."""

    element_length: float = 20.0
    internal_damping: float = 0.0
    rho_inf: float = 0.7
    substeps: int = 1
    axial_stiffness_limit: float | None = None
    seabed: dict = field(default_factory=dict)
    friction: Friction | None = None

    def seabed_for(self, water_depth: float) -> Seabed:
        """The :class:`Seabed` at ``water_depth`` (m) with the scene's settings."""
        return Seabed(depth=water_depth, **self.seabed)


def parse_fe_options(node: Node | None) -> FEOptions:
    """Read a ``finite_element:`` mapping (``None``: all defaults)."""
    if node is None:
        return FEOptions()
    node.reject_unknown(_KEYS)
    kw = {}
    if "element_length" in node:
        kw["element_length"] = node.float("element_length", gt=0.0, unit="m")
    if "internal_damping" in node:
        kw["internal_damping"] = node.float("internal_damping", unit="N s (or -zeta)")
    if "rho_inf" in node:
        kw["rho_inf"] = node.float("rho_inf", ge=0.0, le=1.0)
    if "substeps" in node:
        kw["substeps"] = node.int("substeps", ge=1)
    if "axial_stiffness_limit" in node:
        kw["axial_stiffness_limit"] = node.float("axial_stiffness_limit", gt=0.0, unit="N")
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

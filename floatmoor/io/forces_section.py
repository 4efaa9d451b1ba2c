"""The ``forces:`` section of a scene: options of the time-domain force models.

```yaml
forces:
  exclude: [drift, wind]           # models (or groups drift, damping, waves) not to build
  drift: newman                    # qtf (default with a QTF) | newman (default with mean
                                   # drift only) | none
  retardation: true                # radiation memory on (default) or off
  max_memory: 120.0                # s, longest retardation memory kept
  line_failure: {line6: 1500.0}    # transient ALS: line name -> time of failure (s)
  record_forces: false             # store force(time, model, dof) in the results
  relative_velocity: low_frequency # body velocity in the wind and current relative velocity:
                                   # low_frequency (default) | total
  viscous_drift: {model: slender_elements}   # | correction_formula | none (default); see
                                   # floatmoor.io.viscous_drift_section
  wave_drift_damping: false        # Aranha's wave drift damping on the low-frequency motion
```

The section serves both domains: the frequency domain assembles the same models
(:func:`floatmoor.forces.select_models`), so ``exclude``, ``drift``, ``retardation``,
``viscous_drift`` and ``wave_drift_damping`` act in both (``frequency_domain: drift`` and
``frequency_domain: wave_drift_damping`` may override the last two in the frequency domain
alone, with a note).

``wave_drift_damping``: Aranha's formula from the mean drift coefficients and the sea's
spectrum (:mod:`floatmoor.forces.wave_drift_damping`), a damping of the low-frequency motion
(the pose rate less the linear wave-frequency velocity in the time domain; the LF system in the
frequency domain).  Off by default: it lowers the LF motion, and a default must not flatter a
design.

``relative_velocity``: Wang (2016) writes the hull wind and current forces with the flow velocity
relative to the low-frequency body velocity, eq. 2.24 ``Q_wi = C_wi [(U + u(t)) - x'_LF]^2``
and eq. 2.26 ``Q_cu = C_cu (V - x'_LF)|V - x'_LF|``.  With ``low_frequency`` the solver predicts
the linear wave-frequency velocity x'_WF from the motion RAOs (same database, mass, damping and
linearised stiffness at the static start) and the same wave realisation as the first-order wave
force, and uses ``x'_LF = x' - x'_WF`` (:mod:`floatmoor.solvers.wf_velocity`); without waves
x'_LF = x'.  ``total`` uses the total body velocity x' (the slender-element form of section 6.3,
eq. 6.7, which turns the hull coefficients into a viscous-drift model: the mean current force on
the Floatel-like semi in the 100-year sea more than doubles).

Every key is optional.  The models themselves are chosen by the other sections (no wind in the
environment: no wind model); this section only removes or tunes them.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..core.config import Node

__all__ = ["ForcesSpec", "parse_forces", "FORCES_KEYS", "DRIFT_METHODS", "RELATIVE_VELOCITY"]

FORCES_KEYS = ("exclude", "drift", "retardation", "max_memory", "line_failure", "record_forces",
               "relative_velocity", "viscous_drift", "wave_drift_damping")
RELATIVE_VELOCITY = ("low_frequency", "total")
DRIFT_METHODS = ("qtf", "newman", "none")


@dataclass(frozen=True, kw_only=True)
class ForcesSpec:
    """Options of the force models (see the module docstring); ``file`` for messages."""

    exclude: tuple[str, ...] = ()
    drift: str | None = None
    retardation: bool = True
    max_memory: float | None = None
    line_failure: dict = field(default_factory=dict)
    record_forces: bool = False
    relative_velocity: str = "low_frequency"
    viscous_drift: object = None     # ViscousDriftSpec (floatmoor.io.viscous_drift_section)
    wave_drift_damping: bool = False
    file: object = field(default=None, compare=False)


def parse_forces(node: Node) -> ForcesSpec:
    """Read a ``forces:`` mapping (SceneError naming file and key for every mistake)."""
    from ..forces import GROUPS, REGISTRY
    node.reject_unknown(FORCES_KEYS)
    names = sorted(set(REGISTRY) | set(GROUPS))
    exclude = []
    for _i, item in enumerate(node.list("exclude", [])):
        if not isinstance(item, str) or item not in names:
            raise node.error("exclude", "force model names: " + ", ".join(names), item)
        exclude.append(item)
    drift = node.str("drift", None, choices=DRIFT_METHODS) if "drift" in node else None
    failures = {}
    if "line_failure" in node:
        fl = node.child("line_failure")
        for name in fl.keys():
            failures[str(name)] = fl.float(name, ge=0.0, unit="s")
    from .viscous_drift_section import parse_viscous_drift
    viscous = (parse_viscous_drift(node.child("viscous_drift"), drift=drift)
               if "viscous_drift" in node else None)
    return ForcesSpec(exclude=tuple(exclude), drift=drift, viscous_drift=viscous,
                      retardation=node.bool("retardation", True),
                      max_memory=node.float("max_memory", None, gt=0.0, unit="s")
                      if "max_memory" in node else None,
                      line_failure=failures, record_forces=node.bool("record_forces", False),
                      relative_velocity=node.str("relative_velocity", "low_frequency",
                                                 choices=RELATIVE_VELOCITY),
                      wave_drift_damping=node.bool("wave_drift_damping", False),
                      file=node.file)


def describe_forces(spec: ForcesSpec | None, scene=None) -> list[str]:
    if spec is None:
        return []
    parts = []
    if spec.exclude:
        parts.append("excluded " + ", ".join(spec.exclude))
    if spec.drift:
        parts.append(f"drift {spec.drift}")
    if not spec.retardation:
        parts.append("no radiation memory")
    if spec.wave_drift_damping:
        parts.append("wave drift damping")
    if spec.relative_velocity != "low_frequency":
        parts.append(f"wind/current relative to the {spec.relative_velocity} body velocity")
    for name, t in spec.line_failure.items():
        parts.append(f"line {name} fails at {t:g} s")
    return ["forces: " + ("; ".join(parts) if parts else "defaults")]

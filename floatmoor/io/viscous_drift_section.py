"""The ``forces: viscous_drift:`` key of a scene: how viscous drift is modelled (Wang (2016) ch. 6).

```yaml
forces:
  viscous_drift:
    model: slender_elements        # slender_elements | correction_formula | none (default)
    # -- slender_elements (the vessel file's slender_elements section) -------------------
    double_counting: true          # zero the hull current coefficients in the DOFs the
                                   # elements cover (Wang (2016) section 6.1.2), with a warning
    stretching: wheeler            # wheeler | constant (MWL velocity in the splash zone)
    inertia: false                 # Morison inertia cm a (vessel file inertia_per_length);
                                   # off by default: potential flow already carries it
    drag:                          # optional per-type override, N s^2/m^3 (cases 3 and 4)
      column: {c2y: 4144.37}
      pontoon: {c2x: 0.0, c2y: 0.0, c2z: 0.0}
    station_spacing: 10.0          # m, kinematics stations along long elements
    level_step: 3.0                # m, stretched-depth step of the kinematics table
    table_step: 0.4                # s, time step of the kinematics table
    # -- correction_formula (eq. 6.6 on the mean drift coefficients) -----------------------
    column_diameters: [12.5, 12.5, 12.5, 12.5]   # d_i (m)
    main_column_diameter: 12.5     # D0 (m)
    cp: 0.25                       # s/m
    g_time: 10.0                   # G (s)
    b0: 1000.0                     # N/m^3 (the kN/m^3 of eq. 6.6)
    current_speed: 0.94            # m/s, default: the scene's current at z = 0
    extra_damping: 1.0             # fraction added to the surge/sway linear damping (sec. 6.6)
```

Where each model acts: ``slender_elements`` only in the time domain (``floatmoor.simulate``;
``floatmoor.frequency_domain`` warns with a FloatmoorWarning that it runs without viscous drift
and with the hull current coefficients); ``correction_formula`` in both, through the same
corrected mean drift coefficients (the time domain's Newman drift; the FD mean drift and
slow-drift spectrum) and the same extra damping.  Both need Newman's approximation for the
slow drift: ``forces: {drift: qtf}`` / ``frequency_domain: {drift: qtf}`` are refused with the
correction formula.
"""

from __future__ import annotations

from dataclasses import dataclass, field

from ..core.config import Node

__all__ = ["ViscousDriftSpec", "parse_viscous_drift", "VISCOUS_DRIFT_MODELS"]

VISCOUS_DRIFT_MODELS = ("slender_elements", "correction_formula", "none")
_SLENDER_KEYS = {"double_counting", "stretching", "drag", "station_spacing", "level_step",
                 "table_step", "inertia"}
_CF_KEYS = {"column_diameters", "main_column_diameter", "cp", "g_time", "b0", "current_speed",
            "extra_damping"}


@dataclass(frozen=True, kw_only=True)
class ViscousDriftSpec:
    """Validated ``viscous_drift`` options (SI units; see the module docstring)."""

    model: str = "none"
    double_counting: bool = True
    wheeler: bool = True
    inertia: bool = False
    drag: dict = field(default_factory=dict)
    station_spacing: float = 10.0
    level_step: float = 3.0
    table_step: float = 0.4
    column_diameters: tuple = ()
    main_column_diameter: float | None = None
    cp: float = 0.25
    g_time: float = 10.0
    b0: float = 1000.0
    current_speed: float | None = None
    extra_damping: float = 0.0
    file: object = field(default=None, compare=False)

    def correction_formula(self):
        """The :class:`floatmoor.hydro.viscous_drift.CorrectionFormula` of these options."""
        from ..hydro.viscous_drift import CorrectionFormula
        return CorrectionFormula(column_diameters=self.column_diameters,
                                 main_column_diameter=self.main_column_diameter, cp=self.cp,
                                 g_time=self.g_time, b0=self.b0)


def parse_viscous_drift(node: Node, *, drift: str | None = None) -> ViscousDriftSpec:
    """Read the ``viscous_drift`` mapping (``node`` is that mapping's Node).

    ``drift``: the scene's drift method; the correction formula corrects the mean drift
    coefficients and therefore needs ``drift: newman`` (or the default without a QTF).
    """
    model = node.str("model", "none", choices=VISCOUS_DRIFT_MODELS)
    allowed = {"model"}
    if model == "slender_elements":
        allowed |= _SLENDER_KEYS
    elif model == "correction_formula":
        allowed |= _CF_KEYS
    node.reject_unknown(allowed)
    kw = {"model": model, "file": node.file}
    if model == "slender_elements":
        kw["double_counting"] = node.bool("double_counting", True)
        kw["inertia"] = node.bool("inertia", False)
        kw["wheeler"] = node.str("stretching", "wheeler", choices=("wheeler", "constant")) \
            == "wheeler"
        drag = {}
        if "drag" in node:
            dn = node.child("drag")
            for t in dn.keys():
                tn = dn.child(t)
                tn.reject_unknown({"c2x", "c2y", "c2z"})
                drag[str(t)] = {k: tn.float(k, ge=0.0, unit="N s^2/m^3")
                                for k in ("c2x", "c2y", "c2z") if k in tn}
        kw["drag"] = drag
        kw["station_spacing"] = node.float("station_spacing", 10.0, gt=0.0, unit="m")
        kw["level_step"] = node.float("level_step", 3.0, gt=0.0, unit="m")
        kw["table_step"] = node.float("table_step", 0.4, gt=0.0, unit="s")
    elif model == "correction_formula":
        if drift == "qtf":
            raise node.error("model", "drift: newman with the correction formula (it corrects "
                             "the mean drift coefficients)", "drift: qtf")
        d = node.array("column_diameters", shape=(None,), gt=0.0, unit="m")
        if d.size == 0:
            raise node.error("column_diameters", "at least one column diameter (m)", [])
        kw["column_diameters"] = tuple(float(x) for x in d)
        kw["main_column_diameter"] = node.float("main_column_diameter", float(d.max()), gt=0.0,
                                                unit="m")
        kw["cp"] = node.float("cp", 0.25, unit="s/m")
        kw["g_time"] = node.float("g_time", 10.0, unit="s")
        kw["b0"] = node.float("b0", 1000.0, ge=0.0, unit="N/m^3")
        kw["current_speed"] = node.float("current_speed", None, unit="m/s")
        kw["extra_damping"] = node.float("extra_damping", 0.0, ge=0.0)
    return ViscousDriftSpec(**kw)

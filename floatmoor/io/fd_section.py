"""The ``frequency_domain:`` section of a scene: options of the frequency-domain analysis.

```yaml
frequency_domain:
  duration: 10800.0            # s, storm duration for the Rayleigh maxima (N = duration / Tz)
  tension_model: quasi_static  # or dynamic: WF tension of the FE lines in the frequency domain
  drift: auto                  # auto (full QTF when the database has one) | newman | qtf
  wave_drift_damping: null     # null: the scene's forces: wave_drift_damping (both domains);
                               # true/false: in the frequency domain alone (with a note)
  lf_cutoff_period: 30.0       # s, upper end of the LF band
  n_lf: 1200                   # LF frequencies from 0 to the cut-off
  d_omega: 0.005               # rad/s, step of the WF frequency grid
  heading_iterations: 4        # fixed-point iterations on the mean yaw
  line_current_drag: false     # static current drag on the lines in the mean position
  line_damping: none           # or fe: LF damping (and dynamic stiffness) of the FE lines
```

``line_current_drag: true`` solves every line's statics in the scene's current with its FE
model (the ``finite_element`` options of the mooring, else 20 m elements) and adds the drag's
change of the line forces to the catenary mooring in the mean equilibrium; the static tensions
and the linearisation are then taken at that mean pose, with the drag's own change with the
pose in the stiffness and the tension gradients (:mod:`floatmoor.mooring.fe.current_statics`).  Without current in the scene it changes
nothing.

``line_damping: fe`` adds the mooring lines' LF damping: every line's FE model in the frequency
domain under the WF and LF fairlead motion (drag linearised with both, iterated with the
response), its impedance beyond the static stiffness in the LF system
(:mod:`floatmoor.analyses.fd_line_damping`).  Without it the LF damping is the hull's only.

Every key is optional (defaults of :class:`~floatmoor.solvers.frequency_domain.FDOptions`).
"""

from __future__ import annotations

from collections.abc import Mapping
from dataclasses import fields
from typing import Any

from ..core.config import Node
from ..core.errors import SceneError
from ..solvers.frequency_domain import (
    DRIFT_METHODS,
    LINE_DAMPING_MODELS,
    TENSION_MODELS,
    FDOptions,
)

__all__ = ["parse_fd_options", "parse_frequency_domain", "describe_frequency_domain",
           "FD_KEYS"]

FD_KEYS = tuple(f.name for f in fields(FDOptions))


def parse_fd_options(node: Node) -> FDOptions:
    """Read a ``frequency_domain:`` mapping into :class:`FDOptions` (SceneError naming the file
    and key for every mistake)."""
    node.reject_unknown(FD_KEYS)
    d = FDOptions()
    kw = {
        "duration": node.float("duration", d.duration, gt=0.0, unit="s"),
        "tension_model": node.str("tension_model", d.tension_model, choices=TENSION_MODELS),
        "drift": node.str("drift", d.drift, choices=DRIFT_METHODS),
        "wave_drift_damping": (None if node.raw("wave_drift_damping", None) is None
                               else node.bool("wave_drift_damping")),
        "lf_cutoff_period": node.float("lf_cutoff_period", d.lf_cutoff_period, gt=0.0, unit="s"),
        "n_lf": node.int("n_lf", d.n_lf, ge=50),
        "d_omega": node.float("d_omega", d.d_omega, gt=0.0, unit="rad/s"),
        "heading_iterations": node.int("heading_iterations", d.heading_iterations, ge=1),
        "line_current_drag": node.bool("line_current_drag", d.line_current_drag),
        "line_damping": node.str("line_damping", d.line_damping, choices=LINE_DAMPING_MODELS),
    }
    try:
        return FDOptions(**kw)
    except SceneError as exc:  # name the file
        raise SceneError(node.file, exc.key, exc.expected, exc.found, exc.hint) from None


def parse_frequency_domain(node: Node, key: str, parsed: Mapping[str, Any]) -> FDOptions | None:
    """Section parser for :data:`floatmoor.io.scene.SECTIONS` (None when the key is absent)."""
    if key not in node:
        return None
    return parse_fd_options(node.child(key))


def describe_frequency_domain(options: FDOptions | None, scene) -> list[str]:
    """Lines for ``Scene.describe()``."""
    if options is None:
        return []
    return [f"frequency domain: duration {options.duration:g} s, tensions "
            f"{options.tension_model}, drift {options.drift}, LF cut-off "
            f"{options.lf_cutoff_period:g} s"
            + {True: ", wave drift damping", False: ", no wave drift damping",
               None: ""}[options.wave_drift_damping]
            + (", current drag on the lines" if options.line_current_drag else "")
            + (", FE line damping" if options.line_damping == "fe" else "")]

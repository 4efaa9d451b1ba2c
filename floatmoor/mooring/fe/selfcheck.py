"""Self-check of finite-element line results: bounds a correct solution cannot break.

Hard bounds stop the run inside the time loop (:func:`~.kernels.ga_advance`, status -4 and
-5, :meth:`FELine.step_error`): a time step that creates more than a quarter of the line's
kinetic and elastic energy even at its smallest sub-step, and a node deeper below the seabed
than its contact spring allows.  The warning-level bounds below are evaluated over a run and
recorded with the results (``selfcheck_*`` variables per line), in the ``floatmoor lines``
table and in the report, and announced with a :class:`~floatmoor.core.errors.FloatmoorWarning`:

``tension``
    The largest tension anywhere along the line over the run may exceed the largest fairlead
    tension by at most what the line between them can carry statically: its submerged weight
    over the height of the fairlead above the anchor, the seabed friction of its whole
    submerged weight, and the tangential drag of the whole line at the current speed plus the
    largest fairlead speed, ``T_along <= T_fair + w_max h + mu W + sum_i k_t,i (u_i + v_f)^2``
    (the tension changes along a cable by its tangential loads only, ``dT/ds = w dz/ds + f_t``;
    normal loads turn it).  Inertia is not in the bound: a snap load travelling down the
    line and reflected at the anchor can exceed it in a correct solution, so this bound warns
    instead of stopping.  An answer like 12.5 MN at the anchor while the fairlead stays below
    4 MN breaks it by a factor of two.
``energy``
    Steps that still created energy at the smallest sub-step (:data:`~.kernels.AUDIT_REL` of
    the energy budget): their count and the energy they created.
``compression``
    An element pushing (net tension below zero beyond round-off: the internal damping force of
    an element shortening fast can exceed its elastic tension); a cable cannot push.

Every bound has a test on a deliberately broken setting that trips it
(``tests/mooring/fe/test_selfcheck.py``).
"""

from __future__ import annotations

import math
import warnings

import numpy as np

from ...core.errors import FloatmoorWarning
from . import kernels as K

__all__ = ["tension_allowance", "line_selfcheck", "selfcheck_variables", "warn_broken",
           "COMPRESSION_TOL"]

COMPRESSION_TOL = 1e-6
"""An element tension below ``-COMPRESSION_TOL`` times the line's largest tension (or -1 N)
counts as an element pushing."""


def tension_allowance(line, *, fairlead_height: float, fairlead_speed: float) -> float:
    """What the line between fairlead and any point can add to the tension statically (N):
    ``w_max h + mu_max W + sum_i k_t,i (u_max + v_f)^2`` with ``w_max`` the largest submerged
    weight per metre of its segments, ``h`` (m) the largest height of the fairlead above the
    anchor, ``mu_max`` the largest seabed friction coefficient, ``W`` the line's submerged
    weight, ``k_t,i`` the tangential drag coefficient of node ``i`` (N s^2/m^2), ``u_max`` the
    largest current speed and ``v_f`` (m/s) the largest fairlead speed."""
    P = line.P
    rho, g = line.spec.water_density, line.spec.gravity
    w_max = max(abs(s.line_type.submerged_weight(rho, g)) for s in line.spec.segments)
    mu = float(max(np.max(P[:, K.NP_MUA]), np.max(P[:, K.NP_MUL]))) if line.fric_code else 0.0
    W = float(np.sum(np.abs(P[:, K.NP_W])))
    u = float(np.max(np.abs(line.cur_u))) if line.cur_u.size else 0.0
    drag = float(np.sum(P[:, K.NP_KDT])) * (u + fairlead_speed) ** 2
    return w_max * max(fairlead_height, 0.0) + mu * W + drag


def line_selfcheck(line, *, fairlead_tension, max_tension, fairlead_height: float,
                   fairlead_speed: float) -> dict:
    """The self-check of one line over a run: ``fairlead_tension``, ``max_tension`` (nt,) N
    over the statistics window, the largest fairlead height above the anchor (m) and speed
    (m/s); the line's energy audit (:attr:`FELine.audit`).  Returns the numbers and ``broken``,
    the list of warning-level bounds it breaks (module docstring)."""
    Tf = float(np.max(fairlead_tension))
    Tm = float(np.max(max_tension))
    allow = tension_allowance(line, fairlead_height=fairlead_height,
                              fairlead_speed=fairlead_speed)
    bound = Tf + allow
    au = line.audit
    out = {"tension_bound": bound, "tension_ratio": Tm / bound if bound > 0 else math.inf,
           "max_tension_along_line": Tm, "max_fairlead_tension": Tf, **au}
    broken = []
    if not out["tension_ratio"] <= 1.0:
        broken.append(f"tension along the line {Tm / 1e3:.0f} kN above the bound "
                      f"{bound / 1e3:.0f} kN (fairlead {Tf / 1e3:.0f} kN + weight, friction "
                      f"and drag {allow / 1e3:.0f} kN)")
    if au["energy_unresolved_steps"] > 0:
        broken.append(f"{au['energy_unresolved_steps']} step(s) created energy at the smallest "
                      f"sub-step ({au['energy_unresolved_j'] / 1e3:.3g} kJ; worst "
                      f"{au['energy_worst_ratio']:.2g} of the line's energy at t = "
                      f"{au['energy_worst_time']:.1f} s, s = {au['energy_worst_arc_length']:.0f} m)")
    if au["min_element_tension"] < -max(COMPRESSION_TOL * Tm, 1.0):
        broken.append(f"an element pushes with {-au['min_element_tension'] / 1e3:.3g} kN at t = "
                      f"{au['min_element_tension_time']:.1f} s, s = "
                      f"{au['min_element_tension_arc_length']:.0f} m (internal damping above "
                      "the elastic tension of a fast-shortening element: lower the damping or "
                      "the step)")
    out["broken"] = broken
    return out


_VARS = {
    "tension_bound": ("N", "self-check: largest fairlead tension plus what weight, friction and "
                           "tangential drag can add along the line"),
    "tension_ratio": ("1", "self-check: largest tension along the line over the tension bound "
                           "(above 1: broken)"),
    "energy_halvings": ("1", "self-check: time steps halved because they created energy"),
    "energy_unresolved_steps": ("1", "self-check: steps that created energy at the smallest "
                                     "sub-step"),
    "energy_unresolved_j": ("J", "self-check: energy created by those steps"),
    "energy_worst_ratio": ("1", "self-check: largest energy created in one step over the line's "
                                "kinetic and elastic energy"),
    "seabed_penetration_ratio": ("1", "self-check: deepest seabed penetration over its bound"),
    "min_element_tension": ("N", "self-check: most negative element tension (0: no element "
                                 "pushed)"),
}


def selfcheck_variables(checks: list, dim: str = "line") -> dict:
    """Dataset variables (``selfcheck_*`` over ``dim``) of :func:`line_selfcheck` results
    (None for a line without a check: NaN, and ``selfcheck`` "-")."""
    data = {}
    for k, (unit, ln) in _VARS.items():
        data[f"selfcheck_{k}"] = ((dim,), np.array([np.nan if c is None else float(c[k])
                                                   for c in checks]),
                                  {"units": unit, "long_name": ln})
    data["selfcheck"] = ((dim,), np.array(["-" if c is None else
                                           ("ok" if not c["broken"] else "; ".join(c["broken"]))
                                           for c in checks]),
                         {"units": "1", "long_name": "self-check of the finite-element line: "
                                                    "ok, or the warning-level bounds it breaks"})
    return data


def warn_broken(names, checks, *, stacklevel: int = 3) -> None:
    """One FloatmoorWarning naming every line that breaks a warning-level bound."""
    bad = [f"{n}: {'; '.join(c['broken'])}" for n, c in zip(names, checks)
           if c is not None and c["broken"]]
    if bad:
        warnings.warn("finite-element line self-check: " + " | ".join(bad)
                      + " (results recorded with selfcheck_* variables)", FloatmoorWarning,
                      stacklevel=stacklevel)

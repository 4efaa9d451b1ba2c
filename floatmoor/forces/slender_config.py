"""Reading the vessel file's ``slender_elements`` section (Morison strips fixed to the hull).

```yaml
slender_elements:
  n_strips: 10                    # optional default strips per element (over its wetted part)
  quadratic_drag_per_length:      # SIMO-style C = 0.5 rho C_D D per local axis, N s^2/m^3
    column:  {c2x: 0.0, c2y: 7687.5, c2z: 8610.0}        # (Wang (2016) table 6.3)
  drag_coefficients:              # or: C_D and the width D (m) per local axis (y, z; x optional)
    pontoon: {cdy: 0.4, dy: 8.625, cdz: 1.6, dz: 14.0}
  dnv_rounded_rectangle:          # or: C_D from DNV-RP-C205 (rectangle with rounded corners,
    column:                       #     Re ~ 1e5), per local axis: width D facing the flow,
      y: {d: 12.5, l: 14.0, r: 3.0}   # length L along the flow, corner radius R (m)
      z: {d: 14.0, l: 12.5, r: 3.0}
  inertia_per_length:             # optional, rho C_M A per local axis (kg/m), used only with
    column: {my: 3.5e5, mz: 3.5e5}  # forces: viscous_drift: {inertia: true}
  elements:
    - {name: column_1, type: column, p1: [-25.25, -25.5, 14.5], p2: [-25.25, -25.5, -4.375]}
    - {name: pontoon_1, type: pontoon, p1: [...], p2: [...], n_strips: 12}
```

End points in body coordinates (m, about the vessel's reference point).  Local axes: see
:mod:`floatmoor.forces.slender_kernels` (local x from p1 to p2; a pontoon along body y has local
y = body x and local z = up; a vertical column has local y = body x, local z = body -y).

DNV-RP-C205 (2010) figure 6-? / Wang (2016) figure 6.2, "4. Rectangle with rounded corners"
(Re ~ 1e5): C_D by L/D (rows 0.5, 1, 2, 6) and R/D.  The lookup takes the nearest L/D row and
the nearest tabulated R/D, as the seed does for its table 6.2 (e.g. L/D 1, R/D 0.24 -> 0.167 ->
C_D 1.2); ``interpolation: linear`` interpolates in R/D within the nearest row instead.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..core.config import Node
from ..core.constants import RHO_WATER
from ..core.errors import SceneError

__all__ = ["SlenderElementSpec", "parse_slender_elements", "dnv_rounded_rectangle_cd",
           "DNV_ROUNDED_RECTANGLE"]

DNV_ROUNDED_RECTANGLE = {
    # L/D: [(R/D, C_D), ...]  (DNV-RP-C205, as reproduced in Wang (2016) figure 6.2)
    0.5: [(0.0, 2.5), (0.021, 2.2), (0.083, 1.9), (0.250, 1.6)],
    1.0: [(0.0, 2.2), (0.021, 2.0), (0.167, 1.2), (0.333, 1.0)],
    2.0: [(0.0, 1.6), (0.042, 1.4), (0.167, 0.7), (0.50, 0.4)],
    6.0: [(0.0, 0.89), (0.5, 0.29)],
}


def dnv_rounded_rectangle_cd(l_over_d: float, r_over_d: float, *,
                             interpolation: str = "nearest") -> float:
    """Steady-flow C_D of a rectangle with rounded corners (DNV-RP-C205, Re ~ 1e5).

    Parameters
    ----------
    l_over_d : L/D, length along the flow over the width facing it.
    r_over_d : corner radius over the width.
    interpolation : ``nearest`` (nearest tabulated R/D, as Wang (2016) table 6.2) or ``linear``
        (linear in R/D inside the row, clamped).

    The L/D row is the nearest tabulated one (0.5, 1, 2, 6; nearest in log(L/D)).
    """
    if not (l_over_d > 0 and r_over_d >= 0):
        raise SceneError(None, "dnv_rounded_rectangle", "L/D > 0 and R/D >= 0",
                         (l_over_d, r_over_d))
    rows = np.array(sorted(DNV_ROUNDED_RECTANGLE))
    row = float(rows[np.argmin(np.abs(np.log(rows) - np.log(l_over_d)))])
    tab = np.array(DNV_ROUNDED_RECTANGLE[row])
    if interpolation == "nearest":
        return float(tab[np.argmin(np.abs(tab[:, 0] - r_over_d)), 1])
    if interpolation == "linear":
        return float(np.interp(r_over_d, tab[:, 0], tab[:, 1]))
    raise SceneError(None, "interpolation", "nearest or linear", interpolation)


@dataclass(frozen=True, kw_only=True)
class SlenderElementSpec:
    """One element: name, end points p1, p2 (m, body), drag per length c2 = (cx, cy, cz)
    (N s^2/m^3) along the local axes, number of strips, inertia per length cm = rho C_M A
    (kg/m) along the local axes (used only with the inertia option)."""

    name: str
    p1: tuple
    p2: tuple
    c2: tuple
    n_strips: int
    cm: tuple = (0.0, 0.0, 0.0)


def _type_coefficients(node: Node, rho: float) -> dict:
    """Coefficients (cx, cy, cz) by element type from the three ways of giving them."""
    out: dict = {}

    def put(name, value, key):
        if name in out:
            raise node.error(key, f"drag of type {name!r} given once", "given twice")
        out[name] = value

    if "quadratic_drag_per_length" in node:
        q = node.child("quadratic_drag_per_length")
        for t in q.keys():
            tn = q.child(t)
            tn.reject_unknown({"c2x", "c2y", "c2z"})
            put(str(t), tuple(tn.float(k, 0.0, ge=0.0, unit="N s^2/m^3")
                              for k in ("c2x", "c2y", "c2z")), q.key(t))
    if "drag_coefficients" in node:
        q = node.child("drag_coefficients")
        for t in q.keys():
            tn = q.child(t)
            tn.reject_unknown({"cdx", "cdy", "cdz", "dx", "dy", "dz"})
            c = []
            for ax in "xyz":
                cd = tn.float("cd" + ax, 0.0, ge=0.0)
                d = tn.float("d" + ax, 0.0, ge=0.0, unit="m")
                if cd > 0.0 and d <= 0.0:
                    raise tn.error("d" + ax, f"the width (m) that goes with cd{ax}")
                c.append(0.5 * rho * cd * d)
            put(str(t), tuple(c), q.key(t))
    if "dnv_rounded_rectangle" in node:
        q = node.child("dnv_rounded_rectangle")
        for t in q.keys():
            tn = q.child(t)
            tn.reject_unknown({"x", "y", "z", "interpolation"})
            mode = tn.str("interpolation", "nearest", choices=("nearest", "linear"))
            c = []
            for ax in "xyz":
                if ax not in tn:
                    c.append(0.0)
                    continue
                an = tn.child(ax)
                an.reject_unknown({"d", "l", "r"})
                d = an.float("d", gt=0.0, unit="m")
                l_ = an.float("l", gt=0.0, unit="m")
                r = an.float("r", 0.0, ge=0.0, unit="m")
                c.append(0.5 * rho * dnv_rounded_rectangle_cd(l_ / d, r / d,
                                                              interpolation=mode) * d)
            put(str(t), tuple(c), q.key(t))
    return out


def parse_slender_elements(raw, *, file=None, key: str = "slender_elements",
                           rho: float = RHO_WATER, scale: dict | None = None) -> list:
    """Parse the raw ``slender_elements`` data of a vessel file.

    Parameters
    ----------
    raw : the mapping as read from the YAML file (``Vessel.slender_elements``).
    file : the vessel file (for messages).
    rho : water density (kg/m^3) for C = 0.5 rho C_D D.
    scale : optional {type: (cx, cy, cz)} or {type: {"c2y": value, ...}} overriding all or
        some coefficients of a type (scene-level tuning, e.g. Wang (2016) cases 3 and 4).

    Returns
    -------
    list of :class:`SlenderElementSpec`.  SceneError naming the file and key otherwise.
    """
    if raw is None:
        raise SceneError(file, key, "a slender_elements section in the vessel file")
    node = Node(raw, file, key)
    node.reject_unknown({"n_strips", "quadratic_drag_per_length", "drag_coefficients",
                         "dnv_rounded_rectangle", "inertia_per_length", "elements"})
    n_default = node.int("n_strips", 10, ge=1)
    coeffs = _type_coefficients(node, rho)
    inertia = {}
    if "inertia_per_length" in node:
        q = node.child("inertia_per_length")
        for t in q.keys():
            tn = q.child(t)
            tn.reject_unknown({"mx", "my", "mz"})
            inertia[str(t)] = tuple(tn.float(k, 0.0, ge=0.0, unit="kg/m")
                                    for k in ("mx", "my", "mz"))
    if scale:
        for t, c in scale.items():
            if t not in coeffs:
                raise SceneError(file, key, f"an element type among {sorted(coeffs)}", t)
            if isinstance(c, dict):  # partial override {c2x: .., c2y: .., c2z: ..}
                old = dict(zip(("c2x", "c2y", "c2z"), coeffs[t]))
                old.update({k: float(v) for k, v in c.items()})
                coeffs[t] = (old["c2x"], old["c2y"], old["c2z"])
            else:
                coeffs[t] = tuple(float(x) for x in c)
    out = []
    names = set()
    for i, en in enumerate(node.item_nodes("elements", min_len=1)):
        en.reject_unknown({"name", "type", "p1", "p2", "n_strips", "c2x", "c2y", "c2z"})
        name = en.str("name", f"element_{i + 1}")
        if name in names:
            raise en.error("name", "a unique element name", name)
        names.add(name)
        p1 = en.array("p1", shape=(3,), unit="m")
        p2 = en.array("p2", shape=(3,), unit="m")
        if np.linalg.norm(p2 - p1) <= 0.0:
            raise en.error("p2", "an end point different from p1", list(p2))
        cm = (0.0, 0.0, 0.0)
        if "type" in en:
            t = en.str("type")
            cm = inertia.get(t, cm)
            if t not in coeffs:
                raise en.error("type", "a type with drag coefficients: " +
                               (", ".join(sorted(coeffs)) or "(none given)"), t)
            c2 = coeffs[t]
        else:
            c2 = tuple(en.float(k, 0.0, ge=0.0, unit="N s^2/m^3") for k in ("c2x", "c2y", "c2z"))
        out.append(SlenderElementSpec(name=name, p1=tuple(map(float, p1)),
                                      p2=tuple(map(float, p2)), c2=tuple(map(float, c2)),
                                      n_strips=en.int("n_strips", n_default, ge=1),
                                      cm=tuple(map(float, cm))))
    return out

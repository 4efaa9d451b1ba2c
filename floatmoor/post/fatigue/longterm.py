"""Long-term fatigue: metocean scatter diagrams, annual damage, fatigue life and design check.

Scatter file (YAML)
-------------------
Either a joint Hs-Tp table with a direction distribution::

    name: my-site-scatter
    source: where the numbers come from
    spectrum: jonswap            # wave spectrum of every cell (gamma: null -> DNV-RP-C205 rule)
    gamma: null
    hs: [1.0, 3.0, 5.0]          # bin centres, m
    tp: [6.0, 8.0, 10.0, 12.0]   # bin centres, s
    probability: [[...], ...]    # (n_hs, n_tp) joint probability of the sea states
    u10: [5.0, 9.0, 12.0]        # optional: 1-hour mean wind at 10 m per Hs bin, m/s
    directions:                  # direction of travel of waves (and wind), from +x towards +y
      heading_deg: [0.0, 90.0, 180.0, 270.0]
      probability: [0.4, 0.2, 0.2, 0.2]

or an explicit list ``cells: [{hs: 3.0, tp: 9.0, heading_deg: 0.0, probability: 0.1,
u10: 9.0}, ...]``.  The probabilities (table x directions, or the cells) must sum to 1 (within
1 %; they are then normalised); cells of zero probability are dropped.

Refused (SceneError naming the file and key), before anything is allocated or run: more than
:data:`MAX_CELLS` sea states of non-zero probability; a sea state of non-zero probability
that cannot exist (significant steepness Hs/Lp above 1/10, the rule of scene files,
:func:`floatmoor.io.environment.check_sea_state`, in the scene's water depth); JONSWAP gamma
below 1 (above 7 warned); headings in radians or repeated (modulo 360 deg); bin centres not
increasing; a wind above :data:`MAX_U10`.

Annual damage: ``D_year = sum_i p_i d_i T_year`` with ``d_i`` the damage rate (1/s) of cell ``i``
(stationary sea state) and ``T_year = 365.25 days``.  Fatigue life ``1 / D_year``; design check
of DNV (2008) with :func:`~floatmoor.post.fatigue.tn_curves.design_check`.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ...core.config import Node

__all__ = [
    "SECONDS_PER_YEAR",
    "Scatter",
    "adjacent_ratio",
    "annual_damage",
    "dominant_cells",
    "load_scatter",
]

SECONDS_PER_YEAR = 365.25 * 86400.0

MAX_U10 = 60.0
"""Largest wind speed (m/s, 1-hour mean at 10 m) of a scatter cell: above any design value (the
North Sea 100-year wind is 36-41 m/s); knots or km/h typed for m/s."""

MAX_CELLS = 20_000
"""Most sea states (cells of non-zero probability, Hs x Tp x directions) of a scatter diagram:
each is one frequency-domain analysis (about 0.3 s) and a row of every (cell, location, line)
array of the result.  Design scatter diagrams hold a few hundred to a few thousand."""


@dataclass(frozen=True, kw_only=True)
class Scatter:
    """Sea-state cells of a scatter diagram (arrays of equal length; headings in rad)."""

    name: str
    source: str
    spectrum: str
    gamma: float | None
    hs: np.ndarray
    tp: np.ndarray
    heading: np.ndarray
    probability: np.ndarray
    u10: np.ndarray  # NaN: no wind
    file: object = None

    @property
    def n_cells(self) -> int:
        return int(self.hs.size)

    def label(self, i: int) -> str:
        return (f"Hs {self.hs[i]:g} m Tp {self.tp[i]:g} s dir {math.degrees(self.heading[i]):g}"
                " deg")


def _check_cells(root: Node, hs, tp, p, key_of, water_depth, gravity) -> None:
    """Every cell of non-zero probability a sea state that can exist."""
    from ...io.environment import check_sea_state
    for i in np.flatnonzero(p > 0):
        check_sea_state(root.file, key_of(int(i)), float(hs[i]), float(tp[i]),
                        water_depth=water_depth, gravity=gravity, stacklevel=4)


def _headings(node: Node, key: str, values) -> None:
    """Headings in degrees: not radians, not repeated (modulo 360 deg)."""
    from ...core.config import radians_list_hint
    hint = radians_list_hint(values)
    if hint:
        raise node.error(key, "headings in degrees", node.raw(key), hint)
    seen: dict[float, float] = {}
    for v in values:
        d = round(float(v) % 360.0, 6) % 360.0
        if d in seen:
            raise node.error(key, "distinct directions (modulo 360 deg)", node.raw(key),
                             f"{seen[d]:g} and {float(v):g} deg are the same direction")
        seen[d] = float(v)


def load_scatter(path, *, water_depth: float | None = None,
                 gravity: float = 9.80665) -> Scatter:
    """Read a scatter file (format and refusals in the module docstring); SceneError on bad
    input.  ``water_depth`` (m; None: deep water) for the steepness of its sea states."""
    import warnings

    from ...core.errors import FloatmoorWarning, SceneError
    root = Node.load(path)
    root.reject_unknown({"name", "description", "source", "spectrum", "gamma", "hs", "tp",
                         "probability", "u10", "directions", "cells"})
    spectrum = root.str("spectrum", "jonswap", choices=["jonswap", "pierson_moskowitz"])
    gamma = root.float("gamma", None, ge=1.0, allow_none=True)
    if gamma is not None and spectrum != "jonswap":
        raise root.error("gamma", f"no gamma for the {spectrum} spectrum (gamma is JONSWAP's)",
                         gamma)
    if gamma is not None and gamma > 7.0:
        warnings.warn(f"{root.file}: gamma: gamma = {gamma:g} is outside the range 1-7 of "
                      "measured seas", FloatmoorWarning, stacklevel=2)
    if ("cells" in root) == ("probability" in root):
        raise root.error("cells", "either a list of cells or an Hs-Tp table (hs, tp, "
                         "probability, directions)", "both" if "cells" in root else "neither")
    if "cells" in root:
        items = root.item_nodes("cells", min_len=1)
        if len(items) > MAX_CELLS:
            raise root.error("cells", f"at most {MAX_CELLS:,} sea states", f"{len(items):,}",
                             "each cell is one frequency-domain analysis")
        hs, tp, hd, p, u = [], [], [], [], []
        for c in items:
            c.reject_unknown({"hs", "tp", "heading_deg", "probability", "u10"})
            hs.append(c.float("hs", gt=0.0, unit="m"))
            tp.append(c.float("tp", gt=0.0, unit="s"))
            hd.append(c.angle_deg("heading_deg", 0.0))
            p.append(c.float("probability", ge=0.0))
            u.append(c.float("u10", math.nan, ge=0.0, le=MAX_U10, unit="m/s"))
        hs, tp, hd, p, u = map(np.asarray, (hs, tp, hd, p, u))
        key = "cells[].probability"
        _check_cells(root, hs, tp, p, lambda i: f"cells[{i}].hs", water_depth, gravity)
    else:
        hs_b = root.array("hs", gt=0.0, unit="m")
        tp_b = root.array("tp", gt=0.0, unit="s")
        if hs_b.ndim != 1 or tp_b.ndim != 1:
            raise root.error("hs", "1-D lists of bin centres hs and tp")
        for k, b in (("hs", hs_b), ("tp", tp_b)):
            if np.any(np.diff(b) <= 0):
                raise root.error(k, "bin centres in increasing order", root.raw(k))
        table = root.array("probability", shape=(hs_b.size, tp_b.size), ge=0.0)
        u_b = root.array("u10", np.full(hs_b.size, np.nan), shape=(hs_b.size,), ge=0.0,
                         unit="m/s")
        if np.any(u_b > MAX_U10):
            raise root.error("u10", f"1-hour mean winds at 10 m of at most {MAX_U10:g} m/s",
                             root.raw("u10"), "in knots or km/h? give m/s")
        d = root.child("directions")
        if not isinstance(d, Node):
            raise root.error("directions", "a mapping with heading_deg and probability lists", d)
        d.reject_unknown({"heading_deg", "probability"})
        hd_deg = d.array("heading_deg", unit="deg")
        if hd_deg.ndim != 1:
            raise d.error("heading_deg", "a list of headings in degrees", d.raw("heading_deg"))
        _headings(d, "heading_deg", hd_deg)
        hd_b = np.radians(hd_deg)
        pd_b = d.array("probability", shape=(hd_b.size,), ge=0.0)
        n_cells = int(np.count_nonzero(table)) * int(np.count_nonzero(pd_b))
        if n_cells > MAX_CELLS:
            raise root.error("probability", f"a scatter diagram of at most {MAX_CELLS:,} sea "
                             "states of non-zero probability (Hs-Tp cells x directions)",
                             f"{int(np.count_nonzero(table)):,} cells x "
                             f"{int(np.count_nonzero(pd_b))} directions = {n_cells:,}",
                             "each sea state is one frequency-domain analysis; merge bins or "
                             "directions")
        ih, it = np.nonzero(table)
        _check_cells(root, hs_b[ih], tp_b[it], table[ih, it],
                     lambda i: f"probability[{ih[i]}][{it[i]}] (hs {hs_b[ih[i]]:g} m, tp "
                               f"{tp_b[it[i]]:g} s)", water_depth, gravity)
        idir = np.flatnonzero(pd_b)
        ih, it, idir = (np.repeat(ih, idir.size), np.repeat(it, idir.size),
                        np.tile(idir, ih.size))
        hs, tp, hd, u = hs_b[ih], tp_b[it], hd_b[idir], u_b[ih]
        p = table[ih, it] * pd_b[idir]
        key = "probability"
    total = float(np.sum(p))
    if not abs(total - 1.0) <= 0.01:
        raise root.error(key, "probabilities summing to 1 (within 1 %)", f"sum {total:.6g}")
    keep = p > 0.0
    if not keep.any():
        raise SceneError(root.file, key, "some sea states of non-zero probability", "none")
    return Scatter(name=root.str("name", str(path)), source=root.str("source", ""),
                   spectrum=spectrum, gamma=gamma, hs=hs[keep], tp=tp[keep],
                   heading=hd[keep], probability=p[keep] / total, u10=u[keep], file=root.file)


def annual_damage(rates, probability) -> np.ndarray:
    """Annual damage ``sum_i p_i d_i T_year`` from damage rates (1/s) ``rates`` of shape
    ``(n_cells, ...)`` and the cell probabilities."""
    r = np.asarray(rates, float)
    p = np.asarray(probability, float).reshape((-1,) + (1,) * (r.ndim - 1))
    return np.sum(p * r, axis=0) * SECONDS_PER_YEAR


def dominant_cells(contribution, *, fraction: float = 0.5, max_cells: int = 3) -> np.ndarray:
    """Indices of the cells that carry the most damage: in decreasing order of
    ``contribution`` (n_cells,), until ``fraction`` of the total or ``max_cells`` cells."""
    c = np.nan_to_num(np.asarray(contribution, float))
    order = np.argsort(c)[::-1]
    total = c.sum()
    out = []
    acc = 0.0
    for i in order[:max(max_cells, 0)]:
        out.append(int(i))
        acc += c[i]
        if total > 0 and acc >= fraction * total:
            break
    return np.array(out, int)


def adjacent_ratio(damage, azimuth) -> tuple[float, int, int]:
    """``d_F`` of DNV (2008): the damage of the line adjacent (nearest in azimuth) to the most
    exposed line over that line's damage.  Returns ``(d_F, most exposed, adjacent)`` (line
    indices); NaN when fewer than two lines have damage."""
    d = np.nan_to_num(np.asarray(damage, float), nan=-1.0)
    az = np.asarray(azimuth, float)
    if d.size < 2 or d.max() <= 0:
        return math.nan, -1, -1
    i = int(np.argmax(d))
    gap = np.abs((az - az[i] + math.pi) % (2 * math.pi) - math.pi)
    gap[i] = np.inf
    gap[d < 0] = np.inf
    near = np.flatnonzero(gap <= gap.min() + 1e-9)
    j = int(near[np.argmax(d[near])])
    return float(d[j] / d[i]), i, j


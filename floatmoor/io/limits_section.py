"""The ``limits:`` section of a scene: offset limits and named points on the body.

```yaml
limits:
  offset:                               # horizontal offset of the body reference point from the
                                        # origin (its position at zero pose), m
    - {name: riser, max: 25.0}          # radial limit
    - name: gangway                     # per direction: the direction of the offset (from +x
      directions_deg: [0, 90, 180, 270] # towards +y), the limit interpolated linearly between
      max: [8.0, 12.0, 8.0, 12.0]       # them (periodic over 360 deg)
      limit_states: [ULS]               # optional: ULS, ALS or both (default both)
  points:                               # points fixed on the body, body axes, m
    - name: gangway_tip
      position: [40.0, 0.0, 25.0]
      max_horizontal: 6.0               # optional limits, m: horizontal excursion from the
      max_vertical: 4.0                 # point's position at zero pose, and |vertical| one
```

The limits change no analysis; ``floatmoor report`` checks the characteristic extremes over the
seeds (the Gumbel 90 % value of the seed maxima, as for the line tensions) against them, one
line in the verdict.  A point without a limit is reported, not checked.  Every mistake is a
:class:`~floatmoor.core.errors.SceneError` naming the key.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from ..core.config import Node

__all__ = ["LimitsSpec", "OffsetLimit", "PointSpec", "describe_limits", "parse_limits"]

_LS = ("ULS", "ALS")
MAX_OFFSET = 10_000.0
"""m: a larger offset limit (or point coordinate) is a typo."""


@dataclass(frozen=True, kw_only=True)
class OffsetLimit:
    """A radial limit (``directions`` empty, one value in ``max``) or a polar one (the limit at
    each direction of ``directions``, rad, increasing in [0, 2 pi))."""

    name: str
    max: tuple
    directions: tuple = ()
    limit_states: tuple = _LS

    def limit_at(self, direction) -> np.ndarray:
        """The limit (m) at the offset direction(s) ``direction`` (rad), linear in the angle
        between the given directions, periodic."""
        d = np.asarray(direction, float)
        if not self.directions:
            return np.full(d.shape, float(self.max[0]))
        th = np.asarray(self.directions, float)
        mx = np.asarray(self.max, float)
        th_ext = np.concatenate([th - 2 * math.pi, th, th + 2 * math.pi])
        mx_ext = np.concatenate([mx, mx, mx])
        return np.interp(np.mod(d, 2 * math.pi), th_ext, mx_ext)

    def describe(self) -> str:
        if not self.directions:
            return f"{self.name}: radial {self.max[0]:g} m"
        return f"{self.name}: " + ", ".join(
            f"{m:g} m at {math.degrees(t):g} deg" for t, m in zip(self.directions, self.max))


@dataclass(frozen=True, kw_only=True)
class PointSpec:
    """A named point fixed on the body (``position`` in body axes, m) and its optional limits
    (m): ``max_horizontal`` excursion and ``max_vertical`` (absolute) excursion from its
    position at zero pose."""

    name: str
    position: tuple
    max_horizontal: float | None = None
    max_vertical: float | None = None
    limit_states: tuple = _LS


@dataclass(frozen=True, kw_only=True)
class LimitsSpec:
    offset: tuple = ()
    points: tuple = ()


def _limit_states(node: Node) -> tuple:
    if "limit_states" not in node:
        return _LS
    vals = node.list("limit_states", min_len=1)
    for v in vals:
        if v not in _LS:
            raise node.error("limit_states", "a list of: ULS, ALS", vals)
    return tuple(dict.fromkeys(vals))


def parse_limits(node: Node) -> LimitsSpec:
    """Read a ``limits:`` mapping (see the module docstring)."""
    node.reject_unknown({"offset", "points"})
    offsets, names = [], set()
    for item in node.item_nodes("offset", []):
        item.reject_unknown({"name", "max", "directions_deg", "limit_states"})
        name = item.str("name")
        if name in names:
            raise item.error("name", "a name used once among the offset limits", name)
        names.add(name)
        if "directions_deg" in item:
            th = item.array("directions_deg", shape=(None,), unit="deg")
            if th.size < 2:
                raise item.error("directions_deg", "at least 2 directions (or a radial limit "
                                 "without directions_deg)", list(th))
            mx = item.array("max", shape=(th.size,), gt=0.0, unit="m")
            rad = np.mod(np.radians(th), 2 * math.pi)
            order = np.argsort(rad)
            if np.any(np.diff(rad[order]) <= 0):
                raise item.error("directions_deg", "distinct directions (modulo 360 deg)",
                                 list(th))
            if np.any(mx > MAX_OFFSET):
                raise item.error("max", f"limits below {MAX_OFFSET:g} m", list(mx))
            offsets.append(OffsetLimit(name=name, max=tuple(mx[order]),
                                       directions=tuple(rad[order]),
                                       limit_states=_limit_states(item)))
        else:
            m = item.float("max", gt=0.0, le=MAX_OFFSET, unit="m")
            offsets.append(OffsetLimit(name=name, max=(m,), limit_states=_limit_states(item)))
    points, pnames = [], set()
    for item in node.item_nodes("points", []):
        item.reject_unknown({"name", "position", "max_horizontal", "max_vertical",
                             "limit_states"})
        name = item.str("name")
        if name in pnames:
            raise item.error("name", "a name used once among the points", name)
        pnames.add(name)
        pos = item.array("position", shape=(3,), unit="m")
        if np.any(np.abs(pos) > MAX_OFFSET):
            raise item.error("position", f"coordinates within {MAX_OFFSET:g} m of the body "
                             "reference point", list(pos))
        points.append(PointSpec(
            name=name, position=tuple(float(x) for x in pos),
            max_horizontal=item.float("max_horizontal", None, gt=0.0, le=MAX_OFFSET, unit="m"),
            max_vertical=item.float("max_vertical", None, gt=0.0, le=MAX_OFFSET, unit="m"),
            limit_states=_limit_states(item)))
    return LimitsSpec(offset=tuple(offsets), points=tuple(points))


def describe_limits(limits: LimitsSpec | None, scene=None) -> list[str]:
    if limits is None:
        return []
    out = []
    for o in limits.offset:
        out.append("offset limit " + o.describe() + f" ({', '.join(o.limit_states)})")
    for p in limits.points:
        lim = [f"horizontal {p.max_horizontal:g} m" if p.max_horizontal else "",
               f"vertical {p.max_vertical:g} m" if p.max_vertical else ""]
        lim = [x for x in lim if x]
        out.append(f"point {p.name} at {list(p.position)} (body axes)"
                   + (f", limits {', '.join(lim)}" if lim else ", no limit (reported)"))
    return out

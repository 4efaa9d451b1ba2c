"""The ``site:`` section of a scene: water depth, densities and gravity.

```yaml
site: {water_depth: 150.0, water_density: 1025.0}   # gravity and air_density optional
```
"""

from __future__ import annotations

import warnings
from dataclasses import dataclass

from ..core.config import Node
from ..core.constants import GRAVITY, RHO_AIR, RHO_WATER
from ..core.errors import FloatmoorWarning

__all__ = ["SiteSpec", "parse_site", "SITE_KEYS"]

SITE_KEYS = ("water_depth", "water_density", "gravity", "air_density")

# Deepest point of the oceans (Challenger Deep) is about 10,935 m: anything deeper is a typo.
_MAX_OCEAN_DEPTH = 11_000.0


@dataclass(frozen=True, kw_only=True)
class SiteSpec:
    """The site: ``water_depth`` (m, > 0, flat seabed at z = -water_depth), ``water_density``
    (kg/m^3), ``gravity`` (m/s^2) and ``air_density`` (kg/m^3)."""

    water_depth: float
    water_density: float = RHO_WATER
    gravity: float = GRAVITY
    air_density: float = RHO_AIR


def parse_site(node: Node) -> SiteSpec:
    """Read a ``site:`` mapping into a :class:`SiteSpec`.

    Refused: a depth <= 0 or deeper than any ocean (11,000 m), densities or gravity <= 0.
    Warned (:class:`~floatmoor.FloatmoorWarning`): a water density outside 990-1050 kg/m^3,
    gravity outside 9.76-9.84 m/s^2 (the range over the Earth's surface) and an air density
    outside 1.0-1.4 kg/m^3 -- plausible as typos or a unit mix-up (g/cm^3, lb/ft^3).
    """
    node.reject_unknown(SITE_KEYS)
    depth = node.float("water_depth", gt=0.0, le=_MAX_OCEAN_DEPTH, unit="m")
    rho = node.float("water_density", RHO_WATER, gt=0.0, unit="kg/m^3")
    g = node.float("gravity", GRAVITY, gt=0.0, unit="m/s^2")
    rho_air = node.float("air_density", RHO_AIR, gt=0.0, unit="kg/m^3")
    _plausible(node, "water_density", rho, 990.0, 1050.0, "kg/m^3", "sea water is about 1025")
    _plausible(node, "gravity", g, 9.76, 9.84, "m/s^2", "standard gravity is 9.80665")
    _plausible(node, "air_density", rho_air, 1.0, 1.4, "kg/m^3", "air at 15 deg C is 1.226")
    return SiteSpec(water_depth=depth, water_density=rho, gravity=g, air_density=rho_air)


def _plausible(node: Node, key: str, value: float, lo: float, hi: float, unit: str, note: str):
    if key in node and not lo <= value <= hi:
        warnings.warn(f"{node.file}: {node.key(key)} = {value:g} {unit} is outside the usual "
                      f"range {lo:g}-{hi:g} {unit} ({note}); check the value and its unit",
                      FloatmoorWarning, stacklevel=3)

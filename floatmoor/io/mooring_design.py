"""Design keys of a mooring file: anchors, design life, corrosion allowance and its zones.

These keys change no analysis (tensions and motions are the same with or without them); the
design checks of ``floatmoor report`` read them (anchor checks, end-of-life capacity).  Format::

    design:                              # optional, top level of the mooring file
      design_life: 20.0                  # years (end-of-life capacity; default 20, stated in the
                                         # report as a default)
      corrosion: {splash: 0.4, catenary: 0.3, bottom: 0.4}   # mm of chain diameter per year by
                                         # zone (default: the design code's, DNV-OS-E301 table B1)
      corrosion_wire: {splash: 0.2, catenary: 0.1, bottom: 0.2}  # steel wire rope (default none:
                                         # the codes give no rate for wire)
      splash_zone_depth: 10.0            # m below the mean water line: a segment reaching above
                                         # -10 m is in the splash zone (default: the segment at
                                         # the fairlead is)
    defaults: {anchor_type: drag}        # per line keys may sit in defaults
    lines:
      - name: line1
        anchor_type: drag                # drag | plate | pile | suction | gravity
        anchor_capacity: 2.0e+7          # N, characteristic holding capacity (optional: without
                                         # it the anchor load is reported, not checked)
        anchor_uplift_deg: 5.0           # optional: the largest uplift angle the anchor is
                                         # designed for (replaces the code's rule for its type)
        segments:
          - {type: chain_studless_R4, diameter: 0.084, length: 1200.0,
             corrosion_zone: bottom}     # optional: the zone of the segment (splash, catenary,
                                         # bottom), instead of the one found from its geometry

Every mistake is a :class:`~floatmoor.core.errors.SceneError` naming the file and key.
:func:`parse_mooring_design` reads them; :func:`floatmoor.io.mooring_section.parse_mooring`
calls it so that ``floatmoor check`` refuses a typo.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field

from ..core.config import Node
from ..post.design_codes import ANCHOR_TYPES

__all__ = ["ANCHOR_TYPES", "AnchorSpec", "DESIGN_KEYS", "LINE_DESIGN_KEYS", "MooringDesign",
           "SEGMENT_DESIGN_KEYS", "ZONES", "parse_mooring_design"]

ZONES = ("splash", "catenary", "bottom")
DESIGN_KEYS = {"design_life", "corrosion", "corrosion_wire", "splash_zone_depth"}
LINE_DESIGN_KEYS = {"anchor_type", "anchor_capacity", "anchor_uplift_deg"}
SEGMENT_DESIGN_KEYS = {"corrosion_zone"}
DEFAULT_DESIGN_LIFE = 20.0
"""Years, when the mooring file gives none (as ``floatmoor fatigue --design-life``)."""
MAX_DESIGN_LIFE = 200.0
MAX_RATE = 5.0
"""mm/year: a larger allowance rate is a typo (the codes' rates are 0.1-1 mm/year)."""


@dataclass(frozen=True, kw_only=True)
class AnchorSpec:
    """One line's anchor: ``type`` (None: not given), characteristic holding ``capacity`` (N,
    None: not given), ``uplift_deg`` (the allowed uplift angle in degrees replacing the
    code's rule, None: the code's)."""

    type: str | None = None
    capacity: float | None = None
    uplift_deg: float | None = None


@dataclass(frozen=True, kw_only=True)
class MooringDesign:
    """The design keys of a mooring file (see the module docstring).  ``design_life`` and
    ``corrosion`` are None when not given (the report then states its default);
    ``segment_zones`` maps ``(line, segment index from the anchor)`` to a zone."""

    design_life: float | None = None
    corrosion: dict | None = None
    corrosion_wire: dict | None = None
    splash_zone_depth: float | None = None
    anchors: dict = field(default_factory=dict)
    segment_zones: dict = field(default_factory=dict)
    file: object = None

    @property
    def life(self) -> float:
        """The design life in years (the default when not given)."""
        return DEFAULT_DESIGN_LIFE if self.design_life is None else self.design_life

    def anchor(self, line: str) -> AnchorSpec:
        return self.anchors.get(line, AnchorSpec())


def _rates(node: Node, key: str) -> dict | None:
    if key not in node:
        return None
    c = node.child(key)
    c.reject_unknown(ZONES)
    return {z: c.float(z, 0.0, ge=0.0, le=MAX_RATE, unit="mm/year") for z in ZONES}


def _anchor(node: Node, defaults: Node | None) -> AnchorSpec:
    def src(key):
        return node if key in node or defaults is None or key not in defaults else defaults
    kw = {}
    s = src("anchor_type")
    if "anchor_type" in s:
        kw["type"] = s.str("anchor_type", choices=ANCHOR_TYPES)
    s = src("anchor_capacity")
    if "anchor_capacity" in s:
        kw["capacity"] = s.float("anchor_capacity", gt=0.0, le=1e10, unit="N")
    s = src("anchor_uplift_deg")
    if "anchor_uplift_deg" in s:
        kw["uplift_deg"] = math.degrees(s.angle_deg("anchor_uplift_deg", lo=0.0, hi=90.0))
    return AnchorSpec(**kw)


def parse_mooring_design(node: Node) -> MooringDesign:
    """The design keys of a ``mooring:`` mapping (the other keys are left to
    :func:`~floatmoor.io.mooring_section.parse_mooring`)."""
    kw = {"file": node.file}
    if "design" in node:
        d = node.child("design")
        d.reject_unknown(DESIGN_KEYS)
        kw["design_life"] = d.float("design_life", None, gt=0.0, le=MAX_DESIGN_LIFE,
                                    unit="years")
        kw["corrosion"] = _rates(d, "corrosion")
        kw["corrosion_wire"] = _rates(d, "corrosion_wire")
        kw["splash_zone_depth"] = d.float("splash_zone_depth", None, ge=0.0, unit="m")
    defaults = node.child("defaults", None)
    anchors, zones = {}, {}
    for ln in node.item_nodes("lines", min_len=1):
        name = ln.str("name")
        anchors[name] = _anchor(ln, defaults)
        src = ln if "segments" in ln or defaults is None else defaults
        for k, sn in enumerate(src.item_nodes("segments", [])):
            if "corrosion_zone" in sn:
                zones[(name, k)] = sn.str("corrosion_zone", choices=ZONES)
    return MooringDesign(anchors=anchors, segment_zones=zones, **kw)

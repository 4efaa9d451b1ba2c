"""``floatmoor export moordyn MOORING.yaml``: write a floatmoor mooring as a MoorDyn v2 input file.

``MOORING.yaml`` is a scene (its ``site`` and ``mooring`` are used) or a mooring file: its
water depth is ``--water-depth``, else the depth of its deepest anchor when every anchor is
given with its ``z`` (anchors given by radius and azimuth lie on a seabed the file does not
place: then ``--water-depth`` is needed); density and gravity default to 1025 kg/m^3 and
9.80665 m/s^2.
Each segment becomes a MoorDyn line, each joint a free point carrying the clump weight or buoy,
each fairlead a coupled point; see :func:`floatmoor.io.moordyn.export` for the conversions.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from .argtypes import positive_float

HELP = "export a floatmoor mooring (or a scene's) as a MoorDyn v2 input file"


def add_arguments(p: argparse.ArgumentParser) -> None:
    """Arguments of ``floatmoor export``."""
    p.add_argument("format", choices=["moordyn"], help="the output format")
    p.add_argument("file", metavar="MOORING.yaml", help="a mooring file or a scene")
    p.add_argument("--out", metavar="FILE", default=None,
                   help="file to write (default: MOORING.dat beside the input)")
    p.add_argument("--water-depth", type=positive_float, default=None, metavar="M",
                   help="water depth, m (a mooring file: default the depth of its deepest "
                        "anchor when every anchor has its z)")
    p.add_argument("--water-density", type=float, default=1025.0, metavar="KG/M3")
    p.add_argument("--gravity", type=float, default=9.80665, metavar="M/S2")
    p.add_argument("--segments", type=int, default=None, metavar="N",
                   help="MoorDyn segments per line (default: the file's finite_element options)")


def load_system(path, *, water_depth=None, water_density=1025.0, gravity=9.80665):
    """The :class:`MooringSystem` of a mooring file or of a scene."""
    from ..core.config import Node
    from ..core.errors import SceneError
    from ..io.mooring_section import parse_mooring

    node = Node.load(path)
    if "site" in node:
        from .. import load_scene

        scene = load_scene(path)
        if scene.mooring is None:
            raise SceneError(path, "mooring", "a mooring section to export")
        s = scene.site
        mnode = node.child_or_file("mooring")
        return parse_mooring(mnode, water_depth=s.water_depth, water_density=s.water_density,
                             gravity=s.gravity)
    if water_depth is None:
        water_depth = _depth_from_anchors(node)
        if water_depth is None:
            raise SceneError(path, "", "a scene, or a mooring file with --water-depth M (its "
                             "anchors lie on a seabed the file does not place: they have no "
                             "z)", "a mooring file without --water-depth",
                             f"floatmoor export moordyn {path} --water-depth M, or export the "
                             "scene that uses it (its site gives the depth)")
        print(f"water depth {water_depth:g} m: the depth of the deepest anchor of {path}")
    return parse_mooring(node, water_depth=water_depth, water_density=water_density,
                         gravity=gravity)


def _depth_from_anchors(node) -> float | None:
    """The depth of the deepest anchor when every line (or the defaults) gives its anchor
    with ``z`` (and none is declared above the seabed), else None."""
    defaults = node.data.get("defaults") if isinstance(node.data.get("defaults"), dict) else {}
    lines = node.data.get("lines")
    if not isinstance(lines, list) or not lines:
        return None
    zs = []
    for ln in lines:
        a = ln.get("anchor", defaults.get("anchor")) if isinstance(ln, dict) else None
        if not isinstance(a, dict) or "z" not in a or a.get("above_seabed") is True:
            return None
        z = a["z"]
        if isinstance(z, bool) or not isinstance(z, (int, float)):
            return None
        zs.append(float(z))
    depth = -min(zs)
    return depth if depth > 0 else None


def run(args: argparse.Namespace) -> int:
    """Run ``floatmoor export``."""
    from ..io.moordyn import export

    system = load_system(args.file, water_depth=args.water_depth,
                         water_density=args.water_density, gravity=args.gravity)
    out = Path(args.out) if args.out else Path(args.file).with_suffix(".dat")
    export(system, out, n_segments=args.segments)
    print(f"wrote {out}: MoorDyn v2, {system.n_lines} lines")
    return 0

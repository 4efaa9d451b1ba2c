"""``floatmoor import moordyn|map|openfast FILE --out ...``: read models made for other tools.

* ``moordyn FILE.dat --out mooring.yaml``: a MoorDyn v1 or v2 input file
  (:mod:`floatmoor.io.moordyn`);
* ``map FILE.dat --out mooring.yaml``: a MAP++ input file (:mod:`floatmoor.io.map`; give
  ``--water-depth`` when a node has ``Z = depth``);
* ``openfast FILE.fst --out DIR``: an OpenFAST floating model: ``DIR/vessel.yaml`` (ElastoDyn
  mass and inertia, HydroDyn WAMIT database and additional damping and stiffness),
  ``DIR/mooring.yaml`` (its MoorDyn or MAP++ file) and ``DIR/scene.yaml`` (the SeaState sea
  state) (:mod:`floatmoor.io.openfast`).

The written files carry a comment per unit or convention conversion; whatever could not be
mapped is printed as one warning.  Water depth, density and gravity of a mooring import go in
the scene's ``site:`` section (the command prints them).
"""

from __future__ import annotations

import argparse
from pathlib import Path

from .argtypes import positive_float

HELP = "import a MoorDyn, MAP++ or OpenFAST model as floatmoor files"


def add_arguments(p: argparse.ArgumentParser) -> None:
    """Arguments of ``floatmoor import``."""
    p.add_argument("format", choices=["moordyn", "map", "openfast"], help="the input format")
    p.add_argument("file", metavar="FILE", help="the input file (.dat, or .fst for openfast)")
    p.add_argument("--out", required=True, metavar="PATH",
                   help="mooring.yaml to write (moordyn, map) or output folder (openfast)")
    p.add_argument("--water-depth", type=positive_float, default=None, metavar="M",
                   help="water depth, m (default: the file's, else the deepest anchor; a "
                        "MAP++ file with nodes at Z = depth needs it)")
    p.add_argument("--water-density", type=positive_float, default=None, metavar="KG/M3",
                   help="water density (default: the file's, else 1025)")
    p.add_argument("--gravity", type=positive_float, default=None, metavar="M/S2",
                   help="gravity (default: the file's, else 9.80665)")
    p.add_argument("--model", choices=["quasi-static", "finite-element"], default="quasi-static",
                   help="line model written into the mooring file (default quasi-static)")


def run(args: argparse.Namespace) -> int:
    """Run ``floatmoor import``."""
    if args.format == "openfast":
        from ..io.openfast import import_openfast

        res = import_openfast(args.file, args.out, model=args.model)
        for what, path in res.files.items():
            print(f"wrote {what}: {path}")
        print(f"run it with: floatmoor run {res.files['scene']}")
        return 0
    if args.format == "moordyn":
        from ..io.moordyn import read_model
    else:
        from ..io.map import read_model
    r = read_model(args.file, water_depth=args.water_depth, water_density=args.water_density,
                   gravity=args.gravity, model=args.model)
    out = Path(args.out)
    out.parent.mkdir(parents=True, exist_ok=True)
    out.write_text(r.yaml_text)
    print(f"wrote {out}: {r.system.n_lines} lines ({r.format})")
    print(f"scene site: {{water_depth: {r.water_depth:g}, water_density: {r.water_density:g}, "
          f"gravity: {r.gravity:g}}}")
    return 0

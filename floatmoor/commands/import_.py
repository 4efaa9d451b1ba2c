"""``floatmoor import moordyn|map|openfast FILE --out ...``: read models made for other tools.

* ``moordyn FILE.dat --out mooring.yaml``: a MoorDyn v1 or v2 input file
  (:mod:`floatmoor.io.moordyn`);
* ``map FILE.dat --out mooring.yaml``: a MAP++ input file (:mod:`floatmoor.io.map`; give
  ``--water-depth`` when a node has ``Z = depth``);
* ``openfast FILE.fst --out DIR [--hydrodyn FILE]``: an OpenFAST floating model (OpenFAST 2.0
  to 5.0 files): ``DIR/vessel.yaml`` (every ElastoDyn mass, HydroDyn ballast, WAMIT database,
  additional preload, damping and stiffness, the mass budget), ``DIR/mooring.yaml`` (its
  MoorDyn or MAP++ file) and ``DIR/scene.yaml`` (the sea state of SeaState or HydroDyn)
  (:mod:`floatmoor.io.openfast`).  ``--hydrodyn`` reads another HydroDyn file than the
  driver's (e.g. the potential-flow variant a model ships beside a strip-theory one).  The
  command prints the mass budget and everything not mapped (file, line, what floatmoor does
  instead), checks the written scene as ``floatmoor check`` does and prints ``run it with``
  only for a scene that passes; a scene that does not pass is exit status 2.

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
    p.add_argument("--hydrodyn", default=None, metavar="FILE",
                   help="openfast: a HydroDyn file to read instead of the driver's HydroFile")


def run(args: argparse.Namespace) -> int:
    """Run ``floatmoor import``."""
    if args.format == "openfast":
        import warnings

        from ..core.errors import FloatmoorWarning
        from ..io.openfast import import_openfast

        with warnings.catch_warnings():
            warnings.simplefilter("ignore", FloatmoorWarning)  # printed below, in full
            res = import_openfast(args.file, args.out, model=args.model, hydrodyn=args.hydrodyn)
        for what, path in res.files.items():
            print(f"wrote {what}: {path}")
        for line in res.budget.lines():
            print(line)
        if res.unmapped:
            print("not mapped (file:line key: what -- what floatmoor does instead):")
            for u in res.unmapped:
                print(f"  - {u}")
        for n in res.notes:
            print(f"note: {n}")
        if not res.budget.closes:
            print(f"WARNING: the mass budget does not close within 0.5 %: "
                  f"{res.budget.likely_missing()}")
        if res.check is not None:
            print(f"floatmoor check refuses the written scene: {res.check}")
            return 2
        print(f"floatmoor check: {res.files['scene']}: OK")
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

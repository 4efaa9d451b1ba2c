"""``floatmoor statics SCENE.yaml``: static equilibrium, line tensions, stiffness, restoring curves.

Prints the still-water equilibrium pose of the scene's vessel on its mooring (hydrostatics,
net buoyancy, quasi-static lines, and an optional constant force), each line's fairlead and
anchor tension, angle, grounded length and utilisation, and the analytic 6x6 mooring stiffness.
``--curve`` adds restoring force against offset for the given headings; ``--out`` writes the
equilibrium (and curves) as netCDF.
"""

from __future__ import annotations

import argparse
from pathlib import Path

HELP = "static equilibrium, line tensions, 6x6 stiffness and restoring curves"


def _floats(n: int | None):
    def parse(text: str):
        try:
            vals = [float(v) for v in text.replace(" ", "").split(",") if v != ""]
        except ValueError:
            raise argparse.ArgumentTypeError(f"expected comma-separated numbers, found {text!r}") from None
        if n is not None and len(vals) != n:
            raise argparse.ArgumentTypeError(f"expected {n} comma-separated numbers, found {text!r}")
        if not vals:
            raise argparse.ArgumentTypeError("expected at least one number")
        return vals
    return parse


def add_arguments(p: argparse.ArgumentParser) -> None:
    """Arguments of ``floatmoor statics``."""
    p.add_argument("scene", metavar="SCENE.yaml", help="the scene file (vessel and mooring needed)")
    p.add_argument("--force", type=_floats(6), default=None, metavar="FX,FY,FZ,MX,MY,MZ",
                   help="constant external force and moment on the body, N and N m about the "
                        "reference point (e.g. mean wind + current + drift)")
    p.add_argument("--fail", nargs="+", default=None, metavar="LINE",
                   help="remove these lines (ALS), in addition to the scene's failed_lines")
    p.add_argument("--curve", type=_floats(None), default=None, metavar="DEG[,DEG...]",
                   help="print restoring curves for these offset headings, deg")
    p.add_argument("--max-offset", type=float, default=40.0, metavar="M",
                   help="largest offset of the restoring curves, m (default 40)")
    p.add_argument("--out", metavar="FILE", default=None, help="write the results as netCDF")


def format_curves(ds) -> str:
    """Restoring force (kN) and most loaded line tension (kN) against offset, per heading."""
    lines = ["Restoring curves (offsets from the still-water equilibrium; force opposing the offset)",
             "  heading  offset   restoring   stiffness   max fairlead tension",
             "    deg      m         kN         kN/m       kN   (line)"]
    for h in ds["heading"].values:
        c = ds.sel(heading=h)
        for s in c["offset"].values:
            r = c.sel(offset=s)
            tf = r["fairlead_tension"].values
            j = int(tf.argmax())
            lines.append(f"  {h:7.1f} {s:7.1f} {float(r['restoring_force']) / 1e3:11.1f} "
                         f"{float(r['stiffness_along_heading']) / 1e3:11.2f} "
                         f"{tf[j] / 1e3:10.1f}   ({c['line'].values[j]})")
    return "\n".join(lines)


def run(args: argparse.Namespace) -> int:
    """Solve and print; returns the exit status."""
    import numpy as np
    import xarray as xr

    from ..analyses.statics import equilibrium, restoring_curves
    from ..io.build import build

    built = build(args.scene, failed_lines=args.fail)
    from ..io.plausibility import check_built
    check_built(built)
    if args.out:
        from .argtypes import check_out_file
        check_out_file(args.out)
    res = equilibrium(built, external_force=args.force)
    print(f"scene: {built.scene.name}  [{built.scene.file}]")
    print(f"net buoyancy at zero pose: {built.static_force[2] / 1e3:.1f} kN"
          + (f"; external force {args.force}" if args.force else ""))
    print(res.summary())
    unknown = built.mooring.unknown_mbs() if built.mooring is not None else ""
    if unknown:
        print(f"utilisation nan: {unknown}")
    curves = None
    if args.curve:
        offsets = np.linspace(0.0, args.max_offset, 9)
        curves = restoring_curves(built, headings_deg=args.curve, offsets=offsets)
        print()
        print(format_curves(curves))
    if args.out:
        ds = res.to_dataset()
        for name, var in ds.data_vars.items():
            if var.dtype == bool:
                ds[name] = var.astype("int8")
        if curves is not None:
            c = curves.rename({"line": "curve_line", "dof": "curve_dof"})
            c = c.rename({v: f"curve_{v}" for v in c.data_vars})
            ds = xr.merge([ds, c], combine_attrs="drop_conflicts")
        ds.attrs["scene"] = str(built.scene.file)
        from ..analyses.fingerprint import FINGERPRINT_ATTR, fingerprint_json
        ds.attrs[FINGERPRINT_ATTR] = fingerprint_json(built.scene, {"fail": args.fail,
                                                                    "force": args.force})
        path = Path(args.out)
        ds.to_netcdf(path)
        print(f"written: {path}")
    return 0

"""``floatmoor fd SCENE.yaml [--out FILE]``: frequency-domain analysis, MIMOSA-style table.

Prints the motions (mean, LF, WF, eq. 2.49 total) and the line-tension table of Wang (2016)
figure 5.9; ``--out`` writes the full result (spectra, RAOs, per-line columns) as netCDF.
"""

from __future__ import annotations

import argparse
from pathlib import Path

from .argtypes import check_out_file, positive_float

HELP = "frequency-domain analysis (mean, LF, WF, Rayleigh maxima, line tensions)"


def add_arguments(p: argparse.ArgumentParser) -> None:
    """Arguments of ``floatmoor fd``."""
    p.add_argument("scene", metavar="SCENE.yaml", help="the scene file (vessel and mooring needed)")
    p.add_argument("--out", metavar="FILE", default=None,
                   help="write the result Dataset as netCDF (.nc)")
    p.add_argument("--duration", type=positive_float, default=None, metavar="S",
                   help="storm duration for the Rayleigh maxima, s (default 10800)")
    p.add_argument("--drift", choices=("auto", "newman", "qtf"), default=None,
                   help="slowly varying drift: the scene's choice (auto: the full QTF when "
                        "present), Newman, or QTF; other than auto: in the FD alone")
    p.add_argument("--wave-drift-damping", action="store_true",
                   help="add Aranha's wave drift damping to the LF system (the scene key "
                        "forces: wave_drift_damping puts it in both domains)")
    p.add_argument("--lf-cutoff", type=positive_float, default=None, metavar="S",
                   help="LF cut-off period, s (default 30)")
    p.add_argument("--tension-model", choices=("quasi_static", "dynamic"), default=None,
                   help="WF line tension: quasi-static catenary, or dynamic (FE lines in the "
                        "frequency domain; LF stays quasi-static unless --line-damping fe)")
    p.add_argument("--line-current-drag", action="store_true",
                   help="include the static current drag on the lines in the mean position "
                        "(each line's FE statics in the current; scene key "
                        "frequency_domain: line_current_drag)")
    p.add_argument("--line-damping", choices=("none", "fe"), default=None,
                   help="LF mooring-line damping: none (default), or fe: the FE lines in the "
                        "frequency domain under the WF and LF fairlead motion (scene key "
                        "frequency_domain: line_damping)")


def to_netcdf(ds, path) -> Path:
    """Write a frequency-domain result as netCDF (booleans stored as int8)."""
    path = Path(path)
    path.parent.mkdir(parents=True, exist_ok=True)
    out = ds.copy()
    for name, var in out.data_vars.items():
        if var.dtype == bool:
            out[name] = var.astype("int8")
    out.to_netcdf(path)
    return path


def run(args: argparse.Namespace) -> int:
    """Run the analysis and print the table; returns the exit status.  A first run after an
    installation says that numba compiles the kernels (``--tension-model dynamic``: the FE
    line kernels, about 30-40 s once)."""
    from .compile_notice import compile_notice
    with compile_notice("the statics and frequency-domain kernels"):
        return _run(args)


def _run(args: argparse.Namespace) -> int:
    from ..analyses.fd_dataset import format_table
    from ..analyses.frequency_domain import frequency_domain

    if args.out:
        check_out_file(args.out)
    from ..io.build import build
    from ..io.plausibility import check_built
    built0 = build(args.scene)
    check_built(built0, time_domain=False)
    overrides = {}
    if args.duration is not None:
        overrides["duration"] = args.duration
    if args.drift is not None:
        overrides["drift"] = args.drift
    if args.wave_drift_damping:
        overrides["wave_drift_damping"] = True
    if args.lf_cutoff is not None:
        overrides["lf_cutoff_period"] = args.lf_cutoff
    if args.tension_model is not None:
        overrides["tension_model"] = args.tension_model
    if args.line_current_drag:
        overrides["line_current_drag"] = True
    if args.line_damping is not None:
        overrides["line_damping"] = args.line_damping
    bounds = _fibre_bounds(built0)
    if bounds:
        return _run_fibre_bounds(args, overrides, bounds)
    ds = frequency_domain(args.scene, **overrides)
    print(format_table(ds))
    if args.out:
        from ..analyses.fingerprint import FINGERPRINT_ATTR, fingerprint_json
        ds.attrs[FINGERPRINT_ATTR] = fingerprint_json(args.scene, overrides)
        print(f"written: {to_netcdf(ds, args.out)}")
    return 0


def _fibre_bounds(built) -> tuple[str, ...]:
    """The fibre stiffness bounds of a built scene whose mooring has fibre ropes (``()``
    without)."""
    if built.mooring is None or not built.mooring.has_fibre:
        return ()
    return built.scene.analysis.fibre_bounds


def _run_fibre_bounds(args, overrides, bounds) -> int:
    """Fibre ropes: the analysis per stiffness bound (``analysis.fibre_stiffness``); with both,
    both tables, ``--out`` as FILE_lower.nc and FILE_upper.nc, and the governing bound (the
    smaller line safety factor)."""
    import numpy as np

    from ..analyses.fd_dataset import format_table
    from ..analyses.fingerprint import FINGERPRINT_ATTR, fingerprint_json
    from ..analyses.frequency_domain import frequency_domain
    from ..io.build import build, with_fibre_bound
    sf = {}
    for b in bounds:
        ds = frequency_domain(with_fibre_bound(build(args.scene), b), **overrides)
        ds.attrs["fibre_stiffness"] = b
        print(f"fibre stiffness bound: {b}")
        print(format_table(ds))
        sf[b] = float(np.nanmin(ds["safety_factor"].values))
        if args.out:
            out = Path(args.out)
            if len(bounds) > 1:
                out = out.with_name(f"{out.stem}_{b}{out.suffix}")
            ds.attrs[FINGERPRINT_ATTR] = fingerprint_json(args.scene,
                                                          {**overrides, "fibre_stiffness": b})
            print(f"written: {to_netcdf(ds, out)}")
    if len(bounds) > 1:
        gov = min(sf, key=sf.get)
        print("fibre stiffness bounds: " + ", ".join(f"{b} smallest safety factor {v:.2f}"
                                                     for b, v in sf.items())
              + f"; governing: {gov}")
    return 0

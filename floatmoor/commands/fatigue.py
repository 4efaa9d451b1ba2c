"""``floatmoor fatigue SCENE.yaml --scatter FILE``: fatigue limit state (FLS) of the lines.

Runs the analysis :func:`floatmoor.analyses.fatigue.fatigue_analysis` (frequency domain over
the scatter diagram, time domain on the dominant cells) and prints the fatigue life per line and
location and the DNV (2008) design check (:func:`~floatmoor.analyses.fatigue.format_fatigue`).
"""

from __future__ import annotations

import argparse

from .argtypes import positive_float

HELP = "fatigue limit state: annual damage, fatigue life and DNV check per line and location"

DEFAULT_METHOD = "dual_narrow_band"
"""As :data:`floatmoor.analyses.fatigue.DEFAULT_METHOD` (not imported: building the parser
imports nothing heavy)."""
METHOD_CHOICES = ("combined_spectrum", "dual_narrow_band", "dirlik", "simple_summation")
"""The spectral methods (:data:`floatmoor.post.fatigue.spectral.METHODS`, repeated here so that
building the parser imports nothing heavy)."""


# -- command -------------------------------------------------------------------------------------
def add_arguments(p: argparse.ArgumentParser) -> None:
    """Arguments of ``floatmoor fatigue``."""
    p.add_argument("scene", metavar="SCENE.yaml", help="the scene file (vessel and mooring)")
    p.add_argument("--scatter", required=True, metavar="FILE",
                   help="metocean scatter file (Hs, Tp, directions, probabilities)")
    p.add_argument("--method", choices=METHOD_CHOICES, default=DEFAULT_METHOD,
                   help="spectral method of the FD damage (default dual_narrow_band)")
    p.add_argument("--design-life", type=positive_float, default=20.0, metavar="YEARS",
                   help="design life, years (default 20)")
    p.add_argument("--corrosion", type=float, nargs=2, default=None,
                   metavar=("CATENARY", "BOTTOM"),
                   help="corrosion/wear allowance, mm/year, catenary and bottom "
                   "(default DNV-OS-E301 0.3 and 0.4; 0 0 for none)")
    p.add_argument("--td-cells", type=int, default=3, metavar="N",
                   help="time-domain runs on at most N dominant cells (0: none; default 3)")
    p.add_argument("--td-duration", type=positive_float, default=10800.0, metavar="S",
                   help="length of each time-domain storm after the transient (default 10800)")
    p.add_argument("--seed", type=int, default=1, help="time-domain seed (default 1)")
    p.add_argument("--out", metavar="FILE", default=None, help="write the result as netCDF "
                   "(floatmoor report --fatigue FILE adds it to the design report)")
    p.add_argument("--report", metavar="DIR", default=None,
                   help="write the FLS report section alone (fls.md, fls.html) in DIR")
    p.add_argument("--quiet", action="store_true", help="no progress line")


def run(args: argparse.Namespace) -> int:
    """Run the analysis and print the tables; returns the exit status."""
    import sys
    import time

    from ..analyses.fatigue import fatigue_analysis, format_fatigue
    corrosion = None
    if args.corrosion is not None:
        corrosion = {"catenary": args.corrosion[0], "bottom": args.corrosion[1]}

    last = [time.perf_counter()]

    def progress(i, n):
        if args.quiet:
            return
        if sys.stderr.isatty():
            print(f"\r  frequency domain: sea state {i}/{n}", end="" if i < n else "\n",
                  file=sys.stderr)
        elif i == n or time.perf_counter() - last[0] > 10.0:
            last[0] = time.perf_counter()
            print(f"  frequency domain: sea state {i}/{n}", file=sys.stderr, flush=True)

    from .compile_notice import compile_notice
    with compile_notice("the frequency- and time-domain kernels"):
        ds = fatigue_analysis(args.scene, args.scatter, method=args.method,
                              design_life=args.design_life, corrosion=corrosion,
                              td_cells=args.td_cells, td_duration=args.td_duration,
                              seed=args.seed, progress=progress)
    print(format_fatigue(ds))
    if args.out:
        from .fd import to_netcdf
        print(f"written: {to_netcdf(ds, args.out)}")
    if args.report:
        from ..post.fatigue_report import write_fls_report
        files = write_fls_report(ds, args.report)
        print(f"written: {files['markdown']}, {files['html']}")
    return 0

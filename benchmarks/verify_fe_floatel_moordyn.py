"""Verification of the FE line in the flagship's regime against MoorDyn: lines of the
Floatel-like mooring (chain 1200 m + polyester 1200 m + chain 250 m, 150 m depth, about 1100 m
of chain on the seabed) driven by the fairlead track of a quasi-static flagship storm (3 hours
after the 1200 s transient), with identical inputs in both codes
(tests/mooring/fe/moordyn_floatel.py: the line written by floatmoor's MoorDyn exporter, the
scene's current as MoorDyn's steady profile, MoorDyn's seabed law in both, no internal damping;
the start-of-step position and chord velocity of one piecewise-linear fairlead track).

Cases: line 1 (windward, slack: the line that failed before the energy audit) with the current
and without it, line 7 (leeward, the most loaded) with the current; seabed friction off in both
(floatmoor's friction on as a separate case: line 1 with the velocity-ramp friction
``mu = 0.7``, against floatmoor without it).

Printed per case: fairlead and anchor tension mean, std, max, min over the 3-hour window,
MoorDyn and floatmoor, and floatmoor's difference; the CPU time of each.

Run: ``python benchmarks/verify_fe_floatel_moordyn.py [--seed 19] [--motion SEED.nc]
[--cases line1-current line1-calm line7-current line1-friction] [--duration 12000]``
(``--motion``: a seed file of ``floatmoor run scenes/floatel_100yr.yaml`` instead of running
the quasi-static storm here).  MoorDyn: 132 segments (20 m, floatmoor's count), RK4, dtM 2 ms
(RK2 blows up on an undamped line; 2 ms and 1 ms give the same statistics within 0.1 %).
"""

from __future__ import annotations

import argparse
import os
import platform
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))

from tests.mooring.fe import moordyn_floatel as FL  # noqa: E402

CASES = {
    "line1-current": ("line1", True, 0.0),
    "line1-calm": ("line1", False, 0.0),
    "line7-current": ("line7", True, 0.0),
    "line1-friction": ("line1", True, 0.7),
}


def stats_row(name, T, window):
    s = FL.statistics(T, window)
    return s, f"{name:<9}" + "".join(f"{s[k] / 1e3:10.1f}" for k in ("mean", "std", "max", "min"))


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--seed", type=int, default=19)
    ap.add_argument("--motion", default=None)
    ap.add_argument("--duration", type=float, default=None)
    ap.add_argument("--cases", nargs="+", default=list(CASES))
    ap.add_argument("--dtm", type=float, default=2e-3)
    args = ap.parse_args()
    print(f"# {platform.machine()}, Python {platform.python_version()}; load "
          f"{' / '.join(f'{v:.2f}' for v in os.getloadavg())}")
    t, poses, transient = FL.storm_track(seed=args.seed, duration=args.duration,
                                         motion_file=args.motion)
    window = t >= transient
    print(f"# fairlead track: quasi-static flagship storm, seed {args.seed}, {t[-1]:g} s, "
          f"statistics after {transient:g} s")
    for name in args.cases:
        line, current, mu = CASES[name]
        c = FL.case(line, current=current)
        r, x = FL.fairlead_track(c, t, poses)
        print(f"\n## {name}: {line}, current {'on' if current else 'off'}")
        print(f"{'':<9}{'mean':>10}{'std':>10}{'max':>10}{'min':>10}   kN")
        if mu == 0.0:
            Tf_m, Ta_m, cpu_m = FL.run_moordyn(c, t, r, dtm=args.dtm)
        Tf, Ta, Tm, cpu, ln = FL.run_floatmoor(c, t, x, pose0=poses[0])
        if mu:
            cf = FL.case(line, current=current, friction=mu)
            Tf2, Ta2, Tm2, cpu2, ln2 = FL.run_floatmoor(cf, t, x, pose0=poses[0])
        for what, a, b in (("fairlead", Tf, None if mu else Tf_m),
                           ("anchor", Ta, None if mu else Ta_m)):
            print(what)
            if b is not None:
                sb, row = stats_row("MoorDyn", b, window)
                print(row)
            sa, row = stats_row("floatmoor", a, window)
            print(row + ("" if b is None else "   diff " + " ".join(
                f"{k} {100 * (sa[k] / sb[k] - 1):+.1f} %" for k in ("mean", "std", "max"))))
            if mu:
                s2, row = stats_row(f"mu {mu:g}", Tf2 if what == "fairlead" else Ta2, window)
                print(row + "   friction effect " + " ".join(
                    f"{k} {100 * (s2[k] / sa[k] - 1):+.1f} %" for k in ("mean", "std", "max")))
        print(f"largest tension along the line {np.max(Tm[window]) / 1e3:.1f} kN, fairlead "
              f"maximum {np.max(Tf[window]) / 1e3:.1f} kN; energy audit: "
              f"{ln.audit['energy_halvings']} step(s) halved, "
              f"{ln.audit['energy_unresolved_steps']} unresolved; CPU floatmoor {cpu:.1f} s"
              + ("" if mu else f", MoorDyn {cpu_m:.1f} s"))
    print(f"\n# load {' / '.join(f'{v:.2f}' for v in os.getloadavg())}")


if __name__ == "__main__":
    main()

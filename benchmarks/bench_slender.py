"""Viscous-drift benchmark: cost of slender elements in the flagship storm.

The Floatel-like semi in the 100-year storm (``scenes/floatel_100yr.yaml``: Hs 16 m, Tp 18.2 s,
NPD wind, current 0.94 m/s, 12 quasi-static lines, radiation memory, RK4 dt = 0.1 s), 10800 s,
run without a viscous model (case 1), with the six slender elements of the vessel file (case 2,
Wang (2016) table 6.1/6.3) and with the correction formula (case 5).  Prints, per case, the setup
time (scene models, FFT series, kinematics table, static equilibrium), the time loop and the
total, and the added fraction against case 1; the kinematics table's size; the single-seed
surge statistics (not a study: one seed).  Runs are interleaved (1, 2, 5, 1, 2, 5) and the
smaller of the two times is kept, because the 2-core machine is shared.

Run: ``.venv/bin/python benchmarks/bench_slender.py [--duration 10800] [--dt 0.1]``
"""

from __future__ import annotations

import argparse
import os
import platform
import time
import warnings
from pathlib import Path

import numpy as np

ROOT = Path(__file__).resolve().parents[1]
SCENE = ROOT / "scenes" / "floatel_100yr.yaml"


def main() -> None:
    ap = argparse.ArgumentParser()
    ap.add_argument("--duration", type=float, default=10800.0)
    ap.add_argument("--dt", type=float, default=0.1)
    ap.add_argument("--seed", type=int, default=1)
    ap.add_argument("--repeat", type=int, default=2)
    ap.add_argument("--accuracy", action="store_true",
                    help="instead: error of the default kinematics table against a finer one")
    args = ap.parse_args()
    if args.accuracy:
        accuracy(args.seed)
        return
    import numba

    from floatmoor.io.build import build
    from floatmoor.io.forces_section import ForcesSpec
    from floatmoor.io.viscous_drift_section import ViscousDriftSpec
    from floatmoor.solvers.time_domain import assemble, integrate

    warnings.simplefilter("ignore")
    print(f"machine: {platform.machine()}, {os.cpu_count()} cores, Python "
          f"{platform.python_version()}, numba {numba.__version__}, load average "
          f"{os.getloadavg()[0]:.1f}")
    built = build(SCENE)
    cases = {
        "case 1 (no viscous model)": None,
        "case 2 (slender elements)": ForcesSpec(viscous_drift=ViscousDriftSpec(
            model="slender_elements")),
        "case 5 (correction formula)": ForcesSpec(viscous_drift=ViscousDriftSpec(
            model="correction_formula", column_diameters=(12.5, 12.5, 12.5, 12.5),
            main_column_diameter=12.5)),
    }
    # warm-up (numba compile / cache load) on short runs
    for opts in cases.values():
        a = assemble(built, seed=args.seed, dt=args.dt, duration=60.0, ramp=10.0, options=opts)
        integrate(a, built=built)
    best = {k: [np.inf, np.inf] for k in cases}
    stats = {}
    for _ in range(args.repeat):
        for name, opts in cases.items():
            t0 = time.perf_counter()
            a = assemble(built, seed=args.seed, dt=args.dt, duration=args.duration, ramp=100.0,
                         options=opts)
            t1 = time.perf_counter()
            r = integrate(a, built=built)
            t2 = time.perf_counter()
            best[name][0] = min(best[name][0], t1 - t0)
            best[name][1] = min(best[name][1], t2 - t1)
            x = r.motion[r.time >= 1200.0, 0] if args.duration > 2400 else r.motion[:, 0]
            stats[name] = (float(x.max()), float(x.mean()), float(x.std()))
            if "slender_elements" in a.models:
                tab = a.models["slender_elements"].table
                stats["table"] = (tab.nbytes / 1e6, tab.u.shape, tab.H)
    base = sum(best["case 1 (no viscous model)"])
    print(f"flagship storm {args.duration:.0f} s, dt {args.dt} s, seed {args.seed}, best of "
          f"{args.repeat}:")
    print("| case | setup (s) | loop (s) | total (s) | added vs case 1 | surge max / mean / std "
          "(m) |")
    print("|---|---|---|---|---|---|")
    for name in cases:
        s, l = best[name]
        mx, mn, sd = stats[name]
        print(f"| {name} | {s:.2f} | {l:.2f} | {s + l:.2f} | {100 * (s + l - base) / base:+.0f} % "
              f"| {mx:.2f} / {mn:.2f} / {sd:.2f} |")
    mb, shape, H = stats["table"]
    print(f"kinematics table: {mb:.0f} MB, (times, stations, levels, 3) = {shape}, step {H:.2f} s")


def accuracy(seed: int, duration: float = 1200.0, dt: float = 0.1) -> None:
    """Slender force on the body at rest in the 100-year sea over ``duration``: default table
    (0.4 s, 3 m levels, 10 m stations) against a fine one (0.05 s, 1 m, 5 m)."""
    from floatmoor.forces.base import SetupContext
    from floatmoor.forces.slender import SlenderElements
    from floatmoor.forces.waves import wave_components
    from floatmoor.io.build import build
    from floatmoor.io.forces_section import ForcesSpec
    from floatmoor.io.viscous_drift_section import ViscousDriftSpec

    warnings.simplefilter("ignore")
    built = build(SCENE)
    site = built.scene.site
    comp = wave_components(built.scene.environment.waves, duration=duration, seed=seed,
                           h=0.5 * dt, water_depth=site.water_depth, gravity=site.gravity)
    out = {}
    for name, kw in (("default", {}), ("fine", dict(table_step=0.05, level_step=1.0,
                                                      station_spacing=5.0))):
        ctx = SetupContext(built=built, seed=seed, dt=dt, n_steps=int(duration / dt), ramp=0.0,
                           options=ForcesSpec(viscous_drift=ViscousDriftSpec(
                               model="slender_elements", **kw)), waves=comp)
        m = SlenderElements()
        m.setup(ctx)
        f = np.zeros((ctx.n_samples - 1, 6))
        for j in range(ctx.n_samples - 1):
            m.force(j * m.h, np.zeros(6), np.zeros(6), f[j])
        out[name] = f
    d, r = out["default"][:, 0], out["fine"][:, 0]
    print(f"slender surge force at rest, {duration:.0f} s of the 100-year sea, seed {seed}: "
          f"mean {d.mean() / 1e3:.1f} kN (fine table {r.mean() / 1e3:.1f} kN), std "
          f"{d.std() / 1e3:.1f} kN ({r.std() / 1e3:.1f}), rms difference "
          f"{np.sqrt(np.mean((d - r) ** 2)) / r.std() * 100:.2f} % of the std, max difference "
          f"{np.abs(d - r).max() / np.abs(r).max() * 100:.2f} % of the max")


if __name__ == "__main__":
    main()

"""Benchmark of the FE (lumped-mass) line: the OC3-Hywind line under prescribed fairlead motion.

1. Converged reference: floatmoor generalised-alpha with 160 elements at dt = 0.01 s.
2. Error against run time: fairlead tension range and maximum over the last period, relative
   to the reference, for element counts and time steps (floatmoor) and for MoorDyn (PyPI,
   RK2, dtM from its CFL) with 20 and 40 segments.
3. Wall time of floatmoor vs MoorDyn at equal or better accuracy in one run.
4. Largest stable dt of the explicit scheme; the implicit scheme at large dt.

5. Storm projection: 12 lines x 50 elements on a moving body through ``FEMooring``, line by
   line and with all lines in one numba call per body step.

Run: ``.venv/bin/python benchmarks/bench_fe_line.py [--quick] [--storm]`` (``--storm``: part 5
only).  MoorDyn rows are skipped
when the ``moordyn`` package is missing.
"""

from __future__ import annotations

import math
import os
import sys
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(__file__), ".."))

from floatmoor.core.errors import NumericalError  # noqa: E402
from floatmoor.mooring.fe import FELine  # noqa: E402
from floatmoor.mooring.fe.prescribed import HarmonicMotion, run_prescribed  # noqa: E402
from tests.mooring.fe.conftest import oc3_spec  # noqa: E402

PERIOD = 15.0
AMP = (-3.0, 0.0, 0.0)      # surge 3 m at 15 s (towards -x: away from the anchor)
T_END = 4 * PERIOD
BA_TOTAL = 0.8 * 2.0 * math.sqrt(384.243e6 * 77.7066) * 902.2   # B = BA_TOTAL / n


def motion():
    return HarmonicMotion(amplitude=AMP, period=PERIOD, ramp=PERIOD)


STATICS = {}


def run_fe(n, dt, integrator="generalized_alpha"):
    line = FELine(oc3_spec(n=n, damping=BA_TOTAL / n))
    t0 = time.perf_counter()
    line.solve_static()
    STATICS[n] = time.perf_counter() - t0
    line.start(integrator=integrator)
    t0 = time.perf_counter()
    ds = run_prescribed(line, motion(), T_END, dt)
    wall = time.perf_counter() - t0
    sel = ds.time.values > T_END - PERIOD + 1e-9
    T = ds.fairlead_tension.values[sel]
    return T, wall, line


def metrics(T, ref):
    rng = np.ptp(T)
    return (abs(rng / np.ptp(ref) - 1), abs(T.max() / ref.max() - 1))


def main(quick=False):
    # warm up the numba kernels (compiled or loaded from the cache)
    run_fe(10, 0.1)
    print("OC3 line, surge 3 m / 15 s, 4 periods (60 s), last period evaluated")
    ref, wall_ref, _ = run_fe(80 if quick else 160, 0.01)
    print(f"reference: {'80' if quick else '160'} elements, dt 0.01 s, wall {wall_ref:.2f} s, "
          f"range {np.ptp(ref) / 1e3:.1f} kN, max {ref.max() / 1e3:.1f} kN")
    rows = []
    for n in (10, 20, 40, 80):
        for dt in (0.2, 0.1, 0.05):
            try:
                T, wall, line = run_fe(n, dt)
            except NumericalError as e:
                print(f"  n={n} dt={dt}: {e}")
                continue
            e_rng, e_max = metrics(T, ref)
            rows.append(("floatmoor gen-alpha", n, dt, e_rng, e_max, wall))
    try:
        import moordyn  # noqa: F401

        from tests.mooring.fe.moordyn_ref import run_moordyn
        have_md = True
    except ImportError:
        have_md = False
    if have_md:
        for n, dtm in ((20, 1e-3), (40, 5e-4)):
            devnull = os.open(os.devnull, os.O_WRONLY)
            saved = os.dup(1)
            os.dup2(devnull, 1)
            try:
                t0 = time.perf_counter()
                t, F, wall = run_moordyn(motion(), T_END, 0.05, nseg=n, dtm=dtm, ba=BA_TOTAL / n,
                                         timing=True)
                wall_all = time.perf_counter() - t0
            finally:
                os.dup2(saved, 1)
                os.close(devnull)
            print(f"MoorDyn {n} segments: {wall_all:.2f} s in all, of which time steps "
                  f"{wall:.2f} s (the rest: initial conditions, file I/O)")
            T = np.linalg.norm(F, axis=1)[t > T_END - PERIOD + 1e-9]
            e_rng, e_max = metrics(T, ref)
            rows.append(("MoorDyn RK2", n, dtm, e_rng, e_max, wall))
    print()
    print("| model | elements | dt (s) | range error | max error | wall time (s) |")
    print("|---|---|---|---|---|---|")
    for name, n, dt, er, em, w in rows:
        print(f"| {name} | {n} | {dt:g} | {100 * er:.2f} % | {100 * em:.3f} % | {w:.3f} |")
    if have_md:
        md = [r for r in rows if r[0].startswith("MoorDyn")]
        fm = [r for r in rows if r[0].startswith("floatmoor")]
        for m in md:
            ok = [r for r in fm if r[3] <= m[3] and r[4] <= m[4]]
            if ok:
                best = min(ok, key=lambda r: r[5])
                print(f"MoorDyn {m[1]} segments: error range {100 * m[3]:.2f} %, max "
                      f"{100 * m[4]:.3f} %, {m[5]:.2f} s; floatmoor at equal or better accuracy: "
                      f"{best[1]} elements, dt {best[2]} s, {best[5]:.3f} s -> "
                      f"{m[5] / best[5]:.0f}x faster")
            else:
                print(f"MoorDyn {m[1]} segments: no floatmoor row at equal accuracy")
    print("floatmoor statics (catenary start + Newton), not counted above: " +
          ", ".join(f"{n} el. {1e3 * w:.1f} ms" for n, w in sorted(STATICS.items())))
    # explicit stability limit
    print()
    for n in (20, 50):
        lo, hi = 1e-4, 0.05
        for _ in range(12):
            mid = math.sqrt(lo * hi)
            line = FELine(oc3_spec(n=n, damping=BA_TOTAL / n))
            line.solve_static()
            line.start(integrator="explicit")
            try:
                ds = run_prescribed(line, motion(), 10.0, mid)
                ok = np.all(np.isfinite(ds.fairlead_tension.values)) and \
                    ds.fairlead_tension.values.max() < 1e8
            except NumericalError:
                ok = False
            lo, hi = (mid, hi) if ok else (lo, mid)
        print(f"explicit (symplectic Euler), {n} elements: largest stable dt ~ {lo * 1e3:.2f} ms "
              f"(unstable at {hi * 1e3:.2f} ms)")
    for dt in (0.5, 1.0):
        try:
            T, wall, line = run_fe(50, dt)
            print(f"gen-alpha 50 elements dt {dt} s: runs, range error "
                  f"{100 * metrics(T, ref)[0]:.1f} %, {line.substeps_taken} step splits")
        except NumericalError as e:
            print(f"gen-alpha 50 elements dt {dt} s: {e}")


def storm_projection(n_lines=12, n_el=50, dt=0.1, n_steps=1000, fast=True):
    """Time of FEMooring.advance/accept for 12 OC3-like lines of 50 elements around a body in
    harmonic surge/sway/yaw, projected to a 3-hour run (lines only: body dynamics excluded;
    the coupled run is ``bench_coupled_fe.py``)."""
    from floatmoor.mooring.fe import FELineSpec
    from floatmoor.mooring.fe.body import FEMooring
    base = oc3_spec(n=n_el, damping=BA_TOTAL / n_el)
    specs, fair_b = [], []
    for k in range(n_lines):
        a = 2 * math.pi * k / n_lines
        c, s_ = math.cos(a), math.sin(a)
        fb = (5.2 * c, 5.2 * s_, -70.0)
        specs.append(FELineSpec(**{**base.__dict__, "name": f"line{k + 1}",
                                   "anchor": (853.87 * c, 853.87 * s_, -320.0), "fairlead": fb}))
        fair_b.append(fb)
    fm = FEMooring(specs, fair_b, fast=fast)
    fm.solve_static(np.zeros(6))
    fm.start()
    t0 = time.perf_counter()
    for k in range(1, n_steps + 1):
        t = k * dt
        w = 2 * math.pi / 12.0
        pose = np.array([2 * math.sin(w * t), 1.5 * math.sin(w * t + 1), 0, 0, 0,
                         0.02 * math.sin(w * t)])
        vel = np.array([2 * w * math.cos(w * t), 1.5 * w * math.cos(w * t + 1), 0, 0, 0,
                        0.02 * w * math.cos(w * t)])
        fm.advance(t, dt, pose, vel)
        fm.accept()
    wall = time.perf_counter() - t0
    print(f"{'one numba call per body step' if fast else 'line by line (FELine.advance)'}: "
          f"{n_lines} lines x {n_el} elements, {n_steps} steps of {dt} s: {wall:.2f} s -> 3 h "
          f"({int(10800 / dt)} steps): {wall * 10800 / dt / n_steps:.0f} s (lines only), "
          f"{int(fm.newton_iterations.sum())} Newton iterations")


if __name__ == "__main__":
    if "--storm" not in sys.argv:
        main(quick="--quick" in sys.argv)
        print()
    storm_projection(n_steps=50)     # warm-up: numba compilation or cache load
    for dt in (0.1, 0.2):
        for fast in (False, True):
            storm_projection(dt=dt, fast=fast)

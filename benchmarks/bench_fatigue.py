"""Benchmark of the fatigue module.

Run: .venv/bin/python benchmarks/bench_fatigue.py

1. Rainflow counting (ASTM E1049-85, numba) of a 3-hour 10 Hz tension history (108,000
   samples): a bimodal Gaussian tension shaped like the Floatel-like fairlead tension (LF std
   141 kN at Tz 97 s, WF std 213 kN at Tz 16.5 s); best of 20 after a warm-up, beside the
   pure-Python ``rainflow`` package (optional) as a reference.
2. FD fatigue over a 1000-cell scatter for 12 lines x 4 locations: spectral moments of the LF
   (1200 frequencies) and WF (490 frequencies) tension spectra of every cell, the damage rates of
   the four spectral methods and the annual damage (the FD solves themselves are not included:
   their cost per sea state is printed by ``floatmoor fatigue`` runs, see RESULTS.md).
3. The bimodal verification table (spectral methods against time-domain rainflow).
"""

import math
import time

import numpy as np

from floatmoor.post.fatigue import DNV_CURVES, rainflow
from floatmoor.post.fatigue.locations import damage_rates
from floatmoor.post.fatigue.longterm import annual_damage
from floatmoor.post.fatigue.spectral import METHODS, gaussian_realisation, moments


def bump(w, w0, rel, var):
    s = rel * w0
    return var * np.exp(-0.5 * ((w - w0) / s) ** 2) / (s * math.sqrt(2.0 * math.pi))


def bench_rainflow():
    w = np.linspace(0.0, 3.0, 6001)
    S = bump(w, 2 * math.pi / 97.0, 0.15, 141e3 ** 2) + bump(w, 2 * math.pi / 16.5, 0.15,
                                                              213e3 ** 2)
    _, x = gaussian_realisation(w, S, 10800.0, 0.1, seed=1)
    x = x + 1.0e6
    rainflow(x)  # compile / load the cache
    times = []
    for _ in range(20):
        t0 = time.perf_counter()
        r, _, _c = rainflow(x)
        times.append(time.perf_counter() - t0)
    print(f"rainflow, {x.size} samples: best {1e3 * min(times):.2f} ms, median "
          f"{1e3 * float(np.median(times)):.2f} ms ({r.size} cycles and half cycles)")
    # worst case: every sample a turning point (white noise), 108,000 reversals
    y = np.random.default_rng(2).standard_normal(x.size)
    times = []
    for _ in range(20):
        t0 = time.perf_counter()
        r2, _, _ = rainflow(y)
        times.append(time.perf_counter() - t0)
    print(f"rainflow, {y.size} samples of white noise (every sample a reversal): best "
          f"{1e3 * min(times):.2f} ms, median {1e3 * float(np.median(times)):.2f} ms "
          f"({r2.size} cycles and half cycles)")
    try:
        import rainflow as rf
        t0 = time.perf_counter()
        n = sum(1 for _ in rf.extract_cycles(x))
        print(f"  reference: rainflow package {1e3 * (time.perf_counter() - t0):.0f} ms "
              f"({n} entries)")
    except ImportError:
        pass


def bench_scatter(n_cells=1000, n_lines=12, n_loc=4):
    rng = np.random.default_rng(3)
    w = np.linspace(0.05, 2.5, 491)        # the FD's WF grid (d_omega 0.005)
    mu = np.linspace(0.0, 2 * math.pi / 30.0, 1200)  # the FD's LF grid
    wf = np.empty((w.size, n_loc, n_lines))
    lf = np.empty((mu.size, n_loc, n_lines))
    chain, poly = DNV_CURVES["chain_studless"], DNV_CURVES["polyester"]
    curves = np.empty((n_loc, n_lines), object)
    curves[:] = chain
    curves[1] = poly
    rbs = np.full((n_loc, n_lines), 7.9e6)
    mom_l = np.empty((4, n_cells, n_loc, n_lines))
    mom_w = np.empty((4, n_cells, n_loc, n_lines))
    spectra = []
    for _c in range(n_cells):  # synthetic spectra (not timed)
        tp = rng.uniform(5, 20)
        a = rng.uniform(0.2, 2.0, (n_loc, n_lines))
        spectra.append((bump(w, 2 * math.pi / tp, 0.2, 1e10)[:, None, None] * a,
                        bump(mu, 2 * math.pi / 97.0, 0.15, 5e9)[:, None, None] * a))
    t0 = time.perf_counter()
    for c, (wf, lf) in enumerate(spectra):  # per cell, as each FD result comes
        mom_l[:, c], mom_w[:, c] = moments(mu, lf), moments(w, wf)
    t1 = time.perf_counter()
    rates = damage_rates(mom_l, mom_w, curves[None], rbs[None])
    p = rng.uniform(size=n_cells)
    annual = annual_damage(np.moveaxis(rates, 1, 0), p / p.sum())
    dt = time.perf_counter() - t0
    print(f"FD fatigue, {n_cells} cells x {n_lines} lines x {n_loc} locations x "
          f"{len(METHODS)} methods: {dt:.2f} s (moments {t1 - t0:.2f} s, damage + annual "
          f"{time.perf_counter() - t1:.2f} s); "
          f"max annual damage {np.nanmax(annual):.3g}")


def bimodal_table():
    import sys
    from pathlib import Path
    sys.path.insert(0, str(Path(__file__).resolve().parents[1] / "tests" / "post"))
    from test_fatigue_core import bimodal_table as table
    t0 = time.perf_counter()
    rows = table()
    print(f"bimodal LF + WF, FD damage / TD rainflow damage ({time.perf_counter() - t0:.1f} s):")
    print("| var ratio L/W | freq ratio W/L | WF width | " + " | ".join(METHODS) + " |")
    for vr, fr, width, res in rows:
        print(f"| {vr:g} | {fr:g} | {width:g} | " + " | ".join(f"{res[m]:.3f}" for m in METHODS)
              + " |")


if __name__ == "__main__":
    bench_rainflow()
    bench_scatter()
    bimodal_table()

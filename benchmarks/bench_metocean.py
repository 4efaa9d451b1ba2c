"""Benchmark of the metocean layer.

Times, for the Heidrun 100-year sea state (JONSWAP Hs 16 m, Tp 18.2 s, 320 m depth):

* numba compile time of each kernel (first call on tiny inputs, fresh cache directory unless
  ``--use-cache``), reported separately from run times;
* realising the waves (discretisation, random numbers, dispersion relation);
* 3 hours of wave elevation at 0.1 s (108 000 samples) at one point, with the fast uniform-grid
  kernel and with the general direct-sum kernel;
* Airy kinematics (velocity, acceleration, dynamic pressure, Wheeler stretching) at 100 points
  per time step, as a time loop would call it, extrapolated to 3 hours at 0.1 s;
* 3 hours of NPD wind gust at 0.1 s.

Usage:  python benchmarks/bench_metocean.py [--use-cache] [--steps 200]
"""

from __future__ import annotations

import argparse
import os
import platform
import sys
import tempfile
import time


def main() -> None:
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--use-cache", action="store_true",
                    help="use the normal numba cache (compile times then show cache loading)")
    ap.add_argument("--steps", type=int, default=200,
                    help="time steps for the kinematics timing (default 200)")
    args = ap.parse_args()
    if not args.use_cache:
        os.environ["NUMBA_CACHE_DIR"] = tempfile.mkdtemp(prefix="floatmoor-bench-")

    import numba
    import numpy as np

    from floatmoor.metocean import (
        CurrentSpec,
        WaveSpec,
        WindSpec,
        airy_kinematics_into,
        cosine_sum_uniform_into,
        current_speed,
        realise_waves,
        realise_wind,
        surface_elevation_into,
    )

    print(f"floatmoor metocean benchmark - {platform.machine()}, {os.cpu_count()} cores, "
          f"Python {platform.python_version()}, numpy {np.__version__}, numba {numba.__version__}")
    print(f"numba cache: {'normal' if args.use_cache else 'fresh (compile from scratch)'}")

    # ---------------------------------------------------------------- compile times
    print("\ncompile (first call on tiny inputs):")
    a1 = np.ones(2)
    t0 = time.perf_counter()
    surface_elevation_into(a1, a1, a1, a1, a1, a1, 0.0, 0.0, np.empty(2))
    print(f"  surface_elevation_into   {time.perf_counter() - t0:8.2f} s")
    t0 = time.perf_counter()
    cosine_sum_uniform_into(a1, a1, a1, 0.0, 0.1, np.empty((4, 2)), np.zeros(3))
    print(f"  cosine_sum_uniform_into  {time.perf_counter() - t0:8.2f} s")
    t0 = time.perf_counter()
    p3 = -np.ones((1, 3))
    airy_kinematics_into(a1, a1, a1, a1, a1, a1 * 0, 50.0, 9.81, 1025.0, True, 0.0, p3,
                         np.empty((3, 2)), np.empty((1, 3)), np.empty((1, 3)), np.empty(1),
                         np.empty(1))
    print(f"  airy_kinematics_into     {time.perf_counter() - t0:8.2f} s")
    t0 = time.perf_counter()
    current_speed(CurrentSpec(z=(0.0, -50.0), speed=(1.0, 0.5)), a1, 100.0)
    current_speed(CurrentSpec(profile="power_law", speed=(1.0,)), a1, 100.0)
    print(f"  current kernels (2)      {time.perf_counter() - t0:8.2f} s")

    # ---------------------------------------------------------------- waves
    spec = WaveSpec(hs=16.0, tp=18.2)
    duration, dt = 10800.0, 0.1
    n = int(round(duration / dt))
    t0 = time.perf_counter()
    real = realise_waves(spec, duration=duration, seed=1, water_depth=320.0)
    t_real = time.perf_counter() - t0
    print(f"\nwaves: Heidrun 100-year, {real.n_components} components "
          f"({real.omega.min():.3f}-{real.omega.max():.3f} rad/s), 3 h at dt = {dt} s "
          f"({n} samples)")
    print(f"  realise_waves                               {t_real * 1e3:9.1f} ms")
    t0 = time.perf_counter()
    eta = real.elevation_series(n, dt)
    t_fast = time.perf_counter() - t0
    print(f"  elevation, uniform-grid kernel (3 h)        {t_fast:9.3f} s   "
          f"({t_fast / (n * real.n_components) * 1e9:.2f} ns per component-sample)")
    t0 = time.perf_counter()
    eta_d = real.elevation(np.arange(n) * dt)
    t_direct = time.perf_counter() - t0
    print(f"  elevation, direct-sum kernel (3 h)          {t_direct:9.3f} s   "
          f"({t_direct / (n * real.n_components) * 1e9:.2f} ns per component-sample)")
    print(f"  max |fast - direct|                         {np.abs(eta - eta_d).max():9.1e} m")
    print(f"  realised Hs = 4 std                         {4 * eta.std():9.2f} m")

    # ---------------------------------------------------------------- kinematics
    rng = np.random.default_rng(0)
    m = 100
    pts = np.c_[rng.uniform(-40, 40, m), rng.uniform(-40, 40, m), rng.uniform(-30, 5, m)]
    for n_freq in (None, 300):
        r = real if n_freq is None else realise_waves(spec, duration=duration, seed=1,
                                                      water_depth=320.0, n_frequencies=n_freq)
        vel, acc = np.empty((m, 3)), np.empty((m, 3))
        pres, et = np.empty(m), np.empty(m)
        work = np.empty((3, r.n_components))
        r.kinematics_into(0.0, pts, work, vel, acc, pres, et)  # warm
        steps = args.steps
        t0 = time.perf_counter()
        for j in range(steps):
            r.kinematics_into(j * dt, pts, work, vel, acc, pres, et)
        per_step = (time.perf_counter() - t0) / steps
        print(f"\nkinematics at {m} points (Wheeler), {r.n_components} components:")
        print(f"  per time step                               {per_step * 1e3:9.2f} ms   "
              f"({per_step / (m * r.n_components) * 1e9:.1f} ns per component-point)")
        print(f"  3 h at dt = {dt} s (extrapolated, {n} steps) {per_step * n:9.1f} s")

    # ---------------------------------------------------------------- wind
    wspec = WindSpec(u10=36.0)
    t0 = time.perf_counter()
    wr = realise_wind(wspec, duration=duration, seed=1)
    t_wr = time.perf_counter() - t0
    t0 = time.perf_counter()
    u = wr.speed_series(n, dt)
    t_ws = time.perf_counter() - t0
    print(f"\nwind: NPD, U10 = 36 m/s, {wr.n_components} components (0-{wr.f.max():.3f} Hz)")
    print(f"  realise_wind                                {t_wr * 1e3:9.1f} ms")
    print(f"  speed, uniform-grid kernel (3 h)            {t_ws:9.3f} s   "
          f"(mean {u.mean():.2f} m/s, std {u.std():.2f} m/s)")
    sys.stdout.flush()


if __name__ == "__main__":
    main()

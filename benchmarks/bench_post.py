"""Benchmark of floatmoor.post: 20 seeds x 3 h at dt = 0.1 s x (6 DOFs + 12 lines).

Run: .venv/bin/python benchmarks/bench_post.py
Synthetic results shaped like the simulator's: motion(time, dof), line_tension(time,
line) in N.  Building the data is not timed.
"""

import time

import numpy as np
import xarray as xr

from floatmoor.post import dnv_os_e301, per_seed_statistics, seed_maxima, upcrossing_peaks

DT, DURATION, N_SEEDS, N_LINES = 0.1, 10800.0, 20, 12
DOFS = ["surge", "sway", "heave", "roll", "pitch", "yaw"]


def make(seed: int) -> xr.Dataset:
    rng = np.random.default_rng(seed)
    t = np.arange(0.0, DURATION + DT / 2, DT)
    f_wf = rng.uniform(0.05, 0.15, 40)
    f_lf = rng.uniform(0.003, 0.02, 10)
    ph = rng.uniform(0, 2 * np.pi, 50)
    base = (np.sin(2 * np.pi * np.outer(t, f_wf) + ph[:40]).sum(1) * 0.3
            + np.sin(2 * np.pi * np.outer(t, f_lf) + ph[40:]).sum(1) * 2.0)
    motion = np.outer(base, [1, 0.2, 0.1, 0.01, 0.01, 0.005]) + [12, 0, 0, 0, 0, 0]
    tension = 1.5e6 + 1e5 * np.outer(base, np.linspace(0.5, 1.5, N_LINES))
    return xr.Dataset(
        {"motion": (("time", "dof"), motion, {"units": "m", "long_name": "motion"}),
         "line_tension": (("time", "line"), tension, {"units": "N", "long_name": "tension"})},
        coords={"time": t, "dof": DOFS, "line": np.arange(1, N_LINES + 1)},
        attrs={"seed": seed, "scene": "bench"})


def main():
    runs = [make(s) for s in range(1, N_SEEDS + 1)]
    n = runs[0].sizes["time"]
    print(f"{N_SEEDS} seeds x {n} samples x ({len(DOFS)} DOFs + {N_LINES} lines)")
    t0 = time.perf_counter()
    stats = per_seed_statistics(runs, start=1200.0)
    t1 = time.perf_counter()
    smax = seed_maxima(runs, "line_tension", start=1200.0)
    ct = dnv_os_e301.characteristic_tensions(smax, stats["line_tension_mean"])
    chk = dnv_os_e301.check_lines(ct.line.values, 8.5e6, uls_mean=ct.t_c_mean.values,
                                  uls_max=ct.t_c.values, consequence_class=2)
    t2 = time.perf_counter()
    npk = 0
    for ds in runs:
        x = ds["line_tension"].values
        for j in range(N_LINES):
            npk += len(upcrossing_peaks(x[:, j]))
    t3 = time.perf_counter()
    print(f"statistics (filter + 12 stats), all seeds : {t1 - t0:6.2f} s")
    print(f"seed maxima + Gumbel + ULS check        : {t2 - t1:6.2f} s")
    print(f"up-crossing peaks, 12 lines x 20 seeds   : {t3 - t2:6.2f} s ({npk} peaks)")
    print(f"total                                    : {t3 - t0:6.2f} s")
    print(f"governing line {chk.attrs['governing_line']}, max utilisation "
          f"{chk.attrs['max_utilisation']:.3f}")


if __name__ == "__main__":
    main()
